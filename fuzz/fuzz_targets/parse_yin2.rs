//! The `yin2` text reader, then the constructor on what it read (see yinset_fuzz::text).
#![no_main]
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    yinset_fuzz::text::yin2(&yinset_fuzz::text::text_of(data));
});
