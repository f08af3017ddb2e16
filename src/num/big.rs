//! Big rationals kept in lowest terms with the fewest and smallest gcds: Knuth's
//! cross-cancellation for sums, products and quotients (TAOCP vol. 2, §4.5.1), and Lehmer's gcd
//! from `dashu-int` (num-bigint's binary gcd is quadratic with a large constant, and reducing
//! big fractions with it dominated exact-mode profiles, 2D and 3D).

use num_bigint::{BigInt, BigUint, Sign};
use num_rational::BigRational;
use num_traits::{One, Signed, Zero};

/// gcd(|a|, |b|): in `u128` when both fit ([`gcd_u128`], no allocation), else by Lehmer's
/// algorithm (`dashu-int`), the operands handed over as machine words.
pub(super) fn gcd(a: &BigInt, b: &BigInt) -> BigInt {
    use num_traits::ToPrimitive;
    let (a, b) = (a.magnitude(), b.magnitude());
    if let (Some(x), Some(y)) = (a.to_u128(), b.to_u128()) {
        return BigInt::from(gcd_u128(x, y));
    }
    // gcd(2^k, m) = 2^min(k, tz(m)): the denominators of dyadic values (what f64 input reads
    // as) are powers of two, and their sums and products stay dyadic.
    if let (Some(s), Some(t)) = (a.trailing_zeros(), b.trailing_zeros()) {
        if a.bits() == s + 1 || b.bits() == t + 1 {
            return BigInt::one() << s.min(t);
        }
    }
    let g = dashu_int::ops::Gcd::gcd(&to_dashu(a), &to_dashu(b));
    BigInt::from_biguint(Sign::Plus, from_dashu(&g))
}

/// gcd(a, b) of machine integers, by the `gcd` crate's binary algorithm, on `u64` where both
/// fit.
pub(crate) fn gcd_u128(a: u128, b: u128) -> u128 {
    match (u64::try_from(a), u64::try_from(b)) {
        (Ok(x), Ok(y)) => u128::from(gcd::binary_u64(x, y)),
        _ => gcd::binary_u128(a, b),
    }
}

/// `x` as a `dashu-int` number, word by word (64-bit targets, where dashu's word is `u64`).
#[cfg(target_pointer_width = "64")]
fn to_dashu(x: &BigUint) -> dashu_int::UBig {
    let words: Vec<dashu_int::Word> = x.iter_u64_digits().collect();
    dashu_int::UBig::from_words(&words)
}

/// `x` as a `dashu-int` number, through its bytes.
#[cfg(not(target_pointer_width = "64"))]
fn to_dashu(x: &BigUint) -> dashu_int::UBig {
    dashu_int::UBig::from_le_bytes(&x.to_bytes_le())
}

/// A `dashu-int` number as a `num-bigint` one, word by word (64-bit targets).
#[cfg(target_pointer_width = "64")]
fn from_dashu(x: &dashu_int::UBig) -> BigUint {
    from_words(x.as_words())
}

/// The number of the 64-bit `words`, least significant first (up to eight words through a
/// buffer on the stack: one allocation, the number's own).
pub(crate) fn from_words(words: &[u64]) -> BigUint {
    let halves = words.iter().flat_map(|&w| [w as u32, (w >> 32) as u32]);
    if words.len() <= 8 {
        let mut buffer = [0u32; 16];
        for (slot, half) in buffer.iter_mut().zip(halves) {
            *slot = half;
        }
        BigUint::from_slice(&buffer[..2 * words.len()])
    } else {
        BigUint::new(halves.collect())
    }
}

/// A `dashu-int` number as a `num-bigint` one, through its bytes.
#[cfg(not(target_pointer_width = "64"))]
fn from_dashu(x: &dashu_int::UBig) -> BigUint {
    BigUint::from_bytes_le(&x.to_le_bytes())
}

/// `x / g` for a divisor `g` of `x`, skipping the division by one.
pub(super) fn exact_div(x: &BigInt, g: &BigInt) -> BigInt {
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

#[cfg(test)]
mod tests {
    use super::*;
    use num_integer::Integer;

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(yinset_testkit::cases(256)))]
        /// `gcd` equals num-integer's gcd on big operands of every shape its paths take: a power
        /// of two against anything (the dyadic path), two values with common factors of two and
        /// odd parts (Lehmer's), and zeros.
        #[test]
        fn gcd_is_the_gcd(
            odd in proptest::collection::vec(proptest::num::u64::ANY, 1..5),
            other in proptest::collection::vec(proptest::num::u64::ANY, 0..5),
            shifts in (0u32..300, 0u32..300),
            power in proptest::bool::ANY,
            negative in proptest::bool::ANY,
        ) {
            let number = |words: &[u64]| {
                let halves = words.iter().flat_map(|&w| [w as u32, (w >> 32) as u32]);
                BigInt::from_biguint(Sign::Plus, BigUint::new(halves.collect()))
            };
            let a = if power { BigInt::one() } else { number(&odd) } << shifts.0;
            let b = number(&other) << shifts.1;
            let b = if negative { -b } else { b };
            proptest::prop_assert_eq!(gcd(&a, &b), a.gcd(&b));
            proptest::prop_assert_eq!(gcd(&b, &a), a.gcd(&b));
        }

        /// `gcd_u128` equals num-integer's gcd on both of its paths (both operands below 2⁶⁴,
        /// or either above), with common factors, powers of two and zeros.
        #[test]
        fn gcd_u128_is_the_gcd(
            x in proptest::num::u128::ANY,
            y in proptest::num::u128::ANY,
            common in 0u128..1000,
            widths in (0u32..=128, 0u32..=128),
        ) {
            let narrow = |v: u128, bits: u32| v.checked_shr(128 - bits).unwrap_or(0);
            let (a, b) = (narrow(x, widths.0), narrow(y, widths.1));
            let (a, b) = (a.saturating_mul(common), b.saturating_mul(common));
            proptest::prop_assert_eq!(gcd_u128(a, b), a.gcd(&b));
            proptest::prop_assert_eq!(gcd_u128(b, a), a.gcd(&b));
        }
    }
}
