//! Emits `src/generated/formats.rs`: the aspects each `VkFormat` has, from the
//! registry's `<formats>`, for the checks of rules about a format's kind (a color
//! format, a depth/stencil one) and about the aspects an image has.

use crate::model::Model;
use proc_macro2::{Literal, TokenStream};
use quote::quote;

/// The aspect bits of a format: COLOR (1), DEPTH (2), STENCIL (4), and PLANE_0 to
/// PLANE_2 (0x10, 0x20, 0x40) for a multi-planar one, which is a color format too.
fn aspect_bits(f: &crate::model::Format) -> u32 {
    let mut bits = 0;
    if f.color() {
        bits |= 0x1;
    }
    if f.depth() {
        bits |= 0x2;
    }
    if f.stencil() {
        bits |= 0x4;
    }
    for plane in 0..f.planes.min(3) {
        bits |= 0x10 << plane;
    }
    bits
}

pub(super) fn emit(model: &Model) -> TokenStream {
    // Formats by number, grouped into runs of consecutive numbers with the same
    // aspects.
    let mut by_number: Vec<(i64, u32)> = model
        .formats
        .iter()
        .filter_map(|f| Some((*model.enum_numbers.get(&f.name)?, aspect_bits(f))))
        .collect();
    by_number.sort_unstable();
    by_number.dedup_by_key(|(n, _)| *n);
    let mut runs: Vec<(i64, i64, u32)> = Vec::new();
    for (n, bits) in by_number {
        match runs.last_mut() {
            Some((_, end, b)) if *end + 1 == n && *b == bits => *end = n,
            _ => runs.push((n, n, bits)),
        }
    }
    let arms = runs.iter().map(|(a, b, bits)| {
        let (la, lb) = (Literal::i64_unsuffixed(*a), Literal::i64_unsuffixed(*b));
        let bits = Literal::u32_unsuffixed(*bits);
        if a == b {
            quote!(#la => #bits,)
        } else {
            quote!(#la..=#lb => #bits,)
        }
    });
    quote! {
        //! The aspects of each format the registry describes.
        use ash::vk;

        /// The aspects an image of `format` has (COLOR for a color or multi-planar
        /// format, with PLANE_0 to PLANE_2 for a multi-planar one; DEPTH and STENCIL
        /// for the components it has), or `None` for a format the registry does not
        /// describe (`UNDEFINED`, or one newer than it).
        pub(crate) fn aspects(format: vk::Format) -> Option<vk::ImageAspectFlags> {
            let bits: u32 = match format.as_raw() {
                #(#arms)*
                _ => return None,
            };
            Some(vk::ImageAspectFlags::from_raw(bits))
        }
    }
}
