//! The faces around each edge in exact rotation order, and their good pairings (seed 003 Def. 5.12,
//! Lemma 5.13; seed 004 "pasting"; yin3 docs: *Rotation order around an edge*): no angles, no
//! atan2.

use super::tri::apart_across;
use crate::kernel::{orient3d, Point3};
use crate::num::Num;
use smallvec::SmallVec;
use std::cmp::Ordering;

/// A triangle seen from one of its edges (a "fin" of the edge).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct Fin {
    /// The triangle.
    pub tri: usize,
    /// Its vertex off the edge.
    pub apex: usize,
    /// True if the triangle runs along the edge from its smaller to its larger vertex index.
    pub forward: bool,
}

/// Every edge of a closed triangle complex with its fins sorted counterclockwise about the
/// edge's direction (from its smaller to its larger vertex index).
#[derive(Clone, Debug, Default, PartialEq)]
pub(crate) struct FinTable {
    /// The edges `(a, b)` with `a < b`, in order of first appearance in the triangles.
    pub edges: Vec<(usize, usize)>,
    /// Where the fins of each edge start in `all`, and the end of the last edge's.
    start: Vec<usize>,
    /// The fins of all edges, each edge's in counterclockwise order about b − a.
    all: Vec<Fin>,
}

/// Which good pairing of the fins around an edge (seed 003 Lemma 5.13).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Pairing {
    /// The pairing that locally bounds 𝒴: each fin with the next one on its −n side.
    Inside,
    /// The pairing that locally bounds 𝒴^⊥: each fin with the next one on its +n side.
    Outside,
}

impl FinTable {
    /// Build the table of the triangles `tris` over `points` (each edge's fins sorted).
    pub(crate) fn new<N: Num>(points: &[Point3<N>], tris: &[[usize; 3]], ctx: &N::Ctx) -> FinTable {
        let mut table = unsorted(tris, points.len());
        for e in 0..table.edges.len() {
            let (a, b) = table.edges[e];
            let fins = &mut table.all[table.start[e]..table.start[e + 1]];
            sort_about(&points[a], &points[b], fins, points, ctx);
        }
        table
    }

    /// The fins of edge `e`.
    pub(crate) fn fins(&self, e: usize) -> &[Fin] {
        &self.all[self.start[e]..self.start[e + 1]]
    }

    /// The fins of each edge, in the order of `edges`.
    pub(crate) fn fin_lists(&self) -> impl ExactSizeIterator<Item = &[Fin]> + '_ {
        self.start.windows(2).map(|w| &self.all[w[0]..w[1]])
    }

    /// True if on `points` — the vertices of the same triangles, moved — the fins of every
    /// edge turn about it in this table's order (an edge of two fins has one order).
    pub(crate) fn order_kept<N: Num>(&self, points: &[Point3<N>], ctx: &N::Ctx) -> bool {
        (self.edges.iter().zip(self.fin_lists())).all(|(&(a, b), fins)| {
            fins.len() <= 2 || {
                let mut again = fins.to_vec();
                sort_about(&points[a], &points[b], &mut again, points, ctx);
                again == fins
            }
        })
    }

    /// The table of the same triangles each reversed (`[p, q, r]` → `[p, r, q]`), without a
    /// predicate: the same edges with the same fins in the same order, each fin's `forward`
    /// flipped. Proof: reversing a triangle keeps its edges and, for each edge, its vertex off
    /// it (the fin's `apex`), and turns the direction it runs along the edge. [`FinTable::new`]
    /// keys an edge by its vertex indices in increasing order, whatever the direction, and
    /// collects its fins in increasing triangle order (a triangle has one fin per edge), so
    /// each edge has the same fins in the same first order; `sort_about` then compares fins by
    /// the edge's endpoints and their apexes alone, never by `forward`, and its sort is stable
    /// from a fixed first fin, so it gives the same rotation order. (The edges of the table
    /// built by [`FinTable::new`] from the reversed triangles may be numbered differently,
    /// since a reversed triangle meets its edges in another order; nothing depends on that
    /// numbering.)
    pub(crate) fn reversed(&self) -> FinTable {
        let all = (self.all.iter())
            .map(|f| Fin {
                forward: !f.forward,
                ..*f
            })
            .collect();
        FinTable {
            edges: self.edges.clone(),
            start: self.start.clone(),
            all,
        }
    }
}

/// The side `k` of triangle `t` (`tris[t][k]` to the next corner) as its edge key (smaller
/// vertex, larger vertex) and its fin.
fn side(tris: &[[usize; 3]], t: usize, k: usize) -> ((usize, usize), Fin) {
    let tri = tris[t];
    let (u, v, w) = (tri[k], tri[(k + 1) % 3], tri[(k + 2) % 3]);
    let fin = Fin {
        tri: t,
        apex: w,
        forward: u < v,
    };
    ((u.min(v), u.max(v)), fin)
}

/// The sides (3 t + k: side k of triangle t) of the triangles `tris` over `count` vertices,
/// grouped by their smaller vertex (a counting sort, stable): the sides in that order and
/// where each vertex's group starts.
fn sides_by_smaller_vertex(tris: &[[usize; 3]], count: usize) -> (Vec<usize>, Vec<usize>) {
    let smaller = |h: usize| side(tris, h / 3, h % 3).0 .0;
    let mut start = vec![0usize; count + 1];
    for h in 0..3 * tris.len() {
        start[smaller(h) + 1] += 1;
    }
    for v in 0..count {
        start[v + 1] += start[v];
    }
    let mut next = start.clone();
    let mut order = vec![0usize; 3 * tris.len()];
    for h in 0..3 * tris.len() {
        let slot = &mut next[smaller(h)];
        order[*slot] = h;
        *slot += 1;
    }
    (order, start)
}

/// The edge of each side of the triangles `tris` over `count` vertices, edges numbered in
/// order of first appearance (side 3 t + k in increasing order), and the edges' keys: sides
/// with one smaller vertex are matched by their larger vertex through a per-vertex slot.
fn edge_of_sides(tris: &[[usize; 3]], count: usize) -> (Vec<usize>, Vec<(usize, usize)>) {
    let (order, start) = sides_by_smaller_vertex(tris, count);
    // Groups of sides with one key, numbered in the order of `order`; then renumbered.
    let mut group = vec![usize::MAX; order.len()];
    let mut slot = vec![usize::MAX; count];
    let mut groups = 0;
    for sides in start.windows(2).map(|w| &order[w[0]..w[1]]) {
        for &h in sides {
            let larger = side(tris, h / 3, h % 3).0 .1;
            if slot[larger] == usize::MAX {
                slot[larger] = groups;
                groups += 1;
            }
            group[h] = slot[larger];
        }
        for &h in sides {
            slot[side(tris, h / 3, h % 3).0 .1] = usize::MAX;
        }
    }
    let mut number = vec![usize::MAX; groups];
    let mut edges = Vec::with_capacity(groups);
    for (h, g) in group.iter_mut().enumerate() {
        if number[*g] == usize::MAX {
            number[*g] = edges.len();
            edges.push(side(tris, h / 3, h % 3).0);
        }
        *g = number[*g];
    }
    (group, edges)
}

/// The fin table of the triangles `tris` over `count` vertices before sorting: each edge's
/// fins in increasing triangle order.
fn unsorted(tris: &[[usize; 3]], count: usize) -> FinTable {
    let (edge, edges) = edge_of_sides(tris, count);
    let mut start = vec![0usize; edges.len() + 1];
    for &e in &edge {
        start[e + 1] += 1;
    }
    for e in 0..edges.len() {
        start[e + 1] += start[e];
    }
    let mut next = start.clone();
    let mut all = vec![
        Fin {
            tri: 0,
            apex: 0,
            forward: false
        };
        edge.len()
    ];
    for (h, &e) in edge.iter().enumerate() {
        all[next[e]] = side(tris, h / 3, h % 3).1;
        next[e] += 1;
    }
    FinTable { edges, start, all }
}

/// The partner of `fin` in `pairing`, given the fins `prev` and `next` to it in the
/// counterclockwise order (orientations alternating): the +n side of a forward fin is
/// counterclockwise from it (yin3 docs: *Rotation order around an edge*).
pub(crate) fn partner(fin: Fin, pairing: Pairing, prev: usize, next: usize) -> usize {
    match (pairing, fin.forward) {
        (Pairing::Inside, true) | (Pairing::Outside, false) => prev,
        (Pairing::Inside, false) | (Pairing::Outside, true) => next,
    }
}

/// Sort the fins of the edge `a → b` counterclockwise about b − a, starting from the first.
fn sort_about<N: Num>(
    a: &Point3<N>,
    b: &Point3<N>,
    fins: &mut [Fin],
    points: &[Point3<N>],
    ctx: &N::Ctx,
) {
    if fins.len() <= 2 {
        return;
    }
    let r = &points[fins[0].apex];
    // The class of a fin's angle from the reference: (0, π), π, (π, 2π), 0 (a fin in the
    // reference's plane lies at π iff it is across the edge from it there).
    let class = |c: &Point3<N>| match orient3d(a, b, r, c, ctx) {
        Ordering::Greater => 0u8,
        Ordering::Less => 2,
        Ordering::Equal if apart_across([a, b], r, c, ctx) => 1,
        Ordering::Equal => 3,
    };
    // Each fin's class found once, not at every comparison.
    let mut keyed: SmallVec<[(u8, Fin); 8]> = (fins[1..].iter())
        .map(|&f| (class(&points[f.apex]), f))
        .collect();
    keyed.sort_by(|(cf, f), (cg, g)| {
        cf.cmp(cg)
            .then_with(|| orient3d(a, b, &points[g.apex], &points[f.apex], ctx))
    });
    for (slot, (_, f)) in fins[1..].iter_mut().zip(keyed) {
        *slot = f;
    }
}

/// True if fins at every edge alternate in direction (invariant I3 of the yin3 docs); otherwise the
/// first edge and the two neighbouring fins that do not.
pub(crate) fn first_non_alternating(table: &FinTable) -> Option<(usize, Fin, Fin)> {
    for (e, fins) in table.fin_lists().enumerate() {
        let m = fins.len();
        for i in 0..m {
            let (f, g) = (fins[i], fins[(i + 1) % m]);
            if m % 2 == 1 || f.forward == g.forward {
                return Some((e, f, g));
            }
        }
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::num::Rational;
    use proptest::prelude::*;

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(yinset_testkit::cases(256)))]
        /// Before sorting, the table has each edge once, numbered in order of first appearance
        /// in the triangles, with the fins of the triangles along it in triangle order: an
        /// oracle that scans the edges found so far for each side.
        #[test]
        fn unsorted_fins_follow_the_triangles(
            tris in proptest::collection::vec(
                (0usize..12, 0usize..12, 0usize..12)
                    .prop_filter("three corners", |(a, b, c)| a != b && b != c && c != a)
                    .prop_map(|(a, b, c)| [a, b, c]),
                0..40,
            ),
        ) {
            let mut edges: Vec<(usize, usize)> = Vec::new();
            let mut fins: Vec<Vec<Fin>> = Vec::new();
            for (t, tri) in tris.iter().enumerate() {
                for k in 0..3 {
                    let (u, v) = (tri[k], tri[(k + 1) % 3]);
                    let key = (u.min(v), u.max(v));
                    let e = edges.iter().position(|&f| f == key).unwrap_or_else(|| {
                        edges.push(key);
                        fins.push(Vec::new());
                        edges.len() - 1
                    });
                    fins[e].push(Fin { tri: t, apex: tri[(k + 2) % 3], forward: u < v });
                }
            }
            let table = unsorted(&tris, 12);
            prop_assert_eq!(&table.edges, &edges);
            let got: Vec<Vec<Fin>> = table.fin_lists().map(<[Fin]>::to_vec).collect();
            prop_assert_eq!(got, fins);
        }
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(yinset_testkit::cases(256)))]
        /// Fins about the z axis sort by the angle of their apexes' (x, y) from the first's:
        /// an oracle on integer cross and dot products, with apexes on a small lattice so that
        /// fins in the first's plane, on its side of the edge and across it, occur.
        #[test]
        fn fins_sort_by_angle_from_the_first(
            apexes in proptest::collection::vec((-2i64..=2, -2i64..=2, -2i64..=2), 3..8),
        ) {
            prop_assume!(apexes.iter().all(|&(x, y, _)| (x, y) != (0, 0)));
            let mut pts = vec![Point3::<Rational>::int(0, 0, 0), Point3::int(0, 0, 1)];
            pts.extend(apexes.iter().map(|&(x, y, z)| Point3::int(x, y, z)));
            let mut fins: Vec<Fin> = (2..pts.len())
                .map(|apex| Fin { tri: apex, apex, forward: true })
                .collect();
            sort_about(&pts[0], &pts[1], &mut fins, &pts, &());
            let (rx, ry, _) = apexes[0];
            // The class of the angle from the reference, (0, π), π, (π, 2π), 0, then the
            // order within it (a stable sort keeps equal angles in input order).
            let class = |(x, y): (i64, i64)| match (rx * y - ry * x).signum() {
                1 => 0,
                -1 => 2,
                _ if rx * x + ry * y < 0 => 1,
                _ => 3,
            };
            let mut want: Vec<usize> = (1..apexes.len()).collect();
            want.sort_by(|&f, &g| {
                let ((fx, fy, _), (gx, gy, _)) = (apexes[f], apexes[g]);
                class((fx, fy)).cmp(&class((gx, gy))).then((gy * fx - gx * fy).cmp(&0).reverse())
            });
            let got: Vec<usize> = fins[1..].iter().map(|f| f.apex - 2).collect();
            prop_assert_eq!(fins[0].apex, 2);
            prop_assert_eq!(got, want);
        }
    }

    #[test]
    fn fins_sort_counterclockwise_about_the_edge() {
        // Edge along +z through the origin; apexes at angles 0, 90, 180, 270 degrees.
        let pts: Vec<Point3<Rational>> = vec![
            Point3::int(0, 0, 0),
            Point3::int(0, 0, 1),
            Point3::int(1, 0, 0),
            Point3::int(0, -1, 0),
            Point3::int(-1, 0, 0),
            Point3::int(0, 1, 0),
        ];
        let mut fins: Vec<Fin> = [2, 3, 4, 5]
            .map(|apex| Fin {
                tri: apex,
                apex,
                forward: apex % 2 == 0,
            })
            .to_vec();
        sort_about(&pts[0], &pts[1], &mut fins, &pts, &());
        let order: Vec<usize> = fins.iter().map(|f| f.apex).collect();
        assert_eq!(order, vec![2, 5, 4, 3]);
        // Fin at angle 0 runs forward: its +n side is counterclockwise, so its Inside partner
        // is the previous fin (at 270°) and its Outside partner the next (at 90°).
        assert_eq!(partner(fins[0], Pairing::Inside, 3, 1), 3);
        assert_eq!(partner(fins[0], Pairing::Outside, 3, 1), 1);
    }
}
