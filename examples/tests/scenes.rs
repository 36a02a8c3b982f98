//! The scenes, run as their binaries on lavapipe with the Khronos validation layer
//! and its synchronization validation on (`--validate`: any message it reports fails
//! the run): golden images, windows resized 20 times in a row, depth precision far
//! away, and the teapot's degenerate patches at every tessellation level.
//!
//! Golden images live in `examples/golden/`; `TUFF_BLESS=1` rewrites them from the
//! current renders (look at them before committing).

mod common;

use common::*;
use tuff_examples::image_file::read_png;

#[test]
fn triangle_matches_its_golden_image_in_tuff_and_in_raw_ash() {
    let tuff = golden(env!("CARGO_BIN_EXE_triangle"), "triangle", &[]);
    assert_ash_port_matches(env!("CARGO_BIN_EXE_triangle_ash"), "triangle", &tuff, &[]);
}

#[test]
fn teapots_match_their_golden_image_in_tuff_and_in_raw_ash() {
    let args = ["--count", "100", "--seed", "1"];
    let tuff = golden(env!("CARGO_BIN_EXE_teapots"), "teapots", &args);
    assert_ash_port_matches(env!("CARGO_BIN_EXE_teapots_ash"), "teapots", &tuff, &args);
}

/// The textured quad: the golden image, and independently of it, the checkerboard's
/// texels where the quad is (its centre texel, and one texel across) and the clear
/// color where it is not.
#[test]
fn textured_quad_shows_its_checkerboard() {
    use tuff_examples::scenes::textured_quad::{CHECKER, TEXTURE_SIZE};
    let (w, h, rgba) = golden(env!("CARGO_BIN_EXE_textured_quad"), "textured_quad", &[]);
    let pixel = |x: u32, y: u32| -> [u8; 4] {
        let i = ((y * w + x) * 4) as usize;
        rgba[i..i + 4].try_into().expect("four channels")
    };
    // The quad spans the middle 75% of each side; outside it is the clear color.
    assert_eq!(pixel(2, 2), [0, 0, 0, 255]);
    assert_eq!(pixel(w - 3, h - 3), [0, 0, 0, 255]);
    // Texel (i, j) covers quad-relative [i / 8, (i + 1) / 8); the centre of texel
    // (x, y) in the image is at 1/8 + 3/4 * (x + 0.5) / 8 of each side.
    let at = |t: u32| ((0.125 + 0.75 * (t as f32 + 0.5) / TEXTURE_SIZE as f32) * w as f32) as u32;
    for (tx, ty) in [(0, 0), (1, 0), (3, 4), (7, 7), (6, 7)] {
        assert_eq!(
            pixel(at(tx), at(ty)),
            CHECKER[((tx + ty) % 2) as usize],
            "texel ({tx}, {ty})"
        );
    }
}

/// The textured quad, the teapots and the Bézier patches with automatic
/// synchronization (`--auto-sync`): no barrier written by hand in their frames (the
/// texture's upload is `Queue::upload_image`'s, the host's read tuff's at the end of
/// the recording), the same image byte for byte, and the layer with synchronization
/// validation quiet.
#[test]
fn scenes_with_automatic_synchronization_render_the_same_images() {
    let dir = tempfile::tempdir().expect("temp dir");
    for (binary, name, args) in [
        (
            env!("CARGO_BIN_EXE_textured_quad"),
            "textured_quad",
            &[][..],
        ),
        (
            env!("CARGO_BIN_EXE_teapots"),
            "teapots",
            &["--count", "20", "--seed", "1"][..],
        ),
        (env!("CARGO_BIN_EXE_bezier"), "bezier", &[][..]),
    ] {
        let manual = render(binary, &format!("{name}-manual"), dir.path(), args);
        let mut auto_args = args.to_vec();
        auto_args.push("--auto-sync");
        let auto = render(binary, &format!("{name}-auto"), dir.path(), &auto_args);
        assert!(manual == auto, "{name}: --auto-sync rendered another image");
    }
}

/// The compute example adds two arrays of a million floats on the device, under the
/// layer, and checks every sum on the host.
#[test]
fn compute_adds_a_million_floats_and_checks_every_sum() {
    let out = run(env!("CARGO_BIN_EXE_compute"), &["--validate"]);
    assert!(
        out.contains("compute: 1048576 sums computed on llvmpipe"),
        "{out}"
    );
    let mut zero = scene(env!("CARGO_BIN_EXE_compute"));
    zero.args(["--count", "0"]);
    let output = output(zero);
    assert!(!output.status.success());
    assert!(String::from_utf8_lossy(&output.stderr).contains("--count must be at least 1"));
}

#[test]
fn bezier_matches_its_golden_image_in_tuff_and_in_raw_ash() {
    let args = ["--level", "16"];
    let tuff = golden(env!("CARGO_BIN_EXE_bezier"), "bezier", &args);
    assert_ash_port_matches(env!("CARGO_BIN_EXE_bezier_ash"), "bezier", &tuff, &args);
}

#[test]
fn bezier_wireframe_asks_for_and_gets_non_solid_fill() {
    let dir = tempfile::tempdir().expect("temp dir");
    let lit = |extra: &[&str]| {
        let mut args = vec!["--level", "1"];
        args.extend_from_slice(extra);
        let (_, _, rgba) = render(env!("CARGO_BIN_EXE_bezier"), "b", dir.path(), &args);
        rgba.chunks_exact(4).filter(|p| p[0] > 40).count()
    };
    let (filled, lines) = (lit(&[]), lit(&["--wireframe"]));
    // Lines leave most of the teapot's area showing the background.
    assert!(lines > 100, "no lines drawn");
    assert!(
        lines * 2 < filled,
        "{lines} pixels lit in wireframe, {filled} filled: filled, not lines"
    );
}

#[test]
fn teapot_counts_from_one_to_ten_thousand_render_and_zero_is_refused() {
    let dir = tempfile::tempdir().expect("temp dir");
    let binary = env!("CARGO_BIN_EXE_teapots");
    for count in ["1", "10000"] {
        let out = dir.path().join(format!("{count}.png"));
        run(
            binary,
            &[
                "--validate",
                "--count",
                count,
                "--width",
                "64",
                "--height",
                "64",
                "--out",
                out.to_str().expect("utf-8"),
            ],
        );
        let (_, _, rgba) = read_png(&out).expect("png");
        assert!(
            rgba.chunks_exact(4).any(|p| p[0].max(p[1]).max(p[2]) > 60),
            "{count} teapots: nothing drawn"
        );
    }
    let mut command = scene(binary);
    command.args([
        "--count",
        "0",
        "--out",
        dir.path().join("0.png").to_str().expect("utf-8"),
    ]);
    let output = output(command);
    assert!(!output.status.success());
    let err = String::from_utf8_lossy(&output.stderr);
    assert!(err.contains("1 to 10000"), "unclear error: {err}");
}

#[test]
fn far_nearly_coplanar_surfaces_resolve_in_depth_order() {
    let dir = tempfile::tempdir().expect("temp dir");
    let (_, _, rgba) = render(
        env!("CARGO_BIN_EXE_teapots"),
        "probe",
        dir.path(),
        &["--depth-probe"],
    );
    // Green in front, red 0.05 % behind covering the same pixels: any red is
    // z-fighting.
    let red = rgba
        .chunks_exact(4)
        .filter(|p| p[0] > 40 && p[0] > 2 * p[1])
        .count();
    let green = rgba
        .chunks_exact(4)
        .filter(|p| p[1] > 40 && p[1] > 2 * p[0])
        .count();
    assert!(
        green > 5_000,
        "the probe's teapot is missing ({green} pixels)"
    );
    assert_eq!(red, 0, "{red} pixels of the farther teapot show through");
}

/// The disk of pixels within `radius` (model units, in the plane z = `z`) of the
/// teapot's axis, as the bezier scene's camera for `view` sees it.
fn axis_disk(
    view: tuff_examples::scenes::bezier_view::Viewpoint,
    z: f32,
    radius: f32,
    size: u32,
) -> ([f32; 2], f32) {
    use glam::{Mat4, Vec4};
    let extent = tuff::vk::Extent2D {
        width: size,
        height: size,
    };
    let p = tuff_examples::scenes::bezier_view::params(view, 1, 0.0, extent);
    let mvp = Mat4::from_cols_array_2d(&p.model_view_projection);
    let pixel = |x: f32| {
        let c = mvp * Vec4::new(x, 0.0, z, 1.0);
        let ndc = [c.x / c.w, c.y / c.w];
        [
            (ndc[0] + 1.0) * 0.5 * size as f32,
            (ndc[1] + 1.0) * 0.5 * size as f32,
        ]
    };
    let (centre, edge) = (pixel(0.0), pixel(radius));
    let r = ((edge[0] - centre[0]).powi(2) + (edge[1] - centre[1]).powi(2)).sqrt();
    (centre, r)
}

#[test]
fn degenerate_patches_have_no_dark_speckles_at_any_level() {
    use tuff_examples::scenes::bezier_view::Viewpoint;
    let dir = tempfile::tempdir().expect("temp dir");
    let binary = env!("CARGO_BIN_EXE_bezier");
    let size = 160u32;
    // The lid's apex (z = 3.15) seen from above, and the bottom's centre (z = 0) seen
    // from below: where a row of control points collapses to one point.
    for (view, name, z, radius) in [
        (Viewpoint::Top, "top", 3.15f32, 0.4f32),
        (Viewpoint::Bottom, "bottom", 0.0, 1.0),
    ] {
        let (centre, r) = axis_disk(view, z, radius, size);
        assert!(r > 8.0, "{name}: the disk is only {r} pixels");
        for level in 1..=64u32 {
            let out = dir.path().join(format!("{name}{level}.png"));
            let (level_arg, size_arg) = (level.to_string(), size.to_string());
            run(
                binary,
                &[
                    "--view",
                    name,
                    "--level",
                    &level_arg,
                    "--width",
                    &size_arg,
                    "--height",
                    &size_arg,
                    "--out",
                    out.to_str().expect("utf-8"),
                ],
            );
            let (w, _, rgba) = read_png(&out).expect("png");
            let mut checked = 0;
            for (i, p) in rgba.chunks_exact(4).enumerate() {
                let (x, y) = ((i as u32 % w) as f32 + 0.5, (i as u32 / w) as f32 + 0.5);
                if (x - centre[0]).powi(2) + (y - centre[1]).powi(2) > r * r {
                    continue;
                }
                checked += 1;
                // Lit or in shadow, the surface is at least the ambient term (about
                // 40 in red); a NaN normal or a hole shows black or the background.
                assert!(
                    p[0].max(p[1]).max(p[2]) >= 25,
                    "{name}, level {level}: dark pixel {p:?} at ({x}, {y})"
                );
            }
            assert!(checked > 100, "{name}: only {checked} pixels checked");
        }
    }
}

#[test]
fn every_scene_survives_twenty_window_resizes() {
    assert!(
        std::env::var_os("DISPLAY").is_some(),
        "no X server: the test command starts Xvfb (scripts/xvfb.sh) when DISPLAY is unset"
    );
    for (binary, extra) in [
        (env!("CARGO_BIN_EXE_triangle"), &[][..]),
        (env!("CARGO_BIN_EXE_teapots"), &["--count", "16"][..]),
        (env!("CARGO_BIN_EXE_bezier"), &["--level", "8"][..]),
    ] {
        let mut args = vec![
            "--validate",
            "--window",
            "--resizes",
            "20",
            "--width",
            "200",
            "--height",
            "150",
        ];
        args.extend_from_slice(extra);
        let text = run(binary, &args);
        let line = text
            .lines()
            .find(|l| l.starts_with("window:"))
            .unwrap_or_else(|| panic!("{binary}: no summary in\n{text}"));
        assert!(line.contains(" 20 resizes"), "{binary}: {line}");
        // Each resize changes the size, so each needs at least one new swapchain.
        let recreations: u32 = line
            .split(", ")
            .find_map(|part| part.strip_suffix(" swapchain recreations"))
            .and_then(|n| n.parse().ok())
            .unwrap_or_else(|| panic!("{binary}: {line}"));
        assert!(recreations >= 20, "{binary}: {line}");
        // Every requested size, 1x1 and the thin ones included, got a swapchain.
        let extents = text
            .lines()
            .find_map(|l| l.strip_prefix("swapchain extents: "))
            .unwrap_or_else(|| panic!("{binary}: no extents in\n{text}"));
        for size in [
            "320x240", "1x1", "640x32", "24x480", "2x300", "300x2", "33x33",
        ] {
            assert!(
                extents.split(' ').any(|e| e == size),
                "{binary}: no {size} swapchain among {extents}"
            );
        }
    }
}

/// Both frame loops of the stage benchmark draw valid frames: tuff's and raw ash's,
/// headless and in a window, under the layer with synchronization validation.
#[test]
fn the_stage_benchmark_loops_are_valid_vulkan() {
    let stages = env!("CARGO_BIN_EXE_stages");
    for variant in ["tuff", "ash"] {
        for window in [false, true] {
            let mut args = vec![
                "run",
                "--variant",
                variant,
                "--count",
                "3",
                "--writes",
                "4",
                "--frames",
                "4",
                "--warmup",
                "1",
                "--size",
                "32",
                "--validate",
            ];
            if window {
                args.push("--window");
            }
            let out = run(stages, &args);
            let timed: Vec<&str> = out.lines().filter(|l| !l.starts_with('#')).collect();
            assert_eq!(
                timed.len(),
                4,
                "{variant} window={window}: four timed frames:\n{out}"
            );
            for line in timed {
                let times: Vec<u64> = line.split(',').map(|t| t.parse().expect("ns")).collect();
                assert_eq!(times.len(), 6, "{line}");
                // Uniform, command, submit and present each took some time; acquire
                // only in a window.
                assert!(times[2..].iter().all(|&t| t > 0), "{variant}: {line}");
                assert_eq!(times[1] > 0, window, "{variant} acquire: {line}");
            }
        }
    }
}

/// `stages bench` interleaves the variants this build has (raw ash, tuff, tuff with
/// `auto_sync`, and raw ash under the layer) and writes the samples, the tables and the charts; a variant that
/// needs another build is refused by name.
#[test]
fn the_stage_benchmark_writes_its_tables() {
    let stages = env!("CARGO_BIN_EXE_stages");
    let dir = tempfile::tempdir().expect("temp dir");
    let out = dir.path().to_str().expect("utf-8 temp path");
    let text = run(
        stages,
        &[
            "bench",
            "--out",
            out,
            "--label",
            "test",
            "--rounds",
            "2",
            "--counts",
            "1",
            "--many-writes",
            "3",
            "--frames",
            "2",
            "--warmup",
            "1",
            "--size",
            "16",
            "--window",
        ],
    );
    let csv = std::fs::read_to_string(dir.path().join("test.csv")).expect("the CSV");
    let rows = tuff_examples::stages::report::parse_csv(&csv).expect("a CSV it can read");
    // 2 rounds x 2 modes x 2 configurations x 5 variants x 2 frames.
    assert_eq!(rows.len(), 80, "{csv}");
    for variant in ["ash", "tuff", "tuff-auto", "ash-layer", "ash-sync"] {
        assert_eq!(
            rows.iter().filter(|r| r.variant == variant).count(),
            16,
            "{variant}"
        );
    }
    assert!(csv.contains("# device: llvmpipe"), "{csv}");
    let md = std::fs::read_to_string(dir.path().join("test.md")).expect("the tables");
    assert_eq!(
        md.matches(
            "| Stage | raw ash | tuff | tuff `auto_sync` | ash + layer | ash + layer + sync |"
        )
        .count(),
        4,
        "{md}"
    );
    assert!(
        md.contains("**window, 100 teapots, 3 uniform writes per frame**"),
        "{md}"
    );
    assert!(text.contains("| present |"), "{text}");
    for mode in ["headless", "window"] {
        let svg =
            std::fs::read_to_string(dir.path().join(format!("test-{mode}.svg"))).expect("a chart");
        assert!(svg.starts_with("<svg") && svg.contains("<rect x="), "{svg}");
    }
    let mut refused = scene(stages);
    refused.args(["run", "--variant", "tuff-mt", "--frames", "1"]);
    let output = output(refused);
    assert!(!output.status.success());
    let err = String::from_utf8_lossy(&output.stderr);
    assert!(
        err.contains("variant tuff-mt needs a build with multi_thread=true"),
        "{err}"
    );
    let mut untracked = scene(stages);
    untracked.args(["run", "--variant", "tuff-untracked", "--frames", "1"]);
    let refused = self::output(untracked);
    assert!(!refused.status.success());
    let err = String::from_utf8_lossy(&refused.stderr);
    assert!(err.contains("tuff_untracked=true"), "{err}");
    if !cfg!(feature = "vulkano") {
        let mut peer = scene(stages);
        peer.args(["run", "--variant", "vulkano", "--frames", "1"]);
        let refused = self::output(peer);
        assert!(!refused.status.success());
        let err = String::from_utf8_lossy(&refused.stderr);
        assert!(
            err.contains("needs a build with the vulkano feature"),
            "{err}"
        );
    }
}
