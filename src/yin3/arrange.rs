//! The arrangement of triangles against each other (seed 004 steps 1–2; yin3 docs:
//! *Triangle–triangle*, *Re-triangulation*): every contact of two triangles is computed exactly
//! (a meet's pairs first by name where [`Named`] settles them), every contact point is given to
//! every triangle that contains it, and each triangle that received points or cut segments is
//! re-triangulated in its plane. Because a triangle receives *every* contact point lying on it,
//! two triangles that share a segment split it at the same points: the pieces form a conforming
//! complex.

use super::bvh::Bvh;
use super::contact::{key, Edge};
use super::corners::{Corners, F64Corners, RationalCorners};
use super::geom::{f64_box, in_triangle3, Chart};
use super::named::{Named, Settled};
use super::soup::Soup;
use super::tri::{apart_across, corners_after, intersect_with, meet_only_at};
use super::triangulate::{triangulate, TriangulateError};
use super::values::exact_points;
use crate::kernel::{orient, orient3d, Point, Point3};
use crate::num::{Float, Num, Rational};
use foldhash::{HashMap, HashMapExt};
use rstar::AABB;
use smallvec::{smallvec, SmallVec};
use std::cell::OnceCell;
use std::cmp::Ordering;
use std::collections::BTreeSet;

/// Which pairs of triangles are intersected.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Pairs {
    /// Only triangles of different operands (each operand is already a valid boundary).
    Across,
    /// Every pair: the validation of one operand; meeting interiors are an error.
    All,
}

/// Why an arrangement could not be made.
#[derive(Clone, Debug)]
pub(crate) enum ArrangeError<N> {
    /// Triangles `a` and `b` cross (`coplanar` false) or overlap (true) near `point`.
    Clash {
        a: usize,
        b: usize,
        coplanar: bool,
        point: Point3<N>,
    },
    /// Cut segments crossed inside a triangle (an operand was not valid).
    Internal(String),
}

/// The arrangement of a soup's triangles against each other.
pub(crate) struct Arrangement {
    /// The pieces: each a triangle over the soup's points, oriented as its parent, with the
    /// index of its parent triangle.
    pub pieces: Vec<([usize; 3], usize)>,
    /// For each of the soup's points, true if two intersected triangles meet there (for
    /// [`Pairs::Across`]: the points of each operand on the other's boundary).
    pub contact: Vec<bool>,
    /// For each triangle, the triangles it was intersected with that overlap it in an area
    /// of their common plane.
    pub coplanar: Vec<Vec<usize>>,
    /// The hierarchies of the soup's triangles' boxes: for [`Pairs::Across`] each operand's,
    /// for [`Pairs::All`] one of all of them.
    pub trees: Vec<Bvh>,
}

/// The segments a triangle is cut along by one contact, as pairs of the soup's points.
type Cuts = SmallVec<[(usize, usize); 3]>;

/// The arrangement of the soup's triangles (`soup.points` gains the contact points), every
/// contact constructed.
pub(crate) fn arrange<N: Num>(
    soup: &mut Soup<N>,
    pairs: Pairs,
    ctx: &N::Ctx,
) -> Result<Arrangement, ArrangeError<N>> {
    arrange_on::<N, F64Corners, N>(soup, pairs, ctx, None)
}

/// The arrangement of an exact meet's soup ([`Pairs::Across`]) whose pairs are first
/// classified as the transversal meet does ([`Named`]), on the input vertices' `f64`s where
/// each is one, and constructed only where that does not settle them.
pub(crate) fn arrange_named<N: Num>(
    soup: &mut Soup<N>,
    ctx: &N::Ctx,
) -> Result<Arrangement, ArrangeError<N>> {
    debug_assert!(N::EXACT, "named points are exact");
    let exact = exact_points(&soup.points);
    if exact.iter().all(Point3::is_f64) {
        let (f64s, floats) = f64_values(&exact);
        arrange_on(soup, Pairs::Across, ctx, Some((F64Corners(f64s), floats)))
    } else {
        let corners = RationalCorners::new(exact.clone());
        arrange_on(soup, Pairs::Across, ctx, Some((corners, exact)))
    }
}

/// Points whose coordinates are `f64`s, as `f64` triples and as float points.
pub(super) fn f64_values(exact: &[Point3<Rational>]) -> (Vec<[f64; 3]>, Vec<Point3<Float>>) {
    let f64s: Vec<[f64; 3]> = exact.iter().map(Point3::to_f64).collect();
    let floats = (f64s.iter())
        .map(|&[x, y, z]| Point3::new(Float::new(x), Float::new(y), Float::new(z)))
        .collect();
    (f64s, floats)
}

/// [`arrange`], with the pairs classified first where `named` gives the input vertices' exact
/// tests and values ([`Named::new`]).
fn arrange_on<N: Num, C: Corners, M: Num>(
    soup: &mut Soup<N>,
    pairs: Pairs,
    ctx: &N::Ctx,
    named: Option<(C, Vec<Point3<M>>)>,
) -> Result<Arrangement, ArrangeError<N>> {
    let n = soup.tris.len();
    let group: Vec<usize> = (0..n)
        .map(|i| match pairs {
            Pairs::Across => usize::from(soup.operand[i]),
            Pairs::All => 0,
        })
        .collect();
    let f64_boxes: Vec<AABB<[f64; 3]>> = (0..n).map(|i| f64_box(soup.corners(i))).collect();
    let members: [Vec<usize>; 2] = [0, 1].map(|g| (0..n).filter(|&i| group[i] == g).collect());
    // The hierarchies of the groups' boxes, and the pairs whose boxes meet, each as (smaller,
    // larger): of the two operands' hierarchies walked together, or of the one hierarchy
    // walked with itself.
    let trees: Vec<Bvh> = match pairs {
        Pairs::Across => members.iter().map(|m| Bvh::new(m, &f64_boxes)).collect(),
        Pairs::All => vec![Bvh::new(&members[0], &f64_boxes)],
    };
    let mut meeting: Vec<(usize, usize)> = Vec::new();
    let (x, y) = (&trees[0], trees.last().expect("a hierarchy"));
    x.each_meeting_pair(y, |t, s| match pairs {
        Pairs::Across => meeting.push((t.min(s), t.max(s))),
        // Each pair comes twice, once in each order, and each box with itself.
        Pairs::All if t < s => meeting.push((t, s)),
        Pairs::All => {}
    });
    meeting.sort_unstable();
    let mut cuts: Vec<Vec<(usize, usize)>> = vec![Vec::new(); n];
    let mut coplanar: Vec<Vec<usize>> = vec![Vec::new(); n];
    let mut contact: BTreeSet<usize> = BTreeSet::new();
    // The contact points each triangle is known to contain: in exact mode those of its own
    // intersections (constructed exactly on both triangles), which the distribution below need
    // not test again; float mode's constructed points are rounded and are tested like others.
    let mut extra: Vec<BTreeSet<usize>> = vec![BTreeSet::new(); n];
    // Each triangle's normal, made once where a pair needs it.
    let normals: Vec<OnceCell<Point3<N>>> = (0..n).map(|_| OnceCell::new()).collect();
    let mut named = named.map(|(p, values)| Named::new(p, &values, soup, &meeting));
    for (k, (i, j)) in meeting.into_iter().enumerate() {
        // The contact's points in the soup, and the segments each triangle is cut along.
        let (ids, cut): (SmallVec<[usize; 6]>, [Cuts; 2]) = match named
            .as_mut()
            .map_or(Settled::Open, |n| n.settled(k, (i, j), soup))
        {
            Settled::Apart => continue,
            Settled::Touch(at) => {
                contact.extend(at);
                continue;
            }
            Settled::Cross([p, q]) if p == q => (smallvec![p], Default::default()),
            Settled::Cross([p, q]) => (smallvec![p, q], [smallvec![(p, q)], smallvec![(p, q)]]),
            Settled::InPlane { points, cuts, area } => {
                if area {
                    coplanar[i].push(j);
                    coplanar[j].push(i);
                }
                (points, cuts)
            }
            Settled::Open => {
                if let Some(shared) = shared_only(&soup.points, soup.tris[i], soup.tris[j], ctx) {
                    contact.extend(shared);
                    continue;
                }
                let (t, s) = (soup.corners(i), soup.corners(j));
                let Some(c) = intersect_with(t, s, [&normals[i], &normals[j]], ctx) else {
                    continue;
                };
                if c.interiors_meet && pairs == Pairs::All {
                    return Err(ArrangeError::Clash {
                        a: i,
                        b: j,
                        coplanar: c.coplanar,
                        point: c.points[0].clone(),
                    });
                }
                if c.coplanar && c.interiors_meet {
                    coplanar[i].push(j);
                    coplanar[j].push(i);
                }
                let ids: SmallVec<[usize; 6]> = c.points.iter().map(|p| soup.intern(p)).collect();
                let cut = [&c.cuts_t, &c.cuts_s]
                    .map(|cuts| cuts.iter().map(|&(p, q)| (ids[p], ids[q])).collect());
                (ids, cut)
            }
        };
        for &v in &ids {
            contact.insert(v);
            for t in [i, j] {
                if N::EXACT && !soup.tris[t].contains(&v) {
                    extra[t].insert(v);
                }
            }
        }
        let [cut_i, cut_j] = cut;
        cuts[i].extend(cut_i);
        cuts[j].extend(cut_j);
    }
    // Every contact point goes to every triangle containing it: the hierarchy of the points'
    // boxes walked with the triangles'. A point inside an edge by its name already has them
    // all: inside an edge e of one operand and inside a triangle s or an edge f of the other,
    // it lies (each operand's boundary being conforming) only in e's triangles and in s or
    // in f's triangles. Each such pair of triangles meets there, in no shared corner, and the
    // point is an end of the pair's contact (e pierces s's plane; e and f cross), named alike
    // or constructed with the same value: it is in both triangles' points already.
    let through = named.map_or_else(HashMap::new, |n| n.edges_through());
    let contacts: Vec<usize> = (contact.iter().copied())
        .filter(|v| !through.contains_key(v))
        .collect();
    let point_boxes: Vec<AABB<[f64; 3]>> = (contacts.iter())
        .map(|&v| f64_box([&soup.points[v]]))
        .collect();
    let at_points = Bvh::new(&(0..contacts.len()).collect::<Vec<_>>(), &point_boxes);
    let mut near: Vec<(usize, usize)> = Vec::new();
    for tree in &trees {
        at_points.each_meeting_pair(tree, |k, t| near.push((t, contacts[k])));
    }
    for (t, v) in near {
        if !soup.tris[t].contains(&v)
            && !extra[t].contains(&v)
            && in_triangle3(soup.corners(t), &soup.points[v], ctx)
        {
            extra[t].insert(v);
        }
    }
    let no_edges: &[Edge] = &[];
    let named_edges = |v: usize| through.get(&v).map_or(no_edges, |e| &e[..]);
    let mut pieces = Vec::with_capacity(n);
    for t in 0..n {
        if extra[t].is_empty() {
            pieces.push((soup.tris[t], t));
            continue;
        }
        let [a, b, c] = soup.corners(t);
        let chart = Chart::of_triangle(a, b, c);
        let (sides, others) = by_side(
            &soup.points,
            soup.tris[t],
            &chart,
            &extra[t],
            named_edges,
            ctx,
        );
        let cut = retriangulate(
            &soup.points,
            soup.tris[t],
            chart,
            [&sides[0], &sides[1], &sides[2]],
            others,
            &cuts[t],
            ctx,
        )
        .map_err(|e| ArrangeError::Internal(format!("re-triangulating triangle {t}: {e:?}")))?;
        pieces.extend(cut.into_iter().map(|piece| (piece, t)));
    }
    let mut on_contact = vec![false; soup.points.len()];
    for v in contact {
        on_contact[v] = true;
    }
    Ok(Arrangement {
        pieces,
        contact: on_contact,
        coplanar,
        trees,
    })
}

/// The points `extra` of the closed triangle `tri` (indices into `points`, none a corner),
/// as those inside each side (side k from corner k to corner k + 1) and the others, where the
/// predicates are exact (a tolerance could put a point on a side that is not); else all as
/// others. A point inside an edge by its name (`named`: the edges, smaller end first, each
/// point lies inside) that is a side is on it without a predicate; the others are told by
/// orientations, exact and unfiltered where they are zero. Re-triangulation splits the sides
/// at the former without locating them, and may then cut the triangle along chains of cuts
/// without any predicate.
fn by_side<'a, N: Num>(
    points: &[Point3<N>],
    tri: [usize; 3],
    chart: &Chart,
    extra: &BTreeSet<usize>,
    named: impl Fn(usize) -> &'a [Edge],
    ctx: &N::Ctx,
) -> ([SmallVec<[usize; 4]>; 3], SmallVec<[usize; 8]>) {
    let mut sides: [SmallVec<[usize; 4]>; 3] = Default::default();
    if !N::EXACT {
        return (sides, extra.iter().copied().collect());
    }
    let side_edges = [0, 1, 2].map(|k| key(tri[k], tri[(k + 1) % 3]));
    let corners = tri.map(|v| chart.project(&points[v]));
    let mut others = SmallVec::new();
    for &v in extra {
        let edges = named(v);
        let on = (0..3)
            .find(|&k| edges.contains(&side_edges[k]))
            .or_else(|| {
                let p = chart.project(&points[v]);
                (0..3).find(|&k| {
                    orient(&corners[k], &corners[(k + 1) % 3], &p, ctx) == Ordering::Equal
                })
            });
        match on {
            Some(k) => sides[k].push(v),
            None => others.push(v),
        }
    }
    (sides, others)
}

/// The shared vertices of triangles `t` and `s` (indices into `points`) if they are the whole
/// intersection, decided without constructing anything: two triangles sharing an edge and not
/// coplanar meet in that edge, and coplanar ones iff they lie on opposite sides of it; two
/// sharing one vertex, as [`meet_only_at`] tells.
pub(crate) fn shared_only<N: Num>(
    points: &[Point3<N>],
    t: [usize; 3],
    s: [usize; 3],
    ctx: &N::Ctx,
) -> Option<Vec<usize>> {
    let shared: Vec<usize> = t.iter().copied().filter(|v| s.contains(v)).collect();
    let from = |tri: [usize; 3], v: usize| corners_after(tri, v).map(|x| &points[x]);
    let alone = match shared[..] {
        [u, v] => {
            // The third corner of a triangle.
            let third = |tri: [usize; 3]| {
                let x = tri.into_iter().find(|x| !shared.contains(x));
                &points[x.expect("a triangle has three distinct corners")]
            };
            let (a, w) = (third(t), third(s));
            let (pu, pv) = (&points[u], &points[v]);
            orient3d(pu, pv, a, w, ctx) != Ordering::Equal || apart_across([pu, pv], a, w, ctx)
        }
        [v] => meet_only_at(&points[v], from(t, v), from(s, v), ctx),
        _ => false,
    };
    alone.then_some(shared)
}

/// The pieces of the triangle `tri` (indices into `points`), counterclockwise in `chart`,
/// with the points `sides[k]` known to lie inside its side k (from corner k to corner k + 1),
/// the points `extra` on it and the cut segments `cuts`, triangulated in the chart.
pub(crate) fn retriangulate<N: Num>(
    points: &[Point3<N>],
    tri: [usize; 3],
    chart: Chart,
    sides: [&[usize]; 3],
    extra: impl IntoIterator<Item = usize>,
    cuts: &[(usize, usize)],
    ctx: &N::Ctx,
) -> Result<Vec<[usize; 3]>, TriangulateError> {
    // Most cut triangles hold a few points: these tables stay on the stack.
    let ids: SmallVec<[usize; 16]> = tri
        .into_iter()
        .chain(sides.iter().flat_map(|side| side.iter().copied()))
        .chain(extra)
        .collect();
    // Each point's (last) place in `ids`, by a search of the pairs sorted by point.
    let mut by_point: SmallVec<[(usize, usize); 16]> =
        ids.iter().enumerate().map(|(k, &v)| (v, k)).collect();
    by_point.sort_unstable();
    let local = |v: &usize| {
        let after = by_point.partition_point(|&(w, _)| w <= *v);
        let &(w, k) = by_point.get(after.checked_sub(1)?)?;
        (w == *v).then_some(k)
    };
    let pts: SmallVec<[Point<N>; 16]> = ids.iter().map(|&v| chart.project(&points[v])).collect();
    let cons: SmallVec<[(usize, usize); 16]> = cuts
        .iter()
        .filter(|(p, q)| p != q)
        .filter_map(|(p, q)| Some((local(p)?, local(q)?)))
        .collect();
    let on_side = sides.map(|side| {
        (side.iter())
            .map(|v| local(v).expect("a side's points are among the ids"))
            .collect::<SmallVec<[usize; 8]>>()
    });
    let on_side = [&on_side[0][..], &on_side[1][..], &on_side[2][..]];
    let tris = triangulate(&pts, [0, 1, 2], on_side, &cons, ctx)?;
    Ok(tris.into_iter().map(|tri| tri.map(|k| ids[k])).collect())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::num::Rational;

    /// Points of a triangle's sides are told from those inside it, each by its side, and the
    /// triangle re-triangulated with them is tiled, with one cut (the general path) and with
    /// a chain of cuts from side to side (the predicate-free path): every point is a vertex,
    /// every piece is counterclockwise, each edge is met once each way or lies on a side, and
    /// the pieces' areas sum to the triangle's.
    #[test]
    fn points_on_sides_are_told_apart_and_the_pieces_tile() {
        let p = |x, y| Point3::<Rational>::int(x, y, 0);
        let points = vec![
            p(0, 0),
            p(4, 0),
            p(0, 4),
            p(2, 0),
            p(2, 2),
            p(0, 1),
            p(1, 1),
            p(3, 1),
        ];
        let tri = [0, 1, 2];
        let chart = Chart::of_triangle(&points[0], &points[1], &points[2]);
        let extra: BTreeSet<usize> = (3..points.len()).collect();
        let (sides, others) = by_side(&points, tri, &chart, &extra, |_| &[], &());
        assert_eq!(
            sides.each_ref().map(|s| s.to_vec()),
            [vec![3], vec![4, 7], vec![5]]
        );
        assert_eq!(others.to_vec(), vec![6]);
        let area = |t: [usize; 3]| {
            let [a, b, c] = t.map(|v| chart.project(&points[v]));
            (b.x.clone() - a.x.clone()) * (c.y.clone() - a.y.clone())
                - (b.y.clone() - a.y.clone()) * (c.x.clone() - a.x.clone())
        };
        // The side (0 to 2) holding both ends of an edge, if any.
        let on_side = |u: usize, v: usize| {
            (0..3).any(|k| {
                let side = [tri[k], tri[(k + 1) % 3]];
                let on = |w: usize| side.contains(&w) || sides[k].contains(&w);
                on(u) && on(v)
            })
        };
        for cuts in [vec![(3, 4), (5, 6)], vec![(5, 6), (6, 4)]] {
            let side_slices = [&sides[0][..], &sides[1][..], &sides[2][..]];
            let pieces =
                retriangulate(&points, tri, chart, side_slices, others.clone(), &cuts, &())
                    .unwrap();
            assert!(pieces.iter().all(|&t| area(t) > Rational::from_i64(0)));
            let total = pieces
                .iter()
                .fold(Rational::from_i64(0), |s, &t| s + area(t));
            assert_eq!(total, area(tri));
            assert!((0..points.len()).all(|v| pieces.iter().any(|t| t.contains(&v))));
            let edges: Vec<(usize, usize)> = (pieces.iter())
                .flat_map(|t| (0..3).map(move |k| (t[k], t[(k + 1) % 3])))
                .collect();
            for &(u, v) in &edges {
                let twins = edges.iter().filter(|&&e| e == (v, u)).count();
                assert!(twins == 1 || twins == 0 && on_side(u, v), "edge {u}-{v}");
                assert_eq!(edges.iter().filter(|&&e| e == (u, v)).count(), 1);
            }
            for &(u, v) in &cuts {
                assert!(edges.contains(&(u, v)) || edges.contains(&(v, u)));
            }
        }
    }
}
