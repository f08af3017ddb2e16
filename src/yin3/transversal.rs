//! The meet of two float sets whose boundaries cross transversally (seed 004 steps 1–5 for the
//! generic case; README, "3D float mode"): every pair of triangles of different operands either
//! misses or crosses properly — no vertex on the other's plane where they meet, no edge through
//! the other's edge. Then everything the general arrangement decides with constructed points
//! is decided from exact orientations of the `f64` input vertices:
//! - each end of a crossing segment is where an edge of one operand pierces a triangle of the
//!   other, named by that (edge, triangle) pair and constructed exactly once;
//! - a pierce point lies on the edge's triangles and in the pierced triangle, and nowhere else;
//! - membership is constant on patches (pieces of one operand joined across edges that are not
//!   crossing segments) and flips across every crossing segment, so one ray per connected
//!   surface decides every patch.
//!
//! Where no pair meets at all, each glued surface lies wholly inside or outside the other
//! operand, and one ray per glued surface decides it ([`Transversal::Apart`]).
//!
//! If any pair is not generic the caller falls back to the general exact meet; the result is
//! the exact meet either way.

use super::arrange::retriangulate;
use super::float::exact_points;
use super::geom::Chart;
use super::locate::{winding, TriBoxes};
use super::set::Brep;
use crate::kernel::Point3;
use crate::num::{exact_orient3d_f64, Num, Rational};
use crate::union_find::UnionFind;
use foldhash::{HashMap, HashMapExt, HashSet, HashSetExt};
use num_bigint::BigInt;
use num_traits::Float as _;
use rayon::prelude::*;
use rstar::{primitives::GeomWithData, primitives::Rectangle, Envelope, RTree, AABB};
use std::cell::{Cell, OnceCell};
use std::cmp::Ordering::{self, Equal};

/// Where an edge `(u, v)` (global point indices, u < v) pierces triangle `tri` (global index).
type Pierce = ((usize, usize), usize);

/// Rays that scan every triangle of the other operand before an R-tree of its boxes is built
/// (one in unit tests, so that they take both ways).
const SCANNED_RAYS: usize = if cfg!(test) { 1 } else { 8 };

/// Triangles of both operands from which the meet runs on rayon's threads (16 in unit tests,
/// so that they take both ways): handing small work over costs more than it saves.
const PARALLEL_FROM: usize = if cfg!(test) { 16 } else { 8192 };

/// `f` on each of `items`, in order, on rayon's threads if `parallel`.
fn map_all<T: Sync, R: Send>(
    items: &[T],
    parallel: bool,
    f: impl Fn(&T) -> R + Sync + Send,
) -> Vec<R> {
    if parallel {
        items.par_iter().map(f).collect()
    } else {
        items.iter().map(f).collect()
    }
}

/// Triangles over a table of exact points.
type Complex = (Vec<Point3<Rational>>, Vec<[usize; 3]>);

/// How two triangles of different operands meet.
enum Contact {
    /// Disjoint.
    Apart,
    /// Crossing properly along the segment between two pierce points.
    Cross([Pierce; 2]),
    /// Touching, coplanar, or crossing through an edge or a vertex: not generic.
    Degenerate,
}

/// The meet of two float boundaries that cross transversally or not at all.
pub(crate) enum Transversal {
    /// The boundaries do not meet: for each operand, whether each of its glued surfaces lies
    /// inside the other operand (one ray per surface).
    Apart([Vec<bool>; 2]),
    /// They cross: the meet's triangles (a conforming complex, as the validator would rebuild
    /// it) over a table of exact points, some of which may be unused.
    Crossing(Complex),
}

impl Transversal {
    /// The meet's triangles over a table of exact points: operand `a`'s, then `b`'s, then the
    /// pierce points; where the boundaries are apart, the triangles of the glued surfaces that
    /// lie inside the other operand.
    pub(crate) fn complex<N: Num>(self, a: &Brep<N>, b: &Brep<N>) -> Complex {
        let inside = match self {
            Transversal::Crossing(complex) => return complex,
            Transversal::Apart(inside) => inside,
        };
        let mut points = exact_points(&a.points);
        points.extend(exact_points(&b.points));
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
        (points, tris)
    }
}

/// The exact meet of the float boundaries `a` and `b` (bounded or not) if they cross
/// transversally or not at all (module docs), `None` otherwise.
pub(crate) fn transversal_meet<N: Num>(a: &Brep<N>, b: &Brep<N>) -> Option<Transversal> {
    let na = a.points.len();
    let f64s: Vec<[f64; 3]> = a
        .points
        .iter()
        .chain(&b.points)
        .map(|p| p.to_f64())
        .collect();
    let mut tris: Vec<[usize; 3]> = a.tris.clone();
    tris.extend(b.tris.iter().map(|t| t.map(|v| v + na)));
    let first_b = a.tris.len();
    let boxes: Vec<AABB<[f64; 3]>> = tris
        .iter()
        .map(|t| AABB::from_points(t.map(|v| &f64s[v])))
        .collect();
    let hull = |of: &[AABB<[f64; 3]>]| of.iter().fold(AABB::new_empty(), |h, b| h.merged(b));
    let (hull_a, hull_b) = (hull(&boxes[..first_b]), hull(&boxes[first_b..]));
    // Only triangles whose boxes meet the other operand's box can meet it.
    let tree = RTree::bulk_load(
        (first_b..tris.len())
            .filter(|&s| boxes[s].intersects(&hull_a))
            .map(|s| GeomWithData::new(Rectangle::from_aabb(boxes[s]), s))
            .collect(),
    );
    // Every pair of boxes that meet; the first degenerate pair ends it.
    let search = |t: usize| {
        let mut mine = Vec::new();
        for g in tree.locate_in_envelope_intersecting(&boxes[t]) {
            match contact(&f64s, (t, tris[t]), (g.data, tris[g.data])) {
                Contact::Apart => {}
                Contact::Cross(ends) => mine.push((t, g.data, ends)),
                Contact::Degenerate => return None,
            }
        }
        Some(mine)
    };
    let parallel = tris.len() >= PARALLEL_FROM;
    let near: Vec<usize> = (0..first_b)
        .filter(|&t| boxes[t].intersects(&hull_b))
        .collect();
    let found: Vec<Vec<_>> = map_all(&near, parallel, |&t| search(t))
        .into_iter()
        .collect::<Option<_>>()?;
    let crossings: Vec<(usize, usize, [Pierce; 2])> = found.into_iter().flatten().collect();
    let rays = Rays::new([a, b]);
    if crossings.is_empty() {
        // Each glued surface lies wholly on one side of the other boundary.
        let inside = |o: usize| {
            let op = [a, b][o];
            op.surfaces
                .iter()
                .map(|s| rays.inside_other(o, &op.points[op.tris[s.triangles[0]][0]]))
                .collect()
        };
        return Some(Transversal::Apart([inside(0), inside(1)]));
    }
    let mut points = exact_points(&a.points);
    points.extend(exact_points(&b.points));
    // The pierce points: each constructed once, on its edge's triangles and in its triangle.
    let mut index: HashMap<Pierce, usize> = HashMap::new();
    let mut pierces: Vec<Pierce> = Vec::new();
    let mut on_edge: HashMap<(usize, usize), Vec<usize>> = HashMap::new();
    let mut extra: Vec<Vec<usize>> = vec![Vec::new(); tris.len()];
    let mut cuts: Vec<Vec<(usize, usize)>> = vec![Vec::new(); tris.len()];
    let mut crossing_edges: HashSet<(usize, usize)> = HashSet::new();
    let first_pierce = points.len();
    for &(t, s, ends) in &crossings {
        let [p, q] = ends.map(|(edge, tri)| {
            *index.entry((edge, tri)).or_insert_with(|| {
                let v = first_pierce + pierces.len();
                pierces.push((edge, tri));
                on_edge.entry(edge).or_default().push(v);
                extra[tri].push(v);
                v
            })
        });
        cuts[t].push((p, q));
        cuts[s].push((p, q));
        crossing_edges.insert((p.min(q), p.max(q)));
    }
    points.extend(map_all(&pierces, parallel, |&(edge, tri)| {
        pierce(&f64s, edge, tris[tri])
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
    let cut: Vec<usize> = (0..tris.len())
        .filter(|&t| !extra[t].is_empty() || sides(t).iter().any(|side| !side.is_empty()))
        .collect();
    let parts: Vec<Vec<[usize; 3]>> = map_all(&cut, parallel, |&t| {
        let chart = Chart::of_f64_triangle(tris[t].map(|v| f64s[v]))?;
        let extra = extra[t].iter().copied();
        retriangulate(&points, tris[t], chart, sides(t), extra, &cuts[t], &()).ok()
    })
    .into_iter()
    .collect::<Option<_>>()?;
    let mut parts: HashMap<usize, Vec<[usize; 3]>> = cut.into_iter().zip(parts).collect();
    let mut pieces: Vec<([usize; 3], usize)> = Vec::with_capacity(tris.len());
    for (t, &tri) in tris.iter().enumerate() {
        match parts.remove(&t) {
            Some(part) => pieces.extend(part.into_iter().map(|piece| (piece, t))),
            None => pieces.push((tri, t)),
        }
    }
    let inside = inside(&pieces, &crossing_edges, &rays, parallel)?;
    let kept: Vec<[usize; 3]> = pieces
        .iter()
        .zip(&inside)
        .filter(|(_, &inside)| inside)
        .map(|((piece, _), _)| *piece)
        .collect();
    Some(Transversal::Crossing((points, kept)))
}

/// The edge `uv` as a key (smaller index first).
fn key(u: usize, v: usize) -> (usize, usize) {
    (u.min(v), u.max(v))
}

/// How triangles `t` and `s` (indices into `p`) meet, from orientations of their vertices.
/// Each plane must separate the other's vertices strictly; the line of the planes then meets
/// each triangle in a segment from one straddling edge to the other, and the ends of the
/// intersection are the pierce points of either triangle's straddling edges that lie strictly
/// inside the other's segment — left of both of its straddling edges, a sign that
/// orient3d(e₀, e₁, f₀, f₁) gives up to the side of f₁.
fn contact(p: &[[f64; 3]], (ti, t): (usize, [usize; 3]), (si, s): (usize, [usize; 3])) -> Contact {
    let o = |a: usize, b: usize, c: usize, d: usize| exact_orient3d_f64(p[a], p[b], p[c], p[d]);
    let s_sides = s.map(|v| o(t[0], t[1], t[2], v));
    let t_sides = t.map(|v| o(s[0], s[1], s[2], v));
    if one_side(&s_sides) || one_side(&t_sides) {
        return Contact::Apart;
    }
    if s_sides.contains(&Equal) || t_sides.contains(&Equal) {
        return Contact::Degenerate;
    }
    let mut ends = Vec::with_capacity(2);
    for (host, hi, host_sides, guest, guest_sides) in
        [(t, ti, t_sides, s, s_sides), (s, si, s_sides, t, t_sides)]
    {
        let host_edges = straddling(host, &host_sides);
        for (f, f1_side) in straddling(guest, &guest_sides) {
            let mut inside = true;
            for (e, _) in host_edges {
                match o(e.0, e.1, f.0, f.1) {
                    Equal => return Contact::Degenerate,
                    sign => inside &= sign == f1_side,
                }
            }
            if inside {
                ends.push((key(f.0, f.1), hi));
            }
        }
    }
    match ends[..] {
        [] => Contact::Apart,
        [x, y] => Contact::Cross([x, y]),
        _ => Contact::Degenerate,
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

/// The point where the edge `(u, v)` pierces the plane of the triangle `tri` (indices into the
/// `f64` points `p`), exactly: (du·V − dv·U) / (du − dv), du and dv the plane's values at U and
/// V, in integers after scaling every coordinate by one power of two
/// ([`Rational::section_point`]); the same value whichever triangle of the edge asks.
fn pierce(p: &[[f64; 3]], (u, v): (usize, usize), tri: [usize; 3]) -> Point3<Rational> {
    let parts = [u, v, tri[0], tri[1], tri[2]].map(|i| p[i].map(|x| x.integer_decode()));
    let low = parts
        .iter()
        .flatten()
        .filter(|(m, _, _)| *m != 0)
        .map(|(_, e, _)| i32::from(*e))
        .min()
        .unwrap_or(0);
    let int = |(m, e, sign): (u64, i16, i8)| match m {
        0 => BigInt::ZERO,
        _ => (BigInt::from(m) << (i32::from(e) - low)) * sign,
    };
    let [pu, pv, a, b, c] = parts.map(|q| q.map(int));
    let sub = |x: &[BigInt; 3], y: &[BigInt; 3]| [0, 1, 2].map(|k| &x[k] - &y[k]);
    let (ab, ac) = (sub(&b, &a), sub(&c, &a));
    let n = [
        &ab[1] * &ac[2] - &ab[2] * &ac[1],
        &ab[2] * &ac[0] - &ab[0] * &ac[2],
        &ab[0] * &ac[1] - &ab[1] * &ac[0],
    ];
    let value = |x: &[BigInt; 3]| {
        let d = sub(x, &a);
        &n[0] * &d[0] + &n[1] * &d[1] + &n[2] * &d[2]
    };
    let [x, y, z] = Rational::section_point(&value(&pu), &value(&pv), [&pu, &pv], low);
    Point3::new(x, y, z)
}

/// The bits of each field of a packed fin ([`fin`]).
const FIELD: u32 = 42;

/// The low [`FIELD`] bits.
const MASK: u128 = (1 << FIELD) - 1;

/// The edge `(u, v)` and the piece `i` at it as one integer that sorts by edge (each below
/// 2^[`FIELD`]).
fn fin((u, v): (usize, usize), i: usize) -> u128 {
    (u as u128) << (2 * FIELD) | (v as u128) << FIELD | i as u128
}

/// For each piece of the transversal arrangement of `ops` (each with its parent: operand 0's
/// triangles first, then operand 1's; over operand 0's points, operand 1's, then the pierce
/// points), true if it lies inside the other operand: patches joined across edges that are not
/// crossing segments, one ray from an input vertex per connected surface, the side flipped
/// across every crossing segment. `None` if the flips contradict each other or the rays (not a
/// transversal arrangement).
fn inside<N: Num>(
    pieces: &[([usize; 3], usize)],
    crossing: &HashSet<(usize, usize)>,
    rays: &Rays<N>,
    parallel: bool,
) -> Option<Vec<bool>> {
    let ops = rays.ops;
    let (points_a, first_b) = (ops[0].points.len(), ops[0].tris.len());
    let inputs = points_a + ops[1].points.len();
    let operand = |i: usize| usize::from(pieces[i].1 >= first_b);
    // Each piece's edges, grouped by edge: (edge, piece) packed in one integer and sorted.
    let too_big = |n: usize| n as u128 > MASK;
    if too_big(pieces.len()) || pieces.iter().flat_map(|p| p.0).any(too_big) {
        return None;
    }
    let mut fins: Vec<u128> = pieces
        .iter()
        .enumerate()
        .flat_map(|(i, (t, _))| (0..3).map(move |k| fin(key(t[k], t[(k + 1) % 3]), i)))
        .collect();
    if parallel {
        fins.par_sort_unstable();
    } else {
        fins.sort_unstable();
    }
    let edge = |f: &u128| ((f >> (2 * FIELD)) as usize, (f >> FIELD & MASK) as usize);
    let mut uf = UnionFind::new(pieces.len());
    let mut flips: Vec<(usize, usize)> = Vec::new();
    for at in fins.chunk_by(|x, y| x >> FIELD == y >> FIELD) {
        let across = crossing.contains(&edge(&at[0]));
        for o in 0..2 {
            let mut mine = at
                .iter()
                .map(|f| (f & MASK) as usize)
                .filter(|&i| operand(i) == o);
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
    let mut next: Vec<Vec<usize>> = vec![Vec::new(); pieces.len()];
    for (x, y) in flips {
        let (x, y) = (uf.find(x), uf.find(y));
        next[x].push(y);
        next[y].push(x);
    }
    let mut side: Vec<Option<bool>> = vec![None; pieces.len()];
    for (i, (piece, _)) in pieces.iter().enumerate() {
        let root = uf.find(i);
        if side[root].is_some() {
            continue;
        }
        let Some(&v) = piece.iter().find(|&&v| v < inputs) else {
            continue;
        };
        let o = operand(i);
        let q = &ops[o].points[if o == 0 { v } else { v - points_a }];
        side[root] = Some(rays.inside_other(o, q));
        let mut stack = vec![root];
        while let Some(x) = stack.pop() {
            let flipped = side[x].map(|s| !s);
            for &y in &next[x] {
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
/// triangle, later ones an R-tree of the other's boxes, built on first need.
struct Rays<'a, N: Num> {
    ops: [&'a Brep<N>; 2],
    trees: [OnceCell<TriBoxes>; 2],
    cast: Cell<usize>,
}

impl<'a, N: Num> Rays<'a, N> {
    fn new(ops: [&'a Brep<N>; 2]) -> Self {
        Rays {
            ops,
            trees: Default::default(),
            cast: Cell::new(0),
        }
    }

    /// True if `q`, a point of operand `o` off the other's boundary, lies inside the other.
    fn inside_other(&self, o: usize, q: &Point3<N>) -> bool {
        let other = self.ops[1 - o];
        self.cast.set(self.cast.get() + 1);
        let w = if self.cast.get() <= SCANNED_RAYS {
            winding(other.all_corners(), q, &N::exact_ctx())
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
    use crate::yin3::float::exact_set;
    use crate::yin3::set::compact;
    use crate::yin3::shapes::cuboid;
    use crate::yin3::YinSet3;
    use proptest::prelude::*;

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
        #![proptest_config(ProptestConfig::with_cases(64))]

        /// Jittered cubes that cross, nest or miss (the second operand also as its complement,
        /// unbounded, the first also with a second cube far away, and both scaled by 2^80):
        /// the transversal meet is taken and equals the general exact meet (a different
        /// algorithm: constructed contacts, point-in-triangle distribution, one ray per patch).
        #[test]
        fn equals_the_general_meet(
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
                let exact = ea.meet(&eb);
                prop_assert_eq!(fast.unwrap(), exact.clone());
                if let Some(Transversal::Apart(_)) = transversal_meet(fa.brep().unwrap(), fb.brep().unwrap()) {
                    // Nothing is rounded where the boundaries are apart: the float meet is exact.
                    let float = fa.try_meet(&fb).expect("a float meet");
                    prop_assert_eq!(exact_set(&float), exact);
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
                assert!(matches!(meet, Some(Transversal::Apart(_))));
                let float = fa.try_meet(&fb).expect("a float meet");
                assert_eq!(exact_set(&float), ea.meet(&eb));
            }
        }
    }

    /// Overlapping coplanar faces, a shared vertex and a vertex on a face are declined.
    #[test]
    fn declines_degenerate_pairs() {
        let still = [[0.0; 3]; 8];
        let a = solid::<Float>(&jittered_cube([0.0; 3], 1.0, &still));
        let mut down = still;
        down[0] = [0.0, 0.0, -0.2];
        for (o, jitter) in [
            ([0.5, 0.5, 0.0], still),
            ([1.0; 3], still),
            ([0.3, 0.3, 1.2], down),
        ] {
            let b = solid::<Float>(&jittered_cube(o, 1.0, &jitter));
            assert!(transversal(&a, &b).is_none(), "offset {o:?}");
        }
    }
}
