//! Emits `src/generated/formats.rs`: the aspects each `VkFormat` has, from the
//! registry's `<formats>`, for the checks of rules about a format's kind (a color
//! format, a depth/stencil one) and about the aspects an image has, with its
//! compatibility class and chroma subsampling.

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

/// Match arms `number => value` over the registry's formats, consecutive numbers
/// with one value as a range; formats `value` gives `None` for are left out.
fn value_arms(
    model: &Model,
    value: impl Fn(&crate::model::Format) -> Option<u32>,
) -> Vec<TokenStream> {
    let mut by_number: Vec<(i64, u32)> = model
        .formats
        .iter()
        .filter_map(|f| Some((*model.enum_numbers.get(&f.name)?, value(f)?)))
        .collect();
    by_number.sort_unstable();
    by_number.dedup_by_key(|(n, _)| *n);
    let mut runs: Vec<(i64, i64, u32)> = Vec::new();
    for (n, v) in by_number {
        match runs.last_mut() {
            Some((_, end, b)) if *end + 1 == n && *b == v => *end = n,
            _ => runs.push((n, n, v)),
        }
    }
    runs.iter()
        .map(|(a, b, v)| {
            let (la, lb) = (Literal::i64_unsuffixed(*a), Literal::i64_unsuffixed(*b));
            let v = Literal::u32_unsuffixed(*v);
            if a == b {
                quote!(#la => #v,)
            } else {
                quote!(#la..=#lb => #v,)
            }
        })
        .collect()
}

pub(super) fn emit(model: &Model) -> TokenStream {
    let arms = value_arms(model, |f| Some(aspect_bits(f)));
    // Classes are numbered in name order, so the numbers are stable for a registry.
    let mut classes: Vec<&str> = model.formats.iter().map(|f| f.class.as_str()).collect();
    classes.sort_unstable();
    classes.dedup();
    let class_arms = value_arms(model, |f| {
        classes
            .binary_search(&f.class.as_str())
            .ok()
            .map(|i| i as u32)
    });
    let chroma_arms = value_arms(model, |f| f.chroma.as_deref()?.parse().ok());
    // The SPIR-V sampled type a color format's texels read as (the specification's
    // Interpretation of Numeric Format): 1 for OpTypeFloat, 2 for OpTypeInt.
    let numeric_arms = value_arms(model, |f| {
        if !f.color() {
            return None;
        }
        match f.numeric.first()?.as_str() {
            "UINT" | "SINT" => Some(2),
            _ => Some(1),
        }
    });
    // Whether a color format's integer texels are signed (1, SINT) or not (0, UINT).
    let sign_arms = value_arms(model, |f| {
        if !f.color() {
            return None;
        }
        match f.numeric.first()?.as_str() {
            "SINT" => Some(1),
            "UINT" => Some(0),
            _ => None,
        }
    });
    // How many components a color format's texels have (what a texel written to
    // it with OpImageWrite must have at least).
    let component_arms = value_arms(model, |f| {
        f.color()
            .then(|| u32::try_from(f.components.len()).ok())
            .flatten()
    });
    // Whether every component of a color format is UNORM (1).
    let unorm_arms = value_arms(model, |f| {
        (f.color() && !f.numeric.is_empty() && f.numeric.iter().all(|n| n == "UNORM")).then_some(1)
    });
    // A color format's R, G, B and A bit widths, a byte each (0: absent).
    let bits_arms = value_arms(model, |f| {
        if !f.color() {
            return None;
        }
        let mut packed = 0u32;
        for (c, b) in f.components.iter().zip(&f.bits) {
            let b: u32 = b.parse().ok()?;
            let shift = match c.as_str() {
                "R" => 0,
                "G" => 8,
                "B" => 16,
                "A" => 24,
                _ => return None,
            };
            packed |= b.min(255) << shift;
        }
        Some(packed)
    });
    let number = |name: &str| {
        model
            .enum_numbers
            .get(name)
            .and_then(|n| u32::try_from(*n).ok())
    };
    let plane_arms: Vec<Vec<TokenStream>> = (0..3)
        .map(|p| value_arms(model, |f| number(f.plane_formats.get(p)?)))
        .collect();
    let (plane0, plane1, plane2) = (&plane_arms[0], &plane_arms[1], &plane_arms[2]);
    let blocks = block_arms(model);
    quote! {
        //! The aspects of each format the registry describes, and the texel blocks
        //! copies between buffers and images lay out.
        use crate::vk;

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

        /// The number of `format`'s compatibility class (vk.xml's `class`): formats
        /// with the same number are compatible. `None` for a format the registry does
        /// not describe.
        pub(crate) fn class(format: vk::Format) -> Option<u32> {
            Some(match format.as_raw() {
                #(#class_arms)*
                _ => return None,
            })
        }

        /// The single-plane format compatible with plane `plane` (0 to 2) of a
        /// multi-planar format (vk.xml's `<plane compatible>`); `None` for a format
        /// without that plane.
        pub(crate) fn plane_format(format: vk::Format, plane: usize) -> Option<vk::Format> {
            let raw: u32 = match plane {
                0 => match format.as_raw() {
                    #(#plane0)*
                    _ => return None,
                },
                1 => match format.as_raw() {
                    #(#plane1)*
                    _ => return None,
                },
                2 => match format.as_raw() {
                    #(#plane2)*
                    _ => return None,
                },
                _ => return None,
            };
            Some(vk::Format::from_raw(raw as i32))
        }

        /// The SPIR-V sampled type the texels of a color format read as: 1 for a
        /// float type (`UNORM`, `SNORM`, `SFLOAT`, `SRGB`, ...), 2 for an integer type
        /// (`UINT`, `SINT`); `None` for a depth/stencil format or one the registry
        /// does not describe.
        pub(crate) fn color_numeric(format: vk::Format) -> Option<u32> {
            Some(match format.as_raw() {
                #(#numeric_arms)*
                _ => return None,
            })
        }

        /// For a color format of integer texels, whether they are signed (`SINT`:
        /// `true`) or not (`UINT`: `false`); `None` for any other format.
        pub(crate) fn integer_signed(format: vk::Format) -> Option<bool> {
            let signed: u32 = match format.as_raw() {
                #(#sign_arms)*
                _ => return None,
            };
            Some(signed == 1)
        }

        /// How many components a color format has (vk.xml's `<component>`s); `None`
        /// for a depth/stencil format or one the registry does not describe.
        pub(crate) fn color_components(format: vk::Format) -> Option<u32> {
            Some(match format.as_raw() {
                #(#component_arms)*
                _ => return None,
            })
        }

        /// Whether every component of a color format is `UNORM`.
        pub(crate) fn unorm(format: vk::Format) -> bool {
            let unorm: u32 = match format.as_raw() {
                #(#unorm_arms)*
                _ => 0,
            };
            unorm == 1
        }

        /// The bit widths of a color format's R, G, B and A components, 0 where it
        /// has none; `None` for a depth/stencil or compressed format, or one the
        /// registry does not describe.
        pub(crate) fn rgba_bits(format: vk::Format) -> Option<[u32; 4]> {
            let packed: u32 = match format.as_raw() {
                #(#bits_arms)*
                _ => return None,
            };
            Some([packed & 0xff, (packed >> 8) & 0xff, (packed >> 16) & 0xff, packed >> 24])
        }

        /// For a format that needs a sampler Y'CbCr conversion, its chroma
        /// subsampling (420, 422 or 444, vk.xml's `chroma`); `None` for any other.
        pub(crate) fn chroma(format: vk::Format) -> Option<u32> {
            Some(match format.as_raw() {
                #(#chroma_arms)*
                _ => return None,
            })
        }
    }
}
