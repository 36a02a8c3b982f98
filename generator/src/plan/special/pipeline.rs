//! The special-case rows of one concern; their functions are the `tuff` crate's
//! `special/pipeline.rs`, and a row here calls no other (but the image-layout tracker).
//!
//! Pipelines: compute and graphics pipeline creation (each create info, derivatives,
//! caches, creation feedback) and the record the device keeps of each.

use super::{call, How, Special, MULTI_VIEWPORT, NONE, VIEWPORTS};

const CACHE_DATA: &str = "refuses any initial data: where the bytes came from is what the rule is about, which tuff cannot see (data saved to disk comes back through the `unsafe` `create_pipeline_cache_unchecked`, on the caller's word); the 1.3.239 layer does not check it: the error alone proves it";
const CACHE_DATA_SAME: &str = "checked by the safe methods in every build, by the check of VUID-VkPipelineCacheCreateInfo-initialDataSize-00769, which refuses any initial data and whose VUID the error names";
const MERGE_SELF: &str = "checks the destination cache is none of the sources";
const STAGE_MODULE: &str = "checks each stage of a compute or graphics pipeline names a module, the only way its code can have had the shader promise (proven by the error alone: the layer is not asked, since a NULL module would reach the driver)";
const SHADER_LAYOUT: &str = "checks every resource variable the stage's module declares (a superset of those it uses) has a binding in the layout of a descriptor type that can back it, visible to the stage and with as many descriptors, and that its push-constant block lies inside a range for the stage";
const ENTRY_POINT: &str = "checks each stage of a graphics or compute pipeline names an entry point of its module with the stage's execution model (the module's entry points are read from its SPIR-V when it is made)";
const CACHE_LOCKED: &str = "the checked method holds the pipeline cache's lock for the call (with `multi_thread`; without it the cache cannot reach another thread), so no two pipeline creations use one cache at once";
const UNPROVEN_FEEDBACK_COUNT: &str = "checked by the safe methods in every build (a chained VkPipelineCreationFeedbackCreateInfo's stage count against the pipeline's, or 0), but no test breaks it: the safe struct has no setter for the stage feedbacks, so their count stays 0, which the rule allows";
const WORKGROUP_SUBGROUPS: &str = "checks a stage that asks for full subgroups: the width of the workgroup its entry point declares (the LocalSize execution mode, read from the module's SPIR-V; a size given otherwise is refused) against the required subgroup size, maxSubgroupSize with a varying size, or the device's subgroupSize";
const UNPROVEN_WORKGROUP_SUBGROUPS: &str = "checked by the safe methods in every build (a compute stage with a required subgroup size: the invocations of the workgroup its entry point declares against maxComputeWorkgroupSubgroups subgroups of that size), but no test breaks it: lavapipe's maxComputeWorkgroupSubgroups times its subgroup size is its largest workgroup";
const SUBGROUP_SIZES: &str = "checks each stage of a graphics or compute pipeline: its subgroup size flags against the subgroupSizeControl and computeFullSubgroups features the device recorded, and a chained required subgroup size against a power of two, the device's minSubgroupSize, maxSubgroupSize and requiredSubgroupSizeStages (Vulkan 1.3 properties, read at the call), the varying-size flag and the subgroupSizeControl feature (the 1.3.239 layer names the flags rules and 02754 for a graphics stage, and says nothing of the required size's others: the error alone proves them)";
const UNPROVEN_BUILTINS: &str = "checked by the safe methods in every build (the built-in variables of the interface of the entry point a graphics stage names, read from the module's SPIR-V: clip and cull distance and sample mask array sizes against the limits, no cull distance input to a vertex stage or output from a fragment stage), but no test breaks it: GLSL compilers keep these arrays within their own limits, which lavapipe's match, and declare no such variables, and the test shaders are GLSL";
const CONSTANT_SIZES: &str = "checks each specialization map entry that names a constant the stage's module declares (its SpecId and scalar type, read from the SPIR-V when the module is made) against the byte size of that type, four for a boolean";
const SPECIALIZATION: &str = "checks each specialization map entry lies inside the specialization data (graphics and compute pipelines)";
const GIVEN_OR_DYNAMIC: &str =
    "checks the viewports (scissors) are given or dynamic unless rasterization is discarded";
const PIPELINE_STATE: &str = "checks the pipeline's state as a whole (every pipeline is complete, as tuff emits no pipeline library): derivatives, the set of stages and the topology they need, the state structs it must have, its subpass's attachments (kept from the render pass's creation) or its rendering formats and their format features, and fixed-function values against the features the device recorded";
const PIPELINE_STATE_ALONE: &str = "checks the pipeline's state as a whole, as for its other rules (the 1.3.239 layer does not check this one, and lavapipe crashes on a missing layout or multisample state: proven by the error alone)";
const STATE_STRUCTS: &str = "checks each state struct on its own: dynamic states, vertex bindings and locations once each, every attribute's binding described and its format one the device reads vertices in (VERTEX_BUFFER among its buffer features), primitive restart only with strip and fan topologies, adjacency only with geometryShader, the patch size within maxTessellationPatchSize, minSampleShading within [0, 1], a defined logic operation, each stage's specialization constants once each (for compute pipelines too)";
const COMPUTE_STATE: &str = "checks the stage is a compute stage and a derivative names its base one way (by handle, or by the index of an earlier create info), and one that allows derivatives (a pipeline by handle, as the device recorded its flags); the 1.3.239 layer names none of the derivative rules but 00698 and 00699 for compute pipelines, so the error alone proves the others";
const UNAVAILABLE_DYNAMIC_STATES: &str = "checked by the safe methods in every build (the state is refused, as its feature is VK_EXT_extended_dynamic_state2's, which no device made through the safe create_device enables), but no test breaks it: on such a device the implicit check of pDynamicStates refuses the state first, as a value of an extension not enabled";
const RENDER_PASS_WRAPPER: &str = "the safe struct's `render_pass` takes an `Option<&RenderPass>`: no handle, or a live wrapper's, which is valid";
const NO_VIEW_MASK_BUILT_IN: &str = "SPIR-V has no ViewMask built-in (the 1.3.239 rule's name for it), so no interface variable can be decorated with it";
const STAGE_INTERFACES: &str = "checks the built-ins the stages' entry points declare and store to (read from each module's SPIR-V): a fragment stage that reads PrimitiveId after a geometry stage that does not write it is refused (the 1.3.239 layer does not check it: the error alone proves it)";
const STAGE_LINKING: &str = "checks the linking rules between consecutive stages (the user-defined inputs and outputs and the built-in blocks of the entry points the stages name, read from each module's SPIR-V): each input of a stage has an output of the stage before it at its location and component, of the same type (or with maintenance4 a vector of more components of that type), per-patch alike; the built-in blocks of two stages neither of which is a fragment stage are the same; an input nothing writes, and a type the reader cannot follow, are refused; the stages' resource and push-constant interfaces are checked as for layout-00756, and the chapter's rules on one module alone against the device are the shader promise's (the 1.3.239 layer reports these cases under unassigned IDs, or not at all: the error alone proves them)";
const UNPROVEN_COMPUTE_LINKING: &str = "checked by the safe methods in every build: the linking rules a compute stage has are its resource and push-constant interfaces against the layout, checked and proven as VkComputePipelineCreateInfo-layout-00703 (which a broken interface breaks first, so no test names this rule), and the chapter's rules on one module alone against the device, which the shader promise covers";
const INPUT_ASPECTS: &str = "checks each input attachment variable of the fragment stage (its InputAttachmentIndex, array size and numeric type, read from the module's SPIR-V) against the aspects the subpass's references let it read, kept from the render pass's creation (a chained VkRenderPassInputAttachmentAspectCreateInfo, or VkAttachmentReference2's aspectMask): a float variable reads a depth/stencil attachment's depth, an integer one its stencil, any other a color attachment's color (the 1.3.239 layer does not check it: the error alone proves it)";
const UNPROVEN_STAGE_INTERFACES: &str = "checked by the safe methods in every build (with a view mask, tessellation and geometry stages against the multiview features and no Layer written or declared; input attachments of a fragment stage only in a render pass, none unused in the subpass, no InputAttachment capability in dynamic rendering), but no test breaks it yet: the test devices enable the multiview features with the stages, the test render passes have no view mask, and the test shaders written for Vulkan 1.0 cannot write Layer from a vertex stage";
const POINT_SIZE: &str = "checks the last pre-rasterization stage of a pipeline that rasterizes points (a vertex stage alone with a point list, a geometry stage that outputs points, a tessellation evaluation stage in point mode) writes PointSize, or with shaderTessellationAndGeometryPointSize off for the last two does not: the stores of the module into a PointSize variable or block member of its interface are read from its SPIR-V when it is made";
const UNPROVEN_POINT_SIZE: &str = "checked by the safe methods in every build (as for Vertex-07722 and Geometry-07725), but no test breaks it: the test devices enable shaderTessellationAndGeometryPointSize whenever they enable geometry and tessellation shaders, and no test shader tessellates in point mode";
const EXECUTION_MODES: &str = "checks the execution modes of the entry points the tessellation and geometry stages name (read from each module's SPIR-V when it is made): a geometry stage's input primitive against the topology, or against what the tessellation stages emit (points, lines for isolines, else triangles); the 1.3.239 layer checks neither case: the error alone proves them";
const UNPROVEN_EXECUTION_MODES: &str = "checked by the safe methods in every build (the execution modes of the entry points the tessellation and geometry stages name, read from each module's SPIR-V: one subdivision and one output patch size between the tessellation stages, within maxTessellationPatchSize; a geometry stage's output vertex and invocation counts within the limits), but no test breaks it: GLSL writes these modes in the stage that must have them, within the compiler's limits, and the test shaders are GLSL";
const UNPROVEN_STAGE_RESOURCES: &str = "checked by the safe methods in every build (for each stage, the descriptors of the limited kinds its layout's set layouts without UPDATE_AFTER_BIND_POOL make visible to it, and for the fragment stage the color attachments, against maxPerStageResources), but no test breaks it: a pipeline layout past the limit is refused when it is made (VkPipelineLayoutCreateInfo-descriptorType-03022), and one at lavapipe's limit is more descriptors than a test should make to add a color attachment to";
const COMPLETE_PIPELINES: &str = "every graphics pipeline the emitted API makes is complete (no pipeline libraries are emitted): it always has pre-rasterization shader state, its vertex stage among them (stage-00727 is checked)";
const VIEWPORT_STATE_ALONE: &str = "checks the pipeline's state as a whole, as for its other rules (a pipeline with rasterizer discard dynamic and no viewport state crashed the test process under the 1.3.239 layer, which lets it through to lavapipe: proven by the error alone)";
const RENDERING_FORMATS_SLICE: &str = "the safe VkPipelineRenderingCreateInfo's `color_attachment_formats` takes a slice and sets `colorAttachmentCount` from its length, so the pointer is valid for that many formats (each checked as a VkFormat value, renderPass-06580)";
const BLEND_ATTACHMENTS_SLICE: &str = "the safe struct's `attachments` takes a slice and sets `attachmentCount` from its length, so the pointer is valid for that many states";
const SAME_AS_00699: &str = "checked by the safe methods in every build: a derivative with a base pipeline handle and an index other than -1 is refused as VUID-VkComputePipelineCreateInfo-flags-00699, whose text states the same case, and the layer names both";
const SAME_AS_00724: &str = "checked by the safe methods in every build: a derivative with a base pipeline handle and an index other than -1 is refused as VUID-VkGraphicsPipelineCreateInfo-flags-00724, whose text states the same case, and the layer names both";
const UNPROVEN_DEPTH_BOUNDS: &str = "checked by the safe methods in every build, but no test breaks it: lavapipe has no depthBounds feature, without which a depth bounds test is refused first";
const UNPROVEN_DEPTH_FORMAT: &str = "checked by the safe methods in every build, but no test breaks it: every format lavapipe has with a depth (or stencil) aspect is a depth/stencil attachment format, so a format without the feature lacks the aspect, which is refused first";

/// The rows of this concern.
pub(super) const ROWS: &[Special] = &[
    Special {
        command: "vkCreatePipelineCache",
        check: call("special::pipeline::create_pipeline_cache_checks", &["create_info"]),
        settles: &[
            ("VUID-VkPipelineCacheCreateInfo-initialDataSize-00769", How::Dynamic(CACHE_DATA)),
            ("VUID-VkPipelineCacheCreateInfo-initialDataSize-00768", How::User(CACHE_DATA_SAME)),
        ],
        ..NONE
    },
    Special {
        command: "vkMergePipelineCaches",
        check: call(
            "special::pipeline::merge_pipeline_caches_checks",
            &["dst_cache", "src_caches"],
        ),
        settles: &[(
            "VUID-vkMergePipelineCaches-dstCache-00770",
            How::Dynamic(MERGE_SELF),
        )],
        ..NONE
    },
    Special {
        command: "vkCreateComputePipelines",
        check: call("special::pipeline::create_compute_pipelines_checks", &["self", "create_infos"]),
        hold: call("special::pipeline::pipeline_cache_hold", &["self", "pipeline_cache"]),
        created: call(
            "special::pipeline::compute_pipelines_created",
            &["self", "created", "create_infos"],
        ),
        settles: &[
            ("VUID-VkComputePipelineCreateInfo-stage-00701", How::Dynamic(COMPUTE_STATE)),
            ("VUID-VkComputePipelineCreateInfo-flags-00697", How::Dynamic(COMPUTE_STATE)),
            ("VUID-VkComputePipelineCreateInfo-flags-00698", How::Dynamic(COMPUTE_STATE)),
            ("VUID-VkComputePipelineCreateInfo-flags-00699", How::Dynamic(COMPUTE_STATE)),
            ("VUID-vkCreateComputePipelines-flags-00695", How::Dynamic(COMPUTE_STATE)),
            ("VUID-VkComputePipelineCreateInfo-flags-00700", How::User(SAME_AS_00699)),
            ("VUID-VkComputePipelineCreateInfo-layout-01687", How::User(UNPROVEN_STAGE_RESOURCES)),
            ("VUID-vkCreateComputePipelines-flags-00696", How::Dynamic(COMPUTE_STATE)),
            ("VUID-VkSpecializationInfo-offset-00773", How::Dynamic(SPECIALIZATION)),
            ("VUID-VkSpecializationMapEntry-constantID-00776", How::Dynamic(CONSTANT_SIZES)),
            ("VUID-VkPipelineShaderStageCreateInfo-maxClipDistances-00708", How::User(UNPROVEN_BUILTINS)),
            ("VUID-VkPipelineShaderStageCreateInfo-maxCullDistances-00709", How::User(UNPROVEN_BUILTINS)),
            ("VUID-VkPipelineShaderStageCreateInfo-maxCombinedClipAndCullDistances-00710", How::User(UNPROVEN_BUILTINS)),
            ("VUID-VkPipelineShaderStageCreateInfo-maxSampleMaskWords-00711", How::User(UNPROVEN_BUILTINS)),
            ("VUID-VkPipelineShaderStageCreateInfo-stage-00712", How::User(UNPROVEN_BUILTINS)),
            ("VUID-VkPipelineShaderStageCreateInfo-stage-00718", How::User(UNPROVEN_BUILTINS)),
            ("VUID-VkSpecializationInfo-pMapEntries-00774", How::Dynamic(SPECIALIZATION)),
            ("VUID-VkComputePipelineCreateInfo-layout-00703", How::Dynamic(SHADER_LAYOUT)),
            ("VUID-VkComputePipelineCreateInfo-stage-00702", How::User(UNPROVEN_COMPUTE_LINKING)),
            ("VUID-VkPipelineShaderStageCreateInfo-module-06716", How::Dynamic(STAGE_MODULE)),
            ("VUID-vkCreateComputePipelines-pipelineCache-02873", How::Static(CACHE_LOCKED)),
            ("VUID-vkCreateGraphicsPipelines-pipelineCache-02876", How::Static(CACHE_LOCKED)),
            ("VUID-VkComputePipelineCreateInfo-pipelineStageCreationFeedbackCount-06566", How::User(UNPROVEN_FEEDBACK_COUNT)),
            ("VUID-VkGraphicsPipelineCreateInfo-pipelineStageCreationFeedbackCount-06594", How::User(UNPROVEN_FEEDBACK_COUNT)),
            ("VUID-VkPipelineShaderStageCreateInfo-pName-00707", How::Dynamic(ENTRY_POINT)),
            ("VUID-VkPipelineShaderStageCreateInfo-flags-02784", How::Dynamic(SUBGROUP_SIZES)),
            ("VUID-VkPipelineShaderStageCreateInfo-pNext-02756", How::User(UNPROVEN_WORKGROUP_SUBGROUPS)),
            ("VUID-VkPipelineShaderStageCreateInfo-pNext-02757", How::Dynamic(WORKGROUP_SUBGROUPS)),
            ("VUID-VkPipelineShaderStageCreateInfo-flags-02758", How::Dynamic(WORKGROUP_SUBGROUPS)),
            ("VUID-VkPipelineShaderStageCreateInfo-flags-02759", How::Dynamic(WORKGROUP_SUBGROUPS)),
            ("VUID-VkPipelineShaderStageCreateInfo-flags-02785", How::Dynamic(SUBGROUP_SIZES)),
            ("VUID-VkPipelineShaderStageCreateInfo-pNext-02754", How::Dynamic(SUBGROUP_SIZES)),
            ("VUID-VkPipelineShaderStageCreateInfo-pNext-02755", How::Dynamic(SUBGROUP_SIZES)),
            ("VUID-VkPipelineShaderStageRequiredSubgroupSizeCreateInfo-requiredSubgroupSize-02760", How::Dynamic(SUBGROUP_SIZES)),
            ("VUID-VkPipelineShaderStageRequiredSubgroupSizeCreateInfo-requiredSubgroupSize-02761", How::Dynamic(SUBGROUP_SIZES)),
            ("VUID-VkPipelineShaderStageRequiredSubgroupSizeCreateInfo-requiredSubgroupSize-02762", How::Dynamic(SUBGROUP_SIZES)),
        ],
        ..NONE
    },
    Special {
        command: "vkCreateGraphicsPipelines",
        check: call("special::pipeline::create_graphics_pipelines_checks", &["self", "create_infos"]),
        hold: call("special::pipeline::pipeline_cache_hold", &["self", "pipeline_cache"]),
        check_last: call(
            "special::pipeline::graphics_pipeline_state_checks",
            &["self", "create_infos"],
        ),
        created: call(
            "special::pipeline::graphics_pipelines_created",
            &["self", "created", "create_infos"],
        ),
        settles: &[
            ("VUID-VkPipelineDynamicStateCreateInfo-pDynamicStates-01442", How::Dynamic(STATE_STRUCTS)),
            ("VUID-VkPipelineVertexInputStateCreateInfo-pVertexBindingDescriptions-00616", How::Dynamic(STATE_STRUCTS)),
            ("VUID-VkPipelineVertexInputStateCreateInfo-pVertexAttributeDescriptions-00617", How::Dynamic(STATE_STRUCTS)),
            ("VUID-VkPipelineVertexInputStateCreateInfo-binding-00615", How::Dynamic(STATE_STRUCTS)),
            ("VUID-VkPipelineInputAssemblyStateCreateInfo-topology-00428", How::Dynamic(STATE_STRUCTS)),
            ("VUID-VkPipelineInputAssemblyStateCreateInfo-topology-00429", How::Dynamic(STATE_STRUCTS)),
            ("VUID-VkPipelineTessellationStateCreateInfo-patchControlPoints-01214", How::Dynamic(STATE_STRUCTS)),
            ("VUID-VkPipelineMultisampleStateCreateInfo-minSampleShading-00786", How::Dynamic(STATE_STRUCTS)),
            ("VUID-VkPipelineColorBlendStateCreateInfo-logicOpEnable-00607", How::Dynamic(STATE_STRUCTS)),
            ("VUID-VkSpecializationInfo-constantID-04911", How::Dynamic(STATE_STRUCTS)),
            ("VUID-VkGraphicsPipelineCreateInfo-layout-00756", How::Dynamic(SHADER_LAYOUT)),
            ("VUID-VkPipelineViewportStateCreateInfo-viewportCount-04135", How::Dynamic(PIPELINE_STATE)),
            ("VUID-VkPipelineViewportStateCreateInfo-viewportCount-arraylength", How::Dynamic(PIPELINE_STATE)),
            ("VUID-VkPipelineViewportStateCreateInfo-scissorCount-arraylength", How::Dynamic(PIPELINE_STATE)),
            ("VUID-VkPipelineViewportStateCreateInfo-scissorCount-04136", How::Dynamic(PIPELINE_STATE)),
            ("VUID-VkPipelineViewportStateCreateInfo-scissorCount-04134", How::Dynamic(PIPELINE_STATE)),
            ("VUID-VkPipelineViewportStateCreateInfo-x-02821", How::Dynamic(PIPELINE_STATE)),
            ("VUID-VkPipelineViewportStateCreateInfo-offset-02822", How::Dynamic(PIPELINE_STATE)),
            ("VUID-VkPipelineViewportStateCreateInfo-offset-02823", How::Dynamic(PIPELINE_STATE)),
            ("VUID-VkPipelineColorBlendStateCreateInfo-pAttachments-00605", How::Dynamic(PIPELINE_STATE)),
            ("VUID-VkGraphicsPipelineCreateInfo-flags-00764", How::Dynamic(PIPELINE_STATE)),
            ("VUID-VkGraphicsPipelineCreateInfo-flags-00722", How::Dynamic(PIPELINE_STATE_ALONE)),
            ("VUID-VkGraphicsPipelineCreateInfo-flags-00723", How::Dynamic(PIPELINE_STATE)),
            ("VUID-VkGraphicsPipelineCreateInfo-flags-00724", How::Dynamic(PIPELINE_STATE)),
            ("VUID-VkGraphicsPipelineCreateInfo-flags-00725", How::User(SAME_AS_00724)),
            ("VUID-VkVertexInputAttributeDescription-format-00623", How::Dynamic(STATE_STRUCTS)),
            ("VUID-VkGraphicsPipelineCreateInfo-renderPass-06603", How::Static(RENDER_PASS_WRAPPER)),
            ("VUID-VkGraphicsPipelineCreateInfo-pStages-06894", How::Dynamic(PIPELINE_STATE)),
            ("VUID-VkGraphicsPipelineCreateInfo-subpass-00758", How::Dynamic(PIPELINE_STATE)),
            ("VUID-VkGraphicsPipelineCreateInfo-layout-01688", How::User(UNPROVEN_STAGE_RESOURCES)),
            ("VUID-VkGraphicsPipelineCreateInfo-pStages-00738", How::Dynamic(EXECUTION_MODES)),
            ("VUID-VkGraphicsPipelineCreateInfo-Vertex-07722", How::Dynamic(POINT_SIZE)),
            ("VUID-VkGraphicsPipelineCreateInfo-pStages-00740", How::Dynamic(STAGE_INTERFACES)),
            ("VUID-VkGraphicsPipelineCreateInfo-pStages-00742", How::Dynamic(STAGE_LINKING)),
            ("VUID-VkGraphicsPipelineCreateInfo-None-04889", How::Dynamic(STAGE_LINKING)),
            ("VUID-VkGraphicsPipelineCreateInfo-pStages-01565", How::Dynamic(INPUT_ASPECTS)),
            ("VUID-VkGraphicsPipelineCreateInfo-renderPass-06047", How::User(UNPROVEN_STAGE_INTERFACES)),
            ("VUID-VkGraphicsPipelineCreateInfo-renderPass-06048", How::User(UNPROVEN_STAGE_INTERFACES)),
            ("VUID-VkGraphicsPipelineCreateInfo-renderPass-06049", How::User(UNPROVEN_STAGE_INTERFACES)),
            ("VUID-VkGraphicsPipelineCreateInfo-renderPass-06050", How::User(UNPROVEN_STAGE_INTERFACES)),
            ("VUID-VkGraphicsPipelineCreateInfo-renderPass-06057", How::User(UNPROVEN_STAGE_INTERFACES)),
            ("VUID-VkGraphicsPipelineCreateInfo-renderPass-06058", How::User(UNPROVEN_STAGE_INTERFACES)),
            ("VUID-VkGraphicsPipelineCreateInfo-renderPass-07718", How::User(UNPROVEN_STAGE_INTERFACES)),
            ("VUID-VkGraphicsPipelineCreateInfo-renderPass-06059", How::User(UNPROVEN_STAGE_INTERFACES)),
            ("VUID-VkGraphicsPipelineCreateInfo-renderPass-07719", How::User(UNPROVEN_STAGE_INTERFACES)),
            ("VUID-VkGraphicsPipelineCreateInfo-renderPass-07717", How::Static(NO_VIEW_MASK_BUILT_IN)),
            ("VUID-VkGraphicsPipelineCreateInfo-None-06573", How::Static(COMPLETE_PIPELINES)),
            ("VUID-VkGraphicsPipelineCreateInfo-renderPass-06038", How::User(UNPROVEN_STAGE_INTERFACES)),
            ("VUID-VkGraphicsPipelineCreateInfo-renderPass-06056", How::User(UNPROVEN_STAGE_INTERFACES)),
            ("VUID-VkGraphicsPipelineCreateInfo-renderPass-06061", How::User(UNPROVEN_STAGE_INTERFACES)),
            ("VUID-VkGraphicsPipelineCreateInfo-Geometry-07725", How::Dynamic(POINT_SIZE)),
            ("VUID-VkGraphicsPipelineCreateInfo-TessellationEvaluation-07723", How::User(UNPROVEN_POINT_SIZE)),
            ("VUID-VkGraphicsPipelineCreateInfo-TessellationEvaluation-07724", How::User(UNPROVEN_POINT_SIZE)),
            ("VUID-VkGraphicsPipelineCreateInfo-Geometry-07726", How::User(UNPROVEN_POINT_SIZE)),
            ("VUID-VkGraphicsPipelineCreateInfo-pStages-00739", How::Dynamic(EXECUTION_MODES)),
            ("VUID-VkGraphicsPipelineCreateInfo-pStages-00732", How::User(UNPROVEN_EXECUTION_MODES)),
            ("VUID-VkGraphicsPipelineCreateInfo-pStages-00733", How::User(UNPROVEN_EXECUTION_MODES)),
            ("VUID-VkGraphicsPipelineCreateInfo-pStages-00734", How::User(UNPROVEN_EXECUTION_MODES)),
            ("VUID-VkGraphicsPipelineCreateInfo-pStages-00735", How::User(UNPROVEN_EXECUTION_MODES)),
            ("VUID-VkPipelineShaderStageCreateInfo-stage-00713", How::User(UNPROVEN_EXECUTION_MODES)),
            ("VUID-VkPipelineShaderStageCreateInfo-stage-00714", How::User(UNPROVEN_EXECUTION_MODES)),
            ("VUID-VkPipelineShaderStageCreateInfo-stage-00715", How::User(UNPROVEN_EXECUTION_MODES)),
            ("VUID-VkGraphicsPipelineCreateInfo-pStages-06895", How::Static(COMPLETE_PIPELINES)),
            ("VUID-VkGraphicsPipelineCreateInfo-pStages-06896", How::Dynamic(PIPELINE_STATE)),
            ("VUID-VkGraphicsPipelineCreateInfo-renderPass-06579", How::Static(RENDERING_FORMATS_SLICE)),
            ("VUID-VkGraphicsPipelineCreateInfo-renderPass-06580", How::Dynamic(PIPELINE_STATE)),
            ("VUID-VkGraphicsPipelineCreateInfo-renderPass-06583", How::Dynamic(PIPELINE_STATE)),
            ("VUID-VkGraphicsPipelineCreateInfo-renderPass-06584", How::Dynamic(PIPELINE_STATE)),
            ("VUID-VkGraphicsPipelineCreateInfo-renderPass-06053", How::Dynamic(PIPELINE_STATE)),
            ("VUID-VkGraphicsPipelineCreateInfo-renderPass-06054", How::Dynamic(PIPELINE_STATE)),
            ("VUID-VkGraphicsPipelineCreateInfo-pViewportState-04892", How::Dynamic(VIEWPORT_STATE_ALONE)),
            ("VUID-VkGraphicsPipelineCreateInfo-renderPass-06575", How::Static(RENDER_PASS_WRAPPER)),
            ("VUID-VkPipelineColorBlendStateCreateInfo-pAttachments-07354", How::Static(BLEND_ATTACHMENTS_SLICE)),
            ("VUID-vkCreateGraphicsPipelines-flags-00720", How::Dynamic(PIPELINE_STATE)),
            ("VUID-vkCreateGraphicsPipelines-flags-00721", How::Dynamic(PIPELINE_STATE)),
            ("VUID-VkGraphicsPipelineCreateInfo-pDynamicStates-04869", How::User(UNAVAILABLE_DYNAMIC_STATES)),
            ("VUID-VkGraphicsPipelineCreateInfo-pDynamicStates-04870", How::User(UNAVAILABLE_DYNAMIC_STATES)),
            ("VUID-VkGraphicsPipelineCreateInfo-stage-06897", How::Dynamic(PIPELINE_STATE)),
            ("VUID-VkGraphicsPipelineCreateInfo-stage-00727", How::Dynamic(PIPELINE_STATE)),
            ("VUID-VkGraphicsPipelineCreateInfo-pStages-00729", How::Dynamic(PIPELINE_STATE)),
            ("VUID-VkGraphicsPipelineCreateInfo-pStages-00730", How::Dynamic(PIPELINE_STATE)),
            ("VUID-VkGraphicsPipelineCreateInfo-pStages-00731", How::Dynamic(PIPELINE_STATE)),
            ("VUID-VkGraphicsPipelineCreateInfo-pStages-00736", How::Dynamic(PIPELINE_STATE)),
            ("VUID-VkGraphicsPipelineCreateInfo-topology-00737", How::Dynamic(PIPELINE_STATE)),
            ("VUID-VkGraphicsPipelineCreateInfo-pStages-02097", How::Dynamic(PIPELINE_STATE)),
            ("VUID-VkGraphicsPipelineCreateInfo-pStages-02098", How::Dynamic(PIPELINE_STATE)),
            ("VUID-VkGraphicsPipelineCreateInfo-pRasterizationState-06601", How::Dynamic(PIPELINE_STATE)),
            ("VUID-VkGraphicsPipelineCreateInfo-layout-06602", How::Dynamic(PIPELINE_STATE_ALONE)),
            ("VUID-VkGraphicsPipelineCreateInfo-rasterizerDiscardEnable-00750", How::Dynamic(PIPELINE_STATE)),
            ("VUID-VkGraphicsPipelineCreateInfo-rasterizerDiscardEnable-00751", How::Dynamic(PIPELINE_STATE_ALONE)),
            ("VUID-VkGraphicsPipelineCreateInfo-renderPass-06046", How::Dynamic(PIPELINE_STATE)),
            ("VUID-VkGraphicsPipelineCreateInfo-dynamicRendering-06576", How::Dynamic(PIPELINE_STATE)),
            ("VUID-VkGraphicsPipelineCreateInfo-multiview-06577", How::Dynamic(PIPELINE_STATE)),
            ("VUID-VkGraphicsPipelineCreateInfo-renderPass-06578", How::Dynamic(PIPELINE_STATE)),
            ("VUID-VkGraphicsPipelineCreateInfo-renderPass-06581", How::Dynamic(PIPELINE_STATE)),
            ("VUID-VkGraphicsPipelineCreateInfo-renderPass-06585", How::User(UNPROVEN_DEPTH_FORMAT)),
            ("VUID-VkGraphicsPipelineCreateInfo-renderPass-06586", How::User(UNPROVEN_DEPTH_FORMAT)),
            ("VUID-VkGraphicsPipelineCreateInfo-renderPass-06587", How::Dynamic(PIPELINE_STATE)),
            ("VUID-VkGraphicsPipelineCreateInfo-renderPass-06588", How::Dynamic(PIPELINE_STATE)),
            ("VUID-VkGraphicsPipelineCreateInfo-renderPass-06589", How::Dynamic(PIPELINE_STATE)),
            ("VUID-VkGraphicsPipelineCreateInfo-renderPass-06043", How::Dynamic(PIPELINE_STATE)),
            ("VUID-VkGraphicsPipelineCreateInfo-renderPass-06044", How::Dynamic(PIPELINE_STATE)),
            ("VUID-VkGraphicsPipelineCreateInfo-renderPass-06042", How::Dynamic(PIPELINE_STATE)),
            ("VUID-VkGraphicsPipelineCreateInfo-renderPass-06055", How::Dynamic(PIPELINE_STATE)),
            ("VUID-VkGraphicsPipelineCreateInfo-renderPass-06041", How::Dynamic(PIPELINE_STATE)),
            ("VUID-VkGraphicsPipelineCreateInfo-renderPass-06062", How::Dynamic(PIPELINE_STATE)),
            ("VUID-VkGraphicsPipelineCreateInfo-pDynamicStates-00749", How::Dynamic(PIPELINE_STATE)),
            ("VUID-VkGraphicsPipelineCreateInfo-pDynamicStates-00754", How::Dynamic(PIPELINE_STATE)),
            ("VUID-VkGraphicsPipelineCreateInfo-pDynamicStates-00755", How::User(UNPROVEN_DEPTH_BOUNDS)),
            ("VUID-VkGraphicsPipelineCreateInfo-pDynamicStates-03379", How::Dynamic(PIPELINE_STATE)),
            ("VUID-VkGraphicsPipelineCreateInfo-pDynamicStates-03380", How::Dynamic(PIPELINE_STATE)),
            ("VUID-VkGraphicsPipelineCreateInfo-pDynamicStates-04132", How::Dynamic(PIPELINE_STATE)),
            ("VUID-VkGraphicsPipelineCreateInfo-pDynamicStates-04133", How::Dynamic(PIPELINE_STATE)),
            (
                "VUID-VkGraphicsPipelineCreateInfo-pStages-06600",
                How::Dynamic("checks the stages are set when stageCount is not 0 (the layer would read the NULL array too: proven by the error alone)"),
            ),
            (
                "VUID-VkGraphicsPipelineCreateInfo-pDynamicStates-04130",
                How::Dynamic(GIVEN_OR_DYNAMIC),
            ),
            (
                "VUID-VkGraphicsPipelineCreateInfo-pDynamicStates-04131",
                How::Dynamic(GIVEN_OR_DYNAMIC),
            ),
            ("VUID-VkPipelineViewportStateCreateInfo-viewportCount-01216", How::Dynamic(MULTI_VIEWPORT)),
            ("VUID-VkPipelineViewportStateCreateInfo-scissorCount-01217", How::Dynamic(MULTI_VIEWPORT)),
            ("VUID-VkPipelineViewportStateCreateInfo-viewportCount-01218", How::Dynamic(VIEWPORTS)),
            ("VUID-VkPipelineViewportStateCreateInfo-scissorCount-01219", How::Dynamic(VIEWPORTS)),
        ],
        ..NONE
    },
];
