#![doc = include_str!("../README.md")]
//!
//! # Architecture
//!
//! Six layers; data flows down, and no module imports from a layer below its own in this list:
//!
//! | layer | what it holds |
//! | --- | --- |
//! | [`num`] | the number trait [`num::Num`] and its backends: exact rationals ([`num::Rational`], `GmpRational` with the `gmp` feature) and ε-floats ([`num::Float`] with [`num::Tolerance`]) |
//! | [`kernel`] | predicates and constructions, the only layer that looks at the coordinates' arithmetic: orientation (the `robust` crate's adaptive predicates for `f64`), point/segment and segment/segment classification, exact angular order around a vertex; the 3D orientation test |
//! | [`yin2`] | Jordan curves, realizable spadjors and the Jordan space: validation, locate, the arrangement sweep, the pasting map, complement, meet, join, Hasse diagram, atoms, Betti numbers, canonical form; float mode's snap rounding |
//! | [`yin3`] | the same for 3D: conforming triangulations, glued surfaces, their Hasse diagram, Betti numbers, locate, volume, the Boolean operations and 3D float mode |
//! | [`io`] | readers and writers: yin2 text, WKT, GeoJSON, WKB, SVG (2D); OBJ, STL, OFF, PLY, PNG and HTML (3D) |
//! | `cli` | the `yinset` command (feature `cli`, on by default) |
//!
//! Items are named as the seed papers name them (spadjor, atom, pasting map, locate, meet,
//! join, complement, Hasse diagram, glued surface), and each cites its definition in its doc
//! comment by seed and number: 000 is Zhang & Li's 2D paper, 002 Li's implementation notes,
//! 003 and 004 the 3D theory and its algorithm outline. The module docs of [`yin2`] and
//! [`yin3`] map the definitions to the items and describe the algorithms; the float contracts
//! are stated in full on [`num::Tolerance`] (2D) and in [`yin3`] (3D).
//!
//! # Exactness
//!
//! In exact mode every decision is an exact predicate on rationals, so the Boolean-algebra
//! laws hold with `==` and areas and volumes are exact. Exact mode does not pay big-number
//! prices where a floating-point filter decides a sign: rationals that fit are stored inline in
//! machine integers, and crossing points are held implicitly behind interval filters until a
//! result needs their coordinates. Float mode's ε and what it does are described on
//! [`num::Num`] and [`num::Tolerance`].
#![warn(missing_docs)]
#[cfg(feature = "cli")]
pub mod cli;
#[cfg(feature = "cli")]
mod demo;
pub mod io;
pub mod kernel;
pub mod num;
mod union_find;
pub mod yin2;
pub mod yin3;
