//! How registry names become Rust names, and where `ash` keeps each command.
//!
//! The generated crate calls ash's function tables directly, so these names must match
//! the ones ash's own generator derives (snake case of the name without `vk`, `type`
//! spelled `ty`).

pub use crate::model::tables::{minimal_feature_sets, table, Table};
use crate::model::{Condition, Model};
use heck::{ToShoutySnakeCase, ToSnakeCase, ToUpperCamelCase};
use proc_macro2::{Ident, Span, TokenStream};
use quote::quote;
use std::collections::{BTreeMap, BTreeSet};

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

/// The name a command's method is made from: the one ash knows it by, except for a
/// command of a core version ash has no table for, which the emitted crate calls by
/// its core name (`vkCmdPushDescriptorSet`, not ash's `vkCmdPushDescriptorSetKHR`).
fn method_spelling<'a>(model: &'a Model, command: &'a str) -> &'a str {
    match table(model, command) {
        Some(Table::Own(_)) => command,
        _ => model.spelling(command),
    }
}

/// The method of every command of `model`, by command: `command_fn` of the name the
/// emitted API knows it by ([`Model::spelling`]), less the words that repeat the
/// receiver (see [`receiver_relative`]), unless that would give two commands of one
/// receiver the same name, in which case the shortened one keeps its Vulkan name
/// (`vkGetDeviceBufferMemoryRequirements` stays `get_device_buffer_memory_requirements`
/// beside `vkGetBufferMemoryRequirements`'s `get_buffer_memory_requirements`).
pub fn methods(model: &Model) -> BTreeMap<String, String> {
    let receiver_of = |command: &str| receiver_type(model, command).to_owned();
    let full: BTreeMap<&str, (String, String)> = model
        .commands
        .keys()
        .map(|c| {
            (
                c.as_str(),
                (receiver_of(c), command_fn(method_spelling(model, c))),
            )
        })
        .collect();
    let taken: BTreeSet<(&str, &str)> = full
        .values()
        .map(|(r, m)| (r.as_str(), m.as_str()))
        .collect();
    let short: BTreeMap<&str, String> = full
        .iter()
        .map(|(command, (receiver, name))| (*command, receiver_relative(model, receiver, name)))
        .collect();
    let mut uses: BTreeMap<(&str, &str), usize> = BTreeMap::new();
    for (command, (receiver, _)) in &full {
        *uses
            .entry((receiver.as_str(), short[command].as_str()))
            .or_default() += 1;
    }
    full.iter()
        .map(|(command, (receiver, name))| {
            let s = &short[command];
            let clashes = s != name
                && (uses[&(receiver.as_str(), s.as_str())] > 1
                    || taken.contains(&(receiver.as_str(), s.as_str())));
            let chosen = if clashes { name.clone() } else { s.clone() };
            (command.to_string(), chosen)
        })
        .collect()
}

/// The type whose method a command becomes: its dispatchable handle
/// (`VkQueue`), `Recorder` for a command recorded into a command buffer, `Entry`
/// for a global command.
pub fn receiver_type<'a>(model: &'a Model, command: &str) -> &'a str {
    match model.receiver(command) {
        Some("VkCommandBuffer") if command.starts_with("vkCmd") => "Recorder",
        Some(r) => r,
        None => "Entry",
    }
}

/// A method name without the words that repeat its receiver: `cmd_draw` on a
/// recorder is `draw`, `queue_submit` on a queue `submit`, `device_wait_idle` on a
/// device `wait_idle`, `get_physical_device_properties` on a physical device
/// `get_properties`, `reset_command_buffer` on a command buffer `reset`. The words
/// stay where they begin another handle's name (`get_device_memory_commitment`
/// speaks of a `VkDeviceMemory`), and where nothing would be left.
pub fn receiver_relative(model: &Model, receiver: &str, name: &str) -> String {
    // A receiver's vendor tag is not among the command's words (`VkDisplayKHR`'s
    // `vkReleaseDisplayEXT`).
    let full = type_name(receiver);
    let base = VENDOR_TAGS
        .iter()
        .find_map(|t| full.strip_suffix(t))
        .unwrap_or(&full);
    let words = if receiver == "Recorder" {
        "cmd".to_owned()
    } else {
        base.to_snake_case()
    };
    let names_a_type = |rest: &str| {
        let next = rest.split('_').next().unwrap_or("");
        let candidate = format!("{base}{}", next.to_upper_camel_case());
        !next.is_empty()
            && model.category(&format!("Vk{candidate}")) == Some(crate::model::Kind::Handle)
    };
    let stripped = if let Some(rest) = name.strip_prefix(&format!("{words}_")) {
        (!names_a_type(rest)).then(|| rest.to_owned())
    } else if let Some((verb, rest)) = name.split_once('_') {
        if rest == words {
            Some(verb.to_owned())
        } else {
            rest.strip_prefix(&format!("{words}_"))
                .filter(|r| !names_a_type(r))
                .map(|r| format!("{verb}_{r}"))
        }
    } else {
        None
    };
    match stripped {
        Some(s) if !s.is_empty() && syn::parse_str::<Ident>(&s).is_ok() => s,
        _ => name.to_owned(),
    }
}

/// Vendor tags, which ash keeps upper case in a type's or a value's name.
const VENDOR_TAGS: &[&str] = &[
    "KHR", "EXT", "NV", "NVX", "AMD", "ARM", "QCOM", "INTEL", "GOOGLE", "HUAWEI", "VALVE",
    "FUCHSIA", "MVK", "GGP", "ANDROID", "QNX", "SEC", "IMG", "MESA", "LUNARG", "NN", "MSFT",
];

/// The name ash gives an enum value in its type's `impl`: `VK_DESCRIPTOR_TYPE_SAMPLER`
/// of `VkDescriptorType` is `SAMPLER`, `VK_GEOMETRY_TYPE_TRIANGLES_KHR` of
/// `VkGeometryTypeKHR` is `TRIANGLES` (the type's own vendor tag goes too).
pub fn enum_const(type_name: &str, value: &str) -> String {
    let base = type_name.strip_prefix("Vk").unwrap_or(type_name);
    let tag = VENDOR_TAGS.iter().find(|t| base.ends_with(*t));
    let base = tag.map_or(base, |t| &base[..base.len() - t.len()]);
    let prefix = format!("VK_{}_", base.to_shouty_snake_case());
    let mut rest = value.strip_prefix(&prefix).unwrap_or(value).to_owned();
    if let Some(t) = tag {
        if let Some(r) = rest.strip_suffix(&format!("_{t}")) {
            rest = r.to_owned();
        }
    }
    if rest.starts_with(|c: char| c.is_ascii_digit()) {
        rest = format!("TYPE_{rest}");
    }
    rest
}

/// An enum value's name as a Rust variant: `ACCELERATION_STRUCTURE_KHR` ->
/// `AccelerationStructureKHR`.
pub fn variant_name(shouty: &str) -> String {
    shouty
        .split('_')
        .map(|w| match VENDOR_TAGS.contains(&w) {
            true => w.to_owned(),
            false => w.to_upper_camel_case(),
        })
        .collect()
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

/// The field of `table` that holds `command`'s function pointer: ash names an
/// extension's field after the name that extension's require blocks use, which for
/// a command promoted or renamed since is one of its aliases
/// (`get_ray_tracing_shader_group_handles_nv` in `VK_NV_ray_tracing`'s table).
pub fn fn_field(model: &Model, command: &str, table: &Table) -> Ident {
    match table {
        Table::Core(_) | Table::Own(_) => ident(&command_fn(command)),
        Table::Extension(e) => ident(&command_fn(model.name_in(command, e))),
    }
}

/// Of a table that may be absent (an extension's, or the crate's own of a core
/// version ash lacks): its field of the receiver's `ext()`, and the error a call
/// gets without it; `None` for a core table of ash's, which is always there.
pub fn optional_table(table: &Table) -> Option<(Ident, TokenStream)> {
    match table {
        Table::Extension(e) => Some((ident(&feature(e)), quote!(Error::ExtensionNotEnabled(#e)))),
        Table::Own(m) => {
            let version = format!("Vulkan 1.{m}");
            Some((
                ident(&format!("v1_{m}")),
                quote!(Error::VersionNotSupported(#version)),
            ))
        }
        Table::Core(_) => None,
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn enum_values_are_named_as_ash_names_them() {
        assert_eq!(
            enum_const("VkDescriptorType", "VK_DESCRIPTOR_TYPE_SAMPLER"),
            "SAMPLER"
        );
        // The type's own vendor tag goes; another vendor's stays.
        assert_eq!(
            enum_const("VkGeometryTypeKHR", "VK_GEOMETRY_TYPE_TRIANGLES_KHR"),
            "TRIANGLES"
        );
        assert_eq!(
            enum_const(
                "VkDescriptorType",
                "VK_DESCRIPTOR_TYPE_ACCELERATION_STRUCTURE_NV"
            ),
            "ACCELERATION_STRUCTURE_NV"
        );
        // A name that would start with a digit gets ash's `TYPE_`.
        assert_eq!(enum_const("VkImageType", "VK_IMAGE_TYPE_2D"), "TYPE_2D");
        assert_eq!(
            variant_name("ACCELERATION_STRUCTURE_KHR"),
            "AccelerationStructureKHR"
        );
        assert_eq!(variant_name("UNIFORM_TEXEL_BUFFER"), "UniformTexelBuffer");
    }

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
