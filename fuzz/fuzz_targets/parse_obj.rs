//! The OBJ reader (exact and float), its writer, then the 3D constructor on small meshes read
//! (see yinset_fuzz::check3::obj).
#![no_main]
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    yinset_fuzz::check3::obj(&yinset_fuzz::text::text_of(data));
});
