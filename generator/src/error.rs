//! The one error type of the generator. Every variant names the file (and, where the
//! format has them, the line and column) that caused it, so the CLI can print a single
//! clear line and exit non-zero.

use std::path::PathBuf;

/// Everything that can stop a generator run.
#[derive(Debug, thiserror::Error)]
pub enum Error {
    /// An input file is missing or unreadable.
    #[error("cannot read {path}: {source}")]
    Read {
        /// The file that could not be read.
        path: PathBuf,
        /// What the operating system said.
        source: std::io::Error,
    },
    /// An input file is not well-formed XML.
    #[error("{path}:{line}:{column}: malformed XML: {message}")]
    MalformedXml {
        /// The registry file.
        path: PathBuf,
        /// 1-based line of the error.
        line: usize,
        /// 1-based column (in bytes) of the error.
        column: usize,
        /// What the XML reader found wrong.
        message: String,
    },
    /// Well-formed XML that is not a Vulkan registry the generator understands.
    #[error("{path}: not a usable Vulkan registry: {message}")]
    BadRegistry {
        /// The registry file.
        path: PathBuf,
        /// What is missing or wrong.
        message: String,
    },
    /// An item's condition, built from the registry's `depends` expressions, does
    /// not parse.
    #[error("vk.xml: the condition of `{item}` (`{condition}`) does not parse: {message}")]
    BadCondition {
        /// The type or command.
        item: String,
        /// The condition's text.
        condition: String,
        /// Where it is malformed.
        message: String,
    },
    /// `validusage.json` is not valid JSON.
    #[error("{path}:{line}:{column}: malformed JSON: {message}")]
    MalformedJson {
        /// The valid-usage file.
        path: PathBuf,
        /// 1-based line of the error.
        line: usize,
        /// 1-based column of the error.
        column: usize,
        /// What the JSON reader found wrong.
        message: String,
    },
    /// Valid JSON that does not follow the validusage.json schema.
    #[error("{path}: not a validusage.json file: {message}")]
    ValidUsageSchema {
        /// The valid-usage file.
        path: PathBuf,
        /// Which part of the schema is violated.
        message: String,
    },
    /// The registry and the valid-usage file come from different Vulkan versions.
    #[error(
        "version mismatch: {registry} is Vulkan {registry_version} but {validusage} is Vulkan \
         {validusage_version}; use the validusage.json of the same release, or pass \
         --allow-version-mismatch to accept it"
    )]
    VersionMismatch {
        /// The registry file.
        registry: PathBuf,
        /// The version its `VK_HEADER_VERSION_COMPLETE` names.
        registry_version: String,
        /// The valid-usage file.
        validusage: PathBuf,
        /// The version its `version info` names.
        validusage_version: String,
    },
    /// The new output would emit fewer commands, structs or handles than the output
    /// folder holds now: a registry bump that loses items is a bug until someone says
    /// otherwise (`--allow-shrink`).
    #[error("{out}: the emitted API would lose {count} of the commands, structs and handles it has now ({sample}); nothing was written. Pass --allow-shrink to write it anyway")]
    Shrink {
        /// The output folder.
        out: PathBuf,
        /// How many items would go.
        count: usize,
        /// The first few, comma-separated.
        sample: String,
    },
    /// `tuff-gen diff` was given two registries of one version.
    #[error("{old} and {new} are both Vulkan {version}: a diff compares two versions (pass the older registry first)")]
    SameVersion {
        /// OLD's vk.xml.
        old: PathBuf,
        /// NEW's vk.xml.
        new: PathBuf,
        /// The version both have.
        version: String,
    },
    /// The config file is unreadable as TOML or names something that does not exist.
    #[error("{path}: {message}")]
    Config {
        /// The config file.
        path: PathBuf,
        /// What is wrong with it.
        message: String,
    },
    /// Writing the output failed; the previous output is left as it was.
    #[error("cannot write {path}: {source}")]
    Write {
        /// The file or folder being written.
        path: PathBuf,
        /// What the operating system said.
        source: std::io::Error,
    },
    /// `--check` found that the committed output differs from a fresh run.
    #[error(
        "the output in {dir} differs from what the generator writes now (run tuff-gen \
         again with the same options, without --check, to update it):\n{summary}"
    )]
    OutOfDate {
        /// The output folder that was checked.
        dir: PathBuf,
        /// One line per differing file.
        summary: String,
    },
}

/// Shorthand for results of the generator.
pub type Result<T, E = Error> = std::result::Result<T, E>;
