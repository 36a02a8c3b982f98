//! Creations whose rules read several values at once: a device's queues and
//! feature structs, an allocation's memory type and flags, a descriptor set layout's
//! bindings and binding flags, and a sampler's filters and modes.
//!
//! Each case breaks one rule. tuff must refuse the safe call with the rule's VUID;
//! the validation layer, for the `_unchecked` twin (with a messenger that makes it
//! skip a call it finds wrong), must name that VUID and nothing else but the rules
//! the case says the same change breaks, or say nothing (the rule is then proven by
//! the error alone).
//!
//! SAFETY of the `unsafe` blocks: the methods are `unsafe` for rules their
//! `# Safety` sections list, which these calls keep but for the one each case
//! breaks on purpose, which tuff refuses and the layer skips.

#[path = "common/tuff_setup.rs"]
mod tuff_setup;
#[path = "common/vulkan.rs"]
mod vulkan;

use tuff::{vk, Handle as _};
use tuff_setup::Setup;

/// Runs `unchecked` with the layer told to skip erroring calls, and returns what it
/// said.
fn under_layer(s: &Setup, unchecked: impl FnOnce()) -> Vec<String> {
    s.messages.take();
    s.messages.abort_on_error(true);
    unchecked();
    s.messages.abort_on_error(false);
    s.messages.take()
}

/// Rules the 1.3.239 layer reports under the VUID a later registry gives them; its
/// message states the rule.
const RENAMED: &[(&str, &str)] = &[(
    "VUID-VkDescriptorSetLayoutBinding-descriptorType-02210",
    "VUID-VkDescriptorSetLayoutBinding-descriptorType-08004",
)];

/// What the cases saw: failures, and the rules the layer named or left to the error.
#[derive(Default)]
struct Verdicts {
    failures: Vec<String>,
    by_layer: usize,
    alone: Vec<&'static str>,
}

impl Verdicts {
    /// Judges one case: the safe call's result and what the layer said of the
    /// unchecked one, with the rules the same change breaks too.
    fn judge(
        &mut self,
        vuid: &'static str,
        also: &[&str],
        safe: tuff::Result<()>,
        layer: Vec<String>,
    ) {
        match &safe {
            Err(tuff::Error::Validation { vuid: got, .. }) if *got == vuid => {}
            other => {
                self.failures
                    .push(format!("{vuid}: the safe method returned {other:?}"));
                return;
            }
        }
        let names = |m: &String, v: &str| {
            m.contains(&format!("[ {v} ]"))
                || RENAMED
                    .iter()
                    .any(|(rule, name)| *rule == v && m.contains(&format!("[ {name} ]")))
        };
        let implied = |m: &String| also.iter().any(|a| names(m, a));
        if layer.iter().all(implied) {
            self.alone.push(vuid);
        } else if layer.iter().any(|m| names(m, vuid))
            && layer.iter().all(|m| names(m, vuid) || implied(m))
        {
            self.by_layer += 1;
        } else {
            self.failures.push(format!(
                "{vuid}: the layer said something else:\n  {}",
                layer.join("\n  ")
            ));
        }
    }

    fn finish(self, what: &str) {
        println!(
            "{what}: the layer named {}, the error alone proves {} ({})",
            self.by_layer,
            self.alone.len(),
            self.alone.join(", ")
        );
        assert!(self.failures.is_empty(), "{}", self.failures.join("\n"));
    }
}

/// A device create info's parts a case can change.
#[derive(Clone)]
struct DeviceParts {
    queues: Vec<(u32, vk::DeviceQueueCreateFlags, Vec<f32>)>,
    features2: bool,
    enabled_features: bool,
    /// Chain a core version's features struct and one of the structs it took over.
    both: Option<u32>,
    /// Device extensions to enable.
    extensions: Vec<&'static core::ffi::CStr>,
    /// Chain a multiview features struct: multiview, its geometry and tessellation
    /// shader features.
    multiview: Option<[bool; 3]>,
    /// Chain a variable pointers features struct: variablePointersStorageBuffer and
    /// variablePointers.
    pointers: Option<[bool; 2]>,
    /// Chain a device group create info that names the physical device this many
    /// times.
    group: usize,
}

impl Default for DeviceParts {
    fn default() -> Self {
        DeviceParts {
            queues: vec![(0, vk::DeviceQueueCreateFlags::empty(), vec![1.0])],
            features2: false,
            enabled_features: false,
            both: None,
            extensions: Vec::new(),
            multiview: None,
            pointers: None,
            group: 0,
        }
    }
}

fn create_device(s: &Setup, p: &DeviceParts) -> (tuff::Result<()>, Vec<String>) {
    let queues: Vec<_> = p
        .queues
        .iter()
        .map(|(family, flags, priorities)| {
            tuff::DeviceQueueCreateInfo::new()
                .flags(*flags)
                .queue_family_index(*family)
                .queue_priorities(priorities)
        })
        .collect();
    let features = vk::PhysicalDeviceFeatures::default();
    let mut features2 = tuff::PhysicalDeviceFeatures2::new();
    let mut v11 = tuff::PhysicalDeviceVulkan11Features::new();
    let mut multiview = tuff::PhysicalDeviceMultiviewFeatures::new();
    let mut v12 = tuff::PhysicalDeviceVulkan12Features::new();
    let mut timeline = tuff::PhysicalDeviceTimelineSemaphoreFeatures::new();
    let mut v13 = tuff::PhysicalDeviceVulkan13Features::new();
    let mut sync2 = tuff::PhysicalDeviceSynchronization2Features::new();
    let [view, geometry, tessellation] = p.multiview.unwrap_or_default();
    let mut views = tuff::PhysicalDeviceMultiviewFeatures::new()
        .multiview(view)
        .multiview_geometry_shader(geometry)
        .multiview_tessellation_shader(tessellation);
    let [storage, variable] = p.pointers.unwrap_or_default();
    let mut pointers = tuff::PhysicalDeviceVariablePointersFeatures::new()
        .variable_pointers_storage_buffer(storage)
        .variable_pointers(variable);
    let members = vec![&s.physical; p.group];
    let members = tuff::HandleSlice::new(&members);
    let mut group = tuff::DeviceGroupDeviceCreateInfo::new().physical_devices(&members);
    let extensions: Vec<tuff::CStrPtr<'_>> = p
        .extensions
        .iter()
        .map(|e| tuff::CStrPtr::from(*e))
        .collect();
    let mut info = tuff::DeviceCreateInfo::new()
        .queue_create_infos(&queues)
        .enabled_extension_names(&extensions);
    if p.multiview.is_some() {
        info = info.push_next(&mut views);
    }
    if p.pointers.is_some() {
        info = info.push_next(&mut pointers);
    }
    if p.group > 0 {
        info = info.push_next(&mut group);
    }
    if p.enabled_features {
        info = info.enabled_features(Some(&features));
    }
    if p.features2 {
        info = info.push_next(&mut features2);
    }
    match p.both {
        Some(1) => info = info.push_next(&mut v11).push_next(&mut multiview),
        Some(2) => info = info.push_next(&mut v12).push_next(&mut timeline),
        Some(3) => info = info.push_next(&mut v13).push_next(&mut sync2),
        _ => {}
    }
    let safe = s.physical.create_device(&info).map(drop);
    let layer = under_layer(s, || {
        let _ = unsafe { s.physical.create_device_unchecked(&info) };
    });
    // After skipping a device creation the layer also says that it made no device,
    // naming no rule.
    let layer = layer
        .into_iter()
        .filter(|m| !m.contains("vkCreateDevice:  Failed to create device chain."))
        .collect();
    (safe, layer)
}

#[test]
fn device_creation_rules_are_refused_and_the_layer_agrees() {
    let _serial = vulkan::serial();
    let s = tuff_setup::setup(true);
    let (safe, layer) = create_device(&s, &DeviceParts::default());
    assert!(
        safe.is_ok() && layer.is_empty(),
        "the valid device: {safe:?} {layer:?}"
    );
    let none = vk::DeviceQueueCreateFlags::empty();
    let cases: [(&str, &[&str], DeviceParts); 14] = [
        (
            // The test's instance has no VK_KHR_surface.
            "VUID-vkCreateDevice-ppEnabledExtensionNames-01387",
            &[],
            DeviceParts {
                extensions: vec![c"VK_KHR_swapchain"],
                ..Default::default()
            },
        ),
        (
            "VUID-VkPhysicalDeviceMultiviewFeatures-multiviewGeometryShader-00580",
            &[],
            DeviceParts {
                multiview: Some([false, true, false]),
                ..Default::default()
            },
        ),
        (
            "VUID-VkPhysicalDeviceMultiviewFeatures-multiviewTessellationShader-00581",
            &[],
            DeviceParts {
                multiview: Some([false, false, true]),
                ..Default::default()
            },
        ),
        (
            "VUID-VkPhysicalDeviceVariablePointersFeatures-variablePointers-01431",
            &[],
            DeviceParts {
                pointers: Some([false, true]),
                ..Default::default()
            },
        ),
        (
            "VUID-VkDeviceGroupDeviceCreateInfo-pPhysicalDevices-00375",
            &[],
            DeviceParts {
                group: 2,
                ..Default::default()
            },
        ),
        (
            "VUID-VkDeviceCreateInfo-pNext-00373",
            &[],
            DeviceParts {
                features2: true,
                enabled_features: true,
                ..Default::default()
            },
        ),
        (
            "VUID-VkDeviceCreateInfo-pNext-02829",
            &[],
            DeviceParts {
                both: Some(1),
                ..Default::default()
            },
        ),
        (
            "VUID-VkDeviceCreateInfo-pNext-02830",
            &[],
            DeviceParts {
                both: Some(2),
                ..Default::default()
            },
        ),
        (
            "VUID-VkDeviceCreateInfo-pNext-06532",
            &[],
            DeviceParts {
                both: Some(3),
                ..Default::default()
            },
        ),
        (
            "VUID-VkDeviceQueueCreateInfo-queueFamilyIndex-00381",
            &[],
            DeviceParts {
                queues: vec![(64, none, vec![1.0])],
                ..Default::default()
            },
        ),
        (
            "VUID-VkDeviceQueueCreateInfo-queueCount-00382",
            &[],
            DeviceParts {
                queues: vec![(0, none, vec![1.0; 64])],
                ..Default::default()
            },
        ),
        (
            "VUID-VkDeviceQueueCreateInfo-pQueuePriorities-00383",
            &[],
            DeviceParts {
                queues: vec![(0, none, vec![2.0])],
                ..Default::default()
            },
        ),
        (
            "VUID-VkDeviceQueueCreateInfo-flags-02861",
            // The test's physical device has no protected queues either.
            &["VUID-VkDeviceQueueCreateInfo-flags-06449"],
            DeviceParts {
                queues: vec![(0, vk::DeviceQueueCreateFlags::PROTECTED, vec![1.0])],
                ..Default::default()
            },
        ),
        (
            "VUID-VkDeviceCreateInfo-queueFamilyIndex-02802",
            &[],
            DeviceParts {
                queues: vec![(0, none, vec![1.0]), (0, none, vec![1.0])],
                ..Default::default()
            },
        ),
    ];
    let mut v = Verdicts::default();
    for (vuid, also, parts) in cases {
        let (safe, layer) = create_device(&s, &parts);
        v.judge(vuid, also, safe, layer);
    }
    v.finish("device creation");
}

#[test]
fn allocation_rules_are_refused_and_the_layer_agrees() {
    let _serial = vulkan::serial();
    let s = tuff_setup::setup(true);
    let memory = s.physical.get_memory_properties();
    let buffer = s
        .device
        .create_buffer(
            &tuff::BufferCreateInfo::new()
                .size(1024)
                .usage(vk::BufferUsageFlags::TRANSFER_SRC),
        )
        .expect("buffer");
    let image = s
        .device
        .create_image(&tuff_setup::rgba8_image_info(
            16,
            vk::ImageUsageFlags::TRANSFER_SRC,
        ))
        .expect("image");
    let buffer_size = s
        .device
        .get_buffer_memory_requirements(&buffer)
        .expect("requirements")
        .size;
    let allocate = |p: Alloc<'_>| {
        let mut flags = tuff::MemoryAllocateFlagsInfo::new()
            .flags(p.flags)
            .device_mask(p.mask);
        let mut address =
            tuff::MemoryOpaqueCaptureAddressAllocateInfo::new().opaque_capture_address(p.capture);
        let mut dedicated = tuff::MemoryDedicatedAllocateInfo::new()
            .image(p.image)
            .buffer(p.buffer);
        let mut export = tuff::ExportMemoryAllocateInfo::new().handle_types(p.export);
        let mut info = tuff::MemoryAllocateInfo::new()
            .allocation_size(p.size)
            .memory_type_index(p.index)
            .push_next(&mut flags)
            .push_next(&mut address);
        if p.image.is_some() || p.buffer.is_some() {
            info = info.push_next(&mut dedicated);
        }
        if !p.export.is_empty() {
            info = info.push_next(&mut export);
        }
        let safe = s.device.allocate_memory(&info).map(drop);
        let layer = under_layer(&s, || {
            let _ = unsafe { s.device.allocate_memory_unchecked(&info) };
        });
        (safe, layer)
    };
    let (safe, layer) = allocate(Alloc::default());
    assert!(
        safe.is_ok() && layer.is_empty(),
        "the valid allocation: {safe:?} {layer:?}"
    );
    let (safe, layer) = allocate(Alloc {
        size: buffer_size,
        buffer: Some(&buffer),
        ..Alloc::default()
    });
    assert!(
        safe.is_ok() && layer.is_empty(),
        "the valid dedicated allocation: {safe:?} {layer:?}"
    );
    let heap = memory.memory_heaps[memory.memory_types[0].heap_index as usize].size;
    let mut v = Verdicts::default();
    let masked = vk::MemoryAllocateFlags::DEVICE_MASK;
    for (vuid, also, p) in [
        (
            "VUID-vkAllocateMemory-pAllocateInfo-01714",
            &[][..],
            Alloc {
                index: memory.memory_type_count,
                ..Alloc::default()
            },
        ),
        (
            "VUID-vkAllocateMemory-pAllocateInfo-01713",
            &[],
            Alloc {
                size: heap + 1,
                ..Alloc::default()
            },
        ),
        (
            "VUID-VkMemoryAllocateInfo-flags-03330",
            &[],
            Alloc {
                flags: vk::MemoryAllocateFlags::DEVICE_ADDRESS_CAPTURE_REPLAY,
                ..Alloc::default()
            },
        ),
        (
            "VUID-VkMemoryAllocateInfo-flags-03331",
            &[],
            Alloc {
                flags: vk::MemoryAllocateFlags::DEVICE_ADDRESS,
                ..Alloc::default()
            },
        ),
        (
            "VUID-VkMemoryAllocateInfo-opaqueCaptureAddress-03329",
            &[],
            Alloc {
                capture: 0x1000,
                ..Alloc::default()
            },
        ),
        (
            "VUID-VkMemoryAllocateFlagsInfo-deviceMask-00676",
            &[],
            Alloc {
                flags: masked,
                mask: 0,
                ..Alloc::default()
            },
        ),
        (
            "VUID-VkMemoryAllocateFlagsInfo-deviceMask-00675",
            &[],
            Alloc {
                flags: masked,
                mask: 0b10,
                ..Alloc::default()
            },
        ),
        (
            "VUID-VkMemoryDedicatedAllocateInfo-image-01432",
            &[],
            Alloc {
                image: Some(&image),
                buffer: Some(&buffer),
                ..Alloc::default()
            },
        ),
        (
            "VUID-VkMemoryDedicatedAllocateInfo-image-01433",
            &[],
            Alloc {
                size: 1 << 20,
                image: Some(&image),
                ..Alloc::default()
            },
        ),
        (
            "VUID-VkMemoryDedicatedAllocateInfo-buffer-01435",
            &[],
            Alloc {
                size: buffer_size + 64,
                buffer: Some(&buffer),
                ..Alloc::default()
            },
        ),
        (
            "VUID-VkExportMemoryAllocateInfo-handleTypes-00656",
            &[],
            Alloc {
                size: buffer_size,
                buffer: Some(&buffer),
                export: vk::ExternalMemoryHandleTypeFlags::D3D11_TEXTURE,
                ..Alloc::default()
            },
        ),
    ] {
        let (safe, layer) = allocate(p);
        v.judge(vuid, also, safe, layer);
    }
    v.finish("allocation");
    // An export without a dedicated object has no properties to check it against.
    let (safe, _) = allocate(Alloc {
        export: vk::ExternalMemoryHandleTypeFlags::OPAQUE_FD,
        ..Alloc::default()
    });
    assert!(
        matches!(safe, Err(tuff::Error::Misuse(_))),
        "an export without a dedicated object: {safe:?}"
    );
}

/// An allocate info's parts a case can change.
struct Alloc<'a> {
    size: u64,
    index: u32,
    flags: vk::MemoryAllocateFlags,
    mask: u32,
    capture: u64,
    image: Option<&'a tuff::Image>,
    buffer: Option<&'a tuff::Buffer>,
    export: vk::ExternalMemoryHandleTypeFlags,
}

impl Default for Alloc<'_> {
    fn default() -> Self {
        Alloc {
            size: 64,
            index: 0,
            flags: vk::MemoryAllocateFlags::empty(),
            mask: 0,
            capture: 0,
            image: None,
            buffer: None,
            export: vk::ExternalMemoryHandleTypeFlags::empty(),
        }
    }
}

/// One binding of a descriptor set layout: binding number, type, count, stages and
/// binding flags.
type Binding = (
    u32,
    vk::DescriptorType,
    u32,
    vk::ShaderStageFlags,
    vk::DescriptorBindingFlags,
);

fn create_set_layout(
    s: &Setup,
    bindings: &[Binding],
    flag_count: Option<usize>,
) -> (tuff::Result<()>, Vec<String>) {
    let list: Vec<_> = bindings
        .iter()
        .map(|&(binding, ty, count, stages, _)| {
            tuff::DescriptorSetLayoutBinding::new()
                .binding(binding)
                .descriptor_type(ty)
                .descriptor_count(count)
                .stage_flags(stages)
        })
        .collect();
    let flags: Vec<_> = bindings.iter().map(|b| b.4).collect();
    let flags = &flags[..flag_count.unwrap_or(flags.len())];
    let mut binding_flags =
        tuff::DescriptorSetLayoutBindingFlagsCreateInfo::new().binding_flags(flags);
    let after_bind = flags
        .iter()
        .any(|f| f.contains(vk::DescriptorBindingFlags::UPDATE_AFTER_BIND));
    let mut info = tuff::DescriptorSetLayoutCreateInfo::new()
        .bindings(&list)
        .push_next(&mut binding_flags);
    if after_bind {
        info = info.flags(vk::DescriptorSetLayoutCreateFlags::UPDATE_AFTER_BIND_POOL);
    }
    let safe = s.device.create_descriptor_set_layout(&info).map(drop);
    let layer = under_layer(s, || {
        let _ = unsafe { s.device.create_descriptor_set_layout_unchecked(&info) };
    });
    (safe, layer)
}

#[test]
fn set_layout_rules_are_refused_and_the_layer_agrees() {
    let _serial = vulkan::serial();
    let s = tuff_setup::setup(true);
    let full = tuff_setup::setup_full_features(true);
    let compute = vk::ShaderStageFlags::COMPUTE;
    let fragment = vk::ShaderStageFlags::FRAGMENT;
    let no = vk::DescriptorBindingFlags::empty();
    let after = vk::DescriptorBindingFlags::UPDATE_AFTER_BIND;
    let ty = vk::DescriptorType::UNIFORM_BUFFER;
    let valid: [Binding; 2] = [(0, ty, 1, compute, no), (1, ty, 1, compute, no)];
    let (safe, layer) = create_set_layout(&s, &valid, None);
    assert!(
        safe.is_ok() && layer.is_empty(),
        "the valid layout: {safe:?} {layer:?}"
    );
    let block = vk::DescriptorType::INLINE_UNIFORM_BLOCK;
    let max_block = {
        let mut p13 = vk::PhysicalDeviceVulkan13Properties::default();
        let mut p2 = vk::PhysicalDeviceProperties2::default().push_next(&mut p13);
        // SAFETY: a live physical device of a Vulkan 1.3 instance; the chain is local.
        unsafe {
            full.instance
                .fns()
                .get_physical_device_properties2(full.physical.raw(), &mut p2)
        };
        p13.max_inline_uniform_block_size
    };
    let mut v = Verdicts::default();
    let mut run = |s: &Setup, vuid: &'static str, bindings: &[Binding], count: Option<usize>| {
        let (safe, layer) = create_set_layout(s, bindings, count);
        v.judge(vuid, &[], safe, layer);
    };
    run(
        &s,
        "VUID-VkDescriptorSetLayoutBinding-descriptorCount-00283",
        &[(0, ty, 1, vk::ShaderStageFlags::from_raw(0x4000_0000), no)],
        None,
    );
    run(
        &s,
        "VUID-VkDescriptorSetLayoutCreateInfo-binding-00279",
        &[(0, ty, 1, compute, no), (0, ty, 1, compute, no)],
        None,
    );
    run(
        &s,
        "VUID-VkDescriptorSetLayoutBinding-descriptorType-01510",
        &[(0, vk::DescriptorType::INPUT_ATTACHMENT, 1, compute, no)],
        None,
    );
    run(
        &full,
        "VUID-VkDescriptorSetLayoutBinding-descriptorType-02210",
        &[(0, block, (max_block + 4) & !3, fragment, no)],
        None,
    );
    run(
        &s,
        "VUID-VkDescriptorSetLayoutBindingFlagsCreateInfo-bindingCount-03002",
        &valid,
        Some(1),
    );
    for (ty, vuid) in [
        (
            vk::DescriptorType::UNIFORM_BUFFER,
            "VUID-VkDescriptorSetLayoutBindingFlagsCreateInfo-descriptorBindingUniformBufferUpdateAfterBind-03005",
        ),
        (
            vk::DescriptorType::SAMPLED_IMAGE,
            "VUID-VkDescriptorSetLayoutBindingFlagsCreateInfo-descriptorBindingSampledImageUpdateAfterBind-03006",
        ),
        (
            vk::DescriptorType::STORAGE_IMAGE,
            "VUID-VkDescriptorSetLayoutBindingFlagsCreateInfo-descriptorBindingStorageImageUpdateAfterBind-03007",
        ),
        (
            vk::DescriptorType::STORAGE_BUFFER,
            "VUID-VkDescriptorSetLayoutBindingFlagsCreateInfo-descriptorBindingStorageBufferUpdateAfterBind-03008",
        ),
        (
            vk::DescriptorType::UNIFORM_TEXEL_BUFFER,
            "VUID-VkDescriptorSetLayoutBindingFlagsCreateInfo-descriptorBindingUniformTexelBufferUpdateAfterBind-03009",
        ),
        (
            vk::DescriptorType::STORAGE_TEXEL_BUFFER,
            "VUID-VkDescriptorSetLayoutBindingFlagsCreateInfo-descriptorBindingStorageTexelBufferUpdateAfterBind-03010",
        ),
    ] {
        run(&s, vuid, &[(0, ty, 1, compute, after)], None);
    }
    run(
        &s,
        "VUID-VkDescriptorSetLayoutBindingFlagsCreateInfo-None-03011",
        &[(0, vk::DescriptorType::INPUT_ATTACHMENT, 1, fragment, after)],
        None,
    );
    for (flag, vuid) in [
        (
            vk::DescriptorBindingFlags::UPDATE_UNUSED_WHILE_PENDING,
            "VUID-VkDescriptorSetLayoutBindingFlagsCreateInfo-descriptorBindingUpdateUnusedWhilePending-03012",
        ),
        (
            vk::DescriptorBindingFlags::PARTIALLY_BOUND,
            "VUID-VkDescriptorSetLayoutBindingFlagsCreateInfo-descriptorBindingPartiallyBound-03013",
        ),
        (
            vk::DescriptorBindingFlags::VARIABLE_DESCRIPTOR_COUNT,
            "VUID-VkDescriptorSetLayoutBindingFlagsCreateInfo-descriptorBindingVariableDescriptorCount-03014",
        ),
    ] {
        run(&s, vuid, &[(0, ty, 1, compute, flag)], None);
    }
    v.finish("descriptor set layouts");
}

/// A sampler's parts a case can change.
#[derive(Clone, Copy)]
struct SamplerParts {
    min: vk::Filter,
    unnormalized: bool,
    mode: vk::SamplerAddressMode,
    compare: bool,
    reduction: vk::SamplerReductionMode,
    border: vk::BorderColor,
    compare_op: vk::CompareOp,
}

fn create_sampler(s: &Setup, p: SamplerParts) -> (tuff::Result<()>, Vec<String>) {
    let mut reduction = tuff::SamplerReductionModeCreateInfo::new().reduction_mode(p.reduction);
    let info = tuff::SamplerCreateInfo::new()
        .min_filter(p.min)
        .mag_filter(vk::Filter::NEAREST)
        .mipmap_mode(vk::SamplerMipmapMode::NEAREST)
        .address_mode_u(p.mode)
        .address_mode_v(p.mode)
        .address_mode_w(p.mode)
        .unnormalized_coordinates(p.unnormalized)
        .compare_enable(p.compare)
        .compare_op(p.compare_op)
        .border_color(p.border)
        .push_next(&mut reduction);
    let safe = s.device.create_sampler(&info).map(drop);
    let layer = under_layer(s, || {
        let _ = unsafe { s.device.create_sampler_unchecked(&info) };
    });
    (safe, layer)
}

#[test]
fn sampler_rules_are_refused_and_the_layer_agrees() {
    let _serial = vulkan::serial();
    let s = tuff_setup::setup(true);
    let full = tuff_setup::setup_full_features(true);
    let valid = SamplerParts {
        min: vk::Filter::NEAREST,
        unnormalized: false,
        mode: vk::SamplerAddressMode::CLAMP_TO_EDGE,
        compare: false,
        reduction: vk::SamplerReductionMode::WEIGHTED_AVERAGE,
        border: vk::BorderColor::FLOAT_TRANSPARENT_BLACK,
        compare_op: vk::CompareOp::NEVER,
    };
    // Read where used: a border colour for a border clamp, a compare op for a
    // comparing sampler.
    let border = SamplerParts {
        mode: vk::SamplerAddressMode::CLAMP_TO_BORDER,
        border: vk::BorderColor::INT_OPAQUE_WHITE,
        ..valid
    };
    let comparing = SamplerParts {
        compare: true,
        compare_op: vk::CompareOp::LESS,
        ..valid
    };
    for s in [&s, &full] {
        for parts in [valid, border, comparing] {
            let (safe, layer) = create_sampler(s, parts);
            assert!(
                safe.is_ok() && layer.is_empty(),
                "the valid sampler: {safe:?} {layer:?}"
            );
        }
    }
    // Values the rules ask for only where they are read are asked for always, as
    // drivers read them whatever the modes (lavapipe crashes on an invalid border
    // colour of a sampler that never clamps to the border).
    for (rule, parts) in [
        (
            "VUID-VkSamplerCreateInfo-addressModeU-01078",
            SamplerParts {
                border: vk::BorderColor::from_raw(99),
                ..valid
            },
        ),
        (
            "VUID-VkSamplerCreateInfo-compareEnable-01080",
            SamplerParts {
                compare_op: vk::CompareOp::from_raw(99),
                ..valid
            },
        ),
    ] {
        let info = tuff::SamplerCreateInfo::new()
            .border_color(parts.border)
            .compare_op(parts.compare_op);
        assert_eq!(tuff_setup::vuid(s.device.create_sampler(&info)), rule);
    }
    let mut v = Verdicts::default();
    for (s, vuid, parts) in [
        (
            &s,
            "VUID-VkSamplerCreateInfo-unnormalizedCoordinates-01072",
            SamplerParts {
                min: vk::Filter::LINEAR,
                unnormalized: true,
                ..valid
            },
        ),
        (
            &s,
            "VUID-VkSamplerCreateInfo-addressModeU-01079",
            SamplerParts {
                mode: vk::SamplerAddressMode::MIRROR_CLAMP_TO_EDGE,
                ..valid
            },
        ),
        (
            &s,
            "VUID-VkSamplerCreateInfo-pNext-06726",
            SamplerParts {
                reduction: vk::SamplerReductionMode::MIN,
                ..valid
            },
        ),
        (
            &s,
            "VUID-VkSamplerCreateInfo-addressModeU-01078",
            SamplerParts {
                border: vk::BorderColor::from_raw(99),
                ..border
            },
        ),
        (
            &s,
            "VUID-VkSamplerCreateInfo-compareEnable-01080",
            SamplerParts {
                compare_op: vk::CompareOp::from_raw(99),
                ..comparing
            },
        ),
        (
            &full,
            "VUID-VkSamplerCreateInfo-compareEnable-01423",
            SamplerParts {
                reduction: vk::SamplerReductionMode::MIN,
                ..comparing
            },
        ),
    ] {
        let (safe, layer) = create_sampler(s, parts);
        v.judge(vuid, &[], safe, layer);
    }
    v.finish("samplers");
}

/// A device makes at most `maxSamplerAllocationCount` samplers: the next is refused
/// with the rule's VUID and the layer names it for the unchecked call; once one
/// goes, a new one is made again.
#[test]
fn samplers_are_counted_against_the_limit() {
    let _serial = vulkan::serial();
    let s = tuff_setup::setup(true);
    let max = s
        .physical
        .get_properties()
        .limits
        .max_sampler_allocation_count;
    assert!(
        max <= 1 << 20,
        "a limit of {max} samplers is more than the test makes"
    );
    let info = tuff::SamplerCreateInfo::new();
    let mut samplers: Vec<_> = (0..max)
        .map(|_| s.device.create_sampler(&info).expect("below the limit"))
        .collect();
    let safe = s.device.create_sampler(&info).map(drop);
    let layer = under_layer(&s, || {
        // SAFETY: the layer skips the call, which breaks only the count.
        let _ = unsafe { s.device.create_sampler_unchecked(&info) };
    });
    let mut v = Verdicts::default();
    v.judge(
        "VUID-vkCreateSampler-maxSamplerAllocationCount-04110",
        &[],
        safe,
        layer,
    );
    v.finish("sampler count");
    samplers.pop();
    samplers.push(s.device.create_sampler(&info).expect("one went"));
    drop(samplers);
    vulkan::assert_silent(&s.messages);
}

/// An image create info's parts a case can change.
#[derive(Clone, Copy)]
struct ImageParts {
    ty: vk::ImageType,
    format: vk::Format,
    extent: vk::Extent3D,
    mip_levels: u32,
    layers: u32,
    samples: vk::SampleCountFlags,
    flags: vk::ImageCreateFlags,
    usage: vk::ImageUsageFlags,
    stencil_usage: Option<vk::ImageUsageFlags>,
    view_formats: usize,
    /// A view format other than the two `view_formats` picks from, listed third.
    other_view: Option<vk::Format>,
    /// Queue families of a concurrent image (exclusive when empty).
    families: &'static [u32],
    external: vk::ExternalMemoryHandleTypeFlags,
    initial_layout: vk::ImageLayout,
}

const IMAGE: ImageParts = ImageParts {
    ty: vk::ImageType::TYPE_2D,
    format: vk::Format::R8G8B8A8_UNORM,
    extent: vk::Extent3D {
        width: 4,
        height: 4,
        depth: 1,
    },
    mip_levels: 1,
    layers: 1,
    samples: vk::SampleCountFlags::TYPE_1,
    flags: vk::ImageCreateFlags::empty(),
    usage: vk::ImageUsageFlags::SAMPLED,
    stencil_usage: None,
    view_formats: 0,
    other_view: None,
    families: &[],
    external: vk::ExternalMemoryHandleTypeFlags::empty(),
    initial_layout: vk::ImageLayout::UNDEFINED,
};

fn create_image(s: &Setup, p: ImageParts) -> (tuff::Result<()>, Vec<String>) {
    let mut formats = [p.format, vk::Format::R8G8B8A8_SRGB][..p.view_formats].to_vec();
    formats.extend(p.other_view);
    let mut list = tuff::ImageFormatListCreateInfo::new().view_formats(&formats);
    let mut external = tuff::ExternalMemoryImageCreateInfo::new().handle_types(p.external);
    let mut stencil =
        tuff::ImageStencilUsageCreateInfo::new().stencil_usage(p.stencil_usage.unwrap_or_default());
    let mut info = tuff::ImageCreateInfo::new()
        .flags(p.flags)
        .image_type(p.ty)
        .format(p.format)
        .extent(p.extent)
        .mip_levels(p.mip_levels)
        .array_layers(p.layers)
        .samples(p.samples)
        .usage(p.usage)
        .initial_layout(p.initial_layout);
    if !p.families.is_empty() {
        info = info
            .sharing_mode(vk::SharingMode::CONCURRENT)
            .queue_family_indices(p.families);
    }
    if !formats.is_empty() {
        info = info.push_next(&mut list);
    }
    if !p.external.is_empty() {
        info = info.push_next(&mut external);
    }
    if p.stencil_usage.is_some() {
        info = info.push_next(&mut stencil);
    }
    let safe = s.device.create_image(&info).map(drop);
    let layer = under_layer(s, || {
        let _ = unsafe { s.device.create_image_unchecked(&info) };
    });
    (safe, layer)
}

#[test]
fn image_rules_are_refused_and_the_layer_agrees() {
    let _serial = vulkan::serial();
    let s = tuff_setup::setup(true);
    let limits = s.physical.get_properties().limits;
    let depth = ImageParts {
        format: vk::Format::D32_SFLOAT_S8_UINT,
        usage: vk::ImageUsageFlags::DEPTH_STENCIL_ATTACHMENT,
        stencil_usage: Some(vk::ImageUsageFlags::DEPTH_STENCIL_ATTACHMENT),
        ..IMAGE
    };
    for valid in [IMAGE, depth] {
        let (safe, layer) = create_image(&s, valid);
        assert!(
            safe.is_ok() && layer.is_empty(),
            "the valid image: {safe:?} {layer:?}"
        );
    }
    let color = vk::ImageUsageFlags::COLOR_ATTACHMENT;
    let transient = vk::ImageUsageFlags::TRANSIENT_ATTACHMENT;
    let ds = vk::ImageUsageFlags::DEPTH_STENCIL_ATTACHMENT;
    let cases: [(&str, &[&str], ImageParts); 14] = [
        (
            "VUID-VkImageCreateInfo-imageType-00956",
            &[],
            ImageParts {
                ty: vk::ImageType::TYPE_1D,
                ..IMAGE
            },
        ),
        (
            "VUID-VkImageCreateInfo-imageType-00954",
            &[],
            ImageParts {
                flags: vk::ImageCreateFlags::CUBE_COMPATIBLE,
                layers: 6,
                extent: vk::Extent3D {
                    width: 4,
                    height: 2,
                    depth: 1,
                },
                ..IMAGE
            },
        ),
        (
            "VUID-VkImageCreateInfo-usage-00966",
            &[],
            ImageParts {
                usage: transient,
                ..IMAGE
            },
        ),
        (
            "VUID-VkImageCreateInfo-samples-02257",
            &[],
            ImageParts {
                samples: vk::SampleCountFlags::TYPE_4,
                mip_levels: 2,
                usage: color,
                ..IMAGE
            },
        ),
        (
            "VUID-VkImageCreateInfo-flags-01572",
            &[],
            ImageParts {
                flags: vk::ImageCreateFlags::BLOCK_TEXEL_VIEW_COMPATIBLE
                    | vk::ImageCreateFlags::MUTABLE_FORMAT,
                ..IMAGE
            },
        ),
        (
            "VUID-VkImageCreateInfo-format-01577",
            &[],
            ImageParts {
                flags: vk::ImageCreateFlags::DISJOINT,
                ..IMAGE
            },
        ),
        (
            "VUID-VkImageCreateInfo-usage-00964",
            // An image wider than the framebuffer limit is wider than the device's
            // 2D images too, on the test's device.
            &["VUID-VkImageCreateInfo-extent-02252"],
            ImageParts {
                usage: color,
                extent: vk::Extent3D {
                    width: limits.max_framebuffer_width + 1,
                    height: 4,
                    depth: 1,
                },
                ..IMAGE
            },
        ),
        (
            "VUID-VkImageCreateInfo-usage-00965",
            &["VUID-VkImageCreateInfo-extent-02253"],
            ImageParts {
                usage: color,
                extent: vk::Extent3D {
                    width: 4,
                    height: limits.max_framebuffer_height + 1,
                    depth: 1,
                },
                ..IMAGE
            },
        ),
        (
            "VUID-VkImageCreateInfo-format-02795",
            &[],
            ImageParts {
                stencil_usage: Some(vk::ImageUsageFlags::SAMPLED),
                ..depth
            },
        ),
        (
            "VUID-VkImageCreateInfo-format-02796",
            &[],
            ImageParts {
                usage: vk::ImageUsageFlags::SAMPLED,
                stencil_usage: Some(ds),
                ..depth
            },
        ),
        (
            "VUID-VkImageCreateInfo-format-02797",
            &[],
            ImageParts {
                usage: ds | transient,
                stencil_usage: Some(ds),
                ..depth
            },
        ),
        (
            "VUID-VkImageCreateInfo-format-02798",
            &[],
            ImageParts {
                stencil_usage: Some(ds | transient),
                ..depth
            },
        ),
        (
            "VUID-VkImageCreateInfo-Format-02536",
            &["VUID-VkImageCreateInfo-extent-02252"],
            ImageParts {
                usage: vk::ImageUsageFlags::SAMPLED,
                stencil_usage: Some(vk::ImageUsageFlags::INPUT_ATTACHMENT),
                extent: vk::Extent3D {
                    width: limits.max_framebuffer_width + 1,
                    height: 4,
                    depth: 1,
                },
                ..depth
            },
        ),
        (
            "VUID-VkImageCreateInfo-flags-04738",
            &[],
            ImageParts {
                view_formats: 2,
                ..IMAGE
            },
        ),
    ];
    let mut v = Verdicts::default();
    for (vuid, also, parts) in cases {
        let (safe, layer) = create_image(&s, parts);
        v.judge(vuid, also, safe, layer);
    }
    v.finish("images");
}

#[test]
fn image_rules_of_sharing_external_memory_and_chroma_are_refused_and_the_layer_agrees() {
    let _serial = vulkan::serial();
    let s = tuff_setup::setup(true);
    let two_planes = vk::Format::G8_B8R8_2PLANE_420_UNORM;
    let cases: [(&str, &[&str], ImageParts); 13] = [
        (
            "VUID-VkImageCreateInfo-format-06411",
            &["VUID-VkImageCreateInfo-imageCreateMaxMipLevels-02251"],
            ImageParts {
                format: two_planes,
                samples: vk::SampleCountFlags::TYPE_4,
                ..IMAGE
            },
        ),
        (
            "VUID-VkImageCreateInfo-imageCreateFormatFeatures-02260",
            &["VUID-VkImageCreateInfo-imageCreateMaxMipLevels-02251"],
            ImageParts {
                format: two_planes,
                flags: vk::ImageCreateFlags::DISJOINT,
                ..IMAGE
            },
        ),
        (
            "VUID-VkImageCreateInfo-format-02538",
            &[],
            ImageParts {
                format: vk::Format::D32_SFLOAT_S8_UINT,
                samples: vk::SampleCountFlags::TYPE_4,
                usage: vk::ImageUsageFlags::DEPTH_STENCIL_ATTACHMENT,
                stencil_usage: Some(
                    vk::ImageUsageFlags::DEPTH_STENCIL_ATTACHMENT | vk::ImageUsageFlags::STORAGE,
                ),
                ..IMAGE
            },
        ),
        (
            // Lavapipe has one queue family.
            "VUID-VkImageCreateInfo-sharingMode-01420",
            &[],
            ImageParts {
                families: &[0, 1],
                ..IMAGE
            },
        ),
        (
            "VUID-VkImageCreateInfo-pNext-06722",
            &[],
            ImageParts {
                flags: vk::ImageCreateFlags::MUTABLE_FORMAT,
                other_view: Some(vk::Format::R16G16B16A16_SFLOAT),
                ..IMAGE
            },
        ),
        (
            "VUID-VkImageCreateInfo-pNext-01443",
            &[],
            ImageParts {
                external: vk::ExternalMemoryHandleTypeFlags::OPAQUE_FD,
                initial_layout: vk::ImageLayout::PREINITIALIZED,
                ..IMAGE
            },
        ),
        (
            "VUID-VkImageCreateInfo-pNext-00990",
            &[],
            ImageParts {
                external: vk::ExternalMemoryHandleTypeFlags::D3D11_TEXTURE,
                ..IMAGE
            },
        ),
        (
            "VUID-VkImageCreateInfo-physicalDeviceCount-01421",
            &[],
            ImageParts {
                flags: vk::ImageCreateFlags::SPLIT_INSTANCE_BIND_REGIONS,
                ..IMAGE
            },
        ),
        (
            "VUID-VkImageCreateInfo-flags-02259",
            &["VUID-VkImageCreateInfo-physicalDeviceCount-01421"],
            ImageParts {
                flags: vk::ImageCreateFlags::SPLIT_INSTANCE_BIND_REGIONS,
                layers: 2,
                ..IMAGE
            },
        ),
        (
            "VUID-VkImageCreateInfo-format-06410",
            // The format's limits allow neither.
            &["VUID-VkImageCreateInfo-imageCreateMaxMipLevels-02251"],
            ImageParts {
                format: two_planes,
                mip_levels: 2,
                ..IMAGE
            },
        ),
        (
            "VUID-VkImageCreateInfo-format-06412",
            // The format's limits allow neither.
            &["VUID-VkImageCreateInfo-imageCreateMaxMipLevels-02251"],
            ImageParts {
                format: two_planes,
                ty: vk::ImageType::TYPE_3D,
                ..IMAGE
            },
        ),
        (
            "VUID-VkImageCreateInfo-format-04712",
            &[],
            ImageParts {
                format: two_planes,
                extent: vk::Extent3D {
                    width: 3,
                    height: 4,
                    depth: 1,
                },
                ..IMAGE
            },
        ),
        (
            "VUID-VkImageCreateInfo-format-04713",
            &[],
            ImageParts {
                format: two_planes,
                extent: vk::Extent3D {
                    width: 4,
                    height: 3,
                    depth: 1,
                },
                ..IMAGE
            },
        ),
    ];
    let mut v = Verdicts::default();
    for (vuid, also, parts) in cases {
        let (safe, layer) = create_image(&s, parts);
        v.judge(vuid, also, safe, layer);
    }
    v.finish("images' sharing, external memory and chroma");
}

/// An image for the view cases: format, type, extent, levels, layers, samples,
/// flags, usage, stencil usage and listed view formats.
#[derive(Clone, Copy)]
struct Viewed {
    format: vk::Format,
    ty: vk::ImageType,
    extent: (u32, u32, u32),
    levels: u32,
    layers: u32,
    samples: vk::SampleCountFlags,
    flags: vk::ImageCreateFlags,
    usage: vk::ImageUsageFlags,
    stencil: Option<vk::ImageUsageFlags>,
    listed: &'static [vk::Format],
}

const VIEWED: Viewed = Viewed {
    format: vk::Format::R8G8B8A8_UNORM,
    ty: vk::ImageType::TYPE_2D,
    extent: (4, 4, 1),
    levels: 1,
    layers: 1,
    samples: vk::SampleCountFlags::TYPE_1,
    flags: vk::ImageCreateFlags::empty(),
    usage: vk::ImageUsageFlags::SAMPLED,
    stencil: None,
    listed: &[],
};

/// A view of an image: type, format, aspect, levels, layers (base and count), and a
/// chained usage.
#[derive(Clone, Copy)]
struct View {
    ty: vk::ImageViewType,
    format: Option<vk::Format>,
    aspect: vk::ImageAspectFlags,
    levels: u32,
    base_layer: u32,
    layers: u32,
    usage: Option<vk::ImageUsageFlags>,
}

const VIEW: View = View {
    ty: vk::ImageViewType::TYPE_2D,
    format: None,
    aspect: vk::ImageAspectFlags::COLOR,
    levels: 1,
    base_layer: 0,
    layers: 1,
    usage: None,
};

fn create_view(s: &Setup, i: Viewed, v: View) -> (tuff::Result<()>, Vec<String>) {
    let mut stencil =
        tuff::ImageStencilUsageCreateInfo::new().stencil_usage(i.stencil.unwrap_or_default());
    let mut list = tuff::ImageFormatListCreateInfo::new().view_formats(i.listed);
    let mut info = tuff::ImageCreateInfo::new()
        .flags(i.flags)
        .image_type(i.ty)
        .format(i.format)
        .extent(vk::Extent3D {
            width: i.extent.0,
            height: i.extent.1,
            depth: i.extent.2,
        })
        .mip_levels(i.levels)
        .array_layers(i.layers)
        .samples(i.samples)
        .usage(i.usage);
    if i.stencil.is_some() {
        info = info.push_next(&mut stencil);
    }
    if !i.listed.is_empty() {
        info = info.push_next(&mut list);
    }
    let allocator = s.device.naive_allocator();
    let image = s
        .device
        .create_image_in(&info, &allocator, tuff::MemoryLocation::DeviceLocal)
        .expect("the viewed image");
    let mut usage = tuff::ImageViewUsageCreateInfo::new().usage(v.usage.unwrap_or_default());
    let mut view = tuff::ImageViewCreateInfo::new(&image)
        .view_type(v.ty)
        .format(v.format.unwrap_or(i.format))
        .subresource_range(vk::ImageSubresourceRange {
            aspect_mask: v.aspect,
            base_mip_level: 0,
            level_count: v.levels,
            base_array_layer: v.base_layer,
            layer_count: v.layers,
        });
    if v.usage.is_some() {
        view = view.push_next(&mut usage);
    }
    let safe = s.device.create_image_view(&view).map(drop);
    let layer = under_layer(s, || {
        let _ = unsafe { s.device.create_image_view_unchecked(&view) };
    });
    (safe, layer)
}

#[test]
fn image_view_rules_are_refused_and_the_layer_agrees() {
    let _serial = vulkan::serial();
    let s = tuff_setup::setup(true);
    let (safe, layer) = create_view(&s, VIEWED, VIEW);
    assert!(
        safe.is_ok() && layer.is_empty(),
        "the valid view: {safe:?} {layer:?}"
    );
    use vk::ImageCreateFlags as C;
    use vk::ImageUsageFlags as U;
    use vk::ImageViewType as V;
    let layers = |n| Viewed {
        layers: n,
        ..VIEWED
    };
    let cube = |n| Viewed {
        layers: n,
        flags: C::CUBE_COMPATIBLE,
        ..VIEWED
    };
    let three_d = |flags| Viewed {
        ty: vk::ImageType::TYPE_3D,
        extent: (4, 4, 4),
        levels: 2,
        flags,
        ..VIEWED
    };
    let mutable = Viewed {
        flags: C::MUTABLE_FORMAT,
        ..VIEWED
    };
    let depth = Viewed {
        format: vk::Format::D32_SFLOAT_S8_UINT,
        usage: U::DEPTH_STENCIL_ATTACHMENT | U::SAMPLED,
        stencil: Some(U::DEPTH_STENCIL_ATTACHMENT),
        ..VIEWED
    };
    let block_texel = Viewed {
        format: vk::Format::BC1_RGBA_UNORM_BLOCK,
        levels: 2,
        flags: C::MUTABLE_FORMAT | C::BLOCK_TEXEL_VIEW_COMPATIBLE,
        ..VIEWED
    };
    let remaining = vk::REMAINING_ARRAY_LAYERS;
    let cases: Vec<(&str, &[&str], Viewed, View)> = vec![
        (
            "VUID-VkImageViewCreateInfo-image-01003",
            &[],
            layers(6),
            View {
                ty: V::CUBE,
                layers: 6,
                ..VIEW
            },
        ),
        (
            "VUID-VkImageViewCreateInfo-image-04441",
            &[],
            Viewed {
                usage: U::TRANSFER_SRC,
                ..VIEWED
            },
            VIEW,
        ),
        (
            "VUID-VkImageViewCreateInfo-subResourceRange-01021",
            &[],
            VIEWED,
            View {
                ty: V::TYPE_1D,
                ..VIEW
            },
        ),
        (
            "VUID-VkImageViewCreateInfo-image-06723",
            &[],
            three_d(C::empty()),
            View {
                ty: V::TYPE_2D_ARRAY,
                ..VIEW
            },
        ),
        (
            "VUID-VkImageViewCreateInfo-image-06727",
            &[],
            three_d(C::empty()),
            VIEW,
        ),
        (
            "VUID-VkImageViewCreateInfo-image-04970",
            &[],
            three_d(C::TYPE_2D_ARRAY_COMPATIBLE),
            View { levels: 2, ..VIEW },
        ),
        (
            "VUID-VkImageViewCreateInfo-image-02724",
            &["VUID-VkImageViewCreateInfo-subresourceRange-02725"],
            three_d(C::TYPE_2D_ARRAY_COMPATIBLE),
            View {
                base_layer: 4,
                ..VIEW
            },
        ),
        (
            "VUID-VkImageViewCreateInfo-subresourceRange-02725",
            &[],
            three_d(C::TYPE_2D_ARRAY_COMPATIBLE),
            View {
                ty: V::TYPE_2D_ARRAY,
                base_layer: 2,
                layers: 3,
                ..VIEW
            },
        ),
        (
            "VUID-VkImageViewCreateInfo-image-04972",
            &["VUID-VkImageViewCreateInfo-image-01003"],
            Viewed {
                samples: vk::SampleCountFlags::TYPE_4,
                usage: U::COLOR_ATTACHMENT,
                layers: 6,
                ..VIEWED
            },
            View {
                ty: V::CUBE,
                layers: 6,
                ..VIEW
            },
        ),
        (
            "VUID-VkImageViewCreateInfo-image-01482",
            &["VUID-VkImageViewCreateInfo-subresourceRange-01483"],
            layers(2),
            View {
                base_layer: 2,
                ..VIEW
            },
        ),
        (
            "VUID-VkImageViewCreateInfo-subresourceRange-01483",
            &[],
            layers(2),
            View {
                ty: V::TYPE_2D_ARRAY,
                base_layer: 1,
                layers: 2,
                ..VIEW
            },
        ),
        (
            "VUID-VkImageViewCreateInfo-imageViewType-04973",
            &[],
            layers(2),
            View { layers: 2, ..VIEW },
        ),
        (
            "VUID-VkImageViewCreateInfo-imageViewType-04974",
            &[],
            layers(2),
            View {
                layers: remaining,
                ..VIEW
            },
        ),
        (
            "VUID-VkImageViewCreateInfo-viewType-02962",
            &[],
            cube(12),
            View {
                ty: V::CUBE,
                layers: remaining,
                ..VIEW
            },
        ),
        (
            "VUID-VkImageViewCreateInfo-image-01761",
            &[],
            mutable,
            View {
                format: Some(vk::Format::R16G16B16A16_SFLOAT),
                ..VIEW
            },
        ),
        (
            "VUID-VkImageViewCreateInfo-image-01762",
            &[],
            VIEWED,
            View {
                format: Some(vk::Format::R8G8B8A8_SRGB),
                ..VIEW
            },
        ),
        (
            "VUID-VkImageViewCreateInfo-pNext-01585",
            &[],
            Viewed {
                listed: &[vk::Format::R8G8B8A8_UNORM, vk::Format::R8G8B8A8_SRGB],
                ..mutable
            },
            View {
                format: Some(vk::Format::B8G8R8A8_UNORM),
                ..VIEW
            },
        ),
        (
            "VUID-VkImageViewCreateInfo-pNext-02662",
            &[],
            VIEWED,
            View {
                usage: Some(U::STORAGE),
                ..VIEW
            },
        ),
        (
            "VUID-VkImageViewCreateInfo-pNext-02663",
            &[],
            depth,
            View {
                aspect: vk::ImageAspectFlags::STENCIL,
                usage: Some(U::SAMPLED),
                ..VIEW
            },
        ),
        (
            "VUID-VkImageViewCreateInfo-pNext-02664",
            &["VUID-VkImageViewCreateInfo-usage-02275"],
            depth,
            View {
                aspect: vk::ImageAspectFlags::DEPTH,
                usage: Some(U::STORAGE),
                ..VIEW
            },
        ),
        (
            "VUID-VkImageViewCreateInfo-usage-02275",
            &[],
            Viewed {
                usage: U::STORAGE,
                ..mutable
            },
            View {
                format: Some(vk::Format::R8G8B8A8_SRGB),
                ..VIEW
            },
        ),
        (
            "VUID-VkImageViewCreateInfo-image-01583",
            &[],
            block_texel,
            View {
                format: Some(vk::Format::R8G8B8A8_UNORM),
                ..VIEW
            },
        ),
        (
            "VUID-VkImageViewCreateInfo-image-07072",
            &[],
            block_texel,
            View {
                format: Some(vk::Format::R32G32_UINT),
                levels: 2,
                ..VIEW
            },
        ),
    ];
    let mut v = Verdicts::default();
    for (vuid, also, image, view) in cases {
        let (safe, layer) = create_view(&s, image, view);
        v.judge(vuid, also, safe, layer);
    }
    v.finish("image views");
}

/// The safe call's result and what the layer said of the unchecked one.
type Outcome = (tuff::Result<()>, Vec<String>);

#[test]
fn framebuffer_rules_are_refused_and_the_layer_agrees() {
    let _serial = vulkan::serial();
    let s = tuff_setup::setup(true);
    let d = &s.device;
    use vk::ImageUsageFlags as U;
    let rgba = vk::Format::R8G8B8A8_UNORM;
    let depth_format = vk::Format::D32_SFLOAT_S8_UINT;
    let attachment = |format| vk::AttachmentDescription {
        format,
        samples: vk::SampleCountFlags::TYPE_1,
        load_op: vk::AttachmentLoadOp::DONT_CARE,
        store_op: vk::AttachmentStoreOp::DONT_CARE,
        stencil_load_op: vk::AttachmentLoadOp::DONT_CARE,
        stencil_store_op: vk::AttachmentStoreOp::DONT_CARE,
        initial_layout: vk::ImageLayout::UNDEFINED,
        final_layout: vk::ImageLayout::GENERAL,
        ..Default::default()
    };
    let attachments = [attachment(rgba), attachment(depth_format)];
    let color_ref = [vk::AttachmentReference {
        attachment: 0,
        layout: vk::ImageLayout::COLOR_ATTACHMENT_OPTIMAL,
    }];
    let depth_ref = vk::AttachmentReference {
        attachment: 1,
        layout: vk::ImageLayout::DEPTH_STENCIL_ATTACHMENT_OPTIMAL,
    };
    let subpasses = [tuff::SubpassDescription::new()
        .pipeline_bind_point(vk::PipelineBindPoint::GRAPHICS)
        .color_attachments(&color_ref)
        .depth_stencil_attachment(Some(&depth_ref))];
    let render_pass = d
        .create_render_pass(
            &tuff::RenderPassCreateInfo::new()
                .attachments(&attachments)
                .subpasses(&subpasses),
        )
        .expect("render pass");
    let allocator = d.naive_allocator();
    // A view of a new bound image: format, type, levels, samples, usage, flags, the
    // view's type and swizzle.
    let view = |format, ty, levels, samples, usage, flags, view_ty, swizzle| {
        let info = tuff::ImageCreateInfo::new()
            .flags(flags)
            .image_type(ty)
            .format(format)
            .extent(vk::Extent3D {
                width: 16,
                height: 16,
                depth: 1,
            })
            .mip_levels(levels)
            .array_layers(1)
            .samples(samples)
            .usage(usage);
        let image = d
            .create_image_in(&info, &allocator, tuff::MemoryLocation::DeviceLocal)
            .expect("image");
        let aspect = if format == depth_format {
            vk::ImageAspectFlags::DEPTH | vk::ImageAspectFlags::STENCIL
        } else {
            vk::ImageAspectFlags::COLOR
        };
        let view = d
            .create_image_view(
                &tuff::ImageViewCreateInfo::new(&image)
                    .view_type(view_ty)
                    .format(format)
                    .components(vk::ComponentMapping {
                        r: swizzle,
                        ..Default::default()
                    })
                    .subresource_range(vk::ImageSubresourceRange {
                        aspect_mask: aspect,
                        base_mip_level: 0,
                        level_count: levels,
                        base_array_layer: 0,
                        layer_count: 1,
                    }),
            )
            .expect("view");
        (image, view)
    };
    let one = vk::SampleCountFlags::TYPE_1;
    let flat = vk::ImageType::TYPE_2D;
    let v2 = vk::ImageViewType::TYPE_2D;
    let id = vk::ComponentSwizzle::IDENTITY;
    let none = vk::ImageCreateFlags::empty();
    let color = view(
        rgba,
        flat,
        1,
        one,
        U::COLOR_ATTACHMENT | U::SAMPLED,
        none,
        v2,
        id,
    );
    let depth = view(
        depth_format,
        flat,
        1,
        one,
        U::DEPTH_STENCIL_ATTACHMENT | U::SAMPLED,
        none,
        v2,
        id,
    );
    let sampled = view(rgba, flat, 1, one, U::SAMPLED, none, v2, id);
    let sampled_depth = view(depth_format, flat, 1, one, U::SAMPLED, none, v2, id);
    let srgb = view(
        vk::Format::R8G8B8A8_SRGB,
        flat,
        1,
        one,
        U::COLOR_ATTACHMENT,
        none,
        v2,
        id,
    );
    let four = view(
        rgba,
        flat,
        1,
        vk::SampleCountFlags::TYPE_4,
        U::COLOR_ATTACHMENT,
        none,
        v2,
        id,
    );
    let levels = view(rgba, flat, 2, one, U::COLOR_ATTACHMENT, none, v2, id);
    let swizzled = view(
        rgba,
        flat,
        1,
        one,
        U::COLOR_ATTACHMENT,
        none,
        v2,
        vk::ComponentSwizzle::G,
    );
    let solid = view(
        rgba,
        vk::ImageType::TYPE_3D,
        1,
        one,
        U::COLOR_ATTACHMENT,
        none,
        vk::ImageViewType::TYPE_3D,
        id,
    );
    let create = |views: &[&tuff::ImageView],
                  size: (u32, u32, u32),
                  imageless: Option<&[tuff::FramebufferAttachmentImageInfo<'_>]>| {
        let views = tuff::HandleSlice::new(views);
        let mut infos = tuff::FramebufferAttachmentsCreateInfo::new();
        let mut info = tuff::FramebufferCreateInfo::new(&render_pass)
            .attachments(&views)
            .width(size.0)
            .height(size.1)
            .layers(size.2);
        if let Some(images) = imageless {
            info = info.flags(vk::FramebufferCreateFlags::IMAGELESS);
            if !images.is_empty() {
                infos = infos.attachment_image_infos(images);
                info = info.push_next(&mut infos);
            }
        }
        let safe = d.create_framebuffer(&info).map(drop);
        let layer = under_layer(&s, || {
            let _ = unsafe { d.create_framebuffer_unchecked(&info) };
        });
        (safe, layer)
    };
    let size = (16, 16, 1);
    let (safe, layer) = create(&[&color.1, &depth.1], size, None);
    assert!(
        safe.is_ok() && layer.is_empty(),
        "the valid framebuffer: {safe:?} {layer:?}"
    );
    let image_info = |usage, width, layers, format: &'static [vk::Format]| {
        tuff::FramebufferAttachmentImageInfo::new()
            .usage(usage)
            .width(width)
            .height(16)
            .layer_count(layers)
            .view_formats(format)
    };
    let good = [
        image_info(U::COLOR_ATTACHMENT, 16, 1, &[vk::Format::R8G8B8A8_UNORM]),
        image_info(
            U::DEPTH_STENCIL_ATTACHMENT,
            16,
            1,
            &[vk::Format::D32_SFLOAT_S8_UINT],
        ),
    ];
    let (safe, layer) = create(&[&color.1, &depth.1], size, Some(&good));
    assert!(
        safe.is_ok() && layer.is_empty(),
        "the valid imageless framebuffer: {safe:?} {layer:?}"
    );
    let mut v = Verdicts::default();
    let cases: Vec<(&str, &[&str], Outcome)> = vec![
        (
            "VUID-VkFramebufferCreateInfo-attachmentCount-00876",
            &[],
            create(&[&color.1], size, None),
        ),
        (
            "VUID-VkFramebufferCreateInfo-pAttachments-00877",
            &[],
            create(&[&sampled.1, &depth.1], size, None),
        ),
        (
            "VUID-VkFramebufferCreateInfo-pAttachments-02633",
            &[],
            create(&[&color.1, &sampled_depth.1], size, None),
        ),
        (
            "VUID-VkFramebufferCreateInfo-pAttachments-00880",
            &[],
            create(&[&srgb.1, &depth.1], size, None),
        ),
        (
            "VUID-VkFramebufferCreateInfo-pAttachments-00881",
            &[],
            create(&[&four.1, &depth.1], size, None),
        ),
        (
            "VUID-VkFramebufferCreateInfo-flags-04533",
            &[],
            create(&[&color.1, &depth.1], (32, 16, 1), None),
        ),
        (
            "VUID-VkFramebufferCreateInfo-flags-04534",
            &[],
            create(&[&color.1, &depth.1], (16, 32, 1), None),
        ),
        (
            "VUID-VkFramebufferCreateInfo-flags-04535",
            &[],
            create(&[&color.1, &depth.1], (16, 16, 2), None),
        ),
        (
            "VUID-VkFramebufferCreateInfo-pAttachments-00883",
            &[],
            create(&[&levels.1, &depth.1], size, None),
        ),
        (
            "VUID-VkFramebufferCreateInfo-pAttachments-00884",
            &[],
            create(&[&swizzled.1, &depth.1], size, None),
        ),
        (
            "VUID-VkFramebufferCreateInfo-flags-04113",
            &[],
            create(&[&solid.1, &depth.1], size, None),
        ),
        (
            "VUID-VkFramebufferCreateInfo-flags-03190",
            &[],
            create(&[&color.1, &depth.1], size, Some(&[])),
        ),
        (
            "VUID-VkFramebufferCreateInfo-flags-03191",
            &[],
            create(&[&color.1, &depth.1], size, Some(&good[..1])),
        ),
        (
            "VUID-VkFramebufferCreateInfo-flags-03201",
            &[],
            create(
                &[&color.1, &depth.1],
                size,
                Some(&[
                    image_info(U::SAMPLED, 16, 1, &[vk::Format::R8G8B8A8_UNORM]),
                    good[1],
                ]),
            ),
        ),
        (
            "VUID-VkFramebufferCreateInfo-flags-03202",
            &[],
            create(
                &[&color.1, &depth.1],
                size,
                Some(&[
                    good[0],
                    image_info(U::SAMPLED, 16, 1, &[vk::Format::D32_SFLOAT_S8_UINT]),
                ]),
            ),
        ),
        (
            "VUID-VkFramebufferCreateInfo-flags-03205",
            &[],
            create(
                &[&color.1, &depth.1],
                size,
                Some(&[
                    image_info(U::COLOR_ATTACHMENT, 16, 1, &[vk::Format::R8G8B8A8_SRGB]),
                    good[1],
                ]),
            ),
        ),
        (
            "VUID-VkFramebufferCreateInfo-flags-04541",
            &[],
            create(
                &[&color.1, &depth.1],
                size,
                Some(&[
                    image_info(U::COLOR_ATTACHMENT, 8, 1, &[vk::Format::R8G8B8A8_UNORM]),
                    good[1],
                ]),
            ),
        ),
        (
            "VUID-VkFramebufferCreateInfo-flags-04542",
            &[],
            create(&[&color.1, &depth.1], (16, 32, 1), Some(&good)),
        ),
        (
            "VUID-VkFramebufferCreateInfo-renderPass-04546",
            &[],
            create(&[&color.1, &depth.1], (16, 16, 2), Some(&good)),
        ),
    ];
    for (vuid, also, (safe, layer)) in cases {
        v.judge(vuid, also, safe, layer);
    }
    v.finish("framebuffers");
}

/// A chained struct of an extension the device does not enable is no valid node of
/// the chain: tuff refuses it as the parent's `pNext-pNext` rule (the 1.3.239 layer
/// lets this one through: the error alone proves it). The fixture's device enables
/// no swapchain extension.
#[test]
fn a_struct_of_an_extension_not_enabled_is_refused_in_a_chain() {
    let _serial = vulkan::serial();
    let s = tuff_setup::setup(true);
    tuff_setup::breaks(
        &s,
        "VUID-VkImageCreateInfo-pNext-pNext",
        tuff_setup::Layer::Silent,
        |unchecked| {
            let mut swapchain = tuff::ImageSwapchainCreateInfoKHR::new();
            let info = tuff::ImageCreateInfo::new()
                .image_type(vk::ImageType::TYPE_2D)
                .format(vk::Format::R8G8B8A8_UNORM)
                .extent(vk::Extent3D {
                    width: 4,
                    height: 4,
                    depth: 1,
                })
                .mip_levels(1)
                .array_layers(1)
                .samples(vk::SampleCountFlags::TYPE_1)
                .usage(vk::ImageUsageFlags::SAMPLED)
                .push_next(&mut swapchain);
            match unchecked {
                // SAFETY: the layer skips the call it reports; the chain breaks only
                // the rule under test.
                true => unsafe { s.device.create_image_unchecked(&info) }.map(drop),
                false => s.device.create_image(&info).map(drop),
            }
        },
    );
}

/// A buffer's device address needs the buffer made with `SHADER_DEVICE_ADDRESS`
/// usage and bound to memory: each is refused with the rule's VUID, and the layer
/// names it for the unchecked call (which it skips); a bound buffer with the usage
/// has its address.
#[test]
fn buffer_addresses_need_their_usage_and_memory() {
    let _serial = vulkan::serial();
    let s = tuff_setup::setup_full_features(true);
    let d = &s.device;
    let buffer = |usage| {
        d.create_buffer(&tuff::BufferCreateInfo::new().size(256).usage(usage))
            .expect("buffer")
    };
    let address =
        vk::BufferUsageFlags::SHADER_DEVICE_ADDRESS | vk::BufferUsageFlags::STORAGE_BUFFER;
    let bind = |b: &tuff::Buffer| {
        let reqs = d.get_buffer_memory_requirements(b).expect("requirements");
        let mut flags =
            tuff::MemoryAllocateFlagsInfo::new().flags(vk::MemoryAllocateFlags::DEVICE_ADDRESS);
        let memory = d
            .allocate_memory(
                &tuff::MemoryAllocateInfo::new()
                    .allocation_size(reqs.size)
                    .memory_type_index(
                        s.memory_type(reqs.memory_type_bits, vk::MemoryPropertyFlags::empty()),
                    )
                    .push_next(&mut flags),
            )
            .expect("memory");
        d.bind_buffer_memory(b, &memory, 0).expect("bind");
        memory
    };
    let no_usage = buffer(vk::BufferUsageFlags::STORAGE_BUFFER);
    let _m0 = bind(&no_usage);
    let unbound = buffer(address);
    let mut v = Verdicts::default();
    for (rule, b) in [
        ("VUID-VkBufferDeviceAddressInfo-buffer-02601", &no_usage),
        ("VUID-VkBufferDeviceAddressInfo-buffer-02600", &unbound),
    ] {
        let info = tuff::BufferDeviceAddressInfo::new(b);
        let safe = d.get_buffer_device_address(&info).map(drop);
        let layer = under_layer(&s, || {
            // SAFETY: the layer skips the call, which breaks only the rule under test.
            let _ = unsafe { d.get_buffer_device_address_unchecked(&info) };
        });
        v.judge(rule, &[], safe, layer);
    }
    v.finish("buffer addresses");
    let bound = buffer(address);
    let _m1 = bind(&bound);
    let at = d
        .get_buffer_device_address(&tuff::BufferDeviceAddressInfo::new(&bound))
        .expect("the address of a bound buffer");
    assert_ne!(at, 0);
    vulkan::assert_silent(&s.messages);
}
