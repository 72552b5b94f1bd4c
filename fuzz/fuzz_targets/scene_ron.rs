#![no_main]
//! Fuzz target: see [`fixstep_fuzz::scene_ron`].

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    fixstep_fuzz::scene_ron(data);
});
