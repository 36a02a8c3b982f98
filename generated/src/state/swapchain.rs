//! What the device records of swapchains: their images, which are acquired, and
//! presentation.

#[cfg(feature = "khr_swapchain")]
use super::image::ImageRecord;
use super::live::Live;
use ash::vk;
#[cfg(feature = "khr_swapchain")]
use ash::vk::Handle as _;

/// What the device knows of a live swapchain beyond its images' parameters.
#[cfg_attr(not(feature = "khr_swapchain"), allow(dead_code))]
pub(crate) struct SwapchainState {
    /// The surface it presents to.
    pub(super) surface: u64,
    /// A later creation named it as `oldSwapchain`.
    pub(super) retired: bool,
    /// The indices of its images acquired and not presented since, with the device
    /// mask each was acquired with.
    pub(super) acquired: Vec<(u32, u32)>,
    /// Its images, by index, once `get_swapchain_images_khr` returned them.
    pub(super) images: Vec<vk::Image>,
    /// The device-group present modes it may use (`VkDeviceGroupSwapchainCreateInfoKHR`).
    pub(super) modes: vk::DeviceGroupPresentModeFlagsKHR,
    /// The queue families (as bits; the first 64) seen to support presentation to
    /// its surface.
    pub(super) present_families: u64,
}

impl Live {
    /// Records what a swapchain's images are.
    #[cfg(feature = "khr_swapchain")]
    pub(crate) fn swapchain_created(
        &self,
        raw: vk::SwapchainKHR,
        surface: vk::SurfaceKHR,
        images: ImageRecord,
        modes: vk::DeviceGroupPresentModeFlagsKHR,
    ) {
        self.swapchains.lock().insert(raw.as_raw(), images);
        self.swapchain_states.lock().insert(
            raw.as_raw(),
            SwapchainState {
                surface: surface.as_raw(),
                retired: false,
                acquired: Vec::new(),
                images: Vec::new(),
                modes,
                present_families: 0,
            },
        );
    }

    /// The device-group present modes a live swapchain may use.
    #[cfg(feature = "khr_swapchain")]
    pub(crate) fn swapchain_modes(
        &self,
        raw: vk::SwapchainKHR,
    ) -> vk::DeviceGroupPresentModeFlagsKHR {
        self.swapchain_states
            .lock()
            .get(&raw.as_raw())
            .map_or(vk::DeviceGroupPresentModeFlagsKHR::LOCAL, |s| s.modes)
    }

    /// Whether queue family `family` was seen to support presentation to the
    /// swapchain's surface.
    #[cfg(feature = "khr_swapchain")]
    pub(crate) fn presents_from(&self, raw: vk::SwapchainKHR, family: u32) -> bool {
        family < 64
            && self
                .swapchain_states
                .lock()
                .get(&raw.as_raw())
                .is_some_and(|s| s.present_families & (1 << family) != 0)
    }

    /// Queue family `family` supports presentation to the swapchain's surface.
    #[cfg(feature = "khr_swapchain")]
    pub(crate) fn set_presents_from(&self, raw: vk::SwapchainKHR, family: u32) {
        if let (true, Some(s)) = (
            family < 64,
            self.swapchain_states.lock().get_mut(&raw.as_raw()),
        ) {
            s.present_families |= 1 << family;
        }
    }

    /// `VkDeviceGroupPresentCapabilitiesKHR::presentMask`, once read.
    #[cfg_attr(not(feature = "khr_swapchain"), allow(dead_code))]
    pub(crate) fn present_masks(&self) -> Option<[u32; vk::MAX_DEVICE_GROUP_SIZE]> {
        *self.present_masks.lock()
    }

    /// Records `VkDeviceGroupPresentCapabilitiesKHR::presentMask`.
    #[cfg_attr(not(feature = "khr_swapchain"), allow(dead_code))]
    pub(crate) fn set_present_masks(&self, masks: [u32; vk::MAX_DEVICE_GROUP_SIZE]) {
        *self.present_masks.lock() = Some(masks);
    }

    /// The surface a live swapchain presents to.
    #[cfg(feature = "khr_swapchain")]
    pub(crate) fn swapchain_surface(&self, raw: vk::SwapchainKHR) -> Option<vk::SurfaceKHR> {
        self.swapchain_states
            .lock()
            .get(&raw.as_raw())
            .map(|s| vk::SurfaceKHR::from_raw(s.surface))
    }

    /// Marks a swapchain retired: a creation named it as `oldSwapchain`.
    #[cfg(feature = "khr_swapchain")]
    pub(crate) fn retire(&self, raw: vk::SwapchainKHR) {
        if let Some(s) = self.swapchain_states.lock().get_mut(&raw.as_raw()) {
            s.retired = true;
        }
    }

    /// Whether a creation retired the swapchain.
    #[cfg(feature = "khr_swapchain")]
    pub(crate) fn is_retired(&self, raw: vk::SwapchainKHR) -> bool {
        self.swapchain_states
            .lock()
            .get(&raw.as_raw())
            .is_some_and(|s| s.retired)
    }

    /// How many images of the swapchain are acquired and not presented.
    #[cfg(feature = "khr_swapchain")]
    pub(crate) fn acquired_count(&self, raw: vk::SwapchainKHR) -> usize {
        self.swapchain_states
            .lock()
            .get(&raw.as_raw())
            .map_or(0, |s| s.acquired.len())
    }

    /// Image `index` of the swapchain was acquired.
    #[cfg(feature = "khr_swapchain")]
    pub(crate) fn image_acquired(&self, raw: vk::SwapchainKHR, index: u32, device_mask: u32) {
        if let Some(s) = self.swapchain_states.lock().get_mut(&raw.as_raw()) {
            s.acquired.retain(|(i, _)| *i != index);
            s.acquired.push((index, device_mask));
        }
    }

    /// Image `index` of the swapchain was handed to a presentation.
    #[cfg(feature = "khr_swapchain")]
    pub(crate) fn image_presented(&self, raw: vk::SwapchainKHR, index: u32) {
        if let Some(s) = self.swapchain_states.lock().get_mut(&raw.as_raw()) {
            s.acquired.retain(|(i, _)| *i != index);
        }
    }

    /// The image record a swapchain's images get.
    #[cfg(feature = "khr_swapchain")]
    pub(crate) fn swapchain(&self, raw: vk::SwapchainKHR) -> Option<ImageRecord> {
        self.swapchains.lock().get(&raw.as_raw()).copied()
    }

    /// Records a swapchain's images, as it was created, once they are wrapped.
    #[cfg(feature = "khr_swapchain")]
    pub(crate) fn swapchain_images(&self, raw: vk::SwapchainKHR, images: &[vk::Image]) {
        let Some(record) = self.swapchains.lock().get(&raw.as_raw()).copied() else {
            return;
        };
        {
            let mut recorded = self.images.lock();
            for image in images {
                recorded.insert(image.as_raw(), record);
            }
        }
        if let Some(s) = self.swapchain_states.lock().get_mut(&raw.as_raw()) {
            s.images = images.to_vec();
        }
    }

    /// Image `index` of a swapchain, if it is acquired and not presented since
    /// (`Err(false)`: not acquired; `Err(true)`: acquired, but its image was never
    /// returned by `get_swapchain_images_khr`).
    #[cfg(feature = "khr_swapchain")]
    pub(crate) fn acquired_image(
        &self,
        raw: vk::SwapchainKHR,
        index: u32,
    ) -> core::result::Result<(vk::Image, u32), bool> {
        let states = self.swapchain_states.lock();
        let Some(s) = states.get(&raw.as_raw()) else {
            return Err(false);
        };
        let Some((_, mask)) = s.acquired.iter().find(|(i, _)| *i == index) else {
            return Err(false);
        };
        let image = s.images.get(index as usize).copied().ok_or(true)?;
        Ok((image, *mask))
    }
}
