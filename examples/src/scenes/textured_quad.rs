//! A textured quad: a checkerboard texture uploaded through a staging buffer (with
//! its layout transitions, in one call: `Queue::upload_image`), a view and a
//! sampler, a combined image-sampler descriptor, and a quad whose corners come from
//! the vertex index alone.

use crate::gpu::{Gpu, Requirements};
use crate::pipeline::{self, PipelineDesc};
use crate::render::{Scene, View};
use anyhow::Result;
use tuff::vk;

/// What the quad asks of the device: nothing beyond core Vulkan.
pub const REQUIREMENTS: Requirements = Requirements::core("textured_quad");

/// Texels per side of the checkerboard.
pub const TEXTURE_SIZE: u32 = 8;

/// The checkerboard's two colors, RGBA8: texel `(x, y)` is the first where `x + y`
/// is even.
pub const CHECKER: [[u8; 4]; 2] = [[240, 200, 40, 255], [30, 90, 200, 255]];

/// The texture's texels, rows top first, tightly packed RGBA8.
pub fn checkerboard() -> Vec<u8> {
    (0..TEXTURE_SIZE * TEXTURE_SIZE)
        .flat_map(|i| CHECKER[((i % TEXTURE_SIZE + i / TEXTURE_SIZE) % 2) as usize])
        .collect()
}

/// The quad's pipeline and its descriptor set (which keeps the view, the image and
/// the sampler it names).
pub struct TexturedQuad {
    pipeline: tuff::Pipeline,
    layout: tuff::PipelineLayout,
    set: tuff::DescriptorSet,
}

impl TexturedQuad {
    /// Uploads the texture and builds the pipeline for `render_pass`.
    pub fn new(gpu: &Gpu, render_pass: &tuff::RenderPass) -> Result<TexturedQuad> {
        let d = &gpu.device;
        let format = vk::Format::R8G8B8A8_UNORM;
        let extent = vk::Extent2D {
            width: TEXTURE_SIZE,
            height: TEXTURE_SIZE,
        };
        let usage = vk::ImageUsageFlags::SAMPLED | vk::ImageUsageFlags::TRANSFER_DST;
        let image = gpu.image(extent, format, usage)?;
        let read = vk::ImageLayout::SHADER_READ_ONLY_OPTIMAL;
        let color = vk::ImageAspectFlags::COLOR;
        gpu.queue
            .upload_image(&image, color, &checkerboard(), read, &gpu.allocator)?;
        let view = gpu.view(&image, format, color)?;
        // Nearest texels, so every pixel shows one of the checkerboard's two colors.
        let info = tuff::SamplerCreateInfo::new()
            .mag_filter(vk::Filter::NEAREST)
            .min_filter(vk::Filter::NEAREST)
            .address_mode_u(vk::SamplerAddressMode::CLAMP_TO_EDGE)
            .address_mode_v(vk::SamplerAddressMode::CLAMP_TO_EDGE)
            .address_mode_w(vk::SamplerAddressMode::CLAMP_TO_EDGE)
            .max_lod(0.0);
        let sampler = d.create_sampler(&info)?;
        let bindings = [tuff::DescriptorSetLayoutBinding::new()
            .binding(0)
            .descriptor_type(vk::DescriptorType::COMBINED_IMAGE_SAMPLER)
            .descriptor_count(1)
            .stage_flags(vk::ShaderStageFlags::FRAGMENT)];
        let set_layout = d.create_descriptor_set_layout(
            &tuff::DescriptorSetLayoutCreateInfo::new().bindings(&bindings),
        )?;
        let layout = pipeline::layout(gpu, &[&set_layout], vk::ShaderStageFlags::empty(), 0)?;
        let pool = d.create_descriptor_pool(
            &tuff::DescriptorPoolCreateInfo::new()
                .max_sets(1)
                .pool_sizes(&[vk::DescriptorPoolSize {
                    ty: vk::DescriptorType::COMBINED_IMAGE_SAMPLER,
                    descriptor_count: 1,
                }]),
        )?;
        let set_layouts = tuff::HandleSlice::new(&[&set_layout]);
        let set = d
            .allocate_descriptor_sets(
                &pool,
                &tuff::DescriptorSetAllocateInfo::new(&pool).set_layouts(&set_layouts),
            )?
            .remove(0);
        let texture = [tuff::DescriptorImageInfo::new()
            .sampler(Some(&sampler))
            .image_view(Some(&view))
            .image_layout(read)];
        d.update_descriptor_sets(
            &[tuff::WriteDescriptorSet::new(&set)
                .descriptor_type(vk::DescriptorType::COMBINED_IMAGE_SAMPLER)
                .image_info(&texture)],
            &[],
        )?;
        let vert = crate::shader(d, crate::spirv!("quad.vert"))?;
        let frag = crate::shader(d, crate::spirv!("quad.frag"))?;
        let pipeline = pipeline::graphics(
            gpu,
            &layout,
            render_pass,
            &PipelineDesc {
                stages: &[
                    (vk::ShaderStageFlags::VERTEX, &vert),
                    (vk::ShaderStageFlags::FRAGMENT, &frag),
                ],
                bindings: &[],
                attributes: &[],
                topology: vk::PrimitiveTopology::TRIANGLE_STRIP,
                patch_control_points: 0,
                polygon_mode: vk::PolygonMode::FILL,
                depth: false,
                subpass: 0,
                colors: 1,
            },
        )?;
        Ok(TexturedQuad {
            pipeline,
            layout,
            set,
        })
    }
}

impl Scene for TexturedQuad {
    const DEPTH: bool = false;

    fn clear_color(&self) -> [f32; 4] {
        [0.0, 0.0, 0.0, 1.0]
    }

    fn draw(
        &self,
        rec: &mut tuff::Recorder<'_, tuff::InRenderPass>,
        _view: &View,
    ) -> tuff::Result<()> {
        rec.bind_pipeline(vk::PipelineBindPoint::GRAPHICS, &self.pipeline)?;
        rec.bind_descriptor_sets(
            vk::PipelineBindPoint::GRAPHICS,
            &self.layout,
            0,
            &self.set,
            &[],
        )?;
        rec.draw(4, 1, 0, 0)
    }
}
