//! Transfer commands: buffer and image copies, fills and updates, each region against
//! the resources it names, their usage, formats and protection.

use super::buffer::{buffer_record, check_buffer_use, used_buffer};
use super::{pool_family, refuse};
use crate::handles::{Device, *};
use crate::recorder::{Recorder, Scope};
use crate::state::ImageRecord;
use crate::state::PoolFamily;
use crate::structs::*;
use crate::{Handle, Result};
use ash::vk;
use smallvec::SmallVec;

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

/// The checks of `vkCmdCopyBuffer` that keep the copy inside both buffers: a copy out
/// of range reads or writes memory the buffers do not own.
pub(crate) fn cmd_copy_buffer_checks<S: Scope>(
    recorder: &Recorder<'_, S>,
    src_buffer: &Buffer,
    dst_buffer: &Buffer,
    regions: &[vk::BufferCopy],
) -> Result<()> {
    let device = recorder.device();
    let src = buffer_record(device, src_buffer)?;
    let dst = buffer_record(device, dst_buffer)?;
    check_buffer_use(
        &src,
        vk::BufferUsageFlags::TRANSFER_SRC,
        (
            "VUID-vkCmdCopyBuffer-srcBuffer-00118",
            "VUID-vkCmdCopyBuffer-srcBuffer-00119",
        ),
        &"srcBuffer",
    )?;
    check_buffer_use(
        &dst,
        vk::BufferUsageFlags::TRANSFER_DST,
        (
            "VUID-vkCmdCopyBuffer-dstBuffer-00120",
            "VUID-vkCmdCopyBuffer-dstBuffer-00121",
        ),
        &"dstBuffer",
    )?;
    for (i, r) in regions.iter().enumerate() {
        if r.size == 0 {
            refuse(
                "VUID-VkBufferCopy-size-01988",
                format!("pRegions[{i}].size must be greater than 0 (size = 0)"),
            )?;
        }
        if r.src_offset >= src.size {
            refuse(
                "VUID-vkCmdCopyBuffer-srcOffset-00113",
                format!("pRegions[{i}].srcOffset must be less than the size of srcBuffer (srcOffset = {}, size of srcBuffer = {})", r.src_offset, src.size),
            )?;
        }
        if r.dst_offset >= dst.size {
            refuse(
                "VUID-vkCmdCopyBuffer-dstOffset-00114",
                format!("pRegions[{i}].dstOffset must be less than the size of dstBuffer (dstOffset = {}, size of dstBuffer = {})", r.dst_offset, dst.size),
            )?;
        }
        if r.size > src.size - r.src_offset {
            refuse(
                "VUID-vkCmdCopyBuffer-size-00115",
                format!("pRegions[{i}].size must be at most the size of srcBuffer minus srcOffset (size = {}, srcOffset = {}, size of srcBuffer = {})", r.size, r.src_offset, src.size),
            )?;
        }
        if r.size > dst.size - r.dst_offset {
            refuse(
                "VUID-vkCmdCopyBuffer-size-00116",
                format!("pRegions[{i}].size must be at most the size of dstBuffer minus dstOffset (size = {}, dstOffset = {}, size of dstBuffer = {})", r.size, r.dst_offset, dst.size),
            )?;
        }
    }
    if src_buffer.raw() == dst_buffer.raw() {
        // Every source range against every destination range, the region's own
        // included; the offsets and sizes are in range, so the ends do not overflow.
        for (i, a) in regions.iter().enumerate() {
            for (j, b) in regions.iter().enumerate() {
                let (a0, a1) = (a.src_offset, a.src_offset + a.size);
                let (b0, b1) = (b.dst_offset, b.dst_offset + b.size);
                if a0 < b1 && b0 < a1 {
                    refuse(
                        "VUID-vkCmdCopyBuffer-pRegions-00117",
                        format!("the source of pRegions[{i}] ({a0}..{a1}) overlaps the destination of pRegions[{j}] ({b0}..{b1}) in the same buffer"),
                    )?;
                }
            }
        }
    }
    Ok(())
}

/// The byte just past the last one that a buffer-image copy region reaches in its
/// buffer, by Buffer and Image Addressing: rows of `bufferRowLength` (or the
/// extent's width) texels, `bufferImageHeight` (or its height) rows a slice, one
/// slice per depth and per layer, in texel blocks of the aspect's size. `None` when
/// the format or aspect is not one the registry describes (an aspect mask of more
/// than one aspect), which another rule refuses.
#[allow(clippy::too_many_arguments)]
fn buffer_image_end(
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
    if let Some(record) = device.live().image(image) {
        check_regions(device, &record, family, regions.iter().copied(), rules)?;
    }
    check_protection(device, family, (buffer, image), rules)?;
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
    /// An unprotected command buffer: the image is not protected.
    pub protected_image: &'static str,
    /// An unprotected command buffer: the buffer is not protected.
    pub protected_buffer: &'static str,
    /// A protected command buffer: the destination is protected.
    pub unprotected_dst: &'static str,
    /// The buffer's and the image's memory do not overlap.
    pub overlap: &'static str,
    /// Each region's buffer range inside the buffer.
    pub range: &'static str,
    /// Whether the copy writes the image (else the buffer).
    pub to_image: bool,
}

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
    protected_image: "VUID-vkCmdCopyBufferToImage-commandBuffer-01829",
    protected_buffer: "VUID-vkCmdCopyBufferToImage-commandBuffer-01828",
    unprotected_dst: "VUID-vkCmdCopyBufferToImage-commandBuffer-01830",
    overlap: "VUID-vkCmdCopyBufferToImage-pRegions-00173",
    range: "VUID-vkCmdCopyBufferToImage-pRegions-00171",
    to_image: true,
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
    protected_image: "VUID-vkCmdCopyImageToBuffer-commandBuffer-01831",
    protected_buffer: "VUID-vkCmdCopyImageToBuffer-commandBuffer-01832",
    unprotected_dst: "VUID-vkCmdCopyImageToBuffer-commandBuffer-01833",
    overlap: "VUID-vkCmdCopyImageToBuffer-pRegions-00184",
    range: "VUID-vkCmdCopyImageToBuffer-pRegions-00183",
    to_image: false,
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
    protected_image: "VUID-vkCmdCopyBufferToImage2-commandBuffer-01829",
    protected_buffer: "VUID-vkCmdCopyBufferToImage2-commandBuffer-01828",
    unprotected_dst: "VUID-vkCmdCopyBufferToImage2-commandBuffer-01830",
    overlap: "VUID-VkCopyBufferToImageInfo2-pRegions-00173",
    range: "VUID-VkCopyBufferToImageInfo2-pRegions-00171",
    to_image: true,
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
    protected_image: "VUID-vkCmdCopyImageToBuffer2-commandBuffer-01831",
    protected_buffer: "VUID-vkCmdCopyImageToBuffer2-commandBuffer-01832",
    unprotected_dst: "VUID-vkCmdCopyImageToBuffer2-commandBuffer-01833",
    overlap: "VUID-VkCopyImageToBufferInfo2-pRegions-00184",
    range: "VUID-VkCopyImageToBufferInfo2-pRegions-00183",
    to_image: false,
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

fn check(vuid: &'static str, holds: bool, message: impl FnOnce() -> String) -> Result<()> {
    if vuid.is_empty() || holds {
        Ok(())
    } else {
        refuse(vuid, message())
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
        let props = device
            .live()
            .format_properties(device.parent(), image.format)?;
        let features = if image.tiling == vk::ImageTiling::LINEAR {
            props.linear_tiling_features
        } else {
            props.optimal_tiling_features
        };
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

/// The protected-memory rules of a copy between `buffer` and `image` recorded into
/// a buffer of `family`'s pool.
pub(crate) fn check_protection(
    device: &Device,
    family: PoolFamily,
    (buffer, image): (vk::Buffer, vk::Image),
    rules: &Rules,
) -> Result<()> {
    let buffer_protected = device
        .live()
        .buffer(buffer)
        .is_some_and(|b| b.flags.contains(vk::BufferCreateFlags::PROTECTED));
    let image_protected = device
        .live()
        .image(image)
        .is_some_and(|i| i.flags.contains(vk::ImageCreateFlags::PROTECTED));
    if family.protected {
        let dst_protected = if rules.to_image {
            image_protected
        } else {
            buffer_protected
        };
        check(rules.unprotected_dst, dst_protected, || {
            "a protected command buffer writes an unprotected destination".into()
        })
    } else {
        check(rules.protected_image, !image_protected, || {
            "an unprotected command buffer copies a protected image".into()
        })?;
        check(rules.protected_buffer, !buffer_protected, || {
            "an unprotected command buffer copies a protected buffer".into()
        })
    }
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
        let Some(end) = buffer_image_end(
            record.format,
            r.subresource.aspect_mask,
            r.offset,
            r.row_length,
            r.image_height,
            r.extent,
            r.subresource.layer_count,
        ) else {
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
