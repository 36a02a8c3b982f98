//! The oracle: every explicit rule that the generator's recognisers read, on a
//! struct this file has a fixture for, is broken once, by the change
//! `generated/oracle_cases.rs` derives from the rule's check.
//!
//! Each case runs twice. Through the safe method, tuff must refuse the call with the
//! rule's VUID. Through the `_unchecked` twin, under the validation layer with a
//! messenger that makes the layer skip an erroring call, the layer must name the same
//! VUID and nothing else, or say nothing at all: the rule is then "proven by the error
//! alone", as for rules the layer does not check. Any other outcome fails the test.
//! The generator reports exactly these rules as dynamically settled.

#[path = "common/pipelines.rs"]
mod pipelines;
#[path = "common/tuff_setup.rs"]
mod tuff_setup;
#[path = "common/vulkan.rs"]
mod vulkan;

use tuff::vk;
use tuff_setup::{setup, Setup};

type Limits = vk::PhysicalDeviceLimits;

/// What one run of a case saw: the safe method's result and what the layer said
/// about the unchecked call.
struct Outcome {
    safe: tuff::Result<()>,
    layer: Vec<String>,
}

/// A case: the rule, and the run of its fixture with its change.
type Case = (&'static str, Box<dyn Fn(&Setup, &Limits) -> Outcome>);

macro_rules! oracle_cases {
    ($($fixture:ident: $ty:ident { $($vuid:literal => |$v:ident, $l:ident| $body:block),* $(,)? }),* $(,)?) => {
        fn cases() -> Vec<Case> {
            vec![$($(
                (
                    $vuid,
                    Box::new(|s: &Setup, limits: &Limits| {
                        $fixture(s, limits, &|$v: &mut vk::$ty<'_>, $l: &Limits| {
                            let _ = $l;
                            $body
                        })
                    }),
                ),
            )*)*]
        }
    };
}

include!("../generated/oracle_cases.rs");

/// Runs `unchecked` with the layer told to skip erroring calls, and returns what it
/// said.
fn under_layer(s: &Setup, unchecked: impl FnOnce()) -> Vec<String> {
    s.messages.take();
    s.messages.abort_on_error(true);
    unchecked();
    s.messages.abort_on_error(false);
    s.messages.take()
}

fn buffer_create_info(
    s: &Setup,
    limits: &Limits,
    change: &dyn Fn(&mut vk::BufferCreateInfo<'_>, &Limits),
) -> Outcome {
    let mut info = tuff::BufferCreateInfo::new()
        .size(64)
        .usage(vk::BufferUsageFlags::TRANSFER_SRC);
    // SAFETY: the change sets plain values only (the generator never changes a
    // pointer or a count).
    change(unsafe { info.raw_values_mut() }, limits);
    let safe = s.device.create_buffer(&info).map(drop);
    // SAFETY: the layer skips the call if it finds the rule broken; where it does
    // not, the driver gets a value that breaks only a rule the layer does not check.
    let layer = under_layer(s, || {
        drop(unsafe { s.device.create_buffer_unchecked(&info) })
    });
    Outcome { safe, layer }
}

fn image_create_info(
    s: &Setup,
    limits: &Limits,
    change: &dyn Fn(&mut vk::ImageCreateInfo<'_>, &Limits),
) -> Outcome {
    let mut info = tuff::ImageCreateInfo::new()
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
        .usage(vk::ImageUsageFlags::SAMPLED);
    // SAFETY: as in `buffer_create_info`.
    change(unsafe { info.raw_values_mut() }, limits);
    let safe = s.device.create_image(&info).map(drop);
    // SAFETY: as in `buffer_create_info`.
    let layer = under_layer(s, || {
        drop(unsafe { s.device.create_image_unchecked(&info) })
    });
    Outcome { safe, layer }
}

fn sampler_create_info(
    s: &Setup,
    limits: &Limits,
    change: &dyn Fn(&mut vk::SamplerCreateInfo<'_>, &Limits),
) -> Outcome {
    let edge = vk::SamplerAddressMode::CLAMP_TO_EDGE;
    let mut info = tuff::SamplerCreateInfo::new()
        .address_mode_u(edge)
        .address_mode_v(edge)
        .address_mode_w(edge)
        .max_anisotropy(1.0);
    // SAFETY: as in `buffer_create_info`.
    change(unsafe { info.raw_values_mut() }, limits);
    let safe = s.device.create_sampler(&info).map(drop);
    // SAFETY: as in `buffer_create_info`.
    let layer = under_layer(s, || {
        drop(unsafe { s.device.create_sampler_unchecked(&info) })
    });
    Outcome { safe, layer }
}

/// Records `barrier` through the safe method (whose refusal `end` returns) and
/// through the unchecked one under the layer.
fn barrier(s: &Setup, info: &tuff::DependencyInfo<'_>) -> Outcome {
    let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let mut rec = cb
        .begin(&tuff::CommandBufferBeginInfo::new())
        .expect("begin");
    rec.cmd_pipeline_barrier2(info);
    let safe = rec.end();
    let (_pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let mut rec = cb
        .begin(&tuff::CommandBufferBeginInfo::new())
        .expect("begin");
    // SAFETY: as in `buffer_create_info`; the command buffer is never submitted.
    let layer = under_layer(s, || unsafe { rec.cmd_pipeline_barrier2_unchecked(info) });
    rec.end().expect("end");
    Outcome { safe, layer }
}

const ALL: vk::PipelineStageFlags2 = vk::PipelineStageFlags2::ALL_COMMANDS;

fn memory_barrier2(
    s: &Setup,
    limits: &Limits,
    change: &dyn Fn(&mut vk::MemoryBarrier2<'_>, &Limits),
) -> Outcome {
    let mut b = tuff::MemoryBarrier2::new()
        .src_stage_mask(ALL)
        .dst_stage_mask(ALL);
    // SAFETY: as in `buffer_create_info`.
    change(unsafe { b.raw_values_mut() }, limits);
    let barriers = [b];
    barrier(s, &tuff::DependencyInfo::new().memory_barriers(&barriers))
}

fn buffer_memory_barrier2(
    s: &Setup,
    limits: &Limits,
    change: &dyn Fn(&mut vk::BufferMemoryBarrier2<'_>, &Limits),
) -> Outcome {
    let (buffer, _memory) = pipelines::host_buffer(s, 64, vk::BufferUsageFlags::TRANSFER_SRC);
    let mut b = tuff::BufferMemoryBarrier2::new(&buffer)
        .src_stage_mask(ALL)
        .dst_stage_mask(ALL)
        .src_queue_family_index(vk::QUEUE_FAMILY_IGNORED)
        .dst_queue_family_index(vk::QUEUE_FAMILY_IGNORED)
        .size(vk::WHOLE_SIZE);
    // SAFETY: as in `buffer_create_info`.
    change(unsafe { b.raw_values_mut() }, limits);
    let barriers = [b];
    barrier(
        s,
        &tuff::DependencyInfo::new().buffer_memory_barriers(&barriers),
    )
}

fn image_memory_barrier2(
    s: &Setup,
    limits: &Limits,
    change: &dyn Fn(&mut vk::ImageMemoryBarrier2<'_>, &Limits),
) -> Outcome {
    let target = s.color_target(4, vk::ImageUsageFlags::empty());
    let mut b = tuff::ImageMemoryBarrier2::new(&target.image)
        .src_stage_mask(ALL)
        .dst_stage_mask(ALL)
        .old_layout(vk::ImageLayout::UNDEFINED)
        .new_layout(vk::ImageLayout::GENERAL)
        .src_queue_family_index(vk::QUEUE_FAMILY_IGNORED)
        .dst_queue_family_index(vk::QUEUE_FAMILY_IGNORED)
        .subresource_range(vk::ImageSubresourceRange {
            aspect_mask: vk::ImageAspectFlags::COLOR,
            base_mip_level: 0,
            level_count: 1,
            base_array_layer: 0,
            layer_count: 1,
        });
    // SAFETY: as in `buffer_create_info`.
    change(unsafe { b.raw_values_mut() }, limits);
    let barriers = [b];
    barrier(
        s,
        &tuff::DependencyInfo::new().image_memory_barriers(&barriers),
    )
}

/// Every case breaks its rule: tuff refuses it with the rule's VUID, and the layer
/// names that VUID alone or nothing.
#[test]
fn every_recognised_rule_is_refused_and_the_layer_agrees() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let limits = s.physical.get_physical_device_properties().limits;
    // `setup` enables no Vulkan 1.0 feature, which the cases of rules that apply
    // when a feature is off rely on.
    let cases = cases();
    assert!(!cases.is_empty(), "generated/oracle_cases.rs has no case");
    let (mut by_layer, mut alone, mut failures) = (0, Vec::new(), Vec::new());
    for (vuid, run) in &cases {
        let out = run(&s, &limits);
        match &out.safe {
            Err(tuff::Error::Validation { vuid: got, .. }) if got == vuid => {}
            other => {
                failures.push(format!("{vuid}: the safe method returned {other:?}"));
                continue;
            }
        }
        if out.layer.is_empty() {
            alone.push(*vuid);
        } else if out.layer.iter().all(|m| m.contains(vuid)) {
            by_layer += 1;
        } else {
            failures.push(format!(
                "{vuid}: the layer said something else:\n  {}",
                out.layer.join("\n  ")
            ));
        }
    }
    println!(
        "oracle: {} rules broken; the layer named {by_layer}, the error alone proves {} ({})",
        cases.len(),
        alone.len(),
        alone.join(", ")
    );
    assert!(
        failures.is_empty(),
        "{} of {} cases failed:\n{}",
        failures.len(),
        cases.len(),
        failures.join("\n")
    );
}
