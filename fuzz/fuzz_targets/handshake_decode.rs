#![no_main]
//! Fuzz target: a peer's handshake message ([`fixstep_net::Hello`]). Decoding never
//! panics, and an accepted message encodes back to exactly its bytes. `fixstep-net`'s
//! unit tests run the seeds through the same check (the engine's test suite, which runs
//! the other targets' seeds, does not depend on the network crate).

use fixstep_net::Hello;
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    if let Ok(hello) = Hello::decode(data) {
        assert_eq!(hello.encode(), data, "an accepted message has one encoding");
    }
});
