//! The checks of render pass creation over its subpass dependencies: stages,
//! accesses, self-dependencies and view offsets.

use super::refuse;
use super::render_pass::{multiview_view_count, Pass, Rule};
use crate::handles::*;
use crate::structs::RenderPassCreateInfo;
use crate::Result;
use ash::vk;

/// The dependencies of either render pass creation, and its view masks, offsets
/// and correlation masks, each rule under the version's VUID.
pub(super) fn subpass_dependency_checks(device: &Device, pass: &Pass) -> Result<()> {
    let external = vk::SUBPASS_EXTERNAL;
    let sync2 = device.live().with_features(|f| f.v13.synchronization2) != vk::FALSE;
    let masks = pass.view_masks();
    let graphics = super::stages::GRAPHICS
        | vk::PipelineStageFlags::ALL_GRAPHICS
        | vk::PipelineStageFlags::ALL_COMMANDS;
    let fb = super::stages::FRAMEBUFFER_SPACE;
    for (i, d) in pass.dependencies.iter().enumerate() {
        let at = format!("pDependencies[{i}]");
        let (src_subpass, dst_subpass) = d.subpasses;
        let (src_stage, dst_stage) = d.stages;
        let (src_access, dst_access) = d.access;
        if src_subpass == external && dst_subpass == external {
            refuse(
                pass.vuid(BOTH_EXTERNAL),
                format!("{at} has VK_SUBPASS_EXTERNAL at both ends"),
            )?;
        }
        if src_subpass != external && dst_subpass != external && src_subpass > dst_subpass {
            refuse(
                pass.vuid(ORDER),
                format!(
                    "{at}'s srcSubpass ({src_subpass}) is after its dstSubpass ({dst_subpass})"
                ),
            )?;
        }
        if !sync2 && src_stage.is_empty() {
            refuse(
                pass.vuid(SRC_ZERO),
                format!("{at}'s srcStageMask is 0, and synchronization2 is not enabled"),
            )?;
        }
        if !sync2 && dst_stage.is_empty() {
            refuse(
                pass.vuid(DST_ZERO),
                format!("{at}'s dstStageMask is 0, and synchronization2 is not enabled"),
            )?;
        }
        if src_subpass != external && !graphics.contains(src_stage) {
            refuse(
                pass.vuid(SRC_GRAPHICS),
                format!(
                    "{at}'s srcStageMask ({src_stage:?}) names a stage a graphics pipeline has not"
                ),
            )?;
        }
        if dst_subpass != external && !graphics.contains(dst_stage) {
            refuse(
                pass.vuid(DST_GRAPHICS),
                format!(
                    "{at}'s dstStageMask ({dst_stage:?}) names a stage a graphics pipeline has not"
                ),
            )?;
        }
        if let Some(a) = super::stages::unsupported_access(src_access, src_stage) {
            refuse(
                pass.vuid(SRC_ACCESS),
                format!("{at}'s srcAccessMask has {a:?}, which no stage of its srcStageMask ({src_stage:?}) supports"),
            )?;
        }
        if let Some(a) = super::stages::unsupported_access(dst_access, dst_stage) {
            refuse(
                pass.vuid(DST_ACCESS),
                format!("{at}'s dstAccessMask has {a:?}, which no stage of its dstStageMask ({dst_stage:?}) supports"),
            )?;
        }
        if src_subpass == dst_subpass && src_subpass != external {
            let (src, dst) = (
                super::stages::expand(src_stage),
                super::stages::expand(dst_stage),
            );
            let logical =
                vk::PipelineStageFlags::TOP_OF_PIPE | vk::PipelineStageFlags::BOTTOM_OF_PIPE;
            if src.intersects(fb) && !fb.contains(dst & !logical) {
                refuse(
                    pass.vuid(SELF_FRAMEBUFFER),
                    format!("{at} is a self-dependency whose srcStageMask has a framebuffer-space stage, but its dstStageMask ({dst_stage:?}) has others"),
                )?;
            }
            if src.intersects(fb)
                && dst.intersects(fb)
                && !d.flags.contains(vk::DependencyFlags::BY_REGION)
            {
                refuse(
                    pass.vuid(SELF_BY_REGION),
                    format!("{at} is a self-dependency between framebuffer-space stages without VK_DEPENDENCY_BY_REGION_BIT"),
                )?;
            }
            let views = masks
                .get(src_subpass as usize)
                .map_or(0, |m| m.count_ones());
            if views > 1 && !d.flags.contains(vk::DependencyFlags::VIEW_LOCAL) {
                refuse(
                    pass.vuid(SELF_VIEW_LOCAL),
                    format!("{at} is a self-dependency of a subpass of {views} views without VK_DEPENDENCY_VIEW_LOCAL_BIT"),
                )?;
            }
        }
        if let Some(offset) = d.view_offset.filter(|o| *o != 0) {
            if src_subpass == dst_subpass {
                refuse(
                    pass.vuid(OFFSET_SELF),
                    format!("{at} has view offset {offset} but the same subpass at both ends"),
                )?;
            }
            // The second version's rule for this is its struct's own (checked by
            // the emitted checks).
            if !pass.second && !d.flags.contains(vk::DependencyFlags::VIEW_LOCAL) {
                refuse(
                    "VUID-VkRenderPassCreateInfo-pNext-02512",
                    format!("{at} has view offset {offset} but is not view-local"),
                )?;
            }
        }
    }
    // The second version's view masks are checked with its subpasses' references.
    if !pass.second {
        let multiview_on = device.live().with_features(|f| f.v11.multiview) != vk::FALSE;
        let max = if masks.iter().any(|m| *m != 0) {
            multiview_view_count(device)
        } else {
            None
        };
        for (i, m) in masks.iter().enumerate() {
            if *m != 0 && !multiview_on {
                refuse(
                    "VUID-VkRenderPassMultiviewCreateInfo-multiview-06555",
                    format!("pViewMasks[{i}] is {m:#x}, but the multiview feature is not enabled"),
                )?;
            }
            let highest = 32 - m.leading_zeros();
            if let Some(max) = max.filter(|max| *m != 0 && highest > *max) {
                refuse(
                    "VUID-VkRenderPassMultiviewCreateInfo-pViewMasks-06697",
                    format!(
                        "pViewMasks[{i}] ({m:#x}) names view {}, past maxMultiviewViewCount ({max})",
                        highest - 1
                    ),
                )?;
            }
        }
    }
    let mut seen = 0u32;
    for (i, c) in pass.correlations.iter().enumerate() {
        if seen & c != 0 {
            refuse(
                pass.vuid(CORRELATION),
                format!("the correlation mask {i} ({c:#x}) shares a view with an earlier mask"),
            )?;
        }
        seen |= c;
    }
    Ok(())
}

const BOTH_EXTERNAL: Rule = (
    "VUID-VkSubpassDependency-srcSubpass-00865",
    "VUID-VkSubpassDependency2-srcSubpass-03085",
);
const ORDER: Rule = (
    "VUID-VkSubpassDependency-srcSubpass-00864",
    "VUID-VkSubpassDependency2-srcSubpass-03084",
);
const SRC_ZERO: Rule = (
    "VUID-VkSubpassDependency-srcStageMask-03937",
    "VUID-VkSubpassDependency2-srcStageMask-03937",
);
const DST_ZERO: Rule = (
    "VUID-VkSubpassDependency-dstStageMask-03937",
    "VUID-VkSubpassDependency2-dstStageMask-03937",
);
const SRC_GRAPHICS: Rule = (
    "VUID-VkRenderPassCreateInfo-pDependencies-00837",
    "VUID-VkRenderPassCreateInfo2-pDependencies-03054",
);
const DST_GRAPHICS: Rule = (
    "VUID-VkRenderPassCreateInfo-pDependencies-00838",
    "VUID-VkRenderPassCreateInfo2-pDependencies-03055",
);
const SRC_ACCESS: Rule = (
    "VUID-VkSubpassDependency-srcAccessMask-00868",
    "VUID-VkSubpassDependency2-srcAccessMask-03088",
);
const DST_ACCESS: Rule = (
    "VUID-VkSubpassDependency-dstAccessMask-00869",
    "VUID-VkSubpassDependency2-dstAccessMask-03089",
);
const SELF_FRAMEBUFFER: Rule = (
    "VUID-VkSubpassDependency-srcSubpass-06809",
    "VUID-VkSubpassDependency2-srcSubpass-06810",
);
const SELF_BY_REGION: Rule = (
    "VUID-VkSubpassDependency-srcSubpass-02243",
    "VUID-VkSubpassDependency2-srcSubpass-02245",
);
const SELF_VIEW_LOCAL: Rule = (
    "VUID-VkSubpassDependency-srcSubpass-00872",
    "VUID-VkRenderPassCreateInfo2-pDependencies-03060",
);
const OFFSET_SELF: Rule = (
    "VUID-VkRenderPassCreateInfo-pNext-01930",
    "VUID-VkSubpassDependency2-viewOffset-02530",
);
const CORRELATION: Rule = (
    "VUID-VkRenderPassMultiviewCreateInfo-pCorrelationMasks-00841",
    "VUID-VkRenderPassCreateInfo2-pCorrelatedViewMasks-03056",
);

/// How a subpass uses an attachment, for the hazards between subpasses: the stage
/// an earlier use is waited for at, the stage a later one starts at, the access
/// type, whether it writes, its layout and how the message names it.
#[derive(Clone, Copy)]
struct AttachmentUse {
    subpass: u32,
    done_at: u64,
    starts_at: u64,
    access: u64,
    write: bool,
    layout: vk::ImageLayout,
    what: &'static str,
}

/// The uses of attachment `a` by each subpass that uses it, in order (a subpass
/// that both reads and writes it counts as writing).
fn attachment_uses(pass: &Pass, a: u32) -> Vec<AttachmentUse> {
    // COLOR_ATTACHMENT_OUTPUT, EARLY and LATE_FRAGMENT_TESTS, FRAGMENT_SHADER; the
    // attachment access types.
    const OUTPUT: u64 = 0x400;
    const EARLY: u64 = 0x100;
    const LATE: u64 = 0x200;
    const FRAGMENT: u64 = 0x80;
    const INPUT: u64 = 0x10;
    const COLOR_WRITE: u64 = 0x100;
    const DEPTH_READ: u64 = 0x200;
    const DEPTH_WRITE: u64 = 0x400;
    let read_only = |l: vk::ImageLayout| {
        use vk::ImageLayout as L;
        matches!(
            l,
            L::DEPTH_STENCIL_READ_ONLY_OPTIMAL
                | L::DEPTH_READ_ONLY_OPTIMAL
                | L::STENCIL_READ_ONLY_OPTIMAL
                | L::DEPTH_READ_ONLY_STENCIL_ATTACHMENT_OPTIMAL
                | L::READ_ONLY_OPTIMAL
        )
    };
    let mut uses = Vec::new();
    for (i, s) in pass.subpasses.iter().enumerate() {
        let subpass = i as u32;
        let at = |r: &&super::render_pass::Ref| r.attachment == a;
        let color = s.colors.iter().chain(s.resolves.iter().flatten()).find(at);
        let depth = s.depth.as_ref().filter(|r| r.attachment == a);
        let input = s.inputs.iter().find(at);
        let found = if let Some(r) = color {
            Some((
                OUTPUT,
                OUTPUT,
                COLOR_WRITE,
                true,
                r.layout,
                "a color or resolve attachment",
            ))
        } else if let Some(r) = depth.filter(|r| !read_only(r.layout)) {
            Some((
                LATE,
                EARLY,
                DEPTH_WRITE,
                true,
                r.layout,
                "its depth/stencil attachment",
            ))
        } else if let Some(r) = depth {
            Some((
                LATE,
                EARLY,
                DEPTH_READ,
                false,
                r.layout,
                "its read-only depth/stencil attachment",
            ))
        } else {
            input.map(|r| {
                (
                    FRAGMENT,
                    FRAGMENT,
                    INPUT,
                    false,
                    r.layout,
                    "an input attachment",
                )
            })
        };
        if let Some((done_at, starts_at, access, write, layout, what)) = found {
            uses.push(AttachmentUse {
                subpass,
                done_at,
                starts_at,
                access,
                write,
                layout,
                what,
            });
        }
    }
    uses
}

/// The pairs of uses of one attachment by two subpasses, one of which writes, that
/// no subpass dependency orders: neither one between the two whose scopes hold
/// both uses, nor a chain of dependencies through the subpasses between (its masks
/// are not compared, so no correct render pass is found wanting).
fn unordered(pass: &Pass) -> Vec<(u32, AttachmentUse, AttachmentUse)> {
    use crate::state::hazards::Barrier;
    let external = vk::SUBPASS_EXTERNAL;
    let linked = |from: u32, to: u32| -> bool {
        // Whether a chain of dependencies leads from `from` to `to`.
        let mut reached = vec![from];
        let mut at = 0;
        while at < reached.len() {
            let s = reached[at];
            for d in &pass.dependencies {
                let (src, dst) = d.subpasses;
                if src == s && dst != external && dst > s && !reached.contains(&dst) {
                    reached.push(dst);
                }
            }
            at += 1;
        }
        reached.contains(&to)
    };
    let mut found = Vec::new();
    for a in 0..pass.attachments.len() as u32 {
        let uses = attachment_uses(pass, a);
        for pair in uses.windows(2) {
            let (before, after) = (pair[0], pair[1]);
            if !before.write && !after.write {
                continue;
            }
            let ordered = pass
                .dependencies
                .iter()
                .filter(|d| d.subpasses == (before.subpass, after.subpass))
                .any(|d| {
                    let b = Barrier::new(
                        u64::from(d.stages.0.as_raw()),
                        u64::from(d.access.0.as_raw()),
                        u64::from(d.stages.1.as_raw()),
                        u64::from(d.access.1.as_raw()),
                    );
                    b.orders(
                        (before.done_at, before.access, before.write),
                        (after.starts_at, after.access),
                    )
                });
            let (b, e) = (before.subpass, after.subpass);
            let chained = (b + 1..e).any(|k| linked(b, k) && linked(k, e));
            if !ordered && !chained {
                found.push((a, before, after));
            }
        }
    }
    found
}

/// A later subpass that reads or writes an attachment an earlier one wrote (or
/// writes one it read) needs a subpass dependency between them that orders the two
/// uses: without one the subpasses may run in any order, or at once. A path through
/// other subpasses' dependencies counts (its masks are not compared), so no correct
/// render pass is refused. The error names the hazard as the validation layer's
/// synchronization validation reports it when the render pass runs.
pub(super) fn subpass_hazard_checks(pass: &Pass) -> Result<()> {
    if let Some((a, before, after)) = unordered(pass).first() {
        let kind = match (before.write, after.write) {
            (true, true) => "SYNC-HAZARD-WRITE-AFTER-WRITE",
            // A layout transition between them writes.
            (true, false) if before.layout != after.layout => "SYNC-HAZARD-WRITE-AFTER-WRITE",
            (true, false) => "SYNC-HAZARD-READ-AFTER-WRITE",
            _ => "SYNC-HAZARD-WRITE-AFTER-READ",
        };
        let fix = if before.write {
            "a dependency from the stage that writes it, with its access type, to the stage and access type that use it"
        } else {
            "a dependency from the stage that reads it to the stage that writes it"
        };
        refuse(
            kind,
            format!(
                "pSubpasses[{}] uses attachment {a} as {} after pSubpasses[{}] uses it as {}, and no subpass dependency from {} to {} orders the two: it needs {fix} (`RenderPassCreateInfo::needed_dependencies` adds it)",
                after.subpass, after.what, before.subpass, before.what, before.subpass, after.subpass
            ),
        )?;
    }
    Ok(())
}

impl RenderPassCreateInfo<'_> {
    /// The subpass dependencies the render pass needs: its own, one for each pair of
    /// subpasses that use an attachment in turn, one of them writing, that none of
    /// its own orders (from the earlier use's stage and access type to the later
    /// one's, by region: what [`Device::create_render_pass`] refuses without), and
    /// for each subpass that uses an attachment first or last with no dependency
    /// with the outside, one from every command before the render pass instance, or
    /// to every command after it. The masks are those of the uses, so the
    /// dependencies are as narrow as the attachments allow; what comes before and
    /// after the instance is not known here, so the outside's side is every
    /// command. Pass them back with `dependencies`:
    ///
    /// ```no_run
    /// # fn f(device: &tuff::Device, attachments: &[tuff::vk::AttachmentDescription], subpasses: &[tuff::SubpassDescription<'_>]) -> tuff::Result<()> {
    /// let info = tuff::RenderPassCreateInfo::new()
    ///     .attachments(attachments)
    ///     .subpasses(subpasses);
    /// let dependencies = info.needed_dependencies();
    /// let render_pass = device.create_render_pass(&info.dependencies(&dependencies))?;
    /// # Ok(()) }
    /// ```
    pub fn needed_dependencies(&self) -> Vec<vk::SubpassDependency> {
        needed_dependencies(&Pass::of(self))
    }
}

/// [`RenderPassCreateInfo::needed_dependencies`] of a render pass read.
fn needed_dependencies(pass: &Pass) -> Vec<vk::SubpassDependency> {
    use vk::{AccessFlags as A, PipelineStageFlags as P};
    let external = vk::SUBPASS_EXTERNAL;
    let mut out: Vec<vk::SubpassDependency> = pass
        .dependencies
        .iter()
        .map(|d| vk::SubpassDependency {
            src_subpass: d.subpasses.0,
            dst_subpass: d.subpasses.1,
            src_stage_mask: d.stages.0,
            dst_stage_mask: d.stages.1,
            src_access_mask: d.access.0,
            dst_access_mask: d.access.1,
            dependency_flags: d.flags,
        })
        .collect();
    let own = out.len();
    // One dependency per pair of subpasses: a second need widens the first.
    let add = |out: &mut Vec<vk::SubpassDependency>, d: vk::SubpassDependency| match out[own..]
        .iter_mut()
        .find(|o| (o.src_subpass, o.dst_subpass) == (d.src_subpass, d.dst_subpass))
    {
        Some(o) => {
            o.src_stage_mask |= d.src_stage_mask;
            o.dst_stage_mask |= d.dst_stage_mask;
            o.src_access_mask |= d.src_access_mask;
            o.dst_access_mask |= d.dst_access_mask;
            o.dependency_flags &= d.dependency_flags;
        }
        None => out.push(d),
    };
    let stages = |m: u64| P::from_raw(m as u32);
    let access = |m: u64| A::from_raw(m as u32);
    for (_, before, after) in unordered(pass) {
        let (src_access, dst_access) = match before.write {
            true => (access(before.access), access(after.access)),
            // After a read, an execution dependency is enough.
            false => (A::empty(), A::empty()),
        };
        add(
            &mut out,
            vk::SubpassDependency {
                src_subpass: before.subpass,
                dst_subpass: after.subpass,
                src_stage_mask: stages(before.done_at),
                dst_stage_mask: stages(after.starts_at),
                src_access_mask: src_access,
                dst_access_mask: dst_access,
                dependency_flags: vk::DependencyFlags::BY_REGION,
            },
        );
    }
    let has = |src: u32, dst: u32| pass.dependencies.iter().any(|d| d.subpasses == (src, dst));
    for a in 0..pass.attachments.len() as u32 {
        let uses = attachment_uses(pass, a);
        let (Some(first), Some(last)) = (uses.first(), uses.last()) else {
            continue;
        };
        // The load operation and layout transition at the first use, the store
        // operation and final transition at the last: each reads or writes the
        // attachment as its kind (color or depth/stencil) does.
        let depth = uses.iter().any(|u| u.what.contains("depth"));
        let (read_write, store) = match depth {
            true => (
                A::DEPTH_STENCIL_ATTACHMENT_READ | A::DEPTH_STENCIL_ATTACHMENT_WRITE,
                (P::LATE_FRAGMENT_TESTS, A::DEPTH_STENCIL_ATTACHMENT_WRITE),
            ),
            false => (
                A::COLOR_ATTACHMENT_READ | A::COLOR_ATTACHMENT_WRITE,
                (P::COLOR_ATTACHMENT_OUTPUT, A::COLOR_ATTACHMENT_WRITE),
            ),
        };
        let load_stage = match depth {
            true => P::EARLY_FRAGMENT_TESTS | P::LATE_FRAGMENT_TESTS,
            false => P::COLOR_ATTACHMENT_OUTPUT,
        };
        if !has(external, first.subpass) {
            add(
                &mut out,
                vk::SubpassDependency {
                    src_subpass: external,
                    dst_subpass: first.subpass,
                    src_stage_mask: P::ALL_COMMANDS,
                    dst_stage_mask: load_stage | stages(first.starts_at),
                    src_access_mask: A::MEMORY_WRITE,
                    dst_access_mask: read_write | access(first.access),
                    dependency_flags: vk::DependencyFlags::empty(),
                },
            );
        }
        if !has(last.subpass, external) {
            add(
                &mut out,
                vk::SubpassDependency {
                    src_subpass: last.subpass,
                    dst_subpass: external,
                    src_stage_mask: store.0 | stages(last.done_at),
                    dst_stage_mask: P::ALL_COMMANDS,
                    src_access_mask: store.1,
                    dst_access_mask: A::MEMORY_READ | A::MEMORY_WRITE,
                    dependency_flags: vk::DependencyFlags::empty(),
                },
            );
        }
    }
    out
}
