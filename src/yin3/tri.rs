//! Triangle–triangle intersection with every coplanar and touching case (seed 004 step 1;
//! DESIGN-3D §2.3): the contact points, the segments each triangle must be cut along, and
//! whether the two relative interiors meet (a crossing or an overlap).

use super::geom::{dominant_axis, in_triangle2, normal, Chart};
use crate::kernel::{classify, orient, orient3d, Contact, Point, Point3};
use crate::num::Num;
use std::cmp::Ordering;

/// How two closed triangles `t` and `s` meet.
#[derive(Clone, Debug)]
pub(crate) struct TriContact<N> {
    /// The vertices of the intersection (each a point of both triangles).
    pub points: Vec<Point3<N>>,
    /// Segments of the intersection that `t` must be cut along.
    pub cuts_t: Vec<(Point3<N>, Point3<N>)>,
    /// Segments of the intersection that `s` must be cut along.
    pub cuts_s: Vec<(Point3<N>, Point3<N>)>,
    /// True if the relative interiors meet: the triangles cross (not coplanar) or overlap in
    /// an area (coplanar). Legal contacts — a vertex or an edge on the other — leave it false.
    pub interiors_meet: bool,
    /// True if the triangles are coplanar.
    pub coplanar: bool,
}

/// The intersection of the closed, non-degenerate triangles `t` and `s`; `None` if disjoint.
pub(crate) fn intersect<N: Num>(
    t: [&Point3<N>; 3],
    s: [&Point3<N>; 3],
    ctx: &N::Ctx,
) -> Option<TriContact<N>> {
    let s_side = t_side(t, s, ctx);
    if strictly_one_side(&s_side) {
        return None;
    }
    if s_side.iter().all(|o| *o == Ordering::Equal) {
        return coplanar(t, s, ctx);
    }
    let t_sides = t_side(s, t, ctx);
    if strictly_one_side(&t_sides) {
        return None;
    }
    // Both meet the line L where the planes meet; order points along L's dominant axis.
    let (nt, ns) = (normal(t[0], t[1], t[2]), normal(s[0], s[1], s[2]));
    let axis = dominant_axis(&nt.cross(&ns));
    let key = |p: &Point3<N>| p.coord(axis).clone();
    let it = section(t, (&ns, s[0]), &t_sides, axis);
    let is = section(s, (&nt, t[0]), &s_side, axis);
    let lo = if key(&it.0) >= key(&is.0) {
        &it.0
    } else {
        &is.0
    };
    let hi = if key(&it.1) <= key(&is.1) {
        &it.1
    } else {
        &is.1
    };
    match key(lo).cmp(&key(hi)) {
        Ordering::Greater => None,
        Ordering::Equal => Some(TriContact {
            points: vec![lo.clone()],
            cuts_t: vec![],
            cuts_s: vec![],
            interiors_meet: false,
            coplanar: false,
        }),
        Ordering::Less => {
            let cut = (lo.clone(), hi.clone());
            Some(TriContact {
                points: vec![lo.clone(), hi.clone()],
                cuts_t: vec![cut.clone()],
                cuts_s: vec![cut],
                // Both planes cut through the other triangle's interior, and the open intervals
                // (lo, hi) lie in both relative interiors.
                interiors_meet: proper(&t_sides) && proper(&s_side),
                coplanar: false,
            })
        }
    }
}

/// The sides of `s`'s vertices relative to the plane of `t`.
fn t_side<N: Num>(t: [&Point3<N>; 3], s: [&Point3<N>; 3], ctx: &N::Ctx) -> [Ordering; 3] {
    s.map(|p| orient3d(t[0], t[1], t[2], p, ctx))
}

/// True if all three are strictly on one side.
fn strictly_one_side(o: &[Ordering; 3]) -> bool {
    o.iter().all(|x| *x == Ordering::Greater) || o.iter().all(|x| *x == Ordering::Less)
}

/// True if the plane passes through the triangle's interior (vertices strictly on both sides).
fn proper(o: &[Ordering; 3]) -> bool {
    o.contains(&Ordering::Greater) && o.contains(&Ordering::Less)
}

/// The segment in which the plane through `origin` with normal `n` meets `t` (whose vertices
/// have sides `sides`), as its two ends ordered along coordinate `axis` (equal for a single
/// point).
fn section<N: Num>(
    t: [&Point3<N>; 3],
    (n, origin): (&Point3<N>, &Point3<N>),
    sides: &[Ordering; 3],
    axis: usize,
) -> (Point3<N>, Point3<N>) {
    let value = |p: &Point3<N>| n.dot(&p.sub(origin));
    let mut pts: Vec<Point3<N>> = Vec::with_capacity(2);
    for i in 0..3 {
        let j = (i + 1) % 3;
        if sides[i] == Ordering::Equal {
            pts.push(t[i].clone());
        }
        if sides[i] != Ordering::Equal && sides[j] != Ordering::Equal && sides[i] != sides[j] {
            let (vi, vj) = (value(t[i]), value(t[j]));
            pts.push(t[i].lerp(t[j], &(vi.clone() / (vi - vj))));
        }
    }
    let (mut lo, mut hi) = (pts[0].clone(), pts[0].clone());
    for p in &pts[1..] {
        if p.coord(axis) < lo.coord(axis) {
            lo = p.clone();
        }
        if p.coord(axis) > hi.coord(axis) {
            hi = p.clone();
        }
    }
    (lo, hi)
}

/// Coplanar triangles: contacts of their edges and vertices in a 2D chart of the plane.
fn coplanar<N: Num>(t: [&Point3<N>; 3], s: [&Point3<N>; 3], ctx: &N::Ctx) -> Option<TriContact<N>> {
    let n = normal(t[0], t[1], t[2]);
    let d = n.dot(t[0]);
    let chart = Chart::of_normal(&n);
    let t2 = t.map(|p| chart.project(p));
    let mut s2 = s.map(|p| chart.project(p));
    if orient(&s2[0], &s2[1], &s2[2], ctx) == Ordering::Less {
        s2.swap(1, 2);
    }
    // On each edge of either triangle, the points of the edge that lie in the other triangle.
    let mut on_t: [Vec<Point<N>>; 3] = Default::default();
    let mut on_s: [Vec<Point<N>>; 3] = Default::default();
    for i in 0..3 {
        let (ta, tb) = (&t2[i], &t2[(i + 1) % 3]);
        if in_triangle2(&s2[0], &s2[1], &s2[2], ta, ctx) {
            on_t[i].push(ta.clone());
            on_t[(i + 2) % 3].push(ta.clone());
        }
        if in_triangle2(&t2[0], &t2[1], &t2[2], &s2[i], ctx) {
            on_s[i].push(s2[i].clone());
            on_s[(i + 2) % 3].push(s2[i].clone());
        }
        for j in 0..3 {
            let (sa, sb) = (&s2[j], &s2[(j + 1) % 3]);
            let found = match classify(ta, tb, sa, sb, ctx) {
                Contact::Disjoint => vec![],
                Contact::Crossing(p) | Contact::Touching(p) => vec![p],
                Contact::Overlap(p, q) => vec![p, q],
            };
            on_t[i].extend(found.iter().cloned());
            on_s[j].extend(found);
        }
    }
    let mut all: Vec<Point<N>> = on_t.iter().chain(on_s.iter()).flatten().cloned().collect();
    all.sort();
    all.dedup();
    if all.is_empty() {
        return None;
    }
    let lift = |q: &Point<N>| chart.lift(q, &n, &d);
    let cuts = |on: [Vec<Point<N>>; 3]| -> Vec<(Point3<N>, Point3<N>)> {
        on.into_iter()
            .filter_map(|v| {
                let (lo, hi) = (v.iter().min()?, v.iter().max()?);
                (lo != hi).then(|| (lift(lo), lift(hi)))
            })
            .collect()
    };
    // The intersection is the convex hull of `all`: an area iff three of them are not collinear.
    let area = all.len() >= 3
        && all[2..]
            .iter()
            .any(|p| orient(&all[0], &all[1], p, ctx) != Ordering::Equal);
    Some(TriContact {
        points: all.iter().map(lift).collect(),
        cuts_t: cuts(on_s),
        cuts_s: cuts(on_t),
        interiors_meet: area,
        coplanar: true,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::num::Rational;

    fn p(x: i64, y: i64, z: i64) -> Point3<Rational> {
        Point3::int(x, y, z)
    }

    #[test]
    fn crossing_triangles_meet_in_a_segment_through_both_interiors() {
        let (a, b, c) = (p(0, 0, 0), p(4, 0, 0), p(0, 4, 0));
        let (d, e, f) = (p(1, 1, -1), p(1, 1, 1), p(2, -3, 0));
        let c1 = intersect([&a, &b, &c], [&d, &e, &f], &()).unwrap();
        assert!(c1.interiors_meet);
        assert_eq!(c1.points.len(), 2);
        assert!(c1.points.contains(&p(1, 1, 0)));
    }

    #[test]
    fn vertex_on_face_and_edge_on_face_are_legal_contacts() {
        let (a, b, c) = (p(0, 0, 0), p(4, 0, 0), p(0, 4, 0));
        let tip = intersect([&a, &b, &c], [&p(1, 1, 0), &p(2, 1, 3), &p(1, 2, 3)], &()).unwrap();
        assert!(!tip.interiors_meet);
        assert_eq!(tip.points, vec![p(1, 1, 0)]);
        let edge = intersect([&a, &b, &c], [&p(1, 1, 0), &p(2, 1, 0), &p(1, 2, 3)], &()).unwrap();
        assert!(!edge.interiors_meet);
        assert_eq!(edge.cuts_t, vec![(p(1, 1, 0), p(2, 1, 0))]);
    }

    #[test]
    fn coplanar_overlap_and_touch() {
        let (a, b, c) = (p(0, 0, 0), p(2, 0, 0), p(0, 2, 0));
        // The case of a shared collinear stretch with a vertex on the hypotenuse: overlap.
        let o = intersect([&a, &b, &c], [&p(1, 0, 0), &p(3, 0, 0), &p(1, 1, 0)], &()).unwrap();
        assert!(o.interiors_meet);
        // Mirror image across y = 0: touches along [1,2] on the x axis only.
        let t = intersect([&a, &b, &c], [&p(1, 0, 0), &p(1, -1, 0), &p(3, 0, 0)], &()).unwrap();
        assert!(!t.interiors_meet);
        assert_eq!(t.cuts_t, vec![(p(1, 0, 0), p(2, 0, 0))]);
        assert!(intersect([&a, &b, &c], [&p(5, 5, 0), &p(6, 5, 0), &p(5, 6, 0)], &()).is_none());
    }

    #[test]
    fn parallel_and_separated_planes_do_not_meet() {
        let (a, b, c) = (p(0, 0, 0), p(2, 0, 0), p(0, 2, 0));
        assert!(intersect([&a, &b, &c], [&p(0, 0, 1), &p(2, 0, 1), &p(0, 2, 1)], &()).is_none());
        assert!(intersect([&a, &b, &c], [&p(5, 0, -1), &p(5, 0, 1), &p(6, 1, 0)], &()).is_none());
    }
}
