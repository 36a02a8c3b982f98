//! The public API's shape, read from the source: every public type of the `tuff` and
//! `tuff-runtime` crates implements `Debug` (a handle shows its type and raw value, a
//! safe struct its ash struct's members), so a user can print anything they hold.

use std::collections::BTreeSet;
use std::path::{Path, PathBuf};
use syn::visit::Visit;

/// Every `.rs` file under `dir`.
fn sources(dir: &Path) -> Vec<PathBuf> {
    let mut todo = vec![dir.to_owned()];
    let mut out = Vec::new();
    while let Some(d) = todo.pop() {
        for entry in std::fs::read_dir(&d).expect("a source folder") {
            let path = entry.expect("an entry").path();
            if path.is_dir() {
                todo.push(path);
            } else if path.extension().is_some_and(|e| e == "rs") {
                out.push(path);
            }
        }
    }
    out
}

#[derive(Default)]
struct Types {
    /// `pub struct` and `pub enum` names, with the file they are in.
    public: Vec<(String, String)>,
    /// Names with a `Debug` derive or impl, or made by a macro that implements it.
    debug: BTreeSet<String>,
    file: String,
}

/// The macros of `support.rs` that implement `Debug` for the type they are given.
const DEBUG_MACROS: [&str; 2] = ["safe_struct", "child_handle"];

impl<'ast> Visit<'ast> for Types {
    fn visit_item_struct(&mut self, i: &'ast syn::ItemStruct) {
        self.item(&i.vis, &i.ident, &i.attrs);
        syn::visit::visit_item_struct(self, i);
    }
    fn visit_item_enum(&mut self, i: &'ast syn::ItemEnum) {
        self.item(&i.vis, &i.ident, &i.attrs);
        syn::visit::visit_item_enum(self, i);
    }
    fn visit_item_impl(&mut self, i: &'ast syn::ItemImpl) {
        let is_debug = i
            .trait_
            .as_ref()
            .and_then(|(path, _)| path.segments.last())
            .is_some_and(|s| s.ident == "Debug");
        if let (true, syn::Type::Path(p)) = (is_debug, &*i.self_ty) {
            if let Some(last) = p.path.segments.last() {
                self.debug.insert(last.ident.to_string());
            }
        }
        syn::visit::visit_item_impl(self, i);
    }
    fn visit_item_macro(&mut self, i: &'ast syn::ItemMacro) {
        let name = i.mac.path.segments.last().map(|s| s.ident.to_string());
        if name.is_some_and(|n| DEBUG_MACROS.contains(&n.as_str())) {
            // The type is the first identifier after any `#[cfg(..)]`.
            let tokens: Vec<proc_macro2::TokenTree> = i.mac.tokens.clone().into_iter().collect();
            let ident = tokens.iter().find_map(|t| match t {
                proc_macro2::TokenTree::Ident(id) if id != "cfg" => Some(id.to_string()),
                _ => None,
            });
            self.debug.extend(ident);
        }
    }
}

impl Types {
    fn item(&mut self, vis: &syn::Visibility, ident: &syn::Ident, attrs: &[syn::Attribute]) {
        if !matches!(vis, syn::Visibility::Public(_)) {
            return;
        }
        self.public.push((ident.to_string(), self.file.clone()));
        let derives_debug = attrs.iter().any(|a| {
            a.path().is_ident("derive")
                && a.to_token_stream_string()
                    .split(|c: char| !c.is_alphanumeric())
                    .any(|w| w == "Debug")
        });
        if derives_debug {
            self.debug.insert(ident.to_string());
        }
    }
}

trait AttrText {
    fn to_token_stream_string(&self) -> String;
}

impl AttrText for syn::Attribute {
    fn to_token_stream_string(&self) -> String {
        quote::ToTokens::to_token_stream(self).to_string()
    }
}

#[test]
fn every_public_type_implements_debug() {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("..");
    let mut types = Types::default();
    for crate_src in ["generated/src", "runtime/src"] {
        for path in sources(&root.join(crate_src)) {
            let text = std::fs::read_to_string(&path).expect("a source file");
            let file = syn::parse_file(&text).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
            types.file = path
                .strip_prefix(&root)
                .unwrap_or(&path)
                .display()
                .to_string();
            types.visit_file(&file);
        }
    }
    assert!(
        types.public.len() > 700,
        "{} public types found",
        types.public.len()
    );
    let missing: Vec<String> = types
        .public
        .iter()
        .filter(|(name, _)| !types.debug.contains(name))
        .map(|(name, file)| format!("{name} ({file})"))
        .collect();
    assert!(
        missing.is_empty(),
        "public types without Debug:\n{}",
        missing.join("\n")
    );
}

/// The doc comment right above line `at` (over attributes), as text.
fn doc_above(lines: &[&str], at: usize) -> String {
    let mut k = at;
    while k > 0 && lines[k - 1].trim_start().starts_with("#[") {
        k -= 1;
    }
    let mut doc = Vec::new();
    if k > 0 && lines[k - 1].trim_end().ends_with("*/") {
        while k > 0 {
            k -= 1;
            doc.push(lines[k]);
            if lines[k].trim_start().starts_with("/**") {
                break;
            }
        }
    } else {
        while k > 0 && lines[k - 1].trim_start().starts_with("///") {
            k -= 1;
            doc.push(lines[k]);
        }
    }
    doc.reverse();
    doc.join("\n")
}

/// Every command method and every struct the example programs use (the tuff ones:
/// a file that names `ash` is a raw-ash program) shows, in its docs, a statement of
/// the examples that uses it.
#[test]
fn every_method_and_struct_the_examples_use_shows_an_example() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    let mut called = BTreeSet::new();
    let mut made = BTreeSet::new();
    for file in sources(&root.join("examples/src")) {
        let text = std::fs::read_to_string(&file).unwrap();
        if text.contains("ash::") || text.contains("use ash") {
            continue;
        }
        let ident = |s: &str| -> String {
            let rev: String = s
                .chars()
                .rev()
                .take_while(|c| c.is_ascii_alphanumeric() || *c == '_')
                .collect();
            rev.chars().rev().collect()
        };
        for line in text.lines() {
            let code = line.split("//").next().unwrap_or("");
            for (at, _) in code.match_indices('(') {
                let name = ident(&code[..at]);
                let before = &code[..at - name.len()];
                if let Some(on) = before.strip_suffix('.') {
                    // The variable it is called on: `rec` in `rec.draw(`, so that
                    // `frame.submit(` is not taken for `Queue::submit`.
                    called.insert((ident(on), name));
                } else if name == "new" && before.ends_with("::") {
                    made.insert(ident(&before[..before.len() - 2]));
                }
            }
        }
    }
    // Command methods carry their Vulkan name as a doc alias; structs are
    // `pub struct`s of the generated struct modules.
    // A call counts for a method when it is made on a variable whose name begins
    // the snake-case name of the method's type (`rec` for `Recorder`, `physical`
    // for `PhysicalDevice`).
    let mut missing = Vec::new();
    let (mut methods, mut structs) = (0, 0);
    for file in sources(&root.join("generated/src/generated")) {
        let text = std::fs::read_to_string(&file).unwrap();
        let lines: Vec<&str> = text.lines().collect();
        let mut receiver = String::new();
        for (i, line) in lines.iter().enumerate() {
            let t = line.trim_start();
            if t.starts_with("impl") && t.ends_with('{') {
                // `impl<'c, S: Scope> Recorder<'c, S> {` -> `Recorder`.
                let mut rest = t.trim_start_matches("impl");
                if rest.starts_with('<') {
                    let mut depth = 0;
                    let end = rest
                        .char_indices()
                        .find(|&(_, c)| {
                            depth += match c {
                                '<' => 1,
                                '>' => -1,
                                _ => 0,
                            };
                            depth == 0
                        })
                        .map_or(rest.len(), |(i, _)| i + 1);
                    rest = &rest[end..];
                }
                let ty = rest.trim_start().split(['<', ' ']).next().unwrap_or("");
                receiver = ty
                    .chars()
                    .enumerate()
                    .flat_map(|(i, c)| {
                        let sep = (i > 0 && c.is_ascii_uppercase()).then_some('_');
                        sep.into_iter()
                            .chain(std::iter::once(c.to_ascii_lowercase()))
                    })
                    .collect();
            }
            let fn_name = t
                .strip_prefix("pub fn ")
                .or_else(|| t.strip_prefix("pub unsafe fn "))
                .map(|r| r.split(['(', '<']).next().unwrap_or(""));
            if let Some(name) = fn_name {
                let aliased = i > 0
                    && lines[i.saturating_sub(3)..i]
                        .iter()
                        .any(|l| l.contains("#[doc(alias = \"vk"));
                let on_it = called.iter().any(|(on, n)| {
                    n == name && !on.is_empty() && receiver.starts_with(on.as_str())
                });
                if aliased && on_it {
                    methods += 1;
                    if !doc_above(&lines, i).contains("# Example") {
                        missing.push(format!("{name} ({})", file.display()));
                    }
                }
            }
            if let Some(rest) = t.strip_prefix("pub struct ") {
                let name = rest.split(['<', ' ', '(', '{', ';']).next().unwrap_or("");
                if made.contains(name) && file.to_string_lossy().contains("structs") {
                    structs += 1;
                    if !doc_above(&lines, i).contains("# Example") {
                        missing.push(format!("struct {name} ({})", file.display()));
                    }
                }
            }
        }
    }
    assert!(
        methods > 30 && structs > 20,
        "{methods} methods, {structs} structs"
    );
    assert!(
        missing.is_empty(),
        "no example in the docs of: {missing:#?}"
    );
}

/// Each rule in an item's docs carries its VUID, its text and a mark that agrees with
/// the coverage report (`validation.json`): *yours* for a rule left to the caller (or
/// settled only by the safe forms of the indirect commands), *checked* for a dynamic
/// check, *by the types* for a static one.
#[test]
fn the_docs_mark_each_rule_as_the_report_settles_it() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    let report: serde_json::Value = serde_json::from_str(
        &std::fs::read_to_string(root.join("generated/validation.json")).unwrap(),
    )
    .unwrap();
    // A rule settled by the indirect commands' safe forms alone is the caller's in
    // the docs of the generated methods, which take any buffer.
    let form = "by the safe forms over an `IndirectBuffer` only: ";
    let status: std::collections::BTreeMap<&str, &str> = report["rules"]
        .as_array()
        .unwrap()
        .iter()
        .map(|r| {
            let by_form = r["mechanism"].as_str().is_some_and(|m| m.starts_with(form));
            let status = if by_form {
                "user"
            } else {
                r["status"].as_str().unwrap()
            };
            (r["vuid"].as_str().unwrap(), status)
        })
        .collect();
    let mut seen = 0;
    for file in sources(&root.join("generated/src/generated")) {
        let text = std::fs::read_to_string(&file).unwrap();
        for line in text.lines() {
            let Some(rest) = line.strip_prefix("- `VUID-") else {
                continue;
            };
            let Some((vuid, after)) = rest.split_once("` (*") else {
                continue;
            };
            let vuid = format!("VUID-{vuid}");
            let (mark, text) = after
                .split_once("): ")
                .expect("a rule's text after its mark");
            let mark = mark.split('*').next().unwrap();
            let expected = match status.get(vuid.as_str()) {
                Some(&"user") => "yours",
                Some(&"dynamic") => "checked",
                Some(&"static") => "by the types",
                other => panic!("{vuid} is in the docs but the report has {other:?}"),
            };
            assert_eq!(mark, expected, "{vuid} in {}", file.display());
            assert!(
                text.split_whitespace().count() >= 3,
                "{vuid}: no text in {}",
                file.display()
            );
            seen += 1;
        }
    }
    assert!(seen > 5000, "{seen} rules in the docs");
}

/// A command that may defer (`vkCreateRayTracingPipelinesKHR`, the host
/// acceleration-structure and micromap builds and copies) keeps reading its arguments
/// and writing its outputs until its deferred operation completes, after the method's
/// storage is gone. No method but the operation's own takes a deferred operation:
/// each such command is called with `VK_NULL_HANDLE`, and the report settles the
/// rules about the operation statically.
#[test]
fn no_method_lets_a_command_defer_past_its_return() {
    #[derive(Default)]
    struct Methods {
        receiver: String,
        taking: Vec<String>,
        passing_null: usize,
    }
    impl<'ast> Visit<'ast> for Methods {
        fn visit_item_impl(&mut self, i: &'ast syn::ItemImpl) {
            let ty = &i.self_ty;
            self.receiver = quote::quote!(#ty).to_string();
            syn::visit::visit_item_impl(self, i);
        }
        fn visit_impl_item_fn(&mut self, f: &'ast syn::ImplItemFn) {
            let inputs = &f.sig.inputs;
            // The operation's own commands (join, result, concurrency) take it.
            if quote::quote!(#inputs)
                .to_string()
                .contains("DeferredOperationKHR")
                && !f.sig.ident.to_string().contains("deferred_operation")
            {
                self.taking
                    .push(format!("{}::{}", self.receiver, f.sig.ident));
            }
            let body = &f.block;
            if quote::quote!(#body)
                .to_string()
                .contains("vk :: DeferredOperationKHR :: null ()")
            {
                self.passing_null += 1;
            }
        }
    }
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    let mut methods = Methods::default();
    for file in sources(&root.join("generated/src/generated/commands")) {
        let text = std::fs::read_to_string(&file).unwrap();
        methods.visit_file(&syn::parse_file(&text).expect("generated code parses"));
    }
    assert_eq!(methods.taking, Vec::<String>::new());
    // The unchecked twins of the 3 acceleration-structure copies, the host build, the
    // 4 micromap builds and copies and the ray-tracing pipelines.
    assert!(methods.passing_null >= 9, "{}", methods.passing_null);

    let report: serde_json::Value = serde_json::from_str(
        &std::fs::read_to_string(root.join("generated/validation.json")).unwrap(),
    )
    .unwrap();
    let deferred: Vec<(&str, &str)> = report["rules"]
        .as_array()
        .unwrap()
        .iter()
        .map(|r| (r["vuid"].as_str().unwrap(), r["status"].as_str().unwrap()))
        .filter(|(vuid, _)| vuid.contains("-deferredOperation-"))
        .collect();
    assert!(deferred.len() >= 30, "{deferred:?}");
    for (vuid, status) in deferred {
        assert_eq!(status, "static", "{vuid}");
    }
}
