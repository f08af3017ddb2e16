//! Number text for the writers: exact decimals wherever the expansion terminates.

use crate::num::{Literal, Num};
use num_bigint::BigInt;
use num_integer::Integer;
use num_traits::{One, Signed, Zero};

/// Significant digits of a non-terminating number written as a rounded decimal (more than
/// `f64` holds).
const SIGNIFICANT: i64 = 17;

/// `n` exactly: a decimal when its expansion terminates, its `Display` (`p/q`) otherwise.
pub(crate) fn exact_text<N: Num>(n: &N) -> String {
    decimal_text(n, |_, _| n.to_string())
}

/// `n` as a JSON number: exact when its decimal expansion terminates, otherwise rounded (half
/// away from zero) to [`SIGNIFICANT`] significant digits.
pub(crate) fn json_text<N: Num>(n: &N) -> String {
    decimal_text(n, rounded)
}

/// `n` as an exact decimal, or `inexact(p, q)` of its reduced fraction when none exists.
fn decimal_text<N: Num>(n: &N, inexact: impl FnOnce(&BigInt, &BigInt) -> String) -> String {
    let Some((p, q)) = fraction(n) else {
        return n.to_string();
    };
    match terminating_scale(&q) {
        Some(k) => scaled(&(p * ten_pow(k) / q), k),
        None => inexact(&p, &q),
    }
}

/// `n` as a reduced fraction `p/q` with `q > 0`, read back from its `Display` text (a decimal
/// or `p/q` in every backend).
fn fraction<N: Num>(n: &N) -> Option<(BigInt, BigInt)> {
    let lit = Literal::parse(&n.to_string()).ok()?;
    let mut p: BigInt = lit.digits.parse().ok()?;
    let mut q: BigInt = lit.den.parse().ok()?;
    let scale = ten_pow(lit.exp10.unsigned_abs());
    if lit.exp10 >= 0 {
        p *= scale;
    } else {
        q *= scale;
    }
    if lit.negative {
        p = -p;
    }
    let g = p.gcd(&q);
    Some((p / &g, q / g))
}

/// The least `k` with `q | 10^k`, if any (i.e. if `q` has no prime factor but 2 and 5).
fn terminating_scale(q: &BigInt) -> Option<u64> {
    let twos = q.trailing_zeros().unwrap_or(0);
    let mut rest = q >> twos;
    let five = BigInt::from(5);
    let mut fives = 0;
    while !rest.is_zero() && (&rest % &five).is_zero() {
        rest /= &five;
        fives += 1;
    }
    rest.is_one().then_some(twos.max(fives))
}

/// `p/q` rounded half away from zero to [`SIGNIFICANT`] significant digits.
fn rounded(p: &BigInt, q: &BigInt) -> String {
    let magnitude = p.abs().to_string().len() as i64 - q.to_string().len() as i64;
    let k = (SIGNIFICANT - magnitude).max(0).unsigned_abs();
    let m = (p.abs() * ten_pow(k) * 2u8 + q) / (q * 2u8);
    scaled(&if p.is_negative() { -m } else { m }, k)
}

/// The decimal text of `m / 10^k`, without trailing zeros after the point.
fn scaled(m: &BigInt, k: u64) -> String {
    let sign = if m.is_negative() { "-" } else { "" };
    let digits = m.abs().to_string();
    let k = k as usize;
    let padded = format!("{digits:0>width$}", width = k + 1);
    let (int, frac) = padded.split_at(padded.len() - k);
    let frac = frac.trim_end_matches('0');
    if frac.is_empty() {
        format!("{sign}{int}")
    } else {
        format!("{sign}{int}.{frac}")
    }
}

/// `10^k`.
fn ten_pow(k: u64) -> BigInt {
    num_traits::pow(BigInt::from(10), k as usize)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::num::{Float, Rational};

    fn q(s: &str) -> Rational {
        Rational::parse(s).unwrap()
    }

    #[test]
    fn terminating_rationals_are_exact_decimals() {
        for (s, want) in [("1/8", "0.125"), ("-5/2", "-2.5"), ("7", "7"), ("0", "0")] {
            assert_eq!(exact_text(&q(s)), want);
            assert_eq!(json_text(&q(s)), want);
        }
        assert_eq!(exact_text(&q("-1/1024")), "-0.0009765625");
        assert_eq!(exact_text(&q("1e30")), format!("1{}", "0".repeat(30)));
    }

    #[test]
    fn other_rationals_stay_fractions_or_round() {
        assert_eq!(exact_text(&q("-1/3")), "-1/3");
        assert_eq!(json_text(&q("1/3")), "0.33333333333333333");
        assert_eq!(json_text(&q("-2/3")), "-0.66666666666666667");
        assert_eq!(json_text(&q("100/3")), "33.333333333333333");
        assert_eq!(json_text(&q("1e20/3")), "33333333333333333333");
    }

    #[test]
    fn floats_print_their_shortest_decimal() {
        assert_eq!(json_text(&Float::parse("0.1").unwrap()), "0.1");
        assert_eq!(exact_text(&Float::parse("-2.5e-3").unwrap()), "-0.0025");
    }
}
