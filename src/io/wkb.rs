//! Well-known binary (OGC WKB, as PostGIS, GEOS and shapely exchange it), binary and hex:
//! polygonal geometries read, multipolygons written.
//!
//! Read: `Polygon` (type 3), `MultiPolygon` (6) and `GeometryCollection`s (7) of them (nested
//! collections too), each possibly empty, in either byte order, per geometry. PostGIS's EWKB
//! header is read too: its SRID is skipped (Yin sets have no coordinate reference system).
//! Coordinates are `f64`, each read as the rational it is (exact backends) and refused if NaN
//! or infinite; rings must be closed (their first point repeated at the end, as OGC requires)
//! and are returned open. Z and M coordinates, curved types and non-polygonal types (`Point`,
//! `LineString`, …) are rejected with an error, except by [`read_polygonal_parts`], which skips
//! points and line strings. Every error names the 0-based byte offset of the fault.
//!
//! Written: a little-endian `MultiPolygon` with each ring closed, coordinates the nearest
//! `f64` ([`NumberStyle::Decimal`]; refused where the rounded rings would not bound the set's
//! rings, see `super::nearest`) or, in [`NumberStyle::Exact`], only coordinates that are
//! `f64` values (an error names the first that is not).
//!
//! Hex: the upper-case hex digits of the bytes ([`to_hex`]), as PostGIS prints geometries and
//! shapely's `wkb_hex` gives them; [`from_hex`] reads either case.

use super::nearest::{exact_f64_polygons, nearest_polygons};
use super::{closed, ogc_ring, without_bom, NumberStyle, Polygon, WriteError};
use crate::kernel::Point;
use crate::num::Num;

/// Deepest nesting of collections read (bounds the reader's recursion).
const MAX_NESTING: usize = 64;

/// The fewest bytes a geometry takes (an empty `Polygon`: byte order, type, ring count), to
/// refuse counts the rest of the input cannot hold before allocating for them.
const MIN_GEOMETRY: usize = 9;

/// Bytes of one 2D point.
const POINT_BYTES: usize = 16;

/// The WKB geometry type codes of OGC Simple Features (ISO 13249-3 numbering).
const POINT: u32 = 1;
const LINE_STRING: u32 = 2;
const POLYGON: u32 = 3;
const MULTI_POINT: u32 = 4;
const MULTI_LINE_STRING: u32 = 5;
const MULTI_POLYGON: u32 = 6;
const GEOMETRY_COLLECTION: u32 = 7;

/// The EWKB flags of the type code: Z, M and SRID present.
const EWKB_Z: u32 = 0x8000_0000;
const EWKB_M: u32 = 0x4000_0000;
const EWKB_SRID: u32 = 0x2000_0000;

/// A malformed WKB input: the 0-based byte `offset` of the fault (of the decoded bytes, for hex
/// input: hex digits `2·offset` and `2·offset + 1`), and what is wrong there.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("byte {offset}: {message}")]
pub struct WkbError {
    /// 0-based byte offset of the fault.
    pub offset: usize,
    /// What is wrong there.
    pub message: String,
}

/// Read the polygons of one WKB geometry (a collection's polygons in order, a multipolygon's
/// parts, one polygon, or none if empty).
pub fn read_polygons<N: Num>(bytes: &[u8]) -> Result<Vec<Polygon<N>>, WkbError> {
    read(bytes, false)
}

/// Read the polygons of one WKB geometry, skipping its points and line strings (the parts that
/// have no area).
pub fn read_polygonal_parts<N: Num>(bytes: &[u8]) -> Result<Vec<Polygon<N>>, WkbError> {
    read(bytes, true)
}

/// The little-endian WKB `MultiPolygon` of `polys` (no parts for none), coordinates as `style`
/// says; rings must be non-empty.
pub fn write_multipolygon<N: Num>(
    polys: &[Polygon<N>],
    style: NumberStyle,
) -> Result<Vec<u8>, WriteError> {
    let polys = match style {
        NumberStyle::Decimal => nearest_polygons(polys)?,
        NumberStyle::Exact => exact_f64_polygons(polys)?,
    };
    let mut out = vec![1];
    out.extend(MULTI_POLYGON.to_le_bytes());
    put_count(&mut out, polys.len(), "polygons")?;
    for polygon in &polys {
        out.push(1);
        out.extend(POLYGON.to_le_bytes());
        put_count(&mut out, polygon.interiors.len() + 1, "rings")?;
        for ring in polygon.rings() {
            put_count(&mut out, ring.len() + 1, "points")?;
            for p in closed(ring) {
                out.extend(p.x.to_le_bytes());
                out.extend(p.y.to_le_bytes());
            }
        }
    }
    Ok(out)
}

/// The upper-case hex digits of `bytes`.
pub fn to_hex(bytes: &[u8]) -> String {
    hex::encode_upper(bytes)
}

/// The bytes spelled by the hex digits of `text` (either case; surrounding blanks and a
/// byte-order mark ignored), or an error at the byte the first fault falls in.
pub fn from_hex(text: &str) -> Result<Vec<u8>, WkbError> {
    let text = without_bom(text);
    let digits = text.trim();
    let lead = text.len() - text.trim_start().len();
    hex::decode(digits).map_err(|e| match e {
        hex::FromHexError::InvalidHexCharacter { index, .. } => {
            // `index` is a byte of `digits` where a character starts (pairs are checked in order).
            let (before, after) = text.split_at(lead + index);
            let c = after.chars().next().unwrap_or_default();
            WkbError {
                offset: index / 2,
                message: format!(
                    "`{}` (character {} of the text) is not a hex digit",
                    c.escape_debug(),
                    before.chars().count() + 1
                ),
            }
        }
        _ => WkbError {
            offset: digits.len() / 2,
            message: format!(
                "an odd number of hex digits ({}): WKB hex has two per byte",
                digits.len()
            ),
        },
    })
}

/// True if `bytes`, but for surrounding blanks, are one non-empty run of hex digits: WKB hex
/// (binary WKB starts with the byte 0 or 1, which is no hex digit).
pub fn is_hex(bytes: &[u8]) -> bool {
    let trimmed = bytes.trim_ascii();
    !trimmed.is_empty() && trimmed.iter().all(u8::is_ascii_hexdigit)
}

/// True if `bytes` begin as binary WKB does: a byte-order byte (0 or 1), then an OGC geometry
/// type code 1–7 in that byte order (ISO's Z/M thousands and EWKB's flags allowed); for
/// messages that suggest `--from wkb`, never to read input as WKB unasked.
pub fn looks_binary(bytes: &[u8]) -> bool {
    let [order @ (0 | 1), a, b, c, d, ..] = *bytes else {
        return false;
    };
    let code = if order == 1 {
        u32::from_le_bytes([a, b, c, d])
    } else {
        u32::from_be_bytes([a, b, c, d])
    };
    (POINT..=GEOMETRY_COLLECTION).contains(&((code & !(EWKB_Z | EWKB_M | EWKB_SRID)) % 1000))
}

/// The number `n` of things written as the WKB count (`u32`), or an error if it does not fit.
fn put_count(out: &mut Vec<u8>, n: usize, what: &str) -> Result<(), WriteError> {
    let n = u32::try_from(n)
        .map_err(|_| WriteError(format!("{n} {what}: more than WKB can count (2^32 - 1)")))?;
    out.extend(n.to_le_bytes());
    Ok(())
}

/// Read one geometry, skipping points and line strings if `skip_lower`; trailing bytes are an
/// error.
fn read<N: Num>(bytes: &[u8], skip_lower: bool) -> Result<Vec<Polygon<N>>, WkbError> {
    let mut reader = Reader {
        bytes,
        pos: 0,
        skip_lower,
    };
    let polygons = reader.geometry(0, None)?;
    let rest = bytes.len() - reader.pos;
    if rest > 0 {
        return Err(reader.error(
            reader.pos,
            format!("{rest} bytes after the end of the geometry"),
        ));
    }
    Ok(polygons)
}

/// The byte order of a geometry (its first byte).
#[derive(Clone, Copy)]
enum Order {
    /// 0: XDR, big-endian.
    Big,
    /// 1: NDR, little-endian.
    Little,
}

/// A reader over the bytes, at byte `pos`.
struct Reader<'a> {
    bytes: &'a [u8],
    pos: usize,
    skip_lower: bool,
}

impl Reader<'_> {
    /// The error `message` at byte `offset`.
    fn error(&self, offset: usize, message: impl Into<String>) -> WkbError {
        WkbError {
            offset,
            message: message.into(),
        }
    }

    /// The next `K` bytes, `what` they are for the message if the input ends first.
    fn take<const K: usize>(&mut self, what: &str) -> Result<[u8; K], WkbError> {
        let rest = self.bytes.len() - self.pos;
        let Some(chunk) = self.bytes.get(self.pos..self.pos + K) else {
            let message = format!("truncated: {what} needs {K} bytes, {rest} remain");
            return Err(self.error(self.pos, message));
        };
        self.pos += K;
        Ok(chunk.try_into().expect("a slice of K bytes"))
    }

    /// The next `u32` in `order`.
    fn u32(&mut self, order: Order, what: &str) -> Result<u32, WkbError> {
        let b = self.take::<4>(what)?;
        Ok(match order {
            Order::Big => u32::from_be_bytes(b),
            Order::Little => u32::from_le_bytes(b),
        })
    }

    /// The next `f64` in `order`.
    fn f64(&mut self, order: Order, what: &str) -> Result<f64, WkbError> {
        let b = self.take::<8>(what)?;
        Ok(match order {
            Order::Big => f64::from_be_bytes(b),
            Order::Little => f64::from_le_bytes(b),
        })
    }

    /// A count of `item`s, each at least `size` bytes: an error if the rest cannot hold them.
    fn count(&mut self, order: Order, item: &str, size: usize) -> Result<usize, WkbError> {
        let at = self.pos;
        let n = self.u32(order, &format!("the number of {item}s"))? as usize;
        let rest = self.bytes.len() - self.pos;
        if n.saturating_mul(size) > rest {
            let message = format!(
                "truncated: {n} {item}s need at least {} bytes, {rest} remain",
                n.saturating_mul(size)
            );
            return Err(self.error(at, message));
        }
        Ok(n)
    }

    /// The header of a geometry: its offset, byte order and type code (without an EWKB SRID).
    fn header(&mut self) -> Result<(usize, Order, u32), WkbError> {
        let at = self.pos;
        let order = match self.take::<1>("the byte order")?[0] {
            0 => Order::Big,
            1 => Order::Little,
            b => {
                let message = format!(
                    "byte order {b:#04x}: expected 0 (big-endian) or 1 (little-endian) at the \
                     start of a geometry"
                );
                return Err(self.error(at, message));
            }
        };
        let code_at = self.pos;
        let code = self.u32(order, "the geometry type")?;
        if code & EWKB_SRID != 0 {
            self.u32(order, "the EWKB SRID")?;
        }
        let base = code & !(EWKB_Z | EWKB_M | EWKB_SRID);
        let iso_zm = (1..=3).contains(&(base / 1000)) && (1..=17).contains(&(base % 1000));
        if code & (EWKB_Z | EWKB_M) != 0 || iso_zm {
            let message = format!(
                "geometry type {code} ({code:#010x}) has Z or M coordinates: only 2D is supported"
            );
            return Err(self.error(code_at, message));
        }
        Ok((code_at, order, base))
    }

    /// One geometry `depth` collections deep; inside a multi-geometry, of type `part` if given.
    fn geometry<N: Num>(
        &mut self,
        depth: usize,
        part: Option<u32>,
    ) -> Result<Vec<Polygon<N>>, WkbError> {
        let (at, order, kind) = self.header()?;
        if let Some(want) = part.filter(|&w| w != kind) {
            let message = format!(
                "a part of a {} must be a {}, not a {}",
                multi_name(want),
                type_name(want),
                type_name(kind)
            );
            return Err(self.error(at, message));
        }
        match kind {
            POLYGON => Ok(self.polygon(order)?.into_iter().collect()),
            MULTI_POLYGON => self.parts(order, depth, Some(POLYGON)),
            GEOMETRY_COLLECTION if depth >= MAX_NESTING => {
                let message = format!("geometry collections nested deeper than {MAX_NESTING}");
                Err(self.error(at, message))
            }
            GEOMETRY_COLLECTION => self.parts(order, depth, None),
            POINT | LINE_STRING | MULTI_POINT | MULTI_LINE_STRING if !self.skip_lower => {
                let message = format!(
                    "a {} is not polygonal: only Polygon, MultiPolygon and GeometryCollection \
                     are read",
                    type_name(kind)
                );
                Err(self.error(at, message))
            }
            POINT => {
                self.take::<POINT_BYTES>("a point")?;
                Ok(Vec::new())
            }
            LINE_STRING => {
                let n = self.count(order, "point", POINT_BYTES)?;
                self.pos += n * POINT_BYTES;
                Ok(Vec::new())
            }
            MULTI_POINT => self.parts(order, depth, Some(POINT)),
            MULTI_LINE_STRING => self.parts(order, depth, Some(LINE_STRING)),
            8..=17 => {
                let message = format!(
                    "a {} is not supported: only Polygon, MultiPolygon and GeometryCollection \
                     are read",
                    type_name(kind)
                );
                Err(self.error(at, message))
            }
            _ => Err(self.error(at, format!("unknown geometry type {kind}"))),
        }
    }

    /// The parts of a multi-geometry or collection (`part`: the type of every part, if fixed).
    fn parts<N: Num>(
        &mut self,
        order: Order,
        depth: usize,
        part: Option<u32>,
    ) -> Result<Vec<Polygon<N>>, WkbError> {
        let n = self.count(order, "part", MIN_GEOMETRY)?;
        let mut polygons = Vec::new();
        for _ in 0..n {
            polygons.extend(self.geometry(depth + 1, part)?);
        }
        Ok(polygons)
    }

    /// The body of a polygon: its rings, the first the exterior (`None`: no rings, empty).
    fn polygon<N: Num>(&mut self, order: Order) -> Result<Option<Polygon<N>>, WkbError> {
        let n = self.count(order, "ring", 4)?;
        let mut rings = (0..n)
            .map(|_| self.ring(order))
            .collect::<Result<Vec<_>, _>>()?
            .into_iter();
        Ok(rings.next().map(|exterior| Polygon {
            exterior,
            interiors: rings.collect(),
        }))
    }

    /// A closed ring, returned open.
    fn ring<N: Num>(&mut self, order: Order) -> Result<Vec<Point<N>>, WkbError> {
        let at = self.pos;
        let n = self.count(order, "point", POINT_BYTES)?;
        let points = (0..n)
            .map(|_| self.point(order))
            .collect::<Result<Vec<_>, _>>()?;
        ogc_ring(points).map_err(|message| self.error(at, message))
    }

    /// A point of finite coordinates.
    fn point<N: Num>(&mut self, order: Order) -> Result<Point<N>, WkbError> {
        let mut coordinate = |axis: &str| {
            let at = self.pos;
            let v = self.f64(order, &format!("the {axis} coordinate"))?;
            N::from_f64(v).map_err(|_| {
                self.error(
                    at,
                    format!("the {axis} coordinate is {v}, not a finite number"),
                )
            })
        };
        let x = coordinate("x")?;
        let y = coordinate("y")?;
        Ok(Point { x, y })
    }
}

/// The name of WKB geometry type `code` (1–17), for messages.
fn type_name(code: u32) -> &'static str {
    const NAMES: [&str; 17] = [
        "Point",
        "LineString",
        "Polygon",
        "MultiPoint",
        "MultiLineString",
        "MultiPolygon",
        "GeometryCollection",
        "CircularString",
        "CompoundCurve",
        "CurvePolygon",
        "MultiCurve",
        "MultiSurface",
        "Curve",
        "Surface",
        "PolyhedralSurface",
        "TIN",
        "Triangle",
    ];
    (code as usize)
        .checked_sub(1)
        .and_then(|k| NAMES.get(k))
        .copied()
        .unwrap_or("geometry of unknown type")
}

/// The multi-geometry whose parts are of type `part`, for messages.
fn multi_name(part: u32) -> &'static str {
    match part {
        POINT => "MultiPoint",
        LINE_STRING => "MultiLineString",
        _ => "MultiPolygon",
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::num::{Float, Rational};

    /// A WKB geometry from its parts in little-endian order: `1`, then each `u32` and `f64`.
    enum W {
        U(u32),
        F(f64),
    }

    fn le(parts: &[W]) -> Vec<u8> {
        let mut out = vec![1];
        for p in parts {
            match p {
                W::U(u) => out.extend(u.to_le_bytes()),
                W::F(f) => out.extend(f.to_le_bytes()),
            }
        }
        out
    }

    /// The unit right triangle (0,0), (1,0), (0,1), closed, as a little-endian WKB Polygon.
    fn triangle() -> Vec<u8> {
        use W::{F, U};
        let pts = [0.0, 0.0, 1.0, 0.0, 0.0, 1.0, 0.0, 0.0].map(F);
        let mut parts = vec![U(3), U(1), U(4)];
        parts.extend(pts);
        le(&parts)
    }

    fn err(bytes: &[u8]) -> WkbError {
        read_polygons::<Rational>(bytes).unwrap_err()
    }

    #[test]
    fn a_polygon_in_either_byte_order() {
        let p = |x, y| Point::<Rational>::int(x, y);
        let little = read_polygons::<Rational>(&triangle()).unwrap();
        assert_eq!(little.len(), 1);
        assert_eq!(little[0].exterior, vec![p(0, 0), p(1, 0), p(0, 1)]);
        // The same polygon in big-endian order, digits written out by hand (XDR).
        let big = from_hex(
            "00 00000003 00000001 00000004 \
             0000000000000000 0000000000000000 3FF0000000000000 0000000000000000 \
             0000000000000000 3FF0000000000000 0000000000000000 0000000000000000"
                .replace(' ', "")
                .as_str(),
        )
        .unwrap();
        assert_eq!(read_polygons::<Rational>(&big).unwrap(), little);
    }

    #[test]
    fn binary_wkb_is_recognized_by_its_first_five_bytes() {
        assert!(looks_binary(&triangle()));
        assert!(looks_binary(&[0, 0, 0, 0, 6]));
        // EWKB with an SRID, and ISO's Z polygon (1003).
        assert!(looks_binary(&[1, 3, 0, 0, 0x20]));
        assert!(looks_binary(&[1, 0xEB, 0x03, 0, 0]));
        let others: [&[u8]; 5] = [
            b"0 0\n1 0\n",
            b"",
            &[1, 8, 0, 0, 0],
            &[2, 3, 0, 0, 0],
            &[1, 3, 0],
        ];
        for text in others {
            assert!(!looks_binary(text), "{text:?}");
        }
    }

    #[test]
    fn coordinates_are_read_exactly() {
        use W::{F, U};
        let mut parts = vec![U(3), U(1), U(4)];
        parts.extend([0.0, 0.0, 0.1, 0.0, 0.0, 1.0, 0.0, 0.0].map(F));
        let polys = read_polygons::<Rational>(&le(&parts)).unwrap();
        // 0.1 as an f64 is 3602879701896397 / 2^55, not 1/10.
        let tenth = Rational::parse("3602879701896397/36028797018963968").unwrap();
        assert_eq!(polys[0].exterior[1].x, tenth);
        let floats = read_polygons::<Float>(&le(&parts)).unwrap();
        assert_eq!(floats[0].exterior[1].x, Float::new(0.1));
    }

    #[test]
    fn writer_output_reads_back() {
        let p = |x, y| Point::<Rational>::int(x, y);
        let square = Polygon {
            exterior: vec![p(0, 0), p(4, 0), p(4, 4), p(0, 4)],
            interiors: vec![vec![p(1, 1), p(1, 2), p(2, 1)]],
        };
        let polys = vec![square.clone(), square];
        let bytes = write_multipolygon(&polys, NumberStyle::Exact).unwrap();
        // Header 9 bytes; each polygon 9 + (4 + 5·16) + (4 + 4·16) bytes.
        assert_eq!(bytes.len(), 9 + 2 * (9 + 84 + 68));
        assert_eq!(&bytes[..9], &[1, 6, 0, 0, 0, 2, 0, 0, 0]);
        assert_eq!(read_polygons::<Rational>(&bytes).unwrap(), polys);
        let hex = to_hex(&bytes);
        assert!(hex.starts_with("010600000002000000"), "{hex}");
        assert_eq!(from_hex(&hex.to_lowercase()).unwrap(), bytes);
        assert_eq!(
            write_multipolygon::<Rational>(&[], NumberStyle::Decimal).unwrap(),
            [1, 6, 0, 0, 0, 0, 0, 0, 0]
        );
    }

    #[test]
    fn exact_style_refuses_what_is_not_an_f64() {
        let third = Rational::parse("1/3").unwrap();
        let p = |x: Rational| Point {
            x,
            y: Rational::zero(),
        };
        let polys = [Polygon {
            exterior: vec![
                p(Rational::zero()),
                p(third.clone()),
                p(Rational::from_i64(1)),
            ],
            interiors: vec![],
        }];
        let e = write_multipolygon(&polys, NumberStyle::Exact).unwrap_err();
        assert!(
            e.0.contains("the coordinate 1/3 of vertex 1 (1/3, 0) of polygon 0's exterior ring is not an f64"),
            "{e}"
        );
        let rounded = write_multipolygon(&polys, NumberStyle::Decimal).unwrap();
        let back = read_polygons::<Rational>(&rounded).unwrap();
        assert_eq!(back[0].exterior[1].x.to_f64(), 1.0 / 3.0);
        let huge = [Polygon {
            exterior: vec![p(Rational::parse("1e400").unwrap())],
            interiors: vec![],
        }];
        let e = write_multipolygon(&huge, NumberStyle::Decimal).unwrap_err();
        assert!(e.0.contains("beyond the range of f64"), "{e}");
    }

    #[test]
    fn truncation_is_located() {
        let whole = triangle();
        // The point count (at byte 9) announces more points than the rest holds.
        let e = err(&whole[..whole.len() - 3]);
        assert_eq!(e.offset, 9);
        assert_eq!(
            e.message,
            "truncated: 4 points need at least 64 bytes, 61 remain"
        );
        assert_eq!(
            err(&[]).to_string(),
            "byte 0: truncated: the byte order needs 1 bytes, 0 remain"
        );
        let e = err(&whole[..3]);
        assert_eq!(e.offset, 1);
        assert!(e.message.contains("the geometry type"), "{e}");
    }

    #[test]
    fn counts_beyond_the_input_are_refused_before_allocating() {
        let e = err(&le(&[W::U(3), W::U(1), W::U(u32::MAX)]));
        assert_eq!(e.offset, 9);
        assert!(e.message.contains("4294967295 points need at least"), "{e}");
    }

    #[test]
    fn bad_headers_are_named() {
        let mut bad_order = triangle();
        bad_order[0] = 7;
        let e = err(&bad_order);
        assert_eq!(e.offset, 0);
        assert!(e.message.starts_with("byte order 0x07"), "{e}");
        let e = err(&le(&[W::U(99), W::U(0)]));
        assert_eq!(
            (e.offset, e.message.as_str()),
            (1, "unknown geometry type 99")
        );
        let e = err(&le(&[W::U(1003), W::U(0)]));
        assert!(e.message.contains("Z or M"), "{e}");
        let e = err(&le(&[W::U(3 | EWKB_Z), W::U(0)]));
        assert!(e.message.contains("Z or M"), "{e}");
        let e = err(&le(&[W::U(1), W::F(0.0), W::F(0.0)]));
        assert!(e.message.contains("a Point is not polygonal"), "{e}");
        let e = err(&le(&[W::U(17), W::U(0)]));
        assert!(e.message.contains("a Triangle is not supported"), "{e}");
    }

    #[test]
    fn nan_and_open_rings_are_refused() {
        use W::{F, U};
        let mut parts = vec![U(3), U(1), U(4)];
        parts.extend([0.0, 0.0, 1.0, f64::NAN, 0.0, 1.0, 0.0, 0.0].map(F));
        let e = err(&le(&parts));
        assert_eq!(e.offset, 13 + 3 * 8);
        assert!(e.message.contains("the y coordinate is NaN"), "{e}");
        let mut parts = vec![U(3), U(1), U(3)];
        parts.extend([0.0, 0.0, 1.0, 0.0, 0.0, 1.0].map(F));
        let e = err(&le(&parts));
        assert_eq!(e.offset, 9);
        assert!(
            e.message.contains("a ring of 3 points is not closed"),
            "{e}"
        );
        let e = err(&le(&[U(3), U(1), U(0)]));
        assert!(e.message.contains("without points"), "{e}");
    }

    #[test]
    fn trailing_bytes_and_wrong_parts_are_refused() {
        let mut long = triangle();
        long.push(0);
        let e = err(&long);
        assert_eq!(
            e.to_string(),
            format!(
                "byte {}: 1 bytes after the end of the geometry",
                long.len() - 1
            )
        );
        let mut multi = le(&[W::U(6), W::U(1)]);
        multi.extend(le(&[W::U(2), W::U(0)]));
        let e = err(&multi);
        assert_eq!(e.offset, 10);
        assert!(
            e.message.contains("must be a Polygon, not a LineString"),
            "{e}"
        );
    }

    #[test]
    fn collections_nest_and_empties_are_empty() {
        let mut coll = le(&[W::U(7), W::U(3)]);
        coll.extend(triangle());
        coll.extend(le(&[W::U(6), W::U(0)]));
        coll.extend(le(&[W::U(3), W::U(0)]));
        let polys = read_polygons::<Rational>(&coll).unwrap();
        assert_eq!(polys.len(), 1);
        let mut deep = Vec::new();
        for _ in 0..=MAX_NESTING {
            deep.extend(le(&[W::U(7), W::U(1)]));
        }
        deep.extend(triangle());
        assert!(err(&deep).message.contains("nested deeper"));
    }

    #[test]
    fn polygonal_parts_skip_points_and_lines() {
        use W::{F, U};
        let mut coll = le(&[U(7), U(4)]);
        coll.extend(le(&[U(1), F(f64::NAN), F(f64::NAN)]));
        coll.extend(le(&[U(2), U(2), F(0.0), F(0.0), F(1.0), F(1.0)]));
        coll.extend(le(&[U(5), U(1)]));
        coll.extend(le(&[U(2), U(0)]));
        coll.extend(triangle());
        let polys = read_polygonal_parts::<Rational>(&coll).unwrap();
        assert_eq!(polys, read_polygons::<Rational>(&triangle()).unwrap());
        assert!(read_polygons::<Rational>(&coll).is_err());
    }

    #[test]
    fn ewkb_srid_is_skipped() {
        let mut ewkb = le(&[W::U(3 | EWKB_SRID), W::U(4326)]);
        ewkb.extend(&triangle()[5..]);
        assert_eq!(
            read_polygons::<Rational>(&ewkb).unwrap(),
            read_polygons::<Rational>(&triangle()).unwrap()
        );
    }

    #[test]
    fn hex_is_told_apart_and_its_faults_located() {
        assert!(is_hex(b" 0103000000\n"));
        assert!(!is_hex(&triangle()));
        assert!(!is_hex(b"0 0\n1 0\n"));
        assert!(!is_hex(b"  "));
        let e = from_hex("\u{feff} 0103x0").unwrap_err();
        assert_eq!(e.offset, 2);
        assert!(
            e.message.starts_with("`x` (character 6 of the text)"),
            "{e}"
        );
        let e = from_hex("01é").unwrap_err();
        assert!(
            e.message.starts_with("`é` (character 3 of the text)"),
            "{e}"
        );
        let e = from_hex("010").unwrap_err();
        assert!(e.message.contains("odd number of hex digits (3)"), "{e}");
    }
}
