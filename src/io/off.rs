//! OFF (Object File Format) polygon meshes, ASCII, read and written exactly.
//!
//! ```text
//! OFF
//! # a tetrahedron
//! 4 4 6
//! 0 0 0
//! 1 0 0
//! 0 1 0
//! 0 0 1/3
//! 3 0 2 1
//! 3 0 1 3
//! 3 1 2 3
//! 3 2 0 3
//! ```
//!
//! No maintained Rust crate reads OFF, so it is parsed here. Reading ([`read_off`]):
//!
//! * An optional `OFF` keyword, then the counts `vertices faces edges` (on the keyword's line
//!   or the next); the edge count is not checked (many files write 0).
//! * One vertex per line, exactly three coordinates, each read with [`Num::parse`] (exact
//!   decimals; fractions `p/q` are this crate's extension). The variants with colours, normals
//!   or other dimensions (`COFF`, `NOFF`, `4OFF`, `nOFF`, …) are not read.
//! * One face per line: its vertex count `n ≥ 3` and `n` 0-based vertex indices, counterclockwise
//!   seen from outside. Numbers after the indices (a face colour) are ignored.
//! * Everything from a `#` to the end of its line is a comment; blank lines are skipped; text
//!   after the last face is an error. A UTF-8 byte-order mark at the start is ignored.
//!
//! Malformed input is a [`ParseError`] with the line and column of the offending token.
//!
//! Writing ([`write_off`]) gives triangles with coordinates exact: a decimal when the expansion
//! terminates, `p/q` otherwise (read back by [`read_off`] but not by other OFF tools).

use super::mesh::{coordinate, indexed_text, Mesh};
use super::{without_bom, ParseError};
use crate::kernel::Point3;
use crate::num::Num;

/// A non-blank line of the file without its comment: its 1-based number and tokens.
struct Line<'a> {
    number: usize,
    tokens: Vec<&'a str>,
}

/// The non-blank lines of `text`, comments stripped.
fn lines(text: &str) -> impl Iterator<Item = Line<'_>> {
    text.split('\n').enumerate().filter_map(|(k, line)| {
        let content = line.split('#').next().unwrap_or_default();
        let tokens: Vec<&str> = content.split_whitespace().collect();
        (!tokens.is_empty()).then_some(Line {
            number: k + 1,
            tokens,
        })
    })
}

/// The non-negative integer `token`, or an error at it saying it should be `what`.
fn count(text: &str, token: &str, what: &str) -> Result<usize, ParseError> {
    token.parse().map_err(|_| {
        let message = format!("`{token}` is not {what} (a non-negative integer)");
        ParseError::at_token(text, token, message)
    })
}

/// The error at the end of `text`: it ends before `wanted`.
fn ends_early(text: &str, wanted: &str) -> ParseError {
    let message = format!("the file ends where {wanted} is due");
    ParseError::at_token(text, &text[text.len()..], message)
}

/// Read the vertices and faces of an OFF text (see the [module documentation](self)).
pub fn read_off<N: Num>(text: &str) -> Result<Mesh<N>, ParseError> {
    let text = without_bom(text);
    let mut lines = lines(text);
    let first = lines
        .next()
        .ok_or_else(|| ends_early(text, "the `OFF` keyword or the counts"))?;
    let mut counts = first.tokens.clone();
    if counts[0] == "OFF" {
        counts.remove(0);
        if counts.is_empty() {
            counts = lines
                .next()
                .ok_or_else(|| ends_early(text, "the counts `vertices faces edges`"))?
                .tokens;
        }
    } else if counts[0].ends_with("OFF") {
        let message = format!("`{}` files are not read, only plain `OFF`", counts[0]);
        return Err(ParseError::at_token(text, counts[0], message));
    }
    let (nv, nf) = match counts[..] {
        [v, f, e] => {
            count(text, e, "an edge count")?;
            (
                count(text, v, "a vertex count")?,
                count(text, f, "a face count")?,
            )
        }
        _ => {
            let message = format!(
                "expected the counts `vertices faces edges`, found {} number(s)",
                counts.len()
            );
            return Err(ParseError::at_token(
                text,
                counts.first().unwrap_or(&""),
                message,
            ));
        }
    };
    let mut mesh = Mesh::default();
    for k in 0..nv {
        let line = lines
            .next()
            .ok_or_else(|| ends_early(text, &format!("vertex {k} of {nv}")))?;
        match line.tokens[..] {
            [x, y, z] => mesh.vertices.push(Point3::new(
                coordinate(text, x)?,
                coordinate(text, y)?,
                coordinate(text, z)?,
            )),
            _ => {
                let message = format!(
                    "a vertex line needs 3 coordinates `x y z`, found {} number(s)",
                    line.tokens.len()
                );
                return Err(ParseError::at_token(text, line.tokens[0], message));
            }
        }
    }
    for k in 0..nf {
        let line = lines
            .next()
            .ok_or_else(|| ends_early(text, &format!("face {k} of {nf}")))?;
        mesh.faces.push(face(text, &line.tokens, nv)?);
        mesh.face_lines.push(line.number);
    }
    if let Some(extra) = lines.next() {
        let message = format!("text after the {nf} faces the header announces");
        return Err(ParseError::at_token(text, extra.tokens[0], message));
    }
    Ok(mesh)
}

/// The vertex indices of the face line `tokens`, with `nv` vertices in the file.
fn face(text: &str, tokens: &[&str], nv: usize) -> Result<Vec<usize>, ParseError> {
    let n = count(text, tokens[0], "a face's vertex count")?;
    if n < 3 {
        let message = format!("a face needs at least 3 vertices, found {n}");
        return Err(ParseError::at_token(text, tokens[0], message));
    }
    let Some(indices) = tokens.get(1..=n) else {
        let message = format!(
            "the face has {n} vertices but only {} indices follow",
            tokens.len() - 1
        );
        return Err(ParseError::at_token(text, tokens[0], message));
    };
    indices
        .iter()
        .map(|&token| match count(text, token, "a vertex index")? {
            i if i < nv => Ok(i),
            i => {
                let message = format!(
                    "vertex index {i} is out of range: there are {nv} vertices, numbered from 0"
                );
                Err(ParseError::at_token(text, token, message))
            }
        })
        .collect()
}

/// The OFF text of `triangles` (indices into `vertices`, counterclockwise seen from outside):
/// the vertices they use, coordinates exact, and the triangles.
///
/// # Panics
/// If a triangle index is out of range of `vertices`.
pub fn write_off<N: Num>(vertices: &[Point3<N>], triangles: &[[usize; 3]]) -> String {
    indexed_text(vertices, triangles, |nv, nt| {
        format!("OFF\n# yinset: coordinates exact (p/q where no decimal is)\n{nv} {nt} 0\n")
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::num::Rational;

    fn q(s: &str) -> Rational {
        Rational::parse(s).unwrap()
    }

    const TETRA: &str =
        "OFF\n# t\n4 4 6\n0 0 0\n1 0 0\n0 1 0\n0 0 1/3\n3 0 2 1\n\n3 0 1 3 255 0 0\n\
                         3 1 2 3\n3 2 0 3 # last\n";

    #[test]
    fn reads_exact_coordinates_and_faces_with_their_lines() {
        let mesh = read_off::<Rational>(TETRA).unwrap();
        assert_eq!(mesh.vertices[3], Point3::new(q("0"), q("0"), q("1/3")));
        assert_eq!(mesh.faces[1], vec![0, 1, 3]);
        assert_eq!(mesh.face_lines, vec![8, 10, 11, 12]);
        let inline = read_off::<Rational>("OFF 3 1 0\n0 0 0\n0.1 0 0\n0 1 0\n3 0 1 2\n").unwrap();
        assert_eq!(inline.vertices[1].x, q("1/10"));
        let bare = read_off::<Rational>("3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n").unwrap();
        assert_eq!(bare.faces, vec![vec![0, 1, 2]]);
    }

    /// `(line, column, message)` of the error reading `text`.
    fn error(text: &str) -> (usize, usize, String) {
        let e = read_off::<Rational>(text).unwrap_err();
        (e.line, e.column, e.message)
    }

    #[test]
    fn errors_name_line_and_column() {
        let (line, column, message) = error(&TETRA.replace("3 1 2 3", "3 1 2 4"));
        assert_eq!((line, column), (11, 7));
        assert_eq!(
            message,
            "vertex index 4 is out of range: there are 4 vertices, numbered from 0"
        );
        let (line, column, message) = error(&TETRA.replace("1 0 0", "1 x 0"));
        assert_eq!((line, column), (5, 3));
        assert!(message.contains("`x` is not a number"), "{message}");
        assert_eq!(error(&TETRA.replace("3 0 2 1", "2 0 2")).0, 8);
        assert!(error(&TETRA.replace("3 0 2 1", "3 0 2"))
            .2
            .contains("only 2 indices"));
        let (line, _, message) = error(&TETRA.replace("3 2 0 3 # last\n", ""));
        assert_eq!(
            (line, message.as_str()),
            (12, "the file ends where face 3 of 4 is due")
        );
        assert_eq!(error(&format!("{TETRA}1 2 3\n")).0, 13);
        assert!(error("COFF\n").2.contains("only plain `OFF`"));
        assert!(error("OFF\n3 1\n").2.contains("found 2 number(s)"));
        assert!(error("").2.contains("ends where the `OFF` keyword"));
        assert!(error("OFF\n1 0 0\n0 0\n").2.contains("found 2 number(s)"));
    }

    #[test]
    fn writer_is_read_back_exactly() {
        let v = vec![
            Point3::int(5, 5, 5), // unused
            Point3::new(q("1/3"), q("0.1"), q("-2")),
            Point3::int(1, 0, 0),
            Point3::int(0, 1, 0),
        ];
        let text = write_off(&v, &[[1, 2, 3]]);
        assert!(text.contains("\n3 1 0\n1/3 0.1 -2\n"), "{text}");
        let mesh = read_off::<Rational>(&text).unwrap();
        assert_eq!(mesh.vertices, v[1..]);
        assert_eq!(mesh.faces, vec![vec![0, 1, 2]]);
    }
}
