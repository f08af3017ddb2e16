//! The default exact backend: `num-rational`'s big rationals.

use super::{exact_orient, filtered_orient, Literal, Num, NumError};
use num_bigint::BigInt;
use num_traits::{Signed, ToPrimitive, Zero};
use std::cmp::Ordering;

/// Exact rational coordinates (the default backend).
pub type Rational = num_rational::BigRational;

/// The big integer of a signed string of decimal digits (checked by [`Literal::parse`]).
fn digits(s: &str) -> BigInt {
    BigInt::parse_bytes(s.as_bytes(), 10).unwrap_or_default()
}

/// `v` within 3 ulps (numerator and denominator rounded, then divided: cheaper than the
/// correctly rounded `to_f64`); NaN or infinite when out of range, which the filter rejects.
fn approx(v: &Rational) -> f64 {
    let n = ToPrimitive::to_f64(v.numer()).unwrap_or(f64::NAN);
    let d = ToPrimitive::to_f64(v.denom()).unwrap_or(f64::NAN);
    n / d
}

impl Num for Rational {
    type Ctx = ();
    const EXACT: bool = true;

    fn from_i64(v: i64) -> Self {
        Rational::from_integer(BigInt::from(v))
    }

    fn from_f64(v: f64) -> Result<Self, NumError> {
        Rational::from_float(v).ok_or(NumError::NotFinite(v))
    }

    fn from_literal(lit: &Literal) -> Self {
        let (num, den) = lit.fraction();
        Rational::new(digits(&num), digits(&den))
    }

    fn to_f64(&self) -> f64 {
        ToPrimitive::to_f64(self).unwrap_or(f64::NAN)
    }

    fn sign(&self) -> Ordering {
        if self.is_zero() {
            Ordering::Equal
        } else if self.is_positive() {
            Ordering::Greater
        } else {
            Ordering::Less
        }
    }

    fn orient2d(a: [&Self; 2], b: [&Self; 2], c: [&Self; 2], _ctx: &()) -> Ordering {
        let f = |p: [&Self; 2]| [approx(p[0]), approx(p[1])];
        filtered_orient(f(a), f(b), f(c)).unwrap_or_else(|| exact_orient(a, b, c))
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
}
