//! The dynamic checks compiled in with `runtime_implicit_validations`: which implicit
//! rules get one, the code of each, and `src/checks.rs`, which holds the checks of
//! enum and flags values, of every struct, and of `pNext` chains.
//!
//! The settlement records read [`Checker::dynamic`], so a rule is reported as
//! dynamically solved exactly when the emitted code checks it.

use super::commands::{Param, Plan};
use super::shape::{struct_members, Member};
use super::Context;
use crate::model::LenEntry;
use crate::names::{field_ident, ident, param};
use crate::validity::{DerivedRule, ImplicitKind as K};
use heck::ToSnakeCase;
use proc_macro2::TokenStream;
use quote::quote;
use std::collections::{BTreeMap, BTreeSet};

/// One check: the rule it settles (none for a call into a nested struct's checks),
/// what it does, and its code, which may use `s` (the scope) and `?`.
#[derive(Clone)]
pub struct Check {
    /// The rule.
    pub vuid: Option<String>,
    /// What the check does, for the report.
    pub what: String,
    /// The code.
    pub code: TokenStream,
    /// Enum and flags types whose value checks the code calls.
    pub needs: Vec<String>,
}

/// Decides the checks of every emitted command and struct.
pub struct Checker<'c, 'm> {
    pub(crate) cx: &'c Context<'m>,
    pub(crate) rules: BTreeMap<&'m str, Vec<&'m DerivedRule>>,
    /// Structs that have a check function.
    pub(crate) checked: BTreeSet<String>,
    /// Structs whose check function some emitted command reaches.
    pub(crate) reachable: BTreeSet<String>,
    /// The rules checked, with what checks them.
    pub(crate) dynamic: BTreeMap<String, String>,
    /// The checks of each struct that has a check function.
    pub(crate) struct_cache: BTreeMap<String, Vec<Check>>,
    /// The checks of each emitted command.
    pub(crate) command_cache: BTreeMap<String, Vec<Check>>,
}

const ENUM_VALUE: &str = "checks the value is one that the versions and extensions enabled on the instance or device define";
const FLAGS_VALUE: &str = "checks every bit set is one that the versions and extensions enabled on the instance or device define";

impl<'c, 'm> Checker<'c, 'm> {
    /// Decide the checks for the emitted API, given the commands' plans.
    pub fn new(cx: &'c Context<'m>, plans: &[&Plan]) -> Self {
        let mut rules: BTreeMap<&str, Vec<&DerivedRule>> = BTreeMap::new();
        for r in &cx.validity.derived {
            rules.entry(r.item.as_str()).or_default().push(r);
        }
        let mut checker = Checker {
            cx,
            rules,
            checked: BTreeSet::new(),
            reachable: BTreeSet::new(),
            dynamic: BTreeMap::new(),
            struct_cache: BTreeMap::new(),
            command_cache: BTreeMap::new(),
        };
        let structs: Vec<String> = cx
            .model
            .types
            .values()
            .filter(|t| {
                t.alias.is_none()
                    && t.category.as_deref() == Some("struct")
                    && cx.model.emitted.contains(&t.name)
            })
            .map(|t| t.name.clone())
            .collect();
        // Nested structs first: repeat until no struct gains a check function.
        loop {
            let before = checker.checked.len();
            for s in &structs {
                if !checker.checked.contains(s) && !checker.build_struct_checks(s).is_empty() {
                    checker.checked.insert(s.clone());
                }
            }
            if checker.checked.len() == before {
                break;
            }
        }
        // The checks are final now that every nested struct's function is known.
        checker.struct_cache = checker
            .checked
            .iter()
            .map(|s| (s.clone(), checker.build_struct_checks(s)))
            .collect();
        checker.command_cache = plans
            .iter()
            .map(|p| (p.name.clone(), checker.build_command_checks(p)))
            .collect();
        let mut todo: Vec<String> = Vec::new();
        for plan in plans {
            for check in &checker.command_cache[&plan.name] {
                if let Some(v) = &check.vuid {
                    checker.dynamic.insert(v.clone(), check.what.clone());
                }
            }
            todo.extend(checker.struct_params(plan));
        }
        // `CommandBuffer::begin`, part of the recorder, checks its info.
        todo.push("VkCommandBufferBeginInfo".to_owned());
        while let Some(s) = todo.pop() {
            if !checker.checked.contains(&s) || !checker.reachable.insert(s.clone()) {
                continue;
            }
            for check in &checker.struct_cache[&s] {
                if let Some(v) = &check.vuid {
                    checker.dynamic.insert(v.clone(), check.what.clone());
                }
            }
            todo.extend(checker.nested(&s));
        }
        checker
    }

    /// Whether some emitted command runs the checks of struct `name`.
    pub fn reaches(&self, name: &str) -> bool {
        self.reachable.contains(name)
    }

    /// How the emitted code checks `vuid`, if it does.
    pub fn dynamic(&self, vuid: &str) -> Option<&str> {
        self.dynamic.get(vuid).map(String::as_str)
    }

    /// Structs a command takes whose checks it calls.
    fn struct_params(&self, plan: &Plan) -> Vec<String> {
        let cmd = &self.cx.model.commands[&plan.name];
        cmd.params
            .iter()
            .zip(&plan.params)
            .filter(|(p, shape)| {
                matches!(
                    shape,
                    Param::StructRef { .. } | Param::Slice | Param::InOut | Param::Value
                ) && self.checked.contains(&p.type_name)
            })
            .map(|(p, _)| p.type_name.clone())
            .collect()
    }

    /// Structs whose checks a struct's checks call: members and chain extenders.
    fn nested(&self, name: &str) -> Vec<String> {
        let model = self.cx.model;
        let mut out: Vec<String> = struct_members(model, &self.cx.facts, name)
            .into_iter()
            .filter(|(_, shape)| {
                matches!(
                    shape,
                    Member::Value
                        | Member::Nested
                        | Member::StructRef { .. }
                        | Member::Slice { .. }
                )
            })
            .map(|(m, _)| m.type_name)
            .filter(|t| self.checked.contains(t))
            .collect();
        if let Some(ext) = model.extended_by.get(name) {
            out.extend(ext.iter().filter(|e| self.checked.contains(*e)).cloned());
        }
        out
    }

    fn rules_of(&self, item: &str) -> &[&'m DerivedRule] {
        self.rules.get(item).map_or(&[], Vec::as_slice)
    }

    /// The code that checks a value of an enum or flags type, or of a plain struct
    /// with checks; `expr` is the value.
    fn value_check(
        &self,
        type_name: &str,
        expr: TokenStream,
        vuid: &str,
    ) -> Option<(TokenStream, Vec<String>, &'static str)> {
        let model = self.cx.model;
        match model.category(type_name) {
            Some("enum") if !enum_values(model, type_name).is_empty() => {
                let f = ident(&format!("enum_{}", snake(type_name)));
                Some((
                    quote!(crate::checks::#f(#expr, s, #vuid)?;),
                    vec![type_name.to_owned()],
                    ENUM_VALUE,
                ))
            }
            Some("bitmask") if flag_bits(model, type_name).is_some() => {
                let f = ident(&format!("flags_{}", snake(type_name)));
                Some((
                    quote!(crate::checks::#f(#expr, s, #vuid)?;),
                    vec![type_name.to_owned()],
                    FLAGS_VALUE,
                ))
            }
            Some("struct") if self.checked.contains(type_name) => {
                let f = ident(&format!("check_{}", snake(type_name)));
                Some((
                    quote!(crate::checks::#f(&#expr, s)?;),
                    Vec::new(),
                    "checks the struct's own rules",
                ))
            }
            _ => None,
        }
    }

    /// The checks of an emitted command, with its parameters as the method's
    /// arguments and `self` as the wrapper (or recorder) it is called on.
    pub fn command_checks(&self, plan: &Plan) -> &[Check] {
        self.command_cache
            .get(&plan.name)
            .map_or(&[], Vec::as_slice)
    }

    /// The checks of one struct, over `v: &vk::Struct`.
    fn build_struct_checks(&self, name: &str) -> Vec<Check> {
        let model = self.cx.model;
        let members = struct_members(model, &self.cx.facts, name);
        let member = |n: &str| members.iter().find(|(m, _)| m.name == n);
        let mut out = Vec::new();
        let mut unique = None;
        for rule in self.rules_of(name) {
            let vuid = rule.vuid.as_str();
            let field = rule.field.as_deref().and_then(member);
            let check = match (rule.kind, field) {
                (K::Parameter, Some((m, Member::Value)))
                    if model.category(&m.type_name) == Some("funcpointer") =>
                {
                    let f = field_ident(&m.name);
                    let msg = format!("`{}` is NULL", m.name);
                    Some((
                        quote!(if v.#f.is_none() { return Err(fail(#vuid, #msg.into())); }),
                        Vec::new(),
                        "checks the function pointer is set".to_owned(),
                    ))
                }
                (K::Parameter, Some((m, Member::Value))) => {
                    let f = field_ident(&m.name);
                    self.value_check(&m.type_name, quote!(v.#f), vuid)
                        .map(|(c, n, w)| (c, n, w.to_owned()))
                }
                (K::Parameter, Some((m, Member::Array(_)))) => {
                    let f = field_ident(&m.name);
                    self.value_check(&m.type_name, quote!(*e), vuid)
                        .map(|(c, n, w)| {
                            (
                                quote!(for e in v.#f.iter() { #c }),
                                n,
                                format!("{w}, for each element"),
                            )
                        })
                }
                (K::Parameter, Some((m, Member::Slice { count, .. })))
                    if matches!(model.category(&m.type_name), Some("enum" | "bitmask")) =>
                {
                    let f = field_ident(&m.name);
                    let n = field_ident(count);
                    self.value_check(&m.type_name, quote!(*e), vuid)
                        .map(|(c, needs, w)| {
                            (
                                quote! {
                                    __safety!("the safe setter stored this array and its count.");
                                    for e in unsafe { members(v.#f, v.#n) } { #c }
                                },
                                needs,
                                format!("{w}, for each element"),
                            )
                        })
                }
                (K::ArrayLength, Some((m, _))) if m.pointers == 0 => {
                    let f = field_ident(&m.name);
                    let msg = format!("`{}` is 0", m.name);
                    Some((
                        quote!(if v.#f == 0 { return Err(fail(#vuid, #msg.into())); }),
                        Vec::new(),
                        "checks the count is not 0".to_owned(),
                    ))
                }
                (K::RequiredBitmask, Some((m, Member::Value))) => {
                    let f = field_ident(&m.name);
                    let msg = format!("`{}` is empty", m.name);
                    Some((
                        quote!(if v.#f.is_empty() { return Err(fail(#vuid, #msg.into())); }),
                        Vec::new(),
                        "checks the flags are not 0".to_owned(),
                    ))
                }
                (K::ZeroBitmask, Some((m, Member::Value))) => {
                    let f = field_ident(&m.name);
                    let msg = format!("`{}` is not 0", m.name);
                    Some((
                        quote!(if v.#f.as_raw() != 0 { return Err(fail(#vuid, #msg.into())); }),
                        Vec::new(),
                        "checks the reserved flags are 0".to_owned(),
                    ))
                }
                (K::Unique, _) => {
                    unique = Some(vuid.to_owned());
                    continue;
                }
                (K::CommonParent, _) => self.struct_common_parent(rule, &members),
                _ => None,
            };
            if let Some((code, needs, what)) = check {
                out.push(Check {
                    vuid: Some(vuid.to_owned()),
                    what,
                    code,
                    needs,
                });
            }
        }
        // Nested structs' own checks.
        for (m, shape) in &members {
            if !self.checked.contains(&m.type_name) {
                continue;
            }
            let f = field_ident(&m.name);
            let call = ident(&format!("check_{}", snake(&m.type_name)));
            let code = match shape {
                Member::Value | Member::Nested => quote!(crate::checks::#call(&v.#f, s)?;),
                Member::StructRef { .. } => quote! {
                    if !v.#f.is_null() {
                        __safety!("the safe setter stores a reference that outlives `v`.");
                        crate::checks::#call(unsafe { &*v.#f }, s)?;
                    }
                },
                Member::Slice { count, .. } => {
                    let n = field_ident(count);
                    quote! {
                        __safety!("the safe setter stored this array and its count.");
                        for e in unsafe { members(v.#f, v.#n) } {
                            crate::checks::#call(e, s)?;
                        }
                    }
                }
                _ => continue,
            };
            out.push(Check {
                vuid: None,
                what: String::new(),
                code,
                needs: Vec::new(),
            });
        }
        let chain_checked = model
            .extended_by
            .get(name)
            .is_some_and(|e| e.iter().any(|x| self.checked.contains(x)));
        if unique.is_some() || chain_checked {
            let u = match &unique {
                Some(v) => quote!(Some(#v)),
                None => quote!(None),
            };
            out.push(Check {
                vuid: unique,
                what: "walks the chain and checks no structure type appears twice".into(),
                code: quote!(crate::checks::chain(v.p_next, s, #u)?;),
                needs: Vec::new(),
            });
        }
        out
    }

    /// `commonparent` of a struct's handle members: each non-null one must come from
    /// the device (or instance) the command runs on.
    fn struct_common_parent(
        &self,
        rule: &DerivedRule,
        members: &[(crate::model::Field, Member)],
    ) -> Option<(TokenStream, Vec<String>, String)> {
        let owner = owner_fn(rule.ancestor.as_deref()?)?;
        let vuid = rule.vuid.as_str();
        let mut code = Vec::new();
        for name in &rule.related {
            let (m, shape) = members.iter().find(|(m, _)| &m.name == name)?;
            let f = field_ident(&m.name);
            let msg = format!(
                "`{}` does not come from the {} the command is called on",
                m.name,
                rule.ancestor.as_deref()?
            );
            code.push(match shape {
                Member::Handle { .. } => quote! {
                    if v.#f != Default::default() && !s.#owner(v.#f) {
                        return Err(fail(#vuid, #msg.into()));
                    }
                },
                Member::HandleSlice { count } => {
                    let n = field_ident(count);
                    quote! {
                        __safety!("the safe setter stored this HandleSlice and its count.");
                        for h in unsafe { members(v.#f, v.#n) } {
                            if *h != Default::default() && !s.#owner(*h) {
                                return Err(fail(#vuid, #msg.into()));
                            }
                        }
                    }
                }
                _ => return None,
            });
        }
        Some((
            quote!(#(#code)*),
            Vec::new(),
            "checks each handle was created from the device (or instance) the command is called on, so they share it".into(),
        ))
    }

    /// The checks of one command.
    fn build_command_checks(&self, plan: &Plan) -> Vec<Check> {
        let model = self.cx.model;
        let cmd = &model.commands[&plan.name];
        let arg = |name: &str| -> Option<(usize, &Param)> {
            let i = cmd.params.iter().position(|p| p.name == name)?;
            Some((i, plan.params.get(i)?))
        };
        let mut out = Vec::new();
        for rule in self.rules_of(&plan.name) {
            let vuid = rule.vuid.as_str();
            let field = rule.field.as_deref().and_then(arg);
            let check: Option<(TokenStream, Vec<String>, String)> = match (rule.kind, field) {
                (K::Parameter, Some((i, Param::Value))) => {
                    let p = &cmd.params[i];
                    let a = ident(&param(&p.name));
                    self.value_check(&p.type_name, quote!(#a), vuid)
                        .map(|(c, n, w)| (c, n, w.to_owned()))
                }
                (K::Parameter, Some((i, Param::Slice)))
                    if matches!(
                        model.category(&cmd.params[i].type_name),
                        Some("enum" | "bitmask")
                    ) =>
                {
                    let p = &cmd.params[i];
                    let a = ident(&param(&p.name));
                    self.value_check(&p.type_name, quote!(*e), vuid)
                        .map(|(c, n, w)| {
                            (
                                quote!(for e in #a.iter() { #c }),
                                n,
                                format!("{w}, for each element"),
                            )
                        })
                }
                (K::RequiredBitmask, Some((i, Param::Value))) => {
                    let a = ident(&param(&cmd.params[i].name));
                    let msg = format!("`{}` is empty", cmd.params[i].name);
                    Some((
                        quote!(if #a.is_empty() { return Err(fail(#vuid, #msg.into())); }),
                        Vec::new(),
                        "checks the flags are not 0".into(),
                    ))
                }
                (K::ZeroBitmask, Some((i, Param::Value))) => {
                    let a = ident(&param(&cmd.params[i].name));
                    let msg = format!("`{}` is not 0", cmd.params[i].name);
                    Some((
                        quote!(if #a.as_raw() != 0 { return Err(fail(#vuid, #msg.into())); }),
                        Vec::new(),
                        "checks the reserved flags are 0".into(),
                    ))
                }
                (K::ArrayLength, _) => self.command_array_length(plan, rule),
                (K::Parent, Some((i, shape))) => {
                    let owner = owner_fn(rule.ancestor.as_deref().unwrap_or_default());
                    let is_dispatch = rule.related.first() == cmd.params.first().map(|p| &p.name);
                    match owner {
                        Some(owner) if is_dispatch => {
                            let a = ident(&param(&cmd.params[i].name));
                            let msg = format!(
                                "`{}` does not come from `{}`",
                                cmd.params[i].name, rule.related[0]
                            );
                            handle_owned(shape, &a, &owner, vuid, &msg).map(|c| {
                                (c, Vec::new(), "checks the handle was created, allocated or retrieved from the object the method is called on".into())
                            })
                        }
                        _ => None,
                    }
                }
                (K::CommonParent, _) => self.command_common_parent(plan, rule),
                (K::CmdPool, _) => {
                    let needed = queue_flags(cmd.queues.as_deref().unwrap_or_default());
                    let msg = format!(
                        "the command buffer's pool does not support {} operations",
                        cmd.queues.as_deref().unwrap_or_default()
                    );
                    Some((
                        quote! {
                            if !crate::validation::supports(self.command_buffer().parent().queue_flags(), #needed) {
                                return Err(fail(#vuid, #msg.into()));
                            }
                        },
                        Vec::new(),
                        "checks the queue flags of the pool's family, recorded when the pool was created".into(),
                    ))
                }
                (K::QueueType, _) => {
                    let needed = queue_flags(cmd.queues.as_deref().unwrap_or_default());
                    let msg = format!(
                        "the queue does not support {} operations",
                        cmd.queues.as_deref().unwrap_or_default()
                    );
                    Some((
                        quote! {
                            if !crate::validation::supports(self.queue_flags(), #needed) {
                                return Err(fail(#vuid, #msg.into()));
                            }
                        },
                        Vec::new(),
                        "checks the queue flags of the queue's family, recorded when the queue was retrieved".into(),
                    ))
                }
                (K::BufferLevel, _) => {
                    let level = cmd.cmdbufferlevel.as_deref().unwrap_or_default();
                    let want = if level == "primary" {
                        quote!(vk::CommandBufferLevel::PRIMARY)
                    } else {
                        quote!(vk::CommandBufferLevel::SECONDARY)
                    };
                    let msg = format!("the command buffer is not a {level} command buffer");
                    Some((
                        quote! {
                            if self.command_buffer().level() != #want {
                                return Err(fail(#vuid, #msg.into()));
                            }
                        },
                        Vec::new(),
                        "checks the level the command buffer was allocated with".into(),
                    ))
                }
                _ => None,
            };
            if let Some((code, needs, what)) = check {
                out.push(Check {
                    vuid: Some(vuid.to_owned()),
                    what,
                    code,
                    needs,
                });
            }
        }
        // The checks of the structs it takes.
        for (p, shape) in cmd.params.iter().zip(&plan.params) {
            if !self.checked.contains(&p.type_name) {
                continue;
            }
            let a = ident(&param(&p.name));
            let call = ident(&format!("check_{}", snake(&p.type_name)));
            let code = match shape {
                Param::StructRef { optional: true } => {
                    quote!(if let Some(x) = #a { crate::checks::#call(x, s)?; })
                }
                Param::StructRef { optional: false } | Param::InOut => {
                    quote!(crate::checks::#call(#a, s)?;)
                }
                Param::Value => quote!(crate::checks::#call(&#a, s)?;),
                Param::Slice => quote!(for x in #a.iter() { crate::checks::#call(x, s)?; }),
                _ => continue,
            };
            out.push(Check {
                vuid: None,
                what: String::new(),
                code,
                needs: Vec::new(),
            });
        }
        out
    }

    fn command_array_length(
        &self,
        plan: &Plan,
        rule: &DerivedRule,
    ) -> Option<(TokenStream, Vec<String>, String)> {
        let model = self.cx.model;
        let cmd = &model.commands[&plan.name];
        let field = rule.field.as_deref()?;
        let vuid = rule.vuid.as_str();
        let msg = format!("`{field}` is 0");
        let what = "checks the count is not 0".to_owned();
        if let Some((head, member)) = field.split_once("::") {
            // `pAllocateInfo::commandBufferCount`: a member of a struct parameter.
            let i = cmd.params.iter().position(|p| p.name == head)?;
            if !matches!(plan.params.get(i)?, Param::StructRef { optional: false }) {
                return None;
            }
            let a = ident(&param(head));
            let m = field_ident(member);
            return Some((
                quote!(if #a.#m == 0 { return Err(fail(#vuid, #msg.into())); }),
                Vec::new(),
                what,
            ));
        }
        // A count filled in from the slices it sizes.
        let users: Vec<_> = cmd
            .params
            .iter()
            .zip(&plan.params)
            .filter(|(q, _)| {
                model
                    .parse_field(q)
                    .len
                    .first()
                    .and_then(LenEntry::other_param)
                    == Some(field)
            })
            .collect();
        let slice = users.iter().find(|(_, s)| {
            matches!(
                s,
                Param::Slice | Param::HandleSlice | Param::Bytes | Param::BytesOut
            )
        })?;
        let a = ident(&param(&slice.0.name));
        Some((
            quote!(if #a.is_empty() { return Err(fail(#vuid, #msg.into())); }),
            Vec::new(),
            "checks the slice is not empty".into(),
        ))
    }

    fn command_common_parent(
        &self,
        plan: &Plan,
        rule: &DerivedRule,
    ) -> Option<(TokenStream, Vec<String>, String)> {
        let cmd = &self.cx.model.commands[&plan.name];
        let owner = owner_fn(rule.ancestor.as_deref()?)?;
        let vuid = rule.vuid.as_str();
        let mut code = Vec::new();
        for name in &rule.related {
            let i = cmd.params.iter().position(|p| &p.name == name)?;
            let shape = plan.params.get(i)?;
            if matches!(shape, Param::Dispatch) {
                continue;
            }
            let a = ident(&param(name));
            let msg = format!(
                "`{name}` does not come from the {} the command is called on",
                rule.ancestor.as_deref()?
            );
            code.push(handle_owned(shape, &a, &owner, vuid, &msg)?);
        }
        Some((
            quote!(#(#code)*),
            Vec::new(),
            "checks each handle was created from the device (or instance) the method is called on, so they share it".into(),
        ))
    }
}

/// The scope method that says whether a handle comes from the ancestor.
fn owner_fn(ancestor: &str) -> Option<proc_macro2::Ident> {
    match ancestor {
        "VkDevice" => Some(ident("owned_by_device")),
        "VkInstance" => Some(ident("owned_by_instance")),
        _ => None,
    }
}

/// Code that fails unless the wrapper (or wrappers) `a` of `shape` come from the owner.
fn handle_owned(
    shape: &Param,
    a: &proc_macro2::Ident,
    owner: &proc_macro2::Ident,
    vuid: &str,
    msg: &str,
) -> Option<TokenStream> {
    Some(match shape {
        Param::Handle { optional: false } => quote! {
            if !s.#owner(#a.raw()) { return Err(fail(#vuid, #msg.into())); }
        },
        Param::Handle { optional: true } => quote! {
            if let Some(h) = #a { if !s.#owner(h.raw()) { return Err(fail(#vuid, #msg.into())); } }
        },
        Param::HandleSlice => quote! {
            for h in #a.iter() { if !s.#owner(h.raw()) { return Err(fail(#vuid, #msg.into())); } }
        },
        _ => return None,
    })
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

pub(crate) fn snake(type_name: &str) -> String {
    type_name.trim_start_matches("Vk").to_snake_case()
}

/// The numeric `sType` of a struct.
pub(crate) fn struct_type_value(cx: &Context, name: &str) -> Option<i32> {
    let t = cx.model.types.get(name)?;
    let value = t
        .members
        .iter()
        .find(|m| m.name == "sType")?
        .values
        .clone()?;
    i32::try_from(*cx.model.enum_numbers.get(&value)?).ok()
}

/// The values of an enum type the all-extensions build defines: (number, origins).
pub(crate) fn enum_values(
    model: &crate::model::Model,
    type_name: &str,
) -> BTreeMap<i64, BTreeSet<String>> {
    let mut out: BTreeMap<i64, BTreeSet<String>> = BTreeMap::new();
    for v in model.enum_values.get(type_name).into_iter().flatten() {
        if let Some(n) = model.enum_numbers.get(v) {
            out.entry(*n)
                .or_default()
                .extend(model.enum_origins.get(v).into_iter().flatten().cloned());
        }
    }
    out
}

/// The bits group of a flags type, when it has one with values.
pub(crate) fn flag_bits(model: &crate::model::Model, flags: &str) -> Option<String> {
    let t = model.types.get(flags)?;
    let bits = t.bit_values.clone()?;
    (!enum_values(model, &bits).is_empty()).then_some(bits)
}

/// Whether `code` names the identifier `name` anywhere, groups included.
pub(crate) fn mentions(code: &TokenStream, name: &str) -> bool {
    code.clone().into_iter().any(|t| match t {
        proc_macro2::TokenTree::Ident(i) => i == name,
        proc_macro2::TokenTree::Group(g) => mentions(&g.stream(), name),
        _ => false,
    })
}
