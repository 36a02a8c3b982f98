//! What the device records of render passes: each subpass's attachments, layouts and
//! self-dependencies.

use super::hazards::Barrier;
use super::live::Live;
use ash::vk::{self, Handle as _};
use tuff_runtime::Vrc;

/// A live render pass's subpasses, which the recorder follows an instance of it
/// through.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub(crate) struct RenderPassRecord {
    /// Each attachment's format, sample count and the roles the subpasses give it
    /// (`USED_*` bits).
    pub attachments: Vec<(vk::Format, vk::SampleCountFlags, u8)>,
    /// Each subpass's view mask (0 without multiview), in order.
    pub view_masks: Vec<u32>,
    /// Whether each subpass uses no attachment (every reference unused, or none).
    pub no_attachments: Vec<bool>,
    /// Each subpass's color attachments' formats (`UNDEFINED` for an unused one).
    pub color_formats: Vec<Vec<vk::Format>>,
    /// Each subpass's depth/stencil attachment's format, if it uses one.
    pub depth_formats: Vec<Option<vk::Format>>,
    /// Each subpass's color and depth/stencil attachments' sample count, if it uses
    /// any (its creation checks they agree).
    pub subpass_samples: Vec<Option<vk::SampleCountFlags>>,
    /// Each subpass's depth/stencil reference's layouts (depth aspect, stencil
    /// aspect), if it uses one.
    pub depth_layouts: Vec<Option<(vk::ImageLayout, vk::ImageLayout)>>,
    /// Each attachment's initial and final layouts, and those of its stencil
    /// aspect (the same unless a `VkAttachmentDescriptionStencilLayout` says
    /// otherwise).
    pub layouts: Vec<AttachmentLayouts>,
    /// The attachments each subpass references.
    pub used: Vec<Vec<u32>>,
    /// Each subpass's input attachment references: the attachment each names
    /// (`VK_ATTACHMENT_UNUSED` for an unused one), and the aspects the fragment
    /// shader may read through it (empty: every aspect of its format).
    pub inputs: Vec<Vec<(u32, vk::ImageAspectFlags)>>,
    /// Each subpass's input attachment references: the attachment each names and
    /// the layout the subpass gives it.
    pub input_layouts: Vec<Vec<(u32, vk::ImageLayout)>>,
    /// Its dependencies from a subpass to itself.
    pub self_dependencies: Vec<SelfDependency>,
    /// One more than the largest attachment index that a render pass instance
    /// clears (0: none), the `clearValueCount` it needs at least.
    pub clear_count: u32,
    /// Every layout each attachment takes: initial, final, and in each reference.
    pub taken: Vec<Vec<vk::ImageLayout>>,
    /// The layouts each attachment's stencil aspect takes through
    /// `VkAttachmentDescriptionStencilLayout` and `VkAttachmentReferenceStencilLayout`.
    pub stencil_taken: Vec<Vec<vk::ImageLayout>>,
    /// Each attachment's `VK_ATTACHMENT_DESCRIPTION_MAY_ALIAS_BIT`.
    pub may_alias: Vec<bool>,
    /// The union of the source and of the destination stage masks of its
    /// dependencies.
    pub dependency_stages: (vk::PipelineStageFlags, vk::PipelineStageFlags),
    /// Its dependencies between two of its subpasses (source, destination).
    pub dependencies: Vec<(u32, u32)>,
    /// Made by `vkCreateRenderPass2`.
    pub second: bool,
    /// What each attachment does at the edges of a render pass instance.
    pub boundaries: Vec<Boundary>,
    /// What render pass compatibility compares.
    pub compatibility: Compatibility,
    /// The barriers at an instance's edges, for the hazard tracker.
    pub edges: Edges,
}

/// The barriers at the edges of a render pass instance's subpasses, expanded once
/// at creation (an instance begins every frame): each subpass's dependencies into
/// it, the one its attachments' first layout transitions happen under, and the
/// same out of the render pass.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub(crate) struct Edges {
    /// Each subpass's dependencies into it.
    pub into: Vec<Vec<Barrier>>,
    /// For each subpass, the barrier of the layout transitions of the attachments it
    /// uses first.
    pub first_transitions: Vec<Barrier>,
    /// The dependencies out of the render pass.
    pub out: Vec<Barrier>,
    /// The barrier of the attachments' final layout transitions.
    pub last_transition: Barrier,
}

impl Edges {
    /// The edges of a render pass of `subpasses` subpasses with these dependencies.
    pub(crate) fn of(compatibility: &Compatibility, subpasses: u32) -> Edges {
        // Each dependency whose destination is `dst` (`VK_SUBPASS_EXTERNAL` at the
        // end), only those from outside when `from_outside`, as barriers.
        let dependencies = |dst: u32, from_outside: bool| -> Vec<Barrier> {
            compatibility
                .dependencies
                .iter()
                .filter(|d| d.0 .1 == dst && (!from_outside || d.0 .0 == vk::SUBPASS_EXTERNAL))
                .map(|(_, (ss, ds), (sa, da), _, _)| {
                    Barrier::new(
                        u64::from(ss.as_raw()),
                        u64::from(sa.as_raw()),
                        u64::from(ds.as_raw()),
                        u64::from(da.as_raw()),
                    )
                })
                .collect()
        };
        // A layout transition under several dependencies is ordered by each.
        let merged = |b: Vec<Barrier>| b.into_iter().reduce(|a, b| a.union(&b));
        const TOP: u64 = 0x1;
        const BOTTOM: u64 = 0x2000;
        const ALL_COMMANDS: u64 = 0x10000;
        const ATTACHMENT_ACCESS: u64 = 0x10 | 0x80 | 0x100 | 0x200 | 0x400;
        const ATTACHMENT_WRITES: u64 = 0x100 | 0x400;
        let out = dependencies(vk::SUBPASS_EXTERNAL, false);
        Edges {
            into: (0..subpasses).map(|s| dependencies(s, false)).collect(),
            // Without a dependency from outside, the implicit one, which orders
            // nothing before it (its first scope is TOP_OF_PIPE).
            first_transitions: (0..subpasses)
                .map(|s| {
                    merged(dependencies(s, true))
                        .unwrap_or_else(|| Barrier::new(TOP, 0, ALL_COMMANDS, ATTACHMENT_ACCESS))
                })
                .collect(),
            // Without a dependency out, the implicit one: every attachment write,
            // to BOTTOM_OF_PIPE.
            last_transition: merged(out.clone())
                .unwrap_or_else(|| Barrier::new(ALL_COMMANDS, ATTACHMENT_WRITES, BOTTOM, 0)),
            out,
        }
    }
}

/// What the specification's render pass compatibility compares of a render pass
/// (Render Pass Compatibility): attachment references by their attachments' format
/// and sample count, everything else as it is, but the attachments' layouts and
/// load and store operations and the references' layouts.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub(crate) struct Compatibility {
    /// Its create flags.
    pub flags: vk::RenderPassCreateFlags,
    /// Each attachment's format, sample count and `MAY_ALIAS`.
    pub attachments: Vec<(vk::Format, vk::SampleCountFlags, bool)>,
    /// Each subpass.
    pub subpasses: Vec<SubpassShape>,
    /// Each dependency: its subpasses, stage and access masks, flags and view offset.
    #[allow(clippy::type_complexity)]
    pub dependencies: Vec<(
        (u32, u32),
        (vk::PipelineStageFlags, vk::PipelineStageFlags),
        (vk::AccessFlags, vk::AccessFlags),
        vk::DependencyFlags,
        i32,
    )>,
    /// Its correlated view masks.
    pub correlations: Vec<u32>,
}

/// A subpass as render pass compatibility compares it: each reference by its
/// attachment's format and sample count (`None`: unused; none past the last used
/// one), the rest as it is.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub(crate) struct SubpassShape {
    pub flags: vk::SubpassDescriptionFlags,
    pub bind_point: vk::PipelineBindPoint,
    pub inputs: Vec<Option<(vk::Format, vk::SampleCountFlags)>>,
    /// The aspects each input attachment reference lets the shader read.
    pub input_aspects: Vec<vk::ImageAspectFlags>,
    pub colors: Vec<Option<(vk::Format, vk::SampleCountFlags)>>,
    /// Empty in a render pass of one subpass, which compatibility leaves them out of.
    pub resolves: Vec<Option<(vk::Format, vk::SampleCountFlags)>>,
    pub depth: Option<(vk::Format, vk::SampleCountFlags)>,
    /// The depth/stencil resolve attachment and modes (`None` in a render pass of
    /// one subpass).
    #[allow(clippy::type_complexity)]
    pub depth_resolve: Option<(
        (vk::Format, vk::SampleCountFlags),
        (vk::ResolveModeFlags, vk::ResolveModeFlags),
    )>,
    pub preserve: Vec<u32>,
    pub view_mask: u32,
}

impl RenderPassRecord {
    /// Whether a chain of dependencies leads from subpass `from` to subpass `to`.
    pub(crate) fn depends(&self, from: u32, to: u32) -> bool {
        let mut reached = vec![from];
        let mut next = 0;
        while let Some(&s) = reached.get(next) {
            next += 1;
            if s == to {
                return true;
            }
            for &(a, b) in &self.dependencies {
                if a == s && !reached.contains(&b) {
                    reached.push(b);
                }
            }
        }
        false
    }
}

impl RenderPassRecord {
    /// Whether two render passes are compatible, as the specification defines it
    /// ([`Compatibility`]).
    pub(crate) fn compatible(&self, other: &RenderPassRecord) -> bool {
        self.compatibility == other.compatibility
    }
}

/// A render pass's dependency from a subpass to itself, which a pipeline barrier
/// inside the subpass must fit in.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct SelfDependency {
    /// The subpass.
    pub subpass: u32,
    /// Its source and destination stage masks.
    pub stages: (vk::PipelineStageFlags, vk::PipelineStageFlags),
    /// Its source and destination access masks.
    pub access: (vk::AccessFlags, vk::AccessFlags),
}

/// What an attachment does at the edges of a render pass instance, for the hazard
/// tracker: its load and store operations (color or depth, stencil), and the first
/// and last subpasses that use it with the layouts they give it (color or depth,
/// stencil); `None` for an attachment no subpass uses.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct Boundary {
    pub load: (vk::AttachmentLoadOp, vk::AttachmentLoadOp),
    pub store: (vk::AttachmentStoreOp, vk::AttachmentStoreOp),
    pub first: Option<(u32, vk::ImageLayout, vk::ImageLayout)>,
    pub last: Option<(u32, vk::ImageLayout, vk::ImageLayout)>,
}

/// The layouts a render pass instance needs an attachment in and leaves it in.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct AttachmentLayouts {
    /// `initialLayout`.
    pub initial: vk::ImageLayout,
    /// `finalLayout`.
    pub last: vk::ImageLayout,
    /// The stencil aspect's `initialLayout`.
    pub stencil_initial: vk::ImageLayout,
    /// The stencil aspect's `finalLayout`.
    pub stencil_last: vk::ImageLayout,
}

/// An attachment's role in some subpass: color, resolve, depth/stencil, input, or
/// depth/stencil resolve.
pub(crate) const USED_COLOR: u8 = 1;

/// See [`USED_COLOR`].
pub(crate) const USED_RESOLVE: u8 = 2;

/// See [`USED_COLOR`].
pub(crate) const USED_DEPTH: u8 = 4;

/// See [`USED_COLOR`].
pub(crate) const USED_INPUT: u8 = 8;

/// See [`USED_COLOR`].
pub(crate) const USED_DEPTH_RESOLVE: u8 = 16;

impl Live {
    /// Records a new render pass's subpasses.
    pub(crate) fn render_pass_created(&self, raw: vk::RenderPass, record: RenderPassRecord) {
        self.render_passes
            .lock()
            .insert(raw.as_raw(), Vrc::new(record));
    }

    /// The record of a live render pass made through the wrappers.
    pub(crate) fn render_pass(&self, raw: vk::RenderPass) -> Option<Vrc<RenderPassRecord>> {
        self.render_passes.lock().get(&raw.as_raw()).cloned()
    }
}
