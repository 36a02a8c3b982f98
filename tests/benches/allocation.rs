//! Allocation throughput: create, allocate, bind, then destroy and free 10,000 small
//! buffers through the naive allocator (one vkAllocateMemory each) and through
//! gpu-allocator (sub-allocation), side by side in one run.
//!
//! Run with `cargo bench -p tuff-tests --bench allocation`.

#[path = "../common/vulkan.rs"]
mod vulkan;

use ash::vk;
use criterion::{criterion_group, criterion_main, Criterion};
use std::time::Duration;
use tuff_runtime::{
    Allocation, AllocationRequest, Allocator, GpuAllocator, MemoryLocation, NaiveAllocator,
};

const BUFFERS: usize = 10_000;

fn churn(device: &ash::Device, allocator: &dyn Allocator) {
    let mut live: Vec<(vk::Buffer, Allocation)> = Vec::with_capacity(BUFFERS);
    for i in 0..BUFFERS {
        let info = vk::BufferCreateInfo::default()
            .size(64 + (i as u64 % 16) * 16)
            .usage(vk::BufferUsageFlags::UNIFORM_BUFFER);
        // SAFETY: valid calls on a live device; each buffer is bound once to memory
        // that satisfies its requirements and destroyed before its memory is freed.
        unsafe {
            let buffer = device.create_buffer(&info, None).expect("vkCreateBuffer");
            let requirements = device.get_buffer_memory_requirements(buffer);
            let allocation = allocator
                .allocate(&AllocationRequest::new(
                    requirements,
                    MemoryLocation::Upload,
                ))
                .expect("allocation");
            device
                .bind_buffer_memory(buffer, allocation.memory(), allocation.offset())
                .expect("bind");
            live.push((buffer, allocation));
        }
    }
    for (buffer, allocation) in live {
        // SAFETY: no command uses the buffer.
        unsafe { device.destroy_buffer(buffer, None) };
        drop(allocation);
    }
}

fn benches(c: &mut Criterion) {
    let (dev, _) = vulkan::device(false);
    let naive = NaiveAllocator::new(dev.clone());
    let gpu = GpuAllocator::new(dev.clone()).expect("gpu-allocator");
    let mut g = c.benchmark_group("allocate and free 10,000 small buffers");
    g.sample_size(10);
    g.measurement_time(Duration::from_secs(15));
    g.bench_function("naive (one vkAllocateMemory each)", |b| {
        b.iter(|| churn(&dev.device, &naive))
    });
    g.bench_function("gpu-allocator (sub-allocated)", |b| {
        b.iter(|| churn(&dev.device, &gpu))
    });
    g.finish();
}

criterion_group!(allocation, benches);
criterion_main!(allocation);
