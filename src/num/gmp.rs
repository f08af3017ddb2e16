//! The GMP exact backend (feature `gmp`): `rug::Rational` on the system libgmp.

use super::{
    exact_orient, exact_orient3d, filtered_orient, filtered_orient3d, Literal, Num, NumError,
};
use rug::{Integer, Rational};
use std::cmp::Ordering;
use std::fmt;
use std::hash::{Hash, Hasher};
use std::ops::{Add, Div, Mul, Neg, Sub};

/// An exact rational on GMP.
#[derive(Clone, Debug, Default, PartialEq, Eq, PartialOrd, Ord)]
pub struct GmpRational(pub Rational);

impl Hash for GmpRational {
    fn hash<H: Hasher>(&self, state: &mut H) {
        self.0.hash(state)
    }
}

impl fmt::Display for GmpRational {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}", self.0)
    }
}

macro_rules! gmp_binop {
    ($tr:ident, $m:ident, $op:tt) => {
        impl $tr for GmpRational {
            type Output = GmpRational;
            fn $m(self, o: GmpRational) -> GmpRational {
                GmpRational(self.0 $op o.0)
            }
        }
    };
}
gmp_binop!(Add, add, +);
gmp_binop!(Sub, sub, -);
gmp_binop!(Mul, mul, *);
gmp_binop!(Div, div, /);

impl Neg for GmpRational {
    type Output = GmpRational;
    fn neg(self) -> GmpRational {
        GmpRational(-self.0)
    }
}

impl Num for GmpRational {
    type Ctx = ();
    const EXACT: bool = true;

    fn nearest(r: &super::Rational) -> Self {
        let parse = |i: num_bigint::BigInt| {
            Integer::from_str_radix(&i.to_str_radix(16), 16).expect("a BigInt's hex digits")
        };
        GmpRational(Rational::from((parse(r.numer()), parse(r.denom()))))
    }

    fn from_i64(v: i64) -> Self {
        GmpRational(Rational::from(v))
    }

    fn from_f64(v: f64) -> Result<Self, NumError> {
        Rational::from_f64(v)
            .map(GmpRational)
            .ok_or(NumError::NotFinite(v))
    }

    fn from_literal(lit: &Literal) -> Self {
        let (num, den) = lit.fraction();
        let parse = |s: &str| Integer::from_str_radix(s, 10).unwrap_or_default();
        GmpRational(Rational::from((parse(&num), parse(&den))))
    }

    fn to_f64(&self) -> f64 {
        self.0.to_f64()
    }

    fn fraction(&self) -> (num_bigint::BigInt, num_bigint::BigInt) {
        let big = |i: &Integer| {
            let magnitude =
                num_bigint::BigUint::from_bytes_le(&i.to_digits::<u8>(rug::integer::Order::Lsf));
            let sign = match i.cmp0() {
                Ordering::Less => num_bigint::Sign::Minus,
                _ => num_bigint::Sign::Plus,
            };
            num_bigint::BigInt::from_biguint(sign, magnitude)
        };
        (big(self.0.numer()), big(self.0.denom()))
    }

    fn sign(&self) -> Ordering {
        self.0.cmp0()
    }

    fn orient2d(a: [&Self; 2], b: [&Self; 2], c: [&Self; 2], _ctx: &()) -> Ordering {
        let f = |p: [&Self; 2]| [p[0].0.to_f64(), p[1].0.to_f64()];
        filtered_orient(f(a), f(b), f(c)).unwrap_or_else(|| exact_orient(a, b, c))
    }

    fn orient3d(a: [&Self; 3], b: [&Self; 3], c: [&Self; 3], d: [&Self; 3], _ctx: &()) -> Ordering {
        let f = |p: [&Self; 3]| p.map(|v| v.0.to_f64());
        filtered_orient3d(f(a), f(b), f(c), f(d)).unwrap_or_else(|| exact_orient3d(a, b, c, d))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn parses_without_rounding() {
        let x = GmpRational::parse("4.5040114e+00").unwrap();
        assert_eq!(x.0, Rational::from((45040114, 10_000_000)));
        assert_eq!(GmpRational::parse("1/3").unwrap().0, Rational::from((1, 3)));
    }

    /// Negation, the nearest `f64` and the orientation on values worked by hand.
    #[test]
    fn arithmetic_by_hand() {
        let q = |n: i64, d: i64| GmpRational(Rational::from((n, d)));
        assert_eq!(-q(1, 3), q(-1, 3));
        assert_eq!(-q(-5, 2), q(5, 2));
        assert_eq!(q(1, 4).to_f64(), 0.25);
        assert_eq!(q(-3, 2).to_f64(), -1.5);
        let (o, x, y) = ([q(0, 1), q(0, 1)], [q(1, 1), q(0, 1)], [q(0, 1), q(1, 1)]);
        // (1, 0) × (0, 1) = 1: y lies left of o → x, and x right of o → y.
        assert_eq!(
            GmpRational::orient2d(o.each_ref(), x.each_ref(), y.each_ref(), &()),
            Ordering::Greater
        );
        assert_eq!(
            GmpRational::orient2d(o.each_ref(), y.each_ref(), x.each_ref(), &()),
            Ordering::Less
        );
    }

    /// The fraction in lowest terms, sign on the numerator, beyond 64 bits.
    #[test]
    fn fraction_is_the_exact_value() {
        let big = |s: &str| s.parse::<num_bigint::BigInt>().unwrap();
        let x = GmpRational::parse("-123456789012345678901234567890/4").unwrap();
        assert_eq!(
            x.fraction(),
            (big("-61728394506172839450617283945"), big("2"))
        );
        assert_eq!(
            GmpRational::parse("0").unwrap().fraction(),
            (big("0"), big("1"))
        );
    }
}
