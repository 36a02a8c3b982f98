//! Integration tests live in the other files of this folder; see Cargo.toml.
