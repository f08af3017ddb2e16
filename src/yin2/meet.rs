//! Meet (seed 000 Def. 4.8) and the other Boolean operations on two spadjors in
//! O((n + I) log n) (seed 002 §1.3).

use super::error::YinError;
use super::faces::inside_set;
use super::paste::or_kernel_bug;
use super::set::{Repr, Spadjor, YinSet2};
use super::stage::faces_where;
use super::winding::Winding;
use crate::num::Num;

impl<N: Num> YinSet2<N> {
    /// The meet 𝒥 ∧ 𝒦 (seed 000 Def. 4.8): ρ(𝒥 ∧ 𝒦) = ρ(𝒥) ∩ ρ(𝒦).
    ///
    /// ```
    /// use yinset::{kernel::Point, num::{Num, Rational}, yin2::YinSet2};
    /// let sq = |x: i64, y: i64, s: i64| {
    ///     let p = Point::<Rational>::int;
    ///     YinSet2::from_curves(vec![vec![p(x, y), p(x + s, y), p(x + s, y + s), p(x, y + s)]]).unwrap()
    /// };
    /// let m = sq(0, 0, 2).meet(&sq(1, 1, 2)); // also `&a & &b`
    /// assert_eq!(m, sq(1, 1, 1));
    /// assert_eq!(m.area(), Some(Rational::from_i64(1)));
    /// // Squares touching at a corner meet in nothing (the sets are open).
    /// assert!(sq(0, 0, 1).meet(&sq(1, 1, 1)).is_empty());
    /// ```
    pub fn meet(&self, other: &YinSet2<N>) -> YinSet2<N> {
        let ctx = N::combine_ctx(self.ctx, other.ctx);
        match (&self.repr, &other.repr) {
            (Repr::Empty, _) | (_, Repr::Empty) => YinSet2::empty().with_ctx(ctx),
            (Repr::Full, _) => other.clone().with_ctx(ctx),
            (_, Repr::Full) => self.clone().with_ctx(ctx),
            (Repr::Spadjor(a), Repr::Spadjor(b)) => {
                or_kernel_bug(overlay(a, b, ctx, |x, y| x && y))
            }
        }
    }
}

/// The Boolean operation `keep` on two spadjors: the faces where `keep(in 𝒥, in 𝒦)` holds,
/// decided by the winding numbers of each operand's boundary (every boundary is oriented with
/// its set on the left, seed 000 Def. 3.10: off the boundary, 𝒥's winding number is 1 inside
/// and 0 outside a bounded 𝒥, 0 inside and −1 outside an unbounded one), in one arrangement of
/// both boundaries ([`faces_where`]: exact, or snap-rounded in float mode).
pub(crate) fn overlay<N: Num>(
    a: &Spadjor<N>,
    b: &Spadjor<N>,
    ctx: N::Ctx,
    keep: impl Fn(bool, bool) -> bool,
) -> Result<YinSet2<N>, YinError> {
    let (ua, ub) = (!a.bounded, !b.bounded);
    let inside = |w: Winding| keep(inside_set(w[0], ua), inside_set(w[1], ub));
    let rings = [a, b]
        .into_iter()
        .enumerate()
        .flat_map(|(label, s)| s.curves.iter().map(move |c| (c.vertices(), label)));
    faces_where(rings, true, ctx, inside)
}
