//! Samplers: their creation checks and the record the device keeps of each.

use super::{chained, refuse};
use crate::handles::*;
use crate::structs::*;
use crate::{Handle, Result};
use ash::vk;

/// The device remembers what a new sampler does (its filters, mipmap mode,
/// unnormalized coordinates and Y'CbCr conversion), which draws and dispatches check
/// the image views it samples against.
pub(crate) fn sampler_created(
    device: &Device,
    sampler: Sampler,
    create_info: &SamplerCreateInfo<'_>,
) -> Sampler {
    let info = create_info.as_raw();
    // SAFETY: the `pNext` of a safe struct, and the type its sType names.
    let conversion: Option<&vk::SamplerYcbcrConversionInfo<'_>> = unsafe {
        chained(
            info.p_next,
            vk::StructureType::SAMPLER_YCBCR_CONVERSION_INFO,
        )
    };
    device.live().sampler_created(
        sampler.raw(),
        crate::state::sampler_bits(info, conversion.is_some()),
    );
    sampler
}

/// Holds other safe sampler creations off while this one is checked against
/// `maxSamplerAllocationCount` and made, so that two threads cannot both take the
/// last one (`VUID-vkCreateSampler-maxSamplerAllocationCount-04110`). Every sampler
/// made through the wrappers, checked or not, is listed until it is destroyed.
pub(crate) fn create_sampler_hold(device: &Device) -> Result<tuff_runtime::VutexGuard<'_, ()>> {
    let (gate, live) = device.live().sampler_gate();
    let max = crate::special::limits(device).max_sampler_allocation_count;
    if live as u64 >= u64::from(max) {
        refuse(
            "VUID-vkCreateSampler-maxSamplerAllocationCount-04110",
            format!("the device has {live} live samplers, the most maxSamplerAllocationCount ({max}) allows"),
        )?;
    }
    Ok(gate)
}

/// The checks of `vkCreateSampler` over its filters and address modes together,
/// the values its modes read, a chained reduction mode and Y'CbCr conversion,
/// against the device's features.
pub(crate) fn sampler_checks(device: &Device, create_info: &SamplerCreateInfo<'_>) -> Result<()> {
    let info = create_info.as_raw();
    // SAFETY: the `pNext` of a safe struct, and the type its sType names.
    let reduction: Option<&vk::SamplerReductionModeCreateInfo<'_>> = unsafe {
        chained(
            info.p_next,
            vk::StructureType::SAMPLER_REDUCTION_MODE_CREATE_INFO,
        )
    };
    values_valid(device, info)?;
    conversion_checks(device, info, reduction)?;
    if info.unnormalized_coordinates == vk::TRUE && info.min_filter != info.mag_filter {
        refuse(
            "VUID-VkSamplerCreateInfo-unnormalizedCoordinates-01072",
            format!("with unnormalized coordinates, minFilter ({:?}) and magFilter ({:?}) must be equal", info.min_filter, info.mag_filter),
        )?;
    }
    let (mirror, minmax) = device.live().with_features(|f| {
        (
            f.v12.sampler_mirror_clamp_to_edge,
            f.v12.sampler_filter_minmax,
        )
    });
    let modes = [
        info.address_mode_u,
        info.address_mode_v,
        info.address_mode_w,
    ];
    if mirror == vk::FALSE && modes.contains(&vk::SamplerAddressMode::MIRROR_CLAMP_TO_EDGE) {
        refuse(
            "VUID-VkSamplerCreateInfo-addressModeU-01079",
            format!("address modes {modes:?} use MIRROR_CLAMP_TO_EDGE, but the device does not enable samplerMirrorClampToEdge"),
        )?;
    }
    let Some(mode) = reduction
        .map(|r| r.reduction_mode)
        .filter(|m| *m != vk::SamplerReductionMode::WEIGHTED_AVERAGE)
    else {
        return Ok(());
    };
    if minmax == vk::FALSE {
        refuse(
            "VUID-VkSamplerCreateInfo-pNext-06726",
            format!("the chained reduction mode is {mode:?}, but the device does not enable samplerFilterMinmax"),
        )?;
    }
    if info.compare_enable == vk::TRUE {
        refuse(
            "VUID-VkSamplerCreateInfo-compareEnable-01423",
            format!("a comparing sampler reduces by weighted average, not {mode:?}"),
        )?;
    }
    Ok(())
}

/// The border colour and compare operation must be values of the API. The rules
/// ask it only where they are read (an address mode clamps to the border,
/// comparison is on; the registry marks them `noautovalidity`), but drivers read
/// them at creation whatever the modes (lavapipe crashes on an invalid border
/// colour), so the safe method asks it always, naming the rule that would apply.
fn values_valid(device: &Device, info: &vk::SamplerCreateInfo<'_>) -> Result<()> {
    use vk::BorderColor as B;
    let scope = device.scope();
    let custom = [crate::checks::origin::VK_EXT_CUSTOM_BORDER_COLOR];
    let valid = match info.border_color {
        B::FLOAT_CUSTOM_EXT | B::INT_CUSTOM_EXT => scope.enabled(&custom),
        b => (B::FLOAT_TRANSPARENT_BLACK.as_raw()..=B::INT_OPAQUE_WHITE.as_raw())
            .contains(&b.as_raw()),
    };
    if !valid {
        refuse(
            "VUID-VkSamplerCreateInfo-addressModeU-01078",
            format!("borderColor {:?} is not a VkBorderColor value of the versions and extensions enabled here (drivers read it even where no address mode clamps to the border)", info.border_color),
        )?;
    }
    crate::checks::enum_compare_op(
        info.compare_op,
        &scope,
        "VUID-VkSamplerCreateInfo-compareEnable-01080",
    )
}

/// The rules of a sampler with a chained Y'CbCr conversion: it clamps to the edge,
/// without anisotropy or unnormalized coordinates, reduces by weighted average, and
/// filters as the conversion's chroma filter unless the conversion's format can
/// reconstruct chroma with its own filter.
fn conversion_checks(
    device: &Device,
    info: &vk::SamplerCreateInfo<'_>,
    reduction: Option<&vk::SamplerReductionModeCreateInfo<'_>>,
) -> Result<()> {
    // SAFETY: the `pNext` of a safe struct, and the type its sType names.
    let conversion: Option<&vk::SamplerYcbcrConversionInfo<'_>> = unsafe {
        chained(
            info.p_next,
            vk::StructureType::SAMPLER_YCBCR_CONVERSION_INFO,
        )
    };
    let Some(conversion) = conversion else {
        return Ok(());
    };
    let modes = [
        info.address_mode_u,
        info.address_mode_v,
        info.address_mode_w,
    ];
    if modes
        .iter()
        .any(|m| *m != vk::SamplerAddressMode::CLAMP_TO_EDGE)
        || info.anisotropy_enable == vk::TRUE
        || info.unnormalized_coordinates == vk::TRUE
    {
        refuse(
            "VUID-VkSamplerCreateInfo-addressModeU-01646",
            format!("a sampler with a Y'CbCr conversion clamps to the edge without anisotropy or unnormalized coordinates (address modes {modes:?}, anisotropyEnable {}, unnormalizedCoordinates {})", info.anisotropy_enable, info.unnormalized_coordinates),
        )?;
    }
    if let Some(r) =
        reduction.filter(|r| r.reduction_mode != vk::SamplerReductionMode::WEIGHTED_AVERAGE)
    {
        refuse(
            "VUID-VkSamplerCreateInfo-None-01647",
            format!(
                "a sampler with a Y'CbCr conversion reduces by weighted average, not {:?}",
                r.reduction_mode
            ),
        )?;
    }
    let Some((format, chroma)) = device.live().conversion(conversion.conversion) else {
        return Ok(());
    };
    let physical = device.parent();
    let p = device.live().format_properties(physical, format)?;
    let separate =
        vk::FormatFeatureFlags::SAMPLED_IMAGE_YCBCR_CONVERSION_SEPARATE_RECONSTRUCTION_FILTER;
    let potential = p.linear_tiling_features | p.optimal_tiling_features;
    if !potential.contains(separate) && (info.min_filter != chroma || info.mag_filter != chroma) {
        refuse(
            "VUID-VkSamplerCreateInfo-minFilter-01645",
            format!("the conversion's format {format:?} cannot reconstruct chroma separately, so minFilter ({:?}) and magFilter ({:?}) must be its chromaFilter ({chroma:?})", info.min_filter, info.mag_filter),
        )?;
    }
    Ok(())
}
