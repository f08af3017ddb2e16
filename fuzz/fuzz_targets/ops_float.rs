//! Binary operations on two grid Yin sets, float mode (see yinset_fuzz::check::ops_float).
#![no_main]
use libfuzzer_sys::fuzz_target;
use yinset_fuzz::input::OpsInput;

fuzz_target!(|input: OpsInput| {
    yinset_fuzz::check::ops_float(&input);
});
