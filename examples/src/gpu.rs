//! Instance, device and queue for a scene, made through tuff, asking for exactly the
//! features and extensions the scene uses.

use anyhow::{anyhow, Context as _, Result};
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
    /// `robustBufferAccess`: an indexed draw that fetches vertex attributes is safe
    /// in tuff only when every vertex its indices can name lies inside the bound
    /// vertex buffers, which the host cannot know of the index buffer's contents,
    /// or when robust buffer access keeps every fetch inside them.
    pub robust_buffer_access: bool,
    /// `VK_KHR_surface`, `VK_KHR_xlib_surface` and `VK_KHR_swapchain`, for a window.
    pub window: bool,
}

impl Requirements {
    /// What a scene named `scene` asks when it needs nothing beyond core Vulkan.
    pub const fn core(scene: &'static str) -> Requirements {
        Requirements {
            scene,
            tessellation_shader: false,
            fill_mode_non_solid: false,
            robust_buffer_access: false,
            window: false,
        }
    }
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
    _messenger: Option<tuff::DebugUtilsMessengerEXT>,
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
        let mut exts = Vec::new();
        if validation {
            exts.push(tuff::CStrPtr::new(c"VK_EXT_debug_utils"));
        }
        if req.window {
            exts.extend(crate::window::INSTANCE_EXTENSIONS);
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
        // A discrete GPU first, then integrated, then anything (lavapipe is a CPU);
        // TUFF_DEVICE picks by name instead (the scene tests pin lavapipe with it).
        let rank = |p: &tuff::PhysicalDevice| match p.get_properties().device_type {
            vk::PhysicalDeviceType::DISCRETE_GPU => 0,
            vk::PhysicalDeviceType::INTEGRATED_GPU => 1,
            _ => 2,
        };
        let physical = match std::env::var("TUFF_DEVICE") {
            Ok(wanted) if !wanted.is_empty() => physicals
                .iter()
                .find(|p| p.name().contains(&wanted))
                .ok_or_else(|| {
                    let names: Vec<String> = physicals.iter().map(|p| p.name()).collect();
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
        let name = physical.name();
        let features = vk::PhysicalDeviceFeatures {
            tessellation_shader: req.tessellation_shader.into(),
            fill_mode_non_solid: req.fill_mode_non_solid.into(),
            robust_buffer_access: req.robust_buffer_access.into(),
            ..Default::default()
        };
        let device_exts: &[_] = if req.window {
            &crate::window::DEVICE_EXTENSIONS
        } else {
            &[]
        };
        let family = physical
            .queue_family_index(vk::QueueFlags::GRAPHICS)?
            .ok_or_else(|| anyhow!("the device \"{name}\" has no graphics queue"))?;
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
            queue: device.get_queue(family, 0)?,
            family,
            device,
            physical,
            name,
            _messenger: messenger,
            instance,
            log,
        })
    }

    /// Drops the device and instance and returns what the validation layer reported
    /// over the whole run, including while objects were destroyed. Drop every object
    /// made from this device first.
    pub fn finish(mut self) -> Vec<String> {
        let log = std::mem::take(&mut self.log);
        drop(self);
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
