//! How two triangles of different operands meet, decided from exact orientations of their
//! corners ([`super::corners`]; seed 004 step 1 for the cases [`super::transversal`]
//! constructs without the general arrangement, and that the general arrangement of a meet
//! settles by name, [`super::named`]). Where two triangles cross, each meets the line of the
//! two planes in a segment — from one straddling edge's pierce point to the other's, or from a
//! shared corner or a vertex on the other's plane to the opposite edge's — and the triangles
//! meet in the overlap of the two segments. Each end of the overlap is an end of one segment
//! in the other triangle (a pierce point or a vertex inside it, a vertex on its edge, an edge
//! through its corner) or an end of both (an edge of one operand through an edge of the other,
//! or the shared corner), and is named by what defines it, so that every pair that finds it
//! finds the same point.

use super::corners::Corners;
use super::tri::{self, apart_across, corners_after, meet_only_at_given};
use crate::kernel::Point3;
use crate::num::Num;
use smallvec::{smallvec, SmallVec};
use std::cmp::Ordering::{self, Equal};

/// An edge of one operand: its ends' global point indices, the smaller first.
pub(super) type Edge = (usize, usize);

/// A point where two crossing triangles' boundaries meet, named by what defines it.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub(super) enum End {
    /// Where an edge of one operand pierces the interior of a triangle (global index) of the
    /// other.
    Pierce(Edge, usize),
    /// Where an edge of operand 0 crosses an edge of operand 1 inside both, with a triangle of
    /// one edge (global index) through whose plane the other edge passes there: of the second
    /// edge, but in [`Contact::Along`] where the first lies in the second's plane.
    Edges(Edge, Edge, usize),
    /// A corner of operand 0 (global index) equal to a corner of operand 1.
    Corner(usize, usize),
    /// A vertex of one operand (global index) inside a triangle (global index) of the other,
    /// or, in [`Contact::OnEdge`] and [`Contact::Along`], on its boundary.
    Vertex(usize, usize),
}

/// A point where the boundaries meet, by what defines it ([`End`]; the triangle through whose
/// plane two crossing edges' point is constructed is left out: the point is the same).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub(super) enum Site {
    /// An edge through a triangle's interior.
    Pierce(Edge, usize),
    /// An edge of operand 0 through an edge of operand 1.
    Edges(Edge, Edge),
    /// A vertex inside a triangle (an input point: nothing to construct).
    Vertex(usize, usize),
}

/// How two triangles of different operands meet.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) enum Contact {
    /// Disjoint.
    Apart,
    /// Crossing along the segment between two ends; one end twice where they meet in one
    /// point only: an edge of each crossing the other's ([`End::Edges`]) or a vertex inside
    /// the other ([`End::Vertex`]).
    Cross([End; 2]),
    /// Meeting only in a shared corner or a shared edge: the pairs of equal corners (t's, s's;
    /// one pair twice for a corner).
    Touch([[usize; 2]; 2]),
    /// An edge of one lying on the other's plane, through the other along the segment between
    /// two ends, or meeting it in one (given twice) ([`on_plane`]): membership need not flip
    /// across it, so the transversal meet declines it; an arrangement cuts both triangles
    /// along it.
    Along([End; 2]),
    /// Crossing or touching along the segment between two ends, one of them on the boundary
    /// of the triangle it is named in ([`End::Vertex`]: a vertex on an edge of the other, or
    /// an edge through a corner of the other): the triangles across that edge meet there too,
    /// which the transversal meet does not provide for, so it declines it; an arrangement cuts
    /// both triangles along it.
    OnEdge([End; 2]),
    /// Meeting otherwise (coplanar, meeting beyond their shared corners): not handled here.
    Degenerate,
}

/// The edge `uv` as a key (smaller index first).
pub(super) fn key(u: usize, v: usize) -> Edge {
    (u.min(v), u.max(v))
}

/// How triangles `t` (operand 0) and `s` (operand 1) meet, as indices into `p`, the exact
/// values of `corners`, with their global indices `ti`, `si` and their planes (t's, then
/// s's).
/// Triangles with a vertex on the other's plane go to [`touch`]. Else each plane must separate
/// the other's vertices strictly; the line of the planes meets each triangle in a segment
/// between its straddling edges' pierce points, and the sign of orient3d(e₀, e₁, f₀, f₁) — for
/// a straddling edge e of one and f of the other, each directed as its triangle runs — tells,
/// up to the side of f₁, whether f's pierce point lies left of e (inside e's triangle), on it
/// (the edges cross: [`End::Edges`]) or right of it. The same sign serves with the triangles'
/// roles swapped (the permutation is even), so four orientations settle the overlap.
pub(super) fn contact<N: Num, C: Corners>(
    p: &C,
    [t_plane, s_plane]: [&C::Plane; 2],
    corners: &[&Point3<N>],
    (ti, t): (usize, [usize; 3]),
    (si, s): (usize, [usize; 3]),
) -> Contact {
    let s_sides = s.map(|v| p.side(t_plane, v));
    if one_side(&s_sides) {
        return Contact::Apart;
    }
    let t_sides = t.map(|v| p.side(s_plane, v));
    if one_side(&t_sides) {
        return Contact::Apart;
    }
    if s_sides.contains(&Equal) || t_sides.contains(&Equal) {
        return touch(p, corners, (ti, t), (si, s), [&s_sides, &t_sides]);
    }
    let (te, se) = (straddling(t, &t_sides), straddling(s, &s_sides));
    let sign = te.map(|(e, _)| se.map(|(f, _)| p.orient3d([e.0, e.1, f.0, f.1])));
    let mut ends: SmallVec<[End; 4]> = SmallVec::new();
    for (j, &(f, side)) in se.iter().enumerate() {
        if sign.iter().all(|row| row[j] == side) {
            ends.push(End::Pierce(key(f.0, f.1), ti));
        }
    }
    for (i, &(e, side)) in te.iter().enumerate() {
        if sign[i].iter().all(|&o| o == side) {
            ends.push(End::Pierce(key(e.0, e.1), si));
        }
        for (j, &(f, _)) in se.iter().enumerate() {
            if sign[i][j] == Equal {
                ends.push(End::Edges(key(e.0, e.1), key(f.0, f.1), si));
            }
        }
    }
    match ends[..] {
        [] => Contact::Apart,
        [x @ End::Edges(..)] => Contact::Cross([x, x]),
        [x, y] => Contact::Cross([x, y]),
        _ => Contact::Degenerate,
    }
}

/// [`contact`] of triangles `t` and `s` with a vertex on the other's plane (`s_sides`: s's
/// vertices against t's plane; `t_sides`: t's against s's): where they share no corner, as
/// [`on_plane`] finds, or if coplanar apart where [`tri::apart`] shows it, else degenerate; a
/// touch in one shared corner or one shared edge; beyond one shared corner, crossing from it
/// where both triangles' other corners straddle the other's plane ([`through_corner`]), else
/// as [`on_plane`] finds; coplanar beyond shared corners, degenerate.
fn touch<N: Num, C: Corners>(
    p: &C,
    corners: &[&Point3<N>],
    (ti, t): (usize, [usize; 3]),
    (si, s): (usize, [usize; 3]),
    [s_sides, t_sides]: [&[Ordering; 3]; 2],
) -> Contact {
    let ctx = N::exact_ctx();
    // The first three pairs of equal corners (t's, s's).
    let mut shared = [None; 3];
    let mut n = 0;
    for x in t {
        for y in s {
            if n < 3 && p.same(x, y) {
                shared[n] = Some([x, y]);
                n += 1;
            }
        }
    }
    let after = |tri: [usize; 3], v: usize| corners_after(tri, v).map(|w| corners[w]);
    let coplanar = s_sides.iter().all(|&o| o == Equal);
    match shared {
        [None, _, _] if coplanar => {
            match tri::apart(t.map(|v| corners[v]), s.map(|v| corners[v]), &ctx) {
                true => Contact::Apart,
                false => Contact::Degenerate,
            }
        }
        [None, _, _] => on_plane(p, (ti, t), (si, s), [s_sides, t_sides]),
        [Some([x, y]), None, _] => {
            // The planes' sides of the corners after the shared one, as `contact` found them.
            let sides_after = |tri: [usize; 3], v: usize, sides: &[Ordering; 3]| {
                let k = tri.iter().position(|&w| w == v).expect("a shared corner");
                [sides[(k + 1) % 3], sides[(k + 2) % 3]]
            };
            let sides = [sides_after(s, y, s_sides), sides_after(t, x, t_sides)];
            let straddle = |[u, v]: [Ordering; 2]| u != v && u != Equal && v != Equal;
            if meet_only_at_given(corners[x], after(t, x), after(s, y), sides, &ctx) {
                Contact::Touch([[x, y]; 2])
            } else if coplanar {
                Contact::Degenerate
            } else if sides.iter().all(|&two| straddle(two)) {
                through_corner(p, (ti, t), (si, s), [x, y], sides[0][1])
            } else {
                on_plane(p, (ti, t), (si, s), [s_sides, t_sides])
            }
        }
        [Some(e0), Some(e1), None] => {
            // s's third corner off t's plane, or on it across the shared edge.
            let third = |tri: [usize; 3], k: usize| {
                (0..3)
                    .find(|&i| tri[i] != e0[k] && tri[i] != e1[k])
                    .expect("a triangle has three distinct corners")
            };
            let (a, w) = (t[third(t, 0)], third(s, 1));
            let edge = [corners[e0[0]], corners[e1[0]]];
            let meets_only_in_edge =
                s_sides[w] != Equal || apart_across(edge, corners[a], corners[s[w]], &ctx);
            match meets_only_in_edge {
                true => Contact::Touch([e0, e1]),
                false => Contact::Degenerate,
            }
        }
        _ => Contact::Degenerate,
    }
}

/// Triangles `t` and `s` sharing only the corner `x` (t's) = `y` (s's), which meet elsewhere
/// too, the corners after it straddling the other's plane strictly on both (`sd`: the side of
/// t's plane of s's second corner after it): both meet the planes' line in a segment from the
/// corner to the opposite edge's pierce point, pointing the same way (they meet beyond the
/// corner), and they cross from the corner to the nearer of the two — by the sign of orient3d
/// of the opposite edges, as in [`contact`].
fn through_corner(
    p: &impl Corners,
    (ti, t): (usize, [usize; 3]),
    (si, s): (usize, [usize; 3]),
    [x, y]: [usize; 2],
    sd: Ordering,
) -> Contact {
    let ([a, b], [c, d]) = (corners_after(t, x), corners_after(s, y));
    let far = match p.orient3d([a, b, c, d]) {
        Equal => End::Edges(key(a, b), key(c, d), si),
        o if o == sd => End::Pierce(key(c, d), ti),
        _ => End::Pierce(key(a, b), si),
    };
    Contact::Cross([End::Corner(x, y), far])
}

/// Triangles `t` and `s`, not coplanar, with a vertex on the other's plane (`sides` as in
/// [`touch`]), sharing no corner or one. Each meets the planes' line in a segment or a point
/// whose ends are its vertices on the other's plane and its straddling edges' pierce points,
/// each on a line (f₀, f₁) with f₁ off that plane ([`line_ends`]). Such an end lies in the
/// other triangle (the host) iff it lies left of or on each of the host's edges e, that is,
/// iff no orient3d(e₀, e₁, f₀, f₁) has the sign opposite to f₁'s side; the ends of the overlap
/// are the ends of either that lie in the other, named by where they lie: strictly inside it
/// as themselves; a pierce point on one host edge where the two edges cross ([`End::Edges`]);
/// a vertex on a host edge as itself, and a pierce point on two host edges as the host's
/// corner there ([`End::Vertex`] both, on the boundary of the triangle named:
/// [`Contact::OnEdge`]); a vertex on two host edges, the shared corner, as [`End::Corner`]
/// (a touch where it is the only end). An edge on the other's plane makes the contact
/// [`Contact::Along`], whatever its ends.
fn on_plane(
    p: &impl Corners,
    (ti, t): (usize, [usize; 3]),
    (si, s): (usize, [usize; 3]),
    [s_sides, t_sides]: [&[Ordering; 3]; 2],
) -> Contact {
    let (t_ends, s_ends) = (line_ends(t, t_sides, si), line_ends(s, s_sides, ti));
    let mut ends: SmallVec<[End; 4]> = SmallVec::new();
    let mut on_edge = false;
    for (mine, mine_index, host) in [(&s_ends, si, t), (&t_ends, ti, s)] {
        for &(end, (f0, f1), side) in mine {
            let signs = [0, 1, 2].map(|k| {
                let (e0, e1) = (host[k], host[(k + 1) % 3]);
                p.orient3d([e0, e1, f0, f1])
            });
            let on: SmallVec<[usize; 3]> = (0..3).filter(|&k| signs[k] == Equal).collect();
            if signs.iter().any(|&o| o != Equal && o != side) {
                continue;
            }
            let found = match (&on[..], end) {
                ([], _) => end,
                (&[k], End::Pierce(f, h)) => {
                    let e = key(host[k], host[(k + 1) % 3]);
                    if host == s {
                        End::Edges(f, e, h)
                    } else if t_sides[k] == Equal && t_sides[(k + 1) % 3] == Equal {
                        // t's edge e lies in s's plane: constructed where f pierces t's (`h`).
                        End::Edges(e, f, h)
                    } else {
                        End::Edges(e, f, si)
                    }
                }
                (&[_], End::Vertex(..)) => {
                    on_edge = true;
                    end
                }
                (&[k, l], End::Pierce(..)) => {
                    on_edge = true;
                    End::Vertex(corner_of(host, k, l), mine_index)
                }
                (&[k, l], End::Vertex(v, _)) => match host == t {
                    true => End::Corner(corner_of(host, k, l), v),
                    false => End::Corner(v, corner_of(host, k, l)),
                },
                _ => return Contact::Degenerate,
            };
            if !ends.contains(&found) {
                ends.push(found);
            }
        }
    }
    let edge_on_plane = |sides: &[Ordering; 3]| sides.iter().filter(|&&o| o == Equal).count() == 2;
    let ends = match ends[..] {
        [] => return Contact::Apart,
        [End::Corner(x, y)] => return Contact::Touch([[x, y]; 2]),
        [x @ (End::Edges(..) | End::Vertex(..))] => [x, x],
        [x, y] => [x, y],
        _ => return Contact::Degenerate,
    };
    if edge_on_plane(t_sides) || edge_on_plane(s_sides) {
        Contact::Along(ends)
    } else if on_edge {
        Contact::OnEdge(ends)
    } else {
        Contact::Cross(ends)
    }
}

/// The corner of triangle `tri` where its edges `k` (from corner k to k + 1) and `l` meet.
fn corner_of(tri: [usize; 3], k: usize, l: usize) -> usize {
    let corner = [tri[k], tri[(k + 1) % 3]]
        .into_iter()
        .find(|v| [tri[l], tri[(l + 1) % 3]].contains(v));
    corner.expect("two edges of a triangle share a corner")
}

/// An end of a triangle's meet with the planes' line, with a line (f₀, f₁) through it, f₁ off
/// the other's plane, and f₁'s side of it ([`on_plane`]).
type LineEnd = (End, (usize, usize), Ordering);

/// The ends of triangle `tri`'s meet with the planes' line, its vertices' sides of the other
/// triangle's plane `sides` (some on it or not all on one side, not all three; the other
/// triangle `other`): each with a line (f₀, f₁) through it, f₁ off the plane, and f₁'s side
/// ([`on_plane`]): the vertices on the plane, and the pierce points of the edges straddling it.
fn line_ends(tri: [usize; 3], sides: &[Ordering; 3], other: usize) -> SmallVec<[LineEnd; 2]> {
    let on: SmallVec<[usize; 3]> = (0..3).filter(|&k| sides[k] == Equal).collect();
    match on[..] {
        [] => straddling(tri, sides)
            .map(|(e, side)| (End::Pierce(key(e.0, e.1), other), e, side))
            .into(),
        [k] => {
            let (v, a, b) = (tri[k], tri[(k + 1) % 3], tri[(k + 2) % 3]);
            let (sa, sb) = (sides[(k + 1) % 3], sides[(k + 2) % 3]);
            let mut ends = smallvec![(End::Vertex(v, other), (v, a), sa)];
            if sa != sb {
                ends.push((End::Pierce(key(a, b), other), (a, b), sb));
            }
            ends
        }
        _ => {
            // An edge on the plane: its ends, each on the line to the third corner.
            let k = (0..3)
                .find(|&k| sides[k] != Equal)
                .expect("a corner off the plane");
            let c = tri[k];
            [1, 2]
                .map(|j| tri[(k + j) % 3])
                .map(|v| (End::Vertex(v, other), (v, c), sides[k]))
                .into()
        }
    }
}

/// True if no vertex lies on the plane and all lie on one side of it.
fn one_side(sides: &[Ordering; 3]) -> bool {
    sides[0] != Equal && sides[0] == sides[1] && sides[1] == sides[2]
}

/// The two edges of triangle `tri` whose ends lie on opposite sides of a plane (`sides`, none
/// on it), each directed as the triangle runs, with the side of its second end.
fn straddling(tri: [usize; 3], sides: &[Ordering; 3]) -> [((usize, usize), Ordering); 2] {
    let mut out = [((0, 0), Equal); 2];
    let mut n = 0;
    for k in 0..3 {
        let j = (k + 1) % 3;
        if sides[k] != sides[j] {
            out[n] = ((tri[k], tri[j]), sides[j]);
            n += 1;
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::num::Float;
    use crate::yin3::corners::{F64Corners, RationalCorners};
    use crate::yin3::values::exact_point;

    /// The contact of two triangles given by their corners (points 0–2 and 3–5, triangles 0
    /// and 1).
    fn contact_of(t: [[f64; 3]; 3], s: [[f64; 3]; 3]) -> Contact {
        let p = [t, s].concat();
        let points: Vec<Point3<Float>> = p
            .iter()
            .map(|c| c.map(|x| Float::from_f64(x).expect("finite")))
            .map(|[x, y, z]| Point3::new(x, y, z))
            .collect();
        let corners: Vec<&Point3<Float>> = points.iter().collect();
        let (t, s) = ((0, [0, 1, 2]), (1, [3, 4, 5]));
        let f64s = F64Corners(p);
        let [a, b] = [t.1, s.1].map(|tri| f64s.plane(tri));
        let on_f64s = contact(&f64s, [&a, &b], &corners, t, s);
        // The same contact on the points' exact rationals.
        let rationals = RationalCorners::new(points.iter().map(exact_point).collect());
        let on_rationals = contact(&rationals, [&t.1, &s.1], &corners, t, s);
        assert_eq!(on_f64s, on_rationals);
        on_f64s
    }

    /// Triangles sharing a corner or an edge touch only where they meet in nothing else:
    /// leaving the corner away from the other, across the edge in one plane or off it. On the
    /// same side of the shared edge in one plane they are degenerate; with a vertex on the
    /// other's plane and nothing shared, apart where they miss.
    #[test]
    fn shared_corners_and_edges_touch_only_where_nothing_else_meets() {
        let t = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]];
        let touch = |s| matches!(contact_of(t, s), Contact::Touch(_));
        let degenerate = |s| matches!(contact_of(t, s), Contact::Degenerate);
        assert!(touch([[0.0; 3], [-1.0, -1.0, 1.0], [-1.0, -1.0, -1.0]]));
        assert!(touch([[1.0, 0.0, 0.0], [0.0; 3], [0.2, -0.3, 0.0]]));
        assert!(touch([[1.0, 0.0, 0.0], [0.0; 3], [0.2, 0.3, 1.0]]));
        assert!(degenerate([[1.0, 0.0, 0.0], [0.0; 3], [0.2, 0.2, 0.0]]));
        assert!(matches!(
            contact_of(t, [[2.0, 0.0, 0.0], [2.0, 1.0, 1.0], [3.0, 0.0, -1.0]]),
            Contact::Apart
        ));
    }

    /// A vertex of s inside t: where s's other corners straddle t's plane, they cross from the
    /// vertex to where t's long edge (points 1–2) leaves s's plane; where both lie above it,
    /// they meet in the vertex alone (the end twice). A vertex of s on t's edge 0–1 ends the
    /// contact on that edge: s (in the plane x + y − z = 1/2 of the vertex) crosses t from it
    /// to where s's far edge pierces t inside, or to where that edge crosses t's edge 0–2,
    /// or, with its far edge below t, meets t in the vertex alone.
    #[test]
    fn a_vertex_inside_the_other_ends_the_overlap() {
        let t = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]];
        let through = contact_of(t, [[0.5, 0.2, 0.0], [2.0, 1.0, 1.0], [3.0, 0.0, -1.0]]);
        let Contact::Cross(ends) = through else {
            panic!("not a crossing: {through:?}");
        };
        assert!(ends.contains(&End::Vertex(3, 0)), "{ends:?}");
        assert!(ends.contains(&End::Pierce((1, 2), 1)), "{ends:?}");
        let touching = contact_of(t, [[0.2, 0.2, 0.0], [1.0, 1.0, 1.0], [0.0, 1.0, 1.0]]);
        assert!(
            matches!(touching, Contact::Cross(ends) if ends == [End::Vertex(3, 0); 2]),
            "{touching:?}"
        );
        let on_edge = |s| match contact_of(t, s) {
            Contact::OnEdge(ends) => ends,
            other => panic!("not on an edge: {other:?}"),
        };
        assert_eq!(
            on_edge([[0.5, 0.0, 0.0], [0.25, 1.25, 1.0], [0.25, -0.75, -1.0]]),
            [End::Vertex(3, 0), End::Pierce((4, 5), 0)]
        );
        assert_eq!(
            on_edge([[0.5, 0.0, 0.0], [0.0, 1.5, 1.0], [0.0, -0.5, -1.0]]),
            [End::Vertex(3, 0), End::Edges((0, 2), (4, 5), 1)]
        );
        assert_eq!(
            on_edge([[0.5, 0.0, 0.0], [0.0, -1.0, -1.5], [1.0, -1.0, -0.5]]),
            [End::Vertex(3, 0); 2]
        );
    }

    /// Through a shared corner, the triangles cross from it to the nearer end: t (in z = 0,
    /// x + y ≤ 1) and s (in the plane x = y) meet along the diagonal from the origin to where
    /// t's long edge (points 1–2) pierces s, (1/2, 1/2, 0), short of where s's far edge
    /// pierces t's plane; with s's far edge moved to x = y = 1/2 the edges cross there, and to
    /// x = y = 1/4 s's edge pierces t first. With its edge from the corner on t's plane, s
    /// meets t along it from the corner to where t's long edge crosses it.
    #[test]
    fn triangles_cross_from_a_shared_corner_to_the_nearer_end() {
        let t = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]];
        let s = |h: f64| [[0.0; 3], [h, h, 1.0], [h, h, -1.0]];
        let cross = |s| match contact_of(t, s) {
            Contact::Cross(ends) => ends,
            other => panic!("not a crossing: {other:?}"),
        };
        assert_eq!(cross(s(1.0)), [End::Corner(0, 3), End::Pierce((1, 2), 1)]);
        assert_eq!(
            cross(s(0.5)),
            [End::Corner(0, 3), End::Edges((1, 2), (4, 5), 1)]
        );
        assert_eq!(cross(s(0.25)), [End::Corner(0, 3), End::Pierce((4, 5), 0)]);
        let edge_in_plane = contact_of(t, [[0.0; 3], [1.0, 1.0, 0.0], [1.0, 1.0, -1.0]]);
        assert_eq!(
            edge_in_plane,
            Contact::Along([End::Corner(0, 3), End::Edges((1, 2), (3, 4), 1)])
        );
    }

    /// An edge of t on s's plane (z = 0, s the triangle x, y ≥ −1, x + y ≤ 2): they meet
    /// along its part inside s, ended by its corners inside s and by its crossings with s's
    /// edges (constructed through t's plane, t being the first edge's triangle), also with
    /// the roles of the operands swapped; a corner on s's edge ends it there as a vertex, a
    /// corner of s on the line of t's edge beyond it changes nothing, and an edge beside s
    /// misses it.
    #[test]
    fn an_edge_on_the_others_plane_meets_it_along_its_part_inside() {
        let s = [[-1.0, -1.0, 0.0], [3.0, -1.0, 0.0], [-1.0, 3.0, 0.0]];
        let t = |x0: f64, x1: f64| [[x0, 0.0, 0.0], [x1, 0.0, 0.0], [0.5, 0.0, 1.0]];
        let along = |t, s| match contact_of(t, s) {
            Contact::Along(ends) => ends,
            other => panic!("not along: {other:?}"),
        };
        assert_eq!(
            along(t(0.0, 1.0), s),
            [End::Vertex(0, 1), End::Vertex(1, 1)]
        );
        assert_eq!(
            along(t(0.0, 5.0), s),
            [End::Edges((0, 1), (4, 5), 0), End::Vertex(0, 1)]
        );
        assert_eq!(
            along(t(-2.0, 5.0), s),
            [End::Edges((0, 1), (4, 5), 0), End::Edges((0, 1), (3, 5), 0)]
        );
        // s first: its edge (points 0–1 now) crosses t's edge 3–4 through t's plane.
        assert_eq!(
            along(s, t(0.0, 5.0)),
            [End::Vertex(3, 0), End::Edges((1, 2), (3, 4), 1)]
        );
        assert_eq!(
            along(t(-1.0, 1.0), s),
            [End::Vertex(0, 1), End::Vertex(1, 1)]
        );
        // s with a corner on the line of t's edge (and so on t's plane).
        let on_line = [[-1.0, 0.0, 0.0], [3.0, -1.0, 0.0], [0.0, 3.0, 0.0]];
        assert_eq!(
            along(t(0.0, 1.0), on_line),
            [End::Vertex(0, 1), End::Vertex(1, 1)]
        );
        assert!(matches!(contact_of(t(5.0, 6.0), s), Contact::Apart));
    }

    /// Triangles whose straddling edges cross: t (in z = 0) meets the x-axis in [0, 1], its
    /// edge 1–2 ending it at (1, 0, 0); s (in y = 0) meets it in [1/2, 1] or [1, 3/2], its edge
    /// 3–5 ending it at (1, 0, 0) too. Where the segments overlap, the crossing runs from the
    /// crossing edges to s's other pierce point; where they only touch end to end, the
    /// triangles meet in that one point (the end twice).
    #[test]
    fn crossing_edges_end_the_overlap() {
        let t = [[-1.0, -1.0, 0.0], [1.0, -1.0, 0.0], [1.0, 1.0, 0.0]];
        let edges = End::Edges((1, 2), (3, 5), 1);
        let cross = |s| match contact_of(t, s) {
            Contact::Cross(ends) => ends,
            other => panic!("not a crossing: {other:?}"),
        };
        let overlap = cross([[0.75, 0.0, 1.0], [0.25, 0.0, -1.0], [1.25, 0.0, -1.0]]);
        assert!(overlap.contains(&edges), "{overlap:?}");
        assert!(overlap.contains(&End::Pierce((3, 4), 0)), "{overlap:?}");
        let end_to_end = cross([[0.0, 0.0, 1.0], [3.0, 0.0, -1.0], [2.0, 0.0, -1.0]]);
        assert_eq!(end_to_end, [edges, edges]);
    }
}
