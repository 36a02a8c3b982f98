//! The command line every scene shares, and the run that follows it: headless into
//! a PNG, or into a window.

use crate::gpu::{Gpu, Requirements};
use crate::render::Scene;
use anyhow::{bail, Result};
use std::path::PathBuf;

/// Options every scene takes.
#[derive(clap::Args, Debug, Clone)]
pub struct Common {
    /// Where the PNG goes (headless); `<scene>.png` in the current folder by default.
    #[arg(long)]
    pub out: Option<PathBuf>,
    /// Render into a window through a swapchain instead of into a PNG.
    #[arg(long)]
    pub window: bool,
    /// Image width in pixels (the window's initial width).
    #[arg(long, default_value_t = 512)]
    pub width: u32,
    /// Image height in pixels (the window's initial height).
    #[arg(long, default_value_t = 512)]
    pub height: u32,
    /// Frames to render; the PNG is the last one. Headless the default is 1; in a
    /// window the default (and 0) runs until the window is closed.
    #[arg(long)]
    pub frames: Option<u32>,
    /// Turn on VK_LAYER_KHRONOS_validation with synchronization validation; any
    /// warning or error it reports fails the run.
    #[arg(long)]
    pub validate: bool,
    /// In a window: resize it this many times in a row (a frame or more between
    /// resizes), then close it.
    #[arg(long, default_value_t = 0)]
    pub resizes: u32,
    /// Record with automatic synchronization (`tuff::Recorder::auto_sync`): tuff
    /// records every barrier the frames need, the one before the host reads the
    /// image included.
    #[arg(long)]
    pub auto_sync: bool,
}

/// Runs a scene as `common` says and reports what the validation layer said.
/// Headless, it writes the PNG and prints the frame rate.
pub fn run<S: Scene>(
    common: &Common,
    mut req: Requirements,
    make: impl Fn(&crate::gpu::Gpu, &tuff::RenderPass) -> Result<S>,
) -> Result<()> {
    if common.validate {
        enable_sync_validation();
    }
    req.window = common.window;
    crate::render::set_auto_sync(common.auto_sync);
    let frames = common.frames.unwrap_or(1);
    if frames == 0 && !common.window {
        bail!("--frames must be at least 1 without --window");
    }
    let gpu = Gpu::new(req, common.validate)?;
    let outcome = if common.window {
        crate::window::run(&gpu, common, make)
    } else {
        crate::headless::render(&gpu, common.width, common.height, frames, make).and_then(|r| {
            let out = common
                .out
                .clone()
                .unwrap_or_else(|| PathBuf::from(format!("{}.png", req.scene)));
            crate::image_file::write_png(&out, r.width, r.height, &r.rgba)?;
            println!(
                "{}: wrote {} ({}x{}); {} frames in {:.3} s: {:.1} frames/s on {}{}",
                req.scene,
                out.display(),
                r.width,
                r.height,
                r.frames,
                r.elapsed.as_secs_f64(),
                r.fps(),
                gpu.name,
                r.resident.describe("frame", r.frames)
            );
            Ok(())
        })
    };
    conclude(gpu.finish(), outcome)
}

/// Asks the validation layer, when the instance is made, for synchronization
/// validation too (`VK_LAYER_ENABLES`), keeping what the user enabled.
pub fn enable_sync_validation() {
    // Read by the layer when the instance is created; call before any thread starts.
    let sync = "VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT";
    let enables = match std::env::var("VK_LAYER_ENABLES") {
        Ok(v) if v.split(',').any(|e| e == sync) => v,
        Ok(v) if !v.is_empty() => format!("{v},{sync}"),
        _ => sync.to_owned(),
    };
    std::env::set_var("VK_LAYER_ENABLES", enables);
}

/// Prints what the validation layer reported (even when the run failed: it often
/// says why), then returns `outcome`, or fails if the layer reported anything.
pub fn conclude<T>(messages: Vec<String>, outcome: Result<T>) -> Result<T> {
    for m in &messages {
        eprintln!("{m}");
    }
    let value = outcome?;
    if !messages.is_empty() {
        bail!(
            "the validation layer reported {} message(s) (above)",
            messages.len()
        );
    }
    Ok(value)
}

/// Options of a headless-only scene (the raw-ash twins, the deferred scene): those
/// of [`Common`] less the window.
#[derive(clap::Args, Debug, Clone)]
pub struct Headless {
    /// Where the PNG goes; `<scene>.png` in the current folder by default.
    #[arg(long)]
    pub out: Option<PathBuf>,
    /// Image width in pixels.
    #[arg(long, default_value_t = 512)]
    pub width: u32,
    /// Image height in pixels.
    #[arg(long, default_value_t = 512)]
    pub height: u32,
    /// Frames to render; the PNG is the last one.
    #[arg(long, default_value_t = 1)]
    pub frames: u32,
    /// Turn on VK_LAYER_KHRONOS_validation with synchronization validation; any
    /// warning or error it reports fails the run.
    #[arg(long)]
    pub validate: bool,
}
