//! The special-case rows of one concern; their functions are the `tuff` crate's
//! `special/sampler.rs`, and a row here calls no other (but the image-layout tracker).
//!
//! Samplers: their creation checks and the record the device keeps of each.

use super::{call, How, Special, NONE};

const SAMPLER_MODES: &str = "checks the filters, address modes and a chained reduction mode together, against the device's samplerMirrorClampToEdge and samplerFilterMinmax features";

const SAMPLER_COUNT: &str = "checks the live samplers the device lists (every one made through the wrappers, until destroyed) against maxSamplerAllocationCount, under a lock held until the new sampler is listed";
const VALUES_READ: &str = "checks the border colour and the compare operation against the values of the versions and extensions enabled, always: drivers read them whatever the address modes and comparison (lavapipe crashes on an invalid border colour)";
const UNPROVEN_CONVERSION: &str = "checked by the safe methods in every build (the address modes, anisotropy, coordinates, reduction mode and filters against the chained conversion's format and chroma filter, recorded at its creation), but no test breaks it: lavapipe 22.3 has no samplerYcbcrConversion feature, so no conversion can be made";

/// The rows of this concern.
pub(super) const ROWS: &[Special] = &[Special {
    command: "vkCreateSampler",
    check_last: call("special::sampler::sampler_checks", &["self", "create_info"]),
    hold: call("special::sampler::create_sampler_hold", &["self"]),
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
        (
            "VUID-vkCreateSampler-maxSamplerAllocationCount-04110",
            How::Dynamic(SAMPLER_COUNT),
        ),
        (
            "VUID-VkSamplerCreateInfo-addressModeU-01078",
            How::Dynamic(VALUES_READ),
        ),
        (
            "VUID-VkSamplerCreateInfo-compareEnable-01080",
            How::Dynamic(VALUES_READ),
        ),
        (
            "VUID-VkSamplerCreateInfo-addressModeU-01646",
            How::User(UNPROVEN_CONVERSION),
        ),
        (
            "VUID-VkSamplerCreateInfo-None-01647",
            How::User(UNPROVEN_CONVERSION),
        ),
        (
            "VUID-VkSamplerCreateInfo-minFilter-01645",
            How::User(UNPROVEN_CONVERSION),
        ),
    ],
    ..NONE
}];
