//! How registry names become Rust names, and where `ash` keeps each command.
//!
//! The generated crate calls ash's function tables directly, so these names must match
//! the ones ash's own generator derives (snake case of the name without `vk`, `type`
//! spelled `ty`).

use crate::model::{Condition, Model};
use heck::ToSnakeCase;
use proc_macro2::{Ident, Span, TokenStream};
use quote::quote;
use std::collections::BTreeSet;

/// An identifier token.
pub fn ident(name: &str) -> Ident {
    // Registry names are identifiers; an empty one (an emitter asking for a name
    // that does not apply) becomes a placeholder rather than a panic.
    let name = if name.is_empty() { "unnamed" } else { name };
    Ident::new(name, Span::call_site())
}

/// `VkBufferCreateInfo` -> `BufferCreateInfo`, as ash and the generated crate name it.
pub fn type_name(vk_name: &str) -> String {
    vk_name.strip_prefix("Vk").unwrap_or(vk_name).to_owned()
}

/// The Rust identifier of a registry type.
pub fn type_ident(vk_name: &str) -> Ident {
    ident(&type_name(vk_name))
}

/// `vkCmdDraw` -> `cmd_draw`.
pub fn command_fn(name: &str) -> String {
    name.strip_prefix("vk").unwrap_or(name).to_snake_case()
}

/// A member or parameter name as ash spells it.
pub fn field(name: &str) -> String {
    let snake = name.to_snake_case();
    match snake.as_str() {
        "type" => "ty".to_owned(),
        _ => snake,
    }
}

/// A member or parameter identifier as ash spells it.
pub fn field_ident(name: &str) -> Ident {
    ident(&field(name))
}

/// A parameter name without its Hungarian pointer prefix: `pCreateInfo` ->
/// `create_info`, `ppData` -> `data`.
pub fn param(name: &str) -> String {
    let bytes = name.as_bytes();
    let mut i = 0;
    while i < bytes.len() && bytes[i] == b'p' {
        i += 1;
    }
    let stripped = if i > 0 && i < bytes.len() && bytes[i].is_ascii_uppercase() {
        &name[i..]
    } else {
        name
    };
    let snake = stripped.to_snake_case();
    match snake.as_str() {
        "type" => "ty".to_owned(),
        "ref" | "in" | "fn" | "mod" | "use" | "match" | "loop" | "move" | "self" => {
            format!("{snake}_")
        }
        _ => snake,
    }
}

/// `VK_KHR_swapchain` -> `khr_swapchain`: the generated crate's Cargo feature.
pub fn feature(ext: &str) -> String {
    ext.strip_prefix("VK_").unwrap_or(ext).to_lowercase()
}

/// `VK_KHR_swapchain` -> `ash::khr::swapchain`.
pub fn ash_extension_module(ext: &str) -> TokenStream {
    let rest = ext.strip_prefix("VK_").unwrap_or(ext);
    let (vendor, name) = rest.split_once('_').unwrap_or(("khr", rest));
    let vendor = ident(&vendor.to_lowercase());
    let name = ident(name);
    quote!(ash::#vendor::#name)
}

/// The `#[cfg]` under which an item with this condition exists in the generated
/// crate: the smallest sets of the config's extensions that make the condition hold
/// (with every core version up to the cap enabled). `None` when core alone suffices.
pub fn cfg_of(model: &Model, condition: &Condition) -> Option<TokenStream> {
    let sets = minimal_feature_sets(model, condition);
    if sets.iter().any(BTreeSet::is_empty) {
        return None;
    }
    let alternatives: Vec<TokenStream> = sets
        .iter()
        .map(|set| {
            let features: Vec<String> = set.iter().map(|e| feature(e)).collect();
            match features.as_slice() {
                [one] => quote!(feature = #one),
                _ => quote!(all(#(feature = #features),*)),
            }
        })
        .collect();
    Some(match alternatives.as_slice() {
        [one] => quote!(#[cfg(#one)]),
        _ => quote!(#[cfg(any(#(#alternatives),*))]),
    })
}

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
}

/// The field of `table` that holds `command`'s function pointer: ash names an
/// extension's field after the name that extension's require blocks use, which for
/// a command promoted or renamed since is one of its aliases
/// (`get_ray_tracing_shader_group_handles_nv` in `VK_NV_ray_tracing`'s table).
pub fn fn_field(model: &Model, command: &str, table: &Table) -> Ident {
    match table {
        Table::Core(_) => ident(&command_fn(command)),
        Table::Extension(e) => ident(&command_fn(model.name_in(command, e))),
    }
}

/// Which level a command dispatches at.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Level {
    /// No dispatchable handle: the loader's entry points.
    Entry,
    /// `VkInstance` or `VkPhysicalDevice`.
    Instance,
    /// `VkDevice`, `VkQueue` or `VkCommandBuffer`.
    Device,
}

/// The dispatch level of a command, from its first parameter.
pub fn level(model: &Model, command: &str) -> Level {
    let first = model
        .commands
        .get(command)
        .and_then(|c| c.params.first())
        .map(|p| p.type_name.as_str());
    match first {
        Some("VkInstance" | "VkPhysicalDevice") => Level::Instance,
        Some("VkDevice" | "VkQueue" | "VkCommandBuffer") => Level::Device,
        _ => Level::Entry,
    }
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
            crate::model::expr::Expr::Name(n) if model.enabled.contains(n) => {
                n.strip_prefix("VK_VERSION_1_")?.parse::<u32>().ok()
            }
            _ => None,
        })
        .min();
    if let Some(m) = best {
        return Some(Table::Core(m));
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_match_ash() {
        assert_eq!(command_fn("vkCmdDraw"), "cmd_draw");
        assert_eq!(
            command_fn("vkGetPhysicalDeviceSurfaceSupportKHR"),
            "get_physical_device_surface_support_khr"
        );
        assert_eq!(field("pQueueFamilyIndices"), "p_queue_family_indices");
        assert_eq!(field("type"), "ty");
        assert_eq!(param("pCreateInfo"), "create_info");
        assert_eq!(param("ppEnabledLayerNames"), "enabled_layer_names");
        assert_eq!(param("physicalDevice"), "physical_device");
        assert_eq!(feature("VK_KHR_swapchain"), "khr_swapchain");
        assert_eq!(
            ash_extension_module("VK_EXT_debug_utils").to_string(),
            "ash :: ext :: debug_utils"
        );
    }
}
