//! `locate`: points as `x y` (2D) or `x y z` (3D) lines → inside / outside / boundary, one
//! output line per input line (an empty one for a blank or comment line), so that answers line
//! up with their points.

use crate::io::ParseError;
use crate::kernel::{Point, Point3};
use crate::num::Num;
use crate::yin2::Location;

/// The point on each line of `text`, one `x y` per line (none for blank and `#` comment lines).
pub fn read_points<N: Num>(text: &str) -> Result<Vec<Option<Point<N>>>, ParseError> {
    let lines = read_coordinates::<N, 2>(text)?;
    Ok(lines
        .into_iter()
        .map(|p| p.map(|[x, y]| Point::new(x, y)))
        .collect())
}

/// The point on each line of `text`, one `x y z` per line (none for blank and comment lines).
pub fn read_points3<N: Num>(text: &str) -> Result<Vec<Option<Point3<N>>>, ParseError> {
    let lines = read_coordinates::<N, 3>(text)?;
    Ok(lines
        .into_iter()
        .map(|p| p.map(|[x, y, z]| Point3::new(x, y, z)))
        .collect())
}

/// The `D` coordinates on each line of `text` (none for blank and `#` comment lines).
fn read_coordinates<N: Num, const D: usize>(text: &str) -> Result<Vec<Option<[N; D]>>, ParseError> {
    let text = crate::io::without_bom(text);
    let mut points = Vec::new();
    for (k, line) in text.lines().enumerate() {
        let trimmed = line.trim();
        if trimmed.is_empty() || trimmed.starts_with('#') {
            points.push(None);
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
        points.push(Some(coordinates));
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

/// One line per input line: where its point lies, as `locate` (the kernel's, on all points
/// at once) says, or nothing for a line without a point.
pub fn aligned<P: Clone>(
    lines: &[Option<P>],
    locate: impl FnOnce(&[P]) -> Vec<Location>,
) -> String {
    let points: Vec<P> = lines.iter().flatten().cloned().collect();
    let mut words = locate(&points).into_iter().map(word);
    lines
        .iter()
        .map(|line| match line {
            Some(_) => format!("{}\n", words.next().unwrap_or_default()),
            None => "\n".to_string(),
        })
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
        assert_eq!(pts.len(), 5);
        assert_eq!(pts.iter().flatten().count(), 3);
        assert!(pts[0].is_none() && pts[2].is_none());
        assert_eq!(
            pts[3].as_ref().unwrap().x,
            Rational::new(1.into(), 2.into())
        );
        let bom = read_points::<Rational>("\u{feff}0 0\n").unwrap();
        assert_eq!(bom, vec![Some(Point::int(0, 0))]);
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
                None,
                Some(Point3::new(
                    Rational::from_i64(0),
                    Rational::from_i64(0),
                    Rational::new(1.into(), 2.into())
                )),
                None,
                Some(Point3::int(1, 2, 3))
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
        let half = Rational::new(1.into(), 2.into());
        let lines = [
            Some(p(0, 0)),
            None,
            Some(p(1, 0)),
            Some(p(3, 3)),
            None,
            Some(Point::new(half.clone(), half)),
        ];
        assert_eq!(
            aligned(&lines, |points| set.locate(points)),
            "boundary\n\nboundary\noutside\n\ninside\n"
        );
    }
}
