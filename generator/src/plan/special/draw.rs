//! The special-case rows of one concern; their functions are the `tuff` crate's
//! `special/draw.rs`, and a row here calls no other (but the image-layout tracker).
//!
//! Draws and dispatches: the recorded state each needs (pipeline, sets, vertex and index
//! buffers, dynamic state, push constants, attachments and blending), checked once per
//! change of the bound state.

use super::{call, How, Special, NONE};

const PASS_COMPATIBLE: &str = "checks the bound pipeline's render pass and subpass, recorded at its creation, against the render pass instance's and its current subpass (a pipeline made for dynamic rendering is refused inside one)";
const RENDERING_FORMATS: &str = "checks, in dynamic rendering (begun in the recording, or inherited by a continuing secondary), the view mask and attachment formats the bound pipeline was made for (its chained VkPipelineRenderingCreateInfo, recorded at its creation) against the instance's (its views' recorded formats)";
const NO_VIEW_FORMATS: &str = "checks, in dynamic rendering (begun in the recording, or inherited by a continuing secondary), that the bound pipeline was made for no format (UNDEFINED) where the instance's attachment has no view (the 1.3.239 layer does not check it: proven by the error alone)";
const VERTEX_WRAPPERS: &str =
    "vertex buffers are bound as wrappers, which always hold valid handles, never VK_NULL_HANDLE";
const VERTEX_RANGE: &str = "checks the vertices and instances a direct draw fetches, by the bound pipeline's vertex bindings (stride, rate, and the end of the attributes its vertex shader reads, recorded at its creation), lie inside the range of each bound vertex buffer (its recorded size past the bound offset, or the bound size); the 1.3.239 layer does not check it: proven by the error alone";
const DYNAMIC_SET: &str = "checks the dynamic states of the bound pipeline, recorded at its creation, against those the recorder saw set since a pipeline that has them static was bound, and that no state the pipeline has static was set since it was bound";
const PIPELINE_BOUND: &str =
    "checks a pipeline is bound at the command's bind point, which the recorder tracks";
const SETS_BOUND: &str = "checks a set of the right set layout is bound at every set number of the bound pipeline's layout (every set, as which ones the shaders use is not known)";
const VERTEX_BOUND: &str = "checks a vertex buffer is bound at every binding that an attribute the vertex shader reads comes from (the pipeline records them from its vertex input state and the shader's input locations; the recorder tracks the bindings bound)";
const INDEX_BOUND: &str = "checks an index buffer is bound, which the recorder tracks";
const INDEX_RANGE: &str = "checks the indices the draw reads lie inside the bound index buffer (whatever robustBufferAccess2 says, which is not tracked)";
const IMAGE_VIEW_TYPE: &str = "checks, once per change of the bound state, each image view the bound sets hold at a binding that an image variable of the pipeline's modules declares, against the view type the variable's Dim and Arrayed name (read from the module's SPIR-V when it was made; every variable a module declares counts, as which ones the entry point uses is not read)";
const DESCRIPTORS_WRITTEN: &str = "checks, once per change of the bound state, that every descriptor of each binding a resource variable of the pipeline's modules reads (every element of an array, every byte of an inline uniform block) was written in the set bound, as the device recorded its writes, copies and template updates when the set was bound (an update after that leaves the recording invalid; one that empties a slot does so even under UPDATE_AFTER_BIND); a binding with PARTIALLY_BOUND leaves its descriptors to the shader promise, and every variable a module declares counts";
const PUSH_CONSTANTS_SET: &str = "checks, once per change of the bound state (a push with a layout of other push-constant ranges is one), that every byte of the push-constant blocks the pipeline's modules declare was pushed in the recording with a layout of the same push-constant ranges as the pipeline's (the recorder keeps the bytes pushed), unless the device enabled maintenance4 (the 1.3.239 layer does not check it: the error alone proves it)";
const WITH_COUNT: &str = "checks, once per change of the bound state, the viewport and scissor counts the recording last set with vkCmdSetViewportWithCount and vkCmdSetScissorWithCount against each other, or against the count the bound pipeline has static, as the device recorded it from its viewport state";
const MULTIVIEW_INSTANCES: &str = "checks, in a render pass instance with a view mask, the draw's last instance index against maxMultiviewInstanceIndex, read once from the physical device (the 1.3.239 layer does not check it: the error alone proves it)";
const READ_ONLY_WRITES: &str = "checks, once per change of the bound state, whether the draw writes depth (depth test and writes enabled) or stencil (stencil test enabled, a face with a write mask and an operation other than KEEP), from the bound pipeline's depth/stencil and rasterization state or the values the recording set where it has them dynamic, against the layouts of the instance's depth/stencil attachment (the subpass's reference, with its stencil layout, or the vkCmdBeginRendering attachment infos); in a secondary that continues dynamic rendering, whose layouts the inheritance info does not give, a draw that writes either is refused";
const READ_ONLY_RENDERING: &str = "checks, as for the rule of any render pass instance (None-06886 and -06887), a draw that writes depth or stencil against the layout the vkCmdBeginRendering attachment info names (the 1.3.239 layer does not check it: the error alone proves it)";
const RASTERIZATION_SAMPLES: &str = "checks, once per change of the bound state and unless rasterization is discarded, the bound pipeline's rasterization samples against the sample count of the current subpass's color and depth/stencil attachments (kept from the render pass's creation), or in dynamic rendering of the attachment views' images (in a continuing secondary, the inheritance info's rasterization samples); in dynamic rendering the 1.3.239 layer names the case by the sibling rule colorAttachmentCount-06188, of pipelines made with an attachment sample count info";
const IMAGE_ATOMICS: &str = "checks, once per change of the bound state, each image view the bound sets hold at a binding whose variable the pipeline's modules use with OpImageTexelPointer (followed from the variable through loads, access chains, copies, selections, phis and function arguments; an atomic on a value of no variable found counts for every image variable) against its format's features for its image's tiling";
const UNPROVEN_DEPTH_COMPARISON: &str = "checked by the safe methods in every build (each image view at a binding whose variable the pipeline's modules sample with depth comparison, OpImage*Dref*, against its format's VkFormatProperties3 features for its image's tiling; before Vulkan 1.3, a depth format that can be sampled), but no test breaks it yet: no test shader samples with depth comparison";
const UNPROVEN_WITHOUT_FORMAT: &str = "checked by the safe methods in every build (each image view at a binding whose storage image variable has the Unknown format and that the pipeline's modules write, against its format's VkFormatProperties3 features), but no test breaks it: lavapipe writes every storage format without a format";
const READ_WITHOUT_FORMAT: &str = "checks, once per change of the bound state, each image view the bound sets hold at a binding whose storage image variable has the Unknown format and that the pipeline's modules read (OpImageRead, followed as for atomics), against its format's VkFormatProperties3 features for its image's tiling (before Vulkan 1.3: storage, and the device's shaderStorageImageReadWithoutFormat)";
const UNPROVEN_PROTECTED_ACCESS: &str = "checked by the safe methods in every build (on a device that enabled protectedMemory without protectedNoFault, a draw or dispatch in an unprotected command buffer is refused while a protected buffer or image is alive, as which resources its pipeline reaches is not followed; without protectedMemory no protected object can be made, their creation checking the feature), but no test breaks it: lavapipe has no protectedMemory";
const UNPROVEN_PROTECTED_BUFFER: &str = "checked by the safe methods in every build (a draw or dispatch in a protected command buffer is refused: which resources its pipeline writes, and from which stages, is not followed), but no test breaks it: lavapipe has no protectedMemory, so no command buffer is protected";
const IMAGE_VIEW_NUMERIC: &str = "checks, once per change of the bound state, each image view the bound sets hold at a binding that an image variable of the pipeline's modules declares, its format's numeric type (vk.xml's numericFormat, or the depth or stencil aspect it views) against the variable's sampled type, float against integer (every variable a module declares counts)";
const INDEXED_FETCH: &str = "checks, once per indexed draw and unless the device enabled robustBufferAccess (which keeps every vertex fetch inside the bound range), that the vertices every index of the bound index type can name (its largest value, plus the vertex offset; a negative offset is refused) and the instances drawn lie inside the range of each bound vertex buffer the pipeline's vertex shader reads, as for a direct draw; the index buffer's contents are the device's, so no smaller bound is known (the 1.3.239 layer does not check it: proven by the error alone)";
const COMPUTE_STATIC: &str = "checks, once per change of the bound state, that no dynamic state setting command was recorded since the bound compute pipeline was bound (a compute pipeline has every state static; the recorder keeps a bit per state set since, cleared by each compute bind); the 1.3.239 layer does not check it for dispatches: the error alone proves it";
const DISPATCH_BASE: &str = "checks, when a base group is not zero, that the compute pipeline bound (whose create flags the device records) was created with VK_PIPELINE_CREATE_DISPATCH_BASE_BIT";
const COMPUTE_NO_DYNAMIC: &str = "a compute pipeline has no dynamic state (VkComputePipelineCreateInfo has no pDynamicState), so a dispatch's pipeline requires none to be set";
const SAMPLER_LINEAR: &str = "checks, once per change of the bound state, each image view the bound sets hold at a binding whose variable the pipeline's modules sample, against the samplers that may sample it (a combined image sampler's own and its binding's immutable ones; for a separate image, every sampler the modules declare, as which sampler an OpSampledImage pairs with which image is not followed): with a LINEAR filter or mipmap mode (and no depth comparison), the view's format features (VkFormatProperties3, for its image's tiling) must have SAMPLED_IMAGE_FILTER_LINEAR; samplers record their filters when they are made";
const SAMPLER_UNNORMALIZED: &str = "checks, once per change of the bound state, each image view the bound sets hold at a binding whose variable the pipeline's modules sample, against the samplers that may sample it (as for the linear filter rule): with unnormalized coordinates, a view of type 1D or 2D only, and no OpImageSample instruction with ImplicitLod, Dref or Proj, LOD bias or offset on the variable (read from the module's SPIR-V when it was made, followed from the variable as for atomics)";
const UNPROVEN_DISPATCH_SAMPLERS: &str = "checked by the safe methods in every build (the samplers that may sample each image view the bound sets hold, as for a draw's rules of the same text, which the draw tests break), but no dispatch test breaks it yet";
const UNPROVEN_UNNORMALIZED_VIEW: &str = "checked by the safe methods in every build (each image view a sampler with unnormalized coordinates may sample, as for None-02703, against the 1D and 2D view types), but no test breaks it yet: the tests' sampled views are 2D";
const UNPROVEN_TEXEL_COMPONENTS: &str = "checked by the safe methods in every build (each image or texel buffer view at a binding whose variable the pipeline's modules write with OpImageWrite, against the fewest components of the texels written, read from the module's SPIR-V), but no test breaks it: GLSL's imageStore always writes four components, and the test shaders are GLSL";
const UNPROVEN_TEXEL_WITHOUT_FORMAT: &str = "checked by the safe methods in every build (each texel buffer view at a binding whose storage texel buffer variable has the Unknown format and that the pipeline's modules write or read, against its format's VkFormatProperties3 buffer features), but no test breaks it: lavapipe reads and writes every storage texel buffer format without a format";
const UNPROVEN_YCBCR: &str = "checked by the safe methods in every build (an image view made with a sampler Y'CbCr conversion, or sampled by a sampler made with one, against the instructions the pipeline's modules use on its variable: sampling only, without ConstOffset or Offset), but no test breaks it: lavapipe has no samplerYcbcrConversion";
const UNPROVEN_INPUT_WRITTEN: &str = "checked by the safe methods in every build (the check of None-02699: every descriptor of a binding an input attachment variable of the pipeline's modules declares was written when the set was bound), but no test breaks it apart from that rule";
const UNPROVEN_INPUT_ATTACHMENTS: &str = "checked by the safe methods in every build (once per change of the bound state, each input attachment variable's InputAttachmentIndex, read from the module's SPIR-V, against the current subpass's input attachment references, kept from the render pass's creation; in dynamic rendering no input attachment is valid), but no test breaks it yet";
const INPUT_VIEW: &str = "checks, once per change of the bound state, the view each input attachment descriptor holds against the current subpass's attachment at its InputAttachmentIndex (read from the module's SPIR-V): the attachment's format, kept from the render pass's creation, and the image of the framebuffer's view (in a continuing secondary, of the framebuffer its inheritance names, where it names one); the 1.3.239 layer does not check it: proven by the error alone";
const ATTACHMENT_MEMORY: &str = "checked by the safe methods in every build (once per change of the bound state, the memory each descriptor the pipeline's modules declare reaches (an image view's image, a texel buffer view's or buffer descriptor's buffer, where each is bound) against the memory of the current subpass's attachments (the framebuffer's views' images, or the dynamic rendering's views' and resolve views'): a descriptor the shader may write (a storage buffer, or a storage image or texel buffer it writes or uses atomically) names the first rule, any other the second, as which commands of the subpass write each attachment is not followed; in a secondary continuing an instance whose attachments are not known, a draw whose shaders declare such a descriptor is refused), but no test proves it against the layer: an attachment in a render pass instance is in an attachment layout, so a descriptor that reaches it breaks VkDescriptorImageInfo-imageLayout-00344 too, which the 1.3.239 layer names instead";
const UNPROVEN_ATTACHMENT_READ_BEFORE: &str = "checked by the safe methods in every build: no safe draw reads or writes an attachment's memory other than as an attachment (None-06537 and None-06538 refuse it), so no command of the subpass reads it before a draw writes it as an attachment; no test breaks it apart from those rules";
const UNPROVEN_BLEND: &str = "checked by the safe methods in every build (once per change of the bound state, unless rasterization is discarded, the color attachments the bound pipeline blends into, recorded at its creation, against the features of the instance's color formats, optimal tiling and linear where an attachment image is linear or the attachments are not known), but no test breaks it: the pipeline's creation refuses the same blending for its render pass or rendering formats first";

/// The `DrawRules` of a draw command, as the Rust expression its functions take: a
/// reference to a constant, so a draw passes a pointer rather than building the
/// struct.
macro_rules! draw_rules {
    ($command:literal, $protected:literal) => {
        concat!(
            "{ const RULES: crate::special::draw::DrawRules = crate::special::draw::DrawRules { render_pass: \"VUID-",
            $command,
            "-renderPass-02684\", ",
            "subpass: \"VUID-",
            $command,
            "-subpass-02685\", ",
            "dynamic_set: \"VUID-",
            $command,
            "-commandBuffer-02701\", ",
            "static_unset: \"VUID-",
            $command,
            "-None-02859\", ",
            "named: [(crate::special::draw::NAMED_STATES[0], \"VUID-",
            $command,
            "-primitiveTopology-03420\"), ",
            "(crate::special::draw::NAMED_STATES[1], \"VUID-",
            $command,
            "-pStrides-04884\"), ",
            "(crate::special::draw::NAMED_STATES[2], \"VUID-",
            $command,
            "-None-04876\"), ",
            "(crate::special::draw::NAMED_STATES[3], \"VUID-",
            $command,
            "-None-04877\"), ",
            "(crate::special::draw::NAMED_STATES[4], \"VUID-",
            $command,
            "-None-04879\")], ",
            "rendering: crate::special::draw::RenderingRules { ",
            "view_mask: \"VUID-",
            $command,
            "-viewMask-06178\", ",
            "color_count: \"VUID-",
            $command,
            "-colorAttachmentCount-06179\", ",
            "color_format: \"VUID-",
            $command,
            "-colorAttachmentCount-06180\", ",
            "color_no_view: \"VUID-",
            $command,
            "-colorAttachmentCount-07616\", ",
            "depth_format: \"VUID-",
            $command,
            "-pDepthAttachment-06181\", ",
            "depth_no_view: \"VUID-",
            $command,
            "-pDepthAttachment-07617\", ",
            "stencil_format: \"VUID-",
            $command,
            "-pStencilAttachment-06182\", ",
            "stencil_no_view: \"VUID-",
            $command,
            "-pStencilAttachment-07618\", ",
            "}, ",
            "read_only: crate::special::draw::ReadOnlyRules { ",
            "depth: \"VUID-",
            $command,
            "-None-06886\", ",
            "stencil: \"VUID-",
            $command,
            "-None-06887\", ",
            "depth_in_both_read_only: \"VUID-",
            $command,
            "-imageView-06172\", ",
            "stencil_in_both_read_only: \"VUID-",
            $command,
            "-imageView-06173\", ",
            "depth_in_depth_read_only_stencil_attachment: \"VUID-",
            $command,
            "-imageView-06174\", ",
            "stencil_in_depth_attachment_stencil_read_only: \"VUID-",
            $command,
            "-imageView-06175\", ",
            "depth_in_depth_read_only: \"VUID-",
            $command,
            "-imageView-06176\", ",
            "stencil_in_stencil_read_only: \"VUID-",
            $command,
            "-imageView-06177\", ",
            "rasterization_samples: \"VUID-",
            $command,
            "-rasterizationSamples-04740\", ",
            "}, ",
            "counts: crate::special::draw::CountRules { ",
            "viewports: \"VUID-",
            $command,
            "-viewportCount-03417\", ",
            "scissors: \"VUID-",
            $command,
            "-scissorCount-03418\", ",
            "both: \"VUID-",
            $command,
            "-viewportCount-03419\", ",
            "}, ",
            "attachments: crate::special::draw::AttachmentRules { ",
            "input_index: \"VUID-",
            $command,
            "-OpTypeImage-07468\", ",
            "input_view: \"VUID-",
            $command,
            "-None-07469\", ",
            "memory_written: \"VUID-",
            $command,
            "-None-06537\", ",
            "memory_read: \"VUID-",
            $command,
            "-None-06538\", ",
            "blend: \"VUID-",
            $command,
            "-blendEnable-04727\", ",
            "}, shader: ",
            shader_rules!($command, $protected),
            " }; &RULES }"
        )
    };
}

/// The `ShaderRules` of a draw or dispatch command, as a Rust struct expression.
macro_rules! shader_rules {
    ($command:literal, $protected:literal) => {
        concat!(
            "crate::special::draw::ShaderRules { ",
            "view_type: \"VUID-",
            $command,
            "-viewType-07752\", ",
            "view_numeric: \"VUID-",
            $command,
            "-format-07753\", ",
            "written: \"VUID-",
            $command,
            "-None-02699\", ",
            "push_constants: \"VUID-",
            $command,
            "-maintenance4-06425\", ",
            "atomics: \"VUID-",
            $command,
            "-None-02691\", ",
            "depth_comparison: \"VUID-",
            $command,
            "-None-06479\", ",
            "write_without_format: \"VUID-",
            $command,
            "-OpTypeImage-07027\", ",
            "read_without_format: \"VUID-",
            $command,
            "-OpTypeImage-07028\", ",
            "protected_access: \"VUID-",
            $command,
            "-commandBuffer-02707\", ",
            "protected_command_buffer: \"",
            $protected,
            "\", ",
            "linear_filter: \"VUID-",
            $command,
            "-magFilter-04553\", ",
            "linear_mipmap: \"VUID-",
            $command,
            "-mipmapMode-04770\", ",
            "unnormalized_view_type: \"VUID-",
            $command,
            "-None-02702\", ",
            "unnormalized_instructions: \"VUID-",
            $command,
            "-None-02703\", ",
            "unnormalized_bias_offset: \"VUID-",
            $command,
            "-None-02704\", ",
            "image_write_components: \"VUID-",
            $command,
            "-None-04115\", ",
            "texel_write_components: \"VUID-",
            $command,
            "-OpImageWrite-04469\", ",
            "texel_write_without_format: \"VUID-",
            $command,
            "-OpTypeImage-07029\", ",
            "texel_read_without_format: \"VUID-",
            $command,
            "-OpTypeImage-07030\", ",
            "ycbcr_sampling: \"VUID-",
            $command,
            "-None-06550\", ",
            "ycbcr_offset: \"VUID-",
            $command,
            "-ConstOffset-06551\", ",
            "}"
        )
    };
}

/// A draw or dispatch: a pipeline bound at its bind point, and a set bound at every
/// set number of its layout; for a draw, a vertex buffer bound at every binding its
/// vertex shader reads.
macro_rules! bound {
    ($command:literal, COMPUTE, $sets:expr, $protected:literal, [$($extra:expr),* $(,)?]) => {
        bound!($command, COMPUTE, $sets, $protected, None, [$($extra),*])
    };
    ($command:literal, COMPUTE, $sets:expr, $protected:literal, $last:expr, [$($extra:expr),* $(,)?]) => {
        Special {
            command: $command,
            check_last: $last,
            after: call(
                "special::draw::descriptor_layouts_used",
                &["self", "vk::PipelineBindPoint::COMPUTE"],
            ),
            check: call(
                "special::draw::dispatch_checks",
                &[
                    "self",
                    concat!("\"VUID-", $command, "-None-02700\""),
                    concat!("\"VUID-", $command, "-None-02697\""),
                    concat!("\"VUID-", $command, "-None-02859\""),
                    concat!("&", shader_rules!($command, $protected)),
                ],
            ),
            settles: &[
                (
                    concat!("VUID-", $command, "-None-02700"),
                    How::Dynamic(PIPELINE_BOUND),
                ),
                (concat!("VUID-", $command, "-None-02697"), $sets),
                (concat!("VUID-", $command, "-None-02859"), How::Dynamic(COMPUTE_STATIC)),
                (concat!("VUID-", $command, "-commandBuffer-02701"), How::Static(COMPUTE_NO_DYNAMIC)),
                (concat!("VUID-", $command, "-viewType-07752"), How::Dynamic(IMAGE_VIEW_TYPE)),
                (concat!("VUID-", $command, "-format-07753"), How::Dynamic(IMAGE_VIEW_NUMERIC)),
                (concat!("VUID-", $command, "-None-02699"), How::Dynamic(DESCRIPTORS_WRITTEN)),
                (concat!("VUID-", $command, "-maintenance4-06425"), How::Dynamic(PUSH_CONSTANTS_SET)),
                (concat!("VUID-", $command, "-None-02691"), How::Dynamic(IMAGE_ATOMICS)),
                (concat!("VUID-", $command, "-None-06479"), How::User(UNPROVEN_DEPTH_COMPARISON)),
                (concat!("VUID-", $command, "-OpTypeImage-07027"), How::User(UNPROVEN_WITHOUT_FORMAT)),
                (concat!("VUID-", $command, "-OpTypeImage-07028"), How::Dynamic(READ_WITHOUT_FORMAT)),
                (concat!("VUID-", $command, "-commandBuffer-02707"), How::User(UNPROVEN_PROTECTED_ACCESS)),
                (concat!("VUID-", $command, "-magFilter-04553"), How::User(UNPROVEN_DISPATCH_SAMPLERS)),
                (concat!("VUID-", $command, "-mipmapMode-04770"), How::User(UNPROVEN_DISPATCH_SAMPLERS)),
                (concat!("VUID-", $command, "-None-02702"), How::User(UNPROVEN_UNNORMALIZED_VIEW)),
                (concat!("VUID-", $command, "-None-02703"), How::User(UNPROVEN_DISPATCH_SAMPLERS)),
                (concat!("VUID-", $command, "-None-02704"), How::User(UNPROVEN_DISPATCH_SAMPLERS)),
                (concat!("VUID-", $command, "-None-04115"), How::User(UNPROVEN_TEXEL_COMPONENTS)),
                (concat!("VUID-", $command, "-OpImageWrite-04469"), How::User(UNPROVEN_TEXEL_COMPONENTS)),
                (concat!("VUID-", $command, "-OpTypeImage-07029"), How::User(UNPROVEN_TEXEL_WITHOUT_FORMAT)),
                (concat!("VUID-", $command, "-OpTypeImage-07030"), How::User(UNPROVEN_TEXEL_WITHOUT_FORMAT)),
                (concat!("VUID-", $command, "-None-06550"), How::User(UNPROVEN_YCBCR)),
                (concat!("VUID-", $command, "-ConstOffset-06551"), How::User(UNPROVEN_YCBCR)),
                $($extra,)*
            ],
            ..NONE
        }
    };
    ($command:literal, GRAPHICS, $sets:expr, $protected:literal, $vertices:literal, [$($extra:expr),* $(,)?]) => {
        Special {
            command: $command,
            after: call(
                "special::draw::descriptor_layouts_used",
                &["self", "vk::PipelineBindPoint::GRAPHICS"],
            ),
            check: call(
                "special::draw::draw_checks",
                &[
                    "self",
                    concat!("\"VUID-", $command, "-None-02700\""),
                    concat!("\"VUID-", $command, "-None-02697\""),
                    concat!("\"VUID-", $command, "-None-04007\""),
                    $vertices,
                    draw_rules!($command, $protected),
                ],
            ),
            settles: with_draw_state!(
                $command,
                [
                    $($extra,)*
                    (
                        concat!("VUID-", $command, "-None-02700"),
                        How::Dynamic(PIPELINE_BOUND),
                    ),
                    (concat!("VUID-", $command, "-None-02697"), $sets),
                    (
                        concat!("VUID-", $command, "-None-04007"),
                        How::Dynamic(VERTEX_BOUND),
                    ),
                ]
            ),
            ..NONE
        }
    };
}

/// An indexed draw: [`bound!`]'s checks, an index buffer bound, and for a direct draw
/// the indices it reads inside it (`range`, Rust for an `Option` the function takes).
macro_rules! indexed {
    ($command:literal, $protected:literal, $range:literal, [$($settles:expr),* $(,)?]) => {
        Special {
            command: $command,
            after: call(
                "special::draw::descriptor_layouts_used",
                &["self", "vk::PipelineBindPoint::GRAPHICS"],
            ),
            check: call(
                "special::draw::indexed_draw_checks",
                &[
                    "self",
                    concat!("\"VUID-", $command, "-None-02700\""),
                    concat!("\"VUID-", $command, "-None-02697\""),
                    concat!("\"VUID-", $command, "-None-07312\""),
                    concat!("\"VUID-", $command, "-None-04007\""),
                    $range,
                    draw_rules!($command, $protected),
                ],
            ),
            settles: with_draw_state!($command, [$($settles),*]),
            ..NONE
        }
    };
}

/// A draw's settlements: `$settles`, and those of the state it draws with (its
/// pipeline's render pass and subpass, and its dynamic states).
macro_rules! with_draw_state {
    ($command:literal, [$($settles:expr),* $(,)?]) => {
        &[
            $($settles,)*
            (concat!("VUID-", $command, "-renderPass-02684"), How::Dynamic(PASS_COMPATIBLE)),
            (concat!("VUID-", $command, "-subpass-02685"), How::Dynamic(PASS_COMPATIBLE)),
            (concat!("VUID-", $command, "-commandBuffer-02701"), How::Dynamic(DYNAMIC_SET)),
            (concat!("VUID-", $command, "-None-02859"), How::Dynamic(DYNAMIC_SET)),
            (concat!("VUID-", $command, "-primitiveTopology-03420"), How::Dynamic(DYNAMIC_SET)),
            (concat!("VUID-", $command, "-pStrides-04884"), How::Dynamic(DYNAMIC_SET)),
            (concat!("VUID-", $command, "-None-04876"), How::Dynamic(DYNAMIC_SET)),
            (concat!("VUID-", $command, "-None-04877"), How::Dynamic(DYNAMIC_SET)),
            (concat!("VUID-", $command, "-None-04879"), How::Dynamic(DYNAMIC_SET)),
            (concat!("VUID-", $command, "-None-04008"), How::Static(VERTEX_WRAPPERS)),
            (concat!("VUID-", $command, "-viewMask-06178"), How::Dynamic(RENDERING_FORMATS)),
            (concat!("VUID-", $command, "-colorAttachmentCount-06179"), How::Dynamic(RENDERING_FORMATS)),
            (concat!("VUID-", $command, "-colorAttachmentCount-06180"), How::Dynamic(RENDERING_FORMATS)),
            (concat!("VUID-", $command, "-colorAttachmentCount-07616"), How::Dynamic(NO_VIEW_FORMATS)),
            (concat!("VUID-", $command, "-pDepthAttachment-06181"), How::Dynamic(RENDERING_FORMATS)),
            (concat!("VUID-", $command, "-pDepthAttachment-07617"), How::Dynamic(NO_VIEW_FORMATS)),
            (concat!("VUID-", $command, "-pStencilAttachment-06182"), How::Dynamic(RENDERING_FORMATS)),
            (concat!("VUID-", $command, "-pStencilAttachment-07618"), How::Dynamic(NO_VIEW_FORMATS)),
            (concat!("VUID-", $command, "-viewType-07752"), How::Dynamic(IMAGE_VIEW_TYPE)),
            (concat!("VUID-", $command, "-format-07753"), How::Dynamic(IMAGE_VIEW_NUMERIC)),
            (concat!("VUID-", $command, "-None-02699"), How::Dynamic(DESCRIPTORS_WRITTEN)),
            (concat!("VUID-", $command, "-maintenance4-06425"), How::Dynamic(PUSH_CONSTANTS_SET)),
            (concat!("VUID-", $command, "-None-02691"), How::Dynamic(IMAGE_ATOMICS)),
            (concat!("VUID-", $command, "-None-06479"), How::User(UNPROVEN_DEPTH_COMPARISON)),
            (concat!("VUID-", $command, "-OpTypeImage-07027"), How::User(UNPROVEN_WITHOUT_FORMAT)),
            (concat!("VUID-", $command, "-OpTypeImage-07028"), How::Dynamic(READ_WITHOUT_FORMAT)),
            (concat!("VUID-", $command, "-commandBuffer-02707"), How::User(UNPROVEN_PROTECTED_ACCESS)),
            (concat!("VUID-", $command, "-magFilter-04553"), How::Dynamic(SAMPLER_LINEAR)),
            (concat!("VUID-", $command, "-mipmapMode-04770"), How::Dynamic(SAMPLER_LINEAR)),
            (concat!("VUID-", $command, "-None-02702"), How::User(UNPROVEN_UNNORMALIZED_VIEW)),
            (concat!("VUID-", $command, "-None-02703"), How::Dynamic(SAMPLER_UNNORMALIZED)),
            (concat!("VUID-", $command, "-None-02704"), How::Dynamic(SAMPLER_UNNORMALIZED)),
            (concat!("VUID-", $command, "-None-04115"), How::User(UNPROVEN_TEXEL_COMPONENTS)),
            (concat!("VUID-", $command, "-OpImageWrite-04469"), How::User(UNPROVEN_TEXEL_COMPONENTS)),
            (concat!("VUID-", $command, "-OpTypeImage-07029"), How::User(UNPROVEN_TEXEL_WITHOUT_FORMAT)),
            (concat!("VUID-", $command, "-OpTypeImage-07030"), How::User(UNPROVEN_TEXEL_WITHOUT_FORMAT)),
            (concat!("VUID-", $command, "-None-06550"), How::User(UNPROVEN_YCBCR)),
            (concat!("VUID-", $command, "-ConstOffset-06551"), How::User(UNPROVEN_YCBCR)),
            (concat!("VUID-", $command, "-None-07748"), How::User(UNPROVEN_INPUT_WRITTEN)),
            (concat!("VUID-", $command, "-OpTypeImage-07468"), How::User(UNPROVEN_INPUT_ATTACHMENTS)),
            (concat!("VUID-", $command, "-None-07469"), How::Dynamic(INPUT_VIEW)),
            (concat!("VUID-", $command, "-None-06537"), How::User(ATTACHMENT_MEMORY)),
            (concat!("VUID-", $command, "-None-06538"), How::User(ATTACHMENT_MEMORY)),
            (concat!("VUID-", $command, "-None-06539"), How::User(UNPROVEN_ATTACHMENT_READ_BEFORE)),
            (concat!("VUID-", $command, "-blendEnable-04727"), How::User(UNPROVEN_BLEND)),
            (concat!("VUID-", $command, "-viewportCount-03417"), How::Dynamic(WITH_COUNT)),
            (concat!("VUID-", $command, "-scissorCount-03418"), How::Dynamic(WITH_COUNT)),
            (concat!("VUID-", $command, "-viewportCount-03419"), How::Dynamic(WITH_COUNT)),
            (concat!("VUID-", $command, "-None-06886"), How::Dynamic(READ_ONLY_WRITES)),
            (concat!("VUID-", $command, "-None-06887"), How::Dynamic(READ_ONLY_WRITES)),
            (concat!("VUID-", $command, "-imageView-06172"), How::Dynamic(READ_ONLY_RENDERING)),
            (concat!("VUID-", $command, "-imageView-06173"), How::Dynamic(READ_ONLY_RENDERING)),
            (concat!("VUID-", $command, "-imageView-06174"), How::Dynamic(READ_ONLY_RENDERING)),
            (concat!("VUID-", $command, "-imageView-06175"), How::Dynamic(READ_ONLY_RENDERING)),
            (concat!("VUID-", $command, "-imageView-06176"), How::Dynamic(READ_ONLY_RENDERING)),
            (concat!("VUID-", $command, "-imageView-06177"), How::Dynamic(READ_ONLY_RENDERING)),
            (concat!("VUID-", $command, "-rasterizationSamples-04740"), How::Dynamic(RASTERIZATION_SAMPLES)),
        ]
    };
}

/// The rows of this concern.
pub(super) const ROWS: &[Special] = &[
    bound!(
        "vkCmdDraw",
        GRAPHICS,
        How::Dynamic(SETS_BOUND),
        "VUID-vkCmdDraw-commandBuffer-02712",
        "Some((first_vertex, vertex_count, first_instance, instance_count, \"VUID-vkCmdDraw-None-02721\", \"VUID-vkCmdDraw-maxMultiviewInstanceIndex-02688\"))",
        [
            ("VUID-vkCmdDraw-None-02721", How::Dynamic(VERTEX_RANGE)),
            ("VUID-vkCmdDraw-maxMultiviewInstanceIndex-02688", How::Dynamic(MULTIVIEW_INSTANCES)),
            ("VUID-vkCmdDraw-commandBuffer-02712", How::User(UNPROVEN_PROTECTED_BUFFER)),
            ("VUID-vkCmdDraw-commandBuffer-02713", How::User(UNPROVEN_PROTECTED_BUFFER)),
        ]
    ),
    indexed!(
        "vkCmdDrawIndexed",
        "VUID-vkCmdDrawIndexed-commandBuffer-02712",
        "Some((index_count, first_index, first_instance, instance_count, vertex_offset, \"VUID-vkCmdDrawIndexed-robustBufferAccess2-07825\", \"VUID-vkCmdDrawIndexed-maxMultiviewInstanceIndex-02688\", \"VUID-vkCmdDrawIndexed-None-02721\"))",
        [
            ("VUID-vkCmdDrawIndexed-None-02700", How::Dynamic(PIPELINE_BOUND)),
            ("VUID-vkCmdDrawIndexed-None-02697", How::Dynamic(SETS_BOUND)),
            ("VUID-vkCmdDrawIndexed-None-07312", How::Dynamic(INDEX_BOUND)),
            ("VUID-vkCmdDrawIndexed-None-04007", How::Dynamic(VERTEX_BOUND)),
            ("VUID-vkCmdDrawIndexed-robustBufferAccess2-07825", How::Dynamic(INDEX_RANGE)),
            ("VUID-vkCmdDrawIndexed-maxMultiviewInstanceIndex-02688", How::Dynamic(MULTIVIEW_INSTANCES)),
            ("VUID-vkCmdDrawIndexed-None-02721", How::Dynamic(INDEXED_FETCH)),
            ("VUID-vkCmdDrawIndexed-commandBuffer-02712", How::User(UNPROVEN_PROTECTED_BUFFER)),
            ("VUID-vkCmdDrawIndexed-commandBuffer-02713", How::User(UNPROVEN_PROTECTED_BUFFER)),
        ]
    ),
    bound!(
        "vkCmdDrawIndirect",
        GRAPHICS,
        How::Dynamic(SETS_BOUND),
        "VUID-vkCmdDrawIndirect-commandBuffer-02711",
        "None",
        [("VUID-vkCmdDrawIndirect-commandBuffer-02711", How::User(UNPROVEN_PROTECTED_BUFFER))]
    ),
    indexed!(
        "vkCmdDrawIndexedIndirect",
        "VUID-vkCmdDrawIndexedIndirect-commandBuffer-02711",
        "None",
        [
            ("VUID-vkCmdDrawIndexedIndirect-commandBuffer-02711", How::User(UNPROVEN_PROTECTED_BUFFER)),
            ("VUID-vkCmdDrawIndexedIndirect-None-02700", How::Dynamic(PIPELINE_BOUND)),
            ("VUID-vkCmdDrawIndexedIndirect-None-02697", How::Dynamic(SETS_BOUND)),
            ("VUID-vkCmdDrawIndexedIndirect-None-07312", How::Dynamic(INDEX_BOUND)),
            ("VUID-vkCmdDrawIndexedIndirect-None-04007", How::Dynamic(VERTEX_BOUND)),
        ]
    ),
    bound!(
        "vkCmdDrawIndirectCount",
        GRAPHICS,
        How::Dynamic(SETS_BOUND),
        "VUID-vkCmdDrawIndirectCount-commandBuffer-02711",
        "None",
        [("VUID-vkCmdDrawIndirectCount-commandBuffer-02711", How::User(UNPROVEN_PROTECTED_BUFFER))]
    ),
    indexed!(
        "vkCmdDrawIndexedIndirectCount",
        "VUID-vkCmdDrawIndexedIndirectCount-commandBuffer-02711",
        "None",
        [
            ("VUID-vkCmdDrawIndexedIndirectCount-commandBuffer-02711", How::User(UNPROVEN_PROTECTED_BUFFER)),
            ("VUID-vkCmdDrawIndexedIndirectCount-None-02700", How::Dynamic(PIPELINE_BOUND)),
            ("VUID-vkCmdDrawIndexedIndirectCount-None-02697", How::Dynamic(SETS_BOUND)),
            ("VUID-vkCmdDrawIndexedIndirectCount-None-07312", How::Dynamic(INDEX_BOUND)),
            ("VUID-vkCmdDrawIndexedIndirectCount-None-04007", How::Dynamic(VERTEX_BOUND)),
        ]
    ),
    bound!(
        "vkCmdDispatch",
        COMPUTE,
        How::Dynamic(SETS_BOUND),
        "VUID-vkCmdDispatch-commandBuffer-02712",
        [
            ("VUID-vkCmdDispatch-commandBuffer-02712", How::User(UNPROVEN_PROTECTED_BUFFER)),
            ("VUID-vkCmdDispatch-commandBuffer-02713", How::User(UNPROVEN_PROTECTED_BUFFER)),
        ]
    ),
    bound!(
        "vkCmdDispatchIndirect",
        COMPUTE,
        How::Dynamic(SETS_BOUND),
        "VUID-vkCmdDispatchIndirect-commandBuffer-02711",
        [("VUID-vkCmdDispatchIndirect-commandBuffer-02711", How::User(UNPROVEN_PROTECTED_BUFFER))]
    ),
    bound!(
        "vkCmdDispatchBase",
        COMPUTE,
        How::Dynamic(SETS_BOUND),
        "VUID-vkCmdDispatchBase-commandBuffer-02712",
        call(
            "special::draw::dispatch_base_checks",
            &["self", "base_group_x", "base_group_y", "base_group_z"]
        ),
        [
            ("VUID-vkCmdDispatchBase-baseGroupX-00427", How::Dynamic(DISPATCH_BASE)),
            ("VUID-vkCmdDispatchBase-commandBuffer-02712", How::User(UNPROVEN_PROTECTED_BUFFER)),
            ("VUID-vkCmdDispatchBase-commandBuffer-02713", How::User(UNPROVEN_PROTECTED_BUFFER)),
        ]
    ),
];
