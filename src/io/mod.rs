//! Formats read and written exactly: the `yin2` curve lists ([`yin2_text`]), WKT ([`wkt`]),
//! GeoJSON ([`geojson`]) and WKB ([`wkb`], binary `f64` coordinates) in 2D; the meshes
//! ([`mesh`]) of Wavefront OBJ ([`obj`]), STL ([`stl`]), OFF ([`off`]) and PLY ([`ply`]) in 3D. Pictures: SVG of 2D sets ([`svg`]); PNG
//! (`png3`) and interactive HTML ([`html3`]) of 3D sets, from a [`scene3`]. The PNG writers,
//! `png` (2D sets' SVG rasterized) and `png3`, need the feature `png` (on by default).
//!
//! Readers parse every coordinate with [`crate::num::Num::parse`], so exact backends get the
//! decimal text's value without rounding (binary floats of STL and PLY are exact rationals);
//! they never panic, and report malformed input as a [`ParseError`] with its line and column
//! (a [`mesh::MeshError`] with its byte offset for binary files). A UTF-8 byte-order mark at
//! the start of a text is ignored by every reader. Rings are returned open (the closing
//! repetition of the first point is stripped). The rings of WKT, GeoJSON and WKB must be
//! closed, their first point repeated at the end, as OGC Simple Features and RFC 7946 require:
//! an unclosed ring is an error naming it in all three (yin2 curves may be closed or not).
//! Validity (enough distinct points, simplicity) is the kernel's business, not the readers'.

mod decimal;
mod error;
#[cfg(feature = "geo-types")]
pub mod geo_interop;
pub mod geojson;
pub mod html3;
mod lettering;
mod limits;
pub mod mesh;
mod nearest;
pub mod obj;
pub mod off;
mod picture_frame;
pub mod ply;
#[cfg(feature = "png")]
pub mod png;
#[cfg(feature = "png")]
pub mod png3;
pub mod scene3;
pub mod stl;
pub mod svg;
#[cfg(test)]
pub(crate) mod testdata;
pub mod wkb;
pub mod wkt;
pub mod yin2_text;

pub use decimal::NumberStyle;
pub use error::{ParseError, WriteError};
pub use limits::check_digit_runs;

use crate::kernel::Point;
use crate::num::Num;
use crate::yin2::YinSet2;
use std::cmp::Ordering;

/// A polygon as the GIS formats give it: an exterior ring and interior rings (holes), each open
/// (without the closing repetition of its first point).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Polygon<N> {
    /// The outer boundary.
    pub exterior: Vec<Point<N>>,
    /// The holes.
    pub interiors: Vec<Vec<Point<N>>>,
}

impl<N> Polygon<N> {
    /// All rings: the exterior first, then the holes.
    pub fn rings(&self) -> impl Iterator<Item = &[Point<N>]> {
        std::iter::once(self.exterior.as_slice()).chain(self.interiors.iter().map(Vec::as_slice))
    }
}

impl<N: Num> Polygon<N> {
    /// The rings oriented as boundary curves of a Yin set (interior on the left, seed 000): the
    /// exterior counterclockwise, the holes clockwise; each with its index among the holes
    /// (`None` for the exterior) and whether it was reversed to orient it.
    pub fn oriented_rings(self) -> impl Iterator<Item = (Option<usize>, Vec<Point<N>>, bool)> {
        let holes = self
            .interiors
            .into_iter()
            .enumerate()
            .map(|(k, r)| (Some(k), r));
        std::iter::once((None, self.exterior))
            .chain(holes)
            .map(|(ring, mut points)| {
                let want = if ring.is_none() {
                    Ordering::Greater
                } else {
                    Ordering::Less
                };
                let reversed = twice_signed_area(&points).sign() == want.reverse();
                if reversed {
                    points.reverse();
                }
                (ring, points, reversed)
            })
    }
}

/// The polygons of a bounded Yin set: one per atom (seed 000, Def. of atoms), its positive
/// curve the exterior and its negative curves the holes; `None` if the set is unbounded.
pub fn polygons_of<N: Num>(set: &YinSet2<N>) -> Option<Vec<Polygon<N>>> {
    if !set.is_bounded() {
        return None;
    }
    let curve = |k: usize| set.curves()[k].vertices().to_vec();
    let polygon = |atom: &crate::yin2::Atom| {
        Some(Polygon {
            exterior: curve(atom.outer?),
            interiors: atom.holes.iter().map(|&h| curve(h)).collect(),
        })
    };
    Some(set.atoms().iter().filter_map(polygon).collect())
}

/// Twice the signed area of a vertex cycle (positive iff counterclockwise).
pub(crate) fn twice_signed_area<N: Num>(ring: &[Point<N>]) -> N {
    let next = ring.iter().cycle().skip(1);
    ring.iter().zip(next).fold(N::zero(), |acc, (p, q)| {
        acc + p.x.clone() * q.y.clone() - q.x.clone() * p.y.clone()
    })
}

/// The UTF-8 byte-order mark (which editors on Windows write), which every reader ignores.
const BOM: &str = "\u{feff}";

/// `text` without a leading UTF-8 byte-order mark.
pub(crate) fn without_bom(text: &str) -> &str {
    text.strip_prefix(BOM).unwrap_or(text)
}

/// `bytes` without a leading UTF-8 byte-order mark (the readers of files that may be binary).
pub(crate) fn without_bom_bytes(bytes: &[u8]) -> &[u8] {
    bytes.strip_prefix(BOM.as_bytes()).unwrap_or(bytes)
}

/// The OGC `ring` (of WKT, GeoJSON or WKB) without the closing repetition of its first point,
/// or why it is not a ring: it has no points, or it does not end at its first point (OGC
/// Simple Features and RFC 7946 require rings to be closed).
fn ogc_ring<N: Num>(ring: Vec<Point<N>>) -> Result<Vec<Point<N>>, String> {
    match (ring.first(), ring.last()) {
        (Some(first), Some(last)) if first == last => Ok(open_ring(ring)),
        // The points are not shown: in float mode they are the input's values rounded, and
        // the message must be the same in both modes.
        (Some(_), Some(_)) => Err(format!(
            "a ring of {} points is not closed: its last point is not its first (OGC rings \
             repeat their first point at the end)",
            ring.len()
        )),
        _ => Err("a ring without points".to_string()),
    }
}

/// `ring` without the closing repetition of its first point, if it has one.
fn open_ring<N: PartialEq>(mut ring: Vec<Point<N>>) -> Vec<Point<N>> {
    if ring.len() > 1 && ring.first() == ring.last() {
        ring.pop();
    }
    ring
}

/// Each of `polys` as the list of its rings, each ring the list of its points closed (its first
/// point repeated at the end, as OGC requires), a point `point(x, y)` of its coordinates' texts
/// in `style` (the nearest `f64`s checked by [`nearest::nearest_polygons`], or exactly, `p/q`
/// only if `fractions`), lists between `brackets` and separated by `sep`.
fn polygon_texts<N: Num>(
    polys: &[Polygon<N>],
    style: NumberStyle,
    fractions: bool,
    point: impl Fn(String, String) -> String,
    brackets: [&str; 2],
    sep: &str,
) -> Result<Vec<String>, WriteError> {
    match style {
        NumberStyle::Decimal => {
            let rounded = nearest::nearest_polygons(polys)?;
            ring_texts(&rounded, |f| Ok(f.to_string()), point, brackets, sep)
        }
        NumberStyle::Exact => {
            let text = |n: &N| decimal::exact_coordinate_text(n, fractions).map_err(WriteError);
            ring_texts(polys, text, point, brackets, sep)
        }
    }
}

/// [`polygon_texts`] of coordinates spelled by `text`: each polygon's text, or the first error
/// of `text`.
fn ring_texts<C>(
    polys: &[Polygon<C>],
    text: impl Fn(&C) -> Result<String, WriteError>,
    point: impl Fn(String, String) -> String,
    [open, close]: [&str; 2],
    sep: &str,
) -> Result<Vec<String>, WriteError> {
    let list = |items: Vec<String>| format!("{open}{}{close}", items.join(sep));
    let ring = |ring: &[Point<C>]| {
        let points = closed(ring).map(|p| Ok(point(text(&p.x)?, text(&p.y)?)));
        Ok(list(points.collect::<Result<_, WriteError>>()?))
    };
    let polygon = |p: &Polygon<C>| Ok(list(p.rings().map(ring).collect::<Result<_, _>>()?));
    polys.iter().map(polygon).collect()
}

/// The points of `ring` followed by its first point again (the closed form of the formats).
fn closed<N>(ring: &[Point<N>]) -> impl Iterator<Item = &Point<N>> {
    ring.iter().chain(ring.first())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::num::{Float, Rational};

    #[test]
    fn rings_open_and_close() {
        let p = |x| Point::<Rational>::int(x, 0);
        assert_eq!(
            open_ring(vec![p(1), p(2), p(3), p(1)]),
            vec![p(1), p(2), p(3)]
        );
        assert_eq!(open_ring(vec![p(1), p(2)]), vec![p(1), p(2)]);
        assert_eq!(open_ring(Vec::<Point<Rational>>::new()), vec![]);
        let ring = [p(1), p(2)];
        assert_eq!(
            closed(&ring).cloned().collect::<Vec<_>>(),
            vec![p(1), p(2), p(1)]
        );
        assert_eq!(closed::<Rational>(&[]).count(), 0);
    }

    #[test]
    fn ogc_rings_must_be_closed() {
        let p = |x| Point::<Rational>::int(x, 0);
        assert_eq!(
            ogc_ring(vec![p(1), p(2), p(3), p(1)]),
            Ok(vec![p(1), p(2), p(3)])
        );
        assert_eq!(
            ogc_ring(vec![p(1), p(2), p(3)]).unwrap_err(),
            "a ring of 3 points is not closed: its last point is not its first (OGC rings \
             repeat their first point at the end)"
        );
        assert_eq!(
            ogc_ring::<Rational>(vec![]).unwrap_err(),
            "a ring without points"
        );
    }

    #[test]
    fn readers_work_in_float_mode() {
        let wkt = wkt::read_polygons::<Float>("POLYGON ((0 0, 0.1 0, 0 1, 0 0))").unwrap();
        assert_eq!(wkt[0].exterior[1].x, Float::new(0.1));
        let json = r#"{"type": "Polygon", "coordinates": [[[0, 0], [0.1, 0], [0, 1], [0, 0]]]}"#;
        assert_eq!(geojson::read_polygons::<Float>(json).unwrap(), wkt);
        let curves = yin2_text::read_curves::<Float>("0 0\n0.1 0\n0 1\n").unwrap();
        assert_eq!(curves[0], wkt[0].exterior);
    }
}
