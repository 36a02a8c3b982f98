//! The oracle's cases: for each recognised rule of a struct that `tests/oracle.rs`
//! has a fixture for, the change to that fixture's smallest valid value that breaks
//! exactly that rule, derived from the rule's check.
//!
//! The test runs each case twice: through the safe method, which must refuse it with
//! the rule's VUID, and through the `_unchecked` twin under the validation layer,
//! which must name the same VUID or nothing (the rule is then proven by the error
//! alone). A recognised rule is reported as dynamically settled only when it has a
//! case here; the others are checked in every build but counted as the user's.

use super::checks::Checker;
use super::Context;
use crate::model::Model;
use crate::validity::explicit::{FormatClass, Object, Op, Pred, Recognised, Rhs, Value};

/// The array elements `tests/oracle.rs`'s `Objects` keeps, by the name a case gives
/// them (the element's type in snake case, and the array's name where the item has
/// more than one array of that type).
pub const ELEMENT_FIXTURES: &[&str] = &[
    "buffer_copy2",
    "image_copy",
    "image_copy2",
    "buffer_image_copy",
    "buffer_image_copy2",
    "image_blit",
    "image_blit2",
    "image_resolve",
    "image_resolve2",
    "image_subresource_range",
    "attachment_reference_color_attachments",
    "attachment_reference2_color_attachments",
    "clear_rect",
];

/// The structs and commands `tests/oracle.rs` has a fixture for: a smallest valid
/// value and the safe call (and its `_unchecked` twin) that takes it. A struct's
/// fixture function is its name in snake case without `Vk`; a command's is its
/// method's name, over an `args::` struct of the parameters a rule can name.
pub const FIXTURES: &[&str] = &[
    "VkBufferCreateInfo",
    "VkDebugUtilsObjectNameInfoEXT",
    "VkImageCreateInfo",
    "VkSamplerCreateInfo",
    "VkMemoryBarrier2",
    "VkBufferMemoryBarrier2",
    "VkImageMemoryBarrier2",
    "VkDescriptorPoolCreateInfo",
    "VkDescriptorPoolSize",
    "VkPushConstantRange",
    "VkQueryPoolCreateInfo",
    "VkSubpassDependency",
    "VkSubpassDependency2",
    "VkAttachmentDescription",
    "VkAttachmentDescription2",
    "VkSubpassDescription",
    "VkSubpassDescription2",
    "VkPipelineColorBlendAttachmentState",
    "VkPipelineColorBlendStateCreateInfo",
    "VkPipelineRasterizationStateCreateInfo",
    "VkPipelineMultisampleStateCreateInfo",
    "VkVertexInputBindingDescription",
    "VkImageViewCreateInfo",
    "VkFramebufferCreateInfo",
    "VkCopyBufferInfo2",
    "VkCopyImageInfo2",
    "VkBlitImageInfo2",
    "VkCopyBufferToImageInfo2",
    "VkCopyImageToBufferInfo2",
    "vkCmdSetEvent",
    "vkCmdResetEvent",
    "vkCmdResetEvent2",
    "vkCmdWaitEvents",
    "vkCmdPipelineBarrier",
    "vkCmdWriteTimestamp",
    "vkCmdClearColorImage",
    "vkCmdCopyImage",
    "vkCmdCopyBufferToImage",
    "vkCmdCopyImageToBuffer",
    "vkCmdBlitImage",
    "vkCmdDrawIndirect",
    "vkCmdDrawIndexedIndirect",
    "vkCmdDispatchIndirect",
    "vkCmdResolveImage",
    "VkResolveImageInfo2",
    "vkCmdCopyQueryPoolResults",
    "VkBufferViewCreateInfo",
    "VkBufferMemoryBarrier",
    "VkImageMemoryBarrier",
    "VkDescriptorBufferInfo",
    "VkImageSubresourceRange",
    "VkAttachmentReference",
    "VkAttachmentReference2",
    "VkViewport",
    "VkImageCopy",
    "VkImageCopy2",
    "VkBufferImageCopy",
    "VkBufferImageCopy2",
    "VkImageSubresourceLayers",
    "vkCmdDispatch",
    "vkCmdDispatchBase",
    "vkCmdSetDepthBounds",
    "VkSemaphoreTypeCreateInfo",
    "vkCmdDrawIndirectCount",
    "vkCmdDrawIndexedIndirectCount",
    "vkCmdSetLineWidth",
    "vkCmdSetDepthBias",
    "vkCmdPipelineBarrier2",
    "vkCmdSetEvent2",
    "vkCmdWaitEvents2",
    "vkCmdWriteTimestamp2",
    "vkCreatePrivateDataSlot",
    "vkCmdClearAttachments",
    "VkClearAttachment",
    "vkCmdClearDepthStencilImage",
    "VkClearDepthStencilValue",
    "vkResetQueryPool",
    "vkCmdBeginRendering",
    "VkRenderingInfo",
    "VkGraphicsPipelineCreateInfo",
    "VkComputePipelineCreateInfo",
    "VkPipelineDepthStencilStateCreateInfo",
    "VkPipelineCacheCreateInfo",
    "VkShaderModuleCreateInfo",
    "VkMemoryAllocateInfo",
    "VkDescriptorSetLayoutBinding",
    "VkImageStencilUsageCreateInfo",
    "VkInputAttachmentAspectReference",
    "VkAttachmentDescriptionStencilLayout",
    "VkAttachmentReferenceStencilLayout",
    "VkCommandBufferInheritanceInfo",
    "VkCommandBufferInheritanceRenderingInfo",
    "vkQueueSubmit2",
    "VkSemaphoreSubmitInfo",
    "VkDeviceGroupCommandBufferBeginInfo",
    "vkCmdSetDeviceMask",
    "VkDeviceGroupRenderPassBeginInfo",
];

/// Rules whose case runs on the full device (every feature the physical device has
/// enabled): on the fixtures' device, its change also breaks a rule of a feature
/// that device leaves off. Each with the feature.
pub const ON_FULL: &[(&str, &str)] = &[
    (
        "VUID-VkSamplerCreateInfo-anisotropyEnable-01071",
        "samplerAnisotropy",
    ),
    (
        "VUID-VkSamplerCreateInfo-unnormalizedCoordinates-01076",
        "samplerAnisotropy",
    ),
    (
        "VUID-VkImageViewCreateInfo-viewType-02961",
        "imageCubeArray",
    ),
    (
        "VUID-VkAttachmentDescription-format-03286",
        "separateDepthStencilLayouts",
    ),
    (
        "VUID-VkAttachmentDescription-format-03287",
        "separateDepthStencilLayouts",
    ),
    (
        "VUID-VkAttachmentDescription-format-03290",
        "separateDepthStencilLayouts",
    ),
    (
        "VUID-VkAttachmentDescription-format-03291",
        "separateDepthStencilLayouts",
    ),
    (
        "VUID-VkAttachmentDescription-format-03292",
        "separateDepthStencilLayouts",
    ),
    (
        "VUID-VkAttachmentDescription-format-03293",
        "separateDepthStencilLayouts",
    ),
    (
        "VUID-VkAttachmentDescription2-format-03286",
        "separateDepthStencilLayouts",
    ),
    (
        "VUID-VkAttachmentDescription2-format-03287",
        "separateDepthStencilLayouts",
    ),
    (
        "VUID-VkAttachmentDescription2-format-03290",
        "separateDepthStencilLayouts",
    ),
    (
        "VUID-VkAttachmentDescription2-format-03291",
        "separateDepthStencilLayouts",
    ),
    (
        "VUID-VkSubpassDescription-attachment-06919",
        "separateDepthStencilLayouts",
    ),
    (
        "VUID-VkSubpassDescription2-attachment-06919",
        "separateDepthStencilLayouts",
    ),
];

/// Rules of fixture structs whose case the IR cannot build as one change, with why.
pub const SKIP: &[(&str, &str)] = &[
    ("VUID-VkMemoryBarrier2-srcAccessMask-07454", SHADER_READ_STAGES),
    ("VUID-VkMemoryBarrier2-dstAccessMask-07454", SHADER_READ_STAGES),
    ("VUID-VkBufferMemoryBarrier2-srcAccessMask-07454", SHADER_READ_STAGES),
    ("VUID-VkBufferMemoryBarrier2-dstAccessMask-07454", SHADER_READ_STAGES),
    ("VUID-VkImageMemoryBarrier2-srcAccessMask-07454", SHADER_READ_STAGES),
    ("VUID-VkImageMemoryBarrier2-dstAccessMask-07454", SHADER_READ_STAGES),
    ("VUID-VkBufferCreateInfo-flags-00916", SPARSE),
    ("VUID-VkBufferCreateInfo-flags-00918", SPARSE),
    ("VUID-VkImageMemoryBarrier2-synchronization2-07793", BARRIER2_BARE),
    ("VUID-VkImageMemoryBarrier2-synchronization2-07794", BARRIER2_BARE),
    ("VUID-VkImageCreateInfo-flags-00987", SPARSE),
    ("VUID-VkImageCreateInfo-flags-01573", "a block-texel-view-compatible image also needs a compressed format (`flags-01572`), which the fixture's RGBA8 image is not"),
    ("VUID-VkBufferCreateInfo-flags-00917", SPARSE),
    ("VUID-VkImageCreateInfo-flags-01924", SPARSE),
    ("VUID-VkImageCreateInfo-tiling-04121", SPARSE),
    ("VUID-VkImageCreateInfo-imageType-00970", SPARSE),
    ("VUID-VkImageCreateInfo-imageType-00971", SPARSE),
    ("VUID-VkImageCreateInfo-imageType-00972", SPARSE),
    ("VUID-VkImageCreateInfo-imageType-00973", SPARSE),
    ("VUID-VkImageCreateInfo-imageType-00974", SPARSE),
    ("VUID-VkImageCreateInfo-imageType-00975", SPARSE),
    ("VUID-VkImageCreateInfo-imageType-00976", SPARSE),
    ("VUID-VkImageCreateInfo-extent-00946", "a depth of 0 also breaks `imageType-00957` (a 2D image has depth 1), and the fixture's image is 2D"),
    ("VUID-VkImageCreateInfo-flags-00949", ONE_D),
    ("VUID-VkImageCreateInfo-flags-00950", ONE_D),
    ("VUID-VkPushConstantRange-size-00298", "a size past the limit by one is not a multiple of 4 (`size-00297`), and an offset past it by one not one either (`offset-00295`)"),
    ("VUID-VkImageSubresourceLayers-aspectMask-00168", "the metadata aspect is not an aspect of the fixture's color image, which the copy's aspect rule (`aspectMask-00142`) refuses first"),
    ("VUID-VkViewport-y-01776", "a `y` past the upper bound puts `y + height` past it too (`y-01233`), which is checked first"),
    ("VUID-VkViewport-y-01777", "a `y + height` below the lower bound puts `y` below it too (`y-01775`), which is checked first"),
    ("VUID-VkPushConstantRange-offset-00294", "an offset at the limit leaves no room for a size, so `size-00298` breaks as well"),
    ("VUID-VkPipelineInputAssemblyStateCreateInfo-topology-00430", "a patch list without tessellation shaders also breaks `VkGraphicsPipelineCreateInfo-topology-00737`"),
    ("VUID-vkCmdWriteTimestamp2-stage-03929", ONE_STAGE),
    ("VUID-vkCmdWriteTimestamp2-stage-03930", ONE_STAGE),
    ("VUID-VkFramebufferCreateInfo-width-00886", PAST_ATTACHMENT),
    ("VUID-VkFramebufferCreateInfo-height-00888", PAST_ATTACHMENT),
    ("VUID-VkFramebufferCreateInfo-layers-00890", PAST_ATTACHMENT),
    ("VUID-VkImageViewCreateInfo-viewType-01004", "a cube-array view of the fixture's one layer also breaks `viewType-02961` (a multiple of six layers)"),
    ("VUID-VkImageViewCreateInfo-subresourceRange-01478", "a base level at the image's level count also puts base plus count past it, which breaks `subresourceRange-01718` as well"),
    ("VUID-VkImageMemoryBarrier2-subresourceRange-01486", "a base level at the image's level count also puts base plus count past it, which breaks `subresourceRange-01724` as well"),
    ("VUID-VkImageMemoryBarrier-subresourceRange-01486", "as for `VkImageMemoryBarrier2`: `subresourceRange-01724` breaks as well"),
    ("VUID-VkImageMemoryBarrier-subresourceRange-01488", "as for `VkImageMemoryBarrier2`: the 1.3.239 layer throws a C++ exception on it"),
    ("VUID-VkImageMemoryBarrier2-subresourceRange-01488", "the 1.3.239 validation layer throws a C++ exception (which aborts the test) on a barrier whose layer is past the image's"),
    ("VUID-vkCmdDrawIndirect-drawCount-02719", MULTI_DRAW),
    ("VUID-vkCmdDrawIndexedIndirect-drawCount-02719", MULTI_DRAW),
    ("VUID-VkCopyImageToBufferInfo2-imageSubresource-01703", LAYER_RENAMES),
    ("VUID-VkCopyImageToBufferInfo2-imageOffset-00197", LAYER_RENAMES),
    ("VUID-VkCopyImageToBufferInfo2-imageOffset-00198", LAYER_RENAMES),
    ("VUID-VkCopyImageToBufferInfo2-imageOffset-00200", LAYER_RENAMES),
    ("VUID-VkSubpassDescription-attachment-06912", NO_INPUT),
    ("VUID-VkSubpassDescription-attachment-06918", NO_INPUT),
    ("VUID-VkSubpassDescription-attachment-06914", NO_RESOLVE),
    ("VUID-VkSubpassDescription-attachment-06917", NO_RESOLVE),
    ("VUID-VkSubpassDescription-attachment-06920", NO_RESOLVE),
    ("VUID-VkSubpassDescription2-attachment-06912", NO_INPUT),
    ("VUID-VkSubpassDescription2-attachment-06918", NO_INPUT),
    ("VUID-VkSubpassDescription2-attachment-06914", NO_RESOLVE),
    ("VUID-VkSubpassDescription2-attachment-06917", NO_RESOLVE),
    ("VUID-VkSubpassDescription2-attachment-06920", NO_RESOLVE),
    ("VUID-VkImageMemoryBarrier2-subresourceRange-01725", LAYER_THROWS),
    ("VUID-VkImageMemoryBarrier-subresourceRange-01725", LAYER_THROWS),
    ("VUID-VkSubpassDependency-dependencyFlags-02521", FROM_EXTERNAL),
    ("VUID-VkSubpassDependency2-dependencyFlags-03091", FROM_EXTERNAL),
    ("VUID-VkSubpassDependency2-dependencyFlags-03090", "a view-local dependency in a render pass without multiview also breaks `VkRenderPassCreateInfo2-viewMask-03059`, which the layer reports instead"),
    ("VUID-VkBufferViewCreateInfo-offset-00931", "a range past the buffer's end by less than a texel also breaks `range-00929` (a whole number of texels), and an offset past it breaks the offset's alignment"),
    ("VUID-vkCmdClearColorImage-pRanges-01692", RANGE_BASE),
    ("VUID-vkCmdClearDepthStencilImage-pRanges-01694", RANGE_BASE),
    ("VUID-vkCmdClearDepthStencilImage-pRanges-01695", RANGE_BASE),
    ("VUID-vkCmdClearColorImage-pRanges-01693", RANGE_BASE),
    ("VUID-VkAttachmentDescription-format-06700", COLOR_REFERENCE),
    ("VUID-VkAttachmentDescription2-format-03292", DEPTH_LAYOUTS),
    ("VUID-VkAttachmentDescription2-format-03293", DEPTH_LAYOUTS),
    ("VUID-VkAttachmentDescription2-format-06700", COLOR_REFERENCE),
    ("VUID-VkAttachmentReference-separateDepthStencilLayouts-03313", COLOR_REFERENCE_LAYOUT),
    ("VUID-VkAttachmentReference2-separateDepthStencilLayouts-03313", COLOR_REFERENCE_LAYOUT),
    ("VUID-VkVertexInputAttributeDescription-binding-00621", "a binding past the limit has no binding description, so `VkPipelineVertexInputStateCreateInfo-binding-00615` breaks as well"),
];

const BARRIER2_BARE: &str = "on a device without synchronization2, the barrier's command (`vkCmdPipelineBarrier2-synchronization2-03848`) is refused first";
const SHADER_READ_STAGES: &str = "a shader read with a stage mask that runs no shader also breaks `srcAccessMask-03908` (`dstAccessMask-03908`), which the 1.3.239 layer names instead, so its verdict on this rule cannot be told apart";
const LAYER_RENAMES: &str = "the 1.3.239 layer reports this region of `vkCmdCopyImageToBuffer2` under `vkCmdCopyImageToBuffer` VUIDs of other rules (`pRegions-06221`, `06222`, `imageOffset-00200`), so its verdict cannot be told apart";
const LAYER_THROWS: &str = "the 1.3.239 validation layer throws a C++ exception (which aborts the test) on a barrier whose layers run past the image's";
const FROM_EXTERNAL: &str = "the fixture's dependency comes from `VK_SUBPASS_EXTERNAL`, so the view-local flag breaks the rule on `srcSubpass` first";
const RANGE_BASE: &str = "a range is an element, so its case moves the base past the end, which breaks the rule that the base lies inside (`baseMipLevel-01470`, `baseArrayLayer-01472`) too";
const DEPTH_LAYOUTS: &str = "the layouts the rule forbids are depth-only or stencil-only ones, which without `separateDepthStencilLayouts` (off on the fixtures' device) break `separateDepthStencilLayouts-03284` or `03285` too";
const COLOR_REFERENCE: &str = "the fixture's attachment is its subpass's color attachment, which a depth/stencil format cannot be (`VkSubpassDescription-pColorAttachments-02648`)";
const COLOR_REFERENCE_LAYOUT: &str = "the fixture's reference is its subpass's color attachment, and the depth-only layouts the rule forbids without the feature a color attachment may not have either (`VkSubpassDescription-attachment-06919`, checked first)";
const NO_INPUT: &str = "the fixture's subpass has no input attachment, and one needs a descriptor-free input the test pipelines lack";
const NO_RESOLVE: &str = "the fixture's subpass has no resolve attachment, which needs a multisampled color attachment to resolve";
const SPARSE: &str = "setting a sparse residency or aliased bit needs `SPARSE_BINDING` too, which breaks the `sparseBinding` rule as well on a device without sparse features";
const PAST_ATTACHMENT: &str = "a framebuffer larger than the limit is larger than its attachment too, which breaks `flags-04533` (or `04534`, `04535`) as well";
const MULTI_DRAW: &str = "a draw count past the limit is more than one draw, which breaks `drawCount-02718` as well on a device without `multiDrawIndirect`";
const ONE_STAGE: &str = "the stage is a single bit; the case adds the forbidden one to the fixture's, which breaks `stage-03859` as well";
const ONE_D: &str = "the other image type the case picks is 1D, and the fixture's 4x4 image breaks `imageType-00956` (a 1D image has height 1) as well";

/// One change to a fixture's value.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Assign {
    /// Set these bits of a flags member (`|=`).
    SetBits {
        /// The member path.
        member: String,
        /// The flags type (`VkImageCreateFlags`).
        ty: String,
        /// The bits.
        bits: u64,
    },
    /// Replace a flags member with exactly these bits.
    Bits {
        /// The member path.
        member: String,
        /// The flags type.
        ty: String,
        /// The bits.
        bits: u64,
    },
    /// Clear these bits of a flags member.
    ClearBits {
        /// The member path.
        member: String,
        /// The flags type.
        ty: String,
        /// The bits.
        bits: u64,
    },
    /// Set an enum member.
    Enum {
        /// The member path.
        member: String,
        /// The enum type.
        ty: String,
        /// The value.
        value: i64,
    },
    /// Add one to a number member.
    Increment {
        /// The member path.
        member: String,
    },
    /// Create the object a handle names without these usage bits.
    ClearUsage {
        /// The handle's path.
        handle: String,
        /// What it names.
        object: Object,
        /// The bits.
        bits: u64,
    },
    /// Create the image a handle names with this `VkImageType`.
    ImageType {
        /// The handle's path.
        handle: String,
        /// The type's value.
        value: i64,
    },
    /// Create the object a handle names without binding memory to it.
    Unbound {
        /// The handle's path.
        handle: String,
    },
    /// Set a `VkBool32` or number member to a Rust expression over `v` (the value),
    /// `l` (the device's limits) and `o` (how the fixture makes its objects).
    Number {
        /// The member path.
        member: String,
        /// The expression.
        expr: String,
    },
}

impl Assign {
    /// The member path the change sets.
    pub fn member(&self) -> &str {
        match self {
            Assign::SetBits { member, .. }
            | Assign::Bits { member, .. }
            | Assign::ClearBits { member, .. }
            | Assign::Enum { member, .. }
            | Assign::Number { member, .. }
            | Assign::Increment { member } => member,
            Assign::ClearUsage { handle, .. }
            | Assign::ImageType { handle, .. }
            | Assign::Unbound { handle } => handle,
        }
    }
}

/// One case: the rule and the changes that break it.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Case {
    /// The rule.
    pub vuid: String,
    /// The struct (the fixture).
    pub item: String,
    /// Whether its ash type has a lifetime (`vk::MemoryBarrier2<'_>`).
    pub lifetime: bool,
    /// The item is a command: the fixture's value is the test's `args::Cmd*`
    /// struct of its parameters.
    pub on_command: bool,
    /// The changes, in order.
    pub assigns: Vec<Assign>,
    /// For a rule about each element of an array, the field of the test's
    /// `Objects` that holds the fixture's one element (`image_copy` for
    /// `VkImageCopy`), which element paths are written to.
    pub element: Option<String>,
    /// The device the case runs on.
    pub device: OnDevice,
}

/// The device a case runs on.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum OnDevice {
    /// The fixtures' device, with [`FIXTURE_FEATURES`] enabled.
    Fixture,
    /// One that enables no feature: the rule applies only with one of
    /// [`FIXTURE_FEATURES`] off.
    Bare,
    /// One that enables every feature the physical device has: the rule applies
    /// only with a feature on that the fixtures' device leaves off.
    Full,
}

impl Case {
    /// A member path as a Rust place: of the fixture's value `v`, or of its
    /// element in `o`.
    pub fn place(&self, p: &str) -> String {
        path(p, self.on_command, self.element.as_deref())
    }
}

/// The cases of every recognised rule of a fixture struct that some emitted command
/// checks.
pub fn cases(cx: &Context, checker: &Checker) -> Vec<Case> {
    cx.validity
        .recognised
        .iter()
        .filter(|r| FIXTURES.contains(&r.item.as_str()) && checker.dynamic(&r.vuid).is_some())
        .filter(|r| !SKIP.iter().any(|(v, _)| *v == r.vuid))
        .filter_map(|r| case(cx.model, r))
        .map(|c| Case {
            lifetime: cx.facts.has_lifetime(&c.item),
            ..c
        })
        .collect()
}

/// Where a case's paths lead: the item, and the `Objects` field of its element.
struct At<'a> {
    model: &'a Model,
    item: &'a str,
    on_command: bool,
    element: Option<String>,
}

impl At<'_> {
    /// The C type of a member path.
    fn ty(&self, p: &str) -> Option<String> {
        Some(
            crate::validity::explicit::path_field(self.model, self.item, p)?
                .type_name
                .clone(),
        )
    }

    /// A member path as a Rust place.
    fn path(&self, p: &str) -> String {
        path(p, self.on_command, self.element.as_deref())
    }
}

fn case(model: &Model, r: &Recognised) -> Option<Case> {
    let fields = match model.commands.get(&r.item) {
        Some(cmd) => &cmd.params,
        None => &model.types.get(&r.item)?.members,
    };
    // The element is named by its type (`image_copy`), and by its array too where
    // the item has more than one array of that type
    // (`attachment_reference_color_attachments`).
    let element = match &r.check.each {
        Some(each) => {
            let array = format!("{}[]", each.array);
            let f = crate::validity::explicit::path_field(model, &r.item, &array)?;
            let ty = super::checks::snake(&f.type_name);
            let alike = fields
                .iter()
                .filter(|g| g.pointers == 1 && g.len.is_some() && g.type_name == f.type_name)
                .count();
            Some(if alike > 1 {
                format!("{ty}_{}", crate::names::param(&each.array))
            } else {
                ty
            })
        }
        None => None,
    };
    // A rule about elements of an array the fixtures keep no element of has no case.
    if element
        .as_deref()
        .is_some_and(|e| !ELEMENT_FIXTURES.contains(&e))
    {
        return None;
    }
    let at = At {
        model,
        item: &r.item,
        on_command: r.on_command,
        element,
    };
    let mut assigns = Vec::new();
    for p in &r.check.when {
        make_true(&at, p, &mut assigns)?;
    }
    make_false(&at, &r.check.must, &mut assigns)?;
    // The oracle's devices enable no extension: a case that sets a value only an
    // extension defines is refused as that value first.
    if !assigns.iter().all(|a| core_values(model, a)) {
        return None;
    }
    let device = match device_for(r)? {
        OnDevice::Fixture if ON_FULL.iter().any(|(v, _)| *v == r.vuid) => OnDevice::Full,
        d => d,
    };
    // A count that goes with a pointer member is not the fixture's to change: the
    // safe struct's setters keep the two together.
    let counts: Vec<&str> = fields
        .iter()
        .filter_map(|m| m.len.as_deref()?.split(',').next())
        .collect();
    if assigns.iter().any(|a| counts.contains(&a.member())) {
        return None;
    }
    Some(Case {
        vuid: r.vuid.clone(),
        item: r.item.clone(),
        lifetime: false,
        on_command: r.on_command,
        assigns,
        element: at.element,
        device,
    })
}

/// The device a rule's case needs, from the features its conditions and
/// requirement name: the bare one for a feature of the fixtures' device it needs
/// off, the full one for another feature it needs on, or `None` where no device
/// has what it needs.
fn device_for(r: &Recognised) -> Option<OnDevice> {
    let fixture = |name: &str| FIXTURE_FEATURES.contains(&name);
    // (the feature's name, whether the case needs it on)
    let mut needs: Vec<(&str, bool)> = r
        .check
        .when
        .iter()
        .filter_map(|p| match p {
            Pred::Feature { name, enabled, .. } => Some((name.as_str(), *enabled)),
            _ => None,
        })
        .collect();
    if let Pred::Feature { name, enabled, .. } = &r.check.must {
        needs.push((name.as_str(), !*enabled));
    }
    let off_of_fixture = needs.iter().any(|&(n, on)| !on && fixture(n));
    let on_of_fixture = needs.iter().any(|&(n, on)| on && fixture(n));
    let on_other = needs.iter().any(|&(n, on)| on && !fixture(n));
    let off_other = needs.iter().any(|&(n, on)| !on && !fixture(n));
    match (on_other, off_of_fixture) {
        (true, _) => (!off_other && !off_of_fixture).then_some(OnDevice::Full),
        (false, true) => (!on_of_fixture).then_some(OnDevice::Bare),
        (false, false) => Some(OnDevice::Fixture),
    }
}

fn mask(bits: &[Value]) -> u64 {
    bits.iter().fold(0, |acc, b| acc | b.number as u64)
}

/// The core features the fixtures' device enables (`tests/common/tuff_setup.rs`):
/// the tests record `*2` barriers, imageless framebuffers, timeline semaphores,
/// private data, indirect draws with a count, host query resets and dynamic
/// rendering. It enables no Vulkan 1.0 feature.
pub const FIXTURE_FEATURES: &[&str] = &[
    "privateData",
    "synchronization2",
    "imagelessFramebuffer",
    "timelineSemaphore",
    "drawIndirectCount",
    "hostQueryReset",
    "dynamicRendering",
];

/// `VK_IMAGE_TYPE_2D`, the type of the fixtures' images.
const IMAGE_2D: i64 = 1;

/// Changes that make a condition hold: a feature is on or off as the fixtures'
/// device has it, or the case is not made.
fn make_true(at: &At, p: &Pred, out: &mut Vec<Assign>) -> Option<()> {
    match p {
        // The device the case runs on has it as the condition asks (`device_for`).
        Pred::Feature { .. } => {}
        // A format of the kind: one each kind's fixtures can use.
        Pred::FormatIs { member, class } => out.push(Assign::Enum {
            member: member.clone(),
            ty: at.ty(member)?,
            value: representative(*class),
        }),
        // The fixtures use no API constant (`VK_ATTACHMENT_UNUSED`, `VK_WHOLE_SIZE`,
        // `VK_REMAINING_MIP_LEVELS`); a fixture that did would fail its case, not
        // pass it.
        Pred::Compare {
            op: Op::Ne,
            rhs: Rhs::Const(c),
            ..
        } if c.ends_with("::MAX") => {}
        Pred::AnyBit { member, bits } => out.push(Assign::SetBits {
            ty: at.ty(member)?,
            member: member.clone(),
            bits: bits.first()?.number as u64,
        }),
        Pred::NoBit { member, bits } => out.push(Assign::ClearBits {
            ty: at.ty(member)?,
            member: member.clone(),
            bits: mask(bits),
        }),
        // The fixtures' images are 2D; another type is the image made so.
        Pred::ImageType { values, .. } if values.iter().any(|v| v.number == IMAGE_2D) => {}
        Pred::ImageType { handle, values } => out.push(Assign::ImageType {
            handle: handle.clone(),
            value: values.first()?.number,
        }),
        Pred::OneOf { member, values } => out.push(value_of(at, member, values.first()?)?),
        Pred::Compare {
            member,
            op: Op::Eq,
            rhs: Rhs::Const(c),
            float,
            ..
        } => out.push(Assign::Number {
            member: member.clone(),
            expr: crate::validity::explicit::number(c, *float),
        }),
        _ => return None,
    }
    Some(())
}

/// Changes that make a requirement fail.
fn make_false(at: &At, p: &Pred, out: &mut Vec<Assign>) -> Option<()> {
    match p {
        // A member a condition set bits of (`if flags has A, flags must have B`)
        // keeps them and lacks the required ones; another gets one other bit.
        Pred::AnyBit { member, bits } if out.iter().any(|a| a.member() == member) => {
            out.push(Assign::ClearBits {
                ty: at.ty(member)?,
                member: member.clone(),
                bits: mask(bits),
            })
        }
        Pred::AnyBit { member, bits } => {
            let ty = at.ty(member)?;
            let group = at.model.types.get(&ty)?.bit_values.clone()?;
            let other = first_other(at.model, &group, bits, true)?;
            out.push(Assign::Bits {
                member: member.clone(),
                ty,
                bits: other.number as u64,
            });
        }
        Pred::NoBit { member, bits } => out.push(Assign::SetBits {
            ty: at.ty(member)?,
            member: member.clone(),
            bits: bits.first()?.number as u64,
        }),
        Pred::NoneOf { member, values } => out.push(value_of(at, member, values.first()?)?),
        Pred::OneOf { member, values } if crate::validity::explicit::is_bool(values) => {
            // A number outside the list (`drawCount` of 2 for `0 or 1`), or the other
            // `VkBool32`.
            let numbers = values
                .iter()
                .all(|v| v.name.starts_with(|c: char| c.is_ascii_digit()));
            let v = if numbers {
                values.iter().map(|v| v.number).max()? + 1
            } else if values.iter().any(|v| v.number == 1) {
                0
            } else {
                1
            };
            out.push(Assign::Number {
                member: member.clone(),
                expr: v.to_string(),
            });
        }
        Pred::OneOf { member, values } => {
            let ty = at.ty(member)?;
            let other = first_other(at.model, &ty, values, false)?;
            out.push(Assign::Enum {
                member: member.clone(),
                ty,
                value: other.number,
            });
        }
        // The fixtures' images are RGBA8, which has no depth aspect.
        Pred::AspectsIn { member, .. } => out.push(Assign::Bits {
            ty: at.ty(member)?,
            member: member.clone(),
            bits: 0x2,
        }),
        Pred::Usage {
            handle,
            object,
            bits,
        } => out.push(Assign::ClearUsage {
            handle: handle.clone(),
            object: *object,
            bits: mask(bits),
        }),
        Pred::Bound { handle, .. } => out.push(Assign::Unbound {
            handle: handle.clone(),
        }),
        // Of `x and (y + x) must both be in [0, extent]`, break the last: the sum
        // past the level's extent.
        Pred::All(ps) => make_false(at, ps.last()?, out)?,
        // Below minus the limit.
        Pred::AbsAtMost {
            member,
            rhs: Rhs::Limit(l),
        } => out.push(Assign::Number {
            member: member.clone(),
            expr: format!("-({} as f64 + 1.0) as _", limit(l)),
        }),
        // One more than the fixture's value is a multiple of nothing above 1.
        Pred::MultipleOf { member, .. } => out.push(Assign::Increment {
            member: member.clone(),
        }),
        // The fixtures' device lacks every feature it does not list; the bare device
        // (`case`) lacks those too.
        Pred::Feature { enabled: true, .. } => {}
        // `a + b <= n` breaks at `a = n - b + 1`; `a <= n` at `a = n + 1`.
        Pred::Compare {
            member,
            plus,
            op: Op::Le,
            rhs: rhs @ (Rhs::Created { .. } | Rhs::Extent { .. }),
            ..
        } => {
            let bound = match rhs {
                Rhs::Created { handle, field, .. } => format!(
                    "o.{}.{} as i64",
                    crate::names::param(handle),
                    crate::names::field(field)
                ),
                Rhs::Extent { handle, dim, level } => format!(
                    "(o.{}.extent.{} >> {}).max(1) as i64",
                    crate::names::param(handle),
                    crate::names::field(dim),
                    at.path(level)
                ),
                _ => return None,
            };
            // Of `offset + count <= n`, the count goes past: the offset alone past `n`
            // would break the rule that it lies inside too. In a region (an element)
            // the offset goes past instead: its counts are tied to the other image's
            // and to the buffer's size, and its extent is shared by both images.
            let element = member.contains("[]");
            let (set, other) = match (plus, rhs) {
                (Some(p), Rhs::Created { .. }) if !element => (p, Some(member)),
                (p, _) => (member, p.as_ref()),
            };
            let minus = match other {
                Some(p) => format!(" - {} as i64", at.path(p)),
                None => String::new(),
            };
            out.push(Assign::Number {
                member: set.clone(),
                expr: format!("({bound}{minus} + 1) as _"),
            });
        }
        // `a + b <= L` breaks at `a = L - b + 1`, `a + b >= L` at `a = L - b - 1`.
        Pred::Compare {
            member,
            plus: Some(p),
            op: op @ (Op::Le | Op::Ge),
            rhs: Rhs::Limit(l),
            float,
            ..
        } => {
            let (cast, one) = if *float { ("f64", "1.0") } else { ("i64", "1") };
            let sign = if *op == Op::Le { "+" } else { "-" };
            out.push(Assign::Number {
                member: member.clone(),
                expr: format!(
                    "({} as {cast} - {} as {cast} {sign} {one}) as _",
                    limit(l),
                    at.path(p)
                ),
            });
        }
        Pred::Compare {
            member,
            plus: None,
            op: Op::Lt,
            rhs: Rhs::Created { handle, field, .. },
            ..
        } => out.push(Assign::Number {
            member: member.clone(),
            expr: format!(
                "o.{}.{} as _",
                crate::names::param(handle),
                crate::names::field(field)
            ),
        }),
        Pred::Compare {
            member,
            plus: None,
            op,
            rhs,
            float,
            ..
        } => {
            let one = if *float { "1.0" } else { "1" };
            let expr = match (rhs, op) {
                (Rhs::Const(c), Op::Gt | Op::Lt | Op::Ne) => {
                    crate::validity::explicit::number(c, *float)
                }
                (Rhs::Const(c), Op::Le | Op::Eq) => shifted(c, *float, 1)?,
                (Rhs::Const(c), Op::Ge) if c != "0" => shifted(c, *float, -1)?,
                (Rhs::Limit(l), Op::Lt) => format!("{} as _", limit(l)),
                (Rhs::Limit(l), Op::Le) if *float => format!("({} as f64 + 1.0) as _", limit(l)),
                (Rhs::Limit(l), Op::Le) => {
                    format!("({} as u64 + 1) as _", limit(l))
                }
                (Rhs::Limit(l), Op::Gt) => format!("{} as _", limit(l)),
                (Rhs::Limit(l), Op::Ge) if *float => format!("({} as f64 - 1.0) as _", limit(l)),
                (Rhs::Limit(l), Op::Ge) => format!("({} as i64 - 1) as _", limit(l)),
                (Rhs::Member(m), Op::Gt | Op::Lt) => at.path(m),
                (Rhs::Member(m), Op::Ge) => format!("{} - {one}", at.path(m)),
                (Rhs::Member(m), Op::Le | Op::Eq) => format!("{} + {one}", at.path(m)),
                _ => return None,
            };
            out.push(Assign::Number {
                member: member.clone(),
                expr,
            });
        }
        _ => return None,
    }
    Some(())
}

/// A limit of the device's `l`, or an element of an array limit.
fn limit(name: &str) -> String {
    match name.split_once('[') {
        Some((base, index)) => format!("l.{}[{index}", crate::names::field(base)),
        None => format!("l.{}", crate::names::field(name)),
    }
}

/// A format of each kind that lavapipe (and most devices) support:
/// `R8G8B8A8_UNORM`, `D32_SFLOAT_S8_UINT`, `D32_SFLOAT`, `S8_UINT`.
fn representative(class: FormatClass) -> i64 {
    match class {
        FormatClass::Color | FormatClass::ColorOrDepth => 37,
        FormatClass::DepthStencil | FormatClass::DepthAndStencil | FormatClass::Stencil => 130,
        FormatClass::DepthOnly => 126,
        FormatClass::StencilOnly => 127,
    }
}

/// A constant of the text moved by `by`, as a literal of the compared type.
fn shifted(c: &str, float: bool, by: i64) -> Option<String> {
    if float {
        let v: f64 = c.parse().ok()?;
        Some(crate::validity::explicit::number(
            &format!("{}", v + by as f64),
            true,
        ))
    } else {
        let v: i64 = c.parse().ok()?;
        Some((v + by).to_string())
    }
}

/// A member path as a Rust place: `v.extent.width` of the fixture's value (a
/// command's parameter named as the safe method names it), or, for an element's
/// member (`pRegions[].srcOffset.x`), `o.image_copy.src_offset.x` of the element
/// the fixture keeps in its objects.
pub fn path(p: &str, on_command: bool, element: Option<&str>) -> String {
    let field = |s: &str| match s.split_once('[') {
        Some((name, index)) => format!("{}[{index}", crate::names::field(name)),
        None => crate::names::field(s),
    };
    if let (Some((_, rest)), Some(element)) = (p.split_once("[]."), element) {
        let rest: Vec<String> = rest.split('.').map(field).collect();
        return format!("o.{element}.{}", rest.join("."));
    }
    let parts: Vec<String> = p
        .split('.')
        .enumerate()
        .map(|(i, s)| {
            if i == 0 && on_command {
                crate::names::param(s)
            } else {
                field(s)
            }
        })
        .collect();
    format!("v.{}", parts.join("."))
}

fn value_of(at: &At, member: &str, v: &Value) -> Option<Assign> {
    let ty = at.ty(member)?;
    Some(if ty == "VkBool32" {
        Assign::Number {
            member: member.to_owned(),
            expr: v.number.to_string(),
        }
    } else {
        Assign::Enum {
            member: member.to_owned(),
            ty,
            value: v.number,
        }
    })
}

/// Whether the values an assignment sets are all defined by a core version: each
/// bit it sets of a flags member, or the value of an enum member.
fn core_values(model: &Model, a: &Assign) -> bool {
    let core = |group: &str, number: i64| {
        model.enum_values.get(group).is_none_or(|names| {
            names
                .iter()
                .filter(|n| model.enum_numbers.get(*n) == Some(&number))
                .any(|n| {
                    model
                        .enum_origins
                        .get(n)
                        .is_some_and(|o| o.iter().any(|x| x.starts_with("VK_VERSION_")))
                })
        })
    };
    match a {
        Assign::SetBits { ty, bits, .. } | Assign::Bits { ty, bits, .. } => {
            let group = model
                .types
                .get(ty)
                .and_then(|t| t.bit_values.clone())
                .unwrap_or_else(|| ty.replace("Flags", "FlagBits"));
            (0..64)
                .filter(|i| bits & (1u64 << i) != 0)
                .all(|i| core(&group, (1u64 << i) as i64))
        }
        Assign::Enum { ty, value, .. } => core(ty, *value),
        _ => true,
    }
}

/// The first value of a group that a core version defines and the list does not
/// name (for bits, a bit rather than 0).
fn first_other(model: &Model, group: &str, listed: &[Value], bits: bool) -> Option<Value> {
    model
        .enum_values
        .get(group)?
        .iter()
        .filter(|n| {
            model
                .enum_origins
                .get(*n)
                .is_some_and(|o| o.iter().any(|x| x.starts_with("VK_VERSION_")))
        })
        .filter_map(|n| {
            Some(Value {
                name: n.clone(),
                number: *model.enum_numbers.get(n)?,
            })
        })
        .find(|v| {
            !listed.iter().any(|l| l.number == v.number)
                && v.number != 0x7FFF_FFFF
                && (!bits || (v.number as u64).is_power_of_two())
        })
}
