//! Three scenes rendered through tuff (`triangle`, `teapots`, `bezier`, each a binary
//! in `src/bin`), each again in raw ash to be measured against (`triangle_ash`,
//! `teapots_ash`, `bezier_ash`, on [`raw_ash`]), and what they share: device setup,
//! render pass and frames in flight, headless and windowed presentation, the camera,
//! and the Utah teapot's geometry.
//!
//! Each binary renders headless into `<scene>.png` by default, or into a window with
//! `--window`; `--validate` turns the Khronos validation layer on and fails the run on
//! any message it reports.
//!
//! ```no_run
//! use tuff_examples::gpu::{Gpu, Requirements};
//! let gpu = Gpu::new(Requirements { scene: "mine", ..Default::default() }, true)?;
//! assert!(gpu.finish().is_empty());
//! # Ok::<(), anyhow::Error>(())
//! ```

pub mod accuracy;
pub mod camera;
pub mod cli;
pub mod deferred_ash;
pub mod gpu;
pub mod headless;
pub mod image_file;
pub mod pipeline;
pub mod raw_ash;
pub mod render;
pub mod scenes;
pub mod stages;
pub mod teapot;
mod teapot_data;
pub mod teapots_ash;
pub mod window;
pub mod workers;

/// The committed SPIR-V of a shader in `shaders/src` (compiled by
/// `scripts/shaders.sh`).
#[macro_export]
macro_rules! spirv {
    ($name:literal) => {
        include_bytes!(concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/../shaders/spv/",
            $name,
            ".spv"
        ))
    };
}

/// A shader module from one of the scenes' compiled shaders (`spirv!`).
///
/// This is where the scenes make tuff's shader promise, once for all of them.
pub fn shader(device: &tuff::Device, bytes: &[u8]) -> tuff::Result<tuff::ShaderModule> {
    // SAFETY: the shader promise. The scenes' shaders are compiled from the GLSL in
    // `shaders/` by `scripts/shaders.sh` (a test fails if the committed SPIR-V is
    // stale), are valid SPIR-V for Vulkan 1.3, use no feature the scenes' devices do
    // not enable, declare a few interface locations and std140/std430 blocks (within
    // every Vulkan device's minimum limits), terminate, and read and write only the
    // uniform buffers, push
    // constants and attachments their pipelines give them, at indices their own
    // vertex and instance counts bound.
    unsafe { device.create_shader_module_from_spirv(bytes) }
}

/// Runs `main`, printing an error and its causes on failure.
pub fn exit(main: impl FnOnce() -> anyhow::Result<()>) -> std::process::ExitCode {
    match main() {
        Ok(()) => std::process::ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e:#}");
            std::process::ExitCode::FAILURE
        }
    }
}
