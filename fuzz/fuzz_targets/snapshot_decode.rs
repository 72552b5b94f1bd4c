#![no_main]
//! Fuzz target: see [`fixstep_fuzz::snapshot_decode`].

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    fixstep_fuzz::snapshot_decode(data);
});
