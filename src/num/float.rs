//! The float backend: `f64` coordinates with a run-time tolerance ε (seed 000 §5.2).

use super::grid_orient::grid_orient3d;
use super::{Literal, Num, NumError, Parts, Rational};
use std::cmp::Ordering;
use std::fmt;
use std::hash::{Hash, Hasher};
use std::ops::{Add, Div, Mul, Neg, Sub};

/// An `f64` coordinate, totally ordered, with `-0.0` normalized to `0.0` so that `Eq`,
/// `Ord` and `Hash` agree.
#[derive(Clone, Copy, Debug, Default)]
pub struct Float(f64);

impl Float {
    /// Wrap an `f64` (non-finite values are rejected by the Yin-set constructors).
    pub fn new(v: f64) -> Float {
        Float(v + 0.0)
    }

    /// The wrapped value.
    pub fn get(self) -> f64 {
        self.0
    }
}

/// Float mode's tolerance ε (seed 000 §5.2 made precise): results are snap-rounded to the grid
/// g·ℤ², g the largest power of two not above ε ([`Tolerance::grid`]).
///
/// # Contract
///
/// * **Grid.** Every vertex of a float set is a point of g·ℤ² (g a power of two, so the grid
///   is the same wherever the shape sits: translating the input by a multiple of g translates
///   the result). The grid is chosen from ε alone; the input's coordinates only decide whether
///   it is representable: every coordinate must be at most 2⁵¹·g in magnitude, so that grid
///   points are exact `f64`s and the snapping runs on integers below 2⁵² relative to a local
///   origin, with exact integer predicates. A finer ε is refused with
///   `YinError::ToleranceTooFine { requested, representable }`, never coarsened.
/// * **Default ε.** `Tolerance::default()` asks for [`Tolerance::RELATIVE_DEFAULT`] times the
///   larger side of the input's bounding box (not its distance from the origin), raised to the
///   finest representable grid when the shape sits far from the origin, and rounded down to a
///   power of two (so ε = g, and the f64 rounding of a translated box does not change it).
/// * **Displacement.** Snap rounding moves every boundary point by at most g·√2/2 (half a
///   pixel's diagonal: pieces are rerouted through the centres of pixels they meet, after
///   Hobby's hot pixels), so the result's boundary lies within g of the exact one; features
///   thinner than the grid (slivers, spikes, gaps) may vanish or close, and curves closer than
///   g may merge. An input that vanishes entirely on its grid is refused
///   (`YinError::CollapsedOnGrid`), not turned into 0̂.
/// * **Accuracy.** Every float result F is exactly valid (its `f64` vertices read as rationals
///   pass the exact validator). Against the exact result E of the same operation on the same
///   input values, area(F △ E) ≤ C · g · L ≤ C · ε · L with **C = 1**, L the total boundary
///   length of the operands plus those of E and of F (a feature much smaller than the grid
///   around a point halfway between grid points can round to the four grid points around it
///   and grow to a square of side g, whose boundary only F has). C is measured, not proved:
///   `tests/float_mode.rs` compares every operation with exact mode, and the largest
///   area(F △ E) / (ε · L) over the 11 135 comparisons of its default run is 0.22 (a
///   complement of a jittered input). Betti numbers agree with exact mode when no feature of
///   the input is thinner than g.
/// * **Location.** [`crate::yin2::YinSet2::locate`] reports a point as on the boundary when
///   its distance to the boundary is at most ε, whatever the direction of the nearest edge;
///   otherwise inside or outside exactly.
/// * **3D.** [`crate::yin3::YinSet3`] in float mode computes every operation exactly on the
///   operands' `f64` values and rounds the result's vertices to the nearest `f64`s (no grid):
///   a valid rounded result with the exact result's topology, or
///   `Yin3Error::Unrepresentable`; ε decides `locate`'s boundary
///   band (a point at Euclidean distance at most ε from a face, decided exactly), the default
///   and the representable ε as above (the contract in full: [`crate::yin3`], *Float mode*).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Tolerance {
    eps: f64,
}

/// The largest power of two not above a finite `v > 0` (exact, subnormals included).
fn pow2_floor(v: f64) -> f64 {
    let bits = v.to_bits();
    if v >= f64::MIN_POSITIVE {
        f64::from_bits(bits & 0xfff0_0000_0000_0000)
    } else {
        f64::from_bits(1u64 << (63 - bits.leading_zeros()))
    }
}

/// `v · 2^k`, exact unless the result overflows or falls below the subnormal range.
fn ldexp(mut v: f64, mut k: i32) -> f64 {
    let step = |k: i32| f64::from_bits(((k + 1023) as u64) << 52);
    while k > 1000 {
        v *= step(1000);
        k -= 1000;
    }
    while k < -1000 {
        v *= step(-1000);
        k += 1000;
    }
    v * step(k)
}

impl Tolerance {
    /// ε relative to the larger side of the input's bounding box when no ε is given.
    pub const RELATIVE_DEFAULT: f64 = 1e-10;

    /// Bits of a grid coordinate: every coordinate is at most 2^GRID_BITS grid steps from 0.
    pub const GRID_BITS: i32 = 51;

    /// A user-chosen ε > 0 (anything else, NaN included, asks for the default).
    pub fn new(eps: f64) -> Tolerance {
        Tolerance {
            eps: if eps.is_finite() && eps > 0.0 {
                eps
            } else {
                0.0
            },
        }
    }

    /// The tolerance in force (0 until resolved from an input's extent).
    pub fn eps(self) -> f64 {
        self.eps
    }

    /// The grid spacing g: the largest power of two not above ε (`None` until resolved).
    pub fn grid(self) -> Option<f64> {
        (self.eps > 0.0).then(|| pow2_floor(self.eps))
    }

    /// The finest grid that can carry coordinates of magnitude up to `magnitude`: the smallest
    /// power of two g with `magnitude ≤ 2^GRID_BITS · g`.
    pub fn finest_grid(magnitude: f64) -> f64 {
        if magnitude <= 0.0 {
            return f64::from_bits(1);
        }
        let m = pow2_floor(magnitude);
        let top = if m == magnitude { m } else { 2.0 * m };
        ldexp(top, -Tolerance::GRID_BITS).max(f64::from_bits(1))
    }

    /// This tolerance resolved for an input whose bounding box has larger side `span` and
    /// largest coordinate magnitude `magnitude`: the default ε if none was given, an error if
    /// the requested grid is finer than [`Tolerance::finest_grid`].
    pub fn resolve(self, span: f64, magnitude: f64) -> Result<Tolerance, TooFine> {
        let finest = Tolerance::finest_grid(magnitude);
        match self.grid() {
            None => Ok(Tolerance {
                eps: pow2_floor((span * Tolerance::RELATIVE_DEFAULT).max(finest)),
            }),
            Some(g) if g < finest => Err(TooFine {
                requested: self.eps,
                representable: finest,
            }),
            Some(_) => Ok(self),
        }
    }
}

/// A tolerance too fine for the coordinates it applies to: the grid of `requested` cannot
/// carry them, `representable` is the smallest ε that can.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TooFine {
    /// The ε asked for.
    pub requested: f64,
    /// The smallest ε whose grid can carry the coordinates.
    pub representable: f64,
}

/// The exact sign of a determinant of the `f64` coordinates `all`: `robust_sign` (Shewchuk's
/// adaptive arithmetic) on them, or on them scaled by an exact power of two, when every
/// coordinate then has magnitude in `[2^lo, 2^hi]` or is 0 — where no product of the
/// expansions overflows or underflows — and `rational` on their exact values otherwise.
fn exact_sign_f64<const K: usize>(
    all: [f64; K],
    (lo, hi): (i32, i32),
    robust_sign: impl Fn([f64; K]) -> Ordering,
    rational: impl Fn([Rational; K]) -> Ordering,
) -> Ordering {
    let (lo, hi) = (ldexp(1.0, lo), ldexp(1.0, hi));
    let safe = |v: &f64| *v == 0.0 || (lo..=hi).contains(&v.abs());
    if all.iter().all(safe) {
        return robust_sign(all);
    }
    let m = all.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    let k = unit_scale(m);
    let scaled = all.map(|v| ldexp(v, k));
    if scaled.iter().all(safe) && scaled.iter().zip(&all).all(|(s, v)| ldexp(*s, -k) == *v) {
        return robust_sign(scaled);
    }
    rational(all.map(|v| Rational::from_f64(v).unwrap_or_else(|_| Rational::zero())))
}

/// Sums of absolute products (Shewchuk's permanents) from which the static filters below are
/// trusted: far above the subnormal range, where products lose relative precision.
const FILTERED_FROM: f64 = 1e-250;

/// The sign of `det` if Shewchuk's static error bound `bound · permanent` (his
/// `ccwerrboundA`, `o3derrboundA`), doubled, plus `slack` (what products that underflowed
/// can add) decides it; `None` otherwise (also where anything overflowed).
fn filtered(det: f64, permanent: f64, bound: f64, slack: f64) -> Option<Ordering> {
    let sure = permanent.is_finite()
        && permanent >= FILTERED_FROM
        && det.abs() > 2.0 * bound * permanent + slack;
    sure.then(|| det.partial_cmp(&0.0).unwrap_or(Ordering::Equal))
}

/// The sign of (b − a) × (c − a) for `f64` points, exactly: a static filter on the values
/// ([`filtered`]), inlined, else [`unfiltered_orient_f64`].
#[inline]
pub(crate) fn exact_orient_f64(a: [f64; 2], b: [f64; 2], c: [f64; 2]) -> Ordering {
    let left = (a[0] - c[0]) * (b[1] - c[1]);
    let right = (a[1] - c[1]) * (b[0] - c[0]);
    let bound = (3.0 + 16.0 * f64::EPSILON / 2.0) * f64::EPSILON / 2.0;
    // An underflowed product is off by at most 2^-1075, far below the bound.
    filtered(left - right, left.abs() + right.abs(), bound, 0.0)
        .unwrap_or_else(|| unfiltered_orient_f64(a, b, c))
}

/// [`exact_orient_f64`] where its filter failed: [`exact_sign_f64`].
#[cold]
#[inline(never)]
fn unfiltered_orient_f64(a: [f64; 2], b: [f64; 2], c: [f64; 2]) -> Ordering {
    if (0..2).any(|k| a[k] == c[k] && b[k] == c[k]) {
        // On one line of constant coordinate: no area.
        return Ordering::Equal;
    }
    // Coordinates of magnitude in [2^-480, 2^500] (or 0) are multiples of 2^-532: every
    // product of two stays representable, and none overflows.
    let robust_sign = |p: [f64; 6]| {
        let q = |x: f64, y: f64| robust::Coord { x, y };
        let det = robust::orient2d(q(p[0], p[1]), q(p[2], p[3]), q(p[4], p[5]));
        det.partial_cmp(&0.0).unwrap_or(Ordering::Equal)
    };
    exact_sign_f64(
        [a[0], a[1], b[0], b[1], c[0], c[1]],
        (-480, 500),
        robust_sign,
        |r| super::exact_orient([&r[0], &r[1]], [&r[2], &r[3]], [&r[4], &r[5]]),
    )
}

/// The sign of det[b − a, c − a, d − a] for `f64` points, exactly — a static filter on the
/// values ([`filtered`]), else in grid integers ([`grid_orient3d`]) where they fit, else
/// [`exact_sign_f64`] — in the convention of [`Num::orient3d`].
pub(crate) fn exact_orient3d_f64(a: [f64; 3], b: [f64; 3], c: [f64; 3], d: [f64; 3]) -> Ordering {
    if d == a || d == b || d == c {
        // A repeated point (the common case of triangles sharing a corner): no volume.
        return Ordering::Equal;
    }
    // det[b − a, c − a, d − a] = −det[a − d, b − d, c − d], Shewchuk's form.
    let [u, v, w] = [a, b, c].map(|p| [p[0] - d[0], p[1] - d[1], p[2] - d[2]]);
    let (vw, wv) = (v[0] * w[1], w[0] * v[1]);
    let (wu, uw) = (w[0] * u[1], u[0] * w[1]);
    let (uv, vu) = (u[0] * v[1], v[0] * u[1]);
    let det = u[2] * (vw - wv) + v[2] * (wu - uw) + w[2] * (uv - vu);
    let permanent = (vw.abs() + wv.abs()) * u[2].abs()
        + (wu.abs() + uw.abs()) * v[2].abs()
        + (uv.abs() + vu.abs()) * w[2].abs();
    let slack = underflow_slack([u[2], v[2], w[2]]);
    filtered(-det, permanent, ORIENT3D_BOUND, slack)
        .unwrap_or_else(|| unfiltered_orient3d_f64(a, b, c, d))
}

/// [`exact_orient3d_f64`] without its static filter, for callers whose own filter failed:
/// in grid integers where they fit, else [`exact_sign_f64`].
fn unfiltered_orient3d_f64(a: [f64; 3], b: [f64; 3], c: [f64; 3], d: [f64; 3]) -> Ordering {
    if (0..3).any(|k| a[k] == d[k] && b[k] == d[k] && c[k] == d[k]) {
        // In one plane of constant coordinate (faces of boxes and grids): no volume.
        return Ordering::Equal;
    }
    if let Some(sign) = grid_orient3d(a, b, c, d) {
        return sign;
    }
    // Coordinates of magnitude in [2^-300, 2^300] (or 0) are multiples of 2^-352: every
    // product of three stays representable, and none overflows.
    let robust_sign = |p: [f64; 12]| {
        let q = |i: usize| robust::Coord3D {
            x: p[i],
            y: p[i + 1],
            z: p[i + 2],
        };
        // Shewchuk's orient3d is positive when d lies below the plane abc (seen from above,
        // a, b, c counterclockwise): the opposite of our convention.
        let det = robust::orient3d(q(0), q(3), q(6), q(9));
        0.0f64.partial_cmp(&det).unwrap_or(Ordering::Equal)
    };
    let points = [a, b, c, d];
    let all: [f64; 12] = std::array::from_fn(|k| points[k / 3][k % 3]);
    exact_sign_f64(all, (-300, 300), robust_sign, |r| {
        let p = |i: usize| [&r[i], &r[i + 1], &r[i + 2]];
        super::exact_orient3d(p(0), p(3), p(6), p(9))
    })
}

/// Shewchuk's `o3derrboundA`: the relative error bound of his orient3d's static filter.
const ORIENT3D_BOUND: f64 = (7.0 + 56.0 * f64::EPSILON / 2.0) * f64::EPSILON / 2.0;

/// What an orient3d sum can lose beyond [`ORIENT3D_BOUND`]: a 2 × 2 minor whose products
/// underflowed is off by up to 2^-1074, times its factor in `factors`. Taken as at least
/// 2^-970: that much is under half an ulp of any bound [`filtered`] trusts (at least
/// 2 · ORIENT3D_BOUND · FILTERED_FROM > 2^-880), so adding it changes nothing; and computed
/// by two factors of 2^-535, so that no operand or result is subnormal (each a microcode
/// assist on x86, which cost a quarter of a touching 3D meet's time).
fn underflow_slack(factors: [f64; 3]) -> f64 {
    let sum = factors[0].abs() + factors[1].abs() + factors[2].abs();
    let half = ldexp(1.0, -535);
    sum.max(ldexp(1.0, 100)) * half * half
}

/// The plane through three `f64` points, prepared so that [`exact_orient3d_f64`] of many
/// points against it costs a dot product each: det[b − a, c − a, d − a] = (d − a) · n with
/// n = (b − a) × (c − a), the same tree of rounded operations as Shewchuk's orient3d (three
/// rounded differences times a difference of products of rounded differences, summed), so his
/// static bound holds with the permanent Σ |dᵢ − aᵢ| · (|product| + |product|) of n's minors.
pub(crate) struct PlaneF64 {
    corners: [[f64; 3]; 3],
    normal: [f64; 3],
    minor_permanents: [f64; 3],
}

impl PlaneF64 {
    /// The plane through `a`, `b`, `c`.
    pub(crate) fn new(a: [f64; 3], b: [f64; 3], c: [f64; 3]) -> PlaneF64 {
        let (u, v) = (
            [0, 1, 2].map(|k| b[k] - a[k]),
            [0, 1, 2].map(|k| c[k] - a[k]),
        );
        let products = [0, 1, 2].map(|k| {
            let (i, j) = ((k + 1) % 3, (k + 2) % 3);
            (u[i] * v[j], u[j] * v[i])
        });
        PlaneF64 {
            corners: [a, b, c],
            normal: products.map(|(p, q)| p - q),
            minor_permanents: products.map(|(p, q)| p.abs() + q.abs()),
        }
    }

    /// The plane of the triangle `t`, indices into the points `p`.
    pub(crate) fn of_triangle(p: &[[f64; 3]], t: [usize; 3]) -> PlaneF64 {
        PlaneF64::new(p[t[0]], p[t[1]], p[t[2]])
    }

    /// [`exact_orient3d_f64`] of the plane's corners and `d`.
    pub(crate) fn side(&self, d: [f64; 3]) -> Ordering {
        let [a, b, c] = self.corners;
        if d == a || d == b || d == c {
            return Ordering::Equal;
        }
        self.certain_side(d)
            .unwrap_or_else(|| unfiltered_orient3d_f64(a, b, c, d))
    }

    /// [`PlaneF64::side`] where the static filter is certain of it (one dot product), `None`
    /// where the exact sign would have to be computed — always for a point on the plane.
    pub(crate) fn certain_side(&self, d: [f64; 3]) -> Option<Ordering> {
        let a = self.corners[0];
        let w = [0, 1, 2].map(|k| d[k] - a[k]);
        let det = w[0] * self.normal[0] + w[1] * self.normal[1] + w[2] * self.normal[2];
        let permanent = w[0].abs() * self.minor_permanents[0]
            + w[1].abs() * self.minor_permanents[1]
            + w[2].abs() * self.minor_permanents[2];
        filtered(det, permanent, ORIENT3D_BOUND, underflow_slack(w))
    }
}

/// True if `d` is within distance `eps` of the plane through `a`, `b`, `c` (not collinear),
/// on differences halved and scaled by a power of two so that nothing overflows.
fn within_plane(a: [f64; 3], b: [f64; 3], c: [f64; 3], d: [f64; 3], eps: f64) -> bool {
    let half = |p: [f64; 3]| [0, 1, 2].map(|k| p[k] / 2.0 - a[k] / 2.0);
    let (u, v, w) = (half(b), half(c), half(d));
    let m = [u, v, w]
        .iter()
        .flatten()
        .fold(0.0f64, |m, x| m.max(x.abs()));
    if m == 0.0 {
        return true;
    }
    let k = unit_scale(m);
    let s = |p: [f64; 3]| p.map(|x| ldexp(x, k));
    let (u, v, w) = (s(u), s(v), s(w));
    let n = [
        u[1] * v[2] - u[2] * v[1],
        u[2] * v[0] - u[0] * v[2],
        u[0] * v[1] - u[1] * v[0],
    ];
    let len = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt();
    let det = n[0] * w[0] + n[1] * w[1] + n[2] * w[2];
    // distance = |det| / |n| in scaled half units; ε in the same units is ε · 2^k / 2.
    det.abs() <= len * ldexp(eps / 2.0, k)
}

/// The power of two 2^k that brings `m > 0` into [1, 2).
fn unit_scale(m: f64) -> i32 {
    -(m.log2().floor() as i32)
}

/// The half-differences b − a and c − a, scaled by the power of two 2^k that brings their
/// largest magnitude into [1, 2): nothing overflows or underflows on the way. `None` if both
/// are 0.
fn scaled_differences(a: [f64; 2], b: [f64; 2], c: [f64; 2]) -> Option<([f64; 2], [f64; 2], i32)> {
    let half = |p: [f64; 2]| [p[0] / 2.0 - a[0] / 2.0, p[1] / 2.0 - a[1] / 2.0];
    let (d, e) = (half(b), half(c));
    let m = [d[0], d[1], e[0], e[1]]
        .iter()
        .fold(0.0f64, |m, v| m.max(v.abs()));
    if m == 0.0 {
        return None;
    }
    let k = unit_scale(m);
    Some((d.map(|v| ldexp(v, k)), e.map(|v| ldexp(v, k)), k))
}

/// The Euclidean distance from `p` to the segment `ab` (the result may be +∞ when it exceeds
/// `f64::MAX`), on [`scaled_differences`].
pub(crate) fn segment_distance(a: [f64; 2], b: [f64; 2], p: [f64; 2]) -> f64 {
    let Some((d, e, k)) = scaled_differences(a, b, p) else {
        return 0.0;
    };
    let dd = d[0] * d[0] + d[1] * d[1];
    let t = if dd > 0.0 {
        ((e[0] * d[0] + e[1] * d[1]) / dd).clamp(0.0, 1.0)
    } else {
        0.0
    };
    let gap = (e[0] - t * d[0]).hypot(e[1] - t * d[1]);
    2.0 * ldexp(gap, -k)
}

/// True if `c` is within distance `eps` of the line through `a` and `b` (`a ≠ b`), on
/// [`scaled_differences`].
fn within_line(a: [f64; 2], b: [f64; 2], c: [f64; 2], eps: f64) -> bool {
    let Some((d, e, k)) = scaled_differences(a, b, c) else {
        return true;
    };
    let det = d[0] * e[1] - d[1] * e[0];
    // distance = |det| / |d| in scaled half units; ε in the same units is ε · 2^k / 2.
    det.abs() / d[0].hypot(d[1]) <= ldexp(eps / 2.0, k)
}

impl PartialEq for Float {
    fn eq(&self, other: &Self) -> bool {
        self.0.total_cmp(&other.0) == Ordering::Equal
    }
}
impl Eq for Float {}
impl PartialOrd for Float {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}
impl Ord for Float {
    fn cmp(&self, other: &Self) -> Ordering {
        self.0.total_cmp(&other.0)
    }
}
impl Hash for Float {
    fn hash<H: Hasher>(&self, state: &mut H) {
        self.0.to_bits().hash(state)
    }
}

/// The shortest decimal that reads back as `v`, in scientific notation (`1.5e-300`) where plain
/// digits would run long (magnitudes from 10¹⁶ up or below 10⁻⁵): numbers in messages.
pub(crate) fn short_f64(v: f64) -> String {
    let a = v.abs();
    if a != 0.0 && a.is_finite() && !(1e-5..1e16).contains(&a) {
        format!("{v:e}")
    } else {
        format!("{v}")
    }
}

impl fmt::Display for Float {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}", self.0)
    }
}

macro_rules! float_binop {
    ($tr:ident, $m:ident, $op:tt) => {
        impl $tr for Float {
            type Output = Float;
            fn $m(self, o: Float) -> Float {
                Float::new(self.0 $op o.0)
            }
        }
    };
}
float_binop!(Add, add, +);
float_binop!(Sub, sub, -);
float_binop!(Mul, mul, *);
float_binop!(Div, div, /);

impl Neg for Float {
    type Output = Float;
    fn neg(self) -> Float {
        Float::new(-self.0)
    }
}

/// The longest decimal text that [`Float::parse`] hands to the standard library's parse.
const SHORT_DECIMAL: usize = 64;

impl Num for Float {
    type Ctx = Tolerance;
    const EXACT: bool = false;

    fn nearest(r: &Rational) -> Self {
        Float::new(r.to_f64())
    }

    fn from_i64(v: i64) -> Self {
        Float::new(v as f64)
    }

    fn from_f64(v: f64) -> Result<Self, NumError> {
        if v.is_finite() {
            Ok(Float::new(v))
        } else {
            Err(NumError::NotFinite(v))
        }
    }

    fn parse(s: &str) -> Result<Self, NumError> {
        let parts = Parts::scan(s)?;
        // A decimal's nearest f64 straight from its text: the standard library's correctly
        // rounded parse of the literal just checked, the value `from_literal` would make. Only
        // for short text: the standard parse stops reading an exponent past 65 536, which a
        // literal reaches only with as many fraction digits to bring it back.
        match parts.den.is_none() && s.len() <= SHORT_DECIMAL {
            true => Ok(s
                .trim()
                .parse()
                .map_or_else(|_| Float::from_literal(&parts.literal()), Float::new)),
            false => Ok(Float::from_literal(&parts.literal())),
        }
    }

    /// The nearest `f64` of the literal's value: a decimal by the standard library's correctly
    /// rounded parse, a fraction from its exact value (its terms rounded apart and divided could
    /// miss the nearest by an ulp, and overflow to NaN where both exceed `f64`'s range).
    fn from_literal(lit: &Literal) -> Self {
        if lit.den != "1" {
            return Float::new(Rational::from_literal(lit).to_f64());
        }
        let sign = if lit.negative { "-" } else { "" };
        let num: f64 = format!("{sign}{}e{}", lit.digits, lit.exp10)
            .parse()
            .unwrap_or(f64::NAN);
        Float::new(num)
    }

    fn to_f64(&self) -> f64 {
        self.0
    }

    fn fraction(&self) -> (num_bigint::BigInt, num_bigint::BigInt) {
        Rational::from_f64(self.0)
            .expect("float sets have finite coordinates")
            .fraction()
    }

    fn rational(&self) -> Rational {
        Rational::from_f64(self.0).expect("float sets have finite coordinates")
    }

    fn sign(&self) -> Ordering {
        self.0.total_cmp(&0.0)
    }

    fn is_finite(&self) -> bool {
        self.0.is_finite()
    }

    fn orient2d(a: [&Self; 2], b: [&Self; 2], c: [&Self; 2], ctx: &Tolerance) -> Ordering {
        let p = |q: [&Float; 2]| [q[0].0, q[1].0];
        let (a, b, c) = (p(a), p(b), p(c));
        let sign = exact_orient_f64(a, b, c);
        if sign == Ordering::Equal || (ctx.eps > 0.0 && a != b && within_line(a, b, c, ctx.eps)) {
            Ordering::Equal
        } else {
            sign
        }
    }

    fn orient3d(
        a: [&Self; 3],
        b: [&Self; 3],
        c: [&Self; 3],
        d: [&Self; 3],
        ctx: &Tolerance,
    ) -> Ordering {
        let p = |q: [&Float; 3]| [q[0].0, q[1].0, q[2].0];
        let (a, b, c, d) = (p(a), p(b), p(c), p(d));
        let sign = exact_orient3d_f64(a, b, c, d);
        if sign == Ordering::Equal || (ctx.eps > 0.0 && within_plane(a, b, c, d, ctx.eps)) {
            Ordering::Equal
        } else {
            sign
        }
    }

    fn grid(ctx: &Tolerance) -> Option<f64> {
        ctx.grid()
    }

    fn tolerance(ctx: &Tolerance) -> f64 {
        ctx.eps
    }

    fn combine_ctx(a: Tolerance, b: Tolerance) -> Tolerance {
        Tolerance {
            eps: a.eps.max(b.eps),
        }
    }

    fn resolve_ctx(ctx: Tolerance, span: f64, magnitude: f64) -> Result<Tolerance, TooFine> {
        ctx.resolve(span, magnitude)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(yinset_testkit::cases(1024)))]
        /// A parsed decimal is its value correctly rounded: the standard library's parse, and
        /// the nearest f64 of its exact value.
        #[test]
        fn parsed_decimals_are_correctly_rounded(
            (text, exact) in crate::num::literal::texts::literals(false),
        ) {
            let got = Float::parse(&text).unwrap().0;
            // `Float::new` makes −0 into +0, as every float coordinate is.
            let std = Float::new(text.parse::<f64>().unwrap()).0;
            proptest::prop_assert_eq!(got.to_bits(), std.to_bits(), "{}", text);
            proptest::prop_assert_eq!(got, Rational::from(exact).to_f64(), "{}", text);
        }

        /// A parsed fraction is the nearest f64 of its exact value (rounded once).
        #[test]
        fn parsed_fractions_are_correctly_rounded(
            (text, exact) in crate::num::literal::texts::literals(true),
        ) {
            let got = Float::parse(&text).unwrap().0;
            proptest::prop_assert_eq!(got, Rational::from(exact).to_f64(), "{}", text);
        }
    }

    /// A fraction whose terms, each rounded to `f64` and then divided, miss its nearest `f64`
    /// by an ulp: 3.799759413396676 is nearest, 3.7997594133966754 the twice-rounded quotient.
    #[test]
    fn a_fraction_is_rounded_once() {
        let got = Float::parse("91770119583970787981/24151560559444937093").unwrap();
        assert_eq!(got.0, 3.799759413396676);
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(yinset_testkit::cases(256)))]
        /// A decimal read from its text is the value of its literal (signs, leading dots and
        /// zeros, exponents up to ±400: past f64's range both ways), bit for bit.
        #[test]
        fn parsed_decimals_are_their_literals(
            sign in "[-+]?", int in "[0-9]{0,20}", frac in "(\\.[0-9]{0,20})?",
            exp in proptest::option::of(-400i32..400),
        ) {
            proptest::prop_assume!(!(int.is_empty() && frac.len() < 2));
            let text = format!("{sign}{int}{frac}{}", exp.map_or(String::new(), |e| format!("e{e}")));
            let lit = Literal::parse(&text).expect("a decimal");
            let got = Float::parse(&text).expect("a decimal");
            proptest::prop_assert_eq!(got.0.to_bits(), Float::from_literal(&lit).0.to_bits(), "{}", text);
        }
    }

    /// A literal whose exponent passes 65 536, brought back by as many fraction digits, is
    /// its literal's value: 0.(699 999 zeros)1e700000 is 1.
    #[test]
    fn a_huge_exponent_balanced_by_fraction_digits_is_read_exactly() {
        let text = format!("0.{}1e700000", "0".repeat(699_999));
        assert_eq!(Float::parse(&text), Ok(Float::new(1.0)));
    }

    #[test]
    fn negative_zero_is_zero() {
        assert_eq!(Float::new(-0.0), Float::new(0.0));
        assert_eq!(Float::new(0.0) * Float::new(-1.0), Float::new(0.0));
    }

    #[test]
    fn negation_flips_the_sign() {
        assert_eq!(-Float::new(1.5), Float::new(-1.5));
        assert_eq!(-Float::new(-0.25), Float::new(0.25));
        assert_eq!(-Float::new(0.0), Float::new(0.0));
    }

    #[test]
    fn negative_zero_determinant_is_collinear() {
        let f = Float::new;
        let (a, b) = (
            [&f(1.2843602), &f(3.8413011)],
            [&f(1.2854123), &f(3.774248)],
        );
        assert_eq!(
            Float::orient2d(a, b, b, &Tolerance::default()),
            Ordering::Equal
        );
        assert_eq!(
            Float::orient2d(b, a, a, &Tolerance::default()),
            Ordering::Equal
        );
    }

    #[test]
    fn orientation_respects_eps() {
        let f = Float::new;
        let (a, b) = ([&f(0.0), &f(0.0)], [&f(1.0), &f(0.0)]);
        let near = [&f(0.5), &f(1e-9)];
        assert_eq!(
            Float::orient2d(a, b, near, &Tolerance::new(1e-6)),
            Ordering::Equal
        );
        assert_eq!(
            Float::orient2d(a, b, near, &Tolerance::new(1e-12)),
            Ordering::Greater
        );
    }

    /// A coordinate near `k · 2^e`: `k` small, moved by `ulps` steps of its own spacing
    /// (points on a line or plane of small integers, nudged off it or not, at any scale).
    fn near(k: i64, e: i32, ulps: i32) -> f64 {
        let mut v = ldexp(k as f64, e);
        for _ in 0..ulps.abs() {
            v = if ulps > 0 { v.next_up() } else { v.next_down() };
        }
        v
    }

    /// Mostly on the lattice (so that a quarter of the draws is exactly degenerate where the
    /// lattice points are), else nudged.
    fn coordinate() -> impl proptest::strategy::Strategy<Value = (i64, i32)> {
        use proptest::prelude::*;
        (-2i64..=2, prop_oneof![8 => Just(0), 1 => -2i32..=2])
    }

    /// A plane whose x-y minor's products underflow, against a point far off it that nearly
    /// cancels the other term (found by a search for where the bound without the underflow
    /// slack accepts the wrong sign): the prepared plane still gives the exact side.
    #[test]
    fn plane_side_counts_what_underflowed_minors_lose() {
        let (a, b, c) = (
            [0.0; 3],
            [5.4708779169162457e-163, 4.79519246273353e-163, 0.0],
            [
                4.244439558430982e-163,
                4.9003522730050704e-163,
                4.1110291312702665e-151,
            ],
        );
        let d = [-2.0411489561093225e+256, 0.0, 6.603681639195816e+268];
        let r = |p: [f64; 3]| p.map(|x| Rational::from_f64(x).expect("finite"));
        let (ra, rb, rc, rd) = (r(a), r(b), r(c), r(d));
        fn refs(p: &[Rational; 3]) -> [&Rational; 3] {
            [&p[0], &p[1], &p[2]]
        }
        let exact = super::super::exact_orient3d(refs(&ra), refs(&rb), refs(&rc), refs(&rd));
        assert_eq!(exact, Ordering::Greater);
        assert_eq!(PlaneF64::new(a, b, c).side(d), exact);
    }

    /// The orientation is exact where both products of `exact_orient_f64`'s filter round in
    /// the subnormal range: with c = (2⁻⁵³, 0), a = (1.5, −(1.5 − 2⁻⁵²)·2⁻¹⁰²¹) and
    /// b = (−2⁻¹⁰⁶, 2⁻¹⁰⁷⁴), the rounded differences 1.5 and −2⁻⁵³ make the products
    /// 1.5·2⁻¹⁰⁷⁴ (a tie, rounded to 2·2⁻¹⁰⁷⁴) and (1.5 − 2⁻⁵²)·2⁻¹⁰⁷⁴ (rounded to 2⁻¹⁰⁷⁴), a
    /// positive difference; the exact determinant is 2⁻¹⁰⁷⁴·(2⁻¹⁰⁵ − 2⁻⁵⁴) < 0 (by hand).
    #[test]
    fn orientation_with_subnormal_products_is_exact() {
        let (a, b, c) = (
            [1.5, -ldexp(1.5 - f64::EPSILON, -1021)],
            [-ldexp(1.0, -106), f64::from_bits(1)],
            [ldexp(1.0, -53), 0.0],
        );
        let r = |p: [f64; 2]| p.map(|x| Rational::from_f64(x).expect("finite"));
        let (ra, rb, rc) = (r(a), r(b), r(c));
        let exact =
            super::super::exact_orient([&ra[0], &ra[1]], [&rb[0], &rb[1]], [&rc[0], &rc[1]]);
        assert_eq!(exact, Ordering::Less);
        assert_eq!(exact_orient_f64(a, b, c), Ordering::Less);
    }

    /// `within_plane` against distances worked by hand: the plane through (3, 5, 7), (5, 3, 7)
    /// and (5, 5, 5) is x + y + z = 15, and (4, 6, 8) lies √3 ≈ 1.732 off it.
    #[test]
    fn within_plane_is_the_distance_to_the_plane() {
        let (a, b, c, d) = (
            [3.0, 5.0, 7.0],
            [5.0, 3.0, 7.0],
            [5.0, 5.0, 5.0],
            [4.0, 6.0, 8.0],
        );
        assert!(within_plane(a, b, c, d, 1.74));
        assert!(!within_plane(a, b, c, d, 1.72));
        // A point of the plane, and one 0.5 off the plane z = 7 through a, b and (3, 9, 7).
        assert!(within_plane(a, b, c, [4.0, 4.0, 7.0], 1e-12));
        assert!(within_plane(a, b, [3.0, 9.0, 7.0], [10.0, -4.0, 7.5], 0.51));
        assert!(!within_plane(
            a,
            b,
            [3.0, 9.0, 7.0],
            [10.0, -4.0, 7.5],
            0.49
        ));
    }

    /// `segment_distance` against distances worked by hand: to the inside of a segment, to an
    /// end, and to a segment of one point (a = b).
    #[test]
    fn segment_distance_by_hand() {
        assert_eq!(segment_distance([1.0, 1.0], [5.0, 1.0], [3.0, 4.0]), 3.0);
        assert_eq!(segment_distance([1.0, 1.0], [5.0, 1.0], [8.0, 5.0]), 5.0);
        assert_eq!(segment_distance([1.0, 1.0], [1.0, 1.0], [4.0, 5.0]), 5.0);
        assert_eq!(segment_distance([1.0, 1.0], [1.0, 1.0], [1.0, 1.0]), 0.0);
        // Subnormal differences, scaled up by 2^1069 and back down in steps (`ldexp`).
        let u = f64::from_bits(16); // 2^-1070
        assert_eq!(
            segment_distance([0.0, 0.0], [4.0 * u, 0.0], [2.0 * u, 3.0 * u]),
            3.0 * u
        );
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(yinset_testkit::cases(2000)))]

        /// The filtered orientations equal the exact ones of the values read as rationals, on
        /// points of small-integer lines and planes (degenerate or nudged by ulps off them) scaled
        /// by 2^e for e from the subnormal range to near overflow, and on arbitrary finite
        /// `f64`s.
        #[test]
        fn filtered_orientations_are_exact(
            p in proptest::array::uniform12(coordinate()),
            e in -1070i32..1000,
            raw in proptest::array::uniform12(proptest::num::f64::NORMAL | proptest::num::f64::SUBNORMAL | proptest::num::f64::ZERO),
            arbitrary in proptest::bool::ANY,
        ) {
            let v: [f64; 12] = if arbitrary { raw } else { p.map(|(k, u)| near(k, e, u)) };
            let r = v.map(|x| Rational::from_f64(x).expect("finite"));
            let two = |i: usize| [v[i], v[i + 1]];
            let rtwo = |i: usize| [&r[i], &r[i + 1]];
            proptest::prop_assert_eq!(
                exact_orient_f64(two(0), two(2), two(4)),
                super::super::exact_orient(rtwo(0), rtwo(2), rtwo(4))
            );
            let three = |i: usize| [v[i], v[i + 1], v[i + 2]];
            let rthree = |i: usize| [&r[i], &r[i + 1], &r[i + 2]];
            let exact = super::super::exact_orient3d(rthree(0), rthree(3), rthree(6), rthree(9));
            proptest::prop_assert_eq!(exact_orient3d_f64(three(0), three(3), three(6), three(9)), exact);
            proptest::prop_assert_eq!(PlaneF64::new(three(0), three(3), three(6)).side(three(9)), exact);
        }
    }
}
