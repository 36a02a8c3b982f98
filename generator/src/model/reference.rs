//! What the `ash` release the generated crate builds on defines.
//! `ash` is generated from one registry (0.38 from 1.3.281's); every item the emitted
//! code names must exist there with the same shape. Given that registry (the
//! config's `reference_registry`), this pass keeps each wanted extension whose items
//! the reference defines alike or lacks (the delta, `missing_items`), and leaves out,
//! with the reason, each one it defines otherwise (a member renamed, a command's
//! parameters changed), and each one that depends on an extension left out. Core items are not compared
//! here: a registry newer than the reference is the version-bump work's.

use super::expr;
use crate::registry::{Field, Interface, Registry};
use std::collections::{BTreeMap, BTreeSet};

/// An extension left out of the emitted API, and why.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct LeftOut {
    /// `VK_KHR_video_encode_queue`.
    pub name: String,
    /// What the reference lacks or defines otherwise.
    pub reason: String,
}

/// What the reference defines, by name.
struct Defined<'a> {
    types: BTreeMap<&'a str, &'a crate::registry::TypeDef>,
    commands: BTreeMap<&'a str, &'a crate::registry::CommandDef>,
}

impl<'a> Defined<'a> {
    fn of(reference: &'a Registry) -> Defined<'a> {
        Defined {
            types: reference
                .types
                .iter()
                .map(|t| (t.name.as_str(), t))
                .collect(),
            commands: reference
                .commands
                .iter()
                .map(|c| (c.name.as_str(), c))
                .collect(),
        }
    }
}

/// Type names that one of the two registries makes another name of the same type,
/// each mapped to one representative: a newer registry renames an item promoted to
/// core (`VkLineRasterizationModeKHR` becomes an alias of `VkLineRasterizationMode`),
/// and ash defines every name of the reference's class as one type.
struct Classes<'a> {
    representative: BTreeMap<&'a str, &'a str>,
    /// Constants by number (`VK_MAX_GLOBAL_PRIORITY_SIZE_KHR` became
    /// `VK_MAX_GLOBAL_PRIORITY_SIZE`), so array sizes compare by value.
    numbers: BTreeMap<&'a str, i64>,
}

impl<'a> Classes<'a> {
    fn of(registries: &[&'a Registry]) -> Classes<'a> {
        let mut parent: BTreeMap<&'a str, &'a str> = BTreeMap::new();
        fn find<'a>(parent: &BTreeMap<&'a str, &'a str>, mut x: &'a str) -> &'a str {
            while let Some(&p) = parent.get(x) {
                if p == x {
                    break;
                }
                x = p;
            }
            x
        }
        for r in registries {
            for t in &r.types {
                if let Some(target) = t.alias.as_deref() {
                    let (a, b) = (find(&parent, &t.name), find(&parent, target));
                    if a != b {
                        // The smaller name represents the class, so that the
                        // result does not depend on the order of the registries.
                        let (small, large) = if a < b { (a, b) } else { (b, a) };
                        parent.insert(large, small);
                    }
                }
            }
        }
        let representative = parent
            .keys()
            .map(|&name| (name, find(&parent, name)))
            .collect();
        let numbers = registries
            .iter()
            .flat_map(|r| r.enum_numbers.iter().map(|(k, v)| (k.as_str(), *v)))
            .collect();
        Classes {
            representative,
            numbers,
        }
    }

    fn array(&self, size: Option<&'a str>) -> Option<String> {
        size.map(|s| match self.numbers.get(s) {
            Some(n) => n.to_string(),
            None => s.to_owned(),
        })
    }

    fn of_name(&self, name: &'a str) -> &'a str {
        self.representative.get(name).copied().unwrap_or(name)
    }
}

/// The parts of a member or parameter the generated code depends on, its type named
/// by its class's representative.
type Shape<'a> = (&'a str, &'a str, usize, Option<String>);

fn shape<'a>(f: &'a Field, classes: &Classes<'a>) -> Shape<'a> {
    (
        f.name.as_str(),
        classes.of_name(f.type_name.as_str()),
        f.pointers,
        classes.array(f.static_array.as_deref()),
    )
}

fn fields<'a>(list: &'a [Field], classes: &Classes<'a>) -> Vec<Shape<'a>> {
    list.iter().map(|f| shape(f, classes)).collect()
}

/// A command's parameters as its function pointer types them: names do not matter
/// (a newer registry renames `pLocationInfo`), types and pointer levels do.
fn signature<'a>(list: &'a [Field], classes: &Classes<'a>) -> Vec<Shape<'a>> {
    list.iter()
        .map(|f| {
            let (_, ty, pointers, array) = shape(f, classes);
            ("", ty, pointers, array)
        })
        .collect()
}

/// The type an alias names (through at most a few aliases), or `t` itself.
fn resolve<'a>(
    types: &BTreeMap<&str, &'a crate::registry::TypeDef>,
    mut t: &'a crate::registry::TypeDef,
) -> &'a crate::registry::TypeDef {
    for _ in 0..4 {
        match t.alias.as_deref().and_then(|a| types.get(a)) {
            Some(target) => t = target,
            None => break,
        }
    }
    t
}

/// The first item of `interface` that `defined` lacks or defines otherwise. A require
/// block whose own condition cannot hold with `possible` enabled (it adds to an
/// extension the reference lacks) is skipped: none of its items is emitted.
fn differs<'a>(
    pinned: &'a Registry,
    defined: &Defined<'a>,
    classes: &Classes<'a>,
    possible: &BTreeSet<String>,
    interface: &'a Interface,
) -> Option<String> {
    let types: BTreeMap<&str, &crate::registry::TypeDef> =
        pinned.types.iter().map(|t| (t.name.as_str(), t)).collect();
    let commands: BTreeMap<&str, &crate::registry::CommandDef> = pinned
        .commands
        .iter()
        .map(|c| (c.name.as_str(), c))
        .collect();
    for require in &interface.requires {
        if let Some(depends) = require.depends.as_deref() {
            if !expr::eval(depends, possible) {
                continue;
            }
        }
        // An item the reference lacks altogether (a newer registry adds it to the
        // extension) is left out on its own by `missing_items`; the extension stays.
        for name in &require.types {
            let Some(theirs) = defined.types.get(name.as_str()) else {
                continue;
            };
            let Some(ours) = types.get(name.as_str()) else {
                continue;
            };
            // An alias names its target's members (ash defines it as a type alias).
            let (ours, theirs) = (resolve(&types, ours), resolve(&defined.types, theirs));
            let (a, b) = (
                fields(&ours.members, classes),
                fields(&theirs.members, classes),
            );
            if a != b {
                let at = a
                    .iter()
                    .zip(&b)
                    .position(|(x, y)| x != y)
                    .unwrap_or(a.len().min(b.len()));
                let show = |f: Option<&Shape<'_>>| match f {
                    Some((name, ty, pointers, array)) => format!(
                        "`{ty}{} {name}{}`",
                        "*".repeat(*pointers),
                        array.as_ref().map(|n| format!("[{n}]")).unwrap_or_default()
                    ),
                    None => "nothing".to_owned(),
                };
                return Some(format!(
                    "the reference defines `{name}` otherwise: member {at} is {} there, {} here",
                    show(b.get(at)),
                    show(a.get(at))
                ));
            }
        }
        for name in &require.commands {
            let Some(theirs) = defined.commands.get(name.as_str()) else {
                continue;
            };
            let Some(ours) = commands.get(name.as_str()) else {
                continue;
            };
            let theirs = match theirs
                .alias
                .as_deref()
                .and_then(|a| defined.commands.get(a))
            {
                Some(target) => target,
                None => theirs,
            };
            let ours = match ours.alias.as_deref().and_then(|a| commands.get(a)) {
                Some(target) => target,
                None => ours,
            };
            if signature(&ours.params, classes) != signature(&theirs.params, classes) {
                return Some(format!("the reference gives `{name}` other parameters"));
            }
        }
    }
    None
}

/// The extensions of `wanted` to emit, and those left out with the reason, checked
/// against `reference`, with the core versions `versions` enabled. Without a
/// reference every wanted extension is kept.
pub fn select(
    pinned: &Registry,
    reference: Option<&Registry>,
    versions: &[String],
    wanted: &[String],
) -> (Vec<String>, Vec<LeftOut>) {
    let Some(reference) = reference else {
        return (wanted.to_vec(), Vec::new());
    };
    let defined = Defined::of(reference);
    let classes = Classes::of(&[pinned, reference]);
    // What can be enabled at most: the versions and every wanted extension.
    let possible: BTreeSet<String> = versions.iter().chain(wanted).cloned().collect();
    let mut left: Vec<LeftOut> = Vec::new();
    for name in wanted {
        // An extension the reference lacks altogether stays: its items are ash's
        // where ash has them, and the others are the delta or left out one by one
        // (`missing_items`), as a newer registry's additions to an extension ash has.
        let reason = pinned
            .extensions
            .iter()
            .find(|e| &e.name == name)
            .and_then(|e| differs(pinned, &defined, &classes, &possible, e));
        if let Some(reason) = reason {
            left.push(LeftOut {
                name: name.clone(),
                reason,
            });
        }
    }
    // An extension whose dependencies need one left out goes too, until none does.
    loop {
        let kept: BTreeSet<String> = versions
            .iter()
            .cloned()
            .chain(
                wanted
                    .iter()
                    .filter(|w| !left.iter().any(|l| &l.name == *w))
                    .cloned(),
            )
            .collect();
        let unmet: Vec<LeftOut> = wanted
            .iter()
            .filter(|w| kept.contains(*w))
            .filter_map(|w| {
                let e = pinned.extensions.iter().find(|e| &e.name == w)?;
                let depends = e.depends.as_deref()?;
                // A dependency the config never asked for is the model's error to
                // report, not a reason to leave the extension out.
                let asked: BTreeSet<String> = versions.iter().chain(wanted).cloned().collect();
                (!expr::eval(depends, &kept) && expr::eval(depends, &asked)).then(|| LeftOut {
                    name: w.clone(),
                    reason: format!("it depends on `{depends}`, which the emitted API lacks"),
                })
            })
            .collect();
        if unmet.is_empty() {
            break;
        }
        left.extend(unmet);
    }
    let kept = wanted
        .iter()
        .filter(|w| !left.iter().any(|l| &l.name == *w))
        .cloned()
        .collect();
    left.sort_by(|a, b| a.name.cmp(&b.name));
    (kept, left)
}

/// The items of the emitted API that ash lacks although it has their extension: a
/// registry newer than the reference adds a type, a command or a value to an
/// extension, or moves a command to another extension's require block (ash keeps
/// a command in the function table of the extension that names it in the
/// reference). Each is left out on its own, and so is every item that names one
/// (a struct with such a member, a command with such a parameter, an alias).
///
/// A struct the reference lacks whose members ash can spell (or that are such
/// structs themselves) is not left out: it is returned as the delta, which the
/// emitted crate defines itself (`emit::delta`); so are the unions, enums, bitmasks
/// and handles the reference lacks, and the commands of the extensions it lacks
/// altogether (`Model::own_extensions`), which the crate calls through function
/// tables of its own.
pub fn missing_items(model: &super::Model, reference: &Registry) -> Missing {
    let defined = Defined::of(reference);
    let mut homes: BTreeMap<&str, BTreeSet<&str>> = BTreeMap::new();
    for iface in reference.features.iter().chain(&reference.extensions) {
        for require in &iface.requires {
            for c in &require.commands {
                homes
                    .entry(c.as_str())
                    .or_default()
                    .insert(iface.name.as_str());
            }
        }
    }
    let mut out: BTreeMap<String, String> = BTreeMap::new();
    let mut delta: BTreeSet<String> = BTreeSet::new();
    let mut commands: BTreeSet<String> = BTreeSet::new();
    for name in &model.emitted {
        let spelled = model.spelling(name);
        if let Some(t) = model.types.get(name) {
            // ash spells bits as their bitmask (`AccessFlags` for
            // `VkAccessFlagBits`): bits the reference lacks whose bitmask it has are
            // ash's type, their values the delta's (`delta_values`).
            let bits_of_ash = || {
                t.category == Some(super::Kind::Enum)
                    && model
                        .bitmask_of(name)
                        .is_some_and(|b| defined.types.contains_key(model.spelling(&b.name)))
            };
            // The delta defines the version constants of the versions ash lacks.
            let own_version = name
                .strip_prefix("VK_API_VERSION_1_")
                .and_then(|m| m.parse::<u32>().ok())
                .is_some_and(|m| model.own_tables.contains(&m));
            if own_version {
                continue;
            }
            if t.alias.is_none() && !defined.types.contains_key(spelled) && !bits_of_ash() {
                use super::Kind;
                if t.category == Some(Kind::Handle) && t.dispatchable {
                    // Commands dispatch through the tables of ash's five dispatchable
                    // handles; a sixth has none.
                    out.insert(
                        name.clone(),
                        format!(
                            "the reference registry (Vulkan {}) has no type `{spelled}`, and a new dispatchable handle has no function table the crate could call through",
                            reference.version
                        ),
                    );
                    continue;
                }
                if let Some(
                    Kind::Struct | Kind::Union | Kind::Enum | Kind::Bitmask | Kind::Handle,
                ) = t.category
                {
                    delta.insert(name.clone());
                    continue;
                }
                out.insert(
                    name.clone(),
                    format!(
                        "the reference registry (Vulkan {}) has no type `{spelled}`",
                        reference.version
                    ),
                );
            }
        } else if let Some(c) = model.commands.get(name) {
            if c.alias.is_some() {
                continue;
            }
            let device_level = c.params.first().is_some_and(|p| {
                matches!(
                    p.type_name.as_str(),
                    "VkDevice" | "VkQueue" | "VkCommandBuffer"
                )
            });
            let own = match super::tables::table(model, name) {
                Some(super::tables::Table::Extension(e)) => model.own_extensions.contains(&e),
                _ => false,
            };
            if own {
                commands.insert(name.clone());
            } else if !defined.commands.contains_key(spelled) {
                out.insert(
                    name.clone(),
                    format!(
                        "the reference registry (Vulkan {}) has no command `{spelled}`",
                        reference.version
                    ),
                );
            } else if let (Some(super::tables::Table::Own(m)), false) =
                (super::tables::table(model, name), device_level)
            {
                // The crate's own tables of a version ash lacks are device-level.
                out.insert(
                    name.clone(),
                    format!(
                        "ash has no function table for `VK_VERSION_1_{m}`, and the emitted crate loads only its device-level commands"
                    ),
                );
            } else if let Some(super::tables::Table::Extension(e)) =
                super::tables::table(model, name)
            {
                let field = model.name_in(name, &e);
                let named = [name.as_str(), spelled, field]
                    .iter()
                    .any(|n| homes.get(n).is_some_and(|h| h.contains(e.as_str())));
                if !named {
                    let there: Vec<&str> =
                        homes.get(spelled).into_iter().flatten().copied().collect();
                    out.insert(
                        name.clone(),
                        format!(
                            "ash keeps `{spelled}` in the function table of `{}`, not of `{e}`",
                            there.join("`, `")
                        ),
                    );
                }
            }
        }
    }
    // A delta struct or union whose member ash cannot spell goes: a bit field, a
    // member of a type ash lacks that is no delta type, or no type at all.
    loop {
        let gone: Vec<(String, String)> = delta
            .iter()
            .filter_map(|name| {
                let t = &model.types[name];
                t.members.iter().find_map(|m| {
                    let why = if m.bitfield.is_some() {
                        format!("its member `{}` is a bit field", m.name)
                    } else if !spellable(model, &defined, &delta, &out, &m.type_name) {
                        format!(
                            "the reference registry (Vulkan {}) has no type `{}`, which its member `{}` is",
                            reference.version, m.type_name, m.name
                        )
                    } else {
                        return None;
                    };
                    Some((name.clone(), why))
                })
            })
            .collect();
        if gone.is_empty() {
            break;
        }
        for (name, why) in gone {
            delta.remove(&name);
            out.insert(name, why);
        }
    }
    // Whatever names a missing item goes too, until nothing more does.
    loop {
        let more: Vec<(String, String)> = model
            .emitted
            .iter()
            .filter(|n| !out.contains_key(*n))
            .filter_map(|n| {
                // The same walk as the model's requirement closure: aliases, member,
                // parameter and result types, bit values, parents.
                let named = super::references(n, &model.types, &model.commands);
                let gone = named.into_iter().find(|x| out.contains_key(x))?;
                Some((n.clone(), format!("it names `{gone}`, which is left out")))
            })
            .collect();
        if more.is_empty() {
            break;
        }
        out.extend(more);
    }
    // A delta item that names something left out goes too.
    delta.retain(|d| !out.contains_key(d));
    commands.retain(|c| !out.contains_key(c));
    let left = out
        .into_iter()
        .map(|(name, reason)| LeftOut { name, reason })
        .collect();
    Missing {
        left_out: left,
        delta,
        commands,
    }
}

/// What [`missing_items`] found.
#[derive(Debug)]
pub struct Missing {
    /// The items left out, each with the reason.
    pub left_out: Vec<LeftOut>,
    /// The types the emitted crate defines itself (`Model::delta`).
    pub delta: BTreeSet<String>,
    /// The commands of extensions ash lacks, called through the crate's own tables
    /// (`Model::delta_commands`).
    pub commands: BTreeSet<String>,
}

/// Whether a member of type `name` has a spelling in the emitted crate: a C scalar,
/// a type ash has (under the reference's name for it), or a delta type.
fn spellable(
    model: &super::Model,
    defined: &Defined<'_>,
    delta: &BTreeSet<String>,
    out: &BTreeMap<String, String>,
    name: &str,
) -> bool {
    const SCALARS: [&str; 15] = [
        "void", "char", "float", "double", "uint8_t", "uint16_t", "uint32_t", "uint64_t", "int8_t",
        "int16_t", "int32_t", "int64_t", "size_t", "int", "VkBool32",
    ];
    if SCALARS.contains(&name) {
        return true;
    }
    if out.contains_key(name) {
        return false;
    }
    delta.contains(name) || defined.types.contains_key(model.spelling(name))
}
