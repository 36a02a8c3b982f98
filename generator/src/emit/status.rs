//! Renders the status enums of commands with several success codes
//! ([`crate::plan::status`]) into `status.rs`.

use crate::names::{ident, receiver_type, type_name};
use crate::plan::status::Status;
use proc_macro2::TokenStream;
use quote::quote;

/// The `status.rs` module.
pub fn emit(cx: &crate::plan::Context, statuses: &[Status]) -> TokenStream {
    let items = statuses.iter().map(|s| {
        let name = ident(&s.name);
        let users: Vec<String> = s
            .commands
            .iter()
            .map(|c| {
                let receiver = type_name(receiver_type(cx.model, c));
                format!("`{receiver}::{}`", cx.method(c))
            })
            .collect();
        let doc = format!(
            "What {} returned, of the success codes Vulkan gives it. Marked `#[must_use]`: \
             a caller that goes on regardless says so with `let _ =`.",
            users.join(", ")
        );
        let variants = s.variants.iter().map(|v| {
            let var = ident(&v.variant);
            let doc = format!("`{}`.", v.code);
            quote!(#[doc = #doc] #var,)
        });
        let from = s.variants.iter().map(|v| {
            let var = ident(&v.variant);
            let constant = ident(&v.constant);
            quote!(vk::Result::#constant => Some(Self::#var),)
        });
        let to = s.variants.iter().map(|v| {
            let var = ident(&v.variant);
            let constant = ident(&v.constant);
            quote!(Self::#var => vk::Result::#constant,)
        });
        quote! {
            #[doc = #doc]
            #[must_use]
            #[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
            pub enum #name {
                #(#variants)*
            }
            impl #name {
                /// The status of a success code, or `None` for a code that is not
                /// one of these.
                pub fn from_code(code: vk::Result) -> Option<Self> {
                    match code {
                        #(#from)*
                        _ => None,
                    }
                }
                /// The success code.
                pub fn code(self) -> vk::Result {
                    match self {
                        #(#to)*
                    }
                }
            }
            impl From<#name> for vk::Result {
                fn from(status: #name) -> vk::Result {
                    status.code()
                }
            }
        }
    });
    quote! {
        //! Typed results of the commands with more than one success code: one enum
        //! per set of codes, so that a timeout or a suboptimal swapchain is a
        //! variant to match on rather than a `vk::Result` beside `Ok`.
        use crate::vk;
        #(#items)*
    }
}
