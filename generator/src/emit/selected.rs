//! A union that another member selects (`VkDescriptorGetInfoEXT::data`, chosen by
//! `type`), rendered as a safe enum with one variant per selector value: the variant
//! is the only way to set the union, and it sets the selector with it, so no struct
//! names one member and holds another.

use crate::model::Field;
use crate::names::{enum_const, field_ident, type_ident, variant_name};
use crate::plan::shape::{Variant, VariantKind};
use crate::plan::types::spelled;
use crate::plan::Context;
use proc_macro2::TokenStream;
use quote::quote;

/// The enum of a selected union, and its type as a member's setter takes it.
pub(super) fn render(
    cx: &Context,
    member: &Field,
    selector: &Field,
    variants: &[Variant],
    cfg: &Option<TokenStream>,
) -> (TokenStream, TokenStream) {
    let model = cx.model;
    let union = model.spelling(&member.type_name);
    let id = type_ident(union);
    let sel_ty = type_ident(model.spelling(&selector.type_name));
    let mut arms = Vec::new();
    let mut selects = Vec::new();
    let mut raws = Vec::new();
    let mut seen = Vec::new();
    for v in variants {
        // An alias selects what the value it aliases does: one variant for both.
        let number = model.enum_numbers.get(&v.selection);
        if number.is_some() && seen.contains(&number) {
            continue;
        }
        seen.push(number);
        let konst = enum_const(&selector.type_name, &v.selection);
        let name = crate::names::ident(&variant_name(&konst));
        let konst = crate::names::ident(&konst);
        let field = field_ident(&v.member.name);
        let w = type_ident(model.spelling(&v.member.type_name));
        let (payload, lowered) = match v.kind {
            VariantKind::Handle { optional: false } => (quote!(&'a #w), quote!(x.raw_ref())),
            VariantKind::Handle { optional: true } => (
                quote!(Option<&'a #w>),
                quote!(x.map_or(core::ptr::null(), |h| h.raw_ref())),
            ),
            VariantKind::StructRef { optional, safe } => {
                let ty = match safe {
                    true => quote!(#w<'a>),
                    false => spelled(model, &cx.facts, &v.member.type_name),
                };
                // A safe struct is `repr(transparent)` over ash's: a pointer to one
                // is a pointer to the other.
                match optional {
                    false => (quote!(&'a #ty), quote!((x as *const #ty).cast())),
                    true => (
                        quote!(Option<&'a #ty>),
                        quote!(x.map_or(core::ptr::null(), |s| (s as *const #ty).cast())),
                    ),
                }
            }
            VariantKind::Nested => (quote!(#w<'a>), quote!(*x)),
            VariantKind::Value => (spelled(model, &cx.facts, &v.member.type_name), quote!(x)),
        };
        let doc = format!(
            "`{}`, which `{} = {}` selects.",
            v.member.name, selector.name, v.selection
        );
        arms.push(quote!(#[doc = #doc] #name(#payload)));
        selects.push(quote!(Self::#name(_) => vk::#sel_ty::#konst));
        raws.push(quote!(Self::#name(x) => vk::#id { #field: #lowered }));
    }
    let doc = format!(
        "A member of [`vk::{}`] with the `{}` that selects it, as `{}` takes them: the \
         one way to set the union, so that it always holds what the selector names.",
        crate::names::type_name(union),
        selector.name,
        member.name,
    );
    // ash's unions of pointers to structs with lifetimes have one; a union this
    // crate defines (the delta) has one only where tuff's facts say so.
    let raw_lifetime = match cx.facts.has_lifetime(union) {
        true => quote!(<'a>),
        false => quote!(),
    };
    let item = quote! {
        #[doc = #doc]
        #cfg
        #[derive(Clone, Copy, Debug)]
        pub enum #id<'a> {
            #(#arms,)*
        }
        #cfg
        impl<'a> #id<'a> {
            /// The selector's value for this member.
            #[inline]
            pub fn selector(&self) -> vk::#sel_ty {
                match self {
                    #(#selects,)*
                }
            }
            /// The union, holding this member.
            #[inline]
            pub fn raw(self) -> vk::#id #raw_lifetime {
                match self {
                    #(#raws,)*
                }
            }
        }
    };
    (item, quote!(#id<'a>))
}
