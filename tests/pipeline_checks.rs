//! Graphics pipeline creation: the pipeline's state as a whole is checked
//! (derivatives, its stages and topology, the state structs it must have, what its
//! subpass or its dynamic rendering formats render to, and fixed-function values
//! that need a feature).
//!
//! Each case changes one valid pipeline so that it breaks one rule. tuff must refuse
//! the safe call with the rule's VUID; the validation layer, for the `_unchecked`
//! twin (with a messenger that makes it skip a call it finds wrong), must name that
//! VUID and nothing else but the rules the case says the same change breaks, or say
//! nothing (the rule is then proven by the error alone).
//!
//! SAFETY of the `unsafe` blocks: the `_unchecked` twins check nothing; these
//! pipelines keep every rule but the one each case breaks on purpose, which the
//! layer, told to skip a call it reports, skips. The shaders are the repository's
//! (see `tuff_setup::shader`).

#[path = "common/tuff_setup.rs"]
mod tuff_setup;
#[path = "common/vulkan.rs"]
mod vulkan;

use tuff::vk;
use tuff::Handle as _;
use tuff_setup::Setup;

const RGBA8: vk::Format = vk::Format::R8G8B8A8_UNORM;
const D32S8: vk::Format = vk::Format::D32_SFLOAT_S8_UINT;

/// A required subgroup size.
#[derive(Clone, Copy)]
enum SubgroupSize {
    /// This size.
    Of(u32),
    /// The device's `minSubgroupSize`, a valid size.
    DeviceMin,
}

/// What a pipeline renders to.
#[derive(Clone)]
enum Target {
    /// Subpass `subpass` of a render pass of one subpass with these color
    /// attachments and depth/stencil attachment.
    Pass {
        colors: Vec<vk::Format>,
        depth: Option<vk::Format>,
        subpass: u32,
    },
    /// Dynamic rendering with a chained `VkPipelineRenderingCreateInfo`.
    Rendering {
        view_mask: u32,
        colors: Vec<vk::Format>,
        depth: vk::Format,
        stencil: vk::Format,
    },
}

/// A graphics pipeline, in parts a case can change.
#[derive(Clone)]
struct Parts {
    flags: vk::PipelineCreateFlags,
    /// Name the base pipeline by handle (a pipeline made for it).
    base_handle: bool,
    /// Whether that base pipeline allows derivatives.
    base_allows: bool,
    base_index: i32,
    /// The stages, each with the repository's shader of that stage: the test
    /// shaders, or the Bézier ones for a pipeline with tessellation.
    stages: Vec<vk::ShaderStageFlags>,
    bezier: bool,
    vertex_input: bool,
    topology: Option<vk::PrimitiveTopology>,
    tessellation: bool,
    viewport_counts: Option<(u32, u32)>,
    /// Each static scissor.
    scissor: vk::Rect2D,
    raster: bool,
    discard: bool,
    line_width: f32,
    depth_bias: Option<f32>,
    multisample: bool,
    /// The multisample state's rasterization samples.
    samples: vk::SampleCountFlags,
    depth_stencil: Option<(bool, f32, f32)>,
    /// Each color blend attachment's `blendEnable`; `None` for no blend state.
    blend: Option<Vec<bool>>,
    dynamic: Vec<vk::DynamicState>,
    layout: bool,
    target: Target,
    /// The input assembly's primitive restart.
    restart: bool,
    patch_points: u32,
    min_sample_shading: f32,
    /// Vertex binding numbers and attribute (location, binding) pairs, and the
    /// attributes' format.
    bindings: Vec<u32>,
    attributes: Vec<(u32, u32)>,
    attribute_format: vk::Format,
    /// A logic operation, enabled, for the blend state.
    logic_op: Option<vk::LogicOp>,
    /// Specialization constant IDs of the first stage.
    constants: Vec<u32>,
    /// The bytes each map entry gives its constant.
    constant_size: usize,
    /// The vertex stage runs `spec.vert`, which declares a boolean specialization
    /// constant 0, instead of the test shader.
    spec_vertex: bool,
    /// The geometry stage does not write the point size.
    unsized_geometry: bool,
    /// The fragment stage reads PrimitiveId (`prim.frag`).
    primitive_fragment: bool,
    /// Stages that run one of [`Common::named`]'s shaders instead, by file name.
    named: Vec<(vk::ShaderStageFlags, &'static str)>,
    /// The render pass's depth/stencil attachment is the subpass's input attachment
    /// 0 instead, with these aspects chained (none: no aspect info), and the
    /// fragment stage reads it through `input_depth.frag` with the input layout.
    input_aspect: Option<vk::ImageAspectFlags>,
    /// The first stage's flags and entry point name.
    stage_flags: vk::PipelineShaderStageCreateFlags,
    entry: &'static core::ffi::CStr,
    /// A required subgroup size chained to the first stage.
    subgroup_size: Option<SubgroupSize>,
    /// A creation feedback info chained to the pipeline, with the feedback struct
    /// its constructor requires.
    feedback: bool,
}

impl Default for Parts {
    fn default() -> Self {
        Parts {
            flags: vk::PipelineCreateFlags::empty(),
            base_handle: false,
            base_allows: true,
            base_index: -1,
            stages: vec![vk::ShaderStageFlags::VERTEX, vk::ShaderStageFlags::FRAGMENT],
            bezier: false,
            vertex_input: true,
            topology: Some(vk::PrimitiveTopology::TRIANGLE_LIST),
            tessellation: false,
            viewport_counts: Some((1, 1)),
            scissor: vk::Rect2D {
                offset: vk::Offset2D::default(),
                extent: vk::Extent2D {
                    width: 4,
                    height: 4,
                },
            },
            raster: true,
            discard: false,
            line_width: 1.0,
            depth_bias: None,
            multisample: true,
            samples: vk::SampleCountFlags::TYPE_1,
            depth_stencil: None,
            blend: Some(vec![false]),
            dynamic: vec![vk::DynamicState::VIEWPORT, vk::DynamicState::SCISSOR],
            layout: true,
            target: Target::Pass {
                colors: vec![RGBA8],
                depth: None,
                subpass: 0,
            },
            restart: false,
            patch_points: 16,
            min_sample_shading: 0.0,
            bindings: vec![],
            attributes: vec![],
            attribute_format: vk::Format::R32G32B32A32_SFLOAT,
            logic_op: None,
            constants: vec![],
            constant_size: 4,
            spec_vertex: false,
            unsized_geometry: false,
            primitive_fragment: false,
            named: vec![],
            input_aspect: None,
            stage_flags: vk::PipelineShaderStageCreateFlags::empty(),
            entry: c"main",
            subgroup_size: None,
            feedback: false,
        }
    }
}

impl Parts {
    /// The parts of a pipeline of points through a geometry stage (on a device that
    /// has the feature).
    fn through_geometry() -> Parts {
        Parts {
            stages: vec![
                vk::ShaderStageFlags::VERTEX,
                vk::ShaderStageFlags::GEOMETRY,
                vk::ShaderStageFlags::FRAGMENT,
            ],
            topology: Some(vk::PrimitiveTopology::POINT_LIST),
            ..Parts::default()
        }
    }

    /// The parts of a pipeline with tessellation (on a device that has the feature).
    fn tessellated() -> Parts {
        Parts {
            stages: vec![
                vk::ShaderStageFlags::VERTEX,
                vk::ShaderStageFlags::TESSELLATION_CONTROL,
                vk::ShaderStageFlags::TESSELLATION_EVALUATION,
                vk::ShaderStageFlags::FRAGMENT,
            ],
            bezier: true,
            topology: Some(vk::PrimitiveTopology::PATCH_LIST),
            tessellation: true,
            ..Parts::default()
        }
    }
}

/// A render pass of one subpass that writes these attachments; with `input`, the
/// depth/stencil one is its input attachment 0 instead, with those aspects chained
/// unless empty.
fn render_pass(
    s: &Setup,
    colors: &[vk::Format],
    depth: Option<vk::Format>,
    input: Option<vk::ImageAspectFlags>,
) -> tuff::RenderPass {
    let description = |format, layout| vk::AttachmentDescription {
        format,
        samples: vk::SampleCountFlags::TYPE_1,
        load_op: vk::AttachmentLoadOp::DONT_CARE,
        store_op: vk::AttachmentStoreOp::STORE,
        stencil_load_op: vk::AttachmentLoadOp::DONT_CARE,
        stencil_store_op: vk::AttachmentStoreOp::DONT_CARE,
        initial_layout: vk::ImageLayout::UNDEFINED,
        final_layout: layout,
        ..Default::default()
    };
    let color = vk::ImageLayout::COLOR_ATTACHMENT_OPTIMAL;
    let depth_layout = vk::ImageLayout::DEPTH_STENCIL_ATTACHMENT_OPTIMAL;
    let mut attachments: Vec<_> = colors.iter().map(|&f| description(f, color)).collect();
    attachments.extend(depth.map(|f| description(f, depth_layout)));
    let color_refs: Vec<_> = (0..colors.len() as u32)
        .map(|attachment| vk::AttachmentReference {
            attachment,
            layout: color,
        })
        .collect();
    let depth_ref = depth.map(|_| vk::AttachmentReference {
        attachment: colors.len() as u32,
        layout: depth_layout,
    });
    let input_refs: Vec<_> = depth_ref
        .iter()
        .filter(|_| input.is_some())
        .map(|r| vk::AttachmentReference {
            attachment: r.attachment,
            layout: vk::ImageLayout::DEPTH_STENCIL_READ_ONLY_OPTIMAL,
        })
        .collect();
    let subpasses = [tuff::SubpassDescription::new()
        .pipeline_bind_point(vk::PipelineBindPoint::GRAPHICS)
        .color_attachments(&color_refs)
        .input_attachments(&input_refs)
        .depth_stencil_attachment(depth_ref.as_ref().filter(|_| input.is_none()))];
    let aspect_references = [vk::InputAttachmentAspectReference {
        subpass: 0,
        input_attachment_index: 0,
        aspect_mask: input.unwrap_or_default(),
    }];
    let mut aspects = tuff::RenderPassInputAttachmentAspectCreateInfo::new()
        .aspect_references(&aspect_references);
    let mut info = tuff::RenderPassCreateInfo::new()
        .attachments(&attachments)
        .subpasses(&subpasses);
    if input.is_some_and(|a| !a.is_empty()) {
        info = info.push_next(&mut aspects);
    }
    s.device.create_render_pass(&info).expect("render pass")
}

/// The shaders and layout every pipeline here uses: a layout that covers the test
/// shaders and the Bézier ones (a storage buffer for the vertex stage, 112 bytes of
/// push constants for the others).
struct Common {
    test: [tuff::ShaderModule; 2],
    bezier: [tuff::ShaderModule; 4],
    /// A geometry shader of points in and out.
    geometry: tuff::ShaderModule,
    /// The test vertex shader with a boolean specialization constant.
    spec_vertex: tuff::ShaderModule,
    /// The geometry shader of points without their size.
    unsized_geometry: tuff::ShaderModule,
    /// A fragment shader that reads PrimitiveId.
    primitive_fragment: tuff::ShaderModule,
    /// Shaders whose interfaces link, or fail to, by their file names.
    named: Vec<(&'static str, tuff::ShaderModule)>,
    layout: tuff::PipelineLayout,
    /// A layout of one input attachment for the fragment stage.
    input_layout: tuff::PipelineLayout,
    _input_set_layout: tuff::DescriptorSetLayout,
    _set_layout: tuff::DescriptorSetLayout,
}

fn common(s: &Setup) -> Common {
    let shader = |bytes: &[u8]| tuff_setup::shader(s, bytes);
    let bindings = [tuff::DescriptorSetLayoutBinding::new()
        .binding(0)
        .descriptor_type(vk::DescriptorType::STORAGE_BUFFER)
        .descriptor_count(1)
        .stage_flags(vk::ShaderStageFlags::VERTEX)];
    let set_layout = s
        .device
        .create_descriptor_set_layout(
            &tuff::DescriptorSetLayoutCreateInfo::new().bindings(&bindings),
        )
        .expect("set layout");
    let push = [vk::PushConstantRange {
        stage_flags: vk::ShaderStageFlags::TESSELLATION_CONTROL
            | vk::ShaderStageFlags::TESSELLATION_EVALUATION
            | vk::ShaderStageFlags::FRAGMENT,
        offset: 0,
        size: 112,
    }];
    let set_layouts = tuff::HandleSlice::new(&[&set_layout]);
    let layout = s
        .device
        .create_pipeline_layout(
            &tuff::PipelineLayoutCreateInfo::new()
                .set_layouts(&set_layouts)
                .push_constant_ranges(&push),
        )
        .expect("layout");
    let input_bindings = [tuff::DescriptorSetLayoutBinding::new()
        .binding(0)
        .descriptor_type(vk::DescriptorType::INPUT_ATTACHMENT)
        .descriptor_count(1)
        .stage_flags(vk::ShaderStageFlags::FRAGMENT)];
    let input_set_layout = s
        .device
        .create_descriptor_set_layout(
            &tuff::DescriptorSetLayoutCreateInfo::new().bindings(&input_bindings),
        )
        .expect("input set layout");
    let input_layout = s
        .device
        .create_pipeline_layout(
            &tuff::PipelineLayoutCreateInfo::new().set_layouts(&input_set_layout),
        )
        .expect("input layout");
    Common {
        input_layout,
        _input_set_layout: input_set_layout,
        test: [
            shader(include_bytes!("../shaders/spv/test.vert.spv")),
            shader(include_bytes!("../shaders/spv/test.frag.spv")),
        ],
        bezier: [
            shader(include_bytes!("../shaders/spv/bezier.vert.spv")),
            shader(include_bytes!("../shaders/spv/bezier.tesc.spv")),
            shader(include_bytes!("../shaders/spv/bezier.tese.spv")),
            shader(include_bytes!("../shaders/spv/bezier.frag.spv")),
        ],
        geometry: shader(include_bytes!("../shaders/spv/points.geom.spv")),
        spec_vertex: shader(include_bytes!("../shaders/spv/spec.vert.spv")),
        unsized_geometry: shader(include_bytes!("../shaders/spv/points_unsized.geom.spv")),
        primitive_fragment: shader(include_bytes!("../shaders/spv/prim.frag.spv")),
        named: vec![
            (
                "varying.vert",
                shader(include_bytes!("../shaders/spv/varying.vert.spv")),
            ),
            (
                "varying.geom",
                shader(include_bytes!("../shaders/spv/varying.geom.spv")),
            ),
            (
                "varying.frag",
                shader(include_bytes!("../shaders/spv/varying.frag.spv")),
            ),
            (
                "triangle.frag",
                shader(include_bytes!("../shaders/spv/triangle.frag.spv")),
            ),
            (
                "position_only.vert",
                shader(include_bytes!("../shaders/spv/position_only.vert.spv")),
            ),
            (
                "input_depth.frag",
                shader(include_bytes!("../shaders/spv/input_depth.frag.spv")),
            ),
        ],
        layout,
        _set_layout: set_layout,
    }
}

/// Builds `parts` through the safe method and, where `layer`, under the layer
/// through the unchecked one.
fn create(s: &Setup, c: &Common, parts: &Parts, layer: bool) -> (tuff::Result<()>, Vec<String>) {
    let module = |stage: vk::ShaderStageFlags| {
        let input = (stage == vk::ShaderStageFlags::FRAGMENT && parts.input_aspect.is_some())
            .then_some((stage, "input_depth.frag"));
        if let Some((_, name)) = input.iter().chain(&parts.named).find(|(s, _)| *s == stage) {
            return &c
                .named
                .iter()
                .find(|(n, _)| n == name)
                .expect("a named shader")
                .1;
        }
        if stage == vk::ShaderStageFlags::GEOMETRY {
            return if parts.unsized_geometry {
                &c.unsized_geometry
            } else {
                &c.geometry
            };
        }
        if stage == vk::ShaderStageFlags::VERTEX && parts.spec_vertex {
            return &c.spec_vertex;
        }
        if stage == vk::ShaderStageFlags::FRAGMENT && parts.primitive_fragment {
            return &c.primitive_fragment;
        }
        let i = match stage {
            vk::ShaderStageFlags::VERTEX => 0,
            vk::ShaderStageFlags::TESSELLATION_CONTROL => 1,
            vk::ShaderStageFlags::TESSELLATION_EVALUATION => 2,
            _ => 3,
        };
        match (parts.bezier, i) {
            (true, i) => &c.bezier[i],
            (false, 0) => &c.test[0],
            (false, _) => &c.test[1],
        }
    };
    let entries: Vec<_> = parts
        .constants
        .iter()
        .map(|&constant_id| vk::SpecializationMapEntry {
            constant_id,
            offset: 0,
            size: parts.constant_size,
        })
        .collect();
    let spec_data = [0u8; 4];
    let spec = tuff::SpecializationInfo::new()
        .map_entries(&entries)
        .data(&spec_data);
    let mut required: Option<_> = parts.subgroup_size.map(|size| {
        let size = match size {
            SubgroupSize::Of(size) => size,
            SubgroupSize::DeviceMin => min_subgroup_size(s),
        };
        let mut info = tuff::PipelineShaderStageRequiredSubgroupSizeCreateInfo::new();
        // SAFETY: a plain value member (the registry marks the struct returned-only,
        // so it has no setter).
        unsafe { info.raw_values_mut() }.required_subgroup_size = size;
        info
    });
    // The first stage takes the chained size, once.
    let mut chained = required.iter_mut();
    let stages: Vec<_> = parts
        .stages
        .iter()
        .enumerate()
        .map(|(k, &stage)| {
            let mut stage = tuff::PipelineShaderStageCreateInfo::new(c"main")
                .stage(stage)
                .module(Some(module(stage)));
            if k == 0 {
                stage = stage.flags(parts.stage_flags).name(parts.entry);
                if let Some(next) = chained.next() {
                    stage = stage.push_next(next);
                }
            }
            if k == 0 && !entries.is_empty() {
                stage.specialization_info(Some(&spec))
            } else {
                stage
            }
        })
        .collect();
    let binding_descriptions: Vec<_> = parts
        .bindings
        .iter()
        .map(|&binding| vk::VertexInputBindingDescription {
            binding,
            stride: 16,
            input_rate: vk::VertexInputRate::VERTEX,
        })
        .collect();
    let attribute_descriptions: Vec<_> = parts
        .attributes
        .iter()
        .map(|&(location, binding)| vk::VertexInputAttributeDescription {
            location,
            binding,
            format: parts.attribute_format,
            offset: 0,
        })
        .collect();
    let vertex_input = tuff::PipelineVertexInputStateCreateInfo::new()
        .vertex_binding_descriptions(&binding_descriptions)
        .vertex_attribute_descriptions(&attribute_descriptions);
    let assembly = parts.topology.map(|t| {
        tuff::PipelineInputAssemblyStateCreateInfo::new()
            .topology(t)
            .primitive_restart_enable(parts.restart)
    });
    let tessellation =
        tuff::PipelineTessellationStateCreateInfo::new().patch_control_points(parts.patch_points);
    // Static viewports and scissors are given; dynamic ones only counted.
    let viewports = vec![
        vk::Viewport {
            width: 4.0,
            height: 4.0,
            max_depth: 1.0,
            ..Default::default()
        };
        parts.viewport_counts.map_or(0, |c| c.0 as usize)
    ];
    let scissors = vec![parts.scissor; parts.viewport_counts.map_or(0, |c| c.1 as usize)];
    let viewport = parts.viewport_counts.map(|(v, s)| {
        let mut state = tuff::PipelineViewportStateCreateInfo::new();
        state = match parts.dynamic.contains(&vk::DynamicState::VIEWPORT) {
            true => state.viewport_count(v),
            false => state.viewports(&viewports),
        };
        match parts.dynamic.contains(&vk::DynamicState::SCISSOR) {
            true => state.scissor_count(s),
            false => state.scissors(&scissors),
        }
    });
    let mut raster = tuff::PipelineRasterizationStateCreateInfo::new()
        .polygon_mode(vk::PolygonMode::FILL)
        .cull_mode(vk::CullModeFlags::NONE)
        .rasterizer_discard_enable(parts.discard)
        .line_width(parts.line_width);
    if let Some(clamp) = parts.depth_bias {
        raster = raster.depth_bias_enable(true).depth_bias_clamp(clamp);
    }
    let multisample = tuff::PipelineMultisampleStateCreateInfo::new()
        .rasterization_samples(parts.samples)
        .min_sample_shading(parts.min_sample_shading);
    let depth_stencil = parts.depth_stencil.map(|(bounds, min, max)| {
        tuff::PipelineDepthStencilStateCreateInfo::new()
            .depth_bounds_test_enable(bounds)
            .min_depth_bounds(min)
            .max_depth_bounds(max)
    });
    let blend_attachments: Vec<_> = parts
        .blend
        .iter()
        .flatten()
        .map(|&enable| vk::PipelineColorBlendAttachmentState {
            blend_enable: enable as vk::Bool32,
            color_write_mask: vk::ColorComponentFlags::RGBA,
            ..Default::default()
        })
        .collect();
    let blend = parts.blend.as_ref().map(|_| {
        let blend = tuff::PipelineColorBlendStateCreateInfo::new().attachments(&blend_attachments);
        match parts.logic_op {
            Some(op) => blend.logic_op_enable(true).logic_op(op),
            None => blend,
        }
    });
    let dynamic = tuff::PipelineDynamicStateCreateInfo::new().dynamic_states(&parts.dynamic);
    let pass = match &parts.target {
        Target::Pass { colors, depth, .. } => {
            Some(render_pass(s, colors, *depth, parts.input_aspect))
        }
        Target::Rendering { .. } => None,
    };
    let (rendering_colors, mut rendering) = match &parts.target {
        Target::Rendering {
            view_mask,
            colors,
            depth,
            stencil,
        } => (colors.clone(), Some((*view_mask, *depth, *stencil))),
        Target::Pass { .. } => (Vec::new(), None),
    };
    let mut rendering_info = rendering.take().map(|(view_mask, depth, stencil)| {
        tuff::PipelineRenderingCreateInfo::new()
            .view_mask(view_mask)
            .color_attachment_formats(&rendering_colors)
            .depth_attachment_format(depth)
            .stencil_attachment_format(stencil)
    });
    let base = parts.base_handle.then(|| {
        let (mut made, _) = s
            .device
            .create_graphics_pipelines(None, &[base_info(c, pass.as_ref(), parts.base_allows)])
            .expect("base pipeline");
        made.pop().expect("one pipeline")
    });
    let mut info = tuff::GraphicsPipelineCreateInfo::new()
        .flags(parts.flags)
        .stages(&stages)
        .vertex_input_state(parts.vertex_input.then_some(&vertex_input))
        .input_assembly_state(assembly.as_ref())
        .tessellation_state(parts.tessellation.then_some(&tessellation))
        .viewport_state(viewport.as_ref())
        .rasterization_state(parts.raster.then_some(&raster))
        .multisample_state(parts.multisample.then_some(&multisample))
        .depth_stencil_state(depth_stencil.as_ref())
        .color_blend_state(blend.as_ref())
        .dynamic_state(Some(&dynamic))
        .layout(parts.layout.then_some(match parts.input_aspect {
            Some(_) => &c.input_layout,
            None => &c.layout,
        }))
        .render_pass(pass.as_ref())
        .base_pipeline_handle(base.as_ref())
        .base_pipeline_index(parts.base_index);
    if let Target::Pass { subpass, .. } = parts.target {
        info = info.subpass(subpass);
    }
    if let Some(r) = rendering_info.as_mut() {
        info = info.push_next(r);
    }
    let mut written = vk::PipelineCreationFeedback::default();
    let mut feedback = parts
        .feedback
        .then(|| tuff::PipelineCreationFeedbackCreateInfo::new(&mut written));
    if let Some(f) = feedback.as_mut() {
        info = info.push_next(f);
    }
    let infos = [info];
    let safe = s.device.create_graphics_pipelines(None, &infos).map(drop);
    let layer = match layer {
        true => under_layer(s, || {
            let _ = unsafe { s.device.create_graphics_pipelines_unchecked(None, &infos) };
        }),
        false => Vec::new(),
    };
    if parts.feedback && safe.is_ok() {
        // The driver wrote where the safe struct pointed.
        assert!(
            written
                .flags
                .contains(vk::PipelineCreationFeedbackFlags::VALID),
            "no feedback written: {written:?}"
        );
    }
    (safe, layer)
}

/// The create info of a base pipeline, the test pipeline, that allows derivatives
/// (`allows`) or not.
fn base_info<'a>(
    c: &'a Common,
    pass: Option<&'a tuff::RenderPass>,
    allows: bool,
) -> tuff::GraphicsPipelineCreateInfo<'a> {
    // Leaked: the info outlives this function; a few bytes once per case.
    let parts: &'a _ = Box::leak(Box::new((
        [
            tuff::PipelineShaderStageCreateInfo::new(c"main")
                .stage(vk::ShaderStageFlags::VERTEX)
                .module(Some(&c.test[0])),
            tuff::PipelineShaderStageCreateInfo::new(c"main")
                .stage(vk::ShaderStageFlags::FRAGMENT)
                .module(Some(&c.test[1])),
        ],
        tuff::PipelineVertexInputStateCreateInfo::new(),
        tuff::PipelineInputAssemblyStateCreateInfo::new()
            .topology(vk::PrimitiveTopology::TRIANGLE_LIST),
        tuff::PipelineViewportStateCreateInfo::new()
            .viewport_count(1)
            .scissor_count(1),
        tuff::PipelineRasterizationStateCreateInfo::new().line_width(1.0),
        tuff::PipelineMultisampleStateCreateInfo::new()
            .rasterization_samples(vk::SampleCountFlags::TYPE_1),
        [vk::PipelineColorBlendAttachmentState {
            color_write_mask: vk::ColorComponentFlags::RGBA,
            ..Default::default()
        }],
        [vk::DynamicState::VIEWPORT, vk::DynamicState::SCISSOR],
    )));
    let blend: &'a _ = Box::leak(Box::new(
        tuff::PipelineColorBlendStateCreateInfo::new().attachments(&parts.6),
    ));
    let dynamic: &'a _ = Box::leak(Box::new(
        tuff::PipelineDynamicStateCreateInfo::new().dynamic_states(&parts.7),
    ));
    let flags = if allows {
        vk::PipelineCreateFlags::ALLOW_DERIVATIVES
    } else {
        vk::PipelineCreateFlags::empty()
    };
    tuff::GraphicsPipelineCreateInfo::new()
        .flags(flags)
        .stages(&parts.0)
        .vertex_input_state(Some(&parts.1))
        .input_assembly_state(Some(&parts.2))
        .viewport_state(Some(&parts.3))
        .rasterization_state(Some(&parts.4))
        .multisample_state(Some(&parts.5))
        .color_blend_state(Some(blend))
        .dynamic_state(Some(dynamic))
        .layout(Some(&c.layout))
        .render_pass(pass)
        .subpass(0)
}

/// Runs `unchecked` with the layer told to skip erroring calls, and returns what it
/// said.
fn under_layer(s: &Setup, unchecked: impl FnOnce()) -> Vec<String> {
    s.messages.take();
    s.messages.abort_on_error(true);
    unchecked();
    s.messages.abort_on_error(false);
    s.messages.take()
}

/// The device a case runs on.
#[derive(Clone, Copy, PartialEq, Eq)]
enum On {
    /// The tests' device: no Vulkan 1.0 feature, dynamic rendering on.
    Fixture,
    /// Every feature the physical device has.
    Full,
    /// No feature at all.
    Bare,
    /// A Vulkan 1.2 device (no feature either): no count of viewports can be dynamic.
    V12,
}

/// One case: the rule, the device, the rules the same change necessarily breaks
/// too (which the layer may name beside it), and the change.
struct Case {
    vuid: &'static str,
    on: On,
    /// Whether the unchecked call may run under the layer: not where the 1.3.239
    /// layer lets the broken call through to a driver that crashes on it, or
    /// crashes on it itself.
    layer: bool,
    also: &'static [&'static str],
    change: fn(&mut Parts),
}

const fn case(vuid: &'static str, change: fn(&mut Parts)) -> Case {
    Case {
        vuid,
        on: On::Fixture,
        layer: true,
        also: &[],
        change,
    }
}

fn rendering(
    view_mask: u32,
    colors: Vec<vk::Format>,
    depth: vk::Format,
    stencil: vk::Format,
) -> Target {
    Target::Rendering {
        view_mask,
        colors,
        depth,
        stencil,
    }
}

const CASES: &[Case] = &[
    case(
        "VUID-VkPipelineDynamicStateCreateInfo-pDynamicStates-01442",
        |p| p.dynamic.push(vk::DynamicState::VIEWPORT),
    ),
    case(
        "VUID-VkPipelineVertexInputStateCreateInfo-pVertexBindingDescriptions-00616",
        |p| p.bindings = vec![0, 0],
    ),
    case(
        "VUID-VkPipelineVertexInputStateCreateInfo-pVertexAttributeDescriptions-00617",
        |p| {
            p.bindings = vec![0];
            p.attributes = vec![(0, 0), (0, 0)];
        },
    ),
    case(
        "VUID-VkPipelineVertexInputStateCreateInfo-binding-00615",
        |p| {
            p.bindings = vec![0];
            p.attributes = vec![(0, 1)];
        },
    ),
    case(
        "VUID-VkPipelineInputAssemblyStateCreateInfo-topology-00428",
        |p| p.restart = true,
    ),
    case(
        "VUID-VkPipelineInputAssemblyStateCreateInfo-topology-00429",
        |p| p.topology = Some(vk::PrimitiveTopology::LINE_LIST_WITH_ADJACENCY),
    ),
    Case {
        on: On::Full,
        ..case(
            "VUID-VkPipelineTessellationStateCreateInfo-patchControlPoints-01214",
            |p| {
                *p = Parts::tessellated();
                p.patch_points = 0;
            },
        )
    },
    // The 1.3.239 layer does not check it, and lavapipe at times crashes on a
    // fraction past 1 (it sizes per-sample work from it): proven by the error alone,
    // without the driver.
    Case {
        layer: false,
        ..case(
            "VUID-VkPipelineMultisampleStateCreateInfo-minSampleShading-00786",
            |p| p.min_sample_shading = 2.0,
        )
    },
    Case {
        on: On::Full,
        ..case(
            "VUID-VkPipelineColorBlendStateCreateInfo-logicOpEnable-00607",
            |p| p.logic_op = Some(vk::LogicOp::from_raw(99)),
        )
    },
    case("VUID-VkSpecializationInfo-constantID-04911", |p| {
        p.constants = vec![1, 1]
    }),
    // The test vertex shader writes no point size.
    case("VUID-VkGraphicsPipelineCreateInfo-Vertex-07722", |p| {
        p.topology = Some(vk::PrimitiveTopology::POINT_LIST)
    }),
    Case {
        on: On::Full,
        ..case("VUID-VkGraphicsPipelineCreateInfo-Geometry-07725", |p| {
            *p = Parts {
                unsized_geometry: true,
                ..Parts::through_geometry()
            };
        })
    },
    // The points geometry shader does not write PrimitiveId.
    Case {
        on: On::Full,
        ..case("VUID-VkGraphicsPipelineCreateInfo-pStages-00740", |p| {
            *p = Parts {
                primitive_fragment: true,
                ..Parts::through_geometry()
            };
        })
    },
    // The test vertex shader writes nothing at location 0, which the fragment
    // shader reads: the 1.3.239 layer names it under an unassigned ID.
    Case {
        also: &["UNASSIGNED-CoreValidation-Shader-InputNotProduced"],
        ..case("VUID-VkGraphicsPipelineCreateInfo-None-04889", |p| {
            p.named = vec![(vk::ShaderStageFlags::FRAGMENT, "triangle.frag")]
        })
    },
    // A vec4 output read as a vec3, on a device without maintenance4: the 1.3.239
    // layer warns of the unread component under an unassigned ID.
    Case {
        also: &["UNASSIGNED-CoreValidation-Shader-OutputNotConsumed"],
        ..case("VUID-VkGraphicsPipelineCreateInfo-None-04889", |p| {
            p.named = vec![
                (vk::ShaderStageFlags::VERTEX, "varying.vert"),
                (vk::ShaderStageFlags::FRAGMENT, "triangle.frag"),
            ]
        })
    },
    // The geometry stage reads location 0, which the test vertex shader does not
    // write: the 1.3.239 layer names it under an unassigned ID.
    Case {
        on: On::Full,
        also: &["UNASSIGNED-CoreValidation-Shader-InputNotProduced"],
        ..case("VUID-VkGraphicsPipelineCreateInfo-pStages-00742", |p| {
            *p = Parts {
                named: vec![(vk::ShaderStageFlags::GEOMETRY, "varying.geom")],
                ..Parts::through_geometry()
            };
        })
    },
    // A built-in output block of gl_Position alone, and the geometry stage's full
    // input block: the 1.3.239 layer names it under an unassigned ID.
    Case {
        on: On::Full,
        also: &["UNASSIGNED-CoreValidation-Shader-InterfaceTypeMismatch"],
        ..case("VUID-VkGraphicsPipelineCreateInfo-pStages-00742", |p| {
            *p = Parts {
                named: vec![(vk::ShaderStageFlags::VERTEX, "position_only.vert")],
                ..Parts::through_geometry()
            };
        })
    },
    // The fragment stage reads the depth aspect of an input attachment that the
    // render pass lets it read the stencil aspect of alone.
    case("VUID-VkGraphicsPipelineCreateInfo-pStages-01565", |p| {
        p.target = Target::Pass {
            colors: vec![RGBA8],
            depth: Some(D32S8),
            subpass: 0,
        };
        p.input_aspect = Some(vk::ImageAspectFlags::STENCIL);
    }),
    // One byte for a boolean, which takes a VkBool32's four.
    case("VUID-VkSpecializationMapEntry-constantID-00776", |p| {
        p.spec_vertex = true;
        p.constants = vec![0];
        p.constant_size = 1;
    }),
    case("VUID-VkGraphicsPipelineCreateInfo-flags-00764", |p| {
        p.flags = vk::PipelineCreateFlags::DISPATCH_BASE
    }),
    // Without a handle or an index, the base is named by neither: 00723 breaks too.
    Case {
        also: &["VUID-VkGraphicsPipelineCreateInfo-flags-00723"],
        ..case("VUID-VkGraphicsPipelineCreateInfo-flags-00722", |p| {
            p.flags = vk::PipelineCreateFlags::DERIVATIVE
        })
    },
    case("VUID-VkGraphicsPipelineCreateInfo-flags-00723", |p| {
        p.flags = vk::PipelineCreateFlags::DERIVATIVE;
        p.base_index = 1;
    }),
    // A handle and an index break the rule each way.
    Case {
        also: &["VUID-VkGraphicsPipelineCreateInfo-flags-00725"],
        ..case("VUID-VkGraphicsPipelineCreateInfo-flags-00724", |p| {
            p.flags = vk::PipelineCreateFlags::DERIVATIVE;
            p.base_handle = true;
            p.base_index = 0;
        })
    },
    // The base is the create info itself, which does not allow derivatives.
    Case {
        also: &["VUID-vkCreateGraphicsPipelines-flags-00721"],
        ..case("VUID-vkCreateGraphicsPipelines-flags-00720", |p| {
            p.flags = vk::PipelineCreateFlags::DERIVATIVE;
            p.base_index = 0;
        })
    },
    case("VUID-vkCreateGraphicsPipelines-flags-00721", |p| {
        p.flags = vk::PipelineCreateFlags::DERIVATIVE;
        p.base_handle = true;
        p.base_allows = false;
    }),
    // A block-compressed format holds no vertex attributes. The test vertex shader
    // reads no input, so the layer also notes the attribute goes unread.
    Case {
        also: &["UNASSIGNED-CoreValidation-Shader-OutputNotConsumed"],
        ..case("VUID-VkVertexInputAttributeDescription-format-00623", |p| {
            p.bindings = vec![0];
            p.attributes = vec![(0, 0)];
            p.attribute_format = vk::Format::BC1_RGB_UNORM_BLOCK;
        })
    },
    // A format of an extension the device does not enable (VK_IMG_format_pvrtc): it
    // has no attachment feature or depth/stencil aspect either, which is what the
    // 1.3.239 layer names (it does not check the value itself).
    Case {
        also: &["VUID-VkGraphicsPipelineCreateInfo-renderPass-06581"],
        ..case("VUID-VkGraphicsPipelineCreateInfo-renderPass-06580", |p| {
            p.target = rendering(
                0,
                vec![vk::Format::PVRTC1_2BPP_UNORM_BLOCK_IMG],
                vk::Format::UNDEFINED,
                vk::Format::UNDEFINED,
            )
        })
    },
    Case {
        also: &["VUID-VkGraphicsPipelineCreateInfo-renderPass-06587"],
        ..case("VUID-VkGraphicsPipelineCreateInfo-renderPass-06583", |p| {
            p.target = rendering(
                0,
                vec![RGBA8],
                vk::Format::PVRTC1_2BPP_UNORM_BLOCK_IMG,
                vk::Format::UNDEFINED,
            )
        })
    },
    Case {
        also: &["VUID-VkGraphicsPipelineCreateInfo-renderPass-06588"],
        ..case("VUID-VkGraphicsPipelineCreateInfo-renderPass-06584", |p| {
            p.target = rendering(
                0,
                vec![RGBA8],
                vk::Format::UNDEFINED,
                vk::Format::PVRTC1_2BPP_UNORM_BLOCK_IMG,
            )
        })
    },
    case("VUID-VkGraphicsPipelineCreateInfo-renderPass-06053", |p| {
        p.target = rendering(0, vec![RGBA8], D32S8, D32S8);
        p.depth_stencil = None;
    }),
    case("VUID-VkGraphicsPipelineCreateInfo-renderPass-06054", |p| {
        p.target = rendering(0, vec![RGBA8], vk::Format::UNDEFINED, vk::Format::UNDEFINED);
        p.blend = None;
    }),
    // Rasterization discarded statically, so the viewport state is wanted only for
    // the dynamic state. The unchecked call crashed the test process (the 1.3.239
    // layer lets it through to lavapipe, which reads the missing state): proven by
    // the error alone, without the driver.
    Case {
        layer: false,
        ..case(
            "VUID-VkGraphicsPipelineCreateInfo-pViewportState-04892",
            |p| {
                p.discard = true;
                p.dynamic.push(vk::DynamicState::RASTERIZER_DISCARD_ENABLE);
                p.viewport_counts = None;
            },
        )
    },
    case("VUID-VkGraphicsPipelineCreateInfo-pStages-06894", |p| {
        p.discard = true
    }),
    // A geometry shader of points after a triangle list.
    Case {
        on: On::Full,
        ..case("VUID-VkGraphicsPipelineCreateInfo-pStages-00738", |p| {
            p.stages = vec![
                vk::ShaderStageFlags::VERTEX,
                vk::ShaderStageFlags::GEOMETRY,
                vk::ShaderStageFlags::FRAGMENT,
            ]
        })
    },
    // A geometry shader of points after tessellation into triangles (quads); it
    // does not pass on the outputs of the evaluation stage that the Bézier fragment
    // shader reads.
    Case {
        on: On::Full,
        also: &["UNASSIGNED-CoreValidation-Shader-InputNotProduced"],
        ..case("VUID-VkGraphicsPipelineCreateInfo-pStages-00739", |p| {
            *p = Parts::tessellated();
            p.stages.insert(3, vk::ShaderStageFlags::GEOMETRY);
        })
    },
    // The fragment module has no compute entry point either.
    Case {
        also: &["VUID-VkPipelineShaderStageCreateInfo-pName-00707"],
        ..case("VUID-VkGraphicsPipelineCreateInfo-pStages-06896", |p| {
            p.stages = vec![vk::ShaderStageFlags::VERTEX, vk::ShaderStageFlags::COMPUTE]
        })
    },
    // Lavapipe renders to no attachment with 1 or 4 samples, not 8. The test
    // fragment shader's color output then has no attachment, which the layer notes.
    Case {
        also: &["UNASSIGNED-CoreValidation-Shader-OutputNotConsumed"],
        ..case("VUID-VkGraphicsPipelineCreateInfo-subpass-00758", |p| {
            p.target = Target::Pass {
                colors: vec![],
                depth: None,
                subpass: 0,
            };
            p.blend = None;
            p.samples = vk::SampleCountFlags::TYPE_8;
        })
    },
    case("VUID-VkPipelineShaderStageCreateInfo-pName-00707", |p| {
        p.entry = c"other"
    }),
    Case {
        on: On::Bare,
        ..case("VUID-VkPipelineShaderStageCreateInfo-flags-02784", |p| {
            p.stage_flags = vk::PipelineShaderStageCreateFlags::ALLOW_VARYING_SUBGROUP_SIZE
        })
    },
    Case {
        on: On::Bare,
        ..case("VUID-VkPipelineShaderStageCreateInfo-flags-02785", |p| {
            p.stage_flags = vk::PipelineShaderStageCreateFlags::REQUIRE_FULL_SUBGROUPS
        })
    },
    // A vertex stage may not be among the stages that take a required size.
    Case {
        on: On::Full,
        also: &["VUID-VkPipelineShaderStageCreateInfo-pNext-02755"],
        ..case(
            "VUID-VkPipelineShaderStageRequiredSubgroupSizeCreateInfo-requiredSubgroupSize-02760",
            |p| p.subgroup_size = Some(SubgroupSize::Of(3)),
        )
    },
    // Lavapipe's smallest subgroup is larger than one invocation.
    Case {
        on: On::Full,
        also: &["VUID-VkPipelineShaderStageCreateInfo-pNext-02755"],
        ..case(
            "VUID-VkPipelineShaderStageRequiredSubgroupSizeCreateInfo-requiredSubgroupSize-02761",
            |p| p.subgroup_size = Some(SubgroupSize::Of(1)),
        )
    },
    Case {
        on: On::Full,
        also: &["VUID-VkPipelineShaderStageCreateInfo-pNext-02755"],
        ..case(
            "VUID-VkPipelineShaderStageRequiredSubgroupSizeCreateInfo-requiredSubgroupSize-02762",
            |p| p.subgroup_size = Some(SubgroupSize::Of(1 << 20)),
        )
    },
    Case {
        on: On::Full,
        also: &["VUID-VkPipelineShaderStageCreateInfo-pNext-02755"],
        ..case("VUID-VkPipelineShaderStageCreateInfo-pNext-02754", |p| {
            p.stage_flags = vk::PipelineShaderStageCreateFlags::ALLOW_VARYING_SUBGROUP_SIZE;
            p.subgroup_size = Some(SubgroupSize::DeviceMin);
        })
    },
    Case {
        on: On::Bare,
        ..case("VUID-VkPipelineShaderStageCreateInfo-pNext-02755", |p| {
            p.subgroup_size = Some(SubgroupSize::DeviceMin)
        })
    },
    case("VUID-VkGraphicsPipelineCreateInfo-stage-06897", |p| {
        p.stages = vec![
            vk::ShaderStageFlags::VERTEX,
            vk::ShaderStageFlags::VERTEX,
            vk::ShaderStageFlags::FRAGMENT,
        ]
    }),
    // The 1.3.239 layer also reports a pipeline without a vertex stage under 06896.
    Case {
        also: &["VUID-VkGraphicsPipelineCreateInfo-pStages-06896"],
        ..case("VUID-VkGraphicsPipelineCreateInfo-stage-00727", |p| {
            p.stages = vec![vk::ShaderStageFlags::FRAGMENT]
        })
    },
    // The 1.3.239 layer takes an unpaired stage as no tessellation, so the patch list breaks 00737 for it; and the fragment shader's inputs, written by the missing evaluation stage, are not produced.
    Case {
        also: &[
            "VUID-VkGraphicsPipelineCreateInfo-topology-00737",
            "UNASSIGNED-CoreValidation-Shader-InputNotProduced",
        ],
        on: On::Full,
        ..case("VUID-VkGraphicsPipelineCreateInfo-pStages-00729", |p| {
            *p = Parts::tessellated();
            p.stages
                .retain(|s| *s != vk::ShaderStageFlags::TESSELLATION_EVALUATION);
        })
    },
    // As for 00729, the patch list.
    Case {
        also: &["VUID-VkGraphicsPipelineCreateInfo-topology-00737"],
        on: On::Full,
        ..case("VUID-VkGraphicsPipelineCreateInfo-pStages-00730", |p| {
            *p = Parts::tessellated();
            p.stages
                .retain(|s| *s != vk::ShaderStageFlags::TESSELLATION_CONTROL);
        })
    },
    Case {
        on: On::Full,
        ..case("VUID-VkGraphicsPipelineCreateInfo-pStages-00731", |p| {
            *p = Parts::tessellated();
            p.tessellation = false;
        })
    },
    Case {
        on: On::Full,
        ..case("VUID-VkGraphicsPipelineCreateInfo-pStages-00736", |p| {
            *p = Parts::tessellated();
            p.topology = Some(vk::PrimitiveTopology::TRIANGLE_LIST);
        })
    },
    Case {
        on: On::Full,
        ..case("VUID-VkGraphicsPipelineCreateInfo-topology-00737", |p| {
            p.topology = Some(vk::PrimitiveTopology::PATCH_LIST)
        })
    },
    case("VUID-VkGraphicsPipelineCreateInfo-pStages-02097", |p| {
        p.vertex_input = false
    }),
    case("VUID-VkGraphicsPipelineCreateInfo-pStages-02098", |p| {
        p.topology = None
    }),
    case(
        "VUID-VkGraphicsPipelineCreateInfo-pRasterizationState-06601",
        |p| p.raster = false,
    ),
    // The 1.3.239 layer does not check it, and lavapipe crashes on a NULL layout.
    Case {
        layer: false,
        ..case("VUID-VkGraphicsPipelineCreateInfo-layout-06602", |p| {
            p.layout = false
        })
    },
    case(
        "VUID-VkGraphicsPipelineCreateInfo-rasterizerDiscardEnable-00750",
        |p| p.viewport_counts = None,
    ),
    // As for the layout: lavapipe crashes on a NULL multisample state.
    Case {
        layer: false,
        ..case(
            "VUID-VkGraphicsPipelineCreateInfo-rasterizerDiscardEnable-00751",
            |p| p.multisample = false,
        )
    },
    // With the subpass out of range, the 1.3.239 layer reads past the render pass's
    // subpasses: it misreports the stage's resources (01688) and the subpass's
    // attachments, and in about one run in fifteen crashes. Proven by the error
    // alone, without the layer.
    Case {
        layer: false,
        ..case("VUID-VkGraphicsPipelineCreateInfo-renderPass-06046", |p| {
            p.target = Target::Pass {
                colors: vec![RGBA8],
                depth: None,
                subpass: 1,
            }
        })
    },
    // The 1.3.239 layer also reports the NULL render pass under 06603, and the fragment output with no attachment it knows of.
    Case {
        also: &[
            "VUID-VkGraphicsPipelineCreateInfo-renderPass-06603",
            "UNASSIGNED-CoreValidation-Shader-OutputNotConsumed",
        ],
        on: On::Bare,
        ..case(
            "VUID-VkGraphicsPipelineCreateInfo-dynamicRendering-06576",
            |p| p.target = rendering(0, vec![RGBA8], vk::Format::UNDEFINED, vk::Format::UNDEFINED),
        )
    },
    case("VUID-VkGraphicsPipelineCreateInfo-multiview-06577", |p| {
        p.target = rendering(1, vec![RGBA8], vk::Format::UNDEFINED, vk::Format::UNDEFINED)
    }),
    Case {
        on: On::Full,
        ..case("VUID-VkGraphicsPipelineCreateInfo-renderPass-06578", |p| {
            p.target = rendering(
                1 << 31,
                vec![RGBA8],
                vk::Format::UNDEFINED,
                vk::Format::UNDEFINED,
            )
        })
    },
    case("VUID-VkGraphicsPipelineCreateInfo-renderPass-06581", |p| {
        p.target = rendering(
            0,
            vec![vk::Format::BC1_RGBA_UNORM_BLOCK],
            vk::Format::UNDEFINED,
            vk::Format::UNDEFINED,
        )
    }),
    case("VUID-VkGraphicsPipelineCreateInfo-renderPass-06587", |p| {
        p.depth_stencil = Some((false, 0.0, 1.0));
        p.target = rendering(0, vec![RGBA8], vk::Format::S8_UINT, vk::Format::UNDEFINED)
    }),
    case("VUID-VkGraphicsPipelineCreateInfo-renderPass-06588", |p| {
        p.depth_stencil = Some((false, 0.0, 1.0));
        p.target = rendering(
            0,
            vec![RGBA8],
            vk::Format::UNDEFINED,
            vk::Format::D32_SFLOAT,
        )
    }),
    case("VUID-VkGraphicsPipelineCreateInfo-renderPass-06589", |p| {
        p.depth_stencil = Some((false, 0.0, 1.0));
        p.target = rendering(0, vec![RGBA8], vk::Format::D32_SFLOAT, D32S8)
    }),
    case("VUID-VkGraphicsPipelineCreateInfo-renderPass-06043", |p| {
        p.target = Target::Pass {
            colors: vec![RGBA8],
            depth: Some(D32S8),
            subpass: 0,
        }
    }),
    case("VUID-VkGraphicsPipelineCreateInfo-renderPass-06044", |p| {
        p.blend = None
    }),
    case("VUID-VkGraphicsPipelineCreateInfo-renderPass-06042", |p| {
        p.blend = Some(vec![false, false])
    }),
    case("VUID-VkGraphicsPipelineCreateInfo-renderPass-06055", |p| {
        p.blend = Some(vec![false, false]);
        p.target = rendering(0, vec![RGBA8], vk::Format::UNDEFINED, vk::Format::UNDEFINED)
    }),
    // The formats without blending are integer formats, which the test shader's
    // float output does not match (a warning).
    Case {
        also: &["UNASSIGNED-CoreValidation-Shader-InterfaceTypeMismatch"],
        ..case("VUID-VkGraphicsPipelineCreateInfo-renderPass-06041", |p| {
            p.blend = Some(vec![true]);
            p.target = Target::Pass {
                colors: vec![vk::Format::R8G8B8A8_UINT],
                depth: None,
                subpass: 0,
            }
        })
    },
    // The formats without blending are integer formats, which the test shader's
    // float output does not match (a warning).
    Case {
        also: &["UNASSIGNED-CoreValidation-Shader-InterfaceTypeMismatch"],
        ..case("VUID-VkGraphicsPipelineCreateInfo-renderPass-06062", |p| {
            p.blend = Some(vec![true]);
            p.target = rendering(
                0,
                vec![vk::Format::R8G8B8A8_UINT],
                vk::Format::UNDEFINED,
                vk::Format::UNDEFINED,
            )
        })
    },
    case(
        "VUID-VkGraphicsPipelineCreateInfo-pDynamicStates-00749",
        |p| p.line_width = 2.0,
    ),
    case(
        "VUID-VkGraphicsPipelineCreateInfo-pDynamicStates-00754",
        |p| p.depth_bias = Some(0.5),
    ),
    case(
        "VUID-VkGraphicsPipelineCreateInfo-pDynamicStates-03379",
        |p| {
            p.dynamic = vec![
                vk::DynamicState::VIEWPORT_WITH_COUNT,
                vk::DynamicState::SCISSOR,
            ]
        },
    ),
    case(
        "VUID-VkGraphicsPipelineCreateInfo-pDynamicStates-03380",
        |p| {
            p.dynamic = vec![
                vk::DynamicState::VIEWPORT,
                vk::DynamicState::SCISSOR_WITH_COUNT,
            ]
        },
    ),
    case(
        "VUID-VkGraphicsPipelineCreateInfo-pDynamicStates-04132",
        |p| {
            p.viewport_counts = Some((0, 1));
            p.dynamic = vec![
                vk::DynamicState::VIEWPORT,
                vk::DynamicState::VIEWPORT_WITH_COUNT,
                vk::DynamicState::SCISSOR,
            ]
        },
    ),
    case(
        "VUID-VkGraphicsPipelineCreateInfo-pDynamicStates-04133",
        |p| {
            p.viewport_counts = Some((1, 0));
            p.dynamic = vec![
                vk::DynamicState::VIEWPORT,
                vk::DynamicState::SCISSOR,
                vk::DynamicState::SCISSOR_WITH_COUNT,
            ]
        },
    ),
    Case {
        on: On::Full,
        ..case(
            "VUID-VkPipelineViewportStateCreateInfo-scissorCount-04134",
            |p| p.viewport_counts = Some((1, 2)),
        )
    },
    // A viewport count of 0 without VIEWPORT_WITH_COUNT differs from a scissor count
    // other than 0 (04134), or a scissor count of 0 breaks 04136.
    Case {
        on: On::Full,
        also: &["VUID-VkPipelineViewportStateCreateInfo-scissorCount-04134"],
        ..case(
            "VUID-VkPipelineViewportStateCreateInfo-viewportCount-04135",
            |p| p.viewport_counts = Some((0, 1)),
        )
    },
    Case {
        on: On::Full,
        ..case(
            "VUID-VkPipelineViewportStateCreateInfo-scissorCount-04136",
            |p| {
                p.viewport_counts = Some((0, 0));
                p.dynamic = vec![
                    vk::DynamicState::VIEWPORT_WITH_COUNT,
                    vk::DynamicState::SCISSOR,
                ];
            },
        )
    },
    // Without Vulkan 1.3 the counts are simply required (the registry's
    // hand-written arraylength rules); a render pass, as there is no dynamic
    // rendering either. Equal counts, so that 01220 (they must match) holds.
    Case {
        on: On::V12,
        also: &["VUID-VkPipelineViewportStateCreateInfo-scissorCount-arraylength"],
        ..case(
            "VUID-VkPipelineViewportStateCreateInfo-viewportCount-arraylength",
            |p| {
                p.viewport_counts = Some((0, 0));
                p.target = Target::Pass {
                    colors: vec![RGBA8],
                    depth: None,
                    subpass: 0,
                };
            },
        )
    },
    Case {
        on: On::V12,
        also: &["VUID-VkPipelineViewportStateCreateInfo-scissorCount-01220"],
        ..case(
            "VUID-VkPipelineViewportStateCreateInfo-scissorCount-arraylength",
            |p| {
                p.viewport_counts = Some((1, 0));
                p.target = Target::Pass {
                    colors: vec![RGBA8],
                    depth: None,
                    subpass: 0,
                };
            },
        )
    },
    case("VUID-VkPipelineViewportStateCreateInfo-x-02821", |p| {
        p.dynamic = vec![vk::DynamicState::VIEWPORT];
        p.scissor.offset.x = -1;
    }),
    case("VUID-VkPipelineViewportStateCreateInfo-offset-02822", |p| {
        p.dynamic = vec![vk::DynamicState::VIEWPORT];
        p.scissor.offset.x = 1;
        p.scissor.extent.width = i32::MAX as u32;
    }),
    case("VUID-VkPipelineViewportStateCreateInfo-offset-02823", |p| {
        p.dynamic = vec![vk::DynamicState::VIEWPORT];
        p.scissor.offset.y = 1;
        p.scissor.extent.height = i32::MAX as u32;
    }),
    // The test fragment shader writes one attachment; the layer warns of the second.
    Case {
        also: &["UNASSIGNED-CoreValidation-Shader-InputNotProduced"],
        ..case(
            "VUID-VkPipelineColorBlendStateCreateInfo-pAttachments-00605",
            |p| {
                p.blend = Some(vec![false, true]);
                p.target = Target::Pass {
                    colors: vec![RGBA8, RGBA8],
                    depth: None,
                    subpass: 0,
                };
            },
        )
    },
];

/// The pipelines the cases start from are valid on their devices, so that a case
/// cannot pass on a rule it did not break.
#[test]
fn the_cases_start_from_valid_pipelines() {
    let _serial = vulkan::serial();
    let s = tuff_setup::setup(true);
    let full = tuff_setup::setup_full_features(true);
    for (s, parts, what) in [
        (&s, Parts::default(), "the test pipeline"),
        // `create` checks that the driver wrote the feedback.
        (
            &s,
            Parts {
                feedback: true,
                ..Parts::default()
            },
            "the test pipeline with a creation feedback",
        ),
        (
            &s,
            Parts {
                target: rendering(0, vec![RGBA8], D32S8, D32S8),
                depth_stencil: Some((false, 0.0, 1.0)),
                ..Parts::default()
            },
            "the test pipeline with dynamic rendering",
        ),
        (&full, Parts::tessellated(), "the Bézier pipeline"),
        (
            &s,
            Parts {
                target: Target::Pass {
                    colors: vec![RGBA8],
                    depth: Some(D32S8),
                    subpass: 0,
                },
                input_aspect: Some(vk::ImageAspectFlags::DEPTH),
                ..Parts::default()
            },
            "a fragment stage that reads the depth aspect it may read",
        ),
        (
            &full,
            Parts {
                named: vec![
                    (vk::ShaderStageFlags::VERTEX, "varying.vert"),
                    (vk::ShaderStageFlags::GEOMETRY, "varying.geom"),
                    (vk::ShaderStageFlags::FRAGMENT, "varying.frag"),
                ],
                ..Parts::through_geometry()
            },
            "a color passed through a geometry stage",
        ),
        (
            &full,
            Parts {
                named: vec![
                    (vk::ShaderStageFlags::VERTEX, "varying.vert"),
                    (vk::ShaderStageFlags::FRAGMENT, "triangle.frag"),
                ],
                ..Parts::default()
            },
            "a vec4 output read as a vec3 with maintenance4",
        ),
    ] {
        let c = common(s);
        let (safe, layer) = create(s, &c, &parts, true);
        assert!(safe.is_ok(), "{what}: tuff refused it: {safe:?}");
        assert!(
            layer.is_empty(),
            "{what}: the layer said:\n{}",
            layer.join("\n")
        );
    }
}

/// Each case is refused with its rule's VUID, and the layer names the same rule or
/// nothing.
#[test]
fn each_broken_pipeline_rule_is_refused_and_the_layer_agrees() {
    let _serial = vulkan::serial();
    let fixture = tuff_setup::setup(true);
    let full = tuff_setup::setup_full_features(true);
    let bare = tuff_setup::setup_bare(true);
    let v12 = tuff_setup::setup_v1_2(true);
    let mut failures = Vec::new();
    let (mut by_layer, mut alone) = (0, Vec::new());
    for case in CASES {
        if std::env::var_os("CASE_TRACE").is_some() {
            eprintln!("case: {}", case.vuid);
        }
        let s = match case.on {
            On::Fixture => &fixture,
            On::Full => &full,
            On::Bare => &bare,
            On::V12 => &v12,
        };
        let c = common(s);
        let mut parts = Parts::default();
        (case.change)(&mut parts);
        let (safe, layer) = create(s, &c, &parts, case.layer);
        match &safe {
            Err(tuff::Error::Validation { vuid, .. }) if *vuid == case.vuid => {}
            other => {
                failures.push(format!("{}: the safe method returned {other:?}", case.vuid));
                continue;
            }
        }
        let names = |m: &String, v: &str| m.contains(&format!("[ {v} ]"));
        let also = |m: &String| case.also.iter().any(|a| names(m, a));
        // A layer that names only rules the change breaks too does not check this
        // one: the error alone proves it.
        if layer.iter().all(also) {
            alone.push(case.vuid);
        } else if layer.iter().any(|m| names(m, case.vuid))
            && layer.iter().all(|m| names(m, case.vuid) || also(m))
        {
            by_layer += 1;
        } else {
            failures.push(format!(
                "{}: the layer said something else:\n  {}",
                case.vuid,
                layer.join("\n  ")
            ));
        }
    }
    println!(
        "graphics pipeline state: the layer named {by_layer}, the error alone proves {} ({})",
        alone.len(),
        alone.join(", ")
    );
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

/// A compute pipeline of the test compute shader, with this stage and derivative.
fn create_compute(
    s: &Setup,
    stage: vk::ShaderStageFlags,
    flags: vk::PipelineCreateFlags,
    base: Option<vk::PipelineCreateFlags>,
    index: i32,
) -> (tuff::Result<()>, Vec<String>) {
    let module = tuff_setup::shader(s, include_bytes!("../shaders/spv/test.comp.spv"));
    let bindings = [
        tuff::DescriptorSetLayoutBinding::new()
            .binding(0)
            .descriptor_type(vk::DescriptorType::UNIFORM_BUFFER)
            .descriptor_count(1)
            .stage_flags(vk::ShaderStageFlags::COMPUTE | vk::ShaderStageFlags::VERTEX),
        tuff::DescriptorSetLayoutBinding::new()
            .binding(1)
            .descriptor_type(vk::DescriptorType::STORAGE_BUFFER)
            .descriptor_count(1)
            .stage_flags(vk::ShaderStageFlags::COMPUTE | vk::ShaderStageFlags::VERTEX),
    ];
    let set_layout = s
        .device
        .create_descriptor_set_layout(
            &tuff::DescriptorSetLayoutCreateInfo::new().bindings(&bindings),
        )
        .expect("set layout");
    let set_layouts = tuff::HandleSlice::new(&[&set_layout]);
    let layout = s
        .device
        .create_pipeline_layout(&tuff::PipelineLayoutCreateInfo::new().set_layouts(&set_layouts))
        .expect("layout");
    let info = |stage, flags, base| {
        tuff::ComputePipelineCreateInfo::new(
            tuff::PipelineShaderStageCreateInfo::new(c"main")
                .stage(stage)
                .module(Some(&module)),
            &layout,
        )
        .flags(flags)
        .base_pipeline_handle(base)
        .base_pipeline_index(index)
    };
    let base_pipeline = base.map(|base_flags| {
        let base = info(vk::ShaderStageFlags::COMPUTE, base_flags, None).base_pipeline_index(-1);
        let (mut made, _) = s
            .device
            .create_compute_pipelines(None, &[base])
            .expect("base pipeline");
        made.pop().expect("one pipeline")
    });
    let infos = [info(stage, flags, base_pipeline.as_ref())];
    let safe = s.device.create_compute_pipelines(None, &infos).map(drop);
    let layer = under_layer(s, || {
        let _ = unsafe { s.device.create_compute_pipelines_unchecked(None, &infos) };
    });
    (safe, layer)
}

/// The device's `minSubgroupSize` (Vulkan 1.3).
fn min_subgroup_size(s: &Setup) -> u32 {
    let mut p13 = vk::PhysicalDeviceVulkan13Properties::default();
    let mut p2 = vk::PhysicalDeviceProperties2::default().push_next(&mut p13);
    // SAFETY: a live physical device of a Vulkan 1.3 instance; the chain is local.
    unsafe {
        s.instance
            .fns()
            .get_physical_device_properties2(s.physical.raw(), &mut p2)
    };
    p13.min_subgroup_size
}

/// A compute pipeline of `one.comp` (one invocation per workgroup, no resources)
/// whose stage has `flags` and, if given, a chained required subgroup size (the
/// device's smallest), on a device with every feature.
fn create_subgroups(
    s: &Setup,
    flags: vk::PipelineShaderStageCreateFlags,
    required: bool,
) -> (tuff::Result<()>, Vec<String>) {
    let module = tuff_setup::shader(s, include_bytes!("../shaders/spv/one.comp.spv"));
    let layout = s
        .device
        .create_pipeline_layout(&tuff::PipelineLayoutCreateInfo::new())
        .expect("layout");
    let mut size = tuff::PipelineShaderStageRequiredSubgroupSizeCreateInfo::new();
    // SAFETY: a plain value member (the registry marks the struct returned-only, so
    // it has no setter).
    unsafe { size.raw_values_mut() }.required_subgroup_size = min_subgroup_size(s);
    let mut stage = tuff::PipelineShaderStageCreateInfo::new(c"main")
        .stage(vk::ShaderStageFlags::COMPUTE)
        .module(Some(&module))
        .flags(flags);
    if required {
        stage = stage.push_next(&mut size);
    }
    let infos = [tuff::ComputePipelineCreateInfo::new(stage, &layout)];
    let safe = s.device.create_compute_pipelines(None, &infos).map(drop);
    let layer = under_layer(s, || {
        let _ = unsafe { s.device.create_compute_pipelines_unchecked(None, &infos) };
    });
    (safe, layer)
}

/// Compute pipelines: a stage other than compute, and a derivative that names its
/// base no way or both ways, are refused; the layer names the same rules.
#[test]
fn compute_pipeline_rules_are_refused_and_the_layer_agrees() {
    let _serial = vulkan::serial();
    let s = tuff_setup::setup(true);
    // Full subgroups need computeFullSubgroups and subgroupSizeControl.
    let full = tuff_setup::setup_full_features(true);
    type F = vk::PipelineShaderStageCreateFlags;
    let compute = vk::ShaderStageFlags::COMPUTE;
    let none = vk::PipelineCreateFlags::empty();
    let derivative = vk::PipelineCreateFlags::DERIVATIVE;
    let allows = vk::PipelineCreateFlags::ALLOW_DERIVATIVES;
    let (safe, layer) = create_compute(&s, compute, none, None, -1);
    assert!(
        safe.is_ok() && layer.is_empty(),
        "the valid pipeline: {safe:?} {layer:?}"
    );
    let names = |m: &String, v: &str| m.contains(&format!("[ {v} ]"));
    let mut failures = Vec::new();
    let (mut by_layer, mut alone) = (0, Vec::new());
    for (vuid, also, (safe, layer)) in [
        (
            "VUID-VkComputePipelineCreateInfo-stage-00701",
            // The compute module has no entry point for the vertex stage.
            &["VUID-VkPipelineShaderStageCreateInfo-pName-00707"][..],
            create_compute(&s, vk::ShaderStageFlags::VERTEX, none, None, -1),
        ),
        (
            "VUID-VkComputePipelineCreateInfo-flags-00697",
            // Without a handle or an index, the base is named by neither.
            &["VUID-VkComputePipelineCreateInfo-flags-00698"][..],
            create_compute(&s, compute, derivative, None, -1),
        ),
        (
            "VUID-VkComputePipelineCreateInfo-flags-00698",
            &[][..],
            create_compute(&s, compute, derivative, None, 1),
        ),
        (
            "VUID-VkComputePipelineCreateInfo-flags-00699",
            // A handle and an index break the rule each way.
            &["VUID-VkComputePipelineCreateInfo-flags-00700"][..],
            create_compute(&s, compute, derivative, Some(allows), 0),
        ),
        (
            "VUID-vkCreateComputePipelines-flags-00695",
            // The base is the create info itself, which does not allow derivatives.
            &["VUID-vkCreateComputePipelines-flags-00696"][..],
            create_compute(&s, compute, derivative, None, 0),
        ),
        (
            "VUID-vkCreateComputePipelines-flags-00696",
            &[][..],
            create_compute(&s, compute, derivative, Some(none), -1),
        ),
        // A workgroup one invocation wide, with full subgroups.
        (
            "VUID-VkPipelineShaderStageCreateInfo-flags-02759",
            &[][..],
            create_subgroups(&full, F::REQUIRE_FULL_SUBGROUPS, false),
        ),
        (
            "VUID-VkPipelineShaderStageCreateInfo-flags-02758",
            &[][..],
            create_subgroups(
                &full,
                F::REQUIRE_FULL_SUBGROUPS | F::ALLOW_VARYING_SUBGROUP_SIZE,
                false,
            ),
        ),
        (
            "VUID-VkPipelineShaderStageCreateInfo-pNext-02757",
            &[][..],
            create_subgroups(&full, F::REQUIRE_FULL_SUBGROUPS, true),
        ),
    ] {
        match &safe {
            Err(tuff::Error::Validation { vuid: got, .. }) if *got == vuid => {}
            other => {
                failures.push(format!("{vuid}: the safe method returned {other:?}"));
                continue;
            }
        }
        let implied = |m: &String| also.iter().any(|a| names(m, a));
        if layer.iter().all(implied) {
            alone.push(vuid);
        } else if layer.iter().any(|m| names(m, vuid))
            && layer.iter().all(|m| names(m, vuid) || implied(m))
        {
            by_layer += 1;
        } else {
            failures.push(format!(
                "{vuid}: the layer said something else:\n  {}",
                layer.join("\n  ")
            ));
        }
    }
    println!(
        "compute pipelines: the layer named {by_layer}, the error alone proves {} ({})",
        alone.len(),
        alone.join(", ")
    );
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

/// A pipeline cache made by the safe method starts empty: initial data is refused
/// (00769), as tuff cannot tell whether it came from `vkGetPipelineCacheData`; data
/// the caller vouches for goes through the `_unchecked` twin.
#[test]
fn a_pipeline_cache_takes_initial_data_only_on_the_callers_word() {
    let _serial = vulkan::serial();
    let s = tuff_setup::setup(true);
    let d = &s.device;
    let empty = d
        .create_pipeline_cache(&tuff::PipelineCacheCreateInfo::new())
        .expect("an empty cache");
    let data = d.get_pipeline_cache_data(&empty).expect("data");
    let rule = "VUID-VkPipelineCacheCreateInfo-initialDataSize-00769";
    let info = tuff::PipelineCacheCreateInfo::new().initial_data(&data);
    assert_eq!(tuff_setup::vuid(d.create_pipeline_cache(&info)), rule);
    // Bytes from nowhere: the 1.3.239 layer does not check the rule, so tuff's error
    // alone proves it (lavapipe ignores data whose header is not its own). A layer
    // that starts checking it fails here.
    let nowhere = [0u8; 64];
    s.messages.take();
    // SAFETY: lavapipe checks the header of initial data and ignores data that is
    // not its own.
    let ignored = unsafe {
        d.create_pipeline_cache_unchecked(
            &tuff::PipelineCacheCreateInfo::new().initial_data(&nowhere),
        )
    };
    let said = s.messages.take();
    assert!(said.is_empty(), "the layer now checks {rule}: {said:?}");
    drop(ignored);
    // SAFETY: the data came from vkGetPipelineCacheData of this device.
    let _reloaded = unsafe { d.create_pipeline_cache_unchecked(&info) }.expect("reloaded");
    vulkan::assert_silent(&s.messages);
}
