//! Big rationals kept in lowest terms with the fewest and smallest gcds: Knuth's
//! cross-cancellation for sums, products and quotients (TAOCP vol. 2, §4.5.1), and Lehmer's gcd
//! from `dashu-int` (num-bigint's binary gcd is quadratic with a large constant, and reducing
//! big fractions with it dominated exact-mode profiles, 2D and 3D).

use num_bigint::{BigInt, BigUint, Sign};
use num_rational::BigRational;
use num_traits::{One, Signed, Zero};

/// gcd(|a|, |b|) (Lehmer's algorithm, `dashu-int`).
fn gcd(a: &BigInt, b: &BigInt) -> BigInt {
    let to_dashu = |x: &BigInt| dashu_int::UBig::from_le_bytes(&x.magnitude().to_bytes_le());
    let g = dashu_int::ops::Gcd::gcd(&to_dashu(a), &to_dashu(b));
    BigInt::from_biguint(Sign::Plus, BigUint::from_bytes_le(&g.to_le_bytes()))
}

/// `x / g` for a divisor `g` of `x`, skipping the division by one.
fn exact_div(x: &BigInt, g: &BigInt) -> BigInt {
    if g.is_one() {
        x.clone()
    } else {
        x / g
    }
}

/// `n / d` in lowest terms with a positive denominator (panics if `d` is zero, like
/// `num-rational`).
pub(super) fn new(n: BigInt, d: BigInt) -> BigRational {
    assert!(!d.is_zero(), "denominator == 0");
    if n.is_zero() {
        return BigRational::zero();
    }
    let g = gcd(&n, &d);
    let (n, d) = (exact_div(&n, &g), exact_div(&d, &g));
    if d.is_negative() {
        BigRational::new_raw(-n, -d)
    } else {
        BigRational::new_raw(n, d)
    }
}

/// a/b + c/d in lowest terms: with g = gcd(b, d), the sum is t / (b/g · d) for
/// t = a·(d/g) + c·(b/g), and only gcd(t, g) remains to cancel (Knuth §4.5.1).
pub(super) fn add(x: &BigRational, y: &BigRational) -> BigRational {
    let (a, b, c, d) = (x.numer(), x.denom(), y.numer(), y.denom());
    let g = gcd(b, d);
    if g.is_one() {
        return BigRational::new_raw(a * d + c * b, b * d);
    }
    let (bg, dg) = (b / &g, d / &g);
    let t = a * &dg + c * &bg;
    if t.is_zero() {
        return BigRational::zero();
    }
    let h = gcd(&t, &g);
    BigRational::new_raw(exact_div(&t, &h), bg * exact_div(d, &h))
}

/// (a/b)·(c/d) in lowest terms: cancel gcd(a, d) and gcd(c, b) before multiplying.
pub(super) fn mul(x: &BigRational, y: &BigRational) -> BigRational {
    let (a, b, c, d) = (x.numer(), x.denom(), y.numer(), y.denom());
    if a.is_zero() || c.is_zero() {
        return BigRational::zero();
    }
    let (g, h) = (gcd(a, d), gcd(c, b));
    BigRational::new_raw(
        exact_div(a, &g) * exact_div(c, &h),
        exact_div(b, &h) * exact_div(d, &g),
    )
}

/// (a/b) / (c/d) = (a/b)·(d/c), the reciprocal's sign moved to its numerator (panics if
/// `y` is zero, like `num-rational`).
pub(super) fn div(x: &BigRational, y: &BigRational) -> BigRational {
    assert!(!y.is_zero(), "division by zero");
    let (c, d) = (y.numer(), y.denom());
    let reciprocal = if c.is_negative() {
        BigRational::new_raw(-d, -c)
    } else {
        BigRational::new_raw(d.clone(), c.clone())
    };
    mul(x, &reciprocal)
}
