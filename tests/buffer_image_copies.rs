//! Copies between buffers and images: every region is checked against the image's
//! type, format and texel blocks, its subresources, the buffer, and the memory both
//! are bound to.
//!
//! Each case changes one valid region so that it breaks one rule, and records it
//! through the four commands that copy between a buffer and an image
//! (`vkCmdCopyBufferToImage`, `vkCmdCopyImageToBuffer` and their `2` forms). tuff
//! must refuse the safe call with the rule's VUID for that command; the validation
//! layer, for the `_unchecked` twin (told to skip the call it reports), must name
//! the same VUID.
//!
//! SAFETY of the `unsafe` blocks: the copy methods are `unsafe` for rules their
//! `# Safety` sections list, which these copies keep but for the one each case
//! breaks on purpose, which tuff refuses and the layer skips; no command buffer is
//! submitted.

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

const DST: vk::ImageLayout = vk::ImageLayout::TRANSFER_DST_OPTIMAL;
const SRC: vk::ImageLayout = vk::ImageLayout::TRANSFER_SRC_OPTIMAL;
const COLOR: vk::ImageAspectFlags = vk::ImageAspectFlags::COLOR;
const DEPTH: vk::ImageAspectFlags = vk::ImageAspectFlags::DEPTH;
const STENCIL: vk::ImageAspectFlags = vk::ImageAspectFlags::STENCIL;

/// The images the cases copy to and from.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Kind {
    /// 8x8 RGBA8.
    Rgba,
    /// 8 texels of RGBA8, 1D.
    OneD,
    /// 8x8x4 RGBA8, 3D.
    ThreeD,
    /// 8x8 BC1 (4x4 blocks of 8 bytes).
    Bc1,
    /// 8x8 D16.
    Depth16,
    /// 8x8 D32 with S8.
    DepthStencil,
    /// 8x8 RGBA8 with 4 samples.
    Multisampled,
}

const KINDS: [Kind; 7] = [
    Kind::Rgba,
    Kind::OneD,
    Kind::ThreeD,
    Kind::Bc1,
    Kind::Depth16,
    Kind::DepthStencil,
    Kind::Multisampled,
];

fn image(s: &Setup, kind: Kind) -> (tuff::Image, tuff::DeviceMemory) {
    let (ty, format, extent, samples) = match kind {
        Kind::Rgba => (
            vk::ImageType::TYPE_2D,
            vk::Format::R8G8B8A8_UNORM,
            (8, 8, 1),
            1,
        ),
        Kind::OneD => (
            vk::ImageType::TYPE_1D,
            vk::Format::R8G8B8A8_UNORM,
            (8, 1, 1),
            1,
        ),
        Kind::ThreeD => (
            vk::ImageType::TYPE_3D,
            vk::Format::R8G8B8A8_UNORM,
            (8, 8, 4),
            1,
        ),
        Kind::Bc1 => (
            vk::ImageType::TYPE_2D,
            vk::Format::BC1_RGBA_UNORM_BLOCK,
            (8, 8, 1),
            1,
        ),
        Kind::Depth16 => (vk::ImageType::TYPE_2D, vk::Format::D16_UNORM, (8, 8, 1), 1),
        Kind::DepthStencil => (
            vk::ImageType::TYPE_2D,
            vk::Format::D32_SFLOAT_S8_UINT,
            (8, 8, 1),
            1,
        ),
        Kind::Multisampled => (
            vk::ImageType::TYPE_2D,
            vk::Format::R8G8B8A8_UNORM,
            (8, 8, 1),
            4,
        ),
    };
    let mut usage = vk::ImageUsageFlags::TRANSFER_SRC | vk::ImageUsageFlags::TRANSFER_DST;
    if samples > 1 {
        usage |= vk::ImageUsageFlags::COLOR_ATTACHMENT;
    }
    let image = s
        .device
        .create_image(
            &tuff::ImageCreateInfo::new()
                .image_type(ty)
                .format(format)
                .extent(vk::Extent3D {
                    width: extent.0,
                    height: extent.1,
                    depth: extent.2,
                })
                .mip_levels(1)
                .array_layers(1)
                .samples(vk::SampleCountFlags::from_raw(samples))
                .usage(usage),
        )
        .unwrap_or_else(|e| panic!("a {kind:?} image: {e}"));
    let memory = s.bind_image(&image);
    (image, memory)
}

/// The valid region the cases change: the whole first 4x4 (or 4-wide) corner.
fn region(aspect: vk::ImageAspectFlags) -> vk::BufferImageCopy {
    vk::BufferImageCopy {
        buffer_offset: 0,
        buffer_row_length: 0,
        buffer_image_height: 0,
        image_subresource: vk::ImageSubresourceLayers {
            aspect_mask: aspect,
            mip_level: 0,
            base_array_layer: 0,
            layer_count: 1,
        },
        image_offset: vk::Offset3D::default(),
        image_extent: vk::Extent3D {
            width: 4,
            height: 4,
            depth: 1,
        },
    }
}

/// A case: what it breaks, the image, the region, and the rule each command names
/// (in the order buffer to image, image to buffer, and their `2` forms).
struct Case {
    what: &'static str,
    kind: Kind,
    region: vk::BufferImageCopy,
    rules: [&'static str; 4],
    /// Whether the layer checks the rule; where it does not, it must report no
    /// error, and tuff's error alone proves the rule.
    layer: bool,
}

/// The rule `tail` of each of the four commands, whose VUIDs name the command or
/// its info struct.
fn each(tail: &str) -> [&'static str; 4] {
    [
        "VUID-vkCmdCopyBufferToImage-",
        "VUID-vkCmdCopyImageToBuffer-",
        "VUID-VkCopyBufferToImageInfo2-",
        "VUID-VkCopyImageToBufferInfo2-",
    ]
    .map(|p| &*Box::leak(format!("{p}{tail}").into_boxed_str()))
}

/// As [`each`], for a rule of `VkBufferImageCopy` and `VkBufferImageCopy2`.
fn of_struct(tail: &str) -> [&'static str; 4] {
    let one = &*Box::leak(format!("VUID-VkBufferImageCopy-{tail}").into_boxed_str());
    let two = &*Box::leak(format!("VUID-VkBufferImageCopy2-{tail}").into_boxed_str());
    [one, one, two, two]
}

fn cases() -> Vec<Case> {
    let with = |kind, aspect, change: fn(&mut vk::BufferImageCopy)| {
        let mut r = region(aspect);
        change(&mut r);
        (kind, r)
    };
    let mut out = Vec::new();
    let mut add = |what, (kind, region), rules| {
        out.push(Case {
            what,
            kind,
            region,
            rules,
            layer: true,
        })
    };
    add(
        "a row length below the width",
        with(Kind::Rgba, COLOR, |r| r.buffer_row_length = 2),
        of_struct("bufferRowLength-00195"),
    );
    add(
        "an image height below the height",
        with(Kind::Rgba, COLOR, |r| r.buffer_image_height = 2),
        of_struct("bufferImageHeight-00196"),
    );
    add(
        "two aspects",
        with(Kind::DepthStencil, DEPTH | STENCIL, |_| {}),
        of_struct("aspectMask-00212"),
    );
    add(
        "color with depth",
        with(Kind::Rgba, COLOR | DEPTH, |_| {}),
        ["VUID-VkImageSubresourceLayers-aspectMask-00167"; 4],
    );
    add(
        "an aspect the image has not",
        with(Kind::Rgba, DEPTH, |_| {}),
        each("aspectMask-00211"),
    );
    // The `2` forms check the z range first (a rule of its own).
    let mut flat = each("srcImage-00201");
    flat[2] = "";
    flat[3] = "";
    add(
        "a 2D copy with a z offset",
        with(Kind::Rgba, COLOR, |r| r.image_offset.z = 1),
        flat,
    );
    let mut deep = each("imageOffset-00200");
    deep[2] = "";
    deep[3] = "";
    add(
        "a 3D copy past the depth",
        with(Kind::ThreeD, COLOR, |r| {
            r.image_offset.z = 2;
            r.image_extent.depth = 4;
        }),
        deep,
    );
    add(
        "a row length that is not a whole number of blocks",
        with(Kind::Bc1, COLOR, |r| r.buffer_row_length = 6),
        each("bufferRowLength-00203"),
    );
    add(
        "an image height that is not a whole number of blocks",
        with(Kind::Bc1, COLOR, |r| r.buffer_image_height = 6),
        each("bufferImageHeight-00204"),
    );
    add(
        "an x offset inside a block",
        with(Kind::Bc1, COLOR, |r| r.image_offset.x = 2),
        each("pRegions-07274"),
    );
    add(
        "a y offset inside a block",
        with(Kind::Bc1, COLOR, |r| r.image_offset.y = 2),
        each("pRegions-07275"),
    );
    add(
        "a width that is not a whole number of blocks",
        with(Kind::Bc1, COLOR, |r| r.image_extent.width = 2),
        each("imageExtent-00207"),
    );
    add(
        "a height that is not a whole number of blocks",
        with(Kind::Bc1, COLOR, |r| r.image_extent.height = 2),
        each("imageExtent-00208"),
    );
    add(
        "a row of 2 GiB",
        // One row: the buffer holds it.
        with(Kind::Rgba, COLOR, |r| {
            r.buffer_row_length = 1 << 29;
            r.image_extent.height = 1;
        }),
        each("pRegions-07277"),
    );
    add(
        "a buffer offset inside a texel",
        with(Kind::Rgba, COLOR, |r| r.buffer_offset = 2),
        each("pRegions-07273"),
    );
    add(
        "a depth copy at an offset that is not a multiple of 4",
        with(Kind::Depth16, DEPTH, |r| r.buffer_offset = 2),
        each("srcImage-04053"),
    );
    let mut samples = each("srcImage-00188");
    let to_image = each("dstImage-00179");
    samples[0] = to_image[0];
    samples[2] = to_image[2];
    add(
        "a multisampled image",
        with(Kind::Multisampled, COLOR, |_| {}),
        samples,
    );
    // The 1.3.239 layer does not check the row pitch.
    for c in &mut out {
        c.layer &= c.what != "a row of 2 GiB";
    }
    out
}

/// Records `region` through command `which` (0 to 3, as in [`Case::rules`]).
fn record(
    rec: &mut tuff::Recorder<'_, tuff::Outside>,
    which: usize,
    (buffer, image): (&tuff::Buffer, &tuff::Image),
    region: vk::BufferImageCopy,
    unchecked: bool,
) -> tuff::Result<()> {
    let region2 = [tuff::BufferImageCopy2::new()
        .buffer_offset(region.buffer_offset)
        .buffer_row_length(region.buffer_row_length)
        .buffer_image_height(region.buffer_image_height)
        .image_subresource(region.image_subresource)
        .image_offset(region.image_offset)
        .image_extent(region.image_extent)];
    let to_image = tuff::CopyBufferToImageInfo2::new(buffer, image)
        .dst_image_layout(DST)
        .regions(&region2);
    let to_buffer = tuff::CopyImageToBufferInfo2::new(image, buffer)
        .src_image_layout(SRC)
        .regions(&region2);
    unsafe {
        match (which, unchecked) {
            (0, false) => rec.copy_buffer_to_image(buffer, image, DST, &[region]),
            (0, true) => rec.copy_buffer_to_image_unchecked(buffer, image, DST, &[region]),
            (1, false) => rec.copy_image_to_buffer(image, SRC, buffer, &[region]),
            (1, true) => rec.copy_image_to_buffer_unchecked(image, SRC, buffer, &[region]),
            (2, false) => rec.copy_buffer_to_image2(&to_image),
            (2, true) => rec.copy_buffer_to_image2_unchecked(&to_image),
            (3, false) => rec.copy_image_to_buffer2(&to_buffer),
            _ => rec.copy_image_to_buffer2_unchecked(&to_buffer),
        }
    }
}

/// Every case through every command: the safe call names the case's rule, the
/// layer names it for the unchecked one; the unchanged region records silently.
#[test]
fn each_region_rule_is_checked_and_the_layer_agrees() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let images: Vec<_> = KINDS.iter().map(|k| (*k, image(&s, *k))).collect();
    let image_of = |kind| &images.iter().find(|(k, _)| *k == kind).expect("made").1 .0;
    let (buffer, _memory) = host_buffer(
        &s,
        1 << 16,
        vk::BufferUsageFlags::TRANSFER_SRC | vk::BufferUsageFlags::TRANSFER_DST,
    );
    let mut wrong = Vec::new();
    for case in cases() {
        let image = image_of(case.kind);
        for (which, rule) in case.rules.iter().enumerate() {
            if rule.is_empty() {
                continue;
            }
            let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
            let mut rec = cb
                .begin(&tuff::CommandBufferBeginInfo::new())
                .expect("begin");
            let safe = vuid(record(
                &mut rec,
                which,
                (&buffer, image),
                case.region,
                false,
            ));
            s.messages.take();
            s.messages.abort_on_error(true);
            let _ = record(&mut rec, which, (&buffer, image), case.region, true);
            s.messages.abort_on_error(false);
            let layer = s.messages.take();
            // The 1.3.239 layer names the rules of `vkCmdCopyImageToBuffer2` (its
            // info's and its regions') by the VUIDs of `vkCmdCopyImageToBuffer`.
            let alias = if which == 3 {
                rule.replace("VkCopyImageToBufferInfo2-", "vkCmdCopyImageToBuffer-")
                    .replace("VkBufferImageCopy2-", "VkBufferImageCopy-")
            } else {
                rule.to_string()
            };
            let errors: Vec<_> = layer.iter().filter(|m| m.starts_with("ERROR")).collect();
            let named = if case.layer {
                errors
                    .iter()
                    .any(|m| m.contains(rule) || m.contains(&alias))
            } else {
                errors.is_empty()
            };
            if safe != *rule || !named {
                wrong.push(format!(
                    "{} through command {which}: tuff said {safe}, expected {rule}; the layer said {:?}",
                    case.what,
                    layer
                        .iter()
                        .map(|m| m.split(']').next().unwrap_or(m))
                        .collect::<Vec<_>>()
                ));
            }
            rec.end().expect("end");
        }
    }
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
    // The unchanged regions record through every command.
    for (kind, (image, _)) in &images {
        let aspect = match kind {
            Kind::Depth16 | Kind::DepthStencil => DEPTH,
            _ => COLOR,
        };
        if *kind == Kind::Multisampled {
            continue;
        }
        // One recording per command: the copies to and from the image name
        // different layouts.
        for which in 0..4 {
            let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
            let mut rec = cb
                .begin(&tuff::CommandBufferBeginInfo::new())
                .expect("begin");
            let mut r = region(aspect);
            if *kind == Kind::OneD {
                r.image_extent.height = 1;
            }
            // A copy into the depth aspect of a float depth format reads depth values
            // from the buffer, which tuff cannot see: refused, and recorded through
            // `_unchecked` (never submitted), which the layer accepts.
            let float_depth = match (kind, which) {
                (Kind::DepthStencil, 0) => Some("VUID-vkCmdCopyBufferToImage-None-00214"),
                (Kind::DepthStencil, 2) => Some("VUID-VkCopyBufferToImageInfo2-None-00214"),
                _ => None,
            };
            if let Some(rule) = float_depth {
                let safe = record(&mut rec, which, (&buffer, image), r, false);
                assert_eq!(vuid(safe), rule, "{kind:?} through command {which}");
            }
            record(&mut rec, which, (&buffer, image), r, float_depth.is_some())
                .unwrap_or_else(|e| panic!("{kind:?} through command {which}: {e}"));
            rec.end().expect("end");
        }
    }
    assert_silent(&s.messages);
}

/// A buffer and an image bound to the same bytes of one allocation: a copy between
/// them is refused through every command (the unchecked copy is recorded, never
/// submitted).
#[test]
fn a_copy_between_a_buffer_and_an_image_in_the_same_memory_is_refused() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let d = &s.device;
    let image = d
        .create_image(
            &tuff::ImageCreateInfo::new()
                .image_type(vk::ImageType::TYPE_2D)
                .format(vk::Format::R8G8B8A8_UNORM)
                .extent(vk::Extent3D {
                    width: 8,
                    height: 8,
                    depth: 1,
                })
                .mip_levels(1)
                .array_layers(1)
                .samples(vk::SampleCountFlags::TYPE_1)
                .tiling(vk::ImageTiling::LINEAR)
                .usage(vk::ImageUsageFlags::TRANSFER_SRC | vk::ImageUsageFlags::TRANSFER_DST),
        )
        .expect("image");
    let buffer = d
        .create_buffer(
            &tuff::BufferCreateInfo::new()
                .size(256)
                .usage(vk::BufferUsageFlags::TRANSFER_SRC | vk::BufferUsageFlags::TRANSFER_DST),
        )
        .expect("buffer");
    let image_needs = d
        .get_image_memory_requirements(&image)
        .expect("image requirements");
    let buffer_needs = d
        .get_buffer_memory_requirements(&buffer)
        .expect("buffer requirements");
    let memory = d
        .allocate_memory(
            &tuff::MemoryAllocateInfo::new()
                .allocation_size(image_needs.size.max(buffer_needs.size))
                .memory_type_index(s.memory_type(
                    image_needs.memory_type_bits & buffer_needs.memory_type_bits,
                    vk::MemoryPropertyFlags::empty(),
                )),
        )
        .expect("memory");
    d.bind_image_memory(&image, &memory, 0).expect("bind image");
    d.bind_buffer_memory(&buffer, &memory, 0)
        .expect("bind buffer");
    let rules = [
        "VUID-vkCmdCopyBufferToImage-pRegions-00173",
        "VUID-vkCmdCopyImageToBuffer-pRegions-00184",
        "VUID-VkCopyBufferToImageInfo2-pRegions-00173",
        "VUID-VkCopyImageToBufferInfo2-pRegions-00184",
    ];
    let mut said = Vec::new();
    for (which, rule) in rules.iter().enumerate() {
        let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
        let mut rec = cb
            .begin(&tuff::CommandBufferBeginInfo::new())
            .expect("begin");
        let r = region(COLOR);
        assert_eq!(
            vuid(record(&mut rec, which, (&buffer, &image), r, false)),
            *rule
        );
        s.messages.take();
        s.messages.abort_on_error(true);
        let _ = record(&mut rec, which, (&buffer, &image), r, true);
        s.messages.abort_on_error(false);
        said.push(s.messages.take());
        rec.end().expect("end");
    }
    // The 1.3.239 layer does not check this rule: it stays silent (the command
    // buffer is never submitted), and tuff's error alone proves the rule.
    assert!(
        said.iter().all(|m| m.is_empty()),
        "the layer now checks the overlap: {said:?}"
    );
    assert_silent(&s.messages);
}

/// An image of `format` with `usage`, bound to memory.
fn clear_target(
    s: &Setup,
    format: vk::Format,
    usage: vk::ImageUsageFlags,
) -> (tuff::Image, tuff::DeviceMemory) {
    let image = s
        .device
        .create_image(
            &tuff::ImageCreateInfo::new()
                .image_type(vk::ImageType::TYPE_2D)
                .format(format)
                .extent(vk::Extent3D {
                    width: 8,
                    height: 8,
                    depth: 1,
                })
                .mip_levels(1)
                .array_layers(1)
                .samples(vk::SampleCountFlags::TYPE_1)
                .usage(usage),
        )
        .unwrap_or_else(|e| panic!("a {format:?} image: {e}"));
    let memory = s.bind_image(&image);
    (image, memory)
}

/// Each rule of a clear outside a render pass: the safe call names it, the layer
/// names it for the unchecked one (which it skips); correct clears of a colour, a
/// depth and a depth/stencil image record silently.
#[test]
fn clears_check_their_image_and_the_layer_agrees() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let dst = vk::ImageUsageFlags::TRANSFER_DST;
    let sampled = vk::ImageUsageFlags::SAMPLED;
    let (rgba, _m0) = clear_target(&s, vk::Format::R8G8B8A8_UNORM, dst);
    let (bc1, _m1) = clear_target(&s, vk::Format::BC1_RGBA_UNORM_BLOCK, dst);
    let (d16, _m2) = clear_target(&s, vk::Format::D16_UNORM, dst);
    let (ds, _m3) = clear_target(&s, vk::Format::D32_SFLOAT_S8_UINT, dst);
    let (d16_sampled, _m4) = clear_target(&s, vk::Format::D16_UNORM, sampled);
    let (ds_sampled, _m5) = clear_target(&s, vk::Format::D32_SFLOAT_S8_UINT, sampled);
    let range = |aspect_mask, base_mip_level, base_array_layer| vk::ImageSubresourceRange {
        aspect_mask,
        base_mip_level,
        level_count: vk::REMAINING_MIP_LEVELS,
        base_array_layer,
        layer_count: vk::REMAINING_ARRAY_LAYERS,
    };
    let attachment = vk::ImageLayout::DEPTH_STENCIL_ATTACHMENT_OPTIMAL;
    // (rule, a colour clear (else a depth/stencil one), image, layout, range)
    let cases = [
        (
            "VUID-vkCmdClearColorImage-image-00007",
            true,
            &d16,
            DST,
            range(DEPTH, 0, 0),
        ),
        (
            "VUID-vkCmdClearColorImage-image-00007",
            true,
            &bc1,
            DST,
            range(COLOR, 0, 0),
        ),
        (
            "VUID-vkCmdClearColorImage-aspectMask-02498",
            true,
            &rgba,
            DST,
            range(DEPTH, 0, 0),
        ),
        (
            "VUID-vkCmdClearColorImage-baseMipLevel-01470",
            true,
            &rgba,
            DST,
            range(COLOR, 1, 0),
        ),
        (
            "VUID-vkCmdClearColorImage-baseArrayLayer-01472",
            true,
            &rgba,
            DST,
            range(COLOR, 0, 1),
        ),
        (
            "VUID-vkCmdClearDepthStencilImage-image-00014",
            false,
            &rgba,
            DST,
            range(COLOR, 0, 0),
        ),
        (
            "VUID-vkCmdClearDepthStencilImage-aspectMask-02824",
            false,
            &ds,
            DST,
            range(COLOR | DEPTH, 0, 0),
        ),
        (
            "VUID-vkCmdClearDepthStencilImage-image-02825",
            false,
            &d16,
            DST,
            range(STENCIL, 0, 0),
        ),
        (
            "VUID-vkCmdClearDepthStencilImage-imageLayout-00012",
            false,
            &ds,
            attachment,
            range(DEPTH, 0, 0),
        ),
        (
            "VUID-vkCmdClearDepthStencilImage-pRanges-02659",
            false,
            &ds_sampled,
            DST,
            range(STENCIL, 0, 0),
        ),
        (
            "VUID-vkCmdClearDepthStencilImage-pRanges-02660",
            false,
            &d16_sampled,
            DST,
            range(DEPTH, 0, 0),
        ),
        (
            "VUID-vkCmdClearDepthStencilImage-baseMipLevel-01474",
            false,
            &d16,
            DST,
            range(DEPTH, 1, 0),
        ),
        (
            "VUID-vkCmdClearDepthStencilImage-baseArrayLayer-01476",
            false,
            &d16,
            DST,
            range(DEPTH, 0, 1),
        ),
    ];
    let color = vk::ClearColorValue::default();
    let depth = vk::ClearDepthStencilValue::default();
    let mut wrong = Vec::new();
    for (rule, is_color, image, layout, range) in cases {
        let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
        let mut rec = cb
            .begin(&tuff::CommandBufferBeginInfo::new())
            .expect("begin");
        let ranges = [range];
        let safe = vuid(if is_color {
            rec.clear_color_image(image, layout, &color, &ranges)
        } else {
            rec.clear_depth_stencil_image(image, layout, &depth, &ranges)
        });
        s.messages.take();
        s.messages.abort_on_error(true);
        // SAFETY: the layer skips the call, which breaks only the rule under test;
        // the command buffer is never submitted.
        let _ = unsafe {
            if is_color {
                rec.clear_color_image_unchecked(image, layout, &color, &ranges)
            } else {
                rec.clear_depth_stencil_image_unchecked(image, layout, &depth, &ranges)
            }
        };
        s.messages.abort_on_error(false);
        let layer = s.messages.take();
        if safe != rule || !layer.iter().any(|m| m.contains(rule)) {
            wrong.push(format!(
                "{rule}: tuff said {safe}; the layer said {layer:?}"
            ));
        }
        drop(rec);
    }
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
    let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let mut rec = cb
        .begin(&tuff::CommandBufferBeginInfo::new())
        .expect("begin");
    rec.clear_color_image(&rgba, DST, &color, &[range(COLOR, 0, 0)])
        .expect("a colour clear");
    rec.clear_depth_stencil_image(&d16, DST, &depth, &[range(DEPTH, 0, 0)])
        .expect("a depth clear");
    rec.clear_depth_stencil_image(&ds, DST, &depth, &[range(DEPTH | STENCIL, 0, 0)])
        .expect("a depth/stencil clear");
    rec.end().expect("end");
    assert_silent(&s.messages);
}
