//! Emits `src/commands.rs`: every command of the emitted API whose parameters have a
//! safe shape becomes a method on the wrapper it dispatches on (commands recorded into
//! command buffers go on the `Recorder` of the right render-pass state). A command
//! with a parameter of no safe shape is not emitted; its rules are recorded as left to
//! the user, who can call it through ash on the raw handles.

mod keep;

use super::structs::safe_or_ash;
use crate::model::CommandDef;
use crate::model::Kind;
use crate::model::LenEntry;
use crate::names::{field_ident, ident, level, param, table, type_ident, Level, Table};
use crate::plan::checks::{Check, Checker};
use crate::plan::commands::{
    parent_of, parent_param, recorded, DisplayKind, Param, Plan, RecorderState, Transition,
};
use crate::plan::special::{special, Call, Keeps};
use crate::plan::types::{ash_type, spelled};
use crate::plan::Context;
use crate::plan::Plans;
use keep::{keep_expr, struct_retains};
use proc_macro2::{Ident, TokenStream};
use quote::{quote, ToTokens};

/// A call of a hand-written function of the special-case table: `crate::path(args)`, with
/// `created` standing for the value the method would return without the special case.
fn special_call(c: &Call, created: &TokenStream) -> TokenStream {
    let path = c.path.split("::").map(ident);
    // A binding is named; anything else (a path, a string literal) is Rust as written.
    let args = c.args.iter().map(|a| match *a {
        "self" => quote!(self),
        "created" => created.clone(),
        a if a.chars().all(|c| c.is_alphanumeric() || c == '_') => ident(a).into_token_stream(),
        a => a
            .parse()
            .unwrap_or_else(|_| quote!(compile_error!("a special-case argument is not Rust"))),
    });
    let call = quote!(crate::#(#path)::*(#(#args),*));
    match c.promise {
        Some(promise) => {
            let safety = super::safety(promise);
            quote!({ #safety unsafe { #call } })
        }
        None => call,
    }
}

/// Whether a slice parameter is optional and shares its count with an earlier one.
fn optional_same_len(plan: &Plan, param: &str) -> bool {
    plan.same_len.iter().any(|s| s.param == param && s.optional)
}

/// The rule a slice shorter than its count breaks: its implicit `-parameter` rule
/// (a valid pointer to an array of that many elements).
fn same_len_vuid(plan: &Plan, s: &crate::plan::commands::SameLen) -> String {
    format!("VUID-{}-{}-parameter", plan.name, s.param)
}

/// The checks every build runs that slices sharing a count are as long as the one
/// that sets it (or empty, where optional).
fn same_len_checks(plan: &Plan) -> Vec<TokenStream> {
    plan.same_len
        .iter()
        .map(|s| {
            let vuid = same_len_vuid(plan, s);
            let (q, first) = (param(&s.param), param(&s.first));
            let (qi, fi) = (ident(&q), ident(&first));
            let message = format!("`{q}` has {{}} elements where `{first}` has {{}}");
            let empty_ok = s.optional.then(|| quote!(!#qi.is_empty() &&));
            quote! {
                if #empty_ok #qi.len() != #fi.len() {
                    return Err(Error::Validation {
                        vuid: #vuid,
                        message: format!(#message, #qi.len(), #fi.len()),
                    });
                }
            }
        })
        .collect()
}

/// A special-case function called as a statement.
fn special_stmt(c: &Call) -> TokenStream {
    match c.promise {
        Some(promise) => {
            let safety = super::safety(promise);
            let call = special_call(
                &Call {
                    promise: None,
                    ..*c
                },
                &quote!(),
            );
            quote!(#safety unsafe { #call };)
        }
        None => {
            let call = special_call(c, &quote!());
            quote!(#call;)
        }
    }
}

/// The `commands` module, and the `command_checks` module with the named dynamic checks
/// that its checked methods call.
/// Generated files by path, as `emit::split` writes them.
type Files = Vec<(String, TokenStream)>;

pub(super) fn emit(all: &Plans, plans: &[&Plan]) -> (Files, Files) {
    let mut modules: std::collections::BTreeMap<String, (Vec<String>, ImplBlocks)> =
        Default::default();
    let mut validators: std::collections::BTreeMap<String, (Vec<String>, ImplBlocks)> =
        Default::default();
    for plan in plans {
        let (header, item, validator) = emit_command(all, plan);
        if item.is_empty() {
            continue;
        }
        // Core versions keep their recorded commands apart: Vulkan 1.0's alone would
        // make one file of 6,000 lines.
        let mut module = super::module_of(all.cx.model, &plan.name);
        if recorded(plan) && module.starts_with("v1_") {
            module.push_str("_recording");
        }
        if let Some(v) = validator {
            let (names, blocks) = validators.entry(module.clone()).or_default();
            names.push(plan.name.clone());
            blocks.push(header.clone(), v);
        }
        let (names, blocks) = modules.entry(module).or_default();
        names.push(plan.name.clone());
        blocks.push(header, item);
    }
    let modules = modules
        .into_iter()
        .map(|(m, (names, blocks))| (m, (names, blocks.render().collect())))
        .collect();
    let validators = validators
        .into_iter()
        .map(|(m, (names, blocks))| (m, (names, blocks.render().collect())))
        .collect();
    let head = quote! {
        //! Commands as methods on the wrappers they dispatch on, one module per core
        //! version and extension.
        //!
        //! Every call into Vulkan here is sound for the same reasons, which its
        //! `// SAFETY:` comment names in short: every handle argument comes from a live
        //! wrapper (which keeps its parent alive), every pointer from a reference or
        //! slice that outlives the call, and every count from the length of the slice
        //! it sizes. A checked method calls its `_unchecked` twin after the checks that
        //! every build runs; the rules it does not check are
        //! listed, rule by rule, in `validation.json`.
        #![allow(clippy::too_many_arguments)]
        // Vulkan commands take as many parameters as the registry gives them.
        use crate::handles::*;
        use crate::structs::*;
        use crate::{recorder::*, Entry, Error, Handle, Result};
        use crate::vk;
    };
    let commands = super::split(
        all.cx.model,
        "commands",
        "The commands",
        head,
        modules,
        false,
    );
    let checks_head = quote! {
        //! The dynamic checks of each command, run in every build: one `validate_*`
        //! method per checked command,
        //! beside it on the same receiver, which the checked method calls first;
        //! one module per core version and extension, as the commands are.
        #![allow(clippy::too_many_arguments)]
        // A check takes the parameters its rules read, as many as the command has.
        #[allow(unused_imports)]
        use crate::checks::origin;
        use crate::handles::*;
        use crate::structs::*;
        use crate::support::refuse;
        use crate::{recorder::*, Entry, Handle, Result};
        use crate::vk;
    };
    let checks = super::split(
        all.cx.model,
        "command_checks",
        "The dynamic checks of the commands",
        checks_head,
        validators,
        false,
    );
    (commands, checks)
}

/// A command's `impl` header, its methods, and its `validate_*` method if it has checks.
fn emit_command(all: &Plans, plan: &Plan) -> (TokenStream, TokenStream, Option<TokenStream>) {
    let (cx, checker): (&Context, &Checker) = (all.cx, &all.checker);
    let model = cx.model;
    let cmd = &model.commands[&plan.name];
    let cfg = crate::names::cfg_of(model, &plan.condition);
    let f = ident(&cx.method(&plan.name));
    // Commands recorded into a command buffer go on the recorder; the others of a
    // command buffer (`vkResetCommandBuffer`) on the buffer itself, taken mutably,
    // so that no recorder of it is alive.
    let is_cmd = recorded(plan);
    let lvl = level(model, &plan.name);
    // The dispatchable handle: `self`'s, or its parent's where the method is called
    // on a display (a physical device's child).
    let receiver_raw = if plan.receiver == "Entry" {
        quote!()
    } else if cmd
        .params
        .first()
        .is_some_and(|p| p.type_name != plan.receiver)
    {
        quote!(self.parent().raw(),)
    } else {
        quote!(self.raw(),)
    };
    // The ash table of the command.
    let device_path = match (lvl, plan.receiver.as_str()) {
        (Level::Entry, _) => quote!(self),
        (Level::Instance, "VkInstance") => quote!(self),
        (Level::Instance, "VkDisplayKHR") => quote!(self.parent().parent()),
        (Level::Instance, _) => quote!(self.parent()),
        (Level::Device, "VkDevice") => quote!(self),
        (Level::Device, "VkQueue") => quote!(self.parent()),
        (Level::Device, _) => quote!(self.device()),
    };
    // The function pointer, copied out of its table: for an extension, so that no
    // borrow of the receiver's table is held across what the call does to the
    // receiver (and the call fails when the extension is not enabled); for core,
    // alike, which keeps the call on one line.
    let the_table = table(model, &plan.name);
    // A transition's missing extension table poisons the recorder.
    let poisons_without_table =
        plan.transition.is_some() && matches!(the_table, Some(Table::Extension(_) | Table::Own(_)));
    let field = the_table
        .as_ref()
        .map(|t| crate::names::fn_field(model, &plan.name, t));
    let (load_fp, fallible_ext) = match the_table {
        Some(Table::Core(m)) => {
            let table = ident(&format!("fp_v1_{m}"));
            (quote!(let fp = #device_path.fns().#table().#field;), false)
        }
        // An extension's table, or the crate's own table of a core version ash
        // lacks: either may be absent (the extension not enabled, the version not
        // the device's), and the call is then refused.
        Some(t) => {
            let Some((fe, missing)) = crate::names::optional_table(&t) else {
                unreachable!("a core table is matched above")
            };
            match plan.transition {
                // A method that moves the recorder returns the next one, not a
                // `Result`: a missing table poisons the recorder (its `end` returns
                // the error), and a begin not recorded makes its end a no-op.
                Some(_) => {
                    let skip = matches!(plan.transition, Some(Transition::Begin(_)))
                        .then(|| quote!(self.skip_begin(true);));
                    (
                        quote! {
                            let Some(table) = #device_path.ext().#fe.as_ref() else {
                                let _ = self.accept(Err(#missing));
                                #skip
                                return self.into_state();
                            };
                            let fp = table.#field;
                        },
                        false,
                    )
                }
                None => (
                    quote!(let fp = #device_path.ext().#fe.as_ref().ok_or(#missing)?.#field;),
                    true,
                ),
            }
        }
        None => return (quote!(), quote!(), None),
    };
    let mut args: Vec<Arg> = Vec::new(); // method parameters
    let mut pre: Vec<TokenStream> = Vec::new();
    let mut call_args: Vec<TokenStream> = Vec::new();
    // Handle arrays, taken as `impl Handles` (one wrapper or a `HandleSlice`, as struct
    // members take them) and seen by the body as a slice of wrappers: name, wrapper.
    let mut handle_arrays: Vec<(proc_macro2::Ident, proc_macro2::Ident)> = Vec::new();
    let mut retain: Vec<TokenStream> = Vec::new();
    // What the method returns besides errors: its type and the expression that
    // makes it, `()` until a parameter or the result gives a value (`has_value`).
    let mut ret_ty = quote!(());
    let mut ret_expr = quote!(());
    let mut has_value = false;
    // The enumerated elements are returned as the two calls fill them.
    let mut items_as_is = false;
    // The body records on the recorder (retains a handle, poisons it, hands it to a
    // special case), so a transition's unchecked method takes it mutably.
    let mut uses_recorder = poisons_without_table;
    let mut post: Vec<TokenStream> = Vec::new();
    let mut two_call = None;
    // The element type of a second array the same two calls fill.
    let mut second: Option<TokenStream> = None;
    // Parameters taken as `bool` for a `VkBool32`, by name.
    let mut bools: Vec<String> = Vec::new();
    let special = special(&plan.name);
    let same_len = same_len_checks(plan);
    // A recorded command that an always-on check may refuse returns its error.
    // A command that moves the recorder (a render pass's begin, next subpass or end)
    // poisons the recorder instead: its checks' errors come from `end`.
    let mut fallible = cmd.return_type == "VkResult"
        || fallible_ext
        || (is_cmd
            && plan.transition.is_none()
            && (special.is_some_and(|s| s.check.is_some() || s.check_last.is_some())
                || !same_len.is_empty()));
    let mut lifetimes = false;
    let created_ty = cmd
        .params
        .last()
        .map(|p| p.type_name.clone())
        .unwrap_or_default();
    let created_parent = parent_of(cx, &created_ty).unwrap_or_default();
    let pool_override = if created_parent != plan.receiver {
        parent_param(cx, cmd, &created_parent)
    } else {
        None
    };
    // The create info (or infos, one per created object) of a create command.
    let info_param = cmd
        .params
        .iter()
        .zip(&plan.params)
        .find(|(_, s)| matches!(s, Param::StructRef { optional: false }))
        .map(|(p, _)| {
            (
                ident(&param(&p.name)).into_token_stream(),
                p.type_name.as_str(),
            )
        });
    let infos_param = cmd
        .params
        .iter()
        .zip(&plan.params)
        .find(|(p, s)| matches!(s, Param::Slice) && cx.facts.is_safe(&p.type_name))
        .map(|(p, _)| {
            (
                ident(&param(&p.name)).into_token_stream(),
                p.type_name.as_str(),
            )
        });
    let override_member = pool_override.as_ref().and_then(|(_, m)| m.as_deref());
    for (p, shape) in cmd.params.iter().zip(&plan.params) {
        let name = ident(&param(&p.name));
        match shape {
            Param::Raw => {
                let ty = crate::plan::types::raw_type(model, &cx.facts, p);
                lifetimes |= names_a(&ty);
                args.push(Arg::new(&name, quote!(#ty)));
                call_args.push(quote!(#name,));
            }
            Param::Display(kind) => {
                // `window.rs` reads the connection out of the handle, as surfaces do.
                let get = ident(match kind {
                    DisplayKind::Xlib => "xlib_display",
                    DisplayKind::Xcb => "xcb_connection",
                    DisplayKind::Wayland => "wayland_display",
                });
                let ty = crate::plan::types::raw_type(model, &cx.facts, p);
                args.push(Arg::new(
                    &name,
                    quote!(raw_window_handle::DisplayHandle<'_>),
                ));
                pre.push(quote! {
                    let #name: #ty = crate::present::window::#get(#name.as_raw())?.as_ptr().cast();
                });
                call_args.push(quote!(#name,));
            }
            Param::Dispatch => call_args.push(receiver_raw.clone()),
            Param::Receiver => call_args.push(quote!(self.raw(),)),
            Param::Allocator => call_args.push(quote!(core::ptr::null(),)),
            Param::HostAllocator => call_args.push(quote!(
                crate::memory::host::HostCallbacks::host_callbacks(self),
            )),
            Param::NotDeferred => call_args.push(quote!(vk::DeferredOperationKHR::null(),)),
            Param::Count => {
                // The length of the first slice that names this count.
                let user = cmd
                    .params
                    .iter()
                    .zip(&plan.params)
                    .find(|(q, _)| {
                        q.parsed
                            .len
                            .first()
                            .and_then(|l| l.other_param().map(str::to_owned))
                            == Some(p.name.clone())
                    })
                    .map(|(q, _)| ident(&param(&q.name)));
                match user {
                    Some(u) => {
                        let ty = ash_type(model, &cx.facts, &p.type_name).unwrap_or(quote!(u32));
                        if p.type_name == "size_t" {
                            call_args.push(quote!(#u.len(),));
                        } else {
                            call_args.push(quote!(#u.len() as #ty,));
                        }
                    }
                    None => call_args.push(quote!(0,)),
                }
            }
            // Rust's `bool` where Vulkan has `VkBool32`, as ash's own wrappers do; the
            // body (and the special-case functions it calls) sees Vulkan's value.
            Param::Value if p.type_name == "VkBool32" => {
                bools.push(name.to_string());
                args.push(Arg::new(&name, quote!(bool)));
                pre.push(quote!(let #name = vk::Bool32::from(#name);));
                call_args.push(quote!(#name,));
            }
            Param::Value => {
                let ty = spelled(model, &cx.facts, &p.type_name);
                args.push(Arg::new(&name, quote!(#ty)));
                call_args.push(quote!(#name,));
            }
            Param::Array => {
                let ty = spelled(model, &cx.facts, &p.type_name);
                let n = crate::plan::types::array_size(p.static_array.as_deref().unwrap_or("1"));
                args.push(Arg::new(&name, quote!(&[#ty; #n])));
                call_args.push(quote!(#name,));
            }
            Param::Handle { optional } => {
                let w = type_ident(&p.type_name);
                if *optional {
                    {
                        args.push(Arg::new(&name, quote!(Option<&#w>)));
                        call_args.push(quote!(#name.map_or(vk::#w::null(), |h| h.raw()),));
                        if is_cmd {
                            retain.push(
                                quote!(if let Some(h) = #name { self.retain_with(h.address(), || h.retained()); }),
                            );
                        }
                        continue;
                    }
                }
                args.push(Arg::new(&name, quote!(&#w)));
                call_args.push(quote!(#name.raw(),));
                if is_cmd {
                    retain.push(quote!(self.retain_with(#name.address(), || #name.retained());));
                }
            }
            Param::HandleSlice => {
                let w = type_ident(&p.type_name);
                args.push(Arg::new(&name, quote!(&[&#w])));
                if is_cmd {
                    pre.push(quote!(for h in #name { self.retain(h.retained()); }));
                    uses_recorder = true;
                }
                let given = given_ident(&name);
                call_args.push(quote!(crate::Handles::raws(#given).as_ptr(),));
                handle_arrays.push((name.clone(), w));
            }
            Param::NumberRef { optional } => {
                lifetimes = true;
                let ty = spelled(model, &cx.facts, &p.type_name);
                if *optional {
                    args.push(Arg::new(&name, quote!(Option<&#ty>)));
                    call_args.push(
                        quote!(#name.map_or(core::ptr::null(), |s| s as *const #ty as *const _),),
                    );
                } else {
                    args.push(Arg::new(&name, quote!(&#ty)));
                    call_args.push(quote!(#name as *const #ty as *const _,));
                }
            }
            Param::StructRef { optional } => {
                lifetimes = true;
                let ty = safe_or_ash(cx, &p.type_name);
                let is_override = pool_override
                    .as_ref()
                    .is_some_and(|(pn, m)| pn == &p.name && m.is_some());
                if *optional {
                    args.push(Arg::new(&name, quote!(Option<&#ty>)));
                    call_args.push(
                        quote!(#name.map_or(core::ptr::null(), |s| s as *const #ty as *const _),),
                    );
                } else if let Some(Keeps::Member(member, kept_ty)) = special.map(|s| s.keeps) {
                    let kept_name = ident(&param(member));
                    let member = field_ident(member);
                    let kept_w = type_ident(kept_ty);
                    args.push(Arg::new(&kept_name, quote!(&#kept_w)));
                    args.push(Arg::new(&name, quote!(&#ty)));
                    pre.push(quote! {
                        // Taken as a wrapper and written into the info, so the created
                        // object can keep it alive.
                        let mut #name = *#name;
                        #name.as_raw_mut().#member = #kept_name.raw();
                        let #name = &#name;
                    });
                    call_args.push(quote!(#name.as_raw(),));
                } else if is_override {
                    let (_, member) = pool_override.clone().unwrap_or_default();
                    let member = field_ident(&member.unwrap_or_default());
                    let parent_w = type_ident(&created_parent);
                    let parent_name = ident(&param(created_parent.trim_start_matches("Vk")));
                    args.push(Arg::new(&parent_name, quote!(&#parent_w)));
                    args.push(Arg::new(&name, quote!(&#ty)));
                    pre.push(quote! {
                        // The parent is taken as a wrapper and written into the info, so
                        // the created objects can hold it.
                        let mut #name = *#name;
                        #name.as_raw_mut().#member = #parent_name.raw();
                        let #name = &#name;
                    });
                    call_args.push(quote!(#name.as_raw(),));
                } else {
                    args.push(Arg::new(&name, quote!(&#ty)));
                    call_args.push(quote!(#name as *const #ty as *const _,));
                    if is_cmd {
                        retain.extend(struct_retains(cx, p, &name, false));
                    }
                }
            }
            Param::Slice => {
                lifetimes = true;
                let ty = if model.category(&p.type_name) == Some(Kind::Struct) {
                    safe_or_ash(cx, &p.type_name)
                } else {
                    spelled(model, &cx.facts, &p.type_name)
                };
                args.push(Arg::new(&name, quote!(&[#ty])));
                if optional_same_len(plan, &p.name) {
                    // An empty optional slice is NULL, not a dangling pointer.
                    call_args.push(quote!(if #name.is_empty() { core::ptr::null() } else { #name.as_ptr().cast() },));
                } else {
                    call_args.push(quote!(#name.as_ptr().cast(),));
                }
                if is_cmd {
                    retain.extend(struct_retains(cx, p, &name, true));
                }
            }
            Param::Bytes => {
                args.push(Arg::new(&name, quote!(&[u8])));
                call_args.push(quote!(#name.as_ptr().cast(),));
            }
            Param::RawData => {
                args.push(Arg::new(&name, quote!(*const core::ffi::c_void)));
                call_args.push(quote!(#name,));
            }
            Param::SliceOfSlices => {
                lifetimes = true;
                let ty = spelled(model, &cx.facts, &p.type_name);
                let ptrs = ident(&format!("{name}_ptrs"));
                args.push(Arg::new(&name, quote!(&[&[#ty]])));
                pre.push(quote! {
                    let #ptrs: smallvec::SmallVec<[*const #ty; 4]> =
                        #name.iter().map(|s| s.as_ptr()).collect();
                });
                call_args.push(quote!(#ptrs.as_ptr(),));
            }
            Param::SliceOut => {
                let ty = spelled(model, &cx.facts, &p.type_name);
                args.push(Arg::new(&name, quote!(&mut [#ty])));
                call_args.push(quote!(#name.as_mut_ptr(),));
            }
            Param::BytesOut | Param::BytesOutUnsized => {
                args.push(Arg::new(&name, quote!(&mut [u8])));
                call_args.push(quote!(#name.as_mut_ptr().cast(),));
            }
            Param::CStr { optional: true } => {
                args.push(Arg::new(&name, quote!(Option<&core::ffi::CStr>)));
                call_args.push(quote!(#name.map_or(core::ptr::null(), |s| s.as_ptr()),));
            }
            Param::CStr { optional: false } => {
                args.push(Arg::new(&name, quote!(&core::ffi::CStr)));
                call_args.push(quote!(#name.as_ptr(),));
            }
            Param::InOut => {
                lifetimes = true;
                let ty = safe_or_ash(cx, &p.type_name);
                args.push(Arg::new(&name, quote!(&mut #ty)));
                call_args.push(quote!(#name as *mut #ty as *mut _,));
            }
            Param::Output | Param::ForeignOutput => {
                let ty = spelled(model, &cx.facts, &p.type_name);
                let ty = if cx.facts.has_lifetime(&p.type_name) {
                    let id = type_ident(&p.type_name);
                    quote!(vk::#id<'static>)
                } else {
                    ty
                };
                // A pointer typedef (`VkRemoteAddressNV`, `void*`) is spelled by ash
                // without its pointer, so the output is a pointer to it, written
                // through the `void**` the command takes.
                let pointer_typedef = model
                    .types
                    .get(&p.type_name)
                    .is_some_and(|t| t.category == Some(Kind::Basetype) && t.code.contains('*'));
                let ty = if pointer_typedef || p.pointers == 2 {
                    pre.push(quote!(let mut out: *mut #ty = core::ptr::null_mut();));
                    call_args.push(quote!(core::ptr::addr_of_mut!(out).cast(),));
                    quote!(*mut #ty)
                } else if matches!(shape, Param::ForeignOutput) {
                    // ash spells these as the C typedefs (`*mut c_void`, `u32`), some
                    // without `Default`.
                    pre.push(quote! {
                        __safety!("a window-system value is a C integer or pointer, for which all-zero bytes are a value.");
                        let mut out: #ty = unsafe { core::mem::zeroed() };
                    });
                    call_args.push(quote!(&mut out,));
                    ty
                } else {
                    pre.push(quote!(let mut out: #ty = Default::default();));
                    call_args.push(quote!(&mut out,));
                    ty
                };
                // `bool` where Vulkan writes a `VkBool32`, as for inputs.
                has_value = true;
                (ret_ty, ret_expr) = match p.type_name.as_str() {
                    "VkBool32" => (quote!(bool), quote!(out != vk::FALSE)),
                    _ => (ty, quote!(out)),
                };
            }
            Param::Created | Param::CreatedArray => {
                let w = type_ident(&p.type_name);
                let parent_expr = if created_parent == plan.receiver {
                    quote!(self)
                } else {
                    let parent_name = match &pool_override {
                        Some((pn, None)) => ident(&param(pn)),
                        _ => ident(&param(created_parent.trim_start_matches("Vk"))),
                    };
                    quote!(#parent_name)
                };
                let parent_arg = if p.type_name == "VkInstance" || p.type_name == "VkDevice" {
                    quote!()
                } else {
                    quote!(#parent_expr,)
                };
                if matches!(shape, Param::Created) {
                    pre.push(quote!(let mut out = vk::#w::null();));
                    call_args.push(quote!(&mut out,));
                    has_value = true;
                    ret_ty = quote!(#w);
                    ret_expr = match special.map_or(Keeps::Reached, |s| s.keeps) {
                        Keeps::Member(member, _) => {
                            let kept_name = ident(&param(member));
                            quote!(#w::from_raw(out, #parent_arg Some(#kept_name.retained()), true))
                        }
                        Keeps::Nothing => quote!(#w::from_raw(out, #parent_arg None, true)),
                        Keeps::Reached => {
                            let keep = info_param
                                .as_ref()
                                .filter(|_| lvl == Level::Device)
                                .and_then(|(info, ty)| {
                                    keep_expr(
                                        cx,
                                        ty,
                                        info,
                                        &created_parent,
                                        override_member,
                                        &device_path,
                                    )
                                })
                                .unwrap_or(quote!(None));
                            quote!(#w::from_raw(out, #parent_arg #keep, true))
                        }
                    };
                } else {
                    let count = match p.parsed.len.first() {
                        Some(LenEntry::Reference(parts)) if parts.len() == 2 => {
                            let s = ident(&param(&parts[0]));
                            let m = field_ident(&parts[1]);
                            quote!(#s.as_raw().#m as usize)
                        }
                        Some(LenEntry::Reference(parts)) => {
                            // The length of an input array.
                            let arr = cmd
                                .params
                                .iter()
                                .find(|q| {
                                    q.parsed
                                        .len
                                        .first()
                                        .and_then(|l| l.other_param().map(str::to_owned))
                                        == Some(parts[0].clone())
                                        && q.name != p.name
                                })
                                .map(|q| ident(&param(&q.name)));
                            match arr {
                                Some(a) => quote!(#a.len()),
                                None => quote!(0usize),
                            }
                        }
                        _ => quote!(0usize),
                    };
                    pre.push(quote!(let mut out = vec![vk::#w::null(); #count];));
                    call_args.push(quote!(out.as_mut_ptr(),));
                    has_value = true;
                    ret_ty = quote!(Vec<#w>);
                    // One create info per created object (pipelines): each keeps what
                    // its own info names.
                    let per_info = infos_param
                        .as_ref()
                        .filter(|_| lvl == Level::Device)
                        .and_then(|(infos, ty)| {
                            keep_expr(cx, ty, &quote!(info), &created_parent, None, &device_path)
                                .map(|k| (infos, k))
                        });
                    ret_expr = match per_info {
                        Some((infos, keep)) => {
                            quote!(out.into_iter().zip(#infos.iter()).map(|(raw, info)| #w::from_raw(raw, #parent_arg #keep, true)).collect())
                        }
                        None => {
                            quote!(out.into_iter().map(|raw| #w::from_raw(raw, #parent_arg None, true)).collect())
                        }
                    };
                }
            }
            Param::EnumCount => {
                call_args.push(quote!(count,));
            }
            Param::Enumerated => {
                let elem_is_handle = model.category(&p.type_name) == Some(Kind::Handle);
                let elem = if p.type_name == "void" {
                    quote!(u8)
                } else if elem_is_handle {
                    let id = type_ident(&p.type_name);
                    quote!(vk::#id)
                } else if cx.facts.has_lifetime(&p.type_name) {
                    let id = type_ident(&p.type_name);
                    quote!(vk::#id<'static>)
                } else {
                    spelled(model, &cx.facts, &p.type_name)
                };
                // A second array of the same count (`pCounterDescriptions`)
                // comes back beside the first.
                if two_call.is_some() {
                    call_args.push(quote!(others_ptr.cast(),));
                    let first = ret_ty.clone();
                    ret_ty = quote!((#first, Vec<#elem>));
                    second = Some(elem);
                    continue;
                }
                call_args.push(quote!(items_ptr.cast(),));
                two_call = Some(elem.clone());
                if elem_is_handle {
                    // Images of a swapchain: owned by it, kept alive with it.
                    let w = type_ident(&p.type_name);
                    let keep = cmd
                        .params
                        .iter()
                        .find(|q| {
                            q.type_name != p.type_name
                                && model.category(&q.type_name) == Some(Kind::Handle)
                                && q.pointers == 0
                                && !model.types[&q.type_name].dispatchable
                        })
                        .map(|q| ident(&param(&q.name)));
                    let keep = match keep {
                        Some(k) => quote!(Some(#k.retained())),
                        None => quote!(None),
                    };
                    has_value = true;
                    ret_ty = quote!(Vec<#w>);
                    ret_expr = quote!(items.into_iter().map(|raw| #w::from_raw(raw, self, #keep, false)).collect());
                } else {
                    has_value = true;
                    items_as_is = true;
                    ret_ty = quote!(Vec<#elem>);
                    ret_expr = quote!(items);
                }
            }
        }
    }
    if let Some(sp) = special {
        pre.extend(sp.before.as_ref().map(special_stmt));
        post.extend(sp.after.as_ref().map(special_stmt));
        uses_recorder |= [&sp.before, &sp.after]
            .into_iter()
            .flatten()
            .any(|c| c.args.contains(&"&mut self"));
        if let Some(c) = sp.created {
            ret_expr = special_call(&c, &ret_expr);
            items_as_is = false;
        }
    }
    // A command that moves the recorder to another state hands on a new one, which
    // checks again anyway.
    if plan.changes_draw_state
        && !matches!(
            plan.transition,
            Some(Transition::Begin(_) | Transition::End(_))
        )
    {
        post.push(quote!(self.state_changed();));
    }
    let fp = quote!(fp);
    let status = all.status_of(&plan.name).map(|s| ident(&s.name));
    let count_ty = cmd
        .params
        .iter()
        .zip(&plan.params)
        .find(|(_, s)| matches!(s, Param::EnumCount))
        .and_then(|(p, _)| ash_type(model, &cx.facts, &p.type_name))
        .unwrap_or(quote!(u32));
    let body = if let Some(elem) = &two_call {
        let call = if cmd.return_type == "VkResult" {
            quote!(#fp(#(#call_args)*))
        } else {
            quote!({
                #fp(#(#call_args)*);
                vk::Result::SUCCESS
            })
        };
        let safety = super::safety(
            "`two_call` hands the command its count and array; other arguments as for any call.",
        );
        let enumerate = match &second {
            None => quote! {
                unsafe {
                    crate::support::two_call(|count: &mut #count_ty, items_ptr: *mut #elem| #call)
                }
            },
            Some(other) => quote! {
                unsafe {
                    crate::support::two_call_pair(
                        |count: &mut #count_ty, items_ptr: *mut #elem, others_ptr: *mut #other| #call,
                    )
                }
            },
        };
        if items_as_is {
            quote!(#(#pre)* #safety #enumerate)
        } else {
            quote! {
                #(#pre)*
                #safety
                let items = #enumerate?;
                Ok(#ret_expr)
            }
        }
    } else if cmd.return_type == "VkResult" {
        // A creation that lacks a layer, extension or feature names what it lacks.
        let error = match special.and_then(|s| s.error) {
            Some(c) => special_call(&c, &ret_expr),
            None => quote!(Error::Vk(r)),
        };
        // A code outside the command's success codes is the driver's error; what
        // the call made is still retained above, and dropped with the error.
        let ok = match &status {
            Some(s) if !has_value => {
                // Nothing else to return: the status alone (`Suboptimal`, say).
                ret_ty = quote!(crate::status::#s);
                quote!(crate::status::#s::from_code(r).ok_or(Error::Vk(r)))
            }
            Some(s) => {
                ret_ty = quote!((#ret_ty, crate::status::#s));
                quote! {
                    let status = crate::status::#s::from_code(r).ok_or(Error::Vk(r))?;
                    Ok((#ret_expr, status))
                }
            }
            None => quote!(Ok(#ret_expr)),
        };
        has_value |= status.is_some();
        quote! {
            #(#pre)*
            __safety!("live wrappers' handles, borrowed pointers and counts (module docs).");
            let r = unsafe { #fp(#(#call_args)*) };
            if r.as_raw() < 0 {
                return Err(#error);
            }
            #(#post)*
            #(#retain)*
            #ok
        }
    } else if cmd.return_type == "void" {
        // A unit result is left out, as hand-written code would.
        let unit_free_ret = has_value.then_some(&ret_expr);
        quote! {
            #(#pre)*
            __safety!("live wrappers' handles, borrowed pointers and counts (module docs).");
            unsafe { #fp(#(#call_args)*) };
            #(#post)*
            #(#retain)*
            #unit_free_ret
        }
    } else {
        // `bool` where Vulkan returns a `VkBool32`.
        let (rt, value) = match cmd.return_type.as_str() {
            "VkBool32" => (quote!(bool), quote!(r != vk::FALSE)),
            t => (spelled(model, &cx.facts, t), quote!(r)),
        };
        ret_ty = rt;
        has_value = true;
        quote! {
            #(#pre)*
            __safety!("live wrappers' handles, borrowed pointers and counts (module docs).");
            let r = unsafe { #fp(#(#call_args)*) };
            #(#retain)*
            #value
        }
    };
    // Nothing kept after the call: its value is the body's.
    let body = if retain.is_empty()
        && matches!(cmd.return_type.as_str(), t if t != "VkResult" && t != "void" && t != "VkBool32")
        && two_call.is_none()
    {
        quote! {
            #(#pre)*
            __safety!("live wrappers' handles, borrowed pointers and counts (module docs).");
            unsafe { #fp(#(#call_args)*) }
        }
    } else {
        body
    };
    if two_call.is_some() {
        fallible = true;
    }
    let ret = if fallible {
        quote!(Result<#ret_ty>)
    } else {
        quote!(#ret_ty)
    };
    let host_sync = super::sync::host_syncs(cx, plan);
    // The handle arrays as slices of wrappers, before anything reads them; the
    // argument itself stays for the raw handles (and the checked method's call).
    let as_slices = handle_arrays.iter().map(|(name, _)| {
        let given = given_ident(name);
        quote!(let #given = #name; #[allow(unused_variables)] let #name = crate::Handles::wrappers(&#given);)
    });
    let as_slices = quote!(#(#as_slices)*);
    let body = if fallible && cmd.return_type != "VkResult" && two_call.is_none() {
        if !has_value {
            // A unit result is not passed through `Ok(..)`.
            quote!(#as_slices #host_sync #load_fp { #body } Ok(()))
        } else {
            quote!(#as_slices #host_sync #load_fp Ok({ #body }))
        }
    } else {
        quote!(#as_slices #host_sync #load_fp #body)
    };
    // The methods' parameters: a handle array as `impl Handles`, where the body and
    // the checks see the slice `args` names.
    let inner_args = args.clone();
    let args: Vec<Arg> = args
        .into_iter()
        .map(|a| match handle_arrays.iter().find(|(n, _)| *n == a.name) {
            Some((name, w)) => Arg::new(name, quote!(impl crate::Handles<'h, #w>)),
            None => a,
        })
        .collect();
    // `'a` is declared only where a parameter or the result names it.
    let names_lt_a = lifetimes && (args.iter().any(|a| names_a(&a.ty)) || names_a(&ret));
    let lt = match (names_lt_a, handle_arrays.is_empty()) {
        (true, true) => quote!(<'a>),
        (true, false) => quote!(<'a, 'h>),
        (false, false) => quote!(<'h>),
        (false, true) => quote!(),
    };
    let mut self_ref = if plan.receiver == "VkCommandBuffer" {
        quote!(&mut self)
    } else {
        quote!(&self)
    };
    // The state a transition leaves the recorder in, which the method returns.
    let transition = match plan.transition {
        Some(Transition::Begin(to)) => Some(ident(to.type_name())),
        Some(Transition::End(_)) => Some(ident(RecorderState::Outside.type_name())),
        Some(Transition::Within(_)) | None => None,
    };
    // Nothing returned at all, not even a `Result` or the next recorder.
    let returns_unit = !has_value && !fallible && transition.is_none();
    let (ret, body) = match &transition {
        Some(state) => {
            self_ref = quote!(mut self);
            (
                quote!(Recorder<'c, #state>),
                quote!(#body; self.into_state()),
            )
        }
        None => (ret, body),
    };
    let raw_of = |which: fn(&Param) -> bool| -> Vec<String> {
        cmd.params
            .iter()
            .zip(&plan.params)
            .filter(|(_, s)| which(s))
            .map(|(p, _)| format!("`{}`", param(&p.name)))
            .collect()
    };
    let raw_data = raw_of(|s| matches!(s, Param::RawData));
    let raw = raw_of(|s| matches!(s, Param::Raw));
    let contract = special.and_then(|s| s.contract);
    let mut promises: Vec<String> = Vec::new();
    if !raw_data.is_empty() {
        promises.push(format!(
            "{} is passed to Vulkan as is: it must point to data laid out as the specification of `{}` describes, readable for the whole call.",
            raw_data.join(", "),
            plan.name
        ));
    }
    if !raw.is_empty() {
        promises.push(format!(
            "{} {} passed to Vulkan as ash's raw type: each must be what the specification of `{}` requires of it (a valid pointer to as many elements as it says, a live window-system object or handle), for the whole call.",
            raw.join(", "),
            if raw.len() == 1 { "is" } else { "are" },
            plan.name
        ));
    }
    if !plan.unlocked.is_empty() {
        let paths: Vec<String> = plan.unlocked.iter().map(|p| format!("`{p}`")).collect();
        promises.push(format!(
            "The wrappers cannot lock {}, which `{}` needs externally synchronized: no other thread may use {} during the call.",
            paths.join(", "),
            plan.name,
            if paths.len() == 1 { "it" } else { "them" }
        ));
    }
    promises.extend(contract.map(str::to_owned));
    let (unsafe_kw, safety) = match promises.is_empty() {
        true => (quote!(), String::new()),
        false => (
            quote!(unsafe),
            format!("\n\n# Safety\n\n{}", promises.join(" ")),
        ),
    };
    // Rules that apply, that no check enforces and no reviewed class covers make the
    // method `unsafe`; its docs list them (`plan/safety.rs`).
    let owned = all
        .safety
        .get(&plan.name)
        .map_or(&[][..], |m| m.owned.as_slice());
    let unsafe_kw = if owned.is_empty() {
        unsafe_kw
    } else {
        quote!(unsafe)
    };
    let owned_doc = owned_rules_doc(&plan.name, owned, safety.is_empty());
    // No `-> ()`: a unit return is left out, as hand-written code would.
    let ret_arrow = if returns_unit {
        quote!()
    } else {
        quote!(-> #ret)
    };
    let example = super::example_doc(
        cx,
        &f.to_string(),
        Some(crate::names::receiver_type(model, &plan.name)),
        "Called",
    );
    // Where the deferred operation went: the method runs the command to completion.
    let not_deferred = if plan.params.contains(&Param::NotDeferred) {
        "\n\nThe command completes before the method returns: the method passes no \
         deferred operation (`deferredOperation` is `VK_NULL_HANDLE`), as what it lends \
         Vulkan lives only for the call."
    } else {
        ""
    };
    let doc = format!(
        "`{}`{not_deferred}{safety}{owned_doc}{example}{}",
        plan.name,
        super::doc_rules(all, &plan.name)
    );
    // Search finds the method by its Vulkan name.
    let alias = model.spelling(&plan.name).to_owned();
    let checks = checker.command_checks(plan);
    let always = special.and_then(|s| s.check);
    let last = special.and_then(|s| s.check_last);
    let mut validator = None;
    let held = special.and_then(|s| s.hold);
    let method = if checks.is_empty()
        && always.is_none()
        && last.is_none()
        && held.is_none()
        && same_len.is_empty()
    {
        quote! {
            #[doc = #doc]
            #[doc(alias = #alias)]
            #[inline]
            pub #unsafe_kw fn #f #lt(#self_ref, #(#args),*) #ret_arrow {
                #body
            }
        }
    } else {
        let unchecked = ident(&format!("{}_unchecked", f));
        let names: Vec<&Ident> = args.iter().map(|a| &a.name).collect();
        // The `_unchecked` twin takes the handle arrays as they were given.
        let call_names: Vec<Ident> = names
            .iter()
            .map(|n| match handle_arrays.iter().any(|(h, _)| h == *n) {
                true => given_ident(n),
                false => (*n).clone(),
            })
            .collect();
        let scope = scope_expr(cx, plan, &device_path);
        // Where handles come from is asked before the special case's check, which
        // may read records or ask the driver about them; the other checks run after.
        let (first, rest): (Vec<&Check>, Vec<&Check>) = match always {
            Some(_) => checks.iter().partition(|c| c.is_ownership()),
            None => (Vec::new(), checks.iter().collect()),
        };
        let checks = rest;
        // A transition's special check joins its other checks' result, which the
        // recorder keeps.
        let moves = plan.transition.is_some();
        // A transition's last check joins its other checks' result too (the recorder
        // keeps it); any other command returns its error.
        let last_call = last.map(|c| special_call(&c, &ret_expr));
        let last_code = match (&last_call, moves) {
            (Some(c), false) => Some(quote!(#c?;)),
            _ => None,
        };
        let last_join = match (&last_call, moves) {
            (Some(c), true) => quote!(.and_then(|()| #c)),
            _ => quote!(),
        };
        let hold_code = special.and_then(|s| s.hold).map(|c| {
            let c = special_call(&c, &ret_expr);
            quote!(let _held = #c?;)
        });
        // The hazard tracker's declaration of the command's accesses comes last, once
        // every other check has passed: what it records is what the call does. A
        // transition's joins its other checks' result (the recorder keeps it).
        let hazard = crate::plan::accesses::row(&plan.name)
            .filter(|_| model.sync.is_some())
            .map(|row| super::sync_tables::call(row, transition.is_some()));
        let hazard_join = match (&hazard, moves) {
            (Some(c), true) => quote!(.and_then(|()| #c)),
            _ => quote!(),
        };
        let last_join = quote!(#last_join #hazard_join);
        let always_vuids = special
            .filter(|s| s.check.is_some() || s.check_last.is_some() || s.hold.is_some())
            .map_or(&[][..], |s| s.settles);
        let same_len_vuids: Vec<String> = plan
            .same_len
            .iter()
            .map(|s| same_len_vuid(plan, s))
            .collect();
        let owned: Vec<String> = first
            .iter()
            .chain(&checks)
            .filter_map(|c| c.vuid.as_deref())
            .chain(always_vuids.iter().map(|(v, _)| *v))
            .chain(same_len_vuids.iter().map(String::as_str))
            .map(|v| format!("`{v}`"))
            .collect();
        let unchecked_doc = format!(
            "`{}` without its dynamic checks.\n\n# Safety\n\nThe caller upholds the rules that [`Self::{}`] checks at run time{}.",
            plan.name,
            f,
            if owned.is_empty() {
                " (those of the structs it takes)".to_owned()
            } else {
                format!(": {}, and those of the structs it takes", owned.join(", "))
            }
        ) + &safety.replace("\n\n# Safety\n\n", " ")
            + if owned.is_empty() {
                ""
            } else {
                " So does every rule the `# Safety` section of the checked method lists."
            };
        // The checks are named methods beside the command's, each taking only the
        // arguments its checks read: where handles come from, when the special
        // case's check runs between, and the rest.
        let is_bool = |n: &Ident| bools.contains(&n.to_string());
        let validator_of = |name: &Ident, checks: &[&Check], doc: &str| {
            // The scope is bound only when a check reads it.
            let bind_scope = checks
                .iter()
                .any(|c| c.uses_scope())
                .then(|| quote!(let s = &#scope;));
            let read: Vec<&Arg> = inner_args
                .iter()
                .filter(|a| {
                    checks
                        .iter()
                        .any(|c| c.reads().contains(&a.name.to_string()))
                })
                .collect();
            // The checks compare Vulkan's values: a `bool` argument reaches them as
            // the `VkBool32` the command passes on.
            let v_args = read.iter().map(|a| match is_bool(&a.name) {
                true => Arg::new(&a.name, quote!(vk::Bool32)).into_token_stream(),
                false => a.into_token_stream(),
            });
            let v_names: Vec<TokenStream> = read
                .iter()
                .map(|a| {
                    let n = &a.name;
                    match is_bool(n) {
                        true => quote!(vk::Bool32::from(#n)),
                        false => quote!(#n),
                    }
                })
                .collect();
            // The checks see handle arrays as slices, so only `'a` can be theirs.
            let v_lt = read.iter().any(|a| names_a(&a.ty)).then(|| quote!(<'a>));
            let codes = checks.iter().copied().map(super::checks::render);
            let method = quote! {
                #[doc = #doc]
                pub(crate) fn #name #v_lt(&self, #(#v_args),*) -> Result<()> {
                    #bind_scope
                    #(#codes)*
                    Ok(())
                }
            };
            (method, quote!(self.#name(#(#v_names),*)))
        };
        let validate = ident(&format!("validate_{}", f));
        let v_doc = format!(
            "The dynamic checks of [`Self::{}`], run before the call.",
            f
        );
        let (rest_method, rest_call) = validator_of(&validate, &checks, &v_doc);
        let origins = (!first.is_empty()).then(|| {
            let name = ident(&format!("validate_origins_{}", f));
            let doc = format!(
                "Where the handles [`Self::{}`] names come from, checked before its special case's check.",
                f
            );
            validator_of(&name, &first, &doc)
        });
        validator = match (&origins, checks.is_empty()) {
            (Some((o, _)), true) => Some(o.clone()),
            (Some((o, _)), false) => Some(quote!(#o #rest_method)),
            (None, false) => Some(rest_method),
            (None, true) => None,
        };
        let always_code = always.map(|c| {
            let c = special_call(&c, &ret_expr);
            match (moves, origins.as_ref().map(|(_, call)| call)) {
                (true, Some(o)) => quote!(let always: Result<()> = #o.and_then(|()| #c);),
                (true, None) => quote!(let always: Result<()> = #c;),
                (false, Some(o)) => quote!(#o?; #c?;),
                (false, None) => quote!(#c?;),
            }
        });
        let always_code = quote!(#(#same_len)* #always_code);
        let run = if moves && always.is_some() {
            quote! {
                let r = always.and_then(|()| #rest_call) #last_join;
            }
        } else {
            quote! {
                let r = #rest_call #last_join;
            }
        };
        let (ret_checked, guard, call) = match (&transition, is_cmd) {
            (Some(state), _) => {
                let begins = matches!(plan.transition, Some(Transition::Begin(_)));
                let guard = if begins {
                    quote!(if !self.accept(r) { self.skip_begin(true); return self.into_state(); } self.skip_begin(false);)
                } else {
                    quote!(let _ = self.accept(r); if self.begin_skipped() { return self.into_state(); })
                };
                (
                    quote!(Recorder<'c, #state>),
                    guard,
                    quote!(unsafe { self.#unchecked(#(#call_names),*) }),
                )
            }
            (None, true) if !fallible => {
                // A refused next subpass is not recorded (the recorder is poisoned, and
                // its end stays valid); one after another refusal is, so that the end
                // comes in the last subpass.
                let guard = if matches!(plan.transition, Some(Transition::Within(_))) {
                    quote!(if r.is_err() { let _ = self.accept(r); return; } if self.begin_skipped() { return; })
                } else {
                    quote!(if !self.accept(r) {
                        return;
                    })
                };
                (
                    ret.clone(),
                    guard,
                    quote!(unsafe { self.#unchecked(#(#call_names),*) }),
                )
            }
            _ => {
                let call = if fallible {
                    quote!(unsafe { self.#unchecked(#(#call_names),*) })
                } else if returns_unit {
                    quote!(unsafe { self.#unchecked(#(#call_names),*) }; Ok(()))
                } else {
                    quote!(Ok(unsafe { self.#unchecked(#(#call_names),*) }))
                };
                let ret_checked = if fallible {
                    ret.clone()
                } else {
                    quote!(Result<#ret>)
                };
                (ret_checked, quote!(r?;), call)
            }
        };
        let hazard_code = match (&hazard, moves) {
            (Some(c), false) if is_cmd && !fallible && transition.is_none() => {
                Some(quote!(if !self.accept(#c) { return; }))
            }
            (Some(c), false) => Some(quote!(#c?;)),
            _ => None,
        };
        // A transition that keeps nothing (the ends of a render pass) does not
        // change the recorder it consumes before handing it on.
        let unchecked_self = if transition.is_some() && !uses_recorder && retain.is_empty() {
            quote!(self)
        } else {
            self_ref.clone()
        };
        // Only a recorded command's checks poison the recorder rather than return
        // an error, so only it can return nothing.
        let checked_arrow = if is_cmd && returns_unit {
            quote!()
        } else {
            quote!(-> #ret_checked)
        };
        // Only commands with implicit checks get the block that runs them.
        let implicit_block = (!checks.is_empty()).then(|| {
            quote! {
                {
                    #run
                    #guard
                }
            }
        });
        quote! {
            #[doc = #doc]
            #[doc(alias = #alias)]
            #[inline]
            pub #unsafe_kw fn #f #lt(#self_ref, #(#args),*) #checked_arrow {
                #as_slices
                // Held across the checks too, so what they saw holds at the call.
                #host_sync
                // The special cases' checks first: each refuses a call that would
                // break memory safety, whatever else is wrong with it.
                #always_code
                #implicit_block
                // Checks that query the driver with the values, once they are valid.
                #last_code
                #hold_code
                #hazard_code
                __safety!("the rules the checks above settle hold; the others are the caller's (see the docs).");
                #call
            }
            #[doc = #unchecked_doc]
            #[inline]
            pub unsafe fn #unchecked #lt(#unchecked_self, #(#args),*) #ret_arrow {
                #body
            }
        }
    };
    (impl_header(plan, cmd, &cfg), method, validator)
}

/// The name a handle array's argument keeps once `name` is its slice of wrappers.
/// A method parameter: its name, and the type the method takes it as.
#[derive(Clone)]
struct Arg {
    name: Ident,
    ty: TokenStream,
}

impl Arg {
    fn new(name: &Ident, ty: TokenStream) -> Arg {
        Arg {
            name: name.clone(),
            ty,
        }
    }
}

impl ToTokens for Arg {
    fn to_tokens(&self, out: &mut TokenStream) {
        let (name, ty) = (&self.name, &self.ty);
        out.extend(quote!(#name: #ty));
    }
}

fn given_ident(name: &proc_macro2::Ident) -> proc_macro2::Ident {
    ident(&format!("{name}_given"))
}

/// The `# Safety` text of a method whose caller owns `owned` (empty when it owns
/// none), with the section's heading when `heading` says no other text gave it one.
fn owned_rules_doc(command: &str, owned: &[crate::plan::safety::Owned], heading: bool) -> String {
    if owned.is_empty() {
        return String::new();
    }
    let mut s = String::from(if heading { "\n\n# Safety\n\n" } else { "\n\n" });
    // An indirect command reads its arguments from GPU memory when it executes.
    let read = crate::plan::special::INDIRECT
        .iter()
        .find(|(c, _)| *c == command)
        .map(|(_, read)| *read);
    if let Some(read) = read.filter(|r| {
        owned
            .iter()
            .any(|o| o.vuid.starts_with(&format!("VUID-{r}-")))
    }) {
        s.push_str(&format!(
            "The `{read}` arguments it reads from the buffer live in GPU memory, which tuff cannot read when the command is recorded: their rules are the caller's. "
        ));
        if let Some(form) = crate::plan::special::indirect::form(command) {
            s.push_str(&format!(
                "Its safe form, [`Self::{}`], reads them from an [`IndirectBuffer`](crate::IndirectBuffer) that only the host writes, and checks them. ",
                form.method
            ));
        }
    }
    s.push_str(&format!(
        "The caller upholds {} that no check of this method enforces (its command's and those of the structs it takes):\n",
        if owned.len() == 1 { "the rule".to_owned() } else { format!("these {} rules", owned.len()) }
    ));
    for o in owned {
        s.push_str(&format!("\n- `{}`: {}", o.vuid, super::doc_escape(&o.text)));
    }
    s
}

/// Whether a parameter or result type names the lifetime `'a`, which the method
/// then declares.
fn names_a(t: &TokenStream) -> bool {
    t.to_string().contains("'a")
}

/// The `impl` block header a command's methods go in: its receiver (a recorder in the
/// states the command is allowed in, for recorded commands), under its `cfg`.
fn impl_header(plan: &Plan, cmd: &CommandDef, cfg: &Option<TokenStream>) -> TokenStream {
    match plan.receiver.as_str() {
        "Entry" => quote!(#cfg impl Entry),
        "VkCommandBuffer" if recorded(plan) => {
            let state = match (plan.transition, cmd.renderpass.as_deref()) {
                (Some(Transition::End(from) | Transition::Within(from)), _) => {
                    let from = ident(from.type_name());
                    quote!(impl<'c> Recorder<'c, #from>)
                }
                // A video coding scope is never inside a render pass instance: its
                // state is a fourth one, and the command's two attributes together
                // pick the states that have it.
                (_, renderpass) => match (renderpass, cmd.videocoding.as_deref()) {
                    (Some("inside"), _) => quote!(impl<'c, S: Inside> Recorder<'c, S>),
                    (Some("outside"), Some("inside")) => {
                        quote!(impl<'c> Recorder<'c, InVideoCoding>)
                    }
                    (Some("outside"), Some("both")) => {
                        quote!(impl<'c, S: OutsideRenderPass> Recorder<'c, S>)
                    }
                    (Some("outside"), _) => quote!(impl<'c> Recorder<'c, Outside>),
                    (_, Some("inside")) => quote!(impl<'c> Recorder<'c, InVideoCoding>),
                    (_, Some("both")) => quote!(impl<'c, S: Scope> Recorder<'c, S>),
                    _ => quote!(impl<'c, S: State> Recorder<'c, S>),
                },
            };
            quote!(#cfg #state)
        }
        r => {
            let w = type_ident(r);
            quote!(#cfg impl #w)
        }
    }
}

/// Items grouped into one `impl` block per header, in the order headers first appear.
#[derive(Default)]
struct ImplBlocks(Vec<(String, TokenStream, Vec<TokenStream>)>);

impl ImplBlocks {
    fn push(&mut self, header: TokenStream, item: TokenStream) {
        let key = header.to_string();
        match self.0.iter_mut().find(|(k, _, _)| *k == key) {
            Some((_, _, items)) => items.push(item),
            None => self.0.push((key, header, vec![item])),
        }
    }

    fn render(self) -> impl Iterator<Item = TokenStream> {
        self.0
            .into_iter()
            .map(|(_, header, items)| quote!(#header { #(#items)* }))
    }
}

/// The scope of a command's checks: what is enabled where it runs, and the objects of
/// its instance and device.
fn scope_expr(cx: &Context, plan: &Plan, device_path: &TokenStream) -> TokenStream {
    if let Some(c) = special(&plan.name).and_then(|s| s.scope) {
        return special_call(&c, &quote!());
    }
    match level(cx.model, &plan.name) {
        Level::Entry => quote!(crate::validation::Scope {
            exts: crate::checks::Exts::new(0, &[]),
            instance: None,
            device: None,
        }),
        _ => quote!(#device_path.scope()),
    }
}
