//! Emits `src/structs.rs`: a safe counterpart of every struct of the emitted API that
//! carries handles, pointers or an `sType`. Each is a `#[repr(transparent)]` wrapper of
//! ash's struct whose setters take wrappers, references and slices, so lowering to ash
//! at the call is free and a slice of safe structs is a valid C array. `pNext` chains
//! are typed: `push_next` accepts only structs that `structextends` the head.

use super::names::{cfg_of, field_ident, type_ident};
use super::shape::{struct_members, Member};
use super::types::{array_size, ash_type, TypeFacts};
use super::{doc_rules, Context};
use proc_macro2::TokenStream;
use quote::quote;

/// The structs that get safe counterparts, in name order.
pub fn safe_structs(cx: &Context) -> Vec<String> {
    cx.model
        .types
        .iter()
        .filter(|(name, t)| {
            t.alias.is_none()
                && t.category.as_deref() == Some("struct")
                && cx.model.emitted.contains(*name)
                && cx.facts.is_safe(name)
        })
        .map(|(name, _)| name.clone())
        .collect()
}

pub(super) fn emit(cx: &Context) -> TokenStream {
    let mut items = Vec::new();
    for name in safe_structs(cx) {
        items.push(emit_struct(cx, &name));
    }
    quote! {
        //! Safe counterparts of the registry's structs that carry handles, pointers or
        //! an `sType`. Plain structs (`vk::Extent2D`, ...) are used as ash has them.
        #![allow(clippy::needless_lifetimes, clippy::new_without_default, clippy::field_reassign_with_default, clippy::unnecessary_cast)]
        use crate::{chain::Extends, handles::*, CStrPtr, Handle, HandleSlice};
        use ash::vk;
        use core::marker::PhantomData;
        #(#items)*
    }
}

fn emit_struct(cx: &Context, name: &str) -> TokenStream {
    let model = cx.model;
    let facts: &TypeFacts = &cx.facts;
    let t = &model.types[name];
    let id = type_ident(name);
    let raw_ty = if facts.has_lifetime(name) {
        quote!(vk::#id<'a>)
    } else {
        quote!(vk::#id)
    };
    let cfg = cfg_of(model, model.condition(name));
    let members = struct_members(model, facts, name);
    let mut ctor_args = Vec::new();
    let mut ctor_sets = Vec::new();
    let mut setters = Vec::new();
    let returned_only = t.returned_only;
    for (m, shape) in &members {
        let f = field_ident(&m.name);
        let setter = field_ident(&super::names::param(&m.name));
        let doc = format!("Sets `{}`.", m.name);
        let ty = ash_type(model, facts, &m.type_name);
        if returned_only && !matches!(shape, Member::PNext) {
            continue;
        }
        match shape {
            Member::SType | Member::Count | Member::Unsupported(_) => {}
            Member::PNext => {}
            Member::Value => {
                let ty = ty.unwrap_or_else(|| quote!(()));
                setters.push(quote! {
                    #[doc = #doc]
                    #[inline]
                    pub fn #setter(mut self, value: #ty) -> Self {
                        self.raw.#f = value;
                        self
                    }
                });
            }
            Member::Array(size) => {
                let ty = ty.unwrap_or_else(|| quote!(()));
                let n = array_size(size);
                setters.push(quote! {
                    #[doc = #doc]
                    #[inline]
                    pub fn #setter(mut self, value: [#ty; #n]) -> Self {
                        self.raw.#f = value;
                        self
                    }
                });
            }
            Member::Handle { optional } => {
                let w = type_ident(&m.type_name);
                if *optional {
                    setters.push(quote! {
                        #[doc = #doc]
                        #[inline]
                        pub fn #setter(mut self, value: Option<&'a #w>) -> Self {
                            self.raw.#f = value.map_or(vk::#w::null(), |h| h.raw());
                            self
                        }
                    });
                } else {
                    ctor_args.push(quote!(#setter: &'a #w));
                    ctor_sets.push(quote!(raw.#f = #setter.raw();));
                    setters.push(quote! {
                        #[doc = #doc]
                        #[inline]
                        pub fn #setter(mut self, value: &'a #w) -> Self {
                            self.raw.#f = value.raw();
                            self
                        }
                    });
                }
            }
            Member::HandleSlice { count } => {
                let w = type_ident(&m.type_name);
                let c = field_ident(count);
                setters.push(quote! {
                    #[doc = #doc]
                    #[inline]
                    pub fn #setter(mut self, value: &'a HandleSlice<'a, #w>) -> Self {
                        self.raw.#c = value.len() as _;
                        self.raw.#f = value.as_ptr();
                        self
                    }
                });
            }
            Member::Nested => {
                let target = safe_or_ash(cx, &m.type_name);
                ctor_args.push(quote!(#setter: #target));
                ctor_sets.push(quote!(raw.#f = #setter.raw;));
                setters.push(quote! {
                    #[doc = #doc]
                    #[inline]
                    pub fn #setter(mut self, value: #target) -> Self {
                        self.raw.#f = value.raw;
                        self
                    }
                });
            }
            Member::StructRef { optional } => {
                let target = safe_or_ash(cx, &m.type_name);
                let cast = quote!(value as *const #target as *const _);
                if *optional {
                    setters.push(quote! {
                        #[doc = #doc]
                        #[inline]
                        pub fn #setter(mut self, value: Option<&'a #target>) -> Self {
                            self.raw.#f = value.map_or(core::ptr::null(), |value| #cast);
                            self
                        }
                    });
                } else {
                    ctor_args.push(quote!(#setter: &'a #target));
                    ctor_sets.push(quote!(raw.#f = { let value = #setter; #cast };));
                    setters.push(quote! {
                        #[doc = #doc]
                        #[inline]
                        pub fn #setter(mut self, value: &'a #target) -> Self {
                            self.raw.#f = #cast;
                            self
                        }
                    });
                }
            }
            Member::Slice { count, safe } => {
                let c = field_ident(count);
                let elem = if *safe {
                    safe_or_ash(cx, &m.type_name)
                } else {
                    ty.unwrap_or_else(|| quote!(()))
                };
                setters.push(quote! {
                    #[doc = #doc]
                    #[inline]
                    pub fn #setter(mut self, value: &'a [#elem]) -> Self {
                        self.raw.#c = value.len() as _;
                        self.raw.#f = value.as_ptr().cast();
                        self
                    }
                });
            }
            Member::Bytes { count } => {
                let c = field_ident(count);
                setters.push(quote! {
                    #[doc = #doc]
                    #[inline]
                    pub fn #setter(mut self, value: &'a [u8]) -> Self {
                        self.raw.#c = value.len() as _;
                        self.raw.#f = value.as_ptr().cast();
                        self
                    }
                });
            }
            Member::Code { count } => {
                let c = field_ident(count);
                setters.push(quote! {
                    #[doc = "Sets the SPIR-V words (and the size in bytes)."]
                    #[inline]
                    pub fn #setter(mut self, value: &'a [u32]) -> Self {
                        self.raw.#c = core::mem::size_of_val(value);
                        self.raw.#f = value.as_ptr();
                        self
                    }
                });
            }
            Member::CStr { optional } => {
                if *optional {
                    setters.push(quote! {
                        #[doc = #doc]
                        #[inline]
                        pub fn #setter(mut self, value: Option<&'a core::ffi::CStr>) -> Self {
                            self.raw.#f = value.map_or(core::ptr::null(), |s| s.as_ptr());
                            self
                        }
                    });
                } else {
                    ctor_args.push(quote!(#setter: &'a core::ffi::CStr));
                    ctor_sets.push(quote!(raw.#f = #setter.as_ptr();));
                    setters.push(quote! {
                        #[doc = #doc]
                        #[inline]
                        pub fn #setter(mut self, value: &'a core::ffi::CStr) -> Self {
                            self.raw.#f = value.as_ptr();
                            self
                        }
                    });
                }
            }
            Member::CStrSlice { count } => {
                let c = field_ident(count);
                setters.push(quote! {
                    #[doc = #doc]
                    #[inline]
                    pub fn #setter(mut self, value: &'a [CStrPtr<'a>]) -> Self {
                        self.raw.#c = value.len() as _;
                        self.raw.#f = value.as_ptr().cast();
                        self
                    }
                });
            }
            Member::UserData => {
                setters.push(quote! {
                    #[doc = "Sets the pointer handed back to the callback; Vulkan never reads through it."]
                    #[inline]
                    pub fn #setter(mut self, value: *mut core::ffi::c_void) -> Self {
                        self.raw.#f = value;
                        self
                    }
                });
            }
            Member::PlatformValue => {
                let ty = ty.unwrap_or_else(|| quote!(()));
                let doc = format!(
                    "Sets `{}`.\n\n# Safety\n\n`value` must name a live window-system object that outlives every Vulkan object created from this struct.",
                    m.name
                );
                setters.push(quote! {
                    #[doc = #doc]
                    #[inline]
                    pub unsafe fn #setter(mut self, value: #ty) -> Self {
                        self.raw.#f = value;
                        self
                    }
                });
            }
            Member::Platform => {
                let ty = ty.unwrap_or_else(|| quote!(core::ffi::c_void));
                let mutability = if m.is_const {
                    quote!(const)
                } else {
                    quote!(mut)
                };
                let doc = format!(
                    "Sets `{}`.\n\n# Safety\n\n`value` must be a valid window-system object that outlives every Vulkan object created from this struct.",
                    m.name
                );
                setters.push(quote! {
                    #[doc = #doc]
                    #[inline]
                    pub unsafe fn #setter(mut self, value: *#mutability #ty) -> Self {
                        self.raw.#f = value;
                        self
                    }
                });
            }
        }
    }
    let has_next = members.iter().any(|(_, s)| matches!(s, Member::PNext));
    let push_next = has_next.then(|| {
        quote! {
            /// Pushes a struct that extends this one onto its `pNext` chain; only
            /// structs that the registry says extend this one are accepted.
            #[inline]
            pub fn push_next<T: Extends<Self>>(mut self, next: &'a mut T) -> Self {
                // SAFETY: `Extends` is implemented only for structs that begin with
                // `sType` and `pNext` (the VkBaseOutStructure layout), as this one
                // does; `next` and its chain are borrowed for `'a`, as long as `self`.
                unsafe {
                    let next = next as *mut T as *mut vk::BaseOutStructure<'a>;
                    let mut last = next;
                    while !(*last).p_next.is_null() {
                        last = (*last).p_next;
                    }
                    (*last).p_next = self.raw.p_next as *mut _;
                    self.raw.p_next = next as _;
                }
                self
            }
        }
    });
    let rules = doc_rules(cx, name);
    let doc = format!(
        "Safe counterpart of [`vk::{}`].{rules}",
        super::names::type_name(name)
    );
    let (new_fn, default_impl) = if ctor_args.is_empty() {
        (
            quote! {
                /// A struct with every member zero or empty (and `sType` set).
                #[inline]
                pub fn new() -> Self {
                    Self { raw: Default::default(), _marker: PhantomData }
                }
            },
            quote! {
                #cfg
                impl Default for #id<'_> {
                    fn default() -> Self {
                        Self::new()
                    }
                }
            },
        )
    } else {
        (
            quote! {
                /// A struct with its required members set and every other member zero or
                /// empty (and `sType` set).
                #[inline]
                pub fn new(#(#ctor_args),*) -> Self {
                    #[allow(unused_mut)]
                    let mut raw: #raw_ty = Default::default();
                    #(#ctor_sets)*
                    Self { raw, _marker: PhantomData }
                }
            },
            quote!(),
        )
    };
    let extends: Vec<TokenStream> = model.types[name]
        .struct_extends
        .iter()
        .filter(|head| cx.model.emitted.contains(*head) && cx.facts.is_safe(head))
        .map(|head| {
            let h = type_ident(head);
            let head_cfg = cfg_of(model, model.condition(head));
            quote! {
                #cfg
                #head_cfg
                // SAFETY: the registry lists this struct in the head's `structextends`.
                unsafe impl<'a, 'b> Extends<#h<'b>> for #id<'a> {}
            }
        })
        .collect();
    quote! {
        #[doc = #doc]
        #cfg
        #[repr(transparent)]
        #[derive(Clone, Copy)]
        pub struct #id<'a> {
            raw: #raw_ty,
            _marker: PhantomData<&'a ()>,
        }
        #cfg
        impl<'a> #id<'a> {
            #new_fn
            #(#setters)*
            #push_next
            /// The ash struct this lowers to.
            #[inline]
            pub fn as_raw(&self) -> &#raw_ty {
                &self.raw
            }
            /// The ash struct, for a command that writes into it.
            #[inline]
            #[allow(dead_code)]
            pub(crate) fn as_raw_mut(&mut self) -> &mut #raw_ty {
                &mut self.raw
            }
        }
        #default_impl
        #cfg
        impl<'a> core::ops::Deref for #id<'a> {
            type Target = #raw_ty;
            #[inline]
            fn deref(&self) -> &Self::Target {
                &self.raw
            }
        }
        #(#extends)*
    }
}

/// The generated safe type of a struct, or ash's when it has none.
pub fn safe_or_ash(cx: &Context, name: &str) -> TokenStream {
    let id = type_ident(name);
    if cx.facts.is_safe(name) {
        quote!(#id<'a>)
    } else if cx.facts.has_lifetime(name) {
        quote!(vk::#id<'a>)
    } else {
        quote!(vk::#id)
    }
}
