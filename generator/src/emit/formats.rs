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

/// The arms of `block`: `(format, aspect) => (bytes, [w, h, d])`, color blocks of
/// consecutive formats with the same block as one range.
fn block_arms(model: &Model) -> Vec<TokenStream> {
    let number = |name: &str| model.enum_numbers.get(name).copied();
    let by_name = |name: &str| model.formats.iter().find(|f| f.name == name);
    // (format, aspect bit, bytes, extent)
    let mut entries: Vec<(i64, u32, u32, [u32; 3])> = Vec::new();
    for f in &model.formats {
        let Some(n) = number(&f.name) else {
            continue;
        };
        if f.color() && f.planes == 0 {
            entries.push((n, 0x1, u32::from(f.block_size), f.block_extent));
        }
        if let Some(b) = f.aspect_bytes("D") {
            entries.push((n, 0x2, b, [1, 1, 1]));
        }
        if let Some(b) = f.aspect_bytes("S") {
            entries.push((n, 0x4, b, [1, 1, 1]));
        }
        for (i, plane) in f.plane_formats.iter().enumerate().take(3) {
            if let Some(p) = by_name(plane) {
                entries.push((n, 0x10 << i, u32::from(p.block_size), p.block_extent));
            }
        }
    }
    entries.sort_unstable();
    entries.dedup_by_key(|e| (e.0, e.1));
    // Runs of consecutive formats with one aspect and the same block.
    let mut runs: Vec<(i64, i64, u32, u32, [u32; 3])> = Vec::new();
    let mut colors: Vec<&(i64, u32, u32, [u32; 3])> =
        entries.iter().filter(|e| e.1 == 0x1).collect();
    colors.sort_unstable();
    for e in colors {
        match runs.last_mut() {
            Some((_, end, _, b, x)) if *end + 1 == e.0 && *b == e.2 && *x == e.3 => *end = e.0,
            _ => runs.push((e.0, e.0, e.1, e.2, e.3)),
        }
    }
    runs.extend(
        entries
            .iter()
            .filter(|e| e.1 != 0x1)
            .map(|e| (e.0, e.0, e.1, e.2, e.3)),
    );
    runs.iter()
        .map(|(a, b, aspect, bytes, [w, h, d])| {
            let (la, lb) = (Literal::i64_unsuffixed(*a), Literal::i64_unsuffixed(*b));
            let aspect = Literal::u32_unsuffixed(*aspect);
            let bytes = Literal::u32_unsuffixed(*bytes);
            let (w, h, d) = (
                Literal::u32_unsuffixed(*w),
                Literal::u32_unsuffixed(*h),
                Literal::u32_unsuffixed(*d),
            );
            let formats = if a == b {
                quote!(#la)
            } else {
                quote!(#la..=#lb)
            };
            quote!((#formats, #aspect) => (#bytes, [#w, #h, #d]),)
        })
        .collect()
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
    let blocks = block_arms(model);
    quote! {
        //! The aspects of each format the registry describes, and the texel blocks
        //! copies between buffers and images lay out.
        use ash::vk;

        /// A texel block of one aspect of `format` as copies between buffers and
        /// images lay it out: its size in bytes and its width, height and depth in
        /// texels (a plane's are those of the plane's compatible format). `None` for
        /// a format or aspect the registry does not describe.
        pub(crate) fn block(format: vk::Format, aspect: vk::ImageAspectFlags) -> Option<(u32, [u32; 3])> {
            Some(match (format.as_raw(), aspect.as_raw()) {
                #(#blocks)*
                _ => return None,
            })
        }

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
