//! The safe forms of the indirect draws and dispatches. The generated
//! `draw_indirect` and its siblings take any buffer, whose arguments the device reads
//! when the command executes, so they leave the arguments' rules to their caller and
//! stay `unsafe`. The forms here take an [`IndirectBuffer`] instead, whose contents
//! only the host writes and tuff keeps a copy of (`memory/indirect.rs`), and check
//! each draw or dispatch they name as the direct command is checked: the range they
//! read inside the buffer, a count buffer's count against the limit, and for every
//! draw its instances in a multiview instance, its indices inside the bound index
//! buffer and its vertex fetches inside the bound vertex buffers (`special::draw`).
//! The arguments' own rules (`firstInstance` without `drawIndirectFirstInstance`, a
//! dispatch's group counts) were checked when they were written. Then the generated
//! method runs every check of the command's state, and records it.
//!
//! The generator's `plan/special/indirect.rs` lists the rules each form settles; a
//! form is `unsafe` where its command leaves its caller a rule outside those (a
//! registry or extension set wider than this crate's), through `as_safe_as!`.

use super::draw::{indexed_range_checks, vertices_checks};
use super::refuse;
use crate::memory::indirect::{IndirectArguments, IndirectBuffer};
use crate::recorder::{Inside, Outside, Recorder};
use crate::{Error, Result};
use ash::vk;
use core::ops::Range;

/// The rules of one indirect command about the range of arguments it reads.
struct RangeRules {
    /// The buffer holds the one draw (or dispatch) read.
    one: &'static str,
    /// The buffer holds every draw read.
    many: &'static str,
}

/// The byte offset and count of `draws`, refused (by `rules`) when they reach past
/// the arguments the buffer holds.
fn range_checks<T: IndirectArguments>(
    arguments: &IndirectBuffer<T>,
    draws: &Range<u32>,
    rules: RangeRules,
) -> Result<(vk::DeviceSize, u32)> {
    let Some(count) = draws.end.checked_sub(draws.start) else {
        return Err(Error::Misuse("the range of indirect arguments is reversed"));
    };
    let held = arguments.len();
    if draws.end as usize > held {
        refuse(
            if count == 1 { rules.one } else { rules.many },
            format!(
                "the command reads arguments {}..{} of an indirect buffer that holds {held}",
                draws.start, draws.end
            ),
        )?;
    }
    let offset = u64::from(draws.start) * u64::from(IndirectBuffer::<T>::stride());
    Ok((offset, count))
}

/// The rules of a count command about its count buffer and what the count names.
struct CountRules {
    /// The count is read inside the count buffer.
    inside: &'static str,
    /// The buffer holds `maxDrawCount` draws.
    max: &'static str,
    /// The count is at most `maxDrawIndirectCount`.
    limit: &'static str,
    /// The buffer holds the one draw a count of 1 names.
    one: &'static str,
    /// The buffer holds every draw a larger count names.
    many: &'static str,
    /// The command needs the `drawIndirectCount` feature.
    feature: &'static str,
}

/// The byte offsets of `draws` and of the count, and how many draws the device
/// executes (the count read, at most `draws`' length), refused (by `rules`) where the
/// feature is off, the count is not in its buffer or past the limit, or the draws
/// `draws` or the count name reach past the arguments.
fn count_checks<T: IndirectArguments, S: crate::recorder::Scope>(
    recorder: &Recorder<'_, S>,
    arguments: &IndirectBuffer<T>,
    draws: &Range<u32>,
    count: &IndirectBuffer<u32>,
    count_at: u32,
    rules: CountRules,
) -> Result<(vk::DeviceSize, vk::DeviceSize, u32)> {
    let device = recorder.device();
    let scope = device.scope();
    if !scope.feature(|f| f.v12.draw_indirect_count) {
        refuse(
            rules.feature,
            "the device did not enable the drawIndirectCount feature",
        )?;
    }
    if count_at as usize >= count.len() {
        refuse(
            rules.inside,
            format!(
                "the count is read at element {count_at} of a count buffer that holds {}",
                count.len()
            ),
        )?;
    }
    let stored = count.arguments()[count_at as usize];
    let (offset, max) = range_checks(
        arguments,
        draws,
        RangeRules {
            one: rules.max,
            many: rules.max,
        },
    )?;
    if let Some(limit) = scope.limits().map(|l| l.max_draw_indirect_count) {
        if stored > limit {
            refuse(
                rules.limit,
                format!(
                    "the count buffer holds {stored} draws, past maxDrawIndirectCount ({limit})"
                ),
            )?;
        }
    }
    let held = arguments.len() as u64;
    if stored >= 1 && u64::from(draws.start) + u64::from(stored) > held {
        refuse(
            if stored == 1 { rules.one } else { rules.many },
            format!("the count buffer names {stored} draws from argument {}, and the indirect buffer holds {held}", draws.start),
        )?;
    }
    Ok((offset, u64::from(count_at) * 4, stored.min(max)))
}

/// The vertices and instances of each draw of `draws`.
fn draws_checks<S: crate::recorder::Scope>(
    recorder: &Recorder<'_, S>,
    draws: &[vk::DrawIndirectCommand],
    vertex: &'static str,
    multiview: &'static str,
) -> Result<()> {
    for d in draws {
        vertices_checks(
            recorder,
            Some((
                d.first_vertex,
                d.vertex_count,
                d.first_instance,
                d.instance_count,
                vertex,
                multiview,
            )),
        )?;
    }
    Ok(())
}

/// The indices, vertices and instances of each indexed draw of `draws`.
fn indexed_draws_checks<S: crate::recorder::Scope>(
    recorder: &Recorder<'_, S>,
    draws: &[vk::DrawIndexedIndirectCommand],
    (index, multiview, fetch): (&'static str, &'static str, &'static str),
) -> Result<()> {
    for d in draws {
        indexed_range_checks(
            recorder,
            Some((
                d.index_count,
                d.first_index,
                d.first_instance,
                d.instance_count,
                d.vertex_offset,
                index,
                multiview,
                fetch,
            )),
        )?;
    }
    Ok(())
}

/// The `executed` arguments from element `start` on.
fn named<T: IndirectArguments>(arguments: &IndirectBuffer<T>, start: u32, executed: u32) -> &[T] {
    let start = start as usize;
    &arguments.arguments()[start..start + executed as usize]
}

impl<S: Inside> Recorder<'_, S> {
    crate::helpers::as_safe_as! { draw_indirect_from,
        /// `vkCmdDrawIndirect` of the draws `draws` of `arguments`: the safe form of
        /// [`Self::draw_indirect`], whose arguments are known because the host wrote
        /// them ([`IndirectBuffer`]). Each draw is checked as [`Self::draw`] checks
        /// its parameters (its vertex fetches inside the bound vertex buffers, its
        /// instances in a multiview instance), then every check of `draw_indirect`
        /// runs (a range of more than one draw needs `multiDrawIndirect`).
        ///
        /// # Safety
        ///
        /// As [`Self::draw_indirect`], but for the rules this method checks (those of
        /// the arguments and the range it reads): safe with this crate's emitted API.
        ///
        /// ```no_run
        /// # fn f(rec: &mut tuff::Recorder<'_, tuff::InRenderPass>, draws: &tuff::IndirectBuffer<tuff::vk::DrawIndirectCommand>) -> tuff::Result<()> {
        /// rec.draw_indirect_from(draws, 0..1)?;
        /// # Ok(()) }
        /// ```
        pub fn draw_indirect_from(
            &mut self,
            arguments: &IndirectBuffer<vk::DrawIndirectCommand>,
            draws: Range<u32>,
        ) -> Result<()> {
            let rules = RangeRules {
                one: "VUID-vkCmdDrawIndirect-drawCount-00487",
                many: "VUID-vkCmdDrawIndirect-drawCount-00488",
            };
            let (offset, count) = range_checks(arguments, &draws, rules)?;
            draws_checks(
                self,
                named(arguments, draws.start, count),
                "VUID-vkCmdDrawIndirect-None-02721",
                "VUID-vkCmdDrawIndirect-maxMultiviewInstanceIndex-02688",
            )?;
            let stride = IndirectBuffer::<vk::DrawIndirectCommand>::stride();
            #[allow(unused_unsafe)]
            // SAFETY: the arguments are the host's copy, which the device reads
            // unchanged (`memory/indirect.rs`); the range lies inside them (00487,
            // 00488); the stride is the struct's size (00476); each draw's fetches and
            // instances were checked above (02721, 02688, VkDrawIndirectCommand-None-00500)
            // and its firstInstance when written (VkDrawIndirectCommand-firstInstance-00501).
            unsafe { self.draw_indirect(arguments.buffer(), offset, count, stride) }?;
            self.retain(arguments.token());
            Ok(())
        }
    }

    crate::helpers::as_safe_as! { draw_indexed_indirect_from,
        /// `vkCmdDrawIndexedIndirect` of the draws `draws` of `arguments`: the safe
        /// form of [`Self::draw_indexed_indirect`] ([`IndirectBuffer`]). Each draw is
        /// checked as [`Self::draw_indexed`] checks its parameters (its indices inside
        /// the bound index buffer, the vertices they can name inside the bound vertex
        /// buffers, its instances in a multiview instance), then every check of
        /// `draw_indexed_indirect` runs.
        ///
        /// # Safety
        ///
        /// As [`Self::draw_indexed_indirect`], but for the rules this method checks:
        /// safe with this crate's emitted API.
        ///
        /// ```no_run
        /// # fn f(rec: &mut tuff::Recorder<'_, tuff::InRenderPass>, draws: &tuff::IndirectBuffer<tuff::vk::DrawIndexedIndirectCommand>) -> tuff::Result<()> {
        /// rec.draw_indexed_indirect_from(draws, 0..draws.len() as u32)?;
        /// # Ok(()) }
        /// ```
        pub fn draw_indexed_indirect_from(
            &mut self,
            arguments: &IndirectBuffer<vk::DrawIndexedIndirectCommand>,
            draws: Range<u32>,
        ) -> Result<()> {
            let rules = RangeRules {
                one: "VUID-vkCmdDrawIndexedIndirect-drawCount-00539",
                many: "VUID-vkCmdDrawIndexedIndirect-drawCount-00540",
            };
            let (offset, count) = range_checks(arguments, &draws, rules)?;
            indexed_draws_checks(
                self,
                named(arguments, draws.start, count),
                (
                    "VUID-vkCmdDrawIndexedIndirect-robustBufferAccess2-07825",
                    "VUID-vkCmdDrawIndexedIndirect-maxMultiviewInstanceIndex-02688",
                    "VUID-vkCmdDrawIndexedIndirect-None-02721",
                ),
            )?;
            let stride = IndirectBuffer::<vk::DrawIndexedIndirectCommand>::stride();
            #[allow(unused_unsafe)]
            // SAFETY: the arguments are the host's copy, which the device reads
            // unchanged; the range lies inside them (00539, 00540); the stride is the
            // struct's size (00528); each draw's indices, fetches and instances were
            // checked above (07825, 02721, 02688, VkDrawIndexedIndirectCommand-None-00552)
            // and its firstInstance when written (-firstInstance-00554).
            unsafe { self.draw_indexed_indirect(arguments.buffer(), offset, count, stride) }?;
            self.retain(arguments.token());
            Ok(())
        }
    }

    crate::helpers::as_safe_as! { draw_indirect_count_from,
        /// `vkCmdDrawIndirectCount` of the draws `draws` of `arguments`, as many of
        /// them as element `count_at` of `count` says (at most `draws`' length): the
        /// safe form of [`Self::draw_indirect_count`] ([`IndirectBuffer`]). The count
        /// is checked against `maxDrawIndirectCount`, the draws the range and the
        /// count name against the arguments held, and each draw the device executes
        /// as [`Self::draw_indirect_from`] checks it; the device must have enabled
        /// `drawIndirectCount`.
        ///
        /// # Safety
        ///
        /// As [`Self::draw_indirect_count`], but for the rules this method checks:
        /// safe with this crate's emitted API.
        ///
        /// ```no_run
        /// # fn f(rec: &mut tuff::Recorder<'_, tuff::InRenderPass>, draws: &tuff::IndirectBuffer<tuff::vk::DrawIndirectCommand>, count: &tuff::IndirectBuffer<u32>) -> tuff::Result<()> {
        /// rec.draw_indirect_count_from(draws, 0..4, count, 0)?;
        /// # Ok(()) }
        /// ```
        pub fn draw_indirect_count_from(
            &mut self,
            arguments: &IndirectBuffer<vk::DrawIndirectCommand>,
            draws: Range<u32>,
            count: &IndirectBuffer<u32>,
            count_at: u32,
        ) -> Result<()> {
            let rules = CountRules {
                inside: "VUID-vkCmdDrawIndirectCount-countBufferOffset-04129",
                max: "VUID-vkCmdDrawIndirectCount-maxDrawCount-03111",
                limit: "VUID-vkCmdDrawIndirectCount-countBuffer-02717",
                one: "VUID-vkCmdDrawIndirectCount-countBuffer-03121",
                many: "VUID-vkCmdDrawIndirectCount-countBuffer-03122",
                feature: "VUID-vkCmdDrawIndirectCount-None-04445",
            };
            let (offset, count_offset, executed) =
                count_checks(self, arguments, &draws, count, count_at, rules)?;
            draws_checks(
                self,
                named(arguments, draws.start, executed),
                "VUID-vkCmdDrawIndirectCount-None-02721",
                "VUID-vkCmdDrawIndirectCount-maxMultiviewInstanceIndex-02688",
            )?;
            let stride = IndirectBuffer::<vk::DrawIndirectCommand>::stride();
            let max = draws.end - draws.start;
            #[allow(unused_unsafe)]
            // SAFETY: the arguments and the count are the host's copies, which the
            // device reads unchanged; the feature is on (04445); the count lies in its
            // buffer (04129) and under the limit (02717); the draws the range and the
            // count name lie inside the arguments (03111, 03121, 03122); the stride is
            // the struct's size (03110); each draw executed was checked above (02721,
            // 02688, VkDrawIndirectCommand-None-00500) and when written (-00501).
            unsafe {
                self.draw_indirect_count(arguments.buffer(), offset, count.buffer(), count_offset, max, stride)
            }?;
            self.retain(arguments.token());
            self.retain(count.token());
            Ok(())
        }
    }

    crate::helpers::as_safe_as! { draw_indexed_indirect_count_from,
        /// `vkCmdDrawIndexedIndirectCount` of the draws `draws` of `arguments`, as
        /// many as element `count_at` of `count` says (at most `draws`' length): the
        /// safe form of [`Self::draw_indexed_indirect_count`] ([`IndirectBuffer`]),
        /// checked as [`Self::draw_indirect_count_from`] and
        /// [`Self::draw_indexed_indirect_from`] check theirs.
        ///
        /// # Safety
        ///
        /// As [`Self::draw_indexed_indirect_count`], but for the rules this method
        /// checks: safe with this crate's emitted API.
        ///
        /// ```no_run
        /// # fn f(rec: &mut tuff::Recorder<'_, tuff::InRenderPass>, draws: &tuff::IndirectBuffer<tuff::vk::DrawIndexedIndirectCommand>, count: &tuff::IndirectBuffer<u32>) -> tuff::Result<()> {
        /// rec.draw_indexed_indirect_count_from(draws, 0..4, count, 0)?;
        /// # Ok(()) }
        /// ```
        pub fn draw_indexed_indirect_count_from(
            &mut self,
            arguments: &IndirectBuffer<vk::DrawIndexedIndirectCommand>,
            draws: Range<u32>,
            count: &IndirectBuffer<u32>,
            count_at: u32,
        ) -> Result<()> {
            let rules = CountRules {
                inside: "VUID-vkCmdDrawIndexedIndirectCount-countBufferOffset-04129",
                max: "VUID-vkCmdDrawIndexedIndirectCount-maxDrawCount-03143",
                limit: "VUID-vkCmdDrawIndexedIndirectCount-countBuffer-02717",
                one: "VUID-vkCmdDrawIndexedIndirectCount-countBuffer-03153",
                many: "VUID-vkCmdDrawIndexedIndirectCount-countBuffer-03154",
                feature: "VUID-vkCmdDrawIndexedIndirectCount-None-04445",
            };
            let (offset, count_offset, executed) =
                count_checks(self, arguments, &draws, count, count_at, rules)?;
            indexed_draws_checks(
                self,
                named(arguments, draws.start, executed),
                (
                    "VUID-vkCmdDrawIndexedIndirectCount-robustBufferAccess2-07825",
                    "VUID-vkCmdDrawIndexedIndirectCount-maxMultiviewInstanceIndex-02688",
                    "VUID-vkCmdDrawIndexedIndirectCount-None-02721",
                ),
            )?;
            let stride = IndirectBuffer::<vk::DrawIndexedIndirectCommand>::stride();
            let max = draws.end - draws.start;
            #[allow(unused_unsafe)]
            // SAFETY: as for `draw_indirect_count_from` (04445, 04129, 02717, 03143,
            // 03153, 03154, 03142), each draw executed checked above (07825, 02721,
            // 02688, VkDrawIndexedIndirectCommand-None-00552) and when written (-00554).
            unsafe {
                self.draw_indexed_indirect_count(arguments.buffer(), offset, count.buffer(), count_offset, max, stride)
            }?;
            self.retain(arguments.token());
            self.retain(count.token());
            Ok(())
        }
    }
}

impl Recorder<'_, Outside> {
    crate::helpers::as_safe_as! { dispatch_indirect_from,
        /// `vkCmdDispatchIndirect` of dispatch `at` of `arguments`: the safe form of
        /// [`Self::dispatch_indirect`], whose group counts were checked against
        /// `maxComputeWorkGroupCount` when the host wrote them ([`IndirectBuffer`]);
        /// then every check of `dispatch_indirect` runs.
        ///
        /// # Safety
        ///
        /// As [`Self::dispatch_indirect`], but for the rules this method checks: safe
        /// with this crate's emitted API.
        ///
        /// ```no_run
        /// # fn f(rec: &mut tuff::Recorder<'_, tuff::Outside>, groups: &tuff::IndirectBuffer<tuff::vk::DispatchIndirectCommand>) -> tuff::Result<()> {
        /// rec.dispatch_indirect_from(groups, 0)?;
        /// # Ok(()) }
        /// ```
        pub fn dispatch_indirect_from(
            &mut self,
            arguments: &IndirectBuffer<vk::DispatchIndirectCommand>,
            at: u32,
        ) -> Result<()> {
            let rule = "VUID-vkCmdDispatchIndirect-offset-00407";
            let rules = RangeRules { one: rule, many: rule };
            let Some(end) = at.checked_add(1) else {
                return refuse(rule, "the dispatch is read past the last element an indirect buffer can hold");
            };
            let (offset, _) = range_checks(arguments, &(at..end), rules)?;
            #[allow(unused_unsafe)]
            // SAFETY: the arguments are the host's copy, which the device reads
            // unchanged; the dispatch read lies inside them (00407), and its group
            // counts were checked when written (VkDispatchIndirectCommand-x-00417,
            // -y-00418, -z-00419).
            unsafe { self.dispatch_indirect(arguments.buffer(), offset) }?;
            self.retain(arguments.token());
            Ok(())
        }
    }
}
