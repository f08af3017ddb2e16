//! The input vertices of the transversal meet ([`super::transversal`]) with the exact tests and
//! constructions it makes on them: `f64` values (float sets, and exact sets scaled to a common
//! integer grid) on static filters and stack integers, or the exact rationals of any other
//! exact set on their own filtered predicates.

use super::geom::{widened_box, Chart};
use super::pierce::{pierce, pierce_f64, pierce_rational};
use crate::kernel::{orient3d, Point3};
use crate::num::{
    exact_orient, exact_orient3d_f64, exact_orient_f64, filtered_orient, filtered_orient3d, Num,
    PlaneF64, Rational,
};
use rstar::AABB;
use std::cmp::Ordering;

/// Input vertices by index, with exact predicates on them and the exact points they define.
pub(super) trait Corners: Sync {
    /// The plane of a triangle, prepared for many side tests.
    type Plane: Send + Sync;

    /// True if vertices `x` and `y` are the same point.
    fn same(&self, x: usize, y: usize) -> bool;

    /// The sign of det[b − a, c − a, d − a] for the vertices `[a, b, c, d]`.
    fn orient3d(&self, v: [usize; 4]) -> Ordering;

    /// The plane of the triangle `t`.
    fn plane(&self, t: [usize; 3]) -> Self::Plane;

    /// [`Corners::orient3d`] of the plane's triangle and the vertex `d`.
    fn side(&self, plane: &Self::Plane, d: usize) -> Ordering;

    /// An `f64` box holding the triangle `t`.
    fn bbox(&self, t: [usize; 3]) -> AABB<[f64; 3]>;

    /// The point where the edge `(u, v)` pierces the plane of the triangle `tri` (u and v
    /// strictly on either side), the same whichever triangle of the edge asks.
    fn pierce(&self, edge: (usize, usize), tri: [usize; 3]) -> Point3<Rational>;

    /// The chart in which the triangle `t` is counterclockwise; `None` if it is degenerate.
    fn chart(&self, t: [usize; 3]) -> Option<Chart>;

    /// The orientation of the images of the vertices `[a, b, c]` in `chart`.
    fn orient2d(&self, chart: &Chart, v: [usize; 3]) -> Ordering;

    /// The point where the coplanar edges `e` and `f` cross, their images in `chart` crossing
    /// properly: where `f` pierces the plane through `e` along the coordinate the chart drops
    /// ([`off_along`]), the same value however the pair is met.
    fn crossing(&self, chart: &Chart, e: (usize, usize), f: (usize, usize)) -> Point3<Rational>;
}

/// The corner `a` moved along coordinate `k` to a value of that coordinate's own grid: to its
/// negative, or to 1 from 0 (a third point of a plane through `a` along that axis).
fn off_along<T: Clone + PartialEq + std::ops::Neg<Output = T>>(
    a: [T; 3],
    k: usize,
    zero: T,
    one: T,
) -> [T; 3] {
    let mut c = a;
    c[k] = match c[k] == zero {
        true => one,
        false => -c[k].clone(),
    };
    c
}

/// Vertices that are `f64` points, read exactly.
pub(super) struct F64Corners(pub Vec<[f64; 3]>);

impl Corners for F64Corners {
    type Plane = PlaneF64;

    fn same(&self, x: usize, y: usize) -> bool {
        self.0[x] == self.0[y]
    }

    fn orient3d(&self, [a, b, c, d]: [usize; 4]) -> Ordering {
        let p = &self.0;
        exact_orient3d_f64(p[a], p[b], p[c], p[d])
    }

    fn plane(&self, t: [usize; 3]) -> PlaneF64 {
        PlaneF64::of_triangle(&self.0, t)
    }

    fn side(&self, plane: &PlaneF64, d: usize) -> Ordering {
        plane.side(self.0[d])
    }

    fn bbox(&self, t: [usize; 3]) -> AABB<[f64; 3]> {
        AABB::from_points(t.map(|v| &self.0[v]))
    }

    fn pierce(&self, edge: (usize, usize), tri: [usize; 3]) -> Point3<Rational> {
        pierce(&self.0, edge, tri)
    }

    fn chart(&self, t: [usize; 3]) -> Option<Chart> {
        Chart::of_f64_triangle(t.map(|v| self.0[v]))
    }

    fn orient2d(&self, chart: &Chart, v: [usize; 3]) -> Ordering {
        let [a, b, c] = v.map(|v| chart.image_f64(self.0[v]));
        exact_orient_f64(a, b, c)
    }

    fn crossing(&self, chart: &Chart, e: (usize, usize), f: (usize, usize)) -> Point3<Rational> {
        let p = &self.0;
        let c = off_along(p[e.0], chart.dropped(), 0.0, 1.0);
        pierce_f64([p[f.0], p[f.1], p[e.0], p[e.1], c])
    }
}

/// Vertices that are exact rationals, with their nearest `f64`s: the corners of boxes and the
/// input of the orientation filter.
pub(super) struct RationalCorners {
    points: Vec<Point3<Rational>>,
    near: Vec<[f64; 3]>,
}

impl RationalCorners {
    /// The vertices `points`.
    pub(super) fn new(points: Vec<Point3<Rational>>) -> RationalCorners {
        let near = points.iter().map(Point3::to_f64).collect();
        RationalCorners { points, near }
    }
}

impl Corners for RationalCorners {
    type Plane = [usize; 3];

    fn same(&self, x: usize, y: usize) -> bool {
        self.points[x] == self.points[y]
    }

    fn orient3d(&self, [a, b, c, d]: [usize; 4]) -> Ordering {
        let q = &self.near;
        filtered_orient3d(q[a], q[b], q[c], q[d]).unwrap_or_else(|| {
            let p = &self.points;
            orient3d(&p[a], &p[b], &p[c], &p[d], &())
        })
    }

    fn plane(&self, t: [usize; 3]) -> [usize; 3] {
        t
    }

    fn side(&self, &[a, b, c]: &[usize; 3], d: usize) -> Ordering {
        self.orient3d([a, b, c, d])
    }

    fn bbox(&self, t: [usize; 3]) -> AABB<[f64; 3]> {
        widened_box(t.map(|v| self.near[v]))
    }

    fn pierce(&self, (u, v): (usize, usize), [a, b, c]: [usize; 3]) -> Point3<Rational> {
        pierce_rational([u, v, a, b, c].map(|i| &self.points[i]))
    }

    fn chart(&self, t: [usize; 3]) -> Option<Chart> {
        let [a, b, c] = t.map(|v| &self.points[v]);
        Chart::checked_of_triangle(a, b, c)
    }

    fn orient2d(&self, chart: &Chart, v: [usize; 3]) -> Ordering {
        let [a, b, c] = v.map(|v| chart.image_f64(self.near[v]));
        filtered_orient(a, b, c).unwrap_or_else(|| {
            let [a, b, c] = v.map(|v| chart.image_of(&self.points[v]));
            exact_orient(a, b, c)
        })
    }

    fn crossing(&self, chart: &Chart, e: (usize, usize), f: (usize, usize)) -> Point3<Rational> {
        let p = &self.points;
        let a = [0, 1, 2].map(|k| p[e.0].coord(k).clone());
        let [x, y, z] = off_along(a, chart.dropped(), Rational::zero(), Rational::from_i64(1));
        let c = Point3::new(x, y, z);
        pierce_rational([&p[f.0], &p[f.1], &p[e.0], &p[e.1], &c])
    }
}
