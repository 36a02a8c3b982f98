//! Bad input: every case exits non-zero with one clear message and leaves the
//! output folder exactly as it was.

mod common;

use common::{cli, root, shared_registry, snapshot_dir};
use std::path::{Path, PathBuf};

struct Case {
    _dir: tempfile::TempDir,
    out: PathBuf,
    dir: PathBuf,
}

/// An output folder holding a previous good run, and a scratch folder for inputs.
fn case() -> Case {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("generated");
    std::fs::create_dir(&out).unwrap();
    std::fs::write(out.join("VALIDATION.md"), "previous report\n").unwrap();
    std::fs::write(out.join("keep.txt"), "not the generator's\n").unwrap();
    Case {
        out,
        dir: dir.path().to_owned(),
        _dir: dir,
    }
}

fn pinned(name: &str) -> String {
    root().join(name).display().to_string()
}

/// Run with `args` plus `--out`, expect failure whose message contains every
/// `needle`, and expect the output folder unchanged.
fn fails(c: &Case, args: &[&str], needles: &[&str]) {
    let before = snapshot_dir(&c.out);
    let out = c.out.display().to_string();
    let mut all: Vec<&str> = args.to_vec();
    all.extend(["--out", &out]);
    let (code, stdout, stderr) = cli(&all);
    assert_ne!(code, 0, "expected failure for {args:?}; stdout: {stdout}");
    assert_eq!(stderr.lines().count(), 1, "one message, got: {stderr}");
    for n in needles {
        assert!(stderr.contains(n), "`{n}` not in: {stderr}");
    }
    assert_eq!(snapshot_dir(&c.out), before, "the output folder changed");
}

fn write(dir: &Path, name: &str, text: &str) -> String {
    let p = dir.join(name);
    std::fs::write(&p, text).unwrap();
    p.display().to_string()
}

#[test]
fn missing_registry() {
    let c = case();
    let missing = c.dir.join("nope/vk.xml").display().to_string();
    fails(
        &c,
        &["--registry", &missing, "--no-validusage"],
        &["cannot read", "nope/vk.xml"],
    );
}

#[test]
fn unreadable_registry() {
    let c = case();
    // A folder where a file is expected cannot be read, even by root.
    let folder = c.dir.display().to_string();
    fails(
        &c,
        &["--registry", &folder, "--no-validusage"],
        &["cannot read"],
    );
}

#[test]
fn malformed_xml_names_file_line_and_column() {
    let c = case();
    let vk = write(
        &c.dir,
        "vk.xml",
        "<registry>\n  <types>\n    <type name=\"x\">\n  </types>\n</registry>\n",
    );
    fails(
        &c,
        &["--registry", &vk, "--no-validusage"],
        &["vk.xml:4:", "malformed XML"],
    );
}

#[test]
fn truncated_registry() {
    let c = case();
    let full = std::fs::read_to_string(root().join("vk.xml")).unwrap();
    let vk = write(&c.dir, "vk.xml", &full[..full.len() / 2]);
    fails(
        &c,
        &["--registry", &vk, "--no-validusage"],
        &["vk.xml:", "malformed XML"],
    );
}

#[test]
fn xml_that_is_not_a_registry() {
    let c = case();
    let vk = write(
        &c.dir,
        "vk.xml",
        "<registry><comment>empty</comment></registry>\n",
    );
    fails(
        &c,
        &["--registry", &vk, "--no-validusage"],
        &["not a usable Vulkan registry"],
    );
}

#[test]
fn validusage_of_the_wrong_schema() {
    let c = case();
    let vu = write(&c.dir, "validusage.json", r#"{"rules": [{"id": 1}]}"#);
    fails(
        &c,
        &["--registry", &pinned("vk.xml"), "--validusage", &vu],
        &["validusage.json", "not a validusage.json file"],
    );
}

#[test]
fn malformed_json_names_line_and_column() {
    let c = case();
    let vu = write(&c.dir, "validusage.json", "{\n  \"version info\": {,\n}");
    fails(
        &c,
        &["--registry", &pinned("vk.xml"), "--validusage", &vu],
        &["validusage.json:2:", "malformed JSON"],
    );
}

#[test]
fn versions_that_differ_name_both_files() {
    let c = case();
    let newer_vu = shared_registry("1.4.309")
        .join("validusage.json")
        .display()
        .to_string();
    fails(
        &c,
        &["--registry", &pinned("vk.xml"), "--validusage", &newer_vu],
        &[
            "version mismatch",
            "1.3.239",
            "1.4.309",
            "vk.xml",
            "--allow-version-mismatch",
        ],
    );
}

#[test]
fn a_version_mismatch_can_be_accepted_explicitly() {
    let c = case();
    let newer_vu = shared_registry("1.4.309")
        .join("validusage.json")
        .display()
        .to_string();
    let out = c.out.display().to_string();
    let (code, stdout, stderr) = cli(&[
        "--registry",
        &pinned("vk.xml"),
        "--validusage",
        &newer_vu,
        "--allow-version-mismatch",
        "--out",
        &out,
    ]);
    assert_eq!(code, 0, "{stderr}");
    assert!(stdout.contains("Vulkan 1.3.239"), "{stdout}");
    assert!(c.out.join("validation.json").is_file());
    assert_eq!(
        std::fs::read_to_string(c.out.join("keep.txt")).unwrap(),
        "not the generator's\n"
    );
}

#[test]
fn config_naming_an_unknown_extension() {
    let c = case();
    let cfg = write(
        &c.dir,
        "tuff-gen.toml",
        "api_version = \"1.3\"\nextensions = [\"VK_KHR_surface\", \"VK_KHR_teleport\"]\n",
    );
    fails(
        &c,
        &["--config", &cfg],
        &["tuff-gen.toml", "VK_KHR_teleport", "does not exist"],
    );
}

#[test]
fn config_naming_an_unknown_version() {
    let c = case();
    let cfg = write(
        &c.dir,
        "tuff-gen.toml",
        "api_version = \"1.9\"\nextensions = []\n",
    );
    fails(
        &c,
        &["--config", &cfg],
        &["tuff-gen.toml", "`1.9` is newer than", "1.3"],
    );
}

#[test]
fn config_that_is_not_toml() {
    let c = case();
    let cfg = write(&c.dir, "tuff-gen.toml", "api_version = \n");
    fails(&c, &["--config", &cfg], &["tuff-gen.toml"]);
}

#[test]
fn unknown_command_line_flag() {
    let (code, _, stderr) = cli(&["--frobnicate"]);
    assert_eq!(code, 2);
    assert!(stderr.contains("--frobnicate"), "{stderr}");
}

#[test]
fn other_inputs_need_an_explicit_output_folder() {
    // Without --out, a run on another registry would overwrite the committed generated/.
    let before = snapshot_dir(&root().join("generated"));
    let newer = shared_registry("1.4.309")
        .join("vk.xml")
        .display()
        .to_string();
    let (code, _, stderr) = cli(&["--registry", &newer]);
    assert_eq!(code, 2);
    assert!(stderr.contains("pass --out"), "{stderr}");
    assert_eq!(snapshot_dir(&root().join("generated")), before);
}

#[test]
fn registry_with_an_undefined_entity() {
    let c = case();
    let vk = write(
        &c.dir,
        "vk.xml",
        "<registry>\n  <comment>&nbsp;</comment>\n</registry>\n",
    );
    fails(
        &c,
        &["--registry", &vk, "--no-validusage"],
        &["vk.xml:2:", "undefined entity"],
    );
}

#[test]
fn config_with_an_absurd_version() {
    let c = case();
    let cfg = write(
        &c.dir,
        "tuff-gen.toml",
        "api_version = \"1.4294967295\"\nextensions = []\n",
    );
    fails(
        &c,
        &["--config", &cfg],
        &["tuff-gen.toml", "not a Vulkan version"],
    );
}

#[test]
fn config_missing_an_extension_dependency() {
    let c = case();
    let cfg = write(
        &c.dir,
        "tuff-gen.toml",
        "api_version = \"1.3\"\nextensions = [\"VK_KHR_swapchain\"]\n",
    );
    fails(
        &c,
        &["--config", &cfg],
        &["VK_KHR_swapchain", "needs", "VK_KHR_surface"],
    );
}

#[test]
fn registry_with_a_malformed_dependency_expression() {
    let c = case();
    let text = std::fs::read_to_string(root().join("vk.xml")).unwrap();
    let needle = r#"<require extension="VK_EXT_fragment_density_map">"#;
    assert!(text.contains(needle));
    let bad = text.replacen(
        needle,
        r#"<require extension="VK_EXT_fragment_density_map+(">"#,
        1,
    );
    let vk = write(&c.dir, "vk.xml", &bad);
    fails(
        &c,
        &["--registry", &vk, "--no-validusage"],
        &[
            "vk.xml: the condition of `",
            "VK_EXT_fragment_density_map+(",
            "does not parse",
        ],
    );
}

/// A name that is no C identifier (a comment's text where a command's name goes, as
/// the structure-aware fuzz target made one) is refused by the reader, naming the
/// element, not by the emitter's identifier maker in a panic.
#[test]
fn registry_with_a_name_that_is_no_identifier() {
    let c = case();
    let text = std::fs::read_to_string(root().join("vk.xml")).unwrap();
    let needle = "<name>vkCmdFillBuffer</name>";
    assert!(text.contains(needle));
    let bad = text.replacen(needle, "<name>1.0.0: patch version</name>", 1);
    let vk = write(&c.dir, "vk.xml", &bad);
    fails(
        &c,
        &["--registry", &vk, "--no-validusage"],
        &["a <command>: `1.0.0: patch version` is not a C identifier"],
    );
}

/// A run that would emit fewer commands, structs or handles than the output folder
/// lists (its `emitted-items.txt`, written by the run before) fails, naming what would
/// go, and writes nothing; `--allow-shrink` says a human accepts it.
#[test]
fn an_output_that_would_lose_items_needs_allow_shrink() {
    let c = case();
    std::fs::write(
        c.out.join("emitted-items.txt"),
        "# from an earlier run\nvkCreateBuffer\nvkFrobnicateGPU\nVkFrobnicateInfo\n",
    )
    .unwrap();
    fails(
        &c,
        &[],
        &[
            "would lose 2 of the commands, structs and handles",
            "vkFrobnicateGPU, VkFrobnicateInfo",
            "--allow-shrink",
        ],
    );
    let out = c.out.display().to_string();
    let (code, _, stderr) = cli(&["--out", &out, "--allow-shrink"]);
    assert_eq!(code, 0, "{stderr}");
    let items = std::fs::read_to_string(c.out.join("emitted-items.txt")).unwrap();
    assert!(items.lines().any(|l| l == "vkCreateBuffer"));
    assert!(!items.contains("vkFrobnicateGPU"));
}

#[test]
fn registry_without_a_readable_version() {
    let c = case();
    // The pinned registry with its header-version defines renamed: everything
    // else is a good registry.
    let text = std::fs::read_to_string(root().join("vk.xml"))
        .unwrap()
        .replace(
            "<name>VK_HEADER_VERSION</name>",
            "<name>VK_HEADER_REVISION</name>",
        )
        .replace(
            "<name>VK_HEADER_VERSION_COMPLETE</name>",
            "<name>VK_HEADER_REVISION_COMPLETE</name>",
        );
    let vk = write(&c.dir, "vk.xml", &text);
    fails(
        &c,
        &["--registry", &vk, "--no-validusage"],
        &[
            "vk.xml",
            "not a usable Vulkan registry",
            "VK_HEADER_VERSION",
        ],
    );
}

#[test]
fn a_diff_of_two_registries_of_one_version() {
    let c = case();
    // A copy of the pinned registry: another file, the same version.
    let copy = c.dir.join("copy.xml");
    std::fs::copy(root().join("vk.xml"), &copy).unwrap();
    let before = snapshot_dir(&c.dir);
    let (code, stdout, stderr) = cli(&["diff", &pinned("vk.xml"), &copy.display().to_string()]);
    assert_ne!(code, 0);
    assert_eq!(stdout, "", "nothing is printed but the error");
    assert_eq!(stderr.lines().count(), 1, "one message, got: {stderr}");
    for n in ["both Vulkan 1.3.239", "copy.xml", "two versions"] {
        assert!(stderr.contains(n), "`{n}` not in: {stderr}");
    }
    assert_eq!(snapshot_dir(&c.dir), before, "nothing was written");
}
