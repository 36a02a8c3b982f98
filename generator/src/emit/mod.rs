//! Emit pass: one emitter per kind of item writes Rust into `generated/`, and records,
//! for every rule it touches, how the emitted code settles it. The report is tallied
//! from these records alone, so it cannot claim more than the code does.

mod api_info;

use crate::config::Config;
use crate::model::Model;
use crate::validity::Validity;
use std::path::PathBuf;

/// How emitted code settles one rule.
#[derive(Debug, Clone, PartialEq, Eq, serde::Serialize)]
#[serde(tag = "status", content = "mechanism", rename_all = "lowercase")]
pub enum Settlement {
    /// Enforced by types at compile time; the text names the mechanism.
    Static(String),
    /// Checked at run time; the text names the check.
    Dynamic(String),
    /// Left to the user; the text says why.
    User(String),
}

impl Settlement {
    /// `static`, `dynamic` or `user`.
    pub fn status(&self) -> &'static str {
        match self {
            Settlement::Static(_) => "static",
            Settlement::Dynamic(_) => "dynamic",
            Settlement::User(_) => "user",
        }
    }

    /// The mechanism or reason.
    pub fn mechanism(&self) -> &str {
        match self {
            Settlement::Static(m) | Settlement::Dynamic(m) | Settlement::User(m) => m,
        }
    }
}

/// An emitter's statement about one rule.
#[derive(Debug, Clone, PartialEq, Eq, serde::Serialize)]
pub struct Record {
    /// The rule.
    pub vuid: String,
    /// How it is settled.
    pub settlement: Settlement,
}

/// One file of the output, relative to the output folder.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct OutputFile {
    /// Path relative to the output folder, with `/` separators.
    pub path: PathBuf,
    /// Full contents.
    pub contents: String,
}

/// What the emitters produced.
#[derive(Debug, Clone, Default)]
pub struct Emission {
    /// Source files.
    pub files: Vec<OutputFile>,
    /// Settlement records, from every emitter.
    pub records: Vec<Record>,
}

/// Run every emitter.
pub fn emit(model: &Model, _validity: &Validity, config: &Config) -> Emission {
    let mut emission = Emission::default();
    api_info::emit(model, config, &mut emission);
    emission
}
