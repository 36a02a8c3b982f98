//! tuff-runtime's allocators and mapped memory on a real device (lavapipe on CI) with
//! the Khronos validation layer on: it must report nothing, leaked objects included.

#[path = "common/vulkan.rs"]
mod vulkan;

use ash::vk;
use std::ptr::NonNull;
use tuff_runtime::{
    AllocError, Allocation, AllocationBacking, AllocationParts, AllocationRequest, Allocator,
    DeviceOwner, GpuAllocator, MapError, MemoryLocation, NaiveAllocator, Vrc, Vutex,
};
use vulkan::{assert_silent, device, TestDevice};

/// A small deterministic generator, so runs repeat.
struct Lcg(u64);
impl Lcg {
    fn next(&mut self) -> u64 {
        self.0 = self
            .0
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        self.0 >> 33
    }
}

#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, bytemuck::Pod, bytemuck::Zeroable)]
struct Uniforms {
    model: [[f32; 4]; 4],
    color: [f32; 4],
}

struct Resource {
    buffer: vk::Buffer,
    allocation: Allocation,
}

fn create(
    dev: &TestDevice,
    allocator: &dyn Allocator,
    size: u64,
    location: MemoryLocation,
) -> Resource {
    let info = vk::BufferCreateInfo::default()
        .size(size)
        .usage(
            vk::BufferUsageFlags::TRANSFER_SRC
                | vk::BufferUsageFlags::TRANSFER_DST
                | vk::BufferUsageFlags::STORAGE_BUFFER,
        )
        .sharing_mode(vk::SharingMode::EXCLUSIVE);
    // SAFETY: valid create info on a live device.
    let buffer = unsafe { dev.device.create_buffer(&info, None) }.expect("vkCreateBuffer");
    // SAFETY: the buffer is live.
    let requirements = unsafe { dev.device.get_buffer_memory_requirements(buffer) };
    let allocation = allocator
        .allocate(&AllocationRequest {
            requirements,
            location,
            linear: true,
            name: "test buffer",
        })
        .expect("allocation");
    // SAFETY: the allocation satisfies the buffer's requirements and is unbound.
    unsafe {
        dev.device
            .bind_buffer_memory(buffer, allocation.memory(), allocation.offset())
            .expect("vkBindBufferMemory")
    };
    Resource { buffer, allocation }
}

fn destroy(dev: &TestDevice, r: Resource) {
    // SAFETY: no command uses the buffer.
    unsafe { dev.device.destroy_buffer(r.buffer, None) };
    drop(r.allocation);
}

fn round_trip(r: &mut Resource, size: u64, seed: u32) {
    let a = &mut r.allocation;
    let words = (size / 4) as usize;
    let data: Vec<u32> = (0..words as u32)
        .map(|i| i.wrapping_mul(2654435761) ^ seed)
        .collect();
    a.write_slice(0, &data).expect("write fits");
    let mut back = vec![0u32; words];
    a.read_slice(0, &mut back).expect("read fits");
    assert_eq!(back, data);
    // An unaligned typed write and read of a struct with 16-byte rows.
    if size > std::mem::size_of::<Uniforms>() as u64 {
        let u = Uniforms {
            model: [[seed as f32; 4]; 4],
            color: [0.25, 0.5, 0.75, 1.0],
        };
        a.write(1, &u).expect("unaligned write fits");
        assert_eq!(a.read::<Uniforms>(1).expect("unaligned read"), u);
    }
    // One byte past the end is refused, and nothing is written.
    let end = a.size();
    assert!(matches!(
        a.write(end, &0u8),
        Err(MapError::OutOfRange { .. })
    ));
    assert!(matches!(
        a.write(u64::MAX, &0u32),
        Err(MapError::Overflow { .. })
    ));
}

/// Create and free 10,000 buffers of mixed sizes (at most 512 alive at once, freed in
/// random order), writing and reading back every host-visible one.
fn churn(dev: &Vrc<TestDevice>, allocator: &dyn Allocator, seed: u64) {
    let mut rng = Lcg(seed);
    let mut live: Vec<(Resource, u64)> = Vec::new();
    for i in 0..10_000u32 {
        let size = match rng.next() % 4 {
            0 => 16 + rng.next() % 256,
            1 => 256 + rng.next() % 4096,
            2 => 4096 + rng.next() % 65536,
            _ => 64,
        } & !3;
        let location = match rng.next() % 8 {
            0 => MemoryLocation::DeviceLocal,
            1 => MemoryLocation::Readback,
            _ => MemoryLocation::Upload,
        };
        let mut r = create(dev, allocator, size, location);
        if r.allocation.mapped_ptr().is_some() {
            round_trip(&mut r, size, i);
        } else {
            // Device-local memory that is not host-visible has no mapping.
            assert_eq!(r.allocation.write(0, &1u32), Err(MapError::NotMapped));
        }
        live.push((r, size));
        if live.len() > 512 {
            let victim = (rng.next() as usize) % live.len();
            destroy(dev, live.swap_remove(victim).0);
        }
    }
    while !live.is_empty() {
        let victim = (rng.next() as usize) % live.len();
        destroy(dev, live.swap_remove(victim).0);
    }
}

#[test]
fn naive_allocator_churn_is_clean() {
    let _serial = vulkan::serial();
    let (dev, messages) = device(true);
    let allocator = NaiveAllocator::new(dev.clone());
    churn(&dev, &allocator, 1);
    drop(allocator);
    drop(dev);
    assert_silent(&messages);
}

#[test]
fn gpu_allocator_churn_is_clean() {
    let _serial = vulkan::serial();
    let (dev, messages) = device(true);
    let allocator = GpuAllocator::new(dev.clone()).expect("gpu-allocator");
    churn(&dev, &allocator, 2);
    drop(allocator);
    drop(dev);
    assert_silent(&messages);
}

#[test]
fn allocations_keep_the_device_alive_in_any_drop_order() {
    let _serial = vulkan::serial();
    let (dev, messages) = device(true);
    let weak_check = Vrc::downgrade(&dev);
    let allocator = GpuAllocator::new(dev.clone()).expect("gpu-allocator");
    let req = vk::MemoryRequirements {
        size: 1024,
        alignment: 256,
        memory_type_bits: !0,
    };
    let mut a = allocator
        .allocate(&AllocationRequest::new(req, MemoryLocation::Upload))
        .expect("allocation");
    let b = NaiveAllocator::new(dev.clone())
        .allocate(&AllocationRequest::new(req, MemoryLocation::Readback))
        .expect("allocation");
    // The user drops the device and the allocator first...
    drop(allocator);
    drop(dev);
    assert!(
        weak_check.upgrade().is_some(),
        "the allocations keep the device alive"
    );
    // ...and the memory is still usable.
    a.write(0, &[7u32; 4]).expect("write");
    assert_eq!(a.read::<[u32; 4]>(0).expect("read"), [7; 4]);
    drop(a);
    drop(b);
    assert!(
        weak_check.upgrade().is_none(),
        "the last allocation released the device"
    );
    assert_silent(&messages);
}

/// A user's allocator: bump allocation from one block of host-visible memory, freed
/// when the allocator and every allocation are gone.
struct BumpAllocator {
    block: Vrc<BumpBlock>,
    next: Vutex<u64>,
}

struct BumpBlock {
    owner: Vrc<TestDevice>,
    memory: vk::DeviceMemory,
    size: u64,
    type_index: u32,
    properties: vk::MemoryPropertyFlags,
    mapped: NonNull<u8>,
}

// SAFETY: the block never reads or writes through `mapped`; it only computes the
// disjoint sub-ranges it hands to allocations, so sharing it across threads is sound.
unsafe impl Send for BumpBlock {}
// SAFETY: as for Send.
unsafe impl Sync for BumpBlock {}

impl Drop for BumpBlock {
    fn drop(&mut self) {
        // SAFETY: every allocation holds the block, so none is alive; freeing unmaps.
        unsafe { self.owner.device.free_memory(self.memory, None) };
    }
}

struct BumpBacking {
    _block: Vrc<BumpBlock>,
}

impl AllocationBacking for BumpBacking {
    fn free(self: Box<Self>) {
        // Bump allocation never reuses memory: the block goes when its last user does.
    }
}

impl BumpAllocator {
    fn new(owner: Vrc<TestDevice>, size: u64, properties: vk::MemoryPropertyFlags) -> Option<Self> {
        let m = &owner.memory;
        let type_index = (0..m.memory_type_count)
            .find(|i| m.memory_types[*i as usize].property_flags == properties)?;
        let info = vk::MemoryAllocateInfo::default()
            .allocation_size(size)
            .memory_type_index(type_index);
        // SAFETY: valid allocate and map calls on a live device; the memory is host-visible.
        let (memory, mapped) = unsafe {
            let memory = owner.device.allocate_memory(&info, None).ok()?;
            let mapped = owner
                .device
                .map_memory(memory, 0, vk::WHOLE_SIZE, vk::MemoryMapFlags::empty())
                .ok()
                .and_then(|ptr| NonNull::new(ptr.cast::<u8>()));
            let Some(mapped) = mapped else {
                owner.device.free_memory(memory, None);
                return None;
            };
            (memory, mapped)
        };
        Some(BumpAllocator {
            block: Vrc::new(BumpBlock {
                owner,
                memory,
                size,
                type_index,
                properties,
                mapped,
            }),
            next: Vutex::new(0),
        })
    }
}

impl Allocator for BumpAllocator {
    fn allocate(&self, request: &AllocationRequest<'_>) -> Result<Allocation, AllocError> {
        let b = &self.block;
        let r = request.requirements;
        if r.memory_type_bits & (1 << b.type_index) == 0 {
            return Err(AllocError::NoSuitableMemoryType {
                memory_type_bits: r.memory_type_bits,
                location: request.location,
            });
        }
        // On non-coherent memory, whole atoms keep flushes and invalidations off the
        // neighbours (see Allocation::from_parts).
        let coherent = b
            .properties
            .contains(vk::MemoryPropertyFlags::HOST_COHERENT);
        let (alignment, size) = if coherent {
            (r.alignment.max(1), r.size)
        } else {
            let atom = b.owner.atom;
            (r.alignment.max(atom), r.size.next_multiple_of(atom))
        };
        let mut next = self.next.lock();
        let offset = next
            .checked_next_multiple_of(alignment)
            .filter(|o| o.checked_add(size).is_some_and(|end| end <= b.size))
            .ok_or(AllocError::Vulkan {
                call: "bump allocation",
                result: vk::Result::ERROR_OUT_OF_DEVICE_MEMORY,
            })?;
        *next = offset + size;
        let parts = AllocationParts {
            memory: b.memory,
            offset,
            size,
            memory_size: b.size,
            memory_type_index: b.type_index,
            properties: b.properties,
            // SAFETY: offset + size <= block size, inside the mapping.
            mapped: Some(unsafe { NonNull::new_unchecked(b.mapped.as_ptr().add(offset as usize)) }),
            non_coherent_atom_size: b.owner.atom,
        };
        let owner: Vrc<dyn DeviceOwner> = b.owner.clone();
        // SAFETY: bump ranges never overlap, and the backing keeps the block (mapped)
        // and the device alive.
        Ok(unsafe {
            Allocation::from_parts(parts, owner, Box::new(BumpBacking { _block: b.clone() }))
        })
    }
}

fn bump_round_trip(dev: &Vrc<TestDevice>, properties: vk::MemoryPropertyFlags) {
    let allocator = BumpAllocator::new(dev.clone(), 1 << 20, properties).expect("bump block");
    let mut resources: Vec<Resource> = (0..64)
        .map(|i| create(dev, &allocator, 64 + 4 * i, MemoryLocation::Upload))
        .collect();
    for (i, r) in resources.iter_mut().enumerate() {
        let size = r.allocation.size();
        round_trip(r, size & !3, i as u32);
    }
    for r in resources.drain(..) {
        destroy(dev, r);
    }
}

#[test]
fn a_custom_allocator_plugs_in_through_the_same_trait() {
    let _serial = vulkan::serial();
    let (dev, messages) = device(true);
    let host = vk::MemoryPropertyFlags::HOST_VISIBLE;
    let coherent = (0..dev.memory.memory_type_count)
        .map(|i| dev.memory.memory_types[i as usize].property_flags)
        .find(|f| f.contains(host | vk::MemoryPropertyFlags::HOST_COHERENT))
        .expect("Vulkan guarantees a host-visible coherent memory type");
    bump_round_trip(&dev, coherent);
    // Non-coherent memory, where the device offers it, exercises the flush and
    // invalidate paths for real; lavapipe's host memory is all coherent.
    let non_coherent = (0..dev.memory.memory_type_count)
        .map(|i| dev.memory.memory_types[i as usize].property_flags)
        .find(|f| f.contains(host) && !f.contains(vk::MemoryPropertyFlags::HOST_COHERENT));
    if let Some(flags) = non_coherent {
        bump_round_trip(&dev, flags);
    }
    println!(
        "{}: non-coherent host memory {}",
        dev.name,
        if non_coherent.is_some() {
            "tested"
        } else {
            "not offered"
        }
    );
    drop(dev);
    assert_silent(&messages);
}

#[test]
fn explicit_flushes_of_coherent_memory_are_valid() {
    let _serial = vulkan::serial();
    let (dev, messages) = device(true);
    let allocator = NaiveAllocator::new(dev.clone());
    let mut r = create(&dev, &allocator, 1000, MemoryLocation::Upload);
    r.allocation.write_slice(3, &[1u8; 997]).expect("write");
    // Rounded to the atom size and clamped to the memory: the layer checks the range.
    r.allocation.flush(3, 997).expect("flush");
    r.allocation.invalidate(999, 1).expect("invalidate");
    r.allocation.flush(0, 0).expect("empty flush");
    assert!(r.allocation.flush(0, 1 << 40).is_err());
    destroy(&dev, r);
    drop(allocator);
    drop(dev);
    assert_silent(&messages);
}

#[test]
fn the_harness_hears_the_validation_layer() {
    let _serial = vulkan::serial();
    // A buffer leaked on purpose must be reported when the device is destroyed;
    // otherwise the silence the other tests assert would prove nothing.
    let (dev, messages) = device(true);
    let info = vk::BufferCreateInfo::default()
        .size(64)
        .usage(vk::BufferUsageFlags::UNIFORM_BUFFER);
    // SAFETY: valid create info; the buffer is deliberately never destroyed.
    let _leaked = unsafe { dev.device.create_buffer(&info, None) }.expect("vkCreateBuffer");
    drop(dev);
    let m = messages.take();
    assert!(
        m.iter().any(|msg| msg.contains("VkBuffer")),
        "expected a leak report, got {m:?}"
    );
}

#[repr(C, align(16))]
#[derive(Clone, Copy, Debug, PartialEq, bytemuck::Pod, bytemuck::Zeroable)]
struct Align16([f32; 4]);

#[repr(C, align(64))]
#[derive(Clone, Copy, Debug, PartialEq, bytemuck::Pod, bytemuck::Zeroable)]
struct Align64([u8; 64]);

/// Write `value` at every offset in `offsets` (aligned and not), read it back, and
/// check the write that ends exactly at the allocation's end and the one a byte past.
fn typed_round_trip<T>(a: &mut Allocation, value: T, offsets: &[u64])
where
    T: bytemuck::Pod + PartialEq + std::fmt::Debug,
{
    let size = std::mem::size_of::<T>() as u64;
    for &offset in offsets {
        a.write(offset, &value).expect("in range");
        assert_eq!(
            a.read::<T>(offset).expect("in range"),
            value,
            "at offset {offset}"
        );
    }
    let last = a.size() - size;
    a.write(last, &value)
        .expect("a write ending exactly at the end fits");
    assert_eq!(a.read::<T>(last).expect("in range"), value);
    assert!(matches!(
        a.write(last + 1, &value),
        Err(MapError::OutOfRange { .. })
    ));
    assert!(matches!(
        a.read::<T>(last + 1),
        Err(MapError::OutOfRange { .. })
    ));
}

#[test]
fn typed_access_for_alignments_1_4_16_64() {
    let _serial = vulkan::serial();
    let (dev, messages) = device(true);
    for allocator in [
        Box::new(NaiveAllocator::new(dev.clone())) as Box<dyn Allocator>,
        Box::new(GpuAllocator::new(dev.clone()).expect("gpu-allocator")),
    ] {
        let mut r = create(&dev, allocator.as_ref(), 4096, MemoryLocation::Upload);
        let a = &mut r.allocation;
        typed_round_trip(a, 0xA5u8, &[0, 1, 63]);
        typed_round_trip(a, 0xDEAD_BEEFu32, &[0, 4, 1, 2, 3]);
        typed_round_trip(a, Align16([1.0, 2.0, 3.0, 4.0]), &[0, 16, 1, 8, 24]);
        typed_round_trip(
            a,
            Align64(std::array::from_fn(|i| i as u8)),
            &[0, 64, 1, 32, 100],
        );
        // Slices of over-aligned values, at an unaligned offset.
        let values = [Align16([5.0; 4]), Align16([6.0; 4]), Align16([7.0; 4])];
        a.write_slice(3, &values).expect("in range");
        let mut back = [Align16([0.0; 4]); 3];
        a.read_slice(3, &mut back).expect("in range");
        assert_eq!(back, values);
        destroy(&dev, r);
    }
    drop(dev);
    assert_silent(&messages);
}

#[test]
fn flushes_of_mapped_device_local_memory_are_valid() {
    let _serial = vulkan::serial();
    // Device-local memory is host-visible on lavapipe and integrated GPUs, and then
    // mapped: its flush ranges must be as valid as those of upload memory.
    let (dev, messages) = device(true);
    let allocator = GpuAllocator::new(dev.clone()).expect("gpu-allocator");
    let mut live = Vec::new();
    for size in [100u64, 36, 1000, 4] {
        let r = create(&dev, &allocator, size, MemoryLocation::DeviceLocal);
        if r.allocation.mapped_ptr().is_some() {
            r.allocation.flush(0, size).expect("flush");
            r.allocation.invalidate(size - 1, 1).expect("invalidate");
        }
        live.push(r);
    }
    for r in live {
        destroy(&dev, r);
    }
    drop(allocator);
    drop(dev);
    assert_silent(&messages);
}
