// The `tuff` crate: part emitted by tuff-gen, part written by hand.
//
// Emitted (do not edit; regenerate with `cargo run -p tuff-gen`): everything under
// `src/generated/`, each file starting with an `@generated` line, and beside `src/`
// the manifest, VALIDATION.md, validation.json, validation.svg, emitted-items.txt
// and oracle_cases.rs.
//
// Written by hand: every other module under `src/`. `special/` holds what a command
// does beyond its parameters' shapes, one file per concern, each called from the
// generator's special-case table (`generator/src/plan/special/`); `state/` the
// records the device keeps of its objects, below every check; `memory/` allocation
// and host mapping; `present/` surfaces from windows and the swapchain's recreate
// path; `routine/` routine work in one call (setup, frames in flight, one-object
// forms, choosing a device); `diagnostics/` the layers' messages and why a creation
// failed; beside them the recorder, the submission checks, SPIR-V reading, the
// checks' scope and what every wrapper shares.

//! tuff: safe Vulkan wrappers over `ash`, generated from the Khronos registry by
//! `tuff-gen`.
//!
//! Every Vulkan object is a wrapper that keeps its parent alive and destroys itself
//! when its last clone goes ([`Buffer`], [`Device`], ...); every command is a method
//! on the object it acts on, with the Vulkan name in its docs. A safe method runs the
//! checks of the rules it settles and returns [`Error::Validation`] naming the rule
//! instead of calling Vulkan; a method with rules it cannot check is `unsafe fn`, and
//! its `# Safety` section lists them. Each method's `_unchecked` twin skips the
//! checks. `VALIDATION.md`, beside this crate's `Cargo.toml`, says rule by rule which
//! is which.
//!
//! # A guide, in order
//!
//! An instance, a device with one queue, a storage buffer, a compute pipeline and
//! its descriptor set, a command buffer recorded and submitted, a fence waited on, and
//! the result read back. Everything but the shader module is safe: no check can tell
//! what a shader does, so [`Device::create_shader_module_from_spirv`] makes you
//! promise it.
//!
//! ```no_run
//! use tuff::vk;
//!
//! fn run(spirv: &[u8]) -> Result<Vec<u32>, Box<dyn std::error::Error>> {
//!     // The instance: Vulkan 1.3, no layer or extension (the README's first program
//!     // adds the validation layer and a `MessageLog`, with `ext_debug_utils`).
//!     let app = tuff::ApplicationInfo::new().api_version(vk::API_VERSION_1_3);
//!     let instance = tuff::Entry::load()?
//!         .create_instance(&tuff::InstanceCreateInfo::new().application_info(Some(&app)))?;
//!
//!     // A device with one queue of a family that computes.
//!     let physical = instance.enumerate_physical_devices()?.remove(0);
//!     let family = physical
//!         .queue_family_index(vk::QueueFlags::COMPUTE)?
//!         .ok_or("no compute queue")?;
//!     let queues = [tuff::DeviceQueueCreateInfo::new()
//!         .queue_family_index(family)
//!         .queue_priorities(&[1.0])];
//!     let device =
//!         physical.create_device(&tuff::DeviceCreateInfo::new().queue_create_infos(&queues))?;
//!     let queue = device.get_queue(family, 0)?;
//!
//!     // A storage buffer the shader writes and the host reads back.
//!     let allocator = device.gpu_allocator()?;
//!     let info = tuff::BufferCreateInfo::new()
//!         .size(64 * 4)
//!         .usage(vk::BufferUsageFlags::STORAGE_BUFFER);
//!     let buffer = device.create_buffer_in(&info, &allocator, tuff::MemoryLocation::Readback)?;
//!
//!     // The pipeline: one storage buffer at binding 0, a compute shader.
//!     let bindings = [tuff::DescriptorSetLayoutBinding::new()
//!         .binding(0)
//!         .descriptor_type(vk::DescriptorType::STORAGE_BUFFER)
//!         .descriptor_count(1)
//!         .stage_flags(vk::ShaderStageFlags::COMPUTE)];
//!     let set_layout = device.create_descriptor_set_layout(
//!         &tuff::DescriptorSetLayoutCreateInfo::new().bindings(&bindings),
//!     )?;
//!     // An array of handles takes one wrapper as it is, several as a `HandleSlice`.
//!     let layout = device
//!         .create_pipeline_layout(&tuff::PipelineLayoutCreateInfo::new().set_layouts(&set_layout))?;
//!     // SAFETY: the shader promise: `spirv` is valid SPIR-V for this device, it
//!     // terminates, and it writes only the 64 words of the buffer at binding 0.
//!     let module = unsafe { device.create_shader_module_from_spirv(spirv) }?;
//!     let stage = tuff::PipelineShaderStageCreateInfo::new(c"main")
//!         .stage(vk::ShaderStageFlags::COMPUTE)
//!         .module(Some(&module));
//!     let pipeline = device
//!         .create_compute_pipeline(None, &tuff::ComputePipelineCreateInfo::new(stage, &layout))?;
//!
//!     // Its descriptor set, pointing at the buffer.
//!     let sizes = [vk::DescriptorPoolSize {
//!         ty: vk::DescriptorType::STORAGE_BUFFER,
//!         descriptor_count: 1,
//!     }];
//!     let pool = device.create_descriptor_pool(
//!         &tuff::DescriptorPoolCreateInfo::new().max_sets(1).pool_sizes(&sizes),
//!     )?;
//!     let set = device.allocate_descriptor_set(&pool, &set_layout)?;
//!     let written = [tuff::DescriptorBufferInfo::new()
//!         .buffer(Some(&buffer))
//!         .range(vk::WHOLE_SIZE)];
//!     device.update_descriptor_sets(
//!         &[tuff::WriteDescriptorSet::new(&set)
//!             .descriptor_type(vk::DescriptorType::STORAGE_BUFFER)
//!             .buffer_info(&written)],
//!         &[],
//!     )?;
//!
//!     // Record: a recorder exists only between `begin` and `end`, and has only the
//!     // commands of the state it is in.
//!     let commands = device.create_command_pool(
//!         &tuff::CommandPoolCreateInfo::new().queue_family_index(family),
//!     )?;
//!     let mut cb = device
//!         .allocate_command_buffers(
//!             &commands,
//!             &tuff::CommandBufferAllocateInfo::new(&commands).command_buffer_count(1),
//!         )?
//!         .pop()
//!         .ok_or("no command buffer")?;
//!     let mut rec = cb.begin(&tuff::CommandBufferBeginInfo::new())?;
//!     rec.bind_pipeline(vk::PipelineBindPoint::COMPUTE, &pipeline)?;
//!     rec.bind_descriptor_sets(vk::PipelineBindPoint::COMPUTE, &layout, 0, &set, &[])?;
//!     rec.dispatch(1, 1, 1)?;
//!     let to_host = tuff::MemoryBarrier::new()
//!         .src_access_mask(vk::AccessFlags::SHADER_WRITE)
//!         .dst_access_mask(vk::AccessFlags::HOST_READ);
//!     rec.pipeline_barrier(
//!         vk::PipelineStageFlags::COMPUTE_SHADER,
//!         vk::PipelineStageFlags::HOST,
//!         vk::DependencyFlags::empty(),
//!         &[to_host],
//!         &[],
//!         &[],
//!     )?;
//!     rec.end()?;
//!
//!     // Submit, wait, read back. The fence keeps what the submission uses alive
//!     // until it is seen signalled.
//!     let fence = device.create_fence(&tuff::FenceCreateInfo::new())?;
//!     queue.submit(&[tuff::SubmitInfo::new().command_buffers(&cb)], Some(&fence))?;
//!     // A wait answers which of its success codes it got: with no timeout, the
//!     // fence signalled.
//!     let waited = device.wait_for_fences(&fence, true, u64::MAX)?;
//!     assert_eq!(waited, tuff::SuccessOrTimeout::Success);
//!     Ok(buffer.memory().read::<u32>(0, 64)?)
//! }
//! ```
//!
//! # Threads
//!
//! With the `multi_thread` feature every wrapper is `Send` and `Sync` (shared through
//! `Arc`, its externally synchronized state behind real locks); without it they share
//! through `Rc`, and moving one to another thread fails to compile ("`Rc<..Inner>`
//! cannot be sent between threads safely": turn the feature on). A [`Recorder`] is
//! never `Send`: it holds its command pool's lock from `begin` to `end`, taken by the
//! thread that began it. Workers that record at once each use their own pool and
//! command buffers, and one primary executes their secondaries:
//!
//! ```ignore
//! std::thread::scope(|s| {
//!     for (pool, secondary) in &mut workers {
//!         s.spawn(move || {
//!             let mut rec = secondary.begin_continuing(&info)?; // RENDER_PASS_CONTINUE
//!             // ... the worker's draws ...
//!             rec.end()
//!         });
//!     }
//! });
//! rec.execute_commands(&tuff::HandleSlice::new(&secondaries))?;
//! ```
//!
//! # The generated and hand-written parts
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
#[path = "generated/delta.rs"]
#[rustfmt::skip]
mod delta;
#[path = "generated/features.rs"]
#[rustfmt::skip]
mod features;
#[path = "generated/formats.rs"]
#[rustfmt::skip]
mod formats;
#[path = "generated/sync_tables.rs"]
#[rustfmt::skip]
mod sync_tables;
#[path = "generated/handles.rs"]
#[rustfmt::skip]
pub mod handles;
#[path = "generated/helpers.rs"]
#[rustfmt::skip]
mod helpers;
#[path = "generated/reach.rs"]
#[rustfmt::skip]
mod reach;
#[path = "generated/status.rs"]
#[rustfmt::skip]
pub mod status;
#[path = "generated/structs/mod.rs"]
#[rustfmt::skip]
pub mod structs;

mod diagnostics;
#[doc(hidden)]
pub mod fuzzing;
mod memory;
mod present;
pub mod recorder;
mod routine;
mod special;
mod spirv;
mod state;
mod submission;
mod support;
mod validation;

/// ash's `vk`, and what this crate's registry has that ash lacks, defined in ash's
/// style (nothing when the registry is ash's or older): structs, `API_VERSION_1_<m>`,
/// and enum values as associated constants of one trait per type (a 1.4 crate's
/// `vk::IndexType::UINT8` with `vk::IndexTypeDelta` in scope).
pub mod vk {
    pub use crate::delta::*;
    pub use ash::vk::*;
}
#[cfg(feature = "ext_debug_utils")]
pub use diagnostics::debug_log::MessageLog;
pub use handles::*;
pub use memory::allocation::{
    Bound, BoundMemory, GpuAllocator, LockedMemory, MemoryLocation, NaiveAllocator,
};
pub use memory::host::{HostAllocator, HostRequest, HostStats};
pub use memory::indirect::{IndirectArguments, IndirectBuffer};
pub use memory::mapping::MappedMemory;
pub use recorder::{
    InRenderPass, InRendering, InVideoCoding, Inside, Outside, OutsideRenderPass, Recorder, Scope,
    State,
};
pub use routine::frames::{Frame, FramesInFlight};
pub use spirv::spirv_words;
pub use status::*;
pub use structs::*;
pub use support::*;
pub use tuff_runtime as runtime;
