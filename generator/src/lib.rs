//! `tuff-gen`: reads the Khronos Vulkan registry (`vk.xml`) and its valid-usage rules
//! (`validusage.json`) and writes the `tuff` crate's generated code together with a
//! validation coverage report.
//!
//! The generator is a pipeline of passes with plain data between them:
//!
//! 1. [`registry`]: parse the files into plain Rust data.
//! 2. [`model`]: resolve handles, commands, structs and the conditions under which
//!    each exists, and select the emitted API from the [`config`].
//! 3. [`validity`]: derive every implicit rule, attach and classify the explicit ones.
//! 4. [`plan`]: decide, once, every command's and struct's shape, the dynamic checks,
//!    and how each rule is settled.
//! 5. [`emit`]: render the plans as Rust; [`report`]: tally the plans' records into
//!    `VALIDATION.md`, `validation.json` and an SVG.
//!
//! Each pass imports only those before it ([`names`] is the shared spelling of
//! registry names in Rust); `tests/generator_layers.rs` holds that.
//!
//! ```no_run
//! use tuff_gen::{generate, Options};
//! let opts = Options::pinned();
//! let generation = generate(&opts)?;
//! tuff_gen::output::write_all(&opts.out, &generation.files)?;
//! # Ok::<(), tuff_gen::Error>(())
//! ```

#![warn(missing_docs)]

pub mod cli;
pub mod config;
pub mod diff;
pub mod emit;
pub mod error;
pub mod model;
pub mod names;
pub mod output;
pub mod plan;
pub mod registry;
pub mod report;
pub mod validity;

pub use error::{Error, Result};

use std::path::{Path, PathBuf};

/// Where the inputs are and where the output goes.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Options {
    /// `vk.xml`.
    pub registry: PathBuf,
    /// `validusage.json`, or `None` to derive implicit rules only.
    pub validusage: Option<PathBuf>,
    /// The config file (`tuff-gen.toml`).
    pub config: PathBuf,
    /// The output folder (`generated/`).
    pub out: PathBuf,
    /// Accept a validusage.json of another version than vk.xml.
    pub allow_version_mismatch: bool,
    /// Write an output that emits fewer items than the output folder holds.
    pub allow_shrink: bool,
}

impl Options {
    /// The repository's pinned inputs and its `generated/` folder.
    pub fn pinned() -> Options {
        let root = workspace_root();
        Options {
            registry: root.join("vk.xml"),
            validusage: Some(root.join("validusage.json")),
            config: root.join("tuff-gen.toml"),
            out: root.join("generated"),
            allow_version_mismatch: false,
            allow_shrink: false,
        }
    }
}

/// The repository root this generator was built in.
pub fn workspace_root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .parent()
        .map_or_else(|| PathBuf::from("."), Path::to_owned)
}

/// How many items the crate defines itself because ash lacks them.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct Delta {
    /// Structs.
    pub structs: usize,
    /// Other types: unions, enums, flags types and handles.
    pub types: usize,
    /// Constants: core versions' `API_VERSION_1_<m>`, array sizes, and the enum
    /// values ash lacks by name (structure types included).
    pub constants: usize,
    /// Commands of extensions ash lacks, in the crate's own function tables.
    pub commands: usize,
    /// Those extensions.
    pub extensions: usize,
}

impl Delta {
    /// What the layout test compares with the C headers: every type and constant.
    pub fn laid_out(&self) -> usize {
        self.structs + self.types + self.constants
    }
}

/// What a run produced, before anything is written.
#[derive(Debug, Clone)]
pub struct Generation {
    /// Every file of the output, relative to the output folder.
    pub files: Vec<emit::OutputFile>,
    /// Registry version.
    pub version: String,
    /// The emitted API's coverage table.
    pub emitted: report::Table,
    /// The whole registry's coverage table.
    pub registry: report::Table,
    /// Derived against listed implicit rules, when validusage.json was given.
    pub comparison: Option<validity::Comparison>,
    /// The extensions the config wants that the reference registry lacks or
    /// defines otherwise, with the reason.
    pub left_out: Vec<model::reference::LeftOut>,
    /// Registry shapes read by the toolchain's convention where the registry says
    /// otherwise (`validity::implicit::bitmask_shape_notes`): warnings to print.
    pub shape_notes: Vec<String>,
    /// What the registry has and ash lacks that the crate defines itself in ash's
    /// style (`src/generated/delta.rs`): structs, and constants (`API_VERSION_1_<m>`
    /// and enum values).
    pub delta: Delta,
}

/// The rules as they apply in programs that enable only what the safe constructors
/// allow. Which extensions those are depends on the checks the plan can make, and
/// those on which rules apply (a rule filed under the absence of an extension is
/// read, and checked, only where that extension cannot be enabled), so the two are
/// decided together: plan with everything the config emits, then again with what
/// that plan allows, until the allowed set stays the same (a few rounds at most).
pub fn enabled_validity(
    model: &model::Model,
    vu: Option<&registry::ValidUsage>,
) -> validity::Validity {
    let mut reach = model.enabled.clone();
    for _ in 0..4 {
        let validity = validity::analyze_with(model, vu, &reach);
        let allowed = {
            let cx = plan::Context::new(model, &validity);
            plan::Plans::build(&cx).enabling.allowed
        };
        if allowed == reach {
            return validity;
        }
        reach = allowed;
    }
    validity::analyze_with(model, vu, &reach)
}

/// The `.rs` files under the config's `scene_sources`, in path order, each with its
/// path relative to the config's folder and its text, read once for every scan. A
/// folder that cannot be read names nothing.
fn scene_sources(config_path: &Path, config: &config::Config) -> Vec<(String, String)> {
    let base = config_path.parent().unwrap_or(Path::new("."));
    let mut files = Vec::new();
    let mut todo: Vec<PathBuf> = config.scene_sources.iter().map(|d| base.join(d)).collect();
    while let Some(path) = todo.pop() {
        if let Ok(entries) = std::fs::read_dir(&path) {
            todo.extend(entries.filter_map(|e| e.ok().map(|e| e.path())));
        } else if path.extension().is_some_and(|e| e == "rs") {
            files.push(path);
        }
    }
    files.sort();
    files
        .into_iter()
        .map(|path| {
            let text = std::fs::read_to_string(&path).unwrap_or_default();
            let shown = path
                .strip_prefix(base)
                .unwrap_or(&path)
                .to_string_lossy()
                .replace('\\', "/");
            (shown, text)
        })
        .collect()
}

/// The identifier `text` ends with (empty if none).
fn trailing_ident(text: &str) -> &str {
    let start = text
        .rfind(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))
        .map_or(0, |at| at + 1);
    &text[start..]
}

/// The method names the scene sources call (every `.name(`).
fn scene_calls(sources: &[(String, String)]) -> std::collections::BTreeSet<String> {
    let mut out = std::collections::BTreeSet::new();
    for (_, text) in sources {
        for (i, _) in text.match_indices('(') {
            let name = trailing_ident(&text[..i]);
            let before = text[..i - name.len()]
                .chars()
                .rev()
                .find(|c| !c.is_whitespace());
            if !name.is_empty() && before == Some('.') {
                out.insert(name.to_owned());
            }
        }
    }
    out
}

/// For the docs: the first statement of the scene sources that calls each method
/// (`.create_buffer(`) or makes each struct (`BufferCreateInfo::new(`), files in
/// path order. Files that name `ash` are the raw-ash programs, whose calls are ash's,
/// and are skipped.
fn scene_snippets(
    sources: &[(String, String)],
) -> std::collections::BTreeMap<String, Vec<plan::Snippet>> {
    let mut out = std::collections::BTreeMap::new();
    for (shown, text) in sources {
        if text.contains("ash::") || text.contains("use ash") {
            continue;
        }
        let lines: Vec<&str> = text.lines().collect();
        for (i, line) in lines.iter().enumerate() {
            let code = line.split("//").next().unwrap_or("");
            for (at, _) in code.match_indices('(') {
                let name = trailing_ident(&code[..at]);
                let before = &code[..at - name.len()];
                let (key, receiver) = if let Some(on) = before.strip_suffix('.') {
                    (name, trailing_ident(on))
                } else if name == "new" && before.ends_with("::") {
                    let ty = trailing_ident(&before[..before.len() - 2]);
                    if !ty.starts_with(|c: char| c.is_ascii_uppercase()) {
                        continue;
                    }
                    (ty, "")
                } else {
                    continue;
                };
                // One example per receiver spelling is enough to choose from.
                let seen = |s: &plan::Snippet| s.receiver == receiver;
                if key.is_empty() || out.get(key).is_some_and(|v: &Vec<_>| v.iter().any(seen)) {
                    continue;
                }
                if let Some(code) = statement(&lines, i) {
                    let snippet = plan::Snippet {
                        file: shown.clone(),
                        line: i + 1,
                        code,
                        receiver: receiver.to_owned(),
                    };
                    out.entry(key.to_owned()).or_default().push(snippet);
                }
            }
        }
    }
    out
}

/// The statement around line `i`: back to the end of the previous one, then on
/// until its brackets close at a `;` (or at a block it opens, shown closed), at
/// most 16 lines, dedented.
fn statement(lines: &[&str], i: usize) -> Option<String> {
    let ends = |l: &str| {
        let t = l.split("//").next().unwrap_or("").trim();
        t.is_empty() || t.ends_with(';') || t.ends_with('{') || t.ends_with('}')
    };
    let mut start = i;
    while start > 0 && i - start < 6 && !ends(lines[start - 1]) {
        start -= 1;
    }
    // The comments right above it (a `// SAFETY:` justification among them).
    while start > 0 && i - start < 12 && lines[start - 1].trim_start().starts_with("//") {
        start -= 1;
    }
    // Bracket depth from `start`, outside string literals and comments.
    let mut depth = 0i32;
    let mut end = start;
    let mut opened_block = false;
    loop {
        let code = lines[end].split("//").next().unwrap_or("");
        let mut in_str = false;
        let mut prev = ' ';
        for c in code.chars() {
            match c {
                '"' if prev != '\\' => in_str = !in_str,
                '(' | '[' | '{' if !in_str => depth += 1,
                ')' | ']' | '}' if !in_str => depth -= 1,
                _ => {}
            }
            prev = c;
        }
        let t = code.trim_end();
        // A tail expression ends where the next line closes what encloses it.
        let closes_next = lines
            .get(end + 1)
            .is_some_and(|n| n.trim_start().starts_with(['}', ')', ']']));
        if depth < 0 || (depth == 0 && (t.ends_with(';') || t.ends_with('}') || closes_next)) {
            break;
        }
        if depth == 1 && t.ends_with('{') && end >= i {
            opened_block = true;
            break;
        }
        if end + 1 >= lines.len() || end - start >= 15 {
            break;
        }
        end += 1;
    }
    let slice = &lines[start..=end];
    let indent = slice
        .iter()
        .filter(|l| !l.trim().is_empty())
        .map(|l| l.len() - l.trim_start().len())
        .min()
        .unwrap_or(0);
    let mut code = slice
        .iter()
        .map(|l| l.get(indent..).unwrap_or_else(|| l.trim_start()))
        .collect::<Vec<_>>()
        .join("\n");
    if opened_block {
        code.push_str("\n    // ...\n}");
    } else if depth != 0 {
        // Cut short, or the tail of an enclosing expression: not a statement that
        // reads on its own.
        return None;
    }
    Some(code)
}

/// Run every pass and return the files to write. Reads the inputs; writes nothing.
pub fn generate(opts: &Options) -> Result<Generation> {
    let config = config::Config::load(&opts.config)?;
    let reg = registry::load_registry(&opts.registry)?;
    let vu = match &opts.validusage {
        Some(path) => Some(registry::load_validusage(path)?),
        None => None,
    };
    if let (Some(vu), Some(path)) = (&vu, &opts.validusage) {
        if vu.api_version != reg.version && !opts.allow_version_mismatch {
            return Err(Error::VersionMismatch {
                registry: opts.registry.clone(),
                registry_version: reg.version.clone(),
                validusage: path.clone(),
                validusage_version: vu.api_version.clone(),
            });
        }
    }
    let reference = match config.reference_path(&opts.config) {
        Some(path) => Some(registry::load_registry(&path)?),
        None => None,
    };
    let sources = scene_sources(&opts.config, &config);
    let inputs = Inputs {
        registry_path: &opts.registry,
        registry: &reg,
        reference: reference.as_ref(),
        validusage: vu.as_ref(),
        config: &config,
        config_path: &opts.config,
        sources: &sources,
    };
    let mut generation = passes(&inputs)?;
    standalone(&opts.out, &mut generation.files)?;
    Ok(generation)
}

/// The inputs of the passes, read.
pub(crate) struct Inputs<'a> {
    pub(crate) registry_path: &'a Path,
    pub(crate) registry: &'a registry::Registry,
    pub(crate) reference: Option<&'a registry::Registry>,
    pub(crate) validusage: Option<&'a registry::ValidUsage>,
    pub(crate) config: &'a config::Config,
    pub(crate) config_path: &'a Path,
    pub(crate) sources: &'a [(String, String)],
}

/// Every pass from the model to the rendered files, on inputs already read.
pub(crate) fn passes(inputs: &Inputs) -> Result<Generation> {
    let config = inputs.config;
    let model = model::Model::build(
        inputs.registry,
        inputs.reference,
        config,
        inputs.config_path,
    )?;
    // The per-command facts of the hazard tracker must be the sync tables' own.
    if let Some(tables) = &model.sync {
        plan::accesses::check(tables).map_err(|message| Error::BadRegistry {
            path: inputs.registry_path.to_owned(),
            message: format!(
                "the hazard tracker's facts (plan/accesses.rs) disagree with <sync> of {}: {message}",
                tables.version
            ),
        })?;
    }
    let validity = enabled_validity(&model, inputs.validusage);
    let mut cx = plan::Context::new(&model, &validity);
    let sources = inputs.sources;
    cx.examples = scene_snippets(sources);
    let plans = plan::Plans::build(&cx);
    let emission = emit::emit(&plans);
    let mut report = report::build(&model, &validity, &plans.records);
    // The commands the scenes use: called by their ash name in the raw-ash programs,
    // or by their method, on a receiver of its type, in the tuff ones (as the docs'
    // examples are chosen).
    let ash_calls = scene_calls(sources);
    let scenes: std::collections::BTreeSet<String> = plans
        .methods
        .iter()
        .filter(|r| {
            ash_calls.contains(&names::command_fn(model.spelling(&r.command)))
                || cx
                    .example(&r.method, Some(names::receiver_type(&model, &r.command)))
                    .is_some()
        })
        .map(|r| r.command.clone())
        .collect();
    report.add_methods(
        &plans.methods,
        &plans.safety,
        &plans.enabling,
        &scenes,
        |command| model.home(command),
    );
    let mut files = emission.files;
    files.extend(report::render(&report));
    files.push(emit::OutputFile {
        path: ITEMS_FILE.into(),
        contents: items_list(&model),
    });
    Ok(Generation {
        files,
        version: model.version.clone(),
        emitted: report.emitted,
        registry: report.registry,
        comparison: validity.comparison.clone(),
        left_out: model.left_out.clone(),
        shape_notes: validity::implicit::bitmask_shape_notes(&model),
        delta: Delta {
            structs: model
                .delta
                .iter()
                .filter(|n| model.category(n) == Some(model::Kind::Struct))
                .count(),
            types: model
                .delta
                .iter()
                .filter(|n| match model.category(n) {
                    Some(model::Kind::Union | model::Kind::Handle) => true,
                    Some(model::Kind::Enum) => !n.contains("FlagBits"),
                    _ => false,
                })
                .count()
                + model.delta_flags().len(),
            commands: model.delta_commands.len(),
            extensions: model.own_extensions.len(),
            constants: model.own_tables.len()
                + model.delta_constants().count()
                + model.delta_sizes.len(),
        },
    })
}

/// The fuzz targets' bodies (`fuzz/`), here so that the test suite replays their
/// corpus and every crash they found on the stable toolchain (`tests/fuzz_corpus.rs`).
#[doc(hidden)]
pub mod fuzzing;

/// For an output folder other than the repository's `generated/`, what makes it a
/// crate that builds where it is: the crate's hand-written modules, copied from the
/// repository the generator was built in, and the runtime named by its absolute
/// path there.
fn standalone(out: &Path, files: &mut Vec<emit::OutputFile>) -> Result<()> {
    let root = workspace_root();
    let template = root.join("generated");
    let same = |a: &Path, b: &Path| match (a.canonicalize(), b.canonicalize()) {
        (Ok(a), Ok(b)) => a == b,
        _ => false,
    };
    if out.as_os_str().is_empty() || same(out, &template) {
        return Ok(());
    }
    let runtime = root.join("runtime");
    for f in files
        .iter_mut()
        .filter(|f| f.path == Path::new("Cargo.toml"))
    {
        f.contents = f.contents.replace(
            "tuff-runtime = { path = \"../runtime\" }",
            &format!(
                "tuff-runtime = {{ path = {:?} }}",
                runtime.display().to_string()
            ),
        );
    }
    let generated = template.join(emit::GENERATED_DIR);
    let mut stack = vec![template.join("src")];
    while let Some(dir) = stack.pop() {
        let entries = std::fs::read_dir(&dir).map_err(|source| Error::Read {
            path: dir.clone(),
            source,
        })?;
        for entry in entries {
            let path = entry
                .map_err(|source| Error::Read {
                    path: dir.clone(),
                    source,
                })?
                .path();
            if path == generated {
                continue;
            }
            if path.is_dir() {
                stack.push(path);
            } else if path.extension().is_some_and(|e| e == "rs") {
                let contents = std::fs::read_to_string(&path).map_err(|source| Error::Read {
                    path: path.clone(),
                    source,
                })?;
                let rel = path.strip_prefix(&template).unwrap_or(&path).to_owned();
                files.push(emit::OutputFile {
                    path: rel,
                    contents,
                });
            }
        }
    }
    Ok(())
}

/// The output's list of what it emits, which the next run compares with.
pub const ITEMS_FILE: &str = "emitted-items.txt";

/// Every command, struct and handle the output emits, one per line, sorted, under a
/// line saying what the file is.
fn items_list(model: &model::Model) -> String {
    let mut s = String::from(
        "# @generated by tuff-gen: the commands, structs and handles this crate emits. A \
         run that would emit fewer fails unless given --allow-shrink.\n",
    );
    for name in &model.emitted {
        let kept = model.commands.contains_key(name)
            || model.types.get(name).is_some_and(|t| {
                matches!(t.category, Some(model::Kind::Struct | model::Kind::Handle))
            });
        if kept {
            s.push_str(name);
            s.push('\n');
        }
    }
    s
}

/// Fails, naming what would go, when `files` emit fewer items than the output folder
/// `out` lists now (its `emitted-items.txt`; a folder without one has nothing to lose).
pub fn check_shrink(out: &Path, files: &[emit::OutputFile]) -> Result<()> {
    let Ok(old) = std::fs::read_to_string(out.join(ITEMS_FILE)) else {
        return Ok(());
    };
    let new: std::collections::BTreeSet<&str> = files
        .iter()
        .find(|f| f.path == Path::new(ITEMS_FILE))
        .map(|f| f.contents.lines().filter(|l| !l.starts_with('#')).collect())
        .unwrap_or_default();
    let lost: Vec<&str> = old
        .lines()
        .filter(|l| !l.starts_with('#') && !l.trim().is_empty() && !new.contains(l))
        .collect();
    if lost.is_empty() {
        return Ok(());
    }
    let mut sample = lost.iter().take(8).copied().collect::<Vec<_>>().join(", ");
    if lost.len() > 8 {
        sample.push_str(", ...");
    }
    Err(Error::Shrink {
        out: out.to_owned(),
        count: lost.len(),
        sample,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn scene_calls_are_the_method_calls_of_the_scene_sources() {
        let dir = tempfile::tempdir().expect("temp dir");
        std::fs::create_dir(dir.path().join("scenes")).expect("folder");
        std::fs::write(
            dir.path().join("scenes/a.rs"),
            "fn f() { let b = device.create_buffer(&info)?; helper(b); x.\ncmd_draw(3, 1, 0, 0); }",
        )
        .expect("source");
        std::fs::write(dir.path().join("scenes/notes.txt"), "device.not_rust()").expect("text");
        let config = config::Config {
            api_version: "1.3".into(),
            extensions: vec![],
            all_extensions: false,
            reference_registry: None,
            scene_sources: vec!["scenes".into(), "missing".into()],
        };
        let calls = scene_calls(&scene_sources(&dir.path().join("tuff-gen.toml"), &config));
        assert_eq!(
            calls.into_iter().collect::<Vec<_>>(),
            ["cmd_draw", "create_buffer"]
        );
    }

    #[test]
    fn snippets_are_whole_statements_of_the_tuff_programs() {
        let dir = tempfile::tempdir().expect("temp dir");
        std::fs::create_dir(dir.path().join("src")).expect("folder");
        let tuff = "fn f() {\n    // Why it holds.\n    let info = tuff::BufferCreateInfo::new()\n        .size(64);\n    let b = device\n        .create_buffer(&info)?;\n    items.iter().map(|i| {\n        Ok(x.cmd_draw(i, 1, 0, 0))\n    })\n}\n";
        std::fs::write(dir.path().join("src/a.rs"), tuff).expect("source");
        // A raw-ash program's calls are ash's, not tuff's.
        std::fs::write(
            dir.path().join("src/b.rs"),
            "use ash::vk;\nfn g() { device.destroy_buffer(b, None); }\n",
        )
        .expect("source");
        let config = config::Config {
            api_version: "1.3".into(),
            scene_sources: vec!["src".into()],
            ..Default::default()
        };
        let s = scene_snippets(&scene_sources(&dir.path().join("tuff-gen.toml"), &config));
        assert_eq!(
            s["BufferCreateInfo"][0].code,
            "// Why it holds.\nlet info = tuff::BufferCreateInfo::new()\n    .size(64);"
        );
        assert_eq!(s["BufferCreateInfo"][0].line, 3);
        assert_eq!(s["BufferCreateInfo"][0].file, "src/a.rs");
        assert_eq!(
            s["create_buffer"][0].code,
            "let b = device\n    .create_buffer(&info)?;"
        );
        // A tail expression closed by the next line stands alone.
        assert_eq!(s["cmd_draw"][0].code, "Ok(x.cmd_draw(i, 1, 0, 0))");
        // What each call is made on, to tell methods of one name apart.
        assert_eq!(s["cmd_draw"][0].receiver, "x");
        assert_eq!(s["create_buffer"][0].receiver, "");
        assert!(!s.contains_key("destroy_buffer"));
    }
}
