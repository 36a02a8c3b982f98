//! The rules that apply to each emitted method: its command's own and those of every
//! struct it takes, through members and `pNext` chains (but those the safe structs
//! refuse, `special::UNCHAINED`), and of the indirect arguments it reads from GPU
//! memory (`special::INDIRECT`), for the report's per-method table and the safety
//! decision.

use super::commands::Plan;
use super::Context;
use crate::model::Kind;
use std::collections::BTreeSet;

/// One emitted method and the items whose rules apply to a call of it.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct MethodRow {
    /// The registry command.
    pub command: String,
    /// The safe method's name.
    pub method: String,
    /// The type it is a method of (`Queue`, `Recorder`), as method names are
    /// unique only within one (`Queue::wait_idle`, `Device::wait_idle`).
    pub receiver: String,
    /// The command and every struct a call can pass, in name order.
    pub items: Vec<String>,
}

/// A row for every planned command.
pub fn rows(cx: &Context, plans: &[&Plan]) -> Vec<MethodRow> {
    let model = cx.model;
    plans
        .iter()
        .map(|plan| {
            let mut seen: BTreeSet<String> = BTreeSet::new();
            // `pAllocator` is NULL or tuff's own callbacks: its struct's rules are
            // never the caller's.
            let mut todo: Vec<String> = model.commands[&plan.name]
                .params
                .iter()
                .zip(&plan.params)
                .filter(|(_, shape)| {
                    !matches!(
                        shape,
                        super::commands::Param::Allocator | super::commands::Param::HostAllocator
                    )
                })
                .map(|(p, _)| p.type_name.clone())
                .collect();
            // The indirect arguments a command reads from GPU memory.
            todo.extend(
                super::special::INDIRECT
                    .iter()
                    .filter(|(command, _)| *command == plan.name)
                    .map(|(_, read)| read.to_string()),
            );
            while let Some(t) = todo.pop() {
                let Some(def) = model.types.get(&t) else {
                    continue;
                };
                if def.category != Some(Kind::Struct)
                    || !model.emitted.contains(&t)
                    || !seen.insert(t.clone())
                {
                    continue;
                }
                todo.extend(def.members.iter().map(|m| m.type_name.clone()));
                // A chain the safe structs refuse cannot carry its struct's rules
                // into a call.
                todo.extend(
                    model
                        .extended_by
                        .get(&t)
                        .into_iter()
                        .flatten()
                        .filter(|e| !super::special::unchained(e, &t))
                        .cloned(),
                );
            }
            let mut items = vec![plan.name.clone()];
            items.extend(seen);
            MethodRow {
                command: plan.name.clone(),
                method: cx.method(&plan.name),
                receiver: crate::names::type_name(crate::names::receiver_type(model, &plan.name)),
                items,
            }
        })
        .collect()
}
