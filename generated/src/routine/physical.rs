//! What choosing a physical device and a queue family asks every program to dig out
//! of raw property structs.
//!
//! ```no_run
//! # fn f(instance: &tuff::Instance) -> tuff::Result<()> {
//! for physical in instance.enumerate_physical_devices()? {
//!     let graphics = physical.queue_family_index(tuff::vk::QueueFlags::GRAPHICS)?;
//!     println!("{}: graphics queue family {graphics:?}", physical.name());
//! }
//! # Ok(()) }
//! ```

use crate::handles::PhysicalDevice;
use crate::Result;
use ash::vk;

impl PhysicalDevice {
    /// The device's name (`deviceName`), up to its terminating NUL; a name that has
    /// none, against the specification, is taken whole.
    pub fn name(&self) -> String {
        let properties = self.get_properties();
        match properties.device_name_as_c_str() {
            Ok(name) => name.to_string_lossy().into_owned(),
            Err(_) => {
                let bytes: Vec<u8> = properties.device_name.iter().map(|&c| c as u8).collect();
                String::from_utf8_lossy(&bytes).into_owned()
            }
        }
    }

    /// The index of the first queue family whose queues support all of `flags`, or
    /// `None` when no family does.
    pub fn queue_family_index(&self, flags: vk::QueueFlags) -> Result<Option<u32>> {
        let families = self.get_queue_family_properties()?;
        Ok(families
            .iter()
            .position(|f| f.queue_count > 0 && f.queue_flags.contains(flags))
            .and_then(|i| u32::try_from(i).ok()))
    }
}
