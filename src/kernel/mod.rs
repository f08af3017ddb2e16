//! Predicates and constructions: the only layer that looks at coordinates' arithmetic
//! (crate docs: *Architecture*). Every decision reduces to [`crate::num::Num::orient2d`] and the
//! exact order of numbers, so it is exact in exact mode and ε-consistent in float mode.

mod angle;
mod point;
mod point3;
mod segment;

pub use angle::cmp_clockwise_from;
pub use point::{orient, BBox, Point};
pub use point3::{orient3d, BBox3, Point3};
pub(crate) use segment::crossing_point;
pub use segment::{classify, crosses, on_closed_segment, Contact};
