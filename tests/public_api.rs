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
