//! The spinning teapots of `teapots`, written against raw ash: the baseline tuff is
//! measured against. It makes the same instance, device, objects and per-frame
//! commands as `teapots` does headless, and writes `teapots_ash.png`. Headless only:
//! there is no `--window`.

use clap::Parser;
use tuff_examples::raw_ash;
use tuff_examples::scenes::teapot_grid::Layout;
use tuff_examples::teapots_ash::{Teapots, REQUIREMENTS};

/// Renders a grid of spinning teapots through raw ash, headless.
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
    common: raw_ash::Common,
}

fn main() -> std::process::ExitCode {
    let args = Args::parse();
    tuff_examples::exit(|| {
        let layout = if args.depth_probe {
            Layout::depth_probe()
        } else {
            Layout::grid(args.count, args.seed)?
        };
        // The same device features as tuff's scene, so both draw alike.
        raw_ash::run(&args.common, REQUIREMENTS, |device, o, render_pass| {
            Teapots::new(device, o, render_pass, layout, 1)
        })
    })
}
