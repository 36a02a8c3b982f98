//! What the device records of framebuffers: their attachments and size, and what an
//! imageless one says of the views it takes.

use super::layouts::Sel;
use super::live::Live;
use super::render_pass::RenderPassRecord;
use ash::vk::{self, Handle as _};
use tuff_runtime::Vrc;

/// A framebuffer's attachments (none for an imageless one), its width, height
/// and layer count, and its attachments' memory ([`AttachmentMemory`]).
pub(crate) type FramebufferRecord = (Vrc<[vk::ImageView]>, [u32; 3], AttachmentMemory);

/// Each attachment of a framebuffer as the hazard tracker names it: its view's
/// image and subresources, by attachment number (`None` for a view the wrappers did
/// not make). Read once at creation: a render pass instance begins every frame.
pub(crate) type AttachmentMemory = Vrc<[Option<(vk::Image, Sel)>]>;

/// What an imageless framebuffer's `VkFramebufferAttachmentImageInfo` says of the
/// view that a render pass instance on it gives for one attachment.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(crate) struct AttachmentImage {
    /// `flags`.
    pub flags: vk::ImageCreateFlags,
    /// `usage`.
    pub usage: vk::ImageUsageFlags,
    /// `width`, `height` and `layerCount`.
    pub size: [u32; 3],
    /// `pViewFormats`, sorted.
    pub formats: Vec<vk::Format>,
}

impl Live {
    /// Records a new framebuffer's attachments.
    pub(crate) fn framebuffer_created(
        &self,
        raw: vk::Framebuffer,
        views: &[vk::ImageView],
        size: [u32; 3],
    ) {
        let memory = views
            .iter()
            .map(|v| {
                let r = self.view(*v)?;
                let sel = Sel {
                    aspect: r.aspect,
                    mips: (r.base_level, r.base_level.saturating_add(r.levels)),
                    layers: (r.base_layer, r.base_layer.saturating_add(r.layers)),
                };
                Some((r.image, sel))
            })
            .collect();
        self.framebuffers
            .lock()
            .insert(raw.as_raw(), (views.into(), size, memory));
    }

    /// Records an imageless framebuffer's attachment image infos.
    pub(crate) fn imageless_created(&self, raw: vk::Framebuffer, infos: Vec<AttachmentImage>) {
        self.imageless.lock().insert(raw.as_raw(), infos);
    }

    /// A live imageless framebuffer's attachment image infos (`None` for a
    /// framebuffer with image views).
    pub(crate) fn imageless(&self, raw: vk::Framebuffer) -> Option<Vec<AttachmentImage>> {
        self.imageless.lock().get(&raw.as_raw()).cloned()
    }

    /// Records the render pass a new framebuffer was created with.
    pub(crate) fn framebuffer_pass(&self, raw: vk::Framebuffer, pass: vk::RenderPass) {
        if let Some(record) = self.render_pass(pass) {
            self.framebuffer_passes.lock().insert(raw.as_raw(), record);
        }
    }

    /// The record of the render pass a live framebuffer was created with.
    pub(crate) fn framebuffer_pass_record(
        &self,
        raw: vk::Framebuffer,
    ) -> Option<Vrc<RenderPassRecord>> {
        self.framebuffer_passes.lock().get(&raw.as_raw()).cloned()
    }

    /// A live framebuffer's width, height and layer count.
    pub(crate) fn framebuffer_size(&self, raw: vk::Framebuffer) -> Option<[u32; 3]> {
        self.framebuffers.lock().get(&raw.as_raw()).map(|f| f.1)
    }

    /// The memory of a live framebuffer's attachments (empty for an imageless one).
    pub(crate) fn framebuffer_memory(&self, raw: vk::Framebuffer) -> Option<AttachmentMemory> {
        self.framebuffers
            .lock()
            .get(&raw.as_raw())
            .map(|f| f.2.clone())
    }

    /// The attachments of a live framebuffer as its record holds them (empty for an
    /// imageless one): each framebuffer created has its own list.
    pub(crate) fn framebuffer_record_views(
        &self,
        raw: vk::Framebuffer,
    ) -> Option<Vrc<[vk::ImageView]>> {
        self.framebuffers
            .lock()
            .get(&raw.as_raw())
            .map(|f| f.0.clone())
    }

    /// The attachments of a live framebuffer (empty for an imageless one).
    pub(crate) fn framebuffer_views(&self, raw: vk::Framebuffer) -> Vrc<[vk::ImageView]> {
        self.framebuffers
            .lock()
            .get(&raw.as_raw())
            .map_or_else(|| Vrc::from([]), |f| f.0.clone())
    }
}
