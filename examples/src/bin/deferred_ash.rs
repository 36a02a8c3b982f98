//! The deferred scene of `deferred`, written against raw ash: the same objects,
//! lights, worker threads and image, into `deferred_ash.png`.

use clap::Parser;
use tuff_examples::deferred_ash::{self, REQUIREMENTS};
use tuff_examples::raw_ash;
use tuff_examples::scenes::deferred_data::{Layout, Options};

/// Renders the deferred scene through raw ash, headless.
#[derive(Parser)]
struct Args {
    #[command(flatten)]
    scene: Options,
    #[command(flatten)]
    common: raw_ash::Common,
}

fn main() -> std::process::ExitCode {
    let args = Args::parse();
    tuff_examples::exit(|| {
        let layout = Layout::grid(args.scene.count, args.scene.seed)?;
        let c = &args.common;
        let extent = ash::vk::Extent2D {
            width: c.width,
            height: c.height,
        };
        raw_ash::run_with(c, REQUIREMENTS, |vulkan| {
            let (rgba, elapsed, recording, resident) =
                deferred_ash::render(vulkan, layout, extent, c.frames, args.scene.threads)?;
            let note = format!(
                "; {} objects, {} threads, recording {:.1} us/frame{}",
                args.scene.count,
                args.scene.threads,
                recording.as_secs_f64() * 1e6,
                resident.describe("frame", c.frames.max(1))
            );
            Ok((rgba, elapsed, note))
        })
    })
}
