//! The faces around each edge in exact rotation order, and their good pairings (seed 003 Def. 5.12,
//! Lemma 5.13; seed 004 "pasting"; yin3 docs: *Rotation order around an edge*): no angles, no
//! atan2.

use crate::kernel::{orient3d, Point3};
use crate::num::Num;
use foldhash::{HashMap, HashMapExt};
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
#[derive(Clone, Debug, Default)]
pub(crate) struct FinTable {
    /// The edges `(a, b)` with `a < b`.
    pub edges: Vec<(usize, usize)>,
    /// The fins of each edge, in counterclockwise order about b − a.
    pub fins: Vec<SmallVec<[Fin; 2]>>,
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
        // A closed surface has 3T/2 edges.
        let edges = 3 * tris.len() / 2;
        let mut index: HashMap<(usize, usize), usize> = HashMap::with_capacity(edges);
        let mut table = FinTable {
            edges: Vec::with_capacity(edges),
            fins: Vec::with_capacity(edges),
        };
        for (t, tri) in tris.iter().enumerate() {
            for k in 0..3 {
                let (u, v, w) = (tri[k], tri[(k + 1) % 3], tri[(k + 2) % 3]);
                let key = (u.min(v), u.max(v));
                let e = *index.entry(key).or_insert_with(|| {
                    table.edges.push(key);
                    table.fins.push(SmallVec::new());
                    table.edges.len() - 1
                });
                table.fins[e].push(Fin {
                    tri: t,
                    apex: w,
                    forward: u < v,
                });
            }
        }
        for (e, fins) in table.fins.iter_mut().enumerate() {
            let (a, b) = table.edges[e];
            sort_about(&points[a], &points[b], fins, points, ctx);
        }
        table
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
        let fins = (self.fins.iter())
            .map(|fins| {
                (fins.iter())
                    .map(|f| Fin {
                        forward: !f.forward,
                        ..*f
                    })
                    .collect()
            })
            .collect();
        FinTable {
            edges: self.edges.clone(),
            fins,
        }
    }
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
    let d = b.sub(a);
    // The class of a fin's angle from the reference: (0, π), π, (π, 2π), 0.
    let class = |c: &Point3<N>| match orient3d(a, b, r, c, ctx) {
        Ordering::Greater => 0u8,
        Ordering::Less => 2,
        Ordering::Equal => {
            let (u, v) = (r.sub(a), c.sub(a));
            let perp = d.dot(&d) * u.dot(&v) - u.dot(&d) * v.dot(&d);
            if perp.sign() == Ordering::Less {
                1
            } else {
                3
            }
        }
    };
    let first = fins[0];
    fins[1..].sort_by(|f, g| {
        let (cf, cg) = (&points[f.apex], &points[g.apex]);
        class(cf)
            .cmp(&class(cg))
            .then_with(|| orient3d(a, b, cg, cf, ctx))
    });
    debug_assert_eq!(fins[0], first);
}

/// True if fins at every edge alternate in direction (invariant I3 of the yin3 docs); otherwise the
/// first edge and the two neighbouring fins that do not.
pub(crate) fn first_non_alternating(table: &FinTable) -> Option<(usize, Fin, Fin)> {
    for (e, fins) in table.fins.iter().enumerate() {
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
