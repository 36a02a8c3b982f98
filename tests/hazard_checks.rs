//! Memory hazards inside a recording: a corpus of small programs, each a command
//! that reads or writes what an earlier one wrote or read, with the barrier that
//! orders them missing or too weak, and the same program with it right.
//!
//! Each broken program runs twice (`tuff_setup::breaks`): through the safe methods,
//! where tuff must refuse its last command with the hazard's identifier and the
//! layer say nothing, and with that command through its `_unchecked` twin, where the
//! layer's synchronization validation (on in every test setup) must report the same
//! hazard: so the corpus proves itself against the layer. Each fixed program is
//! recorded through the safe methods, submitted and waited for: tuff refuses
//! nothing and the layer, synchronization validation included, says nothing.
//!
//! SAFETY of the `unsafe` blocks: each `_unchecked` call breaks only the ordering
//! under test, which the layer reports and so skips; the buffer is never submitted.

#[path = "common/pipelines.rs"]
mod pipelines;
#[path = "common/tuff_setup.rs"]
mod tuff_setup;
#[path = "common/vulkan.rs"]
mod vulkan;

use tuff::vk;
use tuff_setup::{breaks, setup, Layer, Setup};
use vulkan::assert_silent;

type L = vk::ImageLayout;
type S = vk::PipelineStageFlags;
type A = vk::AccessFlags;
type S2 = vk::PipelineStageFlags2;
type A2 = vk::AccessFlags2;
type Rec<'c> = tuff::Recorder<'c, tuff::Outside>;

const RAW: &str = "SYNC-HAZARD-READ-AFTER-WRITE";
const WAR: &str = "SYNC-HAZARD-WRITE-AFTER-READ";
const WAW: &str = "SYNC-HAZARD-WRITE-AFTER-WRITE";
const IGNORED: u32 = vk::QUEUE_FAMILY_IGNORED;

/// The buffers, image and event the programs use, and a compute pipeline over the
/// buffers.
struct Objects {
    a: tuff::Buffer,
    b: tuff::Buffer,
    c: tuff::Buffer,
    /// RGBA8, 4x4, a transfer source and destination.
    image: tuff::Image,
    event: tuff::Event,
    /// `add.comp`: reads `a` and `b`, writes `c` (16 floats each).
    add: Dispatcher,
    _memory: Vec<tuff::DeviceMemory>,
}

/// A compute pipeline over storage buffers, with its set written.
struct Dispatcher {
    pipeline: tuff::Pipeline,
    layout: tuff::PipelineLayout,
    set: tuff::DescriptorSet,
    _pool: tuff::DescriptorPool,
    _set_layout: tuff::DescriptorSetLayout,
    _module: tuff::ShaderModule,
}

/// A compute pipeline of `bytes` whose set binds `buffers` as storage buffers
/// 0, 1, ... (their first 64 bytes), and takes a 4-byte push constant.
fn dispatcher(s: &Setup, bytes: &[u8], buffers: &[&tuff::Buffer]) -> Dispatcher {
    let d = &s.device;
    let storage = vk::DescriptorType::STORAGE_BUFFER;
    let bindings: Vec<_> = (0..buffers.len() as u32)
        .map(|b| {
            tuff::DescriptorSetLayoutBinding::new()
                .binding(b)
                .descriptor_type(storage)
                .descriptor_count(1)
                .stage_flags(vk::ShaderStageFlags::COMPUTE)
        })
        .collect();
    let set_layout = d
        .create_descriptor_set_layout(
            &tuff::DescriptorSetLayoutCreateInfo::new().bindings(&bindings),
        )
        .expect("set layout");
    let push = [vk::PushConstantRange {
        stage_flags: vk::ShaderStageFlags::COMPUTE,
        offset: 0,
        size: 4,
    }];
    let set_layouts = tuff::HandleSlice::new(&[&set_layout]);
    let layout = d
        .create_pipeline_layout(
            &tuff::PipelineLayoutCreateInfo::new()
                .set_layouts(&set_layouts)
                .push_constant_ranges(&push),
        )
        .expect("layout");
    let module = tuff_setup::shader(s, bytes);
    let stage = tuff::PipelineShaderStageCreateInfo::new(c"main")
        .stage(vk::ShaderStageFlags::COMPUTE)
        .module(Some(&module));
    let pipeline = d
        .create_compute_pipeline(None, &tuff::ComputePipelineCreateInfo::new(stage, &layout))
        .expect("compute pipeline");
    let sizes = [vk::DescriptorPoolSize {
        ty: storage,
        descriptor_count: buffers.len() as u32,
    }];
    let pool = d
        .create_descriptor_pool(
            &tuff::DescriptorPoolCreateInfo::new()
                .max_sets(1)
                .pool_sizes(&sizes),
        )
        .expect("pool");
    let set = d
        .allocate_descriptor_sets(
            &pool,
            &tuff::DescriptorSetAllocateInfo::new(&pool).set_layouts(&set_layout),
        )
        .expect("set")
        .pop()
        .expect("one set");
    let infos: Vec<[tuff::DescriptorBufferInfo<'_>; 1]> = buffers
        .iter()
        .map(|b| {
            [tuff::DescriptorBufferInfo::new()
                .buffer(Some(b))
                .offset(0)
                .range(64)]
        })
        .collect();
    let writes: Vec<_> = infos
        .iter()
        .enumerate()
        .map(|(b, info)| {
            tuff::WriteDescriptorSet::new(&set)
                .dst_binding(b as u32)
                .descriptor_type(storage)
                .buffer_info(info)
        })
        .collect();
    d.update_descriptor_sets(&writes, &[]).expect("writes");
    Dispatcher {
        pipeline,
        layout,
        set,
        _pool: pool,
        _set_layout: set_layout,
        _module: module,
    }
}

/// Binds `p` and its set, pushes 16 (add.comp's count) and dispatches one group,
/// through `_unchecked` when `unchecked`.
fn dispatch(p: &Dispatcher, rec: &mut Rec<'_>, unchecked: bool) -> tuff::Result<()> {
    let bind = vk::PipelineBindPoint::COMPUTE;
    rec.bind_pipeline(bind, &p.pipeline)?;
    rec.bind_descriptor_sets(bind, &p.layout, 0, &p.set, &[])?;
    rec.push_constants(
        &p.layout,
        vk::ShaderStageFlags::COMPUTE,
        0,
        &16u32.to_ne_bytes(),
    )?;
    match unchecked {
        false => rec.dispatch(1, 1, 1),
        true => unsafe { rec.dispatch_unchecked(1, 1, 1) },
    }
}

fn buffer(s: &Setup) -> (tuff::Buffer, tuff::DeviceMemory) {
    let usage = vk::BufferUsageFlags::TRANSFER_SRC
        | vk::BufferUsageFlags::TRANSFER_DST
        | vk::BufferUsageFlags::STORAGE_BUFFER;
    let b = s
        .device
        .create_buffer(&tuff::BufferCreateInfo::new().size(256).usage(usage))
        .expect("buffer");
    let needs = s.device.get_buffer_memory_requirements(&b).expect("needs");
    let m = s
        .device
        .allocate_memory(
            &tuff::MemoryAllocateInfo::new()
                .allocation_size(needs.size)
                .memory_type_index(
                    s.memory_type(needs.memory_type_bits, vk::MemoryPropertyFlags::empty()),
                ),
        )
        .expect("memory");
    s.device.bind_buffer_memory(&b, &m, 0).expect("bind");
    (b, m)
}

fn objects(s: &Setup) -> Objects {
    let (a, m1) = buffer(s);
    let (b, m2) = buffer(s);
    let (c, m3) = buffer(s);
    let usage = vk::ImageUsageFlags::TRANSFER_SRC | vk::ImageUsageFlags::TRANSFER_DST;
    let (image, m4) = layered_image(s, 1, usage);
    let event = s
        .device
        .create_event(&tuff::EventCreateInfo::new())
        .expect("event");
    let add = dispatcher(
        s,
        include_bytes!("../shaders/spv/add.comp.spv"),
        &[&a, &b, &c],
    );
    Objects {
        a,
        b,
        c,
        image,
        event,
        add,
        _memory: vec![m1, m2, m3, m4],
    }
}

fn region(src: u64, dst: u64, size: u64) -> [vk::BufferCopy; 1] {
    [vk::BufferCopy {
        src_offset: src,
        dst_offset: dst,
        size,
    }]
}

const WHOLE: vk::ImageSubresourceRange = vk::ImageSubresourceRange {
    aspect_mask: vk::ImageAspectFlags::COLOR,
    base_mip_level: 0,
    level_count: 1,
    base_array_layer: 0,
    layer_count: 1,
};

fn texels() -> [vk::BufferImageCopy; 1] {
    [vk::BufferImageCopy {
        buffer_offset: 0,
        buffer_row_length: 0,
        buffer_image_height: 0,
        image_subresource: vk::ImageSubresourceLayers {
            aspect_mask: vk::ImageAspectFlags::COLOR,
            mip_level: 0,
            base_array_layer: 0,
            layer_count: 1,
        },
        image_offset: vk::Offset3D::default(),
        image_extent: vk::Extent3D {
            width: 4,
            height: 4,
            depth: 1,
        },
    }]
}

/// A global memory barrier of the first version.
fn barrier(rec: &mut Rec<'_>, (ss, sa): (S, A), (ds, da): (S, A)) -> tuff::Result<()> {
    let m = [tuff::MemoryBarrier::new()
        .src_access_mask(sa)
        .dst_access_mask(da)];
    rec.pipeline_barrier(ss, ds, vk::DependencyFlags::empty(), &m, &[], &[])
}

/// The first version's image barrier of the whole image, from `old` to `new`.
fn image_barrier(
    o: &Objects,
    (old, new): (L, L),
    (sa, da): (A, A),
) -> [tuff::ImageMemoryBarrier<'_>; 1] {
    [tuff::ImageMemoryBarrier::new(&o.image)
        .old_layout(old)
        .new_layout(new)
        .src_access_mask(sa)
        .dst_access_mask(da)
        .src_queue_family_index(IGNORED)
        .dst_queue_family_index(IGNORED)
        .subresource_range(WHOLE)]
}

/// The image out of UNDEFINED into TRANSFER_DST_OPTIMAL, before the transfers.
fn to_dst(o: &Objects, rec: &mut Rec<'_>) -> tuff::Result<()> {
    let b = image_barrier(
        o,
        (L::UNDEFINED, L::TRANSFER_DST_OPTIMAL),
        (A::empty(), A::TRANSFER_WRITE),
    );
    rec.pipeline_barrier(
        S::TOP_OF_PIPE,
        S::TRANSFER,
        vk::DependencyFlags::empty(),
        &[],
        &[],
        &b,
    )
}

/// The image into TRANSFER_DST_OPTIMAL, then cleared.
fn clear(o: &Objects, rec: &mut Rec<'_>) -> tuff::Result<()> {
    to_dst(o, rec)?;
    let color = vk::ClearColorValue { float32: [1.0; 4] };
    rec.clear_color_image(&o.image, L::TRANSFER_DST_OPTIMAL, &color, &[WHOLE])
}

/// The image from TRANSFER_DST_OPTIMAL to TRANSFER_SRC_OPTIMAL, after `src`, for
/// transfer reads.
fn dst_to_src(
    o: &Objects,
    rec: &mut Rec<'_>,
    (ss, sa): (S, A),
    unchecked: bool,
) -> tuff::Result<()> {
    let b = image_barrier(
        o,
        (L::TRANSFER_DST_OPTIMAL, L::TRANSFER_SRC_OPTIMAL),
        (sa, A::TRANSFER_READ),
    );
    let (ds, f) = (S::TRANSFER, vk::DependencyFlags::empty());
    match unchecked {
        false => rec.pipeline_barrier(ss, ds, f, &[], &[], &b),
        true => unsafe { rec.pipeline_barrier_unchecked(ss, ds, f, &[], &[], &b) },
    }
}

/// The image from TRANSFER_SRC_OPTIMAL back to TRANSFER_DST_OPTIMAL, after `src`.
fn src_to_dst(o: &Objects, rec: &mut Rec<'_>, ss: S, unchecked: bool) -> tuff::Result<()> {
    let b = image_barrier(
        o,
        (L::TRANSFER_SRC_OPTIMAL, L::TRANSFER_DST_OPTIMAL),
        (A::empty(), A::TRANSFER_WRITE),
    );
    let (ds, f) = (S::TRANSFER, vk::DependencyFlags::empty());
    match unchecked {
        false => rec.pipeline_barrier(ss, ds, f, &[], &[], &b),
        true => unsafe { rec.pipeline_barrier_unchecked(ss, ds, f, &[], &[], &b) },
    }
}

/// A 2x2 region of the image at `(x, y)` gets `a`'s first 16 bytes.
fn quarter_from_a(
    o: &Objects,
    rec: &mut Rec<'_>,
    (x, y): (i32, i32),
    unchecked: bool,
) -> tuff::Result<()> {
    let mut t = texels();
    t[0].image_offset = vk::Offset3D { x, y, z: 0 };
    t[0].image_extent = vk::Extent3D {
        width: 2,
        height: 2,
        depth: 1,
    };
    let l = L::TRANSFER_DST_OPTIMAL;
    match unchecked {
        false => rec.copy_buffer_to_image(&o.a, &o.image, l, &t),
        true => unsafe { rec.copy_buffer_to_image_unchecked(&o.a, &o.image, l, &t) },
    }
}

/// The image gets `a`'s first 64 bytes.
fn texels_from_a(o: &Objects, rec: &mut Rec<'_>, unchecked: bool) -> tuff::Result<()> {
    let (t, l) = (texels(), L::TRANSFER_DST_OPTIMAL);
    match unchecked {
        false => rec.copy_buffer_to_image(&o.a, &o.image, l, &t),
        true => unsafe { rec.copy_buffer_to_image_unchecked(&o.a, &o.image, l, &t) },
    }
}

const TRANSFER_WRITE: (S, A) = (S::TRANSFER, A::TRANSFER_WRITE);
const TRANSFER_READ: (S, A) = (S::TRANSFER, A::TRANSFER_READ);

/// `c` gets `b`'s first 64 bytes: the command most programs end with.
fn copy_b_to_c(o: &Objects, rec: &mut Rec<'_>, unchecked: bool) -> tuff::Result<()> {
    let r = region(0, 0, 64);
    match unchecked {
        false => rec.copy_buffer(&o.b, &o.c, &r),
        true => unsafe { rec.copy_buffer_unchecked(&o.b, &o.c, &r) },
    }
}

fn fill_b(o: &Objects, rec: &mut Rec<'_>, unchecked: bool) -> tuff::Result<()> {
    match unchecked {
        false => rec.fill_buffer(&o.b, 0, 64, 7),
        true => unsafe { rec.fill_buffer_unchecked(&o.b, 0, 64, 7) },
    }
}

/// A program: it records into `rec`, with the barrier that orders its last command
/// after the earlier ones when `fixed` (and the weaker one, or none, otherwise), and
/// returns the result of its last command, recorded through `_unchecked` when
/// `unchecked`.
type Program = fn(&Objects, &mut Rec<'_>, bool, bool) -> tuff::Result<()>;

/// One hazard: the program, and the hazard it has without its barrier (`""`: a
/// program with none, which must run as it is).
struct Case {
    name: &'static str,
    hazard: &'static str,
    program: Program,
    /// Whether automatic synchronization makes the broken program right: not where
    /// the hazard is the program's own barrier (a layout transition it does not
    /// order), which tuff leaves as written.
    auto: bool,
}

/// The read-after-write fix of most programs: transfer writes made visible to
/// transfer reads.
fn transfer_barrier(rec: &mut Rec<'_>, fixed: bool) -> tuff::Result<()> {
    match fixed {
        true => barrier(rec, TRANSFER_WRITE, TRANSFER_READ),
        false => Ok(()),
    }
}

const CASES: &[Case] = &[
    Case {
        name: "a copy reads what a copy wrote",
        auto: true,
        hazard: RAW,
        program: |o, rec, fixed, u| {
            rec.copy_buffer(&o.a, &o.b, &region(0, 0, 64))?;
            transfer_barrier(rec, fixed)?;
            copy_b_to_c(o, rec, u)
        },
    },
    Case {
        name: "a copy reads what a fill wrote",
        auto: true,
        hazard: RAW,
        program: |o, rec, fixed, u| {
            fill_b(o, rec, false)?;
            transfer_barrier(rec, fixed)?;
            copy_b_to_c(o, rec, u)
        },
    },
    Case {
        name: "a copy reads what an update wrote",
        auto: true,
        hazard: RAW,
        program: |o, rec, fixed, u| {
            rec.update_buffer(&o.b, 0, &[1; 64])?;
            transfer_barrier(rec, fixed)?;
            copy_b_to_c(o, rec, u)
        },
    },
    Case {
        name: "a fill overwrites what a copy reads",
        auto: true,
        hazard: WAR,
        // A write after a read needs only an execution dependency.
        program: |o, rec, fixed, u| {
            rec.copy_buffer(&o.b, &o.a, &region(0, 0, 64))?;
            if fixed {
                let f = vk::DependencyFlags::empty();
                rec.pipeline_barrier(S::TRANSFER, S::TRANSFER, f, &[], &[], &[])?;
            }
            fill_b(o, rec, u)
        },
    },
    Case {
        name: "a fill overwrites a fill",
        auto: true,
        hazard: WAW,
        program: |o, rec, fixed, u| {
            fill_b(o, rec, false)?;
            if fixed {
                barrier(rec, TRANSFER_WRITE, TRANSFER_WRITE)?;
            }
            fill_b(o, rec, u)
        },
    },
    Case {
        name: "the barrier waits for no stage (TOP_OF_PIPE as its source)",
        auto: true,
        hazard: RAW,
        program: |o, rec, fixed, u| {
            fill_b(o, rec, false)?;
            let src = match fixed {
                true => TRANSFER_WRITE,
                false => (S::TOP_OF_PIPE, A::empty()),
            };
            barrier(rec, src, TRANSFER_READ)?;
            copy_b_to_c(o, rec, u)
        },
    },
    Case {
        name: "the barrier makes nothing available (no source access)",
        auto: true,
        hazard: RAW,
        program: |o, rec, fixed, u| {
            fill_b(o, rec, false)?;
            let src = match fixed {
                true => TRANSFER_WRITE,
                false => (S::TRANSFER, A::empty()),
            };
            barrier(rec, src, TRANSFER_READ)?;
            copy_b_to_c(o, rec, u)
        },
    },
    Case {
        name: "the barrier makes the write visible to another stage",
        auto: true,
        hazard: RAW,
        program: |o, rec, fixed, u| {
            fill_b(o, rec, false)?;
            let shader = (S::FRAGMENT_SHADER, A::SHADER_READ);
            let dst = match fixed {
                true => (shader.0 | S::TRANSFER, shader.1 | A::TRANSFER_READ),
                false => shader,
            };
            barrier(rec, TRANSFER_WRITE, dst)?;
            copy_b_to_c(o, rec, u)
        },
    },
    Case {
        name: "a buffer barrier of other bytes",
        auto: true,
        hazard: RAW,
        program: |o, rec, fixed, u| {
            fill_b(o, rec, false)?;
            let b = [tuff::BufferMemoryBarrier::new(&o.b)
                .src_access_mask(A::TRANSFER_WRITE)
                .dst_access_mask(A::TRANSFER_READ)
                .src_queue_family_index(IGNORED)
                .dst_queue_family_index(IGNORED)
                .offset(if fixed { 0 } else { 64 })
                .size(64)];
            let f = vk::DependencyFlags::empty();
            rec.pipeline_barrier(S::TRANSFER, S::TRANSFER, f, &[], &b, &[])?;
            copy_b_to_c(o, rec, u)
        },
    },
    Case {
        name: "a copy reads bytes other than those written (no hazard)",
        auto: true,
        hazard: "",
        program: |o, rec, _, u| {
            rec.fill_buffer(&o.b, 64, 64, 7)?;
            copy_b_to_c(o, rec, u)
        },
    },
    Case {
        name: "two barriers chained: available, then visible (no hazard)",
        auto: true,
        hazard: "",
        program: |o, rec, _, u| {
            fill_b(o, rec, false)?;
            barrier(rec, TRANSFER_WRITE, (S::COMPUTE_SHADER, A::empty()))?;
            barrier(rec, (S::COMPUTE_SHADER, A::empty()), TRANSFER_READ)?;
            copy_b_to_c(o, rec, u)
        },
    },
    Case {
        name: "a copy into an image overwrites a clear",
        auto: true,
        hazard: WAW,
        program: |o, rec, fixed, u| {
            clear(o, rec)?;
            if fixed {
                barrier(rec, TRANSFER_WRITE, TRANSFER_WRITE)?;
            }
            texels_from_a(o, rec, u)
        },
    },
    Case {
        name: "copies into two disjoint regions of one image level (no hazard)",
        auto: true,
        hazard: "",
        program: |o, rec, _, u| {
            to_dst(o, rec)?;
            quarter_from_a(o, rec, (0, 0), false)?;
            quarter_from_a(o, rec, (2, 2), u)
        },
    },
    Case {
        name: "a copy into an image region that meets one a copy wrote",
        auto: true,
        hazard: WAW,
        program: |o, rec, fixed, u| {
            to_dst(o, rec)?;
            quarter_from_a(o, rec, (0, 0), false)?;
            if fixed {
                barrier(rec, TRANSFER_WRITE, TRANSFER_WRITE)?;
            }
            quarter_from_a(o, rec, (1, 1), u)
        },
    },
    Case {
        name: "a copy into an image reads what a fill wrote",
        auto: true,
        hazard: RAW,
        program: |o, rec, fixed, u| {
            to_dst(o, rec)?;
            rec.fill_buffer(&o.a, 0, 64, 7)?;
            transfer_barrier(rec, fixed)?;
            texels_from_a(o, rec, u)
        },
    },
    Case {
        name: "a layout transition overwrites a clear it does not wait for",
        auto: false,
        hazard: WAW,
        program: |o, rec, fixed, u| {
            clear(o, rec)?;
            let src = match fixed {
                true => TRANSFER_WRITE,
                false => (S::TOP_OF_PIPE, A::empty()),
            };
            dst_to_src(o, rec, src, u)
        },
    },
    Case {
        name: "a layout transition overwrites what a copy reads",
        auto: false,
        hazard: WAR,
        // A transition after a read needs only an execution dependency.
        program: |o, rec, fixed, u| {
            clear(o, rec)?;
            dst_to_src(o, rec, TRANSFER_WRITE, false)?;
            rec.copy_image_to_buffer(&o.image, L::TRANSFER_SRC_OPTIMAL, &o.c, &texels())?;
            let src = if fixed { S::TRANSFER } else { S::TOP_OF_PIPE };
            src_to_dst(o, rec, src, u)
        },
    },
    Case {
        name: "a copy out of an image after its clear and transition (no hazard)",
        auto: true,
        hazard: "",
        program: |o, rec, _, u| {
            clear(o, rec)?;
            dst_to_src(o, rec, TRANSFER_WRITE, false)?;
            let (t, l) = (texels(), L::TRANSFER_SRC_OPTIMAL);
            match u {
                false => rec.copy_image_to_buffer(&o.image, l, &o.c, &t),
                true => unsafe { rec.copy_image_to_buffer_unchecked(&o.image, l, &o.c, &t) },
            }
        },
    },
    Case {
        name: "synchronization2: the barrier names the blit stage, not the fill's",
        auto: true,
        hazard: RAW,
        program: |o, rec, fixed, u| {
            fill_b(o, rec, false)?;
            let src = if fixed { S2::COPY } else { S2::BLIT };
            barrier2(rec, (src, A2::TRANSFER_WRITE))?;
            copy_b_to_c(o, rec, u)
        },
    },
    Case {
        name: "a dispatch reads what a copy wrote",
        auto: true,
        hazard: RAW,
        program: |o, rec, fixed, u| {
            rec.copy_buffer(&o.b, &o.a, &region(0, 0, 64))?;
            if fixed {
                barrier(rec, TRANSFER_WRITE, (S::COMPUTE_SHADER, A::SHADER_READ))?;
            }
            dispatch(&o.add, rec, u)
        },
    },
    Case {
        name: "a copy reads what a dispatch wrote",
        auto: true,
        hazard: RAW,
        program: |o, rec, fixed, u| {
            dispatch(&o.add, rec, false)?;
            if fixed {
                barrier(rec, (S::COMPUTE_SHADER, A::SHADER_WRITE), TRANSFER_READ)?;
            }
            let r = region(0, 0, 64);
            match u {
                false => rec.copy_buffer(&o.c, &o.b, &r),
                true => unsafe { rec.copy_buffer_unchecked(&o.c, &o.b, &r) },
            }
        },
    },
    Case {
        name: "a fill overwrites what a dispatch reads",
        auto: true,
        hazard: WAR,
        program: |o, rec, fixed, u| {
            dispatch(&o.add, rec, false)?;
            if fixed {
                let f = vk::DependencyFlags::empty();
                rec.pipeline_barrier(S::COMPUTE_SHADER, S::TRANSFER, f, &[], &[], &[])?;
            }
            match u {
                false => rec.fill_buffer(&o.a, 0, 64, 0),
                true => unsafe { rec.fill_buffer_unchecked(&o.a, 0, 64, 0) },
            }
        },
    },
    Case {
        name: "a copy overwrites what a dispatch wrote",
        auto: true,
        hazard: WAW,
        program: |o, rec, fixed, u| {
            dispatch(&o.add, rec, false)?;
            if fixed {
                barrier(rec, (S::COMPUTE_SHADER, A::SHADER_WRITE), TRANSFER_WRITE)?;
            }
            copy_b_to_c(o, rec, u)
        },
    },
    Case {
        name: "a dispatch reads what a copy wrote beside its range (no hazard)",
        auto: true,
        hazard: "",
        program: |o, rec, _, u| {
            rec.copy_buffer(&o.b, &o.a, &region(0, 64, 64))?;
            dispatch(&o.add, rec, u)
        },
    },
    Case {
        name: "an event wait that makes nothing visible",
        auto: true,
        hazard: RAW,
        program: |o, rec, fixed, u| {
            fill_b(o, rec, false)?;
            rec.set_event(&o.event, S::TRANSFER)?;
            wait(o, rec, if fixed { A::TRANSFER_READ } else { A::empty() })?;
            copy_b_to_c(o, rec, u)
        },
    },
];

/// A synchronization2 memory barrier from `src` to the copy's read.
fn barrier2(rec: &mut Rec<'_>, (ss, sa): (S2, A2)) -> tuff::Result<()> {
    let m = [tuff::MemoryBarrier2::new()
        .src_stage_mask(ss)
        .src_access_mask(sa)
        .dst_stage_mask(S2::COPY)
        .dst_access_mask(A2::TRANSFER_READ)];
    rec.pipeline_barrier2(&tuff::DependencyInfo::new().memory_barriers(&m))
}

/// Waits for the event, making transfer writes visible as `dst` to transfers.
fn wait(o: &Objects, rec: &mut Rec<'_>, dst: A) -> tuff::Result<()> {
    let m = [tuff::MemoryBarrier::new()
        .src_access_mask(A::TRANSFER_WRITE)
        .dst_access_mask(dst)];
    rec.wait_events(&o.event, S::TRANSFER, S::TRANSFER, &m, &[], &[])
}

#[test]
fn each_broken_program_is_refused_and_the_layer_reports_the_same_hazard() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let o = objects(&s);
    let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    for case in CASES.iter().filter(|c| !c.hazard.is_empty()) {
        println!("{}", case.name);
        breaks(&s, case.hazard, Layer::Names, |unchecked| {
            let mut rec = cb.begin(&tuff::CommandBufferBeginInfo::new())?;
            let r = (case.program)(&o, &mut rec, false, unchecked);
            let _ = rec.end();
            r
        });
    }
}

#[test]
fn each_fixed_program_runs_and_the_layer_is_silent() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let o = objects(&s);
    let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    for case in CASES {
        println!("{}", case.name);
        let mut rec = cb
            .begin(&tuff::CommandBufferBeginInfo::new())
            .expect("begin");
        if let Err(e) = (case.program)(&o, &mut rec, true, false) {
            panic!("{}: refused: {e}", case.name);
        }
        rec.end().expect("end");
        s.submit_wait(&cb);
        assert_silent(&s.messages);
    }
}

#[test]
fn automatic_synchronization_records_the_missing_barrier_and_the_layer_is_silent() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let o = objects(&s);
    let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    for case in CASES.iter().filter(|c| !c.hazard.is_empty()) {
        println!("{}", case.name);
        let mut rec = cb
            .begin(&tuff::CommandBufferBeginInfo::new())
            .expect("begin");
        rec.auto_sync(true);
        let r = (case.program)(&o, &mut rec, false, false);
        if !case.auto {
            // The program's own barrier is the hazard: refused as without the mode.
            assert_eq!(tuff_setup::vuid(r), case.hazard, "{}", case.name);
            let _ = rec.end();
            continue;
        }
        if let Err(e) = r {
            panic!("{}: refused: {e}", case.name);
        }
        rec.end().expect("end");
        s.submit_wait(&cb);
        assert_silent(&s.messages);
    }
}

#[test]
fn the_error_names_both_commands_the_memory_and_the_barrier() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let o = objects(&s);
    let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let mut rec = cb
        .begin(&tuff::CommandBufferBeginInfo::new())
        .expect("begin");
    fill_b(&o, &mut rec, false).expect("fill");
    let e = copy_b_to_c(&o, &mut rec, false).expect_err("a hazard");
    let _ = rec.end();
    let text = e.to_string();
    for part in [
        RAW,
        "vkCmdCopyBuffer (command 1 of the recording)",
        "vkCmdFillBuffer (command 0 of the recording)",
        "VK_ACCESS_2_TRANSFER_READ_BIT at VK_PIPELINE_STAGE_2_COPY_BIT",
        "VK_ACCESS_2_TRANSFER_WRITE_BIT at VK_PIPELINE_STAGE_2_COPY_BIT or VK_PIPELINE_STAGE_2_CLEAR_BIT",
        "bytes 0..64 of buffer",
        "a barrier from VK_PIPELINE_STAGE_2_COPY_BIT or VK_PIPELINE_STAGE_2_CLEAR_BIT with VK_ACCESS_2_TRANSFER_WRITE_BIT to VK_PIPELINE_STAGE_2_COPY_BIT with VK_ACCESS_2_TRANSFER_READ_BIT",
    ] {
        assert!(text.contains(part), "the error does not say {part:?}: {text}");
    }
    assert_silent(&s.messages);
}

/// What the draw programs use: a color target, a pipeline fetching binding 0's
/// 20-byte vertices, a vertex buffer of six and an index buffer of three that
/// transfers also write; `produce.comp` writing the vertices and an indirect draw's
/// parameters; a pipeline sampling a texture through a combined image sampler.
struct Draws {
    target: tuff_setup::ColorTarget,
    _layout: tuff::PipelineLayout,
    pipeline: tuff::Pipeline,
    vertices: tuff::Buffer,
    indices: tuff::Buffer,
    /// One `VkDrawIndirectCommand`, which `produce` writes.
    args: tuff::Buffer,
    produce: Dispatcher,
    sampling: Sampling,
    _memory: Vec<tuff::DeviceMemory>,
}

/// `quad.vert` and `quad.frag` sampling `texture` (RGBA8, 4x4) through set 0.
struct Sampling {
    pipeline: tuff::Pipeline,
    layout: tuff::PipelineLayout,
    set: tuff::DescriptorSet,
    texture: tuff::Image,
    _view: tuff::ImageView,
    _sampler: tuff::Sampler,
    _pool: tuff::DescriptorPool,
    _set_layout: tuff::DescriptorSetLayout,
    _modules: [tuff::ShaderModule; 2],
    _memory: tuff::DeviceMemory,
}

fn sampling(s: &Setup, render_pass: &tuff::RenderPass) -> Sampling {
    let d = &s.device;
    let (texture, memory, view) = s.color_image(
        4,
        vk::ImageUsageFlags::SAMPLED | vk::ImageUsageFlags::TRANSFER_DST,
    );
    let sampler = d
        .create_sampler(&tuff::SamplerCreateInfo::new())
        .expect("sampler");
    let combined = vk::DescriptorType::COMBINED_IMAGE_SAMPLER;
    let bindings = [tuff::DescriptorSetLayoutBinding::new()
        .binding(0)
        .descriptor_type(combined)
        .descriptor_count(1)
        .stage_flags(vk::ShaderStageFlags::FRAGMENT)];
    let set_layout = d
        .create_descriptor_set_layout(
            &tuff::DescriptorSetLayoutCreateInfo::new().bindings(&bindings),
        )
        .expect("set layout");
    let set_layouts = tuff::HandleSlice::new(&[&set_layout]);
    let layout = d
        .create_pipeline_layout(&tuff::PipelineLayoutCreateInfo::new().set_layouts(&set_layouts))
        .expect("layout");
    let module = |bytes| tuff_setup::shader(s, bytes);
    let vert = module(include_bytes!("../shaders/spv/quad.vert.spv"));
    let frag = module(include_bytes!("../shaders/spv/quad.frag.spv"));
    let stages = pipelines::test_stages(&vert, &frag);
    let (mut made, _) = pipelines::with_graphics_info(&stages, &layout, render_pass, |info| {
        d.create_graphics_pipelines(None, &[info])
    })
    .expect("sampling pipeline");
    let pipeline = made.pop().expect("one pipeline");
    let sizes = [vk::DescriptorPoolSize {
        ty: combined,
        descriptor_count: 1,
    }];
    let pool = d
        .create_descriptor_pool(
            &tuff::DescriptorPoolCreateInfo::new()
                .max_sets(1)
                .pool_sizes(&sizes),
        )
        .expect("pool");
    let set = d
        .allocate_descriptor_sets(
            &pool,
            &tuff::DescriptorSetAllocateInfo::new(&pool).set_layouts(&set_layout),
        )
        .expect("set")
        .pop()
        .expect("one set");
    let info = [tuff::DescriptorImageInfo::new()
        .sampler(Some(&sampler))
        .image_view(Some(&view))
        .image_layout(L::SHADER_READ_ONLY_OPTIMAL)];
    let write = tuff::WriteDescriptorSet::new(&set)
        .dst_binding(0)
        .descriptor_type(combined)
        .image_info(&info);
    d.update_descriptor_sets(&[write], &[]).expect("write");
    Sampling {
        pipeline,
        layout,
        set,
        texture,
        _view: view,
        _sampler: sampler,
        _pool: pool,
        _set_layout: set_layout,
        _modules: [vert, frag],
        _memory: memory,
    }
}

fn draws(s: &Setup) -> Draws {
    const SIZE: u32 = 4;
    let target = s.color_target(
        SIZE,
        vk::ImageUsageFlags::TRANSFER_SRC | vk::ImageUsageFlags::TRANSFER_DST,
    );
    let layout = s
        .device
        .create_pipeline_layout(&tuff::PipelineLayoutCreateInfo::new())
        .expect("layout");
    let pipeline = pipelines::vertex_pipeline(s, &layout, &target.render_pass);
    let u = vk::BufferUsageFlags::TRANSFER_DST | vk::BufferUsageFlags::STORAGE_BUFFER;
    // Three vertices drawn, room for three more.
    let (vertices, m1) = pipelines::host_buffer(s, 120, u | vk::BufferUsageFlags::VERTEX_BUFFER);
    let (indices, m2) = pipelines::host_buffer(s, 12, u | vk::BufferUsageFlags::INDEX_BUFFER);
    let (args, m3) = pipelines::host_buffer(s, 64, u | vk::BufferUsageFlags::INDIRECT_BUFFER);
    let produce = dispatcher(
        s,
        include_bytes!("../shaders/spv/produce.comp.spv"),
        &[&vertices, &args],
    );
    let sampling = sampling(s, &target.render_pass);
    Draws {
        target,
        _layout: layout,
        pipeline,
        vertices,
        indices,
        args,
        produce,
        sampling,
        _memory: vec![m1, m2, m3],
    }
}

/// Which draw a draw program ends its render pass instance with.
#[derive(Clone, Copy)]
enum Drawn {
    /// Three vertices.
    Vertices,
    /// Three indices.
    Indexed,
    /// The parameters in `args`.
    Indirect,
    /// Three vertices of the sampling pipeline.
    Sampled,
}

/// A render pass instance with one draw, `unchecked` through `_unchecked`; the
/// draw's result.
fn draw_pass<'c>(
    d: &Draws,
    rec: Rec<'c>,
    drawn: Drawn,
    unchecked: bool,
) -> (Rec<'c>, tuff::Result<()>) {
    let clear = [vk::ClearValue::default()];
    let area = vk::Rect2D {
        offset: vk::Offset2D::default(),
        extent: vk::Extent2D {
            width: 4,
            height: 4,
        },
    };
    let begin = tuff::RenderPassBeginInfo::new(&d.target.render_pass, &d.target.framebuffer)
        .render_area(area)
        .clear_values(&clear);
    let mut rec = rec.begin_render_pass(&begin, vk::SubpassContents::INLINE);
    let viewport = vk::Viewport {
        width: 4.0,
        height: 4.0,
        max_depth: 1.0,
        ..Default::default()
    };
    let graphics = vk::PipelineBindPoint::GRAPHICS;
    let setup = (|| {
        if let Drawn::Sampled = drawn {
            let p = &d.sampling;
            rec.bind_pipeline(graphics, &p.pipeline)?;
            rec.bind_descriptor_sets(graphics, &p.layout, 0, &p.set, &[])?;
        } else {
            rec.bind_pipeline(graphics, &d.pipeline)?;
            rec.bind_vertex_buffers(0, &d.vertices, &[0])?;
            rec.bind_index_buffer(&d.indices, 0, vk::IndexType::UINT32)?;
        }
        rec.set_viewport(0, &[viewport])?;
        rec.set_scissor(0, &[area])
    })();
    setup.expect("the draw's state");
    // SAFETY (the indirect draw): `produce.comp` writes three vertices, one instance.
    let r = match (drawn, unchecked) {
        (Drawn::Vertices | Drawn::Sampled, false) => rec.draw(3, 1, 0, 0),
        (Drawn::Vertices | Drawn::Sampled, true) => unsafe { rec.draw_unchecked(3, 1, 0, 0) },
        (Drawn::Indexed, false) => rec.draw_indexed(3, 1, 0, 0, 0),
        (Drawn::Indexed, true) => unsafe { rec.draw_indexed_unchecked(3, 1, 0, 0, 0) },
        (Drawn::Indirect, false) => unsafe { rec.draw_indirect(&d.args, 0, 1, 16) },
        (Drawn::Indirect, true) => unsafe { rec.draw_indirect_unchecked(&d.args, 0, 1, 16) },
    };
    (rec.end_render_pass(), r)
}

/// What a draw program records after its render pass: `(fixed, unchecked)` flags.
type After = fn(&Objects, &Draws, &mut Rec<'_>, bool, bool) -> tuff::Result<()>;

/// The draw cases: what comes before the draw, which draw, what comes after it, and
/// the hazard; `fixed` says whether the barrier that orders them is recorded.
struct DrawCase {
    name: &'static str,
    hazard: &'static str,
    before: fn(&Objects, &Draws, &mut Rec<'_>, bool) -> tuff::Result<()>,
    drawn: Drawn,
    /// After the render pass; its result is the program's when the draw is not the
    /// hazard.
    after: Option<After>,
    /// Whether automatic synchronization makes the broken program right (see
    /// [`Case::auto`]).
    auto: bool,
}

const DRAW_CASES: &[DrawCase] = &[
    DrawCase {
        name: "a draw fetches vertices a copy wrote",
        hazard: RAW,
        before: |o, d, rec, fixed| {
            rec.copy_buffer(&o.a, &d.vertices, &region(0, 0, 60))?;
            if fixed {
                barrier(
                    rec,
                    TRANSFER_WRITE,
                    (S::VERTEX_INPUT, A::VERTEX_ATTRIBUTE_READ),
                )?;
            }
            Ok(())
        },
        drawn: Drawn::Vertices,
        after: None,
        auto: true,
    },
    DrawCase {
        name: "an indexed draw reads indices a fill wrote",
        hazard: RAW,
        before: |_, d, rec, fixed| {
            rec.fill_buffer(&d.indices, 0, 12, 0)?;
            if fixed {
                barrier(rec, TRANSFER_WRITE, (S::VERTEX_INPUT, A::INDEX_READ))?;
            }
            Ok(())
        },
        drawn: Drawn::Indexed,
        after: None,
        auto: true,
    },
    DrawCase {
        name: "a fill overwrites vertices a draw fetched",
        hazard: WAR,
        before: |_, _, _, _| Ok(()),
        drawn: Drawn::Vertices,
        after: Some(|_, d, rec, fixed, unchecked| {
            if fixed {
                rec.pipeline_barrier(
                    S::VERTEX_INPUT,
                    S::TRANSFER,
                    vk::DependencyFlags::empty(),
                    &[],
                    &[],
                    &[],
                )?;
            }
            match unchecked {
                false => rec.fill_buffer(&d.vertices, 0, 60, 0),
                true => unsafe { rec.fill_buffer_unchecked(&d.vertices, 0, 60, 0) },
            }
        }),
        auto: true,
    },
    DrawCase {
        name: "a layout transition for a copy out overwrites what the render pass stored",
        hazard: WAW,
        before: |_, _, _, _| Ok(()),
        drawn: Drawn::Vertices,
        after: Some(|o, d, rec, fixed, unchecked| {
            // The render pass leaves its color attachment in COLOR_ATTACHMENT_OPTIMAL.
            let (src, access) = match fixed {
                true => (S::COLOR_ATTACHMENT_OUTPUT, A::COLOR_ATTACHMENT_WRITE),
                false => (S::TRANSFER, A::empty()),
            };
            let b = [tuff::ImageMemoryBarrier::new(&d.target.image)
                .old_layout(L::COLOR_ATTACHMENT_OPTIMAL)
                .new_layout(L::TRANSFER_SRC_OPTIMAL)
                .src_access_mask(access)
                .dst_access_mask(A::TRANSFER_READ)
                .src_queue_family_index(IGNORED)
                .dst_queue_family_index(IGNORED)
                .subresource_range(WHOLE)];
            let (ds, f) = (S::TRANSFER, vk::DependencyFlags::empty());
            let r = match unchecked {
                false => rec.pipeline_barrier(src, ds, f, &[], &[], &b),
                true => unsafe { rec.pipeline_barrier_unchecked(src, ds, f, &[], &[], &b) },
            };
            if r.is_err() || unchecked {
                return r;
            }
            let l = L::TRANSFER_SRC_OPTIMAL;
            rec.copy_image_to_buffer(&d.target.image, l, &o.c, &texels())
        }),
        auto: false,
    },
    DrawCase {
        name: "a draw fetches vertices a dispatch wrote",
        hazard: RAW,
        before: |_, d, rec, fixed| {
            dispatch(&d.produce, rec, false)?;
            if fixed {
                let fetch = (S::VERTEX_INPUT, A::VERTEX_ATTRIBUTE_READ);
                barrier(rec, (S::COMPUTE_SHADER, A::SHADER_WRITE), fetch)?;
            }
            Ok(())
        },
        drawn: Drawn::Vertices,
        after: None,
        auto: true,
    },
    DrawCase {
        name: "an indirect draw reads parameters a dispatch wrote",
        hazard: RAW,
        before: |_, d, rec, fixed| {
            dispatch(&d.produce, rec, false)?;
            if fixed {
                let read = (
                    S::DRAW_INDIRECT | S::VERTEX_INPUT,
                    A::INDIRECT_COMMAND_READ | A::VERTEX_ATTRIBUTE_READ,
                );
                barrier(rec, (S::COMPUTE_SHADER, A::SHADER_WRITE), read)?;
            }
            Ok(())
        },
        drawn: Drawn::Indirect,
        after: None,
        auto: true,
    },
    DrawCase {
        name: "a draw samples a texture whose barrier waits for another stage",
        hazard: RAW,
        before: |o, d, rec, fixed| {
            let texture = &d.sampling.texture;
            let to = |old, new, (sa, da)| {
                [tuff::ImageMemoryBarrier::new(texture)
                    .old_layout(old)
                    .new_layout(new)
                    .src_access_mask(sa)
                    .dst_access_mask(da)
                    .src_queue_family_index(IGNORED)
                    .dst_queue_family_index(IGNORED)
                    .subresource_range(WHOLE)]
            };
            let f = vk::DependencyFlags::empty();
            let b = to(
                L::UNDEFINED,
                L::TRANSFER_DST_OPTIMAL,
                (A::empty(), A::TRANSFER_WRITE),
            );
            rec.pipeline_barrier(S::TOP_OF_PIPE, S::TRANSFER, f, &[], &[], &b)?;
            let l = L::TRANSFER_DST_OPTIMAL;
            rec.copy_buffer_to_image(&o.a, texture, l, &texels())?;
            // A compute shader would see the texture; the fragment shader does not.
            let dst = if fixed {
                S::FRAGMENT_SHADER
            } else {
                S::COMPUTE_SHADER
            };
            let b = to(
                L::TRANSFER_DST_OPTIMAL,
                L::SHADER_READ_ONLY_OPTIMAL,
                (A::TRANSFER_WRITE, A::SHADER_READ),
            );
            rec.pipeline_barrier(S::TRANSFER, dst, f, &[], &[], &b)
        },
        drawn: Drawn::Sampled,
        after: None,
        auto: true,
    },
    DrawCase {
        name: "a draw fetches vertices other than those a fill wrote (no hazard)",
        hazard: "",
        before: |_, d, rec, _| rec.fill_buffer(&d.vertices, 60, 60, 0),
        drawn: Drawn::Vertices,
        after: None,
        auto: true,
    },
];

/// Records a draw case's program into `cb`: the hazardous command through
/// `_unchecked` when `unchecked`; its result.
fn draw_program(
    o: &Objects,
    d: &Draws,
    cb: &mut tuff::CommandBuffer,
    case: &DrawCase,
    (fixed, unchecked, auto): (bool, bool, bool),
) -> tuff::Result<()> {
    let mut rec = cb.begin(&tuff::CommandBufferBeginInfo::new())?;
    rec.auto_sync(auto);
    (case.before)(o, d, &mut rec, fixed)?;
    let draw_is_last = case.after.is_none();
    let (mut rec, drawn) = draw_pass(d, rec, case.drawn, unchecked && draw_is_last);
    let r = match case.after {
        None => drawn,
        Some(after) => drawn.and_then(|()| after(o, d, &mut rec, fixed, unchecked)),
    };
    let _ = rec.end();
    r
}

#[test]
fn draws_read_their_buffers_after_what_wrote_them() {
    let _serial = vulkan::serial();
    // Robust buffer access lets an indexed draw fetch vertices its indices pick.
    let robust = vk::PhysicalDeviceFeatures {
        robust_buffer_access: vk::TRUE,
        ..Default::default()
    };
    let s = tuff_setup::setup_with_features(true, robust);
    let o = objects(&s);
    let d = draws(&s);
    let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    for case in DRAW_CASES {
        println!("{}", case.name);
        if !case.hazard.is_empty() {
            breaks(&s, case.hazard, Layer::Names, |unchecked| {
                draw_program(&o, &d, &mut cb, case, (false, unchecked, false))
            });
        }
        if let Err(e) = draw_program(&o, &d, &mut cb, case, (true, false, false)) {
            panic!("{}: refused: {e}", case.name);
        }
        s.submit_wait(&cb);
        assert_silent(&s.messages);
        // The broken program with automatic synchronization.
        let r = draw_program(&o, &d, &mut cb, case, (false, false, true));
        if !case.auto {
            assert_eq!(tuff_setup::vuid(r), case.hazard, "{}", case.name);
            continue;
        }
        if let Err(e) = r {
            panic!("{}: refused with automatic synchronization: {e}", case.name);
        }
        s.submit_wait(&cb);
        assert_silent(&s.messages);
    }
}

/// A render pass whose attachment's initial layout is UNDEFINED transitions it when
/// it begins, under the implicit dependency from outside (whose first scope is
/// TOP_OF_PIPE): a copy into the image just before, with no dependency that waits
/// for it, is overwritten unordered.
#[test]
fn a_render_pass_transitions_its_attachment_after_what_wrote_it() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let o = objects(&s);
    let d = draws(&s);
    let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    breaks(&s, WAW, Layer::Names, |unchecked| {
        let mut rec = cb.begin(&tuff::CommandBufferBeginInfo::new())?;
        let b = [tuff::ImageMemoryBarrier::new(&d.target.image)
            .old_layout(L::UNDEFINED)
            .new_layout(L::TRANSFER_DST_OPTIMAL)
            .dst_access_mask(A::TRANSFER_WRITE)
            .src_queue_family_index(IGNORED)
            .dst_queue_family_index(IGNORED)
            .subresource_range(WHOLE)];
        let f = vk::DependencyFlags::empty();
        rec.pipeline_barrier(S::TOP_OF_PIPE, S::TRANSFER, f, &[], &[], &b)?;
        let l = L::TRANSFER_DST_OPTIMAL;
        rec.copy_buffer_to_image(&o.a, &d.target.image, l, &texels())?;
        let clear = [vk::ClearValue::default()];
        let area = vk::Rect2D {
            offset: vk::Offset2D::default(),
            extent: vk::Extent2D {
                width: 4,
                height: 4,
            },
        };
        let begin = tuff::RenderPassBeginInfo::new(&d.target.render_pass, &d.target.framebuffer)
            .render_area(area)
            .clear_values(&clear);
        let contents = vk::SubpassContents::INLINE;
        let rec = match unchecked {
            false => rec.begin_render_pass(&begin, contents),
            true => unsafe { rec.begin_render_pass_unchecked(&begin, contents) },
        };
        rec.end_render_pass().end()
    });
}

/// Two submissions to one queue, neither waited for before the next: what the
/// first does, and the second's commands (with the barrier that orders them after
/// the first's when `fixed` and no semaphore fixes them).
struct SubmissionCase {
    name: &'static str,
    hazard: &'static str,
    first: fn(&Objects, &mut Rec<'_>) -> tuff::Result<()>,
    second: fn(&Objects, &mut Rec<'_>, bool) -> tuff::Result<()>,
    /// Fixed by a semaphore the first submission signals and the second waits for
    /// at these stages, rather than by a barrier.
    semaphore: Option<S>,
}

const SUBMISSION_CASES: &[SubmissionCase] = &[
    SubmissionCase {
        name: "a fill overwrites what the last submission's copy reads",
        hazard: WAR,
        first: |o, rec| copy_b_to_c(o, rec, false),
        second: |o, rec, fixed| {
            if fixed {
                let f = vk::DependencyFlags::empty();
                rec.pipeline_barrier(S::TRANSFER, S::TRANSFER, f, &[], &[], &[])?;
            }
            fill_b(o, rec, false)
        },
        semaphore: None,
    },
    SubmissionCase {
        name: "two submissions without a semaphore: a copy reads what a fill wrote",
        hazard: RAW,
        first: |o, rec| fill_b(o, rec, false),
        second: |o, rec, _| copy_b_to_c(o, rec, false),
        semaphore: Some(S::TRANSFER),
    },
    SubmissionCase {
        name: "two submissions without a semaphore: a copy reads what a dispatch wrote",
        hazard: RAW,
        first: |o, rec| dispatch(&o.add, rec, false),
        second: |o, rec, _| {
            let r = region(0, 0, 64);
            rec.copy_buffer(&o.c, &o.b, &r)
        },
        semaphore: Some(S::TRANSFER),
    },
    SubmissionCase {
        name: "the last submission's fill made visible by a barrier in the next (no hazard)",
        hazard: "",
        first: |o, rec| fill_b(o, rec, false),
        second: |o, rec, _| {
            barrier(rec, TRANSFER_WRITE, TRANSFER_READ)?;
            copy_b_to_c(o, rec, false)
        },
        semaphore: None,
    },
];

/// Records `case`'s two command buffers (the second fixed when `fixed`, with
/// automatic synchronization when `auto`), submits the first, and then the
/// second (through `_unchecked` when `unchecked`, waiting for the first's
/// semaphore when `semaphore`); waits for the queue and returns the second
/// submission's result.
fn submit_pair(
    s: &Setup,
    o: &Objects,
    cbs: &mut [tuff::CommandBuffer; 2],
    case: &SubmissionCase,
    (fixed, auto, unchecked): (bool, bool, bool),
) -> tuff::Result<()> {
    let [one, two] = cbs;
    let mut rec = one.begin(&tuff::CommandBufferBeginInfo::new())?;
    (case.first)(o, &mut rec)?;
    rec.end()?;
    let mut rec = two.begin(&tuff::CommandBufferBeginInfo::new())?;
    rec.auto_sync(auto);
    (case.second)(o, &mut rec, fixed && case.semaphore.is_none())?;
    rec.end()?;
    let semaphore = s
        .device
        .create_semaphore(&tuff::SemaphoreCreateInfo::new())?;
    let gate = tuff::HandleSlice::new(&[&semaphore]);
    let wait = case.semaphore.filter(|_| fixed);
    let stages = wait.map(|st| [st]).unwrap_or_default();
    let first = tuff::HandleSlice::new(&[&*one]);
    let mut info = tuff::SubmitInfo::new().command_buffers(&first);
    if wait.is_some() {
        info = info.signal_semaphores(&gate);
    }
    s.queue.submit(&[info], None)?;
    let second = tuff::HandleSlice::new(&[&*two]);
    let mut info = tuff::SubmitInfo::new().command_buffers(&second);
    if wait.is_some() {
        info = info.wait_semaphores(&gate, &stages)?;
    }
    let r = match unchecked {
        false => s.queue.submit(&[info], None),
        true => unsafe { s.queue.submit_unchecked(&[info], None) },
    };
    s.queue.wait_idle()?;
    r
}

#[test]
fn submissions_are_ordered_after_what_the_queue_did_before() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let o = objects(&s);
    let (_pool, one) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let (_pool2, two) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let mut cbs = [one, two];
    for case in SUBMISSION_CASES {
        println!("{}", case.name);
        if !case.hazard.is_empty() {
            // The 1.3.239 layer's synchronization validation does not compare
            // submissions: tuff's error alone shows these.
            breaks(&s, case.hazard, Layer::Silent, |unchecked| {
                submit_pair(&s, &o, &mut cbs, case, (false, false, unchecked))
            });
            // Automatic synchronization orders what came before the recording.
            if let Err(e) = submit_pair(&s, &o, &mut cbs, case, (false, true, false)) {
                panic!("{}: refused with automatic synchronization: {e}", case.name);
            }
            assert_silent(&s.messages);
        }
        if let Err(e) = submit_pair(&s, &o, &mut cbs, case, (true, false, false)) {
            panic!("{}: refused: {e}", case.name);
        }
        assert_silent(&s.messages);
    }
}

/// Something recorded into a command buffer.
type Recording<'a> = dyn Fn(&mut Rec<'_>) -> tuff::Result<()> + 'a;

/// A primary command buffer (with its pool) for each program, recorded and ended.
fn recorded(
    s: &Setup,
    programs: &[&Recording<'_>],
) -> (Vec<tuff::CommandPool>, Vec<tuff::CommandBuffer>) {
    let (pools, mut cbs): (Vec<_>, Vec<_>) = programs
        .iter()
        .map(|_| s.command_buffer(vk::CommandBufferLevel::PRIMARY))
        .unzip();
    for (cb, program) in cbs.iter_mut().zip(programs) {
        let mut rec = cb
            .begin(&tuff::CommandBufferBeginInfo::new())
            .expect("begin");
        program(&mut rec).expect("recorded");
        rec.end().expect("end");
    }
    (pools, cbs)
}

/// Submits `cb` alone, with no fence.
fn submit_alone(s: &Setup, cb: &tuff::CommandBuffer) -> tuff::Result<()> {
    let list = tuff::HandleSlice::new(&[cb]);
    s.queue
        .submit(&[tuff::SubmitInfo::new().command_buffers(&list)], None)
}

/// A refused submission leaves nothing of itself in the queue's state, neither
/// what its command buffer wrote nor what its barriers ordered before the hazard:
/// the next submissions are compared with the submissions that were made only.
#[test]
fn a_refused_submission_leaves_nothing_behind() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let o = objects(&s);
    let fill_a = |rec: &mut Rec<'_>| rec.fill_buffer(&o.a, 0, 64, 1);
    let programs: [&Recording<'_>; 4] = [
        &|rec| fill_b(&o, rec, false),
        // Makes the fill of B visible to transfer reads, not to a write: the
        // second fill of B is refused after the fill of A and the barrier.
        &|rec| {
            fill_a(rec)?;
            barrier(rec, TRANSFER_WRITE, TRANSFER_READ)?;
            fill_b(&o, rec, false)
        },
        &|rec| fill_a(rec),
        &|rec| copy_b_to_c(&o, rec, false),
    ];
    let (_pools, cbs) = recorded(&s, &programs);
    let submit = |cb| submit_alone(&s, cb);
    submit(&cbs[0]).expect("the fill of B");
    let refused = submit(&cbs[1]).expect_err("a second fill of B not ordered after the first");
    assert!(
        refused.to_string().contains("WRITE-AFTER-WRITE"),
        "{refused}"
    );
    // A is written by no submission that was made.
    if let Err(e) = submit(&cbs[2]) {
        panic!("refused after the refused submission's fill of A: {e}");
    }
    // The refused submission's barrier was never made: the copy reads B with
    // nothing between it and the fill.
    let refused = submit(&cbs[3]).expect_err("a copy of B not ordered after its fill");
    assert!(
        refused.to_string().contains("READ-AFTER-WRITE"),
        "{refused}"
    );
    s.queue.wait_idle().expect("wait");
    assert_silent(&s.messages);
}

/// A fence waited for between two submissions orders the first before the second:
/// nothing of it is compared.
#[test]
fn a_waited_submission_is_complete() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let o = objects(&s);
    let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let (_pool2, mut cb2) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let mut rec = cb
        .begin(&tuff::CommandBufferBeginInfo::new())
        .expect("begin");
    fill_b(&o, &mut rec, false).expect("fill");
    rec.end().expect("end");
    s.submit_wait(&cb);
    let mut rec = cb2
        .begin(&tuff::CommandBufferBeginInfo::new())
        .expect("begin");
    copy_b_to_c(&o, &mut rec, false).expect("copy");
    rec.end().expect("end");
    s.submit_wait(&cb2);
    assert_silent(&s.messages);
}

/// A queue's complete submissions stop counting as they complete, while those still
/// running count: with one fill of B waited for and one fill of A running, a copy
/// of B passes and another fill of A is refused. Then many submissions of a fill
/// of B, each waited for, pass one after the other (the complete ones are hidden,
/// and dropped every few submissions), and a running one still counts after them.
#[test]
fn complete_submissions_stop_counting_and_running_ones_count() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let o = objects(&s);
    let fill_a = |rec: &mut Rec<'_>| rec.fill_buffer(&o.a, 0, 64, 1);
    let programs: [&Recording<'_>; 4] = [
        &|rec| fill_b(&o, rec, false),
        &|rec| fill_a(rec),
        &|rec| copy_b_to_c(&o, rec, false),
        &|rec| fill_a(rec),
    ];
    let (_pools, cbs) = recorded(&s, &programs);
    let submit = |cb| submit_alone(&s, cb);
    s.submit_wait(&cbs[0]);
    submit(&cbs[1]).expect("a fill of A");
    if let Err(e) = submit(&cbs[2]) {
        panic!("a copy of B after its fill completed was refused: {e}");
    }
    let refused = submit(&cbs[3]).expect_err("a fill of A while the first one runs");
    assert!(
        refused.to_string().contains("WRITE-AFTER-WRITE"),
        "{refused}"
    );
    s.queue.wait_idle().expect("wait");
    for n in 0..80 {
        let list = tuff::HandleSlice::new(&[&cbs[0]]);
        let fence = s
            .device
            .create_fence(&tuff::FenceCreateInfo::new())
            .expect("fence");
        let info = tuff::SubmitInfo::new().command_buffers(&list);
        if let Err(e) = s.queue.submit(&[info], Some(&fence)) {
            panic!("fill {n} of B after the last completed was refused: {e}");
        }
        let waited = s
            .device
            .wait_for_fences(&fence, true, u64::MAX)
            .expect("wait");
        assert_eq!(waited, tuff::SuccessOrTimeout::Success);
    }
    submit(&cbs[1]).expect("a fill of A");
    let refused = submit(&cbs[3]).expect_err("a fill of A while the first one runs");
    assert!(
        refused.to_string().contains("WRITE-AFTER-WRITE"),
        "{refused}"
    );
    s.queue.wait_idle().expect("wait");
    assert_silent(&s.messages);
}

/// A 4x4 RGBA image of `layers` layers for `usage`, with its memory.
fn layered_image(
    s: &Setup,
    layers: u32,
    usage: vk::ImageUsageFlags,
) -> (tuff::Image, tuff::DeviceMemory) {
    let image = s
        .device
        .create_image(
            &tuff::ImageCreateInfo::new()
                .image_type(vk::ImageType::TYPE_2D)
                .format(vk::Format::R8G8B8A8_UNORM)
                .extent(vk::Extent3D {
                    width: 4,
                    height: 4,
                    depth: 1,
                })
                .mip_levels(1)
                .array_layers(layers)
                .samples(vk::SampleCountFlags::TYPE_1)
                .usage(usage),
        )
        .expect("image");
    let memory = s.bind_image(&image);
    (image, memory)
}

/// Layer `layer` of `image` into TRANSFER_DST_OPTIMAL, then cleared.
fn clear_layer(rec: &mut Rec<'_>, image: &tuff::Image, layer: u32) -> tuff::Result<()> {
    let range = vk::ImageSubresourceRange {
        base_array_layer: layer,
        ..WHOLE
    };
    let b = [tuff::ImageMemoryBarrier::new(image)
        .old_layout(L::UNDEFINED)
        .new_layout(L::TRANSFER_DST_OPTIMAL)
        .dst_access_mask(A::TRANSFER_WRITE)
        .src_queue_family_index(IGNORED)
        .dst_queue_family_index(IGNORED)
        .subresource_range(range)];
    rec.pipeline_barrier(
        S::TOP_OF_PIPE,
        S::TRANSFER,
        vk::DependencyFlags::empty(),
        &[],
        &[],
        &b,
    )?;
    let color = vk::ClearColorValue { float32: [1.0; 4] };
    rec.clear_color_image(image, L::TRANSFER_DST_OPTIMAL, &color, &[range])
}

/// A queue's record of an image goes once the image's submissions complete: the
/// driver may give a destroyed image's handle to a new image of another shape
/// (lavapipe does, for an image made right after), whose subresources must not be
/// read through the old one's. Two clears of two layers of the new image, the
/// first still running, are not a hazard. Without the validation layer, which
/// gives every object a handle of its own.
#[test]
fn a_new_image_under_a_destroyed_one_s_handle_is_tracked_by_its_own_shape() {
    let _serial = vulkan::serial();
    let s = setup(false);
    let mut reused = 0;
    for _ in 0..4 {
        let (old_raw, _) = {
            let (image, memory) = layered_image(&s, 1, vk::ImageUsageFlags::TRANSFER_DST);
            let (pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
            let mut rec = cb
                .begin(&tuff::CommandBufferBeginInfo::new())
                .expect("begin");
            clear_layer(&mut rec, &image, 0).expect("clear");
            rec.end().expect("end");
            s.submit_wait(&cb);
            let raw = tuff::Handle::raw(&image);
            drop((cb, pool, image));
            (raw, memory)
        };
        let (image, _memory) = layered_image(&s, 2, vk::ImageUsageFlags::TRANSFER_DST);
        reused += u32::from(tuff::Handle::raw(&image) == old_raw);
        let programs: [&Recording<'_>; 2] = [&|rec| clear_layer(rec, &image, 0), &|rec| {
            clear_layer(rec, &image, 1)
        }];
        let (_pools, cbs) = recorded(&s, &programs);
        for (layer, cb) in cbs.iter().enumerate() {
            if let Err(e) = submit_alone(&s, cb) {
                panic!("the clear of layer {layer} of the new image was refused: {e}");
            }
        }
        s.queue.wait_idle().expect("wait");
    }
    // Without a handle given again, this test would show nothing.
    assert!(
        reused > 0,
        "the driver never gave a destroyed image's handle again"
    );
}

/// A secondary's commands are checked where the primary executes them: its copy
/// reads what the primary's fill wrote before, with no barrier between.
#[test]
fn a_secondary_is_checked_against_what_its_primary_did() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let o = objects(&s);
    let (_pool, mut secondary) = s.command_buffer(vk::CommandBufferLevel::SECONDARY);
    let inheritance = tuff::CommandBufferInheritanceInfo::new();
    let begin = tuff::CommandBufferBeginInfo::new().inheritance_info(Some(&inheritance));
    let mut rec = secondary.begin(&begin).expect("begin");
    copy_b_to_c(&o, &mut rec, false).expect("copy");
    rec.end().expect("end");
    let (_pool2, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let program = |cb: &mut tuff::CommandBuffer, (fixed, auto, unchecked)| {
        let mut rec = cb.begin(&tuff::CommandBufferBeginInfo::new())?;
        rec.auto_sync(auto);
        fill_b(&o, &mut rec, false)?;
        transfer_barrier(&mut rec, fixed)?;
        let r = match unchecked {
            false => rec.execute_commands(&secondary),
            true => unsafe { rec.execute_commands_unchecked(&secondary) },
        };
        let _ = rec.end();
        r
    };
    breaks(&s, RAW, Layer::Names, |unchecked| {
        program(&mut cb, (false, false, unchecked))
    });
    for (fixed, auto) in [(true, false), (false, true)] {
        program(&mut cb, (fixed, auto, false)).expect("ordered");
        s.submit_wait(&cb);
        assert_silent(&s.messages);
    }
}

/// A render pass whose second subpass reads, as an input attachment, what its first
/// wrote as a color attachment, with the dependency between them missing (broken)
/// or given: refused at creation, or begun, stepped through and ended; the layer
/// reports the hazard of the broken one when its instance steps into the second
/// subpass (the input attachment's layout transition overwrites the first
/// subpass's writes).
/// The dependencies of [`two_subpasses`]' render pass.
#[derive(Clone, Copy, PartialEq)]
enum Dependencies {
    /// None: subpass 1 reads what subpass 0 wrote, unordered.
    Missing,
    /// Subpass 0's writes before subpass 1's reads, written by hand.
    Written,
    /// `RenderPassCreateInfo::needed_dependencies`.
    Needed,
}

fn two_subpasses(
    s: &Setup,
    cb: &mut tuff::CommandBuffer,
    views: [&tuff::ImageView; 2],
    dependencies: Dependencies,
) -> tuff::Result<()> {
    let attachment = vk::AttachmentDescription {
        format: vk::Format::R8G8B8A8_UNORM,
        samples: vk::SampleCountFlags::TYPE_1,
        load_op: vk::AttachmentLoadOp::CLEAR,
        store_op: vk::AttachmentStoreOp::STORE,
        stencil_load_op: vk::AttachmentLoadOp::DONT_CARE,
        stencil_store_op: vk::AttachmentStoreOp::DONT_CARE,
        initial_layout: L::UNDEFINED,
        final_layout: L::SHADER_READ_ONLY_OPTIMAL,
        ..Default::default()
    };
    let written = [vk::AttachmentReference {
        attachment: 0,
        layout: L::COLOR_ATTACHMENT_OPTIMAL,
    }];
    let read = [vk::AttachmentReference {
        attachment: 0,
        layout: L::SHADER_READ_ONLY_OPTIMAL,
    }];
    let out = [vk::AttachmentReference {
        attachment: 1,
        layout: L::COLOR_ATTACHMENT_OPTIMAL,
    }];
    let subpasses = [
        tuff::SubpassDescription::new()
            .pipeline_bind_point(vk::PipelineBindPoint::GRAPHICS)
            .color_attachments(&written),
        tuff::SubpassDescription::new()
            .pipeline_bind_point(vk::PipelineBindPoint::GRAPHICS)
            .input_attachments(&read)
            .color_attachments(&out),
    ];
    let dependency = [vk::SubpassDependency {
        src_subpass: 0,
        dst_subpass: 1,
        src_stage_mask: S::COLOR_ATTACHMENT_OUTPUT,
        dst_stage_mask: S::FRAGMENT_SHADER,
        src_access_mask: A::COLOR_ATTACHMENT_WRITE,
        dst_access_mask: A::INPUT_ATTACHMENT_READ,
        dependency_flags: vk::DependencyFlags::BY_REGION,
    }];
    let output = vk::AttachmentDescription {
        final_layout: L::COLOR_ATTACHMENT_OPTIMAL,
        ..attachment
    };
    let attachments = [attachment, output];
    let mut info = tuff::RenderPassCreateInfo::new()
        .attachments(&attachments)
        .subpasses(&subpasses);
    let needed;
    match dependencies {
        Dependencies::Missing => {}
        Dependencies::Written => info = info.dependencies(&dependency),
        Dependencies::Needed => {
            needed = info.needed_dependencies();
            let inside: Vec<_> = needed
                .iter()
                .filter(|d| d.dst_subpass != vk::SUBPASS_EXTERNAL && d.src_subpass == 0)
                .collect();
            // Subpass 0's color write before subpass 1's input read, at one pixel;
            // one from outside into each subpass (each uses an attachment first),
            // one out of subpass 1 (where both attachments are used last).
            assert_eq!(inside.len(), 1, "{needed:?}");
            assert_eq!(
                (inside[0].src_stage_mask, inside[0].dst_stage_mask),
                (S::COLOR_ATTACHMENT_OUTPUT, S::FRAGMENT_SHADER)
            );
            assert_eq!(
                (inside[0].src_access_mask, inside[0].dst_access_mask),
                (A::COLOR_ATTACHMENT_WRITE, A::INPUT_ATTACHMENT_READ)
            );
            assert_eq!(needed.len(), 4, "{needed:?}");
            info = info.dependencies(&needed);
        }
    }
    let pass = s.device.create_render_pass(&info)?;
    let views = tuff::HandleSlice::new(&views);
    let framebuffer = s.device.create_framebuffer(
        &tuff::FramebufferCreateInfo::new(&pass)
            .attachments(&views)
            .width(4)
            .height(4)
            .layers(1),
    )?;
    let clear = [vk::ClearValue::default(); 2];
    let area = vk::Rect2D {
        offset: vk::Offset2D::default(),
        extent: vk::Extent2D {
            width: 4,
            height: 4,
        },
    };
    let begin = tuff::RenderPassBeginInfo::new(&pass, &framebuffer)
        .render_area(area)
        .clear_values(&clear);
    let rec = cb.begin(&tuff::CommandBufferBeginInfo::new())?;
    let mut rec = rec.begin_render_pass(&begin, vk::SubpassContents::INLINE);
    rec.next_subpass(vk::SubpassContents::INLINE);
    rec.end_render_pass().end()?;
    s.submit_wait(cb);
    Ok(())
}

#[test]
fn a_render_pass_orders_an_attachment_between_its_subpasses() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let (_image, _memory, view) = s.color_image(4, vk::ImageUsageFlags::INPUT_ATTACHMENT);
    let (_image2, _memory2, output) = s.color_image(4, vk::ImageUsageFlags::empty());
    let views = [&view, &output];
    // Refused at creation. The broken render pass is not run through the layer: the
    // 1.3.239 layer's synchronization validation crashes in vkCmdNextSubpass on it.
    let r = two_subpasses(&s, &mut cb, views, Dependencies::Missing);
    assert_eq!(tuff_setup::vuid(r), WAW);
    assert_silent(&s.messages);
    two_subpasses(&s, &mut cb, views, Dependencies::Written).expect("ordered");
    assert_silent(&s.messages);
    // The dependencies tuff derives order it too (and the pass's edges), the layer's
    // synchronization validation silent.
    two_subpasses(&s, &mut cb, views, Dependencies::Needed).expect("derived");
    assert_silent(&s.messages);
}

/// With automatic synchronization, the end of a recording that wrote a buffer
/// records one barrier to the host (a fence's memory dependency covers device
/// accesses only): one barrier orders what came before the recording, one the copy
/// after the fill, one the host's reads after both. A recording that writes only an
/// image gets no barrier to the host, and checked mode records none at all.
#[test]
fn automatic_synchronization_makes_buffer_writes_visible_to_the_host() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let o = objects(&s);
    let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let mut rec = cb
        .begin(&tuff::CommandBufferBeginInfo::new())
        .expect("begin");
    rec.auto_sync(true);
    assert!(rec.is_auto_sync());
    fill_b(&o, &mut rec, false).expect("fill");
    copy_b_to_c(&o, &mut rec, false).expect("copy");
    rec.end().expect("end");
    assert_eq!(cb.auto_barriers(), 3);
    s.submit_wait(&cb);

    let mut rec = cb
        .begin(&tuff::CommandBufferBeginInfo::new())
        .expect("begin");
    rec.auto_sync(true);
    let color = vk::ImageAspectFlags::COLOR;
    rec.transition_image(&o.image, color, L::UNDEFINED, L::TRANSFER_DST_OPTIMAL)
        .expect("transition");
    rec.copy_buffer_to_image(&o.a, &o.image, L::TRANSFER_DST_OPTIMAL, &texels())
        .expect("upload");
    rec.end().expect("end");
    assert_eq!(cb.auto_barriers(), 1, "only the one before the copy");
    s.submit_wait(&cb);

    let mut rec = cb
        .begin(&tuff::CommandBufferBeginInfo::new())
        .expect("begin");
    fill_b(&o, &mut rec, false).expect("fill");
    rec.end().expect("end");
    assert_eq!(cb.auto_barriers(), 0);
    s.submit_wait(&cb);
    assert_silent(&s.messages);
}

/// `transition_image` waits for what the recording did to the image, as the tracker
/// followed it (its old layout alone only where the recording has not touched the
/// image): after a copy wrote the image, the transition's barrier waits for that
/// copy, and the copy out in the new layout reads what it wrote. A first scope that
/// missed the copy is refused by tuff's transition check and reported by the layer;
/// neither says anything.
#[test]
fn transition_image_waits_for_what_the_recording_did_to_the_image() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let o = objects(&s);
    let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let mut rec = cb
        .begin(&tuff::CommandBufferBeginInfo::new())
        .expect("begin");
    let color = vk::ImageAspectFlags::COLOR;
    rec.transition_image(&o.image, color, L::UNDEFINED, L::TRANSFER_DST_OPTIMAL)
        .expect("to TRANSFER_DST");
    rec.copy_buffer_to_image(&o.a, &o.image, L::TRANSFER_DST_OPTIMAL, &texels())
        .expect("upload");
    rec.transition_image(
        &o.image,
        color,
        L::TRANSFER_DST_OPTIMAL,
        L::TRANSFER_SRC_OPTIMAL,
    )
    .expect("after the copy");
    rec.copy_image_to_buffer(&o.image, L::TRANSFER_SRC_OPTIMAL, &o.c, &texels())
        .expect("the copy out reads after the transition");
    rec.end().expect("end");
    s.submit_wait(&cb);
    assert_silent(&s.messages);
}

/// With automatic synchronization, a copy that names a transfer layout the
/// recording left the image out of gets the layout transition before it: the copy
/// out after an upload needs no hand-written transition (one barrier orders what came
/// before the recording, one moves the image to TRANSFER_SRC_OPTIMAL after the
/// upload, one makes the buffer's bytes visible to the host), and the layer says
/// nothing. Checked, the same program is refused for its layout. A copy whose region
/// reaches past the image's layers is refused by its own checks with no transition recorded
/// (the layer would report one over subresources the image does not have).
#[test]
fn automatic_synchronization_moves_an_image_to_the_layout_a_copy_names() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let o = objects(&s);
    let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let color = vk::ImageAspectFlags::COLOR;
    let program = |rec: &mut Rec<'_>| -> tuff::Result<()> {
        rec.transition_image(&o.image, color, L::UNDEFINED, L::TRANSFER_DST_OPTIMAL)?;
        rec.copy_buffer_to_image(&o.a, &o.image, L::TRANSFER_DST_OPTIMAL, &texels())?;
        rec.copy_image_to_buffer(&o.image, L::TRANSFER_SRC_OPTIMAL, &o.c, &texels())
    };
    let mut rec = cb
        .begin(&tuff::CommandBufferBeginInfo::new())
        .expect("begin");
    let e = program(&mut rec).expect_err("checked: the image is in TRANSFER_DST_OPTIMAL");
    assert!(e.to_string().contains("TRANSFER_DST_OPTIMAL"), "{e}");
    let _ = rec.end();
    assert_silent(&s.messages);

    let mut rec = cb
        .begin(&tuff::CommandBufferBeginInfo::new())
        .expect("begin");
    rec.auto_sync(true);
    program(&mut rec).expect("automatic: the transition is tuff's");
    let mut outside = texels();
    outside[0].image_subresource.layer_count = 2;
    rec.copy_image_to_buffer(&o.image, L::GENERAL, &o.c, &outside)
        .expect_err("an array layer the image does not have");
    rec.end().expect("end");
    assert_eq!(cb.auto_barriers(), 3);
    s.submit_wait(&cb);
    assert_silent(&s.messages);
}
