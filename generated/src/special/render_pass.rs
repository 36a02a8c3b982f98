//! Render passes: `vkCreateRenderPass` and `vkCreateRenderPass2` read into one `Pass`,
//! whose rules are each written once.

use super::subpass_dependencies::subpass_dependency_checks;
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
struct Ref {
    attachment: u32,
    layout: vk::ImageLayout,
    /// The stencil aspect's layout (a chained `VkAttachmentReferenceStencilLayout`'s,
    /// or `layout`).
    stencil_layout: vk::ImageLayout,
    /// Whether a `VkAttachmentReferenceStencilLayout` gave `stencil_layout`.
    stencil_chained: bool,
    aspect_mask: vk::ImageAspectFlags,
}

impl Ref {
    fn used(&self) -> bool {
        self.attachment != vk::ATTACHMENT_UNUSED
    }
}

/// One subpass's references.
struct Subpass {
    inputs: Vec<Ref>,
    colors: Vec<Ref>,
    resolves: Option<Vec<Ref>>,
    depth: Option<Ref>,
    preserve: Vec<u32>,
    /// Its view mask (`VkSubpassDescription2`'s, or a chained
    /// `VkRenderPassMultiviewCreateInfo`'s; 0 without multiview).
    view_mask: u32,
    /// The attachment a chained `VkSubpassDescriptionDepthStencilResolve` resolves
    /// depth/stencil into.
    depth_resolve: Option<u32>,
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
struct Pass {
    /// Each attachment's format and sample count.
    attachments: Vec<(vk::Format, vk::SampleCountFlags)>,
    /// The rest of each attachment's description.
    described: Vec<Described>,
    subpasses: Vec<Subpass>,
    dependencies: Vec<Dependency>,
    /// Read from `vkCreateRenderPass2`: the VUIDs of its rules are the second ones.
    second: bool,
}

/// What a render pass's record keeps of an attachment description beyond its format
/// and samples.
struct Described {
    /// Its `loadOp` and `stencilLoadOp`.
    load: (vk::AttachmentLoadOp, vk::AttachmentLoadOp),
    may_alias: bool,
    layouts: crate::state::AttachmentLayouts,
    /// Whether a `VkAttachmentDescriptionStencilLayout` gave the stencil aspect's.
    stencil_chained: bool,
}

/// Reads an attachment description of either version (their fields share names),
/// with its stencil aspect's layouts where a struct gives them apart.
macro_rules! described {
    ($a:expr, $stencil:expr) => {
        Described::of(
            ($a.load_op, $a.stencil_load_op),
            $a.flags,
            ($a.initial_layout, $a.final_layout),
            $stencil,
        )
    };
}

impl Described {
    fn of(
        (load, stencil_load): (vk::AttachmentLoadOp, vk::AttachmentLoadOp),
        flags: vk::AttachmentDescriptionFlags,
        (initial, last): (vk::ImageLayout, vk::ImageLayout),
        stencil: Option<(vk::ImageLayout, vk::ImageLayout)>,
    ) -> Described {
        let (stencil_initial, stencil_last) = stencil.unwrap_or((initial, last));
        Described {
            load: (load, stencil_load),
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
struct Dependency {
    subpasses: (u32, u32),
    stages: (vk::PipelineStageFlags, vk::PipelineStageFlags),
    access: (vk::AccessFlags, vk::AccessFlags),
}

/// A rule's VUIDs through `vkCreateRenderPass` and `vkCreateRenderPass2` (empty where
/// one of them has no such rule).
type Rule = (&'static str, &'static str);

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
                }
            })
            .collect::<Vec<_>>()
    };
}

impl Pass {
    /// Reads `vkCreateRenderPass`'s create info.
    fn of(create_info: &RenderPassCreateInfo<'_>) -> Pass {
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
            let dependencies = crate::state::raw_slice(raw.p_dependencies, raw.dependency_count)
                .iter()
                .map(|d| Dependency {
                    subpasses: (d.src_subpass, d.dst_subpass),
                    stages: (d.src_stage_mask, d.dst_stage_mask),
                    access: (d.src_access_mask, d.dst_access_mask),
                })
                .collect();
            Pass {
                attachments: attachments.iter().map(|a| (a.format, a.samples)).collect(),
                described,
                subpasses,
                dependencies,
                second: false,
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
                    }
                })
                .collect();
            Pass {
                attachments: attachments.iter().map(|a| (a.format, a.samples)).collect(),
                described,
                subpasses,
                dependencies,
                second: true,
            }
        }
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
                self_dependencies,
                clear_count,
                stencil_taken: self.stencil_taken(),
                may_alias: self.described.iter().map(|d| d.may_alias).collect(),
                dependency_stages,
            },
        );
        render_pass
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

    fn vuid(&self, rule: Rule) -> &'static str {
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
    Pass::of2(create_info).check_references(device)?;
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
    check_view_masks(device, &masks, raw.correlated_view_mask_count, &flags, true)
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

/// A depth/stencil format's layouts that name one aspect only, refused for a format
/// with both (`VkAttachmentDescription-format-06242`, `06243`, `06906`, `06907`).
const ONE_ASPECT_LAYOUTS: [(vk::ImageLayout, bool); 4] = [
    (vk::ImageLayout::DEPTH_ATTACHMENT_OPTIMAL, true),
    (vk::ImageLayout::DEPTH_READ_ONLY_OPTIMAL, true),
    (vk::ImageLayout::STENCIL_ATTACHMENT_OPTIMAL, false),
    (vk::ImageLayout::STENCIL_READ_ONLY_OPTIMAL, false),
];

/// The checks of `vkCreateRenderPass` that read its create info alone, with the
/// device's features and limits: attachment formats and layouts, the layout of
/// each attachment's first use against its load operations, dependencies against
/// the stages a graphics pipeline has and the accesses each stage supports, and a
/// chained multiview or input-attachment-aspect struct.
fn render_pass_description_checks(
    device: &Device,
    create_info: &RenderPassCreateInfo<'_>,
) -> Result<()> {
    let raw = create_info.as_raw();
    // SAFETY: the safe setters store each array with its count.
    let (attachments, subpasses, dependencies) = unsafe {
        (
            crate::state::raw_slice(raw.p_attachments, raw.attachment_count),
            crate::state::raw_slice(raw.p_subpasses, raw.subpass_count),
            crate::state::raw_slice(raw.p_dependencies, raw.dependency_count),
        )
    };
    for (i, a) in attachments.iter().enumerate() {
        if a.format == vk::Format::UNDEFINED {
            refuse(
                "VUID-VkAttachmentDescription-format-06698",
                format!("pAttachments[{i}].format is VK_FORMAT_UNDEFINED"),
            )?;
        }
        let both = crate::formats::aspects(a.format).is_some_and(|x| {
            x.contains(vk::ImageAspectFlags::DEPTH | vk::ImageAspectFlags::STENCIL)
        });
        if !both {
            continue;
        }
        for (layout, depth) in ONE_ASPECT_LAYOUTS {
            let (initial, last) = if depth {
                (
                    "VUID-VkAttachmentDescription-format-06242",
                    "VUID-VkAttachmentDescription-format-06243",
                )
            } else {
                (
                    "VUID-VkAttachmentDescription-format-06906",
                    "VUID-VkAttachmentDescription-format-06907",
                )
            };
            if a.initial_layout == layout {
                refuse(initial, format!("pAttachments[{i}] ({:?}, with depth and stencil) starts in {layout:?}, which names one aspect", a.format))?;
            }
            if a.final_layout == layout {
                refuse(last, format!("pAttachments[{i}] ({:?}, with depth and stencil) ends in {layout:?}, which names one aspect", a.format))?;
            }
        }
    }
    // Each subpass's references, as (attachment, layout, is an input attachment).
    let uses: Vec<Vec<(u32, vk::ImageLayout, bool)>> = subpasses
        .iter()
        .map(|s| {
            let mut refs = Vec::new();
            // SAFETY: the safe setters store each array with its count (the resolve
            // array with the color count).
            unsafe {
                for r in crate::state::raw_slice(s.p_input_attachments, s.input_attachment_count) {
                    refs.push((r.attachment, r.layout, true));
                }
                for r in crate::state::raw_slice(s.p_color_attachments, s.color_attachment_count) {
                    refs.push((r.attachment, r.layout, false));
                }
                if !s.p_resolve_attachments.is_null() {
                    for r in
                        crate::state::raw_slice(s.p_resolve_attachments, s.color_attachment_count)
                    {
                        refs.push((r.attachment, r.layout, false));
                    }
                }
                if let Some(d) = s.p_depth_stencil_attachment.as_ref() {
                    refs.push((d.attachment, d.layout, false));
                }
            }
            refs.retain(|r| r.0 != vk::ATTACHMENT_UNUSED);
            refs
        })
        .collect();
    for (i, s) in subpasses.iter().enumerate() {
        // SAFETY: as above.
        if let Some(d) = unsafe { s.p_depth_stencil_attachment.as_ref() } {
            if d.attachment != vk::ATTACHMENT_UNUSED
                && matches!(
                    d.layout,
                    vk::ImageLayout::COLOR_ATTACHMENT_OPTIMAL
                        | vk::ImageLayout::SHADER_READ_ONLY_OPTIMAL
                )
            {
                refuse(
                    "VUID-VkSubpassDescription-attachment-06915",
                    format!(
                        "pSubpasses[{i}]'s depth/stencil attachment is in {:?}",
                        d.layout
                    ),
                )?;
            }
        }
    }
    for (n, a) in attachments.iter().enumerate() {
        let n = n as u32;
        let Some((i, first)) = uses
            .iter()
            .enumerate()
            .find(|(_, refs)| refs.iter().any(|r| r.0 == n))
        else {
            continue;
        };
        let refs: Vec<_> = first.iter().filter(|r| r.0 == n).collect();
        let clear = vk::AttachmentLoadOp::CLEAR;
        for r in &refs {
            let read_only = matches!(
                r.1,
                vk::ImageLayout::SHADER_READ_ONLY_OPTIMAL
                    | vk::ImageLayout::DEPTH_STENCIL_READ_ONLY_OPTIMAL
            );
            if a.load_op == clear && read_only {
                refuse(
                    "VUID-VkRenderPassCreateInfo-pAttachments-00836",
                    format!(
                        "pAttachments[{n}] is cleared, but its first use (subpass {i}) is in {:?}",
                        r.1
                    ),
                )?;
            }
            if a.stencil_load_op == clear && read_only {
                refuse(
                    "VUID-VkRenderPassCreateInfo-pAttachments-02511",
                    format!("pAttachments[{n}]'s stencil is cleared, but its first use (subpass {i}) is in {:?}", r.1),
                )?;
            }
            if a.load_op == clear
                && r.1 == vk::ImageLayout::DEPTH_READ_ONLY_STENCIL_ATTACHMENT_OPTIMAL
            {
                refuse(
                    "VUID-VkRenderPassCreateInfo-pAttachments-01566",
                    format!("pAttachments[{n}] is cleared, but its first use (subpass {i}) reads its depth only"),
                )?;
            }
            if a.stencil_load_op == clear
                && r.1 == vk::ImageLayout::DEPTH_ATTACHMENT_STENCIL_READ_ONLY_OPTIMAL
            {
                refuse(
                    "VUID-VkRenderPassCreateInfo-pAttachments-01567",
                    format!("pAttachments[{n}]'s stencil is cleared, but its first use (subpass {i}) reads its stencil only"),
                )?;
            }
        }
        let only_input = refs.iter().all(|r| r.2);
        if only_input && a.load_op == clear {
            refuse(
                "VUID-VkSubpassDescription-loadOp-00846",
                format!("pAttachments[{n}] is first used as an input attachment only (subpass {i}), so it must not be cleared"),
            )?;
        }
    }
    subpass_dependency_checks(device, raw, dependencies)?;
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
