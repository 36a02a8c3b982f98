//! What a draw's or dispatch's shaders reach through the bound descriptor sets: each
//! descriptor written, each image view's type, format and features against the
//! variables and samplers that read it, and protected access.

use super::draw::ShaderRules;
use super::refuse;
use crate::handles::*;
use crate::recorder::{Recorder, Scope};
use crate::state::PipelineRecord;
use crate::{Handle, Result};
use ash::vk;
use ash::vk::Handle as _;

/// The rule of an image descriptor's layout, checked where a draw or dispatch reads
/// it.
pub(super) const DESCRIPTOR_LAYOUT: &str = "VUID-VkDescriptorImageInfo-imageLayout-00344";

/// The image descriptors a draw or dispatch at `bound` may read: those of the sets
/// bound at every set number of the bound pipeline's layout (which of them the
/// shaders read is not known).
#[inline]
fn used_images(
    bound: &crate::recorder::Bound,
) -> impl Iterator<Item = &crate::state::ImageDescriptor> {
    let n = bound.pipeline.as_ref().map_or(0, |p| p.layout.sets.len());
    bound
        .images
        .iter()
        .take(n)
        .flatten()
        .flat_map(|images| images.iter().map(|(_, d)| d))
        .filter(|d| d.kind == crate::state::SlotKind::Image)
}

/// The features of `format` as `VkFormatProperties3` gives them (where the device
/// has Vulkan 1.3): linear tiling, optimal tiling and buffer. On an older device, the
/// bits that `VK_KHR_format_feature_flags2` made per format follow from the first
/// set: depth comparison from sampling a depth format, storage without format from
/// storage (an image's or a texel buffer's) and the device's
/// `shaderStorageImage*WithoutFormat` features.
fn format_features2(device: &Device, format: vk::Format) -> Result<[vk::FormatFeatureFlags2; 3]> {
    let physical = device.parent();
    let instance = physical.parent();
    let version = physical.get_properties().api_version;
    if instance.exts().version(1) && vk::api_version_minor(version) >= 3 {
        let mut p3 = vk::FormatProperties3::default();
        let mut p2 = vk::FormatProperties2::default().push_next(&mut p3);
        // SAFETY: a live physical device of a Vulkan 1.3 device; the chain is local.
        unsafe {
            instance
                .fns()
                .get_physical_device_format_properties2(physical.raw(), format, &mut p2)
        };
        return Ok([
            p3.linear_tiling_features,
            p3.optimal_tiling_features,
            p3.buffer_features,
        ]);
    }
    let live = device.live();
    let props = live.format_properties(physical, format)?;
    let (read, write) = live.with_features(|f| {
        (
            f.v10.shader_storage_image_read_without_format == vk::TRUE,
            f.v10.shader_storage_image_write_without_format == vk::TRUE,
        )
    });
    let depth =
        crate::formats::aspects(format).is_some_and(|a| a.contains(vk::ImageAspectFlags::DEPTH));
    type F = vk::FormatFeatureFlags;
    type F2 = vk::FormatFeatureFlags2;
    let widen = |first: F, storage: F| {
        let mut features = F2::from_raw(u64::from(first.as_raw()));
        if depth && first.contains(F::SAMPLED_IMAGE) {
            features |= F2::SAMPLED_IMAGE_DEPTH_COMPARISON;
        }
        if first.contains(storage) && read {
            features |= F2::STORAGE_READ_WITHOUT_FORMAT;
        }
        if first.contains(storage) && write {
            features |= F2::STORAGE_WRITE_WITHOUT_FORMAT;
        }
        features
    };
    Ok([
        widen(props.linear_tiling_features, F::STORAGE_IMAGE),
        widen(props.optimal_tiling_features, F::STORAGE_IMAGE),
        widen(props.buffer_features, F::STORAGE_TEXEL_BUFFER),
    ])
}

/// The features of the view of `d`'s format for its image's tiling
/// ([`format_features2`]).
fn view_features2(
    device: &Device,
    d: &crate::state::ImageDescriptor,
) -> Result<vk::FormatFeatureFlags2> {
    let linear = device
        .live()
        .image(d.image)
        .is_some_and(|i| i.tiling == vk::ImageTiling::LINEAR);
    let [linear_features, optimal, _] = format_features2(device, d.format)?;
    Ok(if linear { linear_features } else { optimal })
}

/// Refuses a draw or dispatch in a protected command buffer (`in_protected` names
/// the rule: which resources its pipeline writes, and from which stages, is not
/// followed), and, on a device that enabled protectedMemory without
/// protectedNoFault, one in an unprotected command buffer while a protected buffer
/// or image is alive (which resources its pipeline reaches is not followed).
/// Without protectedMemory no protected object can be made (their creation checks
/// the feature), so nothing is refused.
pub(super) fn protected_checks<S: Scope>(
    recorder: &Recorder<'_, S>,
    vuid: &'static str,
    in_protected: &'static str,
) -> Result<()> {
    let device = recorder.device();
    let live = device.live();
    if live.with_features(|f| f.v11.protected_memory) != vk::TRUE {
        return Ok(());
    }
    let protected = recorder
        .command_buffer()
        .uses()
        .pool()
        .is_some_and(|(_, protected)| protected);
    if protected {
        return refuse(
            in_protected,
            "a draw or dispatch in a protected command buffer: which resources its pipeline writes, and from which stages, is not followed",
        );
    }
    if super::render_pass::protected_no_fault(device) {
        return Ok(());
    }
    if live.has_protected_resources() {
        return refuse(
            vuid,
            "a draw or dispatch in an unprotected command buffer while protected buffers or images are alive: which resources its pipeline reaches is not followed",
        );
    }
    Ok(())
}

/// Refuses a draw or dispatch whose shaders use atomic operations on the image view
/// of `d`, where the view's format features (for its image's tiling) lack
/// `STORAGE_IMAGE_ATOMIC`.
fn atomic_checks(
    device: &Device,
    d: &crate::state::ImageDescriptor,
    at: &dyn Fn() -> String,
    vuid: &'static str,
) -> Result<()> {
    if !view_features2(device, d)?.contains(vk::FormatFeatureFlags2::STORAGE_IMAGE_ATOMIC) {
        return refuse(
            vuid,
            format!("{}: the shader uses atomic operations on the image view, and the features of its format {:?} (for its image's tiling) lack STORAGE_IMAGE_ATOMIC", at(), d.format),
        );
    }
    Ok(())
}

/// Refuses a draw or dispatch that reads resource `r` where the set bound at its
/// set number has a descriptor of the binding that was never written.
fn written_checks(
    bound: &crate::recorder::Bound,
    r: &crate::spirv::Resource,
    vuid: &'static str,
) -> Result<()> {
    let (Some(Some(layout)), Some(written)) = (
        bound.sets.get(r.set as usize),
        bound.written.get(r.set as usize),
    ) else {
        return Ok(());
    };
    // A set bound with no record of its slots has none written.
    let written: &[(u32, u32)] = written.as_ref().map_or(&[], |w| w.as_slice());
    let Some(b) = layout.bindings.iter().find(|b| b.binding == r.binding) else {
        return Ok(());
    };
    let partly = b
        .flags
        .contains(vk::DescriptorBindingFlags::PARTIALLY_BOUND);
    // A sampler binding with immutable samplers holds its samplers from the start.
    let fixed = b.immutable && b.ty == vk::DescriptorType::SAMPLER;
    if partly || fixed {
        return Ok(());
    }
    // The variable's descriptors (a runtime array's: the binding's), or an inline
    // uniform block's bytes.
    let count = if r.count == 0 || b.ty == vk::DescriptorType::INLINE_UNIFORM_BLOCK {
        b.count
    } else {
        r.count.min(b.count)
    };
    if let Some(element) = (0..count).find(|e| written.binary_search(&(r.binding, *e)).is_err()) {
        let what = if b.ty == vk::DescriptorType::INLINE_UNIFORM_BLOCK {
            "byte"
        } else {
            "element"
        };
        return refuse(
            vuid,
            format!("set {} binding {} {what} {element}, which the pipeline's shaders declare, was never written (when the set was bound)", r.set, r.binding),
        );
    }
    Ok(())
}

/// Refuses a draw or dispatch whose sets hold an image descriptor whose layout is
/// not the one the recording's earlier commands leave its subresources in, or
/// which names an attachment of the render pass instance (whose layout in each
/// subpass the recorder does not follow).
pub(super) fn descriptor_layout_checks<S: Scope>(
    recorder: &Recorder<'_, S>,
    bound: &crate::recorder::Bound,
) -> Result<()> {
    if bound.images.iter().all(Option::is_none) {
        return Ok(());
    }
    // The images of the render pass instance's attachments (a render pass's, not
    // dynamic rendering's, whose layouts the recording follows).
    let in_pass = recorder.instance.as_ref().is_some_and(|i| !i.dynamic);
    for (k, d) in used_images(bound).enumerate() {
        // Two descriptors that state different layouts for one subresource: one of
        // them is wrong whatever the recording did before.
        if let Some(other) = used_images(bound)
            .take(k)
            .find(|e| e.image == d.image && e.layout != d.layout && e.sel.overlaps(&d.sel))
        {
            return refuse(
                DESCRIPTOR_LAYOUT,
                format!("two image descriptors the bound sets hold name one subresource of image 0x{:x} in different layouts ({:?} and {:?})", d.image.as_raw(), other.layout, d.layout),
            );
        }
        if in_pass && recorder.pass_images.contains(&d.image) {
            // An input attachment of the current subpass is in the layout its
            // reference gives it there.
            let given = d.input.then(|| input_layout(recorder, d.image)).flatten();
            match given {
                Some(layout) if layout == d.layout => continue,
                Some(layout) => {
                    return refuse(
                        DESCRIPTOR_LAYOUT,
                        format!("an input attachment descriptor names image 0x{:x} in {:?}, and the current subpass reads the attachment in {layout:?}", d.image.as_raw(), d.layout),
                    )
                }
                None => {
                    return refuse(
                        DESCRIPTOR_LAYOUT,
                        format!("an image descriptor names image 0x{:x}, an attachment of the render pass instance that the current subpass does not read as an input attachment, whose layout there is not followed", d.image.as_raw()),
                    )
                }
            }
        }
        recorder
            .layouts
            .check(d.image, d.sel, d.layout, DESCRIPTOR_LAYOUT)?;
    }
    Ok(())
}

/// The layout the current subpass gives the input attachment whose image is
/// `image`, if it reads one.
fn input_layout<S: Scope>(recorder: &Recorder<'_, S>, image: vk::Image) -> Option<vk::ImageLayout> {
    let instance = recorder.instance.as_ref()?;
    let record = instance.record.as_ref()?;
    record
        .input_layouts
        .get(instance.subpass as usize)?
        .iter()
        .find(|(a, _)| recorder.pass_images.get(*a as usize) == Some(&image))
        .map(|(_, layout)| *layout)
}

/// Refuses a draw or dispatch whose sets hold, at a binding a resource variable of
/// its pipeline's shaders reads, a descriptor never written (or whose slot a copy of
/// an unwritten one emptied), or an image view that an image variable cannot read: a
/// view type other than the one the variable's `Dim` and `Arrayed` name, a format
/// whose texels read as another numeric type than the variable's sampled type
/// (float against integer), or a format whose features lack what the shader's
/// operations on it need (atomics, depth comparison, storage reads and writes of an
/// `Unknown` format). Every variable the modules declare counts, as
/// which ones the entry points use is not read; a binding with
/// `PARTIALLY_BOUND` leaves its descriptors to the shader promise (a shader that
/// reads one that was not written reads past what the pipeline gave it).
pub(super) fn bound_descriptor_checks(
    device: &Device,
    bound: &crate::recorder::Bound,
    pipeline: &PipelineRecord,
    rules: &ShaderRules,
) -> Result<()> {
    // What the separate samplers the modules declare do, together: which of them
    // samples which image is not followed, so each sampled image counts them all.
    let separate = pipeline
        .resources
        .iter()
        .filter(|r| r.kind == crate::spirv::ResourceKind::Sampler)
        .fold(0, |bits, r| {
            bits | slot_sampler_bits(bound, r.set, r.binding, None)
        });
    for r in pipeline.resources.iter() {
        written_checks(bound, r, rules.written)?;
        let Some(shape) = r.image else {
            continue;
        };
        let (set, binding) = (r.set, r.binding);
        let Some(Some(images)) = bound.images.get(set as usize) else {
            continue;
        };
        for ((_, element), d) in images.iter().filter(|((b, _), _)| *b == binding) {
            let at = || format!("set {set} binding {binding} element {element}");
            if d.kind == crate::state::SlotKind::TexelBuffer {
                texel_buffer_checks(device, r, shape, d, &at, rules)?;
                continue;
            }
            if d.kind != crate::state::SlotKind::Image {
                continue;
            }
            let samplers = if r.kind == crate::spirv::ResourceKind::CombinedImageSampler {
                slot_sampler_bits(bound, set, binding, Some(d.sampler))
            } else {
                separate
            };
            sampled_view_checks(device, r, d, samplers, &at, rules)?;
            written_components(r, d.format, &at, rules.image_write_components)?;
            if let Some(wanted) = shape.view_type() {
                if d.view_type != wanted {
                    refuse(
                        rules.view_type,
                        format!("{}: the shader's image type (Dim {}, Arrayed {}) reads a view of type {wanted:?}, and the descriptor's view is of type {:?}", at(), shape.dim, u32::from(shape.arrayed), d.view_type),
                    )?;
                }
            }
            let aspect = d.sel.aspect;
            let texels = if aspect == vk::ImageAspectFlags::STENCIL {
                2
            } else if aspect == vk::ImageAspectFlags::DEPTH {
                1
            } else {
                crate::formats::color_numeric(d.format).unwrap_or(0)
            };
            if r.ops & crate::spirv::ops::ATOMIC != 0 {
                atomic_checks(device, d, &at, rules.atomics)?;
            }
            let unknown_storage =
                shape.format == 0 && r.kind == crate::spirv::ResourceKind::StorageImage;
            let needs = [
                (
                    crate::spirv::ops::DREF,
                    vk::FormatFeatureFlags2::SAMPLED_IMAGE_DEPTH_COMPARISON,
                    rules.depth_comparison,
                    "samples it with depth comparison",
                ),
                (
                    if unknown_storage {
                        crate::spirv::ops::WRITE
                    } else {
                        0
                    },
                    vk::FormatFeatureFlags2::STORAGE_WRITE_WITHOUT_FORMAT,
                    rules.write_without_format,
                    "writes it as a storage image of Unknown format",
                ),
                (
                    if unknown_storage {
                        crate::spirv::ops::READ
                    } else {
                        0
                    },
                    vk::FormatFeatureFlags2::STORAGE_READ_WITHOUT_FORMAT,
                    rules.read_without_format,
                    "reads it as a storage image of Unknown format",
                ),
            ];
            for (op, feature, vuid, what) in needs {
                if r.ops & op != 0 && !view_features2(device, d)?.contains(feature) {
                    refuse(
                        vuid,
                        format!("{}: the shader {what}, and the features of the view's format {:?} lack {feature:?}", at(), d.format),
                    )?;
                }
            }
            if shape.numeric != 0 && texels != 0 && shape.numeric != texels {
                let name = |n: u32| if n == 1 { "a float" } else { "an integer" };
                refuse(
                    rules.view_numeric,
                    format!("{}: the shader's image type has {} sampled type, and the view's format {:?} reads as {} type", at(), name(shape.numeric), d.format, name(texels)),
                )?;
            }
        }
    }
    Ok(())
}

/// What the samplers at binding `binding` of set `set` do ([`crate::state::sampler_bits`]):
/// the binding's immutable samplers, and `own` (a combined image sampler's) or,
/// without it, every sampler written there.
fn slot_sampler_bits(
    bound: &crate::recorder::Bound,
    set: u32,
    binding: u32,
    own: Option<u8>,
) -> u8 {
    let immutable = bound
        .sets
        .get(set as usize)
        .and_then(Option::as_ref)
        .and_then(|l| l.bindings.iter().find(|b| b.binding == binding))
        .map_or(0, |b| b.immutable_bits);
    let written = own.unwrap_or_else(|| {
        bound
            .images
            .get(set as usize)
            .and_then(Option::as_ref)
            .map_or(0, |list| {
                list.iter()
                    .filter(|((b, _), _)| *b == binding)
                    .fold(0, |bits, (_, d)| bits | d.sampler)
            })
    });
    immutable | written
}

/// Refuses a draw or dispatch whose shaders sample the image view of `d` with
/// samplers (`samplers`, their [`crate::state::sampler_bits`]) it does not allow:
/// linear filtering or linear mipmaps where the view's format features lack
/// `SAMPLED_IMAGE_FILTER_LINEAR` (04553, 04770); unnormalized coordinates on a view
/// of a type other than 1D or 2D (02702), with implicit-LOD, depth-comparison or
/// projective instructions (02703) or with a LOD bias or offsets (02704); and a
/// Y'CbCr conversion (of the sampler or the view) with instructions other than
/// sampling (06550) or with offsets (06551).
fn sampled_view_checks(
    device: &Device,
    r: &crate::spirv::Resource,
    d: &crate::state::ImageDescriptor,
    samplers: u8,
    at: &dyn Fn() -> String,
    rules: &ShaderRules,
) -> Result<()> {
    use crate::spirv::ops;
    use crate::state::{
        SAMPLER_LINEAR, SAMPLER_MIPMAP_LINEAR, SAMPLER_UNNORMALIZED, SAMPLER_YCBCR,
    };
    let sampled = r.ops & ops::SAMPLE != 0;
    if sampled && samplers & (SAMPLER_LINEAR | SAMPLER_MIPMAP_LINEAR) != 0 {
        let linear = view_features2(device, d)?
            .contains(vk::FormatFeatureFlags2::SAMPLED_IMAGE_FILTER_LINEAR);
        if !linear {
            let (vuid, what) = if samplers & SAMPLER_LINEAR != 0 {
                (rules.linear_filter, "a LINEAR magFilter or minFilter")
            } else {
                (rules.linear_mipmap, "a LINEAR mipmapMode")
            };
            refuse(
                vuid,
                format!("{}: a sampler with {what} (and no depth comparison) samples the image view, and the features of its format {:?} (for its image's tiling) lack SAMPLED_IMAGE_FILTER_LINEAR", at(), d.format),
            )?;
        }
    }
    if sampled && samplers & SAMPLER_UNNORMALIZED != 0 {
        use vk::ImageViewType as V;
        if matches!(
            d.view_type,
            V::TYPE_3D | V::CUBE | V::TYPE_1D_ARRAY | V::TYPE_2D_ARRAY | V::CUBE_ARRAY
        ) {
            refuse(
                rules.unnormalized_view_type,
                format!("{}: a sampler with unnormalized coordinates samples an image view of type {:?}", at(), d.view_type),
            )?;
        }
        if r.ops & ops::IMPLICIT_DREF_PROJ != 0 {
            refuse(
                rules.unnormalized_instructions,
                format!("{}: a sampler with unnormalized coordinates may sample the image with an OpImageSample instruction with ImplicitLod, Dref or Proj in its name", at()),
            )?;
        }
        if r.ops & ops::SAMPLE_BIAS_OFFSET != 0 {
            refuse(
                rules.unnormalized_bias_offset,
                format!("{}: a sampler with unnormalized coordinates may sample the image with a LOD bias or an offset", at()),
            )?;
        }
    }
    if d.ycbcr || (sampled && samplers & SAMPLER_YCBCR != 0) {
        if r.ops & ops::NOT_SAMPLE != 0 {
            refuse(
                rules.ycbcr_sampling,
                format!("{}: the image view or a sampler of it has a sampler Y'CbCr conversion, and the shader uses it with an instruction other than OpImageSample* and OpImageSparseSample*", at()),
            )?;
        }
        if r.ops & ops::OFFSET != 0 {
            refuse(
                rules.ycbcr_offset,
                format!("{}: the image view or a sampler of it has a sampler Y'CbCr conversion, and the shader uses it with ConstOffset or Offset", at()),
            )?;
        }
    }
    Ok(())
}

/// Refuses a draw or dispatch whose shaders write texels with fewer components than
/// the view's `format` has (04115 for an image view, 04469 for a texel buffer view).
fn written_components(
    r: &crate::spirv::Resource,
    format: vk::Format,
    at: &dyn Fn() -> String,
    vuid: &'static str,
) -> Result<()> {
    let Some(has) = crate::formats::color_components(format) else {
        return Ok(());
    };
    if r.write_components != 0 && u32::from(r.write_components) < has {
        return refuse(
            vuid,
            format!("{}: the shader writes texels of {} components with OpImageWrite, and the view's format {format:?} has {has}", at(), r.write_components),
        );
    }
    Ok(())
}

/// Refuses a draw or dispatch whose shaders write the texel buffer view of `d` with
/// texels of fewer components than its format has (04469), or write or read it as a
/// storage texel buffer of `Unknown` format where its format's buffer features lack
/// that (07029, 07030).
fn texel_buffer_checks(
    device: &Device,
    r: &crate::spirv::Resource,
    shape: crate::spirv::ImageShape,
    d: &crate::state::ImageDescriptor,
    at: &dyn Fn() -> String,
    rules: &ShaderRules,
) -> Result<()> {
    use crate::spirv::ops;
    written_components(r, d.format, at, rules.texel_write_components)?;
    if shape.format != 0 || r.kind != crate::spirv::ResourceKind::StorageTexelBuffer {
        return Ok(());
    }
    let needs = [
        (
            ops::WRITE,
            vk::FormatFeatureFlags2::STORAGE_WRITE_WITHOUT_FORMAT,
            rules.texel_write_without_format,
            "writes",
        ),
        (
            ops::READ,
            vk::FormatFeatureFlags2::STORAGE_READ_WITHOUT_FORMAT,
            rules.texel_read_without_format,
            "reads",
        ),
    ];
    for (op, feature, vuid, what) in needs {
        if r.ops & op != 0 && !format_features2(device, d.format)?[2].contains(feature) {
            refuse(
                vuid,
                format!("{}: the shader {what} the storage texel buffer with the Unknown format, and the buffer features of the view's format {:?} lack {feature:?}", at(), d.format),
            )?;
        }
    }
    Ok(())
}
