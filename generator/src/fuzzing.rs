//! The fuzz targets' bodies (`fuzz/fuzz_targets/`). Each takes any bytes and must
//! return, never panic: a registry, rules or a config, or an error saying what is wrong
//! and where. They live here, not in the fuzz crate, so that `tests/fuzz_corpus.rs`
//! replays the committed seeds and every input a fuzzer found on the stable toolchain.

use crate::{config, passes, registry, Inputs};
use quick_xml::events::Event;
use std::path::Path;

/// `vk.xml` bytes through the reader and, when they read, every pass with every
/// extension emitted (no validusage.json, no reference registry, nothing written).
pub fn registry(bytes: &[u8]) {
    let path = Path::new("fuzz/vk.xml");
    let Ok(reg) = registry::parse_registry(path, bytes) else {
        return;
    };
    let config = config::Config {
        api_version: "1.3".into(),
        all_extensions: true,
        ..config::Config::default()
    };
    let _ = passes(&Inputs {
        registry_path: path,
        registry: &reg,
        reference: None,
        validusage: None,
        config: &config,
        config_path: Path::new("fuzz/tuff-gen.toml"),
        sources: &[],
    });
}

/// Structure-aware: `edits` read as whole-element edits of the registry `seed`
/// ([`apply_edits`]), the result through [`registry`]. Byte-level mutations of a
/// registry rarely survive the XML reader; these keep it well formed and reach the
/// passes with elements missing, repeated, moved and renamed.
pub fn registry_edits(seed: &str, edits: &[u8]) {
    registry(apply_edits(seed, edits).as_bytes());
}

/// `validusage.json` bytes through its reader.
pub fn validusage(bytes: &[u8]) {
    let _ = registry::parse_validusage(Path::new("fuzz/validusage.json"), bytes);
}

/// Config text through its reader (bytes that are not UTF-8 are an error the file
/// reader reports before parsing).
pub fn config(bytes: &[u8]) {
    if let Ok(text) = std::str::from_utf8(bytes) {
        let _ = config::Config::parse(Path::new("fuzz/tuff-gen.toml"), text);
    }
}

/// One element or text node of a document, by byte range.
#[derive(Clone, Copy)]
struct Node {
    /// Where it starts.
    start: usize,
    /// Where its start tag ends (an element) or where it ends (text).
    tag_end: usize,
    /// Where it ends, end tag included.
    end: usize,
    /// Text (else an element).
    text: bool,
}

/// The elements and text nodes of `doc`, in document order; empty where it is not
/// well formed.
fn nodes(doc: &str) -> Vec<Node> {
    let mut reader = quick_xml::Reader::from_str(doc);
    let mut out = Vec::new();
    let mut open: Vec<usize> = Vec::new();
    loop {
        let before = reader.buffer_position() as usize;
        let Ok(event) = reader.read_event() else {
            return Vec::new();
        };
        let after = reader.buffer_position() as usize;
        let node = |text| Node {
            start: before,
            tag_end: after,
            end: after,
            text,
        };
        match event {
            Event::Start(_) => {
                open.push(out.len());
                out.push(node(false));
            }
            Event::End(_) => {
                if let Some(i) = open.pop() {
                    out[i].end = after;
                }
            }
            Event::Empty(_) => out.push(node(false)),
            Event::Text(t) if !t.as_ref().trim().is_empty() => out.push(node(true)),
            Event::Eof => return out,
            _ => {}
        }
    }
}

/// The byte ranges of the attribute values in a start tag (between their quotes).
fn attribute_values(tag: &str) -> Vec<(usize, usize)> {
    let mut out = Vec::new();
    let mut rest = 0;
    while let Some(eq) = tag[rest..].find("=\"") {
        let start = rest + eq + 2;
        let Some(len) = tag[start..].find('"') else {
            break;
        };
        out.push((start, start + len));
        rest = start + len + 1;
    }
    out
}

/// `seed` with the edits `edits` encodes applied in turn, five bytes each (what is
/// left over is ignored, as are edits past the sixteenth): an operation and two
/// 16-bit node numbers `a` and `b`, taken modulo the number of nodes there are.
///
/// - 0: remove element `a`;
/// - 1: repeat element `a` after itself;
/// - 2: replace element `a` with a copy of element `b`;
/// - 3: set an attribute value of element `a` to one of element `b`'s;
/// - 4: remove an attribute of element `a`;
/// - 5: replace text `a` with text `b`;
/// - 6: append a copy of element `b` inside element `a`.
///
/// Each edit keeps the document well formed; the XML reader sees a registry whose
/// parts are wrong, not broken bytes.
pub fn apply_edits(seed: &str, edits: &[u8]) -> String {
    let mut doc = seed.to_owned();
    for edit in edits.chunks_exact(5).take(16) {
        let all = nodes(&doc);
        let (elements, texts): (Vec<Node>, Vec<Node>) = all.iter().partition(|n| !n.text);
        // The root stays: removing or replacing it leaves no registry to read.
        let elements = elements.get(1..).unwrap_or_default();
        if elements.is_empty() {
            break;
        }
        let a = usize::from(u16::from_le_bytes([edit[1], edit[2]]));
        let b = usize::from(u16::from_le_bytes([edit[3], edit[4]]));
        let (x, y) = (elements[a % elements.len()], elements[b % elements.len()]);
        let copy = doc[y.start..y.end].to_owned();
        let replaced = match edit[0] % 7 {
            0 => (x.start, x.end, String::new()),
            1 => (x.end, x.end, doc[x.start..x.end].to_owned()),
            2 => (x.start, x.end, copy),
            3 | 4 => {
                let values = attribute_values(&doc[x.start..x.tag_end]);
                let donor = attribute_values(&doc[y.start..y.tag_end]);
                let Some(&(s, e)) = values.get(b % values.len().max(1)) else {
                    continue;
                };
                if edit[0] % 7 == 3 {
                    let Some(&(ds, de)) = donor.get(a % donor.len().max(1)) else {
                        continue;
                    };
                    let value = doc[y.start + ds..y.start + de].to_owned();
                    (x.start + s, x.start + e, value)
                } else {
                    // The name, its `=` and both quotes go with the value.
                    let tag = &doc[x.start..x.start + s];
                    let name_start = tag.trim_end_matches("=\"").rfind(' ').unwrap_or(0);
                    (x.start + name_start, x.start + e + 1, String::new())
                }
            }
            5 if !texts.is_empty() => {
                let (t, u) = (texts[a % texts.len()], texts[b % texts.len()]);
                (t.start, t.end, doc[u.start..u.end].to_owned())
            }
            6 if x.tag_end < x.end => {
                let close = doc[..x.end].rfind("</").unwrap_or(x.end);
                (close, close, copy)
            }
            _ => continue,
        };
        doc.replace_range(replaced.0..replaced.1, &replaced.2);
    }
    doc
}

#[cfg(test)]
mod tests {
    use super::*;

    const SEED: &str = "<registry><types><type name=\"A\" alias=\"B\">a</type>\
                        <type name=\"B\"/></types><commands/></registry>";

    #[test]
    fn edits_keep_the_document_well_formed() {
        for op in 0..8u8 {
            for a in 0..6u16 {
                for b in 0..6u16 {
                    let [a0, a1] = a.to_le_bytes();
                    let [b0, b1] = b.to_le_bytes();
                    let doc = apply_edits(SEED, &[op, a0, a1, b0, b1]);
                    assert!(!nodes(&doc).is_empty(), "{op} {a} {b}: {doc}");
                }
            }
        }
    }

    #[test]
    fn each_operation_does_what_it_says() {
        let edit = |op: u8, a: u8, b: u8| apply_edits(SEED, &[op, a, 0, b, 0]);
        // Elements after the root: types, type A, type B, commands.
        assert_eq!(
            edit(0, 1, 0),
            "<registry><types><type name=\"B\"/></types><commands/></registry>"
        );
        assert!(edit(1, 2, 0).contains("<type name=\"B\"/><type name=\"B\"/>"));
        assert!(edit(2, 3, 2).contains("<types><type name=\"A\""));
        assert!(edit(2, 3, 2).ends_with("<type name=\"B\"/></registry>"));
        assert!(edit(3, 1, 2).contains("<type name=\"B\" alias=\"B\">"));
        assert!(edit(4, 1, 1).contains("<type name=\"A\">a</type>"));
        assert!(edit(6, 0, 3).contains("<commands/></types>"));
    }
}
