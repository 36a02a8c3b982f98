//! The deferred scene as its binaries, on lavapipe with the validation layer and its
//! synchronization validation on: its golden image with one worker and with four,
//! and its raw-ash twin's image, byte for byte. The test command runs this file
//! twice: in the first pass tuff's workers record in turn (tuff's wrappers cross
//! threads only with `multi_thread`), in the threaded pass on threads of their own.

mod common;

use common::*;

/// The deferred scene: a G-buffer subpass whose objects worker secondaries record,
/// and a lighting subpass reading the G-buffer as input attachments. One worker and
/// four draw the objects in the same order, so both give the golden image, byte for
/// byte, and so does the raw-ash twin (its workers on threads of their own in any
/// build). A thread count out of range is refused.
#[test]
fn deferred_matches_its_golden_image_with_one_and_four_workers_and_in_raw_ash() {
    let binary = env!("CARGO_BIN_EXE_deferred");
    let args = |threads| ["--count", "2000", "--seed", "1", "--threads", threads];
    let one = golden(binary, "deferred", &args("1"));
    let four = golden(binary, "deferred", &args("4"));
    assert!(
        one == four,
        "deferred: one worker and four rendered different images"
    );
    assert_ash_port_matches(
        env!("CARGO_BIN_EXE_deferred_ash"),
        "deferred",
        &four,
        &args("4"),
    );
    for binary in [binary, env!("CARGO_BIN_EXE_deferred_ash")] {
        let mut zero = scene(binary);
        zero.args(["--threads", "0", "--width", "8", "--height", "8"]);
        let output = output(zero);
        assert!(!output.status.success());
        let stderr = String::from_utf8_lossy(&output.stderr);
        assert!(
            stderr.contains("the thread count must be 1 to 64, not 0"),
            "{stderr}"
        );
    }
}

/// With automatic synchronization (`--auto-sync`) the frame has no synchronization
/// written by hand: no barrier in the primary, not even the one before the host
/// reads the image (tuff records it at the recording's end), and the render pass's
/// subpass dependencies are those `RenderPassCreateInfo::needed_dependencies`
/// derives: the same image, byte for byte, and the layer with synchronization
/// validation says nothing.
#[test]
fn deferred_with_automatic_synchronization_renders_the_same_image() {
    let binary = env!("CARGO_BIN_EXE_deferred");
    let args = ["--count", "300", "--seed", "1", "--threads", "2"];
    let dir = tempfile::tempdir().expect("temp dir");
    let manual = render(binary, "deferred-manual", dir.path(), &args);
    let mut auto_args = args.to_vec();
    auto_args.push("--auto-sync");
    let auto = render(binary, "deferred-auto", dir.path(), &auto_args);
    assert!(
        manual == auto,
        "deferred: --auto-sync rendered another image"
    );
}

/// Built with `multi_thread` (the test command's threaded pass), the tuff scene's
/// workers run on threads of their own; without it, in turn, and it says so.
#[test]
fn deferred_says_whether_its_workers_ran_on_threads() {
    let dir = tempfile::tempdir().expect("temp dir");
    let out = dir.path().join("d.png");
    let text = run(
        env!("CARGO_BIN_EXE_deferred"),
        &[
            "--validate",
            "--count",
            "100",
            "--threads",
            "4",
            "--width",
            "32",
            "--height",
            "32",
            "--out",
            out.to_str().expect("utf-8 temp path"),
        ],
    );
    assert!(text.contains("100 objects, 4 threads"), "{text}");
    assert_eq!(
        text.contains("in turn: no multi_thread"),
        !cfg!(feature = "multi_thread"),
        "{text}"
    );
}
