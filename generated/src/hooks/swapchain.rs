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
        supported |=
            physical.get_physical_device_surface_support_khr(family, surface)? != vk::FALSE;
    }
    if !supported {
        refuse(
            "VUID-VkSwapchainCreateInfoKHR-surface-01270",
            "no queue family the device was created with presents to the surface".into(),
        )?;
    }
    let caps = physical.get_physical_device_surface_capabilities_khr(surface)?;
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
    let formats = unsafe { physical.get_physical_device_surface_formats_khr(Some(surface)) }?;
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
    let modes = unsafe { physical.get_physical_device_surface_present_modes_khr(Some(surface)) }?;
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
        physical.get_physical_device_image_format_properties(
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
