//! Swapchains and presentation: creation, image acquisition and presents (the images
//! presented, their layouts, device groups).

use super::buffer::concurrent_families;
use super::image::family_bits;
#[cfg(feature = "khr_surface")]
use super::surface::surface_supported;
use super::{chained, refuse};
use crate::handles::*;
use crate::state::ImageRecord;
use crate::structs::*;
use crate::submission::{self};
use crate::{Error, Handle, Result};
use ash::vk;
use smallvec::SmallVec;

/// As [`queue_bind_sparse_hold`], for `vkQueuePresentKHR`'s waits.
#[cfg(feature = "khr_swapchain")]
pub(crate) fn queue_present_khr_hold<'q>(
    queue: &'q Queue,
    present_info: &PresentInfoKHR<'_>,
) -> Result<tuff_runtime::VutexGuard<'q, ()>> {
    let gate = queue.parent().live().descriptor_gate();
    // SAFETY: the safe struct stores the array with its length.
    let waits = unsafe {
        crate::state::raw_slice(
            present_info.p_wait_semaphores,
            present_info.wait_semaphore_count,
        )
    };
    let ops: Vec<submission::SemOp> = waits.iter().map(|s| submission::SemOp::Wait(*s)).collect();
    submission::check_binary_ops(
        queue.parent(),
        queue.raw(),
        &ops,
        &submission::PRESENT_BINARY,
    )?;
    Ok(gate)
}

/// Refuses timeline semaphores.
#[cfg(feature = "khr_swapchain")]
pub(crate) fn queue_present_khr_checks(
    queue: &Queue,
    present_info: &PresentInfoKHR<'_>,
) -> Result<()> {
    // SAFETY: the safe struct stores the array with its length.
    let waits = unsafe {
        crate::state::raw_slice(
            present_info.p_wait_semaphores,
            present_info.wait_semaphore_count,
        )
    };
    submission::check_semaphore_type(
        queue.parent().live(),
        waits,
        false,
        "VUID-vkQueuePresentKHR-pWaitSemaphores-03267",
    )?;
    let ops: Vec<submission::SemOp> = waits.iter().map(|s| submission::SemOp::Wait(*s)).collect();
    submission::check_binary_ops(
        queue.parent(),
        queue.raw(),
        &ops,
        &submission::PRESENT_BINARY,
    )?;
    check_presented_images(queue.parent(), present_info)?;
    check_surface_support(queue, present_info)?;
    check_device_group_present(queue.parent(), present_info)
}

/// Refuses a swapchain whose surface the queue's family cannot present to, as
/// `vkGetPhysicalDeviceSurfaceSupportKHR` says (asked once per swapchain and family).
#[cfg(feature = "khr_swapchain")]
fn check_surface_support(queue: &Queue, present_info: &PresentInfoKHR<'_>) -> Result<()> {
    let device = queue.parent();
    let Some(family) = device.live().queue_family(queue.raw()) else {
        return Ok(());
    };
    // SAFETY: the safe setter stores the array with its count.
    let swapchains =
        unsafe { crate::state::raw_slice(present_info.p_swapchains, present_info.swapchain_count) };
    for (n, swapchain) in swapchains.iter().enumerate() {
        if device.live().presents_from(*swapchain, family) {
            continue;
        }
        let Some(surface) = device.live().swapchain_surface(*swapchain) else {
            continue;
        };
        let fp = device
            .parent()
            .parent()
            .ext()
            .khr_surface
            .as_ref()
            .ok_or(Error::ExtensionNotEnabled("VK_KHR_surface"))?
            .get_physical_device_surface_support_khr;
        let mut supported = vk::FALSE;
        // SAFETY: the physical device of the device, a family the device has a queue
        // of, and the live surface of a live swapchain (its wrapper keeps it alive).
        let r = unsafe { fp(device.parent().raw(), family, surface, &mut supported) };
        if r.as_raw() < 0 {
            return Err(Error::Vk(r));
        }
        if supported != vk::TRUE {
            return refuse(
                "VUID-vkQueuePresentKHR-pSwapchains-01292",
                format!("the surface of pSwapchains[{n}] does not support presentation from the queue's family {family}"),
            );
        }
        device.live().set_presents_from(*swapchain, family);
    }
    Ok(())
}

/// `VkDeviceGroupPresentCapabilitiesKHR::presentMask`, read once (a device of one
/// physical device that cannot ask presents from it alone).
#[cfg(feature = "khr_swapchain")]
fn present_masks(device: &Device) -> Result<[u32; vk::MAX_DEVICE_GROUP_SIZE]> {
    if let Some(masks) = device.live().present_masks() {
        return Ok(masks);
    }
    let mut masks = [0; vk::MAX_DEVICE_GROUP_SIZE];
    masks[0] = 1;
    if device.exts().version(1) {
        let mut caps = DeviceGroupPresentCapabilitiesKHR::new();
        device.get_group_present_capabilities_khr(&mut caps)?;
        masks = caps.present_mask;
    }
    device.live().set_present_masks(masks);
    Ok(masks)
}

/// The rules of a chained `VkDeviceGroupPresentInfoKHR`: its count, each device
/// mask against the mode and the devices that can present, against the mask its
/// image was acquired with, and the mode against the swapchain's modes.
#[cfg(feature = "khr_swapchain")]
fn check_device_group_present(device: &Device, present_info: &PresentInfoKHR<'_>) -> Result<()> {
    let info = present_info.as_raw();
    // SAFETY: the chain of a safe struct, and the type its sType names.
    let Some(group) = (unsafe {
        chained::<vk::DeviceGroupPresentInfoKHR<'_>>(
            info.p_next,
            vk::StructureType::DEVICE_GROUP_PRESENT_INFO_KHR,
        )
    }) else {
        return Ok(());
    };
    if group.swapchain_count != 0 && group.swapchain_count != info.swapchain_count {
        return refuse(
            "VUID-VkDeviceGroupPresentInfoKHR-swapchainCount-01297",
            format!(
                "swapchainCount is {}, and VkPresentInfoKHR::swapchainCount is {}",
                group.swapchain_count, info.swapchain_count
            ),
        );
    }
    // SAFETY: the safe setters store each array with its count.
    let (masks, swapchains, indices) = unsafe {
        (
            crate::state::raw_slice(group.p_device_masks, group.swapchain_count),
            crate::state::raw_slice(info.p_swapchains, info.swapchain_count),
            crate::state::raw_slice(info.p_image_indices, info.swapchain_count),
        )
    };
    let present = present_masks(device)?;
    let can_present = |bit: u32| present.get(bit as usize).is_some_and(|m| *m != 0);
    let bits = |mask: u32| (0..32).filter(move |b| mask & (1 << b) != 0);
    type Mode = vk::DeviceGroupPresentModeFlagsKHR;
    for (n, mask) in masks.iter().enumerate() {
        let one_bit = mask.count_ones() == 1;
        let (vuid, ok) = match group.mode {
            Mode::LOCAL => (
                "VUID-VkDeviceGroupPresentInfoKHR-mode-01298",
                one_bit && bits(*mask).all(can_present),
            ),
            Mode::REMOTE => (
                "VUID-VkDeviceGroupPresentInfoKHR-mode-01299",
                one_bit && present.iter().any(|p| p & mask != 0),
            ),
            Mode::SUM => (
                "VUID-VkDeviceGroupPresentInfoKHR-mode-01300",
                present.iter().any(|p| p & mask == *mask),
            ),
            Mode::LOCAL_MULTI_DEVICE => (
                "VUID-VkDeviceGroupPresentInfoKHR-mode-01301",
                bits(*mask).all(can_present),
            ),
            _ => ("", true),
        };
        if !ok {
            return refuse(
                vuid,
                format!(
                    "pDeviceMasks[{n}] = {mask:#x} does not suit mode {:?} with the device group's presentMask {:x?}",
                    group.mode, &present[..device.live().physical_count().clamp(1, 32) as usize]
                ),
            );
        }
        let acquired = swapchains
            .get(n)
            .zip(indices.get(n))
            .and_then(|(s, i)| device.live().acquired_image(*s, *i).ok());
        if let Some((_, acquired_mask)) = acquired {
            if acquired_mask != *mask {
                return refuse(
                    "VUID-VkDeviceGroupPresentInfoKHR-pDeviceMasks-01302",
                    format!("pDeviceMasks[{n}] = {mask:#x}, and the image was acquired with device mask {acquired_mask:#x}"),
                );
            }
        }
    }
    for (n, swapchain) in swapchains.iter().enumerate() {
        let modes = device.live().swapchain_modes(*swapchain);
        if group.mode.as_raw().count_ones() != 1 || !modes.contains(group.mode) {
            return refuse(
                "VUID-VkDeviceGroupPresentInfoKHR-mode-01303",
                format!(
                    "mode is {:?}, and pSwapchains[{n}] was created for modes {modes:?}",
                    group.mode
                ),
            );
        }
    }
    Ok(())
}

/// Refuses an image index that is not acquired, or whose image the submissions so
/// far leave in a layout other than `PRESENT_SRC_KHR` (or `SHARED_PRESENT_KHR`).
#[cfg(feature = "khr_swapchain")]
fn check_presented_images(device: &Device, present_info: &PresentInfoKHR<'_>) -> Result<()> {
    const VUID: &str = "VUID-VkPresentInfoKHR-pImageIndices-01296";
    let info = present_info.as_raw();
    // SAFETY: the safe setter stores both arrays with the one count.
    let (swapchains, indices) = unsafe {
        (
            crate::state::raw_slice(info.p_swapchains, info.swapchain_count),
            crate::state::raw_slice(info.p_image_indices, info.swapchain_count),
        )
    };
    for (n, (swapchain, index)) in swapchains.iter().zip(indices).enumerate() {
        match device.live().acquired_image(*swapchain, *index) {
            Ok((image, _)) => crate::state::layouts::check_device_layout(
                device.live(),
                image,
                &[
                    vk::ImageLayout::PRESENT_SRC_KHR,
                    vk::ImageLayout::SHARED_PRESENT_KHR,
                ],
                VUID,
            )?,
            Err(false) => refuse(
                VUID,
                format!("pImageIndices[{n}] = {index} is not an image acquired from pSwapchains[{n}] and not presented since"),
            )?,
            Err(true) => refuse(
                VUID,
                format!("image {index} of pSwapchains[{n}] was never returned by get_swapchain_images_khr, so no command made its layout PRESENT_SRC_KHR"),
            )?,
        }
    }
    Ok(())
}

/// Held before the call: a presentation the engine rejects still waits on its
/// semaphores. The queue holds it until it is known complete.
#[cfg(feature = "khr_swapchain")]
pub(crate) fn queue_present_khr_before(queue: &Queue, present_info: &PresentInfoKHR<'_>) {
    let device = queue.parent();
    let mut reached = crate::validation::Reached::keeping(device.live());
    // SAFETY: the safe struct stores every array with its length.
    unsafe { crate::reach::present_info_khr(present_info.as_raw(), &mut reached) };
    let sub = submission::submitted(
        device,
        queue.raw(),
        None,
        &[],
        reached.kept,
        Default::default(),
    );
    // SAFETY: the safe struct stores the array with its length.
    let waits = unsafe {
        crate::state::raw_slice(
            present_info.p_wait_semaphores,
            present_info.wait_semaphore_count,
        )
    };
    let ops: Vec<submission::SemOp> = waits.iter().map(|s| submission::SemOp::Wait(*s)).collect();
    submission::record_binary_ops(device, queue.raw(), &ops, Some(&sub));
    queue.hold(sub);
    let info = present_info.as_raw();
    // SAFETY: the safe setter stores both arrays with the one count.
    let (swapchains, indices) = unsafe {
        (
            crate::state::raw_slice(info.p_swapchains, info.swapchain_count),
            crate::state::raw_slice(info.p_image_indices, info.swapchain_count),
        )
    };
    for (swapchain, index) in swapchains.iter().zip(indices) {
        device.live().image_presented(*swapchain, *index);
    }
}

/// The image creation flags a swapchain's flags imply for its images (the
/// specification's implied image creation parameters).
#[cfg(feature = "khr_swapchain")]
fn swapchain_image_flags(flags: vk::SwapchainCreateFlagsKHR) -> vk::ImageCreateFlags {
    let mut image = vk::ImageCreateFlags::empty();
    if flags.contains(vk::SwapchainCreateFlagsKHR::SPLIT_INSTANCE_BIND_REGIONS) {
        image |= vk::ImageCreateFlags::SPLIT_INSTANCE_BIND_REGIONS;
    }
    if flags.contains(vk::SwapchainCreateFlagsKHR::PROTECTED) {
        image |= vk::ImageCreateFlags::PROTECTED;
    }
    if flags.contains(vk::SwapchainCreateFlagsKHR::MUTABLE_FORMAT) {
        image |= vk::ImageCreateFlags::MUTABLE_FORMAT | vk::ImageCreateFlags::EXTENDED_USAGE;
    }
    image
}

/// The device remembers what the swapchain's images are, as the images a
/// `VkImageCreateInfo` of its parameters would make (2D, one level, its extent,
/// layers and usage, bound), for [`swapchain_images`].
#[cfg(feature = "khr_swapchain")]
pub(crate) fn swapchain_created(
    device: &Device,
    swapchain: SwapchainKHR,
    surface: &SurfaceKHR,
    create_info: &SwapchainCreateInfoKHR<'_>,
) -> SwapchainKHR {
    device.live().swapchain_created(
        swapchain.raw(),
        surface.raw(),
        ImageRecord {
            flags: swapchain_image_flags(create_info.flags),
            image_type: vk::ImageType::TYPE_2D,
            format: create_info.image_format,
            extent: vk::Extent3D {
                width: create_info.image_extent.width,
                height: create_info.image_extent.height,
                depth: 1,
            },
            mip_levels: 1,
            array_layers: create_info.image_array_layers,
            usage: create_info.image_usage,
            tiling: vk::ImageTiling::OPTIMAL,
            samples: vk::SampleCountFlags::TYPE_1,
            stencil_usage: None,
            sharing: create_info.image_sharing_mode,
            families: family_bits(
                create_info.image_sharing_mode,
                &vk::ImageCreateInfo::default().queue_family_indices(
                    // SAFETY: the safe setter stores the indices with their count.
                    unsafe {
                        crate::state::raw_slice(
                            create_info.p_queue_family_indices,
                            create_info.queue_family_index_count,
                        )
                    },
                ),
            ),
            bound: true,
            external: vk::ExternalMemoryHandleTypeFlags::empty(),
            for_swapchain: true,
        },
        // SAFETY: the chain of a safe struct, and the type its sType names.
        unsafe {
            chained::<vk::DeviceGroupSwapchainCreateInfoKHR<'_>>(
                create_info.p_next,
                vk::StructureType::DEVICE_GROUP_SWAPCHAIN_CREATE_INFO_KHR,
            )
        }
        .map_or(vk::DeviceGroupPresentModeFlagsKHR::LOCAL, |g| g.modes),
    );
    swapchain
}

/// The swapchain's images get its record, so the checks of the commands that name
/// one read its size and usage as for any image.
#[cfg(feature = "khr_swapchain")]
pub(crate) fn swapchain_images(
    device: &Device,
    images: Vec<Image>,
    swapchain: &SwapchainKHR,
) -> Vec<Image> {
    let raw: SmallVec<[vk::Image; 8]> = images.iter().map(|i| i.raw()).collect();
    device.live().swapchain_images(swapchain.raw(), &raw);
    images
}

/// As [`surface_supported`], for the device's physical device: tuff's devices have
/// one. (Only the device-group query of `VK_KHR_swapchain` asks.)
#[cfg(feature = "khr_swapchain")]
pub(crate) fn device_surface_supported(
    device: &Device,
    surface: &SurfaceKHR,
    vuid: &'static str,
) -> Result<()> {
    surface_supported(device.parent(), surface, vuid, vuid)
}

/// The checks of `vkCreateSwapchainKHR` that ask the physical device about the
/// surface, and of the swapchain it retires.
pub(crate) fn create_swapchain_checks(
    device: &Device,
    surface: &SurfaceKHR,
    create_info: &SwapchainCreateInfoKHR<'_>,
) -> Result<()> {
    let info = create_info.as_raw();
    let physical = device.parent();
    let families: Vec<u32> = device.live().queue_infos().iter().map(|q| q.0).collect();
    let mut supported = false;
    for family in families {
        supported |= physical.get_surface_support_khr(family, surface)?;
    }
    if !supported {
        refuse(
            "VUID-VkSwapchainCreateInfoKHR-surface-01270",
            "no queue family the device was created with presents to the surface",
        )?;
    }
    let caps = physical.get_surface_capabilities_khr(surface)?;
    let count = info.min_image_count;
    if count < caps.min_image_count {
        refuse(
            "VUID-VkSwapchainCreateInfoKHR-minImageCount-01271",
            format!(
                "minImageCount ({count}) is less than the surface's minImageCount ({})",
                caps.min_image_count
            ),
        )?;
    }
    if caps.max_image_count != 0 && count > caps.max_image_count {
        refuse(
            "VUID-VkSwapchainCreateInfoKHR-minImageCount-01272",
            format!(
                "minImageCount ({count}) is more than the surface's maxImageCount ({})",
                caps.max_image_count
            ),
        )?;
    }
    // The queries below are safe in the pinned configuration and may be `unsafe` in
    // wider ones, for rules of extensions (a surfaceless query, DRM format
    // modifiers) that these calls keep: a live surface, optimal tiling.
    #[allow(unused_unsafe)]
    // SAFETY: a live surface of the physical device's instance.
    let formats = unsafe { physical.get_surface_formats_khr(Some(surface)) }?;
    if !formats
        .iter()
        .any(|f| f.format == info.image_format && f.color_space == info.image_color_space)
    {
        refuse(
            "VUID-VkSwapchainCreateInfoKHR-imageFormat-01273",
            format!(
                "the surface does not offer {:?} in {:?}",
                info.image_format, info.image_color_space
            ),
        )?;
    }
    let e = info.image_extent;
    if e.width == 0 || e.height == 0 {
        refuse(
            "VUID-VkSwapchainCreateInfoKHR-imageExtent-01689",
            format!("imageExtent ({}x{}) is empty", e.width, e.height),
        )?;
    }
    let (min, max) = (caps.min_image_extent, caps.max_image_extent);
    if e.width < min.width || e.height < min.height || e.width > max.width || e.height > max.height
    {
        refuse(
            "VUID-VkSwapchainCreateInfoKHR-imageExtent-01274",
            format!(
                "imageExtent ({}x{}) is outside the surface's {}x{} to {}x{}",
                e.width, e.height, min.width, min.height, max.width, max.height
            ),
        )?;
    }
    let layers = info.image_array_layers;
    if layers == 0 || layers > caps.max_image_array_layers {
        refuse(
            "VUID-VkSwapchainCreateInfoKHR-imageArrayLayers-01275",
            format!("imageArrayLayers ({layers}) is not within 1 to the surface's maxImageArrayLayers ({})", caps.max_image_array_layers),
        )?;
    }
    #[allow(unused_unsafe)]
    // SAFETY: as for the formats.
    let modes = unsafe { physical.get_surface_present_modes_khr(Some(surface)) }?;
    let mode = info.present_mode;
    if !modes.contains(&mode) {
        refuse(
            "VUID-VkSwapchainCreateInfoKHR-presentMode-01281",
            format!("the surface does not offer {mode:?} (it offers {modes:?})"),
        )?;
    }
    let shared = [
        vk::PresentModeKHR::IMMEDIATE,
        vk::PresentModeKHR::MAILBOX,
        vk::PresentModeKHR::FIFO,
        vk::PresentModeKHR::FIFO_RELAXED,
    ];
    if shared.contains(&mode) && !caps.supported_usage_flags.contains(info.image_usage) {
        refuse(
            "VUID-VkSwapchainCreateInfoKHR-presentMode-01427",
            format!(
                "imageUsage ({:?}) is not within the surface's supportedUsageFlags ({:?})",
                info.image_usage, caps.supported_usage_flags
            ),
        )?;
    }
    let one_of = |bit: u32, set: u32| bit.count_ones() == 1 && set & bit != 0;
    if !one_of(
        info.pre_transform.as_raw(),
        caps.supported_transforms.as_raw(),
    ) {
        refuse(
            "VUID-VkSwapchainCreateInfoKHR-preTransform-01279",
            format!(
                "preTransform ({:?}) is not one of the surface's supportedTransforms ({:?})",
                info.pre_transform, caps.supported_transforms
            ),
        )?;
    }
    if !one_of(
        info.composite_alpha.as_raw(),
        caps.supported_composite_alpha.as_raw(),
    ) {
        refuse(
            "VUID-VkSwapchainCreateInfoKHR-compositeAlpha-01280",
            format!(
                "compositeAlpha ({:?}) is not one of the surface's supportedCompositeAlpha ({:?})",
                info.composite_alpha, caps.supported_composite_alpha
            ),
        )?;
    }
    if info.image_sharing_mode == vk::SharingMode::CONCURRENT {
        // SAFETY: the safe setter stores the indices with their count.
        let families = unsafe {
            crate::state::raw_slice(info.p_queue_family_indices, info.queue_family_index_count)
        };
        concurrent_families(
            physical,
            families,
            "VUID-VkSwapchainCreateInfoKHR-imageSharingMode-01428",
        )?;
    }
    if info
        .flags
        .contains(vk::SwapchainCreateFlagsKHR::SPLIT_INSTANCE_BIND_REGIONS)
        && device.live().physical_count() == 1
    {
        refuse(
            "VUID-VkSwapchainCreateInfoKHR-physicalDeviceCount-01429",
            "a swapchain with SPLIT_INSTANCE_BIND_REGIONS needs a device of more than one physical device",
        )?;
    }
    let flags = swapchain_image_flags(info.flags);
    #[allow(unused_unsafe)]
    // SAFETY: optimal tiling, and values the implicit checks found valid.
    let limits = unsafe {
        physical.get_image_format_properties(
            info.image_format,
            vk::ImageType::TYPE_2D,
            vk::ImageTiling::OPTIMAL,
            info.image_usage,
            flags,
        )
    };
    let fits = limits.as_ref().is_ok_and(|l| {
        l.max_array_layers >= layers
            && l.max_extent.width >= e.width
            && l.max_extent.height >= e.height
    });
    if !fits {
        refuse(
            "VUID-VkSwapchainCreateInfoKHR-imageFormat-01778",
            format!("the physical device does not support the swapchain's images ({:?}, {:?}, {flags:?}, {}x{}, {layers} layers): {limits:?}", info.image_format, info.image_usage, e.width, e.height),
        )?;
    }
    if info.old_swapchain != vk::SwapchainKHR::null() {
        if device.live().is_retired(info.old_swapchain) {
            refuse(
                "VUID-VkSwapchainCreateInfoKHR-oldSwapchain-01933",
                "oldSwapchain was retired by an earlier swapchain creation",
            )?;
        }
        let same_surface = device
            .live()
            .swapchain_surface(info.old_swapchain)
            .is_some_and(|s| s == surface.raw());
        if !same_surface {
            refuse(
                "VUID-VkSwapchainCreateInfoKHR-oldSwapchain-01933",
                "oldSwapchain presents to another surface (the check compares surface objects, so a second surface of the same window is refused too)",
            )?;
        }
    }
    Ok(())
}

/// `vkCreateSwapchainKHR` retires its `oldSwapchain`, whether or not it succeeds.
pub(crate) fn swapchain_retires(device: &Device, create_info: &SwapchainCreateInfoKHR<'_>) {
    let old = create_info.as_raw().old_swapchain;
    if old != vk::SwapchainKHR::null() {
        device.live().retire(old);
    }
}

/// The rules an acquire checks, by command.
struct AcquireRules {
    timeline: &'static str,
    retired: &'static str,
    neither: &'static str,
    binary: &'static submission::BinaryRules,
}

const ACQUIRE: AcquireRules = AcquireRules {
    timeline: "VUID-vkAcquireNextImageKHR-semaphore-03265",
    retired: "VUID-vkAcquireNextImageKHR-swapchain-01285",
    neither: "VUID-vkAcquireNextImageKHR-semaphore-01780",
    binary: &submission::ACQUIRE_BINARY,
};

const ACQUIRE2: AcquireRules = AcquireRules {
    timeline: "VUID-VkAcquireNextImageInfoKHR-semaphore-03266",
    retired: "VUID-VkAcquireNextImageInfoKHR-swapchain-01675",
    neither: "VUID-VkAcquireNextImageInfoKHR-semaphore-01782",
    binary: &submission::ACQUIRE2_BINARY,
};

/// The checks of an acquire that do not need its fence's wrapper: something to
/// signal, a swapchain that is not retired, and a binary semaphore with nothing
/// signaled or pending.
fn acquire_checks(
    device: &Device,
    swapchain: vk::SwapchainKHR,
    semaphore: vk::Semaphore,
    fence: vk::Fence,
    rules: &AcquireRules,
) -> Result<()> {
    if semaphore == vk::Semaphore::null() && fence == vk::Fence::null() {
        refuse(
            rules.neither,
            "an acquire needs a semaphore or a fence to signal",
        )?;
    }
    if semaphore != vk::Semaphore::null() {
        submission::check_semaphore_type(device.live(), &[semaphore], false, rules.timeline)?;
        submission::check_binary_ops(
            device,
            vk::Queue::null(),
            &[submission::SemOp::Signal(semaphore)],
            rules.binary,
        )?;
    }
    if device.live().is_retired(swapchain) {
        refuse(
            rules.retired,
            "the swapchain was retired by a later swapchain creation",
        )?;
    }
    Ok(())
}

/// The checks of `vkAcquireNextImageKHR`: those of [`acquire_checks`], an
/// unsignaled fence no other operation will signal, and no infinite wait where the
/// swapchain cannot give another image (more images acquired than its count less
/// the surface's minimum: the presentation engine may hold the rest until a
/// present).
pub(crate) fn acquire_next_image_khr_checks(
    device: &Device,
    swapchain: &SwapchainKHR,
    timeout: u64,
    semaphore: Option<&Semaphore>,
    fence: Option<&Fence>,
) -> Result<()> {
    acquire_checks(
        device,
        swapchain.raw(),
        semaphore.map_or(vk::Semaphore::null(), |s| s.raw()),
        fence.map_or(vk::Fence::null(), |f| f.raw()),
        &ACQUIRE,
    )?;
    if let Some(f) = fence {
        submission::check_fence(f, &submission::ACQUIRE)?;
    }
    let acquired = device.live().acquired_count(swapchain.raw());
    if timeout == u64::MAX && acquired > 0 {
        let swapchain_fns = device
            .ext()
            .khr_swapchain
            .as_ref()
            .ok_or(Error::ExtensionNotEnabled("VK_KHR_swapchain"))?;
        let mut count = 0u32;
        // SAFETY: a live swapchain of this device; a count query writes only `count`.
        let r = unsafe {
            (swapchain_fns.get_swapchain_images_khr)(
                device.raw(),
                swapchain.raw(),
                &mut count,
                core::ptr::null_mut(),
            )
        };
        if r != vk::Result::SUCCESS {
            return Err(Error::Vk(r));
        }
        let images = count as usize;
        let surface = device.live().swapchain_surface(swapchain.raw());
        let min = match surface {
            Some(surface) => {
                let mut caps = vk::SurfaceCapabilitiesKHR::default();
                let physical = device.parent();
                let fns = physical
                    .parent()
                    .ext()
                    .khr_surface
                    .as_ref()
                    .ok_or(Error::ExtensionNotEnabled("VK_KHR_surface"))?;
                // SAFETY: the surface lives as long as the swapchain, which the
                // caller holds; the output is local.
                let r = unsafe {
                    (fns.get_physical_device_surface_capabilities_khr)(
                        physical.raw(),
                        surface,
                        &mut caps,
                    )
                };
                if r != vk::Result::SUCCESS {
                    return Err(Error::Vk(r));
                }
                caps.min_image_count as usize
            }
            None => images,
        };
        if acquired > images.saturating_sub(min) {
            refuse(
                "VUID-vkAcquireNextImageKHR-surface-07783",
                format!("{acquired} of the swapchain's {images} images are acquired, more than its count less the surface's minImageCount ({min}): forward progress is not guaranteed, so the timeout must not be UINT64_MAX"),
            )?;
        }
    }
    Ok(())
}

/// After `vkAcquireNextImageKHR` returned: when it acquired an image, the semaphore
/// is signaled, the fence belongs to the acquire until it is seen signaled, and the
/// image is acquired until a presentation takes it.
#[allow(clippy::too_many_arguments)]
pub(crate) fn acquire_next_image_khr_done(
    device: &Device,
    swapchain: &SwapchainKHR,
    semaphore: Option<&Semaphore>,
    fence: Option<&Fence>,
    index: u32,
    r: vk::Result,
) {
    if r != vk::Result::SUCCESS && r != vk::Result::SUBOPTIMAL_KHR {
        return;
    }
    if fence.is_some() {
        submission::submitted(
            device,
            vk::Queue::null(),
            fence,
            &[],
            Default::default(),
            Default::default(),
        );
    }
    // An image acquired with vkAcquireNextImageKHR is acquired for every physical
    // device of the logical device.
    let all = (1u64 << device.live().physical_count().min(32)) - 1;
    let semaphore = semaphore.map_or(vk::Semaphore::null(), |s| s.raw());
    acquired(device, swapchain.raw(), semaphore, (index, all as u32));
}

/// An acquire of image `index` for the physical devices of `mask` succeeded: its
/// semaphore is signaled and the image acquired until a presentation takes it.
fn acquired(
    device: &Device,
    swapchain: vk::SwapchainKHR,
    semaphore: vk::Semaphore,
    (index, mask): (u32, u32),
) {
    if semaphore != vk::Semaphore::null() {
        let signal = [submission::SemOp::Signal(semaphore)];
        submission::record_binary_ops(device, vk::Queue::null(), &signal, None);
    }
    device.live().image_acquired(swapchain, index, mask);
}

/// The checks of `vkAcquireNextImage2KHR` that [`acquire_checks`] makes.
pub(crate) fn acquire_next_image2_khr_checks(
    device: &Device,
    acquire_info: &AcquireNextImageInfoKHR<'_>,
) -> Result<()> {
    acquire_checks(
        device,
        acquire_info.swapchain,
        acquire_info.semaphore,
        acquire_info.fence,
        &ACQUIRE2,
    )
}

/// After `vkAcquireNextImage2KHR`, as after `vkAcquireNextImageKHR` (its fence is a
/// raw handle here, so it is not tracked: the method stays `unsafe` for it).
pub(crate) fn acquire_next_image2_khr_done(
    device: &Device,
    acquire_info: &AcquireNextImageInfoKHR<'_>,
    index: u32,
    r: vk::Result,
) {
    if r == vk::Result::SUCCESS || r == vk::Result::SUBOPTIMAL_KHR {
        let info = acquire_info;
        acquired(
            device,
            info.swapchain,
            info.semaphore,
            (index, info.device_mask),
        );
    }
}
