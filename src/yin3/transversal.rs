//! The meet of two sets whose boundaries cross transversally (seed 004 steps 1–5 for the
//! generic case; yin3 docs: *Float mode*, *Meet*; exact sets come here through
//! [`super::grid`], scaled to float sets where they lie on a small common integer grid):
//! every pair of triangles of different operands misses, crosses along a segment whose inside
//! runs through both triangles' insides, or touches in a shared corner or edge
//! ([`super::contact`]) — no vertex on an edge of the other, no edge on the other's plane.
//! Then everything the general arrangement decides with constructed points is decided from
//! exact orientations of the input vertices ([`super::corners`]: `f64` filters and integers
//! for float points, filtered rational orientations for exact ones):
//! - each end of a crossing segment is where an edge of one operand pierces a triangle of the
//!   other, where an edge of one crosses an edge of the other, a vertex of one inside a
//!   triangle of the other, or a shared corner; each constructed point is named by what
//!   defines it and constructed exactly once;
//! - a pierce point lies on the edge's triangles and in the pierced triangle, crossing edges'
//!   point on both edges' triangles, a vertex also in the triangle it lies in, and nowhere
//!   else;
//! - membership is constant on patches (pieces of one operand joined across edges that are
//!   neither crossing segments nor shared edges) and flips across every crossing segment, so
//!   one ray per connected surface and per patch that flips cannot reach, from an input vertex
//!   off the other boundary, decides every patch; shared corners become one point in the
//!   meet.
//!
//! Where no pair meets at all, each glued surface lies wholly inside or outside the other
//! operand, and one ray per glued surface decides it ([`Transversal::Apart`]).
//!
//! Where no pair crosses and pairs meet at most in shared corners or a shared edge, with
//! nothing else in common (the boundaries touch, as an inner ball touching a torus along a
//! loop of edges), the operands' triangles are the pieces: a patch — triangles of one operand
//! joined across its edges that do not touch — lies off the other boundary but for its
//! touching corners and stays connected without them, so one ray per patch, from a corner that
//! does not touch, decides it (where no edge of an operand touches, its glued surfaces serve as
//! the patches).
//!
//! If any pair is not generic the caller falls back to the general exact meet; the result is
//! the exact meet either way.

use super::arrange::retriangulate;
use super::bvh::Bvh;
use super::contact::{contact, key, Contact, Edge, End, Site};
use super::corners::{Corners, F64Corners, RationalCorners};
use super::fins::Fin;
use super::locate::{ray_box, winding, TriBoxes};
use super::parallel::{map_all, PARALLEL_FROM};
use super::set::{compact, Brep};
use super::values::{exact_point, exact_points};
use crate::kernel::Point3;
use crate::num::{Num, Rational};
use crate::union_find::UnionFind;
use foldhash::{HashMap, HashMapExt, HashSet, HashSetExt};
use rayon::prelude::*;
use rstar::{Envelope, AABB};
use std::cell::{Cell, OnceCell};

/// Where the boundaries meet, as edges of the pieces of the transversal meet.
#[derive(Default)]
struct Seams {
    /// The crossing segments: membership flips across each.
    crossing: HashSet<Edge>,
    /// The shared edges, in each operand's numbering: membership may change across them.
    shared: HashSet<Edge>,
    /// Operand 1's shared corners, to operand 0's equal ones.
    same: HashMap<usize, usize>,
    /// The input vertices on the other operand's boundary: shared corners (both indices) and
    /// vertices inside the other's triangles.
    on_other: HashSet<usize>,
}

impl Seams {
    /// Records operand 1's corner `y`, equal to operand 0's corner `x`.
    fn corner(&mut self, x: usize, y: usize) {
        self.same.insert(y, x);
        self.on_other.extend([x, y]);
    }
}

/// The points where the boundaries meet, each once: constructed ones numbered from `first`,
/// each on the sides of its edges' triangles (`on_edge`); a pierce point or a vertex inside its
/// triangle (`extra`).
struct Sites {
    first: usize,
    index: HashMap<Site, usize>,
    /// For each point in order, an edge and a triangle through whose plane it passes there.
    made: Vec<(Edge, usize)>,
    on_edge: HashMap<Edge, Vec<usize>>,
    extra: Vec<Vec<usize>>,
}

impl Sites {
    /// No points yet, numbered from `first`, on `tris` triangles, room for those of `ends`
    /// contact ends.
    fn new(first: usize, tris: usize, ends: usize) -> Self {
        Sites {
            first,
            index: HashMap::with_capacity(ends),
            made: Vec::with_capacity(ends),
            on_edge: HashMap::with_capacity(ends),
            extra: vec![Vec::new(); tris],
        }
    }

    /// The index of the point `end` in operand 0's triangles and in operand 1's: a corner's
    /// own in each, a vertex's own in both (put inside its triangle on first sight), a
    /// constructed point's (numbered on first sight) in both.
    fn at(&mut self, end: End) -> (usize, usize) {
        let (site, made, edges, inside) = match end {
            End::Pierce(edge, tri) => {
                let site = Site::Pierce(edge, tri);
                (site, (edge, tri), [Some(edge), None], Some(tri))
            }
            End::Edges(e, f, tri) => (Site::Edges(e, f), (e, tri), [Some(e), Some(f)], None),
            End::Corner(x, y) => return (x, y),
            End::Vertex(v, tri) => {
                if self.index.insert(Site::Vertex(v, tri), v).is_none() {
                    self.extra[tri].push(v);
                }
                return (v, v);
            }
        };
        let next = self.first + self.made.len();
        let v = *self.index.entry(site).or_insert(next);
        if v == next {
            self.made.push(made);
            for edge in edges.into_iter().flatten() {
                self.on_edge.entry(edge).or_default().push(v);
            }
            if let Some(tri) = inside {
                self.extra[tri].push(v);
            }
        }
        (v, v)
    }
}

/// Rays that scan every triangle's box of the other operand before an R-tree of its boxes is
/// built (one in unit tests, so that they take both ways).
const SCANNED_RAYS: usize = if cfg!(test) { 1 } else { 8 };

/// The contact search on rayon's threads is split into at least this many pieces.
const PIECES: usize = 64;

/// Triangles over a table of exact points.
type Complex = (Vec<Point3<Rational>>, Vec<[usize; 3]>);

/// The meet of two boundaries that cross transversally, touch, or do not meet.
pub(crate) enum Transversal {
    /// The meet is this operand (0 or 1) as it is: its boundary lies inside the other but
    /// where the two touch, and none of the other's lies inside it.
    Operand(usize),
    /// The boundaries do not meet: for each operand, whether each of its glued surfaces lies
    /// inside the other operand (one ray per surface).
    Apart([Vec<bool>; 2]),
    /// They cross or touch: the meet's triangles (a conforming complex, as the validator
    /// would rebuild it) over a table of exact points, some of which may be unused (and then
    /// need not be the operands' values).
    Crossing(Complex),
}

impl Transversal {
    /// The meet's triangles over a table of exact points (some may be unused); where the
    /// boundaries are apart, the triangles of the glued surfaces that lie inside the other
    /// operand, over the points they use.
    pub(crate) fn complex<N: Num>(self, a: &Brep<N>, b: &Brep<N>) -> Complex {
        let inside = match self {
            Transversal::Crossing(complex) => return complex,
            Transversal::Apart(inside) => inside,
            Transversal::Operand(o) => {
                let sides = [
                    vec![o == 0; a.surfaces.len()],
                    vec![o == 1; b.surfaces.len()],
                ];
                return Transversal::Apart(sides).complex(a, b);
            }
        };
        let mut tris = Vec::new();
        for (o, (op, inside)) in [a, b].into_iter().zip(inside).enumerate() {
            let shift = o * a.points.len();
            for (surface, _) in op.surfaces.iter().zip(inside).filter(|(_, kept)| *kept) {
                tris.extend(
                    surface
                        .triangles
                        .iter()
                        .map(|&t| op.tris[t].map(|v| v + shift)),
                );
            }
        }
        exact_complex([a, b], tris)
    }
}

/// The exact meet of the boundaries `a` and `b` (bounded or not) if they cross transversally,
/// touch in shared corners and edges only, or do not meet (module docs); `None` otherwise.
/// Float points are read as `f64`s, exact ones as rationals ([`super::corners`]).
pub(crate) fn transversal_meet<N: Num>(a: &Brep<N>, b: &Brep<N>) -> Option<Transversal> {
    let all = || a.points.iter().chain(&b.points);
    if N::EXACT {
        meet_on(
            a,
            b,
            &RationalCorners::new(all().map(exact_point).collect()),
        )
    } else {
        meet_on(a, b, &F64Corners(all().map(|p| p.to_f64()).collect()))
    }
}

/// [`transversal_meet`] with the exact predicates and constructions of `p`, the vertices of
/// `a` then those of `b`.
fn meet_on<N: Num, C: Corners>(a: &Brep<N>, b: &Brep<N>, p: &C) -> Option<Transversal> {
    let na = a.points.len();
    let mut tris: Vec<[usize; 3]> = a.tris.clone();
    tris.extend(b.tris.iter().map(|t| t.map(|v| v + na)));
    let first_b = a.tris.len();
    let corners: Vec<&Point3<N>> = a.points.iter().chain(&b.points).collect();
    let boxes: Vec<AABB<[f64; 3]>> = tris.iter().map(|&t| p.bbox(t)).collect();
    let (near_a, near_b) = near(&boxes, first_b);
    // Each operand's near triangles in a hierarchy of boxes; both are walked together.
    let (bvh_a, bvh_b) = (Bvh::new(&near_a, &boxes), Bvh::new(&near_b, &boxes));
    let parallel = tris.len() >= PARALLEL_FROM;
    // The crossing and the touching pairs found so far, to which `search` adds those of the
    // pairs of boxes that meet under a pair of nodes (operand 0's triangle first); the first
    // degenerate pair ends the search.
    type Found = (Vec<(usize, usize, [End; 2])>, Vec<[[usize; 2]; 2]>);
    let search = |(mut crossing, mut touching): Found, pair| {
        let generic = bvh_a.meeting_pairs(&bvh_b, pair, &mut |t, s| {
            let both = [&p.plane(tris[t]), &p.plane(tris[s])];
            match contact(p, both, &corners, (t, tris[t]), (s, tris[s])) {
                Contact::Apart => {}
                Contact::Cross(ends) => crossing.push((t, s, ends)),
                Contact::Touch(at) => touching.push(at),
                Contact::Along(_) | Contact::OnEdge(_) | Contact::Degenerate => return false,
            }
            true
        });
        generic.then_some((crossing, touching))
    };
    let pieces = bvh_a.meeting_nodes(&bvh_b, if parallel { PIECES } else { 1 });
    let (crossings, touching) = if parallel {
        let join = |(mut c, mut t): Found, (c1, t1): Found| {
            c.extend(c1);
            t.extend(t1);
            Some((c, t))
        };
        (pieces.into_par_iter())
            .try_fold(Found::default, search)
            .try_reduce(Found::default, join)?
    } else {
        pieces.into_iter().try_fold(Found::default(), search)?
    };
    // The search's hierarchies are done with: free them before the points are made.
    drop((bvh_a, bvh_b));
    let rays = Rays::new([a, b], &boxes);
    if crossings.is_empty() && !touching.is_empty() {
        return touching_meet(&touching, &rays);
    }
    if crossings.is_empty() {
        // Each glued surface lies wholly on one side of the other boundary.
        let inside = |o: usize| -> Vec<bool> {
            let op = [a, b][o];
            op.surfaces
                .iter()
                .map(|s| rays.inside_other(o, &op.points[op.tris[s.triangles[0]][0]]))
                .collect()
        };
        let inside = [inside(0), inside(1)];
        return Some(match whole_operand([&inside[0], &inside[1]]) {
            Some(o) => Transversal::Operand(o),
            None => Transversal::Apart(inside),
        });
    }
    let mut seams = Seams {
        crossing: HashSet::with_capacity(2 * crossings.len()),
        ..Seams::default()
    };
    for [e0, e1] in touching {
        seams.corner(e0[0], e0[1]);
        seams.corner(e1[0], e1[1]);
        if e0 != e1 {
            seams.shared.extend([key(e0[0], e1[0]), key(e0[1], e1[1])]);
        }
    }
    let mut sites = Sites::new(corners.len(), tris.len(), 2 * crossings.len());
    let mut cuts: Vec<Vec<(usize, usize)>> = vec![Vec::new(); tris.len()];
    for (t, s, ends) in crossings {
        let [(pt, ps), (qt, qs)] = ends.map(|end| {
            match end {
                End::Corner(x, y) => seams.corner(x, y),
                End::Vertex(v, _) => {
                    seams.on_other.insert(v);
                }
                _ => {}
            }
            sites.at(end)
        });
        if pt != qt {
            cuts[t].push((pt, qt));
            cuts[s].push((ps, qs));
            seams.crossing.extend([key(pt, qt), key(ps, qs)]);
        }
    }
    let Sites {
        made,
        on_edge,
        extra,
        ..
    } = sites;
    let (on_edge, extra) = (&on_edge, &extra);
    // The corners' exact values are made where a triangle that is cut or kept uses them (a
    // meet keeps a part of each operand); the others stay zero and unused.
    let mut points = Vec::with_capacity(corners.len() + made.len());
    points.resize(corners.len(), Point3::int(0, 0, 0));
    points.extend(map_all(&made, parallel, |&(edge, tri)| {
        p.pierce(edge, tris[tri])
    }));
    // Every triangle with points on it, re-triangulated: the pierce points of its edges lie
    // inside those sides, the others inside it.
    let no_points = Vec::new();
    let sides = |t: usize| {
        let tri = tris[t];
        [0, 1, 2].map(|k| {
            on_edge
                .get(&key(tri[k], tri[(k + 1) % 3]))
                .unwrap_or(&no_points)
                .as_slice()
        })
    };
    // A side has points only if both its ends are ends of an edge with points: most
    // triangles have no such corner, and skip the lookups.
    let mut ends = vec![false; points.len()];
    for &(a, b) in on_edge.keys() {
        (ends[a], ends[b]) = (true, true);
    }
    let has_points = |t: usize| {
        let on_sides = || sides(t).iter().any(|side| !side.is_empty());
        !extra[t].is_empty() || tris[t].iter().filter(|&&v| ends[v]).count() >= 2 && on_sides()
    };
    let cut: Vec<usize> = (0..tris.len()).filter(|&t| has_points(t)).collect();
    let mut exact = vec![false; corners.len()];
    let mut make_exact = |points: &mut [Point3<Rational>],
                          used: &mut dyn Iterator<Item = usize>| {
        for v in used.filter(|&v| v < corners.len()) {
            if !exact[v] {
                (points[v], exact[v]) = (exact_point(corners[v]), true);
            }
        }
    };
    for &t in &cut {
        // A cut triangle's corners and the other operand's corners inside it: the points on
        // its sides are all constructed, and its cuts end at these or at constructed points.
        let mut used = tris[t].into_iter().chain(extra[t].iter().copied());
        make_exact(&mut points, &mut used);
    }
    let parts: Vec<Vec<[usize; 3]>> = map_all(&cut, parallel, |&t| {
        let chart = p.chart(tris[t])?;
        let extra = extra[t].iter().copied();
        retriangulate(&points, tris[t], chart, sides(t), extra, &cuts[t], &()).ok()
    })
    .into_iter()
    .collect::<Option<_>>()?;
    let mut parts: HashMap<usize, Vec<[usize; 3]>> = cut.into_iter().zip(parts).collect();
    let mut pieces: Vec<([usize; 3], usize)> = Vec::with_capacity(tris.len());
    let mut whole: Vec<Option<usize>> = vec![None; tris.len()];
    for (t, &tri) in tris.iter().enumerate() {
        match parts.remove(&t) {
            Some(part) => pieces.extend(part.into_iter().map(|piece| (piece, t))),
            None => {
                whole[t] = Some(pieces.len());
                pieces.push((tri, t));
            }
        }
    }
    let inside = inside(&pieces, &whole, &seams, &rays)?;
    let rename = |v: usize| *seams.same.get(&v).unwrap_or(&v);
    let kept: Vec<[usize; 3]> = kept(&pieces, &inside)
        .into_iter()
        .map(|t| t.map(rename))
        .collect();
    make_exact(&mut points, &mut kept.iter().flatten().copied());
    Some(Transversal::Crossing((points, kept)))
}

/// The triangles of each operand (0 below `first_b`, 1 from it) whose boxes meet the box of
/// the other operand's triangles that can still meet them, narrowed in three turns (operand
/// 0, 1, 0): only these can meet a triangle of the other operand.
fn near(boxes: &[AABB<[f64; 3]>], first_b: usize) -> (Vec<usize>, Vec<usize>) {
    let hull = |of: &[usize]| {
        of.iter()
            .fold(AABB::new_empty(), |h, &t| h.merged(&boxes[t]))
    };
    let mut near: [Vec<usize>; 2] = [(0..first_b).collect(), (first_b..boxes.len()).collect()];
    for o in [0, 1, 0] {
        let other = hull(&near[1 - o]);
        near[o].retain(|&t| boxes[t].intersects(&other));
    }
    let [a, b] = near;
    (a, b)
}

/// The operand whose parts (glued surfaces or patches, by operand) all lie inside the other,
/// none of the other's inside it: the meet is that operand as it is.
fn whole_operand(inside: [&[bool]; 2]) -> Option<usize> {
    let (all, none) = (
        |v: &[bool]| !v.contains(&false),
        |v: &[bool]| !v.contains(&true),
    );
    (0..2).find(|&o| all(inside[o]) && none(inside[1 - o]))
}

/// The pieces that lie inside the other operand.
fn kept(pieces: &[([usize; 3], usize)], inside: &[bool]) -> Vec<[usize; 3]> {
    pieces
        .iter()
        .zip(inside)
        .filter(|(_, &inside)| inside)
        .map(|((piece, _), _)| *piece)
        .collect()
}

/// The meet of boundaries that touch only in shared corners and edges (module docs), from
/// the pairs of equal corners of the touching contacts (global indices, operand 0's first):
/// each operand's triangles joined across its own edges that do not touch (its glued surfaces
/// where none touches), each patch inside the other operand or not by a ray from one of its
/// corners that does not touch. `None` if a patch has no such corner.
fn touching_meet<N: Num>(touching: &[[[usize; 2]; 2]], rays: &Rays<N>) -> Option<Transversal> {
    let ops = rays.ops;
    let na = ops[0].points.len();
    // Touching corners (flags by vertex) and edges of each operand, in its own numbering.
    let mut corners = ops.map(|op| vec![false; op.points.len()]);
    let mut edges: [HashSet<(usize, usize)>; 2] = Default::default();
    for &[e0, e1] in touching {
        for o in 0..2 {
            let (x, y) = (e0[o] - o * na, e1[o] - o * na);
            (corners[o][x], corners[o][y]) = (true, true);
            if x != y {
                edges[o].insert(key(x, y));
            }
        }
    }
    let inside = [0, 1].map(|o| {
        let op = ops[o];
        if edges[o].is_empty() {
            // Each glued surface is joined across its edges, none of which touches: one
            // patch, one ray.
            let mut side = vec![false; op.tris.len()];
            for s in &op.surfaces {
                let mut corners_of = s.triangles.iter().flat_map(|&t| op.tris[t]);
                let v = corners_of.find(|&v| !corners[o][v])?;
                let inside = rays.inside_other(o, &op.points[v]);
                s.triangles.iter().for_each(|&t| side[t] = inside);
            }
            return Some(side);
        }
        let mut uf = UnionFind::new(op.tris.len());
        for (e, fins) in op.table.edges.iter().zip(op.table.fin_lists()) {
            let touches = corners[o][e.0] && corners[o][e.1] && edges[o].contains(e);
            if !touches {
                for f in &fins[1..] {
                    uf.union(fins[0].tri, f.tri);
                }
            }
        }
        let mut side: Vec<Option<bool>> = vec![None; op.tris.len()];
        for (t, tri) in op.tris.iter().enumerate() {
            let root = uf.find(t);
            if side[root].is_none() {
                if let Some(&v) = tri.iter().find(|&&v| !corners[o][v]) {
                    side[root] = Some(rays.inside_other(o, &op.points[v]));
                }
            }
        }
        (0..op.tris.len())
            .map(|t| side[uf.find(t)])
            .collect::<Option<Vec<bool>>>()
    });
    let [Some(in_b), Some(in_a)] = inside else {
        return None;
    };
    if let Some(o) = whole_operand([&in_b, &in_a]) {
        return Some(Transversal::Operand(o));
    }
    if !in_b.contains(&true) && !in_a.contains(&true) {
        return Some(Transversal::Crossing(Complex::default()));
    }
    // Operand 1's touching corners become operand 0's equal ones: no point occurs twice.
    let same: HashMap<usize, usize> = touching.iter().flatten().map(|&[x, y]| (y, x)).collect();
    let rename = |v: usize| *same.get(&(v + na)).unwrap_or(&(v + na));
    let mut tris: Vec<[usize; 3]> = (0..ops[0].tris.len())
        .filter(|&t| in_b[t])
        .map(|t| ops[0].tris[t])
        .collect();
    tris.extend(
        (0..ops[1].tris.len())
            .filter(|&t| in_a[t])
            .map(|t| ops[1].tris[t].map(rename)),
    );
    Some(Transversal::Crossing(exact_complex(ops, tris)))
}

/// The triangles `tris` over operand 0's points then operand 1's, on the points they use,
/// made exact.
fn exact_complex<N: Num>(ops: [&Brep<N>; 2], tris: Vec<[usize; 3]>) -> Complex {
    let all: Vec<Point3<N>> = ops[0]
        .points
        .iter()
        .chain(&ops[1].points)
        .cloned()
        .collect();
    let (points, tris) = compact(all, tris);
    (exact_points(&points), tris)
}

/// The fins `(edge, piece)` grouped by edge, as `(start, grouped)`: for each vertex u, the
/// pairs (v, piece) of the fins at the edges (u, v), u < v, sorted, at
/// `grouped[start[u]..start[u + 1]]` — a counting sort by u, then a sort of each vertex's few.
fn fins_by_vertex(fins: &[((usize, usize), usize)]) -> (Vec<usize>, Vec<(usize, usize)>) {
    let vertices = fins.iter().map(|((_, v), _)| v + 1).max().unwrap_or(0);
    let mut start = vec![0usize; vertices + 1];
    for ((u, _), _) in fins {
        start[u + 1] += 1;
    }
    for u in 0..vertices {
        start[u + 1] += start[u];
    }
    let mut next = start.clone();
    let mut grouped = vec![(0, 0); fins.len()];
    for &((u, v), i) in fins {
        grouped[next[u]] = (v, i);
        next[u] += 1;
    }
    for u in 0..vertices {
        grouped[start[u]..start[u + 1]].sort_unstable();
    }
    (start, grouped)
}

/// For each piece of the transversal arrangement of `ops` (each with its parent: operand 0's
/// triangles first, then operand 1's; over operand 0's points, operand 1's, then the pierce
/// points), true if it lies inside the other operand: patches joined across edges that are
/// neither crossing segments nor shared edges ([`Seams`]), one ray from an input vertex off the
/// other boundary (not a shared corner) per connected surface, the side flipped across every
/// crossing segment. `whole[t]` is the piece that is the triangle `t` where `t` was not cut:
/// an edge with no cut triangle is joined from the operand's fin table, the others from the
/// pieces' edges. `None` if the flips contradict each other or the rays, or a patch gets no
/// side.
fn inside<N: Num>(
    pieces: &[([usize; 3], usize)],
    whole: &[Option<usize>],
    seams: &Seams,
    rays: &Rays<N>,
) -> Option<Vec<bool>> {
    let ops = rays.ops;
    let (points_a, first_b) = (ops[0].points.len(), ops[0].tris.len());
    let inputs = points_a + ops[1].points.len();
    let operand = |i: usize| usize::from(pieces[i].1 >= first_b);
    let mut uf = UnionFind::new(pieces.len());
    // The fins at edges of cut triangles: the pieces' own, and the uncut triangles' there.
    let mut loose: Vec<((usize, usize), usize)> = Vec::new();
    for (o, op) in ops.iter().enumerate() {
        for (&(a, b), fins) in op.table.edges.iter().zip(op.table.fin_lists()) {
            let edge = (a + o * points_a, b + o * points_a);
            let piece = |f: &Fin| whole[f.tri + o * first_b];
            if fins.iter().any(|f| piece(f).is_none()) {
                loose.extend(fins.iter().filter_map(piece).map(|p| (edge, p)));
            } else if !seams.shared.contains(&edge) {
                let first = piece(&fins[0]).expect("an uncut triangle");
                for f in &fins[1..] {
                    uf.union(first, piece(f).expect("an uncut triangle"));
                }
            }
        }
    }
    for (i, (t, parent)) in pieces.iter().enumerate() {
        if whole[*parent].is_none() {
            loose.extend((0..3).map(|k| (key(t[k], t[(k + 1) % 3]), i)));
        }
    }
    let (start, fins) = fins_by_vertex(&loose);
    drop(loose);
    let mut flips: Vec<(usize, usize)> = Vec::new();
    let at_edges = (0..start.len() - 1).flat_map(|u| {
        let fins = &fins[start[u]..start[u + 1]];
        fins.chunk_by(|x, y| x.0 == y.0)
            .map(move |at| ((u, at[0].0), at))
    });
    for (edge, at) in at_edges {
        if seams.shared.contains(&edge) {
            continue;
        }
        let across = seams.crossing.contains(&edge);
        for o in 0..2 {
            let mut mine = at.iter().map(|&(_, i)| i).filter(|&i| operand(i) == o);
            let Some(first) = mine.next() else {
                continue;
            };
            if across {
                // A crossing segment runs inside one triangle: one piece on each side.
                let (Some(second), None) = (mine.next(), mine.next()) else {
                    return None;
                };
                flips.push((first, second));
            } else {
                for w in mine {
                    uf.union(first, w);
                }
            }
        }
    }
    // The flips between patches, each both ways, sorted: a patch's are one run.
    let mut next: Vec<(usize, usize)> = Vec::with_capacity(2 * flips.len());
    for (x, y) in flips {
        let (x, y) = (uf.find(x), uf.find(y));
        next.extend([(x, y), (y, x)]);
    }
    next.sort_unstable();
    let across = |x: usize| {
        let from = next.partition_point(|&(p, _)| p < x);
        next[from..]
            .iter()
            .take_while(move |&&(p, _)| p == x)
            .map(|&(_, y)| y)
    };
    let mut side: Vec<Option<bool>> = vec![None; pieces.len()];
    for (i, (piece, _)) in pieces.iter().enumerate() {
        let root = uf.find(i);
        if side[root].is_some() {
            continue;
        }
        let o = operand(i);
        // An input vertex of the piece's own operand, off the other's boundary.
        let own = [0..points_a, points_a..inputs];
        let Some(&v) = piece
            .iter()
            .find(|&&v| own[o].contains(&v) && !seams.on_other.contains(&v))
        else {
            continue;
        };
        let q = &ops[o].points[v - own[o].start];
        side[root] = Some(rays.inside_other(o, q));
        let mut stack = vec![root];
        while let Some(x) = stack.pop() {
            let flipped = side[x].map(|s| !s);
            for y in across(x) {
                match side[y] {
                    None => {
                        side[y] = flipped;
                        stack.push(y);
                    }
                    s if s != flipped => return None,
                    _ => {}
                }
            }
        }
    }
    (0..pieces.len()).map(|i| side[uf.find(i)]).collect()
}

/// Rays from points of one operand to the other ([`winding`]): the first few scan every
/// triangle's box, later ones an R-tree of the other's boxes, built on first need.
struct Rays<'a, N: Num> {
    ops: [&'a Brep<N>; 2],
    /// The triangles' `f64` boxes, operand 0's first, each holding its triangle.
    boxes: &'a [AABB<[f64; 3]>],
    trees: [OnceCell<TriBoxes>; 2],
    cast: Cell<usize>,
}

impl<'a, N: Num> Rays<'a, N> {
    fn new(ops: [&'a Brep<N>; 2], boxes: &'a [AABB<[f64; 3]>]) -> Self {
        Rays {
            ops,
            boxes,
            trees: Default::default(),
            cast: Cell::new(0),
        }
    }

    /// True if `q`, a point of operand `o` off the other's boundary, lies inside the other.
    fn inside_other(&self, o: usize, q: &Point3<N>) -> bool {
        let other = self.ops[1 - o];
        self.cast.set(self.cast.get() + 1);
        let w = if self.cast.get() <= SCANNED_RAYS {
            // Only triangles whose box meets the ray can count ([`ray_box`]).
            let boxes = &self.boxes[(1 - o) * self.ops[0].tris.len()..];
            let ray = ray_box(q);
            let near = (0..other.tris.len()).filter(|&s| boxes[s].intersects(&ray));
            winding(near.map(|s| other.corners(s)), q, &N::exact_ctx())
        } else {
            let tree = self.trees[1 - o].get_or_init(|| {
                TriBoxes::new((0..other.tris.len()).map(|s| (s, other.corners(s))))
            });
            winding(
                tree.along_x(q).map(|s| other.corners(s)),
                q,
                &N::exact_ctx(),
            )
        };
        w + i64::from(!other.bounded) == 1
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::num::Float;
    use crate::yin3::bvh::tests::a_box;
    use crate::yin3::meet::constructed_meet;
    use crate::yin3::set::compact;
    use crate::yin3::shapes::{concat, cuboid, Mesh};
    use crate::yin3::{Yin3Error, YinSet3};
    use proptest::prelude::*;
    use std::cmp::Ordering;

    /// Vertices and triangles.
    type Raw = (Vec<[f64; 3]>, Vec<Vec<usize>>);

    /// The cube [o, o + s]³ with corner i moved by s · `jitter[i]`, each quad split into two
    /// triangles (a jitter below 1/10 keeps it a simple closed surface).
    fn jittered_cube(o: [f64; 3], s: f64, jitter: &[[f64; 3]]) -> Raw {
        let corners = (0..8)
            .map(|i| [0, 1, 2].map(|k| o[k] + s * (f64::from(i >> k & 1) + jitter[i as usize][k])))
            .collect();
        // The unit cube's quads, with cuboid's corner numbering (bit k of i: coordinate k).
        let unit = |v: i64| Point3::new(Float::from_i64(v), Float::from_i64(v), Float::from_i64(v));
        let (_, quads) = cuboid(&unit(0), &unit(1));
        let tris = quads
            .iter()
            .flat_map(|q| [vec![q[0], q[1], q[2]], vec![q[0], q[2], q[3]]])
            .collect();
        (corners, tris)
    }

    /// Two raw meshes as one.
    fn both((mut v, mut f): Raw, (w, g): Raw) -> Raw {
        let n = v.len();
        v.extend(w);
        f.extend(
            g.into_iter()
                .map(|t| t.into_iter().map(|i| i + n).collect()),
        );
        (v, f)
    }

    /// The set bounded by a raw mesh, its coordinates read in backend `N`.
    fn solid<N: Num>((v, f): &Raw) -> YinSet3<N> {
        let c = |x: f64| N::from_f64(x).expect("finite");
        let pts = v
            .iter()
            .map(|p| Point3::new(c(p[0]), c(p[1]), c(p[2])))
            .collect();
        YinSet3::from_triangles(pts, f.clone()).expect("a valid mesh")
    }

    /// The cube [lo, hi]³.
    fn cube<N: Num>(lo: f64, hi: f64) -> Mesh<N> {
        let corner = |v: f64| {
            let v = N::from_f64(v).expect("finite");
            Point3::new(v.clone(), v.clone(), v)
        };
        cuboid(&corner(lo), &corner(hi))
    }

    /// The transversal meet of two float sets as an exact set, `None` where it declines.
    fn transversal(a: &YinSet3<Float>, b: &YinSet3<Float>) -> Option<YinSet3<Rational>> {
        let (x, y) = (a.brep()?, b.brep()?);
        let (points, kept) = transversal_meet(x, y)?.complex(x, y);
        if kept.is_empty() {
            return Some(YinSet3::empty());
        }
        let (points, kept) = compact(points, kept);
        Some(YinSet3::from_brep(
            Brep::assemble(points, kept).expect("a valid meet"),
            (),
        ))
    }

    fn jitter() -> impl Strategy<Value = Vec<[f64; 3]>> {
        prop::collection::vec([-0.1..0.1, -0.1..0.1, -0.1..0.1], 8)
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(yinset_testkit::cases(256)))]

        /// The broad phase finds every pair of boxes that meet: the near triangles of each
        /// side include every one whose box meets a box of the other side (boxes that touch
        /// in a face or corner included: sides may be 0).
        #[test]
        fn the_broad_phase_finds_every_meeting_pair(
            boxes in prop::collection::vec(
                ([0.0..8.0, 0.0..8.0, 0.0..8.0f64], [0.0..3.0, 0.0..3.0, 0.0..3.0f64]), 2..40),
            split in 1usize..39,
        ) {
            let boxes: Vec<AABB<[f64; 3]>> = boxes
                .into_iter()
                .map(|(c, s)| a_box(c.map(f64::floor), s.map(f64::floor)))
                .collect();
            let first_b = split.min(boxes.len() - 1);
            let (near_a, near_b) = near(&boxes, first_b);
            let meets = |t: usize, s: usize| boxes[t].intersects(&boxes[s]);
            let hull = |of: std::ops::Range<usize>| {
                of.fold(AABB::new_empty(), |h, t| h.merged(&boxes[t]))
            };
            let (hull_a, hull_b) = (hull(0..first_b), hull(first_b..boxes.len()));
            prop_assert!(near_a.iter().all(|&t| boxes[t].intersects(&hull_b)));
            prop_assert!(near_b.iter().all(|&s| boxes[s].intersects(&hull_a)));
            for t in 0..first_b {
                for s in first_b..boxes.len() {
                    if meets(t, s) {
                        prop_assert!(near_a.contains(&t) && near_b.contains(&s));
                    }
                }
            }
        }
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(yinset_testkit::cases(64)))]

        /// Jittered cubes that cross, nest or miss (the second operand also as its complement,
        /// unbounded, the first also with a second cube far away, and both scaled by 2^80):
        /// the transversal meet is taken and equals the general exact meet (a different
        /// algorithm: constructed contacts, point-in-triangle distribution, one ray per patch).
        #[test]
        fn equals_the_constructed_meet(
            ja in jitter(), jb in jitter(), jc in jitter(),
            offset in [-1.2..1.2, -1.2..1.2, -1.2..1.2f64], size in 0.3..1.6f64,
        ) {
            // Corner 0 of the first cube at the origin: coordinates 0 occur.
            let mut ja = ja;
            ja[0] = [0.0; 3];
            let a = jittered_cube([0.0; 3], 1.0, &ja);
            let b = jittered_cube(offset, size, &jb);
            let far = both(a.clone(), jittered_cube([5.0, 0.0, 0.0], 1.0, &jc));
            // Coordinates of 2^80 and more: integers already, in the pierce points' arithmetic.
            let huge = |(v, f): &Raw| (v.iter().map(|p| p.map(|x| x * 2f64.powi(80))).collect(), f.clone());
            let (ha, hb) = (huge(&a), huge(&b));
            for (a, b, complement) in [(&a, &b, false), (&a, &b, true), (&far, &b, false), (&ha, &hb, false)] {
                let (fa, mut fb) = (solid::<Float>(a), solid::<Float>(b));
                let (ea, mut eb) = (solid::<Rational>(a), solid::<Rational>(b));
                if complement {
                    (fb, eb) = (fb.complement(), eb.complement());
                }
                let fast = transversal(&fa, &fb);
                prop_assert!(fast.is_some(), "declined a generic pair");
                let exact = constructed_meet(&ea, &eb);
                prop_assert_eq!(fast.unwrap(), exact.clone());
                if let Some(Transversal::Apart(_) | Transversal::Operand(_)) = transversal_meet(fa.brep().unwrap(), fb.brep().unwrap()) {
                    // Nothing is rounded where the boundaries are apart: the float meet is exact.
                    let float = fa.try_meet(&fb).expect("a float meet");
                    prop_assert_eq!(float.exact_values(), exact);
                }
            }
        }
    }

    /// Boundaries that do not meet — nested either way, disjoint, and with complements (glued
    /// surfaces of both operands kept) — take the apart path, and the float meet is the exact
    /// meet of the values, unrounded.
    #[test]
    fn apart_boundaries_meet_exactly() {
        let still = [[0.0; 3]; 8];
        let big = jittered_cube([0.0; 3], 4.0, &still);
        let small = jittered_cube([1.0; 3], 1.0, &still);
        let far = jittered_cube([9.0; 3], 1.0, &still);
        for (x, y) in [(&big, &small), (&small, &big), (&small, &far), (&big, &far)] {
            let (fx, fy) = (solid::<Float>(x), solid::<Float>(y));
            let (ex, ey) = (solid::<Rational>(x), solid::<Rational>(y));
            for (fa, fb, ea, eb) in [
                (fx.clone(), fy.clone(), ex.clone(), ey.clone()),
                (fx.clone(), fy.complement(), ex.clone(), ey.complement()),
                (
                    fx.complement(),
                    fy.complement(),
                    ex.complement(),
                    ey.complement(),
                ),
            ] {
                let meet = transversal_meet(fa.brep().unwrap(), fb.brep().unwrap());
                assert!(matches!(
                    meet,
                    Some(Transversal::Apart(_) | Transversal::Operand(_))
                ));
                let float = fa.try_meet(&fb).expect("a float meet");
                assert_eq!(float.exact_values(), constructed_meet(&ea, &eb));
            }
        }
    }

    /// Overlapping coplanar faces, a shared face, a vertex on an edge (the top face's diagonal)
    /// and a face that crosses the other from a shared corner along one of its edges are
    /// declined.
    #[test]
    fn declines_degenerate_pairs() {
        let still = [[0.0; 3]; 8];
        let a = solid::<Float>(&jittered_cube([0.0; 3], 1.0, &still));
        let mut down = still;
        down[0] = [0.0, 0.0, -0.2];
        for (o, jitter) in [
            ([0.5, 0.5, 0.0], still),
            ([1.0, 0.0, 0.0], still),
            ([0.3, 0.3, 1.2], down),
        ] {
            let b = solid::<Float>(&jittered_cube(o, 1.0, &jitter));
            assert!(transversal(&a, &b).is_none(), "offset {o:?}");
        }
        // A tetrahedron at the cube's corner (1, 1, 1) with a face in the plane y = z, which
        // enters the cube there along the cube's edge to (0, 1, 1).
        let (v, f) = (
            vec![[1.0; 3], [0.5, 1.2, 1.2], [2.0, 0.5, 0.5], [1.5, 1.5, 2.0]],
            vec![vec![0, 1, 2], vec![0, 3, 1], vec![0, 2, 3], vec![1, 3, 2]],
        );
        let tet = solid::<Float>(&(v, f));
        assert!(transversal(&a, &tet).is_none());
    }

    /// A jitter that moves corners only into corner 0's octant (each coordinate by 1/32 or a
    /// value in (0, 1/10), and by 0 too where `zero`), and corners `fixed` not at all.
    fn outward(fixed: &'static [usize], zero: bool) -> impl Strategy<Value = Vec<[f64; 3]>> {
        let off = prop_oneof![Just(1.0 / 32.0), 0.001..0.1];
        let step = match zero {
            true => prop_oneof![Just(0.0), off].boxed(),
            false => off.boxed(),
        };
        prop::collection::vec([step.clone(), step.clone(), step], 8).prop_map(move |mut j| {
            for &k in fixed {
                j[k] = [0.0; 3];
            }
            j
        })
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(yinset_testkit::cases(64)))]

        /// Cubes that touch the unit cube in a shared corner from outside or from inside, or
        /// in a shared edge from outside (outside, where a jitter is 0: faces coplanar at the
        /// touching corner or edge, and vertices on the unit cube's planes off its faces), each
        /// operand also as its complement: the touching meet is taken and equals the general
        /// exact meet, and so does the float meet, unrounded.
        #[test]
        fn touching_boundaries_meet_as_the_constructed_meet(
            corner in outward(&[0], true), inner in outward(&[0], false),
            edge in outward(&[0, 4], true),
            size in 0.25..0.75f64,
        ) {
            let unit = jittered_cube([0.0; 3], 1.0, &[[0.0; 3]; 8]);
            // Corner 0 of the second cube at the unit cube's corner (1, 1, 1), at its corner
            // (0, 0, 0) from inside, and its edge from corner 0 to corner 4 (along z) on the
            // unit cube's edge from (1, 1, 0) to (1, 1, 1), its bottom and top in the unit
            // cube's (a side straddling the top's plane with a corner on it, apart from the
            // top, is beyond the contact test: the general meet's case).
            let flat: Vec<[f64; 3]> = edge.iter().map(|j| [j[0], j[1], 0.0]).collect();
            let others = [
                jittered_cube([1.0; 3], size, &corner),
                jittered_cube([0.0; 3], size, &inner),
                jittered_cube([1.0, 1.0, 0.0], 1.0, &flat),
            ];
            for other in &others {
                let (fa, fb) = (solid::<Float>(&unit), solid::<Float>(other));
                let (ea, eb) = (solid::<Rational>(&unit), solid::<Rational>(other));
                for (fa, fb, ea, eb) in [
                    (fa.clone(), fb.clone(), ea.clone(), eb.clone()),
                    (fa.clone(), fb.complement(), ea.clone(), eb.complement()),
                    (fa.complement(), fb.clone(), ea.complement(), eb.clone()),
                ] {
                    let fast = transversal(&fa, &fb);
                    prop_assert!(fast.is_some(), "declined a touching pair");
                    let exact = constructed_meet(&ea, &eb);
                    prop_assert_eq!(fast.unwrap(), exact.clone());
                    // No point is constructed, so nothing is rounded: the float meet is exact.
                    prop_assert_eq!(fa.try_meet(&fb).expect("a float meet").exact_values(), exact);
                }
            }
        }
    }

    /// The kinds of contact between the triangles of two float sets: crossing edges, crossing
    /// through shared corners, meeting in one point only, touching in a shared edge where
    /// other triangles cross, and a vertex inside the other's triangle.
    fn crossing_kinds(a: &YinSet3<Float>, b: &YinSet3<Float>) -> [bool; 5] {
        let (x, y) = (a.brep().unwrap(), b.brep().unwrap());
        let points: Vec<Point3<Float>> = x.points.iter().chain(&y.points).cloned().collect();
        let p = F64Corners(points.iter().map(|q| q.to_f64()).collect());
        let corners: Vec<&Point3<Float>> = points.iter().collect();
        let n = x.points.len();
        let tris: Vec<[usize; 3]> = (x.tris.iter().copied())
            .chain(y.tris.iter().map(|t| t.map(|v| v + n)))
            .collect();
        let planes: Vec<_> = tris.iter().map(|&t| p.plane(t)).collect();
        let (mut kinds, mut edge_touch, mut cross) = ([false; 5], false, false);
        for t in 0..x.tris.len() {
            for s in x.tris.len()..tris.len() {
                match contact(
                    &p,
                    [&planes[t], &planes[s]],
                    &corners,
                    (t, tris[t]),
                    (s, tris[s]),
                ) {
                    Contact::Cross(ends) => {
                        cross = true;
                        for end in ends {
                            kinds[0] |= matches!(end, End::Edges(..));
                            kinds[1] |= matches!(end, End::Corner(..));
                            kinds[4] |= matches!(end, End::Vertex(..));
                        }
                        kinds[2] |= ends[0] == ends[1];
                    }
                    Contact::Touch([e0, e1]) => edge_touch |= e0 != e1,
                    _ => {}
                }
            }
        }
        kinds[3] = edge_touch && cross;
        kinds
    }

    /// A tetrahedron with corners on the half-integer lattice in [−1, 3]³, outward, `None` if
    /// flat: half of them with a corner at one of `other`'s, half of those with an edge on one
    /// of `other`'s.
    fn lattice_tetrahedron(rng: &mut rand::rngs::StdRng, other: &Raw) -> Option<Raw> {
        use rand::RngExt;
        let mut v: Vec<[f64; 3]> = (0..4)
            .map(|_| [0; 3].map(|_| f64::from(rng.random_range(-2..7i32)) / 2.0))
            .collect();
        if rng.random_bool(0.5) {
            let face = &other.1[rng.random_range(0..other.1.len())];
            let k = rng.random_range(0..face.len());
            v[0] = other.0[face[k]];
            if rng.random_bool(0.5) {
                v[1] = other.0[face[(k + 1) % face.len()]];
            }
        }
        let d = |i: usize| [0, 1, 2].map(|k| v[i][k] - v[0][k]);
        let (x, y, z) = (d(1), d(2), d(3));
        let volume = x[0] * (y[1] * z[2] - y[2] * z[1]) - x[1] * (y[0] * z[2] - y[2] * z[0])
            + x[2] * (y[0] * z[1] - y[1] * z[0]);
        let f = match volume.partial_cmp(&0.0)? {
            Ordering::Greater => vec![vec![0, 2, 1], vec![0, 1, 3], vec![0, 3, 2], vec![1, 2, 3]],
            Ordering::Less => vec![vec![0, 1, 2], vec![0, 3, 1], vec![0, 2, 3], vec![1, 3, 2]],
            Ordering::Equal => return None,
        };
        Some((v, f))
    }

    /// Lattice tetrahedra ([`lattice_tetrahedron`]) against a cube on the lattice and against
    /// one another, also as their complements: their edges cross the cube's edges, face
    /// diagonals and each other, and they cross through shared corners and beside shared
    /// edges. Wherever the transversal meet is taken it equals the general exact meet, and the
    /// float meet (rounded) is valid with the exact meet's Betti numbers, or — in at most a
    /// tenth of the cases — unrepresentable; it is taken with crossing edges, through shared corners, with pairs meeting in one
    /// point and with shared edges beside crossings, each in many cases.
    #[test]
    fn lattice_solids_meet_as_the_constructed_meet() {
        use rand::{RngExt, SeedableRng};
        let mut rng = rand::rngs::StdRng::seed_from_u64(18);
        let cube = jittered_cube([0.0; 3], 2.0, &[[0.0; 3]; 8]);
        let (mut taken, mut rounded, mut meets) = ([0usize; 5], 0, 0);
        for _ in 0..3000 {
            let a = match rng.random_bool(0.5) {
                true => cube.clone(),
                false => match lattice_tetrahedron(&mut rng, &cube) {
                    Some(tetra) => tetra,
                    None => continue,
                },
            };
            let Some(b) = lattice_tetrahedron(&mut rng, &a) else {
                continue;
            };
            let (fa, ea) = (solid::<Float>(&a), solid::<Rational>(&a));
            let (fb, eb) = (solid::<Float>(&b), solid::<Rational>(&b));
            for (fb, eb) in [(fb.clone(), eb.clone()), (fb.complement(), eb.complement())] {
                let Some(fast) = transversal(&fa, &fb) else {
                    continue;
                };
                let exact = constructed_meet(&ea, &eb);
                assert_eq!(fast, exact, "{:?} ∧ {:?}", a.0, b.0);
                meets += 1;
                match fa.try_meet(&fb) {
                    Ok(float) => {
                        rounded += 1;
                        assert!(float.validate().is_ok(), "{:?} ∧ {:?}", a.0, b.0);
                        assert_eq!(float.betti(), exact.betti(), "{:?} ∧ {:?}", a.0, b.0);
                    }
                    Err(Yin3Error::Unrepresentable(_)) => {}
                    Err(e) => panic!("{:?} ∧ {:?}: {e}", a.0, b.0),
                }
                for (n, kind) in taken.iter_mut().zip(crossing_kinds(&fa, &fb)) {
                    *n += usize::from(kind);
                }
            }
        }
        assert!(taken.iter().all(|&n| n >= 50), "taken {taken:?}");
        assert!(
            rounded * 10 >= meets * 9,
            "{rounded} of {meets} float meets representable"
        );
    }

    /// ballmid and torus of ../shared/data/3d, on one lattice, cross in edges through edges and
    /// through shared corners: the transversal meet is taken and equals the general exact meet.
    #[test]
    fn ballmid_and_torus_meet_as_the_constructed_meet() {
        if !crate::io::testdata::available() {
            return;
        }
        let read = |name: &str| {
            let text = std::fs::read_to_string(crate::io::testdata::dir("3d").join(name));
            let mesh = crate::io::obj::read_obj::<Float>(&text.expect("readable")).unwrap();
            YinSet3::from_triangles(mesh.vertices, mesh.faces).expect("a valid mesh")
        };
        let (ball, torus) = (read("ballmid.obj"), read("torus.obj"));
        let kinds = crossing_kinds(&ball, &torus);
        assert!(
            kinds[0] && kinds[1],
            "crossing edges and corners: {kinds:?}"
        );
        let fast = transversal(&ball, &torus).expect("the transversal meet");
        assert_eq!(
            fast,
            constructed_meet(&ball.exact_values(), &torus.exact_values())
        );
    }

    /// Axis-aligned cubes sharing a corner (their faces at it coplanar) take the touching meet
    /// and meet in nothing; one of them also as its complement, and the meet is the other; a
    /// cube touching one of two others and holding the other meets them in that one.
    #[test]
    fn cubes_sharing_a_corner_touch() {
        let still = [[0.0; 3]; 8];
        let (a, b) = (
            solid::<Float>(&jittered_cube([0.0; 3], 1.0, &still)),
            solid::<Float>(&jittered_cube([1.0; 3], 1.0, &still)),
        );
        assert!(transversal(&a, &b).expect("touching").is_empty());
        let not_b = b.complement();
        assert!(matches!(
            transversal_meet(a.brep().unwrap(), not_b.brep().unwrap()),
            Some(Transversal::Operand(0))
        ));
        // Two cubes, one inside the unit cube, one at its corner (1, 1, 1) from outside: no
        // part of the unit cube's boundary is in them, one of them is in it, and the meet is
        // that one.
        let (v, f) = concat(vec![cube(0.25, 0.75), cube(1.0, 1.5)]);
        let both = YinSet3::<Float>::from_triangles(v, f).expect("two cubes");
        let (v, f) = cube(0.25, 0.75);
        let inner = YinSet3::<Rational>::from_triangles(v, f).expect("a cube");
        for meet in [transversal(&a, &both), transversal(&both, &a)] {
            assert_eq!(meet.expect("touching"), inner);
        }
    }

    /// The bipyramid over the square with corners (±1, 0, 0), (0, ±1, 0), apexes at heights
    /// `top` and −`bottom`, faces outward.
    fn bipyramid(top: f64, bottom: f64) -> Raw {
        let v = vec![
            [1.0, 0.0, 0.0],
            [0.0, 1.0, 0.0],
            [-1.0, 0.0, 0.0],
            [0.0, -1.0, 0.0],
            [0.0, 0.0, top],
            [0.0, 0.0, -bottom],
        ];
        let f = (0..4)
            .flat_map(|k| [vec![k, (k + 1) % 4, 4], vec![(k + 1) % 4, k, 5]])
            .collect();
        (v, f)
    }

    /// Bipyramids on one square whose surfaces cross along it (apexes 1 and −1 against 2 and
    /// −1/2): each surface is two patches on opposite sides of the other, and the touching meet
    /// keeps one of each, as the general meet does; with equal bottoms (coplanar faces on both
    /// sides of the square's edges, none shared) the touching meet declines.
    #[test]
    fn surfaces_crossing_along_shared_edges() {
        let (a, b) = (bipyramid(1.0, 1.0), bipyramid(2.0, 0.5));
        let (fa, fb) = (solid::<Float>(&a), solid::<Float>(&b));
        let meet = transversal_meet(fa.brep().unwrap(), fb.brep().unwrap());
        assert!(matches!(meet, Some(Transversal::Crossing(_))));
        let exact = constructed_meet(&solid::<Rational>(&a), &solid::<Rational>(&b));
        assert_eq!(transversal(&fa, &fb).unwrap(), exact);
        assert_eq!(fa.try_meet(&fb).unwrap().exact_values(), exact);
        let same_bottom = solid::<Float>(&bipyramid(2.0, 1.0));
        assert!(transversal(&fa, &same_bottom).is_none());
    }

    /// A tetrahedron sharing the unit cube's edge from (0, 0, 0) to (0, 0, 1), its dihedral
    /// wedge there straddling the cube's face y = 0 (one face of each inside the other,
    /// one outside), and crossing that face elsewhere: the transversal meet is taken and is the
    /// tetrahedron's part y ≥ 0.
    #[test]
    fn wedges_interleaved_at_a_shared_edge() {
        let cube = jittered_cube([0.0; 3], 1.0, &[[0.0; 3]; 8]);
        // Corner 2 inside the cube, corner 3 beyond y = 0, the edge between them through the
        // face y = 0 at q = (7/12, 0, 1/2).
        let tet = (
            vec![
                [0.0; 3],
                [0.0, 0.0, 1.0],
                [0.5, 0.25, 0.5],
                [0.75, -0.5, 0.5],
            ],
            vec![vec![0, 1, 2], vec![0, 3, 1], vec![0, 2, 3], vec![1, 3, 2]],
        );
        let (fa, fb) = (solid::<Float>(&cube), solid::<Float>(&tet));
        // The meet is the tetrahedron (0, 0, 0), (0, 0, 1), (1/2, 1/4, 1/2), q, of volume a
        // sixth of the triple product |(0, 0, 1) · ((1/2, 1/4, 1/2) × q)| = 7/48.
        let volume = Rational::from_i64(7) / Rational::from_i64(288);
        for (x, y) in [(&fa, &fb), (&fb, &fa)] {
            let meet = transversal(x, y).expect("the transversal meet");
            assert_eq!(meet.volume(), Some(volume.clone()));
        }
    }

    /// A tetrahedron touching two tetrahedra from outside, one along its edge uv, the other
    /// at its corner w: its face uvw has every corner touching but two edges that do not, so
    /// it is joined to the rest of its surface, whose corner off the others decides it. The
    /// touching meet is taken: empty with the two, the tetrahedron itself with their
    /// complement.
    #[test]
    fn a_face_with_every_corner_touching() {
        // Corners u, v, w, x; outward faces, the volume being positive.
        let faces = vec![vec![0, 2, 1], vec![0, 1, 3], vec![0, 3, 2], vec![1, 2, 3]];
        let a = (
            vec![[0.0; 3], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]],
            faces.clone(),
        );
        // Along uv, its other corners at y < 0, where the first has none (positive volume).
        let edge = (
            vec![
                [0.0; 3],
                [1.0, 0.0, 0.0],
                [0.5, -1.0, 0.5],
                [0.5, -0.5, -1.0],
            ],
            faces,
        );
        // At w, its other corners at y > 1, where the first has none (negative volume).
        let corner = (
            vec![
                [0.0, 1.0, 0.0],
                [0.5, 2.0, 0.25],
                [-0.5, 2.0, 0.5],
                [0.125, 1.5, -0.5],
            ],
            vec![vec![0, 1, 2], vec![0, 3, 1], vec![0, 2, 3], vec![1, 3, 2]],
        );
        let b = both(edge, corner);
        let (fa, fb) = (solid::<Float>(&a), solid::<Float>(&b));
        for (x, y) in [(&fa, &fb), (&fb, &fa)] {
            assert!(transversal(x, y).expect("touching").is_empty());
        }
        let not_b = fb.complement();
        for (x, y) in [(&fa, &not_b), (&not_b, &fa)] {
            assert_eq!(transversal(x, y).expect("touching"), solid::<Rational>(&a));
        }
    }
}
