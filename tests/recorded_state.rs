//! The checks that read what the instance, the physical device and the device know:
//! the API version and extensions an instance is created with, the queues a device
//! was created with, the queue families and surfaces of a physical device, the
//! handle types it can export, and where a buffer is bound.
//!
//! Each test breaks one rule through the safe method, which must refuse it with the
//! rule's VUID, and through the `_unchecked` twin under the validation layer (with a
//! messenger that makes the layer skip the call), which must name the same VUID.
//!
//! SAFETY of the `unsafe` blocks around `_unchecked` calls: each breaks only the rule
//! under test, which the layer reports and so skips; the driver never sees it. Of
//! those around checked methods: the method is `unsafe` for rules its `# Safety`
//! section lists, which the calls here keep.

#[path = "common/pipelines.rs"]
mod pipelines;
#[path = "common/tuff_setup.rs"]
mod tuff_setup;
#[path = "common/vulkan.rs"]
mod vulkan;
#[path = "common/x11_window.rs"]
mod x11_window;

use tuff::{vk, Handle as _};
use tuff_setup::{setup, setup_with, vuid, Setup, Wsi};
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

#[test]
fn instance_creation_rules_are_refused_and_the_layer_agrees() {
    let _serial = vulkan::serial();
    let entry = tuff::Entry::load().expect("the Vulkan loader is not installed");
    let messages = tuff::MessageLog::new();
    let layers = [tuff::CStrPtr::from(c"VK_LAYER_KHRONOS_validation")];
    let debug = tuff::CStrPtr::from(c"VK_EXT_debug_utils");
    let xlib = tuff::CStrPtr::from(c"VK_KHR_xlib_surface");
    let surface = tuff::CStrPtr::from(c"VK_KHR_surface");
    let below_1_0 = tuff::ApplicationInfo::new().api_version(vk::make_api_version(0, 0, 9, 0));
    let v1_3 = tuff::ApplicationInfo::new().api_version(vk::API_VERSION_1_3);

    // An extension without the one it depends on, with the layer's messenger chained
    // so that it hears the creation itself.
    let expected = "VUID-vkCreateInstance-ppEnabledExtensionNames-01388";
    let exts = [debug, xlib];
    let mut chained = messages.messenger_info();
    let info = tuff::InstanceCreateInfo::new()
        .application_info(Some(&v1_3))
        .enabled_layer_names(&layers)
        .enabled_extension_names(&exts)
        .push_next(&mut chained);
    assert_eq!(vuid(entry.create_instance(&info)), expected);
    layer_names(&messages, expected, || {
        // SAFETY: see the module docs.
        let made = unsafe { entry.create_instance_unchecked(&info) };
        assert!(made.is_err(), "the layer let {expected} through");
    });

    // An API version below 1.0. The 1.3.239 loader crashes once the layer has
    // refused such an instance, so the refusal alone shows this check.
    let info = tuff::InstanceCreateInfo::new()
        .application_info(Some(&below_1_0))
        .enabled_layer_names(&layers);
    assert_eq!(
        vuid(entry.create_instance(&info)),
        "VUID-VkApplicationInfo-apiVersion-04010"
    );

    // A messenger chained without the extension that defines it: the layer cannot
    // speak through it, so the refusal alone shows the check.
    let mut chained = messages.messenger_info();
    let info = tuff::InstanceCreateInfo::new()
        .application_info(Some(&v1_3))
        .push_next(&mut chained);
    assert_eq!(
        vuid(entry.create_instance(&info)),
        "VUID-VkInstanceCreateInfo-pNext-04926"
    );

    // The same instances, each rule kept, are made, with nothing said.
    for exts in [vec![debug], vec![debug, surface, xlib]] {
        let mut chained = messages.messenger_info();
        let info = tuff::InstanceCreateInfo::new()
            .application_info(Some(&v1_3))
            .enabled_layer_names(&layers)
            .enabled_extension_names(&exts)
            .push_next(&mut chained);
        drop(entry.create_instance(&info).expect("a valid instance"));
    }
    assert_silent(&messages);
}

#[test]
fn queues_are_got_as_the_device_was_created_and_the_layer_agrees() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let families = s
        .physical
        .get_queue_family_properties()
        .expect("queue families")
        .len();
    let absent = u32::try_from(families).expect("few families");
    let d = &s.device;
    let cases = [
        (absent, 0, "VUID-vkGetDeviceQueue-queueFamilyIndex-00384"),
        (s.family, 1, "VUID-vkGetDeviceQueue-queueIndex-00385"),
    ];
    for (family, index, expected) in cases {
        assert_eq!(vuid(d.get_queue(family, index)), expected);
    }
    let info = |family, flags, index| {
        tuff::DeviceQueueInfo2::new()
            .queue_family_index(family)
            .flags(flags)
            .queue_index(index)
    };
    let none = vk::DeviceQueueCreateFlags::empty();
    let protected = vk::DeviceQueueCreateFlags::PROTECTED;
    let cases2 = [
        (
            info(absent, none, 0),
            "VUID-VkDeviceQueueInfo2-queueFamilyIndex-01842",
        ),
        (
            info(s.family, protected, 0),
            "VUID-VkDeviceQueueInfo2-flags-06225",
        ),
        (
            info(s.family, none, 1),
            "VUID-VkDeviceQueueInfo2-queueIndex-01843",
        ),
    ];
    for (info, expected) in &cases2 {
        assert_eq!(vuid(d.get_queue2(info)), *expected);
    }
    // The queue the device was created with is got both ways.
    d.get_queue(s.family, 0).expect("queue");
    d.get_queue2(&info(s.family, none, 0)).expect("queue");
    assert_silent(&s.messages);

    for (family, index, expected) in cases {
        layer_names(&s.messages, expected, || {
            // SAFETY: see the module docs; the skipped call leaves a null queue, which
            // is dropped unused.
            drop(unsafe { d.get_queue_unchecked(family, index) });
        });
    }
    for (info, expected) in &cases2 {
        layer_names(&s.messages, expected, || {
            // SAFETY: as above.
            drop(unsafe { d.get_queue2_unchecked(info) });
        });
    }
}

#[test]
fn surface_queries_name_a_family_and_a_surface_and_the_layer_agrees() {
    let _serial = vulkan::serial();
    let window = x11_window::X11Window::open(32, 32);
    let s = setup_with(true, Wsi::Xlib);
    // `window` outlives the surface.
    // SAFETY: the display and window are the open X11 window's.
    let surface = unsafe {
        s.instance.create_xlib_surface_khr(
            &tuff::XlibSurfaceCreateInfoKHR::new()
                .dpy(window.display.cast())
                .window(window.window),
        )
    }
    .expect("surface");
    let p = &s.physical;
    let families = p
        .get_queue_family_properties()
        .expect("queue families")
        .len();
    let absent = u32::try_from(families).expect("few families");
    let past = "VUID-vkGetPhysicalDeviceSurfaceSupportKHR-queueFamilyIndex-01269";
    assert_eq!(vuid(p.get_surface_support_khr(absent, &surface)), past);
    assert_eq!(
        vuid(p.get_surface_formats_khr(None)),
        "VUID-vkGetPhysicalDeviceSurfaceFormatsKHR-surface-06523"
    );
    assert_eq!(
        vuid(p.get_surface_present_modes_khr(None)),
        "VUID-vkGetPhysicalDeviceSurfacePresentModesKHR-surface-06523"
    );
    // With the surface, each query answers.
    assert!(p
        .get_surface_support_khr(s.family, &surface)
        .expect("support"));
    assert!(!p
        .get_surface_formats_khr(Some(&surface))
        .expect("formats")
        .is_empty());
    assert!(!p
        .get_surface_present_modes_khr(Some(&surface))
        .expect("present modes")
        .is_empty());
    let caps = p
        .get_surface_capabilities_khr(&surface)
        .expect("capabilities");
    assert!(caps.max_image_array_layers >= 1);
    assert_silent(&s.messages);

    layer_names(&s.messages, past, || {
        // SAFETY: see the module docs.
        drop(unsafe { p.get_surface_support_khr_unchecked(absent, &surface) });
    });
    drop(surface);
    drop(s);
    drop(window);
}

/// The Xlib presentation query takes the window's display connection as a
/// `raw_window_handle::DisplayHandle`, so it is safe: a handle of another window
/// system is refused, and a family past the count is refused as the layer refuses it.
#[test]
fn presentation_support_takes_a_display_handle_and_the_layer_agrees() {
    use raw_window_handle::HasDisplayHandle;
    let _serial = vulkan::serial();
    let window = x11_window::X11Window::open(32, 32);
    let s = setup_with(true, Wsi::Xlib);
    let p = &s.physical;
    let display = window.display_handle().expect("display handle");
    // ash spells Xlib's `VisualID` as a 32-bit number; X11 IDs fit in 29 bits.
    let visual = u32::try_from(window.visual_id()).expect("an X11 ID");
    assert!(p
        .get_xlib_presentation_support_khr(s.family, display, visual)
        .expect("support"));
    let families = p
        .get_queue_family_properties()
        .expect("queue families")
        .len();
    let absent = u32::try_from(families).expect("few families");
    let past = "VUID-vkGetPhysicalDeviceXlibPresentationSupportKHR-queueFamilyIndex-01315";
    assert_eq!(
        vuid(p.get_xlib_presentation_support_khr(absent, display, visual)),
        past
    );
    // A Wayland display is not an Xlib one: refused before Vulkan sees it.
    let raw = raw_window_handle::WaylandDisplayHandle::new(std::ptr::NonNull::dangling());
    // SAFETY: the handle is refused for its window system before anything reads it.
    let wayland = unsafe { raw_window_handle::DisplayHandle::borrow_raw(raw.into()) };
    assert!(matches!(
        p.get_xlib_presentation_support_khr(s.family, wayland, visual),
        Err(tuff::Error::Window(_))
    ));
    assert_silent(&s.messages);
    layer_names(&s.messages, past, || {
        // SAFETY: see the module docs.
        drop(unsafe { p.get_xlib_presentation_support_khr_unchecked(absent, display, visual) });
    });
    drop(s);
    drop(window);
}

#[test]
fn an_index_buffer_is_bound_at_an_aligned_address_and_the_layer_agrees() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let (indices, _memory) = pipelines::host_buffer(&s, 64, vk::BufferUsageFlags::INDEX_BUFFER);
    let expected = "VUID-vkCmdBindIndexBuffer-offset-00432";
    for (offset, ty) in [(1, vk::IndexType::UINT16), (2, vk::IndexType::UINT32)] {
        let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
        let mut rec = cb
            .begin(&tuff::CommandBufferBeginInfo::new())
            .expect("begin");
        assert_eq!(vuid(rec.bind_index_buffer(&indices, offset, ty)), expected);
        // The recorder stays usable: an aligned offset is bound.
        rec.bind_index_buffer(&indices, 4, ty)
            .expect("aligned offset");
        rec.end().expect("end");
        let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
        let mut rec = cb
            .begin(&tuff::CommandBufferBeginInfo::new())
            .expect("begin");
        layer_names(&s.messages, expected, || {
            // SAFETY: see the module docs; the command buffer is never submitted.
            drop(unsafe { rec.bind_index_buffer_unchecked(&indices, offset, ty) });
        });
        rec.end().expect("end");
    }
    assert_silent(&s.messages);
}

/// The 1.3.239 layer does not check this rule (and lavapipe crashes on the call), so
/// the refusal alone shows it.
#[test]
fn private_data_of_an_instance_object_is_refused() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let d = &s.device;
    let slot = d
        .create_private_data_slot(&tuff::PrivateDataSlotCreateInfo::new())
        .expect("slot");
    let expected = "VUID-vkGetPrivateData-objectType-04018";
    let instance = vk::Handle::as_raw(s.instance.raw());
    assert_eq!(
        vuid(d.get_private_data(vk::ObjectType::INSTANCE, instance, &slot)),
        expected
    );
    assert_eq!(
        d.get_private_data(vk::ObjectType::DEVICE, vk::Handle::as_raw(d.raw()), &slot)
            .expect("the device's private data"),
        0
    );
    assert_silent(&s.messages);
}

#[test]
fn a_cache_is_not_merged_into_itself_and_the_layer_agrees() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let d = &s.device;
    let new_cache = || {
        d.create_pipeline_cache(&tuff::PipelineCacheCreateInfo::new())
            .expect("cache")
    };
    let (a, b) = (new_cache(), new_cache());
    let expected = "VUID-vkMergePipelineCaches-dstCache-00770";
    assert_eq!(
        vuid(d.merge_pipeline_caches(&a, &tuff::HandleSlice::new(&[&b, &a]))),
        expected
    );
    d.merge_pipeline_caches(&a, &b).expect("merge");
    layer_names(&s.messages, expected, || {
        // SAFETY: see the module docs.
        drop(unsafe { d.merge_pipeline_caches_unchecked(&a, &tuff::HandleSlice::new(&[&b, &a])) });
    });
    assert_silent(&s.messages);
}

/// The 1.3.239 layer does not check this rule: the refusal alone shows it.
#[test]
fn unknown_pipeline_statistics_are_refused() {
    let _serial = vulkan::serial();
    let s = setup_with_statistics();
    let d = &s.device;
    let info = |bits| {
        tuff::QueryPoolCreateInfo::new()
            .query_type(vk::QueryType::PIPELINE_STATISTICS)
            .query_count(1)
            .pipeline_statistics(vk::QueryPipelineStatisticFlags::from_raw(bits))
    };
    let unknown = info(0x1 | 0x1000);
    assert_eq!(
        vuid(d.create_query_pool(&unknown)),
        "VUID-VkQueryPoolCreateInfo-queryType-00792"
    );
    drop(
        d.create_query_pool(&info(0x1))
            .expect("a pool of one statistic"),
    );
    assert_silent(&s.messages);
}

/// A device with the pipelineStatisticsQuery feature, which statistics pools need.
fn setup_with_statistics() -> Setup {
    tuff_setup::setup_with_features(
        true,
        vk::PhysicalDeviceFeatures {
            pipeline_statistics_query: vk::TRUE,
            ..Default::default()
        },
    )
}

/// The 1.3.239 layer checks neither rule: the refusals alone show them.
#[test]
fn handle_types_a_device_cannot_export_are_refused() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let d = &s.device;
    // Win32 handles: never exportable on the Linux devices the tests run on.
    let mut fence_export = tuff::ExportFenceCreateInfo::new()
        .handle_types(vk::ExternalFenceHandleTypeFlags::OPAQUE_WIN32);
    let fence_info = tuff::FenceCreateInfo::new().push_next(&mut fence_export);
    let fence_rule = "VUID-VkExportFenceCreateInfo-handleTypes-01446";
    assert_eq!(vuid(d.create_fence(&fence_info)), fence_rule);
    let mut semaphore_export = tuff::ExportSemaphoreCreateInfo::new()
        .handle_types(vk::ExternalSemaphoreHandleTypeFlags::OPAQUE_WIN32);
    let semaphore_info = tuff::SemaphoreCreateInfo::new().push_next(&mut semaphore_export);
    let semaphore_rule = "VUID-VkExportSemaphoreCreateInfo-handleTypes-01124";
    assert_eq!(vuid(d.create_semaphore(&semaphore_info)), semaphore_rule);
    // Without an export, both are made.
    drop(
        d.create_fence(&tuff::FenceCreateInfo::new())
            .expect("fence"),
    );
    drop(
        d.create_semaphore(&tuff::SemaphoreCreateInfo::new())
            .expect("semaphore"),
    );
    assert_silent(&s.messages);
}

#[test]
fn vertex_bindings_stay_under_the_device_limits_and_the_layer_agrees() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let limits = s.physical.get_properties().limits;
    let (vertices, _memory) = pipelines::host_buffer(&s, 64, vk::BufferUsageFlags::VERTEX_BUFFER);
    // The last binding, and one past it.
    let last = limits.max_vertex_input_bindings - 1;
    let two: [&tuff::Buffer; 2] = [&vertices, &vertices];
    let stride = u64::from(limits.max_vertex_input_binding_stride) + 1;
    let first = "VUID-vkCmdBindVertexBuffers-firstBinding-00625";
    let first2 = "VUID-vkCmdBindVertexBuffers2-firstBinding-03356";
    let strides = "VUID-vkCmdBindVertexBuffers2-pStrides-03362";
    let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let mut rec = cb
        .begin(&tuff::CommandBufferBeginInfo::new())
        .expect("begin");
    assert_eq!(
        vuid(rec.bind_vertex_buffers(last, &tuff::HandleSlice::new(&two), &[0, 0])),
        first
    );
    let refused = rec.bind_vertex_buffers2(last, &tuff::HandleSlice::new(&two), &[0, 0], &[], &[]);
    assert_eq!(vuid(refused), first2);
    let refused = rec.bind_vertex_buffers2(0, &vertices, &[0], &[], &[stride]);
    assert_eq!(vuid(refused), strides);
    // The last binding the device has is bound.
    rec.bind_vertex_buffers(last, &vertices, &[0])
        .expect("the last binding");
    rec.end().expect("end");
    assert_silent(&s.messages);

    let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let mut rec = cb
        .begin(&tuff::CommandBufferBeginInfo::new())
        .expect("begin");
    layer_names(&s.messages, first, || {
        // SAFETY: see the module docs; the command buffer is never submitted.
        drop(unsafe {
            rec.bind_vertex_buffers_unchecked(last, &tuff::HandleSlice::new(&two), &[0, 0])
        });
    });
    layer_names(&s.messages, first2, || {
        // SAFETY: as above.
        drop(unsafe {
            rec.bind_vertex_buffers2_unchecked(
                last,
                &tuff::HandleSlice::new(&two),
                &[0, 0],
                &[],
                &[],
            )
        });
    });
    layer_names(&s.messages, strides, || {
        // SAFETY: as above.
        drop(unsafe { rec.bind_vertex_buffers2_unchecked(0, &vertices, &[0], &[], &[stride]) });
    });
    rec.end().expect("end");
}

#[test]
fn a_device_only_event_is_not_touched_by_the_host_and_the_layer_agrees() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let d = &s.device;
    let event = d
        .create_event(&tuff::EventCreateInfo::new().flags(vk::EventCreateFlags::DEVICE_ONLY))
        .expect("device-only event");
    let set = "VUID-vkSetEvent-event-03941";
    let status = "VUID-vkGetEventStatus-event-03940";
    let reset = "VUID-vkResetEvent-event-03823";
    assert_eq!(vuid(d.set_event(&event)), set);
    assert_eq!(vuid(d.get_event_status(&event)), status);
    assert_eq!(vuid(d.reset_event(&event)), reset);
    // A host event is set, read and reset.
    let host = d
        .create_event(&tuff::EventCreateInfo::new())
        .expect("event");
    d.set_event(&host).expect("set");
    assert_eq!(
        d.get_event_status(&host).expect("status"),
        tuff::EventSetOrEventReset::EventSet
    );
    d.reset_event(&host).expect("reset");
    assert_silent(&s.messages);
    layer_names(&s.messages, set, || {
        // SAFETY: see the module docs.
        drop(unsafe { d.set_event_unchecked(&event) });
    });
    layer_names(&s.messages, status, || {
        // SAFETY: see the module docs.
        drop(unsafe { d.get_event_status_unchecked(&event) });
    });
    layer_names(&s.messages, reset, || {
        // SAFETY: see the module docs.
        drop(unsafe { d.reset_event_unchecked(&event) });
    });
}

#[test]
fn the_commitment_of_memory_that_is_not_lazily_allocated_is_refused() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let (_buffer, memory) = pipelines::host_buffer(&s, 64, vk::BufferUsageFlags::TRANSFER_SRC);
    let expected = "VUID-vkGetDeviceMemoryCommitment-memory-00690";
    assert_eq!(
        vuid(s.device.get_device_memory_commitment(&memory)),
        expected
    );
    assert_silent(&s.messages);
    layer_names(&s.messages, expected, || {
        // SAFETY: see the module docs.
        let _ = unsafe { s.device.get_device_memory_commitment_unchecked(&memory) };
    });
}

/// The 1.3.239 layer checks neither rule: the refusals alone show them.
#[test]
fn sparse_queries_name_a_sample_count_of_the_format() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let p = &s.physical;
    let query = (
        vk::Format::R8G8B8A8_UNORM,
        vk::ImageType::TYPE_2D,
        vk::SampleCountFlags::TYPE_64,
        vk::ImageUsageFlags::SAMPLED,
        vk::ImageTiling::OPTIMAL,
    );
    let (format, ty, samples, usage, tiling) = query;
    let expected = "VUID-vkGetPhysicalDeviceSparseImageFormatProperties-samples-01094";
    assert_eq!(
        vuid(p.get_sparse_image_format_properties(format, ty, samples, usage, tiling)),
        expected
    );
    let info = tuff::PhysicalDeviceSparseImageFormatInfo2::new()
        .format(format)
        .ty(ty)
        .samples(samples)
        .usage(usage)
        .tiling(tiling);
    let expected2 = "VUID-VkPhysicalDeviceSparseImageFormatInfo2-samples-01095";
    assert_eq!(
        vuid(p.get_sparse_image_format_properties2(&info)),
        expected2
    );
    // One sample is a count every format has.
    p.get_sparse_image_format_properties(format, ty, vk::SampleCountFlags::TYPE_1, usage, tiling)
        .expect("one sample");
    assert_silent(&s.messages);
}

#[test]
fn plane_requirements_of_an_image_that_is_not_disjoint_are_refused_and_the_layer_agrees() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let d = &s.device;
    let image = s.color_target(4, vk::ImageUsageFlags::empty()).image;
    let mut plane =
        tuff::ImagePlaneMemoryRequirementsInfo::new().plane_aspect(vk::ImageAspectFlags::PLANE_0);
    let info = tuff::ImageMemoryRequirementsInfo2::new(&image).push_next(&mut plane);
    let expected = "VUID-VkImageMemoryRequirementsInfo2-image-01590";
    let mut out = tuff::MemoryRequirements2::new();
    assert_eq!(
        vuid(d.get_image_memory_requirements2(&info, &mut out)),
        expected
    );
    let whole = tuff::ImageMemoryRequirementsInfo2::new(&image);
    d.get_image_memory_requirements2(&whole, &mut out)
        .expect("the whole image's requirements");
    assert!(out.memory_requirements.size > 0);
    assert_silent(&s.messages);
    layer_names(&s.messages, expected, || {
        // SAFETY: see the module docs.
        unsafe { d.get_image_memory_requirements2_unchecked(&info, &mut out) };
    });
}

#[test]
fn a_query_reset_stays_inside_its_pool_and_the_layer_agrees() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let pool = s
        .device
        .create_query_pool(
            &tuff::QueryPoolCreateInfo::new()
                .query_type(vk::QueryType::TIMESTAMP)
                .query_count(2),
        )
        .expect("query pool");
    let cases = [
        (2, 1, "VUID-vkCmdResetQueryPool-firstQuery-00796"),
        (1, 2, "VUID-vkCmdResetQueryPool-firstQuery-00797"),
    ];
    for (first, count, expected) in cases {
        let (_cb_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
        let mut rec = cb
            .begin(&tuff::CommandBufferBeginInfo::new())
            .expect("begin");
        assert_eq!(vuid(rec.reset_query_pool(&pool, first, count)), expected);
        rec.reset_query_pool(&pool, 0, 2).expect("the whole pool");
        rec.end().expect("end");
        let (_cb_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
        let mut rec = cb
            .begin(&tuff::CommandBufferBeginInfo::new())
            .expect("begin");
        layer_names(&s.messages, expected, || {
            // SAFETY: see the module docs; the command buffer is never submitted.
            let _ = unsafe { rec.reset_query_pool_unchecked(&pool, first, count) };
        });
        rec.end().expect("end");
    }
    assert_silent(&s.messages);
}

/// A render pass of two subpasses over the target's one color attachment, and its
/// framebuffer.
fn two_subpasses(
    s: &Setup,
    target: &tuff_setup::ColorTarget,
) -> (tuff::RenderPass, tuff::Framebuffer) {
    let attachments = [vk::AttachmentDescription {
        format: vk::Format::R8G8B8A8_UNORM,
        samples: vk::SampleCountFlags::TYPE_1,
        load_op: vk::AttachmentLoadOp::CLEAR,
        store_op: vk::AttachmentStoreOp::STORE,
        stencil_load_op: vk::AttachmentLoadOp::DONT_CARE,
        stencil_store_op: vk::AttachmentStoreOp::DONT_CARE,
        initial_layout: vk::ImageLayout::UNDEFINED,
        final_layout: vk::ImageLayout::COLOR_ATTACHMENT_OPTIMAL,
        ..Default::default()
    }];
    let color = [vk::AttachmentReference {
        attachment: 0,
        layout: vk::ImageLayout::COLOR_ATTACHMENT_OPTIMAL,
    }];
    let subpasses = [
        tuff::SubpassDescription::new()
            .pipeline_bind_point(vk::PipelineBindPoint::GRAPHICS)
            .color_attachments(&color),
        tuff::SubpassDescription::new()
            .pipeline_bind_point(vk::PipelineBindPoint::GRAPHICS)
            .color_attachments(&color),
    ];
    let stage = vk::PipelineStageFlags::COLOR_ATTACHMENT_OUTPUT;
    let access = vk::AccessFlags::COLOR_ATTACHMENT_WRITE;
    let dependencies = [vk::SubpassDependency {
        src_subpass: 0,
        dst_subpass: 1,
        src_stage_mask: stage,
        dst_stage_mask: stage,
        src_access_mask: access,
        dst_access_mask: access,
        dependency_flags: vk::DependencyFlags::BY_REGION,
    }];
    let render_pass = s
        .device
        .create_render_pass(
            &tuff::RenderPassCreateInfo::new()
                .attachments(&attachments)
                .subpasses(&subpasses)
                .dependencies(&dependencies),
        )
        .expect("render pass");
    let framebuffer = s
        .device
        .create_framebuffer(
            &tuff::FramebufferCreateInfo::new(&render_pass)
                .attachments(&target.view)
                .width(4)
                .height(4)
                .layers(1),
        )
        .expect("framebuffer");
    (render_pass, framebuffer)
}

/// Records `inside` into a render pass instance of `render_pass`, and ends both.
fn in_render_pass(
    s: &Setup,
    (render_pass, framebuffer): (&tuff::RenderPass, &tuff::Framebuffer),
    before: impl FnOnce(&mut tuff::Recorder<'_, tuff::Outside>),
    inside: impl FnOnce(&mut tuff::Recorder<'_, tuff::InRenderPass>),
) -> tuff::Result<()> {
    let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let mut rec = cb
        .begin(&tuff::CommandBufferBeginInfo::new())
        .expect("begin");
    before(&mut rec);
    let clear = [vk::ClearValue::default()];
    let area = vk::Rect2D {
        offset: vk::Offset2D::default(),
        extent: vk::Extent2D {
            width: 4,
            height: 4,
        },
    };
    let mut rec = rec.begin_render_pass(
        &tuff::RenderPassBeginInfo::new(render_pass, framebuffer)
            .render_area(area)
            .clear_values(&clear),
        vk::SubpassContents::INLINE,
    );
    inside(&mut rec);
    rec.end_render_pass().end()
}

/// A recorder inside a render pass instance of `render_pass` over its 4x4 area.
fn begun<'c>(
    cb: &'c mut tuff::CommandBuffer,
    render_pass: (&tuff::RenderPass, &tuff::Framebuffer),
) -> tuff::Recorder<'c, tuff::InRenderPass> {
    let rec = cb
        .begin(&tuff::CommandBufferBeginInfo::new())
        .expect("begin");
    inside_area(rec, render_pass)
}

/// `rec` inside a render pass instance of `render_pass` over its 4x4 area.
fn inside_area<'c>(
    rec: tuff::Recorder<'c, tuff::Outside>,
    (rp, fb): (&tuff::RenderPass, &tuff::Framebuffer),
) -> tuff::Recorder<'c, tuff::InRenderPass> {
    let clear = [vk::ClearValue::default()];
    rec.begin_render_pass(
        &tuff::RenderPassBeginInfo::new(rp, fb)
            .render_area(vk::Rect2D {
                offset: vk::Offset2D::default(),
                extent: vk::Extent2D {
                    width: 4,
                    height: 4,
                },
            })
            .clear_values(&clear),
        vk::SubpassContents::INLINE,
    )
}

#[test]
fn render_pass_instances_end_in_their_last_subpass_and_the_layer_agrees() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let target = s.color_target(4, vk::ImageUsageFlags::empty());
    let (two, two_fb) = two_subpasses(&s, &target);
    let one = (&target.render_pass, &target.framebuffer);
    let last = "VUID-vkCmdEndRenderPass-None-00910";
    let past = "VUID-vkCmdNextSubpass-None-00909";
    // Ended in the first of two subpasses: refused, and the driver sees the second
    // subpass recorded before the end (the layer says nothing).
    assert_eq!(
        vuid(in_render_pass(&s, (&two, &two_fb), |_| {}, |_| {})),
        last
    );
    // A next subpass after the last: refused and not recorded.
    let next = |r: &mut tuff::Recorder<'_, tuff::InRenderPass>| {
        r.next_subpass(vk::SubpassContents::INLINE)
    };
    assert_eq!(vuid(in_render_pass(&s, one, |_| {}, next)), past);
    // Both subpasses visited: recorded.
    in_render_pass(&s, (&two, &two_fb), |_| {}, next).expect("two subpasses");
    assert_silent(&s.messages);

    // Through `_unchecked`, each under the layer: the buffers are never submitted,
    // and are dropped unended (the layer skipped the call, so the recorders' view of
    // them no longer holds).
    let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let rec = begun(&mut cb, (&two, &two_fb));
    layer_names(&s.messages, last, || {
        // SAFETY: see the module docs.
        drop(unsafe { rec.end_render_pass_unchecked() });
    });
    let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let mut rec = begun(&mut cb, one);
    layer_names(&s.messages, past, || {
        // SAFETY: see the module docs.
        unsafe { rec.next_subpass_unchecked(vk::SubpassContents::INLINE) };
    });
    // The recorder follows the calls it was given, not what the layer skipped: it
    // is dropped unended.
    drop(rec);
    assert_silent(&s.messages);
}

#[test]
fn queries_end_where_they_began_and_the_layer_agrees() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let target = s.color_target(4, vk::ImageUsageFlags::empty());
    let one = (&target.render_pass, &target.framebuffer);
    let pool = |ty, count| {
        s.device
            .create_query_pool(
                &tuff::QueryPoolCreateInfo::new()
                    .query_type(ty)
                    .query_count(count),
            )
            .expect("query pool")
    };
    let occlusion = pool(vk::QueryType::OCCLUSION, 2);
    let timestamps = pool(vk::QueryType::TIMESTAMP, 1);
    let none = vk::QueryControlFlags::empty();
    let reset = |r: &mut tuff::Recorder<'_, tuff::Outside>| {
        r.reset_query_pool(&occlusion, 0, 2).expect("reset");
    };
    let begin = |r: &mut tuff::Recorder<'_, tuff::Outside>| {
        reset(r);
        r.begin_query(&occlusion, 0, none).expect("begin query");
    };
    let end_inside =
        |r: &mut tuff::Recorder<'_, tuff::InRenderPass>| r.end_query(&occlusion, 0).map(drop);
    // Begun outside, ended inside.
    let outside_in = "VUID-vkCmdEndQuery-None-07008";
    let refused = in_render_pass(&s, one, begin, |r| {
        assert_eq!(vuid(end_inside(r)), outside_in);
    });
    assert_eq!(vuid(refused), "VUID-vkEndCommandBuffer-commandBuffer-00061");
    // Begun inside, left active at the render pass's end: refused, and ended before
    // the end the driver sees.
    let left = "VUID-vkCmdEndRenderPass-None-07004";
    let refused = in_render_pass(&s, one, reset, |r| {
        r.begin_query(&occlusion, 0, none).expect("begin query");
    });
    assert_eq!(vuid(refused), left);
    // Ended without being begun; two active queries of one type; a timestamp pool; a
    // query past the pool.
    let (_cb_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let mut rec = cb
        .begin(&tuff::CommandBufferBeginInfo::new())
        .expect("begin");
    reset(&mut rec);
    assert_eq!(
        vuid(rec.end_query(&occlusion, 0)),
        "VUID-vkCmdEndQuery-None-01923"
    );
    // A precise occlusion query needs occlusionQueryPrecise, which `setup` leaves off.
    let precise = vk::QueryControlFlags::PRECISE;
    assert_eq!(
        vuid(rec.begin_query(&occlusion, 0, precise)),
        "VUID-vkCmdBeginQuery-queryType-00800"
    );
    rec.begin_query(&occlusion, 0, none).expect("begin query");
    assert_eq!(
        vuid(rec.begin_query(&occlusion, 1, none)),
        "VUID-vkCmdBeginQuery-queryPool-01922"
    );
    assert_eq!(
        vuid(rec.begin_query(&timestamps, 0, none)),
        "VUID-vkCmdBeginQuery-queryType-02804"
    );
    rec.end_query(&occlusion, 0).expect("end query");
    assert_eq!(
        vuid(rec.begin_query(&occlusion, 2, none)),
        "VUID-vkCmdBeginQuery-query-00802"
    );
    rec.end().expect("end");
    // Begun and ended in the render pass's subpass: recorded.
    in_render_pass(&s, one, reset, |r| {
        r.begin_query(&occlusion, 0, none).expect("begin query");
        r.end_query(&occlusion, 0).expect("end query");
    })
    .expect("a query in a subpass");
    assert_silent(&s.messages);

    // Through `_unchecked`, under the layer.
    let (_cb_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let mut rec = cb
        .begin(&tuff::CommandBufferBeginInfo::new())
        .expect("begin");
    reset(&mut rec);
    layer_names(&s.messages, "VUID-vkCmdEndQuery-None-01923", || {
        // SAFETY: see the module docs; the command buffer is never submitted.
        drop(unsafe { rec.end_query_unchecked(&occlusion, 0) });
    });
    // A reset of an active query.
    rec.begin_query(&occlusion, 0, none).expect("begin query");
    assert_eq!(
        vuid(rec.reset_query_pool(&occlusion, 0, 2)),
        "VUID-vkCmdResetQueryPool-None-02841"
    );
    // The 1.3.239 layer does not check it when recording: the error alone proves it.
    rec.end_query(&occlusion, 0).expect("end query");
    layer_names(&s.messages, "VUID-vkCmdBeginQuery-queryType-00800", || {
        // SAFETY: as above.
        drop(unsafe { rec.begin_query_unchecked(&occlusion, 0, precise) });
    });
    // The recorder follows the begin the layer skipped; end it as the layer sees
    // nothing begun, so both agree again.
    layer_names(&s.messages, "VUID-vkCmdEndQuery-None-01923", || {
        // SAFETY: as above.
        drop(unsafe { rec.end_query_unchecked(&occlusion, 0) });
    });
    // Used since the last reset (by the begin before the reset refused above).
    reset(&mut rec);
    rec.begin_query(&occlusion, 0, none).expect("begin query");
    layer_names(&s.messages, "VUID-vkCmdBeginQuery-queryPool-01922", || {
        // SAFETY: as above.
        drop(unsafe { rec.begin_query_unchecked(&occlusion, 1, none) });
    });
    layer_names(&s.messages, "VUID-vkCmdBeginQuery-queryType-02804", || {
        // SAFETY: as above.
        drop(unsafe { rec.begin_query_unchecked(&timestamps, 0, none) });
    });
    rec.end_query(&occlusion, 0).expect("end query");
    layer_names(&s.messages, "VUID-vkCmdBeginQuery-query-00802", || {
        // SAFETY: as above.
        drop(unsafe { rec.begin_query_unchecked(&occlusion, 2, none) });
    });
    // The recorder counts the begun queries the layer skipped: dropped unended.
    drop(rec);
    // A primary ended with an active query, through ash (`Recorder::end` has no
    // unchecked twin). (The 1.3.239 layer checks neither a query begun outside and
    // ended inside nor one left active at a render pass's end: the refusals above
    // alone show those.)
    let (_cb_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let mut rec = cb
        .begin(&tuff::CommandBufferBeginInfo::new())
        .expect("begin");
    reset(&mut rec);
    rec.begin_query(&occlusion, 0, none).expect("begin query");
    let raw = rec.raw();
    layer_names(
        &s.messages,
        "VUID-vkEndCommandBuffer-commandBuffer-00061",
        || {
            // SAFETY: see the module docs; the buffer is never submitted, and its
            // recorder is dropped below without a second end.
            let _ = unsafe { s.device.fns().end_command_buffer(raw) };
        },
    );
    drop(rec);
    assert_silent(&s.messages);
}

/// A recorder whose one-query pool is reset, inside a render pass instance of
/// `render_pass` begun with `vkCmdBeginRenderPass2`.
fn begun2<'c>(
    cb: &'c mut tuff::CommandBuffer,
    (rp, fb): (&tuff::RenderPass, &tuff::Framebuffer),
    pool: &tuff::QueryPool,
) -> tuff::Recorder<'c, tuff::InRenderPass> {
    let mut rec = cb
        .begin(&tuff::CommandBufferBeginInfo::new())
        .expect("begin");
    rec.reset_query_pool(pool, 0, 1).expect("reset");
    let clear = [vk::ClearValue::default()];
    rec.begin_render_pass2(
        &tuff::RenderPassBeginInfo::new(rp, fb)
            .render_area(AREA)
            .clear_values(&clear),
        &tuff::SubpassBeginInfo::new().contents(vk::SubpassContents::INLINE),
    )
}

/// A recorder inside dynamic rendering to `view`, with the one query of `pool`
/// begun.
fn rendered<'c>(
    cb: &'c mut tuff::CommandBuffer,
    view: &tuff::ImageView,
    pool: &tuff::QueryPool,
) -> tuff::Recorder<'c, tuff::InRendering> {
    let mut rec = cb
        .begin(&tuff::CommandBufferBeginInfo::new())
        .expect("begin");
    rec.reset_query_pool(pool, 0, 1).expect("reset");
    let color = [tuff::RenderingAttachmentInfo::new()
        .image_view(Some(view))
        .image_layout(vk::ImageLayout::COLOR_ATTACHMENT_OPTIMAL)
        .load_op(vk::AttachmentLoadOp::CLEAR)
        .store_op(vk::AttachmentStoreOp::STORE)];
    let rendering = tuff::RenderingInfo::new()
        .render_area(AREA)
        .layer_count(1)
        .color_attachments(&color);
    let mut rec = rec.begin_rendering(&rendering);
    rec.begin_query(pool, 0, vk::QueryControlFlags::empty())
        .expect("begin query");
    rec
}

const AREA: vk::Rect2D = vk::Rect2D {
    offset: vk::Offset2D { x: 0, y: 0 },
    extent: vk::Extent2D {
        width: 4,
        height: 4,
    },
};

/// The rules the recorder's subpass and active queries settle, through the commands
/// the test above does not use: `vkCmdEndRenderPass2`, `vkCmdEndRendering`, and an
/// end of a query in another subpass than its begin.
#[test]
fn render_pass2_rendering_and_subpass_queries_end_where_they_began() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let target = s.color_target(4, vk::ImageUsageFlags::empty());
    let (two, two_fb) = two_subpasses(&s, &target);
    let one = (&target.render_pass, &target.framebuffer);
    let occlusion = s
        .device
        .create_query_pool(
            &tuff::QueryPoolCreateInfo::new()
                .query_type(vk::QueryType::OCCLUSION)
                .query_count(1),
        )
        .expect("query pool");
    let none = vk::QueryControlFlags::empty();
    let end_info = tuff::SubpassEndInfo::new();
    let query = |r: &mut tuff::Recorder<'_, tuff::InRenderPass>| {
        r.begin_query(&occlusion, 0, none).expect("begin query");
    };

    // Ended in the first of two subpasses.
    let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let rec = begun2(&mut cb, (&two, &two_fb), &occlusion);
    assert_eq!(
        vuid(rec.end_render_pass2(&end_info).end()),
        "VUID-vkCmdEndRenderPass2-None-03103"
    );
    // A query left active at the instance's end.
    let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let mut rec = begun2(&mut cb, one, &occlusion);
    query(&mut rec);
    assert_eq!(
        vuid(rec.end_render_pass2(&end_info).end()),
        "VUID-vkCmdEndRenderPass2-None-07005"
    );
    // A query ended in the subpass after the one it began in.
    let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let mut rec = begun2(&mut cb, (&two, &two_fb), &occlusion);
    query(&mut rec);
    rec.next_subpass(vk::SubpassContents::INLINE);
    assert_eq!(
        vuid(rec.end_query(&occlusion, 0)),
        "VUID-vkCmdEndQuery-None-07007"
    );
    drop(rec);
    // A query left active at the end of dynamic rendering.
    let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    assert_eq!(
        vuid(
            rendered(&mut cb, &target.view, &occlusion)
                .end_rendering()
                .end()
        ),
        "VUID-vkCmdEndRendering-None-06999"
    );
    assert_silent(&s.messages);

    // Through `_unchecked`, under the layer; the buffers are never submitted and
    // are dropped unended.
    let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let rec = begun2(&mut cb, (&two, &two_fb), &occlusion);
    layer_names(&s.messages, "VUID-vkCmdEndRenderPass2-None-03103", || {
        // SAFETY: see the module docs.
        drop(unsafe { rec.end_render_pass2_unchecked(&end_info) });
    });
    // (The 1.3.239 layer checks neither a query left active at the end of an
    // instance, as for `vkCmdEndRenderPass`, nor one ended in another subpass: the
    // refusals above alone show 07005, 06999 and 07007.)
    assert_silent(&s.messages);
}

/// The 1.3.239 layer does not check this rule at the bind: the refusal alone shows
/// it.
#[test]
fn a_subpass_without_attachments_keeps_its_first_sample_count() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let d = &s.device;
    assert_eq!(
        s.physical.get_features().variable_multisample_rate,
        vk::FALSE,
        "the rule applies where the device cannot vary the sample count"
    );
    let subpasses =
        [tuff::SubpassDescription::new().pipeline_bind_point(vk::PipelineBindPoint::GRAPHICS)];
    let render_pass = d
        .create_render_pass(&tuff::RenderPassCreateInfo::new().subpasses(&subpasses))
        .expect("render pass");
    let framebuffer = d
        .create_framebuffer(
            &tuff::FramebufferCreateInfo::new(&render_pass)
                .width(4)
                .height(4)
                .layers(1),
        )
        .expect("framebuffer");
    let vert = tuff_setup::shader(&s, include_bytes!("../shaders/spv/test.vert.spv"));
    let layout = d
        .create_pipeline_layout(&tuff::PipelineLayoutCreateInfo::new())
        .expect("layout");
    let stages = [tuff::PipelineShaderStageCreateInfo::new(c"main")
        .stage(vk::ShaderStageFlags::VERTEX)
        .module(Some(&vert))];
    let vertex_input = tuff::PipelineVertexInputStateCreateInfo::new();
    let assembly = tuff::PipelineInputAssemblyStateCreateInfo::new()
        .topology(vk::PrimitiveTopology::TRIANGLE_LIST);
    let viewport = tuff::PipelineViewportStateCreateInfo::new()
        .viewport_count(1)
        .scissor_count(1);
    let raster = tuff::PipelineRasterizationStateCreateInfo::new()
        .polygon_mode(vk::PolygonMode::FILL)
        .cull_mode(vk::CullModeFlags::NONE)
        .line_width(1.0);
    let dynamic_states = [vk::DynamicState::VIEWPORT, vk::DynamicState::SCISSOR];
    let dynamic = tuff::PipelineDynamicStateCreateInfo::new().dynamic_states(&dynamic_states);
    let pipeline = |samples| {
        let multisample =
            tuff::PipelineMultisampleStateCreateInfo::new().rasterization_samples(samples);
        let info = tuff::GraphicsPipelineCreateInfo::new()
            .stages(&stages)
            .vertex_input_state(Some(&vertex_input))
            .input_assembly_state(Some(&assembly))
            .viewport_state(Some(&viewport))
            .rasterization_state(Some(&raster))
            .multisample_state(Some(&multisample))
            .dynamic_state(Some(&dynamic))
            .layout(Some(&layout))
            .render_pass(Some(&render_pass))
            .subpass(0);
        let (mut made, r) = d
            .create_graphics_pipelines(None, &[info])
            .expect("pipeline");
        assert_eq!(r, tuff::SuccessOrPipelineCompileRequired::Success);
        made.pop().expect("one pipeline")
    };
    let one = pipeline(vk::SampleCountFlags::TYPE_1);
    let four = pipeline(vk::SampleCountFlags::TYPE_4);
    let expected = "VUID-vkCmdBindPipeline-pipeline-00781";
    let graphics = vk::PipelineBindPoint::GRAPHICS;
    let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let mut rec = begun(&mut cb, (&render_pass, &framebuffer));
    rec.bind_pipeline(graphics, &one)
        .expect("the first pipeline");
    rec.bind_pipeline(graphics, &one)
        .expect("the same count again");
    assert_eq!(vuid(rec.bind_pipeline(graphics, &four)), expected);
    drop(rec.end_render_pass().end());
    assert_silent(&s.messages);
}

/// Buffer creation against the device: concurrent queue families, a capture
/// address, exportable handle types and `maxBufferSize`.
#[test]
fn buffer_creation_is_checked_against_the_device_and_the_layer_agrees() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let d = &s.device;
    let info = || {
        tuff::BufferCreateInfo::new()
            .size(64)
            .usage(vk::BufferUsageFlags::TRANSFER_SRC)
    };
    let families = [s.family, s.family];
    let twice = info()
        .sharing_mode(vk::SharingMode::CONCURRENT)
        .queue_family_indices(&families);
    let mut capture = tuff::BufferOpaqueCaptureAddressCreateInfo::new().opaque_capture_address(64);
    let captured = info().push_next(&mut capture);
    let mut external = tuff::ExternalMemoryBufferCreateInfo::new()
        .handle_types(vk::ExternalMemoryHandleTypeFlags::OPAQUE_WIN32);
    let exported = info().push_next(&mut external);
    let cases = [
        (&twice, "VUID-VkBufferCreateInfo-sharingMode-01419"),
        (
            &captured,
            "VUID-VkBufferCreateInfo-opaqueCaptureAddress-03337",
        ),
        (&exported, "VUID-VkBufferCreateInfo-pNext-00920"),
    ];
    for (info, expected) in &cases {
        assert_eq!(vuid(d.create_buffer(info)), *expected);
    }
    let max = {
        let mut p13 = vk::PhysicalDeviceVulkan13Properties::default();
        let mut p2 = vk::PhysicalDeviceProperties2::default().push_next(&mut p13);
        // SAFETY: a live physical device of a Vulkan 1.3 instance; the chain is local.
        unsafe {
            s.instance
                .fns()
                .get_physical_device_properties2(s.physical.raw(), &mut p2)
        };
        p13.max_buffer_size
    };
    let huge = info().size(max + 1);
    let too_large = "VUID-VkBufferCreateInfo-size-06409";
    assert_eq!(vuid(d.create_buffer(&huge)), too_large);
    drop(d.create_buffer(&info()).expect("a plain buffer"));
    assert_silent(&s.messages);
    // The 1.3.239 layer checks the first two; the refusals alone show the others.
    for (info, expected) in &cases[..2] {
        layer_names(&s.messages, expected, || {
            // SAFETY: see the module docs.
            drop(unsafe { d.create_buffer_unchecked(info) });
        });
    }
}

/// Memory for `buffer`, allocated with `chain` pushed into its allocate info.
fn memory_for(
    s: &Setup,
    buffer: &tuff::Buffer,
    chain: impl FnOnce(tuff::MemoryAllocateInfo<'_>) -> tuff::DeviceMemory,
) -> tuff::DeviceMemory {
    let reqs = s
        .device
        .get_buffer_memory_requirements(buffer)
        .expect("memory requirements");
    chain(
        tuff::MemoryAllocateInfo::new()
            .allocation_size(reqs.size)
            .memory_type_index(
                s.memory_type(reqs.memory_type_bits, vk::MemoryPropertyFlags::HOST_VISIBLE),
            ),
    )
}

#[test]
fn memory_is_bound_only_to_what_it_was_allocated_for_and_the_layer_agrees() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let d = &s.device;
    let buffer = |usage| {
        d.create_buffer(&tuff::BufferCreateInfo::new().size(64).usage(usage))
            .expect("buffer")
    };
    let usage = vk::BufferUsageFlags::TRANSFER_SRC;
    let (a, b) = (buffer(usage), buffer(usage));
    // Memory dedicated to `a`, bound to `b`.
    let dedicated = memory_for(&s, &a, |info| {
        let mut only_a = tuff::MemoryDedicatedAllocateInfo::new().buffer(Some(&a));
        d.allocate_memory(&info.push_next(&mut only_a))
            .expect("dedicated memory")
    });
    let to_other = "VUID-vkBindBufferMemory-memory-01508";
    assert_eq!(vuid(d.bind_buffer_memory(&b, &dedicated, 0)), to_other);
    // Memory exportable as an opaque fd (the safe method exports only for a
    // dedicated object), bound to a buffer with no external handle type.
    let exportable = memory_for(&s, &b, |info| {
        let mut export = tuff::ExportMemoryAllocateInfo::new()
            .handle_types(vk::ExternalMemoryHandleTypeFlags::OPAQUE_FD);
        let mut only_b = tuff::MemoryDedicatedAllocateInfo::new().buffer(Some(&b));
        d.allocate_memory(&info.push_next(&mut export).push_next(&mut only_b))
            .expect("exportable memory")
    });
    let not_external = "VUID-vkBindBufferMemory-memory-02726";
    assert_eq!(vuid(d.bind_buffer_memory(&b, &exportable, 0)), not_external);
    // The second version checks each info alike, under its struct's VUIDs.
    let two =
        |buffer, memory| d.bind_buffer_memory2(&[tuff::BindBufferMemoryInfo::new(buffer, memory)]);
    let to_other2 = "VUID-VkBindBufferMemoryInfo-memory-01508";
    let not_external2 = "VUID-VkBindBufferMemoryInfo-memory-02726";
    assert_eq!(vuid(two(&b, &dedicated)), to_other2);
    assert_eq!(vuid(two(&b, &exportable)), not_external2);
    // The dedicated memory binds to its buffer.
    d.bind_buffer_memory(&a, &dedicated, 0)
        .expect("the dedicated buffer");
    assert_silent(&s.messages);
    layer_names(&s.messages, to_other, || {
        // SAFETY: see the module docs.
        drop(unsafe { d.bind_buffer_memory_unchecked(&b, &dedicated, 0) });
    });
    layer_names(&s.messages, not_external, || {
        // SAFETY: see the module docs.
        drop(unsafe { d.bind_buffer_memory_unchecked(&b, &exportable, 0) });
    });
    for (memory, rule) in [(&dedicated, to_other2), (&exportable, not_external2)] {
        layer_names(&s.messages, rule, || {
            // SAFETY: see the module docs.
            drop(unsafe {
                d.bind_buffer_memory2_unchecked(&[tuff::BindBufferMemoryInfo::new(&b, memory)])
            });
        });
    }
}

#[test]
fn a_buffer_with_a_device_address_needs_such_memory_and_the_layer_agrees() {
    let _serial = vulkan::serial();
    let s = tuff_setup::setup_full_features(true);
    let d = &s.device;
    let buffer = d
        .create_buffer(
            &tuff::BufferCreateInfo::new()
                .size(64)
                .usage(vk::BufferUsageFlags::SHADER_DEVICE_ADDRESS),
        )
        .expect("buffer");
    let plain = memory_for(&s, &buffer, |info| {
        d.allocate_memory(&info).expect("memory")
    });
    let expected = "VUID-vkBindBufferMemory-bufferDeviceAddress-03339";
    assert_eq!(vuid(d.bind_buffer_memory(&buffer, &plain, 0)), expected);
    let expected2 = "VUID-VkBindBufferMemoryInfo-bufferDeviceAddress-03339";
    assert_eq!(
        vuid(d.bind_buffer_memory2(&[tuff::BindBufferMemoryInfo::new(&buffer, &plain)])),
        expected2
    );
    let addressable = memory_for(&s, &buffer, |info| {
        let mut flags =
            tuff::MemoryAllocateFlagsInfo::new().flags(vk::MemoryAllocateFlags::DEVICE_ADDRESS);
        d.allocate_memory(&info.push_next(&mut flags))
            .expect("memory")
    });
    d.bind_buffer_memory(&buffer, &addressable, 0)
        .expect("memory with a device address");
    assert_silent(&s.messages);
    let other = d
        .create_buffer(
            &tuff::BufferCreateInfo::new()
                .size(64)
                .usage(vk::BufferUsageFlags::SHADER_DEVICE_ADDRESS),
        )
        .expect("buffer");
    layer_names(&s.messages, expected, || {
        // SAFETY: see the module docs.
        drop(unsafe { d.bind_buffer_memory_unchecked(&other, &plain, 0) });
    });
    // The 1.3.239 layer names the first version's VUID for the second's call.
    layer_names(&s.messages, expected, || {
        // SAFETY: see the module docs.
        drop(unsafe {
            d.bind_buffer_memory2_unchecked(&[tuff::BindBufferMemoryInfo::new(&other, &plain)])
        });
    });
}

/// A device group binding names one device index per physical device (01606),
/// each valid (01607); lavapipe's devices have one physical device.
#[test]
fn a_device_group_buffer_binding_names_the_devices_it_has() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let d = &s.device;
    let buffer = || {
        d.create_buffer(
            &tuff::BufferCreateInfo::new()
                .size(64)
                .usage(vk::BufferUsageFlags::TRANSFER_SRC),
        )
        .expect("buffer")
    };
    let (a, b) = (buffer(), buffer());
    let memory = memory_for(&s, &a, |info| d.allocate_memory(&info).expect("memory"));
    for (indices, rule) in [
        (
            &[0u32, 0][..],
            "VUID-VkBindBufferMemoryDeviceGroupInfo-deviceIndexCount-01606",
        ),
        (
            &[1u32][..],
            "VUID-VkBindBufferMemoryDeviceGroupInfo-pDeviceIndices-01607",
        ),
    ] {
        let mut group = tuff::BindBufferMemoryDeviceGroupInfo::new().device_indices(indices);
        let info = [tuff::BindBufferMemoryInfo::new(&a, &memory).push_next(&mut group)];
        assert_eq!(vuid(d.bind_buffer_memory2(&info)), rule);
        layer_names(&s.messages, rule, || {
            // SAFETY: see the module docs.
            drop(unsafe { d.bind_buffer_memory2_unchecked(&info) });
        });
    }
    let mut group = tuff::BindBufferMemoryDeviceGroupInfo::new().device_indices(&[0]);
    d.bind_buffer_memory2(&[tuff::BindBufferMemoryInfo::new(&a, &memory).push_next(&mut group)])
        .expect("the one device's instance");
    let other = memory_for(&s, &b, |info| d.allocate_memory(&info).expect("memory"));
    d.bind_buffer_memory2(&[tuff::BindBufferMemoryInfo::new(&b, &other)])
        .expect("no device group info");
    assert_silent(&s.messages);
}

/// An event set or reset from no stage at all needs synchronization2: on a device
/// without it the safe call is refused with the rule's VUID and the layer names it
/// for the unchecked one; from a stage the pool's family runs, both record.
#[test]
fn events_without_stages_need_synchronization2() {
    let _serial = vulkan::serial();
    let s = tuff_setup::setup_bare(true);
    let event = s
        .device
        .create_event(&tuff::EventCreateInfo::new())
        .expect("event");
    let none = vk::PipelineStageFlags::empty();
    let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let mut rec = cb
        .begin(&tuff::CommandBufferBeginInfo::new())
        .expect("begin");
    assert_eq!(
        vuid(rec.set_event(&event, none)),
        "VUID-vkCmdSetEvent-stageMask-03937"
    );
    layer_names(&s.messages, "VUID-vkCmdSetEvent-stageMask-03937", || {
        // SAFETY: the layer skips the call, which breaks only the rule under test;
        // the command buffer is never submitted.
        drop(unsafe { rec.set_event_unchecked(&event, none) });
    });
    let reset = rec.reset_event(&event, none);
    assert_eq!(vuid(reset), "VUID-vkCmdResetEvent-stageMask-03937");
    layer_names(&s.messages, "VUID-vkCmdResetEvent-stageMask-03937", || {
        // SAFETY: as above.
        drop(unsafe { rec.reset_event_unchecked(&event, none) });
    });
    // Two events: a reset after a set of one event without a barrier between them
    // would race.
    let other = s
        .device
        .create_event(&tuff::EventCreateInfo::new())
        .expect("event");
    let transfer = vk::PipelineStageFlags::TRANSFER;
    rec.set_event(&event, transfer).expect("set from a stage");
    rec.reset_event(&other, transfer)
        .expect("reset from a stage");
    rec.end().expect("end");
    assert_silent(&s.messages);
}

/// A copy of query results into a buffer: queries past the pool, results past the
/// buffer, partial timestamps and an active query are refused with the rule's VUID,
/// and the layer names each for the unchecked call, which it skips; a copy of every
/// result, at its stride, inside the buffer records silently.
#[test]
fn query_results_are_copied_inside_their_buffer() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let pool = |ty| {
        s.device
            .create_query_pool(
                &tuff::QueryPoolCreateInfo::new()
                    .query_type(ty)
                    .query_count(2),
            )
            .expect("query pool")
    };
    let occlusion = pool(vk::QueryType::OCCLUSION);
    let timestamps = pool(vk::QueryType::TIMESTAMP);
    let (buffer, _memory) = pipelines::host_buffer(&s, 16, vk::BufferUsageFlags::TRANSFER_DST);
    let none = vk::QueryResultFlags::empty();
    let partial = vk::QueryResultFlags::PARTIAL;
    // (rule, pool, first, count, dstOffset, flags)
    let cases = [
        (
            "VUID-vkCmdCopyQueryPoolResults-firstQuery-00821",
            &occlusion,
            1,
            2,
            0,
            none,
        ),
        (
            "VUID-vkCmdCopyQueryPoolResults-dstBuffer-00824",
            &occlusion,
            0,
            2,
            8,
            none,
        ),
        (
            "VUID-vkCmdCopyQueryPoolResults-queryType-00827",
            &timestamps,
            0,
            1,
            0,
            partial,
        ),
        (
            "VUID-vkCmdCopyQueryPoolResults-None-07429",
            &occlusion,
            0,
            1,
            0,
            none,
        ),
    ];
    let (_cb_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let mut wrong = Vec::new();
    for (rule, pool, first, count, offset, flags) in cases {
        let mut rec = cb
            .begin(&tuff::CommandBufferBeginInfo::new())
            .expect("begin");
        rec.reset_query_pool(pool, 0, 2).expect("reset");
        if rule.ends_with("-07429") {
            rec.begin_query(pool, 0, vk::QueryControlFlags::empty())
                .expect("begin query");
        }
        let safe = vuid(rec.copy_query_pool_results(pool, first, count, &buffer, offset, 8, flags));
        s.messages.take();
        s.messages.abort_on_error(true);
        // SAFETY: the layer skips the call, which breaks only the rule under test;
        // the command buffer is never submitted.
        let _ = unsafe {
            rec.copy_query_pool_results_unchecked(pool, first, count, &buffer, offset, 8, flags)
        };
        s.messages.abort_on_error(false);
        let said = s.messages.take();
        // The 1.3.239 layer does not check an active query's copy: the error alone
        // proves it.
        let named = match rule.ends_with("-07429") {
            true => said.is_empty(),
            false => said.iter().any(|m| m.contains(rule)),
        };
        if safe != rule || !named {
            wrong.push(format!("{rule}: tuff said {safe}; the layer said {said:?}"));
        }
        drop(rec);
    }
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
    let mut rec = cb
        .begin(&tuff::CommandBufferBeginInfo::new())
        .expect("begin");
    rec.reset_query_pool(&occlusion, 0, 2).expect("reset");
    rec.copy_query_pool_results(&occlusion, 0, 2, &buffer, 8, 4, none)
        .expect("both results inside the buffer");
    rec.end().expect("end");
    assert_silent(&s.messages);
}

/// A dispatch from a base group other than zero needs the bound compute pipeline to
/// have been created with `DISPATCH_BASE` (00427): refused without it, as the layer
/// says through `_unchecked`, and recorded with it.
#[test]
fn a_base_group_needs_a_dispatch_base_pipeline() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let target = s.color_target(4, vk::ImageUsageFlags::empty());
    let p = pipelines::pipelines(&s, &target);
    let stage = tuff::PipelineShaderStageCreateInfo::new(c"main")
        .stage(vk::ShaderStageFlags::COMPUTE)
        .module(Some(&p.comp));
    let based = s
        .device
        .create_compute_pipeline(
            None,
            &tuff::ComputePipelineCreateInfo::new(stage, &p.compute_layout)
                .flags(vk::PipelineCreateFlags::DISPATCH_BASE),
        )
        .expect("a pipeline made for base groups");
    let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let mut rec = cb
        .begin(&tuff::CommandBufferBeginInfo::new())
        .expect("begin");
    let compute = vk::PipelineBindPoint::COMPUTE;
    rec.bind_pipeline(compute, &p.compute).expect("bind");
    rec.bind_descriptor_sets(compute, &p.compute_layout, 0, &p.set, &[])
        .expect("sets");
    let rule = "VUID-vkCmdDispatchBase-baseGroupX-00427";
    for base in [[1, 0, 0], [0, 1, 0], [0, 0, 1]] {
        assert_eq!(
            vuid(rec.dispatch_base(base[0], base[1], base[2], 1, 1, 1)),
            rule
        );
    }
    // From group zero any pipeline dispatches.
    rec.dispatch_base(0, 0, 0, 1, 1, 1)
        .expect("a dispatch from group zero");
    layer_names(&s.messages, rule, || {
        // SAFETY: see the module docs; the command buffer is never submitted.
        drop(unsafe { rec.dispatch_base_unchecked(1, 0, 0, 1, 1, 1) });
    });
    rec.bind_pipeline(compute, &based).expect("bind");
    // The dispatches write the same storage buffer: ordered, or they race.
    let w = [tuff::MemoryBarrier::new()
        .src_access_mask(vk::AccessFlags::SHADER_WRITE)
        .dst_access_mask(vk::AccessFlags::SHADER_WRITE)];
    let cs = vk::PipelineStageFlags::COMPUTE_SHADER;
    rec.pipeline_barrier(cs, cs, vk::DependencyFlags::empty(), &w, &[], &[])
        .expect("barrier");
    rec.dispatch_base(1, 1, 1, 1, 1, 1)
        .expect("a dispatch from a base group with a pipeline made for it");
    rec.end().expect("end");
    assert_silent(&s.messages);
}

/// A device mask names only physical devices the device has (00108); lavapipe's
/// devices have one, so every other bit is refused, as the layer says through
/// `_unchecked`, and the one device's mask is recorded.
#[test]
fn a_device_mask_names_the_devices_physical_devices() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let mut rec = cb
        .begin(&tuff::CommandBufferBeginInfo::new())
        .expect("begin");
    let rule = "VUID-vkCmdSetDeviceMask-deviceMask-00108";
    for mask in [0b10, 0b11, 1 << 31] {
        assert_eq!(vuid(rec.set_device_mask(mask)), rule);
    }
    rec.set_device_mask(1).expect("the one physical device");
    layer_names(&s.messages, rule, || {
        // SAFETY: see the module docs; the command buffer is never submitted.
        drop(unsafe { rec.set_device_mask_unchecked(0b10) });
    });
    rec.end().expect("end");
    assert_silent(&s.messages);
}

/// Device indices, split regions, the rule they break, and what the layer names.
type GroupCase<'a> = (&'a [u32], &'a [vk::Rect2D], &'a str, Option<&'a str>);

/// The second version's image binds: a device group info names one device index per
/// physical device, each valid, or split regions (01633 to 01636, 01627); an image
/// is bound once per call (04006); memory dedicated to another image or exportable
/// as no handle type of the image is refused (01509, 02728).
#[test]
fn an_image_bound_by_the_second_version_gets_memory_it_can_live_in() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let d = &s.device;
    let image = || {
        d.create_image(
            &tuff::ImageCreateInfo::new()
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
                .usage(vk::ImageUsageFlags::SAMPLED),
        )
        .expect("image")
    };
    let (a, b) = (image(), image());
    let reqs = d
        .get_image_memory_requirements(&a)
        .expect("memory requirements");
    let info = || {
        tuff::MemoryAllocateInfo::new()
            .allocation_size(reqs.size)
            .memory_type_index(
                s.memory_type(reqs.memory_type_bits, vk::MemoryPropertyFlags::empty()),
            )
    };
    let memory = d.allocate_memory(&info()).expect("memory");
    let whole = [vk::Rect2D {
        offset: vk::Offset2D::default(),
        extent: vk::Extent2D {
            width: 4,
            height: 4,
        },
    }];
    let two = [whole[0], whole[0]];
    // Each with what the layer names: 01635 it does not check, and a split region
    // it reports as 01627 first, which lavapipe's images always break (an image with
    // split instance bind regions needs a device group of more than one device).
    let split = "VUID-VkBindImageMemoryInfo-pNext-01627";
    let cases: [GroupCase<'_>; 5] = [
        (
            &[0, 0],
            &[],
            "VUID-VkBindImageMemoryDeviceGroupInfo-deviceIndexCount-01634",
            Some("VUID-VkBindImageMemoryDeviceGroupInfo-deviceIndexCount-01634"),
        ),
        (
            &[1],
            &[],
            "VUID-VkBindImageMemoryDeviceGroupInfo-pDeviceIndices-01635",
            None,
        ),
        (
            &[0],
            &whole,
            "VUID-VkBindImageMemoryDeviceGroupInfo-deviceIndexCount-01633",
            Some(split),
        ),
        (
            &[],
            &two,
            "VUID-VkBindImageMemoryDeviceGroupInfo-splitInstanceBindRegionCount-01636",
            Some(split),
        ),
        (&[], &whole, split, Some(split)),
    ];
    for (indices, regions, rule, layer) in cases {
        // A fresh image and memory each: a call the layer does not skip binds them.
        let (fresh, memory) = (image(), d.allocate_memory(&info()).expect("memory"));
        let mut group = tuff::BindImageMemoryDeviceGroupInfo::new()
            .device_indices(indices)
            .split_instance_bind_regions(regions);
        let infos = [tuff::BindImageMemoryInfo::new(&fresh, &memory).push_next(&mut group)];
        assert_eq!(vuid(d.bind_image_memory2(&infos)), rule);
        assert_silent(&s.messages);
        s.messages.take();
        s.messages.abort_on_error(true);
        // SAFETY: see the module docs.
        drop(unsafe { d.bind_image_memory2_unchecked(&infos) });
        s.messages.abort_on_error(false);
        let said = s.messages.take();
        match layer {
            Some(named) => assert!(
                said.iter().any(|m| m.contains(named)),
                "the layer did not name {named} for {rule}: {said:?}"
            ),
            None => assert!(said.is_empty(), "the layer now checks {rule}: {said:?}"),
        }
    }
    // One image twice in one call.
    let other = d.allocate_memory(&info()).expect("memory");
    let twice = [
        tuff::BindImageMemoryInfo::new(&a, &memory),
        tuff::BindImageMemoryInfo::new(&a, &other),
    ];
    let rule = "VUID-vkBindImageMemory2-pBindInfos-04006";
    assert_eq!(vuid(d.bind_image_memory2(&twice)), rule);
    assert_silent(&s.messages);
    layer_names(&s.messages, rule, || {
        // SAFETY: see the module docs.
        drop(unsafe { d.bind_image_memory2_unchecked(&twice) });
    });
    // Memory dedicated to `a`, and memory exportable as an opaque fd dedicated to
    // `b` (which names no external handle type), bound to `b`.
    let mut only_a = tuff::MemoryDedicatedAllocateInfo::new().image(Some(&a));
    let dedicated = d
        .allocate_memory(&info().push_next(&mut only_a))
        .expect("dedicated memory");
    let mut export = tuff::ExportMemoryAllocateInfo::new()
        .handle_types(vk::ExternalMemoryHandleTypeFlags::OPAQUE_FD);
    let mut only_b = tuff::MemoryDedicatedAllocateInfo::new().image(Some(&b));
    let exportable = d
        .allocate_memory(&info().push_next(&mut export).push_next(&mut only_b))
        .expect("exportable memory");
    for (memory, rule) in [
        (&dedicated, "VUID-VkBindImageMemoryInfo-memory-01509"),
        (&exportable, "VUID-VkBindImageMemoryInfo-memory-02728"),
    ] {
        let infos = [tuff::BindImageMemoryInfo::new(&b, memory)];
        assert_eq!(vuid(d.bind_image_memory2(&infos)), rule);
        assert_silent(&s.messages);
        layer_names(&s.messages, rule, || {
            // SAFETY: see the module docs.
            drop(unsafe { d.bind_image_memory2_unchecked(&infos) });
        });
    }
    // The one device's instance, and the dedicated memory to its image.
    let mut group = tuff::BindImageMemoryDeviceGroupInfo::new().device_indices(&[0]);
    d.bind_image_memory2(&[
        tuff::BindImageMemoryInfo::new(&a, &dedicated).push_next(&mut group),
        tuff::BindImageMemoryInfo::new(&b, &memory),
    ])
    .expect("two images, each with memory it can live in");
    assert_silent(&s.messages);
}
