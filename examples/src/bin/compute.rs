//! Adds two arrays of floats on the GPU: storage buffers, a descriptor set, a compute
//! pipeline with a push constant, one dispatch, and the result read back and checked
//! on the host. Written against tuff alone, as a first compute program would be;
//! `--validate` turns the Khronos validation layer on and fails on any message.

use anyhow::{bail, ensure, Context as _, Result};
use clap::Parser;
use tuff::vk;

/// Adds two arrays of floats on the GPU and checks every sum.
#[derive(Parser)]
struct Args {
    /// How many floats in each array.
    #[arg(long, default_value_t = 1 << 20)]
    count: u32,
    /// Turn on VK_LAYER_KHRONOS_validation; any warning or error it reports fails
    /// the run.
    #[arg(long)]
    validate: bool,
}

/// Invocations per workgroup (`local_size_x` in `shaders/src/add.comp`).
const GROUP: u32 = 64;

fn main() -> std::process::ExitCode {
    let args = Args::parse();
    tuff_examples::exit(|| {
        let log = tuff::MessageLog::new();
        let sums = add_on_gpu(&args, &log);
        // Printed even when the run failed: they often say why.
        let messages = log.take();
        for m in &messages {
            eprintln!("{m}");
        }
        let (device, count) = sums?;
        if !messages.is_empty() {
            bail!(
                "the validation layer reported {} message(s) (above)",
                messages.len()
            );
        }
        println!("compute: {count} sums computed on {device} and checked");
        Ok(())
    })
}

/// Runs the addition and checks it; returns the device's name and the count.
fn add_on_gpu(args: &Args, log: &tuff::MessageLog) -> Result<(String, u32)> {
    ensure!(args.count > 0, "--count must be at least 1");
    let n = args.count as usize;

    // An instance (with the layer and a messenger into `log` when validating) and a
    // device with one queue of a family that computes.
    let app = tuff::ApplicationInfo::new().api_version(vk::API_VERSION_1_3);
    let layers = [tuff::CStrPtr::new(c"VK_LAYER_KHRONOS_validation")];
    let extensions = [tuff::CStrPtr::new(c"VK_EXT_debug_utils")];
    let mut chained = log.messenger_info();
    let mut info = tuff::InstanceCreateInfo::new().application_info(Some(&app));
    if args.validate {
        info = info
            .enabled_layer_names(&layers)
            .enabled_extension_names(&extensions)
            .push_next(&mut chained);
    }
    let instance = tuff::Entry::load()?.create_instance(&info)?;
    let _messenger = args
        .validate
        .then(|| instance.create_debug_utils_messenger_ext(&log.messenger_info()))
        .transpose()?;
    let physicals = instance.enumerate_physical_devices()?;
    // TUFF_DEVICE picks a device by name (the tests pin lavapipe with it).
    let wanted = std::env::var("TUFF_DEVICE").unwrap_or_default();
    let physical = physicals
        .into_iter()
        .find(|p| p.name().contains(&wanted))
        .context("no Vulkan device found (for lavapipe: apt-get install mesa-vulkan-drivers)")?;
    let family = physical
        .queue_family_index(vk::QueueFlags::COMPUTE)?
        .context("the device has no compute queue")?;
    let queues = [tuff::DeviceQueueCreateInfo::new()
        .queue_family_index(family)
        .queue_priorities(&[1.0])];
    let device =
        physical.create_device(&tuff::DeviceCreateInfo::new().queue_create_infos(&queues))?;
    let queue = device.get_queue(family, 0)?;
    let allocator = device.gpu_allocator()?;

    // The inputs, written by the host; the output, read back by it.
    let a: Vec<f32> = (0..n).map(|i| i as f32).collect();
    let b: Vec<f32> = (0..n).map(|i| 0.5 * (n - i) as f32).collect();
    let bytes = (n * std::mem::size_of::<f32>()) as u64;
    let storage = |location| {
        let info = tuff::BufferCreateInfo::new()
            .size(bytes)
            .usage(vk::BufferUsageFlags::STORAGE_BUFFER);
        device.create_buffer_in(&info, &allocator, location)
    };
    let (buf_a, buf_b) = (
        storage(tuff::MemoryLocation::Upload)?,
        storage(tuff::MemoryLocation::Upload)?,
    );
    let buf_c = storage(tuff::MemoryLocation::Readback)?;
    buf_a.memory().write(0, &a)?;
    buf_b.memory().write(0, &b)?;

    // Three storage buffers at bindings 0 to 2, and the count as a push constant.
    let binding = |i| {
        tuff::DescriptorSetLayoutBinding::new()
            .binding(i)
            .descriptor_type(vk::DescriptorType::STORAGE_BUFFER)
            .descriptor_count(1)
            .stage_flags(vk::ShaderStageFlags::COMPUTE)
    };
    let set_layout = device.create_descriptor_set_layout(
        &tuff::DescriptorSetLayoutCreateInfo::new().bindings(&[binding(0), binding(1), binding(2)]),
    )?;
    let set_layouts = tuff::HandleSlice::new(&[&set_layout]);
    let count_range = [vk::PushConstantRange {
        stage_flags: vk::ShaderStageFlags::COMPUTE,
        offset: 0,
        size: 4,
    }];
    let layout = device.create_pipeline_layout(
        &tuff::PipelineLayoutCreateInfo::new()
            .set_layouts(&set_layouts)
            .push_constant_ranges(&count_range),
    )?;
    // SAFETY: the shader promise: `add.comp` is valid SPIR-V for Vulkan 1.0, it
    // terminates, and it reads and writes only elements below `count`, which the
    // buffers hold.
    let module =
        unsafe { device.create_shader_module_from_spirv(tuff_examples::spirv!("add.comp")) }?;
    let stage = tuff::PipelineShaderStageCreateInfo::new(c"main")
        .stage(vk::ShaderStageFlags::COMPUTE)
        .module(Some(&module));
    let pipeline = device
        .create_compute_pipeline(None, &tuff::ComputePipelineCreateInfo::new(stage, &layout))?;

    // The descriptor set: a, b and c at bindings 0, 1 and 2.
    let pool = device.create_descriptor_pool(
        &tuff::DescriptorPoolCreateInfo::new()
            .max_sets(1)
            .pool_sizes(&[vk::DescriptorPoolSize {
                ty: vk::DescriptorType::STORAGE_BUFFER,
                descriptor_count: 3,
            }]),
    )?;
    let set = device.allocate_descriptor_set(&pool, &set_layout)?;
    let infos: Vec<[tuff::DescriptorBufferInfo<'_>; 1]> = [&buf_a, &buf_b, &buf_c]
        .into_iter()
        .map(|b| {
            [tuff::DescriptorBufferInfo::new()
                .buffer(Some(b))
                .range(vk::WHOLE_SIZE)]
        })
        .collect();
    let writes: Vec<_> = infos
        .iter()
        .enumerate()
        .map(|(i, info)| {
            tuff::WriteDescriptorSet::new(&set)
                .dst_binding(i as u32)
                .descriptor_type(vk::DescriptorType::STORAGE_BUFFER)
                .buffer_info(info)
        })
        .collect();
    device.update_descriptor_sets(&writes, &[])?;

    // One dispatch of enough workgroups, then the shader's writes made visible to the
    // host; recorded, submitted and waited for in one call.
    queue.submit_and_wait(|rec| {
        rec.bind_pipeline(vk::PipelineBindPoint::COMPUTE, &pipeline)?;
        rec.bind_descriptor_sets(vk::PipelineBindPoint::COMPUTE, &layout, 0, &set, &[])?;
        rec.push_constants(
            &layout,
            vk::ShaderStageFlags::COMPUTE,
            0,
            &args.count.to_ne_bytes(),
        )?;
        rec.dispatch(args.count.div_ceil(GROUP), 1, 1)?;
        let to_host = tuff::MemoryBarrier::new()
            .src_access_mask(vk::AccessFlags::SHADER_WRITE)
            .dst_access_mask(vk::AccessFlags::HOST_READ);
        rec.pipeline_barrier(
            vk::PipelineStageFlags::COMPUTE_SHADER,
            vk::PipelineStageFlags::HOST,
            vk::DependencyFlags::empty(),
            &[to_host],
            &[],
            &[],
        )
    })?;

    let c: Vec<f32> = buf_c.memory().read(0, n)?;
    for (i, ((x, y), sum)) in a.iter().zip(&b).zip(&c).enumerate() {
        ensure!(x + y == *sum, "element {i}: {x} + {y} came back as {sum}");
    }
    Ok((physical.name(), args.count))
}
