//! Shared code of the yinset fuzz targets: input formats ([`input`], 3D: [`input3`]), and the
//! property each target checks ([`check`], [`text`], 3D: [`check3`], [`check3_float`]), kept
//! out of `fuzz_targets/` so that the seed generator and the unit tests of this crate run the
//! very same checks without libFuzzer.
//!
//! Every check panics (with the decoded input in the message) on a property violation; a
//! panic in the kernel is reported by libFuzzer the same way.

pub mod check;
pub mod check3;
pub mod check3_float;
pub mod input;
pub mod input3;
pub mod text;
