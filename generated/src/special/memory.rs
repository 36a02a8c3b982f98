//! Device memory: allocation (counts, types, dedicated and exported memory), the
//! binding of buffers and images to it, and the memory requirements it is checked against.

use super::{chained, chains, refuse};
use crate::handles::*;
use crate::structs::*;
use crate::{Error, Handle, Result};
use ash::vk;
use ash::vk::Handle as _;

/// The buffer keeps its memory alive; commands that use it may now read it.
pub(crate) fn bind_buffer_memory_done(
    device: &Device,
    buffer: &Buffer,
    memory: &DeviceMemory,
    memory_offset: vk::DeviceSize,
) {
    buffer.retain_memory(memory.retained());
    device
        .live()
        .buffer_bound(buffer.raw(), memory.raw(), memory_offset);
}

/// Each buffer keeps its memory alive (the safe infos name both by wrappers); commands
/// that use it may now read it.
pub(crate) fn bind_buffer_memory2_done(device: &Device, bind_infos: &[BindBufferMemoryInfo<'_>]) {
    for info in bind_infos {
        device.live().bound2(info.buffer, info.memory);
        device
            .live()
            .buffer_bound(info.buffer, info.memory, info.memory_offset);
    }
}

/// Each image keeps its memory alive; commands that use it may now read it.
pub(crate) fn bind_image_memory2_done(device: &Device, bind_infos: &[BindImageMemoryInfo<'_>]) {
    for info in bind_infos {
        device.live().bound2(info.image, info.memory);
        let size = image_size(device, info.image);
        device
            .live()
            .image_bound(info.image, info.memory, info.memory_offset, size);
    }
}

/// The image keeps its memory alive.
pub(crate) fn bind_image_memory_done(
    device: &Device,
    image: &Image,
    memory: &DeviceMemory,
    memory_offset: vk::DeviceSize,
) {
    image.retain_memory(memory.retained());
    let size = image_size(device, image.raw());
    device
        .live()
        .image_bound(image.raw(), memory.raw(), memory_offset, size);
}

/// The bytes a live image of the device takes in the memory it is bound to.
fn image_size(device: &Device, image: vk::Image) -> vk::DeviceSize {
    // SAFETY: `image` is a live image of `device` (a wrapper's, just bound).
    unsafe { device.fns().get_image_memory_requirements(image) }.size
}

/// The device remembers the allocation's size and memory type, which mapping needs.
pub(crate) fn memory_allocated(
    device: &Device,
    memory: DeviceMemory,
    raw: vk::DeviceMemory,
    allocate_info: &MemoryAllocateInfo<'_>,
) -> DeviceMemory {
    let next = allocate_info.as_raw().p_next;
    // SAFETY: the `pNext` of a safe struct, and the types the sTypes name.
    let (dedicated, export, flags) = unsafe {
        (
            chained::<vk::MemoryDedicatedAllocateInfo<'_>>(
                next,
                vk::StructureType::MEMORY_DEDICATED_ALLOCATE_INFO,
            ),
            chained::<vk::ExportMemoryAllocateInfo<'_>>(
                next,
                vk::StructureType::EXPORT_MEMORY_ALLOCATE_INFO,
            ),
            chained::<vk::MemoryAllocateFlagsInfo<'_>>(
                next,
                vk::StructureType::MEMORY_ALLOCATE_FLAGS_INFO,
            ),
        )
    };
    let dedicated = dedicated.and_then(|d| {
        if d.buffer != vk::Buffer::null() {
            Some((vk::ObjectType::BUFFER, d.buffer.as_raw()))
        } else if d.image != vk::Image::null() {
            Some((vk::ObjectType::IMAGE, d.image.as_raw()))
        } else {
            None
        }
    });
    let asked = crate::state::MemoryAsked {
        dedicated,
        export: export.map_or(vk::ExternalMemoryHandleTypeFlags::empty(), |e| {
            e.handle_types
        }),
        device_address: flags
            .is_some_and(|f| f.flags.contains(vk::MemoryAllocateFlags::DEVICE_ADDRESS)),
    };
    device.live().allocated(
        raw,
        allocate_info.allocation_size,
        allocate_info.memory_type_index,
        asked,
    );
    memory
}

/// The VUIDs of one bind command's rules, which `vkBindBufferMemory`,
/// `vkBindImageMemory` and their `*2` infos state alike.
struct BindRules {
    /// Not bound before.
    bound: &'static str,
    /// Not created sparse.
    sparse: &'static str,
    /// `memoryOffset` inside the memory.
    offset: &'static str,
    /// The memory's type among the resource's `memoryTypeBits`.
    type_bits: &'static str,
    /// `memoryOffset` a multiple of the resource's `alignment`.
    alignment: &'static str,
    /// The resource's `size` fits in the memory past `memoryOffset`.
    size: &'static str,
}

const BIND_BUFFER: BindRules = BindRules {
    bound: "VUID-vkBindBufferMemory-buffer-07459",
    sparse: "VUID-vkBindBufferMemory-buffer-01030",
    offset: "VUID-vkBindBufferMemory-memoryOffset-01031",
    type_bits: "VUID-vkBindBufferMemory-memory-01035",
    alignment: "VUID-vkBindBufferMemory-memoryOffset-01036",
    size: "VUID-vkBindBufferMemory-size-01037",
};

const BIND_BUFFER2: BindRules = BindRules {
    bound: "VUID-VkBindBufferMemoryInfo-buffer-07459",
    sparse: "VUID-VkBindBufferMemoryInfo-buffer-01030",
    offset: "VUID-VkBindBufferMemoryInfo-memoryOffset-01031",
    type_bits: "VUID-VkBindBufferMemoryInfo-memory-01035",
    alignment: "VUID-VkBindBufferMemoryInfo-memoryOffset-01036",
    size: "VUID-VkBindBufferMemoryInfo-size-01037",
};

const BIND_IMAGE: BindRules = BindRules {
    bound: "VUID-vkBindImageMemory-image-07460",
    sparse: "VUID-vkBindImageMemory-image-01045",
    offset: "VUID-vkBindImageMemory-memoryOffset-01046",
    type_bits: "VUID-vkBindImageMemory-memory-01047",
    alignment: "VUID-vkBindImageMemory-memoryOffset-01048",
    size: "VUID-vkBindImageMemory-size-01049",
};

const BIND_IMAGE2: BindRules = BindRules {
    bound: "VUID-VkBindImageMemoryInfo-image-07460",
    sparse: "VUID-VkBindImageMemoryInfo-image-01045",
    offset: "VUID-VkBindImageMemoryInfo-memoryOffset-01046",
    type_bits: "VUID-VkBindImageMemoryInfo-pNext-01615",
    alignment: "VUID-VkBindImageMemoryInfo-pNext-01616",
    size: "VUID-VkBindImageMemoryInfo-pNext-01617",
};

/// The sparse binding, residency and aliased bits, the same in buffer and image
/// create flags.
const SPARSE_FLAGS: u32 = 0x1 | 0x2 | 0x4;

/// Checks one binding of `memory` at `offset` to a resource: `record` is what the
/// device recorded of it (whether bound, its create flags), `reqs` its memory
/// requirements. A memory the wrappers did not allocate has no record and is not
/// checked against.
fn check_bind(
    device: &Device,
    rules: &BindRules,
    record: Option<(bool, u32)>,
    reqs: vk::MemoryRequirements,
    memory: vk::DeviceMemory,
    offset: vk::DeviceSize,
) -> Result<()> {
    if let Some((bound, flags)) = record {
        if bound {
            refuse(rules.bound, "the object is already bound to memory")?;
        }
        if flags & SPARSE_FLAGS != 0 {
            refuse(
                rules.sparse,
                format!("the object was created with sparse flags ({flags:#x})"),
            )?;
        }
    }
    let Some((size, type_index)) = device
        .live()
        .memory(memory, |m| (m.size, m.memory_type_index))
    else {
        return Ok(());
    };
    if offset >= size {
        refuse(
            rules.offset,
            format!("memoryOffset must be less than the size of memory (memoryOffset = {offset}, size = {size})"),
        )?;
    }
    if reqs.memory_type_bits & (1u32.checked_shl(type_index).unwrap_or(0)) == 0 {
        refuse(
            rules.type_bits,
            format!(
                "memory's type {type_index} is not among the object's memoryTypeBits ({:#x})",
                reqs.memory_type_bits
            ),
        )?;
    }
    if reqs.alignment != 0 && offset % reqs.alignment != 0 {
        refuse(
            rules.alignment,
            format!(
                "memoryOffset must be a multiple of the object's alignment (memoryOffset = {offset}, alignment = {})",
                reqs.alignment
            ),
        )?;
    }
    if reqs.size > size.saturating_sub(offset) {
        refuse(
            rules.size,
            format!(
                "the object needs {} bytes, and memory has {} past memoryOffset (size = {size}, memoryOffset = {offset})",
                reqs.size,
                size.saturating_sub(offset)
            ),
        )?;
    }
    Ok(())
}

/// The buffer's memory requirements, from the driver.
fn buffer_requirements(device: &Device, buffer: vk::Buffer) -> vk::MemoryRequirements {
    let mut reqs = vk::MemoryRequirements::default();
    // SAFETY: `buffer` is a live buffer of `device` (a wrapper, or a safe info's
    // member that a wrapper filled), and `reqs` is written storage.
    unsafe {
        (device.fns().fp_v1_0().get_buffer_memory_requirements)(device.raw(), buffer, &mut reqs)
    };
    reqs
}

/// The image's memory requirements, from the driver.
fn image_requirements(device: &Device, image: vk::Image) -> vk::MemoryRequirements {
    let mut reqs = vk::MemoryRequirements::default();
    // SAFETY: as in `buffer_requirements`.
    unsafe {
        (device.fns().fp_v1_0().get_image_memory_requirements)(device.raw(), image, &mut reqs)
    };
    reqs
}

/// The rules of what an allocation asked for that a bind must match, by VUID.
struct KindRules {
    requires_dedicated: &'static str,
    dedicated: &'static str,
    protected: &'static str,
    unprotected: &'static str,
    export: &'static str,
    device_address: Option<&'static str>,
}

/// The object a bind gives memory to, as [`check_memory_kind`] needs it.
struct Bound {
    ty: vk::ObjectType,
    raw: u64,
    protected: bool,
    external: vk::ExternalMemoryHandleTypeFlags,
    device_address: bool,
}

/// Refuses memory of the wrong kind for the object: not dedicated to it where it
/// requires (or the memory is dedicated to another object), protected memory for an
/// unprotected object or the reverse, exportable memory of no handle type the
/// object names, or memory without a device address for a buffer with one.
fn check_memory_kind(
    device: &Device,
    rules: &KindRules,
    object: &Bound,
    memory: vk::DeviceMemory,
    offset: vk::DeviceSize,
) -> Result<()> {
    let Some((asked, type_index)) = device
        .live()
        .memory(memory, |m| (m.asked, m.memory_type_index))
    else {
        return Ok(());
    };
    let mine = asked.dedicated == Some((object.ty, object.raw));
    if dedicated_required(device, object) && !mine {
        refuse(
            rules.requires_dedicated,
            "the object requires a dedicated allocation (VkMemoryDedicatedRequirements), and \
             the memory was not allocated with a VkMemoryDedicatedAllocateInfo naming it",
        )?;
    }
    if asked.dedicated.is_some_and(|(ty, _)| ty == object.ty) && (!mine || offset != 0) {
        refuse(
            rules.dedicated,
            format!(
                "the memory is dedicated to another object, or bound at an offset other than \
                 zero (memoryOffset = {offset})"
            ),
        )?;
    }
    let physical = device.parent();
    let types = physical.get_memory_properties();
    let protected_type = types
        .memory_types_as_slice()
        .get(type_index as usize)
        .is_some_and(|t| {
            t.property_flags
                .contains(vk::MemoryPropertyFlags::PROTECTED)
        });
    if object.protected && !protected_type {
        refuse(
            rules.protected,
            "a protected object must be bound to memory of a protected type",
        )?;
    }
    if !object.protected && protected_type {
        refuse(
            rules.unprotected,
            "an unprotected object must not be bound to memory of a protected type",
        )?;
    }
    if !asked.export.is_empty() && !asked.export.intersects(object.external) {
        refuse(
            rules.export,
            format!(
                "the memory was allocated exportable as {:?}, which must include one of the \
                 handle types the object was created with ({:?})",
                asked.export, object.external
            ),
        )?;
    }
    if let Some(vuid) = rules.device_address {
        let enabled = device.live().with_features(|f| f.v12.buffer_device_address) == vk::TRUE;
        if enabled && object.device_address && !asked.device_address {
            refuse(
                vuid,
                "the buffer was created with VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT, so its \
                 memory must have been allocated with VK_MEMORY_ALLOCATE_DEVICE_ADDRESS_BIT",
            )?;
        }
    }
    Ok(())
}

/// Whether the driver requires the object to have a dedicated allocation (a Vulkan
/// 1.1 query; never below it).
fn dedicated_required(device: &Device, object: &Bound) -> bool {
    if !device.parent().parent().exts().version(1) {
        return false;
    }
    let mut dedicated = vk::MemoryDedicatedRequirements::default();
    let mut reqs = vk::MemoryRequirements2::default().push_next(&mut dedicated);
    // SAFETY: the object is a live buffer or image of `device` (a wrapper's), and
    // the chain is local.
    unsafe {
        if object.ty == vk::ObjectType::BUFFER {
            let info = vk::BufferMemoryRequirementsInfo2::default()
                .buffer(vk::Buffer::from_raw(object.raw));
            device
                .fns()
                .get_buffer_memory_requirements2(&info, &mut reqs);
        } else {
            let info =
                vk::ImageMemoryRequirementsInfo2::default().image(vk::Image::from_raw(object.raw));
            device
                .fns()
                .get_image_memory_requirements2(&info, &mut reqs);
        }
    }
    let _ = reqs;
    dedicated.requires_dedicated_allocation == vk::TRUE
}

const KIND_BUFFER: KindRules = KindRules {
    requires_dedicated: "VUID-vkBindBufferMemory-buffer-01444",
    dedicated: "VUID-vkBindBufferMemory-memory-01508",
    protected: "VUID-vkBindBufferMemory-None-01898",
    unprotected: "VUID-vkBindBufferMemory-None-01899",
    export: "VUID-vkBindBufferMemory-memory-02726",
    device_address: Some("VUID-vkBindBufferMemory-bufferDeviceAddress-03339"),
};

const KIND_BUFFER2: KindRules = KindRules {
    requires_dedicated: "VUID-VkBindBufferMemoryInfo-buffer-01444",
    dedicated: "VUID-VkBindBufferMemoryInfo-memory-01508",
    protected: "VUID-VkBindBufferMemoryInfo-None-01898",
    unprotected: "VUID-VkBindBufferMemoryInfo-None-01899",
    export: "VUID-VkBindBufferMemoryInfo-memory-02726",
    device_address: Some("VUID-VkBindBufferMemoryInfo-bufferDeviceAddress-03339"),
};

/// Refuses a buffer's device group binding whose device indices are not one per
/// physical device of the device, each a valid index, or that names other than
/// the one instance of a device of one physical device (tuff does not record which
/// instances a memory of a device group has).
fn check_device_indices(device: &Device, indices: &[u32], at: usize) -> Result<()> {
    let count = device.live().physical_count();
    if !indices.is_empty() && indices.len() as u64 != u64::from(count) {
        refuse(
            "VUID-VkBindBufferMemoryDeviceGroupInfo-deviceIndexCount-01606",
            format!("pBindInfos[{at}] gives {} device indices, and the device has {count} physical devices", indices.len()),
        )?;
    }
    if let Some(bad) = indices.iter().find(|d| **d >= count) {
        refuse(
            "VUID-VkBindBufferMemoryDeviceGroupInfo-pDeviceIndices-01607",
            format!("pBindInfos[{at}] names device index {bad}, and the device has {count} physical devices"),
        )?;
    }
    if count > 1 && !indices.is_empty() {
        refuse(
            "VUID-VkBindBufferMemoryInfo-pNext-01605",
            format!("pBindInfos[{at}] names memory instances of a device group, which tuff does not follow; bind_buffer_memory2_unchecked takes them on the caller's word"),
        )?;
    }
    Ok(())
}

const KIND_IMAGE: KindRules = KindRules {
    requires_dedicated: "VUID-vkBindImageMemory-image-01445",
    dedicated: "VUID-vkBindImageMemory-memory-01509",
    protected: "VUID-vkBindImageMemory-None-01901",
    unprotected: "VUID-vkBindImageMemory-None-01902",
    export: "VUID-vkBindImageMemory-memory-02728",
    device_address: None,
};

/// Refuses a binding that would give the buffer memory it cannot live in: bound
/// before, sparse, or memory of the wrong type, too small past the offset, or at a
/// misaligned offset.
pub(crate) fn bind_buffer_memory_checks(
    device: &Device,
    buffer: &Buffer,
    memory: &DeviceMemory,
    memory_offset: vk::DeviceSize,
) -> Result<()> {
    if let Some(r) = device.live().buffer(buffer.raw()) {
        let object = Bound {
            ty: vk::ObjectType::BUFFER,
            raw: buffer.raw().as_raw(),
            protected: r.flags.contains(vk::BufferCreateFlags::PROTECTED),
            external: r.external,
            device_address: r
                .usage
                .contains(vk::BufferUsageFlags::SHADER_DEVICE_ADDRESS),
        };
        check_memory_kind(device, &KIND_BUFFER, &object, memory.raw(), memory_offset)?;
    }
    let record = device
        .live()
        .buffer(buffer.raw())
        .map(|r| (r.bound, r.flags.as_raw()));
    let reqs = buffer_requirements(device, buffer.raw());
    check_bind(
        device,
        &BIND_BUFFER,
        record,
        reqs,
        memory.raw(),
        memory_offset,
    )
}

/// As [`bind_buffer_memory_checks`], for each info, and each chained device group
/// info's device indices; a buffer named twice is bound twice.
pub(crate) fn bind_buffer_memory2_checks(
    device: &Device,
    bind_infos: &[BindBufferMemoryInfo<'_>],
) -> Result<()> {
    for (i, info) in bind_infos.iter().enumerate() {
        if bind_infos[..i].iter().any(|b| b.buffer == info.buffer) {
            refuse(
                BIND_BUFFER2.bound,
                format!("pBindInfos[{i}] binds a buffer an earlier info binds"),
            )?;
        }
        // SAFETY: the safe struct chains only structs pushed through `push_next`,
        // each a valid Vulkan struct of the type its sType names.
        let group = unsafe {
            chained::<vk::BindBufferMemoryDeviceGroupInfo<'_>>(
                info.p_next,
                vk::StructureType::BIND_BUFFER_MEMORY_DEVICE_GROUP_INFO,
            )
        };
        if let Some(group) = group {
            // SAFETY: the safe setter stored the indices with their count.
            let indices = unsafe {
                crate::state::raw_slice(group.p_device_indices, group.device_index_count)
            };
            check_device_indices(device, indices, i)?;
        }
        if let Some(r) = device.live().buffer(info.buffer) {
            let object = Bound {
                ty: vk::ObjectType::BUFFER,
                raw: info.buffer.as_raw(),
                protected: r.flags.contains(vk::BufferCreateFlags::PROTECTED),
                external: r.external,
                device_address: r
                    .usage
                    .contains(vk::BufferUsageFlags::SHADER_DEVICE_ADDRESS),
            };
            check_memory_kind(
                device,
                &KIND_BUFFER2,
                &object,
                info.memory,
                info.memory_offset,
            )?;
        }
        let record = device
            .live()
            .buffer(info.buffer)
            .map(|r| (r.bound, r.flags.as_raw()));
        let reqs = buffer_requirements(device, info.buffer);
        check_bind(
            device,
            &BIND_BUFFER2,
            record,
            reqs,
            info.memory,
            info.memory_offset,
        )?;
    }
    Ok(())
}

/// As [`bind_buffer_memory_checks`], for an image; a disjoint image binds its
/// planes through `bind_image_memory2` (`VUID-vkBindImageMemory-image-01608`).
pub(crate) fn bind_image_memory_checks(
    device: &Device,
    image: &Image,
    memory: &DeviceMemory,
    memory_offset: vk::DeviceSize,
) -> Result<()> {
    let record = device.live().image(image.raw());
    if record.is_some_and(|r| r.flags.contains(vk::ImageCreateFlags::DISJOINT)) {
        refuse(
            "VUID-vkBindImageMemory-image-01608",
            "the image was created with VK_IMAGE_CREATE_DISJOINT_BIT; bind its planes with bind_image_memory2",
        )?;
    }
    if let Some(r) = record {
        let object = Bound {
            ty: vk::ObjectType::IMAGE,
            raw: image.raw().as_raw(),
            protected: r.flags.contains(vk::ImageCreateFlags::PROTECTED),
            external: r.external,
            device_address: false,
        };
        check_memory_kind(device, &KIND_IMAGE, &object, memory.raw(), memory_offset)?;
    }
    let reqs = image_requirements(device, image.raw());
    check_bind(
        device,
        &BIND_IMAGE,
        record.map(|r| (r.bound, r.flags.as_raw())),
        reqs,
        memory.raw(),
        memory_offset,
    )
}

const KIND_IMAGE2: KindRules = KindRules {
    requires_dedicated: "VUID-VkBindImageMemoryInfo-image-01445",
    dedicated: "VUID-VkBindImageMemoryInfo-memory-01509",
    protected: "VUID-VkBindImageMemoryInfo-None-01901",
    unprotected: "VUID-VkBindImageMemoryInfo-None-01902",
    export: "VUID-VkBindImageMemoryInfo-memory-02728",
    device_address: None,
};

/// Refuses an image's device group binding whose counts or device indices do not
/// fit the device, and split instance bind regions, which tuff does not follow
/// (after the rules that need no record of instances).
fn check_image_device_group(
    device: &Device,
    group: &vk::BindImageMemoryDeviceGroupInfo<'_>,
    record: Option<&crate::state::ImageRecord>,
    at: usize,
) -> Result<()> {
    let count = device.live().physical_count();
    let (indices, regions) = (
        group.device_index_count,
        group.split_instance_bind_region_count,
    );
    if indices != 0 && regions != 0 {
        refuse(
            "VUID-VkBindImageMemoryDeviceGroupInfo-deviceIndexCount-01633",
            format!("pBindInfos[{at}] gives both device indices ({indices}) and split instance bind regions ({regions})"),
        )?;
    }
    if indices != 0 && indices != count {
        refuse(
            "VUID-VkBindImageMemoryDeviceGroupInfo-deviceIndexCount-01634",
            format!("pBindInfos[{at}] gives {indices} device indices, and the device has {count} physical devices"),
        )?;
    }
    // SAFETY: the safe setter stored the indices with their count.
    let list = unsafe { crate::state::raw_slice(group.p_device_indices, indices) };
    if let Some(bad) = list.iter().find(|d| **d >= count) {
        refuse(
            "VUID-VkBindImageMemoryDeviceGroupInfo-pDeviceIndices-01635",
            format!("pBindInfos[{at}] names device index {bad}, and the device has {count} physical devices"),
        )?;
    }
    if regions != 0 && u64::from(regions) != u64::from(count) * u64::from(count) {
        refuse(
            "VUID-VkBindImageMemoryDeviceGroupInfo-splitInstanceBindRegionCount-01636",
            format!("pBindInfos[{at}] gives {regions} split instance bind regions, and the device has {count} physical devices (their square is the count)"),
        )?;
    }
    let split = vk::ImageCreateFlags::SPLIT_INSTANCE_BIND_REGIONS;
    if regions != 0 && record.is_some_and(|r| !r.flags.contains(split)) {
        refuse(
            "VUID-VkBindImageMemoryInfo-pNext-01627",
            format!("pBindInfos[{at}] gives split instance bind regions for an image created without VK_IMAGE_CREATE_SPLIT_INSTANCE_BIND_REGIONS_BIT"),
        )?;
    }
    if regions != 0 {
        return Err(Error::Misuse(
            "the safe bind_image_memory2 does not bind split instance bind regions (tuff does not follow the memory instances of a device group); use bind_image_memory2_unchecked",
        ));
    }
    if count > 1 && indices != 0 {
        refuse(
            "VUID-VkBindImageMemoryInfo-pNext-01626",
            format!("pBindInfos[{at}] names memory instances of a device group, which tuff does not follow; bind_image_memory2_unchecked takes them on the caller's word"),
        )?;
    }
    Ok(())
}

/// As [`bind_image_memory_checks`], for each info: its chained device group info,
/// an image named twice, and an image whose memory is a swapchain's. A plane of a
/// disjoint image is refused: the device records one binding per image, which the
/// overlap checks of copies, blits and attachments read.
pub(crate) fn bind_image_memory2_checks(
    device: &Device,
    bind_infos: &[BindImageMemoryInfo<'_>],
) -> Result<()> {
    for (i, info) in bind_infos.iter().enumerate() {
        let record = device.live().image(info.image);
        // SAFETY: the safe struct chains only structs pushed through `push_next`,
        // each a valid Vulkan struct of the type its sType names.
        let (plane, swapchain, group) = unsafe {
            (
                chains(info.p_next, vk::StructureType::BIND_IMAGE_PLANE_MEMORY_INFO),
                chains(
                    info.p_next,
                    vk::StructureType::BIND_IMAGE_MEMORY_SWAPCHAIN_INFO_KHR,
                ),
                chained::<vk::BindImageMemoryDeviceGroupInfo<'_>>(
                    info.p_next,
                    vk::StructureType::BIND_IMAGE_MEMORY_DEVICE_GROUP_INFO,
                ),
            )
        };
        if swapchain {
            refuse(
                "VUID-VkBindImageMemoryInfo-pNext-01631",
                format!("pBindInfos[{i}] chains a VkBindImageMemorySwapchainInfoKHR, so its memory must be VK_NULL_HANDLE, and the safe info always names memory"),
            )?;
        }
        if record.as_ref().is_some_and(|r| r.for_swapchain) {
            refuse(
                "VUID-VkBindImageMemoryInfo-image-01630",
                format!("pBindInfos[{i}]'s image was created with a VkImageSwapchainCreateInfoKHR, so it is bound to its swapchain's memory through a chained VkBindImageMemorySwapchainInfoKHR, which the safe info cannot give (its memory must be VK_NULL_HANDLE); use bind_image_memory2_unchecked"),
            )?;
        }
        if let Some(group) = group {
            check_image_device_group(device, group, record.as_ref(), i)?;
        }
        let disjoint = record
            .as_ref()
            .is_some_and(|r| r.flags.contains(vk::ImageCreateFlags::DISJOINT));
        if plane && !disjoint && record.is_some() {
            refuse(
                "VUID-VkBindImageMemoryInfo-pNext-01618",
                format!("pBindInfos[{i}] binds a plane of an image created without VK_IMAGE_CREATE_DISJOINT_BIT"),
            )?;
        }
        if disjoint {
            return Err(Error::Misuse(
                "the safe bind_image_memory2 does not bind the planes of a disjoint image (the device records one binding per image, which the overlap checks read); use bind_image_memory2_unchecked",
            ));
        }
        if bind_infos[..i].iter().any(|b| b.image == info.image) {
            refuse(
                "VUID-vkBindImageMemory2-pBindInfos-04006",
                format!("pBindInfos[{i}] binds an image an earlier info binds"),
            )?;
        }
        if let Some(r) = record.as_ref() {
            let object = Bound {
                ty: vk::ObjectType::IMAGE,
                raw: info.image.as_raw(),
                protected: r.flags.contains(vk::ImageCreateFlags::PROTECTED),
                external: r.external,
                device_address: false,
            };
            check_memory_kind(
                device,
                &KIND_IMAGE2,
                &object,
                info.memory,
                info.memory_offset,
            )?;
        }
        let reqs = image_requirements(device, info.image);
        check_bind(
            device,
            &BIND_IMAGE2,
            record.map(|r| (r.bound, r.flags.as_raw())),
            reqs,
            info.memory,
            info.memory_offset,
        )?;
    }
    Ok(())
}

/// An image whose memory is one binding: not created disjoint.
pub(crate) fn whole_image_requirements(device: &Device, image: &Image) -> Result<()> {
    let disjoint = device
        .live()
        .image(image.raw())
        .is_some_and(|r| r.flags.contains(vk::ImageCreateFlags::DISJOINT));
    if disjoint {
        refuse(
            "VUID-vkGetImageMemoryRequirements-image-01588",
            "`image` must not have been created with the `VK_IMAGE_CREATE_DISJOINT_BIT` flag \
             set (its planes have their own requirements: use get_image_memory_requirements2)",
        )?;
    }
    Ok(())
}

/// Memory whose commitment is asked for is of a lazily allocated type.
pub(crate) fn lazily_allocated(device: &Device, memory: &DeviceMemory) -> Result<()> {
    let Some(index) = device.live().memory(memory.raw(), |r| r.memory_type_index) else {
        return Ok(());
    };
    let physical = device.parent();
    // SAFETY: a live physical device of its instance.
    let properties = unsafe {
        physical
            .parent()
            .fns()
            .get_physical_device_memory_properties(physical.raw())
    };
    let lazy = properties
        .memory_types_as_slice()
        .get(index as usize)
        .is_some_and(|t| {
            t.property_flags
                .contains(vk::MemoryPropertyFlags::LAZILY_ALLOCATED)
        });
    if !lazy {
        refuse(
            "VUID-vkGetDeviceMemoryCommitment-memory-00690",
            format!(
                "`memory` must have been created with a memory type that reports \
                 `VK_MEMORY_PROPERTY_LAZILY_ALLOCATED_BIT` (its type, {index}, does not)"
            ),
        )?;
    }
    Ok(())
}

/// A plane's requirements are asked only of a disjoint multi-planar image, and
/// always of one: a chained `VkImagePlaneMemoryRequirementsInfo` names one of its
/// planes.
pub(crate) fn image_requirements2_planes(
    device: &Device,
    info: &ImageMemoryRequirementsInfo2<'_>,
) -> Result<()> {
    let raw = info.as_raw();
    let Some(record) = device.live().image(raw.image) else {
        return Ok(());
    };
    // SAFETY: `raw` is a safe struct's.
    let plane: Option<&vk::ImagePlaneMemoryRequirementsInfo<'_>> = unsafe {
        chained(
            raw.p_next,
            vk::StructureType::IMAGE_PLANE_MEMORY_REQUIREMENTS_INFO,
        )
    };
    let aspects = crate::formats::aspects(record.format).unwrap_or_default();
    let planar = aspects.contains(vk::ImageAspectFlags::PLANE_0);
    let disjoint = record.flags.contains(vk::ImageCreateFlags::DISJOINT);
    match plane {
        None if planar && disjoint => refuse(
            "VUID-VkImageMemoryRequirementsInfo2-image-01589",
            "`image` was created with a multi-planar format and the \
             `VK_IMAGE_CREATE_DISJOINT_BIT` flag, so a VkImagePlaneMemoryRequirementsInfo must be \
             chained",
        ),
        Some(_) if !disjoint => refuse(
            "VUID-VkImageMemoryRequirementsInfo2-image-01590",
            "`image` was not created with the `VK_IMAGE_CREATE_DISJOINT_BIT` flag, so no \
             VkImagePlaneMemoryRequirementsInfo may be chained",
        ),
        Some(_) if !planar => refuse(
            "VUID-VkImageMemoryRequirementsInfo2-image-01591",
            "`image` was created with a single-plane format, so no \
             VkImagePlaneMemoryRequirementsInfo may be chained",
        ),
        Some(p)
            if p.plane_aspect.as_raw().count_ones() != 1 || !aspects.contains(p.plane_aspect) =>
        {
            refuse(
                "VUID-VkImagePlaneMemoryRequirementsInfo-planeAspect-02281",
                format!(
                    "`planeAspect` must be a single valid format plane for the image \
                     (`planeAspect` = {:?}, the format's aspects: {aspects:?})",
                    p.plane_aspect
                ),
            )
        }
        _ => Ok(()),
    }
}

/// The requirements of an image not yet made: its create info chains no swapchain
/// (06416), and a disjoint image names one of its format's planes (06417, 06419).
pub(crate) fn device_image_requirements_checks(
    _device: &Device,
    info: &DeviceImageMemoryRequirements<'_>,
) -> Result<()> {
    let raw = info.as_raw();
    // SAFETY: a safe struct's create info is a reference the struct borrows.
    let Some(create) = (unsafe { raw.p_create_info.as_ref() }) else {
        return Ok(());
    };
    // SAFETY: the chain of a safe struct, and the type its sType names.
    if unsafe {
        chains(
            create.p_next,
            vk::StructureType::IMAGE_SWAPCHAIN_CREATE_INFO_KHR,
        )
    } {
        refuse(
            "VUID-VkDeviceImageMemoryRequirementsKHR-pCreateInfo-06416",
            "pCreateInfo chains a VkImageSwapchainCreateInfoKHR",
        )?;
    }
    if !create.flags.contains(vk::ImageCreateFlags::DISJOINT) {
        return Ok(());
    }
    let aspects = crate::formats::aspects(create.format).unwrap_or_default();
    let plane = raw.plane_aspect;
    if aspects.contains(vk::ImageAspectFlags::PLANE_0) && plane == vk::ImageAspectFlags::NONE {
        refuse(
            "VUID-VkDeviceImageMemoryRequirementsKHR-pCreateInfo-06417",
            format!(
                "the image is disjoint, of the multi-planar format {:?}, and planeAspect is NONE",
                create.format
            ),
        )?;
    }
    let tiling = [vk::ImageTiling::LINEAR, vk::ImageTiling::OPTIMAL];
    let planes = vk::ImageAspectFlags::PLANE_0
        | vk::ImageAspectFlags::PLANE_1
        | vk::ImageAspectFlags::PLANE_2;
    if tiling.contains(&create.tiling)
        && (plane.as_raw().count_ones() != 1 || !(aspects & planes).contains(plane))
    {
        refuse(
            "VUID-VkDeviceImageMemoryRequirementsKHR-pCreateInfo-06419",
            format!("the image is disjoint, of {:?} tiling, and planeAspect {plane:?} is not one plane of its format {:?} (aspects {aspects:?})", create.tiling, create.format),
        )?;
    }
    Ok(())
}

/// `vkGetDeviceGroupPeerMemoryFeatures`: a heap of the physical device (00691), and
/// two different device indices of the device's physical devices (00692 to 00694).
/// On a device of one physical device no call is valid.
pub(crate) fn peer_memory_checks(
    device: &Device,
    heap_index: u32,
    local_device_index: u32,
    remote_device_index: u32,
) -> Result<()> {
    let heaps = device.parent().get_memory_properties().memory_heap_count;
    if heap_index >= heaps {
        refuse(
            "VUID-vkGetDeviceGroupPeerMemoryFeatures-heapIndex-00691",
            format!("heapIndex ({heap_index}) must be less than the physical device's {heaps} memory heaps"),
        )?;
    }
    let count = device.live().physical_count();
    for (index, vuid, name) in [
        (
            local_device_index,
            "VUID-vkGetDeviceGroupPeerMemoryFeatures-localDeviceIndex-00692",
            "localDeviceIndex",
        ),
        (
            remote_device_index,
            "VUID-vkGetDeviceGroupPeerMemoryFeatures-remoteDeviceIndex-00693",
            "remoteDeviceIndex",
        ),
    ] {
        if index >= count {
            refuse(
                vuid,
                format!("{name} ({index}) is not a device index of the device's {count} physical devices"),
            )?;
        }
    }
    if local_device_index == remote_device_index {
        refuse(
            "VUID-vkGetDeviceGroupPeerMemoryFeatures-localDeviceIndex-00694",
            format!("localDeviceIndex and remoteDeviceIndex are both {local_device_index}"),
        )?;
    }
    Ok(())
}

/// `vkGetDeviceMemoryOpaqueCaptureAddress`: on a device group, the multi-device
/// feature (03335); the memory allocated with a device address (03336).
pub(crate) fn memory_capture_address_checks(
    device: &Device,
    info: &DeviceMemoryOpaqueCaptureAddressInfo<'_>,
) -> Result<()> {
    super::buffer::check_multi_device_address(
        device,
        "VUID-vkGetDeviceMemoryOpaqueCaptureAddress-device-03335",
    )?;
    let live = device.live();
    let asked = live.memory(info.memory, |m| m.asked).ok_or(Error::Misuse(
        "the memory was not allocated through the wrappers",
    ))?;
    if !asked.device_address {
        refuse(
            "VUID-VkDeviceMemoryOpaqueCaptureAddressInfo-memory-03336",
            "the memory was not allocated with VK_MEMORY_ALLOCATE_DEVICE_ADDRESS_BIT",
        )?;
    }
    Ok(())
}

/// The checks of `vkAllocateMemory` against the physical device's memory types and
/// heaps, and of its chained flags against the device's features.
pub(crate) fn allocate_memory_checks(
    device: &Device,
    allocate_info: &MemoryAllocateInfo<'_>,
) -> Result<()> {
    let info = allocate_info.as_raw();
    let memory = device.parent().get_memory_properties();
    let index = info.memory_type_index;
    let Some(ty) = memory.memory_types_as_slice().get(index as usize) else {
        return refuse(
            "VUID-vkAllocateMemory-pAllocateInfo-01714",
            format!(
                "memoryTypeIndex ({index}) must be less than the physical device's {} memory types",
                memory.memory_type_count
            ),
        );
    };
    let heap = memory.memory_heaps[ty.heap_index as usize];
    if info.allocation_size > heap.size {
        refuse(
            "VUID-vkAllocateMemory-pAllocateInfo-01713",
            format!(
                "allocationSize ({}) is more than memory type {index}'s heap holds ({})",
                info.allocation_size, heap.size
            ),
        )?;
    }
    // SAFETY: the `pNext` of a safe struct, and the types the sTypes name.
    let (flags, capture) = unsafe {
        (
            chained::<vk::MemoryAllocateFlagsInfo<'_>>(
                info.p_next,
                vk::StructureType::MEMORY_ALLOCATE_FLAGS_INFO,
            ),
            chained::<vk::MemoryOpaqueCaptureAddressAllocateInfo<'_>>(
                info.p_next,
                vk::StructureType::MEMORY_OPAQUE_CAPTURE_ADDRESS_ALLOCATE_INFO,
            ),
        )
    };
    let flags = flags.map_or(vk::MemoryAllocateFlags::empty(), |f| f.flags);
    let (address, replay) = device.live().with_features(|f| {
        (
            f.v12.buffer_device_address,
            f.v12.buffer_device_address_capture_replay,
        )
    });
    if flags.contains(vk::MemoryAllocateFlags::DEVICE_ADDRESS_CAPTURE_REPLAY) && replay == vk::FALSE
    {
        refuse(
            "VUID-VkMemoryAllocateInfo-flags-03330",
            "the allocation asks for capture and replay of device addresses, but the device does not enable bufferDeviceAddressCaptureReplay",
        )?;
    }
    if flags.contains(vk::MemoryAllocateFlags::DEVICE_ADDRESS) && address == vk::FALSE {
        refuse(
            "VUID-VkMemoryAllocateInfo-flags-03331",
            "the allocation asks for a device address, but the device does not enable bufferDeviceAddress",
        )?;
    }
    if let Some(c) = capture.filter(|c| c.opaque_capture_address != 0) {
        if !flags.contains(vk::MemoryAllocateFlags::DEVICE_ADDRESS_CAPTURE_REPLAY) {
            refuse(
                "VUID-VkMemoryAllocateInfo-opaqueCaptureAddress-03329",
                format!("the allocation gives an opaque capture address ({:#x}) without VK_MEMORY_ALLOCATE_DEVICE_ADDRESS_CAPTURE_REPLAY_BIT", c.opaque_capture_address),
            )?;
        }
    }
    let protected_memory = device.live().with_features(|f| f.v11.protected_memory);
    if ty
        .property_flags
        .contains(vk::MemoryPropertyFlags::PROTECTED)
        && protected_memory == vk::FALSE
    {
        refuse(
            "VUID-VkMemoryAllocateInfo-memoryTypeIndex-01872",
            format!(
                "memory type {index} is protected, but the device does not enable protectedMemory"
            ),
        )?;
    }
    // SAFETY: the `pNext` of a safe struct, and the type the sType names.
    let flags_info: Option<&vk::MemoryAllocateFlagsInfo<'_>> =
        unsafe { chained(info.p_next, vk::StructureType::MEMORY_ALLOCATE_FLAGS_INFO) };
    if let Some(f) = flags_info.filter(|f| f.flags.contains(vk::MemoryAllocateFlags::DEVICE_MASK)) {
        if f.device_mask == 0 {
            refuse(
                "VUID-VkMemoryAllocateFlagsInfo-deviceMask-00676",
                "VK_MEMORY_ALLOCATE_DEVICE_MASK_BIT is set and deviceMask is 0",
            )?;
        }
        let count = device.live().physical_count();
        if count < 32 && f.device_mask >> count != 0 {
            refuse(
                "VUID-VkMemoryAllocateFlagsInfo-deviceMask-00675",
                format!("deviceMask ({:#x}) names a physical device the device's {count} do not include", f.device_mask),
            )?;
        }
    }
    dedicated_allocation_checks(device, info)
}

/// A chained `VkMemoryDedicatedAllocateInfo` names one image or one buffer, not
/// sparse, and the allocation has exactly its size; a chained
/// `VkExportMemoryAllocateInfo` names handle types that object can export.
fn dedicated_allocation_checks(device: &Device, info: &vk::MemoryAllocateInfo<'_>) -> Result<()> {
    // SAFETY: the `pNext` of a safe struct, and the types the sTypes name.
    let (dedicated, export) = unsafe {
        (
            chained::<vk::MemoryDedicatedAllocateInfo<'_>>(
                info.p_next,
                vk::StructureType::MEMORY_DEDICATED_ALLOCATE_INFO,
            ),
            chained::<vk::ExportMemoryAllocateInfo<'_>>(
                info.p_next,
                vk::StructureType::EXPORT_MEMORY_ALLOCATE_INFO,
            ),
        )
    };
    let export = export.map_or(vk::ExternalMemoryHandleTypeFlags::empty(), |e| {
        e.handle_types
    });
    let (image, buffer) = dedicated.map_or((vk::Image::null(), vk::Buffer::null()), |d| {
        (d.image, d.buffer)
    });
    if image != vk::Image::null() && buffer != vk::Buffer::null() {
        refuse(
            "VUID-VkMemoryDedicatedAllocateInfo-image-01432",
            "VkMemoryDedicatedAllocateInfo names both an image and a buffer",
        )?;
    }
    let physical = device.parent();
    let instance = physical.parent();
    if let Some(record) = device.live().image(image) {
        if record.flags.contains(vk::ImageCreateFlags::SPARSE_BINDING) {
            refuse(
                "VUID-VkMemoryDedicatedAllocateInfo-image-01434",
                "the dedicated image was created with VK_IMAGE_CREATE_SPARSE_BINDING_BIT",
            )?;
        }
        if record.flags.contains(vk::ImageCreateFlags::DISJOINT) {
            // Its planes have requirements of their own, which this query may not
            // ask for.
            return refuse(
                "VUID-VkMemoryDedicatedAllocateInfo-image-01797",
                "the dedicated image was created with VK_IMAGE_CREATE_DISJOINT_BIT",
            );
        }
        let mut needs = vk::MemoryRequirements::default();
        // SAFETY: a live image of this device (its record is listed) and an output
        // this function owns.
        unsafe {
            (device.fns().fp_v1_0().get_image_memory_requirements)(device.raw(), image, &mut needs)
        };
        if info.allocation_size != needs.size {
            refuse(
                "VUID-VkMemoryDedicatedAllocateInfo-image-01433",
                format!(
                    "allocationSize ({}) is not the dedicated image's memory requirement ({})",
                    info.allocation_size, needs.size
                ),
            )?;
        }
        for handle in each_bit(export) {
            let (r, p) = external_image_properties(
                physical,
                vk::PhysicalDeviceImageFormatInfo2::default()
                    .format(record.format)
                    .ty(record.image_type)
                    .tiling(record.tiling)
                    .usage(record.usage)
                    .flags(record.flags),
                handle,
            );

            if r != vk::Result::SUCCESS || !exports(&p, export) {
                refuse(
                    "VUID-VkExportMemoryAllocateInfo-handleTypes-00656",
                    format!("the dedicated image cannot export {export:?} together: the physical device reports {:?} for {handle:?} ({r:?})", p),
                )?;
            }
        }
    } else if let Some(record) = device.live().buffer(buffer) {
        if record.flags.contains(vk::BufferCreateFlags::SPARSE_BINDING) {
            refuse(
                "VUID-VkMemoryDedicatedAllocateInfo-buffer-01436",
                "the dedicated buffer was created with VK_BUFFER_CREATE_SPARSE_BINDING_BIT",
            )?;
        }
        let mut needs = vk::MemoryRequirements::default();
        // SAFETY: a live buffer of this device (its record is listed) and an output
        // this function owns.
        unsafe {
            (device.fns().fp_v1_0().get_buffer_memory_requirements)(
                device.raw(),
                buffer,
                &mut needs,
            )
        };
        if info.allocation_size != needs.size {
            refuse(
                "VUID-VkMemoryDedicatedAllocateInfo-buffer-01435",
                format!(
                    "allocationSize ({}) is not the dedicated buffer's memory requirement ({})",
                    info.allocation_size, needs.size
                ),
            )?;
        }
        for handle in each_bit(export) {
            let external = vk::PhysicalDeviceExternalBufferInfo::default()
                .flags(record.flags)
                .usage(record.usage)
                .handle_type(handle);
            let mut props = vk::ExternalBufferProperties::default();
            // SAFETY: as for the image above.
            unsafe {
                (instance
                    .fns()
                    .fp_v1_1()
                    .get_physical_device_external_buffer_properties)(
                    physical.raw(),
                    &external,
                    &mut props,
                )
            };
            let p = props.external_memory_properties;
            if !exports(&p, export) {
                refuse(
                    "VUID-VkExportMemoryAllocateInfo-handleTypes-00656",
                    format!("the dedicated buffer cannot export {export:?} together: the physical device reports {:?} for {handle:?}", p),
                )?;
            }
        }
    } else if !export.is_empty() {
        // Without an object the reports that the rule names do not apply to one
        // allocation; binding checks the handle types against each object later, but
        // the export itself would go unchecked.
        return Err(Error::Misuse(
            "the safe allocate_memory exports memory only for a dedicated image or buffer (VkMemoryDedicatedAllocateInfo), whose external memory properties it checks; use allocate_memory_unchecked otherwise",
        ));
    }
    Ok(())
}

/// What the physical device reports for an image of `format_info`'s parameters with
/// external memory of `handle`: the query's result and the external memory
/// properties.
pub(super) fn external_image_properties(
    physical: &PhysicalDevice,
    format_info: vk::PhysicalDeviceImageFormatInfo2<'_>,
    handle: vk::ExternalMemoryHandleTypeFlags,
) -> (vk::Result, vk::ExternalMemoryProperties) {
    let mut asked = vk::PhysicalDeviceExternalImageFormatInfo::default().handle_type(handle);
    let format_info = format_info.push_next(&mut asked);
    let mut props = vk::ExternalImageFormatProperties::default();
    let mut out = vk::ImageFormatProperties2::default().push_next(&mut props);
    // SAFETY: a live physical device of a Vulkan 1.1 instance (the external structs
    // are core 1.1, which chaining an external memory struct required); the chains
    // are local.
    let r = unsafe {
        (physical
            .parent()
            .fns()
            .fp_v1_1()
            .get_physical_device_image_format_properties2)(
            physical.raw(), &format_info, &mut out
        )
    };
    (r, props.external_memory_properties)
}

/// Each handle type of a set, alone.
pub(super) fn each_bit(
    set: vk::ExternalMemoryHandleTypeFlags,
) -> impl Iterator<Item = vk::ExternalMemoryHandleTypeFlags> {
    (0..32)
        .map(|b| vk::ExternalMemoryHandleTypeFlags::from_raw(1 << b))
        .filter(move |h| set.contains(*h))
}

/// Whether memory with these properties for one handle type can be exported, with
/// every type of `all` beside it.
fn exports(p: &vk::ExternalMemoryProperties, all: vk::ExternalMemoryHandleTypeFlags) -> bool {
    p.external_memory_features
        .contains(vk::ExternalMemoryFeatureFlags::EXPORTABLE)
        && p.compatible_handle_types.contains(all)
}

/// Flushes and invalidates name memory a live [`crate::MappedMemory`] maps (00684).
/// Its mapping is always the whole memory (`DeviceMemory::map`), so each range is
/// checked against the memory's size (00685, 00686) and `nonCoherentAtomSize` (00687,
/// 01390). The records stay locked until the call has returned, so that no mapping
/// ends (or begins) on another thread meanwhile.
pub(crate) fn mapped_ranges_hold<'d>(
    device: &'d Device,
    memory_ranges: &[MappedMemoryRange<'_>],
) -> Result<crate::state::MemoryRecords<'d>> {
    let records = device.live().memories_locked();
    for (i, range) in memory_ranges.iter().enumerate() {
        let record = records.get(&range.memory.as_raw()).ok_or(Error::Misuse(
            "the memory was not allocated through the wrappers",
        ))?;
        if !record.mapped {
            refuse(
                "VUID-VkMappedMemoryRange-memory-00684",
                format!("pMemoryRanges[{i}].memory is not mapped (no MappedMemory of it lives)"),
            )?;
        }
        let atom = record.host.map_or(1, |(_, atom)| atom.max(1));
        let (offset, size, end) = (range.offset, range.size, record.size);
        if size == vk::WHOLE_SIZE {
            if offset >= end {
                refuse(
                    "VUID-VkMappedMemoryRange-size-00686",
                    format!("pMemoryRanges[{i}].offset ({offset}) is not inside the mapping, which is the whole memory of {end} bytes"),
                )?;
            }
        } else if offset.checked_add(size).is_none_or(|e| e > end) {
            refuse(
                "VUID-VkMappedMemoryRange-size-00685",
                format!("pMemoryRanges[{i}] ({size} bytes at {offset}) is not inside the mapping, which is the whole memory of {end} bytes"),
            )?;
        }
        if offset % atom != 0 {
            refuse(
                "VUID-VkMappedMemoryRange-offset-00687",
                format!("pMemoryRanges[{i}].offset ({offset}) is not a multiple of nonCoherentAtomSize ({atom})"),
            )?;
        }
        if size != vk::WHOLE_SIZE && size % atom != 0 && offset + size != end {
            refuse(
                "VUID-VkMappedMemoryRange-size-01390",
                format!("pMemoryRanges[{i}].size ({size}) is not a multiple of nonCoherentAtomSize ({atom}), and the range ends before the memory's end ({end})"),
            )?;
        }
    }
    Ok(records)
}

/// Holds other safe allocations off while this one is checked against
/// `maxMemoryAllocationCount` and made, so that two threads cannot both take the
/// last one (`VUID-vkAllocateMemory-maxMemoryAllocationCount-04101`).
pub(crate) fn allocate_memory_hold(device: &Device) -> Result<tuff_runtime::VutexGuard<'_, ()>> {
    let (gate, live) = device.live().allocation_gate();
    let max = crate::special::limits(device).max_memory_allocation_count;
    if live as u64 >= u64::from(max) {
        refuse(
            "VUID-vkAllocateMemory-maxMemoryAllocationCount-04101",
            format!("the device has {live} live allocations, the most maxMemoryAllocationCount ({max}) allows"),
        )?;
    }
    Ok(gate)
}
