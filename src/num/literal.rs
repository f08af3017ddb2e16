//! Number literals as written in input files: decimals with an optional exponent, and fractions.

use super::NumError;

/// Largest decimal exponent accepted, so that "1e999999999" cannot exhaust memory.
pub const MAX_EXPONENT: i64 = 4096;

/// An exactly parsed number literal: `±digits·10^exp10 / den`.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Literal {
    /// True for a leading minus sign.
    pub negative: bool,
    /// Decimal digits of the numerator's integer significand (no sign, no point).
    pub digits: String,
    /// Power of ten applied to `digits`.
    pub exp10: i64,
    /// Decimal digits of the denominator (for fractions `p/q`; "1" otherwise).
    pub den: String,
}

impl Literal {
    /// The value as a fraction of two decimal integer strings: the signed numerator and the
    /// positive denominator, with the power of ten written out (at most `MAX_EXPONENT` zeros).
    pub fn fraction(&self) -> (String, String) {
        let zeros = "0".repeat(self.exp10.unsigned_abs() as usize);
        let sign = if self.negative { "-" } else { "" };
        if self.exp10 >= 0 {
            (format!("{sign}{}{zeros}", self.digits), self.den.clone())
        } else {
            (
                format!("{sign}{}", self.digits),
                format!("{}{zeros}", self.den),
            )
        }
    }

    /// Parse "12", "-4.5040114e+00", ".5", "1/3", "-7/2" exactly.
    pub fn parse(text: &str) -> Result<Literal, NumError> {
        Parts::scan(text).map(|parts| parts.literal())
    }
}

/// A checked literal's text in borrowed pieces, `±(int frac)·10^exp10 / den`: what
/// [`Literal::parse`] reads before it allocates, so that values of machine integers are made
/// without allocating.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Parts<'a> {
    /// True for a leading minus sign.
    pub negative: bool,
    /// The significand's digits before the point (possibly empty or with leading zeros).
    pub int: &'a str,
    /// The significand's digits after the point.
    pub frac: &'a str,
    /// Power of ten applied to the digits `int frac` taken as one integer.
    pub exp10: i64,
    /// Digits of the denominator of a fraction `p/q`; `None` for a decimal.
    pub den: Option<&'a str>,
}

impl<'a> Parts<'a> {
    /// Check the syntax of "12", "-4.5040114e+00", ".5", "1/3", "-7/2" and split it.
    pub fn scan(text: &'a str) -> Result<Parts<'a>, NumError> {
        let s = text.trim();
        let err = || NumError::Syntax(text.to_string());
        if let Some((p, q)) = s.split_once('/') {
            let num = Parts::scan_decimal(p.trim(), text)?;
            let den = q.trim();
            if den.is_empty() || !den.bytes().all(|c| c.is_ascii_digit()) {
                return Err(err());
            }
            if den.bytes().all(|c| c == b'0') {
                return Err(NumError::ZeroDenominator(text.to_string()));
            }
            return Ok(Parts {
                den: Some(den),
                ..num
            });
        }
        Parts::scan_decimal(s, text)
    }

    /// The parts of an already parsed literal.
    pub fn of(lit: &'a Literal) -> Parts<'a> {
        Parts {
            negative: lit.negative,
            int: &lit.digits,
            frac: "",
            exp10: lit.exp10,
            den: (lit.den != "1").then_some(&lit.den),
        }
    }

    /// Check and split the decimal `s` (a trimmed piece of `text`, which errors name).
    fn scan_decimal(s: &'a str, text: &str) -> Result<Parts<'a>, NumError> {
        let err = || NumError::Syntax(text.to_string());
        let (negative, rest) = split_sign(s);
        let (int, rest) = split_digits(rest);
        let (frac, rest) = rest.strip_prefix('.').map_or(("", rest), split_digits);
        if int.is_empty() && frac.is_empty() {
            return Err(err());
        }
        let mut exp10: i64 = 0;
        if let Some(e) = rest.strip_prefix(['e', 'E']) {
            let (eneg, e) = split_sign(e);
            let (edigits, tail) = split_digits(e);
            if edigits.is_empty() || !tail.is_empty() {
                return Err(err());
            }
            let trimmed = edigits.trim_start_matches('0');
            if trimmed.len() > 6 {
                return Err(NumError::ExponentRange(text.to_string()));
            }
            let v: i64 = trimmed.parse().unwrap_or(0);
            exp10 = if eneg { -v } else { v };
        } else if !rest.is_empty() {
            return Err(err());
        }
        exp10 -= frac.len() as i64;
        if exp10.abs() > MAX_EXPONENT + frac.len() as i64 {
            return Err(NumError::ExponentRange(text.to_string()));
        }
        Ok(Parts {
            negative,
            int,
            frac,
            exp10,
            den: None,
        })
    }

    /// The owned literal, its digits without leading zeros.
    pub fn literal(&self) -> Literal {
        let digits = format!("{}{}", self.int, self.frac);
        let trimmed = digits.trim_start_matches('0');
        Literal {
            negative: self.negative,
            digits: if trimmed.is_empty() { "0" } else { trimmed }.to_string(),
            exp10: self.exp10,
            den: self.den.unwrap_or("1").to_string(),
        }
    }

    /// The significand `int frac` as an integer, if it fits in a `u64`.
    fn significand(&self) -> Option<u64> {
        integer(self.int.bytes().chain(self.frac.bytes()))
    }

    /// The decimal as `m / 10^k` with `m` and `10^k` in `u64`s (sign aside), where they fit.
    pub fn decimal(&self) -> Option<(u64, u32)> {
        let k = u32::try_from(self.exp10.checked_neg()?).ok()?;
        match self.den {
            None => Some((self.significand()?, k)).filter(|_| 10u64.checked_pow(k).is_some()),
            Some(_) => None,
        }
    }

    /// The value as a signed numerator and a positive denominator of `i128`s (not reduced),
    /// where the significand, the denominator and the power of ten fit.
    pub fn small_fraction(&self) -> Option<(i128, i128)> {
        let n = i128::from(self.significand()?);
        let d = i128::from(integer(self.den.unwrap_or("1").bytes())?);
        let ten = 10i128.checked_pow(u32::try_from(self.exp10.unsigned_abs()).ok()?)?;
        let (n, d) = match self.exp10 >= 0 {
            true => (n.checked_mul(ten)?, d),
            false => (n, d.checked_mul(ten)?),
        };
        Some((if self.negative { -n } else { n }, d))
    }
}

/// `s` without its leading sign, and whether that sign is a minus.
fn split_sign(s: &str) -> (bool, &str) {
    match s.as_bytes().first() {
        Some(b'-') => (true, &s[1..]),
        Some(b'+') => (false, &s[1..]),
        _ => (false, s),
    }
}

/// `s` split after its leading ASCII digits.
fn split_digits(s: &str) -> (&str, &str) {
    s.split_at(s.bytes().take_while(u8::is_ascii_digit).count())
}

/// The integer of the decimal digits `digits`, if they are digits and it fits in a `u64`.
fn integer(mut digits: impl Iterator<Item = u8>) -> Option<u64> {
    let digit = |c: u8| char::from(c).to_digit(10).map(u64::from);
    digits.try_fold(0u64, |v, c| v.checked_mul(10)?.checked_add(digit(c)?))
}

/// Decimal and fraction texts with their exact values, for the readers' property tests.
#[cfg(test)]
pub(crate) mod texts {
    use num_bigint::BigInt;
    use num_rational::BigRational;
    use proptest::prelude::*;

    /// Integers of every size, many just under or over the bounds of the machine-integer
    /// paths: 2⁶² (small rationals), 2⁶³, 2⁶⁴ and 10¹⁹ (the `u64` significand).
    fn integers() -> impl Strategy<Value = u128> {
        let bound = prop_oneof![
            Just(1u128 << 62),
            Just(1 << 63),
            Just(1 << 64),
            Just(10u128.pow(19))
        ];
        prop_oneof![
            0u128..1000,
            any::<u64>().prop_map(u128::from),
            any::<u128>(),
            (bound, -300i128..300).prop_map(|(b, d)| b.wrapping_add_signed(d)),
        ]
    }

    /// A literal's text (`[-+]` sign, leading zeros, a point anywhere or none, an exponent
    /// `e`/`E` with or without `+`, a denominator `/q` if `fractions`) and its exact value
    /// from big integers.
    pub(crate) fn literals(fractions: bool) -> impl Strategy<Value = (String, BigRational)> {
        let exponent = proptest::option::of((-40i64..40, "[eE]", any::<bool>()));
        let den = proptest::option::of(integers().prop_filter("a denominator", |&q| q > 0));
        let den = den.prop_map(move |q| q.filter(|_| fractions));
        (
            "[-+]?",
            0usize..3,
            integers(),
            proptest::option::of(any::<prop::sample::Index>()),
            exponent,
            den,
        )
            .prop_map(|(sign, zeros, m, point, exponent, den)| {
                let digits = format!("{}{m}", "0".repeat(zeros));
                let p = point.map_or(digits.len(), |i| i.index(digits.len() + 1));
                let (int, frac) = digits.split_at(p);
                let mut text = format!(
                    "{sign}{int}{}",
                    point.map_or(String::new(), |_| format!(".{frac}"))
                );
                let mut exp10 = -(frac.len() as i64);
                if let Some((e, mark, plus)) = &exponent {
                    let plus = if *plus && *e >= 0 { "+" } else { "" };
                    text += &format!("{mark}{plus}{e}");
                    exp10 += e;
                }
                let q = den.unwrap_or(1);
                if let Some(q) = den {
                    text += &format!("/{q}");
                }
                let ten = |k: i64| num_traits::pow(BigInt::from(10), k.unsigned_abs() as usize);
                let (mut n, mut d) = (BigInt::from(m), BigInt::from(q));
                if exp10 >= 0 {
                    n *= ten(exp10)
                } else {
                    d *= ten(exp10)
                }
                if sign == "-" {
                    n = -n
                }
                (text, BigRational::new(n, d))
            })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn decimal_with_exponent() {
        let l = Literal::parse("4.5040114e+00").unwrap();
        assert_eq!(
            (l.negative, l.digits.as_str(), l.exp10),
            (false, "45040114", -7)
        );
    }

    #[test]
    fn fraction_and_sign() {
        let l = Literal::parse("-7/2").unwrap();
        assert_eq!(
            (l.negative, l.digits.as_str(), l.den.as_str()),
            (true, "7", "2")
        );
    }

    /// An exponent of six digits is in range when the fraction's digits bring the power of
    /// ten back within `MAX_EXPONENT`: 10⁻¹⁰⁰⁰⁰⁰ · 10¹⁰⁰⁰⁰⁰ is 1.
    #[test]
    fn six_digit_exponent_balanced_by_fraction_digits() {
        let text = format!("0.{}1e100000", "0".repeat(99_999));
        let l = Literal::parse(&text).unwrap();
        assert_eq!(
            (l.negative, l.digits.as_str(), l.exp10, l.den.as_str()),
            (false, "1", 0, "1")
        );
    }

    /// The parts of a decimal: signs, a point at either end, exponents; every other character
    /// is refused, in the mantissa or after the exponent.
    #[test]
    fn scans_decimals_by_parts() {
        let parts = |t| {
            let p = Parts::scan(t).unwrap();
            (p.negative, p.int, p.frac, p.exp10, p.den)
        };
        assert_eq!(parts("-012.50e+3"), (true, "012", "50", 1, None));
        assert_eq!(parts("+.5E-2"), (false, "", "5", -3, None));
        assert_eq!(parts(" 7./ 040 "), (false, "7", "", 0, Some("040")));
        for bad in [
            "1.5x", "1e5e3", "1e5.", "+-5", "1..2", "1 2", "0x10", "1_000", "١",
        ] {
            assert!(
                matches!(Parts::scan(bad), Err(NumError::Syntax(_))),
                "{bad:?}"
            );
        }
    }

    #[test]
    fn rejects_garbage() {
        for bad in [
            "",
            "-",
            "1.2.3",
            "e5",
            "1e",
            "abc",
            "1/0",
            "1/x",
            "1e9999999999",
        ] {
            assert!(Literal::parse(bad).is_err(), "{bad:?} accepted");
        }
    }
}
