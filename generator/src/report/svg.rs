//! `validation.svg`: the two tables as horizontal stacked bars, one bar per category,
//! split into statically solved, dynamically solved and left to the user.

use super::{Report, Table};
use crate::validity::Category;
use std::fmt::Write;

const COLORS: [&str; 3] = ["#2e7d32", "#1565c0", "#c62828"];
const LABELS: [&str; 3] = ["statically solved", "dynamically solved", "left to user"];
const BAR_WIDTH: f64 = 560.0;

pub(super) fn render(r: &Report) -> String {
    let panels = [("Emitted API", &r.emitted), ("Whole registry", &r.registry)];
    let height = 60 + panels.len() * 150 + 30;
    let mut s = String::new();
    let _ = writeln!(
        s,
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="760" height="{height}" viewBox="0 0 760 {height}" font-family="sans-serif" font-size="13">"#
    );
    let _ = writeln!(s, r#"  <rect width="760" height="{height}" fill="white"/>"#);
    let _ = writeln!(
        s,
        r#"  <text x="20" y="28" font-size="16" font-weight="bold">Validation coverage, Vulkan {}</text>"#,
        r.version
    );
    // One scale for both panels, so bar lengths compare across them.
    let max = panels
        .iter()
        .flat_map(|(_, t)| (0..3).map(|i| t.row_total(i)))
        .max()
        .unwrap_or(0)
        .max(1) as f64;
    let mut y = 60;
    for (title, table) in panels {
        panel(&mut s, title, table, y, max);
        y += 150;
    }
    let mut x = 20.0;
    for (color, label) in COLORS.iter().zip(LABELS) {
        let _ = writeln!(
            s,
            r#"  <rect x="{x}" y="{y}" width="12" height="12" fill="{color}"/>"#
        );
        let _ = writeln!(
            s,
            r#"  <text x="{}" y="{}">{label}</text>"#,
            x + 18.0,
            y + 11
        );
        x += 170.0;
    }
    s.push_str("</svg>\n");
    s
}

fn panel(s: &mut String, title: &str, t: &Table, y0: usize, max: f64) {
    let _ = writeln!(
        s,
        r#"  <text x="20" y="{y0}" font-weight="bold">{title} ({} rules)</text>"#,
        t.total()
    );
    for (i, c) in Category::ALL.iter().enumerate() {
        let y = y0 + 14 + i * 36;
        let _ = writeln!(s, r#"  <text x="20" y="{}">{}</text>"#, y + 17, c.name());
        let mut x = 100.0;
        for (col, color) in COLORS.iter().enumerate() {
            let w = t.counts[i][col] as f64 / max * BAR_WIDTH;
            if w > 0.0 {
                let _ = writeln!(
                    s,
                    r#"  <rect x="{x:.1}" y="{y}" width="{w:.1}" height="24" fill="{color}"><title>{}: {} {}</title></rect>"#,
                    c.name(),
                    t.counts[i][col],
                    LABELS[col]
                );
            }
            x += w;
        }
        let _ = writeln!(
            s,
            r#"  <text x="{:.1}" y="{}">{}</text>"#,
            x + 6.0,
            y + 17,
            t.row_total(i)
        );
    }
}
