//! STL (stereolithography) triangle meshes, ASCII and binary, read exactly.
//!
//! ```text
//! solid tetrahedron
//!   facet normal 0 0 -1
//!     outer loop
//!       vertex 0 0 0
//!       vertex 0 1 0
//!       vertex 1 0 0
//!     endloop
//!   endfacet
//!   …
//! endsolid tetrahedron
//! ```
//!
//! Reading ([`read_stl`]) tells the two kinds apart by size, not by the first word (binary
//! files from some tools begin with `solid` too): a file of exactly 84 + 50·n bytes whose
//! header announces n facets is binary, anything else beginning with `solid` (after a UTF-8
//! byte-order mark, which is ignored) is ASCII. Other text is an error saying that an ASCII
//! STL begins with `solid` (and, if it has facets, that this line is what is missing).
//!
//! * **ASCII** is parsed here, not by the `stl_io` crate, which rounds coordinates to `f32`:
//!   every `vertex x y z` coordinate is read with [`Num::parse`], so `0.1` is exactly 1/10 in
//!   exact mode (fractions `p/q` are accepted too, this crate's extension). A file may hold
//!   several `solid … endsolid` blocks; their facets are read together and the solid names
//!   are not kept. A facet loop needs at least 3 vertices (more make a planar polygon).
//! * **Binary** facets are decoded by `stl_io` (its header is blanked first, so that a
//!   header beginning with `solid` is not mistaken for ASCII); their `f32` coordinates are
//!   exact rationals and are taken as such. The 80-byte header and the attribute words are
//!   not kept.
//!
//! Equal vertices of different facets are welded into one. A facet's orientation is its vertex
//! order (counterclockwise seen from outside, the right-hand rule, as the format prescribes);
//! the normal it states is checked to be three numbers but otherwise ignored. Malformed text is
//! an error with its line and column; a malformed binary file an error with its byte offset and
//! facet.
//!
//! Writing: [`write_stl_ascii`] writes coordinates exactly (a decimal when the expansion
//! terminates, `p/q` otherwise — read back by [`read_stl`] but not by other STL tools), with
//! normals rounded to `f64`; [`write_stl_binary`] writes `f32` through `stl_io` and refuses a
//! set with a coordinate that no `f32` holds exactly.

use super::decimal::exact_text;
use super::mesh::{binary_coordinate, coordinate, push_coords, used, Mesh, MeshError, Welder};
use super::{without_bom_bytes, ParseError};
use crate::kernel::Point3;
use crate::num::Num;
use std::fmt::Write;
use std::io::Cursor;

/// Bytes of a binary STL's header and facet count.
const HEADER: usize = 84;
/// Bytes of one binary STL facet: normal, three vertices (12 `f32`), attribute word.
const FACET: usize = 50;

/// Read an STL file, ASCII or binary (see the [module documentation](self)).
pub fn read_stl<N: Num>(bytes: &[u8]) -> Result<Mesh<N>, MeshError> {
    let announced = announced_facets(bytes);
    if announced.is_some_and(|n| HEADER as u64 + FACET as u64 * n == bytes.len() as u64) {
        return read_binary(bytes);
    }
    let bytes = without_bom_bytes(bytes);
    let ascii = bytes.trim_ascii_start().starts_with(b"solid");
    match (ascii, announced) {
        (false, _) if is_text(bytes) => Err(not_ascii_stl(bytes).into()),
        (true, _) => {
            let text = std::str::from_utf8(bytes).map_err(|e| MeshError::Binary {
                offset: e.valid_up_to(),
                message: "an ASCII STL file (it begins with `solid`) holds a byte that is not \
                          UTF-8 text, and its size is not that of a binary STL"
                    .to_string(),
            })?;
            Ok(read_ascii(text)?)
        }
        (false, None) => Err(MeshError::Binary {
            offset: bytes.len(),
            message: format!(
                "a binary STL file needs an 80-byte header and a facet count ({HEADER} bytes), \
                 this one ends after {} bytes",
                bytes.len()
            ),
        }),
        (false, Some(n)) => Err(size_mismatch(bytes.len(), n)),
    }
}

/// True if `bytes` are UTF-8 text without control characters but tabs and line ends (a binary
/// STL's facet count and coordinates hold other bytes).
fn is_text(bytes: &[u8]) -> bool {
    std::str::from_utf8(bytes).is_ok()
        && bytes
            .iter()
            .all(|&b| b >= b' ' || matches!(b, b'\t' | b'\n' | b'\r'))
}

/// The error of a text (`bytes`, UTF-8) that does not begin with `solid`: what it begins with,
/// and whether it has the facets of an ASCII STL without its `solid` line.
fn not_ascii_stl(bytes: &[u8]) -> ParseError {
    let text = std::str::from_utf8(bytes).unwrap_or_default();
    let Some(first) = text.split_whitespace().next() else {
        return ParseError::at(
            text,
            text.len(),
            "the file is empty: an STL file holds a solid",
        );
    };
    let facets = text.split_whitespace().any(|t| t == "facet");
    let advice = if facets {
        "; this text has facets: begin it with a line `solid NAME`"
    } else {
        ", and it is not a binary STL either (binary STL is not text)"
    };
    ParseError::at_token(
        text,
        first,
        format!("an ASCII STL file begins with `solid`, this one with `{first}`{advice}"),
    )
}

/// The facet count a binary header announces, if the file is long enough to have one.
fn announced_facets(bytes: &[u8]) -> Option<u64> {
    let count: [u8; 4] = bytes.get(80..HEADER)?.try_into().ok()?;
    Some(u64::from(u32::from_le_bytes(count)))
}

/// The error of a binary STL of `len` bytes whose header announces `n` facets.
fn size_mismatch(len: usize, n: u64) -> MeshError {
    let whole = (len - HEADER) / FACET;
    let expected = HEADER as u64 + FACET as u64 * n;
    if (len as u64) < expected {
        MeshError::Binary {
            offset: len,
            message: format!(
                "truncated binary STL: the header announces {n} facets ({expected} bytes), \
                 the file ends after {len} bytes, inside facet {whole} (counting from 0)"
            ),
        }
    } else {
        MeshError::Binary {
            offset: expected as usize,
            message: format!(
                "the binary STL header announces {n} facets ({expected} bytes), \
                 but {} more bytes follow them",
                len as u64 - expected
            ),
        }
    }
}

/// The facets of a binary STL whose size matches its facet count.
fn read_binary<N: Num>(bytes: &[u8]) -> Result<Mesh<N>, MeshError> {
    let mut blanked = bytes.to_vec();
    blanked[..80].fill(0);
    let mut cursor = Cursor::new(blanked);
    let facets = stl_io::create_stl_reader(&mut cursor).map_err(|e| MeshError::Binary {
        offset: 0,
        message: format!("cannot read the binary STL header: {e}"),
    })?;
    let mut welder = Welder::new();
    let mut faces = Vec::new();
    for (k, facet) in facets.enumerate() {
        let start = HEADER + FACET * k;
        let facet = facet.map_err(|e| MeshError::Binary {
            offset: start,
            message: format!("facet {k} (counting from 0): {e}"),
        })?;
        let mut face = Vec::with_capacity(3);
        for (j, vertex) in facet.vertices.iter().enumerate() {
            let mut c = [N::zero(), N::zero(), N::zero()];
            for (i, value) in vertex.0.iter().enumerate() {
                let offset = start + 12 * (j + 1) + 4 * i;
                let what = format!("facet {k} (counting from 0), vertex {j}");
                c[i] = binary_coordinate(f64::from(*value), offset, &what)?;
            }
            let [x, y, z] = c;
            face.push(welder.weld(Point3::new(x, y, z)));
        }
        faces.push(face);
    }
    Ok(Mesh {
        vertices: welder.vertices,
        faces,
        face_lines: Vec::new(),
    })
}

/// The tokens of `text` with their 1-based line numbers.
fn tokens(text: &str) -> Vec<(&str, usize)> {
    text.split('\n')
        .enumerate()
        .flat_map(|(k, line)| line.split_whitespace().map(move |t| (t, k + 1)))
        .collect()
}

/// The facets of an ASCII STL text.
fn read_ascii<N: Num>(text: &str) -> Result<Mesh<N>, ParseError> {
    let tokens = tokens(text);
    let mut at = 0;
    let end = &text[text.len()..];
    // The token at `at` and its line, or an error saying the file ended where `wanted` was due.
    let next = |at: &mut usize, wanted: &str| -> Result<(&str, usize), ParseError> {
        let t = tokens.get(*at).copied().ok_or_else(|| {
            ParseError::at_token(text, end, format!("the file ends where {wanted} is due"))
        })?;
        *at += 1;
        Ok(t)
    };
    let expect = |at: &mut usize, keyword: &str| -> Result<(), ParseError> {
        let (t, _) = next(at, &format!("`{keyword}`"))?;
        if t == keyword {
            Ok(())
        } else {
            let message = format!("expected `{keyword}`, found `{t}`");
            Err(ParseError::at_token(text, t, message))
        }
    };
    // Skip a solid's name: the rest of the line of token `at - 1`, up to a keyword that may
    // follow on the same line (`facet`, `endsolid`, `solid`).
    let skip_line = |at: &mut usize| {
        let line = tokens[*at - 1].1;
        while tokens
            .get(*at)
            .is_some_and(|t| t.1 == line && !matches!(t.0, "facet" | "endsolid" | "solid"))
        {
            *at += 1;
        }
    };
    let mut welder = Welder::new();
    let mut mesh = Mesh::default();
    while at < tokens.len() {
        expect(&mut at, "solid")?;
        skip_line(&mut at);
        loop {
            let (t, line) = next(&mut at, "`facet` or `endsolid`")?;
            match t {
                "endsolid" => {
                    skip_line(&mut at);
                    break;
                }
                "facet" => {}
                _ => {
                    let message = format!("expected `facet` or `endsolid`, found `{t}`");
                    return Err(ParseError::at_token(text, t, message));
                }
            }
            expect(&mut at, "normal")?;
            for _ in 0..3 {
                let (n, _) = next(&mut at, "a normal coordinate")?;
                coordinate::<N>(text, n)?;
            }
            expect(&mut at, "outer")?;
            expect(&mut at, "loop")?;
            let mut face = Vec::new();
            while tokens.get(at).is_some_and(|t| t.0 == "vertex") {
                at += 1;
                let mut c = [N::zero(), N::zero(), N::zero()];
                for x in &mut c {
                    *x = coordinate(text, next(&mut at, "a vertex coordinate")?.0)?;
                }
                let [x, y, z] = c;
                face.push(welder.weld(Point3::new(x, y, z)));
            }
            if face.len() < 3 {
                let (t, _) = next(&mut at, "`endloop`")?;
                let message = format!(
                    "a facet needs at least 3 vertices, found {} before `{t}`",
                    face.len()
                );
                return Err(ParseError::at_token(text, t, message));
            }
            expect(&mut at, "endloop")?;
            expect(&mut at, "endfacet")?;
            mesh.faces.push(face);
            mesh.face_lines.push(line);
        }
    }
    mesh.vertices = welder.vertices;
    Ok(mesh)
}

/// The unit normal of triangle `t` by the right-hand rule, rounded to `f64` (zero if
/// degenerate): what STL files state beside their vertices.
fn normal<N: Num>(t: [&Point3<N>; 3]) -> [f64; 3] {
    let [a, b, c] = t.map(Point3::to_f64);
    let u = [b[0] - a[0], b[1] - a[1], b[2] - a[2]];
    let v = [c[0] - a[0], c[1] - a[1], c[2] - a[2]];
    let n = [
        u[1] * v[2] - u[2] * v[1],
        u[2] * v[0] - u[0] * v[2],
        u[0] * v[1] - u[1] * v[0],
    ];
    let len = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt();
    if len > 0.0 && len.is_finite() {
        n.map(|x| x / len)
    } else {
        [0.0; 3]
    }
}

/// The ASCII STL text of `triangles` (indices into `vertices`, counterclockwise seen from
/// outside), coordinates exact, in one solid named `yinset`.
///
/// # Panics
/// If a triangle index is out of range of `vertices`.
pub fn write_stl_ascii<N: Num>(vertices: &[Point3<N>], triangles: &[[usize; 3]]) -> String {
    let mut out = String::from("solid yinset\n");
    for t in triangles {
        let corners = t.map(|i| &vertices[i]);
        let [nx, ny, nz] = normal(corners);
        let _ = writeln!(out, "  facet normal {nx:e} {ny:e} {nz:e}\n    outer loop");
        for p in corners {
            out.push_str("      vertex ");
            push_coords(&mut out, p);
            out.push('\n');
        }
        out.push_str("    endloop\n  endfacet\n");
    }
    out.push_str("endsolid yinset\n");
    out
}

/// A coordinate that binary STL cannot hold.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("binary STL holds 32-bit floats, and the coordinate {coordinate} of vertex {vertex} is not one: write ASCII STL, which is exact")]
pub struct NotF32 {
    /// The coordinate, exactly (a decimal where one is exact).
    pub coordinate: String,
    /// The vertex, exactly (decimals where exact).
    pub vertex: String,
}

/// The binary STL bytes of `triangles` (indices into `vertices`), written by `stl_io`; an
/// error if a coordinate is not exactly an `f32`.
///
/// # Panics
/// If a triangle index is out of range of `vertices`.
pub fn write_stl_binary<N: Num>(
    vertices: &[Point3<N>],
    triangles: &[[usize; 3]],
) -> Result<Vec<u8>, NotF32> {
    let (kept, renumbered) = used(vertices, triangles);
    let exact = kept
        .iter()
        .map(|p| {
            let mut c = [0f32; 3];
            for (x, n) in c.iter_mut().zip(p.coords()) {
                *x = n.to_f64() as f32;
                if N::from_f64(f64::from(*x)).ok().as_ref() != Some(n) {
                    let [x, y, z] = p.coords().map(exact_text);
                    return Err(NotF32 {
                        coordinate: exact_text(n),
                        vertex: format!("({x}, {y}, {z})"),
                    });
                }
            }
            Ok(stl_io::Vertex::new(c))
        })
        .collect::<Result<Vec<_>, _>>()?;
    let facets: Vec<stl_io::Triangle> = renumbered
        .iter()
        .map(|t| stl_io::Triangle {
            normal: stl_io::Normal::new(normal(t.map(|i| kept[i])).map(|x| x as f32)),
            vertices: t.map(|i| exact[i]),
        })
        .collect();
    let mut bytes = Vec::new();
    // Writing to a vector cannot fail.
    let _ = stl_io::write_stl(&mut bytes, facets.iter());
    Ok(bytes)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::num::Rational;

    fn q(s: &str) -> Rational {
        Rational::parse(s).unwrap()
    }

    const TETRA: &str = "solid t\n facet normal 0 0 -1\n  outer loop\n   vertex 0 0 0\n   \
        vertex 0 1 0\n   vertex 0.1 0 0\n  endloop\n endfacet\n facet normal 0 0 0\n  outer loop\n   \
        vertex 0 0 0\n   vertex 0.1 0 0\n   vertex 0 0 1/3\n  endloop\n endfacet\nendsolid t\n";

    #[test]
    fn ascii_coordinates_are_exact_and_vertices_welded() {
        let mesh = read_stl::<Rational>(TETRA.as_bytes()).unwrap();
        assert_eq!(mesh.vertices.len(), 4);
        assert_eq!(mesh.vertices[2], Point3::new(q("1/10"), q("0"), q("0")));
        assert_eq!(mesh.vertices[3], Point3::new(q("0"), q("0"), q("1/3")));
        assert_eq!(mesh.faces, vec![vec![0, 1, 2], vec![0, 2, 3]]);
        assert_eq!(mesh.face_lines, vec![2, 9]);
    }

    /// `(line, column, message)` of the error reading `text`.
    fn error(text: &str) -> (usize, usize, String) {
        crate::io::mesh::text_error(read_stl::<Rational>(text.as_bytes()))
    }

    /// The corners of the unit right triangle in the xy plane.
    fn unit_triangle() -> Vec<Point3<Rational>> {
        vec![
            Point3::int(0, 0, 0),
            Point3::int(1, 0, 0),
            Point3::int(0, 1, 0),
        ]
    }

    #[test]
    fn ascii_on_one_line_keeps_every_facet() {
        let one_line = TETRA.replace('\n', " ").replace("solid t", "solid my part");
        let mesh = read_stl::<Rational>(one_line.as_bytes()).unwrap();
        assert_eq!(mesh.faces.len(), 2);
        assert_eq!(mesh.face_lines, vec![1, 1]);
    }

    #[test]
    fn ascii_errors_name_line_and_column() {
        let bad = TETRA.replace("vertex 0 1 0", "vertex 0 one 0");
        let (line, column, message) = error(&bad);
        assert_eq!((line, column), (5, 13), "{message}");
        assert!(message.contains("`one` is not a number"), "{message}");
        let (line, _, message) = error(&TETRA.replace("endloop\n endfacet\nendsolid", "endsolid"));
        assert_eq!(line, 14);
        assert_eq!(message, "expected `endloop`, found `endsolid`");
        let two = TETRA.replacen("   vertex 0 0 0\n", "", 1);
        let (line, _, message) = error(&two);
        assert_eq!(line, 6);
        assert_eq!(
            message,
            "a facet needs at least 3 vertices, found 2 before `endloop`"
        );
        let (line, _, message) = error(&TETRA[..TETRA.len() - 11]);
        assert_eq!(line, 16);
        assert_eq!(message, "the file ends where `facet` or `endsolid` is due");
        assert!(error("solid x\n facet normal 0 0 x\n").2.contains("`x`"));
    }

    #[test]
    fn binary_round_trips_f32_coordinates_and_refuses_others() {
        let v = vec![
            Point3::new(q("0.25"), q("-3"), q("1e5")),
            Point3::int(1, 0, 0),
            Point3::int(0, 1, 0),
            Point3::int(7, 7, 7), // unused
        ];
        let bytes = write_stl_binary(&v, &[[0, 1, 2], [2, 1, 0]]).unwrap();
        assert_eq!(bytes.len(), HEADER + 2 * FACET);
        let mesh = read_stl::<Rational>(&bytes).unwrap();
        assert_eq!(mesh.faces, vec![vec![0, 1, 2], vec![2, 1, 0]]);
        assert_eq!(mesh.vertices[..3], v[..3]);
        assert!(mesh.face_lines.is_empty());
        for (x, shown) in [
            ("1/3", "1/3"),
            ("1e20", "100000000000000000000"),
            ("0.1", "0.1"),
        ] {
            let mut w = v.clone();
            w[1].x = q(x);
            let e = write_stl_binary(&w, &[[0, 1, 2]]).unwrap_err();
            assert_eq!(e.coordinate, shown);
        }
    }

    #[test]
    fn binary_with_a_solid_header_is_binary() {
        let v = unit_triangle();
        let mut bytes = write_stl_binary::<Rational>(&v, &[[0, 1, 2]]).unwrap();
        bytes[..6].copy_from_slice(b"solid ");
        let mesh = read_stl::<Rational>(&bytes).unwrap();
        assert_eq!(mesh.vertices, v);
    }

    #[test]
    fn truncated_or_padded_binary_names_the_facet() {
        let v = unit_triangle();
        let bytes = write_stl_binary::<Rational>(&v, &[[0, 1, 2], [0, 2, 1], [1, 0, 2]]).unwrap();
        let e = read_stl::<Rational>(&bytes[..HEADER + FACET + 7]).unwrap_err();
        assert_eq!(
            e.to_string(),
            "byte 141: truncated binary STL: the header announces 3 facets (234 bytes), \
             the file ends after 141 bytes, inside facet 1 (counting from 0)"
        );
        let mut padded = bytes.clone();
        padded.push(0);
        let e = read_stl::<Rational>(&padded).unwrap_err().to_string();
        assert!(e.contains("1 more bytes follow"), "{e}");
        let e = read_stl::<Rational>(&bytes[..40]).unwrap_err().to_string();
        assert!(e.contains("ends after 40 bytes"), "{e}");
        let mut nan = bytes;
        nan[HEADER + FACET + 28..HEADER + FACET + 32].copy_from_slice(&f32::NAN.to_le_bytes());
        let e = read_stl::<Rational>(&nan).unwrap_err().to_string();
        assert!(
            e.starts_with("byte 162: facet 1 (counting from 0), vertex 1: the coordinate NaN"),
            "{e}"
        );
    }

    #[test]
    fn ascii_writer_is_read_back_exactly() {
        let v = vec![
            Point3::new(q("1/3"), q("0.1"), q("-2")),
            Point3::int(1, 0, 0),
            Point3::int(0, 1, 0),
        ];
        let text = write_stl_ascii(&v, &[[0, 1, 2]]);
        assert!(text.contains("vertex 1/3 0.1 -2\n"), "{text}");
        let mesh = read_stl::<Rational>(text.as_bytes()).unwrap();
        assert_eq!((mesh.vertices, mesh.faces), (v, vec![vec![0, 1, 2]]));
    }
}
