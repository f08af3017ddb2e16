//! The 3D Yin space (seeds 003, 004; DESIGN-3D): boundary representations by oriented
//! triangles partitioned into glued surfaces, and the Boolean algebra on them, on the same
//! number trait and kernel as [`crate::yin2`].

mod arrange;
mod betti;
mod canonical;
mod contact;
mod error;
mod fins;
mod float;
mod geom;
mod glue;
mod hasse;
mod kept;
mod link;
mod locate;
mod meet;
mod near;
mod ops;
mod pierce;
mod set;
pub mod shapes;
mod sweep;
mod transversal;
mod tri;
mod triangulate;
mod validate;

pub use betti::Betti3;
pub use error::{Spot, Yin3Error};
pub use hasse::Atom3;
pub use set::{GluedSurface, YinSet3};
