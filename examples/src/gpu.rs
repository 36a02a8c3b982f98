//! Instance, device and queue for a scene, made through tuff, asking for exactly the
//! features and extensions the scene uses.

use anyhow::{anyhow, bail, Context as _, Result};
use std::ffi::{c_void, CStr};
use std::sync::{Arc, Mutex};
use tuff::vk;

/// Messages the validation layer emitted.
type Messages = Arc<Mutex<Vec<String>>>;

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
/// after the device, so it hears what the device's objects report as they go.
pub struct Gpu {
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
    memory_types: vk::PhysicalDeviceMemoryProperties,
    messenger: Option<tuff::DebugUtilsMessengerEXT>,
    /// The instance.
    pub instance: tuff::Instance,
    messages: Messages,
    _user_data: Box<Messages>,
}

/// Hears the validation layer. Registered with a `Box<Messages>` as user data.
///
/// # Safety
///
/// `user` is the `Messages` box of a live [`Gpu`] and `data` the layer's valid
/// callback data.
unsafe extern "system" fn on_message(
    severity: vk::DebugUtilsMessageSeverityFlagsEXT,
    _types: vk::DebugUtilsMessageTypeFlagsEXT,
    data: *const vk::DebugUtilsMessengerCallbackDataEXT<'_>,
    user: *mut c_void,
) -> vk::Bool32 {
    // SAFETY: the layer passes valid callback data, and `user` is the Gpu's boxed
    // Messages, which outlives the messenger.
    unsafe {
        let text = if data.is_null() || (*data).p_message.is_null() {
            "<no message>".to_owned()
        } else {
            CStr::from_ptr((*data).p_message)
                .to_string_lossy()
                .into_owned()
        };
        let messages = &*(user as *const Messages);
        if let Ok(mut m) = messages.lock() {
            m.push(format!("{severity:?}: {text}"));
        }
    }
    vk::FALSE
}

/// Whether `list` names `name`.
fn has_extension(list: &[vk::ExtensionProperties], name: &CStr) -> bool {
    list.iter()
        .any(|e| e.extension_name_as_c_str().is_ok_and(|n| n == name))
}

impl Gpu {
    /// Opens the device. With `validation`, the Khronos validation layer and its
    /// synchronization validation are on, and every warning or error it reports is
    /// kept for [`Gpu::finish`].
    ///
    /// Fails with a message naming what is missing: the loader, the layer, a device,
    /// a feature or an extension.
    pub fn new(req: Requirements, validation: bool) -> Result<Gpu> {
        let entry = tuff::Entry::load().context("cannot load the Vulkan loader (libvulkan1)")?;
        let messages: Messages = Arc::new(Mutex::new(Vec::new()));
        let user_data = Box::new(messages.clone());
        let available = entry
            .enumerate_instance_extension_properties(None)
            .context("cannot list the instance extensions")?;
        let mut exts = Vec::new();
        if validation {
            exts.push(c"VK_EXT_debug_utils");
        }
        if req.window {
            exts.push(c"VK_KHR_surface");
            exts.push(c"VK_KHR_xlib_surface");
        }
        for e in &exts {
            if !has_extension(&available, e) {
                bail!(
                    "the Vulkan instance lacks the extension {}, which the {} scene needs",
                    e.to_string_lossy(),
                    req.scene
                );
            }
        }
        let ext_ptrs: Vec<tuff::CStrPtr> = exts.iter().map(|e| (*e).into()).collect();
        let layers = [tuff::CStrPtr::from(c"VK_LAYER_KHRONOS_validation")];
        let app = tuff::ApplicationInfo::new().api_version(vk::API_VERSION_1_3);
        let mut messenger_info = tuff::DebugUtilsMessengerCreateInfoEXT::new()
            .message_severity(
                vk::DebugUtilsMessageSeverityFlagsEXT::WARNING
                    | vk::DebugUtilsMessageSeverityFlagsEXT::ERROR,
            )
            .message_type(
                vk::DebugUtilsMessageTypeFlagsEXT::VALIDATION
                    | vk::DebugUtilsMessageTypeFlagsEXT::PERFORMANCE
                    | vk::DebugUtilsMessageTypeFlagsEXT::GENERAL,
            )
            .pfn_user_callback(Some(on_message))
            .user_data(&*user_data as *const Messages as *mut _);
        let mut info = tuff::InstanceCreateInfo::new()
            .application_info(Some(&app))
            .enabled_extension_names(&ext_ptrs);
        if validation {
            info = info
                .enabled_layer_names(&layers)
                .push_next(&mut messenger_info);
        }
        let instance = entry.create_instance(&info).with_context(|| {
            if validation {
                "cannot create a Vulkan instance with VK_LAYER_KHRONOS_validation \
                 (apt-get install vulkan-validationlayers)"
            } else {
                "cannot create a Vulkan instance"
            }
        })?;
        let messenger = if validation {
            Some(instance.create_debug_utils_messenger_ext(&messenger_info)?)
        } else {
            None
        };
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
        let supported = physical.get_physical_device_features();
        let mut features = vk::PhysicalDeviceFeatures::default();
        for (wanted, have, slot, feature) in [
            (
                req.tessellation_shader,
                supported.tessellation_shader,
                &mut features.tessellation_shader,
                "tessellationShader",
            ),
            (
                req.fill_mode_non_solid,
                supported.fill_mode_non_solid,
                &mut features.fill_mode_non_solid,
                "fillModeNonSolid",
            ),
        ] {
            if wanted {
                if have == vk::FALSE {
                    bail!(
                        "the device \"{name}\" lacks the feature {feature}, which the {} scene needs",
                        req.scene
                    );
                }
                *slot = vk::TRUE;
            }
        }
        let mut device_exts = Vec::new();
        if req.window {
            let available = physical.enumerate_device_extension_properties(None)?;
            if !has_extension(&available, c"VK_KHR_swapchain") {
                bail!(
                    "the device \"{name}\" lacks the extension VK_KHR_swapchain, which the {} \
                     scene needs to render into a window",
                    req.scene
                );
            }
            device_exts.push(tuff::CStrPtr::from(c"VK_KHR_swapchain"));
        }
        let family = physical
            .get_physical_device_queue_family_properties()?
            .iter()
            .position(|f| f.queue_flags.contains(vk::QueueFlags::GRAPHICS))
            .ok_or_else(|| anyhow!("the device \"{name}\" has no graphics queue"))?
            as u32;
        let priorities = [1.0f32];
        let queues = [tuff::DeviceQueueCreateInfo::new()
            .queue_family_index(family)
            .queue_priorities(&priorities)];
        let device = physical
            .create_device(
                &tuff::DeviceCreateInfo::new()
                    .queue_create_infos(&queues)
                    .enabled_extension_names(&device_exts)
                    .enabled_features(Some(&features)),
            )
            .with_context(|| format!("cannot create a device on \"{name}\""))?;
        let queue = device.get_device_queue(family, 0);
        let memory_types = physical.get_physical_device_memory_properties();
        Ok(Gpu {
            queue,
            family,
            device,
            physical,
            name,
            memory_types,
            messenger,
            instance,
            messages,
            _user_data: user_data,
        })
    }

    /// Drops the device and instance and returns what the validation layer reported
    /// over the whole run, including while objects were destroyed. Drop every object
    /// made from this device first.
    pub fn finish(self) -> Vec<String> {
        let Gpu {
            queue,
            device,
            physical,
            messenger,
            instance,
            messages,
            _user_data,
            ..
        } = self;
        drop((queue, device, physical));
        drop(messenger);
        drop(instance);
        let out = messages.lock().map(|m| m.clone()).unwrap_or_default();
        drop(_user_data);
        out
    }

    /// A memory type allowed by `bits` with `flags`.
    pub fn memory_type(&self, bits: u32, flags: vk::MemoryPropertyFlags) -> Result<u32> {
        (0..self.memory_types.memory_type_count)
            .find(|i| {
                bits & (1 << i) != 0
                    && self.memory_types.memory_types[*i as usize]
                        .property_flags
                        .contains(flags)
            })
            .ok_or_else(|| anyhow!("\"{}\" has no memory type with {flags:?}", self.name))
    }

    /// A buffer bound to memory of its own with `flags`.
    pub fn buffer(
        &self,
        size: u64,
        usage: vk::BufferUsageFlags,
        flags: vk::MemoryPropertyFlags,
    ) -> Result<(tuff::Buffer, tuff::DeviceMemory)> {
        let d = &self.device;
        let buffer = d.create_buffer(&tuff::BufferCreateInfo::new().size(size).usage(usage))?;
        let reqs = d.get_buffer_memory_requirements(&buffer)?;
        let memory = d.allocate_memory(
            &tuff::MemoryAllocateInfo::new()
                .allocation_size(reqs.size)
                .memory_type_index(self.memory_type(reqs.memory_type_bits, flags)?),
        )?;
        d.bind_buffer_memory(&buffer, &memory, 0)?;
        Ok((buffer, memory))
    }

    /// A host-visible buffer holding `data`.
    pub fn buffer_with<T: bytemuck::NoUninit>(
        &self,
        usage: vk::BufferUsageFlags,
        data: &[T],
    ) -> Result<(tuff::Buffer, tuff::DeviceMemory)> {
        let size = std::mem::size_of_val(data).max(4) as u64;
        let (buffer, memory) = self.buffer(size, usage, HOST)?;
        memory.map()?.write(0, data)?;
        Ok((buffer, memory))
    }

    /// A 2D image with its own memory.
    pub fn image(
        &self,
        extent: vk::Extent2D,
        format: vk::Format,
        usage: vk::ImageUsageFlags,
    ) -> Result<(tuff::Image, tuff::DeviceMemory)> {
        let d = &self.device;
        let image = d.create_image(
            &tuff::ImageCreateInfo::new()
                .image_type(vk::ImageType::TYPE_2D)
                .format(format)
                .extent(extent.into())
                .mip_levels(1)
                .array_layers(1)
                .samples(vk::SampleCountFlags::TYPE_1)
                .usage(usage),
        )?;
        let reqs = d.get_image_memory_requirements(&image)?;
        let memory = d.allocate_memory(
            &tuff::MemoryAllocateInfo::new()
                .allocation_size(reqs.size)
                .memory_type_index(
                    self.memory_type(reqs.memory_type_bits, vk::MemoryPropertyFlags::empty())?,
                ),
        )?;
        d.bind_image_memory(&image, &memory, 0)?;
        Ok((image, memory))
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
        let words: Vec<u32> = spirv
            .chunks_exact(4)
            .map(|w| u32::from_le_bytes([w[0], w[1], w[2], w[3]]))
            .collect();
        Ok(self
            .device
            .create_shader_module(&tuff::ShaderModuleCreateInfo::new().code(&words))?)
    }
}

/// Memory the host writes and reads without flushes: buffers the CPU fills each
/// frame and the readback.
pub const HOST: vk::MemoryPropertyFlags = vk::MemoryPropertyFlags::from_raw(
    vk::MemoryPropertyFlags::HOST_VISIBLE.as_raw()
        | vk::MemoryPropertyFlags::HOST_COHERENT.as_raw(),
);

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
