//! The deferred scene of `deferred`, written against raw ash: the same objects,
//! lights, worker threads and image, into `deferred_ash.png`.

use clap::Parser;
use tuff_examples::deferred_ash::{self, REQUIREMENTS};
use tuff_examples::raw_ash;
use tuff_examples::scenes::deferred_data::Layout;

/// Renders the deferred scene through raw ash, headless.
#[derive(Parser)]
struct Args {
    /// How many objects, 1 to 100,000.
    #[arg(long, default_value_t = 2000)]
    count: u32,
    /// Seeds the objects' meshes, colors, phases and spins, and the lights.
    #[arg(long, default_value_t = 1)]
    seed: u64,
    /// Worker threads recording the objects, 1 to 64.
    #[arg(long, default_value_t = 4)]
    threads: u32,
    #[command(flatten)]
    common: raw_ash::Common,
}

fn main() -> std::process::ExitCode {
    let args = Args::parse();
    tuff_examples::exit(|| {
        let layout = Layout::grid(args.count, args.seed)?;
        let c = &args.common;
        let extent = ash::vk::Extent2D {
            width: c.width,
            height: c.height,
        };
        raw_ash::run_with(c, REQUIREMENTS, |vulkan| {
            let (rgba, elapsed, recording) =
                deferred_ash::render(vulkan, layout, extent, c.frames, args.threads)?;
            let note = format!(
                "; {} objects, {} threads, recording {:.1} us/frame",
                args.count,
                args.threads,
                recording.as_secs_f64() * 1e6
            );
            Ok((rgba, elapsed, note))
        })
    })
}
