//! The spinning teapots of `teapots`, written against raw ash: the baseline tuff is
//! measured against. It makes the same instance, device, objects and per-frame
//! commands as `teapots` does headless, and writes `teapots_ash.png`. Headless only:
//! there is no `--window`.

use anyhow::{bail, Context as _, Result};
use ash::vk;
use clap::Parser;
use std::ffi::c_void;
use std::io::Cursor;
use std::path::PathBuf;
use std::sync::Mutex;
use std::time::{Duration, Instant};
use tuff_examples::headless::COLOR_FORMAT;
use tuff_examples::image_file::write_png;
use tuff_examples::render::{DEPTH_CLEAR, DEPTH_FORMAT, FRAMES_IN_FLIGHT};
use tuff_examples::scenes::teapot_grid::{
    mesh_data, vertex_input, CameraBlock, Layout, TeapotBlock,
};
use tuff_examples::spirv;

/// Renders a grid of spinning teapots through raw ash, headless.
#[derive(Parser)]
struct Args {
    /// How many teapots, 1 to 10,000.
    #[arg(long, default_value_t = 100)]
    count: u32,
    /// Seeds the teapots' colors, phases and spin speeds.
    #[arg(long, default_value_t = 1)]
    seed: u64,
    /// Instead of the grid, two identical teapots 10,000 units away, 0.05 % apart in
    /// depth: green in front, red behind. Any red pixel is z-fighting.
    #[arg(long)]
    depth_probe: bool,
    /// Where the PNG goes.
    #[arg(long, default_value = "teapots_ash.png")]
    out: PathBuf,
    /// Image width in pixels.
    #[arg(long, default_value_t = 512)]
    width: u32,
    /// Image height in pixels.
    #[arg(long, default_value_t = 512)]
    height: u32,
    /// Frames to render; the PNG is the last one.
    #[arg(long, default_value_t = 1)]
    frames: u32,
    /// Turn on VK_LAYER_KHRONOS_validation with synchronization validation; any
    /// warning or error it reports fails the run.
    #[arg(long)]
    validate: bool,
}

/// The background color.
const CLEAR_COLOR: [f32; 4] = [0.02, 0.02, 0.04, 1.0];

/// What the validation layer reported.
static MESSAGES: Mutex<Vec<String>> = Mutex::new(Vec::new());

/// Keeps every message the validation layer sends.
unsafe extern "system" fn on_message(
    severity: vk::DebugUtilsMessageSeverityFlagsEXT,
    _types: vk::DebugUtilsMessageTypeFlagsEXT,
    data: *const vk::DebugUtilsMessengerCallbackDataEXT<'_>,
    _user: *mut c_void,
) -> vk::Bool32 {
    // SAFETY: the layer passes null or valid callback data, whose message is null or a
    // NUL-terminated string, for the duration of the call.
    let text = unsafe { data.as_ref().and_then(|d| d.message_as_c_str()) }
        .map_or_else(|| "<no message>".into(), |m| m.to_string_lossy());
    if let Ok(mut messages) = MESSAGES.lock() {
        messages.push(format!("{severity:?}: {text}"));
    }
    vk::FALSE
}

fn main() -> std::process::ExitCode {
    let args = Args::parse();
    tuff_examples::exit(|| run(&args))
}

/// Renders as `args` say and fails on any message of the validation layer.
fn run(args: &Args) -> Result<()> {
    let layout = if args.depth_probe {
        Layout::depth_probe()
    } else {
        Layout::grid(args.count, args.seed)?
    };
    if args.width == 0 || args.height == 0 {
        bail!(
            "cannot render a {}x{} image: both sides must be at least 1",
            args.width,
            args.height
        );
    }
    if args.validate {
        // Read by the layer when the instance is created; no other thread runs yet.
        std::env::set_var(
            "VK_LAYER_ENABLES",
            "VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT",
        );
    }
    // SAFETY: the Vulkan loader is a system library whose initialisation has no
    // preconditions; the entry outlives the instance.
    let entry =
        unsafe { ash::Entry::load() }.context("cannot load the Vulkan loader (libvulkan1)")?;
    let app = vk::ApplicationInfo::default().api_version(vk::API_VERSION_1_3);
    let mut messenger_info = vk::DebugUtilsMessengerCreateInfoEXT::default()
        .message_severity(
            vk::DebugUtilsMessageSeverityFlagsEXT::WARNING
                | vk::DebugUtilsMessageSeverityFlagsEXT::ERROR,
        )
        .message_type(
            vk::DebugUtilsMessageTypeFlagsEXT::VALIDATION
                | vk::DebugUtilsMessageTypeFlagsEXT::PERFORMANCE
                | vk::DebugUtilsMessageTypeFlagsEXT::GENERAL,
        )
        .pfn_user_callback(Some(on_message));
    let layers = [c"VK_LAYER_KHRONOS_validation".as_ptr()];
    let extensions = [ash::ext::debug_utils::NAME.as_ptr()];
    let mut info = vk::InstanceCreateInfo::default().application_info(&app);
    if args.validate {
        info = info
            .enabled_layer_names(&layers)
            .enabled_extension_names(&extensions)
            .push_next(&mut messenger_info);
    }
    // SAFETY: the create info and everything it points at live across the call.
    let instance = unsafe { entry.create_instance(&info, None) }.context(if args.validate {
        "cannot create a Vulkan instance with VK_LAYER_KHRONOS_validation and \
         VK_EXT_debug_utils (apt-get install vulkan-validationlayers)"
    } else {
        "cannot create a Vulkan instance"
    })?;
    let debug_utils = ash::ext::debug_utils::Instance::new(&entry, &instance);
    let messenger = args
        .validate
        .then(|| {
            // SAFETY: the instance has VK_EXT_debug_utils enabled; the messenger is
            // destroyed before it.
            unsafe { debug_utils.create_debug_utils_messenger(&messenger_info, None) }
        })
        .transpose();
    let outcome = messenger
        .context("vkCreateDebugUtilsMessengerEXT")
        .and_then(|_| render_on_device(&instance, args, &layout));
    // SAFETY: render_on_device destroyed the device and all its objects; the messenger
    // goes before the instance, which goes last.
    unsafe {
        if let Ok(Some(messenger)) = messenger {
            debug_utils.destroy_debug_utils_messenger(messenger, None);
        }
        instance.destroy_instance(None);
    }
    outcome?;
    let messages = MESSAGES.lock().map(|m| m.clone()).unwrap_or_default();
    if !messages.is_empty() {
        for m in &messages {
            eprintln!("{m}");
        }
        bail!(
            "the validation layer reported {} message(s) (above)",
            messages.len()
        );
    }
    Ok(())
}

/// Opens the device, renders on it, destroys it, and writes the PNG.
fn render_on_device(instance: &ash::Instance, args: &Args, layout: &Layout) -> Result<()> {
    // SAFETY: the instance is live throughout; the device is destroyed below, once it
    // is idle and every object made from it is gone.
    let (name, rendered, idle) = unsafe {
        let physicals = instance
            .enumerate_physical_devices()
            .context("vkEnumeratePhysicalDevices")?;
        let name_of = |p| {
            instance
                .get_physical_device_properties(p)
                .device_name_as_c_str()
                .map_or_else(|_| "<unnamed>".into(), |n| n.to_string_lossy().into_owned())
        };
        // A discrete GPU first, then integrated, then anything (lavapipe is a CPU);
        // TUFF_DEVICE picks by name instead, as in the tuff scenes.
        let physical = match std::env::var("TUFF_DEVICE") {
            Ok(wanted) if !wanted.is_empty() => physicals
                .iter()
                .copied()
                .find(|&p| name_of(p).contains(&wanted))
                .with_context(|| {
                    format!("no Vulkan device's name contains TUFF_DEVICE={wanted:?}")
                })?,
            _ => physicals
                .iter()
                .copied()
                .min_by_key(
                    |&p| match instance.get_physical_device_properties(p).device_type {
                        vk::PhysicalDeviceType::DISCRETE_GPU => 0,
                        vk::PhysicalDeviceType::INTEGRATED_GPU => 1,
                        _ => 2,
                    },
                )
                .context(
                    "no Vulkan device found (for lavapipe: apt-get install mesa-vulkan-drivers)",
                )?,
        };
        let name: String = name_of(physical);
        let limits = instance.get_physical_device_properties(physical).limits;
        let largest = limits
            .max_image_dimension2_d
            .min(limits.max_framebuffer_width)
            .min(limits.max_framebuffer_height);
        if args.width > largest || args.height > largest {
            bail!(
                "cannot render a {}x{} image: \"{name}\" allows at most {largest} pixels a side",
                args.width,
                args.height
            );
        }
        let family = instance
            .get_physical_device_queue_family_properties(physical)
            .iter()
            .position(|f| f.queue_flags.contains(vk::QueueFlags::GRAPHICS))
            .with_context(|| format!("the device \"{name}\" has no graphics queue"))?
            as u32;
        let priorities = [1.0];
        let queues = [vk::DeviceQueueCreateInfo::default()
            .queue_family_index(family)
            .queue_priorities(&priorities)];
        let features = vk::PhysicalDeviceFeatures::default();
        let device = instance
            .create_device(
                physical,
                &vk::DeviceCreateInfo::default()
                    .queue_create_infos(&queues)
                    .enabled_features(&features),
                None,
            )
            .with_context(|| format!("cannot create a device on \"{name}\""))?;
        let queue = device.get_device_queue(family, 0);
        let types = instance.get_physical_device_memory_properties(physical);
        let mut objects = Objects::default();
        let rendered = render(&device, queue, family, &types, &mut objects, args, layout);
        let idle = device.device_wait_idle();
        objects.destroy(&device);
        device.destroy_device(None);
        (name, rendered, idle)
    };
    let (rgba, elapsed) = rendered?;
    idle.context("vkDeviceWaitIdle")?;
    write_png(&args.out, args.width, args.height, &rgba)?;
    let frames = args.frames.max(1);
    println!(
        "teapots_ash: wrote {} ({}x{}); {} frames in {:.3} s: {:.1} frames/s on {}",
        args.out.display(),
        args.width,
        args.height,
        frames,
        elapsed.as_secs_f64(),
        frames as f64 / elapsed.as_secs_f64().max(1e-9),
        name
    );
    Ok(())
}

/// Everything made from the device, null until made.
#[derive(Default)]
struct Objects {
    render_pass: vk::RenderPass,
    set_layout: vk::DescriptorSetLayout,
    pipeline_layout: vk::PipelineLayout,
    shaders: Vec<vk::ShaderModule>,
    pipeline: vk::Pipeline,
    descriptor_pool: vk::DescriptorPool,
    buffers: Vec<vk::Buffer>,
    images: Vec<vk::Image>,
    memories: Vec<vk::DeviceMemory>,
    views: Vec<vk::ImageView>,
    framebuffers: Vec<vk::Framebuffer>,
    command_pool: vk::CommandPool,
    fences: Vec<vk::Fence>,
}

impl Objects {
    /// Destroys everything, users before what they use (null handles are no-ops).
    ///
    /// # Safety
    ///
    /// Every object was made from `device`, which is idle.
    unsafe fn destroy(&self, device: &ash::Device) {
        // SAFETY: as the caller promises; the command pool frees its command buffers
        // and the descriptor pool its sets.
        unsafe {
            for &fence in &self.fences {
                device.destroy_fence(fence, None);
            }
            device.destroy_command_pool(self.command_pool, None);
            for &framebuffer in &self.framebuffers {
                device.destroy_framebuffer(framebuffer, None);
            }
            for &view in &self.views {
                device.destroy_image_view(view, None);
            }
            for &image in &self.images {
                device.destroy_image(image, None);
            }
            for &buffer in &self.buffers {
                device.destroy_buffer(buffer, None);
            }
            for &memory in &self.memories {
                device.free_memory(memory, None);
            }
            device.destroy_descriptor_pool(self.descriptor_pool, None);
            device.destroy_pipeline(self.pipeline, None);
            for &shader in &self.shaders {
                device.destroy_shader_module(shader, None);
            }
            device.destroy_pipeline_layout(self.pipeline_layout, None);
            device.destroy_descriptor_set_layout(self.set_layout, None);
            device.destroy_render_pass(self.render_pass, None);
        }
    }

    /// Memory for `reqs` of the first type with `flags`.
    fn allocate(
        &mut self,
        device: &ash::Device,
        types: &vk::PhysicalDeviceMemoryProperties,
        reqs: vk::MemoryRequirements,
        flags: vk::MemoryPropertyFlags,
    ) -> Result<vk::DeviceMemory> {
        let index = (0..types.memory_type_count)
            .find(|&i| {
                reqs.memory_type_bits & (1 << i) != 0
                    && types.memory_types[i as usize]
                        .property_flags
                        .contains(flags)
            })
            .with_context(|| format!("no memory type with {flags:?}"))?;
        let info = vk::MemoryAllocateInfo::default()
            .allocation_size(reqs.size)
            .memory_type_index(index);
        // SAFETY: a valid allocate info of an existing memory type.
        let memory = unsafe { device.allocate_memory(&info, None) }.context("vkAllocateMemory")?;
        self.memories.push(memory);
        Ok(memory)
    }

    /// A buffer of `size` bytes bound to host-visible, host-coherent memory of its own.
    fn buffer(
        &mut self,
        device: &ash::Device,
        types: &vk::PhysicalDeviceMemoryProperties,
        size: u64,
        usage: vk::BufferUsageFlags,
    ) -> Result<(vk::Buffer, vk::DeviceMemory)> {
        let info = vk::BufferCreateInfo::default().size(size).usage(usage);
        // SAFETY: valid create info; the memory is of a type the buffer allows, at least
        // its size, and bound once at offset 0.
        unsafe {
            let buffer = device
                .create_buffer(&info, None)
                .context("vkCreateBuffer")?;
            self.buffers.push(buffer);
            let memory = self.allocate(
                device,
                types,
                device.get_buffer_memory_requirements(buffer),
                vk::MemoryPropertyFlags::HOST_VISIBLE | vk::MemoryPropertyFlags::HOST_COHERENT,
            )?;
            device
                .bind_buffer_memory(buffer, memory, 0)
                .context("vkBindBufferMemory")?;
            Ok((buffer, memory))
        }
    }

    /// A 2D image with memory of its own, and a view of all of it.
    fn image(
        &mut self,
        device: &ash::Device,
        types: &vk::PhysicalDeviceMemoryProperties,
        extent: vk::Extent2D,
        format: vk::Format,
        usage: vk::ImageUsageFlags,
        aspect: vk::ImageAspectFlags,
    ) -> Result<(vk::Image, vk::ImageView)> {
        let info = vk::ImageCreateInfo::default()
            .image_type(vk::ImageType::TYPE_2D)
            .format(format)
            .extent(extent.into())
            .mip_levels(1)
            .array_layers(1)
            .samples(vk::SampleCountFlags::TYPE_1)
            .usage(usage);
        // SAFETY: valid create infos; the memory is of a type the image allows, at least
        // its size, and bound once at offset 0 before the view is made.
        unsafe {
            let image = device.create_image(&info, None).context("vkCreateImage")?;
            self.images.push(image);
            let memory = self.allocate(
                device,
                types,
                device.get_image_memory_requirements(image),
                vk::MemoryPropertyFlags::empty(),
            )?;
            device
                .bind_image_memory(image, memory, 0)
                .context("vkBindImageMemory")?;
            let view_info = vk::ImageViewCreateInfo::default()
                .image(image)
                .view_type(vk::ImageViewType::TYPE_2D)
                .format(format)
                .subresource_range(vk::ImageSubresourceRange {
                    aspect_mask: aspect,
                    base_mip_level: 0,
                    level_count: 1,
                    base_array_layer: 0,
                    layer_count: 1,
                });
            let view = device
                .create_image_view(&view_info, None)
                .context("vkCreateImageView")?;
            self.views.push(view);
            Ok((image, view))
        }
    }
}

/// Copies `bytes` to the start of `memory`: map, copy, unmap.
///
/// # Safety
///
/// `memory` is host-visible and host-coherent, not mapped, at least `bytes.len()`
/// long, and no pending submission uses it.
unsafe fn write(device: &ash::Device, memory: vk::DeviceMemory, bytes: &[u8]) -> Result<()> {
    // SAFETY: as the caller promises; being coherent, it needs no flush.
    unsafe {
        let ptr = device
            .map_memory(memory, 0, vk::WHOLE_SIZE, vk::MemoryMapFlags::empty())
            .context("vkMapMemory")?;
        std::ptr::copy_nonoverlapping(bytes.as_ptr(), ptr.cast::<u8>(), bytes.len());
        device.unmap_memory(memory);
    }
    Ok(())
}

/// A render pass that clears a color and a depth attachment, stores the color and
/// leaves it ready to be copied out.
fn render_pass(device: &ash::Device) -> Result<vk::RenderPass> {
    let attachments = [
        vk::AttachmentDescription {
            format: COLOR_FORMAT,
            samples: vk::SampleCountFlags::TYPE_1,
            load_op: vk::AttachmentLoadOp::CLEAR,
            store_op: vk::AttachmentStoreOp::STORE,
            stencil_load_op: vk::AttachmentLoadOp::DONT_CARE,
            stencil_store_op: vk::AttachmentStoreOp::DONT_CARE,
            initial_layout: vk::ImageLayout::UNDEFINED,
            final_layout: vk::ImageLayout::TRANSFER_SRC_OPTIMAL,
            ..Default::default()
        },
        vk::AttachmentDescription {
            format: DEPTH_FORMAT,
            samples: vk::SampleCountFlags::TYPE_1,
            load_op: vk::AttachmentLoadOp::CLEAR,
            store_op: vk::AttachmentStoreOp::DONT_CARE,
            stencil_load_op: vk::AttachmentLoadOp::DONT_CARE,
            stencil_store_op: vk::AttachmentStoreOp::DONT_CARE,
            initial_layout: vk::ImageLayout::UNDEFINED,
            final_layout: vk::ImageLayout::DEPTH_STENCIL_ATTACHMENT_OPTIMAL,
            ..Default::default()
        },
    ];
    let color = [vk::AttachmentReference {
        attachment: 0,
        layout: vk::ImageLayout::COLOR_ATTACHMENT_OPTIMAL,
    }];
    let depth = vk::AttachmentReference {
        attachment: 1,
        layout: vk::ImageLayout::DEPTH_STENCIL_ATTACHMENT_OPTIMAL,
    };
    let subpasses = [vk::SubpassDescription::default()
        .pipeline_bind_point(vk::PipelineBindPoint::GRAPHICS)
        .color_attachments(&color)
        .depth_stencil_attachment(&depth)];
    let fragment_tests =
        vk::PipelineStageFlags::EARLY_FRAGMENT_TESTS | vk::PipelineStageFlags::LATE_FRAGMENT_TESTS;
    let dependencies = [
        // The previous frame's color and depth writes and its copy come before this
        // frame's clears.
        vk::SubpassDependency {
            src_subpass: vk::SUBPASS_EXTERNAL,
            dst_subpass: 0,
            src_stage_mask: vk::PipelineStageFlags::COLOR_ATTACHMENT_OUTPUT
                | fragment_tests
                | vk::PipelineStageFlags::TRANSFER,
            dst_stage_mask: vk::PipelineStageFlags::COLOR_ATTACHMENT_OUTPUT | fragment_tests,
            src_access_mask: vk::AccessFlags::COLOR_ATTACHMENT_WRITE
                | vk::AccessFlags::DEPTH_STENCIL_ATTACHMENT_WRITE,
            dst_access_mask: vk::AccessFlags::COLOR_ATTACHMENT_WRITE
                | vk::AccessFlags::COLOR_ATTACHMENT_READ
                | vk::AccessFlags::DEPTH_STENCIL_ATTACHMENT_READ
                | vk::AccessFlags::DEPTH_STENCIL_ATTACHMENT_WRITE,
            dependency_flags: vk::DependencyFlags::empty(),
        },
        // This frame's color writes come before the copy.
        vk::SubpassDependency {
            src_subpass: 0,
            dst_subpass: vk::SUBPASS_EXTERNAL,
            src_stage_mask: vk::PipelineStageFlags::COLOR_ATTACHMENT_OUTPUT,
            dst_stage_mask: vk::PipelineStageFlags::TRANSFER,
            src_access_mask: vk::AccessFlags::COLOR_ATTACHMENT_WRITE,
            dst_access_mask: vk::AccessFlags::TRANSFER_READ,
            dependency_flags: vk::DependencyFlags::empty(),
        },
    ];
    let info = vk::RenderPassCreateInfo::default()
        .attachments(&attachments)
        .subpasses(&subpasses)
        .dependencies(&dependencies);
    // SAFETY: the create info and the arrays it points at live across the call.
    unsafe { device.create_render_pass(&info, None) }.context("vkCreateRenderPass")
}

/// The teapots' pipeline for subpass 0 of `render_pass`: dynamic viewport and
/// scissor, no culling (the teapot is not a closed surface), reversed-Z depth.
fn pipeline(
    device: &ash::Device,
    layout: vk::PipelineLayout,
    render_pass: vk::RenderPass,
    vert: vk::ShaderModule,
    frag: vk::ShaderModule,
) -> Result<vk::Pipeline> {
    let stages = [
        vk::PipelineShaderStageCreateInfo::default()
            .stage(vk::ShaderStageFlags::VERTEX)
            .module(vert)
            .name(c"main"),
        vk::PipelineShaderStageCreateInfo::default()
            .stage(vk::ShaderStageFlags::FRAGMENT)
            .module(frag)
            .name(c"main"),
    ];
    let (bindings, attributes) = vertex_input();
    let vertex_input = vk::PipelineVertexInputStateCreateInfo::default()
        .vertex_binding_descriptions(&bindings)
        .vertex_attribute_descriptions(&attributes);
    let assembly = vk::PipelineInputAssemblyStateCreateInfo::default()
        .topology(vk::PrimitiveTopology::TRIANGLE_LIST);
    let viewport = vk::PipelineViewportStateCreateInfo::default()
        .viewport_count(1)
        .scissor_count(1);
    let raster = vk::PipelineRasterizationStateCreateInfo::default()
        .polygon_mode(vk::PolygonMode::FILL)
        .cull_mode(vk::CullModeFlags::NONE)
        .front_face(vk::FrontFace::COUNTER_CLOCKWISE)
        .line_width(1.0);
    let multisample = vk::PipelineMultisampleStateCreateInfo::default()
        .rasterization_samples(vk::SampleCountFlags::TYPE_1);
    let depth = vk::PipelineDepthStencilStateCreateInfo::default()
        .depth_test_enable(true)
        .depth_write_enable(true)
        // Reversed Z: nearer is greater.
        .depth_compare_op(vk::CompareOp::GREATER);
    let blend_attachments = [vk::PipelineColorBlendAttachmentState {
        color_write_mask: vk::ColorComponentFlags::RGBA,
        ..Default::default()
    }];
    let blend = vk::PipelineColorBlendStateCreateInfo::default().attachments(&blend_attachments);
    let dynamic_states = [vk::DynamicState::VIEWPORT, vk::DynamicState::SCISSOR];
    let dynamic = vk::PipelineDynamicStateCreateInfo::default().dynamic_states(&dynamic_states);
    let info = vk::GraphicsPipelineCreateInfo::default()
        .stages(&stages)
        .vertex_input_state(&vertex_input)
        .input_assembly_state(&assembly)
        .viewport_state(&viewport)
        .rasterization_state(&raster)
        .multisample_state(&multisample)
        .depth_stencil_state(&depth)
        .color_blend_state(&blend)
        .dynamic_state(&dynamic)
        .layout(layout)
        .render_pass(render_pass)
        .subpass(0);
    // SAFETY: the create info and all it points at live across the call; the shader
    // modules, layout and render pass are live objects of `device`.
    let pipelines =
        unsafe { device.create_graphics_pipelines(vk::PipelineCache::null(), &[info], None) }
            .map_err(|(_, e)| e)
            .context("vkCreateGraphicsPipelines")?;
    pipelines
        .into_iter()
        .next()
        .context("no pipeline was created")
}

/// Makes the scene's objects into `o`, renders the frames and reads the last one
/// back: its pixels, and the time from the first recording to the last completion.
fn render(
    device: &ash::Device,
    queue: vk::Queue,
    family: u32,
    types: &vk::PhysicalDeviceMemoryProperties,
    o: &mut Objects,
    args: &Args,
    layout: &Layout,
) -> Result<(Vec<u8>, Duration)> {
    let extent = vk::Extent2D {
        width: args.width,
        height: args.height,
    };
    let area: vk::Rect2D = extent.into();
    let frames = args.frames.max(1);
    let stages = vk::ShaderStageFlags::VERTEX | vk::ShaderStageFlags::FRAGMENT;
    // SAFETY: every create info and what it points at lives across its call; each
    // object goes into `o` as soon as it is made, to be destroyed once the device is
    // idle; a slot's mapped uniform memory is written only after its fence says the
    // slot's last submission completed, and the readback only after every fence.
    unsafe {
        o.render_pass = render_pass(device)?;
        let bindings = [vk::DescriptorSetLayoutBinding::default()
            .binding(0)
            .descriptor_type(vk::DescriptorType::UNIFORM_BUFFER)
            .descriptor_count(1)
            .stage_flags(stages)];
        o.set_layout = device
            .create_descriptor_set_layout(
                &vk::DescriptorSetLayoutCreateInfo::default().bindings(&bindings),
                None,
            )
            .context("vkCreateDescriptorSetLayout")?;
        let set_layouts = [o.set_layout];
        let push = [vk::PushConstantRange {
            stage_flags: stages,
            offset: 0,
            size: size_of::<TeapotBlock>() as u32,
        }];
        o.pipeline_layout = device
            .create_pipeline_layout(
                &vk::PipelineLayoutCreateInfo::default()
                    .set_layouts(&set_layouts)
                    .push_constant_ranges(&push),
                None,
            )
            .context("vkCreatePipelineLayout")?;
        let spirv: [&[u8]; 2] = [spirv!("teapot.vert"), spirv!("teapot.frag")];
        for bytes in spirv {
            let code = ash::util::read_spv(&mut Cursor::new(bytes)).context("bad SPIR-V")?;
            let info = vk::ShaderModuleCreateInfo::default().code(&code);
            o.shaders.push(
                device
                    .create_shader_module(&info, None)
                    .context("vkCreateShaderModule")?,
            );
        }
        o.pipeline = pipeline(
            device,
            o.pipeline_layout,
            o.render_pass,
            o.shaders[0],
            o.shaders[1],
        )?;
        for shader in o.shaders.drain(..) {
            device.destroy_shader_module(shader, None);
        }

        let pool_sizes = [vk::DescriptorPoolSize {
            ty: vk::DescriptorType::UNIFORM_BUFFER,
            descriptor_count: FRAMES_IN_FLIGHT as u32,
        }];
        o.descriptor_pool = device
            .create_descriptor_pool(
                &vk::DescriptorPoolCreateInfo::default()
                    .max_sets(FRAMES_IN_FLIGHT as u32)
                    .pool_sizes(&pool_sizes),
                None,
            )
            .context("vkCreateDescriptorPool")?;
        let set_layouts = [o.set_layout; FRAMES_IN_FLIGHT];
        let sets = device
            .allocate_descriptor_sets(
                &vk::DescriptorSetAllocateInfo::default()
                    .descriptor_pool(o.descriptor_pool)
                    .set_layouts(&set_layouts),
            )
            .context("vkAllocateDescriptorSets")?;
        let camera_size = size_of::<CameraBlock>() as u64;
        let mut uniforms = Vec::new();
        for &set in &sets {
            let (buffer, memory) = o.buffer(
                device,
                types,
                camera_size,
                vk::BufferUsageFlags::UNIFORM_BUFFER,
            )?;
            let info = [vk::DescriptorBufferInfo {
                buffer,
                offset: 0,
                range: camera_size,
            }];
            let write = vk::WriteDescriptorSet::default()
                .dst_set(set)
                .descriptor_type(vk::DescriptorType::UNIFORM_BUFFER)
                .buffer_info(&info);
            device.update_descriptor_sets(&[write], &[]);
            // Mapped for the whole run, as tuff's allocator keeps it; freeing the
            // memory unmaps it.
            let ptr = device
                .map_memory(memory, 0, vk::WHOLE_SIZE, vk::MemoryMapFlags::empty())
                .context("vkMapMemory")?;
            uniforms.push(ptr.cast::<CameraBlock>());
        }

        let (flat, index_data) = mesh_data();
        let vertex_bytes: &[u8] = bytemuck::cast_slice(&flat);
        let (vertices, memory) = o.buffer(
            device,
            types,
            vertex_bytes.len() as u64,
            vk::BufferUsageFlags::VERTEX_BUFFER,
        )?;
        write(device, memory, vertex_bytes)?;
        let index_bytes: &[u8] = bytemuck::cast_slice(&index_data);
        let (indices, memory) = o.buffer(
            device,
            types,
            index_bytes.len() as u64,
            vk::BufferUsageFlags::INDEX_BUFFER,
        )?;
        write(device, memory, index_bytes)?;

        let mut images = Vec::new();
        for _ in 0..FRAMES_IN_FLIGHT {
            images.push(o.image(
                device,
                types,
                extent,
                COLOR_FORMAT,
                vk::ImageUsageFlags::COLOR_ATTACHMENT | vk::ImageUsageFlags::TRANSFER_SRC,
                vk::ImageAspectFlags::COLOR,
            )?);
        }
        // One depth buffer for every frame: the render pass orders their use.
        let (_, depth_view) = o.image(
            device,
            types,
            extent,
            DEPTH_FORMAT,
            vk::ImageUsageFlags::DEPTH_STENCIL_ATTACHMENT,
            vk::ImageAspectFlags::DEPTH,
        )?;
        for &(_, view) in &images {
            let attachments = [view, depth_view];
            let info = vk::FramebufferCreateInfo::default()
                .render_pass(o.render_pass)
                .attachments(&attachments)
                .width(extent.width)
                .height(extent.height)
                .layers(1);
            o.framebuffers.push(
                device
                    .create_framebuffer(&info, None)
                    .context("vkCreateFramebuffer")?,
            );
        }
        let bytes = u64::from(extent.width) * u64::from(extent.height) * 4;
        let (readback, readback_memory) =
            o.buffer(device, types, bytes, vk::BufferUsageFlags::TRANSFER_DST)?;

        o.command_pool = device
            .create_command_pool(
                &vk::CommandPoolCreateInfo::default()
                    .flags(vk::CommandPoolCreateFlags::RESET_COMMAND_BUFFER)
                    .queue_family_index(family),
                None,
            )
            .context("vkCreateCommandPool")?;
        let commands = device
            .allocate_command_buffers(
                &vk::CommandBufferAllocateInfo::default()
                    .command_pool(o.command_pool)
                    .level(vk::CommandBufferLevel::PRIMARY)
                    .command_buffer_count(FRAMES_IN_FLIGHT as u32),
            )
            .context("vkAllocateCommandBuffers")?;
        for _ in 0..FRAMES_IN_FLIGHT {
            let info = vk::FenceCreateInfo::default().flags(vk::FenceCreateFlags::SIGNALED);
            o.fences
                .push(device.create_fence(&info, None).context("vkCreateFence")?);
        }

        let clear = [
            vk::ClearValue {
                color: vk::ClearColorValue {
                    float32: CLEAR_COLOR,
                },
            },
            vk::ClearValue {
                depth_stencil: vk::ClearDepthStencilValue {
                    depth: DEPTH_CLEAR,
                    stencil: 0,
                },
            },
        ];
        let index_count = index_data.len() as u32;
        let start = Instant::now();
        for frame in 0..frames {
            let slot = frame as usize % FRAMES_IN_FLIGHT;
            let (cb, fence) = (commands[slot], o.fences[slot]);
            device
                .wait_for_fences(&[fence], true, u64::MAX)
                .context("vkWaitForFences")?;
            device.reset_fences(&[fence]).context("vkResetFences")?;
            let time = frame as f32 / 60.0;
            // The mapping is aligned to minMemoryMapAlignment (at least 64 bytes) and
            // coherent, so a plain store needs no flush.
            uniforms[slot].write(layout.camera(extent));

            device
                .begin_command_buffer(
                    cb,
                    &vk::CommandBufferBeginInfo::default()
                        .flags(vk::CommandBufferUsageFlags::ONE_TIME_SUBMIT),
                )
                .context("vkBeginCommandBuffer")?;
            device.cmd_begin_render_pass(
                cb,
                &vk::RenderPassBeginInfo::default()
                    .render_pass(o.render_pass)
                    .framebuffer(o.framebuffers[slot])
                    .render_area(area)
                    .clear_values(&clear),
                vk::SubpassContents::INLINE,
            );
            device.cmd_set_viewport(
                cb,
                0,
                &[vk::Viewport {
                    x: 0.0,
                    y: 0.0,
                    width: extent.width as f32,
                    height: extent.height as f32,
                    min_depth: 0.0,
                    max_depth: 1.0,
                }],
            );
            device.cmd_set_scissor(cb, 0, &[area]);
            device.cmd_bind_pipeline(cb, vk::PipelineBindPoint::GRAPHICS, o.pipeline);
            device.cmd_bind_descriptor_sets(
                cb,
                vk::PipelineBindPoint::GRAPHICS,
                o.pipeline_layout,
                0,
                &[sets[slot]],
                &[],
            );
            device.cmd_bind_vertex_buffers(cb, 0, &[vertices], &[0]);
            device.cmd_bind_index_buffer(cb, indices, 0, vk::IndexType::UINT32);
            for teapot in &layout.teapots {
                let block = teapot.block(time);
                device.cmd_push_constants(
                    cb,
                    o.pipeline_layout,
                    stages,
                    0,
                    bytemuck::bytes_of(&block),
                );
                device.cmd_draw_indexed(cb, index_count, 1, 0, 0, 0);
            }
            device.cmd_end_render_pass(cb);
            if frame + 1 == frames {
                let region = vk::BufferImageCopy {
                    image_subresource: vk::ImageSubresourceLayers {
                        aspect_mask: vk::ImageAspectFlags::COLOR,
                        mip_level: 0,
                        base_array_layer: 0,
                        layer_count: 1,
                    },
                    image_extent: extent.into(),
                    ..Default::default()
                };
                device.cmd_copy_image_to_buffer(
                    cb,
                    images[slot].0,
                    vk::ImageLayout::TRANSFER_SRC_OPTIMAL,
                    readback,
                    &[region],
                );
                // A fence wait does not make device writes visible to the host.
                let to_host = vk::BufferMemoryBarrier::default()
                    .src_access_mask(vk::AccessFlags::TRANSFER_WRITE)
                    .dst_access_mask(vk::AccessFlags::HOST_READ)
                    .src_queue_family_index(vk::QUEUE_FAMILY_IGNORED)
                    .dst_queue_family_index(vk::QUEUE_FAMILY_IGNORED)
                    .buffer(readback)
                    .offset(0)
                    .size(vk::WHOLE_SIZE);
                device.cmd_pipeline_barrier(
                    cb,
                    vk::PipelineStageFlags::TRANSFER,
                    vk::PipelineStageFlags::HOST,
                    vk::DependencyFlags::empty(),
                    &[],
                    &[to_host],
                    &[],
                );
            }
            device
                .end_command_buffer(cb)
                .context("vkEndCommandBuffer")?;
            let submit = vk::SubmitInfo::default().command_buffers(std::slice::from_ref(&cb));
            device
                .queue_submit(queue, &[submit], fence)
                .context("vkQueueSubmit")?;
        }
        device
            .wait_for_fences(&o.fences, true, u64::MAX)
            .context("vkWaitForFences")?;
        let elapsed = start.elapsed();

        let ptr = device
            .map_memory(
                readback_memory,
                0,
                vk::WHOLE_SIZE,
                vk::MemoryMapFlags::empty(),
            )
            .context("vkMapMemory")?;
        let rgba = std::slice::from_raw_parts(ptr.cast::<u8>(), bytes as usize).to_vec();
        device.unmap_memory(readback_memory);
        Ok((rgba, elapsed))
    }
}
