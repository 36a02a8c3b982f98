//! What the `ash` release the generated crate builds on defines.
//! `ash` is generated from one registry (0.38 from 1.3.281's); every item the emitted
//! code names must exist there with the same shape. Given that registry (the
//! config's `reference_registry`), this pass keeps each wanted extension whose items
//! the reference defines alike, and leaves out, with the reason, each one it lacks
//! or defines otherwise (a member renamed, a command's parameters changed), and
//! each one that depends on an extension left out. Core items are not compared
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
    extensions: BTreeSet<&'a str>,
    values: &'a BTreeMap<String, i64>,
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
            extensions: reference
                .extensions
                .iter()
                .filter(|e| super::is_supported(e.supported.as_deref()))
                .map(|e| e.name.as_str())
                .collect(),
            values: &reference.enum_numbers,
        }
    }
}

/// The parts of a member or parameter the generated code depends on; a type name
/// that the reference makes an alias stands for its target (ash defines both names
/// as one type).
fn shape<'a>(
    f: &'a Field,
    aliases: &BTreeMap<&str, &'a crate::registry::TypeDef>,
) -> (&'a str, &'a str, usize, Option<&'a str>) {
    let ty = match aliases
        .get(f.type_name.as_str())
        .and_then(|t| t.alias.as_deref())
    {
        Some(target) => target,
        None => f.type_name.as_str(),
    };
    (f.name.as_str(), ty, f.pointers, f.static_array.as_deref())
}

fn fields<'a>(
    list: &'a [Field],
    aliases: &BTreeMap<&str, &'a crate::registry::TypeDef>,
) -> Vec<(&'a str, &'a str, usize, Option<&'a str>)> {
    list.iter().map(|f| shape(f, aliases)).collect()
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

/// The first item of `interface` that `defined` lacks or defines otherwise.
fn differs(pinned: &Registry, defined: &Defined<'_>, interface: &Interface) -> Option<String> {
    let types: BTreeMap<&str, &crate::registry::TypeDef> =
        pinned.types.iter().map(|t| (t.name.as_str(), t)).collect();
    let commands: BTreeMap<&str, &crate::registry::CommandDef> = pinned
        .commands
        .iter()
        .map(|c| (c.name.as_str(), c))
        .collect();
    for require in &interface.requires {
        for name in &require.types {
            let Some(theirs) = defined.types.get(name.as_str()) else {
                return Some(format!("the reference has no type `{name}`"));
            };
            let Some(ours) = types.get(name.as_str()) else {
                continue;
            };
            // An alias names its target's members (ash defines it as a type alias).
            let (ours, theirs) = (resolve(&types, ours), resolve(&defined.types, theirs));
            let (a, b) = (
                fields(&ours.members, &defined.types),
                fields(&theirs.members, &defined.types),
            );
            if a != b {
                let at = a
                    .iter()
                    .zip(&b)
                    .position(|(x, y)| x != y)
                    .unwrap_or(a.len().min(b.len()));
                let show = |f: Option<&(&str, &str, usize, Option<&str>)>| match f {
                    Some((name, ty, pointers, array)) => format!(
                        "`{ty}{} {name}{}`",
                        "*".repeat(*pointers),
                        array.map(|n| format!("[{n}]")).unwrap_or_default()
                    ),
                    None => "nothing".to_owned(),
                };
                return Some(format!(
                    "the reference defines `{name}` otherwise: member {at} is {} there, {} here",
                    show(b.get(at)),
                    show(a.get(at))
                ));
            }
            if let Some(group) = pinned.enum_groups.iter().find(|g| &g.name == name) {
                if let Some(v) = group
                    .values
                    .iter()
                    .find(|v| !defined.values.contains_key(*v))
                {
                    return Some(format!("the reference has no value `{v}` of `{name}`"));
                }
            }
        }
        for name in &require.commands {
            let Some(theirs) = defined.commands.get(name.as_str()) else {
                return Some(format!("the reference has no command `{name}`"));
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
            if fields(&ours.params, &defined.types) != fields(&theirs.params, &defined.types) {
                return Some(format!("the reference gives `{name}` other parameters"));
            }
        }
        for (value, group) in &require.enum_extensions {
            if !defined.values.contains_key(value) {
                return Some(format!("the reference has no value `{value}` of `{group}`"));
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
    let mut left: Vec<LeftOut> = Vec::new();
    for name in wanted {
        let reason = if !defined.extensions.contains(name.as_str()) {
            Some(format!(
                "the reference registry (Vulkan {}) has no such extension for the vulkan API",
                reference.version
            ))
        } else {
            pinned
                .extensions
                .iter()
                .find(|e| &e.name == name)
                .and_then(|e| differs(pinned, &defined, e))
        };
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
