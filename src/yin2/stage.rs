//! Float mode as one stage: the one place where a 2D construction or operation chooses between
//! exact mode's sweep of the boundaries as given and float mode's snap rounding of them to the
//! grid of ε (seed 000 §5.2; [`crate::num::Tolerance`]), and resolves the context first. The
//! rest of the 2D kernel computes the same way in both modes, with the exact predicates of
//! [`crate::num::Num`] under the context it is given.

use super::error::YinError;
use super::faces::{fill_exact, inside_set};
use super::set::{Spadjor, YinSet2};
use super::snap::{regularize, Ring};
use super::winding::Winding;
use crate::kernel::{BBox, Point};
use crate::num::{Float, Num};

/// True if results under `ctx` are snapped to a grid (float mode, [`Num::grid`]).
fn snapped<N: Num>(ctx: &N::Ctx) -> bool {
    N::grid(ctx).is_some()
}

/// The Yin set of the faces where `inside` holds, for the winding numbers of the closed
/// `rings` labelled by operand (`0` or `1`): exact mode arranges their edges as given
/// (zero-length ones dropped, [`fill_exact`]); float mode snaps them to the grid of `ctx` first
/// ([`regularize`], where `valid` says that the rings of each label bound a Yin set).
pub(crate) fn faces_where<'a, N: Num>(
    rings: impl Iterator<Item = Ring<'a, N>> + Clone,
    valid: bool,
    ctx: N::Ctx,
    inside: impl Fn(Winding) -> bool,
) -> Result<YinSet2<N>, YinError> {
    if snapped::<N>(&ctx) {
        return regularize(rings, valid, ctx, inside);
    }
    let count = rings.clone().map(|(ring, _)| ring.len()).sum();
    let (mut edges, mut labels) = (Vec::with_capacity(count), Vec::with_capacity(count));
    for (ring, label) in rings {
        let next = ring.iter().skip(1).chain(ring.first());
        for (a, b) in ring.iter().zip(next).filter(|(a, b)| a != b) {
            edges.push((a.clone(), b.clone()));
            labels.push(label);
        }
    }
    fill_exact(&edges, |e| labels[e], ctx, inside)
}

/// The Yin set that the realized `spadjor` bounds under `ctx`: itself in exact mode; in float
/// mode snapped to the grid, or the error that it vanished there ([`not_collapsed`]).
pub(crate) fn bounded_by<N: Num>(spadjor: Spadjor<N>, ctx: N::Ctx) -> Result<YinSet2<N>, YinError> {
    if !snapped::<N>(&ctx) {
        return Ok(YinSet2::from_spadjor(spadjor, ctx));
    }
    let unbounded = !spadjor.bounded;
    let rings = spadjor.curves.iter().map(|c| (c.vertices(), 0));
    let y = regularize(rings, true, ctx, |w| inside_set(w[0], unbounded))?;
    not_collapsed(y)
}

/// The context `ctx` resolved for the finite points of `curves` ([`Num::resolve_ctx`]: float
/// mode's default ε, or the error that the requested one is too fine for them).
pub(crate) fn resolve_for<N: Num>(
    curves: &[Vec<Point<N>>],
    ctx: N::Ctx,
) -> Result<N::Ctx, YinError> {
    let (span, magnitude) =
        BBox::of(curves.iter().flatten()).map_or((0.0, 0.0), |b| (b.span(), b.extent()));
    N::resolve_ctx(ctx, span, magnitude).map_err(|e| YinError::ToleranceTooFine {
        requested: Float::new(e.requested),
        representable: Float::new(e.representable),
    })
}

/// A float set snapped from a non-empty input, or the error that the whole input vanished on
/// its grid (a non-empty set never silently becomes 0̂ or 1̂).
pub(crate) fn not_collapsed<N: Num>(y: YinSet2<N>) -> Result<YinSet2<N>, YinError> {
    match y.grid() {
        Some(g) if y.is_empty() || y.is_full() => Err(YinError::CollapsedOnGrid {
            grid: Float::new(g),
        }),
        _ => Ok(y),
    }
}
