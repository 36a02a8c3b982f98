//! Render pass creation: what each subpass references is checked against the render
//! pass's attachments (formats and their features, sample counts, layouts,
//! preserved attachments) and its view masks against each other.
//!
//! Each case changes one valid render pass so that it breaks one rule, and builds it
//! through both `vkCreateRenderPass` and `vkCreateRenderPass2` (where the rule has a
//! VUID there). tuff must refuse the safe call with the rule's VUID; the validation
//! layer, for the `_unchecked` twin (with a messenger that makes it skip a call it
//! finds wrong), must name that VUID and nothing else but the rules the case says the
//! same change breaks, or say nothing (the rule is then proven by the error alone).
//!
//! SAFETY of the `unsafe` blocks: `create_render_pass` and `create_render_pass2` are
//! `unsafe` for rules their `# Safety` sections list, which these render passes keep
//! but for the one each case breaks on purpose, which tuff refuses and the layer
//! skips.

#[path = "common/tuff_setup.rs"]
mod tuff_setup;
#[path = "common/vulkan.rs"]
mod vulkan;

use tuff::vk;
use tuff_setup::Setup;

const GENERAL: vk::ImageLayout = vk::ImageLayout::GENERAL;
const COLOR: vk::ImageLayout = vk::ImageLayout::COLOR_ATTACHMENT_OPTIMAL;
const READ: vk::ImageLayout = vk::ImageLayout::SHADER_READ_ONLY_OPTIMAL;
const DEPTH: vk::ImageLayout = vk::ImageLayout::DEPTH_STENCIL_ATTACHMENT_OPTIMAL;
const ONE: vk::SampleCountFlags = vk::SampleCountFlags::TYPE_1;
const FOUR: vk::SampleCountFlags = vk::SampleCountFlags::TYPE_4;

/// The render pass's attachments, by index: one- and four-sample color, a
/// depth/stencil one, a second one-sample color, a second four-sample color, a
/// one-sample color of another format, a compressed format no attachment can have,
/// and a four-sample depth/stencil one.
const ATTACHMENTS: [(vk::Format, vk::SampleCountFlags); 8] = [
    (vk::Format::R8G8B8A8_UNORM, ONE),
    (vk::Format::R8G8B8A8_UNORM, FOUR),
    (vk::Format::D32_SFLOAT_S8_UINT, ONE),
    (vk::Format::R8G8B8A8_UNORM, ONE),
    (vk::Format::R8G8B8A8_UNORM, FOUR),
    (vk::Format::R8_UNORM, ONE),
    (vk::Format::BC1_RGBA_UNORM_BLOCK, ONE),
    (vk::Format::D32_SFLOAT_S8_UINT, FOUR),
];

/// A render pass of one subpass (or as many as it has view masks), in terms both
/// create infos can express.
#[derive(Clone)]
struct Spec {
    inputs: Vec<(u32, vk::ImageLayout, vk::ImageAspectFlags)>,
    colors: Vec<(u32, vk::ImageLayout)>,
    resolves: Option<Vec<(u32, vk::ImageLayout)>>,
    depth: Option<(u32, vk::ImageLayout)>,
    preserve: Vec<u32>,
    /// One view mask per subpass; empty for one subpass without multiview (no
    /// `VkRenderPassMultiviewCreateInfo` is chained to `vkCreateRenderPass`'s).
    view_masks: Vec<u32>,
    correlation_masks: Vec<u32>,
    /// A dependency of subpass 0 on itself, with these flags.
    self_dependency: Option<vk::DependencyFlags>,
    /// View offsets of the multiview info, one per dependency it describes.
    view_offsets: Vec<i32>,
}

impl Default for Spec {
    fn default() -> Self {
        Spec {
            inputs: vec![],
            colors: vec![(0, COLOR)],
            resolves: None,
            depth: None,
            preserve: vec![],
            view_masks: vec![],
            correlation_masks: vec![],
            self_dependency: None,
            view_offsets: vec![],
        }
    }
}

fn descriptions() -> Vec<vk::AttachmentDescription> {
    ATTACHMENTS
        .iter()
        .map(|&(format, samples)| vk::AttachmentDescription {
            format,
            samples,
            load_op: vk::AttachmentLoadOp::DONT_CARE,
            store_op: vk::AttachmentStoreOp::DONT_CARE,
            stencil_load_op: vk::AttachmentLoadOp::DONT_CARE,
            stencil_store_op: vk::AttachmentStoreOp::DONT_CARE,
            initial_layout: vk::ImageLayout::UNDEFINED,
            final_layout: GENERAL,
            ..Default::default()
        })
        .collect()
}

fn dependency(flags: vk::DependencyFlags) -> vk::SubpassDependency {
    let stage = vk::PipelineStageFlags::COLOR_ATTACHMENT_OUTPUT;
    vk::SubpassDependency {
        src_subpass: 0,
        dst_subpass: 0,
        src_stage_mask: stage,
        dst_stage_mask: stage,
        src_access_mask: vk::AccessFlags::COLOR_ATTACHMENT_WRITE,
        dst_access_mask: vk::AccessFlags::COLOR_ATTACHMENT_WRITE,
        dependency_flags: flags,
    }
}

/// `spec` through `vkCreateRenderPass`: the safe call's result, and what the layer
/// said of the unchecked one.
fn create1(s: &Setup, spec: &Spec) -> (tuff::Result<()>, Vec<String>) {
    let r = |(attachment, layout): (u32, vk::ImageLayout)| vk::AttachmentReference {
        attachment,
        layout,
    };
    let inputs: Vec<_> = spec.inputs.iter().map(|&(a, l, _)| r((a, l))).collect();
    let colors: Vec<_> = spec.colors.iter().copied().map(r).collect();
    let resolves: Option<Vec<_>> = spec
        .resolves
        .as_ref()
        .map(|v| v.iter().copied().map(r).collect());
    let depth = spec.depth.map(r);
    let mut subpass = tuff::SubpassDescription::new()
        .pipeline_bind_point(vk::PipelineBindPoint::GRAPHICS)
        .input_attachments(&inputs)
        .color_attachments(&colors)
        .depth_stencil_attachment(depth.as_ref())
        .preserve_attachments(&spec.preserve);
    if let Some(resolves) = &resolves {
        subpass = subpass
            .resolve_attachments(resolves)
            .expect("one per color");
    }
    let subpasses = vec![subpass; spec.view_masks.len().max(1)];
    let attachments = descriptions();
    let dependencies: Vec<_> = spec.self_dependency.into_iter().map(dependency).collect();
    let mut multiview = tuff::RenderPassMultiviewCreateInfo::new()
        .view_masks(&spec.view_masks)
        .view_offsets(&spec.view_offsets)
        .correlation_masks(&spec.correlation_masks);
    let mut info = tuff::RenderPassCreateInfo::new()
        .attachments(&attachments)
        .subpasses(&subpasses)
        .dependencies(&dependencies);
    if !spec.view_masks.is_empty() {
        info = info.push_next(&mut multiview);
    }
    let safe = s.device.create_render_pass(&info).map(drop);
    let layer = under_layer(s, || {
        let _ = unsafe { s.device.create_render_pass_unchecked(&info) };
    });
    (safe, layer)
}

/// `spec` through `vkCreateRenderPass2`.
fn create2(s: &Setup, spec: &Spec) -> (tuff::Result<()>, Vec<String>) {
    let r = |&(attachment, layout): &(u32, vk::ImageLayout)| {
        tuff::AttachmentReference2::new()
            .attachment(attachment)
            .layout(layout)
    };
    let inputs: Vec<_> = spec
        .inputs
        .iter()
        .map(|&(a, l, aspect)| r(&(a, l)).aspect_mask(aspect))
        .collect();
    let colors: Vec<_> = spec.colors.iter().map(r).collect();
    let resolves: Option<Vec<_>> = spec.resolves.as_ref().map(|v| v.iter().map(r).collect());
    let depth = spec.depth.as_ref().map(r);
    let subpass = |view_mask| {
        let mut subpass = tuff::SubpassDescription2::new()
            .pipeline_bind_point(vk::PipelineBindPoint::GRAPHICS)
            .view_mask(view_mask)
            .input_attachments(&inputs)
            .color_attachments(&colors)
            .depth_stencil_attachment(depth.as_ref())
            .preserve_attachments(&spec.preserve);
        if let Some(resolves) = &resolves {
            subpass = subpass
                .resolve_attachments(resolves)
                .expect("one per color");
        }
        subpass
    };
    let subpasses: Vec<_> = if spec.view_masks.is_empty() {
        vec![subpass(0)]
    } else {
        spec.view_masks.iter().map(|&m| subpass(m)).collect()
    };
    let attachments: Vec<_> = descriptions()
        .iter()
        .map(|a| {
            tuff::AttachmentDescription2::new()
                .format(a.format)
                .samples(a.samples)
                .load_op(a.load_op)
                .store_op(a.store_op)
                .stencil_load_op(a.stencil_load_op)
                .stencil_store_op(a.stencil_store_op)
                .initial_layout(a.initial_layout)
                .final_layout(a.final_layout)
        })
        .collect();
    let dependencies: Vec<_> = spec
        .self_dependency
        .into_iter()
        .map(|flags| {
            let d = dependency(flags);
            tuff::SubpassDependency2::new()
                .src_subpass(d.src_subpass)
                .dst_subpass(d.dst_subpass)
                .src_stage_mask(d.src_stage_mask)
                .dst_stage_mask(d.dst_stage_mask)
                .src_access_mask(d.src_access_mask)
                .dst_access_mask(d.dst_access_mask)
                .dependency_flags(d.dependency_flags)
        })
        .collect();
    let info = tuff::RenderPassCreateInfo2::new()
        .attachments(&attachments)
        .subpasses(&subpasses)
        .dependencies(&dependencies)
        .correlated_view_masks(&spec.correlation_masks);
    let safe = s.device.create_render_pass2(&info).map(drop);
    let layer = under_layer(s, || {
        let _ = unsafe { s.device.create_render_pass2_unchecked(&info) };
    });
    (safe, layer)
}

/// Runs `unchecked` with the layer told to skip erroring calls, and returns what it
/// said.
fn under_layer(s: &Setup, unchecked: impl FnOnce()) -> Vec<String> {
    s.messages.take();
    s.messages.abort_on_error(true);
    unchecked();
    s.messages.abort_on_error(false);
    s.messages.take()
}

/// One case: the rule's VUID through each create info (`""` where it has none), the
/// rules the same change necessarily breaks too (which the layer may name beside
/// it, each with why), and the change.
struct Case {
    vuids: (&'static str, &'static str),
    also: &'static [&'static str],
    change: fn(&mut Spec),
}

const CASES: &[Case] = &[
    Case {
        vuids: (
            "VUID-VkSubpassDescription-attachment-00853",
            "VUID-VkSubpassDescription2-attachment-03073",
        ),
        also: &[],
        change: |s| s.preserve = vec![vk::ATTACHMENT_UNUSED],
    },
    Case {
        vuids: (
            "VUID-VkSubpassDescription-pPreserveAttachments-00854",
            "VUID-VkSubpassDescription2-pPreserveAttachments-03074",
        ),
        also: &[],
        change: |s| s.preserve = vec![0],
    },
    Case {
        vuids: (
            "VUID-VkSubpassDescription-pResolveAttachments-00847",
            "VUID-VkSubpassDescription2-pResolveAttachments-03065",
        ),
        also: &[],
        change: |s| {
            s.colors = vec![(vk::ATTACHMENT_UNUSED, COLOR)];
            s.resolves = Some(vec![(3, COLOR)]);
        },
    },
    Case {
        vuids: (
            "VUID-VkSubpassDescription-pResolveAttachments-00848",
            "VUID-VkSubpassDescription2-pResolveAttachments-03066",
        ),
        also: &[],
        change: |s| s.resolves = Some(vec![(3, COLOR)]),
    },
    Case {
        vuids: (
            "VUID-VkSubpassDescription-pResolveAttachments-00849",
            "VUID-VkSubpassDescription2-pResolveAttachments-03067",
        ),
        also: &[],
        change: |s| {
            s.colors = vec![(1, COLOR)];
            s.resolves = Some(vec![(4, COLOR)]);
        },
    },
    Case {
        vuids: (
            "VUID-VkSubpassDescription-pResolveAttachments-00850",
            "VUID-VkSubpassDescription2-pResolveAttachments-03068",
        ),
        also: &[],
        change: |s| {
            s.colors = vec![(1, COLOR)];
            s.resolves = Some(vec![(5, COLOR)]);
        },
    },
    Case {
        vuids: (
            "VUID-VkSubpassDescription-pInputAttachments-02647",
            "VUID-VkSubpassDescription2-pInputAttachments-02897",
        ),
        also: &[],
        change: |s| s.inputs = vec![(6, READ, vk::ImageAspectFlags::COLOR)],
    },
    Case {
        vuids: (
            "VUID-VkSubpassDescription-pColorAttachments-02648",
            "VUID-VkSubpassDescription2-pColorAttachments-02898",
        ),
        also: &[],
        change: |s| s.colors = vec![(6, COLOR)],
    },
    Case {
        vuids: (
            "VUID-VkSubpassDescription-pDepthStencilAttachment-02650",
            "VUID-VkSubpassDescription2-pDepthStencilAttachment-02900",
        ),
        also: &[],
        change: |s| s.depth = Some((3, DEPTH)),
    },
    Case {
        vuids: (
            "VUID-VkSubpassDescription-pColorAttachments-06868",
            "VUID-VkSubpassDescription2-multisampledRenderToSingleSampled-06872",
        ),
        also: &[],
        change: |s| s.colors = vec![(0, COLOR), (1, COLOR)],
    },
    Case {
        vuids: (
            "VUID-VkSubpassDescription-pDepthStencilAttachment-01418",
            "VUID-VkSubpassDescription2-multisampledRenderToSingleSampled-06872",
        ),
        also: &[],
        change: |s| s.depth = Some((7, DEPTH)),
    },
    Case {
        vuids: (
            "VUID-VkSubpassDescription-layout-02519",
            "VUID-VkSubpassDescription2-layout-02528",
        ),
        also: &[],
        change: |s| s.inputs = vec![(0, GENERAL, vk::ImageAspectFlags::COLOR)],
    },
    Case {
        vuids: (
            "VUID-VkSubpassDescription-pDepthStencilAttachment-04438",
            "VUID-VkSubpassDescription2-pDepthStencilAttachment-04440",
        ),
        // No format lavapipe has is both a color and a depth/stencil attachment, so
        // one attachment in both places lacks a feature one of them needs.
        also: &[
            "VUID-VkSubpassDescription-pDepthStencilAttachment-02650",
            "VUID-VkSubpassDescription2-pDepthStencilAttachment-02900",
        ],
        change: |s| s.depth = Some((0, COLOR)),
    },
    Case {
        vuids: ("", "VUID-VkSubpassDescription2-attachment-02800"),
        // The 1.3.239 layer also reads an empty mask of a color format as missing
        // the color aspect, under the rule of aspects present in the format.
        also: &["VUID-VkRenderPassCreateInfo2-attachment-02525"],
        change: |s| s.inputs = vec![(3, READ, vk::ImageAspectFlags::empty())],
    },
    Case {
        vuids: ("", "VUID-VkSubpassDescription2-attachment-02801"),
        // No format has a metadata aspect.
        also: &["VUID-VkRenderPassCreateInfo2-attachment-02525"],
        change: |s| {
            s.inputs = vec![(
                3,
                READ,
                vk::ImageAspectFlags::COLOR | vk::ImageAspectFlags::METADATA,
            )]
        },
    },
    Case {
        vuids: ("", "VUID-VkRenderPassCreateInfo2-attachment-02525"),
        also: &[],
        change: |s| s.inputs = vec![(3, READ, vk::ImageAspectFlags::DEPTH)],
    },
    Case {
        vuids: ("", "VUID-VkSubpassDescription2-viewMask-06706"),
        also: &[],
        change: |s| s.view_masks = vec![1 << 31],
    },
    Case {
        vuids: ("VUID-VkRenderPassCreateInfo-pNext-01929", ""),
        also: &[],
        change: |s| {
            s.view_masks = vec![1];
            s.self_dependency =
                Some(vk::DependencyFlags::BY_REGION | vk::DependencyFlags::VIEW_LOCAL);
            s.view_offsets = vec![0, 0];
        },
    },
    Case {
        vuids: (
            "VUID-VkRenderPassCreateInfo-pNext-02513",
            "VUID-VkRenderPassCreateInfo2-viewMask-03058",
        ),
        also: &[],
        change: |s| s.view_masks = vec![1, 0],
    },
    Case {
        vuids: (
            "VUID-VkRenderPassCreateInfo-pNext-02515",
            "VUID-VkRenderPassCreateInfo2-viewMask-03057",
        ),
        also: &[],
        change: |s| {
            s.view_masks = vec![0];
            s.correlation_masks = vec![1];
        },
    },
    Case {
        vuids: (
            "VUID-VkRenderPassCreateInfo-pNext-02514",
            "VUID-VkRenderPassCreateInfo2-viewMask-03059",
        ),
        also: &[],
        change: |s| {
            s.view_masks = vec![0];
            s.self_dependency =
                Some(vk::DependencyFlags::BY_REGION | vk::DependencyFlags::VIEW_LOCAL);
        },
    },
];

/// The render pass every case starts from is valid through both create infos, so
/// that a case cannot pass on a rule it did not break.
#[test]
fn the_cases_start_from_a_valid_render_pass() {
    let _serial = vulkan::serial();
    let s = tuff_setup::setup_full_features(true);
    let mut valid = vec![Spec::default()];
    // The parts the cases use, each valid on its own: a resolve, an input
    // attachment, a depth attachment, view masks with a view-local dependency.
    valid.push(Spec {
        colors: vec![(1, COLOR)],
        resolves: Some(vec![(3, COLOR)]),
        ..Spec::default()
    });
    valid.push(Spec {
        inputs: vec![(3, READ, vk::ImageAspectFlags::COLOR)],
        depth: Some((2, DEPTH)),
        preserve: vec![5],
        ..Spec::default()
    });
    valid.push(Spec {
        view_masks: vec![1],
        correlation_masks: vec![1],
        self_dependency: Some(vk::DependencyFlags::BY_REGION | vk::DependencyFlags::VIEW_LOCAL),
        view_offsets: vec![0],
        ..Spec::default()
    });
    for (n, spec) in valid.iter().enumerate() {
        for (version, (safe, layer)) in [(1, create1(&s, spec)), (2, create2(&s, spec))] {
            assert!(
                safe.is_ok(),
                "render pass {n} through version {version}: tuff refused it: {safe:?}"
            );
            assert!(
                layer.is_empty(),
                "render pass {n} through version {version}: the layer said:\n{}",
                layer.join("\n")
            );
        }
    }
}

/// Each case is refused with its rule's VUID through both create infos, and the
/// layer names the same rule or nothing.
#[test]
fn each_broken_reference_rule_is_refused_and_the_layer_agrees() {
    let _serial = vulkan::serial();
    let s = tuff_setup::setup_full_features(true);
    let mut failures = Vec::new();
    let (mut by_layer, mut alone) = (0, Vec::new());
    for case in CASES {
        let mut spec = Spec::default();
        (case.change)(&mut spec);
        for (vuid, (safe, layer)) in [
            (case.vuids.0, create1(&s, &spec)),
            (case.vuids.1, create2(&s, &spec)),
        ] {
            if vuid.is_empty() {
                continue;
            }
            match &safe {
                Err(tuff::Error::Validation { vuid: got, .. }) if *got == vuid => {}
                other => {
                    failures.push(format!("{vuid}: the safe method returned {other:?}"));
                    continue;
                }
            }
            let names = |m: &String, v: &str| m.contains(&format!("[ {v} ]"));
            if layer.is_empty() {
                alone.push(vuid);
            } else if layer.iter().any(|m| names(m, vuid))
                && layer
                    .iter()
                    .all(|m| names(m, vuid) || case.also.iter().any(|a| names(m, a)))
            {
                by_layer += 1;
            } else {
                failures.push(format!(
                    "{vuid}: the layer said something else:\n  {}",
                    layer.join("\n  ")
                ));
            }
        }
    }
    println!(
        "render pass references: the layer named {by_layer}, the error alone proves {} ({})",
        alone.len(),
        alone.join(", ")
    );
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

/// A `vkCreateRenderPass` create info a description case changes: attachments,
/// subpasses that all reference the same attachments, dependencies, and chained
/// multiview and input-aspect structs.
#[derive(Clone)]
struct Described {
    attachments: Vec<vk::AttachmentDescription>,
    subpasses: usize,
    inputs: Vec<vk::AttachmentReference>,
    colors: Vec<vk::AttachmentReference>,
    depth: Option<vk::AttachmentReference>,
    dependencies: Vec<vk::SubpassDependency>,
    view_masks: Vec<u32>,
    view_offsets: Vec<i32>,
    correlations: Vec<u32>,
    aspects: Vec<vk::InputAttachmentAspectReference>,
}

impl Default for Described {
    fn default() -> Self {
        let attachment = |format| vk::AttachmentDescription {
            format,
            samples: ONE,
            load_op: vk::AttachmentLoadOp::DONT_CARE,
            store_op: vk::AttachmentStoreOp::DONT_CARE,
            stencil_load_op: vk::AttachmentLoadOp::DONT_CARE,
            stencil_store_op: vk::AttachmentStoreOp::DONT_CARE,
            initial_layout: vk::ImageLayout::UNDEFINED,
            final_layout: GENERAL,
            ..Default::default()
        };
        Described {
            attachments: vec![
                attachment(vk::Format::R8G8B8A8_UNORM),
                attachment(vk::Format::D32_SFLOAT_S8_UINT),
            ],
            subpasses: 1,
            inputs: vec![],
            colors: vec![vk::AttachmentReference {
                attachment: 0,
                layout: COLOR,
            }],
            depth: None,
            dependencies: vec![],
            view_masks: vec![],
            view_offsets: vec![],
            correlations: vec![],
            aspects: vec![],
        }
    }
}

fn create_described(s: &Setup, d: &Described, unchecked: bool) -> (tuff::Result<()>, Vec<String>) {
    let subpass = tuff::SubpassDescription::new()
        .pipeline_bind_point(vk::PipelineBindPoint::GRAPHICS)
        .input_attachments(&d.inputs)
        .color_attachments(&d.colors)
        .depth_stencil_attachment(d.depth.as_ref());
    let subpasses = vec![subpass; d.subpasses];
    let mut multiview = tuff::RenderPassMultiviewCreateInfo::new()
        .view_masks(&d.view_masks)
        .view_offsets(&d.view_offsets)
        .correlation_masks(&d.correlations);
    let mut aspects =
        tuff::RenderPassInputAttachmentAspectCreateInfo::new().aspect_references(&d.aspects);
    let mut info = tuff::RenderPassCreateInfo::new()
        .attachments(&d.attachments)
        .subpasses(&subpasses)
        .dependencies(&d.dependencies);
    if !d.view_masks.is_empty() {
        info = info.push_next(&mut multiview);
    }
    if !d.aspects.is_empty() {
        info = info.push_next(&mut aspects);
    }
    let safe = s.device.create_render_pass(&info).map(drop);
    if !unchecked {
        return (safe, Vec::new());
    }
    let layer = under_layer(s, || {
        let _ = unsafe { s.device.create_render_pass_unchecked(&info) };
    });
    (safe, layer)
}

/// A dependency between two subpasses (or a subpass and itself).
fn between(
    src: u32,
    dst: u32,
    stages: (vk::PipelineStageFlags, vk::PipelineStageFlags),
    access: (vk::AccessFlags, vk::AccessFlags),
    flags: vk::DependencyFlags,
) -> vk::SubpassDependency {
    vk::SubpassDependency {
        src_subpass: src,
        dst_subpass: dst,
        src_stage_mask: stages.0,
        dst_stage_mask: stages.1,
        src_access_mask: access.0,
        dst_access_mask: access.1,
        dependency_flags: flags,
    }
}

type Described1 = (&'static str, &'static [&'static str], fn(&mut Described));

/// The description cases on a device with every feature (multiview,
/// separateDepthStencilLayouts, synchronization2).
const DESCRIBED: &[Described1] = &[
    ("VUID-VkAttachmentDescription-format-06698", &[], |d| {
        d.attachments.push(vk::AttachmentDescription {
            format: vk::Format::UNDEFINED,
            ..d.attachments[0]
        })
    }),
    ("VUID-VkAttachmentDescription-format-06242", &[], |d| {
        d.attachments[1].initial_layout = vk::ImageLayout::DEPTH_ATTACHMENT_OPTIMAL
    }),
    ("VUID-VkAttachmentDescription-format-06243", &[], |d| {
        d.attachments[1].final_layout = vk::ImageLayout::DEPTH_READ_ONLY_OPTIMAL
    }),
    ("VUID-VkAttachmentDescription-format-06906", &[], |d| {
        d.attachments[1].initial_layout = vk::ImageLayout::STENCIL_ATTACHMENT_OPTIMAL
    }),
    ("VUID-VkAttachmentDescription-format-06907", &[], |d| {
        d.attachments[1].final_layout = vk::ImageLayout::STENCIL_READ_ONLY_OPTIMAL
    }),
    ("VUID-VkRenderPassCreateInfo-pAttachments-00836", &[], |d| {
        d.attachments[1].load_op = vk::AttachmentLoadOp::CLEAR;
        d.depth = Some(vk::AttachmentReference {
            attachment: 1,
            layout: vk::ImageLayout::DEPTH_STENCIL_READ_ONLY_OPTIMAL,
        });
    }),
    ("VUID-VkRenderPassCreateInfo-pAttachments-02511", &[], |d| {
        d.attachments[1].stencil_load_op = vk::AttachmentLoadOp::CLEAR;
        d.depth = Some(vk::AttachmentReference {
            attachment: 1,
            layout: vk::ImageLayout::DEPTH_STENCIL_READ_ONLY_OPTIMAL,
        });
    }),
    ("VUID-VkRenderPassCreateInfo-pAttachments-01566", &[], |d| {
        d.attachments[1].load_op = vk::AttachmentLoadOp::CLEAR;
        d.depth = Some(vk::AttachmentReference {
            attachment: 1,
            layout: vk::ImageLayout::DEPTH_READ_ONLY_STENCIL_ATTACHMENT_OPTIMAL,
        });
    }),
    ("VUID-VkRenderPassCreateInfo-pAttachments-01567", &[], |d| {
        d.attachments[1].stencil_load_op = vk::AttachmentLoadOp::CLEAR;
        d.depth = Some(vk::AttachmentReference {
            attachment: 1,
            layout: vk::ImageLayout::DEPTH_ATTACHMENT_STENCIL_READ_ONLY_OPTIMAL,
        });
    }),
    ("VUID-VkSubpassDescription-loadOp-00846", &[], |d| {
        d.attachments.push(vk::AttachmentDescription {
            load_op: vk::AttachmentLoadOp::CLEAR,
            ..d.attachments[0]
        });
        d.inputs = vec![vk::AttachmentReference {
            attachment: 2,
            layout: GENERAL,
        }];
    }),
    ("VUID-VkSubpassDescription-attachment-06915", &[], |d| {
        d.depth = Some(vk::AttachmentReference {
            attachment: 1,
            layout: COLOR,
        });
    }),
    (
        "VUID-VkRenderPassCreateInfo-pDependencies-00837",
        &[],
        |d| {
            d.dependencies = vec![between(
                0,
                vk::SUBPASS_EXTERNAL,
                (
                    vk::PipelineStageFlags::TRANSFER,
                    vk::PipelineStageFlags::TRANSFER,
                ),
                (vk::AccessFlags::empty(), vk::AccessFlags::empty()),
                vk::DependencyFlags::empty(),
            )];
        },
    ),
    (
        "VUID-VkRenderPassCreateInfo-pDependencies-00838",
        &[],
        |d| {
            d.dependencies = vec![between(
                vk::SUBPASS_EXTERNAL,
                0,
                (
                    vk::PipelineStageFlags::TRANSFER,
                    vk::PipelineStageFlags::COMPUTE_SHADER,
                ),
                (vk::AccessFlags::empty(), vk::AccessFlags::empty()),
                vk::DependencyFlags::empty(),
            )];
        },
    ),
    ("VUID-VkSubpassDependency-srcSubpass-00864", &[], |d| {
        d.subpasses = 2;
        let color = vk::PipelineStageFlags::COLOR_ATTACHMENT_OUTPUT;
        d.dependencies = vec![between(
            1,
            0,
            (color, color),
            (vk::AccessFlags::empty(), vk::AccessFlags::empty()),
            vk::DependencyFlags::empty(),
        )];
    }),
    ("VUID-VkSubpassDependency-srcSubpass-00865", &[], |d| {
        let color = vk::PipelineStageFlags::COLOR_ATTACHMENT_OUTPUT;
        d.dependencies = vec![between(
            vk::SUBPASS_EXTERNAL,
            vk::SUBPASS_EXTERNAL,
            (color, color),
            (vk::AccessFlags::empty(), vk::AccessFlags::empty()),
            vk::DependencyFlags::empty(),
        )];
    }),
    ("VUID-VkSubpassDependency-srcSubpass-06809", &[], |d| {
        d.dependencies = vec![between(
            0,
            0,
            (
                vk::PipelineStageFlags::COLOR_ATTACHMENT_OUTPUT,
                vk::PipelineStageFlags::VERTEX_SHADER,
            ),
            (
                vk::AccessFlags::COLOR_ATTACHMENT_WRITE,
                vk::AccessFlags::SHADER_READ,
            ),
            vk::DependencyFlags::BY_REGION,
        )];
    }),
    ("VUID-VkSubpassDependency-srcSubpass-02243", &[], |d| {
        let color = vk::PipelineStageFlags::COLOR_ATTACHMENT_OUTPUT;
        let write = vk::AccessFlags::COLOR_ATTACHMENT_WRITE;
        d.dependencies = vec![between(
            0,
            0,
            (color, color),
            (write, write),
            vk::DependencyFlags::empty(),
        )];
    }),
    ("VUID-VkSubpassDependency-srcAccessMask-00868", &[], |d| {
        let color = vk::PipelineStageFlags::COLOR_ATTACHMENT_OUTPUT;
        d.dependencies = vec![between(
            vk::SUBPASS_EXTERNAL,
            0,
            (color, color),
            (vk::AccessFlags::TRANSFER_WRITE, vk::AccessFlags::empty()),
            vk::DependencyFlags::empty(),
        )];
    }),
    ("VUID-VkSubpassDependency-dstAccessMask-00869", &[], |d| {
        let color = vk::PipelineStageFlags::COLOR_ATTACHMENT_OUTPUT;
        d.dependencies = vec![between(
            vk::SUBPASS_EXTERNAL,
            0,
            (color, color),
            (vk::AccessFlags::empty(), vk::AccessFlags::INDEX_READ),
            vk::DependencyFlags::empty(),
        )];
    }),
    ("VUID-VkSubpassDependency-srcSubpass-00872", &[], |d| {
        d.view_masks = vec![0b11];
        let color = vk::PipelineStageFlags::COLOR_ATTACHMENT_OUTPUT;
        let write = vk::AccessFlags::COLOR_ATTACHMENT_WRITE;
        d.dependencies = vec![between(
            0,
            0,
            (color, color),
            (write, write),
            vk::DependencyFlags::BY_REGION,
        )];
    }),
    ("VUID-VkRenderPassCreateInfo-pNext-01930", &[], |d| {
        d.view_masks = vec![0b1];
        d.view_offsets = vec![1];
        let color = vk::PipelineStageFlags::COLOR_ATTACHMENT_OUTPUT;
        let write = vk::AccessFlags::COLOR_ATTACHMENT_WRITE;
        d.dependencies = vec![between(
            0,
            0,
            (color, color),
            (write, write),
            vk::DependencyFlags::BY_REGION | vk::DependencyFlags::VIEW_LOCAL,
        )];
    }),
    ("VUID-VkRenderPassCreateInfo-pNext-02512", &[], |d| {
        d.subpasses = 2;
        d.view_masks = vec![0b1, 0b1];
        d.view_offsets = vec![1];
        let color = vk::PipelineStageFlags::COLOR_ATTACHMENT_OUTPUT;
        let write = vk::AccessFlags::COLOR_ATTACHMENT_WRITE;
        d.dependencies = vec![between(
            0,
            1,
            (color, color),
            (write, write),
            vk::DependencyFlags::empty(),
        )];
    }),
    (
        "VUID-VkRenderPassMultiviewCreateInfo-pCorrelationMasks-00841",
        &[],
        |d| {
            d.view_masks = vec![0b11];
            d.correlations = vec![0b11, 0b01];
        },
    ),
    (
        "VUID-VkRenderPassMultiviewCreateInfo-pViewMasks-06697",
        &[],
        |d| {
            d.view_masks = vec![1 << 31];
        },
    ),
    ("VUID-VkRenderPassCreateInfo-pNext-01963", &[], |d| {
        d.inputs = vec![vk::AttachmentReference {
            attachment: 0,
            layout: GENERAL,
        }];
        d.colors = vec![vk::AttachmentReference {
            attachment: 0,
            layout: GENERAL,
        }];
        d.aspects = vec![vk::InputAttachmentAspectReference {
            subpass: 0,
            input_attachment_index: 0,
            aspect_mask: vk::ImageAspectFlags::DEPTH,
        }];
    }),
];

/// The description cases that need a feature off: synchronization2 (a stage mask of
/// 0) and multiview (a view mask).
const DESCRIBED_BARE: &[Described1] = &[
    ("VUID-VkSubpassDependency-srcStageMask-03937", &[], |d| {
        let color = vk::PipelineStageFlags::COLOR_ATTACHMENT_OUTPUT;
        d.dependencies = vec![between(
            vk::SUBPASS_EXTERNAL,
            0,
            (vk::PipelineStageFlags::empty(), color),
            (vk::AccessFlags::empty(), vk::AccessFlags::empty()),
            vk::DependencyFlags::empty(),
        )];
    }),
    ("VUID-VkSubpassDependency-dstStageMask-03937", &[], |d| {
        let color = vk::PipelineStageFlags::COLOR_ATTACHMENT_OUTPUT;
        d.dependencies = vec![between(
            0,
            vk::SUBPASS_EXTERNAL,
            (color, vk::PipelineStageFlags::empty()),
            (vk::AccessFlags::empty(), vk::AccessFlags::empty()),
            vk::DependencyFlags::empty(),
        )];
    }),
    (
        "VUID-VkRenderPassMultiviewCreateInfo-multiview-06555",
        &[],
        |d| {
            d.view_masks = vec![0b1];
        },
    ),
];

/// Rules the 1.3.239 layer reports, for `vkCreateRenderPass`, under the VUID of the
/// same rule of `vkCreateRenderPass2` (it checks the first through the second); its
/// message states the rule.
const DESCRIBED_RENAMED: &[(&str, &str)] = &[(
    "VUID-VkRenderPassMultiviewCreateInfo-multiview-06555",
    "VUID-VkSubpassDescription2-multiview-06558",
)];

/// Each description case is refused with its rule's VUID, and the layer names the
/// same rule or nothing.
#[test]
fn each_broken_description_rule_is_refused_and_the_layer_agrees() {
    let _serial = vulkan::serial();
    let mut failures = Vec::new();
    let (mut by_layer, mut alone) = (0, Vec::new());
    for (setup, cases) in [
        (tuff_setup::setup_full_features(true), DESCRIBED),
        (tuff_setup::setup_bare(true), DESCRIBED_BARE),
    ] {
        let (safe, layer) = create_described(&setup, &Described::default(), true);
        assert!(
            safe.is_ok() && layer.is_empty(),
            "the valid render pass: {safe:?} {layer:?}"
        );
        for (vuid, also, change) in cases {
            let mut d = Described::default();
            change(&mut d);
            let (safe, layer) = create_described(&setup, &d, true);
            match &safe {
                Err(tuff::Error::Validation { vuid: got, .. }) if got == vuid => {}
                other => {
                    failures.push(format!("{vuid}: the safe method returned {other:?}"));
                    continue;
                }
            }
            let names = |m: &String, v: &str| {
                m.contains(&format!("[ {v} ]"))
                    || DESCRIBED_RENAMED
                        .iter()
                        .any(|(rule, name)| *rule == v && m.contains(&format!("[ {name} ]")))
            };
            if layer.is_empty() {
                alone.push(*vuid);
            } else if layer.iter().any(|m| names(m, vuid))
                && layer
                    .iter()
                    .all(|m| names(m, vuid) || also.iter().any(|a| names(m, a)))
            {
                by_layer += 1;
            } else {
                failures.push(format!(
                    "{vuid}: the layer said something else:\n  {}",
                    layer.join("\n  ")
                ));
            }
        }
    }
    println!(
        "render pass descriptions: the layer named {by_layer}, the error alone proves {} ({})",
        alone.len(),
        alone.join(", ")
    );
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

/// What the second version's create info can say beyond the first's.
#[derive(Default)]
struct Extra2 {
    /// A chained `VkAttachmentDescriptionStencilLayout` per attachment index.
    stencil_layouts: Vec<(usize, vk::ImageLayout, vk::ImageLayout)>,
    /// A chained `VkAttachmentReferenceStencilLayout` on the depth/stencil reference.
    depth_stencil_layout: Option<vk::ImageLayout>,
    /// A chained `VkSubpassDescriptionDepthStencilResolve`: attachment, modes.
    resolve: Option<(u32, vk::ResolveModeFlags, vk::ResolveModeFlags)>,
    /// The input references' aspect masks, where not their formats'.
    input_aspects: Option<vk::ImageAspectFlags>,
}

/// Builds `d` (and `x`) through `vkCreateRenderPass2`: view masks on the subpasses,
/// view offsets on the dependencies, correlation masks on the create info.
fn create_described2(
    s: &Setup,
    d: &Described,
    x: &Extra2,
    unchecked: bool,
) -> (tuff::Result<()>, Vec<String>) {
    let mut stencil_layouts: Vec<tuff::AttachmentDescriptionStencilLayout<'_>> = x
        .stencil_layouts
        .iter()
        .map(|&(_, initial, last)| {
            tuff::AttachmentDescriptionStencilLayout::new()
                .stencil_initial_layout(initial)
                .stencil_final_layout(last)
        })
        .collect();
    let mut chained = stencil_layouts.iter_mut();
    let attachments: Vec<_> = d
        .attachments
        .iter()
        .enumerate()
        .map(|(i, a)| {
            let mut a2 = tuff::AttachmentDescription2::new()
                .flags(a.flags)
                .format(a.format)
                .samples(a.samples)
                .load_op(a.load_op)
                .store_op(a.store_op)
                .stencil_load_op(a.stencil_load_op)
                .stencil_store_op(a.stencil_store_op)
                .initial_layout(a.initial_layout)
                .final_layout(a.final_layout);
            if x.stencil_layouts.iter().any(|l| l.0 == i) {
                a2 = a2.push_next(chained.next().expect("one per listed attachment"));
            }
            a2
        })
        .collect();
    let aspect_of = |a: u32| {
        let format = d.attachments.get(a as usize).map(|a| a.format);
        match format {
            Some(vk::Format::D32_SFLOAT_S8_UINT) => vk::ImageAspectFlags::DEPTH,
            _ => vk::ImageAspectFlags::COLOR,
        }
    };
    let inputs: Vec<_> = d
        .inputs
        .iter()
        .map(|r| {
            tuff::AttachmentReference2::new()
                .attachment(r.attachment)
                .layout(r.layout)
                .aspect_mask(x.input_aspects.unwrap_or(aspect_of(r.attachment)))
        })
        .collect();
    let colors: Vec<_> = d
        .colors
        .iter()
        .map(|r| {
            tuff::AttachmentReference2::new()
                .attachment(r.attachment)
                .layout(r.layout)
        })
        .collect();
    let mut depth_stencil = tuff::AttachmentReferenceStencilLayout::new()
        .stencil_layout(x.depth_stencil_layout.unwrap_or(GENERAL));
    let depth = d.depth.map(|r| {
        let r2 = tuff::AttachmentReference2::new()
            .attachment(r.attachment)
            .layout(r.layout);
        match x.depth_stencil_layout {
            Some(_) => r2.push_next(&mut depth_stencil),
            None => r2,
        }
    });
    let resolve_reference = x.resolve.map(|(a, _, _)| {
        tuff::AttachmentReference2::new()
            .attachment(a)
            .layout(GENERAL)
    });
    let mut resolves: Vec<_> = (0..d.subpasses)
        .map(|_| {
            let (_, depth_mode, stencil_mode) = x.resolve.unwrap_or_default();
            tuff::SubpassDescriptionDepthStencilResolve::new()
                .depth_resolve_mode(depth_mode)
                .stencil_resolve_mode(stencil_mode)
                .depth_stencil_resolve_attachment(resolve_reference.as_ref())
        })
        .collect();
    let mut resolves = resolves.iter_mut();
    let subpasses: Vec<_> = (0..d.subpasses)
        .map(|i| {
            let subpass = tuff::SubpassDescription2::new()
                .pipeline_bind_point(vk::PipelineBindPoint::GRAPHICS)
                .view_mask(d.view_masks.get(i).copied().unwrap_or(0))
                .input_attachments(&inputs)
                .color_attachments(&colors)
                .depth_stencil_attachment(depth.as_ref());
            let resolve = resolves.next().expect("one per subpass");
            match x.resolve {
                Some(_) => subpass.push_next(resolve),
                None => subpass,
            }
        })
        .collect();
    let dependencies: Vec<_> = d
        .dependencies
        .iter()
        .enumerate()
        .map(|(i, dep)| {
            tuff::SubpassDependency2::new()
                .src_subpass(dep.src_subpass)
                .dst_subpass(dep.dst_subpass)
                .src_stage_mask(dep.src_stage_mask)
                .dst_stage_mask(dep.dst_stage_mask)
                .src_access_mask(dep.src_access_mask)
                .dst_access_mask(dep.dst_access_mask)
                .dependency_flags(dep.dependency_flags)
                .view_offset(d.view_offsets.get(i).copied().unwrap_or(0))
        })
        .collect();
    let info = tuff::RenderPassCreateInfo2::new()
        .attachments(&attachments)
        .subpasses(&subpasses)
        .dependencies(&dependencies)
        .correlated_view_masks(&d.correlations);
    let safe = s.device.create_render_pass2(&info).map(drop);
    if !unchecked {
        return (safe, Vec::new());
    }
    let layer = under_layer(s, || {
        let _ = unsafe { s.device.create_render_pass2_unchecked(&info) };
    });
    (safe, layer)
}

/// Cases the 1.3.239 layer lets through and lavapipe crashes on: only the safe
/// method builds them (its error alone proves the rule).
const CRASH_UNCHECKED: &[&str] =
    &["VUID-VkSubpassDescriptionDepthStencilResolve-pDepthStencilResolveAttachment-03177"];

/// The first version's description cases that the second states under its own
/// VUID, with that VUID (the others have no second-version twin: a multiview info,
/// an input-attachment-aspect info, a view offset's VIEW_LOCAL rule).
const SECOND_VUIDS: &[(&str, &str)] = &[
    (
        "VUID-VkAttachmentDescription-format-06698",
        "VUID-VkAttachmentDescription2-format-06698",
    ),
    (
        "VUID-VkAttachmentDescription-format-06242",
        "VUID-VkAttachmentDescription2-format-06249",
    ),
    (
        "VUID-VkAttachmentDescription-format-06243",
        "VUID-VkAttachmentDescription2-format-06250",
    ),
    (
        "VUID-VkAttachmentDescription-format-06906",
        "VUID-VkAttachmentDescription2-format-06906",
    ),
    (
        "VUID-VkAttachmentDescription-format-06907",
        "VUID-VkAttachmentDescription2-format-06907",
    ),
    (
        "VUID-VkRenderPassCreateInfo-pAttachments-00836",
        "VUID-VkRenderPassCreateInfo2-pAttachments-02522",
    ),
    (
        "VUID-VkRenderPassCreateInfo-pAttachments-02511",
        "VUID-VkRenderPassCreateInfo2-pAttachments-02523",
    ),
    (
        "VUID-VkRenderPassCreateInfo-pAttachments-01566",
        "VUID-VkRenderPassCreateInfo2-pAttachments-02522",
    ),
    (
        "VUID-VkRenderPassCreateInfo-pAttachments-01567",
        "VUID-VkRenderPassCreateInfo2-pAttachments-02523",
    ),
    (
        "VUID-VkSubpassDescription-loadOp-00846",
        "VUID-VkSubpassDescription2-loadOp-03064",
    ),
    (
        "VUID-VkSubpassDescription-attachment-06915",
        "VUID-VkSubpassDescription2-attachment-06915",
    ),
    (
        "VUID-VkRenderPassCreateInfo-pDependencies-00837",
        "VUID-VkRenderPassCreateInfo2-pDependencies-03054",
    ),
    (
        "VUID-VkRenderPassCreateInfo-pDependencies-00838",
        "VUID-VkRenderPassCreateInfo2-pDependencies-03055",
    ),
    (
        "VUID-VkSubpassDependency-srcSubpass-00864",
        "VUID-VkSubpassDependency2-srcSubpass-03084",
    ),
    (
        "VUID-VkSubpassDependency-srcSubpass-00865",
        "VUID-VkSubpassDependency2-srcSubpass-03085",
    ),
    (
        "VUID-VkSubpassDependency-srcSubpass-06809",
        "VUID-VkSubpassDependency2-srcSubpass-06810",
    ),
    (
        "VUID-VkSubpassDependency-srcSubpass-02243",
        "VUID-VkSubpassDependency2-srcSubpass-02245",
    ),
    (
        "VUID-VkSubpassDependency-srcAccessMask-00868",
        "VUID-VkSubpassDependency2-srcAccessMask-03088",
    ),
    (
        "VUID-VkSubpassDependency-dstAccessMask-00869",
        "VUID-VkSubpassDependency2-dstAccessMask-03089",
    ),
    (
        "VUID-VkSubpassDependency-srcSubpass-00872",
        "VUID-VkRenderPassCreateInfo2-pDependencies-03060",
    ),
    (
        "VUID-VkRenderPassCreateInfo-pNext-01930",
        "VUID-VkSubpassDependency2-viewOffset-02530",
    ),
    (
        "VUID-VkRenderPassMultiviewCreateInfo-pCorrelationMasks-00841",
        "VUID-VkRenderPassCreateInfo2-pCorrelatedViewMasks-03056",
    ),
    (
        "VUID-VkSubpassDependency-srcStageMask-03937",
        "VUID-VkSubpassDependency2-srcStageMask-03937",
    ),
    (
        "VUID-VkSubpassDependency-dstStageMask-03937",
        "VUID-VkSubpassDependency2-dstStageMask-03937",
    ),
];

type Described2 = (&'static str, fn(&mut Described, &mut Extra2));

/// A four-sample depth/stencil attachment (index 2), the subpass's depth/stencil
/// attachment, resolved into attachment `into`.
fn resolving(
    d: &mut Described,
    x: &mut Extra2,
    into: u32,
    modes: (vk::ResolveModeFlags, vk::ResolveModeFlags),
) {
    d.attachments.push(vk::AttachmentDescription {
        samples: FOUR,
        ..d.attachments[1]
    });
    d.colors.clear();
    d.depth = Some(vk::AttachmentReference {
        attachment: 2,
        layout: DEPTH,
    });
    x.resolve = Some((into, modes.0, modes.1));
}

/// [`resolving`] the depth aspect by sample zero, the stencil not at all.
fn depth_resolving(d: &mut Described, x: &mut Extra2, into: u32) {
    resolving(
        d,
        x,
        into,
        (
            vk::ResolveModeFlags::SAMPLE_ZERO,
            vk::ResolveModeFlags::NONE,
        ),
    );
}

fn attachment_of(
    d: &Described,
    format: vk::Format,
    samples: vk::SampleCountFlags,
) -> vk::AttachmentDescription {
    vk::AttachmentDescription {
        format,
        samples,
        ..d.attachments[1]
    }
}

/// The second version's own cases: stencil layouts, input aspects, indices, and
/// depth/stencil resolves.
const DESCRIBED_SECOND: &[Described2] = &[
    ("VUID-VkAttachmentDescription2-pNext-06704", |d, _| {
        d.attachments[1].stencil_load_op = vk::AttachmentLoadOp::LOAD;
    }),
    ("VUID-VkAttachmentDescription2-pNext-06705", |d, x| {
        d.attachments[1].stencil_load_op = vk::AttachmentLoadOp::LOAD;
        d.attachments[1].initial_layout = GENERAL;
        x.stencil_layouts = vec![(1, vk::ImageLayout::UNDEFINED, GENERAL)];
    }),
    ("VUID-VkAttachmentDescription2-format-06247", |d, _| {
        let mut s8 = attachment_of(d, vk::Format::S8_UINT, ONE);
        s8.initial_layout = vk::ImageLayout::DEPTH_ATTACHMENT_OPTIMAL;
        d.attachments.push(s8);
    }),
    ("VUID-VkAttachmentDescription2-format-06248", |d, _| {
        let mut s8 = attachment_of(d, vk::Format::S8_UINT, ONE);
        s8.final_layout = vk::ImageLayout::DEPTH_READ_ONLY_OPTIMAL;
        d.attachments.push(s8);
    }),
    ("VUID-VkRenderPassCreateInfo2-attachment-06244", |d, _| {
        d.depth = Some(vk::AttachmentReference {
            attachment: 1,
            layout: vk::ImageLayout::DEPTH_ATTACHMENT_OPTIMAL,
        });
    }),
    ("VUID-VkRenderPassCreateInfo2-attachment-06245", |d, _| {
        d.depth = Some(vk::AttachmentReference {
            attachment: 1,
            layout: vk::ImageLayout::STENCIL_ATTACHMENT_OPTIMAL,
        });
    }),
    ("VUID-VkRenderPassCreateInfo2-attachment-06246", |d, _| {
        d.attachments
            .push(attachment_of(d, vk::Format::S8_UINT, ONE));
        d.depth = Some(vk::AttachmentReference {
            attachment: 2,
            layout: vk::ImageLayout::DEPTH_ATTACHMENT_OPTIMAL,
        });
    }),
    ("VUID-VkSubpassDescription2-attachment-06251", |d, x| {
        d.attachments
            .push(attachment_of(d, vk::Format::S8_UINT, ONE));
        d.depth = Some(vk::AttachmentReference {
            attachment: 2,
            layout: vk::ImageLayout::STENCIL_ATTACHMENT_OPTIMAL,
        });
        x.depth_stencil_layout = Some(vk::ImageLayout::STENCIL_ATTACHMENT_OPTIMAL);
    }),
    ("VUID-VkRenderPassCreateInfo2-srcSubpass-02526", |d, _| {
        let color = vk::PipelineStageFlags::COLOR_ATTACHMENT_OUTPUT;
        d.dependencies = vec![between(
            3,
            vk::SUBPASS_EXTERNAL,
            (color, color),
            Default::default(),
            vk::DependencyFlags::empty(),
        )];
    }),
    ("VUID-VkRenderPassCreateInfo2-dstSubpass-02527", |d, _| {
        let color = vk::PipelineStageFlags::COLOR_ATTACHMENT_OUTPUT;
        d.dependencies = vec![between(
            vk::SUBPASS_EXTERNAL,
            3,
            (color, color),
            Default::default(),
            vk::DependencyFlags::empty(),
        )];
    }),
    ("VUID-VkRenderPassCreateInfo2-pSubpasses-06473", |d, x| {
        depth_resolving(d, x, 9);
    }),
    (
        "VUID-VkSubpassDescriptionDepthStencilResolve-pDepthStencilResolveAttachment-03177",
        |d, x| {
            depth_resolving(d, x, 1);
            d.depth = None;
            d.colors = vec![vk::AttachmentReference {
                attachment: 0,
                layout: COLOR,
            }];
            d.attachments[0].samples = FOUR;
        },
    ),
    (
        "VUID-VkSubpassDescriptionDepthStencilResolve-pDepthStencilResolveAttachment-03179",
        |d, x| {
            depth_resolving(d, x, 2);
            d.attachments[2].samples = ONE;
            d.depth = Some(vk::AttachmentReference {
                attachment: 1,
                layout: DEPTH,
            });
        },
    ),
    (
        "VUID-VkSubpassDescriptionDepthStencilResolve-pDepthStencilResolveAttachment-03180",
        |d, x| depth_resolving(d, x, 2),
    ),
    (
        "VUID-VkSubpassDescriptionDepthStencilResolve-pDepthStencilResolveAttachment-02651",
        |d, x| depth_resolving(d, x, 0),
    ),
    (
        "VUID-VkSubpassDescriptionDepthStencilResolve-pDepthStencilResolveAttachment-03181",
        |d, x| {
            depth_resolving(d, x, 3);
            d.attachments
                .push(attachment_of(d, vk::Format::D16_UNORM, ONE));
        },
    ),
    (
        "VUID-VkSubpassDescriptionDepthStencilResolve-pDepthStencilResolveAttachment-03182",
        |d, x| {
            depth_resolving(d, x, 1);
            d.attachments[2].format = vk::Format::D32_SFLOAT;
        },
    ),
    (
        "VUID-VkSubpassDescriptionDepthStencilResolve-pDepthStencilResolveAttachment-03178",
        |d, x| {
            resolving(
                d,
                x,
                1,
                (vk::ResolveModeFlags::NONE, vk::ResolveModeFlags::NONE),
            )
        },
    ),
    ("VUID-VkSubpassDescription2-attachment-02799", |d, x| {
        d.attachments.push(d.attachments[0]);
        d.inputs = vec![vk::AttachmentReference {
            attachment: 2,
            layout: GENERAL,
        }];
        x.input_aspects = Some(vk::ImageAspectFlags::from_raw(0x1000));
    }),
    (
        "VUID-VkSubpassDescriptionDepthStencilResolve-stencilResolveMode-03184",
        |d, x| {
            resolving(
                d,
                x,
                1,
                (vk::ResolveModeFlags::NONE, vk::ResolveModeFlags::AVERAGE),
            )
        },
    ),
];

/// The second version's description cases: each first-version case under its
/// twin's VUID, and the second version's own, refused with the rule's VUID while
/// the layer names it or nothing; a depth/stencil resolve that keeps the rules
/// goes through.
#[test]
fn each_broken_second_version_description_rule_is_refused_and_the_layer_agrees() {
    let _serial = vulkan::serial();
    let mut failures = Vec::new();
    let (mut by_layer, mut alone) = (0, Vec::new());
    let full = tuff_setup::setup_full_features(true);
    let bare = tuff_setup::setup_bare(true);
    let mut cases: Vec<(&Setup, &str, Described, Extra2)> = Vec::new();
    for (setup, list) in [(&full, DESCRIBED), (&bare, DESCRIBED_BARE)] {
        for (vuid, _, change) in list {
            let Some((_, second)) = SECOND_VUIDS.iter().find(|(one, _)| one == vuid) else {
                continue;
            };
            let mut d = Described::default();
            change(&mut d);
            cases.push((setup, second, d, Extra2::default()));
        }
    }
    for (vuid, change) in DESCRIBED_SECOND {
        let (mut d, mut x) = (Described::default(), Extra2::default());
        change(&mut d, &mut x);
        cases.push((&full, vuid, d, x));
    }
    for setup in [&full, &bare] {
        let (safe, layer) =
            create_described2(setup, &Described::default(), &Extra2::default(), true);
        assert!(
            safe.is_ok() && layer.is_empty(),
            "the valid render pass: {safe:?} {layer:?}"
        );
    }
    let (mut d, mut x) = (Described::default(), Extra2::default());
    resolving(
        &mut d,
        &mut x,
        1,
        (
            vk::ResolveModeFlags::SAMPLE_ZERO,
            vk::ResolveModeFlags::SAMPLE_ZERO,
        ),
    );
    let (safe, layer) = create_described2(&full, &d, &x, true);
    assert!(
        safe.is_ok() && layer.is_empty(),
        "a depth/stencil resolve: {safe:?} {layer:?}"
    );
    // The stages of extensions the safe create_device does not enable (mesh and
    // task shading, conditional rendering, fragment density, transform feedback,
    // shading rate attachments), in either mask of either version: their parameter
    // rule refuses them before the rules that name their features.
    let extension_stages = [
        vk::PipelineStageFlags::MESH_SHADER_EXT,
        vk::PipelineStageFlags::TASK_SHADER_EXT,
        vk::PipelineStageFlags::CONDITIONAL_RENDERING_EXT,
        vk::PipelineStageFlags::FRAGMENT_DENSITY_PROCESS_EXT,
        vk::PipelineStageFlags::TRANSFORM_FEEDBACK_EXT,
        vk::PipelineStageFlags::FRAGMENT_SHADING_RATE_ATTACHMENT_KHR,
    ];
    let color = vk::PipelineStageFlags::COLOR_ATTACHMENT_OUTPUT;
    for stage in extension_stages {
        for (stages, mask) in [
            ((stage, color), "srcStageMask"),
            ((color, stage), "dstStageMask"),
        ] {
            let d = Described {
                dependencies: vec![between(
                    vk::SUBPASS_EXTERNAL,
                    0,
                    stages,
                    Default::default(),
                    vk::DependencyFlags::empty(),
                )],
                ..Described::default()
            };
            let (safe, _) = create_described2(&full, &d, &Extra2::default(), false);
            assert_eq!(
                tuff_setup::vuid(safe),
                format!("VUID-VkSubpassDependency2-{mask}-parameter"),
                "{stage:?}"
            );
            let (safe, _) = create_described(&full, &d, false);
            assert_eq!(
                tuff_setup::vuid(safe),
                format!("VUID-VkSubpassDependency-{mask}-parameter"),
                "{stage:?}"
            );
        }
    }
    for (setup, vuid, d, x) in &cases {
        let (safe, layer) = create_described2(setup, d, x, !CRASH_UNCHECKED.contains(vuid));
        match &safe {
            Err(tuff::Error::Validation { vuid: got, .. }) if got == vuid => {}
            other => {
                failures.push(format!("{vuid}: the safe method returned {other:?}"));
                continue;
            }
        }
        let names = |m: &String| m.contains(&format!("[ {vuid} ]"));
        if layer.is_empty() {
            alone.push(*vuid);
        } else if layer.iter().any(names) {
            by_layer += 1;
        } else {
            failures.push(format!(
                "{vuid}: the layer said something else:\n  {}",
                layer.join("\n  ")
            ));
        }
    }
    println!(
        "second-version descriptions: the layer named {by_layer}, the error alone proves {} ({})",
        alone.len(),
        alone.join(", ")
    );
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}
