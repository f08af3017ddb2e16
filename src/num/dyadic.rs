//! Exact sums of determinants of `f64` points: the area and the volume of a float set as the
//! rationals its vertices are (a float set is the exact set of its `f64` values, seed 000
//! §5.2), with no rounding, cancellation, overflow or underflow at any offset or scale.
//!
//! Every finite `f64` is an integer multiple of 2^low, low the least exponent of the nonzero
//! values (their common power-of-two grid, [`super::common_grid`]). On that grid, relative to
//! the first point, each simplex's determinant is an integer: computed in `i128` where the
//! relative integers are narrow enough, on big integers otherwise, and summed in `i128`
//! words spilled into a big integer before they overflow. The sum times 2^(D·low) is the exact
//! value.

use super::grid_orient::odd_decode;
use super::{Num, Rational};
use num_bigint::BigInt;
use num_traits::{ToPrimitive, Zero};

/// Σ over `simplices` of det[p₁ − o, …, p_D − o], the `p`s indices into the finite `points`
/// and o = `points[0]`: twice the signed area of closed curves given by their directed edges
/// (D = 2), six times the signed volume of closed surfaces given by their triangles (D = 3).
/// For closed curves and surfaces the sum does not depend on o.
pub(crate) fn det_sum<const D: usize>(
    points: &[[f64; D]],
    simplices: impl Iterator<Item = [usize; D]>,
) -> Rational {
    if points.is_empty() {
        return Rational::from_i64(0);
    }
    let decoded: Vec<[(i64, i32); D]> = points
        .iter()
        .map(|p| p.map(|v| if v == 0.0 { (0, 0) } else { odd_decode(v) }))
        .collect();
    let nonzero = decoded.iter().flatten().filter(|(m, _)| *m != 0);
    let low = nonzero.clone().map(|&(_, e)| e).min().unwrap_or(0);
    let width = nonzero
        .map(|&(m, e)| 64 - m.unsigned_abs().leading_zeros() as i32 + (e - low))
        .max()
        .unwrap_or(0);
    let scale = Rational::times_power_of_two(BigInt::from(1), BigInt::from(1), D as i32 * low);
    let relative = if width <= NARROW[D - 2] {
        let ints = |p: &[(i64, i32); D]| {
            p.map(|(m, e)| {
                if m == 0 {
                    0
                } else {
                    i128::from(m) << (e - low)
                }
            })
        };
        let o = ints(&decoded[0]);
        Relative::Narrow(
            (decoded.iter())
                .map(|p| {
                    let p = ints(p);
                    std::array::from_fn(|k| p[k] - o[k])
                })
                .collect(),
        )
    } else {
        let ints = |p: &[(i64, i32); D]| {
            p.map(|(m, e)| BigInt::from(m) << if m == 0 { 0 } else { e - low })
        };
        let o = ints(&decoded[0]);
        Relative::Wide(
            (decoded.iter())
                .map(|p| {
                    let p = ints(p);
                    std::array::from_fn(|k| &p[k] - &o[k])
                })
                .collect(),
        )
    };
    Rational::from_integer(relative.det_sum(simplices)) * scale
}

/// Integer points relative to the first, as `i128`s where they are narrow enough for exact
/// `i128` determinants ([`NARROW`]), else as big integers.
pub(super) enum Relative<const D: usize> {
    /// Every relative coordinate below 2^(`NARROW` + 1) in magnitude.
    Narrow(Vec<[i128; D]>),
    /// Any others.
    Wide(Vec<[BigInt; D]>),
}

impl<const D: usize> Relative<D> {
    /// The relative form of the integer points `points` (not empty), narrow where it can be.
    pub(super) fn of(points: &[[BigInt; D]]) -> Relative<D> {
        let o = &points[0];
        let wide: Vec<[BigInt; D]> = (points.iter())
            .map(|p| std::array::from_fn(|k| &p[k] - &o[k]))
            .collect();
        let bits = (wide.iter().flatten().map(|v| v.bits()).max()).unwrap_or(0);
        let to_narrow = |p: &[BigInt; D]| -> Option<[i128; D]> {
            let mut out = [0i128; D];
            for (o, v) in out.iter_mut().zip(p) {
                *o = v.to_i128()?;
            }
            Some(out)
        };
        let narrow = (bits <= NARROW[D - 2] as u64)
            .then(|| wide.iter().map(to_narrow).collect::<Option<Vec<_>>>())
            .flatten();
        match narrow {
            Some(rel) => Relative::Narrow(rel),
            None => Relative::Wide(wide),
        }
    }

    /// Σ over `simplices` (indices into the points) of det[p₁ − o, …, p_D − o].
    pub(super) fn det_sum(&self, simplices: impl Iterator<Item = [usize; D]>) -> BigInt {
        match self {
            Relative::Narrow(rel) => {
                let mut total = Total::default();
                for s in simplices {
                    total.add(det(s.map(|i| &rel[i])));
                }
                total.value()
            }
            Relative::Wide(rel) => simplices
                .map(|s| big_det(s.map(|i| &rel[i])))
                .fold(BigInt::zero(), |a, b| a + b),
        }
    }
}

/// The widest grid integers, in bits, whose `i128` path is exact, for D = 2 and 3: the
/// relative coordinates are below 2^(w + 1), a 2 × 2 determinant below 2^(2w + 3) and a 3 × 3
/// one below 2^(3w + 6), which must stay below 2^127.
const NARROW: [i32; 2] = [61, 40];

/// An `i128` running sum that spills into a big integer where it would overflow.
#[derive(Default)]
struct Total {
    /// The sum of the terms spilled so far.
    spilled: BigInt,
    /// The sum of the terms since.
    word: i128,
}

impl Total {
    /// Adds `t`.
    fn add(&mut self, t: i128) {
        match self.word.checked_add(t) {
            Some(w) => self.word = w,
            None => {
                self.spilled += self.word;
                self.word = t;
            }
        }
    }

    /// The sum.
    fn value(self) -> BigInt {
        self.spilled + self.word
    }
}

/// det[p₁, …, p_D] on `i128`s narrow enough not to overflow ([`NARROW`]).
fn det<const D: usize>(p: [&[i128; D]; D]) -> i128 {
    match D {
        2 => p[0][0] * p[1][1] - p[0][1] * p[1][0],
        _ => {
            let minor = |i: usize, j: usize| p[1][i] * p[2][j] - p[1][j] * p[2][i];
            p[0][0] * minor(1, 2) - p[0][1] * minor(0, 2) + p[0][2] * minor(0, 1)
        }
    }
}

/// det[p₁, …, p_D] on big integers.
fn big_det<const D: usize>(p: [&[BigInt; D]; D]) -> BigInt {
    match D {
        2 => &p[0][0] * &p[1][1] - &p[0][1] * &p[1][0],
        _ => {
            let minor = |i: usize, j: usize| &p[1][i] * &p[2][j] - &p[1][j] * &p[2][i];
            &p[0][0] * minor(1, 2) - &p[0][1] * minor(0, 2) + &p[0][2] * minor(0, 1)
        }
    }
}

#[cfg(test)]
pub(super) mod tests {
    use super::*;
    use proptest::prelude::*;

    /// Σ det[p₁ − o, …, p_D − o] on the rationals the `f64`s are, the way exact mode would.
    fn oracle<const D: usize>(points: &[[f64; D]], simplices: &[[usize; D]]) -> Rational {
        let r = |v: f64| Rational::from_float(v).unwrap();
        let exact: Vec<[Rational; D]> = points.iter().map(|p| p.map(r)).collect();
        rational_det_sum(&exact, simplices)
    }

    /// Σ det[p₁ − o, …, p_D − o] over `simplices` in reduced rational arithmetic: the oracle
    /// of the exact sums here and in `num::lattice`.
    pub(in crate::num) fn rational_det_sum<const D: usize>(
        points: &[[Rational; D]],
        simplices: &[[usize; D]],
    ) -> Rational {
        let rel = |i: usize| -> [Rational; D] {
            std::array::from_fn(|k| points[i][k].clone() - points[0][k].clone())
        };
        let mut sum = Rational::from_i64(0);
        for s in simplices {
            let p: [[Rational; D]; D] = s.map(rel);
            sum = sum
                + match D {
                    2 => p[0][0].clone() * p[1][1].clone() - p[0][1].clone() * p[1][0].clone(),
                    _ => {
                        let minor = |i: usize, j: usize| {
                            p[1][i].clone() * p[2][j].clone() - p[1][j].clone() * p[2][i].clone()
                        };
                        p[0][0].clone() * minor(1, 2) - p[0][1].clone() * minor(0, 2)
                            + p[0][2].clone() * minor(0, 1)
                    }
                };
        }
        sum
    }

    /// An `f64`: 0 one time in eight, else a random 53-bit mantissa times 2^(base + e), |e| at
    /// most `spread`; with `narrow`, only the mantissa's leading 40 bits (an integer times
    /// 2^base).
    fn value(base: i32, spread: i32, narrow: bool) -> impl Strategy<Value = f64> {
        (any::<i64>(), -spread..=spread, 0u8..8).prop_map(move |(m, e, zero)| {
            let m = (m >> 11) as f64;
            match (zero, narrow) {
                (0, _) => 0.0,
                (_, true) => (m * 2f64.powi(-13)).trunc() * 2f64.powi(base),
                (_, false) => m * 2f64.powi(base + e - 52),
            }
        })
    }

    /// Points near 2⁻⁷⁰⁰, 1 or 2⁷⁰⁰ on a narrow grid (the `i128` path in 2D and 3D: integers
    /// below 2⁴⁰), a middle one (exponents 5 apart: `i128` in 2D, big integers in 3D) or wide
    /// ones (exponents up to 600 apart: big integers), and simplices of random indices: the
    /// sum equals the rational one.
    fn case<const D: usize>() -> impl Strategy<Value = (Vec<[f64; D]>, Vec<[usize; D]>)> {
        let bases = prop_oneof![Just(-700), Just(0), Just(700)];
        let spreads = prop_oneof![Just(-1), Just(2), Just(5), Just(300)];
        (bases, spreads)
            .prop_flat_map(|(base, spread)| {
                let v = value(base, spread.max(0), spread < 0);
                proptest::collection::vec(proptest::array::uniform::<_, D>(v), 1..12)
            })
            .prop_flat_map(|points| {
                let n = points.len();
                let simplex = proptest::array::uniform::<_, D>(0..n);
                (Just(points), proptest::collection::vec(simplex, 0..20))
            })
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(yinset_testkit::cases(256)))]
        #[test]
        fn det_sum_2d_is_the_rational_sum((points, simplices) in case::<2>()) {
            let got = det_sum(&points, simplices.iter().copied());
            prop_assert_eq!(got, oracle(&points, &simplices));
        }

        #[test]
        fn det_sum_3d_is_the_rational_sum((points, simplices) in case::<3>()) {
            let got = det_sum(&points, simplices.iter().copied());
            prop_assert_eq!(got, oracle(&points, &simplices));
        }
    }

    /// The `i128` total spills instead of overflowing: 2¹²⁶ · 3 summed in three terms.
    #[test]
    fn total_spills_into_a_big_integer() {
        let mut t = Total::default();
        for _ in 0..3 {
            t.add(1 << 126);
        }
        assert_eq!(t.value(), BigInt::from(3) << 126);
    }
}
