//! Framebuffers: each attachment view against the render pass and the framebuffer's
//! size, and the views imageless framebuffers take at begin.

use super::{chained, refuse};
use crate::handles::{Device, Framebuffer};
use crate::structs::FramebufferCreateInfo;
use crate::{Handle, Result};
use ash::vk;

/// The usage bit each role of an attachment needs, with its rules for a framebuffer
/// with image views and for an imageless one.
const ROLE_USAGE: [(u8, vk::ImageUsageFlags, &str, &str); 5] = [
    (
        crate::state::USED_COLOR,
        vk::ImageUsageFlags::COLOR_ATTACHMENT,
        "VUID-VkFramebufferCreateInfo-pAttachments-00877",
        "VUID-VkFramebufferCreateInfo-flags-03201",
    ),
    (
        crate::state::USED_RESOLVE,
        vk::ImageUsageFlags::COLOR_ATTACHMENT,
        "VUID-VkFramebufferCreateInfo-pAttachments-00877",
        "VUID-VkFramebufferCreateInfo-flags-03201",
    ),
    (
        crate::state::USED_DEPTH,
        vk::ImageUsageFlags::DEPTH_STENCIL_ATTACHMENT,
        "VUID-VkFramebufferCreateInfo-pAttachments-02633",
        "VUID-VkFramebufferCreateInfo-flags-03202",
    ),
    (
        crate::state::USED_INPUT,
        vk::ImageUsageFlags::INPUT_ATTACHMENT,
        "VUID-VkFramebufferCreateInfo-pAttachments-00879",
        "VUID-VkFramebufferCreateInfo-flags-03204",
    ),
    (
        crate::state::USED_DEPTH_RESOLVE,
        vk::ImageUsageFlags::DEPTH_STENCIL_ATTACHMENT,
        "VUID-VkFramebufferCreateInfo-pAttachments-02634",
        "VUID-VkFramebufferCreateInfo-flags-03202",
    ),
];

/// The checks of `vkCreateFramebuffer` against its render pass's attachments and
/// view masks and, for each attachment, the view's or the imageless info's
/// recorded parameters.
pub(crate) fn create_framebuffer_checks(
    device: &Device,
    create_info: &FramebufferCreateInfo<'_>,
) -> Result<()> {
    let info = create_info.as_raw();
    let Some(pass) = device.live().render_pass(info.render_pass) else {
        return Ok(());
    };
    if info.attachment_count as usize != pass.attachments.len() {
        refuse(
            "VUID-VkFramebufferCreateInfo-attachmentCount-00876",
            format!(
                "attachmentCount ({}) is not the render pass's {}",
                info.attachment_count,
                pass.attachments.len()
            ),
        )?;
    }
    let masks: u32 = pass.view_masks.iter().fold(0, |a, m| a | m);
    let multiview = masks != 0;
    if multiview && info.layers != 1 {
        refuse(
            "VUID-VkFramebufferCreateInfo-renderPass-02531",
            format!(
                "the render pass has view masks, so layers must be 1, not {}",
                info.layers
            ),
        )?;
    }
    let views_needed = 32 - masks.leading_zeros();
    let attachment_roles = crate::state::USED_COLOR
        | crate::state::USED_RESOLVE
        | crate::state::USED_DEPTH
        | crate::state::USED_INPUT;
    if info.flags.contains(vk::FramebufferCreateFlags::IMAGELESS) {
        return imageless_checks(info, &pass.attachments, multiview, views_needed);
    }
    // SAFETY: the safe setter stores the views with their count.
    let views = unsafe { crate::state::raw_slice(info.p_attachments, info.attachment_count) };
    for (i, raw) in views.iter().enumerate() {
        let at = format!("pAttachments[{i}]");
        let Some(view) = device.live().view(*raw) else {
            return refuse(
                "VUID-vkCreateFramebuffer-pCreateInfo-02777",
                format!("{at} is not an image view of this device"),
            );
        };
        let Some(&(format, samples, roles)) = pass.attachments.get(i) else {
            continue;
        };
        let image = device.live().image(view.image);
        for (role, bit, vuid, _) in ROLE_USAGE {
            if roles & role != 0 && !view.usage.contains(bit) {
                refuse(vuid, format!("{at} is used as an attachment that needs {bit:?}, which its usage ({:?}) lacks", view.usage))?;
            }
        }
        if view.format != format {
            refuse(
                "VUID-VkFramebufferCreateInfo-pAttachments-00880",
                format!(
                    "{at}'s format ({:?}) is not the render pass attachment's ({format:?})",
                    view.format
                ),
            )?;
        }
        if let Some(image) = image {
            if image.samples != samples {
                refuse(
                    "VUID-VkFramebufferCreateInfo-pAttachments-00881",
                    format!(
                        "{at}'s image has {:?}, the render pass attachment {samples:?}",
                        image.samples
                    ),
                )?;
            }
        }
        if view.levels != 1 {
            refuse(
                "VUID-VkFramebufferCreateInfo-pAttachments-00883",
                format!("{at} has {} mip levels, not one", view.levels),
            )?;
        }
        if !view.identity {
            refuse(
                "VUID-VkFramebufferCreateInfo-pAttachments-00884",
                format!("{at} does not have the identity swizzle"),
            )?;
        }
        if view.view_type == vk::ImageViewType::TYPE_3D {
            refuse(
                "VUID-VkFramebufferCreateInfo-flags-04113",
                format!("{at} is a 3D view"),
            )?;
        }
        if let Some(image) = image {
            let depth_stencil = crate::formats::aspects(view.format).is_some_and(|a| {
                a.intersects(vk::ImageAspectFlags::DEPTH | vk::ImageAspectFlags::STENCIL)
            });
            if image.image_type == vk::ImageType::TYPE_3D && depth_stencil {
                refuse(
                    "VUID-VkFramebufferCreateInfo-pAttachments-00891",
                    format!("{at} is a 2D view of a 3D image in a depth/stencil format"),
                )?;
            }
            if roles & attachment_roles != 0 {
                if image.extent.width < info.width {
                    refuse(
                        "VUID-VkFramebufferCreateInfo-flags-04533",
                        format!(
                            "{at}'s image is {} wide, less than the framebuffer's {}",
                            image.extent.width, info.width
                        ),
                    )?;
                }
                if image.extent.height < info.height {
                    refuse(
                        "VUID-VkFramebufferCreateInfo-flags-04534",
                        format!(
                            "{at}'s image is {} high, less than the framebuffer's {}",
                            image.extent.height, info.height
                        ),
                    )?;
                }
            }
        }
        if roles & attachment_roles != 0 {
            if view.layers < info.layers {
                refuse(
                    "VUID-VkFramebufferCreateInfo-flags-04535",
                    format!(
                        "{at} has {} layers, fewer than the framebuffer's {}",
                        view.layers, info.layers
                    ),
                )?;
            }
            if multiview && view.layers < views_needed {
                refuse(
                    "VUID-VkFramebufferCreateInfo-renderPass-04536",
                    format!(
                        "{at} has {} layers, but the view masks name view {}",
                        view.layers,
                        views_needed - 1
                    ),
                )?;
            }
        }
    }
    Ok(())
}

/// An imageless framebuffer's chained attachment infos against its render pass.
fn imageless_checks(
    info: &vk::FramebufferCreateInfo<'_>,
    attachments: &[(vk::Format, vk::SampleCountFlags, u8)],
    multiview: bool,
    views_needed: u32,
) -> Result<()> {
    // SAFETY: the `pNext` of a safe struct, and the type the sType names.
    let chained: Option<&vk::FramebufferAttachmentsCreateInfo<'_>> = unsafe {
        chained(
            info.p_next,
            vk::StructureType::FRAMEBUFFER_ATTACHMENTS_CREATE_INFO,
        )
    };
    let Some(chained) = chained else {
        return refuse(
            "VUID-VkFramebufferCreateInfo-flags-03190",
            "an imageless framebuffer chains no VkFramebufferAttachmentsCreateInfo",
        );
    };
    let count = chained.attachment_image_info_count;
    if count != 0 && count != info.attachment_count {
        refuse(
            "VUID-VkFramebufferCreateInfo-flags-03191",
            format!(
                "attachmentImageInfoCount ({count}) is neither 0 nor attachmentCount ({})",
                info.attachment_count
            ),
        )?;
    }
    // SAFETY: the safe setter stores the infos with their count.
    let images = unsafe { crate::state::raw_slice(chained.p_attachment_image_infos, count) };
    let roles_any = crate::state::USED_COLOR
        | crate::state::USED_RESOLVE
        | crate::state::USED_DEPTH
        | crate::state::USED_INPUT;
    for (i, (a, &(format, _, roles))) in images.iter().zip(attachments).enumerate() {
        let at = format!("pAttachmentImageInfos[{i}]");
        for (role, bit, _, vuid) in ROLE_USAGE {
            if roles & role != 0 && !a.usage.contains(bit) {
                refuse(vuid, format!("{at} is used as an attachment that needs {bit:?}, which its usage ({:?}) lacks", a.usage))?;
            }
        }
        // SAFETY: the safe setter stores the formats with their count.
        let formats = unsafe { crate::state::raw_slice(a.p_view_formats, a.view_format_count) };
        if !formats.contains(&format) {
            refuse(
                "VUID-VkFramebufferCreateInfo-flags-03205",
                format!("{at}'s view formats ({formats:?}) do not include the render pass attachment's {format:?}"),
            )?;
        }
        if roles & roles_any == 0 {
            continue;
        }
        if a.width < info.width {
            refuse(
                "VUID-VkFramebufferCreateInfo-flags-04541",
                format!(
                    "{at} is {} wide, less than the framebuffer's {}",
                    a.width, info.width
                ),
            )?;
        }
        if a.height < info.height {
            refuse(
                "VUID-VkFramebufferCreateInfo-flags-04542",
                format!(
                    "{at} is {} high, less than the framebuffer's {}",
                    a.height, info.height
                ),
            )?;
        }
        if multiview && a.layer_count < views_needed {
            refuse(
                "VUID-VkFramebufferCreateInfo-renderPass-03198",
                format!(
                    "{at} has {} layers, but the view masks name view {}",
                    a.layer_count,
                    views_needed - 1
                ),
            )?;
        }
        if !multiview && a.layer_count < info.layers {
            refuse(
                "VUID-VkFramebufferCreateInfo-renderPass-04546",
                format!(
                    "{at} has {} layers, fewer than the framebuffer's {}",
                    a.layer_count, info.layers
                ),
            )?;
        }
    }
    Ok(())
}

/// The device remembers a framebuffer's attachments, whose layouts each render
/// pass instance on it needs and leaves.
pub(crate) fn framebuffer_created(
    device: &Device,
    framebuffer: Framebuffer,
    create_info: &FramebufferCreateInfo<'_>,
) -> Framebuffer {
    let info = create_info.as_raw();
    let views = if info.flags.contains(vk::FramebufferCreateFlags::IMAGELESS) {
        &[][..]
    } else {
        // SAFETY: the safe setter stores the attachments with their count.
        unsafe { crate::state::raw_slice(info.p_attachments, info.attachment_count) }
    };
    device.live().framebuffer_created(
        framebuffer.raw(),
        views,
        [info.width, info.height, info.layers],
    );
    device
        .live()
        .framebuffer_pass(framebuffer.raw(), info.render_pass);
    // SAFETY: the chain of a safe struct, and the type its sType names.
    let images: Option<&vk::FramebufferAttachmentsCreateInfo<'_>> = unsafe {
        super::chained(
            info.p_next,
            vk::StructureType::FRAMEBUFFER_ATTACHMENTS_CREATE_INFO,
        )
    };
    if let (true, Some(images)) = (
        info.flags.contains(vk::FramebufferCreateFlags::IMAGELESS),
        images,
    ) {
        // SAFETY: the safe setters store each array with its count.
        let infos = unsafe {
            crate::state::raw_slice(
                images.p_attachment_image_infos,
                images.attachment_image_info_count,
            )
        }
        .iter()
        .map(|i| {
            // SAFETY: as above.
            let mut formats =
                unsafe { crate::state::raw_slice(i.p_view_formats, i.view_format_count) }.to_vec();
            formats.sort_by_key(|f| f.as_raw());
            crate::state::AttachmentImage {
                flags: i.flags,
                usage: i.usage,
                size: [i.width, i.height, i.layer_count],
                formats,
            }
        })
        .collect();
        device.live().imageless_created(framebuffer.raw(), infos);
    }
    framebuffer
}
