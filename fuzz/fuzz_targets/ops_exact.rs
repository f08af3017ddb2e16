//! Binary operations on two grid Yin sets, exact mode (see yinset_fuzz::check::ops_exact).
#![no_main]
use libfuzzer_sys::fuzz_target;
use yinset_fuzz::input::OpsInput;

fuzz_target!(|input: OpsInput| {
    yinset_fuzz::check::ops_exact(&input);
});
