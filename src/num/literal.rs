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
        let s = text.trim();
        let err = || NumError::Syntax(text.to_string());
        if let Some((p, q)) = s.split_once('/') {
            let num = Literal::parse_decimal(p.trim(), text)?;
            let den = q.trim();
            if den.is_empty() || !den.bytes().all(|c| c.is_ascii_digit()) {
                return Err(err());
            }
            if den.bytes().all(|c| c == b'0') {
                return Err(NumError::ZeroDenominator(text.to_string()));
            }
            return Ok(Literal {
                den: den.to_string(),
                ..num
            });
        }
        Literal::parse_decimal(s, text)
    }

    fn parse_decimal(s: &str, text: &str) -> Result<Literal, NumError> {
        let err = || NumError::Syntax(text.to_string());
        let (negative, rest) = match s.as_bytes().first() {
            Some(b'-') => (true, &s[1..]),
            Some(b'+') => (false, &s[1..]),
            _ => (false, s),
        };
        let (mantissa, exponent) = match rest.find(['e', 'E']) {
            Some(i) => (&rest[..i], Some(&rest[i + 1..])),
            None => (rest, None),
        };
        let (int_part, frac_part) = mantissa.split_once('.').unwrap_or((mantissa, ""));
        let all_digits = |t: &str| t.bytes().all(|c| c.is_ascii_digit());
        if (int_part.is_empty() && frac_part.is_empty())
            || !all_digits(int_part)
            || !all_digits(frac_part)
        {
            return Err(err());
        }
        let mut exp10: i64 = 0;
        if let Some(e) = exponent {
            let (eneg, edigits) = match e.as_bytes().first() {
                Some(b'-') => (true, &e[1..]),
                Some(b'+') => (false, &e[1..]),
                _ => (false, e),
            };
            if edigits.is_empty() || !all_digits(edigits) {
                return Err(err());
            }
            let trimmed = edigits.trim_start_matches('0');
            if trimmed.len() > 6 {
                return Err(NumError::ExponentRange(text.to_string()));
            }
            let v: i64 = trimmed.parse().unwrap_or(0);
            exp10 = if eneg { -v } else { v };
        }
        exp10 -= frac_part.len() as i64;
        if exp10.abs() > MAX_EXPONENT + frac_part.len() as i64 {
            return Err(NumError::ExponentRange(text.to_string()));
        }
        let mut digits = format!("{int_part}{frac_part}");
        let trimmed = digits.trim_start_matches('0');
        digits = if trimmed.is_empty() {
            "0".to_string()
        } else {
            trimmed.to_string()
        };
        Ok(Literal {
            negative,
            digits,
            exp10,
            den: "1".to_string(),
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
