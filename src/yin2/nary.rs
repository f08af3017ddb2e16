//! The join and meet of many Yin sets by divide and conquer: the operands are split
//! in halves, each half is reduced (on rayon's threads), and the two partial results are met or
//! joined once more — ⌈log₂ k⌉ levels of binary operations for k operands.
//!
//! A single fill of all boundaries at once (by the count of containing operands) was tried
//! first and measured slower on the workload it was meant for: on k nearly coincident copies of
//! a polygon it meets every edge with every other (Θ(k²) crossings, W6 at 300 copies over
//! 5 minutes exact), while the partial unions of divide and conquer stay as small as the
//! result, so their binary operations never see the edges interior to a half (W6: 300 copies in
//! under a second exact, benches/BENCHMARKS.md). In float mode every level snap-rounds once
//! ([`crate::num::Tolerance`]), so a vertex of the result moves by at most ⌈log₂ k⌉ grid steps'
//! rounding, against one for a binary operation.

use super::set::YinSet2;
use crate::num::Num;

impl<N: Num> YinSet2<N> {
    /// The join ⋁ of all `sets`, the regularized union (0̂ for none), by divide and conquer over
    /// binary joins (module documentation); equal to the fold of [`YinSet2::join`] in exact
    /// mode.
    ///
    /// ```
    /// use yinset::{kernel::Point, num::Rational, yin2::YinSet2};
    /// let p = Point::<Rational>::int;
    /// let square = |x: i64| YinSet2::from_curves(vec![vec![p(x, 0), p(x + 2, 0), p(x + 2, 2), p(x, 2)]]).unwrap();
    /// let row: Vec<_> = (0..3).map(square).collect();
    /// let union = YinSet2::join_all(&row);
    /// assert_eq!(union.area(), Some(Rational::from_integer(8.into())));
    /// assert_eq!(union, row[0].join(&row[1]).join(&row[2]));
    /// ```
    #[doc(alias = "union_all")]
    pub fn join_all(sets: &[YinSet2<N>]) -> YinSet2<N> {
        reduce(sets, &YinSet2::empty, &YinSet2::join)
    }

    /// The meet ⋀ of all `sets`, the regularized intersection (1̂ for none), by divide and
    /// conquer over binary meets; equal to the fold of [`YinSet2::meet`] in exact mode.
    ///
    /// ```
    /// use yinset::{kernel::Point, num::{Num, Rational}, yin2::YinSet2};
    /// let sq = |x: i64, y: i64, s: i64| {
    ///     let p = Point::<Rational>::int;
    ///     YinSet2::from_curves(vec![vec![p(x, y), p(x + s, y), p(x + s, y + s), p(x, y + s)]]).unwrap()
    /// };
    /// let sets = [sq(0, 0, 3), sq(1, 1, 3), sq(2, 2, 3)];
    /// let m = YinSet2::meet_all(&sets);
    /// assert_eq!(m, sq(2, 2, 1));
    /// assert_eq!(m.area(), Some(Rational::from_i64(1)));
    /// ```
    #[doc(alias = "intersection_all")]
    pub fn meet_all(sets: &[YinSet2<N>]) -> YinSet2<N> {
        reduce(sets, &YinSet2::full, &YinSet2::meet)
    }
}

/// `op` over all `sets` as a balanced tree, the halves on rayon's threads; `neutral()` for none.
fn reduce<N: Num>(
    sets: &[YinSet2<N>],
    neutral: &(impl Fn() -> YinSet2<N> + Sync),
    op: &(impl Fn(&YinSet2<N>, &YinSet2<N>) -> YinSet2<N> + Sync),
) -> YinSet2<N> {
    match sets {
        [] => neutral(),
        [one] => one.clone(),
        _ => {
            let (lo, hi) = sets.split_at(sets.len() / 2);
            let (a, b) = rayon::join(|| reduce(lo, neutral, op), || reduce(hi, neutral, op));
            op(&a, &b)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::kernel::Point;
    use crate::num::{Float, Tolerance};

    /// The square [x, x + 2] × [y, y + 2] in float mode, or its complement.
    fn square(x: f64, y: f64, outside: bool) -> YinSet2<Float> {
        let p = |x: f64, y: f64| Point::new(Float::new(x), Float::new(y));
        let mut ring = vec![p(x, y), p(x + 2.0, y), p(x + 2.0, y + 2.0), p(x, y + 2.0)];
        if outside {
            ring.reverse();
        }
        YinSet2::from_curves_with(vec![ring], Tolerance::new(1e-9)).unwrap()
    }

    #[test]
    fn float_join_and_meet_of_overlapping_squares() {
        // Three squares shifted by 1 along the diagonal: union area 3·4 − 2·1, meet of all empty,
        // meet of the first two the unit square [1, 2]².
        let sets: Vec<_> = (0..3).map(|k| square(k as f64, k as f64, false)).collect();
        let join = YinSet2::join_all(&sets);
        assert!(join.validate().is_ok());
        assert_eq!(join.area().map(|a| a.to_f64()), Some(10.0));
        assert!(YinSet2::meet_all(&sets).is_empty());
        assert_eq!(
            YinSet2::meet_all(&sets[..2]).area().map(|a| a.to_f64()),
            Some(1.0)
        );
        // With the complement of [1, 3]²: the join misses [1, 3]² ∖ [0, 2]², area 4 − 1.
        let with_hole = [sets[0].clone(), square(1.0, 1.0, true)];
        let join = YinSet2::join_all(&with_hole);
        assert!(!join.is_bounded());
        assert_eq!(join.complement().area().map(|a| a.to_f64()), Some(3.0));
    }

    #[test]
    fn empty_and_full_operands_decide_or_drop_out() {
        let (e, f) = (YinSet2::<Float>::empty(), YinSet2::<Float>::full());
        let a = square(0.0, 0.0, false);
        assert!(YinSet2::<Float>::join_all(&[]).is_empty());
        assert!(YinSet2::<Float>::meet_all(&[]).is_full());
        assert!(YinSet2::join_all(&[a.clone(), f.clone()]).is_full());
        assert!(YinSet2::meet_all(&[a.clone(), e.clone()]).is_empty());
        assert_eq!(YinSet2::join_all(&[e, a.clone()]), a);
        assert_eq!(YinSet2::meet_all(&[f, a.clone()]), a);
        // A set and its complement: every edge cancels, and the far face decides.
        assert!(YinSet2::join_all(&[a.clone(), a.complement()]).is_full());
    }
}
