//! Routine setup work in one call each: record, submit and wait
//! ([`Queue::submit_and_wait`]); an image-layout transition that waits for what the
//! recording did to the image, as the hazard tracker followed it, and blocks what
//! its new layout is for ([`Recorder::transition_image`]); and bytes uploaded
//! into an image through a staging buffer, with the transitions around the copy
//! ([`Queue::upload_image`]).
//!
//! They are built from the safe methods, so every rule those check still holds: a
//! transition from a layout the image is not in is refused when it is submitted
//! (the device follows each image's layouts), and an upload of too few bytes is
//! refused by the copy's checks.

use crate::recorder::{Outside, Recorder};
use crate::structs::{
    BufferCreateInfo, CommandBufferAllocateInfo, CommandBufferBeginInfo, CommandPoolCreateInfo,
    FenceCreateInfo, ImageMemoryBarrier, SubmitInfo,
};
use crate::{Error, Handle as _, Image, MemoryLocation, Queue, Result, SuccessOrTimeout};
use ash::vk;
use tuff_runtime::Allocator;

/// The stages and accesses that use an image in `layout`: what a barrier into the
/// layout waits before, or what one out of it waits for. Layouts of one use get that
/// use's stage; the rest (`GENERAL`, shader reads, which any stage may do) every
/// command and every memory access, which is always correct, if not the tightest.
fn layout_use(layout: vk::ImageLayout) -> (vk::PipelineStageFlags, vk::AccessFlags) {
    use vk::{AccessFlags as A, ImageLayout as L, PipelineStageFlags as P};
    match layout {
        L::UNDEFINED => (P::TOP_OF_PIPE, A::empty()),
        L::PREINITIALIZED => (P::HOST, A::HOST_WRITE),
        L::TRANSFER_SRC_OPTIMAL => (P::TRANSFER, A::TRANSFER_READ),
        L::TRANSFER_DST_OPTIMAL => (P::TRANSFER, A::TRANSFER_WRITE),
        L::COLOR_ATTACHMENT_OPTIMAL => (
            P::COLOR_ATTACHMENT_OUTPUT,
            A::COLOR_ATTACHMENT_READ | A::COLOR_ATTACHMENT_WRITE,
        ),
        L::DEPTH_STENCIL_ATTACHMENT_OPTIMAL => (
            P::EARLY_FRAGMENT_TESTS | P::LATE_FRAGMENT_TESTS,
            A::DEPTH_STENCIL_ATTACHMENT_READ | A::DEPTH_STENCIL_ATTACHMENT_WRITE,
        ),
        L::PRESENT_SRC_KHR => (P::BOTTOM_OF_PIPE, A::empty()),
        _ => (P::ALL_COMMANDS, A::MEMORY_READ | A::MEMORY_WRITE),
    }
}

impl Recorder<'_, Outside> {
    crate::helpers::as_safe_as! { vkCmdPipelineBarrier,
        /// Moves every mip level and array layer of `aspect` of `image` from `old` to
        /// `new` with one pipeline barrier: the work that used it in `old` (none for
        /// `UNDEFINED`) finishes, and its writes are visible, before any work that uses
        /// it in `new` starts. The barrier waits for the recording's last accesses to
        /// the image as the hazard tracker followed them (the copy that wrote it, the
        /// draws that sampled it), and, where the recording has not touched every
        /// subresource, for what `old` implies (any stage for `GENERAL`).
        ///
        /// `old` must be the layout the image is in when the command buffer runs; tuff
        /// follows every image's layouts and refuses the submission otherwise
        /// (`UNDEFINED` is always accepted and discards the contents).
        ///
        /// ```no_run
        /// # fn f(rec: &mut tuff::Recorder<'_, tuff::Outside>, image: &tuff::Image) -> tuff::Result<()> {
        /// use tuff::vk;
        /// rec.transition_image(
        ///     image,
        ///     vk::ImageAspectFlags::COLOR,
        ///     vk::ImageLayout::UNDEFINED,
        ///     vk::ImageLayout::TRANSFER_DST_OPTIMAL,
        /// )?;
        /// # Ok(()) }
        /// ```
        ///
        /// # Safety
        ///
        /// This method is `unsafe` exactly when [`Recorder::pipeline_barrier`] is
        /// (it is safe with this crate's emitted API); the caller then upholds the
        /// rules its `# Safety` section lists for this one image barrier.
        pub fn transition_image(
            &mut self,
            image: &Image,
            aspect: vk::ImageAspectFlags,
            old: vk::ImageLayout,
            new: vk::ImageLayout,
        ) -> Result<()> {
            let range = vk::ImageSubresourceRange {
                aspect_mask: aspect,
                base_mip_level: 0,
                level_count: vk::REMAINING_MIP_LEVELS,
                base_array_layer: 0,
                layer_count: vk::REMAINING_ARRAY_LAYERS,
            };
            // What waits: the recording's last uses of the image as the hazard
            // tracker followed them, else the uses its old layout implies.
            let (src_stage, src_access) =
                crate::special::hazards::source_scope(
                    self,
                    image.raw(),
                    &crate::state::layouts::Sel::range(&range),
                )
                    .unwrap_or_else(|| layout_use(old));
            let (dst_stage, dst_access) = layout_use(new);
            let barrier = ImageMemoryBarrier::new(image)
                .src_access_mask(src_access)
                .dst_access_mask(dst_access)
                .old_layout(old)
                .new_layout(new)
                .src_queue_family_index(vk::QUEUE_FAMILY_IGNORED)
                .dst_queue_family_index(vk::QUEUE_FAMILY_IGNORED)
                .subresource_range(range);
            #[allow(unused_unsafe)]
            // SAFETY: where `pipeline_barrier` is `unsafe`, so is this method, and
            // its caller upholds the rules of this barrier.
            unsafe {
                self.pipeline_barrier(
                    src_stage,
                    dst_stage,
                    vk::DependencyFlags::empty(),
                    &[],
                    &[],
                    &[barrier],
                )
            }
        }
    }
}

impl Queue {
    /// The family of this queue: the `queue_family_index` it was got with.
    ///
    /// ```no_run
    /// # fn f(device: &tuff::Device) -> tuff::Result<()> {
    /// let queue = device.get_queue(0, 0)?;
    /// assert_eq!(queue.family_index(), 0);
    /// # Ok(()) }
    /// ```
    pub fn family_index(&self) -> u32 {
        // Every queue wrapper comes from `get_queue` or `get_queue2`,
        // which record its family (`special::queue::queue_got`).
        self.parent()
            .live()
            .queue_family(self.raw())
            .unwrap_or_default()
    }

    crate::helpers::as_safe_as! { vkQueueSubmit,
        /// Records `record` into a new command buffer (of a transient pool of this
        /// queue's family, begun for one submission), submits it to this queue with a
        /// fence, and waits for the fence: setup work in one call. Returns what
        /// `record` returned. Everything the commands use is kept alive until they
        /// completed, as in any submission.
        ///
        /// Fails with the error of the first check that refuses a command (nothing is
        /// submitted then), or of the submission or the wait.
        ///
        /// ```no_run
        /// # fn f(queue: &tuff::Queue, image: &tuff::Image) -> tuff::Result<()> {
        /// use tuff::vk::{ImageAspectFlags, ImageLayout};
        /// queue.submit_and_wait(|rec| {
        ///     let color = ImageAspectFlags::COLOR;
        ///     rec.transition_image(image, color, ImageLayout::UNDEFINED, ImageLayout::GENERAL)
        /// })?;
        /// # Ok(()) }
        /// ```
        ///
        /// # Safety
        ///
        /// This method is `unsafe` exactly when [`Queue::submit`] is (it is safe
        /// with this crate's emitted API; a crate generated from more of the registry
        /// may leave it rules); the caller then upholds the rules its `# Safety`
        /// section lists for a submission of the recorded command buffer.
        pub fn submit_and_wait<R>(
            &self,
            record: impl FnOnce(&mut Recorder<'_, Outside>) -> Result<R>,
        ) -> Result<R> {
            #[allow(unused_unsafe)]
            // SAFETY: as `submit_and_wait_with`, which is `unsafe` where this is.
            unsafe {
                self.submit_and_wait_with(|mut rec| {
                    let out = record(&mut rec)?;
                    Ok((rec, out))
                })
            }
        }
    }

    crate::helpers::as_safe_as! { vkQueueSubmit,
        /// [`Queue::submit_and_wait`] with a closure that owns the recorder, so that
        /// it can begin a render pass instance (which moves the recorder into the
        /// instance's state) and hands it back outside one, with its value.
        ///
        /// ```no_run
        /// # fn f(queue: &tuff::Queue, begin: &tuff::RenderPassBeginInfo<'_>) -> tuff::Result<()> {
        /// queue.submit_and_wait_with(|rec| {
        ///     let rec = rec.begin_render_pass(begin, tuff::vk::SubpassContents::INLINE);
        ///     // ... the instance's commands ...
        ///     Ok((rec.end_render_pass(), ()))
        /// })?;
        /// # Ok(()) }
        /// ```
        ///
        /// # Safety
        ///
        /// As [`Queue::submit_and_wait`].
        pub fn submit_and_wait_with<R>(
            &self,
            record: impl for<'r> FnOnce(Recorder<'r, Outside>) -> Result<(Recorder<'r, Outside>, R)>,
        ) -> Result<R> {
            let device = self.parent();
            let pool = device.create_command_pool(
                &CommandPoolCreateInfo::new()
                    .flags(vk::CommandPoolCreateFlags::TRANSIENT)
                    .queue_family_index(self.family_index()),
            )?;
            let mut buffers = device.allocate_command_buffers(
                &pool,
                &CommandBufferAllocateInfo::new(&pool)
                    .level(vk::CommandBufferLevel::PRIMARY)
                    .command_buffer_count(1),
            )?;
            let mut commands = buffers
                .pop()
                .ok_or(Error::Misuse("vkAllocateCommandBuffers returned no command buffer"))?;
            let out = {
                let rec = commands.begin(
                    &CommandBufferBeginInfo::new()
                        .flags(vk::CommandBufferUsageFlags::ONE_TIME_SUBMIT),
                )?;
                let (rec, out) = record(rec)?;
                rec.end()?;
                out
            };
            // `create_fence` is safe in the pinned configuration and may be `unsafe`
            // in wider ones.
            #[allow(unused_unsafe)]
            // SAFETY: a fence with no flags and no chain: the rules a wider
            // configuration adds are about chained export infos.
            let fence = unsafe { device.create_fence(&FenceCreateInfo::new()) }?;
            #[allow(unused_unsafe)]
            // SAFETY: where `submit` is `unsafe`, so is this method, and its
            // caller upholds the rules of this submission.
            unsafe { self.submit(&[SubmitInfo::new().command_buffers(&commands)], Some(&fence)) }?;
            match device.wait_for_fences(&fence, true, u64::MAX)? {
                SuccessOrTimeout::Success => Ok(out),
                // No timeout was asked for; a driver that reports one anyway fails
                // here.
                SuccessOrTimeout::Timeout => Err(Error::Vk(vk::Result::TIMEOUT)),
            }
        }
    }

    crate::helpers::as_safe_as! { upload_image,
        /// Copies `bytes` into mip level 0, array layer 0 of `aspect` of `image` (its
        /// whole extent, rows tightly packed) through a staging buffer from
        /// `allocator`, and leaves the image in `layout`: one call for a texture's
        /// upload. The image must have the transfer-destination usage; whatever it
        /// held is discarded (it is moved from `UNDEFINED`). Waits until the copy is
        /// done.
        ///
        /// Fails, with nothing submitted, when `bytes` is shorter than the region
        /// (`VUID-vkCmdCopyBufferToImage-pRegions-00171`) or the copy is otherwise
        /// refused, and with [`Error::Misuse`] for a depth aspect, whose data must be
        /// in \[0, 1\] (`VUID-vkCmdCopyBufferToImage-None-00214`), which depends on its
        /// format: copy it with [`Recorder::copy_buffer_to_image`].
        ///
        /// ```no_run
        /// # fn f(queue: &tuff::Queue, image: &tuff::Image, a: &tuff::GpuAllocator) -> tuff::Result<()> {
        /// use tuff::vk;
        /// let pixels = vec![255u8; 4 * 16 * 16]; // a white 16x16 RGBA8 image
        /// queue.upload_image(
        ///     image,
        ///     vk::ImageAspectFlags::COLOR,
        ///     &pixels,
        ///     vk::ImageLayout::SHADER_READ_ONLY_OPTIMAL,
        ///     a,
        /// )?;
        /// # Ok(()) }
        /// ```
        ///
        /// # Safety
        ///
        /// This method is `unsafe` exactly when one of [`Queue::submit`],
        /// [`Recorder::pipeline_barrier`] and [`Recorder::copy_buffer_to_image`]
        /// leaves its caller a rule other than the depth rule above (none does with this
        /// crate's emitted API); the caller then upholds the rules their `# Safety`
        /// sections list for the staging copy, the two image barriers around it and
        /// their submission.
        pub fn upload_image<A: Allocator + ?Sized>(
            &self,
            image: &Image,
            aspect: vk::ImageAspectFlags,
            bytes: &[u8],
            layout: vk::ImageLayout,
            allocator: &A,
        ) -> Result<()> {
            if aspect.contains(vk::ImageAspectFlags::DEPTH) {
                // VUID-vkCmdCopyBufferToImage-None-00214 asks depth data in [0, 1],
                // which depends on the format; this helper leaves depth to the copy.
                return Err(Error::Misuse(
                    "upload_image copies color, stencil and plane aspects; copy depth data with Recorder::copy_buffer_to_image",
                ));
            }
            let device = self.parent();
            let extent = device
                .live()
                .image(image.raw())
                .map(|r| r.extent)
                .ok_or(Error::Misuse("the image is not one this device made"))?;
            let staging = device.create_buffer_in(
                &BufferCreateInfo::new()
                    .size(bytes.len().max(1) as u64)
                    .usage(vk::BufferUsageFlags::TRANSFER_SRC),
                allocator,
                MemoryLocation::Upload,
            )?;
            staging.memory().write(0, bytes)?;
            let region = vk::BufferImageCopy {
                image_subresource: vk::ImageSubresourceLayers {
                    aspect_mask: aspect,
                    mip_level: 0,
                    base_array_layer: 0,
                    layer_count: 1,
                },
                image_extent: extent,
                ..Default::default()
            };
            let record = |rec: &mut Recorder<'_, Outside>| {
                let dst = vk::ImageLayout::TRANSFER_DST_OPTIMAL;
                #[allow(unused_unsafe)]
                // SAFETY: where any of these leaves its caller a rule other than
                // VUID-vkCmdCopyBufferToImage-None-00214, this method is `unsafe`
                // (`as_safe_as!`) and its caller upholds it; 00214 is about depth
                // aspects, which this method refuses above.
                unsafe {
                    rec.transition_image(image, aspect, vk::ImageLayout::UNDEFINED, dst)?;
                    rec.copy_buffer_to_image(&staging, image, dst, &[region])?;
                    rec.transition_image(image, aspect, dst, layout)
                }
            };
            #[allow(unused_unsafe)]
            // SAFETY: as above, for the submission.
            unsafe { self.submit_and_wait(record) }
        }
    }
}
