//! The threads table: the deferred scene's recording time per frame and frame rate
//! for each object count and worker count, tuff (`deferred`, built with
//! `multi_thread` so its workers run on threads of their own) beside its raw-ash
//! twin (`deferred_ash`) with the same threads, each run a process of its own,
//! interleaved over rounds; the medians go into `<out>/threads-<label>.csv` and
//! `.md`. `scripts/threads-bench.sh` builds the binaries and runs it.

use anyhow::{bail, Context as _, Result};
use clap::Parser;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use std::process::Command;

/// Times the deferred scene in tuff and raw ash over worker and object counts.
#[derive(Parser)]
struct Args {
    /// The tuff scene's binary, built with the `multi_thread` feature.
    #[arg(long)]
    tuff: PathBuf,
    /// The raw-ash twin's binary.
    #[arg(long)]
    ash: PathBuf,
    /// Object counts.
    #[arg(long, value_delimiter = ',', default_values_t = [1000, 10_000, 100_000])]
    counts: Vec<u32>,
    /// Worker thread counts.
    #[arg(long, value_delimiter = ',', default_values_t = [1, 2, 4, 8, 16])]
    threads: Vec<u32>,
    /// Frames per run (the first frame's recording is left out of the mean).
    #[arg(long, default_value_t = 30)]
    frames: u32,
    /// Frames per run at 100,000 objects or more.
    #[arg(long, default_value_t = 10)]
    frames_100000: u32,
    /// Rounds; each runs every configuration once, tuff then ash.
    #[arg(long, default_value_t = 3)]
    rounds: u32,
    /// Image width and height.
    #[arg(long, default_value_t = 256)]
    size: u32,
    /// Where the tables go.
    #[arg(long, default_value = "docs/stages")]
    out: PathBuf,
    /// Names the tables: `threads-<label>`.
    #[arg(long, default_value = "lavapipe")]
    label: String,
    /// The command that made the tables, for their header.
    #[arg(long, default_value = "target/threads/threads")]
    made_by: String,
}

/// One run's figures.
#[derive(Debug, Clone, Copy)]
struct Figures {
    recording_us: f64,
    fps: f64,
}

/// The number just before `unit` in `line`.
fn number_before(line: &str, unit: &str) -> Option<f64> {
    let head = &line[..line.find(unit)?];
    head.rsplit(' ').next()?.parse().ok()
}

/// Runs a scene binary and reads its summary line; also returns the device's name.
fn run(
    binary: &Path,
    count: u32,
    threads: u32,
    frames: u32,
    size: u32,
    png: &Path,
) -> Result<(Figures, String)> {
    let size = size.to_string();
    let output = Command::new(binary)
        .args([
            "--count",
            &count.to_string(),
            "--threads",
            &threads.to_string(),
        ])
        .args([
            "--frames",
            &frames.to_string(),
            "--width",
            &size,
            "--height",
            &size,
        ])
        .arg("--out")
        .arg(png)
        .output()
        .with_context(|| format!("cannot run {}", binary.display()))?;
    let text = String::from_utf8_lossy(&output.stdout).into_owned();
    if !output.status.success() {
        bail!(
            "{} failed: {text}{}",
            binary.display(),
            String::from_utf8_lossy(&output.stderr)
        );
    }
    if text.contains("in turn") {
        bail!(
            "{} records its workers in turn: build it with `--features multi_thread`",
            binary.display()
        );
    }
    let line = text
        .lines()
        .find(|l| l.contains("us/frame"))
        .with_context(|| format!("{} printed no summary: {text}", binary.display()))?;
    let figures = Figures {
        recording_us: number_before(line, " us/frame").context("no recording time")?,
        fps: number_before(line, " frames/s").context("no frame rate")?,
    };
    let device = line.rsplit(" on ").next().unwrap_or("?").to_owned();
    Ok((figures, device))
}

fn median(values: &mut [f64]) -> f64 {
    values.sort_by(f64::total_cmp);
    values[values.len() / 2]
}

fn main() -> std::process::ExitCode {
    let args = Args::parse();
    tuff_examples::exit(|| bench(&args))
}

fn bench(args: &Args) -> Result<()> {
    let scratch = std::env::temp_dir().join(format!("tuff-threads-{}", std::process::id()));
    std::fs::create_dir_all(&scratch)?;
    let png = scratch.join("frame.png");
    let configs: Vec<(u32, u32)> = args
        .counts
        .iter()
        .flat_map(|&c| args.threads.iter().map(move |&t| (c, t)))
        .collect();
    // (tuff, ash) figures per configuration, one per round.
    let mut runs: Vec<Vec<(Figures, Figures)>> = vec![Vec::new(); configs.len()];
    let mut device = String::new();
    let started = std::time::Instant::now();
    for round in 0..args.rounds.max(1) {
        for (i, &(count, threads)) in configs.iter().enumerate() {
            let frames = if count >= 100_000 {
                args.frames_100000
            } else {
                args.frames
            };
            let (tuff, name) = run(&args.tuff, count, threads, frames, args.size, &png)?;
            let (ash, _) = run(&args.ash, count, threads, frames, args.size, &png)?;
            device = name;
            eprintln!(
                "round {round}: {count} objects, {threads} threads: tuff {:.0} us, ash {:.0} us",
                tuff.recording_us, ash.recording_us
            );
            runs[i].push((tuff, ash));
        }
    }
    let _ = std::fs::remove_dir_all(&scratch);
    let mut csv = String::from(
        "objects,threads,tuff_recording_us,ash_recording_us,ratio,tuff_speedup,ash_speedup,tuff_fps,ash_fps\n",
    );
    let mut md = format!(
        "# Threads: the deferred scene, {}\n\n\
         Recording per frame (workers recording their secondaries at once, then the primary), \
         median of {} interleaved rounds of {} frames ({} at 100,000 objects), first frame left out; \
         frames per second over the whole run; {}x{} pixels; speed-up over one thread of the same \
         library. Device: {device}. Made by `{}` on {} ({:.0} s).\n\n\
         | objects | threads | tuff µs/frame | ash µs/frame | tuff / ash | tuff speed-up | ash speed-up | tuff frames/s | ash frames/s |\n\
         |---:|---:|---:|---:|---:|---:|---:|---:|---:|\n",
        args.label,
        args.rounds.max(1),
        args.frames,
        args.frames_100000,
        args.size,
        args.size,
        args.made_by,
        tuff_examples::stages::today(),
        started.elapsed().as_secs_f64(),
    );
    let mut one_thread = std::collections::HashMap::new();
    for (&(count, threads), runs) in configs.iter().zip(&runs) {
        let med = |pick: fn(&(Figures, Figures)) -> f64| {
            median(&mut runs.iter().map(pick).collect::<Vec<_>>())
        };
        let tuff = med(|r| r.0.recording_us);
        let ash = med(|r| r.1.recording_us);
        let (tuff_fps, ash_fps) = (med(|r| r.0.fps), med(|r| r.1.fps));
        if threads == 1 {
            one_thread.insert(count, (tuff, ash));
        }
        let (tuff_speedup, ash_speedup) = one_thread
            .get(&count)
            .map_or((f64::NAN, f64::NAN), |&(t, a)| (t / tuff, a / ash));
        let ratio = tuff / ash;
        writeln!(
            csv,
            "{count},{threads},{tuff:.1},{ash:.1},{ratio:.3},{tuff_speedup:.2},{ash_speedup:.2},{tuff_fps:.2},{ash_fps:.2}"
        )?;
        writeln!(
            md,
            "| {count} | {threads} | {tuff:.0} | {ash:.0} | {ratio:.2}x | {tuff_speedup:.2}x | {ash_speedup:.2}x | {tuff_fps:.1} | {ash_fps:.1} |"
        )?;
    }
    std::fs::create_dir_all(&args.out)?;
    let base = args.out.join(format!("threads-{}", args.label));
    tuff_examples::stages::write_file(&base.with_extension("csv"), &csv)?;
    tuff_examples::stages::write_file(&base.with_extension("md"), &md)?;
    print!("{md}");
    Ok(())
}
