//! Images: creation (type, format and usage limits, sharing, sparse residency, swapchain
//! and Y'CbCr rules) and the record the device keeps of each.

use super::buffer::concurrent_families;
use super::memory::{each_bit, external_image_properties};
use super::{chained, limits, refuse, vulkan13_properties};
use crate::handles::*;
use crate::state::ImageRecord;
use crate::structs::*;
use crate::{Handle, Result};
use ash::vk;

/// The device remembers the image's creation parameters for the checks of the
/// commands and structs that name it.
pub(crate) fn image_created(
    device: &Device,
    image: Image,
    create_info: &ImageCreateInfo<'_>,
) -> Image {
    if create_info
        .flags
        .contains(vk::ImageCreateFlags::SPARSE_BINDING)
    {
        // What the creation's check counted, so the total stays what it checks.
        let required = sparse_image_requirement(device, create_info.as_raw());
        device.live().sparse_created(image.raw(), required);
    }
    let next = create_info.as_raw().p_next;
    // SAFETY: the `pNext` of a safe struct, and the types the sTypes name.
    let (stencil, list) = unsafe {
        (
            chained::<vk::ImageStencilUsageCreateInfo<'_>>(
                next,
                vk::StructureType::IMAGE_STENCIL_USAGE_CREATE_INFO,
            ),
            chained::<vk::ImageFormatListCreateInfo<'_>>(
                next,
                vk::StructureType::IMAGE_FORMAT_LIST_CREATE_INFO,
            ),
        )
    };
    // SAFETY: the safe setter stores the formats with their count.
    let views = list.map_or(&[][..], |l| unsafe {
        crate::state::raw_slice(l.p_view_formats, l.view_format_count)
    });
    device.live().image_created(
        image.raw(),
        ImageRecord {
            flags: create_info.flags,
            image_type: create_info.image_type,
            format: create_info.format,
            extent: create_info.extent,
            mip_levels: create_info.mip_levels,
            array_layers: create_info.array_layers,
            usage: create_info.usage,
            tiling: create_info.tiling,
            samples: create_info.samples,
            stencil_usage: stencil.map(|s| s.stencil_usage),
            sharing: create_info.sharing_mode,
            families: family_bits(create_info.sharing_mode, create_info.as_raw()),
            bound: false,
            external: external_handle_types(next),
            for_swapchain: names_swapchain(next),
        },
        views,
    );
    if create_info.initial_layout == vk::ImageLayout::PREINITIALIZED {
        device.live().image_preinitialized(image.raw());
    }
    image
}

/// Whether an image create info's chain names a swapchain whose memory the image
/// binds (a `VkImageSwapchainCreateInfoKHR` with a swapchain).
fn names_swapchain(next: *const core::ffi::c_void) -> bool {
    // SAFETY: the `pNext` of a safe struct, and the type the sType names.
    let chained: Option<&vk::ImageSwapchainCreateInfoKHR<'_>> =
        unsafe { chained(next, vk::StructureType::IMAGE_SWAPCHAIN_CREATE_INFO_KHR) };
    chained.is_some_and(|c| c.swapchain != vk::SwapchainKHR::null())
}

/// The queue families of a concurrent resource as bits (see `ImageRecord::families`).
pub(super) fn family_bits(sharing: vk::SharingMode, info: &vk::ImageCreateInfo<'_>) -> u64 {
    if sharing != vk::SharingMode::CONCURRENT {
        return 0;
    }
    // SAFETY: the safe setter stores the indices with their count.
    let families = unsafe {
        crate::state::raw_slice(info.p_queue_family_indices, info.queue_family_index_count)
    };
    families
        .iter()
        .fold(0, |bits, &f| match 1u64.checked_shl(f) {
            Some(bit) => bits | bit,
            None => u64::MAX,
        })
}

/// The handle types a chained `VkExternalMemoryBufferCreateInfo` or
/// `VkExternalMemoryImageCreateInfo` names (none without one).
pub(super) fn external_handle_types(
    next: *const core::ffi::c_void,
) -> vk::ExternalMemoryHandleTypeFlags {
    // SAFETY: the `pNext` of a safe struct, and the types the sTypes name (the two
    // structs have the same layout).
    let (buffer, image) = unsafe {
        (
            chained::<vk::ExternalMemoryBufferCreateInfo<'_>>(
                next,
                vk::StructureType::EXTERNAL_MEMORY_BUFFER_CREATE_INFO,
            ),
            chained::<vk::ExternalMemoryImageCreateInfo<'_>>(
                next,
                vk::StructureType::EXTERNAL_MEMORY_IMAGE_CREATE_INFO,
            ),
        )
    };
    buffer
        .map(|b| b.handle_types)
        .or(image.map(|i| i.handle_types))
        .unwrap_or_default()
}

/// The Image Creation Limits of a create info: what
/// `vkGetPhysicalDeviceImageFormatProperties(2)` says of its format, type, tiling,
/// usage and flags, with the chained structs that narrow them (a format list, a
/// stencil usage, each external handle type), intersected; `None` where a query
/// says the combination is not supported.
fn image_creation_limits(
    device: &Device,
    info: &vk::ImageCreateInfo<'_>,
) -> Option<vk::ImageFormatProperties> {
    let physical = device.parent();
    let instance = physical.parent();
    let mut list = None;
    let mut stencil = None;
    let mut handles = vk::ExternalMemoryHandleTypeFlags::empty();
    let mut next = info.p_next.cast::<vk::BaseInStructure<'_>>();
    // SAFETY: the safe struct chains only structs pushed through `push_next`, each a
    // valid Vulkan struct that starts with sType and pNext.
    while let Some(node) = unsafe { next.as_ref() } {
        match node.s_type {
            vk::StructureType::IMAGE_FORMAT_LIST_CREATE_INFO => {
                // SAFETY: the sType says which struct this is.
                list = Some(unsafe { *next.cast::<vk::ImageFormatListCreateInfo<'_>>() });
            }
            vk::StructureType::IMAGE_STENCIL_USAGE_CREATE_INFO => {
                // SAFETY: as above.
                stencil = Some(unsafe { *next.cast::<vk::ImageStencilUsageCreateInfo<'_>>() });
            }
            vk::StructureType::EXTERNAL_MEMORY_IMAGE_CREATE_INFO => {
                // SAFETY: as above.
                handles =
                    unsafe { (*next.cast::<vk::ExternalMemoryImageCreateInfo<'_>>()).handle_types };
            }
            _ => {}
        }
        next = node.p_next;
    }
    let narrowed = list.is_some() || stencil.is_some() || !handles.is_empty();
    if !narrowed || !instance.exts().version(1) {
        // SAFETY: a live physical device of its instance; the values come from a safe
        // create info (the implicit checks passed).
        return unsafe {
            instance.fns().get_physical_device_image_format_properties(
                physical.raw(),
                info.format,
                info.image_type,
                info.tiling,
                info.usage,
                info.flags,
            )
        }
        .ok();
    }
    // Each handle type is its own query; no handle type is one query without one.
    let mut each: Vec<Option<vk::ExternalMemoryHandleTypeFlags>> = (0..32)
        .map(|b| vk::ExternalMemoryHandleTypeFlags::from_raw(1 << b))
        .filter(|h| handles.contains(*h))
        .map(Some)
        .collect();
    if each.is_empty() {
        each.push(None);
    }
    let mut limits: Option<vk::ImageFormatProperties> = None;
    for handle in each {
        let mut format_info = vk::PhysicalDeviceImageFormatInfo2::default()
            .format(info.format)
            .ty(info.image_type)
            .tiling(info.tiling)
            .usage(info.usage)
            .flags(info.flags);
        // The copies join this query's chain instead of the create info's.
        let mut list = list.map(|mut l| {
            l.p_next = std::ptr::null();
            l
        });
        let mut stencil = stencil.map(|mut s| {
            s.p_next = std::ptr::null();
            s
        });
        let mut external =
            handle.map(|h| vk::PhysicalDeviceExternalImageFormatInfo::default().handle_type(h));
        if let Some(l) = list.as_mut() {
            format_info = format_info.push_next(l);
        }
        if let Some(s) = stencil.as_mut() {
            format_info = format_info.push_next(s);
        }
        if let Some(e) = external.as_mut() {
            format_info = format_info.push_next(e);
        }
        let mut out = vk::ImageFormatProperties2::default();
        // SAFETY: a live physical device of a Vulkan 1.1 instance; the chain holds
        // copies of the create info's own structs, each with its pNext reset.
        unsafe {
            instance.fns().get_physical_device_image_format_properties2(
                physical.raw(),
                &format_info,
                &mut out,
            )
        }
        .ok()?;
        let p = out.image_format_properties;
        limits = Some(match limits {
            None => p,
            Some(l) => vk::ImageFormatProperties {
                max_extent: vk::Extent3D {
                    width: l.max_extent.width.min(p.max_extent.width),
                    height: l.max_extent.height.min(p.max_extent.height),
                    depth: l.max_extent.depth.min(p.max_extent.depth),
                },
                max_mip_levels: l.max_mip_levels.min(p.max_mip_levels),
                max_array_layers: l.max_array_layers.min(p.max_array_layers),
                sample_counts: l.sample_counts & p.sample_counts,
                max_resource_size: l.max_resource_size.min(p.max_resource_size),
            },
        });
    }
    limits
}

/// Refuses an image that its format cannot have: a combination of format, type,
/// tiling, usage and flags the device does not support, an extent, level count,
/// layer count or sample count past the Image Creation Limits, or more levels than
/// the extent has.
pub(crate) fn create_image_checks(
    device: &Device,
    create_info: &ImageCreateInfo<'_>,
) -> Result<()> {
    image_create_rules(device, create_info)?;
    let info = create_info.as_raw();
    let e = info.extent;
    let longest = e.width.max(e.height).max(e.depth).max(1);
    let chain = 32 - longest.leading_zeros();
    if info.mip_levels > chain {
        refuse(
            "VUID-VkImageCreateInfo-mipLevels-00958",
            format!(
                "mipLevels must be at most the {chain} levels of a full chain for extent {}x{}x{} (mipLevels = {})",
                e.width, e.height, e.depth, info.mip_levels
            ),
        )?;
    }
    let Some(limits) = image_creation_limits(device, info) else {
        return refuse(
            "VUID-VkImageCreateInfo-imageCreateMaxMipLevels-02251",
            format!(
                "the device supports no image of format {:?}, type {:?}, tiling {:?}, usage {:?} and flags {:?}",
                info.format, info.image_type, info.tiling, info.usage, info.flags
            ),
        );
    };
    let m = limits.max_extent;
    for (vuid, dim, value, max) in [
        (
            "VUID-VkImageCreateInfo-extent-02252",
            "width",
            e.width,
            m.width,
        ),
        (
            "VUID-VkImageCreateInfo-extent-02253",
            "height",
            e.height,
            m.height,
        ),
        (
            "VUID-VkImageCreateInfo-extent-02254",
            "depth",
            e.depth,
            m.depth,
        ),
    ] {
        if value > max {
            refuse(
                vuid,
                format!("extent.{dim} must be at most the format's {max} (extent.{dim} = {value})"),
            )?;
        }
    }
    if info.mip_levels > limits.max_mip_levels {
        refuse(
            "VUID-VkImageCreateInfo-mipLevels-02255",
            format!(
                "mipLevels must be at most the format's {} (mipLevels = {})",
                limits.max_mip_levels, info.mip_levels
            ),
        )?;
    }
    if info.array_layers > limits.max_array_layers {
        refuse(
            "VUID-VkImageCreateInfo-arrayLayers-02256",
            format!(
                "arrayLayers must be at most the format's {} (arrayLayers = {})",
                limits.max_array_layers, info.array_layers
            ),
        )?;
    }
    if !limits.sample_counts.contains(info.samples) {
        refuse(
            "VUID-VkImageCreateInfo-samples-02258",
            format!(
                "samples must be one of the format's {:?} (samples = {:?})",
                limits.sample_counts, info.samples
            ),
        )?;
    }
    Ok(())
}

/// A sample count a sparse format query asks about is one the format supports for
/// the type, usage and tiling (as `vkGetPhysicalDeviceImageFormatProperties`
/// reports, for an image created with the sparse flags the query is about).
pub(crate) fn sparse_samples(
    physical: &PhysicalDevice,
    (format, ty, samples, usage, tiling): (
        vk::Format,
        vk::ImageType,
        vk::SampleCountFlags,
        vk::ImageUsageFlags,
        vk::ImageTiling,
    ),
    vuid: &'static str,
) -> Result<()> {
    // SAFETY: a live physical device of its instance; the values passed the implicit
    // checks (valid enums and flags).
    let properties = unsafe {
        physical
            .parent()
            .fns()
            .get_physical_device_image_format_properties(
                physical.raw(),
                format,
                ty,
                tiling,
                usage,
                vk::ImageCreateFlags::empty(),
            )
    };
    let supported = properties.map_or(vk::SampleCountFlags::empty(), |p| p.sample_counts);
    if !supported.contains(samples) {
        refuse(
            vuid,
            format!(
                "`samples` must be a bit value that is set in \
                 `VkImageFormatProperties::sampleCounts` returned by \
                 `vkGetPhysicalDeviceImageFormatProperties` with `format`, `type`, `tiling` \
                 and `usage` (`samples` = {samples:?}, sampleCounts = {supported:?})"
            ),
        )?;
    }
    Ok(())
}

/// As [`sparse_samples`], for the `2` query's info.
pub(crate) fn sparse_samples2(
    physical: &PhysicalDevice,
    format_info: &PhysicalDeviceSparseImageFormatInfo2<'_>,
) -> Result<()> {
    let f = format_info.as_raw();
    sparse_samples(
        physical,
        (f.format, f.ty, f.samples, f.usage, f.tiling),
        "VUID-VkPhysicalDeviceSparseImageFormatInfo2-samples-01095",
    )
}

/// As [`sparse_buffer_hold`], for a sparse image (`VUID-vkCreateImage-flags-00939`).
pub(crate) fn sparse_image_hold<'d>(
    device: &'d Device,
    create_info: &ImageCreateInfo<'_>,
) -> Result<Option<tuff_runtime::VutexGuard<'d, ()>>> {
    if !create_info
        .flags
        .contains(vk::ImageCreateFlags::SPARSE_BINDING)
    {
        return Ok(None);
    }
    let gate = device.live().sparse_gate();
    let required = sparse_image_requirement(device, create_info.as_raw());
    let total = device.live().sparse_total();
    let limit = limits(device).sparse_address_space_size;
    if total.saturating_add(required) > limit {
        refuse(
            "VUID-vkCreateImage-flags-00939",
            format!("this sparse image requires {required} bytes, which with the {total} live sparse resources require is more than sparseAddressSpaceSize ({limit})"),
        )?;
    }
    Ok(Some(gate))
}

/// The memory a sparse image of this create info requires, from
/// `vkGetDeviceImageMemoryRequirements` (without creating it), or, where the device
/// is older than Vulkan 1.3, a bound above it: every texel of every level, layer and
/// sample at the bytes of all its aspects' blocks and at least 16, rounded up to
/// 64 KiB, the largest sparse block size.
fn sparse_image_requirement(device: &Device, info: &vk::ImageCreateInfo<'_>) -> u64 {
    let planes = crate::formats::aspects(info.format)
        .filter(|_| info.flags.contains(vk::ImageCreateFlags::DISJOINT))
        .map_or(0, |a| (a.as_raw() >> 4).count_ones());
    if vulkan13_properties(device).is_some() {
        // A disjoint image's planes are asked for one by one.
        let aspects: Vec<vk::ImageAspectFlags> = if planes == 0 {
            vec![vk::ImageAspectFlags::NONE]
        } else {
            (0..planes)
                .map(|p| vk::ImageAspectFlags::from_raw(0x10 << p))
                .collect()
        };
        return aspects
            .into_iter()
            .map(|plane| {
                let asked = vk::DeviceImageMemoryRequirements::default()
                    .create_info(info)
                    .plane_aspect(plane);
                let mut out = vk::MemoryRequirements2::default();
                // SAFETY: a live Vulkan 1.3 device; the create info passed the
                // implicit checks, and a disjoint one's plane is named.
                unsafe {
                    device
                        .fns()
                        .get_device_image_memory_requirements(&asked, &mut out)
                };
                out.memory_requirements.size
            })
            .fold(0, u64::saturating_add);
    }
    let aspects = crate::formats::aspects(info.format).unwrap_or(vk::ImageAspectFlags::COLOR);
    let bytes = (0..7)
        .map(|b| vk::ImageAspectFlags::from_raw(1 << b))
        .filter(|a| aspects.contains(*a))
        .filter_map(|a| crate::formats::block(info.format, a).map(|b| u64::from(b.0)))
        .sum::<u64>()
        .max(16);
    let e = info.extent;
    let texels: u64 = (0..info.mip_levels.min(32))
        .map(|l| {
            u64::from((e.width >> l).max(1))
                * u64::from((e.height >> l).max(1))
                * u64::from((e.depth >> l).max(1))
        })
        .sum();
    let total = texels
        .saturating_mul(bytes)
        .saturating_mul(u64::from(info.array_layers))
        .saturating_mul(u64::from(info.samples.as_raw().max(1)));
    total.div_ceil(1 << 16).saturating_mul(1 << 16)
}

/// Whether `format` is a block-compressed format (its texel blocks span more than
/// one texel, and it is not one of the 4:2:2 formats, whose blocks also do).
pub(super) fn compressed(format: vk::Format) -> bool {
    let subsampled = (1_000_156_000..1_000_157_000).contains(&format.as_raw());
    crate::formats::block(format, vk::ImageAspectFlags::COLOR)
        .is_some_and(|(_, [w, h, _])| (w > 1 || h > 1) && !subsampled)
}

/// The checks of `vkCreateImage` that relate its type, extent, flags, usage and
/// format to each other and to a chained stencil usage or format list. They come
/// before the checks that ask the physical device about the image.
pub(crate) fn image_create_rules(device: &Device, create_info: &ImageCreateInfo<'_>) -> Result<()> {
    let info = create_info.as_raw();
    let (flags, usage, e) = (info.flags, info.usage, info.extent);
    if info.image_type == vk::ImageType::TYPE_1D && (e.height != 1 || e.depth != 1) {
        refuse(
            "VUID-VkImageCreateInfo-imageType-00956",
            format!(
                "a 1D image has height and depth 1 (extent = {}x{}x{})",
                e.width, e.height, e.depth
            ),
        )?;
    }
    if info.image_type == vk::ImageType::TYPE_2D
        && flags.contains(vk::ImageCreateFlags::CUBE_COMPATIBLE)
        && (e.width != e.height || info.array_layers < 6)
    {
        refuse(
            "VUID-VkImageCreateInfo-imageType-00954",
            format!("a cube-compatible image is square with at least 6 layers (extent = {}x{}, arrayLayers = {})", e.width, e.height, info.array_layers),
        )?;
    }
    let attachments = vk::ImageUsageFlags::COLOR_ATTACHMENT
        | vk::ImageUsageFlags::DEPTH_STENCIL_ATTACHMENT
        | vk::ImageUsageFlags::INPUT_ATTACHMENT;
    if usage.contains(vk::ImageUsageFlags::TRANSIENT_ATTACHMENT) && !usage.intersects(attachments) {
        refuse(
            "VUID-VkImageCreateInfo-usage-00966",
            format!("a transient image is an attachment too (usage = {usage:?})"),
        )?;
    }
    if info.samples != vk::SampleCountFlags::TYPE_1
        && (info.image_type != vk::ImageType::TYPE_2D
            || flags.contains(vk::ImageCreateFlags::CUBE_COMPATIBLE)
            || info.mip_levels != 1
            || info.tiling == vk::ImageTiling::LINEAR)
    {
        refuse(
            "VUID-VkImageCreateInfo-samples-02257",
            format!("a multisampled image ({:?}) is an optimal 2D image of one level, not cube-compatible", info.samples),
        )?;
    }
    if flags.contains(vk::ImageCreateFlags::BLOCK_TEXEL_VIEW_COMPATIBLE) && !compressed(info.format)
    {
        refuse(
            "VUID-VkImageCreateInfo-flags-01572",
            format!(
                "a block-texel-view-compatible image has a compressed format, not {:?}",
                info.format
            ),
        )?;
    }
    let planes = vk::ImageAspectFlags::PLANE_0;
    let multi_planar = crate::formats::aspects(info.format).is_some_and(|a| a.contains(planes));
    if flags.contains(vk::ImageCreateFlags::DISJOINT)
        && !multi_planar
        && !flags.contains(vk::ImageCreateFlags::ALIAS)
    {
        refuse(
            "VUID-VkImageCreateInfo-format-01577",
            format!(
                "a disjoint image has a multi-planar format, not {:?}",
                info.format
            ),
        )?;
    }
    let limits = limits(device);
    let max = (limits.max_framebuffer_width, limits.max_framebuffer_height);
    if usage.intersects(attachments | vk::ImageUsageFlags::TRANSIENT_ATTACHMENT) {
        if e.width > max.0 {
            refuse(
                "VUID-VkImageCreateInfo-usage-00964",
                format!(
                    "an attachment image is at most maxFramebufferWidth ({}) wide, not {}",
                    max.0, e.width
                ),
            )?;
        }
        if e.height > max.1 {
            refuse(
                "VUID-VkImageCreateInfo-usage-00965",
                format!(
                    "an attachment image is at most maxFramebufferHeight ({}) high, not {}",
                    max.1, e.height
                ),
            )?;
        }
    }
    // SAFETY: the `pNext` of a safe struct, and the types the sTypes name.
    let (stencil, list) = unsafe {
        (
            chained::<vk::ImageStencilUsageCreateInfo<'_>>(
                info.p_next,
                vk::StructureType::IMAGE_STENCIL_USAGE_CREATE_INFO,
            ),
            chained::<vk::ImageFormatListCreateInfo<'_>>(
                info.p_next,
                vk::StructureType::IMAGE_FORMAT_LIST_CREATE_INFO,
            ),
        )
    };
    let depth_stencil = crate::formats::aspects(info.format)
        .is_some_and(|a| a.intersects(vk::ImageAspectFlags::DEPTH | vk::ImageAspectFlags::STENCIL));
    if let Some(stencil) = stencil.filter(|_| depth_stencil) {
        let s = stencil.stencil_usage;
        for (bit, given, vuid) in [
            (
                vk::ImageUsageFlags::DEPTH_STENCIL_ATTACHMENT,
                true,
                "VUID-VkImageCreateInfo-format-02795",
            ),
            (
                vk::ImageUsageFlags::DEPTH_STENCIL_ATTACHMENT,
                false,
                "VUID-VkImageCreateInfo-format-02796",
            ),
            (
                vk::ImageUsageFlags::TRANSIENT_ATTACHMENT,
                true,
                "VUID-VkImageCreateInfo-format-02797",
            ),
            (
                vk::ImageUsageFlags::TRANSIENT_ATTACHMENT,
                false,
                "VUID-VkImageCreateInfo-format-02798",
            ),
        ] {
            if usage.contains(bit) == given && s.contains(bit) != given {
                refuse(
                    vuid,
                    format!("the stencil usage {s:?} must {}include {bit:?}, as the usage {usage:?} does{}", if given { "" } else { "not " }, if given { "" } else { " not" }),
                )?;
            }
        }
        if s.contains(vk::ImageUsageFlags::INPUT_ATTACHMENT) {
            if e.width > max.0 {
                refuse(
                    "VUID-VkImageCreateInfo-Format-02536",
                    format!("a stencil input attachment is at most maxFramebufferWidth ({}) wide, not {}", max.0, e.width),
                )?;
            }
            if e.height > max.1 {
                refuse(
                    "VUID-VkImageCreateInfo-format-02537",
                    format!("a stencil input attachment is at most maxFramebufferHeight ({}) high, not {}", max.1, e.height),
                )?;
            }
        }
    }
    if let Some(list) = list {
        if !flags.contains(vk::ImageCreateFlags::MUTABLE_FORMAT) && list.view_format_count > 1 {
            refuse(
                "VUID-VkImageCreateInfo-flags-04738",
                format!(
                    "an image without MUTABLE_FORMAT lists at most one view format, not {}",
                    list.view_format_count
                ),
            )?;
        }
        // SAFETY: the safe setter stores the formats with their count.
        let views = unsafe { crate::state::raw_slice(list.p_view_formats, list.view_format_count) };
        let class = crate::formats::class(info.format);
        let block_texel = flags.contains(vk::ImageCreateFlags::BLOCK_TEXEL_VIEW_COMPATIBLE);
        let size = crate::formats::block(info.format, vk::ImageAspectFlags::COLOR).map(|b| b.0);
        for (i, v) in views.iter().enumerate() {
            let same_class = class.is_some() && crate::formats::class(*v) == class;
            let size_compatible = block_texel
                && !compressed(*v)
                && size.is_some()
                && crate::formats::block(*v, vk::ImageAspectFlags::COLOR).map(|b| b.0) == size;
            if !same_class && !size_compatible {
                refuse(
                    "VUID-VkImageCreateInfo-pNext-06722",
                    format!("pViewFormats[{i}] ({v:?}) is not compatible with the image's format ({:?})", info.format),
                )?;
            }
        }
    }
    sharing_and_group_rules(device, info)?;
    chroma_rules(device, info, stencil)?;
    #[cfg(feature = "khr_swapchain")]
    swapchain_image_rules(device, info)?;
    Ok(())
}

/// An image made for a swapchain's memory has the swapchain's implied image
/// creation parameters (`VUID-VkImageSwapchainCreateInfoKHR-swapchain-00995`).
#[cfg(feature = "khr_swapchain")]
fn swapchain_image_rules(device: &Device, info: &vk::ImageCreateInfo<'_>) -> Result<()> {
    // SAFETY: the `pNext` of a safe struct, and the type the sType names.
    let chained: Option<&vk::ImageSwapchainCreateInfoKHR<'_>> = unsafe {
        chained(
            info.p_next,
            vk::StructureType::IMAGE_SWAPCHAIN_CREATE_INFO_KHR,
        )
    };
    let Some(swapchain) = chained
        .map(|c| c.swapchain)
        .filter(|s| *s != vk::SwapchainKHR::null())
    else {
        return Ok(());
    };
    let Some(implied) = device.live().swapchain(swapchain) else {
        return Ok(());
    };
    let made = crate::state::ImageRecord {
        flags: info.flags,
        image_type: info.image_type,
        format: info.format,
        extent: info.extent,
        mip_levels: info.mip_levels,
        array_layers: info.array_layers,
        usage: info.usage,
        tiling: info.tiling,
        samples: info.samples,
        stencil_usage: implied.stencil_usage,
        sharing: info.sharing_mode,
        families: family_bits(info.sharing_mode, info),
        bound: implied.bound,
        external: implied.external,
        for_swapchain: implied.for_swapchain,
    };
    let matches = made.flags == implied.flags
        && made.image_type == implied.image_type
        && made.format == implied.format
        && made.extent == implied.extent
        && made.mip_levels == implied.mip_levels
        && made.array_layers == implied.array_layers
        && made.usage == implied.usage
        && made.tiling == implied.tiling
        && made.sharing == implied.sharing
        && made.families == implied.families
        && info.samples == vk::SampleCountFlags::TYPE_1
        && info.initial_layout == vk::ImageLayout::UNDEFINED;
    if !matches {
        refuse(
            "VUID-VkImageSwapchainCreateInfoKHR-swapchain-00995",
            format!("the image's parameters ({made:?}, {:?}, {:?}) are not the swapchain's implied ones ({implied:?}, one sample, UNDEFINED)", info.samples, info.initial_layout),
        )?;
    }
    Ok(())
}

/// An image's sharing, sparse, external and device-group parameters against each
/// other and the device.
fn sharing_and_group_rules(device: &Device, info: &vk::ImageCreateInfo<'_>) -> Result<()> {
    let flags = info.flags;
    if info.sharing_mode == vk::SharingMode::CONCURRENT {
        // SAFETY: the safe setter stores the indices with their count.
        let families = unsafe {
            crate::state::raw_slice(info.p_queue_family_indices, info.queue_family_index_count)
        };
        concurrent_families(
            device.parent(),
            families,
            "VUID-VkImageCreateInfo-sharingMode-01420",
        )?;
    }
    let sparse = vk::ImageCreateFlags::SPARSE_BINDING
        | vk::ImageCreateFlags::SPARSE_RESIDENCY
        | vk::ImageCreateFlags::SPARSE_ALIASED;
    if flags.intersects(sparse) {
        if info
            .usage
            .contains(vk::ImageUsageFlags::TRANSIENT_ATTACHMENT)
        {
            refuse(
                "VUID-VkImageCreateInfo-None-01925",
                format!("a sparse image ({flags:?}) is not a transient attachment"),
            )?;
        }
        if flags.contains(vk::ImageCreateFlags::PROTECTED) {
            refuse(
                "VUID-VkImageCreateInfo-None-01891",
                format!("a sparse image ({flags:?}) is not protected"),
            )?;
        }
    }
    let split = vk::ImageCreateFlags::SPLIT_INSTANCE_BIND_REGIONS;
    if flags.contains(split) {
        let maybe_linear = info.tiling == vk::ImageTiling::LINEAR;
        if info.mip_levels != 1
            || info.array_layers != 1
            || info.image_type != vk::ImageType::TYPE_2D
            || maybe_linear
        {
            refuse(
                "VUID-VkImageCreateInfo-flags-02259",
                format!("an image with SPLIT_INSTANCE_BIND_REGIONS is an optimal 2D image of one level and one layer (mipLevels = {}, arrayLayers = {}, {:?}, {:?})", info.mip_levels, info.array_layers, info.image_type, info.tiling),
            )?;
        }
        if device.live().physical_count() == 1 {
            refuse(
                "VUID-VkImageCreateInfo-physicalDeviceCount-01421",
                "an image with SPLIT_INSTANCE_BIND_REGIONS needs a device of more than one physical device",
            )?;
        }
    }
    let external = external_handle_types(info.p_next);
    if !external.is_empty() && info.initial_layout != vk::ImageLayout::UNDEFINED {
        refuse(
            "VUID-VkImageCreateInfo-pNext-01443",
            format!(
                "an image with external handle types starts in UNDEFINED, not {:?}",
                info.initial_layout
            ),
        )?;
    }
    let physical = device.parent();
    for handle in each_bit(external) {
        let (r, props) = external_image_properties(
            physical,
            vk::PhysicalDeviceImageFormatInfo2::default()
                .format(info.format)
                .ty(info.image_type)
                .tiling(info.tiling)
                .usage(info.usage)
                .flags(info.flags),
            handle,
        );
        let compatible = props.compatible_handle_types;
        if r != vk::Result::SUCCESS || !compatible.contains(external) {
            refuse(
                "VUID-VkImageCreateInfo-pNext-00990",
                format!("the external handle types {external:?} are not all compatible with {handle:?} for this image: the physical device reports {compatible:?} ({r:?})"),
            )?;
        }
    }
    Ok(())
}

/// The rules of formats that need a sampler Y'CbCr conversion and of multi-planar
/// ones, and of a multisampled depth/stencil image's stencil storage usage.
fn chroma_rules(
    device: &Device,
    info: &vk::ImageCreateInfo<'_>,
    stencil: Option<&vk::ImageStencilUsageCreateInfo<'_>>,
) -> Result<()> {
    let (format, e) = (info.format, info.extent);
    if let Some(chroma) = crate::formats::chroma(format) {
        if info.mip_levels != 1 {
            refuse(
                "VUID-VkImageCreateInfo-format-06410",
                format!("an image of {format:?}, which needs a Y'CbCr conversion, has one level, not {}", info.mip_levels),
            )?;
        }
        if info.samples != vk::SampleCountFlags::TYPE_1 {
            refuse(
                "VUID-VkImageCreateInfo-format-06411",
                format!("an image of {format:?}, which needs a Y'CbCr conversion, has one sample, not {:?}", info.samples),
            )?;
        }
        if info.image_type != vk::ImageType::TYPE_2D {
            refuse(
                "VUID-VkImageCreateInfo-format-06412",
                format!(
                    "an image of {format:?}, which needs a Y'CbCr conversion, is 2D, not {:?}",
                    info.image_type
                ),
            )?;
        }
        if matches!(chroma, 420 | 422) && e.width % 2 != 0 {
            refuse(
                "VUID-VkImageCreateInfo-format-04712",
                format!("an image of {format:?} has an even width, not {}", e.width),
            )?;
        }
        if chroma == 420 && e.height % 2 != 0 {
            refuse(
                "VUID-VkImageCreateInfo-format-04713",
                format!(
                    "an image of {format:?} has an even height, not {}",
                    e.height
                ),
            )?;
        }
    }
    let multi_planar =
        crate::formats::aspects(format).is_some_and(|a| a.contains(vk::ImageAspectFlags::PLANE_0));
    if multi_planar && info.flags.contains(vk::ImageCreateFlags::DISJOINT) {
        let props = device.parent().get_format_properties(format)?;
        let features = if info.tiling == vk::ImageTiling::LINEAR {
            props.linear_tiling_features
        } else {
            props.optimal_tiling_features
        };
        if !features.contains(vk::FormatFeatureFlags::DISJOINT) {
            refuse(
                "VUID-VkImageCreateInfo-imageCreateFormatFeatures-02260",
                format!("a disjoint image of {format:?} needs VK_FORMAT_FEATURE_DISJOINT_BIT, which the format's {:?} features lack", info.tiling),
            )?;
        }
    }
    let depth_stencil = crate::formats::aspects(format)
        .is_some_and(|a| a.intersects(vk::ImageAspectFlags::DEPTH | vk::ImageAspectFlags::STENCIL));
    let storage_stencil =
        stencil.is_some_and(|s| s.stencil_usage.contains(vk::ImageUsageFlags::STORAGE));
    if depth_stencil
        && storage_stencil
        && info.samples != vk::SampleCountFlags::TYPE_1
        && device.live().features().shader_storage_image_multisample == vk::FALSE
    {
        refuse(
            "VUID-VkImageCreateInfo-format-02538",
            format!("a multisampled ({:?}) depth/stencil image with a storage stencil usage needs shaderStorageImageMultisample", info.samples),
        )?;
    }
    Ok(())
}

/// `vkGetImageSubresourceLayout`: a linear image (or, where the DRM format modifier
/// extension made one, an image of that tiling, whose aspects are that extension's
/// rules), a level and layer it has, and one aspect of its format.
pub(crate) fn subresource_layout_checks(
    device: &Device,
    image: &Image,
    subresource: &vk::ImageSubresource,
) -> Result<()> {
    let Some(record) = device.live().image(image.raw()) else {
        return Ok(());
    };
    let tiling = record.tiling;
    if tiling != vk::ImageTiling::LINEAR && tiling != vk::ImageTiling::DRM_FORMAT_MODIFIER_EXT {
        refuse(
            "VUID-vkGetImageSubresourceLayout-image-07789",
            format!("the image's tiling is {tiling:?}, not LINEAR"),
        )?;
    }
    let aspect = subresource.aspect_mask;
    if aspect.as_raw().count_ones() != 1 {
        refuse(
            "VUID-vkGetImageSubresourceLayout-aspectMask-00997",
            format!("aspectMask {aspect:?} is not one aspect"),
        )?;
    }
    if subresource.mip_level >= record.mip_levels {
        refuse(
            "VUID-vkGetImageSubresourceLayout-mipLevel-01716",
            format!(
                "mipLevel {} is not one of the image's {} levels",
                subresource.mip_level, record.mip_levels
            ),
        )?;
    }
    if subresource.array_layer >= record.array_layers {
        refuse(
            "VUID-vkGetImageSubresourceLayout-arrayLayer-01717",
            format!(
                "arrayLayer {} is not one of the image's {} layers",
                subresource.array_layer, record.array_layers
            ),
        )?;
    }
    if tiling != vk::ImageTiling::LINEAR {
        return Ok(());
    }
    type F = vk::ImageAspectFlags;
    let has = crate::formats::aspects(record.format).unwrap_or(F::COLOR);
    let format = record.format;
    let planes = [F::PLANE_0, F::PLANE_1, F::PLANE_2]
        .into_iter()
        .filter(|p| has.contains(*p))
        .count();
    let refused = match planes {
        2 if aspect != F::PLANE_0 && aspect != F::PLANE_1 => Some((
            "VUID-vkGetImageSubresourceLayout-format-01581",
            "PLANE_0 or PLANE_1",
        )),
        3 if ![F::PLANE_0, F::PLANE_1, F::PLANE_2].contains(&aspect) => Some((
            "VUID-vkGetImageSubresourceLayout-format-01582",
            "PLANE_0, PLANE_1 or PLANE_2",
        )),
        0 if has == F::COLOR && aspect != F::COLOR => {
            Some(("VUID-vkGetImageSubresourceLayout-format-04461", "COLOR"))
        }
        // Read as written: a format with both depth and stencil takes no single
        // aspect, as the aspect must contain each.
        0 if has.contains(F::DEPTH) && !aspect.contains(F::DEPTH) => {
            Some(("VUID-vkGetImageSubresourceLayout-format-04462", "DEPTH"))
        }
        0 if has.contains(F::STENCIL) && !aspect.contains(F::STENCIL) => {
            Some(("VUID-vkGetImageSubresourceLayout-format-04463", "STENCIL"))
        }
        _ => None,
    };
    if let Some((vuid, wanted)) = refused {
        refuse(
            vuid,
            format!("aspectMask is {aspect:?}, and an image of {format:?} takes {wanted}"),
        )?;
    }
    if !has.intersects(F::DEPTH | F::STENCIL) && aspect.intersects(F::DEPTH | F::STENCIL) {
        refuse(
            "VUID-vkGetImageSubresourceLayout-format-04464",
            format!("aspectMask is {aspect:?}, and {format:?} has no depth or stencil"),
        )?;
    }
    Ok(())
}

/// The format features of an image's format for its tiling (the device asks the
/// physical device once per format).
pub(crate) fn tiling_features(
    device: &Device,
    image: &ImageRecord,
) -> Result<vk::FormatFeatureFlags> {
    let props = device
        .live()
        .format_properties(device.parent(), image.format)?;
    Ok(if image.tiling == vk::ImageTiling::LINEAR {
        props.linear_tiling_features
    } else {
        props.optimal_tiling_features
    })
}

/// Where two images' bindings, as the device recorded them, share bytes of one
/// memory: the message to refuse with; `None` when they are apart or either has no
/// binding recorded. Where in its binding a region of an optimally tiled image lies
/// is the driver's, so a command between two such images cannot tell more.
pub(crate) fn bindings_overlap(
    live: &crate::state::Live,
    a: vk::Image,
    b: vk::Image,
) -> Option<String> {
    let ((am, aoff, asize), (bm, boff, bsize)) = (live.binding(a)?, live.binding(b)?);
    let apart =
        am != bm || aoff.saturating_add(asize) <= boff || boff.saturating_add(bsize) <= aoff;
    (!apart).then(|| {
        format!("the source's memory ({aoff}..+{asize}) and the destination's ({boff}..+{bsize}) overlap")
    })
}
