//! The number trait that every geometric algorithm is generic over, and its backends.
//!
//! * [`Rational`] (`num-rational`'s `BigRational`): exact, the default.
//! * `GmpRational` (`rug::Rational`, feature `gmp`): exact, faster big numbers.
//! * [`Float`] (`f64`) with a run-time tolerance [`Tolerance`] ε (seed 000 §5.2).
//!
//! Exact backends parse decimal strings ("4.5040114e+00", "0.1") and fractions ("1/3")
//! without rounding, and convert from `f64` losslessly.

mod big;
mod dyadic;
mod float;
#[cfg(feature = "gmp")]
mod gmp;
mod grid_orient;
mod interval;
mod lattice;
mod literal;
mod quotient;
mod rational;

pub(crate) use big::{from_words, gcd_u128};
pub(crate) use dyadic::det_sum;
pub(crate) use float::{
    exact_orient3d_f64, exact_orient_f64, segment_distance, short_f64, PlaneF64,
};
pub use float::{Float, Tolerance, TooFine};
#[cfg(feature = "gmp")]
pub use gmp::GmpRational;
pub(crate) use grid_orient::common_grid;
pub(crate) use interval::Interval;
pub(crate) use lattice::lattice_det_sum;
pub use literal::Literal;
use literal::Parts;
pub use rational::Rational;

use num_bigint::BigInt;
use std::cmp::Ordering;
use std::fmt::{Debug, Display};
use std::hash::Hash;
use std::ops::{Add, Div, Mul, Neg, Sub};

/// Why a number could not be made.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum NumError {
    /// The text is not a decimal number or a fraction `p/q`.
    #[error("`{0}` is not a number (expected a decimal such as 4.5e-1 or a fraction p/q)")]
    Syntax(String),
    /// A fraction with denominator zero.
    #[error("`{0}` has a zero denominator")]
    ZeroDenominator(String),
    /// The decimal exponent is too large to represent exactly in reasonable memory.
    #[error("`{0}` has an exponent outside ±{max}", max = literal::MAX_EXPONENT)]
    ExponentRange(String),
    /// NaN or an infinity.
    #[error("{0} is not finite")]
    NotFinite(f64),
}

/// A coordinate number: exact rationals or ε-floats behind one interface, the layer every
/// geometric algorithm of the crate is generic over.
///
/// Arithmetic is by value; `Ord` is the exact order of the stored values (for [`Float`], the
/// total order of `f64`), so sweeps and canonical forms are deterministic. The tolerance ε of
/// float mode lives in the run-time context [`Num::Ctx`] ([`Tolerance`]), and enters in three
/// places only:
///
/// * **The grid** ([`Num::grid`]): 2D float results are snap-rounded to the grid of the
///   largest power of two not above ε, on grid integers with exact integer predicates; one
///   place in `yin2` chooses that stage for every construction and operation.
/// * **Location**: a point within ε of a set's boundary is located on it ([`Num::tolerance`]):
///   in 2D by its distance to the nearest edge, in 3D by [`Num::orient3d`] and
///   [`Num::orient2d`] under ε (the only callers that pass them a context with ε > 0).
/// * **Its own resolution** ([`Num::resolve_ctx`], [`Num::combine_ctx`]): the default ε from
///   the input's extent, the refusal of an ε too fine for its coordinates, and the coarser ε of
///   two operands.
///
/// Every other decision, in both modes, is exact: the constructions, validation and Boolean
/// operations call the predicates with the exact context ([`Num::exact_ctx`]: for floats the
/// exact sign on the `f64` values), and 3D float operations are computed exactly on the
/// operands' `f64` values, their results' vertices then rounded to `f64`.
pub trait Num:
    Clone
    + Debug
    + Display
    + Eq
    + Ord
    + Hash
    + Send
    + Sync
    + 'static
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<Output = Self>
    + Div<Output = Self>
    + Neg<Output = Self>
{
    /// Run-time context of the backend: `()` for exact numbers, the tolerance ε for floats.
    type Ctx: Copy + Debug + Default + PartialEq + Send + Sync + 'static;

    /// True for the exact backends, where every predicate is decided without rounding.
    const EXACT: bool;

    /// The integer `v`.
    fn from_i64(v: i64) -> Self;

    /// The value of a finite `f64`, without rounding in exact backends.
    fn from_f64(v: f64) -> Result<Self, NumError>;

    /// The value of a parsed literal (exact backends: without rounding).
    fn from_literal(lit: &Literal) -> Self;

    /// Parse a decimal ("4.5040114e+00", "-0.1") or a fraction ("1/3").
    fn parse(s: &str) -> Result<Self, NumError> {
        Literal::parse(s).map(|lit| Self::from_literal(&lit))
    }

    /// The nearest `f64` (for output and rendering, never for exact decisions).
    fn to_f64(&self) -> f64;

    /// The exact value as a numerator and a positive denominator in lowest terms (float
    /// backends: of the `f64` value; panics if it is not finite).
    fn fraction(&self) -> (BigInt, BigInt);

    /// The exact value as a [`Rational`] (float backends: of the `f64` value; panics if it is
    /// not finite). Default: from [`Num::fraction`].
    fn rational(&self) -> Rational {
        let (n, d) = self.fraction();
        Rational::new(n, d)
    }

    /// The exact value as a numerator and a positive denominator in lowest terms when both fit
    /// in an `i64`, else `None`. Default: from [`Num::fraction`].
    fn small_fraction(&self) -> Option<(i64, i64)> {
        let (n, d) = self.fraction();
        Some((i64::try_from(n).ok()?, i64::try_from(d).ok()?))
    }

    /// An `f64` within 4 ulps of the value (relative; within 2⁻¹⁰⁶² absolute below the normal
    /// range), or NaN or an infinity when out of range: the input of floating-point filters,
    /// never of a decision by itself. Default: [`Num::to_f64`].
    fn approx(&self) -> f64 {
        self.to_f64()
    }

    /// The sign of `self` compared with zero.
    fn sign(&self) -> Ordering;

    /// False for NaN and infinities (float backend only).
    fn is_finite(&self) -> bool {
        true
    }

    /// Orientation of `c` relative to the directed line `a → b` (the Left test of seed 002,
    /// Alg. 1): `Greater` if `c` is to the left, `Less` if to the right, `Equal` if on the line
    /// (under a float context with ε > 0: within ε of it; only 3D location passes one).
    fn orient2d(a: [&Self; 2], b: [&Self; 2], c: [&Self; 2], ctx: &Self::Ctx) -> Ordering;

    /// Orientation of `d` relative to the plane through `a`, `b`, `c`: the sign of
    /// det[b − a, c − a, d − a], `Greater` on the side the normal (b − a) × (c − a) points to
    /// (yin3 docs: *Primitives*), `Equal` on the plane (under a float context with ε > 0: within ε of
    /// it, which only 3D location passes; the sign otherwise is exact, by Shewchuk's adaptive
    /// `orient3d`).
    fn orient3d(
        a: [&Self; 3],
        b: [&Self; 3],
        c: [&Self; 3],
        d: [&Self; 3],
        ctx: &Self::Ctx,
    ) -> Ordering;

    /// The context whose predicates decide without tolerance (float mode: ε = 0, the exact sign
    /// of Shewchuk's adaptive determinant). The edges of a valid set never cross exactly, so
    /// orders between them are decided with it.
    fn exact_ctx() -> Self::Ctx {
        Self::Ctx::default()
    }

    /// The context for an operation on two sets with contexts `a` and `b`.
    fn combine_ctx(a: Self::Ctx, b: Self::Ctx) -> Self::Ctx {
        let _ = b;
        a
    }

    /// Fill in context defaults that depend on the input and check the context against it,
    /// given the larger side `span` of its bounding box and its largest coordinate
    /// `magnitude` as `f64`s (float mode: the default ε, or [`TooFine`]).
    fn resolve_ctx(ctx: Self::Ctx, span: f64, magnitude: f64) -> Result<Self::Ctx, TooFine> {
        let _ = (span, magnitude);
        Ok(ctx)
    }

    /// The spacing of the grid that float mode snaps results to (seed 000 §5.2): the largest
    /// power of two not above ε. `None` for exact backends, which never snap.
    fn grid(ctx: &Self::Ctx) -> Option<f64> {
        let _ = ctx;
        None
    }

    /// Float mode's ε, the distance within which a point is located on the boundary
    /// ([`Tolerance`]); 0 for exact backends.
    fn tolerance(ctx: &Self::Ctx) -> f64 {
        let _ = ctx;
        0.0
    }

    /// The crossing point of the lines `ab` and `cd` (not parallel). Default: `a + t (b − a)`
    /// with `t = ((c − a) × (d − c)) / ((b − a) × (d − c))`; [`Rational`] computes it in
    /// homogeneous integers with one reduction per coordinate.
    fn crossing(a: [&Self; 2], b: [&Self; 2], c: [&Self; 2], d: [&Self; 2]) -> [Self; 2] {
        let cross =
            |u: [Self; 2], v: [Self; 2]| u[0].clone() * v[1].clone() - u[1].clone() * v[0].clone();
        let diff = |p: [&Self; 2], q: [&Self; 2]| {
            [p[0].clone() - q[0].clone(), p[1].clone() - q[1].clone()]
        };
        let (ab, dc) = (diff(b, a), diff(d, c));
        let t = cross(diff(c, a), dc.clone()) / cross(ab.clone(), dc);
        let [x, y] = ab;
        [a[0].clone() + t.clone() * x, a[1].clone() + t * y]
    }

    /// The integer 0.
    fn zero() -> Self {
        Self::from_i64(0)
    }

    /// Half of `self` (midpoints are exact in exact backends).
    fn half(&self) -> Self {
        self.clone() / Self::from_i64(2)
    }

    /// The number nearest to the exact `r`: `r` itself in exact backends; in float mode the
    /// nearest `f64` (0 below half the least subnormal, an infinity beyond `f64::MAX`).
    fn nearest(r: &Rational) -> Self;
}

/// The sum of `terms`, added pairwise in a balanced tree: exact sums of many fractions with
/// unrelated denominators then cost O(M(s) log n) for a result of size s, not O(n · s).
pub(crate) fn balanced_sum<N: Num>(mut terms: Vec<N>) -> N {
    while terms.len() > 1 {
        let mut next = Vec::with_capacity(terms.len().div_ceil(2));
        let mut it = terms.into_iter();
        while let Some(a) = it.next() {
            next.push(match it.next() {
                Some(b) => a + b,
                None => a,
            });
        }
        terms = next;
    }
    terms.pop().unwrap_or_else(N::zero)
}

/// The least positive L such that every one of `values` times L is an integer, if L and each
/// of those integers lie below `bound` in magnitude.
pub(crate) fn common_denominator<'a, N: Num + 'a>(
    values: impl Iterator<Item = &'a N> + Clone,
    bound: i64,
) -> Option<i64> {
    let mut l: i64 = 1;
    for v in values.clone() {
        let (_, d) = v.small_fraction()?;
        if l % d != 0 {
            l = (l / gcd::binary_u64(l as u64, d as u64) as i64).checked_mul(d)?;
            if l >= bound {
                return None;
            }
        }
    }
    for v in values {
        let (n, d) = v.small_fraction()?;
        if n.checked_mul(l / d)?.unsigned_abs() >= bound.unsigned_abs() {
            return None;
        }
    }
    Some(l)
}

/// The sign of `(b − a) × (c − a)` evaluated in `f64` from coordinates each within 3 ulps of
/// the exact ones, if the error bound proves it; `None` if it cannot decide
/// ([`filtered_orient_sum`] of one point).
pub(crate) fn filtered_orient(a: [f64; 2], b: [f64; 2], c: [f64; 2]) -> Option<Ordering> {
    filtered_orient_sum(a, b, [c])
}

/// The sign of the sum of `(b − a) × (cᵢ − a)` over the points `c` — for three points, the
/// orientation of their centroid, which is never constructed — evaluated in `f64` from
/// coordinates each within 3 ulps of the exact ones, if the error bound proves it; `None` if
/// it cannot decide.
///
/// A semi-static bound, as [`filtered_orient3d`]'s: with M the largest coordinate, u = 2⁻⁵³
/// and D the largest computed difference, each difference is off by at most e = 8M·u (3u·|x|
/// per input, and the subtraction's rounding) and every difference is at most D′ = D + e; each
/// product is then off by at most 2D′e + e² ≤ 3D′e, and each determinant by
/// E = 6D′e + 6D′²u. Each computed determinant is at most 2D′² + E, so adding K of them
/// rounds by at most (K − 1)·u·K·(2D′² + E): the sum is off by at most
/// K·E + (K − 1)·u·K·(2D′² + E). Twice that is returned, which also covers inputs 4 whole
/// ulps off ([`Num::approx`]'s promise: e ≤ 18M·u).
pub(crate) fn filtered_orient_sum<const K: usize>(
    a: [f64; 2],
    b: [f64; 2],
    c: [[f64; 2]; K],
) -> Option<Ordering> {
    let mut m = [a[0], a[1], b[0], b[1]]
        .iter()
        .fold(0.0f64, |m, v| m.max(v.abs()));
    let u = [b[0] - a[0], b[1] - a[1]];
    let mut reach = u[0].abs().max(u[1].abs());
    let mut det = 0.0;
    for c in c {
        m = m.max(c[0].abs()).max(c[1].abs());
        let v = [c[0] - a[0], c[1] - a[1]];
        reach = reach.max(v[0].abs()).max(v[1].abs());
        det += u[0] * v[1] - u[1] * v[0];
    }
    let unit = f64::EPSILON * 0.5;
    let e = 8.0 * m * unit;
    let reach = reach + e;
    let one = reach * (6.0 * e + 6.0 * reach * unit);
    let k = K as f64;
    let rounding = match K {
        1 => 0.0,
        _ => (k - 1.0) * unit * k * (2.0 * reach * reach + one),
    };
    let bound = 2.0 * (k * one + rounding);
    // Below 1e-140 products of two differences could lose bits to underflow.
    if !det.is_finite() || !bound.is_finite() || reach < 1e-140 {
        return None;
    }
    outside(det, bound)
}

/// The sign of `det` if it lies outside [−bound, bound] (then the exact value it approximates
/// within `bound` has that sign too); `None` inside.
fn outside(det: f64, bound: f64) -> Option<Ordering> {
    if det > bound {
        Some(Ordering::Greater)
    } else if det < -bound {
        Some(Ordering::Less)
    } else {
        None
    }
}

/// The sign of det[b − a, c − a, d − a] evaluated in `f64` from coordinates each within
/// 3 ulps of the exact ones, if the error bound proves it; `None` if it cannot decide
/// ([`NearPlane::certain_side`] of `d` against the plane through `a`, `b`, `c`).
pub(crate) fn filtered_orient3d(
    a: [f64; 3],
    b: [f64; 3],
    c: [f64; 3],
    d: [f64; 3],
) -> Option<Ordering> {
    NearPlane::new(a, b, c).certain_side(d)
}

/// The plane through three points given by coordinates each within 3 ulps of the exact ones,
/// prepared so that the side of many points costs a dot product and a bound each:
/// det[b − a, c − a, d − a] = (d − a) · ((b − a) × (c − a)).
///
/// The bound is semi-static, in the size of the differences rather than of the coordinates, so
/// that small triangles far from the origin are decided too. With M the largest coordinate of
/// the four points, u = 2⁻⁵³ and D the largest computed difference, each difference is off by
/// at most e = 8M·u and every difference, true or computed, is at most D′ = D + e; each 2×2
/// minor of the normal is then off by at most 4D′e + 2e² + 6D′²u, and the determinant by
/// 3(2D′²e + D′(4D′e + 2e² + 6D′²u)) + 30D′³u ≤ 24D′²e + 48D′³u; twice that is safe against
/// the rounding of the bound itself.
pub(crate) struct NearPlane {
    /// The first corner, from which the differences are taken.
    a: [f64; 3],
    /// (b − a) × (c − a), computed.
    normal: [f64; 3],
    /// The largest coordinate of the corners in magnitude.
    largest: f64,
    /// The largest computed difference b − a, c − a in magnitude.
    reach: f64,
}

impl NearPlane {
    /// The plane through `a`, `b`, `c`.
    pub(crate) fn new(a: [f64; 3], b: [f64; 3], c: [f64; 3]) -> NearPlane {
        let u = [0, 1, 2].map(|k| b[k] - a[k]);
        let v = [0, 1, 2].map(|k| c[k] - a[k]);
        let largest = (a.iter().chain(&b).chain(&c)).fold(0.0f64, |m, x| m.max(x.abs()));
        NearPlane {
            a,
            normal: [
                u[1] * v[2] - u[2] * v[1],
                u[2] * v[0] - u[0] * v[2],
                u[0] * v[1] - u[1] * v[0],
            ],
            largest,
            reach: u.iter().chain(&v).fold(0.0f64, |m, x| m.max(x.abs())),
        }
    }

    /// The plane of the triangle `t`, indices into the points `p`.
    pub(crate) fn of_triangle(p: &[[f64; 3]], t: [usize; 3]) -> NearPlane {
        NearPlane::new(p[t[0]], p[t[1]], p[t[2]])
    }

    /// The sign of det[b − a, c − a, d − a] of the plane's corners and `d` (also within
    /// 3 ulps of its exact value), if the bound (type docs) proves it; `None` if it cannot.
    pub(crate) fn certain_side(&self, d: [f64; 3]) -> Option<Ordering> {
        let w = [0, 1, 2].map(|k| d[k] - self.a[k]);
        let det = w[0] * self.normal[0] + w[1] * self.normal[1] + w[2] * self.normal[2];
        let m = d.iter().fold(self.largest, |m, x| m.max(x.abs()));
        let unit = f64::EPSILON * 0.5;
        let e = 8.0 * m * unit;
        let reach = w.iter().fold(self.reach, |r, x| r.max(x.abs())) + e;
        let bound = 2.0 * reach * reach * (24.0 * e + 48.0 * reach * unit);
        // Below 1e-90 products of three differences could lose bits to underflow.
        // A NaN or infinite coordinate makes `det` NaN or infinite.
        if !det.is_finite() || !bound.is_finite() || reach < 1e-90 {
            return None;
        }
        outside(det, bound)
    }
}

/// Sign of det[b − a, c − a, d − a] in exact arithmetic: the shared body of the exact
/// backends' [`Num::orient3d`].
pub(crate) fn exact_orient3d<N>(a: [&N; 3], b: [&N; 3], c: [&N; 3], d: [&N; 3]) -> Ordering
where
    N: Clone + Ord + Add<Output = N> + Sub<Output = N> + Mul<Output = N>,
{
    let diff = |p: [&N; 3]| [0, 1, 2].map(|k| p[k].clone() - a[k].clone());
    let (u, v, w) = (diff(b), diff(c), diff(d));
    let minor = |i: usize, j: usize| v[i].clone() * w[j].clone() - v[j].clone() * w[i].clone();
    let pos = u[0].clone() * minor(1, 2) + u[2].clone() * minor(0, 1);
    let neg = u[1].clone() * minor(0, 2);
    pos.cmp(&neg)
}

/// Sign of the 2×2 determinant `(b − a) × (c − a)` in exact arithmetic: the shared body of
/// the exact backends' [`Num::orient2d`].
pub(crate) fn exact_orient<N>(a: [&N; 2], b: [&N; 2], c: [&N; 2]) -> Ordering
where
    N: Clone + Ord + Sub<Output = N> + Mul<Output = N>,
{
    let l = (b[0].clone() - a[0].clone()) * (c[1].clone() - a[1].clone());
    let r = (b[1].clone() - a[1].clone()) * (c[0].clone() - a[0].clone());
    l.cmp(&r)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The exact value of `x` moved by `k` quarter ulps (so within 3 ulps for |k| ≤ 12).
    fn off_by(x: f64, k: i64) -> Rational {
        let ulp = (x.abs().max(f64::MIN_POSITIVE)).next_up() - x.abs().max(f64::MIN_POSITIVE);
        Rational::from_f64(x).expect("finite")
            + Rational::from_f64(ulp / 4.0).expect("finite") * Rational::from_i64(k)
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(yinset_testkit::cases(3000)))]

        /// Where [`filtered_orient_sum`] decides, its sign is the exact sign of the sum of the
        /// three orientations, on exact values up to 3 ulps from the `f64`s it is given. The
        /// points are often on the line (zero terms), two of them mirror images across a
        /// point of the line (terms that cancel: a zero sum), or either nudged by an ulp.
        #[test]
        fn filtered_orient_sum_is_the_exact_sign_of_the_sum(
            a in proptest::array::uniform2(-(1i64 << 52)..(1i64 << 52)),
            b in proptest::array::uniform2(-(1i64 << 52)..(1i64 << 52)),
            c in proptest::array::uniform2(-1000i32..1000),
            t in proptest::array::uniform3(-8i32..8),
            kind in 0u8..4,
            scale in -40i32..40,
            fine in proptest::bool::ANY,
            nudge in proptest::array::uniform2(-1i32..2),
            off in proptest::array::uniform::<_, 10>(-12i64..13),
        ) {
            let s = 2f64.powi(scale);
            let f = |p: [i32; 2]| p.map(|v| f64::from(v) * s);
            // Small integers (every point of the line below is exact), or full mantissas
            // (points of the line rounded: sums near zero whose f64 terms round).
            let g = |p: [i64; 2]| match fine {
                true => p.map(|v| v as f64 * s / 2f64.powi(43)),
                false => f(p.map(|v| (v >> 42) as i32)),
            };
            let (a, b) = (g(a), g(b));
            // A point of the line a + t (b − a), as f64 computes it.
            let on = |t: i32| [0, 1].map(|k| a[k] + f64::from(t) * (b[k] - a[k]));
            let c0 = f(c);
            let mirror = |p: [f64; 2], m: [f64; 2]| [2.0 * m[0] - p[0], 2.0 * m[1] - p[1]];
            let mut cs = match kind {
                0 => [on(t[0]), on(t[1]), on(t[2])],
                1 => [c0, mirror(c0, on(t[0])), on(t[1])],
                2 => [c0, on(t[0]), on(t[1])],
                _ => [c0, f([t[0], t[1]]), f([t[2], t[0]])],
            };
            cs[0][0] += f64::from(nudge[0]) * f64::EPSILON * cs[0][0].abs();
            cs[1][1] += f64::from(nudge[1]) * f64::EPSILON * cs[1][1].abs();
            let mut k = off.into_iter();
            let mut exact = |p: [f64; 2]| p.map(|x| off_by(x, k.next().unwrap_or(0)));
            let (ea, eb) = (exact(a), exact(b));
            let ec = cs.map(&mut exact);
            let det = |c: &[Rational; 2]| {
                (eb[0].clone() - ea[0].clone()) * (c[1].clone() - ea[1].clone())
                    - (eb[1].clone() - ea[1].clone()) * (c[0].clone() - ea[0].clone())
            };
            let sum = ec.iter().fold(Rational::from_i64(0), |acc, c| acc + det(c));
            if let Some(sign) = filtered_orient_sum(a, b, cs) {
                proptest::prop_assert_eq!(sign, sum.sign());
            }
        }
    }

    #[test]
    fn filter_decides_clear_cases_and_defers_near_degenerate_ones() {
        assert_eq!(
            filtered_orient([0.0, 0.0], [1.0, 0.0], [0.0, 1.0]),
            Some(Ordering::Greater)
        );
        assert_eq!(
            filtered_orient([0.0, 0.0], [1.0, 0.0], [0.0, -1.0]),
            Some(Ordering::Less)
        );
        assert_eq!(filtered_orient([0.0, 0.0], [1.0, 1.0], [2.0, 2.0]), None);
        // Three points: one on the line, two left of it (the centroid is left).
        let cs = [[2.0, 0.0], [0.0, 1.0], [5.0, 0.5]];
        assert_eq!(
            filtered_orient_sum([0.0, 0.0], [1.0, 0.0], cs),
            Some(Ordering::Greater)
        );
        // Mirror images across the line: a zero sum, which the filter leaves undecided.
        let cs = [[2.0, 1.0], [2.0, -1.0], [3.0, 0.0]];
        assert_eq!(filtered_orient_sum([0.0, 0.0], [1.0, 0.0], cs), None);
        assert_eq!(
            filtered_orient([0.0, 0.0], [1.0, 1.0], [2.0, 2.0 + 1e-15]),
            None
        );
        assert_eq!(
            filtered_orient([0.0, 0.0], [f64::MAX, 0.0], [0.0, 1.0]),
            None
        );
    }

    /// The default `crossing` (float mode's) on small integers, exact in `f64`: the line
    /// through (1, 2) and (5, 4) meets the line through (2, 5) and (4, 1) at (3, 3), the
    /// midpoint of both segments (t = (−10) / (−20) = 1/2 by hand).
    #[test]
    fn default_crossing_by_hand() {
        let f = Float::new;
        let (a, b, c, d) = (
            [f(1.0), f(2.0)],
            [f(5.0), f(4.0)],
            [f(2.0), f(5.0)],
            [f(4.0), f(1.0)],
        );
        let x = Float::crossing(a.each_ref(), b.each_ref(), c.each_ref(), d.each_ref());
        assert_eq!(x, [f(3.0), f(3.0)]);
    }

    /// On a nearly flat tetrahedron of coordinates near 10⁶ to 10⁷, where a bound in m²·u
    /// instead of m³·u decides the wrong sign, the filter either defers or agrees with
    /// `exact_orient3d` on the same values as rationals (Greater).
    #[test]
    fn filtered_orient3d_on_a_nearly_flat_tetrahedron_far_out() {
        let a = [2097599.677707631, 4095721.8480184656, 1877360.4406349268];
        let b = [-1669836.9282060806, -3562891.905917269, 601311.7009010501];
        let c = [-5079842.93925414, -4752655.350767068, 6216525.025966568];
        let d = [-6350174.638304699, -6398879.3503321735, 6890008.074510893];
        let q = |p: [f64; 3]| p.map(|v| Rational::from_f64(v).unwrap());
        let (qa, qb, qc, qd) = (q(a), q(b), q(c), q(d));
        let exact = exact_orient3d(qa.each_ref(), qb.each_ref(), qc.each_ref(), qd.each_ref());
        assert_eq!(exact, Ordering::Greater);
        assert!(matches!(
            filtered_orient3d(a, b, c, d),
            None | Some(Ordering::Greater)
        ));
    }

    #[test]
    fn filtered_orientation_agrees_with_exact_on_near_collinear_rationals() {
        // c is 1e-30 above the line through a and b: the filter must defer to exact arithmetic.
        let r = |s: &str| Rational::parse(s).unwrap();
        let (a, b) = ([r("0"), r("0")], [r("1"), r("1")]);
        let c = [r("0.5"), r("0.500000000000000000000000000001")];
        let o = Rational::orient2d([&a[0], &a[1]], [&b[0], &b[1]], [&c[0], &c[1]], &());
        assert_eq!(o, Ordering::Greater);
    }
}
