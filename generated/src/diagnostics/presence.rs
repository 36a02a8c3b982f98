//! Why an instance or a device could not be created. When `vkCreateInstance` or
//! `vkCreateDevice` says that a layer, an extension or a feature is not present, the
//! wrappers ask the implementation what it has and name what is missing in
//! [`Error::NotPresent`]. Only a failed creation pays for the questions.
//!
//! Features are named for `VkPhysicalDeviceFeatures`, set directly or through a
//! chained `VkPhysicalDeviceFeatures2`; a missing feature of another chained
//! feature struct leaves the plain [`Error::Vk`]. Device extensions are compared with
//! what the physical device itself offers, so one that only a layer provides may be
//! named too.

use crate::api_info::DEVICE_FEATURES;
use crate::{DeviceCreateInfo, Entry, Error, InstanceCreateInfo, PhysicalDevice};
use ash::vk;
use core::ffi::CStr;

/// The error for a failed `vkCreateInstance` that returned `r`.
pub(crate) fn instance_error(entry: &Entry, info: &InstanceCreateInfo<'_>, r: vk::Result) -> Error {
    let named = match r {
        vk::Result::ERROR_LAYER_NOT_PRESENT => entry
            .enumerate_instance_layer_properties()
            .ok()
            .map(|have| {
                let have: Vec<&CStr> = have
                    .iter()
                    .filter_map(|l| l.layer_name_as_c_str().ok())
                    .collect();
                ("instance layer", missing(&info.enabled_layers(), &have))
            }),
        vk::Result::ERROR_EXTENSION_NOT_PRESENT => {
            // Layers the info enables may provide extensions too.
            let mut have = entry.enumerate_instance_extension_properties(None).ok();
            for layer in info.enabled_layers() {
                if let (Some(have), Ok(more)) = (
                    have.as_mut(),
                    entry.enumerate_instance_extension_properties(Some(layer)),
                ) {
                    have.extend(more);
                }
            }
            have.map(|have| {
                (
                    "instance extension",
                    missing(&info.enabled_extensions(), &names_of(&have)),
                )
            })
        }
        _ => None,
    };
    not_present(r, named)
}

/// The error for a failed `vkCreateDevice` on `physical` that returned `r`.
pub(crate) fn device_error(
    physical: &PhysicalDevice,
    info: &DeviceCreateInfo<'_>,
    r: vk::Result,
) -> Error {
    let named = match r {
        vk::Result::ERROR_EXTENSION_NOT_PRESENT => physical
            .enumerate_device_extension_properties(None)
            .ok()
            .map(|have| {
                (
                    "device extension",
                    missing(&info.enabled_extensions(), &names_of(&have)),
                )
            }),
        vk::Result::ERROR_FEATURE_NOT_PRESENT => wanted_features(info).map(|wanted| {
            let have = physical.get_features();
            let names = match (as_bools(&wanted), as_bools(&have)) {
                (Some(wanted), Some(have)) => DEVICE_FEATURES
                    .iter()
                    .zip(wanted.iter().zip(have))
                    .filter(|(_, (w, h))| **w != vk::FALSE && **h == vk::FALSE)
                    .map(|(name, _)| (*name).to_owned())
                    .collect(),
                _ => Vec::new(),
            };
            ("device feature", names)
        }),
        _ => None,
    };
    not_present(r, named)
}

/// [`Error::NotPresent`] when something was named, else the plain result.
fn not_present(r: vk::Result, named: Option<(&'static str, Vec<String>)>) -> Error {
    match named {
        Some((what, names)) if !names.is_empty() => Error::NotPresent {
            result: r,
            what,
            names,
        },
        _ => Error::Vk(r),
    }
}

/// The extension names of `properties`.
fn names_of(properties: &[vk::ExtensionProperties]) -> Vec<&CStr> {
    properties
        .iter()
        .filter_map(|e| e.extension_name_as_c_str().ok())
        .collect()
}

/// The names in `wanted` that are not in `have`.
fn missing(wanted: &[&CStr], have: &[&CStr]) -> Vec<String> {
    wanted
        .iter()
        .filter(|w| !have.contains(w))
        .map(|w| w.to_string_lossy().into_owned())
        .collect()
}

/// The core features `info` asks for: `pEnabledFeatures`, or the `features` of a
/// chained `VkPhysicalDeviceFeatures2`.
fn wanted_features(info: &DeviceCreateInfo<'_>) -> Option<vk::PhysicalDeviceFeatures> {
    if !info.p_enabled_features.is_null() {
        // SAFETY: the safe setter stores a reference that outlives `info`.
        return Some(unsafe { *info.p_enabled_features });
    }
    // SAFETY: the safe create info only chains structs pushed through `push_next`.
    let node = unsafe { crate::support::chain_nodes(info.p_next) }
        .find(|n| n.s_type == vk::StructureType::PHYSICAL_DEVICE_FEATURES_2)?;
    // SAFETY: the sType says the node is a VkPhysicalDeviceFeatures2.
    let features = unsafe {
        &*(node as *const vk::BaseInStructure<'_>).cast::<vk::PhysicalDeviceFeatures2<'_>>()
    };
    Some(features.features)
}

/// The features as the `VkBool32`s they are, when ash's struct has exactly the
/// registry's members.
fn as_bools(features: &vk::PhysicalDeviceFeatures) -> Option<&[vk::Bool32]> {
    if core::mem::size_of::<vk::PhysicalDeviceFeatures>()
        != DEVICE_FEATURES.len() * core::mem::size_of::<vk::Bool32>()
    {
        return None;
    }
    // SAFETY: the struct is `repr(C)` and, as the size check confirms, made of exactly
    // DEVICE_FEATURES.len() `VkBool32` members, so it is that many u32s, in order,
    // with no padding.
    Some(unsafe {
        core::slice::from_raw_parts(
            (features as *const vk::PhysicalDeviceFeatures).cast::<vk::Bool32>(),
            DEVICE_FEATURES.len(),
        )
    })
}
