//! Which registry types get safe counterparts, and the `ash` spelling of every type.

use crate::model::Kind;
use crate::model::Model;
use crate::names::{ident, type_ident};
use proc_macro2::TokenStream;
use quote::quote;
use std::collections::{BTreeMap, BTreeSet};

/// What the generated crate knows about every struct and union of the emitted API.
#[derive(Debug, Clone, Default)]
pub struct TypeFacts {
    /// ash declares the type with a lifetime parameter (`vk::X<'a>`).
    pub lifetime: BTreeMap<String, bool>,
    /// The type gets a safe counterpart in the generated crate (it carries handles,
    /// pointers or an `sType`), else ash's type is used as it is.
    pub safe: BTreeMap<String, bool>,
    /// Structs that the emitted API only hands to Vulkan to write, which the
    /// registry does not mark `returnedonly` but the reference registry does.
    pub written: BTreeSet<String>,
}

impl TypeFacts {
    /// Compute the facts for every struct and union of the model.
    pub fn new(model: &Model) -> TypeFacts {
        let mut facts = TypeFacts::default();
        for (name, t) in &model.types {
            if matches!(t.category, Some(Kind::Struct | Kind::Union)) {
                facts.lifetime_of(model, name, 0);
                facts.safe_of(model, name, 0);
            }
        }
        facts.written = written_only(model);
        facts
    }

    /// Whether Vulkan only writes `name` in the emitted API (see `written_only`).
    pub fn is_written(&self, name: &str) -> bool {
        self.written.contains(name)
    }

    fn lifetime_of(&mut self, model: &Model, name: &str, depth: usize) -> bool {
        if let Some(v) = self.lifetime.get(name) {
            return *v;
        }
        let Some(t) = model.types.get(name) else {
            return false;
        };
        if let Some(alias) = &t.alias {
            let v = depth < 16 && self.lifetime_of(model, &alias.clone(), depth + 1);
            self.lifetime.insert(name.to_owned(), v);
            return v;
        }
        // ash gives a struct a lifetime for any pointer member, but a union only
        // through a member type that has one (`PerformanceValueDataINTEL`, with a
        // string pointer, has none).
        let is_union = t.category == Some(Kind::Union);
        let members = t.members.clone();
        let v = members.iter().any(|m| {
            (m.pointers > 0 && !is_union)
                || (depth < 16
                    && matches!(
                        model.category(&m.type_name),
                        Some(Kind::Struct | Kind::Union)
                    )
                    && self.lifetime_of(model, &m.type_name, depth + 1))
        });
        self.lifetime.insert(name.to_owned(), v);
        v
    }

    fn safe_of(&mut self, model: &Model, name: &str, depth: usize) -> bool {
        if let Some(v) = self.safe.get(name) {
            return *v;
        }
        let Some(t) = model.types.get(name) else {
            return false;
        };
        if t.category == Some(Kind::Union) {
            // Unions are used as ash has them; a union that holds pointers or handles
            // makes its users unsupported instead.
            self.safe.insert(name.to_owned(), false);
            return false;
        }
        let members = t.members.clone();
        let v = members.iter().any(|m| {
            m.pointers > 0
                || m.name == "sType"
                || model.category(&m.type_name) == Some(Kind::Handle)
                || (depth < 16
                    && model.category(&m.type_name) == Some(Kind::Struct)
                    && self.safe_of(model, &m.type_name, depth + 1))
        });
        self.safe.insert(name.to_owned(), v);
        v
    }

    /// Whether `name` has a safe counterpart.
    pub fn is_safe(&self, name: &str) -> bool {
        self.safe.get(name).copied().unwrap_or(false)
    }

    /// Whether ash's `name` takes a lifetime.
    pub fn has_lifetime(&self, name: &str) -> bool {
        self.lifetime.get(name).copied().unwrap_or(false)
    }

    /// Whether a union holds anything that would need a safe counterpart.
    pub fn union_is_plain(&self, model: &Model, name: &str) -> bool {
        model.types.get(name).is_some_and(|t| {
            t.members.iter().all(|m| {
                m.pointers == 0
                    && model.category(&m.type_name) != Some(Kind::Handle)
                    && !self.is_safe(&m.type_name)
                    && !self.has_lifetime(&m.type_name)
            })
        })
    }
}

/// The structs that this registry does not mark `returnedonly` and the reference
/// registry does (Khronos's correction: `VkCooperativeMatrixPropertiesNV`,
/// `VkQueueFamilyGlobalPriorityPropertiesKHR`), where the emitted API agrees that
/// Vulkan only writes them: every emitted command takes them through a
/// non-`const` pointer, every emitted struct holds them the same way or is itself
/// written, every struct whose chain they extend is written or `returnedonly`, and
/// their members are plain values (no handle or pointer Vulkan would read).
fn written_only(model: &Model) -> BTreeSet<String> {
    let base = |name: &str| -> String {
        model
            .types
            .get(name)
            .and_then(|t| t.alias.clone())
            .unwrap_or_else(|| name.to_owned())
    };
    let output = |f: &crate::model::Field| {
        f.pointers == 1 && !f.const_pointees.first().copied().unwrap_or(f.is_const)
    };
    let structs: Vec<&crate::model::TypeDef> = model
        .types
        .values()
        .filter(|t| {
            t.alias.is_none() && t.category == Some(Kind::Struct) && model.emitted.contains(&t.name)
        })
        .collect();
    // Each struct's uses: (written through the use, the struct that holds it).
    let mut uses: BTreeMap<String, Vec<(bool, Option<String>)>> = BTreeMap::new();
    for c in model
        .commands
        .values()
        .filter(|c| model.emitted.contains(&c.name))
    {
        for p in &c.params {
            uses.entry(base(&p.type_name))
                .or_default()
                .push((output(p), None));
        }
    }
    for t in &structs {
        // A chain's `pNext` is not a use of the struct type it is declared as
        // (`VkBaseOutStructure`'s own).
        for m in t.members.iter().filter(|m| m.name != "pNext") {
            let holder = (m.pointers == 0).then(|| t.name.clone());
            uses.entry(base(&m.type_name))
                .or_default()
                .push((output(m) || m.pointers == 0, holder));
        }
        for e in &t.struct_extends {
            uses.entry(t.name.clone())
                .or_default()
                .push((true, Some(base(e))));
        }
    }
    let plain = |t: &crate::model::TypeDef| {
        t.members.iter().all(|m| {
            m.name == "pNext"
                || m.name == "sType"
                || (m.pointers == 0 && model.category(&m.type_name) != Some(Kind::Handle))
        })
    };
    let mut written: BTreeSet<String> = structs
        .iter()
        .filter(|t| {
            model.returned_only_in_reference.contains(&t.name)
                && plain(t)
                && uses.contains_key(&t.name)
        })
        .map(|t| t.name.clone())
        .collect();
    // Drop every struct with a use that reads it, until none is left to drop.
    loop {
        let returned = |n: &str| model.types.get(n).is_some_and(|t| t.returned_only);
        let read: Vec<String> = written
            .iter()
            .filter(|n| {
                uses[n.as_str()].iter().any(|(w, holder)| {
                    !w || holder
                        .as_deref()
                        .is_some_and(|h| !written.contains(h) && !returned(h))
                })
            })
            .cloned()
            .collect();
        if read.is_empty() {
            return written;
        }
        for n in read {
            written.remove(&n);
        }
    }
}

/// [`ash_type`], for a renderer: the plan has already refused every item whose types
/// ash cannot spell, so a `None` here is a generator bug, and it becomes a compile error
/// in the generated crate that names the type rather than a silent `()`.
pub fn spelled(model: &Model, facts: &TypeFacts, name: &str) -> TokenStream {
    ash_type(model, facts, name).unwrap_or_else(|| {
        let msg = format!("tuff-gen: no ash spelling for the registry type `{name}`");
        quote!(compile_error!(#msg))
    })
}

/// ash's spelling of a parameter as written, pointers included, outermost first:
/// `*const *const vk::AccelerationStructureBuildRangeInfoKHR`, `*mut vk::Display`,
/// `vk::HANDLE`.
pub fn raw_type(model: &Model, facts: &TypeFacts, p: &crate::model::Field) -> TokenStream {
    let ty = ash_type(model, facts, &p.type_name).unwrap_or(quote!(::core::ffi::c_void));
    with_pointers(ty, p)
}

/// `ty` behind the pointers `p` is declared with, outermost first.
pub fn with_pointers(mut ty: TokenStream, p: &crate::model::Field) -> TokenStream {
    for level in (0..p.pointers).rev() {
        ty = match p.const_pointees.get(level).copied().unwrap_or(p.is_const) {
            true => quote!(*const #ty),
            false => quote!(*mut #ty),
        };
    }
    ty
}

/// ash's spelling of a base type, without pointers: `u32`, `vk::Format`,
/// `vk::BufferCreateInfo<'a>`. `None` for types ash lacks a name for here.
pub fn ash_type(model: &Model, facts: &TypeFacts, name: &str) -> Option<TokenStream> {
    let c = match name {
        "void" => quote!(::core::ffi::c_void),
        "char" => quote!(::core::ffi::c_char),
        "float" => quote!(f32),
        "double" => quote!(f64),
        "uint8_t" => quote!(u8),
        "uint16_t" => quote!(u16),
        "uint32_t" => quote!(u32),
        "uint64_t" => quote!(u64),
        "int8_t" => quote!(i8),
        "int16_t" => quote!(i16),
        "int32_t" => quote!(i32),
        "int64_t" => quote!(i64),
        "size_t" => quote!(usize),
        "int" => quote!(::core::ffi::c_int),
        _ => {
            let t = model.types.get(name)?;
            return match t.category {
                Some(Kind::Struct | Kind::Union) => {
                    let id = type_ident(model.spelling(name));
                    Some(if facts.has_lifetime(name) {
                        quote!(vk::#id<'a>)
                    } else {
                        quote!(vk::#id)
                    })
                }
                Some(Kind::Enum) if name.contains("FlagBits") => {
                    // ash has one type for a bitmask and its bits.
                    let id = ident(
                        &crate::names::type_name(model.spelling(name)).replace("FlagBits", "Flags"),
                    );
                    Some(quote!(vk::#id))
                }
                Some(Kind::Handle | Kind::Enum | Kind::Bitmask | Kind::Basetype) => {
                    let id = type_ident(model.spelling(name));
                    Some(quote!(vk::#id))
                }
                Some(Kind::Funcpointer) => {
                    let id = ident(name);
                    Some(quote!(vk::#id))
                }
                // The video codecs' own types (video.xml), in ash's `native` module.
                None if is_codec_std(model, name) => {
                    let id = ident(name);
                    Some(quote!(vk::native::#id))
                }
                None if t.name.chars().next().is_some_and(char::is_alphabetic) => {
                    // Platform types (Display, HWND, ...) ash re-exports under vk.
                    let id = ident(name);
                    Some(quote!(vk::#id))
                }
                _ => None,
            };
        }
    };
    Some(c)
}

/// A video codec's own type (video.xml's, which vk.xml names with the codec
/// header it `requires`), which ash has in `vk::native`.
pub fn is_codec_std(model: &Model, name: &str) -> bool {
    model
        .types
        .get(name)
        .and_then(|t| t.bit_values.as_deref())
        .is_some_and(|header| header.starts_with("vk_video/"))
}

/// A constant of a fixed array size as ash names it (`VK_UUID_SIZE` ->
/// `vk::UUID_SIZE`), or the number.
pub fn array_size(size: &str) -> TokenStream {
    if let Ok(n) = size.parse::<usize>() {
        quote!(#n)
    } else {
        let id = ident(size.strip_prefix("VK_").unwrap_or(size));
        quote!(vk::#id)
    }
}
