//! tuff: safe Vulkan wrappers over `ash`, generated from the Khronos registry by
//! `tuff-gen`.
//!
//! Everything under `src/` except this file is written by the generator; so are
//! `Cargo.toml`, `VALIDATION.md`, `validation.json` and `validation.svg`, the
//! coverage report that says, rule by rule, what the wrappers guarantee.
//!
//! ```
//! assert_eq!(tuff::api_info::API_VERSION, (1, 3));
//! assert!(tuff::api_info::EXTENSIONS.contains(&"VK_KHR_swapchain"));
//! ```

#![warn(missing_docs)]

/// Which registry, core versions and extensions this crate was generated from.
pub mod api_info;
#[rustfmt::skip]
mod allocation;
// The generator formats its output with prettyplease; rustfmt leaves it as written,
// so the freshness test compares exactly what the generator writes.
#[rustfmt::skip]
#[cfg(feature = "runtime_implicit_validations")]
mod checks;
#[rustfmt::skip]
mod commands;
#[rustfmt::skip]
mod frames;
#[rustfmt::skip]
pub mod handles;
#[rustfmt::skip]
#[cfg(feature = "ext_debug_utils")]
mod debug_log;
#[rustfmt::skip]
mod mapping;
#[rustfmt::skip]
mod physical;
#[rustfmt::skip]
mod presence;
#[rustfmt::skip]
pub mod recorder;
#[rustfmt::skip]
mod reach;
#[rustfmt::skip]
mod retention;
#[rustfmt::skip]
pub mod structs;
#[rustfmt::skip]
mod spirv;
#[rustfmt::skip]
mod submission;
#[rustfmt::skip]
mod support;
#[rustfmt::skip]
#[cfg(feature = "khr_swapchain")]
mod swapchain;
#[rustfmt::skip]
#[cfg(feature = "runtime_implicit_validations")]
mod validation;

pub use allocation::{Bound, BoundMemory, GpuAllocator, MemoryLocation, NaiveAllocator};
pub use ash::vk;
#[cfg(feature = "ext_debug_utils")]
pub use debug_log::MessageLog;
pub use frames::{Frame, FramesInFlight};
pub use handles::*;
pub use mapping::MappedMemory;
pub use recorder::{InRenderPass, InRendering, Inside, Outside, Recorder, State};
pub use spirv::spirv_words;
pub use structs::*;
pub use support::*;
pub use tuff_runtime as runtime;
