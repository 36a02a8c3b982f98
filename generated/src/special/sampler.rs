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

/// The checks of `vkCreateSampler` over its filters and address modes together,
/// and a chained reduction mode, against the device's features.
pub(crate) fn sampler_checks(device: &Device, create_info: &SamplerCreateInfo<'_>) -> Result<()> {
    let info = create_info.as_raw();
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
    // SAFETY: the `pNext` of a safe struct, and the type its sType names.
    let reduction: Option<&vk::SamplerReductionModeCreateInfo<'_>> = unsafe {
        chained(
            info.p_next,
            vk::StructureType::SAMPLER_REDUCTION_MODE_CREATE_INFO,
        )
    };
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
