//! Frames in flight: a ring of command buffers, each with the fence of its last
//! submission, so the host records one frame while the device still executes the
//! ones before it.
//!
//! The ring upholds, by construction, rules a hand-written loop must get right every
//! frame: a command buffer is recorded again only once its fence says the last
//! submission of it completed (`VUID-vkBeginCommandBuffer-commandBuffer-00049`), a
//! fence is reset only right before the submission that signals it, so a wait never
//! hangs on a fence nothing will signal, and is unsignalled when submitted
//! (`VUID-vkQueueSubmit-fence-00063`); the semaphores of a submission are kept alive
//! until its fence is seen signalled.

use crate::handles::{CommandBuffer, Device, Fence, Queue, Semaphore};
use crate::recorder::{Outside, Recorder};
use crate::structs::{
    CommandBufferAllocateInfo, CommandBufferBeginInfo, CommandPoolCreateInfo, FenceCreateInfo,
    SubmitInfo,
};
use crate::{Error, HandleSlice, Handles, Result, SuccessOrTimeout};
use ash::vk;
use smallvec::SmallVec;

/// `count` primary command buffers from one pool, each with a fence: the host
/// records one frame while the device still executes the ones before it.
///
/// ```no_run
/// # fn f(device: &tuff::Device, queue: &tuff::Queue, family: u32) -> tuff::Result<()> {
/// let mut frames = device.frames_in_flight(family, 2)?;
/// for _ in 0..100 {
///     let mut frame = frames.next_frame()?;
///     // frame.index picks this frame's uniform buffer, descriptor set, ...
///     let rec = frame.record()?;
///     // ... record the frame's commands ...
///     rec.end()?;
///     // SAFETY: the recording keeps the rules `Queue::submit` lists.
///     unsafe { frame.submit(queue, &[], &[]) }?;
/// }
/// frames.wait_all()?;
/// # Ok(()) }
/// ```
pub struct FramesInFlight {
    /// Each frame's command buffer (which keeps the pool) and the fence of its last
    /// submission, created signalled so the first wait returns at once.
    frames: Vec<(CommandBuffer, Fence)>,
    /// Each frame's worker secondaries, one per worker, each from a pool of its own
    /// (a pool is used by one thread at a time).
    workers: Vec<Vec<CommandBuffer>>,
    /// The frame [`FramesInFlight::next_frame`] hands out.
    next: usize,
}

impl core::fmt::Debug for FramesInFlight {
    /// The frames' command buffers and fences, and the one handed out next.
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.debug_struct("FramesInFlight")
            .field("frames", &self.frames)
            .field("next", &self.next)
            .finish()
    }
}

impl Device {
    /// A ring of `count` frames in flight (at least one) whose command buffers are
    /// submitted to queues of family `queue_family_index`.
    ///
    /// Fails with `VUID-vkCreateCommandPool-queueFamilyIndex-01937` when the device
    /// has no queue of that family.
    ///
    /// ```no_run
    /// # fn f(device: &tuff::Device) -> tuff::Result<()> {
    /// let frames = device.frames_in_flight(0, 2)?;
    /// assert_eq!(frames.len(), 2);
    /// # Ok(()) }
    /// ```
    pub fn frames_in_flight(
        &self,
        queue_family_index: u32,
        count: usize,
    ) -> Result<FramesInFlight> {
        let count = count.max(1);
        let pool = self.create_command_pool(
            &CommandPoolCreateInfo::new()
                .flags(vk::CommandPoolCreateFlags::RESET_COMMAND_BUFFER)
                .queue_family_index(queue_family_index),
        )?;
        let buffers = self.allocate_command_buffers(
            &pool,
            &CommandBufferAllocateInfo::new(&pool)
                .level(vk::CommandBufferLevel::PRIMARY)
                .command_buffer_count(u32::try_from(count).unwrap_or(u32::MAX)),
        )?;
        let signalled = FenceCreateInfo::new().flags(vk::FenceCreateFlags::SIGNALED);
        let frames = buffers
            .into_iter()
            .map(|cb| {
                // `create_fence` is safe in the pinned configuration and may be
                // `unsafe` in wider ones.
                #[allow(unused_unsafe)]
                // SAFETY: a fence with the signalled flag and no chain: the rules a
                // wider configuration adds are about chained export infos.
                let fence = unsafe { self.create_fence(&signalled) }?;
                Ok((cb, fence))
            })
            .collect::<Result<Vec<_>>>()?;
        Ok(FramesInFlight {
            workers: frames.iter().map(|_| Vec::new()).collect(),
            frames,
            next: 0,
        })
    }

    /// [`Device::frames_in_flight`], with `workers` secondary command buffers per
    /// frame, each from a pool of its own, for worker threads to record at once
    /// ([`Frame::workers`]); the frame's primary executes them, and its fence tells
    /// when they may be recorded again. Without the `multi_thread` feature the
    /// secondaries cannot move to other threads (see the crate docs, "Threads").
    ///
    /// ```no_run
    /// # fn f(device: &tuff::Device, queue: &tuff::Queue) -> tuff::Result<()> {
    /// let mut frames = device.frames_in_flight_with_workers(0, 2, 4)?;
    /// let mut frame = frames.next_frame()?;
    /// for secondary in frame.workers() {
    ///     // ... on a worker thread: begin_continuing, record, end ...
    /// #   let _ = secondary;
    /// }
    /// let (primary, workers) = frame.parts();
    /// let mut rec = primary.begin(&tuff::CommandBufferBeginInfo::new())?;
    /// // ... begin a render pass with SECONDARY_COMMAND_BUFFERS contents ...
    /// # let _ = (&mut rec, workers);
    /// # Ok(()) }
    /// ```
    pub fn frames_in_flight_with_workers(
        &self,
        queue_family_index: u32,
        count: usize,
        workers: usize,
    ) -> Result<FramesInFlight> {
        let mut frames = self.frames_in_flight(queue_family_index, count)?;
        for list in &mut frames.workers {
            for _ in 0..workers {
                let pool = self.create_command_pool(
                    &CommandPoolCreateInfo::new()
                        .flags(vk::CommandPoolCreateFlags::RESET_COMMAND_BUFFER)
                        .queue_family_index(queue_family_index),
                )?;
                let secondary = self
                    .allocate_command_buffers(
                        &pool,
                        &CommandBufferAllocateInfo::new(&pool)
                            .level(vk::CommandBufferLevel::SECONDARY)
                            .command_buffer_count(1),
                    )?
                    .pop()
                    .ok_or(Error::Misuse(
                        "vkAllocateCommandBuffers returned no command buffer",
                    ))?;
                list.push(secondary);
            }
        }
        Ok(frames)
    }
}

impl FramesInFlight {
    /// How many frames the ring holds.
    pub fn len(&self) -> usize {
        self.frames.len()
    }

    /// Always false: a ring holds at least one frame.
    pub fn is_empty(&self) -> bool {
        self.frames.is_empty()
    }

    /// Waits until the last submission of the next frame's command buffer completed,
    /// and hands the frame out. The ring moves on only when the frame is submitted,
    /// so a frame dropped unsubmitted comes back next time.
    pub fn next_frame(&mut self) -> Result<Frame<'_>> {
        let index = self.next;
        let count = self.frames.len();
        let (commands, fence) = &mut self.frames[index];
        wait(commands.device(), &*fence)?;
        Ok(Frame {
            index,
            commands,
            workers: &mut self.workers[index],
            fence,
            next: &mut self.next,
            count,
        })
    }

    /// Waits until every frame's last submission completed, as before reading what
    /// the frames wrote or changing what they use.
    pub fn wait_all(&self) -> Result<()> {
        let fences: HandleSlice<Fence> = self.frames.iter().map(|(_, f)| f).collect();
        match self.frames.first() {
            Some((cb, _)) => wait(cb.device(), &fences),
            None => Ok(()),
        }
    }
}

/// Waits without timeout for all of `fences`.
fn wait<'a>(device: &Device, fences: impl Handles<'a, Fence>) -> Result<()> {
    match device.wait_for_fences(fences, true, u64::MAX)? {
        SuccessOrTimeout::Success => Ok(()),
        // No timeout was asked for; a driver that reports one anyway fails here.
        SuccessOrTimeout::Timeout => Err(Error::Vk(vk::Result::TIMEOUT)),
    }
}

/// The frame whose turn it is: its command buffer is free to record, and nothing
/// the frame's previous submission used is still in use by it.
///
/// # Example
///
/// [`FramesInFlight`]'s example is the loop: `next_frame` gives the frame, which is
/// recorded and submitted.
pub struct Frame<'r> {
    /// Which of the ring's frames this is, `0..len`: the index of the frame's own
    /// uniform buffers, descriptor sets or semaphores.
    pub index: usize,
    commands: &'r mut CommandBuffer,
    workers: &'r mut [CommandBuffer],
    fence: &'r Fence,
    next: &'r mut usize,
    count: usize,
}

impl core::fmt::Debug for Frame<'_> {
    /// Its index, command buffer and fence.
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.debug_struct("Frame")
            .field("index", &self.index)
            .field("command_buffer", &*self.commands)
            .field("fence", self.fence)
            .finish_non_exhaustive()
    }
}

impl Frame<'_> {
    /// Begins recording the frame's command buffer for one submission; what its
    /// previous recording kept alive is let go.
    pub fn record(&mut self) -> Result<Recorder<'_, Outside>> {
        self.commands.begin(
            &CommandBufferBeginInfo::new().flags(vk::CommandBufferUsageFlags::ONE_TIME_SUBMIT),
        )
    }

    /// The frame's command buffer, to record with other begin flags.
    pub fn commands(&mut self) -> &mut CommandBuffer {
        self.commands
    }

    /// The frame's worker secondaries ([`Device::frames_in_flight_with_workers`];
    /// none otherwise), free to record: the frame's last submission, which executed
    /// them, completed.
    pub fn workers(&mut self) -> &mut [CommandBuffer] {
        self.workers
    }

    /// The frame's command buffer and its worker secondaries together, so the
    /// primary's recording can execute them.
    pub fn parts(&mut self) -> (&mut CommandBuffer, &mut [CommandBuffer]) {
        (self.commands, self.workers)
    }

    crate::helpers::as_safe_as! { vkQueueSubmit,
        /// Submits the recorded command buffer to `queue`: it waits for each of `waits`
        /// at its stages and signals `signals`. The ring moves on to the next frame.
        ///
        /// Each submission needs a recording of its own: fails with
        /// `VUID-vkQueueSubmit-pCommandBuffers-00070` if the command buffer was not
        /// recorded and ended since its last submission (a one-time-submit command buffer
        /// is no longer executable once submitted).
        ///
        /// # Safety
        ///
        /// This method is `unsafe` exactly when [`Queue::submit`] is (it is safe
        /// with this crate's emitted API; a crate generated from more of the registry
        /// may leave it rules); the caller then upholds the rules its `# Safety` section
        /// lists for a submission of this frame's command buffer with `waits` and
        /// `signals`.
        pub fn submit(
            self,
            queue: &Queue,
            waits: &[(&Semaphore, vk::PipelineStageFlags)],
            signals: &[&Semaphore],
        ) -> Result<()> {
            if !self.commands.is_executable() {
                return Err(Error::Validation {
                    vuid: "VUID-vkQueueSubmit-pCommandBuffers-00070",
                    message: "the frame's command buffer was not recorded and ended before it \
                              was submitted"
                        .into(),
                });
            }
            // Once per frame: a few semaphores stay on the stack, as in `HandleSlice`.
            let wait_semaphores: SmallVec<[&Semaphore; 4]> = waits.iter().map(|(s, _)| *s).collect();
            let stages: SmallVec<[vk::PipelineStageFlags; 4]> =
                waits.iter().map(|(_, st)| *st).collect();
            let wait_semaphores = HandleSlice::new(&wait_semaphores);
            let signal_semaphores = HandleSlice::new(signals);
            let mut info = SubmitInfo::new().command_buffers(&*self.commands);
            if !waits.is_empty() {
                info = info.wait_semaphores(&wait_semaphores, &stages)?;
            }
            if !signals.is_empty() {
                info = info.signal_semaphores(&signal_semaphores);
            }
            let device = self.commands.device();
            // The fence was seen signalled by `next_frame`, so the reset cannot orphan a wait.
            device.reset_fences(self.fence)?;
            // `submit` is safe in the pinned configuration and may be `unsafe` in
            // wider ones.
            #[allow(unused_unsafe)]
            // SAFETY: where `submit` is `unsafe`, so is this method, and its caller
            // upholds the rules of this submission.
            let submitted = unsafe { queue.submit(&[info], Some(self.fence)) };
            if let Err(e) = submitted {
                // An empty batch signals the fence once the queue's earlier work is done,
                // so the next wait for this frame does not hang on a failed submission.
                #[allow(unused_unsafe)]
                // SAFETY: an empty batch has no command buffer or semaphore for a rule to
                // be about.
                let _ = unsafe { queue.submit(&[], Some(self.fence)) };
                return Err(e);
            }
            // The submission holds its semaphores; the frame needs a new recording.
            self.commands.set_executable(false);
            *self.next = (*self.next + 1) % self.count;
            Ok(())
        }
    }
}
