//! Errors the device and the window system give a correct program: device memory
//! and host memory that run out, a window destroyed under its swapchain. Each comes
//! back as a `Result`, every wrapper stays usable or droppable, nothing panics, and
//! the layer stays quiet.
//!
//! Not here, and why: a lost device (lavapipe cannot simulate one).

#[path = "common/pipelines.rs"]
mod pipelines;
#[path = "common/tuff_setup.rs"]
mod tuff_setup;
#[path = "common/vulkan.rs"]
mod vulkan;
#[path = "common/x11_window.rs"]
mod x11_window;

use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Arc;
use tuff::{vk, Handle as _};
use tuff_setup::{rgba8_image_info, setup, setup_on, setup_with, swapchain_info, Setup, Wsi};
use vulkan::assert_silent;

/// Device memory asked for until the heap refuses: every allocation a heap can give,
/// then `ERROR_OUT_OF_DEVICE_MEMORY` (or the host's), as an error; what was allocated
/// stays usable, is freed, and the heap gives again.
///
/// lavapipe's heap is host memory, reserved and committed only when written, and it
/// never refuses an allocation that fits the heap (64 of a quarter of its 2 GiB heap
/// went through): the case runs in a child process whose address space is limited to
/// 8 GiB (`ulimit -v`), where the host's memory runs out as a device's would.
#[test]
fn device_memory_runs_out_as_an_error() {
    let exe = std::env::current_exe().unwrap();
    let output = std::process::Command::new("bash")
        .arg("-c")
        .arg(r#"ulimit -v 8388608 && exec "$0" --exact out_of_memory_in_a_limited_process --ignored --nocapture --test-threads=1"#)
        .arg(&exe)
        .output()
        .expect("run the limited process");
    let text = format!(
        "{}{}",
        String::from_utf8_lossy(&output.stdout),
        String::from_utf8_lossy(&output.stderr)
    );
    assert!(output.status.success(), "{text}");
    assert!(text.contains("1 passed"), "{text}");
    let line = text
        .lines()
        .find(|l| l.contains(" allocations of "))
        .unwrap();
    println!("{line}");
}

#[test]
#[ignore = "device_memory_runs_out_as_an_error runs it in a process of limited address space"]
fn out_of_memory_in_a_limited_process() {
    let s = setup(true);
    let properties = s.physical.get_memory_properties();
    let index = s.memory_type(u32::MAX, vk::MemoryPropertyFlags::HOST_VISIBLE);
    let heap = properties.memory_types[index as usize].heap_index;
    let heap_size = properties.memory_heaps[heap as usize].size;
    let limits = s.physical.get_properties().limits;
    // The largest a single allocation may be: the heap, and Vulkan 1.1's limit.
    let mut maintenance3 = vk::PhysicalDeviceMaintenance3Properties::default();
    let mut properties2 = vk::PhysicalDeviceProperties2::default().push_next(&mut maintenance3);
    // SAFETY: a live physical device of a Vulkan 1.3 instance; the chain is local.
    unsafe {
        s.instance
            .fns()
            .get_physical_device_properties2(s.physical.raw(), &mut properties2)
    };
    let chunk = (heap_size / 4).min(maintenance3.max_memory_allocation_size);
    let info = tuff::MemoryAllocateInfo::new()
        .allocation_size(chunk)
        .memory_type_index(index);
    let mut held = Vec::new();
    let refused = loop {
        match s.device.allocate_memory(&info) {
            Ok(memory) => held.push(memory),
            Err(e) => break e,
        }
        assert!(
            held.len() < 64 && (held.len() as u32) < limits.max_memory_allocation_count,
            "{} allocations of {chunk} bytes from a heap of {heap_size} and no refusal",
            held.len()
        );
    };
    match refused {
        tuff::Error::Vk(vk::Result::ERROR_OUT_OF_DEVICE_MEMORY)
        | tuff::Error::Vk(vk::Result::ERROR_OUT_OF_HOST_MEMORY) => {}
        // Past the heap, the rule that a heap's allocations fit it: tuff refuses.
        tuff::Error::Validation { vuid, .. } => {
            assert_eq!(vuid, "VUID-vkAllocateMemory-pAllocateInfo-01713")
        }
        other => panic!("expected running out of memory, got {other}"),
    }
    println!(
        "{} allocations of {chunk} bytes from a heap of {heap_size}, then: {refused}",
        held.len()
    );
    // What was given stays usable: map one and write to it.
    if let Some(memory) = held.first() {
        let mut mapped = memory.map().expect("map");
        mapped.write(0, &[7u32; 16]).expect("write");
        assert_eq!(mapped.read::<u32>(0, 16).expect("read"), [7; 16]);
    }
    let count = held.len();
    drop(held);
    // Freed, the heap gives again.
    let again = s.device.allocate_memory(&info).expect("memory once freed");
    drop(again);
    assert!(count >= 1, "not even one allocation of {chunk} bytes");
    // The layer reports a call's error result as it passes (no rule broken): that
    // message, and nothing else.
    let said = s.messages.take();
    assert!(
        said.iter()
            .all(|m| m.ends_with(": VK_ERROR_OUT_OF_DEVICE_MEMORY")
                || m.ends_with(": VK_ERROR_OUT_OF_HOST_MEMORY")),
        "the layer reported {said:?}"
    );
}

/// The window destroyed under its swapchain, as a user closing it would: acquiring,
/// presenting and asking for the surface's capabilities give errors (the surface is
/// lost or out of date), never a panic; the swapchain and surface drop cleanly.
#[test]
fn a_window_destroyed_under_its_swapchain_is_an_error() {
    let _serial = vulkan::serial();
    let window = tuff::runtime::Vrc::new(x11_window::X11Window::open(64, 48));
    let s = setup_with(true, Wsi::Xlib);
    let surface = s.instance.create_surface(window.clone()).expect("surface");
    assert!(s
        .physical
        .get_surface_support_khr(s.family, &surface)
        .expect("support"));
    let swapchain = s
        .device
        .create_swapchain_khr(&surface, &swapchain_info(&s, &surface))
        .expect("swapchain");
    window.destroy_window();
    let semaphore = s
        .device
        .create_semaphore(&tuff::SemaphoreCreateInfo::new())
        .expect("semaphore");
    let acquired =
        s.device
            .acquire_next_image_khr(&swapchain, 1_000_000_000, Some(&semaphore), None);
    let lost = |e: &tuff::Error| {
        matches!(
            e,
            tuff::Error::Vk(
                vk::Result::ERROR_SURFACE_LOST_KHR
                    | vk::Result::ERROR_OUT_OF_DATE_KHR
                    | vk::Result::ERROR_OUT_OF_HOST_MEMORY
            )
        )
    };
    match &acquired {
        Err(e) => assert!(lost(e), "acquire: {e}"),
        Ok(r) => println!("acquire after the window went: {r:?}"),
    }
    let capabilities = s.physical.get_surface_capabilities_khr(&surface);
    match &capabilities {
        // tuff asks whether the device still presents to the surface, and refuses
        // the query by the rule that it must.
        Err(tuff::Error::Validation { vuid, .. }) => {
            assert_eq!(
                *vuid,
                "VUID-vkGetPhysicalDeviceSurfaceCapabilitiesKHR-surface-06211"
            )
        }
        Err(e) => assert!(lost(e), "capabilities: {e}"),
        Ok(_) => {}
    }
    // A new swapchain for the lost surface is an error too, not a crash.
    if let Ok(caps) = &capabilities {
        println!(
            "capabilities after the window went: {:?}",
            caps.current_extent
        );
    }
    println!(
        "acquire: {acquired:?}; capabilities: {:?}",
        capabilities.map(|c| c.current_extent)
    );
    drop((semaphore, swapchain, surface));
    assert_eq!(tuff::runtime::Vrc::strong_count(&window), 1);
    s.device.wait_idle().expect("the device is still usable");
    // The device goes on: a buffer is made and dropped.
    let buffer = s.device.create_buffer(
        &tuff::BufferCreateInfo::new()
            .size(64)
            .usage(vk::BufferUsageFlags::TRANSFER_SRC),
    );
    assert!(buffer.is_ok());
    drop(buffer);
    assert_silent(&s.messages);
}

/// A host allocator whose policy refuses everything while the returned flag is set.
fn starvable() -> (tuff::HostAllocator, Arc<AtomicBool>) {
    let starve = Arc::new(AtomicBool::new(false));
    let flag = starve.clone();
    let host = tuff::HostAllocator::with_policy(move |_| !flag.load(Ordering::SeqCst));
    (host, starve)
}

/// Whether `e` is the error a refused host allocation gives.
fn out_of_host_memory(e: &tuff::Error) -> bool {
    matches!(e, tuff::Error::Vk(vk::Result::ERROR_OUT_OF_HOST_MEMORY))
}

/// The host allocator refuses from the start: the instance is not made, and that is
/// an error naming the host's memory.
#[test]
fn an_instance_without_host_memory_is_an_error() {
    let host = tuff::HostAllocator::with_policy(|_| false);
    let entry = tuff::Entry::load()
        .expect("the Vulkan loader is not installed")
        .with_host_allocator(host.clone());
    let app = tuff::ApplicationInfo::new().api_version(vk::API_VERSION_1_3);
    let made = entry.create_instance(&tuff::InstanceCreateInfo::new().application_info(Some(&app)));
    match made {
        Err(e) => assert!(out_of_host_memory(&e), "{e}"),
        Ok(_) => panic!("an instance made without a byte of host memory"),
    }
    let stats = host.stats();
    assert!(stats.refused > 0 && stats.granted == 0, "{stats:?}");
    assert_eq!(stats.live_blocks, 0, "{stats:?}");
}

/// Objects made, commands recorded and work submitted while the host allocator
/// refuses: each refused step is `ERROR_OUT_OF_HOST_MEMORY` as an `Err`, what was
/// refused can be dropped or done again, and once the allocator gives again the same
/// device makes, records and submits as before. When everything is dropped, every
/// block the loader, layer and driver took through the callbacks has come back.
#[test]
fn host_memory_runs_out_as_an_error() {
    let (host, starve) = starvable();
    let entry = tuff::Entry::load()
        .expect("the Vulkan loader is not installed")
        .with_host_allocator(host.clone());
    let s = setup_on(entry, true);
    let before = host.stats();
    assert!(
        before.live_blocks > 0,
        "the implementation took no host memory through the callbacks: {before:?}"
    );
    let (pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let buffer_info = tuff::BufferCreateInfo::new()
        .size(256)
        .usage(vk::BufferUsageFlags::TRANSFER_DST);
    let (buffer, memory) = pipelines::host_buffer(&s, 256, vk::BufferUsageFlags::TRANSFER_DST);

    starve.store(true, Ordering::SeqCst);
    let mut refused = Vec::new();
    let mut note = |what: &str, r: Result<(), tuff::Error>| match r {
        Ok(()) => {}
        Err(e) => {
            assert!(out_of_host_memory(&e), "{what}: {e}");
            refused.push(what.to_owned());
        }
    };
    note("buffer", s.device.create_buffer(&buffer_info).map(drop));
    note(
        "image",
        s.device
            .create_image(&rgba8_image_info(16, vk::ImageUsageFlags::TRANSFER_DST))
            .map(drop),
    );
    note(
        "sampler",
        s.device
            .create_sampler(&tuff::SamplerCreateInfo::new())
            .map(drop),
    );
    note(
        "fence",
        s.device
            .create_fence(&tuff::FenceCreateInfo::new())
            .map(drop),
    );
    note(
        "command pool",
        s.device
            .create_command_pool(&tuff::CommandPoolCreateInfo::new().queue_family_index(s.family))
            .map(drop),
    );
    note(
        "command buffers",
        s.device
            .allocate_command_buffers(
                &pool,
                &tuff::CommandBufferAllocateInfo::new(&pool).command_buffer_count(4),
            )
            .map(drop),
    );
    // Recording: lavapipe keeps each command in host memory, so a refusal shows at
    // the latest when the recording ends.
    let recorded = (|| {
        let mut rec = cb.begin(&tuff::CommandBufferBeginInfo::new())?;
        for i in 0..64 {
            rec.fill_buffer(&buffer, u64::from(i) * 4, 4, i)?;
        }
        rec.end()
    })();
    note("recording", recorded.map(drop));
    starve.store(false, Ordering::SeqCst);
    let stats = host.stats();
    println!(
        "refused while starved: {} ({:?}); allocator: {stats:?}",
        refused.len(),
        refused
    );
    assert!(
        refused.len() >= 4 && stats.refused > 0,
        "the driver took almost nothing from the callbacks: {refused:?}"
    );

    // Given again: the same pool and buffer record and submit; the buffer holds the
    // fill.
    record_fill_and_submit(&s, &mut cb, &buffer, 0x5eed);
    let mapped = memory.map().expect("map");
    assert_eq!(mapped.read::<u32>(0, 4).expect("read"), [0x5eed; 4]);
    drop(mapped);
    // A submission the host allocator refuses, then the same work again.
    starve.store(true, Ordering::SeqCst);
    let fence = {
        starve.store(false, Ordering::SeqCst);
        let fence = s
            .device
            .create_fence(&tuff::FenceCreateInfo::new())
            .expect("fence");
        starve.store(true, Ordering::SeqCst);
        fence
    };
    let cbs = tuff::HandleSlice::new(&[&cb]);
    let submitted = s.queue.submit(
        &[tuff::SubmitInfo::new().command_buffers(&cbs)],
        Some(&fence),
    );
    starve.store(false, Ordering::SeqCst);
    match &submitted {
        Ok(()) => {
            let waited = s.device.wait_for_fences(&fence, true, u64::MAX);
            assert_eq!(waited.expect("wait"), tuff::SuccessOrTimeout::Success);
        }
        Err(e) => assert!(out_of_host_memory(e), "submit: {e}"),
    }
    println!("a submission while starved: {submitted:?}");
    s.device.wait_idle().expect("idle");
    record_fill_and_submit(&s, &mut cb, &buffer, 7);
    let said = s.messages.take();
    assert!(
        said.iter()
            .all(|m| m.ends_with(": VK_ERROR_OUT_OF_HOST_MEMORY")),
        "the layer reported {said:?}"
    );
    drop((fence, cb, pool, buffer, memory));
    drop(s);
    let after = host.stats();
    println!("after everything is dropped: {after:?}");
    assert_eq!(
        (after.live_blocks, after.live_bytes),
        (0, 0),
        "blocks the implementation never gave back"
    );
}

/// Records `fill` into all of `buffer`, submits it and waits.
fn record_fill_and_submit(
    s: &Setup,
    cb: &mut tuff::CommandBuffer,
    buffer: &tuff::Buffer,
    fill: u32,
) {
    let mut rec = cb
        .begin(&tuff::CommandBufferBeginInfo::new())
        .expect("begin once memory is given again");
    rec.fill_buffer(buffer, 0, 256, fill).expect("fill");
    rec.end().expect("end");
    s.submit_wait(cb);
}
