//! Secondary command buffers executed from a primary: `execute_commands` checks
//! what each was recorded for (its begin flags and inheritance info) against where
//! the primary executes it, and the lifecycle rules of executing one.
//!
//! Each case breaks one rule through `tuff_setup::breaks`: the safe method must
//! refuse it with the rule's VUID, and `execute_commands_unchecked`, under the layer
//! told to skip the call it reports, must make the layer name it (or say nothing
//! where the 1.3.239 layer does not check it). No command buffer that breaks a rule
//! is submitted. The positive cases beside them record, submit and run.
//!
//! SAFETY of the `unsafe` blocks: the `_unchecked` calls break, on purpose, only the
//! rule each case names, which the layer skips (the command buffer is never
//! submitted).

#[path = "common/tuff_setup.rs"]
mod tuff_setup;
#[path = "common/vulkan.rs"]
mod vulkan;

use tuff::{vk, Handle as _};
use tuff_setup::{breaks, setup, ColorTarget, Layer, Setup};
use vulkan::assert_silent;

type Usage = vk::CommandBufferUsageFlags;
const SIZE: u32 = 8;
const CONTINUE: Usage = Usage::RENDER_PASS_CONTINUE;

fn area() -> vk::Rect2D {
    vk::Rect2D {
        offset: vk::Offset2D::default(),
        extent: vk::Extent2D {
            width: SIZE,
            height: SIZE,
        },
    }
}

fn framebuffer(s: &Setup, pass: &tuff::RenderPass, view: &tuff::ImageView) -> tuff::Framebuffer {
    s.device
        .create_framebuffer(
            &tuff::FramebufferCreateInfo::new(pass)
                .attachments(view)
                .width(SIZE)
                .height(SIZE)
                .layers(1),
        )
        .expect("framebuffer")
}

/// Records `cb` as a secondary begun with `flags` and `inheritance` (continuing a
/// render pass instance where `flags` says so), with nothing in it, and ends it.
fn record_secondary(
    cb: &mut tuff::CommandBuffer,
    flags: Usage,
    inheritance: &tuff::CommandBufferInheritanceInfo<'_>,
) {
    let info = tuff::CommandBufferBeginInfo::new()
        .flags(flags)
        .inheritance_info(Some(inheritance));
    if flags.contains(CONTINUE) {
        let rec = cb.begin_continuing(&info).expect("begin continuing");
        rec.end().expect("end");
    } else {
        let rec = cb.begin(&info).expect("begin");
        rec.end().expect("end");
    }
}

/// Executes `secondaries` from a new recording of `primary`, inside subpass
/// `subpass` of a render pass instance of `target`'s render pass and framebuffer (or
/// of `pass` and `fb`) begun with `contents`, through the safe method or its
/// `_unchecked` twin.
#[allow(clippy::too_many_arguments)]
fn execute_in_pass(
    primary: &mut tuff::CommandBuffer,
    pass: &tuff::RenderPass,
    fb: &tuff::Framebuffer,
    contents: vk::SubpassContents,
    subpass: u32,
    secondaries: &[&tuff::CommandBuffer],
    unchecked: bool,
) -> tuff::Result<()> {
    let clear = [vk::ClearValue::default()];
    let begin = tuff::RenderPassBeginInfo::new(pass, fb)
        .render_area(area())
        .clear_values(&clear);
    let rec = primary
        .begin(&tuff::CommandBufferBeginInfo::new())
        .expect("begin");
    let mut rec = rec.begin_render_pass(&begin, contents);
    for _ in 0..subpass {
        rec.next_subpass(contents);
    }
    let list = tuff::HandleSlice::new(secondaries);
    if unchecked {
        unsafe { rec.execute_commands_unchecked(&list) }
    } else {
        rec.execute_commands(&list)
    }
}

/// Executes `secondaries` from a new recording of `primary`, outside any render
/// pass instance.
fn execute_outside(
    primary: &mut tuff::CommandBuffer,
    secondaries: &[&tuff::CommandBuffer],
    unchecked: bool,
) -> tuff::Result<()> {
    let mut rec = primary
        .begin(&tuff::CommandBufferBeginInfo::new())
        .expect("begin");
    let list = tuff::HandleSlice::new(secondaries);
    if unchecked {
        unsafe { rec.execute_commands_unchecked(&list) }
    } else {
        rec.execute_commands(&list)
    }
}

/// A secondary is executable, and runs as often as its flags allow: not a primary
/// (00088), not one whose recording never ended (00089), not twice in one recording
/// without SIMULTANEOUS_USE (00092, 00093); with it, twice is fine.
#[test]
fn secondaries_execute_as_their_lifecycle_allows() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let none = tuff::CommandBufferInheritanceInfo::new();
    let (_pool, mut primary) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let (_spool, mut secondary) = s.command_buffer(vk::CommandBufferLevel::SECONDARY);
    let other_ended = {
        let (pool, mut cb) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
        cb.begin(&tuff::CommandBufferBeginInfo::new())
            .expect("begin")
            .end()
            .expect("end");
        (pool, cb)
    };
    breaks(
        &s,
        "VUID-vkCmdExecuteCommands-pCommandBuffers-00088",
        Layer::Names,
        |unchecked| execute_outside(&mut primary, &[&other_ended.1], unchecked),
    );
    // Begun, and its recorder dropped: it never ended.
    let info = tuff::CommandBufferBeginInfo::new().inheritance_info(Some(&none));
    drop(secondary.begin(&info).expect("begin"));
    breaks(
        &s,
        "VUID-vkCmdExecuteCommands-pCommandBuffers-00089",
        // The 1.3.239 layer names the case by its own identifier.
        Layer::NamesOr("UNASSIGNED-CoreValidation-DrawState-NoEndCommandBuffer"),
        |unchecked| execute_outside(&mut primary, &[&secondary], unchecked),
    );
    record_secondary(&mut secondary, Usage::empty(), &none);
    breaks(
        &s,
        "VUID-vkCmdExecuteCommands-pCommandBuffers-00093",
        Layer::Names,
        |unchecked| execute_outside(&mut primary, &[&secondary, &secondary], unchecked),
    );
    breaks(
        &s,
        "VUID-vkCmdExecuteCommands-pCommandBuffers-00092",
        Layer::Names,
        |unchecked| {
            let mut rec = primary
                .begin(&tuff::CommandBufferBeginInfo::new())
                .expect("begin");
            rec.execute_commands(&secondary)
                .expect("the first execution");
            if unchecked {
                unsafe { rec.execute_commands_unchecked(&secondary) }
            } else {
                rec.execute_commands(&secondary)
            }
        },
    );
    // SIMULTANEOUS_USE: twice in one call and again later, then run.
    record_secondary(&mut secondary, Usage::SIMULTANEOUS_USE, &none);
    let mut rec = primary
        .begin(&tuff::CommandBufferBeginInfo::new())
        .expect("begin");
    rec.execute_commands(&tuff::HandleSlice::new(&[&secondary, &secondary]))
        .expect("twice with SIMULTANEOUS_USE");
    rec.execute_commands(&secondary).expect("and again");
    rec.end().expect("end");
    s.submit_wait(&primary);
    assert_silent(&s.messages);
}

/// Inside a render pass instance begun with `vkCmdBeginRenderPass`, a secondary
/// continues it: the subpass takes secondaries (06018), the secondary was recorded
/// with RENDER_PASS_CONTINUE (00096) for the current subpass (06019) of a
/// compatible render pass (06020) and, if it names one, the instance's framebuffer
/// (00099); outside an instance it continues none (00100). A secondary recorded
/// for subpass 1 runs in subpass 1, and one for a compatible render pass of another
/// format-compatible pass runs too.
#[test]
fn secondaries_continue_the_render_pass_instance_they_were_recorded_for() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let target = s.color_target(SIZE, vk::ImageUsageFlags::empty());
    let other = s.color_target(SIZE, vk::ImageUsageFlags::empty());
    let two = s.color_pass(vk::Format::R8G8B8A8_UNORM, 2);
    let two_fb = framebuffer(&s, &two, &target.view);
    let bgra = s.color_pass(vk::Format::B8G8R8A8_UNORM, 1);
    let other_fb = framebuffer(&s, &target.render_pass, &other.view);
    let (_pool, mut primary) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let (_spool, mut secondary) = s.command_buffer(vk::CommandBufferLevel::SECONDARY);
    let secondaries = vk::SubpassContents::SECONDARY_COMMAND_BUFFERS;
    let inline = vk::SubpassContents::INLINE;
    let ColorTarget {
        render_pass: pass,
        framebuffer: fb,
        ..
    } = &target;

    let subpass0 = tuff::CommandBufferInheritanceInfo::new().render_pass(Some(pass));
    record_secondary(&mut secondary, CONTINUE, &subpass0);
    breaks(
        &s,
        "VUID-vkCmdExecuteCommands-contents-06018",
        Layer::Names,
        |unchecked| execute_in_pass(&mut primary, pass, fb, inline, 0, &[&secondary], unchecked),
    );
    breaks(
        &s,
        "VUID-vkCmdExecuteCommands-pCommandBuffers-00100",
        Layer::Names,
        |unchecked| execute_outside(&mut primary, &[&secondary], unchecked),
    );
    record_secondary(
        &mut secondary,
        Usage::empty(),
        &tuff::CommandBufferInheritanceInfo::new(),
    );
    breaks(
        &s,
        "VUID-vkCmdExecuteCommands-pCommandBuffers-00096",
        Layer::Names,
        |unchecked| {
            execute_in_pass(
                &mut primary,
                pass,
                fb,
                secondaries,
                0,
                &[&secondary],
                unchecked,
            )
        },
    );
    let two_subpass0 = tuff::CommandBufferInheritanceInfo::new().render_pass(Some(&two));
    record_secondary(&mut secondary, CONTINUE, &two_subpass0);
    breaks(
        &s,
        "VUID-vkCmdExecuteCommands-pCommandBuffers-06019",
        Layer::Names,
        |unchecked| {
            execute_in_pass(
                &mut primary,
                &two,
                &two_fb,
                secondaries,
                1,
                &[&secondary],
                unchecked,
            )
        },
    );
    let for_bgra = tuff::CommandBufferInheritanceInfo::new().render_pass(Some(&bgra));
    record_secondary(&mut secondary, CONTINUE, &for_bgra);
    breaks(
        &s,
        "VUID-vkCmdExecuteCommands-pBeginInfo-06020",
        Layer::Names,
        |unchecked| {
            execute_in_pass(
                &mut primary,
                pass,
                fb,
                secondaries,
                0,
                &[&secondary],
                unchecked,
            )
        },
    );
    let with_other_fb = tuff::CommandBufferInheritanceInfo::new()
        .render_pass(Some(pass))
        .framebuffer(Some(&other_fb));
    record_secondary(&mut secondary, CONTINUE, &with_other_fb);
    breaks(
        &s,
        "VUID-vkCmdExecuteCommands-pCommandBuffers-00099",
        Layer::Names,
        |unchecked| {
            execute_in_pass(
                &mut primary,
                pass,
                fb,
                secondaries,
                0,
                &[&secondary],
                unchecked,
            )
        },
    );

    // Subpass 1 of the two-subpass pass, and the one-subpass pass's secondary in a
    // render pass of the same attachments (compatible), with its framebuffer.
    let two_subpass1 = tuff::CommandBufferInheritanceInfo::new()
        .render_pass(Some(&two))
        .subpass(1);
    record_secondary(&mut secondary, CONTINUE, &two_subpass1);
    let (_opool, mut first) = s.command_buffer(vk::CommandBufferLevel::SECONDARY);
    record_secondary(&mut first, CONTINUE, &two_subpass0);
    let clear = [vk::ClearValue::default()];
    let rec = primary
        .begin(&tuff::CommandBufferBeginInfo::new())
        .expect("begin");
    let mut rec = rec.begin_render_pass(
        &tuff::RenderPassBeginInfo::new(&two, &two_fb)
            .render_area(area())
            .clear_values(&clear),
        secondaries,
    );
    rec.execute_commands(&first).expect("subpass 0");
    rec.next_subpass(secondaries);
    rec.execute_commands(&secondary).expect("subpass 1");
    rec.end_render_pass().end().expect("end");
    s.submit_wait(&primary);
    let with_fb = tuff::CommandBufferInheritanceInfo::new()
        .render_pass(Some(&other.render_pass))
        .framebuffer(Some(fb));
    record_secondary(&mut secondary, CONTINUE, &with_fb);
    execute_in_pass(&mut primary, pass, fb, secondaries, 0, &[&secondary], false)
        .expect("a compatible render pass and the instance's framebuffer");
    assert_silent(&s.messages);
}

/// Inside dynamic rendering, a secondary continues it: the instance takes
/// secondaries (06024), and the secondary was recorded with RENDER_PASS_CONTINUE for
/// no render pass (06025), the instance's flags (06026), view mask (06031) and
/// attachment formats, UNDEFINED where the instance has no view (06027 to 06030,
/// 07606, 06774, 06775).
#[test]
fn secondaries_continue_the_dynamic_rendering_they_were_recorded_for() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let target = s.color_target(SIZE, vk::ImageUsageFlags::empty());
    let (_pool, mut primary) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let (_spool, mut secondary) = s.command_buffer(vk::CommandBufferLevel::SECONDARY);
    let rgba = vk::Format::R8G8B8A8_UNORM;
    let undefined = vk::Format::UNDEFINED;
    let contents = vk::RenderingFlags::CONTENTS_SECONDARY_COMMAND_BUFFERS;
    let with_view = [tuff::RenderingAttachmentInfo::new()
        .image_view(Some(&target.view))
        .image_layout(vk::ImageLayout::COLOR_ATTACHMENT_OPTIMAL)
        .load_op(vk::AttachmentLoadOp::CLEAR)
        .store_op(vk::AttachmentStoreOp::STORE)];
    let two = [
        with_view[0],
        tuff::RenderingAttachmentInfo::new()
            .image_layout(vk::ImageLayout::COLOR_ATTACHMENT_OPTIMAL)
            .load_op(vk::AttachmentLoadOp::DONT_CARE)
            .store_op(vk::AttachmentStoreOp::DONT_CARE),
    ];
    let execute = |primary: &mut tuff::CommandBuffer,
                   secondary: &tuff::CommandBuffer,
                   flags: vk::RenderingFlags,
                   colors: &[tuff::RenderingAttachmentInfo<'_>],
                   unchecked: bool| {
        let rendering = tuff::RenderingInfo::new()
            .flags(flags)
            .render_area(area())
            .layer_count(1)
            .color_attachments(colors);
        let rec = primary
            .begin(&tuff::CommandBufferBeginInfo::new())
            .expect("begin");
        let mut rec = rec.begin_rendering(&rendering);
        if unchecked {
            unsafe { rec.execute_commands_unchecked(secondary) }
        } else {
            rec.execute_commands(secondary)
        }
    };
    let record = |cb: &mut tuff::CommandBuffer,
                  flags: vk::RenderingFlags,
                  view_mask: u32,
                  colors: &[vk::Format],
                  depth: vk::Format| {
        let mut rendering = tuff::CommandBufferInheritanceRenderingInfo::new()
            .flags(flags)
            .view_mask(view_mask)
            .color_attachment_formats(colors)
            .depth_attachment_format(depth)
            .rasterization_samples(vk::SampleCountFlags::TYPE_1);
        let inheritance = tuff::CommandBufferInheritanceInfo::new().push_next(&mut rendering);
        record_secondary(cb, CONTINUE, &inheritance);
    };
    record(
        &mut secondary,
        vk::RenderingFlags::empty(),
        0,
        &[rgba],
        undefined,
    );
    breaks(
        &s,
        "VUID-vkCmdExecuteCommands-flags-06024",
        Layer::Names,
        |unchecked| {
            execute(
                &mut primary,
                &secondary,
                vk::RenderingFlags::empty(),
                &with_view,
                unchecked,
            )
        },
    );
    execute(&mut primary, &secondary, contents, &with_view, false)
        .expect("the formats it was recorded for");
    type Case<'a> = (
        &'a str,
        vk::RenderingFlags,
        u32,
        &'a [vk::Format],
        vk::Format,
        &'a [tuff::RenderingAttachmentInfo<'a>],
    );
    let cases: [Case<'_>; 5] = [
        (
            "VUID-vkCmdExecuteCommands-flags-06026",
            vk::RenderingFlags::RESUMING,
            0,
            &[rgba],
            undefined,
            &with_view,
        ),
        (
            "VUID-vkCmdExecuteCommands-colorAttachmentCount-06027",
            vk::RenderingFlags::empty(),
            0,
            &[rgba, rgba],
            undefined,
            &with_view,
        ),
        (
            "VUID-vkCmdExecuteCommands-imageView-06028",
            vk::RenderingFlags::empty(),
            0,
            &[vk::Format::B8G8R8A8_UNORM],
            undefined,
            &with_view,
        ),
        (
            "VUID-vkCmdExecuteCommands-imageView-07606",
            vk::RenderingFlags::empty(),
            0,
            &[rgba, rgba],
            undefined,
            &two,
        ),
        (
            "VUID-vkCmdExecuteCommands-pDepthAttachment-06774",
            vk::RenderingFlags::empty(),
            0,
            &[rgba],
            vk::Format::D32_SFLOAT,
            &with_view,
        ),
    ];
    for (rule, flags, view_mask, colors, depth, attachments) in cases {
        record(&mut secondary, flags, view_mask, colors, depth);
        // The 1.3.239 layer does not check a format given where the instance has no
        // view: tuff's error alone proves it.
        let layer = if rule.ends_with("07606") {
            Layer::Silent
        } else {
            Layer::Names
        };
        breaks(&s, rule, layer, |unchecked| {
            execute(&mut primary, &secondary, contents, attachments, unchecked)
        });
    }
    record(
        &mut secondary,
        vk::RenderingFlags::empty(),
        0,
        &[rgba, undefined],
        undefined,
    );
    execute(&mut primary, &secondary, contents, &two, false)
        .expect("UNDEFINED where the instance has no view");
    // A secondary recorded for a render pass.
    let for_pass = tuff::CommandBufferInheritanceInfo::new().render_pass(Some(&target.render_pass));
    record_secondary(&mut secondary, CONTINUE, &for_pass);
    breaks(
        &s,
        "VUID-vkCmdExecuteCommands-pBeginInfo-06025",
        Layer::Names,
        |unchecked| execute(&mut primary, &secondary, contents, &with_view, unchecked),
    );
    assert_silent(&s.messages);
}

/// While the primary has a query active, a secondary runs only where the device
/// inherits queries (00101). (lavapipe has no inheritedQueries, so the rules of a
/// secondary run under an active query, 00102 to 00105, are checked but unproven.)
#[test]
fn secondaries_run_under_active_queries_only_where_queries_are_inherited() {
    let _serial = vulkan::serial();
    let execute = |primary: &mut tuff::CommandBuffer,
                   secondary: &tuff::CommandBuffer,
                   pool: &tuff::QueryPool,
                   flags: vk::QueryControlFlags,
                   unchecked: bool| {
        let mut rec = primary
            .begin(&tuff::CommandBufferBeginInfo::new())
            .expect("begin");
        rec.reset_query_pool(pool, 0, 2).expect("reset");
        rec.begin_query(pool, 0, flags).expect("begin query");
        if unchecked {
            unsafe { rec.execute_commands_unchecked(secondary) }
        } else {
            rec.execute_commands(secondary)
        }
    };

    let s = setup(true);
    let occlusion = s
        .device
        .create_query_pool(
            &tuff::QueryPoolCreateInfo::new()
                .query_type(vk::QueryType::OCCLUSION)
                .query_count(2),
        )
        .expect("query pool");
    let (_pool, mut primary) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let (_spool, mut secondary) = s.command_buffer(vk::CommandBufferLevel::SECONDARY);
    // (Without the feature, no secondary can be recorded for an occlusion query.)
    record_secondary(
        &mut secondary,
        Usage::empty(),
        &tuff::CommandBufferInheritanceInfo::new(),
    );
    breaks(
        &s,
        "VUID-vkCmdExecuteCommands-commandBuffer-00101",
        Layer::Names,
        |unchecked| {
            execute(
                &mut primary,
                &secondary,
                &occlusion,
                vk::QueryControlFlags::empty(),
                unchecked,
            )
        },
    );
    // The same secondary runs once the query has ended.
    let mut rec = primary
        .begin(&tuff::CommandBufferBeginInfo::new())
        .expect("begin");
    rec.reset_query_pool(&occlusion, 0, 2).expect("reset");
    rec.begin_query(&occlusion, 0, vk::QueryControlFlags::empty())
        .expect("begin query");
    rec.end_query(&occlusion, 0).expect("end query");
    rec.execute_commands(&secondary)
        .expect("no query is active");
    rec.end().expect("end");
    s.submit_wait(&primary);
    assert_silent(&s.messages);
}

/// A secondary that suspends or resumes a render pass instance (recorded through
/// `begin_rendering_unchecked`, as the safe `begin_rendering` refuses) is not
/// executed by the safe method.
#[test]
fn suspending_secondaries_are_not_executed_safely() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let target = s.color_target(SIZE, vk::ImageUsageFlags::empty());
    let (_pool, mut primary) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let (_spool, mut secondary) = s.command_buffer(vk::CommandBufferLevel::SECONDARY);
    let color = [tuff::RenderingAttachmentInfo::new()
        .image_view(Some(&target.view))
        .image_layout(vk::ImageLayout::COLOR_ATTACHMENT_OPTIMAL)
        .load_op(vk::AttachmentLoadOp::CLEAR)
        .store_op(vk::AttachmentStoreOp::STORE)];
    let rendering = tuff::RenderingInfo::new()
        .flags(vk::RenderingFlags::SUSPENDING)
        .render_area(area())
        .layer_count(1)
        .color_attachments(&color);
    let none = tuff::CommandBufferInheritanceInfo::new();
    let rec = secondary
        .begin(&tuff::CommandBufferBeginInfo::new().inheritance_info(Some(&none)))
        .expect("begin");
    // SAFETY: the instance is suspended and never resumed; the buffer is never
    // submitted.
    let rec = unsafe { rec.begin_rendering_unchecked(&rendering) };
    rec.end_rendering().end().expect("end");
    breaks(
        &s,
        "VUID-vkCmdExecuteCommands-pCommandBuffers-06021",
        Layer::Silent,
        |unchecked| execute_outside(&mut primary, &[&secondary], unchecked),
    );
    assert_silent(&s.messages);
}

/// A secondary keeps the render pass and framebuffer its inheritance names alive as
/// long as its recording: dropped while it records, they are still there when it
/// ends and when a primary runs it.
#[test]
fn secondaries_keep_what_their_inheritance_names() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let target = s.color_target(SIZE, vk::ImageUsageFlags::empty());
    let (_pool, mut primary) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let (_spool, mut secondary) = s.command_buffer(vk::CommandBufferLevel::SECONDARY);
    let before = s.device.live_object_count();
    let pass = s.color_pass(vk::Format::R8G8B8A8_UNORM, 1);
    let fb = framebuffer(&s, &pass, &target.view);
    let inheritance = tuff::CommandBufferInheritanceInfo::new()
        .render_pass(Some(&pass))
        .framebuffer(Some(&fb));
    let info = tuff::CommandBufferBeginInfo::new()
        .flags(CONTINUE)
        .inheritance_info(Some(&inheritance));
    let rec = secondary.begin_continuing(&info).expect("begin continuing");
    drop((pass, fb));
    rec.end().expect("end");
    assert_eq!(s.device.live_object_count(), before + 2);
    // Run where the inheritance fits no framebuffer the test still holds: as a
    // secondary that names none, in the target's (compatible) render pass.
    let nameless = s.color_pass(vk::Format::R8G8B8A8_UNORM, 1);
    let inheritance = tuff::CommandBufferInheritanceInfo::new().render_pass(Some(&nameless));
    let (_npool, mut other) = s.command_buffer(vk::CommandBufferLevel::SECONDARY);
    let info = tuff::CommandBufferBeginInfo::new()
        .flags(CONTINUE)
        .inheritance_info(Some(&inheritance));
    let rec = other.begin_continuing(&info).expect("begin continuing");
    drop(nameless);
    rec.end().expect("end");
    execute_in_pass(
        &mut primary,
        &target.render_pass,
        &target.framebuffer,
        vk::SubpassContents::SECONDARY_COMMAND_BUFFERS,
        0,
        &[&other],
        false,
    )
    .expect("a secondary for a compatible render pass");
    drop(primary);
    // Recording again lets them go.
    let held = s.device.live_object_count();
    record_secondary(
        &mut secondary,
        Usage::empty(),
        &tuff::CommandBufferInheritanceInfo::new(),
    );
    assert_eq!(s.device.live_object_count(), held - 2);
    assert_silent(&s.messages);
}

/// A secondary that a pending primary runs is pending too: it is not recorded
/// again (`VUID-vkBeginCommandBuffer-commandBuffer-00049`) nor its pool reset
/// (`VUID-vkResetCommandPool-commandPool-00040`) until the primary completes, and
/// its pool dropped meanwhile keeps it until then.
#[test]
fn a_pending_primary_keeps_its_secondaries() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let (_pool, mut primary) = s.command_buffer(vk::CommandBufferLevel::PRIMARY);
    let (spool, mut secondary) = s.command_buffer(vk::CommandBufferLevel::SECONDARY);
    let none = tuff::CommandBufferInheritanceInfo::new();
    record_secondary(&mut secondary, Usage::empty(), &none);
    let mut rec = primary
        .begin(&tuff::CommandBufferBeginInfo::new())
        .expect("begin");
    rec.execute_commands(&secondary).expect("execute");
    rec.end().expect("end");
    let pending = tuff_setup::Pending::submit(&s, &primary);
    let info = tuff::CommandBufferBeginInfo::new().inheritance_info(Some(&none));
    assert_eq!(
        tuff_setup::vuid(secondary.begin(&info)),
        "VUID-vkBeginCommandBuffer-commandBuffer-00049"
    );
    assert_eq!(
        tuff_setup::vuid(
            s.device
                .reset_command_pool(&spool, vk::CommandPoolResetFlags::empty())
        ),
        "VUID-vkResetCommandPool-commandPool-00040"
    );
    drop((secondary, spool));
    pending.release();
    assert_silent(&s.messages);
}

/// Begins `cb`, a secondary, with `inheritance` (continuing a render pass instance
/// where `flags` says so): through the safe method, or through ash's raw
/// `vkBeginCommandBuffer` (the layer told to skip a call it reports).
fn begin_with(
    s: &Setup,
    cb: &mut tuff::CommandBuffer,
    flags: Usage,
    inheritance: &tuff::CommandBufferInheritanceInfo<'_>,
    unchecked: bool,
) -> tuff::Result<()> {
    let info = tuff::CommandBufferBeginInfo::new()
        .flags(flags)
        .inheritance_info(Some(inheritance));
    if unchecked {
        // SAFETY: the command buffer is not recording nor pending, and the info is a
        // safe struct's; the layer skips the call it reports, so the driver never
        // sees the rule broken.
        unsafe { s.device.fns().begin_command_buffer(cb.raw(), info.as_raw()) }
            .map_err(tuff::Error::Vk)
    } else if flags.contains(CONTINUE) {
        cb.begin_continuing(&info).map(drop)
    } else {
        cb.begin(&info).map(drop)
    }
}

/// What a secondary's inheritance info says is checked when it is begun: the
/// queries it runs under against the device's features (02788, 00058), and the
/// dynamic rendering it continues: its formats' aspects and features (06540, 06541,
/// 06006), that depth and stencil agree (06200), and its view mask (06009).
#[test]
fn inheritance_infos_are_checked_when_begun() {
    let _serial = vulkan::serial();
    let s = setup(true);
    let (_pool, mut secondary) = s.command_buffer(vk::CommandBufferLevel::SECONDARY);
    let none = Usage::empty();
    let precise =
        tuff::CommandBufferInheritanceInfo::new().query_flags(vk::QueryControlFlags::PRECISE);
    breaks(
        &s,
        "VUID-VkCommandBufferInheritanceInfo-queryFlags-02788",
        Layer::Names,
        |unchecked| begin_with(&s, &mut secondary, none, &precise, unchecked),
    );
    let counting = tuff::CommandBufferInheritanceInfo::new()
        .pipeline_statistics(vk::QueryPipelineStatisticFlags::CLIPPING_INVOCATIONS);
    breaks(
        &s,
        "VUID-VkCommandBufferInheritanceInfo-pipelineStatistics-00058",
        Layer::Names,
        |unchecked| begin_with(&s, &mut secondary, none, &counting, unchecked),
    );
    let rgba = [vk::Format::R8G8B8A8_UNORM];
    let undefined = vk::Format::UNDEFINED;
    // (rule, colors, depth, stencil, samples, view mask)
    type Case<'a> = (
        &'a str,
        &'a [vk::Format],
        vk::Format,
        vk::Format,
        vk::SampleCountFlags,
        u32,
    );
    let one = vk::SampleCountFlags::TYPE_1;
    let cases: [Case<'_>; 4] = [
        (
            "VUID-VkCommandBufferInheritanceRenderingInfo-depthAttachmentFormat-06540",
            &[],
            vk::Format::R8G8B8A8_UNORM,
            undefined,
            one,
            0,
        ),
        (
            "VUID-VkCommandBufferInheritanceRenderingInfo-stencilAttachmentFormat-06541",
            &[],
            undefined,
            vk::Format::D32_SFLOAT,
            one,
            0,
        ),
        (
            "VUID-VkCommandBufferInheritanceRenderingInfo-depthAttachmentFormat-06200",
            &[],
            vk::Format::D32_SFLOAT_S8_UINT,
            vk::Format::S8_UINT,
            one,
            0,
        ),
        (
            "VUID-VkCommandBufferInheritanceRenderingInfo-pColorAttachmentFormats-06006",
            &[vk::Format::BC1_RGB_UNORM_BLOCK],
            undefined,
            undefined,
            one,
            0,
        ),
    ];
    for (rule, colors, depth, stencil, samples, view_mask) in cases {
        breaks(&s, rule, Layer::Names, |unchecked| {
            let mut rendering = tuff::CommandBufferInheritanceRenderingInfo::new()
                .view_mask(view_mask)
                .color_attachment_formats(colors)
                .depth_attachment_format(depth)
                .stencil_attachment_format(stencil)
                .rasterization_samples(samples);
            let inheritance = tuff::CommandBufferInheritanceInfo::new().push_next(&mut rendering);
            begin_with(&s, &mut secondary, CONTINUE, &inheritance, unchecked)
        });
    }
    // What the device allows begins.
    let mut rendering = tuff::CommandBufferInheritanceRenderingInfo::new()
        .color_attachment_formats(&rgba)
        .depth_attachment_format(vk::Format::D32_SFLOAT_S8_UINT)
        .stencil_attachment_format(vk::Format::D32_SFLOAT_S8_UINT)
        .rasterization_samples(one);
    let inheritance = tuff::CommandBufferInheritanceInfo::new().push_next(&mut rendering);
    begin_with(&s, &mut secondary, CONTINUE, &inheritance, false).expect("a valid inheritance");
    assert_silent(&s.messages);
    drop((secondary, _pool));

    // A view past maxMultiviewViewCount, on a device with multiview.
    let s = tuff_setup::setup_full_features(true);
    let (_pool, mut secondary) = s.command_buffer(vk::CommandBufferLevel::SECONDARY);
    breaks(
        &s,
        "VUID-VkCommandBufferInheritanceRenderingInfo-viewMask-06009",
        Layer::Names,
        |unchecked| {
            let mut rendering = tuff::CommandBufferInheritanceRenderingInfo::new()
                .view_mask(1 << 31)
                .color_attachment_formats(&rgba)
                .rasterization_samples(one);
            let inheritance = tuff::CommandBufferInheritanceInfo::new().push_next(&mut rendering);
            begin_with(&s, &mut secondary, CONTINUE, &inheritance, unchecked)
        },
    );
    assert_silent(&s.messages);
}
