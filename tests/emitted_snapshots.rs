//! Insta snapshots (in `snapshots/`) of emitted code for central items: a buffer's
//! creation, drop and memory binding, a draw, a submission with its safe SubmitInfo,
//! the beginning of a render pass, the typed pNext chain of
//! VkPhysicalDeviceFeatures2 and an enumeration. The items are cut out of the
//! committed `generated/src/generated` files, which `generated_fresh` proves are exactly what
//! the generator writes; a change to an emitter shows up here as a readable diff.

use quote::ToTokens;
use std::path::PathBuf;

/// A generated module; for a folder (`structs`, `commands`), the items of all its
/// files together.
fn parse(module: &str) -> syn::File {
    let base = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../generated/src/generated");
    let dir = base.join(module.trim_end_matches(".rs"));
    let paths: Vec<PathBuf> = if dir.is_dir() {
        let mut v: Vec<PathBuf> = std::fs::read_dir(&dir)
            .expect("a generated folder")
            .map(|e| e.expect("entry").path())
            .collect();
        v.sort();
        v
    } else {
        vec![base.join(module)]
    };
    let mut file: syn::File = syn::parse_quote!();
    for path in paths {
        let text = std::fs::read_to_string(&path)
            .unwrap_or_else(|e| panic!("cannot read {}: {e}", path.display()));
        let parsed = syn::parse_file(&text)
            .unwrap_or_else(|e| panic!("{} does not parse: {e}", path.display()));
        file.items.extend(parsed.items);
    }
    file
}

fn show(items: Vec<syn::Item>) -> String {
    assert!(!items.is_empty(), "no item matched");
    let mut file: syn::File = syn::parse_quote!();
    file.items = items;
    prettyplease::unparse(&file)
}

/// Methods named `names` of the impl blocks of `file`, each in its impl block.
fn methods(file: &syn::File, names: &[&str]) -> Vec<syn::Item> {
    let mut out = Vec::new();
    for name in names {
        let before = out.len();
        for item in &file.items {
            if let syn::Item::Impl(imp) = item {
                for member in &imp.items {
                    if let syn::ImplItem::Fn(f) = member {
                        if f.sig.ident == name {
                            let mut one = imp.clone();
                            one.items = vec![member.clone()];
                            out.push(syn::Item::Impl(one));
                        }
                    }
                }
            }
        }
        assert!(out.len() > before, "no method `{name}` was emitted");
    }
    out
}

/// Type definitions and impl blocks for `ty` (by the name of their self type).
fn items_of(file: &syn::File, ty: &str) -> Vec<syn::Item> {
    file.items
        .iter()
        .filter(|item| match item {
            syn::Item::Struct(s) => s.ident == ty,
            // `safe_struct!(#[cfg(..)] Name, 'a; ..)`: the struct's shared plumbing.
            syn::Item::Macro(m) => m
                .mac
                .tokens
                .to_string()
                .split(|c: char| !c.is_alphanumeric() && c != '_')
                .any(|word| word == ty),
            syn::Item::Impl(imp) => {
                let self_ty = imp.self_ty.to_token_stream().to_string();
                self_ty == ty || self_ty.starts_with(&format!("{ty} <"))
            }
            _ => false,
        })
        .cloned()
        .collect()
}

fn snapshot(name: &str, text: String) {
    insta::with_settings!({ snapshot_path => "../snapshots", prepend_module_to_snapshot => false }, {
        insta::assert_snapshot!(name, text);
    });
}

#[test]
fn buffer_create_drop_and_bind() {
    let handles = parse("handles.rs");
    let commands = parse("commands.rs");
    let mut items = items_of(&handles, "Buffer");
    items.extend(items_of(&handles, "BufferInner"));
    items.extend(methods(
        &commands,
        &[
            "create_buffer",
            "bind_buffer_memory",
            "bind_buffer_memory_unchecked",
        ],
    ));
    snapshot("emitted-buffer", show(items));
}

#[test]
fn cmd_draw() {
    let commands = parse("commands.rs");
    let mut items = methods(&commands, &["draw", "draw_unchecked"]);
    items.extend(methods(&parse("command_checks.rs"), &["validate_draw"]));
    snapshot("emitted-vkCmdDraw", show(items));
}

#[test]
fn queue_submit_and_submit_info() {
    let commands = parse("commands.rs");
    let structs = parse("structs.rs");
    let mut items = methods(&commands, &["submit", "submit_unchecked"]);
    items.extend(methods(&parse("command_checks.rs"), &["validate_submit"]));
    items.extend(items_of(&structs, "SubmitInfo"));
    snapshot("emitted-vkQueueSubmit", show(items));
}

#[test]
fn cmd_begin_render_pass() {
    let commands = parse("commands.rs");
    let mut items = methods(
        &commands,
        &["begin_render_pass", "begin_render_pass_unchecked"],
    );
    items.extend(methods(
        &parse("command_checks.rs"),
        &["validate_begin_render_pass"],
    ));
    snapshot("emitted-vkCmdBeginRenderPass", show(items));
}

#[test]
fn physical_device_features2_chain() {
    let structs = parse("structs.rs");
    let mut items = items_of(&structs, "PhysicalDeviceFeatures2");
    // The structs that may extend its chain: one `Extends` impl each.
    let extenders: Vec<String> = structs
        .items
        .iter()
        .filter_map(|item| match item {
            syn::Item::Impl(imp) if imp.unsafety.is_some() => {
                let text = imp.to_token_stream().to_string();
                text.contains("Extends < PhysicalDeviceFeatures2 <")
                    .then(|| imp.self_ty.to_token_stream().to_string())
            }
            _ => None,
        })
        .collect();
    assert!(extenders
        .iter()
        .any(|e| e.starts_with("PhysicalDeviceVulkan13Features")));
    items.retain(|i| !matches!(i, syn::Item::Impl(imp) if imp.unsafety.is_some()));
    snapshot(
        "emitted-VkPhysicalDeviceFeatures2",
        format!(
            "{}\n// Extends<PhysicalDeviceFeatures2> is implemented for:\n{}\n",
            show(items),
            extenders
                .iter()
                .map(|e| format!("// - {e}"))
                .collect::<Vec<_>>()
                .join("\n")
        ),
    );
}

#[test]
fn enumeration() {
    let commands = parse("commands.rs");
    snapshot(
        "emitted-vkEnumeratePhysicalDevices",
        show(methods(&commands, &["enumerate_physical_devices"])),
    );
}

/// Every generated file, recursively, with its text.
fn generated_files() -> Vec<(PathBuf, String)> {
    let mut todo =
        vec![PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../generated/src/generated")];
    let mut out = Vec::new();
    while let Some(dir) = todo.pop() {
        for entry in std::fs::read_dir(&dir).expect("generated/src/generated") {
            let path = entry.expect("entry").path();
            if path.is_dir() {
                todo.push(path);
            } else {
                let text = std::fs::read_to_string(&path).expect("a generated file");
                out.push((path, text));
            }
        }
    }
    out
}

/// The emitted code reads as written by hand: no function declares `-> ()`, no
/// binding is made only to be discarded (`let _ = s;`), and no closure is called
/// where it is written (checks are named `validate_*` methods).
#[test]
fn emitted_code_has_no_generator_noise() {
    let mut found = Vec::new();
    for (path, text) in generated_files() {
        for (i, line) in text.lines().enumerate() {
            if line.contains("-> ()") || line.contains("let _ = s;") || line.contains("})()") {
                found.push(format!("{}:{}: {}", path.display(), i + 1, line.trim()));
            }
        }
    }
    assert!(found.is_empty(), "generator noise:\n{}", found.join("\n"));
}

/// Generated code is split by core version and extension so a reader can find an
/// item and an editor can open its file: no generated file above 5,000 lines.
#[test]
fn no_generated_file_is_too_long() {
    let files = generated_files();
    let mut long = Vec::new();
    for (path, text) in &files {
        let lines = text.lines().count();
        if lines > 5_000 {
            long.push(format!("{}: {lines} lines", path.display()));
        }
    }
    let files = files.len();
    assert!(files > 10, "only {files} generated files found");
    assert!(long.is_empty(), "{}", long.join("\n"));
}

/// Every `unsafe` block of the generated code says why it is sound: the statement it
/// is in is preceded by a `// SAFETY:` comment (the generator writes them through a
/// marker, since `quote!` drops comments).
#[test]
fn every_generated_unsafe_block_has_a_safety_comment() {
    let (mut blocks, mut bare) = (0, Vec::new());
    for (path, text) in generated_files() {
        // Doc examples are read as the code they show.
        let lines: Vec<&str> = text
            .lines()
            .map(|l| {
                let t = l.trim_start();
                t.strip_prefix("///")
                    .or_else(|| t.strip_prefix("//!"))
                    .unwrap_or(l)
            })
            .collect();
        for (i, line) in lines.iter().enumerate() {
            if !line.contains("unsafe {") {
                continue;
            }
            blocks += 1;
            // Up to the first line of the statement, then the line above it.
            let mut start = i;
            while start > 0 {
                let prev = lines[start - 1].trim_end();
                let ends = prev.trim_start().starts_with("//")
                    || prev.trim().is_empty()
                    || prev.ends_with([';', '{', '}', ',']);
                if ends {
                    break;
                }
                start -= 1;
            }
            // A comment run above the statement that includes a SAFETY line.
            let mut k = start;
            let mut justified = false;
            while k > 0 && lines[k - 1].trim_start().starts_with("//") {
                justified |= lines[k - 1].trim_start().starts_with("// SAFETY:");
                k -= 1;
            }
            if !justified {
                bare.push(format!("{}:{}: {}", path.display(), i + 1, line.trim()));
            }
        }
    }
    assert!(blocks > 100, "only {blocks} unsafe blocks found");
    assert!(
        bare.is_empty(),
        "{} unsafe blocks without a SAFETY comment:\n{}",
        bare.len(),
        bare.join("\n")
    );
}
