//! Which Cargo features turn on which: an extension's feature turns on those of the
//! extensions it depends on and of those whose types its items name, and an item
//! whose condition its feature set does not imply gets a `cfg` of its own.

use crate::model::{Condition, Kind, Model};
use crate::names::{table, Table};
use std::collections::BTreeSet;

/// The extensions whose features the feature of `ext` turns on: those its
/// `depends` names, then those whose items its own items reference.
pub fn feature_deps(model: &Model, ext: &str) -> Vec<String> {
    let mut deps: Vec<String> = model
        .extension_depends
        .get(ext)
        .map(|d| {
            model
                .enabled
                .iter()
                .filter(|e| !e.starts_with("VK_VERSION_") && *e != ext && d.contains(e.as_str()))
                .cloned()
                .collect()
        })
        .unwrap_or_default();
    for e in referenced_extensions(model, ext) {
        if !deps.contains(&e) {
            deps.push(e);
        }
    }
    deps
}

/// `exts` with every extension their features turn on, transitively.
pub fn feature_closure(
    model: &Model,
    exts: &std::collections::BTreeSet<String>,
) -> std::collections::BTreeSet<String> {
    let mut on = exts.clone();
    let mut todo: Vec<String> = exts.iter().cloned().collect();
    while let Some(e) = todo.pop() {
        for d in feature_deps(model, &e) {
            if on.insert(d.clone()) {
                todo.push(d);
            }
        }
    }
    on
}

/// The emitted extensions whose types the items of extension `ext` name (a member's
/// or a parameter's type) where no core version defines them: `ext`'s feature
/// turns theirs on, so that its items compile alone (`VkRayTracingPipelineCreateInfoKHR`
/// points to `VkPipelineLibraryCreateInfoKHR`, which only `VK_KHR_pipeline_library`
/// requires).
fn referenced_extensions(model: &Model, ext: &str) -> Vec<String> {
    // Items compiled whenever `ext`'s feature is on: one alternative of their
    // condition needs `ext` and core versions alone.
    let gated = |item: &str| {
        let c = model.condition(item);
        !c.is_core()
            && c.expr()
                .minimal_sets(&|_| None)
                .unwrap_or_default()
                .iter()
                .any(|set| {
                    set.contains(ext)
                        && set.iter().all(|n| n == ext || n.starts_with("VK_VERSION_"))
                })
    };
    let mut named: BTreeSet<&str> = BTreeSet::new();
    for t in model
        .types
        .values()
        .filter(|t| model.emitted.contains(&t.name))
    {
        if gated(&t.name) {
            named.extend(t.members.iter().map(|m| m.type_name.as_str()));
        }
    }
    for c in model
        .commands
        .values()
        .filter(|c| model.emitted.contains(&c.name))
    {
        if gated(&c.name) {
            named.extend(c.params.iter().map(|p| p.type_name.as_str()));
        }
    }
    let mut out: BTreeSet<String> = BTreeSet::new();
    for t in named {
        if !model.emitted.contains(t) || !model.types.contains_key(t) {
            continue;
        }
        let c = model.condition(t);
        if c.is_core() {
            continue;
        }
        let sets = c.expr().minimal_sets(&|_| None).unwrap_or_default();
        // Defined by a core version, or by `ext` itself: nothing to add.
        let free = sets
            .iter()
            .any(|set| set.iter().all(|n| n.starts_with("VK_VERSION_") || n == ext));
        if free {
            continue;
        }
        if let Some(smallest) = sets.iter().min_by_key(|set| set.len()) {
            out.extend(
                smallest
                    .iter()
                    .filter(|n| {
                        !n.starts_with("VK_VERSION_") && *n != ext && model.enabled.contains(*n)
                    })
                    .cloned(),
            );
        }
    }
    out.into_iter().collect()
}

/// The condition a command's method is compiled under: its own, or, for a command of
/// several extensions called through one of their function tables
/// (`vkGetRayTracingShaderGroupHandlesKHR`, also `VK_NV_ray_tracing`'s under another
/// name), that table's extension, where its own condition does not imply it.
pub fn command_condition(model: &Model, command: &str) -> Condition {
    if let Some(Table::Extension(e)) = table(model, command) {
        if let Ok(table_ext) = Condition::parse(&e) {
            if !model
                .condition(command)
                .implies(&table_ext, &|set| feature_closure(model, set))
            {
                return table_ext;
            }
        }
    }
    model.condition(command).clone()
}

/// The condition of a struct member's setter where it is narrower than its struct's:
/// the member's type is tuff's own (a wrapper or safe struct, which exist only
/// under their `cfg`; ash has every type whatever the features) and the struct's
/// condition, with the features it turns on, does not imply the type's
/// (`accelerationStructureNV` of a struct that VK_KHR_acceleration_structure alone
/// also brings).
pub fn member_condition(
    model: &Model,
    facts: &super::types::TypeFacts,
    struct_name: &str,
    member_type: &str,
) -> Option<Condition> {
    let of_type = model.condition(member_type);
    let tuffs = model.category(member_type) == Some(Kind::Handle) || facts.is_safe(member_type);
    if of_type.is_core() || !tuffs {
        return None;
    }
    (!model
        .condition(struct_name)
        .implies(of_type, &|set| feature_closure(model, set)))
    .then(|| of_type.clone())
}
