//! Helpers shared by the integration tests.
#![allow(dead_code)]

use std::path::{Path, PathBuf};
use tuff_gen::{model::Model, registry, validity, Options};

/// The repository root.
pub fn root() -> PathBuf {
    tuff_gen::workspace_root()
}

/// A registry folder of `../shared/registry/`. Fails (never skips) when it is missing.
pub fn shared_registry(version: &str) -> PathBuf {
    let dir = root().join("../shared/registry").join(version);
    assert!(
        dir.join("vk.xml").is_file(),
        "the {version} registry is missing: expected {}/vk.xml (the shared/ folder \
         beside the repository)",
        dir.display()
    );
    dir
}

/// Everything the passes produce for one registry.
pub struct Loaded {
    pub model: Model,
    pub validusage: Option<registry::ValidUsage>,
    pub validity: validity::Validity,
}

/// Load a registry folder's vk.xml (and validusage.json unless `implicit_only`) with
/// the pinned config.
pub fn load(dir: &Path, implicit_only: bool) -> Loaded {
    let opts = Options::pinned();
    let config = tuff_gen::config::Config::load(&opts.config).expect("pinned config");
    load_config(dir, implicit_only, config)
}

/// As [`load`], with the pinned config's extensions list alone (the scenes' eight),
/// not every extension.
pub fn load_scenes(dir: &Path) -> Loaded {
    let opts = Options::pinned();
    let config = tuff_gen::config::Config::load(&opts.config).expect("pinned config");
    let config = tuff_gen::config::Config {
        all_extensions: false,
        ..config
    };
    load_config(dir, false, config)
}

fn load_config(dir: &Path, implicit_only: bool, config: tuff_gen::config::Config) -> Loaded {
    let opts = Options::pinned();
    let reg = registry::load_registry(&dir.join("vk.xml")).expect("registry loads");
    let validusage = (!implicit_only).then(|| {
        registry::load_validusage(&dir.join("validusage.json")).expect("validusage loads")
    });
    let model = Model::build(&reg, None, &config, &opts.config).expect("model builds");
    let validity = validity::analyze(&model, validusage.as_ref());
    Loaded {
        model,
        validusage,
        validity,
    }
}

/// Run the CLI with `args` and return (exit code, stdout, stderr).
pub fn cli(args: &[&str]) -> (i32, String, String) {
    let mut out = Vec::new();
    let mut err = Vec::new();
    let argv = std::iter::once("tuff-gen").chain(args.iter().copied());
    let code = tuff_gen::cli::run(argv, &mut out, &mut err);
    (
        code,
        String::from_utf8_lossy(&out).into_owned(),
        String::from_utf8_lossy(&err).into_owned(),
    )
}

/// Every file under `dir`, relative path to contents, for before/after comparisons.
pub fn snapshot_dir(dir: &Path) -> std::collections::BTreeMap<PathBuf, Vec<u8>> {
    let mut out = std::collections::BTreeMap::new();
    let mut stack = vec![dir.to_owned()];
    while let Some(d) = stack.pop() {
        for entry in std::fs::read_dir(&d).expect("readable dir") {
            let path = entry.expect("dir entry").path();
            if path.is_dir() {
                stack.push(path);
            } else {
                let rel = path.strip_prefix(dir).expect("under dir").to_owned();
                out.insert(rel, std::fs::read(&path).expect("readable file"));
            }
        }
    }
    out
}
