//! The constructors on grid curves (see yinset_fuzz::check::construct).
#![no_main]
use libfuzzer_sys::fuzz_target;
use yinset_fuzz::input::ConstructInput;

fuzz_target!(|input: ConstructInput| {
    yinset_fuzz::check::construct(&input);
});
