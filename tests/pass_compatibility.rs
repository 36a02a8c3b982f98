//! Render pass compatibility, as the specification defines it (Render Pass
//! Compatibility): a draw's pipeline, made for one render pass, draws in an instance
//! of another only when the two are compatible (`VUID-vkCmdDraw-renderPass-02684`).
//! Attachment references compare by their attachments' format and sample count
//! (unused past the end of the shorter array); everything else must be identical but
//! the attachments' layouts and load and store operations and the references'
//! layouts. The same test serves a framebuffer's render pass at `vkCmdBeginRenderPass`
//! and a secondary's inheritance at `vkCmdExecuteCommands`.
//!
//! Each incompatible pass is refused through the safe `draw`, and the layer names the
//! rule for `draw_unchecked`; each compatible one draws, the layer silent.
//!
//! SAFETY of the `unsafe` blocks: `draw_unchecked` breaks, on purpose, only the rule
//! each case names, which the layer skips (the command buffer is never submitted);
//! the shaders are the repository's (the shader promise, see `tuff_setup::shader`).

#[path = "common/pipelines.rs"]
mod pipelines;
#[path = "common/tuff_setup.rs"]
mod tuff_setup;
#[path = "common/vulkan.rs"]
mod vulkan;

use tuff::vk;
use tuff_setup::{breaks, setup, Layer, Setup};
use vulkan::assert_silent;

const SIZE: u32 = 8;
const RGBA: vk::Format = vk::Format::R8G8B8A8_UNORM;

/// A render pass of one attachment of `format` (loaded and stored as `ops` say,
/// from `layouts.0` to `layouts.1`), with one subpass per entry of `subpasses`, each
/// writing the color references it lists (in layout `layouts.2`), and
/// `dependencies`.
struct Shape<'a> {
    format: vk::Format,
    ops: (vk::AttachmentLoadOp, vk::AttachmentStoreOp),
    layouts: (vk::ImageLayout, vk::ImageLayout, vk::ImageLayout),
    subpasses: &'a [&'a [u32]],
    dependencies: &'a [vk::SubpassDependency],
}

/// The target's render pass, as `tuff_setup::color_target` makes it.
const BASE: Shape<'static> = Shape {
    format: RGBA,
    ops: (vk::AttachmentLoadOp::CLEAR, vk::AttachmentStoreOp::STORE),
    layouts: (
        vk::ImageLayout::UNDEFINED,
        vk::ImageLayout::COLOR_ATTACHMENT_OPTIMAL,
        vk::ImageLayout::COLOR_ATTACHMENT_OPTIMAL,
    ),
    subpasses: &[&[0]],
    dependencies: &[],
};

fn render_pass(s: &Setup, shape: &Shape<'_>) -> tuff::RenderPass {
    let attachments = [vk::AttachmentDescription {
        format: shape.format,
        samples: vk::SampleCountFlags::TYPE_1,
        load_op: shape.ops.0,
        store_op: shape.ops.1,
        stencil_load_op: vk::AttachmentLoadOp::DONT_CARE,
        stencil_store_op: vk::AttachmentStoreOp::DONT_CARE,
        initial_layout: shape.layouts.0,
        final_layout: shape.layouts.1,
        ..Default::default()
    }];
    let references: Vec<Vec<vk::AttachmentReference>> = shape
        .subpasses
        .iter()
        .map(|colors| {
            colors
                .iter()
                .map(|a| vk::AttachmentReference {
                    attachment: *a,
                    layout: shape.layouts.2,
                })
                .collect()
        })
        .collect();
    let subpasses: Vec<tuff::SubpassDescription<'_>> = references
        .iter()
        .map(|r| {
            tuff::SubpassDescription::new()
                .pipeline_bind_point(vk::PipelineBindPoint::GRAPHICS)
                .color_attachments(r)
        })
        .collect();
    s.device
        .create_render_pass(
            &tuff::RenderPassCreateInfo::new()
                .attachments(&attachments)
                .subpasses(&subpasses)
                .dependencies(shape.dependencies),
        )
        .expect("render pass")
}

/// The test graphics pipeline for subpass 0 of `pass`, blending `colors` attachments.
fn pipeline(
    s: &Setup,
    p: &pipelines::Pipelines,
    pass: &tuff::RenderPass,
    colors: usize,
) -> tuff::Pipeline {
    let stages = pipelines::test_stages(&p.vert, &p.frag);
    let blend_attachments = vec![
        vk::PipelineColorBlendAttachmentState {
            color_write_mask: vk::ColorComponentFlags::RGBA,
            ..Default::default()
        };
        colors
    ];
    let blend = tuff::PipelineColorBlendStateCreateInfo::new().attachments(&blend_attachments);
    pipelines::with_graphics_info(&stages, &p.graphics_layout, pass, |info| {
        s.device
            .create_graphics_pipeline(None, &info.color_blend_state(Some(&blend)))
    })
    .expect("pipeline")
}

/// Records a draw with `pipeline` in an instance of the target's render pass.
fn draw(
    s: &Setup,
    target: &tuff_setup::ColorTarget,
    p: &pipelines::Pipelines,
    pipeline: &tuff::Pipeline,
    unchecked: bool,
) -> tuff::Result<()> {
    let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let area = vk::Rect2D {
        offset: vk::Offset2D::default(),
        extent: vk::Extent2D {
            width: SIZE,
            height: SIZE,
        },
    };
    let clear = [vk::ClearValue::default()];
    let rec = cb
        .begin(&tuff::CommandBufferBeginInfo::new())
        .expect("begin");
    let mut rec = rec.begin_render_pass(
        &tuff::RenderPassBeginInfo::new(&target.render_pass, &target.framebuffer)
            .render_area(area)
            .clear_values(&clear),
        vk::SubpassContents::INLINE,
    );
    rec.bind_pipeline(vk::PipelineBindPoint::GRAPHICS, pipeline)
        .expect("bind");
    rec.set_viewport(
        0,
        &[vk::Viewport {
            width: SIZE as f32,
            height: SIZE as f32,
            max_depth: 1.0,
            ..Default::default()
        }],
    )
    .expect("viewport");
    rec.set_scissor(0, &[area]).expect("scissor");
    pipelines::push_color(&mut rec, p);
    if unchecked {
        unsafe { rec.draw_unchecked(3, 1, 0, 0) }
    } else {
        rec.draw(3, 1, 0, 0)
    }
}

/// Render passes that differ from the target's only where compatibility allows
/// (layouts, load and store operations, a trailing unused color reference) draw with
/// a pipeline made for either; those that differ in an attachment's format, their
/// subpasses or their dependencies are refused, and the layer agrees.
#[test]
fn pipelines_draw_in_the_render_passes_compatible_with_theirs() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let target = s.color_target(SIZE, vk::ImageUsageFlags::empty());
    let p = pipelines::pipelines(&s, &target);
    let general = vk::ImageLayout::GENERAL;
    let output = vk::PipelineStageFlags::COLOR_ATTACHMENT_OUTPUT;
    let write = vk::AccessFlags::COLOR_ATTACHMENT_WRITE;
    let external = [vk::SubpassDependency {
        src_subpass: vk::SUBPASS_EXTERNAL,
        dst_subpass: 0,
        src_stage_mask: output,
        dst_stage_mask: output,
        src_access_mask: vk::AccessFlags::empty(),
        dst_access_mask: write,
        dependency_flags: vk::DependencyFlags::empty(),
    }];
    let compatible = [
        (
            Shape {
                ops: (
                    vk::AttachmentLoadOp::DONT_CARE,
                    vk::AttachmentStoreOp::DONT_CARE,
                ),
                layouts: (vk::ImageLayout::COLOR_ATTACHMENT_OPTIMAL, general, general),
                ..BASE
            },
            1,
        ),
        (
            Shape {
                subpasses: &[&[0, vk::ATTACHMENT_UNUSED]],
                ..BASE
            },
            2,
        ),
    ];
    for (shape, colors) in &compatible {
        let pass = render_pass(&s, shape);
        let made_for = pipeline(&s, &p, &pass, *colors);
        draw(&s, &target, &p, &made_for, false).expect("a compatible render pass");
    }
    let incompatible = [
        Shape {
            format: vk::Format::B8G8R8A8_UNORM,
            ..BASE
        },
        Shape {
            dependencies: &external,
            ..BASE
        },
        Shape {
            subpasses: &[&[0], &[0]],
            dependencies: &[vk::SubpassDependency {
                src_subpass: 0,
                dst_subpass: 1,
                src_stage_mask: output,
                dst_stage_mask: output,
                src_access_mask: write,
                dst_access_mask: write,
                dependency_flags: vk::DependencyFlags::BY_REGION,
            }],
            ..BASE
        },
    ];
    for shape in &incompatible {
        let pass = render_pass(&s, shape);
        let colors = shape.subpasses[0].len();
        let made_for = pipeline(&s, &p, &pass, colors);
        breaks(
            &s,
            "VUID-vkCmdDraw-renderPass-02684",
            Layer::Names,
            |unchecked| draw(&s, &target, &p, &made_for, unchecked),
        );
    }
    assert_silent(&s.messages);
}
