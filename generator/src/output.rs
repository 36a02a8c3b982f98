//! Writing the output without ever leaving it half-written, and `--check`.

use crate::emit::{OutputFile, GENERATED_DIR};
use crate::error::{Error, Result};
use std::path::Path;

/// Write `files` under `out`. Everything is first written to a staging folder inside
/// `out`. Then each file is swapped into place: the previous version (if any) is moved
/// into the staging folder and the new one renamed over its path. If any step fails,
/// the swaps already made are undone, so an error leaves the previous output as it was.
pub fn write_all(out: &Path, files: &[OutputFile]) -> Result<()> {
    std::fs::create_dir_all(out).map_err(write_err(out))?;
    let staging = tempfile::Builder::new()
        .prefix(".tuff-gen-")
        .tempdir_in(out)
        .map_err(write_err(out))?;
    let new_dir = staging.path().join("new");
    let old_dir = staging.path().join("old");
    for f in files {
        let path = new_dir.join(&f.path);
        create_parent(&path)?;
        std::fs::write(&path, &f.contents).map_err(write_err(&path))?;
    }
    // Fail before touching anything when a target cannot be replaced by a file.
    for f in files {
        let target = out.join(&f.path);
        if target.is_dir() {
            return Err(Error::Write {
                path: target,
                source: std::io::Error::other("a folder is in the way of this file"),
            });
        }
    }
    let retired = retire_stale(out, files, &old_dir)?;
    let mut swapped: Vec<(&OutputFile, bool)> = Vec::new();
    for f in files {
        if let Err(e) = swap_in(out, &new_dir, &old_dir, f) {
            for (done, had_old) in swapped.into_iter().rev() {
                undo_swap(out, &old_dir, done, had_old);
            }
            for path in retired {
                let _ = std::fs::rename(old_dir.join(&path), out.join(&path));
            }
            return Err(e);
        }
        swapped.push((f, old_dir.join(&f.path).exists()));
    }
    Ok(())
}

/// Move the generated folder's stale files aside (see [`check`]), so that a module the
/// generator stopped writing cannot linger; undone with the swaps if a later step fails.
fn retire_stale(
    out: &Path,
    files: &[OutputFile],
    old_dir: &Path,
) -> Result<Vec<std::path::PathBuf>> {
    let stale = stale(out, files)?;
    for (i, path) in stale.iter().enumerate() {
        let aside = old_dir.join(path);
        let moved = create_parent(&aside)
            .and_then(|()| std::fs::rename(out.join(path), &aside).map_err(write_err(path)));
        if let Err(e) = moved {
            for done in &stale[..i] {
                let _ = std::fs::rename(old_dir.join(done), out.join(done));
            }
            return Err(e);
        }
    }
    Ok(stale)
}

fn write_err(path: &Path) -> impl FnOnce(std::io::Error) -> Error {
    let path = path.to_owned();
    move |source| Error::Write { path, source }
}

fn create_parent(path: &Path) -> Result<()> {
    match path.parent() {
        Some(dir) => std::fs::create_dir_all(dir).map_err(write_err(dir)),
        None => Ok(()),
    }
}

/// Move the previous `f` (if any) aside into `old_dir`, then the new one into place.
fn swap_in(out: &Path, new_dir: &Path, old_dir: &Path, f: &OutputFile) -> Result<()> {
    let target = out.join(&f.path);
    let aside = old_dir.join(&f.path);
    if target.exists() {
        create_parent(&aside)?;
        std::fs::rename(&target, &aside).map_err(write_err(&target))?;
    }
    create_parent(&target)?;
    if let Err(source) = std::fs::rename(new_dir.join(&f.path), &target) {
        if aside.exists() {
            let _ = std::fs::rename(&aside, &target);
        }
        return Err(Error::Write {
            path: target,
            source,
        });
    }
    Ok(())
}

/// Best effort: put the previous file back (or remove the new one if there was none).
fn undo_swap(out: &Path, old_dir: &Path, f: &OutputFile, had_old: bool) {
    let target = out.join(&f.path);
    if had_old {
        let _ = std::fs::rename(old_dir.join(&f.path), &target);
    } else {
        let _ = std::fs::remove_file(&target);
    }
}

/// Compare `files` in memory with what `out` holds, as the generator would write them.
/// Returns [`Error::OutOfDate`] with one line per differing, missing or stale file; a
/// stale file is one under the generated folder that the generator no longer writes.
/// Reads only: the folder is left as it was.
pub fn check(out: &Path, files: &[OutputFile]) -> Result<()> {
    let mut summary = Vec::new();
    for f in files {
        match std::fs::read_to_string(out.join(&f.path)) {
            Err(e) if e.kind() == std::io::ErrorKind::NotFound => {
                summary.push(format!("  {}: missing", f.path.display()))
            }
            Err(e) => summary.push(format!("  {}: unreadable ({e})", f.path.display())),
            Ok(committed) if committed != f.contents => summary.push(format!(
                "  {}: {}",
                f.path.display(),
                first_difference(&committed, &f.contents)
            )),
            Ok(_) => {}
        }
    }
    for path in stale(out, files)? {
        summary.push(format!(
            "  {}: stale (the generator no longer writes it)",
            path.display()
        ));
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

/// Files in the generated folder of `out` (and its subfolders) that are not among
/// `files`, relative to `out`.
fn stale(out: &Path, files: &[OutputFile]) -> Result<Vec<std::path::PathBuf>> {
    let mut found = Vec::new();
    let mut todo = vec![std::path::PathBuf::from(GENERATED_DIR)];
    while let Some(rel_dir) = todo.pop() {
        let dir = out.join(&rel_dir);
        let entries = match std::fs::read_dir(&dir) {
            Ok(entries) => entries,
            Err(e) if e.kind() == std::io::ErrorKind::NotFound => continue,
            Err(source) => return Err(Error::Write { path: dir, source }),
        };
        for entry in entries {
            let entry = entry.map_err(write_err(&dir))?;
            let rel = rel_dir.join(entry.file_name());
            if entry.path().is_dir() {
                todo.push(rel);
            } else if !files.iter().any(|f| f.path == rel) {
                found.push(rel);
            }
        }
    }
    found.sort();
    Ok(found)
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
    fn a_failed_swap_restores_the_files_already_replaced() {
        let dir = tempfile::tempdir().unwrap();
        write_all(
            dir.path(),
            &[file("a.txt", "old a\n"), file("b.txt", "old b\n")],
        )
        .unwrap();
        // A folder where the third file goes makes the write fail.
        std::fs::create_dir(dir.path().join("c.txt")).unwrap();
        let err = write_all(
            dir.path(),
            &[
                file("a.txt", "new a\n"),
                file("b.txt", "new b\n"),
                file("c.txt", "new c\n"),
            ],
        )
        .unwrap_err();
        assert!(err.to_string().contains("c.txt"), "{err}");
        assert_eq!(
            std::fs::read_to_string(dir.path().join("a.txt")).unwrap(),
            "old a\n"
        );
        assert_eq!(
            std::fs::read_to_string(dir.path().join("b.txt")).unwrap(),
            "old b\n"
        );
    }

    #[test]
    fn undo_puts_back_every_swapped_file() {
        let dir = tempfile::tempdir().unwrap();
        let out = dir.path();
        write_all(out, &[file("a.txt", "old\n")]).unwrap();
        let (new_dir, old_dir) = (out.join("stage/new"), out.join("stage/old"));
        std::fs::create_dir_all(&new_dir).unwrap();
        std::fs::write(new_dir.join("a.txt"), "new\n").unwrap();
        std::fs::write(new_dir.join("b.txt"), "new\n").unwrap();
        let (a, b) = (file("a.txt", "new\n"), file("b.txt", "new\n"));
        swap_in(out, &new_dir, &old_dir, &a).unwrap();
        swap_in(out, &new_dir, &old_dir, &b).unwrap();
        assert_eq!(std::fs::read_to_string(out.join("a.txt")).unwrap(), "new\n");
        undo_swap(out, &old_dir, &b, false);
        undo_swap(out, &old_dir, &a, true);
        assert_eq!(std::fs::read_to_string(out.join("a.txt")).unwrap(), "old\n");
        assert!(!out.join("b.txt").exists());
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

    #[test]
    fn a_module_no_longer_generated_is_flagged_then_retired() {
        let dir = tempfile::tempdir().unwrap();
        let (old, kept) = (
            file("src/generated/sub/old.rs", "old\n"),
            file("src/generated/kept.rs", "kept\n"),
        );
        let hand = file("src/lib.rs", "hand-written\n");
        write_all(dir.path(), &[old, kept.clone(), hand]).unwrap();
        let text = check(dir.path(), std::slice::from_ref(&kept))
            .unwrap_err()
            .to_string();
        assert!(text.contains("src/generated/sub/old.rs: stale"), "{text}");
        // Outside the generated folder nothing is the generator's to judge.
        assert!(!text.contains("lib.rs"), "{text}");
        write_all(dir.path(), std::slice::from_ref(&kept)).unwrap();
        assert!(!dir.path().join("src/generated/sub/old.rs").exists());
        assert!(dir.path().join("src/lib.rs").exists());
        check(dir.path(), &[kept]).unwrap();
    }
}
