//! Draws check the state they draw with: the bound pipeline's render pass and
//! subpass against the render pass instance's, and its dynamic states against those
//! the recording set (each set since a pipeline with it static was bound, none of
//! its static ones set since it was bound).
//!
//! Each case records one draw, by each of the six draw commands, that breaks one
//! rule: tuff must refuse the safe call with the rule's VUID, and the validation
//! layer, for the `_unchecked` twin (told to skip the call it reports), must name
//! the same VUID. No command buffer is submitted.
//!
//! SAFETY of the `unsafe` blocks: the draws are `unsafe` for rules their `# Safety`
//! sections list, which these recordings keep but for the one each case breaks on
//! purpose, which tuff refuses and the layer skips; the shaders are the repository's
//! (the shader promise, see `tuff_setup::shader`).

#[path = "common/pipelines.rs"]
mod pipelines;
#[path = "common/tuff_setup.rs"]
mod tuff_setup;
#[path = "common/vulkan.rs"]
mod vulkan;

use tuff::vk;
use tuff_setup::{setup, setup_full_features, vuid, Setup};
use vulkan::assert_silent;

type D = vk::DynamicState;
type Inside<'r> = tuff::Recorder<'r, tuff::InRenderPass>;
const SIZE: u32 = 8;

/// The test pipeline for subpass `subpass` of `pass`, with `dynamic` states.
fn pipeline(
    s: &Setup,
    p: &pipelines::Pipelines,
    pass: &tuff::RenderPass,
    subpass: u32,
    dynamic: &[D],
) -> tuff::Pipeline {
    let stages = pipelines::test_stages(&p.vert, &p.frag);
    let states = tuff::PipelineDynamicStateCreateInfo::new().dynamic_states(dynamic);
    let (mut made, _) = pipelines::with_graphics_info(&stages, &p.graphics_layout, pass, |info| {
        let info = info.subpass(subpass).dynamic_state(Some(&states));
        s.device.create_graphics_pipelines(None, &[info])
    })
    .expect("pipeline");
    made.pop().expect("one pipeline")
}

/// One draw command, recorded checked (`false`) or unchecked (`true`).
type Draw<'a, S> = Box<dyn Fn(&mut tuff::Recorder<'_, S>, bool) -> tuff::Result<()> + 'a>;

/// What a case records before its draw.
type Prepare<'a> = Box<dyn Fn(&mut Inside<'_>) + 'a>;

/// The six draw commands, each with its VUID prefix; an indexed one binds `index`
/// first, an indirect one reads `args`.
fn draws<'a, S: tuff::recorder::Inside + 'a>(
    index: &'a tuff::Buffer,
    args: &'a tuff::Buffer,
) -> Vec<(&'static str, Draw<'a, S>)> {
    macro_rules! call {
        ($rec:ident, $unchecked:ident, $f:ident, $g:ident ($($a:expr),*)) => {
            if $unchecked {
                unsafe { $rec.$g($($a),*) }
            } else {
                #[allow(unused_unsafe)]
                unsafe { $rec.$f($($a),*) }
            }
        };
    }
    let indexed = move |r: &mut tuff::Recorder<'_, S>| {
        r.bind_index_buffer(index, 0, vk::IndexType::UINT32)
            .expect("index buffer");
    };
    vec![
        (
            "vkCmdDraw",
            Box::new(|r, u| call!(r, u, draw, draw_unchecked(3, 1, 0, 0))),
        ),
        (
            "vkCmdDrawIndexed",
            Box::new(move |r, u| {
                indexed(r);
                call!(r, u, draw_indexed, draw_indexed_unchecked(3, 1, 0, 0, 0))
            }),
        ),
        (
            "vkCmdDrawIndirect",
            Box::new(move |r, u| {
                call!(r, u, draw_indirect, draw_indirect_unchecked(args, 0, 1, 16))
            }),
        ),
        (
            "vkCmdDrawIndexedIndirect",
            Box::new(move |r, u| {
                indexed(r);
                call!(
                    r,
                    u,
                    draw_indexed_indirect,
                    draw_indexed_indirect_unchecked(args, 0, 1, 20)
                )
            }),
        ),
        (
            "vkCmdDrawIndirectCount",
            Box::new(move |r, u| {
                call!(
                    r,
                    u,
                    draw_indirect_count,
                    draw_indirect_count_unchecked(args, 0, args, 64, 1, 16)
                )
            }),
        ),
        (
            "vkCmdDrawIndexedIndirectCount",
            Box::new(move |r, u| {
                indexed(r);
                call!(
                    r,
                    u,
                    draw_indexed_indirect_count,
                    draw_indexed_indirect_count_unchecked(args, 0, args, 64, 1, 20)
                )
            }),
        ),
    ]
}

fn area() -> vk::Rect2D {
    vk::Rect2D {
        offset: vk::Offset2D::default(),
        extent: vk::Extent2D {
            width: SIZE,
            height: SIZE,
        },
    }
}

fn set_viewport(r: &mut Inside<'_>) {
    let viewport = vk::Viewport {
        width: SIZE as f32,
        height: SIZE as f32,
        max_depth: 1.0,
        ..Default::default()
    };
    r.set_viewport(0, &[viewport]).expect("viewport");
}

fn set_scissor(r: &mut Inside<'_>) {
    r.set_scissor(0, &[area()]).expect("scissor");
}

#[test]
fn draws_check_their_pipeline_and_dynamic_state() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let target = s.color_target(SIZE, vk::ImageUsageFlags::empty());
    let p = pipelines::pipelines(&s, &target);
    let usage = vk::BufferUsageFlags::INDIRECT_BUFFER
        | vk::BufferUsageFlags::INDEX_BUFFER
        | vk::BufferUsageFlags::VERTEX_BUFFER;
    let (args, _memory) = pipelines::host_buffer(&s, 256, usage);
    let rgba = vk::Format::R8G8B8A8_UNORM;
    let two = s.color_pass(rgba, 2);
    let two_framebuffer = s
        .device
        .create_framebuffer(
            &tuff::FramebufferCreateInfo::new(&two)
                .attachments(&target.view)
                .width(SIZE)
                .height(SIZE)
                .layers(1),
        )
        .expect("framebuffer");
    let other_format = s.color_pass(vk::Format::R8_UNORM, 1);
    let viewport_scissor = [D::VIEWPORT, D::SCISSOR];
    let plain = pipeline(&s, &p, &target.render_pass, 0, &viewport_scissor);
    let incompatible = pipeline(&s, &p, &other_format, 0, &viewport_scissor);
    let second_subpass = pipeline(&s, &p, &two, 1, &viewport_scissor);
    let named = [
        (D::PRIMITIVE_TOPOLOGY, "primitiveTopology-03420"),
        (D::VERTEX_INPUT_BINDING_STRIDE, "pStrides-04884"),
        (D::RASTERIZER_DISCARD_ENABLE, "None-04876"),
        (D::DEPTH_BIAS_ENABLE, "None-04877"),
        (D::PRIMITIVE_RESTART_ENABLE, "None-04879"),
    ];
    let all_dynamic: Vec<D> = viewport_scissor
        .iter()
        .copied()
        .chain(named.iter().map(|(d, _)| *d))
        .collect();
    let extended = pipeline(&s, &p, &target.render_pass, 0, &all_dynamic);
    let set_named = |r: &mut Inside<'_>, state: D| match state {
        D::PRIMITIVE_TOPOLOGY => r.set_primitive_topology(vk::PrimitiveTopology::TRIANGLE_LIST),
        D::VERTEX_INPUT_BINDING_STRIDE => r
            .bind_vertex_buffers2(0, &args, &[0], &[], &[16])
            .expect("vertex buffer with its stride"),
        D::RASTERIZER_DISCARD_ENABLE => r.set_rasterizer_discard_enable(false),
        D::DEPTH_BIAS_ENABLE => r.set_depth_bias_enable(false),
        D::PRIMITIVE_RESTART_ENABLE => r.set_primitive_restart_enable(false),
        _ => unreachable!("a named state"),
    };

    // (rule suffix, whether the instance is of the two-subpass render pass, what
    // the case records before the draw)
    let mut cases: Vec<(String, bool, Prepare<'_>)> = vec![
        (
            "renderPass-02684".into(),
            false,
            Box::new(|r| {
                r.bind_pipeline(vk::PipelineBindPoint::GRAPHICS, &incompatible)
                    .expect("bind");
                set_viewport(r);
                set_scissor(r);
            }),
        ),
        (
            "commandBuffer-02701".into(),
            false,
            Box::new(|r| {
                r.bind_pipeline(vk::PipelineBindPoint::GRAPHICS, &plain)
                    .expect("bind");
                set_scissor(r);
            }),
        ),
        (
            "None-02859".into(),
            false,
            Box::new(|r| {
                r.bind_pipeline(vk::PipelineBindPoint::GRAPHICS, &plain)
                    .expect("bind");
                set_viewport(r);
                set_scissor(r);
                r.set_line_width(1.0);
            }),
        ),
    ];
    for (missing, suffix) in named {
        let (extended, set_named) = (&extended, &set_named);
        cases.push((
            suffix.into(),
            false,
            Box::new(move |r| {
                r.bind_pipeline(vk::PipelineBindPoint::GRAPHICS, extended)
                    .expect("bind");
                set_viewport(r);
                set_scissor(r);
                for (state, _) in named {
                    if state != missing {
                        set_named(r, state);
                    }
                }
            }),
        ));
    }
    cases.push((
        "subpass-02685".into(),
        true,
        Box::new(|r| {
            r.bind_pipeline(vk::PipelineBindPoint::GRAPHICS, &second_subpass)
                .expect("bind");
            set_viewport(r);
            set_scissor(r);
        }),
    ));

    let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let clear = [vk::ClearValue::default()];
    for (command, draw) in draws::<tuff::InRenderPass>(&args, &args) {
        for (suffix, in_two, prepare) in &cases {
            let rule = format!("VUID-{command}-{suffix}");
            let (pass, framebuffer) = if *in_two {
                (&two, &two_framebuffer)
            } else {
                (&target.render_pass, &target.framebuffer)
            };
            let begin = tuff::RenderPassBeginInfo::new(pass, framebuffer)
                .render_area(area())
                .clear_values(&clear);
            tuff_setup::breaks(&s, &rule, tuff_setup::Layer::Names, |unchecked| {
                let rec = cb
                    .begin(&tuff::CommandBufferBeginInfo::new())
                    .expect("begin");
                let mut rec = rec.begin_render_pass(&begin, vk::SubpassContents::INLINE);
                prepare(&mut rec);
                pipelines::push_color(&mut rec, &p);
                let r = draw(&mut rec, unchecked);
                drop(rec);
                r
            });
        }
    }
    assert_silent(&s.messages);
}

/// A pipeline made for dynamic rendering with these formats and view mask (the
/// test pipeline's create info for `pass`, with no render pass).
fn rendering_pipeline(
    s: &Setup,
    p: &pipelines::Pipelines,
    pass: &tuff::RenderPass,
    view_mask: u32,
    colors: &[vk::Format],
    depth: vk::Format,
    stencil: vk::Format,
) -> tuff::Pipeline {
    let depth_stencil = tuff::PipelineDepthStencilStateCreateInfo::new();
    rendering_pipeline_with(
        s,
        p,
        pass,
        view_mask,
        colors,
        (depth, stencil),
        &depth_stencil,
    )
}

/// [`rendering_pipeline`] with the depth/stencil state `depth_stencil`.
fn rendering_pipeline_with(
    s: &Setup,
    p: &pipelines::Pipelines,
    pass: &tuff::RenderPass,
    view_mask: u32,
    colors: &[vk::Format],
    (depth, stencil): (vk::Format, vk::Format),
    depth_stencil: &tuff::PipelineDepthStencilStateCreateInfo<'_>,
) -> tuff::Pipeline {
    let stages = pipelines::test_stages(&p.vert, &p.frag);
    let blend_attachments = vec![
        vk::PipelineColorBlendAttachmentState {
            color_write_mask: vk::ColorComponentFlags::RGBA,
            ..Default::default()
        };
        colors.len()
    ];
    let blend = tuff::PipelineColorBlendStateCreateInfo::new().attachments(&blend_attachments);
    let (mut made, _) = pipelines::with_graphics_info(&stages, &p.graphics_layout, pass, |info| {
        let mut rendering = tuff::PipelineRenderingCreateInfo::new()
            .view_mask(view_mask)
            .color_attachment_formats(colors)
            .depth_attachment_format(depth)
            .stencil_attachment_format(stencil);
        let info = info
            .render_pass(None)
            .color_blend_state(Some(&blend))
            .depth_stencil_state(Some(depth_stencil))
            .push_next(&mut rendering);
        s.device.create_graphics_pipelines(None, &[info])
    })
    .expect("pipeline");
    made.pop().expect("one pipeline")
}

/// A color attachment of `view` (or none) for dynamic rendering.
fn color_attachment(view: Option<&tuff::ImageView>) -> [tuff::RenderingAttachmentInfo<'_>; 1] {
    [tuff::RenderingAttachmentInfo::new()
        .image_view(view)
        .image_layout(vk::ImageLayout::COLOR_ATTACHMENT_OPTIMAL)
        .load_op(vk::AttachmentLoadOp::DONT_CARE)
        .store_op(vk::AttachmentStoreOp::DONT_CARE)]
}

/// In dynamic rendering, a draw's pipeline must have been made for the instance's
/// view mask and attachment formats (`UNDEFINED` where the instance has no view).
#[test]
fn dynamic_rendering_draws_check_their_pipeline_formats() {
    let _serial = vulkan::serial();
    let s = setup_full_features(true);
    let target = s.color_target(SIZE, vk::ImageUsageFlags::empty());
    let p = pipelines::pipelines(&s, &target);
    let usage = vk::BufferUsageFlags::INDIRECT_BUFFER | vk::BufferUsageFlags::INDEX_BUFFER;
    let (args, _memory) = pipelines::host_buffer(&s, 256, usage);
    let (ds_format, _ds_image, _ds_memory, ds_view) = depth_stencil_view(&s);
    let rgba = vk::Format::R8G8B8A8_UNORM;
    let none = vk::Format::UNDEFINED;
    let pass = &target.render_pass;
    let make = |mask, colors: &[vk::Format], depth, stencil| {
        rendering_pipeline(&s, &p, pass, mask, colors, depth, stencil)
    };
    let view_mask = make(1, &[rgba], none, none);
    let two_colors = make(0, &[rgba, rgba], none, none);
    let other_color = make(0, &[vk::Format::R8_UNORM], none, none);
    let color = make(0, &[rgba], none, none);
    let stencil_only = make(0, &[rgba], none, ds_format);
    let depth_only = make(0, &[rgba], ds_format, none);

    let with_view = color_attachment(Some(&target.view));
    let without_view = color_attachment(None);
    let ds_attachment = tuff::RenderingAttachmentInfo::new()
        .image_view(Some(&ds_view))
        .image_layout(vk::ImageLayout::DEPTH_STENCIL_ATTACHMENT_OPTIMAL)
        .load_op(vk::AttachmentLoadOp::DONT_CARE)
        .store_op(vk::AttachmentStoreOp::DONT_CARE);
    let info = |colors| {
        tuff::RenderingInfo::new()
            .render_area(area())
            .layer_count(1)
            .color_attachments(colors)
    };
    let color_only = info(&with_view);
    let null_color = info(&without_view);
    let depth_stencil = info(&with_view)
        .depth_attachment(Some(&ds_attachment))
        .stencil_attachment(Some(&ds_attachment));
    // (rule suffix, the instance, the pipeline, whether the layer checks the rule)
    let cases = [
        ("viewMask-06178", &color_only, &view_mask, true),
        ("colorAttachmentCount-06179", &color_only, &two_colors, true),
        (
            "colorAttachmentCount-06180",
            &color_only,
            &other_color,
            true,
        ),
        ("colorAttachmentCount-07616", &null_color, &color, false),
        (
            "pDepthAttachment-06181",
            &depth_stencil,
            &stencil_only,
            true,
        ),
        ("pDepthAttachment-07617", &color_only, &depth_only, false),
        (
            "pStencilAttachment-06182",
            &depth_stencil,
            &depth_only,
            true,
        ),
        (
            "pStencilAttachment-07618",
            &color_only,
            &stencil_only,
            false,
        ),
    ];
    let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    for (command, draw) in draws::<tuff::InRendering>(&args, &args) {
        for (suffix, rendering, pipeline, layer_checks) in &cases {
            let rule = format!("VUID-{command}-{suffix}");
            for unchecked in [false, true] {
                let rec = cb
                    .begin(&tuff::CommandBufferBeginInfo::new())
                    .expect("begin");
                let mut rec = rec.begin_rendering(rendering);
                rec.bind_pipeline(vk::PipelineBindPoint::GRAPHICS, pipeline)
                    .expect("bind");
                let viewport = vk::Viewport {
                    width: SIZE as f32,
                    height: SIZE as f32,
                    max_depth: 1.0,
                    ..Default::default()
                };
                rec.set_viewport(0, &[viewport]).expect("viewport");
                rec.set_scissor(0, &[area()]).expect("scissor");
                if unchecked {
                    s.messages.abort_on_error(true);
                    let _ = draw(&mut rec, true);
                    s.messages.abort_on_error(false);
                    let said = s.messages.take();
                    if *layer_checks {
                        assert!(
                            said.iter().any(|m| m.contains(&rule)),
                            "the layer did not name {rule}; it said {said:?}"
                        );
                    } else {
                        // The 1.3.239 layer does not check the rules of attachments
                        // without a view: tuff's error alone proves them (the command
                        // buffer is never submitted).
                        assert!(said.is_empty(), "the layer said {said:?}");
                    }
                } else {
                    assert_eq!(vuid(draw(&mut rec, false)), rule);
                    assert_silent(&s.messages);
                }
                drop(rec);
            }
        }
    }
    assert_silent(&s.messages);
}

/// A direct draw fetches its vertices inside the bound vertex buffers: past the
/// buffer's end (or its bound offset leaves too little) is refused.
#[test]
fn direct_draws_fetch_inside_their_vertex_buffers() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let dynamic = [D::VIEWPORT, D::SCISSOR];
    // (bound offset, vertex count, first vertex, refused)
    let cases = [
        (0, 3, 0, false),
        (0, 4, 0, true),
        (0, 2, 1, false),
        (0, 2, 2, true),
        (20, 2, 0, false),
        (20, 3, 0, true),
    ]
    .map(|(offset, count, first, refused)| VertexDraw {
        bind: Box::new(move |r, vertices| r.bind_vertex_buffers(0, vertices, &[offset])),
        count,
        first,
        refused,
    });
    // The 1.3.239 layer does not check vertex fetches: tuff's error alone proves
    // the rule (the command buffer is never submitted).
    vertex_draws(&s, &dynamic, cases, "VUID-vkCmdDraw-None-02721", false);
}

/// How a draw of [`vertex_draws`] binds its vertex buffer.
type BindVertices = dyn Fn(&mut Inside<'_>, &tuff::Buffer) -> tuff::Result<()>;

/// One draw of [`vertex_draws`]: how it binds the vertex buffer, the vertices it
/// draws, and whether tuff refuses it.
struct VertexDraw {
    bind: Box<BindVertices>,
    count: u32,
    first: u32,
    refused: bool,
}

/// Records each draw with the vertex pipeline (of `dynamic` states) and a 60-byte
/// vertex buffer bound as the draw says: a refused one names `rule`, through
/// `draw_unchecked` too where `layer` says the layer checks it (else the layer
/// must say nothing); the others record.
fn vertex_draws<const N: usize>(
    s: &Setup,
    dynamic: &[D],
    draws: [VertexDraw; N],
    rule: &str,
    layer: bool,
) {
    let target = s.color_target(SIZE, vk::ImageUsageFlags::empty());
    let layout = s
        .device
        .create_pipeline_layout(&tuff::PipelineLayoutCreateInfo::new())
        .expect("layout");
    // Binding 0: 20-byte vertices, each reaching 20 bytes past its start.
    let pipeline = pipelines::vertex_pipeline_with(s, &layout, &target.render_pass, dynamic);
    let (vertices, _memory) = pipelines::host_buffer(s, 60, vk::BufferUsageFlags::VERTEX_BUFFER);
    let clear = [vk::ClearValue::default()];
    let begin = tuff::RenderPassBeginInfo::new(&target.render_pass, &target.framebuffer)
        .render_area(area())
        .clear_values(&clear);
    let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    for d in draws {
        for unchecked in [false, true] {
            if unchecked && !d.refused {
                continue;
            }
            let rec = cb
                .begin(&tuff::CommandBufferBeginInfo::new())
                .expect("begin");
            let mut rec = rec.begin_render_pass(&begin, vk::SubpassContents::INLINE);
            rec.bind_pipeline(vk::PipelineBindPoint::GRAPHICS, &pipeline)
                .expect("bind");
            set_viewport(&mut rec);
            set_scissor(&mut rec);
            (d.bind)(&mut rec, &vertices).expect("vertex buffer");
            if unchecked {
                s.messages.abort_on_error(true);
                // SAFETY: the layer skips the call it reports, and the command
                // buffer is never submitted.
                let _ = unsafe { rec.draw_unchecked(d.count, 1, d.first, 0) };
                s.messages.abort_on_error(false);
                let said = s.messages.take();
                let named = said.iter().any(|m| m.contains(rule));
                assert!(
                    if layer { named } else { said.is_empty() },
                    "the layer said {said:?}"
                );
            } else if d.refused {
                assert_eq!(vuid(rec.draw(d.count, 1, d.first, 0)), rule);
            } else {
                rec.draw(d.count, 1, d.first, 0)
                    .expect("a draw inside the buffer");
            }
            drop(rec);
        }
    }
    assert_silent(&s.messages);
}

/// A graphics pipeline whose fragment shader `code` reads a storage image at set 0
/// binding 0, with its layout and a set that holds `view` there in `GENERAL`.
struct ImageDraw {
    _module: tuff::ShaderModule,
    _set_layout: tuff::DescriptorSetLayout,
    layout: tuff::PipelineLayout,
    pipeline: tuff::Pipeline,
    _pool: tuff::DescriptorPool,
    set: tuff::DescriptorSet,
}

fn image_draw(
    s: &Setup,
    p: &pipelines::Pipelines,
    pass: &tuff::RenderPass,
    view: Option<&tuff::ImageView>,
    code: &[u8],
) -> ImageDraw {
    // A storage image descriptor reads no sampler; the struct takes one.
    let sampler = s
        .device
        .create_sampler(&tuff::SamplerCreateInfo::new())
        .expect("sampler");
    descriptor_draw(
        s,
        p,
        pass,
        vk::DescriptorType::STORAGE_IMAGE,
        view.map(|v| (v, &sampler)),
        code,
    )
}

/// [`image_draw`] with a descriptor of type `ty` (an image type) that holds the view
/// and sampler of `written`, if given.
fn descriptor_draw(
    s: &Setup,
    p: &pipelines::Pipelines,
    pass: &tuff::RenderPass,
    ty: vk::DescriptorType,
    written: Option<(&tuff::ImageView, &tuff::Sampler)>,
    code: &[u8],
) -> ImageDraw {
    let d = &s.device;
    let module = tuff_setup::shader(s, code);
    let bindings = [tuff::DescriptorSetLayoutBinding::new()
        .binding(0)
        .descriptor_type(ty)
        .descriptor_count(1)
        .stage_flags(vk::ShaderStageFlags::FRAGMENT)];
    let set_layout = d
        .create_descriptor_set_layout(
            &tuff::DescriptorSetLayoutCreateInfo::new().bindings(&bindings),
        )
        .expect("set layout");
    let set_layouts = tuff::HandleSlice::new(&[&set_layout]);
    let layout = d
        .create_pipeline_layout(&tuff::PipelineLayoutCreateInfo::new().set_layouts(&set_layouts))
        .expect("pipeline layout");
    let stages = pipelines::test_stages(&p.vert, &module);
    let (mut made, _) = pipelines::with_graphics_info(&stages, &layout, pass, |info| {
        d.create_graphics_pipelines(None, &[info])
    })
    .expect("pipeline");
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
        .expect("pool");
    let set = d
        .allocate_descriptor_sets(
            &pool,
            &tuff::DescriptorSetAllocateInfo::new(&pool).set_layouts(&set_layout),
        )
        .expect("set")
        .pop()
        .expect("one set");
    if let Some((view, sampler)) = written {
        let images = [tuff::DescriptorImageInfo::new()
            .sampler(Some(sampler))
            .image_view(Some(view))
            .image_layout(vk::ImageLayout::GENERAL)];
        d.update_descriptor_sets(
            &[tuff::WriteDescriptorSet::new(&set)
                .dst_binding(0)
                .descriptor_type(ty)
                .image_info(&images)],
            &[],
        )
        .expect("the storage image");
    }
    ImageDraw {
        _module: module,
        _set_layout: set_layout,
        layout,
        pipeline: made.pop().expect("one pipeline"),
        _pool: pool,
        set,
    }
}

/// Each draw command reads its sets' image views with its shaders' image types: a
/// 2D view where the fragment shader reads a 2D array image breaks the view type
/// rule, a UNORM view where it reads unsigned integer texels the numeric format
/// rule; a set whose storage image was never written breaks the rule that the
/// descriptors a shader reads are valid; and atomics on a view whose format has
/// none (RGBA8_UINT) the atomic rule.
#[test]
fn draws_read_views_their_shaders_can_read() {
    let _serial = vulkan::serial();
    // Atomics in a fragment shader need fragmentStoresAndAtomics.
    let s = setup_full_features(true);
    let target = s.color_target(SIZE, vk::ImageUsageFlags::empty());
    let p = pipelines::pipelines(&s, &target);
    let usage = vk::BufferUsageFlags::INDIRECT_BUFFER | vk::BufferUsageFlags::INDEX_BUFFER;
    let (args, _memory) = pipelines::host_buffer(&s, 256, usage);
    let (_image, _image_memory, view) = pipelines::storage_image(&s, vk::ImageUsageFlags::empty());
    // An unsigned integer view whose format has no atomics, for the atomic shader.
    let (_uint_image, _uint_memory, uint_view) =
        pipelines::storage_image_of(&s, vk::Format::R8G8B8A8_UINT, vk::ImageUsageFlags::empty());
    let cases: [(&[u8], Option<&tuff::ImageView>, &str); 5] = [
        (
            include_bytes!("../shaders/spv/image_array.frag.spv"),
            Some(&view),
            "viewType-07752",
        ),
        (
            include_bytes!("../shaders/spv/image_uint.frag.spv"),
            Some(&view),
            "format-07753",
        ),
        (
            include_bytes!("../shaders/spv/image_array.frag.spv"),
            None,
            "None-02699",
        ),
        (
            include_bytes!("../shaders/spv/atomic.frag.spv"),
            Some(&uint_view),
            "None-02691",
        ),
        // lavapipe reads no storage format without a format.
        (
            include_bytes!("../shaders/spv/image_unknown.frag.spv"),
            Some(&view),
            "OpTypeImage-07028",
        ),
    ];
    let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    for (code, view, suffix) in cases {
        let reader = image_draw(&s, &p, &target.render_pass, view, code);
        breaks_with_every_draw(&s, &mut cb, &target, &reader, &args, suffix);
    }
    assert_silent(&s.messages);
}

/// Each draw command reads the push constants its fragment shader declares: before
/// any push, tuff refuses the safe call (the test device does not enable
/// maintenance4; the 1.3.239 layer does not check the rule). A push with a
/// layout of other push-constant ranges leaves the earlier bytes undefined, so a draw
/// after it is refused again though the same state passed before.
#[test]
fn draws_read_pushed_constants() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let target = s.color_target(SIZE, vk::ImageUsageFlags::empty());
    let p = pipelines::pipelines(&s, &target);
    let usage = vk::BufferUsageFlags::INDIRECT_BUFFER | vk::BufferUsageFlags::INDEX_BUFFER;
    let (args, _memory) = pipelines::host_buffer(&s, 256, usage);
    let other_ranges = [vk::PushConstantRange {
        stage_flags: vk::ShaderStageFlags::VERTEX,
        offset: 0,
        size: 4,
    }];
    let other = s
        .device
        .create_pipeline_layout(
            &tuff::PipelineLayoutCreateInfo::new().push_constant_ranges(&other_ranges),
        )
        .expect("layout");
    let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let clear = [vk::ClearValue::default()];
    let begin = tuff::RenderPassBeginInfo::new(&target.render_pass, &target.framebuffer)
        .render_area(area())
        .clear_values(&clear);
    for (command, draw) in draws::<tuff::InRenderPass>(&args, &args) {
        let rule = format!("VUID-{command}-maintenance4-06425");
        for unchecked in [false, true] {
            let rec = cb
                .begin(&tuff::CommandBufferBeginInfo::new())
                .expect("begin");
            let mut rec = rec.begin_render_pass(&begin, vk::SubpassContents::INLINE);
            rec.bind_pipeline(vk::PipelineBindPoint::GRAPHICS, &p.graphics)
                .expect("bind");
            set_viewport(&mut rec);
            set_scissor(&mut rec);
            if unchecked {
                s.messages.abort_on_error(true);
                let _ = draw(&mut rec, true);
                s.messages.abort_on_error(false);
                // The 1.3.239 layer does not check the rule: tuff's error alone proves
                // it (the values read are undefined, no memory is touched).
                let said = s.messages.take();
                assert!(said.is_empty(), "the layer now checks {rule}: {said:?}");
            } else {
                assert_eq!(vuid(draw(&mut rec, false)), rule);
                assert_silent(&s.messages);
                // Bytes 4 to 8 of the 16 the shader reads left out: refused, naming
                // the first byte missing; pushed too, the draw passes.
                let stage = vk::ShaderStageFlags::FRAGMENT;
                let layout = &p.graphics_layout;
                rec.push_constants(layout, stage, 0, &[0u8; 4])
                    .expect("push");
                rec.push_constants(layout, stage, 8, &[0u8; 8])
                    .expect("push");
                match draw(&mut rec, false) {
                    Err(tuff::Error::Validation { vuid, message }) => {
                        assert_eq!(vuid, rule);
                        assert!(message.contains("byte 4 was not pushed"), "{message}");
                    }
                    other => panic!("{command} with a gap in its push constants: {other:?}"),
                }
                rec.push_constants(layout, stage, 4, &[0u8; 4])
                    .expect("push");
                draw(&mut rec, false).expect("a draw with every byte pushed");
                pipelines::push_color(&mut rec, &p);
                draw(&mut rec, false).expect("a draw with its push constants");
                rec.push_constants(&other, vk::ShaderStageFlags::VERTEX, 0, &[0u8; 4])
                    .expect("push with another layout");
                assert_eq!(vuid(draw(&mut rec, false)), rule);
            }
            drop(rec);
        }
    }
    assert_silent(&s.messages);
}

/// Each draw command checks the viewport and scissor counts it draws with where its
/// pipeline has them dynamic with their counts: against the count the pipeline has
/// static (03417, 03418), or against each other (03419).
#[test]
fn draws_use_the_viewport_and_scissor_counts_they_set() {
    let _serial = vulkan::serial();
    // Two viewports need multiViewport.
    let s = setup_full_features(true);
    let target = s.color_target(SIZE, vk::ImageUsageFlags::empty());
    let p = pipelines::pipelines(&s, &target);
    let usage = vk::BufferUsageFlags::INDIRECT_BUFFER | vk::BufferUsageFlags::INDEX_BUFFER;
    let (args, _memory) = pipelines::host_buffer(&s, 256, usage);
    let viewport = vk::Viewport {
        width: SIZE as f32,
        height: SIZE as f32,
        max_depth: 1.0,
        ..Default::default()
    };
    let made = |counts: (u32, u32), dynamic: &[D]| {
        let stages = pipelines::test_stages(&p.vert, &p.frag);
        let viewports = tuff::PipelineViewportStateCreateInfo::new()
            .viewport_count(counts.0)
            .scissor_count(counts.1);
        let states = tuff::PipelineDynamicStateCreateInfo::new().dynamic_states(dynamic);
        let (mut made, _) = pipelines::with_graphics_info(
            &stages,
            &p.graphics_layout,
            &target.render_pass,
            |info| {
                let info = info
                    .viewport_state(Some(&viewports))
                    .dynamic_state(Some(&states));
                s.device.create_graphics_pipelines(None, &[info])
            },
        )
        .expect("pipeline");
        made.pop().expect("one pipeline")
    };
    let viewport_with_count = made((0, 2), &[D::VIEWPORT_WITH_COUNT, D::SCISSOR]);
    let scissor_with_count = made((2, 0), &[D::VIEWPORT, D::SCISSOR_WITH_COUNT]);
    let both = made((0, 0), &[D::VIEWPORT_WITH_COUNT, D::SCISSOR_WITH_COUNT]);
    let cases: [(&str, &tuff::Pipeline, Prepare<'_>); 3] = [
        (
            "viewportCount-03417",
            &viewport_with_count,
            Box::new(|r| {
                r.set_viewport_with_count(&[viewport]).expect("viewports");
                r.set_scissor(0, &[area(), area()]).expect("scissors");
            }),
        ),
        (
            "scissorCount-03418",
            &scissor_with_count,
            Box::new(|r| {
                r.set_viewport(0, &[viewport, viewport]).expect("viewports");
                r.set_scissor_with_count(&[area()]).expect("scissors");
            }),
        ),
        (
            "viewportCount-03419",
            &both,
            Box::new(|r| {
                r.set_viewport_with_count(&[viewport]).expect("viewports");
                r.set_scissor_with_count(&[area(), area()])
                    .expect("scissors");
            }),
        ),
    ];
    let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let clear = [vk::ClearValue::default()];
    let begin = tuff::RenderPassBeginInfo::new(&target.render_pass, &target.framebuffer)
        .render_area(area())
        .clear_values(&clear);
    for (command, draw) in draws::<tuff::InRenderPass>(&args, &args) {
        for (suffix, pipeline, prepare) in &cases {
            let rule = format!("VUID-{command}-{suffix}");
            tuff_setup::breaks(&s, &rule, tuff_setup::Layer::Names, |unchecked| {
                let rec = cb
                    .begin(&tuff::CommandBufferBeginInfo::new())
                    .expect("begin");
                let mut rec = rec.begin_render_pass(&begin, vk::SubpassContents::INLINE);
                rec.bind_pipeline(vk::PipelineBindPoint::GRAPHICS, pipeline)
                    .expect("bind");
                prepare(&mut rec);
                pipelines::push_color(&mut rec, &p);
                let r = draw(&mut rec, unchecked);
                drop(rec);
                r
            });
        }
    }
    assert_silent(&s.messages);
}

/// A direct draw in a multiview render pass instance draws no instance past
/// maxMultiviewInstanceIndex (lavapipe's is below the last 32-bit first instance):
/// tuff refuses the safe call (the 1.3.239 layer does not check the rule).
#[test]
fn multiview_draws_stay_under_the_instance_limit() {
    let _serial = vulkan::serial();
    let s = setup_full_features(true);
    let target = s.color_target(SIZE, vk::ImageUsageFlags::empty());
    let p = pipelines::pipelines(&s, &target);
    let (index, _memory) = pipelines::host_buffer(&s, 64, vk::BufferUsageFlags::INDEX_BUFFER);
    let rgba = vk::Format::R8G8B8A8_UNORM;
    let none = vk::Format::UNDEFINED;
    let pipeline = rendering_pipeline(&s, &p, &target.render_pass, 1, &[rgba], none, none);
    let with_view = color_attachment(Some(&target.view));
    let rendering = tuff::RenderingInfo::new()
        .render_area(area())
        .layer_count(1)
        .view_mask(1)
        .color_attachments(&with_view);
    type Direct = fn(&mut tuff::Recorder<'_, tuff::InRendering>, bool) -> tuff::Result<()>;
    let commands: [(&str, Direct); 2] = [
        ("vkCmdDraw", |r, unchecked| {
            if unchecked {
                unsafe { r.draw_unchecked(3, 1, 0, u32::MAX) }
            } else {
                r.draw(3, 1, 0, u32::MAX)
            }
        }),
        ("vkCmdDrawIndexed", |r, unchecked| {
            if unchecked {
                unsafe { r.draw_indexed_unchecked(3, 1, 0, 0, u32::MAX) }
            } else {
                r.draw_indexed(3, 1, 0, 0, u32::MAX)
            }
        }),
    ];
    let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    for (command, draw) in commands {
        let rule = format!("VUID-{command}-maxMultiviewInstanceIndex-02688");
        tuff_setup::breaks(&s, &rule, tuff_setup::Layer::Silent, |unchecked| {
            let rec = cb
                .begin(&tuff::CommandBufferBeginInfo::new())
                .expect("begin");
            let mut rec = rec.begin_rendering(&rendering);
            rec.bind_pipeline(vk::PipelineBindPoint::GRAPHICS, &pipeline)
                .expect("bind");
            rec.bind_index_buffer(&index, 0, vk::IndexType::UINT32)
                .expect("index buffer");
            let viewport = vk::Viewport {
                width: SIZE as f32,
                height: SIZE as f32,
                max_depth: 1.0,
                ..Default::default()
            };
            rec.set_viewport(0, &[viewport]).expect("viewport");
            rec.set_scissor(0, &[area()]).expect("scissor");
            // The 1.3.239 layer does not check the rule: tuff's error alone
            // proves it (the command buffer is never submitted).
            let r = draw(&mut rec, unchecked);
            drop(rec);
            r
        });
    }
    assert_silent(&s.messages);
}

/// A D32_SFLOAT_S8_UINT depth/stencil attachment image of the test size, its memory
/// and a view of both aspects.
fn depth_stencil_view(s: &Setup) -> (vk::Format, tuff::Image, tuff::DeviceMemory, tuff::ImageView) {
    let d = &s.device;
    let format = vk::Format::D32_SFLOAT_S8_UINT;
    let image = d
        .create_image(
            &tuff::ImageCreateInfo::new()
                .image_type(vk::ImageType::TYPE_2D)
                .format(format)
                .extent(vk::Extent3D {
                    width: SIZE,
                    height: SIZE,
                    depth: 1,
                })
                .mip_levels(1)
                .array_layers(1)
                .samples(vk::SampleCountFlags::TYPE_1)
                .usage(vk::ImageUsageFlags::DEPTH_STENCIL_ATTACHMENT),
        )
        .expect("depth image");
    let memory = s.bind_image(&image);
    let view = d
        .create_image_view(
            &tuff::ImageViewCreateInfo::new(&image)
                .view_type(vk::ImageViewType::TYPE_2D)
                .format(format)
                .subresource_range(vk::ImageSubresourceRange {
                    aspect_mask: vk::ImageAspectFlags::DEPTH | vk::ImageAspectFlags::STENCIL,
                    base_mip_level: 0,
                    level_count: 1,
                    base_array_layer: 0,
                    layer_count: 1,
                }),
        )
        .expect("depth view");
    (format, image, memory, view)
}

/// Depth/stencil states that write depth, and that write stencil.
fn writing_states() -> [tuff::PipelineDepthStencilStateCreateInfo<'static>; 2] {
    let writes = vk::StencilOpState {
        fail_op: vk::StencilOp::REPLACE,
        pass_op: vk::StencilOp::REPLACE,
        depth_fail_op: vk::StencilOp::REPLACE,
        compare_op: vk::CompareOp::ALWAYS,
        compare_mask: !0,
        write_mask: !0,
        reference: 1,
    };
    [
        tuff::PipelineDepthStencilStateCreateInfo::new()
            .depth_test_enable(true)
            .depth_write_enable(true)
            .depth_compare_op(vk::CompareOp::ALWAYS),
        tuff::PipelineDepthStencilStateCreateInfo::new()
            .stencil_test_enable(true)
            .front(writes)
            .back(writes),
    ]
}

/// A draw that writes depth or stencil where the render pass instance has that
/// aspect of its depth/stencil attachment in a read-only layout is refused: in a
/// render pass (06886, 06887) and in dynamic rendering, by the layout the
/// attachment info names (06172 to 06177, which the 1.3.239 layer does not check).
#[test]
fn draws_do_not_write_read_only_depth_or_stencil() {
    let _serial = vulkan::serial();
    // Separate depth and stencil layouts need separateDepthStencilLayouts.
    let s = setup_full_features(true);
    let d = &s.device;
    let target = s.color_target(SIZE, vk::ImageUsageFlags::empty());
    let p = pipelines::pipelines(&s, &target);
    let usage = vk::BufferUsageFlags::INDIRECT_BUFFER | vk::BufferUsageFlags::INDEX_BUFFER;
    let (args, _memory) = pipelines::host_buffer(&s, 256, usage);
    let (ds_format, _ds_image, _ds_memory, ds_view) = depth_stencil_view(&s);
    let rgba = vk::Format::R8G8B8A8_UNORM;
    let [depth_writes, stencil_writes] = writing_states();
    let viewport = vk::Viewport {
        width: SIZE as f32,
        height: SIZE as f32,
        max_depth: 1.0,
        ..Default::default()
    };
    type L = vk::ImageLayout;
    let read_only = L::DEPTH_STENCIL_READ_ONLY_OPTIMAL;

    // A render pass whose subpass reads its depth/stencil attachment only.
    let attachments = [
        vk::AttachmentDescription {
            format: rgba,
            samples: vk::SampleCountFlags::TYPE_1,
            load_op: vk::AttachmentLoadOp::DONT_CARE,
            store_op: vk::AttachmentStoreOp::DONT_CARE,
            stencil_load_op: vk::AttachmentLoadOp::DONT_CARE,
            stencil_store_op: vk::AttachmentStoreOp::DONT_CARE,
            initial_layout: L::UNDEFINED,
            final_layout: L::COLOR_ATTACHMENT_OPTIMAL,
            ..Default::default()
        },
        vk::AttachmentDescription {
            format: ds_format,
            samples: vk::SampleCountFlags::TYPE_1,
            load_op: vk::AttachmentLoadOp::DONT_CARE,
            store_op: vk::AttachmentStoreOp::DONT_CARE,
            stencil_load_op: vk::AttachmentLoadOp::DONT_CARE,
            stencil_store_op: vk::AttachmentStoreOp::DONT_CARE,
            initial_layout: read_only,
            final_layout: read_only,
            ..Default::default()
        },
    ];
    let color = [vk::AttachmentReference {
        attachment: 0,
        layout: L::COLOR_ATTACHMENT_OPTIMAL,
    }];
    let depth = vk::AttachmentReference {
        attachment: 1,
        layout: read_only,
    };
    let subpass = [tuff::SubpassDescription::new()
        .pipeline_bind_point(vk::PipelineBindPoint::GRAPHICS)
        .color_attachments(&color)
        .depth_stencil_attachment(Some(&depth))];
    let pass = d
        .create_render_pass(
            &tuff::RenderPassCreateInfo::new()
                .attachments(&attachments)
                .subpasses(&subpass),
        )
        .expect("render pass");
    let views = tuff::HandleSlice::new(&[&target.view, &ds_view]);
    let framebuffer = d
        .create_framebuffer(
            &tuff::FramebufferCreateInfo::new(&pass)
                .attachments(&views)
                .width(SIZE)
                .height(SIZE)
                .layers(1),
        )
        .expect("framebuffer");
    let pass_pipeline = |state: &tuff::PipelineDepthStencilStateCreateInfo<'_>| {
        let stages = pipelines::test_stages(&p.vert, &p.frag);
        let (mut made, _) =
            pipelines::with_graphics_info(&stages, &p.graphics_layout, &pass, |info| {
                let info = info.depth_stencil_state(Some(state));
                d.create_graphics_pipelines(None, &[info])
            })
            .expect("pipeline");
        made.pop().expect("one pipeline")
    };
    let pass_cases = [
        ("None-06886", pass_pipeline(&depth_writes)),
        ("None-06887", pass_pipeline(&stencil_writes)),
    ];
    let clear = [vk::ClearValue::default(); 2];
    let begin = tuff::RenderPassBeginInfo::new(&pass, &framebuffer)
        .render_area(area())
        .clear_values(&clear);
    let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    for (command, draw) in draws::<tuff::InRenderPass>(&args, &args) {
        for (suffix, pipeline) in &pass_cases {
            let rule = format!("VUID-{command}-{suffix}");
            tuff_setup::breaks(&s, &rule, tuff_setup::Layer::Names, |unchecked| {
                let rec = cb
                    .begin(&tuff::CommandBufferBeginInfo::new())
                    .expect("begin");
                let mut rec = rec.begin_render_pass(&begin, vk::SubpassContents::INLINE);
                rec.bind_pipeline(vk::PipelineBindPoint::GRAPHICS, pipeline)
                    .expect("bind");
                rec.set_viewport(0, &[viewport]).expect("viewport");
                rec.set_scissor(0, &[area()]).expect("scissor");
                let r = draw(&mut rec, unchecked);
                drop(rec);
                r
            });
        }
    }

    // Where the pipeline has depth writes dynamic, the value set decides.
    let dynamic_states = [D::VIEWPORT, D::SCISSOR, D::DEPTH_WRITE_ENABLE];
    let dynamic_write = {
        let stages = pipelines::test_stages(&p.vert, &p.frag);
        let states = tuff::PipelineDynamicStateCreateInfo::new().dynamic_states(&dynamic_states);
        let (mut made, _) =
            pipelines::with_graphics_info(&stages, &p.graphics_layout, &pass, |info| {
                let info = info
                    .depth_stencil_state(Some(&depth_writes))
                    .dynamic_state(Some(&states));
                d.create_graphics_pipelines(None, &[info])
            })
            .expect("pipeline");
        made.pop().expect("one pipeline")
    };
    let rec = cb
        .begin(&tuff::CommandBufferBeginInfo::new())
        .expect("begin");
    let mut rec = rec.begin_render_pass(&begin, vk::SubpassContents::INLINE);
    rec.bind_pipeline(vk::PipelineBindPoint::GRAPHICS, &dynamic_write)
        .expect("bind");
    rec.set_viewport(0, &[viewport]).expect("viewport");
    rec.set_scissor(0, &[area()]).expect("scissor");
    rec.set_depth_write_enable(false);
    rec.draw(3, 1, 0, 0).expect("a draw with depth writes off");
    rec.set_depth_write_enable(true);
    assert_eq!(vuid(rec.draw(3, 1, 0, 0)), "VUID-vkCmdDraw-None-06886");
    drop(rec);

    // A pipeline that has the stencil operations static, bound in between, leaves
    // the back face's operations undefined: setting the front face's only is not
    // enough.
    let stencil_dynamic = [D::VIEWPORT, D::SCISSOR, D::STENCIL_OP];
    let dynamic_ops = {
        let stages = pipelines::test_stages(&p.vert, &p.frag);
        let states = tuff::PipelineDynamicStateCreateInfo::new().dynamic_states(&stencil_dynamic);
        let (mut made, _) =
            pipelines::with_graphics_info(&stages, &p.graphics_layout, &pass, |info| {
                let info = info
                    .depth_stencil_state(Some(&stencil_writes))
                    .dynamic_state(Some(&states));
                d.create_graphics_pipelines(None, &[info])
            })
            .expect("pipeline");
        made.pop().expect("one pipeline")
    };
    let keep = vk::StencilOp::KEEP;
    let rec = cb
        .begin(&tuff::CommandBufferBeginInfo::new())
        .expect("begin");
    let mut rec = rec.begin_render_pass(&begin, vk::SubpassContents::INLINE);
    rec.bind_pipeline(vk::PipelineBindPoint::GRAPHICS, &dynamic_ops)
        .expect("bind");
    rec.set_viewport(0, &[viewport]).expect("viewport");
    rec.set_scissor(0, &[area()]).expect("scissor");
    rec.set_stencil_op(
        vk::StencilFaceFlags::FRONT_AND_BACK,
        keep,
        keep,
        keep,
        vk::CompareOp::ALWAYS,
    );
    rec.draw(3, 1, 0, 0).expect("a draw that keeps the stencil");
    rec.bind_pipeline(vk::PipelineBindPoint::GRAPHICS, &pass_cases[1].1)
        .expect("bind the static pipeline");
    rec.bind_pipeline(vk::PipelineBindPoint::GRAPHICS, &dynamic_ops)
        .expect("bind again");
    rec.set_stencil_op(
        vk::StencilFaceFlags::FRONT,
        keep,
        keep,
        keep,
        vk::CompareOp::ALWAYS,
    );
    assert_eq!(vuid(rec.draw(3, 1, 0, 0)), "VUID-vkCmdDraw-None-06887");
    drop(rec);

    // Dynamic rendering: the rule follows the layout of the attachment info (the
    // 1.3.239 layer checks none of them).
    let rendering_with = |state| {
        rendering_pipeline_with(
            &s,
            &p,
            &target.render_pass,
            0,
            &[rgba],
            (ds_format, ds_format),
            state,
        )
    };
    let depth_pipeline = rendering_with(&depth_writes);
    let stencil_pipeline = rendering_with(&stencil_writes);
    let with_view = color_attachment(Some(&target.view));
    // (rule suffix, depth layout, stencil layout, the pipeline)
    let rendering_cases = [
        ("imageView-06172", read_only, read_only, &depth_pipeline),
        ("imageView-06173", read_only, read_only, &stencil_pipeline),
        (
            "imageView-06174",
            L::DEPTH_READ_ONLY_STENCIL_ATTACHMENT_OPTIMAL,
            L::DEPTH_READ_ONLY_STENCIL_ATTACHMENT_OPTIMAL,
            &depth_pipeline,
        ),
        (
            "imageView-06175",
            L::DEPTH_ATTACHMENT_STENCIL_READ_ONLY_OPTIMAL,
            L::DEPTH_ATTACHMENT_STENCIL_READ_ONLY_OPTIMAL,
            &stencil_pipeline,
        ),
        (
            "imageView-06176",
            L::DEPTH_READ_ONLY_OPTIMAL,
            L::STENCIL_ATTACHMENT_OPTIMAL,
            &depth_pipeline,
        ),
        (
            "imageView-06177",
            L::DEPTH_ATTACHMENT_OPTIMAL,
            L::STENCIL_READ_ONLY_OPTIMAL,
            &stencil_pipeline,
        ),
    ];
    for (command, draw) in draws::<tuff::InRendering>(&args, &args) {
        for (suffix, depth_layout, stencil_layout, pipeline) in &rendering_cases {
            let rule = format!("VUID-{command}-{suffix}");
            let attachment = |layout| {
                tuff::RenderingAttachmentInfo::new()
                    .image_view(Some(&ds_view))
                    .image_layout(layout)
                    .load_op(vk::AttachmentLoadOp::DONT_CARE)
                    .store_op(vk::AttachmentStoreOp::DONT_CARE)
            };
            let (depth, stencil) = (attachment(*depth_layout), attachment(*stencil_layout));
            let rendering = tuff::RenderingInfo::new()
                .render_area(area())
                .layer_count(1)
                .color_attachments(&with_view)
                .depth_attachment(Some(&depth))
                .stencil_attachment(Some(&stencil));
            tuff_setup::breaks(&s, &rule, tuff_setup::Layer::Silent, |unchecked| {
                let rec = cb
                    .begin(&tuff::CommandBufferBeginInfo::new())
                    .expect("begin");
                let mut rec = rec.begin_rendering(&rendering);
                rec.bind_pipeline(vk::PipelineBindPoint::GRAPHICS, pipeline)
                    .expect("bind");
                rec.set_viewport(0, &[viewport]).expect("viewport");
                rec.set_scissor(0, &[area()]).expect("scissor");
                // The 1.3.239 layer does not check these rules: tuff's error
                // alone proves them (the command buffer is never submitted).
                let r = draw(&mut rec, unchecked);
                drop(rec);
                r
            });
        }
    }
    assert_silent(&s.messages);
}

/// Each draw command rasterizes the sample count of the instance's attachments: a
/// pipeline of 4 samples in dynamic rendering into a single-sampled view is refused
/// by tuff, and the layer names the rule for the unchecked draw (by its sibling for
/// dynamic rendering, 06188).
#[test]
fn draws_rasterize_their_attachments_samples() {
    let _serial = vulkan::serial();
    let s = setup_full_features(true);
    let target = s.color_target(SIZE, vk::ImageUsageFlags::empty());
    let p = pipelines::pipelines(&s, &target);
    let usage = vk::BufferUsageFlags::INDIRECT_BUFFER | vk::BufferUsageFlags::INDEX_BUFFER;
    let (args, _memory) = pipelines::host_buffer(&s, 256, usage);
    let rgba = [vk::Format::R8G8B8A8_UNORM];
    let four = {
        let stages = pipelines::test_stages(&p.vert, &p.frag);
        let multisample = tuff::PipelineMultisampleStateCreateInfo::new()
            .rasterization_samples(vk::SampleCountFlags::TYPE_4);
        let (mut made, _) = pipelines::with_graphics_info(
            &stages,
            &p.graphics_layout,
            &target.render_pass,
            |info| {
                let mut rendering =
                    tuff::PipelineRenderingCreateInfo::new().color_attachment_formats(&rgba);
                let info = info
                    .render_pass(None)
                    .multisample_state(Some(&multisample))
                    .push_next(&mut rendering);
                s.device.create_graphics_pipelines(None, &[info])
            },
        )
        .expect("pipeline");
        made.pop().expect("one pipeline")
    };
    let with_view = color_attachment(Some(&target.view));
    let rendering = tuff::RenderingInfo::new()
        .render_area(area())
        .layer_count(1)
        .color_attachments(&with_view);
    let viewport = vk::Viewport {
        width: SIZE as f32,
        height: SIZE as f32,
        max_depth: 1.0,
        ..Default::default()
    };
    let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    for (command, draw) in draws::<tuff::InRendering>(&args, &args) {
        let rule = format!("VUID-{command}-rasterizationSamples-04740");
        // The 1.3.239 layer states the case in dynamic rendering by the sibling rule
        // of pipelines made with an attachment sample count info.
        let sibling = format!("VUID-{command}-colorAttachmentCount-06188");
        tuff_setup::breaks(
            &s,
            &rule,
            tuff_setup::Layer::NamesOr(&sibling),
            |unchecked| {
                let rec = cb
                    .begin(&tuff::CommandBufferBeginInfo::new())
                    .expect("begin");
                let mut rec = rec.begin_rendering(&rendering);
                rec.bind_pipeline(vk::PipelineBindPoint::GRAPHICS, &four)
                    .expect("bind");
                rec.set_viewport(0, &[viewport]).expect("viewport");
                rec.set_scissor(0, &[area()]).expect("scissor");
                let r = draw(&mut rec, unchecked);
                drop(rec);
                r
            },
        );
    }
    assert_silent(&s.messages);
}

/// Breaks `VUID-<command>-<suffix>` with each draw command over `draw`'s pipeline and
/// set (an indexed one binds `args` as its index buffer, an indirect one reads it):
/// tuff refuses the safe call, and the layer names the rule for the unchecked one.
fn breaks_with_every_draw(
    s: &Setup,
    cb: &mut tuff::CommandBuffer,
    target: &tuff_setup::ColorTarget,
    draw: &ImageDraw,
    args: &tuff::Buffer,
    suffix: &str,
) {
    for (command, call) in draws::<tuff::InRenderPass>(args, args) {
        let rule = format!("VUID-{command}-{suffix}");
        tuff_setup::breaks(s, &rule, tuff_setup::Layer::Names, |unchecked| {
            record_descriptor_draw(cb, target, draw, unchecked, &|rec, u| call(rec, u))
        });
    }
}

/// Records a render pass instance of `target` that binds `draw`'s pipeline and set,
/// sets the viewport and scissor, and makes one draw with `command` (`unchecked`:
/// through its `_unchecked` twin).
fn record_descriptor_draw(
    cb: &mut tuff::CommandBuffer,
    target: &tuff_setup::ColorTarget,
    draw: &ImageDraw,
    unchecked: bool,
    command: &dyn Fn(&mut Inside<'_>, bool) -> tuff::Result<()>,
) -> tuff::Result<()> {
    let clear = [vk::ClearValue::default()];
    let begin = tuff::RenderPassBeginInfo::new(&target.render_pass, &target.framebuffer)
        .render_area(area())
        .clear_values(&clear);
    let rec = cb
        .begin(&tuff::CommandBufferBeginInfo::new())
        .expect("begin");
    let mut rec = rec.begin_render_pass(&begin, vk::SubpassContents::INLINE);
    rec.bind_pipeline(vk::PipelineBindPoint::GRAPHICS, &draw.pipeline)
        .expect("bind");
    rec.bind_descriptor_sets(
        vk::PipelineBindPoint::GRAPHICS,
        &draw.layout,
        0,
        &draw.set,
        &[],
    )
    .expect("set");
    set_viewport(&mut rec);
    set_scissor(&mut rec);
    let r = command(&mut rec, unchecked);
    drop(rec);
    r
}

/// A draw samples its views only as their samplers allow: linear filtering or a
/// linear mipmap mode on an unsigned integer view (whose format lacks
/// SAMPLED_IMAGE_FILTER_LINEAR) breaks the linear filter rules; a sampler with
/// unnormalized coordinates sampling with an implicit LOD, or with an offset,
/// breaks the unnormalized coordinates rules. tuff refuses the safe draw, and the
/// layer names the same rule for the unchecked one.
#[test]
fn draws_sample_views_as_their_samplers_allow() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let d = &s.device;
    let target = s.color_target(SIZE, vk::ImageUsageFlags::empty());
    let p = pipelines::pipelines(&s, &target);
    let sampled = vk::ImageUsageFlags::SAMPLED;
    let (_uint_image, _uint_memory, uint_view) =
        pipelines::storage_image_of(&s, vk::Format::R8G8B8A8_UINT, sampled);
    let (_image, _memory, view) =
        pipelines::storage_image_of(&s, vk::Format::R8G8B8A8_UNORM, sampled);
    let sampler = |info: tuff::SamplerCreateInfo<'_>| d.create_sampler(&info).expect("sampler");
    let linear = sampler(
        tuff::SamplerCreateInfo::new()
            .mag_filter(vk::Filter::LINEAR)
            .min_filter(vk::Filter::LINEAR),
    );
    let mipmap = sampler(tuff::SamplerCreateInfo::new().mipmap_mode(vk::SamplerMipmapMode::LINEAR));
    let edge = vk::SamplerAddressMode::CLAMP_TO_EDGE;
    let unnormalized = sampler(
        tuff::SamplerCreateInfo::new()
            .unnormalized_coordinates(true)
            .address_mode_u(edge)
            .address_mode_v(edge)
            .address_mode_w(edge),
    );
    let sample_uint: &[u8] = include_bytes!("../shaders/spv/sample_uint.frag.spv");
    let sample_lod: &[u8] = include_bytes!("../shaders/spv/sample_lod.frag.spv");
    let cases = [
        (sample_uint, &uint_view, &linear, "magFilter-04553"),
        (sample_uint, &uint_view, &mipmap, "mipmapMode-04770"),
        (sample_uint, &uint_view, &unnormalized, "None-02703"),
        (sample_lod, &view, &unnormalized, "None-02704"),
    ];
    let usage = vk::BufferUsageFlags::INDIRECT_BUFFER | vk::BufferUsageFlags::INDEX_BUFFER;
    let (args, _args_memory) = pipelines::host_buffer(&s, 256, usage);
    let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    for (code, view, sampler, suffix) in cases {
        let ty = vk::DescriptorType::COMBINED_IMAGE_SAMPLER;
        let draw = descriptor_draw(&s, &p, &target.render_pass, ty, Some((view, sampler)), code);
        breaks_with_every_draw(&s, &mut cb, &target, &draw, &args, suffix);
    }
    assert_silent(&s.messages);
}

/// A draw's descriptors do not reach its attachments' memory: a storage image the
/// fragment shader writes that is the color attachment itself breaks the rule that
/// attachments are written only as attachments, and a sampled one the rule that
/// they are read only as attachments. tuff refuses both safe draws. The layer does
/// not judge these cases: an attachment in a render pass instance is in an
/// attachment layout, so the 1.3.239 layer names the descriptor's layout rule
/// (00344) instead, and the rules stay counted as the user's.
#[test]
fn draws_do_not_reach_their_attachments_through_descriptors() {
    let _serial = vulkan::serial();
    // Stores in a fragment shader need fragmentStoresAndAtomics.
    let s = setup_full_features(true);
    let usage = vk::ImageUsageFlags::STORAGE | vk::ImageUsageFlags::SAMPLED;
    let target = s.color_target(SIZE, usage);
    let p = pipelines::pipelines(&s, &target);
    let sampler = s
        .device
        .create_sampler(&tuff::SamplerCreateInfo::new())
        .expect("sampler");
    let cases = [
        (
            include_bytes!("../shaders/spv/image_store.frag.spv").as_slice(),
            vk::DescriptorType::STORAGE_IMAGE,
            "None-06537",
        ),
        (
            include_bytes!("../shaders/spv/sample_lod.frag.spv").as_slice(),
            vk::DescriptorType::COMBINED_IMAGE_SAMPLER,
            "None-06538",
        ),
    ];
    let usage = vk::BufferUsageFlags::INDIRECT_BUFFER | vk::BufferUsageFlags::INDEX_BUFFER;
    let (args, _args_memory) = pipelines::host_buffer(&s, 256, usage);
    let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    for (code, ty, suffix) in cases {
        let written = Some((&target.view, &sampler));
        let draw = descriptor_draw(&s, &p, &target.render_pass, ty, written, code);
        for (command, call) in draws::<tuff::InRenderPass>(&args, &args) {
            let recorded =
                record_descriptor_draw(&mut cb, &target, &draw, false, &|rec, u| call(rec, u));
            assert_eq!(vuid(recorded), format!("VUID-{command}-{suffix}"));
        }
    }
    assert_silent(&s.messages);
}

/// An indexed draw on a device without robustBufferAccess fetches whatever vertex
/// its indices name, which the host cannot know: with a vertex buffer of three
/// vertices, tuff refuses it (the 1.3.239 layer does not check the indices'
/// vertices: the error alone proves the rule); a device with robustBufferAccess
/// keeps the fetches inside the buffer, and the same draw is recorded.
#[test]
fn indexed_draws_fetch_inside_their_vertex_buffers() {
    let _serial = vulkan::serial();
    let robust = vk::PhysicalDeviceFeatures::default().robust_buffer_access(true);
    for (robust, s) in [
        (false, setup(true)),
        (true, tuff_setup::setup_with_features(true, robust)),
    ] {
        let target = s.color_target(SIZE, vk::ImageUsageFlags::empty());
        let empty = s
            .device
            .create_pipeline_layout(&tuff::PipelineLayoutCreateInfo::new())
            .expect("layout");
        let pipeline = pipelines::vertex_pipeline(&s, &empty, &target.render_pass);
        let (vertices, _vertex_memory) =
            pipelines::host_buffer(&s, 60, vk::BufferUsageFlags::VERTEX_BUFFER);
        let (indices, _index_memory) =
            pipelines::host_buffer(&s, 12, vk::BufferUsageFlags::INDEX_BUFFER);
        let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
        let clear = [vk::ClearValue::default()];
        let begin = tuff::RenderPassBeginInfo::new(&target.render_pass, &target.framebuffer)
            .render_area(area())
            .clear_values(&clear);
        let rec = cb
            .begin(&tuff::CommandBufferBeginInfo::new())
            .expect("begin");
        let mut rec = rec.begin_render_pass(&begin, vk::SubpassContents::INLINE);
        rec.bind_pipeline(vk::PipelineBindPoint::GRAPHICS, &pipeline)
            .expect("bind");
        rec.bind_vertex_buffers(0, &vertices, &[0])
            .expect("vertex buffer");
        rec.bind_index_buffer(&indices, 0, vk::IndexType::UINT32)
            .expect("index buffer");
        set_viewport(&mut rec);
        set_scissor(&mut rec);
        let r = rec.draw_indexed(3, 1, 0, 0, 0);
        if robust {
            r.expect("a draw whose fetches robust buffer access keeps inside");
        } else {
            assert_eq!(vuid(r), "VUID-vkCmdDrawIndexed-None-02721");
        }
        drop(rec);
        assert_silent(&s.messages);
    }
}

/// A compute pipeline has every state static: a dispatch after a dynamic state was
/// set since its pipeline was bound is refused by each dispatch command (the 1.3.239
/// layer says nothing of the unchecked one: the error alone proves the rule), and
/// binding the pipeline again clears it.
#[test]
fn dispatches_refuse_dynamic_state_set_since_their_pipeline() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let target = s.color_target(SIZE, vk::ImageUsageFlags::empty());
    let p = pipelines::pipelines(&s, &target);
    let (args, _memory) = pipelines::host_buffer(&s, 64, vk::BufferUsageFlags::INDIRECT_BUFFER);
    type Dispatch<'a> =
        Box<dyn Fn(&mut tuff::Recorder<'_, tuff::Outside>, bool) -> tuff::Result<()> + 'a>;
    // SAFETY (each `unsafe` call): the recording is never submitted; the rules these
    // methods leave to their caller concern what the device does when it runs, and
    // the layer is told to skip an unchecked call it reports.
    let dispatches: [(&str, Dispatch<'_>); 3] = [
        (
            "vkCmdDispatch",
            Box::new(|r, unchecked| match unchecked {
                true => unsafe { r.dispatch_unchecked(1, 1, 1) },
                false => r.dispatch(1, 1, 1),
            }),
        ),
        (
            "vkCmdDispatchBase",
            Box::new(|r, unchecked| match unchecked {
                true => unsafe { r.dispatch_base_unchecked(0, 0, 0, 1, 1, 1) },
                false => r.dispatch_base(0, 0, 0, 1, 1, 1),
            }),
        ),
        (
            "vkCmdDispatchIndirect",
            Box::new(|r, unchecked| match unchecked {
                true => unsafe { r.dispatch_indirect_unchecked(&args, 0) },
                false => unsafe { r.dispatch_indirect(&args, 0) },
            }),
        ),
    ];
    let bind = |r: &mut tuff::Recorder<'_, tuff::Outside>| {
        r.bind_pipeline(vk::PipelineBindPoint::COMPUTE, &p.compute)
            .expect("bind");
        r.bind_descriptor_sets(
            vk::PipelineBindPoint::COMPUTE,
            &p.compute_layout,
            0,
            &p.set,
            &[],
        )
        .expect("sets");
    };
    let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    for (command, dispatch) in &dispatches {
        let rule = format!("VUID-{command}-None-02859");
        tuff_setup::breaks(&s, &rule, tuff_setup::Layer::Silent, |unchecked| {
            let mut rec = cb
                .begin(&tuff::CommandBufferBeginInfo::new())
                .expect("begin");
            bind(&mut rec);
            rec.set_line_width(1.0);
            dispatch(&mut rec, unchecked)
        });
        let mut rec = cb
            .begin(&tuff::CommandBufferBeginInfo::new())
            .expect("begin");
        bind(&mut rec);
        dispatch(&mut rec, false).expect("a dispatch with nothing set since the bind");
        rec.set_line_width(1.0);
        // The dispatches write the same storage buffer: ordered, or they race.
        let w = [tuff::MemoryBarrier::new()
            .src_access_mask(vk::AccessFlags::SHADER_WRITE)
            .dst_access_mask(vk::AccessFlags::SHADER_WRITE)];
        let cs = vk::PipelineStageFlags::COMPUTE_SHADER;
        rec.pipeline_barrier(cs, cs, vk::DependencyFlags::empty(), &w, &[], &[])
            .expect("barrier");
        bind(&mut rec);
        dispatch(&mut rec, false).expect("a dispatch after the pipeline is bound again");
        rec.end().expect("end");
    }
    assert_silent(&s.messages);
}

/// With the vertex binding stride dynamic, a stride `bind_vertex_buffers2` sets is
/// 0 or reaches past the attributes the vertex shader fetches from its binding
/// (here 20 bytes): a shorter one is refused at the draw, where the pipeline that
/// says which attributes are fetched is known.
#[test]
fn dynamic_strides_reach_past_their_attributes() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let dynamic = [D::VIEWPORT, D::SCISSOR, D::VERTEX_INPUT_BINDING_STRIDE];
    // (stride, refused)
    let cases = [(20, false), (0, false), (8, true)].map(|(stride, refused)| VertexDraw {
        bind: Box::new(move |r, vertices| {
            r.bind_vertex_buffers2(0, vertices, &[0], &[], &[stride])
        }),
        count: 2,
        first: 0,
        refused,
    });
    let rule = "VUID-vkCmdBindVertexBuffers2-pStrides-06209";
    vertex_draws(&s, &dynamic, cases, rule, true);
}

/// A clear of attachments inside a render pass instance: an attachment the subpass
/// does not have, an empty rectangle, one past the render area or past the
/// framebuffer's layers is refused with the rule's VUID, and the layer names it for
/// the unchecked call, which it skips; a clear of the whole area records silently.
#[test]
fn attachment_clears_stay_inside_the_instance() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let target = s.color_target(SIZE, vk::ImageUsageFlags::empty());
    let clear = [vk::ClearValue::default()];
    let begin = tuff::RenderPassBeginInfo::new(&target.render_pass, &target.framebuffer)
        .render_area(area())
        .clear_values(&clear);
    let color = |color_attachment| vk::ClearAttachment {
        aspect_mask: vk::ImageAspectFlags::COLOR,
        color_attachment,
        clear_value: vk::ClearValue::default(),
    };
    let rect = |x, y, width, height, layer_count| vk::ClearRect {
        rect: vk::Rect2D {
            offset: vk::Offset2D { x, y },
            extent: vk::Extent2D { width, height },
        },
        base_array_layer: 0,
        layer_count,
    };
    let whole = rect(0, 0, SIZE, SIZE, 1);
    let cases = [
        (
            "VUID-vkCmdClearAttachments-aspectMask-07271",
            color(1),
            whole,
        ),
        (
            "VUID-vkCmdClearAttachments-rect-02682",
            color(0),
            rect(0, 0, 0, SIZE, 1),
        ),
        (
            "VUID-vkCmdClearAttachments-rect-02683",
            color(0),
            rect(0, 0, SIZE, 0, 1),
        ),
        (
            "VUID-vkCmdClearAttachments-pRects-00016",
            color(0),
            rect(4, 0, SIZE, SIZE, 1),
        ),
        (
            "VUID-vkCmdClearAttachments-pRects-06937",
            color(0),
            rect(0, 0, SIZE, SIZE, 2),
        ),
    ];
    let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let mut wrong = Vec::new();
    for (rule, attachment, r) in cases {
        let rec = cb
            .begin(&tuff::CommandBufferBeginInfo::new())
            .expect("begin");
        let mut rec = rec.begin_render_pass(&begin, vk::SubpassContents::INLINE);
        let safe = vuid(rec.clear_attachments(&[attachment], &[r]));
        s.messages.take();
        s.messages.abort_on_error(true);
        // SAFETY: the layer skips the call, which breaks only the rule under test;
        // the command buffer is never submitted.
        let _ = unsafe { rec.clear_attachments_unchecked(&[attachment], &[r]) };
        s.messages.abort_on_error(false);
        let said = s.messages.take();
        if safe != rule || !said.iter().any(|m| m.contains(rule)) {
            wrong.push(format!("{rule}: tuff said {safe}; the layer said {said:?}"));
        }
        drop(rec);
    }
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
    let rec = cb
        .begin(&tuff::CommandBufferBeginInfo::new())
        .expect("begin");
    let mut rec = rec.begin_render_pass(&begin, vk::SubpassContents::INLINE);
    rec.clear_attachments(&[color(0)], &[whole])
        .expect("a clear of the whole area");
    rec.end_render_pass().end().expect("end");
    assert_silent(&s.messages);
}
