//! # yinset
//!
//! The Boolean algebra of Yin sets (Zhang & Li, seed 000), exact on rationals and ε-robust on
//! floats, in one generic code path.
pub mod demo;
pub mod io;
pub mod kernel;
pub mod num;
pub mod yin2;
