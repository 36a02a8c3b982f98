//! The `tuff-gen` command line, as a library function so that tests can run it with
//! arguments and read its exit code and messages without spawning a process.

use crate::{generate, output, Options};
use clap::Parser;
use std::io::Write;
use std::path::PathBuf;

/// Generate the tuff crate and its validation coverage report from the Vulkan registry.
#[derive(Parser, Debug)]
#[command(version, about, args_conflicts_with_subcommands = true)]
struct Cli {
    #[command(subcommand)]
    command: Option<Command>,
    /// vk.xml to read [default: the pinned vk.xml at the repository root]
    #[arg(long)]
    registry: Option<PathBuf>,
    /// validusage.json to read [default: validusage.json beside the registry, when it exists]
    #[arg(long, conflicts_with = "no_validusage")]
    validusage: Option<PathBuf>,
    /// Derive implicit rules only; explicit rules are reported as unknown
    #[arg(long)]
    no_validusage: bool,
    /// Accept a validusage.json whose version differs from vk.xml's
    #[arg(long)]
    allow_version_mismatch: bool,
    /// Config file [default: tuff-gen.toml at the repository root]
    #[arg(long)]
    config: Option<PathBuf>,
    /// Output folder [default: generated/ at the repository root]
    #[arg(long)]
    out: Option<PathBuf>,
    /// Write nothing; fail if the output folder differs from a fresh run
    #[arg(long)]
    check: bool,
    /// Write the output even if it emits fewer commands, structs or handles than the
    /// output folder holds now
    #[arg(long)]
    allow_shrink: bool,
}

#[derive(clap::Subcommand, Debug)]
enum Command {
    /// Compare two registries for a version bump: items and extensions added and
    /// removed, valid-usage rules added, removed and reworded, and how the emitted
    /// API's coverage and method signatures change. Writes nothing.
    Diff {
        /// The older vk.xml (its validusage.json is read from beside it, when there)
        old: PathBuf,
        /// The newer vk.xml (likewise)
        new: PathBuf,
        /// Config both are generated with [default: tuff-gen.toml at the repository root]
        #[arg(long)]
        config: Option<PathBuf>,
        /// Print JSON instead of Markdown
        #[arg(long)]
        json: bool,
    },
}

/// Run the command line with `args` (the first is the program name). Messages go to
/// `out` and `err`; the return value is the process exit code: 0 on success, 1 on a
/// generator error, 2 on a usage error.
pub fn run<I, T>(args: I, out: &mut dyn Write, err: &mut dyn Write) -> i32
where
    I: IntoIterator<Item = T>,
    T: Into<std::ffi::OsString> + Clone,
{
    let cli = match Cli::try_parse_from(args) {
        Ok(cli) => cli,
        Err(e) => {
            let code = e.exit_code();
            let text = e.render().to_string();
            let _ = if code == 0 {
                write!(out, "{text}")
            } else {
                write!(err, "{text}")
            };
            return code;
        }
    };
    let pinned = Options::pinned();
    if let Some(Command::Diff {
        old,
        new,
        config,
        json,
    }) = &cli.command
    {
        let config = config.clone().unwrap_or(pinned.config);
        let result = crate::diff::diff(
            &crate::diff::Side::beside(old),
            &crate::diff::Side::beside(new),
            &config,
        );
        return match result {
            Ok(d) => {
                let text = if *json {
                    serde_json::to_string_pretty(&d).unwrap_or_default()
                } else {
                    crate::diff::markdown(&d)
                };
                let _ = writeln!(out, "{text}");
                0
            }
            Err(e) => {
                let _ = writeln!(err, "tuff-gen diff: error: {e}");
                1
            }
        };
    }
    let custom_inputs = cli.registry.is_some()
        || cli.config.is_some()
        || cli.validusage.is_some()
        || cli.no_validusage
        || cli.allow_version_mismatch;
    if custom_inputs && cli.out.is_none() && !cli.check {
        let _ = writeln!(
            err,
            "tuff-gen: error: these options change what is generated; pass --out to say \
             where to write it (--out {} replaces the committed output)",
            pinned.out.display()
        );
        return 2;
    }
    let registry = cli.registry.clone().unwrap_or(pinned.registry);
    let validusage = if cli.no_validusage {
        None
    } else if let Some(v) = cli.validusage {
        Some(v)
    } else {
        let beside = registry.with_file_name("validusage.json");
        if beside.exists() {
            Some(beside)
        } else {
            let _ = writeln!(
                err,
                "tuff-gen: no validusage.json beside {}; deriving implicit rules only",
                registry.display()
            );
            None
        }
    };
    let opts = Options {
        registry,
        validusage,
        config: cli.config.unwrap_or(pinned.config),
        out: cli.out.unwrap_or(pinned.out),
        allow_version_mismatch: cli.allow_version_mismatch,
        allow_shrink: cli.allow_shrink,
    };
    let result = generate(&opts).and_then(|g| {
        if cli.check {
            output::check(&opts.out, &g.files)?;
        } else {
            if !opts.allow_shrink {
                crate::check_shrink(&opts.out, &g.files)?;
            }
            output::write_all(&opts.out, &g.files)?;
        }
        Ok(g)
    });
    match result {
        Ok(g) => {
            let verb = if cli.check {
                "is up to date"
            } else {
                "written"
            };
            let _ = writeln!(
                out,
                "tuff-gen: Vulkan {}: {} {verb} ({} files); emitted API: {} rules, whole registry: {} rules",
                g.version,
                opts.out.display(),
                g.files.len(),
                g.emitted.total(),
                g.registry.total()
            );
            for l in &g.left_out {
                let _ = writeln!(out, "tuff-gen: left out {}: {}", l.name, l.reason);
            }
            if g.delta.laid_out() > 0 {
                let _ = writeln!(
                    out,
                    "tuff-gen: delta: {} items ash lacks defined in ash's style ({} structs, {} other types, {} constants; src/generated/delta.rs); {} commands of {} extensions ash lacks, in the crate's own function tables",
                    g.delta.laid_out(),
                    g.delta.structs,
                    g.delta.types,
                    g.delta.constants,
                    g.delta.commands,
                    g.delta.extensions
                );
            }
            for note in &g.shape_notes {
                let _ = writeln!(out, "tuff-gen: warning: {note}");
            }
            if let Some(c) = &g.comparison {
                let _ = writeln!(
                    out,
                    "tuff-gen: implicit rules: {} derived, {} listed, {} both, {} only derived, {} only listed",
                    c.derived,
                    c.listed,
                    c.both,
                    c.only_derived.len(),
                    c.only_listed.len()
                );
            }
            0
        }
        Err(e) => {
            let _ = writeln!(err, "tuff-gen: error: {e}");
            1
        }
    }
}
