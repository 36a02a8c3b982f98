//! Emits `src/generated/features.rs`: which core feature each struct that can
//! enable device features sets, so the device knows every feature it was created
//! with, however the program asked for it (a core version's features struct, or
//! the struct of the extension the feature came from).

use crate::model::Model;
use crate::names::{field_ident, type_name};
use crate::validity::explicit::{core_feature, CORE_FEATURES};
use proc_macro2::{Ident, Span, TokenStream};
use quote::quote;

pub(super) fn emit(model: &Model) -> TokenStream {
    let mut arms = Vec::new();
    for t in model.types.values() {
        let extends = t
            .struct_extends
            .iter()
            .any(|e| e == "VkPhysicalDeviceFeatures2" || e == "VkDeviceCreateInfo");
        if !extends || !model.is_emitted(&t.name) {
            continue;
        }
        let ty = Ident::new(&type_name(model.spelling(&t.name)), Span::call_site());
        let sets: Vec<TokenStream> = if t.name == "VkPhysicalDeviceFeatures2" {
            vec![quote!(f.v10 = s.features;)]
        } else {
            let own = CORE_FEATURES
                .iter()
                .find(|(c, _)| *c == t.name)
                .map(|(_, f)| *f);
            t.members
                .iter()
                .filter(|m| m.type_name == "VkBool32" && m.pointers == 0)
                .filter_map(|m| {
                    let core = own.or_else(|| core_feature(model, &m.name))?;
                    let core = Ident::new(core, Span::call_site());
                    let name = field_ident(&m.name);
                    Some(quote!(f.#core.#name |= s.#name;))
                })
                .collect()
        };
        if sets.is_empty() {
            continue;
        }
        arms.push(quote! {
            if s_type == <vk::#ty<'_> as vk::TaggedStructure>::STRUCTURE_TYPE {
                __safety!("the sType says which struct this is.");
                let s = unsafe { &*node.cast::<vk::#ty<'_>>() };
                #(#sets)*
            }
        });
    }
    quote! {
        //! Which core feature each struct of a device create info's chain enables.
        use crate::vk;
        use crate::state::Features;

        /// Adds the features one struct of a `VkDeviceCreateInfo` chain enables to
        /// `f`: a core version's features struct, `VkPhysicalDeviceFeatures2`, or a
        /// struct whose features a core version took over. Other structs add nothing.
        ///
        /// # Safety
        ///
        /// `node` points to a live Vulkan struct of the type its sType names.
        pub(crate) unsafe fn add_chained(node: *const vk::BaseInStructure<'_>, f: &mut Features) {
            __safety!("the caller promises a live struct that starts with sType.");
            let s_type = unsafe { (*node).s_type };
            #(#arms)else*
        }
    }
}
