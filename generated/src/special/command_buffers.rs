//! Command pools and command buffers: their creation, allocation and resets (the
//! execution of secondaries from a primary is `secondaries.rs`).

use super::refuse;
use crate::handles::*;
use crate::state::PoolFamily;
use crate::structs::*;
use crate::submission::{self};
use crate::{Handle, Result};
use ash::vk;

/// Refuses a buffer that may still be executing, or whose pool does not reset buffers.
pub(crate) fn reset_command_buffer_checks(command_buffer: &CommandBuffer) -> Result<()> {
    command_buffer.uses().check_reset(
        command_buffer.device(),
        command_buffer.parent().resets_buffers(),
    )
}

/// Initial state; the last recording's objects go, as no submission uses the buffer
/// (checked).
pub(crate) fn reset_command_buffer_done(command_buffer: &CommandBuffer) {
    command_buffer.uses().reset();
    command_buffer.keep_alive(Vec::new());
}

/// Refuses a pool one of whose buffers may still be executing or is being recorded.
pub(crate) fn reset_command_pool_checks(device: &Device, command_pool: &CommandPool) -> Result<()> {
    submission::check_pool_reset(device, &command_pool.buffer_uses())
}

/// Every buffer of the pool is back in the initial state.
pub(crate) fn reset_command_pool_done(command_pool: &CommandPool) {
    for u in command_pool.buffer_uses() {
        u.reset();
    }
}

/// A command pool is made for a queue family the device has queues of, and is
/// protected only where the protectedMemory feature is enabled.
pub(crate) fn create_command_pool_checks(
    device: &Device,
    create_info: &CommandPoolCreateInfo<'_>,
) -> Result<()> {
    let family = create_info.queue_family_index;
    if !device.live().queue_infos().iter().any(|q| q.0 == family) {
        refuse(
            "VUID-vkCreateCommandPool-queueFamilyIndex-01937",
            format!("the device was created with no queue of family {family}"),
        )?;
    }
    let protected = create_info
        .flags
        .contains(vk::CommandPoolCreateFlags::PROTECTED);
    if protected && device.live().with_features(|f| f.v11.protected_memory) != vk::TRUE {
        refuse(
            "VUID-VkCommandPoolCreateInfo-flags-02860",
            "a protected command pool needs the protectedMemory feature, which the device \
             did not enable",
        )?;
    }
    Ok(())
}

/// The pool remembers its flags, and its family's queue flags for the `cmdpool` checks
/// (and the granularity and timestamp bits other checks read).
pub(crate) fn command_pool_created(
    device: &Device,
    pool: CommandPool,
    create_info: &CommandPoolCreateInfo<'_>,
) -> CommandPool {
    let physical = device.parent();
    // SAFETY: the physical device is a live wrapper of its instance.
    let families = unsafe {
        physical
            .parent()
            .fns()
            .get_physical_device_queue_family_properties(physical.raw())
    };
    // The family's flags, granularity and timestamp bits, from one query (an index
    // past the families has none).
    let (flags, granularity, timestamp_bits) = families
        .get(create_info.queue_family_index as usize)
        .map_or(Default::default(), |f| {
            (
                f.queue_flags,
                f.min_image_transfer_granularity,
                f.timestamp_valid_bits,
            )
        });
    device.live().pool_created(
        pool.raw(),
        PoolFamily {
            index: create_info.queue_family_index,
            flags,
            granularity,
            timestamp_bits,
            protected: create_info
                .flags
                .contains(vk::CommandPoolCreateFlags::PROTECTED),
        },
    );
    pool.with_create_flags(create_info.flags)
        .with_queue_flags(flags)
}

/// Each buffer remembers its level; the device and the pool track its lifecycle.
pub(crate) fn command_buffers_allocated(
    device: &Device,
    cbs: Vec<CommandBuffer>,
    command_pool: &CommandPool,
    allocate_info: &CommandBufferAllocateInfo<'_>,
) -> Vec<CommandBuffer> {
    let cbs: Vec<CommandBuffer> = cbs
        .into_iter()
        .map(|cb| cb.with_level(allocate_info.level))
        .collect();
    for cb in &cbs {
        device.register_command_buffer(cb);
        command_pool.adopt(cb.uses());
    }
    cbs
}
