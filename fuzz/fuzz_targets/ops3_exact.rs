//! Binary operations on two lattice solids' 3D Yin sets, exact mode (see
//! yinset_fuzz::check3::ops3_exact).
#![no_main]
use libfuzzer_sys::fuzz_target;
use yinset_fuzz::input3::Ops3Input;

fuzz_target!(|input: Ops3Input| {
    yinset_fuzz::check3::ops3_exact(&input);
});
