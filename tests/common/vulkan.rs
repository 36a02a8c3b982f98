//! A headless Vulkan device for tests and benchmarks: lavapipe on CI. With validation
//! on, the Khronos validation layer is required and every message it emits is
//! recorded, so a test can fail on any of them; a missing layer or device is a
//! failure, never a skip.
#![allow(dead_code)]

use ash::vk;
use std::ffi::CStr;
use std::sync::{Arc, Condvar, Mutex, MutexGuard};
use std::thread::ThreadId;
use tuff_runtime::{DeviceOwner, Vrc};

/// The thread whose test uses Vulkan now, and how many guards it holds.
static HOLDER: Mutex<Option<(ThreadId, usize)>> = Mutex::new(None);
/// Signalled when the holder lets go.
static RELEASED: Condvar = Condvar::new();

/// Keeps other tests of this binary away from Vulkan while it lives.
///
/// The validation layer (1.3.239, the one CI installs) keeps its instances and devices
/// in one process-wide table that it reads on every call and changes, without a lock,
/// in `vkCreate/DestroyInstance` and `vkCreate/DestroyDevice`
/// (KhronosGroup/Vulkan-ValidationLayers#4391). The test harness runs tests on
/// parallel threads, and one test's device teardown during another's
/// `vkBindBufferMemory` crashed inside the layer. So every test that uses Vulkan takes
/// this guard first, and holds it until all its objects are gone; a thread may take it
/// more than once.
#[must_use = "the guard serialises only while it lives"]
pub struct Serial(());

fn holder() -> MutexGuard<'static, Option<(ThreadId, usize)>> {
    // A test that panicked inside this tiny critical section left nothing half done.
    HOLDER.lock().unwrap_or_else(|e| e.into_inner())
}

/// Waits until no other thread uses Vulkan, then holds it for this thread.
pub fn serial() -> Serial {
    let me = std::thread::current().id();
    let mut holder = holder();
    loop {
        match &mut *holder {
            None => {
                *holder = Some((me, 1));
                return Serial(());
            }
            Some((id, count)) if *id == me => {
                *count += 1;
                return Serial(());
            }
            Some(_) => holder = RELEASED.wait(holder).unwrap_or_else(|e| e.into_inner()),
        }
    }
}

impl Drop for Serial {
    fn drop(&mut self) {
        let mut holder = holder();
        if let Some((_, count)) = &mut *holder {
            *count -= 1;
            if *count == 0 {
                *holder = None;
                RELEASED.notify_all();
            }
        }
    }
}

const VALIDATION: &CStr = c"VK_LAYER_KHRONOS_validation";

/// Where the validation layer's messages go: tuff's log, whose callback the raw-ash
/// instance uses too.
pub type Messages = Arc<tuff::MessageLog>;

/// The instance, and the debug messenger when validation is on.
pub struct TestInstance {
    pub entry: ash::Entry,
    pub instance: ash::Instance,
    debug: Option<(ash::ext::debug_utils::Instance, vk::DebugUtilsMessengerEXT)>,
}

impl Drop for TestInstance {
    fn drop(&mut self) {
        // SAFETY: everything created from the instance is gone: devices hold an Vrc of
        // this instance.
        unsafe {
            if let Some((utils, messenger)) = self.debug.take() {
                utils.destroy_debug_utils_messenger(messenger, None);
            }
            self.instance.destroy_instance(None);
        }
    }
}

/// A device, owned the way the generated `Device` wrapper will own it.
pub struct TestDevice {
    pub instance: Vrc<TestInstance>,
    pub physical: vk::PhysicalDevice,
    pub device: ash::Device,
    pub queue_family: u32,
    pub atom: u64,
    pub memory: vk::PhysicalDeviceMemoryProperties,
    pub name: String,
}

impl Drop for TestDevice {
    fn drop(&mut self) {
        // SAFETY: allocators and allocations hold a Vrc of this device, so nothing
        // created from it is alive any more.
        unsafe {
            let _ = self.device.device_wait_idle();
            self.device.destroy_device(None);
        }
    }
}

// SAFETY: the test device holds its instance and destroys its device only on drop,
// after every allocator and allocation holding it; `atom` is read from its limits.
unsafe impl DeviceOwner for TestDevice {
    fn instance(&self) -> &ash::Instance {
        &self.instance.instance
    }
    fn physical_device(&self) -> vk::PhysicalDevice {
        self.physical
    }
    fn device(&self) -> &ash::Device {
        &self.device
    }
    fn non_coherent_atom_size(&self) -> u64 {
        self.atom
    }
}

/// Create an instance (with the validation layer when `validation`) and a device with
/// one queue family that supports graphics. Panics with a clear message when the
/// loader, the layer or a device is missing.
pub fn device(validation: bool) -> (Vrc<TestDevice>, Messages) {
    // SAFETY: loading the system Vulkan loader.
    let entry = unsafe { ash::Entry::load() }
        .expect("the Vulkan loader (libvulkan.so.1) is not installed: apt-get install libvulkan1");
    let messages: Messages = Arc::new(tuff::MessageLog::new());

    let mut layers = Vec::new();
    let mut extensions = Vec::new();
    if validation {
        // SAFETY: plain enumeration.
        let available =
            unsafe { entry.enumerate_instance_layer_properties() }.expect("layers enumerate");
        assert!(
            available
                .iter()
                .any(|l| l.layer_name_as_c_str().ok() == Some(VALIDATION)),
            "VK_LAYER_KHRONOS_validation is not installed: apt-get install vulkan-validationlayers"
        );
        layers.push(VALIDATION.as_ptr());
        extensions.push(ash::ext::debug_utils::NAME.as_ptr());
    }
    let mut messenger_info = *messages.messenger_info().as_raw();
    let app = vk::ApplicationInfo::default()
        .application_name(c"tuff-tests")
        .api_version(vk::API_VERSION_1_3);
    let mut info = vk::InstanceCreateInfo::default()
        .application_info(&app)
        .enabled_layer_names(&layers)
        .enabled_extension_names(&extensions);
    if validation {
        // Also covers messages of vkCreateInstance and vkDestroyInstance.
        info = info.push_next(&mut messenger_info);
    }
    // SAFETY: valid create info; the names outlive the call.
    let instance = unsafe { entry.create_instance(&info, None) }.expect("vkCreateInstance");
    let debug = validation.then(|| {
        let utils = ash::ext::debug_utils::Instance::new(&entry, &instance);
        // SAFETY: valid create info; the log's callback is safe to outlive the log.
        let messenger = unsafe { utils.create_debug_utils_messenger(&messenger_info, None) }
            .expect("vkCreateDebugUtilsMessengerEXT");
        (utils, messenger)
    });
    let instance = Vrc::new(TestInstance {
        entry,
        instance,
        debug,
    });

    // SAFETY: plain queries on a live instance.
    let physicals =
        unsafe { instance.instance.enumerate_physical_devices() }.expect("devices enumerate");
    // Lavapipe (a CPU device) where present, so runs compare across machines.
    let is_cpu = |p: &vk::PhysicalDevice| {
        // SAFETY: a plain query on a live instance.
        let props = unsafe { instance.instance.get_physical_device_properties(*p) };
        props.device_type == vk::PhysicalDeviceType::CPU
    };
    let physical = physicals
        .iter()
        .find(|p| is_cpu(p))
        .or_else(|| physicals.first())
        .copied()
        .expect(
            "no Vulkan device found: install Mesa lavapipe (apt-get install mesa-vulkan-drivers)",
        );
    // SAFETY: as above.
    let (props, memory, families) = unsafe {
        (
            instance.instance.get_physical_device_properties(physical),
            instance
                .instance
                .get_physical_device_memory_properties(physical),
            instance
                .instance
                .get_physical_device_queue_family_properties(physical),
        )
    };
    let queue_family = families
        .iter()
        .position(|f| f.queue_flags.contains(vk::QueueFlags::GRAPHICS))
        .expect("the device has no graphics queue") as u32;
    let priorities = [1.0];
    let queues = [vk::DeviceQueueCreateInfo::default()
        .queue_family_index(queue_family)
        .queue_priorities(&priorities)];
    let device_info = vk::DeviceCreateInfo::default().queue_create_infos(&queues);
    // SAFETY: valid create info for this physical device.
    let device = unsafe {
        instance
            .instance
            .create_device(physical, &device_info, None)
    }
    .expect("vkCreateDevice");
    let name = props
        .device_name_as_c_str()
        .map(|n| n.to_string_lossy().into_owned())
        .unwrap_or_default();
    let owner = Vrc::new(TestDevice {
        instance,
        physical,
        device,
        queue_family,
        atom: props.limits.non_coherent_atom_size,
        memory,
        name,
    });
    (owner, messages)
}

/// Fail with every message the validation layer emitted.
pub fn assert_silent(messages: &tuff::MessageLog) {
    let m = messages.take();
    assert!(
        m.is_empty(),
        "the validation layer reported {} message(s):\n{}",
        m.len(),
        m.join("\n")
    );
}
