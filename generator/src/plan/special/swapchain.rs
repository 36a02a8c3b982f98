//! The special-case rows of one concern; their functions are the `tuff` crate's
//! `special/swapchain.rs`, and a row here calls no other (but the image-layout tracker).
//!
//! Swapchains and presentation: creation, image acquisition and presents (the images
//! presented, their layouts, device groups).

use super::{
    call, How, Keeps, Special, BINARY_STATE, FENCE, NONE, ONE_WAITER, SEMAPHORE_TYPE, UNPROVEN,
    UNPROVEN_SURFACE,
};

const PRESENTED: &str = "checks each index against the images acquired from the swapchain and not presented since, and the image's layout against the one the device's submissions so far leave it in (the recorder follows every command that changes a layout)";
const UNPROVEN_SURFACE_SUPPORT: &str = "checked by the safe methods in every build (vkGetPhysicalDeviceSurfaceSupportKHR, asked once per swapchain and queue family), but no test breaks it: lavapipe's only queue family presents to every surface";
const GROUP_PRESENT: &str = "checks the chained struct's count and each device mask against its mode and the device group's present masks (read once with vkGetDeviceGroupPresentCapabilitiesKHR), against the mask its image was acquired with (every physical device for vkAcquireNextImageKHR), and the mode against the modes the swapchain was created with (the 1.3.239 layer does not check these rules on a device of one physical device: the error alone proves them)";
const SURFACE_REPORTS: &str = "checks the create info against what the physical device reports for the surface (support from a queue family of the device, capabilities, formats, present modes) and for the swapchain's implied images, its queue families, and the device's physical-device count";
const UNPROVEN_SWAPCHAIN_SURFACE: &str = "checked by the safe methods in every build (against what the physical device reports for the surface and the swapchain's images), but no test breaks it: lavapipe's X11 surface is supported by its only queue family, has no maximum image count, offers every present mode the emitted API defines, and supports the images of every create info the other checks let through";
const RETIRED_SWAPCHAIN: &str = "checks oldSwapchain presents to the same surface and was not retired: the device records each swapchain's surface, and a creation retires its oldSwapchain before the call, whether or not it succeeds";
const SAME_AS_03268: &str = "checked by the safe methods in every build, by the check of VUID-vkQueuePresentKHR-pWaitSemaphores-03268, whose condition it shares and whose VUID the error names (a presentation waits only on binary semaphores: 03267)";
const ACQUIRE_SIGNALS: &str = "checks the acquire has a semaphore or a fence to signal";
const RETIRED_ACQUIRE: &str = "checks the swapchain was not retired: the device records a swapchain as retired when a creation names it as oldSwapchain";
const FORWARD_PROGRESS: &str = "checks an infinite timeout against the swapchain's acquired images (the device records each acquire and presentation), its image count and the surface's minImageCount";

/// The rows of this concern.
pub(super) const ROWS: &[Special] = &[
    Special {
        command: "vkAcquireNextImageKHR",
        check: call(
            "special::swapchain::acquire_next_image_khr_checks",
            &["self", "swapchain", "timeout", "semaphore", "fence"],
        ),
        after: call(
            "special::swapchain::acquire_next_image_khr_done",
            &["self", "swapchain", "semaphore", "fence", "out", "r"],
        ),
        settles: &[
            (
                "VUID-vkAcquireNextImageKHR-semaphore-03265",
                How::Dynamic(SEMAPHORE_TYPE),
            ),
            (
                "VUID-vkAcquireNextImageKHR-semaphore-01780",
                How::Dynamic(ACQUIRE_SIGNALS),
            ),
            (
                "VUID-vkAcquireNextImageKHR-swapchain-01285",
                How::Dynamic(RETIRED_ACQUIRE),
            ),
            (
                "VUID-vkAcquireNextImageKHR-semaphore-01286",
                How::Dynamic(BINARY_STATE),
            ),
            (
                "VUID-vkAcquireNextImageKHR-semaphore-01779",
                How::Dynamic(BINARY_STATE),
            ),
            (
                "VUID-vkAcquireNextImageKHR-fence-01287",
                How::Dynamic(FENCE),
            ),
            (
                "VUID-vkAcquireNextImageKHR-surface-07783",
                How::Dynamic(FORWARD_PROGRESS),
            ),
        ],
        ..NONE
    },
    Special {
        command: "vkAcquireNextImage2KHR",
        check: call(
            "special::swapchain::acquire_next_image2_khr_checks",
            &["self", "acquire_info"],
        ),
        after: call(
            "special::swapchain::acquire_next_image2_khr_done",
            &["self", "acquire_info", "out", "r"],
        ),
        settles: &[
            (
                "VUID-VkAcquireNextImageInfoKHR-semaphore-03266",
                How::User(UNPROVEN),
            ),
            (
                "VUID-VkAcquireNextImageInfoKHR-semaphore-01782",
                How::User(UNPROVEN),
            ),
            (
                "VUID-VkAcquireNextImageInfoKHR-swapchain-01675",
                How::User(UNPROVEN),
            ),
            (
                "VUID-VkAcquireNextImageInfoKHR-semaphore-01288",
                How::User(UNPROVEN),
            ),
            (
                "VUID-VkAcquireNextImageInfoKHR-semaphore-01781",
                How::User(UNPROVEN),
            ),
        ],
        ..NONE
    },
    Special {
        command: "vkQueuePresentKHR",
        check: call(
            "special::swapchain::queue_present_khr_checks",
            &["self", "present_info"],
        ),
        hold: call(
            "special::swapchain::queue_present_khr_hold",
            &["self", "present_info"],
        ),
        before: call(
            "special::swapchain::queue_present_khr_before",
            &["self", "present_info"],
        ),
        settles: &[
            (
                "VUID-vkQueuePresentKHR-pWaitSemaphores-03267",
                How::Dynamic(SEMAPHORE_TYPE),
            ),
            (
                "VUID-vkQueuePresentKHR-pWaitSemaphores-03268",
                How::Dynamic(BINARY_STATE),
            ),
            (
                "VUID-vkQueuePresentKHR-pWaitSemaphores-01295",
                How::User(SAME_AS_03268),
            ),
            (
                "VUID-vkQueuePresentKHR-pWaitSemaphores-01294",
                How::User(ONE_WAITER),
            ),
            (
                "VUID-VkPresentInfoKHR-pImageIndices-01296",
                How::Dynamic(PRESENTED),
            ),
            (
                "VUID-vkQueuePresentKHR-pSwapchains-01292",
                How::User(UNPROVEN_SURFACE_SUPPORT),
            ),
            (
                "VUID-VkDeviceGroupPresentInfoKHR-swapchainCount-01297",
                How::Dynamic(GROUP_PRESENT),
            ),
            (
                "VUID-VkDeviceGroupPresentInfoKHR-mode-01298",
                How::Dynamic(GROUP_PRESENT),
            ),
            (
                "VUID-VkDeviceGroupPresentInfoKHR-mode-01299",
                How::Dynamic(GROUP_PRESENT),
            ),
            (
                "VUID-VkDeviceGroupPresentInfoKHR-mode-01300",
                How::Dynamic(GROUP_PRESENT),
            ),
            (
                "VUID-VkDeviceGroupPresentInfoKHR-mode-01301",
                How::Dynamic(GROUP_PRESENT),
            ),
            (
                "VUID-VkDeviceGroupPresentInfoKHR-pDeviceMasks-01302",
                How::Dynamic(GROUP_PRESENT),
            ),
            (
                "VUID-VkDeviceGroupPresentInfoKHR-mode-01303",
                How::Dynamic(GROUP_PRESENT),
            ),
        ],
        ..NONE
    },
    Special {
        command: "vkGetDeviceGroupSurfacePresentModesKHR",
        check_last: call(
            "special::swapchain::device_surface_supported",
            &[
                "self",
                "surface",
                "\"VUID-vkGetDeviceGroupSurfacePresentModesKHR-surface-06212\"",
            ],
        ),
        settles: &[(
            "VUID-vkGetDeviceGroupSurfacePresentModesKHR-surface-06212",
            How::User(UNPROVEN_SURFACE),
        )],
        ..NONE
    },
    Special {
        command: "vkCreateSwapchainKHR",
        check_last: call(
            "special::swapchain::create_swapchain_checks",
            &["self", "surface", "create_info"],
        ),
        before: call(
            "special::swapchain::swapchain_retires",
            &["self", "create_info"],
        ),
        created: call(
            "special::swapchain::swapchain_created",
            &["self", "created", "surface", "create_info"],
        ),
        // VUID-vkDestroySurfaceKHR-surface-01266: swapchains go before their surface.
        keeps: Keeps::Member("surface", "VkSurfaceKHR"),
        settles: &[
            (
                "VUID-vkDestroySurfaceKHR-surface-01266",
                How::Static("a swapchain wrapper keeps its surface alive"),
            ),
            (
                "VUID-VkSwapchainCreateInfoKHR-surface-01270",
                How::User(UNPROVEN_SWAPCHAIN_SURFACE),
            ),
            (
                "VUID-VkSwapchainCreateInfoKHR-minImageCount-01271",
                How::Dynamic(SURFACE_REPORTS),
            ),
            (
                "VUID-VkSwapchainCreateInfoKHR-minImageCount-01272",
                How::User(UNPROVEN_SWAPCHAIN_SURFACE),
            ),
            (
                "VUID-VkSwapchainCreateInfoKHR-imageFormat-01273",
                How::Dynamic(SURFACE_REPORTS),
            ),
            (
                "VUID-VkSwapchainCreateInfoKHR-imageExtent-01689",
                How::Dynamic(SURFACE_REPORTS),
            ),
            (
                "VUID-VkSwapchainCreateInfoKHR-imageExtent-01274",
                How::Dynamic(SURFACE_REPORTS),
            ),
            (
                "VUID-VkSwapchainCreateInfoKHR-imageArrayLayers-01275",
                How::Dynamic(SURFACE_REPORTS),
            ),
            (
                "VUID-VkSwapchainCreateInfoKHR-presentMode-01281",
                How::User(UNPROVEN_SWAPCHAIN_SURFACE),
            ),
            (
                "VUID-VkSwapchainCreateInfoKHR-presentMode-01427",
                How::Dynamic(SURFACE_REPORTS),
            ),
            (
                "VUID-VkSwapchainCreateInfoKHR-preTransform-01279",
                How::Dynamic(SURFACE_REPORTS),
            ),
            (
                "VUID-VkSwapchainCreateInfoKHR-compositeAlpha-01280",
                How::Dynamic(SURFACE_REPORTS),
            ),
            (
                "VUID-VkSwapchainCreateInfoKHR-imageSharingMode-01428",
                How::Dynamic(SURFACE_REPORTS),
            ),
            (
                "VUID-VkSwapchainCreateInfoKHR-physicalDeviceCount-01429",
                How::Dynamic(SURFACE_REPORTS),
            ),
            (
                "VUID-VkSwapchainCreateInfoKHR-imageFormat-01778",
                How::User(UNPROVEN_SWAPCHAIN_SURFACE),
            ),
            (
                "VUID-VkSwapchainCreateInfoKHR-oldSwapchain-01933",
                How::Dynamic(RETIRED_SWAPCHAIN),
            ),
        ],
        ..NONE
    },
    Special {
        command: "vkGetSwapchainImagesKHR",
        created: call(
            "special::swapchain::swapchain_images",
            &["self", "created", "swapchain"],
        ),
        ..NONE
    },
];
