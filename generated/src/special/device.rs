//! Instances and devices: creation (extensions, features, device groups), the
//! scope their checks see, and private data.

use super::{chained, refuse};
use crate::handles::*;
use crate::structs::*;
use crate::{Error, Handle, Result};
use ash::vk;
use ash::vk::Handle as _;

/// The instance remembers its enabled extensions and API version.
pub(crate) fn instance_created(
    entry: &crate::Entry,
    raw: vk::Instance,
    create_info: &InstanceCreateInfo<'_>,
) -> Instance {
    Instance::from_created(
        entry,
        raw,
        &create_info.enabled_extensions(),
        create_info.api_version(),
    )
}

/// The device remembers its enabled extensions and core features (given directly,
/// in a chained `VkPhysicalDeviceFeatures2`, a core version's features struct, or
/// the struct of the extension a core feature came from).
pub(crate) fn device_created(
    physical: &PhysicalDevice,
    raw: vk::Device,
    create_info: &DeviceCreateInfo<'_>,
) -> Device {
    let device = Device::from_created(physical, raw, &create_info.enabled_extensions());
    let info = create_info.as_raw();
    device.live().set_features(enabled_features(create_info));
    let queues = if info.p_queue_create_infos.is_null() {
        &[][..]
    } else {
        // SAFETY: the safe setter stores a slice, with its length, that outlives the
        // create info.
        unsafe {
            core::slice::from_raw_parts(
                info.p_queue_create_infos,
                info.queue_create_info_count as usize,
            )
        }
    };
    // SAFETY: the `pNext` of a safe struct, and the type the sType names.
    let group: Option<&vk::DeviceGroupDeviceCreateInfo<'_>> = unsafe {
        chained(
            info.p_next,
            vk::StructureType::DEVICE_GROUP_DEVICE_CREATE_INFO,
        )
    };
    device
        .live()
        .set_physical_count(group.map_or(1, |g| g.physical_device_count).max(1));
    device.live().set_queue_infos(
        queues
            .iter()
            .map(|q| (q.queue_family_index, q.queue_count, q.flags))
            .collect(),
    );
    device
}

/// The object types that are not the device nor a child of it.
const INSTANCE_LEVEL: &[vk::ObjectType] = &[
    vk::ObjectType::INSTANCE,
    vk::ObjectType::PHYSICAL_DEVICE,
    vk::ObjectType::SURFACE_KHR,
    vk::ObjectType::DEBUG_UTILS_MESSENGER_EXT,
    vk::ObjectType::DEBUG_REPORT_CALLBACK_EXT,
    vk::ObjectType::DISPLAY_KHR,
    vk::ObjectType::DISPLAY_MODE_KHR,
];

/// Whether `object_handle` is the device or a live object of it of `object_type`.
/// Drivers reach an object's private data and debug name through its handle, as a
/// pointer, so a handle of no live object would be used after free.
fn names_live_object(device: &Device, object_type: vk::ObjectType, object_handle: u64) -> bool {
    let is_device = object_type == vk::ObjectType::DEVICE && object_handle == device.raw().as_raw();
    is_device || device.live().sync_of(object_type, object_handle).is_some()
}

/// Refuses an object that is not the device or a live object of it of the type given.
pub(crate) fn set_private_data_checks(
    device: &Device,
    object_type: vk::ObjectType,
    object_handle: u64,
) -> Result<()> {
    if names_live_object(device, object_type, object_handle) {
        return Ok(());
    }
    if INSTANCE_LEVEL.contains(&object_type) {
        return refuse(
            "VUID-vkSetPrivateData-objectHandle-04016",
            format!("objectHandle must be the device or a child of it, not an object of type {object_type:?}"),
        );
    }
    refuse(
        "VUID-vkSetPrivateData-objectHandle-04017",
        format!("objectHandle ({object_handle:#x}) must be the device or a live object of it of type {object_type:?}"),
    )
}

/// Refuses an object that is not the device or a live object of it of the type given.
pub(crate) fn get_private_data_checks(
    device: &Device,
    object_type: vk::ObjectType,
    object_handle: u64,
) -> Result<()> {
    if names_live_object(device, object_type, object_handle) {
        return Ok(());
    }
    if INSTANCE_LEVEL.contains(&object_type) {
        return refuse(
            "VUID-vkGetPrivateData-objectType-04018",
            format!(
                "`objectType` must be `VK_OBJECT_TYPE_DEVICE`, or an object type whose parent \
                 is VkDevice (`objectType` = {object_type:?})"
            ),
        );
    }
    Err(Error::Misuse(
        "objectHandle must be the device or a live object of it of the type given",
    ))
}

/// The scope of `vkCreateInstance`'s checks: the version and extensions it enables.
pub(crate) fn create_instance_scope(
    create_info: &InstanceCreateInfo<'_>,
) -> crate::validation::Scope<'static> {
    crate::validation::Scope {
        exts: crate::checks::Exts::new(
            vk::api_version_minor(create_info.api_version()),
            &create_info.enabled_extensions(),
        ),
        instance: None,
        device: None,
    }
}

/// Every extension an instance enables is part of the emitted API: an extension
/// tuff does not emit adds rules to the commands tuff does emit (a feature that
/// relaxes or changes what a struct may hold), and no safe method checks those.
pub(crate) fn instance_extensions_emitted(create_info: &InstanceCreateInfo<'_>) -> Result<()> {
    extensions_emitted(&create_info.enabled_extensions())
}

/// What emitted extension `ext` needs beside it: its name and the alternatives of
/// `api_info::EXTENSION_REQUIRES` (none: it can never be enabled); `None` for an
/// extension tuff does not emit.
pub(crate) fn extension_requires(
    ext: &core::ffi::CStr,
) -> Option<(&'static str, Vec<Vec<&'static str>>)> {
    let name = *crate::api_info::EXTENSIONS
        .iter()
        .find(|n| n.as_bytes() == ext.to_bytes())?;
    let alternatives = crate::api_info::EXTENSION_REQUIRES
        .iter()
        .filter(|(n, _)| *n == name)
        .map(|(_, all)| all.split('+').filter(|d| !d.is_empty()).collect())
        .collect();
    Some((name, alternatives))
}

/// [`instance_extensions_emitted`], then [`create_instance_checks`]: the checks
/// `vkCreateInstance` runs before the implicit ones.
pub(crate) fn create_instance_first(create_info: &InstanceCreateInfo<'_>) -> Result<()> {
    instance_extensions_emitted(create_info)?;
    create_instance_checks(create_info)
}

/// An instance names a real API version, enables what its extensions depend on, and
/// chains a debug messenger only with the extension that defines it.
pub(crate) fn create_instance_checks(create_info: &InstanceCreateInfo<'_>) -> Result<()> {
    let version = create_info.api_version();
    if version != 0 && version < vk::API_VERSION_1_0 {
        refuse(
            "VUID-VkApplicationInfo-apiVersion-04010",
            format!(
                "If `apiVersion` is not `0`, then it must be greater than or equal to \
                 VK_API_VERSION_1_0 (`apiVersion` = {version:#x})"
            ),
        )?;
    }
    let enabled = create_info.enabled_extensions();
    let has = |name: &str| enabled.iter().any(|e| e.to_bytes() == name.as_bytes());
    for ext in &enabled {
        let Some((name, alternatives)) = extension_requires(ext) else {
            continue;
        };
        let holds = |dep: &&str| match dep.strip_prefix("VK_VERSION_1_") {
            Some(minor) => minor
                .parse::<u32>()
                .is_ok_and(|m| vk::api_version_minor(version.max(vk::API_VERSION_1_0)) >= m),
            None => has(dep),
        };
        if !alternatives.iter().any(|all| all.iter().all(holds)) {
            refuse(
                "VUID-vkCreateInstance-ppEnabledExtensionNames-01388",
                format!(
                    "All required extensions for each extension in the \
                     VkInstanceCreateInfo::`ppEnabledExtensionNames` list must also be present \
                     in that list (`{name}` needs one of {alternatives:?})"
                ),
            )?;
        }
    }
    let mut next = create_info
        .as_raw()
        .p_next
        .cast::<vk::BaseInStructure<'_>>();
    // SAFETY: the safe struct chains only structs pushed through `push_next`, each a
    // valid Vulkan struct that starts with sType and pNext.
    while let Some(node) = unsafe { next.as_ref() } {
        if node.s_type == vk::StructureType::DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT
            && !has("VK_EXT_debug_utils")
        {
            refuse(
                "VUID-VkInstanceCreateInfo-pNext-04926",
                "If the `pNext` chain of `VkInstanceCreateInfo` includes a \
                 `VkDebugUtilsMessengerCreateInfoEXT` structure, the list of enabled extensions \
                 in `ppEnabledExtensionNames` must contain VK_EXT_debug_utils",
            )?;
        }
        next = node.p_next;
    }
    Ok(())
}

/// Every extension a device enables is part of the emitted API (see
/// [`instance_extensions_emitted`]).
pub(crate) fn device_extensions_emitted(create_info: &DeviceCreateInfo<'_>) -> Result<()> {
    extensions_emitted(&create_info.enabled_extensions())
}

fn extensions_emitted(names: &[&core::ffi::CStr]) -> Result<()> {
    for name in names {
        let name = name.to_string_lossy();
        if !crate::api_info::EXTENSIONS.contains(&name.as_ref()) {
            return Err(Error::ExtensionNotEmitted(name.into_owned()));
        }
        // An emitted extension whose rules on other methods are not all checked
        // would leave them to callers of safe methods.
        if !crate::api_info::CHECKED_EXTENSIONS.contains(&name.as_ref()) {
            return Err(Error::ExtensionUnchecked(name.into_owned()));
        }
    }
    Ok(())
}

/// The scope of `vkCreateDevice`'s checks: the instance's, with the device
/// extensions it enables.
pub(crate) fn create_device_scope<'p>(
    physical: &'p PhysicalDevice,
    create_info: &DeviceCreateInfo<'_>,
) -> crate::validation::Scope<'p> {
    let mut s = physical.parent().scope();
    s.exts = s.exts.with(crate::checks::Exts::new(
        0,
        &create_info.enabled_extensions(),
    ));
    s
}

/// The core features a device create info enables (given directly, in a chained
/// `VkPhysicalDeviceFeatures2`, a core version's features struct, or the struct of
/// the extension a core feature came from).
pub(crate) fn enabled_features(create_info: &DeviceCreateInfo<'_>) -> crate::state::Features {
    let info = create_info.as_raw();
    let mut features = crate::state::Features::default();
    // SAFETY: the safe setter stores a reference that outlives the create info.
    if let Some(v10) = unsafe { info.p_enabled_features.as_ref() } {
        features.v10 = *v10;
    }
    for node in chain(info.p_next) {
        // SAFETY: each node is a valid Vulkan struct that starts with sType and
        // pNext (see `chain`).
        unsafe { crate::features::add_chained(node, &mut features) };
    }
    features
}

/// The structs of a safe struct's `pNext` chain.
pub(super) fn chain(
    next: *const core::ffi::c_void,
) -> impl Iterator<Item = *const vk::BaseInStructure<'static>> {
    let mut next = next.cast::<vk::BaseInStructure<'static>>();
    core::iter::from_fn(move || {
        // SAFETY: a safe struct chains only structs pushed through `push_next`, each
        // a valid Vulkan struct that starts with sType and pNext.
        let node = unsafe { next.as_ref() }?;
        let this = next;
        next = node.p_next;
        Some(this)
    })
}

/// The sTypes in a safe struct's `pNext` chain.
fn chained_types(next: *const core::ffi::c_void) -> Vec<vk::StructureType> {
    // SAFETY: as in `chain`.
    chain(next).map(|n| unsafe { (*n).s_type }).collect()
}

/// The feature structs whose features each core version's features struct took
/// over, which the chain must not hold beside it (`VkDeviceCreateInfo-pNext-02829`,
/// `02830`, `06532`).
const TAKEN_OVER: [(vk::StructureType, &str, &[vk::StructureType]); 3] = [
    (
        vk::StructureType::PHYSICAL_DEVICE_VULKAN_1_1_FEATURES,
        "VUID-VkDeviceCreateInfo-pNext-02829",
        &[
            vk::StructureType::PHYSICAL_DEVICE_16BIT_STORAGE_FEATURES,
            vk::StructureType::PHYSICAL_DEVICE_MULTIVIEW_FEATURES,
            vk::StructureType::PHYSICAL_DEVICE_VARIABLE_POINTERS_FEATURES,
            vk::StructureType::PHYSICAL_DEVICE_PROTECTED_MEMORY_FEATURES,
            vk::StructureType::PHYSICAL_DEVICE_SAMPLER_YCBCR_CONVERSION_FEATURES,
            vk::StructureType::PHYSICAL_DEVICE_SHADER_DRAW_PARAMETERS_FEATURES,
        ],
    ),
    (
        vk::StructureType::PHYSICAL_DEVICE_VULKAN_1_2_FEATURES,
        "VUID-VkDeviceCreateInfo-pNext-02830",
        &[
            vk::StructureType::PHYSICAL_DEVICE_8BIT_STORAGE_FEATURES,
            vk::StructureType::PHYSICAL_DEVICE_SHADER_ATOMIC_INT64_FEATURES,
            vk::StructureType::PHYSICAL_DEVICE_SHADER_FLOAT16_INT8_FEATURES,
            vk::StructureType::PHYSICAL_DEVICE_DESCRIPTOR_INDEXING_FEATURES,
            vk::StructureType::PHYSICAL_DEVICE_SCALAR_BLOCK_LAYOUT_FEATURES,
            vk::StructureType::PHYSICAL_DEVICE_IMAGELESS_FRAMEBUFFER_FEATURES,
            vk::StructureType::PHYSICAL_DEVICE_UNIFORM_BUFFER_STANDARD_LAYOUT_FEATURES,
            vk::StructureType::PHYSICAL_DEVICE_SHADER_SUBGROUP_EXTENDED_TYPES_FEATURES,
            vk::StructureType::PHYSICAL_DEVICE_SEPARATE_DEPTH_STENCIL_LAYOUTS_FEATURES,
            vk::StructureType::PHYSICAL_DEVICE_HOST_QUERY_RESET_FEATURES,
            vk::StructureType::PHYSICAL_DEVICE_TIMELINE_SEMAPHORE_FEATURES,
            vk::StructureType::PHYSICAL_DEVICE_BUFFER_DEVICE_ADDRESS_FEATURES,
            vk::StructureType::PHYSICAL_DEVICE_VULKAN_MEMORY_MODEL_FEATURES,
        ],
    ),
    (
        vk::StructureType::PHYSICAL_DEVICE_VULKAN_1_3_FEATURES,
        "VUID-VkDeviceCreateInfo-pNext-06532",
        &[
            vk::StructureType::PHYSICAL_DEVICE_DYNAMIC_RENDERING_FEATURES,
            vk::StructureType::PHYSICAL_DEVICE_IMAGE_ROBUSTNESS_FEATURES,
            vk::StructureType::PHYSICAL_DEVICE_INLINE_UNIFORM_BLOCK_FEATURES,
            vk::StructureType::PHYSICAL_DEVICE_MAINTENANCE_4_FEATURES,
            vk::StructureType::PHYSICAL_DEVICE_PIPELINE_CREATION_CACHE_CONTROL_FEATURES,
            vk::StructureType::PHYSICAL_DEVICE_PRIVATE_DATA_FEATURES,
            vk::StructureType::PHYSICAL_DEVICE_SHADER_DEMOTE_TO_HELPER_INVOCATION_FEATURES,
            vk::StructureType::PHYSICAL_DEVICE_SHADER_INTEGER_DOT_PRODUCT_FEATURES,
            vk::StructureType::PHYSICAL_DEVICE_SHADER_TERMINATE_INVOCATION_FEATURES,
            vk::StructureType::PHYSICAL_DEVICE_SUBGROUP_SIZE_CONTROL_FEATURES,
            vk::StructureType::PHYSICAL_DEVICE_SYNCHRONIZATION_2_FEATURES,
            vk::StructureType::PHYSICAL_DEVICE_TEXTURE_COMPRESSION_ASTC_HDR_FEATURES,
            vk::StructureType::PHYSICAL_DEVICE_ZERO_INITIALIZE_WORKGROUP_MEMORY_FEATURES,
        ],
    ),
];

/// The checks of `vkCreateDevice` over its queue create infos, against the
/// physical device's queue families, and over its chain of feature structs.
pub(crate) fn create_device_checks(
    physical: &PhysicalDevice,
    create_info: &DeviceCreateInfo<'_>,
) -> Result<()> {
    let info = create_info.as_raw();
    let types = chained_types(info.p_next);
    if types.contains(&vk::StructureType::PHYSICAL_DEVICE_FEATURES_2)
        && !info.p_enabled_features.is_null()
    {
        refuse(
            "VUID-VkDeviceCreateInfo-pNext-00373",
            "the chain holds a VkPhysicalDeviceFeatures2, so pEnabledFeatures must be NULL",
        )?;
    }
    for (version, vuid, taken) in TAKEN_OVER {
        if let Some(t) = types
            .iter()
            .find(|t| types.contains(&version) && taken.contains(t))
        {
            refuse(
                vuid,
                format!("the chain holds {version:?} and {t:?}, whose features it took over"),
            )?;
        }
    }
    device_extension_requirements(physical, create_info)?;
    device_feature_pairs(info.p_next)?;
    device_group_members(physical, info.p_next)?;
    let families = physical.get_queue_family_properties()?;
    let protected_memory = enabled_features(create_info).v11.protected_memory == vk::TRUE;
    // SAFETY: the safe setter stores the queue create infos with their count.
    let queues =
        unsafe { crate::state::raw_slice(info.p_queue_create_infos, info.queue_create_info_count) };
    for (i, q) in queues.iter().enumerate() {
        let at = format!("pQueueCreateInfos[{i}]");
        let Some(family) = families.get(q.queue_family_index as usize) else {
            return refuse(
                "VUID-VkDeviceQueueCreateInfo-queueFamilyIndex-00381",
                format!("{at}.queueFamilyIndex ({}) must be less than the physical device's {} queue families", q.queue_family_index, families.len()),
            );
        };
        if q.queue_count > family.queue_count {
            refuse(
                "VUID-VkDeviceQueueCreateInfo-queueCount-00382",
                format!(
                    "{at}.queueCount ({}) is more than family {} has ({})",
                    q.queue_count, q.queue_family_index, family.queue_count
                ),
            )?;
        }
        // SAFETY: the safe setter stores the priorities with their count.
        let priorities = unsafe { crate::state::raw_slice(q.p_queue_priorities, q.queue_count) };
        if let Some(p) = priorities.iter().find(|p| !(0.0..=1.0).contains(*p)) {
            refuse(
                "VUID-VkDeviceQueueCreateInfo-pQueuePriorities-00383",
                format!("{at} has priority {p}, outside 0.0 to 1.0"),
            )?;
        }
        let protected = q.flags.contains(vk::DeviceQueueCreateFlags::PROTECTED);
        if protected && !protected_memory {
            refuse(
                "VUID-VkDeviceQueueCreateInfo-flags-02861",
                format!("{at} asks for protected queues, but the device does not enable protectedMemory"),
            )?;
        }
        if protected && !family.queue_flags.contains(vk::QueueFlags::PROTECTED) {
            refuse(
                "VUID-VkDeviceQueueCreateInfo-flags-06449",
                format!(
                    "{at} asks for protected queues of family {}, which has none",
                    q.queue_family_index
                ),
            )?;
        }
        let twin = |o: &vk::DeviceQueueCreateInfo<'_>| {
            o.queue_family_index == q.queue_family_index
                && o.flags.contains(vk::DeviceQueueCreateFlags::PROTECTED) == protected
        };
        if queues[..i].iter().any(twin) {
            refuse(
                "VUID-VkDeviceCreateInfo-queueFamilyIndex-02802",
                format!("{at} names family {} again", q.queue_family_index),
            )?;
        }
    }
    // Only a protected and an unprotected create info may share a family; their
    // queues together are still the family's.
    for q in queues {
        let Some(family) = families.get(q.queue_family_index as usize) else {
            continue;
        };
        let shared: u32 = queues
            .iter()
            .filter(|o| o.queue_family_index == q.queue_family_index)
            .map(|o| o.queue_count)
            .sum();
        if shared > family.queue_count {
            refuse(
                "VUID-VkDeviceCreateInfo-pQueueCreateInfos-06755",
                format!(
                    "the queue create infos of family {} ask for {shared} queues; it has {}",
                    q.queue_family_index, family.queue_count
                ),
            )?;
        }
    }
    Ok(())
}

/// Every extension a device enables comes with what vk.xml says it depends on:
/// another extension of the device or of its instance, or a core version both
/// reach (`VUID-vkCreateDevice-ppEnabledExtensionNames-01387`).
fn device_extension_requirements(
    physical: &PhysicalDevice,
    create_info: &DeviceCreateInfo<'_>,
) -> Result<()> {
    let enabled = crate::special::device::create_device_scope(physical, create_info).exts;
    for ext in create_info.enabled_extensions() {
        let Some((name, alternatives)) = crate::special::device::extension_requires(ext) else {
            continue;
        };
        if !alternatives
            .iter()
            .any(|all| all.iter().all(|dep| enabled.named(dep)))
        {
            refuse(
                "VUID-vkCreateDevice-ppEnabledExtensionNames-01387",
                format!("`{name}` needs one of {alternatives:?} enabled on the device, its instance or by the API version"),
            )?;
        }
    }
    Ok(())
}

/// The feature structs whose features come in pairs: enabling the first of a pair
/// without the second is refused by the struct's own rule.
fn device_feature_pairs(next: *const core::ffi::c_void) -> Result<()> {
    // SAFETY: the `pNext` of a safe struct, and the types the sTypes name.
    let (multiview, pointers) = unsafe {
        (
            chained::<vk::PhysicalDeviceMultiviewFeatures<'_>>(
                next,
                vk::StructureType::PHYSICAL_DEVICE_MULTIVIEW_FEATURES,
            ),
            chained::<vk::PhysicalDeviceVariablePointersFeatures<'_>>(
                next,
                vk::StructureType::PHYSICAL_DEVICE_VARIABLE_POINTERS_FEATURES,
            ),
        )
    };
    let on = |b: vk::Bool32| b != vk::FALSE;
    if let Some(m) = multiview.filter(|m| !on(m.multiview)) {
        if on(m.multiview_geometry_shader) {
            refuse(
                "VUID-VkPhysicalDeviceMultiviewFeatures-multiviewGeometryShader-00580",
                "VkPhysicalDeviceMultiviewFeatures enables multiviewGeometryShader without multiview",
            )?;
        }
        if on(m.multiview_tessellation_shader) {
            refuse(
                "VUID-VkPhysicalDeviceMultiviewFeatures-multiviewTessellationShader-00581",
                "VkPhysicalDeviceMultiviewFeatures enables multiviewTessellationShader without multiview",
            )?;
        }
    }
    if let Some(p) = pointers {
        if on(p.variable_pointers) && !on(p.variable_pointers_storage_buffer) {
            refuse(
                "VUID-VkPhysicalDeviceVariablePointersFeatures-variablePointers-01431",
                "VkPhysicalDeviceVariablePointersFeatures enables variablePointers without variablePointersStorageBuffer",
            )?;
        }
    }
    Ok(())
}

/// A chained `VkDeviceGroupDeviceCreateInfo` names one device group the physical
/// device belongs to, each member once.
fn device_group_members(physical: &PhysicalDevice, next: *const core::ffi::c_void) -> Result<()> {
    // SAFETY: the `pNext` of a safe struct, and the type the sType names.
    let Some(group) = (unsafe {
        chained::<vk::DeviceGroupDeviceCreateInfo<'_>>(
            next,
            vk::StructureType::DEVICE_GROUP_DEVICE_CREATE_INFO,
        )
    }) else {
        return Ok(());
    };
    // SAFETY: the safe setter stores the wrappers' handles with their count.
    let members =
        unsafe { crate::state::raw_slice(group.p_physical_devices, group.physical_device_count) };
    if let Some(i) = (1..members.len()).find(|&i| members[..i].contains(&members[i])) {
        refuse(
            "VUID-VkDeviceGroupDeviceCreateInfo-pPhysicalDevices-00375",
            format!("pPhysicalDevices[{i}] names a physical device an earlier element names"),
        )?;
    }
    if members.is_empty() {
        return Ok(());
    }
    if !members.contains(&physical.raw()) {
        refuse(
            "VUID-VkDeviceGroupDeviceCreateInfo-physicalDeviceCount-00377",
            "pPhysicalDevices does not hold the physical device the device is created from",
        )?;
    }
    let groups = physical.parent().enumerate_physical_device_groups()?;
    let in_one = groups.iter().any(|g| {
        let of = g
            .physical_devices
            .get(..g.physical_device_count as usize)
            .unwrap_or(&g.physical_devices);
        members.iter().all(|m| of.contains(m))
    });
    if !in_one {
        refuse(
            "VUID-VkDeviceGroupDeviceCreateInfo-pPhysicalDevices-00376",
            "the elements of pPhysicalDevices are not all in one device group",
        )?;
    }
    Ok(())
}
