//! Emits `src/generated/helpers.rs`: the `as_safe_as!` macro, which makes a
//! hand-written helper of the crate (`Frame::submit`, `Device::create_buffer_in`)
//! `unsafe` exactly when a generated method it stands on is. The helpers are written
//! once for every configuration, and a method that is safe with the pinned registry
//! may leave rules to its caller with more extensions or a newer registry.

use crate::plan::Plans;
use proc_macro2::TokenStream;
use quote::{format_ident, quote};

/// The generated methods hand-written helpers call, each helper promising no more
/// than they do: an arm's name (a command, or the helper calling several), the
/// commands it is as safe as, and the rules of theirs that the helper upholds itself
/// (saying how where it calls them). It is safe when no command leaves its caller a
/// rule outside those.
pub const HELPER_COMMANDS: &[(&str, &[&str], &[&str])] = &[
    ("vkCreateBuffer", &["vkCreateBuffer"], &[]),
    ("vkCreateImage", &["vkCreateImage"], &[]),
    ("vkCreateSwapchainKHR", &["vkCreateSwapchainKHR"], &[]),
    ("vkQueueSubmit", &["vkQueueSubmit"], &[]),
    ("vkCmdPipelineBarrier", &["vkCmdPipelineBarrier"], &[]),
    (
        "vkCreateComputePipelines",
        &["vkCreateComputePipelines"],
        &[],
    ),
    (
        "vkCreateGraphicsPipelines",
        &["vkCreateGraphicsPipelines"],
        &[],
    ),
    (
        "vkAllocateDescriptorSets",
        &["vkAllocateDescriptorSets"],
        &[],
    ),
    (
        "upload_image",
        &[
            "vkQueueSubmit",
            "vkCmdPipelineBarrier",
            "vkCmdCopyBufferToImage",
        ],
        // `Queue::upload_image` refuses depth aspects.
        &["VUID-vkCmdCopyBufferToImage-None-00214"],
    ),
];

/// One arm of the macro: the helper named `name`, safe or `unsafe`.
fn arm(name: &str, safe: bool) -> TokenStream {
    let ident = format_ident!("{name}");
    let qualifier = if safe { quote!() } else { quote!(unsafe) };
    quote! {
        (#ident, $(#[$m:meta])* $v:vis fn $($rest:tt)*) => {
            $(#[$m])* $v #qualifier fn $($rest)*
        };
    }
}

/// The macro, with one arm per helper: safe where the plan made every command's
/// method safe but for the rules the helper upholds (or did not emit it), `unsafe`
/// otherwise.
pub fn emit(plans: &Plans) -> TokenStream {
    let arms = HELPER_COMMANDS.iter().map(|(name, commands, upheld)| {
        let safe = commands.iter().all(|command| {
            plans
                .safety
                .get(*command)
                .is_none_or(|s| !s.raw && s.owned.iter().all(|o| upheld.contains(&o.vuid.as_str())))
        });
        arm(name, safe)
    });
    // The safe forms of the indirect commands: safe where their command's method
    // leaves its caller only rules the form settles (`plan/special/indirect.rs`).
    let forms = crate::plan::special::indirect::FORMS.iter().map(|form| {
        let safe = plans.safety.get(form.command).is_none_or(|s| {
            !s.raw
                && s.owned
                    .iter()
                    .all(|o| form.settles.iter().any(|(v, _)| *v == o.vuid))
        });
        arm(form.method, safe)
    });
    let arms = arms.chain(forms);
    quote! {
        //! Which hand-written helpers are `unsafe`: exactly those whose generated
        //! method is (see `generator/src/emit/helpers.rs`).

        /// Defines a helper `fn` as safe or `unsafe`, as the generated methods of the
        /// commands the name first stands for are (`generator/src/emit/helpers.rs`).
        macro_rules! as_safe_as {
            #(#arms)*
        }
        pub(crate) use as_safe_as;
    }
}
