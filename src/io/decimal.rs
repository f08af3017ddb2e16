//! Number text for the writers of WKT, GeoJSON and OBJ: one rule for all of them
//! ([`NumberStyle`]; the nearest `f64`s of the default style are `super::nearest`'s).

use crate::num::Num;
use num_bigint::{BigInt, BigUint};
use num_traits::{One, Signed, Zero};
use std::fmt::Write;

/// How the OGC writers (WKT, GeoJSON) spell coordinates: the same rule for both.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum NumberStyle {
    /// The shortest decimal that reads back as the coordinate's nearest `f64` (what OGC readers
    /// such as GEOS, shapely or PostGIS hold); the default.
    #[default]
    Decimal,
    /// The coordinate exactly: a decimal where its expansion terminates, else the fraction
    /// `p/q` — which WKT writes (a yinset extension other readers reject) and GeoJSON refuses,
    /// since JSON numbers are decimals.
    Exact,
}

/// The text of coordinate `n` exactly ([`NumberStyle::Exact`]): a decimal where its expansion
/// terminates, else the fraction `p/q` if `fractions`, or why it cannot be written.
pub(crate) fn exact_coordinate_text<N: Num>(n: &N, fractions: bool) -> Result<String, String> {
    let mut text = String::new();
    if push_decimal(&mut text, n) {
        Ok(text)
    } else if fractions {
        Ok(n.to_string())
    } else {
        Err(format!(
            "the coordinate {n} has no finite decimal expansion, which JSON numbers \
             need: write decimals (the default) or another format"
        ))
    }
}

/// `n` exactly: a decimal when its expansion terminates, its `Display` (`p/q`) otherwise.
pub(crate) fn exact_text<N: Num>(n: &N) -> String {
    let mut text = String::new();
    push_exact(&mut text, n);
    text
}

/// Append [`exact_text`] of `n` to `out`.
pub(crate) fn push_exact<N: Num>(out: &mut String, n: &N) {
    if !push_decimal(out, n) {
        let _ = write!(out, "{n}");
    }
}

/// Append `n` as an exact decimal to `out` and return true, or return false (`out` as it was)
/// when its expansion does not terminate. A float backend's `Display` is already its shortest
/// decimal; a fraction of machine integers is scaled in `i128` where that holds it.
fn push_decimal<N: Num>(out: &mut String, n: &N) -> bool {
    if !N::EXACT {
        let _ = write!(out, "{n}");
        return true;
    }
    if let Some((p, q)) = n.small_fraction() {
        match small_decimal(p, q) {
            Some(Some((m, k))) => {
                // itoa spells a `u64` faster than a `u128`.
                let mut digits = itoa::Buffer::new();
                let digits = match u64::try_from(m.unsigned_abs()) {
                    Ok(small) => digits.format(small),
                    Err(_) => digits.format(m.unsigned_abs()),
                };
                push_scaled(out, m < 0, digits, k);
                return true;
            }
            Some(None) => return false,
            None => {}
        }
    }
    let (p, q) = n.fraction();
    let Some(k) = terminating_scale(&q) else {
        return false;
    };
    let m = p * ten_pow(k) / q;
    push_scaled(out, m.is_negative(), &m.magnitude().to_string(), k);
    true
}

/// The powers of five that an `i128` holds, `5^0` to `5^54`.
const POWERS_OF_FIVE: [i128; 55] = {
    let mut powers = [1; 55];
    let mut j = 1;
    while j < powers.len() {
        powers[j] = powers[j - 1] * 5;
        j += 1;
    }
    powers
};

/// The exponent `f` of the power of five `5^f` below `2^64` of each binary logarithm (rounded
/// down; they differ, as `5 > 4`), and 0 where none has it.
const FIVES_BY_LOG2: [u32; 64] = {
    let mut fives = [0; 64];
    let mut f = 0;
    while POWERS_OF_FIVE[f].ilog2() < 64 {
        fives[POWERS_OF_FIVE[f].ilog2() as usize] = f as u32;
        f += 1;
    }
    fives
};

/// The reduced fraction `p/q` (`q > 0`) as `(m, k)` with `p/q = m / 10^k`: `Some(None)` if its
/// expansion does not terminate, `None` if `i128` cannot hold `m`.
fn small_decimal(p: i64, q: i64) -> Option<Option<(i128, usize)>> {
    let twos = q.trailing_zeros();
    let rest = q >> twos;
    let fives = FIVES_BY_LOG2[rest.ilog2() as usize];
    if POWERS_OF_FIVE[fives as usize] != i128::from(rest) {
        return Some(None);
    }
    // p/q = p·2^(k−twos)·5^(k−fives) / 10^k, one of the two exponents 0.
    let k = twos.max(fives);
    let factor = POWERS_OF_FIVE.get((k - fives) as usize)? << (k - twos);
    Some(Some((i128::from(p).checked_mul(factor)?, k as usize)))
}

/// The least `k` with `q | 10^k`, if any (i.e. if `q > 0` has no prime factor but 2 and 5).
fn terminating_scale(q: &BigInt) -> Option<usize> {
    let twos = q.trailing_zeros().unwrap_or(0);
    let mut rest = q.magnitude() >> twos;
    // As 5^f ≥ 4^f, an odd part that is a power of five divides 5^(bits/2): one division
    // decides, before the fives are divided out one at a time.
    let five = BigUint::from(5u32);
    let bound = num_traits::pow(five.clone(), rest.bits() as usize / 2);
    if !(bound % &rest).is_zero() {
        return None;
    }
    let mut fives = 0;
    while !rest.is_one() {
        rest /= &five;
        fives += 1;
    }
    Some(twos.max(fives) as usize)
}

/// Append the decimal text of `±m / 10^k` to `out`, `digits` those of `m ≥ 0` and `negative`
/// its sign: no trailing zeros after the point, and no leading zeros but a lone `0` before it.
fn push_scaled(out: &mut String, negative: bool, digits: &str, k: usize) {
    if negative {
        out.push('-');
    }
    let (int, fraction) = digits.split_at(digits.len().saturating_sub(k));
    out.push_str(if int.is_empty() { "0" } else { int });
    let significant = fraction.trim_end_matches('0');
    if !significant.is_empty() {
        out.push('.');
        out.extend(std::iter::repeat_n('0', k - fraction.len()));
        out.push_str(significant);
    }
}

/// `10^k`.
fn ten_pow(k: usize) -> BigInt {
    num_traits::pow(BigInt::from(10), k)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::num::{Float, Rational};
    use proptest::test_runner::TestCaseError;

    fn q(s: &str) -> Rational {
        Rational::parse(s).unwrap()
    }

    /// The exact text, fractions allowed and not.
    fn texts(n: &Rational) -> [Result<String, String>; 2] {
        [
            exact_coordinate_text(n, true),
            exact_coordinate_text(n, false),
        ]
    }

    #[test]
    fn terminating_rationals_are_exact_decimals() {
        for (s, want) in [("1/8", "0.125"), ("-5/2", "-2.5"), ("7", "7"), ("0", "0")] {
            assert_eq!(exact_text(&q(s)), want);
            assert_eq!(texts(&q(s)), [0, 1].map(|_| Ok(want.to_string())));
        }
        assert_eq!(exact_text(&q("-1/1024")), "-0.0009765625");
        assert_eq!(exact_text(&q("1e30")), format!("1{}", "0".repeat(30)));
    }

    #[test]
    fn exact_style_writes_fractions_only_where_allowed() {
        assert_eq!(exact_text(&q("-1/3")), "-1/3");
        let [with, without] = texts(&q("-1/3"));
        assert_eq!(with.as_deref(), Ok("-1/3"));
        assert!(without.unwrap_err().contains("no finite decimal expansion"));
        assert_eq!(texts(&q("1e400"))[1].as_ref().unwrap().len(), 401);
    }

    /// True if the expansion of `x` terminates: its denominator has no prime factor but 2 and 5.
    fn terminates(x: &Rational) -> bool {
        let (_, mut d) = x.fraction();
        for f in [2, 5].map(BigInt::from) {
            while (&d % &f).is_zero() {
                d /= &f;
            }
        }
        d.is_one()
    }

    /// `text` reads back as `x`, and it is a plain decimal where the expansion of `x`
    /// terminates (no exponent, no leading zeros but a lone `0` before the point, no trailing
    /// zeros after it, no `-0`), `p/q` otherwise.
    fn check_exact_text(text: &str, x: &Rational) -> Result<(), TestCaseError> {
        proptest::prop_assert_eq!(&Rational::parse(text).unwrap(), x);
        if !terminates(x) {
            proptest::prop_assert!(text.contains('/'), "{}", text);
            return Ok(());
        }
        let magnitude = text.strip_prefix('-').unwrap_or(text);
        let negative = x.sign() == std::cmp::Ordering::Less;
        proptest::prop_assert_eq!(magnitude.len() < text.len(), negative, "{}", text);
        let (int, fraction) = magnitude.split_once('.').unwrap_or((magnitude, "1"));
        let digits = |s: &str| !s.is_empty() && s.bytes().all(|c| c.is_ascii_digit());
        proptest::prop_assert!(digits(int) && digits(fraction), "{}", text);
        proptest::prop_assert!(int == "0" || !int.starts_with('0'), "{}", text);
        proptest::prop_assert!(!fraction.ends_with('0'), "{}", text);
        Ok(())
    }

    proptest::proptest! {
        /// Fractions of machine integers (denominators 2^a·5^b·r, up to 2⁶²) read back from
        /// their exact text as themselves, in its shape; on the `i128` path and past it (the
        /// denominator 2⁶¹ needs the factor 5⁶¹, which overflows it).
        #[test]
        fn small_fractions_read_back_from_their_text(
            p in -(1i64 << 61)..(1i64 << 61), a in 0u32..62, b in 0u32..27, r in 0usize..3,
        ) {
            let q = (BigInt::one() << a) * num_traits::pow(BigInt::from(5), b as usize)
                * BigInt::from([1, 3, 7][r]);
            let x = Rational::new(BigInt::from(p), q.min(BigInt::from(1i64 << 62)));
            check_exact_text(&exact_text(&x), &x)?;
        }

        /// Fractions of big integers (numerators to 2²⁵⁶, denominators 2^a·5^b·r past 2⁴⁰⁰)
        /// read back as themselves from their exact text appended after other text.
        #[test]
        fn big_fractions_read_back_from_their_appended_text(
            p in proptest::num::i64::ANY, words in 0usize..4, a in 0u32..200, b in 0usize..90,
            r in 0usize..3, before in "[a-z ]{0,3}",
        ) {
            let p = BigInt::from(p) * num_traits::pow(BigInt::from(u64::MAX), words);
            let q = (BigInt::one() << a) * num_traits::pow(BigInt::from(5), b)
                * BigInt::from([1, 3, 7][r]);
            let x = Rational::new(p, q);
            let mut text = before.clone();
            push_exact(&mut text, &x);
            proptest::prop_assert!(text.starts_with(&before), "{}", text);
            check_exact_text(&text[before.len()..], &x)?;
        }
    }

    #[test]
    fn floats_print_their_shortest_decimal() {
        let f = Float::parse("0.1").unwrap();
        assert_eq!(exact_coordinate_text(&f, false).unwrap(), "0.1");
        assert_eq!(exact_text(&Float::parse("-2.5e-3").unwrap()), "-0.0025");
    }
}
