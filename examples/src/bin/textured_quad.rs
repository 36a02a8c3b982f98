//! A textured quad: a checkerboard uploaded through a staging buffer, sampled by the
//! fragment shader, into `textured_quad.png` (or a window with `--window`).

use clap::Parser;
use tuff_examples::{cli, scenes::textured_quad};

/// Renders a textured quad through tuff.
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
            textured_quad::REQUIREMENTS,
            textured_quad::TexturedQuad::new,
        )
    })
}
