//! Checks of creations whose rules read more than one value at a time: a device's
//! queues and feature structs against the physical device, an allocation against the
//! memory types and the device's features, a descriptor set layout's bindings and
//! their flags, and a sampler's filters and modes.

use super::*;

/// The core features a device create info enables (given directly, in a chained
/// `VkPhysicalDeviceFeatures2`, a core version's features struct, or the struct of
/// the extension a core feature came from).
pub(crate) fn enabled_features(create_info: &DeviceCreateInfo<'_>) -> crate::validation::Features {
    let info = create_info.as_raw();
    let mut features = crate::validation::Features::default();
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
fn chain(
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
            "the chain holds a VkPhysicalDeviceFeatures2, so pEnabledFeatures must be NULL".into(),
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
    let queues = unsafe {
        crate::retention::raw_slice(info.p_queue_create_infos, info.queue_create_info_count)
    };
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
        let priorities =
            unsafe { crate::retention::raw_slice(q.p_queue_priorities, q.queue_count) };
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
    let enabled = crate::hooks::create_device_scope(physical, create_info).exts;
    for ext in create_info.enabled_extensions() {
        let Some((name, alternatives)) = crate::hooks::extension_requires(ext) else {
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
                "VkPhysicalDeviceMultiviewFeatures enables multiviewGeometryShader without multiview".into(),
            )?;
        }
        if on(m.multiview_tessellation_shader) {
            refuse(
                "VUID-VkPhysicalDeviceMultiviewFeatures-multiviewTessellationShader-00581",
                "VkPhysicalDeviceMultiviewFeatures enables multiviewTessellationShader without multiview".into(),
            )?;
        }
    }
    if let Some(p) = pointers {
        if on(p.variable_pointers) && !on(p.variable_pointers_storage_buffer) {
            refuse(
                "VUID-VkPhysicalDeviceVariablePointersFeatures-variablePointers-01431",
                "VkPhysicalDeviceVariablePointersFeatures enables variablePointers without variablePointersStorageBuffer".into(),
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
    let members = unsafe {
        crate::retention::raw_slice(group.p_physical_devices, group.physical_device_count)
    };
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
            "pPhysicalDevices does not hold the physical device the device is created from".into(),
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
            "the elements of pPhysicalDevices are not all in one device group".into(),
        )?;
    }
    Ok(())
}

/// The checks of `vkAllocateMemory` against the physical device's memory types and
/// heaps, and of its chained flags against the device's features.
pub(crate) fn allocate_memory_checks(
    device: &Device,
    allocate_info: &MemoryAllocateInfo<'_>,
) -> Result<()> {
    let info = allocate_info.as_raw();
    let memory = device.parent().get_memory_properties();
    let index = info.memory_type_index;
    let Some(ty) = memory.memory_types_as_slice().get(index as usize) else {
        return refuse(
            "VUID-vkAllocateMemory-pAllocateInfo-01714",
            format!(
                "memoryTypeIndex ({index}) must be less than the physical device's {} memory types",
                memory.memory_type_count
            ),
        );
    };
    let heap = memory.memory_heaps[ty.heap_index as usize];
    if info.allocation_size > heap.size {
        refuse(
            "VUID-vkAllocateMemory-pAllocateInfo-01713",
            format!(
                "allocationSize ({}) is more than memory type {index}'s heap holds ({})",
                info.allocation_size, heap.size
            ),
        )?;
    }
    // SAFETY: the `pNext` of a safe struct, and the types the sTypes name.
    let (flags, capture) = unsafe {
        (
            chained::<vk::MemoryAllocateFlagsInfo<'_>>(
                info.p_next,
                vk::StructureType::MEMORY_ALLOCATE_FLAGS_INFO,
            ),
            chained::<vk::MemoryOpaqueCaptureAddressAllocateInfo<'_>>(
                info.p_next,
                vk::StructureType::MEMORY_OPAQUE_CAPTURE_ADDRESS_ALLOCATE_INFO,
            ),
        )
    };
    let flags = flags.map_or(vk::MemoryAllocateFlags::empty(), |f| f.flags);
    let (address, replay) = device.live().with_features(|f| {
        (
            f.v12.buffer_device_address,
            f.v12.buffer_device_address_capture_replay,
        )
    });
    if flags.contains(vk::MemoryAllocateFlags::DEVICE_ADDRESS_CAPTURE_REPLAY) && replay == vk::FALSE
    {
        refuse(
            "VUID-VkMemoryAllocateInfo-flags-03330",
            "the allocation asks for capture and replay of device addresses, but the device does not enable bufferDeviceAddressCaptureReplay".into(),
        )?;
    }
    if flags.contains(vk::MemoryAllocateFlags::DEVICE_ADDRESS) && address == vk::FALSE {
        refuse(
            "VUID-VkMemoryAllocateInfo-flags-03331",
            "the allocation asks for a device address, but the device does not enable bufferDeviceAddress".into(),
        )?;
    }
    if let Some(c) = capture.filter(|c| c.opaque_capture_address != 0) {
        if !flags.contains(vk::MemoryAllocateFlags::DEVICE_ADDRESS_CAPTURE_REPLAY) {
            refuse(
                "VUID-VkMemoryAllocateInfo-opaqueCaptureAddress-03329",
                format!("the allocation gives an opaque capture address ({:#x}) without VK_MEMORY_ALLOCATE_DEVICE_ADDRESS_CAPTURE_REPLAY_BIT", c.opaque_capture_address),
            )?;
        }
    }
    let protected_memory = device.live().with_features(|f| f.v11.protected_memory);
    if ty
        .property_flags
        .contains(vk::MemoryPropertyFlags::PROTECTED)
        && protected_memory == vk::FALSE
    {
        refuse(
            "VUID-VkMemoryAllocateInfo-memoryTypeIndex-01872",
            format!(
                "memory type {index} is protected, but the device does not enable protectedMemory"
            ),
        )?;
    }
    // SAFETY: the `pNext` of a safe struct, and the type the sType names.
    let flags_info: Option<&vk::MemoryAllocateFlagsInfo<'_>> =
        unsafe { chained(info.p_next, vk::StructureType::MEMORY_ALLOCATE_FLAGS_INFO) };
    if let Some(f) = flags_info.filter(|f| f.flags.contains(vk::MemoryAllocateFlags::DEVICE_MASK)) {
        if f.device_mask == 0 {
            refuse(
                "VUID-VkMemoryAllocateFlagsInfo-deviceMask-00676",
                "VK_MEMORY_ALLOCATE_DEVICE_MASK_BIT is set and deviceMask is 0".into(),
            )?;
        }
        let count = device.live().physical_count();
        if count < 32 && f.device_mask >> count != 0 {
            refuse(
                "VUID-VkMemoryAllocateFlagsInfo-deviceMask-00675",
                format!("deviceMask ({:#x}) names a physical device the device's {count} do not include", f.device_mask),
            )?;
        }
    }
    dedicated_allocation_checks(device, info)
}

/// A chained `VkMemoryDedicatedAllocateInfo` names one image or one buffer, not
/// sparse, and the allocation has exactly its size; a chained
/// `VkExportMemoryAllocateInfo` names handle types that object can export.
fn dedicated_allocation_checks(device: &Device, info: &vk::MemoryAllocateInfo<'_>) -> Result<()> {
    // SAFETY: the `pNext` of a safe struct, and the types the sTypes name.
    let (dedicated, export) = unsafe {
        (
            chained::<vk::MemoryDedicatedAllocateInfo<'_>>(
                info.p_next,
                vk::StructureType::MEMORY_DEDICATED_ALLOCATE_INFO,
            ),
            chained::<vk::ExportMemoryAllocateInfo<'_>>(
                info.p_next,
                vk::StructureType::EXPORT_MEMORY_ALLOCATE_INFO,
            ),
        )
    };
    let export = export.map_or(vk::ExternalMemoryHandleTypeFlags::empty(), |e| {
        e.handle_types
    });
    let (image, buffer) = dedicated.map_or((vk::Image::null(), vk::Buffer::null()), |d| {
        (d.image, d.buffer)
    });
    if image != vk::Image::null() && buffer != vk::Buffer::null() {
        refuse(
            "VUID-VkMemoryDedicatedAllocateInfo-image-01432",
            "VkMemoryDedicatedAllocateInfo names both an image and a buffer".into(),
        )?;
    }
    let physical = device.parent();
    let instance = physical.parent();
    if let Some(record) = device.live().image(image) {
        if record.flags.contains(vk::ImageCreateFlags::SPARSE_BINDING) {
            refuse(
                "VUID-VkMemoryDedicatedAllocateInfo-image-01434",
                "the dedicated image was created with VK_IMAGE_CREATE_SPARSE_BINDING_BIT".into(),
            )?;
        }
        if record.flags.contains(vk::ImageCreateFlags::DISJOINT) {
            // Its planes have requirements of their own, which this query may not
            // ask for.
            return refuse(
                "VUID-VkMemoryDedicatedAllocateInfo-image-01797",
                "the dedicated image was created with VK_IMAGE_CREATE_DISJOINT_BIT".into(),
            );
        }
        let mut needs = vk::MemoryRequirements::default();
        // SAFETY: a live image of this device (its record is listed) and an output
        // this function owns.
        unsafe {
            (device.fns().fp_v1_0().get_image_memory_requirements)(device.raw(), image, &mut needs)
        };
        if info.allocation_size != needs.size {
            refuse(
                "VUID-VkMemoryDedicatedAllocateInfo-image-01433",
                format!(
                    "allocationSize ({}) is not the dedicated image's memory requirement ({})",
                    info.allocation_size, needs.size
                ),
            )?;
        }
        for handle in each_bit(export) {
            let (r, p) = external_image_properties(
                physical,
                vk::PhysicalDeviceImageFormatInfo2::default()
                    .format(record.format)
                    .ty(record.image_type)
                    .tiling(record.tiling)
                    .usage(record.usage)
                    .flags(record.flags),
                handle,
            );

            if r != vk::Result::SUCCESS || !exports(&p, export) {
                refuse(
                    "VUID-VkExportMemoryAllocateInfo-handleTypes-00656",
                    format!("the dedicated image cannot export {export:?} together: the physical device reports {:?} for {handle:?} ({r:?})", p),
                )?;
            }
        }
    } else if let Some(record) = device.live().buffer(buffer) {
        if record.flags.contains(vk::BufferCreateFlags::SPARSE_BINDING) {
            refuse(
                "VUID-VkMemoryDedicatedAllocateInfo-buffer-01436",
                "the dedicated buffer was created with VK_BUFFER_CREATE_SPARSE_BINDING_BIT".into(),
            )?;
        }
        let mut needs = vk::MemoryRequirements::default();
        // SAFETY: a live buffer of this device (its record is listed) and an output
        // this function owns.
        unsafe {
            (device.fns().fp_v1_0().get_buffer_memory_requirements)(
                device.raw(),
                buffer,
                &mut needs,
            )
        };
        if info.allocation_size != needs.size {
            refuse(
                "VUID-VkMemoryDedicatedAllocateInfo-buffer-01435",
                format!(
                    "allocationSize ({}) is not the dedicated buffer's memory requirement ({})",
                    info.allocation_size, needs.size
                ),
            )?;
        }
        for handle in each_bit(export) {
            let external = vk::PhysicalDeviceExternalBufferInfo::default()
                .flags(record.flags)
                .usage(record.usage)
                .handle_type(handle);
            let mut props = vk::ExternalBufferProperties::default();
            // SAFETY: as for the image above.
            unsafe {
                (instance
                    .fns()
                    .fp_v1_1()
                    .get_physical_device_external_buffer_properties)(
                    physical.raw(),
                    &external,
                    &mut props,
                )
            };
            let p = props.external_memory_properties;
            if !exports(&p, export) {
                refuse(
                    "VUID-VkExportMemoryAllocateInfo-handleTypes-00656",
                    format!("the dedicated buffer cannot export {export:?} together: the physical device reports {:?} for {handle:?}", p),
                )?;
            }
        }
    } else if !export.is_empty() {
        // Without an object the reports that the rule names do not apply to one
        // allocation; binding checks the handle types against each object later, but
        // the export itself would go unchecked.
        return Err(Error::Misuse(
            "the safe allocate_memory exports memory only for a dedicated image or buffer (VkMemoryDedicatedAllocateInfo), whose external memory properties it checks; use allocate_memory_unchecked otherwise",
        ));
    }
    Ok(())
}

/// What the physical device reports for an image of `format_info`'s parameters with
/// external memory of `handle`: the query's result and the external memory
/// properties.
fn external_image_properties(
    physical: &PhysicalDevice,
    format_info: vk::PhysicalDeviceImageFormatInfo2<'_>,
    handle: vk::ExternalMemoryHandleTypeFlags,
) -> (vk::Result, vk::ExternalMemoryProperties) {
    let mut asked = vk::PhysicalDeviceExternalImageFormatInfo::default().handle_type(handle);
    let format_info = format_info.push_next(&mut asked);
    let mut props = vk::ExternalImageFormatProperties::default();
    let mut out = vk::ImageFormatProperties2::default().push_next(&mut props);
    // SAFETY: a live physical device of a Vulkan 1.1 instance (the external structs
    // are core 1.1, which chaining an external memory struct required); the chains
    // are local.
    let r = unsafe {
        (physical
            .parent()
            .fns()
            .fp_v1_1()
            .get_physical_device_image_format_properties2)(
            physical.raw(), &format_info, &mut out
        )
    };
    (r, props.external_memory_properties)
}

/// Each handle type of a set, alone.
fn each_bit(
    set: vk::ExternalMemoryHandleTypeFlags,
) -> impl Iterator<Item = vk::ExternalMemoryHandleTypeFlags> {
    (0..32)
        .map(|b| vk::ExternalMemoryHandleTypeFlags::from_raw(1 << b))
        .filter(move |h| set.contains(*h))
}

/// Whether memory with these properties for one handle type can be exported, with
/// every type of `all` beside it.
fn exports(p: &vk::ExternalMemoryProperties, all: vk::ExternalMemoryHandleTypeFlags) -> bool {
    p.external_memory_features
        .contains(vk::ExternalMemoryFeatureFlags::EXPORTABLE)
        && p.compatible_handle_types.contains(all)
}

/// Holds other safe allocations off while this one is checked against
/// `maxMemoryAllocationCount` and made, so that two threads cannot both take the
/// last one (`VUID-vkAllocateMemory-maxMemoryAllocationCount-04101`).
pub(crate) fn allocate_memory_gate(device: &Device) -> Result<tuff_runtime::VutexGuard<'_, ()>> {
    let (gate, live) = device.live().allocation_gate();
    let max = crate::hooks::limits(device).max_memory_allocation_count;
    if live as u64 >= u64::from(max) {
        refuse(
            "VUID-vkAllocateMemory-maxMemoryAllocationCount-04101",
            format!("the device has {live} live allocations, the most maxMemoryAllocationCount ({max}) allows"),
        )?;
    }
    Ok(gate)
}

/// Which descriptor types the update-after-bind feature of each
/// `descriptorBinding*UpdateAfterBind` covers, with the rule of its absence.
const UPDATE_AFTER_BIND: [(&[vk::DescriptorType], &str, &str); 6] = [
    (
        &[vk::DescriptorType::UNIFORM_BUFFER],
        "descriptorBindingUniformBufferUpdateAfterBind",
        "VUID-VkDescriptorSetLayoutBindingFlagsCreateInfo-descriptorBindingUniformBufferUpdateAfterBind-03005",
    ),
    (
        &[
            vk::DescriptorType::SAMPLER,
            vk::DescriptorType::COMBINED_IMAGE_SAMPLER,
            vk::DescriptorType::SAMPLED_IMAGE,
        ],
        "descriptorBindingSampledImageUpdateAfterBind",
        "VUID-VkDescriptorSetLayoutBindingFlagsCreateInfo-descriptorBindingSampledImageUpdateAfterBind-03006",
    ),
    (
        &[vk::DescriptorType::STORAGE_IMAGE],
        "descriptorBindingStorageImageUpdateAfterBind",
        "VUID-VkDescriptorSetLayoutBindingFlagsCreateInfo-descriptorBindingStorageImageUpdateAfterBind-03007",
    ),
    (
        &[vk::DescriptorType::STORAGE_BUFFER],
        "descriptorBindingStorageBufferUpdateAfterBind",
        "VUID-VkDescriptorSetLayoutBindingFlagsCreateInfo-descriptorBindingStorageBufferUpdateAfterBind-03008",
    ),
    (
        &[vk::DescriptorType::UNIFORM_TEXEL_BUFFER],
        "descriptorBindingUniformTexelBufferUpdateAfterBind",
        "VUID-VkDescriptorSetLayoutBindingFlagsCreateInfo-descriptorBindingUniformTexelBufferUpdateAfterBind-03009",
    ),
    (
        &[vk::DescriptorType::STORAGE_TEXEL_BUFFER],
        "descriptorBindingStorageTexelBufferUpdateAfterBind",
        "VUID-VkDescriptorSetLayoutBindingFlagsCreateInfo-descriptorBindingStorageTexelBufferUpdateAfterBind-03010",
    ),
];

/// The checks of `vkCreateDescriptorSetLayout` over its bindings as a set and a
/// chained `VkDescriptorSetLayoutBindingFlagsCreateInfo` against the device's
/// descriptor-indexing features.
pub(crate) fn descriptor_set_layout_checks(
    device: &Device,
    create_info: &DescriptorSetLayoutCreateInfo<'_>,
) -> Result<()> {
    let info = create_info.as_raw();
    // SAFETY: the safe setter stores the bindings with their count.
    let bindings = unsafe { crate::retention::raw_slice(info.p_bindings, info.binding_count) };
    // The stages of the emitted API: the graphics stages and compute.
    let stages = vk::ShaderStageFlags::ALL_GRAPHICS | vk::ShaderStageFlags::COMPUTE;
    for (i, b) in bindings.iter().enumerate() {
        if b.descriptor_count != 0
            && b.stage_flags != vk::ShaderStageFlags::ALL
            && !stages.contains(b.stage_flags)
        {
            refuse(
                "VUID-VkDescriptorSetLayoutBinding-descriptorCount-00283",
                format!("pBindings[{i}].stageFlags ({:?}) names stages no emitted version or extension has", b.stage_flags),
            )?;
        }
        if bindings[..i].iter().any(|o| o.binding == b.binding) {
            refuse(
                "VUID-VkDescriptorSetLayoutCreateInfo-binding-00279",
                format!(
                    "pBindings[{i}] is binding {}, as an earlier element is",
                    b.binding
                ),
            )?;
        }
        if b.descriptor_type == vk::DescriptorType::INPUT_ATTACHMENT
            && b.descriptor_count != 0
            && !(vk::ShaderStageFlags::FRAGMENT).contains(b.stage_flags)
        {
            refuse(
                "VUID-VkDescriptorSetLayoutBinding-descriptorType-01510",
                format!("pBindings[{i}] is an input attachment for stages {:?}: only the fragment stage reads one", b.stage_flags),
            )?;
        }
        if b.descriptor_type == vk::DescriptorType::INLINE_UNIFORM_BLOCK {
            let max = vulkan13_properties(device).map(|p| p.max_inline_uniform_block_size);
            if let Some(max) = max.filter(|&max| b.descriptor_count > max) {
                refuse(
                    "VUID-VkDescriptorSetLayoutBinding-descriptorType-02210",
                    format!("pBindings[{i}] is an inline uniform block of {} bytes, more than maxInlineUniformBlockSize ({max})", b.descriptor_count),
                )?;
            }
        }
    }
    // SAFETY: the `pNext` of a safe struct, and the type its sType names.
    let binding_flags: Option<&vk::DescriptorSetLayoutBindingFlagsCreateInfo<'_>> = unsafe {
        chained(
            info.p_next,
            vk::StructureType::DESCRIPTOR_SET_LAYOUT_BINDING_FLAGS_CREATE_INFO,
        )
    };
    let Some(binding_flags) = binding_flags else {
        return Ok(());
    };
    // SAFETY: the safe setter stores the flags with their count.
    let all_flags = unsafe {
        crate::retention::raw_slice(binding_flags.p_binding_flags, binding_flags.binding_count)
    };
    let dynamic = [
        vk::DescriptorType::UNIFORM_BUFFER_DYNAMIC,
        vk::DescriptorType::STORAGE_BUFFER_DYNAMIC,
    ];
    let after_bind = all_flags
        .iter()
        .any(|f| f.contains(vk::DescriptorBindingFlags::UPDATE_AFTER_BIND));
    if after_bind
        && !info
            .flags
            .contains(vk::DescriptorSetLayoutCreateFlags::UPDATE_AFTER_BIND_POOL)
    {
        refuse(
            "VUID-VkDescriptorSetLayoutCreateInfo-flags-03000",
            "a binding is updated after bind, so the layout's flags must include UPDATE_AFTER_BIND_POOL".into(),
        )?;
    }
    if after_bind
        && bindings
            .iter()
            .any(|b| dynamic.contains(&b.descriptor_type))
    {
        refuse(
            "VUID-VkDescriptorSetLayoutCreateInfo-descriptorType-03001",
            "a binding is updated after bind, so no binding may be a dynamic buffer".into(),
        )?;
    }
    let highest = bindings.iter().map(|b| b.binding).max();
    for (i, (f, b)) in all_flags.iter().zip(bindings).enumerate() {
        if !f.contains(vk::DescriptorBindingFlags::VARIABLE_DESCRIPTOR_COUNT) {
            continue;
        }
        if bindings.iter().any(|o| o.binding > b.binding) || Some(b.binding) != highest {
            refuse(
                "VUID-VkDescriptorSetLayoutBindingFlagsCreateInfo-pBindingFlags-03004",
                format!("pBindingFlags[{i}] makes binding {} variable-sized, which only the highest binding may be", b.binding),
            )?;
        }
        if dynamic.contains(&b.descriptor_type) {
            refuse(
                "VUID-VkDescriptorSetLayoutBindingFlagsCreateInfo-pBindingFlags-03015",
                format!("pBindingFlags[{i}] makes a dynamic buffer binding variable-sized"),
            )?;
        }
    }
    if binding_flags.binding_count != 0 && binding_flags.binding_count != info.binding_count {
        return refuse(
            "VUID-VkDescriptorSetLayoutBindingFlagsCreateInfo-bindingCount-03002",
            format!(
                "the chained binding flags are for {} bindings; the layout has {}",
                binding_flags.binding_count, info.binding_count
            ),
        );
    }
    // SAFETY: the safe setter stores the flags with their count.
    let flags = unsafe {
        crate::retention::raw_slice(binding_flags.p_binding_flags, binding_flags.binding_count)
    };
    let (v12, v13) = device.live().with_features(|f| (f.v12, f.v13));
    let on = |b: vk::Bool32| b == vk::TRUE;
    let update_after_bind_features = [
        on(v12.descriptor_binding_uniform_buffer_update_after_bind),
        on(v12.descriptor_binding_sampled_image_update_after_bind),
        on(v12.descriptor_binding_storage_image_update_after_bind),
        on(v12.descriptor_binding_storage_buffer_update_after_bind),
        on(v12.descriptor_binding_uniform_texel_buffer_update_after_bind),
        on(v12.descriptor_binding_storage_texel_buffer_update_after_bind),
    ];
    for (i, (f, b)) in flags.iter().zip(bindings).enumerate() {
        let at = format!("pBindingFlags[{i}]");
        let ty = b.descriptor_type;
        if f.contains(vk::DescriptorBindingFlags::UPDATE_AFTER_BIND) {
            for ((types, feature, vuid), enabled) in
                UPDATE_AFTER_BIND.iter().zip(update_after_bind_features)
            {
                if types.contains(&ty) && !enabled {
                    refuse(
                        vuid,
                        format!("{at} updates a {ty:?} binding after bind, but the device does not enable {feature}"),
                    )?;
                }
            }
            if ty == vk::DescriptorType::INLINE_UNIFORM_BLOCK
                && !on(v13.descriptor_binding_inline_uniform_block_update_after_bind)
            {
                refuse(
                    "VUID-VkDescriptorSetLayoutBindingFlagsCreateInfo-descriptorBindingInlineUniformBlockUpdateAfterBind-02211",
                    format!("{at} updates an inline uniform block after bind, but the device does not enable descriptorBindingInlineUniformBlockUpdateAfterBind"),
                )?;
            }
            let never = [
                vk::DescriptorType::INPUT_ATTACHMENT,
                vk::DescriptorType::UNIFORM_BUFFER_DYNAMIC,
                vk::DescriptorType::STORAGE_BUFFER_DYNAMIC,
            ];
            if never.contains(&ty) {
                refuse(
                    "VUID-VkDescriptorSetLayoutBindingFlagsCreateInfo-None-03011",
                    format!("{at} updates a {ty:?} binding after bind, which no device allows"),
                )?;
            }
        }
        for (flag, enabled, feature, vuid) in [
            (
                vk::DescriptorBindingFlags::UPDATE_UNUSED_WHILE_PENDING,
                v12.descriptor_binding_update_unused_while_pending,
                "descriptorBindingUpdateUnusedWhilePending",
                "VUID-VkDescriptorSetLayoutBindingFlagsCreateInfo-descriptorBindingUpdateUnusedWhilePending-03012",
            ),
            (
                vk::DescriptorBindingFlags::PARTIALLY_BOUND,
                v12.descriptor_binding_partially_bound,
                "descriptorBindingPartiallyBound",
                "VUID-VkDescriptorSetLayoutBindingFlagsCreateInfo-descriptorBindingPartiallyBound-03013",
            ),
            (
                vk::DescriptorBindingFlags::VARIABLE_DESCRIPTOR_COUNT,
                v12.descriptor_binding_variable_descriptor_count,
                "descriptorBindingVariableDescriptorCount",
                "VUID-VkDescriptorSetLayoutBindingFlagsCreateInfo-descriptorBindingVariableDescriptorCount-03014",
            ),
        ] {
            if f.contains(flag) && !on(enabled) {
                refuse(vuid, format!("{at} has {flag:?}, but the device does not enable {feature}"))?;
            }
        }
    }
    Ok(())
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

/// Whether `format` is a block-compressed format (its texel blocks span more than
/// one texel, and it is not one of the 4:2:2 formats, whose blocks also do).
pub(super) fn compressed(format: vk::Format) -> bool {
    let subsampled = (1_000_156_000..1_000_157_000).contains(&format.as_raw());
    crate::formats::block(format, vk::ImageAspectFlags::COLOR)
        .is_some_and(|(_, [w, h, _])| (w > 1 || h > 1) && !subsampled)
}

/// The checks of `vkCreateImage` that relate its type, extent, flags, usage and
/// format to each other and to a chained stencil usage or format list. They come
/// before the checks that ask the physical device about the image.
pub(crate) fn image_create_rules(device: &Device, create_info: &ImageCreateInfo<'_>) -> Result<()> {
    let info = create_info.as_raw();
    let (flags, usage, e) = (info.flags, info.usage, info.extent);
    if info.image_type == vk::ImageType::TYPE_1D && (e.height != 1 || e.depth != 1) {
        refuse(
            "VUID-VkImageCreateInfo-imageType-00956",
            format!(
                "a 1D image has height and depth 1 (extent = {}x{}x{})",
                e.width, e.height, e.depth
            ),
        )?;
    }
    if info.image_type == vk::ImageType::TYPE_2D
        && flags.contains(vk::ImageCreateFlags::CUBE_COMPATIBLE)
        && (e.width != e.height || info.array_layers < 6)
    {
        refuse(
            "VUID-VkImageCreateInfo-imageType-00954",
            format!("a cube-compatible image is square with at least 6 layers (extent = {}x{}, arrayLayers = {})", e.width, e.height, info.array_layers),
        )?;
    }
    let attachments = vk::ImageUsageFlags::COLOR_ATTACHMENT
        | vk::ImageUsageFlags::DEPTH_STENCIL_ATTACHMENT
        | vk::ImageUsageFlags::INPUT_ATTACHMENT;
    if usage.contains(vk::ImageUsageFlags::TRANSIENT_ATTACHMENT) && !usage.intersects(attachments) {
        refuse(
            "VUID-VkImageCreateInfo-usage-00966",
            format!("a transient image is an attachment too (usage = {usage:?})"),
        )?;
    }
    if info.samples != vk::SampleCountFlags::TYPE_1
        && (info.image_type != vk::ImageType::TYPE_2D
            || flags.contains(vk::ImageCreateFlags::CUBE_COMPATIBLE)
            || info.mip_levels != 1
            || info.tiling == vk::ImageTiling::LINEAR)
    {
        refuse(
            "VUID-VkImageCreateInfo-samples-02257",
            format!("a multisampled image ({:?}) is an optimal 2D image of one level, not cube-compatible", info.samples),
        )?;
    }
    if flags.contains(vk::ImageCreateFlags::BLOCK_TEXEL_VIEW_COMPATIBLE) && !compressed(info.format)
    {
        refuse(
            "VUID-VkImageCreateInfo-flags-01572",
            format!(
                "a block-texel-view-compatible image has a compressed format, not {:?}",
                info.format
            ),
        )?;
    }
    let planes = vk::ImageAspectFlags::PLANE_0;
    let multi_planar = crate::formats::aspects(info.format).is_some_and(|a| a.contains(planes));
    if flags.contains(vk::ImageCreateFlags::DISJOINT)
        && !multi_planar
        && !flags.contains(vk::ImageCreateFlags::ALIAS)
    {
        refuse(
            "VUID-VkImageCreateInfo-format-01577",
            format!(
                "a disjoint image has a multi-planar format, not {:?}",
                info.format
            ),
        )?;
    }
    let limits = limits(device);
    let max = (limits.max_framebuffer_width, limits.max_framebuffer_height);
    if usage.intersects(attachments | vk::ImageUsageFlags::TRANSIENT_ATTACHMENT) {
        if e.width > max.0 {
            refuse(
                "VUID-VkImageCreateInfo-usage-00964",
                format!(
                    "an attachment image is at most maxFramebufferWidth ({}) wide, not {}",
                    max.0, e.width
                ),
            )?;
        }
        if e.height > max.1 {
            refuse(
                "VUID-VkImageCreateInfo-usage-00965",
                format!(
                    "an attachment image is at most maxFramebufferHeight ({}) high, not {}",
                    max.1, e.height
                ),
            )?;
        }
    }
    // SAFETY: the `pNext` of a safe struct, and the types the sTypes name.
    let (stencil, list) = unsafe {
        (
            chained::<vk::ImageStencilUsageCreateInfo<'_>>(
                info.p_next,
                vk::StructureType::IMAGE_STENCIL_USAGE_CREATE_INFO,
            ),
            chained::<vk::ImageFormatListCreateInfo<'_>>(
                info.p_next,
                vk::StructureType::IMAGE_FORMAT_LIST_CREATE_INFO,
            ),
        )
    };
    let depth_stencil = crate::formats::aspects(info.format)
        .is_some_and(|a| a.intersects(vk::ImageAspectFlags::DEPTH | vk::ImageAspectFlags::STENCIL));
    if let Some(stencil) = stencil.filter(|_| depth_stencil) {
        let s = stencil.stencil_usage;
        for (bit, given, vuid) in [
            (
                vk::ImageUsageFlags::DEPTH_STENCIL_ATTACHMENT,
                true,
                "VUID-VkImageCreateInfo-format-02795",
            ),
            (
                vk::ImageUsageFlags::DEPTH_STENCIL_ATTACHMENT,
                false,
                "VUID-VkImageCreateInfo-format-02796",
            ),
            (
                vk::ImageUsageFlags::TRANSIENT_ATTACHMENT,
                true,
                "VUID-VkImageCreateInfo-format-02797",
            ),
            (
                vk::ImageUsageFlags::TRANSIENT_ATTACHMENT,
                false,
                "VUID-VkImageCreateInfo-format-02798",
            ),
        ] {
            if usage.contains(bit) == given && s.contains(bit) != given {
                refuse(
                    vuid,
                    format!("the stencil usage {s:?} must {}include {bit:?}, as the usage {usage:?} does{}", if given { "" } else { "not " }, if given { "" } else { " not" }),
                )?;
            }
        }
        if s.contains(vk::ImageUsageFlags::INPUT_ATTACHMENT) {
            if e.width > max.0 {
                refuse(
                    "VUID-VkImageCreateInfo-Format-02536",
                    format!("a stencil input attachment is at most maxFramebufferWidth ({}) wide, not {}", max.0, e.width),
                )?;
            }
            if e.height > max.1 {
                refuse(
                    "VUID-VkImageCreateInfo-format-02537",
                    format!("a stencil input attachment is at most maxFramebufferHeight ({}) high, not {}", max.1, e.height),
                )?;
            }
        }
    }
    if let Some(list) = list {
        if !flags.contains(vk::ImageCreateFlags::MUTABLE_FORMAT) && list.view_format_count > 1 {
            refuse(
                "VUID-VkImageCreateInfo-flags-04738",
                format!(
                    "an image without MUTABLE_FORMAT lists at most one view format, not {}",
                    list.view_format_count
                ),
            )?;
        }
        // SAFETY: the safe setter stores the formats with their count.
        let views =
            unsafe { crate::retention::raw_slice(list.p_view_formats, list.view_format_count) };
        let class = crate::formats::class(info.format);
        let block_texel = flags.contains(vk::ImageCreateFlags::BLOCK_TEXEL_VIEW_COMPATIBLE);
        let size = crate::formats::block(info.format, vk::ImageAspectFlags::COLOR).map(|b| b.0);
        for (i, v) in views.iter().enumerate() {
            let same_class = class.is_some() && crate::formats::class(*v) == class;
            let size_compatible = block_texel
                && !compressed(*v)
                && size.is_some()
                && crate::formats::block(*v, vk::ImageAspectFlags::COLOR).map(|b| b.0) == size;
            if !same_class && !size_compatible {
                refuse(
                    "VUID-VkImageCreateInfo-pNext-06722",
                    format!("pViewFormats[{i}] ({v:?}) is not compatible with the image's format ({:?})", info.format),
                )?;
            }
        }
    }
    sharing_and_group_rules(device, info)?;
    chroma_rules(device, info, stencil)?;
    #[cfg(feature = "khr_swapchain")]
    swapchain_image_rules(device, info)?;
    Ok(())
}

/// An image made for a swapchain's memory has the swapchain's implied image
/// creation parameters (`VUID-VkImageSwapchainCreateInfoKHR-swapchain-00995`).
#[cfg(feature = "khr_swapchain")]
fn swapchain_image_rules(device: &Device, info: &vk::ImageCreateInfo<'_>) -> Result<()> {
    // SAFETY: the `pNext` of a safe struct, and the type the sType names.
    let chained: Option<&vk::ImageSwapchainCreateInfoKHR<'_>> = unsafe {
        chained(
            info.p_next,
            vk::StructureType::IMAGE_SWAPCHAIN_CREATE_INFO_KHR,
        )
    };
    let Some(swapchain) = chained
        .map(|c| c.swapchain)
        .filter(|s| *s != vk::SwapchainKHR::null())
    else {
        return Ok(());
    };
    let Some(implied) = device.live().swapchain(swapchain) else {
        return Ok(());
    };
    let made = crate::retention::ImageRecord {
        flags: info.flags,
        image_type: info.image_type,
        format: info.format,
        extent: info.extent,
        mip_levels: info.mip_levels,
        array_layers: info.array_layers,
        usage: info.usage,
        tiling: info.tiling,
        samples: info.samples,
        stencil_usage: implied.stencil_usage,
        sharing: info.sharing_mode,
        families: family_bits(info.sharing_mode, info),
        bound: implied.bound,
        external: implied.external,
    };
    let matches = made.flags == implied.flags
        && made.image_type == implied.image_type
        && made.format == implied.format
        && made.extent == implied.extent
        && made.mip_levels == implied.mip_levels
        && made.array_layers == implied.array_layers
        && made.usage == implied.usage
        && made.tiling == implied.tiling
        && made.sharing == implied.sharing
        && made.families == implied.families
        && info.samples == vk::SampleCountFlags::TYPE_1
        && info.initial_layout == vk::ImageLayout::UNDEFINED;
    if !matches {
        refuse(
            "VUID-VkImageSwapchainCreateInfoKHR-swapchain-00995",
            format!("the image's parameters ({made:?}, {:?}, {:?}) are not the swapchain's implied ones ({implied:?}, one sample, UNDEFINED)", info.samples, info.initial_layout),
        )?;
    }
    Ok(())
}

/// An image's sharing, sparse, external and device-group parameters against each
/// other and the device.
fn sharing_and_group_rules(device: &Device, info: &vk::ImageCreateInfo<'_>) -> Result<()> {
    let flags = info.flags;
    if info.sharing_mode == vk::SharingMode::CONCURRENT {
        // SAFETY: the safe setter stores the indices with their count.
        let families = unsafe {
            crate::retention::raw_slice(info.p_queue_family_indices, info.queue_family_index_count)
        };
        concurrent_families(
            device.parent(),
            families,
            "VUID-VkImageCreateInfo-sharingMode-01420",
        )?;
    }
    let sparse = vk::ImageCreateFlags::SPARSE_BINDING
        | vk::ImageCreateFlags::SPARSE_RESIDENCY
        | vk::ImageCreateFlags::SPARSE_ALIASED;
    if flags.intersects(sparse) {
        if info
            .usage
            .contains(vk::ImageUsageFlags::TRANSIENT_ATTACHMENT)
        {
            refuse(
                "VUID-VkImageCreateInfo-None-01925",
                format!("a sparse image ({flags:?}) is not a transient attachment"),
            )?;
        }
        if flags.contains(vk::ImageCreateFlags::PROTECTED) {
            refuse(
                "VUID-VkImageCreateInfo-None-01891",
                format!("a sparse image ({flags:?}) is not protected"),
            )?;
        }
    }
    let split = vk::ImageCreateFlags::SPLIT_INSTANCE_BIND_REGIONS;
    if flags.contains(split) {
        let maybe_linear = info.tiling == vk::ImageTiling::LINEAR;
        if info.mip_levels != 1
            || info.array_layers != 1
            || info.image_type != vk::ImageType::TYPE_2D
            || maybe_linear
        {
            refuse(
                "VUID-VkImageCreateInfo-flags-02259",
                format!("an image with SPLIT_INSTANCE_BIND_REGIONS is an optimal 2D image of one level and one layer (mipLevels = {}, arrayLayers = {}, {:?}, {:?})", info.mip_levels, info.array_layers, info.image_type, info.tiling),
            )?;
        }
        if device.live().physical_count() == 1 {
            refuse(
                "VUID-VkImageCreateInfo-physicalDeviceCount-01421",
                "an image with SPLIT_INSTANCE_BIND_REGIONS needs a device of more than one physical device".into(),
            )?;
        }
    }
    let external = external_handle_types(info.p_next);
    if !external.is_empty() && info.initial_layout != vk::ImageLayout::UNDEFINED {
        refuse(
            "VUID-VkImageCreateInfo-pNext-01443",
            format!(
                "an image with external handle types starts in UNDEFINED, not {:?}",
                info.initial_layout
            ),
        )?;
    }
    let physical = device.parent();
    for handle in each_bit(external) {
        let (r, props) = external_image_properties(
            physical,
            vk::PhysicalDeviceImageFormatInfo2::default()
                .format(info.format)
                .ty(info.image_type)
                .tiling(info.tiling)
                .usage(info.usage)
                .flags(info.flags),
            handle,
        );
        let compatible = props.compatible_handle_types;
        if r != vk::Result::SUCCESS || !compatible.contains(external) {
            refuse(
                "VUID-VkImageCreateInfo-pNext-00990",
                format!("the external handle types {external:?} are not all compatible with {handle:?} for this image: the physical device reports {compatible:?} ({r:?})"),
            )?;
        }
    }
    Ok(())
}

/// The rules of formats that need a sampler Y'CbCr conversion and of multi-planar
/// ones, and of a multisampled depth/stencil image's stencil storage usage.
fn chroma_rules(
    device: &Device,
    info: &vk::ImageCreateInfo<'_>,
    stencil: Option<&vk::ImageStencilUsageCreateInfo<'_>>,
) -> Result<()> {
    let (format, e) = (info.format, info.extent);
    if let Some(chroma) = crate::formats::chroma(format) {
        if info.mip_levels != 1 {
            refuse(
                "VUID-VkImageCreateInfo-format-06410",
                format!("an image of {format:?}, which needs a Y'CbCr conversion, has one level, not {}", info.mip_levels),
            )?;
        }
        if info.samples != vk::SampleCountFlags::TYPE_1 {
            refuse(
                "VUID-VkImageCreateInfo-format-06411",
                format!("an image of {format:?}, which needs a Y'CbCr conversion, has one sample, not {:?}", info.samples),
            )?;
        }
        if info.image_type != vk::ImageType::TYPE_2D {
            refuse(
                "VUID-VkImageCreateInfo-format-06412",
                format!(
                    "an image of {format:?}, which needs a Y'CbCr conversion, is 2D, not {:?}",
                    info.image_type
                ),
            )?;
        }
        if matches!(chroma, 420 | 422) && e.width % 2 != 0 {
            refuse(
                "VUID-VkImageCreateInfo-format-04712",
                format!("an image of {format:?} has an even width, not {}", e.width),
            )?;
        }
        if chroma == 420 && e.height % 2 != 0 {
            refuse(
                "VUID-VkImageCreateInfo-format-04713",
                format!(
                    "an image of {format:?} has an even height, not {}",
                    e.height
                ),
            )?;
        }
    }
    let multi_planar =
        crate::formats::aspects(format).is_some_and(|a| a.contains(vk::ImageAspectFlags::PLANE_0));
    if multi_planar && info.flags.contains(vk::ImageCreateFlags::DISJOINT) {
        let props = device.parent().get_format_properties(format)?;
        let features = if info.tiling == vk::ImageTiling::LINEAR {
            props.linear_tiling_features
        } else {
            props.optimal_tiling_features
        };
        if !features.contains(vk::FormatFeatureFlags::DISJOINT) {
            refuse(
                "VUID-VkImageCreateInfo-imageCreateFormatFeatures-02260",
                format!("a disjoint image of {format:?} needs VK_FORMAT_FEATURE_DISJOINT_BIT, which the format's {:?} features lack", info.tiling),
            )?;
        }
    }
    let depth_stencil = crate::formats::aspects(format)
        .is_some_and(|a| a.intersects(vk::ImageAspectFlags::DEPTH | vk::ImageAspectFlags::STENCIL));
    let storage_stencil =
        stencil.is_some_and(|s| s.stencil_usage.contains(vk::ImageUsageFlags::STORAGE));
    if depth_stencil
        && storage_stencil
        && info.samples != vk::SampleCountFlags::TYPE_1
        && device.live().features().shader_storage_image_multisample == vk::FALSE
    {
        refuse(
            "VUID-VkImageCreateInfo-format-02538",
            format!("a multisampled ({:?}) depth/stencil image with a storage stencil usage needs shaderStorageImageMultisample", info.samples),
        )?;
    }
    Ok(())
}
