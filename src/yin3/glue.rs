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

/// Call `f(fin, edge, partner)` for every fin of every edge whose partner in `pairing` is
/// another fin, among the fins of the same `label` only when labels are given (the restricted
/// cyclic order of GS.2); at an edge of two fins, which are each other's partners, for the
/// first only. (Callers join each fin with its partner: a fin paired with itself joins nothing,
/// and a pair joined once is joined.)
pub(crate) fn pair_fins(
    table: &FinTable,
    label: Option<&[usize]>,
    pairing: Pairing,
    mut f: impl FnMut(Fin, usize, Fin),
) {
    let same = |a: &Fin, b: &Fin| label.is_none_or(|l| l[a.tri] == l[b.tri]);
    for (e, fins) in table.fin_lists().enumerate() {
        if let [a, b] = fins {
            if same(a, b) {
                f(*a, e, *b);
            }
            continue;
        }
        // The cyclic order, restricted to one label when labels are given: the nearest fins
        // of the same label before and after each fin (the fin itself if it is alone).
        let m = fins.len();
        // j mod m for j < 2m, without a division.
        let wrap = |j: usize| if j >= m { j - m } else { j };
        for (i, fin) in fins.iter().enumerate() {
            let like = |j: &usize| same(&fins[*j], fin);
            let next = (1..=m).map(|k| wrap(i + k)).find(like).unwrap_or(i);
            let prev = (1..=m).map(|k| wrap(i + m - k)).find(like).unwrap_or(i);
            let p = partner(*fin, pairing, prev, next);
            if p != i {
                f(*fin, e, fins[p]);
            }
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
    let (pgs, count) = gs1.classes();
    if table.fin_lists().all(|fins| fins.len() == 2) {
        // GS.2 would join the same pairs: both fins of each edge lie in one P_GS.
        return (pgs, count);
    }
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
