//! Settlement records: for every rule of the emitted API, how the emitted code
//! settles it. The decisions read the same shapes and plans the emitters use.

use super::checks::Checker;
use super::commands::{handled_elsewhere, Param, Plan};
use super::shape::{struct_members, Member};
use super::special::How;
use super::{Context, Record, Settlement};
use crate::model::{Kind, LenEntry};
use crate::validity::{Category, ImplicitKind};
use std::collections::BTreeMap;

/// How a rule that the safe methods check, but that no oracle case proves yet, is
/// described: left to the user in the tally, enforced for the safe/`unsafe` split.
pub const CHECKED_UNPROVEN: &str = "checked by the safe methods in every build";

/// Records for every rule of the emitted API.
pub fn records(
    cx: &Context,
    checker: &Checker,
    commands: &[(String, Result<Plan, String>)],
    oracle: &[super::oracle::Case],
) -> Vec<Record> {
    let proven: std::collections::BTreeSet<&str> = oracle.iter().map(|c| c.vuid.as_str()).collect();
    let plans: BTreeMap<String, Result<Plan, String>> = commands.iter().cloned().collect();
    let derived: BTreeMap<&str, &crate::validity::DerivedRule> = cx
        .validity
        .derived
        .iter()
        .map(|r| (r.vuid.as_str(), r))
        .collect();
    let mut out = Vec::new();
    for rule in cx.validity.rules.iter().filter(|r| r.emitted) {
        let settlement = match (rule.category, derived.get(rule.vuid.as_str())) {
            // A special case that settles an implicit rule the derivation cannot
            // (a pointer Vulkan writes through, in a struct without a setter for it).
            (Category::Implicit, _) if super::special::settled(&rule.vuid).is_some() => {
                super::special::settled(&rule.vuid)
                    .map_or_else(|| Settlement::User(String::new()), from_table)
            }
            (Category::Implicit, _) if checker.dynamic(&rule.vuid).is_some() => {
                Settlement::Dynamic(checker.dynamic(&rule.vuid).unwrap_or_default().to_owned())
            }
            (Category::Implicit, Some(d)) => implicit(cx, checker, &plans, d),
            (Category::Implicit, None) => Settlement::User(
                "written by hand in the specification; not derived, so not checked".into(),
            ),
            _ => match (
                explicit(&rule.vuid, &rule.text, &|name: &str| {
                    param_shape(cx, &plans, &rule.item, name)
                }),
                checker.dynamic(&rule.vuid),
            ) {
                (Settlement::User(_), Some(what)) if proven.contains(rule.vuid.as_str()) => {
                    Settlement::Dynamic(what.to_owned())
                }
                (Settlement::User(_), Some(_)) => Settlement::User(format!(
                    "{CHECKED_UNPROVEN}, but no oracle case breaks it yet"
                )),
                (settled, _) => settled,
            },
        };
        out.push(Record {
            vuid: rule.vuid.clone(),
            settlement,
        });
    }
    out
}

/// The shape the safe method of command `item` gives its parameter `name` (matched
/// without case, as [`explicit`] reads lowercased text).
fn param_shape(
    cx: &Context,
    plans: &BTreeMap<String, Result<Plan, String>>,
    item: &str,
    name: &str,
) -> Option<Param> {
    // A struct's member, as its safe setter takes it.
    if !cx.model.commands.contains_key(item) {
        return struct_members(cx.model, &cx.facts, item)
            .into_iter()
            .find(|(f, _)| f.name.to_lowercase() == name)
            .and_then(|(_, m)| match m {
                Member::Handle { optional } => Some(Param::Handle { optional }),
                Member::HandleSlice { .. } => Some(Param::HandleSlice),
                Member::Slice { .. } => Some(Param::Slice),
                _ => None,
            });
    }
    let cmd = cx.model.commands.get(item)?;
    let i = cmd
        .params
        .iter()
        .position(|p| p.name.to_lowercase() == name)?;
    match plans.get(item)? {
        Ok(plan) => plan.params.get(i).cloned(),
        Err(_) => None,
    }
}

/// How the rules about a command's deferred operation are settled.
const NOT_DEFERRED: &str =
    "the wrappers pass no deferred operation (VK_NULL_HANDLE): the command completes before the method returns";

fn explicit(vuid: &str, text: &str, param: &dyn Fn(&str) -> Option<Param>) -> Settlement {
    // Plain text without code marks: `If no `VkAllocationCallbacks` were provided`
    // reads as `if no vkallocationcallbacks were provided`.
    let t = crate::validity::explicit::plain(text)
        .replace('`', "")
        .to_lowercase();
    if let Some(how) = super::special::settled(vuid) {
        from_table(how)
    } else if t.contains("all submitted commands that refer to") {
        Settlement::Static(
            "destroyed only when the last wrapper clone goes; recorded command buffers and pending submissions hold clones until their fence signals".into(),
        )
    } else if is_valid_pfn(&t) {
        Settlement::Static(
            "the setter takes a Rust function pointer of the callback's type, valid for the whole program; a missing one is refused by the member's implicit check".into(),
        )
    } else if let Some(how) = wrapper_handle(&t, param) {
        Settlement::Static(how.into())
    } else if t.contains("vkallocationcallbacks were provided when") {
        Settlement::Static("the wrappers never pass allocation callbacks".into())
    } else if t.contains("deferredoperation")
        && matches!(param("deferredoperation"), Some(Param::NotDeferred))
    {
        // Each such rule holds of a non-null operation only (`If deferredOperation
        // is not VK_NULL_HANDLE`, `the previous deferred operation associated with
        // deferredOperation`).
        Settlement::Static(NOT_DEFERRED.into())
    } else {
        Settlement::User("explicit rule; the wrappers do not check it".into())
    }
}

/// The settlement a row of the special-case table gives a rule.
fn from_table(how: How) -> Settlement {
    match how {
        How::Static(m) => Settlement::Static(m.into()),
        How::Dynamic(m) => Settlement::Dynamic(m.into()),
        How::User(m) => Settlement::User(m.into()),
    }
}

/// `pfnX must be a valid PFN_vkY` (lowercased, without code marks): a callback
/// member, which the safe struct takes as a typed Rust function pointer.
fn is_valid_pfn(t: &str) -> bool {
    let words: Vec<&str> = t.split(' ').collect();
    matches!(
        words.as_slice(),
        [member, "must", "be", "a", "valid", ty]
            if member.starts_with("pfn") && ty.starts_with("pfn_vk")
    )
}

/// A rule that a handle parameter is valid or not null, where the safe method takes
/// it as a wrapper (a live handle, never null): `surface must be a valid
/// vksurfacekhr handle`, `x must not be vk_null_handle`, and, for a slice of
/// wrappers, `if the nulldescriptor feature is not enabled, all elements of
/// pbuffers must not be vk_null_handle`.
fn wrapper_handle(t: &str, param: &dyn Fn(&str) -> Option<Param>) -> Option<&'static str> {
    let words: Vec<&str> = t.split(' ').collect();
    let one =
        "the method takes the handle as a wrapper reference, never null and live while borrowed";
    match words.as_slice() {
        [p, "must", "be", "a", "valid", ty, "handle"] if ty.starts_with("vk") => {
            matches!(param(p)?, Param::Handle { optional: false }).then_some(one)
        }
        [p, "must", "not", "be", "vk_null_handle"] => {
            matches!(param(p)?, Param::Handle { optional: false }).then_some(one)
        }
        // `If sharingMode is ..., pQueueFamilyIndices must be a valid pointer to an
        // array of queueFamilyIndexCount uint32_t values`: a slice the setter stores
        // with its length.
        [.., p, "must", "be", "a", "valid", "pointer", "to", "an", "array", "of", _, _, "values"] => {
            matches!(param(p)?, Param::Slice).then_some(
                "the setter takes a slice and stores its length in the count member",
            )
        }
        ["elements", "of", p, "must", "be", "valid", ty, "objects"] if ty.starts_with("vk") => {
            matches!(param(p)?, Param::HandleSlice).then_some(
                "the setter takes the handles as a slice of wrapper references, each live while borrowed",
            )
        }
        [.., "all", "elements", "of", p, "must", "not", "be", "vk_null_handle"] => {
            matches!(param(p)?, Param::HandleSlice).then_some(
                "the method takes the handles as a slice of wrapper references, none of them null",
            )
        }
        _ => None,
    }
}

fn implicit(
    cx: &Context,
    checker: &Checker,
    plans: &BTreeMap<String, Result<Plan, String>>,
    d: &crate::validity::DerivedRule,
) -> Settlement {
    use ImplicitKind as K;
    let model = cx.model;
    if model.commands.contains_key(&d.item) {
        if let Some(why) = handled_elsewhere(cx, &d.item) {
            return match (why, d.kind) {
                ("destroy", K::Parameter | K::Parent | K::CommonParent) => Settlement::Static(
                    "called only from Drop with the wrapper's own live handle, its parent and no allocator".into(),
                ),
                ("recorder", K::Parameter) => {
                    Settlement::Static("`CommandBuffer::begin` takes a wrapper and a safe struct".into())
                }
                ("destroy", K::ArrayLength) => Settlement::Static(
                    "called only from Drop, freeing exactly one object".into(),
                ),
                ("loader", K::Parameter) => Settlement::Static(
                    "called only by ash's loader code, with the wrapper's live handle and NUL-terminated names".into(),
                ),
                ("mapping", K::Parameter | K::Parent | K::ZeroBitmask) => Settlement::Static(
                    "called only by `DeviceMemory::map` and its guard, with the wrapper's own memory and device, flags 0 and their own output pointer".into(),
                ),
                _ => Settlement::User(format!("called by the wrappers' {why} code; not checked")),
            };
        }
        let plan = match plans.get(&d.item) {
            Some(Ok(plan)) => plan,
            Some(Err(reason)) => {
                return Settlement::User(format!(
                    "no safe wrapper is emitted ({reason}); call it through ash"
                ))
            }
            None => return Settlement::User("no safe wrapper is emitted".into()),
        };
        return match d.kind {
            K::VideoCoding if !model.emitted.contains("vkCmdBeginVideoCodingKHR") => Settlement::Static(
                "no video coding scope can begin: the emitted API has no `vkCmdBeginVideoCodingKHR`"
                    .into(),
            ),
            K::VideoCoding => Settlement::Static(
                "the method exists only on a `Recorder` in the video-coding state the command needs"
                    .into(),
            ),
            K::Recording => Settlement::Static(
                "the method exists only on a `Recorder`, which only `CommandBuffer::begin` makes"
                    .into(),
            ),
            K::RenderPass => Settlement::Static(
                "the method exists only on a `Recorder` in the render-pass state the command needs"
                    .into(),
            ),
            K::Parameter => {
                let idx = model.commands[&d.item]
                    .params
                    .iter()
                    .position(|p| Some(&p.name) == d.field.as_ref());
                let shares = plan
                    .same_len
                    .iter()
                    .find(|s| Some(&s.param) == d.field.as_ref());
                match idx.and_then(|i| plan.params.get(i)) {
                    Some(_) if shares.is_some() => Settlement::Dynamic(format!(
                        "checks, in every build, that the slice is as long as `{}`{}",
                        crate::names::param(&shares.map(|s| s.first.clone()).unwrap_or_default()),
                        if shares.is_some_and(|s| s.optional) {
                            " or empty (NULL)"
                        } else {
                            ""
                        }
                    )),
                    Some(p) => param_settlement(p),
                    None => Settlement::User("parameter not found in the plan".into()),
                }
            }
            K::ArrayLength => Settlement::User("a slice may be empty; not checked".into()),
            K::Parent => {
                let shape = model.commands[&d.item]
                    .params
                    .iter()
                    .zip(&plan.params)
                    .find(|(p, _)| Some(&p.name) == d.field.as_ref())
                    .map(|(_, s)| s);
                match shape {
                    // The method is called on the child, and passes its own parent.
                    Some(Param::Receiver) => Settlement::Static(
                        "the method is called on the handle, and passes the handle's own parent as the command's first parameter".into(),
                    ),
                    // No deferred operation is passed, so none has a parent to check.
                    Some(Param::NotDeferred) => Settlement::Static(NOT_DEFERRED.into()),
                    _ => Settlement::User(format!("`{}` rules are not checked yet", d.kind.tag())),
                }
            }
            _ => Settlement::User(format!("`{}` rules are not checked yet", d.kind.tag())),
        };
    }
    // A struct.
    let returned_only = model.types.get(&d.item).is_some_and(|t| t.returned_only);
    if d.kind == K::Unique && returned_only && !checker.reaches(&d.item) {
        // Only commands that return it in an array they allocate take it.
        return Settlement::Static(
            "the wrappers create it themselves, with an empty `pNext` chain".into(),
        );
    }
    if d.kind == K::Parameter && cx.facts.is_written(&d.item) {
        return Settlement::Static(
            "a struct Vulkan writes: every emitted command and struct passes it as storage Vulkan fills (the reference registry marks it `returnedonly` and has no such rule), and the safe struct has no setter for the member, so no value of the caller's is passed".into(),
        );
    }
    if !cx.facts.is_safe(&d.item) {
        return match d.kind {
            K::Parameter => Settlement::User(
                "enum or flags value of a plain struct; ash accepts any raw value".into(),
            ),
            _ => Settlement::User(format!("`{}` rules are not checked yet", d.kind.tag())),
        };
    }
    let members = struct_members(model, &cx.facts, &d.item);
    // A member of a selected union is set only with the selector, by the variant
    // of the safe enum that holds it.
    if let Some(variant) = members.iter().find_map(|(_, s)| match s {
        Member::Selected { variants, .. } => variants
            .iter()
            .find(|v| Some(&v.member.name) == d.field.as_ref()),
        _ => None,
    }) {
        return match (d.kind, variant.kind) {
            (K::Parameter, _) => Settlement::Static(
                "set, with the selector, only by the variant of the safe enum that holds it: a live wrapper, a reference to a struct (its safe counterpart where it has one) or a safe struct by value".into(),
            ),
            (kind, _) => Settlement::User(format!("`{}` rules are not checked yet", kind.tag())),
        };
    }
    let field = members
        .iter()
        .find(|(m, _)| Some(&m.name) == d.field.as_ref());
    let member = field.map(|(_, s)| s.clone());
    if let (K::Parameter, Some((f, Member::Unsupported(_)))) = (d.kind, field) {
        if stays_empty(f, &members) {
            return Settlement::Static(
                "never set: the safe struct has no setter for it, so it stays NULL (or its count 0), which the rule allows".into(),
            );
        }
    }
    match (d.kind, member) {
        (K::SType, _) => Settlement::Static("the safe struct's constructor sets `sType`".into()),
        (K::PNext, Some(Member::PNext)) => {
            Settlement::Static(match cx.model.has_gated_extenders(&d.item) {
                true => "`push_next` accepts only structs that implement `Extends` for the head, and the checks refuse a node of a version or extension not enabled where the call runs (tests/creation_checks.rs)".into(),
                false => "`push_next` accepts only structs that implement `Extends` for the head".into(),
            })
        }
        (K::Parameter, Some(Member::Value)) if plain_numbers(cx, d) => {
            Settlement::Static("a union of plain numbers: every value is valid".into())
        }
        (K::Parameter, Some(shape)) => member_settlement(&shape),
        (K::ArrayLength, _) => Settlement::User("a slice may be empty; not checked".into()),
        (kind, _) => Settlement::User(format!("`{}` rules are not checked yet", kind.tag())),
    }
}

/// Whether a member without a setter keeps a value its `-parameter` rule allows:
/// an optional pointer stays NULL, and an array whose count only its (missing)
/// setter fills in stays empty.
fn stays_empty(f: &crate::model::Field, members: &[(crate::model::Field, Member)]) -> bool {
    if f.pointers == 0 {
        return false;
    }
    f.is_optional()
        || matches!(f.parsed.len.first(), Some(LenEntry::Reference(parts)) if parts.len() == 1
            && members.iter().any(|(m, s)| m.name == parts[0] && matches!(s, Member::Count)))
}

fn member_settlement(shape: &Member) -> Settlement {
    match shape {
        Member::Handle { .. } | Member::HandleSlice { .. } => Settlement::Dynamic(
            "set from wrappers, which hold live handles; the walk over what a call's structs reach checks each is an object of the call's device or instance before any other check or driver call".into(),
        ),
        Member::Nested => Settlement::Static(
            "set from the safe counterpart, which the constructor requires".into(),
        ),
        Member::StructRef { .. }
        | Member::Slice { .. }
        | Member::Bytes { .. }
        | Member::Code { .. }
        | Member::CStr { .. }
        | Member::CStrSlice { .. } => Settlement::Static(
            "set from a reference or slice, a valid pointer with its length".into(),
        ),
        Member::Value | Member::Array(_) => Settlement::User(
            "enum or flags value; ash types accept any raw value, not checked".into(),
        ),
        Member::Platform => {
            Settlement::User("a window-system pointer given through an unsafe setter".into())
        }
        Member::Selected { .. } => Settlement::Static(
            "set from the variant of the safe enum the constructor takes, which names its member".into(),
        ),
        Member::StructMut { .. } => Settlement::Static(
            "taken as a mutable borrow of the struct Vulkan writes (required where the pointer is), a valid pointer for as long as the struct lives".into(),
        ),
        Member::OpaqueBytes => Settlement::Static(
            "taken as a byte slice, a valid pointer (the setter is `unsafe` for what the bytes hold and how many Vulkan reads)".into(),
        ),
        Member::FixedRef { .. } => Settlement::Static(
            "taken as a reference to an array of the length the registry gives".into(),
        ),
        Member::Selector => Settlement::Static(
            "set only by the variant of the union it selects, to that variant's value".into(),
        ),
        Member::CodecStd { .. } => Settlement::Static(
            "taken as a reference or slice of the codec's structs, a valid pointer with its length (the setter is `unsafe` for the pointers inside them)".into(),
        ),
        Member::PlatformValue => {
            Settlement::User("a window-system value given through an unsafe setter".into())
        }
        Member::Unsupported(why) => Settlement::User(format!("not settable safely ({why})")),
        // No catch-all: a new member shape must say here how its rules are settled.
        Member::SType => Settlement::Static("the safe struct's constructor sets `sType`".into()),
        Member::Count => Settlement::Static("filled in by the setter of the array it sizes".into()),
        Member::PNext => Settlement::User(
            "the `pNext` of a generic chain node (`VkBaseInStructure`); the wrappers pass none"
                .into(),
        ),
        // Its one rule is that it be "a pointer value", which every value of the
        // setter's `*mut c_void` is: Vulkan only hands it back to the callback.
        Member::UserData => Settlement::Static(
            "opaque user data handed back to a callback: any `*mut c_void` is a pointer value, and Vulkan never reads through it".into(),
        ),
    }
}

fn param_settlement(p: &Param) -> Settlement {
    match p {
        Param::Dispatch | Param::Receiver => {
            Settlement::Static("`self` is a live wrapper".into())
        }
        Param::Handle { .. } | Param::HandleSlice | Param::Created | Param::CreatedArray => {
            Settlement::Static("taken as wrappers, which always hold valid handles; outputs are written into storage the wrapper provides".into())
        }
        Param::Allocator => Settlement::Static("always NULL".into()),
        Param::HostAllocator => Settlement::Static(
            "NULL, or the callbacks of the entry's `HostAllocator`, which tuff makes and keeps alive while the instance or device lives".into(),
        ),
        Param::NotDeferred => Settlement::Static(NOT_DEFERRED.into()),
        Param::Display(_) => Settlement::Static(
            "taken as a `raw_window_handle::DisplayHandle`, a display connection valid while it is borrowed (a handle of another window system is refused)".into(),
        ),
        Param::CStr { .. } => {
            Settlement::Static("taken as a `CStr`: a valid NUL-terminated string".into())
        }
        Param::StructRef { .. }
        | Param::NumberRef { .. }
        | Param::Slice
        | Param::Bytes
        | Param::BytesOut
        | Param::BytesOutUnsized
        | Param::SliceOfSlices
        | Param::SliceOut
        | Param::Array
        | Param::InOut => {
            Settlement::Static("taken as a reference or slice: a valid pointer with its length".into())
        }
        Param::Output | Param::ForeignOutput | Param::Enumerated | Param::EnumCount => {
            Settlement::Static("written into storage the wrapper provides".into())
        }
        Param::Count => Settlement::Static("computed from the slice it sizes".into()),
        Param::Value => Settlement::User("enum or flags value; ash types accept any raw value, not checked".into()),
        Param::RawData => Settlement::User(
            "a raw pointer the caller vouches for through an `unsafe` method".into(),
        ),
        Param::Raw => Settlement::User(
            "passed as ash's raw type (a window-system object, a pointer to pointers or an array of a length the registry gives as an expression); the caller vouches for it through an `unsafe` method".into(),
        ),
    }
}

/// Whether the member a rule is about is a union of numbers only (`VkClearValue`).
fn plain_numbers(cx: &Context, d: &crate::validity::DerivedRule) -> bool {
    fn numbers(cx: &Context, name: &str, depth: usize) -> bool {
        let Some(t) = cx.model.types.get(name) else {
            return super::shape::is_c_scalar(name);
        };
        depth < 8
            && matches!(t.category, Some(Kind::Union | Kind::Struct))
            && t.members.iter().all(|m| {
                m.pointers == 0
                    && (super::shape::is_c_scalar(&m.type_name)
                        || numbers(cx, &m.type_name, depth + 1))
            })
    }
    let Some(t) = cx.model.types.get(&d.item) else {
        return false;
    };
    t.members
        .iter()
        .find(|m| Some(&m.name) == d.field.as_ref())
        .is_some_and(|m| {
            cx.model.category(&m.type_name) == Some(Kind::Union) && numbers(cx, &m.type_name, 0)
        })
}
