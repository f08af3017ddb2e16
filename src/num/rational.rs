//! The default exact backend: rationals stored inline as two machine integers while they fit,
//! as `num-rational`'s big rationals otherwise, compared through a floating-point filter.

use super::grid_orient::{det3_sign, odd_decode};
use super::quotient::{nearest_f64, Leading};
use super::{
    big, exact_orient, exact_orient3d, exact_orient3d_f64, exact_orient_f64, filtered_orient,
    filtered_orient3d, Literal, Num, NumError, Parts,
};
use num_bigint::{BigInt, Sign};
use num_integer::Integer;
use num_rational::BigRational;
use num_traits::{Signed, ToPrimitive, Zero};
use std::borrow::Cow;
use std::cmp::Ordering;
use std::fmt;
use std::hash::{Hash, Hasher};
use std::ops::{Add, Div, Mul, Neg, Sub};
use std::sync::Arc;

/// Exact rational coordinates (the default backend), always in lowest terms with a positive
/// denominator. A value whose numerator and denominator are below 2⁶² in magnitude is stored
/// as two `i64` and computed in `i128` without allocating (lattice coordinates, decimals of a
/// few digits and most of what is computed from them); any other value is a `num-rational`
/// big rational. The choice is canonical (a value is small iff it fits), so the derived `==`
/// and `Hash` are those of the value. Two small values are ordered exactly in `i128`; big
/// ones from `f64` approximations when they are far enough apart, exactly (by
/// cross-multiplying) otherwise (`num-rational`'s own order expands continued fractions and
/// dominated exact-mode profiles).
#[derive(Clone, PartialEq, Eq, Hash)]
pub struct Rational(Repr);

/// The two representations of a [`Rational`].
#[derive(Clone)]
enum Repr {
    /// `n / d` with |n| < 2⁶² and 0 < d < 2⁶², in lowest terms.
    Small(i64, i64),
    /// Any other value, in lowest terms, shared (small values stay three words, and a clone
    /// of a big one, as every vertex handed from one operation to the next is, allocates
    /// nothing).
    Big(Arc<Big>),
}

/// A big value with its `f64` approximation, computed once: the filters of `cmp` and the
/// orientation predicates read it on every call.
#[derive(Clone)]
struct Big {
    value: BigRational,
    /// See [`approx`].
    approx: f64,
}

impl Big {
    /// `value` (in lowest terms) with its approximation: numerator and denominator rounded, then
    /// divided, so within 3 ulps; NaN when either is out of `f64`'s range, which the filters
    /// reject. (A finite numerator over an overflowing denominator would read as 0 and decide
    /// orders wrongly: found by fuzzing, pinned in tests/fuzz_regressions.rs.)
    fn boxed(value: BigRational) -> Arc<Big> {
        let n = ToPrimitive::to_f64(value.numer()).unwrap_or(f64::NAN);
        let d = ToPrimitive::to_f64(value.denom()).unwrap_or(f64::NAN);
        let approx = if n.is_finite() && d.is_finite() {
            n / d
        } else {
            f64::NAN
        };
        Arc::new(Big { value, approx })
    }
}

/// Equality of values: both representations are canonical, so equal values have equal terms
/// (`num-rational`'s `==` would order unequal values by a continued fraction first).
impl PartialEq for Repr {
    fn eq(&self, o: &Repr) -> bool {
        match (self, o) {
            (Repr::Small(a, b), Repr::Small(c, d)) => a == c && b == d,
            (Repr::Big(x), Repr::Big(y)) => {
                Arc::ptr_eq(x, y)
                    || x.value.numer() == y.value.numer() && x.value.denom() == y.value.denom()
            }
            _ => false,
        }
    }
}

impl Eq for Repr {}

/// The hash of the value's lowest terms (both representations are canonical); `num-rational`'s
/// own `Hash` expands a continued fraction to serve unreduced values, a cost lowest terms do
/// not need.
impl Hash for Repr {
    fn hash<H: Hasher>(&self, h: &mut H) {
        match self {
            Repr::Small(n, d) => (0u8, n, d).hash(h),
            Repr::Big(b) => (1u8, b.value.numer(), b.value.denom()).hash(h),
        }
    }
}

/// Exclusive bound on |numerator| and denominator of a small value: a sum of two products of
/// small values stays below 2¹²⁵, inside `i128`.
const LIMIT: i128 = 1 << 62;

/// `n / d`, already in lowest terms with `d > 0`: small if it fits.
fn lowest(n: i128, d: i128) -> Rational {
    if -LIMIT < n && n < LIMIT && d < LIMIT {
        Rational(Repr::Small(n as i64, d as i64))
    } else {
        Rational(Repr::Big(Big::boxed(BigRational::new_raw(
            n.into(),
            d.into(),
        ))))
    }
}

/// gcd(|x|, d) for d > 0, by one remainder when x fits in 128 bits (the usual case), else
/// by [`big::gcd`]; gcd(0, d) = d.
fn small_gcd(x: &BigInt, d: &BigInt) -> BigInt {
    match x.magnitude().to_u128() {
        Some(0) => d.clone(),
        Some(x) => {
            let r = (d % BigInt::from(x))
                .to_u128()
                .expect("a remainder below x");
            BigInt::from(big::gcd_u128(x, r))
        }
        None => big::gcd(x, d),
    }
}

/// `n / d` for `d > 0`, reduced to lowest terms.
fn reduce(n: i128, d: i128) -> Rational {
    if d == 1 {
        return lowest(n, 1);
    }
    let g = big::gcd_u128(n.unsigned_abs(), d.unsigned_abs()) as i128;
    lowest(n / g, d / g)
}

/// The orientation of three rational points where the filter could not decide it: kept out
/// of line, so that the filtered path stays small.
#[inline(never)]
fn unfiltered_orient(a: [&Rational; 2], b: [&Rational; 2], c: [&Rational; 2]) -> Ordering {
    // Two equal points (edges meeting at a vertex, an arrangement's common ends) give 0,
    // which no filter can certify: settled by comparing terms, not by big products; so do
    // three points on one axis-parallel line (edges of boxes and voxels).
    if a == b || b == c || c == a || (0..2).any(|k| a[k] == b[k] && a[k] == c[k]) {
        return Ordering::Equal;
    }
    let all = [a[0], a[1], b[0], b[1], c[0], c[1]];
    if let Some([ax, ay, bx, by, cx, cy]) = integers(all, 1 << 61) {
        return exact_orient([&ax, &ay], [&bx, &by], [&cx, &cy]);
    }
    if let Some([ax, ay, bx, by, cx, cy]) = dyadic(all) {
        return exact_orient_f64([ax, ay], [bx, by], [cx, cy]);
    }
    fraction_free_orient(a, b, c)
}

/// The value of a literal's `parts` where its terms fit in `i128`: a decimal `m / 10^k` by
/// [`decimal`], any other by [`reduce`].
fn small_literal(parts: &Parts) -> Option<Rational> {
    match parts.decimal() {
        Some((m, k)) => Some(decimal(parts.negative, m, k)),
        None => parts.small_fraction().map(|(n, d)| reduce(n, d)),
    }
}

/// The value of a literal through big integers (any size).
fn big_literal(lit: &Literal) -> Rational {
    let (num, den) = lit.fraction();
    Rational::new(digits(&num), digits(&den))
}

/// `±m / 10^k` (`10^k` in a `u64`) in lowest terms without a gcd: the only factors it can
/// share are twos, removed by a shift, and fives, removed by division.
fn decimal(negative: bool, m: u64, k: u32) -> Rational {
    if m == 0 {
        return lowest(0, 1);
    }
    let twos = m.trailing_zeros().min(k);
    let (mut m, mut d) = (m >> twos, 10u64.pow(k) >> twos);
    for _ in 0..k {
        if m % 5 != 0 {
            break;
        }
        (m, d) = (m / 5, d / 5);
    }
    let n = i128::from(m);
    lowest(if negative { -n } else { n }, i128::from(d))
}

/// A big rational in lowest terms, stored small if it fits.
fn from_big(r: BigRational) -> Rational {
    match (r.numer().to_i128(), r.denom().to_i128()) {
        (Some(n), Some(d)) => lowest(n, d),
        _ => Rational(Repr::Big(Big::boxed(r))),
    }
}

impl Rational {
    /// `numer / denom` in lowest terms (panics if `denom` is zero, like `num-rational`).
    pub fn new(numer: BigInt, denom: BigInt) -> Rational {
        from_big(big::new(numer, denom))
    }

    /// The point (u·V − v·U) / (u − v) · 2^`scale` of the line through the integer points
    /// `pu` = U and `pv` = V (u ≠ v), each coordinate in lowest terms after a single gcd of big
    /// integers: with h = gcd(u, v), u = h·u′, v = h·v′ and d = u′ − v′, the numerator
    /// u′·V − v′·U ≡ u′·(V − U) (mod d) and gcd(u′, d) = gcd(u′, v′) = 1, so it shares with d
    /// exactly gcd(V − U, d), a gcd with the small V − U.
    pub(crate) fn section_point(
        u: &BigInt,
        v: &BigInt,
        [pu, pv]: [&[BigInt; 3]; 2],
        scale: i32,
    ) -> [Rational; 3] {
        let h = big::gcd(u, v);
        let (u, v) = (big::exact_div(u, &h), big::exact_div(v, &h));
        let d = &u - &v;
        let flip = d.is_negative();
        let d = d.abs();
        [0, 1, 2].map(|k| {
            let numer: BigInt = &u * &pv[k] - &v * &pu[k];
            let numer = if flip { -numer } else { numer };
            let g = small_gcd(&(&pv[k] - &pu[k]), &d);
            let (n, d) = (big::exact_div(&numer, &g), big::exact_div(&d, &g));
            Rational::times_power_of_two(n, d, scale)
        })
    }

    /// (`n` / `d`) · 2^`scale` for `n` / `d` in lowest terms with `d` > 0 (0 for n = 0): only
    /// the factors of two of the other side can cancel.
    pub(crate) fn times_power_of_two(mut n: BigInt, mut d: BigInt, scale: i32) -> Rational {
        if n.is_zero() {
            return Rational::zero();
        }
        if scale == 0 {
            return from_big(BigRational::new_raw(n, d));
        }
        if scale > 0 {
            let t = (scale as u64).min(d.trailing_zeros().unwrap_or(0));
            n <<= scale as u64 - t;
            d >>= t;
        } else {
            let t = (-scale as u64).min(n.trailing_zeros().unwrap_or(0));
            n >>= t;
            d <<= -scale as u64 - t;
        }
        from_big(BigRational::new_raw(n, d))
    }

    /// ±`n` / `d` (minus if `negative`) from the 64-bit words of n and d, least significant
    /// first, in lowest terms with d > 0 and n > 0, and `approx` within 3 ulps of it (as
    /// [`Big::boxed`] rounds): small if it fits, no conversion through big integers to tell.
    pub(crate) fn from_lowest_words(negative: bool, n: &[u64], d: &[u64], approx: f64) -> Rational {
        let small = |x: &[u64]| match x.iter().skip(1).all(|&w| w == 0) {
            true => i128::from(x[0]),
            false => LIMIT,
        };
        let (m, e) = (small(n), small(d));
        if m < LIMIT && e < LIMIT {
            return lowest(if negative { -m } else { m }, e);
        }
        let sign = if negative { Sign::Minus } else { Sign::Plus };
        let value = BigRational::new_raw(
            BigInt::from_biguint(sign, big::from_words(n)),
            BigInt::from_biguint(Sign::Plus, big::from_words(d)),
        );
        let approx = if negative { -approx } else { approx };
        Rational(Repr::Big(Arc::new(Big { value, approx })))
    }

    /// The integer `n`.
    pub fn from_integer(n: BigInt) -> Rational {
        from_big(BigRational::from_integer(n))
    }

    /// The exact value of a finite `f64` (`None` for NaN and infinities).
    pub fn from_float(v: f64) -> Option<Rational> {
        if v == 0.0 {
            return Some(Rational::from_i64(0));
        }
        // v = ±m·2^e with m odd, m < 2^53: small as m·2^e while that is below 2^62 (integers
        // such as grid coordinates, however many trailing zeros) or as m / 2^−e for e ≥ −61
        // (both terms below 2^62); else big, already in lowest terms (m odd), no gcd taken.
        if !v.is_finite() {
            return None;
        }
        let (m, e) = odd_decode(v);
        let m = i128::from(m);
        if e >= 0 && 128 - m.unsigned_abs().leading_zeros() as i32 + e <= 62 {
            return Some(lowest(m << e, 1));
        }
        if (-61..0).contains(&e) {
            return Some(lowest(m, 1 << -e));
        }
        let (m, one) = (BigInt::from(m), BigInt::from(1));
        Some(from_big(match e >= 0 {
            true => BigRational::new_raw(m << e, one),
            false => BigRational::new_raw(m, one << -e),
        }))
    }

    /// True if the value is an `f64` (a dyadic of at most 53 significant bits in `f64`'s
    /// range): for a small value, an exact numerator over a power of two, both below 2⁶², so
    /// in range; for a big one, its nearest `f64` read back.
    pub(crate) fn is_f64(&self) -> bool {
        match &self.0 {
            Repr::Small(n, d) => {
                let n = n.unsigned_abs();
                d.count_ones() == 1 && (n == 0 || n.leading_zeros() + n.trailing_zeros() >= 11)
            }
            Repr::Big(_) => Rational::from_float(Num::to_f64(self)).as_ref() == Some(self),
        }
    }

    /// The numerator (lowest terms; carries the sign).
    pub fn numer(&self) -> BigInt {
        match &self.0 {
            Repr::Small(n, _) => BigInt::from(*n),
            Repr::Big(b) => b.value.numer().clone(),
        }
    }

    /// The denominator (lowest terms; positive).
    pub fn denom(&self) -> BigInt {
        match &self.0 {
            Repr::Small(_, d) => BigInt::from(*d),
            Repr::Big(b) => b.value.denom().clone(),
        }
    }

    /// The value as a `num-rational` big rational (borrowed when it is one).
    fn big(&self) -> Cow<'_, BigRational> {
        match &self.0 {
            Repr::Small(n, d) => Cow::Owned(BigRational::new_raw((*n).into(), (*d).into())),
            Repr::Big(b) => Cow::Borrowed(&b.value),
        }
    }
}

impl Default for Rational {
    fn default() -> Rational {
        Rational(Repr::Small(0, 1))
    }
}

impl From<BigRational> for Rational {
    fn from(v: BigRational) -> Rational {
        from_big(v)
    }
}

impl fmt::Display for Rational {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match &self.0 {
            Repr::Small(n, 1) => write!(f, "{n}"),
            Repr::Small(n, d) => write!(f, "{n}/{d}"),
            Repr::Big(b) => fmt::Display::fmt(&b.value, f),
        }
    }
}

impl fmt::Debug for Rational {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        fmt::Display::fmt(self, f)
    }
}

impl Ord for Rational {
    fn cmp(&self, other: &Self) -> Ordering {
        if let (Repr::Small(a, b), Repr::Small(c, d)) = (&self.0, &other.0) {
            return (*a as i128 * *d as i128).cmp(&(*c as i128 * *b as i128));
        }
        if let (Repr::Big(x), Repr::Big(y)) = (&self.0, &other.0) {
            if Arc::ptr_eq(x, y) {
                // One shared value (a point handed on by clones).
                return Ordering::Equal;
            }
        }
        let (x, y) = (self.big(), other.big());
        if x.denom() == y.denom() {
            return x.numer().cmp(y.numer());
        }
        // Each approximation is within 3 ulps of its value (when neither over- nor underflows):
        // 8 ulps of the larger magnitude apart decides.
        let (a, b) = (approx(self), approx(other));
        let m = a.abs().max(b.abs());
        if a.is_finite() && b.is_finite() && m > 1e-290 && (a - b).abs() > 8.0 * f64::EPSILON * m {
            return if a < b {
                Ordering::Less
            } else {
                Ordering::Greater
            };
        }
        (x.numer() * y.denom()).cmp(&(y.numer() * x.denom()))
    }
}

impl PartialOrd for Rational {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

impl Add for Rational {
    type Output = Rational;
    fn add(self, o: Rational) -> Rational {
        match (&self.0, &o.0) {
            (Repr::Small(a, b), Repr::Small(c, d)) => {
                let (a, b, c, d) = (*a as i128, *b as i128, *c as i128, *d as i128);
                if b == d {
                    reduce(a + c, b)
                } else {
                    reduce(a * d + c * b, b * d)
                }
            }
            _ => from_big(big::add(&self.big(), &o.big())),
        }
    }
}

impl Sub for Rational {
    type Output = Rational;
    fn sub(self, o: Rational) -> Rational {
        self + -o
    }
}

impl Mul for Rational {
    type Output = Rational;
    fn mul(self, o: Rational) -> Rational {
        match (&self.0, &o.0) {
            (Repr::Small(a, b), Repr::Small(c, d)) => mul_small(*a, *b, *c, *d),
            _ => from_big(big::mul(&self.big(), &o.big())),
        }
    }
}

/// (a/b)·(c/d) for small values in lowest terms: cancelling across first keeps the product in
/// lowest terms without a gcd of the products.
fn mul_small(a: i64, b: i64, c: i64, d: i64) -> Rational {
    if a == 0 || c == 0 {
        return Rational::default();
    }
    let (a, b, c, d) = (a as i128, b as i128, c as i128, d as i128);
    if b == 1 && d == 1 {
        return lowest(a * c, 1);
    }
    let g = big::gcd_u128(a.unsigned_abs(), d.unsigned_abs()) as i128;
    let h = big::gcd_u128(c.unsigned_abs(), b.unsigned_abs()) as i128;
    lowest((a / g) * (c / h), (b / h) * (d / g))
}

impl Div for Rational {
    type Output = Rational;
    /// Panics on division by zero, like `num-rational`.
    fn div(self, o: Rational) -> Rational {
        match (&self.0, &o.0) {
            (Repr::Small(a, b), Repr::Small(c, d)) => {
                assert!(*c != 0, "division by zero");
                mul_small(*a, *b, d * c.signum(), c.abs())
            }
            _ => from_big(big::div(&self.big(), &o.big())),
        }
    }
}

impl std::iter::Sum for Rational {
    fn sum<I: Iterator<Item = Rational>>(iter: I) -> Rational {
        iter.fold(Rational::default(), |s, v| s + v)
    }
}

impl Neg for Rational {
    type Output = Rational;
    fn neg(self) -> Rational {
        match self.0 {
            Repr::Small(n, d) => Rational(Repr::Small(-n, d)),
            Repr::Big(b) => {
                // The value itself when no other clone holds it.
                let Big { value, approx } = Arc::unwrap_or_clone(b);
                Rational(Repr::Big(Arc::new(Big {
                    value: -value,
                    approx: -approx,
                })))
            }
        }
    }
}

/// The big integer of a signed string of decimal digits (checked by [`Literal::parse`]).
fn digits(s: &str) -> BigInt {
    BigInt::parse_bytes(s.as_bytes(), 10).unwrap_or_default()
}

/// `v` within 3 ulps (numerator and denominator rounded, then divided: cheaper than the
/// correctly rounded `to_f64`); NaN for a big value out of `f64`'s range ([`Big::boxed`]).
fn approx(v: &Rational) -> f64 {
    match &v.0 {
        Repr::Small(n, 1) => *n as f64,
        Repr::Small(n, d) => *n as f64 / *d as f64,
        Repr::Big(b) => b.approx,
    }
}

/// Sign of the determinant `(b − a) × (c − a)` in integers, without reducing any intermediate
/// (a rational sum would take a gcd at every step): with every coordinate `n / d`, `d > 0`,
/// each difference is an integer over a positive product of denominators, and the two products
/// compare as `n₁n₂·d_by·d_cx` against `n₃n₄·d_bx·d_cy` (the factors `d_ax·d_ay` cancel).
fn fraction_free_orient(a: [&Rational; 2], b: [&Rational; 2], c: [&Rational; 2]) -> Ordering {
    let [ax, ay, bx, by, cx, cy] = [a[0], a[1], b[0], b[1], c[0], c[1]].map(|v| v.big());
    let diff = |p: &BigRational, q: &BigRational| p.numer() * q.denom() - q.numer() * p.denom();
    let (bax, cay) = (diff(&bx, &ax), diff(&cy, &ay));
    let (bay, cax) = (diff(&by, &ay), diff(&cx, &ax));
    let left = bax * cay * by.denom() * cx.denom();
    let right = bay * cax * bx.denom() * cy.denom();
    left.cmp(&right)
}

/// Sign of det[b − a, c − a, d − a] for small values on a common grid (decimal input: every
/// denominator divides a power of ten): with L < 2⁶² the lcm of the twelve denominators, the
/// coordinates times L are integers below 2¹²⁴ and their differences below 2¹²⁵, whose
/// determinant is taken on `i128`s when they are below 2⁶¹ ([`det3_sign`]), in big integers
/// otherwise. `None` for a big value or a larger L.
fn lattice_orient3d(points: [[&Rational; 3]; 4]) -> Option<Ordering> {
    let mut terms = [[(0i128, 1i128); 3]; 4];
    let mut l: i128 = 1;
    for (t, p) in terms.iter_mut().flatten().zip(points.iter().flatten()) {
        let Repr::Small(n, d) = p.0 else {
            return None;
        };
        let d = i128::from(d);
        if l % d != 0 {
            l = l / big::gcd_u128(l.unsigned_abs(), d.unsigned_abs()) as i128 * d;
            if l >= LIMIT {
                return None;
            }
        }
        *t = (i128::from(n), d);
    }
    let [o, rest @ ..] = terms.map(|p| p.map(|(n, d)| n * (l / d)));
    let [u, v, w] = rest.map(|p| [0, 1, 2].map(|k| p[k] - o[k]));
    let narrow = |p: [i128; 3]| -> Option<[i64; 3]> {
        let mut out = [0i64; 3];
        for (o, x) in out.iter_mut().zip(p) {
            *o = i64::try_from(x).ok().filter(|x| x.abs() < 1 << 61)?;
        }
        Some(out)
    };
    Some(match (narrow(u), narrow(v), narrow(w)) {
        (Some(u), Some(v), Some(w)) => det3_sign(u, v, w),
        _ => {
            let big = |p: [i128; 3]| p.map(BigInt::from);
            let (z, u, v, w) = (big([0; 3]), big(u), big(v), big(w));
            exact_orient3d(z.each_ref(), u.each_ref(), v.each_ref(), w.each_ref())
        }
    })
}

/// Sign of det[b − a, c − a, d − a] in integers, without reducing any intermediate (a rational
/// sum would take a gcd at every step): each difference p − a is a vector of integers over
/// positive denominators, scaled by their product (by one of them where they are equal, as the
/// coordinates of a constructed point's homogeneous form are) to a vector of integers, which
/// changes the determinant by a positive factor.
fn fraction_free_orient3d(
    a: [&Rational; 3],
    b: [&Rational; 3],
    c: [&Rational; 3],
    d: [&Rational; 3],
) -> Ordering {
    let a = a.map(|v| v.big());
    let scaled = |p: [&Rational; 3]| -> [BigInt; 3] {
        let p = p.map(|v| v.big());
        let num = [0, 1, 2].map(|k| p[k].numer() * a[k].denom() - a[k].numer() * p[k].denom());
        let den = [0, 1, 2].map(|k| p[k].denom() * a[k].denom());
        if den[0] == den[1] && den[1] == den[2] {
            num
        } else {
            let [x, y, z] = num;
            let [dx, dy, dz] = den;
            [x * &dy * &dz, y * &dx * &dz, z * dx * dy]
        }
    };
    let (u, v, w) = (scaled(b), scaled(c), scaled(d));
    let zero = [0, 0, 0].map(BigInt::from);
    exact_orient3d(zero.each_ref(), u.each_ref(), v.each_ref(), w.each_ref())
}

/// The coordinates of a point as `i128` if they are integers of magnitude below `bound`: below
/// 2⁶¹, the 2D orientation determinant of such points is computed exactly in `i128` (its
/// differences stay below 2⁶², its products below 2¹²⁴).
fn integers<const K: usize>(p: [&Rational; K], bound: i64) -> Option<[i128; K]> {
    let mut out = [0i128; K];
    for (o, v) in out.iter_mut().zip(p) {
        match v.0 {
            Repr::Small(n, 1) if n.abs() < bound => *o = n.into(),
            _ => return None,
        }
    }
    Some(out)
}

/// The crossing of the lines `ab` and `cd` (not parallel) without a gcd per operation: each
/// point in homogeneous integers (x·d_x·d_y, y·d_x·d_y, d_x·d_y), each line the cross product
/// of its two points divided by the gcd of its three coefficients (a line through cut points of
/// an input edge comes back to that edge's own coefficients, however big the cut points'
/// numbers), the crossing the cross product of the two lines, and one reduction per coordinate.
fn homogeneous_crossing(
    a: [&Rational; 2],
    b: [&Rational; 2],
    c: [&Rational; 2],
    d: [&Rational; 2],
) -> [Rational; 2] {
    let point = |p: [&Rational; 2]| {
        let (x, y) = (p[0].big(), p[1].big());
        [
            x.numer() * y.denom(),
            y.numer() * x.denom(),
            x.denom() * y.denom(),
        ]
    };
    let cross = |u: &[BigInt; 3], v: &[BigInt; 3]| {
        [
            &u[1] * &v[2] - &u[2] * &v[1],
            &u[2] * &v[0] - &u[0] * &v[2],
            &u[0] * &v[1] - &u[1] * &v[0],
        ]
    };
    let line = |p: [&Rational; 2], q: [&Rational; 2]| {
        let l = cross(&point(p), &point(q));
        let g = big::gcd(&big::gcd(&l[0], &l[1]), &l[2]);
        l.map(|v| big::exact_div(&v, &g))
    };
    let [x, y, w] = cross(&line(a, b), &line(c, d));
    [Rational::new(x, w.clone()), Rational::new(y, w)]
}

/// The coordinates of a point as `f64`s if each is one exactly (a small value with at most 53
/// significant bits over a power of two: what `f64` input reads as), for the dyadic fast path of
/// the orientation predicates: Shewchuk's adaptive arithmetic on the `f64`s (`robust`), exact
/// for them, instead of big rationals.
fn dyadic<const K: usize>(p: [&Rational; K]) -> Option<[f64; K]> {
    let mut out = [0.0; K];
    for (o, v) in out.iter_mut().zip(p) {
        match v.0 {
            Repr::Small(n, d) if d & (d - 1) == 0 && n.unsigned_abs() <= 1 << 53 => {
                *o = n as f64 / d as f64;
            }
            _ => return None,
        }
    }
    Some(out)
}

impl Num for Rational {
    type Ctx = ();
    const EXACT: bool = true;

    fn nearest(r: &Rational) -> Self {
        r.clone()
    }

    fn from_i64(v: i64) -> Self {
        lowest(v.into(), 1)
    }

    fn half(&self) -> Self {
        // Lowest terms without a gcd: halve an even numerator, else double the denominator.
        match &self.0 {
            Repr::Small(n, d) if n % 2 == 0 => lowest((n / 2).into(), (*d).into()),
            Repr::Small(n, d) => lowest((*n).into(), 2 * *d as i128),
            Repr::Big(b) => {
                let (n, d) = (b.value.numer(), b.value.denom());
                from_big(if n.is_even() {
                    BigRational::new_raw(n / 2, d.clone())
                } else {
                    BigRational::new_raw(n.clone(), d * 2)
                })
            }
        }
    }

    fn from_f64(v: f64) -> Result<Self, NumError> {
        Rational::from_float(v).ok_or(NumError::NotFinite(v))
    }

    fn from_literal(lit: &Literal) -> Self {
        small_literal(&Parts::of(lit)).unwrap_or_else(|| big_literal(lit))
    }

    /// The literal's value: straight from its text where its terms fit in `i128` (a value that
    /// does not fit two `i64`s is then stored big), through big integers otherwise.
    fn parse(s: &str) -> Result<Self, NumError> {
        let parts = Parts::scan(s)?;
        Ok(small_literal(&parts).unwrap_or_else(|| big_literal(&parts.literal())))
    }

    fn approx(&self) -> f64 {
        approx(self)
    }

    fn small_fraction(&self) -> Option<(i64, i64)> {
        // A value with terms below 2⁶² is always stored small (the choice is canonical).
        match &self.0 {
            Repr::Small(n, d) => Some((*n, *d)),
            Repr::Big(_) => {
                let (n, d) = self.fraction();
                Some((i64::try_from(n).ok()?, i64::try_from(d).ok()?))
            }
        }
    }

    fn fraction(&self) -> (BigInt, BigInt) {
        (self.numer(), self.denom())
    }

    fn rational(&self) -> Rational {
        self.clone()
    }

    fn to_f64(&self) -> f64 {
        // At most 53 significant bits: exact as an f64 (every dyadic value read from an f64,
        // whatever its power-of-two denominator, is such a pair).
        let exact = |v: u64| v.leading_zeros() + v.trailing_zeros() >= 11;
        match &self.0 {
            // Both operands exact in f64: one correctly rounded division.
            Repr::Small(n, d) if exact(n.unsigned_abs()) && exact(d.unsigned_abs()) => {
                *n as f64 / *d as f64
            }
            Repr::Small(0, _) => 0.0,
            // Otherwise from the leading bits where they settle it, else one exact division.
            repr => {
                let (negative, n, d) = match repr {
                    Repr::Small(n, d) => (
                        (*n < 0) != (*d < 0),
                        Leading::of_u64(n.unsigned_abs()),
                        Leading::of_u64(d.unsigned_abs()),
                    ),
                    Repr::Big(b) => {
                        let (n, d) = (b.value.numer(), b.value.denom());
                        (
                            n.is_negative() != d.is_negative(),
                            Leading::of_big(n.magnitude()),
                            Leading::of_big(d.magnitude()),
                        )
                    }
                };
                match nearest_f64(n, d) {
                    Some(v) if negative => -v,
                    Some(v) => v,
                    None => ToPrimitive::to_f64(self.big().as_ref()).unwrap_or(f64::NAN),
                }
            }
        }
    }

    fn sign(&self) -> Ordering {
        match &self.0 {
            Repr::Small(n, _) => n.cmp(&0),
            Repr::Big(b) if b.value.is_zero() => Ordering::Equal,
            Repr::Big(b) if b.value.is_positive() => Ordering::Greater,
            Repr::Big(_) => Ordering::Less,
        }
    }

    fn crossing(a: [&Self; 2], b: [&Self; 2], c: [&Self; 2], d: [&Self; 2]) -> [Self; 2] {
        homogeneous_crossing(a, b, c, d)
    }

    fn orient2d(a: [&Self; 2], b: [&Self; 2], c: [&Self; 2], _ctx: &()) -> Ordering {
        let f = |p: [&Self; 2]| [approx(p[0]), approx(p[1])];
        filtered_orient(f(a), f(b), f(c)).unwrap_or_else(|| unfiltered_orient(a, b, c))
    }

    fn orient3d(a: [&Self; 3], b: [&Self; 3], c: [&Self; 3], d: [&Self; 3], _ctx: &()) -> Ordering {
        let f = |p: [&Self; 3]| p.map(approx);
        filtered_orient3d(f(a), f(b), f(c), f(d)).unwrap_or_else(|| {
            // A repeated point (triangles sharing a corner) spans no volume, which no filter
            // can certify; nor do points in one axis-parallel plane (faces of boxes, voxels
            // and extrusions), where one column of differences is zero.
            if a == d || b == d || c == d || a == b || b == c || c == a {
                return Ordering::Equal;
            }
            if (0..3).any(|k| a[k] == b[k] && a[k] == c[k] && a[k] == d[k]) {
                return Ordering::Equal;
            }
            match (dyadic(a), dyadic(b), dyadic(c), dyadic(d)) {
                (Some(a), Some(b), Some(c), Some(d)) => exact_orient3d_f64(a, b, c, d),
                _ => lattice_orient3d([a, b, c, d])
                    .unwrap_or_else(|| fraction_free_orient3d(a, b, c, d)),
            }
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(yinset_testkit::cases(1024)))]
        /// A parsed decimal or fraction (on the `u64` decimal path, the `i128` path and the
        /// big path) is the value that big integers make of its digits, in canonical form.
        #[test]
        fn parsed_literals_are_their_exact_values(
            (text, want) in crate::num::literal::texts::literals(true),
        ) {
            let got = Rational::parse(&text).unwrap();
            proptest::prop_assert!(got == Rational::from(want.clone()), "{}", text);
            proptest::prop_assert_eq!(got.fraction(), (want.numer().clone(), want.denom().clone()));
        }
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(yinset_testkit::cases(256)))]
        /// The section point of a line through integer points equals each coordinate's
        /// quotient reduced by a full gcd, for u and v with common factors, equal coordinates
        /// (V − U = 0), coordinates past 128 bits and scales both ways.
        #[test]
        fn section_point_is_the_reduced_quotient(
            (u, v) in (-1i64 << 40..1i64 << 40, -1i64 << 40..1i64 << 40),
            h in 1i64..1_000_000,
            wide in proptest::array::uniform3(0u32..3),
            pu in proptest::array::uniform3(-1000i64..1000),
            step in proptest::array::uniform3(-3i64..3),
            scale in -100i32..100,
        ) {
            proptest::prop_assume!(u != v);
            let big = |x: i64| BigInt::from(x) * BigInt::from(h) * BigInt::from(h);
            let (u, v) = (big(u), big(v));
            // Coordinates times 2^0, 2^70 or 2^140 (the last past u128).
            let at = |x: i64, k: usize| BigInt::from(x) << (70 * wide[k]);
            let pu = [0, 1, 2].map(|k| at(pu[k], k));
            let pv = [0, 1, 2].map(|k| &pu[k] + at(step[k] * 7, k));
            let got = Rational::section_point(&u, &v, [&pu, &pv], scale);
            for k in 0..3 {
                let two = Rational::new(BigInt::from(1) << scale.unsigned_abs(), BigInt::from(1));
                let q = Rational::new(&u * &pv[k] - &v * &pu[k], &u - &v);
                let want = if scale >= 0 { q * two } else { q / two };
                proptest::prop_assert_eq!(&got[k], &want);
                proptest::prop_assert_eq!(got[k].denom().sign() == num_bigint::Sign::Plus, true);
            }
        }
    }

    #[test]
    fn parses_without_rounding() {
        let x = Rational::parse("4.5040114e+00").unwrap();
        assert_eq!(x, Rational::new(45040114.into(), 10_000_000.into()));
        let tenth = Rational::parse("0.1").unwrap();
        assert_eq!(tenth * Rational::from_i64(10), Rational::from_i64(1));
        assert_eq!(
            Rational::parse("1/3").unwrap(),
            Rational::new(1.into(), 3.into())
        );
        assert_eq!(
            Rational::parse("-2.5e-1").unwrap(),
            Rational::new((-1).into(), 4.into())
        );
    }

    /// A numerator of 54 significant bits is not rounded before the division: (2⁵³ + 1) / 3 is
    /// the integer 3002399751580331, which an f64 holds, while 2⁵³ / 3 rounds to …330.5.
    #[test]
    fn to_f64_rounds_once() {
        let x = Rational::new(((1i64 << 53) + 1).into(), 3.into());
        assert_eq!(Num::to_f64(&x), 3002399751580331.0);
    }

    /// `Debug` writes the value as `Display` does: lowest terms, the integer alone when the
    /// denominator is 1.
    #[test]
    fn debug_is_the_fraction() {
        let x = Rational::new(14.into(), (-4).into());
        assert_eq!(format!("{x:?}"), "-7/2");
        assert_eq!(format!("{:?}", Rational::from_i64(5)), "5");
    }

    /// `integers` takes a point only if every coordinate is an integer of magnitude below the
    /// bound: ±(2⁴⁰ − 1) pass the bound 2⁴⁰, ±2⁴⁰, 1/2 and 2⁷⁰ do not.
    #[test]
    fn integers_are_bounded() {
        let n = |v: i64| Rational::from_i64(v);
        let (top, over) = (n((1 << 40) - 1), n(1 << 40));
        assert_eq!(
            integers([&top, &-top.clone()], 1 << 40),
            Some([(1 << 40) - 1, 1 - (1 << 40)])
        );
        assert_eq!(integers([&top, &over], 1 << 40), None);
        assert_eq!(integers([&-over.clone(), &top], 1 << 40), None);
        assert_eq!(integers([&n(1).half()], 1 << 40), None);
        assert_eq!(
            integers([&Rational::from_integer(BigInt::from(1) << 70)], 1 << 40),
            None
        );
    }

    /// `nearest` of the exact backend is the value itself, small or big.
    #[test]
    fn nearest_is_the_value() {
        let small = Rational::new((-7).into(), 2.into());
        let big = Rational::new(BigInt::from(10).pow(40) + 1, 3.into());
        for x in [small, big] {
            assert_eq!(<Rational as Num>::nearest(&x), x);
        }
    }

    /// Negating a big value negates its approximation too, which the comparison filter reads:
    /// −(10⁴⁰ + 1)/(3·10³⁹) lies below −10/3, and its approximation is negative.
    #[test]
    fn negation_of_a_big_value_compares_below() {
        let ten = |k: u32| BigInt::from(10).pow(k);
        let x = Rational::new(ten(40) + 1, BigInt::from(3) * ten(39));
        assert!(matches!(x.0, Repr::Big(_)));
        let y = Rational::new((-10).into(), 3.into());
        assert!(Num::approx(&-x.clone()) < 0.0);
        assert!(-x.clone() < y);
        assert_eq!((-x.clone()).cmp(&y), Ordering::Less);
        assert_eq!(-(-x.clone()), x);
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(yinset_testkit::cases(256)))]
        /// `to_f64` is num-rational's correctly rounded value, both signs, for small fractions
        /// with more than 53 significant bits and for big ones of up to 300 bits a side.
        #[test]
        fn to_f64_is_the_nearest_f64(
            n in proptest::num::i64::ANY, d in 1i64..i64::MAX, k in 0u32..240, j in 0u32..240,
        ) {
            for (n, d) in [
                (BigInt::from(n >> 2), BigInt::from(d >> 2 | 1)),
                ((BigInt::from(n) << k) + 1, (BigInt::from(d) << j) + 3),
            ] {
                let reference = ToPrimitive::to_f64(&BigRational::new(n.clone(), d.clone()));
                proptest::prop_assert_eq!(Some(Num::to_f64(&Rational::new(n, d))), reference);
            }
        }
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(yinset_testkit::cases(256)))]
        /// `from_lowest_words` is the value `Rational::new` makes of the same terms, in the same
        /// representation (small for terms below 2⁶², big otherwise), with the approximation it
        /// is given signed: on coprime terms of one to four words, either sign.
        #[test]
        fn from_lowest_words_is_the_value(
            n in proptest::collection::vec(proptest::num::u64::ANY, 1..5),
            d in proptest::collection::vec(proptest::num::u64::ANY, 1..5),
            narrow in 0u32..64,
            negative in proptest::bool::ANY,
        ) {
            let word = |w: &u64| w >> narrow;
            let (n, d): (Vec<u64>, Vec<u64>) = (n.iter().map(word).collect(), d.iter().map(word).collect());
            let value = |x: &[u64]| BigInt::from_biguint(Sign::Plus, big::from_words(x));
            let (m, e) = (value(&n), value(&d));
            proptest::prop_assume!(!m.is_zero() && !e.is_zero() && m.gcd(&e) == BigInt::from(1));
            let approx = ToPrimitive::to_f64(&m).unwrap_or(f64::NAN) / ToPrimitive::to_f64(&e).unwrap_or(f64::NAN);
            let got = Rational::from_lowest_words(negative, &n, &d, approx);
            let want = Rational::new(if negative { -m } else { m }, e);
            proptest::prop_assert_eq!(Num::approx(&got), Num::approx(&want));
            proptest::prop_assert!(got == want);
        }
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(yinset_testkit::cases(256)))]
        /// A literal's value is num-rational's reduced fraction of its numerator and
        /// denominator, in its canonical form: on decimals and fractions of 1 to 21 digits and
        /// exponents within ±21, both sides of the `i128` path's bounds (18 digits, ±18).
        #[test]
        fn literals_are_their_reduced_fractions(
            digits in "[0-9]{1,21}", den in "[1-9][0-9]{0,20}", exp10 in -21i64..=21,
            negative in proptest::bool::ANY, fraction in proptest::bool::ANY,
        ) {
            let den = if fraction { den } else { "1".to_string() };
            let lit = Literal { negative, digits, exp10, den };
            let (n, d) = lit.fraction();
            let want = BigRational::new(n.parse().unwrap(), d.parse().unwrap());
            let got = Rational::from_literal(&lit);
            proptest::prop_assert!(got == Rational::from(want.clone()));
            proptest::prop_assert_eq!(got.fraction(), (want.numer().clone(), want.denom().clone()));
        }
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(yinset_testkit::cases(1024)))]
        /// `is_f64` holds exactly where the value is m·2^e with m odd below 2⁵³ and
        /// −1074 ≤ e ≤ 1023 − (bits of m − 1): on dyadic values of 1 to 58 significant bits
        /// across and beyond `f64`'s exponents (small and big), and never on a value over 3.
        #[test]
        fn is_f64_holds_exactly_for_the_values_of_f64s(
            m in 1u64..1 << 58, e in -1140i32..1080, negative in proptest::bool::ANY,
        ) {
            let (odd, e) = (m >> m.trailing_zeros(), e + m.trailing_zeros() as i32);
            let bits = 64 - odd.leading_zeros() as i32;
            let want = odd < 1 << 53 && e >= -1074 && e + bits <= 1024;
            let n = BigInt::from(m) * BigInt::from(if negative { -1 } else { 1 });
            let v = Rational::times_power_of_two(n.clone(), BigInt::from(1), e - m.trailing_zeros() as i32);
            proptest::prop_assert_eq!(v.is_f64(), want);
            let thirds = Rational::times_power_of_two(n * 3 + 1, BigInt::from(3), e);
            proptest::prop_assert!(!thirds.is_f64());
        }
    }

    #[test]
    fn from_f64_is_lossless() {
        let x = Rational::from_f64(0.1).unwrap();
        assert_ne!(x, Rational::parse("0.1").unwrap());
        assert_eq!(Num::to_f64(&x), 0.1);
        assert!(Rational::from_f64(f64::NAN).is_err());
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(yinset_testkit::cases(256)))]
        /// The exact value of an `f64` (small when it fits) is num-rational's, canonical form
        /// included, and converts back to the same `f64`: on every bit pattern (subnormals and
        /// huge exponents), on numbers of moderate size and fractions with denominators up to
        /// 2^70, where the small path applies and ends, and on integers and powers of two
        /// around 2^62, where it ends for integers.
        #[test]
        fn from_float_is_the_exact_value(
            bits in proptest::num::u64::ANY, moderate in -1e6f64..1e6, shift in 0i32..70,
        ) {
            // Integers with up to 69 trailing zero bits: small up to 2^62, big from there.
            let round = moderate.trunc() * 2f64.powi(shift);
            let fraction = moderate * 2f64.powi(-shift);
            let values = [f64::from_bits(bits), moderate, round, fraction, 2f64.powi(shift)];
            for v in values.into_iter().flat_map(|v| [v, -v]).filter(|v| v.is_finite()) {
                let exact = Rational::from_float(v);
                proptest::prop_assert_eq!(&exact, &BigRational::from_float(v).map(Rational::from));
                proptest::prop_assert_eq!(exact.map(|r| Num::to_f64(&r)), Some(v));
            }
        }
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(yinset_testkit::cases(256)))]
        /// The filtered order is `num-rational`'s order: on random fractions, on fractions
        /// a few ulps apart, and on equal values written with different denominators.
        #[test]
        fn filtered_order_is_the_exact_order(
            n in -1_000_000_000_000i64..1_000_000_000_000,
            d in 1i64..1_000_000_000_000,
            m in -1_000_000_000_000i64..1_000_000_000_000,
            e in 1i64..1_000_000_000_000,
            k in -3i64..=3,
            big in 0u32..200,
        ) {
            let scale = BigInt::from(2).pow(big);
            let q = |n: BigInt, d: BigInt| BigRational::new(n * &scale, d);
            let (n, d, m, e, k) = (BigInt::from(n), BigInt::from(d), BigInt::from(m), BigInt::from(e), BigInt::from(k));
            let cases = [
                (q(n.clone(), d.clone()), q(m, e.clone())),
                // n/d against (n·e + k)/(d·e): equal or within ~1e-24 of each other.
                (q(n.clone(), d.clone()), q(&n * &e + k, &d * &e)),
                (q(n.clone(), d.clone()), BigRational::new(&n * &scale * 3, d * 3)),
            ];
            for (x, y) in cases {
                let (a, b) = (Rational::from(x.clone()), Rational::from(y.clone()));
                proptest::prop_assert_eq!(a.cmp(&b), x.cmp(&y));
                proptest::prop_assert_eq!(b.cmp(&a), y.cmp(&x));
            }
        }
    }

    /// A value near the small/big boundary: ±(2⁶² + k) / (m or 2⁶¹ + m), so that sums,
    /// products and quotients leave the small representation and come back.
    fn edge_value() -> impl proptest::strategy::Strategy<Value = BigRational> {
        use proptest::prelude::*;
        let part = prop_oneof![
            -20i128..20,
            (-5i128..5).prop_map(|k| (1i128 << 62) + k),
            (-5i128..5).prop_map(|k| -(1i128 << 62) + k),
            (-5i128..5).prop_map(|k| (1i128 << 61) + k),
            any::<i64>().prop_map(i128::from),
            any::<i32>().prop_map(i128::from),
        ];
        (part.clone(), part).prop_filter_map("zero denominator", |(n, d)| {
            (d != 0).then(|| BigRational::new(n.into(), d.into()))
        })
    }

    /// A big value (up to ~190-bit numerator and denominator) with factors drawn from a few
    /// shared ones, so that sums and products of two such values cancel across (the gcds of
    /// Knuth's reductions in `num::big` are then not 1).
    fn big_value() -> impl proptest::strategy::Strategy<Value = BigRational> {
        use proptest::prelude::*;
        let common = prop_oneof![
            Just(1i64),
            Just(6),
            Just(1 << 40),
            Just(999_999_937),
            Just(3 * 5 * 7 * 11 * 13 * 17 * 19 * 23),
        ];
        let nonzero = any::<i64>().prop_filter("zero", |v| *v != 0);
        (
            any::<i64>(),
            any::<i64>(),
            nonzero.clone(),
            nonzero,
            common.clone(),
            common,
        )
            .prop_map(|(a, b, c, d, f, g)| {
                let big =
                    |x: i64, y: i64, z: i64| BigInt::from(x) * BigInt::from(y) * BigInt::from(z);
                BigRational::new(big(a, b, f), big(c, d, g))
            })
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(yinset_testkit::cases(256)))]
        /// Arithmetic, order, sign, halving and conversions of the inline representation equal
        /// `num-rational`'s on values across the small/big boundary and on big values with
        /// shared factors, and the representation stays canonical (equal values compare and
        /// hash equal however they were computed).
        #[test]
        fn inline_arithmetic_is_num_rationals(
            x in proptest::prop_oneof![edge_value(), big_value()],
            y in proptest::prop_oneof![edge_value(), big_value()],
        ) {
            use std::hash::{BuildHasher, RandomState};
            let (a, b) = (Rational::from(x.clone()), Rational::from(y.clone()));
            let same = |r: Rational, e: BigRational| {
                let canonical = Rational::from(e.clone());
                let h = RandomState::new();
                r.big().as_ref() == &e && r == canonical && h.hash_one(&r) == h.hash_one(&canonical)
            };
            proptest::prop_assert!(same(a.clone() + b.clone(), &x + &y));
            proptest::prop_assert!(same(a.clone() - b.clone(), &x - &y));
            proptest::prop_assert!(same(a.clone() * b.clone(), &x * &y));
            if !y.is_zero() {
                proptest::prop_assert!(same(a.clone() / b.clone(), &x / &y));
            }
            proptest::prop_assert!(same(-a.clone(), -x.clone()));
            proptest::prop_assert!(same(a.clone() + -a.clone(), BigRational::zero()));
            proptest::prop_assert!(same(Rational::new(x.numer() * 3, x.denom() * -3), -x.clone()));
            proptest::prop_assert!(same(a.half(), &x / BigRational::from_integer(2.into())));
            proptest::prop_assert_eq!(a.cmp(&b), x.cmp(&y));
            proptest::prop_assert_eq!(a.sign(), x.cmp(&BigRational::zero()));
            proptest::prop_assert_eq!(Num::to_f64(&a), ToPrimitive::to_f64(&x).unwrap());
            proptest::prop_assert_eq!(a.to_string(), x.to_string());
            proptest::prop_assert_eq!((a.numer(), a.denom()), (x.numer().clone(), x.denom().clone()));
        }
    }

    /// The sign of the orientation determinant of a, b, c in plain `num-rational` arithmetic,
    /// without any filter: the oracle of the filtered predicates.
    fn plain_orient(a: [&BigRational; 2], b: [&BigRational; 2], c: [&BigRational; 2]) -> Ordering {
        let det = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
        det.cmp(&BigRational::zero())
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(yinset_testkit::cases(256)))]
        /// `orient3d` (f64 filter, i128, dyadic and rational fallbacks) agrees with plain
        /// rational arithmetic when d is on the plane through a, b, c as rounded to f64 and
        /// then moved a few ulps (the filter defers; the dyadic path decides).
        #[test]
        fn filtered_orient3d_is_plain_rational_near_a_plane(
            a in proptest::array::uniform3(-1e3f64..1e3),
            u in proptest::array::uniform3(-1e3f64..1e3),
            v in proptest::array::uniform3(-1e3f64..1e3),
            st in (0.0f64..1.0, 0.0f64..1.0),
            k in proptest::array::uniform3(-3i64..=3),
        ) {
            let b = [0, 1, 2].map(|i| a[i] + u[i]);
            let c = [0, 1, 2].map(|i| a[i] + v[i]);
            let d = [0, 1, 2].map(|i| ulps(a[i] + st.0 * u[i] + st.1 * v[i], k[i]));
            let [ea, eb, ec, ed] = [a, b, c, d].map(|p| p.map(exact));
            let [ra, rb, rc, rd] = [&ea, &eb, &ec, &ed].map(|p| p.clone().map(Rational::from));
            proptest::prop_assert_eq!(
                Rational::orient3d(ra.each_ref(), rb.each_ref(), rc.each_ref(), rd.each_ref(), &()),
                exact_orient3d(ea.each_ref(), eb.each_ref(), ec.each_ref(), ed.each_ref())
            );
        }
    }

    /// A value of any size: `n / d` raised to the power `k` (up to ~400 bits in numerator and
    /// denominator), so that crossings of crossings occur.
    fn sized(n: i64, d: i64, k: u32) -> BigRational {
        BigRational::new(n.into(), d.into()).pow(k as i32)
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(yinset_testkit::cases(256)))]
        /// The homogeneous crossing construction equals the plain rational formula
        /// a + t (b − a), t = ((c − a) × (d − c)) / ((b − a) × (d − c)), on coordinates from
        /// small integers to ~400-bit fractions, including lines through a common point (whose
        /// line coefficients share big factors) and points on one line scaled apart.
        #[test]
        fn homogeneous_crossing_is_the_plain_rational_crossing(
            v in proptest::collection::vec((-1000i64..1000, 1i64..1000, 1u32..8), 8),
            shared in proptest::bool::ANY,
        ) {
            let mut e: Vec<BigRational> = v.iter().map(|&(n, d, k)| sized(n, d, k)).collect();
            if shared {
                // c = a: both lines through one point, so their coefficients share its size.
                e[4] = e[0].clone();
                e[5] = e[1].clone();
            }
            let p = |i: usize| [&e[i], &e[i + 1]];
            let (a, b, c, d) = (p(0), p(2), p(4), p(6));
            let cross = |u: [BigRational; 2], w: [BigRational; 2]| &u[0] * &w[1] - &u[1] * &w[0];
            let diff = |p: [&BigRational; 2], q: [&BigRational; 2]| [p[0] - q[0], p[1] - q[1]];
            let den = cross(diff(b, a), diff(d, c));
            proptest::prop_assume!(!den.is_zero());
            let t = cross(diff(c, a), diff(d, c)) / den;
            let want = [a[0] + &t * (b[0] - a[0]), a[1] + &t * (b[1] - a[1])];
            let r: Vec<Rational> = e.iter().cloned().map(Rational::from).collect();
            let q = |i: usize| [&r[i], &r[i + 1]];
            let got = Rational::crossing(q(0), q(2), q(4), q(6));
            proptest::prop_assert_eq!(got, want.map(Rational::from));
        }
    }

    /// `v` moved by `k` units in the last place.
    fn ulps(v: f64, k: i64) -> f64 {
        let bits = v.to_bits() as i64 + if v >= 0.0 { k } else { -k };
        f64::from_bits(bits as u64)
    }

    /// The exact value of a finite `f64`.
    fn exact(v: f64) -> BigRational {
        BigRational::from_float(v).expect("finite")
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(yinset_testkit::cases(256)))]
        /// The filtered `orient2d` (f64 filter, i128 and rational fallbacks) agrees with plain
        /// rational arithmetic on near-degenerate inputs: c on the line through a and b as
        /// rounded to f64 and then moved a few ulps, and the exact crossing point of two nearly
        /// parallel segments (directions d and d + a few ulps) against either segment, a third
        /// line through it, and the line of the other segment moved by an ulp.
        #[test]
        fn filtered_orient2d_is_plain_rational_on_near_degenerate_inputs(
            a in (-1e3f64..1e3, -1e3f64..1e3),
            d in (-1e3f64..1e3, -1e3f64..1e3),
            t in 0.0f64..1.0,
            k in (-3i64..=3, -3i64..=3),
            q in (-1e3f64..1e3, -1e3f64..1e3),
            tilt in (-4i64..=4, -4i64..=4),
        ) {
            let a = [a.0, a.1];
            let b = [a[0] + d.0, a[1] + d.1];
            let c = [ulps(a[0] + t * d.0, k.0), ulps(a[1] + t * d.1, k.1)];
            let [ea, eb, ec] = [a, b, c].map(|p| p.map(exact));
            let [ra, rb, rc] = [&ea, &eb, &ec].map(|p| p.clone().map(Rational::from));
            proptest::prop_assert_eq!(
                Rational::orient2d(ra.each_ref(), rb.each_ref(), rc.each_ref(), &()),
                plain_orient(ea.each_ref(), eb.each_ref(), ec.each_ref())
            );
            // Segment 2 from q along d tilted by a few ulps: nearly parallel to segment 1.
            let q2 = [q.0 + ulps(d.0, tilt.0), q.1 + ulps(d.1, tilt.1)];
            let [eq, eq2] = [[q.0, q.1], q2].map(|p| p.map(exact));
            let (u, v) = ([&eb[0] - &ea[0], &eb[1] - &ea[1]], [&eq2[0] - &eq[0], &eq2[1] - &eq[1]]);
            let den = &u[0] * &v[1] - &u[1] * &v[0];
            proptest::prop_assume!(!den.is_zero());
            let s = ((&eq[0] - &ea[0]) * &v[1] - (&eq[1] - &ea[1]) * &v[0]) / den;
            let ex = [&ea[0] + &s * &u[0], &ea[1] + &s * &u[1]];
            let rx = ex.clone().map(Rational::from);
            // Degenerate by construction: the crossing lies on both segments' lines.
            proptest::prop_assert_eq!(plain_orient(ea.each_ref(), eb.each_ref(), ex.each_ref()), Ordering::Equal);
            let [rq, rq2] = [&eq, &eq2].map(|p| p.clone().map(Rational::from));
            let eq_moved = [exact(ulps(q.0, 1)), eq[1].clone()];
            let rq_moved = eq_moved.clone().map(Rational::from);
            let cases = [
                (ra.each_ref(), rb.each_ref(), ea.each_ref(), eb.each_ref()),
                (rq.each_ref(), rq2.each_ref(), eq.each_ref(), eq2.each_ref()),
                (ra.each_ref(), rq2.each_ref(), ea.each_ref(), eq2.each_ref()),
                (rq_moved.each_ref(), rq2.each_ref(), eq_moved.each_ref(), eq2.each_ref()),
            ];
            for (p1, p2, e1, e2) in cases {
                proptest::prop_assert_eq!(
                    Rational::orient2d(p1, p2, rx.each_ref(), &()),
                    plain_orient(e1, e2, ex.each_ref())
                );
            }
        }
    }

    #[test]
    fn huge_denominators_defer_to_exact_comparison() {
        // (10³⁰⁰ + 1)/10⁴⁰⁰ ≈ 10⁻¹⁰⁰ has a finite numerator over a denominator that overflows
        // f64: read as 0 it would order below 10⁻²⁰⁰ and turn orientations around.
        let big = BigInt::from(10).pow(300) + 1;
        let a = Rational::new(big, BigInt::from(10).pow(400));
        let b = Rational::new(1.into(), BigInt::from(10).pow(200));
        assert!(approx(&a).is_nan());
        assert_eq!(a.cmp(&b), Ordering::Greater);
        assert_eq!(b.cmp(&a), Ordering::Less);
        let (o, x) = (Rational::from_i64(0), Rational::from_i64(1));
        // (0,0) → (1,0) → (b, a): a point above the x-axis, to the left of the direction.
        assert_eq!(
            Rational::orient2d([&o, &o], [&x, &o], [&b, &a], &()),
            Ordering::Greater
        );
        let neg = -a.clone();
        assert_eq!(
            Rational::orient2d([&o, &o], [&x, &o], [&b, &neg], &()),
            Ordering::Less
        );
    }

    #[test]
    fn half_stays_in_lowest_terms() {
        for (n, d) in [(3, 4), (6, 5), (-7, 2), (0, 1), (10, 3)] {
            let x = Rational::new(n.into(), d.into());
            let h = x.half();
            assert_eq!(h, Rational::new(n.into(), (2 * d).into()));
            assert_eq!(h.clone() + h, x);
        }
    }

    /// The sign of det[b − a, c − a, d − a] in plain `num-rational` arithmetic: the oracle of
    /// the 3D predicates.
    fn plain_orient3d(p: &[[BigRational; 3]; 4]) -> Ordering {
        let [u, v, w] = [1, 2, 3].map(|i| [0, 1, 2].map(|k| &p[i][k] - &p[0][k]));
        let det = &u[0] * (&v[1] * &w[2] - &v[2] * &w[1]) - &u[1] * (&v[0] * &w[2] - &v[2] * &w[0])
            + &u[2] * (&v[0] * &w[1] - &v[1] * &w[0]);
        det.cmp(&BigRational::zero())
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(yinset_testkit::cases(256)))]
        /// `orient3d` and `orient2d` agree with plain rational arithmetic on points sharing one
        /// coordinate (an axis-parallel plane or line: zero), and on the same points with the
        /// last one's shared coordinate nudged by 2⁻⁶² (not zero unless the rest is
        /// degenerate): big fractions, so that no filter decides.
        #[test]
        fn axis_parallel_points_are_plain_rational(
            terms in proptest::array::uniform12((-(1i64 << 40)..1 << 40, 1i64..1 << 40)),
            axis in 0usize..3,
            nudge in -2i64..=2,
        ) {
            let q = |(n, d): (i64, i64)| BigRational::new(n.into(), d.into());
            let shared = q(terms[0]);
            let mut p: [[BigRational; 3]; 4] =
                std::array::from_fn(|i| std::array::from_fn(|k| q(terms[(3 * i + k) % 12])));
            for (i, point) in p.iter_mut().enumerate() {
                point[axis] = shared.clone() + q((nudge * i64::from(i == 3), 1 << 62));
            }
            let r = p.clone().map(|x| x.map(Rational::from));
            let [ra, rb, rc, rd] = r.each_ref().map(|x| x.each_ref());
            proptest::prop_assert_eq!(Rational::orient3d(ra, rb, rc, rd, &()), plain_orient3d(&p));
            // The 2D test on the shared coordinate and the next, for the last three points: on
            // an axis-parallel line, or the last one off it.
            let (i, j) = (axis, (axis + 1) % 3);
            let (pb, pc, pd) = (&p[1], &p[2], &p[3]);
            proptest::prop_assert_eq!(
                Rational::orient2d([rb[i], rb[j]], [rc[i], rc[j]], [rd[i], rd[j]], &()),
                plain_orient([&pb[i], &pb[j]], [&pc[i], &pc[j]], [&pd[i], &pd[j]])
            );
        }
    }

    proptest::proptest! {
        /// `orient3d` agrees with plain rational arithmetic, and its semi-static filter is never
        /// wrong where it decides, on small triangles far from the origin (offsets to 10¹², sides
        /// down to 10⁻⁹) with decimal corners (not dyadic: the lattice path) and d exactly on
        /// their plane (a big value: the fraction-free path), or nudged off it by a few units of
        /// 10⁻ʲ, or repeating a corner.
        #[test]
        fn orient3d_is_plain_rational_for_small_triangles_far_out(
            offset in proptest::array::uniform3(-1_000_000_000_000i64..1_000_000_000_000),
            sides in proptest::array::uniform3(proptest::array::uniform3(-1000i64..1000)),
            scale in 0u32..10,
            places in 0u32..6,
            st in ((-50i64..50, 1i64..12), (-50i64..50, 1i64..12)),
            nudge in (0usize..3, -3i64..=3, 8u32..40),
            repeat in 0usize..8,
        ) {
            let ten = |k: u32| BigRational::from_integer(BigInt::from(10).pow(k));
            let a: [BigRational; 3] = offset.map(|x| BigRational::from_integer(x.into()) / ten(places));
            let corner = |s: [i64; 3]| [0, 1, 2].map(|k| &a[k] + BigRational::from_integer(s[k].into()) / ten(scale + places));
            let (b, c) = (corner(sides[0]), corner(sides[1]));
            let (s, t) = (BigRational::new(st.0.0.into(), st.0.1.into()), BigRational::new(st.1.0.into(), st.1.1.into()));
            let mut d = [0, 1, 2].map(|k| &a[k] + &s * (&b[k] - &a[k]) + &t * (&c[k] - &a[k]));
            d[nudge.0] += BigRational::from_integer(nudge.1.into()) / ten(nudge.2);
            let p = match repeat {
                0 => [a.clone(), b.clone(), c, a],
                1 => [a, b.clone(), c, b],
                _ => [a, b, c, d],
            };
            let r = p.clone().map(|q| q.map(Rational::from));
            let [ra, rb, rc, rd] = r.each_ref().map(|q| q.each_ref());
            let expected = plain_orient3d(&p);
            proptest::prop_assert_eq!(Rational::orient3d(ra, rb, rc, rd, &()), expected);
            let f = |q: [&Rational; 3]| q.map(approx);
            if let Some(sign) = filtered_orient3d(f(ra), f(rb), f(rc), f(rd)) {
                proptest::prop_assert_eq!(sign, expected);
            }
        }
    }

    proptest::proptest! {
        /// `orient2d` agrees with plain rational arithmetic, and its semi-static filter is never
        /// wrong where it decides, on short segments far from the origin (offsets to 10¹²,
        /// lengths down to 10⁻⁹) with decimal ends and c exactly on their line, nudged off it
        /// by a few units of 10⁻ʲ, or repeating an end.
        #[test]
        fn orient2d_is_plain_rational_for_short_segments_far_out(
            offset in proptest::array::uniform2(-1_000_000_000_000i64..1_000_000_000_000),
            side in proptest::array::uniform2(-1000i64..1000),
            scale in 0u32..10,
            places in 0u32..6,
            t in (-50i64..50, 1i64..12),
            nudge in (0usize..2, -3i64..=3, 8u32..40),
            repeat in 0usize..8,
        ) {
            let ten = |k: u32| BigRational::from_integer(BigInt::from(10).pow(k));
            let a: [BigRational; 2] = offset.map(|x| BigRational::from_integer(x.into()) / ten(places));
            let b = [0, 1].map(|k| &a[k] + BigRational::from_integer(side[k].into()) / ten(scale + places));
            let t = BigRational::new(t.0.into(), t.1.into());
            let mut c = [0, 1].map(|k| &a[k] + &t * (&b[k] - &a[k]));
            c[nudge.0] += BigRational::from_integer(nudge.1.into()) / ten(nudge.2);
            let p = if repeat == 0 { [a.clone(), b, a] } else { [a, b, c] };
            let expected = plain_orient(p[0].each_ref(), p[1].each_ref(), p[2].each_ref());
            let r = p.map(|q| q.map(Rational::from));
            let [ra, rb, rc] = r.each_ref().map(|q| q.each_ref());
            proptest::prop_assert_eq!(Rational::orient2d(ra, rb, rc, &()), expected);
            let f = |q: [&Rational; 2]| q.map(approx);
            if let Some(sign) = filtered_orient(f(ra), f(rb), f(rc)) {
                proptest::prop_assert_eq!(sign, expected);
            }
        }
    }

    /// The two exact fallbacks of `orient3d` on their own, against plain rational arithmetic:
    /// decimals on the lattice of 10⁻¹⁸ (coplanar, and a unit of the last place off the plane),
    /// and values of ~300-bit terms, where only the fraction-free one applies.
    #[test]
    fn exact_orient3d_fallbacks_are_plain_rational() {
        let r = |s: &str| Rational::parse(s).unwrap().big().into_owned();
        let on = ["0.1", "0.2", "0.3", "0.000000000000000001"];
        let p = |x: [&str; 3]| x.map(r);
        let coplanar = [
            p([on[0], on[0], on[0]]),
            p([on[1], on[0], on[0]]),
            p([on[0], on[1], on[0]]),
            p([on[2], on[2], on[0]]),
        ];
        let mut off = coplanar.clone();
        off[3][2] = r("0.100000000000000001");
        for q in [&coplanar, &off] {
            let v = q.clone().map(|x| x.map(Rational::from));
            let [a, b, c, d] = v.each_ref().map(|x| x.each_ref());
            assert_eq!(lattice_orient3d([a, b, c, d]), Some(plain_orient3d(q)));
            assert_eq!(fraction_free_orient3d(a, b, c, d), plain_orient3d(q));
        }
        assert_eq!(plain_orient3d(&off), Ordering::Greater);
        let big = |k: u32| sized(7, 3, 40 + k) - sized(5, 2, 30 + k);
        let q = [0, 1, 2, 3].map(|i| [0, 1, 2].map(|k| big(3 * i + k)));
        let v = q.clone().map(|x| x.map(Rational::from));
        let [a, b, c, d] = v.each_ref().map(|x| x.each_ref());
        assert_eq!(lattice_orient3d([a, b, c, d]), None);
        assert_eq!(fraction_free_orient3d(a, b, c, d), plain_orient3d(&q));
    }
}
