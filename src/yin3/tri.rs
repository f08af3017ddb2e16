//! Triangle–triangle intersection with every coplanar and touching case (seed 004 step 1; yin3
//! docs: *Triangle–triangle*): the contact points, the segments each triangle must be cut along,
//! and whether the two relative interiors meet (a crossing or an overlap).

use super::geom::{dominant_axis, in_triangle2, normal, Chart};
use crate::kernel::{classify, orient, orient3d, Contact, Point, Point3};
use crate::num::Num;
use std::cell::OnceCell;
use std::cmp::Ordering;

/// How two closed triangles `t` and `s` meet.
#[derive(Clone, Debug)]
pub(crate) struct TriContact<N> {
    /// The vertices of the intersection (each a point of both triangles).
    pub points: Vec<Point3<N>>,
    /// Segments of the intersection that `t` must be cut along (their ends' indices in
    /// `points`).
    pub cuts_t: Vec<(usize, usize)>,
    /// Segments of the intersection that `s` must be cut along (as `cuts_t`).
    pub cuts_s: Vec<(usize, usize)>,
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
    intersect_with(t, s, [&OnceCell::new(), &OnceCell::new()], ctx)
}

/// [`intersect`], with each triangle's normal (b − a) × (c − a) taken from `normals` or made
/// there where it is needed (an arrangement makes each once for all its pairs).
pub(crate) fn intersect_with<N: Num>(
    t: [&Point3<N>; 3],
    s: [&Point3<N>; 3],
    normals: [&OnceCell<Point3<N>>; 2],
    ctx: &N::Ctx,
) -> Option<TriContact<N>> {
    let normal_of = |k: usize| {
        let [a, b, c] = [t, s][k];
        normals[k].get_or_init(|| normal(a, b, c))
    };
    let s_side = t_side(t, s, ctx);
    if strictly_one_side(&s_side) {
        return None;
    }
    if s_side.iter().all(|o| *o == Ordering::Equal) {
        // A side of either outside which the other lies, found from orientations alone,
        // before any contact is constructed.
        if misses_in_plane(t, &s, ctx) || misses_in_plane(s, &t, ctx) {
            return None;
        }
        return coplanar(t, s, normal_of(0), ctx);
    }
    if off_plane_of(s, &s_side, t, ctx) {
        return None;
    }
    let t_sides = t_side(s, t, ctx);
    if off_plane_of(t, &t_sides, s, ctx) || separated(t, s, &t_sides, &s_side, ctx) {
        return None;
    }
    // Both meet the line L where the planes meet; order points along L's dominant axis.
    let (nt, ns) = (normal_of(0), normal_of(1));
    let axis = dominant_axis(&nt.cross(ns));
    let key = |p: &Point3<N>| p.coord(axis).clone();
    let it = section(t, (ns, s[0]), &t_sides, axis);
    let is = section(s, (nt, t[0]), &s_side, axis);
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
            Some(TriContact {
                points: vec![lo.clone(), hi.clone()],
                cuts_t: vec![(0, 1)],
                cuts_s: vec![(0, 1)],
                // Both planes cut through the other triangle's interior, and the open intervals
                // (lo, hi) lie in both relative interiors.
                interiors_meet: proper(&t_sides) && proper(&s_side),
                coplanar: false,
            })
        }
    }
}

/// True if the closed triangles `t` and `s` are shown disjoint by orientations of their
/// vertices alone (false where that cannot tell): one lies strictly on one side of the
/// other's plane, or touches it only in vertices that the other misses, or both lie in one
/// plane with a side of one separating them ([`misses_in_plane`]), or [`separated`] tells.
pub(crate) fn apart<N: Num>(t: [&Point3<N>; 3], s: [&Point3<N>; 3], ctx: &N::Ctx) -> bool {
    let s_sides = t_side(t, s, ctx);
    if off_plane_of(s, &s_sides, t, ctx) {
        return true;
    }
    let t_sides = t_side(s, t, ctx);
    off_plane_of(t, &t_sides, s, ctx) || separated(t, s, &t_sides, &s_sides, ctx)
}

/// True if `x` (its vertices on sides `sides` of the plane of `y`) meets that plane at most in
/// one or two of its vertices, none in the closed triangle `y`, or lies in it with a side of
/// `y` separating them.
fn off_plane_of<N: Num>(
    x: [&Point3<N>; 3],
    sides: &[Ordering; 3],
    y: [&Point3<N>; 3],
    ctx: &N::Ctx,
) -> bool {
    if proper(sides) {
        return false;
    }
    let on: Vec<&Point3<N>> = (0..3)
        .filter(|&i| sides[i] == Ordering::Equal)
        .map(|i| x[i])
        .collect();
    match on.len() {
        0 => true,
        _ => misses_in_plane(y, &on, ctx),
    }
}

/// True if the closed triangle `y` misses the point, segment or triangle `on` of its plane, by
/// the separating-line theorem for convex polygons: the line of a side of `y` with `on`
/// strictly outside it, or a segment's own line with `y` strictly on one side.
fn misses_in_plane<N: Num>(y: [&Point3<N>; 3], on: &[&Point3<N>], ctx: &N::Ctx) -> bool {
    let Some(o) = in_plane_of(y, ctx) else {
        return false;
    };
    let outside = |i: usize| {
        on.iter()
            .all(|p| o([y[i], y[(i + 1) % 3], p]) == Ordering::Less)
    };
    (0..3).any(outside) || matches!(on, [p, q] if strictly_one_side(&y.map(|c| o([p, q, c]))))
}

/// True if `t` and `s` are disjoint though each plane passes strictly between the other's
/// vertices (`t_sides`: t's vertices against s's plane; `s_sides`: s's against t's; none on a
/// plane): Devillers and Guigue's test (2002) from two orientations of input vertices, nothing
/// constructed. Rotate each triangle to start at its vertex alone on its side, swap the other
/// two of one so that each lone vertex lies above the other's plane; the sections of the two
/// triangles on the planes' common line then overlap iff neither orientation is positive.
fn separated<N: Num>(
    t: [&Point3<N>; 3],
    s: [&Point3<N>; 3],
    t_sides: &[Ordering; 3],
    s_sides: &[Ordering; 3],
    ctx: &N::Ctx,
) -> bool {
    if t_sides.contains(&Ordering::Equal) || s_sides.contains(&Ordering::Equal) {
        return false;
    }
    let lone = |o: &[Ordering; 3]| (0..3).find(|&i| o[(i + 1) % 3] == o[(i + 2) % 3]);
    let (Some(i), Some(j)) = (lone(t_sides), lone(s_sides)) else {
        return false; // all on one side: decided by the caller
    };
    let (p1, mut q1, mut r1) = (t[i], t[(i + 1) % 3], t[(i + 2) % 3]);
    let (p2, mut q2, mut r2) = (s[j], s[(j + 1) % 3], s[(j + 2) % 3]);
    if t_sides[i] == Ordering::Less {
        std::mem::swap(&mut q2, &mut r2);
    }
    if s_sides[j] == Ordering::Less {
        std::mem::swap(&mut q1, &mut r1);
    }
    orient3d(p1, q1, p2, q2, ctx) == Ordering::Greater
        || orient3d(p1, r1, r2, p2, ctx) == Ordering::Greater
}

/// True if the triangles `vab` and `vcd`, which share the vertex `v`, are known to meet only
/// there, from orientations of their vertices alone (false where it cannot tell):
/// - if either's other two vertices lie strictly on one side of the other's plane;
/// - if each plane strictly separates the other's two: the sections on the planes' common line
///   L are segments from v, which overlap iff they leave v the same way — iff cd crosses the
///   plane of vab on b's side of the line va, which orient3d(v, a, c, d) tells against
///   orient3d(v, a, b, c);
/// - if exactly one other vertex of one lies on the other's plane: the first meets that plane
///   in the edge from v to it, which leaves the other at v iff it points out of the other's
///   corner at v;
/// - if they are coplanar: iff no side of either at v points into the other's corner.
pub(crate) fn meet_only_at<N: Num>(
    v: &Point3<N>,
    [a, b]: [&Point3<N>; 2],
    [c, d]: [&Point3<N>; 2],
    ctx: &N::Ctx,
) -> bool {
    let sides = [
        [orient3d(v, a, b, c, ctx), orient3d(v, a, b, d, ctx)],
        [orient3d(v, c, d, a, ctx), orient3d(v, c, d, b, ctx)],
    ];
    meet_only_at_given(v, [a, b], [c, d], sides, ctx)
}

/// [`meet_only_at`] with the sides of `c`, `d` against the plane of `vab` and of `a`, `b`
/// against the plane of `vcd` known.
pub(crate) fn meet_only_at_given<N: Num>(
    v: &Point3<N>,
    [a, b]: [&Point3<N>; 2],
    [c, d]: [&Point3<N>; 2],
    [[sc, sd], [sa, sb]]: [[Ordering; 2]; 2],
    ctx: &N::Ctx,
) -> bool {
    use Ordering::Equal;
    let one_side = |x: Ordering, y: Ordering| x == y && x != Equal;
    if one_side(sc, sd) || one_side(sa, sb) {
        return true;
    }
    let straddle = |x: Ordering, y: Ordering| x != y && x != Equal && y != Equal;
    if straddle(sc, sd) && straddle(sa, sb) {
        return orient3d(v, a, c, d, ctx) == sc;
    }
    let out = |corner: [&Point3<N>; 2], rays: &[&Point3<N>]| out_of_corner(v, corner, rays, ctx);
    match (sc, sd, sa, sb) {
        (Equal, Equal, _, _) => out([a, b], &[c, d]) && out([c, d], &[a, b]),
        (Equal, _, _, _) => out([a, b], &[c]),
        (_, Equal, _, _) => out([a, b], &[d]),
        (_, _, Equal, _) => out([c, d], &[a]),
        (_, _, _, Equal) => out([c, d], &[b]),
        _ => false,
    }
}

/// The two corners that follow `v` around the triangle `tri` (`v` one of its corners).
pub(crate) fn corners_after(tri: [usize; 3], v: usize) -> [usize; 2] {
    let k = tri.iter().position(|&x| x == v).expect("v is a corner");
    [tri[(k + 1) % 3], tri[(k + 2) % 3]]
}

/// A triangle's image in the coordinate plane onto which it projects largest (chosen in
/// `f64`, a hint only), and the image's turn, for [`images_meet_only_in_shared`].
#[derive(Clone, Copy, Debug)]
pub(crate) struct Image {
    chart: Chart,
    turn: Ordering,
}

impl Image {
    /// The image of the triangle `t` (indices into `points`); `None` where it degenerates.
    pub(crate) fn of<N: Num>(points: &[Point3<N>], t: [usize; 3], ctx: &N::Ctx) -> Option<Image> {
        let chart = Chart::of_f64_triangle(t.map(|v| points[v].to_f64()))?;
        let [a, b, c] = t.map(|v| chart.image_of(&points[v]));
        let turn = N::orient2d(a, b, c, ctx);
        (turn != Ordering::Equal).then_some(Image { chart, turn })
    }
}

/// True if the triangles `t` and `s` (indices into `points`) meet only in their shared
/// corners, decided on their images in the plane of t's [`Image`] `image`: t's image does not
/// degenerate, so projecting is one-to-one on t, and images that meet only in the images of
/// shared corners mean triangles that meet only there (a point of both projects into both
/// images, where only a shared corner's image and t's one point at it lie). One shared corner:
/// s's other corners strictly outside the line of one of t's edges at it; else, where s's
/// image does not degenerate either, as for two shared corners (the third corners' images
/// strictly on opposite sides of the shared edge) or one (the images' closed corners at it
/// disjoint). None: an edge line of one image with the other image strictly outside
/// (separating axis; of t's image, also where s's degenerates, as a wall's image does in the
/// chart of a floor). False where it cannot tell.
pub(crate) fn images_meet_only_in_shared<N: Num>(
    points: &[Point3<N>],
    (t, image): ([usize; 3], &Image),
    s: [usize; 3],
    ctx: &N::Ctx,
) -> bool {
    use Ordering::Equal;
    // The six corners' images: t's are 0..3, s's 3..6, and a corner of s shared with t is
    // named by t's.
    let chart = image.chart;
    let images = [t[0], t[1], t[2], s[0], s[1], s[2]].map(|v| chart.image_of(&points[v]));
    let o = |a: usize, b: usize, c: usize| N::orient2d(images[a], images[b], images[c], ctx);
    let (t, s) = (
        [0, 1, 2],
        [0, 1, 2].map(|k| t.iter().position(|&v| v == s[k]).unwrap_or(3 + k)),
    );
    let st = image.turn;
    let (mut shared, mut n) = ([0; 3], 0);
    for &v in s.iter().filter(|&&v| v < 3) {
        shared[n] = v;
        n += 1;
    }
    if let [v] = shared[..n] {
        // t = (v, a, b) in its turn `st`: outside its edge va right of it, outside bv left.
        let ([a, b], cs) = (corners_after(t, v), corners_after(s, v));
        if cs.iter().all(|&x| o(v, a, x) == st.reverse()) || cs.iter().all(|&x| o(v, b, x) == st) {
            return true;
        }
    }
    // An edge line of one image with the other's corners strictly outside it (separating
    // axis): s's image may be a segment or a point here, only t's turn is read.
    let separates = |(tri, sign, other): ([usize; 3], Ordering, [usize; 3])| {
        (0..3).any(|e| {
            let (a, b) = (tri[e], tri[(e + 1) % 3]);
            other.iter().all(|&x| o(a, b, x) == sign.reverse())
        })
    };
    if n == 0 && separates((t, st, s)) {
        return true;
    }
    let ss = o(s[0], s[1], s[2]);
    if ss == Equal {
        return false;
    }
    // Whether `x` lies in the closed corner spanned at `v` by `a` and `b` (oriented `sign`).
    let in_corner = |v: usize, [a, b]: [usize; 2], sign: Ordering, x: usize| {
        let within = |o: Ordering| o == sign || o == Equal;
        within(o(v, a, x)) && within(o(v, x, b))
    };
    match shared[..n] {
        [x, y] => {
            // The side of the shared edge on which a triangle's third corner lies.
            let third = |tri: [usize; 3]| {
                let v = tri.into_iter().find(|&v| v != x && v != y);
                o(x, y, v.expect("three distinct corners"))
            };
            let (sa, sw) = (third(t), third(s));
            sa != Equal && sw != Equal && sa != sw
        }
        [v] => {
            let (ct, cs) = (corners_after(t, v), corners_after(s, v));
            !cs.iter().any(|&x| in_corner(v, ct, st, x))
                && !ct.iter().any(|&x| in_corner(v, cs, ss, x))
        }
        [] => separates((s, ss, t)),
        _ => false,
    }
}

/// True if the triangle `s` meets the triangle `t` only in their shared corners because its
/// other corners lie strictly on one side of the plane of `t`, where `side` (the side of a
/// vertex, or `None` where a filter cannot tell) is certain of it: `s` then meets that plane
/// only in the shared corners. False where it cannot tell, and for a triangle with all three
/// corners shared.
pub(crate) fn off_plane_but_shared(
    t: [usize; 3],
    s: [usize; 3],
    side: impl Fn(usize) -> Option<Ordering>,
) -> bool {
    let mut first = None;
    for v in s.into_iter().filter(|v| !t.contains(v)) {
        match side(v) {
            Some(x) if first.is_none_or(|y| y == x) => first = Some(x),
            _ => return false,
        }
    }
    first.is_some()
}

/// True if no ray from `v` through a point of `rays` (points of the plane of the triangle
/// `vab`) lies in the triangle's closed corner at `v`; false if `vab` is degenerate.
fn out_of_corner<N: Num>(
    v: &Point3<N>,
    [a, b]: [&Point3<N>; 2],
    rays: &[&Point3<N>],
    ctx: &N::Ctx,
) -> bool {
    in_plane_of([v, a, b], ctx).is_some_and(|o| {
        rays.iter()
            .all(|x| o([v, a, x]) == Ordering::Less || o([v, x, b]) == Ordering::Less)
    })
}

/// True if the coplanar triangles `uva` and `uvw`, which share the edge `uv`, lie strictly on
/// opposite sides of it, so that they meet only in it.
pub(crate) fn apart_across<N: Num>(
    [u, v]: [&Point3<N>; 2],
    a: &Point3<N>,
    w: &Point3<N>,
    ctx: &N::Ctx,
) -> bool {
    in_plane_of([u, v, a], ctx).is_some_and(|o| o([u, v, w]) == Ordering::Less)
}

/// The orientation of three points of the plane of the triangle `t`, signed so that `t` is
/// counterclockwise: `orient` of their images in the first coordinate plane onto which `t`
/// projects without degenerating (no normal is constructed). `None` if `t` is degenerate.
fn in_plane_of<'a, N: Num>(
    t: [&Point3<N>; 3],
    ctx: &'a N::Ctx,
) -> Option<impl Fn([&Point3<N>; 3]) -> Ordering + 'a> {
    fn image<N: Num>(k: usize, p: &Point3<N>) -> [&N; 2] {
        [p.coord((k + 1) % 3), p.coord((k + 2) % 3)]
    }
    let (k, sign) = (0..3).find_map(|k| {
        let [a, b, c] = t.map(|p| image(k, p));
        let sign = N::orient2d(a, b, c, ctx);
        (sign != Ordering::Equal).then_some((k, sign))
    })?;
    Some(move |q: [&Point3<N>; 3]| {
        let [a, b, c] = q.map(|p| image(k, p));
        let o = N::orient2d(a, b, c, ctx);
        if sign == Ordering::Less {
            o.reverse()
        } else {
            o
        }
    })
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

/// Coplanar triangles, `t` with normal `n`: contacts of their edges and vertices in a 2D
/// chart of the plane.
fn coplanar<N: Num>(
    t: [&Point3<N>; 3],
    s: [&Point3<N>; 3],
    n: &Point3<N>,
    ctx: &N::Ctx,
) -> Option<TriContact<N>> {
    let d = n.dot(t[0]);
    let chart = Chart::of_normal(n);
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
    let lift = |q: &Point<N>| chart.lift(q, n, &d);
    let at = |q: &Point<N>| {
        all.binary_search(q)
            .expect("every contact point is in `all`")
    };
    let cuts = |on: [Vec<Point<N>>; 3]| -> Vec<(usize, usize)> {
        on.into_iter()
            .filter_map(|v| {
                let (lo, hi) = (v.iter().min()?, v.iter().max()?);
                (lo != hi).then(|| (at(lo), at(hi)))
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
    use crate::num::{filtered_orient3d, PlaneF64, Rational};
    use crate::yin3::geom::collinear;

    fn p(x: i64, y: i64, z: i64) -> Point3<Rational> {
        Point3::int(x, y, z)
    }

    /// The ends of the cuts `cuts` of the contact `c`.
    fn ends(
        c: &TriContact<Rational>,
        cuts: &[(usize, usize)],
    ) -> Vec<(Point3<Rational>, Point3<Rational>)> {
        (cuts.iter())
            .map(|&(i, j)| (c.points[i].clone(), c.points[j].clone()))
            .collect()
    }

    /// Coplanar triangles are apart when the line of a side of either has the other strictly
    /// outside (here only a side of the second does), not when they overlap or touch.
    #[test]
    fn coplanar_triangles_apart_by_a_side_line() {
        let t = [p(0, 0, 0), p(2, 0, 0), p(1, 1, 0)];
        let above = [p(-5, 2, 0), p(7, 2, 0), p(1, 10, 0)];
        let overlapping = [p(1, 0, 0), p(3, 1, 0), p(0, 3, 0)];
        let touching = [p(1, 1, 0), p(-5, 10, 0), p(7, 10, 0)];
        let t = t.each_ref();
        assert!(apart(t, above.each_ref(), &()) && apart(above.each_ref(), t, &()));
        assert!(!apart(t, overlapping.each_ref(), &()));
        assert!(!apart(t, touching.each_ref(), &()));
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
        assert_eq!(ends(&edge, &edge.cuts_t), vec![(p(1, 1, 0), p(2, 1, 0))]);
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
        assert_eq!(ends(&t, &t.cuts_t), vec![(p(1, 0, 0), p(2, 0, 0))]);
        assert!(intersect([&a, &b, &c], [&p(5, 5, 0), &p(6, 5, 0), &p(5, 6, 0)], &()).is_none());
    }

    #[test]
    fn parallel_and_separated_planes_do_not_meet() {
        let (a, b, c) = (p(0, 0, 0), p(2, 0, 0), p(0, 2, 0));
        assert!(intersect([&a, &b, &c], [&p(0, 0, 1), &p(2, 0, 1), &p(0, 2, 1)], &()).is_none());
        assert!(intersect([&a, &b, &c], [&p(5, 0, -1), &p(5, 0, 1), &p(6, 1, 0)], &()).is_none());
    }

    /// The corners after each corner of a triangle are the next two in its cyclic order.
    #[test]
    fn corners_after_follow_the_corner_cyclically() {
        let tri = [4, 7, 9];
        assert_eq!(corners_after(tri, 4), [7, 9]);
        assert_eq!(corners_after(tri, 7), [9, 4]);
        assert_eq!(corners_after(tri, 9), [4, 7]);
    }

    /// A point of the small lattice the properties draw from (many contacts and coplanarities).
    fn lattice() -> impl proptest::strategy::Strategy<Value = Point3<Rational>> {
        use proptest::prelude::*;
        (-4i64..=4, -4i64..=4, -4i64..=4).prop_map(|(x, y, z)| p(x, y, z))
    }

    /// Whether the segment `pq` crosses the triangle `abc`, when orientations decide it
    /// strictly (`None` for a touch): the ends on opposite sides of the plane and the line pq
    /// on the same side of all three edges.
    fn crosses([p, q]: [&Point3<Rational>; 2], [a, b, c]: [&Point3<Rational>; 3]) -> Option<bool> {
        let o = |a, b, c, d| orient3d(a, b, c, d, &());
        let (sp, sq) = (o(a, b, c, p), o(a, b, c, q));
        let edges = [o(p, q, a, b), o(p, q, b, c), o(p, q, c, a)];
        if sp == Ordering::Equal || sq == Ordering::Equal || edges.contains(&Ordering::Equal) {
            return None;
        }
        Some(sp != sq && edges.iter().all(|e| *e == edges[0]))
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(yinset_testkit::cases(256)))]
        /// Devillers and Guigue's construction-free test equals an independent one: triangles
        /// in general position meet iff an edge of one crosses the other.
        #[test]
        fn separated_iff_no_edge_crosses(t in proptest::array::uniform3(lattice()),
                                         s in proptest::array::uniform3(lattice())) {
            let (t, s) = (t.each_ref(), s.each_ref());
            let (s_sides, t_sides) = (t_side(t, s, &()), t_side(s, t, &()));
            proptest::prop_assume!(!s_sides.contains(&Ordering::Equal));
            proptest::prop_assume!(!t_sides.contains(&Ordering::Equal));
            proptest::prop_assume!(!strictly_one_side(&s_sides) && !strictly_one_side(&t_sides));
            let crossings: Option<Vec<bool>> = [(t, s), (s, t)]
                .into_iter()
                .flat_map(|(x, y)| (0..3).map(move |i| crosses([x[i], x[(i + 1) % 3]], y)))
                .collect();
            let Some(crossings) = crossings else { return Ok(()) };
            proptest::prop_assert_eq!(separated(t, s, &t_sides, &s_sides, &()), !crossings.contains(&true));
        }

        /// The construction-free test of two triangles sharing a vertex equals the
        /// constructed intersection: where it answers, the contact is the vertex alone
        /// (crossing, touching and coplanar pairs: the lattice makes all of them).
        #[test]
        fn meet_only_at_is_the_constructed_contact(v in lattice(),
                                                   ab in proptest::array::uniform2(lattice()),
                                                   cd in proptest::array::uniform2(lattice())) {
            proptest::prop_assume!(!collinear(&v, &ab[0], &ab[1]) && !collinear(&v, &cd[0], &cd[1]));
            let o = |a, b, c| orient3d(&v, a, b, c, &());
            let contact = intersect([&v, &ab[0], &ab[1]], [&v, &cd[0], &cd[1]], &())
                .expect("they share v");
            let alone = contact.points == [v.clone()];
            if meet_only_at(&v, ab.each_ref(), cd.each_ref(), &()) {
                proptest::prop_assert!(alone);
            } else {
                // It says no only where a segment leaves v along both, or it cannot tell.
                let (sc, sd) = (o(&ab[0], &ab[1], &cd[0]), o(&ab[0], &ab[1], &cd[1]));
                let (sa, sb) = (o(&cd[0], &cd[1], &ab[0]), o(&cd[0], &cd[1], &ab[1]));
                let decided = [sa, sb, sc, sd].iter().all(|x| *x != Ordering::Equal)
                    && orient3d(&v, &ab[0], &cd[0], &cd[1], &()) != Ordering::Equal;
                proptest::prop_assert!(!alone || !decided);
            }
        }

        /// Triangles shown apart by orientations do not meet (the constructed intersection),
        /// where s has one, two or three vertices in the plane of t, inside t or not.
        #[test]
        fn apart_is_the_constructed_contact(t in proptest::array::uniform3(lattice()),
                                            s2 in lattice(),
                                            k in proptest::array::uniform6(-4i64..=4),
                                            two in proptest::bool::ANY,
                                            flat in proptest::bool::ANY) {
            // s0, s1 = t0 + (k0 (t1 − t0) + k1 (t2 − t0)) / 2: in the plane of t.
            let in_plane = |k0: i64, k1: i64| {
                let half = |k: i64| Rational::from_i64(k) / Rational::from_i64(2);
                let c = |i: usize| {
                    let o = t[0].coord(i).clone();
                    o.clone() + half(k0) * (t[1].coord(i).clone() - o.clone())
                        + half(k1) * (t[2].coord(i).clone() - o)
                };
                Point3::new(c(0), c(1), c(2))
            };
            let s0 = in_plane(k[0], k[1]);
            let s1 = if two { in_plane(k[2], k[3]) } else { Point3::new(s2.y.clone(), s2.z.clone(), s2.x.clone()) };
            let s2 = if two && flat { in_plane(k[4], k[5]) } else { s2 };
            let s = [&s0, &s1, &s2];
            proptest::prop_assume!(!collinear(&t[0], &t[1], &t[2]) && !collinear(s[0], s[1], s[2]));
            let (t, s3) = (t.each_ref(), s);
            let contact = intersect(t, s3, &());
            if apart(t, s3, &()) || apart(s3, t, &()) {
                proptest::prop_assert!(contact.is_none());
            }
            // Complete where s touches t's plane only in its vertices.
            let sides = t_side(t, s3, &());
            if contact.is_none() && !proper(&sides) && !sides.iter().all(|x| *x == Ordering::Equal) {
                proptest::prop_assert!(apart(t, s3, &()));
            }
        }

        /// Where the test on the images in a coordinate plane says that two triangles sharing
        /// two, one or no corners meet only there, the constructed intersection agrees; and
        /// where the images are nondegenerate and the triangles coplanar, it always answers
        /// (lattice points: coplanar, touching and crossing pairs all occur; and walls, whose
        /// images in a floor's chart are segments).
        #[test]
        fn images_meet_only_in_shared_is_the_constructed_contact(
            q in proptest::array::uniform6((-4i64..=4, -4i64..=4, -4i64..=4)),
            shared in 0usize..3,
            flip in proptest::bool::ANY,
            (flat, wall) in proptest::sample::select(
                vec![(false, false), (true, false), (false, true)],
            ),
        ) {
            let t = [0, 1, 2];
            let mut s = [[0, 1, 3], [0, 3, 4], [3, 4, 5]][shared];
            // Flat: all six points in the plane z = 0. Wall: t in that plane, s in a plane
            // x = c through its shared corners.
            let c = q[s[0]].0;
            let q: [_; 6] = std::array::from_fn(|i| {
                let (x, y, z) = q[i];
                let x = if wall && s.contains(&i) { c } else { x };
                p(x, y, if flat || wall && i < 3 { 0 } else { z })
            });
            if flip {
                s.swap(1, 2);
            }
            let (tp, sp) = (t.map(|v| &q[v]), s.map(|v| &q[v]));
            proptest::prop_assume!(!collinear(tp[0], tp[1], tp[2]) && !collinear(sp[0], sp[1], sp[2]));
            proptest::prop_assume!((0..6).all(|i| (0..i).all(|j| q[i] != q[j])));
            let contact = intersect(tp, sp, &());
            let corners: Vec<&Point3<Rational>> = s.iter().filter(|v| t.contains(v)).map(|&v| &q[v]).collect();
            let only_shared = contact
                .as_ref()
                .is_none_or(|c| !c.interiors_meet && c.points.iter().all(|x| corners.contains(&x)));
            let said = Image::of(&q, t, &()).is_some_and(|i| images_meet_only_in_shared(&q, (t, &i), s, &()));
            if said {
                proptest::prop_assert!(only_shared, "said they meet only in shared corners: {:?}", contact);
            }
            if flat {
                // Coplanar: both images are nondegenerate, and the test is complete.
                proptest::prop_assert_eq!(said, only_shared);
            }
        }

        /// The plane test says that two triangles sharing two, one or no corners meet only
        /// there exactly when the other corners of the second lie strictly on one side of the
        /// first's plane (exact orientations of the lattice points, which the filter always
        /// certifies), and then the constructed intersection agrees; never for a triangle on
        /// the same three corners, nor for coplanar pairs (`flat`).
        #[test]
        fn off_plane_but_shared_is_the_constructed_contact(
            q in proptest::array::uniform6((-4i64..=4, -4i64..=4, -4i64..=4)),
            shared in 0usize..4,
            flat in proptest::bool::ANY,
        ) {
            let q = q.map(|(x, y, z)| p(x, y, if flat { 0 } else { z }));
            let t = [0, 1, 2];
            let s = [[0, 1, 3], [0, 3, 4], [3, 4, 5], [0, 2, 1]][shared];
            let (tp, sp) = (t.map(|v| &q[v]), s.map(|v| &q[v]));
            proptest::prop_assume!(!collinear(tp[0], tp[1], tp[2]));
            proptest::prop_assume!(!collinear(sp[0], sp[1], sp[2]));
            proptest::prop_assume!((0..6).all(|i| (0..i).all(|j| q[i] != q[j])));
            let f64s: Vec<[f64; 3]> = q.iter().map(|v| v.to_f64()).collect();
            let plane = PlaneF64::new(f64s[0], f64s[1], f64s[2]);
            let said = off_plane_but_shared(t, s, |v| plane.certain_side(f64s[v]));
            // The semi-static filter on the same values says the same.
            let filtered = |v: usize| filtered_orient3d(f64s[0], f64s[1], f64s[2], f64s[v]);
            proptest::prop_assert_eq!(off_plane_but_shared(t, s, filtered), said);
            let sides: Vec<Ordering> = (3..6)
                .filter(|v| s.contains(v))
                .map(|v| orient3d(tp[0], tp[1], tp[2], &q[v], &()))
                .collect();
            let one_side = sides
                .first()
                .is_some_and(|&x| x != Ordering::Equal && sides.iter().all(|&y| y == x));
            proptest::prop_assert_eq!(said, one_side);
            if said {
                let contact = intersect(tp, sp, &());
                let shared: Vec<&Point3<Rational>> =
                    (0..3).filter(|v| s.contains(v)).map(|v| &q[v]).collect();
                let only_shared = contact.is_none_or(|c| {
                    !c.interiors_meet && c.points.iter().all(|x| shared.contains(&x))
                });
                proptest::prop_assert!(only_shared);
            }
        }

        /// Coplanar triangles on opposite sides of a shared edge meet in the edge alone, and
        /// on the same side they overlap (the constructed intersection).
        #[test]
        fn apart_across_is_the_constructed_contact(u in lattice(), v in lattice(),
                                                   a in lattice(), k in (-3i64..=3, -3i64..=3)) {
            // w = u + k.0 (v − u) + k.1 (a − u), in the plane of uva.
            let (k0, k1) = (Rational::from_i64(k.0), Rational::from_i64(k.1));
            let w = |i: usize| {
                let (ui, vi, ai) = (u.coord(i).clone(), v.coord(i).clone(), a.coord(i).clone());
                ui.clone() + k0.clone() * (vi - ui.clone()) + k1.clone() * (ai - ui)
            };
            let w = Point3::new(w(0), w(1), w(2));
            proptest::prop_assume!(!collinear(&u, &v, &a) && !collinear(&u, &v, &w));
            proptest::prop_assert_eq!(orient3d(&u, &v, &a, &w, &()), Ordering::Equal);
            let contact = intersect([&u, &v, &a], [&u, &v, &w], &()).expect("they share uv");
            let apart = apart_across([&u, &v], &a, &w, &());
            proptest::prop_assert_eq!(apart, !contact.interiors_meet);
            if apart {
                proptest::prop_assert!(contact.points.iter().all(|p| *p == u || *p == v));
            }
        }
    }
}
