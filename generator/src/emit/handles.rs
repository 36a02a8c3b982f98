//! Emits `src/handles.rs`: one wrapper per handle type of the emitted API. A wrapper
//! is a cheap-to-clone reference (`Vrc`) to the raw handle and its parent; the last
//! clone to go destroys or frees the handle, so children keep parents alive and a
//! command buffer or a pending submission that holds a clone keeps what it uses alive.

use crate::names::{ash_extension_module, cfg_of, feature, ident, level, type_ident, Level};
use crate::plan::commands::parent_of;
use crate::plan::Context;
use proc_macro2::TokenStream;
use quote::quote;

/// Handles of the emitted API, in name order.
pub fn emitted_handles(cx: &Context) -> Vec<String> {
    cx.model
        .handles
        .keys()
        .filter(|n| cx.model.emitted.contains(*n))
        .cloned()
        .collect()
}

/// `.parent()` steps from `from` up to the wrapper of type `to`, or `None`.
pub fn path_to(cx: &Context, from: &str, to: &str) -> Option<TokenStream> {
    let mut steps = Vec::new();
    let mut current = from.to_owned();
    while current != to {
        current = parent_of(cx, &current)?;
        steps.push(quote!(.parent()));
        if steps.len() > 8 {
            return None;
        }
    }
    Some(quote!(#(#steps)*))
}

/// Like [`path_to`], from inside the wrapper's inner struct (whose parent is a field).
fn inner_path(cx: &Context, from: &str, to: &str) -> Option<TokenStream> {
    let path = path_to(cx, from, to)?.to_string();
    let path = path.replacen(". parent ()", ". parent", 1);
    path.parse().ok()
}

/// Extensions of the config with commands at `level`.
pub fn extensions_at(cx: &Context, at: Level) -> Vec<String> {
    let mut exts: Vec<String> = Vec::new();
    for c in cx.model.commands.values() {
        if c.alias.is_some()
            || !cx.model.emitted.contains(&c.name)
            || level(cx.model, &c.name) != at
        {
            continue;
        }
        if let Some(crate::names::Table::Extension(e)) = crate::names::table(cx.model, &c.name) {
            if !exts.contains(&e) {
                exts.push(e);
            }
        }
    }
    exts.sort();
    exts
}

/// Handles bound to memory by a `vkBind*Memory` command of the emitted API.
pub fn memory_bound(cx: &Context, handle: &str) -> bool {
    cx.model.commands.values().any(|c| {
        c.alias.is_none()
            && cx.model.emitted.contains(&c.name)
            && c.name.starts_with("vkBind")
            && c.name.ends_with("Memory")
            && c.params.get(1).is_some_and(|p| p.type_name == handle)
    })
}

pub(super) fn emit(cx: &Context) -> TokenStream {
    let mut items = Vec::new();
    for h in emitted_handles(cx) {
        items.push(match h.as_str() {
            "VkInstance" => emit_instance(cx),
            "VkDevice" => emit_device(cx),
            _ => emit_handle(cx, &h),
        });
    }
    quote! {
        //! Handle wrappers. Each derefs to its raw `ash::vk` handle, so anything the
        //! wrappers lack can still be called through ash.
        #![allow(clippy::new_without_default, clippy::let_and_return)]
        // `from_raw` binds the new wrapper before returning it because device objects
        // are listed among the live objects in between; others return it unchanged.
        use crate::{support::child_handle, Entry, Handle};
        use crate::vk;
        use tuff_runtime::{Retained, Vrc, Vutex};
        #(#items)*
    }
}

/// The struct of extension function tables at `at`, and the statements that fill it
/// for the enabled extensions, calling ash's `<module>::<kind>::new(#loader_args)`.
fn ext_tables(
    cx: &Context,
    at: Level,
    kind: &str,
    loader_args: TokenStream,
    own_fields: Vec<TokenStream>,
) -> (TokenStream, Vec<TokenStream>) {
    let struct_name = ident(&format!("{kind}Extensions"));
    let kind_ext = format!("{kind}Extensions");
    let fn_ty = ident(&format!("{kind}Fn"));
    let loader = ident(kind);
    let mut fields = Vec::new();
    let mut loads = Vec::new();
    for e in &extensions_at(cx, at) {
        let f = ident(&feature(e));
        let feat = feature(e);
        // An extension ash lacks has its table in the delta, under ash's path.
        let own = cx.model.own_extensions.contains(e);
        let module = match own {
            true => {
                let (vendor, name) = super::delta::own_module(e);
                let (vendor, name) = (ident(&vendor), ident(&name));
                quote!(crate::delta::#vendor::#name)
            }
            false => ash_extension_module(e),
        };
        let doc = format!("`{e}`'s commands, when the extension is enabled.");
        fields.push(quote! {
            #[cfg(feature = #feat)]
            #[doc = #doc]
            pub #f: Option<#module::#fn_ty>,
        });
        let name_lit = e.as_str();
        // An instance extension's device-level commands (debug names) are there when
        // the instance enabled it; the device's own list never names it.
        let instance_ext = at == Level::Device && cx.model.instance_extensions.contains(e);
        let enabled = if instance_ext {
            quote!(physical.parent().ext().#f.is_some())
        } else {
            quote!(enabled.iter().any(|n| n.to_bytes() == #name_lit.as_bytes()))
        };
        let load = match own {
            true => quote!(#module::#fn_ty::load_from(#loader_args)),
            false => quote!(Some(#module::#loader::new(#loader_args).fp().clone())),
        };
        loads.push(quote! {
            #[cfg(feature = #feat)]
            if #enabled {
                ext.#f = #load;
            }
        });
    }
    let doc = format!(
        "The function tables of the enabled {} extensions.",
        kind.to_lowercase()
    );
    (
        quote! {
            #[doc = #doc]
            #[derive(Clone, Default)]
            #[allow(missing_copy_implementations)]
            pub struct #struct_name {
                #(#fields)*
                #(#own_fields)*
            }
            impl core::fmt::Debug for #struct_name {
                fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
                    f.debug_struct(#kind_ext).finish_non_exhaustive()
                }
            }
        },
        loads,
    )
}

/// The function tables the crate defines for the core versions ash has none for
/// (`Model::own_tables`), at device level: each table's struct, its field of
/// `DeviceExtensions`, and the statement that loads it when the device's version
/// (capped by the instance's) is at least the table's. Each field is typed by the
/// `PFN_` type ash has for the command under the name it knows it by (the extension
/// alias a version promoted), and loaded by the command's core name.
fn own_device_tables(cx: &Context) -> (TokenStream, Vec<TokenStream>, Vec<TokenStream>) {
    let model = cx.model;
    let mut defs = Vec::new();
    let mut fields = Vec::new();
    let mut loads = Vec::new();
    for m in &model.own_tables {
        let commands: Vec<&String> = model
            .commands
            .values()
            .filter(|c| {
                c.alias.is_none()
                    && model.emitted.contains(&c.name)
                    && level(model, &c.name) == Level::Device
                    && crate::names::table(model, &c.name) == Some(crate::names::Table::Own(*m))
            })
            .map(|c| &c.name)
            .collect();
        if commands.is_empty() {
            continue;
        }
        let struct_name = ident(&format!("DeviceFnV1_{m}"));
        let field = ident(&format!("v1_{m}"));
        let version = format!("VK_VERSION_1_{m}");
        let entries: Vec<super::delta::TableEntry> = commands
            .iter()
            .map(|c| super::delta::TableEntry {
                field: ident(&crate::names::command_fn(c)),
                pfn: {
                    let pfn = ident(&format!("PFN_{}", model.spelling(c)));
                    quote!(vk::#pfn)
                },
                name: (*c).clone(),
            })
            .collect();
        defs.push(super::delta::fn_table(
            &struct_name,
            &format!(
                "`{version}`'s device-level commands, which ash has no function table for: loaded by their core names through `vkGetDeviceProcAddr`."
            ),
            &format!(
                "Loads every command of the table for `device`; `None` if the loader lacks one (a device below Vulkan 1.{m} gives none)."
            ),
            quote!(load(instance: &ash::Instance, device: vk::Device)),
            quote! {
                __safety!("`device` is a live device of `instance`, and `name` a NUL-terminated string.");
                unsafe { (instance.fp_v1_0().get_device_proc_addr)(device, name.as_ptr()) }
            },
            "that of the `PFN_` type of ash's name for it (the same command under the extension alias it was promoted from)",
            &entries,
        ));
        let field_doc =
            format!("`{version}`'s commands, when the device's version is at least 1.{m}.");
        fields.push(quote! {
            #[doc = #field_doc]
            pub #field: Option<#struct_name>,
        });
        let minor = *m;
        loads.push(quote! {
            if exts.version(#minor) {
                ext.#field = #struct_name::load(physical.parent().fns(), raw);
            }
        });
    }
    (quote!(#(#defs)*), fields, loads)
}

fn emit_instance(cx: &Context) -> TokenStream {
    let (ext_struct, load_stmts) = ext_tables(
        cx,
        Level::Instance,
        "Instance",
        quote!(entry.fns(), &fns),
        Vec::new(),
    );
    quote! {
        #ext_struct

        /// A Vulkan instance: the loader's function tables and the extensions enabled on
        /// it. Clones share it; the last one destroys it.
        #[derive(Clone)]
        pub struct Instance {
            inner: Vrc<InstanceInner>,
        }
        struct InstanceInner {
            raw: vk::Instance,
            entry: Entry,
            fns: ash::Instance,
            ext: InstanceExtensions,
            exts: crate::checks::Exts,
            objects: crate::validation::Objects,
        }
        impl Instance {
            /// Wraps an instance created by [`Entry::create_instance`].
            pub(crate) fn from_created(entry: &Entry, raw: vk::Instance, enabled: &[&core::ffi::CStr], api_version: u32) -> Instance {
                __safety!("`raw` was just created from `entry`'s loader.");
                let fns = unsafe { ash::Instance::load(entry.fns().static_fn(), raw) };
                #[allow(unused_mut)]
                let mut ext = InstanceExtensions::default();
                let _ = enabled;
                #(#load_stmts)*
                let _ = api_version;
                Instance { inner: Vrc::new(InstanceInner {
                    raw, entry: entry.clone(), fns, ext,
                    exts: crate::checks::Exts::new(vk::api_version_minor(api_version), enabled),
                    objects: Default::default(),
                }) }
            }
            /// The versions and extensions enabled on this instance.
            pub(crate) fn exts(&self) -> crate::checks::Exts {
                self.inner.exts
            }
            /// The objects created from this instance.
            pub(crate) fn objects(&self) -> &crate::validation::Objects {
                &self.inner.objects
            }
            /// ash's instance-level function tables.
            #[inline]
            pub fn fns(&self) -> &ash::Instance {
                &self.inner.fns
            }
            /// The extension function tables loaded for this instance.
            #[inline]
            pub fn ext(&self) -> &InstanceExtensions {
                &self.inner.ext
            }
            /// The loader this instance was created from.
            #[inline]
            pub fn entry(&self) -> &Entry {
                &self.inner.entry
            }
        }
        impl core::fmt::Debug for Instance {
            fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
                f.debug_tuple("Instance").field(&self.inner.raw).finish()
            }
        }
        impl Handle for Instance {
            type Raw = vk::Instance;
            #[inline]
            fn raw(&self) -> vk::Instance {
                self.inner.raw
            }
            #[inline]
            fn raw_ref(&self) -> &vk::Instance {
                &self.inner.raw
            }
        }
        impl core::ops::Deref for Instance {
            type Target = vk::Instance;
            #[inline]
            fn deref(&self) -> &vk::Instance {
                &self.inner.raw
            }
        }
        impl Drop for InstanceInner {
            fn drop(&mut self) {
                __safety!("every child holds a clone of the instance, so none is left (VUID-vkDestroyInstance-instance-00629); the callbacks it was created with, which the entry it holds keeps alive (VUID-vkDestroyInstance-instance-00630, -00631).");
                unsafe {
                    (self.fns.fp_v1_0().destroy_instance)(
                        self.fns.handle(),
                        crate::memory::host::HostCallbacks::host_callbacks(&self.entry),
                    )
                };
            }
        }
    }
}

fn emit_device(cx: &Context) -> TokenStream {
    let (own_defs, own_fields, own_loads) = own_device_tables(cx);
    let (ext_struct, load_stmts) = ext_tables(
        cx,
        Level::Device,
        "Device",
        quote!(physical.parent().fns(), &fns),
        own_fields,
    );
    quote! {
        #ext_struct
        #own_defs

        /// A logical device: its function tables and the extensions enabled on it.
        /// Clones share it; the last one waits for the device to go idle and destroys it.
        #[derive(Clone)]
        pub struct Device {
            inner: Vrc<DeviceInner>,
        }
        struct DeviceInner {
            raw: vk::Device,
            physical: PhysicalDevice,
            fns: ash::Device,
            ext: DeviceExtensions,
            command_buffers: Vutex<rustc_hash::FxHashMap<vk::CommandBuffer, Vrc<crate::state::Uses>>>,
            live: crate::state::Live,
            exts: crate::checks::Exts,
            objects: crate::validation::Objects,
        }
        impl Device {
            pub(crate) fn from_created(physical: &PhysicalDevice, raw: vk::Device, enabled: &[&core::ffi::CStr]) -> Device {
                __safety!("`raw` was just created from this physical device's instance.");
                let fns = unsafe { ash::Device::load(physical.parent().fns().fp_v1_0(), raw) };
                #[allow(unused_mut)]
                let mut ext = DeviceExtensions::default();
                let _ = enabled;
                #(#load_stmts)*
                let exts = {
                    let instance = physical.parent();
                    __safety!("the physical device is a live wrapper of its instance.");
                    let props = unsafe { instance.fns().get_physical_device_properties(physical.raw()) };
                    instance.exts().cap(vk::api_version_minor(props.api_version)).with(crate::checks::Exts::new(0, enabled))
                };
                #(#own_loads)*
                Device { inner: Vrc::new(DeviceInner {
                    raw, physical: physical.clone(), fns, ext, command_buffers: Vutex::new(Default::default()),
                    live: Default::default(),
                    exts,
                    objects: Default::default(),
                }) }
            }
            /// The versions and extensions enabled on this device and its instance.
            pub(crate) fn exts(&self) -> crate::checks::Exts {
                self.inner.exts
            }
            /// The objects created, allocated or retrieved from this device.
            pub(crate) fn objects(&self) -> &crate::validation::Objects {
                &self.inner.objects
            }
            /// ash's device-level function tables.
            #[inline]
            pub fn fns(&self) -> &ash::Device {
                &self.inner.fns
            }
            /// The extension function tables loaded for this device.
            #[inline]
            pub fn ext(&self) -> &DeviceExtensions {
                &self.inner.ext
            }
            /// The physical device this device was created on.
            #[inline]
            pub fn parent(&self) -> &PhysicalDevice {
                &self.inner.physical
            }
            /// Remembers a command buffer's lifecycle state, so that a submission
            /// naming its raw handle can check and mark it.
            pub(crate) fn register_command_buffer(&self, cb: &CommandBuffer) {
                self.inner.command_buffers.lock().insert(cb.raw(), cb.uses().clone());
            }
            pub(crate) fn forget_command_buffer(&self, raw: vk::CommandBuffer) {
                self.inner.command_buffers.lock().remove(&raw);
            }
            /// The live objects of this device by raw handle, and what its descriptor
            /// sets refer to.
            #[inline]
            pub(crate) fn live(&self) -> &crate::state::Live {
                &self.inner.live
            }
            /// How many objects of this device are alive (queues, command
            /// buffers and every non-dispatchable object), whether the program
            /// holds them or something it made does (a command buffer holds what
            /// its last recording uses, a pending submission what it runs): a
            /// check for leaks, and for what work in flight keeps.
            ///
            /// ```no_run
            /// # fn f(device: &tuff::Device) -> tuff::Result<()> {
            /// let before = device.live_object_count();
            /// // SAFETY: no export info is chained, so no handle type needs support.
            /// let fence = unsafe { device.create_fence(&tuff::FenceCreateInfo::new()) }?;
            /// assert_eq!(device.live_object_count(), before + 1);
            /// drop(fence);
            /// assert_eq!(device.live_object_count(), before);
            /// # Ok(()) }
            /// ```
            pub fn live_object_count(&self) -> usize {
                self.inner.live.count()
            }
            /// The lifecycle state of the live command buffer with this raw handle.
            pub(crate) fn command_buffer_uses(&self, raw: vk::CommandBuffer) -> Option<Vrc<crate::state::Uses>> {
                self.inner.command_buffers.lock().get(&raw).cloned()
            }
        }
        impl core::fmt::Debug for Device {
            fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
                f.debug_tuple("Device").field(&self.inner.raw).finish()
            }
        }
        impl Handle for Device {
            type Raw = vk::Device;
            #[inline]
            fn raw(&self) -> vk::Device {
                self.inner.raw
            }
            #[inline]
            fn raw_ref(&self) -> &vk::Device {
                &self.inner.raw
            }
        }
        impl core::ops::Deref for Device {
            type Target = vk::Device;
            #[inline]
            fn deref(&self) -> &vk::Device {
                &self.inner.raw
            }
        }
        impl Drop for DeviceInner {
            fn drop(&mut self) {
                __safety!("every child holds a clone of the device, so none is left (VUID-vkDestroyDevice-device-00378); waiting for idle first means no submission is still executing (VUID-vkDestroyDevice-device-05137); the callbacks it was created with, which the physical device it holds keeps alive (VUID-vkDestroyDevice-device-00379, -00380).");
                unsafe {
                    let _ = (self.fns.fp_v1_0().device_wait_idle)(self.raw);
                    (self.fns.fp_v1_0().destroy_device)(
                        self.raw,
                        crate::memory::host::HostCallbacks::host_callbacks(&self.physical),
                    );
                }
            }
        }
    }
}

fn emit_handle(cx: &Context, name: &str) -> TokenStream {
    let model = cx.model;
    let id = type_ident(name);
    let inner = ident(&format!("{}Inner", crate::names::type_name(name)));
    let cfg = cfg_of(model, model.condition(name));
    let handle = &model.handles[name];
    let parent = parent_of(cx, name);
    let parent_ty = parent.as_deref().map(type_ident);
    let bound = memory_bound(cx, name);
    let destroy = handle
        .destroyed_by
        .iter()
        .find(|d| model.emitted.contains(*d))
        .cloned();
    let mut doc = match &destroy {
        Some(d) => format!(
            "A `{name}`. Clones share it; the last one to go calls `{d}`, after every submission that used it has completed."
        ),
        None => format!(
            "A `{name}`, owned by the implementation: the wrapper keeps its parent alive and never destroys it."
        ),
    };
    // Where the example programs make one: the maker's docs show the statement
    // (kept there, so that this file stays short).
    if let Some((receiver, maker)) = handle.created_by.iter().find_map(|c| {
        let m = cx.method(c);
        let receiver = crate::names::receiver_type(model, c);
        cx.example(&m, Some(receiver))
            .map(|_| (crate::names::type_name(receiver), m))
    }) {
        doc.push_str(&format!(
            "\n\n# Example\n\nMade by [`{receiver}::{maker}`], whose docs show a call from the example programs."
        ));
    }
    let parent_field = parent_ty.as_ref().map(|p| quote!(parent: #p,));
    let parent_fn = parent_ty.as_ref().map(|p| {
        quote! {
            /// The object this one was created from, which it keeps alive.
            #[inline]
            pub fn parent(&self) -> &#p {
                &self.inner.parent
            }
        }
    });
    let bound_field = bound.then(|| quote!(bound: Vutex<Option<Retained>>,));
    let bound_init = bound.then(|| quote!(bound: Vutex::new(None),));
    let bound_fn = bound.then(|| {
        quote! {
            /// Keeps `memory` alive as long as this object, once it is bound to it.
            pub(crate) fn retain_memory(&self, memory: Retained) {
                *self.inner.bound.lock() = Some(memory);
            }
        }
    });
    // Every object is counted in the objects of the device (or, above devices, the
    // instance) it comes from, for the `parent` and `commonparent` checks.
    let owner = parent
        .as_deref()
        .and_then(|p| path_to(cx, p, "VkDevice").or_else(|| path_to(cx, p, "VkInstance")));
    let register = owner.as_ref().map(|path| {
        quote! {
            parent #path.objects().add(raw);
        }
    });
    let unregister = owner.as_ref().map(|path| {
        quote! {
            self.parent #path.objects().remove(self.raw);
        }
    });
    // Non-dispatchable objects of a device are listed in its live objects, so that a
    // wrapper that Vulkan lets refer to them through a struct can keep them alive.
    let live_path = parent
        .as_deref()
        .filter(|_| !handle.dispatchable || name == "VkCommandBuffer" || name == "VkQueue")
        .and_then(|p| path_to(cx, p, "VkDevice"));
    let live_add = live_path
        .as_ref()
        .map(|path| quote!(parent #path.live().add(raw, &this.retained(), &this.inner.sync);));
    // Every wrapper of one object shares the object's host synchronization.
    let sync_init = match &live_path {
        Some(path) => quote!(parent #path.live().sync_for(raw)),
        None => quote!(tuff_runtime::HostSync::new()),
    };
    let unregister = match (&unregister, &live_path) {
        (_, Some(path)) => Some(quote! {
            #unregister
            self.parent #path.live().remove(self.raw);
        }),
        (u, None) => u.clone(),
    };
    let drop_impl = destroy.as_ref().and_then(|d| {
        let cmd = &model.commands[d];
        let device_path = inner_path(cx, name, &cmd.params[0].type_name)?;
        let the_table = crate::names::table(model, d)?;
        let f = crate::names::fn_field(model, d, &the_table);
        let table = match the_table {
            crate::names::Table::Core(m) => {
                let fp = ident(&format!("fp_v1_{m}"));
                quote!(self #device_path.fns().#fp())
            }
            optional => {
                let (f, _) = crate::names::optional_table(&optional)?;
                quote!(match self #device_path.ext().#f.as_ref() { Some(t) => t, None => return })
            }
        };
        let mut args = Vec::new();
        for (i, p) in cmd.params.iter().enumerate() {
            if i == 0 {
                args.push(quote!(self #device_path.raw()));
            } else if p.type_name == "VkAllocationCallbacks" {
                args.push(quote!(core::ptr::null()));
            } else if p.type_name == name && p.pointers == 1 {
                args.push(quote!(&self.raw));
            } else if p.type_name == name {
                args.push(quote!(self.raw));
            } else if Some(&p.type_name) == parent.as_ref() {
                args.push(quote!(self.parent.raw()));
            } else if p.type_name == "uint32_t" {
                args.push(quote!(1));
            } else {
                return None;
            }
        }
        let call = quote!((#table.#f)(#(#args),*));
        let call = if cmd.return_type == "VkResult" {
            quote!(let _ = #call;)
        } else {
            quote!(#call;)
        };
        let fence_wait = (name == "VkFence").then(|| quote! {
            let submission = self.submission.lock().take();
            if let Some(sub) = submission.filter(|s| !s.is_complete()) {
                __safety!("the fence belongs to this device; waiting is always valid. Its submission may still use what it keeps alive, so the wait comes before those objects go and before the fence does (VUID-vkDestroyFence-fence-01120).");
                let r = unsafe {
                    (self.parent.fns().fp_v1_0().wait_for_fences)(self.parent.raw(), 1, &self.raw, vk::TRUE, u64::MAX)
                };
                if r == vk::Result::SUCCESS {
                    self.parent.live().ledger().retire(&sub);
                } else {
                    // A lost device: nothing can be known complete, so what the
                    // submission uses is leaked rather than freed under it.
                    core::mem::forget(sub);
                }
            }
        });
        let fence_wait = if name == "VkCommandBuffer" {
            quote!(#fence_wait self.parent.parent().forget_command_buffer(self.raw);)
        } else {
            quote!(#fence_wait)
        };
        let guard = if name == "VkDescriptorSet" {
            // Sets of a pool without FREE_DESCRIPTOR_SET go back with the pool.
            quote!(if !self.parent.frees_sets() { return; })
        } else {
            quote!()
        };
        // vkFreeCommandBuffers and vkFreeDescriptorSets synchronize the pool. A drop
        // never waits for it: another thread may hold it for a whole recording while
        // it waits for a lock this thread holds (a queue whose idle wait released the
        // last reference). The pool then frees the handle later, under its lock.
        let fence_wait = if matches!(name, "VkCommandBuffer" | "VkDescriptorSet") {
            quote! {
                #fence_wait
                let Some(_pool) = self.parent.host_sync().try_lock() else {
                    self.parent.defer_free(self.raw);
                    return;
                };
                self.parent.free_deferred();
            }
        } else {
            fence_wait
        };
        Some(quote! {
            #cfg
            impl Drop for #inner {
                fn drop(&mut self) {
                    #unregister
                    if !self.destroy {
                        return;
                    }
                    #guard
                    #fence_wait
                    __safety!("the last clone is gone, so no host reference is left, and every submission that used the object held a clone until its fence signalled; it is destroyed with the parent it came from and no allocator, as it was created without one.");
                    unsafe { #call }
                }
            }
        })
    });
    let descriptor_pool_extra = (name == "VkDescriptorPool").then(|| {
        quote! {
            /// Whether sets allocated from this pool may be freed one by one
            /// (`FREE_DESCRIPTOR_SET`); otherwise they return with the pool.
            #[inline]
            pub fn frees_sets(&self) -> bool {
                self.inner.flags.get().is_some_and(|f| f.contains(vk::DescriptorPoolCreateFlags::FREE_DESCRIPTOR_SET))
            }
            /// The flags the pool was created with (none for a pool the wrappers
            /// did not create).
            pub(crate) fn pool_flags(&self) -> vk::DescriptorPoolCreateFlags {
                self.inner.flags.get().copied().unwrap_or_default()
            }
        }
    });
    let flags_field = (name == "VkDescriptorPool")
        .then(|| quote!(flags: std::sync::OnceLock<vk::DescriptorPoolCreateFlags>,));
    let flags_init =
        (name == "VkDescriptorPool").then(|| quote!(flags: std::sync::OnceLock::new(),));
    let (extra_field, extra_init, extra_fns) = special_state(name);
    let derive_clone = if name == "VkCommandBuffer" {
        quote!()
    } else {
        quote!(#[derive(Clone)])
    };
    let drop_impl = match (drop_impl, &unregister) {
        (Some(d), _) => Some(d),
        (None, u) if name == "VkQueue" => Some(quote! {
            #cfg
            impl Drop for #inner {
                fn drop(&mut self) {
                    #u
                    // Another wrapper of the queue may be submitting on another thread.
                    let _queue = self.sync.lock();
                    let held = core::mem::take(&mut *self.unfenced.lock());
                    if held.iter().any(|s| !s.is_complete()) {
                        __safety!("the queue belongs to this live device. What its fenceless operations use goes only once they are complete (VUID-vkDestroySemaphore-semaphore-01137).");
                        let r = unsafe { (self.parent.fns().fp_v1_0().queue_wait_idle)(self.raw) };
                        if r == vk::Result::SUCCESS {
                            self.parent.live().ledger().retire_queue(self.raw);
                        } else {
                            core::mem::forget(held);
                        }
                    }
                }
            }
        }),
        (None, Some(unregister)) if live_path.is_some() => Some(quote! {
            #cfg
            impl Drop for #inner {
                fn drop(&mut self) {
                    #unregister
                }
            }
        }),
        (None, Some(unregister)) => Some(quote! {
            #cfg
            impl Drop for #inner {
                fn drop(&mut self) {
                    #unregister
                }
            }
        }),
        (None, None) => None,
    };
    let parent_arg = parent_ty.as_ref().map(|p| quote!(parent: &#p,));
    let parent_init = parent_ty.as_ref().map(|_| quote!(parent: parent.clone(),));
    let destroy_doc = if destroy.is_some() {
        "destroyed"
    } else {
        "not destroyed (the implementation owns it)"
    };
    let from_doc = format!(
        "Wraps a handle created from `parent`; it is {destroy_doc} when the last clone goes."
    );
    let pool_setter = (name == "VkDescriptorPool").then(|| {
        quote! {
            pub(crate) fn with_flags(self, flags: vk::DescriptorPoolCreateFlags) -> Self {
                let _ = self.inner.flags.set(flags);
                self
            }
        }
    });
    quote! {
        #[doc = #doc]
        #cfg
        #derive_clone
        pub struct #id {
            inner: Vrc<#inner>,
        }
        #cfg
        #[allow(dead_code)]
        struct #inner {
            raw: vk::#id,
            #parent_field
            #bound_field
            #flags_field
            #extra_field
            keep: Option<Retained>,
            destroy: bool,
            sync: tuff_runtime::HostSync,
        }
        #cfg
        impl #id {
            #[doc = #from_doc]
            #[allow(dead_code)]
            pub(crate) fn from_raw(raw: vk::#id, #parent_arg keep: Option<Retained>, destroy: bool) -> Self {
                #register
                let this = Self {
                    inner: Vrc::new(#inner {
                        raw,
                        #parent_init
                        #bound_init
                        #flags_init
                        #extra_init
                        keep,
                        destroy,
                        sync: #sync_init,
                    }),
                };
                #live_add
                this
            }
            #parent_fn
            #bound_fn
            #descriptor_pool_extra
            #pool_setter
            #extra_fns
        }
        child_handle!(#cfg #id);
        #drop_impl
    }
}

/// State some wrappers carry beyond their handle: what a command buffer's last
/// recording uses, and what a fence's pending submission uses.
fn special_state(name: &str) -> (TokenStream, TokenStream, TokenStream) {
    match name {
        "VkCommandBuffer" => (
            quote!(resources: Vutex<Vec<Retained>>, uses: Vrc<crate::state::Uses>,),
            quote!(resources: Vutex::new(Vec::new()), uses: Default::default(),),
            quote! {
                /// Records the buffer's level, for the `bufferlevel` checks and the
                /// submission rules.
                pub(crate) fn with_level(self, level: vk::CommandBufferLevel) -> Self {
                    self.inner.uses.set_secondary(level == vk::CommandBufferLevel::SECONDARY);
                    self
                }
                /// The buffer's level.
                #[allow(dead_code)]
                pub(crate) fn level(&self) -> vk::CommandBufferLevel {
                    if self.inner.uses.is_secondary() {
                        vk::CommandBufferLevel::SECONDARY
                    } else {
                        vk::CommandBufferLevel::PRIMARY
                    }
                }
                /// The buffer's lifecycle state.
                pub(crate) fn uses(&self) -> &Vrc<crate::state::Uses> {
                    &self.inner.uses
                }
                /// Keeps what the last recording uses; what the recording before kept
                /// goes, which `begin` allows only once no submission uses it. Returns
                /// that list emptied, for the next recording to fill in its allocation.
                pub(crate) fn keep_alive(&self, objects: Vec<Retained>) -> Vec<Retained> {
                    let mut old = core::mem::replace(&mut *self.inner.resources.lock(), objects);
                    // Dropped with the lock released: a last reference may destroy.
                    old.clear();
                    old
                }
                pub(crate) fn set_executable(&self, executable: bool) {
                    self.inner.uses.set_executable(executable);
                }
                /// Whether the buffer has been ended and can be submitted.
                #[inline]
                pub fn is_executable(&self) -> bool {
                    self.inner.uses.is_executable()
                }
            },
        ),
        "VkCommandPool" => {
            let (f, i, fns) = queue_flags_state("the pool's family, for the `cmdpool` checks");
            (
                quote!(#f create_flags: std::sync::OnceLock<vk::CommandPoolCreateFlags>, buffers: Vutex<Vec<tuff_runtime::Vweak<crate::state::Uses>>>, deferred: Vutex<Vec<vk::CommandBuffer>>,),
                quote!(#i create_flags: std::sync::OnceLock::new(), buffers: Vutex::new(Vec::new()), deferred: Vutex::new(Vec::new()),),
                quote! {
                    #fns
                    /// Records the flags the pool was created with.
                    pub(crate) fn with_create_flags(self, flags: vk::CommandPoolCreateFlags) -> Self {
                        let _ = self.inner.create_flags.set(flags);
                        self
                    }
                    /// Keeps a buffer whose wrapper went while another thread held
                    /// the pool, to be freed under the pool's lock.
                    #[allow(dead_code)]
                    pub(crate) fn defer_free(&self, raw: vk::CommandBuffer) {
                        self.inner.deferred.lock().push(raw);
                    }
                    /// Frees the buffers kept by `defer_free`; the caller holds the pool.
                    pub(crate) fn free_deferred(&self) {
                        let raws = core::mem::take(&mut *self.inner.deferred.lock());
                        if !raws.is_empty() {
                            __safety!("their wrappers are gone and no submission uses them (each waited for its fence before it went); the caller holds the pool (VUID-vkFreeCommandBuffers-commandPool-parameter's external synchronization).");
                            unsafe {
                                (self.parent().fns().fp_v1_0().free_command_buffers)(self.parent().raw(), self.raw(), raws.len() as u32, raws.as_ptr())
                            };
                        }
                    }
                    /// Lists a buffer allocated from the pool, whose state a reset of
                    /// the pool changes.
                    pub(crate) fn adopt(&self, uses: &Vrc<crate::state::Uses>) {
                        let mut buffers = self.inner.buffers.lock();
                        buffers.retain(|w| w.strong_count() > 0);
                        buffers.push(Vrc::downgrade(uses));
                    }
                    /// The lifecycle states of the pool's live buffers.
                    pub(crate) fn buffer_uses(&self) -> Vec<Vrc<crate::state::Uses>> {
                        self.inner.buffers.lock().iter().filter_map(|w| w.upgrade()).collect()
                    }
                    /// Whether `begin` may reset a buffer of this pool implicitly
                    /// (`RESET_COMMAND_BUFFER`).
                    pub fn resets_buffers(&self) -> bool {
                        self.inner.create_flags.get().is_some_and(|f| f.contains(vk::CommandPoolCreateFlags::RESET_COMMAND_BUFFER))
                    }
                },
            )
        }
        "VkDescriptorPool" => (
            quote!(sets: Vrc<()>, deferred: Vutex<Vec<vk::DescriptorSet>>,),
            quote!(sets: Vrc::new(()), deferred: Vutex::new(Vec::new()),),
            quote! {
                /// Keeps a set whose wrapper went while another thread held the pool,
                /// to be freed under the pool's lock.
                #[allow(dead_code)]
                pub(crate) fn defer_free(&self, raw: vk::DescriptorSet) {
                    self.inner.deferred.lock().push(raw);
                }
                /// Forgets the sets kept by `defer_free`: a reset of the pool freed them.
                pub(crate) fn forget_deferred(&self) {
                    self.inner.deferred.lock().clear();
                }
                /// Frees the sets kept by `defer_free`; the caller holds the pool.
                pub(crate) fn free_deferred(&self) {
                    let raws = core::mem::take(&mut *self.inner.deferred.lock());
                    if !raws.is_empty() {
                        __safety!("their wrappers are gone, so nothing records or submits them; the pool frees sets (only such sets are deferred) and the caller holds it.");
                        let _ = unsafe {
                            (self.parent().fns().fp_v1_0().free_descriptor_sets)(self.parent().raw(), self.raw(), raws.len() as u32, raws.as_ptr())
                        };
                    }
                }
                /// A token each set allocated from the pool holds: the pool is reset
                /// only when none is left.
                pub(crate) fn set_token(&self) -> Vrc<()> {
                    self.inner.sets.clone()
                }
                /// Whether a set allocated from the pool is still alive (held by the
                /// program, or by a command buffer or submission that uses it).
                pub(crate) fn has_sets(&self) -> bool {
                    Vrc::strong_count(&self.inner.sets) > 1
                }
            },
        ),
        "VkDescriptorSet" => (
            quote!(token: std::sync::OnceLock<Vrc<()>>,),
            quote!(token: std::sync::OnceLock::new(),),
            quote! {
                /// Holds its pool's token, so the pool is not reset under it.
                pub(crate) fn with_token(self, token: Vrc<()>) -> Self {
                    let _ = self.inner.token.set(token);
                    self
                }
            },
        ),
        "VkDescriptorUpdateTemplate" => (
            quote!(entries: std::sync::OnceLock<Vec<vk::DescriptorUpdateTemplateEntry>>,),
            quote!(entries: std::sync::OnceLock::new(),),
            quote! {
                /// Records the template's entries, which say where its data names the
                /// objects the updated set then keeps alive.
                pub(crate) fn with_entries(self, entries: &[vk::DescriptorUpdateTemplateEntry]) -> Self {
                    let _ = self.inner.entries.set(entries.to_vec());
                    self
                }
                /// The template's entries.
                pub(crate) fn entries(&self) -> &[vk::DescriptorUpdateTemplateEntry] {
                    self.inner.entries.get().map_or(&[], Vec::as_slice)
                }
            },
        ),
        "VkQueue" => {
            let (f, i, fns) = queue_flags_state("the queue's family, for the `queuetype` checks");
            (
                quote!(#f unfenced: Vutex<Vec<Vrc<crate::state::Submission>>>,),
                quote!(#i unfenced: Vutex::new(Vec::new()),),
                quote! {
                    #fns
                    /// Holds a queue operation without a fence (a presentation, or a submission
                    /// without one) until it is known complete.
                    #[allow(dead_code)]
                    pub(crate) fn hold(&self, sub: Vrc<crate::state::Submission>) {
                        let done: Vec<_> = {
                            let mut held = self.inner.unfenced.lock();
                            let (done, open): (Vec<_>, Vec<_>) = held.drain(..).partition(|s| s.is_complete());
                            *held = open;
                            held.push(sub);
                            done
                        };
                        drop(done);
                    }
                },
            )
        }
        "VkFence" => (
            quote!(submission: Vutex<Option<Vrc<crate::state::Submission>>>,),
            quote!(submission: Vutex::new(None),),
            quote! {
                /// Holds the queue operation that signals this fence until it is
                /// known complete.
                pub(crate) fn track(&self, sub: Vrc<crate::state::Submission>) {
                    let old = self.inner.submission.lock().replace(sub);
                    drop(old);
                }
                /// The queue operation that signals this fence, while it is not known
                /// complete.
                pub(crate) fn submission(&self) -> Option<Vrc<crate::state::Submission>> {
                    self.inner.submission.lock().clone().filter(|s| !s.is_complete())
                }
                /// The fence was seen signalled: its queue operation, and every one
                /// submitted before it to that queue, are complete.
                pub(crate) fn completed(&self) {
                    if let Some(sub) = self.submission() {
                        self.parent().live().ledger().retire(&sub);
                    }
                }
            },
        ),
        _ => (quote!(), quote!(), quote!()),
    }
}

/// The queue flags of a family, recorded when a pool or queue is made, for the
/// `cmdpool` and `queuetype` checks; `of` says whose family and for which checks.
fn queue_flags_state(of: &str) -> (TokenStream, TokenStream, TokenStream) {
    let set_doc = format!("Records the queue flags of {of}.");
    let get_doc = format!("The queue flags of {of}.");
    (
        quote!(queue_flags: std::sync::OnceLock<vk::QueueFlags>,),
        quote!(queue_flags: std::sync::OnceLock::new(),),
        quote! {
            #[doc = #set_doc]
            pub(crate) fn with_queue_flags(self, flags: vk::QueueFlags) -> Self {
                let _ = self.inner.queue_flags.set(flags);
                self
            }
            #[doc = #get_doc]
            pub(crate) fn queue_flags(&self) -> vk::QueueFlags {
                self.inner.queue_flags.get().copied().unwrap_or_default()
            }
        },
    )
}
