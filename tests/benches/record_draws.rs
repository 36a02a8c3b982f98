//! Recording 10,000 draws, each with a 16-byte push constant, inside a render pass
//! with the test pipeline bound (its viewport and scissor set):
//! raw ash against tuff's `Recorder`, on the same lavapipe command pool. Each round
//! resets the pool, records one buffer with ash and one with tuff (in an order that
//! alternates), and the table reports the median time per draw (the draws only, since
//! the stream moved to `tests/common/draw_stream.rs`) and the geometric mean of the
//! per-round ratios. Nothing is submitted; recording is what is measured.
//!
//! Run with `cargo bench -p tuff-tests --bench record_draws`, and with
//! `--features multi_thread` for `Vrc` = `Arc` and real locks.

#[path = "../common/draw_stream.rs"]
mod draw_stream;
#[path = "../common/pipelines.rs"]
mod pipelines;
#[path = "../common/tuff_setup.rs"]
mod tuff_setup;
#[path = "../common/vulkan.rs"]
mod vulkan;

use draw_stream::DrawStream;

const DRAWS: u32 = 10_000;
const ROUNDS: usize = 41;

fn median(v: &mut [f64]) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

fn main() {
    let mut stream = DrawStream::new();
    let mut ash_ns = Vec::new();
    let mut tuff_ns = Vec::new();
    let mut ratios = Vec::new();
    for round in 0..ROUNDS {
        let mut time_ash = 0.0;
        let mut time_tuff = 0.0;
        for step in 0..2 {
            // Draw i with first instance i, as this bench always drew.
            if (round + step) % 2 == 0 {
                time_ash = stream.ash(DRAWS, true).as_nanos() as f64 / f64::from(DRAWS);
            } else {
                time_tuff = stream.tuff(DRAWS, true).as_nanos() as f64 / f64::from(DRAWS);
            }
        }
        if round > 0 {
            ash_ns.push(time_ash);
            tuff_ns.push(time_tuff);
            ratios.push(time_tuff / time_ash);
        }
    }
    let mode = if cfg!(feature = "multi_thread") {
        "multi_thread (Arc, mutex)"
    } else {
        "single-threaded (Rc)"
    };
    println!(
        "recording {DRAWS} draws with push constants, {} rounds, {mode}",
        ROUNDS - 1
    );
    // The order alternates between rounds, and the second recording of a round is
    // often slower than the first, so the per-round ratios come in two groups; their
    // geometric mean weighs both orders equally, where a median picks one group.
    let geo_mean = (ratios.iter().map(|r| r.ln()).sum::<f64>() / ratios.len() as f64).exp();
    println!("| case | median per draw (ns) | tuff / ash (geometric mean of rounds) |");
    println!("|---|---|---|");
    println!("| raw ash | {:.1} | 1.00 |", median(&mut ash_ns));
    println!(
        "| tuff Recorder | {:.1} | {:.3} |",
        median(&mut tuff_ns),
        geo_mean
    );
}
