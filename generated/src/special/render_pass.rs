//! Render passes: `vkCreateRenderPass` and `vkCreateRenderPass2` read into one `Pass`,
//! whose rules are each written once.

use super::subpass_dependencies::{subpass_dependency_checks, subpass_hazard_checks};
use super::{chained, refuse};
use crate::handles::*;
use crate::state::RenderPassRecord;
use crate::structs::*;
use crate::{Handle, Result};
use ash::vk;

/// The checks of `vkCreateRenderPass` that keep the driver inside the render pass's
/// arrays: attachment indices, dependency subpasses, and the chained multiview and
/// input-attachment-aspect infos.
pub(crate) fn create_render_pass_checks(create_info: &RenderPassCreateInfo<'_>) -> Result<()> {
    let raw = create_info.as_raw();
    let (attachments, subpass_count) = (raw.attachment_count, raw.subpass_count);
    // SAFETY: the safe setters store each array with its count.
    let (subpasses, dependencies) = unsafe {
        (
            crate::state::raw_slice(raw.p_subpasses, raw.subpass_count),
            crate::state::raw_slice(raw.p_dependencies, raw.dependency_count),
        )
    };
    let used = |a: u32| a != vk::ATTACHMENT_UNUSED && a >= attachments;
    for (i, s) in subpasses.iter().enumerate() {
        // SAFETY: the safe setters store each array with its count (and the resolve
        // array with the color attachments' count).
        let refs = unsafe {
            let mut refs: Vec<u32> = Vec::new();
            refs.extend(
                crate::state::raw_slice(s.p_input_attachments, s.input_attachment_count)
                    .iter()
                    .map(|r| r.attachment),
            );
            refs.extend(
                crate::state::raw_slice(s.p_color_attachments, s.color_attachment_count)
                    .iter()
                    .map(|r| r.attachment),
            );
            if !s.p_resolve_attachments.is_null() {
                refs.extend(
                    crate::state::raw_slice(s.p_resolve_attachments, s.color_attachment_count)
                        .iter()
                        .map(|r| r.attachment),
                );
            }
            refs.extend(s.p_depth_stencil_attachment.as_ref().map(|r| r.attachment));
            refs.extend(crate::state::raw_slice(
                s.p_preserve_attachments,
                s.preserve_attachment_count,
            ));
            refs
        };
        if let Some(a) = refs.into_iter().find(|a| used(*a)) {
            refuse(
                "VUID-VkRenderPassCreateInfo-attachment-00834",
                format!(
                    "pSubpasses[{i}] names attachment {a}, but the render pass has {attachments}"
                ),
            )?;
        }
    }
    for (i, d) in dependencies.iter().enumerate() {
        for (vuid, s, what) in [
            (
                "VUID-VkRenderPassCreateInfo-pDependencies-06866",
                d.src_subpass,
                "srcSubpass",
            ),
            (
                "VUID-VkRenderPassCreateInfo-pDependencies-06867",
                d.dst_subpass,
                "dstSubpass",
            ),
        ] {
            if s != vk::SUBPASS_EXTERNAL && s >= subpass_count {
                refuse(vuid, format!("pDependencies[{i}].{what} ({s}) must be less than subpassCount ({subpass_count})"))?;
            }
        }
    }
    // SAFETY: `raw` is a safe struct's.
    let multiview: Option<&vk::RenderPassMultiviewCreateInfo<'_>> = unsafe {
        chained(
            raw.p_next,
            vk::StructureType::RENDER_PASS_MULTIVIEW_CREATE_INFO,
        )
    };
    if let Some(m) = multiview.filter(|m| m.subpass_count != 0 && m.subpass_count != subpass_count)
    {
        refuse(
            "VUID-VkRenderPassCreateInfo-pNext-01928",
            format!("the chained VkRenderPassMultiviewCreateInfo's subpassCount ({}) must be 0 or the render pass's ({subpass_count})", m.subpass_count),
        )?;
    }
    // SAFETY: as above.
    let aspects: Option<&vk::RenderPassInputAttachmentAspectCreateInfo<'_>> = unsafe {
        chained(
            raw.p_next,
            vk::StructureType::RENDER_PASS_INPUT_ATTACHMENT_ASPECT_CREATE_INFO,
        )
    };
    if let Some(a) = aspects {
        // SAFETY: the safe setter stores the references with their count.
        let refs =
            unsafe { crate::state::raw_slice(a.p_aspect_references, a.aspect_reference_count) };
        for (i, r) in refs.iter().enumerate() {
            let Some(s) = subpasses.get(r.subpass as usize) else {
                return refuse(
                    "VUID-VkRenderPassCreateInfo-pNext-01926",
                    format!("pAspectReferences[{i}].subpass ({}) must be less than subpassCount ({subpass_count})", r.subpass),
                );
            };
            if r.input_attachment_index >= s.input_attachment_count {
                refuse(
                    "VUID-VkRenderPassCreateInfo-pNext-01927",
                    format!("pAspectReferences[{i}].inputAttachmentIndex ({}) must be less than subpass {}'s inputAttachmentCount ({})", r.input_attachment_index, r.subpass, s.input_attachment_count),
                )?;
            }
        }
    }
    Ok(())
}

/// The device remembers a render pass's subpasses and their view masks (from a
/// chained `VkRenderPassMultiviewCreateInfo`).
pub(crate) fn render_pass_created(
    device: &Device,
    render_pass: RenderPass,
    create_info: &RenderPassCreateInfo<'_>,
) -> RenderPass {
    Pass::of(create_info).created(device, render_pass)
}

/// As [`render_pass_created`], for `vkCreateRenderPass2`, whose subpasses carry
/// their view masks.
pub(crate) fn render_pass2_created(
    device: &Device,
    render_pass: RenderPass,
    create_info: &RenderPassCreateInfo2<'_>,
) -> RenderPass {
    Pass::of2(create_info).created(device, render_pass)
}

/// One attachment reference: the attachment, its layout, and (for
/// `VkAttachmentReference2`) the aspects an input attachment reads.
#[derive(Clone, Copy)]
pub(super) struct Ref {
    pub(super) attachment: u32,
    pub(super) layout: vk::ImageLayout,
    /// The stencil aspect's layout (a chained `VkAttachmentReferenceStencilLayout`'s,
    /// or `layout`).
    pub(super) stencil_layout: vk::ImageLayout,
    /// Whether a `VkAttachmentReferenceStencilLayout` gave `stencil_layout`.
    pub(super) stencil_chained: bool,
    pub(super) aspect_mask: vk::ImageAspectFlags,
}

impl Ref {
    pub(super) fn used(&self) -> bool {
        self.attachment != vk::ATTACHMENT_UNUSED
    }
}

/// One subpass's references.
pub(super) struct Subpass {
    pub(super) inputs: Vec<Ref>,
    pub(super) colors: Vec<Ref>,
    pub(super) resolves: Option<Vec<Ref>>,
    pub(super) depth: Option<Ref>,
    pub(super) preserve: Vec<u32>,
    /// Its view mask (`VkSubpassDescription2`'s, or a chained
    /// `VkRenderPassMultiviewCreateInfo`'s; 0 without multiview).
    pub(super) view_mask: u32,
    /// The attachment a chained `VkSubpassDescriptionDepthStencilResolve` resolves
    /// depth/stencil into.
    pub(super) depth_resolve: Option<u32>,
    /// That struct's depth and stencil resolve modes.
    pub(super) depth_resolve_modes: (vk::ResolveModeFlags, vk::ResolveModeFlags),
    /// Its flags and pipeline bind point.
    pub(super) flags: vk::SubpassDescriptionFlags,
    pub(super) bind_point: vk::PipelineBindPoint,
}

impl Subpass {
    /// Every reference, with where it comes from.
    fn refs(&self) -> impl Iterator<Item = (&'static str, &Ref)> {
        let inputs = self.inputs.iter().map(|r| ("pInputAttachments", r));
        let colors = self.colors.iter().map(|r| ("pColorAttachments", r));
        let resolves = self
            .resolves
            .iter()
            .flatten()
            .map(|r| ("pResolveAttachments", r));
        let depth = self.depth.iter().map(|r| ("pDepthStencilAttachment", r));
        inputs.chain(colors).chain(resolves).chain(depth)
    }
}

/// A render pass, as either create info gives it.
pub(super) struct Pass {
    /// Each attachment's format and sample count.
    pub(super) attachments: Vec<(vk::Format, vk::SampleCountFlags)>,
    /// The rest of each attachment's description.
    pub(super) described: Vec<Described>,
    pub(super) subpasses: Vec<Subpass>,
    pub(super) dependencies: Vec<Dependency>,
    /// The correlated view masks (`VkRenderPassCreateInfo2`'s, or a chained
    /// `VkRenderPassMultiviewCreateInfo`'s).
    pub(super) correlations: Vec<u32>,
    /// Read from `vkCreateRenderPass2`: the VUIDs of its rules are the second ones.
    pub(super) second: bool,
    /// Its create flags.
    pub(super) flags: vk::RenderPassCreateFlags,
}

/// What a render pass's record keeps of an attachment description beyond its format
/// and samples.
pub(super) struct Described {
    /// Its `loadOp` and `stencilLoadOp`.
    pub(super) load: (vk::AttachmentLoadOp, vk::AttachmentLoadOp),
    /// Its `storeOp` and `stencilStoreOp`.
    pub(super) store: (vk::AttachmentStoreOp, vk::AttachmentStoreOp),
    pub(super) may_alias: bool,
    pub(super) layouts: crate::state::AttachmentLayouts,
    /// Whether a `VkAttachmentDescriptionStencilLayout` gave the stencil aspect's.
    pub(super) stencil_chained: bool,
}

/// Reads an attachment description of either version (their fields share names),
/// with its stencil aspect's layouts where a struct gives them apart.
macro_rules! described {
    ($a:expr, $stencil:expr) => {
        Described::of(
            ($a.load_op, $a.stencil_load_op),
            ($a.store_op, $a.stencil_store_op),
            $a.flags,
            ($a.initial_layout, $a.final_layout),
            $stencil,
        )
    };
}

impl Described {
    fn of(
        (load, stencil_load): (vk::AttachmentLoadOp, vk::AttachmentLoadOp),
        store: (vk::AttachmentStoreOp, vk::AttachmentStoreOp),
        flags: vk::AttachmentDescriptionFlags,
        (initial, last): (vk::ImageLayout, vk::ImageLayout),
        stencil: Option<(vk::ImageLayout, vk::ImageLayout)>,
    ) -> Described {
        let (stencil_initial, stencil_last) = stencil.unwrap_or((initial, last));
        Described {
            load: (load, stencil_load),
            store,
            may_alias: flags.contains(vk::AttachmentDescriptionFlags::MAY_ALIAS),
            layouts: crate::state::AttachmentLayouts {
                initial,
                last,
                stencil_initial,
                stencil_last,
            },
            stencil_chained: stencil.is_some(),
        }
    }
}

/// A subpass dependency: its source and destination subpasses, stages and access
/// types.
pub(super) struct Dependency {
    pub(super) subpasses: (u32, u32),
    pub(super) stages: (vk::PipelineStageFlags, vk::PipelineStageFlags),
    pub(super) access: (vk::AccessFlags, vk::AccessFlags),
    pub(super) flags: vk::DependencyFlags,
    /// Its view offset (`VkSubpassDependency2::viewOffset`, or a chained
    /// `VkRenderPassMultiviewCreateInfo`'s), if one is given.
    pub(super) view_offset: Option<i32>,
}

/// A rule's VUIDs through `vkCreateRenderPass` and `vkCreateRenderPass2` (empty where
/// one of them has no such rule).
pub(super) type Rule = (&'static str, &'static str);

const PRESERVE_UNUSED: Rule = (
    "VUID-VkSubpassDescription-attachment-00853",
    "VUID-VkSubpassDescription2-attachment-03073",
);

const PRESERVE_USED: Rule = (
    "VUID-VkSubpassDescription-pPreserveAttachments-00854",
    "VUID-VkSubpassDescription2-pPreserveAttachments-03074",
);

const RESOLVE_COLOR_UNUSED: Rule = (
    "VUID-VkSubpassDescription-pResolveAttachments-00847",
    "VUID-VkSubpassDescription2-pResolveAttachments-03065",
);

const RESOLVE_COLOR_SINGLE: Rule = (
    "VUID-VkSubpassDescription-pResolveAttachments-00848",
    "VUID-VkSubpassDescription2-pResolveAttachments-03066",
);

const RESOLVE_MULTI: Rule = (
    "VUID-VkSubpassDescription-pResolveAttachments-00849",
    "VUID-VkSubpassDescription2-pResolveAttachments-03067",
);

const RESOLVE_FORMAT: Rule = (
    "VUID-VkSubpassDescription-pResolveAttachments-00850",
    "VUID-VkSubpassDescription2-pResolveAttachments-03068",
);

const INPUT_FEATURES: Rule = (
    "VUID-VkSubpassDescription-pInputAttachments-02647",
    "VUID-VkSubpassDescription2-pInputAttachments-02897",
);

const COLOR_FEATURES: Rule = (
    "VUID-VkSubpassDescription-pColorAttachments-02648",
    "VUID-VkSubpassDescription2-pColorAttachments-02898",
);

const RESOLVE_FEATURES: Rule = (
    "VUID-VkSubpassDescription-pResolveAttachments-02649",
    "VUID-VkSubpassDescription2-pResolveAttachments-02899",
);

const DEPTH_FEATURES: Rule = (
    "VUID-VkSubpassDescription-pDepthStencilAttachment-02650",
    "VUID-VkSubpassDescription2-pDepthStencilAttachment-02900",
);

const COLOR_SAMPLES: Rule = (
    "VUID-VkSubpassDescription-pColorAttachments-06868",
    "VUID-VkSubpassDescription2-multisampledRenderToSingleSampled-06872",
);

const DEPTH_SAMPLES: Rule = (
    "VUID-VkSubpassDescription-pDepthStencilAttachment-01418",
    "VUID-VkSubpassDescription2-multisampledRenderToSingleSampled-06872",
);

const SAME_LAYOUT: Rule = (
    "VUID-VkSubpassDescription-layout-02519",
    "VUID-VkSubpassDescription2-layout-02528",
);

const DEPTH_IS_COLOR: Rule = (
    "VUID-VkSubpassDescription-pDepthStencilAttachment-04438",
    "VUID-VkSubpassDescription2-pDepthStencilAttachment-04440",
);

/// Reads the subpasses of a `VkRenderPassCreateInfo` or `VkRenderPassCreateInfo2`
/// (their subpass descriptions' fields share names; their references' types differ,
/// and `plain` reads either into a [`Ref`]). Used inside `unsafe`: the arrays are a
/// safe struct's, each stored with its count.
macro_rules! subpasses {
    ($raw:expr, $plain:expr) => {
        crate::state::raw_slice($raw.p_subpasses, $raw.subpass_count)
            .iter()
            .map(|s| {
                let list = |p, n| {
                    crate::state::raw_slice(p, n)
                        .iter()
                        .map($plain)
                        .collect::<Vec<_>>()
                };
                Subpass {
                    inputs: list(s.p_input_attachments, s.input_attachment_count),
                    colors: list(s.p_color_attachments, s.color_attachment_count),
                    resolves: (!s.p_resolve_attachments.is_null())
                        .then(|| list(s.p_resolve_attachments, s.color_attachment_count)),
                    depth: s.p_depth_stencil_attachment.as_ref().map($plain),
                    preserve: crate::state::raw_slice(
                        s.p_preserve_attachments,
                        s.preserve_attachment_count,
                    )
                    .to_vec(),
                    view_mask: 0,
                    depth_resolve: None,
                    depth_resolve_modes: Default::default(),
                    flags: s.flags,
                    bind_point: s.pipeline_bind_point,
                }
            })
            .collect::<Vec<_>>()
    };
}

impl Pass {
    /// Reads `vkCreateRenderPass`'s create info.
    pub(super) fn of(create_info: &RenderPassCreateInfo<'_>) -> Pass {
        let raw = create_info.as_raw();
        // SAFETY: the safe setters store each array with its count, resolve
        // attachments one per color attachment; a depth/stencil reference outlives
        // the create info; each chain is a safe struct's, and the type each sType
        // names.
        unsafe {
            let attachments = crate::state::raw_slice(raw.p_attachments, raw.attachment_count);
            let described = attachments.iter().map(|a| described!(a, None)).collect();
            let plain = |r: &vk::AttachmentReference| Ref {
                attachment: r.attachment,
                layout: r.layout,
                stencil_layout: r.layout,
                stencil_chained: false,
                aspect_mask: vk::ImageAspectFlags::empty(),
            };
            let mut subpasses = subpasses!(raw, plain);
            // A chained VkRenderPassInputAttachmentAspectCreateInfo restricts the
            // aspects an input attachment reference lets the shader read.
            let aspects: Option<&vk::RenderPassInputAttachmentAspectCreateInfo<'_>> = chained(
                raw.p_next,
                vk::StructureType::RENDER_PASS_INPUT_ATTACHMENT_ASPECT_CREATE_INFO,
            );
            if let Some(aspects) = aspects {
                let references = crate::state::raw_slice(
                    aspects.p_aspect_references,
                    aspects.aspect_reference_count,
                );
                for r in references {
                    let input = subpasses
                        .get_mut(r.subpass as usize)
                        .and_then(|s| s.inputs.get_mut(r.input_attachment_index as usize));
                    if let Some(input) = input {
                        // Two references to one input leave the aspects both name.
                        input.aspect_mask = match input.aspect_mask.is_empty() {
                            true => r.aspect_mask,
                            false => input.aspect_mask & r.aspect_mask,
                        };
                    }
                }
            }
            let multiview: Option<&vk::RenderPassMultiviewCreateInfo<'_>> = chained(
                raw.p_next,
                vk::StructureType::RENDER_PASS_MULTIVIEW_CREATE_INFO,
            );
            let masks = multiview.map_or(&[][..], |m| {
                crate::state::raw_slice(m.p_view_masks, m.subpass_count)
            });
            for (s, mask) in subpasses.iter_mut().zip(masks) {
                s.view_mask = *mask;
            }
            let offsets = multiview.map_or(&[][..], |m| {
                crate::state::raw_slice(m.p_view_offsets, m.dependency_count)
            });
            let correlations = multiview.map_or(&[][..], |m| {
                crate::state::raw_slice(m.p_correlation_masks, m.correlation_mask_count)
            });
            let dependencies = crate::state::raw_slice(raw.p_dependencies, raw.dependency_count)
                .iter()
                .enumerate()
                .map(|(i, d)| Dependency {
                    subpasses: (d.src_subpass, d.dst_subpass),
                    stages: (d.src_stage_mask, d.dst_stage_mask),
                    access: (d.src_access_mask, d.dst_access_mask),
                    flags: d.dependency_flags,
                    view_offset: offsets.get(i).copied(),
                })
                .collect();
            Pass {
                attachments: attachments.iter().map(|a| (a.format, a.samples)).collect(),
                described,
                subpasses,
                dependencies,
                correlations: correlations.to_vec(),
                second: false,
                flags: raw.flags,
            }
        }
    }

    /// Reads `vkCreateRenderPass2`'s create info.
    fn of2(create_info: &RenderPassCreateInfo2<'_>) -> Pass {
        let raw = create_info.as_raw();
        // SAFETY: as in `of`.
        unsafe {
            let attachments = crate::state::raw_slice(raw.p_attachments, raw.attachment_count);
            let described = attachments
                .iter()
                .map(|a| {
                    let stencil: Option<&vk::AttachmentDescriptionStencilLayout<'_>> = chained(
                        a.p_next,
                        vk::StructureType::ATTACHMENT_DESCRIPTION_STENCIL_LAYOUT,
                    );
                    let stencil =
                        stencil.map(|s| (s.stencil_initial_layout, s.stencil_final_layout));
                    described!(a, stencil)
                })
                .collect();
            let plain = |r: &vk::AttachmentReference2<'_>| {
                let stencil: Option<&vk::AttachmentReferenceStencilLayout<'_>> = chained(
                    r.p_next,
                    vk::StructureType::ATTACHMENT_REFERENCE_STENCIL_LAYOUT,
                );
                Ref {
                    attachment: r.attachment,
                    layout: r.layout,
                    stencil_layout: stencil.map_or(r.layout, |s| s.stencil_layout),
                    stencil_chained: stencil.is_some(),
                    aspect_mask: r.aspect_mask,
                }
            };
            let mut subpasses = subpasses!(raw, plain);
            let descriptions = crate::state::raw_slice(raw.p_subpasses, raw.subpass_count);
            for (s, d) in subpasses.iter_mut().zip(descriptions) {
                s.view_mask = d.view_mask;
                let resolve: Option<&vk::SubpassDescriptionDepthStencilResolve<'_>> = chained(
                    d.p_next,
                    vk::StructureType::SUBPASS_DESCRIPTION_DEPTH_STENCIL_RESOLVE,
                );
                s.depth_resolve = resolve
                    .and_then(|r| r.p_depth_stencil_resolve_attachment.as_ref())
                    .map(|a| a.attachment);
                s.depth_resolve_modes = resolve.map_or(Default::default(), |r| {
                    (r.depth_resolve_mode, r.stencil_resolve_mode)
                });
            }
            // A chained VkMemoryBarrier2's stages and access types replace the
            // dependency's, their first 32 bits read.
            let dependencies = crate::state::raw_slice(raw.p_dependencies, raw.dependency_count)
                .iter()
                .map(|d| {
                    let barrier: Option<&vk::MemoryBarrier2<'_>> =
                        chained(d.p_next, vk::StructureType::MEMORY_BARRIER_2);
                    let low = |v: u64| v as u32;
                    Dependency {
                        subpasses: (d.src_subpass, d.dst_subpass),
                        stages: barrier.map_or((d.src_stage_mask, d.dst_stage_mask), |b| {
                            (
                                vk::PipelineStageFlags::from_raw(low(b.src_stage_mask.as_raw())),
                                vk::PipelineStageFlags::from_raw(low(b.dst_stage_mask.as_raw())),
                            )
                        }),
                        access: barrier.map_or((d.src_access_mask, d.dst_access_mask), |b| {
                            (
                                vk::AccessFlags::from_raw(low(b.src_access_mask.as_raw())),
                                vk::AccessFlags::from_raw(low(b.dst_access_mask.as_raw())),
                            )
                        }),
                        flags: d.dependency_flags,
                        view_offset: Some(d.view_offset),
                    }
                })
                .collect();
            Pass {
                attachments: attachments.iter().map(|a| (a.format, a.samples)).collect(),
                described,
                subpasses,
                dependencies,
                correlations: crate::state::raw_slice(
                    raw.p_correlated_view_masks,
                    raw.correlated_view_mask_count,
                )
                .to_vec(),
                second: true,
                flags: raw.flags,
            }
        }
    }

    /// Each subpass's view mask (0 without multiview).
    pub(super) fn view_masks(&self) -> Vec<u32> {
        self.subpasses.iter().map(|s| s.view_mask).collect()
    }

    /// The device's record of the render pass.
    fn created(&self, device: &Device, render_pass: RenderPass) -> RenderPass {
        let (color_formats, depth_formats) = self.formats();
        let layouts: Vec<_> = self.described.iter().map(|d| d.layouts).collect();
        let depth_resolves: Vec<u32> = self
            .subpasses
            .iter()
            .filter_map(|s| s.depth_resolve)
            .filter(|a| *a != vk::ATTACHMENT_UNUSED)
            .collect();
        let loads = self.attachments.iter().zip(&self.described);
        let clear_count = clear_count(loads.map(|(a, d)| (a.0, d.load.0, d.load.1)));
        let self_dependencies = self
            .dependencies
            .iter()
            .filter(|d| d.subpasses.0 == d.subpasses.1 && d.subpasses.0 != vk::SUBPASS_EXTERNAL)
            .map(|d| crate::state::SelfDependency {
                subpass: d.subpasses.0,
                stages: d.stages,
                access: d.access,
            })
            .collect();
        let dependency_stages = self
            .dependencies
            .iter()
            .fold(Default::default(), |(s, d), x| {
                (s | x.stages.0, d | x.stages.1)
            });
        let compatibility = self.compatibility();
        let edges = crate::state::Edges::of(&compatibility, self.subpasses.len() as u32);
        device.live().render_pass_created(
            render_pass.raw(),
            RenderPassRecord {
                attachments: self.attachment_uses(&depth_resolves),
                view_masks: self.subpasses.iter().map(|s| s.view_mask).collect(),
                no_attachments: self
                    .subpasses
                    .iter()
                    .map(|s| s.refs().all(|(_, r)| !r.used()))
                    .collect(),
                color_formats,
                depth_formats,
                depth_layouts: self.depth_layouts(),
                subpass_samples: self.samples(),
                taken: self.taken(&layouts),
                layouts,
                used: self.used(),
                inputs: self.inputs(),
                input_layouts: self
                    .subpasses
                    .iter()
                    .map(|s| s.inputs.iter().map(|r| (r.attachment, r.layout)).collect())
                    .collect(),
                self_dependencies,
                clear_count,
                stencil_taken: self.stencil_taken(),
                may_alias: self.described.iter().map(|d| d.may_alias).collect(),
                dependency_stages,
                dependencies: self
                    .dependencies
                    .iter()
                    .map(|d| d.subpasses)
                    .filter(|(a, b)| *a != vk::SUBPASS_EXTERNAL && *b != vk::SUBPASS_EXTERNAL)
                    .collect(),
                second: self.second,
                compatibility,
                edges,
                boundaries: self.boundaries(),
            },
        );
        render_pass
    }

    /// What each attachment does at the render pass instance's edges: its load and
    /// store operations, and the subpasses that use it first and last with the
    /// layouts (depth or color, stencil) they give it.
    fn boundaries(&self) -> Vec<crate::state::Boundary> {
        let uses = |a: u32| {
            self.subpasses.iter().enumerate().filter_map(move |(i, s)| {
                s.refs()
                    .map(|(_, r)| r)
                    .find(|r| r.attachment == a)
                    .map(|r| (i as u32, r.layout, r.stencil_layout))
            })
        };
        self.described
            .iter()
            .enumerate()
            .map(|(a, d)| crate::state::Boundary {
                load: d.load,
                store: d.store,
                first: uses(a as u32).next(),
                last: uses(a as u32).next_back(),
            })
            .collect()
    }

    /// What the render pass compatibility of the specification compares: every
    /// attachment reference by its attachment's format and sample count (unused past
    /// the end of the shorter array), and everything else as it is but the
    /// attachments' layouts and load and store operations and the references'
    /// layouts; a render pass of one subpass leaves its resolve references and
    /// depth/stencil resolve modes out.
    fn compatibility(&self) -> crate::state::Compatibility {
        let single = self.subpasses.len() == 1;
        let of = |r: &Ref| {
            self.attachments
                .get(r.attachment as usize)
                .filter(|_| r.used())
                .copied()
        };
        let list = |refs: &[Ref]| {
            let mut out: Vec<_> = refs.iter().map(of).collect();
            while out.last().is_some_and(Option::is_none) {
                out.pop();
            }
            out
        };
        let subpasses = self
            .subpasses
            .iter()
            .map(|s| crate::state::SubpassShape {
                flags: s.flags,
                bind_point: s.bind_point,
                inputs: list(&s.inputs),
                // Of the references compared: none past the last used one.
                input_aspects: s
                    .inputs
                    .iter()
                    .take(list(&s.inputs).len())
                    .map(|r| r.aspect_mask)
                    .collect(),
                colors: list(&s.colors),
                resolves: if single {
                    Vec::new()
                } else {
                    s.resolves.as_deref().map(list).unwrap_or_default()
                },
                depth: s.depth.as_ref().and_then(of),
                depth_resolve: if single {
                    None
                } else {
                    s.depth_resolve
                        .and_then(|a| self.attachments.get(a as usize).copied())
                        .map(|a| (a, s.depth_resolve_modes))
                },
                preserve: s.preserve.clone(),
                view_mask: s.view_mask,
            })
            .collect();
        crate::state::Compatibility {
            flags: self.flags,
            attachments: self
                .attachments
                .iter()
                .zip(&self.described)
                .map(|(a, d)| (a.0, a.1, d.may_alias))
                .collect(),
            subpasses,
            dependencies: self
                .dependencies
                .iter()
                .map(|d| {
                    (
                        d.subpasses,
                        d.stages,
                        d.access,
                        d.flags,
                        d.view_offset.unwrap_or(0),
                    )
                })
                .collect(),
            correlations: self.correlations.clone(),
        }
    }

    /// Every layout each attachment takes: its initial and final layouts (and its
    /// stencil aspect's) and those of the references to it.
    fn taken(&self, layouts: &[crate::state::AttachmentLayouts]) -> Vec<Vec<vk::ImageLayout>> {
        let mut out: Vec<Vec<vk::ImageLayout>> = layouts
            .iter()
            .map(|l| vec![l.initial, l.last, l.stencil_initial, l.stencil_last])
            .collect();
        for s in &self.subpasses {
            for (_, r) in s.refs() {
                if let Some(t) = out.get_mut(r.attachment as usize) {
                    t.push(r.layout);
                }
            }
        }
        out
    }

    /// The layouts each attachment's stencil aspect takes through the stencil layout
    /// structs `vkCreateRenderPass2`'s attachments and input and depth/stencil
    /// references chain (none through `vkCreateRenderPass`).
    fn stencil_taken(&self) -> Vec<Vec<vk::ImageLayout>> {
        if !self.second {
            return Vec::new();
        }
        let mut out: Vec<Vec<vk::ImageLayout>> = self
            .described
            .iter()
            .map(|d| match d.stencil_chained {
                true => vec![d.layouts.stencil_initial, d.layouts.stencil_last],
                false => Vec::new(),
            })
            .collect();
        for s in &self.subpasses {
            for r in s
                .inputs
                .iter()
                .chain(&s.depth)
                .filter(|r| r.stencil_chained)
            {
                if let Some(t) = out.get_mut(r.attachment as usize) {
                    t.push(r.stencil_layout);
                }
            }
        }
        out
    }

    /// The attachments each subpass references (input, color, resolve,
    /// depth/stencil).
    fn used(&self) -> Vec<Vec<u32>> {
        self.subpasses
            .iter()
            .map(|s| {
                s.inputs
                    .iter()
                    .chain(&s.colors)
                    .chain(s.resolves.iter().flatten())
                    .chain(&s.depth)
                    .filter(|r| r.used())
                    .map(|r| r.attachment)
                    .chain(s.depth_resolve.filter(|a| *a != vk::ATTACHMENT_UNUSED))
                    .collect()
            })
            .collect()
    }

    fn attachment_uses(
        &self,
        depth_resolves: &[u32],
    ) -> Vec<(vk::Format, vk::SampleCountFlags, u8)> {
        use crate::state::{USED_COLOR, USED_DEPTH, USED_DEPTH_RESOLVE, USED_INPUT, USED_RESOLVE};
        let mut out: Vec<_> = self.attachments.iter().map(|&(f, s)| (f, s, 0u8)).collect();
        let mut mark = |a: u32, bit: u8| {
            if let Some(e) = out.get_mut(a as usize) {
                e.2 |= bit;
            }
        };
        for s in &self.subpasses {
            for r in s.inputs.iter().filter(|r| r.used()) {
                mark(r.attachment, USED_INPUT);
            }
            for r in s.colors.iter().filter(|r| r.used()) {
                mark(r.attachment, USED_COLOR);
            }
            for r in s.resolves.iter().flatten().filter(|r| r.used()) {
                mark(r.attachment, USED_RESOLVE);
            }
            for r in s.depth.iter().filter(|r| r.used()) {
                mark(r.attachment, USED_DEPTH);
            }
        }
        for a in depth_resolves {
            mark(*a, USED_DEPTH_RESOLVE);
        }
        out
    }

    /// Each subpass's input attachment references: the attachment each names
    /// (`VK_ATTACHMENT_UNUSED` for an unused one) and the aspects it lets the
    /// fragment shader read (empty: every aspect of the format).
    fn inputs(&self) -> Vec<Vec<(u32, vk::ImageAspectFlags)>> {
        self.subpasses
            .iter()
            .map(|s| {
                s.inputs
                    .iter()
                    .map(|r| (r.attachment, r.aspect_mask))
                    .collect()
            })
            .collect()
    }

    /// Each subpass's color attachments' formats and depth/stencil attachment's
    /// format, for the render pass's record. An index past the attachments (which
    /// only the unchecked path lets through) reads as `UNDEFINED`.
    fn formats(&self) -> (Vec<Vec<vk::Format>>, Vec<Option<vk::Format>>) {
        let format = |r: &Ref| {
            self.attachments
                .get(r.attachment as usize)
                .map_or(vk::Format::UNDEFINED, |a| a.0)
        };
        let colors = self
            .subpasses
            .iter()
            .map(|s| {
                s.colors
                    .iter()
                    .map(|r| {
                        if r.used() {
                            format(r)
                        } else {
                            vk::Format::UNDEFINED
                        }
                    })
                    .collect()
            })
            .collect();
        let depths = self
            .subpasses
            .iter()
            .map(|s| s.depth.filter(Ref::used).map(|r| format(&r)))
            .collect();
        (colors, depths)
    }

    /// Each subpass's color and depth/stencil attachments' sample count, if it uses
    /// any.
    fn samples(&self) -> Vec<Option<vk::SampleCountFlags>> {
        self.subpasses
            .iter()
            .map(|s| {
                s.colors
                    .iter()
                    .chain(&s.depth)
                    .filter(|r| r.used())
                    .find_map(|r| self.attachments.get(r.attachment as usize))
                    .map(|a| a.1)
            })
            .collect()
    }

    /// Each subpass's depth/stencil reference's layouts, if it uses one.
    fn depth_layouts(&self) -> Vec<Option<(vk::ImageLayout, vk::ImageLayout)>> {
        self.subpasses
            .iter()
            .map(|s| {
                s.depth
                    .filter(Ref::used)
                    .map(|r| (r.layout, r.stencil_layout))
            })
            .collect()
    }

    /// The rule's VUID for the version the pass was read from.
    pub(super) fn vuid(&self, rule: Rule) -> &'static str {
        if self.second {
            rule.1
        } else {
            rule.0
        }
    }

    /// The first reference past the attachments, for `vkCreateRenderPass2`
    /// (`vkCreateRenderPass` checks it before the other checks, as 00834).
    fn check_indices(&self) -> Result<()> {
        let count = self.attachments.len() as u32;
        for (i, s) in self.subpasses.iter().enumerate() {
            let refs = s.refs().map(|(_, r)| r.attachment);
            if let Some(a) = refs
                .chain(s.preserve.iter().copied())
                .find(|&a| a != vk::ATTACHMENT_UNUSED && a >= count)
            {
                refuse(
                    "VUID-VkRenderPassCreateInfo2-attachment-03051",
                    format!(
                        "pSubpasses[{i}] names attachment {a}, but the render pass has {count}"
                    ),
                )?;
            }
            if let Some(a) = s
                .depth_resolve
                .filter(|&a| a != vk::ATTACHMENT_UNUSED && a >= count)
            {
                refuse(
                    "VUID-VkRenderPassCreateInfo2-pSubpasses-06473",
                    format!("pSubpasses[{i}] resolves depth/stencil into attachment {a}, but the render pass has {count}"),
                )?;
            }
        }
        // Every aspect bit the registry names (COLOR to MEMORY_PLANE_3), before the
        // aspects are read against the formats.
        let known = vk::ImageAspectFlags::from_raw(0x7ff);
        for (i, s) in self.subpasses.iter().enumerate() {
            for (k, r) in s.inputs.iter().enumerate() {
                if r.used() && !known.contains(r.aspect_mask) {
                    refuse("VUID-VkSubpassDescription2-attachment-02799", format!("pSubpasses[{i}].pInputAttachments[{k}].aspectMask ({:?}) is no combination of aspects", r.aspect_mask))?;
                }
            }
        }
        let subpasses = self.subpasses.len() as u32;
        for (i, d) in self.dependencies.iter().enumerate() {
            for (vuid, at, what) in [
                (
                    "VUID-VkRenderPassCreateInfo2-srcSubpass-02526",
                    d.subpasses.0,
                    "srcSubpass",
                ),
                (
                    "VUID-VkRenderPassCreateInfo2-dstSubpass-02527",
                    d.subpasses.1,
                    "dstSubpass",
                ),
            ] {
                if at != vk::SUBPASS_EXTERNAL && at >= subpasses {
                    refuse(
                        vuid,
                        format!("pDependencies[{i}].{what} ({at}) must be less than subpassCount ({subpasses})"),
                    )?;
                }
            }
        }
        Ok(())
    }

    /// Every rule of the subpasses' references. The indices are in range (checked
    /// first).
    fn check_references(&self, device: &Device) -> Result<()> {
        let format_of = |r: &Ref| self.attachments[r.attachment as usize].0;
        let samples_of = |r: &Ref| self.attachments[r.attachment as usize].1;
        let physical = device.parent();
        // What an image of the format can do with either tiling.
        let features = |format: vk::Format| {
            physical
                .get_format_properties(format)
                .map(|p| p.linear_tiling_features | p.optimal_tiling_features)
        };
        for (i, s) in self.subpasses.iter().enumerate() {
            for (k, &p) in s.preserve.iter().enumerate() {
                if p == vk::ATTACHMENT_UNUSED {
                    refuse(
                        self.vuid(PRESERVE_UNUSED),
                        format!(
                            "pSubpasses[{i}].pPreserveAttachments[{k}] is VK_ATTACHMENT_UNUSED"
                        ),
                    )?;
                }
                if let Some((what, _)) = s.refs().find(|(_, r)| r.attachment == p) {
                    refuse(
                        self.vuid(PRESERVE_USED),
                        format!("pSubpasses[{i}] preserves attachment {p}, which its {what} uses"),
                    )?;
                }
            }
            if let Some(resolves) = &s.resolves {
                for (k, (r, c)) in resolves.iter().zip(&s.colors).enumerate() {
                    if !r.used() {
                        continue;
                    }
                    let at = format!("pSubpasses[{i}].pResolveAttachments[{k}]");
                    if !c.used() {
                        refuse(
                            self.vuid(RESOLVE_COLOR_UNUSED),
                            format!("{at} resolves an unused color attachment"),
                        )?;
                        continue;
                    }
                    if samples_of(c) == vk::SampleCountFlags::TYPE_1 {
                        refuse(
                            self.vuid(RESOLVE_COLOR_SINGLE),
                            format!(
                                "{at} resolves attachment {}, which has one sample",
                                c.attachment
                            ),
                        )?;
                    }
                    if samples_of(r) != vk::SampleCountFlags::TYPE_1 {
                        refuse(
                            self.vuid(RESOLVE_MULTI),
                            format!("{at} names attachment {}, of {:?} samples: a resolve attachment has one", r.attachment, samples_of(r)),
                        )?;
                    }
                    if format_of(r) != format_of(c) {
                        refuse(
                            self.vuid(RESOLVE_FORMAT),
                            format!(
                                "{at} has format {:?}, its color attachment {:?}",
                                format_of(r),
                                format_of(c)
                            ),
                        )?;
                    }
                }
            }
            if let Some(d) = s.depth.filter(|d| d.used()) {
                if s.colors.iter().any(|c| c.attachment == d.attachment) {
                    refuse(
                        self.vuid(DEPTH_IS_COLOR),
                        format!("pSubpasses[{i}] uses attachment {} as a color and the depth/stencil attachment", d.attachment),
                    )?;
                }
            }
            let attachment = vk::FormatFeatureFlags::COLOR_ATTACHMENT;
            let depth = vk::FormatFeatureFlags::DEPTH_STENCIL_ATTACHMENT;
            for (what, rule, need) in [
                ("pInputAttachments", INPUT_FEATURES, attachment | depth),
                ("pColorAttachments", COLOR_FEATURES, attachment),
                ("pResolveAttachments", RESOLVE_FEATURES, attachment),
                ("pDepthStencilAttachment", DEPTH_FEATURES, depth),
            ] {
                for (_, r) in s.refs().filter(|(w, r)| *w == what && r.used()) {
                    let format = format_of(r);
                    if !features(format)?.intersects(need) {
                        refuse(
                            self.vuid(rule),
                            format!("pSubpasses[{i}].{what} names attachment {}, whose format {format:?} supports none of {need:?}", r.attachment),
                        )?;
                    }
                }
            }
            let mut colors = s.colors.iter().filter(|r| r.used());
            if let Some(first) = colors.next() {
                let samples = samples_of(first);
                if let Some(other) = colors.find(|r| samples_of(r) != samples) {
                    refuse(
                        self.vuid(COLOR_SAMPLES),
                        format!("pSubpasses[{i}]'s color attachments {} and {} have {samples:?} and {:?} samples", first.attachment, other.attachment, samples_of(other)),
                    )?;
                }
                if let Some(d) = s.depth.filter(|d| d.used() && samples_of(d) != samples) {
                    refuse(
                        self.vuid(DEPTH_SAMPLES),
                        format!("pSubpasses[{i}]'s depth/stencil attachment {} has {:?} samples, its color attachments {samples:?}", d.attachment, samples_of(&d)),
                    )?;
                }
            }
            let refs: Vec<_> = s.refs().filter(|(_, r)| r.used()).collect();
            for (n, (what, r)) in refs.iter().enumerate() {
                if let Some((other, o)) = refs[n + 1..]
                    .iter()
                    .find(|(_, o)| o.attachment == r.attachment && o.layout != r.layout)
                {
                    refuse(
                        self.vuid(SAME_LAYOUT),
                        format!("pSubpasses[{i}] uses attachment {} in {what} as {:?} and in {other} as {:?}", r.attachment, r.layout, o.layout),
                    )?;
                }
            }
            if self.second {
                for (k, r) in s.inputs.iter().enumerate().filter(|(_, r)| r.used()) {
                    check_input_aspects(i, k, r, format_of(r))?;
                }
            }
        }
        Ok(())
    }
}

/// The aspects of an input attachment of `vkCreateRenderPass2`.
fn check_input_aspects(i: usize, k: usize, r: &Ref, format: vk::Format) -> Result<()> {
    let at = format!("pSubpasses[{i}].pInputAttachments[{k}].aspectMask");
    if r.aspect_mask.is_empty() {
        refuse(
            "VUID-VkSubpassDescription2-attachment-02800",
            format!("{at} is 0"),
        )?;
    }
    if r.aspect_mask.contains(vk::ImageAspectFlags::METADATA) {
        refuse(
            "VUID-VkSubpassDescription2-attachment-02801",
            format!("{at} includes VK_IMAGE_ASPECT_METADATA_BIT"),
        )?;
    }
    if let Some(present) = crate::formats::aspects(format) {
        if !present.contains(r.aspect_mask) {
            refuse(
                "VUID-VkRenderPassCreateInfo2-attachment-02525",
                format!(
                    "{at} ({:?}) names aspects that format {format:?} has not ({present:?})",
                    r.aspect_mask
                ),
            )?;
        }
    }
    Ok(())
}

/// The view masks of a render pass's subpasses: all zero or none
/// (`VkRenderPassCreateInfo2-viewMask-03058`, `VkRenderPassCreateInfo-pNext-02513`),
/// and with multiview off, no correlation masks and no view-local dependency.
fn check_view_masks(
    device: &Device,
    masks: &[u32],
    correlations: u32,
    dependencies: &[vk::DependencyFlags],
    second: bool,
) -> Result<()> {
    let pick = |a, b| if second { b } else { a };
    let zero = masks.iter().filter(|&&m| m == 0).count();
    if zero != 0 && zero != masks.len() {
        refuse(
            pick(
                "VUID-VkRenderPassCreateInfo-pNext-02513",
                "VUID-VkRenderPassCreateInfo2-viewMask-03058",
            ),
            format!(
                "{zero} of the {} view masks are 0: all or none must be",
                masks.len()
            ),
        )?;
    }
    if zero == masks.len() {
        if correlations != 0 {
            refuse(
                pick(
                    "VUID-VkRenderPassCreateInfo-pNext-02515",
                    "VUID-VkRenderPassCreateInfo2-viewMask-03057",
                ),
                format!("every view mask is 0, but {correlations} correlation masks are given"),
            )?;
        }
        if let Some(i) = dependencies
            .iter()
            .position(|f| f.contains(vk::DependencyFlags::VIEW_LOCAL))
        {
            refuse(
                pick(
                    "VUID-VkRenderPassCreateInfo-pNext-02514",
                    "VUID-VkRenderPassCreateInfo2-viewMask-03059",
                ),
                format!("every view mask is 0, but pDependencies[{i}] is view-local"),
            )?;
        }
    }
    if second {
        let max = multiview_view_count(device);
        for (i, m) in masks.iter().enumerate() {
            let highest = 32 - m.leading_zeros();
            if *m != 0 && max.is_some_and(|max| highest > max) {
                refuse(
                    "VUID-VkSubpassDescription2-viewMask-06706",
                    format!("pSubpasses[{i}].viewMask ({m:#x}) names view {}, past maxMultiviewViewCount ({})", highest - 1, max.unwrap_or(0)),
                )?;
            }
        }
    }
    Ok(())
}

/// The device's `maxMultiviewViewCount`, where the instance can ask for it.
pub(super) fn multiview_view_count(device: &Device) -> Option<u32> {
    multiview_properties(device).map(|m| m.max_multiview_view_count)
}

/// The device's `protectedNoFault` (false where the instance cannot ask for it).
pub(crate) fn protected_no_fault(device: &Device) -> bool {
    let mut protected = vk::PhysicalDeviceProtectedMemoryProperties::default();
    crate::special::ask_properties2(device, &mut protected)
        && protected.protected_no_fault == vk::TRUE
}

/// The device's multiview limits, where the instance can ask for them (Vulkan 1.1).
pub(super) fn multiview_properties(
    device: &Device,
) -> Option<vk::PhysicalDeviceMultiviewProperties<'static>> {
    let mut multiview = vk::PhysicalDeviceMultiviewProperties::default();
    crate::special::ask_properties2(device, &mut multiview).then_some(multiview)
}

/// The checks of `vkCreateRenderPass` that read the attachments its subpasses
/// reference, and a chained `VkRenderPassMultiviewCreateInfo`. They query the
/// attachments' format features, so they run after the checks of the values.
pub(crate) fn render_pass_reference_checks(
    device: &Device,
    create_info: &RenderPassCreateInfo<'_>,
) -> Result<()> {
    reference_and_view_checks(device, create_info)?;
    // Last: a render pass that breaks a rule is refused for the rule.
    subpass_hazard_checks(&Pass::of(create_info))
}

fn reference_and_view_checks(
    device: &Device,
    create_info: &RenderPassCreateInfo<'_>,
) -> Result<()> {
    Pass::of(create_info).check_references(device)?;
    render_pass_description_checks(device, create_info)?;
    let raw = create_info.as_raw();
    // SAFETY: `raw` is a safe struct's.
    let multiview: Option<&vk::RenderPassMultiviewCreateInfo<'_>> = unsafe {
        chained(
            raw.p_next,
            vk::StructureType::RENDER_PASS_MULTIVIEW_CREATE_INFO,
        )
    };
    let Some(m) = multiview else {
        return Ok(());
    };
    if m.dependency_count != 0 && m.dependency_count != raw.dependency_count {
        refuse(
            "VUID-VkRenderPassCreateInfo-pNext-01929",
            format!("the chained VkRenderPassMultiviewCreateInfo's dependencyCount ({}) must be 0 or the render pass's ({})", m.dependency_count, raw.dependency_count),
        )?;
    }
    // SAFETY: the safe setters store each array with its count.
    let (masks, dependencies) = unsafe {
        (
            crate::state::raw_slice(m.p_view_masks, m.subpass_count),
            crate::state::raw_slice(raw.p_dependencies, raw.dependency_count),
        )
    };
    let flags: Vec<_> = dependencies.iter().map(|d| d.dependency_flags).collect();
    check_view_masks(device, masks, m.correlation_mask_count, &flags, false)
}

/// The checks of `vkCreateRenderPass2` that keep its reads inside the attachments:
/// each reference names one of them.
pub(crate) fn create_render_pass2_checks(create_info: &RenderPassCreateInfo2<'_>) -> Result<()> {
    Pass::of2(create_info).check_indices()
}

/// The checks of `vkCreateRenderPass2` over the attachments its subpasses
/// reference and their view masks, as for `vkCreateRenderPass`.
pub(crate) fn render_pass2_reference_checks(
    device: &Device,
    create_info: &RenderPassCreateInfo2<'_>,
) -> Result<()> {
    let pass = Pass::of2(create_info);
    pass.check_references(device)?;
    pass.check_descriptions(device)?;
    subpass_dependency_checks(device, &pass)?;
    let raw = create_info.as_raw();
    // SAFETY: the safe setters store each array with its count.
    let (subpasses, dependencies) = unsafe {
        (
            crate::state::raw_slice(raw.p_subpasses, raw.subpass_count),
            crate::state::raw_slice(raw.p_dependencies, raw.dependency_count),
        )
    };
    let masks: Vec<_> = subpasses.iter().map(|s| s.view_mask).collect();
    let flags: Vec<_> = dependencies.iter().map(|d| d.dependency_flags).collect();
    check_view_masks(device, &masks, raw.correlated_view_mask_count, &flags, true)?;
    // Last: a render pass that breaks a rule is refused for the rule.
    subpass_hazard_checks(&pass)
}

/// One more than the largest attachment index a render pass instance clears: a
/// `loadOp` of CLEAR, or a `stencilLoadOp` of CLEAR for a depth/stencil format.
pub(super) fn clear_count(
    attachments: impl Iterator<Item = (vk::Format, vk::AttachmentLoadOp, vk::AttachmentLoadOp)>,
) -> u32 {
    let depth_stencil = |f| {
        crate::formats::aspects(f).is_some_and(|a| {
            a.intersects(vk::ImageAspectFlags::DEPTH | vk::ImageAspectFlags::STENCIL)
        })
    };
    attachments
        .enumerate()
        .filter(|(_, (f, load, stencil))| {
            *load == vk::AttachmentLoadOp::CLEAR
                || (depth_stencil(*f) && *stencil == vk::AttachmentLoadOp::CLEAR)
        })
        .map(|(i, _)| i as u32 + 1)
        .max()
        .unwrap_or(0)
}

/// The checks of `vkCreateRenderPass` that read its create info alone, with the
/// device's features and limits: the descriptions and dependencies read into one
/// [`Pass`], then a chained input-attachment-aspect struct.
fn render_pass_description_checks(
    device: &Device,
    create_info: &RenderPassCreateInfo<'_>,
) -> Result<()> {
    let pass = Pass::of(create_info);
    pass.check_descriptions(device)?;
    subpass_dependency_checks(device, &pass)?;
    let raw = create_info.as_raw();
    // SAFETY: the safe setters store each array with its count.
    let (attachments, subpasses) = unsafe {
        (
            crate::state::raw_slice(raw.p_attachments, raw.attachment_count),
            crate::state::raw_slice(raw.p_subpasses, raw.subpass_count),
        )
    };
    input_aspect_checks(raw, attachments, subpasses)
}

/// A chained `VkRenderPassInputAttachmentAspectCreateInfo` names only aspects the
/// referenced attachment's format has.
fn input_aspect_checks(
    raw: &vk::RenderPassCreateInfo<'_>,
    attachments: &[vk::AttachmentDescription],
    subpasses: &[vk::SubpassDescription<'_>],
) -> Result<()> {
    // SAFETY: `raw` is a safe struct's.
    let aspects: Option<&vk::RenderPassInputAttachmentAspectCreateInfo<'_>> = unsafe {
        chained(
            raw.p_next,
            vk::StructureType::RENDER_PASS_INPUT_ATTACHMENT_ASPECT_CREATE_INFO,
        )
    };
    let Some(aspects) = aspects else {
        return Ok(());
    };
    // SAFETY: the safe setter stores the array with its count.
    let references = unsafe {
        crate::state::raw_slice(aspects.p_aspect_references, aspects.aspect_reference_count)
    };
    for (k, r) in references.iter().enumerate() {
        let Some(s) = subpasses.get(r.subpass as usize) else {
            continue;
        };
        // SAFETY: the safe setter stores the array with its count.
        let inputs =
            unsafe { crate::state::raw_slice(s.p_input_attachments, s.input_attachment_count) };
        let Some(input) = inputs.get(r.input_attachment_index as usize) else {
            continue;
        };
        let Some(a) = attachments.get(input.attachment as usize) else {
            continue;
        };
        if let Some(present) = crate::formats::aspects(a.format) {
            if !present.contains(r.aspect_mask) {
                refuse(
                    "VUID-VkRenderPassCreateInfo-pNext-01963",
                    format!("pAspectReferences[{k}].aspectMask ({:?}) names aspects attachment {} ({:?}) has not", r.aspect_mask, input.attachment, a.format),
                )?;
            }
        }
    }
    Ok(())
}
