//! A Vulkan 1.4 program through tuff regenerated with `api_version = "1.4"` on ash
//! 0.38, which has no function table for 1.4: `vkGetRenderingAreaGranularity`
//! (maintenance5, core in 1.4) through the crate's own `DeviceFnV1_4`, called by its
//! core name. On a device below 1.4 (lavapipe in the test command) the call is
//! refused with `Error::VersionNotSupported`; on a 1.4 device it returns the
//! granularity. Either way, under the validation layer when it is installed, and the
//! program fails on any message the layer reports, or when the outcome does not match
//! the device's version. It also reads the device's Vulkan 1.4 features through
//! `vk::PhysicalDeviceVulkan14Features`, a struct ash 0.38 lacks that the crate defines
//! in ash's style (its delta), chained into ash's own `PhysicalDeviceFeatures2`. Where
//! the device offers `VK_KHR_pipeline_binary`, an extension ash lacks altogether, it
//! enables it, reads its properties through the delta's struct and checks that the
//! crate's own function table for it (`vk::khr::pipeline_binary::DeviceFn`) loaded.
//!
//! `bash scripts/core14.sh` generates the crate, builds this and runs it.

use std::process::ExitCode;
use tuff::{vk, Handle as _};

fn main() -> ExitCode {
    match run() {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("core14: {e}");
            ExitCode::FAILURE
        }
    }
}

fn run() -> Result<(), Box<dyn std::error::Error>> {
    let entry = tuff::Entry::load()?;
    let log = tuff::MessageLog::new();
    let validation = std::env::var("CORE14_NO_LAYER").is_err();
    let exts = [tuff::CStrPtr::new(c"VK_EXT_debug_utils")];
    let layers = [tuff::CStrPtr::from(c"VK_LAYER_KHRONOS_validation")];
    // ash 0.38 has no `API_VERSION_1_4`: the crate's delta defines it.
    let app = tuff::ApplicationInfo::new().api_version(vk::API_VERSION_1_4);
    let mut chained = log.messenger_info();
    let mut info = tuff::InstanceCreateInfo::new()
        .application_info(Some(&app))
        .enabled_extension_names(&exts);
    if validation {
        info = info.enabled_layer_names(&layers).push_next(&mut chained);
    }
    // SAFETY: from the 1.4.309 registry, vkCreateInstance has rules tuff does not
    // check yet, which make the method unsafe there (its `# Safety` lists them); this
    // info chains only the debug messenger's create info and enables only
    // VK_EXT_debug_utils and the validation layer, which break none of them.
    let instance = unsafe { entry.create_instance(&info) }?;
    // The chained info covers the instance's creation and destruction; this one the
    // rest of its life.
    let messenger = validation
        .then(|| instance.create_debug_utils_messenger_ext(&log.messenger_info()))
        .transpose()?;
    let physicals = instance.enumerate_physical_devices()?;
    let wanted = std::env::var("TUFF_DEVICE").unwrap_or_default();
    let physical = physicals
        .iter()
        .find(|p| p.name().contains(&wanted))
        .ok_or("no Vulkan device (TUFF_DEVICE picks one by name)")?;
    let props = physical.get_properties();
    let version = props.api_version;
    println!(
        "device: {} (Vulkan {}.{}.{}), instance apiVersion 1.4",
        physical.name(),
        vk::api_version_major(version),
        vk::api_version_minor(version),
        vk::api_version_patch(version)
    );
    if vk::api_version_minor(version) >= 4 {
        let mut v14 = vk::PhysicalDeviceVulkan14Features::default();
        let mut features = vk::PhysicalDeviceFeatures2::default().push_next(&mut v14);
        // SAFETY: a live physical device of a Vulkan 1.4 instance, on a 1.4 device
        // (vkGetPhysicalDeviceFeatures2 may be given VkPhysicalDeviceVulkan14Features
        // there); the chain is local and well formed (ash's push_next, the delta's
        // sType).
        unsafe {
            instance
                .fns()
                .get_physical_device_features2(physical.raw(), &mut features)
        };
        println!(
            "Vulkan 1.4 features (vk::PhysicalDeviceVulkan14Features): pushDescriptor {}, maintenance5 {}, maintenance6 {}, dynamicRenderingLocalRead {}, hostImageCopy {}",
            v14.push_descriptor, v14.maintenance5, v14.maintenance6,
            v14.dynamic_rendering_local_read, v14.host_image_copy
        );
    }
    let family = physical
        .queue_family_index(vk::QueueFlags::GRAPHICS)?
        .ok_or("no graphics queue")?;
    let queues = [tuff::DeviceQueueCreateInfo::new()
        .queue_family_index(family)
        .queue_priorities(&[1.0])];
    // VK_KHR_pipeline_binary, an extension ash 0.38 lacks altogether: its handle, its
    // structs and its function table are the crate's own. Enabled where the device
    // offers it (on a 1.4 device, whose maintenance5 it needs).
    let offered = physical.enumerate_device_extension_properties(None)?;
    let binary = c"VK_KHR_pipeline_binary";
    let has_binary = vk::api_version_minor(version) >= 4
        && offered
            .iter()
            .any(|e| e.extension_name_as_c_str() == Ok(binary));
    let device_exts = [tuff::CStrPtr::new(binary)];
    let mut device_info = tuff::DeviceCreateInfo::new().queue_create_infos(&queues);
    if has_binary {
        device_info = device_info.enabled_extension_names(&device_exts);
    }
    // SAFETY: as for the instance: vkCreateDevice's rules of the 1.4.309 registry
    // that tuff does not check are about chained feature structs, enabled features
    // and extensions; this info chains nothing, and enables at most
    // VK_KHR_pipeline_binary, on a device that offers it and is 1.4 (so has
    // maintenance5, which it depends on), with none of its features.
    let device = unsafe { physical.create_device(&device_info) }?;
    println!(
        "DeviceFnV1_4 loaded: {}",
        if device.ext().v1_4.is_some() {
            "yes"
        } else {
            "no"
        }
    );
    if has_binary {
        let mut binary_props = vk::PhysicalDevicePipelineBinaryPropertiesKHR::default();
        let mut props = vk::PhysicalDeviceProperties2::default().push_next(&mut binary_props);
        // SAFETY: a live physical device; the chain is local and well formed (ash's
        // push_next, the delta's sType), and the device offers the extension whose
        // struct it chains.
        unsafe {
            instance
                .fns()
                .get_physical_device_properties2(physical.raw(), &mut props)
        };
        println!(
            "VK_KHR_pipeline_binary (ash lacks it): enabled, vk::khr::pipeline_binary::DeviceFn loaded: {}; pipelineBinaryInternalCache {}, pipelineBinaryPrefersInternalCache {}",
            if device.ext().khr_pipeline_binary.is_some() {
                "yes"
            } else {
                "no"
            },
            binary_props.pipeline_binary_internal_cache,
            binary_props.pipeline_binary_prefers_internal_cache
        );
        if device.ext().khr_pipeline_binary.is_none() {
            return Err("VK_KHR_pipeline_binary is enabled but its table did not load".into());
        }
    } else {
        println!("VK_KHR_pipeline_binary (ash lacks it): not offered by this device");
    }
    let formats = [vk::Format::R8G8B8A8_UNORM];
    let area = tuff::RenderingAreaInfoKHR::new()
        .color_attachment_formats(&formats)
        .depth_attachment_format(vk::Format::UNDEFINED);
    let is_14 = vk::api_version_minor(version) >= 4;
    match device.get_rendering_area_granularity(&area) {
        Ok(g) if is_14 => {
            println!(
                "vkGetRenderingAreaGranularity (R8G8B8A8_UNORM): {}x{}",
                g.width, g.height
            )
        }
        Err(e @ tuff::Error::VersionNotSupported(_)) if !is_14 => {
            println!("vkGetRenderingAreaGranularity refused, as it must be: {e}")
        }
        other => return Err(format!("unexpected outcome on this device: {other:?}").into()),
    }
    drop(device);
    drop(messenger);
    drop(instance);
    // Two notes are about the installation, not the program: shown, not failed on.
    // The loader's, that a layer built for an older version than the apiVersion asked
    // for is loaded (the installed validation layer is a 1.3 one); and that layer's,
    // that a struct in a chain is one it does not know, when the layer's headers
    // predate the 1.4.309 registry the struct comes from (it names its header
    // version). Anything else fails.
    let older_layer = |m: &str| {
        m.contains("unknown VkStructureType")
            && m.split("Valid Usage documentation for version ")
                .nth(1)
                .and_then(|rest| rest.split(' ').next())
                .and_then(|v| v.parse::<u32>().ok())
                .is_some_and(|v| v < 309)
    };
    let (notes, messages): (Vec<String>, Vec<String>) = log.take().into_iter().partition(|m| {
        (m.contains("uses API version")
            && m.contains("older than the application specified API version"))
            || older_layer(m)
    });
    for n in &notes {
        match older_layer(n) {
            true => println!(
                "layer: {}",
                n.split(". This error is based").next().unwrap_or(n)
            ),
            false => println!("loader: {n}"),
        }
    }
    if !messages.is_empty() {
        return Err(format!("the validation layer reported: {messages:#?}").into());
    }
    println!(
        "validation layer: {}",
        if validation { "on, no message" } else { "off" }
    );
    Ok(())
}
