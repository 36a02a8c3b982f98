//! Render passes of two subpasses, the second reading the first's color through an
//! input attachment: the correct program records, runs and leaves the layer
//! (synchronization validation included) silent, and a descriptor that states
//! another layout than the subpass gives the attachment is refused
//! (`VUID-VkDescriptorImageInfo-imageLayout-00344`), as are a descriptor that views
//! another image than the framebuffer's (`VUID-vkCmdDraw-None-07469`) and a draw
//! recorded inline in a subpass whose contents are secondaries.
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
const READ: vk::ImageLayout = vk::ImageLayout::SHADER_READ_ONLY_OPTIMAL;

/// The two-subpass scene: attachment 0 written in subpass 0 and read as an input
/// attachment in subpass 1, which writes attachment 1; a pipeline per subpass, and
/// a set holding attachment 0's view for the second.
struct Scene {
    _images: [(tuff::Image, tuff::DeviceMemory, tuff::ImageView); 2],
    pass: tuff::RenderPass,
    framebuffer: tuff::Framebuffer,
    p: pipelines::Pipelines,
    first: tuff::Pipeline,
    _module: tuff::ShaderModule,
    layout: tuff::PipelineLayout,
    second: tuff::Pipeline,
    set: pipelines::OneSet,
}

impl Scene {
    fn new(s: &Setup) -> Scene {
        let d = &s.device;
        let gbuffer = s.color_image(SIZE, vk::ImageUsageFlags::INPUT_ATTACHMENT);
        let output = s.color_image(SIZE, vk::ImageUsageFlags::empty());
        let attachment = vk::AttachmentDescription {
            format: RGBA,
            samples: vk::SampleCountFlags::TYPE_1,
            load_op: vk::AttachmentLoadOp::CLEAR,
            store_op: vk::AttachmentStoreOp::STORE,
            stencil_load_op: vk::AttachmentLoadOp::DONT_CARE,
            stencil_store_op: vk::AttachmentStoreOp::DONT_CARE,
            initial_layout: vk::ImageLayout::UNDEFINED,
            final_layout: vk::ImageLayout::COLOR_ATTACHMENT_OPTIMAL,
            ..Default::default()
        };
        let attachments = [attachment, attachment];
        let color = vk::ImageLayout::COLOR_ATTACHMENT_OPTIMAL;
        let written = [vk::AttachmentReference {
            attachment: 0,
            layout: color,
        }];
        let read = [vk::AttachmentReference {
            attachment: 0,
            layout: READ,
        }];
        let out = [vk::AttachmentReference {
            attachment: 1,
            layout: color,
        }];
        let subpasses = [
            tuff::SubpassDescription::new()
                .pipeline_bind_point(vk::PipelineBindPoint::GRAPHICS)
                .color_attachments(&written),
            tuff::SubpassDescription::new()
                .pipeline_bind_point(vk::PipelineBindPoint::GRAPHICS)
                .input_attachments(&read)
                .color_attachments(&out),
        ];
        let dependencies = [vk::SubpassDependency {
            src_subpass: 0,
            dst_subpass: 1,
            src_stage_mask: vk::PipelineStageFlags::COLOR_ATTACHMENT_OUTPUT,
            dst_stage_mask: vk::PipelineStageFlags::FRAGMENT_SHADER,
            src_access_mask: vk::AccessFlags::COLOR_ATTACHMENT_WRITE,
            dst_access_mask: vk::AccessFlags::INPUT_ATTACHMENT_READ,
            dependency_flags: vk::DependencyFlags::BY_REGION,
        }];
        let pass = d
            .create_render_pass(
                &tuff::RenderPassCreateInfo::new()
                    .attachments(&attachments)
                    .subpasses(&subpasses)
                    .dependencies(&dependencies),
            )
            .expect("render pass");
        let views = tuff::HandleSlice::new(&[&gbuffer.2, &output.2]);
        let framebuffer = d
            .create_framebuffer(
                &tuff::FramebufferCreateInfo::new(&pass)
                    .attachments(&views)
                    .width(SIZE)
                    .height(SIZE)
                    .layers(1),
            )
            .expect("framebuffer");
        let target = s.color_target(SIZE, vk::ImageUsageFlags::empty());
        let p = pipelines::pipelines(s, &target);
        let stages = pipelines::test_stages(&p.vert, &p.frag);
        let first = pipelines::with_graphics_info(&stages, &p.graphics_layout, &pass, |info| {
            d.create_graphics_pipeline(None, &info)
        })
        .expect("subpass 0 pipeline");
        let module = tuff_setup::shader(s, include_bytes!("../shaders/spv/input_depth.frag.spv"));
        let one = pipelines::one_set(
            s,
            vk::DescriptorType::INPUT_ATTACHMENT,
            vk::ShaderStageFlags::FRAGMENT,
        );
        let set_layout = &one.layout;
        let set_layouts = tuff::HandleSlice::new(&[set_layout]);
        let layout = d
            .create_pipeline_layout(
                &tuff::PipelineLayoutCreateInfo::new().set_layouts(&set_layouts),
            )
            .expect("pipeline layout");
        let stages = pipelines::test_stages(&p.vert, &module);
        let second = pipelines::with_graphics_info(&stages, &layout, &pass, |info| {
            d.create_graphics_pipeline(None, &info.subpass(1))
        })
        .expect("subpass 1 pipeline");
        Scene {
            _images: [gbuffer, output],
            pass,
            framebuffer,
            p,
            first,
            _module: module,
            layout,
            second,
            set: one,
        }
    }

    /// Writes the set's input attachment: `view` in `layout`.
    fn write(&self, s: &Setup, view: &tuff::ImageView, layout: vk::ImageLayout) {
        let images = [tuff::DescriptorImageInfo::new()
            .image_view(Some(view))
            .image_layout(layout)];
        s.device
            .update_descriptor_sets(
                &[tuff::WriteDescriptorSet::new(&self.set.set)
                    .dst_binding(0)
                    .descriptor_type(vk::DescriptorType::INPUT_ATTACHMENT)
                    .image_info(&images)],
                &[],
            )
            .expect("the input attachment");
    }

    /// Records both subpasses into `cb`, the second begun with `contents` and its
    /// binds and draw through the safe methods or their `_unchecked` forms, and
    /// returns the first refusal among them (if any) with the recorder.
    fn record<'c>(
        &self,
        cb: &'c mut tuff::CommandBuffer,
        unchecked: bool,
        contents: vk::SubpassContents,
    ) -> (tuff::Recorder<'c, tuff::InRenderPass>, tuff::Result<()>) {
        self.record_with(cb, unchecked, contents, &self.second)
    }

    /// [`Self::record`], binding `second` in subpass 1.
    fn record_with<'c>(
        &self,
        cb: &'c mut tuff::CommandBuffer,
        unchecked: bool,
        contents: vk::SubpassContents,
        second: &tuff::Pipeline,
    ) -> (tuff::Recorder<'c, tuff::InRenderPass>, tuff::Result<()>) {
        let area = vk::Rect2D {
            offset: vk::Offset2D::default(),
            extent: vk::Extent2D {
                width: SIZE,
                height: SIZE,
            },
        };
        let clear = [vk::ClearValue::default(); 2];
        let rec = cb
            .begin(&tuff::CommandBufferBeginInfo::new())
            .expect("begin");
        let mut rec = rec.begin_render_pass(
            &tuff::RenderPassBeginInfo::new(&self.pass, &self.framebuffer)
                .render_area(area)
                .clear_values(&clear),
            vk::SubpassContents::INLINE,
        );
        let viewport = vk::Viewport {
            width: SIZE as f32,
            height: SIZE as f32,
            max_depth: 1.0,
            ..Default::default()
        };
        rec.bind_pipeline(vk::PipelineBindPoint::GRAPHICS, &self.first)
            .expect("bind");
        rec.set_viewport(0, &[viewport]).expect("viewport");
        rec.set_scissor(0, &[area]).expect("scissor");
        pipelines::push_color(&mut rec, &self.p);
        rec.draw(3, 1, 0, 0).expect("subpass 0's draw");
        rec.next_subpass(contents);
        // SAFETY: as the module says; in subpass 1 the binds and the draw are valid
        // but for the rule each case breaks.
        let r = if unchecked {
            unsafe {
                rec.bind_pipeline_unchecked(vk::PipelineBindPoint::GRAPHICS, second)
                    .and_then(|()| {
                        rec.bind_descriptor_sets_unchecked(
                            vk::PipelineBindPoint::GRAPHICS,
                            &self.layout,
                            0,
                            &self.set.set,
                            &[],
                        )
                    })
                    .and_then(|()| rec.draw_unchecked(3, 1, 0, 0))
            }
        } else {
            rec.bind_pipeline(vk::PipelineBindPoint::GRAPHICS, second)
                .and_then(|()| {
                    rec.bind_descriptor_sets(
                        vk::PipelineBindPoint::GRAPHICS,
                        &self.layout,
                        0,
                        &self.set.set,
                        &[],
                    )
                })
                .and_then(|()| rec.draw(3, 1, 0, 0))
        };
        (rec, r)
    }
}

/// A draw in subpass 1 reads subpass 0's color through an input attachment in the
/// layout subpass 1 gives it: recorded, submitted and run, the layer silent.
#[test]
fn a_second_subpass_reads_the_first_through_an_input_attachment() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let scene = Scene::new(&s);
    scene.write(&s, &scene._images[0].2, READ);
    let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let (rec, r) = scene.record(&mut cb, false, vk::SubpassContents::INLINE);
    r.expect("the input attachment in the subpass's layout");
    rec.end_render_pass().end().expect("end");
    s.submit_wait(&cb);
    assert_silent(&s.messages);
}

/// One way of breaking the correct two-subpass program.
struct Broken {
    /// The rule it breaks.
    rule: &'static str,
    /// What the 1.3.239 layer says of it through `_unchecked`.
    layer: Layer<'static>,
    /// The input attachment's descriptor views another image (of the same format
    /// and usage) than the framebuffer's.
    other_view: bool,
    /// The layout the descriptor states.
    layout: vk::ImageLayout,
    /// How subpass 1 is begun.
    contents: vk::SubpassContents,
    /// Subpass 1 binds the pipeline made for subpass 0.
    first_pipeline: bool,
}

const CORRECT: Broken = Broken {
    rule: "",
    layer: Layer::Silent,
    other_view: false,
    layout: READ,
    contents: vk::SubpassContents::INLINE,
    first_pipeline: false,
};

const BROKEN: &[Broken] = &[
    // The descriptor states another layout than the subpass gives the attachment.
    Broken {
        rule: "VUID-VkDescriptorImageInfo-imageLayout-00344",
        layer: Layer::Names,
        layout: vk::ImageLayout::GENERAL,
        ..CORRECT
    },
    // The descriptor views another image than the framebuffer's (the 1.3.239 layer
    // does not check it when the draw is recorded).
    Broken {
        rule: "VUID-vkCmdDraw-None-07469",
        layer: Layer::Silent,
        other_view: true,
        ..CORRECT
    },
    // A draw in subpass 1 with the pipeline made for subpass 0.
    Broken {
        rule: "VUID-vkCmdDraw-subpass-02685",
        layer: Layer::Names,
        first_pipeline: true,
        ..CORRECT
    },
    // Subpass 1 begun with SECONDARY_COMMAND_BUFFERS contents takes only
    // `execute_commands` and the commands that leave it: its bind is refused.
    Broken {
        rule: "UNASSIGNED-CoreValidation-DrawState-InvalidCommandBuffer",
        layer: Layer::Names,
        contents: vk::SubpassContents::SECONDARY_COMMAND_BUFFERS,
        ..CORRECT
    },
];

/// Each way of breaking the correct program is refused with its rule, and the layer
/// names the same rule through `_unchecked` (or says nothing where it does not
/// check it).
#[test]
fn broken_two_subpass_programs_are_refused() {
    let _serial = vulkan::serial();
    for case in BROKEN {
        let s = setup(true);
        let scene = Scene::new(&s);
        let other = s.color_image(SIZE, vk::ImageUsageFlags::INPUT_ATTACHMENT);
        let view = if case.other_view {
            &other.2
        } else {
            &scene._images[0].2
        };
        scene.write(&s, view, case.layout);
        let second = if case.first_pipeline {
            &scene.first
        } else {
            &scene.second
        };
        let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
        breaks(&s, case.rule, case.layer, |unchecked| {
            scene
                .record_with(&mut cb, unchecked, case.contents, second)
                .1
        });
        assert_silent(&s.messages);
    }
}

/// `Queue::submit_and_wait_with` hands its closure the recorder itself, so setup work
/// in one call can render: the two subpasses recorded, submitted and waited for,
/// the closure's value handed back.
#[test]
fn setup_work_in_one_call_can_render() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let scene = Scene::new(&s);
    scene.write(&s, &scene._images[0].2, READ);
    let area = vk::Rect2D {
        offset: vk::Offset2D::default(),
        extent: vk::Extent2D {
            width: SIZE,
            height: SIZE,
        },
    };
    let clear = [vk::ClearValue::default(); 2];
    let answer = s
        .queue
        .submit_and_wait_with(|rec| {
            let mut rec = rec.begin_render_pass(
                &tuff::RenderPassBeginInfo::new(&scene.pass, &scene.framebuffer)
                    .render_area(area)
                    .clear_values(&clear),
                vk::SubpassContents::INLINE,
            );
            rec.next_subpass(vk::SubpassContents::INLINE);
            Ok((rec.end_render_pass(), 42))
        })
        .expect("a render pass in one call");
    assert_eq!(answer, 42);
    assert_silent(&s.messages);
}
