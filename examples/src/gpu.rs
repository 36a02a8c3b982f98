//! Instance, device and queue for a scene, made through tuff, asking for exactly the
//! features and extensions the scene uses.

use anyhow::{anyhow, bail, Context as _, Result};
use tuff::vk;

/// What a scene needs of the device.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct Requirements {
    /// The scene's name, for messages.
    pub scene: &'static str,
    /// `tessellationShader`.
    pub tessellation_shader: bool,
    /// `fillModeNonSolid` (wireframe).
    pub fill_mode_non_solid: bool,
    /// `VK_KHR_surface`, `VK_KHR_xlib_surface` and `VK_KHR_swapchain`, for a window.
    pub window: bool,
}

/// The device a scene renders with. Field order is drop order: the messenger goes
/// after the device, so it hears what the device's objects report as they go, and the
/// log goes last.
pub struct Gpu {
    /// Where the scenes' buffers and images get their memory.
    pub allocator: tuff::GpuAllocator,
    /// The graphics queue.
    pub queue: tuff::Queue,
    /// The queue's family.
    pub family: u32,
    /// The logical device.
    pub device: tuff::Device,
    /// The physical device.
    pub physical: tuff::PhysicalDevice,
    /// The physical device's name, for messages.
    pub name: String,
    messenger: Option<tuff::DebugUtilsMessengerEXT>,
    /// The instance.
    pub instance: tuff::Instance,
    log: tuff::MessageLog,
}

impl Gpu {
    /// Opens the device. With `validation`, the Khronos validation layer and its
    /// synchronization validation are on, and every warning or error it reports is
    /// kept for [`Gpu::finish`].
    ///
    /// Fails with a message naming what is missing: the loader, the layer, a device,
    /// a feature or an extension (tuff names the missing layer, extension or feature).
    pub fn new(req: Requirements, validation: bool) -> Result<Gpu> {
        let entry = tuff::Entry::load().context("cannot load the Vulkan loader (libvulkan1)")?;
        let log = tuff::MessageLog::new();
        let mut exts: Vec<tuff::CStrPtr> = Vec::new();
        if validation {
            exts.push(c"VK_EXT_debug_utils".into());
        }
        if req.window {
            exts.extend([
                tuff::CStrPtr::from(c"VK_KHR_surface"),
                c"VK_KHR_xlib_surface".into(),
            ]);
        }
        let layers = [tuff::CStrPtr::from(c"VK_LAYER_KHRONOS_validation")];
        let app = tuff::ApplicationInfo::new().api_version(vk::API_VERSION_1_3);
        let mut chained = log.messenger_info();
        let mut info = tuff::InstanceCreateInfo::new()
            .application_info(Some(&app))
            .enabled_extension_names(&exts);
        if validation {
            info = info.enabled_layer_names(&layers).push_next(&mut chained);
        }
        let instance = entry.create_instance(&info).with_context(|| {
            let hint = if validation {
                " (the layer: apt-get install vulkan-validationlayers)"
            } else {
                ""
            };
            format!(
                "cannot create a Vulkan instance for the {} scene{hint}",
                req.scene
            )
        })?;
        let messenger = validation
            .then(|| instance.create_debug_utils_messenger_ext(&log.messenger_info()))
            .transpose()?;
        let physicals = instance.enumerate_physical_devices()?;
        let name_of = |p: &tuff::PhysicalDevice| {
            p.get_physical_device_properties()
                .device_name_as_c_str()
                .map(|n| n.to_string_lossy().into_owned())
                .unwrap_or_else(|_| "<unnamed>".into())
        };
        // A discrete GPU first, then integrated, then anything (lavapipe is a CPU);
        // TUFF_DEVICE picks by name instead (the scene tests pin lavapipe with it).
        let rank = |p: &tuff::PhysicalDevice| match p.get_physical_device_properties().device_type {
            vk::PhysicalDeviceType::DISCRETE_GPU => 0,
            vk::PhysicalDeviceType::INTEGRATED_GPU => 1,
            _ => 2,
        };
        let physical = match std::env::var("TUFF_DEVICE") {
            Ok(wanted) if !wanted.is_empty() => physicals
                .iter()
                .find(|p| name_of(p).contains(&wanted))
                .ok_or_else(|| {
                    let names: Vec<String> = physicals.iter().map(name_of).collect();
                    anyhow!(
                        "no Vulkan device's name contains TUFF_DEVICE={wanted:?} (devices: {})",
                        names.join(", ")
                    )
                })?,
            _ => physicals.iter().min_by_key(|p| rank(p)).ok_or_else(|| {
                anyhow!(
                    "no Vulkan device found (for lavapipe: apt-get install mesa-vulkan-drivers)"
                )
            })?,
        }
        .clone();
        let name = name_of(&physical);
        let features = vk::PhysicalDeviceFeatures {
            tessellation_shader: req.tessellation_shader.into(),
            fill_mode_non_solid: req.fill_mode_non_solid.into(),
            ..Default::default()
        };
        let device_exts: &[tuff::CStrPtr] = if req.window {
            &[tuff::CStrPtr::from(c"VK_KHR_swapchain")]
        } else {
            &[]
        };
        let family = physical
            .get_physical_device_queue_family_properties()?
            .iter()
            .position(|f| f.queue_flags.contains(vk::QueueFlags::GRAPHICS))
            .ok_or_else(|| anyhow!("the device \"{name}\" has no graphics queue"))?
            as u32;
        let queues = [tuff::DeviceQueueCreateInfo::new()
            .queue_family_index(family)
            .queue_priorities(&[1.0])];
        let device = physical
            .create_device(
                &tuff::DeviceCreateInfo::new()
                    .queue_create_infos(&queues)
                    .enabled_extension_names(device_exts)
                    .enabled_features(Some(&features)),
            )
            .with_context(|| {
                format!(
                    "cannot create a device on \"{name}\" for the {} scene",
                    req.scene
                )
            })?;
        Ok(Gpu {
            allocator: device.gpu_allocator()?,
            queue: device.get_device_queue(family, 0),
            family,
            device,
            physical,
            name,
            messenger,
            instance,
            log,
        })
    }

    /// Drops the device and instance and returns what the validation layer reported
    /// over the whole run, including while objects were destroyed. Drop every object
    /// made from this device first.
    pub fn finish(self) -> Vec<String> {
        let Gpu {
            allocator,
            queue,
            device,
            physical,
            messenger,
            instance,
            log,
            ..
        } = self;
        drop((allocator, queue, device, physical, messenger, instance));
        log.take()
    }

    /// A buffer with memory at `location`.
    pub fn buffer(
        &self,
        size: u64,
        usage: vk::BufferUsageFlags,
        location: tuff::MemoryLocation,
    ) -> Result<tuff::Bound<tuff::Buffer>> {
        let info = tuff::BufferCreateInfo::new().size(size).usage(usage);
        Ok(self
            .device
            .create_buffer_in(&info, &self.allocator, location)?)
    }

    /// A buffer holding `data`, which the device reads.
    pub fn buffer_with<T: bytemuck::NoUninit>(
        &self,
        usage: vk::BufferUsageFlags,
        data: &[T],
    ) -> Result<tuff::Bound<tuff::Buffer>> {
        let size = std::mem::size_of_val(data).max(4) as u64;
        let buffer = self.buffer(size, usage, tuff::MemoryLocation::Upload)?;
        buffer.memory().write(0, data)?;
        Ok(buffer)
    }

    /// A 2D image in device-local memory, which the image keeps.
    pub fn image(
        &self,
        extent: vk::Extent2D,
        format: vk::Format,
        usage: vk::ImageUsageFlags,
    ) -> Result<tuff::Image> {
        let info = tuff::ImageCreateInfo::new()
            .image_type(vk::ImageType::TYPE_2D)
            .format(format)
            .extent(extent.into())
            .mip_levels(1)
            .array_layers(1)
            .samples(vk::SampleCountFlags::TYPE_1)
            .usage(usage);
        let local = tuff::MemoryLocation::DeviceLocal;
        Ok(self
            .device
            .create_image_in(&info, &self.allocator, local)?
            .into_parts()
            .0)
    }

    /// A 2D view of the whole of `image`.
    pub fn view(
        &self,
        image: &tuff::Image,
        format: vk::Format,
        aspect: vk::ImageAspectFlags,
    ) -> Result<tuff::ImageView> {
        Ok(self.device.create_image_view(
            &tuff::ImageViewCreateInfo::new(image)
                .view_type(vk::ImageViewType::TYPE_2D)
                .format(format)
                .subresource_range(whole(aspect)),
        )?)
    }

    /// A shader module from committed SPIR-V bytes.
    pub fn shader(&self, spirv: &[u8]) -> Result<tuff::ShaderModule> {
        if spirv.len() % 4 != 0 {
            bail!(
                "SPIR-V of {} bytes is not a whole number of words",
                spirv.len()
            );
        }
        let words: Vec<u32> = bytemuck::pod_collect_to_vec(spirv);
        let info = tuff::ShaderModuleCreateInfo::new().code(&words);
        Ok(self.device.create_shader_module(&info)?)
    }
}

/// The whole of a one-level, one-layer image.
fn whole(aspect: vk::ImageAspectFlags) -> vk::ImageSubresourceRange {
    vk::ImageSubresourceRange {
        aspect_mask: aspect,
        base_mip_level: 0,
        level_count: 1,
        base_array_layer: 0,
        layer_count: 1,
    }
}
