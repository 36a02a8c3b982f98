//! The graphics pipeline state the scenes share, with what differs between them
//! as fields.

use crate::gpu::Gpu;
use anyhow::{Context as _, Result};
use tuff::vk;

/// What differs between the scenes' pipelines.
pub struct PipelineDesc<'a> {
    /// Shader stages, each with its module (entry point `main`).
    pub stages: &'a [(vk::ShaderStageFlags, &'a tuff::ShaderModule)],
    /// Vertex buffer bindings.
    pub bindings: &'a [vk::VertexInputBindingDescription],
    /// Vertex attributes.
    pub attributes: &'a [vk::VertexInputAttributeDescription],
    /// Primitive topology.
    pub topology: vk::PrimitiveTopology,
    /// Control points per patch, for a PATCH_LIST topology; 0 otherwise.
    pub patch_control_points: u32,
    /// FILL, or LINE for wireframe (which needs `fillModeNonSolid`).
    pub polygon_mode: vk::PolygonMode,
    /// Reversed-Z depth test and write.
    pub depth: bool,
    /// The subpass of the render pass it is made for.
    pub subpass: u32,
    /// How many color attachments it writes (all of their channels, no blending).
    pub colors: u32,
}

/// A graphics pipeline for a subpass of `render_pass`, with dynamic viewport and
/// scissor (so a resize needs no new pipeline) and no culling (the teapot is not a
/// closed surface).
pub fn graphics(
    gpu: &Gpu,
    layout: &tuff::PipelineLayout,
    render_pass: &tuff::RenderPass,
    desc: &PipelineDesc<'_>,
) -> Result<tuff::Pipeline> {
    let stages: Vec<_> = desc
        .stages
        .iter()
        .map(|(stage, module)| {
            tuff::PipelineShaderStageCreateInfo::new(c"main")
                .stage(*stage)
                .module(Some(module))
        })
        .collect();
    let vertex_input = tuff::PipelineVertexInputStateCreateInfo::new()
        .vertex_binding_descriptions(desc.bindings)
        .vertex_attribute_descriptions(desc.attributes);
    let assembly = tuff::PipelineInputAssemblyStateCreateInfo::new().topology(desc.topology);
    let tessellation = tuff::PipelineTessellationStateCreateInfo::new()
        .patch_control_points(desc.patch_control_points);
    let viewport = tuff::PipelineViewportStateCreateInfo::new()
        .viewport_count(1)
        .scissor_count(1);
    let raster = tuff::PipelineRasterizationStateCreateInfo::new()
        .polygon_mode(desc.polygon_mode)
        .cull_mode(vk::CullModeFlags::NONE)
        .front_face(vk::FrontFace::COUNTER_CLOCKWISE)
        .line_width(1.0);
    let multisample = tuff::PipelineMultisampleStateCreateInfo::new()
        .rasterization_samples(vk::SampleCountFlags::TYPE_1);
    let depth = tuff::PipelineDepthStencilStateCreateInfo::new()
        .depth_test_enable(true)
        .depth_write_enable(true)
        // Reversed Z: nearer is greater.
        .depth_compare_op(vk::CompareOp::GREATER);
    let blend_attachments = vec![
        vk::PipelineColorBlendAttachmentState {
            color_write_mask: vk::ColorComponentFlags::RGBA,
            ..Default::default()
        };
        desc.colors as usize
    ];
    let blend = tuff::PipelineColorBlendStateCreateInfo::new().attachments(&blend_attachments);
    let dynamic_states = [vk::DynamicState::VIEWPORT, vk::DynamicState::SCISSOR];
    let dynamic = tuff::PipelineDynamicStateCreateInfo::new().dynamic_states(&dynamic_states);
    let mut info = tuff::GraphicsPipelineCreateInfo::new()
        .stages(&stages)
        .vertex_input_state(Some(&vertex_input))
        .input_assembly_state(Some(&assembly))
        .viewport_state(Some(&viewport))
        .rasterization_state(Some(&raster))
        .multisample_state(Some(&multisample))
        .color_blend_state(Some(&blend))
        .dynamic_state(Some(&dynamic))
        .layout(Some(layout))
        .render_pass(Some(render_pass))
        .subpass(desc.subpass);
    if desc.patch_control_points > 0 {
        info = info.tessellation_state(Some(&tessellation));
    }
    if desc.depth {
        info = info.depth_stencil_state(Some(&depth));
    }
    let (mut pipelines, _) = gpu.device.create_graphics_pipelines(None, &[info])?;
    pipelines.pop().context("no pipeline was created")
}

/// A pipeline layout with `set_layouts` and one push-constant range of `push_size`
/// bytes (none when 0) visible to `push_stages`.
pub fn layout(
    gpu: &Gpu,
    set_layouts: &[&tuff::DescriptorSetLayout],
    push_stages: vk::ShaderStageFlags,
    push_size: u32,
) -> Result<tuff::PipelineLayout> {
    let push = [vk::PushConstantRange {
        stage_flags: push_stages,
        offset: 0,
        size: push_size,
    }];
    let sets = tuff::HandleSlice::new(set_layouts);
    let mut info = tuff::PipelineLayoutCreateInfo::new().set_layouts(&sets);
    if push_size > 0 {
        info = info.push_constant_ranges(&push);
    }
    Ok(gpu.device.create_pipeline_layout(&info)?)
}
