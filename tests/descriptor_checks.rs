//! Descriptor updates: each descriptor a write puts into a set must name objects of
//! the device that fit its type (usage, view shape and aspects, layout, offset
//! alignment, range), a copy must keep its sets' update-after-bind creation alike
//! and not overlap itself, a set a submission may still read is not rewritten, and
//! an update leaves the command buffers that bound the set invalid.
//!
//! Each case breaks one rule: tuff must refuse the safe call with the rule's VUID,
//! and the validation layer, for the `_unchecked` twin (told to skip the call it
//! reports), must name the same VUID.
//!
//! SAFETY of the `unsafe` blocks: the methods called are `unsafe` for rules their
//! `# Safety` sections list, which these calls keep but for the one each case
//! breaks on purpose, which tuff refuses and the layer skips.

#[path = "common/pipelines.rs"]
mod pipelines;
#[path = "common/tuff_setup.rs"]
mod tuff_setup;
#[path = "common/vulkan.rs"]
mod vulkan;

use tuff::vk;
use tuff_setup::{setup, setup_full_features, vuid, Setup};
use vulkan::assert_silent;

type T = vk::DescriptorType;
type L = vk::ImageLayout;
type U = vk::ImageUsageFlags;

/// The binding numbers of the layout every case writes into.
mod binding {
    pub const UNIFORM: u32 = 0;
    pub const STORAGE: u32 = 1;
    pub const SAMPLED: u32 = 2;
    pub const STORAGE_IMAGE: u32 = 3;
    pub const COMBINED: u32 = 4;
    pub const IMMUTABLE_SAMPLER: u32 = 5;
    pub const UNIFORM_TEXEL: u32 = 6;
    pub const STORAGE_TEXEL: u32 = 7;
    pub const INPUT: u32 = 8;
    pub const SAMPLER: u32 = 9;
    /// A combined image sampler with an immutable sampler, followed by one without.
    pub const COMBINED_IMMUTABLE: u32 = 10;
    pub const INLINE: u32 = 12;
}

/// A device's objects for the cases: the set layout and a set of it, and resources.
struct Objects {
    _sampler_layout: tuff::DescriptorSetLayout,
    _pool: tuff::DescriptorPool,
    set: tuff::DescriptorSet,
    sampler: tuff::Sampler,
    /// Uniform and storage, bound, 128 KiB (above lavapipe's uniform range limit).
    buffer: tuff::Buffer,
    /// Uniform, no memory.
    unbound: tuff::Buffer,
    /// Storage only, bound.
    storage_only: tuff::Buffer,
    /// Uniform only, bound.
    uniform_only: tuff::Buffer,
    /// Views of a buffer with only one texel usage each.
    uniform_texel_view: tuff::BufferView,
    storage_texel_view: tuff::BufferView,
    /// A sampled, storage and input-attachment RGBA8 image's view, and one with a
    /// swizzle.
    view: tuff::ImageView,
    swizzled: tuff::ImageView,
    /// A view of an image with color-attachment usage only.
    transfer_only: tuff::ImageView,
    /// 2D and 2D-array views of a 3D image.
    slice_2d: tuff::ImageView,
    slice_2d_array: tuff::ImageView,
    /// A view of both aspects of a sampled depth/stencil image.
    depth_stencil: tuff::ImageView,
    _images: Vec<tuff::Image>,
    _memories: Vec<tuff::DeviceMemory>,
}

fn objects(s: &Setup) -> Objects {
    let d = &s.device;
    let sampler = d
        .create_sampler(&tuff::SamplerCreateInfo::new())
        .expect("sampler");
    let stages = vk::ShaderStageFlags::FRAGMENT;
    let b = |n: u32, ty: T, count: u32| {
        tuff::DescriptorSetLayoutBinding::new()
            .binding(n)
            .descriptor_type(ty)
            .descriptor_count(count)
            .stage_flags(stages)
    };
    let bindings = [
        b(binding::UNIFORM, T::UNIFORM_BUFFER, 2),
        b(binding::STORAGE, T::STORAGE_BUFFER, 1),
        b(binding::SAMPLED, T::SAMPLED_IMAGE, 1),
        b(binding::STORAGE_IMAGE, T::STORAGE_IMAGE, 1),
        b(binding::COMBINED, T::COMBINED_IMAGE_SAMPLER, 1),
        b(binding::IMMUTABLE_SAMPLER, T::SAMPLER, 1).immutable_samplers(&sampler),
        b(binding::UNIFORM_TEXEL, T::UNIFORM_TEXEL_BUFFER, 1),
        b(binding::STORAGE_TEXEL, T::STORAGE_TEXEL_BUFFER, 1),
        b(binding::INPUT, T::INPUT_ATTACHMENT, 1),
        b(binding::SAMPLER, T::SAMPLER, 1),
        b(binding::COMBINED_IMMUTABLE, T::COMBINED_IMAGE_SAMPLER, 1).immutable_samplers(&sampler),
        b(
            binding::COMBINED_IMMUTABLE + 1,
            T::COMBINED_IMAGE_SAMPLER,
            1,
        ),
        b(binding::INLINE, T::INLINE_UNIFORM_BLOCK, 16),
    ];
    let layout = d
        .create_descriptor_set_layout(
            &tuff::DescriptorSetLayoutCreateInfo::new().bindings(&bindings),
        )
        .expect("set layout");
    let size = |ty: T, descriptor_count: u32| vk::DescriptorPoolSize {
        ty,
        descriptor_count,
    };
    let sizes = [
        size(T::UNIFORM_BUFFER, 2),
        size(T::STORAGE_BUFFER, 1),
        size(T::SAMPLED_IMAGE, 1),
        size(T::STORAGE_IMAGE, 1),
        size(T::COMBINED_IMAGE_SAMPLER, 3),
        size(T::SAMPLER, 2),
        size(T::UNIFORM_TEXEL_BUFFER, 1),
        size(T::STORAGE_TEXEL_BUFFER, 1),
        size(T::INPUT_ATTACHMENT, 1),
        size(T::INLINE_UNIFORM_BLOCK, 16),
    ];
    let mut inline = tuff::DescriptorPoolInlineUniformBlockCreateInfo::new()
        .max_inline_uniform_block_bindings(1);
    let pool = d
        .create_descriptor_pool(
            &tuff::DescriptorPoolCreateInfo::new()
                .max_sets(1)
                .pool_sizes(&sizes)
                .push_next(&mut inline),
        )
        .expect("pool");
    let set = d
        .allocate_descriptor_sets(
            &pool,
            &tuff::DescriptorSetAllocateInfo::new(&pool).set_layouts(&layout),
        )
        .expect("set")
        .pop()
        .expect("one set");

    let mut memories = Vec::new();
    let mut bound_buffer = |size: u64, usage: vk::BufferUsageFlags| {
        let buffer = d
            .create_buffer(&tuff::BufferCreateInfo::new().size(size).usage(usage))
            .expect("buffer");
        let reqs = d
            .get_buffer_memory_requirements(&buffer)
            .expect("requirements");
        let memory = d
            .allocate_memory(
                &tuff::MemoryAllocateInfo::new()
                    .allocation_size(reqs.size)
                    .memory_type_index(
                        s.memory_type(reqs.memory_type_bits, vk::MemoryPropertyFlags::empty()),
                    ),
            )
            .expect("memory");
        d.bind_buffer_memory(&buffer, &memory, 0).expect("bind");
        memories.push(memory);
        buffer
    };
    type B = vk::BufferUsageFlags;
    let buffer = bound_buffer(128 << 10, B::UNIFORM_BUFFER | B::STORAGE_BUFFER);
    let storage_only = bound_buffer(256, B::STORAGE_BUFFER);
    let uniform_only = bound_buffer(256, B::UNIFORM_BUFFER);
    let storage_texel = bound_buffer(256, B::STORAGE_TEXEL_BUFFER);
    let uniform_texel = bound_buffer(256, B::UNIFORM_TEXEL_BUFFER);
    let unbound = d
        .create_buffer(
            &tuff::BufferCreateInfo::new()
                .size(256)
                .usage(B::UNIFORM_BUFFER),
        )
        .expect("buffer");
    let texel_view = |buffer: &tuff::Buffer| {
        d.create_buffer_view(
            &tuff::BufferViewCreateInfo::new(buffer)
                .format(vk::Format::R8G8B8A8_UNORM)
                .range(vk::WHOLE_SIZE),
        )
        .expect("buffer view")
    };
    // Each view names a buffer whose only texel usage is the other type's.
    let uniform_texel_view = texel_view(&storage_texel);
    let storage_texel_view = texel_view(&uniform_texel);

    let mut images = Vec::new();
    let mut image = |ty: vk::ImageType, format: vk::Format, usage: U, flags, depth: u32| {
        let image = d
            .create_image(
                &tuff::ImageCreateInfo::new()
                    .flags(flags)
                    .image_type(ty)
                    .format(format)
                    .extent(vk::Extent3D {
                        width: 4,
                        height: 4,
                        depth,
                    })
                    .mip_levels(1)
                    .array_layers(1)
                    .samples(vk::SampleCountFlags::TYPE_1)
                    .usage(usage),
            )
            .expect("image");
        memories.push(s.bind_image(&image));
        image
    };
    let rgba = vk::Format::R8G8B8A8_UNORM;
    let no_flags = vk::ImageCreateFlags::empty();
    let color = image(
        vk::ImageType::TYPE_2D,
        rgba,
        U::SAMPLED | U::STORAGE | U::INPUT_ATTACHMENT,
        no_flags,
        1,
    );
    let transfer = image(
        vk::ImageType::TYPE_2D,
        rgba,
        U::COLOR_ATTACHMENT,
        no_flags,
        1,
    );
    let volume = image(
        vk::ImageType::TYPE_3D,
        rgba,
        U::SAMPLED,
        vk::ImageCreateFlags::TYPE_2D_ARRAY_COMPATIBLE,
        4,
    );
    let ds = image(
        vk::ImageType::TYPE_2D,
        vk::Format::D32_SFLOAT_S8_UINT,
        U::SAMPLED | U::INPUT_ATTACHMENT,
        no_flags,
        1,
    );
    let range = |aspect_mask| vk::ImageSubresourceRange {
        aspect_mask,
        base_mip_level: 0,
        level_count: 1,
        base_array_layer: 0,
        layer_count: 1,
    };
    let color_range = range(vk::ImageAspectFlags::COLOR);
    let view_of = |image: &tuff::Image, ty, format, range, components| {
        d.create_image_view(
            &tuff::ImageViewCreateInfo::new(image)
                .view_type(ty)
                .format(format)
                .components(components)
                .subresource_range(range),
        )
        .expect("view")
    };
    let identity = vk::ComponentMapping::default();
    let two_d = vk::ImageViewType::TYPE_2D;
    let view = view_of(&color, two_d, rgba, color_range, identity);
    let swizzled = view_of(
        &color,
        two_d,
        rgba,
        color_range,
        vk::ComponentMapping {
            r: vk::ComponentSwizzle::B,
            b: vk::ComponentSwizzle::R,
            ..identity
        },
    );
    let transfer_only = view_of(&transfer, two_d, rgba, color_range, identity);
    let slice_2d = view_of(&volume, two_d, rgba, color_range, identity);
    let slice_2d_array = view_of(
        &volume,
        vk::ImageViewType::TYPE_2D_ARRAY,
        rgba,
        color_range,
        identity,
    );
    let depth_stencil = view_of(
        &ds,
        two_d,
        vk::Format::D32_SFLOAT_S8_UINT,
        range(vk::ImageAspectFlags::DEPTH | vk::ImageAspectFlags::STENCIL),
        identity,
    );
    images.extend([color, transfer, volume, ds]);
    Objects {
        _sampler_layout: layout,
        _pool: pool,
        set,
        sampler,
        buffer,
        unbound,
        storage_only,
        uniform_only,
        uniform_texel_view,
        storage_texel_view,
        view,
        swizzled,
        transfer_only,
        slice_2d,
        slice_2d_array,
        depth_stencil,
        _images: images,
        _memories: memories,
    }
}

/// One image info.
fn image_info<'a>(
    sampler: &'a tuff::Sampler,
    view: &'a tuff::ImageView,
    layout: L,
) -> [tuff::DescriptorImageInfo<'a>; 1] {
    [tuff::DescriptorImageInfo::new()
        .sampler(Some(sampler))
        .image_view(Some(view))
        .image_layout(layout)]
}

/// One buffer info.
fn buffer_info(
    buffer: Option<&tuff::Buffer>,
    offset: u64,
    range: u64,
) -> [tuff::DescriptorBufferInfo<'_>; 1] {
    [tuff::DescriptorBufferInfo::new()
        .buffer(buffer)
        .offset(offset)
        .range(range)]
}

/// A write of one descriptor's image info into `binding`.
fn image_write<'a>(
    set: &'a tuff::DescriptorSet,
    binding: u32,
    ty: T,
    infos: &'a [tuff::DescriptorImageInfo<'a>],
) -> tuff::WriteDescriptorSet<'a> {
    tuff::WriteDescriptorSet::new(set)
        .dst_binding(binding)
        .descriptor_type(ty)
        .image_info(infos)
}

/// A write of buffer infos into `binding`.
fn buffer_write<'a>(
    set: &'a tuff::DescriptorSet,
    binding: u32,
    ty: T,
    infos: &'a [tuff::DescriptorBufferInfo<'a>],
) -> tuff::WriteDescriptorSet<'a> {
    tuff::WriteDescriptorSet::new(set)
        .dst_binding(binding)
        .descriptor_type(ty)
        .buffer_info(infos)
}

/// Runs each case through the safe update, which must refuse it with the case's
/// VUID, then through the unchecked one, for which the layer must name it.
fn run(s: &Setup, cases: &[(&'static str, tuff::WriteDescriptorSet<'_>)]) {
    run_or(s, cases, &[]);
}

/// [`run`], where the layer may name one of `siblings` instead: a rule that the same
/// objects break and that it checks first.
fn run_or(s: &Setup, cases: &[(&'static str, tuff::WriteDescriptorSet<'_>)], siblings: &[&str]) {
    let d = &s.device;
    for (rule, w) in cases {
        assert_eq!(
            vuid(d.update_descriptor_sets(&[*w], &[])),
            *rule,
            "the safe update of the case for {rule}"
        );
    }
    assert_silent(&s.messages);
    for (rule, w) in cases {
        s.messages.abort_on_error(true);
        // SAFETY: the layer skips the call, which breaks only the rule under test.
        unsafe { d.update_descriptor_sets_unchecked(&[*w], &[]) };
        s.messages.abort_on_error(false);
        let said = s.messages.take();
        assert!(
            said.iter()
                .any(|m| m.contains(rule) || siblings.iter().any(|r| m.contains(r))),
            "the layer did not name {rule}; it said {said:?}"
        );
    }
}

#[test]
fn image_descriptors_fit_their_type() {
    let _serial = vulkan::serial();
    let s = setup_full_features(true);
    let o = objects(&s);
    let info = |view, layout| image_info(&o.sampler, view, layout);
    let read = L::SHADER_READ_ONLY_OPTIMAL;
    let general = L::GENERAL;
    let swizzled = info(&o.swizzled, general);
    let transfer_sampled = info(&o.transfer_only, read);
    let transfer_storage = info(&o.transfer_only, general);
    let transfer_input = info(&o.transfer_only, read);
    let wrong_layout = info(&o.view, L::TRANSFER_DST_OPTIMAL);
    let storage_read = info(&o.view, read);
    let slice_2d = info(&o.slice_2d, read);
    let slice_2d_array = info(&o.slice_2d_array, read);
    let both_aspects = info(&o.depth_stencil, L::DEPTH_STENCIL_READ_ONLY_OPTIMAL);
    let good = info(&o.view, read);
    let two = [good[0], good[0]];
    // What a type does not read may be left out; what it reads may not.
    let no_sampler = [tuff::DescriptorImageInfo::new()
        .image_view(Some(&o.view))
        .image_layout(read)];
    let no_view = [tuff::DescriptorImageInfo::new()
        .sampler(Some(&o.sampler))
        .image_layout(read)];
    let buffers = buffer_info(Some(&o.buffer), 0, 16);
    let set = &o.set;
    let cases = [
        (
            "VUID-VkWriteDescriptorSet-descriptorType-00325",
            image_write(
                set,
                binding::COMBINED,
                T::COMBINED_IMAGE_SAMPLER,
                &no_sampler,
            ),
        ),
        (
            "VUID-VkWriteDescriptorSet-descriptorType-02997",
            image_write(set, binding::SAMPLED, T::SAMPLED_IMAGE, &no_view),
        ),
        (
            "VUID-VkWriteDescriptorSet-descriptorType-07683",
            image_write(set, binding::INPUT, T::INPUT_ATTACHMENT, &no_view),
        ),
        (
            "VUID-vkUpdateDescriptorSets-pDescriptorWrites-06493",
            buffer_write(set, binding::SAMPLED, T::SAMPLED_IMAGE, &buffers),
        ),
        (
            "VUID-VkWriteDescriptorSet-descriptorType-00336",
            image_write(set, binding::STORAGE_IMAGE, T::STORAGE_IMAGE, &swizzled),
        ),
        (
            "VUID-VkWriteDescriptorSet-descriptorType-00337",
            image_write(set, binding::SAMPLED, T::SAMPLED_IMAGE, &transfer_sampled),
        ),
        (
            "VUID-VkWriteDescriptorSet-descriptorType-00338",
            image_write(set, binding::INPUT, T::INPUT_ATTACHMENT, &transfer_input),
        ),
        (
            "VUID-VkWriteDescriptorSet-descriptorType-00339",
            image_write(
                set,
                binding::STORAGE_IMAGE,
                T::STORAGE_IMAGE,
                &transfer_storage,
            ),
        ),
        (
            "VUID-VkWriteDescriptorSet-descriptorType-04149",
            image_write(set, binding::SAMPLED, T::SAMPLED_IMAGE, &wrong_layout),
        ),
        (
            "VUID-VkWriteDescriptorSet-descriptorType-04150",
            image_write(
                set,
                binding::COMBINED,
                T::COMBINED_IMAGE_SAMPLER,
                &wrong_layout,
            ),
        ),
        (
            "VUID-VkWriteDescriptorSet-descriptorType-04151",
            image_write(set, binding::INPUT, T::INPUT_ATTACHMENT, &wrong_layout),
        ),
        (
            "VUID-VkWriteDescriptorSet-descriptorType-04152",
            image_write(set, binding::STORAGE_IMAGE, T::STORAGE_IMAGE, &storage_read),
        ),
        (
            "VUID-VkDescriptorImageInfo-imageView-06711",
            image_write(set, binding::SAMPLED, T::SAMPLED_IMAGE, &slice_2d),
        ),
        (
            "VUID-VkDescriptorImageInfo-imageView-06712",
            image_write(set, binding::SAMPLED, T::SAMPLED_IMAGE, &slice_2d_array),
        ),
        (
            "VUID-VkWriteDescriptorSet-descriptorType-02752",
            image_write(set, binding::IMMUTABLE_SAMPLER, T::SAMPLER, &good),
        ),
        (
            "VUID-VkWriteDescriptorSet-descriptorCount-00318",
            image_write(
                set,
                binding::COMBINED_IMMUTABLE,
                T::COMBINED_IMAGE_SAMPLER,
                &two,
            ),
        ),
    ];
    run(&s, &cases);
    // A view of both aspects of a depth/stencil image: the 1.3.239 layer reports
    // it (for any type) as UNASSIGNED-CoreValidation-DrawState-InvalidImageView,
    // "has both STENCIL and DEPTH aspects set".
    let aspects = [
        (
            "VUID-VkWriteDescriptorSet-descriptorType-07729",
            image_write(set, binding::INPUT, T::INPUT_ATTACHMENT, &both_aspects),
        ),
        (
            "VUID-VkDescriptorImageInfo-imageView-01976",
            image_write(set, binding::SAMPLED, T::SAMPLED_IMAGE, &both_aspects),
        ),
    ];
    run_or(
        &s,
        &aspects,
        &["UNASSIGNED-CoreValidation-DrawState-InvalidImageView"],
    );
    // The same writes with a fitting view, layout and binding pass.
    s.device
        .update_descriptor_sets(
            &[
                image_write(set, binding::SAMPLED, T::SAMPLED_IMAGE, &good),
                image_write(set, binding::COMBINED, T::COMBINED_IMAGE_SAMPLER, &good),
                image_write(set, binding::INPUT, T::INPUT_ATTACHMENT, &good),
                image_write(set, binding::SAMPLER, T::SAMPLER, &good),
                image_write(
                    set,
                    binding::STORAGE_IMAGE,
                    T::STORAGE_IMAGE,
                    &info(&o.view, general),
                ),
            ],
            &[],
        )
        .expect("fitting image descriptors");
    // A sampler needs no view, and a sampled image no sampler.
    s.device
        .update_descriptor_sets(
            &[
                image_write(set, binding::SAMPLER, T::SAMPLER, &no_view),
                image_write(set, binding::SAMPLED, T::SAMPLED_IMAGE, &no_sampler),
            ],
            &[],
        )
        .expect("image infos without what their type does not read");
    assert_silent(&s.messages);
}

#[test]
fn buffer_descriptors_fit_their_type() {
    let _serial = vulkan::serial();
    let s = setup_full_features(true);
    let o = objects(&s);
    let limits = s.device.parent().get_properties().limits;
    let info = buffer_info;
    let null = info(None, 0, 16);
    let misaligned = info(Some(&o.buffer), 1, 16);
    let unbound = info(Some(&o.unbound), 0, 16);
    let storage_only = info(Some(&o.storage_only), 0, 16);
    let uniform_only = info(Some(&o.uniform_only), 0, 16);
    let whole = info(Some(&o.buffer), 0, vk::WHOLE_SIZE);
    assert!(
        u64::from(limits.max_uniform_buffer_range) < 128 << 10,
        "the uniform-range case needs a limit below the buffer's size"
    );
    let set = &o.set;
    let uniform = |infos| buffer_write(set, binding::UNIFORM, T::UNIFORM_BUFFER, infos);
    let storage = |infos| buffer_write(set, binding::STORAGE, T::STORAGE_BUFFER, infos);
    let cases = [
        ("VUID-VkDescriptorBufferInfo-buffer-02998", uniform(&null)),
        (
            "VUID-VkWriteDescriptorSet-descriptorType-00327",
            uniform(&misaligned),
        ),
        (
            "VUID-VkWriteDescriptorSet-descriptorType-00328",
            storage(&misaligned),
        ),
        (
            "VUID-VkWriteDescriptorSet-descriptorType-00329",
            uniform(&unbound),
        ),
        (
            "VUID-VkWriteDescriptorSet-descriptorType-00330",
            uniform(&storage_only),
        ),
        (
            "VUID-VkWriteDescriptorSet-descriptorType-00331",
            storage(&uniform_only),
        ),
        (
            "VUID-VkWriteDescriptorSet-descriptorType-00332",
            uniform(&whole),
        ),
        (
            "VUID-VkWriteDescriptorSet-descriptorType-00334",
            tuff::WriteDescriptorSet::new(set)
                .dst_binding(binding::UNIFORM_TEXEL)
                .descriptor_type(T::UNIFORM_TEXEL_BUFFER)
                .texel_buffer_view(&o.uniform_texel_view),
        ),
        (
            "VUID-VkWriteDescriptorSet-descriptorType-00335",
            tuff::WriteDescriptorSet::new(set)
                .dst_binding(binding::STORAGE_TEXEL)
                .descriptor_type(T::STORAGE_TEXEL_BUFFER)
                .texel_buffer_view(&o.storage_texel_view),
        ),
    ];
    run(&s, &cases);
    let fits = info(Some(&o.buffer), 0, 256);
    s.device
        .update_descriptor_sets(&[uniform(&fits), storage(&fits)], &[])
        .expect("fitting buffer descriptors");
    assert_silent(&s.messages);
}

/// An inline uniform block write carries its data in a chained struct whose size is
/// the write's count.
#[test]
fn inline_uniform_block_writes_chain_their_data() {
    let _serial = vulkan::serial();
    let s = setup_full_features(true);
    let o = objects(&s);
    let data = [0u8; 16];
    // The safe struct takes its count from an array setter: 16 (ignored) image infos
    // give the 16 bytes of the block.
    let counted = [tuff::DescriptorImageInfo::new()
        .sampler(Some(&o.sampler))
        .image_view(Some(&o.view)); 16];
    let mut block = tuff::WriteDescriptorSetInlineUniformBlock::new().data(&data[..8]);
    let write = tuff::WriteDescriptorSet::new(&o.set)
        .dst_binding(binding::INLINE)
        .descriptor_type(T::INLINE_UNIFORM_BLOCK)
        .image_info(&counted)
        .push_next(&mut block);
    run(
        &s,
        &[("VUID-VkWriteDescriptorSet-descriptorType-02221", write)],
    );
    let mut block = tuff::WriteDescriptorSetInlineUniformBlock::new().data(&data);
    let write = tuff::WriteDescriptorSet::new(&o.set)
        .dst_binding(binding::INLINE)
        .descriptor_type(T::INLINE_UNIFORM_BLOCK)
        .image_info(&counted)
        .push_next(&mut block);
    s.device
        .update_descriptor_sets(&[write], &[])
        .expect("a whole block");
    assert_silent(&s.messages);
}

/// Objects of another device are refused in every kind of descriptor.
#[test]
fn descriptors_of_another_device_are_refused() {
    let _serial = vulkan::serial();
    let s = setup_full_features(true);
    let other = setup(true);
    let o = objects(&s);
    let d2 = &other.device;
    let (foreign_buffer, _memory) = pipelines::host_buffer(
        &other,
        256,
        vk::BufferUsageFlags::UNIFORM_BUFFER | vk::BufferUsageFlags::UNIFORM_TEXEL_BUFFER,
    );
    let foreign_view = d2
        .create_buffer_view(
            &tuff::BufferViewCreateInfo::new(&foreign_buffer)
                .format(vk::Format::R8G8B8A8_UNORM)
                .range(vk::WHOLE_SIZE),
        )
        .expect("buffer view");
    let foreign_sampler = d2
        .create_sampler(&tuff::SamplerCreateInfo::new())
        .expect("sampler");
    let target = other.color_target(4, vk::ImageUsageFlags::SAMPLED);
    let read = L::SHADER_READ_ONLY_OPTIMAL;
    let foreign_image = [tuff::DescriptorImageInfo::new()
        .sampler(Some(&o.sampler))
        .image_view(Some(&target.view))
        .image_layout(read)];
    let foreign_sampled_by = [tuff::DescriptorImageInfo::new()
        .sampler(Some(&foreign_sampler))
        .image_view(Some(&o.view))
        .image_layout(read)];
    let buffers = [tuff::DescriptorBufferInfo::new()
        .buffer(Some(&foreign_buffer))
        .range(16)];
    let set = &o.set;
    let cases = [
        (
            "VUID-vkUpdateDescriptorSets-pDescriptorWrites-06236",
            tuff::WriteDescriptorSet::new(set)
                .dst_binding(binding::UNIFORM_TEXEL)
                .descriptor_type(T::UNIFORM_TEXEL_BUFFER)
                .texel_buffer_view(&foreign_view),
        ),
        (
            "VUID-vkUpdateDescriptorSets-pDescriptorWrites-06238",
            image_write(
                set,
                binding::COMBINED,
                T::COMBINED_IMAGE_SAMPLER,
                &foreign_sampled_by,
            ),
        ),
        (
            "VUID-vkUpdateDescriptorSets-pDescriptorWrites-06239",
            image_write(set, binding::SAMPLED, T::SAMPLED_IMAGE, &foreign_image),
        ),
    ];
    // The 1.3.239 layer names the structs' commonparent rules for these handles,
    // which it checks before the command's own.
    run_or(
        &s,
        &cases,
        &[
            "VUID-VkWriteDescriptorSet-commonparent",
            "VUID-VkDescriptorImageInfo-commonparent",
            // A sampler of another device is not a valid sampler of this one.
            "VUID-VkWriteDescriptorSet-descriptorType-00325",
        ],
    );
    // A buffer of another device: the 1.3.239 layer crashes looking the buffer up
    // among its device's, so the unchecked call is never made and the rule is
    // proven by tuff's error alone.
    let foreign = buffer_write(set, binding::UNIFORM, T::UNIFORM_BUFFER, &buffers);
    assert_eq!(
        vuid(s.device.update_descriptor_sets(&[foreign], &[])),
        "VUID-vkUpdateDescriptorSets-pDescriptorWrites-06237"
    );
    assert_silent(&s.messages);
    assert_silent(&other.messages);
}

/// A set of one storage-buffer binding from `pool`, of `layout`.
fn one_set(
    s: &Setup,
    pool: &tuff::DescriptorPool,
    layout: &tuff::DescriptorSetLayout,
) -> tuff::DescriptorSet {
    s.device
        .allocate_descriptor_sets(
            pool,
            &tuff::DescriptorSetAllocateInfo::new(pool).set_layouts(layout),
        )
        .expect("set")
        .pop()
        .expect("one set")
}

/// A pool of `sets` sets of one storage buffer each, with `flags`.
fn storage_pool(
    s: &Setup,
    sets: u32,
    flags: vk::DescriptorPoolCreateFlags,
) -> tuff::DescriptorPool {
    let sizes = [vk::DescriptorPoolSize {
        ty: T::STORAGE_BUFFER,
        descriptor_count: sets,
    }];
    s.device
        .create_descriptor_pool(
            &tuff::DescriptorPoolCreateInfo::new()
                .flags(flags)
                .max_sets(sets)
                .pool_sizes(&sizes),
        )
        .expect("pool")
}

/// A layout of one storage-buffer binding.
fn storage_layout(s: &Setup) -> tuff::DescriptorSetLayout {
    let bindings = [tuff::DescriptorSetLayoutBinding::new()
        .binding(0)
        .descriptor_type(T::STORAGE_BUFFER)
        .descriptor_count(1)
        .stage_flags(vk::ShaderStageFlags::COMPUTE)];
    s.device
        .create_descriptor_set_layout(
            &tuff::DescriptorSetLayoutCreateInfo::new().bindings(&bindings),
        )
        .expect("set layout")
}

/// A copy keeps its sets' pools' update-after-bind creation alike, does not copy
/// into immutable samplers, and does not overlap itself inside one set. (The layouts'
/// update-after-bind creation, 01918 and 04886, needs a binding updatable after
/// bind, which lavapipe 22.3 offers for no descriptor type.)
#[test]
fn copies_keep_their_sets_alike() {
    let _serial = vulkan::serial();
    let s = setup_full_features(true);
    let d = &s.device;
    let o = objects(&s);
    let fits = buffer_info(Some(&o.buffer), 0, 256);
    let sampler_info = image_info(&o.sampler, &o.view, L::SHADER_READ_ONLY_OPTIMAL);
    d.update_descriptor_sets(
        &[
            buffer_write(&o.set, binding::UNIFORM, T::UNIFORM_BUFFER, &fits),
            image_write(&o.set, binding::SAMPLER, T::SAMPLER, &sampler_info),
        ],
        &[],
    )
    .expect("sources");
    let plain = storage_layout(&s);
    let plain_pool = storage_pool(&s, 2, vk::DescriptorPoolCreateFlags::empty());
    let bind_pool = storage_pool(&s, 2, vk::DescriptorPoolCreateFlags::UPDATE_AFTER_BIND);
    let a = one_set(&s, &plain_pool, &plain);
    let in_bind_pool = one_set(&s, &bind_pool, &plain);
    let fill = |set| buffer_write(set, 0, T::STORAGE_BUFFER, &fits);
    d.update_descriptor_sets(&[fill(&a), fill(&in_bind_pool)], &[])
        .expect("sources");
    let copy = |src, src_binding, dst, dst_binding| {
        tuff::CopyDescriptorSet::new(src, dst)
            .src_binding(src_binding)
            .dst_binding(dst_binding)
            .descriptor_count(1)
    };
    let cases = [
        (
            "VUID-VkCopyDescriptorSet-dstBinding-02753",
            copy(&o.set, binding::SAMPLER, &o.set, binding::IMMUTABLE_SAMPLER),
        ),
        (
            "VUID-VkCopyDescriptorSet-srcSet-01920",
            copy(&in_bind_pool, 0, &a, 0),
        ),
        (
            "VUID-VkCopyDescriptorSet-srcSet-04888",
            copy(&a, 0, &in_bind_pool, 0),
        ),
    ];
    for (rule, c) in &cases {
        assert_eq!(
            vuid(d.update_descriptor_sets(&[], &[*c])),
            *rule,
            "the safe copy of the case for {rule}"
        );
    }
    assert_silent(&s.messages);
    for (rule, c) in &cases {
        s.messages.abort_on_error(true);
        // SAFETY: the layer skips the call, which breaks only the rule under test.
        unsafe { d.update_descriptor_sets_unchecked(&[], &[*c]) };
        s.messages.abort_on_error(false);
        let said = s.messages.take();
        assert!(
            said.iter().any(|m| m.contains(rule)),
            "the layer did not name {rule}; it said {said:?}"
        );
    }
    // A copy of a descriptor onto itself: the 1.3.239 layer does not check the
    // overlap (the driver would copy a range onto itself), so the unchecked call is
    // not made and the rule is proven by tuff's error alone.
    let onto_itself = copy(&o.set, binding::UNIFORM, &o.set, binding::UNIFORM);
    assert_eq!(
        vuid(d.update_descriptor_sets(&[], &[onto_itself])),
        "VUID-VkCopyDescriptorSet-srcSet-00349"
    );
    // Copies inside one set that do not overlap, and between sets made alike, pass.
    let next = onto_itself.dst_array_element(1);
    let b = one_set(&s, &plain_pool, &plain);
    let plain_copy = copy(&a, 0, &b, 0);
    d.update_descriptor_sets(&[], &[next, plain_copy])
        .expect("copies");
    assert_silent(&s.messages);
}

/// A set bound by a command buffer's dispatch: an update leaves the buffer invalid
/// (its submission is refused until it is recorded again), and while a submission of
/// it may still be executing the set is not rewritten.
#[test]
fn sets_in_use_are_not_rewritten() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let d = &s.device;
    let size = 8;
    let target = s.color_target(size, vk::ImageUsageFlags::empty());
    let p = pipelines::pipelines(&s, &target);
    let infos = buffer_info(Some(&p.output.0), 0, vk::WHOLE_SIZE);
    let write = buffer_write(&p.set, 1, T::STORAGE_BUFFER, &infos);
    let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let record = |cb: &mut tuff::CommandBuffer| {
        let rec = cb
            .begin(&tuff::CommandBufferBeginInfo::new())
            .expect("begin");
        p.record(rec, &target, size, None).end().expect("end");
    };
    let fence = d
        .create_fence(&tuff::FenceCreateInfo::new())
        .expect("fence");

    // Updated after it was recorded: the buffer is invalid.
    record(&mut cb);
    d.update_descriptor_sets(&[write], &[])
        .expect("an update of a recorded set");
    let invalid = "VUID-vkQueueSubmit-pCommandBuffers-00070";
    {
        let submit = [tuff::SubmitInfo::new().command_buffers(&cb)];
        assert_eq!(vuid(s.queue.submit(&submit, Some(&fence))), invalid);
        assert_silent(&s.messages);
        s.messages.abort_on_error(true);
        // SAFETY: the layer names the rule and skips the call.
        let _ = unsafe { s.queue.submit_unchecked(&submit, Some(&fence)) };
        s.messages.abort_on_error(false);
        // The 1.3.239 layer names the invalid state by its cause.
        let cause = "UNASSIGNED-CoreValidation-DrawState-InvalidCommandBuffer-VkDescriptorSet";
        let said = s.messages.take();
        assert!(
            said.iter()
                .any(|m| m.contains(invalid) || m.contains(cause)),
            "the layer did not name {invalid}; it said {said:?}"
        );
    }

    // Recorded again, and submitted behind a timeline value the host signals later,
    // so the submission is still pending when the set is written.
    record(&mut cb);
    let mut timeline_type = tuff::SemaphoreTypeCreateInfo::new()
        .semaphore_type(vk::SemaphoreType::TIMELINE)
        .initial_value(0);
    let gate = d
        .create_semaphore(&tuff::SemaphoreCreateInfo::new().push_next(&mut timeline_type))
        .expect("timeline");
    let stages = [vk::PipelineStageFlags::ALL_COMMANDS];
    let mut values = tuff::TimelineSemaphoreSubmitInfo::new().wait_semaphore_values(&[1]);
    let gated = [tuff::SubmitInfo::new()
        .command_buffers(&cb)
        .wait_semaphores(&gate, &stages)
        .expect("one stage per wait")
        .push_next(&mut values)];
    s.queue.submit(&gated, Some(&fence)).expect("gated submit");
    let in_use = "VUID-vkUpdateDescriptorSets-None-03047";
    assert_eq!(vuid(d.update_descriptor_sets(&[write], &[])), in_use);
    assert_silent(&s.messages);
    s.messages.abort_on_error(true);
    // SAFETY: the layer names the rule and skips the call.
    unsafe { d.update_descriptor_sets_unchecked(&[write], &[]) };
    s.messages.abort_on_error(false);
    let said = s.messages.take();
    assert!(
        said.iter().any(|m| m.contains(in_use)),
        "the layer did not name {in_use}; it said {said:?}"
    );
    d.signal_semaphore(&tuff::SemaphoreSignalInfo::new(&gate).value(1))
        .expect("open the gate");
    assert_eq!(
        d.wait_for_fences(&fence, true, u64::MAX)
            .expect("the gated batch"),
        tuff::SuccessOrTimeout::Success
    );
    // Complete now: the set may be written, which leaves the buffer invalid again.
    d.update_descriptor_sets(&[write], &[])
        .expect("an update after the wait");
    d.reset_fences(&fence).expect("reset");
    let submit = [tuff::SubmitInfo::new().command_buffers(&cb)];
    assert_eq!(vuid(s.queue.submit(&submit, Some(&fence))), invalid);
    assert_silent(&s.messages);
}

/// A compute pipeline that reads a storage image (binding 0) into a buffer (binding
/// 1), and a set for it naming `view` in `layout`.
struct ImageReader {
    _module: tuff::ShaderModule,
    _set_layout: tuff::DescriptorSetLayout,
    layout: tuff::PipelineLayout,
    pipeline: tuff::Pipeline,
    _pool: tuff::DescriptorPool,
    set: tuff::DescriptorSet,
}

fn image_reader(s: &Setup, view: &tuff::ImageView, output: &tuff::Buffer) -> ImageReader {
    image_reader_with(s, view, Some(output), None, IMAGE_COMP)
}

/// The compute shader that reads a storage image at binding 0 into the buffer at 1.
const IMAGE_COMP: &[u8] = include_bytes!("../shaders/spv/image.comp.spv");

/// [`image_reader`] of the compute shader `code` (which reads binding 0 and writes
/// binding 1, left unwritten without `output`), whose set also holds `sampled` at
/// binding 2 as a sampled image in `SHADER_READ_ONLY_OPTIMAL` (the shader does not
/// read it).
fn image_reader_with(
    s: &Setup,
    view: &tuff::ImageView,
    output: Option<&tuff::Buffer>,
    sampled: Option<&tuff::ImageView>,
    code: &[u8],
) -> ImageReader {
    let d = &s.device;
    let module = tuff_setup::shader(s, code);
    let b = |n: u32, ty: T| {
        tuff::DescriptorSetLayoutBinding::new()
            .binding(n)
            .descriptor_type(ty)
            .descriptor_count(1)
            .stage_flags(vk::ShaderStageFlags::COMPUTE)
    };
    let bindings = [
        b(0, T::STORAGE_IMAGE),
        b(1, T::STORAGE_BUFFER),
        b(2, T::SAMPLED_IMAGE),
    ];
    let set_layout = d
        .create_descriptor_set_layout(
            &tuff::DescriptorSetLayoutCreateInfo::new().bindings(&bindings),
        )
        .expect("set layout");
    let set_layouts = tuff::HandleSlice::new(&[&set_layout]);
    let layout = d
        .create_pipeline_layout(&tuff::PipelineLayoutCreateInfo::new().set_layouts(&set_layouts))
        .expect("pipeline layout");
    let stage = tuff::PipelineShaderStageCreateInfo::new(c"main")
        .stage(vk::ShaderStageFlags::COMPUTE)
        .module(Some(&module));
    let (mut pipelines, _) = d
        .create_compute_pipelines(
            None,
            &[tuff::ComputePipelineCreateInfo::new(stage, &layout)],
        )
        .expect("compute pipeline");
    let sizes = [
        vk::DescriptorPoolSize {
            ty: T::STORAGE_IMAGE,
            descriptor_count: 1,
        },
        vk::DescriptorPoolSize {
            ty: T::STORAGE_BUFFER,
            descriptor_count: 1,
        },
        vk::DescriptorPoolSize {
            ty: T::SAMPLED_IMAGE,
            descriptor_count: 1,
        },
    ];
    let pool = d
        .create_descriptor_pool(
            &tuff::DescriptorPoolCreateInfo::new()
                .max_sets(1)
                .pool_sizes(&sizes),
        )
        .expect("pool");
    let set = one_set(s, &pool, &set_layout);
    let sampler = d
        .create_sampler(&tuff::SamplerCreateInfo::new())
        .expect("sampler");
    let images = image_info(&sampler, view, L::GENERAL);
    d.update_descriptor_sets(&[image_write(&set, 0, T::STORAGE_IMAGE, &images)], &[])
        .expect("the reader's image");
    if let Some(output) = output {
        let buffers = buffer_info(Some(output), 0, vk::WHOLE_SIZE);
        d.update_descriptor_sets(&[buffer_write(&set, 1, T::STORAGE_BUFFER, &buffers)], &[])
            .expect("the reader's buffer");
    }
    if let Some(sampled) = sampled {
        let images = image_info(&sampler, sampled, L::SHADER_READ_ONLY_OPTIMAL);
        d.update_descriptor_sets(&[image_write(&set, 2, T::SAMPLED_IMAGE, &images)], &[])
            .expect("the sampled image");
    }
    ImageReader {
        _module: module,
        _set_layout: set_layout,
        layout,
        pipeline: pipelines.pop().expect("one pipeline"),
        _pool: pool,
        set,
    }
}

/// Waits for an unchecked submission the driver took (the layer reports some rules
/// only after the call) and resets its fence.
fn settle(s: &Setup, submitted: tuff::Result<()>, fence: &tuff::Fence) {
    if submitted.is_ok() {
        let waited = s
            .device
            .wait_for_fences(fence, true, u64::MAX)
            .expect("wait");
        assert_eq!(waited, tuff::SuccessOrTimeout::Success);
        s.device.reset_fences(fence).expect("reset");
    }
}

/// Records a barrier that moves `image` from `old` to `new`.
fn transition(rec: &mut tuff::Recorder<'_, tuff::Outside>, image: &tuff::Image, old: L, new: L) {
    let barrier = tuff::ImageMemoryBarrier::new(image)
        .old_layout(old)
        .new_layout(new)
        .src_queue_family_index(vk::QUEUE_FAMILY_IGNORED)
        .dst_queue_family_index(vk::QUEUE_FAMILY_IGNORED)
        .dst_access_mask(vk::AccessFlags::SHADER_READ)
        .subresource_range(vk::ImageSubresourceRange {
            aspect_mask: vk::ImageAspectFlags::COLOR,
            base_mip_level: 0,
            level_count: 1,
            base_array_layer: 0,
            layer_count: 1,
        });
    rec.pipeline_barrier(
        vk::PipelineStageFlags::TOP_OF_PIPE,
        vk::PipelineStageFlags::COMPUTE_SHADER,
        vk::DependencyFlags::empty(),
        &[],
        &[],
        &[barrier],
    )
    .expect("barrier");
}

/// A dispatch reads its sets' image descriptors in the layouts they state: one
/// that the recording's earlier commands leave in another layout is refused when
/// it is recorded, and one that an earlier command buffer of the submission leaves
/// so, when it is submitted. The layer names the rule at the submission for both.
#[test]
fn image_descriptors_are_read_in_their_layouts() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let d = &s.device;
    let (image, _image_memory, view) = pipelines::storage_image(&s, U::empty());
    let (output, _output_memory) =
        pipelines::host_buffer(&s, 16, vk::BufferUsageFlags::STORAGE_BUFFER);
    let reader = image_reader(&s, &view, &output);
    let rule = "VUID-VkDescriptorImageInfo-imageLayout-00344";
    let fence = d
        .create_fence(&tuff::FenceCreateInfo::new())
        .expect("fence");
    let bind = |rec: &mut tuff::Recorder<'_, tuff::Outside>| {
        rec.bind_pipeline(vk::PipelineBindPoint::COMPUTE, &reader.pipeline)
            .expect("pipeline");
        rec.bind_descriptor_sets(
            vk::PipelineBindPoint::COMPUTE,
            &reader.layout,
            0,
            &reader.set,
            &[],
        )
        .expect("set");
    };

    // In one recording: the image is a transfer destination when the dispatch reads
    // it as GENERAL.
    let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let mut rec = cb
        .begin(&tuff::CommandBufferBeginInfo::new())
        .expect("begin");
    transition(&mut rec, &image, L::UNDEFINED, L::TRANSFER_DST_OPTIMAL);
    bind(&mut rec);
    assert_eq!(vuid(rec.dispatch(1, 1, 1)), rule);
    drop(rec);
    let mut rec = cb
        .begin(&tuff::CommandBufferBeginInfo::new())
        .expect("begin");
    transition(&mut rec, &image, L::UNDEFINED, L::TRANSFER_DST_OPTIMAL);
    bind(&mut rec);
    // SAFETY: recorded for the layer, which names the rule at the submission, which
    // it checks after the driver took it (lavapipe reads the image whatever its
    // layout).
    let _ = unsafe { rec.dispatch_unchecked(1, 1, 1) };
    rec.end().expect("end");
    {
        let submit = [tuff::SubmitInfo::new().command_buffers(&cb)];
        s.messages.abort_on_error(true);
        // SAFETY: as above.
        let r = unsafe { s.queue.submit_unchecked(&submit, Some(&fence)) };
        s.messages.abort_on_error(false);
        let said = s.messages.take();
        assert!(
            said.iter().any(|m| m.contains(rule)),
            "the layer did not name {rule}; it said {said:?}"
        );
        settle(&s, r, &fence);
    }

    // Across command buffers: the first leaves the image a transfer destination, the
    // second reads it as GENERAL; each recording alone is fine.
    let (_pools, mut first) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let mut rec = first
        .begin(&tuff::CommandBufferBeginInfo::new())
        .expect("begin");
    transition(&mut rec, &image, L::UNDEFINED, L::TRANSFER_DST_OPTIMAL);
    rec.end().expect("end");
    let mut rec = cb
        .begin(&tuff::CommandBufferBeginInfo::new())
        .expect("begin");
    bind(&mut rec);
    rec.dispatch(1, 1, 1)
        .expect("a dispatch of an image the recording leaves alone");
    rec.end().expect("end");
    let both = tuff::HandleSlice::new(&[&first, &cb]);
    let submit = [tuff::SubmitInfo::new().command_buffers(&both)];
    assert_eq!(vuid(s.queue.submit(&submit, Some(&fence))), rule);
    assert_silent(&s.messages);
    s.messages.abort_on_error(true);
    // SAFETY: the layer names the rule (lavapipe reads the image whatever its layout).
    let r = unsafe { s.queue.submit_unchecked(&submit, Some(&fence)) };
    s.messages.abort_on_error(false);
    // Across command buffers the 1.3.239 layer states the same mismatch without the
    // rule's VUID.
    let unassigned = "UNASSIGNED-CoreValidation-DrawState-InvalidImageLayout";
    let said = s.messages.take();
    assert!(
        said.iter().any(|m| m.contains(rule)
            || (m.contains(unassigned) && m.contains("VK_IMAGE_LAYOUT_GENERAL"))),
        "the layer did not name {rule}; it said {said:?}"
    );
    settle(&s, r, &fence);

    // The image moved to GENERAL first: the dispatch runs with no message.
    let mut rec = first
        .begin(&tuff::CommandBufferBeginInfo::new())
        .expect("begin");
    transition(&mut rec, &image, L::UNDEFINED, L::GENERAL);
    rec.end().expect("end");
    let both = tuff::HandleSlice::new(&[&first, &cb]);
    let submit = [tuff::SubmitInfo::new().command_buffers(&both)];
    s.queue
        .submit(&submit, Some(&fence))
        .expect("a dispatch of a GENERAL image");
    assert_eq!(
        d.wait_for_fences(&fence, true, u64::MAX).expect("wait"),
        tuff::SuccessOrTimeout::Success
    );
    assert_silent(&s.messages);
}

/// A dispatch after a barrier that changes its image descriptor's layout is checked
/// again, though the same state passed its checks before the barrier; and two
/// descriptors that state different layouts for one subresource are refused at the
/// first dispatch, as no layout can meet both.
#[test]
fn dispatches_see_the_layouts_of_their_moment() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let (image, _image_memory, view) = pipelines::storage_image(&s, U::SAMPLED);
    let (output, _output_memory) =
        pipelines::host_buffer(&s, 16, vk::BufferUsageFlags::STORAGE_BUFFER);
    let rule = "VUID-VkDescriptorImageInfo-imageLayout-00344";
    let reader = image_reader(&s, &view, &output);
    let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let mut rec = cb
        .begin(&tuff::CommandBufferBeginInfo::new())
        .expect("begin");
    transition(&mut rec, &image, L::UNDEFINED, L::GENERAL);
    rec.bind_pipeline(vk::PipelineBindPoint::COMPUTE, &reader.pipeline)
        .expect("pipeline");
    rec.bind_descriptor_sets(
        vk::PipelineBindPoint::COMPUTE,
        &reader.layout,
        0,
        &reader.set,
        &[],
    )
    .expect("set");
    rec.dispatch(1, 1, 1)
        .expect("a dispatch of a GENERAL image");
    let after_read = tuff::ImageMemoryBarrier::new(&image)
        .old_layout(L::GENERAL)
        .new_layout(L::TRANSFER_DST_OPTIMAL)
        .src_queue_family_index(vk::QUEUE_FAMILY_IGNORED)
        .dst_queue_family_index(vk::QUEUE_FAMILY_IGNORED)
        .src_access_mask(vk::AccessFlags::SHADER_READ)
        .dst_access_mask(vk::AccessFlags::SHADER_READ)
        .subresource_range(vk::ImageSubresourceRange {
            aspect_mask: vk::ImageAspectFlags::COLOR,
            base_mip_level: 0,
            level_count: 1,
            base_array_layer: 0,
            layer_count: 1,
        });
    rec.pipeline_barrier(
        vk::PipelineStageFlags::COMPUTE_SHADER,
        vk::PipelineStageFlags::COMPUTE_SHADER,
        vk::DependencyFlags::empty(),
        &[],
        &[],
        &[after_read],
    )
    .expect("barrier");
    assert_eq!(vuid(rec.dispatch(1, 1, 1)), rule);
    drop(rec);

    let both = image_reader_with(&s, &view, Some(&output), Some(&view), IMAGE_COMP);
    let mut rec = cb
        .begin(&tuff::CommandBufferBeginInfo::new())
        .expect("begin");
    rec.bind_pipeline(vk::PipelineBindPoint::COMPUTE, &both.pipeline)
        .expect("pipeline");
    rec.bind_descriptor_sets(
        vk::PipelineBindPoint::COMPUTE,
        &both.layout,
        0,
        &both.set,
        &[],
    )
    .expect("set");
    assert_eq!(vuid(rec.dispatch(1, 1, 1)), rule);
    drop(rec);
    assert_silent(&s.messages);
}

/// A write that runs on from one binding into the next puts its descriptors where
/// they land: a copy from the binding it reached carries them (and what keeps their
/// objects alive) into the destination set, whose dispatch then reads the copied
/// image in the layout the descriptor states.
#[test]
fn a_copy_carries_what_a_run_on_write_put_in_its_source() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let d = &s.device;
    let (_first_image, _first_memory, first_view) = pipelines::storage_image(&s, U::empty());
    let (second_image, _second_memory, second_view) = pipelines::storage_image(&s, U::empty());
    let (output, _output_memory) =
        pipelines::host_buffer(&s, 16, vk::BufferUsageFlags::STORAGE_BUFFER);
    let reader = image_reader(&s, &first_view, &output);
    // Two consecutive storage-image bindings; a write of two descriptors at binding
    // 0 puts the second view at binding 1.
    let b = |n: u32| {
        tuff::DescriptorSetLayoutBinding::new()
            .binding(n)
            .descriptor_type(T::STORAGE_IMAGE)
            .descriptor_count(1)
            .stage_flags(vk::ShaderStageFlags::COMPUTE)
    };
    let bindings = [b(0), b(1)];
    let layout = d
        .create_descriptor_set_layout(
            &tuff::DescriptorSetLayoutCreateInfo::new().bindings(&bindings),
        )
        .expect("set layout");
    let sizes = [vk::DescriptorPoolSize {
        ty: T::STORAGE_IMAGE,
        descriptor_count: 2,
    }];
    let pool = d
        .create_descriptor_pool(
            &tuff::DescriptorPoolCreateInfo::new()
                .max_sets(1)
                .pool_sizes(&sizes),
        )
        .expect("pool");
    let source = one_set(&s, &pool, &layout);
    let sampler = d
        .create_sampler(&tuff::SamplerCreateInfo::new())
        .expect("sampler");
    let infos = [
        tuff::DescriptorImageInfo::new()
            .sampler(Some(&sampler))
            .image_view(Some(&first_view))
            .image_layout(L::GENERAL),
        tuff::DescriptorImageInfo::new()
            .sampler(Some(&sampler))
            .image_view(Some(&second_view))
            .image_layout(L::GENERAL),
    ];
    d.update_descriptor_sets(&[image_write(&source, 0, T::STORAGE_IMAGE, &infos)], &[])
        .expect("a write running on into binding 1");
    let copy = tuff::CopyDescriptorSet::new(&source, &reader.set)
        .src_binding(1)
        .dst_binding(0)
        .descriptor_count(1);
    d.update_descriptor_sets(&[], &[copy]).expect("copy");
    // The reader's set now names the second image, which the recording leaves a
    // transfer destination: the dispatch is refused for it.
    let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let mut rec = cb
        .begin(&tuff::CommandBufferBeginInfo::new())
        .expect("begin");
    transition(
        &mut rec,
        &second_image,
        L::UNDEFINED,
        L::TRANSFER_DST_OPTIMAL,
    );
    rec.bind_pipeline(vk::PipelineBindPoint::COMPUTE, &reader.pipeline)
        .expect("pipeline");
    rec.bind_descriptor_sets(
        vk::PipelineBindPoint::COMPUTE,
        &reader.layout,
        0,
        &reader.set,
        &[],
    )
    .expect("set");
    assert_eq!(
        vuid(rec.dispatch(1, 1, 1)),
        "VUID-VkDescriptorImageInfo-imageLayout-00344"
    );
    drop(rec);
    assert_silent(&s.messages);
}

/// Each dispatch command reads its sets' image views with its shader's image types:
/// a 2D view where the shader reads a 2D array image breaks the view type rule, a
/// UNORM view where it reads unsigned integer texels the numeric format rule; a set
/// whose output buffer was never written breaks the rule that the descriptors a
/// shader reads are valid; atomics on a view whose format has none (RGBA8_UINT) the
/// atomic rule. tuff refuses the safe call, and the layer names the same
/// rule for the unchecked one.
#[test]
fn dispatches_read_views_their_shaders_can_read() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let (_image, _image_memory, view) = pipelines::storage_image(&s, U::empty());
    let (output, _output_memory) =
        pipelines::host_buffer(&s, 16, vk::BufferUsageFlags::STORAGE_BUFFER);
    let (args, _args_memory) =
        pipelines::host_buffer(&s, 16, vk::BufferUsageFlags::INDIRECT_BUFFER);
    // An unsigned integer view whose format has no atomics, for the atomic shader.
    let (_uint_image, _uint_memory, uint_view) =
        pipelines::storage_image_of(&s, vk::Format::R8G8B8A8_UINT, U::empty());
    let cases: [(&[u8], &tuff::ImageView, Option<&tuff::Buffer>, &str); 5] = [
        (
            include_bytes!("../shaders/spv/image_array.comp.spv"),
            &view,
            Some(&output),
            "viewType-07752",
        ),
        (
            include_bytes!("../shaders/spv/image_uint.comp.spv"),
            &view,
            Some(&output),
            "format-07753",
        ),
        (IMAGE_COMP, &view, None, "None-02699"),
        (
            include_bytes!("../shaders/spv/atomic.comp.spv"),
            &uint_view,
            Some(&output),
            "None-02691",
        ),
        // lavapipe reads no storage format without a format.
        (
            include_bytes!("../shaders/spv/image_unknown.comp.spv"),
            &view,
            Some(&output),
            "OpTypeImage-07028",
        ),
    ];
    let commands = dispatch_commands();
    let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    for (code, view, output, suffix) in cases {
        let reader = image_reader_with(&s, view, output, None, code);
        for (command, dispatch) in commands {
            let rule = format!("VUID-{command}-{suffix}");
            tuff_setup::breaks(&s, &rule, tuff_setup::Layer::Names, |unchecked| {
                let mut rec = cb
                    .begin(&tuff::CommandBufferBeginInfo::new())
                    .expect("begin");
                rec.bind_pipeline(vk::PipelineBindPoint::COMPUTE, &reader.pipeline)
                    .expect("pipeline");
                rec.bind_descriptor_sets(
                    vk::PipelineBindPoint::COMPUTE,
                    &reader.layout,
                    0,
                    &reader.set,
                    &[],
                )
                .expect("set");
                let r = dispatch(&mut rec, &args, unchecked);
                drop(rec);
                r
            });
        }
    }
    assert_silent(&s.messages);
}

/// A copy of a descriptor that was never written leaves its destination unwritten:
/// a dispatch that reads it is refused, though the slot was written before.
#[test]
fn a_copy_of_an_unwritten_descriptor_empties_its_slot() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let (_image, _image_memory, view) = pipelines::storage_image(&s, U::empty());
    let (output, _output_memory) =
        pipelines::host_buffer(&s, 16, vk::BufferUsageFlags::STORAGE_BUFFER);
    let reader = image_reader(&s, &view, &output);
    let unwritten = image_reader_with(&s, &view, None, None, IMAGE_COMP);
    let copy = tuff::CopyDescriptorSet::new(&unwritten.set, &reader.set)
        .src_binding(1)
        .dst_binding(1)
        .descriptor_count(1);
    s.device.update_descriptor_sets(&[], &[copy]).expect("copy");
    let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let mut rec = cb
        .begin(&tuff::CommandBufferBeginInfo::new())
        .expect("begin");
    rec.bind_pipeline(vk::PipelineBindPoint::COMPUTE, &reader.pipeline)
        .expect("pipeline");
    rec.bind_descriptor_sets(
        vk::PipelineBindPoint::COMPUTE,
        &reader.layout,
        0,
        &reader.set,
        &[],
    )
    .expect("set");
    assert_eq!(vuid(rec.dispatch(1, 1, 1)), "VUID-vkCmdDispatch-None-02699");
    drop(rec);
    assert_silent(&s.messages);
}

/// Each dispatch command reads the push constants its shader declares: before any
/// push, or with part of the block pushed, tuff refuses the safe call (the test
/// device does not enable maintenance4; the 1.3.239 layer does not check the rule).
#[test]
fn dispatches_read_pushed_constants() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let d = &s.device;
    let (output, _output_memory) =
        pipelines::host_buffer(&s, 16, vk::BufferUsageFlags::STORAGE_BUFFER);
    let (args, _args_memory) =
        pipelines::host_buffer(&s, 16, vk::BufferUsageFlags::INDIRECT_BUFFER);
    let module = tuff_setup::shader(&s, include_bytes!("../shaders/spv/push.comp.spv"));
    let set_layout = storage_layout(&s);
    let set_layouts = tuff::HandleSlice::new(&[&set_layout]);
    let push = [vk::PushConstantRange {
        stage_flags: vk::ShaderStageFlags::COMPUTE,
        offset: 0,
        size: 16,
    }];
    let layout = d
        .create_pipeline_layout(
            &tuff::PipelineLayoutCreateInfo::new()
                .set_layouts(&set_layouts)
                .push_constant_ranges(&push),
        )
        .expect("pipeline layout");
    let stage = tuff::PipelineShaderStageCreateInfo::new(c"main")
        .stage(vk::ShaderStageFlags::COMPUTE)
        .module(Some(&module));
    let (mut pipelines, _) = d
        .create_compute_pipelines(
            None,
            &[tuff::ComputePipelineCreateInfo::new(stage, &layout)],
        )
        .expect("compute pipeline");
    let pipeline = pipelines.pop().expect("one pipeline");
    let pool = storage_pool(&s, 1, vk::DescriptorPoolCreateFlags::empty());
    let set = one_set(&s, &pool, &set_layout);
    let buffers = buffer_info(Some(&output), 0, vk::WHOLE_SIZE);
    d.update_descriptor_sets(&[buffer_write(&set, 0, T::STORAGE_BUFFER, &buffers)], &[])
        .expect("the output");
    let commands = dispatch_commands();
    let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    for (command, dispatch) in commands {
        let rule = format!("VUID-{command}-maintenance4-06425");
        for unchecked in [false, true] {
            let mut rec = cb
                .begin(&tuff::CommandBufferBeginInfo::new())
                .expect("begin");
            rec.bind_pipeline(vk::PipelineBindPoint::COMPUTE, &pipeline)
                .expect("pipeline");
            rec.bind_descriptor_sets(vk::PipelineBindPoint::COMPUTE, &layout, 0, &set, &[])
                .expect("set");
            if unchecked {
                s.messages.abort_on_error(true);
                let _ = dispatch(&mut rec, &args, true);
                s.messages.abort_on_error(false);
                // The 1.3.239 layer does not check the rule: tuff's error alone proves
                // it (the values read are undefined, no memory is touched).
                let said = s.messages.take();
                assert!(said.is_empty(), "the layer now checks {rule}: {said:?}");
            } else {
                assert_eq!(vuid(dispatch(&mut rec, &args, false)), rule);
                assert_silent(&s.messages);
                // Half the block pushed is not enough; all of it is.
                rec.push_constants(&layout, vk::ShaderStageFlags::COMPUTE, 0, &[0u8; 8])
                    .expect("push");
                assert_eq!(vuid(dispatch(&mut rec, &args, false)), rule);
                rec.push_constants(&layout, vk::ShaderStageFlags::COMPUTE, 8, &[0u8; 8])
                    .expect("push");
                dispatch(&mut rec, &args, false).expect("a dispatch with its push constants");
            }
            drop(rec);
        }
    }
    assert_silent(&s.messages);
}

/// After vkCmdExecuteCommands the primary's bindings are undefined: a dispatch
/// that relies on the pipeline and set bound before the secondaries ran is refused.
#[test]
fn secondaries_leave_nothing_bound() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let (_image, _image_memory, view) = pipelines::storage_image(&s, U::empty());
    let (output, _output_memory) =
        pipelines::host_buffer(&s, 16, vk::BufferUsageFlags::STORAGE_BUFFER);
    let reader = image_reader(&s, &view, &output);
    let (_secondary_pool, mut secondary) = s.command_buffer(vk::CommandBufferLevel::SECONDARY);
    let inheritance = tuff::CommandBufferInheritanceInfo::new();
    secondary
        .begin(&tuff::CommandBufferBeginInfo::new().inheritance_info(Some(&inheritance)))
        .expect("begin")
        .end()
        .expect("end");
    let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let mut rec = cb
        .begin(&tuff::CommandBufferBeginInfo::new())
        .expect("begin");
    rec.bind_pipeline(vk::PipelineBindPoint::COMPUTE, &reader.pipeline)
        .expect("pipeline");
    rec.bind_descriptor_sets(
        vk::PipelineBindPoint::COMPUTE,
        &reader.layout,
        0,
        &reader.set,
        &[],
    )
    .expect("set");
    rec.execute_commands(&secondary).expect("execute");
    assert_eq!(vuid(rec.dispatch(1, 1, 1)), "VUID-vkCmdDispatch-None-02700");
    drop(rec);
    assert_silent(&s.messages);
}

/// One dispatch command, recorded checked (`false`) or unchecked (`true`); an
/// indirect one reads the buffer.
type Dispatch = fn(&mut tuff::Recorder<'_, tuff::Outside>, &tuff::Buffer, bool) -> tuff::Result<()>;

/// The three dispatch commands, each with its VUID prefix.
fn dispatch_commands() -> [(&'static str, Dispatch); 3] {
    // SAFETY (each call): the shader promise (the repository's shaders); the tests
    // record these dispatches to be refused, or for the layer, which skips them.
    [
        ("vkCmdDispatch", |r, _, unchecked| {
            if unchecked {
                unsafe { r.dispatch_unchecked(1, 1, 1) }
            } else {
                r.dispatch(1, 1, 1)
            }
        }),
        ("vkCmdDispatchBase", |r, _, unchecked| {
            if unchecked {
                unsafe { r.dispatch_base_unchecked(0, 0, 0, 1, 1, 1) }
            } else {
                r.dispatch_base(0, 0, 0, 1, 1, 1)
            }
        }),
        ("vkCmdDispatchIndirect", |r, args, unchecked| {
            if unchecked {
                unsafe { r.dispatch_indirect_unchecked(args, 0) }
            } else {
                unsafe { r.dispatch_indirect(args, 0) }
            }
        }),
    ]
}

/// A descriptor update template's entries name bindings of its set layout (00354)
/// and fit them and the consecutive bindings after them as a write must (00355), at
/// multiples of 4 in an inline uniform block (02226, 02227).
#[test]
fn template_entries_fit_their_set_layout() {
    let _serial = vulkan::serial();
    let s = setup_full_features(true);
    let o = objects(&s);
    let d = &s.device;
    let layouts = tuff::HandleSlice::new(&[&o._sampler_layout]);
    let pipeline_layout = d
        .create_pipeline_layout(&tuff::PipelineLayoutCreateInfo::new().set_layouts(&layouts))
        .expect("pipeline layout");
    let entry = |binding, element, count, ty| vk::DescriptorUpdateTemplateEntry {
        dst_binding: binding,
        dst_array_element: element,
        descriptor_count: count,
        descriptor_type: ty,
        offset: 0,
        stride: 64,
    };
    let cases = [
        (
            entry(30, 0, 1, T::UNIFORM_BUFFER),
            "VUID-VkDescriptorUpdateTemplateEntry-dstBinding-00354",
            false,
        ),
        (
            entry(binding::UNIFORM, 1, 2, T::UNIFORM_BUFFER),
            "VUID-VkDescriptorUpdateTemplateEntry-dstArrayElement-00355",
            false,
        ),
        (
            entry(binding::INLINE, 2, 4, T::INLINE_UNIFORM_BLOCK),
            "VUID-VkDescriptorUpdateTemplateEntry-descriptor-02226",
            true,
        ),
        (
            entry(binding::INLINE, 0, 6, T::INLINE_UNIFORM_BLOCK),
            "VUID-VkDescriptorUpdateTemplateEntry-descriptor-02227",
            true,
        ),
    ];
    fn template<'a>(
        layout: &'a tuff::DescriptorSetLayout,
        pipeline_layout: &'a tuff::PipelineLayout,
        entries: &'a [vk::DescriptorUpdateTemplateEntry],
    ) -> tuff::DescriptorUpdateTemplateCreateInfo<'a> {
        tuff::DescriptorUpdateTemplateCreateInfo::new(layout, pipeline_layout)
            .template_type(vk::DescriptorUpdateTemplateType::DESCRIPTOR_SET)
            .descriptor_update_entries(entries)
    }
    let mut wrong = Vec::new();
    // The 1.3.239 layer checks the inline uniform block rules at the template's
    // creation and not the bindings (it reads them at an update): tuff's error alone
    // proves those, and lavapipe only stores the entries.
    for (e, rule, layer_checks) in &cases {
        let entries = [*e];
        let info = template(&o._sampler_layout, &pipeline_layout, &entries);
        let safe = vuid(d.create_descriptor_update_template(&info));
        s.messages.take();
        s.messages.abort_on_error(true);
        // SAFETY: the template breaks only the rule under test, which the layer
        // reports and so skips.
        drop(unsafe { d.create_descriptor_update_template_unchecked(&info) });
        s.messages.abort_on_error(false);
        let said = s.messages.take();
        let named = if *layer_checks {
            said.iter().any(|m| m.contains(rule))
        } else {
            said.is_empty()
        };
        if safe != *rule || !named {
            wrong.push(format!(
                "tuff said {safe}, expected {rule}; the layer said {said:?}"
            ));
        }
    }
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
    // Both uniform buffers, and the whole inline block in two aligned pieces.
    let entries = [
        entry(binding::UNIFORM, 0, 2, T::UNIFORM_BUFFER),
        entry(binding::INLINE, 0, 8, T::INLINE_UNIFORM_BLOCK),
        entry(binding::INLINE, 8, 8, T::INLINE_UNIFORM_BLOCK),
    ];
    d.create_descriptor_update_template(&template(&o._sampler_layout, &pipeline_layout, &entries))
        .expect("a template whose entries fit");
    assert_silent(&s.messages);
}
