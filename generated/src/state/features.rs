//! What the device records of the core features it was created with.

use ash::vk;

/// The core features a device was created with, from its create info's
/// `pEnabledFeatures` and every features struct of its chain (each copied without
/// its `pNext`).
#[derive(Clone, Copy, Default)]
pub(crate) struct Features {
    /// Vulkan 1.0's.
    pub v10: vk::PhysicalDeviceFeatures,
    /// Vulkan 1.1's.
    pub v11: vk::PhysicalDeviceVulkan11Features<'static>,
    /// Vulkan 1.2's.
    pub v12: vk::PhysicalDeviceVulkan12Features<'static>,
    /// Vulkan 1.3's.
    pub v13: vk::PhysicalDeviceVulkan13Features<'static>,
}

// SAFETY: the `pNext` of each struct stays null: the features are copied member
// by member, and nothing dereferences the pointer.
unsafe impl Send for Features {}
// SAFETY: as above; the struct is plain data.
unsafe impl Sync for Features {}
