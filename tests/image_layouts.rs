//! Image layouts: every command that names the layout of an image's subresources
//! is checked against the layout they are in when it executes, which the recorder
//! follows through barriers, render passes and secondaries, and each submission
//! through the submissions before it.
//!
//! Each rule is broken twice: through the safe method, which must refuse it with the
//! rule's VUID, and through the `_unchecked` twin under the validation layer (told to
//! skip the call it reports), which must name the same VUID. Programs that keep the
//! rules run with no message from the layer.
//!
//! SAFETY of the `unsafe` blocks: the recording methods are `unsafe` for rules their
//! `# Safety` sections list; these programs keep them (the images, buffers and
//! regions are valid and in bounds) but for the layout each case names wrongly on
//! purpose, which tuff refuses and the layer skips.

#[path = "common/pipelines.rs"]
mod pipelines;
#[path = "common/tuff_setup.rs"]
mod tuff_setup;
#[path = "common/vulkan.rs"]
mod vulkan;

use pipelines::host_buffer;
use tuff::vk;
use tuff_setup::{setup, vuid, Setup};
use vulkan::assert_silent;

const UNDEFINED: vk::ImageLayout = vk::ImageLayout::UNDEFINED;
const GENERAL: vk::ImageLayout = vk::ImageLayout::GENERAL;
const SRC: vk::ImageLayout = vk::ImageLayout::TRANSFER_SRC_OPTIMAL;
const DST: vk::ImageLayout = vk::ImageLayout::TRANSFER_DST_OPTIMAL;
const SIDE: u32 = 4;

/// Runs `unchecked` with the layer told to skip the call it reports, and fails
/// unless the layer named `vuid`.
fn layer_names(s: &Setup, vuid: &str, unchecked: impl FnOnce()) {
    s.messages.take();
    s.messages.abort_on_error(true);
    unchecked();
    s.messages.abort_on_error(false);
    let messages = s.messages.take();
    assert!(
        messages.iter().any(|m| m.contains(vuid)),
        "the validation layer did not report {vuid}; it said:\n{}",
        messages.join("\n")
    );
}

/// A `SIDE` x `SIDE` image of `format` and `samples` with memory.
fn image(
    s: &Setup,
    format: vk::Format,
    samples: vk::SampleCountFlags,
    usage: vk::ImageUsageFlags,
) -> (tuff::Image, tuff::DeviceMemory) {
    let image = s
        .device
        .create_image(
            &tuff::ImageCreateInfo::new()
                .image_type(vk::ImageType::TYPE_2D)
                .format(format)
                .extent(vk::Extent3D {
                    width: SIDE,
                    height: SIDE,
                    depth: 1,
                })
                .mip_levels(1)
                .array_layers(1)
                .samples(samples)
                .usage(usage),
        )
        .expect("image");
    let memory = s.bind_image(&image);
    (image, memory)
}

fn color_image(s: &Setup) -> (tuff::Image, tuff::DeviceMemory) {
    image(
        s,
        vk::Format::R8G8B8A8_UNORM,
        vk::SampleCountFlags::TYPE_1,
        vk::ImageUsageFlags::TRANSFER_SRC | vk::ImageUsageFlags::TRANSFER_DST,
    )
}

fn range(aspect: vk::ImageAspectFlags) -> vk::ImageSubresourceRange {
    vk::ImageSubresourceRange {
        aspect_mask: aspect,
        base_mip_level: 0,
        level_count: 1,
        base_array_layer: 0,
        layer_count: 1,
    }
}

fn layers(aspect: vk::ImageAspectFlags) -> vk::ImageSubresourceLayers {
    vk::ImageSubresourceLayers {
        aspect_mask: aspect,
        mip_level: 0,
        base_array_layer: 0,
        layer_count: 1,
    }
}

const COLOR: vk::ImageAspectFlags = vk::ImageAspectFlags::COLOR;
const WHOLE: vk::Extent3D = vk::Extent3D {
    width: SIDE,
    height: SIDE,
    depth: 1,
};

/// Records a barrier that moves the whole of `image` (aspects `aspect`) from `old`
/// to `new`.
fn transition(
    rec: &mut tuff::Recorder<'_, tuff::Outside>,
    image: &tuff::Image,
    aspect: vk::ImageAspectFlags,
    old: vk::ImageLayout,
    new: vk::ImageLayout,
) -> tuff::Result<()> {
    let barrier = tuff::ImageMemoryBarrier::new(image)
        .old_layout(old)
        .new_layout(new)
        .src_access_mask(vk::AccessFlags::TRANSFER_WRITE)
        .dst_access_mask(vk::AccessFlags::TRANSFER_READ | vk::AccessFlags::TRANSFER_WRITE)
        .src_queue_family_index(vk::QUEUE_FAMILY_IGNORED)
        .dst_queue_family_index(vk::QUEUE_FAMILY_IGNORED)
        .subresource_range(range(aspect));
    rec.pipeline_barrier(
        vk::PipelineStageFlags::TRANSFER,
        vk::PipelineStageFlags::TRANSFER,
        vk::DependencyFlags::empty(),
        &[],
        &[],
        &[barrier],
    )
}

/// A command that names a layout, recorded checked (`false`) or unchecked (`true`).
type Call<'a> = Box<dyn Fn(&mut tuff::Recorder<'_, tuff::Outside>, bool) -> tuff::Result<()> + 'a>;

/// Every command that names an image layout, each after barriers that leave its
/// images in other layouts than it names: refused with its rule, and named by the
/// layer for the unchecked twin. The same commands with the right layouts record
/// and run with no message.
#[test]
fn each_command_that_names_a_layout_is_checked_and_the_layer_agrees() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let (a, _a_memory) = color_image(&s);
    let (b, _b_memory) = color_image(&s);
    let (depth, _depth_memory) = image(
        &s,
        vk::Format::D32_SFLOAT,
        vk::SampleCountFlags::TYPE_1,
        vk::ImageUsageFlags::TRANSFER_DST,
    );
    let (multi, _multi_memory) = image(
        &s,
        vk::Format::R8G8B8A8_UNORM,
        vk::SampleCountFlags::TYPE_4,
        vk::ImageUsageFlags::TRANSFER_SRC | vk::ImageUsageFlags::COLOR_ATTACHMENT,
    );
    let (buffer, _buffer_memory) = host_buffer(
        &s,
        u64::from(SIDE * SIDE * 4),
        vk::BufferUsageFlags::TRANSFER_SRC | vk::BufferUsageFlags::TRANSFER_DST,
    );
    let buffer_region = vk::BufferImageCopy {
        buffer_offset: 0,
        buffer_row_length: 0,
        buffer_image_height: 0,
        image_subresource: layers(COLOR),
        image_offset: vk::Offset3D::default(),
        image_extent: WHOLE,
    };
    let buffer_region2 = [tuff::BufferImageCopy2::new()
        .image_subresource(layers(COLOR))
        .image_extent(WHOLE)];
    let copy = vk::ImageCopy {
        src_subresource: layers(COLOR),
        src_offset: vk::Offset3D::default(),
        dst_subresource: layers(COLOR),
        dst_offset: vk::Offset3D::default(),
        extent: WHOLE,
    };
    let copy2 = [tuff::ImageCopy2::new()
        .src_subresource(layers(COLOR))
        .dst_subresource(layers(COLOR))
        .extent(WHOLE)];
    let corner = vk::Offset3D {
        x: SIDE as i32,
        y: SIDE as i32,
        z: 1,
    };
    let blit = vk::ImageBlit {
        src_subresource: layers(COLOR),
        src_offsets: [vk::Offset3D::default(), corner],
        dst_subresource: layers(COLOR),
        dst_offsets: [vk::Offset3D::default(), corner],
    };
    let blit2 = [tuff::ImageBlit2::new()
        .src_subresource(layers(COLOR))
        .src_offsets([vk::Offset3D::default(), corner])
        .dst_subresource(layers(COLOR))
        .dst_offsets([vk::Offset3D::default(), corner])];
    let resolve = vk::ImageResolve {
        src_subresource: layers(COLOR),
        src_offset: vk::Offset3D::default(),
        dst_subresource: layers(COLOR),
        dst_offset: vk::Offset3D::default(),
        extent: WHOLE,
    };
    let resolve2 = [tuff::ImageResolve2::new()
        .src_subresource(layers(COLOR))
        .dst_subresource(layers(COLOR))
        .extent(WHOLE)];
    let clear = vk::ClearColorValue {
        float32: [0.5, 0.5, 0.5, 1.0],
    };
    let clear_depth = vk::ClearDepthStencilValue {
        depth: 1.0,
        stencil: 0,
    };
    let depth_aspect = vk::ImageAspectFlags::DEPTH;

    // Before each case the sources `a` and `multi` are moved to
    // TRANSFER_SRC_OPTIMAL and the destinations `b` and `depth` to
    // TRANSFER_DST_OPTIMAL; each case then names GENERAL for one of them.
    let cases: Vec<(&str, Call<'_>)> = vec![
        (
            "VUID-vkCmdCopyBufferToImage-dstImageLayout-00180",
            Box::new(|rec, unchecked| unsafe {
                if unchecked {
                    rec.copy_buffer_to_image_unchecked(&buffer, &b, GENERAL, &[buffer_region])
                } else {
                    rec.copy_buffer_to_image(&buffer, &b, GENERAL, &[buffer_region])
                }
            }),
        ),
        (
            "VUID-vkCmdCopyImageToBuffer-srcImageLayout-00189",
            Box::new(|rec, unchecked| unsafe {
                if unchecked {
                    rec.copy_image_to_buffer_unchecked(&a, GENERAL, &buffer, &[buffer_region])
                } else {
                    rec.copy_image_to_buffer(&a, GENERAL, &buffer, &[buffer_region])
                }
            }),
        ),
        (
            "VUID-VkCopyBufferToImageInfo2-dstImageLayout-00180",
            Box::new(|rec, unchecked| unsafe {
                let info = tuff::CopyBufferToImageInfo2::new(&buffer, &b)
                    .dst_image_layout(GENERAL)
                    .regions(&buffer_region2);
                if unchecked {
                    rec.copy_buffer_to_image2_unchecked(&info)
                } else {
                    rec.copy_buffer_to_image2(&info)
                }
            }),
        ),
        (
            "VUID-VkCopyImageToBufferInfo2-srcImageLayout-00189",
            Box::new(|rec, unchecked| unsafe {
                let info = tuff::CopyImageToBufferInfo2::new(&a, &buffer)
                    .src_image_layout(GENERAL)
                    .regions(&buffer_region2);
                if unchecked {
                    rec.copy_image_to_buffer2_unchecked(&info)
                } else {
                    rec.copy_image_to_buffer2(&info)
                }
            }),
        ),
        (
            "VUID-vkCmdCopyImage-srcImageLayout-00128",
            Box::new(|rec, unchecked| unsafe {
                if unchecked {
                    rec.copy_image_unchecked(&a, GENERAL, &b, DST, &[copy])
                } else {
                    rec.copy_image(&a, GENERAL, &b, DST, &[copy])
                }
            }),
        ),
        (
            "VUID-vkCmdCopyImage-dstImageLayout-00133",
            Box::new(|rec, unchecked| unsafe {
                if unchecked {
                    rec.copy_image_unchecked(&a, SRC, &b, GENERAL, &[copy])
                } else {
                    rec.copy_image(&a, SRC, &b, GENERAL, &[copy])
                }
            }),
        ),
        (
            "VUID-VkCopyImageInfo2-srcImageLayout-00128",
            Box::new(|rec, unchecked| unsafe {
                let info = tuff::CopyImageInfo2::new(&a, &b)
                    .src_image_layout(GENERAL)
                    .dst_image_layout(DST)
                    .regions(&copy2);
                if unchecked {
                    rec.copy_image2_unchecked(&info)
                } else {
                    rec.copy_image2(&info)
                }
            }),
        ),
        (
            "VUID-VkCopyImageInfo2-dstImageLayout-00133",
            Box::new(|rec, unchecked| unsafe {
                let info = tuff::CopyImageInfo2::new(&a, &b)
                    .src_image_layout(SRC)
                    .dst_image_layout(GENERAL)
                    .regions(&copy2);
                if unchecked {
                    rec.copy_image2_unchecked(&info)
                } else {
                    rec.copy_image2(&info)
                }
            }),
        ),
        (
            "VUID-vkCmdBlitImage-srcImageLayout-00221",
            Box::new(|rec, unchecked| unsafe {
                if unchecked {
                    rec.blit_image_unchecked(&a, GENERAL, &b, DST, &[blit], vk::Filter::NEAREST)
                } else {
                    rec.blit_image(&a, GENERAL, &b, DST, &[blit], vk::Filter::NEAREST)
                }
            }),
        ),
        (
            "VUID-vkCmdBlitImage-dstImageLayout-00226",
            Box::new(|rec, unchecked| unsafe {
                if unchecked {
                    rec.blit_image_unchecked(&a, SRC, &b, GENERAL, &[blit], vk::Filter::NEAREST)
                } else {
                    rec.blit_image(&a, SRC, &b, GENERAL, &[blit], vk::Filter::NEAREST)
                }
            }),
        ),
        (
            "VUID-VkBlitImageInfo2-srcImageLayout-00221",
            Box::new(|rec, unchecked| unsafe {
                let info = tuff::BlitImageInfo2::new(&a, &b)
                    .src_image_layout(GENERAL)
                    .dst_image_layout(DST)
                    .regions(&blit2)
                    .filter(vk::Filter::NEAREST);
                if unchecked {
                    rec.blit_image2_unchecked(&info)
                } else {
                    rec.blit_image2(&info)
                }
            }),
        ),
        (
            "VUID-VkBlitImageInfo2-dstImageLayout-00226",
            Box::new(|rec, unchecked| unsafe {
                let info = tuff::BlitImageInfo2::new(&a, &b)
                    .src_image_layout(SRC)
                    .dst_image_layout(GENERAL)
                    .regions(&blit2)
                    .filter(vk::Filter::NEAREST);
                if unchecked {
                    rec.blit_image2_unchecked(&info)
                } else {
                    rec.blit_image2(&info)
                }
            }),
        ),
        (
            "VUID-vkCmdResolveImage-srcImageLayout-00260",
            Box::new(|rec, unchecked| unsafe {
                if unchecked {
                    rec.resolve_image_unchecked(&multi, GENERAL, &b, DST, &[resolve])
                } else {
                    rec.resolve_image(&multi, GENERAL, &b, DST, &[resolve])
                }
            }),
        ),
        (
            "VUID-vkCmdResolveImage-dstImageLayout-00262",
            Box::new(|rec, unchecked| unsafe {
                if unchecked {
                    rec.resolve_image_unchecked(&multi, SRC, &b, GENERAL, &[resolve])
                } else {
                    rec.resolve_image(&multi, SRC, &b, GENERAL, &[resolve])
                }
            }),
        ),
        (
            "VUID-VkResolveImageInfo2-srcImageLayout-00260",
            Box::new(|rec, unchecked| unsafe {
                let info = tuff::ResolveImageInfo2::new(&multi, &b)
                    .src_image_layout(GENERAL)
                    .dst_image_layout(DST)
                    .regions(&resolve2);
                if unchecked {
                    rec.resolve_image2_unchecked(&info)
                } else {
                    rec.resolve_image2(&info)
                }
            }),
        ),
        (
            "VUID-VkResolveImageInfo2-dstImageLayout-00262",
            Box::new(|rec, unchecked| unsafe {
                let info = tuff::ResolveImageInfo2::new(&multi, &b)
                    .src_image_layout(SRC)
                    .dst_image_layout(GENERAL)
                    .regions(&resolve2);
                if unchecked {
                    rec.resolve_image2_unchecked(&info)
                } else {
                    rec.resolve_image2(&info)
                }
            }),
        ),
        (
            "VUID-vkCmdClearColorImage-imageLayout-00004",
            Box::new(|rec, unchecked| unsafe {
                if unchecked {
                    rec.clear_color_image_unchecked(&b, GENERAL, &clear, &[range(COLOR)])
                } else {
                    rec.clear_color_image(&b, GENERAL, &clear, &[range(COLOR)])
                }
            }),
        ),
        (
            "VUID-vkCmdClearDepthStencilImage-imageLayout-00011",
            Box::new(|rec, unchecked| unsafe {
                let ranges = [range(depth_aspect)];
                if unchecked {
                    rec.clear_depth_stencil_image_unchecked(&depth, GENERAL, &clear_depth, &ranges)
                } else {
                    rec.clear_depth_stencil_image(&depth, GENERAL, &clear_depth, &ranges)
                }
            }),
        ),
    ];
    let prepare = |rec: &mut tuff::Recorder<'_, tuff::Outside>| {
        transition(rec, &a, COLOR, UNDEFINED, SRC).expect("a");
        transition(rec, &b, COLOR, UNDEFINED, DST).expect("b");
        transition(rec, &depth, depth_aspect, UNDEFINED, DST).expect("depth");
        transition(rec, &multi, COLOR, UNDEFINED, SRC).expect("multi");
    };
    for (rule, call) in &cases {
        let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
        let mut rec = cb
            .begin(&tuff::CommandBufferBeginInfo::new())
            .expect("begin");
        prepare(&mut rec);
        assert_eq!(vuid(call(&mut rec, false)), *rule, "the safe call");
        layer_names(&s, rule, || {
            let _ = call(&mut rec, true);
        });
        rec.end().expect("end");
    }
    assert_silent(&s.messages);
}

/// A barrier's `oldLayout` is checked against the layout the recording left.
#[test]
fn a_barrier_from_a_layout_the_image_is_not_in_is_refused_and_the_layer_agrees() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let (a, _memory) = color_image(&s);
    let rule = "VUID-VkImageMemoryBarrier-oldLayout-01197";
    let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let mut rec = cb
        .begin(&tuff::CommandBufferBeginInfo::new())
        .expect("begin");
    transition(&mut rec, &a, COLOR, UNDEFINED, DST).expect("to DST");
    assert_eq!(vuid(transition(&mut rec, &a, COLOR, GENERAL, SRC)), rule);
    let barrier = tuff::ImageMemoryBarrier::new(&a)
        .old_layout(GENERAL)
        .new_layout(SRC)
        .src_queue_family_index(vk::QUEUE_FAMILY_IGNORED)
        .dst_queue_family_index(vk::QUEUE_FAMILY_IGNORED)
        .subresource_range(range(COLOR));
    layer_names(&s, rule, || {
        let _ = unsafe {
            rec.pipeline_barrier_unchecked(
                vk::PipelineStageFlags::TRANSFER,
                vk::PipelineStageFlags::TRANSFER,
                vk::DependencyFlags::empty(),
                &[],
                &[],
                &[barrier],
            )
        };
    });
    // The same through vkCmdPipelineBarrier2.
    let rule2 = "VUID-VkImageMemoryBarrier2-oldLayout-01197";
    let barrier2 = [tuff::ImageMemoryBarrier2::new(&a)
        .src_stage_mask(vk::PipelineStageFlags2::TRANSFER)
        .dst_stage_mask(vk::PipelineStageFlags2::TRANSFER)
        .old_layout(GENERAL)
        .new_layout(SRC)
        .src_queue_family_index(vk::QUEUE_FAMILY_IGNORED)
        .dst_queue_family_index(vk::QUEUE_FAMILY_IGNORED)
        .subresource_range(range(COLOR))];
    let dependency = tuff::DependencyInfo::new().image_memory_barriers(&barrier2);
    assert_eq!(vuid(rec.pipeline_barrier2(&dependency)), rule2);
    layer_names(&s, rule2, || {
        let _ = unsafe { rec.pipeline_barrier2_unchecked(&dependency) };
    });
    rec.end().expect("end");
    // The layout the recording left is the one a barrier may leave from (in a new
    // recording: the layer skipped the unchecked barrier above, which the recorder
    // followed as recorded).
    let mut rec = cb
        .begin(&tuff::CommandBufferBeginInfo::new())
        .expect("begin");
    transition(&mut rec, &a, COLOR, UNDEFINED, DST).expect("to DST");
    transition(&mut rec, &a, COLOR, DST, SRC).expect("to SRC");
    rec.end().expect("end");
    assert_silent(&s.messages);
}

fn submit(s: &Setup, cbs: &[&tuff::CommandBuffer]) -> tuff::Result<()> {
    let fence = s
        .device
        .create_fence(&tuff::FenceCreateInfo::new())
        .expect("fence");
    let handles = tuff::HandleSlice::new(cbs);
    s.queue.submit(
        &[tuff::SubmitInfo::new().command_buffers(&handles)],
        Some(&fence),
    )?;
    let waited = s
        .device
        .wait_for_fences(&fence, true, u64::MAX)
        .expect("wait");
    assert_eq!(waited, tuff::SuccessOrTimeout::Success);
    Ok(())
}

/// A recording that needs, at its start, a layout its own commands do not set is
/// checked when it is submitted, against the layout the submissions before it
/// leave (the earlier command buffers of the same submission included).
#[test]
fn layouts_are_followed_across_submissions() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let (a, _memory) = color_image(&s);
    let (buffer, buffer_memory) = host_buffer(
        &s,
        u64::from(SIDE * SIDE * 4),
        vk::BufferUsageFlags::TRANSFER_DST,
    );
    let region = vk::BufferImageCopy {
        buffer_offset: 0,
        buffer_row_length: 0,
        buffer_image_height: 0,
        image_subresource: layers(COLOR),
        image_offset: vk::Offset3D::default(),
        image_extent: WHOLE,
    };
    let clear = vk::ClearColorValue {
        float32: [0.0, 1.0, 0.0, 1.0],
    };
    let (_pool, mut to_dst) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let mut rec = to_dst
        .begin(&tuff::CommandBufferBeginInfo::new())
        .expect("begin");
    transition(&mut rec, &a, COLOR, UNDEFINED, DST).expect("to DST");
    rec.clear_color_image(&a, DST, &clear, &[range(COLOR)])
        .expect("clear");
    rec.end().expect("end");
    // Reads the image in TRANSFER_SRC_OPTIMAL, which it sets nowhere.
    let (_pool2, mut read) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let mut rec = read
        .begin(&tuff::CommandBufferBeginInfo::new())
        .expect("begin");
    rec.copy_image_to_buffer(&a, SRC, &buffer, &[region])
        .expect("copy");
    rec.end().expect("end");
    let (_pool3, mut to_src) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let mut rec = to_src
        .begin(&tuff::CommandBufferBeginInfo::new())
        .expect("begin");
    transition(&mut rec, &a, COLOR, DST, SRC).expect("to SRC");
    rec.end().expect("end");

    let rule = "VUID-vkCmdCopyImageToBuffer-srcImageLayout-00189";
    // Nothing moved the image out of UNDEFINED yet.
    assert_eq!(vuid(submit(&s, &[&read])), rule);
    // The clear leaves it in TRANSFER_DST_OPTIMAL.
    submit(&s, &[&to_dst]).expect("clear");
    assert_eq!(vuid(submit(&s, &[&read])), rule);
    // Moved to TRANSFER_SRC_OPTIMAL by the command buffer before it in the same
    // submission: the read is valid.
    submit(&s, &[&to_src, &read]).expect("moved, then read");
    let texel = pipelines::access_memory(&s, &buffer_memory, 4, None);
    assert_eq!(texel, [0, 255, 0, 255], "the clear color, read back");
    // The image stays in TRANSFER_SRC_OPTIMAL: the read alone is valid now, and
    // the move from TRANSFER_DST_OPTIMAL is not.
    submit(&s, &[&read]).expect("read again");
    assert_eq!(
        vuid(submit(&s, &[&to_src])),
        "VUID-VkImageMemoryBarrier-oldLayout-01197"
    );
    assert_silent(&s.messages);
}

/// A secondary that needs a layout the primary leaves otherwise is refused where
/// the primary executes it.
#[test]
fn a_secondary_is_checked_against_the_layouts_its_primary_leaves() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let (a, _memory) = color_image(&s);
    let clear = vk::ClearColorValue {
        float32: [0.0, 0.0, 0.0, 1.0],
    };
    let (_pool, mut secondary) = s.command_buffer(vk::CommandBufferLevel::SECONDARY);
    let inheritance = tuff::CommandBufferInheritanceInfo::new();
    let mut rec = secondary
        .begin(&tuff::CommandBufferBeginInfo::new().inheritance_info(Some(&inheritance)))
        .expect("begin");
    rec.clear_color_image(&a, DST, &clear, &[range(COLOR)])
        .expect("clear");
    rec.end().expect("end");
    let (_pool2, mut primary) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let mut rec = primary
        .begin(&tuff::CommandBufferBeginInfo::new())
        .expect("begin");
    transition(&mut rec, &a, COLOR, UNDEFINED, GENERAL).expect("to GENERAL");
    assert_eq!(
        vuid(rec.execute_commands(&secondary)),
        "VUID-vkCmdClearColorImage-imageLayout-00004"
    );
    transition(&mut rec, &a, COLOR, GENERAL, DST).expect("to DST");
    rec.execute_commands(&secondary).expect("execute");
    // The secondary leaves the image in TRANSFER_DST_OPTIMAL, as the primary knows.
    transition(&mut rec, &a, COLOR, DST, SRC).expect("to SRC");
    rec.end().expect("end");
    submit(&s, &[&primary]).expect("submit");
    assert_silent(&s.messages);
}

const ATTACHMENT: vk::ImageLayout = vk::ImageLayout::COLOR_ATTACHMENT_OPTIMAL;
const AREA: vk::Rect2D = vk::Rect2D {
    offset: vk::Offset2D { x: 0, y: 0 },
    extent: vk::Extent2D {
        width: 8,
        height: 8,
    },
};

/// Render passes that need the attachment in COLOR_ATTACHMENT_OPTIMAL and leave
/// it in TRANSFER_SRC_OPTIMAL (through `vkCreateRenderPass`, then
/// `vkCreateRenderPass2`), with a framebuffer each on `view`.
fn loading_passes(s: &Setup, view: &tuff::ImageView) -> [(tuff::RenderPass, tuff::Framebuffer); 2] {
    loading_passes_to(s, view, SRC)
}

/// As [`loading_passes`], leaving the attachment in `last`.
fn loading_passes_to(
    s: &Setup,
    view: &tuff::ImageView,
    last: vk::ImageLayout,
) -> [(tuff::RenderPass, tuff::Framebuffer); 2] {
    let d = &s.device;
    let attachments = [vk::AttachmentDescription {
        format: vk::Format::R8G8B8A8_UNORM,
        samples: vk::SampleCountFlags::TYPE_1,
        load_op: vk::AttachmentLoadOp::LOAD,
        store_op: vk::AttachmentStoreOp::STORE,
        stencil_load_op: vk::AttachmentLoadOp::DONT_CARE,
        stencil_store_op: vk::AttachmentStoreOp::DONT_CARE,
        initial_layout: ATTACHMENT,
        final_layout: last,
        ..Default::default()
    }];
    let color = [vk::AttachmentReference {
        attachment: 0,
        layout: ATTACHMENT,
    }];
    let subpasses = [tuff::SubpassDescription::new()
        .pipeline_bind_point(vk::PipelineBindPoint::GRAPHICS)
        .color_attachments(&color)];
    // Transfers before the instance, and the copy after it, are ordered with it.
    let attachment_access =
        vk::AccessFlags::COLOR_ATTACHMENT_READ | vk::AccessFlags::COLOR_ATTACHMENT_WRITE;
    let dependencies = [
        vk::SubpassDependency {
            src_subpass: vk::SUBPASS_EXTERNAL,
            dst_subpass: 0,
            src_stage_mask: vk::PipelineStageFlags::TRANSFER,
            dst_stage_mask: vk::PipelineStageFlags::COLOR_ATTACHMENT_OUTPUT,
            src_access_mask: vk::AccessFlags::TRANSFER_WRITE,
            dst_access_mask: attachment_access,
            dependency_flags: vk::DependencyFlags::empty(),
        },
        vk::SubpassDependency {
            src_subpass: 0,
            dst_subpass: vk::SUBPASS_EXTERNAL,
            src_stage_mask: vk::PipelineStageFlags::COLOR_ATTACHMENT_OUTPUT,
            dst_stage_mask: vk::PipelineStageFlags::TRANSFER,
            src_access_mask: vk::AccessFlags::COLOR_ATTACHMENT_WRITE,
            dst_access_mask: vk::AccessFlags::TRANSFER_READ,
            dependency_flags: vk::DependencyFlags::empty(),
        },
    ];
    let one = d
        .create_render_pass(
            &tuff::RenderPassCreateInfo::new()
                .attachments(&attachments)
                .subpasses(&subpasses)
                .dependencies(&dependencies),
        )
        .expect("render pass");
    let dependencies2 = dependencies.map(|d| {
        tuff::SubpassDependency2::new()
            .src_subpass(d.src_subpass)
            .dst_subpass(d.dst_subpass)
            .src_stage_mask(d.src_stage_mask)
            .dst_stage_mask(d.dst_stage_mask)
            .src_access_mask(d.src_access_mask)
            .dst_access_mask(d.dst_access_mask)
    });
    let attachments2 = [tuff::AttachmentDescription2::new()
        .format(vk::Format::R8G8B8A8_UNORM)
        .samples(vk::SampleCountFlags::TYPE_1)
        .load_op(vk::AttachmentLoadOp::LOAD)
        .store_op(vk::AttachmentStoreOp::STORE)
        .stencil_load_op(vk::AttachmentLoadOp::DONT_CARE)
        .stencil_store_op(vk::AttachmentStoreOp::DONT_CARE)
        .initial_layout(ATTACHMENT)
        .final_layout(last)];
    let color2 = [tuff::AttachmentReference2::new()
        .attachment(0)
        .layout(ATTACHMENT)
        .aspect_mask(COLOR)];
    let subpasses2 = [tuff::SubpassDescription2::new()
        .pipeline_bind_point(vk::PipelineBindPoint::GRAPHICS)
        .color_attachments(&color2)];
    #[allow(unused_unsafe)]
    // SAFETY: a valid render pass of one color attachment and one subpass.
    let two = unsafe {
        d.create_render_pass2(
            &tuff::RenderPassCreateInfo2::new()
                .attachments(&attachments2)
                .subpasses(&subpasses2)
                .dependencies(&dependencies2),
        )
    }
    .expect("render pass 2");
    [one, two].map(|rp| {
        let fb = d
            .create_framebuffer(
                &tuff::FramebufferCreateInfo::new(&rp)
                    .attachments(view)
                    .width(8)
                    .height(8)
                    .layers(1),
            )
            .expect("framebuffer");
        (rp, fb)
    })
}

/// Begins and ends a render pass instance on `pass` (with `vkCmdBeginRenderPass2`
/// when `two`), checked or not.
fn render_pass_instance<'c>(
    rec: tuff::Recorder<'c, tuff::Outside>,
    (rp, fb): &(tuff::RenderPass, tuff::Framebuffer),
    two: bool,
    unchecked: bool,
) -> tuff::Recorder<'c, tuff::Outside> {
    let begin = tuff::RenderPassBeginInfo::new(rp, fb).render_area(AREA);
    let contents = tuff::SubpassBeginInfo::new().contents(vk::SubpassContents::INLINE);
    let end = tuff::SubpassEndInfo::new();
    unsafe {
        match (two, unchecked) {
            (false, false) => rec
                .begin_render_pass(&begin, vk::SubpassContents::INLINE)
                .end_render_pass(),
            (false, true) => rec
                .begin_render_pass_unchecked(&begin, vk::SubpassContents::INLINE)
                .end_render_pass_unchecked(),
            (true, false) => rec
                .begin_render_pass2(&begin, &contents)
                .end_render_pass2(&end),
            (true, true) => rec
                .begin_render_pass2_unchecked(&begin, &contents)
                .end_render_pass2_unchecked(&end),
        }
    }
}

/// A render pass instance needs its attachments in their initial layouts and
/// leaves them in their final ones: a recording that leaves the image in another
/// layout is refused (and the layer names the rule for the unchecked twin), one
/// that needs it at its start is checked at submission, and a copy after the
/// instance reads the final layout.
#[test]
fn render_passes_need_their_initial_layouts_and_leave_their_final_ones() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let target = s.color_target(
        8,
        vk::ImageUsageFlags::TRANSFER_SRC | vk::ImageUsageFlags::TRANSFER_DST,
    );
    let passes = loading_passes(&s, &target.view);
    let rules = [
        "VUID-vkCmdBeginRenderPass-initialLayout-00900",
        "VUID-vkCmdBeginRenderPass2-initialLayout-03100",
    ];
    for (two, rule) in [(false, rules[0]), (true, rules[1])] {
        let pass = &passes[usize::from(two)];
        let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
        let mut rec = cb
            .begin(&tuff::CommandBufferBeginInfo::new())
            .expect("begin");
        transition(&mut rec, &target.image, COLOR, UNDEFINED, GENERAL).expect("to GENERAL");
        let rec = render_pass_instance(rec, pass, two, false);
        assert_eq!(vuid(rec.end()), rule, "the safe begin");

        let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
        let mut rec = cb
            .begin(&tuff::CommandBufferBeginInfo::new())
            .expect("begin");
        transition(&mut rec, &target.image, COLOR, UNDEFINED, GENERAL).expect("to GENERAL");
        // The 1.3.239 layer reports this rule as
        // UNASSIGNED-CoreValidation-DrawState-InvalidRenderpass, in words that name
        // the initial layout and the attachment's layout before the instance. (It
        // then reports the end of an instance it skipped the begin of.)
        s.messages.take();
        s.messages.abort_on_error(true);
        let ended = render_pass_instance(rec, pass, two, true);
        s.messages.abort_on_error(false);
        drop(ended);
        let messages = s.messages.take();
        assert!(
            messages.iter().any(|m| m.contains(rule)
                || (m.contains("UNASSIGNED-CoreValidation-DrawState-InvalidRenderpass")
                    && m.contains(
                        "render pass initial layout is VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL"
                    )
                    && m.contains(
                        "previous known layout of the attachment is VK_IMAGE_LAYOUT_GENERAL"
                    ))),
            "the validation layer did not report {rule}; it said:\n{}",
            messages.join("\n")
        );
    }
    // The instance needs COLOR_ATTACHMENT_OPTIMAL from before the recording: the
    // image is UNDEFINED until a submission moves it.
    let (buffer, memory) = host_buffer(&s, 8 * 8 * 4, vk::BufferUsageFlags::TRANSFER_DST);
    let region = vk::BufferImageCopy {
        buffer_offset: 0,
        buffer_row_length: 0,
        buffer_image_height: 0,
        image_subresource: layers(COLOR),
        image_offset: vk::Offset3D::default(),
        image_extent: vk::Extent3D {
            width: 8,
            height: 8,
            depth: 1,
        },
    };
    let clear = vk::ClearColorValue {
        float32: [1.0, 0.0, 1.0, 1.0],
    };
    let (_pool, mut load) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let rec = load
        .begin(&tuff::CommandBufferBeginInfo::new())
        .expect("begin");
    let mut rec = render_pass_instance(rec, &passes[0], false, false);
    // The final layout, TRANSFER_SRC_OPTIMAL, is the one the copy names.
    rec.copy_image_to_buffer(&target.image, SRC, &buffer, &[region])
        .expect("copy");
    rec.end().expect("end");
    assert_eq!(vuid(submit(&s, &[&load])), rules[0]);
    let (_pool, mut prepare) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let mut rec = prepare
        .begin(&tuff::CommandBufferBeginInfo::new())
        .expect("begin");
    transition(&mut rec, &target.image, COLOR, UNDEFINED, DST).expect("to DST");
    rec.clear_color_image(&target.image, DST, &clear, &[range(COLOR)])
        .expect("clear");
    transition(&mut rec, &target.image, COLOR, DST, ATTACHMENT).expect("to ATTACHMENT");
    rec.end().expect("end");
    submit(&s, &[&prepare, &load]).expect("prepared, then loaded and copied");
    let texel = pipelines::access_memory(&s, &memory, 4, None);
    assert_eq!(
        texel,
        [255, 0, 255, 255],
        "the cleared color, loaded and stored"
    );
    assert_silent(&s.messages);
}

/// A render pass instance's begin: its render area inside the framebuffer, a
/// clear value for each attachment it clears, and the usage each layout the
/// render pass gives an attachment needs of its view. Each is refused through
/// `vkCmdBeginRenderPass` and `vkCmdBeginRenderPass2`, and the layer names the
/// rule for the unchecked begin.
#[test]
fn a_render_pass_begin_is_checked_against_its_framebuffer() {
    let _serial = vulkan::serial();
    let s = setup(true);
    // A view with the color attachment usage alone.
    let target = s.color_target(8, vk::ImageUsageFlags::empty());
    let begin_both = |pass: (&tuff::RenderPass, &tuff::Framebuffer),
                      two: bool,
                      area: vk::Rect2D,
                      clears: &[vk::ClearValue],
                      rule: &str| {
        let begin = tuff::RenderPassBeginInfo::new(pass.0, pass.1)
            .render_area(area)
            .clear_values(clears);
        let contents = tuff::SubpassBeginInfo::new().contents(vk::SubpassContents::INLINE);
        let end = tuff::SubpassEndInfo::new();
        let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
        let rec = cb
            .begin(&tuff::CommandBufferBeginInfo::new())
            .expect("begin");
        let rec = if two {
            rec.begin_render_pass2(&begin, &contents)
                .end_render_pass2(&end)
        } else {
            rec.begin_render_pass(&begin, vk::SubpassContents::INLINE)
                .end_render_pass()
        };
        assert_eq!(vuid(rec.end()), rule, "two: {two}");
        let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
        let rec = cb
            .begin(&tuff::CommandBufferBeginInfo::new())
            .expect("begin");
        s.messages.take();
        s.messages.abort_on_error(true);
        let rec = unsafe {
            if two {
                rec.begin_render_pass2_unchecked(&begin, &contents)
                    .end_render_pass2_unchecked(&end)
            } else {
                rec.begin_render_pass_unchecked(&begin, vk::SubpassContents::INLINE)
                    .end_render_pass_unchecked()
            }
        };
        s.messages.abort_on_error(false);
        drop(rec);
        let messages = s.messages.take();
        assert!(
            messages.iter().any(|m| m.contains(rule)),
            "the layer did not name {rule} (two: {two}): {messages:?}"
        );
    };
    let clear = [vk::ClearValue::default()];
    let cleared = (&target.render_pass, &target.framebuffer);
    let area = |x: i32, y: i32, w: u32, h: u32| vk::Rect2D {
        offset: vk::Offset2D { x, y },
        extent: vk::Extent2D {
            width: w,
            height: h,
        },
    };
    for two in [false, true] {
        for (a, rule) in [
            (area(-1, 0, 4, 4), "VUID-VkRenderPassBeginInfo-pNext-02850"),
            (area(0, -1, 4, 4), "VUID-VkRenderPassBeginInfo-pNext-02851"),
            (area(4, 0, 5, 4), "VUID-VkRenderPassBeginInfo-pNext-02852"),
            (area(0, 4, 4, 5), "VUID-VkRenderPassBeginInfo-pNext-02853"),
        ] {
            begin_both(cleared, two, a, &clear, rule);
        }
        begin_both(
            cleared,
            two,
            AREA,
            &[],
            "VUID-VkRenderPassBeginInfo-clearValueCount-00902",
        );
    }
    for (last, rules) in [
        (
            SRC,
            [
                "VUID-vkCmdBeginRenderPass-initialLayout-00898",
                "VUID-vkCmdBeginRenderPass2-initialLayout-03098",
            ],
        ),
        (
            DST,
            [
                "VUID-vkCmdBeginRenderPass-initialLayout-00899",
                "VUID-vkCmdBeginRenderPass2-initialLayout-03099",
            ],
        ),
        (
            vk::ImageLayout::SHADER_READ_ONLY_OPTIMAL,
            [
                "VUID-vkCmdBeginRenderPass-initialLayout-00897",
                "VUID-vkCmdBeginRenderPass2-initialLayout-03097",
            ],
        ),
    ] {
        let passes = loading_passes_to(&s, &target.view, last);
        for (two, pass) in passes.iter().enumerate() {
            begin_both((&pass.0, &pass.1), two == 1, AREA, &[], rules[two]);
        }
    }
    assert_silent(&s.messages);
}

/// A command buffer remembers its last render pass begin that passed, to skip
/// its checks when the next is the same: a begin of the same render pass and
/// framebuffer with another render area or fewer clear values is still refused, in
/// the same recording and in the next, through either command, and the same begin
/// again passes (the layer quiet).
#[test]
fn a_render_pass_begin_like_the_last_one_is_still_checked() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let target = s.color_target(8, vk::ImageUsageFlags::empty());
    let clear = [vk::ClearValue::default()];
    let good = tuff::RenderPassBeginInfo::new(&target.render_pass, &target.framebuffer)
        .render_area(AREA)
        .clear_values(&clear);
    let wide = vk::Rect2D {
        extent: vk::Extent2D {
            width: 9,
            height: 8,
        },
        ..AREA
    };
    let too_wide = tuff::RenderPassBeginInfo::new(&target.render_pass, &target.framebuffer)
        .render_area(wide)
        .clear_values(&clear);
    let no_clear =
        tuff::RenderPassBeginInfo::new(&target.render_pass, &target.framebuffer).render_area(AREA);
    let contents = tuff::SubpassBeginInfo::new().contents(vk::SubpassContents::INLINE);
    let end = tuff::SubpassEndInfo::new();
    let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    for round in 0..2 {
        let rec = cb
            .begin(&tuff::CommandBufferBeginInfo::new())
            .expect("begin");
        rec.begin_render_pass(&good, vk::SubpassContents::INLINE)
            .end_render_pass()
            .end()
            .unwrap_or_else(|e| panic!("round {round}: the begin: {e}"));
        // In the recording of the begin that passed, and in the next.
        let rec = cb
            .begin(&tuff::CommandBufferBeginInfo::new())
            .expect("begin");
        let rec = rec
            .begin_render_pass(&good, vk::SubpassContents::INLINE)
            .end_render_pass()
            .begin_render_pass(&too_wide, vk::SubpassContents::INLINE)
            .end_render_pass();
        assert_eq!(vuid(rec.end()), "VUID-VkRenderPassBeginInfo-pNext-02852");
        let rec = cb
            .begin(&tuff::CommandBufferBeginInfo::new())
            .expect("begin");
        let rec = rec
            .begin_render_pass(&too_wide, vk::SubpassContents::INLINE)
            .end_render_pass();
        assert_eq!(vuid(rec.end()), "VUID-VkRenderPassBeginInfo-pNext-02852");
        let rec = cb
            .begin(&tuff::CommandBufferBeginInfo::new())
            .expect("begin");
        let rec = rec
            .begin_render_pass(&good, vk::SubpassContents::INLINE)
            .end_render_pass()
            .begin_render_pass(&no_clear, vk::SubpassContents::INLINE)
            .end_render_pass();
        assert_eq!(
            vuid(rec.end()),
            "VUID-VkRenderPassBeginInfo-clearValueCount-00902"
        );
        let rec = cb
            .begin(&tuff::CommandBufferBeginInfo::new())
            .expect("begin");
        rec.begin_render_pass2(&good, &contents)
            .end_render_pass2(&end)
            .end()
            .unwrap_or_else(|e| panic!("round {round}: the second command: {e}"));
    }
    assert_silent(&s.messages);
}

/// The begin a command buffer remembers names its framebuffer by the framebuffer's
/// record, not its handle: once the framebuffer is destroyed and the driver gives
/// its handle to a smaller one, the render area the old one held is refused on the
/// new one. Without the layer, which gives every object a unique handle; the test
/// asserts that the driver did reuse a handle.
#[test]
fn a_new_framebuffer_under_a_destroyed_one_s_handle_is_checked() {
    let _serial = vulkan::serial();
    let s = setup(false);
    let target = s.color_target(8, vk::ImageUsageFlags::empty());
    let framebuffer = |size: u32| {
        s.device
            .create_framebuffer(
                &tuff::FramebufferCreateInfo::new(&target.render_pass)
                    .attachments(&target.view)
                    .width(size)
                    .height(size)
                    .layers(1),
            )
            .expect("framebuffer")
    };
    let clear = [vk::ClearValue::default()];
    let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let mut reused = 0;
    for _ in 0..8 {
        let large = framebuffer(8);
        let begin = tuff::RenderPassBeginInfo::new(&target.render_pass, &large)
            .render_area(AREA)
            .clear_values(&clear);
        let rec = cb
            .begin(&tuff::CommandBufferBeginInfo::new())
            .expect("begin");
        rec.begin_render_pass(&begin, vk::SubpassContents::INLINE)
            .end_render_pass()
            .end()
            .expect("the whole framebuffer");
        let old = tuff::Handle::raw(&large);
        // The next recording lets go of the framebuffer the last one kept.
        cb.begin(&tuff::CommandBufferBeginInfo::new())
            .expect("begin")
            .end()
            .expect("an empty recording");
        drop(large);
        // The driver frees the old one's memory with another block of its size
        // and hands them out last freed first: one more made and destroyed, and a
        // few smaller ones, give one of them the old handle.
        drop(framebuffer(8));
        let smaller: Vec<tuff::Framebuffer> = (0..4).map(|_| framebuffer(4)).collect();
        let Some(small) = smaller.iter().find(|f| tuff::Handle::raw(*f) == old) else {
            continue;
        };
        let rec = cb
            .begin(&tuff::CommandBufferBeginInfo::new())
            .expect("begin");
        reused += 1;
        let begin = tuff::RenderPassBeginInfo::new(&target.render_pass, small)
            .render_area(AREA)
            .clear_values(&clear);
        let rec = rec
            .begin_render_pass(&begin, vk::SubpassContents::INLINE)
            .end_render_pass();
        assert_eq!(vuid(rec.end()), "VUID-VkRenderPassBeginInfo-pNext-02852");
    }
    assert!(
        reused > 0,
        "the driver gave no framebuffer a destroyed one's handle"
    );
}

/// A chained `VkDeviceGroupRenderPassBeginInfo` (on lavapipe, a group of one):
/// its device mask against the device's physical devices, its render areas'
/// count, and each area against the framebuffer and the limits; the layer names
/// each rule for the unchecked begin.
#[test]
fn a_device_group_render_pass_begin_is_checked() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let target = s.color_target(8, vk::ImageUsageFlags::empty());
    let limits = s.physical.get_properties().limits;
    let area = |x: i32, y: i32, w: u32, h: u32| vk::Rect2D {
        offset: vk::Offset2D { x, y },
        extent: vk::Extent2D {
            width: w,
            height: h,
        },
    };
    let (wide, high) = (limits.max_framebuffer_width, limits.max_framebuffer_height);
    let group = "VUID-VkDeviceGroupRenderPassBeginInfo-";
    let cases: Vec<(u32, Vec<vk::Rect2D>, String)> = vec![
        (2, vec![], format!("{group}deviceMask-00905")),
        (
            1,
            vec![AREA, AREA],
            format!("{group}deviceRenderAreaCount-00908"),
        ),
        (1, vec![area(-1, 0, 4, 4)], format!("{group}offset-06166")),
        (1, vec![area(0, -1, 4, 4)], format!("{group}offset-06167")),
        (1, vec![area(1, 0, wide, 4)], format!("{group}offset-06168")),
        (1, vec![area(0, 1, 4, high)], format!("{group}offset-06169")),
        (
            1,
            vec![area(4, 0, 5, 4)],
            "VUID-VkRenderPassBeginInfo-pNext-02856".into(),
        ),
        (
            1,
            vec![area(0, 4, 4, 5)],
            "VUID-VkRenderPassBeginInfo-pNext-02857".into(),
        ),
    ];
    let clear = [vk::ClearValue::default()];
    let mut wrong = Vec::new();
    for (mask, areas, rule) in &cases {
        let mut chained = tuff::DeviceGroupRenderPassBeginInfo::new()
            .device_mask(*mask)
            .device_render_areas(areas);
        let begin = tuff::RenderPassBeginInfo::new(&target.render_pass, &target.framebuffer)
            .render_area(AREA)
            .clear_values(&clear)
            .push_next(&mut chained);
        let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
        let rec = cb
            .begin(&tuff::CommandBufferBeginInfo::new())
            .expect("begin");
        let rec = rec
            .begin_render_pass(&begin, vk::SubpassContents::INLINE)
            .end_render_pass();
        let said = match rec.end() {
            Err(tuff::Error::Validation { vuid, .. }) => vuid.to_string(),
            other => format!("{other:?}"),
        };
        let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
        let rec = cb
            .begin(&tuff::CommandBufferBeginInfo::new())
            .expect("begin");
        s.messages.take();
        s.messages.abort_on_error(true);
        let rec = unsafe {
            rec.begin_render_pass_unchecked(&begin, vk::SubpassContents::INLINE)
                .end_render_pass_unchecked()
        };
        s.messages.abort_on_error(false);
        drop(rec);
        let errors: Vec<String> = s
            .messages
            .take()
            .into_iter()
            .filter(|m| m.starts_with("ERROR"))
            .collect();
        // An area past maxFramebufferWidth is past every framebuffer: the layer
        // names that rule (02856, 02857), which the change breaks too.
        let also = match rule.rsplit('-').next() {
            Some("06168") => "VUID-VkRenderPassBeginInfo-pNext-02856",
            Some("06169") => "VUID-VkRenderPassBeginInfo-pNext-02857",
            _ => rule.as_str(),
        };
        if !errors
            .iter()
            .any(|m| m.contains(rule.as_str()) || m.contains(also))
        {
            wrong.push(format!("the layer did not name {rule}: {errors:?}"));
        }
        if said != *rule {
            wrong.push(format!("tuff said {said}, expected {rule}"));
        }
    }
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
    assert_silent(&s.messages);
}

/// The views a render pass instance on an imageless framebuffer is given must
/// match the framebuffer's attachment image infos and the render pass's
/// attachments; a framebuffer with views takes none; and the render pass must be
/// compatible with the framebuffer's.
#[test]
fn the_views_of_an_imageless_framebuffer_and_the_render_pass_are_checked() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let d = &s.device;
    let rgba = vk::Format::R8G8B8A8_UNORM;
    let srgb = vk::Format::R8G8B8A8_SRGB;
    let color_usage = vk::ImageUsageFlags::COLOR_ATTACHMENT;
    // A one-attachment render pass of `format`.
    let pass = |format: vk::Format| {
        let attachments = [vk::AttachmentDescription {
            format,
            samples: vk::SampleCountFlags::TYPE_1,
            load_op: vk::AttachmentLoadOp::DONT_CARE,
            store_op: vk::AttachmentStoreOp::STORE,
            stencil_load_op: vk::AttachmentLoadOp::DONT_CARE,
            stencil_store_op: vk::AttachmentStoreOp::DONT_CARE,
            initial_layout: UNDEFINED,
            final_layout: ATTACHMENT,
            ..Default::default()
        }];
        let color = [vk::AttachmentReference {
            attachment: 0,
            layout: ATTACHMENT,
        }];
        let subpasses = [tuff::SubpassDescription::new()
            .pipeline_bind_point(vk::PipelineBindPoint::GRAPHICS)
            .color_attachments(&color)];
        d.create_render_pass(
            &tuff::RenderPassCreateInfo::new()
                .attachments(&attachments)
                .subpasses(&subpasses),
        )
        .expect("render pass")
    };
    let render_pass = pass(rgba);
    let formats = [rgba, srgb];
    // A view of a new image: (width, height, layers, levels, samples, flags, usage,
    // listed view formats, view format, swizzled).
    type Spec = (
        u32,
        u32,
        u32,
        u32,
        u32,
        vk::ImageCreateFlags,
        vk::ImageUsageFlags,
        usize,
        vk::Format,
        bool,
    );
    let view = |(w, h, layers, levels, samples, flags, usage, listed, format, swizzle): Spec| {
        let mut list = tuff::ImageFormatListCreateInfo::new().view_formats(&formats[..listed]);
        let image = d
            .create_image(
                &tuff::ImageCreateInfo::new()
                    .flags(flags)
                    .image_type(vk::ImageType::TYPE_2D)
                    .format(rgba)
                    .extent(vk::Extent3D {
                        width: w,
                        height: h,
                        depth: 1,
                    })
                    .mip_levels(levels)
                    .array_layers(layers)
                    .samples(vk::SampleCountFlags::from_raw(samples))
                    .usage(usage)
                    .push_next(&mut list),
            )
            .expect("image");
        let memory = s.bind_image(&image);
        let components = if swizzle {
            vk::ComponentMapping {
                r: vk::ComponentSwizzle::G,
                ..Default::default()
            }
        } else {
            vk::ComponentMapping::default()
        };
        let view = d
            .create_image_view(
                &tuff::ImageViewCreateInfo::new(&image)
                    .view_type(if layers > 1 {
                        vk::ImageViewType::TYPE_2D_ARRAY
                    } else {
                        vk::ImageViewType::TYPE_2D
                    })
                    .format(format)
                    .components(components)
                    .subresource_range(vk::ImageSubresourceRange {
                        aspect_mask: COLOR,
                        base_mip_level: 0,
                        level_count: levels,
                        base_array_layer: 0,
                        layer_count: layers,
                    }),
            )
            .expect("view");
        (image, memory, view)
    };
    let mutable = vk::ImageCreateFlags::MUTABLE_FORMAT;
    let good: Spec = (8, 8, 1, 1, 1, mutable, color_usage, 2, rgba, false);
    // The framebuffer's one attachment image info, which `good` matches.
    let info = [tuff::FramebufferAttachmentImageInfo::new()
        .flags(mutable)
        .usage(color_usage)
        .width(8)
        .height(8)
        .layer_count(1)
        .view_formats(&formats)];
    let mut attachments =
        tuff::FramebufferAttachmentsCreateInfo::new().attachment_image_infos(&info);
    // An imageless framebuffer reads only the count of its attachments.
    let (_placeholder_image, _placeholder_memory, placeholder) = view(good);
    let imageless = d
        .create_framebuffer(
            &tuff::FramebufferCreateInfo::new(&render_pass)
                .flags(vk::FramebufferCreateFlags::IMAGELESS)
                .attachments(&placeholder)
                .width(8)
                .height(8)
                .layers(1)
                .push_next(&mut attachments),
        )
        .expect("imageless framebuffer");
    let with = |f: fn(&mut Spec)| {
        let mut spec = good;
        f(&mut spec);
        spec
    };
    let cases: Vec<(Vec<Spec>, &str)> = vec![
        (
            vec![good, good],
            "VUID-VkRenderPassBeginInfo-framebuffer-03208",
        ),
        (
            vec![with(|s| s.3 = 2)],
            "VUID-VkRenderPassAttachmentBeginInfo-pAttachments-03218",
        ),
        (
            vec![with(|s| s.9 = true)],
            "VUID-VkRenderPassAttachmentBeginInfo-pAttachments-03219",
        ),
        (
            vec![with(|s| {
                s.5 = vk::ImageCreateFlags::empty();
                s.7 = 1;
            })],
            "VUID-VkRenderPassBeginInfo-framebuffer-03209",
        ),
        (
            vec![with(|s| {
                s.6 = vk::ImageUsageFlags::COLOR_ATTACHMENT | vk::ImageUsageFlags::TRANSFER_SRC
            })],
            "VUID-VkRenderPassBeginInfo-framebuffer-04627",
        ),
        (
            vec![with(|s| s.0 = 16)],
            "VUID-VkRenderPassBeginInfo-framebuffer-03211",
        ),
        (
            vec![with(|s| s.1 = 16)],
            "VUID-VkRenderPassBeginInfo-framebuffer-03212",
        ),
        (
            vec![with(|s| s.2 = 2)],
            "VUID-VkRenderPassBeginInfo-framebuffer-03213",
        ),
        (
            vec![with(|s| s.7 = 1)],
            "VUID-VkRenderPassBeginInfo-framebuffer-03214",
        ),
        (
            vec![with(|s| s.8 = vk::Format::R8G8B8A8_SRGB)],
            "VUID-VkRenderPassBeginInfo-framebuffer-03216",
        ),
        (
            vec![with(|s| s.4 = 4)],
            "VUID-VkRenderPassBeginInfo-framebuffer-03217",
        ),
    ];
    let mut wrong = Vec::new();
    let mut kept = Vec::new();
    for (spec, rule) in cases {
        let made: Vec<_> = spec.into_iter().map(view).collect();
        let views: Vec<&tuff::ImageView> = made.iter().map(|m| &m.2).collect();
        let handles = tuff::HandleSlice::new(&views);
        let mut given = tuff::RenderPassAttachmentBeginInfo::new().attachments(&handles);
        let begin = tuff::RenderPassBeginInfo::new(&render_pass, &imageless)
            .render_area(AREA)
            .push_next(&mut given);
        wrong.extend(try_begin(&s, &begin, rule));
        kept.push(made);
    }
    // A framebuffer with views takes none from the begin info; and a render pass
    // of another format is not compatible with the framebuffer's.
    let target = s.color_target(8, vk::ImageUsageFlags::empty());
    let (_i, _m, extra) = view(good);
    let extra_views = [&extra];
    let handles = tuff::HandleSlice::new(&extra_views);
    let mut given = tuff::RenderPassAttachmentBeginInfo::new().attachments(&handles);
    let clear = [vk::ClearValue::default()];
    let begin = tuff::RenderPassBeginInfo::new(&target.render_pass, &target.framebuffer)
        .render_area(AREA)
        .clear_values(&clear)
        .push_next(&mut given);
    wrong.extend(try_begin(
        &s,
        &begin,
        "VUID-VkRenderPassBeginInfo-framebuffer-03207",
    ));
    let other = pass(vk::Format::B8G8R8A8_UNORM);
    let begin = tuff::RenderPassBeginInfo::new(&other, &target.framebuffer).render_area(AREA);
    wrong.extend(try_begin(
        &s,
        &begin,
        "VUID-VkRenderPassBeginInfo-renderPass-00904",
    ));
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
    drop(kept);
    assert_silent(&s.messages);
}

/// Begins and ends a render pass instance with `begin`, safely (which must name
/// `rule`) and unchecked under the layer (which must name it too); returns what
/// went wrong.
fn try_begin(s: &Setup, begin: &tuff::RenderPassBeginInfo<'_>, rule: &str) -> Option<String> {
    let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let rec = cb
        .begin(&tuff::CommandBufferBeginInfo::new())
        .expect("begin");
    let rec = rec
        .begin_render_pass(begin, vk::SubpassContents::INLINE)
        .end_render_pass();
    let said = match rec.end() {
        Err(tuff::Error::Validation { vuid, .. }) => vuid.to_string(),
        other => format!("{other:?}"),
    };
    let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let rec = cb
        .begin(&tuff::CommandBufferBeginInfo::new())
        .expect("begin");
    s.messages.take();
    s.messages.abort_on_error(true);
    let rec = unsafe {
        rec.begin_render_pass_unchecked(begin, vk::SubpassContents::INLINE)
            .end_render_pass_unchecked()
    };
    s.messages.abort_on_error(false);
    drop(rec);
    let errors: Vec<String> = s
        .messages
        .take()
        .into_iter()
        .filter(|m| m.starts_with("ERROR"))
        .map(|m| m.split(']').next().unwrap_or(&m).to_string())
        .collect();
    let named = errors.iter().any(|m| m.contains(rule));
    (said != rule || !named).then(|| format!("{rule}: tuff said {said}; the layer said {errors:?}"))
}

/// `vkCmdBeginRenderPass2` refuses a framebuffer and render pass of another device
/// (the unchecked begin is never submitted). The walk over the begin info refuses
/// them first, under the member's own rule, before the command's rule
/// (`VUID-vkCmdBeginRenderPass2-framebuffer-02779`) is asked.
#[test]
fn a_render_pass_of_another_device_is_refused() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let other = setup(true);
    let target = other.color_target(8, vk::ImageUsageFlags::empty());
    let rule = "VUID-VkRenderPassBeginInfo-renderPass-parameter";
    let clear = [vk::ClearValue::default()];
    let begin = tuff::RenderPassBeginInfo::new(&target.render_pass, &target.framebuffer)
        .render_area(AREA)
        .clear_values(&clear);
    let contents = tuff::SubpassBeginInfo::new().contents(vk::SubpassContents::INLINE);
    let end = tuff::SubpassEndInfo::new();
    let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let rec = cb
        .begin(&tuff::CommandBufferBeginInfo::new())
        .expect("begin");
    let rec = rec
        .begin_render_pass2(&begin, &contents)
        .end_render_pass2(&end);
    assert_eq!(vuid(rec.end()), rule);
    let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let rec = cb
        .begin(&tuff::CommandBufferBeginInfo::new())
        .expect("begin");
    s.messages.take();
    s.messages.abort_on_error(true);
    let rec = unsafe {
        rec.begin_render_pass2_unchecked(&begin, &contents)
            .end_render_pass2_unchecked(&end)
    };
    s.messages.abort_on_error(false);
    drop(rec);
    // The 1.3.239 layer names the begin info's commonparent rule or the command's,
    // which the same objects break.
    let messages = s.messages.take();
    assert!(
        !messages.is_empty()
            && messages.iter().all(|m| m.contains(rule)
                    || m.contains("VUID-VkRenderPassBeginInfo-commonparent")
                    || m.contains("VUID-vkCmdBeginRenderPass2-framebuffer-02779")
                    // The end of the instance whose begin the layer skipped.
                    || m.contains("VUID-vkCmdEndRenderPass2-renderpass")),
        "the layer said {messages:?}"
    );
    assert_silent(&s.messages);
    assert_silent(&other.messages);
}

/// `Queue::upload_image` copies the bytes into the image and leaves it in the layout
/// asked for, through the transitions `Recorder::transition_image` records; what comes
/// back from the image is what went in, and the layer (with synchronization
/// validation) has nothing to say.
#[test]
fn an_upload_leaves_its_bytes_in_the_image_in_the_layout_asked_for() {
    let s = setup(true);
    let usage = vk::ImageUsageFlags::TRANSFER_DST | vk::ImageUsageFlags::TRANSFER_SRC;
    let (img, _memory) = image(
        &s,
        vk::Format::R8G8B8A8_UNORM,
        vk::SampleCountFlags::TYPE_1,
        usage,
    );
    let allocator = s.device.gpu_allocator().expect("allocator");
    let bytes: Vec<u8> = (0..SIDE * SIDE * 4).map(|i| (i * 7 % 251) as u8).collect();
    let color = vk::ImageAspectFlags::COLOR;
    s.queue
        .upload_image(&img, color, &bytes, SRC, &allocator)
        .expect("upload");
    let (back, back_memory) =
        host_buffer(&s, bytes.len() as u64, vk::BufferUsageFlags::TRANSFER_DST);
    let region = vk::BufferImageCopy {
        image_subresource: vk::ImageSubresourceLayers {
            aspect_mask: color,
            mip_level: 0,
            base_array_layer: 0,
            layer_count: 1,
        },
        image_extent: vk::Extent3D {
            width: SIDE,
            height: SIDE,
            depth: 1,
        },
        ..Default::default()
    };
    // The image is in SRC now: a copy that says so is accepted at submission, and
    // `submit_and_wait` hands back what the recording returned.
    let answer = s
        .queue
        .submit_and_wait(|rec| {
            rec.copy_image_to_buffer(&img, SRC, &back, &[region])?;
            let to_host = tuff::MemoryBarrier::new()
                .src_access_mask(vk::AccessFlags::TRANSFER_WRITE)
                .dst_access_mask(vk::AccessFlags::HOST_READ);
            rec.pipeline_barrier(
                vk::PipelineStageFlags::TRANSFER,
                vk::PipelineStageFlags::HOST,
                vk::DependencyFlags::empty(),
                &[to_host],
                &[],
                &[],
            )?;
            Ok(42)
        })
        .expect("copy back");
    assert_eq!(answer, 42);
    let mapped = back_memory.map().expect("map");
    assert_eq!(mapped.read::<u8>(0, bytes.len()).expect("read"), bytes);
    drop(mapped);
    assert_silent(&s.messages);
}

/// A transition from a layout the image is not in is refused when it is submitted,
/// and so is an upload of fewer bytes than the image holds (by the copy's check,
/// before anything is submitted); neither leaves the queue waiting.
#[test]
fn helpers_refuse_a_wrong_layout_and_too_few_bytes() {
    let s = setup(true);
    let usage = vk::ImageUsageFlags::TRANSFER_DST | vk::ImageUsageFlags::TRANSFER_SRC;
    let (img, _memory) = image(
        &s,
        vk::Format::R8G8B8A8_UNORM,
        vk::SampleCountFlags::TYPE_1,
        usage,
    );
    let allocator = s.device.gpu_allocator().expect("allocator");
    let color = vk::ImageAspectFlags::COLOR;
    let short = vec![0u8; (SIDE * SIDE * 4 - 1) as usize];
    assert_eq!(
        vuid(s.queue.upload_image(&img, color, &short, SRC, &allocator)),
        "VUID-vkCmdCopyBufferToImage-pRegions-00171"
    );
    let full = vec![9u8; (SIDE * SIDE * 4) as usize];
    // Depth data must lie in [0, 1], which depends on the format: left to the copy.
    assert!(matches!(
        s.queue
            .upload_image(&img, vk::ImageAspectFlags::DEPTH, &full, SRC, &allocator),
        Err(tuff::Error::Misuse(_))
    ));
    s.queue
        .upload_image(&img, color, &full, SRC, &allocator)
        .expect("upload");
    // The image is in SRC, not DST.
    assert_eq!(
        vuid(
            s.queue
                .submit_and_wait(|rec| rec.transition_image(&img, color, DST, GENERAL))
        ),
        "VUID-VkImageMemoryBarrier-oldLayout-01197"
    );
    // From the layout it is in, the same transition goes through.
    s.queue
        .submit_and_wait(|rec| rec.transition_image(&img, color, SRC, GENERAL))
        .expect("transition");
    assert_silent(&s.messages);
}
