//! The generated wrappers on lavapipe, with the validation layer and its
//! synchronization validation on: objects of every handle type lavapipe supports
//! without a window or shaders are created, used and dropped in random orders
//! (parents before children included), and resources are dropped while the
//! submission that uses them is still in flight.

#[path = "common/tuff_setup.rs"]
mod tuff_setup;
#[path = "common/vulkan.rs"]
mod vulkan;

use std::any::Any;
use tuff::vk;
use tuff_setup::{setup, ColorTarget, Setup};
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
    let buffer = s
        .device
        .create_buffer(&tuff::BufferCreateInfo::new().size(size).usage(
            vk::BufferUsageFlags::TRANSFER_DST
                | vk::BufferUsageFlags::UNIFORM_BUFFER
                | vk::BufferUsageFlags::UNIFORM_TEXEL_BUFFER,
        ))
        .expect("buffer");
    let reqs = s
        .device
        .get_buffer_memory_requirements(&buffer)
        .expect("memory requirements");
    let memory = s
        .device
        .allocate_memory(
            &tuff::MemoryAllocateInfo::new()
                .allocation_size(reqs.size)
                .memory_type_index(
                    s.memory_type(reqs.memory_type_bits, vk::MemoryPropertyFlags::HOST_VISIBLE),
                ),
        )
        .expect("memory");
    s.device
        .bind_buffer_memory(&buffer, &memory, 0)
        .expect("bind");
    (buffer, memory)
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
    let ColorTarget {
        image,
        memory: image_memory,
        view: image_view,
        render_pass,
        framebuffer,
    } = s.color_target(16, vk::ImageUsageFlags::SAMPLED);
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
    let layouts = tuff::HandleSlice::new(&[&set_layout]);
    let sets = d
        .allocate_descriptor_sets(
            &pool,
            &tuff::DescriptorSetAllocateInfo::new(&pool).set_layouts(&layouts),
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
    for seed in 0..6u64 {
        let s = setup(true);
        let mut bag = make_all(&s);
        assert_eq!(bag.len(), 21);
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
    let s = setup(true);
    let d = &s.device;
    let fence = d
        .create_fence(&tuff::FenceCreateInfo::new())
        .expect("fence");
    for round in 0..20u32 {
        let (buffer, memory) = buffer_with_memory(&s, 1 << 20);
        let pool = d
            .create_command_pool(&tuff::CommandPoolCreateInfo::new().queue_family_index(s.family))
            .expect("pool");
        let mut cbs = d
            .allocate_command_buffers(
                &pool,
                &tuff::CommandBufferAllocateInfo::new(&pool).command_buffer_count(1),
            )
            .expect("cbs");
        let mut cb = cbs.pop().expect("one command buffer");
        let mut rec = cb
            .begin(&tuff::CommandBufferBeginInfo::new())
            .expect("begin");
        for i in 0..64u64 {
            rec.cmd_fill_buffer(&buffer, i * 16384, 16384, round);
        }
        rec.end().expect("end");
        let cb_handles = tuff::HandleSlice::new(&[&cb]);
        let submits = [tuff::SubmitInfo::new().command_buffers(&cb_handles)];
        s.queue.queue_submit(&submits, &fence).expect("submit");
        // Everything the submission uses goes while it may still run; the fence
        // keeps the command buffer, and through it the buffer and memory, alive.
        let _ = submits;
        drop(cb_handles);
        drop(cb);
        drop(pool);
        drop(buffer);
        drop(memory);
        let (_, status) = d
            .wait_for_fences(&[&fence], vk::TRUE, u64::MAX)
            .expect("wait");
        assert_eq!(status, vk::Result::SUCCESS);
        d.reset_fences(&[&fence]).expect("reset");
    }
    assert_silent(&s.messages);
}

#[test]
fn a_submitted_buffer_is_written() {
    let s = setup(true);
    let d = &s.device;
    let (buffer, memory) = buffer_with_memory(&s, 256);
    let pool = d
        .create_command_pool(&tuff::CommandPoolCreateInfo::new().queue_family_index(s.family))
        .expect("pool");
    let mut cb = d
        .allocate_command_buffers(
            &pool,
            &tuff::CommandBufferAllocateInfo::new(&pool).command_buffer_count(1),
        )
        .expect("cbs")
        .pop()
        .expect("one");
    let mut rec = cb
        .begin(&tuff::CommandBufferBeginInfo::new())
        .expect("begin");
    rec.cmd_fill_buffer(&buffer, 0, 256, 0xA5A5_A5A5);
    rec.end().expect("end");
    assert!(cb.is_executable());
    let fence = d
        .create_fence(&tuff::FenceCreateInfo::new())
        .expect("fence");
    let handles = tuff::HandleSlice::new(&[&cb]);
    s.queue
        .queue_submit(&[tuff::SubmitInfo::new().command_buffers(&handles)], &fence)
        .expect("submit");
    let (_, status) = d
        .wait_for_fences(&[&fence], vk::TRUE, u64::MAX)
        .expect("wait");
    assert_eq!(status, vk::Result::SUCCESS);
    // Read back through ash on the raw handles: Deref keeps the layer transparent.
    let ash_device = d.fns();
    // SAFETY: the memory is host-visible, coherent on lavapipe, and the fence has
    // signalled, so the fill is complete; the mapping is unmapped before the end.
    let bytes = unsafe {
        let ptr = ash_device
            .map_memory(*memory, 0, 256, vk::MemoryMapFlags::empty())
            .expect("map");
        let v = std::slice::from_raw_parts(ptr as *const u8, 256).to_vec();
        ash_device.unmap_memory(*memory);
        v
    };
    assert!(
        bytes.iter().all(|b| *b == 0xA5),
        "the fill reached the buffer"
    );
    assert_silent(&s.messages);
}
