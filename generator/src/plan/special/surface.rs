//! The special-case rows of one concern; their functions are the `tuff` crate's
//! `special/surface.rs`, and a row here calls no other (but the image-layout tracker).
//!
//! Surfaces: queue family and surface support queries.

use super::{call, How, Special, NONE, UNPROVEN_SURFACE};

const UNPROVEN_XCB: &str = "checked by the safe methods in every build (against the physical device's queue family count), but no test breaks it: the tests' windows are Xlib ones, and the Xlib query's check of the same count is the one the tests break";
const UNPROVEN_WAYLAND: &str = "checked by the safe methods in every build (against the physical device's queue family count), but no test breaks it: the tests have no Wayland compositor";
const NO_SURFACE: &str = "refuses a query without a surface (only VK_GOOGLE_surfaceless_query, which tuff does not emit, allows one)";
const FAMILY_COUNT: &str = "checks the family against the physical device's queue family count";
const UNPROVEN_WIN32: &str = "checked by the safe methods in every build (against the physical device's queue family count), but no test breaks it: the tests run on Linux";

/// A query of a surface's properties: the surface is one the physical device
/// supports (`-surface-06211`).
macro_rules! surface_query {
    ($command:literal) => {
        Special {
            command: $command,
            check_last: call(
                "special::surface::surface_supported",
                &[
                    "self",
                    "surface",
                    concat!("\"VUID-", $command, "-surface-06211\""),
                    concat!("\"VUID-", $command, "-surface-06523\""),
                ],
            ),
            settles: &[
                (
                    concat!("VUID-", $command, "-surface-06211"),
                    How::User(UNPROVEN_SURFACE),
                ),
                (
                    concat!("VUID-", $command, "-surface-06523"),
                    How::Dynamic(NO_SURFACE),
                ),
            ],
            ..NONE
        }
    };
}

/// The rows of this concern.
pub(super) const ROWS: &[Special] = &[
    Special {
        command: "vkGetPhysicalDeviceSurfaceSupportKHR",
        check: call(
            "special::surface::queue_family_exists",
            &[
                "self",
                "queue_family_index",
                "\"VUID-vkGetPhysicalDeviceSurfaceSupportKHR-queueFamilyIndex-01269\"",
            ],
        ),
        settles: &[(
            "VUID-vkGetPhysicalDeviceSurfaceSupportKHR-queueFamilyIndex-01269",
            How::Dynamic(FAMILY_COUNT),
        )],
        ..NONE
    },
    Special {
        command: "vkGetPhysicalDeviceXlibPresentationSupportKHR",
        check: call(
            "special::surface::queue_family_exists",
            &[
                "self",
                "queue_family_index",
                "\"VUID-vkGetPhysicalDeviceXlibPresentationSupportKHR-queueFamilyIndex-01315\"",
            ],
        ),
        settles: &[(
            "VUID-vkGetPhysicalDeviceXlibPresentationSupportKHR-queueFamilyIndex-01315",
            How::Dynamic(FAMILY_COUNT),
        )],
        ..NONE
    },
    Special {
        command: "vkGetPhysicalDeviceXcbPresentationSupportKHR",
        check: call(
            "special::surface::queue_family_exists",
            &[
                "self",
                "queue_family_index",
                "\"VUID-vkGetPhysicalDeviceXcbPresentationSupportKHR-queueFamilyIndex-01312\"",
            ],
        ),
        settles: &[(
            "VUID-vkGetPhysicalDeviceXcbPresentationSupportKHR-queueFamilyIndex-01312",
            How::User(UNPROVEN_XCB),
        )],
        ..NONE
    },
    Special {
        command: "vkGetPhysicalDeviceWaylandPresentationSupportKHR",
        check: call(
            "special::surface::queue_family_exists",
            &[
                "self",
                "queue_family_index",
                "\"VUID-vkGetPhysicalDeviceWaylandPresentationSupportKHR-queueFamilyIndex-01306\"",
            ],
        ),
        settles: &[(
            "VUID-vkGetPhysicalDeviceWaylandPresentationSupportKHR-queueFamilyIndex-01306",
            How::User(UNPROVEN_WAYLAND),
        )],
        ..NONE
    },
    Special {
        command: "vkGetPhysicalDeviceWin32PresentationSupportKHR",
        check: call(
            "special::surface::queue_family_exists",
            &[
                "self",
                "queue_family_index",
                "\"VUID-vkGetPhysicalDeviceWin32PresentationSupportKHR-queueFamilyIndex-01309\"",
            ],
        ),
        settles: &[(
            "VUID-vkGetPhysicalDeviceWin32PresentationSupportKHR-queueFamilyIndex-01309",
            How::User(UNPROVEN_WIN32),
        )],
        ..NONE
    },
    surface_query!("vkGetPhysicalDeviceSurfaceCapabilitiesKHR"),
    surface_query!("vkGetPhysicalDeviceSurfaceFormatsKHR"),
    surface_query!("vkGetPhysicalDeviceSurfacePresentModesKHR"),
    surface_query!("vkGetPhysicalDevicePresentRectanglesKHR"),
];
