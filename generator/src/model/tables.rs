//! Where `ash` keeps each command of the emitted API, and under which sets of the
//! config's extensions an item exists: model queries that both the model's
//! reference check and the emitters ask.

use super::{Condition, Model};
use std::collections::BTreeSet;

/// The extensions of the config, each set minimal, under which `condition` holds.
pub fn minimal_feature_sets(model: &Model, condition: &Condition) -> Vec<BTreeSet<String>> {
    let versions: BTreeSet<String> = model
        .enabled
        .iter()
        .filter(|n| n.starts_with("VK_VERSION_"))
        .cloned()
        .collect();
    let expr = condition.expr();
    if expr.eval(&versions) {
        return vec![BTreeSet::new()];
    }
    let fixed = |n: &str| {
        if n == "core" || n.starts_with("VK_VERSION_") {
            Some(n == "core" || versions.contains(n))
        } else if !model.enabled.contains(n) {
            Some(false)
        } else {
            None
        }
    };
    if let Some(sets) = expr.minimal_sets(&fixed) {
        return sets;
    }
    // A negation (validusage.json's keys only): search subsets of the names it
    // mentions.
    let mentioned = expr.names();
    let exts: Vec<&String> = model
        .enabled
        .iter()
        .filter(|n| !n.starts_with("VK_VERSION_") && mentioned.contains(n.as_str()))
        .collect();
    let mut found: Vec<BTreeSet<String>> = Vec::new();
    // Subsets in order of size, so that a superset of a found set is skipped.
    let mut subsets: Vec<u32> = (1..(1u32 << exts.len().min(16))).collect();
    subsets.sort_by_key(|m| m.count_ones());
    for mask in subsets {
        let set: BTreeSet<String> = exts
            .iter()
            .enumerate()
            .filter(|(i, _)| mask & (1 << i) != 0)
            .map(|(_, e)| (*e).clone())
            .collect();
        if found.iter().any(|f| f.is_subset(&set)) {
            continue;
        }
        let mut names = versions.clone();
        names.extend(set.iter().cloned());
        if expr.eval(&names) {
            found.push(set);
        }
    }
    found
}

/// Where ash keeps a command's function pointer.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Table {
    /// A core table: `fp_v1_<minor>()` of the entry, instance or device.
    Core(u32),
    /// An extension's `InstanceFn` or `DeviceFn`.
    Extension(String),
    /// A core version ash has no table for (`Model::own_tables`): the emitted
    /// crate's `DeviceFnV1_<minor>`, loaded by the commands' core names.
    Own(u32),
}

/// The table a command of the emitted API is called through: the oldest core version
/// that has it, else the first enabled extension that does.
pub fn table(model: &Model, command: &str) -> Option<Table> {
    let condition = model.condition(command);
    if condition.is_core() {
        return Some(Table::Core(0));
    }
    let alternatives = condition.expr().alternatives();
    let best = alternatives
        .iter()
        .filter_map(|alt| match alt {
            super::expr::Expr::Name(n) if model.enabled.contains(n) => {
                n.strip_prefix("VK_VERSION_1_")?.parse::<u32>().ok()
            }
            _ => None,
        })
        .min();
    if let Some(m) = best {
        return Some(match model.own_tables.contains(&m) {
            true => Table::Own(m),
            false => Table::Core(m),
        });
    }
    minimal_feature_sets(model, condition)
        .into_iter()
        .next()
        .and_then(|set| {
            // The command belongs to the extension whose require block names it.
            set.into_iter().find(|e| {
                alternatives
                    .iter()
                    .any(|a| a.first_name() == Some(e.as_str()))
            })
        })
        .map(Table::Extension)
}
