//! The 3D constructor on lattice meshes (see yinset_fuzz::check3::construct3).
#![no_main]
use libfuzzer_sys::fuzz_target;
use yinset_fuzz::input3::Construct3Input;

fuzz_target!(|input: Construct3Input| {
    yinset_fuzz::check3::construct3(&input);
});
