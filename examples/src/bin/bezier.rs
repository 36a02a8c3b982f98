//! The Utah teapot's 32 Bezier patches tessellated on the GPU, into `bezier.png` (or
//! a window with `--window`).

use clap::Parser;
use tuff_examples::cli;
use tuff_examples::scenes::bezier::Bezier;
use tuff_examples::scenes::bezier_view::{self, Options, Viewpoint};

/// Renders the tessellated Bezier teapot through tuff.
#[derive(Parser)]
struct Args {
    /// Tessellation level of every patch edge and inside, 1 to 64.
    #[arg(long, default_value_t = 16, value_parser = clap::value_parser!(u32).range(1..=64))]
    level: u32,
    /// Draw lines instead of filled triangles (needs fillModeNonSolid).
    #[arg(long)]
    wireframe: bool,
    /// Where the camera looks from.
    #[arg(long, value_enum, default_value_t = Viewpoint::Orbit)]
    view: Viewpoint,
    #[command(flatten)]
    common: cli::Common,
}

fn main() -> std::process::ExitCode {
    let args = Args::parse();
    let options = Options {
        level: args.level,
        wireframe: args.wireframe,
        view: args.view,
    };
    tuff_examples::exit(|| {
        cli::run(
            &args.common,
            bezier_view::requirements(&options),
            |gpu, render_pass| Bezier::new(gpu, render_pass, options),
        )
    })
}
