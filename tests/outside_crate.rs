//! A crate outside the workspace depends on `tuff` by path, with one extension
//! feature, as the README tells a user to: README.md's first program must build
//! there and run on lavapipe with the Khronos validation layer silent.

mod common;

use common::root;
use std::process::Command;

/// The user's program: README.md's first program, as a user copies it (between
/// `<!-- quick-start -->` and the end of the code block after it).
fn readme_program() -> String {
    let readme = std::fs::read_to_string(root().join("README.md")).expect("README.md");
    let after = readme
        .split("<!-- quick-start -->")
        .nth(1)
        .expect("README.md marks its first program with <!-- quick-start -->");
    let code = after
        .split_once("```rust\n")
        .expect("a rust code block after the marker")
        .1;
    code.split_once("\n```")
        .expect("the code block ends")
        .0
        .to_owned()
}

#[test]
fn a_crate_outside_the_workspace_builds_on_tuff_and_runs_on_lavapipe() {
    let dir = tempfile::tempdir().expect("temp folder");
    let app = dir.path().join("outside");
    std::fs::create_dir_all(app.join("src")).expect("src folder");
    let manifest = format!(
        "[package]\nname = \"outside\"\nversion = \"0.1.0\"\nedition = \"2021\"\npublish = false\n\n\
         [dependencies]\ntuff = {{ path = {:?}, features = [\"ext_debug_utils\"] }}\n\n\
         # Its own workspace, not one of a folder above.\n[workspace]\n",
        root().join("generated").display().to_string(),
    );
    std::fs::write(app.join("Cargo.toml"), manifest).expect("manifest");
    std::fs::write(app.join("src/main.rs"), readme_program()).expect("program");
    // The workspace's lock file pins the versions its tests ran with, and lets the
    // build run offline from what the workspace's own build fetched.
    std::fs::copy(root().join("Cargo.lock"), app.join("Cargo.lock")).expect("lock file");
    let out = Command::new(env!("CARGO"))
        .args(["run", "--quiet", "--offline"])
        .current_dir(&app)
        // Its own target folder, kept between runs: this build's features differ
        // from the workspace's, and sharing would rebuild both each time.
        .env("CARGO_TARGET_DIR", root().join("target/outside"))
        .output()
        .expect("cargo runs");
    let stdout = String::from_utf8_lossy(&out.stdout);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(
        out.status.success(),
        "the outside crate failed ({}):\n{stdout}\n{stderr}",
        out.status
    );
    // The rule the program breaks on purpose, refused by the safe method.
    assert!(
        stdout.starts_with("VUID-VkBufferCreateInfo-size-00912: "),
        "{stdout}\n{stderr}"
    );
}
