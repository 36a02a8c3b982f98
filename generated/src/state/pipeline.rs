//! What the device records of pipelines, pipeline layouts and shader modules.

use super::descriptors::SetLayoutRecord;
use super::live::Live;
use super::raw_slice;
use super::render_pass::RenderPassRecord;
use ash::vk::{self, Handle as _};
use tuff_runtime::Vrc;

/// The state that decides whether a draw writes its depth/stencil attachment: a
/// pipeline's static values, or the values a recording set.
#[derive(Clone, Copy, Debug)]
pub(crate) struct DepthStencil {
    /// Depth test enabled.
    pub depth_test: bool,
    /// Depth writes enabled.
    pub depth_write: bool,
    /// Stencil test enabled.
    pub stencil_test: bool,
    /// The fail, pass and depth-fail operations of the front and back faces.
    pub ops: [[vk::StencilOp; 3]; 2],
    /// The front and back write masks.
    pub masks: [u32; 2],
    /// Rasterizer discard enabled.
    pub discard: bool,
}

/// The dynamic states the recorder follows, one bit each: those of Vulkan 1.0
/// (0 to 8) and 1.3 (9 to 23); any other state has no bit (0).
pub(crate) const fn dynamic_bit(state: vk::DynamicState) -> u32 {
    let n = state.as_raw();
    let index = match n {
        0..=8 => n,
        1000267000..=1000267011 => 9 + n - 1000267000,
        1000377001 => 21,
        1000377002 => 22,
        1000377004 => 23,
        _ => return 0,
    };
    1 << index
}

/// A live pipeline layout's push-constant ranges and the dynamic descriptors of its
/// sets, which the recorder checks push constants and bound sets against.
#[derive(Clone, Debug)]
pub(crate) struct LayoutRecord {
    /// `VkPipelineLayoutCreateInfo::pPushConstantRanges`.
    pub push_ranges: Vec<vk::PushConstantRange>,
    /// For each set layout: its count of dynamic buffer descriptors.
    pub set_dynamics: Vec<u32>,
    /// The set layouts, by set number.
    pub sets: Vec<Vrc<SetLayoutRecord>>,
}

impl LayoutRecord {
    /// Whether two layouts are compatible for push constants: created with
    /// identical push-constant ranges.
    pub(crate) fn same_push_ranges(&self, other: &LayoutRecord) -> bool {
        let key = |r: &vk::PushConstantRange| (r.stage_flags, r.offset, r.size);
        self.push_ranges.len() == other.push_ranges.len()
            && self
                .push_ranges
                .iter()
                .zip(&other.push_ranges)
                .all(|(a, b)| key(a) == key(b))
    }
}

/// A live pipeline's bind point and layout, which the recorder checks draws and
/// dispatches against.
#[derive(Clone, Debug)]
pub(crate) struct PipelineRecord {
    /// Graphics or compute.
    pub bind_point: vk::PipelineBindPoint,
    /// Its create info's flags.
    pub flags: vk::PipelineCreateFlags,
    /// The layout it was created with.
    pub layout: Vrc<LayoutRecord>,
    /// The vertex-buffer bindings (the first 64) its vertex shader reads, one bit
    /// each.
    pub vertex_bindings: u64,
    /// For each vertex binding its vertex shader reads: the stride, rate and how far
    /// past a vertex's start the read attributes reach.
    pub vertex_reads: Vec<VertexRead>,
    /// Its rasterization sample count (empty for a compute pipeline).
    pub samples: vk::SampleCountFlags,
    /// The render pass it was created for, with the subpass (none for a compute
    /// pipeline, or one made for dynamic rendering).
    pub pass: Option<(Vrc<RenderPassRecord>, u32)>,
    /// Its dynamic states, as [`dynamic_bit`] bits.
    pub dynamic: u32,
    /// For a graphics pipeline made for dynamic rendering, the view mask and
    /// attachment formats its chained `VkPipelineRenderingCreateInfo` gives.
    pub rendering: Option<Vrc<RenderingFormats>>,
    /// The resource variables its stages' modules declare, by set and binding.
    pub resources: Vrc<[crate::spirv::Resource]>,
    /// The bytes `start..end` of the push-constant blocks its stages' modules
    /// declare, if any does.
    pub push: Option<(u32, u32)>,
    /// What its shaders read and write through their descriptors, for the hazard
    /// tracker.
    pub descriptor_uses: Vrc<[DescriptorUse]>,
    /// Its viewport state's viewport and scissor counts (0 without one).
    pub viewports: (u32, u32),
    /// Its depth/stencil and rasterizer discard state, where static.
    pub depth_stencil: DepthStencil,
    /// The color attachments (the first 32) its color blend state enables blending
    /// for, one bit each.
    pub blend: u32,
}

impl RenderingFormats {
    /// The formats a `VkPipelineRenderingCreateInfo` or a
    /// `VkCommandBufferInheritanceRenderingInfo` gives.
    ///
    /// # Safety
    ///
    /// `colors` points to `count` formats (a safe struct's array and its count).
    pub(crate) unsafe fn from_raw(
        view_mask: u32,
        colors: *const vk::Format,
        count: u32,
        depth: vk::Format,
        stencil: vk::Format,
    ) -> Self {
        RenderingFormats {
            view_mask,
            // SAFETY: the caller's promise.
            colors: unsafe { raw_slice(colors, count) }.to_vec(),
            depth,
            stencil,
        }
    }
}

/// One way a pipeline's shader stage reaches a descriptor binding: the elements it
/// spans, the stage and access type (`sync_tables` bits) of the access.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct DescriptorUse {
    /// The set number.
    pub set: u32,
    /// The binding.
    pub binding: u32,
    /// The elements `0..count` of the binding it spans (0: every element).
    pub count: u32,
    /// The stage of the shader that reaches it.
    pub stage: u64,
    /// The access type.
    pub access: u64,
    /// Whether the access type writes.
    pub write: bool,
}

/// A vertex binding a pipeline's vertex shader reads.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct VertexRead {
    /// The binding.
    pub binding: u32,
    /// Its stride (unless the pipeline has it dynamic).
    pub stride: u32,
    /// Whether it advances per instance rather than per vertex.
    pub instance: bool,
    /// How many bytes past a vertex's start its read attributes reach.
    pub end: u64,
}

/// The view mask and attachment formats of dynamic rendering: those a pipeline was
/// made for, or those of a render pass instance (`UNDEFINED` for an attachment with
/// no image view).
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub(crate) struct RenderingFormats {
    /// The view mask.
    pub view_mask: u32,
    /// Each color attachment's format.
    pub colors: Vec<vk::Format>,
    /// The depth attachment's format.
    pub depth: vk::Format,
    /// The stencil attachment's format.
    pub stencil: vk::Format,
}

impl Live {
    /// Records a new pipeline's bind point and layout.
    pub(crate) fn pipeline_created(&self, raw: vk::Pipeline, record: PipelineRecord) {
        let old = self.pipelines.lock().insert(raw.as_raw(), Vrc::new(record));
        drop(old);
    }

    /// The record of a live pipeline made through the wrappers: shared, so that a
    /// bind takes it without copying its lists.
    pub(crate) fn pipeline(&self, raw: vk::Pipeline) -> Option<Vrc<PipelineRecord>> {
        self.pipelines.lock().get(&raw.as_raw()).cloned()
    }

    /// Records a new pipeline layout's push-constant ranges and sets.
    pub(crate) fn pipeline_layout_created(&self, raw: vk::PipelineLayout, record: LayoutRecord) {
        self.pipeline_layouts
            .lock()
            .insert(raw.as_raw(), Vrc::new(record));
    }

    /// The record of a live pipeline layout made through the wrappers.
    pub(crate) fn pipeline_layout(&self, raw: vk::PipelineLayout) -> Option<Vrc<LayoutRecord>> {
        self.pipeline_layouts.lock().get(&raw.as_raw()).cloned()
    }

    /// Records a new shader module's interface.
    pub(crate) fn shader_module_created(
        &self,
        raw: vk::ShaderModule,
        interface: crate::spirv::Interface,
    ) {
        self.shader_modules
            .lock()
            .insert(raw.as_raw(), Vrc::new(interface));
    }

    /// The interface of a live shader module made through the wrappers.
    pub(crate) fn shader_module(
        &self,
        raw: vk::ShaderModule,
    ) -> Option<Vrc<crate::spirv::Interface>> {
        self.shader_modules.lock().get(&raw.as_raw()).cloned()
    }
}
