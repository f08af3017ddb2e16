//! The peers' side: the same `f64` curves in each peer's own types, and their Boolean
//! operations. Every peer reads the curves under the even-odd rule (all workloads are bounded
//! sets whose curves are pairwise almost disjoint, so even-odd is exactly the Yin set), except
//! W6's union of overlapping rings, read under the non-zero rule.

use super::common::Curves;
use geo::{unary_union, Area, BooleanOps, LineString, MultiPolygon, Polygon};
use i_overlay::core::fill_rule::FillRule as IFill;
use i_overlay::core::overlay_rule::OverlayRule;
use i_overlay::float::simplify::SimplifyShape;
use i_overlay::float::single::SingleFloatOverlay;

/// Intersection or union.
#[derive(Clone, Copy, Debug)]
pub enum Op {
    Meet,
    Join,
}

/// i_overlay's input: the contours as they are (its default `i32` engine, no multithreading).
pub fn i_overlay_input(c: &Curves) -> Curves {
    c.clone()
}

/// i_overlay on two contour sets; returns the shapes (outer contour, then holes).
pub fn i_overlay_op(a: &Curves, b: &Curves, op: Op) -> Vec<Vec<Vec<[f64; 2]>>> {
    let rule = match op {
        Op::Meet => OverlayRule::Intersect,
        Op::Join => OverlayRule::Union,
    };
    a.overlay(b, rule, IFill::EvenOdd)
}

/// i_overlay's union of all contours under the non-zero rule (its `simplify_shape`).
pub fn i_overlay_union(a: &Curves) -> Vec<Vec<Vec<[f64; 2]>>> {
    a.simplify_shape(IFill::NonZero)
}

/// The area of i_overlay's result (outer contours counterclockwise, holes clockwise).
pub fn i_overlay_area(shapes: &[Vec<Vec<[f64; 2]>>]) -> f64 {
    shapes.iter().flatten().map(|c| shoelace(c)).sum()
}

/// geo's input: one polygon per curve (geo's BooleanOps reads all rings with a fill rule).
pub fn geo_input(c: &Curves) -> MultiPolygon<f64> {
    MultiPolygon(
        c.iter()
            .map(|ring| {
                let mut pts: Vec<(f64, f64)> = ring.iter().map(|p| (p[0], p[1])).collect();
                pts.push(pts[0]);
                Polygon::new(LineString::from(pts), vec![])
            })
            .collect(),
    )
}

/// geo's BooleanOps (geo 0.33 runs i_overlay 4.5 underneath, with OGC output options).
pub fn geo_op(a: &MultiPolygon<f64>, b: &MultiPolygon<f64>, op: Op) -> MultiPolygon<f64> {
    match op {
        Op::Meet => a.intersection(b),
        Op::Join => a.union(b),
    }
}

/// geo's `unary_union` of the polygons (i_overlay underneath, with the fill rule of the
/// first ring's orientation: positive for counterclockwise rings).
pub fn geo_union(m: &MultiPolygon<f64>) -> MultiPolygon<f64> {
    unary_union(&m.0)
}

/// The area of geo's result.
pub fn geo_area(m: &MultiPolygon<f64>) -> f64 {
    m.unsigned_area()
}

/// Clipper2's coordinate scale: 10⁹ (its integer grid; the crate's default is 100).
#[derive(Debug, Default, Copy, Clone, PartialEq, Hash)]
pub struct Nano;

impl clipper2::PointScaler for Nano {
    const MULTIPLIER: f64 = 1e9;
}

/// Clipper2's input.
pub fn clipper_input(c: &Curves) -> clipper2::Paths<Nano> {
    c.clone().into()
}

/// Clipper2 (the C++ library through the `clipper2` crate). The operands are cloned into the
/// call, as the crate's API consumes them.
pub fn clipper_op(
    a: &clipper2::Paths<Nano>,
    b: &clipper2::Paths<Nano>,
    op: Op,
) -> clipper2::Paths<Nano> {
    let fill = clipper2::FillRule::EvenOdd;
    let r = match op {
        Op::Meet => clipper2::intersect(a.clone(), b.clone(), fill),
        Op::Join => clipper2::union(a.clone(), b.clone(), fill),
    };
    r.expect("clipper2 failed")
}

/// Clipper2's union of all paths as one subject, with no clip, under the non-zero rule.
pub fn clipper_union(a: &clipper2::Paths<Nano>) -> clipper2::Paths<Nano> {
    clipper2::union(
        a.clone(),
        clipper2::Paths::new(vec![]),
        clipper2::FillRule::NonZero,
    )
    .expect("clipper2 failed")
}

/// The area of Clipper2's result.
pub fn clipper_area(p: &clipper2::Paths<Nano>) -> f64 {
    p.signed_area()
}

/// The signed area of a closed polygon (counterclockwise positive).
pub fn shoelace(c: &[[f64; 2]]) -> f64 {
    let n = c.len();
    (0..n)
        .map(|k| {
            let (p, q) = (c[k], c[(k + 1) % n]);
            p[0] * q[1] - p[1] * q[0]
        })
        .sum::<f64>()
        / 2.0
}
