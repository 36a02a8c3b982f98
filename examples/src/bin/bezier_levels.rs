//! What accuracy costs in time for the bezier scene: for each tessellation level
//! (1, 2, 4, ..., 64), the frame time on this device and the largest distance between
//! the tessellated surface and the exact Bezier surface. Prints a Markdown table and
//! writes an SVG plot.

use anyhow::{Context as _, Result};
use clap::Parser;
use std::path::PathBuf;
use tuff_examples::accuracy::{self, Row, LEVELS};
use tuff_examples::gpu::Gpu;
use tuff_examples::headless;
use tuff_examples::scenes::bezier::Bezier;
use tuff_examples::scenes::bezier_view::{self, Options, Viewpoint};

/// Measures frame time and geometric error per tessellation level.
#[derive(Parser)]
struct Args {
    /// Image width and height in pixels.
    #[arg(long, default_value_t = 512)]
    size: u32,
    /// Frames timed per level (pipeline creation is not timed).
    #[arg(long, default_value_t = 30)]
    frames: u32,
    /// Where the SVG plot goes.
    #[arg(long, default_value = "bezier-levels.svg")]
    svg: PathBuf,
}

fn main() -> std::process::ExitCode {
    let args = Args::parse();
    tuff_examples::exit(|| measure(&args))
}

fn measure(args: &Args) -> Result<()> {
    let options = |level| Options {
        level,
        wireframe: false,
        view: Viewpoint::Orbit,
    };
    let gpu = Gpu::new(bezier_view::requirements(&options(1)), false)?;
    let mut rows = Vec::new();
    for level in LEVELS {
        let make = |gpu: &Gpu, pass: &tuff::RenderPass| Bezier::new(gpu, pass, options(level));
        let timed = headless::render(&gpu, args.size, args.size, args.frames, make)?;
        rows.push(Row {
            level,
            frame_ms: timed.elapsed.as_secs_f64() * 1e3 / f64::from(timed.frames),
            error: accuracy::tessellation_error(level),
        });
    }
    let device = gpu.name.clone();
    drop(gpu.finish());
    println!(
        "bezier: tessellation level against frame time ({}x{} on {device}, mean of {} frames) and geometric error\n",
        args.size, args.size, args.frames
    );
    print!("{}", accuracy::markdown_table(&rows));
    // The name up to its details in parentheses, so the title fits the plot.
    let short = device.split(" (").next().unwrap_or(&device);
    let title = format!(
        "Bezier teapot: frame time ({0}x{0}, {short}) and max error",
        args.size
    );
    std::fs::write(&args.svg, accuracy::svg_plot(&rows, &title))
        .with_context(|| format!("cannot write {}", args.svg.display()))?;
    println!("\nbezier: plot written to {}", args.svg.display());
    Ok(())
}
