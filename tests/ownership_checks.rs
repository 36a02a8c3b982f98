//! Handles of another device: every handle a call names, as a wrapper argument or
//! inside a struct (a view's image, a descriptor's buffer, a barrier's image, a
//! batch's command buffer), must be an object of the call's device. Wrappers of two
//! devices have the same types, so the types cannot tell; a driver given a handle of
//! another device reads that device's memory as its own. tuff refuses such a call
//! before any other check or driver call sees the handle.
//!
//! Each case makes the call on device A with one object of device B: the safe method
//! must refuse it with the rule's VUID, and the same call with A's own object
//! succeeds. Where the 1.3.239 validation layer can tell, it must name the same VUID
//! for the `_unchecked` twin (told to skip the call it reports); for most of these
//! calls it cannot: it crashes, or says nothing and passes the call on.
//!
//! SAFETY of the `unsafe` blocks: the methods called are `unsafe` for rules their
//! `# Safety` sections list, which these calls keep but for the one each case breaks
//! on purpose, which tuff refuses and the layer skips.

#[path = "common/tuff_setup.rs"]
mod tuff_setup;
#[path = "common/vulkan.rs"]
mod vulkan;

use tuff::vk;
use tuff_setup::{setup, vuid, Setup};
use vulkan::assert_silent;

/// A second device on the setup's physical device, with one queue of its family.
fn other_device(s: &Setup) -> tuff::Device {
    let queues = [tuff::DeviceQueueCreateInfo::new()
        .queue_family_index(s.family)
        .queue_priorities(&[1.0])];
    s.physical
        .create_device(&tuff::DeviceCreateInfo::new().queue_create_infos(&queues))
        .expect("second device")
}

/// Objects of one device that the cases name.
struct Objects {
    buffer: tuff::Buffer,
    image: tuff::Image,
    _memory: [tuff::DeviceMemory; 2],
}

fn objects(s: &Setup, d: &tuff::Device) -> Objects {
    let buffer = d
        .create_buffer(&tuff::BufferCreateInfo::new().size(256).usage(
            vk::BufferUsageFlags::UNIFORM_BUFFER
                | vk::BufferUsageFlags::TRANSFER_SRC
                | vk::BufferUsageFlags::TRANSFER_DST,
        ))
        .expect("buffer");
    let image = d
        .create_image(
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
                .usage(vk::ImageUsageFlags::SAMPLED | vk::ImageUsageFlags::TRANSFER_DST),
        )
        .expect("image");
    let reqs = d
        .get_image_memory_requirements(&image)
        .expect("requirements");
    let memory = d
        .allocate_memory(
            &tuff::MemoryAllocateInfo::new()
                .allocation_size(reqs.size)
                .memory_type_index(
                    s.memory_type(reqs.memory_type_bits, vk::MemoryPropertyFlags::empty()),
                ),
        )
        .expect("memory");
    d.bind_image_memory(&image, &memory, 0).expect("bind image");
    let reqs = d
        .get_buffer_memory_requirements(&buffer)
        .expect("requirements");
    let buffer_memory = d
        .allocate_memory(
            &tuff::MemoryAllocateInfo::new()
                .allocation_size(reqs.size)
                .memory_type_index(
                    s.memory_type(reqs.memory_type_bits, vk::MemoryPropertyFlags::empty()),
                ),
        )
        .expect("memory");
    d.bind_buffer_memory(&buffer, &buffer_memory, 0)
        .expect("bind buffer");
    Objects {
        buffer,
        image,
        _memory: [memory, buffer_memory],
    }
}

/// What the validation layer does with a case's unchecked call.
enum Layer<'a> {
    /// It names the rule, or one of these VUIDs it files the same condition under,
    /// and skips the call.
    Names(&'a [&'a str]),
    /// It cannot prove the rule: given another device's handle there, the unchecked
    /// call crashes the process (in the layer itself, for a view's image) or the
    /// layer says nothing and passes it on. tuff's refusal alone shows it.
    Unusable,
}

/// Runs a case: the safe call on A with B's object must be refused with `rule`, the
/// same with A's object must succeed, and where the layer can tell, it must name
/// `rule` for the unchecked call with B's object.
fn case(
    s: &Setup,
    rule: &str,
    layer: Layer<'_>,
    mut call: impl FnMut(bool, bool) -> tuff::Result<()>,
) {
    assert_eq!(
        vuid(call(true, false)),
        rule,
        "the safe call with B's object"
    );
    call(false, false).unwrap_or_else(|e| panic!("the safe call with A's own object: {e}"));
    assert_silent(&s.messages);
    let Layer::Names(siblings) = layer else {
        return;
    };
    s.messages.abort_on_error(true);
    let _ = call(true, true);
    s.messages.abort_on_error(false);
    let said = s.messages.take();
    assert!(
        said.iter()
            .any(|m| m.contains(rule) || siblings.iter().any(|r| m.contains(r))),
        "the layer did not name {rule}; it said {said:?}"
    );
}

fn color_range() -> vk::ImageSubresourceRange {
    vk::ImageSubresourceRange {
        aspect_mask: vk::ImageAspectFlags::COLOR,
        base_mip_level: 0,
        level_count: 1,
        base_array_layer: 0,
        layer_count: 1,
    }
}

/// A view's image, inside the create info.
#[test]
fn a_view_of_another_devices_image_is_refused() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let b = other_device(&s);
    let (mine, theirs) = (objects(&s, &s.device), objects(&s, &b));
    case(
        &s,
        "VUID-VkImageViewCreateInfo-image-parameter",
        // The 1.3.239 layer crashes on this call.
        Layer::Unusable,
        |foreign, unchecked| {
            let image = if foreign { &theirs.image } else { &mine.image };
            let info = tuff::ImageViewCreateInfo::new(image)
                .view_type(vk::ImageViewType::TYPE_2D)
                .format(vk::Format::R8G8B8A8_UNORM)
                .subresource_range(color_range());
            let r = match unchecked {
                true => unsafe { s.device.create_image_view_unchecked(&info) },
                false => s.device.create_image_view(&info),
            };
            r.map(drop)
        },
    );
}

/// A wrapper argument, checked before the special case's check that asks the driver
/// for the buffer's memory requirements.
#[test]
fn binding_another_devices_buffer_is_refused_before_the_driver_is_asked() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let b = other_device(&s);
    let memory = |d: &tuff::Device| {
        let buffer = d
            .create_buffer(
                &tuff::BufferCreateInfo::new()
                    .size(256)
                    .usage(vk::BufferUsageFlags::UNIFORM_BUFFER),
            )
            .expect("buffer");
        let reqs = d
            .get_buffer_memory_requirements(&buffer)
            .expect("requirements");
        let memory = d
            .allocate_memory(
                &tuff::MemoryAllocateInfo::new()
                    .allocation_size(reqs.size)
                    .memory_type_index(
                        s.memory_type(reqs.memory_type_bits, vk::MemoryPropertyFlags::empty()),
                    ),
            )
            .expect("memory");
        (buffer, memory)
    };
    let (_, mine) = memory(&s.device);
    let (theirs, _theirs_memory) = memory(&b);
    case(
        &s,
        "VUID-vkBindBufferMemory-buffer-parent",
        Layer::Names(&[]),
        |foreign, unchecked| {
            // A fresh buffer of A for each call A may bind.
            let own = memory(&s.device).0;
            let buffer = if foreign { &theirs } else { &own };
            match unchecked {
                true => unsafe { s.device.bind_buffer_memory_unchecked(buffer, &mine, 0) },
                false => s.device.bind_buffer_memory(buffer, &mine, 0),
            }
        },
    );
}

/// A descriptor's buffer, inside a struct inside the write.
#[test]
fn writing_another_devices_buffer_into_a_set_is_refused() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let b = other_device(&s);
    let (mine, theirs) = (objects(&s, &s.device), objects(&s, &b));
    let d = &s.device;
    let binding = [tuff::DescriptorSetLayoutBinding::new()
        .binding(0)
        .descriptor_type(vk::DescriptorType::UNIFORM_BUFFER)
        .descriptor_count(1)
        .stage_flags(vk::ShaderStageFlags::ALL)];
    let layout = d
        .create_descriptor_set_layout(
            &tuff::DescriptorSetLayoutCreateInfo::new().bindings(&binding),
        )
        .expect("layout");
    let sizes = [vk::DescriptorPoolSize {
        ty: vk::DescriptorType::UNIFORM_BUFFER,
        descriptor_count: 1,
    }];
    let pool = d
        .create_descriptor_pool(
            &tuff::DescriptorPoolCreateInfo::new()
                .max_sets(1)
                .pool_sizes(&sizes),
        )
        .expect("pool");
    let set = d
        .allocate_descriptor_sets(
            &pool,
            &tuff::DescriptorSetAllocateInfo::new(&pool).set_layouts(&layout),
        )
        .expect("set")
        .remove(0);
    case(
        &s,
        // The write's buffer infos are read only for a buffer descriptor: the
        // command's rule checks them there.
        "VUID-vkUpdateDescriptorSets-pDescriptorWrites-06237",
        // Under the 1.3.239 layer, this unchecked call crashes the process.
        Layer::Unusable,
        |foreign, unchecked| {
            let buffer = if foreign {
                &theirs.buffer
            } else {
                &mine.buffer
            };
            let info = [tuff::DescriptorBufferInfo::new()
                .buffer(Some(buffer))
                .offset(0)
                .range(vk::WHOLE_SIZE)];
            let write = tuff::WriteDescriptorSet::new(&set)
                .dst_binding(0)
                .descriptor_type(vk::DescriptorType::UNIFORM_BUFFER)
                .buffer_info(&info);
            match unchecked {
                true => {
                    unsafe { d.update_descriptor_sets_unchecked(&[write], &[]) };
                    Ok(())
                }
                false => d.update_descriptor_sets(&[write], &[]),
            }
        },
    );
}

/// A barrier's image, inside a struct of a slice argument of a recorded command.
#[test]
fn a_barrier_on_another_devices_image_is_refused() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let b = other_device(&s);
    let (mine, theirs) = (objects(&s, &s.device), objects(&s, &b));
    case(
        &s,
        "VUID-VkImageMemoryBarrier-image-parameter",
        // The 1.3.239 layer says nothing and passes the barrier to the driver.
        Layer::Unusable,
        |foreign, unchecked| {
            let image = if foreign { &theirs.image } else { &mine.image };
            let barrier = [tuff::ImageMemoryBarrier::new(image)
                .old_layout(vk::ImageLayout::UNDEFINED)
                .new_layout(vk::ImageLayout::TRANSFER_DST_OPTIMAL)
                .dst_access_mask(vk::AccessFlags::TRANSFER_WRITE)
                .src_queue_family_index(vk::QUEUE_FAMILY_IGNORED)
                .dst_queue_family_index(vk::QUEUE_FAMILY_IGNORED)
                .subresource_range(color_range())];
            let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
            let mut rec = cb
                .begin(&tuff::CommandBufferBeginInfo::new())
                .expect("begin");
            let (top, transfer) = (
                vk::PipelineStageFlags::TOP_OF_PIPE,
                vk::PipelineStageFlags::TRANSFER,
            );
            let no_flags = vk::DependencyFlags::empty();
            let r = unsafe {
                match unchecked {
                    true => {
                        rec.pipeline_barrier_unchecked(top, transfer, no_flags, &[], &[], &barrier)
                    }
                    false => rec.pipeline_barrier(top, transfer, no_flags, &[], &[], &barrier),
                }
            };
            // The refused barrier poisons the recording: its end reports the refusal.
            let ended = rec.end();
            r.and(ended.map(drop))
        },
    );
}

/// A batch's command buffer, inside the submit info.
#[test]
fn submitting_another_devices_command_buffer_is_refused() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let b = other_device(&s);
    let recorded = |d: &tuff::Device| {
        let pool = d
            .create_command_pool(&tuff::CommandPoolCreateInfo::new().queue_family_index(s.family))
            .expect("pool");
        let mut cb = d
            .allocate_command_buffers(
                &pool,
                &tuff::CommandBufferAllocateInfo::new(&pool)
                    .level(vk::CommandBufferLevel::PRIMARY)
                    .command_buffer_count(1),
            )
            .expect("command buffer")
            .remove(0);
        cb.begin(&tuff::CommandBufferBeginInfo::new())
            .expect("begin")
            .end()
            .expect("end");
        (pool, cb)
    };
    let (_theirs_pool, theirs) = recorded(&b);
    case(
        &s,
        "VUID-VkSubmitInfo-pCommandBuffers-parameter",
        Layer::Names(&["VUID-VkSubmitInfo-commonparent"]),
        |foreign, unchecked| {
            let (_own_pool, own) = recorded(&s.device);
            let cb = if foreign { &theirs } else { &own };
            let submit = [tuff::SubmitInfo::new().command_buffers(cb)];
            let r = match unchecked {
                true => unsafe { s.queue.submit_unchecked(&submit, None) },
                false => s.queue.submit(&submit, None),
            };
            s.queue.wait_idle().expect("idle");
            r
        },
    );
}

/// A set layout's immutable samplers, in an array inside a struct of the create info.
#[test]
fn immutable_samplers_of_another_device_are_refused() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let b = other_device(&s);
    let sampler = |d: &tuff::Device| {
        d.create_sampler(&tuff::SamplerCreateInfo::new())
            .expect("sampler")
    };
    let (mine, theirs) = (sampler(&s.device), sampler(&b));
    case(
        &s,
        "VUID-VkDescriptorSetLayoutBinding-descriptorType-00282",
        // The 1.3.239 layer says nothing and passes the call to the driver.
        Layer::Unusable,
        |foreign, unchecked| {
            let samplers = if foreign { &theirs } else { &mine };
            let binding = [tuff::DescriptorSetLayoutBinding::new()
                .binding(0)
                .descriptor_type(vk::DescriptorType::SAMPLER)
                .stage_flags(vk::ShaderStageFlags::FRAGMENT)
                .immutable_samplers(samplers)];
            let info = tuff::DescriptorSetLayoutCreateInfo::new().bindings(&binding);
            let r = match unchecked {
                true => unsafe { s.device.create_descriptor_set_layout_unchecked(&info) },
                false => s.device.create_descriptor_set_layout(&info),
            };
            r.map(drop)
        },
    );
}

/// A pipeline layout's set layouts, a handle array of the create info.
#[test]
fn a_pipeline_layout_of_another_devices_set_layout_is_refused() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let b = other_device(&s);
    let set_layout = |d: &tuff::Device| {
        d.create_descriptor_set_layout(&tuff::DescriptorSetLayoutCreateInfo::new())
            .expect("set layout")
    };
    let (mine, theirs) = (set_layout(&s.device), set_layout(&b));
    case(
        &s,
        "VUID-VkPipelineLayoutCreateInfo-pSetLayouts-parameter",
        // The 1.3.239 layer says nothing and passes the call to the driver.
        Layer::Unusable,
        |foreign, unchecked| {
            let layouts = if foreign { &theirs } else { &mine };
            let info = tuff::PipelineLayoutCreateInfo::new().set_layouts(layouts);
            let r = match unchecked {
                true => unsafe { s.device.create_pipeline_layout_unchecked(&info) },
                false => s.device.create_pipeline_layout(&info),
            };
            r.map(drop)
        },
    );
}

/// A framebuffer's attachments, a handle array Vulkan reads unless the framebuffer
/// is imageless: the create info's `commonparent` rule checks them.
#[test]
fn a_framebuffer_of_another_devices_view_is_refused() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let b = other_device(&s);
    let mine = s.color_target(4, vk::ImageUsageFlags::empty());
    let (theirs, _theirs_memory) = {
        let o = objects(&s, &b);
        let view = b
            .create_image_view(
                &tuff::ImageViewCreateInfo::new(&o.image)
                    .view_type(vk::ImageViewType::TYPE_2D)
                    .format(vk::Format::R8G8B8A8_UNORM)
                    .subresource_range(color_range()),
            )
            .expect("view");
        (view, o)
    };
    case(
        &s,
        "VUID-VkFramebufferCreateInfo-commonparent",
        Layer::Names(&[]),
        |foreign, unchecked| {
            let view = if foreign { &theirs } else { &mine.view };
            let info = tuff::FramebufferCreateInfo::new(&mine.render_pass)
                .attachments(view)
                .width(4)
                .height(4)
                .layers(1);
            let r = match unchecked {
                true => unsafe { s.device.create_framebuffer_unchecked(&info) },
                false => s.device.create_framebuffer(&info),
            };
            r.map(drop)
        },
    );
}

/// A copy's destination, a wrapper argument of a recorded command.
#[test]
fn a_copy_into_another_devices_buffer_is_refused() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let b = other_device(&s);
    let (src, mine, theirs) = (
        objects(&s, &s.device),
        objects(&s, &s.device),
        objects(&s, &b),
    );
    case(
        &s,
        "VUID-vkCmdCopyBuffer-commonparent",
        Layer::Names(&[]),
        |foreign, unchecked| {
            let dst = if foreign {
                &theirs.buffer
            } else {
                &mine.buffer
            };
            let region = [vk::BufferCopy {
                src_offset: 0,
                dst_offset: 0,
                size: 16,
            }];
            let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
            let mut rec = cb
                .begin(&tuff::CommandBufferBeginInfo::new())
                .expect("begin");
            let r = unsafe {
                match unchecked {
                    true => rec.copy_buffer_unchecked(&src.buffer, dst, &region),
                    false => rec.copy_buffer(&src.buffer, dst, &region),
                }
            };
            let ended = rec.end();
            r.and(ended.map(drop))
        },
    );
}
