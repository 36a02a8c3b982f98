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

/// Everything `tuff-gen diff` reports.
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
pub struct Diff {
    /// OLD's version, `1.3.239`.
    pub old_version: String,
    /// NEW's version.
    pub new_version: String,
    /// Items and extensions added and removed.
    pub items: Vec<Change>,
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
        rules,
        rules_not_compared,
        emitted,
    })
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
    if names.is_empty() {
        return;
    }
    let _ = writeln!(
        s,
        "\n<details><summary>{title} ({})</summary>\n\n{}\n\n</details>",
        names.len(),
        names
            .iter()
            .map(|n| format!("`{n}`"))
            .collect::<Vec<_>>()
            .join(", ")
    );
}
