//! Exact constrained triangulation of one triangle with extra points and constraint segments:
//! the re-triangulation of a cut face (seed 004 step 2; yin3 docs: *Re-triangulation*).
//!
//! Points the caller knows to lie on a side split it first, in their order along it; the others
//! are inserted one by one, each located by descending the history of splits; then every
//! constraint, split at the points on it, is made an edge by removing the triangles its open
//! segment crosses and ear-clipping the two pseudo-polygons on its sides. Every decision is an
//! [`orient`] or the exact order of points or coordinates: no Delaunay test, no floats, no ε
//! of our own. Constraints along a side (a coplanar overlap's outline often runs along the cut
//! triangle's own sides) are edges of every triangulation and are set aside first. Two fast
//! paths come next: a single cut between sides (no predicate at all), and cuts that bound
//! faces with the triangle's sides (chains across it, branching outlines), each face traced by
//! turning at every point and ear-clipped.

use crate::kernel::{cmp_clockwise_from, on_closed_segment, orient, Point};
use crate::num::{Interval, Num};
use foldhash::{HashMap, HashMapExt};
use smallvec::{smallvec, SmallVec};
use std::cmp::Ordering::{Equal, Greater, Less};
use std::collections::hash_map::Entry;

/// A cut triangle's few points or indices, on the stack unless there are many.
type Small<T> = SmallVec<[T; 16]>;

/// Why a triangle could not be re-triangulated (a caller's broken promise).
#[derive(Debug, Clone, PartialEq, Eq)]
pub(crate) enum TriangulateError {
    /// Constraints `a` and `b` (indices into the `constraints` slice) cross at a point that is not one of the points.
    CrossingConstraints(usize, usize),
    /// Point `p` lies outside the triangle.
    PointOutside(usize),
    /// The predicates contradicted each other (float mode's ε-predicates are not transitive):
    /// the step that found it.
    Inconsistent(&'static str),
}

/// Triangulate the triangle `corners` (indices into `points`, counterclockwise) using every
/// point of `points` as a vertex, so that every constraint is a union of edges.
///
/// The points must be pairwise distinct and the constraints pairs of distinct points.
/// `sides[k]` lists points the caller knows to lie inside side k (from corner k to corner
/// k + 1): they are ordered along it and split it without a predicate; other points are
/// located by orientations, whether on a side or not. The
/// result is a list of counterclockwise triangles that tile the triangle conformingly: no point
/// lies inside a triangle or inside an edge, and each piece of a constraint between consecutive
/// points on it is an edge. Constraints may overlap, run along the sides or pass through
/// points; two that cross elsewhere are [`TriangulateError::CrossingConstraints`] (reported as
/// `(smaller, larger)` index).
pub(crate) fn triangulate<N: Num>(
    points: &[Point<N>],
    corners: [usize; 3],
    sides: [&[usize]; 3],
    constraints: &[(usize, usize)],
    ctx: &N::Ctx,
) -> Result<Vec<[usize; 3]>, TriangulateError> {
    let (constraints, numbering) = cuts_through(points.len(), corners, sides, constraints);
    let constraints = &constraints[..];
    if let Some(pieces) = one_cut(points.len(), corners, sides, constraints) {
        return Ok(pieces);
    }
    if let Some(pieces) = by_faces(points, corners, sides, constraints, ctx) {
        return Ok(pieces);
    }
    let mut mesh = Mesh::new(points, corners, ctx)?;
    let mut placed = vec![false; points.len()];
    for (k, side) in sides.iter().enumerate() {
        mesh.split_side(corners[k], corners[(k + 1) % 3], side)?;
        for &p in *side {
            placed[p] = true;
        }
    }
    let mut order: Vec<usize> = (0..points.len())
        .filter(|&p| !corners.contains(&p) && !placed[p])
        .collect();
    // Golden-ratio scrambled order: the history of splits stays shallow for sorted input.
    order.sort_by_key(|&p| (p as u64).wrapping_mul(0x9E37_79B9_7F4A_7C15));
    for p in order {
        mesh.insert(p)?;
    }
    let mut owner = HashMap::new();
    let mut pieces = Vec::new();
    let (near, by_axis) = enclosed(points);
    for (c, &(u, v)) in constraints.iter().enumerate() {
        for (a, b) in split(points, &near, by_axis.as_ref(), u, v, ctx) {
            if let Entry::Vacant(e) = owner.entry(key(a, b)) {
                e.insert(c);
                pieces.push((a, b, c));
            }
        }
    }
    for (u, v, c) in pieces {
        mesh.recover(u, v, c, &owner).map_err(|e| match e {
            TriangulateError::CrossingConstraints(a, b) => {
                let [a, b] = [a, b].map(|k| numbering[k]);
                TriangulateError::CrossingConstraints(a.min(b), a.max(b))
            }
            e => e,
        })?;
    }
    Ok(mesh.triangles())
}

/// The constraints among `count` points that may cut the triangle, each once, with each one's
/// index in `constraints`: a constraint with both ends on one side (its corners and the points
/// `sides` declares inside it) is a union of edges of every triangulation of the triangle,
/// and one that repeats an earlier one (either way round) or is a single point adds nothing.
fn cuts_through(
    count: usize,
    corners: [usize; 3],
    sides: [&[usize]; 3],
    constraints: &[(usize, usize)],
) -> (Small<(usize, usize)>, Small<usize>) {
    // Bit k for each point on side k.
    let mut on: Small<u8> = smallvec![0; count];
    for k in 0..3 {
        on[corners[k]] |= 1 << k;
        on[corners[(k + 1) % 3]] |= 1 << k;
        for &p in sides[k] {
            on[p] |= 1 << k;
        }
    }
    // The first index of each constraint, smaller end first: the ones kept.
    let mut first: Small<((usize, usize), usize)> = (constraints.iter().enumerate())
        .filter(|&(_, &(u, v))| u != v && on[u] & on[v] == 0)
        .map(|(c, &(u, v))| (key(u, v), c))
        .collect();
    first.sort_unstable();
    first.dedup_by_key(|(e, _)| *e);
    let mut numbering: Small<usize> = first.iter().map(|&(_, c)| c).collect();
    numbering.sort_unstable();
    let cuts = numbering.iter().map(|&c| constraints[c]).collect();
    (cuts, numbering)
}

/// The pieces, without a predicate, where one constraint is the only cut (most triangles a
/// transversal meet cuts): between points inside two sides, the only points besides the
/// corners, it cuts off the corner between them from a convex quadrilateral (split at the
/// corner before); between a point inside a side, the only other point, and the opposite
/// corner, the triangle is halved at the point. `None` for anything else. (The corners must be
/// counterclockwise, as [`triangulate`] requires; this path does not check it, the general one
/// does.)
fn one_cut(
    count: usize,
    corners: [usize; 3],
    sides: [&[usize]; 3],
    constraints: &[(usize, usize)],
) -> Option<Vec<[usize; 3]>> {
    let &[(u, v)] = constraints else {
        return None;
    };
    let side = |p: usize| (0..3).find(|&k| sides[k] == [p]);
    let corner = |p: usize| corners.iter().position(|&c| c == p);
    // The corners from corner k on, counterclockwise.
    let from = |k: usize| [0, 1, 2].map(|m| corners[(k + m) % 3]);
    match count {
        5 => {
            let (i, j) = (side(u)?, side(v)?);
            // p inside side k, q inside side k + 1: the corner k + 1 is cut off.
            let (k, p, q) = match (j + 3 - i) % 3 {
                1 => (i, u, v),
                2 => (j, v, u),
                _ => return None,
            };
            let [a, b, c] = from(k);
            Some(vec![[p, b, q], [a, p, q], [a, q, c]])
        }
        4 => {
            // p inside side k, the other end the opposite corner k + 2.
            let (p, k) = match (side(u), corner(v), side(v), corner(u)) {
                (Some(k), Some(c), _, _) if c == (k + 2) % 3 => (u, k),
                (_, _, Some(k), Some(c)) if c == (k + 2) % 3 => (v, k),
                _ => return None,
            };
            let [a, b, c] = from(k);
            Some(vec![[a, p, c], [p, b, c]])
        }
        _ => None,
    }
}

/// The pieces where the constraints and the triangle's boundary bound faces (most triangles
/// that a meet cuts more than once: chains across it, and the branching outlines of a coplanar
/// overlap): the boundary cycle counterclockwise (each corner, then the points inside its
/// side in their order along it) and each constraint both ways are the half-edges, each face
/// is traced by leaving every point along the half-edge next clockwise from the one it came
/// in by ([`cmp_clockwise_from`], the face on the left), and each face is ear-clipped. `None`
/// where a point is on no edge, an edge repeats, a face runs into a used half-edge, has more
/// than [`LARGEST_FACE`] corners or has no ear (a ring inside a face, crossing constraints, a
/// point inside an edge) — which the general path takes (and reports crossings and points
/// outside).
///
/// The result needs no further check, whatever the faces traced: every piece is
/// counterclockwise (ear clipping emits only those), and the pieces' edges are the half-edges,
/// each used once, and the ears' diagonals, each met once each way, so the pieces cover each
/// point inside the triangle as often as the boundary winds around it (once) and none
/// outside. Constraints that crossed, or a point outside, on a side it was not declared on, or
/// inside a piece or an edge, would cover some point twice or outside.
fn by_faces<N: Num>(
    points: &[Point<N>],
    corners: [usize; 3],
    sides: [&[usize]; 3],
    constraints: &[(usize, usize)],
    ctx: &N::Ctx,
) -> Option<Vec<[usize; 3]>> {
    let n = points.len();
    let mut boundary: Small<usize> = SmallVec::with_capacity(n);
    for (k, side) in sides.iter().enumerate() {
        let (x, y) = (corners[k], corners[(k + 1) % 3]);
        boundary.push(x);
        let start = boundary.len();
        boundary.extend_from_slice(side);
        along_side(points, x, y, &mut boundary[start..]);
    }
    // The half-edges, by first point: the boundary's steps, and each constraint both ways (one
    // along a step repeats it).
    let mut half: SmallVec<[(usize, usize); 32]> =
        SmallVec::with_capacity(boundary.len() + 2 * constraints.len());
    for (k, &x) in boundary.iter().enumerate() {
        half.push((x, boundary[(k + 1) % boundary.len()]));
    }
    for &(u, v) in constraints {
        half.extend([(u, v), (v, u)]);
    }
    half.sort_unstable();
    if half.windows(2).any(|w| w[0] == w[1]) {
        return None;
    }
    // The half-edges from each point: first[p]..first[p + 1].
    let mut first: Small<usize> = smallvec![0; n + 1];
    for &(u, _) in &half {
        first[u + 1] += 1;
    }
    for p in 0..n {
        if first[p + 1] == 0 {
            return None;
        }
        first[p + 1] += first[p];
    }
    // The boundary's points before and after each of its points.
    let mut around: Small<[usize; 2]> = smallvec![[usize::MAX; 2]; n];
    for (k, &x) in boundary.iter().enumerate() {
        let m = boundary.len();
        around[x] = [boundary[(k + m - 1) % m], boundary[(k + 1) % m]];
    }
    let mut used: Small<bool> = smallvec![false; half.len()];
    let mut pieces = Vec::with_capacity(2 * n);
    for start in 0..half.len() {
        if used[start] {
            continue;
        }
        let mut face: Small<usize> = SmallVec::new();
        let mut h = start;
        while !used[h] {
            used[h] = true;
            let (u, v) = half[h];
            face.push(u);
            let from_v = first[v]..first[v + 1];
            // Reached along a side at a point inside it, the side's next step lies at π
            // clockwise, after every constraint there (each runs into the triangle): taken
            // only where none leaves the point, so that no comparison meets the side's three
            // collinear points.
            let [before, after] = around[v];
            let along = u == before && !corners.contains(&v);
            let (mut next, mut step) = (None, None);
            for e in from_v.clone().filter(|&e| half[e].1 != u) {
                if along && half[e].1 == after {
                    step = Some(e);
                    continue;
                }
                // The edge next clockwise from vu about v.
                let p = &points[half[e].1];
                let nearer = |f: usize| {
                    let q = &points[half[f].1];
                    cmp_clockwise_from(&points[v], &points[u], p, q, ctx) == Less
                };
                if next.is_none_or(nearer) {
                    next = Some(e);
                }
            }
            // Back along vu only at a dead end.
            h = (next.or(step)).or_else(|| from_v.clone().find(|&e| half[e].1 == u))?;
        }
        if h != start || face.len() < 3 || face.len() > LARGEST_FACE {
            return None;
        }
        pieces.extend(ear_clip(points, &face, ctx)?);
    }
    Some(pieces)
}

/// The most corners of a face that [`by_faces`] ear-clips (a quadratic walk, with many points
/// in a row on a side); a triangle with a larger face takes the general path.
const LARGEST_FACE: usize = 64;

/// Sort the points `on` of the segment from `x` to `y` nearest to `x` first: points of a
/// segment are in lexicographic order from its smaller end.
fn along_side<N: Num>(points: &[Point<N>], x: usize, y: usize, on: &mut [usize]) {
    on.sort_by(|&p, &q| points[p].cmp(&points[q]));
    if points[x] > points[y] {
        on.reverse();
    }
}

/// The undirected edge `ab` as a map key.
fn key(a: usize, b: usize) -> (usize, usize) {
    (a.min(b), a.max(b))
}

/// The triangle `t` rotated to start at vertex `x` (`None` if `x` is not a vertex of it).
fn from_vertex(t: [usize; 3], x: usize) -> Option<[usize; 3]> {
    let i = t.iter().position(|&y| y == x)?;
    Some([t[i], t[(i + 1) % 3], t[(i + 2) % 3]])
}

/// True if point `x` lies in the closed triangle `t` (counterclockwise).
fn in_closed<N: Num>(points: &[Point<N>], t: [usize; 3], x: usize, ctx: &N::Ctx) -> bool {
    (0..3).all(|i| orient(&points[t[i]], &points[t[(i + 1) % 3]], &points[x], ctx) != Less)
}

/// An interval around each coordinate of each point (from [`Num::approx`]).
fn enclosures<N: Num>(points: &[Point<N>]) -> Vec<[Interval; 2]> {
    (points.iter())
        .map(|p| [&p.x, &p.y].map(|c| Interval::around(c.approx())))
        .collect()
}

/// The points' [`enclosures`], and their orders on each axis where the predicates are exact
/// (a tolerance's orientation may take points beside a segment's box): what [`split`] needs.
fn enclosed<N: Num>(points: &[Point<N>]) -> (Vec<[Interval; 2]>, Option<ByAxis>) {
    let near = enclosures(points);
    let by_axis = N::EXACT.then(|| ByAxis::new(&near));
    (near, by_axis)
}

/// The points in the order of their enclosures' lower ends on each axis, with the widest
/// enclosure on it: the points whose enclosure meets a range of an axis are a run of its
/// order.
struct ByAxis {
    /// Each axis's order of the points.
    order: [Vec<usize>; 2],
    /// The lower ends along each order.
    lo: [Vec<f64>; 2],
    /// The widest enclosure on each axis (infinite if one is unbounded).
    width: [f64; 2],
}

impl ByAxis {
    /// The orders of the points with the enclosures `near`.
    fn new(near: &[[Interval; 2]]) -> ByAxis {
        let axis = |k: usize| {
            let mut order: Vec<usize> = (0..near.len()).collect();
            order.sort_by(|&p, &q| near[p][k].bounds().0.total_cmp(&near[q][k].bounds().0));
            let lo: Vec<f64> = order.iter().map(|&p| near[p][k].bounds().0).collect();
            let width = (near.iter())
                .map(|n| n[k].bounds().1 - n[k].bounds().0)
                .fold(0.0, f64::max);
            (order, lo, width)
        };
        let [(ox, lx, wx), (oy, ly, wy)] = [0, 1].map(axis);
        ByAxis {
            order: [ox, oy],
            lo: [lx, ly],
            width: [wx, wy],
        }
    }

    /// A superset of the points whose enclosures meet the hull of those of `u` and `v` on both
    /// axes: the shorter of the two axes' runs, each holding every point whose enclosure meets
    /// the hull on that axis (and some whose enclosure ends just before it).
    fn near_segment(&self, near: &[[Interval; 2]], u: usize, v: usize) -> &[usize] {
        let run = |k: usize| {
            let (lo, hi) = Interval::span(near[u][k], near[v][k]).bounds();
            // An enclosure meets [lo, hi] only if its lower end is at most hi and at least lo
            // less the widest enclosure.
            let ends = &self.lo[k];
            let from = ends.partition_point(|&x| x < lo - self.width[k]);
            let to = ends.partition_point(|&x| x <= hi);
            &self.order[k][from..to.max(from)]
        };
        let (x, y) = (run(0), run(1));
        if x.len() <= y.len() {
            x
        } else {
            y
        }
    }
}

/// The pieces of the segment `uv` between consecutive points lying on it (its ends by index:
/// the points are distinct, and an equal point is where the exact tests cost most).
fn split<N: Num>(
    points: &[Point<N>],
    near: &[[Interval; 2]],
    by_axis: Option<&ByAxis>,
    u: usize,
    v: usize,
    ctx: &N::Ctx,
) -> Vec<(usize, usize)> {
    let (a, b) = (&points[u], &points[v]);
    // With exact predicates (`by_axis` given) the segment's box first: only points whose
    // enclosures `near` may meet it on one axis are looked at, most of those beyond it are
    // shown so by their enclosures without exact comparisons, and comparisons cost less than
    // an orientation (which no filter decides where it is zero, as on the segment). A
    // tolerance's orientation may take points beside the box.
    let beyond = |w: usize, k: usize| {
        let (p, q, r) = (near[u][k], near[v][k], near[w][k]);
        let side = r.cmp(p);
        side.is_some() && side == r.cmp(q)
    };
    let within = |lo: &N, hi: &N, x: &N| {
        let (lo, hi) = if lo <= hi { (lo, hi) } else { (hi, lo) };
        lo <= x && x <= hi
    };
    let in_box = |w: usize| {
        let p = &points[w];
        !N::EXACT
            || !beyond(w, 0)
                && !beyond(w, 1)
                && within(&a.x, &b.x, &p.x)
                && within(&a.y, &b.y, &p.y)
    };
    let on_segment = |w: usize| {
        in_box(w) && orient(a, b, &points[w], ctx) == Equal && on_closed_segment(a, b, &points[w])
    };
    let mut on: Vec<usize> = match by_axis {
        Some(by_axis) => by_axis.near_segment(near, u, v).to_vec(),
        None => (0..points.len()).collect(),
    };
    on.retain(|&w| w == u || w == v || on_segment(w));
    on.sort_by(|&x, &y| points[x].cmp(&points[y]));
    on.windows(2).map(|w| (w[0], w[1])).collect()
}

/// Triangulate the counterclockwise simple polygon `poly` (indices into `points`) by clipping
/// ears: strictly convex corners whose closed triangle holds no other vertex of the polygon;
/// `None` if no ear is left (the polygon is not simple).
pub(crate) fn ear_clip<N: Num>(
    points: &[Point<N>],
    poly: &[usize],
    ctx: &N::Ctx,
) -> Option<Vec<[usize; 3]>> {
    let mut poly: Small<usize> = SmallVec::from_slice(poly);
    let mut out = Vec::with_capacity(poly.len().saturating_sub(2));
    let (mut i, mut misses) = (0, 0);
    while poly.len() > 3 {
        let n = poly.len();
        let ear = [poly[(i + n - 1) % n], poly[i], poly[(i + 1) % n]];
        let [a, b, c] = ear.map(|k| &points[k]);
        let empty = || {
            poly.iter().all(|&k| {
                ear.contains(&k)
                    || points[k] == *a
                    || points[k] == *b
                    || points[k] == *c
                    // The diagonal first: most vertices fail there, being beyond it.
                    || orient(c, a, &points[k], ctx) == Less
                    || orient(a, b, &points[k], ctx) == Less
                    || orient(b, c, &points[k], ctx) == Less
            })
        };
        if orient(a, b, c, ctx) == Greater && empty() {
            out.push(ear);
            poly.remove(i);
            i = (i + n - 2) % (n - 1);
            misses = 0;
        } else {
            i = (i + 1) % n;
            misses += 1;
            if misses > n {
                return None;
            }
        }
    }
    let [a, b, c] = [poly[0], poly[1], poly[2]].map(|k| &points[k]);
    (orient(a, b, c, ctx) == Greater).then(|| {
        out.push([poly[0], poly[1], poly[2]]);
        out
    })
}

/// A triangulation under construction, with the history of its splits for point location.
struct Mesh<'a, N: Num> {
    /// The coordinates of the vertices.
    points: &'a [Point<N>],
    /// The context of the predicates.
    ctx: &'a N::Ctx,
    /// Every triangle ever made, counterclockwise.
    tris: Vec<[usize; 3]>,
    /// True for the triangles of the current triangulation.
    alive: Vec<bool>,
    /// The triangles that replaced each split one (the history searched by [`Mesh::locate`]).
    children: Vec<Vec<usize>>,
    /// The current triangle on the left of each directed edge.
    edges: HashMap<(usize, usize), usize>,
}

impl<'a, N: Num> Mesh<'a, N> {
    /// The triangulation of the single triangle `corners`.
    fn new(
        points: &'a [Point<N>],
        corners: [usize; 3],
        ctx: &'a N::Ctx,
    ) -> Result<Self, TriangulateError> {
        let [a, b, c] = corners.map(|i| &points[i]);
        if orient(a, b, c, ctx) != Greater {
            return Err(TriangulateError::Inconsistent(
                "the corners are not counterclockwise",
            ));
        }
        // Sized for n points: at most 2n − 5 current triangles, 6n − 15 directed edges, and a
        // few times as many made in all (no rehashing: the tables are small and built often).
        let n = points.len();
        let mut mesh = Mesh {
            points,
            ctx,
            tris: Vec::with_capacity(4 * n),
            alive: Vec::with_capacity(4 * n),
            children: Vec::with_capacity(4 * n),
            edges: HashMap::with_capacity(6 * n),
        };
        mesh.add(corners);
        Ok(mesh)
    }

    /// Add the counterclockwise triangle `t` to the current triangulation; its id.
    fn add(&mut self, t: [usize; 3]) -> usize {
        let id = self.tris.len();
        self.tris.push(t);
        self.alive.push(true);
        self.children.push(Vec::new());
        for i in 0..3 {
            self.edges.insert((t[i], t[(i + 1) % 3]), id);
        }
        id
    }

    /// Replace the current triangle `id` by the triangles `parts`, recorded as its children.
    fn replace(&mut self, id: usize, parts: &[[usize; 3]]) {
        let t = self.tris[id];
        self.alive[id] = false;
        for i in 0..3 {
            self.edges.remove(&(t[i], t[(i + 1) % 3]));
        }
        self.children[id] = parts.iter().map(|&p| self.add(p)).collect();
    }

    /// The current triangle whose closure holds point `p` (`None` if `p` is outside).
    fn locate(&self, p: usize) -> Option<usize> {
        let inside = |id: usize| in_closed(self.points, self.tris[id], p, self.ctx);
        let mut id = Some(0).filter(|&root| inside(root))?;
        while !self.children[id].is_empty() {
            id = self.children[id].iter().copied().find(|&c| inside(c))?;
        }
        Some(id)
    }

    /// Make point `p` a vertex: split the triangle holding it in 3, or the 1 or 2 triangles
    /// sharing the edge it lies on in 2 each.
    fn insert(&mut self, p: usize) -> Result<(), TriangulateError> {
        let id = self.locate(p).ok_or(TriangulateError::PointOutside(p))?;
        let t = self.tris[id];
        let on_edge = (0..3).find(|&i| {
            orient(
                &self.points[t[i]],
                &self.points[t[(i + 1) % 3]],
                &self.points[p],
                self.ctx,
            ) == Equal
        });
        match on_edge {
            None => self.replace(id, &[[t[0], t[1], p], [t[1], t[2], p], [t[2], t[0], p]]),
            Some(i) => {
                let (a, b) = (t[i], t[(i + 1) % 3]);
                let twin = self.edges.get(&(b, a)).copied();
                self.split_edge(id, a, p)?;
                if let Some(twin) = twin {
                    self.split_edge(twin, b, p)?;
                }
            }
        }
        Ok(())
    }

    /// Make the points `on` of the side `xy` of the triangulation vertices, nearest to `x`
    /// first, each splitting the triangle on the side's remaining piece.
    fn split_side(&mut self, x: usize, y: usize, on: &[usize]) -> Result<(), TriangulateError> {
        let mut on = on.to_vec();
        along_side(self.points, x, y, &mut on);
        let mut from = x;
        for p in on {
            let missing = TriangulateError::Inconsistent("a side point is not inside its side");
            let id = *self.edges.get(&(from, y)).ok_or(missing)?;
            self.split_edge(id, from, p)?;
            from = p;
        }
        Ok(())
    }

    /// Split the current triangle `id`, `[x, y, z]` from its vertex `x`, at the point `p` of
    /// its edge `xy` into `[x, p, z]` and `[p, y, z]`.
    fn split_edge(&mut self, id: usize, x: usize, p: usize) -> Result<(), TriangulateError> {
        let [x, y, z] = from_vertex(self.tris[id], x).ok_or(TriangulateError::Inconsistent(
            "the split edge's start is not a vertex",
        ))?;
        self.replace(id, &[[x, p, z], [p, y, z]]);
        Ok(())
    }

    /// Make the constraint piece `uv` of constraint `c` an edge: remove the triangles its open
    /// segment crosses and ear-clip the pseudo-polygons on its two sides. `owner` maps every
    /// constraint piece to its constraint, so that crossing one is an error.
    fn recover(
        &mut self,
        u: usize,
        v: usize,
        c: usize,
        owner: &HashMap<(usize, usize), usize>,
    ) -> Result<(), TriangulateError> {
        if self.edges.contains_key(&(u, v)) || self.edges.contains_key(&(v, u)) {
            return Ok(());
        }
        let [pu, pv] = [u, v].map(|i| &self.points[i]);
        // The crossed edge (a, b), a right of uv and b left, and the triangle before it.
        let (mut a, mut b, first) = (0..self.tris.len())
            .filter(|&id| self.alive[id])
            .find_map(|id| {
                let [_, a, b] = from_vertex(self.tris[id], u)?;
                let crosses = orient(pu, pv, &self.points[a], self.ctx) == Less
                    && orient(pu, pv, &self.points[b], self.ctx) == Greater;
                crosses.then_some((a, b, id))
            })
            .ok_or(TriangulateError::Inconsistent(
                "no triangle at u meets the constraint",
            ))?;
        let (mut doomed, mut right, mut left) = (vec![first], vec![a], vec![b]);
        loop {
            if let Some(&d) = owner.get(&key(a, b)) {
                return Err(TriangulateError::CrossingConstraints(d.min(c), d.max(c)));
            }
            let lost = TriangulateError::Inconsistent("the constraint leaves the triangle");
            let next = *self.edges.get(&(b, a)).ok_or(lost.clone())?;
            if doomed.len() > self.tris.len() {
                // Each step removes a new triangle: more steps than triangles is a cycle.
                return Err(TriangulateError::Inconsistent("the constraint walk cycles"));
            }
            doomed.push(next);
            let [_, _, w] = from_vertex(self.tris[next], b).ok_or(lost)?;
            if w == v {
                break;
            }
            if orient(pu, pv, &self.points[w], self.ctx) == Less {
                a = w;
                right.push(w);
            } else {
                b = w;
                left.push(w);
            }
        }
        for id in doomed {
            self.replace(id, &[]);
        }
        let left_poly: Vec<usize> = [u, v].into_iter().chain(left.into_iter().rev()).collect();
        let right_poly: Vec<usize> = [v, u].into_iter().chain(right).collect();
        for poly in [left_poly, right_poly] {
            let ears = ear_clip(self.points, &poly, self.ctx).ok_or(
                TriangulateError::Inconsistent("a pseudo-polygon of recovery has no ear"),
            )?;
            for t in ears {
                self.add(t);
            }
        }
        Ok(())
    }

    /// The current triangles.
    fn triangles(&self) -> Vec<[usize; 3]> {
        (0..self.tris.len())
            .filter(|&id| self.alive[id])
            .map(|id| self.tris[id])
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::kernel::{classify, Contact};
    use crate::num::{Float, Rational, Tolerance};
    use proptest::prelude::*;
    use std::collections::HashSet;

    /// Points with integer coordinates.
    fn pts<N: Num>(xy: &[(i64, i64)]) -> Vec<Point<N>> {
        xy.iter().map(|&(x, y)| Point::int(x, y)).collect()
    }

    /// (b − a) × (c − a): twice the signed area of `abc`.
    fn cross<N: Num>(a: &Point<N>, b: &Point<N>, c: &Point<N>) -> N {
        (b.x.clone() - a.x.clone()) * (c.y.clone() - a.y.clone())
            - (b.y.clone() - a.y.clone()) * (c.x.clone() - a.x.clone())
    }

    /// |b − a| in the L1 norm (additive along a line).
    fn l1<N: Num>(a: &Point<N>, b: &Point<N>) -> N {
        let abs = |v: N| if v.sign() == Less { -v } else { v };
        abs(b.x.clone() - a.x.clone()) + abs(b.y.clone() - a.y.clone())
    }

    /// Assert that `tris` is a conforming triangulation of `corners` with every point a vertex
    /// and every constraint a union of edges, checked without the algorithm's own reasoning.
    fn check<N: Num>(
        points: &[Point<N>],
        corners: [usize; 3],
        constraints: &[(usize, usize)],
        tris: &[[usize; 3]],
        ctx: &N::Ctx,
    ) {
        let p = |i: usize| &points[i];
        let mut area = N::zero();
        let mut directed = HashSet::new();
        for &t in tris {
            assert_eq!(
                orient(p(t[0]), p(t[1]), p(t[2]), ctx),
                Greater,
                "{t:?} not ccw"
            );
            area = area + cross(p(t[0]), p(t[1]), p(t[2]));
            for x in (0..points.len()).filter(|x| !t.contains(x)) {
                assert!(!in_closed(points, t, x, ctx), "point {x} on or in {t:?}");
            }
            for i in 0..3 {
                assert!(
                    directed.insert((t[i], t[(i + 1) % 3])),
                    "edge twice in {t:?}"
                );
            }
        }
        let [a, b, c] = corners.map(p);
        assert_eq!(area, cross(a, b, c), "areas do not add up");
        for &(x, y) in &directed {
            let side = (0..3).any(|i| {
                let (s, e) = (p(corners[i]), p(corners[(i + 1) % 3]));
                orient(s, e, p(x), ctx) == Equal && orient(s, e, p(y), ctx) == Equal
            });
            assert!(
                directed.contains(&(y, x)) || side,
                "({x}, {y}) is a loose inner edge"
            );
        }
        let used: HashSet<usize> = tris.iter().flatten().copied().collect();
        assert_eq!(used.len(), points.len(), "a point is not a vertex");
        for &(u, v) in constraints {
            let covered = directed
                .iter()
                .filter(|&&(x, y)| x < y || !directed.contains(&(y, x)))
                .filter(|&&(x, y)| {
                    [x, y].iter().all(|&z| {
                        orient(p(u), p(v), p(z), ctx) == Equal
                            && on_closed_segment(p(u), p(v), p(z))
                    })
                })
                .fold(N::zero(), |s, &(x, y)| s + l1(p(x), p(y)));
            assert_eq!(covered, l1(p(u), p(v)), "constraint ({u}, {v}) not covered");
        }
    }

    /// No point declared on a side.
    const NO_SIDES: [&[usize]; 3] = [&[], &[], &[]];

    /// Triangulate and check, returning the triangles.
    fn run(
        xy: &[(i64, i64)],
        corners: [usize; 3],
        constraints: &[(usize, usize)],
    ) -> Vec<[usize; 3]> {
        let points = pts::<Rational>(xy);
        let tris = triangulate(&points, corners, NO_SIDES, constraints, &()).expect("valid input");
        check(&points, corners, constraints, &tris, &());
        tris
    }

    /// A segment splits at the points on it, in order, and only there: collinear points past
    /// either end, and points beside it, are left out; on axis-parallel segments (a box of
    /// zero width) and a slanted one, in both backends.
    #[test]
    fn a_segment_splits_at_the_points_on_it() {
        fn split<N: Num>(
            points: &[Point<N>],
            u: usize,
            v: usize,
            ctx: &N::Ctx,
        ) -> Vec<(usize, usize)> {
            let (near, by_axis) = enclosed(points);
            super::split(points, &near, by_axis.as_ref(), u, v, ctx)
        }
        fn splits<N: Num>(ctx: &N::Ctx) {
            // Horizontal: 0 → 1 through 2; 3 and 4 collinear beyond the ends; 5 beside.
            let flat = pts::<N>(&[(0, 0), (4, 0), (2, 0), (6, 0), (-1, 0), (2, 1)]);
            assert_eq!(split(&flat, 0, 1, ctx), [(0, 2), (2, 1)]);
            assert_eq!(split(&flat, 1, 0, ctx), [(0, 2), (2, 1)]);
            // Vertical, the same points turned.
            let upright = pts::<N>(&[(0, 0), (0, 4), (0, 2), (0, 6), (0, -1), (1, 2)]);
            assert_eq!(split(&upright, 0, 1, ctx), [(0, 2), (2, 1)]);
            // Slanted: (3, 3) past the end, (1, 2) beside, (1, 1) and (2, 2) on it.
            let slant = pts::<N>(&[(0, 0), (2, 2), (3, 3), (1, 2), (1, 1)]);
            assert_eq!(split(&slant, 0, 1, ctx), [(0, 4), (4, 1)]);
        }
        splits::<Rational>(&());
        splits::<Float>(&Tolerance::default().resolve(8.0, 8.0).expect("a tolerance"));
    }

    /// Looking only at the points whose enclosures may meet a segment's box ([`ByAxis`])
    /// finds the same points on it as looking at all: segments between points of a grid of
    /// thirds (no `f64`s, so enclosures have width), many through other grid points, on
    /// each axis, diagonal and slanted.
    #[test]
    fn a_split_by_axis_finds_every_point_on_the_segment() {
        let third = |k: i64| Rational::from_i64(k) / Rational::from_i64(3);
        let points: Vec<Point<Rational>> = (0..49)
            .map(|i| Point::new(third(i % 7 - 3), third(i / 7 - 3)))
            .collect();
        let (near, by_axis) = enclosed(&points);
        let by_axis = by_axis.expect("exact predicates");
        let (mut through, mut pruned) = (0, 0);
        for u in 0..points.len() {
            for v in 0..points.len() {
                if u == v {
                    continue;
                }
                let all = split(&points, &near, None, u, v, &());
                let some = split(&points, &near, Some(&by_axis), u, v, &());
                assert_eq!(some, all, "segment {u}-{v}");
                through += usize::from(all.len() > 1);
                pruned += usize::from(by_axis.near_segment(&near, u, v).len() < points.len());
            }
        }
        // Segments through other points, and candidate runs shorter than all points.
        assert!(through >= 400 && pruned >= 1500, "{through} {pruned}");
    }

    /// One constraint from inside one side to inside another, or to a corner, with no other
    /// point, for every pair of sides or corner, both directions and every rotation of the
    /// corners: the independent check passes, and [`one_cut`] gives the same pieces without
    /// predicates for each cut across the triangle (one to a corner of the point's own side
    /// runs along it, and is no cut).
    #[test]
    fn one_cut_cuts_off_a_corner_or_halves_the_triangle() {
        // A point inside each side i, from corner i to corner i + 1.
        let (corner_xy, inside_xy) = ([(0, 0), (6, 0), (0, 6)], [(2, 0), (4, 2), (0, 5)]);
        for r in 0..3 {
            let corners = [r, (r + 1) % 3, (r + 2) % 3];
            let side_of = |i: usize| (i + 3 - r) % 3;
            for (i, j) in [(0, 1), (1, 2), (2, 0), (1, 0), (2, 1), (0, 2)] {
                let points = pts::<Rational>(&[
                    corner_xy[0],
                    corner_xy[1],
                    corner_xy[2],
                    inside_xy[i],
                    inside_xy[j],
                ]);
                let mut sides = NO_SIDES;
                (sides[side_of(i)], sides[side_of(j)]) = (&[3], &[4]);
                let tris = triangulate(&points, corners, sides, &[(3, 4)], &()).expect("valid");
                check(&points, corners, &[(3, 4)], &tris, &());
                assert_eq!(one_cut(5, corners, sides, &[(3, 4)]), Some(tris));
            }
            for i in 0..3 {
                let points =
                    pts::<Rational>(&[corner_xy[0], corner_xy[1], corner_xy[2], inside_xy[i]]);
                let mut sides = NO_SIDES;
                sides[side_of(i)] = &[3];
                for c in 0..3 {
                    for cut in [(3, c), (c, 3)] {
                        let tris =
                            triangulate(&points, corners, sides, &[cut], &()).expect("valid");
                        check(&points, corners, &[cut], &tris, &());
                        // A cut to a corner of the point's side runs along it: no cut at all.
                        let opposite = corners[(side_of(i) + 2) % 3] == c;
                        let want = opposite.then_some(tris);
                        assert_eq!(one_cut(4, corners, sides, &[cut]), want);
                    }
                }
            }
        }
    }

    /// True if `tris` has the edge `ab` in either direction.
    fn has_edge(tris: &[[usize; 3]], a: usize, b: usize) -> bool {
        tris.iter()
            .any(|t| (0..3).any(|i| key(t[i], t[(i + 1) % 3]) == key(a, b)))
    }

    #[test]
    fn constraint_along_a_side_through_points() {
        let xy = [(0, 0), (8, 0), (0, 8), (2, 0), (5, 0), (3, 3), (1, 1)];
        let tris = run(&xy, [0, 1, 2], &[(0, 1), (3, 5)]);
        assert!(has_edge(&tris, 0, 3) && has_edge(&tris, 3, 4) && has_edge(&tris, 4, 1));
        assert!(has_edge(&tris, 3, 5));
    }

    /// Constraints along a side (between its corners and its declared points), repeated ones
    /// (either way round) and single points are set aside, the others kept in their order
    /// with their indices; a point not declared on a side leaves its constraints in.
    #[test]
    fn cuts_through_keep_only_cuts() {
        // Corners 0, 1, 2; points 3 and 4 inside side 0, 5 inside side 2, 6 inside.
        let sides: [&[usize]; 3] = [&[3, 4], &[], &[5]];
        let constraints = [
            (3, 1),
            (6, 3),
            (4, 3),
            (0, 5),
            (3, 6),
            (5, 4),
            (2, 2),
            (1, 2),
            (4, 5),
            (6, 0),
        ];
        let (cuts, numbering) = cuts_through(7, [0, 1, 2], sides, &constraints);
        assert_eq!(&cuts[..], &[(6, 3), (5, 4), (6, 0)]);
        assert_eq!(&numbering[..], &[1, 5, 9]);
        let (cuts, _) = cuts_through(7, [0, 1, 2], NO_SIDES, &constraints);
        assert_eq!(&cuts[..], &[(3, 1), (6, 3), (4, 3), (0, 5), (5, 4), (6, 0)]);
    }

    #[test]
    fn overlapping_collinear_constraints() {
        let xy = [
            (0, 0),
            (20, 0),
            (0, 20),
            (2, 3),
            (5, 3),
            (9, 3),
            (12, 3),
            (6, 1),
            (6, 7),
        ];
        let tris = run(&xy, [0, 1, 2], &[(3, 5), (4, 6), (6, 4), (3, 6)]);
        assert!(has_edge(&tris, 3, 4) && has_edge(&tris, 4, 5) && has_edge(&tris, 5, 6));
    }

    #[test]
    fn constraint_through_three_collinear_interior_points() {
        let xy = [
            (0, 0),
            (30, 0),
            (0, 30),
            (3, 3),
            (6, 6),
            (9, 9),
            (12, 12),
            (20, 1),
            (1, 20),
        ];
        let tris = run(&xy, [0, 1, 2], &[(0, 6), (3, 7), (8, 5)]);
        assert!((3..6).all(|i| has_edge(&tris, i, i + 1)));
    }

    /// A triangle with a square (points 3–6) strictly inside, a point inside the square and
    /// two outside.
    const RING_POINTS: [(i64, i64); 10] = [
        (0, 0),
        (40, 0),
        (10, 30),
        (12, 4),
        (20, 4),
        (20, 12),
        (12, 12),
        (15, 9),
        (3, 1),
        (30, 2),
    ];

    /// The closed ring of constraints around the square.
    const RING: [(usize, usize); 4] = [(3, 4), (4, 5), (5, 6), (6, 3)];

    #[test]
    fn square_ring_strictly_inside() {
        let tris = run(&RING_POINTS, [0, 1, 2], &RING);
        let inside: Vec<_> = tris
            .iter()
            .filter(|t| t.iter().all(|&v| (3..8).contains(&v)))
            .collect();
        assert_eq!(
            inside.len(),
            4,
            "the ring's inside is the fan around point 7"
        );
    }

    #[test]
    fn fan_of_points_on_one_side_crossed_by_a_constraint() {
        let mut xy = vec![(0, 0), (100, 0), (50, 100), (12, 20), (88, 20)];
        xy.extend((1..100).map(|x| (x, 0)));
        let tris = run(&xy, [1, 2, 0], &[(3, 4), (4, 60)]);
        assert_eq!(
            tris.len(),
            2 * xy.len() - 2 - 102,
            "Euler: 2n − 2 − h triangles"
        );
    }

    /// Points, the points inside each side and the constraints.
    type Chains = (Vec<Point<Rational>>, [Vec<usize>; 3], Vec<(usize, usize)>);

    /// Chains across the triangle (0, 0), (60, 0), (30, 60), one in each of a few disjoint
    /// horizontal bands (so that none crosses another): from a point inside the left side, or
    /// from corner 0, through up to four points strictly inside in order of x (the first may
    /// lie left of the start, and a chain may fold back along itself: the general path's
    /// cases), to a point inside the right side; a few points on the bottom side on no chain.
    /// The point list is numbered corners first, then each chain's points in order.
    fn banded_chains(rng: &mut rand::rngs::StdRng, bands: usize) -> Chains {
        use rand::RngExt;
        let r = |n: i64, d: i64| Rational::new(n.into(), d.into());
        let mut points = pts::<Rational>(&[(0, 0), (60, 0), (30, 60)]);
        let (mut sides, mut constraints) = ([vec![], vec![], vec![]], vec![]);
        for band in 0..bands {
            let y = |rng: &mut rand::rngs::StdRng| 10 * band as i64 + rng.random_range(2..=8);
            let mut chain = vec![];
            if band == 0 && rng.random() {
                chain.push(0);
            } else {
                let y0 = y(rng);
                points.push(Point::new(r(y0, 2), r(y0, 1)));
                sides[2].push(points.len() - 1);
                chain.push(points.len() - 1);
            }
            let mut inner: Vec<(i64, i64)> = (0..rng.random_range(0..=4))
                .map(|_| {
                    let yi = y(rng);
                    (rng.random_range(yi / 2 + 1..60 - yi / 2), yi)
                })
                .collect();
            inner.sort();
            inner.dedup_by_key(|p| p.0);
            for (x, yi) in inner {
                points.push(Point::int(x, yi));
                chain.push(points.len() - 1);
            }
            let y1 = y(rng);
            points.push(Point::new(r(120 - y1, 2), r(y1, 1)));
            sides[1].push(points.len() - 1);
            chain.push(points.len() - 1);
            constraints.extend(chain.windows(2).map(|w| (w[0], w[1])));
        }
        for _ in 0..rng.random_range(0..3) {
            let x = rng.random_range(1..60);
            if !points.contains(&Point::int(x, 0)) {
                points.push(Point::int(x, 0));
                sides[0].push(points.len() - 1);
            }
        }
        (points, sides, constraints)
    }

    /// On random banded chains (above), the face path answers nearly always and its pieces
    /// pass the independent check, as do `triangulate`'s.
    #[test]
    fn chains_across_the_triangle() {
        use rand::SeedableRng;
        let mut rng = rand::rngs::StdRng::seed_from_u64(5);
        let mut answered = 0;
        for case in 0..400 {
            let (points, sides, constraints) = banded_chains(&mut rng, 1 + case % 5);
            let sides = [&sides[0][..], &sides[1][..], &sides[2][..]];
            if let Some(tris) = by_faces(&points, [0, 1, 2], sides, &constraints, &()) {
                check(&points, [0, 1, 2], &constraints, &tris, &());
                answered += 1;
            }
            let tris = triangulate(&points, [0, 1, 2], sides, &constraints, &()).expect("valid");
            check(&points, [0, 1, 2], &constraints, &tris, &());
        }
        assert!(answered > 300, "the face path answered {answered} of 400");
    }

    /// Chains nested on one side, and chains ending at corners 1 and 2 and on the bottom side:
    /// the face path answers, and its pieces pass the independent check.
    #[test]
    fn nested_chains_and_chains_from_corners() {
        let points = pts::<Rational>(&[
            (0, 0),
            (60, 0),
            (30, 60),
            (58, 4),
            (54, 12),
            (46, 28),
            (42, 36),
            (44, 16),
            (30, 10),
            (30, 30),
            (10, 20),
            (25, 40),
            (20, 0),
            (40, 5),
        ]);
        let sides: [&[usize]; 3] = [&[12], &[6, 3, 5, 4], &[10]];
        let constraints = [
            (4, 7),
            (7, 5),
            (3, 8),
            (8, 9),
            (9, 6),
            (2, 11),
            (11, 10),
            (12, 13),
            (13, 1),
        ];
        let tris = by_faces(&points, [0, 1, 2], sides, &constraints, &()).expect("chains");
        check(&points, [0, 1, 2], &constraints, &tris, &());
    }

    /// A branching outline: a point inside on six constraints (to a point inside each side,
    /// to corner 0, through a second point to corner 2 and through a third to corner 1), two
    /// of them in one line through it: the face path answers, and its pieces pass the
    /// independent check.
    #[test]
    fn a_branching_outline_is_traced_into_faces() {
        let points = pts::<Rational>(&[
            (0, 0),
            (60, 0),
            (30, 60),
            (20, 0),
            (45, 30),
            (15, 30),
            (30, 20),
            (30, 40),
            (45, 10),
        ]);
        let sides: [&[usize]; 3] = [&[3], &[4], &[5]];
        let constraints = [
            (6, 3),
            (6, 4),
            (6, 5),
            (6, 0),
            (6, 7),
            (7, 2),
            (8, 6),
            (8, 1),
        ];
        let tris = by_faces(&points, [0, 1, 2], sides, &constraints, &()).expect("faces");
        check(&points, [0, 1, 2], &constraints, &tris, &());
        assert_eq!(
            tris.len(),
            2 * points.len() - 2 - 6,
            "Euler: 2n − 2 − h triangles"
        );
    }

    /// Two chains that cross twice (their ends on the sides do not interleave, so one polygon
    /// holds both ends of the second): no ear clipping can tile them, and the general path
    /// reports the crossing.
    #[test]
    fn chains_that_cross_are_errors() {
        let points = pts::<Rational>(&[
            (0, 0),
            (60, 0),
            (30, 60),
            (10, 20),
            (50, 20),
            (20, 10),
            (40, 30),
            (5, 10),
            (55, 10),
            (25, 30),
        ]);
        let sides: [&[usize]; 3] = [&[], &[4, 8], &[3, 7]];
        // 3 → 5 → 6 → 4 dips below 7 → 9 → 8 and rises above it again.
        let constraints = [(3, 5), (5, 6), (6, 4), (7, 9), (9, 8)];
        assert_eq!(by_faces(&points, [0, 1, 2], sides, &constraints, &()), None);
        assert!(matches!(
            triangulate(&points, [0, 1, 2], sides, &constraints, &()),
            Err(TriangulateError::CrossingConstraints(..))
        ));
    }

    /// Chains the face path leaves to the general path: one touching a side at a point not
    /// declared on it (a vertex of the pieces on both sides of it there), one along a side (an
    /// edge twice), one that is a closed ring (a face with a hole).
    #[test]
    fn chains_the_general_path_takes() {
        let points = pts::<Rational>(&[(0, 0), (60, 0), (30, 60), (10, 20), (50, 20), (30, 0)]);
        let sides: [&[usize]; 3] = [&[], &[4], &[3]];
        let touching = [(3, 5), (5, 4)];
        let points_on_bottom = pts::<Rational>(&[(0, 0), (60, 0), (30, 60), (20, 0), (50, 20)]);
        let along: [&[usize]; 3] = [&[3], &[4], &[]];
        for (points, sides, constraints) in [
            (&points, sides, &touching[..]),
            (&points_on_bottom, along, &[(0, 3)][..]),
            (&pts::<Rational>(&RING_POINTS), NO_SIDES, &RING[..]),
        ] {
            assert_eq!(by_faces(points, [0, 1, 2], sides, constraints, &()), None);
            let tris = triangulate(points, [0, 1, 2], sides, constraints, &()).expect("valid");
            check(points, [0, 1, 2], constraints, &tris, &());
        }
    }

    #[test]
    fn broken_promises_are_errors() {
        let points = pts::<Rational>(&[(0, 0), (10, 0), (0, 10), (1, 1), (6, 1), (1, 6), (5, 5)]);
        let crossing = [(0, 3), (4, 5), (3, 6)];
        let r = triangulate(&points, [0, 1, 2], NO_SIDES, &crossing, &());
        assert_eq!(r, Err(TriangulateError::CrossingConstraints(1, 2)));
        let outside = pts::<Rational>(&[(0, 0), (10, 0), (0, 10), (1, 1), (6, 5)]);
        let r = triangulate(&outside, [0, 1, 2], NO_SIDES, &[], &());
        assert_eq!(r, Err(TriangulateError::PointOutside(4)));
    }

    #[test]
    fn float_mode_runs_the_ring() {
        let points = pts::<Float>(&RING_POINTS);
        let ctx = Tolerance::new(1e-9);
        let tris = triangulate(&points, [0, 1, 2], NO_SIDES, &RING, &ctx).expect("valid input");
        check(&points, [0, 1, 2], &RING, &tris, &ctx);
    }

    /// The lattice points of the closed triangle (0,0), (12,0), (6,12) other than its corners.
    fn grid() -> Vec<Point<Rational>> {
        let corners = pts::<Rational>(&[(0, 0), (12, 0), (6, 12)]);
        let mut g = Vec::new();
        for x in 0..=12 {
            for y in 0..=12 {
                let q = Point::int(x, y);
                let inside =
                    (0..3).all(|i| orient(&corners[i], &corners[(i + 1) % 3], &q, &()) != Less);
                if inside && !corners.contains(&q) {
                    g.push(q);
                }
            }
        }
        g
    }

    /// True if constraints `a` and `b` cross at a point that is not in `points`.
    fn bad_crossing(points: &[Point<Rational>], a: (usize, usize), b: (usize, usize)) -> bool {
        let c = classify(&points[a.0], &points[a.1], &points[b.0], &points[b.1], &());
        matches!(c, Contact::Crossing(x) if !points.contains(&x))
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(yinset_testkit::cases(300)))]
        #[test]
        fn random_grid_points_and_constraints(
            pick in proptest::sample::subsequence(grid(), 0..=45),
            candidates in proptest::collection::vec((0usize..1000, 0usize..1000), 0..20),
            declare_sides in proptest::bool::ANY,
        ) {
            let mut points = pick;
            let n = points.len();
            points.extend(pts::<Rational>(&[(0, 0), (12, 0), (6, 12)]));
            let corners = [n, n + 1, n + 2];
            let all: Vec<(usize, usize)> = candidates
                .iter()
                .map(|&(a, b)| (a % points.len(), b % points.len()))
                .filter(|&(a, b)| a != b)
                .collect();
            let mut kept: Vec<(usize, usize)> = Vec::new();
            for &s in &all {
                if kept.iter().all(|&k| !bad_crossing(&points, k, s)) {
                    kept.push(s);
                }
            }
            // The points strictly inside each side, by the lattice's own arithmetic (grid
            // points on the line between the two corners, other than the corners).
            let on_side = |k: usize| -> Vec<usize> {
                let (a, b) = (&points[corners[k]], &points[corners[(k + 1) % 3]]);
                (0..n).filter(|&i| cross(a, b, &points[i]) == Rational::zero()).collect()
            };
            let sides = if declare_sides { [0, 1, 2].map(on_side) } else { Default::default() };
            let sides = [&sides[0][..], &sides[1][..], &sides[2][..]];
            let tris = triangulate(&points, corners, sides, &kept, &()).expect("valid input");
            check(&points, corners, &kept, &tris, &());
            if kept.len() < all.len() {
                match triangulate(&points, corners, sides, &all, &()) {
                    Err(TriangulateError::CrossingConstraints(i, j)) => {
                        prop_assert!(i < j && bad_crossing(&points, all[i], all[j]));
                    }
                    other => prop_assert!(false, "expected a crossing, got {:?}", other),
                }
            }
        }
    }
}
