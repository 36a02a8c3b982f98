//! Which emitted methods are safe. A method is safe only when every rule that applies
//! to a call of it (its command's and those of every struct it can pass, the items of
//! its [`MethodRow`]) is enforced by the emitted code, statically or by a check its
//! safe form always runs, or belongs to one of the [`REVIEWED`] classes, whose breach
//! the class's reason shows cannot happen through safe code or cannot cause undefined
//! behaviour. Any other method is emitted as `unsafe fn`, and its `# Safety` section
//! lists the rules the caller owns.

use super::methods::MethodRow;
use super::{Context, Record, Settlement};
use crate::validity::Rule;
use std::collections::BTreeMap;

/// A class of rules that a safe method may leave unchecked, with the reason.
#[derive(Debug)]
pub struct Class {
    /// Short name, used in the report.
    pub name: &'static str,
    /// Why no safe program can break a rule of the class, or why breaking one cannot
    /// cause undefined behaviour.
    pub reason: &'static str,
    /// Whether a rule is in the class.
    pub holds: fn(&Rule) -> bool,
}

/// The reviewed classes. Each is narrow on purpose: a rule joins one by a property
/// of its registry entry or by its VUID, never by a guess at its text.
pub const REVIEWED: &[Class] = &[
    Class {
        name: "needs an extension the safe constructors refuse",
        reason: "the rule applies only on an instance or device that enables an extension \
                 (validusage.json files it under one, or its item belongs to one) that the \
                 safe `create_instance` and `create_device` refuse: every extension outside \
                 the emitted API (`Error::ExtensionNotEmitted`), and every emitted one that \
                 brings rules no check enforces to methods outside it, listed below \
                 (`Error::ExtensionUnchecked`); only `unsafe` code can reach it",
        holds: |r| r.key_holds == Some(false),
    },
    Class {
        name: "the shader's own behaviour",
        reason: "the rule is about what a shader does when it runs (termination, accesses \
                 outside the bound buffers without `robustBufferAccess`, the same Layer and \
                 ViewportIndex for every vertex of a primitive, FragDepth written on every \
                 path of a fragment shader that writes it on one, valid SPIR-V under the \
                 specializations the program's pipelines give it), which only the shader \
                 decides; `create_shader_module` is `unsafe` and makes the caller promise \
                 it once for every shader a pipeline can run",
        holds: |r| {
            (SHADER_TAILS.iter().any(|t| r.vuid.ends_with(t)) && r.item.starts_with("vkCmd"))
                || SHADER_RUN_TIME.contains(&r.vuid.as_str())
        },
    },
    Class {
        name: "queue family ownership of a resource's contents",
        reason: "the rule decides which queue family sees a buffer's or image's contents \
                 as written (ownership transfers, exclusive ownership, the families of a \
                 concurrent resource); the specification makes a breach leave those \
                 contents undefined for the family that breaks it (Queue Family Ownership \
                 Transfer: \"the contents of that resource are undefined\"), and no safe \
                 method relies on a resource's contents for memory safety: a safe program \
                 can write any bytes into host-visible memory, so every check that guards \
                 memory stands on recorded state, never on what a buffer or image holds",
        holds: |r| OWNERSHIP.contains(&r.vuid.as_str()),
    },
];

/// The rules about queue family ownership and sharing that a submission's
/// commands can break, by VUID.
const OWNERSHIP: &[&str] = &[
    "VUID-vkQueueSubmit-pSubmits-02207",
    "VUID-vkQueueSubmit-pSubmits-02808",
    "VUID-vkQueueSubmit-pSubmits-04626",
    "VUID-vkQueueSubmit2-commandBuffer-03879",
];

/// The VUID endings, shared by every draw and dispatch command, of rules that the
/// shader promise covers: termination, and buffer accesses inside the bound ranges
/// where robust buffer access is off.
const SHADER_TAILS: &[&str] = &["-None-07288", "-None-02705", "-None-02706"];

/// Rules of a pipeline's stages about what their shaders do when they run (the
/// values they write, their validity once specialized), which the shader promise
/// covers, by VUID.
const SHADER_RUN_TIME: &[&str] = &[
    "VUID-VkPipelineShaderStageCreateInfo-stage-02596",
    "VUID-VkPipelineShaderStageCreateInfo-stage-02597",
    "VUID-VkPipelineShaderStageCreateInfo-stage-06685",
    "VUID-VkPipelineShaderStageCreateInfo-pSpecializationInfo-06719",
];

/// A rule a method's caller owns.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Owned {
    /// The rule.
    pub vuid: String,
    /// Its text, as one line.
    pub text: String,
}

/// What makes one method safe or not.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct MethodSafety {
    /// Rules that apply, are not enforced, and are in no reviewed class: the caller's.
    pub owned: Vec<Owned>,
    /// Rules that apply and are not enforced but are in a reviewed class (its index).
    pub classed: Vec<(String, usize)>,
    /// Whether the caller vouches for something no check can: a parameter taken as
    /// a raw pointer or window-system value (`Param::Raw`, `Param::RawData`), or an
    /// externally synchronized object the wrappers cannot lock (`Plan::unlocked`).
    pub raw: bool,
}

impl MethodSafety {
    /// Whether the method is emitted safe.
    pub fn safe(&self) -> bool {
        self.owned.is_empty() && !self.raw
    }
}

/// Whether emitted code enforces a rule: settled, or checked by every safe method
/// that can break it while its oracle case is still missing.
pub fn enforced(s: &Settlement) -> bool {
    match s {
        Settlement::Static(_) | Settlement::Dynamic(_) => true,
        Settlement::User(why) => why.starts_with(super::settle::CHECKED_UNPROVEN),
    }
}

/// Whether a generated method enforces a rule: settled, but not by the safe form of
/// an indirect command alone (`special::indirect`), whose checks read arguments the
/// generated method, taking any buffer, cannot see.
fn enforced_by_method(settlement: &BTreeMap<&str, &Settlement>, vuid: &str) -> bool {
    settlement.get(vuid).is_some_and(|s| enforced(s))
        && super::special::indirect::settled(vuid).is_none()
}

/// Which emitted extensions the safe `create_instance` and `create_device` let a
/// program enable. Enabling an extension makes its rules reachable, on its own
/// methods and on every other method whose structs or values it extends (a core
/// struct's rule about an extension's flag, an extension struct chained to a core
/// create info). Its own methods answer for their rules (they are `unsafe` where
/// one is the caller's); a rule it brings to another method that no code enforces
/// would make that method unsafe in every program, so the extension is refused
/// instead and the method stays safe, and only the `unsafe` `_unchecked`
/// constructors enable it. Refusing one can make rules that need it unreachable,
/// which can free another: repeated until nothing changes.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct Enabling {
    /// The versions and extensions a safe program can enable.
    pub allowed: std::collections::BTreeSet<String>,
    /// Each emitted extension the safe constructors refuse, with the rules it would
    /// leave to the callers of other methods, in name order.
    pub refused: Vec<(String, Vec<Owned>)>,
}

impl Enabling {
    /// Whether `rule` can apply to a call in a program that enables only what the
    /// safe constructors allow: the condition validusage.json files it under, and
    /// its item's, hold.
    pub fn reachable(&self, cx: &Context, rule: &Rule) -> bool {
        reachable(cx, rule, &self.allowed)
    }
}

/// Rules whose registry key says `core` but that only a program enabling an
/// extension can break, by VUID ending: a video coding scope begins only with
/// `vkCmdBeginVideoCodingKHR`.
const REACHED_ONLY_WITH: &[(&str, &str)] = &[("-videocoding", "VK_KHR_video_queue")];

fn reachable(cx: &Context, rule: &Rule, allowed: &std::collections::BTreeSet<String>) -> bool {
    let item = cx.model.condition(&rule.item);
    (item.is_core() || item.expr().may_hold(allowed))
        && rule
            .key
            .as_deref()
            .is_none_or(|k| crate::model::expr::may_hold(k, allowed))
        && REACHED_ONLY_WITH
            .iter()
            .all(|(tail, x)| !rule.vuid.ends_with(tail) || allowed.contains(*x))
}

/// The rules that apply to each item of the emitted API: those a registry lists (the
/// derived ones it does not list belong to items it leaves out).
fn rules_by_item<'a>(cx: &'a Context) -> BTreeMap<&'a str, Vec<&'a Rule>> {
    let mut by_item: BTreeMap<&str, Vec<&Rule>> = BTreeMap::new();
    for rule in &cx.validity.rules {
        if rule.emitted && (rule.listed || !cx.validity.explicit_known) {
            by_item.entry(rule.item.as_str()).or_default().push(rule);
        }
    }
    by_item
}

/// Whether a rule that applies, unenforced, to a method is still the caller's once
/// the reviewed classes other than the extension one have taken theirs.
fn unclassed(rule: &Rule) -> bool {
    !REVIEWED[1..].iter().any(|c| (c.holds)(rule))
}

/// The versions and extensions a call of `command` already needs: those its
/// condition names, and what they depend on, transitively. The rules they make
/// reachable are the method's own.
fn own_names(
    cx: &Context,
    command: &str,
    allowed: &std::collections::BTreeSet<String>,
) -> std::collections::BTreeSet<String> {
    let condition = cx.model.condition(command);
    let holds = |set: &std::collections::BTreeSet<String>| {
        condition.is_core() || condition.expr().eval(set)
    };
    // Those the command cannot be called without; all it names for the method of an
    // extension the safe constructors refuse.
    let mut own: std::collections::BTreeSet<String> = condition
        .expr()
        .names()
        .into_iter()
        .filter(|x| {
            let mut without = allowed.clone();
            without.remove(*x);
            !holds(allowed) || !holds(&without)
        })
        .map(str::to_owned)
        .collect();
    let mut todo: Vec<String> = own.iter().cloned().collect();
    while let Some(x) = todo.pop() {
        let Some(depends) = cx.model.extension_depends.get(&x) else {
            continue;
        };
        let Ok(e) = crate::model::expr::Expr::parse(depends) else {
            continue;
        };
        for n in e.names() {
            if own.insert(n.to_owned()) {
                todo.push(n.to_owned());
            }
        }
    }
    own
}

/// The emitted extensions to refuse so that `rule` cannot apply to a method whose
/// own names are `own`: none where it applies without any extension foreign to the
/// method (the method answers for it); else each one whose absence alone makes it
/// unreachable, or, where none does alone (an alternative of several), all of them.
fn needed<'a>(
    cx: &Context,
    rule: &Rule,
    allowed: &'a std::collections::BTreeSet<String>,
    own: &std::collections::BTreeSet<String>,
) -> Vec<&'a str> {
    let mut named: std::collections::BTreeSet<String> = cx
        .model
        .condition(&rule.item)
        .expr()
        .names()
        .into_iter()
        .map(str::to_owned)
        .collect();
    if let Some(e) = rule
        .key
        .as_deref()
        .and_then(|k| crate::model::expr::Expr::parse(k).ok())
    {
        named.extend(e.names().into_iter().map(str::to_owned));
    }
    for (tail, x) in REACHED_ONLY_WITH {
        if rule.vuid.ends_with(tail) {
            named.insert((*x).to_owned());
        }
    }
    let foreign_of = |named: &std::collections::BTreeSet<String>| -> Vec<&'a str> {
        allowed
            .iter()
            .filter(|x| named.contains(*x) && !x.starts_with("VK_VERSION_") && !own.contains(*x))
            .map(String::as_str)
            .collect()
    };
    let foreign = foreign_of(&named);
    let without = |xs: &[&str]| {
        let mut set = allowed.clone();
        for x in xs {
            set.remove(*x);
        }
        set
    };
    if foreign.is_empty() || reachable(cx, rule, &without(&foreign)) {
        // A rule that applies without them may still speak of an extension's struct
        // or value (`not containing VkCopyCommandTransformInfoQCOM`): it is read, and
        // checked, as written only where no program can enable that extension.
        return foreign_of(&mentioned(cx, &rule.text));
    }
    let alone: Vec<&str> = foreign
        .iter()
        .copied()
        .filter(|x| !reachable(cx, rule, &without(&[x])))
        .collect();
    if alone.is_empty() {
        foreign
    } else {
        alone
    }
}

/// The versions and extensions that define the types and values a rule's text
/// names.
fn mentioned(cx: &Context, text: &str) -> std::collections::BTreeSet<String> {
    let mut out = std::collections::BTreeSet::new();
    for word in text.split(|c: char| !(c.is_ascii_alphanumeric() || c == '_')) {
        if word.starts_with("Vk") && cx.model.types.contains_key(word) {
            let c = cx.model.condition(word);
            if !c.is_core() {
                out.extend(c.expr().names().into_iter().map(str::to_owned));
            }
        } else if word.starts_with("VK_") {
            for origin in cx.model.enum_origins.get(word).into_iter().flatten() {
                out.insert(origin.clone());
            }
        }
    }
    out
}

/// Decide [`Enabling`] for the methods of `rows`. An extension is refused only for a
/// method that it alone would make unsafe: one whose every rule left to the caller
/// needs it (or another extension foreign to the method); a method that owns a rule
/// without them is `unsafe` anyway, and lists the extension's rules with its own.
pub fn enabling(cx: &Context, rows: &[MethodRow], records: &[Record]) -> Enabling {
    let settlement: BTreeMap<&str, &Settlement> = records
        .iter()
        .map(|r| (r.vuid.as_str(), &r.settlement))
        .collect();
    let by_item = rules_by_item(cx);
    let mut out = Enabling {
        allowed: cx.model.enabled.clone(),
        refused: Vec::new(),
    };
    loop {
        let owns: Vec<std::collections::BTreeSet<String>> = rows
            .iter()
            .map(|r| own_names(cx, &r.command, &out.allowed))
            .collect();
        let mut blocked: BTreeMap<String, Vec<Owned>> = BTreeMap::new();
        for (row, own) in rows.iter().zip(&owns) {
            let left: Vec<&Rule> = row
                .items
                .iter()
                .flat_map(|i| by_item.get(i.as_str()).into_iter().flatten())
                .copied()
                .filter(|rule| {
                    !enforced_by_method(&settlement, &rule.vuid)
                        && unclassed(rule)
                        && reachable(cx, rule, &out.allowed)
                })
                .collect();
            let foreign: Vec<Vec<&str>> = left
                .iter()
                .map(|rule| needed(cx, rule, &out.allowed, own))
                .collect();
            if left.is_empty() || foreign.iter().any(Vec::is_empty) {
                continue;
            }
            for (rule, xs) in left.iter().zip(&foreign) {
                for x in xs {
                    let list = blocked.entry((*x).to_owned()).or_default();
                    if !list.iter().any(|o| o.vuid == rule.vuid) {
                        list.push(Owned {
                            vuid: rule.vuid.clone(),
                            text: crate::validity::explicit::plain(&rule.text),
                        });
                    }
                }
            }
        }
        if blocked.is_empty() {
            break;
        }
        for (x, rules) in blocked {
            out.allowed.remove(&x);
            out.refused.push((x, rules));
        }
    }
    out.refused.sort_by(|a, b| a.0.cmp(&b.0));
    out
}

/// The safety of every method of `rows`, by command name, in programs that enable
/// only what `enabling` allows.
pub fn decide(
    cx: &Context,
    rows: &[MethodRow],
    records: &[Record],
    enabling: &Enabling,
) -> BTreeMap<String, MethodSafety> {
    let settlement: BTreeMap<&str, &Settlement> = records
        .iter()
        .map(|r| (r.vuid.as_str(), &r.settlement))
        .collect();
    let by_item = rules_by_item(cx);
    rows.iter()
        .map(|row| {
            // A refused extension's own methods still answer for its rules: a
            // program that enables it through `unsafe` code calls them.
            let mut reach = enabling.allowed.clone();
            reach.extend(own_names(cx, &row.command, &enabling.allowed));
            let mut out = MethodSafety::default();
            for rule in row
                .items
                .iter()
                .flat_map(|i| by_item.get(i.as_str()).into_iter().flatten())
            {
                if enforced_by_method(&settlement, &rule.vuid) {
                    continue;
                }
                // A rule only an extension the safe constructors refuse can reach is
                // the extension class's.
                let class = match reachable(cx, rule, &reach) {
                    false => Some(0),
                    true => REVIEWED.iter().position(|c| (c.holds)(rule)),
                };
                match class {
                    Some(class) => out.classed.push((rule.vuid.clone(), class)),
                    None => out.owned.push(Owned {
                        vuid: rule.vuid.clone(),
                        text: crate::validity::explicit::plain(&rule.text),
                    }),
                }
            }
            (row.command.clone(), out)
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn rule(vuid: &str, item: &str, key_holds: Option<bool>) -> Rule {
        Rule {
            vuid: vuid.into(),
            category: crate::validity::Category::Usage,
            item: item.into(),
            condition: "core".into(),
            emitted: true,
            listed: true,
            derived: false,
            text: "x".into(),
            key_holds,
            key: None,
        }
    }

    #[test]
    fn classes_take_only_what_they_name() {
        let ext = &REVIEWED[0];
        assert!((ext.holds)(&rule("VUID-a-b-1", "vkCmdDraw", Some(false))));
        assert!(!(ext.holds)(&rule("VUID-a-b-1", "vkCmdDraw", Some(true))));
        assert!(!(ext.holds)(&rule("VUID-a-b-1", "vkCmdDraw", None)));
        let shader = &REVIEWED[1];
        assert!((shader.holds)(&rule(
            "VUID-vkCmdDraw-None-07288",
            "vkCmdDraw",
            None
        )));
        assert!(!(shader.holds)(&rule(
            "VUID-vkCmdDraw-None-02697",
            "vkCmdDraw",
            None
        )));
        assert!(!(shader.holds)(&rule("VUID-VkX-None-07288", "VkX", None)));
        let ownership = REVIEWED
            .iter()
            .find(|c| c.name.starts_with("queue family ownership"))
            .expect("the ownership class");
        assert!((ownership.holds)(&rule(
            "VUID-vkQueueSubmit-pSubmits-02808",
            "vkQueueSubmit",
            None
        )));
        assert!(!(ownership.holds)(&rule(
            "VUID-vkQueueSubmit-pCommandBuffers-00074",
            "vkQueueSubmit",
            None
        )));
    }

    #[test]
    fn checked_rules_are_enforced_and_user_rules_are_not() {
        assert!(enforced(&Settlement::Static("t".into())));
        assert!(enforced(&Settlement::Dynamic("c".into())));
        assert!(enforced(&Settlement::User(format!(
            "{}, yet",
            super::super::settle::CHECKED_UNPROVEN
        ))));
        assert!(!enforced(&Settlement::User("explicit rule".into())));
    }
}
