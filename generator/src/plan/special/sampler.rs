//! The special-case rows of one concern; their functions are the `tuff` crate's
//! `special/sampler.rs`, and a row here calls no other (but the image-layout tracker).
//!
//! Samplers: their creation checks and the record the device keeps of each.

use super::{call, How, Special, NONE};

const SAMPLER_MODES: &str = "checks the filters, address modes and a chained reduction mode together, against the device's samplerMirrorClampToEdge and samplerFilterMinmax features";

/// The rows of this concern.
pub(super) const ROWS: &[Special] = &[Special {
    command: "vkCreateSampler",
    check_last: call("special::sampler::sampler_checks", &["self", "create_info"]),
    created: call(
        "special::sampler::sampler_created",
        &["self", "created", "create_info"],
    ),
    settles: &[
        (
            "VUID-VkSamplerCreateInfo-unnormalizedCoordinates-01072",
            How::Dynamic(SAMPLER_MODES),
        ),
        (
            "VUID-VkSamplerCreateInfo-addressModeU-01079",
            How::Dynamic(SAMPLER_MODES),
        ),
        (
            "VUID-VkSamplerCreateInfo-pNext-06726",
            How::Dynamic(SAMPLER_MODES),
        ),
        (
            "VUID-VkSamplerCreateInfo-compareEnable-01423",
            How::Dynamic(SAMPLER_MODES),
        ),
    ],
    ..NONE
}];
