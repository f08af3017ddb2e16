//! The default exact backend: `num-rational`'s big rationals, compared through a
//! floating-point filter.

use super::{
    exact_orient, exact_orient3d, filtered_orient, filtered_orient3d, Literal, Num, NumError,
};
use num_bigint::BigInt;
use num_integer::Integer;
use num_rational::BigRational;
use num_traits::{Signed, ToPrimitive, Zero};
use std::cmp::Ordering;
use std::fmt;
use std::ops::{Add, Div, Mul, Neg, Sub};

/// Exact rational coordinates (the default backend): a `num-rational` big rational, always in
/// lowest terms with a positive denominator. Its order is decided from `f64` approximations
/// when they are far enough apart, exactly (by cross-multiplying) otherwise; `num-rational`'s
/// own order expands continued fractions, and dominated exact-mode profiles.
#[derive(Clone, PartialEq, Eq, Hash, Default)]
pub struct Rational(BigRational);

impl Rational {
    /// `numer / denom` in lowest terms (panics if `denom` is zero, like `num-rational`).
    pub fn new(numer: BigInt, denom: BigInt) -> Rational {
        Rational(BigRational::new(numer, denom))
    }

    /// The integer `n`.
    pub fn from_integer(n: BigInt) -> Rational {
        Rational(BigRational::from_integer(n))
    }

    /// The exact value of a finite `f64` (`None` for NaN and infinities).
    pub fn from_float(v: f64) -> Option<Rational> {
        BigRational::from_float(v).map(Rational)
    }

    /// The numerator (lowest terms; carries the sign).
    pub fn numer(&self) -> &BigInt {
        self.0.numer()
    }

    /// The denominator (lowest terms; positive).
    pub fn denom(&self) -> &BigInt {
        self.0.denom()
    }
}

impl From<BigRational> for Rational {
    fn from(v: BigRational) -> Rational {
        Rational(v)
    }
}

impl fmt::Display for Rational {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        fmt::Display::fmt(&self.0, f)
    }
}

impl fmt::Debug for Rational {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        fmt::Display::fmt(&self.0, f)
    }
}

impl Ord for Rational {
    fn cmp(&self, other: &Self) -> Ordering {
        if self.denom() == other.denom() {
            return self.numer().cmp(other.numer());
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
        (self.numer() * other.denom()).cmp(&(other.numer() * self.denom()))
    }
}

impl PartialOrd for Rational {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

/// The arithmetic operators, by value, from `num-rational`'s.
macro_rules! binary_op {
    ($($tr:ident $m:ident),*) => {$(
        impl $tr for Rational {
            type Output = Rational;
            fn $m(self, o: Rational) -> Rational {
                Rational(self.0.$m(o.0))
            }
        }
    )*};
}
binary_op!(Add add, Sub sub, Mul mul, Div div);

impl std::iter::Sum for Rational {
    fn sum<I: Iterator<Item = Rational>>(iter: I) -> Rational {
        Rational(iter.map(|r| r.0).sum())
    }
}

impl Neg for Rational {
    type Output = Rational;
    fn neg(self) -> Rational {
        Rational(-self.0)
    }
}

/// The big integer of a signed string of decimal digits (checked by [`Literal::parse`]).
fn digits(s: &str) -> BigInt {
    BigInt::parse_bytes(s.as_bytes(), 10).unwrap_or_default()
}

/// `v` within 3 ulps (numerator and denominator rounded, then divided: cheaper than the
/// correctly rounded `to_f64`); NaN when the numerator or the denominator is out of `f64`'s
/// range, which the filters reject. (A finite numerator over an overflowing denominator would
/// read as 0 and decide orders wrongly: found by fuzzing, pinned in tests/fuzz_regressions.rs.)
fn approx(v: &Rational) -> f64 {
    let n = ToPrimitive::to_f64(v.numer()).unwrap_or(f64::NAN);
    let d = ToPrimitive::to_f64(v.denom()).unwrap_or(f64::NAN);
    if n.is_finite() && d.is_finite() {
        n / d
    } else {
        f64::NAN
    }
}

impl Num for Rational {
    type Ctx = ();
    const EXACT: bool = true;

    fn from_i64(v: i64) -> Self {
        Rational::from_integer(BigInt::from(v))
    }

    fn half(&self) -> Self {
        // Lowest terms without a gcd: halve an even numerator, else double the denominator.
        let (n, d) = (self.numer(), self.denom());
        Rational(if n.is_even() {
            BigRational::new_raw(n / 2, d.clone())
        } else {
            BigRational::new_raw(n.clone(), d * 2)
        })
    }

    fn from_f64(v: f64) -> Result<Self, NumError> {
        Rational::from_float(v).ok_or(NumError::NotFinite(v))
    }

    fn from_literal(lit: &Literal) -> Self {
        let (num, den) = lit.fraction();
        Rational::new(digits(&num), digits(&den))
    }

    fn to_f64(&self) -> f64 {
        ToPrimitive::to_f64(&self.0).unwrap_or(f64::NAN)
    }

    fn sign(&self) -> Ordering {
        if self.0.is_zero() {
            Ordering::Equal
        } else if self.0.is_positive() {
            Ordering::Greater
        } else {
            Ordering::Less
        }
    }

    fn orient2d(a: [&Self; 2], b: [&Self; 2], c: [&Self; 2], _ctx: &()) -> Ordering {
        let f = |p: [&Self; 2]| [approx(p[0]), approx(p[1])];
        filtered_orient(f(a), f(b), f(c)).unwrap_or_else(|| exact_orient(a, b, c))
    }

    fn orient3d(a: [&Self; 3], b: [&Self; 3], c: [&Self; 3], d: [&Self; 3], _ctx: &()) -> Ordering {
        let f = |p: [&Self; 3]| p.map(approx);
        filtered_orient3d(f(a), f(b), f(c), f(d)).unwrap_or_else(|| exact_orient3d(a, b, c, d))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

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

    #[test]
    fn from_f64_is_lossless() {
        let x = Rational::from_f64(0.1).unwrap();
        assert_ne!(x, Rational::parse("0.1").unwrap());
        assert_eq!(Num::to_f64(&x), 0.1);
        assert!(Rational::from_f64(f64::NAN).is_err());
    }

    proptest::proptest! {
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
                let (a, b) = (Rational(x.clone()), Rational(y.clone()));
                proptest::prop_assert_eq!(a.cmp(&b), x.cmp(&y));
                proptest::prop_assert_eq!(b.cmp(&a), y.cmp(&x));
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
}
