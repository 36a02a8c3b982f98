//! Checks of a swapchain's creation against what the surface reports (its
//! capabilities, formats and present modes) and against the swapchain it replaces.

use super::*;

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
            "no queue family the device was created with presents to the surface".into(),
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
            crate::retention::raw_slice(info.p_queue_family_indices, info.queue_family_index_count)
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
            "a swapchain with SPLIT_INSTANCE_BIND_REGIONS needs a device of more than one physical device".into(),
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
                "oldSwapchain was retired by an earlier swapchain creation".into(),
            )?;
        }
        let same_surface = device
            .live()
            .swapchain_surface(info.old_swapchain)
            .is_some_and(|s| s == surface.raw());
        if !same_surface {
            refuse(
                "VUID-VkSwapchainCreateInfoKHR-oldSwapchain-01933",
                "oldSwapchain presents to another surface (the check compares surface objects, so a second surface of the same window is refused too)".into(),
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
            "an acquire needs a semaphore or a fence to signal".into(),
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
            "the swapchain was retired by a later swapchain creation".into(),
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
    if let Some(s) = semaphore {
        submission::record_binary_ops(
            device,
            vk::Queue::null(),
            &[submission::SemOp::Signal(s.raw())],
            None,
        );
    }
    if fence.is_some() {
        submission::submitted(
            device,
            vk::Queue::null(),
            fence,
            &[],
            Vec::new(),
            Vec::new(),
        );
    }
    // An image acquired with vkAcquireNextImageKHR is acquired for every physical
    // device of the logical device.
    let all = (1u64 << device.live().physical_count().min(32)) - 1;
    device
        .live()
        .image_acquired(swapchain.raw(), index, all as u32);
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
    if r != vk::Result::SUCCESS && r != vk::Result::SUBOPTIMAL_KHR {
        return;
    }
    if acquire_info.semaphore != vk::Semaphore::null() {
        submission::record_binary_ops(
            device,
            vk::Queue::null(),
            &[submission::SemOp::Signal(acquire_info.semaphore)],
            None,
        );
    }
    device
        .live()
        .image_acquired(acquire_info.swapchain, index, acquire_info.device_mask);
}
