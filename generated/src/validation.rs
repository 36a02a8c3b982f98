//! What the dynamic checks of implicit rules share: the objects each
//! device and instance created, and the scope a check runs in (the versions and
//! extensions enabled where the command is called).

// Which checks exist depends on the extension features enabled.
#![allow(dead_code)]

use crate::checks::Exts;
use crate::handles::{Device, Instance};
use crate::state::Features;
use crate::Handle;
use ash::vk;
use tuff_runtime::Vutex;

/// The objects created, allocated or retrieved from one device or instance. Counted,
/// because non-dispatchable handles need not be unique.
pub(crate) struct Objects(Vutex<crate::state::HashMap<(vk::ObjectType, u64), u32>>);

impl Default for Objects {
    fn default() -> Self {
        Objects(Vutex::new(crate::state::HashMap::default()))
    }
}

impl Objects {
    pub(crate) fn add<H: vk::Handle>(&self, raw: H) {
        *self.0.lock().entry((H::TYPE, raw.as_raw())).or_insert(0) += 1;
    }

    pub(crate) fn remove<H: vk::Handle>(&self, raw: H) {
        let mut map = self.0.lock();
        let key = (H::TYPE, raw.as_raw());
        if let Some(n) = map.get_mut(&key) {
            *n -= 1;
            if *n == 0 {
                map.remove(&key);
            }
        }
    }

    pub(crate) fn contains<H: vk::Handle>(&self, raw: H) -> bool {
        self.contains_raw(H::TYPE, raw.as_raw())
    }

    pub(crate) fn contains_raw(&self, ty: vk::ObjectType, raw: u64) -> bool {
        self.0.lock().contains_key(&(ty, raw))
    }
}

pub(crate) use crate::state::Kept;

/// What a walk over a struct (`crate::reach`) found, by what the walk is for: the
/// live objects it names, for the wrapper or recording that must keep them
/// ([`Reached::keeping`]); or the first handle it names that is no object of the
/// call's device or instance, with the rule that handle breaks
/// ([`Reached::checking`]). A driver reached through a handle of another device
/// reads that device's memory as its own, so every handle a struct carries is
/// checked before any other check or driver call sees it.
pub(crate) struct Reached<'a> {
    keep: Option<&'a crate::state::Live>,
    scope: Option<&'a Scope<'a>>,
    /// The live objects found, when keeping.
    pub(crate) kept: Kept,
    foreign: Option<(&'static str, vk::ObjectType, u64)>,
}

impl<'a> Reached<'a> {
    /// A walk that collects the live objects of `live` it finds.
    pub(crate) fn keeping(live: &'a crate::state::Live) -> Reached<'a> {
        Reached {
            keep: Some(live),
            scope: None,
            kept: Kept::new(),
            foreign: None,
        }
    }

    /// A walk that checks every handle it finds against the objects of `scope`.
    pub(crate) fn checking(scope: &'a Scope<'a>) -> Reached<'a> {
        Reached {
            keep: None,
            scope: Some(scope),
            kept: Kept::new(),
            foreign: None,
        }
    }

    /// A handle of a type whose objects come from a device; `rule` is the one it
    /// breaks if it is not the call's device's (`""`: not checked, only kept).
    #[inline]
    pub(crate) fn device_handle<H: vk::Handle>(&mut self, rule: &'static str, h: H) {
        self.raw(rule, H::TYPE, h.as_raw(), true);
    }

    /// A handle of a type whose objects come from an instance (a surface, a display).
    #[inline]
    pub(crate) fn instance_handle<H: vk::Handle>(&mut self, rule: &'static str, h: H) {
        self.raw(rule, H::TYPE, h.as_raw(), false);
    }

    /// Each handle of a slice of device objects.
    #[inline]
    pub(crate) fn device_handles<H: vk::Handle + Copy>(&mut self, rule: &'static str, hs: &[H]) {
        for h in hs {
            self.raw(rule, H::TYPE, h.as_raw(), true);
        }
    }

    /// Each handle of a slice of instance objects.
    #[inline]
    pub(crate) fn instance_handles<H: vk::Handle + Copy>(&mut self, rule: &'static str, hs: &[H]) {
        for h in hs {
            self.raw(rule, H::TYPE, h.as_raw(), false);
        }
    }

    fn raw(&mut self, rule: &'static str, ty: vk::ObjectType, raw: u64, of_device: bool) {
        // A null handle names nothing; where it is not allowed, the member's own
        // rule refuses it.
        if raw == 0 {
            return;
        }
        if let Some(live) = self.keep {
            self.kept.extend(live.get_raw(ty, raw));
        }
        // A member the walk does not check comes with no rule.
        if let Some(s) = self.scope.filter(|_| !rule.is_empty()) {
            let device = s.device.is_some_and(|d| d.objects().contains_raw(ty, raw));
            let instance = !of_device
                && s.instance
                    .is_some_and(|i| i.objects().contains_raw(ty, raw));
            if !device && !instance && self.foreign.is_none() {
                self.foreign = Some((rule, ty, raw));
            }
        }
    }

    /// Stops checking (what the walk finds is still kept) until
    /// [`Reached::resume_checks`] is given what this returns.
    #[inline]
    pub(crate) fn pause_checks(&mut self) -> Option<&'a Scope<'a>> {
        self.scope.take()
    }

    /// Checks again as before [`Reached::pause_checks`].
    #[inline]
    pub(crate) fn resume_checks(&mut self, scope: Option<&'a Scope<'a>>) {
        self.scope = scope;
    }

    /// Refuses a walk that found a handle of another device or instance.
    pub(crate) fn owned(&self) -> crate::Result<()> {
        match self.foreign {
            None => Ok(()),
            Some((rule, ty, raw)) => crate::support::refuse(
                rule,
                format!("a struct names {ty:?} {raw:#x}, which is not an object of the device (or instance) the command is called on"),
            ),
        }
    }
}

/// Where a command runs: what is enabled there, and the instance and device whose
/// objects it may use.
pub(crate) struct Scope<'a> {
    pub(crate) exts: Exts,
    pub(crate) instance: Option<&'a Instance>,
    pub(crate) device: Option<&'a Device>,
}

impl<'a> Scope<'a> {
    /// Whether any of `origins` (indices of versions and extensions that define an
    /// enum value) is enabled.
    #[inline]
    pub(crate) fn enabled(&self, origins: &[u16]) -> bool {
        origins.iter().any(|&i| self.exts.has(i))
    }

    /// Whether a core feature is enabled on the scope's device. Without a device in
    /// scope the answer is yes, so a rule that applies only when a feature is off
    /// is not enforced where the feature cannot be known.
    #[inline]
    pub(crate) fn feature(&self, get: impl FnOnce(&Features) -> vk::Bool32) -> bool {
        self.device
            .is_none_or(|d| d.live().with_features(|f| get(f) != vk::FALSE))
    }

    /// The record of a buffer made through the wrappers on the scope's device.
    #[inline]
    pub(crate) fn buffer(&self, raw: vk::Buffer) -> Option<crate::state::BufferRecord> {
        self.device.and_then(|d| d.live().buffer(raw))
    }

    /// The record of an image made through the wrappers on the scope's device.
    #[inline]
    pub(crate) fn image(&self, raw: vk::Image) -> Option<crate::state::ImageRecord> {
        self.device.and_then(|d| d.live().image(raw))
    }

    /// The limits of the scope's physical device, where the scope has a device.
    #[inline]
    pub(crate) fn limits(&self) -> Option<&'a vk::PhysicalDeviceLimits> {
        self.device.map(crate::state::limits)
    }

    /// Whether `raw` was created, allocated or retrieved from the scope's device.
    pub(crate) fn owned_by_device<H: vk::Handle + Copy>(&self, raw: H) -> bool {
        self.device.is_some_and(|d| d.objects().contains(raw))
    }

    /// Whether `raw` comes from the scope's instance, directly or through its device.
    pub(crate) fn owned_by_instance<H: vk::Handle + Copy>(&self, raw: H) -> bool {
        self.instance.is_some_and(|i| i.objects().contains(raw)) || self.owned_by_device(raw)
    }
}

impl Instance {
    /// The scope of a command called on this instance or one of its physical devices.
    pub(crate) fn scope(&self) -> Scope<'_> {
        Scope {
            exts: self.exts(),
            instance: Some(self),
            device: None,
        }
    }
}

impl Device {
    /// The scope of a command called on this device or one of its queues or command
    /// buffers.
    pub(crate) fn scope(&self) -> Scope<'_> {
        Scope {
            exts: self.exts(),
            instance: Some(self.parent().parent()),
            device: Some(self),
        }
    }
}

/// Whether the queue flags of a family support a command that needs any of `needed`.
/// Graphics and compute families also support transfer.
#[inline]
pub(crate) fn supports(flags: vk::QueueFlags, needed: vk::QueueFlags) -> bool {
    let mut flags = flags;
    if flags.intersects(vk::QueueFlags::GRAPHICS | vk::QueueFlags::COMPUTE) {
        flags |= vk::QueueFlags::TRANSFER;
    }
    flags.intersects(needed)
}

/// The queue flags of `family` on the device's physical device.
pub(crate) fn family_flags(device: &Device, family: u32) -> vk::QueueFlags {
    let physical = device.parent();
    // SAFETY: the physical device is a live wrapper of its instance.
    let families = unsafe {
        physical
            .parent()
            .fns()
            .get_physical_device_queue_family_properties(physical.raw())
    };
    families
        .get(family as usize)
        .map_or(vk::QueueFlags::empty(), |f| f.queue_flags)
}

// The checks reach a struct inside a union that another member selects, and only
// the member the selector names (no device has these extensions on lavapipe, so the
// walk is shown on the checks themselves, in a scope that enables them).
#[cfg(all(
    test,
    feature = "khr_acceleration_structure",
    feature = "ext_descriptor_buffer"
))]
mod tests {
    use super::Scope;
    use crate::checks::Exts;
    use crate::*;

    fn scope() -> Scope<'static> {
        Scope {
            exts: Exts::new(
                3,
                &[
                    c"VK_KHR_acceleration_structure",
                    c"VK_EXT_descriptor_buffer",
                ],
            ),
            instance: None,
            device: None,
        }
    }

    fn vuid(r: crate::Result<()>) -> Option<&'static str> {
        match r {
            Err(Error::Validation { vuid, .. }) => Some(vuid),
            _ => None,
        }
    }

    #[test]
    fn a_selected_union_member_is_checked() {
        let s = scope();
        let bad = vk::Format::from_raw(0x7fff_0001);
        let triangles = AccelerationStructureGeometryTrianglesDataKHR::default()
            .vertex_format(vk::Format::R32G32B32_SFLOAT)
            .index_type(vk::IndexType::UINT32);
        let good = AccelerationStructureGeometryKHR::new(
            AccelerationStructureGeometryDataKHR::Triangles(triangles),
        );
        assert_eq!(
            vuid(crate::checks::check_acceleration_structure_geometry_khr(
                good.as_raw(),
                &s
            )),
            None
        );
        let geometry = AccelerationStructureGeometryKHR::new(
            AccelerationStructureGeometryDataKHR::Triangles(triangles.vertex_format(bad)),
        );
        assert_eq!(
            vuid(crate::checks::check_acceleration_structure_geometry_khr(
                geometry.as_raw(),
                &s
            )),
            Some("VUID-VkAccelerationStructureGeometryTrianglesDataKHR-vertexFormat-parameter")
        );
    }

    #[test]
    fn a_selected_pointer_member_is_checked() {
        let s = scope();
        let address = DescriptorAddressInfoEXT::default()
            .range(256)
            .format(vk::Format::from_raw(0x7fff_0003));
        let info = DescriptorGetInfoEXT::new(DescriptorDataEXT::UniformTexelBuffer(Some(&address)));
        assert_eq!(
            vuid(crate::checks::check_descriptor_get_info_ext(
                info.as_raw(),
                &s
            )),
            Some("VUID-VkDescriptorAddressInfoEXT-format-parameter")
        );
        // A null member (no descriptor) has nothing to check.
        let info = DescriptorGetInfoEXT::new(DescriptorDataEXT::UniformTexelBuffer(None));
        assert_eq!(
            vuid(crate::checks::check_descriptor_get_info_ext(
                info.as_raw(),
                &s
            )),
            None
        );
    }
}
