//! Whole-element edits of the seed registry (`tuff_gen::fuzzing::apply_edits`): a
//! well-formed registry whose parts are wrong gives an error or a crate, never a panic.
#![no_main]

const SEED: &str = include_str!("../seeds/registry/mini-vk.xml");

libfuzzer_sys::fuzz_target!(|edits: &[u8]| tuff_gen::fuzzing::registry_edits(SEED, edits));
