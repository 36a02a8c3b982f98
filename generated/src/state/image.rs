//! What the device records of images, and their layouts as the device's submissions
//! leave them.

use super::live::Live;
use ash::vk::{self, Handle as _};

/// The layouts of an image's subresources, in subresource order: inline for an image
/// of one or two (an attachment's), so a submission's layout checks copy them
/// without allocating.
pub(crate) type ImageLayouts = smallvec::SmallVec<[vk::ImageLayout; 2]>;

/// An image's creation parameters, as its checks read them.
#[derive(Clone, Copy, Debug)]
pub(crate) struct ImageRecord {
    /// `VkImageCreateInfo::flags`.
    pub flags: vk::ImageCreateFlags,
    /// `VkImageCreateInfo::imageType`.
    pub image_type: vk::ImageType,
    /// `VkImageCreateInfo::format`.
    pub format: vk::Format,
    /// `VkImageCreateInfo::extent`: the size of mip level 0.
    pub extent: vk::Extent3D,
    /// `VkImageCreateInfo::mipLevels`.
    pub mip_levels: u32,
    /// `VkImageCreateInfo::arrayLayers`.
    pub array_layers: u32,
    /// `VkImageCreateInfo::usage`.
    pub usage: vk::ImageUsageFlags,
    /// `VkImageCreateInfo::tiling`.
    pub tiling: vk::ImageTiling,
    /// `VkImageCreateInfo::samples`.
    pub samples: vk::SampleCountFlags,
    /// A chained `VkImageStencilUsageCreateInfo::stencilUsage`, if one was.
    pub stencil_usage: Option<vk::ImageUsageFlags>,
    /// `VkImageCreateInfo::sharingMode`.
    pub sharing: vk::SharingMode,
    /// The queue families of a concurrent image, as bits (`u64::MAX` when one is 64
    /// or more, which matches no other set).
    #[cfg_attr(not(feature = "khr_swapchain"), allow(dead_code))]
    pub families: u64,
    /// Whether memory is bound to it.
    pub bound: bool,
    /// `VkExternalMemoryImageCreateInfo::handleTypes`.
    pub external: vk::ExternalMemoryHandleTypeFlags,
    /// Made with a chained `VkImageSwapchainCreateInfoKHR` naming a swapchain (or a
    /// swapchain's own image): its memory is the swapchain's.
    pub for_swapchain: bool,
}

impl Live {
    /// Records a new image's creation parameters, and the view formats it listed.
    pub(crate) fn image_created(&self, raw: vk::Image, record: ImageRecord, views: &[vk::Format]) {
        if record.flags.contains(vk::ImageCreateFlags::PROTECTED) {
            self.protected_one(true);
        }
        self.images.lock().insert(raw.as_raw(), record);
        if !views.is_empty() {
            self.view_formats
                .lock()
                .insert(raw.as_raw(), views.to_vec());
        }
    }

    /// The record of a live image made through the wrappers, or of a swapchain's
    /// image that `get_swapchain_images_khr` returned.
    pub(crate) fn image(&self, raw: vk::Image) -> Option<ImageRecord> {
        self.images.lock().get(&raw.as_raw()).copied()
    }

    /// The layouts of an image's `len` subresources as the submissions so far
    /// leave them.
    pub(crate) fn image_layouts(&self, image: u64, len: usize) -> ImageLayouts {
        match self.layouts.lock().get(&image) {
            Some(l) if l.len() == len => l.clone(),
            _ => smallvec::smallvec![vk::ImageLayout::UNDEFINED; len],
        }
    }

    /// Records that a new image's subresources start `PREINITIALIZED`.
    pub(crate) fn image_preinitialized(&self, image: vk::Image) {
        if let Some(record) = self.image(image) {
            let len = crate::state::layouts::Shape::of(&record).len();
            self.layouts.lock().insert(
                image.as_raw(),
                smallvec::smallvec![vk::ImageLayout::PREINITIALIZED; len],
            );
        }
    }

    /// Records the layouts a submission leaves an image's subresources in.
    pub(crate) fn set_image_layouts(&self, image: u64, layouts: ImageLayouts) {
        // Only a listed image: one destroyed since the check keeps no entry.
        if self.images.lock().contains_key(&image) {
            self.layouts.lock().insert(image, layouts);
        }
    }
}
