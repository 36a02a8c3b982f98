//! `tuff-gen`: reads the Khronos Vulkan registry (`vk.xml`) and its valid-usage rules
//! (`validusage.json`) and writes the `tuff` crate's generated code together with a
//! validation coverage report.
//!
//! The generator is a pipeline of passes with plain data between them:
//!
//! 1. [`registry`]: parse the files into plain Rust data.
//! 2. [`model`]: resolve handles, commands, structs and the conditions under which
//!    each exists, and select the emitted API from the [`config`].
//! 3. [`validity`]: derive every implicit rule, attach and classify the explicit ones.
//! 4. [`plan`]: decide, once, every command's and struct's shape, the dynamic checks,
//!    and how each rule is settled.
//! 5. [`emit`]: render the plans as Rust; [`report`]: tally the plans' records into
//!    `VALIDATION.md`, `validation.json` and an SVG.
//!
//! Each pass imports only those before it ([`names`] is the shared spelling of
//! registry names in Rust); `tests/generator_layers.rs` holds that.
//!
//! ```no_run
//! use tuff_gen::{generate, Options};
//! let opts = Options::pinned();
//! let generation = generate(&opts)?;
//! tuff_gen::output::write_all(&opts.out, &generation.files)?;
//! # Ok::<(), tuff_gen::Error>(())
//! ```

#![warn(missing_docs)]

pub mod cli;
pub mod config;
pub mod emit;
pub mod error;
pub mod model;
pub mod names;
pub mod output;
pub mod plan;
pub mod registry;
pub mod report;
pub mod validity;

pub use error::{Error, Result};

use std::path::{Path, PathBuf};

/// Where the inputs are and where the output goes.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Options {
    /// `vk.xml`.
    pub registry: PathBuf,
    /// `validusage.json`, or `None` to derive implicit rules only.
    pub validusage: Option<PathBuf>,
    /// The config file (`tuff-gen.toml`).
    pub config: PathBuf,
    /// The output folder (`generated/`).
    pub out: PathBuf,
    /// Accept a validusage.json of another version than vk.xml.
    pub allow_version_mismatch: bool,
}

impl Options {
    /// The repository's pinned inputs and its `generated/` folder.
    pub fn pinned() -> Options {
        let root = workspace_root();
        Options {
            registry: root.join("vk.xml"),
            validusage: Some(root.join("validusage.json")),
            config: root.join("tuff-gen.toml"),
            out: root.join("generated"),
            allow_version_mismatch: false,
        }
    }
}

/// The repository root this generator was built in.
pub fn workspace_root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .parent()
        .map_or_else(|| PathBuf::from("."), Path::to_owned)
}

/// What a run produced, before anything is written.
#[derive(Debug, Clone)]
pub struct Generation {
    /// Every file of the output, relative to the output folder.
    pub files: Vec<emit::OutputFile>,
    /// Registry version.
    pub version: String,
    /// The emitted API's coverage table.
    pub emitted: report::Table,
    /// The whole registry's coverage table.
    pub registry: report::Table,
    /// Derived against listed implicit rules, when validusage.json was given.
    pub comparison: Option<validity::Comparison>,
}

/// Run every pass and return the files to write. Reads the inputs; writes nothing.
pub fn generate(opts: &Options) -> Result<Generation> {
    let config = config::Config::load(&opts.config)?;
    let reg = registry::load_registry(&opts.registry)?;
    let vu = match &opts.validusage {
        Some(path) => Some(registry::load_validusage(path)?),
        None => None,
    };
    if let (Some(vu), Some(path)) = (&vu, &opts.validusage) {
        if vu.api_version != reg.version && !opts.allow_version_mismatch {
            return Err(Error::VersionMismatch {
                registry: opts.registry.clone(),
                registry_version: reg.version.clone(),
                validusage: path.clone(),
                validusage_version: vu.api_version.clone(),
            });
        }
    }
    let model = model::Model::build(&reg, &config, &opts.config)?;
    let validity = validity::analyze(&model, vu.as_ref());
    let cx = plan::Context::new(&model, &validity);
    let plans = plan::Plans::build(&cx);
    let emission = emit::emit(&plans, &config);
    let report = report::build(&model, &validity, &plans.records);
    let mut files = emission.files;
    files.extend(report::render(&report));
    Ok(Generation {
        files,
        version: model.version.clone(),
        emitted: report.emitted,
        registry: report.registry,
        comparison: validity.comparison.clone(),
    })
}
