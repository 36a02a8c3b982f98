//! Transfer commands: buffer and image copies, fills and updates, each region against
//! the resources it names, their usage, formats and protection.

use super::buffer::{check_buffer_use, used_buffer};
use super::{check, pool_family, refuse};
use crate::handles::{Device, *};
use crate::recorder::{Recorder, Scope};
use crate::state::ImageRecord;
use crate::state::PoolFamily;
use crate::structs::*;
use crate::{Handle, Result};
use ash::vk;
use smallvec::SmallVec;

const FILL_PROTECTED: Protection = Protection {
    protected_src: "",
    protected_dst: "VUID-vkCmdFillBuffer-commandBuffer-01811",
    unprotected_dst: "VUID-vkCmdFillBuffer-commandBuffer-01812",
};

const UPDATE_PROTECTED: Protection = Protection {
    protected_src: "",
    protected_dst: "VUID-vkCmdUpdateBuffer-commandBuffer-01813",
    unprotected_dst: "VUID-vkCmdUpdateBuffer-commandBuffer-01814",
};

/// The checks of `vkCmdFillBuffer` that keep the fill inside the buffer.
pub(crate) fn cmd_fill_buffer_checks<S: Scope>(
    recorder: &Recorder<'_, S>,
    dst_buffer: &Buffer,
    dst_offset: vk::DeviceSize,
    size: vk::DeviceSize,
) -> Result<()> {
    let dst = used_buffer(
        recorder,
        dst_buffer,
        vk::BufferUsageFlags::TRANSFER_DST,
        (
            "VUID-vkCmdFillBuffer-dstBuffer-00029",
            "VUID-vkCmdFillBuffer-dstBuffer-00031",
        ),
        &"dstBuffer",
    )?;
    let protected = dst.flags.contains(vk::BufferCreateFlags::PROTECTED);
    check_protected(recorder, None, protected, &FILL_PROTECTED)?;
    if dst_offset >= dst.size {
        refuse("VUID-vkCmdFillBuffer-dstOffset-00024", format!("dstOffset must be less than the size of dstBuffer (dstOffset = {dst_offset}, size of dstBuffer = {})", dst.size))?;
    }
    if dst_offset % 4 != 0 {
        refuse(
            "VUID-vkCmdFillBuffer-dstOffset-00025",
            format!("dstOffset must be a multiple of 4 (dstOffset = {dst_offset})"),
        )?;
    }
    if size != vk::WHOLE_SIZE {
        if size == 0 {
            refuse(
                "VUID-vkCmdFillBuffer-size-00026",
                "size must be greater than 0 (size = 0)",
            )?;
        }
        if size > dst.size - dst_offset {
            refuse("VUID-vkCmdFillBuffer-size-00027", format!("size must be at most the size of dstBuffer minus dstOffset (size = {size}, dstOffset = {dst_offset}, size of dstBuffer = {})", dst.size))?;
        }
        if size % 4 != 0 {
            refuse(
                "VUID-vkCmdFillBuffer-size-00028",
                format!("size must be a multiple of 4 (size = {size})"),
            )?;
        }
    }
    Ok(())
}

/// The checks of `vkCmdUpdateBuffer` that keep the update inside the buffer.
pub(crate) fn cmd_update_buffer_checks<S: Scope>(
    recorder: &Recorder<'_, S>,
    dst_buffer: &Buffer,
    dst_offset: vk::DeviceSize,
    data: &[u8],
) -> Result<()> {
    let dst = used_buffer(
        recorder,
        dst_buffer,
        vk::BufferUsageFlags::TRANSFER_DST,
        (
            "VUID-vkCmdUpdateBuffer-dstBuffer-00034",
            "VUID-vkCmdUpdateBuffer-dstBuffer-00035",
        ),
        &"dstBuffer",
    )?;
    let protected = dst.flags.contains(vk::BufferCreateFlags::PROTECTED);
    check_protected(recorder, None, protected, &UPDATE_PROTECTED)?;
    let len = data.len() as u64;
    if dst_offset >= dst.size {
        refuse("VUID-vkCmdUpdateBuffer-dstOffset-00032", format!("dstOffset must be less than the size of dstBuffer (dstOffset = {dst_offset}, size of dstBuffer = {})", dst.size))?;
    }
    if len > dst.size - dst_offset {
        refuse("VUID-vkCmdUpdateBuffer-dataSize-00033", format!("dataSize must be at most the size of dstBuffer minus dstOffset (dataSize = {len}, dstOffset = {dst_offset}, size of dstBuffer = {})", dst.size))?;
    }
    if dst_offset % 4 != 0 {
        refuse(
            "VUID-vkCmdUpdateBuffer-dstOffset-00036",
            format!("dstOffset must be a multiple of 4 (dstOffset = {dst_offset})"),
        )?;
    }
    if len > 65536 {
        refuse(
            "VUID-vkCmdUpdateBuffer-dataSize-00037",
            format!("dataSize must be at most 65536 (dataSize = {len})"),
        )?;
    }
    if len % 4 != 0 {
        refuse(
            "VUID-vkCmdUpdateBuffer-dataSize-00038",
            format!("dataSize must be a multiple of 4 (dataSize = {len})"),
        )?;
    }
    Ok(())
}

/// The rules of a copy between two buffers, by field: `vkCmdCopyBuffer`'s and
/// `vkCmdCopyBuffer2`'s differ only in their names.
pub(crate) struct BufferCopyRules {
    /// The source has the transfer-source usage.
    pub src_usage: &'static str,
    /// The source is bound to memory (or sparse).
    pub src_bound: &'static str,
    /// The destination has the transfer-destination usage.
    pub dst_usage: &'static str,
    /// The destination is bound to memory (or sparse).
    pub dst_bound: &'static str,
    /// Each region's source offset lies inside the source.
    pub src_offset: &'static str,
    /// Each region's destination offset lies inside the destination.
    pub dst_offset: &'static str,
    /// Each region's size fits the source after its offset.
    pub src_size: &'static str,
    /// Each region's size fits the destination after its offset.
    pub dst_size: &'static str,
    /// Each region's size is not zero.
    pub size: &'static str,
    /// No source range overlaps a destination range.
    pub overlap: &'static str,
    /// The protected-memory rules.
    pub protected: Protection,
}

const COPY_BUFFER: BufferCopyRules = BufferCopyRules {
    src_usage: "VUID-vkCmdCopyBuffer-srcBuffer-00118",
    src_bound: "VUID-vkCmdCopyBuffer-srcBuffer-00119",
    dst_usage: "VUID-vkCmdCopyBuffer-dstBuffer-00120",
    dst_bound: "VUID-vkCmdCopyBuffer-dstBuffer-00121",
    src_offset: "VUID-vkCmdCopyBuffer-srcOffset-00113",
    dst_offset: "VUID-vkCmdCopyBuffer-dstOffset-00114",
    src_size: "VUID-vkCmdCopyBuffer-size-00115",
    dst_size: "VUID-vkCmdCopyBuffer-size-00116",
    size: "VUID-VkBufferCopy-size-01988",
    overlap: "VUID-vkCmdCopyBuffer-pRegions-00117",
    protected: Protection {
        protected_src: "VUID-vkCmdCopyBuffer-commandBuffer-01822",
        protected_dst: "VUID-vkCmdCopyBuffer-commandBuffer-01823",
        unprotected_dst: "VUID-vkCmdCopyBuffer-commandBuffer-01824",
    },
};

const COPY_BUFFER2: BufferCopyRules = BufferCopyRules {
    src_usage: "VUID-VkCopyBufferInfo2-srcBuffer-00118",
    src_bound: "VUID-VkCopyBufferInfo2-srcBuffer-00119",
    dst_usage: "VUID-VkCopyBufferInfo2-dstBuffer-00120",
    dst_bound: "VUID-VkCopyBufferInfo2-dstBuffer-00121",
    src_offset: "VUID-VkCopyBufferInfo2-srcOffset-00113",
    dst_offset: "VUID-VkCopyBufferInfo2-dstOffset-00114",
    src_size: "VUID-VkCopyBufferInfo2-size-00115",
    dst_size: "VUID-VkCopyBufferInfo2-size-00116",
    size: "VUID-VkBufferCopy2-size-01988",
    overlap: "VUID-VkCopyBufferInfo2-pRegions-00117",
    protected: Protection {
        protected_src: "VUID-vkCmdCopyBuffer2-commandBuffer-01822",
        protected_dst: "VUID-vkCmdCopyBuffer2-commandBuffer-01823",
        unprotected_dst: "VUID-vkCmdCopyBuffer2-commandBuffer-01824",
    },
};

/// The checks of `vkCmdCopyBuffer` that keep the copy inside both buffers: a copy out
/// of range reads or writes memory the buffers do not own.
pub(crate) fn cmd_copy_buffer_checks<S: Scope>(
    recorder: &Recorder<'_, S>,
    src_buffer: &Buffer,
    dst_buffer: &Buffer,
    regions: &[vk::BufferCopy],
) -> Result<()> {
    let regions = regions.iter().map(|r| (r.src_offset, r.dst_offset, r.size));
    let buffers = (src_buffer.raw(), dst_buffer.raw());
    check_buffer_copy(recorder, buffers, regions, &COPY_BUFFER)
}

/// As [`cmd_copy_buffer_checks`], for `vkCmdCopyBuffer2`.
pub(crate) fn cmd_copy_buffer2_checks<S: Scope>(
    recorder: &Recorder<'_, S>,
    info: &CopyBufferInfo2<'_>,
) -> Result<()> {
    let raw = info.as_raw();
    // SAFETY: the safe struct stores the array with its length.
    let regions = unsafe { crate::state::raw_slice(raw.p_regions, raw.region_count) };
    let regions = regions.iter().map(|r| (r.src_offset, r.dst_offset, r.size));
    let buffers = (raw.src_buffer, raw.dst_buffer);
    check_buffer_copy(recorder, buffers, regions, &COPY_BUFFER2)
}

/// A copy between two buffers, its regions read into one shape (source offset,
/// destination offset, size), against both buffers' records.
fn check_buffer_copy<S: Scope>(
    recorder: &Recorder<'_, S>,
    (src_buffer, dst_buffer): (vk::Buffer, vk::Buffer),
    regions: impl Iterator<Item = (u64, u64, u64)> + Clone,
    rules: &BufferCopyRules,
) -> Result<()> {
    let device = recorder.device();
    let record = |b| {
        device.live().buffer(b).ok_or(crate::Error::Misuse(
            "the buffer was not created through the wrappers, so its size is unknown",
        ))
    };
    let (src, dst) = (record(src_buffer)?, record(dst_buffer)?);
    let usage = vk::BufferUsageFlags::TRANSFER_SRC;
    check_buffer_use(
        &src,
        usage,
        (rules.src_usage, rules.src_bound),
        &"srcBuffer",
    )?;
    let usage = vk::BufferUsageFlags::TRANSFER_DST;
    check_buffer_use(
        &dst,
        usage,
        (rules.dst_usage, rules.dst_bound),
        &"dstBuffer",
    )?;
    let protected =
        |b: &crate::state::BufferRecord| b.flags.contains(vk::BufferCreateFlags::PROTECTED);
    check_protected(
        recorder,
        Some(protected(&src)),
        protected(&dst),
        &rules.protected,
    )?;
    for (i, (src_offset, dst_offset, size)) in regions.clone().enumerate() {
        if size == 0 {
            refuse(
                rules.size,
                format!("pRegions[{i}].size must be greater than 0 (size = 0)"),
            )?;
        }
        if src_offset >= src.size {
            refuse(
                rules.src_offset,
                format!("pRegions[{i}].srcOffset must be less than the size of srcBuffer (srcOffset = {src_offset}, size of srcBuffer = {})", src.size),
            )?;
        }
        if dst_offset >= dst.size {
            refuse(
                rules.dst_offset,
                format!("pRegions[{i}].dstOffset must be less than the size of dstBuffer (dstOffset = {dst_offset}, size of dstBuffer = {})", dst.size),
            )?;
        }
        if size > src.size - src_offset {
            refuse(
                rules.src_size,
                format!("pRegions[{i}].size must be at most the size of srcBuffer minus srcOffset (size = {size}, srcOffset = {src_offset}, size of srcBuffer = {})", src.size),
            )?;
        }
        if size > dst.size - dst_offset {
            refuse(
                rules.dst_size,
                format!("pRegions[{i}].size must be at most the size of dstBuffer minus dstOffset (size = {size}, dstOffset = {dst_offset}, size of dstBuffer = {})", dst.size),
            )?;
        }
    }
    if src_buffer == dst_buffer {
        // Every source range against every destination range, the region's own
        // included; the offsets and sizes are in range, so the ends do not overflow.
        for (i, (a0, _, a)) in regions.clone().enumerate() {
            for (j, (_, b0, b)) in regions.clone().enumerate() {
                let (a1, b1) = (a0 + a, b0 + b);
                if a0 < b1 && b0 < a1 {
                    refuse(
                        rules.overlap,
                        format!("the source of pRegions[{i}] ({a0}..{a1}) overlaps the destination of pRegions[{j}] ({b0}..{b1}) in the same buffer"),
                    )?;
                }
            }
        }
    }
    Ok(())
}

/// The protected-memory rules of a transfer command that writes one buffer or image
/// and reads at most one other, by field.
pub(crate) struct Protection {
    /// An unprotected command buffer: the source is not protected (empty where the
    /// command reads no buffer or image).
    pub protected_src: &'static str,
    /// An unprotected command buffer: the destination is not protected.
    pub protected_dst: &'static str,
    /// A protected command buffer: the destination is not unprotected.
    pub unprotected_dst: &'static str,
}

/// Refuses a transfer that mixes protected and unprotected memory where the device
/// lacks `protectedNoFault`: an unprotected command buffer reading or writing a
/// protected resource, or a protected one writing an unprotected resource. `src` and
/// `dst` say whether each resource is protected (`src` is `None` for a command that
/// reads none). Without protected objects (a device without protectedMemory can
/// make none) nothing is asked of the driver.
pub(crate) fn check_protected<S: Scope>(
    recorder: &Recorder<'_, S>,
    src: Option<bool>,
    dst: bool,
    rules: &Protection,
) -> Result<()> {
    let in_protected = pool_family(recorder).protected;
    let src = src.unwrap_or(false);
    let breaks = if in_protected { !dst } else { src || dst };
    if !breaks || super::render_pass::protected_no_fault(recorder.device()) {
        return Ok(());
    }
    if in_protected {
        refuse(
            rules.unprotected_dst,
            "a protected command buffer writes an unprotected destination, and the device lacks protectedNoFault",
        )
    } else if src {
        refuse(
            rules.protected_src,
            "an unprotected command buffer reads a protected source, and the device lacks protectedNoFault",
        )
    } else {
        refuse(
            rules.protected_dst,
            "an unprotected command buffer writes a protected destination, and the device lacks protectedNoFault",
        )
    }
}

/// The byte just past the last one that a buffer-image copy region reaches in its
/// buffer, by Buffer and Image Addressing: rows of `bufferRowLength` (or the
/// extent's width) texels, `bufferImageHeight` (or its height) rows a slice, one
/// slice per depth and per layer, in texel blocks of the aspect's size. `None` when
/// the format or aspect is not one the registry describes (an aspect mask of more
/// than one aspect), which another rule refuses.
#[allow(clippy::too_many_arguments)]
pub(crate) fn buffer_image_end(
    format: vk::Format,
    aspect: vk::ImageAspectFlags,
    offset: vk::DeviceSize,
    row_length: u32,
    image_height: u32,
    extent: vk::Extent3D,
    layers: u32,
) -> Option<u64> {
    let (bytes, [bw, bh, bd]) = crate::formats::block(format, aspect)?;
    let blocks = |texels: u32, per: u32| u64::from(texels).div_ceil(u64::from(per.max(1)));
    let row = blocks(
        if row_length == 0 {
            extent.width
        } else {
            row_length
        },
        bw,
    );
    let height = blocks(
        if image_height == 0 {
            extent.height
        } else {
            image_height
        },
        bh,
    );
    let (w, h) = (blocks(extent.width, bw), blocks(extent.height, bh));
    let slices = blocks(extent.depth, bd).saturating_mul(u64::from(layers));
    if w == 0 || h == 0 || slices == 0 {
        return Some(offset);
    }
    // A sum past u64 is past any buffer.
    let last_row = (slices - 1)
        .checked_mul(height)
        .and_then(|r| r.checked_add(h - 1))?;
    let texels = last_row.checked_mul(row).and_then(|t| t.checked_add(w));
    Some(
        texels
            .and_then(|t| t.checked_mul(u64::from(bytes)))
            .and_then(|b| b.checked_add(offset))
            .unwrap_or(u64::MAX),
    )
}

/// Refuses a buffer-image copy whose regions reach past the buffer's end (the
/// buffer's size and the image's format as the device recorded them).
#[allow(clippy::too_many_arguments)]
fn check_buffer_image_regions(
    device: &Device,
    buffer: vk::Buffer,
    image: vk::Image,
    regions: impl Iterator<Item = (u64, u32, u32, vk::ImageSubresourceLayers, vk::Extent3D)>,
    vuid: &'static str,
) -> Result<()> {
    let (Some(b), Some(i)) = (device.live().buffer(buffer), device.live().image(image)) else {
        return Ok(());
    };
    for (n, (offset, row_length, image_height, subresource, extent)) in regions.enumerate() {
        let end = buffer_image_end(
            i.format,
            subresource.aspect_mask,
            offset,
            row_length,
            image_height,
            extent,
            subresource.layer_count,
        );
        if let Some(end) = end.filter(|e| *e > b.size) {
            refuse(
                vuid,
                format!(
                    "pRegions[{n}] reaches byte {end} of a buffer of {} bytes (bufferOffset = {offset}, bufferRowLength = {row_length}, bufferImageHeight = {image_height}, imageExtent = {}x{}x{}, layerCount = {})",
                    b.size, extent.width, extent.height, extent.depth, subresource.layer_count
                ),
            )?;
        }
    }
    Ok(())
}

/// The checks of a copy between `buffer` and `image` that memory safety needs:
/// each region against the image (its type, format, texel blocks, subresources,
/// the queue family's granularity), protected memory, the overlap of the two
/// bindings, and the buffer's end. `regions` are either version's, read into one
/// shape here.
fn check_buffer_image_copy<'r, S: Scope, R: 'r>(
    recorder: &Recorder<'_, S>,
    (buffer, image): (vk::Buffer, vk::Image),
    regions: &'r [R],
    rules: &Rules,
) -> Result<()>
where
    Region: From<&'r R>,
{
    let regions: SmallVec<[Region; 4]> = regions.iter().map(Region::from).collect();
    let device = recorder.device();
    let family = pool_family(recorder);
    let image_record = device.live().image(image);
    if let Some(record) = &image_record {
        check_regions(device, record, family, regions.iter().copied(), rules)?;
        if rules.to_image {
            check_depth_values(record, &regions, rules)?;
        }
    }
    let buffer_protected = device
        .live()
        .buffer(buffer)
        .is_some_and(|b| b.flags.contains(vk::BufferCreateFlags::PROTECTED));
    let image_protected =
        image_record.is_some_and(|i| i.flags.contains(vk::ImageCreateFlags::PROTECTED));
    let (src, dst) = if rules.to_image {
        (buffer_protected, image_protected)
    } else {
        (image_protected, buffer_protected)
    };
    check_protected(recorder, Some(src), dst, &rules.protected)?;
    check_overlap(device, (buffer, image), &regions, rules)?;
    check_buffer_image_regions(
        device,
        buffer,
        image,
        regions.iter().map(|r| {
            (
                r.offset,
                r.row_length,
                r.image_height,
                r.subresource,
                r.extent,
            )
        }),
        rules.range,
    )
}

/// Refuses a copy from a buffer into an image that breaks a rule of its regions.
pub(crate) fn cmd_copy_buffer_to_image_checks<S: Scope>(
    recorder: &Recorder<'_, S>,
    src_buffer: &Buffer,
    dst_image: &Image,
    regions: &[vk::BufferImageCopy],
) -> Result<()> {
    let copy = (src_buffer.raw(), dst_image.raw());
    check_buffer_image_copy(recorder, copy, regions, &TO_IMAGE)
}

/// Refuses a copy from an image into a buffer that breaks a rule of its regions.
pub(crate) fn cmd_copy_image_to_buffer_checks<S: Scope>(
    recorder: &Recorder<'_, S>,
    src_image: &Image,
    dst_buffer: &Buffer,
    regions: &[vk::BufferImageCopy],
) -> Result<()> {
    let copy = (dst_buffer.raw(), src_image.raw());
    check_buffer_image_copy(recorder, copy, regions, &TO_BUFFER)
}

/// As [`cmd_copy_buffer_to_image_checks`], for `vkCmdCopyBufferToImage2`.
pub(crate) fn cmd_copy_buffer_to_image2_checks<S: Scope>(
    recorder: &Recorder<'_, S>,
    info: &CopyBufferToImageInfo2<'_>,
) -> Result<()> {
    let raw = info.as_raw();
    // SAFETY: the safe struct stores the array with its length.
    let regions = unsafe { crate::state::raw_slice(raw.p_regions, raw.region_count) };
    check_buffer_image_copy(
        recorder,
        (raw.src_buffer, raw.dst_image),
        regions,
        &TO_IMAGE2,
    )
}

/// As [`cmd_copy_image_to_buffer_checks`], for `vkCmdCopyImageToBuffer2`.
pub(crate) fn cmd_copy_image_to_buffer2_checks<S: Scope>(
    recorder: &Recorder<'_, S>,
    info: &CopyImageToBufferInfo2<'_>,
) -> Result<()> {
    let raw = info.as_raw();
    // SAFETY: the safe struct stores the array with its length.
    let regions = unsafe { crate::state::raw_slice(raw.p_regions, raw.region_count) };
    check_buffer_image_copy(
        recorder,
        (raw.dst_buffer, raw.src_image),
        regions,
        &TO_BUFFER2,
    )
}

/// The rules of one buffer-image copy command, by what they check; `""` where the
/// command has no such rule.
pub(crate) struct Rules {
    /// A 1D image: `imageOffset.y` 0 and `imageExtent.height` 1.
    pub one_d: &'static str,
    /// A 1D or 2D image: `imageOffset.z` 0 and `imageExtent.depth` 1.
    pub flat: &'static str,
    /// A 3D image: `baseArrayLayer` 0 and `layerCount` 1.
    pub layers_3d: &'static str,
    /// `imageSubresource.mipLevel` below the image's level count.
    pub mip: &'static str,
    /// `imageOffset.x` and its sum with the width inside the subresource.
    pub x_range: &'static str,
    /// `imageOffset.y` and its sum with the height inside the subresource.
    pub y_range: &'static str,
    /// `imageOffset.z` and its sum with the depth inside the subresource.
    pub z_range: &'static str,
    /// The region inside the subresource.
    pub contained: &'static str,
    /// `bufferRowLength` a multiple of the texel block width.
    pub row_block: &'static str,
    /// `bufferImageHeight` a multiple of the texel block height.
    pub height_block: &'static str,
    /// `imageOffset` a multiple of the texel block extent (x, y, z).
    pub offset_block: [&'static str; 3],
    /// `imageExtent` a multiple of the texel block extent unless it reaches the
    /// subresource's edge (width, height, depth).
    pub extent_block: [&'static str; 3],
    /// `imageSubresource.aspectMask` an aspect the image has.
    pub aspect: &'static str,
    /// A two-plane format: PLANE_0 or PLANE_1.
    pub two_planes: &'static str,
    /// A three-plane format: PLANE_0, PLANE_1 or PLANE_2.
    pub three_planes: &'static str,
    /// `bufferRowLength` in bytes at most 2^31-1.
    pub row_pitch: &'static str,
    /// `bufferOffset` a multiple of the texel block size.
    pub offset_size: &'static str,
    /// Depth/stencil: `bufferOffset` a multiple of 4.
    pub offset_depth: &'static str,
    /// The image has one sample.
    pub samples: &'static str,
    /// The image's format features hold `features`.
    pub features: (&'static str, vk::FormatFeatureFlags),
    /// A queue family without graphics or compute: `bufferOffset` a multiple of 4.
    pub transfer_offset: &'static str,
    /// The queue family's image transfer granularity.
    pub granularity: &'static str,
    /// A queue family without graphics: no depth or stencil aspect.
    pub no_graphics_depth: &'static str,
    /// `bufferRowLength` 0 or at least the width.
    pub row_length: &'static str,
    /// `bufferImageHeight` 0 or at least the height.
    pub image_height: &'static str,
    /// `aspectMask` one bit.
    pub one_aspect: &'static str,
    /// The protected-memory rules, the buffer or image read as the source.
    pub protected: Protection,
    /// The buffer's and the image's memory do not overlap.
    pub overlap: &'static str,
    /// Each region's buffer range inside the buffer.
    pub range: &'static str,
    /// Whether the copy writes the image (else the buffer).
    pub to_image: bool,
    /// Depth values read from the buffer lie in [0,1] (empty for a copy into a
    /// buffer).
    pub depth_values: &'static str,
}

/// No rule: the base of a command that checks some of these (`..NO_RULES`).
pub(crate) const NO_RULES: Rules = Rules {
    one_d: "",
    flat: "",
    layers_3d: "",
    mip: "",
    x_range: "",
    y_range: "",
    z_range: "",
    contained: "",
    row_block: "",
    height_block: "",
    offset_block: ["", "", ""],
    extent_block: ["", "", ""],
    aspect: "",
    two_planes: "",
    three_planes: "",
    row_pitch: "",
    offset_size: "",
    offset_depth: "",
    samples: "",
    features: ("", vk::FormatFeatureFlags::empty()),
    transfer_offset: "",
    granularity: "",
    no_graphics_depth: "",
    row_length: "",
    image_height: "",
    one_aspect: "",
    protected: Protection {
        protected_src: "",
        protected_dst: "",
        unprotected_dst: "",
    },
    overlap: "",
    range: "",
    to_image: false,
    depth_values: "",
};

/// `vkCmdCopyBufferToImage`.
pub(crate) const TO_IMAGE: Rules = Rules {
    one_d: "VUID-vkCmdCopyBufferToImage-srcImage-00199",
    flat: "VUID-vkCmdCopyBufferToImage-srcImage-00201",
    layers_3d: "VUID-vkCmdCopyBufferToImage-baseArrayLayer-00213",
    mip: "",
    x_range: "",
    y_range: "",
    z_range: "VUID-vkCmdCopyBufferToImage-imageOffset-00200",
    contained: "VUID-vkCmdCopyBufferToImage-pRegions-06217",
    row_block: "VUID-vkCmdCopyBufferToImage-bufferRowLength-00203",
    height_block: "VUID-vkCmdCopyBufferToImage-bufferImageHeight-00204",
    offset_block: [
        "VUID-vkCmdCopyBufferToImage-pRegions-07274",
        "VUID-vkCmdCopyBufferToImage-pRegions-07275",
        "VUID-vkCmdCopyBufferToImage-pRegions-07276",
    ],
    extent_block: [
        "VUID-vkCmdCopyBufferToImage-imageExtent-00207",
        "VUID-vkCmdCopyBufferToImage-imageExtent-00208",
        "VUID-vkCmdCopyBufferToImage-imageExtent-00209",
    ],
    aspect: "VUID-vkCmdCopyBufferToImage-aspectMask-00211",
    two_planes: "VUID-vkCmdCopyBufferToImage-pRegions-07740",
    three_planes: "VUID-vkCmdCopyBufferToImage-pRegions-07741",
    row_pitch: "VUID-vkCmdCopyBufferToImage-pRegions-07277",
    offset_size: "VUID-vkCmdCopyBufferToImage-pRegions-07273",
    offset_depth: "VUID-vkCmdCopyBufferToImage-srcImage-04053",
    samples: "VUID-vkCmdCopyBufferToImage-dstImage-00179",
    features: (
        "VUID-vkCmdCopyBufferToImage-dstImage-01997",
        vk::FormatFeatureFlags::TRANSFER_DST,
    ),
    transfer_offset: "VUID-vkCmdCopyBufferToImage-commandBuffer-07737",
    granularity: "VUID-vkCmdCopyBufferToImage-imageOffset-07738",
    no_graphics_depth: "VUID-vkCmdCopyBufferToImage-commandBuffer-07739",
    row_length: "VUID-VkBufferImageCopy-bufferRowLength-00195",
    image_height: "VUID-VkBufferImageCopy-bufferImageHeight-00196",
    one_aspect: "VUID-VkBufferImageCopy-aspectMask-00212",
    protected: Protection {
        protected_src: "VUID-vkCmdCopyBufferToImage-commandBuffer-01828",
        protected_dst: "VUID-vkCmdCopyBufferToImage-commandBuffer-01829",
        unprotected_dst: "VUID-vkCmdCopyBufferToImage-commandBuffer-01830",
    },
    overlap: "VUID-vkCmdCopyBufferToImage-pRegions-00173",
    range: "VUID-vkCmdCopyBufferToImage-pRegions-00171",
    to_image: true,
    depth_values: "VUID-vkCmdCopyBufferToImage-None-00214",
};

/// `vkCmdCopyImageToBuffer`.
pub(crate) const TO_BUFFER: Rules = Rules {
    one_d: "VUID-vkCmdCopyImageToBuffer-srcImage-00199",
    flat: "VUID-vkCmdCopyImageToBuffer-srcImage-00201",
    layers_3d: "VUID-vkCmdCopyImageToBuffer-baseArrayLayer-00213",
    mip: "",
    x_range: "",
    y_range: "",
    z_range: "VUID-vkCmdCopyImageToBuffer-imageOffset-00200",
    contained: "VUID-vkCmdCopyImageToBuffer-pRegions-06220",
    row_block: "VUID-vkCmdCopyImageToBuffer-bufferRowLength-00203",
    height_block: "VUID-vkCmdCopyImageToBuffer-bufferImageHeight-00204",
    offset_block: [
        "VUID-vkCmdCopyImageToBuffer-pRegions-07274",
        "VUID-vkCmdCopyImageToBuffer-pRegions-07275",
        "VUID-vkCmdCopyImageToBuffer-pRegions-07276",
    ],
    extent_block: [
        "VUID-vkCmdCopyImageToBuffer-imageExtent-00207",
        "VUID-vkCmdCopyImageToBuffer-imageExtent-00208",
        "VUID-vkCmdCopyImageToBuffer-imageExtent-00209",
    ],
    aspect: "VUID-vkCmdCopyImageToBuffer-aspectMask-00211",
    two_planes: "VUID-vkCmdCopyImageToBuffer-pRegions-07740",
    three_planes: "VUID-vkCmdCopyImageToBuffer-pRegions-07741",
    row_pitch: "VUID-vkCmdCopyImageToBuffer-pRegions-07277",
    offset_size: "VUID-vkCmdCopyImageToBuffer-pRegions-07273",
    offset_depth: "VUID-vkCmdCopyImageToBuffer-srcImage-04053",
    samples: "VUID-vkCmdCopyImageToBuffer-srcImage-00188",
    features: (
        "VUID-vkCmdCopyImageToBuffer-srcImage-01998",
        vk::FormatFeatureFlags::TRANSFER_SRC,
    ),
    transfer_offset: "VUID-vkCmdCopyImageToBuffer-commandBuffer-07746",
    granularity: "VUID-vkCmdCopyImageToBuffer-imageOffset-07747",
    no_graphics_depth: "",
    row_length: "VUID-VkBufferImageCopy-bufferRowLength-00195",
    image_height: "VUID-VkBufferImageCopy-bufferImageHeight-00196",
    one_aspect: "VUID-VkBufferImageCopy-aspectMask-00212",
    protected: Protection {
        protected_src: "VUID-vkCmdCopyImageToBuffer-commandBuffer-01831",
        protected_dst: "VUID-vkCmdCopyImageToBuffer-commandBuffer-01832",
        unprotected_dst: "VUID-vkCmdCopyImageToBuffer-commandBuffer-01833",
    },
    overlap: "VUID-vkCmdCopyImageToBuffer-pRegions-00184",
    range: "VUID-vkCmdCopyImageToBuffer-pRegions-00183",
    to_image: false,
    depth_values: "",
};

/// `vkCmdCopyBufferToImage2`.
pub(crate) const TO_IMAGE2: Rules = Rules {
    one_d: "VUID-VkCopyBufferToImageInfo2-srcImage-00199",
    flat: "VUID-VkCopyBufferToImageInfo2-srcImage-00201",
    layers_3d: "VUID-VkCopyBufferToImageInfo2-baseArrayLayer-00213",
    // Checked where the implicit-rule checks run, before these.
    mip: "",
    x_range: "",
    y_range: "",
    z_range: "",
    contained: "VUID-VkCopyBufferToImageInfo2-pRegions-00172",
    row_block: "VUID-VkCopyBufferToImageInfo2-bufferRowLength-00203",
    height_block: "VUID-VkCopyBufferToImageInfo2-bufferImageHeight-00204",
    offset_block: [
        "VUID-VkCopyBufferToImageInfo2-pRegions-07274",
        "VUID-VkCopyBufferToImageInfo2-pRegions-07275",
        "VUID-VkCopyBufferToImageInfo2-pRegions-07276",
    ],
    extent_block: [
        "VUID-VkCopyBufferToImageInfo2-imageExtent-00207",
        "VUID-VkCopyBufferToImageInfo2-imageExtent-00208",
        "VUID-VkCopyBufferToImageInfo2-imageExtent-00209",
    ],
    aspect: "",
    two_planes: "VUID-VkCopyBufferToImageInfo2-pRegions-07740",
    three_planes: "VUID-VkCopyBufferToImageInfo2-pRegions-07741",
    row_pitch: "VUID-VkCopyBufferToImageInfo2-pRegions-07277",
    offset_size: "VUID-VkCopyBufferToImageInfo2-pRegions-07273",
    offset_depth: "VUID-VkCopyBufferToImageInfo2-srcImage-04053",
    samples: "VUID-VkCopyBufferToImageInfo2-dstImage-00179",
    features: (
        "VUID-VkCopyBufferToImageInfo2-dstImage-01997",
        vk::FormatFeatureFlags::TRANSFER_DST,
    ),
    transfer_offset: "VUID-vkCmdCopyBufferToImage2-commandBuffer-07737",
    granularity: "VUID-vkCmdCopyBufferToImage2-imageOffset-07738",
    no_graphics_depth: "VUID-vkCmdCopyBufferToImage2-commandBuffer-07739",
    row_length: "VUID-VkBufferImageCopy2-bufferRowLength-00195",
    image_height: "VUID-VkBufferImageCopy2-bufferImageHeight-00196",
    one_aspect: "VUID-VkBufferImageCopy2-aspectMask-00212",
    protected: Protection {
        protected_src: "VUID-vkCmdCopyBufferToImage2-commandBuffer-01828",
        protected_dst: "VUID-vkCmdCopyBufferToImage2-commandBuffer-01829",
        unprotected_dst: "VUID-vkCmdCopyBufferToImage2-commandBuffer-01830",
    },
    overlap: "VUID-VkCopyBufferToImageInfo2-pRegions-00173",
    range: "VUID-VkCopyBufferToImageInfo2-pRegions-00171",
    to_image: true,
    depth_values: "VUID-VkCopyBufferToImageInfo2-None-00214",
};

/// `vkCmdCopyImageToBuffer2`.
pub(crate) const TO_BUFFER2: Rules = Rules {
    one_d: "VUID-VkCopyImageToBufferInfo2-srcImage-00199",
    flat: "VUID-VkCopyImageToBufferInfo2-srcImage-00201",
    layers_3d: "VUID-VkCopyImageToBufferInfo2-baseArrayLayer-00213",
    // Checked where the implicit-rule checks run, before these.
    mip: "",
    x_range: "",
    y_range: "",
    z_range: "",
    contained: "VUID-VkCopyImageToBufferInfo2-pRegions-00182",
    row_block: "VUID-VkCopyImageToBufferInfo2-bufferRowLength-00203",
    height_block: "VUID-VkCopyImageToBufferInfo2-bufferImageHeight-00204",
    offset_block: [
        "VUID-VkCopyImageToBufferInfo2-pRegions-07274",
        "VUID-VkCopyImageToBufferInfo2-pRegions-07275",
        "VUID-VkCopyImageToBufferInfo2-pRegions-07276",
    ],
    extent_block: [
        "VUID-VkCopyImageToBufferInfo2-imageExtent-00207",
        "VUID-VkCopyImageToBufferInfo2-imageExtent-00208",
        "VUID-VkCopyImageToBufferInfo2-imageExtent-00209",
    ],
    aspect: "",
    two_planes: "VUID-VkCopyImageToBufferInfo2-pRegions-07740",
    three_planes: "VUID-VkCopyImageToBufferInfo2-pRegions-07741",
    row_pitch: "VUID-VkCopyImageToBufferInfo2-pRegions-07277",
    offset_size: "VUID-VkCopyImageToBufferInfo2-pRegions-07273",
    offset_depth: "VUID-VkCopyImageToBufferInfo2-srcImage-04053",
    samples: "VUID-VkCopyImageToBufferInfo2-srcImage-00188",
    features: (
        "VUID-VkCopyImageToBufferInfo2-srcImage-01998",
        vk::FormatFeatureFlags::TRANSFER_SRC,
    ),
    transfer_offset: "VUID-vkCmdCopyImageToBuffer2-commandBuffer-07746",
    granularity: "VUID-vkCmdCopyImageToBuffer2-imageOffset-07747",
    no_graphics_depth: "",
    row_length: "VUID-VkBufferImageCopy2-bufferRowLength-00195",
    image_height: "VUID-VkBufferImageCopy2-bufferImageHeight-00196",
    one_aspect: "VUID-VkBufferImageCopy2-aspectMask-00212",
    protected: Protection {
        protected_src: "VUID-vkCmdCopyImageToBuffer2-commandBuffer-01831",
        protected_dst: "VUID-vkCmdCopyImageToBuffer2-commandBuffer-01832",
        unprotected_dst: "VUID-vkCmdCopyImageToBuffer2-commandBuffer-01833",
    },
    overlap: "VUID-VkCopyImageToBufferInfo2-pRegions-00184",
    range: "VUID-VkCopyImageToBufferInfo2-pRegions-00183",
    to_image: false,
    depth_values: "",
};

/// One region of a buffer-image copy.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Region {
    /// `bufferOffset`.
    pub offset: u64,
    /// `bufferRowLength`.
    pub row_length: u32,
    /// `bufferImageHeight`.
    pub image_height: u32,
    /// `imageSubresource`.
    pub subresource: vk::ImageSubresourceLayers,
    /// `imageOffset`.
    pub image_offset: vk::Offset3D,
    /// `imageExtent`.
    pub extent: vk::Extent3D,
}

impl Region {
    /// The end of the buffer bytes the region reaches, for an image of `format`
    /// (`None` where the region's numbers overflow, which another rule refuses).
    pub(crate) fn buffer_end(&self, format: vk::Format) -> Option<u64> {
        buffer_image_end(
            format,
            self.subresource.aspect_mask,
            self.offset,
            self.row_length,
            self.image_height,
            self.extent,
            self.subresource.layer_count,
        )
    }
}

impl From<&vk::BufferImageCopy> for Region {
    fn from(r: &vk::BufferImageCopy) -> Self {
        Region {
            offset: r.buffer_offset,
            row_length: r.buffer_row_length,
            image_height: r.buffer_image_height,
            subresource: r.image_subresource,
            image_offset: r.image_offset,
            extent: r.image_extent,
        }
    }
}

impl From<&vk::BufferImageCopy2<'_>> for Region {
    fn from(r: &vk::BufferImageCopy2<'_>) -> Self {
        Region {
            offset: r.buffer_offset,
            row_length: r.buffer_row_length,
            image_height: r.buffer_image_height,
            subresource: r.image_subresource,
            image_offset: r.image_offset,
            extent: r.image_extent,
        }
    }
}

/// The size of mip level `mip` of `image`'s aspect `aspect` (a plane of a
/// subsampled format is smaller).
fn level_extent(image: &ImageRecord, aspect: vk::ImageAspectFlags, mip: u32) -> [i64; 3] {
    let e = image.extent;
    let shrink = |v: u32| i64::from((v >> mip.min(31)).max(1));
    let (mut w, mut h, d) = (shrink(e.width), shrink(e.height), shrink(e.depth));
    let chroma_plane =
        aspect.intersects(vk::ImageAspectFlags::PLANE_1 | vk::ImageAspectFlags::PLANE_2);
    match crate::formats::chroma(image.format) {
        Some(420) if chroma_plane => {
            w = (w + 1) / 2;
            h = (h + 1) / 2;
        }
        Some(422) if chroma_plane => w = (w + 1) / 2,
        _ => {}
    }
    [w, h, d]
}

/// The checks of a copy between a buffer and `image` with `rules`, run by `family`.
pub(crate) fn check_regions(
    device: &Device,
    image: &ImageRecord,
    family: PoolFamily,
    regions: impl Iterator<Item = Region>,
    rules: &Rules,
) -> Result<()> {
    check(
        rules.samples,
        image.samples == vk::SampleCountFlags::TYPE_1,
        || format!("the image has {:?} samples", image.samples),
    )?;
    if !rules.features.0.is_empty() {
        let features = super::image::tiling_features(device, image)?;
        check(
            rules.features.0,
            features.contains(rules.features.1),
            || {
                format!(
                    "the {:?} features of {:?} lack {:?}",
                    image.tiling, image.format, rules.features.1
                )
            },
        )?;
    }
    let has = crate::formats::aspects(image.format).unwrap_or(vk::ImageAspectFlags::COLOR);
    let planes = [
        vk::ImageAspectFlags::PLANE_0,
        vk::ImageAspectFlags::PLANE_1,
        vk::ImageAspectFlags::PLANE_2,
    ]
    .iter()
    .filter(|p| has.contains(**p))
    .count();
    let depth_stencil = has.intersects(vk::ImageAspectFlags::DEPTH | vk::ImageAspectFlags::STENCIL);
    for (n, r) in regions.enumerate() {
        let aspect = r.subresource.aspect_mask;
        let o = r.image_offset;
        let e = r.extent;
        check(
            rules.row_length,
            r.row_length == 0 || r.row_length >= e.width,
            || {
                format!(
                    "pRegions[{n}].bufferRowLength is {}, below imageExtent.width {}",
                    r.row_length, e.width
                )
            },
        )?;
        check(
            rules.image_height,
            r.image_height == 0 || r.image_height >= e.height,
            || {
                format!(
                    "pRegions[{n}].bufferImageHeight is {}, below imageExtent.height {}",
                    r.image_height, e.height
                )
            },
        )?;
        check(rules.one_aspect, aspect.as_raw().count_ones() == 1, || {
            format!("pRegions[{n}].imageSubresource.aspectMask is {aspect:?}, not one aspect")
        })?;
        match planes {
            2 => check(
                rules.two_planes,
                aspect == vk::ImageAspectFlags::PLANE_0 || aspect == vk::ImageAspectFlags::PLANE_1,
                || {
                    format!("pRegions[{n}].imageSubresource.aspectMask is {aspect:?}, not a plane of a two-plane {:?} image", image.format)
                },
            )?,
            3 => check(
                rules.three_planes,
                [
                    vk::ImageAspectFlags::PLANE_0,
                    vk::ImageAspectFlags::PLANE_1,
                    vk::ImageAspectFlags::PLANE_2,
                ]
                .contains(&aspect),
                || {
                    format!("pRegions[{n}].imageSubresource.aspectMask is {aspect:?}, not a plane of a three-plane {:?} image", image.format)
                },
            )?,
            _ => check(rules.aspect, has.contains(aspect), || {
                format!("pRegions[{n}].imageSubresource.aspectMask is {aspect:?}, and a {:?} image has {has:?}", image.format)
            })?,
        }
        check(
            rules.no_graphics_depth,
            family.flags.contains(vk::QueueFlags::GRAPHICS)
                || !aspect.intersects(vk::ImageAspectFlags::DEPTH | vk::ImageAspectFlags::STENCIL),
            || format!("pRegions[{n}] copies {aspect:?} on a queue family without graphics"),
        )?;
        let mip = r.subresource.mip_level;
        check(rules.mip, mip < image.mip_levels, || {
            format!(
                "pRegions[{n}].imageSubresource.mipLevel is {mip}, and the image has {} levels",
                image.mip_levels
            )
        })?;
        let layers = r.subresource.layer_count;
        let base = r.subresource.base_array_layer;
        match image.image_type {
            vk::ImageType::TYPE_1D => {
                check(rules.one_d, o.y == 0 && e.height == 1, || {
                    format!("pRegions[{n}] has imageOffset.y {} and imageExtent.height {} in a 1D image", o.y, e.height)
                })?
            }
            vk::ImageType::TYPE_3D => check(rules.layers_3d, base == 0 && layers == 1, || {
                format!("pRegions[{n}] names layers {base}..+{layers} of a 3D image")
            })?,
            _ => {}
        }
        if image.image_type != vk::ImageType::TYPE_3D {
            check(rules.flat, o.z == 0 && e.depth == 1, || {
                format!(
                    "pRegions[{n}] has imageOffset.z {} and imageExtent.depth {} in a {:?} image",
                    o.z, e.depth, image.image_type
                )
            })?;
        }
        let [w, h, d] = level_extent(image, aspect, mip);
        let inside = |offset: i32, extent: u32, size: i64| {
            let end = i64::from(offset) + i64::from(extent);
            offset >= 0 && end <= size
        };
        check(rules.x_range, inside(o.x, e.width, w), || {
            format!(
                "pRegions[{n}] spans x {}..+{} of a level {w} wide",
                o.x, e.width
            )
        })?;
        check(rules.y_range, inside(o.y, e.height, h), || {
            format!(
                "pRegions[{n}] spans y {}..+{} of a level {h} high",
                o.y, e.height
            )
        })?;
        check(rules.z_range, inside(o.z, e.depth, d), || {
            format!(
                "pRegions[{n}] spans z {}..+{} of a level {d} deep",
                o.z, e.depth
            )
        })?;
        check(
            rules.contained,
            inside(o.x, e.width, w) && inside(o.y, e.height, h) && inside(o.z, e.depth, d),
            || {
                format!(
                    "pRegions[{n}] ({:?} + {:?}) is not inside level {mip}, {w}x{h}x{d}",
                    o, e
                )
            },
        )?;
        let Some((size, [bw, bh, bd])) = crate::formats::block(image.format, aspect) else {
            continue;
        };
        let multiple = |v: i64, of: u32| of == 0 || v.rem_euclid(i64::from(of)) == 0;
        check(
            rules.row_block,
            multiple(i64::from(r.row_length), bw),
            || {
                format!("pRegions[{n}].bufferRowLength {} is not a multiple of the texel block width {bw}", r.row_length)
            },
        )?;
        check(
            rules.height_block,
            multiple(i64::from(r.image_height), bh),
            || {
                format!("pRegions[{n}].bufferImageHeight {} is not a multiple of the texel block height {bh}", r.image_height)
            },
        )?;
        for (axis, (v, b)) in [(o.x, bw), (o.y, bh), (o.z, bd)].into_iter().enumerate() {
            check(rules.offset_block[axis], multiple(i64::from(v), b), || {
                format!("pRegions[{n}].imageOffset {o:?} is not a multiple of the texel block extent {bw}x{bh}x{bd}")
            })?;
        }
        for (axis, (off, ext, size, b)) in [
            (o.x, e.width, w, bw),
            (o.y, e.height, h, bh),
            (o.z, e.depth, d, bd),
        ]
        .into_iter()
        .enumerate()
        {
            let edge = i64::from(off) + i64::from(ext) == size;
            check(
                rules.extent_block[axis],
                edge || multiple(i64::from(ext), b),
                || {
                    format!("pRegions[{n}].imageExtent {e:?} is not a multiple of the texel block extent {bw}x{bh}x{bd}, and does not reach the level's edge")
                },
            )?;
        }
        check(
            rules.row_pitch,
            u64::from(r.row_length / bw.max(1)) * u64::from(size) <= i32::MAX as u64,
            || {
                format!(
                    "pRegions[{n}].bufferRowLength {} makes a row of more than 2^31-1 bytes",
                    r.row_length
                )
            },
        )?;
        check(
            rules.offset_size,
            r.offset % u64::from(size.max(1)) == 0,
            || {
                format!("pRegions[{n}].bufferOffset {} is not a multiple of the texel block size {size}", r.offset)
            },
        )?;
        // Where the format is neither depth/stencil nor multi-planar (01558), or is
        // multi-planar (01559, the plane's element size), the rule is the texel block
        // size's above, whose VUID the error names.
        if depth_stencil && planes == 0 {
            check(rules.offset_depth, r.offset % 4 == 0, || {
                format!(
                    "pRegions[{n}].bufferOffset {} of a depth/stencil copy is not a multiple of 4",
                    r.offset
                )
            })?;
        }
        check(
            rules.transfer_offset,
            family
                .flags
                .intersects(vk::QueueFlags::GRAPHICS | vk::QueueFlags::COMPUTE)
                || r.offset % 4 == 0,
            || {
                format!("pRegions[{n}].bufferOffset {} is not a multiple of 4 on a queue family without graphics or compute", r.offset)
            },
        )?;
        let g = family.granularity;
        let granular = |off: i32, ext: u32, size: i64, g: u32, b: u32| {
            if g == 0 {
                off == 0 && i64::from(ext) == size
            } else {
                let step = i64::from(g) * i64::from(b.max(1));
                i64::from(off) % step == 0
                    && (i64::from(ext) % step == 0 || i64::from(off) + i64::from(ext) == size)
            }
        };
        check(
            rules.granularity,
            granular(o.x, e.width, w, g.width, bw)
                && granular(o.y, e.height, h, g.height, bh)
                && granular(o.z, e.depth, d, g.depth, bd),
            || {
                format!("pRegions[{n}] ({o:?} + {e:?}) does not respect the queue family's image transfer granularity {g:?}")
            },
        )?;
    }
    Ok(())
}

/// Refuses a copy from a buffer into the depth aspect of a floating-point depth
/// format: the rule wants every depth value read in [0,1], and what a buffer holds
/// is the GPU's, which tuff cannot see. A unorm depth format holds [0,1] by its
/// encoding, so copies into those pass; for a float one, the `_unchecked` method
/// takes the caller's word for the values.
fn check_depth_values(record: &ImageRecord, regions: &[Region], rules: &Rules) -> Result<()> {
    let float = matches!(
        record.format,
        vk::Format::D32_SFLOAT | vk::Format::D32_SFLOAT_S8_UINT
    );
    for (n, r) in regions.iter().enumerate() {
        if float
            && r.subresource
                .aspect_mask
                .contains(vk::ImageAspectFlags::DEPTH)
        {
            refuse(
                rules.depth_values,
                format!("pRegions[{n}] copies into the depth aspect of a {:?} image, whose values must lie in [0,1]; tuff cannot see the buffer's contents, so only the `_unchecked` method, whose caller vouches for them, records it", record.format),
            )?;
        }
    }
    Ok(())
}

/// Refuses a copy whose buffer regions reach the memory the image is bound to
/// (the image's whole binding: where a region of an optimally tiled image lies in
/// it is the driver's).
pub(crate) fn check_overlap(
    device: &Device,
    (buffer, image): (vk::Buffer, vk::Image),
    regions: &[Region],
    rules: &Rules,
) -> Result<()> {
    let live = device.live();
    let (Some((bm, boff, _)), Some((im, ioff, isize)), Some(record)) =
        (live.binding(buffer), live.binding(image), live.image(image))
    else {
        return Ok(());
    };
    if bm != im {
        return Ok(());
    }
    for (n, r) in regions.iter().enumerate() {
        let Some(end) = r.buffer_end(record.format) else {
            continue;
        };
        let (start, end) = (boff.saturating_add(r.offset), boff.saturating_add(end));
        check(
            rules.overlap,
            end <= ioff || start >= ioff.saturating_add(isize),
            || {
                format!(
                "pRegions[{n}] spans bytes {start}..{end} of the memory the image is bound to at {ioff}..{}",
                ioff.saturating_add(isize)
            )
            },
        )?;
    }
    Ok(())
}

/// The rules of a clear of an image outside a render pass instance, by field:
/// `vkCmdClearColorImage`'s and `vkCmdClearDepthStencilImage`'s differ in their
/// names and in which aspects and formats they take.
pub(crate) struct ClearRules {
    /// The format features of the image have `TRANSFER_DST`.
    pub features: &'static str,
    /// The format is one the command clears (colour, not compressed; depth/stencil).
    pub format: &'static str,
    /// The format needs no sampler Y'CbCr conversion (empty where no rule says so).
    pub ycbcr: &'static str,
    /// Each range's aspects are ones the command clears.
    pub aspects: &'static str,
    /// Each range's base level is below the image's level count.
    pub base_level: &'static str,
    /// Each range's base layer is below the image's layer count.
    pub base_layer: &'static str,
    /// The protected-memory rules.
    pub protected: Protection,
}

const CLEAR_COLOR: ClearRules = ClearRules {
    features: "VUID-vkCmdClearColorImage-image-01993",
    format: "VUID-vkCmdClearColorImage-image-00007",
    ycbcr: "VUID-vkCmdClearColorImage-image-01545",
    aspects: "VUID-vkCmdClearColorImage-aspectMask-02498",
    base_level: "VUID-vkCmdClearColorImage-baseMipLevel-01470",
    base_layer: "VUID-vkCmdClearColorImage-baseArrayLayer-01472",
    protected: Protection {
        protected_src: "",
        protected_dst: "VUID-vkCmdClearColorImage-commandBuffer-01805",
        unprotected_dst: "VUID-vkCmdClearColorImage-commandBuffer-01806",
    },
};

const CLEAR_DEPTH_STENCIL: ClearRules = ClearRules {
    features: "VUID-vkCmdClearDepthStencilImage-image-01994",
    format: "VUID-vkCmdClearDepthStencilImage-image-00014",
    ycbcr: "",
    aspects: "VUID-vkCmdClearDepthStencilImage-aspectMask-02824",
    base_level: "VUID-vkCmdClearDepthStencilImage-baseMipLevel-01474",
    base_layer: "VUID-vkCmdClearDepthStencilImage-baseArrayLayer-01476",
    protected: Protection {
        protected_src: "",
        protected_dst: "VUID-vkCmdClearDepthStencilImage-commandBuffer-01807",
        unprotected_dst: "VUID-vkCmdClearDepthStencilImage-commandBuffer-01808",
    },
};

/// Refuses a clear of a colour image that breaks a rule of its image or ranges.
pub(crate) fn cmd_clear_color_image_checks<S: Scope>(
    recorder: &Recorder<'_, S>,
    image: &Image,
    ranges: &[vk::ImageSubresourceRange],
) -> Result<()> {
    let color = vk::ImageAspectFlags::COLOR;
    check_clear(recorder, image, ranges, color, &CLEAR_COLOR).map(drop)
}

/// Refuses a clear of a depth/stencil image that breaks a rule of its image, layout
/// or ranges: the aspects it clears must be the format's, and the usage it was
/// created with (its stencil usage, for the stencil aspect) must allow the clear.
pub(crate) fn cmd_clear_depth_stencil_image_checks<S: Scope>(
    recorder: &Recorder<'_, S>,
    image: &Image,
    image_layout: vk::ImageLayout,
    ranges: &[vk::ImageSubresourceRange],
) -> Result<()> {
    use vk::ImageAspectFlags as A;
    if ![
        vk::ImageLayout::TRANSFER_DST_OPTIMAL,
        vk::ImageLayout::GENERAL,
    ]
    .contains(&image_layout)
    {
        refuse(
            "VUID-vkCmdClearDepthStencilImage-imageLayout-00012",
            format!("imageLayout must be TRANSFER_DST_OPTIMAL or GENERAL (imageLayout = {image_layout:?})"),
        )?;
    }
    let Some(record) = check_clear(
        recorder,
        image,
        ranges,
        A::DEPTH | A::STENCIL,
        &CLEAR_DEPTH_STENCIL,
    )?
    else {
        return Ok(());
    };
    let has = crate::formats::aspects(record.format).unwrap_or(A::empty());
    let cleared = ranges.iter().fold(A::empty(), |a, r| a | r.aspect_mask);
    if cleared.contains(A::STENCIL) && !has.contains(A::STENCIL) {
        refuse(
            "VUID-vkCmdClearDepthStencilImage-image-02825",
            format!(
                "a range clears the stencil aspect of a {:?} image, which has none",
                record.format
            ),
        )?;
    }
    if cleared.contains(A::DEPTH) && !has.contains(A::DEPTH) {
        refuse(
            "VUID-vkCmdClearDepthStencilImage-image-02826",
            format!(
                "a range clears the depth aspect of a {:?} image, which has none",
                record.format
            ),
        )?;
    }
    let dst = vk::ImageUsageFlags::TRANSFER_DST;
    if cleared.contains(A::STENCIL) {
        let (usage, vuid) = match record.stencil_usage {
            Some(u) => (u, "VUID-vkCmdClearDepthStencilImage-pRanges-02658"),
            None => (
                record.usage,
                "VUID-vkCmdClearDepthStencilImage-pRanges-02659",
            ),
        };
        if !usage.contains(dst) {
            refuse(
                vuid,
                format!("a range clears the stencil aspect, and the image's stencil usage {usage:?} lacks TRANSFER_DST"),
            )?;
        }
    }
    if cleared.contains(A::DEPTH) && !record.usage.contains(dst) {
        refuse(
            "VUID-vkCmdClearDepthStencilImage-pRanges-02660",
            format!(
                "a range clears the depth aspect, and the image's usage {:?} lacks TRANSFER_DST",
                record.usage
            ),
        )?;
    }
    Ok(())
}

/// The checks both clears share: the image's format, its features and protection,
/// and each range's aspects, base level and base layer. Returns the image's record
/// (`None` for an image the wrappers did not create, which they cannot check).
fn check_clear<S: Scope>(
    recorder: &Recorder<'_, S>,
    image: &Image,
    ranges: &[vk::ImageSubresourceRange],
    aspects: vk::ImageAspectFlags,
    rules: &ClearRules,
) -> Result<Option<ImageRecord>> {
    use vk::ImageAspectFlags as A;
    let device = recorder.device();
    let Some(record) = device.live().image(image.raw()) else {
        return Ok(None);
    };
    let has = crate::formats::aspects(record.format).unwrap_or(A::empty());
    let depth_stencil = has.intersects(A::DEPTH | A::STENCIL);
    let color = aspects == A::COLOR;
    if color && (depth_stencil || super::image::compressed(record.format)) {
        refuse(
            rules.format,
            format!(
                "a colour clear takes neither a compressed nor a depth/stencil format ({:?})",
                record.format
            ),
        )?;
    }
    if !color && !depth_stencil {
        refuse(
            rules.format,
            format!(
                "a depth/stencil clear takes a depth/stencil format, not {:?}",
                record.format
            ),
        )?;
    }
    if !rules.ycbcr.is_empty() && crate::formats::chroma(record.format).is_some() {
        refuse(
            rules.ycbcr,
            format!(
                "{:?} needs a sampler Y'CbCr conversion, which a clear cannot use",
                record.format
            ),
        )?;
    }
    let features = super::image::tiling_features(device, &record)?;
    if !features.contains(vk::FormatFeatureFlags::TRANSFER_DST) {
        refuse(
            rules.features,
            format!(
                "the {:?} features of {:?} ({features:?}) lack TRANSFER_DST",
                record.tiling, record.format
            ),
        )?;
    }
    let protected = record.flags.contains(vk::ImageCreateFlags::PROTECTED);
    check_protected(recorder, None, protected, &rules.protected)?;
    for (i, r) in ranges.iter().enumerate() {
        if r.aspect_mask.is_empty() || !aspects.contains(r.aspect_mask) {
            refuse(
                rules.aspects,
                format!(
                    "pRanges[{i}].aspectMask {:?} is not made of {aspects:?}",
                    r.aspect_mask
                ),
            )?;
        }
        if r.base_mip_level >= record.mip_levels {
            refuse(
                rules.base_level,
                format!(
                    "pRanges[{i}].baseMipLevel {} is not below the image's {} levels",
                    r.base_mip_level, record.mip_levels
                ),
            )?;
        }
        if r.base_array_layer >= record.array_layers {
            refuse(
                rules.base_layer,
                format!(
                    "pRanges[{i}].baseArrayLayer {} is not below the image's {} layers",
                    r.base_array_layer, record.array_layers
                ),
            )?;
        }
    }
    Ok(Some(record))
}
