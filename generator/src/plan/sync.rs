//! Host synchronization: what a safe method holds so that two threads never use an
//! object that the registry marks `externsync` in one call at once. Every wrapper
//! carries a `HostSync` (a reentrant lock when tuff-runtime has `multi_thread`,
//! nothing without it, whichever crate turned the feature on);
//! a method locks, in one global order, every object its parameters name as
//! externally synchronized, and those that its structs name through member paths.
//! Recording holds the command buffer (`&mut`) and its pool (the recorder's guard).

use super::Context;
use crate::model::ExternSync;
use proc_macro2::TokenStream;
use quote::quote;

/// The objects that structs name and the registry marks externally synchronized,
/// by command and path: how the wrapper finds their locks. One table; a command
/// with a path not listed here is emitted `unsafe` (see [`unsupported_members`]).
pub(crate) fn member(command: &str, path: &str) -> Option<TokenStream> {
    Some(match (command, path) {
        // The pool is taken again as a wrapper and written into the info.
        ("vkAllocateDescriptorSets", "pAllocateInfo->descriptorPool") => {
            quote!(syncs.push(descriptor_pool.host_sync().clone());)
        }
        ("vkAllocateCommandBuffers", "pAllocateInfo->commandPool") => {
            quote!(syncs.push(command_pool.host_sync().clone());)
        }
        ("vkCreateSwapchainKHR", "pCreateInfo->surface") => {
            quote!(syncs.push(surface.host_sync().clone());)
        }
        ("vkCreateSwapchainKHR", "pCreateInfo->oldSwapchain") => quote! {
            syncs.extend(self.live().sync_of(vk::ObjectType::SWAPCHAIN_KHR, vk::Handle::as_raw(create_info.old_swapchain)));
        },
        ("vkQueuePresentKHR", "pPresentInfo->pWaitSemaphores[]") => quote! {
            __safety!("the safe struct stores each array with its length.");
            for s in unsafe { crate::state::raw_slice(present_info.p_wait_semaphores, present_info.wait_semaphore_count) } {
                syncs.extend(self.parent().live().sync_of(vk::ObjectType::SEMAPHORE, vk::Handle::as_raw(*s)));
            }
        },
        ("vkQueuePresentKHR", "pPresentInfo->pSwapchains[]") => quote! {
            __safety!("the safe struct stores each array with its length.");
            for s in unsafe { crate::state::raw_slice(present_info.p_swapchains, present_info.swapchain_count) } {
                syncs.extend(self.parent().live().sync_of(vk::ObjectType::SWAPCHAIN_KHR, vk::Handle::as_raw(*s)));
            }
        },
        // The device itself, or an object of it; an instance's own objects have no
        // lock the device can find, so naming them is refused where another thread
        // could use them (see `named_object_sync`).
        ("vkSetDebugUtilsObjectNameEXT", "pNameInfo->objectHandle") => quote! {
            syncs.push(crate::submission::named_object_sync(self, name_info.object_type, name_info.object_handle, "VUID-VkDebugUtilsObjectNameInfoEXT-objectType-02590")?);
        },
        ("vkSetDebugUtilsObjectTagEXT", "pTagInfo->objectHandle") => quote! {
            syncs.push(crate::submission::named_object_sync(self, tag_info.object_type, tag_info.object_handle, "VUID-VkDebugUtilsObjectTagInfoEXT-objectHandle-01910")?);
        },
        _ => return None,
    })
}

/// Objects a command synchronizes implicitly (vk.xml's `implicitexternsyncparams`).
pub(crate) fn implicit(command: &str) -> Option<TokenStream> {
    Some(match command {
        "vkDeviceWaitIdle" => quote!(syncs.extend(self.live().queue_syncs());),
        // The buffer's pool.
        "vkResetCommandBuffer" => quote!(syncs.push(self.parent().host_sync().clone());),
        // The pool's sets: a reset is refused while any is alive, so none is in use.
        "vkResetDescriptorPool" => quote!(),
        _ => return None,
    })
}

/// The externally synchronized member paths of `command` that the wrappers cannot
/// lock: such a command is emitted `unsafe`, its caller synchronizing them.
pub fn unsupported_members(cx: &Context, command: &str) -> Vec<String> {
    let Some(cmd) = cx.model.commands.get(command) else {
        return Vec::new();
    };
    cmd.params
        .iter()
        .flat_map(|p| &p.parsed.externsync)
        .filter_map(|e| match e {
            ExternSync::Member(path) if member(command, path).is_none() => Some(path.clone()),
            _ => None,
        })
        .collect()
}
