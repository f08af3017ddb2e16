//! `locate`: points as `x y` (2D) or `x y z` (3D) lines → inside / outside / boundary, one
//! word per point.

use crate::io::ParseError;
use crate::kernel::{Point, Point3};
use crate::num::Num;
use crate::yin2::Location;

/// The points of `text`: one `x y` per line; blank lines and `#` comments are skipped.
pub fn read_points<N: Num>(text: &str) -> Result<Vec<Point<N>>, ParseError> {
    let points = read_coordinates::<N, 2>(text)?;
    Ok(points.into_iter().map(|[x, y]| Point::new(x, y)).collect())
}

/// The points of `text`: one `x y z` per line; blank lines and `#` comments are skipped.
pub fn read_points3<N: Num>(text: &str) -> Result<Vec<Point3<N>>, ParseError> {
    let points = read_coordinates::<N, 3>(text)?;
    Ok(points
        .into_iter()
        .map(|[x, y, z]| Point3::new(x, y, z))
        .collect())
}

/// The `D` coordinates on each line of `text`; blank lines and `#` comments are skipped.
fn read_coordinates<N: Num, const D: usize>(text: &str) -> Result<Vec<[N; D]>, ParseError> {
    let mut points = Vec::new();
    for (k, line) in text.lines().enumerate() {
        let trimmed = line.trim();
        if trimmed.is_empty() || trimmed.starts_with('#') {
            continue;
        }
        let at = |token: &str, message: String| ParseError {
            line: k + 1,
            column: line[..token.as_ptr() as usize - line.as_ptr() as usize]
                .chars()
                .count()
                + 1,
            message,
        };
        let tokens: Vec<&str> = trimmed.split_whitespace().collect();
        let number = |t: &str| N::parse(t).map_err(|e| at(t, e.to_string()));
        if tokens.len() != D {
            let n = tokens.len();
            let found = format!("{n} item{}", if n == 1 { "" } else { "s" });
            let where_ = tokens.get(D).copied().unwrap_or(trimmed);
            let names = ["x", "y", "z"][..D].join(" ");
            return Err(at(
                where_,
                format!("a point line needs {D} numbers `{names}`, found {found}"),
            ));
        }
        let mut coordinates: [N; D] = std::array::from_fn(|_| N::zero());
        for (c, t) in coordinates.iter_mut().zip(tokens) {
            *c = number(t)?;
        }
        points.push(coordinates);
    }
    Ok(points)
}

/// The word for a location.
fn word(l: Location) -> &'static str {
    match l {
        Location::Inside => "inside",
        Location::Outside => "outside",
        Location::OnBoundary => "boundary",
    }
}

/// One line per point: where it lies (`locations`, as the kernel's `locate` gives them).
pub fn classify(locations: Vec<Location>) -> String {
    locations
        .into_iter()
        .map(|l| format!("{}\n", word(l)))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::num::Rational;
    use crate::yin2::YinSet2;

    #[test]
    fn reads_points_with_repeats_comments_and_fractions() {
        let pts = read_points::<Rational>("# p\n0 0\n\n 1/2  3\n0 0\n").unwrap();
        assert_eq!(pts.len(), 3);
        assert_eq!(pts[1].x, Rational::new(1.into(), 2.into()));
    }

    #[test]
    fn malformed_points_are_located() {
        let e = read_points::<Rational>("0 0\n  1 y\n").unwrap_err();
        assert_eq!((e.line, e.column), (2, 5));
        let e = read_points::<Rational>("0 0 9\n").unwrap_err();
        assert_eq!((e.line, e.column), (1, 5));
        let e = read_points::<Rational>("\n é\n").unwrap_err();
        assert_eq!((e.line, e.column), (2, 2));
        assert!(e.message.contains("found 1 item"), "{e}");
    }

    #[test]
    fn reads_3d_points() {
        let pts = read_points3::<Rational>("# p\n0 0 1/2\n\n 1  2 3\n").unwrap();
        assert_eq!(
            pts,
            vec![
                Point3::new(
                    Rational::from_i64(0),
                    Rational::from_i64(0),
                    Rational::new(1.into(), 2.into())
                ),
                Point3::int(1, 2, 3)
            ]
        );
        let e = read_points3::<Rational>("0 0\n").unwrap_err();
        assert!(
            e.message.contains("needs 3 numbers `x y z`, found 2 items"),
            "{e}"
        );
        let e = read_points3::<Rational>("0 0 0 0\n").unwrap_err();
        assert_eq!((e.line, e.column), (1, 7));
    }

    #[test]
    fn classifies_inside_outside_boundary() {
        let p = |x, y| Point::int(x, y);
        let set = YinSet2::<Rational>::from_curves(vec![vec![p(0, 0), p(2, 0), p(0, 2)]]).unwrap();
        assert_eq!(
            classify(set.locate(&[
                p(0, 0),
                p(1, 0),
                p(3, 3),
                Point::new(
                    Rational::new(1.into(), 2.into()),
                    Rational::new(1.into(), 2.into())
                )
            ])),
            "boundary\nboundary\noutside\ninside\n"
        );
    }
}
