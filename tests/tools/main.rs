//! The tools' integration tests: the `fixstep` binary, the viewer, the network peer and the
//! benchmark harness, in one test binary of the `fixstep-cli` package (the binary is built
//! for them). The engine's own tests are `tests/suite`. Run one file's tests with
//! `cargo test -p fixstep-cli --test tools FILE::`.

mod replay_support;

mod bench_accuracy;
mod bench_stability;
#[cfg(target_os = "linux")]
mod cli_args_seeds;
mod cli_bounded_memory;
mod cli_commands;
mod cli_input_files;
mod cli_interrupted_outputs;
mod cli_mesh_files;
mod cli_output_clashes;
mod cli_query;
mod cli_record_stream;
mod cli_render_folder;
mod cli_render_html;
mod cli_run_outputs;
mod cli_scene_files;
mod cli_threads;
mod cli_usage_messages;
mod cli_warnings;
mod net_handshake;
mod net_inputs;
mod net_peers;
mod net_sync_test;
mod replay_determinism;
mod replay_malformed;
mod viewer_cli;
mod viewer_render;
mod world_hardening;
mod world_snapshot_files;
