//! The special cases of generated commands: what a command's method does beyond what
//! its parameters' shapes give, one file per concern.
//!
//! Each function here is named in one row of the generator's special-case table, in
//! the file of the same name under `generator/src/plan/special/` (the row of
//! `vkQueueSubmit` is in `plan/special/queue.rs` and calls `special::queue::*`), and
//! that row lists the rules the function settles, so the report counts exactly what
//! these functions check. A function is named after the row's field that calls it:
//! `*_checks` run in every build before the call (`check`, or `check_last` after the
//! checks of implicit rules), `*_hold` returns a guard held across the call (`hold`),
//! `*_before` and `*_done` are the bookkeeping around a successful call (`before`,
//! `after`), and `*_created`, `*_allocated` and `*_got` finish the wrapper a command
//! returns (`created`). This file keeps what several concerns share: the one
//! `refuse`, the chained-struct lookups and the device's limits and properties.

#[cfg(feature = "khr_acceleration_structure")]
pub(crate) mod acceleration;
pub(crate) mod barriers;
pub(crate) mod blits;
pub(crate) mod buffer;
pub(crate) mod command_buffers;
pub(crate) mod copies;
pub(crate) mod descriptor_set_layout;
pub(crate) mod descriptors;
pub(crate) mod device;
pub(crate) mod draw;
pub(crate) mod draw_descriptors;
pub(crate) mod draw_state;
pub(crate) mod framebuffer;
pub(crate) mod hazards;
pub(crate) mod image;
pub(crate) mod image_copies;
pub(crate) mod image_layouts;
pub(crate) mod indirect;
pub(crate) mod memory;
pub(crate) mod pass_descriptions;
pub(crate) mod pass_instance;
pub(crate) mod pipeline;
pub(crate) mod pipeline_fixed;
pub(crate) mod pipeline_layout;
pub(crate) mod pipeline_stages;
pub(crate) mod query;
pub(crate) mod queue;
pub(crate) mod render_pass;
pub(crate) mod rendering;
pub(crate) mod resolves;
pub(crate) mod sampler;
pub(crate) mod secondaries;
pub(crate) mod shader;
pub(crate) mod stages;
pub(crate) mod subpass_dependencies;
#[cfg(feature = "khr_surface")]
pub(crate) mod surface;
#[cfg(feature = "khr_swapchain")]
pub(crate) mod swapchain;
pub(crate) mod sync;
pub(crate) mod view;

use crate::handles::*;
use crate::recorder::{Recorder, Scope};
pub(crate) use crate::state::limits;
use crate::state::PoolFamily;
pub(crate) use crate::support::refuse;
use crate::Handle;
use ash::vk;

/// Refuses with `vuid` and the message unless `holds`; a rule a command does not
/// have (`vuid` empty) holds.
pub(crate) fn check(
    vuid: &'static str,
    holds: bool,
    message: impl FnOnce() -> String,
) -> crate::Result<()> {
    if vuid.is_empty() || holds {
        Ok(())
    } else {
        refuse(vuid, message())
    }
}

/// The queue family of the recorder's command pool, as its pool's creation
/// recorded it (all capabilities, for a pool the wrappers did not record).
pub(crate) fn pool_family<S: Scope>(recorder: &Recorder<'_, S>) -> PoolFamily {
    let pool = recorder.command_buffer().parent().raw();
    recorder
        .device()
        .live()
        .pool_family(pool)
        .unwrap_or(PoolFamily {
            index: vk::QUEUE_FAMILY_IGNORED,
            flags: recorder.pool_queue_flags(),
            granularity: vk::Extent3D {
                width: 1,
                height: 1,
                depth: 1,
            },
            timestamp_bits: 64,
            protected: false,
        })
}

/// The struct of type `ty` in a safe struct's `pNext` chain, if it has one.
///
/// # Safety
///
/// `next` is the `pNext` of a safe struct: it chains only structs pushed through
/// `push_next`, each a valid Vulkan struct of the Rust type its `sType` names; `T` is
/// the type `ty` names.
pub(super) unsafe fn chained<'c, T>(
    mut next: *const core::ffi::c_void,
    ty: vk::StructureType,
) -> Option<&'c T> {
    // SAFETY: the caller's promise: every node starts with sType and pNext.
    while let Some(node) = unsafe { next.cast::<vk::BaseInStructure<'_>>().as_ref() } {
        if node.s_type == ty {
            // SAFETY: the sType says the node is a `T`.
            return Some(unsafe { &*next.cast::<T>() });
        }
        next = node.p_next.cast();
    }
    None
}

/// Whether a `pNext` chain holds a struct of type `s_type`.
///
/// # Safety
///
/// Every node of the chain is a live Vulkan struct that starts with sType and
/// pNext.
pub(super) unsafe fn chains(mut next: *const std::ffi::c_void, s_type: vk::StructureType) -> bool {
    // SAFETY: the caller promises a chain of valid structs.
    while let Some(node) = unsafe { next.cast::<vk::BaseInStructure<'_>>().as_ref() } {
        if node.s_type == s_type {
            return true;
        }
        next = node.p_next.cast();
    }
    false
}

/// The device's Vulkan 1.2 properties (the update-after-bind limits), where the
/// instance can ask for them and the device has Vulkan 1.2.
pub(super) fn vulkan12_properties(
    device: &Device,
) -> Option<vk::PhysicalDeviceVulkan12Properties<'static>> {
    let version = device.parent().get_properties().api_version;
    let mut p12 = vk::PhysicalDeviceVulkan12Properties::default();
    (vk::api_version_minor(version) >= 2 && ask_properties2(device, &mut p12)).then_some(p12)
}

/// The physical device's Vulkan 1.3 properties, where the instance and device have
/// them.
pub(super) fn vulkan13_properties(
    device: &Device,
) -> Option<vk::PhysicalDeviceVulkan13Properties<'static>> {
    let version = device.parent().get_properties().api_version;
    let mut p13 = vk::PhysicalDeviceVulkan13Properties::default();
    (vk::api_version_minor(version) >= 3 && ask_properties2(device, &mut p13)).then_some(p13)
}

/// The number of queue families of a physical device.
pub(super) fn family_count(physical: &PhysicalDevice) -> u32 {
    let mut count = 0;
    // SAFETY: a live physical device of its instance; the call writes the count only.
    unsafe {
        (physical
            .parent()
            .fns()
            .fp_v1_0()
            .get_physical_device_queue_family_properties)(
            physical.raw(),
            &mut count,
            core::ptr::null_mut(),
        )
    };
    count
}

/// Fills `props` from the device's physical device through
/// vkGetPhysicalDeviceProperties2: `false`, with `props` as it was, where the
/// instance has no Vulkan 1.1 to ask with.
pub(crate) fn ask_properties2<T: vk::ExtendsPhysicalDeviceProperties2>(
    device: &Device,
    props: &mut T,
) -> bool {
    let physical = device.parent();
    let instance = physical.parent();
    if !instance.exts().version(1) {
        return false;
    }
    let mut p2 = vk::PhysicalDeviceProperties2::default().push_next(props);
    // SAFETY: a live physical device of a Vulkan 1.1 instance; the chain is local
    // and ends at `props`, whose `pNext` push_next left null.
    unsafe {
        instance
            .fns()
            .get_physical_device_properties2(physical.raw(), &mut p2)
    };
    true
}
