//! Glued-surface decomposition (seed 003 Def. 7.8; yin3 docs: *Glued surfaces*) and the corner
//! cycles around vertices that the Betti numbers and genera count.
//!
//! CC.1–3 are implicit: triangles are only ever joined across paired fins, never through a
//! vertex alone. GS.1 joins triangles across the pairing that locally bounds the set; GS.2
//! splits each resulting P_GS by the other pairing restricted to its own fins.

use super::fins::{partner, Fin, FinTable, Pairing};
use crate::union_find::UnionFind;

impl Pairing {
    /// The other good pairing.
    pub(crate) fn other(self) -> Pairing {
        match self {
            Pairing::Inside => Pairing::Outside,
            Pairing::Outside => Pairing::Inside,
        }
    }
}

/// Call `f(fin, edge, partner)` for every fin of every edge and its partner in `pairing`,
/// among the fins of the same `label` only when labels are given (the restricted cyclic order
/// of GS.2).
pub(crate) fn pair_fins(
    table: &FinTable,
    label: Option<&[usize]>,
    pairing: Pairing,
    mut f: impl FnMut(Fin, usize, Fin),
) {
    for (e, fins) in table.fins.iter().enumerate() {
        // The cyclic order, restricted to one label when labels are given: the nearest fins
        // of the same label before and after each fin (the fin itself if it is alone).
        let m = fins.len();
        // j mod m for j < 2m, without a division.
        let wrap = |j: usize| if j >= m { j - m } else { j };
        for (i, fin) in fins.iter().enumerate() {
            let same = |j: &usize| label.is_none_or(|l| l[fins[*j].tri] == l[fin.tri]);
            let next = (1..=m).map(|k| wrap(i + k)).find(same).unwrap_or(i);
            let prev = (1..=m).map(|k| wrap(i + m - k)).find(same).unwrap_or(i);
            f(*fin, e, fins[partner(*fin, pairing, prev, next)]);
        }
    }
}

/// The glued surfaces of a closed complex of `ntris` triangles bounding a set on the side
/// that `bounding` pairs (Inside for 𝒴, Outside for its complement): each triangle's surface
/// label and the number of surfaces.
pub(crate) fn glued_surfaces(
    table: &FinTable,
    ntris: usize,
    bounding: Pairing,
) -> (Vec<usize>, usize) {
    let mut gs1 = UnionFind::new(ntris);
    pair_fins(table, None, bounding, |f, _, g| {
        gs1.union(f.tri, g.tri);
    });
    let (pgs, _) = gs1.classes();
    let mut gs2 = UnionFind::new(ntris);
    pair_fins(table, Some(&pgs), bounding.other(), |f, _, g| {
        gs2.union(f.tri, g.tri);
    });
    gs2.classes()
}

/// Corner cycles: corners (3 t + k is corner k of triangle t) joined when their triangles are
/// partners in `pairing` at an edge through the corner's vertex, restricted to fins of one
/// label when labels are given.
pub(crate) fn corner_cycles(
    table: &FinTable,
    tris: &[[usize; 3]],
    label: Option<&[usize]>,
    pairing: Pairing,
) -> UnionFind {
    let corner = |t: usize, v: usize| 3 * t + tris[t].iter().position(|&w| w == v).unwrap_or(0);
    let mut uf = UnionFind::new(3 * tris.len());
    pair_fins(table, label, pairing, |f, e, g| {
        let (a, b) = table.edges[e];
        uf.union(corner(f.tri, a), corner(g.tri, a));
        uf.union(corner(f.tri, b), corner(g.tri, b));
    });
    uf
}
