//! `validation.json`: one entry per VUID, one line per entry so diffs stay readable.

use super::{Report, Table};
use crate::validity::Category;
use serde::Serialize;

#[derive(Serialize)]
struct Entry<'a> {
    vuid: &'a str,
    category: Category,
    item: &'a str,
    condition: &'a str,
    emitted: bool,
    /// In the emitted API and filed by validusage.json under a key that holds for
    /// it: the rules of the report's stricter table. `None` where the keys carry
    /// no conditions.
    #[serde(skip_serializing_if = "Option::is_none")]
    strict: Option<bool>,
    status: &'a str,
    mechanism: &'a str,
    listed: bool,
    derived: bool,
}

#[derive(Serialize)]
struct Header<'a> {
    registry_version: &'a str,
    emitted_api: &'a [String],
    explicit_rules_known: bool,
    tables: Tables,
}

#[derive(Serialize)]
struct Tables {
    emitted: TableJson,
    registry: TableJson,
}

#[derive(Serialize)]
struct TableJson {
    categories: [&'static str; 3],
    statuses: [&'static str; 3],
    counts: [[usize; 3]; 3],
    total: usize,
}

fn table(t: &Table) -> TableJson {
    TableJson {
        categories: ["implicit", "creation", "usage"],
        statuses: ["static", "dynamic", "user"],
        counts: t.counts,
        total: t.total(),
    }
}

pub(super) fn render(report: &Report) -> String {
    let header = Header {
        registry_version: &report.version,
        emitted_api: &report.enabled,
        explicit_rules_known: report.validity.explicit_known,
        tables: Tables {
            emitted: table(&report.emitted),
            registry: table(&report.registry),
        },
    };
    // The header is small: pretty-print it, then splice the rules in one per line.
    let mut out = serde_json::to_string_pretty(&header).unwrap_or_default();
    out.truncate(out.trim_end().len() - 1);
    out.push_str(",\n  \"rules\": [\n");
    let n = report.settled.len();
    for (i, s) in report.settled.iter().enumerate() {
        let entry = Entry {
            vuid: &s.rule.vuid,
            category: s.rule.category,
            item: &s.rule.item,
            condition: &s.rule.condition,
            emitted: s.rule.emitted,
            strict: s.rule.key_holds.map(|holds| {
                holds && s.rule.emitted && (s.rule.listed || !report.validity.explicit_known)
            }),
            status: s.settlement.status(),
            mechanism: s.settlement.mechanism(),
            listed: s.rule.listed,
            derived: s.rule.derived,
        };
        out.push_str("    ");
        out.push_str(&serde_json::to_string(&entry).unwrap_or_default());
        if i + 1 < n {
            out.push(',');
        }
        out.push('\n');
    }
    out.push_str("  ]\n}\n");
    out
}
