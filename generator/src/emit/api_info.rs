//! Emits `src/generated/api_info.rs`: which registry and which part of it the crate was
//! generated from. It settles no rule.

use super::{Emission, OutputFile};
use crate::model::Model;

pub(super) fn emit(model: &Model, enabling: &crate::plan::safety::Enabling, out: &mut Emission) {
    // The newest core version emitted: the config's, less any the reference lacks.
    let minor = model
        .enabled
        .iter()
        .filter_map(|v| v.strip_prefix("VK_VERSION_1_")?.parse::<u32>().ok())
        .max()
        .unwrap_or(0);
    let extensions: Vec<&String> = model
        .enabled
        .iter()
        .filter(|e| !e.starts_with("VK_VERSION_"))
        .collect();
    let mut s = String::new();
    s.push_str(super::HEADER);
    s.push_str("\n\n");
    s.push_str("/// The Vulkan registry version the crate was generated from.\n");
    s.push_str(&format!(
        "pub const REGISTRY_VERSION: &str = {:?};\n\n",
        model.version
    ));
    s.push_str("/// The newest core version the crate emits, as (major, minor).\n");
    s.push_str(&format!(
        "pub const API_VERSION: (u32, u32) = (1, {minor});\n\n"
    ));
    s.push_str("/// The extensions the crate emits besides core.\n");
    s.push_str("pub const EXTENSIONS: &[&str] = &[\n");
    for ext in &extensions {
        s.push_str(&format!("    {ext:?},\n"));
    }
    s.push_str("];\n\n");
    s.push_str(
        "/// The emitted extensions the safe `create_instance` and `create_device` enable:\n\
         /// each of the others brings rules to methods outside it that no check enforces\n\
         /// (`generated/VALIDATION.md` lists them), so only the `unsafe` `_unchecked`\n\
         /// constructors enable it.\n",
    );
    s.push_str("pub const CHECKED_EXTENSIONS: &[&str] = &[\n");
    for ext in extensions.iter().filter(|e| enabling.allowed.contains(**e)) {
        s.push_str(&format!("    {ext:?},\n"));
    }
    s.push_str("];\n");
    extension_requires(model, &extensions, &mut s);
    device_features(model, &mut s);
    out.files.push(OutputFile {
        path: format!("{}/api_info.rs", super::GENERATED_DIR).into(),
        contents: s,
    });
}

/// What each emitted extension needs beside it, from vk.xml's `depends` (or
/// `requires`): one row per alternative, the names that must all hold (an extension
/// enabled with it, or a core version `VK_VERSION_1_x` the API version reaches)
/// joined by `+`; an extension with no dependency has one empty row. The rows are
/// laid out as rustfmt lays out a pair: on one line when the pair's contents are at
/// most 60 characters wide, else one element per line.
fn extension_requires(model: &Model, extensions: &[&String], s: &mut String) {
    s.push_str(
        "\n/// What each emitted extension needs beside it (vk.xml's `depends`): one row per\n\
         /// alternative, the extensions enabled with it and core versions (`VK_VERSION_1_x`)\n\
         /// the API version reaches, joined by `+` (empty: nothing). An extension with no\n\
         /// row can never be enabled.\n",
    );
    s.push_str("pub const EXTENSION_REQUIRES: &[(&str, &str)] = &[\n");
    for ext in extensions {
        let sets = match model.extension_depends.get(*ext) {
            // A dependency with a negation (none in any registry yet) is written as
            // no row: enabling the extension is then refused, never let by.
            Some(depends) => {
                crate::model::expr::minimal_sets(depends, &|_| None).unwrap_or_default()
            }
            None => vec![Default::default()],
        };
        for set in sets {
            let names: Vec<&str> = set.iter().map(String::as_str).collect();
            let (a, b) = (format!("{ext:?}"), format!("{:?}", names.join("+")));
            if a.len() + b.len() + 2 <= 60 {
                s.push_str(&format!("    ({a}, {b}),\n"));
            } else {
                s.push_str(&format!("    (\n        {a},\n        {b},\n    ),\n"));
            }
        }
    }
    s.push_str("];\n");
}

/// The members of `VkPhysicalDeviceFeatures` in declaration order: the wrappers read
/// the struct as that many `VkBool32`s to name what a device lacks when its creation
/// returns `VK_ERROR_FEATURE_NOT_PRESENT`.
fn device_features(model: &Model, s: &mut String) {
    let names: Vec<&str> = model
        .types
        .get("VkPhysicalDeviceFeatures")
        .map(|t| {
            t.members
                .iter()
                .filter(|m| {
                    m.type_name == "VkBool32" && m.pointers == 0 && m.static_array.is_none()
                })
                .map(|m| m.name.as_str())
                .collect()
        })
        .unwrap_or_default();
    s.push_str(
        "\n/// The members of `VkPhysicalDeviceFeatures`, in order: each is a `VkBool32`.\n",
    );
    s.push_str("pub const DEVICE_FEATURES: &[&str] = &[\n");
    for name in names {
        s.push_str(&format!("    {name:?},\n"));
    }
    s.push_str("];\n");
}
