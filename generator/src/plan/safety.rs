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
        name: "needs an extension tuff does not emit",
        reason: "validusage.json files the rule under extensions outside the emitted API, so \
                 it applies only on an instance or device that enables one of them; the safe \
                 `create_instance` and `create_device` refuse every extension outside the \
                 emitted API (`Error::ExtensionNotEmitted`), so only `unsafe` code can reach it",
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
}

impl MethodSafety {
    /// Whether the method is emitted safe.
    pub fn safe(&self) -> bool {
        self.owned.is_empty()
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

/// The safety of every method of `rows`, by command name.
pub fn decide(
    cx: &Context,
    rows: &[MethodRow],
    records: &[Record],
) -> BTreeMap<String, MethodSafety> {
    let settlement: BTreeMap<&str, &Settlement> = records
        .iter()
        .map(|r| (r.vuid.as_str(), &r.settlement))
        .collect();
    let mut by_item: BTreeMap<&str, Vec<&Rule>> = BTreeMap::new();
    for rule in &cx.validity.rules {
        // Rules a registry lists for an item are the rules; derived ones it does not
        // list belong to items it leaves out.
        if rule.emitted && (rule.listed || !cx.validity.explicit_known) {
            by_item.entry(rule.item.as_str()).or_default().push(rule);
        }
    }
    rows.iter()
        .map(|row| {
            let mut out = MethodSafety::default();
            for rule in row
                .items
                .iter()
                .flat_map(|i| by_item.get(i.as_str()).into_iter().flatten())
            {
                if settlement
                    .get(rule.vuid.as_str())
                    .is_some_and(|s| enforced(s))
                {
                    continue;
                }
                match REVIEWED.iter().position(|c| (c.holds)(rule)) {
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
