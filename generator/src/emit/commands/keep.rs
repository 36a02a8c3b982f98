//! What an emitted call keeps alive: the objects a created wrapper's create info
//! names, and those a recorded command's struct arguments name, looked up among the
//! device's live objects.

use crate::names::field_ident;
use crate::plan::shape::{struct_members, Member};
use crate::plan::Context;
use proc_macro2::{Ident, TokenStream};
use quote::quote;

/// The objects a created wrapper keeps alive because its create info names them
/// (a view's image, a framebuffer's attachments, a pipeline's layout and render
/// pass): an expression of type `Option<Retained>` over the info in `var`, or `None`
/// when the info names no other object. The parent and `skip` are kept already.
pub(super) fn keep_expr(
    cx: &Context,
    info_ty: &str,
    var: &TokenStream,
    parent: &str,
    skip: Option<&str>,
    device_path: &TokenStream,
) -> Option<TokenStream> {
    if cx.reaching.contains(info_ty) && skip.is_none() {
        // Everything the info reaches, nested structs and `pNext` included: a
        // descriptor set layout keeps the immutable samplers of its bindings. New
        // objects keep only older ones, so no cycle can form.
        let walk = crate::emit::reach::walk_fn(info_ty);
        return Some(quote!({
            let mut reached = crate::validation::Reached::keeping(#device_path.live());
            __safety!("the safe info stores every array with its length and chains only structs pushed through `push_next`.");
            unsafe { #walk(#var.as_raw(), &mut reached) };
            let kept = reached.kept;
            (!kept.is_empty()).then(|| tuff_runtime::Vrc::new(kept) as tuff_runtime::Retained)
        }));
    }
    let mut parts = Vec::new();
    for (m, shape) in struct_members(cx.model, &cx.facts, info_ty) {
        if m.type_name == parent || Some(m.name.as_str()) == skip {
            continue;
        }
        let f = field_ident(&m.name);
        match shape {
            Member::Handle { .. } => {
                parts.push(quote!(kept.extend(live.get(#var.as_raw().#f));));
            }
            Member::HandleSlice { count } => {
                let c = field_ident(&count);
                parts.push(quote! {
                    __safety!("the safe setter stored this array with its length.");
                    kept.extend(unsafe { crate::state::raw_slice(#var.as_raw().#f, #var.as_raw().#c) }.iter().filter_map(|h| live.get(*h)));
                });
            }
            _ => {}
        }
    }
    if parts.is_empty() {
        return None;
    }
    Some(quote!({
        let live = #device_path.live();
        let mut kept: Vec<tuff_runtime::Retained> = Vec::new();
        #(#parts)*
        (!kept.is_empty()).then(|| tuff_runtime::Vrc::new(kept) as tuff_runtime::Retained)
    }))
}

/// What a recorded command keeps alive beyond its wrapper arguments: the objects
/// named by handle members of a struct argument (a render pass begin's framebuffer,
/// a barrier's image), looked up among the device's live objects.
pub(super) fn struct_retains(
    cx: &Context,
    p: &crate::model::Field,
    name: &Ident,
    slice: bool,
) -> Vec<TokenStream> {
    if !cx.reaching.contains(&p.type_name) {
        return Vec::new();
    }
    let walk = crate::emit::reach::walk_fn(&p.type_name);
    let elems = if slice {
        quote!(#name.iter())
    } else {
        quote!(core::iter::once(#name))
    };
    vec![quote! {
        let kept: crate::validation::Kept = {
            let mut reached = crate::validation::Reached::keeping(self.device().live());
            for e in #elems {
                __safety!("the safe structs store every pointer with its length.");
                unsafe { #walk(e.as_raw(), &mut reached) };
            }
            reached.kept
        };
        for o in kept { self.retain(o); }
    }]
}
