//! Homological Betti numbers of a 2D Yin set, beside the seed's count of holes (seed 000
//! Cor. 3.14), which counts a hole pinched to the outer curve at a point as a hole.

use super::set::YinSet2;
use crate::kernel::Point;
use crate::num::Num;
use crate::union_find::UnionFind;
use foldhash::{HashMap, HashMapExt};

/// The ranks of the singular homology groups H₀ and H₁ of a Yin set as a topological space.
///
/// b₀ is the number of connected components, as in [`super::Betti`]. b₁ differs from the
/// seed's `total_holes` where holes touch: by Alexander duality, b₁ of an open set Y ⊂ ℝ² is
/// the number of components of (ℝ² ∖ Y) ∪ {∞} minus one, and the closed complement ℝ² ∖ Y
/// joins the components of Y′ whose closures share a point. A hole pinched to the outer curve
/// at a vertex is one hole for the seed and none for homology (a loop around it must pass
/// through the pinch point, which is not in Y); two holes touching at a point are two holes
/// for the seed and one homology class.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub struct Homology {
    /// Rank of H₀: connected components.
    pub b0: usize,
    /// Rank of H₁: independent loops.
    pub b1: usize,
}

impl<N: Num> YinSet2<N> {
    /// Homological Betti numbers b₀ and b₁ ([`Homology`]), from the components of the closed
    /// complement: the atoms of the complement (seed 000 Lemma 3.18) joined where they share a
    /// vertex.
    ///
    /// ```
    /// use yinset::{kernel::Point, num::{Num, Rational}, yin2::YinSet2};
    /// let sq = |x: i64, y: i64, s: i64| {
    ///     let p = Point::<Rational>::int;
    ///     YinSet2::from_curves(vec![vec![p(x, y), p(x + s, y), p(x + s, y + s), p(x, y + s)]]).unwrap()
    /// };
    /// // A square with a hole inside: one component, one independent loop.
    /// let ring = &sq(0, 0, 3) - &sq(1, 1, 1);
    /// assert_eq!((ring.homology().b0, ring.homology().b1), (1, 1));
    /// // Two squares touching at a corner: two components, no loop.
    /// let two = &sq(0, 0, 1) | &sq(1, 1, 1);
    /// assert_eq!((two.homology().b0, two.homology().b1), (2, 0));
    /// ```
    pub fn homology(&self) -> Homology {
        let complement = self.complement();
        let atoms = complement.atoms();
        let curves = complement.curves();
        let mut classes = UnionFind::new(atoms.len());
        let mut first_atom_at: HashMap<&Point<N>, usize> = HashMap::new();
        for (k, atom) in atoms.iter().enumerate() {
            for c in atom.outer.iter().chain(&atom.holes) {
                for p in curves[*c].vertices() {
                    let first = *first_atom_at.entry(p).or_insert(k);
                    classes.union(first, k);
                }
            }
        }
        let (_, closed_components) = classes.classes();
        // ∞ belongs to the unbounded component of the complement when Y is bounded, and is a
        // component of its own when Y is unbounded.
        let with_infinity = closed_components + usize::from(!self.is_bounded());
        Homology {
            b0: self.atoms().len() + usize::from(self.is_full()),
            b1: with_infinity.saturating_sub(1),
        }
    }
}
