//! Emits `src/structs.rs`: a safe counterpart of every struct of the emitted API that
//! carries handles, pointers or an `sType`. Each is a `#[repr(transparent)]` wrapper of
//! ash's struct whose setters take wrappers, references and slices, so lowering to ash
//! at the call is free and a slice of safe structs is a valid C array. `pNext` chains
//! are typed: `push_next` accepts only structs that `structextends` the head.

use super::doc_rules;
use crate::model::Field;
use crate::model::Kind;
use crate::names::{cfg_of, field_ident, type_ident};
use crate::plan::shape::{count_groups, struct_members, CountGroup, Member};
use crate::plan::types::{array_size, spelled, TypeFacts};
use crate::plan::{Context, Plans};
use proc_macro2::TokenStream;
use quote::quote;

/// The structs that get safe counterparts, in name order.
pub fn safe_structs(cx: &Context) -> Vec<String> {
    cx.model
        .types
        .iter()
        .filter(|(name, t)| {
            t.alias.is_none()
                && t.category == Some(Kind::Struct)
                && cx.model.emitted.contains(*name)
                && cx.facts.is_safe(name)
        })
        .map(|(name, _)| name.clone())
        .collect()
}

/// `structs/`: one module per core version and extension, re-exported together.
pub(super) fn emit(plans: &Plans) -> Vec<(String, TokenStream)> {
    let cx = plans.cx;
    let mut modules: std::collections::BTreeMap<String, (Vec<String>, Vec<TokenStream>)> =
        Default::default();
    for name in safe_structs(cx) {
        let (names, items) = modules
            .entry(super::module_of(cx.model, &name))
            .or_default();
        items.push(emit_struct(plans, &name));
        names.push(name);
    }
    let head = quote! {
        //! Safe counterparts of the registry's structs that carry handles, pointers or
        //! an `sType`, one module per core version and extension. Plain structs
        //! (`vk::Extent2D`, ...) are used as ash has them.
        use crate::{chain::Extends, handles::*, support::safe_struct, CStrPtr, Handle, Handles};
        use crate::vk;
        use core::marker::PhantomData;
    };
    super::split(cx.model, "structs", "The safe structs", head, modules, true)
}

fn emit_struct(plans: &Plans, name: &str) -> TokenStream {
    let cx = plans.cx;
    let model = cx.model;
    let facts: &TypeFacts = &cx.facts;
    let t = &model.types[name];
    let id = type_ident(model.spelling(name));
    let raw_ty = if facts.has_lifetime(name) {
        quote!(vk::#id<'a>)
    } else {
        quote!(vk::#id)
    };
    let cfg = cfg_of(model, model.condition(name));
    let members = struct_members(model, facts, name);
    let groups = count_groups(&members);
    let array_tys: Vec<ArrayParam> = members
        .iter()
        .filter_map(|(m, shape)| array_param(cx, m, shape))
        .collect();
    let mut ctor_args = Vec::new();
    let mut ctor_sets = Vec::new();
    // Items beside the struct: the enums of its selected unions.
    let mut beside = Vec::new();
    let mut setters = Vec::new();
    // A struct Vulkan only writes gets no setters, as a `returnedonly` one.
    let returned_only = t.returned_only || facts.is_written(name);
    for (m, shape) in &members {
        // A setter of a member whose type a narrower condition gates
        // (`accelerationStructureNV` of a struct that VK_KHR_acceleration_structure
        // alone also brings) exists only where its type does.
        let before = setters.len();
        let gate = member_gate(cx, name, m);
        let gate_from = |setters: &mut Vec<TokenStream>| {
            if let Some(gate) = &gate {
                for s in &mut setters[before..] {
                    *s = quote!(#gate #s);
                }
            }
        };
        let f = field_ident(&m.name);
        let setter = field_ident(&crate::names::param(&m.name));
        let doc = format!("Sets `{}`.", m.name);
        let ty = spelled(model, facts, &m.type_name);
        if returned_only && !matches!(shape, Member::PNext) {
            continue;
        }
        if let Some(array) = array_param(cx, m, shape) {
            setters.extend(array_setter(name, m, &array, &groups, &array_tys));
            gate_from(&mut setters);
            continue;
        }
        match shape {
            Member::SType | Member::Count | Member::Unsupported(_) => {}
            Member::HandleSlice { .. }
            | Member::Slice { .. }
            | Member::Bytes { .. }
            | Member::CStrSlice { .. }
            | Member::CodecStd { count: Some(_) } => unreachable!("arrays are set above"),
            Member::PNext => {}
            Member::Value if groups.iter().any(|g| g.count == m.name) => {
                setters.push(count_setter(m, ty, &groups));
            }
            // Rust's `bool` where Vulkan has `VkBool32`, as ash's builders take.
            Member::Value if m.type_name == "VkBool32" => {
                setters.push(quote! {
                    #[doc = #doc]
                    #[inline]
                    pub fn #setter(mut self, value: bool) -> Self {
                        self.raw.#f = vk::Bool32::from(value);
                        self
                    }
                });
            }
            Member::Value => {
                setters.push(quote! {
                    #[doc = #doc]
                    #[inline]
                    pub fn #setter(mut self, value: #ty) -> Self {
                        self.raw.#f = value;
                        self
                    }
                });
            }
            Member::Array(size) => {
                let n = array_size(size);
                setters.push(quote! {
                    #[doc = #doc]
                    #[inline]
                    pub fn #setter(mut self, value: [#ty; #n]) -> Self {
                        self.raw.#f = value;
                        self
                    }
                });
            }
            Member::Handle { optional } => {
                let w = type_ident(&m.type_name);
                if *optional {
                    setters.push(quote! {
                        #[doc = #doc]
                        #[inline]
                        pub fn #setter(mut self, value: Option<&'a #w>) -> Self {
                            self.raw.#f = value.map_or(vk::#w::null(), |h| h.raw());
                            self
                        }
                    });
                } else {
                    ctor_args.push(quote!(#setter: &'a #w));
                    ctor_sets.push(quote!(#f: #setter.raw()));
                    setters.push(quote! {
                        #[doc = #doc]
                        #[inline]
                        pub fn #setter(mut self, value: &'a #w) -> Self {
                            self.raw.#f = value.raw();
                            self
                        }
                    });
                }
            }
            Member::Nested => {
                let target = safe_or_ash(cx, &m.type_name);
                ctor_args.push(quote!(#setter: #target));
                ctor_sets.push(quote!(#f: #setter.raw));
                setters.push(quote! {
                    #[doc = #doc]
                    #[inline]
                    pub fn #setter(mut self, value: #target) -> Self {
                        self.raw.#f = value.raw;
                        self
                    }
                });
            }
            Member::StructRef { optional } => {
                let target = safe_or_ash(cx, &m.type_name);
                let cast = quote!(value as *const #target as *const _);
                if *optional {
                    setters.push(quote! {
                        #[doc = #doc]
                        #[inline]
                        pub fn #setter(mut self, value: Option<&'a #target>) -> Self {
                            self.raw.#f = value.map_or(core::ptr::null(), |value| #cast);
                            self
                        }
                    });
                } else {
                    ctor_args.push(quote!(#setter: &'a #target));
                    ctor_sets.push(quote!(#f: { let value = #setter; #cast }));
                    setters.push(quote! {
                        #[doc = #doc]
                        #[inline]
                        pub fn #setter(mut self, value: &'a #target) -> Self {
                            self.raw.#f = #cast;
                            self
                        }
                    });
                }
            }
            Member::Code { count } => {
                let c = field_ident(count);
                setters.push(quote! {
                    #[doc = "Sets the SPIR-V words (and the size in bytes)."]
                    #[inline]
                    pub fn #setter(mut self, value: &'a [u32]) -> Self {
                        self.raw.#c = core::mem::size_of_val(value);
                        self.raw.#f = value.as_ptr();
                        self
                    }
                });
            }
            Member::CStr { optional } => {
                if *optional {
                    setters.push(quote! {
                        #[doc = #doc]
                        #[inline]
                        pub fn #setter(mut self, value: Option<&'a core::ffi::CStr>) -> Self {
                            self.raw.#f = value.map_or(core::ptr::null(), |s| s.as_ptr());
                            self
                        }
                    });
                } else {
                    ctor_args.push(quote!(#setter: &'a core::ffi::CStr));
                    ctor_sets.push(quote!(#f: #setter.as_ptr()));
                    setters.push(quote! {
                        #[doc = #doc]
                        #[inline]
                        pub fn #setter(mut self, value: &'a core::ffi::CStr) -> Self {
                            self.raw.#f = value.as_ptr();
                            self
                        }
                    });
                }
            }
            // Set by the variant of the union it selects.
            Member::Selector => {}
            Member::Selected { variants, selector } => {
                let Some(sel) = members.iter().map(|(f, _)| f).find(|f| &f.name == selector) else {
                    continue;
                };
                let (item, ty) = super::selected::render(cx, m, sel, variants, &cfg);
                beside.push(item);
                let sel_f = field_ident(selector);
                ctor_args.push(quote!(#setter: #ty));
                ctor_sets.push(quote!(#sel_f: #setter.selector()));
                ctor_sets.push(quote!(#f: #setter.raw()));
                let doc = format!(
                    "Sets `{}` and the `{selector}` that selects its member.",
                    m.name
                );
                setters.push(quote! {
                    #[doc = #doc]
                    #[inline]
                    pub fn #setter(mut self, value: #ty) -> Self {
                        self.raw.#sel_f = value.selector();
                        self.raw.#f = value.raw();
                        self
                    }
                });
            }
            Member::UserData => {
                setters.push(quote! {
                    #[doc = "Sets the pointer handed back to the callback; Vulkan never reads through it."]
                    #[inline]
                    pub fn #setter(mut self, value: *mut core::ffi::c_void) -> Self {
                        self.raw.#f = value;
                        self
                    }
                });
            }
            Member::PlatformValue => {
                let doc = format!(
                    "Sets `{}`.\n\n# Safety\n\n`value` must name a live window-system object that outlives every Vulkan object created from this struct.",
                    m.name
                );
                setters.push(quote! {
                    #[doc = #doc]
                    #[inline]
                    pub unsafe fn #setter(mut self, value: #ty) -> Self {
                        self.raw.#f = value;
                        self
                    }
                });
            }
            Member::OpaqueBytes => {
                let doc = format!(
                    "Sets `{}`.\n\n# Safety\n\n`value` must hold what the specification of `{}` requires of it, and at least as many bytes as Vulkan reads from it.",
                    m.name, name
                );
                setters.push(quote! {
                    #[doc = #doc]
                    #[inline]
                    pub unsafe fn #setter(mut self, value: &'a [u8]) -> Self {
                        self.raw.#f = value.as_ptr().cast();
                        self
                    }
                });
            }
            Member::FixedRef { size } => {
                let factors = crate::plan::shape::constant_size(size).unwrap_or_default();
                let len = factors
                    .iter()
                    .map(|f| crate::plan::types::array_size(f))
                    .reduce(|a, b| quote!(#a * #b));
                setters.push(quote! {
                    #[doc = #doc]
                    #[inline]
                    pub fn #setter(mut self, value: &'a [#ty; #len]) -> Self {
                        self.raw.#f = value.as_ptr().cast();
                        self
                    }
                });
            }
            Member::CodecStd { count: None } => {
                let (unsafe_kw, codec_safety) = codec_safety(true);
                let doc = format!("Sets `{}`.{codec_safety}", m.name);
                setters.push(quote! {
                    #[doc = #doc]
                    #[inline]
                    pub #unsafe_kw fn #setter(mut self, value: &'a #ty) -> Self {
                        // `cast_mut` where the registry lacks the `const` of a
                        // pointer Vulkan only reads (H.265's picture info).
                        self.raw.#f = (value as *const #ty).cast_mut().cast();
                        self
                    }
                });
            }
            Member::StructMut { optional } => {
                let target = safe_or_ash(cx, &m.type_name);
                let lower = quote!((value as *mut #target).cast());
                if *optional {
                    setters.push(quote! {
                        #[doc = #doc]
                        #[inline]
                        pub fn #setter(mut self, value: Option<&'a mut #target>) -> Self {
                            self.raw.#f = value.map_or(core::ptr::null_mut(), |value| #lower);
                            self
                        }
                    });
                } else {
                    ctor_args.push(quote!(#setter: &'a mut #target));
                    ctor_sets.push(quote!(#f: { let value = #setter; #lower }));
                    setters.push(quote! {
                        #[doc = #doc]
                        #[inline]
                        pub fn #setter(mut self, value: &'a mut #target) -> Self {
                            self.raw.#f = #lower;
                            self
                        }
                    });
                }
            }
            Member::Platform => {
                let mutability = if m.is_const {
                    quote!(const)
                } else {
                    quote!(mut)
                };
                let doc = format!(
                    "Sets `{}`.\n\n# Safety\n\n`value` must be a valid window-system object that outlives every Vulkan object created from this struct.",
                    m.name
                );
                setters.push(quote! {
                    #[doc = #doc]
                    #[inline]
                    pub unsafe fn #setter(mut self, value: *#mutability #ty) -> Self {
                        self.raw.#f = value;
                        self
                    }
                });
            }
        }
        gate_from(&mut setters);
    }
    let has_next = members.iter().any(|(_, s)| matches!(s, Member::PNext));
    let rules = doc_rules(plans, name);
    let example = super::example_doc(
        cx,
        &crate::names::type_name(model.spelling(name)),
        None,
        "Made",
    );
    let written = match facts.is_written(name) {
        true => {
            " Vulkan writes it: pass one made with `default()` where a command or chain \
                 asks for it, and read the members it filled through `Deref`."
        }
        false => "",
    };
    let doc = format!(
        "Safe counterpart of [`vk::{}`].{written}{example}{rules}",
        crate::names::type_name(model.spelling(name))
    );
    let mut parts = Vec::new();
    let new_fn = if ctor_args.is_empty() {
        parts.push(quote!(zeroed));
        quote!()
    } else {
        // What `new` takes is what has no zero form (a handle, a nested struct or
        // pointer, a name); a number the struct needs, such as a queue family
        // index, starts at 0 like the rest, so the doc does not promise more.
        let s_type = model.types[name].members.iter().any(|m| m.name == "sType");
        let new_doc = format!(
            " A struct with the members that have no zero form set from the arguments \
             (handles, nested structs and pointers, names) and every other member zero \
             or empty{}; set the rest with the setters.",
            if s_type { ", its `sType` set" } else { "" }
        );
        quote! {
            #[doc = #new_doc]
            #[inline]
            pub fn new(#(#ctor_args),*) -> Self {
                Self {
                    raw: vk::#id { #(#ctor_sets,)* ..Default::default() },
                    _marker: PhantomData,
                }
            }
        }
    };
    if has_next {
        parts.push(quote!(chained));
    }
    let extends: Vec<TokenStream> = model.types[name]
        .struct_extends
        .iter()
        .filter(|head| cx.model.emitted.contains(*head) && cx.facts.is_safe(head))
        .filter(|head| !crate::plan::special::unchained(name, head))
        .map(|head| {
            let h = type_ident(model.spelling(head));
            let head_cfg = cfg_of(model, model.condition(head));
            // SAFETY: the registry lists this struct in the head's `structextends`.
            // One lifetime for both: a pushed struct holds the head's chain, so it
            // must not outlive what the head borrows. (One line per pair in the
            // output; the trait's docs say what an implementation promises.)
            quote! {
                #cfg
                #head_cfg
                unsafe impl<'a> Extends<#h<'a>> for #id<'a> {}
            }
        })
        .collect();
    let borrows = facts.has_lifetime(name).then(|| quote!(, 'a));
    let setters_impl = (!setters.is_empty() || !new_fn.is_empty()).then(|| {
        quote! {
            #cfg
            impl<'a> #id<'a> {
                #new_fn
                #(#setters)*
            }
        }
    });
    quote! {
        #[doc = #doc]
        #cfg
        #[repr(transparent)]
        #[derive(Clone, Copy)]
        pub struct #id<'a> {
            pub(super) raw: #raw_ty,
            _marker: PhantomData<&'a ()>,
        }
        safe_struct!(#cfg #id #borrows; #(#parts)*);
        #setters_impl
        #(#extends)*
        #(#beside)*
    }
}

/// The `#[cfg]` of a member's setter where its type's condition is narrower than its
/// struct's ([`crate::plan::features::member_condition`]).
fn member_gate(cx: &Context, struct_name: &str, m: &Field) -> Option<TokenStream> {
    crate::plan::features::member_condition(cx.model, &cx.facts, struct_name, &m.type_name)
        .and_then(|c| cfg_of(cx.model, &c))
}

/// The generated safe type of a struct, or ash's when it has none.
pub fn safe_or_ash(cx: &Context, name: &str) -> TokenStream {
    let id = type_ident(cx.model.spelling(name));
    if cx.facts.is_safe(name) {
        quote!(#id<'a>)
    } else if cx.facts.has_lifetime(name) {
        quote!(vk::#id<'a>)
    } else {
        quote!(vk::#id)
    }
}

/// How an array member is taken and lowered: the setter's parameter type, and the
/// pointer and length of `value`.
struct ArrayParam {
    member: String,
    count: String,
    ty: TokenStream,
    /// Taken as `impl Handles`, whose raw handles the setter stores.
    handles: bool,
    /// A video codec's structs: the setter is `unsafe` (`Member::CodecStd`).
    codec: bool,
}

impl ArrayParam {
    /// Rebinds the argument `name` as a slice of what the member points to.
    fn lower(&self, name: &proc_macro2::Ident) -> TokenStream {
        match self.handles {
            true => quote!(let #name = Handles::raws(#name);),
            false => quote!(),
        }
    }
}

fn array_param(cx: &Context, m: &Field, shape: &Member) -> Option<ArrayParam> {
    let (count, ty) = match shape {
        Member::HandleSlice { count } => {
            let w = type_ident(&m.type_name);
            (count, quote!(impl Handles<'a, #w>))
        }
        Member::Slice { count, safe } => {
            let elem = if *safe {
                safe_or_ash(cx, &m.type_name)
            } else {
                spelled(cx.model, &cx.facts, &m.type_name)
            };
            (count, quote!(&'a [#elem]))
        }
        Member::Bytes { count } => (count, quote!(&'a [u8])),
        Member::CodecStd { count: Some(count) } => {
            let elem = spelled(cx.model, &cx.facts, &m.type_name);
            (count, quote!(&'a [#elem]))
        }
        Member::CStrSlice { count } => (count, quote!(&'a [CStrPtr<'a>])),
        _ => return None,
    };
    Some(ArrayParam {
        member: m.name.clone(),
        count: count.clone(),
        ty,
        handles: matches!(shape, Member::HandleSlice { .. }),
        codec: matches!(shape, Member::CodecStd { .. }),
    })
}

/// The `unsafe` of a setter of a video codec's structs, and its `# Safety` section.
fn codec_safety(codec: bool) -> (TokenStream, String) {
    match codec {
        true => (
            quote!(unsafe),
            "\n\n# Safety\n\nEvery pointer inside the codec's structs (a parameter set's \
             scaling lists or VUI, say) must be valid, as the video specification requires, \
             for as long as the struct is used."
                .to_owned(),
        ),
        false => (quote!(), String::new()),
    }
}

/// Statements that null the listed array members when the count is about to change
/// to `len`, so that no array is left shorter than the count.
fn clear_unless_len<'a>(
    others: impl Iterator<Item = &'a String>,
    count: &proc_macro2::Ident,
) -> TokenStream {
    let fields: Vec<_> = others.map(|o| field_ident(o)).collect();
    if fields.is_empty() {
        return quote!();
    }
    quote! {
        if self.raw.#count as usize != len {
            #(self.raw.#fields = core::ptr::null();)*
        }
    }
}

fn array_setter(
    struct_name: &str,
    m: &Field,
    array: &ArrayParam,
    groups: &[CountGroup],
    array_tys: &[ArrayParam],
) -> Option<TokenStream> {
    let f = field_ident(&m.name);
    let setter = field_ident(&crate::names::param(&m.name));
    let c = field_ident(&array.count);
    let ty = &array.ty;
    let lower = array.lower(&proc_macro2::Ident::new(
        "value",
        proc_macro2::Span::call_site(),
    ));
    let (unsafe_kw, codec_safety) = codec_safety(array.codec);
    let Some(g) = groups.iter().find(|g| g.holds(&m.name)) else {
        let doc = format!("Sets `{}`.{codec_safety}", m.name);
        return Some(quote! {
            #[doc = #doc]
            #[inline]
            pub #unsafe_kw fn #setter(mut self, value: #ty) -> Self {
                #lower
                self.raw.#c = value.len() as _;
                self.raw.#f = value.as_ptr().cast();
                self
            }
        });
    };
    if g.leads.len() > 1 {
        // The first lead sets them all; the others have no setter of their own.
        if g.leads[0] != m.name {
            return None;
        }
        return Some(lead_setter(struct_name, g, m, array_tys));
    }
    if g.followers.contains(&m.name) {
        let vuid = format!("VUID-{struct_name}-{}-parameter", m.name);
        let doc = format!(
            "Sets `{}`, which must have `{}` elements, as many as the {} set before.\n\n\
             # Errors\n\n[`Error::Validation`](crate::Error::Validation) (`{vuid}`) when \
             the length differs.",
            m.name,
            array.count,
            g.leads
                .iter()
                .map(|l| format!("`{l}`"))
                .collect::<Vec<_>>()
                .join(", ")
        );
        let what = format!(
            "`{}` has {{}} elements but `{}` is {{}}",
            m.name, array.count
        );
        let doc = format!("{doc}{codec_safety}");
        return Some(quote! {
            #[doc = #doc]
            #[inline]
            pub #unsafe_kw fn #setter(mut self, value: #ty) -> crate::Result<Self> {
                #lower
                if value.len() != self.raw.#c as usize {
                    return Err(crate::Error::Validation {
                        vuid: #vuid,
                        message: format!(#what, value.len(), self.raw.#c),
                    });
                }
                self.raw.#f = value.as_ptr().cast();
                Ok(self)
            }
        });
    }
    // A single lead, or an alternative: this setter decides the count.
    let clear = clear_unless_len(g.others(&m.name), &c);
    let others: Vec<String> = g.others(&m.name).map(|o| format!("`{o}`")).collect();
    let doc = if others.is_empty() {
        format!("Sets `{}` (and `{}`).", m.name, array.count)
    } else {
        format!(
            "Sets `{}` (and `{}`). {} share{} that count: {} cleared when its length differs.",
            m.name,
            array.count,
            others.join(", "),
            if others.len() == 1 { "s" } else { "" },
            if others.len() == 1 {
                "it is"
            } else {
                "each is"
            },
        )
    };
    let doc = format!("{doc}{codec_safety}");
    Some(quote! {
        #[doc = #doc]
        #[inline]
        pub #unsafe_kw fn #setter(mut self, value: #ty) -> Self {
            #lower
            let len = value.len();
            #clear
            self.raw.#c = len as _;
            self.raw.#f = value.as_ptr().cast();
            self
        }
    })
}

/// One setter for every required array of a count: lengths that disagree are
/// refused before the struct holds them.
fn lead_setter(
    struct_name: &str,
    g: &CountGroup,
    first: &Field,
    array_tys: &[ArrayParam],
) -> TokenStream {
    let leads: Vec<&ArrayParam> = g
        .leads
        .iter()
        .map(|l| {
            array_tys
                .iter()
                .find(|a| &a.member == l)
                .expect("every lead is an array")
        })
        .collect();
    let param_tys: Vec<&TokenStream> = leads.iter().map(|a| &a.ty).collect();
    let (unsafe_kw, codec_safety) = codec_safety(leads.iter().any(|a| a.codec));
    let setter = field_ident(&crate::names::param(&first.name));
    let c = field_ident(&g.count);
    let params: Vec<_> = g
        .leads
        .iter()
        .map(|l| field_ident(&crate::names::param(l)))
        .collect();
    let fields: Vec<_> = g.leads.iter().map(|l| field_ident(l)).collect();
    let first_param = &params[0];
    let lower = leads.iter().zip(&params).map(|(a, p)| a.lower(p));
    let checks = g.leads.iter().zip(&params).skip(1).map(|(l, p)| {
        let vuid = format!("VUID-{struct_name}-{l}-parameter");
        let what = format!("`{}` has {{}} elements but `{}` has {{}}", l, g.leads[0]);
        quote! {
            if #p.len() != len {
                return Err(crate::Error::Validation {
                    vuid: #vuid,
                    message: format!(#what, #p.len(), len),
                });
            }
        }
    });
    let clear = clear_unless_len(g.followers.iter().chain(&g.alternatives), &c);
    let names: Vec<String> = g.leads.iter().map(|l| format!("`{l}`")).collect();
    let doc = format!(
        "Sets {} (and `{}`): one element of each per entry.\n\n# Errors\n\n\
         [`Error::Validation`](crate::Error::Validation) when the slices' lengths differ.{codec_safety}",
        names.join(", "),
        g.count
    );
    quote! {
        #[doc = #doc]
        #[inline]
        pub #unsafe_kw fn #setter(mut self, #(#params: #param_tys),*) -> crate::Result<Self> {
            #(#lower)*
            let len = #first_param.len();
            #(#checks)*
            #clear
            self.raw.#c = len as _;
            #(self.raw.#fields = #params.as_ptr().cast();)*
            Ok(self)
        }
    }
}

/// The setter of a count that also means something alone: it clears the arrays that
/// share it whose length differs.
fn count_setter(m: &Field, ty: TokenStream, groups: &[CountGroup]) -> TokenStream {
    let g = groups
        .iter()
        .find(|g| g.count == m.name)
        .expect("a group of this count");
    let f = field_ident(&m.name);
    let setter = field_ident(&crate::names::param(&m.name));
    let arrays: Vec<_> = g.others("").map(|o| field_ident(o)).collect();
    let names: Vec<String> = g.others("").map(|o| format!("`{o}`")).collect();
    let doc = format!(
        "Sets `{}`. {} {} cleared when its length differs from `value`.",
        m.name,
        names.join(", "),
        if names.len() == 1 { "is" } else { "are each" },
    );
    quote! {
        #[doc = #doc]
        #[inline]
        pub fn #setter(mut self, value: #ty) -> Self {
            if self.raw.#f != value {
                #(self.raw.#arrays = core::ptr::null();)*
            }
            self.raw.#f = value;
            self
        }
    }
}
