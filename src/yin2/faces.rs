//! The regularized set of the faces of an arrangement where a winding-number rule holds: the
//! pieces between an inside face and an outside one, pasted (seed 000 Lemma 4.2). Exact mode
//! arranges the edges as given ([`fill_exact`]); float mode's snap rounding arranges its grid
//! fragments ([`fill_arranged`]).

use super::arrangement::Arrangement;
use super::error::YinError;
use super::intersect::{arrange, Edge};
use super::paste::Segmented;
use super::set::YinSet2;
use super::vertex::Vertex;
use super::winding::{Pair, Winding};
use crate::kernel::Point;
use crate::num::Num;

/// The regularized set {p off the edges : inside(w(p))} for w the winding numbers per operand
/// of the directed `edges`, edge `e` from operand `label(e)` (`0` or `1`): the arrangement of
/// all edges in one sweep ([`arrange`]), the winding numbers of the faces beside each of its
/// pieces, and the pasting map (seed 000 Lemma 4.2) of the pieces between an inside face (on
/// their left) and an outside one. With no such piece, the far face (w = 0) decides between 0̂
/// and 1̂. O((n + I) log n) for n edges with I contacts. Its predicates must be exact: exact
/// mode (float mode's snapped fragments go through [`fill_arranged`]).
pub(crate) fn fill_exact<N: Num>(
    edges: &[Edge<N>],
    label: impl Fn(usize) -> usize,
    ctx: N::Ctx,
    inside: impl Fn(Winding) -> bool,
) -> Result<YinSet2<N>, YinError> {
    let arr = arrange(edges, &ctx);
    let ascending = |e: usize| edges[e].0 < edges[e].1;
    fill_arranged(arr, Vertex::into_point, label, ascending, ctx, inside)
}

/// [`fill_exact`] on an arrangement made already, whose edge `e` is from operand `label(e)`
/// and given from its lower end to its upper one (in sweep order) where `ascending(e)`, its
/// points made exact by `point` (float mode's snap rounding makes the arrangement of its grid
/// fragments and checks that no two of them cross).
pub(crate) fn fill_arranged<P, N: Num>(
    arr: Arrangement<P>,
    point: impl FnMut(P) -> Point<N>,
    label: impl Fn(usize) -> usize,
    ascending: impl Fn(usize) -> bool,
    ctx: N::Ctx,
    inside: impl Fn(Winding) -> bool,
) -> Result<YinSet2<N>, YinError> {
    // The sweep orders each edge lo → hi; an edge given hi → lo counts negatively upwards.
    let upward = |e: usize| {
        let unit = Pair::unit(label(e));
        if ascending(e) {
            unit
        } else {
            Pair::default() - unit
        }
    };
    let windings = arr.windings(upward);
    let mut pieces = Vec::with_capacity(arr.groups.len());
    // The piece directly below each piece's lower end, and the piece at or below each group.
    let mut under = Vec::with_capacity(arr.groups.len());
    let mut down: Vec<Option<usize>> = Vec::with_capacity(arr.groups.len());
    for (g, (below, above)) in arr.groups.iter().zip(windings) {
        let beneath = g.below.and_then(|b| down[b]);
        let piece = match (inside(below.0), inside(above.0)) {
            (false, true) => (g.from, g.to),
            (true, false) => (g.to, g.from),
            _ => {
                down.push(beneath);
                continue;
            }
        };
        down.push(Some(pieces.len()));
        pieces.push(piece);
        under.push(beneath);
    }
    if pieces.is_empty() && inside(Winding::default()) {
        return Ok(YinSet2::full().with_ctx(ctx));
    }
    let points = arr.into_points(&mut pieces, point);
    Segmented::swept(points, pieces, under).paste_exact(ctx)
}

/// Whether a face of winding `w` lies in a Yin set bounded by closed cycles: positive winding,
/// or non-negative if the set is unbounded (its far face, of winding 0, is inside).
pub(crate) fn inside_set(w: i64, unbounded: bool) -> bool {
    w + i64::from(unbounded) > 0
}
