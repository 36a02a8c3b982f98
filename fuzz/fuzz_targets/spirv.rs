//! Any bytes as a shader module's: refused, or reflected and queried as pipeline
//! creation does, never a panic or an out-of-bounds read.
#![no_main]

libfuzzer_sys::fuzz_target!(|bytes: &[u8]| tuff::fuzzing::spirv(bytes));
