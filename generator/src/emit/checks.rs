//! Renders `src/checks.rs` from the planned checks: the checks of enum and flags
//! values, of every struct, and of `pNext` chains.

use crate::model::Kind;
use crate::names::{field_ident, ident};
use crate::plan::checks::{
    enum_values, flag_bits, snake, struct_type_value, Check, CheckKind, Checker, HandleAt, Place,
    QueueOf, Seq, StructAt, ValueKind,
};
use crate::plan::types::spelled;
use crate::plan::Context;
use proc_macro2::{Literal, TokenStream};
use quote::quote;
use std::collections::{BTreeMap, BTreeSet};

/// `checks/`: the shared scope code, the value checks and the struct checks.
pub fn emit(checker: &Checker) -> Vec<(String, TokenStream)> {
    let model = checker.cx.model;
    let mut needs: BTreeSet<String> = BTreeSet::new();
    // One file of struct checks per generated module (core version or extension),
    // so no file grows past what a reader can navigate.
    let mut fns: std::collections::BTreeMap<String, (Vec<String>, Vec<TokenStream>)> =
        Default::default();
    for (name, checks) in &checker.struct_cache {
        needs.extend(checks.iter().flat_map(Check::needs));
        let f = ident(&format!("check_{}", snake(name)));
        let ty = crate::names::type_ident(checker.cx.model.spelling(name));
        let lt = if checker.cx.facts.has_lifetime(name) {
            quote!(<'_>)
        } else {
            quote!()
        };
        let cfg = crate::names::cfg_of(model, model.condition(name));
        let codes = checks.iter().map(render);
        // Named `_s` when no check reads the scope, so no binding is left unused.
        let scope_param = if checks.iter().any(Check::uses_scope) {
            quote!(s)
        } else {
            quote!(_s)
        };
        let doc = format!("The rules of `{name}` that are checked at run time.");
        let module = fns.entry(super::module_of(model, name)).or_default();
        module.0.push(name.clone());
        module.1.push(quote! {
            #[doc = #doc]
            #cfg
            pub fn #f(v: &vk::#ty #lt, #scope_param: &Scope<'_>) -> Result<()> {
                #(#codes)*
                Ok(())
            }
        });
    }
    for c in checker.command_cache.values().flatten() {
        needs.extend(c.needs());
    }
    let mut origins = Origins::new(model, &needs);
    origins.add(gated_structs(model).flat_map(|(_, names)| names.into_iter().flatten()));
    // The extensions the keys of recognised rules name, which their checks ask the
    // scope about.
    origins.add(
        checker
            .explicit
            .values()
            .flatten()
            .filter_map(|r| r.key.as_deref())
            .filter_map(|k| crate::model::expr::Expr::parse(k).ok())
            .flat_map(|e| e.names().into_iter().map(str::to_owned).collect::<Vec<_>>()),
    );
    let (mut enums, mut flags) = (Vec::new(), Vec::new());
    for t in &needs {
        match model.category(t) {
            Some(Kind::Enum) => enums.push(enum_fn(checker.cx, &origins, t)),
            _ => flags.push(flags_fn(checker.cx, &origins, t)),
        }
    }
    let chain = chain_fn(checker, &origins);
    let members = quote! {
        /// The array a struct member points to, `count` long; empty when the
        /// pointer is NULL, as an optional array that shares its count may be.
        ///
        /// # Safety
        ///
        /// A non-NULL `ptr` must point to `count` live elements, as the safe
        /// setters store them.
        unsafe fn members<'a, T>(ptr: *const T, count: u32) -> &'a [T] {
            if ptr.is_null() || count == 0 {
                return &[];
            }
            __safety!("the caller promises `count` live elements at `ptr`.");
            unsafe { core::slice::from_raw_parts(ptr, count as usize) }
        }
    };
    let exts = origins.emit();
    let head = quote! {
        //! The dynamic checks of implicit rules, compiled in with
        //! `runtime_implicit_validations`: the enabled versions and extensions here,
        //! the checks of enum values in `enums` and of flags values in `flags`, those
        //! of each struct in `structs`, one file per core version and extension.
        #![allow(dead_code, clippy::match_overlapping_arm, clippy::unnecessary_cast, clippy::match_same_arms)]
        use crate::support::refuse;
        use crate::validation::Scope;
        use crate::Result;
        use crate::vk;
        mod enums;
        mod flags;
        mod structs;
        pub(crate) use enums::*;
        pub(crate) use flags::*;
        pub(crate) use structs::*;
        #exts
        #members
        #chain
    };
    let mut files = vec![
        ("checks/mod.rs".to_owned(), head),
        (
            "checks/enums.rs".to_owned(),
            quote! {
                //! The checks of enum values: each value is one that the versions and
                //! extensions enabled where the call runs define.
                use super::*;
                #(#enums)*
            },
        ),
        (
            "checks/flags.rs".to_owned(),
            quote! {
                //! The checks of flags values: each bit set is one that the versions
                //! and extensions enabled where the call runs define.
                use super::*;
                #(#flags)*
            },
        ),
    ];
    files.extend(super::split(
        model,
        "checks/structs",
        "The checks of the rules of each struct",
        quote! {
            //! The checks of each struct's rules, over the ash struct, one module per
            //! core version and extension.
            use super::*;
        },
        fns,
        true,
    ));
    files
}

/// Each emitted struct that extends another and needs more than Vulkan 1.0, with the
/// alternatives of its condition (each a set of versions and extensions that must
/// all be enabled).
fn gated_structs(
    model: &crate::model::Model,
) -> impl Iterator<Item = (&String, Vec<BTreeSet<String>>)> + '_ {
    model
        .types
        .values()
        .filter(|t| {
            t.alias.is_none()
                && !t.struct_extends.is_empty()
                && model.emitted.contains(&t.name)
                && !model.condition(&t.name).is_core()
        })
        .map(|t| {
            let sets = model
                .condition(&t.name)
                .expr()
                .minimal_sets(&|_| None)
                .unwrap_or_default();
            (&t.name, sets)
        })
}

/// The `pNext` walk: uniqueness of structure types, the version or extension of
/// each node enabled, then each struct's own checks.
fn chain_fn(checker: &Checker, origins: &Origins) -> TokenStream {
    let model = checker.cx.model;
    let mut gates = Vec::new();
    for (name, sets) in gated_structs(model) {
        let Some(stype) = struct_type_value(checker.cx, name) else {
            continue;
        };
        let lit = Literal::i32_unsuffixed(stype);
        let cfg = crate::names::cfg_of(model, model.condition(name));
        // Each alternative is a set that must all be enabled; an empty list is
        // never enabled.
        let alts: Vec<TokenStream> = sets
            .iter()
            .map(|set| {
                let idx: Vec<u16> = set
                    .iter()
                    .map(|n| origins.names.iter().position(|o| o == n).map(|i| i as u16))
                    .collect::<Option<Vec<_>>>()
                    .unwrap_or_default();
                if idx.is_empty() {
                    return quote!(false);
                }
                let has = idx.iter().map(|i| {
                    let i = Literal::u16_unsuffixed(*i);
                    quote!(s.exts.has(#i))
                });
                match (idx.len(), sets.len()) {
                    (1, _) => quote!(#(#has)*),
                    (_, 1) => quote!(#(#has)&&*),
                    _ => quote!((#(#has)&&*)),
                }
            })
            .collect();
        let body = if alts.is_empty() {
            quote!(false)
        } else {
            quote!(#(#alts)||*)
        };
        gates.push(quote! {
            #cfg
            #lit => #body,
        });
    }
    let mut arms = Vec::new();
    let mut duplicates = Vec::new();
    for name in &checker.checked {
        let t = &model.types[name];
        if t.struct_extends.is_empty() {
            continue;
        }
        let Some(stype) = struct_type_value(checker.cx, name) else {
            continue;
        };
        let f = ident(&format!("check_{}", snake(name)));
        let ty = crate::names::type_ident(model.spelling(name));
        let cfg = crate::names::cfg_of(model, model.condition(name));
        let lit = Literal::i32_unsuffixed(stype);
        arms.push(quote! {
            #cfg
            #lit => {
                __safety!("a node with this structure type is this struct.");
                #f(unsafe { &*(p as *const vk::#ty<'_>) }, s)?
            }
        });
    }
    for t in model.types.values() {
        if t.allow_duplicate && t.alias.is_none() && model.emitted.contains(&t.name) {
            if let Some(v) = struct_type_value(checker.cx, &t.name) {
                duplicates.push(Literal::i32_unsuffixed(v));
            }
        }
    }
    quote! {
        /// Structure types that may appear more than once in a chain.
        const DUPLICATES_ALLOWED: &[i32] = &[#(#duplicates),*];

        /// Whether the version or extension that defines structure type `ty` is
        /// enabled in the scope (any type of Vulkan 1.0, or one no gate names, is).
        fn node_enabled(ty: i32, s: &Scope<'_>) -> bool {
            match ty {
                #(#gates)*
                _ => true,
            }
        }

        /// Walks a `pNext` chain: no structure type twice (when `unique` names that
        /// rule), with `pnext` (the struct's `pNext-pNext` rule) no node of a
        /// version or extension the scope does not enable, and each node's own
        /// checks.
        pub(crate) fn chain(next: *const core::ffi::c_void, s: &Scope<'_>, pnext: Option<&'static str>, unique: Option<&'static str>) -> Result<()> {
            let mut seen: smallvec::SmallVec<[i32; 8]> = smallvec::SmallVec::new();
            __safety!("chains are built by `push_next` from safe structs, each a live struct that begins with `sType` and `pNext`.");
            for base in unsafe { crate::support::chain_nodes(next) } {
                let p = base as *const vk::BaseInStructure<'_>;
                let ty = base.s_type.as_raw();
                if let Some(vuid) = pnext {
                    if !node_enabled(ty, s) {
                        return refuse(vuid, format!("{:?} belongs to a version or extension that this instance or device does not enable", base.s_type));
                    }
                }
                if let Some(vuid) = unique {
                    if seen.contains(&ty) && !DUPLICATES_ALLOWED.contains(&ty) {
                        return refuse(vuid, format!("{:?} appears twice in the pNext chain", base.s_type));
                    }
                    seen.push(ty);
                }
                match ty {
                    #(#arms)*
                    _ => {}
                }
            }
            Ok(())
        }
    }
}

/// The versions and extensions that define enum values, numbered for the bit set
/// that instances and devices keep.
struct Origins {
    names: Vec<String>,
    /// The minor version of each leading `VK_VERSION_1_x` entry.
    minors: Vec<u32>,
}

impl Origins {
    fn new(model: &crate::model::Model, types: &BTreeSet<String>) -> Origins {
        let mut all: BTreeSet<String> = BTreeSet::new();
        for t in types {
            let group = match model.category(t) {
                Some(Kind::Enum) => t.clone(),
                _ => flag_bits(model, t).unwrap_or_default(),
            };
            for (_, o) in enum_values(model, &group) {
                all.extend(o);
            }
        }
        // Every enabled version is numbered, whether or not an enum value names it:
        // `Exts::version` answers for each (a version whose values ash lacks, and
        // whose own function table loads only where it holds).
        all.extend(
            model
                .enabled
                .iter()
                .filter(|n| n.starts_with("VK_VERSION_"))
                .cloned(),
        );
        let mut versions: Vec<(u32, String)> = all
            .iter()
            .filter_map(|n| {
                let minor = n.strip_prefix("VK_VERSION_1_")?.parse().ok()?;
                Some((minor, n.clone()))
            })
            .collect();
        versions.sort();
        let mut names: Vec<String> = versions.iter().map(|(_, n)| n.clone()).collect();
        let minors = versions.iter().map(|(m, _)| *m).collect();
        names.extend(all.into_iter().filter(|n| !n.starts_with("VK_VERSION_")));
        Origins { names, minors }
    }

    /// Adds extensions (not versions: every version is numbered already) that no
    /// enum value named.
    fn add(&mut self, names: impl Iterator<Item = String>) {
        for n in names {
            if !n.starts_with("VK_VERSION_") && !self.names.contains(&n) {
                self.names.push(n);
            }
        }
    }

    fn indices(&self, origins: &BTreeSet<String>) -> Vec<u16> {
        origins
            .iter()
            .filter_map(|o| self.names.iter().position(|n| n == o))
            .map(|i| i as u16)
            .collect()
    }

    fn emit(&self) -> TokenStream {
        let words = self.names.len().div_ceil(64).max(1);
        let names = &self.names;
        let n = names.len();
        let minors = &self.minors;
        let nv = minors.len();
        let consts = names.iter().enumerate().map(|(i, n)| {
            let id = ident(&n.to_uppercase());
            let i = i as u16;
            quote!(pub(crate) const #id: u16 = #i;)
        });
        quote! {
            /// Names of the versions and extensions that define enum values: the
            /// versions first, in order, then the extensions.
            const ORIGINS: [&str; #n] = [#(#names),*];
            /// Each entry's index in `ORIGINS`: the explicit checks' conditions test
            /// `Exts::has(origin::NAME)`, a bit, where a name would be a search.
            #[allow(dead_code)]
            pub(crate) mod origin {
                #(#consts)*
            }
            /// The minor version of each leading version entry of `ORIGINS`.
            const VERSION_MINORS: [u32; #nv] = [#(#minors),*];

            /// The versions and extensions enabled on an instance or device, as a bit
            /// set over `ORIGINS`.
            #[derive(Clone, Copy, Default, Debug)]
            pub(crate) struct Exts([u64; #words]);

            impl Exts {
                /// Versions up to 1.`minor` and the extensions named.
                pub(crate) fn new(minor: u32, names: &[&core::ffi::CStr]) -> Exts {
                    let mut e = Exts::default();
                    for (i, m) in VERSION_MINORS.iter().enumerate() {
                        if *m <= minor {
                            e.set(i);
                        }
                    }
                    for name in names {
                        if let Some(i) = ORIGINS.iter().position(|o| o.as_bytes() == name.to_bytes()) {
                            e.set(i);
                        }
                    }
                    e
                }
                fn set(&mut self, i: usize) {
                    self.0[i / 64] |= 1 << (i % 64);
                }
                /// Whether entry `i` of `ORIGINS` is enabled.
                #[inline]
                pub(crate) fn has(&self, i: u16) -> bool {
                    let i = i as usize;
                    self.0[i / 64] & (1 << (i % 64)) != 0
                }
                /// Whether core version 1.`minor` is enabled.
                pub(crate) fn version(&self, minor: u32) -> bool {
                    VERSION_MINORS
                        .iter()
                        .position(|m| *m == minor)
                        .is_some_and(|i| self.has(i as u16))
                }
                /// Whether the version or extension `name` (as vk.xml spells it) is
                /// enabled; a name outside the emitted API never is.
                pub(crate) fn named(&self, name: &str) -> bool {
                    ORIGINS
                        .iter()
                        .position(|o| *o == name)
                        .is_some_and(|i| self.has(i as u16))
                }
                /// Both sets.
                pub(crate) fn with(mut self, other: Exts) -> Exts {
                    for (a, b) in self.0.iter_mut().zip(other.0) {
                        *a |= b;
                    }
                    self
                }
                /// Without the versions above 1.`minor`.
                pub(crate) fn cap(mut self, minor: u32) -> Exts {
                    for (i, m) in VERSION_MINORS.iter().enumerate() {
                        if *m > minor {
                            self.0[i / 64] &= !(1 << (i % 64));
                        }
                    }
                    self
                }
            }
        }
    }
}

/// `enum_<type>`: fails unless the value is defined by an enabled version or
/// extension.
fn enum_fn(cx: &Context, origins: &Origins, t: &str) -> TokenStream {
    let model = cx.model;
    let f = ident(&format!("enum_{}", snake(t)));
    let ty = spelled(model, &cx.facts, t);
    // Values grouped by the set of origins, as ranges of consecutive values.
    let mut by_origin: BTreeMap<Vec<u16>, Vec<i64>> = BTreeMap::new();
    for (n, o) in enum_values(model, t) {
        by_origin.entry(origins.indices(&o)).or_default().push(n);
    }
    let arms = by_origin.iter().map(|(idx, values)| {
        let pats = super::explicit::ranges(values).into_iter().map(|(a, b)| {
            let (la, lb) = (Literal::i64_unsuffixed(a), Literal::i64_unsuffixed(b));
            if a == b {
                quote!(#la)
            } else {
                quote!(#la..=#lb)
            }
        });
        quote!(#(#pats)|* => &[#(#idx),*],)
    });
    let msg = format!("{{v:?}} is not a `{t}` value of the versions and extensions enabled here");
    quote! {
        pub(crate) fn #f(v: #ty, s: &Scope<'_>, vuid: &'static str) -> Result<()> {
            let origins: &[u16] = match v.as_raw() as i64 {
                #(#arms)*
                _ => &[],
            };
            if s.enabled(origins) {
                Ok(())
            } else {
                refuse(vuid, format!(#msg))
            }
        }
    }
}

/// `flags_<type>`: fails unless every bit set is defined by an enabled version or
/// extension.
fn flags_fn(cx: &Context, origins: &Origins, t: &str) -> TokenStream {
    let model = cx.model;
    let f = ident(&format!("flags_{}", snake(t)));
    let ty = spelled(model, &cx.facts, t);
    let bits = flag_bits(model, t).unwrap_or_default();
    let mut by_origin: BTreeMap<Vec<u16>, u64> = BTreeMap::new();
    for (n, o) in enum_values(model, &bits) {
        // Only single bits: `VK_SHADER_STAGE_ALL` and the like are combinations.
        if (n as u64).count_ones() == 1 {
            *by_origin.entry(origins.indices(&o)).or_default() |= n as u64;
        }
    }
    let adds = by_origin.iter().map(|(idx, mask)| {
        let m = Literal::u64_unsuffixed(*mask);
        quote!(if s.enabled(&[#(#idx),*]) { valid |= #m; })
    });
    let msg =
        format!("{{v:?}} sets bits of `{t}` that no version or extension enabled here defines");
    // The bits of core 1.0, which every scope enables (the first origin, when it is
    // VK_VERSION_1_0): a value of those alone, the common case on a draw's path,
    // needs no origin looked up.
    let core = match origins.minors.first() {
        Some(0) => by_origin
            .iter()
            .filter(|(idx, _)| idx.contains(&0))
            .fold(0, |m, (_, mask)| m | mask),
        _ => 0,
    };
    let body = quote! {
        let mut valid: u64 = 0;
        #(#adds)*
        if (v.as_raw() as u64) & !valid == 0 {
            Ok(())
        } else {
            refuse(vuid, format!(#msg))
        }
    };
    if core == 0 {
        return quote! {
            pub(crate) fn #f(v: #ty, s: &Scope<'_>, vuid: &'static str) -> Result<()> {
                #body
            }
        };
    }
    // The test of the core bits inlined where the value is checked; the origins
    // looked up out of line.
    let core = Literal::u64_unsuffixed(core);
    let rest = ident(&format!("flags_{}_past_core", snake(t)));
    quote! {
        #[inline]
        pub(crate) fn #f(v: #ty, s: &Scope<'_>, vuid: &'static str) -> Result<()> {
            if (v.as_raw() as u64) & !#core == 0 {
                Ok(())
            } else {
                #rest(v, s, vuid)
            }
        }
        #[inline(never)]
        fn #rest(v: #ty, s: &Scope<'_>, vuid: &'static str) -> Result<()> {
            #body
        }
    }
}

/// The code of one check. It may read `s` (the scope), the method's arguments or
/// `v` (the checked struct), and returns early with `?` or `Err`.
pub fn render(check: &Check) -> TokenStream {
    let vuid = check.vuid.as_deref().unwrap_or_default();
    let fail = |msg: &str| quote!(return refuse(#vuid, #msg););
    match &check.kind {
        CheckKind::Value { kind, at } => value(kind, place(at), vuid),
        CheckKind::EachValue { kind, over } => {
            let body = value(kind, quote!(*e), vuid);
            match over {
                Seq::MemberArray(m) => {
                    let f = field_ident(m);
                    quote!(for e in v.#f.iter() { #body })
                }
                Seq::MemberSlice { member, count } => {
                    let (f, n) = (field_ident(member), field_ident(count));
                    quote! {
                        __safety!("the safe setter stored this array and its count.");
                        for e in unsafe { members(v.#f, v.#n) } { #body }
                    }
                }
                Seq::ArgSlice(a) => {
                    let a = ident(a);
                    quote!(for e in #a.iter() { #body })
                }
            }
        }
        CheckKind::FnPointerSet { member } => {
            let f = field_ident(member);
            let fail = fail(&format!("`{member}` is NULL"));
            quote!(if v.#f.is_none() { #fail })
        }
        CheckKind::NonZero { at, msg } => {
            let (at, fail) = (place(at), fail(msg));
            quote!(if #at == 0 { #fail })
        }
        CheckKind::NotEmpty { at, msg } => {
            let (at, fail) = (place(at), fail(msg));
            quote!(if #at.is_empty() { #fail })
        }
        CheckKind::ZeroFlags { at, msg } => {
            let (at, fail) = (place(at), fail(msg));
            quote!(if #at.as_raw() != 0 { #fail })
        }
        CheckKind::OwnedBy { ancestor, handles } => {
            let owner = ident(if ancestor == "VkInstance" {
                "owned_by_instance"
            } else {
                "owned_by_device"
            });
            let each = handles.iter().map(|(at, msg)| {
                let fail = fail(msg);
                match at {
                    // A device child's wrapper names its device: a pointer-sized
                    // comparison instead of a lookup in the device's object list.
                    HandleAt::Arg {
                        name,
                        optional: false,
                        parent_is_ancestor: true,
                    } if ancestor == "VkPhysicalDevice" => {
                        let a = ident(name);
                        quote!(if s.device.is_none_or(|d| #a.parent().raw() != d.parent().raw()) { #fail })
                    }
                    HandleAt::Arg {
                        name,
                        optional: false,
                        parent_is_ancestor: true,
                    } => {
                        let a = ident(name);
                        quote!(if s.device.is_none_or(|d| #a.parent().raw() != d.raw()) { #fail })
                    }
                    HandleAt::Arg {
                        name,
                        optional: false,
                        ..
                    } => {
                        let a = ident(name);
                        quote!(if !s.#owner(#a.raw()) { #fail })
                    }
                    HandleAt::Arg {
                        name,
                        optional: true,
                        ..
                    } => {
                        let a = ident(name);
                        quote!(if let Some(h) = #a { if !s.#owner(h.raw()) { #fail } })
                    }
                    HandleAt::ArgSlice(name) => {
                        let a = ident(name);
                        quote!(for h in #a.iter() { if !s.#owner(h.raw()) { #fail } })
                    }
                    HandleAt::Member(m) => {
                        let f = field_ident(m);
                        quote!(if v.#f != Default::default() && !s.#owner(v.#f) { #fail })
                    }
                    HandleAt::MemberSlice { member, count } => {
                        let (f, n) = (field_ident(member), field_ident(count));
                        quote! {
                            __safety!("the safe setter stored these handles and their count.");
                            for h in unsafe { members(v.#f, v.#n) } {
                                if *h != Default::default() && !s.#owner(*h) { #fail }
                            }
                        }
                    }
                }
            });
            quote!(#(#each)*)
        }
        CheckKind::QueueFlags { of, queues } => {
            let needed = queue_flags(queues);
            let (flags, msg) = match of {
                QueueOf::Pool => (
                    quote!(self.pool_queue_flags()),
                    format!("the command buffer's pool does not support {queues} operations"),
                ),
                QueueOf::Queue => (
                    quote!(self.queue_flags()),
                    format!("the queue does not support {queues} operations"),
                ),
            };
            let fail = fail(&msg);
            quote!(if !crate::validation::supports(#flags, #needed) { #fail })
        }
        CheckKind::InlineContents => quote!(self.inline_contents_check()?;),
        CheckKind::DeviceHasQueues => {
            let fail = fail("the device was created with no queue");
            quote!(if self.live().queue_infos().is_empty() { #fail })
        }
        CheckKind::Level { primary } => {
            let (want, level) = if *primary {
                (quote!(vk::CommandBufferLevel::PRIMARY), "primary")
            } else {
                (quote!(vk::CommandBufferLevel::SECONDARY), "secondary")
            };
            let fail = fail(&format!(
                "the command buffer is not a {level} command buffer"
            ));
            quote!(if self.command_buffer().level() != #want { #fail })
        }
        CheckKind::Reaches { ty, at } => {
            let walk = crate::emit::reach::walk_fn(ty);
            let visit = |e: TokenStream| {
                quote! {
                    __safety!("a safe struct, whose setters store every pointer with its length, as the walk requires.");
                    unsafe { #walk(#e.as_raw(), &mut reached) };
                }
            };
            let walks = match at {
                StructAt::Arg(a) => {
                    let a = ident(a);
                    visit(quote!(#a))
                }
                StructAt::OptionalArg(a) => {
                    let (a, v) = (ident(a), visit(quote!(x)));
                    quote!(if let Some(x) = #a { #v })
                }
                StructAt::ArgSlice(a) => {
                    let (a, v) = (ident(a), visit(quote!(x)));
                    quote!(for x in #a.iter() { #v })
                }
                _ => quote!(),
            };
            quote! {
                {
                    let mut reached = crate::validation::Reached::checking(s);
                    #walks
                    reached.owned()?;
                }
            }
        }
        CheckKind::NestedStruct { ty, at } => {
            let call = ident(&format!("check_{}", snake(ty)));
            match at {
                StructAt::Member(m) => {
                    let f = field_ident(m);
                    quote!(crate::checks::#call(&v.#f, s)?;)
                }
                StructAt::MemberRef(m) => {
                    let f = field_ident(m);
                    quote! {
                        if !v.#f.is_null() {
                            __safety!("the safe setter stores a reference that outlives `v`.");
                            crate::checks::#call(unsafe { &*v.#f }, s)?;
                        }
                    }
                }
                StructAt::MemberSlice { member, count } => {
                    let (f, n) = (field_ident(member), field_ident(count));
                    quote! {
                        __safety!("the safe setter stored this array and its count.");
                        for e in unsafe { members(v.#f, v.#n) } {
                            crate::checks::#call(e, s)?;
                        }
                    }
                }
                StructAt::Arg(a) => {
                    let a = ident(a);
                    quote!(crate::checks::#call(#a, s)?;)
                }
                StructAt::OptionalArg(a) => {
                    let a = ident(a);
                    quote!(if let Some(x) = #a { crate::checks::#call(x, s)?; })
                }
                StructAt::ArgByValue(a) => {
                    let a = ident(a);
                    quote!(crate::checks::#call(&#a, s)?;)
                }
                StructAt::ArgSlice(a) => {
                    let a = ident(a);
                    quote!(for x in #a.iter() { crate::checks::#call(x, s)?; })
                }
                StructAt::Variant {
                    union,
                    variant,
                    selector,
                    selector_type,
                    values,
                    by_ref,
                } => {
                    let (u, f, sel) = (
                        field_ident(union),
                        field_ident(variant),
                        field_ident(selector),
                    );
                    let ty = ident(selector_type);
                    let values = values.iter().map(|c| {
                        let c = ident(c);
                        quote!(vk::#ty::#c)
                    });
                    let check = match by_ref {
                        true => quote! {
                            __safety!("the safe enum's variant wrote this member with the selector, from a reference that outlives `v`.");
                            let x = unsafe { v.#u.#f };
                            if !x.is_null() {
                                __safety!("the pointer comes from that reference.");
                                crate::checks::#call(unsafe { &*x }, s)?;
                            }
                        },
                        false => quote! {
                            __safety!("the safe enum's variant wrote this member with the selector.");
                            crate::checks::#call(unsafe { &v.#u.#f }, s)?;
                        },
                    };
                    quote!(if #(v.#sel == #values)||* { #check })
                }
            }
        }
        CheckKind::Chain { pnext } => {
            let unique = match &check.vuid {
                Some(v) => quote!(Some(#v)),
                None => quote!(None),
            };
            let pnext = match pnext {
                Some(v) => quote!(Some(#v)),
                None => quote!(None),
            };
            quote!(crate::checks::chain(v.p_next, s, #pnext, #unique)?;)
        }
        CheckKind::Explicit(r) => super::explicit::render(r),
    }
}

/// Where a checked value is, as an expression.
fn place(at: &Place) -> TokenStream {
    match at {
        Place::Arg(a) => {
            let a = ident(a);
            quote!(#a)
        }
        Place::ArgMember(a, m) => {
            let (a, m) = (ident(a), field_ident(m));
            quote!(#a.#m)
        }
        Place::Member(m) => {
            let f = field_ident(m);
            quote!(v.#f)
        }
    }
}

/// The call of a value's check function.
fn value(kind: &ValueKind, expr: TokenStream, vuid: &str) -> TokenStream {
    match kind {
        ValueKind::Enum(t) => {
            let f = ident(&format!("enum_{}", snake(t)));
            quote!(crate::checks::#f(#expr, s, #vuid)?;)
        }
        ValueKind::Flags(t) => {
            let f = ident(&format!("flags_{}", snake(t)));
            quote!(crate::checks::#f(#expr, s, #vuid)?;)
        }
        ValueKind::Struct(t) => {
            let f = ident(&format!("check_{}", snake(t)));
            quote!(crate::checks::#f(&#expr, s)?;)
        }
    }
}

/// `graphics,compute` as `vk::QueueFlags`.
fn queue_flags(queues: &str) -> TokenStream {
    let flags: Vec<TokenStream> = queues
        .split(',')
        .filter_map(|q| match q.trim() {
            "graphics" => Some(quote!(vk::QueueFlags::GRAPHICS)),
            "compute" => Some(quote!(vk::QueueFlags::COMPUTE)),
            "transfer" => Some(quote!(vk::QueueFlags::TRANSFER)),
            "sparse_binding" => Some(quote!(vk::QueueFlags::SPARSE_BINDING)),
            "protected" => Some(quote!(vk::QueueFlags::PROTECTED)),
            _ => None,
        })
        .collect();
    if flags.is_empty() {
        quote!(vk::QueueFlags::from_raw(u32::MAX))
    } else {
        quote!(#(#flags)|*)
    }
}
