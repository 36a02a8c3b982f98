//! The generated wrappers on lavapipe, with the validation layer and its
//! synchronization validation on: objects of every handle type lavapipe supports are
//! created, used and dropped in random orders (parents before children included),
//! and resources are dropped while the submission that uses them is still in flight.
//!
//! Lavapipe (Mesa 22.3) does not support `samplerYcbcrConversion`, so
//! `SamplerYcbcrConversion` is the one handle type of the emitted API not made here;
//! surfaces and swapchains are made in a window of the X server named by `DISPLAY`
//! (Xvfb on CI).
//!
//! SAFETY of the `unsafe` blocks around checked methods: such a method is `unsafe`
//! because it leaves rules to its caller (its `# Safety` section lists them). The
//! calls here keep every rule so listed and break, on purpose, only rules the method
//! checks; that one argument covers every such block in this file.

#[path = "common/pipelines.rs"]
mod pipelines;
#[path = "common/tuff_setup.rs"]
mod tuff_setup;
#[path = "common/vulkan.rs"]
mod vulkan;
#[path = "common/x11_window.rs"]
mod x11_window;

use pipelines::{access_memory, host_buffer, pipelines, Pipelines, COLOR, FACTOR, INVOCATIONS};
use std::any::Any;
use tuff::vk;
use tuff_setup::{setup, setup_with, swapchain_info, ColorTarget, Setup, Wsi};
use vulkan::assert_silent;

/// A small deterministic shuffle, so a failing order can be replayed.
fn shuffle<T>(items: &mut [T], mut seed: u64) {
    for i in (1..items.len()).rev() {
        seed = seed
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        let j = (seed >> 33) as usize % (i + 1);
        items.swap(i, j);
    }
}

fn buffer_with_memory(s: &Setup, size: u64) -> (tuff::Buffer, tuff::DeviceMemory) {
    host_buffer(
        s,
        size,
        vk::BufferUsageFlags::TRANSFER_DST
            | vk::BufferUsageFlags::UNIFORM_BUFFER
            | vk::BufferUsageFlags::UNIFORM_TEXEL_BUFFER,
    )
}

/// Every handle type this test can make, in one bag, in creation order.
fn make_all(s: &Setup) -> Vec<Box<dyn Any>> {
    let d = &s.device;
    let mut bag: Vec<Box<dyn Any>> = Vec::new();
    let (buffer, memory) = buffer_with_memory(s, 4096);
    let view = d
        .create_buffer_view(
            &tuff::BufferViewCreateInfo::new(&buffer)
                .format(vk::Format::R32_UINT)
                .range(vk::WHOLE_SIZE),
        )
        .expect("buffer view");
    let target = s.color_target(16, vk::ImageUsageFlags::SAMPLED);
    // Shader modules, both pipelines and a descriptor update template, used by a
    // submission that is still in flight when the bag is dropped.
    let work = pipelines(s, &target);
    let sampler = d
        .create_sampler(&tuff::SamplerCreateInfo::new())
        .expect("sampler");
    let bindings = [tuff::DescriptorSetLayoutBinding::new()
        .binding(0)
        .descriptor_type(vk::DescriptorType::UNIFORM_BUFFER)
        .descriptor_count(1)
        .stage_flags(vk::ShaderStageFlags::VERTEX)];
    let set_layout = d
        .create_descriptor_set_layout(
            &tuff::DescriptorSetLayoutCreateInfo::new().bindings(&bindings[..]),
        )
        .expect("set layout");
    let sizes = [vk::DescriptorPoolSize {
        ty: vk::DescriptorType::UNIFORM_BUFFER,
        descriptor_count: 4,
    }];
    let pool = d
        .create_descriptor_pool(
            &tuff::DescriptorPoolCreateInfo::new()
                .flags(vk::DescriptorPoolCreateFlags::FREE_DESCRIPTOR_SET)
                .max_sets(4)
                .pool_sizes(&sizes),
        )
        .expect("descriptor pool");
    let sets = d
        .allocate_descriptor_sets(
            &pool,
            &tuff::DescriptorSetAllocateInfo::new(&pool).set_layouts(&set_layout),
        )
        .expect("descriptor sets");
    let buffer_info = [tuff::DescriptorBufferInfo::new()
        .buffer(Some(&buffer))
        .range(256)];
    let writes = [tuff::WriteDescriptorSet::new(&sets[0])
        .descriptor_type(vk::DescriptorType::UNIFORM_BUFFER)
        .buffer_info(&buffer_info)];
    d.update_descriptor_sets(&writes, &[])
        .expect("descriptor writes");
    let ranges = [vk::PushConstantRange {
        stage_flags: vk::ShaderStageFlags::VERTEX,
        offset: 0,
        size: 64,
    }];
    let set_layouts = tuff::HandleSlice::new(&[&set_layout]);
    let pipeline_layout = d
        .create_pipeline_layout(
            &tuff::PipelineLayoutCreateInfo::new()
                .set_layouts(&set_layouts)
                .push_constant_ranges(&ranges),
        )
        .expect("pipeline layout");
    let cache = d
        .create_pipeline_cache(&tuff::PipelineCacheCreateInfo::new())
        .expect("pipeline cache");
    let cache_data = d
        .get_pipeline_cache_data(&cache)
        .expect("pipeline cache data");
    assert!(!cache_data.is_empty(), "a pipeline cache has a header");
    let semaphore = d
        .create_semaphore(&tuff::SemaphoreCreateInfo::new())
        .expect("semaphore");
    let event = d
        .create_event(&tuff::EventCreateInfo::new())
        .expect("event");
    let query_pool = d
        .create_query_pool(
            &tuff::QueryPoolCreateInfo::new()
                .query_type(vk::QueryType::OCCLUSION)
                .query_count(2),
        )
        .expect("query pool");
    let slot = d
        .create_private_data_slot(&tuff::PrivateDataSlotCreateInfo::new())
        .expect("private data slot");
    let command_pool = d
        .create_command_pool(&tuff::CommandPoolCreateInfo::new().queue_family_index(s.family))
        .expect("command pool");
    let cbs = d
        .allocate_command_buffers(
            &command_pool,
            &tuff::CommandBufferAllocateInfo::new(&command_pool)
                .level(vk::CommandBufferLevel::PRIMARY)
                .command_buffer_count(2),
        )
        .expect("command buffers");
    let fence = d
        .create_fence(&tuff::FenceCreateInfo::new())
        .expect("fence");
    let mut cbs = cbs;
    let mut rec = cbs[0]
        .begin(&tuff::CommandBufferBeginInfo::new())
        .expect("begin");
    rec = work.record(rec, &target, 16, None);
    rec.end().expect("end");
    let handles = tuff::HandleSlice::new(&[&cbs[0]]);
    s.queue
        .submit(
            &[tuff::SubmitInfo::new().command_buffers(&handles)],
            Some(&fence),
        )
        .expect("submit");
    let ColorTarget {
        image,
        memory: image_memory,
        view: image_view,
        render_pass,
        framebuffer,
    } = target;
    let Pipelines {
        vert,
        frag,
        comp,
        graphics_layout,
        graphics,
        compute_set_layout,
        compute_layout,
        compute,
        template,
        descriptor_pool,
        set,
        uniform,
        output,
    } = work;
    bag.push(Box::new(vert));
    bag.push(Box::new(frag));
    bag.push(Box::new(comp));
    bag.push(Box::new(graphics_layout));
    bag.push(Box::new(graphics));
    bag.push(Box::new(compute_set_layout));
    bag.push(Box::new(compute_layout));
    bag.push(Box::new(compute));
    bag.push(Box::new(template));
    bag.push(Box::new(descriptor_pool));
    bag.push(Box::new(set));
    bag.push(Box::new(uniform));
    bag.push(Box::new(output));
    bag.push(Box::new(buffer));
    bag.push(Box::new(memory));
    bag.push(Box::new(view));
    bag.push(Box::new(image));
    bag.push(Box::new(image_memory));
    bag.push(Box::new(image_view));
    bag.push(Box::new(render_pass));
    bag.push(Box::new(framebuffer));
    bag.push(Box::new(sampler));
    bag.push(Box::new(set_layout));
    bag.push(Box::new(pool));
    bag.push(Box::new(sets));
    bag.push(Box::new(pipeline_layout));
    bag.push(Box::new(cache));
    bag.push(Box::new(semaphore));
    bag.push(Box::new(event));
    bag.push(Box::new(query_pool));
    bag.push(Box::new(slot));
    bag.push(Box::new(command_pool));
    bag.push(Box::new(cbs));
    bag.push(Box::new(fence));
    bag
}

#[test]
fn every_handle_type_in_random_drop_orders() {
    let _serial = vulkan::serial();
    for seed in 0..6u64 {
        let s = setup(true);
        let mut bag = make_all(&s);
        assert_eq!(bag.len(), 34);
        shuffle(&mut bag, seed);
        // Dropping a parent (pool, device memory, render pass) before its children
        // only drops a reference; the last one out destroys.
        while let Some(item) = bag.pop() {
            drop(item);
        }
        assert_silent(&s.messages);
    }
}

#[test]
fn parents_dropped_before_children_stay_alive() {
    let _serial = vulkan::serial();
    let Setup {
        device,
        queue,
        family,
        instance,
        messenger,
        messages,
        memory_types,
        ..
    } = setup(true);
    let _ = (memory_types, queue);
    let pool = device
        .create_command_pool(&tuff::CommandPoolCreateInfo::new().queue_family_index(family))
        .expect("pool");
    let cbs = device
        .allocate_command_buffers(
            &pool,
            &tuff::CommandBufferAllocateInfo::new(&pool).command_buffer_count(1),
        )
        .expect("cbs");
    drop(pool);
    drop(device);
    drop(instance);
    // The command buffer still holds its pool, device and instance.
    drop(cbs);
    drop(messenger);
    assert_silent(&messages);
}

#[test]
fn resources_dropped_while_their_submission_is_in_flight() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let d = &s.device;
    let fence = d
        .create_fence(&tuff::FenceCreateInfo::new())
        .expect("fence");
    for round in 0..20u32 {
        let (buffer, memory) = buffer_with_memory(&s, 1 << 20);
        let (pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
        let mut rec = cb
            .begin(&tuff::CommandBufferBeginInfo::new())
            .expect("begin");
        for i in 0..64u64 {
            rec.fill_buffer(&buffer, i * 16384, 16384, round)
                .expect("fill");
        }
        rec.end().expect("end");
        let cb_handles = tuff::HandleSlice::new(&[&cb]);
        let submits = [tuff::SubmitInfo::new().command_buffers(&cb_handles)];
        s.queue.submit(&submits, Some(&fence)).expect("submit");
        // Everything the submission uses goes while it may still run; the fence
        // keeps the command buffer, and through it the buffer and memory, alive.
        let _ = submits;
        drop(cb_handles);
        drop(cb);
        drop(pool);
        drop(buffer);
        drop(memory);
        let status = d.wait_for_fences(&fence, true, u64::MAX).expect("wait");
        assert_eq!(status, tuff::SuccessOrTimeout::Success);
        d.reset_fences(&fence).expect("reset");
    }
    assert_silent(&s.messages);
}

#[test]
fn a_submitted_buffer_is_written() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let (buffer, memory) = buffer_with_memory(&s, 256);
    submit_and_wait(&s, |rec| {
        rec.fill_buffer(&buffer, 0, 256, 0xA5A5_A5A5).expect("fill")
    });
    // Read back through ash on the raw handles: Deref keeps the layer transparent.
    let bytes = access_memory(&s, &memory, 256, None);
    assert!(
        bytes.iter().all(|b| *b == 0xA5),
        "the fill reached the buffer"
    );
    assert_silent(&s.messages);
}

/// A command with several success codes answers with its status enum: a wait that
/// times out is `Timeout`, not an `Ok(())`, and a fence's and an event's states are
/// variants of their own.
#[test]
fn several_success_codes_are_typed() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let d = &s.device;
    let fence = d
        .create_fence(&tuff::FenceCreateInfo::new())
        .expect("fence");
    assert_eq!(
        d.wait_for_fences(&fence, true, 0).expect("wait"),
        tuff::SuccessOrTimeout::Timeout
    );
    assert_eq!(
        d.get_fence_status(&fence).expect("status"),
        tuff::SuccessOrNotReady::NotReady
    );
    let event = d
        .create_event(&tuff::EventCreateInfo::new())
        .expect("event");
    assert_eq!(
        d.get_event_status(&event).expect("status"),
        tuff::EventSetOrEventReset::EventReset
    );
    d.set_event(&event).expect("set");
    assert_eq!(
        d.get_event_status(&event).expect("status"),
        tuff::EventSetOrEventReset::EventSet
    );
    // The code a status stands for.
    assert_eq!(
        vk::Result::from(tuff::SuccessOrTimeout::Timeout),
        vk::Result::TIMEOUT
    );
    assert_silent(&s.messages);
}

#[test]
fn arrays_of_handles_take_the_same_forms_in_commands_and_structs() {
    use tuff::Handle as _;
    let _serial = vulkan::serial();
    let s = setup(true);
    let d = &s.device;
    let fence = || {
        d.create_fence(&tuff::FenceCreateInfo::new().flags(vk::FenceCreateFlags::SIGNALED))
            .expect("fence")
    };
    let (a, b) = (fence(), fence());
    let layout = d
        .create_descriptor_set_layout(&tuff::DescriptorSetLayoutCreateInfo::new())
        .expect("set layout");
    // One wrapper as it is, in a command and in a struct: an array of its one handle.
    assert_eq!(
        d.wait_for_fences(&a, true, 0).expect("wait"),
        tuff::SuccessOrTimeout::Success
    );
    let one = tuff::PipelineLayoutCreateInfo::new().set_layouts(&layout);
    assert_eq!(one.set_layout_count, 1);
    // SAFETY: the setter stored a pointer to one handle, borrowed from `layout`.
    assert_eq!(unsafe { *one.p_set_layouts }, layout.raw());
    // Several as a `HandleSlice`, built from a list or collected, in either place.
    let both = tuff::HandleSlice::new(&[&a, &b]);
    d.reset_fences(&both).expect("reset");
    assert_eq!(
        d.get_fence_status(&b).expect("status"),
        tuff::SuccessOrNotReady::NotReady
    );
    let layouts: tuff::HandleSlice<_> = [&layout, &layout].into_iter().collect();
    let two = tuff::PipelineLayoutCreateInfo::new().set_layouts(&layouts);
    assert_eq!(two.set_layout_count, 2);
    // SAFETY: the setter stored a pointer to `layouts`' two handles.
    let stored = unsafe { std::slice::from_raw_parts(two.p_set_layouts, 2) };
    assert_eq!(stored, [layout.raw(); 2]);
    // The struct reaches Vulkan: two sets of the same (empty) layout.
    let pipeline_layout = d.create_pipeline_layout(&two).expect("pipeline layout");
    drop(pipeline_layout);
    assert_silent(&s.messages);
}

#[test]
fn codec_structs_are_taken_as_slices_that_set_their_count() {
    // SAFETY: all-zero bytes are a parameter set: numbers, bit flags and null pointers.
    let sps: [vk::native::StdVideoH264SequenceParameterSet; 2] = unsafe { std::mem::zeroed() };
    // SAFETY: the parameter sets' own pointers are null, which the codec allows here.
    let add = unsafe { tuff::VideoDecodeH264SessionParametersAddInfoKHR::new().std_sp_ss(&sps) };
    assert_eq!(add.std_sps_count, 2);
    assert_eq!(add.p_std_sp_ss, sps.as_ptr());
    // SAFETY: as above.
    let picture: vk::native::StdVideoDecodeH264PictureInfo = unsafe { std::mem::zeroed() };
    // SAFETY: a picture info holds no pointer.
    let info = unsafe { tuff::VideoDecodeH264PictureInfoKHR::new().std_picture_info(&picture) };
    assert_eq!(info.p_std_picture_info, &picture as *const _);
}

#[test]
fn a_selected_union_is_set_with_the_member_that_selects_it() {
    let address = tuff::DescriptorAddressInfoEXT::new()
        .address(0x1000)
        .range(64);
    let info =
        tuff::DescriptorGetInfoEXT::new(tuff::DescriptorDataEXT::UniformBuffer(Some(&address)));
    assert_eq!(info.ty, vk::DescriptorType::UNIFORM_BUFFER);
    // SAFETY: `ty` says the union holds `p_uniform_buffer`.
    let held = unsafe { info.data.p_uniform_buffer };
    assert_eq!(
        held,
        (&address as *const tuff::DescriptorAddressInfoEXT).cast()
    );
    // Another variant moves the selector with it.
    let info = info.data(tuff::DescriptorDataEXT::AccelerationStructureKHR(0xabc0));
    assert_eq!(info.ty, vk::DescriptorType::ACCELERATION_STRUCTURE_KHR);
    // SAFETY: `ty` says the union holds `acceleration_structure`.
    assert_eq!(unsafe { info.data.acceleration_structure }, 0xabc0);
    // A union of structs held by value.
    let aabbs = tuff::AccelerationStructureGeometryAabbsDataKHR::new().stride(24);
    let geometry = tuff::AccelerationStructureGeometryKHR::new(
        tuff::AccelerationStructureGeometryDataKHR::Aabbs(aabbs),
    );
    assert_eq!(geometry.geometry_type, vk::GeometryTypeKHR::AABBS);
    // SAFETY: `geometry_type` says the union holds `aabbs`.
    let held = unsafe { geometry.geometry.aabbs };
    assert_eq!(
        held.s_type,
        vk::StructureType::ACCELERATION_STRUCTURE_GEOMETRY_AABBS_DATA_KHR
    );
    assert_eq!(held.stride, 24);
}

#[test]
fn a_length_of_constants_is_an_array_of_that_size() {
    // `2*VK_UUID_SIZE` bytes: the type takes exactly that many, no fewer.
    let data = [7u8; 2 * vk::UUID_SIZE];
    let info = tuff::AccelerationStructureVersionInfoKHR::new().version_data(&data);
    assert_eq!(info.p_version_data.cast::<u8>(), data.as_ptr());
}

/// One frame into a swapchain: acquire, clear the image, present.
fn present_one_frame(
    s: &Setup,
    swapchain: &tuff::SwapchainKHR,
    pool: &tuff::CommandPool,
) -> Vec<Box<dyn Any>> {
    let d = &s.device;
    let images = d
        .get_swapchain_images_khr(swapchain)
        .expect("swapchain images");
    assert!(!images.is_empty());
    let acquired = d
        .create_semaphore(&tuff::SemaphoreCreateInfo::new())
        .expect("semaphore");
    let rendered = d
        .create_semaphore(&tuff::SemaphoreCreateInfo::new())
        .expect("semaphore");
    let (index, r) = d
        .acquire_next_image_khr(swapchain, u64::MAX, Some(&acquired), None)
        .expect("acquire");
    assert!(
        r == tuff::SuccessTimeoutNotReadyOrSuboptimal::Success
            || r == tuff::SuccessTimeoutNotReadyOrSuboptimal::Suboptimal,
        "{r:?}"
    );
    let image = &images[index as usize];
    let mut cb = d
        .allocate_command_buffers(
            pool,
            &tuff::CommandBufferAllocateInfo::new(pool).command_buffer_count(1),
        )
        .expect("command buffer")
        .pop()
        .expect("one");
    let range = vk::ImageSubresourceRange {
        aspect_mask: vk::ImageAspectFlags::COLOR,
        base_mip_level: 0,
        level_count: 1,
        base_array_layer: 0,
        layer_count: 1,
    };
    let barrier = |old, new, src_access, dst_access| {
        tuff::ImageMemoryBarrier::new(image)
            .old_layout(old)
            .new_layout(new)
            .src_access_mask(src_access)
            .dst_access_mask(dst_access)
            .src_queue_family_index(vk::QUEUE_FAMILY_IGNORED)
            .dst_queue_family_index(vk::QUEUE_FAMILY_IGNORED)
            .subresource_range(range)
    };
    let mut rec = cb
        .begin(&tuff::CommandBufferBeginInfo::new())
        .expect("begin");
    rec.pipeline_barrier(
        vk::PipelineStageFlags::TRANSFER,
        vk::PipelineStageFlags::TRANSFER,
        vk::DependencyFlags::empty(),
        &[],
        &[],
        &[barrier(
            vk::ImageLayout::UNDEFINED,
            vk::ImageLayout::TRANSFER_DST_OPTIMAL,
            vk::AccessFlags::empty(),
            vk::AccessFlags::TRANSFER_WRITE,
        )],
    )
    .expect("recorded");
    rec.clear_color_image(
        image,
        vk::ImageLayout::TRANSFER_DST_OPTIMAL,
        &vk::ClearColorValue {
            float32: [0.1, 0.2, 0.3, 1.0],
        },
        &[range],
    )
    .expect("recorded");
    rec.pipeline_barrier(
        vk::PipelineStageFlags::TRANSFER,
        vk::PipelineStageFlags::BOTTOM_OF_PIPE,
        vk::DependencyFlags::empty(),
        &[],
        &[],
        &[barrier(
            vk::ImageLayout::TRANSFER_DST_OPTIMAL,
            vk::ImageLayout::PRESENT_SRC_KHR,
            vk::AccessFlags::TRANSFER_WRITE,
            vk::AccessFlags::empty(),
        )],
    )
    .expect("recorded");
    rec.end().expect("end");
    let fence = d
        .create_fence(&tuff::FenceCreateInfo::new())
        .expect("fence");
    let stages = [vk::PipelineStageFlags::TRANSFER];
    s.queue
        .submit(
            &[tuff::SubmitInfo::new()
                .wait_semaphores(&acquired, &stages)
                .expect("one stage per semaphore")
                .command_buffers(&cb)
                .signal_semaphores(&rendered)],
            Some(&fence),
        )
        .expect("submit");
    let swapchains = tuff::HandleSlice::new(&[swapchain]);
    let indices = [index];
    let r = s
        .queue
        .present_khr(
            &tuff::PresentInfoKHR::new()
                .wait_semaphores(&rendered)
                .swapchains(&swapchains, &indices)
                .expect("one index per swapchain"),
        )
        .expect("present");
    assert!(
        r == tuff::SuccessOrSuboptimal::Success || r == tuff::SuccessOrSuboptimal::Suboptimal,
        "{r:?}"
    );
    // Presentation has no fence here: the queue going idle covers it.
    s.queue.wait_idle().expect("wait idle");
    let mut out: Vec<Box<dyn Any>> = vec![
        Box::new(acquired),
        Box::new(rendered),
        Box::new(cb),
        Box::new(fence),
    ];
    out.extend(images.into_iter().map(|i| Box::new(i) as Box<dyn Any>));
    out
}

/// An Xlib surface for `window`.
fn xlib_surface(s: &Setup, window: &x11_window::X11Window) -> tuff::SurfaceKHR {
    // SAFETY: callers drop `window` after every object made from the surface.
    unsafe {
        s.instance.create_xlib_surface_khr(
            &tuff::XlibSurfaceCreateInfoKHR::new()
                .dpy(window.display.cast())
                .window(window.window),
        )
    }
    .expect("xlib surface")
}

#[test]
fn surfaces_and_swapchains_in_random_drop_orders() {
    let _serial = vulkan::serial();
    for seed in 0..4u64 {
        let window = tuff::runtime::Vrc::new(x11_window::X11Window::open(64, 48));
        let s = setup_with(true, Wsi::Xlib);
        // The surface keeps the window alive: it goes into the bag with the rest.
        let surface = s.instance.create_surface(window.clone()).expect("surface");
        let supported = s
            .physical
            .get_surface_support_khr(s.family, &surface)
            .expect("surface support");
        assert!(supported, "the graphics queue family presents to X11");
        let pool = s
            .device
            .create_command_pool(&tuff::CommandPoolCreateInfo::new().queue_family_index(s.family))
            .expect("pool");
        let first = s
            .device
            .create_swapchain_khr(&surface, &swapchain_info(&s, &surface))
            .expect("swapchain");
        assert!(first.presents_to(&surface));
        let mut bag = present_one_frame(&s, &first, &pool);
        // The recreate path after a resize: the new swapchain retires the old one, and
        // both keep the surface alive.
        window.resize(80, 40);
        let second = first
            .recreate(&s.device, &surface, &swapchain_info(&s, &surface))
            .expect("recreate");
        bag.extend(present_one_frame(&s, &second, &pool));
        bag.push(Box::new(first));
        bag.push(Box::new(second));
        bag.push(Box::new(surface));
        bag.push(Box::new(pool));
        let Setup {
            queue,
            physical,
            device,
            messenger,
            instance,
            messages,
            ..
        } = s;
        bag.push(Box::new(queue));
        bag.push(Box::new(physical));
        bag.push(Box::new(device));
        bag.push(Box::new(instance));
        bag.push(Box::new(window));
        shuffle(&mut bag, seed);
        while let Some(item) = bag.pop() {
            drop(item);
        }
        drop(messenger);
        assert_silent(&messages);
    }
}

/// A window whose handles are of a window system no surface extension of this
/// build serves.
struct WebWindow;

impl raw_window_handle::HasWindowHandle for WebWindow {
    fn window_handle(
        &self,
    ) -> Result<raw_window_handle::WindowHandle<'_>, raw_window_handle::HandleError> {
        let raw = raw_window_handle::WebWindowHandle::new(1);
        // SAFETY: a web handle holds an ID, no pointer.
        Ok(unsafe { raw_window_handle::WindowHandle::borrow_raw(raw.into()) })
    }
}

impl raw_window_handle::HasDisplayHandle for WebWindow {
    fn display_handle(
        &self,
    ) -> Result<raw_window_handle::DisplayHandle<'_>, raw_window_handle::HandleError> {
        Ok(raw_window_handle::DisplayHandle::web())
    }
}

/// `create_surface` keeps the window alive as long as the surface, refuses a
/// window of another window system, and an instance without the extension.
#[test]
fn surfaces_keep_their_windows() {
    let _serial = vulkan::serial();
    let window = tuff::runtime::Vrc::new(x11_window::X11Window::open(32, 32));
    let s = setup_with(true, Wsi::Xlib);
    let surface = s.instance.create_surface(window.clone()).expect("surface");
    assert_eq!(tuff::runtime::Vrc::strong_count(&window), 2);
    let supported = s
        .physical
        .get_surface_support_khr(s.family, &surface)
        .expect("surface support");
    assert!(supported);
    drop(surface);
    assert_eq!(tuff::runtime::Vrc::strong_count(&window), 1);
    match s
        .instance
        .create_surface(tuff::runtime::Vrc::new(WebWindow))
    {
        Err(tuff::Error::Window(message)) => assert!(message.contains("Web"), "{message}"),
        Err(e) => panic!("expected a window error, got {e}"),
        Ok(_) => panic!("a surface was made for a web canvas"),
    }
    assert_silent(&s.messages);
    let headless = setup_with(true, Wsi::None);
    match headless.instance.create_surface(window.clone()) {
        Err(tuff::Error::ExtensionNotEnabled(name)) => assert_eq!(name, "VK_KHR_xlib_surface"),
        Err(e) => panic!("expected the extension to be missing, got {e}"),
        Ok(_) => panic!("a surface was made without VK_KHR_xlib_surface"),
    }
    assert_eq!(tuff::runtime::Vrc::strong_count(&window), 1);
    assert_silent(&headless.messages);
}

/// A command that takes a window system's display connection takes it as a
/// `raw_window_handle::DisplayHandle` and is safe; the driver gets the window's own
/// connection and answers as it does through ash.
#[test]
fn a_display_connection_reaches_the_driver_unchanged() {
    use raw_window_handle::HasDisplayHandle;
    let _serial = vulkan::serial();
    let window = x11_window::X11Window::open(16, 16);
    let s = setup_with(true, Wsi::Xlib);
    // X resource IDs fit in 29 bits; ash's VisualID is 32.
    let visual = vk::VisualID::try_from(window.visual_id()).expect("a 32-bit visual ID");
    let display = window.display_handle().expect("display handle");
    let supported = s
        .physical
        .get_xlib_presentation_support_khr(s.family, display, visual)
        .expect("the extension is enabled");
    let loader = ash::khr::xlib_surface::Instance::new(s.instance.entry().fns(), s.instance.fns());
    // SAFETY: a live display connection and a visual of its default screen.
    let through_ash = unsafe {
        loader.get_physical_device_xlib_presentation_support(
            tuff::Handle::raw(&s.physical),
            s.family,
            window.display.cast(),
            visual,
        )
    };
    assert_eq!(supported, through_ash);
    // lavapipe presents to X11 from its one queue family.
    assert!(through_ash);
    // Without the extension the table is missing, and the call says so.
    let headless = setup(true);
    let missing =
        headless
            .physical
            .get_xlib_presentation_support_khr(headless.family, display, visual);
    assert!(matches!(
        missing,
        Err(tuff::Error::ExtensionNotEnabled("VK_KHR_xlib_surface"))
    ));
    assert_silent(&s.messages);
    assert_silent(&headless.messages);
}

#[test]
fn recreate_refuses_another_surface() {
    let _serial = vulkan::serial();
    let window_a = x11_window::X11Window::open(32, 32);
    let window_b = x11_window::X11Window::open(32, 32);
    let s = setup_with(true, Wsi::Xlib);
    // Both windows outlive every object made from their surfaces.
    let (a, b) = (xlib_surface(&s, &window_a), xlib_surface(&s, &window_b));
    let swapchain = s
        .device
        .create_swapchain_khr(&a, &swapchain_info(&s, &a))
        .expect("swapchain");
    assert!(!swapchain.presents_to(&b));
    match swapchain.recreate(&s.device, &b, &swapchain_info(&s, &b)) {
        Err(tuff::Error::Validation { vuid, .. }) => {
            assert_eq!(vuid, "VUID-VkSwapchainCreateInfoKHR-oldSwapchain-01933")
        }
        Err(e) => panic!("expected the oldSwapchain rule, got {e}"),
        Ok(_) => panic!("a swapchain of one window was recreated for another"),
    }
    drop(swapchain);
    drop((a, b));
    assert_silent(&s.messages);
}

#[test]
fn pipelines_draw_and_dispatch() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let d = &s.device;
    let target = s.color_target(8, vk::ImageUsageFlags::TRANSFER_SRC);
    let work = pipelines(&s, &target);
    let readback = host_buffer(&s, 16, vk::BufferUsageFlags::TRANSFER_DST);
    let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let rec = cb
        .begin(&tuff::CommandBufferBeginInfo::new())
        .expect("begin");
    work.record(rec, &target, 8, Some(&readback.0))
        .end()
        .expect("end");
    let fence = d
        .create_fence(&tuff::FenceCreateInfo::new())
        .expect("fence");
    s.queue
        .submit(
            &[tuff::SubmitInfo::new().command_buffers(&cb)],
            Some(&fence),
        )
        .expect("submit");
    let status = d.wait_for_fences(&fence, true, u64::MAX).expect("wait");
    assert_eq!(status, tuff::SuccessOrTimeout::Success);
    let pixel = access_memory(&s, &readback.1, 4, None);
    let expected: Vec<u8> = COLOR.iter().map(|c| (c * 255.0).round() as u8).collect();
    for (got, want) in pixel.iter().zip(&expected) {
        assert!(
            got.abs_diff(*want) <= 1,
            "drawn pixel {pixel:?}, expected {expected:?}"
        );
    }
    let out = access_memory(&s, &work.output.1, (INVOCATIONS * 4) as usize, None);
    for (i, word) in out.chunks_exact(4).enumerate() {
        let v = u32::from_le_bytes([word[0], word[1], word[2], word[3]]);
        assert_eq!(v, i as u32 * FACTOR, "invocation {i} of the dispatch");
    }
    assert_silent(&s.messages);
}

#[test]
fn mapped_memory_is_checked_and_unmapped_on_drop() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let (_buffer, memory) = host_buffer(&s, 64, vk::BufferUsageFlags::TRANSFER_DST);
    {
        let mut mapped = memory.map().expect("map");
        assert!(mapped.size() >= 64);
        mapped.write(8, &[1u32, 2, 3]).expect("write");
        assert_eq!(mapped.read::<u32>(8, 3).expect("read"), [1, 2, 3]);
        // A second mapping while one lives breaks VUID-vkMapMemory-memory-00678.
        match memory.clone().map() {
            Err(tuff::Error::Validation { vuid, .. }) => {
                assert_eq!(vuid, "VUID-vkMapMemory-memory-00678")
            }
            other => panic!("expected a refusal, got {:?}", other.map(|m| m.size())),
        }
        let size = mapped.size();
        assert!(matches!(
            mapped.write(size - 4, &[0u64]),
            Err(tuff::Error::Map(tuff::runtime::MapError::OutOfRange { .. }))
        ));
        assert!(matches!(
            mapped.read::<u8>(size, 1),
            Err(tuff::Error::Map(_))
        ));
    }
    // The guard unmapped the memory, so it maps again and kept what was written.
    let again = memory.map().expect("map again");
    assert_eq!(again.read::<u32>(8, 3).expect("read"), [1, 2, 3]);
    drop(again);
    assert_silent(&s.messages);
}

/// Records `fill` into a one-time command buffer, submits it and waits; `fill` may
/// return resources, which are dropped before the wait to check that the submission
/// keeps them alive.
fn submit_and_wait<K>(s: &Setup, fill: impl FnOnce(&mut tuff::Recorder<'_, tuff::Outside>) -> K) {
    let d = &s.device;
    let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let mut rec = cb
        .begin(&tuff::CommandBufferBeginInfo::new())
        .expect("begin");
    let kept = fill(&mut rec);
    rec.end().expect("end");
    assert!(cb.is_executable());
    let fence = d
        .create_fence(&tuff::FenceCreateInfo::new())
        .expect("fence");
    s.queue
        .submit(
            &[tuff::SubmitInfo::new().command_buffers(&cb)],
            Some(&fence),
        )
        .expect("submit");
    drop(kept);
    let status = d.wait_for_fences(&fence, true, u64::MAX).expect("wait");
    assert_eq!(status, tuff::SuccessOrTimeout::Success);
}

#[test]
fn allocated_buffers_are_bound_written_and_kept_while_in_flight() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let d = &s.device;
    let gpu = d.gpu_allocator().expect("gpu allocator");
    let naive = d.naive_allocator();
    let allocators: [(&str, &dyn tuff::runtime::Allocator); 2] = [("gpu", &gpu), ("naive", &naive)];
    for (name, allocator) in allocators {
        let info = |usage| tuff::BufferCreateInfo::new().size(256).usage(usage);
        let source = d
            .create_buffer_in(
                &info(vk::BufferUsageFlags::TRANSFER_SRC),
                allocator,
                tuff::MemoryLocation::Upload,
            )
            .expect("source");
        let target = d
            .create_buffer_in(
                &info(vk::BufferUsageFlags::TRANSFER_DST),
                allocator,
                tuff::MemoryLocation::Readback,
            )
            .expect("target");
        assert!(source.memory().size() >= 256, "{name}");
        let words: Vec<u32> = (0..64).map(|i| i * 3 + 1).collect();
        source.memory().write(0, &words).expect("write");
        source.memory().write_value(252, &7u32).expect("write one");
        assert!(matches!(
            source.memory().write(source.memory().size(), &[1u8]),
            Err(tuff::Error::Map(_))
        ));
        // A run of writes under one lock: the same checks, the same bytes.
        let doubled: Vec<u32> = words[32..63].iter().map(|w| w * 2).collect();
        let size = source.memory().size();
        {
            let mut held = source.memory().lock();
            held.write(128, &doubled).expect("write under the lock");
            assert_eq!(held.read::<u32>(128, 31).expect("read back"), doubled);
            assert!(matches!(
                held.write_value(size, &1u8),
                Err(tuff::Error::Map(_))
            ));
        }
        // The copy's source goes, memory and all, while the copy may still run: the
        // submission keeps it (the layer would report memory freed in use).
        submit_and_wait(&s, |rec| {
            rec.copy_buffer(
                &source,
                &target,
                &[vk::BufferCopy {
                    src_offset: 0,
                    dst_offset: 0,
                    size: 256,
                }],
            )
            .expect("copy");
            source
        });
        let mut expected = words.clone();
        expected[32..63].copy_from_slice(&doubled);
        expected[63] = 7;
        assert_eq!(
            target.memory().read::<u32>(0, 64).expect("read"),
            expected,
            "{name}"
        );
    }
    // A buffer made and filled in one call; empty data still makes a valid buffer.
    let usage = vk::BufferUsageFlags::INDEX_BUFFER;
    let filled = d
        .create_buffer_with(usage, &[5u16, 6, 7], &gpu)
        .expect("filled buffer");
    assert_eq!(filled.memory().read::<u16>(0, 3).expect("read"), [5, 6, 7]);
    let empty: [u32; 0] = [];
    let empty = d
        .create_buffer_with(usage, &empty, &naive)
        .expect("empty buffer");
    assert!(empty.memory().size() >= 1);
    // An image in device-local memory, and the refusals.
    let image = d
        .create_image_in(
            &tuff::ImageCreateInfo::new()
                .image_type(vk::ImageType::TYPE_2D)
                .format(vk::Format::D32_SFLOAT)
                .extent(vk::Extent3D {
                    width: 64,
                    height: 64,
                    depth: 1,
                })
                .mip_levels(1)
                .array_layers(1)
                .samples(vk::SampleCountFlags::TYPE_1)
                .usage(vk::ImageUsageFlags::DEPTH_STENCIL_ATTACHMENT),
            &gpu,
            tuff::MemoryLocation::DeviceLocal,
        )
        .expect("image");
    assert!(image.memory().size() >= 64 * 64 * 4);
    let refusal = |info: tuff::BufferCreateInfo<'_>| match d.create_buffer_in(
        &info.size(64),
        &gpu,
        tuff::MemoryLocation::Upload,
    ) {
        Err(tuff::Error::Validation { vuid, .. }) => vuid,
        Err(other) => panic!("expected a refusal, got {other}"),
        Ok(_) => panic!("expected a refusal, got a buffer"),
    };
    assert_eq!(
        refusal(
            tuff::BufferCreateInfo::new()
                .flags(vk::BufferCreateFlags::SPARSE_BINDING)
                .usage(vk::BufferUsageFlags::TRANSFER_DST)
        ),
        "VUID-vkBindBufferMemory-buffer-01030"
    );
    assert_eq!(
        refusal(tuff::BufferCreateInfo::new().usage(
            vk::BufferUsageFlags::STORAGE_BUFFER | vk::BufferUsageFlags::SHADER_DEVICE_ADDRESS
        )),
        "VUID-vkBindBufferMemory-bufferDeviceAddress-03339"
    );
    drop(image);
    assert_silent(&s.messages);
}

#[test]
fn an_allocator_of_another_device_is_refused() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let priorities = [1.0f32];
    let queues = [tuff::DeviceQueueCreateInfo::new()
        .queue_family_index(s.family)
        .queue_priorities(&priorities)];
    let other = s
        .physical
        .create_device(&tuff::DeviceCreateInfo::new().queue_create_infos(&queues))
        .expect("second device");
    let foreign = other.naive_allocator();
    let info = tuff::BufferCreateInfo::new()
        .size(64)
        .usage(vk::BufferUsageFlags::UNIFORM_BUFFER);
    match s
        .device
        .create_buffer_in(&info, &foreign, tuff::MemoryLocation::Upload)
    {
        Err(tuff::Error::Validation { vuid, .. }) => {
            assert_eq!(vuid, "VUID-vkBindBufferMemory-memory-parent")
        }
        Err(other) => panic!("expected a refusal, got {other}"),
        Ok(_) => panic!("memory of another device was bound"),
    }
    drop((foreign, other));
    assert_silent(&s.messages);
}

#[test]
fn missing_layers_extensions_and_features_are_named() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let entry = tuff::Entry::load().expect("loader");
    // Through `_unchecked`: the checked constructors refuse an extension outside the
    // emitted API before the driver can say it is absent (tested below).
    // SAFETY: the layers and extensions are absent or only the layer's own, so the
    // instance is never created and no rule of an unemitted extension can apply.
    let create = |layers: &[tuff::CStrPtr<'_>], exts: &[tuff::CStrPtr<'_>]| {
        unsafe {
            entry.create_instance_unchecked(
                &tuff::InstanceCreateInfo::new()
                    .enabled_layer_names(layers)
                    .enabled_extension_names(exts),
            )
        }
        .expect_err("the instance was created")
    };
    let not_present = |e: tuff::Error| match e {
        tuff::Error::NotPresent { what, names, .. } => (what, names),
        other => panic!("expected NotPresent, got {other}"),
    };
    assert_eq!(
        not_present(create(&[c"VK_LAYER_TUFF_absent".into()], &[])),
        ("instance layer", vec!["VK_LAYER_TUFF_absent".to_owned()])
    );
    // The validation layer's own extensions count as present when it is enabled.
    let e = create(
        &[c"VK_LAYER_KHRONOS_validation".into()],
        &[
            c"VK_EXT_validation_features".into(),
            c"VK_TUFF_absent".into(),
        ],
    );
    assert_eq!(
        e.to_string(),
        "instance extension not present: VK_TUFF_absent (ERROR_EXTENSION_NOT_PRESENT)"
    );
    // The first core feature this device lacks (lavapipe lacks several), asked for
    // on a device without the layer, which would rightly complain.
    let have = s.physical.get_features();
    let probe = tuff::vk::PhysicalDeviceFeatures {
        sparse_binding: have.sparse_binding ^ vk::TRUE,
        ..Default::default()
    };
    assert_eq!(
        have.sparse_binding,
        vk::FALSE,
        "the test asks for sparseBinding, which this device must lack"
    );
    let priorities = [1.0f32];
    let queues = [tuff::DeviceQueueCreateInfo::new()
        .queue_family_index(s.family)
        .queue_priorities(&priorities)];
    let bare = entry
        .create_instance(&tuff::InstanceCreateInfo::new())
        .expect("instance without layers");
    let physical = bare
        .enumerate_physical_devices()
        .expect("devices")
        .into_iter()
        .find(|p| p.get_properties().device_name == s.physical.get_properties().device_name)
        .expect("the same device on the second instance");
    let e = physical
        .create_device(
            &tuff::DeviceCreateInfo::new()
                .queue_create_infos(&queues)
                .enabled_features(Some(&probe)),
        )
        .expect_err("a device with a missing feature");
    assert_eq!(
        not_present(e),
        ("device feature", vec!["sparseBinding".to_owned()])
    );
    // SAFETY: the extension is absent, so the device is never created.
    let e = unsafe {
        physical.create_device_unchecked(
            &tuff::DeviceCreateInfo::new()
                .queue_create_infos(&queues)
                .enabled_extension_names(&[c"VK_TUFF_absent".into()]),
        )
    }
    .expect_err("a device with a missing extension");
    assert_eq!(
        not_present(e),
        ("device extension", vec!["VK_TUFF_absent".to_owned()])
    );
    assert_silent(&s.messages);
}

/// An extension outside the emitted API would add rules that no safe method checks,
/// and so would an emitted one that brings unchecked rules to methods outside it: the
/// checked constructors refuse both, present or not, before the driver sees them.
#[test]
fn extensions_outside_the_emitted_api_are_refused() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let entry = tuff::Entry::load().expect("loader");
    let not_emitted = |e: tuff::Error| match e {
        tuff::Error::ExtensionNotEmitted(name) => name,
        other => panic!("expected ExtensionNotEmitted, got {other}"),
    };
    let unchecked = |e: tuff::Error| match e {
        tuff::Error::ExtensionUnchecked(name) => name,
        other => panic!("expected ExtensionUnchecked, got {other}"),
    };
    let instance_with = |name: &'static std::ffi::CStr| {
        entry
            .create_instance(
                &tuff::InstanceCreateInfo::new()
                    .enabled_layer_names(&[c"VK_LAYER_KHRONOS_validation".into()])
                    .enabled_extension_names(&[c"VK_EXT_debug_utils".into(), name.into()]),
            )
            .expect_err("an instance with a refused extension")
    };
    // Present (the layer provides it) and emitted, but its rules reach methods whose
    // checks do not enforce them.
    assert_eq!(
        unchecked(instance_with(c"VK_EXT_validation_features")),
        "VK_EXT_validation_features"
    );
    assert_eq!(
        not_emitted(instance_with(c"VK_TUFF_absent")),
        "VK_TUFF_absent"
    );
    let priorities = [1.0f32];
    let queues = [tuff::DeviceQueueCreateInfo::new()
        .queue_family_index(s.family)
        .queue_priorities(&priorities)];
    // One the generator leaves out (ash's registry defines it otherwise), and one no
    // registry has.
    for name in [c"VK_KHR_video_encode_queue", c"VK_TUFF_absent"] {
        let e = s
            .physical
            .create_device(
                &tuff::DeviceCreateInfo::new()
                    .queue_create_infos(&queues)
                    .enabled_extension_names(&[c"VK_KHR_swapchain".into(), name.into()]),
            )
            .expect_err("a device with an unemitted extension");
        assert_eq!(not_emitted(e), name.to_str().expect("ASCII"));
    }
    assert_silent(&s.messages);
}

#[test]
fn the_message_log_hears_the_layer_and_outlives_nothing() {
    let _serial = vulkan::serial();
    let s = setup(true);
    // A buffer of size 0 breaks VUID-VkBufferCreateInfo-size-00912; the unchecked
    // entry point lets it reach the layer.
    let info = tuff::BufferCreateInfo::new()
        .size(0)
        .usage(vk::BufferUsageFlags::UNIFORM_BUFFER);
    // SAFETY: deliberately not: the rule is broken for the layer to report, and the
    // buffer is never used (lavapipe tolerates the empty buffer).
    let bad = unsafe { s.device.create_buffer_unchecked(&info) };
    drop(bad);
    let heard = s.messages.take();
    assert!(
        heard
            .iter()
            .any(|m| m.contains("VUID-VkBufferCreateInfo-size-00912")),
        "the log missed the layer's message: {heard:?}"
    );
    assert!(s.messages.is_empty(), "take leaves the log empty");
    // A messenger that outlives its log drops what it hears instead of writing
    // through a dangling pointer.
    let log = tuff::MessageLog::new();
    let messenger = s
        .instance
        .create_debug_utils_messenger_ext(&log.messenger_info())
        .expect("messenger");
    drop(log);
    // SAFETY: as above, a deliberate break for the layer to report.
    drop(unsafe { s.device.create_buffer_unchecked(&info) });
    drop(messenger);
    assert!(
        s.messages.take().iter().any(|m| m.contains("00912")),
        "the setup's own log still hears the layer"
    );
    assert_silent(&s.messages);
}

#[test]
fn frames_in_flight_take_turns_and_keep_their_semaphores() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let d = &s.device;
    let gpu = d.gpu_allocator().expect("gpu allocator");
    let mut frames = d.frames_in_flight(s.family, 3).expect("frames in flight");
    assert_eq!(frames.len(), 3);
    let targets: Vec<_> = (0..3)
        .map(|_| {
            let info = tuff::BufferCreateInfo::new()
                .size(64)
                .usage(vk::BufferUsageFlags::TRANSFER_DST);
            d.create_buffer_in(&info, &gpu, tuff::MemoryLocation::Readback)
                .expect("target")
        })
        .collect();
    let first = |t: &tuff::Bound<tuff::Buffer>| t.memory().read::<u32>(0, 1).expect("read")[0];
    let record = |frame: &mut tuff::Frame<'_>, n: u32| {
        let target = &targets[frame.index];
        let mut rec = frame.record().expect("record");
        rec.fill_buffer(target, 0, vk::WHOLE_SIZE, n).expect("fill");
        let to_host = [tuff::BufferMemoryBarrier::new(target)
            .src_access_mask(vk::AccessFlags::TRANSFER_WRITE)
            .dst_access_mask(vk::AccessFlags::HOST_READ)
            .src_queue_family_index(vk::QUEUE_FAMILY_IGNORED)
            .dst_queue_family_index(vk::QUEUE_FAMILY_IGNORED)
            .size(vk::WHOLE_SIZE)];
        rec.pipeline_barrier(
            vk::PipelineStageFlags::TRANSFER,
            vk::PipelineStageFlags::HOST,
            vk::DependencyFlags::empty(),
            &[],
            &to_host,
            &[],
        )
        .expect("recorded");
        rec.end().expect("end");
    };
    let mut order = Vec::new();
    let mut previous: Option<tuff::Semaphore> = None;
    for n in 0..7u32 {
        let mut frame = frames.next_frame().expect("next frame");
        order.push(frame.index);
        // The frame's last submission is complete, so what it wrote is there.
        if n >= 3 {
            assert_eq!(first(&targets[frame.index]), n - 3, "frame {n}");
        }
        record(&mut frame, n);
        // A chain of semaphores, each dropped once the next submission waits on it,
        // while that submission may still run: the frame's fence keeps it (the layer
        // would report a semaphore destroyed in use).
        let signal = d
            .create_semaphore(&tuff::SemaphoreCreateInfo::new())
            .expect("semaphore");
        let waits: Vec<_> = previous
            .iter()
            .map(|p| (p, vk::PipelineStageFlags::TRANSFER))
            .collect();
        frame.submit(&s.queue, &waits, &[&signal]).expect("submit");
        previous = Some(signal);
    }
    assert_eq!(order, [0, 1, 2, 0, 1, 2, 0]);
    // A frame submitted without a new recording is refused, and the ring stays on it.
    let frame = frames.next_frame().expect("next frame");
    assert_eq!(frame.index, 1);
    let refused = frame.submit(&s.queue, &[], &[]);
    assert!(
        matches!(refused, Err(tuff::Error::Validation { vuid, .. })
            if vuid == "VUID-vkQueueSubmit-pCommandBuffers-00070"),
        "{refused:?}"
    );
    let mut frame = frames.next_frame().expect("the same frame again");
    assert_eq!(frame.index, 1);
    record(&mut frame, 7);
    let waits = [(
        previous.as_ref().expect("a semaphore"),
        vk::PipelineStageFlags::TRANSFER,
    )];
    frame.submit(&s.queue, &waits, &[]).expect("submit");
    drop(previous);
    frames.wait_all().expect("wait for all frames");
    let last: Vec<u32> = targets.iter().map(first).collect();
    assert_eq!(last, [6, 7, 5]);
    assert_eq!(frames.next_frame().expect("next frame").index, 2);
    assert_silent(&s.messages);
}

#[test]
fn shader_modules_come_from_spirv_bytes_in_either_byte_order() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let bytes = include_bytes!("../shaders/spv/test.vert.spv");
    tuff_setup::shader(&s, bytes);
    let swapped: Vec<u8> = bytes
        .chunks_exact(4)
        .flat_map(|w| [w[3], w[2], w[1], w[0]])
        .collect();
    assert_eq!(
        tuff::spirv_words(&swapped).expect("big-endian words"),
        tuff::spirv_words(bytes).expect("little-endian words")
    );
    tuff_setup::shader(&s, &swapped);
    // SAFETY: each of these is refused before Vulkan sees it (the test asserts so),
    // so no code is made for the shader promise to cover.
    let refused = |bytes: &[u8]| match unsafe { s.device.create_shader_module_from_spirv(bytes) } {
        Err(tuff::Error::Validation { vuid, .. }) => vuid,
        other => panic!("not refused: {:?}", other.map(|_| ())),
    };
    assert_eq!(refused(&[]), "VUID-VkShaderModuleCreateInfo-codeSize-01085");
    assert_eq!(
        refused(&bytes[..bytes.len() - 1]),
        "VUID-VkShaderModuleCreateInfo-codeSize-01086"
    );
    assert_eq!(
        refused(b"#version 450\nvoid main() {}\n"),
        "VUID-VkShaderModuleCreateInfo-pCode-01087"
    );
    assert_silent(&s.messages);
}

#[test]
fn physical_devices_name_themselves_and_find_queue_families() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let raw = s.physical.get_properties();
    let expected = raw
        .device_name_as_c_str()
        .expect("a NUL-terminated name")
        .to_str()
        .expect("UTF-8");
    assert_eq!(s.physical.name(), expected);
    assert!(!expected.is_empty());
    let families = s.physical.get_queue_family_properties().expect("families");
    for flags in [
        vk::QueueFlags::GRAPHICS,
        vk::QueueFlags::COMPUTE | vk::QueueFlags::TRANSFER,
        vk::QueueFlags::SPARSE_BINDING,
        vk::QueueFlags::PROTECTED,
    ] {
        let scanned = families
            .iter()
            .position(|f| f.queue_flags.contains(flags))
            .map(|i| i as u32);
        assert_eq!(
            s.physical.queue_family_index(flags).expect("query"),
            scanned,
            "{flags:?}"
        );
    }
    assert_eq!(
        s.physical
            .queue_family_index(vk::QueueFlags::GRAPHICS)
            .expect("query"),
        Some(s.family)
    );
    assert_silent(&s.messages);
}

/// Acquire and present take binary semaphores: a timeline semaphore is refused by
/// both, and the layer names the same rules for the unchecked calls.
#[test]
fn acquire_and_present_take_binary_semaphores() {
    let _serial = vulkan::serial();
    let s = setup_with(true, Wsi::Xlib);
    let window = x11_window::X11Window::open(32, 32);
    let surface = xlib_surface(&s, &window);
    let swapchain = s
        .device
        .create_swapchain_khr(&surface, &swapchain_info(&s, &surface))
        .expect("swapchain");
    let mut timeline_type = tuff::SemaphoreTypeCreateInfo::new()
        .semaphore_type(vk::SemaphoreType::TIMELINE)
        .initial_value(0);
    let timeline = s
        .device
        .create_semaphore(&tuff::SemaphoreCreateInfo::new().push_next(&mut timeline_type))
        .expect("timeline semaphore");
    let acquire = "VUID-vkAcquireNextImageKHR-semaphore-03265";
    let r = s
        .device
        .acquire_next_image_khr(&swapchain, u64::MAX, Some(&timeline), None);
    assert_eq!(refused(r), acquire);
    layer_names(&s, acquire, || {
        // SAFETY: the layer names the rule and skips the call.
        let _ = unsafe {
            s.device
                .acquire_next_image_khr_unchecked(&swapchain, u64::MAX, Some(&timeline), None)
        };
    });
    // An image acquired with a fence, presented after a wait on the timeline
    // semaphore.
    let fence = s
        .device
        .create_fence(&tuff::FenceCreateInfo::new())
        .expect("fence");
    let (index, _) = s
        .device
        .acquire_next_image_khr(&swapchain, u64::MAX, None, Some(&fence))
        .expect("acquire");
    assert_eq!(
        s.device
            .wait_for_fences(&fence, true, u64::MAX)
            .expect("acquired"),
        tuff::SuccessOrTimeout::Success
    );
    let swapchains = tuff::HandleSlice::new(&[&swapchain]);
    let indices = [index];
    let present = tuff::PresentInfoKHR::new()
        .wait_semaphores(&timeline)
        .swapchains(&swapchains, &indices)
        .expect("one index per swapchain");
    let binary = "VUID-vkQueuePresentKHR-pWaitSemaphores-03267";
    assert_eq!(refused(s.queue.present_khr(&present)), binary);
    layer_names(&s, binary, || {
        // SAFETY: the layer names the rule and skips the call.
        let _ = unsafe { s.queue.present_khr_unchecked(&present) };
    });
    s.queue.wait_idle().expect("idle");
    drop(swapchain);
    drop(surface);
    assert_silent(&s.messages);
}

/// A presented image must be acquired and not presented since, and in
/// PRESENT_SRC_KHR as the submissions before the presentation leave it: the safe
/// presentation refuses either, and the layer names the layout rule for the
/// unchecked one.
#[test]
fn only_acquired_images_in_the_present_layout_are_presented() {
    let _serial = vulkan::serial();
    let s = setup_with(true, Wsi::Xlib);
    let window = x11_window::X11Window::open(32, 32);
    let surface = xlib_surface(&s, &window);
    let swapchain = s
        .device
        .create_swapchain_khr(&surface, &swapchain_info(&s, &surface))
        .expect("swapchain");
    let images = s
        .device
        .get_swapchain_images_khr(&swapchain)
        .expect("swapchain images");
    let fence = s
        .device
        .create_fence(&tuff::FenceCreateInfo::new())
        .expect("fence");
    let (index, _) = s
        .device
        .acquire_next_image_khr(&swapchain, u64::MAX, None, Some(&fence))
        .expect("acquire");
    assert_eq!(
        s.device
            .wait_for_fences(&fence, true, u64::MAX)
            .expect("acquired"),
        tuff::SuccessOrTimeout::Success
    );
    let rule = "VUID-VkPresentInfoKHR-pImageIndices-01296";
    let swapchains = tuff::HandleSlice::new(&[&swapchain]);
    let indices = [index];
    let other = [(index + 1) % images.len() as u32];
    let present = |indices| {
        tuff::PresentInfoKHR::new()
            .swapchains(&swapchains, indices)
            .expect("one index per swapchain")
    };
    // Acquired, but still UNDEFINED: nothing moved it to PRESENT_SRC_KHR.
    assert_eq!(refused(s.queue.present_khr(&present(&indices))), rule);
    // Another image, never acquired.
    assert_eq!(refused(s.queue.present_khr(&present(&other))), rule);
    layer_names(&s, rule, || {
        // SAFETY: the layer names the rule and skips the call.
        let _ = unsafe { s.queue.present_khr_unchecked(&present(&indices)) };
    });
    s.queue.wait_idle().expect("idle");
    drop(images);
    drop(swapchain);
    drop(surface);
    assert_silent(&s.messages);
}

/// Acquires an image of `swapchain` (waiting on a fence) and moves it to
/// PRESENT_SRC_KHR; returns its index.
fn acquire_for_present(
    s: &Setup,
    swapchain: &tuff::SwapchainKHR,
    images: &[tuff::Image],
    pool: &tuff::CommandPool,
) -> u32 {
    let d = &s.device;
    let fence = d
        .create_fence(&tuff::FenceCreateInfo::new())
        .expect("fence");
    let (index, _) = d
        .acquire_next_image_khr(swapchain, u64::MAX, None, Some(&fence))
        .expect("acquire");
    assert_eq!(
        d.wait_for_fences(&fence, true, u64::MAX).expect("acquired"),
        tuff::SuccessOrTimeout::Success
    );
    let mut cb = d
        .allocate_command_buffers(
            pool,
            &tuff::CommandBufferAllocateInfo::new(pool).command_buffer_count(1),
        )
        .expect("command buffer")
        .pop()
        .expect("one");
    let mut rec = cb
        .begin(&tuff::CommandBufferBeginInfo::new())
        .expect("begin");
    let barrier = tuff::ImageMemoryBarrier::new(&images[index as usize])
        .old_layout(vk::ImageLayout::UNDEFINED)
        .new_layout(vk::ImageLayout::PRESENT_SRC_KHR)
        .src_queue_family_index(vk::QUEUE_FAMILY_IGNORED)
        .dst_queue_family_index(vk::QUEUE_FAMILY_IGNORED)
        .subresource_range(vk::ImageSubresourceRange {
            aspect_mask: vk::ImageAspectFlags::COLOR,
            base_mip_level: 0,
            level_count: 1,
            base_array_layer: 0,
            layer_count: 1,
        });
    rec.pipeline_barrier(
        vk::PipelineStageFlags::TOP_OF_PIPE,
        vk::PipelineStageFlags::BOTTOM_OF_PIPE,
        vk::DependencyFlags::empty(),
        &[],
        &[],
        &[barrier],
    )
    .expect("barrier");
    rec.end().expect("end");
    let done = d
        .create_fence(&tuff::FenceCreateInfo::new())
        .expect("fence");
    s.queue
        .submit(&[tuff::SubmitInfo::new().command_buffers(&cb)], Some(&done))
        .expect("submit");
    assert_eq!(
        d.wait_for_fences(&done, true, u64::MAX).expect("moved"),
        tuff::SuccessOrTimeout::Success
    );
    index
}

/// A chained `VkDeviceGroupPresentInfoKHR` is checked against the presentation's
/// swapchain count, the device group's present masks, the mask each image was
/// acquired with and the swapchain's modes: each rule broken is refused by the
/// safe presentation, and the layer names it for the unchecked one. A valid one
/// presents.
#[test]
fn device_group_presentations_are_checked_and_the_layer_agrees() {
    let _serial = vulkan::serial();
    let s = setup_with(true, Wsi::Xlib);
    let window = x11_window::X11Window::open(32, 32);
    let surface = xlib_surface(&s, &window);
    let swapchain = s
        .device
        .create_swapchain_khr(&surface, &swapchain_info(&s, &surface))
        .expect("swapchain");
    let images = s
        .device
        .get_swapchain_images_khr(&swapchain)
        .expect("swapchain images");
    let pool = s
        .device
        .create_command_pool(&tuff::CommandPoolCreateInfo::new().queue_family_index(s.family))
        .expect("pool");
    type Mode = vk::DeviceGroupPresentModeFlagsKHR;
    // The device is a group of one: its present mask is bit 0, its swapchains use
    // the LOCAL mode, and an image acquired with vkAcquireNextImageKHR has mask 1.
    let cases: [(&[u32], Mode, &str); 7] = [
        (
            &[1, 1],
            Mode::LOCAL,
            "VUID-VkDeviceGroupPresentInfoKHR-swapchainCount-01297",
        ),
        (
            &[3],
            Mode::LOCAL,
            "VUID-VkDeviceGroupPresentInfoKHR-mode-01298",
        ),
        (
            &[2],
            Mode::REMOTE,
            "VUID-VkDeviceGroupPresentInfoKHR-mode-01299",
        ),
        (
            &[2],
            Mode::SUM,
            "VUID-VkDeviceGroupPresentInfoKHR-mode-01300",
        ),
        (
            &[2],
            Mode::LOCAL_MULTI_DEVICE,
            "VUID-VkDeviceGroupPresentInfoKHR-mode-01301",
        ),
        (
            &[0],
            Mode::SUM,
            "VUID-VkDeviceGroupPresentInfoKHR-pDeviceMasks-01302",
        ),
        (
            &[1],
            Mode::REMOTE,
            "VUID-VkDeviceGroupPresentInfoKHR-mode-01303",
        ),
    ];
    let swapchains = tuff::HandleSlice::new(&[&swapchain]);
    let index = acquire_for_present(&s, &swapchain, &images, &pool);
    let indices = [index];
    for (masks, mode, rule) in cases {
        let mut group = tuff::DeviceGroupPresentInfoKHR::new()
            .device_masks(masks)
            .mode(mode);
        let present = tuff::PresentInfoKHR::new()
            .swapchains(&swapchains, &indices)
            .expect("one index per swapchain")
            .push_next(&mut group);
        assert_eq!(
            refused(s.queue.present_khr(&present)),
            rule,
            "{masks:?} {mode:?}"
        );
    }
    // A valid one.
    let mut group = tuff::DeviceGroupPresentInfoKHR::new()
        .device_masks(&[1])
        .mode(Mode::LOCAL);
    let present = tuff::PresentInfoKHR::new()
        .swapchains(&swapchains, &indices)
        .expect("one index per swapchain")
        .push_next(&mut group);
    let r = s.queue.present_khr(&present).expect("present");
    assert!(
        r == tuff::SuccessOrSuboptimal::Success || r == tuff::SuccessOrSuboptimal::Suboptimal,
        "{r:?}"
    );
    s.queue.wait_idle().expect("idle");
    // The layer, for the unchecked presentation: the 1.3.239 layer checks none of
    // these rules on a device of one physical device, so it stays silent and the
    // presentation is made (these rules are proven by tuff's error alone). Each case
    // presents an image of its own.
    for (masks, mode, rule) in cases {
        let index = acquire_for_present(&s, &swapchain, &images, &pool);
        let indices = [index];
        let mut group = tuff::DeviceGroupPresentInfoKHR::new()
            .device_masks(masks)
            .mode(mode);
        let present = tuff::PresentInfoKHR::new()
            .swapchains(&swapchains, &indices)
            .expect("one index per swapchain")
            .push_next(&mut group);
        s.messages.take();
        s.messages.abort_on_error(true);
        // SAFETY: the layer skips the call if it reports it; if it is silent, the
        // driver of a group of one physical device presents the image.
        let _ = unsafe { s.queue.present_khr_unchecked(&present) };
        s.messages.abort_on_error(false);
        let messages = s.messages.take();
        // A layer that names the rule skips the call and leaves the image acquired,
        // which the next case's acquire would wait on: this test must change then.
        assert!(
            messages.is_empty(),
            "the layer now reports {rule} (or another rule): {messages:?}"
        );
        s.queue.wait_idle().expect("idle");
    }
    s.queue.wait_idle().expect("idle");
    drop(images);
    drop(swapchain);
    drop(surface);
    assert_silent(&s.messages);
}

/// Acquires and queue operations follow each binary semaphore's state, and an
/// acquire its swapchain's and fence's: each rule broken is refused by the safe
/// method, and the layer names it for the unchecked one.
#[test]
fn binary_semaphores_fences_and_acquires_are_tracked_and_the_layer_agrees() {
    let _serial = vulkan::serial();
    let s = setup_with(true, Wsi::Xlib);
    let window = x11_window::X11Window::open(32, 32);
    let surface = xlib_surface(&s, &window);
    let d = &s.device;
    let swapchain = d
        .create_swapchain_khr(&surface, &swapchain_info(&s, &surface))
        .expect("swapchain");
    let semaphore = || {
        d.create_semaphore(&tuff::SemaphoreCreateInfo::new())
            .expect("semaphore")
    };
    let fence = |flags| {
        d.create_fence(&tuff::FenceCreateInfo::new().flags(flags))
            .expect("fence")
    };
    let unsignaled = vk::FenceCreateFlags::empty();
    // Nothing to signal.
    let neither = "VUID-vkAcquireNextImageKHR-semaphore-01780";
    assert_eq!(
        refused(d.acquire_next_image_khr(&swapchain, 0, None, None)),
        neither
    );
    layer_names(&s, neither, || {
        // SAFETY: the layer names the rule and skips the call.
        let _ = unsafe { d.acquire_next_image_khr_unchecked(&swapchain, 0, None, None) };
    });
    // A signaled fence.
    let signaled = fence(vk::FenceCreateFlags::SIGNALED);
    let fence_rule = "VUID-vkAcquireNextImageKHR-fence-01287";
    assert_eq!(
        refused(d.acquire_next_image_khr(&swapchain, 0, None, Some(&signaled))),
        fence_rule
    );
    layer_names(&s, fence_rule, || {
        // SAFETY: the layer names the rule and skips the call.
        let _ = unsafe { d.acquire_next_image_khr_unchecked(&swapchain, 0, None, Some(&signaled)) };
    });
    // A semaphore an acquire signaled, not waited on since.
    let acquired = semaphore();
    let done = fence(unsignaled);
    let (index, _) = d
        .acquire_next_image_khr(&swapchain, u64::MAX, Some(&acquired), Some(&done))
        .expect("acquire");
    let again = "VUID-vkAcquireNextImageKHR-semaphore-01286";
    assert_eq!(
        refused(d.acquire_next_image_khr(&swapchain, 0, Some(&acquired), None)),
        again
    );
    layer_names(&s, again, || {
        // SAFETY: the layer names the rule and skips the call.
        let _ = unsafe { d.acquire_next_image_khr_unchecked(&swapchain, 0, Some(&acquired), None) };
    });
    // The acquire's fence belongs to it until it is seen signaled.
    assert_eq!(
        d.wait_for_fences(&done, true, u64::MAX).expect("acquired"),
        tuff::SuccessOrTimeout::Success
    );
    d.reset_fences(&done).expect("reset");
    // A wait on it is pending while a timeline wait holds its batch back.
    let mut timeline_type = tuff::SemaphoreTypeCreateInfo::new()
        .semaphore_type(vk::SemaphoreType::TIMELINE)
        .initial_value(0);
    let gate = d
        .create_semaphore(&tuff::SemaphoreCreateInfo::new().push_next(&mut timeline_type))
        .expect("timeline");
    let waits = tuff::HandleSlice::new(&[&acquired, &gate]);
    let stages = [vk::PipelineStageFlags::ALL_COMMANDS; 2];
    let mut values = tuff::TimelineSemaphoreSubmitInfo::new().wait_semaphore_values(&[0, 1]);
    let gated = [tuff::SubmitInfo::new()
        .wait_semaphores(&waits, &stages)
        .expect("one stage per wait")
        .push_next(&mut values)];
    s.queue.submit(&gated, Some(&done)).expect("gated submit");
    // A second wait on it, with no signal between, is refused too.
    let unsignaled_wait = "VUID-vkQueueSubmit-pWaitSemaphores-03238";
    let one_stage = [vk::PipelineStageFlags::ALL_COMMANDS];
    let second = [tuff::SubmitInfo::new()
        .wait_semaphores(&acquired, &one_stage)
        .expect("one stage per wait")];
    let other = fence(unsignaled);
    assert_eq!(
        refused(s.queue.submit(&second, Some(&other))),
        unsignaled_wait
    );
    layer_names(&s, unsignaled_wait, || {
        // SAFETY: the layer names the rule and skips the call.
        let _ = unsafe { s.queue.submit_unchecked(&second, Some(&other)) };
    });
    let pending = "VUID-vkAcquireNextImageKHR-semaphore-01779";
    assert_eq!(
        refused(d.acquire_next_image_khr(&swapchain, 0, Some(&acquired), None)),
        pending
    );
    // The 1.3.239 layer does not check it: proven by the error alone (lavapipe's
    // acquire signals at once, so the unchecked call does no harm here).
    s.messages.take();
    // SAFETY: see above.
    let _ = unsafe { d.acquire_next_image_khr_unchecked(&swapchain, 0, Some(&acquired), None) };
    let said = s.messages.take();
    assert!(said.is_empty(), "the layer said: {said:?}");
    d.signal_semaphore(&tuff::SemaphoreSignalInfo::new(&gate).value(1))
        .expect("open the gate");
    assert_eq!(
        d.wait_for_fences(&done, true, u64::MAX)
            .expect("the gated batch"),
        tuff::SuccessOrTimeout::Success
    );
    // A signal of a semaphore already signaled.
    let twice = semaphore();
    let signals = tuff::HandleSlice::new(&[&twice]);
    let signal = [tuff::SubmitInfo::new().signal_semaphores(&signals)];
    s.queue.submit(&signal, Some(&other)).expect("signal");
    let signaled_again = "VUID-vkQueueSubmit-pSignalSemaphores-00067";
    let third = fence(unsignaled);
    assert_eq!(
        refused(s.queue.submit(&signal, Some(&third))),
        signaled_again
    );
    // The 1.3.239 layer reports this rule under an unassigned name ("... was
    // previously signaled ... but has not since been waited on").
    layer_names(
        &s,
        "UNASSIGNED-CoreValidation-DrawState-QueueForwardProgress",
        || {
            // SAFETY: the layer reports the rule and skips the call.
            let _ = unsafe { s.queue.submit_unchecked(&signal, Some(&third)) };
        },
    );
    // A presentation that waits on a semaphore nothing signals.
    let nothing = semaphore();
    let swapchains = tuff::HandleSlice::new(&[&swapchain]);
    let indices = [index];
    let present = tuff::PresentInfoKHR::new()
        .wait_semaphores(&nothing)
        .swapchains(&swapchains, &indices)
        .expect("one index per swapchain");
    let present_rule = "VUID-vkQueuePresentKHR-pWaitSemaphores-03268";
    assert_eq!(refused(s.queue.present_khr(&present)), present_rule);
    layer_names(&s, present_rule, || {
        // SAFETY: the layer names the rule and skips the call.
        let _ = unsafe { s.queue.present_khr_unchecked(&present) };
    });
    // A swapchain a later creation retired.
    let successor = d
        .create_swapchain_khr(
            &surface,
            &swapchain_info(&s, &surface).old_swapchain(Some(&swapchain)),
        )
        .expect("successor");
    let retired = "VUID-vkAcquireNextImageKHR-swapchain-01285";
    let spare = semaphore();
    assert_eq!(
        refused(d.acquire_next_image_khr(&swapchain, 0, Some(&spare), None)),
        retired
    );
    layer_names(&s, retired, || {
        // SAFETY: the layer names the rule and skips the call.
        let _ = unsafe { d.acquire_next_image_khr_unchecked(&swapchain, 0, Some(&spare), None) };
    });
    s.queue.wait_idle().expect("idle");
    d.wait_idle().expect("idle");
    drop((successor, swapchain));
    drop(surface);
    assert_silent(&s.messages);
}

/// An infinite acquire where the swapchain cannot give another image without a
/// present is refused, and the layer names the rule.
#[test]
fn an_acquire_that_cannot_progress_may_not_wait_forever() {
    let _serial = vulkan::serial();
    let s = setup_with(true, Wsi::Xlib);
    let window = x11_window::X11Window::open(32, 32);
    let surface = xlib_surface(&s, &window);
    let d = &s.device;
    let swapchain = d
        .create_swapchain_khr(&surface, &swapchain_info(&s, &surface))
        .expect("swapchain");
    let images = d
        .get_swapchain_images_khr(&swapchain)
        .expect("images")
        .len();
    let min = s
        .physical
        .get_surface_capabilities_khr(&surface)
        .expect("capabilities")
        .min_image_count as usize;
    let mut fences = Vec::new();
    // As many images as may be acquired at once without a present.
    for _ in 0..=images.saturating_sub(min) {
        let f = d
            .create_fence(&tuff::FenceCreateInfo::new())
            .expect("fence");
        let (_, r) = d
            .acquire_next_image_khr(&swapchain, 1_000_000_000, None, Some(&f))
            .expect("acquire");
        assert!(
            r == tuff::SuccessTimeoutNotReadyOrSuboptimal::Success
                || r == tuff::SuccessTimeoutNotReadyOrSuboptimal::Suboptimal,
            "an image within the count is acquired ({r:?})"
        );
        fences.push(f);
    }
    let f = d
        .create_fence(&tuff::FenceCreateInfo::new())
        .expect("fence");
    let rule = "VUID-vkAcquireNextImageKHR-surface-07783";
    assert_eq!(
        refused(d.acquire_next_image_khr(&swapchain, u64::MAX, None, Some(&f))),
        rule
    );
    layer_names(&s, rule, || {
        // SAFETY: the layer names the rule and skips the call.
        let _ = unsafe { d.acquire_next_image_khr_unchecked(&swapchain, u64::MAX, None, Some(&f)) };
    });
    let all: Vec<&tuff::Fence> = fences.iter().collect();
    assert_eq!(
        d.wait_for_fences(&tuff::HandleSlice::new(&all), true, u64::MAX)
            .expect("acquired"),
        tuff::SuccessOrTimeout::Success
    );
    drop(swapchain);
    drop(surface);
    assert_silent(&s.messages);
}

/// An image made for a swapchain's memory has the swapchain's implied image
/// parameters: one of another format is refused.
#[test]
fn an_image_for_a_swapchain_has_its_parameters() {
    let _serial = vulkan::serial();
    let s = setup_with(true, Wsi::Xlib);
    let window = x11_window::X11Window::open(32, 32);
    let surface = xlib_surface(&s, &window);
    let info = swapchain_info(&s, &surface);
    let (format, extent, usage) = {
        let raw = info.as_raw();
        (raw.image_format, raw.image_extent, raw.image_usage)
    };
    let swapchain = s
        .device
        .create_swapchain_khr(&surface, &info)
        .expect("swapchain");
    let other = if format == vk::Format::B8G8R8A8_UNORM {
        vk::Format::R8G8B8A8_UNORM
    } else {
        vk::Format::B8G8R8A8_UNORM
    };
    let mut of_swapchain = tuff::ImageSwapchainCreateInfoKHR::new().swapchain(Some(&swapchain));
    let image = tuff::ImageCreateInfo::new()
        .image_type(vk::ImageType::TYPE_2D)
        .format(other)
        .extent(vk::Extent3D {
            width: extent.width,
            height: extent.height,
            depth: 1,
        })
        .mip_levels(1)
        .array_layers(1)
        .samples(vk::SampleCountFlags::TYPE_1)
        .usage(usage)
        .push_next(&mut of_swapchain);
    let rule = "VUID-VkImageSwapchainCreateInfoKHR-swapchain-00995";
    assert_eq!(refused(s.device.create_image(&image).map(drop)), rule);
    // The 1.3.239 layer does not check the rule: it is proven by the error alone
    // (lavapipe makes a plain image of the other format).
    s.messages.take();
    // SAFETY: lavapipe reads nothing of the swapchain for a plain image.
    let made = unsafe { s.device.create_image_unchecked(&image) };
    assert!(made.is_ok() && s.messages.take().is_empty());
    drop(made);
    drop(swapchain);
    drop(surface);
    assert_silent(&s.messages);
}

/// A swapchain's create info is checked against what the surface reports, and an
/// old swapchain against its surface and whether it was retired; the layer names
/// each rule the test's window can break (or says nothing: proven by the error).
#[test]
fn swapchain_creation_is_checked_against_the_surface_and_the_layer_agrees() {
    let _serial = vulkan::serial();
    let s = setup_with(true, Wsi::Xlib);
    let window = x11_window::X11Window::open(32, 32);
    let surface = xlib_surface(&s, &window);
    let p = &s.physical;
    let caps = p
        .get_surface_capabilities_khr(&surface)
        .expect("capabilities");
    let formats = p.get_surface_formats_khr(Some(&surface)).expect("formats");
    let modes = p
        .get_surface_present_modes_khr(Some(&surface))
        .expect("present modes");
    let valid = swapchain_info(&s, &surface);
    let unoffered_format = [vk::Format::R16G16B16A16_SFLOAT, vk::Format::R8G8B8A8_SNORM]
        .into_iter()
        .find(|f| formats.iter().all(|o| o.format != *f))
        .expect("a format the surface does not offer");
    let bit_outside = |set: u32| {
        (0..32)
            .map(|b| 1u32 << b)
            .find(|b| set & b == 0)
            .unwrap_or(0)
    };
    let big = vk::Extent2D {
        width: caps.max_image_extent.width + 1,
        height: caps.max_image_extent.height,
    };
    let mut cases: Vec<(&str, &[&str], tuff::SwapchainCreateInfoKHR<'_>)> = vec![
        (
            "VUID-VkSwapchainCreateInfoKHR-minImageCount-01271",
            &[],
            valid.min_image_count(caps.min_image_count - 1),
        ),
        (
            "VUID-VkSwapchainCreateInfoKHR-imageFormat-01273",
            &[],
            valid.image_format(unoffered_format),
        ),
        (
            "VUID-VkSwapchainCreateInfoKHR-imageExtent-01689",
            &["VUID-VkSwapchainCreateInfoKHR-imageExtent-01274"],
            valid.image_extent(vk::Extent2D::default()),
        ),
        (
            "VUID-VkSwapchainCreateInfoKHR-imageExtent-01274",
            &[],
            valid.image_extent(big),
        ),
        (
            "VUID-VkSwapchainCreateInfoKHR-imageArrayLayers-01275",
            &[],
            valid.image_array_layers(caps.max_image_array_layers + 1),
        ),
        (
            "VUID-VkSwapchainCreateInfoKHR-presentMode-01427",
            &[],
            valid.image_usage(vk::ImageUsageFlags::from_raw(bit_outside(
                caps.supported_usage_flags.as_raw() & 0xff,
            ))),
        ),
        (
            "VUID-VkSwapchainCreateInfoKHR-preTransform-01279",
            // A performance warning that names no rule comes with it.
            &["UNASSIGNED-CoreValidation-SwapchainPreTransform"],
            valid.pre_transform(vk::SurfaceTransformFlagsKHR::from_raw(bit_outside(
                caps.supported_transforms.as_raw() & 0x1ff,
            ))),
        ),
        (
            "VUID-VkSwapchainCreateInfoKHR-compositeAlpha-01280",
            &[],
            valid.composite_alpha(vk::CompositeAlphaFlagsKHR::from_raw(bit_outside(
                caps.supported_composite_alpha.as_raw() & 0xf,
            ))),
        ),
        (
            "VUID-VkSwapchainCreateInfoKHR-imageSharingMode-01428",
            &[],
            valid
                .image_sharing_mode(vk::SharingMode::CONCURRENT)
                .queue_family_indices(&[0, 64]),
        ),
        (
            "VUID-VkSwapchainCreateInfoKHR-physicalDeviceCount-01429",
            &[],
            valid.flags(vk::SwapchainCreateFlagsKHR::SPLIT_INSTANCE_BIND_REGIONS),
        ),
    ];
    if caps.max_image_count != 0 {
        cases.push((
            "VUID-VkSwapchainCreateInfoKHR-minImageCount-01272",
            &[],
            valid.min_image_count(caps.max_image_count + 1),
        ));
    }
    if let Some(mode) = [
        vk::PresentModeKHR::MAILBOX,
        vk::PresentModeKHR::FIFO_RELAXED,
    ]
    .into_iter()
    .find(|m| !modes.contains(m))
    {
        cases.push((
            "VUID-VkSwapchainCreateInfoKHR-presentMode-01281",
            &[],
            valid.present_mode(mode),
        ));
    }
    let mut alone = Vec::new();
    for (rule, also, info) in &cases {
        let safe = s.device.create_swapchain_khr(&surface, info);
        assert_eq!(refused(safe.map(drop)), *rule, "the safe call");
        s.messages.take();
        s.messages.abort_on_error(true);
        // SAFETY: the layer skips a call it reports (its messenger says so).
        let made = unsafe { s.device.create_swapchain_khr_unchecked(&surface, info) };
        s.messages.abort_on_error(false);
        let said = s.messages.take();
        if said.is_empty() {
            alone.push(*rule);
            drop(made);
            continue;
        }
        let names = |m: &String, v: &str| m.contains(&format!("[ {v} ]"));
        assert!(
            said.iter().any(|m| names(m, rule))
                && said
                    .iter()
                    .all(|m| names(m, rule) || also.iter().any(|a| names(m, a))),
            "{rule}: the layer said:\n{}",
            said.join("\n")
        );
        drop(made);
    }
    // A swapchain retired by a creation that named it as the old one cannot be
    // named again.
    let first = s
        .device
        .create_swapchain_khr(&surface, &valid)
        .expect("swapchain");
    let second = s
        .device
        .create_swapchain_khr(&surface, &valid.old_swapchain(Some(&first)))
        .expect("its replacement");
    let again = valid.old_swapchain(Some(&first));
    let retired = "VUID-VkSwapchainCreateInfoKHR-oldSwapchain-01933";
    assert_eq!(
        refused(s.device.create_swapchain_khr(&surface, &again).map(drop)),
        retired
    );
    layer_names(&s, retired, || {
        // SAFETY: the layer names the rule and skips the call.
        drop(unsafe { s.device.create_swapchain_khr_unchecked(&surface, &again) });
    });
    println!(
        "swapchain creation: the layer named {}, the error alone proves {} ({})",
        cases.len() + 1 - alone.len(),
        alone.len(),
        alone.join(", ")
    );
    drop((second, first));
    drop(surface);
    assert_silent(&s.messages);
}

/// The VUID of a refused call.
fn refused<T: std::fmt::Debug>(r: tuff::Result<T>) -> &'static str {
    match r {
        Err(tuff::Error::Validation { vuid, .. }) => vuid,
        other => panic!("expected a refusal, got {other:?}"),
    }
}

/// Runs `unchecked` with the layer told to skip erroring calls, and fails unless it
/// named `expected`.
fn layer_names(s: &Setup, expected: &str, unchecked: impl FnOnce()) {
    s.messages.take();
    s.messages.abort_on_error(true);
    unchecked();
    s.messages.abort_on_error(false);
    let said = s.messages.take();
    assert!(
        said.iter().any(|m| m.contains(expected)),
        "the validation layer did not report {expected}; it said:\n{}",
        said.join("\n")
    );
}

/// `Debug` shows a handle's type and raw value, and a safe struct's members as ash
/// prints them, so a user can print what they hold.
#[test]
fn handles_and_structs_print_their_type_and_raw_value() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let (buffer, _memory) = buffer_with_memory(&s, 64);
    let printed = format!("{buffer:?}");
    assert_eq!(printed, format!("Buffer({:?})", tuff::Handle::raw(&buffer)));
    assert!(printed.starts_with("Buffer(0x"), "{printed}");
    assert!(format!("{:?}", s.device).starts_with("Device(0x"));
    assert!(format!("{:?}", s.instance).starts_with("Instance(0x"));
    let info = tuff::BufferCreateInfo::new()
        .size(64)
        .usage(vk::BufferUsageFlags::UNIFORM_BUFFER);
    let printed = format!("{info:?}");
    assert!(
        printed.starts_with("BufferCreateInfo {") && printed.contains("size: 64"),
        "{printed}"
    );
    let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let rec = cb
        .begin(&tuff::CommandBufferBeginInfo::new())
        .expect("begin");
    let printed = format!("{rec:?}");
    assert!(printed.contains("state: \"Outside\""), "{printed}");
    rec.end().expect("end");
    assert_silent(&s.messages);
}
