//! The committed SPIR-V in `shaders/spv` must be what `scripts/shaders.sh` compiles
//! from `shaders/src` now, so nobody edits a binary by hand or forgets to recompile.

mod common;

use common::root;
use std::collections::BTreeMap;
use std::path::Path;

fn files(dir: &Path) -> BTreeMap<String, Vec<u8>> {
    std::fs::read_dir(dir)
        .unwrap_or_else(|e| panic!("cannot read {}: {e}", dir.display()))
        .map(|e| e.expect("directory entry").path())
        .map(|p| {
            let name = p.file_name().unwrap().to_string_lossy().into_owned();
            (name, std::fs::read(&p).expect("read SPIR-V"))
        })
        .collect()
}

#[test]
fn committed_spirv_is_fresh() {
    let dir = tempfile::tempdir().unwrap();
    let status = std::process::Command::new("bash")
        .arg(root().join("scripts/shaders.sh"))
        .arg(dir.path())
        .status()
        .expect("run scripts/shaders.sh");
    assert!(
        status.success(),
        "scripts/shaders.sh failed (is glslang-tools installed?)"
    );
    let fresh = files(dir.path());
    let committed = files(&root().join("shaders/spv"));
    assert!(!fresh.is_empty(), "no shaders compiled");
    assert_eq!(
        fresh.keys().collect::<Vec<_>>(),
        committed.keys().collect::<Vec<_>>(),
        "shaders/spv does not hold one file per source; run scripts/shaders.sh"
    );
    for (name, bytes) in &fresh {
        assert!(
            &committed[name] == bytes,
            "shaders/spv/{name} differs from its source; run scripts/shaders.sh"
        );
    }
}
