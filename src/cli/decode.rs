//! Text of any format → oriented rings, remembering where each ring came from for messages.

use super::format::Format;
use crate::io::{geojson, wkt, yin2_text, ParseError, Polygon};
use crate::kernel::Point;
use crate::num::Num;
use crate::yin2::YinError;
use std::cmp::Ordering;

/// The yin2 comment line that stands for the whole plane, which has no boundary curves.
pub const FULL_PLANE: &str = "# yinset: the whole plane (no boundary curves)";

/// What an input text holds.
pub enum Decoded<N> {
    /// The whole plane (a yin2 text with only the [`FULL_PLANE`] line).
    Full,
    /// Rings, each a vertex cycle (none: the empty set).
    Rings(Rings<N>),
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

/// Decode `text` in `format`.
pub fn decode<N: Num>(text: &str, format: Format) -> Result<Decoded<N>, ParseError> {
    let polygons = match format {
        Format::Yin2 => {
            let rings = yin2_text::read_curves(text)?;
            if rings.is_empty() && text.lines().any(|l| l.trim() == FULL_PLANE) {
                return Ok(Decoded::Full);
            }
            let origins = Origins(rings.iter().map(|_| Origin::Curve).collect());
            return Ok(Decoded::Rings(Rings { rings, origins }));
        }
        Format::Wkt => wkt::read_polygons(text)?,
        Format::Geojson => geojson::read_polygons(text)?,
    };
    Ok(Decoded::Rings(Rings::of_polygons(polygons)))
}

impl<N: Num> Rings<N> {
    /// The rings of OGC polygons, exteriors counterclockwise and interiors clockwise.
    fn of_polygons(polygons: Vec<Polygon<N>>) -> Rings<N> {
        let mut rings = Vec::new();
        let mut origins = Vec::new();
        for (polygon, p) in polygons.into_iter().enumerate() {
            let tagged = std::iter::once((None, p.exterior)).chain(
                p.interiors
                    .into_iter()
                    .enumerate()
                    .map(|(k, r)| (Some(k), r)),
            );
            for (ring, mut points) in tagged {
                let want = if ring.is_none() {
                    Ordering::Greater
                } else {
                    Ordering::Less
                };
                let reversed = twice_signed_area(&points).sign() == want.reverse();
                if reversed {
                    points.reverse();
                }
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

/// Twice the signed area of a vertex cycle (positive iff counterclockwise).
fn twice_signed_area<N: Num>(ring: &[Point<N>]) -> N {
    let next = ring.iter().cycle().skip(1);
    ring.iter().zip(next).fold(N::zero(), |acc, (p, q)| {
        acc + p.x.clone() * q.y.clone() - q.x.clone() * p.y.clone()
    })
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
    use crate::num::Rational;

    fn rings(text: &str, format: Format) -> Rings<Rational> {
        match decode(text, format).unwrap() {
            Decoded::Rings(r) => r,
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
            decode::<Rational>(&format!("{FULL_PLANE}\n"), Format::Yin2),
            Ok(Decoded::Full)
        ));
        assert_eq!(rings("# nothing\n", Format::Yin2).rings.len(), 0);
    }

    #[test]
    fn errors_are_located_in_polygon_terms() {
        let r = rings(
            r#"{"type":"MultiPolygon","coordinates":[[[[0,0],[1,0],[0,1]]],[[[0,0],[0,5],[5,0]],[[1,1],[2,1],[1,2]]]]}"#,
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
}
