//! The begin of a render pass instance: its render area against the framebuffer,
//! its clear values against the attachments it clears, and each layout the render
//! pass gives an attachment against the usage of the framebuffer's view.

use super::refuse;
use crate::recorder::{Recorder, State};
use crate::structs::RenderPassBeginInfo;
use crate::Result;
use ash::vk;

type L = vk::ImageLayout;
type U = vk::ImageUsageFlags;

/// The rules of one command that begins a render pass instance.
pub(crate) struct BeginRules {
    /// Each attachment's initial layout is its current layout.
    pub initial: &'static str,
    /// For each group of layouts: the usage bits of which the attachment's view
    /// needs one when the render pass gives the attachment one of them, and the
    /// rule.
    pub usage: [(&'static [L], U, &'static str); 6],
}

const COLOR: &[L] = &[L::COLOR_ATTACHMENT_OPTIMAL];
const READ: &[L] = &[L::SHADER_READ_ONLY_OPTIMAL];
const SRC: &[L] = &[L::TRANSFER_SRC_OPTIMAL];
const DST: &[L] = &[L::TRANSFER_DST_OPTIMAL];
const DEPTH_STENCIL: &[L] = &[
    L::DEPTH_READ_ONLY_STENCIL_ATTACHMENT_OPTIMAL,
    L::DEPTH_ATTACHMENT_STENCIL_READ_ONLY_OPTIMAL,
    L::DEPTH_STENCIL_ATTACHMENT_OPTIMAL,
    L::DEPTH_STENCIL_READ_ONLY_OPTIMAL,
];
const SEPARATE: &[L] = &[
    L::DEPTH_ATTACHMENT_OPTIMAL,
    L::DEPTH_READ_ONLY_OPTIMAL,
    L::STENCIL_ATTACHMENT_OPTIMAL,
    L::STENCIL_READ_ONLY_OPTIMAL,
];
const SAMPLED_OR_INPUT: U = U::from_raw(U::SAMPLED.as_raw() | U::INPUT_ATTACHMENT.as_raw());

/// `vkCmdBeginRenderPass`.
pub(crate) const BEGIN: BeginRules = BeginRules {
    initial: "VUID-vkCmdBeginRenderPass-initialLayout-00900",
    usage: [
        (
            COLOR,
            U::COLOR_ATTACHMENT,
            "VUID-vkCmdBeginRenderPass-initialLayout-00895",
        ),
        (
            READ,
            SAMPLED_OR_INPUT,
            "VUID-vkCmdBeginRenderPass-initialLayout-00897",
        ),
        (
            SRC,
            U::TRANSFER_SRC,
            "VUID-vkCmdBeginRenderPass-initialLayout-00898",
        ),
        (
            DST,
            U::TRANSFER_DST,
            "VUID-vkCmdBeginRenderPass-initialLayout-00899",
        ),
        (
            DEPTH_STENCIL,
            U::DEPTH_STENCIL_ATTACHMENT,
            "VUID-vkCmdBeginRenderPass-initialLayout-01758",
        ),
        (
            SEPARATE,
            U::DEPTH_STENCIL_ATTACHMENT,
            "VUID-vkCmdBeginRenderPass-initialLayout-02842",
        ),
    ],
};

/// `vkCmdBeginRenderPass2`.
pub(crate) const BEGIN2: BeginRules = BeginRules {
    initial: "VUID-vkCmdBeginRenderPass2-initialLayout-03100",
    usage: [
        (
            COLOR,
            U::COLOR_ATTACHMENT,
            "VUID-vkCmdBeginRenderPass2-initialLayout-03094",
        ),
        (
            READ,
            SAMPLED_OR_INPUT,
            "VUID-vkCmdBeginRenderPass2-initialLayout-03097",
        ),
        (
            SRC,
            U::TRANSFER_SRC,
            "VUID-vkCmdBeginRenderPass2-initialLayout-03098",
        ),
        (
            DST,
            U::TRANSFER_DST,
            "VUID-vkCmdBeginRenderPass2-initialLayout-03099",
        ),
        (
            DEPTH_STENCIL,
            U::DEPTH_STENCIL_ATTACHMENT,
            "VUID-vkCmdBeginRenderPass2-initialLayout-03096",
        ),
        (
            SEPARATE,
            U::DEPTH_STENCIL_ATTACHMENT,
            "VUID-vkCmdBeginRenderPass2-initialLayout-02844",
        ),
    ],
};

/// The checks of a render pass instance's begin: the render area inside the
/// framebuffer, enough clear values, the usage each attachment's layouts need,
/// and (through [`super::layouts`]) the attachments' current layouts.
pub(crate) fn begin_render_pass_checks<S: State>(
    recorder: &Recorder<'_, S>,
    render_pass_begin: &RenderPassBeginInfo<'_>,
    rules: &BeginRules,
) -> Result<()> {
    let live = recorder.device().live();
    let raw = render_pass_begin.as_raw();
    // SAFETY: the chain of a safe struct, and the type its sType names.
    let group: Option<&vk::DeviceGroupRenderPassBeginInfo<'_>> = unsafe {
        super::chained(
            raw.p_next,
            vk::StructureType::DEVICE_GROUP_RENDER_PASS_BEGIN_INFO,
        )
    };
    if let Some(g) = group {
        check_device_group(recorder, g, live.framebuffer_size(raw.framebuffer))?;
    }
    if group.is_none_or(|g| g.device_render_area_count == 0) {
        let area = raw.render_area;
        let size = live.framebuffer_size(raw.framebuffer);
        let end = |offset: i32, extent: u32| i64::from(offset) + i64::from(extent);
        for (ok, vuid, what) in [
            (
                area.offset.x >= 0,
                "VUID-VkRenderPassBeginInfo-pNext-02850",
                "renderArea.offset.x is negative",
            ),
            (
                area.offset.y >= 0,
                "VUID-VkRenderPassBeginInfo-pNext-02851",
                "renderArea.offset.y is negative",
            ),
            (
                size.is_none_or(|s| end(area.offset.x, area.extent.width) <= i64::from(s[0])),
                "VUID-VkRenderPassBeginInfo-pNext-02852",
                "renderArea reaches past the framebuffer's width",
            ),
            (
                size.is_none_or(|s| end(area.offset.y, area.extent.height) <= i64::from(s[1])),
                "VUID-VkRenderPassBeginInfo-pNext-02853",
                "renderArea reaches past the framebuffer's height",
            ),
        ] {
            if !ok {
                refuse(vuid, format!("{what} ({area:?}, framebuffer {size:?})"))?;
            }
        }
    }
    let Some(pass) = live.render_pass(raw.render_pass) else {
        return super::render_pass_layout_checks(recorder, render_pass_begin, rules.initial);
    };
    if raw.clear_value_count < pass.clear_count {
        refuse(
            "VUID-VkRenderPassBeginInfo-clearValueCount-00902",
            format!(
                "clearValueCount is {}, and the render pass clears attachment {}",
                raw.clear_value_count,
                pass.clear_count - 1
            ),
        )?;
    }
    let views = super::layouts::pass_views(live, render_pass_begin);
    for (n, (view, taken)) in views.iter().zip(&pass.taken).enumerate() {
        let Some(v) = live.view(*view) else {
            continue;
        };
        for (layouts, needs, vuid) in &rules.usage {
            if let Some(l) = taken.iter().find(|l| layouts.contains(l)) {
                if !v.usage.intersects(*needs) {
                    refuse(
                        vuid,
                        format!("the render pass gives attachment {n} layout {l:?}, and its view's usage {:?} has none of {needs:?}", v.usage),
                    )?;
                }
            }
        }
    }
    super::render_pass_layout_checks(recorder, render_pass_begin, rules.initial)
}

/// The rules of a chained `VkDeviceGroupRenderPassBeginInfo`: its device mask
/// against the device's physical devices and the command buffer's initial mask, and
/// each device's render area against the framebuffer and its limits.
fn check_device_group<S: State>(
    recorder: &Recorder<'_, S>,
    g: &vk::DeviceGroupRenderPassBeginInfo<'_>,
    framebuffer: Option<[u32; 3]>,
) -> Result<()> {
    let device = recorder.device();
    let count = device.live().physical_count().min(32);
    let all = ((1u64 << count) - 1) as u32;
    if g.device_mask & !all != 0 {
        refuse(
            "VUID-VkDeviceGroupRenderPassBeginInfo-deviceMask-00905",
            format!(
                "deviceMask {:#x} names a physical device the device has not ({count})",
                g.device_mask
            ),
        )?;
    }
    if g.device_mask & !recorder.device_mask != 0 {
        refuse(
            "VUID-VkDeviceGroupRenderPassBeginInfo-deviceMask-00907",
            format!(
                "deviceMask {:#x} is not within the command buffer's initial device mask {:#x}",
                g.device_mask, recorder.device_mask
            ),
        )?;
    }
    if g.device_render_area_count != 0 && g.device_render_area_count != count {
        refuse(
            "VUID-VkDeviceGroupRenderPassBeginInfo-deviceRenderAreaCount-00908",
            format!(
                "deviceRenderAreaCount is {}, and the device has {count} physical devices",
                g.device_render_area_count
            ),
        )?;
    }
    let limits = super::limits(device);
    // SAFETY: the safe setter stores the areas with their count.
    let areas =
        unsafe { crate::retention::raw_slice(g.p_device_render_areas, g.device_render_area_count) };
    let end = |offset: i32, extent: u32| i64::from(offset) + i64::from(extent);
    for (n, a) in areas.iter().enumerate() {
        let (x, y) = (
            end(a.offset.x, a.extent.width),
            end(a.offset.y, a.extent.height),
        );
        for (ok, vuid) in [
            (
                a.offset.x >= 0,
                "VUID-VkDeviceGroupRenderPassBeginInfo-offset-06166",
            ),
            (
                a.offset.y >= 0,
                "VUID-VkDeviceGroupRenderPassBeginInfo-offset-06167",
            ),
            (
                x <= i64::from(limits.max_framebuffer_width),
                "VUID-VkDeviceGroupRenderPassBeginInfo-offset-06168",
            ),
            (
                y <= i64::from(limits.max_framebuffer_height),
                "VUID-VkDeviceGroupRenderPassBeginInfo-offset-06169",
            ),
            (
                framebuffer.is_none_or(|f| x <= i64::from(f[0])),
                "VUID-VkRenderPassBeginInfo-pNext-02856",
            ),
            (
                framebuffer.is_none_or(|f| y <= i64::from(f[1])),
                "VUID-VkRenderPassBeginInfo-pNext-02857",
            ),
        ] {
            if !ok {
                refuse(
                    vuid,
                    format!("pDeviceRenderAreas[{n}] ({a:?}) is outside the framebuffer ({framebuffer:?}) or its limits"),
                )?;
            }
        }
    }
    Ok(())
}
