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
