//! Classification of explicit rules into *creation* and *usage*.
//!
//! The rule, as the report states it: a rule is *creation* when its item is a command
//! named `vkCreate*` or `vkAllocate*`, a struct named `Vk*CreateInfo*` or
//! `Vk*AllocateInfo*`, or any other struct that has at least one user and all of
//! whose users are creation items, repeated until nothing changes. A struct's users
//! are the commands that take it as a parameter, the structs that have it as a
//! member, and the structs whose `pNext` chain it extends (aliases resolved to the
//! item they name). Every other explicit rule, SPIR-V and built-in rules included, is
//! *usage*.

use super::Category;
use crate::model::Kind;
use crate::model::Model;
use std::collections::{BTreeMap, BTreeSet};

/// The classification rule in words, for the report's preamble.
pub const RULE_TEXT: &str = "A rule is **creation** when its item is a command named \
`vkCreate*` or `vkAllocate*`, a struct named `Vk*CreateInfo*` or `Vk*AllocateInfo*`, or \
any other struct that has at least one user and all of whose users are creation items, \
repeated to a fixed point. A struct's users are the commands that take it as a \
parameter, the structs that have it as a member and the structs whose `pNext` chain it \
extends, with aliases resolved. Every other explicit rule, SPIR-V and built-in rules \
included, is **usage**.";

/// The items whose explicit rules are creation rules.
pub fn creation_items(model: &Model) -> BTreeSet<String> {
    let canonical = |name: &str| -> String {
        let mut n = name.to_owned();
        for _ in 0..4 {
            match model.types.get(&n).and_then(|t| t.alias.clone()) {
                Some(a) => n = a,
                None => break,
            }
        }
        n
    };
    let mut users: BTreeMap<String, BTreeSet<String>> = BTreeMap::new();
    for c in model.commands.values().filter(|c| c.alias.is_none()) {
        for p in &c.params {
            users
                .entry(canonical(&p.type_name))
                .or_default()
                .insert(c.name.clone());
        }
    }
    for t in model.types.values().filter(|t| t.alias.is_none()) {
        for m in &t.members {
            let member = canonical(&m.type_name);
            if member != t.name {
                users.entry(member).or_default().insert(t.name.clone());
            }
        }
        for head in &t.struct_extends {
            users
                .entry(t.name.clone())
                .or_default()
                .insert(canonical(head));
        }
    }

    let mut creation: BTreeSet<String> = model
        .commands
        .keys()
        .filter(|c| c.starts_with("vkCreate") || c.starts_with("vkAllocate"))
        .cloned()
        .collect();
    let structs: Vec<&String> = model
        .types
        .iter()
        .filter(|(_, t)| {
            t.alias.is_none() && matches!(t.category, Some(Kind::Struct | Kind::Union))
        })
        .map(|(n, _)| n)
        .collect();
    for s in &structs {
        if is_info_name(s) {
            creation.insert((*s).clone());
        }
    }
    let mut changed = true;
    while changed {
        changed = false;
        for s in &structs {
            if creation.contains(*s) {
                continue;
            }
            if let Some(u) = users.get(*s) {
                if !u.is_empty() && u.iter().all(|x| creation.contains(x)) {
                    creation.insert((*s).clone());
                    changed = true;
                }
            }
        }
    }
    creation
}

fn is_info_name(name: &str) -> bool {
    name.starts_with("Vk") && (name.contains("CreateInfo") || name.contains("AllocateInfo"))
}

/// The category of an explicit rule of `item`.
pub fn explicit_category(item: &str, creation: &BTreeSet<String>) -> Category {
    if creation.contains(item) {
        Category::Creation
    } else {
        Category::Usage
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn info_names() {
        assert!(is_info_name("VkBufferCreateInfo"));
        assert!(is_info_name("VkCommandBufferAllocateInfo"));
        assert!(is_info_name("VkDeviceQueueCreateInfo"));
        assert!(!is_info_name("VkSubmitInfo"));
    }
}
