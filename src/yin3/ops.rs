//! The Boolean operations (yin3 docs: *Meet*, *Complement*): the meet, by the transversal meet
//! where it applies ([`super::grid`]; float mode: [`super::float`]) and else by the general
//! arrangement ([`super::meet`]); complement (seed 000 Def. 4.4 in 3D), join by De Morgan
//! (Def. 4.10), difference, symmetric difference, and the operators `!`, `&`, `|`, `-`, `^`.

use super::error::Yin3Error;
use super::float::{float_meet, rounded_exact};
use super::grid::exact_transversal_meet;
use super::meet::meet_in;
use super::set::{Repr3, YinSet3};
use crate::num::Num;
use rayon::prelude::*;
use std::ops::{BitAnd, BitOr, BitXor, Not, Sub};

impl<N: Num> YinSet3<N> {
    /// The meet 𝒴 ∧ 𝒵 (seed 000 Def. 4.8 lifted to 3D by seed 004): the regularized
    /// intersection.
    ///
    /// # Panics
    /// Only in float mode, when the result has no valid `f64` representation
    /// ([`Yin3Error::Unrepresentable`]); [`YinSet3::try_meet`] returns that error instead.
    ///
    /// ```
    /// use yinset::{kernel::Point3, num::{Num, Rational}, yin3::YinSet3};
    /// let cube = |x: i64, y: i64, z: i64, s: i64| {
    ///     YinSet3::<Rational>::cuboid(&Point3::int(x, y, z), &Point3::int(x + s, y + s, z + s)).unwrap()
    /// };
    /// let m = cube(0, 0, 0, 2).meet(&cube(1, 1, 1, 2)); // also `&a & &b`
    /// assert_eq!(m, cube(1, 1, 1, 1));
    /// // Cubes sharing a face meet in nothing (the sets are open).
    /// assert!(cube(0, 0, 0, 1).meet(&cube(1, 0, 0, 1)).is_empty());
    /// ```
    pub fn meet(&self, other: &YinSet3<N>) -> YinSet3<N> {
        or_panic(self.try_meet(other), "meet")
    }

    /// The meet, or in float mode the error that it has no valid `f64` representation
    /// (exact mode never fails). Float mode follows the contract in the module docs of
    /// [`crate::yin3`], *Float mode*.
    ///
    /// ```
    /// use yinset::{kernel::Point3, num::{Num, Rational}, yin3::YinSet3};
    /// let cube = |x: i64, y: i64, z: i64, s: i64| {
    ///     YinSet3::<Rational>::cuboid(&Point3::int(x, y, z), &Point3::int(x + s, y + s, z + s)).unwrap()
    /// };
    /// let m = cube(0, 0, 0, 2).try_meet(&cube(1, 1, 1, 2))?; // exact mode never fails
    /// assert_eq!(m.volume(), Some(Rational::from_i64(1)));
    /// # Ok::<(), yinset::yin3::Yin3Error>(())
    /// ```
    pub fn try_meet(&self, other: &YinSet3<N>) -> Result<YinSet3<N>, Yin3Error> {
        let ctx = N::combine_ctx(self.ctx, other.ctx);
        let (a, b) = match (self.brep(), other.brep()) {
            _ if self.is_empty() || other.is_empty() => return Ok(YinSet3::empty().with_ctx(ctx)),
            (None, _) => return Ok(other.clone().with_ctx(ctx)),
            (_, None) => return Ok(self.clone().with_ctx(ctx)),
            (Some(a), Some(b)) => (a, b),
        };
        if a.bounded
            && b.bounded
            && !self
                .bbox()
                .zip(other.bbox())
                .is_some_and(|(x, y)| x.meets(&y))
        {
            return Ok(YinSet3::empty().with_ctx(ctx));
        }
        if N::EXACT {
            exact_transversal_meet([self, other], [a, b], ctx).unwrap_or_else(|| meet_in(a, b, ctx))
        } else {
            float_meet([self, other], [a, b], ctx)
        }
    }

    /// The complement 𝒴' = ℝ³ ∖ closure(𝒴): 0̂ ↔ 1̂, otherwise every triangle reversed and the
    /// glued surfaces regrouped.
    ///
    /// ```
    /// use yinset::{kernel::Point3, num::{Num, Rational}, yin3::YinSet3};
    /// let cube = |x: i64, y: i64, z: i64, s: i64| {
    ///     YinSet3::<Rational>::cuboid(&Point3::int(x, y, z), &Point3::int(x + s, y + s, z + s)).unwrap()
    /// };
    /// use yinset::yin2::Location;
    /// let a = cube(0, 0, 0, 1);
    /// let out = a.complement(); // also `!&a`
    /// assert!(!out.is_bounded());
    /// assert_eq!(out.locate(&[Point3::int(5, 5, 5)]), vec![Location::Inside]);
    /// assert_eq!(out.betti().b2, 1); // ℝ³ minus a cube: one cavity
    /// assert_eq!(out.complement(), a);
    /// ```
    pub fn complement(&self) -> YinSet3<N> {
        match &self.repr {
            Repr3::Empty => YinSet3::full().with_ctx(self.ctx),
            Repr3::Full => YinSet3::empty().with_ctx(self.ctx),
            Repr3::Brep(b) => YinSet3::from_brep(b.complement(), self.ctx),
        }
    }

    /// The meets 𝒴 ∧ 𝒵ᵢ with every cell 𝒵ᵢ, in order, on rayon's threads: the cut of a fluid
    /// by control volumes (seed 000 §5.5 in 3D); the first error of [`YinSet3::try_meet`] (float
    /// mode only). `RAYON_NUM_THREADS=1` runs it on one thread.
    ///
    /// ```
    /// use yinset::{kernel::Point3, num::{Num, Rational}, yin3::YinSet3};
    /// let cube = |x: i64, y: i64, z: i64, s: i64| {
    ///     YinSet3::<Rational>::cuboid(&Point3::int(x, y, z), &Point3::int(x + s, y + s, z + s)).unwrap()
    /// };
    /// // The cube [0, 2]³ cut by the eight unit cells of a grid.
    /// let cells: Vec<_> = (0..8).map(|i| cube(i & 1, i >> 1 & 1, i >> 2 & 1, 1)).collect();
    /// let parts = cube(0, 0, 0, 2).meet_each(&cells)?;
    /// assert!(parts.iter().all(|c| c.volume() == Some(Rational::from_i64(1))));
    /// # Ok::<(), yinset::yin3::Yin3Error>(())
    /// ```
    pub fn meet_each(&self, cells: &[YinSet3<N>]) -> Result<Vec<YinSet3<N>>, Yin3Error> {
        cells.par_iter().map(|c| self.try_meet(c)).collect()
    }

    /// The join 𝒴 ∨ 𝒵 := (𝒴' ∧ 𝒵')' (seed 000 Def. 4.10), the regularized union. Panics as
    /// [`YinSet3::meet`] does; [`YinSet3::try_join`] returns the error.
    ///
    /// ```
    /// use yinset::{kernel::Point3, num::{Num, Rational}, yin3::YinSet3};
    /// let cube = |x: i64, y: i64, z: i64, s: i64| {
    ///     YinSet3::<Rational>::cuboid(&Point3::int(x, y, z), &Point3::int(x + s, y + s, z + s)).unwrap()
    /// };
    /// let j = cube(0, 0, 0, 2).join(&cube(1, 1, 1, 2)); // also `&a | &b`
    /// assert_eq!(j.volume(), Some(Rational::from_i64(15)));
    /// assert_eq!(cube(0, 0, 0, 1).join(&cube(1, 0, 0, 1)).surfaces().len(), 1); // sharing a face
    /// ```
    pub fn join(&self, other: &YinSet3<N>) -> YinSet3<N> {
        or_panic(self.try_join(other), "join")
    }

    /// The join, or float mode's error ([`YinSet3::try_meet`]).
    ///
    /// ```
    /// use yinset::{kernel::Point3, num::Float, yin3::YinSet3};
    /// let cube = |x: f64| {
    ///     let p = |x: f64, y: f64, z: f64| Point3::new(Float::new(x), Float::new(y), Float::new(z));
    ///     YinSet3::cuboid(&p(x, 0.0, 0.0), &p(x + 2.0, 2.0, 2.0))
    /// };
    /// let j = cube(0.0)?.try_join(&cube(1.0)?)?; // float mode: an error instead of a panic
    /// assert_eq!(j.volume().unwrap().get(), 12.0);
    /// # Ok::<(), yinset::yin3::Yin3Error>(())
    /// ```
    pub fn try_join(&self, other: &YinSet3<N>) -> Result<YinSet3<N>, Yin3Error> {
        Ok(self
            .complement()
            .try_meet(&other.complement())?
            .complement())
    }

    /// The difference 𝒴 ∧ 𝒵'. Panics as [`YinSet3::meet`] does.
    ///
    /// ```
    /// use yinset::{kernel::Point3, num::{Num, Rational}, yin3::YinSet3};
    /// let cube = |x: i64, y: i64, z: i64, s: i64| {
    ///     YinSet3::<Rational>::cuboid(&Point3::int(x, y, z), &Point3::int(x + s, y + s, z + s)).unwrap()
    /// };
    /// let d = cube(0, 0, 0, 2).difference(&cube(1, 1, 1, 2)); // also `&a - &b`
    /// assert_eq!(d.volume(), Some(Rational::from_i64(7)));
    /// ```
    pub fn difference(&self, other: &YinSet3<N>) -> YinSet3<N> {
        or_panic(self.try_difference(other), "difference")
    }

    /// The difference, or float mode's error ([`YinSet3::try_meet`]).
    ///
    /// ```
    /// use yinset::{kernel::Point3, num::{Num, Rational}, yin3::YinSet3};
    /// let cube = |x: i64, y: i64, z: i64, s: i64| {
    ///     YinSet3::<Rational>::cuboid(&Point3::int(x, y, z), &Point3::int(x + s, y + s, z + s)).unwrap()
    /// };
    /// let d = cube(0, 0, 0, 2).try_difference(&cube(0, 0, 0, 1))?;
    /// assert_eq!(d.volume(), Some(Rational::from_i64(7)));
    /// # Ok::<(), yinset::yin3::Yin3Error>(())
    /// ```
    pub fn try_difference(&self, other: &YinSet3<N>) -> Result<YinSet3<N>, Yin3Error> {
        self.try_meet(&other.complement())
    }

    /// The symmetric difference (𝒴 ∧ 𝒵') ∨ (𝒴' ∧ 𝒵). Panics as [`YinSet3::meet`] does.
    ///
    /// ```
    /// use yinset::{kernel::Point3, num::{Num, Rational}, yin3::YinSet3};
    /// let cube = |x: i64, y: i64, z: i64, s: i64| {
    ///     YinSet3::<Rational>::cuboid(&Point3::int(x, y, z), &Point3::int(x + s, y + s, z + s)).unwrap()
    /// };
    /// let (a, b) = (cube(0, 0, 0, 2), cube(1, 1, 1, 2));
    /// let x = a.symmetric_difference(&b); // also `&a ^ &b`
    /// assert_eq!(x.volume(), Some(Rational::from_i64(14)));
    /// assert_eq!(x, &(&a - &b) | &(&b - &a));
    /// ```
    pub fn symmetric_difference(&self, other: &YinSet3<N>) -> YinSet3<N> {
        or_panic(self.try_symmetric_difference(other), "symmetric difference")
    }

    /// The symmetric difference, or float mode's error ([`YinSet3::try_meet`]). Float mode
    /// computes it exactly and rounds once, so that it keeps the exact result's topology.
    ///
    /// ```
    /// use yinset::{kernel::Point3, num::{Num, Rational}, yin3::YinSet3};
    /// let cube = |x: i64, y: i64, z: i64, s: i64| {
    ///     YinSet3::<Rational>::cuboid(&Point3::int(x, y, z), &Point3::int(x + s, y + s, z + s)).unwrap()
    /// };
    /// let x = cube(0, 0, 0, 1).try_symmetric_difference(&cube(1, 0, 0, 1))?;
    /// assert_eq!(x.volume(), Some(Rational::from_i64(2))); // disjoint interiors: the union
    /// # Ok::<(), yinset::yin3::Yin3Error>(())
    /// ```
    pub fn try_symmetric_difference(&self, other: &YinSet3<N>) -> Result<YinSet3<N>, Yin3Error> {
        if !N::EXACT {
            let ctx = N::combine_ctx(self.ctx, other.ctx);
            return rounded_exact(self, other, ctx, YinSet3::symmetric_difference);
        }
        self.try_difference(other)?
            .try_join(&other.try_difference(self)?)
    }

    /// True if `self` ≤ `other` in the Boolean algebra.
    ///
    /// ```
    /// use yinset::{kernel::Point3, num::{Num, Rational}, yin3::YinSet3};
    /// let cube = |x: i64, y: i64, z: i64, s: i64| {
    ///     YinSet3::<Rational>::cuboid(&Point3::int(x, y, z), &Point3::int(x + s, y + s, z + s)).unwrap()
    /// };
    /// assert!(cube(1, 1, 1, 1).is_subset(&cube(0, 0, 0, 3)));
    /// assert!(!cube(0, 0, 0, 3).is_subset(&cube(1, 1, 1, 1)));
    /// ```
    pub fn is_subset(&self, other: &YinSet3<N>) -> bool {
        self.meet(other) == *self
    }

    /// The same set under the number context `ctx`.
    pub(crate) fn with_ctx(mut self, ctx: N::Ctx) -> YinSet3<N> {
        self.ctx = ctx;
        self
    }
}

/// The result of an operation, or a panic naming it (float mode only; see `try_meet`).
pub(crate) fn or_panic<N: Num>(r: Result<YinSet3<N>, Yin3Error>, op: &str) -> YinSet3<N> {
    r.unwrap_or_else(|e| panic!("3D {op} failed (float mode: use the try_ method): {e}"))
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
