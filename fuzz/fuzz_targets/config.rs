//! Any bytes as a `tuff-gen.toml`: an error or a result, never a panic.
#![no_main]

libfuzzer_sys::fuzz_target!(|bytes: &[u8]| tuff_gen::fuzzing::config(bytes));
