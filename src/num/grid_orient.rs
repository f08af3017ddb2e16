//! `f64` values as integers on one power-of-two grid, and the exact 3D orientation of `f64`
//! points computed on them in fixed-width integers: the fast exact stage behind the static
//! filter of [`super::float::exact_orient3d_f64`] for the points a filter cannot decide —
//! mostly points exactly on the plane, whose sign Shewchuk's adaptive predicate settles only
//! at its last stage. The grid also serves exact rationals of `f64`s
//! ([`super::Rational::from_float`]) and the 3D float meet's pierce points.

use num_traits::Float as _;
use std::cmp::Ordering;

/// Bits of the grid integers: below 2^60 in magnitude, differences stay below 2^61 (`i64`),
/// the 2 × 2 minors of differences below 2^123 (`i128`), and the determinant is summed in
/// two `i128` words without overflow.
const BITS: u32 = 60;

/// The odd mantissa and exponent of a finite, nonzero `v`: v = m · 2^e with m odd.
pub(crate) fn odd_decode(v: f64) -> (i64, i32) {
    let (m, e, sign) = v.integer_decode();
    let zeros = m.trailing_zeros();
    (
        i64::from(sign) * (m >> zeros) as i64,
        i32::from(e) + zeros as i32,
    )
}

/// Finite `values` on their common power-of-two grid: each as its odd mantissa m (0 for 0)
/// and a shift s, the value being m · 2^(low + s), with `low` the least exponent of the
/// nonzero ones (0 if there are none).
pub(crate) fn common_grid<const K: usize>(values: [f64; K]) -> ([(i64, u32); K], i32) {
    let decoded = values.map(|v| if v == 0.0 { (0, 0) } else { odd_decode(v) });
    let nonzero = decoded.iter().filter(|(m, _)| *m != 0);
    let low = nonzero.map(|&(_, e)| e).min().unwrap_or(0);
    (
        decoded.map(|(m, e)| (m, if m == 0 { 0 } else { (e - low) as u32 })),
        low,
    )
}

/// The coordinates as integers on their [`common_grid`], if all lie below 2^[`BITS`] there.
fn grid_integers<const K: usize>(values: [f64; K]) -> Option<[i64; K]> {
    let (parts, _) = common_grid(values);
    let mut out = [0i64; K];
    for (o, (m, shift)) in out.iter_mut().zip(parts) {
        if m != 0 {
            let width = 64 - m.unsigned_abs().leading_zeros();
            if width + shift > BITS {
                return None;
            }
            *o = m << shift;
        }
    }
    Some(out)
}

/// The sign of det[b − a, c − a, d − a] (the convention of [`crate::num::Num::orient3d`])
/// for finite `f64` points whose coordinates are integers below 2^60 on one power-of-two grid
/// ([`grid_integers`]), exactly; `None` for others.
pub(crate) fn grid_orient3d(
    a: [f64; 3],
    b: [f64; 3],
    c: [f64; 3],
    d: [f64; 3],
) -> Option<Ordering> {
    let [a0, a1, a2] = a;
    let [b0, b1, b2] = b;
    let [c0, c1, c2] = c;
    let [d0, d1, d2] = d;
    let n = grid_integers([a0, a1, a2, b0, b1, b2, c0, c1, c2, d0, d1, d2])?;
    let diff = |p: usize| [0, 1, 2].map(|k| n[3 * p + k] - n[k]);
    Some(det3_sign(diff(1), diff(2), diff(3)))
}

/// The sign of det[u, v, w] for integer vectors with components below 2^61 in magnitude,
/// exactly on `i128`s: each minor of v and w is below 2^123, and each product with u is taken
/// in two halves, the minor split at 2^64.
pub(crate) fn det3_sign(u: [i64; 3], v: [i64; 3], w: [i64; 3]) -> Ordering {
    let wide = |x: i64| i128::from(x);
    // (v × w)ₖ, each below 2^123.
    let cross = [0, 1, 2].map(|k| {
        let (i, j) = ((k + 1) % 3, (k + 2) % 3);
        wide(v[i]) * wide(w[j]) - wide(v[j]) * wide(w[i])
    });
    // u · (v × w) = high · 2^64 + low, each product split at 2^64 of the minor.
    let (mut high, mut low) = (0i128, 0i128);
    for k in 0..3 {
        let (hi, lo) = (cross[k] >> 64, cross[k] & i128::from(u64::MAX));
        high += wide(u[k]) * hi;
        low += wide(u[k]) * lo;
    }
    high += low >> 64;
    let low = low & i128::from(u64::MAX);
    match high {
        0 => low.cmp(&0),
        _ => high.cmp(&0),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::num::{Num, Rational};

    /// The exact orientation of the values read as rationals.
    fn rational_orient3d(p: [[f64; 3]; 4]) -> Ordering {
        let r = p.map(|q| q.map(|x| Rational::from_f64(x).expect("finite")));
        let [a, b, c, d] = [0, 1, 2, 3].map(|i| [&r[i][0], &r[i][1], &r[i][2]]);
        crate::num::exact_orient3d(a, b, c, d)
    }

    /// The largest grid integers allowed, at the largest spread of exponents: no overflow,
    /// the exact sign; one bit more is refused.
    #[test]
    fn the_widest_grid_integers_keep_the_exact_sign() {
        let top = ((1u64 << 53) - 1) as f64 * 128.0; // 2^60 − 2^7, odd mantissa times 2^7
        let p = [
            [top, -top, 1.0],
            [-top, top, top],
            [top, top, -top],
            [-top, -top, top],
        ];
        assert_eq!(
            grid_orient3d(p[0], p[1], p[2], p[3]),
            Some(rational_orient3d(p))
        );
        let q = [
            [top, -top, -top],
            [-top, top, -top],
            [-top, -top, top],
            [top, top, 1.0],
        ];
        assert_eq!(
            grid_orient3d(q[0], q[1], q[2], q[3]),
            Some(rational_orient3d(q))
        );
        let wider = [[2.0 * top, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0; 3], [1.0; 3]];
        assert_eq!(grid_orient3d(wider[0], wider[1], wider[2], wider[3]), None);
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(yinset_testkit::cases(2000)))]

        /// On points of a plane with full-width mantissas, each axis stretched by its own
        /// 2^0 … 2^8 (which keeps them coplanar) so that the grid integers reach and pass
        /// 2^60 (exactly coplanar, or the last moved by a unit of the grid), all scaled by
        /// 2^e down into the subnormals: the exact sign of the values read as rationals
        /// wherever they fit.
        #[test]
        fn grid_orientations_are_exact(
            a in proptest::array::uniform3(-(1i64 << 52)..(1i64 << 52)),
            u in proptest::array::uniform3(-(1i64 << 20)..(1i64 << 20)),
            v in proptest::array::uniform3(-(1i64 << 20)..(1i64 << 20)),
            (s, t) in (-8i64..8, -8i64..8),
            nudge in proptest::array::uniform3(-1i64..=1),
            stretch in proptest::array::uniform3(0u32..=8),
            e in -1130i32..900,
        ) {
            // Below 2^-1000 in two steps (2^e itself would underflow), rounding into the
            // subnormals, where the points are near a plane rather than on it.
            let scale = |x: f64| x * 2f64.powi(e.max(-1000)) * 2f64.powi((e + 1000).min(0));
            let point = |q: [i64; 3]| [0, 1, 2].map(|k| scale((q[k] << stretch[k]) as f64));
            let b = [0, 1, 2].map(|k| a[k] + u[k]);
            let c = [0, 1, 2].map(|k| a[k] + v[k]);
            let d = [0, 1, 2].map(|k| a[k] + s * u[k] + t * v[k] + nudge[k]);
            let p = [point(a), point(b), point(c), point(d)];
            if let Some(sign) = grid_orient3d(p[0], p[1], p[2], p[3]) {
                proptest::prop_assert_eq!(sign, rational_orient3d(p));
            }
        }
    }
}
