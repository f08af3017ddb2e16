//! Point location by a symbolically perturbed ray (yin3 docs: *Locate*): deterministic and exact,
//! with rays through edges and vertices decided by the perturbation q + (0, ε, ε²).

use super::geom::{f64_box, in_triangle3};
use super::near::within;
use crate::kernel::{orient, orient3d, Point, Point3};
use crate::num::Num;
use rstar::{primitives::GeomWithData, primitives::Rectangle, RTree, AABB};
use std::cmp::Ordering;

/// An R-tree of the `f64` boxes of triangles, each widened to contain the exact box (a
/// bounding-volume hierarchy): the broad phase of point location, so that a point or a ray
/// meets only the triangles near it instead of all of them.
pub(crate) struct TriBoxes(RTree<GeomWithData<Rectangle<[f64; 3]>, usize>>);

impl TriBoxes {
    /// The boxes of the triangles `tris`, each named by the index given with it.
    pub(crate) fn new<'a, N: Num>(
        tris: impl IntoIterator<Item = (usize, [&'a Point3<N>; 3])>,
    ) -> TriBoxes {
        TriBoxes::of_boxes(tris.into_iter().map(|(i, t)| (i, f64_box(t))))
    }

    /// The boxes given, each named by the index given with it.
    pub(crate) fn of_boxes(boxes: impl IntoIterator<Item = (usize, AABB<[f64; 3]>)>) -> TriBoxes {
        TriBoxes(RTree::bulk_load(
            (boxes.into_iter())
                .map(|(i, b)| GeomWithData::new(Rectangle::from_aabb(b), i))
                .collect(),
        ))
    }

    /// The triangles whose box, widened by `slack` (float mode's ε; 0 in exact mode),
    /// contains `q`: all that [`on_triangles`] can find `q` on (the sums rounded outward, so
    /// that a triangle exactly `slack` away is among them).
    pub(crate) fn at<N: Num>(&self, q: &Point3<N>, slack: f64) -> impl Iterator<Item = usize> + '_ {
        let b = f64_box([q]);
        let lower = b.lower().map(|x| (x - slack).next_down());
        let upper = b.upper().map(|x| (x + slack).next_up());
        let near = AABB::from_corners(lower, upper);
        self.0
            .locate_in_envelope_intersecting(&near)
            .map(|g| g.data)
    }

    /// The triangles whose box meets the ray from `q` along +x: all that can count in
    /// [`winding`] at `q` (a crossing needs q's y and z in the triangle's closed box and a
    /// corner with x ≥ q's).
    pub(crate) fn along_x<N: Num>(&self, q: &Point3<N>) -> impl Iterator<Item = usize> + '_ {
        self.0
            .locate_in_envelope_intersecting(&ray_box(q))
            .map(|g| g.data)
    }
}

/// A box holding the ray from `q` along +x: a triangle counts in [`winding`] at `q` only if
/// its box (holding its exact box) meets this one — q's y and z in the triangle's closed box,
/// a corner with x ≥ q's.
pub(crate) fn ray_box<N: Num>(q: &Point3<N>) -> AABB<[f64; 3]> {
    let b = f64_box([q]);
    let mut hi = b.upper();
    hi[0] = f64::MAX;
    AABB::from_corners(b.lower(), hi)
}

/// The winding number at `q` of the oriented triangles `tris`: the sum of sign(n_x) over the
/// triangles that the ray from q + (0, ε, ε²) in direction +x crosses. `q` must lie on none of
/// them. For the boundary of a Yin set 𝒴 it is 1_𝒴(q), or 1_𝒴(q) − 1 if 𝒴 is unbounded.
pub(crate) fn winding<'a, N: Num>(
    tris: impl IntoIterator<Item = [&'a Point3<N>; 3]>,
    q: &Point3<N>,
    ctx: &N::Ctx,
) -> i64 {
    tris.into_iter().map(|t| crossing(t, q, ctx)).sum()
}

/// True if `q` lies on one of the closed triangles, or for `eps > 0` (float mode's ε) if its
/// Euclidean distance to one is at most `eps` ([`within`]).
pub(crate) fn on_triangles<'a, N: Num>(
    tris: impl IntoIterator<Item = [&'a Point3<N>; 3]>,
    q: &Point3<N>,
    eps: f64,
) -> bool {
    let exact = N::exact_ctx();
    tris.into_iter().any(|t| match eps > 0.0 {
        true => within(t, q, eps),
        false => in_triangle3(t, q, &exact),
    })
}

/// True if `q`'s coordinates `axes` lie in the closed box of the triangle's.
fn in_box<N: Num>(t: [&Point3<N>; 3], q: &Point3<N>, axes: [usize; 3]) -> bool {
    axes.iter().all(|&k| {
        let v = q.coord(k);
        t.iter().any(|p| p.coord(k) <= v) && t.iter().any(|p| p.coord(k) >= v)
    })
}

/// The contribution of triangle `t` to the winding number at `q`: ±1 if the perturbed ray
/// crosses it (the sign of its normal's x), 0 otherwise; triangles parallel to x never count.
fn crossing<N: Num>(t: [&Point3<N>; 3], q: &Point3<N>, ctx: &N::Ctx) -> i64 {
    if !in_box(t, q, [1, 2, 1]) || t.iter().all(|p| p.x < q.x) {
        return 0;
    }
    let yz = |p: &Point3<N>| Point::new(p.y.clone(), p.z.clone());
    let (a, mut b, mut c) = (yz(t[0]), yz(t[1]), yz(t[2]));
    let nx = orient(&a, &b, &c, ctx);
    if nx == Ordering::Equal {
        return 0;
    }
    if nx == Ordering::Less {
        std::mem::swap(&mut b, &mut c);
    }
    let qp = yz(q);
    let inside = [(&a, &b), (&b, &c), (&c, &a)]
        .iter()
        .all(|(u, v)| left_of_perturbed(u, v, &qp, ctx));
    if !inside {
        return 0;
    }
    // The ray meets the plane beyond q iff q is on the side the normal's x points away from.
    let side = orient3d(t[0], t[1], t[2], q, ctx);
    if side == Ordering::Equal || side == nx {
        return 0;
    }
    if nx == Ordering::Greater {
        1
    } else {
        -1
    }
}

/// True if q + (ε, ε²) is strictly left of the directed line u → v: on a tie the sign of
/// (v − u) × (ε, ε²) = −(v_z − u_z) ε + (v_y − u_y) ε² decides.
fn left_of_perturbed<N: Num>(u: &Point<N>, v: &Point<N>, q: &Point<N>, ctx: &N::Ctx) -> bool {
    match orient(u, v, q, ctx) {
        Ordering::Greater => true,
        Ordering::Less => false,
        Ordering::Equal => match v.y.cmp(&u.y) {
            Ordering::Less => true,
            Ordering::Greater => false,
            Ordering::Equal => v.x > u.x,
        },
    }
}
