//! The dynamic checks every safe method runs (its `_unchecked` twin skips them): which implicit
//! rules get one, and each check as data (a [`CheckKind`] with its VUID), which
//! `emit::checks` renders into the checked methods and `checks/`.
//!
//! The settlement records read [`Checker::dynamic`], so a rule is reported as
//! dynamically solved exactly when the emitted code checks it.

use super::commands::{Param, Plan};
use super::shape::{struct_members, Member, VariantKind};
use super::Context;
use crate::model::Kind;
use crate::model::LenEntry;
use crate::names::param;
use crate::validity::{DerivedRule, ImplicitKind as K};
use heck::ToSnakeCase;
use std::collections::{BTreeMap, BTreeSet};

/// One check: the rule it settles (none for a call into a nested struct's checks),
/// what it does (for the report), and what it checks, as data that the `checks`
/// renderer turns into code.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Check {
    /// The rule.
    pub vuid: Option<String>,
    /// What the check does, for the report.
    pub what: String,
    /// The check.
    pub kind: CheckKind,
}

/// Where a checked value is, in the scope of the check: a method argument (by its
/// Rust name), a member of a struct argument, or a member of the struct being
/// checked (`v`).
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Place {
    /// A method argument.
    Arg(String),
    /// A member of a struct argument.
    ArgMember(String, String),
    /// A member of the checked struct.
    Member(String),
}

/// Values whose checks are generated functions.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum ValueKind {
    /// `enum_*`: one of the values the enabled versions and extensions define.
    Enum(String),
    /// `flags_*`: every bit set is one they define.
    Flags(String),
    /// `check_*`: a plain struct's own checks.
    Struct(String),
}

/// A sequence whose elements are checked one by one.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Seq {
    /// A fixed-size array member of the checked struct.
    MemberArray(String),
    /// An array member stored as a pointer with its count member.
    MemberSlice {
        /// The pointer member.
        member: String,
        /// The count member.
        count: String,
    },
    /// A slice argument.
    ArgSlice(String),
}

/// A handle (or handles) that must come from the object the scope names.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum HandleAt {
    /// A wrapper argument, maybe optional.
    Arg {
        /// The argument.
        name: String,
        /// `Option<&T>`.
        optional: bool,
        /// The wrapper's `parent()` is the ancestor the check asks about (a device
        /// child's device), so comparing the two answers it without a lookup.
        parent_is_ancestor: bool,
    },
    /// A slice of wrapper arguments.
    ArgSlice(String),
    /// A raw handle member of the checked struct (null allowed).
    Member(String),
    /// An array of raw handles of the checked struct.
    MemberSlice {
        /// The pointer member.
        member: String,
        /// The count member.
        count: String,
    },
}

/// Where a nested struct whose checks are called is.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum StructAt {
    /// A struct member of the checked struct, by value.
    Member(String),
    /// A pointer member, maybe null.
    MemberRef(String),
    /// An array member with its count.
    MemberSlice {
        /// The pointer member.
        member: String,
        /// The count member.
        count: String,
    },
    /// An argument by reference.
    Arg(String),
    /// An optional argument by reference.
    OptionalArg(String),
    /// An argument by value.
    ArgByValue(String),
    /// A slice argument.
    ArgSlice(String),
    /// A member of a union that another member of the checked struct selects,
    /// checked when the selector names it (the safe enum sets both together).
    Variant {
        /// The union member of the checked struct.
        union: String,
        /// The union's member that holds the struct.
        variant: String,
        /// The selector member.
        selector: String,
        /// The selector's type, as ash spells it (`GeometryTypeKHR`).
        selector_type: String,
        /// The selector values that choose the variant, as ash's constants.
        values: Vec<String>,
        /// The union holds a pointer to the struct (maybe null), not the struct.
        by_ref: bool,
    },
}

/// Which queue flags a command's checks read.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum QueueOf {
    /// The family of the recording command buffer's pool.
    Pool,
    /// The family of the queue the method is called on.
    Queue,
}

/// The commands a primary may record in a subpass begun with
/// `VK_SUBPASS_CONTENTS_SECONDARY_COMMAND_BUFFERS`: executing the secondaries, and
/// leaving the subpass.
pub const SECONDARY_CONTENTS_COMMANDS: &[&str] = &[
    "vkCmdExecuteCommands",
    "vkCmdNextSubpass",
    "vkCmdNextSubpass2",
    "vkCmdEndRenderPass",
    "vkCmdEndRenderPass2",
];

/// The kinds of dynamic check. The renderer in `emit::checks` writes each one; the
/// failure message of those that fail with one is part of the data.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum CheckKind {
    /// A value's generated check function.
    Value {
        /// Which function.
        kind: ValueKind,
        /// Of what.
        at: Place,
    },
    /// The same for every element of a sequence.
    EachValue {
        /// Which function.
        kind: ValueKind,
        /// Over what.
        over: Seq,
    },
    /// A function-pointer member is set.
    FnPointerSet {
        /// The member.
        member: String,
    },
    /// A count is not 0.
    NonZero {
        /// The count.
        at: Place,
        /// The failure.
        msg: String,
    },
    /// A slice, or a flags value, is not empty.
    NotEmpty {
        /// The value.
        at: Place,
        /// The failure.
        msg: String,
    },
    /// Reserved flags are 0.
    ZeroFlags {
        /// The value.
        at: Place,
        /// The failure.
        msg: String,
    },
    /// Handles come from the device (`owned_by_device`) or instance the call is on.
    OwnedBy {
        /// `VkDevice` or `VkInstance`.
        ancestor: String,
        /// Each handle, with the failure naming it.
        handles: Vec<(HandleAt, String)>,
    },
    /// The queue family supports the command's queue types.
    QueueFlags {
        /// Whose family.
        of: QueueOf,
        /// vk.xml's `queues`, `graphics,compute`.
        queues: String,
    },
    /// The device the command is called on was created with at least one queue.
    DeviceHasQueues,
    /// The command is not recorded in a primary's subpass begun with
    /// `VK_SUBPASS_CONTENTS_SECONDARY_COMMAND_BUFFERS`, which takes only the
    /// commands of [`SECONDARY_CONTENTS_COMMANDS`].
    InlineContents,
    /// The recording command buffer has this level.
    Level {
        /// Primary rather than secondary.
        primary: bool,
    },
    /// A nested struct's own checks.
    NestedStruct {
        /// The struct type.
        ty: String,
        /// Where it is.
        at: StructAt,
    },
    /// The `pNext` chain: each node's checks, no structure type twice when the
    /// rule's VUID is the check's, and with `pnext` (the struct's `pNext-pNext`
    /// rule) no node of a version or extension the scope does not enable.
    Chain {
        /// The struct's `pNext-pNext` VUID, where an emitted struct that extends it
        /// needs more than Vulkan 1.0.
        pnext: Option<String>,
    },
    /// An explicit rule the recognisers read, over the checked struct's members.
    Explicit(Box<crate::validity::explicit::Recognised>),
    /// Every handle a struct argument reaches (members, arrays, nested structs,
    /// `pNext` chains) is an object of the call's device or instance: the walk the
    /// retention uses, checking (`crate::reach`).
    Reaches {
        /// The struct type.
        ty: String,
        /// The argument: by reference, optional, or a slice.
        at: StructAt,
    },
}

impl Check {
    /// Whether the check asks where handles come from: run before every other check
    /// and special case, so that none of them, and no driver call, sees a handle of
    /// another device.
    pub fn is_ownership(&self) -> bool {
        matches!(
            self.kind,
            CheckKind::OwnedBy { .. } | CheckKind::Reaches { .. }
        )
    }

    /// Enum and flags types whose value checks this check calls.
    pub fn needs(&self) -> Vec<String> {
        match &self.kind {
            CheckKind::Value { kind, .. } | CheckKind::EachValue { kind, .. } => match kind {
                ValueKind::Enum(t) | ValueKind::Flags(t) => vec![t.clone()],
                ValueKind::Struct(_) => Vec::new(),
            },
            _ => Vec::new(),
        }
    }

    /// Whether the check reads the scope (`s`): the enabled versions and extensions,
    /// or which objects the device and instance own.
    pub fn uses_scope(&self) -> bool {
        if let CheckKind::Explicit(r) = &self.kind {
            return r.check.reads_device() || r.key.is_some();
        }
        !matches!(
            self.kind,
            CheckKind::FnPointerSet { .. }
                | CheckKind::NonZero { .. }
                | CheckKind::NotEmpty { .. }
                | CheckKind::ZeroFlags { .. }
                | CheckKind::QueueFlags { .. }
                | CheckKind::DeviceHasQueues
                | CheckKind::InlineContents
                | CheckKind::Level { .. }
        )
    }

    /// The method arguments the check reads, by their Rust names.
    pub fn reads(&self) -> Vec<String> {
        if let CheckKind::Explicit(r) = &self.kind {
            if !r.on_command {
                return Vec::new();
            }
            let mut out: Vec<String> = Vec::new();
            for m in r.check.members().into_iter().chain(r.check.handles()) {
                let a = param(crate::validity::explicit::root(m));
                if !out.contains(&a) {
                    out.push(a);
                }
            }
            return out;
        }
        let borrowed: Vec<&str> = match &self.kind {
            CheckKind::Value { at, .. }
            | CheckKind::NonZero { at, .. }
            | CheckKind::NotEmpty { at, .. }
            | CheckKind::ZeroFlags { at, .. } => match at {
                Place::Arg(a) | Place::ArgMember(a, _) => vec![a.as_str()],
                _ => Vec::new(),
            },
            CheckKind::EachValue {
                over: Seq::ArgSlice(a),
                ..
            } => vec![a],
            CheckKind::OwnedBy { handles, .. } => handles
                .iter()
                .filter_map(|(h, _)| match h {
                    HandleAt::Arg { name, .. } | HandleAt::ArgSlice(name) => Some(name.as_str()),
                    _ => None,
                })
                .collect(),
            CheckKind::NestedStruct {
                at:
                    StructAt::Arg(a)
                    | StructAt::OptionalArg(a)
                    | StructAt::ArgByValue(a)
                    | StructAt::ArgSlice(a),
                ..
            }
            | CheckKind::Reaches {
                at: StructAt::Arg(a) | StructAt::OptionalArg(a) | StructAt::ArgSlice(a),
                ..
            } => vec![a],
            _ => Vec::new(),
        };
        borrowed.into_iter().map(str::to_owned).collect()
    }
}

/// Decides the checks of every emitted command and struct.
pub struct Checker<'c, 'm> {
    pub(crate) cx: &'c Context<'m>,
    pub(crate) rules: BTreeMap<&'m str, Vec<&'m DerivedRule>>,
    /// The explicit rules the recognisers read, by struct.
    pub(crate) explicit: BTreeMap<&'m str, Vec<&'m crate::validity::explicit::Recognised>>,
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
        let mut explicit: BTreeMap<&str, Vec<_>> = BTreeMap::new();
        // A rule the special-case table already settles keeps its hand-written check
        // alone: a second, generated one would only cost time.
        for r in cx
            .validity
            .recognised
            .iter()
            .filter(|r| super::special::settled(&r.vuid).is_none())
        {
            explicit.entry(r.item.as_str()).or_default().push(r);
        }
        let mut checker = Checker {
            cx,
            rules,
            explicit,
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
                    && t.category == Some(Kind::Struct)
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
        // The nested structs its checks call (members, and the structs of selected
        // unions), read from the checks themselves.
        let mut out: Vec<String> = self
            .struct_cache
            .get(name)
            .into_iter()
            .flatten()
            .filter_map(|c| match &c.kind {
                CheckKind::NestedStruct { ty, .. } => Some(ty.clone()),
                _ => None,
            })
            .collect();
        if let Some(ext) = self.cx.model.extended_by.get(name) {
            out.extend(ext.iter().filter(|e| self.checked.contains(*e)).cloned());
        }
        out
    }

    fn rules_of(&self, item: &str) -> &[&'m DerivedRule] {
        self.rules.get(item).map_or(&[], Vec::as_slice)
    }

    /// The check of a value of an enum or flags type, or of a plain struct with
    /// checks, and what it does.
    fn value_kind(&self, type_name: &str) -> Option<(ValueKind, &'static str)> {
        let model = self.cx.model;
        // An alias (`VkAccelerationStructureTypeNV`) has the values of the type it
        // names, which ash spells as the same type.
        let type_name = model
            .types
            .get(type_name)
            .and_then(|t| t.alias.as_deref())
            .unwrap_or(type_name);
        match model.category(type_name) {
            Some(Kind::Enum) if !enum_values(model, type_name).is_empty() => {
                Some((ValueKind::Enum(type_name.to_owned()), ENUM_VALUE))
            }
            Some(Kind::Bitmask) if flag_bits(model, type_name).is_some() => {
                Some((ValueKind::Flags(type_name.to_owned()), FLAGS_VALUE))
            }
            Some(Kind::Struct) if self.checked.contains(type_name) => Some((
                ValueKind::Struct(type_name.to_owned()),
                "checks the struct's own rules",
            )),
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
            let check: Option<(CheckKind, String)> = match (rule.kind, field) {
                (K::Parameter, Some((m, Member::Value)))
                    if model.category(&m.type_name) == Some(Kind::Funcpointer) =>
                {
                    Some((
                        CheckKind::FnPointerSet {
                            member: m.name.clone(),
                        },
                        "checks the function pointer is set".to_owned(),
                    ))
                }
                (K::Parameter, Some((m, Member::Value))) => {
                    self.value_kind(&m.type_name).map(|(kind, w)| {
                        let at = Place::Member(m.name.clone());
                        (CheckKind::Value { kind, at }, w.to_owned())
                    })
                }
                (K::Parameter, Some((m, Member::Array(_)))) => {
                    self.value_kind(&m.type_name).map(|(kind, w)| {
                        let over = Seq::MemberArray(m.name.clone());
                        (
                            CheckKind::EachValue { kind, over },
                            format!("{w}, for each element"),
                        )
                    })
                }
                (K::Parameter, Some((m, Member::Slice { count, .. })))
                    if matches!(
                        model.category(&m.type_name),
                        Some(Kind::Enum | Kind::Bitmask)
                    ) =>
                {
                    self.value_kind(&m.type_name).map(|(kind, w)| {
                        let over = Seq::MemberSlice {
                            member: m.name.clone(),
                            count: count.clone(),
                        };
                        (
                            CheckKind::EachValue { kind, over },
                            format!("{w}, for each element"),
                        )
                    })
                }
                (K::ArrayLength, Some((m, _))) if m.pointers == 0 => Some((
                    CheckKind::NonZero {
                        at: Place::Member(m.name.clone()),
                        msg: format!("`{}` is 0", m.name),
                    },
                    "checks the count is not 0".to_owned(),
                )),
                (K::RequiredBitmask, Some((m, Member::Value))) => Some((
                    CheckKind::NotEmpty {
                        at: Place::Member(m.name.clone()),
                        msg: format!("`{}` is empty", m.name),
                    },
                    "checks the flags are not 0".to_owned(),
                )),
                (K::ZeroBitmask, Some((m, Member::Value))) => Some((
                    CheckKind::ZeroFlags {
                        at: Place::Member(m.name.clone()),
                        msg: format!("`{}` is not 0", m.name),
                    },
                    "checks the reserved flags are 0".to_owned(),
                )),
                (K::Unique, _) => {
                    unique = Some(vuid.to_owned());
                    continue;
                }
                (K::CommonParent, _) => self.struct_common_parent(rule, &members),
                _ => None,
            };
            if let Some((kind, what)) = check {
                out.push(Check {
                    vuid: Some(vuid.to_owned()),
                    what,
                    kind,
                });
            }
        }
        // Explicit rules the recognisers read.
        for r in self.explicit.get(name).into_iter().flatten() {
            out.push(Check {
                vuid: Some(r.vuid.clone()),
                what: format!("checks the rule as written (recogniser: {})", r.by),
                kind: CheckKind::Explicit(Box::new((*r).clone())),
            });
        }
        // Nested structs' own checks.
        for (m, shape) in &members {
            if let Member::Selected { variants, selector } = shape {
                out.extend(self.variant_checks(m, selector, variants, &members));
                continue;
            }
            if !self.checked.contains(&m.type_name) {
                continue;
            }
            let at = match shape {
                Member::Value | Member::Nested => StructAt::Member(m.name.clone()),
                Member::StructRef { .. } => StructAt::MemberRef(m.name.clone()),
                Member::Slice { count, .. } => StructAt::MemberSlice {
                    member: m.name.clone(),
                    count: count.clone(),
                },
                _ => continue,
            };
            out.push(Check {
                vuid: None,
                what: String::new(),
                kind: CheckKind::NestedStruct {
                    ty: m.type_name.clone(),
                    at,
                },
            });
        }
        let chain_checked = model
            .extended_by
            .get(name)
            .is_some_and(|e| e.iter().any(|x| self.checked.contains(x)));
        // A struct of a version or extension the instance or device does not enable
        // is not a valid node (the layer names it under the struct's pNext-pNext).
        let pnext_vuid = format!("VUID-{name}-pNext-pNext");
        let gated = model.has_gated_extenders(name)
            && self.rules_of(name).iter().any(|r| r.vuid == pnext_vuid);
        if unique.is_some() || chain_checked || gated {
            out.push(Check {
                vuid: unique,
                what: "walks the chain and checks no structure type appears twice".into(),
                kind: CheckKind::Chain {
                    pnext: gated.then_some(pnext_vuid),
                },
            });
        }
        out
    }

    /// The checks of the structs a selected union's variants hold, each run when the
    /// selector names its variant.
    fn variant_checks(
        &self,
        union: &crate::model::Field,
        selector: &str,
        variants: &[super::shape::Variant],
        members: &[(crate::model::Field, Member)],
    ) -> Vec<Check> {
        let Some((sel, _)) = members.iter().find(|(m, _)| m.name == selector) else {
            return Vec::new();
        };
        let model = self.cx.model;
        let mut out: Vec<Check> = Vec::new();
        for v in variants {
            let by_ref = match v.kind {
                VariantKind::StructRef { .. } => true,
                VariantKind::Nested => false,
                VariantKind::Handle { .. } | VariantKind::Value => continue,
            };
            if !self.checked.contains(&v.member.type_name) {
                continue;
            }
            let value = crate::names::enum_const(&sel.type_name, &v.selection);
            // Several values may select one member (an alias, or the uniform and
            // storage kinds of one pointer): one check names them all.
            let same = out.iter_mut().find_map(|c| match &mut c.kind {
                CheckKind::NestedStruct {
                    at:
                        StructAt::Variant {
                            variant, values, ..
                        },
                    ..
                } if *variant == v.member.name => Some(values),
                _ => None,
            });
            if let Some(values) = same {
                if !values.contains(&value) {
                    values.push(value);
                }
                continue;
            }
            out.push(Check {
                vuid: None,
                what: String::new(),
                kind: CheckKind::NestedStruct {
                    ty: v.member.type_name.clone(),
                    at: StructAt::Variant {
                        union: union.name.clone(),
                        variant: v.member.name.clone(),
                        selector: selector.to_owned(),
                        selector_type: crate::names::type_name(model.spelling(&sel.type_name)),
                        values: vec![value],
                        by_ref,
                    },
                },
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
    ) -> Option<(CheckKind, String)> {
        let ancestor = rule.ancestor.clone()?;
        owner_known(&ancestor)?;
        let mut handles = Vec::new();
        for name in &rule.related {
            let (m, shape) = members.iter().find(|(m, _)| &m.name == name)?;
            let msg = format!(
                "`{}` does not come from the {ancestor} the command is called on",
                m.name
            );
            handles.push((
                match shape {
                    Member::Handle { .. } => HandleAt::Member(m.name.clone()),
                    Member::HandleSlice { count } => HandleAt::MemberSlice {
                        member: m.name.clone(),
                        count: count.clone(),
                    },
                    _ => return None,
                },
                msg,
            ));
        }
        Some((
            CheckKind::OwnedBy { ancestor, handles },
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
        let rust = |i: usize| param(&cmd.params[i].name);
        let queues = cmd.queues.clone().unwrap_or_default();
        let mut out = Vec::new();
        for rule in self.rules_of(&plan.name) {
            let vuid = rule.vuid.as_str();
            let field = rule.field.as_deref().and_then(arg);
            let check: Option<(CheckKind, String)> = match (rule.kind, field) {
                (K::Parameter, Some((i, Param::Value))) => {
                    self.value_kind(&cmd.params[i].type_name).map(|(kind, w)| {
                        let at = Place::Arg(rust(i));
                        (CheckKind::Value { kind, at }, w.to_owned())
                    })
                }
                (K::Parameter, Some((i, Param::Slice)))
                    if matches!(
                        model.category(&cmd.params[i].type_name),
                        Some(Kind::Enum | Kind::Bitmask)
                    ) =>
                {
                    self.value_kind(&cmd.params[i].type_name).map(|(kind, w)| {
                        let over = Seq::ArgSlice(rust(i));
                        (CheckKind::EachValue { kind, over }, format!("{w}, for each element"))
                    })
                }
                (K::RequiredBitmask, Some((i, Param::Value))) => Some((
                    CheckKind::NotEmpty {
                        at: Place::Arg(rust(i)),
                        msg: format!("`{}` is empty", cmd.params[i].name),
                    },
                    "checks the flags are not 0".into(),
                )),
                (K::ZeroBitmask, Some((i, Param::Value))) => Some((
                    CheckKind::ZeroFlags {
                        at: Place::Arg(rust(i)),
                        msg: format!("`{}` is not 0", cmd.params[i].name),
                    },
                    "checks the reserved flags are 0".into(),
                )),
                (K::ArrayLength, _) => self.command_array_length(plan, rule),
                (K::Parent, Some((i, shape))) => {
                    let ancestor = rule.ancestor.clone().unwrap_or_default();
                    let is_dispatch = rule.related.first() == cmd.params.first().map(|p| &p.name);
                    let msg = format!(
                        "`{}` does not come from `{}`",
                        cmd.params[i].name,
                        rule.related.first().map_or("", String::as_str)
                    );
                    match (owner_known(&ancestor), handle_at(shape, rust(i))) {
                        (Some(()), Some(at)) if is_dispatch => Some((
                            CheckKind::OwnedBy {
                                ancestor,
                                handles: vec![(at, msg)],
                            },
                            "checks the handle was created, allocated or retrieved from the object the method is called on".into(),
                        )),
                        _ => None,
                    }
                }
                (K::CommonParent, _) => self.command_common_parent(plan, rule),
                (K::CmdPool, _) => Some((
                    CheckKind::QueueFlags {
                        of: QueueOf::Pool,
                        queues: queues.clone(),
                    },
                    "checks the queue flags of the pool's family, recorded when the pool was created".into(),
                )),
                (K::QueueType, _) => Some((
                    CheckKind::QueueFlags {
                        of: QueueOf::Queue,
                        queues: queues.clone(),
                    },
                    "checks the queue flags of the queue's family, recorded when the queue was retrieved".into(),
                )),
                (K::QueueCount, _) if cmd.params.first().is_some_and(|p| p.type_name == "VkDevice") => Some((
                    CheckKind::DeviceHasQueues,
                    "checks the device was created with a queue, which it records at its creation".into(),
                )),
                (K::BufferLevel, _) => Some((
                    CheckKind::Level {
                        primary: cmd.cmdbufferlevel.as_deref() == Some("primary"),
                    },
                    "checks the level the command buffer was allocated with".into(),
                )),
                _ => None,
            };
            if let Some((kind, what)) = check {
                out.push(Check {
                    vuid: Some(vuid.to_owned()),
                    what,
                    kind,
                });
            }
        }
        // Explicit rules the recognisers read, over parameters the method takes as
        // they are (a count the method derives from a slice is not one).
        for r in self.explicit.get(plan.name.as_str()).into_iter().flatten() {
            // An element's member (`pRegions[].x`) is read from the slice the method
            // takes.
            let by_value = r.check.members().iter().all(|m| {
                let first = crate::validity::explicit::root(m);
                if m.contains("[]") {
                    matches!(arg(first), Some((_, Param::Slice)))
                } else {
                    matches!(arg(first), Some((_, Param::Value)))
                }
            }) && r
                .check
                .handles()
                .iter()
                .all(|h| matches!(arg(h), Some((_, Param::Handle { optional: false }))));
            if by_value {
                out.push(Check {
                    vuid: Some(r.vuid.clone()),
                    what: format!("checks the rule as written (recogniser: {})", r.by),
                    kind: CheckKind::Explicit(Box::new((*r).clone())),
                });
            }
        }
        // The checks of the structs it takes.
        for (i, (p, shape)) in cmd.params.iter().zip(&plan.params).enumerate() {
            if !self.checked.contains(&p.type_name) {
                continue;
            }
            let a = rust(i);
            let at = match shape {
                Param::StructRef { optional: true } => StructAt::OptionalArg(a),
                Param::StructRef { optional: false } | Param::InOut => StructAt::Arg(a),
                Param::Value => StructAt::ArgByValue(a),
                Param::Slice => StructAt::ArgSlice(a),
                _ => continue,
            };
            out.push(Check {
                vuid: None,
                what: String::new(),
                kind: CheckKind::NestedStruct {
                    ty: p.type_name.clone(),
                    at,
                },
            });
        }
        // Every handle the struct arguments reach comes from the call's device or
        // instance.
        for (i, (p, shape)) in cmd.params.iter().zip(&plan.params).enumerate() {
            if !self.cx.reaching.contains(&p.type_name) {
                continue;
            }
            let a = rust(i);
            let at = match shape {
                Param::StructRef { optional: true } => StructAt::OptionalArg(a),
                Param::StructRef { optional: false } | Param::InOut => StructAt::Arg(a),
                Param::Slice => StructAt::ArgSlice(a),
                _ => continue,
            };
            out.push(Check {
                vuid: None,
                what: String::new(),
                kind: CheckKind::Reaches {
                    ty: p.type_name.clone(),
                    at,
                },
            });
        }
        // A subpass whose contents are secondaries takes nothing else: the
        // specification says so in prose, with no VUID (the recorder's check names the
        // layer's identifier for it), so the check settles no rule of the report.
        if matches!(cmd.renderpass.as_deref(), Some("inside" | "both"))
            && !SECONDARY_CONTENTS_COMMANDS.contains(&plan.name.as_str())
        {
            out.push(Check {
                vuid: None,
                what: String::new(),
                kind: CheckKind::InlineContents,
            });
        }
        // Where handles come from is asked first.
        out.sort_by_key(|c| !c.is_ownership());
        out
    }

    fn command_array_length(&self, plan: &Plan, rule: &DerivedRule) -> Option<(CheckKind, String)> {
        let model = self.cx.model;
        let cmd = &model.commands[&plan.name];
        let field = rule.field.as_deref()?;
        let msg = format!("`{field}` is 0");
        if let Some((head, member)) = field.split_once("::") {
            // `pAllocateInfo::commandBufferCount`: a member of a struct parameter.
            let i = cmd.params.iter().position(|p| p.name == head)?;
            if !matches!(plan.params.get(i)?, Param::StructRef { optional: false }) {
                return None;
            }
            return Some((
                CheckKind::NonZero {
                    at: Place::ArgMember(param(head), member.to_owned()),
                    msg,
                },
                "checks the count is not 0".to_owned(),
            ));
        }
        // A count filled in from the slices it sizes.
        let users: Vec<_> = cmd
            .params
            .iter()
            .zip(&plan.params)
            .filter(|(q, _)| q.parsed.len.first().and_then(LenEntry::other_param) == Some(field))
            .collect();
        let slice = users.iter().find(|(_, s)| {
            matches!(
                s,
                Param::Slice | Param::HandleSlice | Param::Bytes | Param::BytesOut
            )
        })?;
        Some((
            CheckKind::NotEmpty {
                at: Place::Arg(param(&slice.0.name)),
                msg,
            },
            "checks the slice is not empty".into(),
        ))
    }

    fn command_common_parent(
        &self,
        plan: &Plan,
        rule: &DerivedRule,
    ) -> Option<(CheckKind, String)> {
        let cmd = &self.cx.model.commands[&plan.name];
        let ancestor = rule.ancestor.clone()?;
        // A physical device's objects (displays) name it as their parent, which the
        // device the method is called on names too.
        let physical = ancestor == "VkPhysicalDevice" && plan.receiver == "VkDevice";
        if !physical {
            owner_known(&ancestor)?;
        }
        let mut handles = Vec::new();
        for name in &rule.related {
            let i = cmd.params.iter().position(|p| &p.name == name)?;
            let shape = plan.params.get(i)?;
            if matches!(shape, Param::Dispatch) {
                continue;
            }
            let msg = match physical {
                true => format!(
                    "`{name}` does not come from the physical device of the device the command is called on"
                ),
                false => {
                    format!("`{name}` does not come from the {ancestor} the command is called on")
                }
            };
            let mut at = handle_at(shape, param(name))?;
            if let HandleAt::Arg {
                parent_is_ancestor, ..
            } = &mut at
            {
                *parent_is_ancestor = (ancestor == "VkDevice" || physical)
                    && self
                        .cx
                        .model
                        .handles
                        .get(&cmd.params[i].type_name)
                        .and_then(|h| h.parent_chain.first())
                        .is_some_and(|p| *p == ancestor);
            }
            if physical
                && !matches!(
                    at,
                    HandleAt::Arg {
                        optional: false,
                        parent_is_ancestor: true,
                        ..
                    }
                )
            {
                return None;
            }
            handles.push((at, msg));
        }
        Some((
            CheckKind::OwnedBy { ancestor, handles },
            "checks each handle was created from the device (or instance) the method is called on, so they share it".into(),
        ))
    }
}

/// Whether the scope can tell which objects the ancestor owns: a device or an
/// instance.
fn owner_known(ancestor: &str) -> Option<()> {
    matches!(ancestor, "VkDevice" | "VkInstance").then_some(())
}

/// Where a wrapper argument of this shape is, for an ownership check.
fn handle_at(shape: &Param, name: String) -> Option<HandleAt> {
    match shape {
        Param::Handle { optional } => Some(HandleAt::Arg {
            name,
            optional: *optional,
            parent_is_ancestor: false,
        }),
        Param::HandleSlice => Some(HandleAt::ArgSlice(name)),
        _ => None,
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
    let delta = model.delta_values.get(type_name).into_iter().flatten();
    for v in model
        .enum_values
        .get(type_name)
        .into_iter()
        .flatten()
        .chain(delta)
    {
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
