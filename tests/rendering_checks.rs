//! Dynamic rendering through the safe `begin_rendering`: each attachment against its
//! slot (usage, aspects, layouts, resolve), the views against each other, and the
//! render area against the views and the device's limits.
//!
//! Each case breaks one rule through the safe method, which must refuse it with the
//! rule's VUID, and through `begin_rendering_unchecked` under the validation layer
//! (with a messenger that makes the layer skip the call), which must name the same
//! VUID, or say nothing where the 1.3.239 layer does not check the rule; a correct
//! instance with a resolved color attachment and a depth/stencil attachment goes
//! through with the layer silent.
//!
//! SAFETY of the `unsafe` blocks around `_unchecked` calls: each breaks only the rule
//! under test, which the layer reports and so skips (the end of the instance it
//! skipped is skipped as well); the command buffers are never submitted.

#[path = "common/tuff_setup.rs"]
mod tuff_setup;
#[path = "common/vulkan.rs"]
mod vulkan;

use tuff::vk;
use tuff_setup::{breaks, Layer, Setup};
use vulkan::assert_silent;

type L = vk::ImageLayout;
type U = vk::ImageUsageFlags;
type M = vk::ResolveModeFlags;

const SIZE: u32 = 8;

/// An image of one format, sample count and usage, its memory and a view of it.
struct Target {
    view: tuff::ImageView,
    _memory: tuff::DeviceMemory,
    _image: tuff::Image,
}

fn target(
    s: &Setup,
    format: vk::Format,
    samples: vk::SampleCountFlags,
    usage: U,
    stencil_usage: Option<U>,
) -> Target {
    let mut stencil =
        tuff::ImageStencilUsageCreateInfo::new().stencil_usage(stencil_usage.unwrap_or(usage));
    let mut info = tuff::ImageCreateInfo::new()
        .image_type(vk::ImageType::TYPE_2D)
        .format(format)
        .extent(vk::Extent3D {
            width: SIZE,
            height: SIZE,
            depth: 1,
        })
        .mip_levels(1)
        .array_layers(1)
        .samples(samples)
        .usage(usage);
    if stencil_usage.is_some() {
        info = info.push_next(&mut stencil);
    }
    let image = s.device.create_image(&info).expect("image");
    let memory = s.bind_image(&image);
    let aspect = match tuff::vk::Format::as_raw(format) {
        f if f == vk::Format::D32_SFLOAT.as_raw() => vk::ImageAspectFlags::DEPTH,
        f if f == vk::Format::S8_UINT.as_raw() => vk::ImageAspectFlags::STENCIL,
        f if f == vk::Format::D32_SFLOAT_S8_UINT.as_raw() => {
            vk::ImageAspectFlags::DEPTH | vk::ImageAspectFlags::STENCIL
        }
        _ => vk::ImageAspectFlags::COLOR,
    };
    let view = s
        .device
        .create_image_view(
            &tuff::ImageViewCreateInfo::new(&image)
                .view_type(vk::ImageViewType::TYPE_2D)
                .format(format)
                .subresource_range(vk::ImageSubresourceRange {
                    aspect_mask: aspect,
                    base_mip_level: 0,
                    level_count: 1,
                    base_array_layer: 0,
                    layer_count: 1,
                }),
        )
        .expect("view");
    Target {
        view,
        _memory: memory,
        _image: image,
    }
}

/// The images the cases render to.
struct Targets {
    /// RGBA8 UNORM, one sample.
    color: Target,
    /// RGBA8 UNORM, four samples.
    color4: Target,
    /// BGRA8 UNORM, one sample: another format.
    other: Target,
    /// R8 UINT, four samples and one.
    uint4: Target,
    uint: Target,
    /// D32 S8, one sample, and one sampled only (its stencil usage says so apart).
    ds: Target,
    ds_no_stencil_usage: Target,
    /// D32 and S8 alone.
    depth: Target,
    stencil: Target,
    /// D32 S8, four samples.
    ds4: Target,
}

fn targets(s: &Setup) -> Targets {
    let one = vk::SampleCountFlags::TYPE_1;
    let four = vk::SampleCountFlags::TYPE_4;
    let color = U::COLOR_ATTACHMENT;
    let ds = U::DEPTH_STENCIL_ATTACHMENT;
    Targets {
        color: target(s, vk::Format::R8G8B8A8_UNORM, one, color, None),
        color4: target(s, vk::Format::R8G8B8A8_UNORM, four, color, None),
        other: target(s, vk::Format::B8G8R8A8_UNORM, one, color, None),
        uint4: target(s, vk::Format::R8_UINT, four, color, None),
        uint: target(s, vk::Format::R8_UINT, one, color, None),
        ds: target(s, vk::Format::D32_SFLOAT_S8_UINT, one, ds, None),
        ds_no_stencil_usage: target(
            s,
            vk::Format::D32_SFLOAT_S8_UINT,
            one,
            U::SAMPLED,
            Some(U::SAMPLED),
        ),
        depth: target(s, vk::Format::D32_SFLOAT, one, ds, None),
        stencil: target(s, vk::Format::S8_UINT, one, ds, None),
        ds4: target(s, vk::Format::D32_SFLOAT_S8_UINT, four, ds, None),
    }
}

fn attachment(view: &tuff::ImageView, layout: L) -> tuff::RenderingAttachmentInfo<'_> {
    tuff::RenderingAttachmentInfo::new()
        .image_view(Some(view))
        .image_layout(layout)
        .load_op(vk::AttachmentLoadOp::CLEAR)
        .store_op(vk::AttachmentStoreOp::STORE)
}

fn resolved<'a>(
    a: tuff::RenderingAttachmentInfo<'a>,
    mode: M,
    view: &'a tuff::ImageView,
    layout: L,
) -> tuff::RenderingAttachmentInfo<'a> {
    a.resolve_mode(mode)
        .resolve_image_view(Some(view))
        .resolve_image_layout(layout)
}

fn area(x: i32, y: i32, width: u32, height: u32) -> vk::Rect2D {
    vk::Rect2D {
        offset: vk::Offset2D { x, y },
        extent: vk::Extent2D { width, height },
    }
}

fn info<'a>(
    color: &'a [tuff::RenderingAttachmentInfo<'a>],
    depth: Option<&'a tuff::RenderingAttachmentInfo<'a>>,
    stencil: Option<&'a tuff::RenderingAttachmentInfo<'a>>,
) -> tuff::RenderingInfo<'a> {
    let mut i = tuff::RenderingInfo::new()
        .render_area(area(0, 0, SIZE, SIZE))
        .layer_count(1)
        .color_attachments(color);
    if let Some(d) = depth {
        i = i.depth_attachment(Some(d));
    }
    if let Some(st) = stencil {
        i = i.stencil_attachment(Some(st));
    }
    i
}

/// Begins and ends a render pass instance of `info` in a recording of `level`
/// (through `begin_rendering_unchecked` where `unchecked`), returning what the
/// recording's end returns.
fn render(
    cb: &mut tuff::CommandBuffer,
    info: &tuff::RenderingInfo<'_>,
    unchecked: bool,
    secondary: bool,
) -> tuff::Result<()> {
    let inheritance = tuff::CommandBufferInheritanceInfo::new();
    let begin = if secondary {
        tuff::CommandBufferBeginInfo::new().inheritance_info(Some(&inheritance))
    } else {
        tuff::CommandBufferBeginInfo::new()
    };
    let rec = cb.begin(&begin).expect("begin");
    let rec = if unchecked {
        // SAFETY: see the module docs.
        unsafe { rec.begin_rendering_unchecked(info) }
    } else {
        rec.begin_rendering(info)
    };
    rec.end_rendering().end()
}

/// The rules the 1.3.239 layer does not check: a depth or stencil layout that
/// names the other aspect alone (tuff's error alone proves them; so it does for the
/// render area past the framebuffer limits).
const LAYER_SILENT: &[&str] = &[
    "VUID-VkRenderingInfo-pDepthAttachment-07732",
    "VUID-VkRenderingInfo-pDepthAttachment-07733",
    "VUID-VkRenderingInfo-pStencilAttachment-07734",
    "VUID-VkRenderingInfo-pStencilAttachment-07735",
];

fn layer(rule: &str) -> Layer<'static> {
    if LAYER_SILENT.contains(&rule) {
        Layer::Silent
    } else {
        Layer::Names
    }
}

/// The rule `rule` is broken by `info`: refused by the safe method and, where
/// `layer` says so, named by the layer.
fn check(s: &Setup, rule: &str, layer: Layer<'_>, info: &tuff::RenderingInfo<'_>) {
    let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    breaks(s, rule, layer, |unchecked| {
        render(&mut cb, info, unchecked, false)
    });
}

/// A correct instance: a four-sample color attachment resolved into a one-sample
/// one, and a depth/stencil view in both the depth and the stencil slot.
#[test]
fn a_correct_instance_begins() {
    let _serial = vulkan::serial();
    let s = tuff_setup::setup_full_features(true);
    let t = targets(&s);
    let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let color = [resolved(
        attachment(&t.color4.view, L::COLOR_ATTACHMENT_OPTIMAL),
        M::AVERAGE,
        &t.color.view,
        L::COLOR_ATTACHMENT_OPTIMAL,
    )];
    render(&mut cb, &info(&color, None, None), false, false).expect("a resolved color attachment");
    let ds = attachment(&t.ds.view, L::DEPTH_STENCIL_ATTACHMENT_OPTIMAL);
    let one = [attachment(&t.color.view, L::COLOR_ATTACHMENT_OPTIMAL)];
    render(&mut cb, &info(&one, Some(&ds), Some(&ds)), false, false)
        .expect("depth and stencil of one view");
    let depth = attachment(&t.depth.view, L::DEPTH_ATTACHMENT_OPTIMAL);
    render(&mut cb, &info(&one, Some(&depth), None), false, false).expect("a depth-only view");
    assert_silent(&s.messages);
}

/// Each attachment's own rules: its layouts and its resolve.
#[test]
fn an_attachment_keeps_its_layouts_and_resolve() {
    let _serial = vulkan::serial();
    let s = tuff_setup::setup_full_features(true);
    let t = targets(&s);
    let color = |layout| [attachment(&t.color.view, layout)];
    let cases: Vec<(&str, [tuff::RenderingAttachmentInfo<'_>; 1])> = vec![
        (
            "VUID-VkRenderingAttachmentInfo-imageView-06135",
            color(L::TRANSFER_DST_OPTIMAL),
        ),
        (
            "VUID-VkRenderingInfo-colorAttachmentCount-06090",
            color(L::DEPTH_STENCIL_ATTACHMENT_OPTIMAL),
        ),
        (
            "VUID-VkRenderingInfo-colorAttachmentCount-06096",
            color(L::DEPTH_READ_ONLY_STENCIL_ATTACHMENT_OPTIMAL),
        ),
        (
            "VUID-VkRenderingInfo-colorAttachmentCount-06100",
            color(L::DEPTH_ATTACHMENT_OPTIMAL),
        ),
        (
            "VUID-VkRenderingAttachmentInfo-imageView-06132",
            [resolved(
                attachment(&t.color.view, L::COLOR_ATTACHMENT_OPTIMAL),
                M::AVERAGE,
                &t.other.view,
                L::COLOR_ATTACHMENT_OPTIMAL,
            )],
        ),
        (
            "VUID-VkRenderingAttachmentInfo-imageView-06860",
            [attachment(&t.color4.view, L::COLOR_ATTACHMENT_OPTIMAL)
                .resolve_mode(M::AVERAGE)
                .resolve_image_layout(L::COLOR_ATTACHMENT_OPTIMAL)],
        ),
        (
            "VUID-VkRenderingAttachmentInfo-imageView-06129",
            [resolved(
                attachment(&t.color4.view, L::COLOR_ATTACHMENT_OPTIMAL),
                M::SAMPLE_ZERO,
                &t.color.view,
                L::COLOR_ATTACHMENT_OPTIMAL,
            )],
        ),
        (
            "VUID-VkRenderingAttachmentInfo-imageView-06130",
            [resolved(
                attachment(&t.uint4.view, L::COLOR_ATTACHMENT_OPTIMAL),
                M::AVERAGE,
                &t.uint.view,
                L::COLOR_ATTACHMENT_OPTIMAL,
            )],
        ),
        (
            "VUID-VkRenderingAttachmentInfo-imageView-06864",
            [resolved(
                attachment(&t.color4.view, L::COLOR_ATTACHMENT_OPTIMAL),
                M::AVERAGE,
                &t.color4.view,
                L::COLOR_ATTACHMENT_OPTIMAL,
            )],
        ),
        (
            "VUID-VkRenderingAttachmentInfo-imageView-06865",
            [resolved(
                attachment(&t.color4.view, L::COLOR_ATTACHMENT_OPTIMAL),
                M::AVERAGE,
                &t.other.view,
                L::COLOR_ATTACHMENT_OPTIMAL,
            )],
        ),
    ];
    let resolve_layout = |layout| {
        [resolved(
            attachment(&t.color4.view, L::COLOR_ATTACHMENT_OPTIMAL),
            M::AVERAGE,
            &t.color.view,
            layout,
        )]
    };
    let resolve_cases: Vec<(&str, L)> = vec![
        (
            "VUID-VkRenderingAttachmentInfo-imageView-06136",
            L::TRANSFER_SRC_OPTIMAL,
        ),
        (
            "VUID-VkRenderingAttachmentInfo-imageView-06137",
            L::DEPTH_READ_ONLY_OPTIMAL,
        ),
        (
            "VUID-VkRenderingAttachmentInfo-imageView-06142",
            L::READ_ONLY_OPTIMAL,
        ),
        (
            "VUID-VkRenderingInfo-colorAttachmentCount-06091",
            L::DEPTH_STENCIL_ATTACHMENT_OPTIMAL,
        ),
        (
            "VUID-VkRenderingInfo-colorAttachmentCount-06097",
            L::DEPTH_ATTACHMENT_STENCIL_READ_ONLY_OPTIMAL,
        ),
        (
            "VUID-VkRenderingInfo-colorAttachmentCount-06101",
            L::STENCIL_ATTACHMENT_OPTIMAL,
        ),
    ];
    for (rule, color) in &cases {
        check(&s, rule, Layer::Names, &info(color, None, None));
    }
    for (rule, layout) in resolve_cases {
        check(
            &s,
            rule,
            Layer::Names,
            &info(&resolve_layout(layout), None, None),
        );
    }
    assert_silent(&s.messages);
}

/// The depth and stencil slots: usage, aspects, layouts, resolve, and one view.
#[test]
fn depth_and_stencil_slots_keep_their_rules() {
    let _serial = vulkan::serial();
    let s = tuff_setup::setup_full_features(true);
    let t = targets(&s);
    let one = [attachment(&t.color.view, L::COLOR_ATTACHMENT_OPTIMAL)];
    let ds = |view, layout| attachment(view, layout);
    let depth_cases: Vec<(&str, tuff::RenderingAttachmentInfo<'_>)> = vec![
        (
            "VUID-VkRenderingInfo-pDepthAttachment-06547",
            ds(&t.stencil.view, L::DEPTH_STENCIL_ATTACHMENT_OPTIMAL),
        ),
        (
            "VUID-VkRenderingInfo-pDepthAttachment-06092",
            ds(&t.ds.view, L::COLOR_ATTACHMENT_OPTIMAL),
        ),
        (
            "VUID-VkRenderingInfo-pDepthAttachment-07732",
            ds(&t.ds.view, L::STENCIL_ATTACHMENT_OPTIMAL),
        ),
        (
            "VUID-VkRenderingInfo-pDepthAttachment-06093",
            resolved(
                ds(&t.ds4.view, L::DEPTH_STENCIL_ATTACHMENT_OPTIMAL),
                M::SAMPLE_ZERO,
                &t.ds.view,
                L::COLOR_ATTACHMENT_OPTIMAL,
            ),
        ),
        (
            "VUID-VkRenderingInfo-pDepthAttachment-06098",
            resolved(
                ds(&t.ds4.view, L::DEPTH_STENCIL_ATTACHMENT_OPTIMAL),
                M::SAMPLE_ZERO,
                &t.ds.view,
                L::DEPTH_READ_ONLY_STENCIL_ATTACHMENT_OPTIMAL,
            ),
        ),
        (
            "VUID-VkRenderingInfo-pDepthAttachment-07733",
            resolved(
                ds(&t.ds4.view, L::DEPTH_STENCIL_ATTACHMENT_OPTIMAL),
                M::SAMPLE_ZERO,
                &t.ds.view,
                L::STENCIL_ATTACHMENT_OPTIMAL,
            ),
        ),
    ];
    let ds4 = [attachment(&t.color4.view, L::COLOR_ATTACHMENT_OPTIMAL)];
    let stencil_cases: Vec<(&str, tuff::RenderingAttachmentInfo<'_>)> = vec![
        (
            "VUID-VkRenderingInfo-pStencilAttachment-06089",
            ds(
                &t.ds_no_stencil_usage.view,
                L::DEPTH_STENCIL_ATTACHMENT_OPTIMAL,
            ),
        ),
        (
            "VUID-VkRenderingInfo-pStencilAttachment-06548",
            ds(&t.depth.view, L::DEPTH_STENCIL_ATTACHMENT_OPTIMAL),
        ),
        (
            "VUID-VkRenderingInfo-pStencilAttachment-06094",
            ds(&t.ds.view, L::COLOR_ATTACHMENT_OPTIMAL),
        ),
        (
            "VUID-VkRenderingInfo-pStencilAttachment-07734",
            ds(&t.ds.view, L::DEPTH_ATTACHMENT_OPTIMAL),
        ),
        (
            "VUID-VkRenderingInfo-pStencilAttachment-06095",
            resolved(
                ds(&t.ds4.view, L::DEPTH_STENCIL_ATTACHMENT_OPTIMAL),
                M::SAMPLE_ZERO,
                &t.ds.view,
                L::COLOR_ATTACHMENT_OPTIMAL,
            ),
        ),
        (
            "VUID-VkRenderingInfo-pStencilAttachment-06099",
            resolved(
                ds(&t.ds4.view, L::DEPTH_STENCIL_ATTACHMENT_OPTIMAL),
                M::SAMPLE_ZERO,
                &t.ds.view,
                L::DEPTH_ATTACHMENT_STENCIL_READ_ONLY_OPTIMAL,
            ),
        ),
        (
            "VUID-VkRenderingInfo-pStencilAttachment-07735",
            resolved(
                ds(&t.ds4.view, L::DEPTH_STENCIL_ATTACHMENT_OPTIMAL),
                M::SAMPLE_ZERO,
                &t.ds.view,
                L::DEPTH_ATTACHMENT_OPTIMAL,
            ),
        ),
    ];
    // Each case in its slot; a resolving one beside a four-sample color attachment.
    let slots = [(true, &depth_cases), (false, &stencil_cases)];
    for (depth, cases) in slots {
        for (rule, a) in cases.iter() {
            let colors = if a.resolve_mode != M::NONE {
                &ds4
            } else {
                &one
            };
            let (d, st) = if depth {
                (Some(a), None)
            } else {
                (None, Some(a))
            };
            check(&s, rule, layer(rule), &info(colors, d, st));
        }
    }
    // A stencil resolve mode the device does not support (lavapipe resolves stencil
    // by sample zero, minimum or maximum, not by average).
    let average = resolved(
        ds(&t.ds4.view, L::DEPTH_STENCIL_ATTACHMENT_OPTIMAL),
        M::AVERAGE,
        &t.ds.view,
        L::DEPTH_STENCIL_ATTACHMENT_OPTIMAL,
    );
    check(
        &s,
        "VUID-VkRenderingInfo-pStencilAttachment-06103",
        Layer::Names,
        &info(&ds4, None, Some(&average)),
    );
    // The depth slot's view must have the depth/stencil usage (a color view there).
    let color_there = ds(&t.color.view, L::DEPTH_STENCIL_ATTACHMENT_OPTIMAL);
    check(
        &s,
        "VUID-VkRenderingInfo-pDepthAttachment-06088",
        Layer::Names,
        &info(&one, Some(&color_there), None),
    );
    // A depth-only view in the color slot.
    let depth_there = [ds(&t.ds.view, L::COLOR_ATTACHMENT_OPTIMAL)];
    check(
        &s,
        "VUID-VkRenderingInfo-colorAttachmentCount-06087",
        Layer::Names,
        &info(&depth_there, None, None),
    );
    // Depth and stencil name one view, and resolve into one.
    let d = ds(&t.ds.view, L::DEPTH_STENCIL_ATTACHMENT_OPTIMAL);
    let other = ds(&t.depth.view, L::DEPTH_STENCIL_ATTACHMENT_OPTIMAL);
    check(
        &s,
        "VUID-VkRenderingInfo-pDepthAttachment-06085",
        Layer::Names,
        &info(&one, Some(&other), Some(&d)),
    );
    let second = target(
        &s,
        vk::Format::D32_SFLOAT_S8_UINT,
        vk::SampleCountFlags::TYPE_1,
        U::DEPTH_STENCIL_ATTACHMENT,
        None,
    );
    let d4 = resolved(
        ds(&t.ds4.view, L::DEPTH_STENCIL_ATTACHMENT_OPTIMAL),
        M::SAMPLE_ZERO,
        &t.ds.view,
        L::DEPTH_STENCIL_ATTACHMENT_OPTIMAL,
    );
    let s4 = resolved(
        ds(&t.ds4.view, L::DEPTH_STENCIL_ATTACHMENT_OPTIMAL),
        M::SAMPLE_ZERO,
        &second.view,
        L::DEPTH_STENCIL_ATTACHMENT_OPTIMAL,
    );
    check(
        &s,
        "VUID-VkRenderingInfo-pDepthAttachment-06086",
        Layer::Names,
        &info(&ds4, Some(&d4), Some(&s4)),
    );
    // The views' sample counts agree.
    check(
        &s,
        "VUID-VkRenderingInfo-multisampledRenderToSingleSampled-06857",
        Layer::Names,
        &info(&ds4, Some(&d), None),
    );
    assert_silent(&s.messages);
}

/// The render area inside the views and the device's limits; the color count and
/// view mask against the limits; a secondary's instance executes no secondaries.
#[test]
fn the_render_area_and_counts_keep_to_the_views_and_limits() {
    let _serial = vulkan::serial();
    let s = tuff_setup::setup_full_features(true);
    let t = targets(&s);
    let one = [attachment(&t.color.view, L::COLOR_ATTACHMENT_OPTIMAL)];
    let with_area = |a| info(&one, None, None).render_area(a);
    check(
        &s,
        "VUID-VkRenderingInfo-pNext-06077",
        Layer::Names,
        &with_area(area(-1, 0, SIZE, SIZE)),
    );
    check(
        &s,
        "VUID-VkRenderingInfo-pNext-06078",
        Layer::Names,
        &with_area(area(0, -1, SIZE, SIZE)),
    );
    check(
        &s,
        "VUID-VkRenderingInfo-pNext-06079",
        Layer::Names,
        &with_area(area(1, 0, SIZE, SIZE)),
    );
    check(
        &s,
        "VUID-VkRenderingInfo-pNext-06080",
        Layer::Names,
        &with_area(area(0, 1, SIZE, SIZE)),
    );
    let limits = s.physical.get_properties().limits;
    let none: [tuff::RenderingAttachmentInfo<'_>; 0] = [];
    let far = |a| info(&none, None, None).render_area(a);
    check(
        &s,
        "VUID-VkRenderingInfo-pNext-07815",
        Layer::Silent,
        &far(area(limits.max_framebuffer_width as i32, 0, 1, 1)),
    );
    check(
        &s,
        "VUID-VkRenderingInfo-pNext-07816",
        Layer::Silent,
        &far(area(0, limits.max_framebuffer_height as i32, 1, 1)),
    );
    // A device group's render areas, each inside the views.
    let areas = [area(0, 0, SIZE + 1, SIZE)];
    let mut group = tuff::DeviceGroupRenderPassBeginInfo::new()
        .device_mask(1)
        .device_render_areas(&areas);
    check(
        &s,
        "VUID-VkRenderingInfo-pNext-06083",
        Layer::Names,
        &info(&one, None, None).push_next(&mut group),
    );
    let areas = [area(0, 0, SIZE, SIZE + 1)];
    let mut group = tuff::DeviceGroupRenderPassBeginInfo::new()
        .device_mask(1)
        .device_render_areas(&areas);
    check(
        &s,
        "VUID-VkRenderingInfo-pNext-06084",
        Layer::Names,
        &info(&one, None, None).push_next(&mut group),
    );
    // More color attachments than the device has.
    let unused: Vec<tuff::RenderingAttachmentInfo<'_>> = (0..=limits.max_color_attachments)
        .map(|_| tuff::RenderingAttachmentInfo::new())
        .collect();
    check(
        &s,
        "VUID-VkRenderingInfo-colorAttachmentCount-06106",
        Layer::Names,
        &info(&unused, None, None),
    );
    // A view past maxMultiviewViewCount (lavapipe's is below 32).
    check(
        &s,
        "VUID-VkRenderingInfo-viewMask-06128",
        Layer::Names,
        &info(&one, None, None).view_mask(1 << 31),
    );
    // A secondary's instance.
    let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::SECONDARY);
    let flagged =
        info(&one, None, None).flags(vk::RenderingFlags::CONTENTS_SECONDARY_COMMAND_BUFFERS);
    breaks(
        &s,
        "VUID-vkCmdBeginRendering-commandBuffer-06068",
        Layer::Names,
        |unchecked| render(&mut cb, &flagged, unchecked, true),
    );
    assert_silent(&s.messages);
}

/// The present layout is no attachment's (06145, 06146): a device with
/// VK_KHR_swapchain, which brings the layout.
#[test]
fn no_attachment_is_rendered_in_the_present_layout() {
    let _serial = vulkan::serial();
    let s = tuff_setup::setup_with(true, tuff_setup::Wsi::Xlib);
    let t = targets(&s);
    let present = [attachment(&t.color.view, L::PRESENT_SRC_KHR)];
    check(
        &s,
        "VUID-VkRenderingAttachmentInfo-imageView-06145",
        Layer::Names,
        &info(&present, None, None),
    );
    let resolve = [resolved(
        attachment(&t.color4.view, L::COLOR_ATTACHMENT_OPTIMAL),
        M::AVERAGE,
        &t.color.view,
        L::PRESENT_SRC_KHR,
    )];
    check(
        &s,
        "VUID-VkRenderingAttachmentInfo-imageView-06146",
        Layer::Names,
        &info(&resolve, None, None),
    );
    assert_silent(&s.messages);
}
