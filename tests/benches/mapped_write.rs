//! Writing through mapped memory: a raw `ash` pointer copy against tuff's typed,
//! bounds-checked `Allocation` writes, on the same lavapipe allocation, plus the flush
//! that non-coherent memory needs after a write.
//!
//! A single 64-byte write takes about 2 ns, where machine noise over the seconds a
//! sequential benchmark runs is as large as the difference being measured. So the cases
//! run interleaved: in each of many rounds every case runs a short batch, in an order
//! that rotates, and the table reports the median time per operation and the median of
//! the per-round ratios to raw.
//!
//! Run with `cargo bench -p tuff-tests --bench mapped_write`.

#[path = "../common/vulkan.rs"]
mod vulkan;

use ash::vk;
use std::hint::black_box;
use std::time::Instant;
use tuff_runtime::{AllocationRequest, Allocator, GpuAllocator, MemoryLocation};

/// A 4x4 matrix: the 64-byte uniform the scenes write per frame.
type Mat4 = [f32; 16];

const ROUNDS: usize = 301;

struct Case<'a> {
    name: &'static str,
    /// Operations per batch (a batch is timed as a whole).
    batch: u32,
    run: Box<dyn FnMut() + 'a>,
    per_op_ns: Vec<f64>,
}

fn median(v: &mut [f64]) -> f64 {
    v.sort_by(|a, b| a.total_cmp(b));
    v[v.len() / 2]
}

fn main() {
    // Cargo passes `--bench`; any other argument is not ours to handle.
    let (dev, _) = vulkan::device(false);
    let allocator = GpuAllocator::new(dev.clone()).expect("gpu-allocator");
    let req = vk::MemoryRequirements {
        size: 64 * 1000,
        alignment: 256,
        memory_type_bits: !0,
    };
    let allocation = std::cell::RefCell::new(
        allocator
            .allocate(&AllocationRequest::new(req, MemoryLocation::Upload))
            .expect("allocation"),
    );
    let (raw, memory, base) = {
        let a = allocation.borrow();
        (
            a.mapped_ptr().expect("upload memory is mapped").as_ptr(),
            a.memory(),
            a.offset(),
        )
    };
    let matrix: Mat4 = std::array::from_fn(|i| i as f32);
    let matrices = vec![matrix; 1000];
    let atom = dev.atom;
    let device = dev.device.clone();

    let raw_one = || {
        // SAFETY: 64 bytes at the start of a 64,000-byte mapped allocation.
        unsafe { std::ptr::copy_nonoverlapping(black_box(&matrix).as_ptr().cast::<u8>(), raw, 64) }
    };
    let raw_flush = || {
        let range = vk::MappedMemoryRange::default()
            .memory(memory)
            .offset(base)
            .size(64u64.next_multiple_of(atom));
        // SAFETY: the range is rounded to the atom by hand and lies inside the
        // allocation, which is atom-aligned.
        unsafe { device.flush_mapped_memory_ranges(&[range]).expect("flush") };
    };
    let mut cases = vec![
        Case {
            name: "one 64-byte write: raw ash pointer copy",
            batch: 20_000,
            run: Box::new(|| {
                for _ in 0..20_000 {
                    raw_one();
                }
            }),
            per_op_ns: Vec::new(),
        },
        Case {
            name: "one 64-byte write: tuff Allocation::write",
            batch: 20_000,
            run: Box::new(|| {
                let mut a = allocation.borrow_mut();
                for _ in 0..20_000 {
                    a.write(black_box(0), black_box(&matrix)).expect("fits");
                }
            }),
            per_op_ns: Vec::new(),
        },
        Case {
            name: "1,000 64-byte writes: raw ash pointer copies",
            batch: 20,
            run: Box::new(|| {
                for _ in 0..20 {
                    for i in 0..1000usize {
                        // SAFETY: i * 64 + 64 <= 64,000, inside the mapped allocation.
                        unsafe {
                            std::ptr::copy_nonoverlapping(
                                black_box(&matrix).as_ptr().cast::<u8>(),
                                raw.add(i * 64),
                                64,
                            )
                        }
                    }
                }
            }),
            per_op_ns: Vec::new(),
        },
        Case {
            name: "1,000 64-byte writes: tuff Allocation::write",
            batch: 20,
            run: Box::new(|| {
                let mut a = allocation.borrow_mut();
                for _ in 0..20 {
                    for i in 0..1000u64 {
                        a.write(black_box(i * 64), black_box(&matrix))
                            .expect("fits");
                    }
                }
            }),
            per_op_ns: Vec::new(),
        },
        Case {
            name: "1,000 64-byte writes as one block: raw ash copy",
            batch: 20,
            run: Box::new(|| {
                for _ in 0..20 {
                    // SAFETY: 64,000 bytes into the 64,000-byte mapped allocation.
                    unsafe {
                        std::ptr::copy_nonoverlapping(
                            black_box(&matrices).as_ptr().cast::<u8>(),
                            raw,
                            64_000,
                        )
                    }
                }
            }),
            per_op_ns: Vec::new(),
        },
        Case {
            name: "1,000 64-byte writes as one block: tuff Allocation::write_slice",
            batch: 20,
            run: Box::new(|| {
                let mut a = allocation.borrow_mut();
                for _ in 0..20 {
                    a.write_slice(black_box(0), black_box(&matrices))
                        .expect("fits");
                }
            }),
            per_op_ns: Vec::new(),
        },
        Case {
            name: "one 64-byte write + flush: raw ash",
            batch: 5_000,
            run: Box::new(|| {
                for _ in 0..5_000 {
                    raw_one();
                    raw_flush();
                }
            }),
            per_op_ns: Vec::new(),
        },
        Case {
            name: "one 64-byte write + flush: tuff write + flush",
            batch: 5_000,
            run: Box::new(|| {
                let mut a = allocation.borrow_mut();
                for _ in 0..5_000 {
                    a.write(black_box(0), black_box(&matrix)).expect("fits");
                    a.flush(0, 64).expect("flush");
                }
            }),
            per_op_ns: Vec::new(),
        },
    ];

    // Warm up, then measure in rotating order.
    for c in cases.iter_mut() {
        (c.run)();
    }
    let n = cases.len();
    for round in 0..ROUNDS {
        for k in 0..n {
            let c = &mut cases[(round + k) % n];
            let start = Instant::now();
            (c.run)();
            c.per_op_ns
                .push(start.elapsed().as_nanos() as f64 / f64::from(c.batch));
        }
    }

    println!("| Case | Median per operation | Median ratio to raw, per round |");
    println!("|---|---|---|");
    for pair in cases.chunks_mut(2) {
        let ratios: Vec<f64> = pair[1]
            .per_op_ns
            .iter()
            .zip(&pair[0].per_op_ns)
            .map(|(t, r)| t / r)
            .collect();
        let mut ratios = ratios;
        let ratio = median(&mut ratios);
        for (i, c) in pair.iter_mut().enumerate() {
            let t = median(&mut c.per_op_ns);
            let shown = if t >= 1000.0 {
                format!("{:.2} us", t / 1000.0)
            } else {
                format!("{t:.2} ns")
            };
            let r = if i == 0 {
                "1x".to_owned()
            } else {
                format!("{ratio:.2}x")
            };
            println!("| {} | {shown} | {r} |", c.name);
        }
    }
    drop(cases);
    drop(allocation);
}
