//! Meet (seed 000 Def. 4.8, MRS-a..d) in O((n + I) log n) (seed 002 §1.3).

use super::cut::cut_at_contacts;
use super::error::YinError;
use super::intersect::Edge;
use super::locate::Location;
use super::paste::{or_kernel_bug, Segmented};
use super::set::{Repr, Spadjor, YinSet2};
use super::snap::{inside_set, regularize};
use crate::kernel::Point;
use crate::num::Num;
use std::collections::HashSet;

impl<N: Num> YinSet2<N> {
    /// The meet 𝒥 ∧ 𝒦 (seed 000 Def. 4.8): ρ(𝒥 ∧ 𝒦) = ρ(𝒥) ∩ ρ(𝒦).
    pub fn meet(&self, other: &YinSet2<N>) -> YinSet2<N> {
        let ctx = N::combine_ctx(self.ctx, other.ctx);
        match (&self.repr, &other.repr) {
            (Repr::Empty, _) | (_, Repr::Empty) => YinSet2::empty().with_ctx(ctx),
            (Repr::Full, _) => other.clone().with_ctx(ctx),
            (_, Repr::Full) => self.clone().with_ctx(ctx),
            (Repr::Spadjor(a), Repr::Spadjor(b)) => match N::grid(&ctx) {
                Some(_) => or_kernel_bug(overlay(a, b, ctx, |x, y| x && y)),
                None => or_kernel_bug(meet_spadjors(a, b, ctx)),
            },
        }
    }
}

/// MRS-a..d on two realizable spadjors, then the pasting map (exact mode).
fn meet_spadjors<N: Num>(
    a: &Spadjor<N>,
    b: &Spadjor<N>,
    ctx: N::Ctx,
) -> Result<YinSet2<N>, YinError> {
    let edges: Vec<Edge<N>> = a
        .edges()
        .into_iter()
        .chain(b.edges())
        .map(|(p, q)| (p.clone(), q.clone()))
        .collect();
    let na = a.curves.iter().map(|c| c.len()).sum::<usize>();
    // MRS-a, MRS-b: S_V of both spadjors, V the points of P(𝒥) ∩ P(𝒦), as interned pieces.
    let mut g = Segmented::new();
    let mut pieces_a = Vec::new();
    let mut pieces_b = Vec::new();
    let cut = cut_at_contacts(&edges, &ctx, |i, j| (i < na) != (j < na));
    for (i, pieces) in cut.into_iter().enumerate() {
        let target = if i < na { &mut pieces_a } else { &mut pieces_b };
        for (p, q) in pieces {
            target.push((g.id(&p), g.id(&q), p, q));
        }
    }
    let set_a: HashSet<(usize, usize)> = pieces_a.iter().map(|x| (x.0, x.1)).collect();
    let set_b: HashSet<(usize, usize)> = pieces_b.iter().map(|x| (x.0, x.1)).collect();
    // MRS-c: pieces of 𝒥 inside ρ(𝒦), or shared with 𝒦 in the same direction.
    let mut probe_a = Vec::new();
    for (u, v, p, q) in &pieces_a {
        if set_b.contains(&(*u, *v)) {
            g.push(*u, *v);
        } else if !set_b.contains(&(*v, *u)) {
            probe_a.push((*u, *v, p.midpoint(q)));
        }
    }
    // MRS-d: pieces of 𝒦 inside ρ(𝒥) (shared pieces were settled in MRS-c).
    let mut probe_b = Vec::new();
    for (u, v, p, q) in &pieces_b {
        if !set_a.contains(&(*u, *v)) && !set_a.contains(&(*v, *u)) {
            probe_b.push((*u, *v, p.midpoint(q)));
        }
    }
    for (probes, region) in [(probe_a, b), (probe_b, a)] {
        let mids: Vec<Point<N>> = probes.iter().map(|x| x.2.clone()).collect();
        for ((u, v, _), loc) in probes.iter().zip(region.locate(&mids, &ctx)) {
            if loc == Location::Inside {
                g.push(*u, *v);
            }
        }
    }
    g.paste_exact(ctx)
}

/// Float mode's Boolean operations, one pipeline on grid integers: snap-round both operands'
/// boundaries together and keep the faces where `keep(in 𝒥, in 𝒦)` holds, decided by the
/// winding numbers per operand ([`regularize`]).
pub(crate) fn overlay<N: Num>(
    a: &Spadjor<N>,
    b: &Spadjor<N>,
    ctx: N::Ctx,
    keep: impl Fn(bool, bool) -> bool,
) -> Result<YinSet2<N>, YinError> {
    let pieces: Vec<(Edge<N>, usize)> = [a, b]
        .iter()
        .enumerate()
        .flat_map(|(label, s)| {
            s.edges()
                .into_iter()
                .map(move |(p, q)| ((p.clone(), q.clone()), label))
        })
        .collect();
    let (ua, ub) = (!a.bounded, !b.bounded);
    regularize(&pieces, ctx, |w| {
        keep(inside_set(w[0], ua), inside_set(w[1], ub))
    })
}
