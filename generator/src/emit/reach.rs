//! The walk over everything a struct names: one function per struct that can reach
//! a handle, through its handle members, handle arrays, nested structs, struct
//! arrays and `pNext` chain. A command that binds, references or submits a struct
//! keeps alive every live object the walk finds, so none goes while Vulkan may
//! still use it; the walk is derived from the model, not listed by hand.

use crate::names::{cfg_of, field_ident, ident, type_ident};
use crate::plan::checks::{snake, struct_type_value};
use crate::plan::reach::extenders;
use crate::plan::shape::{struct_members, Member};
use crate::plan::Context;
use proc_macro2::{Ident, Literal, TokenStream};
use quote::quote;

/// The walk function of `name`, as a path from the generated crate's root.
pub fn walk_fn(name: &str) -> TokenStream {
    let f = fn_ident(name);
    quote!(crate::reach::#f)
}

fn fn_ident(name: &str) -> Ident {
    ident(&snake(name))
}

/// The `reach` module: a walk per reaching struct, and the `pNext` dispatch.
pub fn emit(cx: &Context) -> TokenStream {
    let model = cx.model;
    let found = &cx.reaching;
    let mut fns = Vec::new();
    let mut arms = Vec::new();
    for name in found {
        let ty = type_ident(model.spelling(name));
        let ty = if cx.facts.has_lifetime(name) {
            quote!(#ty<'_>)
        } else {
            quote!(#ty)
        };
        let f = fn_ident(name);
        let cfg = cfg_of(model, model.condition(name));
        let mut parts = Vec::new();
        for (m, shape) in struct_members(model, &cx.facts, name) {
            let field = field_ident(&m.name);
            let inner = || walk_fn(&m.type_name);
            match shape {
                Member::Handle { .. } => {
                    let (visit, rule) = visit(cx, name, &m, false);
                    parts.push(quote!(out.#visit(#rule, x.#field);));
                }
                Member::HandleSlice { count } => {
                    let (visit, rule) = visit(cx, name, &m, true);
                    let c = field_ident(&count);
                    parts.push(quote! {
                        __safety!("the safe setter stored this array with its length.");
                        let handles = unsafe { crate::state::raw_slice(x.#field, x.#c) };
                        out.#visit(#rule, handles);
                    });
                }
                Member::StructRef { .. } if found.contains(&m.type_name) => {
                    let g = inner();
                    parts.push(unchecked_if(
                        m.noautovalidity,
                        quote! {
                            __safety!("the safe setter stored a reference that outlives `x`.");
                            if let Some(y) = unsafe { x.#field.as_ref() } {
                                __safety!("`y` is a live safe struct, as the walk requires.");
                                unsafe { #g(y, out) };
                            }
                        },
                    ));
                }
                Member::Slice { count, safe: true } if found.contains(&m.type_name) => {
                    let c = field_ident(&count);
                    let g = inner();
                    parts.push(unchecked_if(
                        m.noautovalidity,
                        quote! {
                            __safety!("the safe setter stored this array with its length.");
                            for y in unsafe { crate::state::raw_slice(x.#field, x.#c) } {
                                __safety!("`y` is a live safe struct, as the walk requires.");
                                unsafe { #g(y, out) };
                            }
                        },
                    ));
                }
                Member::Nested if found.contains(&m.type_name) => {
                    let g = inner();
                    parts.push(unchecked_if(m.noautovalidity, quote! {
                        __safety!("a nested struct of a live struct, with the same guarantees.");
                        unsafe { #g(&x.#field, out) };
                    }));
                }
                Member::PNext if extenders(cx, name).any(|e| found.contains(e)) => {
                    parts.push(quote! {
                        __safety!("the chain was built by `push_next` from live safe structs.");
                        unsafe { next(x.p_next, out) };
                    });
                }
                _ => {}
            }
        }
        let doc = format!("The handles a `{name}` names, directly or through what it points to.");
        fns.push(quote! {
            #[doc = #doc]
            ///
            /// # Safety
            ///
            /// `x` was built through its safe counterpart, whose setters store every
            /// pointer with its length and borrow what it points to.
            #cfg
            #[inline]
            pub(crate) unsafe fn #f(x: &vk::#ty, out: &mut Reached<'_>) {
                #(#parts)*
            }
        });
        if !model.types[name].struct_extends.is_empty() {
            if let Some(v) = struct_type_value(cx, name) {
                let lit = Literal::i32_unsuffixed(v);
                arms.push(quote! {
                    #cfg
                    #lit => {
                        __safety!("a node with this structure type is this struct.");
                        unsafe { #f(&*(node as *const vk::BaseInStructure<'_>).cast::<vk::#ty>(), out) }
                    }
                });
            }
        }
    }
    quote! {
        //! What a struct names: the walks that check every handle belongs to the call's
        //! device (or instance) and keep the objects alive. Every reaching struct has
        //! one, whether or not a command of this build uses it yet.
        #![allow(dead_code, unused_unsafe, clippy::missing_safety_doc)]
        use crate::validation::Reached;
        use crate::vk;

        /// The handles the structs of a `pNext` chain name.
        ///
        /// # Safety
        ///
        /// `p` is null or a chain that `push_next` built from safe structs.
        #[allow(dead_code)]
        pub(crate) unsafe fn next(p: *const core::ffi::c_void, out: &mut Reached<'_>) {
            __safety!("the caller vouches for every node.");
            for node in unsafe { crate::support::chain_nodes(p) } {
                #[allow(clippy::single_match)]
                match node.s_type.as_raw() {
                    #(#arms)*
                    _ => {}
                }
            }
        }

        #(#fns)*
    }
}

/// A descent into a member Vulkan reads only where other members say so
/// (`noautovalidity`: a descriptor write's buffer infos): what it finds is kept but
/// not checked, as the rules of the commands that read it check it where it is used.
fn unchecked_if(noautovalidity: bool, walk: TokenStream) -> TokenStream {
    match noautovalidity {
        true => quote! {
            let checking = out.pause_checks();
            #walk
            out.resume_checks(checking);
        },
        false => walk,
    }
}

/// The visit of a handle member, one or a slice, as the plan says; a member the
/// walk does not check is visited under no rule (`""`), to keep it.
fn visit(cx: &Context, item: &str, m: &crate::model::Field, slice: bool) -> (Ident, String) {
    let v = crate::plan::reach::handle_visit(cx, item, m);
    let visit = match (v.of_device, slice) {
        (true, false) => "device_handle",
        (true, true) => "device_handles",
        (false, false) => "instance_handle",
        (false, true) => "instance_handles",
    };
    (ident(visit), v.rule.unwrap_or_default())
}
