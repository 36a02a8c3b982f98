//! Report pass: tally the rules by category and by how the emitters settled them, and
//! render `VALIDATION.md`, `validation.json` and `validation.svg`.
//!
//! The tally only reads the records handed to it: a rule no record names is counted
//! as left to the user, with that reason.

mod json;
mod markdown;
mod svg;

use crate::emit::OutputFile;
use crate::model::Model;
use crate::plan::{Record, Settlement};
use crate::validity::{Category, Rule, Validity};
use std::collections::BTreeMap;

/// Why a rule is left to the user when no emitter recorded anything about it.
pub const UNSETTLED: &str = "no emitted wrapper checks it yet";

/// Where the per-extension table counts the rules of SPIR-V and built-in entities,
/// which belong to no version or extension of the registry.
pub const SPIRV_HOME: &str = "SPIR-V and built-ins";

/// Counts of one table: category by status.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, serde::Serialize)]
pub struct Table {
    /// `[category][status]`, categories as in [`Category::ALL`], statuses static,
    /// dynamic, user.
    pub counts: [[usize; 3]; 3],
}

impl Table {
    fn add(&mut self, category: Category, settlement: &Settlement) {
        let row = Category::ALL
            .iter()
            .position(|c| *c == category)
            .unwrap_or(0);
        let col = match settlement {
            Settlement::Static(_) => 0,
            Settlement::Dynamic(_) => 1,
            Settlement::User(_) => 2,
        };
        self.counts[row][col] += 1;
    }

    /// Rules of a category.
    pub fn row_total(&self, row: usize) -> usize {
        self.counts[row].iter().sum()
    }

    /// Rules with a status.
    pub fn column_total(&self, col: usize) -> usize {
        self.counts.iter().map(|r| r[col]).sum()
    }

    /// All rules.
    pub fn total(&self) -> usize {
        self.counts.iter().flatten().sum()
    }
}

/// A rule with its settlement.
#[derive(Debug, Clone)]
pub struct Settled<'a> {
    /// The rule.
    pub rule: &'a Rule,
    /// How it is settled.
    pub settlement: Settlement,
}

/// Everything the renderers need.
#[derive(Debug, Clone)]
pub struct Report<'a> {
    /// Registry version.
    pub version: String,
    /// Versions and extensions of the emitted API.
    pub enabled: Vec<String>,
    /// Every rule with its settlement, in the validity pass's order.
    pub settled: Vec<Settled<'a>>,
    /// The emitted API's table.
    pub emitted: Table,
    /// The whole registry's table, over the rules validusage.json lists (or over the
    /// derived rules without it).
    pub registry: Table,
    /// The emitted API's table counting only rules whose validusage.json condition
    /// key also holds; `None` when the keys carry no conditions.
    pub emitted_by_key: Option<Table>,
    /// Emitted rules of entities that are not registry items (SPIR-V, built-ins).
    pub emitted_non_items: usize,
    /// Of those, the usage rules whose validusage.json key holds (counted in
    /// `emitted_by_key`).
    pub emitted_non_items_by_key: usize,
    /// Derived implicit rules of items validusage.json does not list.
    pub unlisted_derived: usize,
    /// VUIDs that records name but no rule has: an emitter bug, shown in the report.
    pub unknown_records: Vec<String>,
    /// The validity pass's result.
    pub validity: &'a Validity,
    /// The rules that apply to each emitted method, tallied; empty unless
    /// [`Report::add_methods`] ran.
    pub methods: Vec<MethodTally>,
    /// The emitted API's table split by the version or extension each rule's item
    /// belongs to ([`Model::home`]); rules of SPIR-V and built-in entities under
    /// [`SPIRV_HOME`].
    pub by_home: BTreeMap<String, Table>,
    /// The reviewed classes with their rules; empty unless [`Report::add_methods`] ran.
    pub classes: Vec<ClassTally>,
    /// The reference registry's version, when the config names one.
    pub reference_version: Option<String>,
    /// The extensions left out because the reference lacks them or defines them
    /// otherwise, with the reason.
    pub left_out: Vec<crate::model::reference::LeftOut>,
    /// The emitted extensions the safe constructors refuse, with the rules each
    /// would bring to other methods; empty unless [`Report::add_methods`] ran.
    pub refused: Vec<(String, Vec<crate::plan::safety::Owned>)>,
    /// The hazard tracker's reach: the emitted recording commands whose accesses it
    /// knows (with what each reads and writes), and those it leaves to the user.
    pub accesses: Accesses,
}

/// Which recording commands the hazard tracker knows (`plan/accesses.rs`).
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct Accesses {
    /// The registry version of the sync tables, if any.
    pub tables: Option<String>,
    /// Each known command, with its accesses (`reads ... at ...`) and what else it
    /// does to the tracker.
    pub known: Vec<(String, Vec<String>)>,
    /// The emitted recording commands whose accesses it does not know.
    pub left: Vec<String>,
}

impl Accesses {
    fn of(model: &Model) -> Self {
        let recording = model
            .commands
            .keys()
            .filter(|c| c.starts_with("vkCmd") && model.emitted.contains(c.as_str()));
        let mut out = Accesses {
            tables: model.sync.as_ref().map(|t| t.version.clone()),
            ..Accesses::default()
        };
        for c in recording {
            match crate::plan::accesses::row(c).filter(|_| model.sync.is_some()) {
                Some(row) => out.known.push((
                    c.clone(),
                    row.uses
                        .iter()
                        .map(|u| {
                            let what = match u.role {
                                "dst" => "writes",
                                "vertex" => "reads vertex buffers:",
                                "index" => "reads the index buffer:",
                                _ => "reads",
                            };
                            format!(
                                "{what} `{}` at `{}`",
                                u.access,
                                u.stage.replace(',', "` or `")
                            )
                        })
                        .chain((!row.does.is_empty()).then(|| row.does.to_owned()))
                        .collect(),
                )),
                None => out.left.push(c.clone()),
            }
        }
        out
    }
}

/// The rules that apply to one emitted method: its command's and those of every
/// struct a call can pass.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct MethodTally {
    /// The safe method, with its type (`Queue::submit`).
    pub method: String,
    /// Whether the scenes call it.
    pub scenes: bool,
    /// Rules that apply, statically solved, dynamically solved, left to the caller.
    pub counts: [usize; 4],
    /// Whether the method is emitted safe (`plan/safety.rs`).
    pub safe: bool,
    /// Rules the caller of the method owns: not enforced, in no reviewed class.
    pub owned: usize,
    /// Those rules, by VUID and text.
    pub owned_rules: Vec<crate::plan::safety::Owned>,
    /// Whether the caller vouches for a raw parameter or an unlocked object.
    pub raw: bool,
    /// The version or extension the command belongs to (`VK_VERSION_1_0`).
    pub home: String,
    /// The safe form of an indirect command, and the rules it settles of those the
    /// method leaves its caller (`plan/special/indirect.rs`).
    pub form: Option<(&'static str, usize)>,
}

/// One reviewed class of rules a safe method may leave unchecked.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ClassTally {
    /// Its name.
    pub name: &'static str,
    /// Why its rules cannot break memory safety through safe code.
    pub reason: &'static str,
    /// The rules in it that a safe method leaves unchecked.
    pub rules: Vec<String>,
}

impl Report<'_> {
    /// Tally the rules of each method's items (strict rules where the registry's keys
    /// say which hold), those of the commands in `scenes` (which the scene programs
    /// call) first.
    pub fn add_methods(
        &mut self,
        rows: &[crate::plan::methods::MethodRow],
        safety: &BTreeMap<String, crate::plan::safety::MethodSafety>,
        enabling: &crate::plan::safety::Enabling,
        scenes: &std::collections::BTreeSet<String>,
        home: impl Fn(&str) -> String,
    ) {
        self.refused = enabling.refused.clone();
        let mut classes: Vec<ClassTally> = crate::plan::safety::REVIEWED
            .iter()
            .map(|c| ClassTally {
                name: c.name,
                reason: c.reason,
                rules: Vec::new(),
            })
            .collect();
        for (vuid, class) in safety.values().flat_map(|m| &m.classed) {
            classes[*class].rules.push(vuid.clone());
        }
        for c in &mut classes {
            c.rules.sort();
            c.rules.dedup();
        }
        self.classes = classes;
        let mut by_item: BTreeMap<&str, Vec<&str>> = BTreeMap::new();
        for st in &self.settled {
            let counted = st.rule.emitted
                && (st.rule.listed || !self.validity.explicit_known)
                && st.rule.key_holds != Some(false);
            if counted {
                by_item
                    .entry(st.rule.item.as_str())
                    .or_default()
                    .push(st.settlement.status());
            }
        }
        let mut out: Vec<MethodTally> = rows
            .iter()
            .map(|row| {
                let mut counts = [0usize; 4];
                for status in row
                    .items
                    .iter()
                    .flat_map(|i| by_item.get(i.as_str()).into_iter().flatten())
                {
                    counts[0] += 1;
                    counts[match *status {
                        "static" => 1,
                        "dynamic" => 2,
                        _ => 3,
                    }] += 1;
                }
                let method_safety = safety.get(&row.command);
                let owned_rules = method_safety.map(|m| m.owned.clone()).unwrap_or_default();
                MethodTally {
                    method: format!("{}::{}", row.receiver, row.method),
                    scenes: scenes.contains(&row.command),
                    counts,
                    safe: method_safety.is_none_or(|m| m.safe()),
                    owned: owned_rules.len(),
                    raw: method_safety.is_some_and(|m| m.raw),
                    home: home(&row.command),
                    form: crate::plan::special::indirect::form(&row.command).map(|f| {
                        let settled = owned_rules
                            .iter()
                            .filter(|o| f.settles.iter().any(|(v, _)| *v == o.vuid))
                            .count();
                        (f.method, settled)
                    }),
                    owned_rules,
                }
            })
            .collect();
        out.sort_by(|a, b| b.scenes.cmp(&a.scenes).then(a.method.cmp(&b.method)));
        self.methods = out;
    }
}

/// Tally the rules with the emitters' records.
pub fn build<'a>(model: &Model, validity: &'a Validity, records: &[Record]) -> Report<'a> {
    let by_vuid: BTreeMap<&str, &Settlement> = records
        .iter()
        .map(|r| (r.vuid.as_str(), &r.settlement))
        .collect();
    let mut report = Report {
        version: model.version.clone(),
        enabled: model.enabled.iter().cloned().collect(),
        settled: Vec::with_capacity(validity.rules.len()),
        emitted: Table::default(),
        registry: Table::default(),
        emitted_by_key: None,
        emitted_non_items: 0,
        emitted_non_items_by_key: 0,
        unlisted_derived: 0,
        unknown_records: Vec::new(),
        validity,
        methods: Vec::new(),
        by_home: BTreeMap::new(),
        classes: Vec::new(),
        reference_version: model.reference_version.clone(),
        left_out: model.left_out.clone(),
        refused: Vec::new(),
        accesses: Accesses::of(model),
    };
    let known: std::collections::BTreeSet<&str> =
        validity.rules.iter().map(|r| r.vuid.as_str()).collect();
    report.unknown_records = records
        .iter()
        .filter(|r| !known.contains(r.vuid.as_str()))
        .map(|r| r.vuid.clone())
        .collect();
    for rule in &validity.rules {
        let settlement = by_vuid
            .get(rule.vuid.as_str())
            .map(|s| (*s).clone())
            .unwrap_or_else(|| Settlement::User(UNSETTLED.to_owned()));
        let counts_for_registry = rule.listed || !validity.explicit_known;
        if counts_for_registry {
            report.registry.add(rule.category, &settlement);
        } else {
            report.unlisted_derived += 1;
        }
        if rule.emitted && counts_for_registry {
            report.emitted.add(rule.category, &settlement);
            let non_item =
                !model.types.contains_key(&rule.item) && !model.commands.contains_key(&rule.item);
            report.emitted_non_items += usize::from(non_item);
            let home = match non_item {
                true => SPIRV_HOME.to_owned(),
                false => model.home(&rule.item),
            };
            report
                .by_home
                .entry(home)
                .or_default()
                .add(rule.category, &settlement);
            if let Some(holds) = rule.key_holds {
                let table = report.emitted_by_key.get_or_insert_with(Table::default);
                if holds {
                    table.add(rule.category, &settlement);
                    report.emitted_non_items_by_key +=
                        usize::from(non_item && rule.category == Category::Usage);
                }
            }
        }
        report.settled.push(Settled { rule, settlement });
    }
    report
}

/// Render the three report files.
pub fn render(report: &Report) -> Vec<OutputFile> {
    vec![
        OutputFile {
            path: "VALIDATION.md".into(),
            contents: markdown::render(report),
        },
        OutputFile {
            path: "validation.json".into(),
            contents: json::render(report),
        },
        OutputFile {
            path: "validation.svg".into(),
            contents: svg::render(report),
        },
    ]
}
