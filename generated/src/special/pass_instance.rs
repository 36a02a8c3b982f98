//! Render pass instances: beginning a render pass or dynamic rendering (attachments,
//! views, clear values, device groups), moving to the next subpass, and ending.

use super::refuse;
use crate::recorder::{Recorder, Scope};
use crate::structs::RenderPassBeginInfo;
use crate::Result;
use ash::vk;

/// The recorder enters subpass 0 of the render pass it begins.
pub(crate) fn render_pass_begun<S: Scope>(
    recorder: &mut Recorder<'_, S>,
    render_pass_begin: &RenderPassBeginInfo<'_>,
    contents: vk::SubpassContents,
    layout_vuid: &'static str,
) {
    super::image_layouts::render_pass_layouts(recorder, render_pass_begin, layout_vuid);
    let live = recorder.device().live();
    let images = super::image_layouts::pass_views(live, render_pass_begin)
        .iter()
        .map(|v| live.view(*v).map_or(vk::Image::null(), |r| r.image))
        .collect();
    recorder.pass_images = images;
    let record = recorder
        .device()
        .live()
        .render_pass(render_pass_begin.as_raw().render_pass);
    let begin = render_pass_begin.as_raw();
    let area = recorder
        .device()
        .live()
        .framebuffer_size(begin.framebuffer)
        .map(|[_, _, layers]| (begin.render_area, layers));
    // SAFETY: the chain of a safe struct, and the type its sType names.
    let device_mask = unsafe { group_device_mask(begin.p_next) };
    recorder.instance = Some(crate::recorder::PassInstance {
        subpass: 0,
        area,
        device_mask,
        render_pass: render_pass_begin.as_raw().render_pass,
        subpasses: record.as_ref().map_or(0, |r| r.view_masks.len() as u32),
        view_mask: record
            .as_ref()
            .and_then(|r| r.view_masks.first().copied())
            .unwrap_or(0),
        no_attachments: record
            .as_ref()
            .and_then(|r| r.no_attachments.first().copied())
            .unwrap_or(false),
        samples: None,
        dynamic: false,
        record,
        rendering: None,
        rendering_layouts: None,
        rendering_samples: None,
        rendering_images: None,
        contents,
        framebuffer: begin.framebuffer,
        rendering_flags: vk::RenderingFlags::empty(),
    });
}

/// The device mask of a `VkDeviceGroupRenderPassBeginInfo` in a begin info's chain.
///
/// # Safety
///
/// `p_next` is a valid chain whose nodes are the types their `sType`s name.
pub(super) unsafe fn group_device_mask(p_next: *const std::ffi::c_void) -> Option<u32> {
    // SAFETY: as the caller promises.
    let group: Option<&vk::DeviceGroupRenderPassBeginInfo<'_>> = unsafe {
        super::chained(
            p_next,
            vk::StructureType::DEVICE_GROUP_RENDER_PASS_BEGIN_INFO,
        )
    };
    group.map(|g| g.device_mask)
}

/// A next subpass exists.
pub(crate) fn next_subpass_checks<S: Scope>(
    recorder: &Recorder<'_, S>,
    vuid: &'static str,
) -> Result<()> {
    match &recorder.instance {
        Some(i) if i.subpasses != 0 && i.subpass + 1 >= i.subpasses => refuse(
            vuid,
            format!(
                "The current subpass index must be less than the number of subpasses in the \
                 render pass minus one (subpass {} of {})",
                i.subpass, i.subpasses
            ),
        ),
        _ => Ok(()),
    }
}

/// The recorder moves to the next subpass, whose commands `contents` gives.
pub(crate) fn next_subpass_done<S: Scope>(
    recorder: &mut Recorder<'_, S>,
    contents: vk::SubpassContents,
) {
    let Some(i) = recorder.instance.take() else {
        return;
    };
    let record = i.record.clone();
    let next = i.subpass + 1;
    let view_mask = record
        .as_ref()
        .and_then(|r| r.view_masks.get(next as usize).copied())
        .unwrap_or(0);
    let no_attachments = record
        .and_then(|r| r.no_attachments.get(next as usize).copied())
        .unwrap_or(false);
    recorder.instance = Some(crate::recorder::PassInstance {
        subpass: next,
        view_mask,
        no_attachments,
        samples: None,
        contents,
        ..i
    });
}

/// Ends, before the render pass instance's end is recorded, what a refused end
/// would leave broken: the queries begun inside the instance, and the subpasses not
/// yet visited. The recorder is poisoned by then, so the buffer is not submittable,
/// but the driver only ever sees a valid end.
fn repair_instance_end<S: Scope>(recorder: &mut Recorder<'_, S>, next_subpasses: bool) {
    let raw = recorder.raw();
    let fns = recorder.device().fns().fp_v1_0().clone();
    let inside: Vec<crate::recorder::ActiveQuery> = recorder
        .queries
        .iter()
        .filter(|q| q.subpass.is_some())
        .copied()
        .collect();
    for q in &inside {
        // SAFETY: the query was begun in this recording, inside this instance, and is
        // still active.
        unsafe { (fns.cmd_end_query)(raw, q.pool, q.query) };
    }
    recorder.queries.retain(|q| q.subpass.is_none());
    if let Some(i) = recorder.instance.as_mut().filter(|_| next_subpasses) {
        while i.subpasses != 0 && i.subpass + 1 < i.subpasses {
            // SAFETY: a next subpass exists in the render pass begun in this recording;
            // nothing is recorded in it.
            unsafe { (fns.cmd_next_subpass)(raw, vk::SubpassContents::INLINE) };
            i.subpass += 1;
        }
    }
}

/// A render pass instance ends in its last subpass, with every query begun inside
/// it ended; where not, the recorder is refused and repaired
/// ([`repair_instance_end`]).
pub(crate) fn end_render_pass_checks<S: Scope>(
    recorder: &mut Recorder<'_, S>,
    (last, queries): (&'static str, &'static str),
) -> Result<()> {
    let Some(i) = &recorder.instance else {
        return Ok(());
    };
    let r = if i.subpasses != 0 && i.subpass + 1 != i.subpasses {
        refuse(
            last,
            format!(
                "The current subpass index must be equal to the number of subpasses in the \
                 render pass minus one (subpass {} of {})",
                i.subpass, i.subpasses
            ),
        )
    } else if recorder.queries.iter().any(|q| q.subpass.is_some()) {
        refuse(
            queries,
            "If `vkCmdBeginQuery`* was called within a subpass of the render pass, the \
             corresponding `vkCmdEndQuery`* must have been called subsequently within the same \
             subpass",
        )
    } else {
        Ok(())
    };
    if r.is_err() {
        repair_instance_end(recorder, true);
    }
    r
}

/// Dynamic rendering ends with every query begun inside it ended (repaired as
/// [`end_render_pass_checks`] repairs).
pub(crate) fn end_rendering_checks<S: Scope>(recorder: &mut Recorder<'_, S>) -> Result<()> {
    if recorder.queries.iter().any(|q| q.subpass.is_some()) {
        repair_instance_end(recorder, false);
        return refuse(
            "VUID-vkCmdEndRendering-None-06999",
            "If `vkCmdBeginQuery`* was called within the render pass, the corresponding \
             `vkCmdEndQuery`* must have been called subsequently within the same subpass",
        );
    }
    Ok(())
}

/// The recorder leaves the render pass instance.
pub(crate) fn instance_ended<S: Scope>(recorder: &mut Recorder<'_, S>) {
    recorder.instance = None;
}

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
    /// The render pass's dependencies' source and destination stages are ones the
    /// pool's queue family supports.
    pub dependency_stages: (&'static str, &'static str),
    /// Attachments that alias memory and are written have MAY_ALIAS.
    pub alias: &'static str,
    /// The stencil layout structs' STENCIL layouts need the depth/stencil usage.
    pub stencil: &'static str,
    /// The framebuffer and the render pass are the command buffer's device's (a
    /// rule of `vkCmdBeginRenderPass2` only; the begin info's own commonparent
    /// rule says the same for both commands).
    pub same_device: &'static str,
}

pub(super) const COLOR: &[L] = &[L::COLOR_ATTACHMENT_OPTIMAL];

pub(super) const READ: &[L] = &[L::SHADER_READ_ONLY_OPTIMAL];

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
    dependency_stages: (
        "VUID-vkCmdBeginRenderPass-srcStageMask-06451",
        "VUID-vkCmdBeginRenderPass-dstStageMask-06452",
    ),
    alias: "VUID-vkCmdBeginRenderPass-framebuffer-02532",
    stencil: "VUID-vkCmdBeginRenderPass-stencilInitialLayout-02843",
    same_device: "",
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
    dependency_stages: (
        "VUID-vkCmdBeginRenderPass2-srcStageMask-06453",
        "VUID-vkCmdBeginRenderPass2-dstStageMask-06454",
    ),
    alias: "VUID-vkCmdBeginRenderPass2-framebuffer-02533",
    stencil: "VUID-vkCmdBeginRenderPass2-stencilInitialLayout-02845",
    same_device: "VUID-vkCmdBeginRenderPass2-framebuffer-02779",
};

/// The checks of a render pass instance's begin: the render area inside the
/// framebuffer, enough clear values, the usage each attachment's layouts need,
/// and (through [`super::image_layouts`]) the attachments' current layouts.
pub(crate) fn begin_render_pass_checks<S: Scope>(
    recorder: &Recorder<'_, S>,
    render_pass_begin: &RenderPassBeginInfo<'_>,
    rules: &BeginRules,
) -> Result<()> {
    let live = recorder.device().live();
    let raw = render_pass_begin.as_raw();
    // A frame's begin is most often the last one's on this buffer: the same
    // records, parameters and pool give the same verdict (`BeginChecked`). A chain
    // (device group, imageless views) is checked every time.
    let pass = live.render_pass(raw.render_pass);
    let checked = match (raw.p_next.is_null(), pass.clone()) {
        (true, Some(pass)) => {
            live.framebuffer_record_views(raw.framebuffer)
                .map(|views| crate::state::BeginChecked {
                    pass,
                    views,
                    area: raw.render_area,
                    clears: raw.clear_value_count,
                    rules: core::ptr::from_ref(rules) as usize,
                })
        }
        _ => None,
    };
    let uses = recorder.command_buffer().uses();
    if checked.as_ref().is_some_and(|c| uses.begin_checked(c)) {
        return super::image_layouts::render_pass_layout_checks(
            recorder,
            render_pass_begin,
            rules.initial,
        );
    }
    begin_checks(recorder, render_pass_begin, pass, rules)?;
    if let Some(c) = checked {
        uses.set_begin_checked(c);
    }
    super::image_layouts::render_pass_layout_checks(recorder, render_pass_begin, rules.initial)
}

/// The checks of a render pass begin but its image layouts' (`pass`: the record of
/// the render pass it names, if this device has one).
fn begin_checks<S: Scope>(
    recorder: &Recorder<'_, S>,
    render_pass_begin: &RenderPassBeginInfo<'_>,
    pass: Option<tuff_runtime::Vrc<crate::state::RenderPassRecord>>,
    rules: &BeginRules,
) -> Result<()> {
    let live = recorder.device().live();
    let raw = render_pass_begin.as_raw();
    let size = live.framebuffer_size(raw.framebuffer);
    // Every framebuffer and render pass made through the wrappers is listed on its
    // device: one missing from this device's lists is another device's.
    if !rules.same_device.is_empty() && (pass.is_none() || size.is_none()) {
        refuse(
            rules.same_device,
            "the framebuffer or the render pass is not of the command buffer's device",
        )?;
    }
    // SAFETY: the chain of a safe struct, and the type its sType names.
    let group: Option<&vk::DeviceGroupRenderPassBeginInfo<'_>> = unsafe {
        super::chained(
            raw.p_next,
            vk::StructureType::DEVICE_GROUP_RENDER_PASS_BEGIN_INFO,
        )
    };
    if let Some(g) = group {
        check_device_group(recorder, g, size)?;
    }
    if group.is_none_or(|g| g.device_render_area_count == 0) {
        let area = raw.render_area;
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
    let Some(pass) = pass else {
        return Ok(());
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
    let family = super::pool_family(recorder);
    let no_host = |m: vk::PipelineStageFlags| m & !vk::PipelineStageFlags::HOST;
    for (mask, vuid) in [
        (pass.dependency_stages.0, rules.dependency_stages.0),
        (pass.dependency_stages.1, rules.dependency_stages.1),
    ] {
        if let Some(st) = super::stages::unsupported_stage(no_host(mask), family.flags) {
            refuse(
                vuid,
                format!("a dependency of the render pass names {st:?}, which the pool's queue family ({:?}) does not support", family.flags),
            )?;
        }
    }
    if let Some(made_with) = live.framebuffer_pass_record(raw.framebuffer) {
        if !made_with.compatible(&pass) {
            refuse(
                "VUID-VkRenderPassBeginInfo-renderPass-00904",
                "the render pass is not compatible with the one the framebuffer was created with (its attachments' formats and sample counts, or its subpasses' attachments and view masks, differ)",
            )?;
        }
    }
    check_attachment_views(live, render_pass_begin, &pass)?;
    let views = super::image_layouts::pass_views(live, render_pass_begin);
    check_aliasing(live, &views, &pass, rules.alias)?;
    for (n, (view, taken)) in views.iter().zip(&pass.taken).enumerate() {
        let Some(v) = live.view(*view) else {
            continue;
        };
        let stencil = [L::STENCIL_ATTACHMENT_OPTIMAL, L::STENCIL_READ_ONLY_OPTIMAL];
        if let Some(l) = pass
            .stencil_taken
            .get(n)
            .and_then(|t| t.iter().find(|l| stencil.contains(l)))
        {
            if !v.usage.contains(U::DEPTH_STENCIL_ATTACHMENT) {
                refuse(
                    rules.stencil,
                    format!("the render pass gives attachment {n}'s stencil aspect layout {l:?}, and its view's usage {:?} lacks DEPTH_STENCIL_ATTACHMENT", v.usage),
                )?;
            }
        }
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
    Ok(())
}

/// The rules of a chained `VkDeviceGroupRenderPassBeginInfo`: its device mask
/// against the device's physical devices and the command buffer's initial mask, and
/// each device's render area against the framebuffer and its limits.
fn check_device_group<S: Scope>(
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
        unsafe { crate::state::raw_slice(g.p_device_render_areas, g.device_render_area_count) };
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

/// The views a chained `VkRenderPassAttachmentBeginInfo` gives: none for a
/// framebuffer with image views; for an imageless one, one per attachment image
/// info, each matching it and the render pass's attachment, a single level with
/// the identity swizzle, and no 3D view.
fn check_attachment_views(
    live: &crate::state::Live,
    render_pass_begin: &RenderPassBeginInfo<'_>,
    pass: &crate::state::RenderPassRecord,
) -> Result<()> {
    let raw = render_pass_begin.as_raw();
    // SAFETY: the chain of a safe struct, and the type its sType names.
    let chained: Option<&vk::RenderPassAttachmentBeginInfo<'_>> = unsafe {
        super::chained(
            raw.p_next,
            vk::StructureType::RENDER_PASS_ATTACHMENT_BEGIN_INFO,
        )
    };
    // SAFETY: the safe setter stores the views with their count.
    let views = chained.map_or(&[][..], |c| unsafe {
        crate::state::raw_slice(c.p_attachments, c.attachment_count)
    });
    let Some(infos) = live.imageless(raw.framebuffer) else {
        if !views.is_empty() {
            refuse(
                "VUID-VkRenderPassBeginInfo-framebuffer-03207",
                "a framebuffer with image views, and a chained VkRenderPassAttachmentBeginInfo that gives views too",
            )?;
        }
        return Ok(());
    };
    if views.len() != infos.len() {
        refuse(
            "VUID-VkRenderPassBeginInfo-framebuffer-03208",
            format!(
                "the imageless framebuffer has {} attachment image infos, and the begin info gives {} views",
                infos.len(),
                views.len()
            ),
        )?;
    }
    for (n, (view, info)) in views.iter().zip(&infos).enumerate() {
        let (Some(v), at) = (live.view(*view), format!("pAttachments[{n}]")) else {
            refuse(
                "VUID-VkRenderPassBeginInfo-framebuffer-02780",
                format!("pAttachments[{n}] is no view of the framebuffer's device"),
            )?;
            continue;
        };
        let Some(image) = live.image(v.image) else {
            continue;
        };
        let size = |e: u32| (e >> v.base_level.min(31)).max(1);
        let mut formats = live.view_formats(v.image);
        formats.sort_by_key(|f| f.as_raw());
        let attachment = pass.attachments.get(n);
        for (ok, vuid, what) in [
            (v.levels == 1, "VUID-VkRenderPassAttachmentBeginInfo-pAttachments-03218", "names more than one mip level"),
            (v.identity, "VUID-VkRenderPassAttachmentBeginInfo-pAttachments-03219", "swizzles its components"),
            (v.view_type != vk::ImageViewType::TYPE_3D, "VUID-VkRenderPassAttachmentBeginInfo-pAttachments-04114", "is a 3D view"),
            (image.flags == info.flags, "VUID-VkRenderPassBeginInfo-framebuffer-03209", "is of an image whose flags differ from its attachment image info's"),
            (v.usage == info.usage, "VUID-VkRenderPassBeginInfo-framebuffer-04627", "has a usage other than its attachment image info's"),
            (size(image.extent.width) == info.size[0], "VUID-VkRenderPassBeginInfo-framebuffer-03211", "has a width other than its attachment image info's"),
            (size(image.extent.height) == info.size[1], "VUID-VkRenderPassBeginInfo-framebuffer-03212", "has a height other than its attachment image info's"),
            (v.layers == info.size[2], "VUID-VkRenderPassBeginInfo-framebuffer-03213", "has a layer count other than its attachment image info's"),
            // An image that lists no view formats is compared by its view's format
            // alone (03216), as the 1.3.239 layer does.
            (formats.is_empty() || formats.len() == info.formats.len(), "VUID-VkRenderPassBeginInfo-framebuffer-03214", "is of an image listing another number of view formats than its attachment image info"),
            (formats.is_empty() || formats == info.formats, "VUID-VkRenderPassBeginInfo-framebuffer-03215", "is of an image listing other view formats than its attachment image info"),
            (attachment.is_none_or(|a| a.0 == v.format), "VUID-VkRenderPassBeginInfo-framebuffer-03216", "has a format other than the render pass's attachment"),
            (attachment.is_none_or(|a| a.1 == image.samples), "VUID-VkRenderPassBeginInfo-framebuffer-03217", "is of an image with a sample count other than the render pass's attachment"),
        ] {
            if !ok {
                refuse(vuid, format!("{at} {what}"))?;
            }
        }
    }
    Ok(())
}

/// Refuses two attachments the render pass uses, one of them written, whose
/// views share memory (the same subresources of one image, or bindings that
/// overlap) unless both have MAY_ALIAS.
fn check_aliasing(
    live: &crate::state::Live,
    views: &[vk::ImageView],
    pass: &crate::state::RenderPassRecord,
    vuid: &'static str,
) -> Result<()> {
    use crate::state::{USED_COLOR, USED_DEPTH, USED_DEPTH_RESOLVE, USED_RESOLVE};
    let written = USED_COLOR | USED_RESOLVE | USED_DEPTH | USED_DEPTH_RESOLVE;
    // A render pass's few attachments inline.
    let used: smallvec::SmallVec<[(usize, crate::state::ViewRecord, u8); 4]> = views
        .iter()
        .enumerate()
        .filter_map(|(i, v)| {
            let roles = pass.attachments.get(i)?.2;
            (roles != 0).then_some(())?;
            Some((i, live.view(*v)?, roles))
        })
        .collect();
    let overlap = |a: (u32, u32), b: (u32, u32)| a.0 < b.1 && b.0 < a.1;
    for (k, (i, a, ra)) in used.iter().enumerate() {
        for (j, b, rb) in &used[k + 1..] {
            if (ra | rb) & written == 0 {
                continue;
            }
            let shared = if a.image == b.image {
                a.aspect.intersects(b.aspect)
                    && overlap(
                        (a.base_level, a.base_level + a.levels),
                        (b.base_level, b.base_level + b.levels),
                    )
                    && overlap(
                        (a.base_layer, a.base_layer + a.layers),
                        (b.base_layer, b.base_layer + b.layers),
                    )
            } else {
                match (live.binding(a.image), live.binding(b.image)) {
                    (Some((ma, oa, sa)), Some((mb, ob, sb))) => {
                        ma == mb && oa < ob.saturating_add(sb) && ob < oa.saturating_add(sa)
                    }
                    _ => false,
                }
            };
            let flagged = |n: usize| pass.may_alias.get(n).copied().unwrap_or(false);
            if shared && !(flagged(*i) && flagged(*j)) {
                refuse(
                    vuid,
                    format!("attachments {i} and {j} share memory, one is written, and not both have MAY_ALIAS"),
                )?;
            }
            if shared {
                check_aliased_subpasses(pass, (*i as u32, *ra), (*j as u32, *rb), vuid)?;
            }
        }
    }
    Ok(())
}

/// Two attachments that share memory, `a` and `b` with their roles: every two
/// subpasses that use them, one writing, are ordered by a chain of dependencies
/// (`VUID-VkRenderPassCreateInfo2-None-03049`; the first version's render pass
/// states the same in prose, and its begin's aliasing rule names it).
fn check_aliased_subpasses(
    pass: &crate::state::RenderPassRecord,
    a: (u32, u8),
    b: (u32, u8),
    vuid: &'static str,
) -> Result<()> {
    use crate::state::{USED_COLOR, USED_DEPTH, USED_DEPTH_RESOLVE, USED_RESOLVE};
    let written = USED_COLOR | USED_RESOLVE | USED_DEPTH | USED_DEPTH_RESOLVE;
    let users = |x: u32| -> Vec<u32> {
        pass.used
            .iter()
            .enumerate()
            .filter(|(_, u)| u.contains(&x))
            .map(|(s, _)| s as u32)
            .collect()
    };
    if (a.1 | b.1) & written == 0 {
        return Ok(());
    }
    for s1 in users(a.0) {
        for s2 in users(b.0) {
            if s1 != s2 && !pass.depends(s1.min(s2), s1.max(s2)) {
                let rule = if pass.second {
                    "VUID-VkRenderPassCreateInfo2-None-03049"
                } else {
                    vuid
                };
                refuse(
                    rule,
                    format!("attachments {} and {} share memory, one is written, and subpasses {s1} and {s2}, which use them, have no dependency between them", a.0, b.0),
                )?;
            }
        }
    }
    Ok(())
}

const CLEAR_ATTACHMENTS_PROTECTED: super::copies::Protection = super::copies::Protection {
    protected_src: "",
    protected_dst: "VUID-vkCmdClearAttachments-commandBuffer-02504",
    unprotected_dst: "VUID-vkCmdClearAttachments-commandBuffer-02505",
};

/// Refuses a clear of attachments that the current subpass (or dynamic rendering)
/// does not have with the aspects cleared, and rectangles that are empty, leave the
/// render area or the instance's layers, or (with multiview) name other than one
/// layer from 0. In a continuing secondary, whose inheritance info gives no render
/// area, a clear is refused: the area is known only where the instance is begun.
pub(crate) fn clear_attachments_checks<S: Scope>(
    recorder: &Recorder<'_, S>,
    attachments: &[vk::ClearAttachment],
    rects: &[vk::ClearRect],
) -> Result<()> {
    use vk::ImageAspectFlags as A;
    let Some(instance) = &recorder.instance else {
        return Ok(());
    };
    // The current subpass's color formats and its depth/stencil format.
    let (colors, depth_stencil): (Vec<vk::Format>, [vk::Format; 2]) =
        match (&instance.rendering, &instance.record) {
            (Some(r), _) => (r.colors.clone(), [r.depth, r.stencil]),
            (None, Some(record)) => {
                let i = instance.subpass as usize;
                let depth = record
                    .depth_formats
                    .get(i)
                    .copied()
                    .flatten()
                    .unwrap_or(vk::Format::UNDEFINED);
                (
                    record.color_formats.get(i).cloned().unwrap_or_default(),
                    [depth, depth],
                )
            }
            (None, None) => (Vec::new(), [vk::Format::UNDEFINED; 2]),
        };
    let known = instance.rendering.is_some() || instance.record.is_some();
    for (i, a) in attachments.iter().enumerate() {
        if a.aspect_mask.contains(A::COLOR) {
            if known && a.color_attachment as usize >= colors.len() {
                refuse(
                    "VUID-vkCmdClearAttachments-aspectMask-07271",
                    format!("pAttachments[{i}].colorAttachment is {}, and the current subpass has {} color attachments", a.color_attachment, colors.len()),
                )?;
            }
            continue;
        }
        for (aspect, format) in [(A::DEPTH, depth_stencil[0]), (A::STENCIL, depth_stencil[1])] {
            let has = crate::formats::aspects(format).unwrap_or(A::empty());
            if a.aspect_mask.contains(aspect)
                && format != vk::Format::UNDEFINED
                && !has.contains(aspect)
            {
                refuse(
                    "VUID-vkCmdClearAttachments-pAttachments-07270",
                    format!("pAttachments[{i}] clears {aspect:?}, which the current depth/stencil attachment's format {format:?} lacks"),
                )?;
            }
        }
    }
    for (i, r) in rects.iter().enumerate() {
        if r.rect.extent.width == 0 {
            refuse(
                "VUID-vkCmdClearAttachments-rect-02682",
                format!("pRects[{i}].rect.extent.width is 0"),
            )?;
        }
        if r.rect.extent.height == 0 {
            refuse(
                "VUID-vkCmdClearAttachments-rect-02683",
                format!("pRects[{i}].rect.extent.height is 0"),
            )?;
        }
        let Some((area, layers)) = instance.area else {
            refuse(
                "VUID-vkCmdClearAttachments-pRects-00016",
                "the render area is not known in a continuing secondary command buffer (its inheritance info does not give it): clear_attachments_unchecked takes the caller's word that every rectangle lies inside it",
            )?;
            continue;
        };
        let inside = |o: i32, e: u32, ao: i32, ae: u32| {
            i64::from(o) >= i64::from(ao)
                && i64::from(o) + i64::from(e) <= i64::from(ao) + i64::from(ae)
        };
        let (o, e) = (r.rect.offset, r.rect.extent);
        if !inside(o.x, e.width, area.offset.x, area.extent.width)
            || !inside(o.y, e.height, area.offset.y, area.extent.height)
        {
            refuse(
                "VUID-vkCmdClearAttachments-pRects-00016",
                format!(
                    "pRects[{i}].rect ({o:?}, {e:?}) leaves the render area ({:?}, {:?})",
                    area.offset, area.extent
                ),
            )?;
        }
        if instance.view_mask != 0 && (r.base_array_layer != 0 || r.layer_count != 1) {
            refuse(
                "VUID-vkCmdClearAttachments-baseArrayLayer-00018",
                format!("in a multiview instance pRects[{i}] clears layers {} to {}; it must clear layer 0 alone", r.base_array_layer, u64::from(r.base_array_layer) + u64::from(r.layer_count)),
            )?;
        }
        if instance.view_mask == 0
            && u64::from(r.base_array_layer) + u64::from(r.layer_count) > u64::from(layers)
        {
            refuse(
                "VUID-vkCmdClearAttachments-pRects-06937",
                format!(
                    "pRects[{i}] clears layers {} to {}, past the instance's {layers} layers",
                    r.base_array_layer,
                    u64::from(r.base_array_layer) + u64::from(r.layer_count)
                ),
            )?;
        }
    }
    let live = recorder.device().live();
    let images = instance
        .rendering_images
        .as_deref()
        .unwrap_or(&recorder.pass_images);
    for image in images {
        let protected = live
            .image(*image)
            .is_some_and(|i| i.flags.contains(vk::ImageCreateFlags::PROTECTED));
        super::copies::check_protected(recorder, None, protected, &CLEAR_ATTACHMENTS_PROTECTED)?;
    }
    Ok(())
}
