//! The safe forms of the indirect commands (`draw_indirect_from` and its siblings)
//! over an `IndirectBuffer` the host wrote: they draw and dispatch what was written,
//! refuse arguments that break a rule of their struct when they are written, check
//! each draw they read as the direct command's parameters are checked, keep their
//! ranges and counts inside the arguments held, and no write reaches arguments a
//! recording may still read.
//!
//! Each refused case goes through `tuff_setup::breaks`: the safe form must name the
//! rule, and the generated `_unchecked` method over a plain buffer holding the same
//! words must make the validation layer name it too, or say nothing where the layer
//! cannot read the arguments (tuff's error alone proves the rule then; the command
//! buffer is never submitted).
//!
//! SAFETY of the `unsafe` blocks: the `_unchecked` calls break, on purpose, only the
//! rule each case names, which the layer skips or does not check (the command buffer
//! is never submitted); the shaders are the repository's (the shader promise, see
//! `tuff_setup::shader`).

#[path = "common/pipelines.rs"]
mod pipelines;
#[path = "common/tuff_setup.rs"]
mod tuff_setup;
#[path = "common/vulkan.rs"]
mod vulkan;

use tuff::vk;
use tuff_setup::{breaks, setup, setup_with_features, vuid, ColorTarget, Layer, Setup};
use vulkan::assert_silent;

type Pass<'r> = tuff::Recorder<'r, tuff::InRenderPass>;
const SIZE: u32 = 8;

fn draw(vertex_count: u32, first_vertex: u32, first_instance: u32) -> vk::DrawIndirectCommand {
    vk::DrawIndirectCommand {
        vertex_count,
        instance_count: 1,
        first_vertex,
        first_instance,
    }
}

fn indexed(
    index_count: u32,
    first_index: u32,
    first_instance: u32,
) -> vk::DrawIndexedIndirectCommand {
    vk::DrawIndexedIndirectCommand {
        index_count,
        instance_count: 1,
        first_index,
        vertex_offset: 0,
        first_instance,
    }
}

/// A plain host-visible buffer of `usage` holding `words`, for the `_unchecked`
/// twins: the same bytes an `IndirectBuffer` would hold, which the layer cannot read.
fn plain(
    s: &Setup,
    words: &[u32],
    usage: vk::BufferUsageFlags,
) -> (tuff::Buffer, tuff::DeviceMemory) {
    let bytes: Vec<u8> = words.iter().flat_map(|w| w.to_le_bytes()).collect();
    let (buffer, memory) = pipelines::host_buffer(s, bytes.len() as u64, usage);
    pipelines::access_memory(s, &memory, bytes.len(), Some(&bytes));
    (buffer, memory)
}

fn words_of(d: &[vk::DrawIndirectCommand]) -> Vec<u32> {
    d.iter()
        .flat_map(|d| {
            [
                d.vertex_count,
                d.instance_count,
                d.first_vertex,
                d.first_instance,
            ]
        })
        .collect()
}

fn indexed_words(d: &[vk::DrawIndexedIndirectCommand]) -> Vec<u32> {
    d.iter()
        .flat_map(|d| {
            [
                d.index_count,
                d.instance_count,
                d.first_index,
                d.vertex_offset as u32,
                d.first_instance,
            ]
        })
        .collect()
}

/// The four indirect draw forms.
#[derive(Clone, Copy, Debug)]
enum Form {
    Draw,
    Indexed,
    Count,
    IndexedCount,
}

use Form::{Count, Draw, Indexed, IndexedCount};

/// Draws, indexed draws and a draw count, each as an `IndirectBuffer` and as a
/// plain buffer of the same words for the `_unchecked` twins.
struct Args {
    draws: tuff::IndirectBuffer<vk::DrawIndirectCommand>,
    raw: (tuff::Buffer, tuff::DeviceMemory),
    indexed: tuff::IndirectBuffer<vk::DrawIndexedIndirectCommand>,
    raw_indexed: (tuff::Buffer, tuff::DeviceMemory),
    count: tuff::IndirectBuffer<u32>,
    raw_count: (tuff::Buffer, tuff::DeviceMemory),
}

impl Args {
    fn new(
        s: &Setup,
        draws: &[vk::DrawIndirectCommand],
        indexed: &[vk::DrawIndexedIndirectCommand],
        count: u32,
    ) -> Args {
        let d = &s.device;
        let allocator = d.gpu_allocator().expect("allocator");
        let usage = vk::BufferUsageFlags::INDIRECT_BUFFER;
        Args {
            draws: d.create_indirect_buffer(draws, &allocator).expect("draws"),
            raw: plain(s, &words_of(draws), usage),
            indexed: d
                .create_indirect_buffer(indexed, &allocator)
                .expect("indexed draws"),
            raw_indexed: plain(s, &indexed_words(indexed), usage),
            count: d
                .create_indirect_buffer(&[count], &allocator)
                .expect("count"),
            raw_count: plain(s, &[count], usage),
        }
    }

    /// Records `form` over the draws `range` (with the count at element
    /// `count_at`): the safe form, or its `_unchecked` twin over the plain buffers
    /// at the same offsets.
    fn record<S: tuff::recorder::Inside>(
        &self,
        r: &mut tuff::Recorder<'_, S>,
        form: Form,
        range: std::ops::Range<u32>,
        count_at: u32,
        unchecked: bool,
    ) -> tuff::Result<()> {
        let n = range.end - range.start;
        let (at, count_offset) = (u64::from(range.start), u64::from(count_at) * 4);
        let (raw, raw_indexed, raw_count) = (&self.raw.0, &self.raw_indexed.0, &self.raw_count.0);
        match (form, unchecked) {
            (Draw, false) => r.draw_indirect_from(&self.draws, range),
            (Indexed, false) => r.draw_indexed_indirect_from(&self.indexed, range),
            (Count, false) => r.draw_indirect_count_from(&self.draws, range, &self.count, count_at),
            (IndexedCount, false) => {
                r.draw_indexed_indirect_count_from(&self.indexed, range, &self.count, count_at)
            }
            (Draw, true) => unsafe { r.draw_indirect_unchecked(raw, at * 16, n, 16) },
            (Indexed, true) => unsafe {
                r.draw_indexed_indirect_unchecked(raw_indexed, at * 20, n, 20)
            },
            (Count, true) => unsafe {
                r.draw_indirect_count_unchecked(raw, at * 16, raw_count, count_offset, n, 16)
            },
            (IndexedCount, true) => unsafe {
                r.draw_indexed_indirect_count_unchecked(
                    raw_indexed,
                    at * 20,
                    raw_count,
                    count_offset,
                    n,
                    20,
                )
            },
        }
    }
}

/// The test pipelines, a color target of their render pass, and an index buffer of
/// three `u32` indices.
struct Scene {
    target: ColorTarget,
    p: pipelines::Pipelines,
    indices: (tuff::Buffer, tuff::DeviceMemory),
}

impl Scene {
    fn new(s: &Setup) -> Scene {
        let target = s.color_target(SIZE, vk::ImageUsageFlags::empty());
        let p = pipelines::pipelines(s, &target);
        let indices = plain(s, &[0, 1, 2], vk::BufferUsageFlags::INDEX_BUFFER);
        Scene { target, p, indices }
    }

    /// Begins `cb` and the target's render pass, and binds `pipeline` (the test
    /// graphics pipeline by default) with its state and the index buffer.
    fn begin<'c>(
        &self,
        cb: &'c mut tuff::CommandBuffer,
        pipeline: Option<&tuff::Pipeline>,
    ) -> Pass<'c> {
        let clear = [vk::ClearValue::default()];
        let begin =
            tuff::RenderPassBeginInfo::new(&self.target.render_pass, &self.target.framebuffer)
                .render_area(area())
                .clear_values(&clear);
        let rec = cb
            .begin(&tuff::CommandBufferBeginInfo::new())
            .expect("begin");
        let mut rec = rec.begin_render_pass(&begin, vk::SubpassContents::INLINE);
        rec.bind_pipeline(
            vk::PipelineBindPoint::GRAPHICS,
            pipeline.unwrap_or(&self.p.graphics),
        )
        .expect("bind");
        state(&mut rec);
        if pipeline.is_none() {
            pipelines::push_color(&mut rec, &self.p);
        }
        rec.bind_index_buffer(&self.indices.0, 0, vk::IndexType::UINT32)
            .expect("index buffer");
        rec
    }

    /// [`Scene::begin`], then `f` on the recording.
    fn record<R>(
        &self,
        cb: &mut tuff::CommandBuffer,
        pipeline: Option<&tuff::Pipeline>,
        f: impl FnOnce(&mut Pass<'_>) -> R,
    ) -> R {
        f(&mut self.begin(cb, pipeline))
    }
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

/// Sets the viewport and scissor the test pipelines have dynamic.
fn state<S: tuff::recorder::Inside>(rec: &mut tuff::Recorder<'_, S>) {
    let viewport = vk::Viewport {
        width: SIZE as f32,
        height: SIZE as f32,
        max_depth: 1.0,
        ..Default::default()
    };
    rec.set_viewport(0, &[viewport]).expect("viewport");
    rec.set_scissor(0, &[area()]).expect("scissor");
}

/// Each safe form records what the host wrote, and the device runs it: the draws
/// (one by each draw form, two by a range where multiDrawIndirect is on) fill the
/// target and a dispatch writes the compute shader's output, with the layer silent.
#[test]
fn indirect_forms_draw_and_dispatch_what_the_host_wrote() {
    let _serial = vulkan::serial();
    let multi = vk::PhysicalDeviceFeatures::default().multi_draw_indirect(true);
    let s = setup_with_features(true, multi);
    let scene = Scene::new(&s);
    let allocator = s.device.gpu_allocator().expect("allocator");
    let d = &s.device;
    let draws = d
        .create_indirect_buffer(&[draw(3, 0, 0), draw(3, 0, 0)], &allocator)
        .expect("draws");
    let indexed_draws = d
        .create_indirect_buffer(&[indexed(3, 0, 0); 2], &allocator)
        .expect("indexed draws");
    let count = d
        .create_indirect_buffer(&[2u32], &allocator)
        .expect("count");
    let groups = vk::DispatchIndirectCommand { x: 1, y: 1, z: 1 };
    let dispatches = d
        .create_indirect_buffer(&[groups], &allocator)
        .expect("dispatches");
    let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let mut rec = scene.begin(&mut cb, None);
    rec.draw_indirect_from(&draws, 0..1).expect("one draw");
    rec.draw_indirect_from(&draws, 0..2).expect("two draws");
    rec.draw_indexed_indirect_from(&indexed_draws, 1..2)
        .expect("one indexed draw");
    rec.draw_indirect_count_from(&draws, 0..2, &count, 0)
        .expect("counted draws");
    rec.draw_indexed_indirect_count_from(&indexed_draws, 0..2, &count, 0)
        .expect("counted indexed draws");
    let mut rec = rec.end_render_pass();
    rec.bind_pipeline(vk::PipelineBindPoint::COMPUTE, &scene.p.compute)
        .expect("bind");
    rec.bind_descriptor_sets(
        vk::PipelineBindPoint::COMPUTE,
        &scene.p.compute_layout,
        0,
        &scene.p.set,
        &[],
    )
    .expect("sets");
    rec.dispatch_indirect_from(&dispatches, 0)
        .expect("dispatch");
    rec.end().expect("end");
    s.submit_wait(&cb);
    let out = pipelines::access_memory(
        &s,
        &scene.p.output.1,
        4 * pipelines::INVOCATIONS as usize,
        None,
    );
    for (i, word) in out.chunks(4).enumerate() {
        let value = u32::from_le_bytes(word.try_into().expect("a word"));
        assert_eq!(value, i as u32 * pipelines::FACTOR, "invocation {i}");
    }
    assert_silent(&s.messages);
}

/// A range or an element past the arguments written is refused with the rule the
/// buffer's size breaks, which the layer names for the same offsets over a buffer of
/// the same size.
#[test]
fn indirect_ranges_stay_inside_the_arguments_written() {
    let _serial = vulkan::serial();
    let multi = vk::PhysicalDeviceFeatures::default().multi_draw_indirect(true);
    let s = setup_with_features(true, multi);
    let scene = Scene::new(&s);
    let allocator = s.device.gpu_allocator().expect("allocator");
    let d = &s.device;
    let usage = vk::BufferUsageFlags::INDIRECT_BUFFER;
    let args = Args::new(&s, &[draw(3, 0, 0)], &[indexed(3, 0, 0)], 1);
    let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    // (rule, form, the draws read, the count's element)
    let cases = [
        ("VUID-vkCmdDrawIndirect-drawCount-00487", Draw, 1..2, 0),
        ("VUID-vkCmdDrawIndirect-drawCount-00488", Draw, 0..2, 0),
        (
            "VUID-vkCmdDrawIndexedIndirect-drawCount-00539",
            Indexed,
            1..2,
            0,
        ),
        (
            "VUID-vkCmdDrawIndexedIndirect-drawCount-00540",
            Indexed,
            0..2,
            0,
        ),
        (
            "VUID-vkCmdDrawIndirectCount-maxDrawCount-03111",
            Count,
            0..2,
            0,
        ),
        (
            "VUID-vkCmdDrawIndexedIndirectCount-maxDrawCount-03143",
            IndexedCount,
            0..2,
            0,
        ),
        (
            "VUID-vkCmdDrawIndirectCount-countBufferOffset-04129",
            Count,
            0..1,
            1,
        ),
        (
            "VUID-vkCmdDrawIndexedIndirectCount-countBufferOffset-04129",
            IndexedCount,
            0..1,
            1,
        ),
    ];
    for (rule, form, range, count_at) in cases {
        breaks(&s, rule, Layer::Names, |unchecked| {
            scene.record(&mut cb, None, |rec| {
                args.record(rec, form, range.clone(), count_at, unchecked)
            })
        });
    }
    // A dispatch past the one written.
    let groups = [vk::DispatchIndirectCommand { x: 1, y: 1, z: 1 }];
    let dispatches = d
        .create_indirect_buffer(&groups, &allocator)
        .expect("dispatches");
    let raw_groups = plain(&s, &[1, 1, 1], usage);
    breaks(
        &s,
        "VUID-vkCmdDispatchIndirect-offset-00407",
        Layer::Names,
        |unchecked| {
            let mut rec = cb
                .begin(&tuff::CommandBufferBeginInfo::new())
                .expect("begin");
            rec.bind_pipeline(vk::PipelineBindPoint::COMPUTE, &scene.p.compute)
                .expect("bind");
            rec.bind_descriptor_sets(
                vk::PipelineBindPoint::COMPUTE,
                &scene.p.compute_layout,
                0,
                &scene.p.set,
                &[],
            )
            .expect("sets");
            if unchecked {
                unsafe { rec.dispatch_indirect_unchecked(&raw_groups.0, 12) }
            } else {
                rec.dispatch_indirect_from(&dispatches, 1)
            }
        },
    );
    // A reversed range is a mistake, not an empty one.
    #[allow(clippy::reversed_empty_ranges)]
    let reversed = 1..0;
    assert!(matches!(
        scene.record(&mut cb, None, |rec| rec
            .draw_indirect_from(&args.draws, reversed)),
        Err(tuff::Error::Misuse(_))
    ));
    assert_silent(&s.messages);
}

/// Arguments that break a rule of their struct are refused when written (at
/// creation and by `write`, which then writes nothing): a draw's firstInstance
/// without drawIndirectFirstInstance, a dispatch's group counts past
/// maxComputeWorkGroupCount. The layer cannot read arguments in a buffer, and says
/// nothing of the same words drawn through the `_unchecked` twins.
#[test]
fn indirect_arguments_are_checked_when_written() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let scene = Scene::new(&s);
    let allocator = s.device.gpu_allocator().expect("allocator");
    let d = &s.device;
    let usage = vk::BufferUsageFlags::INDIRECT_BUFFER;
    let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);

    let bad = [draw(3, 0, 1)];
    let raw = plain(&s, &words_of(&bad), usage);
    breaks(
        &s,
        "VUID-VkDrawIndirectCommand-firstInstance-00501",
        Layer::Silent,
        |unchecked| {
            if unchecked {
                scene.record(&mut cb, None, |r| unsafe {
                    r.draw_indirect_unchecked(&raw.0, 0, 1, 16)
                })
            } else {
                d.create_indirect_buffer(&bad, &allocator).map(drop)
            }
        },
    );
    let bad_indexed = [indexed(3, 0, 1)];
    let raw_indexed = plain(&s, &indexed_words(&bad_indexed), usage);
    breaks(
        &s,
        "VUID-VkDrawIndexedIndirectCommand-firstInstance-00554",
        Layer::Silent,
        |unchecked| {
            if unchecked {
                scene.record(&mut cb, None, |r| unsafe {
                    r.draw_indexed_indirect_unchecked(&raw_indexed.0, 0, 1, 20)
                })
            } else {
                d.create_indirect_buffer(&bad_indexed, &allocator).map(drop)
            }
        },
    );
    // `write` checks as creation does, and a refused write changes nothing.
    let mut draws = d
        .create_indirect_buffer(&[draw(3, 0, 0)], &allocator)
        .expect("draws");
    assert_eq!(
        vuid(draws.write(0, &bad)),
        "VUID-VkDrawIndirectCommand-firstInstance-00501"
    );
    assert_eq!(draws.arguments()[0].first_instance, 0);
    draws
        .write(0, &[draw(6, 0, 0)])
        .expect("a draw the device allows");
    assert_eq!(draws.arguments()[0].vertex_count, 6);
    assert!(matches!(
        draws.write(1, &[draw(3, 0, 0)]),
        Err(tuff::Error::Misuse(_))
    ));

    let max = s
        .physical
        .get_properties()
        .limits
        .max_compute_work_group_count;
    let rules = [
        "VUID-VkDispatchIndirectCommand-x-00417",
        "VUID-VkDispatchIndirectCommand-y-00418",
        "VUID-VkDispatchIndirectCommand-z-00419",
    ];
    for (axis, rule) in rules.into_iter().enumerate() {
        let mut counts = [1u32; 3];
        counts[axis] = max[axis] + 1;
        let groups = [vk::DispatchIndirectCommand {
            x: counts[0],
            y: counts[1],
            z: counts[2],
        }];
        let raw_groups = plain(&s, &counts, usage);
        breaks(&s, rule, Layer::Silent, |unchecked| {
            if unchecked {
                let mut rec = cb
                    .begin(&tuff::CommandBufferBeginInfo::new())
                    .expect("begin");
                rec.bind_pipeline(vk::PipelineBindPoint::COMPUTE, &scene.p.compute)
                    .expect("bind");
                rec.bind_descriptor_sets(
                    vk::PipelineBindPoint::COMPUTE,
                    &scene.p.compute_layout,
                    0,
                    &scene.p.set,
                    &[],
                )
                .expect("sets");
                unsafe { rec.dispatch_indirect_unchecked(&raw_groups.0, 0) }
            } else {
                d.create_indirect_buffer(&groups, &allocator).map(drop)
            }
        });
    }
    // With the feature on, a first instance is written and drawn.
    let first = vk::PhysicalDeviceFeatures::default().draw_indirect_first_instance(true);
    let s = setup_with_features(true, first);
    let scene = Scene::new(&s);
    let allocator = s.device.gpu_allocator().expect("allocator");
    let draws = s
        .device
        .create_indirect_buffer(&[draw(3, 0, 1)], &allocator)
        .expect("a first instance the device allows");
    let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    scene.record(&mut cb, None, |r| {
        r.draw_indirect_from(&draws, 0..1).expect("draw")
    });
    assert_silent(&s.messages);
}

/// Each draw read is checked as a direct draw's parameters: its vertex fetches
/// inside the bound vertex buffers (an indexed draw's, by every index the index
/// type holds, without robustBufferAccess), its indices inside the bound index
/// buffer. The layer does not read the arguments.
#[test]
fn indirect_draws_read_inside_their_bound_buffers() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let scene = Scene::new(&s);
    let allocator = s.device.gpu_allocator().expect("allocator");
    let d = &s.device;
    let empty = d
        .create_pipeline_layout(&tuff::PipelineLayoutCreateInfo::new())
        .expect("layout");
    // Binding 0: 20-byte vertices; the buffer holds three.
    let vertex_pipeline = pipelines::vertex_pipeline(&s, &empty, &scene.target.render_pass);
    let (vertices, _memory) = pipelines::host_buffer(&s, 60, vk::BufferUsageFlags::VERTEX_BUFFER);
    let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let fits = Args::new(&s, &[draw(3, 0, 0)], &[indexed(3, 0, 0)], 1);
    scene.record(&mut cb, Some(&vertex_pipeline), |r| {
        r.bind_vertex_buffers(0, &vertices, &[0]).expect("vertices");
        fits.record(r, Draw, 0..1, 0, false)
            .expect("a draw inside the buffer");
        fits.record(r, Count, 0..1, 0, false)
            .expect("a counted draw inside the buffer");
    });
    // A fourth vertex, and indices 1..4 of a three-index buffer.
    let past = Args::new(&s, &[draw(4, 0, 0)], &[indexed(3, 1, 0)], 1);
    // (rule, form, whether the vertex pipeline and buffer are bound)
    let cases = [
        ("VUID-vkCmdDrawIndirect-None-02721", Draw, true),
        ("VUID-vkCmdDrawIndirectCount-None-02721", Count, true),
        ("VUID-vkCmdDrawIndexedIndirect-None-02721", Indexed, true),
        (
            "VUID-vkCmdDrawIndexedIndirectCount-None-02721",
            IndexedCount,
            true,
        ),
        (
            "VUID-vkCmdDrawIndexedIndirect-robustBufferAccess2-07825",
            Indexed,
            false,
        ),
        (
            "VUID-vkCmdDrawIndexedIndirectCount-robustBufferAccess2-07825",
            IndexedCount,
            false,
        ),
    ];
    for (rule, form, fetches) in cases {
        let args = if fetches && matches!(form, Indexed | IndexedCount) {
            &fits
        } else {
            &past
        };
        breaks(&s, rule, Layer::Silent, |unchecked| {
            let pipeline = fetches.then_some(&vertex_pipeline);
            scene.record(&mut cb, pipeline, |r| {
                if fetches {
                    r.bind_vertex_buffers(0, &vertices, &[0]).expect("vertices");
                }
                args.record(r, form, 0..1, 0, unchecked)
            })
        });
    }
    // A draw of no instance fetches nothing.
    let none = d
        .create_indirect_buffer(
            &[vk::DrawIndexedIndirectCommand {
                instance_count: 0,
                ..indexed(3, 0, 0)
            }],
            &allocator,
        )
        .expect("indexed");
    scene.record(&mut cb, Some(&vertex_pipeline), |r| {
        r.bind_vertex_buffers(0, &vertices, &[0]).expect("vertices");
        r.draw_indexed_indirect_from(&none, 0..1)
            .expect("a draw of no instance");
    });
    assert_silent(&s.messages);
}

/// The count commands: the drawIndirectCount feature, and the draws the count the
/// host wrote names inside the arguments (the layer cannot read the count).
#[test]
fn indirect_counts_name_draws_the_arguments_hold() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let scene = Scene::new(&s);
    let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    // The range reads from element 1 of one: nothing past maxDrawCount 0, but the
    // count names draws from there.
    for (stored, rules) in [
        (
            1u32,
            [
                "VUID-vkCmdDrawIndirectCount-countBuffer-03121",
                "VUID-vkCmdDrawIndexedIndirectCount-countBuffer-03153",
            ],
        ),
        (
            2,
            [
                "VUID-vkCmdDrawIndirectCount-countBuffer-03122",
                "VUID-vkCmdDrawIndexedIndirectCount-countBuffer-03154",
            ],
        ),
    ] {
        let args = Args::new(&s, &[draw(3, 0, 0)], &[indexed(3, 0, 0)], stored);
        for (rule, form) in rules.into_iter().zip([Count, IndexedCount]) {
            breaks(&s, rule, Layer::Silent, |unchecked| {
                scene.record(&mut cb, None, |r| args.record(r, form, 1..1, 0, unchecked))
            });
        }
    }
    assert_silent(&s.messages);

    // Without drawIndirectCount.
    let s = tuff_setup::setup_bare(true);
    let scene = Scene::new(&s);
    let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let args = Args::new(&s, &[draw(3, 0, 0)], &[indexed(3, 0, 0)], 1);
    for (rule, form) in [
        ("VUID-vkCmdDrawIndirectCount-None-04445", Count),
        (
            "VUID-vkCmdDrawIndexedIndirectCount-None-04445",
            IndexedCount,
        ),
    ] {
        breaks(&s, rule, Layer::Names, |unchecked| {
            scene.record(&mut cb, None, |r| args.record(r, form, 0..1, 0, unchecked))
        });
    }
    assert_silent(&s.messages);
}

/// A draw in a multiview render pass instance draws no instance past
/// maxMultiviewInstanceIndex (lavapipe's is below the last 32-bit first instance):
/// the safe forms refuse it (the 1.3.239 layer does not read the arguments).
#[test]
fn multiview_indirect_draws_stay_under_the_instance_limit() {
    let _serial = vulkan::serial();
    let s = tuff_setup::setup_full_features(true);
    let target = s.color_target(SIZE, vk::ImageUsageFlags::empty());
    let p = pipelines::pipelines(&s, &target);
    let d = &s.device;
    let (indices, _memory) = plain(&s, &[0, 1, 2], vk::BufferUsageFlags::INDEX_BUFFER);
    let stages = pipelines::test_stages(&p.vert, &p.frag);
    let blend_attachments = [vk::PipelineColorBlendAttachmentState {
        color_write_mask: vk::ColorComponentFlags::RGBA,
        ..Default::default()
    }];
    let blend = tuff::PipelineColorBlendStateCreateInfo::new().attachments(&blend_attachments);
    let rgba = [vk::Format::R8G8B8A8_UNORM];
    let (mut made, _) =
        pipelines::with_graphics_info(&stages, &p.graphics_layout, &target.render_pass, |info| {
            let mut rendering = tuff::PipelineRenderingCreateInfo::new()
                .view_mask(1)
                .color_attachment_formats(&rgba);
            let info = info
                .render_pass(None)
                .color_blend_state(Some(&blend))
                .push_next(&mut rendering);
            d.create_graphics_pipelines(None, &[info])
        })
        .expect("pipeline");
    let pipeline = made.pop().expect("one pipeline");
    let color = [tuff::RenderingAttachmentInfo::new()
        .image_view(Some(&target.view))
        .image_layout(vk::ImageLayout::COLOR_ATTACHMENT_OPTIMAL)
        .load_op(vk::AttachmentLoadOp::CLEAR)
        .store_op(vk::AttachmentStoreOp::STORE)];
    let rendering = tuff::RenderingInfo::new()
        .render_area(area())
        .layer_count(1)
        .view_mask(1)
        .color_attachments(&color);
    let args = Args::new(&s, &[draw(3, 0, u32::MAX)], &[indexed(3, 0, u32::MAX)], 1);
    let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let cases = [
        (
            "VUID-vkCmdDrawIndirect-maxMultiviewInstanceIndex-02688",
            Draw,
        ),
        (
            "VUID-vkCmdDrawIndexedIndirect-maxMultiviewInstanceIndex-02688",
            Indexed,
        ),
        (
            "VUID-vkCmdDrawIndirectCount-maxMultiviewInstanceIndex-02688",
            Count,
        ),
        (
            "VUID-vkCmdDrawIndexedIndirectCount-maxMultiviewInstanceIndex-02688",
            IndexedCount,
        ),
    ];
    for (rule, form) in cases {
        breaks(&s, rule, Layer::Silent, |unchecked| {
            let rec = cb
                .begin(&tuff::CommandBufferBeginInfo::new())
                .expect("begin");
            let mut rec = rec.begin_rendering(&rendering);
            rec.bind_pipeline(vk::PipelineBindPoint::GRAPHICS, &pipeline)
                .expect("bind");
            rec.bind_index_buffer(&indices, 0, vk::IndexType::UINT32)
                .expect("index buffer");
            state(&mut rec);
            pipelines::push_color(&mut rec, &p);
            args.record(&mut rec, form, 0..1, 0, unchecked)
        });
    }
    assert_silent(&s.messages);
}

/// No write reaches arguments a recording may read: while a command buffer that
/// recorded the buffer has not been recorded again or freed, `write` is refused;
/// afterwards it writes. (A recording dropped before it ends cannot be submitted,
/// and keeps nothing.)
#[test]
fn indirect_buffers_are_written_only_when_no_recording_reads_them() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let scene = Scene::new(&s);
    let allocator = s.device.gpu_allocator().expect("allocator");
    let mut draws = s
        .device
        .create_indirect_buffer(&[draw(3, 0, 0)], &allocator)
        .expect("draws");
    let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let record = |cb: &mut tuff::CommandBuffer,
                  draws: &tuff::IndirectBuffer<vk::DrawIndirectCommand>| {
        let mut rec = scene.begin(cb, None);
        rec.draw_indirect_from(draws, 0..1).expect("draw");
        rec.end_render_pass().end().expect("end");
    };
    record(&mut cb, &draws);
    assert!(matches!(
        draws.write(0, &[draw(6, 0, 0)]),
        Err(tuff::Error::Misuse(_))
    ));
    assert_eq!(draws.arguments()[0].vertex_count, 3);
    // Recording the command buffer again drops what it kept.
    drop(
        cb.begin(&tuff::CommandBufferBeginInfo::new())
            .expect("begin"),
    );
    draws
        .write(0, &[draw(6, 0, 0)])
        .expect("no recording reads the arguments");
    record(&mut cb, &draws);
    assert!(matches!(
        draws.write(0, &[draw(3, 0, 0)]),
        Err(tuff::Error::Misuse(_))
    ));
    drop(cb);
    draws
        .write(0, &[draw(3, 0, 0)])
        .expect("the command buffer is freed");
    assert_silent(&s.messages);
}
