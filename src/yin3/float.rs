//! 3D float mode (README, "3D float mode"): float sets are exactly valid sets of their `f64`
//! values, and every decision about them is made on those values read as rationals. An
//! operation is computed exactly and the result's vertices are rounded to the nearest `f64`s;
//! the rounded boundary is accepted only if it is valid exactly, otherwise the operation fails
//! with [`Yin3Error::Unrepresentable`]. Topology is the exact result's.

use super::error::Yin3Error;
use super::set::{Brep, YinSet3};
use super::validate::revalidate;
use crate::kernel::Point3;
use crate::num::{Num, Rational};
use std::collections::HashMap;

/// The meet of two float sets under the combined context `ctx` (module docs).
pub(crate) fn float_meet<N: Num>(
    a: &YinSet3<N>,
    b: &YinSet3<N>,
    ctx: N::Ctx,
) -> Result<YinSet3<N>, Yin3Error> {
    rounded_set(&exact_set(a).meet(&exact_set(b)), ctx)
}

/// The exact value of a float vertex.
fn exact_point<N: Num>(p: &Point3<N>) -> Point3<Rational> {
    let r = |v: &N| Rational::from_f64(v.to_f64()).expect("float sets have finite coordinates");
    Point3::new(r(&p.x), r(&p.y), r(&p.z))
}

/// The exact values of a float set's vertices.
pub(crate) fn exact_points<N: Num>(points: &[Point3<N>]) -> Vec<Point3<Rational>> {
    points.iter().map(exact_point).collect()
}

/// The boundary of a float set over its exact values: the same triangles, which form a valid
/// boundary because float sets are valid exactly.
pub(crate) fn exact_brep<N: Num>(b: &Brep<N>) -> Brep<Rational> {
    b.clone().map_points(exact_point)
}

/// The exact set of a float set's values ([`exact_brep`]).
fn exact_set<N: Num>(y: &YinSet3<N>) -> YinSet3<Rational> {
    match y.brep() {
        None if y.is_empty() => YinSet3::empty(),
        None => YinSet3::full(),
        Some(b) => YinSet3::from_brep(exact_brep(b), ()),
    }
}

/// The exact boundary `b` with every vertex rounded to the nearest `f64`. If none moved, the
/// exact structure is kept as it is. Otherwise vertices that round to one point are merged,
/// triangles that collapse to a segment or a point are dropped (each takes a pair of opposite
/// fins off an edge, so closed surfaces stay closed), and the rounded boundary is validated
/// exactly; any failure is [`Yin3Error::Unrepresentable`].
pub(crate) fn rounded_brep<N: Num>(b: &Brep<Rational>) -> Result<Brep<N>, Yin3Error> {
    let unrepresentable = |e: &dyn std::fmt::Display| Yin3Error::Unrepresentable(e.to_string());
    let round = |p: &Point3<Rational>| {
        let f = |v: &Rational| N::from_f64(v.to_f64()).map_err(|e| unrepresentable(&e));
        Ok(Point3::new(f(&p.x)?, f(&p.y)?, f(&p.z)?))
    };
    let rounded = b.points.iter().map(round).collect::<Result<Vec<_>, _>>()?;
    if rounded
        .iter()
        .zip(&b.points)
        .all(|(q, p)| exact_point(q) == *p)
    {
        // Distinct exact points, each an f64 already: the same boundary, no work to redo.
        let mut points = rounded.into_iter();
        return Ok(b
            .clone()
            .map_points(|_| points.next().expect("one rounded point per point")));
    }
    let mut index: HashMap<Point3<N>, usize> = HashMap::new();
    let mut points = Vec::new();
    let mut new = Vec::with_capacity(rounded.len());
    for q in rounded {
        let next = points.len();
        let i = *index.entry(q.clone()).or_insert(next);
        if i == next {
            points.push(q);
        }
        new.push(i);
    }
    let tris: Vec<[usize; 3]> = b
        .tris
        .iter()
        .map(|t| t.map(|v| new[v]))
        .filter(|[p, q, r]| p != q && q != r && r != p)
        .collect();
    if tris.is_empty() {
        return Err(unrepresentable(&"every triangle collapsed when rounded"));
    }
    let brep = Brep::assemble(points, tris).map_err(|e| unrepresentable(&e))?;
    revalidate(exact_points(&brep.points), &brep, ()).map_err(|e| unrepresentable(&e))?;
    Ok(brep)
}

/// The exact set `y` rounded ([`rounded_brep`]), under the context `ctx`.
fn rounded_set<N: Num>(y: &YinSet3<Rational>, ctx: N::Ctx) -> Result<YinSet3<N>, Yin3Error> {
    Ok(match y.brep() {
        Some(b) => YinSet3::from_brep(rounded_brep(b)?, ctx),
        None if y.is_empty() => YinSet3::empty().with_ctx(ctx),
        None => YinSet3::full().with_ctx(ctx),
    })
}
