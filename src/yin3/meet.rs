//! The meet of two 3D Yin sets (DESIGN-3D §2.5, §2.10; seed 004 steps 1–5; the 3D MRS-b..d of
//! seed 000 Lemma 4.6, Cor. 4.7, Def. 4.8): arrange both boundaries against each other, keep
//! the pieces of each that lie in the other (coincident pieces: one copy if equally oriented,
//! none if opposite), and paste the kept pieces into glued surfaces.

use super::arrange::{arrange, Pairs, Soup};
use super::error::Yin3Error;
use super::float::float_meet;
use super::geom::{f64_box, in_triangle3, plane_key};
use super::locate::{winding, TriBoxes};
use super::ops::or_panic;
use super::set::{Brep, YinSet3};
use crate::kernel::Point3;
use crate::num::Num;
use crate::union_find::UnionFind;
use std::cell::OnceCell;
use std::collections::HashMap;

/// Where a piece of one operand lies relative to the other operand.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Side {
    /// On a face of the other with the same orientation (MRS-c, kept once).
    Same,
    /// On a face of the other with the opposite orientation (dropped from both).
    Opposite,
    /// In the other's interior.
    Inside,
    /// In the other's exterior.
    Outside,
}

impl<N: Num> YinSet3<N> {
    /// The meet 𝒴 ∧ 𝒵 (seed 000 Def. 4.8 lifted to 3D by seed 004): the regularized
    /// intersection.
    ///
    /// # Panics
    /// Only in float mode, when the result has no valid `f64` representation
    /// ([`Yin3Error::Unrepresentable`]); [`YinSet3::try_meet`] returns that error instead.
    pub fn meet(&self, other: &YinSet3<N>) -> YinSet3<N> {
        or_panic(self.try_meet(other), "meet")
    }

    /// The meet, or in float mode the error that it has no valid `f64` representation
    /// (exact mode never fails). Float mode follows the contract of [`crate::num::Tolerance`]
    /// in 3D ([`super::float`]).
    pub fn try_meet(&self, other: &YinSet3<N>) -> Result<YinSet3<N>, Yin3Error> {
        let ctx = N::combine_ctx(self.ctx, other.ctx);
        if N::EXACT {
            self.meet_in(other, ctx)
        } else {
            float_meet(self, other, ctx)
        }
    }

    /// The meet computed with the predicates of `ctx` (MRS-a..d in 3D); an error if the
    /// arrangement or the kept pieces are inconsistent (never in exact mode).
    pub(crate) fn meet_in(&self, other: &YinSet3<N>, ctx: N::Ctx) -> Result<YinSet3<N>, Yin3Error> {
        let (a, b) = match (self.brep(), other.brep()) {
            _ if self.is_empty() || other.is_empty() => return Ok(YinSet3::empty().with_ctx(ctx)),
            (None, _) => return Ok(other.clone().with_ctx(ctx)),
            (_, None) => return Ok(self.clone().with_ctx(ctx)),
            (Some(a), Some(b)) => (a, b),
        };
        if a.bounded
            && b.bounded
            && !self
                .bbox()
                .zip(other.bbox())
                .is_some_and(|(x, y)| x.meets(&y))
        {
            return Ok(YinSet3::empty().with_ctx(ctx));
        }
        let mut soup = Soup::new();
        for (operand, brep) in [a, b].into_iter().enumerate() {
            for t in 0..brep.tris.len() {
                soup.push(brep.corners(t), operand as u8);
            }
        }
        let pieces = arrange(&mut soup, Pairs::Across, &ctx).map_err(|e| {
            Yin3Error::Internal(format!(
                "the arrangement of a meet's operands failed: {e:?}"
            ))
        })?;
        let bounded = [a.bounded, b.bounded];
        let sides = classify(&soup, &pieces, bounded, &ctx);
        let kept: Vec<[usize; 3]> = pieces
            .iter()
            .zip(&sides)
            .filter(|((_, parent), side)| {
                matches!(
                    (soup.operand[*parent], side),
                    (0, Side::Same) | (_, Side::Inside)
                )
            })
            .map(|((t, _), _)| *t)
            .collect();
        if kept.is_empty() {
            return Ok(YinSet3::empty().with_ctx(ctx));
        }
        let brep = Brep::assemble(soup.points, kept).map_err(|e| {
            Yin3Error::Internal(format!(
                "the kept pieces of a meet do not bound a Yin set: {e}"
            ))
        })?;
        Ok(YinSet3::from_brep(brep, ctx))
    }
}

/// The side of every piece relative to the other operand. Membership is constant on patches
/// (pieces of one operand joined across edges off the other's boundary): one ray per patch.
fn classify<N: Num>(
    soup: &Soup<N>,
    pieces: &[([usize; 3], usize)],
    bounded: [bool; 2],
    ctx: &N::Ctx,
) -> Vec<Side> {
    let op = |i: usize| soup.operand[pieces[i].1] as usize;
    let trees: [TriBoxes; 2] = [0u8, 1].map(|o| {
        TriBoxes::new(
            (0..soup.tris.len())
                .filter(|&t| soup.operand[t] == o)
                .map(|t| (t, soup.corners(t))),
        )
    });
    let on_operand = |o: usize, q: &Point3<N>| {
        trees[o]
            .at(q, N::tolerance(ctx))
            .find(|&t| in_triangle3(soup.corners(t), q, ctx))
    };
    // True if triangle t's normal points along its plane key's normal.
    let along = |t: usize| {
        let [a, b, c] = soup.corners(t);
        plane_key(a, b, c).1
    };
    // Patches across edges whose midpoints are off the other operand's boundary.
    let mut edges: HashMap<(usize, usize), Vec<usize>> = HashMap::new();
    for (i, (t, _)) in pieces.iter().enumerate() {
        for k in 0..3 {
            let (u, v) = (t[k], t[(k + 1) % 3]);
            edges.entry((u.min(v), u.max(v))).or_default().push(i);
        }
    }
    let mut uf = UnionFind::new(pieces.len());
    for ((u, v), at) in &edges {
        let (pu, pv) = (&soup.points[*u], &soup.points[*v]);
        // The midpoint is constructed only if the edge's box meets one of the other's.
        let mid = OnceCell::new();
        let off = |o: usize| {
            !trees[o].meets(&f64_box([pu, pv]))
                || on_operand(o, mid.get_or_init(|| pu.midpoint(pv))).is_none()
        };
        for o in 0..2 {
            let mine: Vec<usize> = at.iter().copied().filter(|&i| op(i) == o).collect();
            if mine.len() > 1 && off(1 - o) {
                for w in &mine[1..] {
                    uf.union(mine[0], *w);
                }
            }
        }
    }
    let mut memo: HashMap<usize, Side> = HashMap::new();
    (0..pieces.len())
        .map(|i| {
            let (t, parent) = &pieces[i];
            let o = op(i);
            let [a, b, c] = t.map(|v| &soup.points[v]);
            // The centroid is constructed only if the piece's box meets one of the other's,
            // or for the ray of a new patch.
            let q = OnceCell::new();
            let centroid = || q.get_or_init(|| Point3::centroid(a, b, c));
            if trees[1 - o].meets(&f64_box([a, b, c])) {
                if let Some(s) = on_operand(1 - o, centroid()) {
                    return if along(*parent) == along(s) {
                        Side::Same
                    } else {
                        Side::Opposite
                    };
                }
            }
            let root = uf.find(i);
            *memo.entry(root).or_insert_with(|| {
                let q = centroid();
                let others = trees[1 - o].along_x(q).map(|s| soup.corners(s));
                if winding(others, q, ctx) + i64::from(!bounded[1 - o]) == 1 {
                    Side::Inside
                } else {
                    Side::Outside
                }
            })
        })
        .collect()
}
