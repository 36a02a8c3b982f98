//! Criterion benchmark of draw recording, per draw: a 16-byte push constant and a
//! `vkCmdDraw`, inside a render pass with the test pipeline bound, through raw ash and
//! through tuff's `Recorder` (every check and the hazard tracker on), on lavapipe
//! where it is installed (else the first device), without the layer.
//! Two runs of draws: the same parameters each time (a scene's instances with their
//! transforms in push constants, as the teapots draw), and a first instance that
//! changes with every draw (the tracker's per-draw shortcut does not apply).
//!
//! `cargo bench -p tuff-tests --bench draw_recording` (well under a minute; criterion
//! prints each case's time per draw). Nothing is submitted: recording is what is
//! measured. Each measured run records into command buffers of at most 10,000 draws,
//! their beginning and end outside the time.
//!
//! The stream itself is `tests/common/draw_stream.rs`, which `record_draws` times too.

#[path = "../common/draw_stream.rs"]
mod draw_stream;
#[path = "../common/pipelines.rs"]
mod pipelines;
#[path = "../common/tuff_setup.rs"]
mod tuff_setup;
#[path = "../common/vulkan.rs"]
mod vulkan;

use criterion::{criterion_group, criterion_main, Criterion};
use draw_stream::DrawStream;
use std::time::Duration;

/// The most draws one recording holds (lavapipe keeps every command in memory).
const CHUNK: u64 = 10_000;

fn draws(c: &mut Criterion) {
    let mut stream = DrawStream::new();
    let mut group = c.benchmark_group("per draw (push constant + vkCmdDraw)");
    for (name, vary) in [("same parameters", false), ("first instance varies", true)] {
        // Criterion asks for `iters` draws; they go in recordings of at most CHUNK.
        let chunked = |stream: &mut DrawStream, ash: bool, iters: u64| {
            let mut total = Duration::ZERO;
            let mut left = iters;
            while left > 0 {
                let n = left.min(CHUNK) as u32;
                total += match ash {
                    true => stream.ash(n, vary),
                    false => stream.tuff(n, vary),
                };
                left -= u64::from(n);
            }
            total
        };
        group.bench_function(format!("raw ash, {name}"), |b| {
            b.iter_custom(|iters| chunked(&mut stream, true, iters))
        });
        group.bench_function(format!("tuff, {name}"), |b| {
            b.iter_custom(|iters| chunked(&mut stream, false, iters))
        });
    }
    group.finish();
}

criterion_group! {
    name = benches;
    config = Criterion::default()
        .warm_up_time(Duration::from_millis(500))
        .measurement_time(Duration::from_secs(2))
        .sample_size(20);
    targets = draws
}
criterion_main!(benches);
