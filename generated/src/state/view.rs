//! What the device records of image and buffer views and Y'CbCr conversions.

use super::live::Live;
use ash::vk::{self, Handle as _};

/// A live image view's parameters, as a framebuffer's checks read them.
#[derive(Clone, Copy, Debug)]
pub(crate) struct ViewRecord {
    /// The image it views.
    pub image: vk::Image,
    /// `VkImageViewCreateInfo::format`.
    pub format: vk::Format,
    /// `VkImageViewCreateInfo::viewType`.
    pub view_type: vk::ImageViewType,
    /// Its level count, `VK_REMAINING_MIP_LEVELS` resolved.
    pub levels: u32,
    /// Its layer count, `VK_REMAINING_ARRAY_LAYERS` resolved.
    pub layers: u32,
    /// Every component has the identity swizzle.
    pub identity: bool,
    /// Its usage, as the specification derives it.
    pub usage: vk::ImageUsageFlags,
    /// Its subresource range's aspects.
    pub aspect: vk::ImageAspectFlags,
    /// Its subresource range's first mip level.
    pub base_level: u32,
    /// Its subresource range's first array layer.
    pub base_layer: u32,
    /// Created with a chained `VkSamplerYcbcrConversionInfo`.
    pub ycbcr: bool,
}

impl Live {
    /// Records a new buffer view's buffer and format.
    pub(crate) fn buffer_view_created(
        &self,
        raw: vk::BufferView,
        buffer: vk::Buffer,
        format: vk::Format,
    ) {
        self.buffer_views
            .lock()
            .insert(raw.as_raw(), (buffer, format));
    }

    /// The buffer of a live buffer view made through the wrappers.
    pub(crate) fn buffer_view(&self, raw: vk::BufferView) -> Option<vk::Buffer> {
        self.buffer_view_record(raw).map(|(b, _)| b)
    }

    /// The buffer and format of a live buffer view made through the wrappers.
    pub(crate) fn buffer_view_record(
        &self,
        raw: vk::BufferView,
    ) -> Option<(vk::Buffer, vk::Format)> {
        self.buffer_views.lock().get(&raw.as_raw()).copied()
    }

    /// The view formats a live image's create info listed (empty: none listed).
    pub(crate) fn view_formats(&self, raw: vk::Image) -> Vec<vk::Format> {
        self.view_formats
            .lock()
            .get(&raw.as_raw())
            .cloned()
            .unwrap_or_default()
    }

    /// Records a new image view's parameters.
    pub(crate) fn view_created(&self, raw: vk::ImageView, record: ViewRecord) {
        self.views.lock().insert(raw.as_raw(), record);
    }

    /// The parameters of a live image view of this device.
    pub(crate) fn view(&self, raw: vk::ImageView) -> Option<ViewRecord> {
        self.views.lock().get(&raw.as_raw()).copied()
    }

    /// Records a new sampler Y'CbCr conversion's format and chroma filter.
    pub(crate) fn conversion_created(
        &self,
        raw: vk::SamplerYcbcrConversion,
        format: vk::Format,
        chroma_filter: vk::Filter,
    ) {
        let record = (format, chroma_filter);
        self.conversions.lock().insert(raw.as_raw(), record);
    }

    /// The format a live sampler Y'CbCr conversion was created with.
    pub(crate) fn conversion_format(&self, raw: vk::SamplerYcbcrConversion) -> Option<vk::Format> {
        self.conversion(raw).map(|(format, _)| format)
    }

    /// The format and chroma filter a live sampler Y'CbCr conversion was created with.
    pub(crate) fn conversion(
        &self,
        raw: vk::SamplerYcbcrConversion,
    ) -> Option<(vk::Format, vk::Filter)> {
        self.conversions.lock().get(&raw.as_raw()).copied()
    }
}
