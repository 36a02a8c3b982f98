//! The generator's config file: which part of the registry becomes the emitted API.

use crate::error::{Error, Result};
use serde::Deserialize;
use std::path::Path;

/// What the emitted API contains.
#[derive(Debug, Clone, Default, PartialEq, Eq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Config {
    /// The newest core version to emit, as `"1.3"`: every `VK_VERSION_1_x` up to it.
    pub api_version: String,
    /// Extensions to emit besides core, by name.
    #[serde(default)]
    pub extensions: Vec<String>,
    /// Emit every extension the registry supports for the vulkan API (besides
    /// `extensions`), less those the reference registry leaves out.
    #[serde(default)]
    pub all_extensions: bool,
    /// The registry the `ash` release the generated crate builds on was generated
    /// from (relative to the config file): an extension it lacks, or defines
    /// otherwise, is left out and listed.
    #[serde(default)]
    pub reference_registry: Option<String>,
    /// Folders of Rust programs that use the generated crate (relative to the config
    /// file); the report lists the methods they call first.
    #[serde(default)]
    pub scene_sources: Vec<String>,
}

impl Config {
    /// Read and parse a config file. Names are checked against the registry later, by
    /// the model pass, which knows the registry.
    pub fn load(path: &Path) -> Result<Config> {
        let text = std::fs::read_to_string(path).map_err(|source| Error::Read {
            path: path.to_owned(),
            source,
        })?;
        Config::parse(path, &text)
    }

    /// Parse the text of a config file already read; `path` names it in errors. Any
    /// text gives a config or an error, never a panic (`fuzz/`'s `config` target).
    pub fn parse(path: &Path, text: &str) -> Result<Config> {
        let config: Config = toml::from_str(text).map_err(|e| {
            let at = e.span().map_or(0, |s| s.start).min(text.len());
            let line = text[..at].matches('\n').count() + 1;
            let column = at - text[..at].rfind('\n').map_or(0, |p| p + 1) + 1;
            Error::Config {
                path: path.to_owned(),
                message: format!("line {line}, column {column}: {}", e.message().trim()),
            }
        })?;
        config.api_minor().map_err(|message| Error::Config {
            path: path.to_owned(),
            message,
        })?;
        Ok(config)
    }

    /// The minor version of `api_version` (`3` for `"1.3"`).
    pub fn api_minor(&self) -> std::result::Result<u32, String> {
        self.api_version
            .strip_prefix("1.")
            .and_then(|m| m.parse().ok())
            .filter(|m| *m < 100)
            .ok_or_else(|| {
                format!(
                    "api_version `{}` is not a Vulkan version of the form \"1.N\"",
                    self.api_version
                )
            })
    }

    /// The extensions the config asks for: `extensions`, and with `all_extensions`
    /// every extension `registry` supports for the vulkan API, in name order.
    pub fn wanted_extensions(&self, registry: &crate::registry::Registry) -> Vec<String> {
        let mut wanted: Vec<String> = self.extensions.clone();
        if self.all_extensions {
            wanted.extend(
                registry
                    .extensions
                    .iter()
                    .filter(|e| {
                        e.supported
                            .as_deref()
                            .is_some_and(|s| s.split(',').any(|a| a == "vulkan"))
                    })
                    .map(|e| e.name.clone()),
            );
        }
        wanted.sort();
        wanted.dedup();
        wanted
    }

    /// The path of the reference registry, if the config names one.
    pub fn reference_path(&self, config_path: &Path) -> Option<std::path::PathBuf> {
        let base = config_path.parent().unwrap_or(Path::new("."));
        self.reference_registry.as_ref().map(|r| base.join(r))
    }

    /// The feature names the cap enables: `VK_VERSION_1_0` up to the cap.
    pub fn enabled_versions(&self) -> Vec<String> {
        let minor = self.api_minor().unwrap_or(0);
        (0..=minor).map(|m| format!("VK_VERSION_1_{m}")).collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rejects_a_malformed_version() {
        let c = Config {
            api_version: "3".into(),
            extensions: vec![],
            all_extensions: false,
            reference_registry: None,
            scene_sources: vec![],
        };
        assert!(c.api_minor().is_err());
    }

    #[test]
    fn lists_enabled_versions() {
        let c = Config {
            api_version: "1.2".into(),
            extensions: vec![],
            all_extensions: false,
            reference_registry: None,
            scene_sources: vec![],
        };
        assert_eq!(
            c.enabled_versions(),
            ["VK_VERSION_1_0", "VK_VERSION_1_1", "VK_VERSION_1_2"]
        );
    }
}
