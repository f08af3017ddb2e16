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
//! * The whole plane, the one Yin set without boundary curves besides the empty set, is the
//!   statement [`WHOLE_PLANE`] (`plane`) on a line of its own; nothing but blank lines and
//!   comments may go with it. (A text without curves is the empty set.)
//! * A UTF-8 byte-order mark at the start is ignored.

use super::{closed, open_ring, without_bom, ParseError};
use crate::kernel::Point;
use crate::num::Num;

/// The statement of the whole plane, on a line of its own.
pub const WHOLE_PLANE: &str = "plane";

/// What a `yin2` text holds.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Yin2Text<N> {
    /// The whole plane ([`WHOLE_PLANE`]).
    Plane,
    /// Curves, each open (without the closing repetition); none for the empty set.
    Curves(Vec<Vec<Point<N>>>),
}

/// Read a `yin2` text: the whole plane, or its curves.
pub fn read<N: Num>(text: &str) -> Result<Yin2Text<N>, ParseError> {
    let text = without_bom(text);
    let mut curves = Vec::new();
    let mut current = Vec::new();
    let mut plane: Option<&str> = None;
    for line in text.split('\n') {
        let trimmed = line.trim();
        if trimmed == WHOLE_PLANE {
            plane = Some(line);
        } else if trimmed.is_empty() {
            if !current.is_empty() {
                curves.push(open_ring(std::mem::take(&mut current)));
            }
        } else if !trimmed.starts_with('#') {
            current.push(point(text, line)?);
        }
        if let Some(statement) = plane.filter(|_| !curves.is_empty() || !current.is_empty()) {
            let (at, what) = if std::ptr::eq(statement, line) {
                (statement, "follows curves")
            } else {
                (line, "is followed by curves")
            };
            return Err(ParseError::at(
                text,
                offset(text, at.trim_start()),
                format!(
                    "the whole plane (`{WHOLE_PLANE}` on line {}) {what}: the whole plane has \
                     no boundary curves",
                    super::error::line_column(text, offset(text, statement)).0
                ),
            ));
        }
    }
    if !current.is_empty() {
        curves.push(open_ring(current));
    }
    Ok(match plane {
        Some(_) => Yin2Text::Plane,
        None => Yin2Text::Curves(curves),
    })
}

/// Read the curves of a `yin2` text, each open (without the closing repetition); the whole
/// plane, which has none, is an error (read it with [`read`]).
pub fn read_curves<N: Num>(text: &str) -> Result<Vec<Vec<Point<N>>>, ParseError> {
    match read(text)? {
        Yin2Text::Curves(curves) => Ok(curves),
        Yin2Text::Plane => {
            let text = without_bom(text);
            let at = text.find(WHOLE_PLANE).unwrap_or(0);
            Err(ParseError::at(
                text,
                at,
                "the whole plane has no curves (yin2_text::read reads it)",
            ))
        }
    }
}

/// The byte offset of `part`, a slice of `text`, in `text`.
fn offset(text: &str, part: &str) -> usize {
    part.as_ptr() as usize - text.as_ptr() as usize
}

/// The point on a non-blank `line` of `text`.
fn point<N: Num>(text: &str, line: &str) -> Result<Point<N>, ParseError> {
    let at = |token: &str, message: String| ParseError::at(text, offset(text, token), message);
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

/// The `yin2` text of the whole plane: the [`WHOLE_PLANE`] statement and a comment saying so.
pub fn write_plane() -> String {
    format!("{WHOLE_PLANE}\n# yinset: the whole plane (no boundary curves)\n")
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

    fn read_rational(text: &str) -> Result<Vec<Vec<Point<Rational>>>, ParseError> {
        read_curves(text)
    }

    #[test]
    fn reads_blocks_comments_and_exact_numbers() {
        let text =
            "# header\n  0.1 0\n1/3\t-2e-1\n 0.1 0 \n\n\n\r\n# between\n5 5\n# inside\n6 5\n7 7";
        let curves = read_rational(text).unwrap();
        assert_eq!(curves.len(), 2);
        assert_eq!(
            curves[0],
            vec![
                Point::new(q("1/10"), q("0")),
                Point::new(q("1/3"), q("-1/5"))
            ]
        );
        assert_eq!(curves[1].len(), 3);
        assert_eq!(read_rational("1 2\r\n3 4\r\n5 6\r\n").unwrap()[0].len(), 3);
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
        assert_eq!(read_rational(&text).unwrap(), curves);
    }

    #[test]
    fn errors_name_the_place() {
        let e = read_rational("0 0\n1 x\n").unwrap_err();
        assert_eq!((e.line, e.column), (2, 3));
        assert!(e.message.contains("`x` is not a number"), "{e}");
        let e = read_rational("0 0\n  7\n").unwrap_err();
        assert_eq!((e.line, e.column), (2, 3));
        assert!(e.message.contains("needs 2 numbers"), "{e}");
        let e = read_rational("0 0 0\n").unwrap_err();
        assert_eq!(
            e.to_string(),
            "line 1, column 5: a point line needs 2 numbers `x y`, found 3 items"
        );
    }

    #[test]
    fn the_whole_plane_is_a_statement_alone() {
        let plane = read::<Rational>(&write_plane()).unwrap();
        assert_eq!(plane, Yin2Text::Plane);
        assert_eq!(
            read::<Rational>("# the plane\n\n  plane \n\n# end\n").unwrap(),
            Yin2Text::Plane
        );
        // A comment mentioning the plane is only a comment: no curves, the empty set.
        assert_eq!(
            read::<Rational>("# yinset: the whole pl\n").unwrap(),
            Yin2Text::Curves(vec![])
        );
        let e = read::<Rational>("plane\n\n0 0\n1 0\n0 1\n").unwrap_err();
        assert_eq!((e.line, e.column), (3, 1));
        assert!(
            e.message
                .contains("(`plane` on line 1) is followed by curves"),
            "{e}"
        );
        let e = read::<Rational>("0 0\n1 0\n0 1\n\n  plane\n").unwrap_err();
        assert_eq!((e.line, e.column), (5, 3));
        assert!(e.message.contains("on line 5) follows curves"), "{e}");
        let e = read_curves::<Rational>("plane\n").unwrap_err();
        assert!(e.message.contains("no curves"), "{e}");
        let e = read::<Rational>("plane 0\n").unwrap_err();
        assert!(e.message.contains("`plane` is not a number"), "{e}");
    }

    #[test]
    fn a_byte_order_mark_is_ignored() {
        let curves = read_rational("\u{feff}0 0\n1 0\n0 1\n").unwrap();
        assert_eq!(curves, read_rational("0 0\n1 0\n0 1\n").unwrap());
        assert_eq!(
            read::<Rational>("\u{feff}plane\n").unwrap(),
            Yin2Text::Plane
        );
        let e = read_curves::<Rational>("\u{feff}0 x\n").unwrap_err();
        assert_eq!((e.line, e.column), (1, 3));
    }

    #[test]
    fn adversarial_inputs_never_panic() {
        assert_eq!(
            read_rational("").unwrap(),
            Vec::<Vec<Point<Rational>>>::new()
        );
        assert_eq!(read_rational("\n \n\t\n\n").unwrap().len(), 0);
        assert_eq!(read_rational("# only a comment").unwrap().len(), 0);
        for bad in [
            "1e99999999 0",
            "NaN 0",
            "0 inf",
            "0 -infinity",
            "1/0 1",
            "é ü",
            "0,0 1",
        ] {
            let e = read_rational(bad).unwrap_err();
            assert_eq!(e.line, 1, "{bad}: {e}");
        }
        assert_eq!(read_rational("é 1 2").unwrap_err().column, 5);
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
        let curves = read_rational(&texts.join("\n")).unwrap();
        assert_eq!(curves.len(), 10);
        assert_eq!(curves[9][0], Point::new(q("4.5040114"), q("2.830463")));
        for (curve, text) in curves.iter().zip(&texts) {
            let lines = text.lines().filter(|l| !l.trim().is_empty()).count();
            assert_eq!(curve.len() + 1, lines, "the closing repetition is stripped");
        }
    }
}
