//! Emits `src/generated/helpers.rs`: the `as_safe_as!` macro, which makes a
//! hand-written helper of the crate (`Frame::submit`, `Device::create_buffer_in`)
//! `unsafe` exactly when a generated method it stands on is. The helpers are written
//! once for every configuration, and a method that is safe with the pinned registry
//! may leave rules to its caller with more extensions or a newer registry.

use crate::plan::Plans;
use proc_macro2::TokenStream;
use quote::{format_ident, quote};

/// The commands whose generated methods hand-written helpers call, each helper
/// promising no more than the method does.
pub const HELPER_COMMANDS: &[&str] = &[
    "vkCreateBuffer",
    "vkCreateImage",
    "vkCreateSwapchainKHR",
    "vkQueueSubmit",
];

/// The macro, with one arm per helper command: safe where the plan made the
/// command's method safe (or did not emit it), `unsafe` otherwise.
pub fn emit(plans: &Plans) -> TokenStream {
    let arms = HELPER_COMMANDS.iter().map(|command| {
        let ident = format_ident!("{command}");
        let safe = plans.safety.get(*command).is_none_or(|s| s.safe());
        let qualifier = if safe { quote!() } else { quote!(unsafe) };
        quote! {
            (#ident, $(#[$m:meta])* $v:vis fn $($rest:tt)*) => {
                $(#[$m])* $v #qualifier fn $($rest)*
            };
        }
    });
    quote! {
        //! Which hand-written helpers are `unsafe`: exactly those whose generated
        //! method is (see `generator/src/emit/helpers.rs`).

        /// Defines a helper `fn` as safe or `unsafe`, as the generated method of the
        /// command named first is.
        macro_rules! as_safe_as {
            #(#arms)*
        }
        pub(crate) use as_safe_as;
    }
}
