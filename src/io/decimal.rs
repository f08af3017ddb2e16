//! Number text for the writers of WKT, GeoJSON and OBJ: one rule for all of them
//! ([`NumberStyle`]; the nearest `f64`s of the default style are `super::nearest`'s).

use crate::num::Num;
use num_bigint::BigInt;
use num_traits::{One, Signed, Zero};

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
    decimal_text(n, || {
        if fractions {
            Ok(n.to_string())
        } else {
            Err(format!(
                "the coordinate {n} has no finite decimal expansion, which JSON numbers \
                 need: write decimals (the default) or another format"
            ))
        }
    })
}

/// `n` exactly: a decimal when its expansion terminates, its `Display` (`p/q`) otherwise.
pub(crate) fn exact_text<N: Num>(n: &N) -> String {
    let Ok(text) = decimal_text(n, || Ok::<_, std::convert::Infallible>(n.to_string()));
    text
}

/// `n` as an exact decimal, or `inexact()` when its expansion does not terminate. A float
/// backend's `Display` is already its shortest decimal; a fraction of machine integers is
/// scaled in `i128` where that holds it.
fn decimal_text<N: Num, E>(
    n: &N,
    inexact: impl FnOnce() -> Result<String, E>,
) -> Result<String, E> {
    if !N::EXACT {
        return Ok(n.to_string());
    }
    if let Some((p, q)) = n.small_fraction() {
        match small_decimal(p, q) {
            Some(Some(text)) => return Ok(text),
            Some(None) => return inexact(),
            None => {}
        }
    }
    let (p, q) = n.fraction();
    match terminating_scale(&q) {
        Some(k) => Ok(scaled(p * ten_pow(k) / q, k)),
        None => inexact(),
    }
}

/// The decimal text of the reduced fraction `p/q` (`q > 0`): `Some(None)` if its expansion
/// does not terminate, `None` if `i128` cannot hold the scaled numerator.
fn small_decimal(p: i64, q: i64) -> Option<Option<String>> {
    let twos = q.trailing_zeros();
    let mut rest = q >> twos;
    let mut fives = 0;
    while rest % 5 == 0 {
        rest /= 5;
        fives += 1;
    }
    if rest != 1 {
        return Some(None);
    }
    // p/q = p·2^(k−twos)·5^(k−fives) / 10^k.
    let k = twos.max(fives);
    let factor = 2i128
        .checked_pow(k - twos)?
        .checked_mul(5i128.checked_pow(k - fives)?)?;
    Some(Some(scaled(
        i128::from(p).checked_mul(factor)?,
        u64::from(k),
    )))
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

/// The decimal text of `m / 10^k` (an integer type's `m`), without trailing zeros after the
/// point.
fn scaled<I: Signed + std::fmt::Display>(m: I, k: u64) -> String {
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

    proptest::proptest! {
        /// Fractions of machine integers (denominators 2^a·5^b·r, up to 2⁶²) read back from
        /// their exact text as themselves: a plain decimal, without an exponent or trailing
        /// zeros, where the expansion terminates (r = 1), `p/q` otherwise; on the `i128` path
        /// and past it (the denominator 2⁶¹ needs the factor 5⁶¹, which overflows it).
        #[test]
        fn small_fractions_read_back_from_their_text(
            p in -(1i64 << 61)..(1i64 << 61), a in 0u32..62, b in 0u32..27, r in 0usize..3,
        ) {
            let q = (BigInt::one() << a) * num_traits::pow(BigInt::from(5), b as usize)
                * BigInt::from([1, 3, 7][r]);
            let x = Rational::new(BigInt::from(p), q.min(BigInt::from(1i64 << 62)));
            let text = exact_text(&x);
            proptest::prop_assert_eq!(Rational::parse(&text).unwrap(), x.clone());
            let (_, d) = x.fraction();
            if terminating_scale(&d).is_some() {
                proptest::prop_assert!(!text.contains(['/', 'e']), "{}", text);
                proptest::prop_assert!(!text.contains('.') || !text.ends_with('0'), "{}", text);
            } else {
                proptest::prop_assert!(text.contains('/'), "{}", text);
            }
        }
    }

    #[test]
    fn floats_print_their_shortest_decimal() {
        let f = Float::parse("0.1").unwrap();
        assert_eq!(exact_coordinate_text(&f, false).unwrap(), "0.1");
        assert_eq!(exact_text(&Float::parse("-2.5e-3").unwrap()), "-0.0025");
    }
}
