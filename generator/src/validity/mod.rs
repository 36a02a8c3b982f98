//! Validity pass: every valid-usage rule of the registry, with its category, item,
//! condition and whether it belongs to the emitted API.
//!
//! Implicit rules are derived from the model ([`implicit`]) and compared with the ones
//! validusage.json lists; explicit rules come from validusage.json and are classified
//! as *creation* or *usage* ([`classify`]).

pub mod classify;
pub mod explicit;
pub mod implicit;

use crate::model::Model;
use crate::registry::ValidUsage;
use std::collections::{BTreeMap, BTreeSet};

pub use implicit::{DerivedRule, ImplicitKind, Toolchain};

/// The three categories of the coverage table.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash, serde::Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Category {
    /// Rules the specification derives from the registry's markup.
    Implicit,
    /// Explicit rules of creating or allocating objects.
    Creation,
    /// All other explicit rules.
    Usage,
}

impl Category {
    /// All categories, in table order.
    pub const ALL: [Category; 3] = [Category::Implicit, Category::Creation, Category::Usage];

    /// The name used in the report.
    pub fn name(self) -> &'static str {
        match self {
            Category::Implicit => "implicit",
            Category::Creation => "creation",
            Category::Usage => "usage",
        }
    }
}

/// One valid-usage rule.
#[derive(Debug, Clone, PartialEq, Eq, serde::Serialize)]
pub struct Rule {
    /// The VUID.
    pub vuid: String,
    /// Its category.
    pub category: Category,
    /// The command, struct or other entity it belongs to.
    pub item: String,
    /// `core` or the expression of versions and extensions the item needs.
    pub condition: String,
    /// Whether the item is in the emitted API.
    pub emitted: bool,
    /// Whether validusage.json lists the rule.
    pub listed: bool,
    /// Whether the implicit derivation produced the rule.
    pub derived: bool,
    /// The rule's text: validusage.json's (HTML) when listed, else the derivation's.
    pub text: String,
    /// Whether the condition validusage.json files the rule under holds for the
    /// emitted API; `None` where the file's keys carry no conditions (every rule
    /// under `core`, as from 1.3.255 on) or the rule is not listed.
    pub key_holds: Option<bool>,
    /// That condition as validusage.json writes it (an expression of versions and
    /// extensions), where [`Rule::key_holds`] is known.
    #[serde(skip)]
    pub key: Option<String>,
}

/// Derived against listed implicit rules, over the items validusage.json lists.
#[derive(Debug, Clone, Default, PartialEq, Eq, serde::Serialize)]
pub struct Comparison {
    /// Implicit rules derived for listed items.
    pub derived: usize,
    /// Implicit rules validusage.json lists.
    pub listed: usize,
    /// Rules in both.
    pub both: usize,
    /// Derived but not listed.
    pub only_derived: Vec<String>,
    /// Listed but not derived.
    pub only_listed: Vec<String>,
    /// Implicit rules derived for items validusage.json does not list at all.
    pub unlisted_items_rules: usize,
}

impl Comparison {
    /// Share of listed rules that were derived.
    pub fn recall(&self) -> f64 {
        ratio(self.both, self.listed)
    }

    /// Share of derived rules that are listed.
    pub fn precision(&self) -> f64 {
        ratio(self.both, self.derived)
    }
}

fn ratio(a: usize, b: usize) -> f64 {
    if b == 0 {
        1.0
    } else {
        a as f64 / b as f64
    }
}

/// The outcome of the validity pass.
#[derive(Debug, Clone)]
pub struct Validity {
    /// Every rule: those validusage.json lists, in its order, then the derived rules it
    /// lacks.
    pub rules: Vec<Rule>,
    /// The comparison of derived and listed implicit rules; `None` without
    /// validusage.json.
    pub comparison: Option<Comparison>,
    /// Whether explicit rules are known (validusage.json was given).
    pub explicit_known: bool,
    /// The derived implicit rules with the kind and field each is about, which the
    /// emitters read to settle them.
    pub derived: Vec<DerivedRule>,
    /// The explicit rules of emitted structs that the recognisers read, as checks.
    pub recognised: Vec<explicit::Recognised>,
}

/// Run the pass. Without `validusage`, only the derived implicit rules are known.
pub fn analyze(model: &Model, validusage: Option<&ValidUsage>) -> Validity {
    analyze_with(model, validusage, &model.enabled)
}

/// [`analyze`], with the conditions validusage.json files rules under evaluated
/// against `reach` (the versions and extensions a safe program can enable) instead
/// of everything the config emits.
pub fn analyze_with(
    model: &Model,
    validusage: Option<&ValidUsage>,
    reach: &BTreeSet<String>,
) -> Validity {
    let toolchain = Toolchain::for_version(&model.version);
    let derived = implicit::derive_all(model, toolchain);
    let derived_by_vuid: BTreeMap<&str, &DerivedRule> =
        derived.iter().map(|r| (r.vuid.as_str(), r)).collect();
    let creation = classify::creation_items(model);

    let mut rules = Vec::new();
    let mut listed_vuids: BTreeSet<&str> = BTreeSet::new();
    let mut comparison = None;
    if let Some(vu) = validusage {
        let listed_items: BTreeSet<&str> = vu.entries.iter().map(|e| e.entity.as_str()).collect();
        let keys_informative = vu.entries.iter().any(|e| e.key != "core");
        let mut cmp = Comparison::default();
        for e in &vu.entries {
            listed_vuids.insert(&e.vuid);
            let category = if implicit::is_implicit_vuid(&e.vuid) {
                cmp.listed += 1;
                if derived_by_vuid.contains_key(e.vuid.as_str()) {
                    cmp.both += 1;
                } else {
                    cmp.only_listed.push(e.vuid.clone());
                }
                Category::Implicit
            } else {
                classify::explicit_category(&e.entity, &creation)
            };
            rules.push(Rule {
                vuid: e.vuid.clone(),
                category,
                item: e.entity.clone(),
                condition: model.condition(&e.entity).text().to_owned(),
                emitted: model.is_emitted(&e.entity),
                listed: true,
                derived: derived_by_vuid.contains_key(e.vuid.as_str()),
                text: e.text.trim().to_owned(),
                // A rule filed under an extension's absence (`+!(X)`) applies to
                // every program that leaves X off, whether or not X is emitted.
                key_holds: keys_informative.then(|| crate::model::expr::may_hold(&e.key, reach)),
                key: keys_informative.then(|| e.key.clone()),
            });
        }
        for r in &derived {
            if listed_items.contains(r.item.as_str()) {
                cmp.derived += 1;
                if !listed_vuids.contains(r.vuid.as_str()) {
                    cmp.only_derived.push(r.vuid.clone());
                }
            } else {
                cmp.unlisted_items_rules += 1;
            }
        }
        comparison = Some(cmp);
    }
    for r in &derived {
        if !listed_vuids.contains(r.vuid.as_str()) {
            rules.push(Rule {
                vuid: r.vuid.clone(),
                category: Category::Implicit,
                item: r.item.clone(),
                condition: model.condition(&r.item).text().to_owned(),
                emitted: model.is_emitted(&r.item),
                listed: false,
                derived: true,
                text: r.text.clone(),
                key_holds: None,
                key: None,
            });
        }
    }
    let recognised = explicit::recognise(model, &rules, reach);
    Validity {
        rules,
        comparison,
        explicit_known: validusage.is_some(),
        derived,
        recognised,
    }
}
