//! Orientation of glued surfaces, boundedness, the Hasse diagram of inclusion and the atoms
//! (seed 003 Def. 7.3–7.6, Thm 7.10, Cor. 7.11; DESIGN-3D §2.8).

use super::geom::det3;
use super::locate::winding;
use crate::kernel::{BBox3, Point3};
use crate::num::Num;
use std::cmp::Ordering;

/// One connected component of a 3D Yin set (seed 003 Thm 7.10): its positively oriented
/// glued surface (none for the unbounded component) and the negatively oriented ones it
/// covers.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct Atom3 {
    /// The outer surface 𝒮⁺ (an index into the set's surfaces), `None` for the unbounded atom.
    pub outer: Option<usize>,
    /// The surfaces 𝒮⁻ of its cavities (or, for the unbounded atom, of its complement's
    /// components).
    pub inner: Vec<usize>,
}

/// The inclusion structure of a set of glued surfaces.
#[derive(Clone, Debug)]
pub(crate) struct Hasse<N> {
    /// Six times each surface's signed volume (positive iff positively oriented, Def. 7.3).
    pub volume6: Vec<N>,
    /// Each surface's parent: the smallest surface whose bounded complement contains it.
    pub parent: Vec<Option<usize>>,
    /// The atoms.
    pub atoms: Vec<Atom3>,
    /// True if the set is bounded (the total signed volume is positive).
    pub bounded: bool,
}

/// The Hasse diagram of the surfaces `label` (per triangle, `count` of them) of the triangles.
pub(crate) fn hasse<N: Num>(
    points: &[Point3<N>],
    tris: &[[usize; 3]],
    label: &[usize],
    count: usize,
    ctx: &N::Ctx,
) -> Hasse<N> {
    let mut members: Vec<Vec<usize>> = vec![Vec::new(); count];
    for (t, &l) in label.iter().enumerate() {
        members[l].push(t);
    }
    let corners = |t: usize| tris[t].map(|v| &points[v]);
    let volume6: Vec<N> = members
        .iter()
        .map(|m| {
            m.iter().fold(N::zero(), |s, &t| {
                let [a, b, c] = corners(t);
                s + det3(a, b, c)
            })
        })
        .collect();
    let total = volume6.iter().fold(N::zero(), |s, v| s + v.clone());
    let size: Vec<N> = volume6.iter().map(super::geom::abs).collect();
    let boxes: Vec<BBox3<N>> = members
        .iter()
        .map(|m| BBox3::of(m.iter().flat_map(|&t| corners(t))).expect("a surface has triangles"))
        .collect();
    let mut parent = vec![None; count];
    for l in 0..count {
        let q = {
            let [a, b, c] = corners(members[l][0]);
            Point3::centroid(a, b, c)
        };
        let mut best: Option<usize> = None;
        for k in 0..count {
            if k == l
                || size[k] <= size[l]
                || !boxes[k].contains(&boxes[l].min)
                || !boxes[k].contains(&boxes[l].max)
            {
                continue;
            }
            if best.is_some_and(|b| size[b] <= size[k]) {
                continue;
            }
            if winding(members[k].iter().map(|&t| corners(t)), &q, ctx) != 0 {
                best = Some(k);
            }
        }
        parent[l] = best;
    }
    let positive: Vec<bool> = volume6
        .iter()
        .map(|v| v.sign() == Ordering::Greater)
        .collect();
    let mut atoms: Vec<Atom3> = (0..count)
        .filter(|&s| positive[s])
        .map(|s| Atom3 {
            outer: Some(s),
            inner: (0..count)
                .filter(|&n| !positive[n] && parent[n] == Some(s))
                .collect(),
        })
        .collect();
    let free: Vec<usize> = (0..count)
        .filter(|&n| !positive[n] && parent[n].is_none())
        .collect();
    if !free.is_empty() {
        atoms.push(Atom3 {
            outer: None,
            inner: free,
        });
    }
    Hasse {
        volume6,
        parent,
        atoms,
        bounded: total.sign() == Ordering::Greater,
    }
}
