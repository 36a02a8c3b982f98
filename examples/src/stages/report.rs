//! The stage benchmark's samples as CSV, and their summary: median and 90th
//! percentile per stage and variant, as a ratio to raw ash, in a Markdown table and
//! an SVG chart.

use super::{Sample, Stage};
use anyhow::{bail, Context as _, Result};
use std::collections::BTreeMap;
use std::fmt::Write as _;

/// The variants, in the order they run and appear, with their table headings. The
/// first is the baseline every ratio is to. `vulkano` is the peer: the same frame loop
/// through vulkano's automatic command buffer builder (headless only).
pub const VARIANTS: [(&str, &str); 10] = [
    ("ash", "raw ash"),
    ("tuff", "tuff"),
    ("tuff-before", "tuff, earlier build"),
    ("tuff-auto", "tuff `auto_sync`"),
    ("tuff-untracked", "tuff without hazard tracking"),
    ("tuff-mt", "tuff `multi_thread`"),
    ("tuff-checks", "tuff + implicit checks"),
    ("vulkano", "vulkano (automatic builder)"),
    ("ash-layer", "ash + layer"),
    ("ash-sync", "ash + layer + sync"),
];

/// One timed frame of one run.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Row {
    /// `headless` or `window`.
    pub mode: String,
    /// One of [`VARIANTS`].
    pub variant: String,
    /// Teapots.
    pub count: u32,
    /// Camera blocks written per frame.
    pub writes: u32,
    /// Which pass over the variants the run belonged to.
    pub round: u32,
    /// Nanoseconds per stage, indexed as [`Stage::ALL`].
    pub sample: Sample,
}

/// The CSV header line.
pub fn csv_header() -> String {
    let stages: Vec<&str> = Stage::ALL.iter().map(|s| s.name()).collect();
    format!("mode,variant,count,writes,round,{}", stages.join(","))
}

impl Row {
    /// The row as a CSV line (no newline).
    pub fn to_csv(&self) -> String {
        let times: Vec<String> = self.sample.iter().map(u64::to_string).collect();
        format!(
            "{},{},{},{},{},{}",
            self.mode,
            self.variant,
            self.count,
            self.writes,
            self.round,
            times.join(",")
        )
    }

    /// Parses a line [`Row::to_csv`] wrote; `line_no` is for the error.
    pub fn from_csv(line: &str, line_no: usize) -> Result<Row> {
        let fields: Vec<&str> = line.trim().split(',').collect();
        if fields.len() != 5 + Stage::ALL.len() {
            bail!(
                "line {line_no}: {} fields where the header has {}",
                fields.len(),
                5 + Stage::ALL.len()
            );
        }
        let num = |i: usize| -> Result<u64> {
            fields[i].parse().with_context(|| {
                format!(
                    "line {line_no}, field {}: {:?} is not a number",
                    i + 1,
                    fields[i]
                )
            })
        };
        let mut sample = [0; 6];
        for (i, t) in sample.iter_mut().enumerate() {
            *t = num(5 + i)?;
        }
        Ok(Row {
            mode: fields[0].to_owned(),
            variant: fields[1].to_owned(),
            count: u32::try_from(num(2)?)?,
            writes: u32::try_from(num(3)?)?,
            round: u32::try_from(num(4)?)?,
            sample,
        })
    }
}

/// Reads the rows of a CSV file's text: `#` lines are comments, the header must be
/// [`csv_header`].
pub fn parse_csv(text: &str) -> Result<Vec<Row>> {
    let mut rows = Vec::new();
    let mut header = false;
    for (i, line) in text.lines().enumerate() {
        if line.starts_with('#') || line.trim().is_empty() {
            continue;
        }
        if !header {
            if line.trim() != csv_header() {
                bail!("line {}: expected the header {:?}", i + 1, csv_header());
            }
            header = true;
            continue;
        }
        rows.push(Row::from_csv(line, i + 1)?);
    }
    Ok(rows)
}

/// The value below which `q` (0 to 1) of `sorted` lies, by the nearest rank; 0 for
/// no values.
pub fn quantile(sorted: &[u64], q: f64) -> u64 {
    if sorted.is_empty() {
        return 0;
    }
    let rank = (q * sorted.len() as f64).ceil() as usize;
    sorted[rank.clamp(1, sorted.len()) - 1]
}

/// Median and 90th percentile of one stage (or of whole frames).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Stat {
    /// Median, ns.
    pub median: u64,
    /// 90th percentile, ns.
    pub p90: u64,
}

impl Stat {
    fn of(mut values: Vec<u64>) -> Stat {
        values.sort_unstable();
        Stat {
            median: quantile(&values, 0.5),
            p90: quantile(&values, 0.9),
        }
    }
}

/// A configuration: mode, teapots, writes.
pub type Config = (String, u32, u32);

/// Every configuration's variants' statistics: per stage as [`Stage::ALL`], then the
/// whole frame (the sum of its stages).
pub fn summarise(rows: &[Row]) -> BTreeMap<Config, BTreeMap<String, [Stat; 7]>> {
    let mut groups: BTreeMap<(Config, String), Vec<&Row>> = BTreeMap::new();
    for r in rows {
        groups
            .entry(((r.mode.clone(), r.count, r.writes), r.variant.clone()))
            .or_default()
            .push(r);
    }
    let mut out: BTreeMap<Config, BTreeMap<String, [Stat; 7]>> = BTreeMap::new();
    for ((config, variant), rows) in groups {
        let mut stats = [Stat::default(); 7];
        for (i, stat) in stats.iter_mut().enumerate().take(6) {
            *stat = Stat::of(rows.iter().map(|r| r.sample[i]).collect());
        }
        stats[6] = Stat::of(rows.iter().map(|r| r.sample.iter().sum()).collect());
        out.entry(config).or_default().insert(variant, stats);
    }
    out
}

/// `a / b`, or NaN when `b` is 0.
fn ratio(a: u64, b: u64) -> f64 {
    if b == 0 {
        f64::NAN
    } else {
        a as f64 / b as f64
    }
}

/// Nanoseconds as a short human figure in µs or ms.
pub fn time(ns: u64) -> String {
    let us = ns as f64 / 1e3;
    if us >= 1000.0 {
        format!("{:.2} ms", us / 1e3)
    } else if us >= 10.0 {
        format!("{us:.1} µs")
    } else {
        format!("{us:.2} µs")
    }
}

/// Frames per second of a frame of `ns` nanoseconds: whole frames from 100 up, three
/// significant figures below.
fn fps(ns: u64) -> String {
    let f = 1e9 / ns.max(1) as f64;
    if f >= 100.0 {
        format!("{f:.0}")
    } else if f >= 10.0 {
        format!("{f:.1}")
    } else {
        format!("{f:.2}")
    }
}

/// The Markdown tables: one per configuration, a row per stage, a column per variant
/// present. Raw ash's cells give its median and p90; the others' their ratio to raw
/// ash's median and p90, then their own median. Wait, acquire and the whole frame
/// (with frames per second) follow the table's stages, apart.
pub fn markdown(rows: &[Row]) -> String {
    let summary = summarise(rows);
    let mut md = String::new();
    for ((mode, count, writes), variants) in &summary {
        let present: Vec<(&str, &str)> = VARIANTS
            .iter()
            .copied()
            .filter(|(v, _)| variants.contains_key(*v))
            .collect();
        let frames = rows
            .iter()
            .filter(|r| &r.mode == mode && r.count == *count && r.writes == *writes)
            .filter(|r| r.variant == present.first().map_or("", |p| p.0))
            .count();
        let _ = writeln!(
            md,
            "\n**{mode}, {count} teapot{}, {writes} uniform write{} per frame** ({frames} frames per variant)\n",
            if *count == 1 { "" } else { "s" },
            if *writes == 1 { "" } else { "s" },
        );
        let heads: Vec<&str> = present.iter().map(|p| p.1).collect();
        let _ = writeln!(md, "| Stage | {} |", heads.join(" | "));
        let _ = writeln!(md, "|---|{}", "---:|".repeat(present.len()));
        let base = variants.get("ash");
        let mut line = |label: &str, i: usize, fps: bool| {
            let mut cells = Vec::new();
            for (v, _) in &present {
                let s = variants[*v][i];
                let cell = match (base, *v == "ash") {
                    _ if fps => self::fps(s.median),
                    (_, true) | (None, _) => format!("{} (p90 {})", time(s.median), time(s.p90)),
                    (Some(b), false) => format!(
                        "{:.2}x (p90 {:.2}x), {}",
                        ratio(s.median, b[i].median),
                        ratio(s.p90, b[i].p90),
                        time(s.median)
                    ),
                };
                cells.push(cell);
            }
            let _ = writeln!(md, "| {label} | {} |", cells.join(" | "));
        };
        for stage in Stage::TABLE {
            let i = Stage::ALL.iter().position(|s| *s == stage).unwrap_or(0);
            line(stage.name(), i, false);
        }
        line("*wait (apart)*", 0, false);
        if mode == "window" {
            line("*acquire (apart)*", 1, false);
        }
        line("*whole frame*", 6, false);
        line("*frames/s (median frame)*", 6, true);
    }
    md
}

/// One table of a mode's configurations: a row per stage of each teapot count (and
/// the uniform stage of the many-writes run), raw ash's median time, every other
/// variant's median as a ratio to it; then frames per second (of the median frame)
/// per configuration. What README.md shows; [`markdown`] has the rest.
pub fn compact(rows: &[Row], mode: &str) -> String {
    let summary = summarise(rows);
    let configs: Vec<(&Config, &BTreeMap<String, [Stat; 7]>)> =
        summary.iter().filter(|((m, _, _), _)| m == mode).collect();
    let present: Vec<(&str, &str)> = VARIANTS
        .iter()
        .copied()
        .filter(|(v, _)| configs.iter().any(|(_, vs)| vs.contains_key(*v)))
        .collect();
    let mut md = String::new();
    let heads: Vec<&str> = present.iter().map(|p| p.1).collect();
    let _ = writeln!(md, "| Stage | Teapots | {} |", heads.join(" | "));
    let _ = writeln!(md, "|---|---:|{}", "---:|".repeat(present.len()));
    let mut line = |label: String, count: String, cells: Vec<String>| {
        let _ = writeln!(md, "| {label} | {count} | {} |", cells.join(" | "));
    };
    for stage in Stage::TABLE {
        let i = Stage::ALL.iter().position(|s| *s == stage).unwrap_or(0);
        for ((_, count, writes), variants) in &configs {
            if *writes > 1 && stage != Stage::Uniform {
                continue;
            }
            let base = variants.get("ash").map(|b| b[i].median);
            let cells = present
                .iter()
                .map(|(v, _)| match (variants.get(*v), base) {
                    (Some(s), Some(b)) if *v != "ash" => {
                        format!("{:.2}x ({})", ratio(s[i].median, b), time(s[i].median))
                    }
                    (Some(s), _) => time(s[i].median),
                    (None, _) => "-".into(),
                })
                .collect();
            let label = if *writes > 1 {
                format!("{} ({writes} writes)", stage.name())
            } else {
                stage.name().to_owned()
            };
            line(label, count.to_string(), cells);
        }
    }
    for ((_, count, writes), variants) in &configs {
        let cells = present
            .iter()
            .map(|(v, _)| variants.get(*v).map_or("-".into(), |s| fps(s[6].median)))
            .collect();
        let label = if *writes > 1 {
            format!("frames/s ({writes} writes)")
        } else {
            "frames/s".to_owned()
        };
        line(label, count.to_string(), cells);
    }
    md
}

/// A colour per variant after raw ash, as [`VARIANTS`] orders them.
const COLOURS: [&str; 8] = [
    "#2166ac", "#67a9cf", "#1b7837", "#7fbf7b", "#762a83", "#e08214", "#d6604d", "#b2182b",
];

/// A bar chart of each variant's median ratio to raw ash, per configuration and
/// stage of `mode`, on a log scale, with the line of 1x: a bar per variant the mode's
/// rows have (a variant keeps its colour from chart to chart). Self-contained SVG.
pub fn svg(rows: &[Row], mode: &str, title: &str) -> String {
    let summary = summarise(rows);
    let others: Vec<(usize, (&str, &str))> = VARIANTS[1..]
        .iter()
        .copied()
        .enumerate()
        .filter(|(_, (v, _))| rows.iter().any(|r| r.mode == mode && r.variant == *v))
        .collect();
    let mut groups = Vec::new();
    for ((m, count, writes), variants) in &summary {
        let Some(base) = variants.get("ash") else {
            continue;
        };
        if m != mode {
            continue;
        }
        for stage in Stage::TABLE {
            let i = Stage::ALL.iter().position(|s| *s == stage).unwrap_or(0);
            // With many writes only the uniform stage differs from the one-write run.
            if *writes > 1 && stage != Stage::Uniform {
                continue;
            }
            let bars: Vec<Option<f64>> = others
                .iter()
                .map(|(_, (v, _))| {
                    variants
                        .get(*v)
                        .map(|s| ratio(s[i].median, base[i].median))
                        .filter(|r| r.is_finite() && *r > 0.0)
                })
                .collect();
            let label = if *writes > 1 {
                format!("{count}: {} x{writes}", stage.name())
            } else {
                format!("{count}: {}", stage.name())
            };
            groups.push((label, bars));
        }
    }
    let (width, height) = (960.0f64, 420.0f64);
    let (left, right, top, bottom) = (60.0, width - 20.0, 70.0, height - 70.0);
    let values = groups.iter().flat_map(|g| g.1.iter().flatten().copied());
    let low = values.clone().fold(0.5f64, f64::min).log2().floor();
    let high = values.fold(2.0f64, f64::max).log2().ceil();
    let y = |r: f64| bottom - (bottom - top) * (r.log2() - low) / (high - low);
    let mut s = format!(
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{width}\" height=\"{height}\" \
         viewBox=\"0 0 {width} {height}\" font-family=\"sans-serif\" font-size=\"11\">\n\
         <rect width=\"{width}\" height=\"{height}\" fill=\"white\"/>\n\
         <text x=\"{}\" y=\"20\" text-anchor=\"middle\" font-size=\"15\">{}</text>\n",
        width / 2.0,
        escape(title)
    );
    let mut e = low;
    while e <= high {
        let r = 2f64.powf(e);
        let py = y(r);
        let _ =
            writeln!(
            s,
            "<line x1=\"{left}\" y1=\"{py:.1}\" x2=\"{right}\" y2=\"{py:.1}\" stroke=\"{}\"/>\n\
             <text x=\"{:.1}\" y=\"{:.1}\" text-anchor=\"end\">{}x</text>",
            if e == 0.0 { "#333" } else { "#ddd" },
            left - 4.0,
            py + 4.0,
            if r >= 1.0 { format!("{r:.0}") } else { format!("{r}") }
        );
        e += 1.0;
    }
    let slot = (right - left) / groups.len().max(1) as f64;
    let bar = slot * 0.8 / others.len().max(1) as f64;
    for (g, (label, bars)) in groups.iter().enumerate() {
        let x0 = left + slot * g as f64 + slot * 0.1;
        for (b, value) in bars.iter().enumerate() {
            let Some(r) = value else { continue };
            let (y1, y0) = (y(*r), y(1.0));
            let _ = writeln!(
                s,
                "<rect x=\"{:.1}\" y=\"{:.1}\" width=\"{:.1}\" height=\"{:.1}\" fill=\"{}\"><title>{} {}: {:.2}x</title></rect>",
                x0 + bar * b as f64,
                y1.min(y0),
                bar,
                (y1 - y0).abs().max(0.5),
                COLOURS[others[b].0 % COLOURS.len()],
                escape(label),
                escape(others[b].1 .1),
                r
            );
        }
        let cx = x0 + slot * 0.4;
        let _ = writeln!(
            s,
            "<text x=\"{cx:.1}\" y=\"{:.1}\" text-anchor=\"end\" transform=\"rotate(-40 {cx:.1} {:.1})\">{}</text>",
            bottom + 14.0,
            bottom + 14.0,
            escape(label)
        );
    }
    // The legend: four to a row, two rows above the plot.
    for (b, (colour, (_, name))) in others.iter().enumerate() {
        let lx = left + 10.0 + 220.0 * (b % 4) as f64;
        let ly = 30.0 + 16.0 * (b / 4) as f64;
        let _ = writeln!(
            s,
            "<rect x=\"{lx:.1}\" y=\"{ly:.1}\" width=\"12\" height=\"12\" fill=\"{}\"/>\
             <text x=\"{:.1}\" y=\"{:.1}\">{}</text>",
            COLOURS[colour % COLOURS.len()],
            lx + 16.0,
            ly + 10.0,
            escape(&name.replace('`', ""))
        );
    }
    s.push_str("</svg>\n");
    s
}

fn escape(text: &str) -> String {
    text.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
}

#[cfg(test)]
mod tests {
    use super::*;

    fn row(variant: &str, uniform: u64, command: u64) -> Row {
        Row {
            mode: "headless".into(),
            variant: variant.into(),
            count: 100,
            writes: 1,
            round: 0,
            sample: [5, 0, uniform, command, 7, 9],
        }
    }

    #[test]
    fn quantiles_take_the_nearest_rank() {
        let v: Vec<u64> = (1..=10).collect();
        assert_eq!(quantile(&v, 0.5), 5);
        assert_eq!(quantile(&v, 0.9), 9);
        assert_eq!(quantile(&v, 1.0), 10);
        assert_eq!(quantile(&[7], 0.9), 7);
        assert_eq!(quantile(&[], 0.5), 0);
    }

    #[test]
    fn rows_survive_a_round_trip_through_csv() {
        let rows = vec![row("ash", 100, 2000), row("tuff", 110, 2100)];
        let mut text = format!("# device: x\n{}\n", csv_header());
        for r in &rows {
            text.push_str(&r.to_csv());
            text.push('\n');
        }
        assert_eq!(parse_csv(&text).unwrap(), rows);
        let broken = format!("{}\nheadless,ash,1,1,0,1,2\n", csv_header());
        let err = parse_csv(&broken).unwrap_err().to_string();
        assert!(err.contains("line 2"), "{err}");
        assert!(parse_csv("mode,variant\n").is_err());
    }

    #[test]
    fn ratios_are_to_raw_ash_per_stage() {
        let mut rows = Vec::new();
        for i in 0..10 {
            rows.push(row("ash", 100 + i, 1000));
            rows.push(row("tuff", 200 + 2 * i, 1100));
        }
        let s = summarise(&rows);
        let v = &s[&("headless".to_owned(), 100, 1)];
        assert_eq!(v["ash"][2].median, 104);
        assert_eq!(v["tuff"][2].median, 208);
        let md = markdown(&rows);
        assert!(
            md.contains("| uniform | 0.10 µs (p90 0.11 µs) | 2.00x (p90 2.00x), 0.21 µs |"),
            "{md}"
        );
        assert!(
            md.contains("| command | 1.00 µs (p90 1.00 µs) | 1.10x (p90 1.10x), 1.10 µs |"),
            "{md}"
        );
        let table = compact(&rows, "headless");
        assert!(
            table.contains("| uniform | 100 | 0.10 µs | 2.00x (0.21 µs) |"),
            "{table}"
        );
        assert!(table.contains("| frames/s | 100 |"), "{table}");
        let svg = svg(&rows, "headless", "a <title>");
        assert!(svg.starts_with("<svg") && svg.ends_with("</svg>\n"));
        assert!(svg.contains("a &lt;title&gt;"));
        assert!(svg.contains("2.00x") && !svg.contains("NaN"));
    }

    #[test]
    fn a_variant_a_mode_lacks_is_left_out_of_its_tables_and_chart() {
        let mut rows = Vec::new();
        for mode in ["headless", "window"] {
            for variant in ["ash", "tuff", "vulkano"] {
                if mode == "window" && variant == "vulkano" {
                    continue;
                }
                let mut r = row(variant, 100, if variant == "ash" { 1000 } else { 3000 });
                r.mode = mode.into();
                rows.push(r);
            }
        }
        let headless = compact(&rows, "headless");
        assert!(
            headless.contains("| Stage | Teapots | raw ash | tuff | vulkano (automatic builder) |"),
            "{headless}"
        );
        assert!(
            headless.contains("| command | 100 | 1.00 µs | 3.00x (3.00 µs) | 3.00x (3.00 µs) |")
        );
        let window = compact(&rows, "window");
        assert!(
            window.contains("| Stage | Teapots | raw ash | tuff |\n"),
            "{window}"
        );
        let md = markdown(&rows);
        assert!(md.contains("| Stage | raw ash | tuff | vulkano (automatic builder) |"));
        assert!(md.contains("| Stage | raw ash | tuff |\n"), "{md}");
        let chart = svg(&rows, "window", "window");
        assert!(
            !chart.contains("vulkano") && chart.contains(">tuff<"),
            "{chart}"
        );
        let chart = svg(&rows, "headless", "headless");
        assert!(
            chart.contains("vulkano (automatic builder): 3.00x"),
            "{chart}"
        );
    }
}
