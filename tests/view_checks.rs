//! Buffer views: each is checked against the buffer it views (a texel buffer usage,
//! whose format feature its format has), the device's alignment of its offset, and
//! the number of texels its range holds.
//!
//! Each case breaks one rule through the safe method, which must refuse it with the
//! rule's VUID, and through the `_unchecked` twin under the validation layer (with a
//! messenger that makes the layer skip the call), which must name the same VUID;
//! views that keep the rules are made with the layer silent.
//!
//! SAFETY of the `unsafe` blocks around `_unchecked` calls: each breaks only the rule
//! under test, which the layer reports and so skips; the driver never sees it.

#[path = "common/pipelines.rs"]
mod pipelines;
#[path = "common/tuff_setup.rs"]
mod tuff_setup;
#[path = "common/vulkan.rs"]
mod vulkan;

use tuff::vk;
use tuff_setup::{setup, vuid};
use vulkan::assert_silent;

type U = vk::BufferUsageFlags;
type F = vk::FormatFeatureFlags;

#[test]
fn a_buffer_view_fits_its_buffer_format_and_limits() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let d = &s.device;
    let limits = s.physical.get_properties().limits;
    let features = |format| {
        s.physical
            .get_format_properties(format)
            .expect("format properties")
            .buffer_features
    };
    // A format with uniform but not storage texel buffer support, and one with
    // neither (a block-compressed one).
    let uniform_only = [
        vk::Format::R8G8B8_UNORM,
        vk::Format::B8G8R8A8_SRGB,
        vk::Format::R8G8B8A8_SRGB,
        vk::Format::A2R10G10B10_UNORM_PACK32,
    ]
    .into_iter()
    .find(|f| {
        features(*f).contains(F::UNIFORM_TEXEL_BUFFER)
            && !features(*f).contains(F::STORAGE_TEXEL_BUFFER)
    })
    .expect("a format lavapipe reads but does not write in texel buffers");
    let neither = vk::Format::BC1_RGB_UNORM_BLOCK;
    assert!(features(neither).is_empty());
    let (texel, _texel_memory) =
        pipelines::host_buffer(&s, 1024, U::UNIFORM_TEXEL_BUFFER | U::STORAGE_TEXEL_BUFFER);
    let (uniform, _uniform_memory) = pipelines::host_buffer(&s, 1024, U::UNIFORM_BUFFER);
    let (uniform_texel, _uniform_texel_memory) =
        pipelines::host_buffer(&s, 1024, U::UNIFORM_TEXEL_BUFFER);
    // One texel more than maxTexelBufferElements, of one byte each.
    let max = u64::from(limits.max_texel_buffer_elements);
    let (huge, _huge_memory) = pipelines::host_buffer(&s, max + 1, U::UNIFORM_TEXEL_BUFFER);
    let r8 = vk::Format::R8_UNORM;
    let r32 = vk::Format::R32_UINT;
    let view = |buffer, format, offset, range| {
        tuff::BufferViewCreateInfo::new(buffer)
            .format(format)
            .offset(offset)
            .range(range)
    };
    let align = limits.min_texel_buffer_offset_alignment;
    assert!(
        align > 1,
        "lavapipe aligns texel buffer offsets to more than a byte"
    );
    let cases = [
        (
            view(&uniform, r32, 0, 64),
            "VUID-VkBufferViewCreateInfo-buffer-00932",
        ),
        (
            view(&uniform_texel, neither, 0, 64),
            "VUID-VkBufferViewCreateInfo-buffer-00933",
        ),
        (
            view(&texel, uniform_only, 0, 64),
            "VUID-VkBufferViewCreateInfo-buffer-00934",
        ),
        (
            view(&texel, r32, 0, 6),
            "VUID-VkBufferViewCreateInfo-range-00929",
        ),
        (
            view(&huge, r8, 0, max + 1),
            "VUID-VkBufferViewCreateInfo-range-00930",
        ),
        (
            view(&huge, r8, 0, vk::WHOLE_SIZE),
            "VUID-VkBufferViewCreateInfo-range-04059",
        ),
        (
            view(&texel, r32, align / 2, 64),
            "VUID-VkBufferViewCreateInfo-offset-02749",
        ),
    ];
    let mut wrong = Vec::new();
    for (info, rule) in &cases {
        let safe = vuid(d.create_buffer_view(info));
        s.messages.take();
        s.messages.abort_on_error(true);
        // SAFETY: see the module docs.
        drop(unsafe { d.create_buffer_view_unchecked(info) });
        s.messages.abort_on_error(false);
        let said = s.messages.take();
        if safe != *rule || !said.iter().any(|m| m.contains(rule)) {
            wrong.push(format!(
                "tuff said {safe}, expected {rule}; the layer said {said:?}"
            ));
        }
    }
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
    // Views that keep the rules: the whole buffer, a range at the alignment, and the
    // most texels the device allows.
    for info in [
        view(&texel, r32, 0, vk::WHOLE_SIZE),
        view(&texel, r32, align, 64),
        view(&huge, r8, 0, max),
        view(&uniform_texel, uniform_only, 0, 48),
    ] {
        d.create_buffer_view(&info)
            .unwrap_or_else(|e| panic!("{:?}: {e}", info.format));
    }
    assert_silent(&s.messages);
}
