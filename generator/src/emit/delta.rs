//! Emits `src/generated/delta.rs`: what the registry has and ash lacks, in ash's
//! style, so the rest of the crate names it as it names ash's items (`crate::vk`
//! re-exports ash's `vk` and this module together).
//!
//! That is the types of `Model::delta`: structs and unions (`#[repr(C)]` with ash's
//! field names, `Default` with the `sType` set, ash's `TaggedStructure` and the
//! `Extends*` traits of the structs whose chain they extend, so they chain with
//! ash's), enums (`i32` newtypes with their values), flags types (through ash's
//! own `vk_bitflags_wrapped!`) and non-dispatchable handles (ash's
//! `handle_nondispatchable!`); the `PFN_` types of the commands of extensions ash
//! lacks altogether and their function tables, in modules named as ash's
//! (`ash::khr::pipeline_binary` is `khr::pipeline_binary` here); the `API_VERSION_1_<m>` constants of the
//! core versions ash lacks and the array sizes it lacks; and the enum values ash
//! lacks by name (`Model::delta_constants`), as associated constants of one trait
//! per ash type. `examples/core14`'s layout test compares every type and constant
//! with the C headers of its registry.

use crate::model::{Field, Kind};
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
        if t.category == Some(Kind::Union) {
            let (item, row) = union_item(cx, name);
            items.push(item);
            layout_rows.push(row);
            continue;
        }
        if t.category != Some(Kind::Struct) {
            continue;
        }
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
            fields.push(lifetime_marker());
        }
        let doc = item_doc(cx, name, "");
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
        // A union has no `Debug` (which member is live is the struct's to say), nor
        // have some of ash's structs: a struct with such a member shows the others.
        let undebuggable = t.members.iter().any(|m| !has_debug(cx, &m.type_name));
        let (derive, debug) = if undebuggable {
            let shown = t
                .members
                .iter()
                .filter(|m| has_debug(cx, &m.type_name))
                .map(|m| {
                    let (c, f) = (&m.name, field_ident(&m.name));
                    quote!(.field(#c, &self.#f))
                });
            let c_name = name.as_str();
            (
                quote!(#[derive(Copy, Clone)]),
                Some(quote! {
                    impl core::fmt::Debug for #id #anon {
                        fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
                            f.debug_struct(#c_name) #(#shown)* .finish_non_exhaustive()
                        }
                    }
                }),
            )
        } else {
            (quote!(#[derive(Copy, Clone, Debug)]), None)
        };
        items.push(quote! {
            #[repr(C)]
            #derive
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
            #debug
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
    let mut values = Vec::new();
    let mut handles = Vec::new();
    for name in &model.delta {
        let t = &model.types[name];
        match t.category {
            Some(Kind::Enum) if !name.contains("FlagBits") => {
                let (item, row) = enum_item(cx, name, &mut values);
                items.push(item);
                layout_rows.push(row);
            }
            Some(Kind::Handle) => {
                let (item, row) = handle_item(cx, name);
                handles.push(item);
                layout_rows.push(row);
            }
            _ => {}
        }
    }
    // Types made by ash's own macros, whose methods have no docs: in a module of
    // their own that allows that, re-exported.
    let mut by_macro = Vec::new();
    for flags in model.delta_flags() {
        let (item, row) = flags_item(cx, &flags, &mut values);
        by_macro.push(item);
        layout_rows.push(row);
    }
    let pfns = model.delta_commands.iter().map(|c| pfn_item(cx, c));
    let tables = extension_tables(cx);
    let handle_imports = (!handles.is_empty()).then(|| {
        quote!(
            use ash::vk::{Handle, ObjectType};
            use core::fmt;
        )
    });
    let macro_made = (!by_macro.is_empty() || !handles.is_empty()).then(|| {
        quote! {
            pub use by_ash_macros::*;
            /// The flags types and handles, made by ash's own macros (whose methods
            /// are ash's, undocumented here as there).
            mod by_ash_macros {
                #![allow(missing_docs)]
                #[allow(unused_imports)]
                use super::*;
                #handle_imports
                #(#by_macro)*
                #(#handles)*
            }
        }
    });
    let sizes = model.delta_sizes.iter().map(|(c, n)| {
        let id = ident(c.strip_prefix("VK_").unwrap_or(c));
        let doc = format!("`{c}`, which ash lacks.");
        let n = proc_macro2::Literal::usize_unsuffixed(*n as usize);
        quote! {
            #[doc = #doc]
            pub const #id: usize = #n;
        }
    });
    let sizes_values = model.delta_sizes.keys().map(|c| {
        let id = ident(c.strip_prefix("VK_").unwrap_or(c));
        quote!((#c, #id as i64))
    });
    let (traits, trait_values) = value_traits(cx);
    values.extend(trait_values);
    let versions_values = model.own_tables.iter().map(|m| {
        let c = format!("VK_API_VERSION_1_{m}");
        let id = ident(&format!("API_VERSION_1_{m}"));
        quote!((#c, #id as i64))
    });
    quote! {
        //! What the registry has and ash lacks, defined in ash's style: structs,
        //! unions, enums, flags types and handles; the function tables of the
        //! extensions ash lacks (`khr::pipeline_binary::DeviceFn`); core-version and
        //! array-size constants; and enum values of ash's types as associated
        //! constants of one trait per type (`IndexTypeDelta`). `tuff::vk` re-exports
        //! ash's `vk` and this module together.
        #![allow(clippy::too_many_arguments, clippy::missing_safety_doc, non_camel_case_types)]
        // Ash's items and this module's together (the glob re-export of `crate::vk`
        // takes only public items, so this private import makes no cycle). Unused
        // where the registry is ash's or older: then nothing is defined here.
        #[allow(unused_imports)]
        use crate::vk;
        #macro_made

        #(#versions)*

        #(#sizes)*

        #(#traits)*

        #(#items)*

        #(#pfns)*

        #tables

        /// The layout of every item of this module, for the test that compares it
        /// with the C headers of the registry.
        #[doc(hidden)]
        pub mod delta_layout {
            #[allow(unused_imports)]
            use super::*;

            /// One type's layout as Rust lays it out.
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

            /// Every type of this module, laid out.
            pub const LAYOUT: &[LayoutRow] = &[#(#layout_rows),*];

            /// Every constant of this module by its C name, with its value.
            pub const VALUES: &[(&str, i64)] = &[#(#values,)* #(#versions_values,)* #(#sizes_values,)*];
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
        // A type of this module has its values as its own constants.
        if model.delta.contains(group) {
            continue;
        }
        let Some(ty) = ash_type(model, &cx.facts, group) else {
            continue;
        };
        let spelled = type_name(model.spelling(group)).replace("FlagBits", "Flags");
        let tr = ident(&format!("{spelled}Delta"));
        let mut seen = std::collections::BTreeSet::new();
        let mut decls = Vec::new();
        let mut impls = Vec::new();
        for (v, n) in consts {
            let Some(konst) = unique_const(&mut seen, group, v) else {
                continue;
            };
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

/// A value's constant name, unique among `seen`: as ash would write it, or where two
/// values shorten alike, the full name less `VK_`; `None` for a second value of the
/// same full name.
fn unique_const(
    seen: &mut std::collections::BTreeSet<String>,
    group: &str,
    value: &str,
) -> Option<String> {
    let short = value_const(group, value);
    if seen.insert(short.clone()) {
        return Some(short);
    }
    let full = value.strip_prefix("VK_").unwrap_or(value).to_owned();
    seen.insert(full.clone()).then_some(full)
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
    // The type's own vendor tag goes, as ash drops it (`..._BIT_EXT` of an `...EXT`
    // type); another vendor's stays.
    let tag = &after[digits.len()..];
    if !tag.is_empty() {
        if let Some(r) = rest.strip_suffix(&format!("_{tag}")) {
            rest = r.to_owned();
        }
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
        // Another struct or union of this module, named as the module names it.
        t if cx.model.delta.contains(t)
            && matches!(cx.model.category(t), Some(Kind::Struct | Kind::Union)) =>
        {
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
            match cx.model.delta_sizes.contains_key(n) {
                // This module's own constant.
                true => quote!([#ty; #c]),
                false => quote!([#ty; vk::#c]),
            }
        }
    }
}

/// A union the reference lacks, as ash writes one: `#[repr(C)]`, `Copy`, all zeros
/// by default, and a `Debug` that shows only its C name (which member is
/// live is the enclosing struct's to say).
fn union_item(cx: &Context, name: &str) -> (TokenStream, TokenStream) {
    let t = &cx.model.types[name];
    let id = type_ident(name);
    let lifetime = cx.facts.has_lifetime(name);
    let (generics, anon) = match lifetime {
        true => (quote!(<'a>), quote!(<'_>)),
        false => (quote!(), quote!()),
    };
    let fields: Vec<TokenStream> = t
        .members
        .iter()
        .map(|m| {
            let f = field_ident(&m.name);
            let ty = member_type(cx, m);
            let doc = format!("`{}`", m.name);
            quote!(#[doc = #doc] pub #f: #ty)
        })
        .collect();
    // No marker field: the members that borrow carry the lifetime themselves, and a
    // union's every field is one more way to set it.
    let doc = item_doc(cx, name, "");
    let item = quote! {
        #[repr(C)]
        #[derive(Copy, Clone)]
        #[doc = #doc]
        pub union #id #generics {
            #(#fields,)*
        }
        impl Default for #id #anon {
            #[inline]
            fn default() -> Self {
                __safety!("every member is an integer, a float, a raw pointer or a struct of them: all zeros is a value of each.");
                unsafe { core::mem::zeroed() }
            }
        }
        impl core::fmt::Debug for #id #anon {
            fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
                f.write_str(#name)
            }
        }
    };
    let offsets = t.members.iter().map(|m| {
        let (c, f) = (&m.name, field_ident(&m.name));
        quote!((#c, core::mem::offset_of!(#id, #f)))
    });
    let row = quote! {
        LayoutRow {
            c_name: #name,
            size: core::mem::size_of::<#id>(),
            align: core::mem::align_of::<#id>(),
            fields: &[#(#offsets),*],
        }
    };
    (item, row)
}

/// The delta's values of `group` that have a number, each with the constant name
/// ash would give it, two names for one number keeping both; pushed to `values` by
/// their C names for the layout test.
fn own_values(
    cx: &Context,
    group: &str,
    id: &proc_macro2::Ident,
    values: &mut Vec<TokenStream>,
) -> Vec<(proc_macro2::Ident, String, i64)> {
    let model = cx.model;
    let mut out = Vec::new();
    let mut seen = std::collections::BTreeSet::new();
    for v in model.delta_values.get(group).into_iter().flatten() {
        let Some(&n) = model.enum_numbers.get(v) else {
            continue;
        };
        let Some(konst) = unique_const(&mut seen, group, v) else {
            continue;
        };
        let k = ident(&konst);
        values.push(quote!((#v, #id::#k.as_raw() as i64)));
        out.push((k, v.clone(), n));
    }
    out
}

/// An enum the reference lacks, as ash writes one: a `#[repr(transparent)]` `i32`
/// newtype with its values as associated constants, `from_raw`/`as_raw`, and a
/// `Debug` that names a known value.
fn enum_item(
    cx: &Context,
    name: &str,
    values: &mut Vec<TokenStream>,
) -> (TokenStream, TokenStream) {
    let id = type_ident(cx.model.spelling(name));
    let consts = own_values(cx, name, &id, values);
    let decls = consts.iter().map(|(k, v, n)| {
        let doc = format!("`{v}`");
        let n = proc_macro2::Literal::i32_unsuffixed(*n as i32);
        quote!(#[doc = #doc] pub const #k: Self = Self(#n);)
    });
    // One arm per number: a second name for a value is shown by the first.
    let mut numbers = std::collections::BTreeSet::new();
    let arms = consts
        .iter()
        .filter(|(_, _, n)| numbers.insert(*n))
        .map(|(k, _, _)| {
            let shown = k.to_string();
            quote!(Self::#k => Some(#shown),)
        });
    let doc = item_doc(cx, name, "");
    let item = quote! {
        #[repr(transparent)]
        #[derive(Copy, Clone, Default, PartialEq, Eq, PartialOrd, Ord, Hash)]
        #[doc = #doc]
        pub struct #id(i32);
        impl #id {
            /// The value of this number.
            #[inline]
            pub const fn from_raw(x: i32) -> Self {
                Self(x)
            }
            /// The number.
            #[inline]
            pub const fn as_raw(self) -> i32 {
                self.0
            }
        }
        impl #id {
            #(#decls)*
        }
        impl core::fmt::Debug for #id {
            fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
                let name = match *self {
                    #(#arms)*
                    _ => None,
                };
                match name {
                    Some(name) => f.write_str(name),
                    None => core::fmt::Debug::fmt(&self.0, f),
                }
            }
        }
    };
    (item, size_row(name, &id))
}

/// A delta item's doc: what it is, that ash lacks it (`extra` after the name), and
/// its reference page.
fn item_doc(cx: &Context, name: &str, extra: &str) -> String {
    format!(
        "`{name}`{extra}, which ash {} lacks: defined here in ash's style. <https://registry.khronos.org/vulkan/specs/latest/man/html/{name}.html>",
        cx.model.reference_version.as_deref().unwrap_or("")
    )
}

/// The field that gives a struct or union with pointers its lifetime.
fn lifetime_marker() -> TokenStream {
    quote!(
        #[doc = "The lifetime of what the pointers borrow."]
        pub _marker: core::marker::PhantomData<&'a ()>
    )
}

/// A row of a type laid out with no members to compare: its size and alignment.
fn size_row(c_name: &str, id: &proc_macro2::Ident) -> TokenStream {
    quote! {
        LayoutRow {
            c_name: #c_name,
            size: core::mem::size_of::<#id>(),
            align: core::mem::align_of::<#id>(),
            fields: &[],
        }
    }
}

/// A flags type the reference lacks, as ash writes one: a newtype of `vk::Flags`
/// (or `vk::Flags64`) with ash's own `vk_bitflags_wrapped!` operations, the bits as
/// associated constants, and a `Debug` that names the bits set.
fn flags_item(
    cx: &Context,
    flags: &crate::model::DeltaFlags,
    values: &mut Vec<TokenStream>,
) -> (TokenStream, TokenStream) {
    let spelled = type_name(cx.model.spelling(&flags.c_name)).replace("FlagBits", "Flags");
    let id = ident(&spelled);
    let consts = match &flags.bits {
        Some(bits) => own_values(cx, bits, &id, values),
        None => Vec::new(),
    };
    let raw = match flags.wide {
        true => quote!(vk::Flags64),
        false => quote!(vk::Flags),
    };
    let decls = consts.iter().map(|(k, v, n)| {
        let doc = format!("`{v}`");
        let n = proc_macro2::Literal::u64_unsuffixed(*n as u64);
        quote!(#[doc = #doc] pub const #k: Self = Self(#n);)
    });
    let known = consts.iter().map(|(k, _, _)| {
        let shown = k.to_string();
        quote!((#id::#k, #shown))
    });
    let c_name = &flags.c_name;
    let doc = item_doc(cx, c_name, " and its bits");
    let item = quote! {
        #[repr(transparent)]
        #[derive(Copy, Clone, PartialEq, Eq, PartialOrd, Ord, Hash)]
        #[doc = #doc]
        pub struct #id(#raw);
        ash::vk_bitflags_wrapped!(#id, #raw);
        impl #id {
            #(#decls)*
        }
        impl core::fmt::Debug for #id {
            fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
                const KNOWN: &[(#id, &str)] = &[#(#known),*];
                let mut rest = self.0;
                let mut first = true;
                for (bit, name) in KNOWN {
                    if bit.0 != 0 && self.0 & bit.0 == bit.0 && rest & bit.0 != 0 {
                        if !first {
                            f.write_str(" | ")?;
                        }
                        f.write_str(name)?;
                        rest &= !bit.0;
                        first = false;
                    }
                }
                if rest != 0 || first {
                    if !first {
                        f.write_str(" | ")?;
                    }
                    write!(f, "{rest:#x}")?;
                }
                Ok(())
            }
        }
    };
    (item, size_row(c_name, &id))
}

/// A handle the reference lacks, through ash's own `handle_nondispatchable!` (a
/// dispatchable one is left out: `reference::missing_items`), so it is ash's
/// `Handle` with its object type.
fn handle_item(cx: &Context, name: &str) -> (TokenStream, TokenStream) {
    let model = cx.model;
    let t = &model.types[name];
    let id = type_ident(model.spelling(name));
    // The object type's value: `VK_OBJECT_TYPE_` and the name's words.
    let words =
        heck::ToShoutySnakeCase::to_shouty_snake_case(name.strip_prefix("Vk").unwrap_or(name));
    let value = format!("VK_OBJECT_TYPE_{words}");
    assert!(
        model.enum_numbers.contains_key(&value),
        "handle `{name}` has no object type `{value}`"
    );
    let object_type = ident(&value_const("VkObjectType", &value));
    let doc = format!(
        "`{name}`, which ash {} lacks: defined here by ash's own macro. <https://registry.khronos.org/vulkan/specs/latest/man/html/{name}.html>",
        model.reference_version.as_deref().unwrap_or("")
    );
    assert!(!t.dispatchable, "dispatchable delta handle `{name}`");
    let item = quote!(ash::handle_nondispatchable!(#id, #object_type, doc = #doc););
    (item, size_row(name, &id))
}

/// The `PFN_` type of a command of an extension ash lacks, as ash writes one.
fn pfn_item(cx: &Context, command: &str) -> TokenStream {
    let c = &cx.model.commands[command];
    let id = ident(&format!("PFN_{command}"));
    let params = c.params.iter().map(|p| {
        let name = field_ident(&p.name);
        let ty = pfn_type(cx, p);
        quote!(#name: #ty)
    });
    let ret = match c.return_type.as_str() {
        "void" => quote!(),
        r => {
            let ty = ash_type(cx.model, &cx.facts, r).expect("a command's result type ash spells");
            quote!(-> #ty)
        }
    };
    let doc = format!("The type of `{command}`.");
    quote! {
        #[doc = #doc]
        #[allow(non_camel_case_types)]
        pub type #id = unsafe extern "system" fn(#(#params),*) #ret;
    }
}

/// A parameter's type in a `PFN_` type: ash's spelling with any lifetime elided.
fn pfn_type(cx: &Context, p: &Field) -> TokenStream {
    let base = match cx.facts.has_lifetime(&p.type_name) {
        true => {
            let id = type_ident(cx.model.spelling(&p.type_name));
            quote!(vk::#id<'_>)
        }
        false => match ash_type(cx.model, &cx.facts, &p.type_name) {
            Some(ty) => ty,
            // Behind a pointer, an opaque type is `c_void` as in ash; by value, a
            // type with no spelling would give the call the wrong ABI.
            None if p.pointers > 0 => quote!(::core::ffi::c_void),
            None => panic!(
                "parameter `{}` of type `{}` has no spelling",
                p.name, p.type_name
            ),
        },
    };
    match p.static_array.as_deref() {
        // A C array parameter is a pointer to its first element (ash writes
        // `*const [T; N]`).
        Some(n) => {
            let n: usize = n
                .parse()
                .unwrap_or_else(|_| panic!("array parameter `{}` of size `{n}`", p.name));
            let ty = with_pointers(base, p);
            match p.is_const {
                true => quote!(*const [#ty; #n]),
                false => quote!(*mut [#ty; #n]),
            }
        }
        None => with_pointers(base, p),
    }
}

/// Each extension ash lacks that has commands gets ash's module path under this
/// module (`khr::pipeline_binary`) with its `DeviceFn` and `InstanceFn`, as ash
/// splits them: one field per command, named as ash would, loaded by name through
/// `vkGetDeviceProcAddr` or `vkGetInstanceProcAddr`.
fn extension_tables(cx: &Context) -> TokenStream {
    use crate::names::Level;
    let model = cx.model;
    let mut by_vendor: std::collections::BTreeMap<String, Vec<TokenStream>> = Default::default();
    for e in &model.own_extensions {
        let commands: Vec<&String> = model
            .delta_commands
            .iter()
            .filter(|c| {
                crate::names::table(model, c) == Some(crate::names::Table::Extension(e.clone()))
            })
            .collect();
        if commands.is_empty() {
            continue;
        }
        let mut tables = Vec::new();
        for at in [Level::Instance, Level::Device] {
            let here: Vec<&&String> = commands
                .iter()
                .filter(|c| crate::names::level(model, c) == at)
                .collect();
            if here.is_empty() {
                continue;
            }
            let entries: Vec<TableEntry> = here
                .iter()
                .map(|c| TableEntry {
                    // Named as the call sites name it (`names::fn_field`): by the
                    // name the extension's require block gives the command.
                    field: crate::names::fn_field(
                        model,
                        c,
                        &crate::names::Table::Extension(e.clone()),
                    ),
                    pfn: {
                        let pfn = ident(&format!("PFN_{c}"));
                        quote!(super::super::#pfn)
                    },
                    // Loaded by the same name (an alias the extension's require
                    // block uses, where a core version promoted the command).
                    name: model.name_in(c, e).to_owned(),
                })
                .collect();
            let (struct_name, what, args, get) = match at {
                Level::Device => (
                    ident("DeviceFn"),
                    "device-level",
                    quote!(instance: &ash::Instance, device: &ash::Device),
                    quote! {
                        __safety!("`device` is a live device of `instance`, and `name` a NUL-terminated string.");
                        unsafe { (instance.fp_v1_0().get_device_proc_addr)(device.handle(), name.as_ptr()) }
                    },
                ),
                _ => (
                    ident("InstanceFn"),
                    "instance-level",
                    quote!(entry: &ash::Entry, instance: &ash::Instance),
                    quote! {
                        __safety!("`instance` is a live instance of `entry`, and `name` a NUL-terminated string.");
                        unsafe { (entry.static_fn().get_instance_proc_addr)(instance.handle(), name.as_ptr()) }
                    },
                ),
            };
            tables.push(fn_table(
                &struct_name,
                &format!("`{e}`'s {what} commands."),
                "Loads every command of the table; `None` if the loader lacks one.",
                quote!(load_from(#args)),
                get,
                "its `PFN_` type's",
                &entries,
            ));
        }
        let (vendor, module) = own_module(e);
        let module_id = ident(&module);
        let doc = format!("`{e}`, which ash lacks: its function tables.");
        by_vendor.entry(vendor).or_default().push(quote! {
            #[doc = #doc]
            pub mod #module_id {
                #(#tables)*
            }
        });
    }
    let vendors = by_vendor.into_iter().map(|(vendor, modules)| {
        let v = ident(&vendor);
        let doc = format!(
            "Function tables of `{}` extensions ash lacks.",
            vendor.to_uppercase()
        );
        quote! {
            #[doc = #doc]
            pub mod #v {
                #(#modules)*
            }
        }
    });
    quote!(#(#vendors)*)
}

/// One command of a function table the crate defines.
pub(super) struct TableEntry {
    /// The table's field.
    pub field: proc_macro2::Ident,
    /// Its `PFN_` type, as the table's module names it.
    pub pfn: TokenStream,
    /// The name it is loaded by.
    pub name: String,
}

/// A function table the crate defines (an extension's that ash lacks, a core
/// version's that ash has none for): one field per command, typed by its `PFN_`
/// type, and a loader `#load` that looks each up by name through `#get` (a closure
/// body over `name: &CStr`), `None` when one is missing. `signature` says whose
/// signature the `PFN_` type is, for the transmute's `// SAFETY:`.
pub(super) fn fn_table(
    struct_name: &proc_macro2::Ident,
    doc: &str,
    load_doc: &str,
    load: TokenStream,
    get: TokenStream,
    signature: &str,
    entries: &[TableEntry],
) -> TokenStream {
    let safety = format!("the loader returned the command named, whose signature is {signature}.");
    let members = entries.iter().map(|e| {
        let (f, pfn) = (&e.field, &e.pfn);
        let doc = format!("`{}`.", e.name);
        quote! {
            #[doc = #doc]
            pub #f: #pfn,
        }
    });
    let inits = entries.iter().map(|e| {
        let (f, pfn) = (&e.field, &e.pfn);
        let name = proc_macro2::Literal::c_string(
            &std::ffi::CString::new(e.name.as_str()).expect("a command name has no NUL"),
        );
        quote! {
            #f: {
                let f = get(#name)?;
                __safety!(#safety);
                unsafe { core::mem::transmute::<unsafe extern "system" fn(), #pfn>(f) }
            },
        }
    });
    quote! {
        #[doc = #doc]
        #[derive(Clone, Copy)]
        #[allow(missing_debug_implementations)]
        pub struct #struct_name {
            #(#members)*
        }
        impl #struct_name {
            #[doc = #load_doc]
            pub fn #load -> Option<Self> {
                let get = |name: &core::ffi::CStr| { #get };
                Some(#struct_name { #(#inits)* })
            }
        }
    }
}

/// ash's module path of an extension, as (vendor, name): `VK_KHR_pipeline_binary`
/// is `("khr", "pipeline_binary")`.
pub fn own_module(ext: &str) -> (String, String) {
    let rest = ext.strip_prefix("VK_").unwrap_or(ext);
    let (vendor, name) = rest.split_once('_').unwrap_or(("khr", rest));
    (vendor.to_lowercase(), name.to_owned())
}

/// ash's structs that have no `Debug` although no union or bit field says so: a
/// two-dimensional array member (`float matrix[3][4]`).
const NO_DEBUG_IN_ASH: &[&str] = &["VkTransformMatrixKHR"];

/// Whether a member of type `name` implements `Debug`: not a union, nor one of ash's
/// structs with a bit field or in [`NO_DEBUG_IN_ASH`] (this module's own structs
/// always do).
fn has_debug(cx: &Context, name: &str) -> bool {
    let model = cx.model;
    match model.category(name) {
        Some(Kind::Union) => false,
        Some(Kind::Struct) if !model.delta.contains(name) => {
            let spelled = model.spelling(name);
            !NO_DEBUG_IN_ASH.contains(&spelled)
                && !model.types[spelled]
                    .members
                    .iter()
                    .any(|m| m.bitfield.is_some())
        }
        _ => true,
    }
}

#[cfg(test)]
mod tests {
    use super::value_const;

    #[test]
    fn values_are_named_as_ash_names_them() {
        assert_eq!(
            value_const(
                "VkSubgroupFeatureFlagBits",
                "VK_SUBGROUP_FEATURE_ROTATE_BIT"
            ),
            "ROTATE"
        );
        // The type's own vendor tag goes, after its number.
        assert_eq!(
            value_const(
                "VkIndirectCommandsInputModeFlagBitsEXT",
                "VK_INDIRECT_COMMANDS_INPUT_MODE_DXGI_INDEX_BUFFER_EXT"
            ),
            "DXGI_INDEX_BUFFER"
        );
        assert_eq!(
            value_const("VkAccessFlagBits3KHR", "VK_ACCESS_3_NONE_KHR"),
            "NONE"
        );
        // Another vendor's stays.
        assert_eq!(
            value_const(
                "VkPipelineCreateFlagBits",
                "VK_PIPELINE_CREATE_RAY_TRACING_NO_NULL_ANY_HIT_SHADERS_BIT_KHR"
            ),
            "RAY_TRACING_NO_NULL_ANY_HIT_SHADERS_KHR"
        );
        assert_eq!(
            value_const(
                "VkPhysicalDeviceLayeredApiKHR",
                "VK_PHYSICAL_DEVICE_LAYERED_API_METAL_KHR"
            ),
            "METAL"
        );
    }
}
