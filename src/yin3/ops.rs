//! Complement (seed 000 Def. 4.4 in 3D), join by De Morgan (Def. 4.10), difference, symmetric
//! difference, and the operators `!`, `&`, `|`, `-`, `^` (DESIGN-3D §2.9–2.10).

use super::set::{Brep, Repr3, YinSet3};
use crate::num::Num;
use std::ops::{BitAnd, BitOr, BitXor, Not, Sub};

impl<N: Num> YinSet3<N> {
    /// The complement 𝒴' = ℝ³ ∖ closure(𝒴): 0̂ ↔ 1̂, otherwise every triangle reversed and the
    /// glued surfaces regrouped.
    pub fn complement(&self) -> YinSet3<N> {
        match &self.repr {
            Repr3::Empty => YinSet3::full(),
            Repr3::Full => YinSet3::empty(),
            Repr3::Brep(b) => {
                let tris = b.tris.iter().map(|&[p, q, r]| [p, r, q]).collect();
                let brep = Brep::assemble(b.points.clone(), tris, &self.ctx)
                    .unwrap_or_else(|e| panic!("the reversed boundary of a Yin set is one: {e}"));
                YinSet3::from_brep(brep, self.ctx)
            }
        }
    }

    /// The join 𝒴 ∨ 𝒵 := (𝒴' ∧ 𝒵')' (seed 000 Def. 4.10), the regularized union.
    pub fn join(&self, other: &YinSet3<N>) -> YinSet3<N> {
        self.complement().meet(&other.complement()).complement()
    }

    /// The difference 𝒴 ∧ 𝒵'.
    pub fn difference(&self, other: &YinSet3<N>) -> YinSet3<N> {
        self.meet(&other.complement())
    }

    /// The symmetric difference (𝒴 ∧ 𝒵') ∨ (𝒴' ∧ 𝒵).
    pub fn symmetric_difference(&self, other: &YinSet3<N>) -> YinSet3<N> {
        self.difference(other).join(&other.difference(self))
    }

    /// True if `self` ≤ `other` in the Boolean algebra.
    pub fn is_subset(&self, other: &YinSet3<N>) -> bool {
        self.meet(other) == *self
    }
}

macro_rules! binary_operator {
    ($tr:ident, $m:ident, $f:ident) => {
        impl<N: Num> $tr<&YinSet3<N>> for &YinSet3<N> {
            type Output = YinSet3<N>;
            #[doc = concat!("`a ", stringify!($m), " b` is [`YinSet3::", stringify!($f), "`].")]
            fn $m(self, rhs: &YinSet3<N>) -> YinSet3<N> {
                self.$f(rhs)
            }
        }
    };
}
binary_operator!(BitAnd, bitand, meet);
binary_operator!(BitOr, bitor, join);
binary_operator!(Sub, sub, difference);
binary_operator!(BitXor, bitxor, symmetric_difference);

impl<N: Num> Not for &YinSet3<N> {
    type Output = YinSet3<N>;
    /// `!a` is the complement.
    fn not(self) -> YinSet3<N> {
        self.complement()
    }
}
