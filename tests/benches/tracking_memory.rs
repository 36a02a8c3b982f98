//! What tuff's tracking costs in memory: for each kind of object the checks read
//! state of, the heap bytes tuff keeps per live object (its wrapper's shared state,
//! the device's record of its creation parameters, the handles it keeps alive), and
//! the size of the wrapper itself. Raw ash keeps an 8-byte handle and nothing on the
//! heap.
//!
//! The counting allocator sees only Rust's heap: the driver's own allocations (C
//! `malloc` in lavapipe, or the GPU driver's) are not counted, so the figures are
//! tuff's alone. Each kind is made 1,000 times and kept alive; the table gives the
//! live heap growth divided by that count.
//!
//! Run with `cargo bench -p tuff-tests --bench tracking_memory`.
//!
//! SAFETY of the `unsafe` blocks around checked methods: such a method is `unsafe`
//! because it leaves rules to its caller (its `# Safety` section lists them); the
//! calls here keep every rule so listed.

#[path = "../common/pipelines.rs"]
mod pipelines;
#[path = "../common/tuff_setup.rs"]
mod tuff_setup;
#[path = "../common/vulkan.rs"]
mod vulkan;

use std::alloc::{GlobalAlloc, Layout, System};
use std::sync::atomic::{AtomicIsize, Ordering};
use tuff::vk;

/// The system allocator, counting the bytes live on Rust's heap.
struct Counting;

static LIVE: AtomicIsize = AtomicIsize::new(0);

// SAFETY: every call is forwarded to the system allocator with its own arguments;
// the counter is only bookkeeping.
unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        LIVE.fetch_add(layout.size() as isize, Ordering::Relaxed);
        // SAFETY: as the caller promises for `GlobalAlloc::alloc`.
        unsafe { System.alloc(layout) }
    }
    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        LIVE.fetch_sub(layout.size() as isize, Ordering::Relaxed);
        // SAFETY: as the caller promises for `GlobalAlloc::dealloc`.
        unsafe { System.dealloc(ptr, layout) }
    }
    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        LIVE.fetch_add(
            new_size as isize - layout.size() as isize,
            Ordering::Relaxed,
        );
        // SAFETY: as the caller promises for `GlobalAlloc::realloc`.
        unsafe { System.realloc(ptr, layout, new_size) }
    }
}

#[global_allocator]
static ALLOCATOR: Counting = Counting;

const COUNT: usize = 1_000;

/// The heap bytes per object that making `COUNT` of them with `make` keeps live,
/// beyond the vector that holds them, and the size of one.
fn per_object<T>(mut make: impl FnMut() -> T) -> (f64, usize) {
    // One first, so that maps and caches the device fills once are not counted.
    drop(make());
    let mut kept = Vec::with_capacity(COUNT);
    let before = LIVE.load(Ordering::Relaxed);
    for _ in 0..COUNT {
        kept.push(make());
    }
    let after = LIVE.load(Ordering::Relaxed);
    (
        (after - before) as f64 / COUNT as f64,
        std::mem::size_of::<T>(),
    )
}

fn main() {
    let s = tuff_setup::setup(false);
    let d = &s.device;
    let target = s.color_target(4, vk::ImageUsageFlags::empty());
    let mut rows: Vec<(&str, (f64, usize))> = Vec::new();
    rows.push((
        "buffer",
        per_object(|| {
            d.create_buffer(
                &tuff::BufferCreateInfo::new()
                    .size(256)
                    .usage(vk::BufferUsageFlags::UNIFORM_BUFFER),
            )
            .expect("buffer")
        }),
    ));
    rows.push((
        "image",
        per_object(|| {
            d.create_image(
                &tuff::ImageCreateInfo::new()
                    .image_type(vk::ImageType::TYPE_2D)
                    .format(vk::Format::R8G8B8A8_UNORM)
                    .extent(vk::Extent3D {
                        width: 4,
                        height: 4,
                        depth: 1,
                    })
                    .mip_levels(1)
                    .array_layers(1)
                    .samples(vk::SampleCountFlags::TYPE_1)
                    .usage(vk::ImageUsageFlags::SAMPLED),
            )
            .expect("image")
        }),
    ));
    rows.push((
        "image view",
        per_object(|| {
            d.create_image_view(
                &tuff::ImageViewCreateInfo::new(&target.image)
                    .view_type(vk::ImageViewType::TYPE_2D)
                    .format(vk::Format::R8G8B8A8_UNORM)
                    .subresource_range(vk::ImageSubresourceRange {
                        aspect_mask: vk::ImageAspectFlags::COLOR,
                        base_mip_level: 0,
                        level_count: 1,
                        base_array_layer: 0,
                        layer_count: 1,
                    }),
            )
            .expect("view")
        }),
    ));
    rows.push((
        "fence",
        per_object(|| {
            d.create_fence(&tuff::FenceCreateInfo::new())
                .expect("fence")
        }),
    ));
    rows.push((
        "semaphore",
        per_object(|| {
            d.create_semaphore(&tuff::SemaphoreCreateInfo::new())
                .expect("semaphore")
        }),
    ));
    let bindings = [
        tuff::DescriptorSetLayoutBinding::new()
            .binding(0)
            .descriptor_type(vk::DescriptorType::UNIFORM_BUFFER)
            .descriptor_count(1)
            .stage_flags(vk::ShaderStageFlags::VERTEX),
        tuff::DescriptorSetLayoutBinding::new()
            .binding(1)
            .descriptor_type(vk::DescriptorType::STORAGE_BUFFER)
            .descriptor_count(1)
            .stage_flags(vk::ShaderStageFlags::VERTEX),
    ];
    let set_layout = d
        .create_descriptor_set_layout(
            &tuff::DescriptorSetLayoutCreateInfo::new().bindings(&bindings),
        )
        .expect("set layout");
    rows.push((
        "descriptor set layout (2 bindings)",
        per_object(|| {
            d.create_descriptor_set_layout(
                &tuff::DescriptorSetLayoutCreateInfo::new().bindings(&bindings),
            )
            .expect("set layout")
        }),
    ));
    let set_layouts = tuff::HandleSlice::new(&[&set_layout]);
    let push = [vk::PushConstantRange {
        stage_flags: vk::ShaderStageFlags::FRAGMENT,
        offset: 0,
        size: 16,
    }];
    rows.push((
        "pipeline layout (1 set, 1 push range)",
        per_object(|| {
            d.create_pipeline_layout(
                &tuff::PipelineLayoutCreateInfo::new()
                    .set_layouts(&set_layouts)
                    .push_constant_ranges(&push),
            )
            .expect("pipeline layout")
        }),
    ));
    let sizes2 = [
        vk::DescriptorPoolSize {
            ty: vk::DescriptorType::UNIFORM_BUFFER,
            descriptor_count: 2 * COUNT as u32 + 2,
        },
        vk::DescriptorPoolSize {
            ty: vk::DescriptorType::STORAGE_BUFFER,
            descriptor_count: 2 * COUNT as u32 + 2,
        },
    ];
    let pool = d
        .create_descriptor_pool(
            &tuff::DescriptorPoolCreateInfo::new()
                .max_sets(2 * COUNT as u32 + 2)
                .pool_sizes(&sizes2),
        )
        .expect("descriptor pool");
    rows.push((
        "descriptor set (2 bindings)",
        per_object(|| {
            d.allocate_descriptor_sets(
                &pool,
                &tuff::DescriptorSetAllocateInfo::new(&pool).set_layouts(&set_layouts),
            )
            .expect("set")
            .pop()
            .expect("one set")
        }),
    ));
    rows.push((
        "render pass (1 subpass, 1 color)",
        per_object(|| {
            let attachments = [vk::AttachmentDescription {
                format: vk::Format::R8G8B8A8_UNORM,
                samples: vk::SampleCountFlags::TYPE_1,
                load_op: vk::AttachmentLoadOp::CLEAR,
                store_op: vk::AttachmentStoreOp::STORE,
                stencil_load_op: vk::AttachmentLoadOp::DONT_CARE,
                stencil_store_op: vk::AttachmentStoreOp::DONT_CARE,
                initial_layout: vk::ImageLayout::UNDEFINED,
                final_layout: vk::ImageLayout::GENERAL,
                ..Default::default()
            }];
            let colors = [vk::AttachmentReference {
                attachment: 0,
                layout: vk::ImageLayout::COLOR_ATTACHMENT_OPTIMAL,
            }];
            let subpasses = [tuff::SubpassDescription::new()
                .pipeline_bind_point(vk::PipelineBindPoint::GRAPHICS)
                .color_attachments(&colors)];
            d.create_render_pass(
                &tuff::RenderPassCreateInfo::new()
                    .attachments(&attachments)
                    .subpasses(&subpasses),
            )
            .expect("render pass")
        }),
    ));
    let command_pool = d
        .create_command_pool(&tuff::CommandPoolCreateInfo::new().queue_family_index(s.family))
        .expect("command pool");
    rows.push((
        "command buffer",
        per_object(|| {
            d.allocate_command_buffers(
                &command_pool,
                &tuff::CommandBufferAllocateInfo::new(&command_pool).command_buffer_count(1),
            )
            .expect("command buffer")
            .pop()
            .expect("one")
        }),
    ));
    // What a recorded draw keeps: a command buffer that records COUNT draws, with
    // the test pipeline bound.
    let p = pipelines::pipelines(&s, &target);
    let (_draw_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let viewport = vk::Viewport {
        width: 4.0,
        height: 4.0,
        max_depth: 1.0,
        ..Default::default()
    };
    let area = vk::Rect2D {
        offset: vk::Offset2D::default(),
        extent: vk::Extent2D {
            width: 4,
            height: 4,
        },
    };
    let clear = [vk::ClearValue::default()];
    let rec = cb
        .begin(&tuff::CommandBufferBeginInfo::new())
        .expect("begin");
    let mut rec = rec.begin_render_pass(
        &tuff::RenderPassBeginInfo::new(&target.render_pass, &target.framebuffer)
            .render_area(area)
            .clear_values(&clear),
        vk::SubpassContents::INLINE,
    );
    rec.bind_pipeline(vk::PipelineBindPoint::GRAPHICS, &p.graphics)
        .expect("bind");
    rec.set_viewport(0, &[viewport]).expect("viewport");
    rec.set_scissor(0, &[area]).expect("scissor");
    let color = [0u8; 16];
    let before = LIVE.load(Ordering::Relaxed);
    for _ in 0..COUNT {
        rec.push_constants(
            &p.graphics_layout,
            vk::ShaderStageFlags::FRAGMENT,
            0,
            &color,
        )
        .expect("push");
        rec.draw(3, 1, 0, 0).expect("draw");
    }
    let per_draw = (LIVE.load(Ordering::Relaxed) - before) as f64 / COUNT as f64;
    rec.end_render_pass().end().expect("end");

    println!("tuff's own heap per live object ({COUNT} of each kind; the driver's memory is not counted)\n");
    println!("| object | heap bytes per object | wrapper size (bytes) |");
    println!("|---|---|---|");
    for (name, (heap, size)) in &rows {
        println!("| {name} | {heap:.0} | {size} |");
    }
    println!("| recorded draw with its push constant | {per_draw:.0} | - |");
    println!("\nRaw ash keeps one 8-byte handle per object and nothing on the heap.");
}
