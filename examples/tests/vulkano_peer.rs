//! The stage benchmark's vulkano peer (a build with the `vulkano` feature) draws what
//! raw ash and tuff draw: the same last frame, byte for byte, read back the same way;
//! and that frame is the teapots' golden image.

#![cfg(feature = "vulkano")]

mod common;

use common::*;
use tuff_examples::image_file::read_png;

/// `stages run --variant <variant> --png ...` headless on lavapipe; the image.
fn last_frame(
    variant: &str,
    dir: &std::path::Path,
    (count, writes, warmup, frames, size): (u32, u32, u32, u32, u32),
) -> (u32, u32, Vec<u8>) {
    let png = dir.join(format!("{variant}-{count}-{writes}-{size}.png"));
    let numbers = [count, writes, frames, warmup, size].map(|n| n.to_string());
    let out = run(
        env!("CARGO_BIN_EXE_stages"),
        &[
            "run",
            "--variant",
            variant,
            "--count",
            &numbers[0],
            "--writes",
            &numbers[1],
            "--frames",
            &numbers[2],
            "--warmup",
            &numbers[3],
            "--size",
            &numbers[4],
            "--png",
            png.to_str().expect("utf-8 temp path"),
        ],
    );
    let timed = out.lines().filter(|l| !l.starts_with('#')).count();
    assert_eq!(timed, frames as usize, "{variant}: timed frames in\n{out}");
    read_png(&png).expect("the run wrote its last frame")
}

#[test]
fn the_vulkano_peer_draws_the_frames_raw_ash_and_tuff_draw() {
    let dir = tempfile::tempdir().expect("temp dir");
    // (teapots, uniform writes, warm-up frames, timed frames, image side)
    for config in [(1, 1, 1, 3, 64), (100, 4, 2, 5, 96), (100, 1, 1, 2, SIZE)] {
        let ash = last_frame("ash", dir.path(), config);
        let tuff = last_frame("tuff", dir.path(), config);
        let vulkano = last_frame("vulkano", dir.path(), config);
        assert!(
            ash == tuff,
            "{config:?}: tuff drew another frame than raw ash"
        );
        assert!(
            ash == vulkano,
            "{config:?}: vulkano drew another frame than raw ash ({} pixels differ)",
            differing(&ash.2, &vulkano.2)
        );
        // Teapots were drawn: not every pixel is the clear color.
        let clear = &ash.2[..4];
        assert!(
            ash.2.chunks_exact(4).any(|p| p != clear),
            "{config:?}: an empty frame"
        );
    }
    // 100 teapots of seed 1, third frame, 256 pixels: the teapots' golden image.
    let frame = last_frame("vulkano", dir.path(), (100, 1, 1, 2, SIZE));
    let golden = read_png(&golden_path("teapots")).expect("the golden image");
    assert_eq!((frame.0, frame.1), (golden.0, golden.1));
    let off = differing(&frame.2, &golden.2) as f64 / f64::from(SIZE * SIZE);
    assert!(
        off <= MAX_DIFFERING,
        "{:.2} % of pixels differ",
        off * 100.0
    );
}

/// `stages bench --vulkano <a build with the feature>` runs the peer beside the
/// others headless, leaves it out in a window, and puts it in the tables; `--window`
/// runs of it are refused by name.
#[test]
fn the_stage_benchmark_runs_the_vulkano_peer_headless() {
    let stages = env!("CARGO_BIN_EXE_stages");
    let dir = tempfile::tempdir().expect("temp dir");
    let out = dir.path().to_str().expect("utf-8 temp path");
    run(
        stages,
        &[
            "bench",
            "--out",
            out,
            "--label",
            "peer",
            "--vulkano",
            stages,
            "--rounds",
            "1",
            "--counts",
            "1",
            "--many-writes",
            "0",
            "--frames",
            "2",
            "--warmup",
            "1",
            "--size",
            "16",
            "--window",
            "--no-layer",
        ],
    );
    let csv = std::fs::read_to_string(dir.path().join("peer.csv")).expect("the CSV");
    let rows = tuff_examples::stages::report::parse_csv(&csv).expect("a CSV it can read");
    let of = |mode: &str, variant: &str| {
        rows.iter()
            .filter(|r| r.mode == mode && r.variant == variant)
            .count()
    };
    assert_eq!(of("headless", "vulkano"), 2, "{csv}");
    assert_eq!(of("window", "vulkano"), 0, "{csv}");
    assert_eq!(of("window", "ash"), 2, "{csv}");
    let md = std::fs::read_to_string(dir.path().join("peer.md")).expect("the tables");
    assert!(
        md.contains("| Stage | raw ash | tuff | tuff `auto_sync` | vulkano (automatic builder) |"),
        "{md}"
    );
    assert!(
        md.contains("| Stage | raw ash | tuff | tuff `auto_sync` |\n"),
        "{md}"
    );
    let mut refused = scene(stages);
    refused.args(["run", "--variant", "vulkano", "--window", "--frames", "1"]);
    let output = output(refused);
    assert!(!output.status.success());
    let err = String::from_utf8_lossy(&output.stderr);
    assert!(err.contains("headless only"), "{err}");
}
