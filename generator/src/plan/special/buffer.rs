//! The special-case rows of one concern; their functions are the `tuff` crate's
//! `special/buffer.rs`, and a row here calls no other (but the image-layout tracker).
//!
//! Buffers: creation (limits, sharing, sparse residency), the record the device keeps of each,
//! and the check that a recorded command's buffer range lies inside it with the usage it needs.

use super::{call, How, Special, NONE};

const UNPROVEN_SPARSE: &str = "checked by the safe methods in every build, but no test breaks it: lavapipe has no sparse resources, so any sparse flag is refused for that first";
const UNPROVEN_SPARSE_SPACE: &str = "checked by the safe methods in every build (the memory of every live sparse buffer and image against sparseAddressSpaceSize, under a lock held until the new buffer is listed), but no test breaks it: lavapipe has no sparse resources, so any sparse flag is refused for that first";
const BUFFER_INFO: &str = "checks the concurrent queue families against the physical device's family count, and a capture address against the flags";
const BUFFER_ALONE: &str = "checks the size against the device's maxBufferSize, and the external handle types against what the physical device reports it can export for the buffer (the 1.3.239 layer checks neither: proven by the error alone)";

const ADDRESS: &str = "checks the buffer's usage and bound memory, kept from its creation and bind, and on a device group the multi-device feature";
const UNPROVEN_MULTI_DEVICE: &str = "checked by the safe methods in every build (the device's physical-device count and features, recorded at its creation), but no test breaks it: lavapipe's devices are not device groups";

/// The rows of this concern.
pub(super) const ROWS: &[Special] = &[
    Special {
        command: "vkGetBufferDeviceAddress",
        check_last: call(
            "special::buffer::buffer_address_checks",
            &[
                "self",
                "info",
                "\"VUID-vkGetBufferDeviceAddress-device-06543\"",
            ],
        ),
        settles: &[
            (
                "VUID-vkGetBufferDeviceAddress-device-06543",
                How::User(UNPROVEN_MULTI_DEVICE),
            ),
            (
                "VUID-VkBufferDeviceAddressInfo-buffer-02600",
                How::Dynamic(ADDRESS),
            ),
            (
                "VUID-VkBufferDeviceAddressInfo-buffer-02601",
                How::Dynamic(ADDRESS),
            ),
        ],
        ..NONE
    },
    Special {
        command: "vkGetBufferOpaqueCaptureAddress",
        check_last: call(
            "special::buffer::buffer_address_checks",
            &[
                "self",
                "info",
                "\"VUID-vkGetBufferOpaqueCaptureAddress-device-03327\"",
            ],
        ),
        settles: &[(
            "VUID-vkGetBufferOpaqueCaptureAddress-device-03327",
            How::User(UNPROVEN_MULTI_DEVICE),
        )],
        ..NONE
    },
    Special {
        command: "vkCreateBuffer",
        check_last: call(
            "special::buffer::create_buffer_checks",
            &["self", "create_info"],
        ),
        hold: call(
            "special::buffer::sparse_buffer_hold",
            &["self", "create_info"],
        ),
        created: call(
            "special::buffer::buffer_created",
            &["self", "created", "create_info"],
        ),
        settles: &[
            (
                "VUID-VkBufferCreateInfo-None-01888",
                How::User(UNPROVEN_SPARSE),
            ),
            (
                "VUID-vkCreateBuffer-flags-00911",
                How::User(UNPROVEN_SPARSE_SPACE),
            ),
            (
                "VUID-VkBufferCreateInfo-size-06409",
                How::Dynamic(BUFFER_ALONE),
            ),
            (
                "VUID-VkBufferCreateInfo-sharingMode-01419",
                How::Dynamic(BUFFER_INFO),
            ),
            (
                "VUID-VkBufferCreateInfo-opaqueCaptureAddress-03337",
                How::Dynamic(BUFFER_INFO),
            ),
            (
                "VUID-VkBufferCreateInfo-pNext-00920",
                How::Dynamic(BUFFER_ALONE),
            ),
        ],
        ..NONE
    },
];
