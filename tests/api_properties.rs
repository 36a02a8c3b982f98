//! Bad input at the safe API, generated (proptest): sizes, counts and offsets near
//! `u64::MAX`, zero and huge extents, empty and odd slices, NaN and infinite floats,
//! flag bits no version defines. Every call returns `Ok` or an error; a refusal names
//! its rule; nothing panics; and whatever tuff lets through, the validation layer (on,
//! with synchronization validation) finds nothing wrong with, so no broken rule
//! reached the driver.
//!
//! `PROPTEST_CASES` sets the cases per property (256 by default; the test command
//! runs the default).

#[path = "common/tuff_setup.rs"]
mod tuff_setup;

use proptest::prelude::*;
use proptest::test_runner::{Config, TestRunner};
use tuff::vk;
use tuff_setup::{setup, Setup};

/// How many calls of a property went through and how many were refused: a property
/// whose inputs all fail (or all pass) the checks tests nothing of the other side.
#[derive(Default)]
struct Tally {
    made: std::cell::Cell<u32>,
    refused: std::cell::Cell<u32>,
}

impl Tally {
    fn both(&self, property: &str) {
        let (made, refused) = (self.made.get(), self.refused.get());
        println!("{property}: {made} made, {refused} refused");
        assert!(
            made > 0 && refused > 0,
            "{property}: {made} made, {refused} refused"
        );
    }
}

/// What a call may return: a value, a refusal naming a rule, or one of the errors a
/// driver may give for a correct call that asks too much (memory, a format or size
/// the device does not support).
fn accepted<T>(tally: &Tally, what: &str, r: &tuff::Result<T>) -> Result<(), TestCaseError> {
    let counter = match r {
        Ok(_) => &tally.made,
        Err(_) => &tally.refused,
    };
    counter.set(counter.get() + 1);
    if let (Err(e), Some(_)) = (r, std::env::var_os("API_PROPERTIES_VERBOSE")) {
        println!("{what}: {e}");
    }
    match r {
        Ok(_) => Ok(()),
        Err(tuff::Error::Validation { vuid, message }) => {
            // A rule of the specification, or a hazard the tracker found.
            prop_assert!(
                vuid.starts_with("VUID-") || vuid.starts_with("SYNC-HAZARD-"),
                "{what}: refused as {vuid}: {message}"
            );
            prop_assert!(!message.is_empty(), "{what}: {vuid} without a message");
            Ok(())
        }
        Err(tuff::Error::Vk(
            vk::Result::ERROR_OUT_OF_HOST_MEMORY
            | vk::Result::ERROR_OUT_OF_DEVICE_MEMORY
            | vk::Result::ERROR_FORMAT_NOT_SUPPORTED,
        )) => Ok(()),
        Err(other) => Err(TestCaseError::fail(format!("{what}: {other}"))),
    }
}

/// The layer said nothing since the last case.
fn quiet(s: &Setup, what: &str) -> Result<(), TestCaseError> {
    let said = s.messages.take();
    prop_assert!(said.is_empty(), "{what}: the layer reported {said:?}");
    Ok(())
}

/// Mostly a value from `valid`, one time in nine from `wild`: with a dozen fields,
/// about a quarter of the inputs keep every rule and the rest break one or several.
fn or_wild<T: std::fmt::Debug + Clone + 'static>(
    valid: impl Strategy<Value = T> + 'static,
    wild: impl Strategy<Value = T> + 'static,
) -> BoxedStrategy<T> {
    prop_oneof![8 => valid, 1 => wild].boxed()
}

/// Byte counts and offsets: the edges, and anything.
fn size() -> impl Strategy<Value = u64> {
    prop_oneof![
        Just(0u64),
        Just(1),
        Just(4),
        Just(256),
        Just(65_536),
        Just(1 << 40),
        Just(u64::MAX),
        Just(u64::MAX - 3),
        Just(vk::WHOLE_SIZE),
        0u64..4096,
        any::<u64>(),
    ]
}

/// Extents and counts: zero, one, limits and past them, anything.
fn count() -> impl Strategy<Value = u32> {
    prop_oneof![
        Just(0u32),
        Just(1),
        Just(2),
        Just(7),
        Just(4096),
        Just(16_385),
        Just(u32::MAX),
        0u32..64,
        any::<u32>(),
    ]
}

/// Flag bits: none, the defined ones, and any (undefined bits included).
fn bits(defined: u32) -> impl Strategy<Value = u32> {
    prop_oneof![
        Just(0u32),
        (0..=defined).prop_map(move |b| b & defined),
        any::<u32>()
    ]
}

/// Enumerants: the first few defined values, and any.
fn enumerant(defined: i32) -> impl Strategy<Value = i32> {
    prop_oneof![0..defined, any::<i32>()]
}

fn float() -> impl Strategy<Value = f32> {
    prop_oneof![
        Just(0.0f32),
        Just(1.0),
        Just(-1.0),
        Just(16.0),
        Just(f32::NAN),
        Just(f32::INFINITY),
        Just(f32::NEG_INFINITY),
        Just(f32::MAX),
        -20.0f32..20.0,
    ]
}

fn runner() -> TestRunner {
    TestRunner::new(Config {
        // Each case is a Vulkan call: the default 256 cases take a second or two.
        failure_persistence: None,
        ..Config::default()
    })
}

#[test]
fn buffers_of_any_shape_are_made_or_refused_by_rule() {
    let s = setup(true);
    let tally = Tally::default();
    let queue_families = prop::collection::vec(prop_oneof![Just(s.family), any::<u32>()], 0..4);
    let input = (
        or_wild(1u64..65_536, size()),
        or_wild(1u32..0x200, bits(0x3ff)),
        or_wild(Just(0), bits(0xf)),
        or_wild(Just(0), 0..3i32),
        or_wild(Just(Vec::new()), queue_families),
    );
    runner()
        .run(&input, |(size, usage, flags, sharing, families): (u64, u32, u32, i32, Vec<u32>)| {
            let info = tuff::BufferCreateInfo::new()
                .size(size)
                .usage(vk::BufferUsageFlags::from_raw(usage))
                .flags(vk::BufferCreateFlags::from_raw(flags))
                .sharing_mode(vk::SharingMode::from_raw(sharing))
                .queue_family_indices(&families);
            let what = format!("buffer of {size} bytes, usage {usage:#x}, flags {flags:#x}, sharing {sharing}, families {families:?}");
            accepted(&tally, &what, &s.device.create_buffer(&info))?;
            quiet(&s, &what)
        })
        .unwrap();
    tally.both("buffers");
}

#[test]
fn images_of_any_shape_are_made_or_refused_by_rule() {
    let s = setup(true);
    let tally = Tally::default();
    let formats = prop_oneof![
        Just(vk::Format::R8G8B8A8_UNORM),
        Just(vk::Format::D32_SFLOAT),
        Just(vk::Format::BC1_RGB_UNORM_BLOCK),
        Just(vk::Format::G8_B8_R8_3PLANE_420_UNORM),
        Just(vk::Format::UNDEFINED),
        any::<i32>().prop_map(vk::Format::from_raw),
    ];
    let extent = (
        or_wild(1u32..512, count()),
        or_wild(1u32..512, count()),
        or_wild(Just(1), count()),
    );
    let input = (
        (
            or_wild(Just(1), enumerant(3)),
            or_wild(Just(vk::Format::R8G8B8A8_UNORM), formats),
            extent,
            or_wild(1u32..4, count()),
            or_wild(1u32..4, count()),
        ),
        (
            or_wild(Just(1), bits(0x7f)),
            or_wild(Just(0), enumerant(2)),
            or_wild(
                prop_oneof![Just(0x4), Just(0x6), Just(0x3), Just(0x5)],
                bits(0xff),
            ),
            or_wild(Just(0), bits(0x7ff)),
            or_wild(Just(0), enumerant(9)),
        ),
    );
    runner()
        .run(&input, |((ty, format, (w, h, d), mips, layers), (samples, tiling, usage, flags, layout))| {
            let info = tuff::ImageCreateInfo::new()
                .image_type(vk::ImageType::from_raw(ty))
                .format(format)
                .extent(vk::Extent3D { width: w, height: h, depth: d })
                .mip_levels(mips)
                .array_layers(layers)
                .samples(vk::SampleCountFlags::from_raw(samples))
                .tiling(vk::ImageTiling::from_raw(tiling))
                .usage(vk::ImageUsageFlags::from_raw(usage))
                .flags(vk::ImageCreateFlags::from_raw(flags))
                .initial_layout(vk::ImageLayout::from_raw(layout));
            let what = format!(
                "image type {ty}, {format:?} {w}x{h}x{d}, {mips} levels, {layers} layers, samples {samples:#x}, tiling {tiling}, usage {usage:#x}, flags {flags:#x}, layout {layout}"
            );
            accepted(&tally, &what, &s.device.create_image(&info))?;
            quiet(&s, &what)
        })
        .unwrap();
    tally.both("images");
}

#[test]
fn samplers_of_any_settings_are_made_or_refused_by_rule() {
    let s = setup(true);
    let tally = Tally::default();
    let input = (
        (
            or_wild(0..2i32, enumerant(2)),
            or_wild(0..2i32, enumerant(2)),
            or_wild(0..2i32, enumerant(2)),
            or_wild(0..4i32, enumerant(5)),
            or_wild(0..4i32, enumerant(5)),
        ),
        (
            or_wild(-2.0f32..2.0, float()),
            or_wild(Just(false), any::<bool>()),
            or_wild(Just(1.0f32), float()),
            or_wild(any::<bool>(), any::<bool>()),
            or_wild(0..8i32, enumerant(8)),
        ),
        (
            or_wild(0.0f32..1.0, float()),
            or_wild(1.0f32..10.0, float()),
            or_wild(0..6i32, enumerant(6)),
            or_wild(Just(false), any::<bool>()),
        ),
    );
    runner()
        .run(&input, |((mag, min, mip, u, v), (bias, aniso, max_aniso, compare, op), (min_lod, max_lod, border, unnormalized))| {
            let info = tuff::SamplerCreateInfo::new()
                .mag_filter(vk::Filter::from_raw(mag))
                .min_filter(vk::Filter::from_raw(min))
                .mipmap_mode(vk::SamplerMipmapMode::from_raw(mip))
                .address_mode_u(vk::SamplerAddressMode::from_raw(u))
                .address_mode_v(vk::SamplerAddressMode::from_raw(v))
                .mip_lod_bias(bias)
                .anisotropy_enable(aniso)
                .max_anisotropy(max_aniso)
                .compare_enable(compare)
                .compare_op(vk::CompareOp::from_raw(op))
                .min_lod(min_lod)
                .max_lod(max_lod)
                .border_color(vk::BorderColor::from_raw(border))
                .unnormalized_coordinates(unnormalized);
            let what = format!(
                "sampler mag {mag} min {min} mip {mip} u {u} v {v}, bias {bias}, anisotropy {aniso} {max_aniso}, compare {compare} {op}, lod {min_lod}..{max_lod}, border {border}, unnormalized {unnormalized}"
            );
            accepted(&tally, &what, &s.device.create_sampler(&info))?;
            quiet(&s, &what)
        })
        .unwrap();
    tally.both("samplers");
}

/// Copies and fills recorded between two 256-byte buffers: offsets and sizes anywhere,
/// empty region lists. What tuff records, the layer accepts.
#[test]
fn buffer_copies_and_fills_are_recorded_or_refused_by_rule() {
    let s = setup(true);
    let tally = Tally::default();
    let usage = vk::BufferUsageFlags::TRANSFER_SRC | vk::BufferUsageFlags::TRANSFER_DST;
    let allocator = s.device.gpu_allocator().unwrap();
    let info = tuff::BufferCreateInfo::new().size(256).usage(usage);
    let buffers = [(); 2].map(|_| {
        s.device
            .create_buffer_in(&info, &allocator, tuff::MemoryLocation::DeviceLocal)
            .unwrap()
    });
    let (_pool, cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    // proptest's closure is `Fn`; the recording needs the command buffer `&mut`.
    let cb = std::cell::RefCell::new(cb);
    let region = (
        or_wild(0u64..128, size()),
        or_wild(0u64..128, size()),
        or_wild(1u64..128, size()),
    )
        .prop_map(|(src_offset, dst_offset, size)| vk::BufferCopy {
            src_offset,
            dst_offset,
            size,
        })
        .boxed();
    let input = (
        or_wild(
            prop::collection::vec(region.clone(), 1..3),
            prop::collection::vec(region, 0..4),
        ),
        (
            or_wild((0u64..64).prop_map(|o| o * 4), size()),
            or_wild((1u64..32).prop_map(|o| o * 4), size()),
            any::<u32>(),
        ),
        or_wild(Just(false), any::<bool>()),
    );
    runner()
        .run(
            &input,
            |(regions, (offset, size, data), same): (
                Vec<vk::BufferCopy>,
                (u64, u64, u32),
                bool,
            )| {
                let what = format!(
                    "copy {regions:?}, fill at {offset} of {size} bytes, same buffer {same}"
                );
                let mut cb = cb.borrow_mut();
                let mut rec = cb.begin(&tuff::CommandBufferBeginInfo::new()).unwrap();
                let (src, dst) = (&*buffers[0], &*buffers[usize::from(!same)]);
                accepted(&tally, &what, &rec.copy_buffer(src, dst, &regions))?;
                accepted(&tally, &what, &rec.fill_buffer(dst, offset, size, data))?;
                rec.end().unwrap();
                quiet(&s, &what)
            },
        )
        .unwrap();
    tally.both("copies");
}
