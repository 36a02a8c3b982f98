//! Model pass: resolve the registry into the API the generator reasons about.
//!
//! For the whole registry (every feature and every extension the vulkan API supports,
//! the "all extensions" build the specification itself is generated from) it records
//! which items exist, what each handle's parents and lifetime commands are, the parsed
//! attributes of every parameter and member, and for every command and struct the
//! condition (features and extensions) under which it exists. The config then picks
//! the emitted subset.

pub mod attrs;
pub mod expr;
mod item;
pub mod reference;

/// The registry's synchronization tables, as the model keeps them.
pub use crate::registry::{SyncItem, SyncPipeline, SyncTables};
pub mod tables;

use crate::config::Config;
use crate::error::{Error, Result};
use crate::registry::Registry;
use std::collections::{BTreeMap, BTreeSet};
use std::path::Path;

pub use attrs::{ExternSync, LenEntry};
pub use item::{CommandDef, Field, Kind, Parsed, TypeDef};

/// When an item exists: the expression as the model writes it (what the report
/// shows) and its parse, so no pass re-reads the text.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Condition {
    text: String,
    expr: expr::Expr,
}

impl Condition {
    /// Parse the text of a condition.
    pub fn parse(text: &str) -> std::result::Result<Condition, String> {
        Ok(Condition {
            text: text.to_owned(),
            expr: expr::Expr::parse(text)?,
        })
    }

    /// The text, `core` for Vulkan 1.0.
    pub fn text(&self) -> &str {
        &self.text
    }

    /// The parsed expression.
    pub fn expr(&self) -> &expr::Expr {
        &self.expr
    }

    /// Whether the item is in Vulkan 1.0.
    pub fn is_core(&self) -> bool {
        self.text == "core"
    }

    /// Whether every way this condition holds makes `other` hold too, where
    /// `closure` adds to a set of extensions what enabling them enables (the crate's
    /// feature dependencies) and versions count as present (the emitted crate has
    /// them all); false where either has a negation.
    pub fn implies(
        &self,
        other: &Condition,
        closure: &dyn Fn(&BTreeSet<String>) -> BTreeSet<String>,
    ) -> bool {
        let fixed = |n: &str| (n == "core" || n.starts_with("VK_VERSION_")).then_some(true);
        match (
            self.expr.minimal_sets(&fixed),
            other.expr.minimal_sets(&fixed),
        ) {
            (Some(mine), Some(theirs)) => mine.iter().all(|set| {
                let on = closure(set);
                theirs.iter().any(|t| t.is_subset(&on))
            }),
            _ => false,
        }
    }
}

/// The resolved registry.
#[derive(Debug, Clone)]
pub struct Model {
    /// Registry version, `1.3.239`.
    pub version: String,
    /// Every type by name (aliases included, as their own entries).
    pub types: BTreeMap<String, TypeDef>,
    /// Every command by name (aliases included).
    pub commands: BTreeMap<String, CommandDef>,
    /// Every handle type with its resolved relations.
    pub handles: BTreeMap<String, Handle>,
    /// For each struct, the structs that may extend its `pNext` chain.
    pub extended_by: BTreeMap<String, Vec<String>>,
    /// For each enum group, its values that the all-extensions build contains.
    pub enum_values: BTreeMap<String, Vec<String>>,
    /// The numeric value of each enum value name.
    pub enum_numbers: BTreeMap<String, i64>,
    /// What each `VkFormat` is made of, from the registry's `<formats>`.
    pub formats: Vec<Format>,
    /// For each enum value, the features and extensions that add it
    /// (`VK_VERSION_1_0` for the values written in the group itself).
    pub enum_origins: BTreeMap<String, Vec<String>>,
    /// For each type and command: the condition under which it exists, parsed once
    /// (`core` for Vulkan 1.0).
    pub conditions: BTreeMap<String, Condition>,
    /// Items that exist in the all-extensions build of the vulkan API.
    pub required: BTreeSet<String>,
    /// Items of the emitted API: their condition holds with the config's versions
    /// and extensions enabled.
    pub emitted: BTreeSet<String>,
    /// Names the config enables: versions up to the cap and the allowlisted extensions.
    pub enabled: BTreeSet<String>,
    /// For each extension, what it depends on (vk.xml's expression).
    pub extension_depends: BTreeMap<String, String>,
    /// The extensions promoted to a core version the config emits, with that
    /// version: where one is enabled, so is what the extension brings.
    pub promoted_to: BTreeMap<String, String>,
    /// The instance extensions (`type="instance"`); the others are device ones.
    pub instance_extensions: BTreeSet<String>,
    /// The registry's synchronization tables (`<sync>`): this registry's, or where it
    /// has none (before 1.3.2xx) the reference registry's, whose stages and access
    /// types are ash's.
    pub sync: Option<SyncTables>,
    /// The reference registry's version (the one the `ash` release the crate builds
    /// on was generated from), when the config names one.
    pub reference_version: Option<String>,
    /// The extensions the config wants that the reference lacks or defines
    /// otherwise, with the reason, in name order.
    pub left_out: Vec<reference::LeftOut>,
    /// The minor numbers of the enabled core versions ash has no function table for
    /// (the reference registry lacks them): the emitted crate defines and loads one
    /// for each (`DeviceFnV1_<minor>`).
    pub own_tables: BTreeSet<u32>,
    /// The enabled extensions the reference registry (so ash) lacks altogether: the
    /// emitted crate defines their function tables itself (`emit::delta`), and their
    /// types as the delta, or leaves an item out with the reason.
    pub own_extensions: BTreeSet<String>,
    /// The types of the emitted API that the reference registry (so ash) lacks and
    /// the emitted crate defines itself, in ash's style (`reference::missing_items`):
    /// structs and unions whose members are all of types ash has or of other such
    /// types, enums, bitmasks (a `FlagBits` enum is its bitmask's bits) and handles.
    pub delta: BTreeSet<String>,
    /// The commands of the extensions ash lacks altogether (`own_extensions`): the
    /// delta defines their `PFN_` types and the crate loads them into tables of its
    /// own.
    pub delta_commands: BTreeSet<String>,
    /// The structs whose `pNext` chain some struct of the reference registry extends:
    /// ash has an `Extends<Struct>` trait for each, and only for those.
    pub extended_in_reference: BTreeSet<String>,
    /// The values of enabled versions and extensions that the reference lacks by
    /// name, by enum group: the checks accept them (by number), and the delta names
    /// them as associated constants of one trait per type (`IndexTypeDelta::UINT8`).
    pub delta_values: BTreeMap<String, Vec<String>>,
    /// The API constants that size an array member of an emitted struct and that the
    /// reference lacks (`VK_MAX_PIPELINE_BINARY_KEY_SIZE_KHR`), with their values:
    /// the delta defines them as ash defines its own (`usize`).
    pub delta_sizes: BTreeMap<String, i64>,
    /// Structs this registry does not mark `returnedonly` and the reference
    /// registry does: Khronos found Vulkan only writes them, and dropped the value
    /// rules of their members.
    pub returned_only_in_reference: BTreeSet<String>,
    /// For each type and command, the alternatives (`VK_KHR_x`, `VK_KHR_x+dep`) of
    /// the require blocks that name it under this very name, aliases not merged.
    pub named_by: BTreeMap<String, BTreeSet<String>>,
    /// Items of the emitted API that no enabled require block names under their
    /// own name, with the alias one does: a newer registry names an item promoted
    /// to a core version the config does not emit by that version's name
    /// (`VkPhysicalDevicePushDescriptorProperties` of 1.4), while the emitted API
    /// (and ash) knows it by the extension's (`...PropertiesKHR`).
    pub spellings: BTreeMap<String, String>,
}

/// A handle type and what the registry says about its lifetime.
#[derive(Debug, Clone, Default, PartialEq, Eq, serde::Serialize)]
pub struct Handle {
    /// The handle's name.
    pub name: String,
    /// Dispatchable (`VK_DEFINE_HANDLE`) or not.
    pub dispatchable: bool,
    /// Parent types, nearest first, up to `VkInstance`.
    pub parent_chain: Vec<String>,
    /// Commands that create or allocate it.
    pub created_by: Vec<String>,
    /// Commands that destroy or free it.
    pub destroyed_by: Vec<String>,
}

impl Model {
    /// The name the emitted API knows an item by: its own, or the alias an enabled
    /// require block names it by (see [`Model::spellings`]).
    pub fn spelling<'a>(&'a self, name: &'a str) -> &'a str {
        self.spellings.get(name).map_or(name, String::as_str)
    }

    /// The name among `name` and its aliases that `interface`'s require blocks use.
    pub fn name_in<'a>(&'a self, name: &'a str, interface: &str) -> &'a str {
        let names_it = |n: &str| {
            self.named_by.get(n).is_some_and(|alts| {
                alts.iter()
                    .any(|a| a == interface || a.split('+').next() == Some(interface))
            })
        };
        if names_it(name) {
            return name;
        }
        self.commands
            .values()
            .filter(|c| c.alias.as_deref() == Some(name))
            .map(|c| c.name.as_str())
            .chain(
                self.types
                    .values()
                    .filter(|t| t.alias.as_deref() == Some(name))
                    .map(|t| t.name.as_str()),
            )
            .find(|n| names_it(n))
            .unwrap_or(name)
    }

    /// The version or extension an item belongs to, as vk.xml spells it: its core
    /// version (`VK_VERSION_1_0` for `core`), the oldest version that has it on its
    /// own for an item promoted to core (`VK_KHR_copy_commands2,VK_VERSION_1_3`),
    /// else the extension that first names it. The generated module of the item
    /// and the report's per-extension table both read it.
    pub fn home(&self, item: &str) -> String {
        let expr = self.condition(item).expr();
        let version = expr
            .alternatives()
            .iter()
            .filter_map(|alt| match alt {
                expr::Expr::Name(n) if n.starts_with("VK_VERSION_") => Some(n),
                _ => None,
            })
            .min();
        match version.map(String::as_str).or_else(|| expr.first_name()) {
            None | Some("core") => "VK_VERSION_1_0".to_owned(),
            Some(name) => name.to_owned(),
        }
    }

    /// A condition of validusage.json's key syntax, with each extension promoted to
    /// an emitted core version read as "the extension or that version": a rule
    /// filed under `VK_KHR_synchronization2` applies on a Vulkan 1.3 device that
    /// does not enable the extension, since 1.3 has what it brought.
    pub fn with_promotions(&self, key: &str) -> String {
        let mut out = String::with_capacity(key.len());
        let mut rest = key;
        while let Some(at) = rest.find("VK_") {
            out.push_str(&rest[..at]);
            let len = rest[at..]
                .find(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))
                .unwrap_or(rest.len() - at);
            let name = &rest[at..at + len];
            match self.promoted_to.get(name) {
                Some(version) => out.push_str(&format!("({name},{version})")),
                None => out.push_str(name),
            }
            rest = &rest[at + len..];
        }
        out.push_str(rest);
        out
    }

    /// Resolve `registry` and select the emitted API with `config`. Fails if the
    /// config names a version or an extension the registry lacks.
    pub fn build(
        registry: &Registry,
        reference: Option<&Registry>,
        config: &Config,
        config_path: &Path,
    ) -> Result<Model> {
        // A core version the reference lacks has no function table in ash: its
        // commands go through a table the emitted crate defines and loads by their
        // core names (`own_tables`); its items ash lacks altogether are left out one
        // by one (`reference::missing_items`), and the others are named as ash names
        // them (the extension aliases it has).
        let versions = config.enabled_versions();
        let own_tables: BTreeSet<u32> = versions
            .iter()
            .filter(|v| {
                reference.is_some_and(|r| !r.features.iter().any(|f| &f.name == *v))
                    && registry.features.iter().any(|f| &f.name == *v)
            })
            .filter_map(|v| v.strip_prefix("VK_VERSION_1_")?.parse().ok())
            .collect();
        let (extensions, left_out) = reference::select(
            registry,
            reference,
            &versions,
            &config.wanted_extensions(registry),
        );
        let types: BTreeMap<String, TypeDef> = registry
            .types
            .iter()
            .map(|t| (t.name.clone(), TypeDef::from(t)))
            .collect();
        let commands: BTreeMap<String, CommandDef> = registry
            .commands
            .iter()
            .map(|c| (c.name.clone(), CommandDef::from(c)))
            .collect();

        let mut enabled: BTreeSet<String> = BTreeSet::new();
        for version in config.enabled_versions() {
            if !registry.features.iter().any(|f| f.name == version) {
                let newest = registry
                    .features
                    .iter()
                    .filter_map(|f| f.number.as_deref())
                    .max_by_key(|n| {
                        n.split('.')
                            .map(|x| x.parse::<u32>().unwrap_or(0))
                            .collect::<Vec<_>>()
                    })
                    .unwrap_or("1.0");
                return Err(Error::Config {
                    path: config_path.to_owned(),
                    message: format!(
                        "api_version `{}` is newer than this registry (Vulkan {}), whose newest core version is {newest} (no {version} feature)",
                        config.api_version, registry.version
                    ),
                });
            }
            enabled.insert(version);
        }
        for ext in &extensions {
            match registry.extensions.iter().find(|e| &e.name == ext) {
                Some(e) if is_supported(e.supported.as_deref()) => {
                    enabled.insert(ext.clone());
                }
                Some(_) => {
                    return Err(Error::Config {
                        path: config_path.to_owned(),
                        message: format!(
                        "extension `{ext}` is not supported for the vulkan API in this registry"
                    ),
                    })
                }
                None => {
                    return Err(Error::Config {
                        path: config_path.to_owned(),
                        message: format!(
                            "extension `{ext}` does not exist in this registry (Vulkan {})",
                            registry.version
                        ),
                    })
                }
            }
        }
        // An enabled extension whose own dependencies are not enabled would be
        // unusable: say which one is missing.
        for ext in &extensions {
            let depends = registry
                .extensions
                .iter()
                .find(|e| &e.name == ext)
                .and_then(|e| e.depends.as_deref());
            if let Some(depends) = depends {
                if !expr::eval(depends, &enabled) {
                    return Err(Error::Config {
                        path: config_path.to_owned(),
                        message: format!(
                            "extension `{ext}` needs `{depends}`, which the config does not enable"
                        ),
                    });
                }
            }
        }

        // Alternatives under which each item is required, from feature and extension
        // require blocks.
        let mut alternatives: BTreeMap<String, BTreeSet<String>> = BTreeMap::new();
        let mut enum_additions: BTreeMap<String, Vec<String>> = BTreeMap::new();
        let mut enum_origins: BTreeMap<String, Vec<String>> = BTreeMap::new();
        let interfaces = registry.features.iter().chain(
            registry
                .extensions
                .iter()
                .filter(|e| is_supported(e.supported.as_deref())),
        );
        for iface in interfaces {
            for req in &iface.requires {
                let alt = match req.depends.as_deref() {
                    None => iface.name.clone(),
                    Some(dep) if dep.contains(',') => format!("{}+({dep})", iface.name),
                    Some(dep) => format!("{}+{dep}", iface.name),
                };
                for item in req.types.iter().chain(&req.commands) {
                    alternatives
                        .entry(item.clone())
                        .or_default()
                        .insert(alt.clone());
                }
                for (value, group) in &req.enum_extensions {
                    // A value two require blocks add is one value.
                    let added = enum_additions.entry(group.clone()).or_default();
                    if !added.contains(value) {
                        added.push(value.clone());
                    }
                    let origins = enum_origins.entry(value.clone()).or_default();
                    if !origins.contains(&iface.name) {
                        origins.push(iface.name.clone());
                    }
                }
            }
        }

        let named_by = alternatives.clone();
        // A promoted item exists wherever any of its aliases does (vkCmdDrawIndirectCount
        // also with VK_KHR_draw_indirect_count): the alias's blocks name the same item.
        let aliased: Vec<(String, String)> = types
            .values()
            .filter_map(|t| t.alias.clone().map(|a| (t.name.clone(), a)))
            .chain(
                commands
                    .values()
                    .filter_map(|c| c.alias.clone().map(|a| (c.name.clone(), a))),
            )
            .collect();
        let names_enabled = |name: &str| {
            named_by
                .get(name)
                .is_some_and(|alts| alts.iter().any(|a| expr::eval(a, &enabled)))
        };
        // What ash names, where a reference registry says: an item the reference
        // lacks under its own name but has under an alias is spelled by that alias
        // (an item of a core version ash has no table for, promoted from an
        // extension ash has; a type a newer extension ash lacks took over from one
        // ash has, `VkMemoryDecompressionMethodFlagsEXT` from `...NV`).
        // Of the reference's names, ash defines a command's `PFN_` type under the one
        // that is no alias there: that one is preferred.
        let in_reference = |name: &str, canonical: bool| {
            reference.is_some_and(|r| {
                r.types
                    .iter()
                    .any(|t| t.name == name && !(canonical && t.alias.is_some()))
                    || r.commands
                        .iter()
                        .any(|c| c.name == name && !(canonical && c.alias.is_some()))
            })
        };
        let mut spellings: BTreeMap<String, String> = BTreeMap::new();
        for canonical in [true, false] {
            for (alias, target) in &aliased {
                let by_interface = !canonical && !names_enabled(target) && names_enabled(alias);
                let by_reference = !in_reference(target, false)
                    && in_reference(alias, canonical)
                    && names_enabled(target);
                if (by_interface || by_reference) && !spellings.contains_key(target) {
                    spellings.insert(target.clone(), alias.clone());
                }
            }
        }
        for (alias, target) in aliased {
            if let Some(alts) = alternatives.get(&alias).cloned() {
                alternatives.entry(target).or_default().extend(alts);
            }
        }

        // Everything a required item refers to is required too. An item that no
        // require block names exists under the union of its users' conditions.
        let own = alternatives.clone();
        let mut required: BTreeSet<String> = own.keys().cloned().collect();
        let mut queue: Vec<String> = required.iter().cloned().collect();
        let mut users: BTreeMap<String, BTreeSet<String>> = BTreeMap::new();
        while let Some(item) = queue.pop() {
            for dep in references(&item, &types, &commands) {
                if !types.contains_key(&dep) && !commands.contains_key(&dep) {
                    continue;
                }
                users.entry(dep.clone()).or_default().insert(item.clone());
                if required.insert(dep.clone()) {
                    queue.push(dep);
                }
            }
        }
        let mut changed = true;
        while changed {
            changed = false;
            for item in &required {
                if own.contains_key(item) {
                    continue;
                }
                let inherited: BTreeSet<String> = users
                    .get(item)
                    .into_iter()
                    .flatten()
                    .filter_map(|u| alternatives.get(u))
                    .flatten()
                    .cloned()
                    .collect();
                if alternatives.get(item) != Some(&inherited) {
                    alternatives.insert(item.clone(), inherited);
                    changed = true;
                }
            }
        }

        let mut conditions: BTreeMap<String, Condition> = BTreeMap::new();
        for (item, alts) in &alternatives {
            let text = condition_of(alts);
            let condition = Condition::parse(&text).map_err(|message| Error::BadCondition {
                item: item.clone(),
                condition: text.clone(),
                message,
            })?;
            conditions.insert(item.clone(), condition);
        }
        let emitted = conditions
            .iter()
            .filter(|(_, c)| c.expr().eval(&enabled))
            .map(|(item, _)| item.clone())
            .collect();

        let mut enum_values: BTreeMap<String, Vec<String>> = BTreeMap::new();
        for group in &registry.enum_groups {
            let mut values = if required.contains(&group.name) {
                group.values.clone()
            } else {
                Vec::new()
            };
            for v in &values {
                enum_origins
                    .entry(v.clone())
                    .or_default()
                    .insert(0, "VK_VERSION_1_0".to_owned());
            }
            values.extend(enum_additions.remove(&group.name).unwrap_or_default());
            enum_values.insert(group.name.clone(), values);
        }

        let mut extended_by: BTreeMap<String, Vec<String>> = BTreeMap::new();
        for t in types.values() {
            for head in &t.struct_extends {
                extended_by
                    .entry(head.clone())
                    .or_default()
                    .push(t.name.clone());
            }
        }

        let handles = resolve_handles(&types, &commands);
        let promoted_to = registry
            .extensions
            .iter()
            .filter_map(|e| {
                let to = e.promoted_to.as_ref()?;
                enabled.contains(to).then(|| (e.name.clone(), to.clone()))
            })
            .collect();
        let mut model = Model {
            sync: registry
                .sync
                .clone()
                .or_else(|| reference.and_then(|r| r.sync.clone())),
            reference_version: reference.map(|r| r.version.clone()),
            left_out,
            own_tables,
            own_extensions: reference
                .map(|r| {
                    enabled
                        .iter()
                        .filter(|e| {
                            !e.starts_with("VK_VERSION_")
                                && !r
                                    .extensions
                                    .iter()
                                    .any(|x| &x.name == *e && is_supported(x.supported.as_deref()))
                        })
                        .cloned()
                        .collect()
                })
                .unwrap_or_default(),
            delta: BTreeSet::new(),
            delta_commands: BTreeSet::new(),
            delta_values: BTreeMap::new(),
            delta_sizes: BTreeMap::new(),
            extended_in_reference: reference
                .map(|r| {
                    // Only the structs ash has: those a Vulkan version or a supported
                    // extension requires (Vulkan SC's, such as
                    // `VkCommandPoolMemoryReservationCreateInfo`, are not ash's).
                    let required: BTreeSet<&str> = r
                        .features
                        .iter()
                        .chain(
                            r.extensions
                                .iter()
                                .filter(|e| is_supported(e.supported.as_deref())),
                        )
                        .flat_map(|i| &i.requires)
                        .flat_map(|q| &q.types)
                        .map(String::as_str)
                        .collect();
                    r.types
                        .iter()
                        .filter(|t| required.contains(t.name.as_str()))
                        .flat_map(|t| t.struct_extends.iter().cloned())
                        .collect()
                })
                .unwrap_or_default(),
            returned_only_in_reference: reference
                .map(|r| {
                    r.types
                        .iter()
                        .filter(|t| {
                            t.returned_only
                                && types.get(&t.name).is_some_and(|here| {
                                    here.category == Some(Kind::Struct) && !here.returned_only
                                })
                        })
                        .map(|t| t.name.clone())
                        .collect()
                })
                .unwrap_or_default(),
            named_by,
            spellings,
            version: registry.version.clone(),
            types,
            commands,
            handles,
            extended_by,
            enum_values,
            enum_numbers: registry.enum_numbers.clone(),
            formats: registry
                .formats
                .iter()
                .map(|f| Format {
                    name: f.name.clone(),
                    block_size: f.block_size,
                    block_extent: f.block_extent,
                    components: f.components.clone(),
                    planes: f.planes,
                    plane_formats: f.plane_formats.clone(),
                    bits: f.bits.clone(),
                    numeric: f.numeric.clone(),
                    class: f.class.clone(),
                    chroma: f.chroma.clone(),
                })
                .collect(),
            enum_origins,
            conditions,
            required,
            emitted,
            enabled,
            extension_depends: registry
                .extensions
                .iter()
                .filter_map(|e| Some((e.name.clone(), e.depends.clone()?)))
                .collect(),
            promoted_to,
            instance_extensions: registry
                .extensions
                .iter()
                .filter(|e| e.ext_type.as_deref() == Some("instance"))
                .map(|e| e.name.clone())
                .collect(),
        };
        if let Some(reference) = reference {
            let reference::Missing {
                left_out: missing,
                delta,
                commands,
            } = reference::missing_items(&model, reference);
            model.delta = delta;
            model.delta_commands = commands;
            for m in &missing {
                model.emitted.remove(&m.name);
            }
            // A value ash lacks cannot be named by ash's name in the emitted code: it
            // goes to the delta, which names it, and the checks take it by number.
            for (group, values) in model.enum_values.iter_mut() {
                let (kept, gone): (Vec<String>, Vec<String>) = values
                    .drain(..)
                    .partition(|v| reference.enum_numbers.contains_key(v));
                *values = kept;
                // Only what an enabled version or extension adds (a value of an
                // extension left out is no value of this crate).
                let enabled = &model.enabled;
                let gone: Vec<String> = gone
                    .into_iter()
                    .filter(|v| {
                        model
                            .enum_origins
                            .get(v)
                            .is_some_and(|o| o.iter().any(|x| enabled.contains(x)))
                    })
                    .collect();
                if !gone.is_empty() {
                    model.delta_values.insert(group.clone(), gone);
                }
            }
            model.left_out.extend(missing);
            let sizes: BTreeMap<String, i64> = model
                .types
                .values()
                .filter(|t| model.emitted.contains(&t.name))
                .flat_map(|t| &t.members)
                .filter_map(|m| m.static_array.as_deref())
                .filter(|n| n.starts_with("VK_") && !reference.enum_numbers.contains_key(*n))
                .filter_map(|n| Some((n.to_owned(), *model.enum_numbers.get(n)?)))
                .collect();
            model.delta_sizes = sizes;
        }
        Ok(model)
    }

    /// The enum values the crate defines itself (`delta_values`) that it can name:
    /// those of emitted types that have a number, as (type, value, number).
    pub fn delta_constants(&self) -> impl Iterator<Item = (&str, &str, i64)> {
        self.delta_values
            .iter()
            .filter(|(group, _)| self.is_emitted(group))
            .flat_map(|(group, values)| values.iter().map(move |v| (group.as_str(), v.as_str())))
            .filter_map(|(group, v)| Some((group, v, *self.enum_numbers.get(v)?)))
    }

    /// The bitmask whose bits are the `FlagBits` enum `bits` (its `requires` or
    /// `bitvalues`), if the registry has one.
    pub fn bitmask_of(&self, bits: &str) -> Option<&TypeDef> {
        self.types
            .values()
            .find(|t| t.category == Some(Kind::Bitmask) && t.bit_values.as_deref() == Some(bits))
    }

    /// The flags types the delta defines (ash has one type for a bitmask and its
    /// bits): each delta bitmask, and each delta `FlagBits` enum that no delta
    /// bitmask names as its bits, in name order.
    pub fn delta_flags(&self) -> Vec<DeltaFlags> {
        let mut out: Vec<DeltaFlags> = Vec::new();
        for name in &self.delta {
            let t = &self.types[name];
            match t.category {
                Some(Kind::Bitmask) => out.push(DeltaFlags {
                    c_name: name.clone(),
                    bits: t.bit_values.clone().filter(|b| self.is_emitted(b)),
                    wide: t.code.contains("VkFlags64"),
                }),
                Some(Kind::Enum) if name.contains("FlagBits") => {
                    let bitmask = self.bitmask_of(name);
                    if bitmask.is_some_and(|b| self.delta.contains(&b.name)) {
                        continue;
                    }
                    out.push(DeltaFlags {
                        c_name: bitmask.map_or(name.clone(), |b| b.name.clone()),
                        bits: Some(name.clone()),
                        wide: bitmask.is_some_and(|b| b.code.contains("VkFlags64")),
                    });
                }
                _ => {}
            }
        }
        out.sort_by(|a, b| a.c_name.cmp(&b.c_name));
        out
    }

    /// The handle a command's method is called on: its dispatchable first
    /// parameter's type, or the display a physical-device command acts on; `None`
    /// for a global command such as `vkCreateInstance`.
    pub fn receiver(&self, command: &str) -> Option<&str> {
        let params = &self.commands.get(command)?.params;
        let first = params.first()?;
        let def = self.types.get(&first.type_name)?;
        if !(def.category == Some(Kind::Handle) && def.dispatchable) {
            return None;
        }
        // A command of a physical device that acts on one of its displays is the
        // display's: the method passes the display's own parent, so the two cannot
        // disagree.
        let child = params.iter().skip(1).find(|p| {
            p.pointers == 0
                && !p.is_optional()
                && self
                    .handles
                    .get(&p.type_name)
                    .is_some_and(|h| h.parent_chain.first() == Some(&first.type_name))
                && first.type_name == "VkPhysicalDevice"
        });
        Some(child.map_or(first.type_name.as_str(), |p| p.type_name.as_str()))
    }

    /// The category of a type, following no aliases (as the specification's
    /// toolchain does).
    pub fn category(&self, type_name: &str) -> Option<Kind> {
        self.types.get(type_name)?.category
    }

    /// The condition of an item, `core` for items outside the registry's features
    /// and extensions (such as SPIR-V built-ins that validusage.json files as
    /// entities of their own).
    pub fn condition(&self, item: &str) -> &Condition {
        static CORE: std::sync::LazyLock<Condition> = std::sync::LazyLock::new(|| Condition {
            text: "core".to_owned(),
            expr: expr::Expr::Name("core".to_owned()),
        });
        self.conditions.get(item).unwrap_or(&CORE)
    }

    /// Whether an emitted struct that extends `name` needs more than Vulkan 1.0: a
    /// chain of `name` may then hold a node of a version or extension not enabled.
    pub fn has_gated_extenders(&self, name: &str) -> bool {
        self.extended_by.get(name).is_some_and(|e| {
            e.iter()
                .any(|x| self.emitted.contains(x) && !self.condition(x).is_core())
        })
    }

    /// Whether an item is in the emitted API. Entities that are not registry items
    /// (SPIR-V environment rules) apply to every API that accepts shaders.
    pub fn is_emitted(&self, item: &str) -> bool {
        if self.types.contains_key(item) || self.commands.contains_key(item) {
            self.emitted.contains(item)
        } else {
            true
        }
    }
}

/// Whether an extension's `supported` attribute lists the vulkan API.
pub fn is_supported(supported: Option<&str>) -> bool {
    supported.is_some_and(|s| s.split(',').any(|x| x == "vulkan"))
}

/// `core` when Vulkan 1.0 requires the item unconditionally, else the alternatives
/// joined with `,`.
fn condition_of(alts: &BTreeSet<String>) -> String {
    if alts.contains("VK_VERSION_1_0") {
        return "core".to_owned();
    }
    let parts: Vec<String> = alts
        .iter()
        .map(|a| {
            if a.contains(',') && !a.starts_with('(') {
                format!("({a})")
            } else {
                a.clone()
            }
        })
        .collect();
    parts.join(",")
}

/// The types and commands an item's definition names.
fn references(
    item: &str,
    types: &BTreeMap<String, TypeDef>,
    commands: &BTreeMap<String, CommandDef>,
) -> Vec<String> {
    let mut out = Vec::new();
    if let Some(t) = types.get(item) {
        out.extend(t.alias.clone());
        out.extend(t.bit_values.clone());
        out.extend(t.members.iter().map(|m| m.type_name.clone()));
        if let Some(parent) = &t.parent {
            out.extend(parent.split(',').map(str::to_owned));
        }
    }
    if let Some(c) = commands.get(item) {
        out.extend(c.alias.clone());
        if !c.return_type.is_empty() {
            out.push(c.return_type.clone());
        }
        out.extend(c.params.iter().map(|p| p.type_name.clone()));
    }
    out
}

fn resolve_handles(
    types: &BTreeMap<String, TypeDef>,
    commands: &BTreeMap<String, CommandDef>,
) -> BTreeMap<String, Handle> {
    let mut handles = BTreeMap::new();
    for t in types.values() {
        if t.category != Some(Kind::Handle) || t.alias.is_some() {
            continue;
        }
        let mut chain = Vec::new();
        let mut current = t.parent.clone();
        while let Some(p) = current {
            // A handle may name several possible parents; the chain follows the first.
            let first = p.split(',').next().unwrap_or_default().to_owned();
            if chain.contains(&first) {
                break;
            }
            current = types.get(&first).and_then(|pt| pt.parent.clone());
            chain.push(first);
        }
        let mut handle = Handle {
            name: t.name.clone(),
            dispatchable: t.dispatchable,
            parent_chain: chain,
            ..Handle::default()
        };
        for c in commands.values().filter(|c| c.alias.is_none()) {
            let is_create = c.name.starts_with("vkCreate") || c.name.starts_with("vkAllocate");
            let is_destroy = c.name.starts_with("vkDestroy") || c.name.starts_with("vkFree");
            if is_create {
                if let Some(last) = c.params.last() {
                    if last.type_name == t.name && last.pointers == 1 && !last.is_const {
                        handle.created_by.push(c.name.clone());
                    }
                }
            } else if is_destroy {
                let last_handle = c.params.iter().rev().find(|p| {
                    types.get(&p.type_name).and_then(|x| x.category) == Some(Kind::Handle)
                });
                if last_handle.is_some_and(|p| p.type_name == t.name) {
                    handle.destroyed_by.push(c.name.clone());
                }
            }
        }
        handles.insert(t.name.clone(), handle);
    }
    handles
}

/// What a `VkFormat` is made of.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Format {
    /// `VK_FORMAT_...`.
    pub name: String,
    /// Bytes per texel block.
    pub block_size: u8,
    /// Texel block width, height and depth.
    pub block_extent: [u32; 3],
    /// The components' names in order (`R`, `G`, `B`, `A`, `D`, `S`).
    pub components: Vec<String>,
    /// How many planes (0 for a format that is not multi-planar).
    pub planes: u8,
    /// Each plane's compatible single-plane format, in plane order.
    pub plane_formats: Vec<String>,
    /// Each component's bit width as written (`8`, `24`, `compressed`), in order.
    pub bits: Vec<String>,
    /// Each component's `numericFormat` (`UNORM`, `UINT`, `SFLOAT`, ...), in order.
    pub numeric: Vec<String>,
    /// `class`: formats of one class are compatible (views, copies).
    pub class: String,
    /// `chroma` (`420`, `422`, `444`): the format needs a sampler Y'CbCr conversion.
    pub chroma: Option<String>,
}

impl Format {
    /// The bytes a texel of one aspect takes in a buffer, as copies between buffers
    /// and images lay it out: the block size for color, 4 for a depth of 24 or 32
    /// bits and 2 for 16, 1 for stencil.
    pub fn aspect_bytes(&self, component: &str) -> Option<u32> {
        let i = self.components.iter().position(|c| c == component)?;
        match (component, self.bits.get(i)?.as_str()) {
            ("S", _) => Some(1),
            ("D", "16") => Some(2),
            ("D", "24" | "32") => Some(4),
            _ => None,
        }
    }

    /// Has a depth component.
    pub fn depth(&self) -> bool {
        self.components.iter().any(|c| c == "D")
    }

    /// Has a stencil component.
    pub fn stencil(&self) -> bool {
        self.components.iter().any(|c| c == "S")
    }

    /// A color format: neither depth nor stencil.
    pub fn color(&self) -> bool {
        !self.depth() && !self.stencil()
    }
}

/// A flags type the delta defines: ash's one type for a bitmask and its bits.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct DeltaFlags {
    /// The C name the type is laid out as: the bitmask's, or the bits' where the
    /// registry has no bitmask for them.
    pub c_name: String,
    /// The `FlagBits` enum whose values are its constants, if any is emitted.
    pub bits: Option<String>,
    /// `VkFlags64` rather than `VkFlags`.
    pub wide: bool,
}
