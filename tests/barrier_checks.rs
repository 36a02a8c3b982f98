//! Pipeline barriers: each buffer and image barrier is checked against the resource
//! it names (the usage a layout needs, the aspects of its format, its sharing mode
//! and the queue families it transfers between), and the barrier's stages and
//! access types against each other and against the render pass instance it is
//! recorded in.
//!
//! Each case records one barrier that breaks one rule: tuff must refuse the safe
//! call with the rule's VUID, and the validation layer, for the `_unchecked` twin
//! (told to skip the call it reports), must name the same VUID.
//!
//! Each case runs in both versions: `vkCmdPipelineBarrier`, and the same barriers
//! as synchronization2's structs (each under the command's stages) through
//! `vkCmdPipelineBarrier2`, whose rules have the same numbers.
//!
//! SAFETY of the `unsafe` blocks: each `_unchecked` call breaks only the rule under
//! test, which the layer reports and so skips; no command buffer is submitted.

#[path = "common/tuff_setup.rs"]
mod tuff_setup;
#[path = "common/vulkan.rs"]
mod vulkan;

use tuff::vk;
use tuff_setup::{setup, setup_bare, setup_full_features, vuid, Setup};
use vulkan::assert_silent;

type L = vk::ImageLayout;
type U = vk::ImageUsageFlags;
type S = vk::PipelineStageFlags;
type A = vk::AccessFlags;
type S2 = vk::PipelineStageFlags2;
type A2 = vk::AccessFlags2;
const COLOR: vk::ImageAspectFlags = vk::ImageAspectFlags::COLOR;
const DEPTH: vk::ImageAspectFlags = vk::ImageAspectFlags::DEPTH;
const STENCIL: vk::ImageAspectFlags = vk::ImageAspectFlags::STENCIL;
const IGNORED: u32 = vk::QUEUE_FAMILY_IGNORED;

/// The images and the buffer the cases name.
struct Objects {
    /// RGBA8 for transfers only.
    color: tuff::Image,
    /// RGBA8, sampled and a transfer destination, never a source.
    no_src: tuff::Image,
    /// RGBA8, sampled and a transfer source, never a destination.
    no_dst: tuff::Image,
    /// D32 with S8, a transfer destination only.
    depth: tuff::Image,
    buffer: tuff::Buffer,
    _memory: Vec<tuff::DeviceMemory>,
}

fn image(s: &Setup, format: vk::Format, usage: U) -> (tuff::Image, tuff::DeviceMemory) {
    let image = s
        .device
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
                .usage(usage),
        )
        .expect("image");
    let memory = s.bind_image(&image);
    (image, memory)
}

fn objects(s: &Setup) -> Objects {
    let rgba = vk::Format::R8G8B8A8_UNORM;
    let (color, m1) = image(s, rgba, U::TRANSFER_SRC | U::TRANSFER_DST);
    let (no_src, m2) = image(s, rgba, U::SAMPLED | U::TRANSFER_DST);
    let (no_dst, m3) = image(s, rgba, U::SAMPLED | U::TRANSFER_SRC);
    let (depth, m4) = image(s, vk::Format::D32_SFLOAT_S8_UINT, U::TRANSFER_DST);
    let buffer = s
        .device
        .create_buffer(
            &tuff::BufferCreateInfo::new()
                .size(256)
                .usage(vk::BufferUsageFlags::TRANSFER_DST),
        )
        .expect("buffer");
    let needs = s
        .device
        .get_buffer_memory_requirements(&buffer)
        .expect("requirements");
    let m5 = s
        .device
        .allocate_memory(
            &tuff::MemoryAllocateInfo::new()
                .allocation_size(needs.size)
                .memory_type_index(
                    s.memory_type(needs.memory_type_bits, vk::MemoryPropertyFlags::empty()),
                ),
        )
        .expect("memory");
    s.device.bind_buffer_memory(&buffer, &m5, 0).expect("bind");
    Objects {
        color,
        no_src,
        no_dst,
        depth,
        buffer,
        _memory: vec![m1, m2, m3, m4, m5],
    }
}

fn range(aspect: vk::ImageAspectFlags) -> vk::ImageSubresourceRange {
    vk::ImageSubresourceRange {
        aspect_mask: aspect,
        base_mip_level: 0,
        level_count: 1,
        base_array_layer: 0,
        layer_count: 1,
    }
}

/// A barrier of the whole of `image` (aspects `aspect`) from `old` to `new`, on no
/// queue family transfer, with no access.
fn image_barrier<'a>(
    image: &'a tuff::Image,
    aspect: vk::ImageAspectFlags,
    old: L,
    new: L,
) -> tuff::ImageMemoryBarrier<'a> {
    tuff::ImageMemoryBarrier::new(image)
        .old_layout(old)
        .new_layout(new)
        .src_queue_family_index(IGNORED)
        .dst_queue_family_index(IGNORED)
        .subresource_range(range(aspect))
}

fn buffer_barrier(buffer: &tuff::Buffer) -> tuff::BufferMemoryBarrier<'_> {
    tuff::BufferMemoryBarrier::new(buffer)
        .src_queue_family_index(IGNORED)
        .dst_queue_family_index(IGNORED)
        .offset(0)
        .size(vk::WHOLE_SIZE)
}

/// The wrappers the cases' barriers name, by which the second version's structs
/// (which borrow them) are built from the first's (which hold raw handles).
struct Handles<'h> {
    images: Vec<&'h tuff::Image>,
    buffers: Vec<&'h tuff::Buffer>,
}

impl<'h> Handles<'h> {
    fn of(o: &'h Objects, more: &[&'h tuff::Image]) -> Self {
        let mut images = vec![&o.color, &o.no_src, &o.no_dst, &o.depth];
        images.extend(more);
        Handles {
            images,
            buffers: vec![&o.buffer],
        }
    }

    fn image(&self, raw: vk::Image) -> &'h tuff::Image {
        use tuff::Handle as _;
        self.images
            .iter()
            .find(|i| i.raw() == raw)
            .expect("a barrier names an image of the cases")
    }

    fn buffer(&self, raw: vk::Buffer) -> &'h tuff::Buffer {
        use tuff::Handle as _;
        self.buffers
            .iter()
            .find(|b| b.raw() == raw)
            .expect("a barrier names the buffer of the cases")
    }
}

/// Which command records a case.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Version {
    One,
    Two,
}

impl Version {
    /// The rule of this version with the number `rule` (a first-version VUID) has.
    fn rule(self, rule: &str) -> String {
        match self {
            Version::One => rule.to_string(),
            Version::Two => rule
                .replace("MemoryBarrier-", "MemoryBarrier2-")
                .replace("vkCmdPipelineBarrier-", "vkCmdPipelineBarrier2-"),
        }
    }
}

/// One pipeline barrier: its stages, flags and barriers.
struct Barrier<'a> {
    stages: (S, S),
    flags: vk::DependencyFlags,
    memory: Vec<tuff::MemoryBarrier<'a>>,
    buffers: Vec<tuff::BufferMemoryBarrier<'a>>,
    images: Vec<tuff::ImageMemoryBarrier<'a>>,
}

impl<'a> Barrier<'a> {
    fn new() -> Self {
        Barrier {
            stages: (S::TRANSFER, S::TRANSFER),
            flags: vk::DependencyFlags::empty(),
            memory: Vec::new(),
            buffers: Vec::new(),
            images: Vec::new(),
        }
    }

    fn image(mut self, b: tuff::ImageMemoryBarrier<'a>) -> Self {
        self.images.push(b);
        self
    }

    fn record<St: tuff::recorder::State>(
        &self,
        rec: &mut tuff::Recorder<'_, St>,
        unchecked: bool,
    ) -> tuff::Result<()> {
        let (src, dst) = self.stages;
        if unchecked {
            unsafe {
                rec.pipeline_barrier_unchecked(
                    src,
                    dst,
                    self.flags,
                    &self.memory,
                    &self.buffers,
                    &self.images,
                )
            }
        } else {
            rec.pipeline_barrier(
                src,
                dst,
                self.flags,
                &self.memory,
                &self.buffers,
                &self.images,
            )
        }
    }

    /// Records the same barriers through `vkCmdPipelineBarrier2`, each under the
    /// command's stages.
    fn record2<St: tuff::recorder::State>(
        &self,
        rec: &mut tuff::Recorder<'_, St>,
        unchecked: bool,
        handles: &Handles<'_>,
    ) -> tuff::Result<()> {
        let widen = |s: S| S2::from_raw(u64::from(s.as_raw()));
        let access = |a: A| A2::from_raw(u64::from(a.as_raw()));
        let (src, dst) = (widen(self.stages.0), widen(self.stages.1));
        // The second version's stages are its barriers': an execution dependency
        // without barriers is a memory barrier without access types.
        let none = [tuff::MemoryBarrier::new()];
        let bare = self.memory.is_empty() && self.buffers.is_empty() && self.images.is_empty();
        let memory: Vec<_> = if bare { &none[..] } else { &self.memory[..] }
            .iter()
            .map(|b| {
                tuff::MemoryBarrier2::new()
                    .src_stage_mask(src)
                    .dst_stage_mask(dst)
                    .src_access_mask(access(b.src_access_mask))
                    .dst_access_mask(access(b.dst_access_mask))
            })
            .collect();
        let buffers: Vec<_> = self
            .buffers
            .iter()
            .map(|b| {
                tuff::BufferMemoryBarrier2::new(handles.buffer(b.buffer))
                    .src_stage_mask(src)
                    .dst_stage_mask(dst)
                    .src_access_mask(access(b.src_access_mask))
                    .dst_access_mask(access(b.dst_access_mask))
                    .src_queue_family_index(b.src_queue_family_index)
                    .dst_queue_family_index(b.dst_queue_family_index)
                    .offset(b.offset)
                    .size(b.size)
            })
            .collect();
        let images: Vec<_> = self
            .images
            .iter()
            .map(|b| {
                tuff::ImageMemoryBarrier2::new(handles.image(b.image))
                    .src_stage_mask(src)
                    .dst_stage_mask(dst)
                    .src_access_mask(access(b.src_access_mask))
                    .dst_access_mask(access(b.dst_access_mask))
                    .src_queue_family_index(b.src_queue_family_index)
                    .dst_queue_family_index(b.dst_queue_family_index)
                    .old_layout(b.old_layout)
                    .new_layout(b.new_layout)
                    .subresource_range(b.subresource_range)
            })
            .collect();
        let info = tuff::DependencyInfo::new()
            .dependency_flags(self.flags)
            .memory_barriers(&memory)
            .buffer_memory_barriers(&buffers)
            .image_memory_barriers(&images);
        if unchecked {
            unsafe { rec.pipeline_barrier2_unchecked(&info) }
        } else {
            rec.pipeline_barrier2(&info)
        }
    }

    /// Records the barriers through `version`'s command.
    fn record_as<St: tuff::recorder::State>(
        &self,
        rec: &mut tuff::Recorder<'_, St>,
        unchecked: bool,
        (version, handles): (Version, &Handles<'_>),
    ) -> tuff::Result<()> {
        match version {
            Version::One => self.record(rec, unchecked),
            Version::Two => self.record2(rec, unchecked, handles),
        }
    }
}

/// What the 1.3.239 layer says of a case's unchecked barrier.
#[derive(Clone, Copy)]
enum Layer {
    /// It names the rule.
    Names,
    /// It names the rule by another VUID of the same condition.
    NamesAs(&'static str),
    /// It does not check the rule and reports no error: tuff's error alone proves it.
    Silent,
}

/// Records `barrier` safely (which must name `rule`) and unchecked under the layer
/// (which must say what `layer` says) into a new command buffer; returns what went
/// wrong.
fn try_case(
    s: &Setup,
    what: &str,
    barrier: &Barrier<'_>,
    (rule, version, handles): (&str, Version, &Handles<'_>),
    layer_says: Layer,
) -> Option<String> {
    let rule: &str = &version.rule(rule);
    let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let mut rec = cb
        .begin(&tuff::CommandBufferBeginInfo::new())
        .expect("begin");
    let safe = match barrier.record_as(&mut rec, false, (version, handles)) {
        Err(tuff::Error::Validation { vuid, .. }) => vuid.to_string(),
        other => format!("{other:?}"),
    };
    s.messages.take();
    s.messages.abort_on_error(true);
    let _ = barrier.record_as(&mut rec, true, (version, handles));
    s.messages.abort_on_error(false);
    let layer = s.messages.take();
    rec.end().expect("end");
    let what = format!("{what} ({version:?})");
    verdict(&what, (safe.as_str(), rule), &layer, layer_says, &|other| {
        version.rule(other)
    })
}

/// What went wrong with a case, if anything: tuff's error was not `rule`, or the
/// layer did not say what `says` expects (`as_rule` names a `NamesAs` rule in the
/// case's version).
fn verdict(
    what: &str,
    (safe, rule): (&str, &str),
    layer: &[String],
    says: Layer,
    as_rule: &dyn Fn(&str) -> String,
) -> Option<String> {
    let errors: Vec<_> = layer.iter().filter(|m| m.starts_with("ERROR")).collect();
    let named = match says {
        Layer::Names => errors.iter().any(|m| m.contains(rule)),
        Layer::NamesAs(other) => errors.iter().any(|m| m.contains(&as_rule(other))),
        Layer::Silent => errors.is_empty(),
    };
    (safe != rule || !named).then(|| {
        format!(
            "{what}: tuff said {safe}, expected {rule}; the layer said {:?}",
            layer
                .iter()
                .map(|m| m.split(']').next().unwrap_or(m))
                .collect::<Vec<_>>()
        )
    })
}

/// Image barriers whose layouts need a usage the image lacks, whose new layout is
/// none, whose aspects do not fit the format, or whose queue families cannot be
/// transferred between; buffer barriers likewise; and access types no stage of
/// the barrier supports.
#[test]
fn barriers_are_checked_against_their_resources_and_the_layer_agrees() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let o = objects(&s);
    let ds = DEPTH | STENCIL;
    let layout_cases: [(&tuff::Image, vk::ImageAspectFlags, L, &str); 10] = [
        (
            &o.color,
            COLOR,
            L::COLOR_ATTACHMENT_OPTIMAL,
            "oldLayout-01208",
        ),
        (
            &o.depth,
            ds,
            L::DEPTH_STENCIL_ATTACHMENT_OPTIMAL,
            "oldLayout-01209",
        ),
        (
            &o.depth,
            ds,
            L::DEPTH_STENCIL_READ_ONLY_OPTIMAL,
            "oldLayout-01210",
        ),
        (
            &o.color,
            COLOR,
            L::SHADER_READ_ONLY_OPTIMAL,
            "oldLayout-01211",
        ),
        (&o.no_src, COLOR, L::TRANSFER_SRC_OPTIMAL, "oldLayout-01212"),
        (&o.no_dst, COLOR, L::TRANSFER_DST_OPTIMAL, "oldLayout-01213"),
        (
            &o.depth,
            ds,
            L::DEPTH_READ_ONLY_STENCIL_ATTACHMENT_OPTIMAL,
            "oldLayout-01658",
        ),
        (
            &o.depth,
            ds,
            L::DEPTH_ATTACHMENT_STENCIL_READ_ONLY_OPTIMAL,
            "oldLayout-01659",
        ),
        (
            &o.color,
            COLOR,
            L::ATTACHMENT_OPTIMAL,
            "srcQueueFamilyIndex-03938",
        ),
        (
            &o.color,
            COLOR,
            L::READ_ONLY_OPTIMAL,
            "srcQueueFamilyIndex-03939",
        ),
    ];
    let handles = Handles::of(&o, &[]);
    let mut wrong = Vec::new();
    for version in [Version::One, Version::Two] {
        for &(image, aspect, layout, tail) in &layout_cases {
            let rule = format!("VUID-VkImageMemoryBarrier-{tail}");
            let b = Barrier::new().image(image_barrier(image, aspect, L::UNDEFINED, layout));
            // The 1.3.239 layer does not check the usage of synchronization2's layouts.
            let layer = if tail.starts_with("srcQueueFamilyIndex") {
                Layer::Silent
            } else {
                Layer::Names
            };
            let what = format!("to {layout:?}");
            wrong.extend(try_case(&s, &what, &b, (&rule, version, &handles), layer));
        }
    }
    let cases: Vec<(&str, Barrier<'_>, &str, Layer)> = vec![
        (
            "a barrier to UNDEFINED",
            Barrier::new().image(image_barrier(&o.color, COLOR, L::GENERAL, L::UNDEFINED)),
            "VUID-VkImageMemoryBarrier-newLayout-01198",
            Layer::Names,
        ),
        (
            "the depth aspect of a color image",
            Barrier::new().image(image_barrier(&o.color, DEPTH, L::UNDEFINED, L::GENERAL)),
            "VUID-VkImageMemoryBarrier-image-01671",
            Layer::Names,
        ),
        (
            "the depth aspect alone of a depth/stencil image",
            Barrier::new().image(image_barrier(&o.depth, DEPTH, L::UNDEFINED, L::GENERAL)),
            "VUID-VkImageMemoryBarrier-image-03320",
            Layer::Names,
        ),
        (
            "an image transfer between two special families",
            Barrier::new().image(
                image_barrier(&o.color, COLOR, L::GENERAL, L::GENERAL)
                    .src_queue_family_index(vk::QUEUE_FAMILY_EXTERNAL)
                    .dst_queue_family_index(vk::QUEUE_FAMILY_FOREIGN_EXT),
            ),
            "VUID-VkImageMemoryBarrier-srcQueueFamilyIndex-04070",
            Layer::Silent,
        ),
        (
            "an image transfer from a family the device has not",
            Barrier::new().image(
                image_barrier(&o.color, COLOR, L::GENERAL, L::GENERAL)
                    .src_queue_family_index(7)
                    .dst_queue_family_index(0),
            ),
            "VUID-VkImageMemoryBarrier-image-04072",
            Layer::Names,
        ),
        (
            "a memory barrier reading in a stage that does not read",
            Barrier {
                memory: vec![tuff::MemoryBarrier::new().src_access_mask(A::SHADER_READ)],
                ..Barrier::new()
            },
            "VUID-vkCmdPipelineBarrier-srcAccessMask-02815",
            Layer::Names,
        ),
        (
            "a memory barrier writing in a stage that does not write",
            Barrier {
                memory: vec![tuff::MemoryBarrier::new().dst_access_mask(A::SHADER_WRITE)],
                ..Barrier::new()
            },
            "VUID-vkCmdPipelineBarrier-dstAccessMask-02816",
            Layer::Names,
        ),
        (
            "a buffer barrier's source access",
            Barrier {
                buffers: vec![buffer_barrier(&o.buffer).src_access_mask(A::UNIFORM_READ)],
                ..Barrier::new()
            },
            "VUID-vkCmdPipelineBarrier-pBufferMemoryBarriers-02817",
            Layer::NamesAs("VUID-vkCmdPipelineBarrier-srcAccessMask-02815"),
        ),
        (
            "a buffer barrier's destination access",
            Barrier {
                buffers: vec![buffer_barrier(&o.buffer).dst_access_mask(A::UNIFORM_READ)],
                ..Barrier::new()
            },
            "VUID-vkCmdPipelineBarrier-pBufferMemoryBarriers-02818",
            Layer::NamesAs("VUID-vkCmdPipelineBarrier-dstAccessMask-02816"),
        ),
        (
            "an image barrier's source access",
            Barrier::new().image(
                image_barrier(&o.color, COLOR, L::GENERAL, L::GENERAL)
                    .src_access_mask(A::COLOR_ATTACHMENT_WRITE),
            ),
            "VUID-vkCmdPipelineBarrier-pImageMemoryBarriers-02819",
            Layer::NamesAs("VUID-vkCmdPipelineBarrier-srcAccessMask-02815"),
        ),
        (
            "an image barrier's destination access",
            Barrier::new().image(
                image_barrier(&o.color, COLOR, L::GENERAL, L::GENERAL)
                    .dst_access_mask(A::COLOR_ATTACHMENT_WRITE),
            ),
            "VUID-vkCmdPipelineBarrier-pImageMemoryBarriers-02820",
            Layer::NamesAs("VUID-vkCmdPipelineBarrier-dstAccessMask-02816"),
        ),
        (
            "a view-local barrier outside a render pass instance",
            Barrier {
                flags: vk::DependencyFlags::VIEW_LOCAL,
                ..Barrier::new()
            },
            "VUID-vkCmdPipelineBarrier-dependencyFlags-01186",
            Layer::Names,
        ),
        (
            "a buffer transfer between two special families",
            Barrier {
                buffers: vec![buffer_barrier(&o.buffer)
                    .src_queue_family_index(vk::QUEUE_FAMILY_EXTERNAL)
                    .dst_queue_family_index(vk::QUEUE_FAMILY_FOREIGN_EXT)],
                ..Barrier::new()
            },
            "VUID-VkBufferMemoryBarrier-srcQueueFamilyIndex-04087",
            Layer::Silent,
        ),
        (
            "a buffer transfer from a family the device has not",
            Barrier {
                buffers: vec![buffer_barrier(&o.buffer)
                    .src_queue_family_index(7)
                    .dst_queue_family_index(0)],
                ..Barrier::new()
            },
            "VUID-VkBufferMemoryBarrier-buffer-04089",
            Layer::Names,
        ),
    ];
    for version in [Version::One, Version::Two] {
        for (what, b, rule, layer) in &cases {
            // The second version's access types are its structs' own rules.
            if version == Version::Two && rule.contains("-028") {
                continue;
            }
            wrong.extend(try_case(&s, what, b, (rule, version, &handles), *layer));
        }
    }
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
    assert_silent(&s.messages);
}

/// Without synchronization2 a stage mask may not be 0.
#[test]
fn an_empty_stage_mask_needs_synchronization2() {
    let _serial = vulkan::serial();
    let s = setup_bare(true);
    let mut wrong = Vec::new();
    for (stages, rule) in [
        (
            (S::empty(), S::TRANSFER),
            "VUID-vkCmdPipelineBarrier-srcStageMask-03937",
        ),
        (
            (S::TRANSFER, S::empty()),
            "VUID-vkCmdPipelineBarrier-dstStageMask-03937",
        ),
    ] {
        let b = Barrier {
            stages,
            ..Barrier::new()
        };
        // The second version needs synchronization2, which allows an empty mask.
        let handles = Handles {
            images: Vec::new(),
            buffers: Vec::new(),
        };
        wrong.extend(try_case(
            &s,
            rule,
            &b,
            (rule, Version::One, &handles),
            Layer::Names,
        ));
    }
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
    assert_silent(&s.messages);
}

/// The layouts of separate depth and stencil aspects need the usage too, and with
/// separateDepthStencilLayouts a barrier names the depth or the stencil aspect.
#[test]
fn separate_depth_and_stencil_layouts_are_checked() {
    let _serial = vulkan::serial();
    let s = setup_full_features(true);
    let o = objects(&s);
    let handles = Handles::of(&o, &[]);
    let mut wrong = Vec::new();
    for (aspect, layout, tail, version) in [Version::One, Version::Two].into_iter().flat_map(|v| {
        [
            (
                DEPTH,
                L::DEPTH_READ_ONLY_OPTIMAL,
                "srcQueueFamilyIndex-04065",
            ),
            (
                DEPTH,
                L::DEPTH_ATTACHMENT_OPTIMAL,
                "srcQueueFamilyIndex-04066",
            ),
            (
                STENCIL,
                L::STENCIL_READ_ONLY_OPTIMAL,
                "srcQueueFamilyIndex-04067",
            ),
            (
                STENCIL,
                L::STENCIL_ATTACHMENT_OPTIMAL,
                "srcQueueFamilyIndex-04068",
            ),
            (COLOR, L::GENERAL, "image-03319"),
        ]
        .map(|(a, l, t)| (a, l, t, v))
    }) {
        let rule = format!("VUID-VkImageMemoryBarrier-{tail}");
        let b = Barrier::new().image(image_barrier(&o.depth, aspect, L::UNDEFINED, layout));
        // The 1.3.239 layer does not check the usage of separate depth and stencil
        // layouts.
        let layer = if tail.starts_with("srcQueueFamilyIndex") {
            Layer::Silent
        } else {
            Layer::Names
        };
        wrong.extend(try_case(&s, &rule, &b, (&rule, version, &handles), layer));
    }
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
    assert_silent(&s.messages);
}

/// Inside a render pass instance a barrier may not name a buffer, change a layout
/// or transfer ownership; inside dynamic rendering there may be none.
#[test]
fn barriers_inside_render_pass_instances_are_checked() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let target = s.color_target(4, U::TRANSFER_SRC);
    let o = objects(&s);
    let area = vk::Rect2D {
        offset: vk::Offset2D::default(),
        extent: vk::Extent2D {
            width: 4,
            height: 4,
        },
    };
    let clear = [vk::ClearValue::default()];
    // A render pass whose subpass depends on itself, as a barrier inside it needs
    // (VUID-vkCmdPipelineBarrier-pDependencies-02285, which the layer checks first).
    let attachments = [vk::AttachmentDescription {
        format: vk::Format::R8G8B8A8_UNORM,
        samples: vk::SampleCountFlags::TYPE_1,
        load_op: vk::AttachmentLoadOp::CLEAR,
        store_op: vk::AttachmentStoreOp::STORE,
        stencil_load_op: vk::AttachmentLoadOp::DONT_CARE,
        stencil_store_op: vk::AttachmentStoreOp::DONT_CARE,
        initial_layout: L::UNDEFINED,
        final_layout: L::COLOR_ATTACHMENT_OPTIMAL,
        ..Default::default()
    }];
    let color_ref = [vk::AttachmentReference {
        attachment: 0,
        layout: L::COLOR_ATTACHMENT_OPTIMAL,
    }];
    let subpasses = [tuff::SubpassDescription::new()
        .pipeline_bind_point(vk::PipelineBindPoint::GRAPHICS)
        .color_attachments(&color_ref)];
    let itself = [vk::SubpassDependency {
        src_subpass: 0,
        dst_subpass: 0,
        src_stage_mask: S::COLOR_ATTACHMENT_OUTPUT,
        dst_stage_mask: S::COLOR_ATTACHMENT_OUTPUT,
        src_access_mask: A::COLOR_ATTACHMENT_WRITE,
        dst_access_mask: A::COLOR_ATTACHMENT_WRITE,
        dependency_flags: vk::DependencyFlags::BY_REGION,
    }];
    let render_pass = s
        .device
        .create_render_pass(
            &tuff::RenderPassCreateInfo::new()
                .attachments(&attachments)
                .subpasses(&subpasses)
                .dependencies(&itself),
        )
        .expect("render pass");
    let framebuffer = s
        .device
        .create_framebuffer(
            &tuff::FramebufferCreateInfo::new(&render_pass)
                .attachments(&target.view)
                .width(4)
                .height(4)
                .layers(1),
        )
        .expect("framebuffer");
    let begin = tuff::RenderPassBeginInfo::new(&render_pass, &framebuffer)
        .render_area(area)
        .clear_values(&clear);
    let attachment = L::COLOR_ATTACHMENT_OPTIMAL;
    let cases: Vec<(Barrier<'_>, &str)> = vec![
        (
            Barrier {
                stages: (S::COLOR_ATTACHMENT_OUTPUT, S::COLOR_ATTACHMENT_OUTPUT),
                flags: vk::DependencyFlags::BY_REGION,
                buffers: vec![buffer_barrier(&o.buffer)],
                ..Barrier::new()
            },
            "VUID-vkCmdPipelineBarrier-bufferMemoryBarrierCount-01178",
        ),
        (
            Barrier {
                stages: (S::COLOR_ATTACHMENT_OUTPUT, S::COLOR_ATTACHMENT_OUTPUT),
                flags: vk::DependencyFlags::BY_REGION,
                ..Barrier::new()
            }
            .image(image_barrier(&target.image, COLOR, attachment, L::GENERAL)),
            "VUID-vkCmdPipelineBarrier-oldLayout-01181",
        ),
        (
            Barrier {
                stages: (S::COLOR_ATTACHMENT_OUTPUT, S::COLOR_ATTACHMENT_OUTPUT),
                flags: vk::DependencyFlags::BY_REGION,
                ..Barrier::new()
            }
            .image(
                image_barrier(&target.image, COLOR, attachment, attachment)
                    .src_queue_family_index(s.family)
                    .dst_queue_family_index(vk::QUEUE_FAMILY_EXTERNAL),
            ),
            "VUID-vkCmdPipelineBarrier-srcQueueFamilyIndex-01182",
        ),
        (
            Barrier {
                stages: (S::COLOR_ATTACHMENT_OUTPUT, S::COLOR_ATTACHMENT_OUTPUT),
                flags: vk::DependencyFlags::BY_REGION,
                ..Barrier::new()
            }
            .image(image_barrier(&o.color, COLOR, L::GENERAL, L::GENERAL)),
            "VUID-vkCmdPipelineBarrier-image-04073",
        ),
        (
            // Wider than the subpass's dependency on itself.
            Barrier {
                stages: (S::ALL_COMMANDS, S::COLOR_ATTACHMENT_OUTPUT),
                flags: vk::DependencyFlags::BY_REGION,
                ..Barrier::new()
            },
            "VUID-vkCmdPipelineBarrier-pDependencies-02285",
        ),
    ];
    let handles = Handles::of(&o, &[&target.image]);
    let versions = [Version::One, Version::Two];
    let mut wrong = Vec::new();
    for (version, (b, rule)) in versions
        .iter()
        .flat_map(|v| cases.iter().map(move |c| (*v, c)))
    {
        let rule = &version.rule(rule);
        let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
        let rec = cb
            .begin(&tuff::CommandBufferBeginInfo::new())
            .expect("begin");
        let mut rec = rec.begin_render_pass(&begin, vk::SubpassContents::INLINE);
        let safe = match b.record_as(&mut rec, false, (version, &handles)) {
            Err(tuff::Error::Validation { vuid, .. }) => vuid.to_string(),
            other => format!("{other:?}"),
        };
        s.messages.take();
        s.messages.abort_on_error(true);
        let _ = b.record_as(&mut rec, true, (version, &handles));
        s.messages.abort_on_error(false);
        let layer = s.messages.take();
        rec.end_render_pass().end().expect("end");
        if safe != *rule || !layer.iter().any(|m| m.contains(rule)) {
            wrong.push(format!(
                "{version:?}: tuff said {safe}, expected {rule}; the layer said {:?}",
                layer
                    .iter()
                    .map(|m| m.split(']').next().unwrap_or(m))
                    .collect::<Vec<_>>()
            ));
        }
    }
    // Dynamic rendering.
    let rule = "VUID-vkCmdPipelineBarrier-None-06191";
    let rule2 = &Version::Two.rule(rule);
    let color = [tuff::RenderingAttachmentInfo::new()
        .image_view(Some(&target.view))
        .image_layout(attachment)
        .load_op(vk::AttachmentLoadOp::CLEAR)
        .store_op(vk::AttachmentStoreOp::STORE)];
    let info = tuff::RenderingInfo::new()
        .render_area(area)
        .layer_count(1)
        .color_attachments(&color);
    let b = Barrier {
        stages: (S::COLOR_ATTACHMENT_OUTPUT, S::COLOR_ATTACHMENT_OUTPUT),
        ..Barrier::new()
    };
    let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let mut rec = cb
        .begin(&tuff::CommandBufferBeginInfo::new())
        .expect("begin");
    let to_attachment = Barrier {
        stages: (S::TOP_OF_PIPE, S::COLOR_ATTACHMENT_OUTPUT),
        ..Barrier::new()
    }
    .image(
        image_barrier(&target.image, COLOR, L::UNDEFINED, attachment)
            .dst_access_mask(A::COLOR_ATTACHMENT_WRITE),
    );
    to_attachment
        .record(&mut rec, false)
        .expect("to COLOR_ATTACHMENT_OPTIMAL");
    let mut rec = rec.begin_rendering(&info);
    for (version, rule) in [(Version::One, rule), (Version::Two, rule2)] {
        assert_eq!(
            vuid(b.record_as(&mut rec, false, (version, &handles))),
            rule
        );
        s.messages.take();
        s.messages.abort_on_error(true);
        let _ = b.record_as(&mut rec, true, (version, &handles));
        s.messages.abort_on_error(false);
        let layer = s.messages.take();
        assert!(
            layer.iter().any(|m| m.contains(rule)),
            "the layer did not name {rule}: {layer:?}"
        );
    }
    rec.end_rendering().end().expect("end");
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
    assert_silent(&s.messages);
}

/// Records `info` through `vkCmdPipelineBarrier2`, safely (which must name `rule`)
/// and unchecked under the layer (which must say what `layer_says`); returns what
/// went wrong.
fn try_dependency(
    s: &Setup,
    what: &str,
    info: &tuff::DependencyInfo<'_>,
    rule: &str,
    layer_says: Layer,
) -> Option<String> {
    let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let mut rec = cb
        .begin(&tuff::CommandBufferBeginInfo::new())
        .expect("begin");
    let safe = vuid(rec.pipeline_barrier2(info));
    s.messages.take();
    s.messages.abort_on_error(true);
    let _ = unsafe { rec.pipeline_barrier2_unchecked(info) };
    s.messages.abort_on_error(false);
    let layer = s.messages.take();
    rec.end().expect("end");
    verdict(what, (safe, rule), &layer, layer_says, &str::to_string)
}

/// A second-version barrier that names the host stage transfers no queue family
/// ownership (03851, 03854), and a layout transition after host writes starts from
/// a layout the host can write (03855); a host barrier that does neither is recorded.
#[test]
fn a_host_barrier_transfers_nothing_and_moves_from_host_layouts() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let o = objects(&s);
    fn host(b: tuff::ImageMemoryBarrier2<'_>) -> tuff::ImageMemoryBarrier2<'_> {
        b.src_stage_mask(S2::HOST)
            .src_access_mask(A2::HOST_WRITE)
            .dst_stage_mask(S2::TRANSFER)
            .dst_access_mask(A2::TRANSFER_READ)
    }
    let image = |old: L, new: L| {
        host(
            tuff::ImageMemoryBarrier2::new(&o.color)
                .old_layout(old)
                .new_layout(new)
                .src_queue_family_index(IGNORED)
                .dst_queue_family_index(IGNORED)
                .subresource_range(range(COLOR)),
        )
    };
    let release = [image(L::GENERAL, L::GENERAL)
        .src_queue_family_index(s.family)
        .dst_queue_family_index(vk::QUEUE_FAMILY_EXTERNAL)];
    let from_transfer = [image(L::TRANSFER_DST_OPTIMAL, L::GENERAL)];
    let buffer = [tuff::BufferMemoryBarrier2::new(&o.buffer)
        .src_stage_mask(S2::HOST)
        .src_access_mask(A2::HOST_WRITE)
        .dst_stage_mask(S2::TRANSFER)
        .dst_access_mask(A2::TRANSFER_READ)
        .src_queue_family_index(s.family)
        .dst_queue_family_index(vk::QUEUE_FAMILY_EXTERNAL)
        .offset(0)
        .size(vk::WHOLE_SIZE)];
    let mut wrong = Vec::new();
    for (what, info, rule) in [
        (
            "a buffer released by a host barrier",
            tuff::DependencyInfo::new().buffer_memory_barriers(&buffer),
            "VUID-VkBufferMemoryBarrier2-srcStageMask-03851",
        ),
        (
            "an image released by a host barrier",
            tuff::DependencyInfo::new().image_memory_barriers(&release),
            "VUID-VkImageMemoryBarrier2-srcStageMask-03854",
        ),
        (
            "an image moved from TRANSFER_DST_OPTIMAL after host writes",
            tuff::DependencyInfo::new().image_memory_barriers(&from_transfer),
            "VUID-VkImageMemoryBarrier2-srcStageMask-03855",
        ),
    ] {
        // The 1.3.239 layer does not check these rules: tuff's error alone proves
        // them.
        wrong.extend(try_dependency(&s, what, &info, rule, Layer::Silent));
    }
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
    // From a layout the host writes, on one queue family: recorded.
    let fine = [image(L::GENERAL, L::TRANSFER_SRC_OPTIMAL)];
    let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let mut rec = cb
        .begin(&tuff::CommandBufferBeginInfo::new())
        .expect("begin");
    rec.pipeline_barrier2(&tuff::DependencyInfo::new().image_memory_barriers(&fine))
        .expect("a host barrier from GENERAL");
    rec.end().expect("end");
    assert_silent(&s.messages);
}

/// The second version's event commands read their dependency infos' barriers as a
/// pipeline barrier does: a barrier to `UNDEFINED` is refused by `set_event2` and
/// `wait_events2` (whose `unsafe` is for their event rules), as the layer says.
#[test]
fn event_commands_check_their_barriers_as_pipeline_barriers_do() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let o = objects(&s);
    let event = s
        .device
        .create_event(&tuff::EventCreateInfo::new())
        .expect("event");
    let to_none = [tuff::ImageMemoryBarrier2::new(&o.color)
        .src_stage_mask(S2::TRANSFER)
        .dst_stage_mask(S2::TRANSFER)
        .old_layout(L::GENERAL)
        .new_layout(L::UNDEFINED)
        .src_queue_family_index(IGNORED)
        .dst_queue_family_index(IGNORED)
        .subresource_range(range(COLOR))];
    let infos = [tuff::DependencyInfo::new().image_memory_barriers(&to_none)];
    let rule = "VUID-VkImageMemoryBarrier2-newLayout-01198";
    let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let mut rec = cb
        .begin(&tuff::CommandBufferBeginInfo::new())
        .expect("begin");
    assert_eq!(vuid(rec.set_event2(&event, &infos[0])), rule);
    assert_eq!(vuid(rec.wait_events2(&event, &infos)), rule);
    for command in ["set_event2", "wait_events2"] {
        s.messages.take();
        s.messages.abort_on_error(true);
        // SAFETY: as above; the layer skips the call.
        unsafe {
            if command == "set_event2" {
                let _ = rec.set_event2_unchecked(&event, &infos[0]);
            } else {
                let _ = rec.wait_events2_unchecked(&event, &infos);
            }
        }
        s.messages.abort_on_error(false);
        let said = s.messages.take();
        assert!(
            said.iter().any(|m| m.contains(rule)),
            "{command}: the layer did not name {rule}: {said:?}"
        );
    }
    rec.end().expect("end");
    assert_silent(&s.messages);
}
