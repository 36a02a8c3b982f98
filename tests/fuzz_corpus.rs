//! The fuzz targets' seeds and every input a fuzzer found a crash with
//! (`fuzz/seeds/`, `fuzz/regressions/`), through the targets' own bodies on the stable
//! toolchain: each returns. A crash fixed stays fixed; `scripts/fuzz.sh` says how one
//! gets here.

use std::path::{Path, PathBuf};

fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("..")
}

/// The files of `fuzz/seeds/TARGET` and `fuzz/regressions/TARGET`, with their bytes.
fn inputs(target: &str) -> Vec<(PathBuf, Vec<u8>)> {
    let mut out = Vec::new();
    for dir in ["seeds", "regressions"] {
        let dir = root().join("fuzz").join(dir).join(target);
        let Ok(entries) = std::fs::read_dir(&dir) else {
            continue;
        };
        for entry in entries {
            let path = entry.unwrap().path();
            if path.is_file() && path.file_name().is_some_and(|n| n != ".gitkeep") {
                let bytes = std::fs::read(&path).unwrap();
                out.push((path, bytes));
            }
        }
    }
    out.sort();
    out
}

/// Runs `body` on each input of `target`, naming the input that panics.
fn replay(target: &str, body: impl Fn(&[u8]) + std::panic::RefUnwindSafe) -> usize {
    let inputs = inputs(target);
    for (path, bytes) in &inputs {
        if std::panic::catch_unwind(|| body(bytes)).is_err() {
            panic!("{}: the {target} fuzz target panics", path.display());
        }
    }
    inputs.len()
}

#[test]
fn registry_inputs_return() {
    assert!(replay("registry", tuff_gen::fuzzing::registry) >= 1);
}

#[test]
fn registry_edit_inputs_return() {
    let seed = std::fs::read_to_string(root().join("fuzz/seeds/registry/mini-vk.xml")).unwrap();
    assert!(
        replay("registry_edits", |edits| tuff_gen::fuzzing::registry_edits(
            &seed, edits
        )) >= 2
    );
}

#[test]
fn validusage_inputs_return() {
    assert!(replay("validusage", tuff_gen::fuzzing::validusage) >= 1);
}

#[test]
fn config_inputs_return() {
    assert!(replay("config", tuff_gen::fuzzing::config) >= 2);
}

#[test]
fn spirv_inputs_return() {
    replay("spirv", tuff::fuzzing::spirv);
    // The committed shaders are the target's seeds too.
    for entry in std::fs::read_dir(root().join("shaders/spv")).unwrap() {
        tuff::fuzzing::spirv(&std::fs::read(entry.unwrap().path()).unwrap());
    }
}

/// The seed registry reads and runs through every pass: a seed the reader refuses
/// would leave the structure-aware target nothing but errors to explore.
#[test]
fn the_seed_registry_generates_a_crate() {
    let seed = root().join("fuzz/seeds/registry/mini-vk.xml");
    let out = tempfile::tempdir().unwrap();
    let config = out.path().join("tuff-gen.toml");
    std::fs::write(&config, "api_version = \"1.3\"\nall_extensions = true\n").unwrap();
    let generation = tuff_gen::generate(&tuff_gen::Options {
        registry: seed,
        validusage: None,
        config,
        out: out.path().join("crate"),
        allow_version_mismatch: false,
        allow_shrink: false,
    })
    .unwrap();
    assert!(generation.files.len() > 20);
}
