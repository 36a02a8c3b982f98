//! Emits `src/generated/delta.rs`: what the registry has and ash lacks, in ash's
//! style, so the rest of the crate names it as it names ash's items (`crate::vk`
//! re-exports ash's `vk` and this module together).
//!
//! Today that is the structs of `Model::delta` (a struct is delta when its members
//! are all of types ash has, or of other delta structs), the `API_VERSION_1_<m>`
//! constants of the core versions ash lacks, and the `VkStructureType` values of the
//! delta structs as associated constants of one extension trait. Each struct is
//! `#[repr(C)]` with ash's field names, `Default` (its `sType` set), ash's
//! `TaggedStructure` and the `Extends*` traits of the structs whose chain it
//! extends, so it chains with ash's structs. `tests/` compares the layout of every
//! item with the C headers of its registry (`examples/core14`).

use crate::model::Field;
use crate::names::{field, field_ident, ident, type_ident, type_name};
use crate::plan::types::raw_type;
use crate::plan::Context;
use proc_macro2::TokenStream;
use quote::quote;

/// One delta item as the layout test sees it.
pub struct LayoutItem {
    /// The C name (`VkPhysicalDeviceVulkan14Features`).
    pub c_name: String,
    /// Each member: C name and ash's field name.
    pub fields: Vec<(String, String)>,
}

pub(super) fn emit(cx: &Context) -> TokenStream {
    let model = cx.model;
    let mut items = Vec::new();
    let mut s_types = Vec::new();
    let mut s_type_consts = Vec::new();
    let mut layout = Vec::new();
    for name in &model.delta {
        let t = &model.types[name];
        let id = type_ident(name);
        let lifetime = cx.facts.has_lifetime(name);
        let (generics, anon) = if lifetime {
            (quote!(<'a>), quote!(<'_>))
        } else {
            (quote!(), quote!())
        };
        let mut fields = Vec::new();
        let mut setters = Vec::new();
        let mut s_type = None;
        for m in &t.members {
            let f = field_ident(&m.name);
            let ty = member_type(cx, m);
            let field_doc = format!("`{}`", m.name);
            fields.push(quote!(#[doc = #field_doc] pub #f: #ty));
            if m.name == "sType" {
                s_type = m
                    .values
                    .as_deref()
                    .and_then(|v| Some((v, *model_number(cx, v)?)));
                continue;
            }
            if m.name == "pNext" || m.pointers > 0 || m.static_array.is_some() {
                continue;
            }
            let (arg, set) = if m.type_name == "VkBool32" {
                (quote!(bool), quote!(#f.into()))
            } else {
                (ty.clone(), quote!(#f))
            };
            let setter_doc = format!("Sets `{}`.", m.name);
            setters.push(quote! {
                #[doc = #setter_doc]
                #[inline]
                pub fn #f(mut self, #f: #arg) -> Self {
                    self.#f = #set;
                    self
                }
            });
        }
        if lifetime {
            fields.push(quote!(
                #[doc = "The lifetime of what the pointers borrow."]
                pub _marker: core::marker::PhantomData<&'a ()>
            ));
        }
        let doc = format!(
            "`{name}`, which ash {} lacks: defined here in ash's style. <https://registry.khronos.org/vulkan/specs/latest/man/html/{name}.html>",
            model.reference_version.as_deref().unwrap_or("")
        );
        let tagged = s_type.map(|(value, number)| {
            let number = proc_macro2::Literal::i32_unsuffixed(number as i32);
            let konst = ident(&crate::names::enum_const("VkStructureType", value));
            s_types.push(quote! {
                #[doc = #value]
                const #konst: Self;
            });
            s_type_consts.push(quote!(const #konst: Self = vk::StructureType::from_raw(#number);));
            let extends = t.struct_extends.iter().filter(|e| model.extended_in_reference.contains(model.spelling(e))).map(|e| {
                let tr = ident(&format!("Extends{}", type_name(model.spelling(e))));
                quote!(unsafe impl vk::#tr for #id #anon {})
            });
            quote! {
                __safety!("the value the registry gives this struct's `sType`.");
                unsafe impl #generics vk::TaggedStructure for #id #generics {
                    const STRUCTURE_TYPE: vk::StructureType = vk::StructureType::from_raw(#number);
                }
                __safety!("the registry's `structextends`: this struct may be in these structs' `pNext` chains.");
                #(#extends)*
            }
        });
        let set_s_type =
            s_type.map(|_| quote!(value.s_type = <Self as vk::TaggedStructure>::STRUCTURE_TYPE;));
        items.push(quote! {
            #[repr(C)]
            #[derive(Copy, Clone, Debug)]
            #[doc = #doc]
            #[must_use]
            pub struct #id #generics {
                #(#fields,)*
            }
            __safety!("as ash's structs: raw pointers, which a Vulkan call reads only while the struct is borrowed.");
            unsafe impl Send for #id #anon {}
            __safety!("as for `Send`.");
            unsafe impl Sync for #id #anon {}
            impl Default for #id #anon {
                #[inline]
                fn default() -> Self {
                    __safety!("every member is an integer, a float, a raw pointer, an ash newtype of one, an array of those or a struct of them (ash's or this module's): all zeros is a value of each.");
                    #[allow(unused_mut)]
                    let mut value: Self = unsafe { core::mem::zeroed() };
                    #set_s_type
                    value
                }
            }
            #tagged
            impl #generics #id #generics {
                #(#setters)*
            }
        });
        layout.push(LayoutItem {
            c_name: name.to_string(),
            fields: t
                .members
                .iter()
                .map(|m| (m.name.clone(), field(&m.name)))
                .collect(),
        });
    }
    let versions = model.own_tables.iter().map(|m| {
        let c = ident(&format!("API_VERSION_1_{m}"));
        let m = *m;
        let doc = format!("`VK_API_VERSION_1_{m}`, which ash lacks.");
        quote! {
            #[doc = #doc]
            pub const #c: u32 = vk::make_api_version(0, 1, #m, 0);
        }
    });
    let layout_rows = layout.iter().map(|l| {
        let c = &l.c_name;
        let id = type_ident(c);
        let fields = l.fields.iter().map(|(cf, rf)| {
            let f = ident(rf);
            quote!((#cf, core::mem::offset_of!(#id, #f)))
        });
        quote! {
            LayoutRow {
                c_name: #c,
                size: core::mem::size_of::<#id>(),
                align: core::mem::align_of::<#id>(),
                fields: &[#(#fields),*],
            }
        }
    });
    let values = layout.iter().filter_map(|l| {
        let t = &model.types[&l.c_name];
        let v = t
            .members
            .iter()
            .find(|m| m.name == "sType")?
            .values
            .clone()?;
        let n = *model_number(cx, &v)?;
        Some(quote!((#v, #n)))
    });
    let versions_values = model.own_tables.iter().map(|m| {
        let c = format!("VK_API_VERSION_1_{m}");
        let id = ident(&format!("API_VERSION_1_{m}"));
        quote!((#c, #id as i64))
    });
    let trait_doc = "The `VkStructureType` values of this module's structs, as ash would name them: `vk::StructureType::PHYSICAL_DEVICE_VULKAN_1_4_FEATURES` with this trait in scope.";
    quote! {
        //! What the registry has and ash lacks, defined in ash's style: structs,
        //! core-version constants and `VkStructureType` values. `tuff::vk` re-exports
        //! ash's `vk` and this module together.
        #![allow(clippy::too_many_arguments, clippy::missing_safety_doc)]
        use ash::vk;

        #(#versions)*

        #[doc = #trait_doc]
        pub trait StructureTypeDelta {
            #(#s_types)*
        }
        impl StructureTypeDelta for vk::StructureType {
            #(#s_type_consts)*
        }

        #(#items)*

        /// The layout of every item of this module, for the test that compares it
        /// with the C headers of the registry.
        #[doc(hidden)]
        pub mod delta_layout {
            #[allow(unused_imports)]
            use super::*;
        /// One struct's layout as Rust lays it out, for the test that compares it with
        /// the C headers.
                pub struct LayoutRow {
            /// The C name.
            pub c_name: &'static str,
            /// `size_of`.
            pub size: usize,
            /// `align_of`.
            pub align: usize,
            /// Each member's C name and offset.
            pub fields: &'static [(&'static str, usize)],
        }

        /// Every struct of this module, laid out.
                pub const LAYOUT: &[LayoutRow] = &[#(#layout_rows),*];

        /// Every constant of this module by its C name, with its value.
                pub const VALUES: &[(&str, i64)] = &[#(#values,)* #(#versions_values,)*];
        }
    }
}

fn model_number<'a>(cx: &'a Context, value: &str) -> Option<&'a i64> {
    cx.model.enum_numbers.get(value)
}

/// A member's type as ash would write it in the struct: pointers, and a fixed array
/// `[T; N]` with N as ash names the constant (`vk::UUID_SIZE`) or the number.
fn member_type(cx: &Context, m: &Field) -> TokenStream {
    let ty = match m.type_name.as_str() {
        "VkBool32" if m.pointers == 0 => quote!(vk::Bool32),
        _ => raw_type(cx.model, &cx.facts, m),
    };
    match m.static_array.as_deref() {
        None => ty,
        Some(n) if n.chars().all(|c| c.is_ascii_digit()) => {
            let n: usize = n.parse().unwrap_or(0);
            quote!([#ty; #n])
        }
        Some(n) => {
            let c = ident(n.strip_prefix("VK_").unwrap_or(n));
            quote!([#ty; vk::#c])
        }
    }
}
