//! Binary operations on two lattice solids' 3D Yin sets in float mode, against exact mode on
//! the same f64 values (see yinset_fuzz::check3_float::ops3_float).
#![no_main]
use libfuzzer_sys::fuzz_target;
use yinset_fuzz::input3::Ops3Input;

fuzz_target!(|input: Ops3Input| {
    yinset_fuzz::check3_float::ops3_float(&input);
});
