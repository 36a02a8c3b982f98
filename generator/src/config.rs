//! The generator's config file: which part of the registry becomes the emitted API.

use crate::error::{Error, Result};
use serde::Deserialize;
use std::path::Path;

/// What the emitted API contains.
#[derive(Debug, Clone, PartialEq, Eq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Config {
    /// The newest core version to emit, as `"1.3"`: every `VK_VERSION_1_x` up to it.
    pub api_version: String,
    /// Extensions to emit besides core, by name.
    pub extensions: Vec<String>,
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
        let config: Config = toml::from_str(&text).map_err(|e| {
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
            scene_sources: vec![],
        };
        assert!(c.api_minor().is_err());
    }

    #[test]
    fn lists_enabled_versions() {
        let c = Config {
            api_version: "1.2".into(),
            extensions: vec![],
            scene_sources: vec![],
        };
        assert_eq!(
            c.enabled_versions(),
            ["VK_VERSION_1_0", "VK_VERSION_1_1", "VK_VERSION_1_2"]
        );
    }
}
