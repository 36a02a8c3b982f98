//! The registry's synchronization tables (`<sync>`, since 1.3.2xx): every pipeline
//! stage and access type of synchronization2, which stages each access type belongs to,
//! the stages and access types that stand for others, and the logical order of the
//! stages in each kind of pipeline. Values are resolved to numbers here, from the
//! registry that holds the tables.

use crate::error::{Error, Result};
use std::collections::BTreeMap;
use std::path::Path;
use vk_parse as vk;

/// A `<syncstage>` or `<syncaccess>`: its name, value and what the registry says of it.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct SyncItem {
    /// `VK_PIPELINE_STAGE_2_COPY_BIT`, `VK_ACCESS_2_TRANSFER_READ_BIT`.
    pub name: String,
    /// Its bit (`0` for `..._NONE`).
    pub bit: u64,
    /// For an access type: the stages it may be used with (`syncsupport stage`),
    /// `None` where the registry lists none (every stage: `MEMORY_READ`).
    pub stages: Option<Vec<String>>,
    /// The stages or access types it stands for (`syncequivalent`), empty if none.
    pub equivalent: Vec<String>,
}

/// One `<syncpipeline>`: its stages in logical order, each with whether it is
/// ordered against the others (`order="None"`: it is not).
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct SyncPipeline {
    /// `graphics primitive`.
    pub name: String,
    /// The ordered stages, in logical order.
    pub ordered: Vec<String>,
}

/// The `<sync>` block, as written, values resolved.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct SyncTables {
    /// The registry version the tables come from.
    pub version: String,
    /// Every `<syncstage>`.
    pub stages: Vec<SyncItem>,
    /// Every `<syncaccess>`.
    pub accesses: Vec<SyncItem>,
    /// Every `<syncpipeline>`.
    pub pipelines: Vec<SyncPipeline>,
}

fn bad(path: &Path, message: String) -> Error {
    Error::BadRegistry {
        path: path.to_owned(),
        message,
    }
}

fn split(list: Option<&str>) -> Vec<String> {
    list.unwrap_or("")
        .split(',')
        .filter(|s| !s.is_empty())
        .map(str::to_owned)
        .collect()
}

fn bit(numbers: &BTreeMap<String, i64>, name: &str, path: &Path) -> Result<u64> {
    let n = numbers.get(name).copied().ok_or_else(|| {
        bad(
            path,
            format!("<sync> names {name}, which the registry defines no value for"),
        )
    })?;
    Ok(n as u64)
}

/// Reads a `<sync>` block with the values `numbers` resolves.
pub(crate) fn read(
    sync: vk::Sync,
    numbers: &BTreeMap<String, i64>,
    version: &str,
    path: &Path,
) -> Result<SyncTables> {
    let mut out = SyncTables {
        version: version.to_owned(),
        ..SyncTables::default()
    };
    for child in sync.children {
        match child {
            vk::SyncChild::Stage(s) => out.stages.push(SyncItem {
                bit: bit(numbers, &s.name, path)?,
                stages: None,
                equivalent: split(s.syncequivalent.as_ref().and_then(|e| e.stage.as_deref())),
                name: s.name,
            }),
            vk::SyncChild::Access(a) => out.accesses.push(SyncItem {
                bit: bit(numbers, &a.name, path)?,
                stages: a
                    .syncsupport
                    .as_ref()
                    .and_then(|s| s.stage.as_deref())
                    .map(|s| split(Some(s))),
                equivalent: split(a.syncequivalent.as_ref().and_then(|e| e.access.as_deref())),
                name: a.name,
            }),
            vk::SyncChild::Pipeline(p) => out.pipelines.push(SyncPipeline {
                name: p.name,
                ordered: p
                    .children
                    .into_iter()
                    .filter(|s| s.order.as_deref() != Some("None"))
                    .map(|s| s.text)
                    .collect(),
            }),
            _ => {}
        }
    }
    // Every name the tables use must be one of theirs: a misspelt or unknown stage
    // would silently drop out of an equivalence or an order.
    let stage_names: Vec<&str> = out.stages.iter().map(|s| s.name.as_str()).collect();
    let access_names: Vec<&str> = out.accesses.iter().map(|s| s.name.as_str()).collect();
    let known_stage = |n: &str| {
        stage_names.contains(&n) || numbers.contains_key(n) && n.starts_with("VK_PIPELINE_STAGE_2_")
    };
    for s in &out.stages {
        for e in &s.equivalent {
            if !known_stage(e) {
                return Err(bad(
                    path,
                    format!(
                        "<syncstage {}> is equivalent to {e}, which is no stage of <sync>",
                        s.name
                    ),
                ));
            }
        }
    }
    for a in &out.accesses {
        for e in a.stages.iter().flatten() {
            if !known_stage(e) {
                return Err(bad(
                    path,
                    format!(
                        "<syncaccess {}> supports {e}, which is no stage of <sync>",
                        a.name
                    ),
                ));
            }
        }
        for e in &a.equivalent {
            if !access_names.contains(&e.as_str()) {
                return Err(bad(
                    path,
                    format!(
                        "<syncaccess {}> is equivalent to {e}, which is no access of <sync>",
                        a.name
                    ),
                ));
            }
        }
    }
    for p in &out.pipelines {
        for s in &p.ordered {
            if !known_stage(s) {
                return Err(bad(
                    path,
                    format!(
                        "<syncpipeline {}> orders {s}, which is no stage of <sync>",
                        p.name
                    ),
                ));
            }
        }
    }
    Ok(out)
}
