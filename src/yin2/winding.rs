//! Winding numbers of the faces beside pairwise non-crossing pieces, by the sweep of seed 002
//! Alg. 1: shared by the fill rules and float mode's snap rounding.

use super::error::YinError;
use super::locate::first_above;
use crate::kernel::Point;
use crate::num::Num;
use std::ops::{Add, Sub};

/// Winding numbers of a point with respect to the boundaries of the operands (two at most).
pub(crate) type Winding = [i64; 2];

/// A [`Winding`] with the arithmetic that [`left_windings`] and the exact arrangement need.
#[derive(Clone, Copy, Default)]
pub(crate) struct Pair(pub(crate) Winding);

impl Add for Pair {
    type Output = Pair;
    fn add(self, o: Pair) -> Pair {
        Pair([self.0[0] + o.0[0], self.0[1] + o.0[1]])
    }
}

impl Sub for Pair {
    type Output = Pair;
    fn sub(self, o: Pair) -> Pair {
        Pair([self.0[0] - o.0[0], self.0[1] - o.0[1]])
    }
}

/// The winding number on the left of each piece `lo → hi` (`lo < hi`, pieces pairwise
/// non-crossing and non-overlapping, `mult[k]` the net multiplicity of piece k): the face above a
/// non-vertical piece, or east of a vertical one, is the face below the first non-vertical piece
/// above its midpoint, or the far face (winding 0); the face below a piece is the one above it
/// less its multiplicity. O(P log P) for P pieces. A cycle among the pieces above (a wrong
/// sweep order, an internal invariant) is an error, never an endless walk.
pub(crate) fn left_windings<N, W>(
    pieces: &[(&Point<N>, &Point<N>)],
    mult: &[W],
    ctx: &N::Ctx,
) -> Result<Vec<W>, YinError>
where
    N: Num,
    W: Copy + Default + Add<Output = W> + Sub<Output = W>,
{
    let mids: Vec<Point<N>> = pieces.iter().map(|(a, b)| a.midpoint(b)).collect();
    let above = first_above(pieces, &mids, ctx);
    let mut below: Vec<Option<W>> = vec![None; pieces.len()];
    let mut face_above = |k: usize| {
        // Walk up to a piece whose face below is known, then fill in the faces on the way down.
        let mut chain = Vec::new();
        let mut face = W::default();
        let mut cur = above[k];
        while let Some(q) = cur {
            if let Some(w) = below[q] {
                face = w;
                break;
            }
            chain.push(q);
            // A cycle would mean a wrong sweep order: stop instead of growing without bound.
            if chain.len() > pieces.len() {
                return Err(YinError::SweepCycle {
                    point: pieces[k].0.to_string(),
                });
            }
            cur = above[q];
        }
        for &q in chain.iter().rev() {
            face = face - mult[q];
            below[q] = Some(face);
        }
        Ok(face)
    };
    (0..pieces.len())
        .map(|k| {
            let face = face_above(k)?;
            // Going up is right to left across a vertical piece: add its multiplicity.
            Ok(if pieces[k].0.x == pieces[k].1.x {
                face + mult[k]
            } else {
                face
            })
        })
        .collect()
}
