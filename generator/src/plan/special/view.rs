//! The special-case rows of one concern; their functions are the `tuff` crate's
//! `special/view.rs`, and a row here calls no other (but the image-layout tracker).
//!
//! Image and buffer views: each view's creation against the image or buffer it views.

use super::{call, How, Special, NONE};

const UNPROVEN_CONVERSION: &str = "checked by the safe methods in every build (the format's components and numeric format, from the registry's formats, and its potential format features, read from the physical device), but no test breaks it: lavapipe 22.3 has no samplerYcbcrConversion feature, so no conversion can be made";

const UNPROVEN_VIEW_PLANES: &str = "checked by the safe methods in every build (against the image's format, its planes and chroma from vk.xml's <formats>, and a chained conversion's recorded format), but no test breaks it: lavapipe 22.3 supports no multi-planar or Y'CbCr format";
const UNPROVEN_SPARSE_VIEW: &str = "checked by the safe methods in every build (the image's recorded flags), but no test breaks it: lavapipe 22.3 has no sparseBinding";
const UNPROVEN_CUBE_ARRAY: &str = "checked by the safe methods in every build (the layers left from the base layer), but no test breaks it: the tests' device does not enable imageCubeArray, so a cube array view is refused for the feature first";
const UNPROVEN_VIEW_FEATURES: &str = "checked by the safe methods in every build (the view's usage against the format features the physical device reports for the image's tiling), but no test breaks it: no compatible view format the tests found lacks the feature its usage needs on lavapipe where the image's own format has it";
const VIEW_RANGE: &str = "checks the subresource range's aspects, levels and layers against the image's type, flags, extent and layer count, recorded at its creation";
const VIEW_TYPE: &str = "checks the view type against the image's type, flags, usage and sample count, recorded at its creation";
const VIEW_FORMAT: &str = "checks the view's format against the image's (its compatibility class, block size, plane formats and listed view formats, recorded at its creation, from vk.xml's <formats>), its chroma against the image's extent, and a chained Y'CbCr conversion's format and the swizzle";
const VIEW_USAGE: &str = "checks the view's usage (chained, or the image's or its stencil usage, as the specification derives it) against the image's and against the format features the physical device reports for the image's tiling";

const BUFFER_VIEW: &str = "checks the view against its buffer's usage and size, recorded at its creation, the buffer features of its format, and the device's maxTexelBufferElements and minTexelBufferOffsetAlignment";
const RELAXED_ALIGNMENT: &str = "checked by the safe methods in every build (the offset against minTexelBufferOffsetAlignment, a multiple of the relaxed alignments texelBufferAlignment allows, which are powers of two no larger; a program relying on the relaxed alignment is refused, as the feature is not followed), but no test breaks it: the tests' device does not enable texelBufferAlignment";

/// The rows of this concern.
pub(super) const ROWS: &[Special] = &[
    Special {
        command: "vkCreateBufferView",
        check_last: call(
            "special::view::buffer_view_checks",
            &["self", "create_info"],
        ),
        settles: &[
            (
                "VUID-VkBufferViewCreateInfo-buffer-00932",
                How::Dynamic(BUFFER_VIEW),
            ),
            (
                "VUID-VkBufferViewCreateInfo-buffer-00933",
                How::Dynamic(BUFFER_VIEW),
            ),
            (
                "VUID-VkBufferViewCreateInfo-buffer-00934",
                How::Dynamic(BUFFER_VIEW),
            ),
            (
                "VUID-VkBufferViewCreateInfo-range-00929",
                How::Dynamic(BUFFER_VIEW),
            ),
            (
                "VUID-VkBufferViewCreateInfo-range-00930",
                How::Dynamic(BUFFER_VIEW),
            ),
            (
                "VUID-VkBufferViewCreateInfo-range-04059",
                How::Dynamic(BUFFER_VIEW),
            ),
            (
                "VUID-VkBufferViewCreateInfo-offset-02749",
                How::Dynamic(BUFFER_VIEW),
            ),
            (
                "VUID-VkBufferViewCreateInfo-buffer-02750",
                How::User(RELAXED_ALIGNMENT),
            ),
            (
                "VUID-VkBufferViewCreateInfo-buffer-02751",
                How::User(RELAXED_ALIGNMENT),
            ),
        ],
        created: call(
            "special::view::buffer_view_created",
            &["self", "created", "create_info"],
        ),
        ..NONE
    },
    Special {
        command: "vkCreateImageView",
        check_last: call("special::view::image_view_checks", &["self", "create_info"]),
        created: call(
            "special::view::image_view_created",
            &["self", "created", "create_info"],
        ),
        settles: &[
            (
                "VUID-VkImageSubresourceRange-aspectMask-01670",
                How::User(UNPROVEN_VIEW_PLANES),
            ),
            (
                "VUID-VkImageViewCreateInfo-subresourceRange-07818",
                How::User(UNPROVEN_VIEW_PLANES),
            ),
            (
                "VUID-VkImageViewCreateInfo-image-01003",
                How::Dynamic(VIEW_TYPE),
            ),
            (
                "VUID-VkImageViewCreateInfo-image-04441",
                How::Dynamic(VIEW_TYPE),
            ),
            (
                "VUID-VkImageViewCreateInfo-subResourceRange-01021",
                How::Dynamic(VIEW_TYPE),
            ),
            (
                "VUID-VkImageViewCreateInfo-image-06723",
                How::Dynamic(VIEW_TYPE),
            ),
            (
                "VUID-VkImageViewCreateInfo-image-06727",
                How::Dynamic(VIEW_TYPE),
            ),
            (
                "VUID-VkImageViewCreateInfo-image-04970",
                How::Dynamic(VIEW_RANGE),
            ),
            (
                "VUID-VkImageViewCreateInfo-image-04971",
                How::User(UNPROVEN_SPARSE_VIEW),
            ),
            (
                "VUID-VkImageViewCreateInfo-image-04972",
                How::Dynamic(VIEW_TYPE),
            ),
            (
                "VUID-VkImageViewCreateInfo-image-02724",
                How::Dynamic(VIEW_RANGE),
            ),
            (
                "VUID-VkImageViewCreateInfo-subresourceRange-02725",
                How::Dynamic(VIEW_RANGE),
            ),
            (
                "VUID-VkImageViewCreateInfo-image-01482",
                How::Dynamic(VIEW_RANGE),
            ),
            (
                "VUID-VkImageViewCreateInfo-subresourceRange-01483",
                How::Dynamic(VIEW_RANGE),
            ),
            (
                "VUID-VkImageViewCreateInfo-imageViewType-04973",
                How::Dynamic(VIEW_RANGE),
            ),
            (
                "VUID-VkImageViewCreateInfo-imageViewType-04974",
                How::Dynamic(VIEW_RANGE),
            ),
            (
                "VUID-VkImageViewCreateInfo-viewType-02962",
                How::Dynamic(VIEW_RANGE),
            ),
            (
                "VUID-VkImageViewCreateInfo-viewType-02963",
                How::User(UNPROVEN_CUBE_ARRAY),
            ),
            (
                "VUID-VkImageViewCreateInfo-image-01761",
                How::Dynamic(VIEW_FORMAT),
            ),
            (
                "VUID-VkImageViewCreateInfo-image-01583",
                How::Dynamic(VIEW_FORMAT),
            ),
            (
                "VUID-VkImageViewCreateInfo-image-07072",
                How::Dynamic(VIEW_FORMAT),
            ),
            (
                "VUID-VkImageViewCreateInfo-pNext-01585",
                How::Dynamic(VIEW_FORMAT),
            ),
            (
                "VUID-VkImageViewCreateInfo-image-01586",
                How::User(UNPROVEN_VIEW_PLANES),
            ),
            (
                "VUID-VkImageViewCreateInfo-image-01762",
                How::Dynamic(VIEW_FORMAT),
            ),
            (
                "VUID-VkImageViewCreateInfo-format-04714",
                How::User(UNPROVEN_VIEW_PLANES),
            ),
            (
                "VUID-VkImageViewCreateInfo-format-04715",
                How::User(UNPROVEN_VIEW_PLANES),
            ),
            (
                "VUID-VkImageViewCreateInfo-pNext-01970",
                How::User(UNPROVEN_VIEW_PLANES),
            ),
            (
                "VUID-VkImageViewCreateInfo-pNext-06658",
                How::User(UNPROVEN_VIEW_PLANES),
            ),
            (
                "VUID-VkImageViewCreateInfo-format-06415",
                How::User(UNPROVEN_VIEW_PLANES),
            ),
            (
                "VUID-VkImageViewCreateInfo-pNext-02662",
                How::Dynamic(VIEW_USAGE),
            ),
            (
                "VUID-VkImageViewCreateInfo-pNext-02663",
                How::Dynamic(VIEW_USAGE),
            ),
            (
                "VUID-VkImageViewCreateInfo-pNext-02664",
                How::Dynamic(VIEW_USAGE),
            ),
            (
                "VUID-VkImageViewCreateInfo-None-02273",
                How::User(UNPROVEN_VIEW_FEATURES),
            ),
            (
                "VUID-VkImageViewCreateInfo-usage-02274",
                How::User(UNPROVEN_VIEW_FEATURES),
            ),
            (
                "VUID-VkImageViewCreateInfo-usage-02275",
                How::Dynamic(VIEW_USAGE),
            ),
            (
                "VUID-VkImageViewCreateInfo-usage-02276",
                How::User(UNPROVEN_VIEW_FEATURES),
            ),
            (
                "VUID-VkImageViewCreateInfo-usage-02277",
                How::User(UNPROVEN_VIEW_FEATURES),
            ),
            (
                "VUID-VkImageViewCreateInfo-usage-02652",
                How::User(UNPROVEN_VIEW_FEATURES),
            ),
        ],
        ..NONE
    },
    Special {
        command: "vkCreateSamplerYcbcrConversion",
        check_last: call(
            "special::view::sampler_ycbcr_conversion_checks",
            &["self", "create_info"],
        ),
        settles: &[
            (
                "VUID-VkSamplerYcbcrConversionCreateInfo-format-04060",
                How::User(UNPROVEN_CONVERSION),
            ),
            (
                "VUID-VkSamplerYcbcrConversionCreateInfo-format-01650",
                How::User(UNPROVEN_CONVERSION),
            ),
            (
                "VUID-VkSamplerYcbcrConversionCreateInfo-xChromaOffset-01651",
                How::User(UNPROVEN_CONVERSION),
            ),
            (
                "VUID-VkSamplerYcbcrConversionCreateInfo-xChromaOffset-01652",
                How::User(UNPROVEN_CONVERSION),
            ),
            (
                "VUID-VkSamplerYcbcrConversionCreateInfo-components-02581",
                How::User(UNPROVEN_CONVERSION),
            ),
            (
                "VUID-VkSamplerYcbcrConversionCreateInfo-components-02582",
                How::User(UNPROVEN_CONVERSION),
            ),
            (
                "VUID-VkSamplerYcbcrConversionCreateInfo-components-02583",
                How::User(UNPROVEN_CONVERSION),
            ),
            (
                "VUID-VkSamplerYcbcrConversionCreateInfo-components-02584",
                How::User(UNPROVEN_CONVERSION),
            ),
            (
                "VUID-VkSamplerYcbcrConversionCreateInfo-components-02585",
                How::User(UNPROVEN_CONVERSION),
            ),
            (
                "VUID-VkSamplerYcbcrConversionCreateInfo-ycbcrModel-01655",
                How::User(UNPROVEN_CONVERSION),
            ),
            (
                "VUID-VkSamplerYcbcrConversionCreateInfo-ycbcrRange-02748",
                How::User(UNPROVEN_CONVERSION),
            ),
            (
                "VUID-VkSamplerYcbcrConversionCreateInfo-forceExplicitReconstruction-01656",
                How::User(UNPROVEN_CONVERSION),
            ),
            (
                "VUID-VkSamplerYcbcrConversionCreateInfo-chromaFilter-01657",
                How::User(UNPROVEN_CONVERSION),
            ),
        ],
        created: call(
            "special::view::conversion_created",
            &["self", "created", "create_info"],
        ),
        ..NONE
    },
];
