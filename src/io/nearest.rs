//! The `f64` coordinates of polygons for the writers that hold `f64`s (WKT and GeoJSON
//! decimals, WKB, `geo_types`): one rule, so that what they write reads back as a set.
//!
//! Rounding: each coordinate becomes its nearest `f64`, which must be finite; and where that
//! moves any vertex of polygons that bound a valid Yin set (as a set's polygons always do),
//! the rounded rings must still bound a valid Yin set with each ring oriented as before
//! (checked exactly by the validator: no vertices merged, no edges crossing or overlapping,
//! nesting and orientations kept). A set that fails is refused with an error naming the
//! vertex or ring, never written as rings that collapse, cross or turn round (a square of
//! side 10⁻⁴⁰⁰ would otherwise be written `(0 0, 0 0, 0 0, 0 0, 0 0)`). A coordinate whose
//! nearest `f64` is another nonzero value is fine: that is the documented output.
//!
//! Exact: every coordinate must be an `f64` already, else an error names the first that is not.

use super::{twice_signed_area, Polygon, WriteError};
use crate::kernel::Point;
use crate::num::Num;
use crate::yin2::{YinError, YinSet2};

/// What to suggest when the `f64`s cannot hold a set.
const EXACTLY: &str = "write the set exactly instead (WKT with --exact, or yin2)";

/// `polys` with every coordinate rounded to its nearest `f64`, or why the rounded rings would
/// not read back as the set's (see the [module documentation](self)).
pub(crate) fn nearest_polygons<N: Num>(
    polys: &[Polygon<N>],
) -> Result<Vec<Polygon<f64>>, WriteError> {
    let mut moved = false;
    let mut rounded: Vec<Vec<Vec<Point<N>>>> = Vec::with_capacity(polys.len());
    for (k, polygon) in polys.iter().enumerate() {
        let mut rings = Vec::new();
        for (r, ring) in polygon.rings().enumerate() {
            let mut points = Vec::with_capacity(ring.len());
            for (v, p) in ring.iter().enumerate() {
                let (Some(x), Some(y)) = (nearest(&p.x), nearest(&p.y)) else {
                    let c = if nearest(&p.x).is_none() { &p.x } else { &p.y };
                    return Err(WriteError(format!(
                        "the coordinate {c} of vertex {v} {p} of {} is beyond the range of \
                         f64: {EXACTLY}",
                        ring_name(k, r)
                    )));
                };
                moved |= x != p.x || y != p.y;
                points.push(Point { x, y });
            }
            rings.push(points);
        }
        rounded.push(rings);
    }
    if moved {
        check_rounded(polys, &rounded)?;
    }
    Ok(rounded.iter().map(|rings| to_f64_polygon(rings)).collect())
}

/// `polys` as `f64`s if every coordinate is one, else an error naming the first that is not.
pub(crate) fn exact_f64_polygons<N: Num>(
    polys: &[Polygon<N>],
) -> Result<Vec<Polygon<f64>>, WriteError> {
    polys
        .iter()
        .enumerate()
        .map(|(k, polygon)| {
            let rings = polygon.rings().enumerate().map(|(r, ring)| {
                ring.iter()
                    .enumerate()
                    .map(|(v, p)| match (nearest(&p.x), nearest(&p.y)) {
                        (Some(x), Some(y)) if x == p.x && y == p.y => Ok(Point { x, y }),
                        _ => {
                            let c = if nearest(&p.x).as_ref() == Some(&p.x) {
                                &p.y
                            } else {
                                &p.x
                            };
                            Err(WriteError(format!(
                                "the coordinate {c} of vertex {v} {p} of {} is not an f64, and \
                                 WKB holds only f64s: write the nearest f64s (without --exact), \
                                 or WKT or yin2 exactly",
                                ring_name(k, r)
                            )))
                        }
                    })
                    .collect::<Result<Vec<_>, _>>()
            });
            Ok(to_f64_polygon(&rings.collect::<Result<Vec<_>, _>>()?))
        })
        .collect()
}

/// The nearest `f64` of `n` as a number of `n`'s type, `None` if it is beyond the range of
/// `f64`.
fn nearest<N: Num>(n: &N) -> Option<N> {
    N::from_f64(n.to_f64()).ok()
}

/// The polygon of `rings` (the exterior first), its coordinates `f64`s (exactly: each is one).
fn to_f64_polygon<N: Num>(rings: &[Vec<Point<N>>]) -> Polygon<f64> {
    let ring = |points: &Vec<Point<N>>| -> Vec<Point<f64>> {
        points
            .iter()
            .map(|p| Point {
                x: p.x.to_f64(),
                y: p.y.to_f64(),
            })
            .collect()
    };
    let mut rings = rings.iter().map(ring);
    Polygon {
        exterior: rings.next().unwrap_or_default(),
        interiors: rings.collect(),
    }
}

/// An error if `polys` bound a valid Yin set but their `rounded` rings do not, or do with a
/// ring oriented otherwise (polygons that bound no set before rounding are not checked).
fn check_rounded<N: Num>(
    polys: &[Polygon<N>],
    rounded: &[Vec<Vec<Point<N>>>],
) -> Result<(), WriteError> {
    let origins: Vec<(usize, usize, &[Point<N>])> = polys
        .iter()
        .enumerate()
        .flat_map(|(k, p)| p.rings().enumerate().map(move |(r, ring)| (k, r, ring)))
        .collect();
    let a_set = || YinSet2::from_curves(origins.iter().map(|o| o.2.to_vec()).collect()).is_ok();
    if let Err(e) = YinSet2::from_curves(rounded.iter().flatten().cloned().collect()) {
        if !a_set() {
            return Ok(());
        }
        let place = match named_vertex(&e) {
            Some((c, v)) => origins.get(c).and_then(|(k, r, ring)| {
                let p = ring.get(v)?;
                Some(format!(
                    "vertex {v} of {} is {p} before rounding",
                    ring_name(*k, *r)
                ))
            }),
            None => named_curve(&e).and_then(|c| {
                let (k, r, _) = origins.get(c)?;
                Some(format!("curve {c} is {}", ring_name(*k, *r)))
            }),
        };
        let place = place.map_or(String::new(), |p| format!(" ({p})"));
        return Err(WriteError(format!(
            "rounded to the nearest f64s, the rings do not bound a valid set: {e}{place}: \
             {EXACTLY}"
        )));
    }
    // Neighbours merged by rounding where the validator sees none: a last vertex rounded onto
    // the first, which it takes for the closing repeat and drops.
    let merged = origins
        .iter()
        .zip(rounded.iter().flatten())
        .find_map(|((k, r, ring), curve)| {
            let n = ring.len();
            let v = (0..n).find(|&i| {
                let j = (i + 1) % n;
                curve[i] == curve[j] && ring[i] != ring[j]
            })?;
            Some((*k, *r, v, (v + 1) % n, ring))
        });
    if let Some((k, r, v, w, ring)) = merged {
        if a_set() {
            return Err(WriteError(format!(
                "rounded to the nearest f64s, vertices {v} {} and {w} {} of {} coincide: \
                 {EXACTLY}",
                ring[v],
                ring[w],
                ring_name(k, r)
            )));
        }
    }
    let curves = rounded.iter().flatten();
    let turned = origins.iter().zip(curves).find(|((_, _, ring), curve)| {
        twice_signed_area(curve).sign() != twice_signed_area(ring).sign()
    });
    match turned {
        Some(((k, r, _), _)) if a_set() => Err(WriteError(format!(
            "rounded to the nearest f64s, {} turns round (the sign of its area changes): \
             {EXACTLY}",
            ring_name(*k, *r)
        ))),
        _ => Ok(()),
    }
}

/// The curve and vertex an error names first, if it names a vertex.
fn named_vertex(e: &YinError) -> Option<(usize, usize)> {
    match *e {
        YinError::NotFinite { curve, vertex }
        | YinError::RepeatedVertex { curve, vertex, .. }
        | YinError::NotSimple { curve, vertex, .. } => Some((curve, vertex)),
        YinError::ProperCrossing {
            curve_a, vertex_a, ..
        }
        | YinError::SharedEdge {
            curve_a, vertex_a, ..
        } => Some((curve_a, vertex_a)),
        _ => None,
    }
}

/// The curve an error names first, if any.
fn named_curve(e: &YinError) -> Option<usize> {
    match e {
        YinError::TooFewVertices { curve, .. } => Some(*curve),
        YinError::NestedSameOrientation { inner, .. } => Some(*inner),
        YinError::MixedOutermost { positive, .. } => Some(*positive),
        YinError::DisconnectedAtom { curves, .. } => curves.first().copied(),
        _ => named_vertex(e).map(|(c, _)| c),
    }
}

/// "polygon K's exterior ring" for ring 0, "polygon K's interior ring R−1" for the others.
fn ring_name(polygon: usize, ring: usize) -> String {
    match ring {
        0 => format!("polygon {polygon}'s exterior ring"),
        r => format!("polygon {polygon}'s interior ring {}", r - 1),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::num::Rational;

    fn q(s: &str) -> Rational {
        Rational::parse(s).unwrap()
    }

    /// The square [x, x + side]², counterclockwise, as one polygon.
    fn square(x: &str, side: &str) -> Polygon<Rational> {
        let (a, b) = (q(x), q(x) + q(side));
        let p = |x: &Rational, y: &Rational| Point::new(x.clone(), y.clone());
        Polygon {
            exterior: vec![p(&a, &a), p(&b, &a), p(&b, &b), p(&a, &b)],
            interiors: vec![],
        }
    }

    #[test]
    fn values_that_round_to_other_nonzero_f64s_are_written() {
        let third = nearest_polygons(&[square("0", "1/3")]).unwrap();
        assert_eq!(third[0].exterior[1].x, 1.0 / 3.0);
        assert_eq!(third[0].exterior[2].y, 1.0 / 3.0);
        let tiny = nearest_polygons(&[square("1e-300", "1e-300")]).unwrap();
        assert_eq!(tiny[0].exterior[2].x, 2e-300);
    }

    #[test]
    fn rings_that_collapse_when_rounded_are_refused_naming_the_vertex() {
        let e = nearest_polygons(&[square("0", "1e-400")]).unwrap_err().0;
        assert!(
            e.contains("curve 0, vertex 1: repeats the previous vertex (0, 0)"),
            "{e}"
        );
        assert!(
            e.contains("vertex 1 of polygon 0's exterior ring is (1/1"),
            "{e}"
        );
        assert!(e.contains("--exact"), "{e}");
        // Two squares 10⁻⁴⁰⁰ apart: each survives rounding alone, together they share an edge.
        let p = |x: &str, y: &str| Point::new(q(x), q(y));
        let right = Polygon {
            exterior: vec![
                p("1.0000000000000000000001", "0"),
                p("2", "0"),
                p("2", "1"),
                p("1.0000000000000000000001", "1"),
            ],
            interiors: vec![],
        };
        let apart = [square("0", "1"), right];
        let e = nearest_polygons(&apart).unwrap_err().0;
        assert!(e.contains("share the edge"), "{e}");
        assert!(e.contains("'s exterior ring is (1"), "{e}");
    }

    /// A quadrilateral whose last vertex rounds onto its first: the rounded ring is a valid
    /// triangle, but the set written would not be the set.
    #[test]
    fn a_last_vertex_rounded_onto_the_first_is_refused() {
        let p = |x: &str, y: &str| Point::new(q(x), q(y));
        let quad = Polygon {
            exterior: vec![p("0", "0"), p("1", "0"), p("1", "1"), p("1e-400", "2e-400")],
            interiors: vec![],
        };
        let e = nearest_polygons(&[quad]).unwrap_err().0;
        assert!(e.contains("vertices 3 (1/1"), "{e}");
        assert!(
            e.contains("and 0 (0, 0) of polygon 0's exterior ring coincide"),
            "{e}"
        );
    }

    #[test]
    fn a_ring_flattened_or_turned_round_by_rounding_is_refused() {
        let p = |x: &str, y: &str| Point::new(q(x), q(y));
        let polygon = |exterior| Polygon {
            exterior,
            interiors: vec![],
        };
        // A triangle so thin that rounding puts its apex on its base.
        let sliver = polygon(vec![p("0", "0"), p("1", "0"), p("1/2", "1e-400")]);
        let e = nearest_polygons(&[sliver]).unwrap_err().0;
        assert!(e.contains("the rings do not bound a valid set"), "{e}");
        assert!(e.contains("of polygon 0's exterior ring is"), "{e}");
        // A triangle an ulp across near (1, 1), counterclockwise; its corners round to
        // (1, 1), (1 + 2u, 1 + u), (1 + 4u, 1 + u) (u = 2⁻⁵²): a clockwise triangle, which
        // alone is a valid (unbounded) set, so only its orientation tells.
        let u = q("1/4503599627370496");
        let at = |x: i64, y: &str| {
            let c = |k: Rational| q("1") + k * u.clone();
            Point::new(c(Rational::from_i64(x)), c(q(y)))
        };
        let thin = polygon(vec![at(0, "49/100"), at(2, "6/10"), at(4, "149/100")]);
        assert!(twice_signed_area(&thin.exterior).sign().is_gt());
        let e = nearest_polygons(&[thin]).unwrap_err().0;
        assert!(
            e.starts_with("rounded to the nearest f64s, polygon 0's exterior ring turns round"),
            "{e}"
        );
    }

    #[test]
    fn coordinates_beyond_f64_are_refused_naming_the_vertex() {
        let e = nearest_polygons(&[square("1e400", "1")]).unwrap_err().0;
        assert!(e.starts_with("the coordinate 1"), "{e}");
        assert!(e.contains("of vertex 0 (1"), "{e}");
        assert!(
            e.contains("of polygon 0's exterior ring is beyond the range of f64"),
            "{e}"
        );
        let e = exact_f64_polygons(&[square("1e400", "1")]).unwrap_err().0;
        assert!(e.contains("is not an f64"), "{e}");
    }

    #[test]
    fn exact_f64s_only_where_every_coordinate_is_one() {
        let half = exact_f64_polygons(&[square("0.5", "0.25")]).unwrap();
        assert_eq!(half[0].exterior[2].x, 0.75);
        let e = exact_f64_polygons(&[square("0", "0.1")]).unwrap_err().0;
        assert!(
            e.starts_with("the coordinate 1/10 of vertex 1 (1/10, 0) of polygon 0's exterior ring"),
            "{e}"
        );
    }
}
