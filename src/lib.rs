#![doc = include_str!("../README.md")]
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
