//! Device memory through the safe methods: flushes and invalidates of mapped ranges,
//! a memory's capture address, the requirements of an image not yet made, and the
//! peer memory features of a device group.
//!
//! Each case breaks one rule through the safe method, which must refuse it with the
//! rule's VUID, and through the `_unchecked` twin under the validation layer (with a
//! messenger that makes the layer skip the call), which must name the same VUID;
//! beside each, calls that keep the rules go through with the layer silent.
//!
//! SAFETY of the `unsafe` blocks around `_unchecked` calls: each breaks only the rule
//! under test, which the layer reports and so skips; the driver never sees it.

#[path = "common/tuff_setup.rs"]
mod tuff_setup;
#[path = "common/vulkan.rs"]
mod vulkan;

use tuff::vk;
use tuff_setup::{setup, setup_full_features, setup_with, vuid, Setup, Wsi};
use vulkan::assert_silent;

/// Runs `unchecked` with the layer told to skip erroring calls, and fails unless it
/// named `expected`.
fn layer_names(messages: &tuff::MessageLog, expected: &str, unchecked: impl FnOnce()) {
    messages.take();
    messages.abort_on_error(true);
    unchecked();
    messages.abort_on_error(false);
    let said = messages.take();
    assert!(
        said.iter().any(|m| m.contains(expected)),
        "the validation layer did not report {expected}; it said:\n{}",
        said.join("\n")
    );
}

/// Runs `unchecked`, which breaks `rule`, and fails if the layer says anything: the
/// 1.3.239 layer does not check the rule, so tuff's error alone proves it (lavapipe
/// ignores what the rule is about). A layer that starts checking it fails here.
fn layer_silent(messages: &tuff::MessageLog, rule: &str, unchecked: impl FnOnce()) {
    messages.take();
    unchecked();
    let said = messages.take();
    assert!(said.is_empty(), "the layer now checks {rule}: {said:?}");
}

/// `size` bytes of host-visible memory.
fn host_memory(s: &Setup, size: u64, flags: Option<vk::MemoryAllocateFlags>) -> tuff::DeviceMemory {
    let index = s.memory_type(!0, vk::MemoryPropertyFlags::HOST_VISIBLE);
    let mut allocate_flags = tuff::MemoryAllocateFlagsInfo::new().flags(flags.unwrap_or_default());
    let mut info = tuff::MemoryAllocateInfo::new()
        .allocation_size(size)
        .memory_type_index(index);
    if flags.is_some() {
        info = info.push_next(&mut allocate_flags);
    }
    s.device.allocate_memory(&info).expect("memory")
}

/// A flush or invalidate names memory a `MappedMemory` maps (00684), a range inside
/// it (00685, 00686), at a multiple of `nonCoherentAtomSize` (00687) and of a size
/// that is one, or reaches the memory's end (01390).
#[test]
fn flushed_and_invalidated_ranges_lie_in_a_live_mapping() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let atom = s.physical.get_properties().limits.non_coherent_atom_size;
    assert!(
        atom > 1,
        "lavapipe's nonCoherentAtomSize is more than a byte"
    );
    let size = 8 * atom;
    let memory = host_memory(&s, size, None);
    let d = &s.device;
    let range = |offset, length| {
        tuff::MappedMemoryRange::new(&memory)
            .offset(offset)
            .size(length)
    };
    type Call = fn(&tuff::Device, &[tuff::MappedMemoryRange<'_>]) -> tuff::Result<()>;
    type Unchecked = unsafe fn(&tuff::Device, &[tuff::MappedMemoryRange<'_>]) -> tuff::Result<()>;
    let calls: [(&str, Call, Unchecked); 2] = [
        (
            "flush",
            tuff::Device::flush_mapped_memory_ranges,
            tuff::Device::flush_mapped_memory_ranges_unchecked,
        ),
        (
            "invalidate",
            tuff::Device::invalidate_mapped_memory_ranges,
            tuff::Device::invalidate_mapped_memory_ranges_unchecked,
        ),
    ];
    for (what, call, unchecked) in calls {
        // Not mapped: no MappedMemory lives.
        let whole = [range(0, vk::WHOLE_SIZE)];
        assert_eq!(
            vuid(call(d, &whole)),
            "VUID-VkMappedMemoryRange-memory-00684",
            "{what}"
        );
        layer_names(&s.messages, "VUID-VkMappedMemoryRange-memory-00684", || {
            // SAFETY: see the module docs.
            drop(unsafe { unchecked(d, &whole) });
        });
        let mapped = memory.map().expect("map");
        for (ranges, rule) in [
            (
                [range(0, size + atom)],
                "VUID-VkMappedMemoryRange-size-00685",
            ),
            ([range(1, atom)], "VUID-VkMappedMemoryRange-offset-00687"),
            ([range(0, 1)], "VUID-VkMappedMemoryRange-size-01390"),
        ] {
            assert_eq!(vuid(call(d, &ranges)), rule, "{what}");
            layer_names(&s.messages, rule, || {
                // SAFETY: see the module docs.
                drop(unsafe { unchecked(d, &ranges) });
            });
        }
        // An offset past the mapping's end: the layer checks only one below its
        // start, which a mapping of the whole memory cannot have.
        let past = [range(size, vk::WHOLE_SIZE)];
        let rule = "VUID-VkMappedMemoryRange-size-00686";
        assert_eq!(vuid(call(d, &past)), rule, "{what}");
        layer_silent(&s.messages, rule, || {
            // SAFETY: the layer does not check it; lavapipe's memory is coherent, so
            // its flushes and invalidates touch nothing.
            drop(unsafe { unchecked(d, &past) });
        });
        // The whole mapping, one atom, and a range that ends where the memory does.
        for ranges in [
            [range(0, vk::WHOLE_SIZE)],
            [range(atom, atom)],
            [range(size - atom, atom)],
        ] {
            call(d, &ranges).unwrap_or_else(|e| panic!("{what} {ranges:?}: {e}"));
        }
        drop(mapped);
        // Unmapped again with the guard.
        assert_eq!(
            vuid(call(d, &whole)),
            "VUID-VkMappedMemoryRange-memory-00684",
            "{what}"
        );
    }
    assert_silent(&s.messages);
}

/// A memory's opaque capture address needs the memory allocated with a device
/// address (03336).
#[test]
fn a_capture_address_needs_memory_allocated_with_an_address() {
    let _serial = vulkan::serial();
    let s = setup_full_features(true);
    let plain = host_memory(&s, 256, None);
    let addressed = host_memory(&s, 256, Some(vk::MemoryAllocateFlags::DEVICE_ADDRESS));
    let d = &s.device;
    let rule = "VUID-VkDeviceMemoryOpaqueCaptureAddressInfo-memory-03336";
    let info = tuff::DeviceMemoryOpaqueCaptureAddressInfo::new(&plain);
    assert_eq!(
        vuid(d.get_device_memory_opaque_capture_address(&info)),
        rule
    );
    layer_names(&s.messages, rule, || {
        // SAFETY: see the module docs.
        let _ = unsafe { d.get_device_memory_opaque_capture_address_unchecked(&info) };
    });
    d.get_device_memory_opaque_capture_address(&tuff::DeviceMemoryOpaqueCaptureAddressInfo::new(
        &addressed,
    ))
    .expect("the capture address of memory with a device address");
    assert_silent(&s.messages);
}

/// A device group's peer memory features name a heap of the physical device and two
/// different devices of the group (00691 to 00694). Lavapipe's devices have one
/// physical device, so every call is refused, the last for naming it twice.
#[test]
fn peer_memory_features_name_a_heap_and_two_devices_of_the_group() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let d = &s.device;
    for ((heap, local, remote), rule) in [
        (
            (99, 0, 1),
            "VUID-vkGetDeviceGroupPeerMemoryFeatures-heapIndex-00691",
        ),
        (
            (0, 1, 0),
            "VUID-vkGetDeviceGroupPeerMemoryFeatures-localDeviceIndex-00692",
        ),
        (
            (0, 0, 1),
            "VUID-vkGetDeviceGroupPeerMemoryFeatures-remoteDeviceIndex-00693",
        ),
        (
            (0, 0, 0),
            "VUID-vkGetDeviceGroupPeerMemoryFeatures-localDeviceIndex-00694",
        ),
    ] {
        assert_eq!(
            vuid(d.get_group_peer_memory_features(heap, local, remote)),
            rule
        );
        layer_silent(&s.messages, rule, || {
            // SAFETY: the layer does not check it; lavapipe answers for its one
            // device whatever the indices.
            let _ = unsafe { d.get_group_peer_memory_features_unchecked(heap, local, remote) };
        });
    }
    assert_silent(&s.messages);
}

/// The requirements of an image not yet made: its create info chains no swapchain
/// (06416), and a disjoint image names one of its format's planes (06417, 06419).
#[test]
fn the_requirements_of_an_image_not_made_name_its_plane() {
    let _serial = vulkan::serial();
    let s = setup_with(true, Wsi::Xlib);
    let d = &s.device;
    let image = |format, flags| {
        tuff::ImageCreateInfo::new()
            .flags(flags)
            .image_type(vk::ImageType::TYPE_2D)
            .format(format)
            .extent(vk::Extent3D {
                width: 16,
                height: 16,
                depth: 1,
            })
            .mip_levels(1)
            .array_layers(1)
            .samples(vk::SampleCountFlags::TYPE_1)
            .usage(vk::ImageUsageFlags::SAMPLED)
    };
    let rgba = image(vk::Format::R8G8B8A8_UNORM, vk::ImageCreateFlags::empty());
    let mut swapchain = tuff::ImageSwapchainCreateInfoKHR::new();
    let of_swapchain =
        image(vk::Format::R8G8B8A8_UNORM, vk::ImageCreateFlags::empty()).push_next(&mut swapchain);
    let disjoint = image(
        vk::Format::G8_B8R8_2PLANE_420_UNORM,
        vk::ImageCreateFlags::DISJOINT,
    );
    let plane = |info, aspect| tuff::DeviceImageMemoryRequirements::new(info).plane_aspect(aspect);
    let cases = [
        (
            plane(&of_swapchain, vk::ImageAspectFlags::NONE),
            "VUID-VkDeviceImageMemoryRequirementsKHR-pCreateInfo-06416",
        ),
        (
            plane(&disjoint, vk::ImageAspectFlags::NONE),
            "VUID-VkDeviceImageMemoryRequirementsKHR-pCreateInfo-06417",
        ),
        (
            plane(&disjoint, vk::ImageAspectFlags::PLANE_2),
            "VUID-VkDeviceImageMemoryRequirementsKHR-pCreateInfo-06419",
        ),
    ];
    for (info, rule) in &cases {
        let mut out = tuff::MemoryRequirements2::new();
        assert_eq!(
            vuid(d.get_device_image_memory_requirements(info, &mut out)),
            *rule
        );
        assert_eq!(
            vuid(d.get_device_image_sparse_memory_requirements(info)),
            *rule
        );
        layer_silent(&s.messages, rule, || {
            let mut out = tuff::MemoryRequirements2::new();
            // SAFETY: the layer does not check it; lavapipe sizes the image whatever
            // its chain and plane.
            unsafe { d.get_device_image_memory_requirements_unchecked(info, &mut out) };
        });
    }
    let mut out = tuff::MemoryRequirements2::new();
    d.get_device_image_memory_requirements(&plane(&rgba, vk::ImageAspectFlags::NONE), &mut out)
        .expect("the requirements of an image not made");
    assert!(out.memory_requirements.size >= 16 * 16 * 4);
    assert_silent(&s.messages);
}

/// An image's subresource layout is asked of a linear image (07789), for one aspect
/// (00997) of its format (04461, 04464), at a level (01716) and layer (01717) it has.
#[test]
fn a_subresource_layout_is_asked_of_a_linear_image() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let d = &s.device;
    let image = |format, tiling, usage| {
        let image = d
            .create_image(
                &tuff::ImageCreateInfo::new()
                    .image_type(vk::ImageType::TYPE_2D)
                    .format(format)
                    .extent(vk::Extent3D {
                        width: 4,
                        height: 4,
                        depth: 1,
                    })
                    .mip_levels(1)
                    .array_layers(1)
                    .samples(vk::SampleCountFlags::TYPE_1)
                    .tiling(tiling)
                    .usage(usage),
            )
            .unwrap_or_else(|e| panic!("a {tiling:?} {format:?} image: {e}"));
        let memory = s.bind_image(&image);
        (image, memory)
    };
    let linear = vk::ImageTiling::LINEAR;
    let transfer = vk::ImageUsageFlags::TRANSFER_SRC;
    let (color, _m1) = image(vk::Format::R8G8B8A8_UNORM, linear, transfer);
    let (optimal, _m2) = image(
        vk::Format::R8G8B8A8_UNORM,
        vk::ImageTiling::OPTIMAL,
        transfer,
    );
    type A = vk::ImageAspectFlags;
    let at = |aspect, mip_level, array_layer| vk::ImageSubresource {
        aspect_mask: aspect,
        mip_level,
        array_layer,
    };
    let cases = [
        (
            &optimal,
            at(A::COLOR, 0, 0),
            "VUID-vkGetImageSubresourceLayout-image-07789",
        ),
        (
            &color,
            at(A::COLOR | A::DEPTH, 0, 0),
            "VUID-vkGetImageSubresourceLayout-aspectMask-00997",
        ),
        (
            &color,
            at(A::COLOR, 1, 0),
            "VUID-vkGetImageSubresourceLayout-mipLevel-01716",
        ),
        (
            &color,
            at(A::COLOR, 0, 1),
            "VUID-vkGetImageSubresourceLayout-arrayLayer-01717",
        ),
        (
            &color,
            at(A::DEPTH, 0, 0),
            "VUID-vkGetImageSubresourceLayout-format-04461",
        ),
    ];
    for (image, subresource, rule) in &cases {
        assert_eq!(
            vuid(d.get_image_subresource_layout(image, subresource)),
            *rule
        );
        layer_names(&s.messages, rule, || {
            // SAFETY: see the module docs.
            let _ = unsafe { d.get_image_subresource_layout_unchecked(image, subresource) };
        });
    }
    // A depth aspect of a colour format is refused under 04461 first; the layer
    // names 04464 for it too.
    layer_names(
        &s.messages,
        "VUID-vkGetImageSubresourceLayout-format-04464",
        || {
            // SAFETY: see the module docs.
            let _ =
                unsafe { d.get_image_subresource_layout_unchecked(&color, &at(A::DEPTH, 0, 0)) };
        },
    );
    // (Lavapipe makes no linear depth or stencil image, whose aspects 04462 and
    // 04463 are about.)
    let layout = d
        .get_image_subresource_layout(&color, &at(A::COLOR, 0, 0))
        .expect("the layout of a linear colour image");
    assert!(layout.size >= 4 * 4 * 4);
    assert_silent(&s.messages);
}
