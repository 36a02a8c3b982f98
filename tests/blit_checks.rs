//! Blits, through both versions of the command: the images' sample counts and
//! formats, the filter against the source's format, and each region's aspects,
//! layers, offsets and overlap.
//!
//! Each case breaks one rule through the safe method, which must refuse it with the
//! rule's VUID, and through the `_unchecked` twin under the validation layer (with a
//! messenger that makes the layer skip the call), which must name the same VUID (or
//! say nothing, where the 1.3.239 layer does not check the rule);
//! blits that keep the rules are recorded and run with the layer silent.
//!
//! SAFETY of the `unsafe` blocks around `_unchecked` calls: each breaks only the rule
//! under test, which the layer reports and so skips (the command buffer is never
//! submitted).

#[path = "common/tuff_setup.rs"]
mod tuff_setup;
#[path = "common/vulkan.rs"]
mod vulkan;

use tuff::vk;
use tuff_setup::{setup, vuid, Setup};
use vulkan::assert_silent;

type U = vk::ImageUsageFlags;
type L = vk::ImageLayout;
type F = vk::Format;
const TRANSFER: U = U::from_raw(U::TRANSFER_SRC.as_raw() | U::TRANSFER_DST.as_raw());
const COLOR: vk::ImageAspectFlags = vk::ImageAspectFlags::COLOR;
const NEAREST: vk::Filter = vk::Filter::NEAREST;
const LINEAR: vk::Filter = vk::Filter::LINEAR;

/// What an image of a case is made with.
#[derive(Clone, Copy)]
struct Shape {
    ty: vk::ImageType,
    format: vk::Format,
    samples: vk::SampleCountFlags,
    layers: u32,
    depth: u32,
}

const PLAIN: Shape = Shape {
    ty: vk::ImageType::TYPE_2D,
    format: F::R8G8B8A8_UNORM,
    samples: vk::SampleCountFlags::TYPE_1,
    layers: 1,
    depth: 1,
};

/// An image of `shape`, 4x4 (4 wide for 1D), bound to memory.
fn image(s: &Setup, shape: Shape) -> (tuff::Image, tuff::DeviceMemory) {
    let height = if shape.ty == vk::ImageType::TYPE_1D {
        1
    } else {
        4
    };
    let usage = if shape.samples == vk::SampleCountFlags::TYPE_1 {
        TRANSFER
    } else {
        TRANSFER | U::COLOR_ATTACHMENT
    };
    let image = s
        .device
        .create_image(
            &tuff::ImageCreateInfo::new()
                .image_type(shape.ty)
                .format(shape.format)
                .extent(vk::Extent3D {
                    width: 4,
                    height,
                    depth: shape.depth,
                })
                .mip_levels(1)
                .array_layers(shape.layers)
                .samples(shape.samples)
                .usage(usage),
        )
        .expect("image");
    let memory = s.bind_image(&image);
    (image, memory)
}

fn layers(aspect: vk::ImageAspectFlags, base: u32, count: u32) -> vk::ImageSubresourceLayers {
    vk::ImageSubresourceLayers {
        aspect_mask: aspect,
        mip_level: 0,
        base_array_layer: base,
        layer_count: count,
    }
}

fn at(x: i32, y: i32, z: i32) -> vk::Offset3D {
    vk::Offset3D { x, y, z }
}

/// One region of the whole 4x4 colour layer onto itself.
fn region() -> vk::ImageBlit {
    vk::ImageBlit {
        src_subresource: layers(COLOR, 0, 1),
        src_offsets: [at(0, 0, 0), at(4, 4, 1)],
        dst_subresource: layers(COLOR, 0, 1),
        dst_offsets: [at(0, 0, 0), at(4, 4, 1)],
    }
}

fn region2(r: &vk::ImageBlit) -> tuff::ImageBlit2<'static> {
    tuff::ImageBlit2::new()
        .src_subresource(r.src_subresource)
        .src_offsets(r.src_offsets)
        .dst_subresource(r.dst_subresource)
        .dst_offsets(r.dst_offsets)
}

/// Records a blit of `src` into `dst` by one version, safely (which must name
/// `rule`) and unchecked under the layer (which must name it too, where it checks
/// the rule); returns what went wrong. `rule` is the first version's VUID, renamed for the second.
fn try_case(
    s: &Setup,
    (src, dst): (&tuff::Image, &tuff::Image),
    (r, filter): (vk::ImageBlit, vk::Filter),
    rule: &str,
    two: bool,
) -> Option<String> {
    let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let mut rec = cb
        .begin(&tuff::CommandBufferBeginInfo::new())
        .expect("begin");
    // A blit within one image names one layout for both sides.
    let (from, to) = if core::ptr::eq(src, dst) {
        (L::GENERAL, L::GENERAL)
    } else {
        (L::TRANSFER_SRC_OPTIMAL, L::TRANSFER_DST_OPTIMAL)
    };
    let regions2 = [region2(&r)];
    let info = tuff::BlitImageInfo2::new(src, dst)
        .src_image_layout(from)
        .dst_image_layout(to)
        .regions(&regions2)
        .filter(filter);
    let rule = if two {
        rule.replace("vkCmdBlitImage-", "VkBlitImageInfo2-")
            .replace("VkImageBlit-", "VkImageBlit2-")
    } else {
        rule.to_string()
    };
    let safe = vuid(if two {
        rec.blit_image2(&info)
    } else {
        rec.blit_image(src, from, dst, to, &[r], filter)
    });
    s.messages.take();
    s.messages.abort_on_error(true);
    // SAFETY: see the module docs.
    unsafe {
        if two {
            let _ = rec.blit_image2_unchecked(&info);
        } else {
            let _ = rec.blit_image_unchecked(src, from, dst, to, &[r], filter);
        }
    }
    s.messages.abort_on_error(false);
    let said = s.messages.take();
    drop(rec);
    // The 1.3.239 layer does not check the overlap of a blit's regions: it must
    // say nothing there (lavapipe records the command, which is never submitted),
    // and tuff's error alone proves the rule. A layer that starts checking fails.
    let named = if rule.ends_with("pRegions-00217") {
        said.is_empty()
    } else {
        said.iter().any(|m| m.contains(&rule))
    };
    (safe != rule || !named).then(|| {
        format!(
            "{}: tuff said {safe}, expected {rule}; the layer said {said:?}",
            if two { "v2" } else { "v1" }
        )
    })
}

#[test]
fn blits_fit_their_images_filter_and_regions() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let plain = image(&s, PLAIN);
    let plain2 = image(&s, PLAIN);
    let four = image(
        &s,
        Shape {
            samples: vk::SampleCountFlags::TYPE_4,
            ..PLAIN
        },
    );
    let with = |format| image(&s, Shape { format, ..PLAIN });
    let sint = with(F::R8G8B8A8_SINT);
    let uint = with(F::R8G8B8A8_UINT);
    let uint2 = with(F::R8G8B8A8_UINT);
    let d32 = with(F::D32_SFLOAT);
    let d32b = with(F::D32_SFLOAT);
    let d32s8 = with(F::D32_SFLOAT_S8_UINT);
    let d32s8b = with(F::D32_SFLOAT_S8_UINT);
    let two_layers = image(&s, Shape { layers: 2, ..PLAIN });
    let two_layers2 = image(&s, Shape { layers: 2, ..PLAIN });
    let volume = image(
        &s,
        Shape {
            ty: vk::ImageType::TYPE_3D,
            depth: 2,
            ..PLAIN
        },
    );
    let line = image(
        &s,
        Shape {
            ty: vk::ImageType::TYPE_1D,
            ..PLAIN
        },
    );
    let depth_region = |aspect| vk::ImageBlit {
        src_subresource: layers(aspect, 0, 1),
        dst_subresource: layers(aspect, 0, 1),
        ..region()
    };
    let region_with = |src_offsets, dst_offsets| vk::ImageBlit {
        src_offsets,
        dst_offsets,
        ..region()
    };
    let whole = [at(0, 0, 0), at(4, 4, 1)];
    type Case<'a> = (
        (&'a tuff::Image, &'a tuff::Image),
        (vk::ImageBlit, vk::Filter),
        &'static str,
    );
    let cases: [Case<'_>; 15] = [
        (
            (&four.0, &plain.0),
            (region(), NEAREST),
            "VUID-vkCmdBlitImage-srcImage-00233",
        ),
        (
            (&plain.0, &four.0),
            (region(), NEAREST),
            "VUID-vkCmdBlitImage-dstImage-00234",
        ),
        (
            (&sint.0, &plain.0),
            (region(), NEAREST),
            "VUID-vkCmdBlitImage-srcImage-00229",
        ),
        (
            (&uint.0, &plain.0),
            (region(), NEAREST),
            "VUID-vkCmdBlitImage-srcImage-00230",
        ),
        (
            (&d32.0, &d32s8.0),
            (depth_region(vk::ImageAspectFlags::DEPTH), NEAREST),
            "VUID-vkCmdBlitImage-srcImage-00231",
        ),
        (
            (&d32.0, &d32b.0),
            (depth_region(vk::ImageAspectFlags::DEPTH), LINEAR),
            "VUID-vkCmdBlitImage-srcImage-00232",
        ),
        (
            (&uint.0, &uint2.0),
            (region(), LINEAR),
            "VUID-vkCmdBlitImage-filter-02001",
        ),
        (
            (&two_layers.0, &volume.0),
            (
                vk::ImageBlit {
                    src_subresource: layers(COLOR, 1, 1),
                    ..region()
                },
                NEAREST,
            ),
            "VUID-vkCmdBlitImage-srcImage-00240",
        ),
        (
            (&line.0, &plain.0),
            (region_with([at(0, 0, 0), at(4, 0, 1)], whole), NEAREST),
            "VUID-vkCmdBlitImage-srcImage-00245",
        ),
        (
            (&plain.0, &plain2.0),
            (region_with([at(0, 0, 0), at(4, 4, 0)], whole), NEAREST),
            "VUID-vkCmdBlitImage-srcImage-00247",
        ),
        (
            (&plain.0, &line.0),
            (region_with(whole, [at(0, 0, 0), at(4, 0, 1)]), NEAREST),
            "VUID-vkCmdBlitImage-dstImage-00250",
        ),
        (
            (&plain.0, &plain2.0),
            (region_with(whole, [at(0, 0, 0), at(4, 4, 0)]), NEAREST),
            "VUID-vkCmdBlitImage-dstImage-00252",
        ),
        (
            (&d32s8.0, &d32s8b.0),
            (
                vk::ImageBlit {
                    src_subresource: layers(vk::ImageAspectFlags::DEPTH, 0, 1),
                    dst_subresource: layers(vk::ImageAspectFlags::STENCIL, 0, 1),
                    ..region()
                },
                NEAREST,
            ),
            "VUID-VkImageBlit-aspectMask-00238",
        ),
        (
            (&two_layers.0, &two_layers2.0),
            (
                vk::ImageBlit {
                    src_subresource: layers(COLOR, 0, 2),
                    ..region()
                },
                NEAREST,
            ),
            "VUID-VkImageBlit-layerCount-00239",
        ),
        (
            (&plain.0, &plain.0),
            (
                region_with([at(0, 0, 0), at(2, 4, 1)], [at(2, 0, 0), at(4, 4, 1)]),
                NEAREST,
            ),
            "VUID-vkCmdBlitImage-pRegions-00217",
        ),
    ];
    let mut wrong = Vec::new();
    for two in [false, true] {
        for (images, blit, rule) in cases {
            wrong.extend(try_case(&s, images, blit, rule, two));
        }
    }
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
    assert_silent(&s.messages);
}

/// Blits that keep the rules run: a scaled and a mirrored blit between two images,
/// and within one image between regions that do not meet, with the layer silent.
#[test]
fn blits_that_keep_the_rules_run() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let (src, _m) = image(&s, Shape { layers: 2, ..PLAIN });
    let (dst, _m2) = image(&s, PLAIN);
    let range = |base_array_layer, layer_count| vk::ImageSubresourceRange {
        aspect_mask: COLOR,
        base_mip_level: 0,
        level_count: 1,
        base_array_layer,
        layer_count,
    };
    let barrier = |image, (old, new), range| {
        tuff::ImageMemoryBarrier::new(image)
            .src_access_mask(vk::AccessFlags::TRANSFER_WRITE)
            .dst_access_mask(vk::AccessFlags::TRANSFER_READ | vk::AccessFlags::TRANSFER_WRITE)
            .old_layout(old)
            .new_layout(new)
            .subresource_range(range)
    };
    let transfer = vk::PipelineStageFlags::TRANSFER;
    let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let mut rec = cb
        .begin(&tuff::CommandBufferBeginInfo::new())
        .expect("begin");
    let (dst_optimal, src_optimal) = (L::TRANSFER_DST_OPTIMAL, L::TRANSFER_SRC_OPTIMAL);
    rec.pipeline_barrier(
        transfer,
        transfer,
        vk::DependencyFlags::empty(),
        &[],
        &[],
        &[
            barrier(&src, (L::UNDEFINED, dst_optimal), range(0, 2)),
            barrier(&dst, (L::UNDEFINED, dst_optimal), range(0, 1)),
        ],
    )
    .expect("layouts");
    let green = vk::ClearColorValue {
        float32: [0.0, 1.0, 0.0, 1.0],
    };
    rec.clear_color_image(&src, dst_optimal, &green, &[range(0, 1)])
        .expect("clear");
    rec.pipeline_barrier(
        transfer,
        transfer,
        vk::DependencyFlags::empty(),
        &[],
        &[],
        &[barrier(&src, (dst_optimal, src_optimal), range(0, 1))],
    )
    .expect("layer 0 to TRANSFER_SRC");
    // Within one image: layer 0 onto layer 1, which do not meet.
    let within = vk::ImageBlit {
        dst_subresource: layers(COLOR, 1, 1),
        ..region()
    };
    rec.blit_image(&src, src_optimal, &src, dst_optimal, &[within], NEAREST)
        .expect("within one image");
    // Scaled up from a quarter, with the linear filter.
    let scaled = vk::ImageBlit {
        src_offsets: [at(0, 0, 0), at(2, 2, 1)],
        ..region()
    };
    rec.blit_image(&src, src_optimal, &dst, dst_optimal, &[scaled], LINEAR)
        .expect("a scaled blit");
    rec.pipeline_barrier(
        transfer,
        transfer,
        vk::DependencyFlags::empty(),
        &[],
        &[],
        &[barrier(&dst, (dst_optimal, dst_optimal), range(0, 1))],
    )
    .expect("between the blits");
    // Mirrored, by the second version.
    let mirrored = vk::ImageBlit {
        dst_offsets: [at(4, 0, 0), at(0, 4, 1)],
        ..region()
    };
    let regions2 = [region2(&mirrored)];
    rec.blit_image2(
        &tuff::BlitImageInfo2::new(&src, &dst)
            .src_image_layout(src_optimal)
            .dst_image_layout(dst_optimal)
            .regions(&regions2)
            .filter(NEAREST),
    )
    .expect("a mirrored blit");
    rec.end().expect("end");
    let fence = s
        .device
        .create_fence(&tuff::FenceCreateInfo::new())
        .expect("fence");
    let cbs = tuff::HandleSlice::new(&[&cb]);
    s.queue
        .submit(
            &[tuff::SubmitInfo::new().command_buffers(&cbs)],
            Some(&fence),
        )
        .expect("submit");
    assert_eq!(
        s.device
            .wait_for_fences(&fence, true, u64::MAX)
            .expect("wait"),
        tuff::SuccessOrTimeout::Success
    );
    assert_silent(&s.messages);
}
