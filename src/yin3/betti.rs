//! Betti numbers b0, b1, b2 of a 3D Yin set as an open set (DESIGN-3D §2.12):
//! b0 = #atoms; b2 = bounded components of the closed complement (Alexander duality);
//! b1 = b0 + b2 − χ(𝒴), with χ(𝒴) = χ(∂𝒴_ε)/2 + [𝒴 unbounded] and
//! χ(∂𝒴_ε) = Σ_p (2 r_p − l_p) − F/2 over the vertices p of the boundary.

use super::fins::{FinTable, Pairing};
use super::geom::normal;
use super::glue::{corner_cycles, glued_surfaces};
use super::hasse::hasse;
use crate::kernel::{orient, Point3};
use crate::num::Num;
use crate::union_find::UnionFind;
use std::cmp::Ordering;

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
    let chi_surface = link_sum(points, tris, table, ctx) - tris.len() as i64 / 2;
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
pub(crate) fn link_sum<N: Num>(
    points: &[Point3<N>],
    tris: &[[usize; 3]],
    table: &FinTable,
    ctx: &N::Ctx,
) -> i64 {
    let mut inside = corner_cycles(table, tris, None, Pairing::Inside);
    let mut outside = corner_cycles(table, tris, None, Pairing::Outside);
    let mut link = UnionFind::new(3 * tris.len());
    for (e, fins) in table.fins.iter().enumerate() {
        let (a, b) = table.edges[e];
        for v in [a, b] {
            let c0 = corner(tris, fins[0].tri, v);
            for f in &fins[1..] {
                link.union(c0, corner(tris, f.tri, v));
            }
        }
    }
    let mut at: Vec<Vec<usize>> = vec![Vec::new(); points.len()];
    for (t, tri) in tris.iter().enumerate() {
        for (k, &v) in tri.iter().enumerate() {
            at[v].push(3 * t + k);
        }
    }
    let mut sum: i64 = 0;
    for (p, corners) in at.iter().enumerate() {
        if corners.is_empty() {
            continue;
        }
        let mut ycycles: Vec<usize> = corners.iter().map(|&c| inside.find(c)).collect();
        ycycles.sort_unstable();
        ycycles.dedup();
        let l = ycycles.len() as i64;
        let mut comps: Vec<usize> = corners.iter().map(|&c| link.find(c)).collect();
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
                        .filter(|&c| link.find(c) == k)
                        .collect()
                })
                .collect();
            local_components(
                points,
                tris,
                p,
                &groups,
                &mut inside,
                &mut outside,
                &ycycles,
                ctx,
            ) as i64
        };
        sum += 2 * r - l;
    }
    sum
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

/// r_p where the link of `p` has several components (`groups` of corners): the number of
/// faces of the link lying in 𝒴, each a class of 𝒴-cycles bounding one face (Janiszewski).
#[allow(clippy::too_many_arguments)]
fn local_components<N: Num>(
    points: &[Point3<N>],
    tris: &[[usize; 3]],
    p: usize,
    groups: &[Vec<usize>],
    inside: &mut UnionFind,
    outside: &mut UnionFind,
    ycycles: &[usize],
    ctx: &N::Ctx,
) -> usize {
    let m = groups.len();
    // face[i][j]: the face of component i that holds component j, as (in 𝒴?, its cycle).
    let mut face = vec![vec![(false, 0usize); m]; m];
    for i in 0..m {
        for j in 0..m {
            if i != j {
                face[i][j] = face_holding(
                    points, tris, p, &groups[i], &groups[j], inside, outside, ctx,
                );
            }
        }
    }
    let mut uf = UnionFind::new(ycycles.len());
    let pos = |c: usize| ycycles.binary_search(&c).expect("a 𝒴-cycle at p");
    for i in 0..m {
        for j in i + 1..m {
            let (fi, fj) = (face[i][j], face[j][i]);
            let apart = (0..m).any(|k| k != i && k != j && face[k][i] != face[k][j]);
            if fi.0 && fj.0 && !apart {
                uf.union(pos(fi.1), pos(fj.1));
            }
        }
    }
    uf.classes().1
}

/// The face of the link component `ci` (corners at `p`) that holds the component `cj`: found
/// from the first wedge of `ci` that a segment from inside a wedge of `cj` to inside a wedge
/// of `ci` crosses, retried with other points while the segment hits a wedge's edge.
#[allow(clippy::too_many_arguments)]
fn face_holding<N: Num>(
    points: &[Point3<N>],
    tris: &[[usize; 3]],
    p: usize,
    ci: &[usize],
    cj: &[usize],
    inside: &mut UnionFind,
    outside: &mut UnionFind,
    ctx: &N::Ctx,
) -> (bool, usize) {
    const WEIGHTS: [[i64; 3]; 6] = [
        [1, 1, 1],
        [1, 2, 3],
        [3, 1, 2],
        [2, 3, 1],
        [1, 5, 2],
        [4, 1, 7],
    ];
    let wedge = |c: usize| {
        let t = tris[c / 3];
        let k = c % 3;
        [t[k], t[(k + 1) % 3], t[(k + 2) % 3]].map(|v| &points[v])
    };
    let interior = |c: usize, w: [i64; 3]| {
        let [a, b, d] = wedge(c);
        let s = N::from_i64(w[0] + w[1] + w[2]);
        let mix = |k: usize| {
            (N::from_i64(w[0]) * a.coord(k).clone()
                + N::from_i64(w[1]) * b.coord(k).clone()
                + N::from_i64(w[2]) * d.coord(k).clone())
                / s.clone()
        };
        Point3::new(mix(0), mix(1), mix(2))
    };
    for &cx in cj {
        for &cy in ci {
            for wx in WEIGHTS {
                for wy in WEIGHTS {
                    let (x, y) = (interior(cx, wx), interior(cy, wy));
                    if let Some((c, above)) = first_hit(points, p, ci, &wedge, &x, &y, ctx) {
                        return if above {
                            (false, outside.find(c))
                        } else {
                            (true, inside.find(c))
                        };
                    }
                }
            }
        }
    }
    panic!("no generic segment between two link components at vertex {p} (a degenerate configuration the retries did not escape)");
}

/// The first wedge (corner of `comp`) crossed by the segment x → y and whether x is on its +n
/// side; `None` if the segment is degenerate (through p, along a wedge's plane, through a
/// wedge's edge, or two wedges at once).
fn first_hit<'a, N: Num>(
    points: &'a [Point3<N>],
    p: usize,
    comp: &[usize],
    wedge: &impl Fn(usize) -> [&'a Point3<N>; 3],
    x: &Point3<N>,
    y: &Point3<N>,
    ctx: &N::Ctx,
) -> Option<(usize, bool)> {
    let o = &points[p];
    if x.sub(o).cross(&y.sub(o)) == Point3::int(0, 0, 0) {
        return None;
    }
    let mut best: Option<(N, usize, bool)> = None;
    for &c in comp {
        let [_, a, b] = wedge(c);
        let n = normal(o, a, b);
        let (vx, vy) = (n.dot(&x.sub(o)), n.dot(&y.sub(o)));
        if vx.sign() == Ordering::Equal {
            // x lies in the wedge's plane but not in the wedge (the link components are
            // disjoint): the segment leaves the plane at once, unless it runs inside it.
            if vy.sign() == Ordering::Equal {
                return None;
            }
            continue;
        }
        if vy.sign() == vx.sign() {
            continue;
        }
        let s = vx.clone() / (vx.clone() - vy);
        let z = x.lerp(y, &s);
        let chart = super::geom::Chart::of_normal(&n);
        let (o2, a2, b2, z2) = (
            chart.project(o),
            chart.project(a),
            chart.project(b),
            chart.project(&z),
        );
        let (oa, ob) = (orient(&o2, &a2, &z2, ctx), orient(&o2, &b2, &z2, ctx));
        if oa == Ordering::Equal || ob == Ordering::Equal {
            return None;
        }
        if oa != Ordering::Greater || ob != Ordering::Less {
            continue;
        }
        match &best {
            Some((bs, _, _)) if *bs == s => return None,
            Some((bs, _, _)) if *bs < s => {}
            _ => best = Some((s, c, vx.sign() == Ordering::Greater)),
        }
    }
    best.map(|(_, c, above)| (c, above))
}
