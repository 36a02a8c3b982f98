//! A grid of spinning Utah teapots, into `teapots.png` (or a window with `--window`).

use clap::Parser;
use tuff_examples::cli;
use tuff_examples::scenes::teapot_grid::Layout;
use tuff_examples::scenes::teapots::{self, Teapots};

/// Renders a grid of spinning teapots through tuff.
#[derive(Parser)]
struct Args {
    /// How many teapots, 1 to 10,000.
    #[arg(long, default_value_t = 100)]
    count: u32,
    /// Seeds the teapots' colors, phases and spin speeds.
    #[arg(long, default_value_t = 1)]
    seed: u64,
    /// Instead of the grid, two identical teapots 10,000 units away, 0.05 % apart in
    /// depth: green in front, red behind. Any red pixel is z-fighting.
    #[arg(long)]
    depth_probe: bool,
    #[command(flatten)]
    common: cli::Common,
}

fn main() -> std::process::ExitCode {
    let args = Args::parse();
    tuff_examples::exit(|| {
        let layout = if args.depth_probe {
            Layout::depth_probe()
        } else {
            Layout::grid(args.count, args.seed)?
        };
        cli::run(&args.common, teapots::REQUIREMENTS, |gpu, render_pass| {
            Teapots::new(gpu, render_pass, layout.clone())
        })
    })
}
