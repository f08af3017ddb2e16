//! The point where an edge pierces the plane of a triangle (the transversal meet's pierce
//! points, [`super::transversal`]), exactly: from `f64` corners on their common power-of-two
//! grid, from rational corners on the integers over their common denominator; on 256- or
//! 384-bit integers on the stack where those integers are narrow enough (every pair of
//! ../shared/data/3d), on big integers otherwise — the same value either way.

use super::link::{cross, dot, Scalar, Vector};
use crate::kernel::Point3;
use crate::num::{common_denominator, common_grid, from_words, gcd_u128, Num, Rational};
use num_bigint::{BigInt, Sign};
use num_integer::Integer;
use ruint::aliases::U256;
use ruint::Uint;
use std::cmp::Ordering;
use std::ops::{Add, Neg, Sub};

/// The widest grid integers, in bits, that the stack path takes on `BITS`-bit integers: for
/// grid integers below 2^B every value it forms is below 2^(4B + 7) (differences 2^(B+1), the
/// normal 2^(2B+3), the plane's values 2^(3B+6), the section's numerators 2^(4B+7)), which
/// must stay below 2^(BITS − 1); V − U then fits in `u128`.
const fn narrow(bits: usize) -> u32 {
    (bits as u32 - 8) / 4
}

/// An integer in two's complement on the words of a `BITS`-bit `ruint` integer: sums,
/// differences and products wrap, so they are exact while every value stays below 2^(BITS − 1)
/// in magnitude ([`narrow`] sees to it).
#[derive(Clone, Copy, PartialEq, Eq)]
struct Twos<const BITS: usize, const LIMBS: usize>(Uint<BITS, LIMBS>);

impl<const BITS: usize, const LIMBS: usize> Twos<BITS, LIMBS> {
    /// True below zero.
    fn negative(&self) -> bool {
        self.0.bit(BITS - 1)
    }

    /// |self|.
    fn magnitude(self) -> Uint<BITS, LIMBS> {
        match self.negative() {
            true => self.0.wrapping_neg(),
            false => self.0,
        }
    }

    /// The integer of sign `negative` and magnitude `m`.
    fn signed(negative: bool, m: Uint<BITS, LIMBS>) -> Self {
        match negative {
            true => Twos(m.wrapping_neg()),
            false => Twos(m),
        }
    }

    /// The quotient by a divisor `g` > 0 of `self`.
    fn divided(self, g: Uint<BITS, LIMBS>) -> Self {
        Twos::signed(self.negative(), self.magnitude() / g)
    }
}

impl<const BITS: usize, const LIMBS: usize> Add for Twos<BITS, LIMBS> {
    type Output = Self;
    fn add(self, o: Self) -> Self {
        Twos(self.0 + o.0)
    }
}

impl<const BITS: usize, const LIMBS: usize> Sub for Twos<BITS, LIMBS> {
    type Output = Self;
    fn sub(self, o: Self) -> Self {
        Twos(self.0 - o.0)
    }
}

impl<const BITS: usize, const LIMBS: usize> Sub for &Twos<BITS, LIMBS> {
    type Output = Twos<BITS, LIMBS>;
    fn sub(self, o: Self) -> Twos<BITS, LIMBS> {
        *self - *o
    }
}

impl<const BITS: usize, const LIMBS: usize> Neg for Twos<BITS, LIMBS> {
    type Output = Self;
    fn neg(self) -> Self {
        Twos(self.0.wrapping_neg())
    }
}

impl<const BITS: usize, const LIMBS: usize> Scalar for Twos<BITS, LIMBS> {
    fn of(w: i64) -> Self {
        Twos::signed(w < 0, Uint::from(w.unsigned_abs()))
    }
    fn times(&self, o: &Self) -> Self {
        Twos(self.0 * o.0)
    }
    fn sign(&self) -> Option<Ordering> {
        Some(match (self.negative(), self.0 == Uint::ZERO) {
            (true, _) => Ordering::Less,
            (false, true) => Ordering::Equal,
            (false, false) => Ordering::Greater,
        })
    }
}

/// The point where the edge `(u, v)` pierces the plane of the triangle `tri` (indices into the
/// `f64` points `p`), exactly: (du·V − dv·U) / (du − dv), du and dv the plane's values at U and
/// V, in integers after scaling every coordinate by one power of two; the same value whichever
/// triangle of the edge asks.
pub(super) fn pierce(p: &[[f64; 3]], (u, v): (usize, usize), tri: [usize; 3]) -> Point3<Rational> {
    pierce_f64([u, v, tri[0], tri[1], tri[2]].map(|i| p[i]))
}

/// [`pierce`] for the `f64` points `[U, V, A, B, C]`: where the line UV meets the plane ABC.
pub(super) fn pierce_f64(corners: [[f64; 3]; 5]) -> Point3<Rational> {
    let (parts, low) = common_grid::<15>(std::array::from_fn(|k| corners[k / 3][k % 3]));
    let [x, y, z] = match width(&parts) {
        w if w <= narrow(256) => on_stack::<256, 4>(parts, low),
        w if w <= narrow(384) => on_stack::<384, 6>(parts, low),
        _ => {
            let int = |(m, shift): (i64, u32)| BigInt::from(m) << shift;
            let [pu, pv, a, b, c] = points(parts.map(int));
            let (du, dv) = plane_values([&pu, &pv], [a, b, c]);
            Rational::section_point(&du, &dv, [&pu, &pv], low)
        }
    };
    Point3::new(x, y, z)
}

/// [`pierce`] for exact rational corners `[U, V, A, B, C]`: their coordinates as integers
/// over their least common denominator L (in `i64`s on the stack where L and the integers fit,
/// big integers otherwise), the section point on those integers, divided by L.
pub(super) fn pierce_rational(corners: [&Point3<Rational>; 5]) -> Point3<Rational> {
    let coords: [&Rational; 15] = std::array::from_fn(|k| corners[k / 3].coord(k % 3));
    let (xyz, l) = match small_grid(coords) {
        Some((ints, l)) => {
            let parts = ints.map(|m| (m, 0));
            let xyz = match width(&parts) {
                w if w <= narrow(256) => on_stack::<256, 4>(parts, 0),
                _ => on_stack::<384, 6>(parts, 0),
            };
            (xyz, Rational::from_i64(l))
        }
        None => {
            let fractions = coords.map(|v| v.fraction());
            // Most denominators repeat (decimals of a few lengths): a remainder, not a gcd.
            let l =
                (fractions.iter()).fold(BigInt::from(1), |l, (_, d)| match l.is_multiple_of(d) {
                    true => l,
                    false => l.lcm(d),
                });
            let ints = fractions.map(|(n, d)| n * (&l / d));
            let [pu, pv, a, b, c] = points(ints);
            let (du, dv) = plane_values([&pu, &pv], [a, b, c]);
            (
                Rational::section_point(&du, &dv, [&pu, &pv], 0),
                Rational::from_integer(l),
            )
        }
    };
    let [x, y, z] = xyz.map(|v| v / l.clone());
    Point3::new(x, y, z)
}

/// The values as integers over their least common denominator L, with L, if L and every
/// integer fit an `i64`.
fn small_grid(values: [&Rational; 15]) -> Option<([i64; 15], i64)> {
    let l = common_denominator(values.into_iter(), i64::MAX)?;
    let mut ints = [0i64; 15];
    for (i, v) in ints.iter_mut().zip(values) {
        let (n, d) = v.small_fraction()?;
        *i = n * (l / d);
    }
    Some((ints, l))
}

/// The width in bits of the widest of the grid integers m·2^shift (a zero has m = 0 and shift
/// 0, width 0).
fn width(parts: &[(i64, u32)]) -> u32 {
    (parts.iter())
        .map(|&(m, shift)| 64 - m.unsigned_abs().leading_zeros() + shift)
        .max()
        .unwrap_or(0)
}

/// The five points U, V, A, B, C of the 15 grid integers.
fn points<S: Scalar>(ints: [S; 15]) -> [Vector<S>; 5] {
    let mut ints = ints.into_iter();
    std::array::from_fn(|_| std::array::from_fn(|_| ints.next().expect("15 integers")))
}

/// The values at `pu` and `pv` of the plane through a, b, c: n · (x − a), n = (b − a) × (c − a).
fn plane_values<S: Scalar>(at: [&Vector<S>; 2], [a, b, c]: [Vector<S>; 3]) -> (S, S)
where
    for<'x> &'x S: std::ops::Sub<&'x S, Output = S>,
{
    let sub = |x: &Vector<S>, y: &Vector<S>| [0, 1, 2].map(|k| &x[k] - &y[k]);
    let n = cross(&sub(&b, &a), &sub(&c, &a));
    let value = |x: &Vector<S>| dot(&n, &sub(x, &a));
    (value(at[0]), value(at[1]))
}

/// [`Rational::section_point`] on stack integers: the point (u·V − v·U) / (u − v) · 2^`scale`
/// of the line through U = `pu` and V = `pv`, with u and v the plane's values there, each
/// coordinate in lowest terms by the same gcds (h = gcd(u, v), then gcd(V − U, d) with the
/// small V − U).
fn on_stack<const BITS: usize, const LIMBS: usize>(
    parts: [(i64, u32); 15],
    scale: i32,
) -> [Rational; 3] {
    let int = |(m, shift): (i64, u32)| Twos(Twos::<BITS, LIMBS>::of(m).0 << shift as usize);
    let [pu, pv, a, b, c] = points(parts.map(int));
    let (u, v) = plane_values([&pu, &pv], [a, b, c]);
    let h = gcd(u.magnitude(), v.magnitude());
    let (u, v) = match h == Uint::ONE {
        true => (u, v),
        false => (u.divided(h), v.divided(h)),
    };
    let (u, v) = if (u - v).negative() { (-u, -v) } else { (u, v) };
    let d = (u - v).0;
    [0, 1, 2].map(|k| {
        let numer = u.times(&pv[k]) - v.times(&pu[k]);
        let w = u128::try_from((pv[k] - pu[k]).magnitude()).expect("V − U below 2^95");
        let g = match w {
            0 => d,
            w => {
                let r = u128::try_from(d % Uint::from(w)).expect("a remainder below w");
                Uint::from(gcd_u128(w, r))
            }
        };
        let (n, d) = match g == Uint::ONE {
            true => (numer.magnitude(), d),
            false => (numer.magnitude() / g, d / g),
        };
        match scaled(n, d, scale) {
            (n, _, _) if n == Uint::ZERO => Rational::zero(),
            (n, d, 0) => {
                let approx = f64::from(&n) / f64::from(&d);
                Rational::from_lowest_words(numer.negative(), n.as_limbs(), d.as_limbs(), approx)
            }
            (n, d, rest) => {
                Rational::times_power_of_two(big(numer.negative(), n), big(false, d), rest)
            }
        }
    })
}

/// n/d · 2^`scale` (n/d in lowest terms, n ≥ 0, d > 0) as n′/d′ · 2^`rest` in lowest terms:
/// the power of two applied on the stack where the shifted term fits (the common powers of two
/// cancelled, `rest` = 0), else left whole to [`Rational::times_power_of_two`] on big integers.
fn scaled<const BITS: usize, const LIMBS: usize>(
    n: Uint<BITS, LIMBS>,
    d: Uint<BITS, LIMBS>,
    scale: i32,
) -> (Uint<BITS, LIMBS>, Uint<BITS, LIMBS>, i32) {
    let fits = |x: &Uint<BITS, LIMBS>, k: usize| x.bit_len() + k < BITS;
    let k = scale.unsigned_abs() as usize;
    if n == Uint::ZERO {
        (n, d, 0)
    } else if scale < 0 {
        let t = k.min(n.trailing_zeros());
        match fits(&d, k - t) {
            true => (n >> t, d << (k - t), 0),
            false => (n, d, scale),
        }
    } else {
        let t = k.min(d.trailing_zeros());
        match fits(&n, k - t) {
            true => (n << (k - t), d >> t, 0),
            false => (n, d, scale),
        }
    }
}

/// gcd(a, b) by Lehmer's algorithm (`ruint`), on 256 bits where both fit (a binary gcd on
/// 384 bits costs more than all the rest of a pierce point; `dashu-int`'s Lehmer allocates its
/// operands).
fn gcd<const BITS: usize, const LIMBS: usize>(
    a: Uint<BITS, LIMBS>,
    b: Uint<BITS, LIMBS>,
) -> Uint<BITS, LIMBS> {
    if BITS <= 256 || a.bit_len().max(b.bit_len()) <= 256 {
        let narrow = |x: Uint<BITS, LIMBS>| U256::from_limbs(limbs(x.as_limbs()));
        Uint::from_limbs(limbs(narrow(a).gcd(narrow(b)).as_limbs()))
    } else {
        a.gcd(b)
    }
}

/// The first `L` of the words `x`, zeros after them.
fn limbs<const L: usize>(x: &[u64]) -> [u64; L] {
    let mut out = [0; L];
    let n = x.len().min(L);
    out[..n].copy_from_slice(&x[..n]);
    out
}

/// The integer of sign `negative` and magnitude `m`, as a big integer.
fn big<const BITS: usize, const LIMBS: usize>(negative: bool, m: Uint<BITS, LIMBS>) -> BigInt {
    let sign = match (negative, m == Uint::ZERO) {
        (_, true) => Sign::NoSign,
        (true, false) => Sign::Minus,
        (false, false) => Sign::Plus,
    };
    BigInt::from_biguint(sign, from_words(m.as_limbs()))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::num::Num;
    use num_integer::Integer;
    use rand::rngs::StdRng;
    use rand::{RngExt, SeedableRng};

    /// The pierce point by rational arithmetic on the corners' exact values, independent of
    /// the grid and the gcd shortcuts: U + t·(V − U), t = du / (du − dv).
    fn oracle(p: &[[f64; 3]; 5]) -> [Rational; 3] {
        rational_oracle(p.map(|x| x.map(|c| Rational::from_float(c).expect("finite"))))
    }

    /// [`oracle`] on rational corners.
    fn rational_oracle(q: [[Rational; 3]; 5]) -> [Rational; 3] {
        let sub =
            |x: &[Rational; 3], y: &[Rational; 3]| [0, 1, 2].map(|k| x[k].clone() - y[k].clone());
        let (e, f) = (sub(&q[3], &q[2]), sub(&q[4], &q[2]));
        let n = [0, 1, 2].map(|k| {
            let (i, j) = ((k + 1) % 3, (k + 2) % 3);
            e[i].clone() * f[j].clone() - e[j].clone() * f[i].clone()
        });
        let value = |x: &[Rational; 3]| {
            let w = sub(x, &q[2]);
            (0..3)
                .map(|k| n[k].clone() * w[k].clone())
                .sum::<Rational>()
        };
        let (du, dv) = (value(&q[0]), value(&q[1]));
        let t = du.clone() / (du - dv);
        [0, 1, 2].map(|k| q[0][k].clone() + t.clone() * (q[1][k].clone() - q[0][k].clone()))
    }

    /// A coordinate: a random mantissa of 1 to 53 bits times 2^e, e in one of the half-open
    /// ranges `exps`, either sign, or a small integer (shared factors, equal coordinates).
    fn coordinate(rng: &mut StdRng, exps: &[(i32, i32)]) -> f64 {
        if rng.random_range(0..4) == 0 {
            return rng.random_range(-3..=3) as f64;
        }
        let bits = rng.random_range(1..=53);
        let m = rng.random_range(0..1u64 << bits) as f64;
        let s = if rng.random() { -1.0 } else { 1.0 };
        let (low, high) = exps[rng.random_range(0..exps.len())];
        s * m * 2f64.powi(rng.random_range(low..high))
    }

    /// On random edges and triangles whose grid integers take each path — up to 62 bits (256-bit
    /// stack integers), 63 to 94 bits (384-bit), wider (big integers) —, with small integer
    /// coordinates mixed in (shared factors, V − U = 0), the pierce point is the rational
    /// construction's, wherever the edge's ends lie on opposite sides of the plane.
    #[test]
    fn pierce_points_are_the_rational_construction() {
        let mut rng = StdRng::seed_from_u64(7);
        let mut seen = [0usize; 3];
        let mut near_bounds = [0usize; 2];
        for round in 0..8000 {
            // Grids of up to 62, 82, 97 and 202 bits, and mostly of about 94 bits.
            let exps: &[(i32, i32)] = match round % 5 {
                0 => &[(-5, 5)],
                1 => &[(-20, 10)],
                2 => &[(-45, 0)],
                3 => &[(-90, 60)],
                _ => &[(-42, -40), (0, 1)],
            };
            let p: [[f64; 3]; 5] =
                std::array::from_fn(|_| std::array::from_fn(|_| coordinate(&mut rng, exps)));
            let q = p.map(|x| x.map(|c| Rational::from_float(c).expect("finite")));
            let side = |x: &[Rational; 3]| {
                Rational::orient3d(
                    q[2].each_ref(),
                    q[3].each_ref(),
                    q[4].each_ref(),
                    x.each_ref(),
                    &(),
                )
            };
            let (su, sv) = (side(&q[0]), side(&q[1]));
            if su == Ordering::Equal || sv == Ordering::Equal || su == sv {
                continue;
            }
            let (parts, _) = common_grid::<15>(std::array::from_fn(|k| p[k / 3][k % 3]));
            let w = width(&parts);
            seen[usize::from(w > narrow(256)) + usize::from(w > narrow(384))] += 1;
            for (near, n) in near_bounds.iter_mut().zip([narrow(256), narrow(384)]) {
                *near += usize::from(n.abs_diff(w) <= 1);
            }
            let got = pierce(&p, (0, 1), [2, 3, 4]);
            let [x, y, z] = oracle(&p);
            // The same approximations too (the filters read them).
            let approx = |p: &Point3<Rational>| [&p.x, &p.y, &p.z].map(|c| c.approx());
            let want = Point3::new(x, y, z);
            assert_eq!(approx(&got), approx(&want), "corners {p:?}");
            assert_eq!(got, want, "corners {p:?}");
        }
        assert!(seen.iter().all(|&n| n > 300), "paths taken: {seen:?}");
        assert!(
            near_bounds.iter().all(|&n| n > 30),
            "grids at the bounds: {near_bounds:?}"
        );
    }

    /// Rational corners whose coordinates share small denominators (integers over a common
    /// denominator below 2⁶³: the stack path), denominators of about 40 bits whose lcm passes
    /// 2⁶³, or numerators near 2⁶² (big integers): the pierce point is the rational
    /// construction's, wherever the edge's ends lie on opposite sides of the plane.
    #[test]
    fn rational_pierce_points_are_the_rational_construction() {
        let mut rng = StdRng::seed_from_u64(17);
        let mut seen = [0usize; 2];
        for round in 0..3000 {
            let (denominators, top): (&[i64], i64) = match round % 3 {
                0 => (&[1, 3, 10, 1000, 3 << 10], 1 << 20),
                1 => (&[1_099_511_627_791, 1_099_511_627_689, 7], 1 << 41),
                _ => (&[1, 5], 1 << 62),
            };
            let mut coordinate = || {
                let d = denominators[rng.random_range(0..denominators.len())];
                Rational::new(BigInt::from(rng.random_range(-top..top)), BigInt::from(d))
            };
            let q: [[Rational; 3]; 5] =
                std::array::from_fn(|_| std::array::from_fn(|_| coordinate()));
            let side = |x: &[Rational; 3]| {
                let [a, b, c] = [&q[2], &q[3], &q[4]].map(|p| p.each_ref());
                Rational::orient3d(a, b, c, x.each_ref(), &())
            };
            let (su, sv) = (side(&q[0]), side(&q[1]));
            if su == Ordering::Equal || sv == Ordering::Equal || su == sv {
                continue;
            }
            let points = q.clone().map(|[x, y, z]| Point3::new(x, y, z));
            let coords = std::array::from_fn(|k| points[k / 3].coord(k % 3));
            seen[usize::from(small_grid(coords).is_none())] += 1;
            let got = pierce_rational(points.each_ref());
            let [x, y, z] = rational_oracle(q);
            assert_eq!(got, Point3::new(x, y, z), "corners {points:?}");
        }
        assert!(seen.iter().all(|&n| n > 300), "paths taken: {seen:?}");
    }

    /// Corners one bit past each stack path's bound (63 and 95 bits) whose section numerators
    /// need the whole width of the path below plus a bit (256 and 384 bits before the division
    /// by the small gcd; found by a hill-climbing search over f64 corners) take the next path,
    /// and the same corners with their large coordinates halved (62 and 94 bits, numerators of
    /// 252 and 380 bits) stay on theirs: both pierce exactly. (Random corners rarely come near
    /// the bound.)
    #[test]
    fn corners_at_and_past_a_bound_pierce_exactly() {
        let cases: [(u32, [[f64; 3]; 5]); 2] = [
            (
                63,
                [
                    [
                        9055315173615903744.0,
                        9107482703943990272.0,
                        9077110266289732608.0,
                    ],
                    [
                        -8941048411866082304.0,
                        -9214067086600690688.0,
                        9220341277975477248.0,
                    ],
                    [
                        -9222637362244305920.0,
                        9168468029038298112.0,
                        -8429363278516539.0,
                    ],
                    [
                        8479138915574279.0,
                        -9034736414205135872.0,
                        9174084418030732288.0,
                    ],
                    [
                        9015369827622544384.0,
                        -8877480577800155.0,
                        -9152374054353077248.0,
                    ],
                ],
            ),
            (
                95,
                [
                    [
                        38892282525652868645963956224.0,
                        39116340362325088433982144512.0,
                        38985891735900252811944787968.0,
                    ],
                    [
                        -38401510520917561827324329984.0,
                        -39574116800099966315971739648.0,
                        39601064246863519870152081408.0,
                    ],
                    [
                        -39610925853706999088619192320.0,
                        39378270339141068722538545152.0,
                        -8429363278516539.0,
                    ],
                    [
                        8479138915574279.0,
                        -38803897426991368405476442112.0,
                        39402392546185187899891253248.0,
                    ],
                    [
                        38720718570983985561588465664.0,
                        -8877480577800155.0,
                        -39309147244205393217121681408.0,
                    ],
                ],
            ),
        ];
        let halved =
            |p: [[f64; 3]; 5]| p.map(|c| c.map(|x| if x.abs() > 1e17 { x / 2.0 } else { x }));
        for (bits, p) in cases
            .into_iter()
            .flat_map(|(b, p)| [(b, p), (b - 1, halved(p))])
        {
            let (parts, _) = common_grid::<15>(std::array::from_fn(|k| p[k / 3][k % 3]));
            assert_eq!(width(&parts), bits);
            let [x, y, z] = oracle(&p);
            assert_eq!(
                pierce(&p, (0, 1), [2, 3, 4]),
                Point3::new(x, y, z),
                "{bits} bits"
            );
        }
    }
    /// `scaled` keeps the value n/d · 2^scale and lowest terms, and leaves a power of two to
    /// big integers only where the shifted term would not fit: on numerators and denominators
    /// with up to 40 factors of two (one of them odd), widths from a few bits to 250, and scales
    /// of either sign up to 300 (past the stack width). The oracle multiplies rationals.
    #[test]
    fn scaled_keeps_the_value_in_lowest_terms() {
        let mut rng = StdRng::seed_from_u64(11);
        let mut kinds = [0usize; 4];
        for _ in 0..4000 {
            let odd = |rng: &mut StdRng, bits: usize| {
                let words: [u64; 4] = std::array::from_fn(|_| rng.random());
                (U256::from_limbs(words) >> (256 - bits)) | U256::ONE
            };
            let twos = rng.random_range(0..=40);
            let (a, b) = match rng.random() {
                true => (twos, 0),
                false => (0, twos),
            };
            let (bn, bd) = (rng.random_range(1..=250 - a), rng.random_range(1..=250 - b));
            let n = odd(&mut rng, bn) << a;
            let d = odd(&mut rng, bd) << b;
            if big(false, n).gcd(&big(false, d)) != BigInt::from(1) {
                continue;
            }
            let scale = rng.random_range(-300..=300);
            let (m, e, rest) = scaled(n, d, scale);
            let power = |k: i32| {
                let p = Rational::from_integer(BigInt::from(1) << k.unsigned_abs());
                if k >= 0 {
                    p
                } else {
                    Rational::from_i64(1) / p
                }
            };
            let value = |n, d, k| Rational::new(big(false, n), big(false, d)) * power(k);
            assert_eq!(
                value(m, e, rest),
                value(n, d, scale),
                "{n} / {d} · 2^{scale}"
            );
            assert_eq!(big(false, m).gcd(&big(false, e)), BigInt::from(1));
            assert!(e > U256::ZERO);
            // A power of two is left over only where shifting the term would overflow.
            let shifted = if scale < 0 { e } else { m };
            let width = shifted.bit_len() + rest.unsigned_abs() as usize;
            assert!(rest == 0 || width >= 256, "{n} / {d} · 2^{scale}");
            kinds[usize::from(scale > 0) * 2 + usize::from(rest != 0)] += 1;
        }
        assert!(kinds.iter().all(|&k| k > 200), "{kinds:?}");
    }
}
