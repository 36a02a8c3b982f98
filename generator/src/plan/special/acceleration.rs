//! The special-case rows of one concern; their functions are the `tuff` crate's
//! `special/acceleration.rs`, and a row here calls no other (but the image-layout tracker).
//!
//! Acceleration structure builds: each build info's range arrays against its geometry count.

use super::{call, How, Special, NONE};

const UNPROVEN_ACCELERATION: &str = "checked by the safe methods in every build (each build info's range array against its geometry count), but no test breaks it: lavapipe 22.3 has no VK_KHR_acceleration_structure";

/// The rows of this concern.
pub(super) const ROWS: &[Special] = &[
    Special {
        command: "vkCmdBuildAccelerationStructuresKHR",
        check: call(
            "special::acceleration::per_geometry_fits",
            &[
                "infos",
                "build_range_infos",
                "Some(\"VUID-vkCmdBuildAccelerationStructuresKHR-ppBuildRangeInfos-03676\")",
            ],
        ),
        settles: &[(
            "VUID-vkCmdBuildAccelerationStructuresKHR-ppBuildRangeInfos-03676",
            How::User(UNPROVEN_ACCELERATION),
        )],
        ..NONE
    },
    Special {
        command: "vkBuildAccelerationStructuresKHR",
        check: call(
            "special::acceleration::per_geometry_fits",
            &[
                "infos",
                "build_range_infos",
                "Some(\"VUID-vkBuildAccelerationStructuresKHR-ppBuildRangeInfos-03676\")",
            ],
        ),
        settles: &[(
            "VUID-vkBuildAccelerationStructuresKHR-ppBuildRangeInfos-03676",
            How::User(UNPROVEN_ACCELERATION),
        )],
        ..NONE
    },
    Special {
        command: "vkCmdBuildAccelerationStructuresIndirectKHR",
        check: call(
            "special::acceleration::per_geometry_fits",
            &["infos", "max_primitive_counts", "None"],
        ),
        ..NONE
    },
];
