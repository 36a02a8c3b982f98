//! Image and buffer views: each view's creation against the image or buffer it views.

use super::{chained, refuse};
use crate::handles::*;
use crate::structs::*;
use crate::{Handle, Result};
use ash::vk;

/// A buffer view's buffer has a texel buffer usage (00932) whose format feature the
/// format has (00933, 00934); its offset is aligned to minTexelBufferOffsetAlignment
/// (02749, and so 02750 and 02751), and its range a whole number of texels (00929) no more than
/// `maxTexelBufferElements` of them (00930, 04059).
pub(crate) fn buffer_view_checks(
    device: &Device,
    create_info: &BufferViewCreateInfo<'_>,
) -> Result<()> {
    let info = create_info.as_raw();
    let live = device.live();
    let Some(buffer) = live.buffer(info.buffer) else {
        return Ok(());
    };
    type U = vk::BufferUsageFlags;
    let uniform = buffer.usage.contains(U::UNIFORM_TEXEL_BUFFER);
    let storage = buffer.usage.contains(U::STORAGE_TEXEL_BUFFER);
    if !uniform && !storage {
        refuse(
            "VUID-VkBufferViewCreateInfo-buffer-00932",
            format!(
                "the buffer's usage {:?} has no texel buffer usage",
                buffer.usage
            ),
        )?;
    }
    let format = info.format;
    let features = live
        .format_properties(device.parent(), format)?
        .buffer_features;
    type F = vk::FormatFeatureFlags;
    for (used, feature, vuid) in [
        (
            uniform,
            F::UNIFORM_TEXEL_BUFFER,
            "VUID-VkBufferViewCreateInfo-buffer-00933",
        ),
        (
            storage,
            F::STORAGE_TEXEL_BUFFER,
            "VUID-VkBufferViewCreateInfo-buffer-00934",
        ),
    ] {
        if used && !features.contains(feature) {
            refuse(
                vuid,
                format!("the buffer features of {format:?} ({features:?}) lack {feature:?}"),
            )?;
        }
    }
    let Some((texel, [w, h, d])) = crate::formats::block(format, vk::ImageAspectFlags::COLOR)
    else {
        return Ok(());
    };
    let (texel, per_block) = (u64::from(texel.max(1)), u64::from(w * h * d));
    let limits = super::limits(device);
    // The relaxed alignments texelBufferAlignment allows are powers of two no larger
    // than minTexelBufferOffsetAlignment, so an offset aligned to it is aligned to
    // them too (02750, 02751). Which of the two applies is not followed: a program
    // that relies on the relaxed one is refused.
    let align = limits.min_texel_buffer_offset_alignment.max(1);
    if info.offset % align != 0 {
        refuse(
            "VUID-VkBufferViewCreateInfo-offset-02749",
            format!(
                "offset {} is not a multiple of minTexelBufferOffsetAlignment ({align})",
                info.offset
            ),
        )?;
    }
    let whole = info.range == vk::WHOLE_SIZE;
    let range = if whole {
        buffer.size.saturating_sub(info.offset)
    } else {
        info.range
    };
    if !whole && range % texel != 0 {
        refuse(
            "VUID-VkBufferViewCreateInfo-range-00929",
            format!(
                "range {range} is not a multiple of the texel block size of {format:?} ({texel})"
            ),
        )?;
    }
    let elements = range / texel * per_block;
    let max = u64::from(limits.max_texel_buffer_elements);
    if elements > max {
        let vuid = if whole {
            "VUID-VkBufferViewCreateInfo-range-04059"
        } else {
            "VUID-VkBufferViewCreateInfo-range-00930"
        };
        refuse(
            vuid,
            format!("the view holds {elements} texels, more than maxTexelBufferElements ({max})"),
        )?;
    }
    Ok(())
}

/// The device remembers the buffer and format of a new buffer view.
pub(crate) fn buffer_view_created(
    device: &Device,
    view: BufferView,
    create_info: &BufferViewCreateInfo<'_>,
) -> BufferView {
    let info = create_info.as_raw();
    device
        .live()
        .buffer_view_created(view.raw(), info.buffer, info.format);
    view
}

/// The usage a view has: a chained `VkImageViewUsageCreateInfo`'s, or the image's
/// (its stencil usage for a stencil-only view, and both for a view of depth and
/// stencil), as the specification derives it.
fn view_usage(
    record: &crate::state::ImageRecord,
    aspect: vk::ImageAspectFlags,
    chained: Option<vk::ImageUsageFlags>,
) -> vk::ImageUsageFlags {
    if let Some(u) = chained {
        return u;
    }
    let Some(stencil) = record.stencil_usage else {
        return record.usage;
    };
    let has_stencil = aspect.contains(vk::ImageAspectFlags::STENCIL);
    let other = aspect.intersects(!vk::ImageAspectFlags::STENCIL);
    match (has_stencil, other) {
        (true, false) => stencil,
        (true, true) => record.usage & stencil,
        _ => record.usage,
    }
}

/// The checks of `vkCreateImageView` that read the image's creation parameters and
/// ask the physical device about the view's format.
pub(crate) fn image_view_checks(
    device: &Device,
    create_info: &ImageViewCreateInfo<'_>,
) -> Result<()> {
    let info = create_info.as_raw();
    let Some(image) = device.live().image(info.image) else {
        return Ok(());
    };
    let r = info.subresource_range;
    let aspect = r.aspect_mask;
    let planes = vk::ImageAspectFlags::PLANE_0
        | vk::ImageAspectFlags::PLANE_1
        | vk::ImageAspectFlags::PLANE_2;
    if aspect.contains(vk::ImageAspectFlags::COLOR) && aspect.intersects(planes) {
        refuse(
            "VUID-VkImageSubresourceRange-aspectMask-01670",
            format!("aspectMask ({aspect:?}) has COLOR and a plane"),
        )?;
    }
    if aspect.intersects(planes) && aspect.as_raw().count_ones() != 1 {
        refuse(
            "VUID-VkImageViewCreateInfo-subresourceRange-07818",
            format!("aspectMask ({aspect:?}) names a plane and another aspect"),
        )?;
    }
    use vk::ImageViewType as V;
    let ty = info.view_type;
    let flags = image.flags;
    if image.samples != vk::SampleCountFlags::TYPE_1 && !matches!(ty, V::TYPE_2D | V::TYPE_2D_ARRAY)
    {
        refuse(
            "VUID-VkImageViewCreateInfo-image-04972",
            format!("a {ty:?} view of a multisampled image"),
        )?;
    }
    let cube = matches!(ty, V::CUBE | V::CUBE_ARRAY);
    if cube && !flags.contains(vk::ImageCreateFlags::CUBE_COMPATIBLE) {
        refuse(
            "VUID-VkImageViewCreateInfo-image-01003",
            format!("a {ty:?} view of an image created without CUBE_COMPATIBLE"),
        )?;
    }
    let view_usages = vk::ImageUsageFlags::SAMPLED
        | vk::ImageUsageFlags::STORAGE
        | vk::ImageUsageFlags::COLOR_ATTACHMENT
        | vk::ImageUsageFlags::DEPTH_STENCIL_ATTACHMENT
        | vk::ImageUsageFlags::INPUT_ATTACHMENT
        | vk::ImageUsageFlags::TRANSIENT_ATTACHMENT;
    if !image.usage.intersects(view_usages) {
        refuse(
            "VUID-VkImageViewCreateInfo-image-04441",
            format!(
                "the image's usage ({:?}) has none a view can have",
                image.usage
            ),
        )?;
    }
    use vk::ImageType as I;
    let compatible = match image.image_type {
        I::TYPE_1D => matches!(ty, V::TYPE_1D | V::TYPE_1D_ARRAY),
        I::TYPE_2D => matches!(ty, V::TYPE_2D | V::TYPE_2D_ARRAY | V::CUBE | V::CUBE_ARRAY),
        I::TYPE_3D => matches!(ty, V::TYPE_3D | V::TYPE_2D | V::TYPE_2D_ARRAY),
        _ => true,
    };
    if !compatible {
        refuse(
            "VUID-VkImageViewCreateInfo-subResourceRange-01021",
            format!("a {ty:?} view of a {:?} image", image.image_type),
        )?;
    }
    let three_d = image.image_type == I::TYPE_3D;
    let array_2d = flags.contains(vk::ImageCreateFlags::TYPE_2D_ARRAY_COMPATIBLE);
    if three_d && !array_2d && ty == V::TYPE_2D_ARRAY {
        refuse(
            "VUID-VkImageViewCreateInfo-image-06723",
            "a 2D array view of a 3D image created without 2D_ARRAY_COMPATIBLE",
        )?;
    }
    if three_d && !array_2d && ty == V::TYPE_2D {
        refuse(
            "VUID-VkImageViewCreateInfo-image-06727",
            "a 2D view of a 3D image created without 2D_ARRAY_COMPATIBLE",
        )?;
    }
    let slices_of_3d = three_d && matches!(ty, V::TYPE_2D | V::TYPE_2D_ARRAY);
    if slices_of_3d && r.level_count != 1 {
        refuse(
            "VUID-VkImageViewCreateInfo-image-04970",
            format!(
                "a {ty:?} view of a 3D image has one level, not {}",
                r.level_count
            ),
        )?;
    }
    let sparse = vk::ImageCreateFlags::SPARSE_BINDING
        | vk::ImageCreateFlags::SPARSE_RESIDENCY
        | vk::ImageCreateFlags::SPARSE_ALIASED;
    if slices_of_3d && flags.intersects(sparse) {
        refuse(
            "VUID-VkImageViewCreateInfo-image-04971",
            format!("a {ty:?} view of a sparse 3D image"),
        )?;
    }
    // The layers a view may name: the depth slices of its base level for 2D views of
    // a 3D image, the array layers otherwise.
    let remaining = vk::REMAINING_ARRAY_LAYERS;
    if slices_of_3d && array_2d {
        let depth = (image.extent.depth >> r.base_mip_level.min(31)).max(1);
        if r.base_array_layer >= depth {
            refuse(
                "VUID-VkImageViewCreateInfo-image-02724",
                format!(
                    "baseArrayLayer ({}) is past the {depth} slices of level {}",
                    r.base_array_layer, r.base_mip_level
                ),
            )?;
        }
        if r.layer_count != remaining
            && (r.layer_count == 0
                || u64::from(r.base_array_layer) + u64::from(r.layer_count) > u64::from(depth))
        {
            refuse(
                "VUID-VkImageViewCreateInfo-subresourceRange-02725",
                format!(
                    "layers {} to {} are not within the {depth} slices of level {}",
                    r.base_array_layer,
                    u64::from(r.base_array_layer) + u64::from(r.layer_count),
                    r.base_mip_level
                ),
            )?;
        }
    } else {
        if r.base_array_layer >= image.array_layers {
            refuse(
                "VUID-VkImageViewCreateInfo-image-01482",
                format!(
                    "baseArrayLayer ({}) is past the image's {} layers",
                    r.base_array_layer, image.array_layers
                ),
            )?;
        }
        if r.layer_count != remaining
            && (r.layer_count == 0
                || u64::from(r.base_array_layer) + u64::from(r.layer_count)
                    > u64::from(image.array_layers))
        {
            refuse(
                "VUID-VkImageViewCreateInfo-subresourceRange-01483",
                format!(
                    "layers {} to {} are not within the image's {}",
                    r.base_array_layer,
                    u64::from(r.base_array_layer) + u64::from(r.layer_count),
                    image.array_layers
                ),
            )?;
        }
    }
    let layers_left = if slices_of_3d && array_2d {
        (image.extent.depth >> r.base_mip_level.min(31)).max(1)
    } else {
        image.array_layers
    }
    .saturating_sub(r.base_array_layer);
    let single = matches!(ty, V::TYPE_1D | V::TYPE_2D | V::TYPE_3D);
    if single && r.layer_count != remaining && r.layer_count != 1 {
        refuse(
            "VUID-VkImageViewCreateInfo-imageViewType-04973",
            format!("a {ty:?} view has one layer, not {}", r.layer_count),
        )?;
    }
    if single && r.layer_count == remaining && layers_left != 1 {
        refuse(
            "VUID-VkImageViewCreateInfo-imageViewType-04974",
            format!("a {ty:?} view has one layer, but {layers_left} remain"),
        )?;
    }
    if ty == V::CUBE && r.layer_count == remaining && layers_left != 6 {
        refuse(
            "VUID-VkImageViewCreateInfo-viewType-02962",
            format!("a cube view has 6 layers, but {layers_left} remain"),
        )?;
    }
    if ty == V::CUBE_ARRAY && r.layer_count == remaining && layers_left % 6 != 0 {
        refuse(
            "VUID-VkImageViewCreateInfo-viewType-02963",
            format!("a cube array view has a multiple of 6 layers, but {layers_left} remain"),
        )?;
    }
    view_format_checks(device, info, &image)
}

/// The view's format against the image's (mutable, block-texel compatible,
/// listed, multi-planar and Y'CbCr rules) and its usage against the format features.
fn view_format_checks(
    device: &Device,
    info: &vk::ImageViewCreateInfo<'_>,
    image: &crate::state::ImageRecord,
) -> Result<()> {
    let (format, r) = (info.format, info.subresource_range);
    let flags = image.flags;
    let mutable = flags.contains(vk::ImageCreateFlags::MUTABLE_FORMAT);
    let block_texel = flags.contains(vk::ImageCreateFlags::BLOCK_TEXEL_VIEW_COMPATIBLE);
    let planes = crate::formats::aspects(image.format)
        .is_some_and(|a| a.contains(vk::ImageAspectFlags::PLANE_0));
    let same_class = |a: vk::Format, b: vk::Format| {
        crate::formats::class(a).is_some() && crate::formats::class(a) == crate::formats::class(b)
    };
    let color = vk::ImageAspectFlags::COLOR;
    if mutable && !block_texel && !planes && !same_class(format, image.format) {
        refuse(
            "VUID-VkImageViewCreateInfo-image-01761",
            format!(
                "{format:?} is not compatible with the image's {:?}",
                image.format
            ),
        )?;
    }
    if block_texel {
        let size = |f| crate::formats::block(f, color).map(|b| b.0);
        let size_compatible = !super::image::compressed(format)
            && size(format).is_some()
            && size(format) == size(image.format);
        if !same_class(format, image.format) && !size_compatible {
            refuse(
                "VUID-VkImageViewCreateInfo-image-01583",
                format!(
                    "{format:?} is neither compatible nor size-compatible with the image's {:?}",
                    image.format
                ),
            )?;
        }
        if !super::image::compressed(format) && (r.level_count != 1 || r.layer_count != 1) {
            refuse(
                "VUID-VkImageViewCreateInfo-image-07072",
                format!("an uncompressed view of a block-texel-view-compatible image has one level and one layer, not {} and {}", r.level_count, r.layer_count),
            )?;
        }
    }
    let listed = device.live().view_formats(info.image);
    if !listed.is_empty() && !listed.contains(&format) {
        refuse(
            "VUID-VkImageViewCreateInfo-pNext-01585",
            format!("{format:?} is not among the view formats the image listed ({listed:?})"),
        )?;
    }
    let plane = [
        vk::ImageAspectFlags::PLANE_0,
        vk::ImageAspectFlags::PLANE_1,
        vk::ImageAspectFlags::PLANE_2,
    ]
    .iter()
    .position(|p| r.aspect_mask == *p);
    if mutable && planes {
        if let Some(p) = plane {
            let plane_format = crate::formats::plane_format(image.format, p);
            if plane_format.is_some_and(|pf| !same_class(format, pf)) {
                refuse(
                    "VUID-VkImageViewCreateInfo-image-01586",
                    format!("{format:?} is not compatible with plane {p} of the image's {:?} ({plane_format:?})", image.format),
                )?;
            }
        }
    }
    if (!mutable || (planes && r.aspect_mask == color)) && format != image.format {
        refuse(
            "VUID-VkImageViewCreateInfo-image-01762",
            format!("{format:?} is not the image's {:?}", image.format),
        )?;
    }
    if let Some(chroma) = crate::formats::chroma(format) {
        if matches!(chroma, 420 | 422) && image.extent.width % 2 != 0 {
            refuse(
                "VUID-VkImageViewCreateInfo-format-04714",
                format!(
                    "a view of {format:?} needs an image of even width, not {}",
                    image.extent.width
                ),
            )?;
        }
        if chroma == 420 && image.extent.height % 2 != 0 {
            refuse(
                "VUID-VkImageViewCreateInfo-format-04715",
                format!(
                    "a view of {format:?} needs an image of even height, not {}",
                    image.extent.height
                ),
            )?;
        }
    }
    // SAFETY: the `pNext` of a safe struct, and the types the sTypes name.
    let (conversion, usage) = unsafe {
        (
            chained::<vk::SamplerYcbcrConversionInfo<'_>>(
                info.p_next,
                vk::StructureType::SAMPLER_YCBCR_CONVERSION_INFO,
            ),
            chained::<vk::ImageViewUsageCreateInfo<'_>>(
                info.p_next,
                vk::StructureType::IMAGE_VIEW_USAGE_CREATE_INFO,
            ),
        )
    };
    let conversion = conversion
        .map(|c| c.conversion)
        .filter(|c| *c != vk::SamplerYcbcrConversion::null());
    if let Some(c) = conversion {
        let identity = vk::ComponentSwizzle::IDENTITY;
        let m = info.components;
        if [m.r, m.g, m.b, m.a].iter().any(|s| *s != identity) {
            refuse(
                "VUID-VkImageViewCreateInfo-pNext-01970",
                format!("a view with a Y'CbCr conversion has the identity swizzle, not {m:?}"),
            )?;
        }
        if let Some(f) = device.live().conversion_format(c).filter(|f| *f != format) {
            refuse(
                "VUID-VkImageViewCreateInfo-pNext-06658",
                format!("the view's format ({format:?}) is not its Y'CbCr conversion's ({f:?})"),
            )?;
        }
    }
    let chained_usage = usage.map(|u| u.usage);
    if let Some(u) = chained_usage {
        let has_stencil = r.aspect_mask.contains(vk::ImageAspectFlags::STENCIL);
        let other = r.aspect_mask.intersects(!vk::ImageAspectFlags::STENCIL);
        match image.stencil_usage {
            None if !image.usage.contains(u) => refuse(
                "VUID-VkImageViewCreateInfo-pNext-02662",
                format!(
                    "the view's usage ({u:?}) has bits the image's ({:?}) has not",
                    image.usage
                ),
            )?,
            Some(s) if has_stencil && !s.contains(u) => refuse(
                "VUID-VkImageViewCreateInfo-pNext-02663",
                format!(
                    "the view's usage ({u:?}) has bits the image's stencil usage ({s:?}) has not"
                ),
            )?,
            Some(_) if other && !image.usage.contains(u) => refuse(
                "VUID-VkImageViewCreateInfo-pNext-02664",
                format!(
                    "the view's usage ({u:?}) has bits the image's ({:?}) has not",
                    image.usage
                ),
            )?,
            _ => {}
        }
    }
    let usage = view_usage(image, r.aspect_mask, chained_usage);
    let sampled = usage.contains(vk::ImageUsageFlags::SAMPLED);
    if crate::formats::chroma(format).is_some() && sampled && conversion.is_none() {
        refuse(
            "VUID-VkImageViewCreateInfo-format-06415",
            format!("a sampled view of {format:?} needs a Y'CbCr conversion chained"),
        )?;
    }
    let props = device.parent().get_format_properties(format)?;
    let features = if image.tiling == vk::ImageTiling::LINEAR {
        props.linear_tiling_features
    } else {
        props.optimal_tiling_features
    };
    use vk::FormatFeatureFlags as F;
    use vk::ImageUsageFlags as U;
    if features.is_empty() {
        refuse(
            "VUID-VkImageViewCreateInfo-None-02273",
            format!(
                "{format:?} has no format features with {:?} tiling",
                image.tiling
            ),
        )?;
    }
    for (bit, needs, vuid) in [
        (
            U::SAMPLED,
            F::SAMPLED_IMAGE,
            "VUID-VkImageViewCreateInfo-usage-02274",
        ),
        (
            U::STORAGE,
            F::STORAGE_IMAGE,
            "VUID-VkImageViewCreateInfo-usage-02275",
        ),
        (
            U::COLOR_ATTACHMENT,
            F::COLOR_ATTACHMENT,
            "VUID-VkImageViewCreateInfo-usage-02276",
        ),
        (
            U::DEPTH_STENCIL_ATTACHMENT,
            F::DEPTH_STENCIL_ATTACHMENT,
            "VUID-VkImageViewCreateInfo-usage-02277",
        ),
    ] {
        if usage.contains(bit) && !features.contains(needs) {
            refuse(
                vuid,
                format!("the view's usage has {bit:?}, but {format:?}'s {:?} features ({features:?}) lack {needs:?}", image.tiling),
            )?;
        }
    }
    if usage.contains(U::INPUT_ATTACHMENT)
        && !features.intersects(F::COLOR_ATTACHMENT | F::DEPTH_STENCIL_ATTACHMENT)
    {
        refuse(
            "VUID-VkImageViewCreateInfo-usage-02652",
            format!("the view's usage has INPUT_ATTACHMENT, but {format:?}'s features ({features:?}) have neither attachment feature"),
        )?;
    }
    Ok(())
}

/// The device remembers a sampler Y'CbCr conversion's format, which views that use
/// it must have, and its chroma filter, which samplers that use it check their
/// filters against.
/// Refuses a Y'CbCr conversion its format cannot make: a format not `UNORM`, chroma
/// sample locations, reconstruction and a chroma filter its potential format
/// features (both tilings', from the physical device) lack, a swizzle a subsampled
/// format does not allow, or components of the model and range the format has not.
pub(crate) fn sampler_ycbcr_conversion_checks(
    device: &Device,
    create_info: &SamplerYcbcrConversionCreateInfo<'_>,
) -> Result<()> {
    type F = vk::FormatFeatureFlags;
    type C = vk::ComponentSwizzle;
    let info = create_info.as_raw();
    let format = info.format;
    // An external format's conversion (its format is UNDEFINED) has rules of its own.
    if format == vk::Format::UNDEFINED {
        return Ok(());
    }
    if !crate::formats::unorm(format) {
        refuse(
            "VUID-VkSamplerYcbcrConversionCreateInfo-format-04060",
            format!("format {format:?} is not a UNORM format"),
        )?;
    }
    let physical = device.parent();
    // SAFETY: a live physical device of its instance.
    let props = unsafe {
        physical
            .parent()
            .fns()
            .get_physical_device_format_properties(physical.raw(), format)
    };
    let features = props.linear_tiling_features | props.optimal_tiling_features;
    let (midpoint, cosited) = (
        features.contains(F::MIDPOINT_CHROMA_SAMPLES),
        features.contains(F::COSITED_CHROMA_SAMPLES),
    );
    if !midpoint && !cosited {
        refuse(
            "VUID-VkSamplerYcbcrConversionCreateInfo-format-01650",
            format!("format {format:?} supports neither midpoint nor cosited chroma samples ({features:?})"),
        )?;
    }
    let offsets = [info.x_chroma_offset, info.y_chroma_offset];
    if !cosited && offsets.contains(&vk::ChromaLocation::COSITED_EVEN) {
        refuse(
            "VUID-VkSamplerYcbcrConversionCreateInfo-xChromaOffset-01651",
            format!("a chroma offset is COSITED_EVEN, and format {format:?} does not support cosited chroma samples"),
        )?;
    }
    if !midpoint && offsets.contains(&vk::ChromaLocation::MIDPOINT) {
        refuse(
            "VUID-VkSamplerYcbcrConversionCreateInfo-xChromaOffset-01652",
            format!("a chroma offset is MIDPOINT, and format {format:?} does not support midpoint chroma samples"),
        )?;
    }
    let c = info.components;
    let identity = |s: C, own: C| s == C::IDENTITY || s == own;
    if matches!(crate::formats::chroma(format), Some(420 | 422)) {
        let rules: [(bool, &str, &str); 4] = [
            (
                identity(c.g, C::G),
                "VUID-VkSamplerYcbcrConversionCreateInfo-components-02581",
                "components.g must be the identity swizzle",
            ),
            (
                identity(c.a, C::A) || c.a == C::ONE || c.a == C::ZERO,
                "VUID-VkSamplerYcbcrConversionCreateInfo-components-02582",
                "components.a must be the identity swizzle, ONE or ZERO",
            ),
            (
                identity(c.r, C::R) || c.r == C::B,
                "VUID-VkSamplerYcbcrConversionCreateInfo-components-02583",
                "components.r must be the identity swizzle or B",
            ),
            (
                identity(c.b, C::B) || c.b == C::R,
                "VUID-VkSamplerYcbcrConversionCreateInfo-components-02584",
                "components.b must be the identity swizzle or R",
            ),
        ];
        for (holds, vuid, what) in rules {
            if !holds {
                refuse(vuid, format!("format {format:?} is subsampled, so {what}"))?;
            }
        }
        if (identity(c.r, C::R) || identity(c.b, C::B))
            && !(identity(c.r, C::R) && identity(c.b, C::B))
        {
            refuse(
                "VUID-VkSamplerYcbcrConversionCreateInfo-components-02585",
                format!("format {format:?} is subsampled, so components.r and components.b are both the identity swizzle or neither"),
            )?;
        }
    }
    // The component each of R, G and B reads after the swizzle: its index in
    // R, G, B, A, or None for ZERO and ONE.
    let source = |s: C, own: usize| match s {
        C::IDENTITY => Some(own),
        C::R => Some(0),
        C::G => Some(1),
        C::B => Some(2),
        C::A => Some(3),
        _ => None,
    };
    let bits = crate::formats::rgba_bits(format).unwrap_or([0; 4]);
    let read = [(c.r, 0, "r"), (c.g, 1, "g"), (c.b, 2, "b")];
    if info.ycbcr_model != vk::SamplerYcbcrModelConversion::RGB_IDENTITY {
        for (s, own, name) in read {
            if source(s, own).is_none_or(|i| bits[i] == 0) {
                refuse(
                    "VUID-VkSamplerYcbcrConversionCreateInfo-ycbcrModel-01655",
                    format!("components.{name} ({s:?}) reads no component of format {format:?}, and the model converts from Y'CbCr"),
                )?;
            }
        }
    }
    if info.ycbcr_range == vk::SamplerYcbcrRange::ITU_NARROW {
        for (s, own, name) in read {
            if let Some(i) = source(s, own).filter(|i| bits[*i] < 8) {
                refuse(
                    "VUID-VkSamplerYcbcrConversionCreateInfo-ycbcrRange-02748",
                    format!("components.{name} reads a component of {} bits, and the narrow range needs 8 or more", bits[i]),
                )?;
            }
        }
    }
    if info.force_explicit_reconstruction == vk::TRUE
        && !features
            .contains(F::SAMPLED_IMAGE_YCBCR_CONVERSION_CHROMA_RECONSTRUCTION_EXPLICIT_FORCEABLE)
    {
        refuse(
            "VUID-VkSamplerYcbcrConversionCreateInfo-forceExplicitReconstruction-01656",
            format!("forceExplicitReconstruction is set, and format {format:?} does not support forcing explicit reconstruction"),
        )?;
    }
    if info.chroma_filter == vk::Filter::LINEAR
        && !features.contains(F::SAMPLED_IMAGE_YCBCR_CONVERSION_LINEAR_FILTER)
    {
        refuse(
            "VUID-VkSamplerYcbcrConversionCreateInfo-chromaFilter-01657",
            format!("chromaFilter is LINEAR, and format {format:?} does not support a linear chroma filter"),
        )?;
    }
    Ok(())
}

pub(crate) fn conversion_created(
    device: &Device,
    conversion: SamplerYcbcrConversion,
    create_info: &SamplerYcbcrConversionCreateInfo<'_>,
) -> SamplerYcbcrConversion {
    let info = create_info.as_raw();
    device
        .live()
        .conversion_created(conversion.raw(), info.format, info.chroma_filter);
    conversion
}

/// The device remembers a view's format, type, range, swizzle and usage for the
/// checks of the framebuffers that use it.
pub(crate) fn image_view_created(
    device: &Device,
    view: ImageView,
    create_info: &ImageViewCreateInfo<'_>,
) -> ImageView {
    let info = create_info.as_raw();
    let r = info.subresource_range;
    if let Some(image) = device.live().image(info.image) {
        // SAFETY: the `pNext` of a safe struct, and the type the sType names.
        let usage: Option<&vk::ImageViewUsageCreateInfo<'_>> =
            unsafe { chained(info.p_next, vk::StructureType::IMAGE_VIEW_USAGE_CREATE_INFO) };
        let levels = if r.level_count == vk::REMAINING_MIP_LEVELS {
            image.mip_levels.saturating_sub(r.base_mip_level)
        } else {
            r.level_count
        };
        let layers = if r.layer_count == vk::REMAINING_ARRAY_LAYERS {
            let total = if image.image_type == vk::ImageType::TYPE_3D
                && matches!(
                    info.view_type,
                    vk::ImageViewType::TYPE_2D | vk::ImageViewType::TYPE_2D_ARRAY
                ) {
                (image.extent.depth >> r.base_mip_level.min(31)).max(1)
            } else {
                image.array_layers
            };
            total.saturating_sub(r.base_array_layer)
        } else {
            r.layer_count
        };
        let identity = |s: vk::ComponentSwizzle, own: vk::ComponentSwizzle| {
            s == vk::ComponentSwizzle::IDENTITY || s == own
        };
        let c = info.components;
        device.live().view_created(
            view.raw(),
            crate::state::ViewRecord {
                image: info.image,
                format: info.format,
                view_type: info.view_type,
                levels,
                layers,
                identity: identity(c.r, vk::ComponentSwizzle::R)
                    && identity(c.g, vk::ComponentSwizzle::G)
                    && identity(c.b, vk::ComponentSwizzle::B)
                    && identity(c.a, vk::ComponentSwizzle::A),
                usage: view_usage(&image, r.aspect_mask, usage.map(|u| u.usage)),
                aspect: r.aspect_mask,
                base_level: r.base_mip_level,
                base_layer: r.base_array_layer,
                // SAFETY: as for the usage info above.
                ycbcr: unsafe {
                    chained::<vk::SamplerYcbcrConversionInfo<'_>>(
                        info.p_next,
                        vk::StructureType::SAMPLER_YCBCR_CONVERSION_INFO,
                    )
                }
                .is_some(),
            },
        );
    }
    view
}
