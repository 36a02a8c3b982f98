//! Fixtures of the oracle for command-buffer begins, submits, shader modules,
//! pipeline caches, memory, descriptor set layouts, compute pipelines and the
//! depth/stencil parts of render passes. Each builds the smallest valid call,
//! lets the case change one value, and runs the safe method and, under the layer,
//! its `_unchecked` twin (or ash's, for `vkBeginCommandBuffer`, which tuff wraps
//! only checked).

use super::*;
use tuff::Handle;

/// The parameters of these fixtures' commands that their rules name.
pub mod args {
    /// `vkQueueSubmit2`: its rule names the device's feature only.
    pub struct QueueSubmit2;
    pub struct CmdSetDeviceMask {
        pub device_mask: u32,
    }
}

/// Begins a command buffer of `level` with `info`, through tuff and, under the
/// layer, through ash (tuff's `begin` has no unchecked twin).
fn begin(
    s: &Setup,
    level: vk::CommandBufferLevel,
    info: &tuff::CommandBufferBeginInfo<'_>,
) -> Outcome {
    let (_pool, mut cb) = s.command_buffer(level);
    let continuing = info
        .flags
        .contains(vk::CommandBufferUsageFlags::RENDER_PASS_CONTINUE);
    let safe = if continuing {
        cb.begin_continuing(info).and_then(|r| r.end())
    } else {
        cb.begin(info).and_then(|r| r.end())
    };
    let (_pool, cb) = s.command_buffer(level);
    let layer = under_layer(s, || {
        let d = s.device.fns();
        // SAFETY: as in `buffer_create_info`; the buffer is new, its pool is only
        // used here, and it is ended again before it is freed.
        if unsafe { d.begin_command_buffer(cb.raw(), info.as_raw()) }.is_ok() {
            let _ = unsafe { d.end_command_buffer(cb.raw()) };
        }
    });
    Outcome { safe, layer }
}

pub fn command_buffer_inheritance_info(
    s: &Setup,
    limits: &Limits,
    change: &dyn Fn(&mut vk::CommandBufferInheritanceInfo<'_>, &Limits, &mut Objects),
) -> Outcome {
    let mut inheritance = tuff::CommandBufferInheritanceInfo::new();
    // SAFETY: as in `buffer_create_info`.
    change(
        unsafe { inheritance.raw_values_mut() },
        limits,
        &mut Objects::default(),
    );
    let info = tuff::CommandBufferBeginInfo::new().inheritance_info(Some(&inheritance));
    begin(s, vk::CommandBufferLevel::SECONDARY, &info)
}

pub fn command_buffer_inheritance_rendering_info(
    s: &Setup,
    limits: &Limits,
    change: &dyn Fn(&mut vk::CommandBufferInheritanceRenderingInfo<'_>, &Limits, &mut Objects),
) -> Outcome {
    let formats = [vk::Format::R8G8B8A8_UNORM];
    let mut rendering = tuff::CommandBufferInheritanceRenderingInfo::new()
        .color_attachment_formats(&formats)
        .rasterization_samples(vk::SampleCountFlags::TYPE_1);
    // SAFETY: as in `buffer_create_info`.
    change(
        unsafe { rendering.raw_values_mut() },
        limits,
        &mut Objects::default(),
    );
    let inheritance = tuff::CommandBufferInheritanceInfo::new().push_next(&mut rendering);
    let info = tuff::CommandBufferBeginInfo::new()
        .flags(vk::CommandBufferUsageFlags::RENDER_PASS_CONTINUE)
        .inheritance_info(Some(&inheritance));
    begin(s, vk::CommandBufferLevel::SECONDARY, &info)
}

pub fn device_group_command_buffer_begin_info(
    s: &Setup,
    limits: &Limits,
    change: &dyn Fn(&mut vk::DeviceGroupCommandBufferBeginInfo<'_>, &Limits, &mut Objects),
) -> Outcome {
    let mut group = tuff::DeviceGroupCommandBufferBeginInfo::new().device_mask(1);
    // SAFETY: as in `buffer_create_info`.
    change(
        unsafe { group.raw_values_mut() },
        limits,
        &mut Objects::default(),
    );
    let info = tuff::CommandBufferBeginInfo::new().push_next(&mut group);
    begin(s, vk::CommandBufferLevel::PRIMARY, &info)
}

/// Submits `submits` through tuff and, under the layer, through the unchecked twin,
/// each with a fence of its own, and waits for the queue.
fn submit2(
    s: &Setup,
    safe: &[tuff::SubmitInfo2<'_>],
    unchecked: &[tuff::SubmitInfo2<'_>],
) -> Outcome {
    let fence = || {
        s.device
            .create_fence(&tuff::FenceCreateInfo::new())
            .expect("fence")
    };
    let (a, b) = (fence(), fence());
    let safe = s.queue.submit2(safe, Some(&a));
    // SAFETY: as in `buffer_create_info`; the queue is idle again before the
    // fences and semaphores are dropped.
    let layer = under_layer(s, || {
        let _ = unsafe { s.queue.submit2_unchecked(unchecked, Some(&b)) };
    });
    s.queue.wait_idle().expect("wait idle");
    Outcome { safe, layer }
}

pub fn queue_submit2(
    s: &Setup,
    limits: &Limits,
    change: &dyn Fn(&mut args::QueueSubmit2, &Limits, &mut Objects),
) -> Outcome {
    change(&mut args::QueueSubmit2, limits, &mut Objects::default());
    let submits = [tuff::SubmitInfo2::new()];
    submit2(s, &submits, &submits)
}

pub fn semaphore_submit_info(
    s: &Setup,
    limits: &Limits,
    change: &dyn Fn(&mut vk::SemaphoreSubmitInfo<'_>, &Limits, &mut Objects),
) -> Outcome {
    // Each submission signals a semaphore of its own: a binary semaphore is
    // signalled once.
    let semaphore = || {
        s.device
            .create_semaphore(&tuff::SemaphoreCreateInfo::new())
            .expect("semaphore")
    };
    let (a, b) = (semaphore(), semaphore());
    let signal = |semaphore| {
        let mut info = tuff::SemaphoreSubmitInfo::new(semaphore)
            .stage_mask(vk::PipelineStageFlags2::ALL_COMMANDS);
        // SAFETY: as in `buffer_create_info`.
        change(
            unsafe { info.raw_values_mut() },
            limits,
            &mut Objects::default(),
        );
        [info]
    };
    let (sa, sb) = (signal(&a), signal(&b));
    submit2(
        s,
        &[tuff::SubmitInfo2::new().signal_semaphore_infos(&sa)],
        &[tuff::SubmitInfo2::new().signal_semaphore_infos(&sb)],
    )
}

pub fn cmd_set_device_mask(
    s: &Setup,
    limits: &Limits,
    change: &dyn Fn(&mut args::CmdSetDeviceMask, &Limits, &mut Objects),
) -> Outcome {
    let mut a = args::CmdSetDeviceMask { device_mask: 1 };
    change(&mut a, limits, &mut Objects::default());
    let mask = a.device_mask;
    record(
        s,
        |r| r.set_device_mask(mask),
        // SAFETY: as in `buffer_create_info`; the command buffer is never submitted.
        |r| unsafe { r.set_device_mask_unchecked(mask) },
    )
}

pub fn device_group_render_pass_begin_info(
    s: &Setup,
    limits: &Limits,
    change: &dyn Fn(&mut vk::DeviceGroupRenderPassBeginInfo<'_>, &Limits, &mut Objects),
) -> Outcome {
    let target = s.color_target(4, vk::ImageUsageFlags::empty());
    let mut group = tuff::DeviceGroupRenderPassBeginInfo::new().device_mask(1);
    // SAFETY: as in `buffer_create_info`.
    change(
        unsafe { group.raw_values_mut() },
        limits,
        &mut Objects::default(),
    );
    let clear = [vk::ClearValue::default()];
    let info = tuff::RenderPassBeginInfo::new(&target.render_pass, &target.framebuffer)
        .render_area(vk::Rect2D {
            offset: vk::Offset2D::default(),
            extent: vk::Extent2D {
                width: 4,
                height: 4,
            },
        })
        .clear_values(&clear)
        .push_next(&mut group);
    let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let rec = cb
        .begin(&tuff::CommandBufferBeginInfo::new())
        .expect("begin");
    let safe = rec
        .begin_render_pass(&info, vk::SubpassContents::INLINE)
        .end_render_pass()
        .end();
    let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let rec = cb
        .begin(&tuff::CommandBufferBeginInfo::new())
        .expect("begin");
    let mut rec = Some(rec);
    let layer = under_layer(s, || {
        // SAFETY: as in `rendering`: never submitted, dropped unended.
        drop(unsafe {
            rec.take()
                .expect("recorder")
                .begin_render_pass_unchecked(&info, vk::SubpassContents::INLINE)
        });
    });
    Outcome { safe, layer }
}

pub fn shader_module_create_info(
    s: &Setup,
    limits: &Limits,
    change: &dyn Fn(&mut vk::ShaderModuleCreateInfo<'_>, &Limits, &mut Objects),
) -> Outcome {
    let words =
        tuff::spirv_words(include_bytes!("../../shaders/spv/test.comp.spv")).expect("words");
    let mut info = tuff::ShaderModuleCreateInfo::new().code(&words);
    // SAFETY: as in `buffer_create_info`.
    change(
        unsafe { info.raw_values_mut() },
        limits,
        &mut Objects::default(),
    );
    // The shader promise holds for the repository's test shader (see
    // `tuff_setup::shader`).
    create!(
        s,
        create_shader_module,
        create_shader_module_unchecked,
        &info
    )
}

pub fn pipeline_cache_create_info(
    s: &Setup,
    limits: &Limits,
    change: &dyn Fn(&mut vk::PipelineCacheCreateInfo<'_>, &Limits, &mut Objects),
) -> Outcome {
    let mut info = tuff::PipelineCacheCreateInfo::new();
    // SAFETY: as in `buffer_create_info`.
    change(
        unsafe { info.raw_values_mut() },
        limits,
        &mut Objects::default(),
    );
    create!(
        s,
        create_pipeline_cache,
        create_pipeline_cache_unchecked,
        &info
    )
}

pub fn memory_allocate_info(
    s: &Setup,
    limits: &Limits,
    change: &dyn Fn(&mut vk::MemoryAllocateInfo<'_>, &Limits, &mut Objects),
) -> Outcome {
    let mut info = tuff::MemoryAllocateInfo::new()
        .allocation_size(64)
        .memory_type_index(0);
    // SAFETY: as in `buffer_create_info`.
    change(
        unsafe { info.raw_values_mut() },
        limits,
        &mut Objects::default(),
    );
    create!(s, allocate_memory, allocate_memory_unchecked, &info)
}

pub fn descriptor_set_layout_binding(
    s: &Setup,
    limits: &Limits,
    change: &dyn Fn(&mut vk::DescriptorSetLayoutBinding<'_>, &Limits, &mut Objects),
) -> Outcome {
    // Four descriptors: an inline uniform block counts bytes, in multiples of 4.
    let mut binding = tuff::DescriptorSetLayoutBinding::new()
        .binding(0)
        .descriptor_type(vk::DescriptorType::UNIFORM_BUFFER)
        .descriptor_count(4)
        .stage_flags(vk::ShaderStageFlags::COMPUTE);
    // SAFETY: as in `buffer_create_info`.
    change(
        unsafe { binding.raw_values_mut() },
        limits,
        &mut Objects::default(),
    );
    let bindings = [binding];
    let info = tuff::DescriptorSetLayoutCreateInfo::new().bindings(&bindings);
    create!(
        s,
        create_descriptor_set_layout,
        create_descriptor_set_layout_unchecked,
        &info
    )
}

pub fn compute_pipeline_create_info(
    s: &Setup,
    limits: &Limits,
    change: &dyn Fn(&mut vk::ComputePipelineCreateInfo<'_>, &Limits, &mut Objects),
) -> Outcome {
    let target = s.color_target(4, vk::ImageUsageFlags::empty());
    let p = pipelines::pipelines(s, &target);
    let stage = tuff::PipelineShaderStageCreateInfo::new(c"main")
        .stage(vk::ShaderStageFlags::COMPUTE)
        .module(Some(&p.comp));
    let mut info = tuff::ComputePipelineCreateInfo::new(stage, &p.compute_layout);
    // SAFETY: as in `buffer_create_info`.
    change(
        unsafe { info.raw_values_mut() },
        limits,
        &mut Objects::default(),
    );
    let infos = [info];
    create!(
        s,
        create_compute_pipelines,
        create_compute_pipelines_unchecked,
        None,
        &infos
    )
}

/// A depth/stencil attachment of a render pass made through `vkCreateRenderPass2`,
/// with its separate stencil layouts chained, and the reference of its subpass
/// with the reference's stencil layout chained.
fn depth_stencil_pass<'a>(
    s: &Setup,
    description: &'a mut tuff::AttachmentDescriptionStencilLayout<'a>,
    reference: &'a mut tuff::AttachmentReferenceStencilLayout<'a>,
) -> Outcome {
    let attachments = [tuff::AttachmentDescription2::new()
        .format(vk::Format::D32_SFLOAT_S8_UINT)
        .samples(vk::SampleCountFlags::TYPE_1)
        .load_op(vk::AttachmentLoadOp::CLEAR)
        .store_op(vk::AttachmentStoreOp::STORE)
        .stencil_load_op(vk::AttachmentLoadOp::CLEAR)
        .stencil_store_op(vk::AttachmentStoreOp::STORE)
        .initial_layout(vk::ImageLayout::UNDEFINED)
        .final_layout(vk::ImageLayout::DEPTH_STENCIL_ATTACHMENT_OPTIMAL)
        .push_next(description)];
    let depth = tuff::AttachmentReference2::new()
        .attachment(0)
        .layout(vk::ImageLayout::DEPTH_STENCIL_ATTACHMENT_OPTIMAL)
        .aspect_mask(vk::ImageAspectFlags::DEPTH | vk::ImageAspectFlags::STENCIL)
        .push_next(reference);
    let subpasses = [tuff::SubpassDescription2::new()
        .pipeline_bind_point(vk::PipelineBindPoint::GRAPHICS)
        .depth_stencil_attachment(Some(&depth))];
    let info = tuff::RenderPassCreateInfo2::new()
        .attachments(&attachments)
        .subpasses(&subpasses);
    create!(s, create_render_pass2, create_render_pass2_unchecked, &info)
}

fn stencil_layouts() -> (
    tuff::AttachmentDescriptionStencilLayout<'static>,
    tuff::AttachmentReferenceStencilLayout<'static>,
) {
    (
        tuff::AttachmentDescriptionStencilLayout::new()
            .stencil_initial_layout(vk::ImageLayout::UNDEFINED)
            .stencil_final_layout(vk::ImageLayout::GENERAL),
        tuff::AttachmentReferenceStencilLayout::new().stencil_layout(vk::ImageLayout::GENERAL),
    )
}

pub fn attachment_description_stencil_layout(
    s: &Setup,
    limits: &Limits,
    change: &dyn Fn(&mut vk::AttachmentDescriptionStencilLayout<'_>, &Limits, &mut Objects),
) -> Outcome {
    let (mut description, mut reference) = stencil_layouts();
    // SAFETY: as in `buffer_create_info`.
    change(
        unsafe { description.raw_values_mut() },
        limits,
        &mut Objects::default(),
    );
    depth_stencil_pass(s, &mut description, &mut reference)
}

pub fn attachment_reference_stencil_layout(
    s: &Setup,
    limits: &Limits,
    change: &dyn Fn(&mut vk::AttachmentReferenceStencilLayout<'_>, &Limits, &mut Objects),
) -> Outcome {
    let (mut description, mut reference) = stencil_layouts();
    // SAFETY: as in `buffer_create_info`.
    change(
        unsafe { reference.raw_values_mut() },
        limits,
        &mut Objects::default(),
    );
    depth_stencil_pass(s, &mut description, &mut reference)
}

pub fn input_attachment_aspect_reference(
    s: &Setup,
    limits: &Limits,
    change: &dyn Fn(&mut vk::InputAttachmentAspectReference, &Limits, &mut Objects),
) -> Outcome {
    let mut reference = vk::InputAttachmentAspectReference {
        subpass: 0,
        input_attachment_index: 0,
        aspect_mask: vk::ImageAspectFlags::COLOR,
    };
    change(&mut reference, limits, &mut Objects::default());
    let references = [reference];
    let mut aspects =
        tuff::RenderPassInputAttachmentAspectCreateInfo::new().aspect_references(&references);
    // One color attachment, read as the subpass's only input attachment.
    let attachments = [vk::AttachmentDescription {
        format: vk::Format::R8G8B8A8_UNORM,
        samples: vk::SampleCountFlags::TYPE_1,
        load_op: vk::AttachmentLoadOp::LOAD,
        store_op: vk::AttachmentStoreOp::STORE,
        stencil_load_op: vk::AttachmentLoadOp::DONT_CARE,
        stencil_store_op: vk::AttachmentStoreOp::DONT_CARE,
        initial_layout: vk::ImageLayout::SHADER_READ_ONLY_OPTIMAL,
        final_layout: vk::ImageLayout::SHADER_READ_ONLY_OPTIMAL,
        ..Default::default()
    }];
    let input = [vk::AttachmentReference {
        attachment: 0,
        layout: vk::ImageLayout::SHADER_READ_ONLY_OPTIMAL,
    }];
    let subpasses = [tuff::SubpassDescription::new()
        .pipeline_bind_point(vk::PipelineBindPoint::GRAPHICS)
        .input_attachments(&input)];
    let info = tuff::RenderPassCreateInfo::new()
        .attachments(&attachments)
        .subpasses(&subpasses)
        .push_next(&mut aspects);
    create!(s, create_render_pass, create_render_pass_unchecked, &info)
}

pub fn image_stencil_usage_create_info(
    s: &Setup,
    limits: &Limits,
    change: &dyn Fn(&mut vk::ImageStencilUsageCreateInfo<'_>, &Limits, &mut Objects),
) -> Outcome {
    // A transient image: its stencil usage may (and must) be transient too.
    let transient =
        vk::ImageUsageFlags::DEPTH_STENCIL_ATTACHMENT | vk::ImageUsageFlags::TRANSIENT_ATTACHMENT;
    let mut stencil = tuff::ImageStencilUsageCreateInfo::new().stencil_usage(transient);
    // SAFETY: as in `buffer_create_info`.
    change(
        unsafe { stencil.raw_values_mut() },
        limits,
        &mut Objects::default(),
    );
    let info = tuff::ImageCreateInfo::new()
        .image_type(vk::ImageType::TYPE_2D)
        .format(vk::Format::D32_SFLOAT_S8_UINT)
        .extent(EXTENT)
        .mip_levels(1)
        .array_layers(1)
        .samples(vk::SampleCountFlags::TYPE_1)
        .usage(transient)
        .push_next(&mut stencil);
    create!(s, create_image, create_image_unchecked, &info)
}
