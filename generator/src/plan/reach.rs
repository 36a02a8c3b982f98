//! Which structs can reach a handle: through handle members, handle arrays, nested
//! structs, struct arrays and `pNext` chains. The emitted walk covers exactly these.

use super::shape::{struct_members, Member};
use super::Context;
use crate::model::Kind;
use std::collections::BTreeSet;

/// The structs of the emitted API whose walk can find a handle.
pub fn reaching(cx: &Context) -> BTreeSet<String> {
    let model = cx.model;
    let candidates: Vec<&String> = model
        .emitted
        .iter()
        .filter(|n| model.category(n) == Some(Kind::Struct) && cx.facts.is_safe(n))
        .filter(|n| model.types[*n].alias.is_none())
        .collect();
    let mut found = BTreeSet::new();
    // A fixed point: a struct reaches a handle when a member is one, or leads to a
    // struct that reaches one.
    loop {
        let before = found.len();
        for name in &candidates {
            if found.contains(*name) {
                continue;
            }
            let hit = struct_members(model, &cx.facts, name)
                .iter()
                .any(|(m, s)| match s {
                    Member::Handle { .. } | Member::HandleSlice { .. } => true,
                    Member::StructRef { .. }
                    | Member::Nested
                    | Member::Slice { safe: true, .. } => found.contains(&m.type_name),
                    Member::PNext => extenders(cx, name).any(|e| found.contains(e)),
                    _ => false,
                });
            if hit {
                found.insert((*name).clone());
            }
        }
        if found.len() == before {
            return found;
        }
    }
}

/// The emitted structs that may extend `head`'s chain.
pub(crate) fn extenders<'a>(
    cx: &'a Context,
    head: &'a str,
) -> impl Iterator<Item = &'a String> + 'a {
    cx.model.types.values().filter_map(move |t| {
        (cx.model.emitted.contains(&t.name)
            && t.alias.is_none()
            && t.struct_extends.iter().any(|h| h == head))
        .then_some(&t.name)
    })
}

/// How a walk visits one handle member of a struct.
pub struct HandleVisit {
    /// The handle type's objects come from a device (else from an instance).
    pub of_device: bool,
    /// The rule a handle of another device or instance breaks, where the walk checks
    /// the member (see [`handle_visit`]).
    pub rule: Option<String>,
}

/// Members whose handles the walk checks under a rule it cannot derive: the rule
/// that says the handles are valid ones (so of the call's device).
const OWN_RULES: &[(&str, &str, &str)] = &[(
    "VkDescriptorSetLayoutBinding",
    "pImmutableSamplers",
    "VUID-VkDescriptorSetLayoutBinding-descriptorType-00282",
)];

/// How a walk visits member `m` of `item`, and under which rule it checks it: the
/// member's own `-parameter` rule (a valid handle is one of the call's device); else
/// one `OWN_RULES` names; else, for a member Vulkan reads whatever the other
/// members say, the struct's `commonparent` rule that names it. A member Vulkan
/// ignores unless other members say otherwise (`noautovalidity`: a descriptor
/// write's texel buffer views, an image info's sampler) is not checked by the walk:
/// the rules of the commands that read it, or the struct's `commonparent` check,
/// check it where it is used.
pub fn handle_visit(cx: &Context, item: &str, m: &crate::model::Field) -> HandleVisit {
    use crate::validity::implicit::ImplicitKind as K;
    let of_device = m.type_name == "VkDevice"
        || cx
            .model
            .handles
            .get(&m.type_name)
            .is_some_and(|h| h.parent_chain.iter().any(|p| p == "VkDevice"));
    let rules = || cx.validity.derived.iter().filter(|r| r.item == item);
    let own = rules()
        .find(|r| r.kind == K::Parameter && r.field.as_deref() == Some(m.name.as_str()))
        .map(|r| r.vuid.clone());
    let listed = OWN_RULES
        .iter()
        .find(|(i, f, _)| *i == item && *f == m.name)
        .map(|(_, _, v)| (*v).to_owned());
    let common = || {
        rules()
            .find(|r| r.kind == K::CommonParent && r.related.contains(&m.name))
            .map(|r| r.vuid.clone())
    };
    let rule = own
        .or(listed)
        .or_else(|| (!m.noautovalidity).then(common).flatten());
    HandleVisit { of_device, rule }
}
