//! What the raw-ash scenes share: the counterpart, in raw ash, of what the tuff scenes
//! share in `gpu.rs`, `render.rs`, `pipeline.rs`, `headless.rs` and `cli.rs`, with the
//! same structure (a scene trait, optional depth, a pipeline description), so each
//! scene exists both ways and the two can be counted line for line. Headless only.
//!
//! Every object made from the device goes into [`Objects`] as soon as it is made, and
//! is destroyed once the device is idle, also when rendering failed.

use crate::gpu::Requirements;
use crate::headless::COLOR_FORMAT;
use crate::render::{View, DEPTH_CLEAR, DEPTH_FORMAT, FRAMES_IN_FLIGHT};
use anyhow::{bail, Context as _, Result};
use ash::vk;
use std::ffi::c_void;
use std::io::Cursor;
use std::path::PathBuf;
use std::sync::Mutex;
use std::time::{Duration, Instant};

/// Options every raw-ash scene takes: those of the tuff scenes, less the window.
pub use crate::cli::Headless as Common;

/// A scene: pipelines and data made for one render pass, and the draws of a frame.
pub trait Scene {
    /// The background color.
    fn clear_color(&self) -> [f32; 4];

    /// Whether the render pass has a depth attachment.
    const DEPTH: bool = true;

    /// Writes what the frame reads from memory (uniforms).
    ///
    /// # Safety
    ///
    /// The previous submission of `view.slot` has completed.
    unsafe fn update(&mut self, _view: &View) {}

    /// Records the frame's draws; viewport and scissor are set already.
    ///
    /// # Safety
    ///
    /// `cb` is recording, inside the render pass the scene was made for, on `device`.
    unsafe fn draw(&self, device: &ash::Device, cb: vk::CommandBuffer, view: &View);
}

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

/// Whether the Khronos validation layer watches a raw-ash run, and how closely.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Layer {
    /// No layer.
    Off,
    /// VK_LAYER_KHRONOS_validation with its default checks.
    On,
    /// The layer with synchronization validation too.
    Sync,
}

/// Renders the scene `make` builds as `common` says, writes the PNG, prints the frame
/// rate, and fails on any message of the validation layer.
pub fn run<S: Scene>(
    common: &Common,
    req: Requirements,
    make: impl FnOnce(&ash::Device, &mut Objects, vk::RenderPass) -> Result<S>,
) -> Result<()> {
    run_with(common, req, |vulkan| {
        let (rgba, elapsed) = render(vulkan, common, make)?;
        Ok((rgba, elapsed, String::new()))
    })
}

/// What [`run`] does around the rendering: opens the device (with the layer and its
/// synchronization validation when `common` asks), checks the image size, calls
/// `render` for the last frame's pixels, the time taken and a note for the summary
/// line, then writes the PNG, prints that line, and fails on any message of the layer.
pub fn run_with(
    common: &Common,
    req: Requirements,
    render: impl FnOnce(&mut Vulkan) -> Result<(Vec<u8>, Duration, String)>,
) -> Result<()> {
    let extent = vk::Extent2D {
        width: common.width,
        height: common.height,
    };
    crate::render::check_nonempty(extent)?;
    let layer = if common.validate {
        Layer::Sync
    } else {
        Layer::Off
    };
    let mut vulkan = Vulkan::open(req, layer, false)?;
    crate::render::check_limits(extent, &vulkan.properties().limits, &vulkan.name)?;
    let rendered = render(&mut vulkan);
    let name = vulkan.name.clone();
    let messages = vulkan.finish();
    let (rgba, elapsed, note) = rendered?;
    let messages = messages?;
    if !messages.is_empty() {
        for m in &messages {
            eprintln!("{m}");
        }
        bail!(
            "the validation layer reported {} message(s) (above)",
            messages.len()
        );
    }
    let out = common
        .out
        .clone()
        .unwrap_or_else(|| PathBuf::from(format!("{}.png", req.scene)));
    crate::image_file::write_png(&out, common.width, common.height, &rgba)?;
    let frames = common.frames.max(1);
    println!(
        "{}: wrote {} ({}x{}){note}; {} frames in {:.3} s: {:.1} frames/s on {}",
        req.scene,
        out.display(),
        common.width,
        common.height,
        frames,
        elapsed.as_secs_f64(),
        frames as f64 / elapsed.as_secs_f64().max(1e-9),
        name
    );
    Ok(())
}

/// An instance (with the layer and a messenger when asked), a device with one graphics
/// queue, and everything made from it in [`Objects`]. Dropping it (or
/// [`Vulkan::finish`]) waits for the device to be idle and destroys everything, users
/// before what they use.
pub struct Vulkan {
    /// The loader's entry points.
    pub entry: ash::Entry,
    /// The instance.
    pub instance: ash::Instance,
    debug_utils: ash::ext::debug_utils::Instance,
    messenger: Option<vk::DebugUtilsMessengerEXT>,
    /// The physical device.
    pub physical: vk::PhysicalDevice,
    /// The device.
    pub device: ash::Device,
    /// The graphics queue.
    pub queue: vk::Queue,
    /// The queue's family.
    pub family: u32,
    /// The physical device's name.
    pub name: String,
    /// Everything made from the device, destroyed with it.
    pub objects: Objects,
    destroyed: bool,
}

impl Vulkan {
    /// Opens the loader, an instance and a device for a scene that needs `req`, with
    /// the layer as `layer` says; `window` adds the surface and swapchain extensions
    /// (X11). The device is the one `TUFF_DEVICE` names, or else a discrete GPU, an
    /// integrated one, anything, in that order, as in the tuff scenes.
    pub fn open(req: Requirements, layer: Layer, window: bool) -> Result<Vulkan> {
        if layer != Layer::Off {
            // Read by the layer when the instance is created; no other thread runs yet.
            let enables = if layer == Layer::Sync {
                "VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT"
            } else {
                ""
            };
            std::env::set_var("VK_LAYER_ENABLES", enables);
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
        let mut extensions = Vec::new();
        if layer != Layer::Off {
            extensions.push(ash::ext::debug_utils::NAME.as_ptr());
        }
        if window {
            extensions.push(ash::khr::surface::NAME.as_ptr());
            extensions.push(ash::khr::xlib_surface::NAME.as_ptr());
        }
        let mut info = vk::InstanceCreateInfo::default()
            .application_info(&app)
            .enabled_extension_names(&extensions);
        if layer != Layer::Off {
            info = info
                .enabled_layer_names(&layers)
                .push_next(&mut messenger_info);
        }
        // SAFETY: the create info and everything it points at live across the call.
        let instance =
            unsafe { entry.create_instance(&info, None) }.context(if layer != Layer::Off {
                "cannot create a Vulkan instance with VK_LAYER_KHRONOS_validation and \
                 VK_EXT_debug_utils (apt-get install vulkan-validationlayers)"
            } else {
                "cannot create a Vulkan instance"
            })?;
        let debug_utils = ash::ext::debug_utils::Instance::new(&entry, &instance);
        let messenger = if layer != Layer::Off {
            // SAFETY: the instance has VK_EXT_debug_utils enabled; the messenger is
            // destroyed before it.
            unsafe { debug_utils.create_debug_utils_messenger(&messenger_info, None) }
                .context("vkCreateDebugUtilsMessengerEXT")
                .map(Some)
        } else {
            Ok(None)
        };
        let opened = messenger
            .as_ref()
            .map_err(|e| anyhow::anyhow!("{e:#}"))
            .and_then(|_| open_device(&instance, req, window));
        match (messenger, opened) {
            (Ok(messenger), Ok((physical, device, family, name))) => {
                // SAFETY: the device is live and has a queue of `family` (its create
                // info asked for one); the physical device is the instance's.
                let (queue, types) = unsafe {
                    (
                        device.get_device_queue(family, 0),
                        instance.get_physical_device_memory_properties(physical),
                    )
                };
                Ok(Vulkan {
                    entry,
                    instance,
                    debug_utils,
                    messenger,
                    physical,
                    device,
                    queue,
                    family,
                    name,
                    objects: Objects {
                        types,
                        ..Default::default()
                    },
                    destroyed: false,
                })
            }
            (messenger, opened) => {
                // SAFETY: no device was made; the messenger goes before the instance.
                unsafe {
                    if let Ok(Some(m)) = messenger {
                        debug_utils.destroy_debug_utils_messenger(m, None);
                    }
                    instance.destroy_instance(None);
                }
                Err(opened.err().unwrap_or_else(|| anyhow::anyhow!("no device")))
            }
        }
    }

    /// The physical device's properties.
    pub fn properties(&self) -> vk::PhysicalDeviceProperties {
        // SAFETY: the physical device comes from this live instance.
        unsafe { self.instance.get_physical_device_properties(self.physical) }
    }

    /// The driver's name and version string (`VkPhysicalDeviceDriverProperties`).
    pub fn driver(&self) -> String {
        let mut driver = vk::PhysicalDeviceDriverProperties::default();
        let mut properties = vk::PhysicalDeviceProperties2::default().push_next(&mut driver);
        // SAFETY: a Vulkan 1.3 instance; the chain lives across the call.
        unsafe {
            self.instance
                .get_physical_device_properties2(self.physical, &mut properties)
        };
        let name = driver.driver_name_as_c_str().unwrap_or_default();
        let info = driver.driver_info_as_c_str().unwrap_or_default();
        format!("{} {}", name.to_string_lossy(), info.to_string_lossy())
    }

    /// Waits for the device, destroys everything, and returns what the layer reported
    /// over the whole run (an error if the device could not be waited for).
    pub fn finish(mut self) -> Result<Vec<String>> {
        let idle = self.destroy();
        idle?;
        Ok(MESSAGES.lock().map(|m| m.clone()).unwrap_or_default())
    }

    fn destroy(&mut self) -> Result<()> {
        if self.destroyed {
            return Ok(());
        }
        self.destroyed = true;
        // SAFETY: every object in `objects` was made from the device, which is idle
        // after the wait (or lost); the messenger goes before the instance, which goes
        // last; `destroyed` keeps this from running twice.
        unsafe {
            let idle = self.device.device_wait_idle().context("vkDeviceWaitIdle");
            self.objects.destroy(&self.device);
            self.device.destroy_device(None);
            if let Some(messenger) = self.messenger.take() {
                self.debug_utils
                    .destroy_debug_utils_messenger(messenger, None);
            }
            self.instance.destroy_instance(None);
            idle
        }
    }
}

impl Drop for Vulkan {
    fn drop(&mut self) {
        // An error here was already a failed run; `finish` reports it otherwise.
        let _ = self.destroy();
    }
}

/// Picks the physical device (`TUFF_DEVICE` by name, or else a discrete GPU, an
/// integrated one, anything) and makes a device with one graphics queue.
fn open_device(
    instance: &ash::Instance,
    req: Requirements,
    window: bool,
) -> Result<(vk::PhysicalDevice, ash::Device, u32, String)> {
    // SAFETY: the instance is live; the caller destroys the device made here once it
    // is idle and every object made from it is gone.
    unsafe {
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
        let features = vk::PhysicalDeviceFeatures::default()
            .tessellation_shader(req.tessellation_shader)
            .fill_mode_non_solid(req.fill_mode_non_solid)
            .robust_buffer_access(req.robust_buffer_access);
        let swapchain = [ash::khr::swapchain::NAME.as_ptr()];
        let mut info = vk::DeviceCreateInfo::default()
            .queue_create_infos(&queues)
            .enabled_features(&features);
        if window {
            info = info.enabled_extension_names(&swapchain);
        }
        let device = instance
            .create_device(physical, &info, None)
            .with_context(|| {
                format!(
                    "cannot create a device on \"{name}\" for the {} scene",
                    req.scene
                )
            })?;
        Ok((physical, device, family, name))
    }
}
/// Everything made from the device, null until made, and the device's memory types.
#[derive(Default)]
pub struct Objects {
    pub(crate) types: vk::PhysicalDeviceMemoryProperties,
    /// The scene's render pass.
    pub render_pass: vk::RenderPass,
    /// Descriptor set layouts, which the scenes make themselves.
    pub set_layouts: Vec<vk::DescriptorSetLayout>,
    pipeline_layouts: Vec<vk::PipelineLayout>,
    shaders: Vec<vk::ShaderModule>,
    pipelines: Vec<vk::Pipeline>,
    /// Descriptor pools, which free their sets.
    pub descriptor_pools: Vec<vk::DescriptorPool>,
    buffers: Vec<vk::Buffer>,
    images: Vec<vk::Image>,
    memories: Vec<vk::DeviceMemory>,
    views: Vec<vk::ImageView>,
    /// The scene's framebuffers.
    pub framebuffers: Vec<vk::Framebuffer>,
    pub(crate) command_pool: vk::CommandPool,
    /// Command pools of the worker threads' secondaries.
    pub worker_pools: Vec<vk::CommandPool>,
    pub(crate) fences: Vec<vk::Fence>,
    pub(crate) semaphores: Vec<vk::Semaphore>,
}
impl Objects {
    /// Destroys everything, users before what they use (null handles are no-ops).
    ///
    /// # Safety
    ///
    /// Every object was made from `device`, which is idle.
    unsafe fn destroy(&self, device: &ash::Device) {
        // SAFETY: as the caller promises; the command pool frees its command buffers
        // and the descriptor pools their sets.
        unsafe {
            for &fence in &self.fences {
                device.destroy_fence(fence, None);
            }
            for &semaphore in &self.semaphores {
                device.destroy_semaphore(semaphore, None);
            }
            device.destroy_command_pool(self.command_pool, None);
            for &pool in &self.worker_pools {
                device.destroy_command_pool(pool, None);
            }
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
            for &pool in &self.descriptor_pools {
                device.destroy_descriptor_pool(pool, None);
            }
            for &pipeline in &self.pipelines {
                device.destroy_pipeline(pipeline, None);
            }
            for &shader in &self.shaders {
                device.destroy_shader_module(shader, None);
            }
            for &layout in &self.pipeline_layouts {
                device.destroy_pipeline_layout(layout, None);
            }
            for &layout in &self.set_layouts {
                device.destroy_descriptor_set_layout(layout, None);
            }
            device.destroy_render_pass(self.render_pass, None);
        }
    }

    /// Memory for `reqs` of the first type with the first of `wanted` (most preferred
    /// first) that some allowed type has.
    fn allocate(
        &mut self,
        device: &ash::Device,
        reqs: vk::MemoryRequirements,
        wanted: &[vk::MemoryPropertyFlags],
    ) -> Result<vk::DeviceMemory> {
        let types = &self.types;
        let index = wanted
            .iter()
            .find_map(|&flags| {
                (0..types.memory_type_count).find(|&i| {
                    reqs.memory_type_bits & (1 << i) != 0
                        && types.memory_types[i as usize]
                            .property_flags
                            .contains(flags)
                })
            })
            .with_context(|| format!("no memory type with any of {wanted:?}"))?;
        let info = vk::MemoryAllocateInfo::default()
            .allocation_size(reqs.size)
            .memory_type_index(index);
        // SAFETY: a valid allocate info of an existing memory type.
        let memory = unsafe { device.allocate_memory(&info, None) }.context("vkAllocateMemory")?;
        self.memories.push(memory);
        Ok(memory)
    }

    /// A buffer of `size` bytes bound to host-visible, host-coherent memory of its own,
    /// `preferred` too where the device has such memory: device-local for what the
    /// device reads, host-cached for what the host reads back (as tuff's allocator
    /// places its Upload and Readback buffers).
    pub fn buffer(
        &mut self,
        device: &ash::Device,
        size: u64,
        usage: vk::BufferUsageFlags,
        preferred: vk::MemoryPropertyFlags,
    ) -> Result<(vk::Buffer, vk::DeviceMemory)> {
        let host = vk::MemoryPropertyFlags::HOST_VISIBLE | vk::MemoryPropertyFlags::HOST_COHERENT;
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
                device.get_buffer_memory_requirements(buffer),
                &[host | preferred, host],
            )?;
            device
                .bind_buffer_memory(buffer, memory, 0)
                .context("vkBindBufferMemory")?;
            Ok((buffer, memory))
        }
    }

    /// A buffer holding `data`: map, copy, unmap.
    pub fn buffer_with<T: bytemuck::Pod>(
        &mut self,
        device: &ash::Device,
        usage: vk::BufferUsageFlags,
        data: &[T],
    ) -> Result<vk::Buffer> {
        let bytes: &[u8] = bytemuck::cast_slice(data);
        let size = bytes.len().max(1) as u64;
        let local = vk::MemoryPropertyFlags::DEVICE_LOCAL;
        let (buffer, memory) = self.buffer(device, size, usage, local)?;
        // SAFETY: the memory is host-visible, host-coherent (no flush needed), not
        // mapped, at least `bytes.len()` long, and no submission uses it yet.
        unsafe {
            let ptr = device
                .map_memory(memory, 0, vk::WHOLE_SIZE, vk::MemoryMapFlags::empty())
                .context("vkMapMemory")?;
            std::ptr::copy_nonoverlapping(bytes.as_ptr(), ptr.cast::<u8>(), bytes.len());
            device.unmap_memory(memory);
        }
        Ok(buffer)
    }

    /// A 2D image with memory of its own, and a view of all of it.
    pub fn image(
        &mut self,
        device: &ash::Device,
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
                device.get_image_memory_requirements(image),
                &[vk::MemoryPropertyFlags::DEVICE_LOCAL],
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

    /// A shader module from SPIR-V bytes.
    pub fn shader(&mut self, device: &ash::Device, spirv: &[u8]) -> Result<vk::ShaderModule> {
        let code = ash::util::read_spv(&mut Cursor::new(spirv)).context("bad SPIR-V")?;
        let info = vk::ShaderModuleCreateInfo::default().code(&code);
        // SAFETY: the create info and the code live across the call.
        let shader =
            unsafe { device.create_shader_module(&info, None) }.context("vkCreateShaderModule")?;
        self.shaders.push(shader);
        Ok(shader)
    }

    /// A pipeline layout with `set_layouts` and one push-constant range of `push_size`
    /// bytes (none when 0) visible to `push_stages`.
    pub fn pipeline_layout(
        &mut self,
        device: &ash::Device,
        set_layouts: &[vk::DescriptorSetLayout],
        push_stages: vk::ShaderStageFlags,
        push_size: u32,
    ) -> Result<vk::PipelineLayout> {
        let push = [vk::PushConstantRange {
            stage_flags: push_stages,
            offset: 0,
            size: push_size,
        }];
        let mut info = vk::PipelineLayoutCreateInfo::default().set_layouts(set_layouts);
        if push_size > 0 {
            info = info.push_constant_ranges(&push);
        }
        // SAFETY: the create info and what it points at live across the call; the set
        // layouts are live objects of `device`.
        let layout = unsafe { device.create_pipeline_layout(&info, None) }
            .context("vkCreatePipelineLayout")?;
        self.pipeline_layouts.push(layout);
        Ok(layout)
    }
}

/// What differs between the scenes' pipelines.
pub struct PipelineDesc<'a> {
    /// Shader stages, each with its module (entry point `main`).
    pub stages: &'a [(vk::ShaderStageFlags, vk::ShaderModule)],
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

impl Objects {
    /// A graphics pipeline for a subpass of `render_pass`, with dynamic viewport and
    /// scissor and no culling (the teapot is not a closed surface).
    pub fn pipeline(
        &mut self,
        device: &ash::Device,
        layout: vk::PipelineLayout,
        render_pass: vk::RenderPass,
        desc: &PipelineDesc<'_>,
    ) -> Result<vk::Pipeline> {
        let stages: Vec<_> = desc
            .stages
            .iter()
            .map(|&(stage, module)| {
                vk::PipelineShaderStageCreateInfo::default()
                    .stage(stage)
                    .module(module)
                    .name(c"main")
            })
            .collect();
        let vertex_input = vk::PipelineVertexInputStateCreateInfo::default()
            .vertex_binding_descriptions(desc.bindings)
            .vertex_attribute_descriptions(desc.attributes);
        let assembly = vk::PipelineInputAssemblyStateCreateInfo::default().topology(desc.topology);
        let tessellation = vk::PipelineTessellationStateCreateInfo::default()
            .patch_control_points(desc.patch_control_points);
        let viewport = vk::PipelineViewportStateCreateInfo::default()
            .viewport_count(1)
            .scissor_count(1);
        let raster = vk::PipelineRasterizationStateCreateInfo::default()
            .polygon_mode(desc.polygon_mode)
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
        let blend_attachments = vec![
            vk::PipelineColorBlendAttachmentState {
                color_write_mask: vk::ColorComponentFlags::RGBA,
                ..Default::default()
            };
            desc.colors as usize
        ];
        let blend =
            vk::PipelineColorBlendStateCreateInfo::default().attachments(&blend_attachments);
        let dynamic_states = [vk::DynamicState::VIEWPORT, vk::DynamicState::SCISSOR];
        let dynamic = vk::PipelineDynamicStateCreateInfo::default().dynamic_states(&dynamic_states);
        let mut info = vk::GraphicsPipelineCreateInfo::default()
            .stages(&stages)
            .vertex_input_state(&vertex_input)
            .input_assembly_state(&assembly)
            .viewport_state(&viewport)
            .rasterization_state(&raster)
            .multisample_state(&multisample)
            .color_blend_state(&blend)
            .dynamic_state(&dynamic)
            .layout(layout)
            .render_pass(render_pass)
            .subpass(desc.subpass);
        if desc.patch_control_points > 0 {
            info = info.tessellation_state(&tessellation);
        }
        if desc.depth {
            info = info.depth_stencil_state(&depth);
        }
        // SAFETY: the create info and all it points at live across the call; the shader
        // modules, layout and render pass are live objects of `device`.
        let pipelines =
            unsafe { device.create_graphics_pipelines(vk::PipelineCache::null(), &[info], None) }
                .map_err(|(_, e)| e)
                .context("vkCreateGraphicsPipelines")?;
        self.pipelines.extend(&pipelines);
        pipelines
            .into_iter()
            .next()
            .context("no pipeline was created")
    }
}

/// A render pass that clears a color attachment of `format` (and a depth attachment),
/// stores the color and leaves it in `final_layout`: ready to be copied out, or
/// presented. The same dependencies serve both, as in the tuff scenes' render pass.
pub fn render_pass(
    device: &ash::Device,
    format: vk::Format,
    depth: bool,
    final_layout: vk::ImageLayout,
) -> Result<vk::RenderPass> {
    let mut attachments = vec![vk::AttachmentDescription {
        format,
        samples: vk::SampleCountFlags::TYPE_1,
        load_op: vk::AttachmentLoadOp::CLEAR,
        store_op: vk::AttachmentStoreOp::STORE,
        stencil_load_op: vk::AttachmentLoadOp::DONT_CARE,
        stencil_store_op: vk::AttachmentStoreOp::DONT_CARE,
        initial_layout: vk::ImageLayout::UNDEFINED,
        final_layout,
        ..Default::default()
    }];
    if depth {
        attachments.push(vk::AttachmentDescription {
            format: DEPTH_FORMAT,
            samples: vk::SampleCountFlags::TYPE_1,
            load_op: vk::AttachmentLoadOp::CLEAR,
            store_op: vk::AttachmentStoreOp::DONT_CARE,
            stencil_load_op: vk::AttachmentLoadOp::DONT_CARE,
            stencil_store_op: vk::AttachmentStoreOp::DONT_CARE,
            initial_layout: vk::ImageLayout::UNDEFINED,
            final_layout: vk::ImageLayout::DEPTH_STENCIL_ATTACHMENT_OPTIMAL,
            ..Default::default()
        });
    }
    let color = [vk::AttachmentReference {
        attachment: 0,
        layout: vk::ImageLayout::COLOR_ATTACHMENT_OPTIMAL,
    }];
    let depth_ref = vk::AttachmentReference {
        attachment: 1,
        layout: vk::ImageLayout::DEPTH_STENCIL_ATTACHMENT_OPTIMAL,
    };
    let mut subpass = vk::SubpassDescription::default()
        .pipeline_bind_point(vk::PipelineBindPoint::GRAPHICS)
        .color_attachments(&color);
    if depth {
        subpass = subpass.depth_stencil_attachment(&depth_ref);
    }
    let subpasses = [subpass];
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

/// Makes the render pass, the scene and the targets into `o`, renders the frames and
/// reads the last one back: its pixels, and the time from the first recording to the
/// last completion.
fn render<S: Scene>(
    vulkan: &mut Vulkan,
    common: &Common,
    make: impl FnOnce(&ash::Device, &mut Objects, vk::RenderPass) -> Result<S>,
) -> Result<(Vec<u8>, Duration)> {
    let slots = frame_slots(vulkan, FRAMES_IN_FLIGHT)?;
    let Vulkan {
        device,
        queue,
        objects: o,
        ..
    } = vulkan;
    let queue = *queue;
    let extent = vk::Extent2D {
        width: common.width,
        height: common.height,
    };
    let frames = common.frames.max(1);
    let pass = render_pass(
        device,
        COLOR_FORMAT,
        S::DEPTH,
        vk::ImageLayout::TRANSFER_SRC_OPTIMAL,
    )?;
    o.render_pass = pass;
    let mut scene = make(device, o, pass)?;
    // SAFETY: every create info and what it points at lives across its call; each
    // object goes into `o` as soon as it is made, to be destroyed once the device is
    // idle; a slot is updated and recorded only after its fence says the slot's last
    // submission completed, and the readback is read only after every fence.
    unsafe {
        let mut images = Vec::new();
        for _ in 0..FRAMES_IN_FLIGHT {
            images.push(o.image(
                device,
                extent,
                COLOR_FORMAT,
                vk::ImageUsageFlags::COLOR_ATTACHMENT | vk::ImageUsageFlags::TRANSFER_SRC,
                vk::ImageAspectFlags::COLOR,
            )?);
        }
        // One depth buffer for every frame: the render pass orders their use.
        let depth_view = if S::DEPTH {
            let usage = vk::ImageUsageFlags::DEPTH_STENCIL_ATTACHMENT;
            let aspect = vk::ImageAspectFlags::DEPTH;
            Some(o.image(device, extent, DEPTH_FORMAT, usage, aspect)?.1)
        } else {
            None
        };
        for &(_, view) in &images {
            let attachments: Vec<_> = [Some(view), depth_view].into_iter().flatten().collect();
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
        let cached = vk::MemoryPropertyFlags::HOST_CACHED;
        let (readback, readback_memory) =
            o.buffer(device, bytes, vk::BufferUsageFlags::TRANSFER_DST, cached)?;

        let start = Instant::now();
        for frame in 0..frames {
            let slot = frame as usize % FRAMES_IN_FLIGHT;
            let (cb, fence) = slots[slot];
            device
                .wait_for_fences(&[fence], true, u64::MAX)
                .context("vkWaitForFences")?;
            device.reset_fences(&[fence]).context("vkResetFences")?;
            let view = View {
                extent,
                time: frame as f32 / 60.0,
                slot,
            };
            scene.update(&view);
            let last = frame + 1 == frames;
            let copy = last.then_some((images[slot].0, readback));
            record_frame(
                device,
                cb,
                o.render_pass,
                o.framebuffers[slot],
                &scene,
                &view,
                copy,
            )?;
            let submit = vk::SubmitInfo::default().command_buffers(std::slice::from_ref(&cb));
            device
                .queue_submit(queue, &[submit], fence)
                .context("vkQueueSubmit")?;
        }
        device
            .wait_for_fences(&o.fences, true, u64::MAX)
            .context("vkWaitForFences")?;
        let elapsed = start.elapsed();

        let rgba = read_memory(device, readback_memory, bytes as usize)?;
        Ok((rgba, elapsed))
    }
}

/// The first `bytes` bytes of `memory`: mapped, copied, unmapped.
///
/// # Safety
///
/// `memory` is host-visible and host-coherent, not mapped, at least `bytes` long,
/// and no device write to it is pending or unmade visible to the host.
pub unsafe fn read_memory(
    device: &ash::Device,
    memory: vk::DeviceMemory,
    bytes: usize,
) -> Result<Vec<u8>> {
    // SAFETY: as the caller promises; the mapping is read only while mapped.
    unsafe {
        let ptr = device
            .map_memory(memory, 0, vk::WHOLE_SIZE, vk::MemoryMapFlags::empty())
            .context("vkMapMemory")?;
        let bytes = std::slice::from_raw_parts(ptr.cast::<u8>(), bytes).to_vec();
        device.unmap_memory(memory);
        Ok(bytes)
    }
}

/// `count` primary command buffers of the objects' pool (made here if there is none
/// yet, resettable, of the device's queue family), each with a fence created
/// signalled, kept by the objects.
pub fn frame_slots(
    vulkan: &mut Vulkan,
    count: usize,
) -> Result<Vec<(vk::CommandBuffer, vk::Fence)>> {
    let (device, o) = (&vulkan.device, &mut vulkan.objects);
    // SAFETY: valid create infos; every object goes into `o`, destroyed once the
    // device is idle.
    unsafe {
        if o.command_pool == vk::CommandPool::null() {
            o.command_pool = device
                .create_command_pool(
                    &vk::CommandPoolCreateInfo::default()
                        .flags(vk::CommandPoolCreateFlags::RESET_COMMAND_BUFFER)
                        .queue_family_index(vulkan.family),
                    None,
                )
                .context("vkCreateCommandPool")?;
        }
        let buffers = device
            .allocate_command_buffers(
                &vk::CommandBufferAllocateInfo::default()
                    .command_pool(o.command_pool)
                    .level(vk::CommandBufferLevel::PRIMARY)
                    .command_buffer_count(count as u32),
            )
            .context("vkAllocateCommandBuffers")?;
        let mut slots = Vec::new();
        for cb in buffers {
            let info = vk::FenceCreateInfo::default().flags(vk::FenceCreateFlags::SIGNALED);
            let fence = device.create_fence(&info, None).context("vkCreateFence")?;
            o.fences.push(fence);
            slots.push((cb, fence));
        }
        Ok(slots)
    }
}

/// Records a frame of `scene` into `cb`: the render pass on `framebuffer` with the
/// scene's draws and, when asked, the copy of an image (in TRANSFER_SRC_OPTIMAL after
/// the render pass) into a buffer for the host to read, as `render::record_frame`
/// does in tuff.
///
/// # Safety
///
/// `cb` is a primary command buffer of `device`, not pending; every handle is live;
/// the render pass and framebuffer are the scene's, of the view's extent.
pub(crate) unsafe fn record_frame<S: Scene>(
    device: &ash::Device,
    cb: vk::CommandBuffer,
    render_pass: vk::RenderPass,
    framebuffer: vk::Framebuffer,
    scene: &S,
    view: &View,
    readback: Option<(vk::Image, vk::Buffer)>,
) -> Result<()> {
    let area: vk::Rect2D = view.extent.into();
    let clear = [
        vk::ClearValue {
            color: vk::ClearColorValue {
                float32: scene.clear_color(),
            },
        },
        vk::ClearValue {
            depth_stencil: vk::ClearDepthStencilValue {
                depth: DEPTH_CLEAR,
                stencil: 0,
            },
        },
    ];
    // SAFETY: as the caller promises.
    unsafe {
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
                .render_pass(render_pass)
                .framebuffer(framebuffer)
                .render_area(area)
                // Without a depth attachment, only the color is cleared.
                .clear_values(&clear[..1 + usize::from(S::DEPTH)]),
            vk::SubpassContents::INLINE,
        );
        device.cmd_set_viewport(cb, 0, &[crate::render::viewport(view.extent)]);
        device.cmd_set_scissor(cb, 0, &[area]);
        scene.draw(device, cb, view);
        device.cmd_end_render_pass(cb);
        if let Some((image, buffer)) = readback {
            record_readback(device, cb, image, buffer, view.extent);
        }
        device.end_command_buffer(cb).context("vkEndCommandBuffer")
    }
}

/// Records the copy of the whole color `image` of `extent` (in TRANSFER_SRC_OPTIMAL)
/// into `buffer`, tightly packed, and the barrier that makes it visible to the host.
///
/// # Safety
///
/// `cb` is recording, outside a render pass, on `device`; the handles are live.
pub unsafe fn record_readback(
    device: &ash::Device,
    cb: vk::CommandBuffer,
    image: vk::Image,
    buffer: vk::Buffer,
    extent: vk::Extent2D,
) {
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
    // A fence wait does not make device writes visible to the host; this does.
    let to_host = vk::BufferMemoryBarrier::default()
        .src_access_mask(vk::AccessFlags::TRANSFER_WRITE)
        .dst_access_mask(vk::AccessFlags::HOST_READ)
        .src_queue_family_index(vk::QUEUE_FAMILY_IGNORED)
        .dst_queue_family_index(vk::QUEUE_FAMILY_IGNORED)
        .buffer(buffer)
        .offset(0)
        .size(vk::WHOLE_SIZE);
    // SAFETY: as the caller promises.
    unsafe {
        device.cmd_copy_image_to_buffer(
            cb,
            image,
            vk::ImageLayout::TRANSFER_SRC_OPTIMAL,
            buffer,
            &[region],
        );
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
}
