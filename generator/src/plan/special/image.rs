//! The special-case rows of one concern; their functions are the `tuff` crate's
//! `special/image.rs`, and a row here calls no other (but the image-layout tracker).
//!
//! Images: creation (type, format and usage limits, sharing, sparse residency, swapchain
//! and Y'CbCr rules) and the record the device keeps of each.

use super::{call, How, Special, NONE, UNPROVEN};

const SAMPLE_COUNTS: &str = "checks the sample count against the format's sample counts for the type, usage and tiling, queried from the physical device (the 1.3.239 layer does not check it: proven by the error alone)";
const IMAGE_EXTERNAL: &str = "checks each external handle type against the external memory properties the physical device reports for the image's parameters and that type (the 1.3.239 layer does not check it: proven by the error alone)";
const IMAGE_CHROMA: &str = "checks a format that needs a sampler Y'CbCr conversion (vk.xml's `chroma`) against the image's levels, samples, type and extent, and a disjoint multi-planar image against the format's features";
const IMAGE_OF_SWAPCHAIN: &str = "checks the image's parameters against the implied image creation parameters of the swapchain, recorded at its creation (the 1.3.239 layer does not check it: proven by the error alone)";
const UNPROVEN_SPARSE_IMAGES: &str = "checked by the safe methods in every build (flags against each other, and the memory of every live sparse buffer and image against sparseAddressSpaceSize, under a lock held until the new image is listed), but no test breaks it: lavapipe 22.3 has no sparseBinding, so a sparse image is refused for the missing feature first";
const IMAGE_RULES: &str = "checks the type, extent, flags, usage and format against each other, the attachment limits, the queue families, the device's physical devices, and a chained stencil usage, format list or external memory struct (before the checks that ask the physical device about the image)";
const FULL_CHAIN: &str = "checks the level count against the levels of a full chain for the extent";
const IMAGE_LIMITS: &str = "checks the create info against its Image Creation Limits, queried from the physical device for its format, type, tiling, usage and flags (with a chained format list, stencil usage and each external handle type, intersected)";

const SUBRESOURCE_LAYOUT: &str = "checks the subresource against the image's tiling, levels, layers and format, recorded at its creation";
const SUBRESOURCE_NO_DEPTH: &str = "a format without depth or stencil is a colour format, whose aspect must be COLOR (04461), or a multi-planar one, whose aspect must be a plane (01581, 01582): an aspect with depth or stencil is refused under those rules, which the checks name (the test breaks this rule with a colour image, and the layer names it beside 04461)";
const UNPROVEN_DEPTH_LAYOUT: &str = "checked by the safe methods in every build (the image's format and tiling, recorded at its creation; read as written, a format with both depth and stencil takes no single aspect), but no test breaks it: lavapipe makes no linear depth or stencil image";
const UNPROVEN_PLANES_LAYOUT: &str = "checked by the safe methods in every build (the image's format and tiling, recorded at its creation), but no test breaks it: lavapipe has no linear multi-planar format";

/// The rows of this concern.
pub(super) const ROWS: &[Special] = &[
    Special {
        command: "vkGetImageSubresourceLayout",
        check_last: call(
            "special::image::subresource_layout_checks",
            &["self", "image", "subresource"],
        ),
        settles: &[
            (
                "VUID-vkGetImageSubresourceLayout-image-07789",
                How::Dynamic(SUBRESOURCE_LAYOUT),
            ),
            (
                "VUID-vkGetImageSubresourceLayout-aspectMask-00997",
                How::Dynamic(SUBRESOURCE_LAYOUT),
            ),
            (
                "VUID-vkGetImageSubresourceLayout-mipLevel-01716",
                How::Dynamic(SUBRESOURCE_LAYOUT),
            ),
            (
                "VUID-vkGetImageSubresourceLayout-arrayLayer-01717",
                How::Dynamic(SUBRESOURCE_LAYOUT),
            ),
            (
                "VUID-vkGetImageSubresourceLayout-format-04461",
                How::Dynamic(SUBRESOURCE_LAYOUT),
            ),
            (
                "VUID-vkGetImageSubresourceLayout-format-04462",
                How::User(UNPROVEN_DEPTH_LAYOUT),
            ),
            (
                "VUID-vkGetImageSubresourceLayout-format-04463",
                How::User(UNPROVEN_DEPTH_LAYOUT),
            ),
            (
                "VUID-vkGetImageSubresourceLayout-format-04464",
                How::Dynamic(SUBRESOURCE_NO_DEPTH),
            ),
            (
                "VUID-vkGetImageSubresourceLayout-format-01581",
                How::User(UNPROVEN_PLANES_LAYOUT),
            ),
            (
                "VUID-vkGetImageSubresourceLayout-format-01582",
                How::User(UNPROVEN_PLANES_LAYOUT),
            ),
        ],
        ..NONE
    },
    Special {
        command: "vkCreateImage",
        check_last: call(
            "special::image::create_image_checks",
            &["self", "create_info"],
        ),
        hold: call(
            "special::image::sparse_image_hold",
            &["self", "create_info"],
        ),
        created: call(
            "special::image::image_created",
            &["self", "created", "create_info"],
        ),
        settles: &[
            (
                "VUID-VkImageCreateInfo-imageType-00956",
                How::Dynamic(IMAGE_RULES),
            ),
            (
                "VUID-VkImageCreateInfo-imageType-00954",
                How::Dynamic(IMAGE_RULES),
            ),
            (
                "VUID-VkImageCreateInfo-usage-00966",
                How::Dynamic(IMAGE_RULES),
            ),
            (
                "VUID-VkImageCreateInfo-samples-02257",
                How::Dynamic(IMAGE_RULES),
            ),
            (
                "VUID-VkImageCreateInfo-flags-01572",
                How::Dynamic(IMAGE_RULES),
            ),
            (
                "VUID-VkImageCreateInfo-format-01577",
                How::Dynamic(IMAGE_RULES),
            ),
            (
                "VUID-VkImageCreateInfo-usage-00964",
                How::Dynamic(IMAGE_RULES),
            ),
            (
                "VUID-VkImageCreateInfo-usage-00965",
                How::Dynamic(IMAGE_RULES),
            ),
            (
                "VUID-VkImageCreateInfo-format-02795",
                How::Dynamic(IMAGE_RULES),
            ),
            (
                "VUID-VkImageCreateInfo-format-02796",
                How::Dynamic(IMAGE_RULES),
            ),
            (
                "VUID-VkImageCreateInfo-format-02797",
                How::Dynamic(IMAGE_RULES),
            ),
            (
                "VUID-VkImageCreateInfo-format-02798",
                How::Dynamic(IMAGE_RULES),
            ),
            (
                "VUID-VkImageCreateInfo-Format-02536",
                How::Dynamic(IMAGE_RULES),
            ),
            (
                "VUID-VkImageCreateInfo-format-02537",
                How::Dynamic(IMAGE_RULES),
            ),
            (
                "VUID-VkImageCreateInfo-flags-04738",
                How::Dynamic(IMAGE_RULES),
            ),
            (
                "VUID-VkImageCreateInfo-mipLevels-00958",
                How::Dynamic(FULL_CHAIN),
            ),
            (
                "VUID-VkImageCreateInfo-imageCreateMaxMipLevels-02251",
                How::Dynamic(IMAGE_LIMITS),
            ),
            (
                "VUID-VkImageCreateInfo-extent-02252",
                How::Dynamic(IMAGE_LIMITS),
            ),
            (
                "VUID-VkImageCreateInfo-extent-02253",
                How::Dynamic(IMAGE_LIMITS),
            ),
            (
                "VUID-VkImageCreateInfo-extent-02254",
                How::Dynamic(IMAGE_LIMITS),
            ),
            // Lavapipe allows every format the levels of its largest extent, so a
            // level count past the format's limit is past the chain too (00958).
            (
                "VUID-VkImageCreateInfo-mipLevels-02255",
                How::User(UNPROVEN),
            ),
            (
                "VUID-VkImageCreateInfo-arrayLayers-02256",
                How::Dynamic(IMAGE_LIMITS),
            ),
            (
                "VUID-VkImageCreateInfo-samples-02258",
                How::Dynamic(IMAGE_LIMITS),
            ),
            (
                "VUID-VkImageCreateInfo-pNext-06722",
                How::Dynamic(IMAGE_RULES),
            ),
            (
                "VUID-VkImageCreateInfo-sharingMode-01420",
                How::Dynamic(IMAGE_RULES),
            ),
            (
                "VUID-VkImageCreateInfo-pNext-01443",
                How::Dynamic(IMAGE_RULES),
            ),
            (
                "VUID-VkImageCreateInfo-pNext-00990",
                How::Dynamic(IMAGE_EXTERNAL),
            ),
            (
                "VUID-VkImageCreateInfo-physicalDeviceCount-01421",
                How::Dynamic(IMAGE_RULES),
            ),
            (
                "VUID-VkImageCreateInfo-flags-02259",
                How::Dynamic(IMAGE_RULES),
            ),
            (
                "VUID-VkImageCreateInfo-format-06410",
                How::Dynamic(IMAGE_CHROMA),
            ),
            (
                "VUID-VkImageCreateInfo-format-06411",
                How::Dynamic(IMAGE_CHROMA),
            ),
            (
                "VUID-VkImageCreateInfo-format-06412",
                How::Dynamic(IMAGE_CHROMA),
            ),
            (
                "VUID-VkImageCreateInfo-format-04712",
                How::Dynamic(IMAGE_CHROMA),
            ),
            (
                "VUID-VkImageCreateInfo-format-04713",
                How::Dynamic(IMAGE_CHROMA),
            ),
            (
                "VUID-VkImageCreateInfo-imageCreateFormatFeatures-02260",
                How::Dynamic(IMAGE_CHROMA),
            ),
            (
                "VUID-VkImageCreateInfo-format-02538",
                How::Dynamic(IMAGE_RULES),
            ),
            (
                "VUID-VkImageSwapchainCreateInfoKHR-swapchain-00995",
                How::Dynamic(IMAGE_OF_SWAPCHAIN),
            ),
            (
                "VUID-vkCreateImage-flags-00939",
                How::User(UNPROVEN_SPARSE_IMAGES),
            ),
            (
                "VUID-VkImageCreateInfo-None-01925",
                How::User(UNPROVEN_SPARSE_IMAGES),
            ),
            (
                "VUID-VkImageCreateInfo-None-01891",
                How::User(UNPROVEN_SPARSE_IMAGES),
            ),
        ],
        ..NONE
    },
    Special {
        command: "vkGetPhysicalDeviceSparseImageFormatProperties",
        check_last: call(
            "special::image::sparse_samples",
            &[
                "self",
                "(format, ty, samples, usage, tiling)",
                "\"VUID-vkGetPhysicalDeviceSparseImageFormatProperties-samples-01094\"",
            ],
        ),
        settles: &[(
            "VUID-vkGetPhysicalDeviceSparseImageFormatProperties-samples-01094",
            How::Dynamic(SAMPLE_COUNTS),
        )],
        ..NONE
    },
    Special {
        command: "vkGetPhysicalDeviceSparseImageFormatProperties2",
        check_last: call("special::image::sparse_samples2", &["self", "format_info"]),
        settles: &[(
            "VUID-VkPhysicalDeviceSparseImageFormatInfo2-samples-01095",
            How::Dynamic(SAMPLE_COUNTS),
        )],
        ..NONE
    },
];
