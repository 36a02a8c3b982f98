//! tuff: safe Vulkan wrappers over `ash`, generated from the Khronos registry by
//! `tuff-gen`.
//!
//! `src/generated/` is written by the generator; so are `Cargo.toml`,
//! `VALIDATION.md`, `validation.json` and `validation.svg`, the coverage report that
//! says, rule by rule, what the wrappers guarantee. The other modules are hand-written.
//!
//! ```
//! assert_eq!(tuff::api_info::API_VERSION, (1, 3));
//! assert!(tuff::api_info::EXTENSIONS.contains(&"VK_KHR_swapchain"));
//! ```

#![warn(missing_docs)]

// The generator writes only `src/generated/` (and `Cargo.toml`); every other module
// here is hand-written and edited where it lives. Generated modules keep their crate
// paths (`crate::commands`, ...) so hand-written and generated code name each other
// the same way, and are formatted by the generator (prettyplease), not rustfmt, so the
// freshness test compares exactly what it writes.

/// Which registry, core versions and extensions this crate was generated from.
#[path = "generated/api_info.rs"]
pub mod api_info;
#[path = "generated/checks/mod.rs"]
#[rustfmt::skip]
mod checks;
#[path = "generated/command_checks/mod.rs"]
#[rustfmt::skip]
mod command_checks;
#[path = "generated/commands/mod.rs"]
#[rustfmt::skip]
mod commands;
#[path = "generated/features.rs"]
#[rustfmt::skip]
mod features;
#[path = "generated/formats.rs"]
#[rustfmt::skip]
mod formats;
#[path = "generated/handles.rs"]
#[rustfmt::skip]
pub mod handles;
#[path = "generated/helpers.rs"]
#[rustfmt::skip]
mod helpers;
#[path = "generated/reach.rs"]
#[rustfmt::skip]
mod reach;
#[path = "generated/structs/mod.rs"]
#[rustfmt::skip]
pub mod structs;

mod allocation;
#[cfg(feature = "ext_debug_utils")]
mod debug_log;
mod frames;
mod hooks;
mod layouts;
mod mapping;
mod physical;
mod presence;
pub mod recorder;
mod retention;
mod spirv;
mod submission;
mod support;
#[cfg(feature = "khr_swapchain")]
mod swapchain;
mod validation;
#[cfg(feature = "khr_surface")]
mod window;

pub use allocation::{Bound, BoundMemory, GpuAllocator, MemoryLocation, NaiveAllocator};
pub use ash::vk;
#[cfg(feature = "ext_debug_utils")]
pub use debug_log::MessageLog;
pub use frames::{Frame, FramesInFlight};
pub use handles::*;
pub use mapping::MappedMemory;
pub use recorder::{
    InRenderPass, InRendering, InVideoCoding, Inside, Outside, OutsideRenderPass, Recorder, Scope,
    State,
};
pub use spirv::spirv_words;
pub use structs::*;
pub use support::*;
pub use tuff_runtime as runtime;
