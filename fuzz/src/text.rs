//! The properties of the parser targets: on any text, each reader returns curves or a located
//! error without panicking, in exact and float mode alike; what it reads writes back to text
//! that reads the same (exact mode); and the curves read give a valid Yin set or a clear
//! constructor error.

use crate::check::fail;
use std::fmt::Debug;
use yinset::io::{geojson, wkt, yin2_text, NumberStyle, ParseError, Polygon, WriteError};
use yinset::kernel::Point;
use yinset::num::{Float, Num, Rational};
use yinset::yin2::{FillRule, YinSet2};

/// The text of the raw input (invalid UTF-8 replaced, so that every input reaches a reader).
pub fn text_of(data: &[u8]) -> String {
    String::from_utf8_lossy(data).into_owned()
}

/// A parse error must point into the text: line ≤ number of lines, column ≤ line length + 1.
pub(crate) fn check_parse_error(e: &ParseError, text: &str) {
    let lines: Vec<&str> = text.split('\n').collect();
    let ok = e.line >= 1
        && e.line <= lines.len()
        && e.column >= 1
        && e.column <= lines[e.line - 1].chars().count() + 1
        && !e.message.is_empty();
    if !ok {
        fail!(text, "parse error outside the text: {e:?}");
    }
}

/// Largest numerator or denominator (bits) of a coordinate whose rings are built into sets.
/// Exact arithmetic on literals such as `4.5e+1200` is slow (seconds per operation count in
/// the hundreds, in num-bigint's gcd): reported, and kept out of the way of the other checks.
const MAX_BUILD_BITS: u64 = 1024;

/// True if some coordinate is too large a rational to build sets from in fuzzing time.
fn huge<N: Num>(rings: &[Vec<Point<N>>]) -> bool {
    rings.iter().flatten().any(|p| {
        [&p.x, &p.y].iter().any(|v| {
            let t = v.to_string();
            // Display is `p/q` for exact rationals, a decimal for floats: its length bounds the bits.
            t.len() as u64 * 10 / 3 > MAX_BUILD_BITS
        })
    })
}

/// Build from the rings read: the validating constructor (valid set or error) and the even-odd
/// fill (always a valid set).
fn build<N: Num, D: Debug>(rings: &[Vec<Point<N>>], input: &D) {
    if N::EXACT && huge(rings) {
        return;
    }
    if let Ok(set) = YinSet2::from_curves(rings.to_vec()) {
        if let Err(e) = set.validate() {
            fail!(
                input,
                "from_curves output fails the validator: {e}\nset = {set:?}"
            );
        }
    }
    match YinSet2::from_rings_filled(rings.to_vec(), FillRule::EvenOdd) {
        Ok(set) => {
            if let Err(e) = set.validate() {
                fail!(
                    input,
                    "even-odd fill fails the validator: {e}\nset = {set:?}"
                );
            }
        }
        Err(e) => {
            let finite = rings
                .iter()
                .flatten()
                .all(|p| p.x.is_finite() && p.y.is_finite());
            if finite {
                fail!(input, "from_rings_filled rejected finite rings: {e}");
            }
        }
    }
}

/// The shape of what was read (ring lengths), to compare exact and float readings.
fn shape_of<N>(rings: &[Vec<Point<N>>]) -> Vec<usize> {
    rings.iter().map(Vec::len).collect()
}

fn rings_of<N: Clone>(polys: &[Polygon<N>]) -> Vec<Vec<Point<N>>> {
    polys
        .iter()
        .flat_map(|p| p.rings().map(<[Point<N>]>::to_vec))
        .collect()
}

/// Exact and float readings must succeed or fail together (the literal grammar is shared),
/// with the same structure.
fn agree<A, B>(
    exact: &Result<Vec<Vec<Point<A>>>, ParseError>,
    float: &Result<Vec<Vec<Point<B>>>, ParseError>,
    text: &str,
) {
    match (exact, float) {
        (Ok(a), Ok(b)) if shape_of(a) == shape_of(b) => {}
        (Err(a), Err(b)) if a == b => {}
        _ => fail!(
            text,
            "exact and float readings differ: {:?} vs {:?}",
            exact.as_ref().map(|r| shape_of(r)),
            float.as_ref().map(|r| shape_of(r))
        ),
    }
}

/// The `yin2` curve-list reader.
pub fn yin2(text: &str) {
    let exact = yin2_text::read_curves::<Rational>(text);
    let float = yin2_text::read_curves::<Float>(text);
    agree(&exact, &float, text);
    match &exact {
        Err(e) => check_parse_error(e, text),
        Ok(curves) => {
            let written = yin2_text::write_curves(curves);
            match yin2_text::read_curves::<Rational>(&written) {
                Ok(again) if again == *curves => {}
                other => fail!(
                    text,
                    "write then read differs: {other:?}\nwritten: {written:?}"
                ),
            }
            build(curves, &text);
        }
    }
    if let Ok(curves) = &float {
        build(curves, &text);
    }
}

/// The readers of one polygon format, in both modes, and its writer.
struct Format {
    read_exact: fn(&str) -> Result<Vec<Polygon<Rational>>, ParseError>,
    read_float: fn(&str) -> Result<Vec<Polygon<Float>>, ParseError>,
    write: fn(&[Polygon<Rational>]) -> Result<String, WriteError>,
}

/// A polygon reader: exact and float mode agree, errors point into the text, what it reads
/// writes back to text that reads the same, and the rings give sets. Returns the exact reading.
fn polygons(text: &str, f: Format) -> Result<Vec<Polygon<Rational>>, ParseError> {
    let exact = (f.read_exact)(text);
    let float = (f.read_float)(text);
    agree(
        &exact.as_ref().map(|p| rings_of(p)).map_err(Clone::clone),
        &float.as_ref().map(|p| rings_of(p)).map_err(Clone::clone),
        text,
    );
    match &exact {
        Err(e) => check_parse_error(e, text),
        Ok(polys) => {
            if polys.iter().flat_map(|p| p.rings()).all(|r| !r.is_empty()) {
                let written = match (f.write)(polys) {
                    Ok(written) => written,
                    Err(e) => fail!(text, "what was read cannot be written exactly: {e}"),
                };
                match (f.read_exact)(&written) {
                    Ok(again) if again == *polys => {}
                    other => fail!(
                        text,
                        "write then read differs: {other:?}\nwritten: {written:?}"
                    ),
                }
            }
            build(&rings_of(polys), &text);
        }
    }
    if let Ok(polys) = &float {
        build(&rings_of(polys), &text);
    }
    exact
}

/// The WKT reader (both entry points).
pub fn wkt(text: &str) {
    let exact = polygons(
        text,
        Format {
            read_exact: wkt::read_polygons::<Rational>,
            read_float: wkt::read_polygons::<Float>,
            write: |p| wkt::write_multipolygon(p, NumberStyle::Exact),
        },
    );
    match wkt::read_polygonal_parts::<Rational>(text) {
        Err(e) => check_parse_error(&e, text),
        Ok(polys) => {
            if let Ok(strict) = &exact {
                if polys != *strict {
                    fail!(
                        text,
                        "read_polygonal_parts differs from read_polygons on a polygonal text"
                    );
                }
            }
        }
    }
}

/// The GeoJSON reader.
pub fn geojson(text: &str) {
    // The exact reading is checked inside; only WKT compares it with a second entry point.
    let _ = polygons(
        text,
        Format {
            read_exact: geojson::read_polygons::<Rational>,
            read_float: geojson::read_polygons::<Float>,
            write: |p| geojson::write_multipolygon(p, NumberStyle::Exact),
        },
    );
}
