//! Join by De Morgan (seed 000 Def. 4.10), difference, symmetric difference, and operators.

use super::meet::overlay;
use super::paste::or_kernel_bug;
use super::set::{Repr, YinSet2};
use crate::num::Num;
use rayon::prelude::*;
use std::ops::{BitAnd, BitOr, BitXor, Not, Sub};

impl<N: Num> YinSet2<N> {
    /// The join 𝒥 ∨ 𝒦 := (𝒥' ∧ 𝒦')' (seed 000 Def. 4.10), the regularized union.
    ///
    /// ```
    /// use yinset::{kernel::Point, num::{Num, Rational}, yin2::YinSet2};
    /// let sq = |x: i64, y: i64, s: i64| {
    ///     let p = Point::<Rational>::int;
    ///     YinSet2::from_curves(vec![vec![p(x, y), p(x + s, y), p(x + s, y + s), p(x, y + s)]]).unwrap()
    /// };
    /// let j = sq(0, 0, 2).join(&sq(1, 1, 2)); // also `&a | &b`
    /// assert_eq!(j.area(), Some(Rational::from_i64(7)));
    /// // Squares sharing an edge join into one rectangle.
    /// let r = sq(0, 0, 1).join(&sq(1, 0, 1));
    /// assert_eq!((r.curves().len(), r.area()), (1, Some(Rational::from_i64(2))));
    /// ```
    pub fn join(&self, other: &YinSet2<N>) -> YinSet2<N> {
        self.overlay_with(other, |x, y| x || y)
            .unwrap_or_else(|| self.complement().meet(&other.complement()).complement())
    }

    /// The difference 𝒥 ∧ 𝒦'.
    ///
    /// ```
    /// use yinset::{kernel::Point, num::{Num, Rational}, yin2::YinSet2};
    /// let sq = |x: i64, y: i64, s: i64| {
    ///     let p = Point::<Rational>::int;
    ///     YinSet2::from_curves(vec![vec![p(x, y), p(x + s, y), p(x + s, y + s), p(x, y + s)]]).unwrap()
    /// };
    /// let d = sq(0, 0, 2).difference(&sq(1, 1, 2)); // also `&a - &b`
    /// assert_eq!(d.area(), Some(Rational::from_i64(3)));
    /// assert_eq!(sq(1, 1, 1).difference(&sq(0, 0, 3)), YinSet2::empty());
    /// ```
    pub fn difference(&self, other: &YinSet2<N>) -> YinSet2<N> {
        self.overlay_with(other, |x, y| x && !y)
            .unwrap_or_else(|| self.meet(&other.complement()))
    }

    /// The symmetric difference (𝒥 ∧ 𝒦') ∨ (𝒥' ∧ 𝒦).
    ///
    /// ```
    /// use yinset::{kernel::Point, num::{Num, Rational}, yin2::YinSet2};
    /// let sq = |x: i64, y: i64, s: i64| {
    ///     let p = Point::<Rational>::int;
    ///     YinSet2::from_curves(vec![vec![p(x, y), p(x + s, y), p(x + s, y + s), p(x, y + s)]]).unwrap()
    /// };
    /// let (a, b) = (sq(0, 0, 2), sq(1, 1, 2));
    /// let x = a.symmetric_difference(&b); // also `&a ^ &b`
    /// assert_eq!(x.area(), Some(Rational::from_i64(6)));
    /// assert_eq!(x, &(&a - &b) | &(&b - &a));
    /// ```
    pub fn symmetric_difference(&self, other: &YinSet2<N>) -> YinSet2<N> {
        self.overlay_with(other, |x, y| x != y)
            .unwrap_or_else(|| self.difference(other).join(&other.difference(self)))
    }

    /// The operation `keep` on two spadjors in one overlay of both boundaries ([`overlay`],
    /// exact or float); `None` if either operand is 0̂ or 1̂.
    fn overlay_with(
        &self,
        other: &YinSet2<N>,
        keep: impl Fn(bool, bool) -> bool,
    ) -> Option<YinSet2<N>> {
        let ctx = N::combine_ctx(self.ctx, other.ctx);
        match (&self.repr, &other.repr) {
            (Repr::Spadjor(a), Repr::Spadjor(b)) => Some(or_kernel_bug(overlay(a, b, ctx, keep))),
            _ => None,
        }
    }

    /// The meets 𝒥 ∧ 𝒦ᵢ with every cell 𝒦ᵢ, in order, on rayon's threads: the cut of a fluid
    /// by control volumes (seed 000 §5.5); `RAYON_NUM_THREADS=1` runs it on one thread.
    ///
    /// ```
    /// use yinset::{kernel::Point, num::{Num, Rational}, yin2::YinSet2};
    /// let sq = |x: i64, y: i64, s: i64| {
    ///     let p = Point::<Rational>::int;
    ///     YinSet2::from_curves(vec![vec![p(x, y), p(x + s, y), p(x + s, y + s), p(x, y + s)]]).unwrap()
    /// };
    /// // The square [0, 2]² cut by the four unit cells of a grid.
    /// let cells: Vec<_> = [(0, 0), (1, 0), (0, 1), (1, 1)].iter().map(|&(x, y)| sq(x, y, 1)).collect();
    /// let parts = sq(0, 0, 2).meet_each(&cells);
    /// assert!(parts.iter().all(|c| c.area() == Some(Rational::from_i64(1))));
    /// assert_eq!(parts[3], cells[3]);
    /// ```
    pub fn meet_each(&self, cells: &[YinSet2<N>]) -> Vec<YinSet2<N>> {
        cells.par_iter().map(|c| self.meet(c)).collect()
    }

    /// True if `self` ≤ `other` in the Boolean algebra (ρ(self) ⊆ ρ(other)).
    ///
    /// ```
    /// use yinset::{kernel::Point, num::{Num, Rational}, yin2::YinSet2};
    /// let sq = |x: i64, y: i64, s: i64| {
    ///     let p = Point::<Rational>::int;
    ///     YinSet2::from_curves(vec![vec![p(x, y), p(x + s, y), p(x + s, y + s), p(x, y + s)]]).unwrap()
    /// };
    /// assert!(sq(1, 1, 1).is_subset(&sq(0, 0, 3)));
    /// assert!(!sq(0, 0, 3).is_subset(&sq(1, 1, 1)));
    /// assert!(YinSet2::empty().is_subset(&sq(0, 0, 1)));
    /// ```
    pub fn is_subset(&self, other: &YinSet2<N>) -> bool {
        self.meet(other) == *self
    }
}

macro_rules! binary_operator {
    ($tr:ident, $m:ident, $f:ident) => {
        impl<N: Num> $tr<&YinSet2<N>> for &YinSet2<N> {
            type Output = YinSet2<N>;
            #[doc = concat!("`a ", stringify!($m), " b` is [`YinSet2::", stringify!($f), "`].")]
            fn $m(self, rhs: &YinSet2<N>) -> YinSet2<N> {
                self.$f(rhs)
            }
        }
    };
}
binary_operator!(BitAnd, bitand, meet);
binary_operator!(BitOr, bitor, join);
binary_operator!(Sub, sub, difference);
binary_operator!(BitXor, bitxor, symmetric_difference);

impl<N: Num> Not for &YinSet2<N> {
    type Output = YinSet2<N>;
    /// `!a` is the complement (seed 000 Def. 4.4).
    fn not(self) -> YinSet2<N> {
        self.complement()
    }
}
