//! Writing the output without ever leaving it half-written, and `--check`.

use crate::emit::OutputFile;
use crate::error::{Error, Result};
use std::path::Path;

/// Write `files` under `out`. Everything is first written to a temporary folder beside
/// `out`; only when all of it is written are the files renamed into place, one atomic
/// rename each, so an error leaves the previous output as it was.
pub fn write_all(out: &Path, files: &[OutputFile]) -> Result<()> {
    let write_err = |path: &Path| {
        let path = path.to_owned();
        move |source| Error::Write { path, source }
    };
    std::fs::create_dir_all(out).map_err(write_err(out))?;
    let staging = tempfile::Builder::new()
        .prefix(".tuff-gen-")
        .tempdir_in(out)
        .map_err(write_err(out))?;
    for f in files {
        let path = staging.path().join(&f.path);
        if let Some(dir) = path.parent() {
            std::fs::create_dir_all(dir).map_err(write_err(dir))?;
        }
        std::fs::write(&path, &f.contents).map_err(write_err(&path))?;
    }
    for f in files {
        let target = out.join(&f.path);
        if let Some(dir) = target.parent() {
            std::fs::create_dir_all(dir).map_err(write_err(dir))?;
        }
        std::fs::rename(staging.path().join(&f.path), &target).map_err(write_err(&target))?;
    }
    Ok(())
}

/// Regenerate into a temporary folder and compare with what `out` holds. Returns
/// [`Error::OutOfDate`] with one line per differing file.
pub fn check(out: &Path, files: &[OutputFile]) -> Result<()> {
    let scratch = tempfile::tempdir().map_err(|source| Error::Write {
        path: std::env::temp_dir(),
        source,
    })?;
    write_all(scratch.path(), files)?;
    let mut summary = Vec::new();
    for f in files {
        let fresh = std::fs::read_to_string(scratch.path().join(&f.path)).unwrap_or_default();
        match std::fs::read_to_string(out.join(&f.path)) {
            Err(_) => summary.push(format!("  {}: missing", f.path.display())),
            Ok(committed) if committed != fresh => summary.push(format!(
                "  {}: {}",
                f.path.display(),
                first_difference(&committed, &fresh)
            )),
            Ok(_) => {}
        }
    }
    if summary.is_empty() {
        Ok(())
    } else {
        Err(Error::OutOfDate {
            dir: out.to_owned(),
            summary: summary.join("\n"),
        })
    }
}

fn first_difference(committed: &str, fresh: &str) -> String {
    let (a, b): (Vec<&str>, Vec<&str>) = (committed.lines().collect(), fresh.lines().collect());
    let changed = a.iter().zip(&b).filter(|(x, y)| x != y).count() + a.len().abs_diff(b.len());
    match a.iter().zip(&b).position(|(x, y)| x != y) {
        Some(i) => format!(
            "differs from line {} ({changed} lines differ; committed `{}`, fresh `{}`)",
            i + 1,
            clip(a[i]),
            clip(b[i])
        ),
        None => format!(
            "{} lines committed, {} fresh (one is a prefix of the other)",
            a.len(),
            b.len()
        ),
    }
}

fn clip(line: &str) -> String {
    let mut s: String = line.chars().take(80).collect();
    if s.len() < line.len() {
        s.push('…');
    }
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    fn file(path: &str, contents: &str) -> OutputFile {
        OutputFile {
            path: path.into(),
            contents: contents.into(),
        }
    }

    #[test]
    fn writes_then_checks_clean() {
        let dir = tempfile::tempdir().unwrap();
        let files = [file("a.txt", "one\n"), file("src/b.rs", "two\n")];
        write_all(dir.path(), &files).unwrap();
        assert_eq!(
            std::fs::read_to_string(dir.path().join("src/b.rs")).unwrap(),
            "two\n"
        );
        check(dir.path(), &files).unwrap();
        // No staging folder is left behind.
        let leftovers: Vec<_> = std::fs::read_dir(dir.path())
            .unwrap()
            .filter_map(|e| e.ok())
            .filter(|e| e.file_name().to_string_lossy().starts_with(".tuff-gen-"))
            .collect();
        assert!(leftovers.is_empty());
    }

    #[test]
    fn check_names_the_differing_and_missing_files() {
        let dir = tempfile::tempdir().unwrap();
        write_all(dir.path(), &[file("a.txt", "one\ntwo\n")]).unwrap();
        let err = check(
            dir.path(),
            &[file("a.txt", "one\nTWO\n"), file("c.txt", "x")],
        )
        .unwrap_err();
        let text = err.to_string();
        assert!(text.contains("a.txt: differs from line 2"), "{text}");
        assert!(text.contains("c.txt: missing"), "{text}");
    }
}
