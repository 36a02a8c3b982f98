//! Surfaces: queue family and surface support queries.

use super::{family_count, refuse};
use crate::handles::*;
use crate::{Handle, Result};
use ash::vk;

/// A queue family index below the physical device's family count.
pub(crate) fn queue_family_exists(
    physical: &PhysicalDevice,
    queue_family_index: u32,
    vuid: &'static str,
) -> Result<()> {
    let count = family_count(physical);
    if queue_family_index >= count {
        refuse(
            vuid,
            format!(
                "`queueFamilyIndex` must be less than `pQueueFamilyPropertyCount` returned by \
                 `vkGetPhysicalDeviceQueueFamilyProperties` for the given `physicalDevice` \
                 (`queueFamilyIndex` = {queue_family_index}, count = {count})"
            ),
        )?;
    }
    Ok(())
}

/// A surface some queue family of the physical device presents to, as
/// `vkGetPhysicalDeviceSurfaceSupportKHR` reports.
///
/// A query without a surface is refused (`missing`): it needs
/// `VK_GOOGLE_surfaceless_query`, which tuff does not emit.
pub(crate) fn surface_supported<'s>(
    physical: &PhysicalDevice,
    surface: impl Into<Option<&'s SurfaceKHR>>,
    vuid: &'static str,
    missing: &'static str,
) -> Result<()> {
    let Some(surface) = surface.into() else {
        return refuse(
            missing,
            "`surface` must be a valid VkSurfaceKHR handle (a query without one needs \
             VK_GOOGLE_surfaceless_query, which tuff does not emit)",
        );
    };
    // Without the extension the call itself fails, with `ExtensionNotEnabled`.
    let Some(fns) = physical.parent().ext().khr_surface.as_ref() else {
        return Ok(());
    };
    for family in 0..family_count(physical) {
        let mut supported = vk::FALSE;
        // SAFETY: a live physical device and a live surface of one instance (the
        // implicit checks ran first), a family below the count, an output it owns.
        let r = unsafe {
            (fns.get_physical_device_surface_support_khr)(
                physical.raw(),
                family,
                surface.raw(),
                &mut supported,
            )
        };
        if r == vk::Result::SUCCESS && supported == vk::TRUE {
            return Ok(());
        }
    }
    refuse(
        vuid,
        "`surface` must be supported by `physicalDevice`, as reported by \
         vkGetPhysicalDeviceSurfaceSupportKHR (no queue family of it presents to the surface)",
    )
}
