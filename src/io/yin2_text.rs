//! The `yin2` curve-list text format: blocks of `x y` lines, one block per closed curve.
//!
//! ```text
//! # a unit square, then a triangle with exact fractions
//! 0 0
//! 1 0
//!   1   1
//! 0 1
//! 0 0
//!
//! 1/3 0.5
//! 4.5040114e+00 -2
//! 1 1
//! ```
//!
//! * A point is one line of exactly two numbers separated by spaces or tabs (leading and
//!   trailing blanks allowed): exact decimals (`-0.1`, `4.5040114e+00`) or fractions `p/q`.
//! * Curves are separated by one or more blank lines; the first point may be repeated at the
//!   end of its block (that closing repetition is dropped when reading, and always written).
//! * A line whose first non-blank character is `#` is a comment: it is ignored, and neither
//!   adds a point nor separates curves.

use super::{closed, open_ring, ParseError};
use crate::kernel::Point;
use crate::num::Num;

/// Read the curves of a `yin2` text, each open (without the closing repetition).
pub fn read_curves<N: Num>(text: &str) -> Result<Vec<Vec<Point<N>>>, ParseError> {
    let mut curves = Vec::new();
    let mut current = Vec::new();
    for line in text.split('\n') {
        let trimmed = line.trim();
        if trimmed.is_empty() {
            if !current.is_empty() {
                curves.push(open_ring(std::mem::take(&mut current)));
            }
        } else if !trimmed.starts_with('#') {
            current.push(point(text, line)?);
        }
    }
    if !current.is_empty() {
        curves.push(open_ring(current));
    }
    Ok(curves)
}

/// The point on a non-blank `line` of `text`.
fn point<N: Num>(text: &str, line: &str) -> Result<Point<N>, ParseError> {
    let at = |token: &str, message: String| {
        ParseError::at(
            text,
            token.as_ptr() as usize - text.as_ptr() as usize,
            message,
        )
    };
    let tokens: Vec<&str> = line.split_whitespace().collect();
    let number = |token: &str| N::parse(token).map_err(|e| at(token, e.to_string()));
    let message = |found: String| format!("a point line needs 2 numbers `x y`, found {found}");
    match tokens[..] {
        [x, y] => Ok(Point::new(number(x)?, number(y)?)),
        [_, _, extra, ..] => Err(at(extra, message(format!("{} items", tokens.len())))),
        _ => Err(at(
            line.trim_start(),
            message(format!("only `{}`", line.trim())),
        )),
    }
}

/// The `yin2` text of `curves`: each closed by repeating its first point, numbers written
/// exactly by their `Display` (`p/q` for non-integral rationals), a blank line between curves.
pub fn write_curves<N: Num>(curves: &[Vec<Point<N>>]) -> String {
    let blocks: Vec<String> = curves
        .iter()
        .map(|curve| {
            closed(curve)
                .map(|p| format!("{} {}\n", p.x, p.y))
                .collect()
        })
        .collect();
    blocks.join("\n")
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::io::testdata;
    use crate::num::Rational;

    fn q(s: &str) -> Rational {
        Rational::parse(s).unwrap()
    }

    fn read(text: &str) -> Result<Vec<Vec<Point<Rational>>>, ParseError> {
        read_curves(text)
    }

    #[test]
    fn reads_blocks_comments_and_exact_numbers() {
        let text =
            "# header\n  0.1 0\n1/3\t-2e-1\n 0.1 0 \n\n\n\r\n# between\n5 5\n# inside\n6 5\n7 7";
        let curves = read(text).unwrap();
        assert_eq!(curves.len(), 2);
        assert_eq!(
            curves[0],
            vec![
                Point::new(q("1/10"), q("0")),
                Point::new(q("1/3"), q("-1/5"))
            ]
        );
        assert_eq!(curves[1].len(), 3);
        assert_eq!(read("1 2\r\n3 4\r\n5 6\r\n").unwrap()[0].len(), 3);
    }

    #[test]
    fn write_then_read_round_trips_exact_rationals() {
        let curves = vec![
            vec![
                Point::new(q("1/3"), q("-2/7")),
                Point::new(q("0.1"), q("1e30")),
                Point::new(q("-5"), q("1/1000000007")),
            ],
            vec![Point::int(0, 0), Point::int(1, 0), Point::int(0, 1)],
        ];
        let text = write_curves(&curves);
        assert!(text.starts_with("1/3 -2/7\n1/10 "), "{text}");
        assert!(
            text.contains("\n-5 1/1000000007\n1/3 -2/7\n\n0 0\n"),
            "{text}"
        );
        assert_eq!(read(&text).unwrap(), curves);
    }

    #[test]
    fn errors_name_the_place() {
        let e = read("0 0\n1 x\n").unwrap_err();
        assert_eq!((e.line, e.column), (2, 3));
        assert!(e.message.contains("`x` is not a number"), "{e}");
        let e = read("0 0\n  7\n").unwrap_err();
        assert_eq!((e.line, e.column), (2, 3));
        assert!(e.message.contains("needs 2 numbers"), "{e}");
        let e = read("0 0 0\n").unwrap_err();
        assert_eq!(
            e.to_string(),
            "line 1, column 5: a point line needs 2 numbers `x y`, found 3 items"
        );
    }

    #[test]
    fn adversarial_inputs_never_panic() {
        assert_eq!(read("").unwrap(), Vec::<Vec<Point<Rational>>>::new());
        assert_eq!(read("\n \n\t\n\n").unwrap().len(), 0);
        assert_eq!(read("# only a comment").unwrap().len(), 0);
        for bad in [
            "1e99999999 0",
            "NaN 0",
            "0 inf",
            "0 -infinity",
            "1/0 1",
            "é ü",
            "0,0 1",
        ] {
            let e = read(bad).unwrap_err();
            assert_eq!(e.line, 1, "{bad}: {e}");
        }
        assert_eq!(read("é 1 2").unwrap_err().column, 5);
    }

    #[test]
    fn panda_curves_concatenated_read_as_ten_curves() {
        if !testdata::available() {
            return;
        }
        let dir = testdata::dir("2d/panda");
        let texts: Vec<String> = (1..=10)
            .map(|i| dir.join(format!("curve{i:02}.txt")))
            .map(|path| {
                std::fs::read_to_string(&path)
                    .unwrap_or_else(|e| panic!("cannot read {}: {e}", path.display()))
            })
            .collect();
        let curves = read(&texts.join("\n")).unwrap();
        assert_eq!(curves.len(), 10);
        assert_eq!(curves[9][0], Point::new(q("4.5040114"), q("2.830463")));
        for (curve, text) in curves.iter().zip(&texts) {
            let lines = text.lines().filter(|l| !l.trim().is_empty()).count();
            assert_eq!(curve.len() + 1, lines, "the closing repetition is stripped");
        }
    }
}
