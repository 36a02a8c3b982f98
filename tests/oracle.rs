//! The oracle: every explicit rule that the generator's recognisers read, on a
//! struct this file has a fixture for, is broken once, by the change
//! `generated/oracle_cases.rs` derives from the rule's check.
//!
//! Each case runs twice. Through the safe method, tuff must refuse the call with the
//! rule's VUID. Through the `_unchecked` twin, under the validation layer with a
//! messenger that makes the layer skip an erroring call, the layer must name the same
//! VUID and nothing else, or say nothing at all: the rule is then "proven by the error
//! alone", as for rules the layer does not check. Any other outcome fails the test.
//! The generator reports exactly these rules as dynamically settled.
//!
//! SAFETY of the `unsafe` blocks around checked methods: such a method is `unsafe`
//! because it leaves rules to its caller (its `# Safety` section lists them). The
//! calls here keep every rule so listed and break, on purpose, only rules the method
//! checks; that one argument covers every such block in this file.

#[path = "common/pipelines.rs"]
mod pipelines;
#[path = "common/tuff_setup.rs"]
mod tuff_setup;
#[path = "common/vulkan.rs"]
mod vulkan;

use tuff::vk;
use tuff_setup::{setup, setup_with_extension_feature_structs, Setup};

type Limits = vk::PhysicalDeviceLimits;

/// What one run of a case saw: the safe method's result and what the layer said
/// about the unchecked call.
struct Outcome {
    safe: tuff::Result<()>,
    layer: Vec<String>,
}

/// How a fixture makes a buffer a rule names: a case may take a usage bit away,
/// leave it without memory, or read its size.
#[derive(Clone, Copy)]
struct BufferSpec {
    usage: vk::BufferUsageFlags,
    size: vk::DeviceSize,
    bind: bool,
}

/// How a fixture makes an image a rule names.
#[derive(Clone, Copy)]
struct ImageSpec {
    image_type: vk::ImageType,
    format: vk::Format,
    extent: vk::Extent3D,
    usage: vk::ImageUsageFlags,
    samples: vk::SampleCountFlags,
    mip_levels: u32,
    array_layers: u32,
    bind: bool,
}

impl ImageSpec {
    /// An image of another type: a 3D image is a cube of four texels a side, so
    /// that a region can be deeper than one texel.
    fn set_type(&mut self, image_type: vk::ImageType) {
        self.image_type = image_type;
        if image_type == vk::ImageType::TYPE_3D {
            self.extent.depth = 4;
        }
    }
}

/// The objects a fixture makes, by the name its struct or command gives the handle,
/// and the one element of each array of regions it passes, by the element's type
/// (a case about each element changes the element here).
#[derive(Clone, Copy)]
struct Objects {
    buffer: BufferSpec,
    count_buffer: BufferSpec,
    src_buffer: BufferSpec,
    dst_buffer: BufferSpec,
    image: ImageSpec,
    src_image: ImageSpec,
    dst_image: ImageSpec,
    buffer_copy2: vk::BufferCopy2<'static>,
    image_copy: vk::ImageCopy,
    image_copy2: vk::ImageCopy2<'static>,
    buffer_image_copy: vk::BufferImageCopy,
    buffer_image_copy2: vk::BufferImageCopy2<'static>,
    image_blit: vk::ImageBlit,
    image_blit2: vk::ImageBlit2<'static>,
    image_resolve: vk::ImageResolve,
    image_resolve2: vk::ImageResolve2<'static>,
    image_subresource_range: vk::ImageSubresourceRange,
    attachment_reference_color_attachments: vk::AttachmentReference,
    attachment_reference2_color_attachments: vk::AttachmentReference2<'static>,
    clear_rect: vk::ClearRect,
}

impl Default for Objects {
    fn default() -> Self {
        let buffer = BufferSpec {
            usage: vk::BufferUsageFlags::TRANSFER_SRC
                | vk::BufferUsageFlags::TRANSFER_DST
                | vk::BufferUsageFlags::INDIRECT_BUFFER
                | vk::BufferUsageFlags::UNIFORM_TEXEL_BUFFER,
            size: 64,
            bind: true,
        };
        let image = ImageSpec {
            image_type: vk::ImageType::TYPE_2D,
            format: vk::Format::R8G8B8A8_UNORM,
            extent: EXTENT,
            usage: vk::ImageUsageFlags::TRANSFER_SRC
                | vk::ImageUsageFlags::TRANSFER_DST
                | vk::ImageUsageFlags::SAMPLED,
            samples: vk::SampleCountFlags::TYPE_1,
            mip_levels: 1,
            array_layers: 1,
            bind: true,
        };
        let corner = vk::Offset3D { x: 4, y: 4, z: 1 };
        Objects {
            buffer,
            count_buffer: buffer,
            src_buffer: buffer,
            dst_buffer: buffer,
            image,
            src_image: image,
            dst_image: image,
            buffer_copy2: vk::BufferCopy2::default().size(16),
            image_copy: vk::ImageCopy {
                src_subresource: LAYER,
                dst_subresource: LAYER,
                extent: EXTENT,
                ..Default::default()
            },
            image_copy2: vk::ImageCopy2::default()
                .src_subresource(LAYER)
                .dst_subresource(LAYER)
                .extent(EXTENT),
            buffer_image_copy: vk::BufferImageCopy {
                image_subresource: LAYER,
                image_extent: EXTENT,
                ..Default::default()
            },
            buffer_image_copy2: vk::BufferImageCopy2::default()
                .image_subresource(LAYER)
                .image_extent(EXTENT),
            image_blit: vk::ImageBlit {
                src_subresource: LAYER,
                src_offsets: [vk::Offset3D::default(), corner],
                dst_subresource: LAYER,
                dst_offsets: [vk::Offset3D::default(), corner],
            },
            image_blit2: vk::ImageBlit2::default()
                .src_subresource(LAYER)
                .src_offsets([vk::Offset3D::default(), corner])
                .dst_subresource(LAYER)
                .dst_offsets([vk::Offset3D::default(), corner]),
            image_resolve: vk::ImageResolve {
                src_subresource: LAYER,
                dst_subresource: LAYER,
                extent: EXTENT,
                ..Default::default()
            },
            image_resolve2: vk::ImageResolve2::default()
                .src_subresource(LAYER)
                .dst_subresource(LAYER)
                .extent(EXTENT),
            image_subresource_range: WHOLE,
            attachment_reference_color_attachments: vk::AttachmentReference {
                attachment: 0,
                layout: vk::ImageLayout::COLOR_ATTACHMENT_OPTIMAL,
            },
            attachment_reference2_color_attachments: vk::AttachmentReference2::default()
                .attachment(0)
                .layout(vk::ImageLayout::COLOR_ATTACHMENT_OPTIMAL),
            clear_rect: vk::ClearRect {
                rect: vk::Rect2D {
                    offset: vk::Offset2D::default(),
                    extent: vk::Extent2D {
                        width: 4,
                        height: 4,
                    },
                },
                base_array_layer: 0,
                layer_count: 1,
            },
        }
    }
}

/// A buffer as `spec` says, with host-visible memory bound unless it says not.
fn make_buffer(s: &Setup, spec: &BufferSpec) -> (tuff::Buffer, Option<tuff::DeviceMemory>) {
    if spec.bind {
        let (b, m) = pipelines::host_buffer(s, spec.size, spec.usage);
        (b, Some(m))
    } else {
        let info = tuff::BufferCreateInfo::new()
            .size(spec.size)
            .usage(spec.usage);
        (s.device.create_buffer(&info).expect("buffer"), None)
    }
}

/// An image as `spec` says, with device memory bound unless it says not.
fn make_image(s: &Setup, spec: &ImageSpec) -> (tuff::Image, Option<tuff::DeviceMemory>) {
    let d = &s.device;
    let image = d
        .create_image(
            &tuff::ImageCreateInfo::new()
                .image_type(spec.image_type)
                .format(spec.format)
                .extent(spec.extent)
                .mip_levels(spec.mip_levels)
                .array_layers(spec.array_layers)
                .samples(spec.samples)
                .usage(spec.usage),
        )
        .expect("image");
    if !spec.bind {
        return (image, None);
    }
    let memory = s.bind_image(&image);
    (image, Some(memory))
}

/// A case: the rule, the device it runs on (`""` the fixtures' device; `bare`, one
/// that enables no feature, for rules that apply with one of `setup`'s features
/// off; `full`, one that enables every feature the physical device has, for changes
/// that need one `setup` leaves off), and the run of its fixture with its change.
type Case = (
    &'static str,
    &'static str,
    Box<dyn Fn(&Setup, &Limits) -> Outcome>,
);

macro_rules! oracle_cases {
    ($($fixture:ident: $ty:ty { $($vuid:literal $(on $device:ident)? => |$v:ident, $l:ident, $o:ident| $body:block),* $(,)? }),* $(,)?) => {
        /// Each fixture unchanged, by name: a valid call.
        fn fixtures() -> Vec<Case> {
            vec![$(
                (
                    stringify!($fixture),
                    "",
                    Box::new(|s: &Setup, limits: &Limits| {
                        $fixture(s, limits, &|_: &mut $ty, _: &Limits, _: &mut Objects| {})
                    }),
                ),
            )*]
        }

        /// Each case: its rule, whether it runs on the bare device, and its run.
        fn cases() -> Vec<Case> {
            vec![$($(
                (
                    $vuid,
                    stringify!($($device)?),
                    Box::new(|s: &Setup, limits: &Limits| {
                        $fixture(s, limits, &|$v: &mut $ty, $l: &Limits, $o: &mut Objects| {
                            let _ = (&$v, &$l, &$o);
                            $body
                        })
                    }),
                ),
            )*)*]
        }
    };
}

include!("../generated/oracle_cases.rs");

/// Runs `unchecked` with the layer told to skip erroring calls, and returns what it
/// said.
fn under_layer(s: &Setup, unchecked: impl FnOnce()) -> Vec<String> {
    s.messages.take();
    s.messages.abort_on_error(true);
    unchecked();
    s.messages.abort_on_error(false);
    s.messages.take()
}

fn buffer_create_info(
    s: &Setup,
    limits: &Limits,
    change: &dyn Fn(&mut vk::BufferCreateInfo<'_>, &Limits, &mut Objects),
) -> Outcome {
    let mut info = tuff::BufferCreateInfo::new()
        .size(64)
        .usage(vk::BufferUsageFlags::TRANSFER_SRC);
    // SAFETY: the change sets plain values only (the generator never changes a
    // pointer or a count).
    change(
        unsafe { info.raw_values_mut() },
        limits,
        &mut Objects::default(),
    );
    let safe = s.device.create_buffer(&info).map(drop);
    // SAFETY: the layer skips the call if it finds the rule broken; where it does
    // not, the driver gets a value that breaks only a rule the layer does not check.
    let layer = under_layer(s, || {
        drop(unsafe { s.device.create_buffer_unchecked(&info) })
    });
    Outcome { safe, layer }
}

fn image_create_info(
    s: &Setup,
    limits: &Limits,
    change: &dyn Fn(&mut vk::ImageCreateInfo<'_>, &Limits, &mut Objects),
) -> Outcome {
    let mut info = tuff::ImageCreateInfo::new()
        .image_type(vk::ImageType::TYPE_2D)
        .format(vk::Format::R8G8B8A8_UNORM)
        .extent(vk::Extent3D {
            width: 4,
            height: 4,
            depth: 1,
        })
        .mip_levels(1)
        .array_layers(1)
        .samples(vk::SampleCountFlags::TYPE_1)
        .usage(vk::ImageUsageFlags::SAMPLED);
    // SAFETY: as in `buffer_create_info`.
    change(
        unsafe { info.raw_values_mut() },
        limits,
        &mut Objects::default(),
    );
    let safe = s.device.create_image(&info).map(drop);
    // SAFETY: as in `buffer_create_info`.
    let layer = under_layer(s, || {
        drop(unsafe { s.device.create_image_unchecked(&info) })
    });
    Outcome { safe, layer }
}

fn sampler_create_info(
    s: &Setup,
    limits: &Limits,
    change: &dyn Fn(&mut vk::SamplerCreateInfo<'_>, &Limits, &mut Objects),
) -> Outcome {
    let edge = vk::SamplerAddressMode::CLAMP_TO_EDGE;
    let mut info = tuff::SamplerCreateInfo::new()
        .address_mode_u(edge)
        .address_mode_v(edge)
        .address_mode_w(edge)
        .max_anisotropy(1.0);
    // SAFETY: as in `buffer_create_info`.
    change(
        unsafe { info.raw_values_mut() },
        limits,
        &mut Objects::default(),
    );
    let safe = s.device.create_sampler(&info).map(drop);
    // SAFETY: as in `buffer_create_info`.
    let layer = under_layer(s, || {
        drop(unsafe { s.device.create_sampler_unchecked(&info) })
    });
    Outcome { safe, layer }
}

/// Records `barrier` through the safe method (whose refusal `end` returns) and
/// through the unchecked one under the layer.
fn barrier(s: &Setup, info: &tuff::DependencyInfo<'_>) -> Outcome {
    let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let mut rec = cb
        .begin(&tuff::CommandBufferBeginInfo::new())
        .expect("begin");
    // A refused barrier is not recorded; one the implicit checks refuse poisons
    // the recording, whose end returns the error.
    let recorded = rec.pipeline_barrier2(info);
    let ended = rec.end();
    let safe = recorded.and(ended);
    let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let mut rec = cb
        .begin(&tuff::CommandBufferBeginInfo::new())
        .expect("begin");
    // SAFETY: as in `buffer_create_info`; the command buffer is never submitted.
    let layer = under_layer(s, || {
        let _ = unsafe { rec.pipeline_barrier2_unchecked(info) };
    });
    rec.end().expect("end");
    Outcome { safe, layer }
}

const ALL: vk::PipelineStageFlags2 = vk::PipelineStageFlags2::ALL_COMMANDS;

fn memory_barrier2(
    s: &Setup,
    limits: &Limits,
    change: &dyn Fn(&mut vk::MemoryBarrier2<'_>, &Limits, &mut Objects),
) -> Outcome {
    let mut b = tuff::MemoryBarrier2::new()
        .src_stage_mask(ALL)
        .dst_stage_mask(ALL);
    // SAFETY: as in `buffer_create_info`.
    change(
        unsafe { b.raw_values_mut() },
        limits,
        &mut Objects::default(),
    );
    let barriers = [b];
    barrier(s, &tuff::DependencyInfo::new().memory_barriers(&barriers))
}

fn buffer_memory_barrier2(
    s: &Setup,
    limits: &Limits,
    change: &dyn Fn(&mut vk::BufferMemoryBarrier2<'_>, &Limits, &mut Objects),
) -> Outcome {
    // The change runs once for the objects it asks for, then on the barrier.
    let mut o = Objects::default();
    change(&mut Default::default(), limits, &mut o);
    let (buffer, _memory) = make_buffer(s, &o.buffer);
    let mut b = tuff::BufferMemoryBarrier2::new(&buffer)
        .src_stage_mask(ALL)
        .dst_stage_mask(ALL)
        .src_queue_family_index(vk::QUEUE_FAMILY_IGNORED)
        .dst_queue_family_index(vk::QUEUE_FAMILY_IGNORED)
        .size(vk::WHOLE_SIZE);
    // SAFETY: as in `buffer_create_info`.
    change(unsafe { b.raw_values_mut() }, limits, &mut o.clone());
    let barriers = [b];
    barrier(
        s,
        &tuff::DependencyInfo::new().buffer_memory_barriers(&barriers),
    )
}

fn image_memory_barrier2(
    s: &Setup,
    limits: &Limits,
    change: &dyn Fn(&mut vk::ImageMemoryBarrier2<'_>, &Limits, &mut Objects),
) -> Outcome {
    // As in `buffer_memory_barrier2`.
    let mut o = Objects::default();
    change(&mut Default::default(), limits, &mut o);
    let (image, _memory) = make_image(s, &o.image);
    let mut b = tuff::ImageMemoryBarrier2::new(&image)
        .src_stage_mask(ALL)
        .dst_stage_mask(ALL)
        .old_layout(vk::ImageLayout::UNDEFINED)
        .new_layout(vk::ImageLayout::GENERAL)
        .src_queue_family_index(vk::QUEUE_FAMILY_IGNORED)
        .dst_queue_family_index(vk::QUEUE_FAMILY_IGNORED)
        .subresource_range(WHOLE);
    // SAFETY: as in `buffer_create_info`.
    change(unsafe { b.raw_values_mut() }, limits, &mut o.clone());
    let barriers = [b];
    barrier(
        s,
        &tuff::DependencyInfo::new().image_memory_barriers(&barriers),
    )
}

/// Creates with the safe method and, under the layer, with its `_unchecked` twin.
macro_rules! create {
    ($s:expr, $method:ident, $unchecked:ident, $($arg:expr),+) => {{
        // Some of the methods are safe, others `unsafe` (see the module docs).
        #[allow(unused_unsafe)]
        let safe = unsafe { $s.device.$method($($arg),+) }.map(drop);
        // SAFETY: as in `buffer_create_info`.
        let layer = under_layer($s, || {
            let _ = unsafe { $s.device.$unchecked($($arg),+) };
        });
        Outcome { safe, layer }
    }};
}

fn debug_utils_object_name_info_ext(
    s: &Setup,
    limits: &Limits,
    change: &dyn Fn(&mut vk::DebugUtilsObjectNameInfoEXT<'_>, &Limits, &mut Objects),
) -> Outcome {
    use tuff::{vk::Handle as _, Handle as _};
    // A buffer of the device gets a name (with multi_thread, naming the device itself
    // is refused: another thread could use it meanwhile).
    let buffer = s
        .device
        .create_buffer(
            &tuff::BufferCreateInfo::new()
                .size(16)
                .usage(vk::BufferUsageFlags::TRANSFER_SRC),
        )
        .expect("buffer");
    let mut info = tuff::DebugUtilsObjectNameInfoEXT::new()
        .object_type(vk::ObjectType::BUFFER)
        .object_handle(buffer.raw().as_raw())
        .object_name(Some(c"oracle"));
    // SAFETY: as in `buffer_create_info`.
    change(
        unsafe { info.raw_values_mut() },
        limits,
        &mut Objects::default(),
    );
    create!(
        s,
        set_debug_utils_object_name_ext,
        set_debug_utils_object_name_ext_unchecked,
        &info
    )
}

fn image_view_create_info(
    s: &Setup,
    limits: &Limits,
    change: &dyn Fn(&mut vk::ImageViewCreateInfo<'_>, &Limits, &mut Objects),
) -> Outcome {
    // As in `buffer_memory_barrier2`.
    let mut o = Objects::default();
    change(&mut Default::default(), limits, &mut o);
    let (image, _memory) = make_image(s, &o.image);
    let mut info = tuff::ImageViewCreateInfo::new(&image)
        .view_type(vk::ImageViewType::TYPE_2D)
        .format(vk::Format::R8G8B8A8_UNORM)
        .subresource_range(WHOLE);
    // SAFETY: as in `buffer_create_info`.
    change(unsafe { info.raw_values_mut() }, limits, &mut o.clone());
    create!(s, create_image_view, create_image_view_unchecked, &info)
}

fn framebuffer_create_info(
    s: &Setup,
    limits: &Limits,
    change: &dyn Fn(&mut vk::FramebufferCreateInfo<'_>, &Limits, &mut Objects),
) -> Outcome {
    let target = s.color_target(4, vk::ImageUsageFlags::empty());
    let mut info = tuff::FramebufferCreateInfo::new(&target.render_pass)
        .attachments(&target.view)
        .width(4)
        .height(4)
        .layers(1);
    // SAFETY: as in `buffer_create_info`.
    change(
        unsafe { info.raw_values_mut() },
        limits,
        &mut Objects::default(),
    );
    create!(s, create_framebuffer, create_framebuffer_unchecked, &info)
}

fn descriptor_pool_create_info(
    s: &Setup,
    limits: &Limits,
    change: &dyn Fn(&mut vk::DescriptorPoolCreateInfo<'_>, &Limits, &mut Objects),
) -> Outcome {
    let sizes = [vk::DescriptorPoolSize {
        ty: vk::DescriptorType::UNIFORM_BUFFER,
        descriptor_count: 1,
    }];
    let mut info = tuff::DescriptorPoolCreateInfo::new()
        .max_sets(1)
        .pool_sizes(&sizes);
    // SAFETY: as in `buffer_create_info`.
    change(
        unsafe { info.raw_values_mut() },
        limits,
        &mut Objects::default(),
    );
    create!(
        s,
        create_descriptor_pool,
        create_descriptor_pool_unchecked,
        &info
    )
}

fn descriptor_pool_size(
    s: &Setup,
    limits: &Limits,
    change: &dyn Fn(&mut vk::DescriptorPoolSize, &Limits, &mut Objects),
) -> Outcome {
    let mut size = vk::DescriptorPoolSize {
        ty: vk::DescriptorType::UNIFORM_BUFFER,
        descriptor_count: 1,
    };
    change(&mut size, limits, &mut Objects::default());
    let sizes = [size];
    let info = tuff::DescriptorPoolCreateInfo::new()
        .max_sets(1)
        .pool_sizes(&sizes);
    create!(
        s,
        create_descriptor_pool,
        create_descriptor_pool_unchecked,
        &info
    )
}

fn push_constant_range(
    s: &Setup,
    limits: &Limits,
    change: &dyn Fn(&mut vk::PushConstantRange, &Limits, &mut Objects),
) -> Outcome {
    let mut range = vk::PushConstantRange {
        stage_flags: vk::ShaderStageFlags::VERTEX,
        offset: 0,
        size: 16,
    };
    change(&mut range, limits, &mut Objects::default());
    let ranges = [range];
    let info = tuff::PipelineLayoutCreateInfo::new().push_constant_ranges(&ranges);
    create!(
        s,
        create_pipeline_layout,
        create_pipeline_layout_unchecked,
        &info
    )
}

fn query_pool_create_info(
    s: &Setup,
    limits: &Limits,
    change: &dyn Fn(&mut vk::QueryPoolCreateInfo<'_>, &Limits, &mut Objects),
) -> Outcome {
    let mut info = tuff::QueryPoolCreateInfo::new()
        .query_type(vk::QueryType::OCCLUSION)
        .query_count(1);
    // SAFETY: as in `buffer_create_info`.
    change(
        unsafe { info.raw_values_mut() },
        limits,
        &mut Objects::default(),
    );
    create!(s, create_query_pool, create_query_pool_unchecked, &info)
}

/// The parts of a one-subpass render pass with one color attachment and one
/// dependency, for a change to any of them.
struct RenderPass1<'a> {
    attachment: vk::AttachmentDescription,
    subpass: tuff::SubpassDescription<'a>,
    dependency: vk::SubpassDependency,
}

const COLOR_OUT: vk::PipelineStageFlags = vk::PipelineStageFlags::COLOR_ATTACHMENT_OUTPUT;

fn render_pass(s: &Setup, o: &Objects, edit: impl FnOnce(&mut RenderPass1<'_>)) -> Outcome {
    let color = [o.attachment_reference_color_attachments];
    let mut parts = RenderPass1 {
        attachment: vk::AttachmentDescription {
            format: vk::Format::R8G8B8A8_UNORM,
            samples: vk::SampleCountFlags::TYPE_1,
            load_op: vk::AttachmentLoadOp::CLEAR,
            store_op: vk::AttachmentStoreOp::STORE,
            stencil_load_op: vk::AttachmentLoadOp::DONT_CARE,
            stencil_store_op: vk::AttachmentStoreOp::DONT_CARE,
            initial_layout: vk::ImageLayout::UNDEFINED,
            final_layout: vk::ImageLayout::TRANSFER_SRC_OPTIMAL,
            ..Default::default()
        },
        subpass: tuff::SubpassDescription::new()
            .pipeline_bind_point(vk::PipelineBindPoint::GRAPHICS)
            .color_attachments(&color),
        dependency: vk::SubpassDependency {
            src_subpass: vk::SUBPASS_EXTERNAL,
            dst_subpass: 0,
            src_stage_mask: COLOR_OUT,
            dst_stage_mask: COLOR_OUT,
            src_access_mask: vk::AccessFlags::empty(),
            dst_access_mask: vk::AccessFlags::COLOR_ATTACHMENT_WRITE,
            dependency_flags: vk::DependencyFlags::empty(),
        },
    };
    edit(&mut parts);
    let attachments = [parts.attachment];
    let subpasses = [parts.subpass];
    let dependencies = [parts.dependency];
    let info = tuff::RenderPassCreateInfo::new()
        .attachments(&attachments)
        .subpasses(&subpasses)
        .dependencies(&dependencies);
    create!(s, create_render_pass, create_render_pass_unchecked, &info)
}

/// A fixture for one part of a render pass: `$build` makes the render pass from
/// the parts after `$part` (a plain struct, or a safe one with `raw`) is changed.
/// The change runs once on a spare part for the elements it sets in the objects
/// (the subpass's color reference), then on the part.
macro_rules! render_pass_fixture {
    ($name:ident, $ty:ty, $build:ident, |$p:ident| $part:expr) => {
        fn $name(
            s: &Setup,
            limits: &Limits,
            change: &dyn Fn(&mut $ty, &Limits, &mut Objects),
        ) -> Outcome {
            let mut o = Objects::default();
            change(&mut Default::default(), limits, &mut o);
            $build(s, &o, |$p| change($part, limits, &mut o.clone()))
        }
    };
    ($name:ident, $ty:ty, $build:ident, raw |$p:ident| $part:expr) => {
        fn $name(
            s: &Setup,
            limits: &Limits,
            change: &dyn Fn(&mut $ty, &Limits, &mut Objects),
        ) -> Outcome {
            let mut o = Objects::default();
            change(&mut Default::default(), limits, &mut o);
            // SAFETY: as in `buffer_create_info`.
            $build(s, &o, |$p| {
                change(unsafe { $part.raw_values_mut() }, limits, &mut o.clone())
            })
        }
    };
}

render_pass_fixture!(
    subpass_dependency,
    vk::SubpassDependency,
    render_pass,
    |p| &mut p.dependency
);
render_pass_fixture!(
    attachment_description,
    vk::AttachmentDescription,
    render_pass,
    |p| &mut p.attachment
);
render_pass_fixture!(
    subpass_description,
    vk::SubpassDescription<'_>,
    render_pass,
    raw | p | p.subpass
);
render_pass_fixture!(
    subpass_dependency2,
    vk::SubpassDependency2<'_>,
    render_pass2,
    raw | p | p.dependency
);
render_pass_fixture!(
    attachment_description2,
    vk::AttachmentDescription2<'_>,
    render_pass2,
    raw | p | p.attachment
);
render_pass_fixture!(
    subpass_description2,
    vk::SubpassDescription2<'_>,
    render_pass2,
    raw | p | p.subpass
);

/// [`RenderPass1`] through `vkCreateRenderPass2`.
struct RenderPass2<'a> {
    attachment: tuff::AttachmentDescription2<'a>,
    subpass: tuff::SubpassDescription2<'a>,
    dependency: tuff::SubpassDependency2<'a>,
}

fn render_pass2(s: &Setup, o: &Objects, edit: impl FnOnce(&mut RenderPass2<'_>)) -> Outcome {
    let r = o.attachment_reference2_color_attachments;
    let color = [tuff::AttachmentReference2::new()
        .attachment(r.attachment)
        .layout(r.layout)
        .aspect_mask(r.aspect_mask)];
    let mut parts = RenderPass2 {
        attachment: tuff::AttachmentDescription2::new()
            .format(vk::Format::R8G8B8A8_UNORM)
            .samples(vk::SampleCountFlags::TYPE_1)
            .load_op(vk::AttachmentLoadOp::CLEAR)
            .store_op(vk::AttachmentStoreOp::STORE)
            .stencil_load_op(vk::AttachmentLoadOp::DONT_CARE)
            .stencil_store_op(vk::AttachmentStoreOp::DONT_CARE)
            .initial_layout(vk::ImageLayout::UNDEFINED)
            .final_layout(vk::ImageLayout::TRANSFER_SRC_OPTIMAL),
        subpass: tuff::SubpassDescription2::new()
            .pipeline_bind_point(vk::PipelineBindPoint::GRAPHICS)
            .color_attachments(&color),
        dependency: tuff::SubpassDependency2::new()
            .src_subpass(vk::SUBPASS_EXTERNAL)
            .dst_subpass(0)
            .src_stage_mask(COLOR_OUT)
            .dst_stage_mask(COLOR_OUT)
            .dst_access_mask(vk::AccessFlags::COLOR_ATTACHMENT_WRITE),
    };
    edit(&mut parts);
    let attachments = [parts.attachment];
    let subpasses = [parts.subpass];
    let dependencies = [parts.dependency];
    let info = tuff::RenderPassCreateInfo2::new()
        .attachments(&attachments)
        .subpasses(&subpasses)
        .dependencies(&dependencies);
    create!(s, create_render_pass2, create_render_pass2_unchecked, &info)
}

/// The fixed-function parts of the test graphics pipeline, for a change to any of
/// them. The pipeline reads no vertex input; a binding is there only for its own
/// cases (the vertex shader consumes no attribute, so the layer would warn of one).
struct Graphics<'a> {
    assembly: tuff::PipelineInputAssemblyStateCreateInfo<'a>,
    raster: tuff::PipelineRasterizationStateCreateInfo<'a>,
    multisample: tuff::PipelineMultisampleStateCreateInfo<'a>,
    blend_attachment: vk::PipelineColorBlendAttachmentState,
    blend: tuff::PipelineColorBlendStateCreateInfo<'a>,
    binding: Option<vk::VertexInputBindingDescription>,
    depth_stencil: Option<tuff::PipelineDepthStencilStateCreateInfo<'a>>,
    stages: [tuff::PipelineShaderStageCreateInfo<'a>; 2],
}

fn graphics(s: &Setup, edit: impl FnOnce(&mut Graphics<'_>)) -> Outcome {
    graphics_with(s, edit, &|_| {})
}

/// [`graphics`], with a change to the create info itself after its parts are set.
fn graphics_with(
    s: &Setup,
    edit: impl FnOnce(&mut Graphics<'_>),
    edit_info: &dyn Fn(&mut vk::GraphicsPipelineCreateInfo<'_>),
) -> Outcome {
    let d = &s.device;
    let target = s.color_target(4, vk::ImageUsageFlags::empty());
    let vert = tuff_setup::shader(s, include_bytes!("../shaders/spv/test.vert.spv"));
    let frag = tuff_setup::shader(s, include_bytes!("../shaders/spv/test.frag.spv"));
    // The test fragment shader reads 16 bytes of push constants.
    let push = [vk::PushConstantRange {
        stage_flags: vk::ShaderStageFlags::FRAGMENT,
        offset: 0,
        size: 16,
    }];
    let layout = d
        .create_pipeline_layout(&tuff::PipelineLayoutCreateInfo::new().push_constant_ranges(&push))
        .expect("layout");
    let mut parts = Graphics {
        stages: pipelines::test_stages(&vert, &frag),
        assembly: tuff::PipelineInputAssemblyStateCreateInfo::new()
            .topology(vk::PrimitiveTopology::TRIANGLE_LIST),
        raster: tuff::PipelineRasterizationStateCreateInfo::new()
            .polygon_mode(vk::PolygonMode::FILL)
            .cull_mode(vk::CullModeFlags::NONE)
            .line_width(1.0),
        multisample: tuff::PipelineMultisampleStateCreateInfo::new()
            .rasterization_samples(vk::SampleCountFlags::TYPE_1),
        blend_attachment: vk::PipelineColorBlendAttachmentState {
            color_write_mask: vk::ColorComponentFlags::RGBA,
            ..Default::default()
        },
        blend: tuff::PipelineColorBlendStateCreateInfo::new(),
        binding: None,
        depth_stencil: None,
    };
    edit(&mut parts);
    let blend_attachments = [parts.blend_attachment];
    let blend = parts.blend.attachments(&blend_attachments);
    let bindings: Vec<_> = parts.binding.into_iter().collect();
    let vertex_input =
        tuff::PipelineVertexInputStateCreateInfo::new().vertex_binding_descriptions(&bindings);
    let viewport = tuff::PipelineViewportStateCreateInfo::new()
        .viewport_count(1)
        .scissor_count(1);
    let dynamic_states = [vk::DynamicState::VIEWPORT, vk::DynamicState::SCISSOR];
    let dynamic = tuff::PipelineDynamicStateCreateInfo::new().dynamic_states(&dynamic_states);
    let mut info = tuff::GraphicsPipelineCreateInfo::new()
        .stages(&parts.stages)
        .vertex_input_state(Some(&vertex_input))
        .input_assembly_state(Some(&parts.assembly))
        .viewport_state(Some(&viewport))
        .rasterization_state(Some(&parts.raster))
        .multisample_state(Some(&parts.multisample))
        .color_blend_state(Some(&blend))
        .dynamic_state(Some(&dynamic))
        .layout(Some(&layout))
        .render_pass(Some(&target.render_pass))
        .subpass(0);
    if let Some(depth_stencil) = &parts.depth_stencil {
        info = info.depth_stencil_state(Some(depth_stencil));
    }
    // SAFETY: as in `buffer_create_info`.
    edit_info(unsafe { info.raw_values_mut() });
    let infos = [info];
    create!(
        s,
        create_graphics_pipelines,
        create_graphics_pipelines_unchecked,
        None,
        &infos
    )
}

macro_rules! graphics_fixture {
    ($name:ident, $ty:ty, |$p:ident| $part:expr) => {
        fn $name(
            s: &Setup,
            limits: &Limits,
            change: &dyn Fn(&mut $ty, &Limits, &mut Objects),
        ) -> Outcome {
            graphics(s, |$p| change($part, limits, &mut Objects::default()))
        }
    };
    ($name:ident, $ty:ty, raw |$p:ident| $part:expr) => {
        fn $name(
            s: &Setup,
            limits: &Limits,
            change: &dyn Fn(&mut $ty, &Limits, &mut Objects),
        ) -> Outcome {
            // SAFETY: as in `buffer_create_info`.
            graphics(s, |$p| {
                change(
                    unsafe { $part.raw_values_mut() },
                    limits,
                    &mut Objects::default(),
                )
            })
        }
    };
}

graphics_fixture!(
    pipeline_color_blend_attachment_state,
    vk::PipelineColorBlendAttachmentState,
    |p| &mut p.blend_attachment
);
graphics_fixture!(
    pipeline_color_blend_state_create_info,
    vk::PipelineColorBlendStateCreateInfo<'_>,
    raw | p | p.blend
);
graphics_fixture!(
    pipeline_rasterization_state_create_info,
    vk::PipelineRasterizationStateCreateInfo<'_>,
    raw | p | p.raster
);
graphics_fixture!(
    pipeline_multisample_state_create_info,
    vk::PipelineMultisampleStateCreateInfo<'_>,
    raw | p | p.multisample
);

const BINDING: vk::VertexInputBindingDescription = vk::VertexInputBindingDescription {
    binding: 0,
    stride: 16,
    input_rate: vk::VertexInputRate::VERTEX,
};

graphics_fixture!(
    vertex_input_binding_description,
    vk::VertexInputBindingDescription,
    |p| p.binding.insert(BINDING)
);

graphics_fixture!(
    pipeline_depth_stencil_state_create_info,
    vk::PipelineDepthStencilStateCreateInfo<'_>,
    raw | p
        | p.depth_stencil
            .insert(tuff::PipelineDepthStencilStateCreateInfo::new())
);

fn graphics_pipeline_create_info(
    s: &Setup,
    limits: &Limits,
    change: &dyn Fn(&mut vk::GraphicsPipelineCreateInfo<'_>, &Limits, &mut Objects),
) -> Outcome {
    graphics_with(s, |_| {}, &|info| {
        change(info, limits, &mut Objects::default())
    })
}

#[path = "oracle/fixtures.rs"]
mod fixtures;
use fixtures::*;

/// The parameters of a command that its rules name, as its safe method names them.
mod args {
    pub use super::fixtures::args::*;
    use tuff::vk;

    pub struct CmdSetEvent {
        pub stage_mask: vk::PipelineStageFlags,
    }
    pub type CmdResetEvent = CmdSetEvent;
    pub struct CmdResetEvent2 {
        pub stage_mask: vk::PipelineStageFlags2,
    }
    impl From<vk::PipelineStageFlags> for CmdSetEvent {
        fn from(stage_mask: vk::PipelineStageFlags) -> Self {
            Self { stage_mask }
        }
    }
    impl From<vk::PipelineStageFlags2> for CmdResetEvent2 {
        fn from(stage_mask: vk::PipelineStageFlags2) -> Self {
            Self { stage_mask }
        }
    }
    pub struct CmdWaitEvents {
        pub src_stage_mask: vk::PipelineStageFlags,
        pub dst_stage_mask: vk::PipelineStageFlags,
    }
    pub struct CmdPipelineBarrier {
        pub src_stage_mask: vk::PipelineStageFlags,
        pub dst_stage_mask: vk::PipelineStageFlags,
        pub dependency_flags: vk::DependencyFlags,
    }
    pub struct CmdWriteTimestamp {
        pub pipeline_stage: vk::PipelineStageFlags,
    }
    pub struct CmdClearColorImage {
        pub image_layout: vk::ImageLayout,
    }
    pub struct CmdCopyImage {
        pub src_image_layout: vk::ImageLayout,
        pub dst_image_layout: vk::ImageLayout,
    }
    pub struct CmdCopyBufferToImage {
        pub dst_image_layout: vk::ImageLayout,
    }
    pub struct CmdCopyImageToBuffer {
        pub src_image_layout: vk::ImageLayout,
    }
    pub type CmdBlitImage = CmdCopyImage;
    pub struct CmdDrawIndirect {
        pub offset: vk::DeviceSize,
        pub draw_count: u32,
    }
    pub type CmdDrawIndexedIndirect = CmdDrawIndirect;
    pub struct CmdDispatchIndirect {
        pub offset: vk::DeviceSize,
    }
    pub struct CmdDispatch {
        pub group_count_x: u32,
        pub group_count_y: u32,
        pub group_count_z: u32,
    }
    pub struct CmdDispatchBase {
        pub base_group_x: u32,
        pub base_group_y: u32,
        pub base_group_z: u32,
        pub group_count_x: u32,
        pub group_count_y: u32,
        pub group_count_z: u32,
    }
    pub struct CmdDrawIndirectCount {
        pub offset: vk::DeviceSize,
        pub count_buffer_offset: vk::DeviceSize,
    }
    pub type CmdDrawIndexedIndirectCount = CmdDrawIndirectCount;
    pub struct CmdPipelineBarrier2;
    pub struct CmdClearAttachments;
    pub struct CmdClearDepthStencilImage {
        pub image_layout: vk::ImageLayout,
    }
    pub struct ResetQueryPool;
    pub struct CmdBeginRendering;
    pub type CmdSetEvent2 = CmdPipelineBarrier2;
    pub type CmdWaitEvents2 = CmdPipelineBarrier2;
    pub struct CmdWriteTimestamp2 {
        pub stage: vk::PipelineStageFlags2,
    }
    pub struct CreatePrivateDataSlot;
    pub struct CmdSetLineWidth {
        pub line_width: f32,
    }
    pub struct CmdSetDepthBias {
        pub depth_bias_constant_factor: f32,
        pub depth_bias_clamp: f32,
        pub depth_bias_slope_factor: f32,
    }
    pub struct CmdSetDepthBounds {
        pub min_depth_bounds: f32,
        pub max_depth_bounds: f32,
    }
    pub struct CmdCopyQueryPoolResults {
        pub dst_offset: vk::DeviceSize,
        pub stride: vk::DeviceSize,
        pub flags: vk::QueryResultFlags,
    }
    pub type CmdResolveImage = CmdCopyImage;
}

/// Records the safe call into one command buffer (whose `end` returns its refusal)
/// and the unchecked call into another, under the layer.
fn record<R: Recorded, U>(
    s: &Setup,
    safe: impl FnOnce(&mut tuff::Recorder<'_, tuff::Outside>) -> R,
    unchecked: impl FnOnce(&mut tuff::Recorder<'_, tuff::Outside>) -> U,
) -> Outcome {
    let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let mut rec = cb
        .begin(&tuff::CommandBufferBeginInfo::new())
        .expect("begin");
    let called = safe(&mut rec).refusal();
    let safe = called.and(rec.end());
    let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let mut rec = cb
        .begin(&tuff::CommandBufferBeginInfo::new())
        .expect("begin");
    let layer = under_layer(s, || {
        let _ = unchecked(&mut rec);
    });
    rec.end().expect("end");
    Outcome { safe, layer }
}

/// What a recorded command returns: nothing, for one whose refusal the recorder
/// keeps for `end`, or its refusal.
trait Recorded {
    fn refusal(self) -> tuff::Result<()>;
}

impl Recorded for () {
    fn refusal(self) -> tuff::Result<()> {
        Ok(())
    }
}

impl Recorded for tuff::Result<()> {
    fn refusal(self) -> tuff::Result<()> {
        self
    }
}

fn event(s: &Setup) -> tuff::Event {
    s.device
        .create_event(&tuff::EventCreateInfo::new())
        .expect("event")
}

/// A fixture for a command on one event with a stage mask: set, reset, reset2.
/// `unsafe` before the name marks a method still `unsafe` (its caller keeps the
/// rules of the event's waits).
macro_rules! event_fixture {
    (unsafe $name:ident, $args:ty, $stage:expr, $method:ident, $unchecked:ident) => {
        event_fixture!(@ $name, $args, $stage, |r, e, m| r.$method(e, m), $unchecked);
    };
    ($name:ident, $args:ty, $stage:expr, $method:ident, $unchecked:ident) => {
        event_fixture!(@ $name, $args, $stage, |r, e, m| r.$method(e, m), $unchecked);
    };
    (@ $name:ident, $args:ty, $stage:expr, |$r:ident, $e:ident, $m:ident| $call:expr, $unchecked:ident) => {
        fn $name(
            s: &Setup,
            limits: &Limits,
            change: &dyn Fn(&mut $args, &Limits, &mut Objects),
        ) -> Outcome {
            let mut a = <$args>::from($stage);
            change(&mut a, limits, &mut Objects::default());
            let e = event(s);
            record(
                s,
                |$r| {
                    let ($e, $m) = (&e, a.stage_mask);
                    $call
                },
                // SAFETY: as in `buffer_create_info`; the command buffer is never
                // submitted.
                |r| unsafe { r.$unchecked(&e, a.stage_mask) },
            )
        }
    };
}

event_fixture!(
    cmd_set_event,
    args::CmdSetEvent,
    vk::PipelineStageFlags::TRANSFER,
    set_event,
    set_event_unchecked
);
event_fixture!(
    unsafe cmd_reset_event,
    args::CmdResetEvent,
    vk::PipelineStageFlags::TRANSFER,
    reset_event,
    reset_event_unchecked
);
event_fixture!(
    unsafe cmd_reset_event2,
    args::CmdResetEvent2,
    vk::PipelineStageFlags2::TRANSFER,
    reset_event2,
    reset_event2_unchecked
);

fn cmd_wait_events(
    s: &Setup,
    limits: &Limits,
    change: &dyn Fn(&mut args::CmdWaitEvents, &Limits, &mut Objects),
) -> Outcome {
    let mut a = args::CmdWaitEvents {
        src_stage_mask: vk::PipelineStageFlags::TRANSFER,
        dst_stage_mask: vk::PipelineStageFlags::TRANSFER,
    };
    change(&mut a, limits, &mut Objects::default());
    let e = event(s);
    let events = [&e];
    record(
        s,
        |r| {
            r.set_event(&e, vk::PipelineStageFlags::TRANSFER)
                .expect("set");
            r.wait_events(
                &tuff::HandleSlice::new(&events),
                a.src_stage_mask,
                a.dst_stage_mask,
                &[],
                &[],
                &[],
            )
        },
        |r| {
            r.set_event(&e, vk::PipelineStageFlags::TRANSFER)
                .expect("set");
            // SAFETY: as in `buffer_create_info`; the command buffer is never submitted.
            unsafe {
                r.wait_events_unchecked(
                    &tuff::HandleSlice::new(&events),
                    a.src_stage_mask,
                    a.dst_stage_mask,
                    &[],
                    &[],
                    &[],
                )
            }
        },
    )
}

fn cmd_pipeline_barrier(
    s: &Setup,
    limits: &Limits,
    change: &dyn Fn(&mut args::CmdPipelineBarrier, &Limits, &mut Objects),
) -> Outcome {
    let mut a = args::CmdPipelineBarrier {
        src_stage_mask: vk::PipelineStageFlags::TRANSFER,
        dst_stage_mask: vk::PipelineStageFlags::TRANSFER,
        dependency_flags: vk::DependencyFlags::empty(),
    };
    change(&mut a, limits, &mut Objects::default());
    record(
        s,
        |r| {
            r.pipeline_barrier(
                a.src_stage_mask,
                a.dst_stage_mask,
                a.dependency_flags,
                &[],
                &[],
                &[],
            )
        },
        // SAFETY: as in `buffer_create_info`; the command buffer is never submitted.
        |r| unsafe {
            r.pipeline_barrier_unchecked(
                a.src_stage_mask,
                a.dst_stage_mask,
                a.dependency_flags,
                &[],
                &[],
                &[],
            )
        },
    )
}

fn timestamps(s: &Setup) -> tuff::QueryPool {
    s.device
        .create_query_pool(
            &tuff::QueryPoolCreateInfo::new()
                .query_type(vk::QueryType::TIMESTAMP)
                .query_count(1),
        )
        .expect("query pool")
}

fn cmd_write_timestamp(
    s: &Setup,
    limits: &Limits,
    change: &dyn Fn(&mut args::CmdWriteTimestamp, &Limits, &mut Objects),
) -> Outcome {
    let mut a = args::CmdWriteTimestamp {
        pipeline_stage: vk::PipelineStageFlags::TRANSFER,
    };
    change(&mut a, limits, &mut Objects::default());
    let pool = timestamps(s);
    record(
        s,
        |r| {
            r.reset_query_pool(&pool, 0, 1).expect("reset");
            r.write_timestamp(a.pipeline_stage, &pool, 0)
        },
        |r| {
            r.reset_query_pool(&pool, 0, 1).expect("reset");
            // SAFETY: as in `buffer_create_info`; the command buffer is never submitted.
            unsafe { r.write_timestamp_unchecked(a.pipeline_stage, &pool, 0) }
        },
    )
}

const WHOLE: vk::ImageSubresourceRange = vk::ImageSubresourceRange {
    aspect_mask: vk::ImageAspectFlags::COLOR,
    base_mip_level: 0,
    level_count: 1,
    base_array_layer: 0,
    layer_count: 1,
};
const LAYER: vk::ImageSubresourceLayers = vk::ImageSubresourceLayers {
    aspect_mask: vk::ImageAspectFlags::COLOR,
    mip_level: 0,
    base_array_layer: 0,
    layer_count: 1,
};
const EXTENT: vk::Extent3D = vk::Extent3D {
    width: 4,
    height: 4,
    depth: 1,
};

fn cmd_clear_color_image(
    s: &Setup,
    limits: &Limits,
    change: &dyn Fn(&mut args::CmdClearColorImage, &Limits, &mut Objects),
) -> Outcome {
    let mut a = args::CmdClearColorImage {
        image_layout: vk::ImageLayout::TRANSFER_DST_OPTIMAL,
    };
    let mut o = Objects::default();
    change(&mut a, limits, &mut o);
    let (image, _memory) = make_image(s, &o.image);
    let color = vk::ClearColorValue::default();
    record(
        s,
        |r| r.clear_color_image(&image, a.image_layout, &color, &[o.image_subresource_range]),
        // SAFETY: as in `buffer_create_info`; the command buffer is never submitted.
        |r| unsafe {
            r.clear_color_image_unchecked(
                &image,
                a.image_layout,
                &color,
                &[o.image_subresource_range],
            )
        },
    )
}

fn cmd_copy_image(
    s: &Setup,
    limits: &Limits,
    change: &dyn Fn(&mut args::CmdCopyImage, &Limits, &mut Objects),
) -> Outcome {
    let mut a = args::CmdCopyImage {
        src_image_layout: vk::ImageLayout::TRANSFER_SRC_OPTIMAL,
        dst_image_layout: vk::ImageLayout::TRANSFER_DST_OPTIMAL,
    };
    let mut o = Objects::default();
    change(&mut a, limits, &mut o);
    let (src, _src_memory) = make_image(s, &o.src_image);
    let (dst, _dst_memory) = make_image(s, &o.dst_image);
    let region = [o.image_copy];
    record(
        s,
        |r| r.copy_image(&src, a.src_image_layout, &dst, a.dst_image_layout, &region),
        // SAFETY: as in `buffer_create_info`; the command buffer is never submitted.
        |r| unsafe {
            r.copy_image_unchecked(&src, a.src_image_layout, &dst, a.dst_image_layout, &region)
        },
    )
}

fn cmd_blit_image(
    s: &Setup,
    limits: &Limits,
    change: &dyn Fn(&mut args::CmdBlitImage, &Limits, &mut Objects),
) -> Outcome {
    let mut a = args::CmdBlitImage {
        src_image_layout: vk::ImageLayout::TRANSFER_SRC_OPTIMAL,
        dst_image_layout: vk::ImageLayout::TRANSFER_DST_OPTIMAL,
    };
    let mut o = Objects::default();
    change(&mut a, limits, &mut o);
    let (src, _src_memory) = make_image(s, &o.src_image);
    let (dst, _dst_memory) = make_image(s, &o.dst_image);
    let region = [o.image_blit];
    let nearest = vk::Filter::NEAREST;
    record(
        s,
        |r| {
            r.blit_image(
                &src,
                a.src_image_layout,
                &dst,
                a.dst_image_layout,
                &region,
                nearest,
            )
        },
        // SAFETY: as in `buffer_create_info`; the command buffer is never submitted.
        |r| unsafe {
            r.blit_image_unchecked(
                &src,
                a.src_image_layout,
                &dst,
                a.dst_image_layout,
                &region,
                nearest,
            )
        },
    )
}

fn cmd_copy_buffer_to_image(
    s: &Setup,
    limits: &Limits,
    change: &dyn Fn(&mut args::CmdCopyBufferToImage, &Limits, &mut Objects),
) -> Outcome {
    let mut a = args::CmdCopyBufferToImage {
        dst_image_layout: vk::ImageLayout::TRANSFER_DST_OPTIMAL,
    };
    let mut o = Objects::default();
    change(&mut a, limits, &mut o);
    let (image, _image_memory) = make_image(s, &o.dst_image);
    let (buffer, _memory) = make_buffer(s, &o.src_buffer);
    let region = [o.buffer_image_copy];
    record(
        s,
        |r| r.copy_buffer_to_image(&buffer, &image, a.dst_image_layout, &region),
        // SAFETY: as in `buffer_create_info`; the command buffer is never submitted.
        |r| unsafe {
            r.copy_buffer_to_image_unchecked(&buffer, &image, a.dst_image_layout, &region)
        },
    )
}

fn cmd_copy_image_to_buffer(
    s: &Setup,
    limits: &Limits,
    change: &dyn Fn(&mut args::CmdCopyImageToBuffer, &Limits, &mut Objects),
) -> Outcome {
    let mut a = args::CmdCopyImageToBuffer {
        src_image_layout: vk::ImageLayout::TRANSFER_SRC_OPTIMAL,
    };
    let mut o = Objects::default();
    change(&mut a, limits, &mut o);
    let (image, _image_memory) = make_image(s, &o.src_image);
    let (buffer, _memory) = make_buffer(s, &o.dst_buffer);
    let region = [o.buffer_image_copy];
    record(
        s,
        |r| r.copy_image_to_buffer(&image, a.src_image_layout, &buffer, &region),
        // SAFETY: as in `buffer_create_info`; the command buffer is never submitted.
        |r| unsafe {
            r.copy_image_to_buffer_unchecked(&image, a.src_image_layout, &buffer, &region)
        },
    )
}

/// Rules the 1.3.239 layer reports under another name than their VUID, each seen in
/// its message for the case that breaks the rule.
const LAYER_NAMES: &[(&str, &str)] = &[
    // The 1.3.239 layer checks a semaphore's stage against the device's features
    // under an unassigned name; its message states this rule.
    (
        "VUID-VkSemaphoreSubmitInfo-stageMask-03929",
        "stageMask includes VK_PIPELINE_STAGE_GEOMETRY_SHADER_BIT when the device does not have geometryShader feature enabled",
    ),
    (
        "VUID-VkSemaphoreSubmitInfo-stageMask-03930",
        "stageMask includes VK_PIPELINE_STAGE_TESSELLATION_CONTROL_SHADER_BIT when the device does not have tessellationShader feature enabled",
    ),
    // Its parameter check states the code size rule in words (in words of four bytes).
    (
        "VUID-VkShaderModuleCreateInfo-codeSize-01085",
        "pCreateInfo->codeSize / 4 must be greater than 0",
    ),
    (
        "VUID-VkCopyImageToBufferInfo2-aspectMask-00211",
        "[ VUID-vkCmdCopyImageToBuffer-aspectMask-00211 ]",
    ),
    (
        "VUID-VkCopyImageToBufferInfo2-dstBuffer-00192",
        "[ vkCmdCopyImageToBuffer-dstBuffer2-00192 ]",
    ),
    // The rules' VUIDs without VK_EXT_depth_range_unrestricted, which tuff does not
    // emit: the same bounds.
    (
        "VUID-VkViewport-minDepth-02540",
        "[ VUID-VkViewport-minDepth-01234 ]",
    ),
    (
        "VUID-VkViewport-maxDepth-02541",
        "[ VUID-VkViewport-maxDepth-01235 ]",
    ),
    // Without synchronization2 the 1.3.239 layer reports VK_PIPELINE_STAGE_NONE (0)
    // under the rule of a valid stage value.
    (
        "VUID-vkCmdWriteTimestamp-synchronization2-06489",
        "[ VUID-vkCmdWriteTimestamp-pipelineStage-parameter ]",
    ),
    // The rule's VUID for the same feature under VK_EXT_buffer_device_address.
    (
        "VUID-VkBufferCreateInfo-flags-06549",
        "[ VUID-VkBufferCreateInfo-flags-03338 ]",
    ),
];

/// Rules that the change breaking a rule (by its VUID's last two parts, the same
/// for a command and its `*2` info struct) necessarily breaks too, so the layer
/// may name them beside it: the case still proves its rule when the layer names
/// it, and names nothing but these besides.
const IMPLIED: &[(&str, &[&str], &str)] = &[
    (
        "objectType-02589",
        &[
            "VUID-vkSetDebugUtilsObjectNameEXT-pNameInfo-02587",
            "VUID-vkSetDebugUtilsObjectNameEXT-pNameInfo-02588",
        ],
        "vkSetDebugUtilsObjectNameEXT, the call the struct's fixture makes, takes no object of type UNKNOWN and no null handle, which the same change gives it",
    ),
    (
        "srcImage-01791",
        &["srcImage-07744", "srcOffset-00147"],
        "a depth other than the 2D source's layer count copies another number of slices than layers, which the 1.3.239 layer also reports under 07744 (a later registry's VUID of the same rule), and a depth above 1 passes the 2D image's depth",
    ),
    (
        "dstImage-01792",
        &["srcImage-07744", "dstOffset-00153"],
        "as for `srcImage-01791`, with the 2D image the destination",
    ),
    (
        "srcImage-01787",
        &["srcOffset-00147"],
        "a z offset of 1 on a 2D image puts the region past its depth of 1, which the 1.3.239 layer reports under the z range rule of 3D images",
    ),
    (
        "dstImage-01788",
        &["dstOffset-00153"],
        "a z offset of 1 on a 2D image puts the region past its depth of 1, which the 1.3.239 layer reports under the z range rule of 3D images",
    ),
    (
        "aspectMask-01964",
        &["VUID-VkRenderPassCreateInfo-pNext-01963"],
        "no format has a metadata aspect, so an input attachment's aspects that include it are not all present in its format",
    ),
    (
        "flags-03189",
        &["flags-03190"],
        "an imageless framebuffer also needs the chained attachment-image info, which the fixture's framebuffer, made with its views, does not chain",
    ),

    (
        "usage-00963",
        &["usage-00966"],
        "the fixture's image has no attachment usage, which a transient image needs as well",
    ),
    (
        "extent-06670",
        &[
            "VUID-vkCmdCopyImage-srcImage-01790",
            "VUID-VkCopyImageInfo2-srcImage-01790",
        ],
        FLAT_DEPTH,
    ),
    (
        "imageExtent-06661",
        &[
            "VUID-vkCmdCopyBufferToImage-srcImage-00201",
            "VUID-VkCopyBufferToImageInfo2-srcImage-00201",
        ],
        FLAT_DEPTH,
    ),
    (
        "layerCount-01700",
        &["VUID-vkCmdCopyImage-srcImage-07744"],
        "a copy of no layers of a 2D image has a depth (its layer count) unlike the other image's",
    ),
    (
        "srcSubresource-01696",
        &["srcOffset-00144", "srcOffset-00145", "srcOffset-00147"],
        LEVEL_PAST,
    ),
    (
        "dstSubresource-01697",
        &["dstOffset-00150", "dstOffset-00151", "dstOffset-00153"],
        LEVEL_PAST,
    ),
    (
        "imageSubresource-01701",
        &[
            "imageOffset-00200",
            "pRegions-06217",
            "pRegions-06218",
            "pRegions-06219",
            "pRegions-00172",
            "pRegions-06223",
            "pRegions-06224",
        ],
        LEVEL_PAST,
    ),
    (
        "imageSubresource-01703",
        &[
            "imageOffset-00200",
            "pRegions-06220",
            "pRegions-06221",
            "pRegions-06222",
        ],
        LEVEL_PAST,
    ),
    (
        "srcSubresource-01705",
        &[
            "pRegions-00215",
            "srcOffset-00243",
            "srcOffset-00244",
            "srcOffset-00246",
        ],
        LEVEL_PAST,
    ),
    (
        "dstSubresource-01706",
        &[
            "pRegions-00216",
            "dstOffset-00248",
            "dstOffset-00249",
            "dstOffset-00251",
        ],
        LEVEL_PAST,
    ),
    ("pRegions-06218", &["pRegions-06217"], TWICE),
    ("pRegions-06219", &["pRegions-06217"], TWICE),
    ("pRegions-06221", &["pRegions-06220"], TWICE),
    ("pRegions-06222", &["pRegions-06220"], TWICE),
    ("pRegions-06223", &["pRegions-00172"], TWICE),
    ("pRegions-06224", &["pRegions-00172"], TWICE),
    (
        "imageOffset-00200",
        &["pRegions-00172", "srcImage-00201"],
        FLAT,
    ),
    ("srcOffset-00243", &["pRegions-00215"], TWICE),
    ("srcOffset-00244", &["pRegions-00215"], TWICE),
    (
        "srcOffset-00246",
        &["pRegions-00215", "srcImage-00247"],
        FLAT,
    ),
    ("dstOffset-00248", &["pRegions-00216"], TWICE),
    ("dstOffset-00249", &["pRegions-00216"], TWICE),
    (
        "dstOffset-00251",
        &["pRegions-00216", "dstImage-00252"],
        FLAT,
    ),
    ("srcOffset-00272", &["srcImage-00273"], FLAT),
    ("dstOffset-00277", &["dstImage-00278"], FLAT),
    (
        "separateDepthStencilLayouts-03284",
        &["format-03286"],
        COLOR_ATTACHMENT,
    ),
    (
        "separateDepthStencilLayouts-03285",
        &["format-03287"],
        COLOR_ATTACHMENT,
    ),
    ("aspectMask-00142", &["srcImage-01551"], BOTH_COLOR),
    ("aspectMask-00143", &["srcImage-01551"], BOTH_COLOR),
    (
        "aspectMask-00241",
        &[
            "VUID-VkImageBlit-aspectMask-00238",
            "VUID-VkImageBlit2-aspectMask-00238",
        ],
        BOTH_COLOR,
    ),
    (
        "aspectMask-00242",
        &[
            "VUID-VkImageBlit-aspectMask-00238",
            "VUID-VkImageBlit2-aspectMask-00238",
        ],
        BOTH_COLOR,
    ),
    (
        "srcOffset-00113",
        &["size-00115"],
        "an offset at the buffer's size leaves no room for the region's size",
    ),
    (
        "dstOffset-00114",
        &["size-00116"],
        "an offset at the buffer's size leaves no room for the region's size",
    ),
];

const BOTH_COLOR: &str = "the fixture's two images are color images, so an aspect one of them \
     lacks makes the source's and destination's masks differ";
const COLOR_ATTACHMENT: &str = "the fixture's attachment has a color format, and the depth and \
     stencil layouts the rule forbids without the feature a color format forbids as well";
const FLAT_DEPTH: &str = "a region of a 2D image has depth 1, so a depth of 0 breaks that rule too";
const LEVEL_PAST: &str =
    "a mip level past the image's has no extent, so the region lies outside it as well";
const TWICE: &str =
    "the specification states a region inside the image twice: per coordinate and as a whole";
const FLAT: &str = "on a 2D image, a z range past depth 1 is also a z offset other than 0 or a \
     depth other than 1, and the region lies outside the image";

/// Whether a layer message names a rule that breaking `vuid` implies ([`IMPLIED`]).
fn implied(message: &str, vuid: &str) -> bool {
    let mut parts = vuid.rsplitn(3, '-');
    let (Some(number), Some(name), Some(prefix)) = (parts.next(), parts.next(), parts.next())
    else {
        return false;
    };
    let key = format!("{name}-{number}");
    IMPLIED
        .iter()
        .filter(|(k, _, _)| *k == key)
        .flat_map(|(_, also, _)| also.iter())
        // A rule of another item (a region struct's) is named whole.
        .any(|other| match other.strip_prefix("VUID-") {
            Some(_) => names(message, other),
            None => names(message, &format!("{prefix}-{other}")),
        })
}

/// Whether a layer message names `vuid`. The 1.3.239 layer names a few rules
/// without the prefix (`[ vkCmdCopyImageToBuffer dstBuffer-00192 ]`), and a few
/// under another name ([`LAYER_NAMES`]).
fn names(message: &str, vuid: &str) -> bool {
    let bare = vuid
        .strip_prefix("VUID-")
        .map(|rest| rest.replacen('-', " ", 1));
    message.contains(vuid)
        || bare.is_some_and(|b| message.contains(&format!("[ {b} ]")))
        || LAYER_NAMES
            .iter()
            .any(|(v, name)| *v == vuid && message.contains(name))
}

/// A fixture for one of the `vkCmd*2` transfer commands: its info struct is built
/// over the objects the change asks for (the change runs once for them, then on the
/// info), and recorded through the safe method and the unchecked one.
macro_rules! transfer2_fixture {
    ($name:ident, $ty:ident, $cmd:ident, $unchecked:ident, |$s:ident, $o:ident| $build:block) => {
        fn $name(
            s: &Setup,
            limits: &Limits,
            change: &dyn Fn(&mut vk::$ty<'_>, &Limits, &mut Objects),
        ) -> Outcome {
            let mut $o = Objects::default();
            change(&mut Default::default(), limits, &mut $o);
            let $s = s;
            let build = $build;
            build(&mut |info: &mut tuff::$ty<'_>| {
                // SAFETY: as in `buffer_create_info`.
                change(unsafe { info.raw_values_mut() }, limits, &mut $o.clone());
                record(
                    s,
                    // SAFETY: as in `buffer_create_info`; some of these commands are
                    // safe now.
                    #[allow(unused_unsafe)]
                    |r| unsafe { r.$cmd(info) },
                    // SAFETY: as in `buffer_create_info`; the command buffer is never
                    // submitted.
                    |r| unsafe { r.$unchecked(info) },
                )
            })
        }
    };
}

/// The safe struct of a fixture's buffer-image region.
fn safe_buffer_image_copy2(r: &vk::BufferImageCopy2<'_>) -> tuff::BufferImageCopy2<'static> {
    tuff::BufferImageCopy2::new()
        .buffer_offset(r.buffer_offset)
        .buffer_row_length(r.buffer_row_length)
        .buffer_image_height(r.buffer_image_height)
        .image_subresource(r.image_subresource)
        .image_offset(r.image_offset)
        .image_extent(r.image_extent)
}

const SRC: vk::ImageLayout = vk::ImageLayout::TRANSFER_SRC_OPTIMAL;
const DST: vk::ImageLayout = vk::ImageLayout::TRANSFER_DST_OPTIMAL;

transfer2_fixture!(
    copy_buffer_info2,
    CopyBufferInfo2,
    copy_buffer2,
    copy_buffer2_unchecked,
    |s, o| {
        |run: &mut dyn FnMut(&mut tuff::CopyBufferInfo2<'_>) -> Outcome| {
            let (src, _m1) = make_buffer(s, &o.src_buffer);
            let (dst, _m2) = make_buffer(s, &o.dst_buffer);
            let r = o.buffer_copy2;
            let regions = [tuff::BufferCopy2::new()
                .src_offset(r.src_offset)
                .dst_offset(r.dst_offset)
                .size(r.size)];
            run(&mut tuff::CopyBufferInfo2::new(&src, &dst).regions(&regions))
        }
    }
);

transfer2_fixture!(
    copy_image_info2,
    CopyImageInfo2,
    copy_image2,
    copy_image2_unchecked,
    |s, o| {
        |run: &mut dyn FnMut(&mut tuff::CopyImageInfo2<'_>) -> Outcome| {
            let (src, _m1) = make_image(s, &o.src_image);
            let (dst, _m2) = make_image(s, &o.dst_image);
            let r = o.image_copy2;
            let regions = [tuff::ImageCopy2::new()
                .src_subresource(r.src_subresource)
                .src_offset(r.src_offset)
                .dst_subresource(r.dst_subresource)
                .dst_offset(r.dst_offset)
                .extent(r.extent)];
            run(&mut tuff::CopyImageInfo2::new(&src, &dst)
                .src_image_layout(SRC)
                .dst_image_layout(DST)
                .regions(&regions))
        }
    }
);

transfer2_fixture!(
    blit_image_info2,
    BlitImageInfo2,
    blit_image2,
    blit_image2_unchecked,
    |s, o| {
        |run: &mut dyn FnMut(&mut tuff::BlitImageInfo2<'_>) -> Outcome| {
            let (src, _m1) = make_image(s, &o.src_image);
            let (dst, _m2) = make_image(s, &o.dst_image);
            let r = o.image_blit2;
            let regions = [tuff::ImageBlit2::new()
                .src_subresource(r.src_subresource)
                .src_offsets(r.src_offsets)
                .dst_subresource(r.dst_subresource)
                .dst_offsets(r.dst_offsets)];
            run(&mut tuff::BlitImageInfo2::new(&src, &dst)
                .src_image_layout(SRC)
                .dst_image_layout(DST)
                .regions(&regions)
                .filter(vk::Filter::NEAREST))
        }
    }
);

transfer2_fixture!(
    copy_buffer_to_image_info2,
    CopyBufferToImageInfo2,
    copy_buffer_to_image2,
    copy_buffer_to_image2_unchecked,
    |s, o| {
        |run: &mut dyn FnMut(&mut tuff::CopyBufferToImageInfo2<'_>) -> Outcome| {
            let (src, _m1) = make_buffer(s, &o.src_buffer);
            let (dst, _m2) = make_image(s, &o.dst_image);
            let regions = [safe_buffer_image_copy2(&o.buffer_image_copy2)];
            run(&mut tuff::CopyBufferToImageInfo2::new(&src, &dst)
                .dst_image_layout(DST)
                .regions(&regions))
        }
    }
);

transfer2_fixture!(
    copy_image_to_buffer_info2,
    CopyImageToBufferInfo2,
    copy_image_to_buffer2,
    copy_image_to_buffer2_unchecked,
    |s, o| {
        |run: &mut dyn FnMut(&mut tuff::CopyImageToBufferInfo2<'_>) -> Outcome| {
            let (src, _m1) = make_image(s, &o.src_image);
            let (dst, _m2) = make_buffer(s, &o.dst_buffer);
            let regions = [safe_buffer_image_copy2(&o.buffer_image_copy2)];
            run(&mut tuff::CopyImageToBufferInfo2::new(&src, &dst)
                .src_image_layout(SRC)
                .regions(&regions))
        }
    }
);

/// Records a draw inside the test pipeline's render pass (pipeline, viewport,
/// scissor and push constants set), through the safe call and, under the layer, the
/// unchecked one; the safe call's result is the outcome.
fn draw(
    s: &Setup,
    safe: impl FnOnce(&mut tuff::Recorder<'_, tuff::InRenderPass>) -> tuff::Result<()>,
    unchecked: impl FnOnce(&mut tuff::Recorder<'_, tuff::InRenderPass>),
) -> Outcome {
    let target = s.color_target(4, vk::ImageUsageFlags::empty());
    let p = pipelines::pipelines(s, &target);
    let clear = [vk::ClearValue::default()];
    let area = vk::Rect2D {
        offset: vk::Offset2D::default(),
        extent: vk::Extent2D {
            width: 4,
            height: 4,
        },
    };
    let viewport = vk::Viewport {
        width: 4.0,
        height: 4.0,
        max_depth: 1.0,
        ..Default::default()
    };
    let push = [0u8; 16];
    let inside =
        |cb: &mut tuff::CommandBuffer,
         call: &mut dyn FnMut(&mut tuff::Recorder<'_, tuff::InRenderPass>)| {
            let rec = cb
                .begin(&tuff::CommandBufferBeginInfo::new())
                .expect("begin");
            let mut rec = rec.begin_render_pass(
                &tuff::RenderPassBeginInfo::new(&target.render_pass, &target.framebuffer)
                    .render_area(area)
                    .clear_values(&clear),
                vk::SubpassContents::INLINE,
            );
            rec.bind_pipeline(vk::PipelineBindPoint::GRAPHICS, &p.graphics)
                .expect("bind");
            rec.set_viewport(0, &[viewport]).expect("viewport");
            rec.set_scissor(0, &[area]).expect("scissor");
            rec.push_constants(&p.graphics_layout, vk::ShaderStageFlags::FRAGMENT, 0, &push)
                .expect("push");
            call(&mut rec);
            rec.end_render_pass().end()
        };
    let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let mut safe = Some(safe);
    let mut result = Ok(());
    let ended = inside(&mut cb, &mut |rec| {
        if let Some(f) = safe.take() {
            result = f(rec);
        }
    });
    // A command that returns nothing leaves its refusal for `end`.
    let result = result.and(ended);
    let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let mut unchecked = Some(unchecked);
    let layer = under_layer(s, || {
        let _ = inside(&mut cb, &mut |rec| {
            if let Some(f) = unchecked.take() {
                f(rec);
            }
        });
    });
    Outcome {
        safe: result,
        layer,
    }
}

fn cmd_draw_indirect(
    s: &Setup,
    limits: &Limits,
    change: &dyn Fn(&mut args::CmdDrawIndirect, &Limits, &mut Objects),
) -> Outcome {
    let mut a = args::CmdDrawIndirect {
        offset: 0,
        draw_count: 1,
    };
    let mut o = Objects::default();
    change(&mut a, limits, &mut o);
    let (buffer, _memory) = make_buffer(s, &o.buffer);
    draw(
        s,
        |r| unsafe { r.draw_indirect(&buffer, a.offset, a.draw_count, 16) },
        // SAFETY: as in `buffer_create_info`; the command buffer is never submitted.
        |r| drop(unsafe { r.draw_indirect_unchecked(&buffer, a.offset, a.draw_count, 16) }),
    )
}

fn cmd_draw_indexed_indirect(
    s: &Setup,
    limits: &Limits,
    change: &dyn Fn(&mut args::CmdDrawIndexedIndirect, &Limits, &mut Objects),
) -> Outcome {
    let mut a = args::CmdDrawIndexedIndirect {
        offset: 0,
        draw_count: 1,
    };
    let mut o = Objects::default();
    change(&mut a, limits, &mut o);
    let (buffer, _memory) = make_buffer(s, &o.buffer);
    let (indices, _index_memory) =
        pipelines::host_buffer(s, 64, vk::BufferUsageFlags::INDEX_BUFFER);
    let index = vk::IndexType::UINT32;
    draw(
        s,
        |r| {
            r.bind_index_buffer(&indices, 0, index)
                .expect("index buffer");
            unsafe { r.draw_indexed_indirect(&buffer, a.offset, a.draw_count, 20) }
        },
        |r| {
            r.bind_index_buffer(&indices, 0, index)
                .expect("index buffer");
            // SAFETY: as in `buffer_create_info`; the command buffer is never
            // submitted.
            drop(unsafe { r.draw_indexed_indirect_unchecked(&buffer, a.offset, a.draw_count, 20) })
        },
    )
}

fn cmd_dispatch_indirect(
    s: &Setup,
    limits: &Limits,
    change: &dyn Fn(&mut args::CmdDispatchIndirect, &Limits, &mut Objects),
) -> Outcome {
    let mut a = args::CmdDispatchIndirect { offset: 0 };
    let mut o = Objects::default();
    change(&mut a, limits, &mut o);
    let (buffer, _memory) = make_buffer(s, &o.buffer);
    let target = s.color_target(4, vk::ImageUsageFlags::empty());
    let p = pipelines::pipelines(s, &target);
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
    let mut result = Ok(());
    let mut out = record(
        s,
        |r| {
            bind(r);
            result = unsafe { r.dispatch_indirect(&buffer, a.offset) };
        },
        |r| {
            bind(r);
            // SAFETY: as in `buffer_create_info`; the command buffer is never
            // submitted.
            drop(unsafe { r.dispatch_indirect_unchecked(&buffer, a.offset) });
        },
    );
    // A dispatch returns its refusal itself, rather than through `end`.
    if result.is_err() {
        out.safe = result;
    }
    out
}

/// The objects of a resolve: a 4-sample source, unless the change asks otherwise.
fn resolve_objects(change: impl FnOnce(&mut Objects)) -> Objects {
    let mut o = Objects::default();
    o.src_image.samples = vk::SampleCountFlags::TYPE_4;
    change(&mut o);
    o
}

fn cmd_resolve_image(
    s: &Setup,
    limits: &Limits,
    change: &dyn Fn(&mut args::CmdResolveImage, &Limits, &mut Objects),
) -> Outcome {
    let mut a = args::CmdResolveImage {
        src_image_layout: SRC,
        dst_image_layout: DST,
    };
    let o = resolve_objects(|o| change(&mut a, limits, o));
    let (src, _m1) = make_image(s, &o.src_image);
    let (dst, _m2) = make_image(s, &o.dst_image);
    record(
        s,
        |r| {
            r.resolve_image(
                &src,
                a.src_image_layout,
                &dst,
                a.dst_image_layout,
                &[o.image_resolve],
            )
        },
        // SAFETY: as in `buffer_create_info`; the command buffer is never submitted.
        |r| unsafe {
            r.resolve_image_unchecked(
                &src,
                a.src_image_layout,
                &dst,
                a.dst_image_layout,
                &[o.image_resolve],
            )
        },
    )
}

transfer2_fixture!(
    resolve_image_info2,
    ResolveImageInfo2,
    resolve_image2,
    resolve_image2_unchecked,
    |s, o| {
        |run: &mut dyn FnMut(&mut tuff::ResolveImageInfo2<'_>) -> Outcome| {
            let o = resolve_objects(|x| {
                *x = Objects {
                    src_image: ImageSpec {
                        samples: x.src_image.samples,
                        ..o.src_image
                    },
                    ..o
                }
            });
            let (src, _m1) = make_image(s, &o.src_image);
            let (dst, _m2) = make_image(s, &o.dst_image);
            let r = o.image_resolve2;
            let regions = [tuff::ImageResolve2::new()
                .src_subresource(r.src_subresource)
                .src_offset(r.src_offset)
                .dst_subresource(r.dst_subresource)
                .dst_offset(r.dst_offset)
                .extent(r.extent)];
            run(&mut tuff::ResolveImageInfo2::new(&src, &dst)
                .src_image_layout(SRC)
                .dst_image_layout(DST)
                .regions(&regions))
        }
    }
);

fn cmd_copy_query_pool_results(
    s: &Setup,
    limits: &Limits,
    change: &dyn Fn(&mut args::CmdCopyQueryPoolResults, &Limits, &mut Objects),
) -> Outcome {
    let mut a = args::CmdCopyQueryPoolResults {
        dst_offset: 0,
        stride: 8,
        flags: vk::QueryResultFlags::TYPE_64,
    };
    let mut o = Objects::default();
    change(&mut a, limits, &mut o);
    let (buffer, _memory) = make_buffer(s, &o.dst_buffer);
    let pool = timestamps(s);
    let (stride, flags) = (a.stride, a.flags);
    record(
        s,
        |r| {
            r.reset_query_pool(&pool, 0, 1).expect("reset");
            r.copy_query_pool_results(&pool, 0, 1, &buffer, a.dst_offset, stride, flags)
        },
        |r| {
            r.reset_query_pool(&pool, 0, 1).expect("reset");
            // SAFETY: as in `buffer_create_info`; the command buffer is never
            // submitted.
            unsafe {
                r.copy_query_pool_results_unchecked(
                    &pool,
                    0,
                    1,
                    &buffer,
                    a.dst_offset,
                    stride,
                    flags,
                )
            }
        },
    )
}

fn buffer_view_create_info(
    s: &Setup,
    limits: &Limits,
    change: &dyn Fn(&mut vk::BufferViewCreateInfo<'_>, &Limits, &mut Objects),
) -> Outcome {
    // As in `buffer_memory_barrier2`.
    let mut o = Objects::default();
    change(&mut Default::default(), limits, &mut o);
    let (buffer, _memory) = make_buffer(s, &o.buffer);
    let mut info = tuff::BufferViewCreateInfo::new(&buffer)
        .format(vk::Format::R8G8B8A8_UNORM)
        .range(vk::WHOLE_SIZE);
    // SAFETY: as in `buffer_create_info`.
    change(unsafe { info.raw_values_mut() }, limits, &mut o.clone());
    create!(s, create_buffer_view, create_buffer_view_unchecked, &info)
}

/// Records a Vulkan 1.0 pipeline barrier holding `buffers` and `images`.
fn barrier1(
    s: &Setup,
    buffers: &[tuff::BufferMemoryBarrier<'_>],
    images: &[tuff::ImageMemoryBarrier<'_>],
) -> Outcome {
    let stage = vk::PipelineStageFlags::ALL_COMMANDS;
    let flags = vk::DependencyFlags::empty();
    record(
        s,
        |r| r.pipeline_barrier(stage, stage, flags, &[], buffers, images),
        // SAFETY: as in `buffer_create_info`; the command buffer is never submitted.
        |r| unsafe { r.pipeline_barrier_unchecked(stage, stage, flags, &[], buffers, images) },
    )
}

fn buffer_memory_barrier(
    s: &Setup,
    limits: &Limits,
    change: &dyn Fn(&mut vk::BufferMemoryBarrier<'_>, &Limits, &mut Objects),
) -> Outcome {
    // As in `buffer_memory_barrier2`.
    let mut o = Objects::default();
    change(&mut Default::default(), limits, &mut o);
    let (buffer, _memory) = make_buffer(s, &o.buffer);
    let mut b = tuff::BufferMemoryBarrier::new(&buffer)
        .src_queue_family_index(vk::QUEUE_FAMILY_IGNORED)
        .dst_queue_family_index(vk::QUEUE_FAMILY_IGNORED)
        .size(vk::WHOLE_SIZE);
    // SAFETY: as in `buffer_create_info`.
    change(unsafe { b.raw_values_mut() }, limits, &mut o.clone());
    barrier1(s, &[b], &[])
}

fn image_memory_barrier(
    s: &Setup,
    limits: &Limits,
    change: &dyn Fn(&mut vk::ImageMemoryBarrier<'_>, &Limits, &mut Objects),
) -> Outcome {
    // As in `buffer_memory_barrier2`.
    let mut o = Objects::default();
    change(&mut Default::default(), limits, &mut o);
    let (image, _memory) = make_image(s, &o.image);
    let mut b = tuff::ImageMemoryBarrier::new(&image)
        .old_layout(vk::ImageLayout::UNDEFINED)
        .new_layout(vk::ImageLayout::GENERAL)
        .src_queue_family_index(vk::QUEUE_FAMILY_IGNORED)
        .dst_queue_family_index(vk::QUEUE_FAMILY_IGNORED)
        .subresource_range(WHOLE);
    // SAFETY: as in `buffer_create_info`.
    change(unsafe { b.raw_values_mut() }, limits, &mut o.clone());
    barrier1(s, &[], &[b])
}

/// Each fixture's value, unchanged, is valid: tuff accepts the call and the layer
/// says nothing. Without this, a case could pass on a rule its fixture already breaks.
#[test]
fn every_fixture_is_valid_as_it_stands() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let limits = s.physical.get_properties().limits;
    let fixtures = fixtures();
    assert!(
        !fixtures.is_empty(),
        "generated/oracle_cases.rs has no fixture"
    );
    for (name, _, run) in &fixtures {
        let out = run(&s, &limits);
        assert!(
            out.safe.is_ok(),
            "{name}: tuff refused the valid call: {:?}",
            out.safe
        );
        assert!(
            out.layer.is_empty(),
            "{name}: the layer reported the valid call:\n{}",
            out.layer.join("\n")
        );
    }
}

/// Every case breaks its rule: tuff refuses it with the rule's VUID, and the layer
/// names that VUID (with only the rules the same change must break, [`IMPLIED`])
/// or nothing.
#[test]
fn every_recognised_rule_is_refused_and_the_layer_agrees() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let bare = tuff_setup::setup_bare(true);
    let full = tuff_setup::setup_full_features(true);
    let limits = s.physical.get_properties().limits;
    // `setup` enables no Vulkan 1.0 feature, which the cases of rules that apply
    // when a feature is off rely on; `setup_bare` enables none at all.
    let cases = cases();
    assert!(!cases.is_empty(), "generated/oracle_cases.rs has no case");
    let (mut by_layer, mut alone, mut failures) = (0, Vec::new(), Vec::new());
    for (vuid, device, run) in &cases {
        if std::env::var_os("ORACLE_TRACE").is_some() {
            eprintln!("oracle: {vuid}");
        }
        let device = match *device {
            "bare" => &bare,
            "full" => &full,
            _ => &s,
        };
        let out = run(device, &limits);
        match &out.safe {
            Err(tuff::Error::Validation { vuid: got, .. }) if got == vuid => {}
            other => {
                failures.push(format!("{vuid}: the safe method returned {other:?}"));
                continue;
            }
        }
        if out.layer.is_empty() {
            alone.push(*vuid);
        } else if out.layer.iter().any(|m| names(m, vuid))
            && out.layer.iter().all(|m| names(m, vuid) || implied(m, vuid))
        {
            by_layer += 1;
        } else {
            failures.push(format!(
                "{vuid}: the layer said something else:\n  {}",
                out.layer.join("\n  ")
            ));
        }
    }
    println!(
        "oracle: {} rules broken; the layer named {by_layer}, the error alone proves {} ({})",
        cases.len(),
        alone.len(),
        alone.join(", ")
    );
    assert!(
        failures.is_empty(),
        "{} of {} cases failed:\n{}",
        failures.len(),
        cases.len(),
        failures.join("\n")
    );
}

/// A stage that stands for several (`PRE_RASTERIZATION_SHADERS`) satisfies a rule
/// that asks for one of them: a barrier the specification allows is not refused.
#[test]
fn a_meta_stage_satisfies_a_rule_that_asks_for_one_of_its_stages() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let b = [tuff::MemoryBarrier2::new()
        .src_stage_mask(vk::PipelineStageFlags2::PRE_RASTERIZATION_SHADERS)
        .src_access_mask(vk::AccessFlags2::UNIFORM_READ)
        .dst_stage_mask(ALL)];
    let out = barrier(&s, &tuff::DependencyInfo::new().memory_barriers(&b));
    assert!(
        out.safe.is_ok(),
        "tuff refused a valid barrier: {:?}",
        out.safe
    );
    assert!(
        out.layer.is_empty(),
        "the layer reported the valid barrier:\n{}",
        out.layer.join("\n")
    );
}

/// The VUID of a refused call, or a panic naming what came back instead.
fn refusal<T>(r: tuff::Result<T>) -> &'static str {
    match r {
        Err(tuff::Error::Validation { vuid, .. }) => vuid,
        Err(e) => panic!("expected tuff to refuse the call, got {e}"),
        Ok(_) => panic!("expected tuff to refuse the call, got success"),
    }
}

/// A refused call leaves its objects and the device usable: after three refusals on
/// the objects of a frame (a barrier recorded into the frame's own command buffer, a
/// view of its image, a buffer of size 0), the same command buffer records the frame,
/// which draws the expected pixel and dispatches the expected output, and the layer
/// says nothing at any point.
#[test]
fn after_a_refusal_the_same_objects_render_a_correct_frame() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let d = &s.device;
    let target = s.color_target(8, vk::ImageUsageFlags::TRANSFER_SRC);
    let work = pipelines::pipelines(&s, &target);
    let readback = pipelines::host_buffer(&s, 16, vk::BufferUsageFlags::TRANSFER_DST);
    let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);

    // A geometry-shader stage on a device without the feature: the barrier is
    // refused and not recorded.
    let mut rec = cb
        .begin(&tuff::CommandBufferBeginInfo::new())
        .expect("begin");
    let refused = rec.pipeline_barrier(
        vk::PipelineStageFlags::GEOMETRY_SHADER,
        vk::PipelineStageFlags::TRANSFER,
        vk::DependencyFlags::empty(),
        &[],
        &[],
        &[],
    );
    assert_eq!(
        refusal(refused),
        "VUID-vkCmdPipelineBarrier-srcStageMask-04090"
    );
    rec.end().expect("end");
    // A cube-array view of the frame's image without the imageCubeArray feature.
    assert_eq!(
        refusal(
            d.create_image_view(
                &tuff::ImageViewCreateInfo::new(&target.image)
                    .view_type(vk::ImageViewType::CUBE_ARRAY)
                    .format(vk::Format::R8G8B8A8_UNORM)
                    .subresource_range(WHOLE),
            )
        ),
        "VUID-VkImageViewCreateInfo-viewType-01004"
    );
    assert_eq!(
        refusal(d.create_buffer(
            &tuff::BufferCreateInfo::new().usage(vk::BufferUsageFlags::TRANSFER_DST),
        )),
        "VUID-VkBufferCreateInfo-size-00912"
    );
    vulkan::assert_silent(&s.messages);

    let rec = cb
        .begin(&tuff::CommandBufferBeginInfo::new())
        .expect("begin again");
    work.record(rec, &target, 8, Some(&readback.0))
        .end()
        .expect("end");
    let fence = d
        .create_fence(&tuff::FenceCreateInfo::new())
        .expect("fence");
    s.queue
        .submit(
            &[tuff::SubmitInfo::new().command_buffers(&cb)],
            Some(&fence),
        )
        .expect("submit");
    let status = d.wait_for_fences(&fence, true, u64::MAX).expect("wait");
    assert_eq!(status, tuff::SuccessOrTimeout::Success);
    let pixel = pipelines::access_memory(&s, &readback.1, 4, None);
    let expected: Vec<u8> = pipelines::COLOR
        .iter()
        .map(|c| (c * 255.0).round() as u8)
        .collect();
    for (got, want) in pixel.iter().zip(&expected) {
        assert!(
            got.abs_diff(*want) <= 1,
            "drawn pixel {pixel:?}, expected {expected:?}"
        );
    }
    vulkan::assert_silent(&s.messages);
}

/// A feature enabled through the struct of the extension it came from
/// (`VkPhysicalDeviceSynchronization2Features`) rather than a core version's
/// features struct is known too: a barrier that needs `synchronization2` (a
/// `READ_ONLY_OPTIMAL` layout, `VUID-VkImageMemoryBarrier-synchronization2-07793`,
/// on the fixture's sampled image, which that layout's usage rule allows) is
/// accepted, and the layer agrees.
#[test]
fn a_feature_enabled_through_its_extension_struct_is_known() {
    let _serial = vulkan::serial();
    let s = setup_with_extension_feature_structs(true);
    let limits = s.physical.get_properties().limits;
    let out = image_memory_barrier(&s, &limits, &|v, _, _| {
        v.old_layout = vk::ImageLayout::READ_ONLY_OPTIMAL;
    });
    assert!(
        out.safe.is_ok(),
        "tuff refused a barrier that synchronization2 allows: {:?}",
        out.safe
    );
    assert!(
        out.layer.is_empty(),
        "the layer reported the barrier:\n{}",
        out.layer.join("\n")
    );
}

/// A uniform-buffer descriptor write of a buffer info (the buffer made as `o.buffer`
/// says, with uniform usage), through `update_descriptor_sets`.
fn descriptor_buffer_info(
    s: &Setup,
    limits: &Limits,
    change: &dyn Fn(&mut vk::DescriptorBufferInfo, &Limits, &mut Objects),
) -> Outcome {
    let mut o = Objects::default();
    o.buffer.usage |= vk::BufferUsageFlags::UNIFORM_BUFFER;
    change(&mut Default::default(), limits, &mut o);
    let (buffer, _memory) = make_buffer(s, &o.buffer);
    let set = pipelines::uniform_set(s);
    let mut info = tuff::DescriptorBufferInfo::new()
        .buffer(Some(&buffer))
        .offset(0)
        .range(o.buffer.size);
    // SAFETY: as in `buffer_create_info`.
    change(unsafe { info.raw_values_mut() }, limits, &mut o.clone());
    let infos = [info];
    let writes = [tuff::WriteDescriptorSet::new(&set.set)
        .descriptor_type(vk::DescriptorType::UNIFORM_BUFFER)
        .buffer_info(&infos)];
    create!(
        s,
        update_descriptor_sets,
        update_descriptor_sets_unchecked,
        &writes,
        &[]
    )
}

/// A clear of the fixture's image over one subresource range.
fn image_subresource_range(
    s: &Setup,
    limits: &Limits,
    change: &dyn Fn(&mut vk::ImageSubresourceRange, &Limits, &mut Objects),
) -> Outcome {
    cmd_clear_color_image(s, limits, &|_, l, o| {
        let mut range = o.image_subresource_range;
        change(&mut range, l, o);
        o.image_subresource_range = range;
    })
}

/// The render pass of [`render_pass`], its subpass's color reference changed.
fn attachment_reference(
    s: &Setup,
    limits: &Limits,
    change: &dyn Fn(&mut vk::AttachmentReference, &Limits, &mut Objects),
) -> Outcome {
    let mut o = Objects::default();
    let mut reference = o.attachment_reference_color_attachments;
    change(&mut reference, limits, &mut o);
    o.attachment_reference_color_attachments = reference;
    render_pass(s, &o, |_| {})
}

/// The render pass of [`render_pass2`], its subpass's color reference changed.
fn attachment_reference2(
    s: &Setup,
    limits: &Limits,
    change: &dyn Fn(&mut vk::AttachmentReference2<'_>, &Limits, &mut Objects),
) -> Outcome {
    let mut o = Objects::default();
    let mut reference = o.attachment_reference2_color_attachments;
    change(&mut reference, limits, &mut o);
    o.attachment_reference2_color_attachments = reference;
    render_pass2(s, &o, |_| {})
}

fn viewport(
    s: &Setup,
    limits: &Limits,
    change: &dyn Fn(&mut vk::Viewport, &Limits, &mut Objects),
) -> Outcome {
    let mut v = vk::Viewport {
        width: 4.0,
        height: 4.0,
        max_depth: 1.0,
        ..Default::default()
    };
    change(&mut v, limits, &mut Objects::default());
    record(
        s,
        |r| r.set_viewport(0, &[v]),
        // SAFETY: as in `buffer_create_info`; the command buffer is never submitted.
        |r| unsafe { r.set_viewport_unchecked(0, &[v]) },
    )
}

/// A fixture for a region struct of a copy: the copy command's fixture, with the
/// change made to the one region it passes.
macro_rules! region_fixture {
    ($name:ident, $ty:ty, $command:ident, $args:ty, |$o:ident| $region:expr) => {
        fn $name(
            s: &Setup,
            limits: &Limits,
            change: &dyn Fn(&mut $ty, &Limits, &mut Objects),
        ) -> Outcome {
            $command(s, limits, &|_: &mut $args, l: &Limits, $o: &mut Objects| {
                let mut region = $region;
                change(&mut region, l, $o);
                $region = region;
            })
        }
    };
}

region_fixture!(
    image_copy,
    vk::ImageCopy,
    cmd_copy_image,
    args::CmdCopyImage,
    |o| o.image_copy
);
region_fixture!(
    buffer_image_copy,
    vk::BufferImageCopy,
    cmd_copy_buffer_to_image,
    args::CmdCopyBufferToImage,
    |o| o.buffer_image_copy
);
region_fixture!(
    image_subresource_layers,
    vk::ImageSubresourceLayers,
    cmd_copy_image,
    args::CmdCopyImage,
    |o| o.image_copy.src_subresource
);

/// As [`region_fixture!`], for the `*2` infos, whose fixtures take the info.
macro_rules! region2_fixture {
    ($name:ident, $ty:ty, $command:ident, $info:ident, |$o:ident| $region:expr) => {
        fn $name(
            s: &Setup,
            limits: &Limits,
            change: &dyn Fn(&mut $ty, &Limits, &mut Objects),
        ) -> Outcome {
            $command(s, limits, &|_: &mut vk::$info<'_>,
                                  l: &Limits,
                                  $o: &mut Objects| {
                let mut region = $region;
                change(&mut region, l, $o);
                $region = region;
            })
        }
    };
}

region2_fixture!(
    image_copy2,
    vk::ImageCopy2<'static>,
    copy_image_info2,
    CopyImageInfo2,
    |o| o.image_copy2
);
region2_fixture!(
    buffer_image_copy2,
    vk::BufferImageCopy2<'static>,
    copy_buffer_to_image_info2,
    CopyBufferToImageInfo2,
    |o| o.buffer_image_copy2
);

fn cmd_dispatch(
    s: &Setup,
    limits: &Limits,
    change: &dyn Fn(&mut args::CmdDispatch, &Limits, &mut Objects),
) -> Outcome {
    let mut a = args::CmdDispatch {
        group_count_x: 1,
        group_count_y: 1,
        group_count_z: 1,
    };
    change(&mut a, limits, &mut Objects::default());
    let target = s.color_target(4, vk::ImageUsageFlags::empty());
    let p = pipelines::pipelines(s, &target);
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
    let (x, y, z) = (a.group_count_x, a.group_count_y, a.group_count_z);
    record(
        s,
        |r| {
            bind(r);
            r.dispatch(x, y, z)
        },
        |r| {
            bind(r);
            // SAFETY: as in `buffer_create_info`; the command buffer is never
            // submitted.
            drop(unsafe { r.dispatch_unchecked(x, y, z) });
        },
    )
}

fn cmd_dispatch_base(
    s: &Setup,
    limits: &Limits,
    change: &dyn Fn(&mut args::CmdDispatchBase, &Limits, &mut Objects),
) -> Outcome {
    let mut a = args::CmdDispatchBase {
        base_group_x: 0,
        base_group_y: 0,
        base_group_z: 0,
        // Two groups each way: a base group that breaks a sum's rule alone (the
        // count's limit less one) then stays below the limit itself.
        group_count_x: 2,
        group_count_y: 2,
        group_count_z: 2,
    };
    change(&mut a, limits, &mut Objects::default());
    let target = s.color_target(4, vk::ImageUsageFlags::empty());
    let p = pipelines::pipelines(s, &target);
    // A pipeline made for base groups, so that a case's base group breaks only its
    // rule (VUID-vkCmdDispatchBase-baseGroupX-00427 asks for the flag).
    let stage = tuff::PipelineShaderStageCreateInfo::new(c"main")
        .stage(vk::ShaderStageFlags::COMPUTE)
        .module(Some(&p.comp));
    let based = s
        .device
        .create_compute_pipeline(
            None,
            &tuff::ComputePipelineCreateInfo::new(stage, &p.compute_layout)
                .flags(vk::PipelineCreateFlags::DISPATCH_BASE),
        )
        .expect("a pipeline made for base groups");
    let bind = |r: &mut tuff::Recorder<'_, tuff::Outside>| {
        r.bind_pipeline(vk::PipelineBindPoint::COMPUTE, &based)
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
    let base = (a.base_group_x, a.base_group_y, a.base_group_z);
    let count = (a.group_count_x, a.group_count_y, a.group_count_z);
    record(
        s,
        |r| {
            bind(r);
            r.dispatch_base(base.0, base.1, base.2, count.0, count.1, count.2)
        },
        |r| {
            bind(r);
            // SAFETY: as in `buffer_create_info`; the command buffer is never
            // submitted.
            drop(unsafe {
                r.dispatch_base_unchecked(base.0, base.1, base.2, count.0, count.1, count.2)
            });
        },
    )
}

fn cmd_set_depth_bounds(
    s: &Setup,
    limits: &Limits,
    change: &dyn Fn(&mut args::CmdSetDepthBounds, &Limits, &mut Objects),
) -> Outcome {
    let mut a = args::CmdSetDepthBounds {
        min_depth_bounds: 0.0,
        max_depth_bounds: 1.0,
    };
    change(&mut a, limits, &mut Objects::default());
    let (min, max) = (a.min_depth_bounds, a.max_depth_bounds);
    record(
        s,
        |r| r.set_depth_bounds(min, max),
        // SAFETY: as in `buffer_create_info`; the command buffer is never submitted.
        |r| unsafe { r.set_depth_bounds_unchecked(min, max) },
    )
}

fn semaphore_type_create_info(
    s: &Setup,
    limits: &Limits,
    change: &dyn Fn(&mut vk::SemaphoreTypeCreateInfo<'_>, &Limits, &mut Objects),
) -> Outcome {
    let mut ty = tuff::SemaphoreTypeCreateInfo::new()
        .semaphore_type(vk::SemaphoreType::TIMELINE)
        .initial_value(1);
    // SAFETY: as in `buffer_create_info`.
    change(
        unsafe { ty.raw_values_mut() },
        limits,
        &mut Objects::default(),
    );
    let info = tuff::SemaphoreCreateInfo::new().push_next(&mut ty);
    create!(s, create_semaphore, create_semaphore_unchecked, &info)
}

fn cmd_draw_indirect_count(
    s: &Setup,
    limits: &Limits,
    change: &dyn Fn(&mut args::CmdDrawIndirectCount, &Limits, &mut Objects),
) -> Outcome {
    let mut a = args::CmdDrawIndirectCount {
        offset: 0,
        count_buffer_offset: 0,
    };
    let mut o = Objects::default();
    change(&mut a, limits, &mut o);
    let (buffer, _memory) = make_buffer(s, &o.buffer);
    let (count, _count_memory) = make_buffer(s, &o.count_buffer);
    draw(
        s,
        |r| unsafe {
            r.draw_indirect_count(&buffer, a.offset, &count, a.count_buffer_offset, 1, 16)
        },
        // SAFETY: as in `buffer_create_info`; the command buffer is never submitted.
        |r| {
            drop(unsafe {
                r.draw_indirect_count_unchecked(
                    &buffer,
                    a.offset,
                    &count,
                    a.count_buffer_offset,
                    1,
                    16,
                )
            })
        },
    )
}

fn cmd_draw_indexed_indirect_count(
    s: &Setup,
    limits: &Limits,
    change: &dyn Fn(&mut args::CmdDrawIndexedIndirectCount, &Limits, &mut Objects),
) -> Outcome {
    let mut a = args::CmdDrawIndexedIndirectCount {
        offset: 0,
        count_buffer_offset: 0,
    };
    let mut o = Objects::default();
    change(&mut a, limits, &mut o);
    let (buffer, _memory) = make_buffer(s, &o.buffer);
    let (count, _count_memory) = make_buffer(s, &o.count_buffer);
    let (indices, _index_memory) =
        pipelines::host_buffer(s, 64, vk::BufferUsageFlags::INDEX_BUFFER);
    let index = vk::IndexType::UINT32;
    draw(
        s,
        |r| {
            r.bind_index_buffer(&indices, 0, index)
                .expect("index buffer");
            unsafe {
                r.draw_indexed_indirect_count(
                    &buffer,
                    a.offset,
                    &count,
                    a.count_buffer_offset,
                    1,
                    20,
                )
            }
        },
        |r| {
            r.bind_index_buffer(&indices, 0, index)
                .expect("index buffer");
            // SAFETY: as in `buffer_create_info`; the command buffer is never
            // submitted.
            drop(unsafe {
                r.draw_indexed_indirect_count_unchecked(
                    &buffer,
                    a.offset,
                    &count,
                    a.count_buffer_offset,
                    1,
                    20,
                )
            })
        },
    )
}

fn cmd_set_line_width(
    s: &Setup,
    limits: &Limits,
    change: &dyn Fn(&mut args::CmdSetLineWidth, &Limits, &mut Objects),
) -> Outcome {
    let mut a = args::CmdSetLineWidth { line_width: 1.0 };
    change(&mut a, limits, &mut Objects::default());
    record(
        s,
        |r| r.set_line_width(a.line_width),
        // SAFETY: as in `buffer_create_info`; the command buffer is never submitted.
        |r| unsafe { r.set_line_width_unchecked(a.line_width) },
    )
}

fn cmd_set_depth_bias(
    s: &Setup,
    limits: &Limits,
    change: &dyn Fn(&mut args::CmdSetDepthBias, &Limits, &mut Objects),
) -> Outcome {
    let mut a = args::CmdSetDepthBias {
        depth_bias_constant_factor: 0.0,
        depth_bias_clamp: 0.0,
        depth_bias_slope_factor: 0.0,
    };
    change(&mut a, limits, &mut Objects::default());
    let (c, clamp, slope) = (
        a.depth_bias_constant_factor,
        a.depth_bias_clamp,
        a.depth_bias_slope_factor,
    );
    record(
        s,
        |r| r.set_depth_bias(c, clamp, slope),
        // SAFETY: as in `buffer_create_info`; the command buffer is never submitted.
        |r| unsafe { r.set_depth_bias_unchecked(c, clamp, slope) },
    )
}

fn cmd_pipeline_barrier2(
    s: &Setup,
    limits: &Limits,
    change: &dyn Fn(&mut args::CmdPipelineBarrier2, &Limits, &mut Objects),
) -> Outcome {
    change(
        &mut args::CmdPipelineBarrier2,
        limits,
        &mut Objects::default(),
    );
    let info = tuff::DependencyInfo::new();
    record(
        s,
        |r| r.pipeline_barrier2(&info),
        // SAFETY: as in `buffer_create_info`; the command buffer is never submitted.
        |r| unsafe { r.pipeline_barrier2_unchecked(&info) },
    )
}

fn cmd_set_event2(
    s: &Setup,
    limits: &Limits,
    change: &dyn Fn(&mut args::CmdSetEvent2, &Limits, &mut Objects),
) -> Outcome {
    change(
        &mut args::CmdPipelineBarrier2,
        limits,
        &mut Objects::default(),
    );
    let e = event(s);
    let info = tuff::DependencyInfo::new();
    record(
        s,
        |r| r.set_event2(&e, &info),
        // SAFETY: as in `buffer_create_info`; the command buffer is never submitted.
        |r| unsafe { r.set_event2_unchecked(&e, &info) },
    )
}

fn cmd_wait_events2(
    s: &Setup,
    limits: &Limits,
    change: &dyn Fn(&mut args::CmdWaitEvents2, &Limits, &mut Objects),
) -> Outcome {
    change(
        &mut args::CmdPipelineBarrier2,
        limits,
        &mut Objects::default(),
    );
    let e = event(s);
    let infos = [tuff::DependencyInfo::new()];
    record(
        s,
        |r| r.wait_events2(&e, &infos),
        // SAFETY: as in `buffer_create_info`; the command buffer is never submitted.
        |r| drop(unsafe { r.wait_events2_unchecked(&e, &infos) }),
    )
}

fn cmd_write_timestamp2(
    s: &Setup,
    limits: &Limits,
    change: &dyn Fn(&mut args::CmdWriteTimestamp2, &Limits, &mut Objects),
) -> Outcome {
    let mut a = args::CmdWriteTimestamp2 {
        stage: vk::PipelineStageFlags2::TRANSFER,
    };
    change(&mut a, limits, &mut Objects::default());
    let pool = timestamps(s);
    record(
        s,
        |r| {
            r.reset_query_pool(&pool, 0, 1).expect("reset");
            r.write_timestamp2(a.stage, &pool, 0)
        },
        |r| {
            r.reset_query_pool(&pool, 0, 1).expect("reset");
            // SAFETY: as in `buffer_create_info`; the command buffer is never submitted.
            unsafe { r.write_timestamp2_unchecked(a.stage, &pool, 0) }
        },
    )
}

fn create_private_data_slot(
    s: &Setup,
    limits: &Limits,
    change: &dyn Fn(&mut args::CreatePrivateDataSlot, &Limits, &mut Objects),
) -> Outcome {
    change(
        &mut args::CreatePrivateDataSlot,
        limits,
        &mut Objects::default(),
    );
    let info = tuff::PrivateDataSlotCreateInfo::new();
    create!(
        s,
        create_private_data_slot,
        create_private_data_slot_unchecked,
        &info
    )
}

/// Clears the test target's color attachment inside its render pass.
fn clear_attachments(s: &Setup, attachment: vk::ClearAttachment, rect: vk::ClearRect) -> Outcome {
    draw(
        s,
        |r| r.clear_attachments(&[attachment], &[rect]),
        // SAFETY: as in `buffer_create_info`; the command buffer is never submitted.
        |r| drop(unsafe { r.clear_attachments_unchecked(&[attachment], &[rect]) }),
    )
}

const CLEAR_COLOR: vk::ClearAttachment = vk::ClearAttachment {
    aspect_mask: vk::ImageAspectFlags::COLOR,
    color_attachment: 0,
    clear_value: vk::ClearValue {
        color: vk::ClearColorValue { float32: [0.0; 4] },
    },
};

fn cmd_clear_attachments(
    s: &Setup,
    limits: &Limits,
    change: &dyn Fn(&mut args::CmdClearAttachments, &Limits, &mut Objects),
) -> Outcome {
    let mut o = Objects::default();
    change(&mut args::CmdClearAttachments, limits, &mut o);
    clear_attachments(s, CLEAR_COLOR, o.clear_rect)
}

fn clear_attachment(
    s: &Setup,
    limits: &Limits,
    change: &dyn Fn(&mut vk::ClearAttachment, &Limits, &mut Objects),
) -> Outcome {
    let mut attachment = CLEAR_COLOR;
    let mut o = Objects::default();
    change(&mut attachment, limits, &mut o);
    clear_attachments(s, attachment, o.clear_rect)
}

/// Clears a depth image's depth aspect to `value`, with the objects' changes.
fn clear_depth(
    s: &Setup,
    a: &args::CmdClearDepthStencilImage,
    o: &Objects,
    value: vk::ClearDepthStencilValue,
) -> Outcome {
    let (image, _memory) = make_image(s, &o.image);
    let ranges = [o.image_subresource_range];
    record(
        s,
        |r| r.clear_depth_stencil_image(&image, a.image_layout, &value, &ranges),
        // SAFETY: as in `buffer_create_info`; the command buffer is never submitted.
        |r| unsafe {
            r.clear_depth_stencil_image_unchecked(&image, a.image_layout, &value, &ranges)
        },
    )
}

/// The objects of a depth clear: a D32 image cleared whole in its depth aspect.
fn depth_objects() -> Objects {
    let mut o = Objects::default();
    o.image.format = vk::Format::D32_SFLOAT;
    o.image.usage = vk::ImageUsageFlags::TRANSFER_DST;
    o.image_subresource_range.aspect_mask = vk::ImageAspectFlags::DEPTH;
    o
}

fn cmd_clear_depth_stencil_image(
    s: &Setup,
    limits: &Limits,
    change: &dyn Fn(&mut args::CmdClearDepthStencilImage, &Limits, &mut Objects),
) -> Outcome {
    let mut a = args::CmdClearDepthStencilImage {
        image_layout: vk::ImageLayout::TRANSFER_DST_OPTIMAL,
    };
    let mut o = depth_objects();
    change(&mut a, limits, &mut o);
    clear_depth(s, &a, &o, vk::ClearDepthStencilValue::default())
}

fn clear_depth_stencil_value(
    s: &Setup,
    limits: &Limits,
    change: &dyn Fn(&mut vk::ClearDepthStencilValue, &Limits, &mut Objects),
) -> Outcome {
    let a = args::CmdClearDepthStencilImage {
        image_layout: vk::ImageLayout::TRANSFER_DST_OPTIMAL,
    };
    let mut o = depth_objects();
    let mut value = vk::ClearDepthStencilValue::default();
    change(&mut value, limits, &mut o);
    clear_depth(s, &a, &o, value)
}

fn reset_query_pool(
    s: &Setup,
    limits: &Limits,
    change: &dyn Fn(&mut args::ResetQueryPool, &Limits, &mut Objects),
) -> Outcome {
    change(&mut args::ResetQueryPool, limits, &mut Objects::default());
    let pool = timestamps(s);
    let safe = s.device.reset_query_pool(&pool, 0, 1);
    let layer = under_layer(s, || {
        // SAFETY: as in `buffer_create_info`; the pool is used by no command.
        unsafe { s.device.reset_query_pool_unchecked(&pool, 0, 1) };
    });
    Outcome { safe, layer }
}

/// Begins and ends dynamic rendering to the test target's image.
fn rendering(s: &Setup, edit: &dyn Fn(&mut vk::RenderingInfo<'_>)) -> Outcome {
    let target = s.color_target(4, vk::ImageUsageFlags::empty());
    let color = [tuff::RenderingAttachmentInfo::new()
        .image_view(Some(&target.view))
        .image_layout(vk::ImageLayout::COLOR_ATTACHMENT_OPTIMAL)
        .load_op(vk::AttachmentLoadOp::CLEAR)
        .store_op(vk::AttachmentStoreOp::STORE)];
    let mut info = tuff::RenderingInfo::new()
        .render_area(vk::Rect2D {
            offset: vk::Offset2D::default(),
            extent: vk::Extent2D {
                width: 4,
                height: 4,
            },
        })
        .layer_count(1)
        .color_attachments(&color);
    // SAFETY: as in `buffer_create_info`.
    edit(unsafe { info.raw_values_mut() });
    let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let rec = cb
        .begin(&tuff::CommandBufferBeginInfo::new())
        .expect("begin");
    let rec = rec.begin_rendering(&info);
    let safe = rec.end_rendering().end();
    let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let rec = cb
        .begin(&tuff::CommandBufferBeginInfo::new())
        .expect("begin");
    let mut layer = Vec::new();
    let mut rec = Some(rec);
    let said = under_layer(s, || {
        // SAFETY: as in `buffer_create_info`; the command buffer is never submitted,
        // and is dropped unended (the layer may have skipped the begin).
        let inside = unsafe {
            rec.take()
                .expect("recorder")
                .begin_rendering_unchecked(&info)
        };
        drop(inside);
    });
    layer.extend(said);
    Outcome { safe, layer }
}

fn cmd_begin_rendering(
    s: &Setup,
    limits: &Limits,
    change: &dyn Fn(&mut args::CmdBeginRendering, &Limits, &mut Objects),
) -> Outcome {
    change(
        &mut args::CmdBeginRendering,
        limits,
        &mut Objects::default(),
    );
    rendering(s, &|_| {})
}

fn rendering_info(
    s: &Setup,
    limits: &Limits,
    change: &dyn Fn(&mut vk::RenderingInfo<'_>, &Limits, &mut Objects),
) -> Outcome {
    rendering(s, &|info| change(info, limits, &mut Objects::default()))
}
