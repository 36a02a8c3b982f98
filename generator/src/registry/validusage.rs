//! Reading `validusage.json`, the specification's machine-readable list of valid-usage
//! rules.

use crate::error::{Error, Result};
use serde::Deserialize;
use std::path::Path;

/// The contents of `validusage.json`.
#[derive(Debug, Clone, Default)]
pub struct ValidUsage {
    /// `version info` / `api version`, e.g. `1.3.239`.
    pub api_version: String,
    /// Every rule, in the file's order (entity by entity).
    pub entries: Vec<VuEntry>,
}

/// One rule of `validusage.json`.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct VuEntry {
    /// The VUID, e.g. `VUID-vkCmdDraw-None-02690`.
    pub vuid: String,
    /// The command, struct or other entity the rule is filed under.
    pub entity: String,
    /// The key the rule is filed under inside the entity (`core` or an extension
    /// expression); since 1.3.255 always `core`, so not a condition to rely on.
    pub key: String,
    /// The rule's text (HTML).
    pub text: String,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct File {
    #[serde(rename = "version info")]
    version_info: VersionInfo,
    validation: indexmap_like::Ordered<indexmap_like::Ordered<Vec<Rule>>>,
}

#[derive(Deserialize)]
struct VersionInfo {
    #[serde(rename = "schema version")]
    schema_version: u32,
    #[serde(rename = "api version")]
    api_version: String,
}

#[derive(Deserialize)]
struct Rule {
    vuid: String,
    text: String,
}

/// serde_json without its `preserve_order` feature sorts object keys and lets a
/// repeated key replace the earlier one; a Vec of pairs keeps the file's order and
/// makes a repeated key an error.
mod indexmap_like {
    use serde::de::{Error, MapAccess, Visitor};
    use serde::{Deserialize, Deserializer};
    use std::marker::PhantomData;

    pub(super) struct Ordered<V>(pub Vec<(String, V)>);

    impl<'de, V: Deserialize<'de>> Deserialize<'de> for Ordered<V> {
        fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
            struct Vis<V>(PhantomData<V>);
            impl<'de, V: Deserialize<'de>> Visitor<'de> for Vis<V> {
                type Value = Ordered<V>;
                fn expecting(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
                    f.write_str("an object")
                }
                fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<Ordered<V>, A::Error> {
                    let mut out: Vec<(String, V)> = Vec::new();
                    let mut seen = std::collections::HashSet::new();
                    while let Some((k, v)) = map.next_entry::<String, V>()? {
                        if !seen.insert(k.clone()) {
                            return Err(A::Error::custom(format!("the key `{k}` appears twice")));
                        }
                        out.push((k, v));
                    }
                    Ok(Ordered(out))
                }
            }
            d.deserialize_map(Vis(PhantomData))
        }
    }
}

/// Read `validusage.json`: a JSON syntax error is reported with line and column, a
/// file of another shape as a schema error.
pub fn load_validusage(path: &Path) -> Result<ValidUsage> {
    let bytes = std::fs::read(path).map_err(|source| Error::Read {
        path: path.to_owned(),
        source,
    })?;
    parse_validusage(path, &bytes)
}

/// Read the text of a `validusage.json` already read; `path` names it in errors. Any
/// bytes give the rules or an error, never a panic (`fuzz/`'s `validusage` target).
pub fn parse_validusage(path: &Path, bytes: &[u8]) -> Result<ValidUsage> {
    let file: File = serde_json::from_slice(bytes).map_err(|e| match e.classify() {
        serde_json::error::Category::Syntax | serde_json::error::Category::Eof => {
            Error::MalformedJson {
                path: path.to_owned(),
                line: e.line(),
                column: e.column(),
                message: strip_position(&e.to_string()),
            }
        }
        _ => Error::ValidUsageSchema {
            path: path.to_owned(),
            message: e.to_string(),
        },
    })?;
    if file.version_info.schema_version != 2 {
        return Err(Error::ValidUsageSchema {
            path: path.to_owned(),
            message: format!(
                "schema version {} is not supported (expected 2)",
                file.version_info.schema_version
            ),
        });
    }
    let mut entries = Vec::new();
    for (entity, keyed) in file.validation.0 {
        for (key, rules) in keyed.0 {
            for rule in rules {
                if !rule.vuid.starts_with("VUID-") {
                    return Err(Error::ValidUsageSchema {
                        path: path.to_owned(),
                        message: format!("`{}` under {entity} is not a VUID", rule.vuid),
                    });
                }
                entries.push(VuEntry {
                    vuid: rule.vuid,
                    entity: entity.clone(),
                    key: key.clone(),
                    text: rule.text,
                });
            }
        }
    }
    Ok(ValidUsage {
        api_version: file.version_info.api_version,
        entries,
    })
}

fn strip_position(message: &str) -> String {
    match message.rfind(" at line ") {
        Some(at) => message[..at].to_owned(),
        None => message.to_owned(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn load(text: &str) -> Result<ValidUsage> {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("validusage.json");
        std::fs::write(&path, text).unwrap();
        load_validusage(&path)
    }

    #[test]
    fn reads_rules_in_order() {
        let vu = load(
            r#"{"version info": {"schema version": 2, "api version": "1.3.239", "comment": "", "date": ""},
                "validation": {"vkCmdDraw": {"core": [
                    {"vuid": "VUID-vkCmdDraw-commandBuffer-parameter", "text": "a"},
                    {"vuid": "VUID-vkCmdDraw-None-02690", "text": "b"}]}}}"#,
        )
        .unwrap();
        assert_eq!(vu.api_version, "1.3.239");
        assert_eq!(vu.entries.len(), 2);
        assert_eq!(vu.entries[1].vuid, "VUID-vkCmdDraw-None-02690");
        assert_eq!(vu.entries[1].entity, "vkCmdDraw");
    }

    #[test]
    fn syntax_errors_carry_line_and_column() {
        let err = load("{\n  \"version info\": ,\n}").unwrap_err();
        match err {
            Error::MalformedJson { line, .. } => assert_eq!(line, 2),
            other => panic!("unexpected {other}"),
        }
    }

    #[test]
    fn a_repeated_entity_is_a_schema_error() {
        let err = load(
            r#"{"version info": {"schema version": 2, "api version": "1.3.239"},
                "validation": {"vkCmdDraw": {"core": []}, "vkCmdDraw": {"core": []}}}"#,
        )
        .unwrap_err();
        assert!(err.to_string().contains("appears twice"), "{err}");
    }

    #[test]
    fn wrong_shape_is_a_schema_error() {
        let err = load(r#"{"rules": []}"#).unwrap_err();
        assert!(matches!(err, Error::ValidUsageSchema { .. }), "{err}");
    }
}
