//! A crate outside the workspace depends on `tuff` by path, with one extension
//! feature, as a user's program would: it must build where it is and run on
//! lavapipe with the Khronos validation layer silent.

mod common;

use common::root;
use std::process::Command;

/// The user's program: an instance with the layer and a debug messenger (the one
/// extension feature), a device on lavapipe, a buffer written and read back through
/// mapped memory, and a command buffer with a barrier submitted and waited for.
const PROGRAM: &str = r#"
use tuff::vk;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let entry = tuff::Entry::load()?;
    let log = tuff::MessageLog::new();
    let extensions = [tuff::CStrPtr::new(c"VK_EXT_debug_utils")];
    let layers = [tuff::CStrPtr::new(c"VK_LAYER_KHRONOS_validation")];
    let app = tuff::ApplicationInfo::new().api_version(vk::API_VERSION_1_3);
    let mut chained = log.messenger_info();
    let info = tuff::InstanceCreateInfo::new()
        .application_info(Some(&app))
        .enabled_extension_names(&extensions)
        .enabled_layer_names(&layers)
        .push_next(&mut chained);
    let instance = entry.create_instance(&info)?;
    let messenger = instance.create_debug_utils_messenger_ext(&log.messenger_info())?;
    let physical = instance
        .enumerate_physical_devices()?
        .into_iter()
        .find(|p| p.name().contains("llvmpipe"))
        .ok_or("no lavapipe device (apt-get install mesa-vulkan-drivers)")?;
    let family = physical
        .queue_family_index(vk::QueueFlags::GRAPHICS)?
        .ok_or("no graphics queue")?;
    let queues = [tuff::DeviceQueueCreateInfo::new()
        .queue_family_index(family)
        .queue_priorities(&[1.0])];
    let device = physical.create_device(&tuff::DeviceCreateInfo::new().queue_create_infos(&queues))?;
    let queue = device.get_device_queue(family, 0)?;
    let allocator = device.gpu_allocator()?;
    let info = tuff::BufferCreateInfo::new()
        .size(64)
        .usage(vk::BufferUsageFlags::TRANSFER_SRC);
    let buffer = device.create_buffer_in(&info, &allocator, tuff::MemoryLocation::Upload)?;
    buffer.memory().write(0, &[42u32; 16])?;

    let pool = device.create_command_pool(
        &tuff::CommandPoolCreateInfo::new().queue_family_index(family),
    )?;
    let mut cb = device
        .allocate_command_buffers(
            &pool,
            &tuff::CommandBufferAllocateInfo::new(&pool).command_buffer_count(1),
        )?
        .pop()
        .ok_or("no command buffer")?;
    let mut rec = cb.begin(&tuff::CommandBufferBeginInfo::new())?;
    let host_writes = tuff::MemoryBarrier::new()
        .src_access_mask(vk::AccessFlags::HOST_WRITE)
        .dst_access_mask(vk::AccessFlags::TRANSFER_READ);
    rec.cmd_pipeline_barrier(
        vk::PipelineStageFlags::HOST,
        vk::PipelineStageFlags::TRANSFER,
        vk::DependencyFlags::empty(),
        &[host_writes],
        &[],
        &[],
    )?;
    rec.end()?;
    let fence = device.create_fence(&tuff::FenceCreateInfo::new())?;
    {
        let buffers = tuff::HandleSlice::new(&[&cb]);
        queue.queue_submit(&[tuff::SubmitInfo::new().command_buffers(&buffers)], &fence)?;
    }
    if device.wait_for_fences(&[&fence], vk::TRUE, u64::MAX)? != vk::Result::SUCCESS {
        return Err("the fence was not signalled".into());
    }
    let back: Vec<u32> = buffer.memory().read(0, 16)?;
    if back != [42u32; 16] {
        return Err(format!("read back {back:?}").into());
    }
    let name = physical.name();
    drop((fence, cb, pool, buffer, allocator, queue, device, physical, messenger));
    drop(instance);
    let messages = log.take();
    if !messages.is_empty() {
        return Err(format!("the validation layer said: {messages:?}").into());
    }
    println!("outside: 16 words written and read back on {name}, the layer silent");
    Ok(())
}
"#;

#[test]
fn a_crate_outside_the_workspace_builds_on_tuff_and_runs_on_lavapipe() {
    let dir = tempfile::tempdir().expect("temp folder");
    let app = dir.path().join("outside");
    std::fs::create_dir_all(app.join("src")).expect("src folder");
    let manifest = format!(
        "[package]\nname = \"outside\"\nversion = \"0.1.0\"\nedition = \"2021\"\npublish = false\n\n\
         [dependencies]\ntuff = {{ path = {:?}, features = [\"ext_debug_utils\"] }}\n\n\
         # Its own workspace, not one of a folder above.\n[workspace]\n",
        root().join("generated").display().to_string(),
    );
    std::fs::write(app.join("Cargo.toml"), manifest).expect("manifest");
    std::fs::write(app.join("src/main.rs"), PROGRAM).expect("program");
    // The workspace's lock file pins the versions its tests ran with, and lets the
    // build run offline from what the workspace's own build fetched.
    std::fs::copy(root().join("Cargo.lock"), app.join("Cargo.lock")).expect("lock file");
    let out = Command::new(env!("CARGO"))
        .args(["run", "--quiet", "--offline"])
        .current_dir(&app)
        // Its own target folder, kept between runs: this build's features differ
        // from the workspace's, and sharing would rebuild both each time.
        .env("CARGO_TARGET_DIR", root().join("target/outside"))
        .output()
        .expect("cargo runs");
    let stdout = String::from_utf8_lossy(&out.stdout);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(
        out.status.success(),
        "the outside crate failed ({}):\n{stdout}\n{stderr}",
        out.status
    );
    assert!(
        stdout.contains("16 words written and read back on llvmpipe"),
        "{stdout}\n{stderr}"
    );
}
