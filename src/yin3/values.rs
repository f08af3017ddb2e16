//! The exact values of points: their coordinates read as rationals (a float point's `f64`s).

use crate::kernel::Point3;
use crate::num::{Num, Rational};

/// The exact value of a vertex ([`Num::rational`]).
pub(crate) fn exact_point<N: Num>(p: &Point3<N>) -> Point3<Rational> {
    Point3::new(p.x.rational(), p.y.rational(), p.z.rational())
}

/// The exact values of a float set's vertices.
pub(crate) fn exact_points<N: Num>(points: &[Point3<N>]) -> Vec<Point3<Rational>> {
    points.iter().map(exact_point).collect()
}
