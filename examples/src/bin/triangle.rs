//! One colored triangle: instance, device, render pass, pipeline, vertex buffer,
//! one frame, into `triangle.png` (or a window with `--window`).

use clap::Parser;
use tuff_examples::{cli, scenes::triangle};

/// Renders a triangle through tuff.
#[derive(Parser)]
struct Args {
    #[command(flatten)]
    common: cli::Common,
}

fn main() -> std::process::ExitCode {
    let args = Args::parse();
    tuff_examples::exit(|| {
        cli::run(
            &args.common,
            triangle::REQUIREMENTS,
            triangle::Triangle::new,
        )
    })
}
