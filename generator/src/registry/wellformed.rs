//! A fast well-formedness pass over the registry with quick-xml, so that malformed XML
//! is reported with file, line and column before vk-parse (which recovers silently
//! from some errors) sees it.

use crate::error::{Error, Result};
use quick_xml::events::Event;
use std::path::Path;

/// Fail with the position of the first XML error in `bytes`, if any, or if the root
/// element is not `<registry>`.
pub(crate) fn check(path: &Path, bytes: &[u8]) -> Result<()> {
    // The XML reader vk-parse uses stops silently at these; report them here.
    if let Err(e) = std::str::from_utf8(bytes) {
        return Err(malformed(
            path,
            bytes,
            e.valid_up_to(),
            "invalid UTF-8".to_owned(),
        ));
    }
    let mut reader = quick_xml::Reader::from_reader(bytes);
    let config = reader.config_mut();
    config.check_end_names = true;
    config.check_comments = true;
    let mut depth = 0usize;
    let mut saw_root = false;
    loop {
        let event = reader.read_event();
        match event {
            Ok(Event::Start(start)) => {
                if let Err(message) = check_attributes(&start) {
                    let pos = reader.buffer_position() as usize;
                    return Err(malformed(path, bytes, pos, message));
                }
                if depth == 0 {
                    if saw_root || start.name().as_ref() != "registry" {
                        let pos = reader.buffer_position() as usize;
                        return Err(malformed(
                            path,
                            bytes,
                            pos,
                            "the root element must be a single <registry>".to_owned(),
                        ));
                    }
                    saw_root = true;
                }
                depth += 1;
            }
            Ok(Event::End(_)) => depth = depth.saturating_sub(1),
            Ok(Event::Empty(e)) if depth > 0 => {
                if let Err(message) = check_attributes(&e) {
                    let pos = reader.buffer_position() as usize;
                    return Err(malformed(path, bytes, pos, message));
                }
            }
            Ok(Event::GeneralRef(r)) => {
                let name: String = r.as_ref().to_owned();
                if !is_known_entity(&name) {
                    let pos = reader.buffer_position() as usize;
                    return Err(malformed(
                        path,
                        bytes,
                        pos,
                        format!("undefined entity `&{name};`"),
                    ));
                }
            }
            Ok(Event::Empty(_)) if depth == 0 => {
                let pos = reader.buffer_position() as usize;
                return Err(malformed(
                    path,
                    bytes,
                    pos,
                    "the root element must be a non-empty <registry>".to_owned(),
                ));
            }
            Ok(Event::Eof) => break,
            Ok(_) => {}
            Err(e) => {
                let pos = reader.error_position() as usize;
                return Err(malformed(path, bytes, pos, e.to_string()));
            }
        }
    }
    if !saw_root {
        return Err(malformed(
            path,
            bytes,
            bytes.len(),
            "no <registry> element".to_owned(),
        ));
    }
    if depth != 0 {
        return Err(malformed(
            path,
            bytes,
            bytes.len(),
            "the file ends inside an element".to_owned(),
        ));
    }
    Ok(())
}

/// XML's predefined entities and character references: the only ones a registry
/// without a DTD can use.
fn is_known_entity(name: &str) -> bool {
    ["lt", "gt", "amp", "apos", "quot"].contains(&name) || name.starts_with('#')
}

/// Duplicate or malformed attributes, and undefined entities inside values.
fn check_attributes(start: &quick_xml::events::BytesStart) -> std::result::Result<(), String> {
    for attr in start.attributes().with_checks(true) {
        let attr = attr.map_err(|e| e.to_string())?;
        let value = &attr.value;
        let mut rest = value.as_ref();
        while let Some(at) = rest.find('&') {
            let entity = rest[at + 1..].split(';').next().unwrap_or_default();
            if !is_known_entity(entity) || !rest[at + 1..].contains(';') {
                return Err(format!("undefined entity `&{entity};` in an attribute"));
            }
            rest = &rest[at + 1..];
        }
    }
    Ok(())
}

fn malformed(path: &Path, bytes: &[u8], offset: usize, message: String) -> Error {
    let (line, column) = line_column(bytes, offset);
    Error::MalformedXml {
        path: path.to_owned(),
        line,
        column,
        message,
    }
}

/// 1-based line and column of a byte offset.
pub(crate) fn line_column(bytes: &[u8], offset: usize) -> (usize, usize) {
    let offset = offset.min(bytes.len());
    let before = &bytes[..offset];
    let line = before.iter().filter(|&&b| b == b'\n').count() + 1;
    let line_start = before
        .iter()
        .rposition(|&b| b == b'\n')
        .map_or(0, |p| p + 1);
    (line, offset - line_start + 1)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reports_line_and_column_of_a_mismatched_end_tag() {
        let xml = b"<registry>\n  <types>\n  </typo>\n</registry>\n";
        let err = check(Path::new("vk.xml"), xml).unwrap_err();
        match err {
            Error::MalformedXml { line, .. } => assert_eq!(line, 3),
            other => panic!("unexpected error {other}"),
        }
    }

    #[test]
    fn rejects_another_root_element() {
        let err = check(Path::new("vk.xml"), b"<html></html>").unwrap_err();
        assert!(err.to_string().contains("<registry>"), "{err}");
    }

    #[test]
    fn rejects_a_truncated_file() {
        let err = check(Path::new("vk.xml"), b"<registry><types>").unwrap_err();
        assert!(matches!(err, Error::MalformedXml { .. }), "{err}");
    }

    #[test]
    fn rejects_entities_duplicates_and_bad_utf8() {
        for bad in [
            &b"<registry>\n<t>&bogus;</t></registry>"[..],
            b"<registry><t a=\"1\" a=\"2\"/></registry>",
            b"<registry><t a=\"&bogus;\"/></registry>",
            b"<registry><t>\xff</t></registry>",
        ] {
            let err = check(Path::new("vk.xml"), bad).unwrap_err();
            assert!(matches!(err, Error::MalformedXml { .. }), "{err}");
        }
        check(
            Path::new("vk.xml"),
            b"<registry><t a=\"&lt;&#65;\">&amp;&#x41;</t></registry>",
        )
        .unwrap();
    }

    #[test]
    fn accepts_a_minimal_registry() {
        check(
            Path::new("vk.xml"),
            b"<?xml version=\"1.0\"?><registry><types/></registry>",
        )
        .unwrap();
    }

    #[test]
    fn line_column_counts_from_one() {
        assert_eq!(line_column(b"ab\ncd", 0), (1, 1));
        assert_eq!(line_column(b"ab\ncd", 4), (2, 2));
    }
}
