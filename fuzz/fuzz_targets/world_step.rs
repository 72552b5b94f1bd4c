#![no_main]
//! Fuzz target: see [`fixstep_fuzz::world_step`].

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    fixstep_fuzz::world_step(data);
});
