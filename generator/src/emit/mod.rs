//! Emit pass: renderers, one per kind of output, that turn the [`Plans`] into Rust
//! under `generated/src/generated/`. They decide nothing the report reads: the
//! settlement of every rule is in the plans, so docs, code and report agree.

mod api_info;
pub mod checks;
pub mod commands;
mod delta;
pub mod explicit;
pub mod features;
pub mod formats;
pub mod handles;
pub mod helpers;
pub mod reach;
mod selected;
pub mod status;
pub mod structs;
pub mod sync;
pub mod sync_tables;

use crate::model::Model;
use crate::names;
use crate::plan::{Plans, Settlement};
use proc_macro2::TokenStream;
use std::collections::BTreeMap;
use std::path::PathBuf;
/// One file of the output, relative to the output folder.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct OutputFile {
    /// Path relative to the output folder, with `/` separators.
    pub path: PathBuf,
    /// Full contents.
    pub contents: String,
}

/// What the renderers produced.
#[derive(Debug, Clone, Default)]
pub struct Emission {
    /// Source files.
    pub files: Vec<OutputFile>,
}

/// The rules of an item as a doc section, after the rest of its docs: a link to the
/// specification's reference page, then each rule with its VUID, whether the
/// wrappers settle it and its text on one line, the caller's first (how each is
/// settled is in `VALIDATION.md` and `validation.json`).
pub(crate) fn doc_rules(plans: &Plans, item: &str) -> String {
    let Some(rules) = plans.by_item.get(item) else {
        return String::new();
    };
    let mut s = format!(
        "\n\n# Valid usage\n\nThe rules of `{item}` that apply to this crate's API ([reference page]({REFERENCE_PAGES}{item}.html)), \
         each marked *yours* (the caller upholds it), *checked* (a run-time check returns \
         `Error::Validation` naming it) or *by the types* (no \
         program that compiles breaks it); how each is settled is in the crate's \
         `validation.json`:\n"
    );
    let by_form = |v: &str| crate::plan::special::indirect::settled(v).is_some();
    let rank = |(v, r): &(String, Settlement)| match r {
        _ if by_form(v) => 0,
        Settlement::User(_) => 0,
        Settlement::Dynamic(_) => 1,
        Settlement::Static(_) => 2,
    };
    let mut ordered: Vec<_> = rules.iter().collect();
    ordered.sort_by_key(|e| rank(e));
    for (vuid, settlement) in ordered {
        // A rule left to the caller says why in a few words: the reason up to its
        // first explanation ("explicit rule", "checked by the safe methods in every
        // build" where no test breaks it yet).
        let mark = match settlement {
            // Settled by a safe form only: the generated method leaves it to its caller.
            _ if by_form(vuid) => {
                "*yours*; checked by the safe forms over an `IndirectBuffer`".to_owned()
            }
            Settlement::User(why) => {
                let short = why
                    .split([':', '(', ';'])
                    .next()
                    .unwrap_or_default()
                    .trim_end_matches([' ', ','])
                    .to_owned();
                format!("*yours*; {short}")
            }
            Settlement::Dynamic(_) => "*checked*".to_owned(),
            Settlement::Static(_) => "*by the types*".to_owned(),
        };
        let text = plans.texts.get(vuid).map_or("", String::as_str);
        s.push_str(&format!(
            "\n- `{vuid}` ({}): {}",
            doc_escape(&mark),
            doc_escape(text)
        ));
    }
    s
}

/// A doc section showing where the example programs use `key` (a method of
/// `receiver`, or a type when `receiver` is `None`), or nothing when they do not.
pub(crate) fn example_doc(
    cx: &crate::plan::Context,
    key: &str,
    receiver: Option<&str>,
    what: &str,
) -> String {
    match cx.example(key, receiver) {
        Some(s) => format!(
            "\n\n# Example\n\n{what}, as `{}` (line {}) does; the example programs run in CI:\n\n```ignore\n{}\n```",
            s.file, s.line, s.code
        ),
        None => String::new(),
    }
}

/// Prose from the specification or a settlement, made safe for rustdoc: outside
/// inline code, `[0,1]` would read as a link and `<formats>` as an HTML tag.
pub(crate) fn doc_escape(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    let mut in_code = false;
    for c in text.chars() {
        match c {
            '`' => {
                in_code = !in_code;
                out.push(c);
            }
            '[' | ']' if !in_code => {
                out.push('\\');
                out.push(c);
            }
            '<' if !in_code => out.push_str("&lt;"),
            '>' if !in_code => out.push_str("&gt;"),
            _ => out.push(c),
        }
    }
    out
}

/// Where the specification's reference pages are, one per command and struct.
const REFERENCE_PAGES: &str = "https://registry.khronos.org/vulkan/specs/1.3-extensions/man/html/";

/// The first line of every generated file: where it comes from and how to remake it.
pub const HEADER: &str =
    "// @generated by tuff-gen from vk.xml; do not edit. Regenerate: cargo run -p tuff-gen";

/// Where generated modules go, relative to the output folder. The rest of the crate
/// (`src/*.rs` around it) is hand-written and never touched by the generator.
pub const GENERATED_DIR: &str = "src/generated";

/// The generated module an item goes in: its core version (`v1_0`, ...) or the
/// extension that first names it (`khr_swapchain`), read from its condition, so a
/// reader finds an extension's items in one file.
pub(crate) fn module_of(model: &Model, item: &str) -> String {
    let home = model.home(item);
    match home.strip_prefix("VK_VERSION_") {
        Some(v) => format!("v{v}"),
        None => names::feature(&home),
    }
}

/// What a module of [`module_of`] holds, for its doc line.
fn module_title(module: &str) -> String {
    if let Some(version) = module.strip_suffix("_recording") {
        return format!("{}, recorded into command buffers", module_title(version));
    }
    match module.strip_prefix('v') {
        Some(v) if v.starts_with(|c: char| c.is_ascii_digit()) => {
            format!("Vulkan {}", v.replace('_', "."))
        }
        _ => format!("`VK_{}`", module.to_uppercase()),
    }
}

/// The `cfg` of a whole extension module: its feature, when every item in it (named
/// by `items`) exists only with that extension, so the module is empty without it.
fn module_cfg(model: &Model, module: &str, items: &[String]) -> Option<TokenStream> {
    let ext = model
        .enabled
        .iter()
        .find(|e| !e.starts_with("VK_VERSION_") && names::feature(e) == module);
    if let Some(ext) = ext {
        let needs_ext = |item: &String| {
            model
                .condition(item)
                .expr()
                .alternatives()
                .iter()
                .all(|alt| alt.names().contains(ext.as_str()))
        };
        if items.iter().all(needs_ext) {
            let feature = names::feature(ext);
            return Some(quote::quote!(#[cfg(feature = #feature)]));
        }
    }
    // Otherwise (a module of items an extension's interaction with another adds, or
    // of items a promoted extension shares with its successor) the module is gated
    // as its items all are, if they agree.
    let cfgs: Vec<Option<String>> = items
        .iter()
        .map(|i| names::cfg_of(model, model.condition(i)).map(|c| c.to_string()))
        .collect();
    let first = cfgs.first()?.clone()?;
    cfgs.iter()
        .all(|c| c.as_deref() == Some(first.as_str()))
        .then(|| names::cfg_of(model, model.condition(&items[0])))
        .flatten()
}

/// The most source text (as tokens print) one generated file holds: about 3,500
/// formatted lines, so that no file grows past 5,000 as the registry grows.
const FILE_BUDGET: usize = 160_000;

/// One generated folder of modules: `dir/mod.rs` with `head` (its docs, lints and
/// imports, which the modules share through `use super::*`) and one file per core
/// version and extension, with the items and the names of the registry items they
/// come from. Versions come first, in order; `reexport` makes the modules' items the
/// folder's own. A module too long for one file is split in parts
/// (`v1_3.rs`, `v1_3_part2.rs`, ..), each gated as the whole.
pub(crate) fn split(
    model: &Model,
    dir: &str,
    what: &str,
    head: TokenStream,
    modules: BTreeMap<String, (Vec<String>, Vec<TokenStream>)>,
    reexport: bool,
) -> Vec<(String, TokenStream)> {
    let mut order: Vec<&String> = modules.keys().collect();
    order.sort_by_key(|m| (!m.starts_with("v1_"), m.to_string()));
    // A module whose items need different features, and no one feature they all
    // share, can be empty in a build: its imports are then unused.
    let partial = |m: &String| {
        let names = &modules[m].0;
        let module = module_cfg(model, m, names).map(|c| c.to_string());
        names.iter().any(|i| {
            let item = names::cfg_of(model, model.condition(i)).map(|c| c.to_string());
            item.is_some() && item != module
        })
    };
    // Each module with its files: each part's file name and items.
    type Parts<'a> = Vec<(String, &'a [TokenStream])>;
    let files: Vec<(&String, Parts)> = order
        .iter()
        .map(|m| {
            let named = parts(&modules[*m].1)
                .into_iter()
                .enumerate()
                .map(|(i, items)| match i {
                    0 => ((*m).clone(), items),
                    _ => (format!("{m}_part{}", i + 1), items),
                })
                .collect();
            (*m, named)
        })
        .collect();
    let decls = files.iter().flat_map(|(m, parts)| {
        let cfg = module_cfg(model, m, &modules[*m].0);
        parts.iter().map(move |(file, _)| {
            let id = names::ident(file);
            if reexport {
                // The folders re-exported crate-privately (`checks/structs`) may not
                // use every item of a module, whose glob then goes unused.
                quote::quote!(#cfg mod #id; #cfg #[allow(unused_imports)] pub use #id::*;)
            } else {
                quote::quote!(#cfg mod #id;)
            }
        })
    });
    let decls: Vec<TokenStream> = decls.collect();
    let mut out = vec![(
        format!("{dir}/mod.rs"),
        quote::quote! {
            #head
            #(#decls)*
        },
    )];
    for (m, parts) in &files {
        let n = parts.len();
        let allow = partial(m).then(|| quote::quote!(#[allow(unused_imports)]));
        for (i, (file, items)) in parts.iter().enumerate() {
            let doc = match n {
                1 => format!("{what} of {}.", module_title(m)),
                _ => format!("{what} of {} (part {} of {n}).", module_title(m), i + 1),
            };
            out.push((
                format!("{dir}/{file}.rs"),
                quote::quote! {
                    #![doc = #doc]
                    #allow
                    use super::*;
                    #(#items)*
                },
            ));
        }
    }
    out
}

/// `items` in consecutive parts of at most [`FILE_BUDGET`] printed characters each
/// (an item larger than that alone in its part).
fn parts(items: &[TokenStream]) -> Vec<&[TokenStream]> {
    let mut parts = Vec::new();
    let (mut start, mut size) = (0, 0);
    for (i, item) in items.iter().enumerate() {
        let len = item.to_string().len();
        if size + len > FILE_BUDGET && i > start {
            parts.push(&items[start..i]);
            (start, size) = (i, 0);
        }
        size += len;
    }
    parts.push(&items[start..]);
    parts
}

/// Format a generated module.
fn format(tokens: TokenStream, header: &str) -> String {
    let text = match syn::parse2::<syn::File>(tokens.clone()) {
        Ok(file) => safety_comments(&prettyplease::unparse(&file)),
        // An emitter bug: keep the raw tokens so the compiler points at it.
        Err(e) => format!("compile_error!({:?});\n{tokens}", e.to_string()),
    };
    format!("{header}\n\n{text}")
}

/// A `// SAFETY:` comment for the statement that follows it in generated code.
/// `quote!` drops comments, so a renderer writes this marker statement instead and
/// [`format`] turns it into the comment.
pub(crate) fn safety(text: &str) -> TokenStream {
    quote::quote!(__safety!(#text);)
}

/// Replace every `__safety!("..");` line (as prettyplease prints it, on one line or
/// spread over several) with `// SAFETY: ..` comment lines at the same indent.
fn safety_comments(text: &str) -> String {
    const MARK: &str = "__safety!(";
    let mut out = String::with_capacity(text.len());
    let mut rest = text;
    while let Some(at) = rest.find(MARK) {
        let line_start = rest[..at].rfind('\n').map_or(0, |i| i + 1);
        let indent = &rest[line_start..at];
        // The argument is one string literal; its end is the first unescaped quote.
        let open = at + MARK.len() + rest[at + MARK.len()..].find('"').unwrap_or(0);
        let mut close = None;
        let mut escaped = false;
        for (i, c) in rest[open + 1..].char_indices() {
            match c {
                '\\' if !escaped => escaped = true,
                '"' if !escaped => {
                    close = Some(open + 1 + i);
                    break;
                }
                _ => escaped = false,
            }
        }
        let Some(close) = close else { break };
        let Some(end) = rest[close..].find(");").map(|e| close + e + 2) else {
            break;
        };
        let Ok(lit) = syn::parse_str::<syn::LitStr>(&rest[open..=close]) else {
            break;
        };
        out.push_str(&rest[..line_start]);
        let mut line = format!("{indent}// SAFETY:");
        for word in lit.value().split_whitespace() {
            if line.len() + 1 + word.len() > 100 && !line.trim_end().ends_with(':') {
                out.push_str(&line);
                out.push('\n');
                line = format!("{indent}//");
            }
            line.push(' ');
            line.push_str(word);
        }
        out.push_str(&line);
        rest = &rest[end..];
    }
    out.push_str(rest);
    out
}

/// Run every renderer over the plans.
pub fn emit(plans: &Plans) -> Emission {
    let cx = plans.cx;
    let mut emission = Emission::default();
    api_info::emit(cx.model, &plans.enabling, &mut emission);
    let ok = plans.ok();
    let (commands, command_checks) = commands::emit(plans, &ok);
    let mut files = vec![
        ("delta.rs".to_owned(), delta::emit(cx)),
        ("handles.rs".to_owned(), handles::emit(cx)),
        ("reach.rs".to_owned(), reach::emit(cx)),
        ("features.rs".to_owned(), features::emit(cx.model)),
        ("formats.rs".to_owned(), formats::emit(cx.model)),
        ("helpers.rs".to_owned(), helpers::emit(plans)),
        ("status.rs".to_owned(), status::emit(cx, &plans.statuses)),
        ("sync_tables.rs".to_owned(), sync_tables::emit(cx.model)),
    ];
    files.extend(command_checks);
    files.extend(checks::emit(&plans.checker));
    files.extend(structs::emit(plans));
    files.extend(commands);
    for (path, tokens) in files {
        emission.files.push(OutputFile {
            path: format!("{GENERATED_DIR}/{path}").into(),
            contents: format(tokens, HEADER),
        });
    }
    emission.files.push(OutputFile {
        path: "oracle_cases.rs".into(),
        contents: explicit::oracle_file(&plans.oracle),
    });
    emission.files.push(OutputFile {
        path: "Cargo.toml".into(),
        contents: cargo_toml(cx.model),
    });
    emission
}

/// The generated crate's manifest, with one feature per extension (and the
/// features of the extensions it depends on).
fn cargo_toml(model: &Model) -> String {
    // The package fields are written out, not inherited from a workspace, so that
    // the crate builds wherever `--out` puts it (the generator's own package
    // inherits the workspace's, so the two agree).
    let mut s = format!(
        "# @generated by tuff-gen from vk.xml; do not edit. Regenerate: cargo run -p tuff-gen
[package]
name = \"tuff\"
description = \"Safe Vulkan wrappers over ash, generated from the Khronos registry\"
version = \"{}\"
edition = \"2021\"
license = \"{}\"
rust-version = \"{}\"
publish = false
",
        env!("CARGO_PKG_VERSION"),
        env!("CARGO_PKG_LICENSE"),
        env!("CARGO_PKG_RUST_VERSION"),
    );
    s.push_str(
        r#"
[dependencies]
ash = "0.38"
tuff-runtime = { path = "../runtime" }
bytemuck = "1"
smallvec = "1"
rustc-hash = "2"
raw-window-handle = "0.6"

# `--cfg tuff_untracked` (RUSTFLAGS) builds tuff without its hazard tracker, for the
# stage benchmark's "no tracking" column alone (scripts/hazard-bench.sh): never a
# feature, so no dependency graph can turn it on.
[lints.rust]
unexpected_cfgs = { level = "warn", check-cfg = ['cfg(tuff_untracked)'] }

[features]
default = []
# Kept so that builds naming it still work: the dynamic checks of implicit rules
# are compiled into every safe method now (the `_unchecked` twins skip them).
runtime_implicit_validations = ["tuff-runtime/runtime_implicit_validations"]
# Arc and real locks instead of Rc and no-op locks: wrappers become Send + Sync.
multi_thread = ["tuff-runtime/multi_thread"]
# Every extension of the generated API.
all_extensions = ["#,
    );
    let exts: Vec<String> = model
        .enabled
        .iter()
        .filter(|e| !e.starts_with("VK_VERSION_"))
        .map(|e| names::feature(e))
        .collect();
    s.push_str(
        &exts
            .iter()
            .map(|e| format!("{e:?}"))
            .collect::<Vec<_>>()
            .join(", "),
    );
    s.push_str("]\n");
    for ext in model
        .enabled
        .iter()
        .filter(|e| !e.starts_with("VK_VERSION_"))
    {
        let deps: Vec<String> = crate::plan::features::feature_deps(model, ext)
            .iter()
            .map(|e| format!("{:?}", names::feature(e)))
            .collect();
        s.push_str(&format!(
            "{} = [{}]\n",
            names::feature(ext),
            deps.join(", ")
        ));
    }
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn safety_markers_become_comments() {
        let tokens = quote::quote! {
            fn f() {
                __safety!("the list (each item checked before);\n it held \"quotes\" and a long enough text to wrap onto a second comment line here.");
                unsafe { g() };
            }
        };
        let text = format(tokens, "// header");
        assert!(!text.contains("__safety"), "{text}");
        let comments: Vec<&str> = text
            .lines()
            .filter(|l| l.trim_start().starts_with("//") && !l.starts_with("// header"))
            .collect();
        assert!(
            comments[0]
                .trim_start()
                .starts_with("// SAFETY: the list (each item checked before);"),
            "{text}"
        );
        assert!(comments.len() >= 2, "{text}");
        assert!(comments.iter().all(|l| l.len() <= 100), "{text}");
        assert!(text.contains("\"quotes\""), "{text}");
        assert!(syn::parse_file(&text).is_ok(), "{text}");
    }

    #[test]
    fn prose_reaches_rustdoc_as_text() {
        assert_eq!(
            super::doc_escape("in the range [0,1], from vk.xml's <formats>"),
            "in the range \\[0,1\\], from vk.xml's &lt;formats&gt;"
        );
        // Inline code keeps its brackets.
        assert_eq!(
            super::doc_escape("`maxComputeWorkGroupCount`[0] and `a[0]`"),
            "`maxComputeWorkGroupCount`\\[0\\] and `a[0]`"
        );
    }
}
