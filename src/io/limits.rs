//! A bound on the length of numbers in a text, checked before parsing: exact numbers of many
//! digits are slow to read (the reduction of a fraction takes time quadratic in its digits)
//! and to compute with, so callers refuse them up front with a located error.

use super::ParseError;

/// An error at the first run of more than `max` ASCII digits in `text` (a number's integer
/// part, fraction or exponent; digits in names or JSON strings count too), naming its length.
pub fn check_digit_runs(text: &str, max: usize) -> Result<(), ParseError> {
    let bytes = text.as_bytes();
    let mut start = 0;
    while start < bytes.len() {
        if !bytes[start].is_ascii_digit() {
            start += 1;
            continue;
        }
        let len = bytes[start..]
            .iter()
            .take_while(|b| b.is_ascii_digit())
            .count();
        if len > max {
            return Err(ParseError::at(
                text,
                start,
                format!(
                    "a number with {len} digits in a row, more than the limit of {max} \
                     (--max-digits)"
                ),
            ));
        }
        start += len;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn long_runs_are_refused_where_they_start() {
        let long = format!("0 0\n1 0.{}\n", "3".repeat(12));
        assert!(check_digit_runs(&long, 12).is_ok());
        let e = check_digit_runs(&long, 11).unwrap_err();
        assert_eq!((e.line, e.column), (2, 5));
        assert!(
            e.message
                .contains("12 digits in a row, more than the limit of 11"),
            "{e}"
        );
        assert!(check_digit_runs("", 0).is_ok());
        assert!(check_digit_runs("é x", 0).is_ok());
        assert_eq!(check_digit_runs("é 12", 1).unwrap_err().column, 3);
    }

    #[test]
    fn a_million_digits_are_refused_at_once() {
        let huge = format!("POLYGON ((0 {}, 1 0, 0 1))", "7".repeat(1_000_000));
        let e = check_digit_runs(&huge, 10_000).unwrap_err();
        assert_eq!((e.line, e.column), (1, 13));
        assert!(e.message.contains("1000000 digits"), "{e}");
    }
}
