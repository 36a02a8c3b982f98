//! Emits `src/generated/delta.rs`: what the registry has and ash lacks, in ash's
//! style, so the rest of the crate names it as it names ash's items (`crate::vk`
//! re-exports ash's `vk` and this module together).
//!
//! Today that is the structs of `Model::delta` (a struct is delta when its members
//! are all of types ash has, or of other delta structs), the `API_VERSION_1_<m>`
//! constants of the core versions ash lacks, and the enum values ash lacks by name
//! (`Model::delta_constants`) as associated constants of one trait per type. Each struct is
//! `#[repr(C)]` with ash's field names, `Default` (its `sType` set), ash's
//! `TaggedStructure` and the `Extends*` traits of the structs whose chain it
//! extends, so it chains with ash's structs. `tests/` compares the layout of every
//! item with the C headers of its registry (`examples/core14`).

use crate::model::Field;
use crate::names::{field_ident, ident, type_ident, type_name};
use crate::plan::types::{ash_type, raw_type, with_pointers};
use crate::plan::Context;
use proc_macro2::TokenStream;
use quote::quote;

pub(super) fn emit(cx: &Context) -> TokenStream {
    let model = cx.model;
    let mut items = Vec::new();
    let mut layout_rows = Vec::new();
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
                    .and_then(|v| model.enum_numbers.get(v).copied());
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
        let tagged = s_type.map(|number| {
            let number = proc_macro2::Literal::i32_unsuffixed(number as i32);
            let extends: Vec<TokenStream> = t.struct_extends.iter().filter(|e| model.extended_in_reference.contains(model.spelling(e))).map(|e| {
                let tr = ident(&format!("Extends{}", type_name(model.spelling(e))));
                quote!(unsafe impl vk::#tr for #id #anon {})
            }).collect();
            // ash has an `Extends` trait only for a struct something extends in its
            // registry; a delta struct that extends only others is chained by tuff's
            // safe struct alone.
            let extends_safety = (!extends.is_empty()).then(|| quote! {
                __safety!("the registry's `structextends`: this struct may be in these structs' `pNext` chains.");
            });
            quote! {
                __safety!("the value the registry gives this struct's `sType`.");
                unsafe impl #generics vk::TaggedStructure for #id #generics {
                    const STRUCTURE_TYPE: vk::StructureType = vk::StructureType::from_raw(#number);
                }
                #extends_safety
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
        let offsets = t.members.iter().map(|m| {
            let (c, f) = (&m.name, field_ident(&m.name));
            quote!((#c, core::mem::offset_of!(#id, #f)))
        });
        layout_rows.push(quote! {
            LayoutRow {
                c_name: #name,
                size: core::mem::size_of::<#id>(),
                align: core::mem::align_of::<#id>(),
                fields: &[#(#offsets),*],
            }
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
    let (traits, values) = value_traits(cx);
    let versions_values = model.own_tables.iter().map(|m| {
        let c = format!("VK_API_VERSION_1_{m}");
        let id = ident(&format!("API_VERSION_1_{m}"));
        quote!((#c, #id as i64))
    });
    quote! {
        //! What the registry has and ash lacks, defined in ash's style: structs,
        //! core-version constants, and enum values as associated constants of one
        //! trait per type (`IndexTypeDelta`). `tuff::vk` re-exports ash's `vk` and this
        //! module together.
        #![allow(clippy::too_many_arguments, clippy::missing_safety_doc)]
        // Unused where the registry is ash's or older: then nothing is defined here.
        #[allow(unused_imports)]
        use ash::vk;

        #(#versions)*

        #(#traits)*

        #(#items)*

        /// The layout of every item of this module, for the test that compares it
        /// with the C headers of the registry.
        #[doc(hidden)]
        pub mod delta_layout {
            #[allow(unused_imports)]
            use super::*;

            /// One struct's layout as Rust lays it out.
            #[derive(Debug)]
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

/// For each enum type ash has whose enabled values it lacks by name, a trait
/// `<Type>Delta` with one associated constant per value (`vk::IndexType::UINT8` with
/// `IndexTypeDelta` in scope), implemented for ash's type; and every such value by
/// its C name with its number, for the layout test.
fn value_traits(cx: &Context) -> (Vec<TokenStream>, Vec<TokenStream>) {
    let model = cx.model;
    let mut by_type: std::collections::BTreeMap<&str, Vec<(&str, i64)>> = Default::default();
    for (group, v, n) in model.delta_constants() {
        by_type.entry(group).or_default().push((v, n));
    }
    let mut traits = Vec::new();
    let mut values = Vec::new();
    for (group, consts) in by_type {
        let Some(ty) = ash_type(model, &cx.facts, group) else {
            continue;
        };
        let spelled = type_name(model.spelling(group)).replace("FlagBits", "Flags");
        let tr = ident(&format!("{spelled}Delta"));
        let mut seen = std::collections::BTreeSet::new();
        let mut decls = Vec::new();
        let mut impls = Vec::new();
        for (v, n) in consts {
            let mut konst = value_const(group, v);
            if !seen.insert(konst.clone()) {
                // Two values that shorten alike keep their full names.
                konst = v.strip_prefix("VK_").unwrap_or(v).to_owned();
                if !seen.insert(konst.clone()) {
                    continue;
                }
            }
            let k = ident(&konst);
            let doc = format!("`{v}`");
            let raw = if group.contains("FlagBits") {
                let n = proc_macro2::Literal::u64_suffixed(n as u64);
                quote!(#ty::from_raw(#n as _))
            } else {
                let n = proc_macro2::Literal::i32_unsuffixed(n as i32);
                quote!(#ty::from_raw(#n))
            };
            decls.push(quote!(#[doc = #doc] const #k: Self;));
            impls.push(quote!(const #k: Self = #raw;));
            values.push(quote!((#v, #n)));
        }
        let doc = format!(
            "The values of `{group}` that ash lacks by these names, as associated constants of ash's type (with this trait in scope: `{}::{}`).",
            spelled,
            seen.iter().next().map_or("", String::as_str)
        );
        traits.push(quote! {
            #[doc = #doc]
            pub trait #tr {
                #(#decls)*
            }
            impl #tr for #ty {
                #(#impls)*
            }
        });
    }
    (traits, values)
}

/// A value's constant name as ash would write it: the type's words and, for bits,
/// the `_BIT` go (`VK_SUBGROUP_FEATURE_ROTATE_BIT` of `VkSubgroupFeatureFlagBits`
/// is `ROTATE`); a name that would start with a digit is prefixed `TYPE_`.
fn value_const(group: &str, value: &str) -> String {
    let Some((before, after)) = group.split_once("FlagBits") else {
        let c = crate::names::enum_const(group, value);
        // A value outside its type's prefix (`VK_ERROR_NOT_PERMITTED` of `VkResult`)
        // keeps its name less `VK_`, as ash writes it.
        return match c == value {
            true => value.strip_prefix("VK_").unwrap_or(value).to_owned(),
            false => c,
        };
    };
    let base = before.strip_prefix("Vk").unwrap_or(before);
    let digits: String = after.chars().take_while(char::is_ascii_digit).collect();
    let words = heck::ToShoutySnakeCase::to_shouty_snake_case(base);
    // `VkAccessFlagBits2` values are `VK_ACCESS_2_...`.
    let prefix = match digits.is_empty() {
        true => format!("VK_{words}_"),
        false => format!("VK_{words}_{digits}_"),
    };
    let mut rest = match value.strip_prefix(&prefix) {
        Some(r) => r.to_owned(),
        None => value.strip_prefix("VK_").unwrap_or(value).to_owned(),
    };
    if let Some(r) = rest.strip_suffix("_BIT") {
        rest = r.to_owned();
    } else if let Some(i) = rest.find("_BIT_") {
        rest = format!("{}{}", &rest[..i], &rest[i + 4..]);
    }
    if rest.starts_with(|c: char| c.is_ascii_digit()) {
        rest = format!("TYPE_{rest}");
    }
    rest
}

/// A member's type as ash would write it in the struct: pointers, and a fixed array
/// `[T; N]` with N as ash names the constant (`vk::UUID_SIZE`) or the number.
fn member_type(cx: &Context, m: &Field) -> TokenStream {
    let ty = match m.type_name.as_str() {
        "VkBool32" if m.pointers == 0 => quote!(vk::Bool32),
        // Another struct of this module (`vk` here is ash's alone).
        t if cx.model.delta.contains(t) => {
            let id = type_ident(t);
            let ty = match cx.facts.has_lifetime(t) {
                true => quote!(#id<'a>),
                false => quote!(#id),
            };
            with_pointers(ty, m)
        }
        t => {
            // `spellable` admitted only types ash spells; a by-value member of one it
            // cannot would be laid out wrong, so that is a generator bug.
            assert!(
                m.pointers > 0 || ash_type(cx.model, &cx.facts, t).is_some(),
                "delta member `{}` of type `{t}` has no spelling",
                m.name
            );
            raw_type(cx.model, &cx.facts, m)
        }
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
