//! Shader modules, a graphics and a compute pipeline, and a descriptor update
//! template, made through the wrappers from the committed SPIR-V, and a recording
//! that uses them all: a draw into a color target and a dispatch whose output the
//! host can read back.
//!
//! SAFETY of the `unsafe` blocks around checked methods: such a method is `unsafe`
//! because it leaves rules to its caller (its `# Safety` section lists them). The
//! calls here keep every rule so listed and break, on purpose, only rules the method
//! checks; that one argument covers every such block in this file.
#![allow(dead_code)]

use crate::tuff_setup::{ColorTarget, Setup};
use tuff::vk;

/// The number of invocations the compute shader runs (one work group of 64).
pub const INVOCATIONS: u64 = 64;
/// The factor the compute shader multiplies each index by, read from a uniform buffer.
pub const FACTOR: u32 = 7;
/// The color the fragment shader writes, from a push constant.
pub const COLOR: [f32; 4] = [1.0, 0.5, 0.25, 1.0];

/// Everything the pipelines need, owned, so a test can drop them in any order.
pub struct Pipelines {
    pub vert: tuff::ShaderModule,
    pub frag: tuff::ShaderModule,
    pub comp: tuff::ShaderModule,
    pub graphics_layout: tuff::PipelineLayout,
    pub graphics: tuff::Pipeline,
    pub compute_set_layout: tuff::DescriptorSetLayout,
    pub compute_layout: tuff::PipelineLayout,
    pub compute: tuff::Pipeline,
    pub template: tuff::DescriptorUpdateTemplate,
    pub descriptor_pool: tuff::DescriptorPool,
    pub set: tuff::DescriptorSet,
    /// Holds the factor (host-visible).
    pub uniform: (tuff::Buffer, tuff::DeviceMemory),
    /// The compute shader's output (host-visible).
    pub output: (tuff::Buffer, tuff::DeviceMemory),
}

/// A host-visible buffer bound to its own memory.
pub fn host_buffer(
    s: &Setup,
    size: u64,
    usage: vk::BufferUsageFlags,
) -> (tuff::Buffer, tuff::DeviceMemory) {
    let d = &s.device;
    let buffer = d
        .create_buffer(&tuff::BufferCreateInfo::new().size(size).usage(usage))
        .expect("buffer");
    let reqs = d
        .get_buffer_memory_requirements(&buffer)
        .expect("memory requirements");
    let memory = d
        .allocate_memory(
            &tuff::MemoryAllocateInfo::new()
                .allocation_size(reqs.size)
                .memory_type_index(s.memory_type(
                    reqs.memory_type_bits,
                    vk::MemoryPropertyFlags::HOST_VISIBLE | vk::MemoryPropertyFlags::HOST_COHERENT,
                )),
        )
        .expect("memory");
    d.bind_buffer_memory(&buffer, &memory, 0).expect("bind");
    (buffer, memory)
}

/// Copies host-coherent memory out (`write == None`) or writes `write` into it, through
/// ash on the raw handles: the wrappers deref to them.
pub fn access_memory(
    s: &Setup,
    memory: &tuff::DeviceMemory,
    len: usize,
    write: Option<&[u8]>,
) -> Vec<u8> {
    let ash_device = s.device.fns();
    // SAFETY: the memory is host-visible and coherent, at least `len` bytes long, not
    // mapped elsewhere, and no submission that uses it is pending (callers wait on its
    // fence first); it is unmapped before returning.
    unsafe {
        let ptr = ash_device
            .map_memory(**memory, 0, len as u64, vk::MemoryMapFlags::empty())
            .expect("map") as *mut u8;
        if let Some(bytes) = write {
            std::ptr::copy_nonoverlapping(bytes.as_ptr(), ptr, bytes.len());
        }
        let out = std::slice::from_raw_parts(ptr, len).to_vec();
        ash_device.unmap_memory(**memory);
        out
    }
}

/// The test vertex and fragment shaders as the two stages of a pipeline.
pub fn test_stages<'a>(
    vert: &'a tuff::ShaderModule,
    frag: &'a tuff::ShaderModule,
) -> [tuff::PipelineShaderStageCreateInfo<'a>; 2] {
    [
        tuff::PipelineShaderStageCreateInfo::new(c"main")
            .stage(vk::ShaderStageFlags::VERTEX)
            .module(Some(vert)),
        tuff::PipelineShaderStageCreateInfo::new(c"main")
            .stage(vk::ShaderStageFlags::FRAGMENT)
            .module(Some(frag)),
    ]
}

/// Gives `f` the test graphics pipeline's create info over `stages`, `layout` and
/// subpass 0 of `render_pass`: triangles, no vertex input, no culling, a dynamic
/// viewport and scissor, and one color attachment written whole.
pub fn with_graphics_info<R>(
    stages: &[tuff::PipelineShaderStageCreateInfo<'_>],
    layout: &tuff::PipelineLayout,
    render_pass: &tuff::RenderPass,
    f: impl FnOnce(tuff::GraphicsPipelineCreateInfo<'_>) -> R,
) -> R {
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
    let multisample = tuff::PipelineMultisampleStateCreateInfo::new()
        .rasterization_samples(vk::SampleCountFlags::TYPE_1);
    let blend_attachments = [vk::PipelineColorBlendAttachmentState {
        color_write_mask: vk::ColorComponentFlags::RGBA,
        ..Default::default()
    }];
    let blend = tuff::PipelineColorBlendStateCreateInfo::new().attachments(&blend_attachments);
    let dynamic_states = [vk::DynamicState::VIEWPORT, vk::DynamicState::SCISSOR];
    let dynamic = tuff::PipelineDynamicStateCreateInfo::new().dynamic_states(&dynamic_states);
    f(tuff::GraphicsPipelineCreateInfo::new()
        .stages(stages)
        .vertex_input_state(Some(&vertex_input))
        .input_assembly_state(Some(&assembly))
        .viewport_state(Some(&viewport))
        .rasterization_state(Some(&raster))
        .multisample_state(Some(&multisample))
        .color_blend_state(Some(&blend))
        .dynamic_state(Some(&dynamic))
        .layout(Some(layout))
        .render_pass(Some(render_pass))
        .subpass(0))
}

/// A pipeline of the triangle shaders for subpass 0 of `render_pass` (the test
/// pipeline's state otherwise), whose vertex shader reads two attributes of binding
/// 0's 20-byte vertices: a vec2 at 0 and a vec3 at 8, so a vertex reaches 20 bytes.
pub fn vertex_pipeline(
    s: &Setup,
    layout: &tuff::PipelineLayout,
    render_pass: &tuff::RenderPass,
) -> tuff::Pipeline {
    let dynamic = [vk::DynamicState::VIEWPORT, vk::DynamicState::SCISSOR];
    vertex_pipeline_with(s, layout, render_pass, &dynamic)
}

/// [`vertex_pipeline`] with `dynamic` as its dynamic states.
#[allow(dead_code)]
pub fn vertex_pipeline_with(
    s: &Setup,
    layout: &tuff::PipelineLayout,
    render_pass: &tuff::RenderPass,
    dynamic: &[vk::DynamicState],
) -> tuff::Pipeline {
    let dynamic = tuff::PipelineDynamicStateCreateInfo::new().dynamic_states(dynamic);
    let module = |bytes| crate::tuff_setup::shader(s, bytes);
    let vert = module(include_bytes!("../../shaders/spv/triangle.vert.spv"));
    let frag = module(include_bytes!("../../shaders/spv/triangle.frag.spv"));
    let stages = test_stages(&vert, &frag);
    let binding = [vk::VertexInputBindingDescription {
        binding: 0,
        stride: 20,
        input_rate: vk::VertexInputRate::VERTEX,
    }];
    let attributes = [
        vk::VertexInputAttributeDescription {
            location: 0,
            binding: 0,
            format: vk::Format::R32G32_SFLOAT,
            offset: 0,
        },
        vk::VertexInputAttributeDescription {
            location: 1,
            binding: 0,
            format: vk::Format::R32G32B32_SFLOAT,
            offset: 8,
        },
    ];
    let input = tuff::PipelineVertexInputStateCreateInfo::new()
        .vertex_binding_descriptions(&binding)
        .vertex_attribute_descriptions(&attributes);
    let (mut made, _) = with_graphics_info(&stages, layout, render_pass, |info| {
        let info = info
            .vertex_input_state(Some(&input))
            .dynamic_state(Some(&dynamic));
        s.device.create_graphics_pipelines(None, &[info])
    })
    .expect("vertex pipeline");
    made.pop().expect("one pipeline")
}

/// Builds both pipelines for `target`'s render pass, and points the compute shader's
/// descriptor set at its buffers through a descriptor update template.
pub fn pipelines(s: &Setup, target: &ColorTarget) -> Pipelines {
    let d = &s.device;
    let module = |bytes: &[u8]| super::tuff_setup::shader(s, bytes);
    let vert = module(include_bytes!("../../shaders/spv/test.vert.spv"));
    let frag = module(include_bytes!("../../shaders/spv/test.frag.spv"));
    let comp = module(include_bytes!("../../shaders/spv/test.comp.spv"));

    let push = [vk::PushConstantRange {
        stage_flags: vk::ShaderStageFlags::FRAGMENT,
        offset: 0,
        size: 16,
    }];
    let graphics_layout = d
        .create_pipeline_layout(&tuff::PipelineLayoutCreateInfo::new().push_constant_ranges(&push))
        .expect("graphics layout");
    let stages = test_stages(&vert, &frag);
    // The one-object forms of the array commands (`create_graphics_pipeline`, ...).
    let graphics = with_graphics_info(&stages, &graphics_layout, &target.render_pass, |info| {
        d.create_graphics_pipeline(None, &info)
    })
    .expect("graphics pipeline");

    let bindings = [
        tuff::DescriptorSetLayoutBinding::new()
            .binding(0)
            .descriptor_type(vk::DescriptorType::UNIFORM_BUFFER)
            .descriptor_count(1)
            .stage_flags(vk::ShaderStageFlags::COMPUTE),
        tuff::DescriptorSetLayoutBinding::new()
            .binding(1)
            .descriptor_type(vk::DescriptorType::STORAGE_BUFFER)
            .descriptor_count(1)
            .stage_flags(vk::ShaderStageFlags::COMPUTE),
    ];
    let compute_set_layout = d
        .create_descriptor_set_layout(
            &tuff::DescriptorSetLayoutCreateInfo::new().bindings(&bindings),
        )
        .expect("compute set layout");
    let set_layouts = tuff::HandleSlice::new(&[&compute_set_layout]);
    let compute_layout = d
        .create_pipeline_layout(&tuff::PipelineLayoutCreateInfo::new().set_layouts(&set_layouts))
        .expect("compute layout");
    let stage = tuff::PipelineShaderStageCreateInfo::new(c"main")
        .stage(vk::ShaderStageFlags::COMPUTE)
        .module(Some(&comp));
    let compute = d
        .create_compute_pipeline(
            None,
            &tuff::ComputePipelineCreateInfo::new(stage, &compute_layout),
        )
        .expect("compute pipeline");

    let sizes = [
        vk::DescriptorPoolSize {
            ty: vk::DescriptorType::UNIFORM_BUFFER,
            descriptor_count: 1,
        },
        vk::DescriptorPoolSize {
            ty: vk::DescriptorType::STORAGE_BUFFER,
            descriptor_count: 1,
        },
    ];
    let descriptor_pool = d
        .create_descriptor_pool(
            &tuff::DescriptorPoolCreateInfo::new()
                .max_sets(1)
                .pool_sizes(&sizes),
        )
        .expect("descriptor pool");
    let set = d
        .allocate_descriptor_set(&descriptor_pool, &compute_set_layout)
        .expect("descriptor set");
    let uniform = host_buffer(s, 256, vk::BufferUsageFlags::UNIFORM_BUFFER);
    access_memory(s, &uniform.1, 4, Some(&FACTOR.to_le_bytes()));
    let output = host_buffer(s, INVOCATIONS * 4, vk::BufferUsageFlags::STORAGE_BUFFER);

    // The template reads two VkDescriptorBufferInfo, one per binding, from an array.
    let stride = std::mem::size_of::<vk::DescriptorBufferInfo>();
    let entries = [
        vk::DescriptorUpdateTemplateEntry {
            dst_binding: 0,
            dst_array_element: 0,
            descriptor_count: 1,
            descriptor_type: vk::DescriptorType::UNIFORM_BUFFER,
            offset: 0,
            stride,
        },
        vk::DescriptorUpdateTemplateEntry {
            dst_binding: 1,
            dst_array_element: 0,
            descriptor_count: 1,
            descriptor_type: vk::DescriptorType::STORAGE_BUFFER,
            offset: stride,
            stride,
        },
    ];
    let template = d
        .create_descriptor_update_template(
            &tuff::DescriptorUpdateTemplateCreateInfo::new(&compute_set_layout, &compute_layout)
                .template_type(vk::DescriptorUpdateTemplateType::DESCRIPTOR_SET)
                .descriptor_update_entries(&entries),
        )
        .expect("descriptor update template");
    let data = [
        vk::DescriptorBufferInfo {
            buffer: *uniform.0,
            offset: 0,
            range: vk::WHOLE_SIZE,
        },
        vk::DescriptorBufferInfo {
            buffer: *output.0,
            offset: 0,
            range: vk::WHOLE_SIZE,
        },
    ];
    // SAFETY: `data` is laid out as the template's entries say (two buffer infos at
    // offsets 0 and `stride`), names live buffers of the right usage, and outlives
    // the call.
    unsafe { d.update_descriptor_set_with_template(&set, &template, data.as_ptr().cast()) }
        .expect("update with template");

    Pipelines {
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
    }
}

impl Pipelines {
    /// Records a draw that fills `target` (of `size` pixels square) with [`COLOR`],
    /// copies its first pixel into `readback` (when given), and a dispatch that writes
    /// `i * FACTOR` into the output buffer.
    pub fn record<'c>(
        &self,
        rec: tuff::Recorder<'c, tuff::Outside>,
        target: &ColorTarget,
        size: u32,
        readback: Option<&tuff::Buffer>,
    ) -> tuff::Recorder<'c, tuff::Outside> {
        let clear = [vk::ClearValue::default()];
        let area = vk::Rect2D {
            offset: vk::Offset2D::default(),
            extent: vk::Extent2D {
                width: size,
                height: size,
            },
        };
        let mut rec = rec.begin_render_pass(
            &tuff::RenderPassBeginInfo::new(&target.render_pass, &target.framebuffer)
                .render_area(area)
                .clear_values(&clear),
            vk::SubpassContents::INLINE,
        );
        rec.bind_pipeline(vk::PipelineBindPoint::GRAPHICS, &self.graphics)
            .expect("recorded");
        rec.set_viewport(
            0,
            &[vk::Viewport {
                x: 0.0,
                y: 0.0,
                width: size as f32,
                height: size as f32,
                min_depth: 0.0,
                max_depth: 1.0,
            }],
        )
        .expect("recorded");
        rec.set_scissor(0, &[area]).expect("recorded");
        let color: Vec<u8> = COLOR.iter().flat_map(|c| c.to_le_bytes()).collect();
        rec.push_constants(
            &self.graphics_layout,
            vk::ShaderStageFlags::FRAGMENT,
            0,
            &color,
        )
        .expect("recorded");
        rec.draw(3, 1, 0, 0).expect("recorded");
        let mut rec = rec.end_render_pass();
        if let Some(buffer) = readback {
            let to_transfer = [tuff::ImageMemoryBarrier::new(&target.image)
                .src_access_mask(vk::AccessFlags::COLOR_ATTACHMENT_WRITE)
                .dst_access_mask(vk::AccessFlags::TRANSFER_READ)
                .old_layout(vk::ImageLayout::COLOR_ATTACHMENT_OPTIMAL)
                .new_layout(vk::ImageLayout::TRANSFER_SRC_OPTIMAL)
                .src_queue_family_index(vk::QUEUE_FAMILY_IGNORED)
                .dst_queue_family_index(vk::QUEUE_FAMILY_IGNORED)
                .subresource_range(vk::ImageSubresourceRange {
                    aspect_mask: vk::ImageAspectFlags::COLOR,
                    base_mip_level: 0,
                    level_count: 1,
                    base_array_layer: 0,
                    layer_count: 1,
                })];
            rec.pipeline_barrier(
                vk::PipelineStageFlags::COLOR_ATTACHMENT_OUTPUT,
                vk::PipelineStageFlags::TRANSFER,
                vk::DependencyFlags::empty(),
                &[],
                &[],
                &to_transfer,
            )
            .expect("recorded");
            rec.copy_image_to_buffer(
                &target.image,
                vk::ImageLayout::TRANSFER_SRC_OPTIMAL,
                buffer,
                &[vk::BufferImageCopy {
                    image_subresource: vk::ImageSubresourceLayers {
                        aspect_mask: vk::ImageAspectFlags::COLOR,
                        mip_level: 0,
                        base_array_layer: 0,
                        layer_count: 1,
                    },
                    image_extent: vk::Extent3D {
                        width: 1,
                        height: 1,
                        depth: 1,
                    },
                    ..Default::default()
                }],
            )
            .expect("recorded");
        }
        rec.bind_pipeline(vk::PipelineBindPoint::COMPUTE, &self.compute)
            .expect("recorded");
        rec.bind_descriptor_sets(
            vk::PipelineBindPoint::COMPUTE,
            &self.compute_layout,
            0,
            &self.set,
            &[],
        )
        .expect("recorded");
        rec.dispatch(1, 1, 1).expect("recorded");
        rec
    }
}

/// A descriptor set of one binding, with its layout and pool.
pub struct OneSet {
    pub set: tuff::DescriptorSet,
    pub pool: tuff::DescriptorPool,
    pub layout: tuff::DescriptorSetLayout,
}

/// A set of one uniform-buffer binding that the compute stage reads.
pub fn uniform_set(s: &Setup) -> OneSet {
    one_set(
        s,
        vk::DescriptorType::UNIFORM_BUFFER,
        vk::ShaderStageFlags::COMPUTE,
    )
}

/// A set of one descriptor of type `ty` at binding 0, visible to `stages`.
pub fn one_set(s: &Setup, ty: vk::DescriptorType, stages: vk::ShaderStageFlags) -> OneSet {
    let d = &s.device;
    let bindings = [tuff::DescriptorSetLayoutBinding::new()
        .binding(0)
        .descriptor_type(ty)
        .descriptor_count(1)
        .stage_flags(stages)];
    let layout = d
        .create_descriptor_set_layout(
            &tuff::DescriptorSetLayoutCreateInfo::new().bindings(&bindings),
        )
        .expect("set layout");
    let sizes = [vk::DescriptorPoolSize {
        ty,
        descriptor_count: 1,
    }];
    let pool = d
        .create_descriptor_pool(
            &tuff::DescriptorPoolCreateInfo::new()
                .max_sets(1)
                .pool_sizes(&sizes),
        )
        .expect("descriptor pool");
    let set = d
        .allocate_descriptor_sets(
            &pool,
            &tuff::DescriptorSetAllocateInfo::new(&pool).set_layouts(&layout),
        )
        .expect("descriptor set")
        .pop()
        .expect("one set");
    OneSet { set, pool, layout }
}

/// A storage image of 4x4 RGBA8 with storage and transfer-destination usage and
/// `usage` as well, its memory and a 2D view of it.
pub fn storage_image(
    s: &Setup,
    usage: vk::ImageUsageFlags,
) -> (tuff::Image, tuff::DeviceMemory, tuff::ImageView) {
    storage_image_of(s, vk::Format::R8G8B8A8_UNORM, usage)
}

/// [`storage_image`] of `format`.
pub fn storage_image_of(
    s: &Setup,
    format: vk::Format,
    usage: vk::ImageUsageFlags,
) -> (tuff::Image, tuff::DeviceMemory, tuff::ImageView) {
    let d = &s.device;
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
                .usage(vk::ImageUsageFlags::STORAGE | vk::ImageUsageFlags::TRANSFER_DST | usage),
        )
        .expect("image");
    let memory = s.bind_image(&image);
    let view = d
        .create_image_view(
            &tuff::ImageViewCreateInfo::new(&image)
                .view_type(vk::ImageViewType::TYPE_2D)
                .format(format)
                .subresource_range(vk::ImageSubresourceRange {
                    aspect_mask: vk::ImageAspectFlags::COLOR,
                    base_mip_level: 0,
                    level_count: 1,
                    base_array_layer: 0,
                    layer_count: 1,
                }),
        )
        .expect("view");
    (image, memory, view)
}

/// Pushes the test fragment shader's color (16 bytes) with the test graphics layout,
/// which draws with the test graphics pipeline need.
pub fn push_color<S: tuff::State>(rec: &mut tuff::Recorder<'_, S>, p: &Pipelines) {
    rec.push_constants(
        &p.graphics_layout,
        vk::ShaderStageFlags::FRAGMENT,
        0,
        &[0u8; 16],
    )
    .expect("push constants");
}
