//! Whether rounding a result's vertices to `f64` kept its topology (yin3 docs: *Float mode*):
//! [`Topology`], compared between the exact and the rounded boundary, and [`provably_kept`],
//! a sufficient test that needs no exact structure.

use super::betti::{corners_at, Betti3, Links};
use super::fins::{FinTable, Pairing};
use super::glue::{corner_cycles, glued_surfaces};
use super::set::Brep;
use crate::kernel::Point3;
use crate::num::{Num, Rational};
use crate::union_find::UnionFind;
use std::cell::OnceCell;

/// What rounding must keep of a set: the [`Invariants`] of the set and of its complement. The
/// set's alone do not fix the complement's: two pieces that rounding makes touch in two places
/// are still two pieces with the same surfaces, while their complement gains a tunnel.
#[derive(Debug, PartialEq)]
pub(crate) struct Topology {
    set: Invariants,
    complement: Invariants,
}

/// Boundedness, the Betti numbers, and each glued surface's orientation, genus and depth in the
/// Hasse diagram (seed 003 Def. 7.3, 7.6), sorted.
#[derive(Debug, PartialEq)]
struct Invariants {
    bounded: bool,
    betti: Betti3,
    surfaces: Vec<(bool, usize, usize)>,
}

impl Topology {
    /// The topology of the set bounded by `b`.
    pub(crate) fn of<N: Num>(b: &Brep<N>) -> Topology {
        Topology {
            set: Invariants::of(b),
            complement: Invariants::of(&b.complement()),
        }
    }
}

impl Invariants {
    /// The invariants of the set bounded by `b`.
    fn of<N: Num>(b: &Brep<N>) -> Invariants {
        let depth = |mut s: usize| {
            let mut d = 0;
            while let Some(p) = b.parent[s] {
                (s, d) = (p, d + 1);
            }
            d
        };
        let mut surfaces: Vec<_> = (b.surfaces.iter().enumerate())
            .map(|(s, g)| (g.positive, g.genus, depth(s)))
            .collect();
        surfaces.sort_unstable();
        Invariants {
            bounded: b.bounded,
            betti: b.betti(),
            surfaces,
        }
    }
}

impl std::fmt::Display for Topology {
    fn fmt(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
        write!(f, "{}; complement {}", self.set, self.complement)
    }
}

impl std::fmt::Display for Invariants {
    fn fmt(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
        let Betti3 { b0, b1, b2 } = self.betti;
        let pos = self.surfaces.iter().filter(|s| s.0).count();
        let neg = self.surfaces.len() - pos;
        let bounded = if self.bounded { "bounded" } else { "unbounded" };
        write!(
            f,
            "{bounded}, Betti ({b0}, {b1}, {b2}), {pos} positive and {neg} negative glued surfaces"
        )
    }
}

/// The unit roundoff of `f64`, 2⁻⁵³.
const U: f64 = f64::EPSILON / 2.0;

/// True only if the rounded boundary `b` — the exact boundary's very triangles over the points
/// `exact`, each vertex moved to its nearest `f64`, or those triangles after the merges
/// `merges` — has the exact boundary's [`Topology`]. `exact_table` is the exact boundary's fin
/// table where it was built (of the very triangles, numbered alike).
/// Sufficient: the exact boundary is valid, the rounded one conforming (I1–I3; with two fins at
/// every edge its windings, I4, then follow from what is shown here, `float::Shown::Conforming`),
/// and the fins of every edge turn about it in the same order on both (with two fins, always),
/// so the pairings, glued surfaces and corner cycles of the set and of its complement are the
/// same, and the topology of each is its surfaces' orientations, which of its surfaces lie
/// inside which, and at each vertex whose link has several components the faces of its link in
/// 𝒴 (r_p, [`Links::term`]; such a vertex has several corner cycles, and the complement's
/// r_p is the link's faces minus the set's: equal counts for the set mean equal counts for the
/// complement). Each surface's signed volume (positive iff it is positively oriented, Def. 7.3)
/// must be farther from 0 than rounding and the `f64` sum can move it; two surfaces of one
/// family whose boxes come within twice the rounding of each other (both move) must each have a
/// vertex off the other and farther from each of its triangles than twice the rounding (then
/// moving every vertex, that one too, straight from its exact to its rounded place never moves
/// the surface through that vertex, so the winding number about it is kept; in both versions
/// the surfaces meet only in shared vertices and edges without crossing — at a shared edge each
/// one's two fins are neighbours in the common order — so that winding number is the one about
/// every other point of the surface: nesting); surfaces farther apart are nested in neither
/// version; and the link terms are compared exactly where a vertex has several corner cycles.
///
/// Where rounding merged vertices, `merges` ([`Merges::of`]) shows the rounded triangles to be
/// the exact ones after independent edge collapses that keep each surface's type, its corner
/// cycles away from the collapses and each Euler characteristic (a collapse takes one vertex,
/// three edges and two triangles); `exact` then gives a merged vertex one of its two exact
/// values, read nowhere: no vertex with several corner cycles may lie in a collapse's star.
/// The collapsed triangles are counted in the volume bounds (they end degenerate, their terms
/// 0), and a witness stays beyond each of them, which ends inside a kept triangle's box.
pub(crate) fn provably_kept<N: Num>(
    b: &Brep<N>,
    exact: &[Point3<Rational>],
    exact_table: Option<&FinTable>,
    merges: &Merges,
) -> bool {
    // The fin table (built on the rounded points) must be the exact points' own, so that both
    // pair the same fins: with two fins at every edge there is no order to sort; with more,
    // the exact boundary's table, where given, must be the same, else each edge's order is
    // sorted again on the exact points (and merges, which Merges::of shows for two fins, are
    // refused).
    let many = b.table.fin_lists().any(|f| f.len() != 2);
    let order_kept = || match exact_table {
        Some(table) => *table == b.table,
        None => b.table.order_kept(exact, &()),
    };
    if many && (merges.collapsed > 0 || !order_kept()) {
        return false;
    }
    let mut cycles = corner_cycles(&b.table, &b.tris, None, Pairing::Inside);
    let mut cycle_at = vec![usize::MAX; b.points.len()];
    let mut pinched = Vec::new();
    for (t, tri) in b.tris.iter().enumerate() {
        for (k, &v) in tri.iter().enumerate() {
            let c = cycles.find(3 * t + k);
            if cycle_at[v] == usize::MAX {
                cycle_at[v] = c;
            } else if cycle_at[v] != c {
                if merges.near.get(v).copied().unwrap_or(false) {
                    return false;
                }
                pinched.push(v);
            }
        }
    }
    let Some((p, moved)) = scaled(&b.points) else {
        return false;
    };
    let set: Vec<&[usize]> = b.surfaces.iter().map(|s| &s.triangles[..]).collect();
    // With more than two fins at an edge the complement's glued surfaces may not be the set's.
    surfaces_kept(&p, &b.tris, &set, merges, moved)
        && (!many || surfaces_kept(&p, &b.tris, &complement_surfaces(b), merges, moved))
        && links_kept(b, exact, pinched, cycles)
}

/// The points `points` as `f64`s scaled by a power of two to below 2, and how far each scaled
/// coordinate may lie from its exact value's, scaled alike, when both are the nearest `f64`s
/// of exact values (`None` where every coordinate is 0).
fn scaled<N: Num>(points: &[Point3<N>]) -> Option<(Vec<[f64; 3]>, f64)> {
    let p: Vec<[f64; 3]> = points.iter().map(|q| q.to_f64()).collect();
    let largest = p.iter().flatten().fold(0.0f64, |m, c| m.max(c.abs()));
    if largest == 0.0 {
        return None;
    }
    // Scaled by a power of two to below 2 (exact, or off by a subnormal's half ulp where a
    // tiny coordinate beside a huge one underflows), so that no product overflows.
    let k = -(largest.log2().floor() as i32);
    let p: Vec<[f64; 3]> = p.iter().map(|v| v.map(|c| times_pow2(c, k))).collect();
    // Each exact coordinate is within half an ulp of its rounding: at most u times its
    // magnitude, or half a subnormal ulp (scaled by 2^k with the rest); the scaled rounding
    // is within half a subnormal ulp more.
    let tiny = f64::from_bits(1);
    Some((
        p,
        2.0 * U * times_pow2(largest, k) + times_pow2(tiny, k) + tiny,
    ))
}

/// The glued surfaces of the complement of the set bounded by `b` (Pairing::Outside), each
/// its triangles in increasing order.
fn complement_surfaces<N: Num>(b: &Brep<N>) -> Vec<Vec<usize>> {
    let (label, count) = glued_surfaces(&b.table, b.tris.len(), Pairing::Outside);
    let mut surfaces = vec![Vec::new(); count];
    for (t, &l) in label.iter().enumerate() {
        surfaces[l].push(t);
    }
    surfaces
}

/// True if the glued `surfaces` (each its triangles, of `tris` over the scaled rounded points
/// `p`, which moved by up to `moved` from the exact ones) keep their orientations and which lie
/// inside which ([`provably_kept`]).
fn surfaces_kept<S: AsRef<[usize]>>(
    p: &[[f64; 3]],
    tris: &[[usize; 3]],
    surfaces: &[S],
    merges: &Merges,
    moved: f64,
) -> bool {
    let boxes: Vec<[[f64; 3]; 2]> = (surfaces.iter())
        .map(|s| corners_box(p, s.as_ref().iter().flat_map(|&t| tris[t])))
        .collect();
    // A difference of f64s above 4·moved is, exactly, above 2·moved.
    let gap = 4.0 * moved;
    let near: Vec<OnceCell<Near>> = surfaces.iter().map(|_| OnceCell::new()).collect();
    let near = |s: usize| near[s].get_or_init(|| Near::of(p, tris, surfaces[s].as_ref()));
    close_pairs(&boxes, gap)
        .iter()
        .all(|&(s, t)| witnessed(p, near(s), near(t), gap) && witnessed(p, near(t), near(s), gap))
        && surfaces.iter().zip(&boxes).all(|(s, bx)| {
            let tris = s.as_ref().iter().map(|&t| tris[t]);
            volume_sign_kept(p, tris, merges.collapsed, bx, moved)
        })
}

/// Vertices of an exact boundary that rounding merged, shown to be independent edge collapses
/// that keep the topology of each glued surface (Dey, Edelsbrunner, Guha, Nekhayev, "Topology
/// preserving edge contraction", 1999: on a closed surface, contracting the edge ab keeps the
/// surface's type iff Lk a ∩ Lk b = Lk ab).
pub(crate) struct Merges {
    /// How many triangles collapsed (two per merge).
    collapsed: usize,
    /// For each vertex of the rounded boundary, whether it is in a collapse's star: a merged
    /// vertex or one of its neighbours.
    near: Vec<bool>,
}

impl Merges {
    /// No merges.
    pub(crate) fn none() -> Merges {
        Merges {
            collapsed: 0,
            near: Vec::new(),
        }
    }

    /// The merges that took the exact triangles `tris` (points `exact`) to a rounded boundary
    /// of `rounded` vertices, vertex `v` becoming its vertex `to[v]`, with an exact value of
    /// each rounded vertex (the first of a merged pair's); `None` unless every merge is two
    /// vertices a, b joined by an edge with exactly two triangles abc and abd, whose common
    /// neighbours are c and d alone and that are not both corners of triangles acd and bcd (the
    /// link condition on a closed surface, where [`provably_kept`] shows every rounded edge has
    /// two fins and the merged vertex one corner cycle), and no two merges share a vertex of
    /// their stars (so each keeps the condition for the next).
    pub(crate) fn of(
        rounded: usize,
        tris: &[[usize; 3]],
        to: &[usize],
        exact: &[Point3<Rational>],
    ) -> Option<(Merges, Vec<Point3<Rational>>)> {
        let mut first = vec![usize::MAX; rounded];
        let mut pairs = Vec::new();
        for (v, &w) in to.iter().enumerate() {
            if first[w] == usize::MAX {
                first[w] = v;
            } else {
                pairs.push((first[w], v));
            }
        }
        // The triangles at each merged vertex (the `2i`th and `2i + 1`st for the `i`th pair).
        let mut slot = vec![usize::MAX; to.len()];
        for (i, &(x, y)) in pairs.iter().enumerate() {
            (slot[x], slot[y]) = (2 * i, 2 * i + 1);
        }
        let at = corners_at(tris, 2 * pairs.len(), |v| {
            Some(slot[v]).filter(|&i| i != usize::MAX)
        });
        let with_vertex = |v: usize| at[slot[v]].iter().map(|c| c / 3);
        let neighbours = |v: usize| {
            let mut n: Vec<usize> = with_vertex(v)
                .flat_map(|t| tris[t])
                .filter(|&w| w != v)
                .collect();
            n.sort_unstable();
            n.dedup();
            n
        };
        let is_triangle = |[x, y, z]: [usize; 3]| {
            with_vertex(x).any(|t| tris[t].contains(&y) && tris[t].contains(&z))
        };
        let mut near = vec![false; rounded];
        for &(x, y) in &pairs {
            let (nx, ny) = (neighbours(x), neighbours(y));
            let common: Vec<usize> = (nx.iter())
                .filter(|w| ny.binary_search(w).is_ok())
                .copied()
                .collect();
            let at_edge = with_vertex(x).filter(|&t| tris[t].contains(&y)).count();
            let [c, d] = common[..] else { return None };
            if at_edge != 2 || is_triangle([x, c, d]) && is_triangle([y, c, d]) {
                return None;
            }
            let mut star: Vec<usize> = nx.into_iter().chain(ny).map(|w| to[w]).collect();
            star.sort_unstable();
            star.dedup();
            if star
                .into_iter()
                .any(|w| std::mem::replace(&mut near[w], true))
            {
                return None;
            }
        }
        let values = first.iter().map(|&v| exact[v].clone()).collect();
        let merges = Merges {
            collapsed: 2 * pairs.len(),
            near,
        };
        Some((merges, values))
    }
}

/// The tetrahedron 0123 with a vertex 4 on its edge 01: the triangles of the tests of merges
/// in rounding.
#[cfg(test)]
pub(super) const SPLIT_TETRAHEDRON: [[usize; 3]; 6] = [
    [0, 2, 4],
    [4, 2, 1],
    [0, 4, 3],
    [4, 1, 3],
    [0, 3, 2],
    [1, 2, 3],
];

/// True if at each of the vertices `pinched` (with several corner cycles; duplicates allowed)
/// the link term 2 r_p − l_p of `b` is the same on its exact points `exact` and on its rounded
/// ones ([`Links::term`]); everywhere else r_p = l_p on both. `cycles` are `b`'s 𝒴-cycles.
fn links_kept<N: Num>(
    b: &Brep<N>,
    exact: &[Point3<Rational>],
    mut pinched: Vec<usize>,
    cycles: UnionFind,
) -> bool {
    if pinched.is_empty() {
        return true;
    }
    pinched.sort_unstable();
    pinched.dedup();
    let mut slot = vec![None; b.points.len()];
    for (i, &p) in pinched.iter().enumerate() {
        slot[p] = Some(i);
    }
    let at = corners_at(&b.tris, pinched.len(), |v| slot[v]);
    let mut links = Links::new(&b.tris, &b.table, cycles);
    (pinched.iter().zip(&at)).all(|(&p, corners)| {
        links.term(exact, &b.tris, p, corners) == links.term(&b.points, &b.tris, p, corners)
    })
}

/// The box `[min, max]` of the points `p[v]` for the indices `v`.
fn corners_box(p: &[[f64; 3]], vertices: impl Iterator<Item = usize>) -> [[f64; 3]; 2] {
    let mut bx = [[f64::INFINITY; 3], [f64::NEG_INFINITY; 3]];
    for v in vertices {
        for k in 0..3 {
            bx[0][k] = bx[0][k].min(p[v][k]);
            bx[1][k] = bx[1][k].max(p[v][k]);
        }
    }
    bx
}

/// Vertices of a surface tried as witnesses that it lies off another ([`witnessed`]).
const WITNESS_TRIES: usize = 8;

/// A surface's vertices (sorted, each once) and its triangles' boxes, for [`witnessed`].
struct Near {
    vertices: Vec<usize>,
    boxes: Vec<[[f64; 3]; 2]>,
}

impl Near {
    /// The vertices and triangle boxes of the surface of `triangles` (points `p`).
    fn of(p: &[[f64; 3]], tris: &[[usize; 3]], triangles: &[usize]) -> Near {
        let mut vertices: Vec<usize> = triangles.iter().flat_map(|&u| tris[u]).collect();
        vertices.sort_unstable();
        vertices.dedup();
        let boxes = (triangles.iter())
            .map(|&u| corners_box(p, tris[u].into_iter()))
            .collect();
        Near { vertices, boxes }
    }
}

/// True if one of the first [`WITNESS_TRIES`] vertices of the surface `s` that are not
/// vertices of the surface `t` lies, on some axis, more than `gap` beyond the box of each
/// triangle of `t` (points `p`).
fn witnessed(p: &[[f64; 3]], s: &Near, t: &Near, gap: f64) -> bool {
    (s.vertices.iter())
        .filter(|v| t.vertices.binary_search(v).is_err())
        .take(WITNESS_TRIES)
        .any(|&v| {
            let q = p[v];
            (t.boxes.iter())
                .all(|bx| (0..3).any(|k| q[k] - bx[1][k] > gap || bx[0][k] - q[k] > gap))
        })
}

/// The pairs of the boxes `[min, max]` that come within `gap` of each other on every axis: a
/// sweep along x, each box compared with those whose x-range reaches it.
fn close_pairs(boxes: &[[[f64; 3]; 2]], gap: f64) -> Vec<(usize, usize)> {
    let mut order: Vec<usize> = (0..boxes.len()).collect();
    order.sort_by(|&i, &j| boxes[i][0][0].total_cmp(&boxes[j][0][0]));
    let close = |x: &[[f64; 3]; 2], y: &[[f64; 3]; 2]| {
        (0..3).all(|k| x[1][k] + gap >= y[0][k] && y[1][k] + gap >= x[0][k])
    };
    let (mut reaching, mut pairs): (Vec<usize>, Vec<(usize, usize)>) = (Vec::new(), Vec::new());
    for i in order {
        reaching.retain(|&j| boxes[j][1][0] + gap >= boxes[i][0][0]);
        pairs.extend(
            (reaching.iter())
                .filter(|&&j| close(&boxes[i], &boxes[j]))
                .map(|&j| (j, i)),
        );
        reaching.push(i);
    }
    pairs
}

/// c·2^k, in steps that neither overflow nor underflow on the way.
fn times_pow2(c: f64, k: i32) -> f64 {
    let step = |c: f64, k: i32| c * 2f64.powi(k);
    let half = k / 2;
    step(step(c, half), k - half)
}

/// Whether the signed volume of the closed surface of triangles `tris` over the points `p`
/// (inside the box `bx`) has the sign it had before every coordinate moved by up to `moved`:
/// 6V = Σ det(a − o, b − o, c − o) for any origin o, here the box's low corner; each
/// determinant moves by at most 6((M + 2δ)³ − (M + δ)³) = 6(3M²δ + 9Mδ² + 7δ³) when its
/// vectors (at most M in each coordinate) move by δ, and the `f64` sum of n determinants errs
/// by at most (n + 16)·2u times the sum of the absolute values of their products.
/// `collapsed` more triangles, degenerate on `p` (their terms 0), count in the geometric bound.
fn volume_sign_kept(
    p: &[[f64; 3]],
    tris: impl Iterator<Item = [usize; 3]>,
    collapsed: usize,
    bx: &[[f64; 3]; 2],
    moved: f64,
) -> bool {
    let o = bx[0];
    let m = (0..3).fold(0.0f64, |m, k| m.max(bx[1][k] - o[k])) * (1.0 + 4.0 * U);
    let (mut sum, mut magnitude, mut n) = (0.0, 0.0, collapsed as f64);
    for [i, j, k] in tris {
        let d = |v: usize| [0, 1, 2].map(|c| p[v][c] - o[c]);
        let (a, b, c) = (d(i), d(j), d(k));
        let terms = [
            a[0] * b[1] * c[2],
            -a[0] * b[2] * c[1],
            a[1] * b[2] * c[0],
            -a[1] * b[0] * c[2],
            a[2] * b[0] * c[1],
            -a[2] * b[1] * c[0],
        ];
        sum += terms.iter().sum::<f64>();
        magnitude += terms.iter().map(|t| t.abs()).sum::<f64>();
        n += 1.0;
    }
    let d = moved;
    let geometric = n * 6.0 * (3.0 * m * m * d + 9.0 * m * d * d + 7.0 * d * d * d);
    let arithmetic = (n + 16.0) * 2.0 * U * magnitude;
    sum.abs() > 1.01 * (geometric + arithmetic)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::kernel::Point3;
    use crate::num::{Float, Tolerance};
    use crate::yin3::shapes::{concat, cuboid};
    use crate::yin3::values::{exact_point, exact_points};
    use crate::yin3::YinSet3;

    /// The float set bounded by the boxes `[lo, hi]` (each reversed if `hi < lo` on x).
    fn boxes_set(corners: &[([f64; 3], [f64; 3])]) -> YinSet3<Float> {
        let p = |v: [f64; 3]| Point3::new(Float::new(v[0]), Float::new(v[1]), Float::new(v[2]));
        let (v, f) = concat(
            corners
                .iter()
                .map(|(lo, hi)| cuboid(&p(*lo), &p(*hi)))
                .collect(),
        );
        YinSet3::from_triangles_with(v, f, Tolerance::new(0.0)).expect("valid boxes")
    }

    fn boxes(corners: &[([f64; 3], [f64; 3])]) -> Brep<Float> {
        boxes_set(corners).brep().expect("a boundary").clone()
    }

    /// [`provably_kept`] of a boundary whose vertices did not move.
    fn kept(b: &Brep<Float>) -> bool {
        provably_kept(b, &exact_points(&b.points), None, &Merges::none())
    }

    /// Unit cubes (0,0,0) and (1,1,0) meet at an edge, joined also through (0,0,1), (0,1,1)
    /// and (1,1,1): one glued surface with four fins on that edge, not a closed manifold,
    /// provable where its fins turn in the same order about the edge on the exact points;
    /// not where an exact apex lies elsewhere in that order (sorted again, or in the exact
    /// boundary's table).
    #[test]
    fn a_surface_through_an_edge_is_provable_where_its_fins_keep_their_order() {
        let cube = |c: [f64; 3]| boxes_set(&[(c, c.map(|x| x + 1.0))]);
        let cells = [
            [0.0, 0.0, 1.0],
            [0.0, 1.0, 1.0],
            [1.0, 1.0, 1.0],
            [1.0, 1.0, 0.0],
        ];
        let y = (cells.iter()).fold(cube([0.0; 3]), |y, &c| y.try_join(&cube(c)).expect("join"));
        assert_eq!(y.surfaces().len(), 1);
        let b = y.brep().expect("a boundary");
        assert!(b.table.fin_lists().any(|f| f.len() == 4));
        assert!(kept(b));
        // The apexes of (1,1,0)'s face on y = 1 at the edge x = y = 1, z in [0, 1], moved
        // between the fins of (0,0,0)'s faces: the order about that edge changes.
        let mut exact = exact_points(&b.points);
        for (e, q) in exact.iter_mut().zip(&b.points) {
            if let [2.0, 1.0, z] = q.to_f64() {
                if z <= 1.0 {
                    let p = Point3::new(Float::new(0.5), Float::new(0.25), Float::new(z));
                    *e = exact_point(&p);
                }
            }
        }
        let table = FinTable::new(&exact, &b.tris, &());
        assert_ne!(table, b.table);
        assert!(!provably_kept(b, &exact, None, &Merges::none()));
        assert!(!provably_kept(b, &exact, Some(&table), &Merges::none()));
    }

    /// Ten cells of a 3 × 3 × 3 grid whose middle layer on x is `t` thick, touching along
    /// edges (found by a search over random cells): the set's two glued surfaces are at least
    /// 1 thick and pass, but the complement's surfaces (Pairing::Outside) are others, one of
    /// them in the middle layer, which at 10⁻¹³ is thinner than rounding: not provable.
    #[test]
    fn the_complements_surfaces_are_checked_where_they_are_not_the_sets() {
        let cells = [
            [0, 1, 1],
            [1, 0, 1],
            [1, 1, 0],
            [1, 1, 2],
            [1, 2, 0],
            [1, 2, 1],
            [1, 2, 2],
            [2, 0, 1],
            [2, 1, 1],
            [2, 2, 1],
        ];
        let grid = |t: f64| {
            let x = [0.0, 1.0, 1.0 + t, 2.0 + t];
            let cell = |[i, j, k]: [usize; 3]| {
                let lo = [x[i], j as f64, k as f64];
                boxes_set(&[(lo, [x[i + 1], lo[1] + 1.0, lo[2] + 1.0])])
            };
            let y = (cells.iter()).fold(YinSet3::empty(), |y, &c| {
                y.try_join(&cell(c)).expect("join")
            });
            y.brep().expect("a boundary").clone()
        };
        let b = grid(1e-13);
        let set: Vec<&[usize]> = b.surfaces.iter().map(|s| &s.triangles[..]).collect();
        let complement = complement_surfaces(&b);
        assert_eq!((set.len(), complement.len()), (2, 2));
        assert!(complement.iter().any(|c| !set.contains(&&c[..])));
        let (p, moved) = scaled(&b.points).expect("coordinates off 0");
        assert!(surfaces_kept(&p, &b.tris, &set, &Merges::none(), moved));
        assert!(!surfaces_kept(
            &p,
            &b.tris,
            &complement,
            &Merges::none(),
            moved
        ));
        assert!(!kept(&b));
    }

    #[test]
    fn a_box_far_from_flat_keeps_its_topology() {
        assert!(kept(&boxes(&[([0.0; 3], [1.0; 3])])));
        assert!(kept(&boxes(&[([1e300; 3], [1.5e300; 3])])));
    }

    /// A box thinner than what rounding its vertices could move it by: its orientation is not
    /// provable (the sign of the volume is the exact result's only if nothing moved).
    #[test]
    fn a_sliver_thinner_than_rounding_is_not_provable() {
        let thin = 1.0 + 4.0 * f64::EPSILON;
        assert!(!kept(&boxes(&[([0.0, 0.0, 1.0], [1.0, 1.0, thin])])));
        assert!(kept(&boxes(&[([0.0, 0.0, 1.0], [1.0, 1.0, 1.0 + 1e-9])])));
        // Subnormal coordinates: one ulp (2⁻¹⁰⁷⁴) thick is within the rounding, 2⁻¹⁰⁴⁰ = 2³⁴
        // ulps is not (written by its bits: unoptimised, `powi` gives 0 for it).
        let (lo, ulp) = (1e-310, f64::from_bits(1));
        let slab = |top: f64| boxes(&[([0.0, 0.0, lo], [lo, lo, top])]);
        assert!(!kept(&slab(lo + ulp)));
        assert!(kept(&slab(lo + f64::from_bits(1 << 34))));
    }

    /// Two boxes apart are provable, and so are a box in the other's cavity, boxes sharing an
    /// edge (four fins on it) and boxes that nearly touch, each with a vertex off the other
    /// beyond rounding; a cavity within rounding of its outer box all round is not.
    #[test]
    fn nesting_and_contact_are_provable_beyond_rounding() {
        assert!(kept(&boxes(&[([0.0; 3], [1.0; 3]), ([2.0; 3], [3.0; 3])])));
        let cavity = ([4.0, 1.0, 1.0], [1.0, 4.0, 4.0]);
        assert!(kept(&boxes(&[([0.0; 3], [5.0; 3]), cavity])));
        let edge = ([1.0, 1.0, 0.0], [2.0, 2.0, 1.0]);
        assert!(kept(&boxes(&[([0.0; 3], [1.0; 3]), edge])));
        let near = ([1.0 + f64::EPSILON, 0.0, 0.0], [2.0, 1.0, 1.0]);
        assert!(kept(&boxes(&[([0.0; 3], [1.0; 3]), near])));
        let hugging = |d: f64| {
            boxes(&[
                ([0.0; 3], [1.0; 3]),
                ([1.0 - d, d, d], [d, 1.0 - d, 1.0 - d]),
            ])
        };
        assert!(!kept(&hugging(f64::EPSILON)));
        assert!(kept(&hugging(1e-9)));
    }

    /// A cavity within rounding of five walls of [0, 10]³ but half the box away from its top:
    /// every vertex of the cavity is within rounding of a wall's triangles (x is 2⁻⁴⁸ from 0 or
    /// 10), while the top vertices of the outer box are far from the cavity. Each of two close
    /// surfaces must have a vertex off the other, so this is not provable; 10⁻⁶ off is.
    #[test]
    fn close_surfaces_must_each_have_a_vertex_off_the_other() {
        let cavity = |d: f64| ([10.0 - d, d, d], [d, 10.0 - d, 5.0]);
        assert!(!kept(&boxes(&[
            ([0.0; 3], [10.0; 3]),
            cavity(2f64.powi(-48))
        ])));
        assert!(kept(&boxes(&[([0.0; 3], [10.0; 3]), cavity(1e-6)])));
    }

    /// [`volume_sign_kept`] of the cube [0, s]³ (its box's low corner the origin) under moves up
    /// to `moved`.
    fn cube_sign_kept(s: f64, moved: f64) -> bool {
        let b = boxes(&[([0.0; 3], [s; 3])]);
        let p: Vec<[f64; 3]> = b.points.iter().map(Point3::to_f64).collect();
        let tris = b.surfaces[0].triangles.iter().map(|&t| b.tris[t]);
        volume_sign_kept(&p, tris, 0, &[[0.0; 3], [s; 3]], moved)
    }

    /// Moves of up to 1 can flatten the cube [0, 1.5]³ (its top and bottom each moved 0.75 to
    /// the middle), so its volume's sign is not kept; they cannot flatten [0, 100]³.
    #[test]
    fn a_volume_sign_is_not_kept_where_moves_can_flatten_the_surface() {
        assert!(!cube_sign_kept(1.5, 1.0));
        assert!(cube_sign_kept(100.0, 1.0));
    }

    /// The inside-out regular tetrahedron on (0,0,0), (0,1,1), (1,0,1), (1,1,0) (6V = −2: the
    /// normal of its first triangle, (1, 1, −1), points to the fourth corner) keeps its
    /// volume's sign under moves up to 10⁻⁶.
    #[test]
    fn an_inside_out_tetrahedron_keeps_its_volume_sign() {
        let p = [[0.0; 3], [0.0, 1.0, 1.0], [1.0, 0.0, 1.0], [1.0, 1.0, 0.0]];
        let tris = [[0, 1, 2], [0, 3, 1], [0, 2, 3], [2, 1, 3]];
        assert!(volume_sign_kept(
            &p,
            tris.into_iter(),
            0,
            &[[0.0; 3], [1.0; 3]],
            1e-6
        ));
    }

    /// The torus grid of `k` × `k` vertices (i, j) numbered k·i + j, each square
    /// (i, j)–(i + 1, j + 1) cut along that diagonal: the edge (i, j)–(i + 1, j) has the fins at
    /// (i + 1, j + 1) and (i, j − 1) and no other common neighbours.
    fn torus(k: usize) -> Vec<[usize; 3]> {
        let v = |i: usize, j: usize| k * (i % k) + j % k;
        (0..k * k)
            .flat_map(|q| {
                let (i, j) = (q / k, q % k);
                [
                    [v(i, j), v(i + 1, j), v(i + 1, j + 1)],
                    [v(i, j), v(i + 1, j + 1), v(i, j + 1)],
                ]
            })
            .collect()
    }

    /// [`Merges::of`] on the triangles `tris`, merging the vertices `pairs` (the other vertices
    /// numbered in order after): the collapsed triangles and how many rounded vertices are in
    /// a collapse's star.
    fn merges_of(tris: &[[usize; 3]], pairs: &[(usize, usize)]) -> Option<(usize, usize)> {
        let n = tris.iter().flatten().max().map_or(0, |m| m + 1);
        let mut to = vec![usize::MAX; n];
        for &(x, y) in pairs {
            to[x] = x.min(y);
            to[y] = x.min(y);
        }
        let mut next = 0;
        for v in 0..n {
            if to[v] == usize::MAX || to[v] == v {
                to[v] = next;
                next += 1;
            } else {
                to[v] = to[to[v]];
            }
        }
        let exact = vec![Point3::int(0, 0, 0); n];
        Merges::of(next, tris, &to, &exact).map(|(m, values)| {
            assert_eq!(values.len(), next);
            (m.collapsed, m.near.iter().filter(|&&x| x).count())
        })
    }

    /// Merging the split vertex with a corner of its edge collapses two triangles and meets the
    /// link condition, and so does merging 0 and 2 (sharing the neighbours 3 and 4, which
    /// the triangle 043 but no triangle 243 joins): every rounded vertex is in the star. Merging
    /// two vertices sharing three neighbours (2 and 3), two not joined by an edge (0 and 1), or
    /// two corners of a plain tetrahedron (their common neighbours joined to both) does not.
    /// On a 6 × 6 torus grid two collapses whose stars (nine rounded vertices each) are apart
    /// are merges, two whose stars share a vertex are not, though each alone is.
    #[test]
    fn only_independent_collapses_under_the_link_condition_are_merges() {
        assert_eq!(merges_of(&SPLIT_TETRAHEDRON, &[(0, 4)]), Some((2, 4)));
        assert_eq!(merges_of(&SPLIT_TETRAHEDRON, &[(1, 4)]), Some((2, 4)));
        assert_eq!(merges_of(&SPLIT_TETRAHEDRON, &[(0, 2)]), Some((2, 4)));
        assert_eq!(merges_of(&SPLIT_TETRAHEDRON, &[(2, 3)]), None);
        assert_eq!(merges_of(&SPLIT_TETRAHEDRON, &[(0, 1)]), None);
        let plain = [[0, 1, 2], [0, 3, 1], [0, 2, 3], [2, 1, 3]];
        assert_eq!(merges_of(&plain, &[(0, 1)]), None);
        let grid = torus(6);
        let v = |i: usize, j: usize| 6 * i + j;
        assert_eq!(merges_of(&grid, &[(v(0, 0), v(1, 0))]), Some((2, 9)));
        assert_eq!(merges_of(&grid, &[(v(2, 1), v(3, 1))]), Some((2, 9)));
        let apart = [(v(0, 0), v(1, 0)), (v(3, 3), v(4, 3))];
        assert_eq!(merges_of(&grid, &apart), Some((4, 18)));
        let touching = [(v(0, 0), v(1, 0)), (v(2, 1), v(3, 1))];
        assert_eq!(merges_of(&grid, &touching), None);
    }

    /// Two boxes sharing only a corner are provable ([`boxes_touching_in_a_corner_are_provable`])
    /// but not where that vertex, with two corner cycles, is in a collapse's star.
    #[test]
    fn a_vertex_with_several_corner_cycles_in_a_collapse_is_not_provable() {
        let b = boxes(&[([0.0; 3], [1.0; 3]), ([1.0; 3], [2.0; 3])]);
        let exact = exact_points(&b.points);
        let corner = (b.points.iter())
            .position(|p| p.to_f64() == [1.0; 3])
            .expect("the shared corner");
        let mut near = vec![false; b.points.len()];
        assert!(provably_kept(
            &b,
            &exact,
            None,
            &Merges {
                collapsed: 0,
                near: near.clone()
            }
        ));
        near[corner] = true;
        assert!(!provably_kept(
            &b,
            &exact,
            None,
            &Merges { collapsed: 0, near }
        ));
    }

    /// Two boxes sharing only a corner: that vertex has two corner cycles, whose link is
    /// compared between the exact and the rounded points.
    #[test]
    fn boxes_touching_in_a_corner_are_provable() {
        assert!(kept(&boxes(&[([0.0; 3], [1.0; 3]), ([1.0; 3], [2.0; 3])])));
    }

    /// The sweep finds a close pair that is not consecutive along x (a long box, one apart
    /// from it in y whose x-range still reaches the third, then one close to the long one),
    /// and none where an axis separates every pair.
    #[test]
    fn the_sweep_finds_every_close_pair() {
        let long = [[0.0, 0.0, 0.0], [10.0, 1.0, 1.0]];
        let above = [[1.0, 5.0, 0.0], [5.0, 6.0, 1.0]];
        let beside = [[3.0, 0.5, 0.5], [4.0, 2.0, 2.0]];
        let far = [[3.0, 3.0, 3.0], [4.0, 4.0, 4.0]];
        for (boxes, close) in [
            (vec![long, above, beside], true),
            (vec![beside, above, long], true),
            (vec![long, above, far], false),
            (vec![above, beside], false),
        ] {
            assert_eq!(!close_pairs(&boxes, 0.1).is_empty(), close, "{boxes:?}");
        }
    }
}
