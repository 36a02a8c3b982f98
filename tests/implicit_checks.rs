//! The dynamic checks of implicit rules on lavapipe, with the validation layer on:
//! each misuse below is caught by the wrapper with the VUID of the rule it breaks,
//! before anything reaches the driver, so the layer hears nothing. The safe methods
//! run these checks in every build.
//!
//! SAFETY of the `unsafe` blocks around checked methods: such a method is `unsafe`
//! because it leaves rules to its caller (its `# Safety` section lists them). The
//! calls here keep every rule so listed and break, on purpose, only rules the method
//! checks; that one argument covers every such block in this file.

#[path = "common/tuff_setup.rs"]
mod tuff_setup;
#[path = "common/vulkan.rs"]
mod vulkan;

use tuff::vk;
use tuff_setup::{setup, vuid};
use vulkan::assert_silent;

#[test]
fn enum_and_flags_values_are_checked() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let d = &s.device;
    let bad_mode = tuff::BufferCreateInfo::new()
        .size(64)
        .usage(vk::BufferUsageFlags::UNIFORM_BUFFER)
        .sharing_mode(vk::SharingMode::from_raw(77));
    assert_eq!(
        vuid(d.create_buffer(&bad_mode)),
        "VUID-VkBufferCreateInfo-sharingMode-parameter"
    );
    let undefined_bit = tuff::BufferCreateInfo::new()
        .size(64)
        .usage(vk::BufferUsageFlags::from_raw(1 << 30));
    assert_eq!(
        vuid(d.create_buffer(&undefined_bit)),
        "VUID-VkBufferCreateInfo-usage-parameter"
    );
    // A bit of VK_EXT_transform_feedback, which this device did not enable, beside
    // a core bit: the core bits alone pass without looking up what is enabled, and
    // any other bit is still looked up.
    let extension_bit = tuff::BufferCreateInfo::new().size(64).usage(
        vk::BufferUsageFlags::UNIFORM_BUFFER | vk::BufferUsageFlags::TRANSFORM_FEEDBACK_BUFFER_EXT,
    );
    assert_eq!(
        vuid(d.create_buffer(&extension_bit)),
        "VUID-VkBufferCreateInfo-usage-parameter"
    );
    let no_usage = tuff::BufferCreateInfo::new().size(64);
    assert_eq!(
        vuid(d.create_buffer(&no_usage)),
        "VUID-VkBufferCreateInfo-usage-requiredbitmask"
    );
    // A format of VK_IMG_format_pvrtc, which this device did not enable.
    let image = tuff::ImageCreateInfo::new()
        .image_type(vk::ImageType::TYPE_2D)
        .format(vk::Format::from_raw(1_000_054_000))
        .extent(vk::Extent3D {
            width: 4,
            height: 4,
            depth: 1,
        })
        .mip_levels(1)
        .array_layers(1)
        .samples(vk::SampleCountFlags::TYPE_1)
        .usage(vk::ImageUsageFlags::SAMPLED);
    assert_eq!(
        vuid(d.create_image(&image)),
        "VUID-VkImageCreateInfo-format-parameter"
    );
    // The same info with a core format passes the checks and creates the image.
    let image = image.format(vk::Format::R8G8B8A8_UNORM);
    assert!(d.create_image(&image).is_ok());
    assert_silent(&s.messages);
}

#[test]
fn objects_of_another_device_are_refused() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let d = &s.device;
    let priorities = [1.0f32];
    let queues = [tuff::DeviceQueueCreateInfo::new()
        .queue_family_index(s.family)
        .queue_priorities(&priorities)];
    let other = d
        .parent()
        .create_device(&tuff::DeviceCreateInfo::new().queue_create_infos(&queues))
        .expect("second device");
    let buffer = d
        .create_buffer(
            &tuff::BufferCreateInfo::new()
                .size(256)
                .usage(vk::BufferUsageFlags::UNIFORM_BUFFER),
        )
        .expect("buffer");
    let foreign_memory = other
        .allocate_memory(
            &tuff::MemoryAllocateInfo::new()
                .allocation_size(256)
                .memory_type_index(0),
        )
        .expect("memory of the other device");
    assert_eq!(
        vuid(d.bind_buffer_memory(&buffer, &foreign_memory, 0)),
        "VUID-vkBindBufferMemory-memory-parent"
    );
    assert_eq!(
        vuid(other.get_buffer_memory_requirements(&buffer)),
        "VUID-vkGetBufferMemoryRequirements-buffer-parent"
    );
    // Two handles that must share a device: a queue of one and a fence of the other.
    let foreign_fence = other
        .create_fence(&tuff::FenceCreateInfo::new())
        .expect("fence of the other device");
    assert_eq!(
        vuid(s.queue.submit(&[], Some(&foreign_fence))),
        "VUID-vkQueueSubmit-commonparent"
    );
    assert_silent(&s.messages);
}

#[test]
fn counts_and_chains_are_checked() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let d = &s.device;
    assert_eq!(
        vuid(d.wait_for_fences(&tuff::HandleSlice::new(&[]), true, 0)),
        "VUID-vkWaitForFences-fenceCount-arraylength"
    );
    let priorities = [1.0f32];
    let queues = [tuff::DeviceQueueCreateInfo::new()
        .queue_family_index(s.family)
        .queue_priorities(&priorities)];
    let mut a = tuff::PhysicalDeviceVulkan13Features::new();
    let mut b = tuff::PhysicalDeviceVulkan13Features::new();
    let twice = tuff::DeviceCreateInfo::new()
        .queue_create_infos(&queues)
        .push_next(&mut a)
        .push_next(&mut b);
    assert_eq!(
        vuid(d.parent().create_device(&twice)),
        "VUID-VkDeviceCreateInfo-sType-unique"
    );
    assert_silent(&s.messages);
}

#[test]
fn a_primary_only_command_in_a_secondary_buffer_fails_at_end() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let target = s.color_target(16, vk::ImageUsageFlags::COLOR_ATTACHMENT);
    let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::SECONDARY);
    let inheritance = tuff::CommandBufferInheritanceInfo::new();
    let rec = cb
        .begin(&tuff::CommandBufferBeginInfo::new().inheritance_info(Some(&inheritance)))
        .expect("begin");
    let clear = [vk::ClearValue::default()];
    let begin = tuff::RenderPassBeginInfo::new(&target.render_pass, &target.framebuffer)
        .render_area(vk::Rect2D {
            offset: vk::Offset2D::default(),
            extent: vk::Extent2D {
                width: 16,
                height: 16,
            },
        })
        .clear_values(&clear);
    // Neither the begin nor the matching end reaches the driver.
    let rec = rec.begin_render_pass(&begin, vk::SubpassContents::INLINE);
    let rec = rec.end_render_pass();
    assert_eq!(vuid(rec.end()), "VUID-vkCmdBeginRenderPass-bufferlevel");
    assert!(!cb.is_executable());
    assert_silent(&s.messages);
}
