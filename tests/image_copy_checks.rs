//! Copies between two images, through both versions of the command: the images'
//! sample counts, types, formats, aspects, usage and memory, and each region's
//! layers, depth and overlap.
//!
//! Each case breaks one rule through the safe method, which must refuse it with the
//! rule's VUID, and through the `_unchecked` twin under the validation layer (with a
//! messenger that makes the layer skip the call), which must name the same VUID (or
//! say nothing, where the 1.3.239 layer does not check the rule); copies that keep
//! the rules are recorded and run with the layer silent.
//!
//! SAFETY of the `unsafe` blocks around `_unchecked` calls: each breaks only the rule
//! under test, which the layer reports and so skips, or which lavapipe records without
//! reading memory (the command buffer is never submitted).

#[path = "common/tuff_setup.rs"]
mod tuff_setup;
#[path = "common/vulkan.rs"]
mod vulkan;

use tuff::vk;
use tuff_setup::{setup, vuid, Setup};
use vulkan::assert_silent;

type U = vk::ImageUsageFlags;
type L = vk::ImageLayout;
const TRANSFER: U = U::from_raw(U::TRANSFER_SRC.as_raw() | U::TRANSFER_DST.as_raw());
const RGBA: vk::Format = vk::Format::R8G8B8A8_UNORM;
const COLOR: vk::ImageAspectFlags = vk::ImageAspectFlags::COLOR;

/// What an image of a case is made with.
#[derive(Clone, Copy)]
struct Shape {
    ty: vk::ImageType,
    format: vk::Format,
    samples: vk::SampleCountFlags,
    usage: U,
    layers: u32,
    depth: u32,
    bound: bool,
}

const PLAIN: Shape = Shape {
    ty: vk::ImageType::TYPE_2D,
    format: RGBA,
    samples: vk::SampleCountFlags::TYPE_1,
    usage: TRANSFER,
    layers: 1,
    depth: 1,
    bound: true,
};

/// An image of `shape`, 4x4 (4 wide for 1D), and its memory.
fn image(s: &Setup, shape: Shape) -> (tuff::Image, Option<tuff::DeviceMemory>) {
    let height = if shape.ty == vk::ImageType::TYPE_1D {
        1
    } else {
        4
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
                .usage(shape.usage),
        )
        .expect("image");
    let memory = shape.bound.then(|| s.bind_image(&image));
    (image, memory)
}

fn layers(aspect: vk::ImageAspectFlags, count: u32) -> vk::ImageSubresourceLayers {
    vk::ImageSubresourceLayers {
        aspect_mask: aspect,
        mip_level: 0,
        base_array_layer: 0,
        layer_count: count,
    }
}

/// One region of the whole 4x4 colour layer.
fn region() -> vk::ImageCopy {
    vk::ImageCopy {
        src_subresource: layers(COLOR, 1),
        src_offset: vk::Offset3D::default(),
        dst_subresource: layers(COLOR, 1),
        dst_offset: vk::Offset3D::default(),
        extent: vk::Extent3D {
            width: 4,
            height: 4,
            depth: 1,
        },
    }
}

fn region2(r: &vk::ImageCopy) -> tuff::ImageCopy2<'static> {
    tuff::ImageCopy2::new()
        .src_subresource(r.src_subresource)
        .src_offset(r.src_offset)
        .dst_subresource(r.dst_subresource)
        .dst_offset(r.dst_offset)
        .extent(r.extent)
}

/// Records a copy of `src` into `dst` by one version, safely (which must name
/// `rule`) and unchecked under the layer (which must name `layer` where it is not
/// empty, and say nothing otherwise); returns what went wrong. Both are the first
/// version's VUIDs, renamed for the second, but a `layer` starting with `=`, which
/// the layer names as it stands.
fn try_case(
    s: &Setup,
    (src, dst): (&tuff::Image, &tuff::Image),
    r: vk::ImageCopy,
    (rule, layer): (&str, &str),
    two: bool,
) -> Option<String> {
    let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let mut rec = cb
        .begin(&tuff::CommandBufferBeginInfo::new())
        .expect("begin");
    let (from, to) = (L::TRANSFER_SRC_OPTIMAL, L::TRANSFER_DST_OPTIMAL);
    let regions2 = [region2(&r)];
    let info = tuff::CopyImageInfo2::new(src, dst)
        .src_image_layout(from)
        .dst_image_layout(to)
        .regions(&regions2);
    let version = |id: &str| {
        if let Some(verbatim) = id.strip_prefix('=') {
            verbatim.to_string()
        } else if two {
            id.replace(
                "vkCmdCopyImage-commandBuffer",
                "vkCmdCopyImage2-commandBuffer",
            )
            .replace("vkCmdCopyImage-", "VkCopyImageInfo2-")
        } else {
            id.to_string()
        }
    };
    let (rule, layer) = (version(rule), version(layer));
    let safe = vuid(if two {
        rec.copy_image2(&info)
    } else {
        rec.copy_image(src, from, dst, to, &[r])
    });
    s.messages.take();
    s.messages.abort_on_error(true);
    // SAFETY: see the module docs.
    unsafe {
        if two {
            let _ = rec.copy_image2_unchecked(&info);
        } else {
            let _ = rec.copy_image_unchecked(src, from, dst, to, &[r]);
        }
    }
    s.messages.abort_on_error(false);
    let said = s.messages.take();
    drop(rec);
    let named = if layer.is_empty() {
        said.is_empty()
    } else {
        said.iter().any(|m| m.contains(&layer))
    };
    (safe != rule || !named).then(|| {
        format!(
            "{}: tuff said {safe}, expected {rule}; the layer said {said:?}",
            if two { "v2" } else { "v1" }
        )
    })
}

#[test]
fn image_copies_fit_both_images_and_each_other() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let plain = image(&s, PLAIN);
    let plain2 = image(&s, PLAIN);
    let four = image(
        &s,
        Shape {
            samples: vk::SampleCountFlags::TYPE_4,
            usage: TRANSFER | U::COLOR_ATTACHMENT,
            ..PLAIN
        },
    );
    let one_d = image(
        &s,
        Shape {
            ty: vk::ImageType::TYPE_1D,
            ..PLAIN
        },
    );
    let one_d2 = image(
        &s,
        Shape {
            ty: vk::ImageType::TYPE_1D,
            ..PLAIN
        },
    );
    let two_layers = image(&s, Shape { layers: 2, ..PLAIN });
    let r8 = image(
        &s,
        Shape {
            format: vk::Format::R8_UNORM,
            ..PLAIN
        },
    );
    let depth_stencil = Shape {
        format: vk::Format::D32_SFLOAT_S8_UINT,
        ..PLAIN
    };
    let ds = image(&s, depth_stencil);
    let ds2 = image(&s, depth_stencil);
    let no_src = image(
        &s,
        Shape {
            usage: U::TRANSFER_DST,
            ..PLAIN
        },
    );
    let no_dst = image(
        &s,
        Shape {
            usage: U::TRANSFER_SRC,
            ..PLAIN
        },
    );
    let unbound = image(
        &s,
        Shape {
            bound: false,
            ..PLAIN
        },
    );
    let line = vk::ImageCopy {
        extent: vk::Extent3D {
            width: 4,
            height: 1,
            depth: 1,
        },
        ..region()
    };
    let deep = |r: vk::ImageCopy| vk::ImageCopy {
        extent: vk::Extent3D {
            depth: 2,
            ..r.extent
        },
        ..r
    };
    let both_layers = vk::ImageCopy {
        src_subresource: layers(COLOR, 2),
        ..region()
    };
    let depth_to_stencil = vk::ImageCopy {
        src_subresource: layers(vk::ImageAspectFlags::DEPTH, 1),
        dst_subresource: layers(vk::ImageAspectFlags::STENCIL, 1),
        ..region()
    };
    // Texels 0..3 of row 0 onto texels 2..5: they meet at 2 and 3.
    let overlapping = vk::ImageCopy {
        extent: vk::Extent3D {
            width: 2,
            height: 4,
            depth: 1,
        },
        dst_offset: vk::Offset3D { x: 1, y: 0, z: 0 },
        ..region()
    };
    type Case<'a> = (
        (&'a tuff::Image, &'a tuff::Image),
        vk::ImageCopy,
        &'static str,
        &'static str,
    );
    let cases: [Case<'_>; 10] = [
        (
            (&four.0, &plain.0),
            region(),
            "VUID-vkCmdCopyImage-srcImage-00136",
            "VUID-vkCmdCopyImage-srcImage-00136",
        ),
        (
            (&one_d.0, &plain.0),
            line,
            "VUID-vkCmdCopyImage-srcImage-07743",
            "VUID-vkCmdCopyImage-srcImage-07743",
        ),
        (
            (&two_layers.0, &plain2.0),
            both_layers,
            "VUID-vkCmdCopyImage-srcImage-07744",
            "VUID-vkCmdCopyImage-srcImage-07744",
        ),
        (
            (&plain.0, &plain2.0),
            deep(region()),
            "VUID-vkCmdCopyImage-srcImage-01790",
            "VUID-vkCmdCopyImage-srcImage-01790",
        ),
        (
            (&one_d.0, &one_d2.0),
            deep(line),
            "VUID-vkCmdCopyImage-srcImage-01785",
            "VUID-vkCmdCopyImage-srcImage-01785",
        ),
        (
            (&plain.0, &r8.0),
            region(),
            "VUID-vkCmdCopyImage-srcImage-01548",
            "VUID-vkCmdCopyImage-srcImage-01548",
        ),
        (
            (&ds.0, &ds2.0),
            depth_to_stencil,
            "VUID-vkCmdCopyImage-srcImage-01551",
            "VUID-vkCmdCopyImage-srcImage-01551",
        ),
        (
            (&no_src.0, &plain.0),
            region(),
            "VUID-vkCmdCopyImage-aspect-06662",
            "VUID-vkCmdCopyImage-aspect-06662",
        ),
        (
            (&plain.0, &no_dst.0),
            region(),
            "VUID-vkCmdCopyImage-aspect-06663",
            // The 1.3.239 layer names the first version's VUID for both versions.
            "=VUID-vkCmdCopyImage-aspect-06663",
        ),
        (
            (&plain.0, &plain.0),
            overlapping,
            "VUID-vkCmdCopyImage-pRegions-00124",
            "VUID-vkCmdCopyImage-pRegions-00124",
        ),
    ];
    let mut wrong = Vec::new();
    for two in [false, true] {
        for (images, r, rule, layer) in cases {
            wrong.extend(try_case(&s, images, r, (rule, layer), two));
        }
    }
    // An image without memory, on either side.
    for two in [false, true] {
        for (images, rule) in [
            ((&unbound.0, &plain.0), "VUID-vkCmdCopyImage-srcImage-01546"),
            ((&plain.0, &unbound.0), "VUID-vkCmdCopyImage-dstImage-01547"),
        ] {
            wrong.extend(try_case(&s, images, region(), (rule, rule), two));
        }
    }
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
    assert_silent(&s.messages);
}

/// Copies that keep the rules run: the whole image, a 2D layer into a 3D slice,
/// and within one image between regions that do not meet, with the layer silent.
#[test]
fn image_copies_that_keep_the_rules_run() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let (src, _m) = image(&s, PLAIN);
    let (dst, _m2) = image(&s, PLAIN);
    let (volume, _m3) = image(
        &s,
        Shape {
            ty: vk::ImageType::TYPE_3D,
            depth: 2,
            ..PLAIN
        },
    );
    let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let mut rec = cb
        .begin(&tuff::CommandBufferBeginInfo::new())
        .expect("begin");
    let range = vk::ImageSubresourceRange {
        aspect_mask: COLOR,
        base_mip_level: 0,
        level_count: 1,
        base_array_layer: 0,
        layer_count: 1,
    };
    let barrier = |image, old, new| {
        tuff::ImageMemoryBarrier::new(image)
            .src_access_mask(vk::AccessFlags::TRANSFER_WRITE)
            .dst_access_mask(vk::AccessFlags::TRANSFER_READ | vk::AccessFlags::TRANSFER_WRITE)
            .old_layout(old)
            .new_layout(new)
            .subresource_range(range)
    };
    let transfer = vk::PipelineStageFlags::TRANSFER;
    rec.pipeline_barrier(
        transfer,
        transfer,
        vk::DependencyFlags::empty(),
        &[],
        &[],
        &[
            barrier(&src, L::UNDEFINED, L::TRANSFER_DST_OPTIMAL),
            barrier(&dst, L::UNDEFINED, L::TRANSFER_DST_OPTIMAL),
            barrier(&volume, L::UNDEFINED, L::TRANSFER_DST_OPTIMAL),
        ],
    )
    .expect("to TRANSFER_DST");
    let green = vk::ClearColorValue {
        float32: [0.0, 1.0, 0.0, 1.0],
    };
    rec.clear_color_image(&src, L::TRANSFER_DST_OPTIMAL, &green, &[range])
        .expect("clear");
    rec.pipeline_barrier(
        transfer,
        transfer,
        vk::DependencyFlags::empty(),
        &[],
        &[],
        &[barrier(&src, L::TRANSFER_DST_OPTIMAL, L::GENERAL)],
    )
    .expect("to GENERAL");
    // Within one image: the left half onto the right half.
    let half = vk::ImageCopy {
        extent: vk::Extent3D {
            width: 2,
            height: 4,
            depth: 1,
        },
        dst_offset: vk::Offset3D { x: 2, y: 0, z: 0 },
        ..region()
    };
    rec.copy_image(&src, L::GENERAL, &src, L::GENERAL, &[half])
        .expect("within one image");
    rec.pipeline_barrier(
        transfer,
        transfer,
        vk::DependencyFlags::empty(),
        &[],
        &[],
        &[barrier(&src, L::GENERAL, L::TRANSFER_SRC_OPTIMAL)],
    )
    .expect("to TRANSFER_SRC");
    rec.copy_image(
        &src,
        L::TRANSFER_SRC_OPTIMAL,
        &dst,
        L::TRANSFER_DST_OPTIMAL,
        &[region()],
    )
    .expect("a copy");
    let slice = vk::ImageCopy {
        dst_offset: vk::Offset3D { x: 0, y: 0, z: 1 },
        ..region()
    };
    let regions2 = [region2(&slice)];
    rec.copy_image2(
        &tuff::CopyImageInfo2::new(&src, &volume)
            .src_image_layout(L::TRANSFER_SRC_OPTIMAL)
            .dst_image_layout(L::TRANSFER_DST_OPTIMAL)
            .regions(&regions2),
    )
    .expect("a 2D layer into a 3D slice");
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
