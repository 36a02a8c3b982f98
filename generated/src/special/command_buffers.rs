//! Command pools and command buffers: their creation, allocation and resets (the
//! execution of secondaries from a primary is `secondaries.rs`).

use super::refuse;
use crate::handles::*;
use crate::recorder::{Continuing, Outside, PassInstance, Recorder};
use crate::state::PoolFamily;
use crate::structs::*;
use crate::submission::{self};
use crate::{Error, Handle, Result};
use ash::vk;
use tuff_runtime::Vrc;

/// Refuses a buffer that may still be executing, or whose pool does not reset buffers.
pub(crate) fn reset_command_buffer_checks(command_buffer: &CommandBuffer) -> Result<()> {
    command_buffer.uses().check_reset(
        command_buffer.device(),
        command_buffer.parent().resets_buffers(),
    )
}

/// Initial state; the last recording's objects go, as no submission uses the buffer
/// (checked).
pub(crate) fn reset_command_buffer_done(command_buffer: &CommandBuffer) {
    command_buffer.uses().reset();
    command_buffer.keep_alive(Vec::new());
}

/// Refuses a pool one of whose buffers may still be executing or is being recorded.
pub(crate) fn reset_command_pool_checks(device: &Device, command_pool: &CommandPool) -> Result<()> {
    submission::check_pool_reset(device, &command_pool.buffer_uses())
}

/// Every buffer of the pool is back in the initial state.
pub(crate) fn reset_command_pool_done(command_pool: &CommandPool) {
    for u in command_pool.buffer_uses() {
        u.reset();
    }
}

/// A command pool is made for a queue family the device has queues of, and is
/// protected only where the protectedMemory feature is enabled.
pub(crate) fn create_command_pool_checks(
    device: &Device,
    create_info: &CommandPoolCreateInfo<'_>,
) -> Result<()> {
    let family = create_info.queue_family_index;
    if !device.live().queue_infos().iter().any(|q| q.0 == family) {
        refuse(
            "VUID-vkCreateCommandPool-queueFamilyIndex-01937",
            format!("the device was created with no queue of family {family}"),
        )?;
    }
    let protected = create_info
        .flags
        .contains(vk::CommandPoolCreateFlags::PROTECTED);
    if protected && device.live().with_features(|f| f.v11.protected_memory) != vk::TRUE {
        refuse(
            "VUID-VkCommandPoolCreateInfo-flags-02860",
            "a protected command pool needs the protectedMemory feature, which the device \
             did not enable",
        )?;
    }
    Ok(())
}

/// The pool remembers its flags, and its family's queue flags for the `cmdpool` checks
/// (and the granularity and timestamp bits other checks read).
pub(crate) fn command_pool_created(
    device: &Device,
    pool: CommandPool,
    create_info: &CommandPoolCreateInfo<'_>,
) -> CommandPool {
    let physical = device.parent();
    // SAFETY: the physical device is a live wrapper of its instance.
    let families = unsafe {
        physical
            .parent()
            .fns()
            .get_physical_device_queue_family_properties(physical.raw())
    };
    // The family's flags, granularity and timestamp bits, from one query (an index
    // past the families has none).
    let (flags, granularity, timestamp_bits) = families
        .get(create_info.queue_family_index as usize)
        .map_or(Default::default(), |f| {
            (
                f.queue_flags,
                f.min_image_transfer_granularity,
                f.timestamp_valid_bits,
            )
        });
    device.live().pool_created(
        pool.raw(),
        PoolFamily {
            index: create_info.queue_family_index,
            flags,
            granularity,
            timestamp_bits,
            protected: create_info
                .flags
                .contains(vk::CommandPoolCreateFlags::PROTECTED),
        },
    );
    pool.with_create_flags(create_info.flags)
        .with_queue_flags(flags)
}

/// Each buffer remembers its level; the device and the pool track its lifecycle.
pub(crate) fn command_buffers_allocated(
    device: &Device,
    cbs: Vec<CommandBuffer>,
    command_pool: &CommandPool,
    allocate_info: &CommandBufferAllocateInfo<'_>,
) -> Vec<CommandBuffer> {
    let cbs: Vec<CommandBuffer> = cbs
        .into_iter()
        .map(|cb| cb.with_level(allocate_info.level))
        .collect();
    for cb in &cbs {
        device.register_command_buffer(cb);
        command_pool.adopt(cb.uses());
    }
    cbs
}

/// What a secondary is begun for: `info`'s flags and inheritance info, with the
/// record of the render pass it names and a chained
/// `VkCommandBufferInheritanceRenderingInfo`.
fn inheritance(device: &Device, info: &CommandBufferBeginInfo<'_>) -> crate::state::Inheritance {
    // SAFETY: the safe setter stores a reference that outlives `info`.
    let Some(i) = (unsafe { info.p_inheritance_info.as_ref() }) else {
        return crate::state::Inheritance {
            flags: info.flags,
            ..Default::default()
        };
    };
    // SAFETY: the safe inheritance info only chains structs pushed through
    // `push_next`; the node's sType names the struct, and its safe setter stores the
    // formats with their count.
    let rendering = unsafe { crate::support::chain_nodes(i.p_next) }
        .find(|n| n.s_type == vk::StructureType::COMMAND_BUFFER_INHERITANCE_RENDERING_INFO)
        .map(|n| unsafe {
            &*(n as *const vk::BaseInStructure<'_>)
                .cast::<vk::CommandBufferInheritanceRenderingInfo<'_>>()
        })
        .map(|r| {
            // SAFETY: as above.
            let formats = unsafe {
                crate::state::RenderingFormats::from_raw(
                    r.view_mask,
                    r.p_color_attachment_formats,
                    r.color_attachment_count,
                    r.depth_attachment_format,
                    r.stencil_attachment_format,
                )
            };
            crate::state::InheritedRendering {
                flags: r.flags,
                formats: Vrc::new(formats),
                samples: r.rasterization_samples,
            }
        });
    crate::state::Inheritance {
        flags: info.flags,
        render_pass: i.render_pass,
        record: device.live().render_pass(i.render_pass),
        subpass: i.subpass,
        framebuffer: i.framebuffer,
        occlusion_query_enable: i.occlusion_query_enable == vk::TRUE,
        query_flags: i.query_flags,
        pipeline_statistics: i.pipeline_statistics,
        rendering,
    }
}

impl CommandBuffer {
    /// `vkBeginCommandBuffer`: starts recording, outside any render pass instance.
    /// Recording again drops what the previous recording kept alive, so a buffer
    /// that a submission may still be executing is refused
    /// (`VUID-vkBeginCommandBuffer-commandBuffer-00049`): wait for the submission's
    /// fence first. Recording a buffer again needs a pool created with
    /// `RESET_COMMAND_BUFFER` (`-00050`). A buffer whose recorder was dropped
    /// without `end` is reset first.
    ///
    /// # Errors
    ///
    /// Besides those rules: a secondary buffer needs inheritance info (`-00051`), and
    /// a secondary that continues a render pass instance
    /// (`RENDER_PASS_CONTINUE`) is begun with [`Self::begin_continuing`], whose
    /// recorder is inside that instance.
    pub fn begin(&mut self, info: &CommandBufferBeginInfo<'_>) -> Result<Recorder<'_, Outside>> {
        if self.level() == vk::CommandBufferLevel::SECONDARY
            && info
                .flags
                .contains(vk::CommandBufferUsageFlags::RENDER_PASS_CONTINUE)
        {
            return Err(Error::Misuse(
                "a secondary command buffer begun with RENDER_PASS_CONTINUE records inside a render pass instance: use `begin_continuing`",
            ));
        }
        self.begin_in(info)
    }

    /// `vkBeginCommandBuffer` of a secondary command buffer that continues a render
    /// pass instance (`flags` holds `RENDER_PASS_CONTINUE`): its recorder records
    /// the commands of a render pass instance, and the primary that executes it
    /// must be inside a compatible one.
    ///
    /// # Errors
    ///
    /// The rules of [`Self::begin`]; a primary buffer, or `flags` without
    /// `RENDER_PASS_CONTINUE`, is refused; so is inheritance info with neither a
    /// render pass nor a `CommandBufferInheritanceRenderingInfo`
    /// (`VUID-VkCommandBufferBeginInfo-flags-06002`).
    pub fn begin_continuing(
        &mut self,
        info: &CommandBufferBeginInfo<'_>,
    ) -> Result<Recorder<'_, Continuing>> {
        if self.level() != vk::CommandBufferLevel::SECONDARY
            || !info
                .flags
                .contains(vk::CommandBufferUsageFlags::RENDER_PASS_CONTINUE)
        {
            return Err(Error::Misuse(
                "`begin_continuing` begins a secondary command buffer with RENDER_PASS_CONTINUE in its flags",
            ));
        }
        // SAFETY: the safe setter stores a reference that outlives `info`.
        let inheritance = unsafe { info.p_inheritance_info.as_ref() };
        if let Some(inheritance) = inheritance {
            // SAFETY: the safe inheritance info only chains structs pushed through
            // `push_next`.
            let rendering = unsafe { crate::support::chain_nodes(inheritance.p_next) }
                .any(|n| n.s_type == vk::StructureType::COMMAND_BUFFER_INHERITANCE_RENDERING_INFO);
            if inheritance.render_pass == vk::RenderPass::null() && !rendering {
                return Err(Error::Validation {
                    vuid: "VUID-VkCommandBufferBeginInfo-flags-06002",
                    message: "the inheritance info names no render pass and chains no CommandBufferInheritanceRenderingInfo".into(),
                });
            }
        }
        let mut rec = self.begin_in(info)?;
        // The inheritance `begin_in` read into the command buffer's record.
        let inherited = rec
            .command_buffer()
            .uses()
            .inheritance()
            .unwrap_or_default();
        let rendering = inherited
            .rendering
            .as_ref()
            .filter(|_| inherited.render_pass == vk::RenderPass::null());
        let subpass = inherited.subpass;
        let view_mask = match (&inherited.record, rendering) {
            (Some(r), _) => r.view_masks.get(subpass as usize).copied().unwrap_or(0),
            (None, Some(r)) => r.formats.view_mask,
            (None, None) => 0,
        };
        rec.instance = Some(PassInstance {
            subpass,
            view_mask,
            dynamic: inherited.render_pass == vk::RenderPass::null(),
            record: inherited.record.clone(),
            rendering: rendering.map(|r| r.formats.clone()),
            rendering_samples: rendering.map(|r| r.samples).filter(|s| !s.is_empty()),
            ..PassInstance::default()
        });
        // A framebuffer named in the inheritance is the one the executing primary's
        // instance has (00099, checked there), so its images are the attachments the
        // draws' descriptors must not alias; without one (or with an imageless one)
        // they stay unknown and such draws are refused.
        let live = rec.device().live();
        rec.pass_images = live
            .framebuffer_views(inherited.framebuffer)
            .iter()
            .map(|v| live.view(*v).map_or(vk::Image::null(), |r| r.image))
            .collect();
        Ok(rec.into_state())
    }

    fn begin_in(&mut self, info: &CommandBufferBeginInfo<'_>) -> Result<Recorder<'_, Outside>> {
        if self.level() == vk::CommandBufferLevel::SECONDARY && info.p_inheritance_info.is_null() {
            return Err(Error::Validation {
                vuid: "VUID-vkBeginCommandBuffer-commandBuffer-00051",
                message: "a secondary command buffer is begun without inheritance info".into(),
            });
        }
        let pool_sync = self.parent().host_sync().lock();
        let still_recording = self
            .uses()
            .check_begin(self.device(), self.parent().resets_buffers())?;
        crate::checks::check_command_buffer_begin_info(info, &self.device().scope())?;
        // After the implicit checks: the format checks hand formats to the driver.
        let inheritance = (self.level() == vk::CommandBufferLevel::SECONDARY)
            .then(|| Vrc::new(inheritance(self.device(), info)));
        if let Some(inherited) = &inheritance {
            super::secondaries::inheritance_checks(self.device(), inherited)?;
        }
        if still_recording {
            // SAFETY: the buffer is not pending (checked above) and its pool resets
            // buffers (a recorded buffer of another pool was refused above), so it
            // may be reset (VUID-vkResetCommandBuffer-commandBuffer-00045, -00046).
            let r = unsafe {
                (self.device().fns().fp_v1_0().reset_command_buffer)(
                    self.raw(),
                    vk::CommandBufferResetFlags::empty(),
                )
            };
            if r != vk::Result::SUCCESS {
                return Err(Error::Vk(r));
            }
            self.uses().reset();
        }
        // SAFETY: the command buffer is borrowed mutably, so no other recording or
        // submission of it is under way on the host; it is neither recording nor
        // pending (checked above); `info` is a valid struct.
        let r = unsafe {
            (self.device().fns().fp_v1_0().begin_command_buffer)(self.raw(), info.as_raw())
        };
        if r != vk::Result::SUCCESS {
            return Err(Error::Vk(r));
        }
        // The earlier recording can no longer run (it is not pending, checked above):
        // what it kept alive goes now, not when this one ends.
        let spare = self.keep_alive(Vec::new());
        self.uses().began(info.flags);
        self.uses().set_inheritance(inheritance);
        // The render pass and framebuffer a secondary's inheritance names live as
        // long as the recording, which refers to them.
        let mut reached = crate::validation::Reached::keeping(self.device().live());
        // SAFETY: a safe struct, whose setters store every pointer with its length
        // and borrow what it points to.
        unsafe { crate::reach::command_buffer_begin_info(info.as_raw(), &mut reached) };
        // In the last recording's list's allocation: a recording per frame keeps about
        // as many objects as the one before.
        let mut kept = spare;
        kept.extend(reached.kept);
        self.uses().set_recorder(true);
        let pool = self.device().live().pool_family(self.parent().raw());
        self.uses().set_pool(pool.map(|p| (p.index, p.protected)));
        // SAFETY: the safe info only chains structs pushed through `push_next`.
        let group = unsafe { crate::support::chain_nodes(info.p_next) }
            .find(|n| n.s_type == vk::StructureType::DEVICE_GROUP_COMMAND_BUFFER_BEGIN_INFO)
            .map(|n| {
                // SAFETY: the node's sType names this struct.
                unsafe {
                    (*(n as *const vk::BaseInStructure<'_>)
                        .cast::<vk::DeviceGroupCommandBufferBeginInfo<'_>>())
                    .device_mask
                }
            });
        let all = ((1u64 << self.device().live().physical_count().min(32)) - 1) as u32;
        Ok(Recorder::began(self, pool_sync, kept, group.unwrap_or(all)))
    }

    /// The device the command buffer's pool belongs to.
    #[inline]
    pub fn device(&self) -> &Device {
        self.parent().parent()
    }

    /// How many pipeline barriers automatic synchronization
    /// ([`Recorder::auto_sync`]) recorded into the last recording that ended: what
    /// it cost, and where a hand-written barrier could take over.
    ///
    /// ```no_run
    /// # fn f(cb: &mut tuff::CommandBuffer, a: &tuff::Buffer, b: &tuff::Buffer) -> tuff::Result<()> {
    /// let region = [tuff::vk::BufferCopy { src_offset: 0, dst_offset: 0, size: 64 }];
    /// let mut rec = cb.begin(&tuff::CommandBufferBeginInfo::new())?;
    /// rec.auto_sync(true);
    /// rec.copy_buffer(a, b, &region)?;
    /// rec.end()?;
    /// // One before the copy (what earlier submissions did), one before the host
    /// // reads `b`.
    /// assert_eq!(cb.auto_barriers(), 2);
    /// # Ok(()) }
    /// ```
    pub fn auto_barriers(&self) -> u32 {
        self.uses().auto_barriers()
    }
}
