//! The 2D Yin space (seed 000): Jordan curves, spadjors, and the Boolean algebra on them.
//!
//! # Data model
//!
//! A [`YinSet2`] is 0̂, 1̂ or a realizable spadjor (seed 000 Def. 3.15–3.19): oriented Jordan
//! polygons that are simple, pairwise almost disjoint (no proper crossing, no shared edge,
//! finitely many touching points) and oriented so that the set lies on their left, whose atoms
//! (Lemma 3.18) have pairwise disjoint interiors. The representation is unique up to where each
//! curve starts and vertices inside straight runs (Thm 3.21), so a canonical form decides `==`
//! and `Hash`. Every constructor from user data validates and names the curve and vertex at
//! fault.
//!
//! # Where the seeds' definitions live
//!
//! | definition | item |
//! | --- | --- |
//! | Jordan polygons, orientation (000 Def. 3.5–3.6) | [`Curve`] |
//! | realizable spadjors, construction without inclusion data (000 Def. 3.15–3.17, §5.1) | [`YinSet2::from_curves`], [`YinError`] |
//! | the Jordan space {0̂, 1̂, spadjors} (000 Def. 3.19) | [`YinSet2`] |
//! | Hasse diagram (002 Alg. 3), atoms (000 Lemma 3.18), Betti numbers (000 Cor. 3.14) | [`YinSet2::parents`], [`Atom`], [`Betti`] |
//! | point location by sweep (002 Alg. 1) | [`YinSet2::locate`], [`locate_in_edges`] |
//! | segmentation S_V and the pasting map S_V⁻¹ (000 Lemma 4.2, S2R-a..d; 002 Alg. 2) | the private `paste` module |
//! | complement (000 Def. 4.4) | [`YinSet2::complement`] |
//! | meet (000 Def. 4.8, MRS-a..d) by one arrangement sweep (002 §1.3) | [`YinSet2::meet`], [`intersect`] |
//! | join by De Morgan (000 Def. 4.10) | [`YinSet2::join`] |
//! | ε-robustness (000 §5.2) | float mode, below, and [`crate::num::Tolerance`] |
//!
//! Every binary operation is one Bentley–Ottmann sweep of both boundaries that records the
//! arrangement and the winding numbers of its faces per operand, with crossing points held
//! implicitly (interval filters; exact coordinates made once, for the result's vertices); the
//! result keeps the faces its operation selects by those winding numbers, and its Hasse diagram
//! is read off the same sweep. The fill rules ([`FillRule`], [`YinSet2::from_rings_filled`])
//! select faces of the arrangement of arbitrary rings the same way.
//!
//! # Float mode
//!
//! The contract is on [`crate::num::Tolerance`]. How it is met: the input of
//! [`YinSet2::from_curves_with`] must be a valid Yin set as given, checked exactly (`f64`
//! orientation by Shewchuk's adaptive predicate after an exact power-of-two scaling, exact
//! rationals where even that would under- or overflow); it is then snapped to the grid.
//! Meet, join, difference and symmetric difference are one pipeline: both operands'
//! boundaries are snap-rounded together on grid integers relative to a local origin (after
//! Hobby: each segment is first rerouted through the pixel centres of its own crossings only,
//! the crossings decided by exact orientations among segments whose boxes meet; where that
//! leaves two pieces crossing, which the result's arrangement sweep reports, and in the fill of
//! arbitrary rings, through every hot pixel it meets), and the faces are kept by their winding
//! numbers per operand. Areas are summed relative to each curve's first vertex, so a small
//! shape far from 0 keeps its area. [`YinSet2::to_exact`] and [`YinSet2::to_float`] move sets
//! between the modes.

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
