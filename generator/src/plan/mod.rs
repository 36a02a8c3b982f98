//! Plan pass: decides, once, everything the renderers and the report read. For every
//! emitted command its parameters' shapes ([`commands::Plan`]); for every struct its
//! members' shapes ([`shape`]); the dynamic checks of commands and structs
//! ([`checks::Checker`]); the host synchronization of each call ([`sync`]); which
//! structs can reach a handle ([`reach`]); the special cases of commands, in one
//! table ([`special`]); which methods are safe ([`safety`]); the typed results of
//! commands with several success codes ([`status`]); and for every rule of the emitted API how
//! it is settled ([`settle`]). Renderers (`emit`) and the report are functions of
//! [`Plans`]; nothing here imports them.

pub mod accesses;
pub mod checks;
pub mod commands;
pub mod features;
pub mod methods;
pub mod oracle;
pub mod reach;
pub mod safety;
pub mod settle;
pub mod shape;
pub mod special;
pub mod status;
pub mod sync;
pub mod types;

use crate::model::Model;
use crate::validity::Validity;
use heck::ToSnakeCase;
use std::collections::{BTreeMap, BTreeSet};

/// How emitted code settles one rule.
#[derive(Debug, Clone, PartialEq, Eq, serde::Serialize)]
#[serde(tag = "status", content = "mechanism", rename_all = "lowercase")]
pub enum Settlement {
    /// Enforced by types at compile time; the text names the mechanism.
    Static(String),
    /// Checked at run time; the text names the check.
    Dynamic(String),
    /// Left to the user; the text says why.
    User(String),
}

impl Settlement {
    /// `static`, `dynamic` or `user`.
    pub fn status(&self) -> &'static str {
        match self {
            Settlement::Static(_) => "static",
            Settlement::Dynamic(_) => "dynamic",
            Settlement::User(_) => "user",
        }
    }

    /// The mechanism or reason.
    pub fn mechanism(&self) -> &str {
        match self {
            Settlement::Static(m) | Settlement::Dynamic(m) | Settlement::User(m) => m,
        }
    }
}

/// The plan's statement about one rule.
#[derive(Debug, Clone, PartialEq, Eq, serde::Serialize)]
pub struct Record {
    /// The rule.
    pub vuid: String,
    /// How it is settled.
    pub settlement: Settlement,
}

/// What the plan is built from, and the facts every part of it reads.
pub struct Context<'m> {
    /// The model.
    pub model: &'m Model,
    /// The rules.
    pub validity: &'m Validity,
    /// Facts about structs.
    pub facts: types::TypeFacts,
    /// The structs whose walk can find a handle (see [`reach`]).
    pub reaching: BTreeSet<String>,
    /// Where the example programs call a method or make a struct, by method name
    /// (`create_buffer`) or type name (`BufferCreateInfo`): the docs show it.
    pub examples: BTreeMap<String, Vec<Snippet>>,
    /// Each command's method name ([`crate::names::methods`]).
    pub methods: BTreeMap<String, String>,
}

/// A statement of the example programs, for an item's docs.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Snippet {
    /// The source file, relative to the repository root, with `/` separators.
    pub file: String,
    /// The 1-based line of the call.
    pub line: usize,
    /// The statement around it, dedented.
    pub code: String,
    /// For a method call, the identifier the call is made on (`queue` in
    /// `queue.submit(..)`); empty when the receiver is an expression or on an
    /// earlier line.
    pub receiver: String,
}

impl<'m> Context<'m> {
    /// Where the example programs call a method of the `receiver` type
    /// (`VkQueue`, or `Recorder` for a recorded command) or, with no receiver, make
    /// a struct. Method names are not unique (`Frame::submit` is not
    /// `Queue::submit`), so a call counts when it is made on a variable whose name
    /// begins the receiver's (`queue`, `rec` for a recorder, `physical` for a
    /// physical device), or, for a name no other receiver's method has, on an
    /// expression.
    pub fn example(&self, key: &str, receiver: Option<&str>) -> Option<&Snippet> {
        let all = self.examples.get(key)?;
        let Some(receiver) = receiver else {
            return all.first();
        };
        let words = crate::names::type_name(receiver).to_snake_case();
        let unique = self.methods.values().filter(|m| *m == key).count() == 1;
        all.iter()
            .find(|s| !s.receiver.is_empty() && words.starts_with(s.receiver.as_str()))
            .or_else(|| all.iter().find(|s| s.receiver.is_empty() && unique))
    }

    /// The method a command becomes, named relative to its receiver
    /// ([`crate::names::methods`]).
    pub fn method(&self, command: &str) -> String {
        self.methods
            .get(command)
            .cloned()
            .unwrap_or_else(|| crate::names::command_fn(self.model.spelling(command)))
    }

    /// The facts of `model` and `validity`.
    pub fn new(model: &'m Model, validity: &'m Validity) -> Context<'m> {
        let mut cx = Context {
            model,
            validity,
            facts: types::TypeFacts::new(model),
            reaching: BTreeSet::new(),
            examples: BTreeMap::new(),
            methods: crate::names::methods(model),
        };
        cx.reaching = reach::reaching(&cx);
        cx
    }
}

/// Every decision about the emitted API, made once.
pub struct Plans<'c, 'm> {
    /// What the plans were built from.
    pub cx: &'c Context<'m>,
    /// Every emitted command with its plan, or why it has none, in name order.
    pub commands: Vec<(String, Result<commands::Plan, String>)>,
    /// The dynamic checks of every command and struct.
    pub checker: checks::Checker<'c, 'm>,
    /// The oracle's cases, one per recognised rule it can break.
    pub oracle: Vec<oracle::Case>,
    /// Each emitted method with the items whose rules apply to it.
    pub methods: Vec<methods::MethodRow>,
    /// For every rule of the emitted API, how it is settled.
    pub records: Vec<Record>,
    /// Each method's safety, by command name.
    pub safety: BTreeMap<String, safety::MethodSafety>,
    /// The extensions the safe constructors let a program enable.
    pub enabling: safety::Enabling,
    /// The same records by the item (command or struct) each rule belongs to.
    pub by_item: BTreeMap<String, Vec<(String, Settlement)>>,
    /// Each rule's text on one line, code in backticks, for the docs.
    pub texts: BTreeMap<String, String>,
    /// The status enums of the planned commands with several success codes.
    pub statuses: Vec<status::Status>,
}

impl<'c, 'm> Plans<'c, 'm> {
    /// Plan every emitted command and struct, and settle every rule.
    pub fn build(cx: &'c Context<'m>) -> Plans<'c, 'm> {
        let commands = commands::plans(cx);
        let ok = planned(&commands);
        let checker = checks::Checker::new(cx, &ok);
        let oracle = oracle::cases(cx, &checker);
        let methods = methods::rows(cx, &ok);
        let records = settle::records(cx, &checker, &commands, &oracle);
        let enabling = safety::enabling(cx, &methods, &records);
        let mut safety = safety::decide(cx, &methods, &records, &enabling);
        for plan in ok.iter().filter(|p| p.caller_vouches()) {
            safety.entry(plan.name.clone()).or_default().raw = true;
        }
        let item_of: BTreeMap<&str, &str> = cx
            .validity
            .rules
            .iter()
            .map(|r| (r.vuid.as_str(), r.item.as_str()))
            .collect();
        let mut by_item: BTreeMap<String, Vec<(String, Settlement)>> = BTreeMap::new();
        for r in &records {
            if let Some(item) = item_of.get(r.vuid.as_str()) {
                by_item
                    .entry((*item).to_owned())
                    .or_default()
                    .push((r.vuid.clone(), r.settlement.clone()));
            }
        }
        let texts = cx
            .validity
            .rules
            .iter()
            .filter(|r| item_of.contains_key(r.vuid.as_str()))
            .map(|r| {
                (
                    r.vuid.clone(),
                    one_line(&crate::validity::explicit::plain(&r.text)),
                )
            })
            .collect();
        let statuses = status::all(cx.model, ok.iter().map(|p| p.name.as_str()));
        Plans {
            cx,
            commands,
            checker,
            oracle,
            methods,
            records,
            safety,
            enabling,
            by_item,
            texts,
            statuses,
        }
    }

    /// The status enum a command returns, if it has several success codes.
    pub fn status_of(&self, command: &str) -> Option<&status::Status> {
        self.statuses
            .iter()
            .find(|s| s.commands.iter().any(|c| c == command))
    }

    /// The commands that have a plan.
    pub fn ok(&self) -> Vec<&commands::Plan> {
        planned(&self.commands)
    }
}

/// A rule's text cut to about one line of docs, at a word, with a code span it
/// cuts through closed.
fn one_line(text: &str) -> String {
    const MAX: usize = 200;
    if text.chars().count() <= MAX {
        return text.to_owned();
    }
    let mut out = String::new();
    for word in text.split(' ') {
        if out.chars().count() + word.chars().count() + 1 > MAX {
            break;
        }
        if !out.is_empty() {
            out.push(' ');
        }
        out.push_str(word);
    }
    if out.matches('`').count() % 2 == 1 {
        out.push('`');
    }
    out.push_str(" …");
    out
}

/// The commands of `commands` that have a plan.
fn planned(commands: &[(String, Result<commands::Plan, String>)]) -> Vec<&commands::Plan> {
    commands
        .iter()
        .filter_map(|(_, p)| p.as_ref().ok())
        .collect()
}
