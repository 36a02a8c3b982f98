//! Host synchronization: what a safe method holds so that two threads never use an
//! object that the registry marks `externsync` in one call at once. Every wrapper
//! carries a `HostSync` (a reentrant lock when tuff-runtime has `multi_thread`,
//! nothing without it, whichever crate turned the feature on);
//! a method locks, in one global order, every object its parameters name as
//! externally synchronized, and those that its structs name through member paths.
//! Recording holds the command buffer (`&mut`) and its pool (the recorder's guard).

use super::commands::{Param, Plan};
use super::names::param;
use super::Context;
use crate::model::ExternSync;
use proc_macro2::TokenStream;
use quote::{format_ident, quote};

/// The objects that structs name and the registry marks externally synchronized,
/// by command and path: how the wrapper finds their locks. One table, so a command
/// with a path not listed here is not emitted (see [`unsupported_member`]).
fn member(command: &str, path: &str) -> Option<TokenStream> {
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
            // SAFETY: the safe struct stores each array with its length.
            for s in unsafe { crate::retention::raw_slice(present_info.p_wait_semaphores, present_info.wait_semaphore_count) } {
                syncs.extend(self.parent().live().sync_of(vk::ObjectType::SEMAPHORE, vk::Handle::as_raw(*s)));
            }
        },
        ("vkQueuePresentKHR", "pPresentInfo->pSwapchains[]") => quote! {
            // SAFETY: the safe struct stores each array with its length.
            for s in unsafe { crate::retention::raw_slice(present_info.p_swapchains, present_info.swapchain_count) } {
                syncs.extend(self.parent().live().sync_of(vk::ObjectType::SWAPCHAIN_KHR, vk::Handle::as_raw(*s)));
            }
        },
        // The device itself, or an object of it; an instance's own objects have no
        // lock the device can find, so naming them is refused where another thread
        // could use them (see `named_object_sync`).
        ("vkSetDebugUtilsObjectNameEXT", "pNameInfo->objectHandle") => quote! {
            syncs.push(crate::submission::named_object_sync(self, name_info.object_type, name_info.object_handle)?);
        },
        ("vkSetDebugUtilsObjectTagEXT", "pTagInfo->objectHandle") => quote! {
            syncs.push(crate::submission::named_object_sync(self, tag_info.object_type, tag_info.object_handle)?);
        },
        _ => return None,
    })
}

/// Objects a command synchronizes implicitly (vk.xml's `implicitexternsyncparams`).
fn implicit(command: &str) -> Option<TokenStream> {
    Some(match command {
        "vkDeviceWaitIdle" => quote!(syncs.extend(self.live().queue_syncs());),
        // The buffer's pool.
        "vkResetCommandBuffer" => quote!(syncs.push(self.parent().host_sync().clone());),
        // The pool's sets: a reset is refused while any is alive, so none is in use.
        "vkResetDescriptorPool" => quote!(),
        _ => return None,
    })
}

/// The first externally synchronized member path of `command` that the wrappers
/// cannot lock, if any: such a command is not emitted safely.
pub fn unsupported_member(cx: &Context, command: &str) -> Option<String> {
    let cmd = cx.model.commands.get(command)?;
    cmd.params.iter().find_map(|p| {
        cx.model
            .parse_field(p)
            .externsync
            .iter()
            .find_map(|e| match e {
                ExternSync::Member(path) if member(command, path).is_none() => Some(path.clone()),
                _ => None,
            })
    })
}

/// Statements that lock what the command synchronizes, for the top of its body, or
/// nothing when it synchronizes nothing (or only the command buffer it records into).
pub fn host_syncs(cx: &Context, plan: &Plan) -> TokenStream {
    let cmd = &cx.model.commands[&plan.name];
    let recorded = plan.receiver == "VkCommandBuffer" && plan.name.starts_with("vkCmd");
    let mut pushes = Vec::new();
    for (i, (p, shape)) in cmd.params.iter().zip(&plan.params).enumerate() {
        for e in &cx.model.parse_field(p).externsync {
            let whole = matches!(e, ExternSync::Whole | ExternSync::Maybe);
            if let ExternSync::Member(path) = e {
                pushes.extend(member(&plan.name, path));
                continue;
            }
            if !whole {
                continue;
            }
            let name = format_ident!("{}", param(&p.name));
            match shape {
                Param::Dispatch if i == 0 && !recorded => {
                    pushes.push(quote!(syncs.push(self.host_sync().clone());))
                }
                Param::Handle { optional: false } => {
                    pushes.push(quote!(syncs.push(#name.host_sync().clone());))
                }
                Param::Handle { optional: true } => pushes.push(quote! {
                    if let Some(h) = #name {
                        syncs.push(h.host_sync().clone());
                    }
                }),
                Param::HandleSlice => pushes.push(quote! {
                    for h in #name.iter() {
                        syncs.push(h.host_sync().clone());
                    }
                }),
                _ => {}
            }
        }
    }
    pushes.extend(implicit(&plan.name));
    if pushes.is_empty() {
        return quote!();
    }
    quote! {
        // The objects the registry marks externally synchronized, held for the call
        // (nothing to hold without `multi_thread`, where no other thread can reach
        // them: the locks are empty and so is the list).
        #[allow(clippy::vec_init_then_push)]
        let _host_sync = {
            let mut syncs: Vec<tuff_runtime::HostSync> = Vec::new();
            #(#pushes)*
            tuff_runtime::lock_all(syncs)
        };
    }
}
