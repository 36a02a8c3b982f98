//! The committed `generated/` must be exactly what the generator writes now.

mod common;

use common::{cli, root};

#[test]
fn committed_output_is_fresh() {
    let (code, stdout, stderr) = cli(&["--check"]);
    assert_eq!(code, 0, "{stderr}");
    assert!(stdout.contains("is up to date"), "{stdout}");
}

#[test]
fn check_reports_a_hand_edit() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("generated");
    let out_s = out.display().to_string();
    let (code, _, stderr) = cli(&["--out", &out_s]);
    assert_eq!(code, 0, "{stderr}");
    let md = out.join("VALIDATION.md");
    let edited = std::fs::read_to_string(&md)
        .unwrap()
        .replacen("Left to user", "Left to you", 1);
    std::fs::write(&md, edited).unwrap();
    let (code, _, stderr) = cli(&["--check", "--out", &out_s]);
    assert_eq!(code, 1);
    assert!(
        stderr.contains("VALIDATION.md: differs from line"),
        "{stderr}"
    );
    // The check itself wrote nothing into the folder it checked.
    assert!(std::fs::read_to_string(&md)
        .unwrap()
        .contains("Left to you"));
    assert!(root().join("generated/VALIDATION.md").is_file());
}
