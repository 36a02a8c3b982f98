//! One-object forms of commands that take arrays, for the common case of one:
//! [`Device::create_compute_pipeline`], [`Device::create_graphics_pipeline`] and
//! [`Device::allocate_descriptor_set`]. Each calls the array form, so its checks run,
//! and hands back the one object instead of a `Vec` to pop.

use crate::structs::{
    ComputePipelineCreateInfo, DescriptorSetAllocateInfo, GraphicsPipelineCreateInfo,
};
use crate::{DescriptorPool, DescriptorSet, DescriptorSetLayout, Device, Error};
use crate::{Pipeline, PipelineCache, Result, SuccessOrPipelineCompileRequired};
use ash::vk;

/// The one pipeline of a creation of one: an error when the driver made none (a
/// `VK_PIPELINE_COMPILE_REQUIRED` answer to `FAIL_ON_PIPELINE_COMPILE_REQUIRED`).
fn one(created: (Vec<Pipeline>, SuccessOrPipelineCompileRequired)) -> Result<Pipeline> {
    let (mut pipelines, status) = created;
    match (pipelines.pop(), status) {
        (Some(p), SuccessOrPipelineCompileRequired::Success) => Ok(p),
        (_, SuccessOrPipelineCompileRequired::Success) => Err(Error::Vk(vk::Result::ERROR_UNKNOWN)),
        (_, other) => Err(Error::Vk(other.code())),
    }
}

impl Device {
    crate::helpers::as_safe_as! { vkCreateComputePipelines,
        /// Creates one compute pipeline: [`Device::create_compute_pipelines`] with one
        /// create info. A pipeline the driver did not make (it answered
        /// `VK_PIPELINE_COMPILE_REQUIRED` to `FAIL_ON_PIPELINE_COMPILE_REQUIRED`) is
        /// `Err(Error::Vk(..))` with that code.
        ///
        /// ```no_run
        /// # fn f(device: &tuff::Device, layout: &tuff::PipelineLayout, module: &tuff::ShaderModule) -> tuff::Result<()> {
        /// use tuff::vk;
        /// let stage = tuff::PipelineShaderStageCreateInfo::new(c"main")
        ///     .stage(vk::ShaderStageFlags::COMPUTE)
        ///     .module(Some(module));
        /// let pipeline = device
        ///     .create_compute_pipeline(None, &tuff::ComputePipelineCreateInfo::new(stage, layout))?;
        /// # let _ = pipeline; Ok(()) }
        /// ```
        ///
        /// # Safety
        ///
        /// This method is `unsafe` exactly when [`Device::create_compute_pipelines`] is
        /// (it is safe with this crate's emitted API); the caller then upholds the rules
        /// its `# Safety` section lists for this one create info.
        pub fn create_compute_pipeline(
            &self,
            pipeline_cache: Option<&PipelineCache>,
            create_info: &ComputePipelineCreateInfo<'_>,
        ) -> Result<Pipeline> {
            #[allow(unused_unsafe)]
            // SAFETY: where the array form is `unsafe`, so is this method, and its
            // caller upholds the rules of this create info.
            one(unsafe { self.create_compute_pipelines(pipeline_cache, core::slice::from_ref(create_info)) }?)
        }
    }

    crate::helpers::as_safe_as! { vkCreateGraphicsPipelines,
        /// Creates one graphics pipeline: [`Device::create_graphics_pipelines`] with one
        /// create info, as [`Device::create_compute_pipeline`] does for compute.
        ///
        /// ```no_run
        /// # fn f(device: &tuff::Device, info: &tuff::GraphicsPipelineCreateInfo<'_>) -> tuff::Result<()> {
        /// let pipeline = device.create_graphics_pipeline(None, info)?;
        /// # let _ = pipeline; Ok(()) }
        /// ```
        ///
        /// # Safety
        ///
        /// This method is `unsafe` exactly when [`Device::create_graphics_pipelines`]
        /// is (it is safe with this crate's emitted API); the caller then upholds the
        /// rules its `# Safety` section lists for this one create info.
        pub fn create_graphics_pipeline(
            &self,
            pipeline_cache: Option<&PipelineCache>,
            create_info: &GraphicsPipelineCreateInfo<'_>,
        ) -> Result<Pipeline> {
            #[allow(unused_unsafe)]
            // SAFETY: where the array form is `unsafe`, so is this method, and its
            // caller upholds the rules of this create info.
            one(unsafe { self.create_graphics_pipelines(pipeline_cache, core::slice::from_ref(create_info)) }?)
        }
    }

    crate::helpers::as_safe_as! { vkAllocateDescriptorSets,
        /// Allocates one descriptor set of `layout` from `pool`: the pool is named once,
        /// and the set comes back alone.
        ///
        /// ```no_run
        /// # fn f(device: &tuff::Device, pool: &tuff::DescriptorPool, layout: &tuff::DescriptorSetLayout) -> tuff::Result<()> {
        /// let set = device.allocate_descriptor_set(pool, layout)?;
        /// # let _ = set; Ok(()) }
        /// ```
        ///
        /// # Safety
        ///
        /// This method is `unsafe` exactly when [`Device::allocate_descriptor_sets`] is
        /// (it is safe with this crate's emitted API); the caller then upholds the rules
        /// its `# Safety` section lists for this allocation.
        pub fn allocate_descriptor_set(
            &self,
            pool: &DescriptorPool,
            layout: &DescriptorSetLayout,
        ) -> Result<DescriptorSet> {
            let info = DescriptorSetAllocateInfo::new(pool).set_layouts(layout);
            #[allow(unused_unsafe)]
            // SAFETY: where the array form is `unsafe`, so is this method, and its
            // caller upholds the rules of this allocation.
            let mut sets = unsafe { self.allocate_descriptor_sets(pool, &info) }?;
            sets.pop()
                .ok_or(Error::Vk(vk::Result::ERROR_UNKNOWN))
        }
    }
}
