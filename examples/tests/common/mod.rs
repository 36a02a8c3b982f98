//! What the scene tests share: running a scene binary on lavapipe with a time
//! limit, rendering it headless with validation, and comparing with its golden
//! image (`TUFF_BLESS=1` rewrites the golden images from the current renders: look
//! at them before committing).

#![allow(dead_code)]

use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};
use tuff_examples::image_file::{read_png, write_png};

/// Size of the golden renders.
pub const SIZE: u32 = 256;
/// Two pixels match when no channel differs by more than this.
pub const CHANNEL_TOLERANCE: u8 = 8;
/// At most this fraction of pixels may differ beyond the tolerance.
pub const MAX_DIFFERING: f64 = 0.01;

/// The longest a scene run may take (debug build, lavapipe, 10,000 teapots included).
pub const RUN_LIMIT: Duration = Duration::from_secs(300);

/// A scene binary on lavapipe, whatever other devices the machine has: the golden
/// images are lavapipe's.
pub fn scene(binary: &str) -> Command {
    let mut command = Command::new(binary);
    command.env("TUFF_DEVICE", "llvmpipe");
    command
}

/// Waits for `command` to finish, killing it (and failing) after [`RUN_LIMIT`] so a
/// stalled frame fails the test instead of hanging it.
pub fn output(mut command: Command) -> std::process::Output {
    let mut child = command
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap_or_else(|e| panic!("cannot run {command:?}: {e}"));
    let start = Instant::now();
    while child.try_wait().expect("wait for the scene").is_none() {
        if start.elapsed() > RUN_LIMIT {
            let _ = child.kill();
            panic!("{command:?} ran longer than {RUN_LIMIT:?}");
        }
        std::thread::sleep(Duration::from_millis(20));
    }
    child
        .wait_with_output()
        .expect("collect the scene's output")
}

/// Runs a scene binary with `args`, failing with its output if it fails.
pub fn run(binary: &str, args: &[&str]) -> String {
    let mut command = scene(binary);
    command.args(args);
    let output = output(command);
    let text = format!(
        "{}{}",
        String::from_utf8_lossy(&output.stdout),
        String::from_utf8_lossy(&output.stderr)
    );
    assert!(output.status.success(), "{binary} {args:?} failed:\n{text}");
    text
}

/// Renders a scene headless with validation into `dir` and returns the image.
pub fn render(binary: &str, name: &str, dir: &Path, extra: &[&str]) -> (u32, u32, Vec<u8>) {
    let out = dir.join(format!("{name}.png"));
    let size = SIZE.to_string();
    let mut args = vec![
        "--validate",
        "--frames",
        "3",
        "--width",
        &size,
        "--height",
        &size,
        "--out",
        out.to_str().expect("utf-8 temp path"),
    ];
    args.extend_from_slice(extra);
    run(binary, &args);
    read_png(&out).expect("the scene wrote a PNG")
}

pub fn golden_path(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("golden")
        .join(format!("{name}.png"))
}

/// Whether the golden images are being rewritten rather than checked.
pub fn blessing() -> bool {
    std::env::var_os("TUFF_BLESS").is_some()
}

/// Pixels whose largest channel difference exceeds the tolerance.
pub fn differing(a: &[u8], b: &[u8]) -> usize {
    a.chunks_exact(4)
        .zip(b.chunks_exact(4))
        .filter(|(p, q)| {
            p.iter()
                .zip(*q)
                .any(|(x, y)| x.abs_diff(*y) > CHANNEL_TOLERANCE)
        })
        .count()
}

/// Compares a render with its golden image (or writes it with TUFF_BLESS=1).
pub fn assert_golden(name: &str, image: &(u32, u32, Vec<u8>)) {
    let path = golden_path(name);
    if blessing() {
        eprintln!("TUFF_BLESS: wrote {} instead of comparing", path.display());
        write_png(&path, image.0, image.1, &image.2).expect("write golden image");
        return;
    }
    let golden = read_png(&path).unwrap_or_else(|e| {
        panic!("{e:#}: run the test with TUFF_BLESS=1 to create it, and look at it")
    });
    assert_eq!((golden.0, golden.1), (image.0, image.1), "{name}: size");
    let n = differing(&golden.2, &image.2);
    let allowed = (MAX_DIFFERING * f64::from(image.0 * image.1)) as usize;
    assert!(
        n <= allowed,
        "{name}: {n} pixels differ from {} by more than {CHANNEL_TOLERANCE} (at most {allowed} may)",
        path.display()
    );
}

/// Renders twice, checks the two renders are identical, and compares with the golden.
pub fn golden(binary: &str, name: &str, extra: &[&str]) -> (u32, u32, Vec<u8>) {
    let dir = tempfile::tempdir().expect("temp dir");
    let first = render(binary, name, dir.path(), extra);
    let second = render(binary, &format!("{name}-again"), dir.path(), extra);
    assert!(
        first == second,
        "{name}: two runs rendered different images"
    );
    assert_golden(name, &first);
    first
}

/// Renders the raw-ash port of a scene with the same arguments and checks it against
/// the tuff scene's golden image (compared, never written: the reference is tuff's)
/// and against tuff's render, byte for byte: the same frames.
pub fn assert_ash_port_matches(
    binary: &str,
    golden_name: &str,
    tuff: &(u32, u32, Vec<u8>),
    args: &[&str],
) {
    let dir = tempfile::tempdir().expect("temp dir");
    let ash = render(binary, "ash", dir.path(), args);
    if !blessing() {
        assert_golden(golden_name, &ash);
    }
    assert!(
        tuff.2 == ash.2,
        "{golden_name}: tuff and raw ash rendered different images"
    );
}
