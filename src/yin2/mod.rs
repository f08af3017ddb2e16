//! The 2D Yin space (seed 000): Jordan curves, spadjors, and the Boolean algebra on them.

mod arrangement;
mod buckets;
mod complement;
mod convert;
mod curve;
mod error;
mod faces;
mod fill;
mod grid_arrange;
mod grid_pairs;
mod hasse;
mod homology;
mod hot_pixels;
pub mod intersect;
mod locate;
mod meet;
mod nary;
mod ops;
mod paste;
mod set;
mod snap;
mod stage;
mod status;
mod validate;
mod vertex;
mod winding;

pub use curve::Curve;
pub use error::YinError;
pub use fill::FillRule;
pub use hasse::{Atom, Betti};
pub use homology::Homology;
pub use locate::{locate_in_edges, Location};
pub use set::YinSet2;
