//! An instance, device and queue made entirely through the generated wrappers.
//!
//! SAFETY of the `unsafe` blocks around checked methods: such a method is `unsafe`
//! because it leaves rules to its caller (its `# Safety` section lists them). The
//! calls here keep every rule so listed and break, on purpose, only rules the method
//! checks; that one argument covers every such block in this file.
#![allow(dead_code)]

use tuff::{vk, Handle as _};

/// What a wrapper test needs. Field order is drop order: the messenger goes last but
/// one, so it hears everything the device's children report.
pub struct Setup {
    pub queue: tuff::Queue,
    pub physical: tuff::PhysicalDevice,
    pub family: u32,
    pub device: tuff::Device,
    pub memory_types: vk::PhysicalDeviceMemoryProperties,
    pub messenger: Option<tuff::DebugUtilsMessengerEXT>,
    pub instance: tuff::Instance,
    pub messages: tuff::MessageLog,
}

/// Window-system integration a setup enables.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Wsi {
    /// None: a headless instance and device.
    None,
    /// `VK_KHR_surface` and `VK_KHR_xlib_surface` on the instance, `VK_KHR_swapchain`
    /// on the device.
    Xlib,
}

/// Build the setup, with the validation layer (and its synchronization validation)
/// when `validation`. Panics with a clear message when no device is found.
pub fn setup(validation: bool) -> Setup {
    setup_with(validation, Wsi::None)
}

/// [`setup`], with window-system extensions.
pub fn setup_with(validation: bool, wsi: Wsi) -> Setup {
    setup_full(
        None,
        validation,
        wsi,
        vk::PhysicalDeviceFeatures::default(),
        Chain::Core,
    )
}

/// The VUID of a refused call, or a panic naming what came back instead.
#[allow(dead_code)]
pub fn vuid<T>(r: tuff::Result<T>) -> &'static str {
    match r {
        Err(tuff::Error::Validation { vuid, .. }) => vuid,
        Err(e) => panic!("expected tuff to refuse the call, got {e}"),
        Ok(_) => panic!("expected tuff to refuse the call, got success"),
    }
}

/// [`setup`], on a device that enables no feature at all (no Vulkan 1.2 or 1.3
/// feature either), for rules that apply with one of `setup`'s features off.
#[allow(dead_code)]
pub fn setup_bare(validation: bool) -> Setup {
    setup_full(
        None,
        validation,
        Wsi::None,
        vk::PhysicalDeviceFeatures::default(),
        Chain::None,
    )
}

/// [`setup`] on a Vulkan 1.2 instance (so a 1.2 device) with no feature of 1.1 or
/// 1.2 enabled either, for rules that apply only without Vulkan 1.3.
#[allow(dead_code)]
pub fn setup_v1_2(validation: bool) -> Setup {
    setup_full(
        None,
        validation,
        Wsi::None,
        vk::PhysicalDeviceFeatures::default(),
        Chain::V12,
    )
}

/// [`setup`], on a device that enables every feature of Vulkan 1.0 to 1.3 the
/// physical device has, for changes that need one `setup` leaves off.
#[allow(dead_code)]
pub fn setup_full_features(validation: bool) -> Setup {
    setup_full(
        None,
        validation,
        Wsi::None,
        vk::PhysicalDeviceFeatures::default(),
        Chain::All,
    )
}

/// [`setup`], with these Vulkan 1.0 features enabled.
pub fn setup_with_features(validation: bool, features: vk::PhysicalDeviceFeatures) -> Setup {
    setup_full(None, validation, Wsi::None, features, Chain::Core)
}

/// [`setup`], with the same Vulkan 1.2 and 1.3 features enabled through the
/// structs of the extensions they came from rather than the core versions' structs.
pub fn setup_with_extension_feature_structs(validation: bool) -> Setup {
    setup_full(
        None,
        validation,
        Wsi::None,
        vk::PhysicalDeviceFeatures::default(),
        Chain::Extensions,
    )
}

/// How the device's Vulkan 1.2 and 1.3 features are chained into its create info.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Chain {
    /// The core versions' feature structs.
    Core,
    /// The structs of the extensions the features came from.
    Extensions,
    /// None: no such feature is enabled.
    None,
    /// Every feature the physical device has, Vulkan 1.0 to 1.3.
    All,
    /// None, on a Vulkan 1.2 instance.
    V12,
}

/// [`setup`], its instance and device made from `entry` (one with a host allocator,
/// say).
#[allow(dead_code)]
pub fn setup_on(entry: tuff::Entry, validation: bool) -> Setup {
    setup_full(
        Some(entry),
        validation,
        Wsi::None,
        vk::PhysicalDeviceFeatures::default(),
        Chain::Core,
    )
}

fn setup_full(
    entry: Option<tuff::Entry>,
    validation: bool,
    wsi: Wsi,
    features: vk::PhysicalDeviceFeatures,
    chain: Chain,
) -> Setup {
    if validation {
        // SAFETY: set before any thread of this test reads the environment.
        unsafe {
            std::env::set_var(
                "VK_LAYER_ENABLES",
                "VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT",
            )
        };
    }
    let entry =
        entry.unwrap_or_else(|| tuff::Entry::load().expect("the Vulkan loader is not installed"));
    let messages = tuff::MessageLog::new();
    let layers = [tuff::CStrPtr::from(c"VK_LAYER_KHRONOS_validation")];
    let mut exts = Vec::new();
    if validation {
        exts.push(tuff::CStrPtr::from(c"VK_EXT_debug_utils"));
    }
    if wsi == Wsi::Xlib {
        exts.push(tuff::CStrPtr::from(c"VK_KHR_surface"));
        exts.push(tuff::CStrPtr::from(c"VK_KHR_xlib_surface"));
    }
    let version = match chain {
        Chain::V12 => vk::API_VERSION_1_2,
        _ => vk::API_VERSION_1_3,
    };
    let app = tuff::ApplicationInfo::new().api_version(version);
    let mut messenger_info = messages.messenger_info();
    let mut info = tuff::InstanceCreateInfo::new()
        .application_info(Some(&app))
        .enabled_extension_names(&exts);
    if validation {
        info = info
            .enabled_layer_names(&layers)
            .push_next(&mut messenger_info);
    }
    let instance = entry
        .create_instance(&info)
        .expect("cannot create an instance (is VK_LAYER_KHRONOS_validation installed?)");
    let messenger = validation.then(|| {
        instance
            .create_debug_utils_messenger_ext(&messages.messenger_info())
            .expect("debug messenger")
    });
    let physicals = instance
        .enumerate_physical_devices()
        .expect("enumerate physical devices");
    let physical = physicals
        .iter()
        .find(|p| p.get_properties().device_type == vk::PhysicalDeviceType::CPU)
        .or(physicals.first())
        .expect("no Vulkan device found: install mesa-vulkan-drivers (lavapipe)")
        .clone();
    let families = physical
        .get_queue_family_properties()
        .expect("queue families");
    let family = families
        .iter()
        .position(|f| f.queue_flags.contains(vk::QueueFlags::GRAPHICS))
        .expect("no graphics queue family") as u32;
    let priorities = [1.0f32];
    let queues = [tuff::DeviceQueueCreateInfo::new()
        .queue_family_index(family)
        .queue_priorities(&priorities)];
    // A typed pNext chain: only structs that extend VkDeviceCreateInfo are accepted.
    let mut features13 = tuff::PhysicalDeviceVulkan13Features::new()
        .private_data(true)
        .synchronization2(true)
        .dynamic_rendering(true);
    let mut features12 = tuff::PhysicalDeviceVulkan12Features::new()
        .imageless_framebuffer(true)
        .timeline_semaphore(true)
        .draw_indirect_count(true)
        .host_query_reset(true);
    let device_exts = match wsi {
        Wsi::None => vec![],
        Wsi::Xlib => vec![tuff::CStrPtr::from(c"VK_KHR_swapchain")],
    };
    let mut sync2 = tuff::PhysicalDeviceSynchronization2Features::new().synchronization2(true);
    let mut private_data = tuff::PhysicalDevicePrivateDataFeatures::new().private_data(true);
    let mut imageless =
        tuff::PhysicalDeviceImagelessFramebufferFeatures::new().imageless_framebuffer(true);
    let mut timeline =
        tuff::PhysicalDeviceTimelineSemaphoreFeatures::new().timeline_semaphore(true);
    // Every feature the physical device has, for `Chain::All`.
    let mut all13 = tuff::PhysicalDeviceVulkan13Features::new();
    let mut all12 = tuff::PhysicalDeviceVulkan12Features::new();
    let mut all11 = tuff::PhysicalDeviceVulkan11Features::new();
    let features = if chain == Chain::All {
        let mut q13 = vk::PhysicalDeviceVulkan13Features::default();
        let mut q12 = vk::PhysicalDeviceVulkan12Features::default();
        let mut q11 = vk::PhysicalDeviceVulkan11Features::default();
        let mut f2 = vk::PhysicalDeviceFeatures2::default()
            .push_next(&mut q11)
            .push_next(&mut q12)
            .push_next(&mut q13);
        // SAFETY: a live physical device of a Vulkan 1.3 instance; the chain is local.
        unsafe {
            instance
                .fns()
                .get_physical_device_features2(physical.raw(), &mut f2)
        };
        let f10 = f2.features;
        let null = std::ptr::null_mut();
        // SAFETY: whole structs of the same types, with no chain of their own.
        unsafe {
            *all13.raw_values_mut() = vk::PhysicalDeviceVulkan13Features {
                p_next: null,
                ..q13
            };
            *all12.raw_values_mut() = vk::PhysicalDeviceVulkan12Features {
                p_next: null,
                ..q12
            };
            *all11.raw_values_mut() = vk::PhysicalDeviceVulkan11Features {
                p_next: null,
                ..q11
            };
        }
        f10
    } else {
        features
    };
    let info = tuff::DeviceCreateInfo::new()
        .queue_create_infos(&queues)
        .enabled_extension_names(&device_exts)
        .enabled_features(Some(&features));
    let info = match chain {
        Chain::Extensions => info
            .push_next(&mut sync2)
            .push_next(&mut private_data)
            .push_next(&mut imageless)
            .push_next(&mut timeline),
        Chain::Core => info.push_next(&mut features13).push_next(&mut features12),
        Chain::None | Chain::V12 => info,
        Chain::All => info
            .push_next(&mut all13)
            .push_next(&mut all12)
            .push_next(&mut all11),
    };
    let device = physical.create_device(&info).expect("create device");
    let queue = device.get_queue(family, 0).expect("queue");
    let memory_types = physical.get_memory_properties();
    Setup {
        queue,
        physical,
        family,
        device,
        memory_types,
        messenger,
        instance,
        messages,
    }
}

impl Setup {
    /// A memory type allowed by `bits` with `flags`.
    pub fn memory_type(&self, bits: u32, flags: vk::MemoryPropertyFlags) -> u32 {
        (0..self.memory_types.memory_type_count)
            .find(|i| {
                bits & (1 << i) != 0
                    && self.memory_types.memory_types[*i as usize]
                        .property_flags
                        .contains(flags)
            })
            .expect("no suitable memory type")
    }
}

impl Setup {
    /// A one-color-attachment render pass of `format`, with `subpasses` subpasses that
    /// each write the attachment, one after the other.
    pub fn color_pass(&self, format: vk::Format, subpasses: u32) -> tuff::RenderPass {
        let attachments = [vk::AttachmentDescription {
            format,
            samples: vk::SampleCountFlags::TYPE_1,
            load_op: vk::AttachmentLoadOp::CLEAR,
            store_op: vk::AttachmentStoreOp::STORE,
            stencil_load_op: vk::AttachmentLoadOp::DONT_CARE,
            stencil_store_op: vk::AttachmentStoreOp::DONT_CARE,
            initial_layout: vk::ImageLayout::UNDEFINED,
            final_layout: vk::ImageLayout::COLOR_ATTACHMENT_OPTIMAL,
            ..Default::default()
        }];
        let color = [vk::AttachmentReference {
            attachment: 0,
            layout: vk::ImageLayout::COLOR_ATTACHMENT_OPTIMAL,
        }];
        let subpass = tuff::SubpassDescription::new()
            .pipeline_bind_point(vk::PipelineBindPoint::GRAPHICS)
            .color_attachments(&color);
        let subpass_list = vec![subpass; subpasses as usize];
        let output = vk::PipelineStageFlags::COLOR_ATTACHMENT_OUTPUT;
        let write = vk::AccessFlags::COLOR_ATTACHMENT_WRITE;
        let dependencies: Vec<vk::SubpassDependency> = (1..subpasses)
            .map(|n| vk::SubpassDependency {
                src_subpass: n - 1,
                dst_subpass: n,
                src_stage_mask: output,
                dst_stage_mask: output,
                src_access_mask: write,
                dst_access_mask: write,
                dependency_flags: vk::DependencyFlags::BY_REGION,
            })
            .collect();
        self.device
            .create_render_pass(
                &tuff::RenderPassCreateInfo::new()
                    .attachments(&attachments)
                    .subpasses(&subpass_list)
                    .dependencies(&dependencies),
            )
            .expect("render pass")
    }

    /// A command pool on the setup's queue family and one command buffer of `level`
    /// from it.
    pub fn command_buffer(
        &self,
        level: vk::CommandBufferLevel,
    ) -> (tuff::CommandPool, tuff::CommandBuffer) {
        let pool = self
            .device
            .create_command_pool(
                &tuff::CommandPoolCreateInfo::new()
                    .flags(vk::CommandPoolCreateFlags::RESET_COMMAND_BUFFER)
                    .queue_family_index(self.family),
            )
            .expect("pool");
        let cb = self
            .device
            .allocate_command_buffers(
                &pool,
                &tuff::CommandBufferAllocateInfo::new(&pool)
                    .level(level)
                    .command_buffer_count(1),
            )
            .expect("command buffers")
            .pop()
            .expect("one command buffer");
        (pool, cb)
    }
}

/// A square 2D RGBA8 image of `size` pixels a side, one level, one layer, one
/// sample: the create info most tests need.
pub fn rgba8_image_info(size: u32, usage: vk::ImageUsageFlags) -> tuff::ImageCreateInfo<'static> {
    tuff::ImageCreateInfo::new()
        .image_type(vk::ImageType::TYPE_2D)
        .format(vk::Format::R8G8B8A8_UNORM)
        .extent(vk::Extent3D {
            width: size,
            height: size,
            depth: 1,
        })
        .mip_levels(1)
        .array_layers(1)
        .samples(vk::SampleCountFlags::TYPE_1)
        .usage(usage)
}

/// A square RGBA8 image with its memory and view, and a one-subpass render pass and
/// framebuffer that clear and store it.
pub struct ColorTarget {
    pub image: tuff::Image,
    pub memory: tuff::DeviceMemory,
    pub view: tuff::ImageView,
    pub render_pass: tuff::RenderPass,
    pub framebuffer: tuff::Framebuffer,
}

impl Setup {
    /// Allocates memory for `image` and binds it.
    pub fn bind_image(&self, image: &tuff::Image) -> tuff::DeviceMemory {
        let d = &self.device;
        let reqs = d
            .get_image_memory_requirements(image)
            .expect("memory requirements");
        let memory = d
            .allocate_memory(
                &tuff::MemoryAllocateInfo::new()
                    .allocation_size(reqs.size)
                    .memory_type_index(
                        self.memory_type(reqs.memory_type_bits, vk::MemoryPropertyFlags::empty()),
                    ),
            )
            .expect("image memory");
        d.bind_image_memory(image, &memory, 0).expect("bind image");
        memory
    }

    /// A square RGBA8 image of `size` pixels, of `usage` and color attachment usage,
    /// with its memory and a 2D view of it.
    pub fn color_image(
        &self,
        size: u32,
        usage: vk::ImageUsageFlags,
    ) -> (tuff::Image, tuff::DeviceMemory, tuff::ImageView) {
        let d = &self.device;
        let image = d
            .create_image(&rgba8_image_info(
                size,
                vk::ImageUsageFlags::COLOR_ATTACHMENT | usage,
            ))
            .expect("image");
        let memory = self.bind_image(&image);
        let view = d
            .create_image_view(
                &tuff::ImageViewCreateInfo::new(&image)
                    .view_type(vk::ImageViewType::TYPE_2D)
                    .format(vk::Format::R8G8B8A8_UNORM)
                    .subresource_range(vk::ImageSubresourceRange {
                        aspect_mask: vk::ImageAspectFlags::COLOR,
                        base_mip_level: 0,
                        level_count: 1,
                        base_array_layer: 0,
                        layer_count: 1,
                    }),
            )
            .expect("image view");
        (image, memory, view)
    }

    /// Submits `cb` alone and waits for it.
    pub fn submit_wait(&self, cb: &tuff::CommandBuffer) {
        let fence = self
            .device
            .create_fence(&tuff::FenceCreateInfo::new())
            .expect("fence");
        let cbs = tuff::HandleSlice::new(&[cb]);
        self.queue
            .submit(
                &[tuff::SubmitInfo::new().command_buffers(&cbs)],
                Some(&fence),
            )
            .expect("submit");
        let waited = self
            .device
            .wait_for_fences(&fence, true, u64::MAX)
            .expect("wait");
        assert_eq!(waited, tuff::SuccessOrTimeout::Success);
    }

    /// A color target of `size` x `size` pixels; `usage` is added to COLOR_ATTACHMENT.
    pub fn color_target(&self, size: u32, usage: vk::ImageUsageFlags) -> ColorTarget {
        let d = &self.device;
        let (image, memory, view) = self.color_image(size, usage);
        let render_pass = self.color_pass(vk::Format::R8G8B8A8_UNORM, 1);
        let framebuffer = d
            .create_framebuffer(
                &tuff::FramebufferCreateInfo::new(&render_pass)
                    .attachments(&view)
                    .width(size)
                    .height(size)
                    .layers(1),
            )
            .expect("framebuffer");
        ColorTarget {
            image,
            memory,
            view,
            render_pass,
            framebuffer,
        }
    }
}

/// A shader module from one of the repository's compiled test shaders.
pub fn shader(s: &Setup, bytes: &[u8]) -> tuff::ShaderModule {
    // SAFETY: the shader promise. The repository's shaders are compiled from its GLSL
    // by `scripts/shaders.sh` (a test fails if the committed SPIR-V is stale), are
    // valid SPIR-V for Vulkan 1.3, need no feature the test device lacks, terminate,
    // and read only the resources their pipelines give them.
    unsafe { s.device.create_shader_module_from_spirv(bytes) }.expect("shader module")
}

/// What the validation layer says of an unchecked call that breaks a rule.
#[allow(dead_code)]
#[derive(Clone, Copy)]
pub enum Layer<'a> {
    /// It names the rule.
    Names,
    /// It names the rule, or this sibling rule that states the same case.
    NamesOr(&'a str),
    /// It says nothing: the 1.3.239 layer does not check the rule, and tuff's error
    /// alone proves it (the command buffer is never submitted).
    Silent,
}

/// Breaks `rule` through both paths: `record(false)` calls the safe method, which
/// tuff must refuse with the rule's VUID while the layer says nothing, and
/// `record(true)` its `_unchecked` twin, under the layer told to skip the call it
/// reports, which must say what `layer` says. `record` makes its own recording for
/// each and returns the call's result.
#[allow(dead_code)]
pub fn breaks(
    s: &Setup,
    rule: &str,
    layer: Layer<'_>,
    mut record: impl FnMut(bool) -> tuff::Result<()>,
) {
    assert_eq!(vuid(record(false)), rule);
    let said = s.messages.take();
    assert!(said.is_empty(), "the layer reported {said:?}");
    s.messages.abort_on_error(true);
    let _ = record(true);
    s.messages.abort_on_error(false);
    let said = s.messages.take();
    match layer {
        Layer::Names => assert!(
            said.iter().any(|m| m.contains(rule)),
            "the layer did not name {rule}; it said {said:?}"
        ),
        Layer::NamesOr(sibling) => assert!(
            said.iter().any(|m| m.contains(rule) || m.contains(sibling)),
            "the layer named neither {rule} nor {sibling}; it said {said:?}"
        ),
        Layer::Silent => assert!(said.is_empty(), "the layer now checks {rule}: {said:?}"),
    }
}

/// A submission kept pending: its batch waits for value 1 of a timeline semaphore,
/// which the host signals when [`Pending::release`] runs or the value drops (so a
/// failed assertion does not leave the fence's drop waiting forever).
pub struct Pending<'a> {
    device: &'a tuff::Device,
    semaphore: tuff::Semaphore,
    pub fence: tuff::Fence,
}

impl<'a> Pending<'a> {
    /// Submits `cb` after a wait for the host's signal.
    pub fn submit(s: &'a Setup, cb: &tuff::CommandBuffer) -> Self {
        let d = &s.device;
        let mut timeline_type = tuff::SemaphoreTypeCreateInfo::new()
            .semaphore_type(vk::SemaphoreType::TIMELINE)
            .initial_value(0);
        let semaphore = d
            .create_semaphore(&tuff::SemaphoreCreateInfo::new().push_next(&mut timeline_type))
            .expect("timeline semaphore");
        let semaphores = tuff::HandleSlice::new(&[&semaphore]);
        let stages = [vk::PipelineStageFlags::ALL_COMMANDS];
        let cbs = tuff::HandleSlice::new(&[cb]);
        let mut wait = tuff::TimelineSemaphoreSubmitInfo::new().wait_semaphore_values(&[1]);
        let submit = [tuff::SubmitInfo::new()
            .wait_semaphores(&semaphores, &stages)
            .expect("one stage mask a semaphore")
            .command_buffers(&cbs)
            .push_next(&mut wait)];
        let fence = d
            .create_fence(&tuff::FenceCreateInfo::new())
            .expect("fence");
        s.queue.submit(&submit, Some(&fence)).expect("submit");
        Pending {
            device: d,
            semaphore,
            fence,
        }
    }

    /// Signals the batch's wait and waits for its fence.
    pub fn release(self) {
        self.signal();
        let waited = self
            .device
            .wait_for_fences(&self.fence, true, u64::MAX)
            .expect("wait");
        assert_eq!(waited, tuff::SuccessOrTimeout::Success);
    }

    fn signal(&self) {
        let info = tuff::SemaphoreSignalInfo::new(&self.semaphore).value(1);
        if self.device.get_semaphore_counter_value(&self.semaphore) == Ok(0) {
            self.device.signal_semaphore(&info).expect("signal");
        }
    }
}

impl Drop for Pending<'_> {
    fn drop(&mut self) {
        if self.device.get_semaphore_counter_value(&self.semaphore) == Ok(0) {
            let info = tuff::SemaphoreSignalInfo::new(&self.semaphore).value(1);
            let _ = self.device.signal_semaphore(&info);
        }
    }
}

/// A swapchain create info for `surface` at its current size.
pub fn swapchain_info<'a>(
    s: &Setup,
    surface: &'a tuff::SurfaceKHR,
) -> tuff::SwapchainCreateInfoKHR<'a> {
    let caps = s
        .physical
        .get_surface_capabilities_khr(surface)
        .expect("surface capabilities");
    let formats = s
        .physical
        .get_surface_formats_khr(Some(surface))
        .expect("surface formats");
    let modes = s
        .physical
        .get_surface_present_modes_khr(Some(surface))
        .expect("present modes");
    assert!(
        modes.contains(&vk::PresentModeKHR::FIFO),
        "FIFO is always supported"
    );
    let format = formats[0];
    tuff::SwapchainCreateInfoKHR::new(surface)
        .min_image_count(
            caps.min_image_count
                .max(2)
                .min(if caps.max_image_count == 0 {
                    u32::MAX
                } else {
                    caps.max_image_count
                }),
        )
        .image_format(format.format)
        .image_color_space(format.color_space)
        .image_extent(caps.current_extent)
        .image_array_layers(1)
        .image_usage(vk::ImageUsageFlags::COLOR_ATTACHMENT | vk::ImageUsageFlags::TRANSFER_DST)
        .image_sharing_mode(vk::SharingMode::EXCLUSIVE)
        .pre_transform(caps.current_transform)
        .composite_alpha(vk::CompositeAlphaFlagsKHR::OPAQUE)
        .present_mode(vk::PresentModeKHR::FIFO)
        .clipped(true)
}
