//! The generator's passes depend on each other in one direction only: a test over
//! the paths its source names (`use` items and paths in code; `quote!` bodies are
//! the generated crate's paths and are not read). A cycle between the passes, or
//! between the modules of one pass, fails here with the modules that form it.

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};
use syn::visit::Visit;

/// Every `.rs` file under `dir`, recursively.
fn files(dir: &Path, out: &mut Vec<PathBuf>) {
    for entry in std::fs::read_dir(dir).expect("a source folder") {
        let path = entry.expect("entry").path();
        if path.is_dir() {
            files(&path, out);
        } else if path.extension().is_some_and(|e| e == "rs") {
            out.push(path);
        }
    }
}

/// The module path of a source file: `emit/commands.rs` -> `["emit", "commands"]`.
fn module_of(src: &Path, file: &Path) -> Vec<String> {
    let rel = file
        .strip_prefix(src)
        .expect("under src")
        .with_extension("");
    let mut parts: Vec<String> = rel
        .components()
        .map(|c| c.as_os_str().to_string_lossy().into_owned())
        .collect();
    if parts.last().is_some_and(|p| p == "mod" || p == "lib") {
        parts.pop();
    }
    parts
}

/// The crate-absolute module paths a file names, as written with `crate::` or
/// `super::` (resolved against the file's module).
#[derive(Default)]
struct Names {
    here: Vec<String>,
    found: BTreeSet<Vec<String>>,
}

impl Names {
    fn add(&mut self, segments: Vec<String>) {
        let mut path = match segments.first().map(String::as_str) {
            Some("crate") => Vec::new(),
            Some("super") => self.here[..self.here.len().saturating_sub(1)].to_vec(),
            Some("self") => self.here.clone(),
            _ => return,
        };
        let mut rest = segments.into_iter().skip(1).peekable();
        while rest.peek().is_some_and(|s| s == "super") {
            path.pop();
            rest.next();
        }
        path.extend(rest);
        self.found.insert(path);
    }
}

impl<'a> Visit<'a> for Names {
    fn visit_path(&mut self, p: &'a syn::Path) {
        self.add(p.segments.iter().map(|s| s.ident.to_string()).collect());
        syn::visit::visit_path(self, p);
    }

    fn visit_item_use(&mut self, u: &'a syn::ItemUse) {
        fn walk(tree: &syn::UseTree, prefix: Vec<String>, out: &mut Vec<Vec<String>>) {
            match tree {
                syn::UseTree::Path(p) => {
                    let mut next = prefix;
                    next.push(p.ident.to_string());
                    walk(&p.tree, next, out);
                }
                syn::UseTree::Name(n) => {
                    let mut next = prefix;
                    next.push(n.ident.to_string());
                    out.push(next);
                }
                syn::UseTree::Rename(r) => {
                    let mut next = prefix;
                    next.push(r.ident.to_string());
                    out.push(next);
                }
                syn::UseTree::Glob(_) => out.push(prefix),
                syn::UseTree::Group(g) => {
                    for t in &g.items {
                        walk(t, prefix.clone(), out);
                    }
                }
            }
        }
        let mut paths = Vec::new();
        walk(&u.tree, Vec::new(), &mut paths);
        for p in paths {
            self.add(p);
        }
    }
}

/// Edges between the generator's modules at `depth` under `within` (the crate root
/// when empty): module -> modules it names, self-edges left out.
fn edges(within: &[&str], depth: usize) -> BTreeMap<String, BTreeSet<String>> {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("../generator/src");
    edges_in(&src, within, depth)
}

/// [`edges`] over the crate whose sources are under `src`; a folder named
/// `generated` (the emitted modules of the `tuff` crate) is not read.
fn edges_in(src: &Path, within: &[&str], depth: usize) -> BTreeMap<String, BTreeSet<String>> {
    let mut all = Vec::new();
    files(src, &mut all);
    all.retain(|f| !f.starts_with(src.join("generated")));
    let modules: BTreeSet<String> = all
        .iter()
        .map(|f| module_of(src, f))
        .filter(|m| m.len() > depth && m[..depth].iter().eq(within.iter()))
        .map(|m| m[depth].clone())
        .collect();
    let mut out: BTreeMap<String, BTreeSet<String>> = BTreeMap::new();
    for file in &all {
        let here = module_of(src, file);
        if here.len() <= depth || !here[..depth].iter().eq(within.iter()) {
            continue;
        }
        let text = std::fs::read_to_string(file).expect("source");
        let ast = syn::parse_file(&text).expect("source parses");
        let mut names = Names {
            here: here.clone(),
            ..Names::default()
        };
        names.visit_file(&ast);
        for path in names.found {
            if path.len() > depth
                && path[..depth].iter().eq(within.iter())
                && modules.contains(&path[depth])
                && path[depth] != here[depth]
            {
                out.entry(here[depth].clone())
                    .or_default()
                    .insert(path[depth].clone());
            }
        }
    }
    out
}

/// A cycle in `graph`, as the modules along it, if there is one.
fn cycle(graph: &BTreeMap<String, BTreeSet<String>>) -> Option<Vec<String>> {
    fn dfs(
        node: &str,
        graph: &BTreeMap<String, BTreeSet<String>>,
        stack: &mut Vec<String>,
        done: &mut BTreeSet<String>,
    ) -> Option<Vec<String>> {
        if let Some(i) = stack.iter().position(|n| n == node) {
            let mut c = stack[i..].to_vec();
            c.push(node.to_owned());
            return Some(c);
        }
        if done.contains(node) {
            return None;
        }
        stack.push(node.to_owned());
        for next in graph.get(node).into_iter().flatten() {
            if let Some(c) = dfs(next, graph, stack, done) {
                return Some(c);
            }
        }
        stack.pop();
        done.insert(node.to_owned());
        None
    }
    let mut done = BTreeSet::new();
    graph
        .keys()
        .find_map(|n| dfs(n, graph, &mut Vec::new(), &mut done))
}

fn assert_acyclic(within: &[&str]) -> BTreeMap<String, BTreeSet<String>> {
    let graph = edges(within, within.len());
    // The walk must find something, or a broken reader would pass every check.
    assert!(
        !within.is_empty() || graph.len() > 5,
        "the generator's passes name each other too little: {graph:?}"
    );
    if let Some(c) = cycle(&graph) {
        panic!(
            "import cycle in generator/src/{}: {}",
            within.join("/"),
            c.join(" -> ")
        );
    }
    graph
}

#[test]
fn the_passes_depend_one_way() {
    let graph = assert_acyclic(&[]);
    // The order the passes run in: each reads only those before it.
    let named = |from: &str, to: &str| graph.get(from).is_some_and(|s| s.contains(to));
    assert!(named("emit", "plan"), "{graph:?}");
    for (later, earlier) in [
        ("plan", "emit"),
        ("plan", "report"),
        ("validity", "plan"),
        ("model", "validity"),
        ("registry", "model"),
        // Renderers and plans read the model, never the registry pass's own data.
        ("emit", "registry"),
        ("plan", "registry"),
    ] {
        assert!(
            !named(later, earlier),
            "`{later}` imports `{earlier}`: {graph:?}"
        );
    }
}

#[test]
fn no_cycle_inside_a_pass() {
    for pass in ["plan", "emit", "model", "validity", "registry", "report"] {
        assert_acyclic(&[pass]);
    }
    // The plan's modules do name each other, so the walk is reading them.
    assert!(!edges(&["plan"], 1).is_empty());
}

#[test]
fn a_cycle_is_found() {
    let graph: BTreeMap<String, BTreeSet<String>> =
        [("a", vec!["b"]), ("b", vec!["c"]), ("c", vec!["a"])]
            .into_iter()
            .map(|(k, v)| (k.to_owned(), v.into_iter().map(str::to_owned).collect()))
            .collect();
    assert_eq!(cycle(&graph).map(|c| c.len()), Some(4));
}

/// Hand-written source files over this many lines hold more than one concern.
const MOST_LINES: usize = 1_500;

#[test]
fn no_hand_written_file_holds_more_than_one_concerns_worth() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    let mut all = Vec::new();
    for dir in [
        "generator/src",
        "generated/src",
        "runtime/src",
        "examples/src",
    ] {
        files(&root.join(dir), &mut all);
    }
    let emitted = root.join("generated/src/generated");
    let mut over = Vec::new();
    for file in all.iter().filter(|f| !f.starts_with(&emitted)) {
        let lines = std::fs::read_to_string(file)
            .expect("source")
            .lines()
            .count();
        let name = file
            .strip_prefix(&root)
            .expect("under root")
            .to_string_lossy()
            .into_owned();
        if lines > MOST_LINES {
            over.push(format!("{name}: {lines} lines (at most {MOST_LINES})"));
        }
    }
    assert!(over.is_empty(), "split these by concern: {over:#?}");
    // The walk reads the crate's hand-written files: the special cases are among them.
    assert!(all
        .iter()
        .any(|f| f.ends_with("generated/src/special/queue.rs")));
}

/// The `tuff` crate's hand-written modules depend on each other one way: the
/// records (`state/`) below the checks (`special/`), the recorder and the submission
/// code, and no cycle among them. Emitted modules are not read; a path through a
/// crate-root re-export (`crate::Device`) names no module and is not counted.
#[test]
fn the_crate_keeps_its_records_below_its_checks() {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("../generated/src");
    let graph = edges_in(&src, &[], 0);
    if let Some(c) = cycle(&graph) {
        panic!("the crate's modules import each other in a cycle: {c:?}");
    }
    let state = graph.get("state").cloned().unwrap_or_default();
    for above in [
        "special",
        "recorder",
        "submission",
        "validation",
        "memory",
        "present",
        "routine",
        "diagnostics",
    ] {
        assert!(
            !state.contains(above),
            "state/ imports `{above}`: {state:?}"
        );
    }
    // The walk reads the crate: the checks name the records they read.
    assert!(
        graph.get("special").is_some_and(|s| s.contains("state")),
        "{graph:?}"
    );
}
