//! Resolves of a multisampled image outside a render pass, through both versions of
//! the command: the images' sample counts and formats, their memory, and each
//! region's aspects, layers and offsets.
//!
//! Each case breaks one rule through the safe method, which must refuse it with the
//! rule's VUID, and through the `_unchecked` twin under the validation layer (with a
//! messenger that makes the layer skip the call), which must name the same VUID (or
//! say nothing, where the 1.3.239 layer does not check the rule); a resolve that keeps
//! the rules is recorded with the layer silent. No command buffer is submitted.
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

fn image(s: &Setup, format: vk::Format, samples: vk::SampleCountFlags, usage: U) -> tuff::Image {
    image_of_layers(s, format, samples, usage, 1)
}

fn image_of_layers(
    s: &Setup,
    format: vk::Format,
    samples: vk::SampleCountFlags,
    usage: U,
    layers: u32,
) -> tuff::Image {
    s.device
        .create_image(
            &tuff::ImageCreateInfo::new()
                .image_type(vk::ImageType::TYPE_2D)
                .format(format)
                .extent(vk::Extent3D {
                    width: 4,
                    height: 4,
                    depth: 1,
                })
                .mip_levels(1)
                .array_layers(layers)
                .samples(samples)
                .usage(usage),
        )
        .expect("image")
}

/// One resolve region of the whole 4x4 colour layer.
fn region() -> vk::ImageResolve {
    let color = vk::ImageSubresourceLayers {
        aspect_mask: vk::ImageAspectFlags::COLOR,
        mip_level: 0,
        base_array_layer: 0,
        layer_count: 1,
    };
    vk::ImageResolve {
        src_subresource: color,
        src_offset: vk::Offset3D::default(),
        dst_subresource: color,
        dst_offset: vk::Offset3D::default(),
        extent: vk::Extent3D {
            width: 4,
            height: 4,
            depth: 1,
        },
    }
}

/// Records a resolve of `src` into `dst` by one version, safely (which must name
/// `rule`) and unchecked under the layer (which must name it where `layer_checks`, and
/// say nothing otherwise); returns what went wrong.
fn try_case(
    s: &Setup,
    (src, dst): (&tuff::Image, &tuff::Image),
    r: vk::ImageResolve,
    (rule, layer_checks): (&str, bool),
    two: bool,
) -> Option<String> {
    let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let mut rec = cb
        .begin(&tuff::CommandBufferBeginInfo::new())
        .expect("begin");
    let (from, to) = (L::TRANSFER_SRC_OPTIMAL, L::TRANSFER_DST_OPTIMAL);
    let regions2 = [tuff::ImageResolve2::new()
        .src_subresource(r.src_subresource)
        .src_offset(r.src_offset)
        .dst_subresource(r.dst_subresource)
        .dst_offset(r.dst_offset)
        .extent(r.extent)];
    let info = tuff::ResolveImageInfo2::new(src, dst)
        .src_image_layout(from)
        .dst_image_layout(to)
        .regions(&regions2);
    let rule = if two {
        rule.replace("vkCmdResolveImage-", "VkResolveImageInfo2-")
            .replace("VkImageResolve-", "VkImageResolve2-")
    } else {
        rule.to_string()
    };
    let safe = vuid(if two {
        rec.resolve_image2(&info)
    } else {
        rec.resolve_image(src, from, dst, to, &[r])
    });
    s.messages.take();
    s.messages.abort_on_error(true);
    // SAFETY: see the module docs.
    unsafe {
        if two {
            let _ = rec.resolve_image2_unchecked(&info);
        } else {
            let _ = rec.resolve_image_unchecked(src, from, dst, to, &[r]);
        }
    }
    s.messages.abort_on_error(false);
    let said = s.messages.take();
    drop(rec);
    let named = if layer_checks {
        said.iter().any(|m| m.contains(&rule))
    } else {
        said.is_empty()
    };
    (safe != rule || !named).then(|| {
        format!(
            "{}: tuff said {safe}, expected {rule}; the layer said {said:?}",
            if two { "v2" } else { "v1" }
        )
    })
}

#[test]
fn resolves_fit_their_images_and_regions() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let rgba = vk::Format::R8G8B8A8_UNORM;
    let four = vk::SampleCountFlags::TYPE_4;
    let one = vk::SampleCountFlags::TYPE_1;
    let attach = U::COLOR_ATTACHMENT | U::TRANSFER_SRC | U::TRANSFER_DST;
    let ms = image(&s, rgba, four, attach);
    let _ms_memory = s.bind_image(&ms);
    let single = image(&s, rgba, one, attach);
    let _single_memory = s.bind_image(&single);
    let ms2 = image(&s, rgba, four, attach);
    let _ms2_memory = s.bind_image(&ms2);
    let bgra = image(&s, vk::Format::B8G8R8A8_UNORM, one, attach);
    let _bgra_memory = s.bind_image(&bgra);
    // Two images in one memory at one offset.
    let aliased = image(&s, rgba, one, attach);
    let shared = {
        let d = &s.device;
        let reqs = d.get_image_memory_requirements(&ms).expect("requirements");
        let other = d
            .get_image_memory_requirements(&aliased)
            .expect("requirements");
        let memory = d
            .allocate_memory(
                &tuff::MemoryAllocateInfo::new()
                    .allocation_size(reqs.size.max(other.size))
                    .memory_type_index(s.memory_type(
                        reqs.memory_type_bits & other.memory_type_bits,
                        vk::MemoryPropertyFlags::empty(),
                    )),
            )
            .expect("memory");
        memory
    };
    let ms_aliased = image(&s, rgba, four, attach);
    s.device
        .bind_image_memory(&ms_aliased, &shared, 0)
        .expect("bind");
    s.device
        .bind_image_memory(&aliased, &shared, 0)
        .expect("bind");
    let depth_aspect = vk::ImageResolve {
        src_subresource: vk::ImageSubresourceLayers {
            aspect_mask: vk::ImageAspectFlags::DEPTH,
            ..region().src_subresource
        },
        ..region()
    };
    // Two layers of a two-layer source into one layer.
    let ms_layers = image_of_layers(&s, rgba, four, attach, 2);
    let _ms_layers_memory = s.bind_image(&ms_layers);
    let two_layers = vk::ImageResolve {
        src_subresource: vk::ImageSubresourceLayers {
            layer_count: 2,
            ..region().src_subresource
        },
        ..region()
    };
    let cases: [((&tuff::Image, &tuff::Image), vk::ImageResolve, &str, bool); 6] = [
        (
            (&single, &single),
            region(),
            "VUID-vkCmdResolveImage-srcImage-00257",
            true,
        ),
        (
            (&ms, &ms2),
            region(),
            "VUID-vkCmdResolveImage-dstImage-00259",
            true,
        ),
        (
            (&ms, &bgra),
            region(),
            "VUID-vkCmdResolveImage-srcImage-01386",
            true,
        ),
        (
            (&ms_aliased, &aliased),
            region(),
            "VUID-vkCmdResolveImage-pRegions-00255",
            false,
        ),
        (
            (&ms, &single),
            depth_aspect,
            "VUID-VkImageResolve-aspectMask-00266",
            true,
        ),
        (
            (&ms_layers, &single),
            two_layers,
            "VUID-VkImageResolve-layerCount-00267",
            true,
        ),
    ];
    let mut wrong = Vec::new();
    for two in [false, true] {
        for (images, r, rule, layer_checks) in cases {
            wrong.extend(try_case(&s, images, r, (rule, layer_checks), two));
        }
    }
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
    // A resolve that keeps the rules, by both versions.
    let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let mut rec = cb
        .begin(&tuff::CommandBufferBeginInfo::new())
        .expect("begin");
    let (from, to) = (L::TRANSFER_SRC_OPTIMAL, L::TRANSFER_DST_OPTIMAL);
    rec.resolve_image(&ms, from, &single, to, &[region()])
        .expect("a resolve");
    rec.end().expect("end");
    // The second version in a recording of its own (two resolves into one image
    // need a barrier between them).
    let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let mut rec = cb
        .begin(&tuff::CommandBufferBeginInfo::new())
        .expect("begin");
    let r = region();
    let regions2 = [tuff::ImageResolve2::new()
        .src_subresource(r.src_subresource)
        .dst_subresource(r.dst_subresource)
        .extent(r.extent)];
    rec.resolve_image2(
        &tuff::ResolveImageInfo2::new(&ms, &single)
            .src_image_layout(from)
            .dst_image_layout(to)
            .regions(&regions2),
    )
    .expect("a resolve by the second version");
    rec.end().expect("end");
    assert_silent(&s.messages);
}
