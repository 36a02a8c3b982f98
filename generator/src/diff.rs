//! `tuff-gen diff OLD NEW`: what changed from one registry to another, for the
//! person who reviews a version bump. Items and extensions come from the two
//! `vk.xml` files, rules from their `validusage.json` files when both have one, and
//! the emitted API's coverage and method signatures from generating both with the
//! same config (in memory: nothing is written).

use crate::registry::{load_registry, load_validusage, Registry};
use crate::{Error, Options, Result};
use serde::Serialize;
use std::collections::{BTreeMap, BTreeSet};
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

/// One side of a diff: a registry and, where it has one, its `validusage.json`.
#[derive(Debug, Clone)]
pub struct Side {
    /// `vk.xml`.
    pub registry: PathBuf,
    /// `validusage.json`, or `None` for a registry without one.
    pub validusage: Option<PathBuf>,
}

impl Side {
    /// `vk.xml` with the `validusage.json` beside it, when there is one.
    pub fn beside(registry: &Path) -> Side {
        let vu = registry.with_file_name("validusage.json");
        Side {
            registry: registry.to_owned(),
            validusage: vu.exists().then_some(vu),
        }
    }
}

/// Names added and removed, of one kind of item.
#[derive(Debug, Clone, Default, PartialEq, Eq, Serialize)]
pub struct Change {
    /// `commands`, `structs`, `handles`, `enums` or `extensions`.
    pub kind: String,
    /// In NEW only, in name order.
    pub added: Vec<String>,
    /// In OLD only, in name order.
    pub removed: Vec<String>,
}

/// The valid-usage rules of the two `validusage.json` files.
#[derive(Debug, Clone, Default, PartialEq, Eq, Serialize)]
pub struct Rules {
    /// VUIDs in NEW only.
    pub added: Vec<String>,
    /// VUIDs in OLD only.
    pub removed: Vec<String>,
    /// VUIDs in both whose text differs.
    pub text_changed: Vec<String>,
}

/// A method whose signature differs.
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
pub struct Signature {
    /// `Device::create_buffer`.
    pub method: String,
    /// Its signature generated from OLD.
    pub old: String,
    /// Its signature generated from NEW.
    pub new: String,
}

/// The emitted API generated from each side with the same config.
#[derive(Debug, Clone, Default, PartialEq, Eq, Serialize)]
pub struct Emitted {
    /// The coverage table from OLD: `[category][status]`, categories implicit,
    /// creation, usage; statuses static, dynamic, left to the user.
    pub old: [[usize; 3]; 3],
    /// The same from NEW.
    pub new: [[usize; 3]; 3],
    /// Public methods generated from NEW only (`Type::method`).
    pub methods_added: Vec<String>,
    /// Public methods generated from OLD only.
    pub methods_removed: Vec<String>,
    /// Public methods of both whose signature differs.
    pub signatures_changed: Vec<Signature>,
}

/// An item a new core version requires that OLD had under another name (an
/// extension's), or under its own.
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
pub struct Moved {
    /// Its name in the core version: `vkCmdPushDescriptorSet`.
    pub core: String,
    /// The names OLD had it under: `vkCmdPushDescriptorSetKHR`.
    pub was: Vec<String>,
}

/// A core version NEW has and OLD lacks: what it took in from extensions, and what
/// is new with it.
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
pub struct CoreVersion {
    /// `VK_VERSION_1_4`.
    pub name: String,
    /// The extensions NEW says were promoted to it (`promotedto`).
    pub promoted_extensions: Vec<String>,
    /// Commands, types and enum values it requires that OLD had, by any name.
    pub moved: Vec<Moved>,
    /// Those OLD had by no name: new in this version.
    pub new: Vec<String>,
}

/// Everything `tuff-gen diff` reports.
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
pub struct Diff {
    /// OLD's version, `1.3.239`.
    pub old_version: String,
    /// NEW's version.
    pub new_version: String,
    /// Items and extensions added and removed.
    pub items: Vec<Change>,
    /// The core versions NEW adds: what moved to core, what is new.
    pub core: Vec<CoreVersion>,
    /// Rules added, removed and changed, when both sides have `validusage.json`.
    pub rules: Option<Rules>,
    /// Why the rules were not compared, when they were not.
    pub rules_not_compared: Option<String>,
    /// The emitted API of each side.
    pub emitted: Emitted,
}

/// Compare `old` with `new`, generating each with the config at `config`.
pub fn diff(old: &Side, new: &Side, config: &Path) -> Result<Diff> {
    let (a, b) = (load_registry(&old.registry)?, load_registry(&new.registry)?);
    if a.version == b.version {
        return Err(Error::SameVersion {
            old: old.registry.clone(),
            new: new.registry.clone(),
            version: a.version,
        });
    }
    let items = item_changes(&a, &b);
    let core = core_changes(&a, &b);
    let (rules, rules_not_compared) = match (&old.validusage, &new.validusage) {
        (Some(x), Some(y)) => (Some(rule_changes(x, y)?), None),
        (x, _) => {
            let lacking = if x.is_none() { &old } else { &new };
            (
                None,
                Some(format!(
                    "{} has no validusage.json beside it",
                    lacking.registry.display()
                )),
            )
        }
    };
    let generate = |side: &Side| {
        crate::generate(&Options {
            registry: side.registry.clone(),
            validusage: side.validusage.clone(),
            config: config.to_owned(),
            out: PathBuf::new(),
            allow_version_mismatch: false,
            allow_shrink: true,
        })
    };
    let (ga, gb) = (generate(old)?, generate(new)?);
    let (ma, mb) = (methods(&ga.files), methods(&gb.files));
    let emitted = Emitted {
        old: ga.emitted.counts,
        new: gb.emitted.counts,
        methods_added: mb
            .keys()
            .filter(|k| !ma.contains_key(*k))
            .cloned()
            .collect(),
        methods_removed: ma
            .keys()
            .filter(|k| !mb.contains_key(*k))
            .cloned()
            .collect(),
        signatures_changed: ma
            .iter()
            .filter_map(|(k, old)| {
                let new = mb.get(k)?;
                (old != new).then(|| Signature {
                    method: k.clone(),
                    old: old.clone(),
                    new: new.clone(),
                })
            })
            .collect(),
    };
    Ok(Diff {
        old_version: a.version,
        new_version: b.version,
        items,
        core,
        rules,
        rules_not_compared,
        emitted,
    })
}

/// For each core version of `b` that `a` lacks, every item its blocks require, each
/// either moved (`a` had it under a name `b` gives as an alias of it, or under its
/// own) or new. Enum values are matched by their group and number, since vk.xml
/// gives a promoted value's core name as one more value of the same number.
fn core_changes(a: &Registry, b: &Registry) -> Vec<CoreVersion> {
    let old_features: BTreeSet<&str> = a.features.iter().map(|f| f.name.as_str()).collect();
    let old_commands: BTreeSet<&str> = a.commands.iter().map(|c| c.name.as_str()).collect();
    let old_types: BTreeSet<&str> = a.types.iter().map(|t| t.name.as_str()).collect();
    // Every name of an item in `b`: itself, what it aliases, what aliases it.
    let mut names: BTreeMap<&str, BTreeSet<&str>> = BTreeMap::new();
    let pairs = b
        .commands
        .iter()
        .filter_map(|c| Some((c.name.as_str(), c.alias.as_deref()?)))
        .chain(
            b.types
                .iter()
                .filter_map(|t| Some((t.name.as_str(), t.alias.as_deref()?))),
        );
    for (x, y) in pairs {
        names.entry(x).or_default().insert(y);
        names.entry(y).or_default().insert(x);
    }
    // Every value name of `b` by (group, number).
    let mut values: BTreeMap<(&str, i64), BTreeSet<&str>> = BTreeMap::new();
    let blocks = b.features.iter().chain(&b.extensions);
    for (value, group) in blocks
        .flat_map(|i| &i.requires)
        .flat_map(|r| &r.enum_extensions)
    {
        if let Some(n) = b.enum_numbers.get(value) {
            values.entry((group, *n)).or_default().insert(value);
        }
    }
    for g in &b.enum_groups {
        for v in &g.values {
            if let Some(n) = b.enum_numbers.get(v) {
                values.entry((&g.name, *n)).or_default().insert(v);
            }
        }
    }
    let mut out = Vec::new();
    for f in b
        .features
        .iter()
        .filter(|f| !old_features.contains(f.name.as_str()))
    {
        let mut moved = Vec::new();
        let mut new = Vec::new();
        let mut sort = |core: &str, was: Vec<String>| {
            if was.is_empty() {
                new.push(core.to_owned());
            } else {
                moved.push(Moved {
                    core: core.to_owned(),
                    was,
                });
            }
        };
        let mut seen = BTreeSet::new();
        for r in &f.requires {
            for (item, old) in r
                .commands
                .iter()
                .map(|c| (c, &old_commands))
                .chain(r.types.iter().map(|t| (t, &old_types)))
            {
                if !seen.insert(item.clone()) {
                    continue;
                }
                let was: Vec<String> = std::iter::once(item.as_str())
                    .chain(names.get(item.as_str()).into_iter().flatten().copied())
                    .filter(|n| old.contains(n))
                    .map(str::to_owned)
                    .collect();
                sort(item, was);
            }
            for (value, group) in &r.enum_extensions {
                if !seen.insert(value.clone()) {
                    continue;
                }
                let same = b
                    .enum_numbers
                    .get(value)
                    .and_then(|n| values.get(&(group.as_str(), *n)));
                let was: Vec<String> = std::iter::once(value.as_str())
                    .chain(same.into_iter().flatten().copied())
                    .filter(|n| a.enum_numbers.contains_key(*n))
                    .map(str::to_owned)
                    .collect::<BTreeSet<_>>()
                    .into_iter()
                    .collect();
                sort(value, was);
            }
        }
        let promoted_extensions = b
            .extensions
            .iter()
            .filter(|e| e.promoted_to.as_deref() == Some(f.name.as_str()))
            .map(|e| e.name.clone())
            .collect();
        out.push(CoreVersion {
            name: f.name.clone(),
            promoted_extensions,
            moved,
            new,
        });
    }
    out
}

fn added_removed(kind: &str, a: BTreeSet<&str>, b: BTreeSet<&str>) -> Change {
    Change {
        kind: kind.to_owned(),
        added: b.difference(&a).map(|s| (*s).to_owned()).collect(),
        removed: a.difference(&b).map(|s| (*s).to_owned()).collect(),
    }
}

/// Commands, structs (and unions), handles, enums and extensions of each registry,
/// aliases included (a rename adds a name); extensions only where supported for
/// the vulkan API.
fn item_changes(a: &Registry, b: &Registry) -> Vec<Change> {
    let types = |r: &'_ Registry, categories: &[&str]| -> BTreeSet<String> {
        r.types
            .iter()
            .filter(|t| {
                // An alias has no category of its own in vk.xml: it has its target's.
                let category = t.category.as_deref().or_else(|| {
                    let target = t.alias.as_deref()?;
                    r.types
                        .iter()
                        .find(|x| x.name == target)?
                        .category
                        .as_deref()
                });
                category.is_some_and(|c| categories.contains(&c))
            })
            .map(|t| t.name.clone())
            .collect()
    };
    let kinds: [(&str, &[&str]); 3] = [
        ("structs", &["struct", "union"]),
        ("handles", &["handle"]),
        ("enums", &["enum"]),
    ];
    let mut out = vec![added_removed(
        "commands",
        a.commands.iter().map(|c| c.name.as_str()).collect(),
        b.commands.iter().map(|c| c.name.as_str()).collect(),
    )];
    for (kind, categories) in kinds {
        let (x, y) = (types(a, categories), types(b, categories));
        out.push(added_removed(
            kind,
            x.iter().map(String::as_str).collect(),
            y.iter().map(String::as_str).collect(),
        ));
    }
    let extensions = |r: &'_ Registry| -> BTreeSet<String> {
        r.extensions
            .iter()
            .filter(|e| crate::model::is_supported(e.supported.as_deref()))
            .map(|e| e.name.clone())
            .collect()
    };
    let (x, y) = (extensions(a), extensions(b));
    out.push(added_removed(
        "extensions",
        x.iter().map(String::as_str).collect(),
        y.iter().map(String::as_str).collect(),
    ));
    out
}

fn rule_changes(old: &Path, new: &Path) -> Result<Rules> {
    let texts = |path: &Path| -> Result<BTreeMap<String, String>> {
        let vu = load_validusage(path)?;
        let mut map = BTreeMap::new();
        for e in vu.entries {
            map.entry(e.vuid)
                .or_insert_with(|| e.text.trim().to_owned());
        }
        Ok(map)
    };
    let (a, b) = (texts(old)?, texts(new)?);
    Ok(Rules {
        added: b.keys().filter(|k| !a.contains_key(*k)).cloned().collect(),
        removed: a.keys().filter(|k| !b.contains_key(*k)).cloned().collect(),
        text_changed: a
            .iter()
            .filter(|(k, t)| b.get(*k).is_some_and(|u| u != *t))
            .map(|(k, _)| k.clone())
            .collect(),
    })
}

/// Every public method of the generated crate's impl blocks (`Type::method` ->
/// its signature as tokens), from the generated files.
fn methods(files: &[crate::emit::OutputFile]) -> BTreeMap<String, String> {
    use quote::ToTokens as _;
    let mut out = BTreeMap::new();
    for f in files {
        if f.path.extension().is_none_or(|e| e != "rs") {
            continue;
        }
        let Ok(file) = syn::parse_file(&f.contents) else {
            continue;
        };
        for item in file.items {
            let syn::Item::Impl(imp) = item else { continue };
            let ty = match &*imp.self_ty {
                syn::Type::Path(p) => p
                    .path
                    .segments
                    .last()
                    .map(|s| s.ident.to_string())
                    .unwrap_or_default(),
                other => other.to_token_stream().to_string(),
            };
            for it in imp.items {
                if let syn::ImplItem::Fn(m) = it {
                    if matches!(m.vis, syn::Visibility::Public(_)) {
                        out.insert(format!("{ty}::{}", m.sig.ident), pretty(&m.sig));
                    }
                }
            }
        }
    }
    out
}

/// A signature as rustfmt would write it, on one line.
fn pretty(sig: &syn::Signature) -> String {
    let file: syn::File = syn::parse_quote!(#sig {});
    let text = prettyplease::unparse(&file);
    let line = text.split_whitespace().collect::<Vec<_>>().join(" ");
    line.trim_end_matches("{}")
        .trim()
        .replace("( ", "(")
        .replace(", )", ")")
}

/// The diff as Markdown, for a pull-request description: counts first, each list
/// folded under its count.
pub fn markdown(d: &Diff) -> String {
    let mut s = String::new();
    let _ = writeln!(
        s,
        "# Vulkan {} -> {}\n\n| Registry items | Added | Removed |\n|---|---|---|",
        d.old_version, d.new_version
    );
    for c in &d.items {
        let _ = writeln!(
            s,
            "| {} | {} | {} |",
            c.kind,
            c.added.len(),
            c.removed.len()
        );
    }
    for c in &d.items {
        list(&mut s, &format!("{} added", c.kind), &c.added);
        list(&mut s, &format!("{} removed", c.kind), &c.removed);
    }
    for v in &d.core {
        let _ = writeln!(
            s,
            "\n## {}\n\n{} extensions promoted to it; of the commands, types and enum values it \
             requires, {} moved to core from what {} had (under an extension's name or \
             their own) and {} are new.",
            v.name,
            v.promoted_extensions.len(),
            v.moved.len(),
            d.old_version,
            v.new.len()
        );
        list(&mut s, "Extensions promoted", &v.promoted_extensions);
        let moved: Vec<String> = v
            .moved
            .iter()
            .map(|m| {
                if m.was == [m.core.clone()] {
                    format!("`{}`", m.core)
                } else {
                    format!("`{}` (was `{}`)", m.core, m.was.join("`, `"))
                }
            })
            .collect();
        list_as(&mut s, "Moved to core", &moved, |n| n.to_owned());
        list(&mut s, "New in core", &v.new);
    }
    let _ = writeln!(s, "\n## Valid-usage rules\n");
    match (&d.rules, &d.rules_not_compared) {
        (Some(r), _) => {
            let _ = writeln!(
                s,
                "{} added, {} removed, {} whose text changed.",
                r.added.len(),
                r.removed.len(),
                r.text_changed.len()
            );
            list(&mut s, "Rules added", &r.added);
            list(&mut s, "Rules removed", &r.removed);
            list(&mut s, "Rules whose text changed", &r.text_changed);
        }
        (None, why) => {
            let _ = writeln!(
                s,
                "Not compared: {}.",
                why.as_deref().unwrap_or("a side has no validusage.json")
            );
        }
    }
    let e = &d.emitted;
    let _ = writeln!(
        s,
        "\n## Emitted API\n\nCoverage, {} -> {} (change):\n\n\
         | Category | Statically solved | Dynamically solved | Left to user | Total |\n\
         |---|---|---|---|---|",
        d.old_version, d.new_version
    );
    for (i, name) in ["Implicit", "Creation", "Usage"].iter().enumerate() {
        let cell = |a: usize, b: usize| format!("{a} -> {b} ({:+})", b as i64 - a as i64);
        let (a, b) = (e.old[i], e.new[i]);
        let _ = writeln!(
            s,
            "| {name} | {} | {} | {} | {} |",
            cell(a[0], b[0]),
            cell(a[1], b[1]),
            cell(a[2], b[2]),
            cell(a.iter().sum(), b.iter().sum())
        );
    }
    let _ = writeln!(
        s,
        "\nMethods: {} added, {} removed, {} whose signature changed.",
        e.methods_added.len(),
        e.methods_removed.len(),
        e.signatures_changed.len()
    );
    list(&mut s, "Methods added", &e.methods_added);
    list(&mut s, "Methods removed", &e.methods_removed);
    if !e.signatures_changed.is_empty() {
        let _ = writeln!(
            s,
            "\n<details><summary>Signatures changed ({})</summary>\n",
            e.signatures_changed.len()
        );
        for c in &e.signatures_changed {
            let _ = writeln!(
                s,
                "- `{}`\n  - old: `{}`\n  - new: `{}`",
                c.method, c.old, c.new
            );
        }
        let _ = writeln!(s, "\n</details>");
    }
    s
}

fn list(s: &mut String, title: &str, names: &[String]) {
    list_as(s, title, names, |n| format!("`{n}`"));
}

/// [`list`], each entry written by `show`.
fn list_as(s: &mut String, title: &str, names: &[String], show: impl Fn(&str) -> String) {
    if names.is_empty() {
        return;
    }
    let _ = writeln!(
        s,
        "\n<details><summary>{title} ({})</summary>\n\n{}\n\n</details>",
        names.len(),
        names.iter().map(|n| show(n)).collect::<Vec<_>>().join(", ")
    );
}
