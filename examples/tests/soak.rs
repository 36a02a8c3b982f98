//! Short versions of the reliability runs (README, "Reliability"): frames that keep
//! their memory, and a window through a storm of resizes. The long versions are
//! commands: `teapots --frames 10000`, `deferred --frames 10000`, `teapots --window
//! --resizes 500`; `scripts/leaks.sh` runs these scenes under memcheck.

mod common;

use common::run;

/// `"...; resident memory 111.4 MiB after frame 100, 112.8 MiB after frame 1000
/// (+1.2 %)"`: the two readings, in MiB.
fn resident(line: &str) -> (f64, f64) {
    let rest = line
        .split("resident memory ")
        .nth(1)
        .unwrap_or_else(|| panic!("no resident memory in {line}"));
    let mut mib = rest
        .split(" MiB")
        .take(2)
        .map(|part| part.rsplit(' ').next().unwrap().parse::<f64>().unwrap());
    (mib.next().unwrap(), mib.next().unwrap())
}

#[test]
fn a_thousand_frames_keep_their_memory() {
    let text = run(
        env!("CARGO_BIN_EXE_teapots"),
        &[
            "--validate",
            "--frames",
            "1000",
            "--width",
            "32",
            "--height",
            "32",
            "--count",
            "4",
            "--out",
        ]
        .into_iter()
        .chain([std::env::temp_dir().join("soak.png").to_str().unwrap()])
        .collect::<Vec<_>>(),
    );
    let line = text.lines().find(|l| l.starts_with("teapots:")).unwrap();
    let (early, last) = resident(line);
    // Frames 100 to 1000 allocate nothing they keep: the same memory within 5 %.
    assert!(last <= early * 1.05, "{line}");
}

#[test]
fn a_window_survives_a_resize_storm() {
    assert!(
        std::env::var_os("DISPLAY").is_some(),
        "no X server: the test command starts Xvfb (scripts/xvfb.sh) when DISPLAY is unset"
    );
    // 100 steps: the ten fixed sizes, then random ones of 1 to 1024 pixels a side,
    // a minimise (step 50) and restore (51), and a 0x0 request (75).
    let text = run(
        env!("CARGO_BIN_EXE_teapots"),
        &[
            "--validate",
            "--window",
            "--resizes",
            "100",
            "--width",
            "200",
            "--height",
            "150",
            "--count",
            "4",
        ],
    );
    let line = text.lines().find(|l| l.starts_with("window:")).unwrap();
    assert!(line.contains(" 100 resizes"), "{line}");
    let frames: u32 = line
        .strip_prefix("window: ")
        .and_then(|l| l.split(' ').next())
        .and_then(|n| n.parse().ok())
        .unwrap_or_else(|| panic!("{line}"));
    // Frames kept coming: two between steps, but where the window had no area.
    assert!(frames >= 190, "{line}");
    let (early, last) = resident(line);
    // Swapchains of up to 1024x1024 come and go: memory follows the size, within
    // bounds, but does not climb with every resize.
    assert!(last <= early * 1.5, "{line}");
    let extents = text
        .lines()
        .find_map(|l| l.strip_prefix("swapchain extents: "))
        .unwrap();
    assert!(extents.split(' ').count() > 80, "{extents}");
}
