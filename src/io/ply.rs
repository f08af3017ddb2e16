//! PLY (Stanford polygon file) meshes, ASCII and binary, read exactly; written as ASCII.
//!
//! ```text
//! ply
//! format ascii 1.0
//! element vertex 4
//! property double x
//! property double y
//! property double z
//! element face 4
//! property list uchar int vertex_indices
//! end_header
//! 0 0 0
//! …
//! 3 0 2 1
//! …
//! ```
//!
//! Parsed here rather than by the `ply-rs` crate, which is unmaintained and parses ASCII
//! numbers into `f32`/`f64`. Reading ([`read_ply`]):
//!
//! * The header (after a UTF-8 byte-order mark, which is ignored; byte offsets count from
//!   after it): `ply`, `format ascii 1.0`, `format binary_little_endian 1.0` or
//!   `format binary_big_endian 1.0`, `comment` and `obj_info` lines, and `element NAME COUNT`
//!   lines each followed by its `property TYPE NAME` or `property list COUNT_TYPE TYPE NAME`
//!   lines, up to `end_header`. Types are `char uchar short ushort int uint float double` and
//!   their sized names (`int8` … `float64`).
//! * The `vertex` element needs scalar properties `x`, `y`, `z`; the `face` element a list
//!   property `vertex_indices` (or `vertex_index`) of 0-based indices, at least 3 per face,
//!   counterclockwise seen from outside. Other properties (colours, normals, …) and other
//!   elements (`edge`, …) are read past but not kept.
//! * ASCII bodies hold one record per line; coordinates are read with [`Num::parse`], so they
//!   are exact decimals (fractions `p/q` are this crate's extension). Binary `float`/`double`
//!   coordinates are exact rationals and taken as such.
//!
//! Malformed text is a [`ParseError`] with its line and column; a malformed binary body a
//! [`MeshError::Binary`] with its byte offset and record.
//!
//! Writing ([`write_ply`]) gives ASCII triangles with coordinates exact: a decimal when the
//! expansion terminates, `p/q` otherwise (read back by [`read_ply`], not by other PLY tools).

use super::mesh::{binary_coordinate, coordinate, indexed_text, Mesh, MeshError};
use super::{without_bom_bytes, ParseError};
use crate::kernel::Point3;
use crate::num::Num;

/// A scalar type of the format.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Scalar {
    /// `char`, `int8`.
    I8,
    /// `uchar`, `uint8`.
    U8,
    /// `short`, `int16`.
    I16,
    /// `ushort`, `uint16`.
    U16,
    /// `int`, `int32`.
    I32,
    /// `uint`, `uint32`.
    U32,
    /// `float`, `float32`.
    F32,
    /// `double`, `float64`.
    F64,
}

impl Scalar {
    /// The type named `name`, if any.
    fn named(name: &str) -> Option<Scalar> {
        Some(match name {
            "char" | "int8" => Scalar::I8,
            "uchar" | "uint8" => Scalar::U8,
            "short" | "int16" => Scalar::I16,
            "ushort" | "uint16" => Scalar::U16,
            "int" | "int32" => Scalar::I32,
            "uint" | "uint32" => Scalar::U32,
            "float" | "float32" => Scalar::F32,
            "double" | "float64" => Scalar::F64,
            _ => return None,
        })
    }

    /// Bytes of a binary value.
    fn size(self) -> usize {
        match self {
            Scalar::I8 | Scalar::U8 => 1,
            Scalar::I16 | Scalar::U16 => 2,
            Scalar::I32 | Scalar::U32 | Scalar::F32 => 4,
            Scalar::F64 => 8,
        }
    }
}

/// A property: one scalar, or a list of scalars preceded by its length.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Kind {
    /// One value.
    Scalar(Scalar),
    /// A count of type `.0`, then that many values of type `.1`.
    List(Scalar, Scalar),
}

/// An element of the header: its name, record count and properties.
struct Element<'a> {
    name: &'a str,
    count: usize,
    properties: Vec<(&'a str, Kind)>,
}

/// How the body is stored.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Encoding {
    Ascii,
    Binary { big_endian: bool },
}

/// The header: encoding, elements, and the byte offset where the body begins.
struct Header<'a> {
    encoding: Encoding,
    elements: Vec<Element<'a>>,
    body: usize,
}

/// Read a PLY file (see the [module documentation](self)).
pub fn read_ply<N: Num>(bytes: &[u8]) -> Result<Mesh<N>, MeshError> {
    let bytes = without_bom_bytes(bytes);
    let header = header(bytes)?;
    let mut body: Box<dyn Body<'_> + '_> = match header.encoding {
        Encoding::Ascii => {
            let text = std::str::from_utf8(bytes).map_err(|e| MeshError::Binary {
                offset: e.valid_up_to(),
                message: "an ASCII PLY file holds a byte that is not UTF-8 text".to_string(),
            })?;
            Box::new(AsciiBody::new(text, header.body))
        }
        Encoding::Binary { big_endian } => Box::new(BinaryBody {
            bytes,
            at: header.body,
            big_endian,
        }),
    };
    let vertices = header
        .elements
        .iter()
        .find(|e| e.name == "vertex")
        .map_or(0, |e| e.count);
    let mut mesh = Mesh::default();
    for element in &header.elements {
        for k in 0..element.count {
            let record = format!("{} {k} (counting from 0)", element.name);
            let line = body.start(&record)?;
            let mut xyz: [Option<N>; 3] = [None, None, None];
            for &(name, kind) in &element.properties {
                let what = format!("{record}, property {name}");
                match kind {
                    Kind::Scalar(ty) => {
                        let n = body.number(ty, &what)?;
                        let axis = ["x", "y", "z"].iter().position(|&a| a == name);
                        if let (Some(i), "vertex") = (axis, element.name) {
                            xyz[i] = Some(n.coordinate()?);
                        }
                    }
                    Kind::List(count_type, ty) => {
                        let len = body.number(count_type, &what)?.index(&what)?;
                        let items = (0..len)
                            .map(|_| body.number(ty, &what))
                            .collect::<Result<Vec<_>, _>>()?;
                        let indices = matches!(name, "vertex_indices" | "vertex_index");
                        if element.name == "face" && indices {
                            let face = items
                                .into_iter()
                                .map(|i| i.vertex(vertices, &what))
                                .collect::<Result<Vec<_>, _>>()?;
                            if face.len() < 3 {
                                return Err(body.error(format!(
                                    "{what}: a face needs at least 3 vertices, found {}",
                                    face.len()
                                )));
                            }
                            mesh.faces.push(face);
                            mesh.face_lines.extend(line);
                        }
                    }
                }
            }
            body.finish(&record)?;
            if let [Some(x), Some(y), Some(z)] = xyz {
                mesh.vertices.push(Point3::new(x, y, z));
            }
        }
    }
    body.rest()?;
    Ok(mesh)
}

/// The header of a PLY file, checked: an error at its line and column if malformed.
fn header(bytes: &[u8]) -> Result<Header<'_>, MeshError> {
    const END: &[u8] = b"end_header";
    let end = bytes
        .windows(END.len())
        .position(|w| w == END)
        .map(|k| k + END.len())
        .ok_or_else(|| MeshError::Binary {
            offset: 0,
            message: "not a PLY file: no `end_header` line".to_string(),
        })?;
    let body = match bytes.get(end..) {
        Some([b'\r', b'\n', ..]) => end + 2,
        Some([b'\n', ..]) => end + 1,
        _ => end,
    };
    let text = std::str::from_utf8(&bytes[..end]).map_err(|e| MeshError::Binary {
        offset: e.valid_up_to(),
        message: "the PLY header holds a byte that is not UTF-8 text".to_string(),
    })?;
    let err = |token: &str, message: String| ParseError::at_token(text, token, message);
    let mut lines = text
        .split('\n')
        .map(|l| l.split_whitespace().collect::<Vec<_>>());
    if lines.next().as_deref() != Some(&["ply"][..]) {
        return Err(err(text, "a PLY file begins with the line `ply`".to_string()).into());
    }
    let mut encoding = None;
    let mut elements: Vec<Element> = Vec::new();
    for tokens in lines {
        match tokens[..] {
            [] | ["comment", ..] | ["obj_info", ..] | ["end_header"] => {}
            ["format", kind, "1.0"] => {
                encoding = Some(match kind {
                    "ascii" => Encoding::Ascii,
                    "binary_little_endian" => Encoding::Binary { big_endian: false },
                    "binary_big_endian" => Encoding::Binary { big_endian: true },
                    _ => return Err(err(kind, format!("unknown PLY format `{kind}`")).into()),
                })
            }
            ["element", name, count] => elements.push(Element {
                name,
                count: count
                    .parse()
                    .map_err(|_| err(count, format!("`{count}` is not a record count")))?,
                properties: Vec::new(),
            }),
            ["property", ..] => {
                let Some(element) = elements.last_mut() else {
                    let message = "a property before any element".to_string();
                    return Err(err(tokens[0], message).into());
                };
                element.properties.push(property(text, &tokens)?);
            }
            _ => {
                let message = format!("unexpected header line `{}`", tokens.join(" "));
                return Err(err(tokens[0], message).into());
            }
        }
    }
    let encoding = encoding.ok_or_else(|| {
        err(
            &text[text.len()..],
            "the header has no `format` line".to_string(),
        )
    })?;
    for element in &elements {
        check_element(text, element)?;
    }
    Ok(Header {
        encoding,
        elements,
        body,
    })
}

/// The property declared by a `property` line's `tokens`.
fn property<'a>(text: &str, tokens: &[&'a str]) -> Result<(&'a str, Kind), ParseError> {
    let scalar = |name: &str| {
        Scalar::named(name)
            .ok_or_else(|| ParseError::at_token(text, name, format!("unknown PLY type `{name}`")))
    };
    match tokens[..] {
        [_, "list", count, ty, name] => Ok((name, Kind::List(scalar(count)?, scalar(ty)?))),
        [_, ty, name] if ty != "list" => Ok((name, Kind::Scalar(scalar(ty)?))),
        _ => Err(ParseError::at_token(
            text,
            tokens[0],
            "expected `property TYPE NAME` or `property list COUNT_TYPE TYPE NAME`".to_string(),
        )),
    }
}

/// An error unless the `vertex` element has scalar `x y z`, the `face` element a vertex index
/// list, and an element with records some property (a record of nothing would take no bytes).
fn check_element(text: &str, element: &Element) -> Result<(), ParseError> {
    if element.count > 0 && element.properties.is_empty() {
        let message = format!(
            "the element `{}` has {} records but no properties",
            element.name, element.count
        );
        return Err(ParseError::at_token(text, element.name, message));
    }
    let has = |wanted: &[&str], list: bool| {
        wanted.iter().all(|w| {
            element
                .properties
                .iter()
                .any(|(n, k)| n == w && matches!(k, Kind::List(..)) == list)
        })
    };
    let missing = match element.name {
        "vertex" if !has(&["x", "y", "z"], false) => "scalar properties x, y and z",
        "face" if !has(&["vertex_indices"], true) && !has(&["vertex_index"], true) => {
            "a list property vertex_indices"
        }
        _ => return Ok(()),
    };
    let message = format!("the element `{}` needs {missing}", element.name);
    Err(ParseError::at_token(text, element.name, message))
}

/// One number of a body: its text (ASCII, parsed exactly) or its binary value and offset.
enum Number<'a> {
    /// A token of `text`.
    Text { text: &'a str, token: &'a str },
    /// An integer-typed binary value at a byte offset.
    Int { value: i64, offset: usize },
    /// A float-typed binary value at a byte offset.
    Float { value: f64, offset: usize },
}

impl Number<'_> {
    /// The number as a coordinate.
    fn coordinate<N: Num>(self) -> Result<N, MeshError> {
        match self {
            Number::Text { text, token } => Ok(coordinate(text, token)?),
            Number::Int { value, .. } => Ok(N::from_i64(value)),
            Number::Float { value, offset } => binary_coordinate(value, offset, "a vertex"),
        }
    }

    /// The error `message` at this number.
    fn error(&self, message: String) -> MeshError {
        match *self {
            Number::Text { text, token } => ParseError::at_token(text, token, message).into(),
            Number::Int { offset, .. } | Number::Float { offset, .. } => {
                MeshError::Binary { offset, message }
            }
        }
    }

    /// The number as a count or index; an error naming `what` if it is not a non-negative
    /// integer.
    fn index(&self, what: &str) -> Result<usize, MeshError> {
        let index = match *self {
            Number::Text { token, .. } => token.parse().ok(),
            Number::Int { value, .. } => usize::try_from(value).ok(),
            Number::Float { .. } => None,
        };
        index.ok_or_else(|| {
            let shown = match *self {
                Number::Text { token, .. } => token.to_string(),
                Number::Int { value, .. } => value.to_string(),
                Number::Float { value, .. } => format!("{value} (a float)"),
            };
            self.error(format!("{what}: `{shown}` is not a non-negative integer"))
        })
    }

    /// The number as an index of one of `vertices` vertices.
    fn vertex(&self, vertices: usize, what: &str) -> Result<usize, MeshError> {
        let i = self.index(what)?;
        if i < vertices {
            return Ok(i);
        }
        Err(self.error(format!(
            "{what}: vertex index {i} is out of range: there are {vertices} vertices, \
             numbered from 0"
        )))
    }
}

/// A PLY body, read record by record.
trait Body<'a> {
    /// Begin the next record (named `record` in messages); its 1-based line if ASCII.
    fn start(&mut self, record: &str) -> Result<Option<usize>, MeshError>;
    /// The next number, of type `ty`, of the record (`what` names it in messages).
    fn number(&mut self, ty: Scalar, what: &str) -> Result<Number<'a>, MeshError>;
    /// End the record: an error if it has more numbers.
    fn finish(&mut self, record: &str) -> Result<(), MeshError>;
    /// An error unless only blanks follow the last record.
    fn rest(&mut self) -> Result<(), MeshError>;
    /// The error `message` at the current place.
    fn error(&self, message: String) -> MeshError;
}

/// An ASCII body: one record per non-blank line.
struct AsciiBody<'a> {
    text: &'a str,
    lines: std::iter::Peekable<Box<dyn Iterator<Item = (usize, &'a str)> + 'a>>,
    tokens: std::vec::IntoIter<&'a str>,
    line: &'a str,
}

impl<'a> AsciiBody<'a> {
    /// The body of `text` from byte `body` on.
    fn new(text: &'a str, body: usize) -> AsciiBody<'a> {
        let first_line = text[..body].matches('\n').count() + 1;
        let lines: Box<dyn Iterator<Item = (usize, &'a str)>> = Box::new(
            text[body..]
                .split('\n')
                .enumerate()
                .map(move |(k, l)| (first_line + k, l))
                .filter(|(_, l)| !l.trim().is_empty()),
        );
        AsciiBody {
            text,
            lines: lines.peekable(),
            tokens: Vec::new().into_iter(),
            line: &text[body..body],
        }
    }

    /// The place right after the current line's last token.
    fn line_end(&self) -> &'a str {
        let trimmed = self.line.trim_end();
        &trimmed[trimmed.len()..]
    }
}

impl<'a> Body<'a> for AsciiBody<'a> {
    fn start(&mut self, record: &str) -> Result<Option<usize>, MeshError> {
        let Some((number, line)) = self.lines.next() else {
            let end = &self.text[self.text.len()..];
            let message = format!("the file ends where {record} is due");
            return Err(ParseError::at_token(self.text, end, message).into());
        };
        self.line = line;
        self.tokens = line.split_whitespace().collect::<Vec<_>>().into_iter();
        Ok(Some(number))
    }

    fn number(&mut self, _: Scalar, what: &str) -> Result<Number<'a>, MeshError> {
        let token = self
            .tokens
            .next()
            .ok_or_else(|| self.error(format!("{what}: the line ends where a number is due")))?;
        Ok(Number::Text {
            text: self.text,
            token,
        })
    }

    fn finish(&mut self, record: &str) -> Result<(), MeshError> {
        match self.tokens.next() {
            None => Ok(()),
            Some(extra) => {
                let message = format!("{record}: more numbers than its properties declare");
                Err(ParseError::at_token(self.text, extra, message).into())
            }
        }
    }

    fn rest(&mut self) -> Result<(), MeshError> {
        match self.lines.peek() {
            None => Ok(()),
            Some(&(_, line)) => {
                let message = "text after the last record the header declares".to_string();
                Err(ParseError::at_token(self.text, line.trim_start(), message).into())
            }
        }
    }

    fn error(&self, message: String) -> MeshError {
        ParseError::at_token(self.text, self.line_end(), message).into()
    }
}

/// A binary body.
struct BinaryBody<'a> {
    bytes: &'a [u8],
    at: usize,
    big_endian: bool,
}

impl<'a> Body<'a> for BinaryBody<'a> {
    fn start(&mut self, _: &str) -> Result<Option<usize>, MeshError> {
        Ok(None)
    }

    fn number(&mut self, ty: Scalar, what: &str) -> Result<Number<'a>, MeshError> {
        let offset = self.at;
        let raw = self
            .bytes
            .get(offset..offset + ty.size())
            .ok_or_else(|| MeshError::Binary {
                offset: self.bytes.len(),
                message: format!("truncated PLY body: the file ends inside {what}"),
            })?;
        self.at += ty.size();
        let mut word = [0u8; 8];
        word[..raw.len()].copy_from_slice(raw);
        if self.big_endian {
            word[..raw.len()].reverse();
        }
        let bits = u64::from_le_bytes(word);
        let int = |value: i64| Number::Int { value, offset };
        Ok(match ty {
            Scalar::I8 => int(i64::from(bits as u8 as i8)),
            Scalar::U8 => int(i64::from(bits as u8)),
            Scalar::I16 => int(i64::from(bits as u16 as i16)),
            Scalar::U16 => int(i64::from(bits as u16)),
            Scalar::I32 => int(i64::from(bits as u32 as i32)),
            Scalar::U32 => int(i64::from(bits as u32)),
            Scalar::F32 => Number::Float {
                value: f64::from(f32::from_bits(bits as u32)),
                offset,
            },
            Scalar::F64 => Number::Float {
                value: f64::from_bits(bits),
                offset,
            },
        })
    }

    fn finish(&mut self, _: &str) -> Result<(), MeshError> {
        Ok(())
    }

    fn rest(&mut self) -> Result<(), MeshError> {
        if self.at == self.bytes.len() {
            return Ok(());
        }
        Err(MeshError::Binary {
            offset: self.at,
            message: format!(
                "{} bytes follow the last record the header declares",
                self.bytes.len() - self.at
            ),
        })
    }

    fn error(&self, message: String) -> MeshError {
        MeshError::Binary {
            offset: self.at,
            message,
        }
    }
}

/// The ASCII PLY text of `triangles` (indices into `vertices`, counterclockwise seen from
/// outside): the vertices they use, coordinates exact, and the triangles.
///
/// # Panics
/// If a triangle index is out of range of `vertices`.
pub fn write_ply<N: Num>(vertices: &[Point3<N>], triangles: &[[usize; 3]]) -> String {
    indexed_text(vertices, triangles, |nv, nt| {
        format!(
            "ply\nformat ascii 1.0\ncomment yinset: coordinates exact (p/q where no decimal is)\n\
             element vertex {nv}\nproperty double x\nproperty double y\nproperty double z\n\
             element face {nt}\nproperty list uchar int vertex_indices\nend_header\n"
        )
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::num::Rational;

    fn q(s: &str) -> Rational {
        Rational::parse(s).unwrap()
    }

    const HEAD: &str = "ply\nformat ascii 1.0\ncomment c\nelement vertex 4\nproperty float x\n\
        property float y\nproperty float z\nproperty uchar red\nelement face 2\n\
        property list uchar int vertex_indices\nelement edge 1\nproperty int vertex1\n\
        property int vertex2\nend_header\n";
    const BODY: &str = "0 0 0 1\n0.1 0 0 2\n0 1 0 3\n0 0 1/3 4\n3 0 2 1\n\n4 0 1 3 2\n0 1\n";

    #[test]
    fn ascii_reads_exact_coordinates_and_skips_other_properties() {
        let mesh = read_ply::<Rational>(format!("{HEAD}{BODY}").as_bytes()).unwrap();
        assert_eq!(mesh.vertices[1], Point3::new(q("1/10"), q("0"), q("0")));
        assert_eq!(mesh.vertices[3].z, q("1/3"));
        assert_eq!(mesh.faces, vec![vec![0, 2, 1], vec![0, 1, 3, 2]]);
        assert_eq!(mesh.face_lines, vec![19, 21]);
    }

    /// `(line, column, message)` of the error reading `text`.
    fn error(text: &str) -> (usize, usize, String) {
        crate::io::mesh::text_error(read_ply::<Rational>(text.as_bytes()))
    }

    #[test]
    fn ascii_errors_name_line_and_column() {
        let (line, column, message) =
            error(&format!("{HEAD}{}", BODY.replace("3 0 2 1", "3 0 9 1")));
        assert_eq!((line, column), (19, 5));
        assert_eq!(
            message,
            "face 0 (counting from 0), property vertex_indices: vertex index 9 is out of range: \
             there are 4 vertices, numbered from 0"
        );
        let (line, column, message) = error(&format!("{HEAD}{}", BODY.replace("0.1 0", "0.1 y")));
        assert_eq!((line, column), (16, 5));
        assert!(message.contains("`y` is not a number"), "{message}");
        let (line, _, message) = error(&format!("{HEAD}{}", BODY.replace("0 1 0 3", "0 1 0")));
        assert_eq!(line, 17);
        assert!(
            message.contains("vertex 2 (counting from 0), property red"),
            "{message}"
        );
        let (line, _, message) = error(&format!("{HEAD}{}", BODY.replace("3 0 2 1", "2 0 2")));
        assert_eq!(line, 19);
        assert!(message.contains("at least 3 vertices"), "{message}");
        assert_eq!(error(&format!("{HEAD}{BODY}1\n")).0, 23);
        assert_eq!(error(&format!("{HEAD}{}", &BODY[..BODY.len() - 4])).0, 22);
        let (line, _, message) = error(&HEAD.replace("property float z\n", ""));
        assert_eq!(line, 4);
        assert!(
            message.contains("needs scalar properties x, y and z"),
            "{message}"
        );
        assert!(error(&HEAD.replace("uchar red", "color red"))
            .2
            .contains("`color`"));
        assert!(error(&HEAD.replace("ascii", "utf16"))
            .2
            .contains("unknown PLY format"));
        assert!(error("ply\nend_header\n").2.contains("no `format` line"));
        let empty = "ply\nformat binary_little_endian 1.0\nelement x 4000000000\nend_header\n";
        assert_eq!(
            error(empty),
            (
                3,
                9,
                "the element `x` has 4000000000 records but no properties".to_string()
            )
        );
        assert!(read_ply::<Rational>(b"solid")
            .unwrap_err()
            .to_string()
            .contains("end_header"));
    }

    /// A binary PLY of the triangle (0,0,0), (0.5,0,0), (0,1,0) with a double x, float y and
    /// int16 z, in the given byte order.
    fn binary(big_endian: bool) -> Vec<u8> {
        let order = if big_endian { "big" } else { "little" };
        let mut bytes = format!(
            "ply\nformat binary_{order}_endian 1.0\nelement vertex 3\nproperty double x\n\
             property float y\nproperty int16 z\nelement face 1\n\
             property list uint8 uint32 vertex_indices\nend_header\n"
        )
        .into_bytes();
        let mut put = |b: &[u8]| {
            let mut b = b.to_vec();
            if big_endian {
                b.reverse();
            }
            bytes.extend(b);
        };
        for (x, y, z) in [(0.0f64, 0.0f32, 0i16), (0.5, 0.0, 0), (0.0, 1.0, -3)] {
            put(&x.to_le_bytes());
            put(&y.to_le_bytes());
            put(&z.to_le_bytes());
        }
        put(&[3]);
        for i in [0u32, 1, 2] {
            put(&i.to_le_bytes());
        }
        bytes
    }

    #[test]
    fn binary_bodies_in_both_byte_orders() {
        for big_endian in [false, true] {
            let mesh = read_ply::<Rational>(&binary(big_endian)).unwrap();
            assert_eq!(mesh.vertices[1], Point3::new(q("0.5"), q("0"), q("0")));
            assert_eq!(mesh.vertices[2], Point3::new(q("0"), q("1"), q("-3")));
            assert_eq!(mesh.faces, vec![vec![0, 1, 2]]);
            assert!(mesh.face_lines.is_empty());
        }
        let bytes = binary(false);
        let e = read_ply::<Rational>(&bytes[..bytes.len() - 2]).unwrap_err();
        assert_eq!(
            e.to_string(),
            format!(
                "byte {}: truncated PLY body: the file ends inside face 0 (counting from 0), \
                 property vertex_indices",
                bytes.len() - 2
            )
        );
        let mut long = bytes.clone();
        long.push(7);
        assert!(read_ply::<Rational>(&long)
            .unwrap_err()
            .to_string()
            .contains("1 bytes follow"));
    }

    #[test]
    fn writer_is_read_back_exactly() {
        let v = vec![
            Point3::new(q("1/3"), q("0.1"), q("-2")),
            Point3::int(9, 9, 9), // unused
            Point3::int(1, 0, 0),
            Point3::int(0, 1, 0),
        ];
        let text = write_ply(&v, &[[0, 2, 3]]);
        let mesh = read_ply::<Rational>(text.as_bytes()).unwrap();
        assert_eq!(
            mesh.vertices,
            vec![v[0].clone(), v[2].clone(), v[3].clone()]
        );
        assert_eq!(
            (mesh.faces, mesh.face_lines),
            (vec![vec![0, 1, 2]], vec![14])
        );
    }
}
