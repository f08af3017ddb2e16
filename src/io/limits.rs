//! A bound on the length of numbers in a text, checked before parsing: exact numbers of many
//! digits are slow to read (the reduction of a fraction takes time quadratic in its digits)
//! and to compute with, so callers refuse them up front with a located error.

use super::ParseError;

/// An error at the first run of more than `max` ASCII digits in `text` (a number's integer
/// part, fraction or exponent; digits in names or JSON strings count too), naming its length.
///
/// Such a run covers a multiple of `max + 1`, so only the runs at those places are measured:
/// in their order, the first too long is the first too long of all.
pub fn check_digit_runs(text: &str, max: usize) -> Result<(), ParseError> {
    let bytes = text.as_bytes();
    let digit = |b: &u8| b.is_ascii_digit();
    for probe in (0..bytes.len()).step_by(max.saturating_add(1)) {
        if !digit(&bytes[probe]) {
            continue;
        }
        let start = bytes[..probe]
            .iter()
            .rposition(|b| !digit(b))
            .map_or(0, |i| i + 1);
        let len = bytes[start..].iter().take_while(|b| digit(b)).count();
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

    proptest::proptest! {
        /// The first run longer than the limit, as a scan of every byte finds it, wherever the
        /// probes fall.
        #[test]
        fn finds_the_first_long_run_as_a_full_scan_does(
            text in "[0-9a. \né]{0,80}", max in 0usize..12,
        ) {
            let bytes = text.as_bytes();
            let mut first = None;
            let mut start = 0;
            while first.is_none() && start < bytes.len() {
                let len = bytes[start..].iter().take_while(|b| b.is_ascii_digit()).count();
                if len > max {
                    first = Some((start, len));
                }
                start += len.max(1);
            }
            let found = check_digit_runs(&text, max).err();
            proptest::prop_assert_eq!(found.is_some(), first.is_some());
            if let (Some(e), Some((start, len))) = (found, first) {
                let want = ParseError::at(&text, start, String::new());
                proptest::prop_assert_eq!((e.line, e.column), (want.line, want.column));
                let words = format!("{len} digits in a row");
                proptest::prop_assert!(e.message.contains(&words), "{}", e.message);
            }
        }
    }

    #[test]
    fn a_million_digits_are_refused_at_once() {
        let huge = format!("POLYGON ((0 {}, 1 0, 0 1))", "7".repeat(1_000_000));
        let e = check_digit_runs(&huge, 10_000).unwrap_err();
        assert_eq!((e.line, e.column), (1, 13));
        assert!(e.message.contains("1000000 digits"), "{e}");
    }
}
