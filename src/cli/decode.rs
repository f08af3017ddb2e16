//! Text or WKB of any format → oriented rings (2D) or faces (3D: OBJ, STL, OFF, PLY), remembering
//! where each ring or face came from for messages.

use super::format::Format;
use crate::io::mesh::{Mesh, MeshError};
use crate::io::obj::read_obj;
use crate::io::wkb::{self, WkbError};
use crate::io::yin2_text::{self, Yin2Text};
use crate::io::{geojson, wkt, ParseError, Polygon};
use crate::io::{off::read_off, ply::read_ply, stl::read_stl};
use crate::kernel::Point;
use crate::num::Num;
use crate::yin2::YinError;
use crate::yin3::Yin3Error;

/// The OBJ comment line that stands for the whole space, which has no boundary.
pub const WHOLE_SPACE: &str = "# yinset: the whole space (no boundary)";

/// What an input text holds.
pub enum Decoded<B> {
    /// The whole plane or space (the yin2 statement `plane`, or an OBJ text without faces but
    /// with the [`WHOLE_SPACE`] line).
    Full,
    /// The boundary: [`Rings`] or a [`Mesh`] (none: the empty set).
    Boundary(B),
}

/// Rings and, for each, where it is in the input.
pub struct Rings<N> {
    /// The vertex cycles, oriented (OGC polygons: exterior counterclockwise, holes clockwise).
    pub rings: Vec<Vec<Point<N>>>,
    /// Where each ring is in the input.
    pub origins: Origins,
}

/// Where each ring of [`Rings`] is in the input.
pub struct Origins(Vec<Origin>);

/// Where a ring is in the input.
enum Origin {
    /// The k-th curve of a yin2 text, as given.
    Curve,
    /// A polygon's exterior (`ring` None) or interior ring, perhaps read backwards to orient it.
    Polygon {
        polygon: usize,
        ring: Option<usize>,
        reversed: bool,
    },
}

/// Decode `text` in `format`, a format of 2D sets; with `polygonal_only`, the points and
/// lines of WKT and GeoJSON are dropped instead of rejected.
pub fn decode<N: Num>(
    text: &str,
    format: Format,
    polygonal_only: bool,
) -> Result<Decoded<Rings<N>>, ParseError> {
    let polygons = match (format, polygonal_only) {
        (Format::Yin2, _) => {
            let rings = match yin2_text::read(text)? {
                Yin2Text::Plane => return Ok(Decoded::Full),
                Yin2Text::Curves(rings) => rings,
            };
            let origins = Origins(rings.iter().map(|_| Origin::Curve).collect());
            return Ok(Decoded::Boundary(Rings { rings, origins }));
        }
        (Format::Wkt, false) => wkt::read_polygons(text)?,
        (Format::Wkt, true) => wkt::read_polygonal_parts(text)?,
        (Format::Geojson, false) => geojson::read_polygons(text)?,
        (Format::Geojson, true) => geojson::read_polygonal_parts(text)?,
        (Format::Obj | Format::Stl | Format::StlBinary | Format::Off | Format::Ply, _) => {
            return Err(not_here(format, "holds 3D sets, not 2D rings"))
        }
        (Format::Wkb | Format::WkbHex, _) => {
            return Err(not_here(format, "is binary: decoded from bytes, not text"))
        }
    };
    Ok(Decoded::Boundary(Rings::of_polygons(polygons)))
}

/// Decode WKB `bytes` (their hex digits if `hex`); with `polygonal_only`, points and line
/// strings are dropped instead of rejected.
pub fn decode_wkb<N: Num>(
    bytes: &[u8],
    hex: bool,
    polygonal_only: bool,
) -> Result<Rings<N>, WkbError> {
    let digits;
    let bytes = if hex {
        let text = std::str::from_utf8(bytes).map_err(|e| WkbError {
            offset: e.valid_up_to() / 2,
            message: "not hex digits: this byte is not even UTF-8 text".to_string(),
        })?;
        digits = wkb::from_hex(text)?;
        &digits
    } else {
        bytes
    };
    let polygons = if polygonal_only {
        wkb::read_polygonal_parts(bytes)?
    } else {
        wkb::read_polygons(bytes)?
    };
    Ok(Rings::of_polygons(polygons))
}

/// Decode the file `bytes` in `format`, a format of 3D sets: its mesh (no vertices and no faces:
/// the empty set; vertices without faces are an error), or the whole space (OBJ only).
pub fn decode_mesh<N: Num>(bytes: &[u8], format: Format) -> Result<Decoded<Mesh<N>>, MeshError> {
    let text = || {
        std::str::from_utf8(bytes).map_err(|e| MeshError::Binary {
            offset: e.valid_up_to(),
            message: format!(
                "{} is a text format, and this byte is not UTF-8 text",
                format.name()
            ),
        })
    };
    let mesh = match format {
        Format::Obj => {
            let text = text()?;
            let mesh = read_obj(text)?;
            if mesh.faces.is_empty() && has_line(text, WHOLE_SPACE) {
                return Ok(Decoded::Full);
            }
            mesh
        }
        Format::Stl | Format::StlBinary => read_stl(bytes)?,
        Format::Off => read_off(text()?)?,
        Format::Ply => read_ply(bytes)?,
        Format::Yin2 | Format::Wkt | Format::Geojson | Format::Wkb | Format::WkbHex => {
            return Err(MeshError::Text(ParseError {
                line: 1,
                column: 1,
                message: format!("{} holds 2D rings, not 3D faces", format.name()),
            }))
        }
    };
    Ok(Decoded::Boundary(mesh.with_faces()?))
}

/// True if a line of `text` is `line` (but for surrounding blanks).
fn has_line(text: &str, line: &str) -> bool {
    text.lines().any(|l| l.trim() == line)
}

/// The error of decoding `format` as 2D text, which it is not (`why`; the command line never
/// asks for it).
fn not_here(format: Format, why: &str) -> ParseError {
    ParseError {
        line: 1,
        column: 1,
        message: format!("{} {why}", format.name()),
    }
}

/// Where the faces named by `e` are in a mesh text whose faces are on `face_lines`, as a
/// sentence to append to it (nothing for binary files, whose faces have no lines).
pub fn locate_faces(e: &Yin3Error, face_lines: &[usize]) -> String {
    let faces = match e {
        Yin3Error::IndexOutOfRange { face, .. }
        | Yin3Error::DegenerateFace { face, .. }
        | Yin3Error::NonPlanarFace { face, .. }
        | Yin3Error::OpenEdge { face, .. }
        | Yin3Error::Orientation { face, .. } => vec![*face],
        Yin3Error::Crossing { a, b, .. }
        | Yin3Error::Overlap { a, b, .. }
        | Yin3Error::Inconsistent { a, b, .. } => vec![*a, *b],
        _ => Vec::new(),
    };
    let notes: Vec<String> = faces
        .into_iter()
        .filter_map(|f| Some(format!("face {f} is on line {}", face_lines.get(f)?)))
        .collect();
    if notes.is_empty() {
        String::new()
    } else {
        format!(" (counting faces from 0: {})", notes.join("; "))
    }
}

impl<N: Num> Rings<N> {
    /// The rings of OGC polygons, exteriors counterclockwise and interiors clockwise.
    fn of_polygons(polygons: Vec<Polygon<N>>) -> Rings<N> {
        let mut rings = Vec::new();
        let mut origins = Vec::new();
        for (polygon, p) in polygons.into_iter().enumerate() {
            for (ring, points, reversed) in p.oriented_rings() {
                rings.push(points);
                origins.push(Origin::Polygon {
                    polygon,
                    ring,
                    reversed,
                });
            }
        }
        Rings {
            rings,
            origins: Origins(origins),
        }
    }

    /// Total number of vertices.
    pub fn vertices(&self) -> usize {
        self.rings.iter().map(Vec::len).sum()
    }
}

impl Origins {
    /// Where the curves named by `e` are in the input, as a sentence to append to it (empty for
    /// yin2, whose curves are numbered as given).
    pub fn locate_error(&self, e: &YinError) -> String {
        let notes: Vec<String> = curves_named(e)
            .into_iter()
            .filter_map(|c| match self.0.get(c)? {
                Origin::Curve => None,
                Origin::Polygon {
                    polygon,
                    ring,
                    reversed,
                } => {
                    let which = ring.map_or("exterior ring".to_string(), |k| {
                        format!("interior ring {k}")
                    });
                    let backwards = if *reversed {
                        " read backwards to orient it"
                    } else {
                        ""
                    };
                    Some(format!(
                        "curve {c} is polygon {polygon}'s {which}{backwards}"
                    ))
                }
            })
            .collect();
        if notes.is_empty() {
            String::new()
        } else {
            format!(" (counting from 0: {})", notes.join("; "))
        }
    }
}

/// The curve indices an error names.
fn curves_named(e: &YinError) -> Vec<usize> {
    match e {
        YinError::NotFinite { curve, .. }
        | YinError::TooFewVertices { curve, .. }
        | YinError::RepeatedVertex { curve, .. }
        | YinError::NotSimple { curve, .. } => vec![*curve],
        YinError::ProperCrossing {
            curve_a, curve_b, ..
        }
        | YinError::SharedEdge {
            curve_a, curve_b, ..
        } => vec![*curve_a, *curve_b],
        YinError::NestedSameOrientation { outer, inner, .. } => vec![*outer, *inner],
        YinError::MixedOutermost { positive, negative } => vec![*positive, *negative],
        YinError::DisconnectedAtom { curves, .. } => curves.clone(),
        _ => Vec::new(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::io::twice_signed_area;
    use crate::num::Rational;

    fn rings(text: &str, format: Format) -> Rings<Rational> {
        match decode(text, format, false).unwrap() {
            Decoded::Boundary(r) => r,
            Decoded::Full => panic!("full"),
        }
    }

    #[test]
    fn ogc_rings_are_oriented_exterior_ccw_holes_cw() {
        // Exterior given clockwise, hole given counterclockwise: both are turned round.
        let r = rings(
            "POLYGON ((0 0, 0 4, 4 4, 4 0, 0 0), (1 1, 2 1, 2 2, 1 1))",
            Format::Wkt,
        );
        assert_eq!(
            twice_signed_area(&r.rings[0]),
            Rational::from_integer(32.into())
        );
        assert_eq!(
            twice_signed_area(&r.rings[1]),
            Rational::from_integer((-1).into())
        );
        assert_eq!(r.vertices(), 7);
    }

    #[test]
    fn yin2_keeps_orientation_and_marks_the_full_plane() {
        let r = rings("0 0\n0 1\n1 0\n", Format::Yin2);
        assert!(twice_signed_area(&r.rings[0]) < Rational::from_integer(0.into()));
        assert!(matches!(
            decode::<Rational>("plane\n", Format::Yin2, false),
            Ok(Decoded::Full)
        ));
        assert_eq!(rings("# nothing\n", Format::Yin2).rings.len(), 0);
    }

    #[test]
    fn errors_are_located_in_polygon_terms() {
        let r = rings(
            r#"{"type":"MultiPolygon","coordinates":[[[[0,0],[1,0],[0,1],[0,0]]],[[[0,0],[0,5],[5,0],[0,0]],[[1,1],[2,1],[1,2],[1,1]]]]}"#,
            Format::Geojson,
        );
        let e = YinError::ProperCrossing {
            curve_a: 0,
            vertex_a: 0,
            curve_b: 2,
            vertex_b: 1,
            point: "(1, 1)".into(),
        };
        assert_eq!(
            r.origins.locate_error(&e),
            " (counting from 0: curve 0 is polygon 0's exterior ring; \
             curve 2 is polygon 1's interior ring 0 read backwards to orient it)"
        );
        let yin2 = rings("0 0\n1 0\n0 1\n", Format::Yin2);
        assert_eq!(yin2.origins.locate_error(&e), "");
    }

    #[test]
    fn obj_without_faces_is_empty_or_the_whole_space() {
        let mesh = |text: &str| match decode_mesh::<Rational>(text.as_bytes(), Format::Obj).unwrap()
        {
            Decoded::Boundary(m) => Some(m),
            Decoded::Full => None,
        };
        assert!(mesh(&format!("{WHOLE_SPACE}\n")).is_none());
        assert!(mesh("").unwrap().faces.is_empty());
        assert!(mesh("# yinset\n\n").unwrap().vertices.is_empty());
        // Vertices without faces (a point cloud) bound nothing, in every format.
        for (text, format) in [
            ("# yinset\nv 0 0 0\n", Format::Obj),
            ("OFF\n1 0 0\n0 0 0\n", Format::Off),
            (
                "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n\
                 property float z\nend_header\n0 0 0\n",
                Format::Ply,
            ),
        ] {
            let Err(e) = decode_mesh::<Rational>(text.as_bytes(), format) else {
                panic!("a point cloud read as a set: {text}")
            };
            assert_eq!(e, MeshError::NoFaces { vertices: 1 }, "{text}");
            assert!(e.to_string().contains("1 vertices but no faces"), "{e}");
        }
        let text = format!("{WHOLE_SPACE}\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
        assert_eq!(mesh(&text).unwrap().faces.len(), 1);
        assert!(decode::<Rational>("v 0 0 0", Format::Obj, false).is_err());
        assert!(decode_mesh::<Rational>(b"0 0\n1 0\n0 1\n", Format::Yin2).is_err());
        // The whole-space line stands for 1̂ in OBJ only.
        let off = format!("{WHOLE_SPACE}\nOFF\n0 0 0\n");
        assert!(matches!(
            decode_mesh::<Rational>(off.as_bytes(), Format::Off),
            Ok(Decoded::Boundary(m)) if m.faces.is_empty()
        ));
        let Err(e) = decode_mesh::<Rational>(b"OFF\n\xff", Format::Off) else {
            panic!("not UTF-8, yet read")
        };
        assert_eq!(
            e.to_string(),
            "byte 4: off is a text format, and this byte is not UTF-8 text"
        );
    }

    #[test]
    fn errors_name_the_obj_lines_of_their_faces() {
        let lines = [3, 5, 9];
        let e = Yin3Error::Crossing {
            a: 0,
            b: 2,
            point: crate::yin3::Spot::new(&crate::kernel::Point3::<crate::num::Rational>::int(
                0, 0, 0,
            )),
        };
        assert_eq!(
            locate_faces(&e, &lines),
            " (counting faces from 0: face 0 is on line 3; face 2 is on line 9)"
        );
        assert_eq!(locate_faces(&Yin3Error::NoFaces, &lines), "");
    }
}
