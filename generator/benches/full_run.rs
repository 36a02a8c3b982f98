//! A full generator run (parse both files, derive, classify, emit, write the report)
//! beside a bare quick-xml pass over the same vk.xml and vk-parse's parse alone, so
//! the figures compare within one run.
//!
//! A second group regenerates the pinned config from the pinned 1.3.239 registry and
//! from 1.4.330 (no validusage.json: its implicit rules are derived), side by side:
//! what a version bump costs in generator time.
//!
//! Run with `cargo bench -p tuff-gen --bench full_run`.

use criterion::{criterion_group, criterion_main, Criterion};
use std::hint::black_box;
use std::time::Duration;
use tuff_gen::{generate, output, Options};

fn bare_quick_xml(bytes: &[u8]) -> usize {
    let mut reader = quick_xml::Reader::from_reader(bytes);
    let mut events = 0usize;
    loop {
        match reader.read_event() {
            Ok(quick_xml::events::Event::Eof) => return events,
            Ok(_) => events += 1,
            Err(e) => panic!("vk.xml is malformed: {e}"),
        }
    }
}

fn benches(c: &mut Criterion) {
    let opts = Options::pinned();
    let bytes = std::fs::read(&opts.registry).expect("the pinned vk.xml");
    let scratch = tempfile::tempdir().expect("a temp folder");

    let mut group = c.benchmark_group("generator");
    group.sample_size(10);
    group.measurement_time(Duration::from_secs(10));
    group.bench_function("quick-xml bare read of vk.xml", |b| {
        b.iter(|| bare_quick_xml(black_box(&bytes)))
    });
    group.bench_function("vk-parse parse of vk.xml", |b| {
        b.iter(|| vk_parse::parse_stream(black_box(bytes.as_slice())).expect("parses"))
    });
    group.bench_function("full run (parse, derive, classify, write report)", |b| {
        b.iter(|| {
            let generation = generate(black_box(&opts)).expect("generates");
            output::write_all(scratch.path(), &generation.files).expect("writes");
        })
    });
    group.finish();

    let newer = opts
        .registry
        .parent()
        .map(|root| root.join("../shared/registry/1.4.330/vk.xml"))
        .expect("the repository root");
    assert!(newer.is_file(), "{} is missing", newer.display());
    let bumped = Options {
        registry: newer,
        validusage: None,
        ..opts.clone()
    };
    let mut group = c.benchmark_group("version bump");
    group.sample_size(10);
    group.measurement_time(Duration::from_secs(20));
    for (name, o) in [("1.3.239", &opts), ("1.4.330", &bumped)] {
        group.bench_function(format!("regenerate from {name}"), |b| {
            b.iter(|| {
                let generation = generate(black_box(o)).expect("generates");
                output::write_all(scratch.path(), &generation.files).expect("writes");
            })
        });
    }
    group.finish();
}

criterion_group!(generator, benches);
criterion_main!(generator);
