//! Buffers: creation (limits, sharing, sparse residency), the record the device keeps of each,
//! and the check that a recorded command's buffer range lies inside it with the usage it needs.

use super::image::external_handle_types;
use super::{chained, family_count, limits, refuse, vulkan13_properties};
use crate::handles::*;
use crate::recorder::{Recorder, Scope};
use crate::state::BufferRecord;
use crate::structs::*;
use crate::{Error, Handle, Result};
use ash::vk;

/// The device remembers the buffer's size, usage and flags for the checks of the
/// commands that use it.
pub(crate) fn buffer_created(
    device: &Device,
    buffer: Buffer,
    create_info: &BufferCreateInfo<'_>,
) -> Buffer {
    if create_info
        .flags
        .contains(vk::BufferCreateFlags::SPARSE_BINDING)
    {
        let required = sparse_requirement(device, create_info);
        device.live().sparse_created(buffer.raw(), required);
    }
    device.live().buffer_created(
        buffer.raw(),
        BufferRecord {
            size: create_info.size,
            usage: create_info.usage,
            flags: create_info.flags,
            sharing: create_info.sharing_mode,
            bound: false,
            memory_offset: 0,
            external: external_handle_types(create_info.as_raw().p_next),
        },
    );
    buffer
}

/// The record of a buffer wrapper, which every buffer made through the wrappers has.
pub(super) fn buffer_record(device: &Device, buffer: &Buffer) -> Result<BufferRecord> {
    device.live().buffer(buffer.raw()).ok_or(Error::Misuse(
        "the buffer was not created through the wrappers, so its size is unknown",
    ))
}

/// Checks that a buffer a command reads or writes has memory (or is sparse) and the
/// usage the command needs.
pub(super) fn check_buffer_use(
    record: &BufferRecord,
    usage: vk::BufferUsageFlags,
    (usage_vuid, bound_vuid): (&'static str, &'static str),
    name: &dyn core::fmt::Display,
) -> Result<()> {
    if !record.usage.contains(usage) {
        refuse(
            usage_vuid,
            format!(
                "{name} must have been created with {usage:?} usage (usage = {:?})",
                record.usage
            ),
        )?;
    }
    let sparse = record.flags.contains(vk::BufferCreateFlags::SPARSE_BINDING);
    if !sparse && !record.bound {
        refuse(
            bound_vuid,
            format!("{name} is not sparse, so memory must be bound to it before a command uses it"),
        )?;
    }
    Ok(())
}

/// The records of buffers a recorded command uses, with their usage and binding
/// checked.
pub(super) fn used_buffer<S: Scope>(
    recorder: &Recorder<'_, S>,
    buffer: &Buffer,
    usage: vk::BufferUsageFlags,
    vuids: (&'static str, &'static str),
    name: &dyn core::fmt::Display,
) -> Result<BufferRecord> {
    let record = buffer_record(recorder.device(), buffer)?;
    check_buffer_use(&record, usage, vuids, name)?;
    Ok(record)
}

/// Queue family indices of a concurrent resource: each once, each a family of the
/// physical device.
pub(super) fn concurrent_families(
    physical: &PhysicalDevice,
    families: &[u32],
    vuid: &'static str,
) -> Result<()> {
    let count = family_count(physical);
    for (i, &f) in families.iter().enumerate() {
        if f >= count || families[..i].contains(&f) {
            refuse(
                vuid,
                format!(
                    "each element of `pQueueFamilyIndices` must be unique and must be less than \
                     `pQueueFamilyPropertyCount` (`pQueueFamilyIndices[{i}]` = {f}, families = \
                     {count})"
                ),
            )?;
        }
    }
    Ok(())
}

/// The memory a sparse buffer of this create info requires, from
/// `vkGetDeviceBufferMemoryRequirements` (without creating it), or its size where
/// the device is older than Vulkan 1.3 (rounded up to 64 KiB, the largest sparse
/// block size).
fn sparse_requirement(device: &Device, create_info: &BufferCreateInfo<'_>) -> u64 {
    if vulkan13_properties(device).is_none() {
        return create_info.as_raw().size.div_ceil(1 << 16) << 16;
    }
    let info = vk::DeviceBufferMemoryRequirements::default().create_info(create_info.as_raw());
    let mut out = vk::MemoryRequirements2::default();
    // SAFETY: a live Vulkan 1.3 device; the create info passed the implicit checks.
    unsafe {
        device
            .fns()
            .get_device_buffer_memory_requirements(&info, &mut out)
    };
    out.memory_requirements.size
}

/// Holds other safe sparse creations off while a sparse buffer is checked against
/// `sparseAddressSpaceSize` and made, so that two threads cannot both take the last
/// of it (`VUID-vkCreateBuffer-flags-00911`); a buffer that is not sparse takes no
/// lock.
pub(crate) fn sparse_buffer_hold<'d>(
    device: &'d Device,
    create_info: &BufferCreateInfo<'_>,
) -> Result<Option<tuff_runtime::VutexGuard<'d, ()>>> {
    if !create_info
        .flags
        .contains(vk::BufferCreateFlags::SPARSE_BINDING)
    {
        return Ok(None);
    }
    let gate = device.live().sparse_gate();
    let required = sparse_requirement(device, create_info);
    let total = device.live().sparse_total();
    let limit = limits(device).sparse_address_space_size;
    if total.saturating_add(required) > limit {
        refuse(
            "VUID-vkCreateBuffer-flags-00911",
            format!(
                "creating this sparse buffer, which requires {required} bytes, must not \
                 cause the total required sparse memory ({total} bytes now) to exceed \
                 sparseAddressSpaceSize ({limit})"
            ),
        )?;
    }
    Ok(Some(gate))
}

/// A buffer's creation: its size within `maxBufferSize`, its queue families, the
/// external handle types it is exportable as, a capture address only with the
/// capture-replay flag, and no protected sparse buffer.
pub(crate) fn create_buffer_checks(
    device: &Device,
    create_info: &BufferCreateInfo<'_>,
) -> Result<()> {
    let raw = create_info.as_raw();
    let sparse = vk::BufferCreateFlags::SPARSE_BINDING
        | vk::BufferCreateFlags::SPARSE_RESIDENCY
        | vk::BufferCreateFlags::SPARSE_ALIASED;
    if raw.flags.intersects(sparse) && raw.flags.contains(vk::BufferCreateFlags::PROTECTED) {
        refuse(
            "VUID-VkBufferCreateInfo-None-01888",
            format!(
                "If any of the bits `VK_BUFFER_CREATE_SPARSE_BINDING_BIT`, \
                 `VK_BUFFER_CREATE_SPARSE_RESIDENCY_BIT`, or `VK_BUFFER_CREATE_SPARSE_ALIASED_BIT` \
                 are set, `VK_BUFFER_CREATE_PROTECTED_BIT` must not also be set (`flags` = {:?})",
                raw.flags
            ),
        )?;
    }
    let max = device
        .live()
        .max_buffer_size(|| vulkan13_properties(device).map(|p| p.max_buffer_size));
    if let Some(max) = max.filter(|&m| raw.size > m) {
        refuse(
            "VUID-VkBufferCreateInfo-size-06409",
            format!(
                "`size` must be less than or equal to \
                 VkPhysicalDeviceMaintenance4Properties::`maxBufferSize` (`size` = {}, \
                 maxBufferSize = {max})",
                raw.size
            ),
        )?;
    }
    if raw.sharing_mode == vk::SharingMode::CONCURRENT {
        // SAFETY: the safe setter stored the indices with their count.
        let families = unsafe {
            crate::state::raw_slice(raw.p_queue_family_indices, raw.queue_family_index_count)
        };
        concurrent_families(
            device.parent(),
            families,
            "VUID-VkBufferCreateInfo-sharingMode-01419",
        )?;
    }
    // SAFETY: `raw` is a safe struct's.
    let (capture, external): (
        Option<&vk::BufferOpaqueCaptureAddressCreateInfo<'_>>,
        Option<&vk::ExternalMemoryBufferCreateInfo<'_>>,
    ) = unsafe {
        (
            chained(
                raw.p_next,
                vk::StructureType::BUFFER_OPAQUE_CAPTURE_ADDRESS_CREATE_INFO,
            ),
            chained(
                raw.p_next,
                vk::StructureType::EXTERNAL_MEMORY_BUFFER_CREATE_INFO,
            ),
        )
    };
    if capture.is_some_and(|c| c.opaque_capture_address != 0)
        && !raw
            .flags
            .contains(vk::BufferCreateFlags::DEVICE_ADDRESS_CAPTURE_REPLAY)
    {
        refuse(
            "VUID-VkBufferCreateInfo-opaqueCaptureAddress-03337",
            "If VkBufferOpaqueCaptureAddressCreateInfo::`opaqueCaptureAddress` is not zero, \
             `flags` must include `VK_BUFFER_CREATE_DEVICE_ADDRESS_CAPTURE_REPLAY_BIT`",
        )?;
    }
    let wanted = external.map_or(vk::ExternalMemoryHandleTypeFlags::empty(), |e| {
        e.handle_types
    });
    let physical = device.parent();
    for bit in (0..32)
        .map(|i| 1u32 << i)
        .filter(|b| wanted.as_raw() & b != 0)
    {
        let info = vk::PhysicalDeviceExternalBufferInfo::default()
            .flags(raw.flags)
            .usage(raw.usage)
            .handle_type(vk::ExternalMemoryHandleTypeFlags::from_raw(bit));
        let mut props = vk::ExternalBufferProperties::default();
        // SAFETY: a live physical device of its instance, a valid info and an output
        // it owns; the external struct is core 1.1, which the implicit checks required.
        unsafe {
            physical
                .parent()
                .fns()
                .get_physical_device_external_buffer_properties(physical.raw(), &info, &mut props)
        };
        let compatible = props.external_memory_properties.compatible_handle_types;
        if !compatible.contains(wanted) {
            refuse(
                "VUID-VkBufferCreateInfo-pNext-00920",
                format!(
                    "the chained VkExternalMemoryBufferCreateInfo's `handleTypes` ({wanted:?}) \
                     must only contain bits that are also in the \
                     `externalMemoryProperties.compatibleHandleTypes` the physical device \
                     reports for {:?} ({compatible:?})",
                    info.handle_type
                ),
            )?;
        }
    }
    Ok(())
}

/// On a device of more than one physical device, a device address (of a buffer or a
/// memory) needs bufferDeviceAddressMultiDevice.
pub(crate) fn check_multi_device_address(device: &Device, vuid: &'static str) -> Result<()> {
    let live = device.live();
    let count = live.physical_count();
    if count > 1 && live.with_features(|f| f.v12.buffer_device_address_multi_device) != vk::TRUE {
        refuse(
            vuid,
            format!("the device has {count} physical devices, and bufferDeviceAddressMultiDevice is not enabled"),
        )?;
    }
    Ok(())
}

/// The checks of `vkGetBufferDeviceAddress` and `vkGetBufferOpaqueCaptureAddress`:
/// on a device group, the multi-device feature; the buffer's usage; its memory
/// bound (unless it is sparse or made for capture and replay).
pub(crate) fn buffer_address_checks(
    device: &Device,
    info: &BufferDeviceAddressInfo<'_>,
    multi_device: &'static str,
) -> Result<()> {
    check_multi_device_address(device, multi_device)?;
    let live = device.live();
    let record = live.buffer(info.buffer).ok_or(Error::Misuse(
        "the buffer was not created through the wrappers",
    ))?;
    if !record
        .usage
        .contains(vk::BufferUsageFlags::SHADER_DEVICE_ADDRESS)
    {
        refuse(
            "VUID-VkBufferDeviceAddressInfo-buffer-02601",
            format!(
                "the buffer's usage {:?} lacks SHADER_DEVICE_ADDRESS",
                record.usage
            ),
        )?;
    }
    let unbound_ok = vk::BufferCreateFlags::SPARSE_BINDING
        | vk::BufferCreateFlags::DEVICE_ADDRESS_CAPTURE_REPLAY;
    if !record.flags.intersects(unbound_ok) && !record.bound {
        refuse(
            "VUID-VkBufferDeviceAddressInfo-buffer-02600",
            "the buffer is neither sparse nor made for capture and replay, so memory must be bound to it before its address is asked",
        )?;
    }
    Ok(())
}
