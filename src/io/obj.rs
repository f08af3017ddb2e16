//! Wavefront OBJ polygon meshes, read and written exactly.
//!
//! The reader is this crate's own rather than the `tobj` crate's: `tobj` parses coordinates
//! into `f32` or `f64`, rounding decimals such as `0.1`, so it cannot give exact mode the
//! values the file says.
//!
//! ```text
//! # yinset
//! v 0 0 0
//! v 1 0 0
//! v 0 1 0
//! v 0 0 1/3
//! o tetrahedron
//! f 1 3 2
//! f 1 2 4
//! f 2 3 4
//! f 3 1 4
//! ```
//!
//! Reading ([`read_obj`]) keeps only the geometry:
//!
//! * `v x y z [w]`: a vertex. Every coordinate is parsed with [`Num::parse`], so exact backends
//!   get the decimal text's value without rounding (`0.1` is exactly 1/10, `4.5040114e+00` is
//!   45040114/10⁷); fractions `p/q` are accepted too. The optional fourth coordinate `w` must
//!   equal 1 exactly (a rational vertex is not a point of space); more than four numbers (the
//!   vertex colours some tools append) are an error.
//! * `f v1 v2 v3 …`: a face of three or more vertices, each written `i`, `i/j`, `i/j/k` or
//!   `i//k`. Only the vertex index `i` is kept; the texture and normal indices `j`, `k` must be
//!   non-zero integers but are not checked against any `vt`/`vn` count. Indices are 1-based;
//!   a negative index counts back from the vertices read so far (`-1` is the last). An index
//!   must refer to a vertex defined **before** its face line (no forward references, which
//!   some tools allow). Faces are kept as given: n-gons stay n-gons, and repeated or collinear
//!   vertices are the kernel's business, not the reader's.
//! * Everything from a `#` to the end of its line is a comment. Every other line kind (`vt`,
//!   `vn`, `vp`, `o`, `g`, `s`, `usemtl`, `mtllib`, `l`, `p`, blank lines, …) is ignored;
//!   keywords are case-sensitive, blanks are spaces or tabs, and CRLF line ends are accepted.
//!   Line continuation by a trailing `\` is **not** supported: on a `v` or `f` line the `\` is
//!   reported as a malformed number or index.
//! * A file without `v` and `f` lines is the mesh without vertices or faces only if it holds
//!   nothing but comments and blank lines (as the empty set is written); with any other line
//!   it is an error at that line, since it is not an OBJ mesh (a yin2 text, say).
//!
//! A UTF-8 byte-order mark at the start is ignored. The reader never panics; malformed input
//! is a [`ParseError`] with the line and column of the offending token.
//!
//! Writing ([`write_obj`]) produces triangle meshes with coordinates written exactly: a decimal
//! when the expansion terminates, `p/q` otherwise. The `p/q` form is this crate's extension of
//! OBJ: [`read_obj`] reads it back exactly, other OBJ tools do not.

use super::mesh::{coordinate, push_coords, push_triangle, text_size, used, Mesh};
use super::{without_bom, ParseError};
use crate::kernel::Point3;
use crate::num::Num;
use crate::yin3::YinSet3;
use std::fmt::Write;

/// Read the vertices and faces of an OBJ text (see the [module documentation](self) for what
/// is accepted).
pub fn read_obj<N: Num>(text: &str) -> Result<Mesh<N>, ParseError> {
    let text = without_bom(text);
    let mut mesh = Mesh::default();
    let mut first_other = None;
    for (number, line) in text.split('\n').enumerate() {
        let content = line.split('#').next().unwrap_or_default();
        let mut tokens = Tokens::of(content);
        match tokens.next() {
            Some("v") => mesh.vertices.push(vertex(text, content, tokens)?),
            Some(keyword @ "f") => {
                let face = face(text, keyword, tokens, mesh.vertices.len())?;
                mesh.faces.push(face);
                mesh.face_lines.push(number + 1);
            }
            Some(other) => {
                first_other.get_or_insert(other);
            }
            None => {}
        }
    }
    match first_other {
        Some(other) if mesh.vertices.is_empty() && mesh.faces.is_empty() => Err(at(
            text,
            other,
            format!(
                "`{other}`: the file has no vertex (`v`) or face (`f`) lines, so it is not an \
                 OBJ mesh (an OBJ file of the empty set holds only comments and blank lines)"
            ),
        )),
        _ => Ok(mesh),
    }
}

/// The blank-separated tokens of a line, those of `str::split_whitespace`: found byte by byte
/// when the line is ASCII, by `split_whitespace` itself otherwise.
enum Tokens<'a> {
    /// The rest of an ASCII line.
    Ascii(&'a str),
    /// The tokens of a line with other characters (some of them Unicode blanks).
    Unicode(std::str::SplitWhitespace<'a>),
}

impl<'a> Tokens<'a> {
    /// The tokens of `line`.
    fn of(line: &'a str) -> Tokens<'a> {
        match line.is_ascii() {
            true => Tokens::Ascii(line),
            false => Tokens::Unicode(line.split_whitespace()),
        }
    }
}

impl<'a> Iterator for Tokens<'a> {
    type Item = &'a str;

    /// The next token: in an ASCII line, the next run of bytes that are not ASCII blanks (the
    /// characters `char::is_whitespace` accepts among them: tab to carriage return, space).
    fn next(&mut self) -> Option<&'a str> {
        match self {
            Tokens::Ascii(rest) => {
                let blank = |b: u8| matches!(b, b'\t'..=b'\r' | b' ');
                let start = rest.bytes().position(|b| !blank(b))?;
                let token = &rest[start..];
                let end = token.bytes().position(blank).unwrap_or(token.len());
                *rest = &token[end..];
                Some(&token[..end])
            }
            Tokens::Unicode(split) => split.next(),
        }
    }
}

/// The error `message` at `token`, a subslice of `text`.
fn at(text: &str, token: &str, message: impl Into<String>) -> ParseError {
    ParseError::at_token(text, token, message)
}

/// The vertex of a `v` line (`content`, comment stripped) whose remaining tokens are `tokens`.
fn vertex<'a, N: Num>(
    text: &str,
    content: &'a str,
    tokens: impl Iterator<Item = &'a str>,
) -> Result<Point3<N>, ParseError> {
    let (first, count) = first_of::<5>(tokens);
    let number = |token: &str| coordinate::<N>(text, token);
    let message = |found: String| format!("a vertex line needs `v x y z` or `v x y z 1`, {found}");
    match (count, first) {
        (3, [x, y, z, ..]) => Ok(Point3::new(number(x)?, number(y)?, number(z)?)),
        (4, [x, y, z, w, _]) => {
            let p = Point3::new(number(x)?, number(y)?, number(z)?);
            if number(w)? == N::from_i64(1) {
                Ok(p)
            } else {
                Err(at(
                    text,
                    w,
                    message(format!("found the weight `{w}` (only 1 is supported)")),
                ))
            }
        }
        (5.., [.., extra]) => Err(at(text, extra, message(format!("found {count} numbers")))),
        _ => {
            let found = format!("found only {count} number(s)");
            let place = count
                .checked_sub(1)
                .map_or(content.trim_start(), |i| first[i]);
            let end = &place[place.len()..];
            Err(at(text, end, message(found)))
        }
    }
}

/// The first `K` items of `tokens` (the rest `""`) and how many items it has in all.
fn first_of<'a, const K: usize>(tokens: impl Iterator<Item = &'a str>) -> ([&'a str; K], usize) {
    let mut first = [""; K];
    let mut count = 0;
    for token in tokens {
        if let Some(slot) = first.get_mut(count) {
            *slot = token;
        }
        count += 1;
    }
    (first, count)
}

/// The 0-based vertex indices of an `f` line whose keyword is `keyword` and whose remaining
/// tokens are `tokens`, with `defined` vertices read so far.
fn face<'a>(
    text: &str,
    keyword: &str,
    tokens: impl Iterator<Item = &'a str>,
    defined: usize,
) -> Result<Vec<usize>, ParseError> {
    let indices = tokens
        .map(|token| corner(text, token, defined))
        .collect::<Result<Vec<usize>, ParseError>>()?;
    if indices.len() < 3 {
        return Err(at(
            text,
            keyword,
            format!("a face needs at least 3 vertices, found {}", indices.len()),
        ));
    }
    Ok(indices)
}

/// The forms of a face corner, for errors.
const CORNER_FORMS: &str = "expected `i`, `i/j`, `i/j/k` or `i//k`";

/// The 0-based vertex index of one face corner `token` (`i`, `i/j`, `i/j/k` or `i//k`).
fn corner(text: &str, token: &str, defined: usize) -> Result<usize, ParseError> {
    if token.bytes().all(|c| c.is_ascii_digit()) {
        return vertex_index(text, token, token, defined);
    }
    let (parts, count) = first_of::<4>(token.split('/'));
    let optional = match (count, &parts) {
        (1, _) => &[][..],
        (2, [_, j, ..]) => &[*j][..],
        (3, [_, "", k, _]) => &[*k][..],
        (3, [_, j, k, _]) => &[*j, *k][..],
        _ => {
            let extra = parts[3];
            return Err(at(
                text,
                extra,
                format!("`{token}`: too many `/`, {CORNER_FORMS}"),
            ));
        }
    };
    for &part in optional {
        match integer(part) {
            Some(Some(0)) => {
                return Err(at(
                    text,
                    part,
                    format!("`{token}`: index 0 (OBJ is 1-based)"),
                ))
            }
            Some(_) => {}
            None => {
                return Err(at(
                    text,
                    part,
                    format!("`{token}`: `{part}` is not an index, {CORNER_FORMS}"),
                ))
            }
        }
    }
    vertex_index(text, token, parts[0], defined)
}

/// The 0-based index of the vertex that `i`, the first part of the face corner `token`,
/// names: 1-based, or counted back from the last of the `defined` vertices if negative.
fn vertex_index(text: &str, token: &str, i: &str, defined: usize) -> Result<usize, ParseError> {
    let range = || {
        format!(
            "`{token}`: vertex index {i} is out of range, {defined} vertices are defined so far"
        )
    };
    match integer(i) {
        None => Err(at(
            text,
            i,
            format!("`{token}`: `{i}` is not a vertex index, {CORNER_FORMS}"),
        )),
        Some(Some(0)) => Err(at(
            text,
            i,
            format!("`{token}`: vertex index 0 (OBJ is 1-based)"),
        )),
        Some(Some(v)) if v > 0 => match usize::try_from(v) {
            Ok(v) if v <= defined => Ok(v - 1),
            _ => Err(at(text, i, range())),
        },
        Some(Some(v)) => match usize::try_from(v.unsigned_abs()) {
            Ok(back) if back <= defined => Ok(defined - back),
            _ => Err(at(text, i, range())),
        },
        Some(None) => Err(at(text, i, range())),
    }
}

/// An optional `-` and decimal digits: `Some(Some(value))`, `Some(None)` if it overflows
/// `i64` (syntactically an index, but out of every range), `None` if it is not an integer.
fn integer(s: &str) -> Option<Option<i64>> {
    let (negative, digits) = match s.strip_prefix('-') {
        Some(digits) => (true, digits),
        None => (false, s),
    };
    if digits.is_empty() {
        return None;
    }
    // The magnitude, `None` once it passes every i64's.
    let mut magnitude = Some(0u64);
    for c in digits.bytes() {
        if !c.is_ascii_digit() {
            return None;
        }
        magnitude = magnitude.and_then(|m| m.checked_mul(10)?.checked_add((c - b'0') as u64));
    }
    Some(magnitude.and_then(|m| match negative {
        true => 0i64.checked_sub_unsigned(m),
        false => i64::try_from(m).ok(),
    }))
}

/// The triangle groups of a 3D set's OBJ text: one object `surface_K_positive` or
/// `surface_K_negative` per glued surface (seed 003 Def. 7.1), its triangles' normals out of
/// the set.
pub fn surface_groups<N: Num>(set: &YinSet3<N>) -> Vec<(String, Vec<[usize; 3]>)> {
    (set.surfaces().iter().enumerate())
        .map(|(k, s)| {
            let sign = if s.positive { "positive" } else { "negative" };
            let triangles = s.triangles.iter().map(|&t| set.triangles()[t]).collect();
            (format!("surface_{k}_{sign}"), triangles)
        })
        .collect()
}

/// The OBJ text of triangle groups: a `# yinset` header line; then, once each and renumbered
/// in the order of first use, the vertices that some triangle uses (coordinates exact: a
/// decimal when the expansion terminates, `p/q` otherwise — this crate's extension, read back
/// by [`read_obj`] but not by other OBJ tools); then for each group with triangles an `o NAME`
/// line (line breaks in the name replaced by spaces) followed by its faces `f a b c`, 1-based.
///
/// # Panics
/// If a triangle index is out of range of `vertices`.
pub fn write_obj<N: Num>(vertices: &[Point3<N>], groups: &[(String, Vec<[usize; 3]>)]) -> String {
    let (kept, triangles) = used(vertices, groups.iter().flat_map(|(_, ts)| ts));
    let mut out = String::with_capacity(text_size(kept.len(), triangles.len()));
    out.push_str("# yinset\n");
    for p in kept {
        out.push_str("v ");
        push_coords(&mut out, p);
        out.push('\n');
    }
    let mut triangles = triangles.into_iter();
    for (name, group) in groups.iter().filter(|(_, g)| !g.is_empty()) {
        let _ = writeln!(out, "o {}", name.replace(['\r', '\n'], " "));
        for t in triangles.by_ref().take(group.len()) {
            push_triangle(&mut out, "f", t.map(|i| i + 1));
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::io::testdata;
    use crate::num::{Float, Rational};

    fn q(s: &str) -> Rational {
        Rational::parse(s).unwrap()
    }

    fn read(text: &str) -> Result<Mesh<Rational>, ParseError> {
        read_obj(text)
    }

    /// `(line, column)` of the error reading `text`, and its message.
    fn error(text: &str) -> (usize, usize, String) {
        let e = read(text).unwrap_err();
        (e.line, e.column, e.message)
    }

    /// `(line, column)` of the error reading `text`.
    fn place(text: &str) -> (usize, usize) {
        let (line, column, _) = error(text);
        (line, column)
    }

    const SQUARE: &str = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n";

    proptest::proptest! {
        /// A line's tokens are those of `str::split_whitespace`: on ASCII lines with every
        /// ASCII blank (vertical tab and form feed too), and on lines with Unicode blanks.
        #[test]
        fn tokens_split_like_split_whitespace(
            line in proptest::prop_oneof![
                "[ \t\n\x0B\x0C\rav1/#-]{0,40}",
                "[ \t\x0B\r\u{85}\u{a0}\u{2003}\u{3000}av1é]{0,40}",
            ],
        ) {
            let want: Vec<&str> = line.split_whitespace().collect();
            proptest::prop_assert_eq!(Tokens::of(&line).collect::<Vec<_>>(), want);
        }
    }

    #[test]
    fn reads_exact_decimals_and_fractions() {
        let mesh = read("v 0.1 -4.5040114e+00 1/3\nv 1 2 3 1\nv 1 2 3 1.0\n").unwrap();
        assert_eq!(
            mesh.vertices[0],
            Point3::new(q("1/10"), q("-45040114/10000000"), q("1/3"))
        );
        assert_ne!(mesh.vertices[0].x, Rational::from_f64(0.1).unwrap());
        assert_eq!(mesh.vertices[1], Point3::int(1, 2, 3));
        assert_eq!(mesh.vertices[2], Point3::int(1, 2, 3));
        assert!(mesh.faces.is_empty() && mesh.face_lines.is_empty());
    }

    proptest::proptest! {
        /// Every `i64` written in decimal reads back as itself.
        #[test]
        fn integers_read_back(v in proptest::prelude::any::<i64>()) {
            proptest::prop_assert_eq!(integer(&v.to_string()), Some(Some(v)));
        }
    }

    /// Integers just past `i64`'s range are indices out of every range; other text is none.
    #[test]
    fn integers_past_i64_or_malformed() {
        let cases = [
            ("9223372036854775807", Some(Some(i64::MAX))),
            ("9223372036854775808", Some(None)),
            ("-9223372036854775808", Some(Some(i64::MIN))),
            ("-9223372036854775809", Some(None)),
            ("99999999999999999999999", Some(None)),
            ("-0", Some(Some(0))),
            ("", None),
            ("-", None),
            ("+1", None),
            ("1a", None),
            ("1/2", None),
        ];
        for (text, want) in cases {
            assert_eq!(integer(text), want, "{text:?}");
        }
    }

    #[test]
    fn reads_every_index_form() {
        let faces = [
            "f 1 2 3",
            "f 1/1 2/2 3/3",
            "f 1/1/1 2/2/2 3/3/3",
            "f 1//1 2//2 3//3",
            "f 1 2/5 3//-1",
        ];
        let text = format!("{SQUARE}{}\n", faces.join("\n"));
        let mesh = read(&text).unwrap();
        assert_eq!(mesh.faces, vec![vec![0, 1, 2]; 5]);
        assert_eq!(mesh.face_lines, vec![5, 6, 7, 8, 9]);
    }

    #[test]
    fn negative_indices_count_back_from_vertices_so_far() {
        let text = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf -3 -2 -1\nv 0 0 1\nf -1 -3 -4\nf 4 -2 1\n";
        let mesh = read(text).unwrap();
        assert_eq!(
            mesh.faces,
            vec![vec![0, 1, 2], vec![3, 1, 0], vec![3, 2, 0]]
        );
        assert_eq!(mesh.face_lines, vec![4, 6, 7]);
    }

    #[test]
    fn n_gons_stay_n_gons() {
        let text = format!("{SQUARE}v 2 2 2\nf 1 2 3 4\nf 1 2 3 4 5\nf 1 2 3\n");
        let mesh = read(&text).unwrap();
        assert_eq!(
            mesh.faces,
            vec![vec![0, 1, 2, 3], vec![0, 1, 2, 3, 4], vec![0, 1, 2]]
        );
    }

    #[test]
    fn ignores_other_lines_comments_and_crlf() {
        let text = concat!(
            "# header\r\nmtllib a.mtl\r\no Cube\r\ng group\r\nv 0 0 0 # origin\r\n",
            "  v\t1 0 0\r\nvt 0.5 0.5\r\nvn 0 0 1\r\nvp 0.1\r\n\r\nv 0 1 0\r\ns off\r\n",
            "usemtl m\r\nl 1 2\r\np 1\r\nf 1/1/1 2/1/1 3/1/1 # tri\r\n#f 1 2\r\n",
        );
        let mesh = read(text).unwrap();
        assert_eq!(mesh.vertices.len(), 3);
        assert_eq!(mesh.vertices[1], Point3::int(1, 0, 0));
        assert_eq!(mesh.faces, vec![vec![0, 1, 2]]);
        assert_eq!(mesh.face_lines, vec![16]);
    }

    #[test]
    fn bad_number_is_named_at_its_place() {
        let (line, column, message) = error("v 0 0 0\nv 1 x 0\n");
        assert_eq!((line, column), (2, 5));
        assert!(message.contains("`x` is not a number"), "{message}");
        let (line, column, _) = error("v 0 0 0\n v 1 2 3 \\\n4\n");
        assert_eq!(
            (line, column),
            (2, 10),
            "continuation lines are not supported"
        );
        let e = read("v 1/0 0 0").unwrap_err();
        assert!(e.message.contains("zero denominator"), "{e}");
    }

    #[test]
    fn vertex_needs_three_coordinates_and_unit_weight() {
        let (line, column, message) = error("v 0 0 0\nv 1 2\n");
        assert_eq!((line, column), (2, 6));
        assert!(message.contains("found only 2 number(s)"), "{message}");
        assert_eq!(place("v"), (1, 2));
        let (line, column, message) = error("v 0 0 0\nv 1 2 3 2\n");
        assert_eq!((line, column), (2, 9));
        assert!(message.contains("weight `2`"), "{message}");
        assert_eq!(place("v 1 2 3 0.5"), (1, 9));
        assert_eq!(place("v 1 2 3 1 1"), (1, 11));
        let (_, _, message) = error("v 1 2 3 1 0 0");
        assert!(message.contains("found 6 numbers"), "{message}");
    }

    #[test]
    fn index_zero_is_an_error() {
        let (line, column, message) = error(&format!("{SQUARE}f 1 0 2\n"));
        assert_eq!((line, column), (5, 5));
        assert!(message.contains("vertex index 0"), "{message}");
        let (line, column, _) = error(&format!("{SQUARE}f 1 2 -0\n"));
        assert_eq!((line, column), (5, 7));
        let (line, column, message) = error(&format!("{SQUARE}f 1 2/0 3\n"));
        assert_eq!((line, column), (5, 7));
        assert!(message.contains("index 0"), "{message}");
    }

    #[test]
    fn out_of_range_index_is_an_error() {
        let (line, column, message) = error(&format!("{SQUARE}f 1 2 5\n"));
        assert_eq!((line, column), (5, 7));
        assert!(
            message.contains("vertex index 5 is out of range, 4 vertices are defined so far"),
            "{message}"
        );
        // Forward references are rejected: the vertex comes after its face.
        let (line, column, _) = error("v 0 0 0\nv 1 0 0\nf 1 2 3\nv 0 1 0\n");
        assert_eq!((line, column), (3, 7));
        let (line, column, _) = error(&format!("{SQUARE}f -5 1 2\n"));
        assert_eq!((line, column), (5, 3));
        for huge in ["99999999999999999999999", "-99999999999999999999999"] {
            let (line, column, message) = error(&format!("{SQUARE}f 1 2 {huge}/1\n"));
            assert_eq!((line, column), (5, 7));
            assert!(message.contains("out of range"), "{message}");
        }
    }

    #[test]
    fn malformed_index_is_an_error() {
        for (face, column) in [
            ("f 1 2 x", 7),
            ("f 1 2 3.0", 7),
            ("f 1 2 +3", 7),
            ("f 1 2 /3", 7),
            ("f 1 2 3/", 9),
            ("f 1 2 3//", 10),
            ("f 1 2 3/x/1", 9),
            ("f 1 2 3/1/1/1", 13),
            ("f 1 2 3 \\", 9),
        ] {
            let (line, col, message) = error(&format!("{SQUARE}{face}\n"));
            assert_eq!((line, col), (5, column), "{face}: {message}");
        }
    }

    #[test]
    fn face_needs_three_vertices() {
        let (line, column, message) = error(&format!("{SQUARE}v 1 1 1\n  f 1 2\n"));
        assert_eq!((line, column), (6, 3));
        assert_eq!(message, "a face needs at least 3 vertices, found 2");
        assert_eq!(place("f"), (1, 1));
    }

    #[test]
    fn adversarial_inputs_never_panic() {
        assert_eq!(read("").unwrap().vertices.len(), 0);
        for text in ["\n\r\n\t", "#", "#v 1", "\u{feff}"] {
            let mesh = read(text).unwrap();
            assert!(mesh.vertices.is_empty() && mesh.faces.is_empty(), "{text}");
        }
        // Without `v` or `f` lines, any other line is not OBJ: an error at it.
        for text in ["\\", "vv 1 2 3", "F 1 2 3", "é v 1", "# c\no cube"] {
            let e = read(text).unwrap_err();
            assert!(
                e.message.contains("no vertex (`v`) or face (`f`) lines"),
                "{text}: {e}"
            );
        }
        assert_eq!(read("# c\n\n  o cube").unwrap_err().column, 3);
        for bad in [
            "v 1e99999999 0 0",
            "v NaN 0 0",
            "v 0 inf 0",
            "v é ü ö",
            "v 0,0 1 2",
            "f 1 2 3",
            "f é 1 2",
            "f ///",
            "f -",
            "v 1 2 3 é",
            "v#",
            "f#",
        ] {
            assert_eq!(read(bad).unwrap_err().line, 1, "{bad}");
        }
        assert_eq!(read("v é 1 2 3").unwrap_err().column, 3);
        assert_eq!(read("v 1 2 3 é").unwrap_err().column, 9);
        let e = read_obj::<Float>("v 1e400 0 0").unwrap_err();
        assert!(e.message.contains("out of range"), "{e}");
    }

    #[test]
    fn write_then_read_round_trips_points_and_triangles() {
        let vertices = vec![
            Point3::new(q("1/3"), q("-2/7"), q("0.1")),
            Point3::int(9, 9, 9), // unused: not written
            Point3::new(q("1e30"), q("-5"), q("1/1000000007")),
            Point3::int(0, 0, 1),
            Point3::new(q("-1/1024"), q("0"), q("7/8")),
        ];
        let groups = vec![
            ("first".to_string(), vec![[2, 0, 3], [3, 0, 4]]),
            ("second\nname".to_string(), vec![[4, 0, 2]]),
            ("empty".to_string(), vec![]),
        ];
        let text = write_obj(&vertices, &groups);
        assert!(
            text.starts_with(&format!(
                concat!(
                    "# yinset\nv 1{} -5 1/1000000007\nv 1/3 -2/7 0.1\nv 0 0 1\n",
                    "v -0.0009765625 0 0.875\no first\nf 1 2 3\nf 3 2 4\no second name\n",
                    "f 4 2 1\n",
                ),
                "0".repeat(30)
            )),
            "{text}"
        );
        let mesh = read(&text).unwrap();
        assert_eq!(mesh.vertices.len(), 4);
        let points = |faces: Vec<Vec<usize>>, of: &[Point3<Rational>]| -> Vec<Vec<_>> {
            faces
                .into_iter()
                .map(|f| f.into_iter().map(|i| of[i].clone()).collect())
                .collect()
        };
        let written: Vec<Vec<usize>> = groups
            .iter()
            .flat_map(|(_, ts)| ts.iter().map(|t| t.to_vec()))
            .collect();
        assert_eq!(
            points(mesh.faces, &mesh.vertices),
            points(written, &vertices)
        );
        assert_eq!(mesh.face_lines, vec![7, 8, 10]);
        assert!(
            text.ends_with("f 4 2 1\n"),
            "no object without triangles: {text}"
        );
        // No triangles at all: only the header comment, which reads back as no mesh.
        let none = write_obj(&vertices, &[("empty".to_string(), vec![])]);
        assert_eq!(none, "# yinset\n");
        assert_eq!(read(&none).unwrap(), Mesh::default());
    }

    #[test]
    fn float_mode_reads_and_writes() {
        let mesh = read_obj::<Float>("v 0.1 1/4 -3\nv 1 0 0\nv 0 1 0\nf 1 2 3\n").unwrap();
        assert_eq!(
            mesh.vertices[0],
            Point3::new(Float::new(0.1), Float::new(0.25), Float::new(-3.0))
        );
        let text = write_obj(&mesh.vertices, &[("t".to_string(), vec![[0, 1, 2]])]);
        assert_eq!(
            text,
            "# yinset\nv 0.1 0.25 -3\nv 1 0 0\nv 0 1 0\no t\nf 1 2 3\n"
        );
        let back = read_obj::<Float>(&text).unwrap();
        assert_eq!((back.vertices, back.faces), (mesh.vertices, mesh.faces));
    }

    /// Name and text of every `.obj` file of the shared data's `3d` directory, sorted by name.
    fn data_files() -> Vec<(String, String)> {
        testdata::files("3d", ".obj")
    }

    #[test]
    fn shared_3d_meshes_have_their_listed_counts() {
        if !testdata::available() {
            return;
        }
        // Vertex and face counts as ../shared/data/README.md lists them.
        let expected = [
            ("Rabbit_Lowpoly_2.obj", 690, 1376),
            ("ballabehind.obj", 26, 48),
            ("ballahead.obj", 26, 48),
            ("ballconnecttorus.obj", 1597, 3194),
            ("ballleft.obj", 122, 240),
            ("ballmid.obj", 722, 1440),
            ("ballright.obj", 122, 240),
            ("heart.obj", 170, 336),
            ("innerball.obj", 26, 48),
            ("teddy.obj", 1598, 3192),
            ("torus.obj", 256, 512),
            ("torusbig.obj", 8192, 16384),
        ];
        let files = data_files();
        for (name, vertices, faces) in expected {
            let (_, text) = files
                .iter()
                .find(|(n, _)| n == name)
                .unwrap_or_else(|| panic!("{name} missing from the shared 3d data"));
            let mesh = read(text).unwrap_or_else(|e| panic!("{name}: {e}"));
            assert_eq!(
                (mesh.vertices.len(), mesh.faces.len()),
                (vertices, faces),
                "{name}"
            );
        }
        // Every file of the directory, listed or not, reads; every vertex is used by a face.
        for (name, text) in &files {
            let mesh = read(text).unwrap_or_else(|e| panic!("{name}: {e}"));
            assert_eq!(mesh.faces.len(), mesh.face_lines.len(), "{name}");
            assert!(mesh.faces.iter().all(|f| f.len() >= 3), "{name}");
            let used: std::collections::BTreeSet<_> = mesh.faces.iter().flatten().collect();
            assert_eq!(used.len(), mesh.vertices.len(), "{name}");
        }
    }

    #[test]
    fn shared_rabbit_and_heart_face_forms() {
        if !testdata::available() {
            return;
        }
        let files = data_files();
        let text = |name: &str| {
            &files
                .iter()
                .find(|(n, _)| n == name)
                .unwrap_or_else(|| panic!("{name} missing from the shared 3d data"))
                .1
        };
        // The rabbit's faces are `i//k` triangles (no n-gons in this file, despite the README's
        // "faces may be n-gons"): every f line has exactly 3 corners, kept as triangles.
        let rabbit = text("Rabbit_Lowpoly_2.obj");
        let mesh = read(rabbit).unwrap();
        let corners: Vec<usize> = rabbit
            .lines()
            .filter(|l| l.starts_with("f "))
            .map(|l| l.split_whitespace().count() - 1)
            .collect();
        assert_eq!(corners, mesh.faces.iter().map(Vec::len).collect::<Vec<_>>());
        assert!(mesh.faces.iter().all(|f| f.len() == 3));
        assert_eq!(mesh.faces[0], vec![0, 108, 295]);
        assert_eq!(
            mesh.vertices[0],
            Point3::new(q("-1.816698"), q("0.346248"), q("-0.291936"))
        );
        // The heart's faces are `i/j/k`.
        let mesh = read(text("heart.obj")).unwrap();
        assert_eq!(mesh.faces[0], vec![82, 1, 2]);
        // Float mode reads the same counts.
        let mesh = read_obj::<Float>(text("torus.obj")).unwrap();
        assert_eq!((mesh.vertices.len(), mesh.faces.len()), (256, 512));
        assert_eq!(mesh.vertices[1].x, Float::new(2.707107));
    }
}
