//! Renders the host synchronization of each call: the statements that lock, in one
//! global order, what the registry marks externally synchronized (see `plan::sync`
//! for which objects, and how the wrappers find their locks).

use crate::model::ExternSync;
use crate::names::param;
use crate::plan::commands::{recorded, Param, Plan};
use crate::plan::sync::{implicit, member};
use crate::plan::Context;
use proc_macro2::TokenStream;
use quote::{format_ident, quote};

/// Statements that lock what the command synchronizes, for the top of its body, or
/// nothing when it synchronizes nothing (or only the command buffer it records into).
pub fn host_syncs(cx: &Context, plan: &Plan) -> TokenStream {
    let cmd = &cx.model.commands[&plan.name];
    let recorded = recorded(plan);
    let mut pushes = Vec::new();
    for (i, (p, shape)) in cmd.params.iter().zip(&plan.params).enumerate() {
        for e in &p.parsed.externsync {
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
                Param::Receiver => pushes.push(quote!(syncs.push(self.host_sync().clone());)),
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
