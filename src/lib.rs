#![doc = include_str!("../README.md")]
pub mod cli;
pub mod demo;
pub mod io;
pub mod kernel;
pub mod num;
mod union_find;
pub mod yin2;
pub mod yin3;
