#![no_main]
//! Fuzz target: see [`fixstep_fuzz::mesh_obj`].

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    fixstep_fuzz::mesh_obj(data);
});
