//! Writing through mapped memory: a raw `ash` pointer copy against tuff's typed,
//! bounds-checked `Allocation::write`, side by side in one run, on the same memory.
//! Also the flush that non-coherent memory needs after the write.
//!
//! Run with `cargo bench -p tuff-tests --bench mapped_write`.

#[path = "../common/vulkan.rs"]
mod vulkan;

use ash::vk;
use criterion::{criterion_group, criterion_main, Criterion};
use std::hint::black_box;
use tuff_runtime::{AllocationRequest, Allocator, GpuAllocator, MemoryLocation};

/// A 4x4 matrix: the 64-byte uniform the scenes write per frame.
type Mat4 = [f32; 16];

fn benches(c: &mut Criterion) {
    let (dev, _) = vulkan::device(false);
    let allocator = GpuAllocator::new(dev.clone()).expect("gpu-allocator");
    let req = vk::MemoryRequirements {
        size: 64 * 1000,
        alignment: 256,
        memory_type_bits: !0,
    };
    let mut allocation = allocator
        .allocate(&AllocationRequest::new(req, MemoryLocation::Upload))
        .expect("allocation");
    let raw = allocation
        .mapped_ptr()
        .expect("upload memory is mapped")
        .as_ptr();
    let matrix: Mat4 = std::array::from_fn(|i| i as f32);
    let atom = dev.atom;
    let device = dev.device.clone();
    let memory = allocation.memory();
    let base = allocation.offset();

    let mut g = c.benchmark_group("mapped write");
    g.bench_function("one 64-byte write: raw ash pointer copy", |b| {
        b.iter(|| {
            // SAFETY: 64 bytes at the start of a 64,000-byte mapped allocation.
            unsafe {
                std::ptr::copy_nonoverlapping(black_box(&matrix).as_ptr().cast::<u8>(), raw, 64)
            }
        })
    });
    g.bench_function("one 64-byte write: tuff typed write", |b| {
        b.iter(|| {
            allocation
                .write(black_box(0), black_box(&matrix))
                .expect("fits")
        })
    });
    g.bench_function("1,000 64-byte writes: raw ash pointer copy", |b| {
        b.iter(|| {
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
        })
    });
    g.bench_function("1,000 64-byte writes: tuff typed write", |b| {
        b.iter(|| {
            for i in 0..1000u64 {
                allocation
                    .write(black_box(i * 64), black_box(&matrix))
                    .expect("fits");
            }
        })
    });
    let matrices = vec![matrix; 1000];
    g.bench_function("1,000 64-byte writes: raw ash, one copy of all", |b| {
        b.iter(|| {
            // SAFETY: 64,000 bytes into the 64,000-byte mapped allocation.
            unsafe {
                std::ptr::copy_nonoverlapping(
                    black_box(&matrices).as_ptr().cast::<u8>(),
                    raw,
                    64_000,
                )
            }
        })
    });
    g.bench_function("1,000 64-byte writes: tuff write_slice of all", |b| {
        b.iter(|| {
            allocation
                .write_slice(black_box(0), black_box(&matrices))
                .expect("fits")
        })
    });
    g.bench_function("one 64-byte write + flush: raw ash", |b| {
        b.iter(|| {
            // SAFETY: as above; the flush range is rounded to the atom by hand and lies
            // inside the allocation (which is atom-aligned).
            unsafe {
                std::ptr::copy_nonoverlapping(black_box(&matrix).as_ptr().cast::<u8>(), raw, 64);
                let range = vk::MappedMemoryRange::default()
                    .memory(memory)
                    .offset(base)
                    .size(64u64.next_multiple_of(atom));
                device.flush_mapped_memory_ranges(&[range]).expect("flush");
            }
        })
    });
    g.bench_function("one 64-byte write + flush: tuff", |b| {
        b.iter(|| {
            allocation
                .write(black_box(0), black_box(&matrix))
                .expect("fits");
            allocation.flush(0, 64).expect("flush");
        })
    });
    g.finish();
    drop(allocation);
}

criterion_group!(mapped, benches);
criterion_main!(mapped);
