//! The join and meet of many Yin sets in one fill of all their boundaries (issue 13), instead
//! of a fold of binary operations.
//!
//! Every Yin set's boundary is oriented with the set on its left (seed 000 Def. 3.10), so off
//! the boundaries the winding number of 𝒥's curves is 1 inside 𝒥 and 0 outside when 𝒥 is
//! bounded, and 0 inside, −1 outside when it is not. The number of operands containing a point
//! is therefore w + u, for w the winding number of all operands' curves together and u the
//! number of unbounded operands: the join is where w + u ≥ 1, the meet where w + u = k for k
//! operands — one fill ([`fill_edges`]: a sweep for the contacts of all edges, one for the
//! winding numbers of the pieces, then the pasting map), O((n + I) log n) for n edges with I
//! contacts.

use super::fill::fill_edges;
use super::paste::or_kernel_bug;
use super::set::{Repr, YinSet2};
use crate::num::Num;

/// Which count of containing operands is inside the result.
#[derive(Clone, Copy)]
enum Count {
    /// At least one operand (join).
    Any,
    /// Every operand (meet).
    All,
}

impl<N: Num> YinSet2<N> {
    /// The join ⋁ of all `sets`, the regularized union (0̂ for none), in one sweep over all
    /// boundary edges instead of `sets.len() − 1` binary joins; equal to the fold of
    /// [`YinSet2::join`].
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
        nary(sets, Count::Any)
    }

    /// The meet ⋀ of all `sets`, the regularized intersection (1̂ for none), in one sweep over
    /// all boundary edges; equal to the fold of [`YinSet2::meet`].
    #[doc(alias = "intersection_all")]
    pub fn meet_all(sets: &[YinSet2<N>]) -> YinSet2<N> {
        nary(sets, Count::All)
    }
}

/// The set of points contained in `count` of the operands, by winding numbers (module
/// documentation). 0̂ and 1̂ operands have no curves and decide or drop out first.
fn nary<N: Num>(sets: &[YinSet2<N>], count: Count) -> YinSet2<N> {
    let ctx = sets
        .iter()
        .map(|s| s.ctx())
        .reduce(N::combine_ctx)
        .unwrap_or_default();
    let (absorbing, neutral) = match count {
        Count::Any => (YinSet2::full(), YinSet2::empty()),
        Count::All => (YinSet2::empty(), YinSet2::full()),
    };
    let mut spadjors = Vec::new();
    for s in sets {
        match (&s.repr, count) {
            (Repr::Spadjor(a), _) => spadjors.push(a),
            (Repr::Full, Count::Any) | (Repr::Empty, Count::All) => return absorbing.with_ctx(ctx),
            _ => {}
        }
    }
    if spadjors.is_empty() {
        return neutral.with_ctx(ctx);
    }
    let k = spadjors.len() as i64;
    let unbounded = spadjors.iter().filter(|a| !a.bounded).count() as i64;
    let edges = spadjors
        .iter()
        .flat_map(|a| a.edges())
        .map(|(p, q)| (p.clone(), q.clone()))
        .collect();
    or_kernel_bug(fill_edges(edges, ctx, |w| match count {
        Count::Any => w + unbounded >= 1,
        Count::All => w + unbounded == k,
    }))
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
