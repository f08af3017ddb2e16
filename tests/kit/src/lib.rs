//! The test kit of yinset: what the integration tests (tests/), the bounded-exhaustive proofs
//! (proofs/) and the fuzz targets (fuzz/) check the kernel with, written once.
//!
//! * [`laws`]: the Boolean-algebra laws (seed 000 Thm 4.11), generic over the 2D and 3D Yin
//!   spaces, counted per law in a [`laws::Tally`], and the cell oracles' common checks;
//! * [`membership`]: the point-membership oracle, locate(p, a op b) = locate(p, a) op
//!   locate(p, b) off both operands' boundaries;
//! * [`cells`] and [`cells3`]: the cell oracles, unions of the pieces of a planar subdivision
//!   and of the unit cells of a 3D grid, whose expected sets, Betti numbers, measures and
//!   locations are read off the masks without the kernel's operations;
//! * [`ops`]: the Boolean operations by name, exact and in 3D float mode;
//! * [`geom3`]: exact integer geometry of 3D boundaries and the ray-parity oracle;
//! * [`rotation`]: rational rotations for general position;
//! * [`shapes`]: integer meshes of boxes, tetrahedra and cell blocks, and descriptions of sets
//!   for failure messages.

#![warn(missing_docs)]
// A universe of cells always has cells: its `len` needs no `is_empty`.
#![allow(clippy::len_without_is_empty)]

mod arrangement;
pub mod cells;
pub mod cells3;
pub mod geom3;
pub mod laws;
pub mod membership;
pub mod ops;
pub mod rotation;
pub mod shapes;

use yinset::kernel::Point3;
use yinset::num::Rational;
use yinset::yin2::YinSet2;
use yinset::yin3::YinSet3;

/// The case count of a property test: `default`, or at most `YINSET_CASES` when that
/// environment variable is set (the mutation run's reduced counts, mutants/run.py).
pub fn cases(default: u32) -> u32 {
    std::env::var("YINSET_CASES")
        .ok()
        .and_then(|v| v.parse().ok())
        .map_or(default, |cap: u32| default.min(cap))
}

/// An exact 2D Yin set.
pub type Y = YinSet2<Rational>;
/// An exact 3D Yin set.
pub type Y3 = YinSet3<Rational>;
/// An exact point of space.
pub type P3 = Point3<Rational>;

/// Exact rational n/d.
pub fn q(n: i64, d: i64) -> Rational {
    Rational::new(n.into(), d.into())
}
