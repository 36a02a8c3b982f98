//! Deferred shading of a grid of objects, recorded by worker threads, into
//! `deferred.png`: see `scenes::deferred`.

use anyhow::Result;
use clap::Parser;
use std::path::PathBuf;
use tuff::vk;
use tuff_examples::gpu::Gpu;
use tuff_examples::scenes::deferred::{self, REQUIREMENTS};
use tuff_examples::scenes::deferred_data::{Layout, Options};

/// Renders a G-buffer and a lighting subpass through tuff, headless, the objects
/// recorded into secondary command buffers by worker threads.
#[derive(Parser)]
struct Args {
    #[command(flatten)]
    scene: Options,
    #[command(flatten)]
    common: tuff_examples::cli::Headless,
    /// Record with automatic synchronization (`tuff::Recorder::auto_sync`): tuff
    /// records every barrier the frames need, the one before the host reads the
    /// image included.
    #[arg(long)]
    auto_sync: bool,
}

fn main() -> std::process::ExitCode {
    let args = Args::parse();
    tuff_examples::exit(|| run(&args))
}

fn run(args: &Args) -> Result<()> {
    let layout = Layout::grid(args.scene.count, args.scene.seed)?;
    let c = &args.common;
    if c.validate {
        tuff_examples::cli::enable_sync_validation();
    }
    tuff_examples::render::set_auto_sync(args.auto_sync);
    let gpu = Gpu::new(REQUIREMENTS, c.validate)?;
    let extent = vk::Extent2D {
        width: c.width,
        height: c.height,
    };
    let outcome = deferred::render(&gpu, layout, extent, c.frames, args.scene.threads);
    let name = gpu.name.clone();
    let run = tuff_examples::cli::conclude(gpu.finish(), outcome)?;
    let out = c
        .out
        .clone()
        .unwrap_or_else(|| PathBuf::from("deferred.png"));
    let r = &run.rendered;
    tuff_examples::image_file::write_png(&out, r.width, r.height, &r.rgba)?;
    println!(
        "deferred: wrote {} ({}x{}); {} objects, {} threads{}; {} frames in {:.3} s: {:.1} frames/s, recording {:.1} us/frame on {name}{}",
        out.display(),
        r.width,
        r.height,
        args.scene.count,
        args.scene.threads,
        if tuff_examples::workers::TUFF_THREADS { "" } else { " (in turn: no multi_thread)" },
        r.frames,
        r.elapsed.as_secs_f64(),
        r.fps(),
        run.recording.as_secs_f64() * 1e6,
        r.resident.describe("frame", r.frames),
    );
    Ok(())
}
