//! A fast well-formedness pass over the registry with quick-xml, so that malformed XML
//! is reported with file, line and column before vk-parse (which recovers silently
//! from some errors) sees it.

use crate::error::{Error, Result};
use quick_xml::events::Event;
use std::path::Path;

/// Fail with the position of the first XML error in `bytes`, if any, or if the root
/// element is not `<registry>`.
pub(crate) fn check(path: &Path, bytes: &[u8]) -> Result<()> {
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
