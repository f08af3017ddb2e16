//! Betti numbers b0, b1, b2 of a 3D Yin set as an open set (yin3 docs: *Betti numbers*):
//! b0 = #atoms; b2 = bounded components of the closed complement (Alexander duality);
//! b1 = b0 + b2 − χ(𝒴), with χ(𝒴) = χ(∂𝒴_ε)/2 + [𝒴 unbounded] and
//! χ(∂𝒴_ε) = Σ_p (2 r_p − l_p) − F/2 over the vertices p of the boundary.

use super::fins::{FinTable, Pairing};
use super::glue::{corner_cycles, glued_surfaces};
use super::hasse::hasse;
use super::link::local_components;
use crate::kernel::Point3;
use crate::num::Num;
use crate::union_find::UnionFind;

/// Betti numbers of a 3D Yin set as an open subset of ℝ³.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct Betti3 {
    /// Connected components.
    pub b0: usize,
    /// Independent tunnels (handles).
    pub b1: usize,
    /// Cavities: bounded components of the complement.
    pub b2: usize,
}

/// The Betti numbers of the set bounded by the closed complex `tris` (with fin table `table`),
/// which has `atoms` atoms and is bounded or not.
pub(crate) fn betti<N: Num>(
    points: &[Point3<N>],
    tris: &[[usize; 3]],
    table: &FinTable,
    atoms: usize,
    bounded: bool,
    ctx: &N::Ctx,
) -> Betti3 {
    let b2 = closed_complement_components(points, tris, table, ctx) - usize::from(bounded);
    let chi_surface = link_sum(points, tris, table) - tris.len() as i64 / 2;
    let chi = chi_surface / 2 + i64::from(!bounded);
    let b1 = atoms as i64 + b2 as i64 - chi;
    Betti3 {
        b0: atoms,
        b1: usize::try_from(b1).unwrap_or_else(|_| {
            panic!("negative b1 = {b1} (b0 = {atoms}, b2 = {b2}, χ = {chi}): a kernel bug")
        }),
        b2,
    }
}

/// Σ_p (2 r_p − l_p) over the vertices p of the closed complex `tris` (fin table `table`):
/// l_p 𝒴-cycles at p, and r_p faces of p's link in 𝒴 (module docs).
pub(crate) fn link_sum<N: Num>(points: &[Point3<N>], tris: &[[usize; 3]], table: &FinTable) -> i64 {
    let inside = corner_cycles(table, tris, None, Pairing::Inside);
    let mut links = Links::new(tris, table, inside);
    let at = corners_at(tris, points.len(), Some);
    (at.iter().enumerate())
        .filter(|(_, corners)| !corners.is_empty())
        .map(|(p, corners)| links.term(points, tris, p, corners))
        .sum()
}

/// The corners (3 · triangle + k) of `tris` at `count` vertices, the vertex v's in the slot
/// `slot(v)` (nowhere where it is `None`).
pub(crate) fn corners_at(
    tris: &[[usize; 3]],
    count: usize,
    slot: impl Fn(usize) -> Option<usize>,
) -> Vec<Vec<usize>> {
    let mut at = vec![Vec::new(); count];
    for (t, tri) in tris.iter().enumerate() {
        for (k, &v) in tri.iter().enumerate() {
            if let Some(i) = slot(v) {
                at[i].push(3 * t + k);
            }
        }
    }
    at
}

/// The corners of a closed complex joined three ways: into 𝒴-cycles, into 𝒴'-cycles, and
/// into the components of each vertex's link (across every fin of an edge).
pub(crate) struct Links {
    inside: UnionFind,
    outside: UnionFind,
    link: UnionFind,
}

impl Links {
    /// The joined corners of the closed complex `tris` with fin table `table`, whose 𝒴-cycles
    /// ([`corner_cycles`] of the inside pairing) the caller has joined already as `inside`.
    /// Where every edge has two fins the three joins are one: each fin's only partner, in
    /// either pairing, is the edge's other fin, and the link joins the same two.
    pub(crate) fn new(tris: &[[usize; 3]], table: &FinTable, inside: UnionFind) -> Links {
        if table.fin_lists().all(|fins| fins.len() == 2) {
            return Links {
                outside: inside.clone(),
                link: inside.clone(),
                inside,
            };
        }
        Links::joined(tris, table, inside)
    }

    /// [`Links::new`] joined fin by fin, for any number of fins at an edge.
    fn joined(tris: &[[usize; 3]], table: &FinTable, inside: UnionFind) -> Links {
        let mut link = UnionFind::new(3 * tris.len());
        for (e, fins) in table.fin_lists().enumerate() {
            let (a, b) = table.edges[e];
            for v in [a, b] {
                let c0 = corner(tris, fins[0].tri, v);
                for f in &fins[1..] {
                    link.union(c0, corner(tris, f.tri, v));
                }
            }
        }
        Links {
            inside,
            outside: corner_cycles(table, tris, None, Pairing::Outside),
            link,
        }
    }

    /// 2 r_p − l_p at the vertex `p`, whose corners are `corners` (module docs), on the exact
    /// values of `points`.
    pub(crate) fn term<N: Num>(
        &mut self,
        points: &[Point3<N>],
        tris: &[[usize; 3]],
        p: usize,
        corners: &[usize],
    ) -> i64 {
        let mut ycycles: Vec<usize> = corners.iter().map(|&c| self.inside.find(c)).collect();
        ycycles.sort_unstable();
        ycycles.dedup();
        let l = ycycles.len() as i64;
        let mut comps: Vec<usize> = corners.iter().map(|&c| self.link.find(c)).collect();
        comps.sort_unstable();
        comps.dedup();
        let r = if comps.len() == 1 {
            l
        } else {
            let groups: Vec<Vec<usize>> = comps
                .iter()
                .map(|&k| {
                    corners
                        .iter()
                        .copied()
                        .filter(|&c| self.link.find(c) == k)
                        .collect()
                })
                .collect();
            local_components(
                points,
                tris,
                p,
                &groups,
                [&mut self.inside, &mut self.outside],
                &ycycles,
            ) as i64
        };
        2 * r - l
    }
}

/// The corner of triangle `t` at vertex `v`.
fn corner(tris: &[[usize; 3]], t: usize, v: usize) -> usize {
    3 * t + tris[t].iter().position(|&w| w == v).unwrap_or(0)
}

/// The number of components of ℝ³ ∖ 𝒴 (closed): the atoms of the complement, joined when
/// they share a vertex.
fn closed_complement_components<N: Num>(
    points: &[Point3<N>],
    tris: &[[usize; 3]],
    table: &FinTable,
    ctx: &N::Ctx,
) -> usize {
    let (label, count) = glued_surfaces(table, tris.len(), Pairing::Outside);
    let reversed: Vec<[usize; 3]> = tris.iter().map(|&[a, b, c]| [a, c, b]).collect();
    let h = hasse(points, &reversed, &label, count, ctx);
    let mut atom_of_surface = vec![0; count];
    for (i, atom) in h.atoms.iter().enumerate() {
        for s in atom.outer.iter().chain(&atom.inner) {
            atom_of_surface[*s] = i;
        }
    }
    let mut uf = UnionFind::new(h.atoms.len());
    let mut first: Vec<Option<usize>> = vec![None; points.len()];
    for (t, tri) in tris.iter().enumerate() {
        let a = atom_of_surface[label[t]];
        for &v in tri {
            match first[v] {
                Some(b) => {
                    uf.union(a, b);
                }
                None => first[v] = Some(a),
            }
        }
    }
    uf.classes().1
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::num::Rational;

    /// Two fins at every edge: the 𝒴′-cycles and link components of [`Links::new`] are those
    /// joined fin by fin, on a tetrahedron and on two sharing a vertex (the second reflected
    /// through it, so reversed: only the fins matter here).
    #[test]
    fn two_fin_links_are_the_joined_ones() {
        let tetra = |o: [i64; 3], s: i64| -> (Vec<[i64; 3]>, Vec<[usize; 3]>) {
            let p = [[0, 0, 0], [s, 0, 0], [0, s, 0], [0, 0, s]];
            let tris = vec![[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]];
            (
                p.iter().map(|v| [0, 1, 2].map(|k| o[k] + v[k])).collect(),
                tris,
            )
        };
        let both = |a: (Vec<[i64; 3]>, Vec<[usize; 3]>), b: (Vec<[i64; 3]>, Vec<[usize; 3]>)| {
            let (mut p, mut t) = a;
            let n = p.len();
            // b's first vertex is a's first: shared.
            p.extend(b.0[1..].iter().copied());
            let at = |v: usize| if v == 0 { 0 } else { v + n - 1 };
            t.extend(b.1.iter().map(|f| f.map(at)));
            (p, t)
        };
        let cases = [
            tetra([0, 0, 0], 1),
            both(tetra([0, 0, 0], 1), tetra([0, 0, 0], -1)),
        ];
        for (p, tris) in cases {
            let points: Vec<Point3<Rational>> =
                p.iter().map(|&[x, y, z]| Point3::int(x, y, z)).collect();
            let table = FinTable::new(&points, &tris, &());
            assert!(table.fin_lists().all(|f| f.len() == 2));
            let inside = || corner_cycles(&table, &tris, None, Pairing::Inside);
            let (mut fast, mut slow) = (
                Links::new(&tris, &table, inside()),
                Links::joined(&tris, &table, inside()),
            );
            assert_eq!(fast.outside.classes(), slow.outside.classes());
            assert_eq!(fast.link.classes(), slow.link.classes());
        }
    }
}
