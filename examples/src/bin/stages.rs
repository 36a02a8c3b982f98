//! The stage benchmark: what each stage of the teapots' frame costs through tuff,
//! against raw ash, raw ash under the validation layer, and vulkano (a build with the
//! `vulkano` feature; headless only).
//!
//! `stages bench` runs every variant over every configuration, interleaved (each
//! round runs each configuration's variants one after another, so drift hits all
//! alike), each run a child process of the binary built for it, and writes the raw
//! samples (CSV), the tables (Markdown) and a chart (SVG). `stages run` is one such
//! child: one variant, one configuration, its frames' stage times as CSV on stdout.
//! `scripts/stage-bench.sh` builds the variants and runs it.

use anyhow::{bail, Context as _, Result};
use clap::{Parser, Subcommand};
use std::path::PathBuf;
use std::process::Command;
use tuff_examples::gpu::Gpu;
use tuff_examples::raw_ash::{Layer, Vulkan};
use tuff_examples::stages::report::{self, Row, VARIANTS};
use tuff_examples::stages::{ash_frames, tuff_frames, Run};

#[derive(Parser)]
struct Args {
    #[command(subcommand)]
    command: Cmd,
}

#[derive(Subcommand)]
enum Cmd {
    /// One variant, one configuration: prints `# device:`/`# driver:` lines and one CSV
    /// line of stage times (ns) per timed frame.
    Run {
        /// One of ash, tuff, tuff-auto, tuff-untracked, tuff-mt, tuff-checks,
        /// vulkano, ash-layer, ash-sync.
        #[arg(long)]
        variant: String,
        #[command(flatten)]
        config: RunArgs,
    },
    /// Every variant over every configuration, interleaved; writes
    /// `<out>/<label>.csv`, `.md` and `-<mode>.svg`.
    Bench {
        /// Where the results go.
        #[arg(long)]
        out: PathBuf,
        /// Names the files and titles the tables (the machine).
        #[arg(long)]
        label: String,
        /// The build of this binary with the `multi_thread` feature.
        #[arg(long)]
        mt: Option<PathBuf>,
        /// The build of this binary with the `implicit_checks` feature.
        #[arg(long)]
        checks: Option<PathBuf>,
        /// The build of this binary with `--cfg tuff_untracked` (no hazard tracker).
        #[arg(long)]
        untracked: Option<PathBuf>,
        /// The build of this binary with the `vulkano` feature (the vulkano peer,
        /// headless only).
        #[arg(long)]
        vulkano: Option<PathBuf>,
        /// This binary built at an earlier commit: its `tuff` runs, interleaved with
        /// this build's, as the variant `tuff-before` (what a change gained).
        #[arg(long)]
        before: Option<PathBuf>,
        /// Rounds over the variants.
        #[arg(long, default_value_t = 3)]
        rounds: u32,
        /// Teapot counts, each run with one uniform write per frame.
        #[arg(long, value_delimiter = ',', default_value = "1,100,10000")]
        counts: Vec<u32>,
        /// Uniform writes per frame of the extra configuration (100 teapots); 0 for none.
        #[arg(long, default_value_t = 1000)]
        many_writes: u32,
        /// Timed frames per run, and per run of 10,000 teapots.
        #[arg(long, default_value_t = 100)]
        frames: u32,
        #[arg(long, default_value_t = 100)]
        frames_10000: u32,
        /// Frames drawn before timing starts.
        #[arg(long, default_value_t = 5)]
        warmup: u32,
        /// Image side in pixels.
        #[arg(long, default_value_t = 256)]
        size: u32,
        /// Also in a window (needs an X server), besides headless.
        #[arg(long)]
        window: bool,
        /// Leave the layer variants out (a machine without the layer).
        #[arg(long)]
        no_layer: bool,
    },
    /// Rewrites the Markdown and SVG from a CSV that `bench` wrote.
    Report {
        /// The CSV.
        csv: PathBuf,
        /// Names the files and titles the tables.
        #[arg(long)]
        label: String,
    },
}

#[derive(clap::Args, Clone)]
struct RunArgs {
    #[arg(long, default_value_t = 100)]
    count: u32,
    #[arg(long, default_value_t = 1)]
    writes: u32,
    #[arg(long, default_value_t = 100)]
    frames: u32,
    #[arg(long, default_value_t = 5)]
    warmup: u32,
    #[arg(long, default_value_t = 256)]
    size: u32,
    #[arg(long)]
    window: bool,
    /// Check the run itself: the validation layer with synchronization validation on
    /// for tuff and raw ash alike (any message fails the run). Not for timing.
    /// Not for vulkano, which has its own checks.
    #[arg(long)]
    validate: bool,
    /// Writes the last frame, as read back, into this PNG (headless only): the
    /// variants draw the same image.
    #[arg(long)]
    png: Option<PathBuf>,
}

fn main() -> std::process::ExitCode {
    let args = Args::parse();
    tuff_examples::exit(|| match args.command {
        Cmd::Run { variant, config } => run(&variant, config),
        Cmd::Bench {
            out,
            label,
            mt,
            checks,
            untracked,
            vulkano,
            before,
            rounds,
            counts,
            many_writes,
            frames,
            frames_10000,
            warmup,
            size,
            window,
            no_layer,
        } => {
            let mut configs = Vec::new();
            for window in [false, true].into_iter().filter(|w| !w || window) {
                for &count in &counts {
                    configs.push((window, count, 1));
                }
                if many_writes > 1 {
                    configs.push((window, 100, many_writes));
                }
            }
            let plan = Plan {
                mt,
                checks,
                untracked,
                vulkano,
                before,
                rounds,
                frames,
                frames_10000,
                warmup,
                size,
                no_layer,
            };
            bench(&out, &label, &plan, &configs)
        }
        Cmd::Report { csv, label } => {
            let text = std::fs::read_to_string(&csv)
                .with_context(|| format!("cannot read {}", csv.display()))?;
            let rows = report::parse_csv(&text).with_context(|| csv.display().to_string())?;
            let out = csv.parent().map(PathBuf::from).unwrap_or_default();
            let head: Vec<&str> = text.lines().take_while(|l| l.starts_with('#')).collect();
            write_reports(&out, &label, &head.join("\n"), &rows)
        }
    })
}

/// The variant's feature set must be the one this binary was built with (the
/// `vulkano` feature adds the vulkano peer and changes nothing else).
fn check_build(variant: &str) -> Result<()> {
    if variant == "vulkano" && !cfg!(feature = "vulkano") {
        bail!(
            "variant vulkano needs a build with the vulkano feature \
             (cargo build --release -p tuff-examples --bin stages --features vulkano); \
             this one has none"
        );
    }
    let (mt, checks, untracked) = (
        cfg!(feature = "multi_thread"),
        cfg!(feature = "implicit_checks"),
        cfg!(tuff_untracked),
    );
    let wanted = match variant {
        "tuff-mt" => (true, false, false),
        "tuff-checks" => (false, true, false),
        "tuff-untracked" => (false, false, true),
        _ => (false, false, false),
    };
    if (mt, checks, untracked) != wanted {
        bail!(
            "variant {variant} needs a build with multi_thread={}, implicit_checks={} and tuff_untracked={}; this one has {mt}, {checks} and {untracked}",
            wanted.0,
            wanted.1,
            wanted.2
        );
    }
    Ok(())
}

fn run(variant: &str, a: RunArgs) -> Result<()> {
    if !VARIANTS.iter().any(|(v, _)| *v == variant) {
        bail!("unknown variant {variant:?}");
    }
    if variant == "tuff-before" {
        bail!("tuff-before is an earlier build's tuff: run that build with --variant tuff");
    }
    check_build(variant)?;
    if a.png.is_some() && a.window {
        bail!("--png reads the last frame back, which only headless runs do");
    }
    tuff_examples::render::set_auto_sync(variant == "tuff-auto");
    let run = Run {
        count: a.count,
        writes: a.writes,
        frames: a.frames,
        warmup: a.warmup,
        size: a.size,
        window: a.window,
    };
    let samples = if variant == "vulkano" {
        vulkano_run(&run, a.validate)?
    } else if variant.starts_with("tuff") {
        let mut req = tuff_examples::scenes::teapots::REQUIREMENTS;
        req.window = run.window;
        if a.validate {
            // Read by the layer when the instance is created; no other thread runs yet.
            std::env::set_var(
                "VK_LAYER_ENABLES",
                "VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT",
            );
        }
        let gpu = Gpu::new(req, a.validate)?;
        println!("# device: {}", gpu.name);
        let samples = if run.window {
            let common = tuff_examples::cli::Common {
                out: None,
                window: true,
                width: run.size,
                height: run.size,
                frames: Some(run.warmup + run.frames),
                validate: false,
                resizes: 0,
                auto_sync: variant == "tuff-auto",
            };
            let writes = u64::from(run.writes);
            tuff_examples::window::run_timed(
                &gpu,
                &common,
                |gpu, pass| {
                    let layout = tuff_examples::scenes::teapot_grid::Layout::grid(run.count, 1)?;
                    tuff_examples::scenes::teapots::Teapots::with_writes(gpu, pass, layout, writes)
                },
                run.warmup,
            )?
        } else {
            tuff_frames::headless(&gpu, &run)?
        };
        let messages = gpu.finish();
        fail_on_messages(&messages)?;
        samples
    } else {
        let layer = match variant {
            _ if a.validate => Layer::Sync,
            "ash-layer" => Layer::On,
            "ash-sync" => Layer::Sync,
            _ => Layer::Off,
        };
        let mut vulkan = Vulkan::open(tuff_examples::teapots_ash::REQUIREMENTS, layer, run.window)?;
        println!("# device: {}", vulkan.name);
        println!("# driver: {}", vulkan.driver());
        let samples = if run.window {
            ash_frames::window(&mut vulkan, &run)
        } else {
            ash_frames::headless(&mut vulkan, &run)
        };
        let messages = vulkan.finish()?;
        let samples = samples?;
        if !messages.is_empty() {
            for m in &messages {
                eprintln!("{m}");
            }
            bail!(
                "the validation layer reported {} message(s) (above)",
                messages.len()
            );
        }
        samples
    };
    if let Some(path) = &a.png {
        tuff_examples::image_file::write_png(path, run.size, run.size, &samples.last_frame)?;
    }
    for s in &samples.frames {
        let times: Vec<String> = s.iter().map(u64::to_string).collect();
        println!("{}", times.join(","));
    }
    Ok(())
}

/// The vulkano peer's run: headless only, and without the layer (vulkano validates
/// every call itself; the benchmark times it so).
#[cfg(feature = "vulkano")]
fn vulkano_run(run: &Run, validate: bool) -> Result<tuff_examples::stages::Samples> {
    use tuff_examples::stages::vulkano_frames;
    if run.window {
        bail!("the vulkano variant runs headless only");
    }
    if validate {
        bail!("the vulkano variant runs without the layer (--validate)");
    }
    let vulkano = vulkano_frames::Vulkano::open()?;
    println!("# device: {}", vulkano.name());
    vulkano_frames::headless(&vulkano, run)
}

#[cfg(not(feature = "vulkano"))]
fn vulkano_run(_: &Run, _: bool) -> Result<tuff_examples::stages::Samples> {
    bail!("this build has no vulkano (check_build refuses the variant first)")
}

/// Fails when the validation layer reported anything, printing what it said.
fn fail_on_messages(messages: &[String]) -> Result<()> {
    if messages.is_empty() {
        return Ok(());
    }
    for m in messages {
        eprintln!("{m}");
    }
    bail!(
        "the validation layer reported {} message(s) (above)",
        messages.len()
    )
}

struct Plan {
    mt: Option<PathBuf>,
    checks: Option<PathBuf>,
    untracked: Option<PathBuf>,
    vulkano: Option<PathBuf>,
    before: Option<PathBuf>,
    rounds: u32,
    frames: u32,
    frames_10000: u32,
    warmup: u32,
    size: u32,
    no_layer: bool,
}

fn bench(
    out: &std::path::Path,
    label: &str,
    plan: &Plan,
    configs: &[(bool, u32, u32)],
) -> Result<()> {
    let me = std::env::current_exe().context("cannot find this binary")?;
    let mut rows = Vec::new();
    let mut head = vec![format!("# date: {}", tuff_examples::stages::today())];
    let started = std::time::Instant::now();
    for round in 0..plan.rounds {
        for &(window, count, writes) in configs {
            for (variant, _) in VARIANTS {
                let binary = match variant {
                    "tuff-mt" => plan.mt.as_ref(),
                    "tuff-checks" => plan.checks.as_ref(),
                    "tuff-untracked" => plan.untracked.as_ref(),
                    "tuff-before" => plan.before.as_ref(),
                    // Headless only.
                    "vulkano" if window => None,
                    "vulkano" => plan.vulkano.as_ref(),
                    _ => Some(&me),
                };
                let Some(binary) = binary else { continue };
                if plan.no_layer && variant.starts_with("ash-") {
                    continue;
                }
                let frames = if count >= 10_000 {
                    plan.frames_10000
                } else {
                    plan.frames
                };
                // The earlier build runs its own `tuff`.
                let run_as = match variant {
                    "tuff-before" => "tuff",
                    v => v,
                };
                let mut cmd = Command::new(binary);
                cmd.args(["run", "--variant", run_as])
                    .args(["--count", &count.to_string()])
                    .args(["--writes", &writes.to_string()])
                    .args(["--frames", &frames.to_string()])
                    .args(["--warmup", &plan.warmup.to_string()])
                    .args(["--size", &plan.size.to_string()]);
                if window {
                    cmd.arg("--window");
                }
                let output = cmd
                    .output()
                    .with_context(|| format!("cannot run {}", binary.display()))?;
                let stdout = String::from_utf8_lossy(&output.stdout);
                if !output.status.success() {
                    bail!(
                        "{variant} ({count} teapots, {writes} writes, window {window}) failed: {}",
                        String::from_utf8_lossy(&output.stderr)
                    );
                }
                let mode = if window { "window" } else { "headless" };
                let mut timed = 0;
                for (i, line) in stdout.lines().enumerate() {
                    if let Some(comment) = line.strip_prefix('#') {
                        let line = format!("#{comment}");
                        if !head.contains(&line) {
                            head.push(line);
                        }
                        continue;
                    }
                    let csv = format!("{mode},{variant},{count},{writes},{round},{line}");
                    rows.push(
                        Row::from_csv(&csv, i + 1)
                            .with_context(|| format!("{variant}'s output"))?,
                    );
                    timed += 1;
                }
                eprintln!(
                    "[{:>6.1} s] round {round}: {mode} {count} teapots, {writes} writes: {variant}, {timed} frames",
                    started.elapsed().as_secs_f64()
                );
            }
        }
    }
    head.push(format!(
        "# {} timed frames in {:.0} s",
        rows.len(),
        started.elapsed().as_secs_f64()
    ));
    let mut csv = head.join("\n");
    csv.push('\n');
    csv.push_str(&report::csv_header());
    csv.push('\n');
    for r in &rows {
        csv.push_str(&r.to_csv());
        csv.push('\n');
    }
    std::fs::create_dir_all(out).with_context(|| format!("cannot create {}", out.display()))?;
    let path = out.join(format!("{label}.csv"));
    tuff_examples::stages::write_file(&path, &csv)?;
    write_reports(out, label, &head.join("\n"), &rows)
}

/// Writes `<label>.md` and one `<label>-<mode>.svg` per mode the rows have.
fn write_reports(out: &std::path::Path, label: &str, head: &str, rows: &[Row]) -> Result<()> {
    let info: Vec<&str> = head.lines().map(|l| l.trim_start_matches("# ")).collect();
    let mut md = format!("Stage benchmark on {label} ({}).\n", info.join("; "));
    for mode in ["headless", "window"] {
        if rows.iter().any(|r| r.mode == mode) {
            md.push_str(&format!(
                "\nMedians, {mode} (raw ash's time; the others as a ratio to it):\n\n"
            ));
            md.push_str(&report::compact(rows, mode));
        }
    }
    md.push_str("\nEach configuration: median and 90th percentile per stage, the others' ratios to raw ash's, and their own medians.\n");
    md.push_str(&report::markdown(rows));
    tuff_examples::stages::write_file(&out.join(format!("{label}.md")), &md)?;
    for mode in ["headless", "window"] {
        if rows.iter().any(|r| r.mode == mode) {
            let title = format!("Median stage time / raw ash, {label}, {mode}");
            let svg = report::svg(rows, mode, &title);
            tuff_examples::stages::write_file(&out.join(format!("{label}-{mode}.svg")), &svg)?;
        }
    }
    print!("{md}");
    Ok(())
}
