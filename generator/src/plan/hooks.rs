//! The special cases of the emitted commands, in one table.
//!
//! Most of a command's method follows from its parameters' shapes. What does not (a
//! check every build needs for memory safety, bookkeeping after a submission, a
//! created wrapper that must remember its create flags) is a row here: the command,
//! the hand-written functions of the `tuff` crate's `hooks` module it calls and when,
//! and the rules those functions settle. The commands renderer turns a row into calls;
//! the report reads the rules from the same row, so what is checked and what the
//! report says is checked cannot drift apart. The functions carry the code and its
//! `// SAFETY:` comments; the table carries only names.

/// A call of a hand-written function: its path under the `tuff` crate root and the
/// bindings of the generated method it takes, in order. A binding is `self`, a
/// parameter's Rust name (a handle slice is the caller's `&[&T]`), `r` (the
/// `vk::Result` of the call), `out` (the raw output of a create or get) or `created`
/// (the wrapper the method would return without the hook).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Call {
    /// `hooks::queue_submit_checks`.
    pub path: &'static str,
    /// The generated method's bindings passed to it.
    pub args: &'static [&'static str],
    /// For an `unsafe` function: why the call upholds its contract, which becomes the
    /// call's `// SAFETY:` comment.
    pub promise: Option<&'static str>,
}

/// How the special row settles one rule.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum How {
    /// By construction; the text names the mechanism.
    Static(&'static str),
    /// By the row's `check` (or a hand-written method); the text names the check.
    Dynamic(&'static str),
    /// Checked, but a safe program can still break it; the text says how.
    User(&'static str),
}

/// What a created object keeps alive of what its create info names.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Keeps {
    /// Every handle the info reaches (members, arrays, nested structs, `pNext`).
    Reached,
    /// Nothing: the objects the info names keep this one alive instead (a dedicated
    /// allocation's image holds its memory once bound; the memory holding the image
    /// too would be a cycle, and neither would ever be destroyed).
    Nothing,
    /// This handle member (member, handle type), which the method takes as a wrapper
    /// and writes into the info, and nothing else.
    Member(&'static str, &'static str),
}

/// One command's special case.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Special {
    /// The command, `vkQueueSubmit`.
    pub command: &'static str,
    /// Run by the safe method in every build, before the call and before the
    /// implicit-rule checks (it refuses what would break memory safety, whatever
    /// else is wrong); returns `Result<()>`. A recorded command with one returns its
    /// error.
    pub check: Option<Call>,
    /// Run by the safe method in every build after the implicit-rule and
    /// recognised checks have passed: a check that hands the call's values to the
    /// driver (a query), which needs them valid first.
    pub check_last: Option<Call>,
    /// Run by the safe method in every build after `check_last`: a check whose
    /// verdict another thread could change before the driver runs (a count of live
    /// objects). It returns `Result<G>`, and the method holds the guard `G` until
    /// the call has returned.
    pub hold: Option<Call>,
    /// Run by the call's body before the call.
    pub before: Option<Call>,
    /// Run by the call's body after a successful call.
    pub after: Option<Call>,
    /// Returns the value the method returns, in place of `created`.
    pub created: Option<Call>,
    /// Builds the error of a failed call from `r`, in place of `Error::Vk(r)`.
    pub error: Option<Call>,
    /// Builds the scope of the implicit-rule checks (what is enabled
    /// where the call runs), in place of the receiver's: a creation's checks see what
    /// it enables.
    pub scope: Option<Call>,
    /// What the created object keeps alive of what its create info names.
    pub keeps: Keeps,
    /// Optional parameters the method takes as required (C names): a sparse
    /// binding's fence is the one completion a host can see of it. (A submission
    /// without a fence is held by its queue until a later fence of that queue or an
    /// idle wait shows it complete.)
    pub required: &'static [&'static str],
    /// The rules the row settles.
    pub settles: &'static [(&'static str, How)],
    /// What a caller of the safe method promises, for a method that cannot check
    /// what its safety rests on: the method is `unsafe`, and this is its `# Safety`.
    pub contract: Option<&'static str>,
}

const NONE: Special = Special {
    command: "",
    check: None,
    check_last: None,
    hold: None,
    before: None,
    after: None,
    created: None,
    error: None,
    scope: None,
    keeps: Keeps::Reached,
    required: &[],
    settles: &[],
    contract: None,
};

const fn call(path: &'static str, args: &'static [&'static str]) -> Option<Call> {
    Some(Call {
        path,
        args,
        promise: None,
    })
}

const fn unsafe_call(
    path: &'static str,
    args: &'static [&'static str],
    promise: &'static str,
) -> Option<Call> {
    Some(Call {
        path,
        args,
        promise: Some(promise),
    })
}

const FENCE: &str =
    "checks the fence is unsignalled and not in use by a queue operation that may still be executing";
const CBS: &str = "checks each command buffer's lifecycle state, kept by the wrapper from its allocation, begin, end and submissions";
const SECONDARY: &str = "checked by the safe methods in every build (a secondary without SIMULTANEOUS_USE that is pending is refused), but no test breaks it yet: recording a pending secondary into another primary is refused (VUID-vkCmdExecuteCommands-pCommandBuffers-00091), so only a second submission of a SIMULTANEOUS_USE primary that executes it reaches the state, and the layer warns at that execution already";
const UNPROVEN_POOL_FAMILY: &str = "checked by the safe methods in every build (the pool's queue family, recorded at its creation and read at each begin, against the queue's), but no test breaks it: lavapipe has one queue family";
const UNPROVEN_PROTECTED_BUFFERS: &str = "checked by the safe methods in every build (the pool's protected flag, recorded at its creation, against the batch's VkProtectedSubmitInfo), but no test breaks it: lavapipe has no protectedMemory, so no pool is protected, and a protected batch is refused for its queue first";
const UNPROVEN_OTHER_QUEUE_EVENTS: &str = "checked by the safe methods in every build (the events each recording's set, reset and wait commands name, against those of the submissions to other queues not known complete), but no test breaks it: lavapipe's queue family has one queue";
const UNPROVEN_TIMELINE_DIFFERENCE: &str = "checked by the safe methods in every build (against the semaphore's possible values, from the value the host last saw to the largest signalled, and the values of its pending operations), but no test breaks it: lavapipe's maxTimelineSemaphoreValueDifference is the largest 64-bit value";
const TIMELINE_RISES: &str = "checks each timeline signal is above the largest value the semaphore was given (initial value, host signals, submitted signals, earlier batches of the call): a bound stricter than the rule's, as the order in which queues execute is not known";
const PROTECTED_QUEUE: &str = "checks a protected batch's queue was got with VK_DEVICE_QUEUE_CREATE_PROTECTED_BIT, which the device records";
const TIMELINE_VALUES: &str =
    "checks each batch gives one value per timeline semaphore it waits on or signals";
const LAYOUT: &str = "checks the layout named against the one the recording's earlier commands leave the subresources in, and, for subresources the recording has not touched before, at submission against the one the device's earlier submissions leave (the recorder follows every barrier, render pass and secondary that changes a layout, in the order the queue executes them)";
const PRESENTED: &str = "checks each index against the images acquired from the swapchain and not presented since, and the image's layout against the one the device's submissions so far leave it in (the recorder follows every command that changes a layout)";
const LAYOUT_PASS: &str = "checks each attachment's initial layout against the one the recording's earlier commands leave its view's subresources in, and, for subresources the recording has not touched before, at submission against the one the device's earlier submissions leave (the 1.3.239 layer reports the rule as UNASSIGNED-CoreValidation-DrawState-InvalidRenderpass, \"the render pass initial layout ... and the previous known layout of the attachment ... must match\")";
const UNPROVEN_CAPTURE: &str = "checked by the safe methods in every build (the slice against the device's descriptor-buffer capture data size), but no test breaks it: lavapipe 22.3 has no VK_EXT_descriptor_buffer";
const UNPROVEN_ACCELERATION: &str = "checked by the safe methods in every build (each build info's range array against its geometry count), but no test breaks it: lavapipe 22.3 has no VK_KHR_acceleration_structure";
const UNPROVEN_DISPLAY: &str = "checked by the safe methods in every build (the display's physical device against the device's), but no test breaks it: lavapipe enumerates no display";
const UNPROVEN_XCB: &str = "checked by the safe methods in every build (against the physical device's queue family count), but no test breaks it: the tests' windows are Xlib ones, and the Xlib query's check of the same count is the one the tests break";
const UNPROVEN_WAYLAND: &str = "checked by the safe methods in every build (against the physical device's queue family count), but no test breaks it: the tests have no Wayland compositor";
const UNPROVEN_SURFACE_SUPPORT: &str = "checked by the safe methods in every build (vkGetPhysicalDeviceSurfaceSupportKHR, asked once per swapchain and queue family), but no test breaks it: lavapipe's only queue family presents to every surface";
const GROUP_PRESENT: &str = "checks the chained struct's count and each device mask against its mode and the device group's present masks (read once with vkGetDeviceGroupPresentCapabilitiesKHR), against the mask its image was acquired with (every physical device for vkAcquireNextImageKHR), and the mode against the modes the swapchain was created with (the 1.3.239 layer does not check these rules on a device of one physical device: the error alone proves them)";
const COPY_REGION: &str = "checks each region against the image's type, format and texel blocks and the subresource it names, as the device recorded them at the image's creation";
const COPY_ROW_PITCH: &str = "checks each region's row length in bytes against 2^31-1 (the 1.3.239 layer does not check it: the error alone proves it)";
const COPY_OVERLAP: &str = "checks each region's bytes of the buffer against the whole binding of the image when both are bound to one memory, as the device recorded their bindings (the 1.3.239 layer does not check it: the error alone proves it)";
const COPY_SAME_AS_SIZE: &str = "checked by the safe methods in every build, by the check of the texel block size (pRegions-07273), whose condition it is for these formats and whose VUID the error names";
const COPY_SAME_AS_RANGES: &str = "checked by the safe methods in every build: the checks of the x, y and z ranges, which together are this rule and come first, name their own VUIDs";
const COPY_SAME_AS_Y: &str = "checked by the safe methods in every build: a 1D image is one texel high, so the check of the y range, which comes first, names its own VUID";
const COPY_SAME_AS_Z: &str = "checked by the safe methods in every build: the image is one texel deep, so the check of the z range, which comes first, names its own VUID";
const COPY_SAME_AS_LAYERS: &str = "checked by the safe methods in every build: a 3D image has one array layer, so the check of the layer range, which comes first, names its own VUID";
const COPY_BLOCK_DEPTH: &str = "checked by the safe methods in every build, but no test breaks it: no format of the emitted API has a texel block deeper than one texel";
const COPY_PLANES: &str = "checked by the safe methods in every build, but no test breaks it: no test copies a multi-planar image yet";
const COPY_FEATURES: &str = "checked by the safe methods in every build, but no test breaks it: an image whose format lacks the transfer feature cannot have the transfer usage the copy also needs";
const COPY_FAMILY: &str = "checked by the safe methods in every build, but no test breaks it: lavapipe's only queue family has graphics and compute and an image transfer granularity of one texel";
const COPY_PROTECTED: &str = "checked by the safe methods in every build, but no test breaks it: lavapipe has no protected memory";
const BARRIER: &str = "checks the barrier against the resource it names (its usage, format and sharing mode, as the device recorded them), the queue families it names, and the barrier's stages, access types and render pass instance";
const BARRIER_ALONE: &str = "checks the barrier against the resource it names and the queue families it names, as the device recorded them (the 1.3.239 layer does not check it: the error alone proves it)";
const BARRIER_ACCESS: &str = "checks each access type against the table of the stages that support it (the 1.3.239 layer names the rule by srcAccessMask-02815 or dstAccessMask-02816, the memory barriers' rules)";
const BARRIER_CONCURRENT: &str = "checked by the safe methods in every build, but no test breaks it: a concurrent resource needs two queue families, and lavapipe has one";
const BARRIER_PLANES: &str = "checked by the safe methods in every build, but no test breaks it: no test makes a disjoint multi-planar image yet";
const BARRIER_FAMILY: &str = "checked by the safe methods in every build (the specification's table of the stages each queue capability supports), but no test breaks it: lavapipe's only queue family supports every stage";
const PASS_BEGIN: &str = "checks the render area against the framebuffer's size, the clear values against the largest attachment the render pass clears, and each layout the render pass gives an attachment against the usage of the framebuffer's view, as the device recorded them";
const PASS_BEGIN_UNPROVEN: &str = "checked by the safe methods in every build, but no test breaks it: the framebuffer's creation already needs the usage each attachment's role in the render pass implies, and no test begins an instance of another render pass that gives the attachment these layouts";
const PASS_GROUP: &str = "checks the chained struct's device mask against the device's physical devices, its render areas' count, and each area against the framebuffer's size and the device's limits";
const PASS_GROUP_LIMIT: &str = "checks each device render area against the device's limits (an area past them is past every framebuffer, and the 1.3.239 layer names only that rule: the error alone proves this one)";
const PASS_GROUP_MASK: &str = "checked by the safe methods in every build, but no test breaks it: in a group of one physical device, the only valid masks are the initial mask";
const PASS_VIEWS: &str = "checks the views a chained VkRenderPassAttachmentBeginInfo gives against the imageless framebuffer's attachment image infos and the render pass's attachments, and the render pass against the one the framebuffer was created with (attachment formats and sample counts, each subpass's attachments and view mask), as the device recorded them";
const PASS_FORMATS: &str = "checks the view formats the view's image lists against the attachment image info's (an image that lists none is judged by its view's format alone, as the 1.3.239 layer judges it)";
const PASS_UNPROVEN: &str = "checked by the safe methods in every build, but no test breaks it yet";
const PASS_FAMILY: &str = "checked by the safe methods in every build (each dependency's stages against the pool's queue family), but no test breaks it: lavapipe's only queue family supports every stage";
const LAYOUT_BARRIER: &str = "checks the old layout against the one the recording's earlier commands leave the subresources in, and, for subresources the recording has not touched before, at submission against the one the device's earlier submissions leave; an acquire (a transfer from another queue family to the pool's) follows the new layout without needing the old one, which the release named and moved from";
const UNPROVEN: &str =
    "checked by the safe methods in every build, but no test breaks it yet, so the report does not count it";
const POOL_FAMILY: &str =
    "checks the family against the queue create infos the device recorded at its creation";
const QUEUE_INFOS: &str =
    "checks the family, flags and index against the queue create infos the device recorded at its creation";
const INSTANCE_INFO: &str = "checks each enabled extension's dependencies (vk.xml's `depends`, emitted as a table) against the enabled extensions and API version";
const INSTANCE_ALONE: &str = "checks the application's API version, and a chained messenger against the enabled extensions (proven by the error alone: the layer cannot speak through a messenger whose extension is off, and the 1.3.239 loader crashes once the layer has refused an API version below 1.0)";
const SUBPASS_SAMPLES: &str = "checks the pipeline's sample count, kept from its creation, against the first one bound in a subpass without attachments (kept from the render pass's creation), where the physical device lacks variableMultisampleRate (the 1.3.239 layer does not check it at the bind: proven by the error alone)";
const UNPROVEN_BLOCKS: &str = "checked by the safe methods in every build (the set layouts' inline uniform block bindings, per stage and in all, against the device's Vulkan 1.3 limits), but no test breaks it yet: the tests' device does not enable inlineUniformBlock";
const UNPROVEN_SPARSE: &str = "checked by the safe methods in every build, but no test breaks it: lavapipe has no sparse resources, so any sparse flag is refused for that first";
const UNPROVEN_SPARSE_SPACE: &str = "checked by the safe methods in every build (the memory of every live sparse buffer and image against sparseAddressSpaceSize, under a lock held until the new buffer is listed), but no test breaks it: lavapipe has no sparse resources, so any sparse flag is refused for that first";
const BUFFER_INFO: &str = "checks the concurrent queue families against the physical device's family count, and a capture address against the flags";
const BUFFER_ALONE: &str = "checks the size against the device's maxBufferSize, and the external handle types against what the physical device reports it can export for the buffer (the 1.3.239 layer checks neither: proven by the error alone)";
const MEMORY_KIND: &str = "checks what the allocation asked for (its dedicated object, exportable handle types and device address, kept from its allocation) against the object the bind gives it to";
const UNPROVEN_DEDICATED: &str = "checked by the safe methods in every build (VkMemoryDedicatedRequirements, queried at the bind, against the allocation's dedicated object), but no test breaks it: lavapipe requires no dedicated allocation";
const UNPROVEN_PROTECTED: &str = "checked by the safe methods in every build (the object's protected flag against its memory's type), but no test breaks it: lavapipe has no protected memory";
const NO_IMPORT: &str = "memory is imported only through structs of extensions tuff does not emit (VK_KHR_external_memory_fd and the like), which no safe allocate info can chain";
const SUBPASSES: &str = "checks the subpass against the render pass's subpass count, which the device records at its creation and the recorder follows (a refused end first records the remaining subpasses, so the driver sees a valid end of an unsubmittable buffer)";
const ACTIVE_QUERIES: &str = "checks the queries the recorder has begun and not ended, with the subpass each began in (a refused end of an instance first ends them, so the driver sees a valid end of an unsubmittable buffer)";
const ACTIVE_QUERIES_ALONE: &str = "checks the queries the recorder has begun and not ended, with the subpass each began in (the 1.3.239 layer does not check it: proven by the error alone; a refused end of an instance first ends them, so the driver sees a valid end of an unsubmittable buffer)";
const UNPROVEN_QUERIES: &str = "checked by the safe methods in every build, as the tested render-pass and query commands are (the recorder's subpass and active queries), but no test breaks it through this command yet";
const QUERY_POOL: &str =
    "checks the query against the pool's type and count, kept from its creation";
const IN_RENDER_PASS: &str = "the method exists only on a recorder inside a render pass begun with `begin_render_pass` (its state type), not dynamic rendering nor a continuing secondary";
const IN_RENDERING: &str = "the method exists only on a recorder inside dynamic rendering it began itself (its state type)";
const RECORDING: &str =
    "`Recorder::end` exists only on a recorder, which only `CommandBuffer::begin` makes";
const OUTSIDE: &str = "`Recorder::end` exists only on a recorder outside a render pass instance, or on a continuing secondary";
const VERTEX_LIMITS: &str = "checks the bindings against maxVertexInputBindings and the strides against maxVertexInputBindingStride, read once";
const UNPROVEN_UAB: &str = "checked by the safe methods in every build (the layouts' and the pool's create flags are kept from their creation), but no test breaks it: lavapipe 22.3 has no update-after-bind descriptors";
const UNPROVEN_VARIABLE: &str = "checked by the safe methods in every build (the variable-count binding is kept from the layout's creation, and each set's writes are checked against the count it was allocated with), but no test breaks it: lavapipe 22.3 has no variable descriptor counts";
const DEVICE_ONLY: &str =
    "checks the event was not created device-only, which the device records at its creation";
const LAZY: &str = "checks the memory's type, kept from its allocation, is lazily allocated";
const SAMPLE_COUNTS: &str = "checks the sample count against the format's sample counts for the type, usage and tiling, queried from the physical device (the 1.3.239 layer does not check it: proven by the error alone)";
const PLANES: &str = "checks a chained plane info against the image's create flags and format, kept from its creation";
const QUERY_RANGE: &str = "checks the queries against the pool's count, kept from its creation";
const INDEX_ALIGNED: &str = "checks the offset plus the buffer's offset in its memory (kept from the bind) is a multiple of the index size; allocations start aligned for any resource";
const STATISTICS: &str = "checks the statistics bits against those the API defines (the 1.3.239 layer does not check it: proven by the error alone)";
const PRIVATE_TYPE: &str = "refuses an object type of the instance level (the 1.3.239 layer does not check it, and lavapipe crashes on it: proven by the error alone)";
const MERGE_SELF: &str = "checks the destination cache is none of the sources";
const EXPORTABLE: &str = "checks each handle type is exportable and the set compatible, as the physical device's external properties report (the 1.3.239 layer does not check it: proven by the error alone)";
const NO_SURFACE: &str = "refuses a query without a surface (only VK_GOOGLE_surfaceless_query, which tuff does not emit, allows one)";
const FAMILY_COUNT: &str = "checks the family against the physical device's queue family count";
const UNPROVEN_DISJOINT: &str = "checked by the safe methods in every build (the image's create flags are kept from its creation), but no test breaks it yet: lavapipe has no format that supports disjoint planes";
const UNPROVEN_WIN32: &str = "checked by the safe methods in every build (against the physical device's queue family count), but no test breaks it: the tests run on Linux";
const UNPROVEN_SURFACE: &str = "checked by the safe methods in every build (a query of each queue family's support), but no test breaks it: every lavapipe queue family presents to every X11 surface";
const UNPROVEN_FAMILY: &str = "checked by the safe methods in every build (against the pool's queue family flags), but no test breaks it: lavapipe's one queue family supports graphics and compute";
const POOL_PROTECTED: &str =
    "checks the protectedMemory feature the device recorded at its creation";
const SEMAPHORE_TYPE: &str = "checks the semaphore's type, kept by the wrapper from its creation";
const COPY_RANGE: &str = "checks each region against the buffers' sizes, kept from their creation";
const QUERIES: &str = "checks the queries against the pool's count, type and statistics, kept from its creation, and that `data` holds every result at its stride";
const PUSH: &str = "checks the range against the layout's push-constant ranges, kept from its creation, its alignment and the device's maxPushConstantsSize";
const LIVE_OBJECT: &str =
    "checks the handle is the device or a live object of it of that type, which the device lists";
const NAMED_OBJECT: &str = "checks the handle is a live object of that type: the device, its instance or physical device, or an object the device lists (the `_unchecked` twin checks it too, as it finds the object's lock so: proven by the error alone)";
const NO_SUSPENSION: &str = "checked by the safe methods in every build: the safe `begin_rendering` refuses the SUSPENDING and RESUMING flags (tuff does not follow suspended render pass instances across commands and command buffers yet), so no recording made through the safe methods holds a suspended or resumed instance";
const IMAGE_INFO_WRAPPERS: &str = "a descriptor image info takes its sampler and image view as wrappers or none, so each is a valid handle or null";
const IMAGE_INFO_SAMPLER: &str = "refuses a SAMPLER or COMBINED_IMAGE_SAMPLER write into a binding without immutable samplers whose image info has no sampler";
const IMAGE_INFO_VIEW: &str = "refuses a write of an image descriptor type other than SAMPLER whose image info has no image view (the nullDescriptor feature is not followed: a null view is refused even where it is enabled)";
const TEXEL_VIEW_WRAPPERS: &str =
    "texel buffer views are taken as a slice of wrappers, which always hold valid handles";
const OTHER_DEVICE_DESCRIPTOR: &str = "checks each object a descriptor names is one the device recorded (the 1.3.239 layer names the structs' commonparent rule, or for a sampler its validity rule, which the same handle breaks)";
const OTHER_DEVICE_BUFFER_DESCRIPTOR: &str = "checks each buffer a descriptor names is one the device recorded (the 1.3.239 layer crashes looking up a buffer of another device: proven by the error alone)";
const NULL_DESCRIPTOR: &str =
    "refuses a null buffer: the emitted API has no nullDescriptor feature";
const BUFFER_DESCRIPTOR: &str = "checks each buffer descriptor's buffer (recorded usage, size and binding; for a texel buffer view, its buffer's usage) and its offset and range against the device's limits";
const IMAGE_DESCRIPTOR: &str = "checks each image descriptor's view (its recorded type, aspects, usage and swizzle, and its image's type) and the layout against the lists its descriptor type allows";
const BOTH_ASPECTS: &str = "checks a view of a depth/stencil image names one of its aspects (the 1.3.239 layer reports it as UNASSIGNED-CoreValidation-DrawState-InvalidImageView, both aspects set)";
const AFTER_BIND_POOLS: &str = "checks the two sets' pools were created alike with or without UPDATE_AFTER_BIND (recorded at each set's allocation)";
const UNPROVEN_INLINE_COPIES: &str = "checked by the safe methods in every build (an inline uniform block's offset and size against 4), but no test breaks it: the safe copy takes its count as a number, and no test has two inline uniform block bindings to copy between yet";
const UNPROVEN_STORAGE_RANGE: &str = "checked by the safe methods in every build (the range against maxStorageBufferRange), but no test breaks it: lavapipe's limit is larger than a test can allocate";
const UNPROVEN_PLANE_SAMPLER: &str = "checked by the safe methods in every build (the image's recorded format and flags, the view's aspect), but no test breaks it: lavapipe 22.3 supports no multi-planar format";
const UNPROVEN_AFTER_BIND_LAYOUTS: &str = "checked by the safe methods in every build (the layouts' UPDATE_AFTER_BIND_POOL flags, recorded at their creation), but no test breaks it: lavapipe 22.3 offers update-after-bind for no descriptor type";
const SET_BINDINGS: &str = "checks the binding, type and array elements against the set's layout, kept from its creation, consecutive bindings included";
const VIEWPORTS: &str =
    "checks the first index plus the count against the device's maxViewports, read once";
const MULTI_VIEWPORT: &str = "checks one viewport or scissor, the first, unless the device was created with the multiViewport feature, which it remembers";
const SCISSORS: &str = "checks each scissor's offset is not negative and its ends do not overflow";
/// Chains the registry allows but the safe structs refuse (no `Extends` between
/// them), each with why.
pub const UNCHAINED: &[(&str, &str, &str)] = &[(
    "VkShaderModuleCreateInfo",
    "VkPipelineShaderStageCreateInfo",
    "it carries shader code, which enters only through the unsafe `create_shader_module` and its shader promise",
)];

/// Handle members the registry does not mark optional that the safe structs take as
/// `Option` all the same, each with why: Vulkan ignores them for some uses of the
/// struct, and the checks of the commands that take it refuse a null one where it
/// is read.
pub const NULLABLE: &[(&str, &str, &str)] = &[
    (
        "VkDescriptorImageInfo",
        "sampler",
        "read only for SAMPLER and COMBINED_IMAGE_SAMPLER descriptors without immutable samplers; `update_descriptor_sets` refuses a null one there (VUID-VkWriteDescriptorSet-descriptorType-00325)",
    ),
    (
        "VkDescriptorImageInfo",
        "imageView",
        "not read for SAMPLER descriptors; `update_descriptor_sets` refuses a null one for every other image type (VUID-VkWriteDescriptorSet-descriptorType-02997, -07683)",
    ),
];

/// Whether the safe structs take member `member` of `ty` as `Option` although the
/// registry does not mark it optional ([`NULLABLE`]).
pub fn nullable(ty: &str, member: &str) -> bool {
    NULLABLE.iter().any(|(t, m, _)| *t == ty && *m == member)
}

/// Whether the safe structs refuse to chain `ext` into `head`.
pub fn unchained(ext: &str, head: &str) -> bool {
    UNCHAINED.iter().any(|(e, h, _)| *e == ext && *h == head)
}

/// The shader promise: the one place where a program vouches for code tuff cannot
/// check, so that the pipelines and commands that run it can stay safe.
pub const SHADER_CONTRACT: &str = "The code is SPIR-V that every pipeline and command running it relies on, and that tuff cannot check beyond its interface. The caller promises that it is valid SPIR-V for the Vulkan environment (the validation rules of the SPIR-V environment appendix, and those of each stage it is used for), as it stands and under every specialization the program's pipelines give its specialization constants; that it declares only capabilities, extensions and features the device has enabled, and stays within the device's limits on what it declares (interface locations and components, workgroup size and memory) and lays out its blocks as the features it has enabled allow; that every invocation of it terminates; that a vertex, tessellation or geometry shader that writes Layer or ViewportIndex writes the same value for every vertex of a primitive, and a fragment shader that writes FragDepth on one path writes it (or discards) on every path that is not a helper invocation's; and that every invocation reads and writes only inside the resources it is given: its descriptors' ranges and images (of a binding created with `PARTIALLY_BOUND`, only descriptors that were written), its push-constant block, its workgroup and private memory (where the device has `robustBufferAccess` enabled, out-of-range buffer accesses are defined and need no promise). What tuff checks instead, when a pipeline is created: each resource variable the module declares has a binding of a descriptor type that can back it, visible to the stage, and its push constants a range that covers them; when a draw or dispatch is recorded: every descriptor of the bindings its variables read was written (but for `PARTIALLY_BOUND` bindings), and each image view there has the view type and numeric format its image variable reads.";
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
const CHAINED_COUNT: &str =
    "checks the chained struct's count against the count of the struct it extends";
const RENDER_PASS_INDICES: &str =
    "checks each attachment, subpass and input attachment index against the render pass's counts";
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
const UNPROVEN_PROTECTED_QUEUES: &str = "checked by the safe methods in every build (against the physical device's queue families), but no test breaks it: lavapipe has no protected queues, and a family is named twice only as protected and unprotected queues, so protectedMemory is refused first";
const UNPROVEN_INLINE_AFTER_BIND: &str = "checked by the safe methods in every build, but no test breaks it: the tests' only device with inlineUniformBlock enables every feature lavapipe has, update-after-bind of inline uniform blocks included";
const IMAGE_EXTERNAL: &str = "checks each external handle type against the external memory properties the physical device reports for the image's parameters and that type (the 1.3.239 layer does not check it: proven by the error alone)";
const IMAGE_CHROMA: &str = "checks a format that needs a sampler Y'CbCr conversion (vk.xml's `chroma`) against the image's levels, samples, type and extent, and a disjoint multi-planar image against the format's features";
const IMAGE_OF_SWAPCHAIN: &str = "checks the image's parameters against the implied image creation parameters of the swapchain, recorded at its creation (the 1.3.239 layer does not check it: proven by the error alone)";
const UNPROVEN_SPARSE_IMAGES: &str = "checked by the safe methods in every build (flags against each other, and the memory of every live sparse buffer and image against sparseAddressSpaceSize, under a lock held until the new image is listed), but no test breaks it: lavapipe 22.3 has no sparseBinding, so a sparse image is refused for the missing feature first";
const IMAGE_RULES: &str = "checks the type, extent, flags, usage and format against each other, the attachment limits, the queue families, the device's physical devices, and a chained stencil usage, format list or external memory struct (before the checks that ask the physical device about the image)";
const STAGE_BITS: &str = "checks the stages are of the emitted API (the graphics stages and compute) or VK_SHADER_STAGE_ALL (the 1.3.239 layer does not check bits no extension defines: proven by the error alone)";
const IMMUTABLE_SAMPLERS: &str = "the safe binding's `immutable_samplers` setter stores the sampler wrappers with their count as descriptorCount, and `descriptor_count` clears them when it sets another count";
const UNPROVEN_AFTER_BIND: &str = "checked by the safe methods in every build, but no test breaks it: lavapipe 22.3 has no update-after-bind descriptors, so a binding updated after bind is refused for the missing feature first";
const UNPROVEN_VARIABLE_COUNT: &str = "checked by the safe methods in every build, but no test breaks it: lavapipe 22.3 has no variable descriptor counts, so a variable-sized binding is refused for the missing feature first";
const DEVICE_QUEUES: &str = "checks the queue create infos against the physical device's queue families (index, count, protected capability), the priorities' range, each family named once, and the chain's feature structs against each other (features that come in pairs included) and against pEnabledFeatures";
const SURFACE_REPORTS: &str = "checks the create info against what the physical device reports for the surface (support from a queue family of the device, capabilities, formats, present modes) and for the swapchain's implied images, its queue families, and the device's physical-device count";
const UNPROVEN_SWAPCHAIN_SURFACE: &str = "checked by the safe methods in every build (against what the physical device reports for the surface and the swapchain's images), but no test breaks it: lavapipe's X11 surface is supported by its only queue family, has no maximum image count, offers every present mode the emitted API defines, and supports the images of every create info the other checks let through";
const RETIRED_SWAPCHAIN: &str = "checks oldSwapchain presents to the same surface and was not retired: the device records each swapchain's surface, and a creation retires its oldSwapchain before the call, whether or not it succeeds";
const BINARY_SIGNALED: &str = "checks the binary semaphore's state, as for a wait: a signal needs it unsignaled, or waited on earlier on the same queue (the 1.3.239 layer reports the rule as UNASSIGNED-CoreValidation-DrawState-QueueForwardProgress, \"signaled ... but has not since been waited on\")";
const SAME_AS_03238: &str = "checked by the safe methods in every build, by the check of VUID-vkQueueSubmit-pWaitSemaphores-03238, whose condition it shares for binary semaphores and whose VUID the error names (a timeline semaphore may be waited on before its signal is submitted, as the timeline rules allow)";
const SAME_AS_03268: &str = "checked by the safe methods in every build, by the check of VUID-vkQueuePresentKHR-pWaitSemaphores-03268, whose condition it shares and whose VUID the error names (a presentation waits only on binary semaphores: 03267)";
const ONE_WAITER: &str = "checked by the safe methods in every build: a wait leaves the semaphore waited on, so a second wait before another signal is refused as a wait on an unsignaled semaphore, which is the rule the error names";
const UNPROVEN_BINARY: &str = "checked by the safe methods in every build (the binary semaphore's state, as for vkQueueSubmit), but no test breaks it through this command";
const SET_LAYOUTS_MATCH: &str = "checks each set's layout, recorded at its allocation, is the pipeline layout's layout at that set number or identically defined (bindings, their types, counts, stages, flags and immutable samplers, and the layout's flags, all recorded at creation)";
const BIND_POINT_FAMILY: &str = "checked by the safe methods in every build (the bind point against the queue flags of the pool's family, recorded when the pool was created), but no test breaks it: lavapipe's only queue family has graphics and compute";
const DYNAMIC_OFFSETS: &str = "checks each dynamic offset, in the order of sets, bindings and elements, against the alignment limit of its descriptor's type";
const DYNAMIC_RANGES: &str = "checks each dynamic offset against the offset and range its descriptor was written with and its buffer's size (the device records them from every write, copy and template update of a dynamic buffer descriptor)";
const ATTACHMENT_DESCRIPTIONS: &str = "checks each attachment's format and layouts, a depth/stencil reference's layout, and a chained input-attachment-aspect struct's aspects against the attachments' formats";
const FIRST_USE: &str = "checks the layout of each attachment's first use (the first subpass that references it) against its load operations";
const DEPENDENCIES: &str = "checks each dependency's subpasses, its stage masks against the stages of a graphics pipeline and the synchronization2 feature, its access masks against the accesses each stage supports (the specification's table, checked in as hooks/stages.rs: the pinned registry has no <sync> block), and a self-dependency's framebuffer-space stages against BY_REGION";
const MULTIVIEW_MASKS: &str = "checks a chained VkRenderPassMultiviewCreateInfo's view masks against the multiview feature and maxMultiviewViewCount, its correlation masks against each other, its view offsets against the dependencies, and multi-view self-dependencies against VIEW_LOCAL";
const UNPROVEN_VIEW_PLANES: &str = "checked by the safe methods in every build (against the image's format, its planes and chroma from vk.xml's <formats>, and a chained conversion's recorded format), but no test breaks it: lavapipe 22.3 supports no multi-planar or Y'CbCr format";
const UNPROVEN_SPARSE_VIEW: &str = "checked by the safe methods in every build (the image's recorded flags), but no test breaks it: lavapipe 22.3 has no sparseBinding";
const UNPROVEN_CUBE_ARRAY: &str = "checked by the safe methods in every build (the layers left from the base layer), but no test breaks it: the tests' device does not enable imageCubeArray, so a cube array view is refused for the feature first";
const UNPROVEN_VIEW_FEATURES: &str = "checked by the safe methods in every build (the view's usage against the format features the physical device reports for the image's tiling), but no test breaks it: no compatible view format the tests found lacks the feature its usage needs on lavapipe where the image's own format has it";
const UNPROVEN_OTHER_DEVICE_VIEW: &str = "checked by the safe methods in every build (each view must be one the device recorded), but no test breaks it: a view of another device is refused by the common-parent check first";
const UNPROVEN_FRAMEBUFFER_ROLES: &str = "checked by the safe methods in every build (the roles the render pass's subpasses give each attachment, recorded at its creation), but no test breaks it: the framebuffer test's render pass has no input or depth/stencil resolve attachment";
const UNPROVEN_FRAMEBUFFER_MULTIVIEW: &str = "checked by the safe methods in every build (against the render pass's recorded view masks), but no test breaks it: the framebuffer test's device does not enable multiview";
const UNPROVEN_DEPTH_3D: &str = "checked by the safe methods in every build (the view's format and its image's recorded type), but no test breaks it: no depth/stencil format can make a 3D image";
const FRAMEBUFFER_ATTACHMENTS: &str = "checks each attachment (the view's recorded format, range, swizzle, derived usage and its image's samples and extent, or an imageless framebuffer's chained attachment info) against the roles the render pass's subpasses give it, its format and samples, the framebuffer's size and layers, and the view masks, all recorded at creation";
const VIEW_RANGE: &str = "checks the subresource range's aspects, levels and layers against the image's type, flags, extent and layer count, recorded at its creation";
const VIEW_TYPE: &str = "checks the view type against the image's type, flags, usage and sample count, recorded at its creation";
const VIEW_FORMAT: &str = "checks the view's format against the image's (its compatibility class, block size, plane formats and listed view formats, recorded at its creation, from vk.xml's <formats>), its chroma against the image's extent, and a chained Y'CbCr conversion's format and the swizzle";
const VIEW_USAGE: &str = "checks the view's usage (chained, or the image's or its stencil usage, as the specification derives it) against the image's and against the format features the physical device reports for the image's tiling";
const WAIT_STAGES: &str = "checks each wait stage mask: no host stage, no geometry or tessellation stage without its feature, not 0 without synchronization2, and each stage one the queue's capabilities (its family's flags, recorded when it was got) support";
const UNPROVEN_QUEUE_STAGES: &str = "checked by the safe methods in every build (each stage against the queue family's flags and the specification's table of supported stages), but no test breaks it: lavapipe's only queue family supports every stage";
const GROUP_INDICES: &str = "checks a chained device group info's device indices and masks against the device's physical-device count, recorded at its creation";
const ACQUIRE_SIGNALS: &str = "checks the acquire has a semaphore or a fence to signal";
const RETIRED_ACQUIRE: &str = "checks the swapchain was not retired: the device records a swapchain as retired when a creation names it as oldSwapchain";
const BINARY_STATE: &str = "checks the binary semaphore's state, which the device follows through every command that signals or waits on one (queue submissions, sparse binds, acquires, presentations): a wait needs a signal submitted and not waited on since, a signal needs it unsignaled, or waited on earlier on the same queue, and a wait is pending until the operation that waits is known complete";
const FORWARD_PROGRESS: &str = "checks an infinite timeout against the swapchain's acquired images (the device records each acquire and presentation), its image count and the surface's minImageCount";
const DEVICE_EXTENSIONS: &str = "checks each enabled extension's dependencies (vk.xml's `depends`) against the extensions of the device and its instance and the API version";
const DEVICE_GROUP: &str = "checks a chained device group create info names each physical device once, the one the device is created from among them, all in one group that the instance enumerates";
const UNPROVEN_DEVICE_GROUP: &str = "checked by the safe methods in every build, but no test breaks it: lavapipe has one physical device, the only member of its only device group";
const DEVICE_MASK: &str = "checks the mask is not zero and names only the physical devices the device was created with (a chained device group create info's count, recorded at creation)";
const UNPROVEN_ALLOCATION_COUNT: &str = "checked by the safe methods in every build (the live allocations the device lists against maxMemoryAllocationCount, under a lock held until the new memory is listed), but no test breaks it: lavapipe allows 4,294,967,295 allocations";
const UNPROVEN_PROTECTED_TYPE: &str = "checked by the safe methods in every build (the memory type's flags against protectedMemory), but no test breaks it: lavapipe has no protected memory type";
const UNPROVEN_SPARSE_DEDICATED: &str = "checked by the safe methods in every build (the object's recorded creation flags), but no test breaks it: lavapipe 22.3 has no sparseBinding, so no sparse object can be named";
const UNPROVEN_DISJOINT_DEDICATED: &str = "checked by the safe methods in every build (the image's recorded creation flags), but no test breaks it: the tests make no disjoint image";
const DEDICATED: &str = "checks the dedicated image or buffer against its recorded creation flags (not sparse, not disjoint), one of the two named, and the allocation size against its memory requirements";
const EXPORT: &str = "checks the exported handle types against the external memory properties the physical device reports for the dedicated image or buffer (exportable, compatible with each other); an export without a dedicated object is refused (`Error::Misuse`)";
const MEMORY_TYPES: &str = "checks the memory type index and the size against the physical device's memory types and heaps, a protected type against protectedMemory, and the chained allocation flags and capture address against the device's bufferDeviceAddress features";
const LAYOUT_BINDINGS: &str = "checks the bindings against each other (each number once), input attachments' stages, inline uniform blocks against maxInlineUniformBlockSize, and a chained binding-flags struct's count and flags against the device's descriptor-indexing features";
const SAMPLER_MODES: &str = "checks the filters, address modes and a chained reduction mode together, against the device's samplerMirrorClampToEdge and samplerFilterMinmax features";
const SUBPASS_REFERENCES: &str = "checks what each subpass references against the render pass's attachments (formats, their format features as the physical device reports them, sample counts, layouts) and its view masks against each other and maxMultiviewViewCount (the 1.3.239 layer does not check that an attachment keeps one layout within a subpass: that rule is proven by the error alone)";
const UNPROVEN_RESOLVE_FEATURES: &str = "checked by the safe methods in every build, but no test breaks it: a resolve attachment has its color attachment's format, whose features a color attachment needs as well, so a format without them is refused for the color attachment first";
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
const BIND_POINT: &str =
    "checks the pipeline was created for the bind point, which the device remembers";
const FULL_CHAIN: &str = "checks the level count against the levels of a full chain for the extent";
const IMAGE_LIMITS: &str = "checks the create info against its Image Creation Limits, queried from the physical device for its format, type, tiling, usage and flags (with a chained format list, stencil usage and each external handle type, intersected)";
const LAYOUT_LIMITS: &str = "checks the set layouts' recorded bindings, counted per kind in each stage and across all stages, against the device's limits (the update-after-bind ones from its Vulkan 1.2 properties), the set count against maxBoundDescriptorSets, and the push-constant ranges for a stage named twice";
const BIND_BOUND: &str = "refuses an object the device recorded as bound (and one an earlier info of the same call binds)";
const BIND_MEMORY: &str = "checks the memory's recorded size and type against the object's memory requirements, read from the driver at the bind";
const VERTEX_BOUND: &str = "checks a vertex buffer is bound at every binding that an attribute the vertex shader reads comes from (the pipeline records them from its vertex input state and the shader's input locations; the recorder tracks the bindings bound)";
const BUFFER_IMAGE_RANGE: &str = "checks each region's bytes, by Buffer and Image Addressing over the image's recorded format (the texel block of the region's aspect, from the registry's formats), lie inside the buffer's recorded size";
const INDEX_BOUND: &str = "checks an index buffer is bound, which the recorder tracks";
const INDEX_RANGE: &str = "checks the indices the draw reads lie inside the bound index buffer (whatever robustBufferAccess2 says, which is not tracked)";
const RANGE: &str = "checks the offsets and sizes against the buffer's size, kept from its creation, and their alignment";
const BUFFER_USE: &str = "checks the buffer's usage, kept from its creation, and that memory is bound to it (or it is sparse)";
const WHOLE: &str = "`DeviceMemory::map` maps the whole memory: offset 0, size VK_WHOLE_SIZE";

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
const COMPUTE_NO_DYNAMIC: &str = "a compute pipeline has no dynamic state (VkComputePipelineCreateInfo has no pDynamicState), so a dispatch's pipeline requires none to be set";
const SAMPLER_LINEAR: &str = "checks, once per change of the bound state, each image view the bound sets hold at a binding whose variable the pipeline's modules sample, against the samplers that may sample it (a combined image sampler's own and its binding's immutable ones; for a separate image, every sampler the modules declare, as which sampler an OpSampledImage pairs with which image is not followed): with a LINEAR filter or mipmap mode (and no depth comparison), the view's format features (VkFormatProperties3, for its image's tiling) must have SAMPLED_IMAGE_FILTER_LINEAR; samplers record their filters when they are made";
const SAMPLER_UNNORMALIZED: &str = "checks, once per change of the bound state, each image view the bound sets hold at a binding whose variable the pipeline's modules sample, against the samplers that may sample it (as for the linear filter rule): with unnormalized coordinates, a view of type 1D or 2D only, and no OpImageSample instruction with ImplicitLod, Dref or Proj, LOD bias or offset on the variable (read from the module's SPIR-V when it was made, followed from the variable as for atomics)";
const UNPROVEN_DISPATCH_SAMPLERS: &str = "checked by the safe methods in every build (the samplers that may sample each image view the bound sets hold, as for a draw's rules of the same text, which the draw tests break), but no dispatch test breaks it yet";
const UNPROVEN_UNNORMALIZED_VIEW: &str = "checked by the safe methods in every build (each image view a sampler with unnormalized coordinates may sample, as for None-02703, against the 1D and 2D view types), but no test breaks it yet: the tests' sampled views are 2D";
const UNPROVEN_TEXEL_COMPONENTS: &str = "checked by the safe methods in every build (each image or texel buffer view at a binding whose variable the pipeline's modules write with OpImageWrite, against the fewest components of the texels written, read from the module's SPIR-V), but no test breaks it: GLSL's imageStore always writes four components, and the test shaders are GLSL";
const UNPROVEN_TEXEL_WITHOUT_FORMAT: &str = "checked by the safe methods in every build (each texel buffer view at a binding whose storage texel buffer variable has the Unknown format and that the pipeline's modules write or read, against its format's VkFormatProperties3 buffer features), but no test breaks it: lavapipe reads and writes every storage texel buffer format without a format";
const UNPROVEN_YCBCR: &str = "checked by the safe methods in every build (an image view made with a sampler Y'CbCr conversion, or sampled by a sampler made with one, against the instructions the pipeline's modules use on its variable: sampling only, without ConstOffset or Offset), but no test breaks it: lavapipe has no samplerYcbcrConversion";
const UNPROVEN_INPUT_WRITTEN: &str = "checked by the safe methods in every build (the check of None-02699: every descriptor of a binding an input attachment variable of the pipeline's modules declares was written when the set was bound), but no test breaks it apart from that rule";
const UNPROVEN_INPUT_ATTACHMENTS: &str = "checked by the safe methods in every build (once per change of the bound state, each input attachment variable's InputAttachmentIndex, read from the module's SPIR-V, against the current subpass's input attachment references, kept from the render pass's creation, and its descriptor's view against that attachment's format and the framebuffer's image; in dynamic rendering no input attachment is valid), but no test breaks it yet";
const ATTACHMENT_MEMORY: &str = "checked by the safe methods in every build (once per change of the bound state, the memory each descriptor the pipeline's modules declare reaches (an image view's image, a texel buffer view's or buffer descriptor's buffer, where each is bound) against the memory of the current subpass's attachments (the framebuffer's views' images, or the dynamic rendering's views' and resolve views'): a descriptor the shader may write (a storage buffer, or a storage image or texel buffer it writes or uses atomically) names the first rule, any other the second, as which commands of the subpass write each attachment is not followed; in a secondary continuing an instance whose attachments are not known, a draw whose shaders declare such a descriptor is refused), but no test proves it against the layer: an attachment in a render pass instance is in an attachment layout, so a descriptor that reaches it breaks VkDescriptorImageInfo-imageLayout-00344 too, which the 1.3.239 layer names instead";
const UNPROVEN_ATTACHMENT_READ_BEFORE: &str = "checked by the safe methods in every build: no safe draw reads or writes an attachment's memory other than as an attachment (None-06537 and None-06538 refuse it), so no command of the subpass reads it before a draw writes it as an attachment; no test breaks it apart from those rules";
const UNPROVEN_BLEND: &str = "checked by the safe methods in every build (once per change of the bound state, unless rasterization is discarded, the color attachments the bound pipeline blends into, recorded at its creation, against the features of the instance's color formats, optimal tiling and linear where an attachment image is linear or the attachments are not known), but no test breaks it: the pipeline's creation refuses the same blending for its render pass or rendering formats first";

/// The `DrawRules` of a draw command, as the Rust expression its hooks take: a
/// reference to a constant, so a draw passes a pointer rather than building the
/// struct.
macro_rules! draw_rules {
    ($command:literal, $protected:literal) => {
        concat!(
            "{ const RULES: crate::hooks::DrawRules = crate::hooks::DrawRules { render_pass: \"VUID-",
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
            "named: [(crate::hooks::NAMED_STATES[0], \"VUID-",
            $command,
            "-primitiveTopology-03420\"), ",
            "(crate::hooks::NAMED_STATES[1], \"VUID-",
            $command,
            "-pStrides-04884\"), ",
            "(crate::hooks::NAMED_STATES[2], \"VUID-",
            $command,
            "-None-04876\"), ",
            "(crate::hooks::NAMED_STATES[3], \"VUID-",
            $command,
            "-None-04877\"), ",
            "(crate::hooks::NAMED_STATES[4], \"VUID-",
            $command,
            "-None-04879\")], ",
            "rendering: [\"VUID-",
            $command,
            "-viewMask-06178\", ",
            "\"VUID-",
            $command,
            "-colorAttachmentCount-06179\", ",
            "\"VUID-",
            $command,
            "-colorAttachmentCount-06180\", ",
            "\"VUID-",
            $command,
            "-colorAttachmentCount-07616\", ",
            "\"VUID-",
            $command,
            "-pDepthAttachment-06181\", ",
            "\"VUID-",
            $command,
            "-pDepthAttachment-07617\", ",
            "\"VUID-",
            $command,
            "-pStencilAttachment-06182\", ",
            "\"VUID-",
            $command,
            "-pStencilAttachment-07618\"], read_only: [\"VUID-",
            $command,
            "-None-06886\", \"VUID-",
            $command,
            "-None-06887\", \"VUID-",
            $command,
            "-imageView-06172\", \"VUID-",
            $command,
            "-imageView-06173\", \"VUID-",
            $command,
            "-imageView-06174\", \"VUID-",
            $command,
            "-imageView-06175\", \"VUID-",
            $command,
            "-imageView-06176\", \"VUID-",
            $command,
            "-imageView-06177\", \"VUID-",
            $command,
            "-rasterizationSamples-04740\"], counts: [\"VUID-",
            $command,
            "-viewportCount-03417\", \"VUID-",
            $command,
            "-scissorCount-03418\", \"VUID-",
            $command,
            "-viewportCount-03419\"], attachments: [\"VUID-",
            $command,
            "-OpTypeImage-07468\", \"VUID-",
            $command,
            "-None-07469\", \"VUID-",
            $command,
            "-None-06537\", \"VUID-",
            $command,
            "-None-06538\", \"VUID-",
            $command,
            "-blendEnable-04727\"], shader: ",
            shader_rules!($command, $protected),
            " }; &RULES }"
        )
    };
}

/// The `ShaderRules` of a draw or dispatch command, as a Rust array expression.
macro_rules! shader_rules {
    ($command:literal, $protected:literal) => {
        concat!(
            "[\"VUID-",
            $command,
            "-viewType-07752\", \"VUID-",
            $command,
            "-format-07753\", \"VUID-",
            $command,
            "-None-02699\", \"VUID-",
            $command,
            "-maintenance4-06425\", \"VUID-",
            $command,
            "-None-02691\", \"VUID-",
            $command,
            "-None-06479\", \"VUID-",
            $command,
            "-OpTypeImage-07027\", \"VUID-",
            $command,
            "-OpTypeImage-07028\", \"VUID-",
            $command,
            "-commandBuffer-02707\", \"",
            $protected,
            "\", \"VUID-",
            $command,
            "-magFilter-04553\", \"VUID-",
            $command,
            "-mipmapMode-04770\", \"VUID-",
            $command,
            "-None-02702\", \"VUID-",
            $command,
            "-None-02703\", \"VUID-",
            $command,
            "-None-02704\", \"VUID-",
            $command,
            "-None-04115\", \"VUID-",
            $command,
            "-OpImageWrite-04469\", \"VUID-",
            $command,
            "-OpTypeImage-07029\", \"VUID-",
            $command,
            "-OpTypeImage-07030\", \"VUID-",
            $command,
            "-None-06550\", \"VUID-",
            $command,
            "-ConstOffset-06551\"]"
        )
    };
}

/// A draw or dispatch: a pipeline bound at its bind point, and a set bound at every
/// set number of its layout; for a draw, a vertex buffer bound at every binding its
/// vertex shader reads.
macro_rules! bound {
    ($command:literal, COMPUTE, $sets:expr, $protected:literal, [$($extra:expr),* $(,)?]) => {
        Special {
            command: $command,
            after: call(
                "hooks::descriptor_layouts_used",
                &["self", "vk::PipelineBindPoint::COMPUTE"],
            ),
            check: call(
                "hooks::dispatch_checks",
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
                "hooks::descriptor_layouts_used",
                &["self", "vk::PipelineBindPoint::GRAPHICS"],
            ),
            check: call(
                "hooks::draw_checks",
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
/// the indices it reads inside it (`range`, Rust for an `Option` the hook takes).
macro_rules! indexed {
    ($command:literal, $protected:literal, $range:literal, [$($settles:expr),* $(,)?]) => {
        Special {
            command: $command,
            after: call(
                "hooks::descriptor_layouts_used",
                &["self", "vk::PipelineBindPoint::GRAPHICS"],
            ),
            check: call(
                "hooks::indexed_draw_checks",
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
            (concat!("VUID-", $command, "-None-07469"), How::User(UNPROVEN_INPUT_ATTACHMENTS)),
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

/// A query of a surface's properties: the surface is one the physical device
/// supports (`-surface-06211`).
macro_rules! surface_query {
    ($command:literal) => {
        Special {
            command: $command,
            check_last: call(
                "hooks::surface_supported",
                &[
                    "self",
                    "surface",
                    concat!("\"VUID-", $command, "-surface-06211\""),
                    concat!("\"VUID-", $command, "-surface-06523\""),
                ],
            ),
            settles: &[
                (
                    concat!("VUID-", $command, "-surface-06211"),
                    How::User(UNPROVEN_SURFACE),
                ),
                (
                    concat!("VUID-", $command, "-surface-06523"),
                    How::Dynamic(NO_SURFACE),
                ),
            ],
            ..NONE
        }
    };
}

/// The recorded commands that leave unchanged everything a draw's or dispatch's
/// state checks read: the draws and dispatches themselves (which only add layouts a
/// later check of the same state finds met) and push constants (which only add
/// bytes set; a push with a layout of other ranges, which drops the earlier bytes,
/// clears the recorder's verified bits itself). After any other command the
/// recorder checks the next draw's or dispatch's state again; after these, a state
/// already checked is not.
pub const KEEPS_DRAW_STATE: &[&str] = &[
    "vkCmdDraw",
    "vkCmdDrawIndexed",
    "vkCmdDrawIndirect",
    "vkCmdDrawIndexedIndirect",
    "vkCmdDrawIndirectCount",
    "vkCmdDrawIndexedIndirectCount",
    "vkCmdDispatch",
    "vkCmdDispatchBase",
    "vkCmdDispatchIndirect",
    "vkCmdPushConstants",
];

/// Every special case, by command.
pub const SPECIALS: &[Special] = &[
    Special {
        command: "vkQueueSubmit",
        check: call("hooks::queue_submit_checks", &["self", "submits", "fence"]),
        hold: call("hooks::queue_submit_gate", &["self", "submits"]),
        after: call("hooks::queue_submit_done", &["self", "submits", "fence"]),
        settles: &[
            ("VUID-vkQueueSubmit-fence-00063", How::Dynamic(FENCE)),
            ("VUID-vkQueueSubmit-fence-00064", How::Dynamic(FENCE)),
            ("VUID-VkSubmitInfo-pCommandBuffers-00075", How::Dynamic(CBS)),
            ("VUID-vkQueueSubmit-pCommandBuffers-00070", How::Dynamic(CBS)),
            ("VUID-vkQueueSubmit-pCommandBuffers-00071", How::Dynamic(CBS)),
            ("VUID-vkQueueSubmit-pCommandBuffers-00072", How::Dynamic(CBS)),
            ("VUID-vkQueueSubmit-pCommandBuffers-00073", How::User(SECONDARY)),
            ("VUID-VkSubmitInfo-pWaitSemaphores-03239", How::Dynamic(TIMELINE_VALUES)),
            ("VUID-VkSubmitInfo-pNext-03240", How::Dynamic(TIMELINE_VALUES)),
            ("VUID-VkSubmitInfo-pNext-03241", How::Dynamic(TIMELINE_VALUES)),
            ("VUID-VkDeviceGroupSubmitInfo-waitSemaphoreCount-00082", How::Dynamic(CHAINED_COUNT)),
            ("VUID-VkDeviceGroupSubmitInfo-commandBufferCount-00083", How::Dynamic(CHAINED_COUNT)),
            ("VUID-VkDeviceGroupSubmitInfo-signalSemaphoreCount-00084", How::Dynamic(CHAINED_COUNT)),
            ("VUID-vkQueueSubmit-pWaitSemaphores-03238", How::Dynamic(BINARY_STATE)),
            ("VUID-VkSubmitInfo-pWaitDstStageMask-00078", How::Dynamic(WAIT_STAGES)),
            ("VUID-VkSubmitInfo-pWaitDstStageMask-04090", How::Dynamic(WAIT_STAGES)),
            ("VUID-VkSubmitInfo-pWaitDstStageMask-04091", How::Dynamic(WAIT_STAGES)),
            ("VUID-VkSubmitInfo-pWaitDstStageMask-03937", How::Dynamic(WAIT_STAGES)),
            ("VUID-vkQueueSubmit-pWaitDstStageMask-00066", How::User(UNPROVEN_QUEUE_STAGES)),
            ("VUID-VkDeviceGroupSubmitInfo-pWaitSemaphoreDeviceIndices-00085", How::Dynamic(GROUP_INDICES)),
            ("VUID-VkDeviceGroupSubmitInfo-pCommandBufferDeviceMasks-00086", How::Dynamic(GROUP_INDICES)),
            ("VUID-vkQueueSubmit-pSignalSemaphores-00067", How::Dynamic(BINARY_SIGNALED)),
            ("VUID-vkQueueSubmit-pWaitSemaphores-00069", How::User(SAME_AS_03238)),
            ("VUID-vkQueueSubmit-pWaitSemaphores-00068", How::User(ONE_WAITER)),
            ("VUID-vkQueueSubmit-pCommandBuffers-00074", How::User(UNPROVEN_POOL_FAMILY)),
            ("VUID-vkQueueSubmit-queue-06448", How::Dynamic(PROTECTED_QUEUE)),
            ("VUID-VkSubmitInfo-pNext-04120", How::User(UNPROVEN_PROTECTED_BUFFERS)),
            ("VUID-VkSubmitInfo-pNext-04148", How::User(UNPROVEN_PROTECTED_BUFFERS)),
            ("VUID-vkQueueSubmit-pCommandBuffers-00065", How::User(UNPROVEN_OTHER_QUEUE_EVENTS)),
            ("VUID-VkSubmitInfo-pSignalSemaphores-03242", How::Dynamic(TIMELINE_RISES)),
            ("VUID-VkSubmitInfo-pWaitSemaphores-03243", How::User(UNPROVEN_TIMELINE_DIFFERENCE)),
            ("VUID-VkSubmitInfo-pSignalSemaphores-03244", How::User(UNPROVEN_TIMELINE_DIFFERENCE)),
        ],
        ..NONE
    },
    Special {
        command: "vkQueueSubmit2",
        check: call("hooks::queue_submit2_checks", &["self", "submits", "fence"]),
        hold: call("hooks::queue_submit2_gate", &["self", "submits"]),
        after: call("hooks::queue_submit2_done", &["self", "submits", "fence"]),
        settles: &[
            ("VUID-vkQueueSubmit2-fence-04894", How::Dynamic(FENCE)),
            ("VUID-vkQueueSubmit2-fence-04895", How::Dynamic(FENCE)),
            ("VUID-VkCommandBufferSubmitInfo-commandBuffer-03890", How::Dynamic(CBS)),
            ("VUID-vkQueueSubmit2-commandBuffer-03874", How::Dynamic(CBS)),
            ("VUID-vkQueueSubmit2-commandBuffer-03875", How::Dynamic(CBS)),
            ("VUID-vkQueueSubmit2-commandBuffer-03876", How::Dynamic(CBS)),
            ("VUID-vkQueueSubmit2-commandBuffer-03877", How::User(SECONDARY)),
            ("VUID-vkQueueSubmit2-semaphore-03873", How::User(UNPROVEN_BINARY)),
            ("VUID-vkQueueSubmit2-semaphore-03868", How::User(UNPROVEN_BINARY)),
            ("VUID-vkQueueSubmit2-semaphore-03872", How::User(UNPROVEN_BINARY)),
            ("VUID-vkQueueSubmit2-semaphore-03871", How::User(ONE_WAITER)),
        ],
        ..NONE
    },
    Special {
        command: "vkQueueBindSparse",
        check: call("hooks::queue_bind_sparse_checks", &["self", "bind_info", "fence"]),
        hold: call("hooks::queue_bind_sparse_gate", &["self", "bind_info"]),
        after: call("hooks::queue_bind_sparse_done", &["self", "bind_info", "fence"]),
        required: &["fence"],
        settles: &[
            ("VUID-vkQueueBindSparse-fence-01113", How::Dynamic(FENCE)),
            ("VUID-vkQueueBindSparse-fence-01114", How::Dynamic(FENCE)),
            ("VUID-VkBindSparseInfo-pWaitSemaphores-03246", How::User(UNPROVEN)),
            ("VUID-VkBindSparseInfo-pNext-03247", How::User(UNPROVEN)),
            ("VUID-VkBindSparseInfo-pNext-03248", How::User(UNPROVEN)),
            ("VUID-vkQueueBindSparse-pWaitSemaphores-03245", How::User(UNPROVEN_BINARY)),
            ("VUID-vkQueueBindSparse-pWaitSemaphores-01117", How::User(UNPROVEN_BINARY)),
            ("VUID-vkQueueBindSparse-pSignalSemaphores-01115", How::User(UNPROVEN_BINARY)),
            ("VUID-vkQueueBindSparse-pWaitSemaphores-01116", How::User(ONE_WAITER)),
        ],
        ..NONE
    },
    Special {
        command: "vkResetFences",
        check: call("hooks::reset_fences_checks", &["self", "fences"]),
        settles: &[(
            "VUID-vkResetFences-pFences-01123",
            How::Dynamic("refuses a fence whose queue operation may still be executing (asks the fence when the wrappers have not seen it signalled)"),
        )],
        ..NONE
    },
    Special {
        command: "vkCmdExecuteCommands",
        check: call("hooks::cmd_execute_commands_checks", &["self", "command_buffers"]),
        before: call("hooks::cmd_execute_commands_before", &["self", "command_buffers"]),
        after: call("hooks::execute_layouts_done", &["self", "command_buffers"]),
        settles: &[(
            "VUID-vkCmdExecuteCommands-pCommandBuffers-00091",
            How::Dynamic("refuses a secondary without SIMULTANEOUS_USE that a submission may still be executing"),
        )],
        ..NONE
    },
    Special {
        command: "vkGetSemaphoreCounterValue",
        check: call("hooks::get_semaphore_counter_value_checks", &["self", "semaphore"]),
        after: call("hooks::semaphore_value_seen", &["self", "semaphore", "out"]),
        settles: &[(
            "VUID-vkGetSemaphoreCounterValue-semaphore-03255",
            How::Dynamic(SEMAPHORE_TYPE),
        )],
        ..NONE
    },
    Special {
        command: "vkWaitSemaphores",
        check: call("hooks::wait_semaphores_checks", &["self", "wait_info"]),
        after: call("hooks::wait_semaphores_done", &["self", "wait_info", "r"]),
        settles: &[(
            "VUID-VkSemaphoreWaitInfo-pSemaphores-03256",
            How::Dynamic(SEMAPHORE_TYPE),
        )],
        ..NONE
    },
    Special {
        command: "vkSignalSemaphore",
        check: call("hooks::signal_semaphore_checks", &["self", "signal_info"]),
        after: call("hooks::signal_semaphore_done", &["self", "signal_info"]),
        settles: &[(
            "VUID-VkSemaphoreSignalInfo-semaphore-03257",
            How::Dynamic(SEMAPHORE_TYPE),
        )],
        ..NONE
    },
    Special {
        command: "vkAcquireNextImageKHR",
        check: call(
            "hooks::acquire_next_image_khr_checks",
            &["self", "swapchain", "timeout", "semaphore", "fence"],
        ),
        after: call(
            "hooks::acquire_next_image_khr_done",
            &["self", "swapchain", "semaphore", "fence", "out", "r"],
        ),
        settles: &[
            ("VUID-vkAcquireNextImageKHR-semaphore-03265", How::Dynamic(SEMAPHORE_TYPE)),
            ("VUID-vkAcquireNextImageKHR-semaphore-01780", How::Dynamic(ACQUIRE_SIGNALS)),
            ("VUID-vkAcquireNextImageKHR-swapchain-01285", How::Dynamic(RETIRED_ACQUIRE)),
            ("VUID-vkAcquireNextImageKHR-semaphore-01286", How::Dynamic(BINARY_STATE)),
            ("VUID-vkAcquireNextImageKHR-semaphore-01779", How::Dynamic(BINARY_STATE)),
            ("VUID-vkAcquireNextImageKHR-fence-01287", How::Dynamic(FENCE)),
            ("VUID-vkAcquireNextImageKHR-surface-07783", How::Dynamic(FORWARD_PROGRESS)),
        ],
        ..NONE
    },
    Special {
        command: "vkAcquireNextImage2KHR",
        check: call("hooks::acquire_next_image2_khr_checks", &["self", "acquire_info"]),
        after: call(
            "hooks::acquire_next_image2_khr_done",
            &["self", "acquire_info", "out", "r"],
        ),
        settles: &[
            ("VUID-VkAcquireNextImageInfoKHR-semaphore-03266", How::User(UNPROVEN)),
            ("VUID-VkAcquireNextImageInfoKHR-semaphore-01782", How::User(UNPROVEN)),
            ("VUID-VkAcquireNextImageInfoKHR-swapchain-01675", How::User(UNPROVEN)),
            ("VUID-VkAcquireNextImageInfoKHR-semaphore-01288", How::User(UNPROVEN)),
            ("VUID-VkAcquireNextImageInfoKHR-semaphore-01781", How::User(UNPROVEN)),
        ],
        ..NONE
    },
    Special {
        command: "vkQueuePresentKHR",
        check: call("hooks::queue_present_khr_checks", &["self", "present_info"]),
        hold: call("hooks::queue_present_khr_gate", &["self", "present_info"]),
        before: call("hooks::queue_present_khr_before", &["self", "present_info"]),
        settles: &[
            ("VUID-vkQueuePresentKHR-pWaitSemaphores-03267", How::Dynamic(SEMAPHORE_TYPE)),
            ("VUID-vkQueuePresentKHR-pWaitSemaphores-03268", How::Dynamic(BINARY_STATE)),
            ("VUID-vkQueuePresentKHR-pWaitSemaphores-01295", How::User(SAME_AS_03268)),
            ("VUID-vkQueuePresentKHR-pWaitSemaphores-01294", How::User(ONE_WAITER)),
            ("VUID-VkPresentInfoKHR-pImageIndices-01296", How::Dynamic(PRESENTED)),
            ("VUID-vkQueuePresentKHR-pSwapchains-01292", How::User(UNPROVEN_SURFACE_SUPPORT)),
            ("VUID-VkDeviceGroupPresentInfoKHR-swapchainCount-01297", How::Dynamic(GROUP_PRESENT)),
            ("VUID-VkDeviceGroupPresentInfoKHR-mode-01298", How::Dynamic(GROUP_PRESENT)),
            ("VUID-VkDeviceGroupPresentInfoKHR-mode-01299", How::Dynamic(GROUP_PRESENT)),
            ("VUID-VkDeviceGroupPresentInfoKHR-mode-01300", How::Dynamic(GROUP_PRESENT)),
            ("VUID-VkDeviceGroupPresentInfoKHR-mode-01301", How::Dynamic(GROUP_PRESENT)),
            ("VUID-VkDeviceGroupPresentInfoKHR-pDeviceMasks-01302", How::Dynamic(GROUP_PRESENT)),
            ("VUID-VkDeviceGroupPresentInfoKHR-mode-01303", How::Dynamic(GROUP_PRESENT)),
        ],
        ..NONE
    },
    Special {
        command: "vkResetCommandBuffer",
        check: call("hooks::reset_command_buffer_checks", &["self"]),
        after: call("hooks::reset_command_buffer_done", &["self"]),
        settles: &[
            (
                "VUID-vkResetCommandBuffer-commandBuffer-00045",
                How::Dynamic("refuses a buffer that a submission may still be executing"),
            ),
            (
                "VUID-vkResetCommandBuffer-commandBuffer-00046",
                How::Dynamic("refuses a buffer whose pool was created without RESET_COMMAND_BUFFER"),
            ),
        ],
        ..NONE
    },
    Special {
        command: "vkResetCommandPool",
        check: call("hooks::reset_command_pool_checks", &["self", "command_pool"]),
        after: call("hooks::reset_command_pool_done", &["command_pool"]),
        settles: &[(
            "VUID-vkResetCommandPool-commandPool-00040",
            How::Dynamic("refuses a pool one of whose buffers a submission may still be executing"),
        )],
        ..NONE
    },
    Special {
        command: "vkResetDescriptorPool",
        check: call("hooks::reset_descriptor_pool_checks", &["descriptor_pool"]),
        after: call("hooks::reset_descriptor_pool_done", &["descriptor_pool"]),
        settles: &[(
            "VUID-vkResetDescriptorPool-descriptorPool-00313",
            How::Dynamic("refuses a pool whose sets are still alive (held by the program, a command buffer or a submission)"),
        )],
        ..NONE
    },
    Special {
        command: "vkUpdateDescriptorSets",
        check: call(
            "hooks::update_descriptor_sets_checks",
            &["self", "descriptor_writes", "descriptor_copies"],
        ),
        hold: call(
            "hooks::update_descriptor_sets_gate",
            &["self", "descriptor_writes", "descriptor_copies"],
        ),
        after: call(
            "hooks::update_descriptor_sets_done",
            &["self", "descriptor_writes", "descriptor_copies"],
        ),
        settles: &[
            (
                "VUID-VkWriteDescriptorSet-descriptorType-00324",
                How::Dynamic("refuses a write whose descriptor type selects an array that is not set"),
            ),
            ("VUID-VkWriteDescriptorSet-dstBinding-00315", How::Dynamic(SET_BINDINGS)),
            ("VUID-VkWriteDescriptorSet-dstBinding-00316", How::Dynamic(SET_BINDINGS)),
            ("VUID-VkWriteDescriptorSet-descriptorType-00319", How::Dynamic(SET_BINDINGS)),
            ("VUID-VkWriteDescriptorSet-dstArrayElement-00321", How::Dynamic(SET_BINDINGS)),
            ("VUID-VkWriteDescriptorSet-descriptorCount-00317", How::Dynamic(SET_BINDINGS)),
            ("VUID-VkCopyDescriptorSet-srcBinding-00345", How::Dynamic(SET_BINDINGS)),
            ("VUID-VkCopyDescriptorSet-srcArrayElement-00346", How::Dynamic(SET_BINDINGS)),
            ("VUID-VkCopyDescriptorSet-dstBinding-00347", How::Dynamic(SET_BINDINGS)),
            ("VUID-VkCopyDescriptorSet-dstArrayElement-00348", How::Dynamic(SET_BINDINGS)),
            ("VUID-VkCopyDescriptorSet-dstBinding-02632", How::Dynamic(SET_BINDINGS)),
            ("VUID-VkWriteDescriptorSet-descriptorCount-00318", How::Dynamic(SET_BINDINGS)),
            ("VUID-VkWriteDescriptorSet-descriptorType-02752", How::Dynamic(SET_BINDINGS)),
            ("VUID-VkCopyDescriptorSet-dstBinding-02753", How::Dynamic(SET_BINDINGS)),
            ("VUID-VkCopyDescriptorSet-srcBinding-02223", How::User(UNPROVEN_INLINE_COPIES)),
            ("VUID-VkCopyDescriptorSet-dstBinding-02224", How::User(UNPROVEN_INLINE_COPIES)),
            ("VUID-VkCopyDescriptorSet-srcBinding-02225", How::User(UNPROVEN_INLINE_COPIES)),
            ("VUID-vkUpdateDescriptorSets-pDescriptorWrites-06493", How::Dynamic("refuses a write whose descriptor type selects an array that is not set")),
            ("VUID-VkWriteDescriptorSet-descriptorType-00325", How::Dynamic(IMAGE_INFO_SAMPLER)),
            ("VUID-VkWriteDescriptorSet-descriptorType-02996", How::Static(IMAGE_INFO_WRAPPERS)),
            ("VUID-VkWriteDescriptorSet-descriptorType-02997", How::Dynamic(IMAGE_INFO_VIEW)),
            ("VUID-VkWriteDescriptorSet-descriptorType-07683", How::Dynamic(IMAGE_INFO_VIEW)),
            ("VUID-VkWriteDescriptorSet-descriptorType-02994", How::Static(TEXEL_VIEW_WRAPPERS)),
            ("VUID-VkWriteDescriptorSet-descriptorType-02995", How::Static(TEXEL_VIEW_WRAPPERS)),
            ("VUID-vkUpdateDescriptorSets-pDescriptorWrites-06236", How::Dynamic(OTHER_DEVICE_DESCRIPTOR)),
            ("VUID-vkUpdateDescriptorSets-pDescriptorWrites-06237", How::Dynamic(OTHER_DEVICE_BUFFER_DESCRIPTOR)),
            ("VUID-vkUpdateDescriptorSets-pDescriptorWrites-06238", How::Dynamic(OTHER_DEVICE_DESCRIPTOR)),
            ("VUID-vkUpdateDescriptorSets-pDescriptorWrites-06239", How::Dynamic(OTHER_DEVICE_DESCRIPTOR)),
            ("VUID-VkDescriptorBufferInfo-buffer-02998", How::Dynamic(NULL_DESCRIPTOR)),
            ("VUID-VkWriteDescriptorSet-descriptorType-00327", How::Dynamic(BUFFER_DESCRIPTOR)),
            ("VUID-VkWriteDescriptorSet-descriptorType-00328", How::Dynamic(BUFFER_DESCRIPTOR)),
            ("VUID-VkWriteDescriptorSet-descriptorType-00329", How::Dynamic(BUFFER_DESCRIPTOR)),
            ("VUID-VkWriteDescriptorSet-descriptorType-00330", How::Dynamic(BUFFER_DESCRIPTOR)),
            ("VUID-VkWriteDescriptorSet-descriptorType-00331", How::Dynamic(BUFFER_DESCRIPTOR)),
            ("VUID-VkWriteDescriptorSet-descriptorType-00332", How::Dynamic(BUFFER_DESCRIPTOR)),
            ("VUID-VkWriteDescriptorSet-descriptorType-00333", How::User(UNPROVEN_STORAGE_RANGE)),
            ("VUID-VkWriteDescriptorSet-descriptorType-00334", How::Dynamic(BUFFER_DESCRIPTOR)),
            ("VUID-VkWriteDescriptorSet-descriptorType-00335", How::Dynamic(BUFFER_DESCRIPTOR)),
            ("VUID-VkWriteDescriptorSet-descriptorType-00336", How::Dynamic(IMAGE_DESCRIPTOR)),
            ("VUID-VkWriteDescriptorSet-descriptorType-00337", How::Dynamic(IMAGE_DESCRIPTOR)),
            ("VUID-VkWriteDescriptorSet-descriptorType-00338", How::Dynamic(IMAGE_DESCRIPTOR)),
            ("VUID-VkWriteDescriptorSet-descriptorType-00339", How::Dynamic(IMAGE_DESCRIPTOR)),
            ("VUID-VkWriteDescriptorSet-descriptorType-04149", How::Dynamic(IMAGE_DESCRIPTOR)),
            ("VUID-VkWriteDescriptorSet-descriptorType-04150", How::Dynamic(IMAGE_DESCRIPTOR)),
            ("VUID-VkWriteDescriptorSet-descriptorType-04151", How::Dynamic(IMAGE_DESCRIPTOR)),
            ("VUID-VkWriteDescriptorSet-descriptorType-04152", How::Dynamic(IMAGE_DESCRIPTOR)),
            ("VUID-VkWriteDescriptorSet-descriptorType-07729", How::Dynamic(BOTH_ASPECTS)),
            ("VUID-VkDescriptorImageInfo-imageView-01976", How::Dynamic(BOTH_ASPECTS)),
            ("VUID-VkDescriptorImageInfo-imageView-06711", How::Dynamic(IMAGE_DESCRIPTOR)),
            ("VUID-VkDescriptorImageInfo-imageView-06712", How::Dynamic(IMAGE_DESCRIPTOR)),
            ("VUID-VkDescriptorImageInfo-sampler-01564", How::User(UNPROVEN_PLANE_SAMPLER)),
            ("VUID-VkWriteDescriptorSet-descriptorType-02221", How::Dynamic("checks an inline uniform block write chains a VkWriteDescriptorSetInlineUniformBlock whose dataSize is the write's count")),
            ("VUID-VkCopyDescriptorSet-srcSet-00349", How::Dynamic("checks the two ranges of a copy inside one set, as positions among the set's elements in binding order, do not overlap (the 1.3.239 layer does not check it: proven by the error alone)")),
            ("VUID-VkCopyDescriptorSet-srcSet-01918", How::User(UNPROVEN_AFTER_BIND_LAYOUTS)),
            ("VUID-VkCopyDescriptorSet-srcSet-04886", How::User(UNPROVEN_AFTER_BIND_LAYOUTS)),
            ("VUID-VkCopyDescriptorSet-srcSet-01920", How::Dynamic(AFTER_BIND_POOLS)),
            ("VUID-VkCopyDescriptorSet-srcSet-04888", How::Dynamic(AFTER_BIND_POOLS)),
            ("VUID-vkUpdateDescriptorSets-None-03047", How::Dynamic("checks the submissions of the command buffers that bound each set the update writes (recorded at each submission, dropped once known complete) when it rewrites a binding without UPDATE_AFTER_BIND or UPDATE_UNUSED_WHILE_PENDING, or one of image descriptors (whose layouts the submission checked); an update also leaves the command buffers that bound the set invalid, and what it replaces stays alive until those submissions complete")),
            ("VUID-VkDescriptorImageInfo-imageLayout-00344", How::Dynamic("checked where each draw and dispatch reads the sets bound at its pipeline layout's set numbers (the image descriptors each set held when it was bound; an update after that leaves the recording invalid): each descriptor's layout against what the recording's earlier commands leave its view's subresources in, and otherwise needed at the recording's start, which its submission checks against what the earlier submissions leave; a descriptor naming an attachment of the render pass instance is refused, as the recorder does not follow subpass layouts (across command buffers the 1.3.239 layer states the mismatch as UNASSIGNED-CoreValidation-DrawState-InvalidImageLayout)")),
            ("VUID-vkUpdateDescriptorSets-pDescriptorWrites-06993", How::Static("every descriptor update and every submission holds the device's descriptor gate, so no two of them touch a set at once")),
        ],
        ..NONE
    },
    Special {
        command: "vkCreateBufferView",
        created: call("hooks::buffer_view_created", &["self", "created", "create_info"]),
        ..NONE
    },
    Special {
        command: "vkUpdateDescriptorSetWithTemplate",
        after: unsafe_call(
            "hooks::update_descriptor_set_with_template_done",
            &["self", "descriptor_set", "descriptor_update_template", "data"],
            "the caller of this unsafe method vouches that `data` is laid out as the template's entries describe.",
        ),
        ..NONE
    },
    Special {
        command: "vkBindBufferMemory",
        check: call(
            "hooks::bind_buffer_memory_checks",
            &["self", "buffer", "memory", "memory_offset"],
        ),
        after: call(
            "hooks::bind_buffer_memory_done",
            &["self", "buffer", "memory", "memory_offset"],
        ),
        settles: &[
            ("VUID-vkBindBufferMemory-buffer-07459", How::Dynamic(BIND_BOUND)),
            ("VUID-vkBindBufferMemory-buffer-01030", How::User(UNPROVEN)),
            ("VUID-vkBindBufferMemory-memoryOffset-01031", How::Dynamic(BIND_MEMORY)),
            ("VUID-vkBindBufferMemory-memory-01035", How::User(UNPROVEN)),
            ("VUID-vkBindBufferMemory-memoryOffset-01036", How::Dynamic(BIND_MEMORY)),
            ("VUID-vkBindBufferMemory-size-01037", How::Dynamic(BIND_MEMORY)),
            ("VUID-vkBindBufferMemory-buffer-01444", How::User(UNPROVEN_DEDICATED)),
            ("VUID-vkBindBufferMemory-memory-01508", How::Dynamic(MEMORY_KIND)),
            ("VUID-vkBindBufferMemory-None-01898", How::User(UNPROVEN_PROTECTED)),
            ("VUID-vkBindBufferMemory-None-01899", How::User(UNPROVEN_PROTECTED)),
            ("VUID-vkBindBufferMemory-memory-02726", How::Dynamic(MEMORY_KIND)),
            ("VUID-vkBindBufferMemory-memory-02727", How::Static(NO_IMPORT)),
            ("VUID-vkBindBufferMemory-bufferDeviceAddress-03339", How::Dynamic(MEMORY_KIND)),
        ],
        ..NONE
    },
    Special {
        command: "vkBindBufferMemory2",
        check: call("hooks::bind_buffer_memory2_checks", &["self", "bind_infos"]),
        after: call("hooks::bind_buffer_memory2_done", &["self", "bind_infos"]),
        settles: &[
            ("VUID-VkBindBufferMemoryInfo-buffer-07459", How::Dynamic(BIND_BOUND)),
            ("VUID-VkBindBufferMemoryInfo-buffer-01030", How::User(UNPROVEN)),
            ("VUID-VkBindBufferMemoryInfo-memoryOffset-01031", How::Dynamic(BIND_MEMORY)),
            ("VUID-VkBindBufferMemoryInfo-memory-01035", How::User(UNPROVEN)),
            ("VUID-VkBindBufferMemoryInfo-memoryOffset-01036", How::Dynamic(BIND_MEMORY)),
            ("VUID-VkBindBufferMemoryInfo-size-01037", How::Dynamic(BIND_MEMORY)),
        ],
        ..NONE
    },
    Special {
        command: "vkBindImageMemory2",
        check: call("hooks::bind_image_memory2_checks", &["self", "bind_infos"]),
        after: call("hooks::bind_image_memory2_done", &["self", "bind_infos"]),
        settles: &[
            ("VUID-VkBindImageMemoryInfo-image-07460", How::Dynamic(BIND_BOUND)),
            ("VUID-VkBindImageMemoryInfo-image-01045", How::User(UNPROVEN)),
            ("VUID-VkBindImageMemoryInfo-memoryOffset-01046", How::Dynamic(BIND_MEMORY)),
            ("VUID-VkBindImageMemoryInfo-pNext-01615", How::User(UNPROVEN)),
            ("VUID-VkBindImageMemoryInfo-pNext-01616", How::Dynamic(BIND_MEMORY)),
            ("VUID-VkBindImageMemoryInfo-pNext-01617", How::Dynamic(BIND_MEMORY)),
            ("VUID-VkBindImageMemoryInfo-pNext-01618", How::User(UNPROVEN)),
        ],
        ..NONE
    },
    Special {
        command: "vkCreateBuffer",
        check_last: call("hooks::create_buffer_checks", &["self", "create_info"]),
        hold: call("hooks::sparse_buffer_gate", &["self", "create_info"]),
        created: call("hooks::buffer_created", &["self", "created", "create_info"]),
        settles: &[
            ("VUID-VkBufferCreateInfo-None-01888", How::User(UNPROVEN_SPARSE)),
            ("VUID-vkCreateBuffer-flags-00911", How::User(UNPROVEN_SPARSE_SPACE)),
            ("VUID-VkBufferCreateInfo-size-06409", How::Dynamic(BUFFER_ALONE)),
            ("VUID-VkBufferCreateInfo-sharingMode-01419", How::Dynamic(BUFFER_INFO)),
            ("VUID-VkBufferCreateInfo-opaqueCaptureAddress-03337", How::Dynamic(BUFFER_INFO)),
            ("VUID-VkBufferCreateInfo-pNext-00920", How::Dynamic(BUFFER_ALONE)),
        ],
        ..NONE
    },
    Special {
        command: "vkCreateShaderModule",
        created: call("hooks::shader_module_created", &["self", "created", "create_info"]),
        contract: Some(SHADER_CONTRACT),
        ..NONE
    },
    Special {
        command: "vkCreateImage",
        check_last: call("hooks::create_image_checks", &["self", "create_info"]),
        hold: call("hooks::sparse_image_gate", &["self", "create_info"]),
        created: call("hooks::image_created", &["self", "created", "create_info"]),
        settles: &[
            ("VUID-VkImageCreateInfo-imageType-00956", How::Dynamic(IMAGE_RULES)),
            ("VUID-VkImageCreateInfo-imageType-00954", How::Dynamic(IMAGE_RULES)),
            ("VUID-VkImageCreateInfo-usage-00966", How::Dynamic(IMAGE_RULES)),
            ("VUID-VkImageCreateInfo-samples-02257", How::Dynamic(IMAGE_RULES)),
            ("VUID-VkImageCreateInfo-flags-01572", How::Dynamic(IMAGE_RULES)),
            ("VUID-VkImageCreateInfo-format-01577", How::Dynamic(IMAGE_RULES)),
            ("VUID-VkImageCreateInfo-usage-00964", How::Dynamic(IMAGE_RULES)),
            ("VUID-VkImageCreateInfo-usage-00965", How::Dynamic(IMAGE_RULES)),
            ("VUID-VkImageCreateInfo-format-02795", How::Dynamic(IMAGE_RULES)),
            ("VUID-VkImageCreateInfo-format-02796", How::Dynamic(IMAGE_RULES)),
            ("VUID-VkImageCreateInfo-format-02797", How::Dynamic(IMAGE_RULES)),
            ("VUID-VkImageCreateInfo-format-02798", How::Dynamic(IMAGE_RULES)),
            ("VUID-VkImageCreateInfo-Format-02536", How::Dynamic(IMAGE_RULES)),
            ("VUID-VkImageCreateInfo-format-02537", How::Dynamic(IMAGE_RULES)),
            ("VUID-VkImageCreateInfo-flags-04738", How::Dynamic(IMAGE_RULES)),
            ("VUID-VkImageCreateInfo-mipLevels-00958", How::Dynamic(FULL_CHAIN)),
            ("VUID-VkImageCreateInfo-imageCreateMaxMipLevels-02251", How::Dynamic(IMAGE_LIMITS)),
            ("VUID-VkImageCreateInfo-extent-02252", How::Dynamic(IMAGE_LIMITS)),
            ("VUID-VkImageCreateInfo-extent-02253", How::Dynamic(IMAGE_LIMITS)),
            ("VUID-VkImageCreateInfo-extent-02254", How::Dynamic(IMAGE_LIMITS)),
            // Lavapipe allows every format the levels of its largest extent, so a
            // level count past the format's limit is past the chain too (00958).
            ("VUID-VkImageCreateInfo-mipLevels-02255", How::User(UNPROVEN)),
            ("VUID-VkImageCreateInfo-arrayLayers-02256", How::Dynamic(IMAGE_LIMITS)),
            ("VUID-VkImageCreateInfo-samples-02258", How::Dynamic(IMAGE_LIMITS)),
            ("VUID-VkImageCreateInfo-pNext-06722", How::Dynamic(IMAGE_RULES)),
            ("VUID-VkImageCreateInfo-sharingMode-01420", How::Dynamic(IMAGE_RULES)),
            ("VUID-VkImageCreateInfo-pNext-01443", How::Dynamic(IMAGE_RULES)),
            ("VUID-VkImageCreateInfo-pNext-00990", How::Dynamic(IMAGE_EXTERNAL)),
            ("VUID-VkImageCreateInfo-physicalDeviceCount-01421", How::Dynamic(IMAGE_RULES)),
            ("VUID-VkImageCreateInfo-flags-02259", How::Dynamic(IMAGE_RULES)),
            ("VUID-VkImageCreateInfo-format-06410", How::Dynamic(IMAGE_CHROMA)),
            ("VUID-VkImageCreateInfo-format-06411", How::Dynamic(IMAGE_CHROMA)),
            ("VUID-VkImageCreateInfo-format-06412", How::Dynamic(IMAGE_CHROMA)),
            ("VUID-VkImageCreateInfo-format-04712", How::Dynamic(IMAGE_CHROMA)),
            ("VUID-VkImageCreateInfo-format-04713", How::Dynamic(IMAGE_CHROMA)),
            ("VUID-VkImageCreateInfo-imageCreateFormatFeatures-02260", How::Dynamic(IMAGE_CHROMA)),
            ("VUID-VkImageCreateInfo-format-02538", How::Dynamic(IMAGE_RULES)),
            ("VUID-VkImageSwapchainCreateInfoKHR-swapchain-00995", How::Dynamic(IMAGE_OF_SWAPCHAIN)),
            ("VUID-vkCreateImage-flags-00939", How::User(UNPROVEN_SPARSE_IMAGES)),
            ("VUID-VkImageCreateInfo-None-01925", How::User(UNPROVEN_SPARSE_IMAGES)),
            ("VUID-VkImageCreateInfo-None-01891", How::User(UNPROVEN_SPARSE_IMAGES)),
        ],
        ..NONE
    },
    Special {
        command: "vkCmdFillBuffer",
        check: call(
            "hooks::cmd_fill_buffer_checks",
            &["self", "dst_buffer", "dst_offset", "size"],
        ),
        settles: &[
            ("VUID-vkCmdFillBuffer-dstOffset-00024", How::Dynamic(RANGE)),
            ("VUID-vkCmdFillBuffer-dstOffset-00025", How::Dynamic(RANGE)),
            ("VUID-vkCmdFillBuffer-size-00026", How::Dynamic(RANGE)),
            ("VUID-vkCmdFillBuffer-size-00027", How::Dynamic(RANGE)),
            ("VUID-vkCmdFillBuffer-size-00028", How::Dynamic(RANGE)),
            ("VUID-vkCmdFillBuffer-dstBuffer-00029", How::Dynamic(BUFFER_USE)),
            ("VUID-vkCmdFillBuffer-dstBuffer-00031", How::Dynamic(BUFFER_USE)),
        ],
        ..NONE
    },
    Special {
        command: "vkCmdUpdateBuffer",
        check: call(
            "hooks::cmd_update_buffer_checks",
            &["self", "dst_buffer", "dst_offset", "data"],
        ),
        settles: &[
            ("VUID-vkCmdUpdateBuffer-dstOffset-00032", How::Dynamic(RANGE)),
            ("VUID-vkCmdUpdateBuffer-dataSize-00033", How::Dynamic(RANGE)),
            ("VUID-vkCmdUpdateBuffer-dstBuffer-00034", How::Dynamic(BUFFER_USE)),
            ("VUID-vkCmdUpdateBuffer-dstBuffer-00035", How::Dynamic(BUFFER_USE)),
            ("VUID-vkCmdUpdateBuffer-dstOffset-00036", How::Dynamic(RANGE)),
            ("VUID-vkCmdUpdateBuffer-dataSize-00037", How::Dynamic(RANGE)),
            ("VUID-vkCmdUpdateBuffer-dataSize-00038", How::Dynamic(RANGE)),
        ],
        ..NONE
    },
    Special {
        command: "vkCmdBindVertexBuffers",
        check: call(
            "hooks::cmd_bind_vertex_buffers_checks",
            &["self", "first_binding", "buffers", "offsets"],
        ),
        after: call(
            "hooks::cmd_bind_vertex_buffers_done",
            &["self", "first_binding", "buffers", "offsets", "(&[], &[])"],
        ),
        settles: &[
            ("VUID-vkCmdBindVertexBuffers-pOffsets-00626", How::Dynamic(RANGE)),
            ("VUID-vkCmdBindVertexBuffers-pBuffers-00627", How::Dynamic(BUFFER_USE)),
            ("VUID-vkCmdBindVertexBuffers-pBuffers-00628", How::Dynamic(BUFFER_USE)),
            ("VUID-vkCmdBindVertexBuffers-firstBinding-00625", How::Dynamic(VERTEX_LIMITS)),
        ],
        ..NONE
    },
    Special {
        command: "vkCmdBindVertexBuffers2",
        check: call(
            "hooks::cmd_bind_vertex_buffers2_checks",
            &["self", "first_binding", "buffers", "offsets", "(sizes, strides)"],
        ),
        after: call(
            "hooks::cmd_bind_vertex_buffers2_done",
            &["self", "first_binding", "buffers", "offsets", "(sizes, strides)"],
        ),
        settles: &[
            ("VUID-vkCmdBindVertexBuffers2-pOffsets-03357", How::Dynamic(RANGE)),
            ("VUID-vkCmdBindVertexBuffers2-pSizes-03358", How::Dynamic(RANGE)),
            ("VUID-vkCmdBindVertexBuffers2-pBuffers-03359", How::Dynamic(BUFFER_USE)),
            ("VUID-vkCmdBindVertexBuffers2-pBuffers-03360", How::Dynamic(BUFFER_USE)),
            ("VUID-vkCmdBindVertexBuffers2-firstBinding-03356", How::Dynamic(VERTEX_LIMITS)),
            ("VUID-vkCmdBindVertexBuffers2-pStrides-03362", How::Dynamic(VERTEX_LIMITS)),
        ],
        ..NONE
    },
    Special {
        command: "vkCmdBindIndexBuffer",
        after: call(
            "hooks::cmd_bind_index_buffer_done",
            &["self", "buffer", "offset", "index_type"],
        ),
        check: call(
            "hooks::cmd_bind_index_buffer_checks",
            &["self", "buffer", "offset", "index_type"],
        ),
        settles: &[
            ("VUID-vkCmdBindIndexBuffer-offset-00432", How::Dynamic(INDEX_ALIGNED)),
            ("VUID-vkCmdBindIndexBuffer-offset-00431", How::Dynamic(RANGE)),
            ("VUID-vkCmdBindIndexBuffer-buffer-00433", How::Dynamic(BUFFER_USE)),
            ("VUID-vkCmdBindIndexBuffer-buffer-00434", How::Dynamic(BUFFER_USE)),
        ],
        ..NONE
    },
    Special {
        command: "vkCreateQueryPool",
        check: call("hooks::create_query_pool_checks", &["create_info"]),
        created: call("hooks::query_pool_created", &["self", "created", "create_info"]),
        settles: &[(
            "VUID-VkQueryPoolCreateInfo-queryType-00792",
            How::Dynamic(STATISTICS),
        )],
        ..NONE
    },
    Special {
        command: "vkCreateSampler",
        check_last: call("hooks::sampler_checks", &["self", "create_info"]),
        created: call("hooks::sampler_created", &["self", "created", "create_info"]),
        settles: &[
            ("VUID-VkSamplerCreateInfo-unnormalizedCoordinates-01072", How::Dynamic(SAMPLER_MODES)),
            ("VUID-VkSamplerCreateInfo-addressModeU-01079", How::Dynamic(SAMPLER_MODES)),
            ("VUID-VkSamplerCreateInfo-pNext-06726", How::Dynamic(SAMPLER_MODES)),
            ("VUID-VkSamplerCreateInfo-compareEnable-01423", How::Dynamic(SAMPLER_MODES)),
        ],
        ..NONE
    },
    Special {
        command: "vkCreateRenderPass2",
        check: call("hooks::create_render_pass2_checks", &["create_info"]),
        check_last: call(
            "hooks::render_pass2_reference_checks",
            &["self", "create_info"],
        ),
        created: call("hooks::render_pass2_created", &["self", "created", "create_info"]),
        settles: &[
            ("VUID-VkRenderPassCreateInfo2-attachment-03051", How::Dynamic(RENDER_PASS_INDICES)),
            ("VUID-VkSubpassDescription2-attachment-03073", How::Dynamic(SUBPASS_REFERENCES)),
            ("VUID-VkSubpassDescription2-pPreserveAttachments-03074", How::Dynamic(SUBPASS_REFERENCES)),
            ("VUID-VkSubpassDescription2-pResolveAttachments-03065", How::Dynamic(SUBPASS_REFERENCES)),
            ("VUID-VkSubpassDescription2-pResolveAttachments-03066", How::Dynamic(SUBPASS_REFERENCES)),
            ("VUID-VkSubpassDescription2-pResolveAttachments-03067", How::Dynamic(SUBPASS_REFERENCES)),
            ("VUID-VkSubpassDescription2-pResolveAttachments-03068", How::Dynamic(SUBPASS_REFERENCES)),
            ("VUID-VkSubpassDescription2-pInputAttachments-02897", How::Dynamic(SUBPASS_REFERENCES)),
            ("VUID-VkSubpassDescription2-pColorAttachments-02898", How::Dynamic(SUBPASS_REFERENCES)),
            ("VUID-VkSubpassDescription2-pResolveAttachments-02899", How::User(UNPROVEN_RESOLVE_FEATURES)),
            ("VUID-VkSubpassDescription2-pDepthStencilAttachment-02900", How::Dynamic(SUBPASS_REFERENCES)),
            ("VUID-VkSubpassDescription2-multisampledRenderToSingleSampled-06872", How::Dynamic(SUBPASS_REFERENCES)),
            ("VUID-VkSubpassDescription2-layout-02528", How::Dynamic(SUBPASS_REFERENCES)),
            ("VUID-VkSubpassDescription2-pDepthStencilAttachment-04440", How::Dynamic(SUBPASS_REFERENCES)),
            ("VUID-VkSubpassDescription2-attachment-02800", How::Dynamic(SUBPASS_REFERENCES)),
            ("VUID-VkSubpassDescription2-attachment-02801", How::Dynamic(SUBPASS_REFERENCES)),
            ("VUID-VkRenderPassCreateInfo2-attachment-02525", How::Dynamic(SUBPASS_REFERENCES)),
            ("VUID-VkSubpassDescription2-viewMask-06706", How::Dynamic(SUBPASS_REFERENCES)),
            ("VUID-VkRenderPassCreateInfo2-viewMask-03057", How::Dynamic(SUBPASS_REFERENCES)),
            ("VUID-VkRenderPassCreateInfo2-viewMask-03058", How::Dynamic(SUBPASS_REFERENCES)),
            ("VUID-VkRenderPassCreateInfo2-viewMask-03059", How::Dynamic(SUBPASS_REFERENCES)),
        ],
        ..NONE
    },
    Special {
        command: "vkCmdBeginRenderPass",
        check: call(
            "hooks::begin_render_pass_checks",
            &["&self", "render_pass_begin", "&crate::hooks::BEGIN"],
        ),
        after: call(
            "hooks::render_pass_begun",
            &["&mut self", "render_pass_begin", "\"VUID-vkCmdBeginRenderPass-initialLayout-00900\""],
        ),
        settles: &[
            ("VUID-VkRenderPassBeginInfo-framebuffer-03207", How::Dynamic(PASS_VIEWS)),
            ("VUID-VkRenderPassBeginInfo-framebuffer-03208", How::Dynamic(PASS_VIEWS)),
            ("VUID-VkRenderPassBeginInfo-framebuffer-03209", How::Dynamic(PASS_VIEWS)),
            ("VUID-VkRenderPassBeginInfo-framebuffer-04627", How::Dynamic(PASS_VIEWS)),
            ("VUID-VkRenderPassBeginInfo-framebuffer-03211", How::Dynamic(PASS_VIEWS)),
            ("VUID-VkRenderPassBeginInfo-framebuffer-03212", How::Dynamic(PASS_VIEWS)),
            ("VUID-VkRenderPassBeginInfo-framebuffer-03213", How::Dynamic(PASS_VIEWS)),
            ("VUID-VkRenderPassBeginInfo-framebuffer-03214", How::Dynamic(PASS_FORMATS)),
            ("VUID-VkRenderPassBeginInfo-framebuffer-03216", How::Dynamic(PASS_VIEWS)),
            ("VUID-VkRenderPassBeginInfo-framebuffer-03217", How::Dynamic(PASS_VIEWS)),
            ("VUID-VkRenderPassBeginInfo-renderPass-00904", How::Dynamic(PASS_VIEWS)),
            ("VUID-VkRenderPassAttachmentBeginInfo-pAttachments-03218", How::Dynamic(PASS_VIEWS)),
            ("VUID-VkRenderPassAttachmentBeginInfo-pAttachments-03219", How::Dynamic(PASS_VIEWS)),
            ("VUID-VkRenderPassBeginInfo-framebuffer-02780", How::User(PASS_UNPROVEN)),
            ("VUID-VkRenderPassBeginInfo-framebuffer-03215", How::User(PASS_UNPROVEN)),
            ("VUID-VkRenderPassAttachmentBeginInfo-pAttachments-04114", How::User(PASS_UNPROVEN)),
            ("VUID-vkCmdBeginRenderPass-framebuffer-02532", How::User(PASS_UNPROVEN)),
            ("VUID-vkCmdBeginRenderPass-stencilInitialLayout-02843", How::User(PASS_UNPROVEN)),
            ("VUID-vkCmdBeginRenderPass-srcStageMask-06451", How::User(PASS_FAMILY)),
            ("VUID-vkCmdBeginRenderPass-dstStageMask-06452", How::User(PASS_FAMILY)),
            ("VUID-VkDeviceGroupRenderPassBeginInfo-deviceMask-00905", How::Dynamic(PASS_GROUP)),
            ("VUID-VkDeviceGroupRenderPassBeginInfo-deviceRenderAreaCount-00908", How::Dynamic(PASS_GROUP)),
            ("VUID-VkDeviceGroupRenderPassBeginInfo-offset-06166", How::Dynamic(PASS_GROUP)),
            ("VUID-VkDeviceGroupRenderPassBeginInfo-offset-06167", How::Dynamic(PASS_GROUP)),
            ("VUID-VkRenderPassBeginInfo-pNext-02856", How::Dynamic(PASS_GROUP)),
            ("VUID-VkRenderPassBeginInfo-pNext-02857", How::Dynamic(PASS_GROUP)),
            ("VUID-VkDeviceGroupRenderPassBeginInfo-offset-06168", How::Dynamic(PASS_GROUP_LIMIT)),
            ("VUID-VkDeviceGroupRenderPassBeginInfo-offset-06169", How::Dynamic(PASS_GROUP_LIMIT)),
            ("VUID-VkDeviceGroupRenderPassBeginInfo-deviceMask-00907", How::User(PASS_GROUP_MASK)),
            ("VUID-VkRenderPassBeginInfo-clearValueCount-04962", How::Static("set from a slice by the safe setter, which stores its pointer with its count")),
            ("VUID-vkCmdBeginRenderPass-initialLayout-00897", How::Dynamic(PASS_BEGIN)),
            ("VUID-vkCmdBeginRenderPass-initialLayout-00898", How::Dynamic(PASS_BEGIN)),
            ("VUID-vkCmdBeginRenderPass-initialLayout-00899", How::Dynamic(PASS_BEGIN)),
            ("VUID-vkCmdBeginRenderPass-initialLayout-00895", How::User(PASS_BEGIN_UNPROVEN)),
            ("VUID-vkCmdBeginRenderPass-initialLayout-01758", How::User(PASS_BEGIN_UNPROVEN)),
            ("VUID-vkCmdBeginRenderPass-initialLayout-02842", How::User(PASS_BEGIN_UNPROVEN)),
            ("VUID-VkRenderPassBeginInfo-pNext-02850", How::Dynamic(PASS_BEGIN)),
            ("VUID-VkRenderPassBeginInfo-pNext-02851", How::Dynamic(PASS_BEGIN)),
            ("VUID-VkRenderPassBeginInfo-pNext-02852", How::Dynamic(PASS_BEGIN)),
            ("VUID-VkRenderPassBeginInfo-pNext-02853", How::Dynamic(PASS_BEGIN)),
            ("VUID-VkRenderPassBeginInfo-clearValueCount-00902", How::Dynamic(PASS_BEGIN)),("VUID-vkCmdBeginRenderPass-initialLayout-00900", How::Dynamic(LAYOUT_PASS))],
        ..NONE
    },
    Special {
        command: "vkCmdBeginRenderPass2",
        check: call(
            "hooks::begin_render_pass_checks",
            &["&self", "render_pass_begin", "&crate::hooks::BEGIN2"],
        ),
        after: call(
            "hooks::render_pass_begun",
            &["&mut self", "render_pass_begin", "\"VUID-vkCmdBeginRenderPass2-initialLayout-03100\""],
        ),
        settles: &[
            (
                "VUID-vkCmdBeginRenderPass2-framebuffer-02779",
                How::Dynamic("checks the framebuffer and the render pass are listed on the command buffer's device, as every one made through the wrappers is on its own (the 1.3.239 layer names only the begin info's commonparent rule, which the same objects break: the error alone proves this one)"),
            ),
            ("VUID-vkCmdBeginRenderPass2-framebuffer-02533", How::User(PASS_UNPROVEN)),
            ("VUID-vkCmdBeginRenderPass2-stencilInitialLayout-02845", How::User(PASS_UNPROVEN)),
            ("VUID-vkCmdBeginRenderPass2-srcStageMask-06453", How::User(PASS_FAMILY)),
            ("VUID-vkCmdBeginRenderPass2-dstStageMask-06454", How::User(PASS_FAMILY)),
            ("VUID-vkCmdBeginRenderPass2-initialLayout-03097", How::Dynamic(PASS_BEGIN)),
            ("VUID-vkCmdBeginRenderPass2-initialLayout-03098", How::Dynamic(PASS_BEGIN)),
            ("VUID-vkCmdBeginRenderPass2-initialLayout-03099", How::Dynamic(PASS_BEGIN)),
            ("VUID-vkCmdBeginRenderPass2-initialLayout-03094", How::User(PASS_BEGIN_UNPROVEN)),
            ("VUID-vkCmdBeginRenderPass2-initialLayout-03096", How::User(PASS_BEGIN_UNPROVEN)),
            ("VUID-vkCmdBeginRenderPass2-initialLayout-02844", How::User(PASS_BEGIN_UNPROVEN)),("VUID-vkCmdBeginRenderPass2-initialLayout-03100", How::Dynamic(LAYOUT_PASS))],
        ..NONE
    },
    Special {
        command: "vkCmdBeginRendering",
        check: call("hooks::begin_rendering_checks", &["&self", "rendering_info"]),
        after: call("hooks::rendering_begun", &["&mut self", "rendering_info"]),
        settles: &[
            ("VUID-VkSubmitInfo-pCommandBuffers-06193", How::User(NO_SUSPENSION)),
            ("VUID-VkSubmitInfo-pCommandBuffers-06014", How::User(NO_SUSPENSION)),
            ("VUID-VkSubmitInfo-pCommandBuffers-06015", How::User(NO_SUSPENSION)),
            ("VUID-VkSubmitInfo-pCommandBuffers-06016", How::User(NO_SUSPENSION)),
            ("VUID-VkSubmitInfo2KHR-commandBuffer-06192", How::User(NO_SUSPENSION)),
            ("VUID-VkSubmitInfo2KHR-commandBuffer-06010", How::User(NO_SUSPENSION)),
            ("VUID-VkSubmitInfo2KHR-commandBuffer-06011", How::User(NO_SUSPENSION)),
            ("VUID-VkSubmitInfo2KHR-commandBuffer-06012", How::User(NO_SUSPENSION)),
        ],
        ..NONE
    },
    Special {
        command: "vkCmdNextSubpass",
        check: call(
            "hooks::next_subpass_checks",
            &["self", "\"VUID-vkCmdNextSubpass-None-00909\""],
        ),
        after: call("hooks::next_subpass_done", &["self"]),
        settles: &[("VUID-vkCmdNextSubpass-None-00909", How::Dynamic(SUBPASSES))],
        ..NONE
    },
    Special {
        command: "vkCmdNextSubpass2",
        check: call(
            "hooks::next_subpass_checks",
            &["self", "\"VUID-vkCmdNextSubpass2-None-03102\""],
        ),
        after: call("hooks::next_subpass_done", &["self"]),
        settles: &[("VUID-vkCmdNextSubpass2-None-03102", How::Dynamic(SUBPASSES))],
        ..NONE
    },
    Special {
        command: "vkCmdEndRenderPass",
        check: call(
            "hooks::end_render_pass_checks",
            &[
                "&mut self",
                "(\"VUID-vkCmdEndRenderPass-None-00910\", \"VUID-vkCmdEndRenderPass-None-07004\")",
            ],
        ),
        after: call("hooks::instance_ended", &["&mut self"]),
        settles: &[
            ("VUID-vkCmdEndRenderPass-None-00910", How::Dynamic(SUBPASSES)),
            ("VUID-vkCmdEndRenderPass-None-07004", How::Dynamic(ACTIVE_QUERIES_ALONE)),
            ("VUID-vkCmdEndRenderPass-None-06170", How::Static(IN_RENDER_PASS)),
        ],
        ..NONE
    },
    Special {
        command: "vkCmdEndRenderPass2",
        check: call(
            "hooks::end_render_pass_checks",
            &[
                "&mut self",
                "(\"VUID-vkCmdEndRenderPass2-None-03103\", \"VUID-vkCmdEndRenderPass2-None-07005\")",
            ],
        ),
        after: call("hooks::instance_ended", &["&mut self"]),
        settles: &[
            ("VUID-vkCmdEndRenderPass2-None-03103", How::Dynamic(SUBPASSES)),
            ("VUID-vkCmdEndRenderPass2-None-07005", How::Dynamic(ACTIVE_QUERIES_ALONE)),
            ("VUID-vkCmdEndRenderPass2-None-06171", How::Static(IN_RENDER_PASS)),
        ],
        ..NONE
    },
    Special {
        command: "vkCmdEndRendering",
        check: call("hooks::end_rendering_checks", &["&mut self"]),
        after: call("hooks::instance_ended", &["&mut self"]),
        settles: &[
            ("VUID-vkCmdEndRendering-None-06999", How::Dynamic(ACTIVE_QUERIES_ALONE)),
            ("VUID-vkCmdEndRendering-None-06161", How::Static(IN_RENDERING)),
            ("VUID-vkCmdEndRendering-commandBuffer-06162", How::Static(IN_RENDERING)),
        ],
        ..NONE
    },
    Special {
        command: "vkCmdBeginQuery",
        check: call("hooks::begin_query_checks", &["self", "query_pool", "query"]),
        after: call("hooks::begin_query_done", &["self", "query_pool", "query"]),
        settles: &[
            ("VUID-vkCmdBeginQuery-queryType-02804", How::Dynamic(QUERY_POOL)),
            ("VUID-vkCmdBeginQuery-query-00802", How::Dynamic(QUERY_POOL)),
            ("VUID-vkCmdBeginQuery-queryType-00803", How::User(UNPROVEN_FAMILY)),
            ("VUID-vkCmdBeginQuery-queryType-00804", How::User(UNPROVEN_FAMILY)),
            ("VUID-vkCmdBeginQuery-queryType-00805", How::User(UNPROVEN_FAMILY)),
            ("VUID-vkCmdBeginQuery-queryPool-01922", How::Dynamic(ACTIVE_QUERIES)),
            ("VUID-vkCmdBeginQuery-query-00808", How::User(UNPROVEN_QUERIES)),
        ],
        ..NONE
    },
    Special {
        command: "vkCmdEndQuery",
        check: call("hooks::end_query_checks", &["self", "query_pool", "query"]),
        after: call("hooks::end_query_done", &["self", "query_pool", "query"]),
        settles: &[
            ("VUID-vkCmdEndQuery-query-00810", How::Dynamic(QUERY_POOL)),
            ("VUID-vkCmdEndQuery-None-01923", How::Dynamic(ACTIVE_QUERIES)),
            ("VUID-vkCmdEndQuery-None-07007", How::Dynamic(ACTIVE_QUERIES_ALONE)),
            ("VUID-vkCmdEndQuery-None-07008", How::Dynamic(ACTIVE_QUERIES_ALONE)),
            ("VUID-vkCmdEndQuery-query-00812", How::User(UNPROVEN_QUERIES)),
        ],
        ..NONE
    },
    // `Recorder::end`, written by hand in `recorder.rs`.
    Special {
        command: "vkEndCommandBuffer",
        settles: &[
            ("VUID-vkEndCommandBuffer-commandBuffer-00059", How::Static(RECORDING)),
            ("VUID-vkEndCommandBuffer-commandBuffer-00060", How::Static(OUTSIDE)),
            ("VUID-vkEndCommandBuffer-commandBuffer-00061", How::Dynamic(ACTIVE_QUERIES)),
        ],
        ..NONE
    },
    Special {
        command: "vkCreateEvent",
        created: call("hooks::event_created", &["self", "created", "create_info"]),
        ..NONE
    },
    Special {
        command: "vkSetEvent",
        check: call(
            "hooks::host_event",
            &["self", "event", "\"VUID-vkSetEvent-event-03941\""],
        ),
        settles: &[("VUID-vkSetEvent-event-03941", How::Dynamic(DEVICE_ONLY))],
        ..NONE
    },
    Special {
        command: "vkResetEvent",
        check: call(
            "hooks::host_event",
            &["self", "event", "\"VUID-vkResetEvent-event-03823\""],
        ),
        settles: &[("VUID-vkResetEvent-event-03823", How::Dynamic(DEVICE_ONLY))],
        ..NONE
    },
    Special {
        command: "vkGetEventStatus",
        check: call(
            "hooks::host_event",
            &["self", "event", "\"VUID-vkGetEventStatus-event-03940\""],
        ),
        settles: &[("VUID-vkGetEventStatus-event-03940", How::Dynamic(DEVICE_ONLY))],
        ..NONE
    },
    Special {
        command: "vkGetDeviceMemoryCommitment",
        check: call("hooks::lazily_allocated", &["self", "memory"]),
        settles: &[(
            "VUID-vkGetDeviceMemoryCommitment-memory-00690",
            How::Dynamic(LAZY),
        )],
        ..NONE
    },
    Special {
        command: "vkGetPhysicalDeviceSparseImageFormatProperties",
        check_last: call(
            "hooks::sparse_samples",
            &[
                "self",
                "(format, ty, samples, usage, tiling)",
                "\"VUID-vkGetPhysicalDeviceSparseImageFormatProperties-samples-01094\"",
            ],
        ),
        settles: &[(
            "VUID-vkGetPhysicalDeviceSparseImageFormatProperties-samples-01094",
            How::Dynamic(SAMPLE_COUNTS),
        )],
        ..NONE
    },
    Special {
        command: "vkGetPhysicalDeviceSparseImageFormatProperties2",
        check_last: call("hooks::sparse_samples2", &["self", "format_info"]),
        settles: &[(
            "VUID-VkPhysicalDeviceSparseImageFormatInfo2-samples-01095",
            How::Dynamic(SAMPLE_COUNTS),
        )],
        ..NONE
    },
    Special {
        command: "vkGetImageMemoryRequirements2",
        check: call("hooks::image_requirements2_planes", &["self", "info"]),
        settles: &[
            ("VUID-VkImageMemoryRequirementsInfo2-image-01589", How::User(UNPROVEN_DISJOINT)),
            ("VUID-VkImageMemoryRequirementsInfo2-image-01590", How::Dynamic(PLANES)),
            ("VUID-VkImageMemoryRequirementsInfo2-image-01591", How::User(UNPROVEN_DISJOINT)),
            ("VUID-VkImagePlaneMemoryRequirementsInfo-planeAspect-02281", How::User(UNPROVEN_DISJOINT)),
        ],
        ..NONE
    },
    Special {
        command: "vkCmdResetQueryPool",
        check: call(
            "hooks::cmd_reset_query_pool_range",
            &["self", "query_pool", "first_query", "query_count"],
        ),
        settles: &[
            ("VUID-vkCmdResetQueryPool-firstQuery-00796", How::Dynamic(QUERY_RANGE)),
            ("VUID-vkCmdResetQueryPool-firstQuery-00797", How::Dynamic(QUERY_RANGE)),
        ],
        ..NONE
    },
    Special {
        command: "vkMergePipelineCaches",
        check: call(
            "hooks::merge_pipeline_caches_checks",
            &["dst_cache", "src_caches"],
        ),
        settles: &[(
            "VUID-vkMergePipelineCaches-dstCache-00770",
            How::Dynamic(MERGE_SELF),
        )],
        ..NONE
    },
    Special {
        command: "vkGetImageMemoryRequirements",
        check: call("hooks::whole_image_requirements", &["self", "image"]),
        settles: &[(
            "VUID-vkGetImageMemoryRequirements-image-01588",
            How::User(UNPROVEN_DISJOINT),
        )],
        ..NONE
    },
    Special {
        command: "vkCreateFence",
        check_last: call("hooks::create_fence_checks", &["self", "create_info"]),
        settles: &[(
            "VUID-VkExportFenceCreateInfo-handleTypes-01446",
            How::Dynamic(EXPORTABLE),
        )],
        ..NONE
    },
    Special {
        command: "vkGetPhysicalDeviceSurfaceSupportKHR",
        check: call(
            "hooks::queue_family_exists",
            &[
                "self",
                "queue_family_index",
                "\"VUID-vkGetPhysicalDeviceSurfaceSupportKHR-queueFamilyIndex-01269\"",
            ],
        ),
        settles: &[(
            "VUID-vkGetPhysicalDeviceSurfaceSupportKHR-queueFamilyIndex-01269",
            How::Dynamic(FAMILY_COUNT),
        )],
        ..NONE
    },
    Special {
        command: "vkGetBufferOpaqueCaptureDescriptorDataEXT",
        check: call(
            "hooks::capture_data_fits",
            &[
                "self",
                "data",
                "|p| p.buffer_capture_replay_descriptor_data_size",
                "\"VUID-vkGetBufferOpaqueCaptureDescriptorDataEXT-pData-08073\"",
            ],
        ),
        settles: &[("VUID-vkGetBufferOpaqueCaptureDescriptorDataEXT-pData-08073", How::User(UNPROVEN_CAPTURE))],
        ..NONE
    },
    Special {
        command: "vkGetImageOpaqueCaptureDescriptorDataEXT",
        check: call(
            "hooks::capture_data_fits",
            &[
                "self",
                "data",
                "|p| p.image_capture_replay_descriptor_data_size",
                "\"VUID-vkGetImageOpaqueCaptureDescriptorDataEXT-pData-08077\"",
            ],
        ),
        settles: &[("VUID-vkGetImageOpaqueCaptureDescriptorDataEXT-pData-08077", How::User(UNPROVEN_CAPTURE))],
        ..NONE
    },
    Special {
        command: "vkGetImageViewOpaqueCaptureDescriptorDataEXT",
        check: call(
            "hooks::capture_data_fits",
            &[
                "self",
                "data",
                "|p| p.image_view_capture_replay_descriptor_data_size",
                "\"VUID-vkGetImageViewOpaqueCaptureDescriptorDataEXT-pData-08081\"",
            ],
        ),
        settles: &[("VUID-vkGetImageViewOpaqueCaptureDescriptorDataEXT-pData-08081", How::User(UNPROVEN_CAPTURE))],
        ..NONE
    },
    Special {
        command: "vkGetSamplerOpaqueCaptureDescriptorDataEXT",
        check: call(
            "hooks::capture_data_fits",
            &[
                "self",
                "data",
                "|p| p.sampler_capture_replay_descriptor_data_size",
                "\"VUID-vkGetSamplerOpaqueCaptureDescriptorDataEXT-pData-08085\"",
            ],
        ),
        settles: &[("VUID-vkGetSamplerOpaqueCaptureDescriptorDataEXT-pData-08085", How::User(UNPROVEN_CAPTURE))],
        ..NONE
    },
    Special {
        command: "vkGetAccelerationStructureOpaqueCaptureDescriptorDataEXT",
        check: call(
            "hooks::capture_data_fits",
            &[
                "self",
                "data",
                "|p| p.acceleration_structure_capture_replay_descriptor_data_size",
                "\"VUID-vkGetAccelerationStructureOpaqueCaptureDescriptorDataEXT-pData-08089\"",
            ],
        ),
        settles: &[("VUID-vkGetAccelerationStructureOpaqueCaptureDescriptorDataEXT-pData-08089", How::User(UNPROVEN_CAPTURE))],
        ..NONE
    },
    Special {
        command: "vkCmdBuildAccelerationStructuresKHR",
        check: call(
            "hooks::per_geometry_fits",
            &["infos", "build_range_infos", "Some(\"VUID-vkCmdBuildAccelerationStructuresKHR-ppBuildRangeInfos-03676\")"],
        ),
        settles: &[("VUID-vkCmdBuildAccelerationStructuresKHR-ppBuildRangeInfos-03676", How::User(UNPROVEN_ACCELERATION))],
        ..NONE
    },
    Special {
        command: "vkBuildAccelerationStructuresKHR",
        check: call(
            "hooks::per_geometry_fits",
            &["infos", "build_range_infos", "Some(\"VUID-vkBuildAccelerationStructuresKHR-ppBuildRangeInfos-03676\")"],
        ),
        settles: &[("VUID-vkBuildAccelerationStructuresKHR-ppBuildRangeInfos-03676", How::User(UNPROVEN_ACCELERATION))],
        ..NONE
    },
    Special {
        command: "vkCmdBuildAccelerationStructuresIndirectKHR",
        check: call(
            "hooks::per_geometry_fits",
            &["infos", "max_primitive_counts", "None"],
        ),
        ..NONE
    },
    // The generated common-parent check compares the display's physical device with
    // the device's.
    Special {
        command: "vkDisplayPowerControlEXT",
        settles: &[("VUID-vkDisplayPowerControlEXT-commonparent", How::User(UNPROVEN_DISPLAY))],
        ..NONE
    },
    // The generated common-parent check compares the display's physical device with
    // the device's.
    Special {
        command: "vkRegisterDisplayEventEXT",
        settles: &[("VUID-vkRegisterDisplayEventEXT-commonparent", How::User(UNPROVEN_DISPLAY))],
        ..NONE
    },
    Special {
        command: "vkGetPhysicalDeviceXlibPresentationSupportKHR",
        check: call(
            "hooks::queue_family_exists",
            &[
                "self",
                "queue_family_index",
                "\"VUID-vkGetPhysicalDeviceXlibPresentationSupportKHR-queueFamilyIndex-01315\"",
            ],
        ),
        settles: &[(
            "VUID-vkGetPhysicalDeviceXlibPresentationSupportKHR-queueFamilyIndex-01315",
            How::Dynamic(FAMILY_COUNT),
        )],
        ..NONE
    },
    Special {
        command: "vkGetPhysicalDeviceXcbPresentationSupportKHR",
        check: call(
            "hooks::queue_family_exists",
            &[
                "self",
                "queue_family_index",
                "\"VUID-vkGetPhysicalDeviceXcbPresentationSupportKHR-queueFamilyIndex-01312\"",
            ],
        ),
        settles: &[(
            "VUID-vkGetPhysicalDeviceXcbPresentationSupportKHR-queueFamilyIndex-01312",
            How::User(UNPROVEN_XCB),
        )],
        ..NONE
    },
    Special {
        command: "vkGetPhysicalDeviceWaylandPresentationSupportKHR",
        check: call(
            "hooks::queue_family_exists",
            &[
                "self",
                "queue_family_index",
                "\"VUID-vkGetPhysicalDeviceWaylandPresentationSupportKHR-queueFamilyIndex-01306\"",
            ],
        ),
        settles: &[(
            "VUID-vkGetPhysicalDeviceWaylandPresentationSupportKHR-queueFamilyIndex-01306",
            How::User(UNPROVEN_WAYLAND),
        )],
        ..NONE
    },
    Special {
        command: "vkGetPhysicalDeviceWin32PresentationSupportKHR",
        check: call(
            "hooks::queue_family_exists",
            &[
                "self",
                "queue_family_index",
                "\"VUID-vkGetPhysicalDeviceWin32PresentationSupportKHR-queueFamilyIndex-01309\"",
            ],
        ),
        settles: &[(
            "VUID-vkGetPhysicalDeviceWin32PresentationSupportKHR-queueFamilyIndex-01309",
            How::User(UNPROVEN_WIN32),
        )],
        ..NONE
    },
    surface_query!("vkGetPhysicalDeviceSurfaceCapabilitiesKHR"),
    surface_query!("vkGetPhysicalDeviceSurfaceFormatsKHR"),
    surface_query!("vkGetPhysicalDeviceSurfacePresentModesKHR"),
    surface_query!("vkGetPhysicalDevicePresentRectanglesKHR"),
    Special {
        command: "vkGetDeviceGroupSurfacePresentModesKHR",
        check_last: call(
            "hooks::device_surface_supported",
            &[
                "self",
                "surface",
                "\"VUID-vkGetDeviceGroupSurfacePresentModesKHR-surface-06212\"",
            ],
        ),
        settles: &[(
            "VUID-vkGetDeviceGroupSurfacePresentModesKHR-surface-06212",
            How::User(UNPROVEN_SURFACE),
        )],
        ..NONE
    },
    Special {
        command: "vkGetQueryPoolResults",
        check: call(
            "hooks::get_query_pool_results_checks",
            &["self", "query_pool", "first_query", "query_count", "data", "stride", "flags"],
        ),
        settles: &[
            ("VUID-vkGetQueryPoolResults-firstQuery-00813", How::Dynamic(QUERIES)),
            ("VUID-vkGetQueryPoolResults-firstQuery-00816", How::Dynamic(QUERIES)),
            ("VUID-vkGetQueryPoolResults-flags-00815", How::Dynamic(QUERIES)),
            ("VUID-vkGetQueryPoolResults-flags-02827", How::Dynamic(QUERIES)),
            ("VUID-vkGetQueryPoolResults-dataSize-00817", How::Dynamic(QUERIES)),
            ("VUID-vkGetQueryPoolResults-queryType-00818", How::Dynamic(QUERIES)),
        ],
        ..NONE
    },
    Special {
        command: "vkCreateDescriptorSetLayout",
        check_last: call("hooks::descriptor_set_layout_checks", &["self", "create_info"]),
        created: call(
            "hooks::descriptor_set_layout_created",
            &["self", "created", "create_info"],
        ),
        settles: &[
            ("VUID-VkDescriptorSetLayoutBinding-descriptorCount-00283", How::Dynamic(STAGE_BITS)),
            ("VUID-VkDescriptorSetLayoutBinding-descriptorType-00282", How::Static(IMMUTABLE_SAMPLERS)),
            ("VUID-VkDescriptorSetLayoutCreateInfo-flags-03000", How::User(UNPROVEN_AFTER_BIND)),
            ("VUID-VkDescriptorSetLayoutCreateInfo-descriptorType-03001", How::User(UNPROVEN_AFTER_BIND)),
            ("VUID-VkDescriptorSetLayoutBindingFlagsCreateInfo-pBindingFlags-03004", How::User(UNPROVEN_VARIABLE_COUNT)),
            ("VUID-VkDescriptorSetLayoutBindingFlagsCreateInfo-pBindingFlags-03015", How::User(UNPROVEN_VARIABLE_COUNT)),
            ("VUID-VkDescriptorSetLayoutCreateInfo-binding-00279", How::Dynamic(LAYOUT_BINDINGS)),
            ("VUID-VkDescriptorSetLayoutBinding-descriptorType-01510", How::Dynamic(LAYOUT_BINDINGS)),
            ("VUID-VkDescriptorSetLayoutBinding-descriptorType-02210", How::Dynamic(LAYOUT_BINDINGS)),
            ("VUID-VkDescriptorSetLayoutBindingFlagsCreateInfo-bindingCount-03002", How::Dynamic(LAYOUT_BINDINGS)),
            ("VUID-VkDescriptorSetLayoutBindingFlagsCreateInfo-descriptorBindingUniformBufferUpdateAfterBind-03005", How::Dynamic(LAYOUT_BINDINGS)),
            ("VUID-VkDescriptorSetLayoutBindingFlagsCreateInfo-descriptorBindingSampledImageUpdateAfterBind-03006", How::Dynamic(LAYOUT_BINDINGS)),
            ("VUID-VkDescriptorSetLayoutBindingFlagsCreateInfo-descriptorBindingStorageImageUpdateAfterBind-03007", How::Dynamic(LAYOUT_BINDINGS)),
            ("VUID-VkDescriptorSetLayoutBindingFlagsCreateInfo-descriptorBindingStorageBufferUpdateAfterBind-03008", How::Dynamic(LAYOUT_BINDINGS)),
            ("VUID-VkDescriptorSetLayoutBindingFlagsCreateInfo-descriptorBindingUniformTexelBufferUpdateAfterBind-03009", How::Dynamic(LAYOUT_BINDINGS)),
            ("VUID-VkDescriptorSetLayoutBindingFlagsCreateInfo-descriptorBindingStorageTexelBufferUpdateAfterBind-03010", How::Dynamic(LAYOUT_BINDINGS)),
            ("VUID-VkDescriptorSetLayoutBindingFlagsCreateInfo-descriptorBindingInlineUniformBlockUpdateAfterBind-02211", How::User(UNPROVEN_INLINE_AFTER_BIND)),
            ("VUID-VkDescriptorSetLayoutBindingFlagsCreateInfo-None-03011", How::Dynamic(LAYOUT_BINDINGS)),
            ("VUID-VkDescriptorSetLayoutBindingFlagsCreateInfo-descriptorBindingUpdateUnusedWhilePending-03012", How::Dynamic(LAYOUT_BINDINGS)),
            ("VUID-VkDescriptorSetLayoutBindingFlagsCreateInfo-descriptorBindingPartiallyBound-03013", How::Dynamic(LAYOUT_BINDINGS)),
            ("VUID-VkDescriptorSetLayoutBindingFlagsCreateInfo-descriptorBindingVariableDescriptorCount-03014", How::Dynamic(LAYOUT_BINDINGS)),
        ],
        ..NONE
    },
    Special {
        command: "vkCreatePipelineLayout",
        check_last: call("hooks::create_pipeline_layout_checks", &["self", "create_info"]),
        created: call("hooks::pipeline_layout_created", &["self", "created", "create_info"]),
        // The update-after-bind limits are larger than the others on lavapipe, so a
        // layout past one is past a set-wide limit first, and no test breaks them
        // alone (but the two dynamic-buffer ones, which are smaller there).
        settles: &[
            ("VUID-VkPipelineLayoutCreateInfo-setLayoutCount-00286", How::Dynamic(LAYOUT_LIMITS)),
            ("VUID-VkPipelineLayoutCreateInfo-descriptorType-02214", How::User(UNPROVEN_BLOCKS)),
            ("VUID-VkPipelineLayoutCreateInfo-descriptorType-02215", How::User(UNPROVEN_BLOCKS)),
            ("VUID-VkPipelineLayoutCreateInfo-descriptorType-02216", How::User(UNPROVEN_BLOCKS)),
            ("VUID-VkPipelineLayoutCreateInfo-descriptorType-02217", How::User(UNPROVEN_BLOCKS)),
            ("VUID-VkPipelineLayoutCreateInfo-pPushConstantRanges-00292", How::Dynamic(LAYOUT_LIMITS)),
            ("VUID-VkPipelineLayoutCreateInfo-descriptorType-03016", How::Dynamic(LAYOUT_LIMITS)),
            ("VUID-VkPipelineLayoutCreateInfo-descriptorType-03017", How::Dynamic(LAYOUT_LIMITS)),
            ("VUID-VkPipelineLayoutCreateInfo-descriptorType-03018", How::Dynamic(LAYOUT_LIMITS)),
            ("VUID-VkPipelineLayoutCreateInfo-descriptorType-03019", How::Dynamic(LAYOUT_LIMITS)),
            ("VUID-VkPipelineLayoutCreateInfo-descriptorType-03020", How::Dynamic(LAYOUT_LIMITS)),
            ("VUID-VkPipelineLayoutCreateInfo-descriptorType-03021", How::Dynamic(LAYOUT_LIMITS)),
            ("VUID-VkPipelineLayoutCreateInfo-descriptorType-03022", How::User(UNPROVEN)),
            ("VUID-VkPipelineLayoutCreateInfo-descriptorType-03023", How::User(UNPROVEN)),
            ("VUID-VkPipelineLayoutCreateInfo-descriptorType-03024", How::User(UNPROVEN)),
            ("VUID-VkPipelineLayoutCreateInfo-descriptorType-03025", How::User(UNPROVEN)),
            ("VUID-VkPipelineLayoutCreateInfo-descriptorType-03026", How::User(UNPROVEN)),
            ("VUID-VkPipelineLayoutCreateInfo-descriptorType-03027", How::User(UNPROVEN)),
            ("VUID-VkPipelineLayoutCreateInfo-descriptorType-03028", How::Dynamic(LAYOUT_LIMITS)),
            ("VUID-VkPipelineLayoutCreateInfo-descriptorType-03029", How::Dynamic(LAYOUT_LIMITS)),
            ("VUID-VkPipelineLayoutCreateInfo-descriptorType-03030", How::Dynamic(LAYOUT_LIMITS)),
            ("VUID-VkPipelineLayoutCreateInfo-descriptorType-03031", How::Dynamic(LAYOUT_LIMITS)),
            ("VUID-VkPipelineLayoutCreateInfo-descriptorType-03032", How::Dynamic(LAYOUT_LIMITS)),
            ("VUID-VkPipelineLayoutCreateInfo-descriptorType-03033", How::Dynamic(LAYOUT_LIMITS)),
            ("VUID-VkPipelineLayoutCreateInfo-descriptorType-03034", How::Dynamic(LAYOUT_LIMITS)),
            ("VUID-VkPipelineLayoutCreateInfo-descriptorType-03035", How::Dynamic(LAYOUT_LIMITS)),
            ("VUID-VkPipelineLayoutCreateInfo-pSetLayouts-03036", How::User(UNPROVEN)),
            ("VUID-VkPipelineLayoutCreateInfo-pSetLayouts-03037", How::User(UNPROVEN)),
            ("VUID-VkPipelineLayoutCreateInfo-pSetLayouts-03038", How::Dynamic(LAYOUT_LIMITS)),
            ("VUID-VkPipelineLayoutCreateInfo-pSetLayouts-03039", How::User(UNPROVEN)),
            ("VUID-VkPipelineLayoutCreateInfo-pSetLayouts-03040", How::Dynamic(LAYOUT_LIMITS)),
            ("VUID-VkPipelineLayoutCreateInfo-pSetLayouts-03041", How::User(UNPROVEN)),
            ("VUID-VkPipelineLayoutCreateInfo-pSetLayouts-03042", How::User(UNPROVEN)),
            ("VUID-VkPipelineLayoutCreateInfo-pSetLayouts-03043", How::User(UNPROVEN)),
        ],
        ..NONE
    },
    Special {
        command: "vkCmdPushConstants",
        check: call(
            "hooks::cmd_push_constants_checks",
            &["self", "layout", "stage_flags", "offset", "values"],
        ),
        after: call(
            "hooks::cmd_push_constants_done",
            &["self", "layout", "offset", "values"],
        ),
        settles: &[
            ("VUID-vkCmdPushConstants-offset-01795", How::Dynamic(PUSH)),
            ("VUID-vkCmdPushConstants-offset-01796", How::Dynamic(PUSH)),
            ("VUID-vkCmdPushConstants-offset-00368", How::Dynamic(PUSH)),
            ("VUID-vkCmdPushConstants-size-00369", How::Dynamic(PUSH)),
            ("VUID-vkCmdPushConstants-offset-00370", How::Dynamic(PUSH)),
            ("VUID-vkCmdPushConstants-size-00371", How::Dynamic(PUSH)),
        ],
        ..NONE
    },
    Special {
        command: "vkCmdBindDescriptorSets",
        after: call(
            "hooks::cmd_bind_descriptor_sets_done",
            &["self", "pipeline_bind_point", "first_set", "descriptor_sets"],
        ),
        check: call(
            "hooks::cmd_bind_descriptor_sets_checks",
            &[
                "self",
                "pipeline_bind_point",
                "layout",
                "first_set",
                "descriptor_sets",
                "dynamic_offsets",
            ],
        ),
        settles: &[
            ("VUID-vkCmdBindDescriptorSets-pDescriptorSets-00358", How::Dynamic(SET_LAYOUTS_MATCH)),
            ("VUID-vkCmdBindDescriptorSets-pipelineBindPoint-00361", How::User(BIND_POINT_FAMILY)),
            ("VUID-vkCmdBindDescriptorSets-pDynamicOffsets-01971", How::Dynamic(DYNAMIC_OFFSETS)),
            ("VUID-vkCmdBindDescriptorSets-pDynamicOffsets-01972", How::Dynamic(DYNAMIC_OFFSETS)),
            ("VUID-vkCmdBindDescriptorSets-pDescriptorSets-01979", How::Dynamic(DYNAMIC_RANGES)),
            ("VUID-vkCmdBindDescriptorSets-pDescriptorSets-06715", How::Dynamic(DYNAMIC_RANGES)),
            (
                "VUID-vkCmdBindDescriptorSets-pDescriptorSets-06563",
                How::Static("taken as wrappers, which always hold valid descriptor sets"),
            ),
            (
                "VUID-vkCmdBindDescriptorSets-firstSet-00360",
                How::Dynamic("checks the sets against the layout's set count, kept from its creation"),
            ),
            (
                "VUID-vkCmdBindDescriptorSets-dynamicOffsetCount-00359",
                How::Dynamic("checks one dynamic offset per dynamic descriptor of the sets, counted from their layouts at creation"),
            ),
        ],
        ..NONE
    },
    Special {
        command: "vkSetPrivateData",
        check: call(
            "hooks::set_private_data_checks",
            &["self", "object_type", "object_handle"],
        ),
        settles: &[
            ("VUID-vkSetPrivateData-objectHandle-04016", How::Dynamic(LIVE_OBJECT)),
            ("VUID-vkSetPrivateData-objectHandle-04017", How::Dynamic(LIVE_OBJECT)),
        ],
        ..NONE
    },
    Special {
        command: "vkGetPrivateData",
        check: call(
            "hooks::get_private_data_checks",
            &["self", "object_type", "object_handle"],
        ),
        settles: &[(
            "VUID-vkGetPrivateData-objectType-04018",
            How::Dynamic(PRIVATE_TYPE),
        )],
        ..NONE
    },
    // Their host synchronization (plan::sync) looks the named object up among the
    // device's live objects and refuses one it does not find.
    Special {
        command: "vkSetDebugUtilsObjectNameEXT",
        settles: &[(
            "VUID-VkDebugUtilsObjectNameInfoEXT-objectType-02590",
            How::Dynamic(NAMED_OBJECT),
        )],
        ..NONE
    },
    Special {
        command: "vkSetDebugUtilsObjectTagEXT",
        settles: &[(
            "VUID-VkDebugUtilsObjectTagInfoEXT-objectHandle-01910",
            How::Dynamic(NAMED_OBJECT),
        )],
        ..NONE
    },
    Special {
        command: "vkCmdSetLineWidth",
        after: call("hooks::dynamic_state_set", &["self", "crate::recorder::dynamic_bit(vk::DynamicState::LINE_WIDTH)"]),
        ..NONE
    },
    Special {
        command: "vkCmdSetDepthBias",
        after: call("hooks::dynamic_state_set", &["self", "crate::recorder::dynamic_bit(vk::DynamicState::DEPTH_BIAS)"]),
        ..NONE
    },
    Special {
        command: "vkCmdSetBlendConstants",
        after: call("hooks::dynamic_state_set", &["self", "crate::recorder::dynamic_bit(vk::DynamicState::BLEND_CONSTANTS)"]),
        ..NONE
    },
    Special {
        command: "vkCmdSetDepthBounds",
        after: call("hooks::dynamic_state_set", &["self", "crate::recorder::dynamic_bit(vk::DynamicState::DEPTH_BOUNDS)"]),
        ..NONE
    },
    Special {
        command: "vkCmdSetStencilCompareMask",
        after: call("hooks::dynamic_state_set", &["self", "crate::recorder::dynamic_bit(vk::DynamicState::STENCIL_COMPARE_MASK)"]),
        ..NONE
    },
    Special {
        command: "vkCmdSetStencilWriteMask",
        after: call("hooks::depth_stencil_set", &["self", "crate::recorder::Set::WriteMask(face_mask, write_mask)", "crate::recorder::dynamic_bit(vk::DynamicState::STENCIL_WRITE_MASK)"]),
        ..NONE
    },
    Special {
        command: "vkCmdSetStencilReference",
        after: call("hooks::dynamic_state_set", &["self", "crate::recorder::dynamic_bit(vk::DynamicState::STENCIL_REFERENCE)"]),
        ..NONE
    },
    Special {
        command: "vkCmdSetCullMode",
        after: call("hooks::dynamic_state_set", &["self", "crate::recorder::dynamic_bit(vk::DynamicState::CULL_MODE)"]),
        ..NONE
    },
    Special {
        command: "vkCmdSetFrontFace",
        after: call("hooks::dynamic_state_set", &["self", "crate::recorder::dynamic_bit(vk::DynamicState::FRONT_FACE)"]),
        ..NONE
    },
    Special {
        command: "vkCmdSetPrimitiveTopology",
        after: call("hooks::dynamic_state_set", &["self", "crate::recorder::dynamic_bit(vk::DynamicState::PRIMITIVE_TOPOLOGY)"]),
        ..NONE
    },
    Special {
        command: "vkCmdSetDepthTestEnable",
        after: call("hooks::depth_stencil_set", &["self", "crate::recorder::Set::DepthTest(depth_test_enable)", "crate::recorder::dynamic_bit(vk::DynamicState::DEPTH_TEST_ENABLE)"]),
        ..NONE
    },
    Special {
        command: "vkCmdSetDepthWriteEnable",
        after: call("hooks::depth_stencil_set", &["self", "crate::recorder::Set::DepthWrite(depth_write_enable)", "crate::recorder::dynamic_bit(vk::DynamicState::DEPTH_WRITE_ENABLE)"]),
        ..NONE
    },
    Special {
        command: "vkCmdSetDepthCompareOp",
        after: call("hooks::dynamic_state_set", &["self", "crate::recorder::dynamic_bit(vk::DynamicState::DEPTH_COMPARE_OP)"]),
        ..NONE
    },
    Special {
        command: "vkCmdSetDepthBoundsTestEnable",
        after: call("hooks::dynamic_state_set", &["self", "crate::recorder::dynamic_bit(vk::DynamicState::DEPTH_BOUNDS_TEST_ENABLE)"]),
        ..NONE
    },
    Special {
        command: "vkCmdSetStencilTestEnable",
        after: call("hooks::depth_stencil_set", &["self", "crate::recorder::Set::StencilTest(stencil_test_enable)", "crate::recorder::dynamic_bit(vk::DynamicState::STENCIL_TEST_ENABLE)"]),
        ..NONE
    },
    Special {
        command: "vkCmdSetStencilOp",
        after: call("hooks::depth_stencil_set", &["self", "crate::recorder::Set::StencilOp(face_mask, [fail_op, pass_op, depth_fail_op])", "crate::recorder::dynamic_bit(vk::DynamicState::STENCIL_OP)"]),
        ..NONE
    },
    Special {
        command: "vkCmdSetRasterizerDiscardEnable",
        after: call("hooks::depth_stencil_set", &["self", "crate::recorder::Set::Discard(rasterizer_discard_enable)", "crate::recorder::dynamic_bit(vk::DynamicState::RASTERIZER_DISCARD_ENABLE)"]),
        ..NONE
    },
    Special {
        command: "vkCmdSetDepthBiasEnable",
        after: call("hooks::dynamic_state_set", &["self", "crate::recorder::dynamic_bit(vk::DynamicState::DEPTH_BIAS_ENABLE)"]),
        ..NONE
    },
    Special {
        command: "vkCmdSetPrimitiveRestartEnable",
        after: call("hooks::dynamic_state_set", &["self", "crate::recorder::dynamic_bit(vk::DynamicState::PRIMITIVE_RESTART_ENABLE)"]),
        ..NONE
    },
    Special {
        command: "vkCmdSetViewport",
        after: call("hooks::dynamic_state_set", &["self", "crate::recorder::dynamic_bit(vk::DynamicState::VIEWPORT)"]),
        check: call("hooks::cmd_set_viewport_checks", &["self", "first_viewport", "viewports"]),
        settles: &[
            ("VUID-vkCmdSetViewport-firstViewport-01223", How::Dynamic(VIEWPORTS)),
            ("VUID-vkCmdSetViewport-firstViewport-01224", How::Dynamic(MULTI_VIEWPORT)),
            ("VUID-vkCmdSetViewport-viewportCount-01225", How::Dynamic(MULTI_VIEWPORT)),
        ],
        ..NONE
    },
    Special {
        command: "vkCmdSetScissor",
        after: call("hooks::dynamic_state_set", &["self", "crate::recorder::dynamic_bit(vk::DynamicState::SCISSOR)"]),
        check: call("hooks::cmd_set_scissor_checks", &["self", "first_scissor", "scissors"]),
        settles: &[
            ("VUID-vkCmdSetScissor-firstScissor-00592", How::Dynamic(VIEWPORTS)),
            ("VUID-vkCmdSetScissor-firstScissor-00593", How::Dynamic(MULTI_VIEWPORT)),
            ("VUID-vkCmdSetScissor-scissorCount-00594", How::Dynamic(MULTI_VIEWPORT)),
            ("VUID-vkCmdSetScissor-x-00595", How::Dynamic(SCISSORS)),
            ("VUID-vkCmdSetScissor-offset-00596", How::Dynamic(SCISSORS)),
            ("VUID-vkCmdSetScissor-offset-00597", How::Dynamic(SCISSORS)),
        ],
        ..NONE
    },
    Special {
        command: "vkCmdSetViewportWithCount",
        after: call("hooks::viewport_count_set", &["self", "viewports.len()", "crate::recorder::dynamic_bit(vk::DynamicState::VIEWPORT_WITH_COUNT)"]),
        check: call("hooks::cmd_set_viewport_with_count_checks", &["self", "viewports"]),
        settles: &[
            ("VUID-vkCmdSetViewportWithCount-viewportCount-03394", How::Dynamic(VIEWPORTS)),
            ("VUID-vkCmdSetViewportWithCount-viewportCount-03395", How::Dynamic(MULTI_VIEWPORT)),
        ],
        ..NONE
    },
    Special {
        command: "vkCmdSetScissorWithCount",
        after: call("hooks::viewport_count_set", &["self", "scissors.len()", "crate::recorder::dynamic_bit(vk::DynamicState::SCISSOR_WITH_COUNT)"]),
        check: call("hooks::cmd_set_scissor_with_count_checks", &["self", "scissors"]),
        settles: &[
            ("VUID-vkCmdSetScissorWithCount-scissorCount-03397", How::Dynamic(VIEWPORTS)),
            ("VUID-vkCmdSetScissorWithCount-scissorCount-03398", How::Dynamic(MULTI_VIEWPORT)),
            ("VUID-vkCmdSetScissorWithCount-x-03399", How::Dynamic(SCISSORS)),
            ("VUID-vkCmdSetScissorWithCount-offset-03400", How::Dynamic(SCISSORS)),
            ("VUID-vkCmdSetScissorWithCount-offset-03401", How::Dynamic(SCISSORS)),
        ],
        ..NONE
    },
    Special {
        command: "vkCreateComputePipelines",
        check: call("hooks::create_compute_pipelines_checks", &["self", "create_infos"]),
        hold: call("hooks::pipeline_cache_gate", &["self", "pipeline_cache"]),
        created: call(
            "hooks::compute_pipelines_created",
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
        check: call("hooks::create_graphics_pipelines_checks", &["self", "create_infos"]),
        hold: call("hooks::pipeline_cache_gate", &["self", "pipeline_cache"]),
        check_last: call(
            "hooks::graphics_pipeline_state_checks",
            &["self", "create_infos"],
        ),
        created: call(
            "hooks::graphics_pipelines_created",
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
    Special {
        command: "vkCreateFramebuffer",
        check_last: call("hooks::create_framebuffer_checks", &["self", "create_info"]),
        created: call("hooks::framebuffer_created", &["self", "created", "create_info"]),
        settles: &[
            ("VUID-vkCreateFramebuffer-pCreateInfo-02777", How::User(UNPROVEN_OTHER_DEVICE_VIEW)),
            ("VUID-VkFramebufferCreateInfo-attachmentCount-00876", How::Dynamic(FRAMEBUFFER_ATTACHMENTS)),
            ("VUID-VkFramebufferCreateInfo-pAttachments-00877", How::Dynamic(FRAMEBUFFER_ATTACHMENTS)),
            ("VUID-VkFramebufferCreateInfo-pAttachments-02633", How::Dynamic(FRAMEBUFFER_ATTACHMENTS)),
            ("VUID-VkFramebufferCreateInfo-pAttachments-00879", How::User(UNPROVEN_FRAMEBUFFER_ROLES)),
            ("VUID-VkFramebufferCreateInfo-pAttachments-00880", How::Dynamic(FRAMEBUFFER_ATTACHMENTS)),
            ("VUID-VkFramebufferCreateInfo-pAttachments-00881", How::Dynamic(FRAMEBUFFER_ATTACHMENTS)),
            ("VUID-VkFramebufferCreateInfo-flags-04533", How::Dynamic(FRAMEBUFFER_ATTACHMENTS)),
            ("VUID-VkFramebufferCreateInfo-flags-04534", How::Dynamic(FRAMEBUFFER_ATTACHMENTS)),
            ("VUID-VkFramebufferCreateInfo-flags-04535", How::Dynamic(FRAMEBUFFER_ATTACHMENTS)),
            ("VUID-VkFramebufferCreateInfo-pAttachments-00883", How::Dynamic(FRAMEBUFFER_ATTACHMENTS)),
            ("VUID-VkFramebufferCreateInfo-pAttachments-00884", How::Dynamic(FRAMEBUFFER_ATTACHMENTS)),
            ("VUID-VkFramebufferCreateInfo-flags-04113", How::Dynamic(FRAMEBUFFER_ATTACHMENTS)),
            ("VUID-VkFramebufferCreateInfo-pAttachments-02634", How::User(UNPROVEN_FRAMEBUFFER_ROLES)),
            ("VUID-VkFramebufferCreateInfo-renderPass-04536", How::User(UNPROVEN_FRAMEBUFFER_MULTIVIEW)),
            ("VUID-VkFramebufferCreateInfo-renderPass-02531", How::User(UNPROVEN_FRAMEBUFFER_MULTIVIEW)),
            ("VUID-VkFramebufferCreateInfo-pAttachments-00891", How::User(UNPROVEN_DEPTH_3D)),
            ("VUID-VkFramebufferCreateInfo-flags-03190", How::Dynamic(FRAMEBUFFER_ATTACHMENTS)),
            ("VUID-VkFramebufferCreateInfo-flags-03191", How::Dynamic(FRAMEBUFFER_ATTACHMENTS)),
            ("VUID-VkFramebufferCreateInfo-flags-04541", How::Dynamic(FRAMEBUFFER_ATTACHMENTS)),
            ("VUID-VkFramebufferCreateInfo-flags-04542", How::Dynamic(FRAMEBUFFER_ATTACHMENTS)),
            ("VUID-VkFramebufferCreateInfo-flags-03201", How::Dynamic(FRAMEBUFFER_ATTACHMENTS)),
            ("VUID-VkFramebufferCreateInfo-flags-03202", How::Dynamic(FRAMEBUFFER_ATTACHMENTS)),
            ("VUID-VkFramebufferCreateInfo-flags-03204", How::User(UNPROVEN_FRAMEBUFFER_ROLES)),
            ("VUID-VkFramebufferCreateInfo-flags-03205", How::Dynamic(FRAMEBUFFER_ATTACHMENTS)),
            ("VUID-VkFramebufferCreateInfo-renderPass-03198", How::User(UNPROVEN_FRAMEBUFFER_MULTIVIEW)),
            ("VUID-VkFramebufferCreateInfo-renderPass-04546", How::Dynamic(FRAMEBUFFER_ATTACHMENTS)),
            ("VUID-VkFramebufferCreateInfo-flags-02778", How::Static("set from wrappers, which always hold valid image views")),
        ],
        ..NONE
    },
    Special {
        command: "vkCreateImageView",
        check_last: call("hooks::image_view_checks", &["self", "create_info"]),
        created: call("hooks::image_view_created", &["self", "created", "create_info"]),
        settles: &[
            ("VUID-VkImageSubresourceRange-aspectMask-01670", How::User(UNPROVEN_VIEW_PLANES)),
            ("VUID-VkImageViewCreateInfo-subresourceRange-07818", How::User(UNPROVEN_VIEW_PLANES)),
            ("VUID-VkImageViewCreateInfo-image-01003", How::Dynamic(VIEW_TYPE)),
            ("VUID-VkImageViewCreateInfo-image-04441", How::Dynamic(VIEW_TYPE)),
            ("VUID-VkImageViewCreateInfo-subResourceRange-01021", How::Dynamic(VIEW_TYPE)),
            ("VUID-VkImageViewCreateInfo-image-06723", How::Dynamic(VIEW_TYPE)),
            ("VUID-VkImageViewCreateInfo-image-06727", How::Dynamic(VIEW_TYPE)),
            ("VUID-VkImageViewCreateInfo-image-04970", How::Dynamic(VIEW_RANGE)),
            ("VUID-VkImageViewCreateInfo-image-04971", How::User(UNPROVEN_SPARSE_VIEW)),
            ("VUID-VkImageViewCreateInfo-image-04972", How::Dynamic(VIEW_TYPE)),
            ("VUID-VkImageViewCreateInfo-image-02724", How::Dynamic(VIEW_RANGE)),
            ("VUID-VkImageViewCreateInfo-subresourceRange-02725", How::Dynamic(VIEW_RANGE)),
            ("VUID-VkImageViewCreateInfo-image-01482", How::Dynamic(VIEW_RANGE)),
            ("VUID-VkImageViewCreateInfo-subresourceRange-01483", How::Dynamic(VIEW_RANGE)),
            ("VUID-VkImageViewCreateInfo-imageViewType-04973", How::Dynamic(VIEW_RANGE)),
            ("VUID-VkImageViewCreateInfo-imageViewType-04974", How::Dynamic(VIEW_RANGE)),
            ("VUID-VkImageViewCreateInfo-viewType-02962", How::Dynamic(VIEW_RANGE)),
            ("VUID-VkImageViewCreateInfo-viewType-02963", How::User(UNPROVEN_CUBE_ARRAY)),
            ("VUID-VkImageViewCreateInfo-image-01761", How::Dynamic(VIEW_FORMAT)),
            ("VUID-VkImageViewCreateInfo-image-01583", How::Dynamic(VIEW_FORMAT)),
            ("VUID-VkImageViewCreateInfo-image-07072", How::Dynamic(VIEW_FORMAT)),
            ("VUID-VkImageViewCreateInfo-pNext-01585", How::Dynamic(VIEW_FORMAT)),
            ("VUID-VkImageViewCreateInfo-image-01586", How::User(UNPROVEN_VIEW_PLANES)),
            ("VUID-VkImageViewCreateInfo-image-01762", How::Dynamic(VIEW_FORMAT)),
            ("VUID-VkImageViewCreateInfo-format-04714", How::User(UNPROVEN_VIEW_PLANES)),
            ("VUID-VkImageViewCreateInfo-format-04715", How::User(UNPROVEN_VIEW_PLANES)),
            ("VUID-VkImageViewCreateInfo-pNext-01970", How::User(UNPROVEN_VIEW_PLANES)),
            ("VUID-VkImageViewCreateInfo-pNext-06658", How::User(UNPROVEN_VIEW_PLANES)),
            ("VUID-VkImageViewCreateInfo-format-06415", How::User(UNPROVEN_VIEW_PLANES)),
            ("VUID-VkImageViewCreateInfo-pNext-02662", How::Dynamic(VIEW_USAGE)),
            ("VUID-VkImageViewCreateInfo-pNext-02663", How::Dynamic(VIEW_USAGE)),
            ("VUID-VkImageViewCreateInfo-pNext-02664", How::Dynamic(VIEW_USAGE)),
            ("VUID-VkImageViewCreateInfo-None-02273", How::User(UNPROVEN_VIEW_FEATURES)),
            ("VUID-VkImageViewCreateInfo-usage-02274", How::User(UNPROVEN_VIEW_FEATURES)),
            ("VUID-VkImageViewCreateInfo-usage-02275", How::Dynamic(VIEW_USAGE)),
            ("VUID-VkImageViewCreateInfo-usage-02276", How::User(UNPROVEN_VIEW_FEATURES)),
            ("VUID-VkImageViewCreateInfo-usage-02277", How::User(UNPROVEN_VIEW_FEATURES)),
            ("VUID-VkImageViewCreateInfo-usage-02652", How::User(UNPROVEN_VIEW_FEATURES)),
        ],
        ..NONE
    },
    Special {
        command: "vkCreateSamplerYcbcrConversion",
        created: call("hooks::conversion_created", &["self", "created", "create_info"]),
        ..NONE
    },
    Special {
        command: "vkCreateRenderPass",
        check: call("hooks::create_render_pass_checks", &["create_info"]),
        check_last: call(
            "hooks::render_pass_reference_checks",
            &["self", "create_info"],
        ),
        created: call("hooks::render_pass_created", &["self", "created", "create_info"]),
        settles: &[
            ("VUID-VkAttachmentDescription-format-06698", How::Dynamic(ATTACHMENT_DESCRIPTIONS)),
            ("VUID-VkAttachmentDescription-format-06242", How::Dynamic(ATTACHMENT_DESCRIPTIONS)),
            ("VUID-VkAttachmentDescription-format-06243", How::Dynamic(ATTACHMENT_DESCRIPTIONS)),
            ("VUID-VkAttachmentDescription-format-06906", How::Dynamic(ATTACHMENT_DESCRIPTIONS)),
            ("VUID-VkAttachmentDescription-format-06907", How::Dynamic(ATTACHMENT_DESCRIPTIONS)),
            ("VUID-VkRenderPassCreateInfo-pAttachments-00836", How::Dynamic(FIRST_USE)),
            ("VUID-VkRenderPassCreateInfo-pAttachments-02511", How::Dynamic(FIRST_USE)),
            ("VUID-VkRenderPassCreateInfo-pAttachments-01566", How::Dynamic(FIRST_USE)),
            ("VUID-VkRenderPassCreateInfo-pAttachments-01567", How::Dynamic(FIRST_USE)),
            ("VUID-VkSubpassDescription-loadOp-00846", How::Dynamic(FIRST_USE)),
            ("VUID-VkSubpassDescription-attachment-06915", How::Dynamic(ATTACHMENT_DESCRIPTIONS)),
            ("VUID-VkRenderPassCreateInfo-pDependencies-00837", How::Dynamic(DEPENDENCIES)),
            ("VUID-VkRenderPassCreateInfo-pDependencies-00838", How::Dynamic(DEPENDENCIES)),
            ("VUID-VkSubpassDependency-srcSubpass-00864", How::Dynamic(DEPENDENCIES)),
            ("VUID-VkSubpassDependency-srcSubpass-00865", How::Dynamic(DEPENDENCIES)),
            ("VUID-VkSubpassDependency-srcSubpass-06809", How::Dynamic(DEPENDENCIES)),
            ("VUID-VkSubpassDependency-srcSubpass-02243", How::Dynamic(DEPENDENCIES)),
            ("VUID-VkSubpassDependency-srcAccessMask-00868", How::Dynamic(DEPENDENCIES)),
            ("VUID-VkSubpassDependency-dstAccessMask-00869", How::Dynamic(DEPENDENCIES)),
            ("VUID-VkSubpassDependency-srcStageMask-03937", How::Dynamic(DEPENDENCIES)),
            ("VUID-VkSubpassDependency-dstStageMask-03937", How::Dynamic(DEPENDENCIES)),
            ("VUID-VkSubpassDependency-srcSubpass-00872", How::Dynamic(MULTIVIEW_MASKS)),
            ("VUID-VkRenderPassCreateInfo-pNext-01930", How::Dynamic(MULTIVIEW_MASKS)),
            ("VUID-VkRenderPassCreateInfo-pNext-02512", How::Dynamic(MULTIVIEW_MASKS)),
            ("VUID-VkRenderPassMultiviewCreateInfo-pCorrelationMasks-00841", How::Dynamic(MULTIVIEW_MASKS)),
            ("VUID-VkRenderPassMultiviewCreateInfo-multiview-06555", How::Dynamic(MULTIVIEW_MASKS)),
            ("VUID-VkRenderPassMultiviewCreateInfo-pViewMasks-06697", How::Dynamic(MULTIVIEW_MASKS)),
            ("VUID-VkRenderPassCreateInfo-pNext-01963", How::Dynamic(ATTACHMENT_DESCRIPTIONS)),
            ("VUID-VkSubpassDescription-attachment-00853", How::Dynamic(SUBPASS_REFERENCES)),
            ("VUID-VkSubpassDescription-pPreserveAttachments-00854", How::Dynamic(SUBPASS_REFERENCES)),
            ("VUID-VkSubpassDescription-pResolveAttachments-00847", How::Dynamic(SUBPASS_REFERENCES)),
            ("VUID-VkSubpassDescription-pResolveAttachments-00848", How::Dynamic(SUBPASS_REFERENCES)),
            ("VUID-VkSubpassDescription-pResolveAttachments-00849", How::Dynamic(SUBPASS_REFERENCES)),
            ("VUID-VkSubpassDescription-pResolveAttachments-00850", How::Dynamic(SUBPASS_REFERENCES)),
            ("VUID-VkSubpassDescription-pInputAttachments-02647", How::Dynamic(SUBPASS_REFERENCES)),
            ("VUID-VkSubpassDescription-pColorAttachments-02648", How::Dynamic(SUBPASS_REFERENCES)),
            ("VUID-VkSubpassDescription-pResolveAttachments-02649", How::User(UNPROVEN_RESOLVE_FEATURES)),
            ("VUID-VkSubpassDescription-pDepthStencilAttachment-02650", How::Dynamic(SUBPASS_REFERENCES)),
            ("VUID-VkSubpassDescription-pColorAttachments-06868", How::Dynamic(SUBPASS_REFERENCES)),
            ("VUID-VkSubpassDescription-pDepthStencilAttachment-01418", How::Dynamic(SUBPASS_REFERENCES)),
            ("VUID-VkSubpassDescription-layout-02519", How::Dynamic(SUBPASS_REFERENCES)),
            ("VUID-VkSubpassDescription-pDepthStencilAttachment-04438", How::Dynamic(SUBPASS_REFERENCES)),
            ("VUID-VkRenderPassCreateInfo-pNext-01929", How::Dynamic(SUBPASS_REFERENCES)),
            ("VUID-VkRenderPassCreateInfo-pNext-02513", How::Dynamic(SUBPASS_REFERENCES)),
            ("VUID-VkRenderPassCreateInfo-pNext-02514", How::Dynamic(SUBPASS_REFERENCES)),
            ("VUID-VkRenderPassCreateInfo-pNext-02515", How::Dynamic(SUBPASS_REFERENCES)),
            ("VUID-VkRenderPassCreateInfo-attachment-00834", How::Dynamic(RENDER_PASS_INDICES)),
            ("VUID-VkRenderPassCreateInfo-pDependencies-06866", How::Dynamic(RENDER_PASS_INDICES)),
            ("VUID-VkRenderPassCreateInfo-pDependencies-06867", How::Dynamic(RENDER_PASS_INDICES)),
            ("VUID-VkRenderPassCreateInfo-pNext-01926", How::Dynamic(RENDER_PASS_INDICES)),
            ("VUID-VkRenderPassCreateInfo-pNext-01927", How::Dynamic(RENDER_PASS_INDICES)),
            ("VUID-VkRenderPassCreateInfo-pNext-01928", How::Dynamic(CHAINED_COUNT)),
        ],
        ..NONE
    },
    Special {
        command: "vkCmdBindPipeline",
        check: call(
            "hooks::cmd_bind_pipeline_checks",
            &["self", "pipeline_bind_point", "pipeline"],
        ),
        settles: &[
            (
                "VUID-vkCmdBindPipeline-pipelineBindPoint-00779",
                How::Dynamic(BIND_POINT),
            ),
            (
                "VUID-vkCmdBindPipeline-pipelineBindPoint-00780",
                How::Dynamic(BIND_POINT),
            ),
            (
                "VUID-vkCmdBindPipeline-pipelineBindPoint-00777",
                How::User(UNPROVEN_FAMILY),
            ),
            ("VUID-vkCmdBindPipeline-pipeline-00781", How::Dynamic(SUBPASS_SAMPLES)),
            (
                "VUID-vkCmdBindPipeline-pipelineBindPoint-00778",
                How::User(UNPROVEN_FAMILY),
            ),
        ],
        after: call(
            "hooks::cmd_bind_pipeline_done",
            &["self", "pipeline_bind_point", "pipeline"],
        ),
        ..NONE
    },
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
        [
            ("VUID-vkCmdDispatchBase-commandBuffer-02712", How::User(UNPROVEN_PROTECTED_BUFFER)),
            ("VUID-vkCmdDispatchBase-commandBuffer-02713", How::User(UNPROVEN_PROTECTED_BUFFER)),
        ]
    ),
    Special {
        command: "vkCmdCopyImage",
        check: call("hooks::image_layout_checks", &["self", "crate::hooks::Names::CopyImage(src_image.raw(), src_image_layout, dst_image.raw(), dst_image_layout, regions)"]),
        after: call("hooks::image_layouts_named", &["self", "crate::hooks::Names::CopyImage(src_image.raw(), src_image_layout, dst_image.raw(), dst_image_layout, regions)"]),
        settles: &[
            ("VUID-vkCmdCopyImage-srcImageLayout-00128", How::Dynamic(LAYOUT)),
            ("VUID-vkCmdCopyImage-dstImageLayout-00133", How::Dynamic(LAYOUT)),
        ],
        ..NONE
    },
    Special {
        command: "vkCmdBlitImage",
        check: call("hooks::image_layout_checks", &["self", "crate::hooks::Names::BlitImage(src_image.raw(), src_image_layout, dst_image.raw(), dst_image_layout, regions)"]),
        after: call("hooks::image_layouts_named", &["self", "crate::hooks::Names::BlitImage(src_image.raw(), src_image_layout, dst_image.raw(), dst_image_layout, regions)"]),
        settles: &[
            ("VUID-vkCmdBlitImage-srcImageLayout-00221", How::Dynamic(LAYOUT)),
            ("VUID-vkCmdBlitImage-dstImageLayout-00226", How::Dynamic(LAYOUT)),
        ],
        ..NONE
    },
    Special {
        command: "vkCmdResolveImage",
        check: call("hooks::image_layout_checks", &["self", "crate::hooks::Names::ResolveImage(src_image.raw(), src_image_layout, dst_image.raw(), dst_image_layout, regions)"]),
        after: call("hooks::image_layouts_named", &["self", "crate::hooks::Names::ResolveImage(src_image.raw(), src_image_layout, dst_image.raw(), dst_image_layout, regions)"]),
        settles: &[
            ("VUID-vkCmdResolveImage-srcImageLayout-00260", How::Dynamic(LAYOUT)),
            ("VUID-vkCmdResolveImage-dstImageLayout-00262", How::Dynamic(LAYOUT)),
        ],
        ..NONE
    },
    Special {
        command: "vkCmdCopyImage2",
        check: call("hooks::image_layout_checks", &["self", "crate::hooks::Names::CopyImage2(copy_image_info)"]),
        after: call("hooks::image_layouts_named", &["self", "crate::hooks::Names::CopyImage2(copy_image_info)"]),
        settles: &[
            ("VUID-VkCopyImageInfo2-srcImageLayout-00128", How::Dynamic(LAYOUT)),
            ("VUID-VkCopyImageInfo2-dstImageLayout-00133", How::Dynamic(LAYOUT)),
        ],
        ..NONE
    },
    Special {
        command: "vkCmdBlitImage2",
        check: call("hooks::image_layout_checks", &["self", "crate::hooks::Names::BlitImage2(blit_image_info)"]),
        after: call("hooks::image_layouts_named", &["self", "crate::hooks::Names::BlitImage2(blit_image_info)"]),
        settles: &[
            ("VUID-VkBlitImageInfo2-srcImageLayout-00221", How::Dynamic(LAYOUT)),
            ("VUID-VkBlitImageInfo2-dstImageLayout-00226", How::Dynamic(LAYOUT)),
        ],
        ..NONE
    },
    Special {
        command: "vkCmdResolveImage2",
        check: call("hooks::image_layout_checks", &["self", "crate::hooks::Names::ResolveImage2(resolve_image_info)"]),
        after: call("hooks::image_layouts_named", &["self", "crate::hooks::Names::ResolveImage2(resolve_image_info)"]),
        settles: &[
            ("VUID-VkResolveImageInfo2-srcImageLayout-00260", How::Dynamic(LAYOUT)),
            ("VUID-VkResolveImageInfo2-dstImageLayout-00262", How::Dynamic(LAYOUT)),
        ],
        ..NONE
    },
    Special {
        command: "vkCmdClearColorImage",
        check: call("hooks::image_layout_checks", &["self", "crate::hooks::Names::ClearColor(image.raw(), image_layout, ranges)"]),
        after: call("hooks::image_layouts_named", &["self", "crate::hooks::Names::ClearColor(image.raw(), image_layout, ranges)"]),
        settles: &[
            ("VUID-vkCmdClearColorImage-imageLayout-00004", How::Dynamic(LAYOUT)),
        ],
        ..NONE
    },
    Special {
        command: "vkCmdClearDepthStencilImage",
        check: call("hooks::image_layout_checks", &["self", "crate::hooks::Names::ClearDepthStencil(image.raw(), image_layout, ranges)"]),
        after: call("hooks::image_layouts_named", &["self", "crate::hooks::Names::ClearDepthStencil(image.raw(), image_layout, ranges)"]),
        settles: &[
            ("VUID-vkCmdClearDepthStencilImage-imageLayout-00011", How::Dynamic(LAYOUT)),
        ],
        ..NONE
    },
    Special {
        command: "vkCmdPipelineBarrier",
        check: call(
            "hooks::pipeline_barrier_checks",
            &[
                "self",
                "src_stage_mask",
                "dst_stage_mask",
                "dependency_flags",
                "memory_barriers",
                "buffer_memory_barriers",
                "image_memory_barriers",
            ],
        ),
        after: call("hooks::cmd_pipeline_barrier_done", &["self", "image_memory_barriers"]),
        settles: &[
            ("VUID-VkImageMemoryBarrier-oldLayout-01197", How::Dynamic(LAYOUT_BARRIER)),
            ("VUID-vkCmdPipelineBarrier-pDependencies-02285", How::Dynamic(BARRIER)),
            ("VUID-vkCmdPipelineBarrier-image-04073", How::Dynamic(BARRIER)),
            ("VUID-VkImageMemoryBarrier-oldLayout-01208", How::Dynamic(BARRIER)),
            ("VUID-VkImageMemoryBarrier-oldLayout-01209", How::Dynamic(BARRIER)),
            ("VUID-VkImageMemoryBarrier-oldLayout-01210", How::Dynamic(BARRIER)),
            ("VUID-VkImageMemoryBarrier-oldLayout-01211", How::Dynamic(BARRIER)),
            ("VUID-VkImageMemoryBarrier-oldLayout-01212", How::Dynamic(BARRIER)),
            ("VUID-VkImageMemoryBarrier-oldLayout-01213", How::Dynamic(BARRIER)),
            ("VUID-VkImageMemoryBarrier-oldLayout-01658", How::Dynamic(BARRIER)),
            ("VUID-VkImageMemoryBarrier-oldLayout-01659", How::Dynamic(BARRIER)),
            ("VUID-VkImageMemoryBarrier-newLayout-01198", How::Dynamic(BARRIER)),
            ("VUID-VkImageMemoryBarrier-image-01671", How::Dynamic(BARRIER)),
            ("VUID-VkImageMemoryBarrier-image-03319", How::Dynamic(BARRIER)),
            ("VUID-VkImageMemoryBarrier-image-03320", How::Dynamic(BARRIER)),
            ("VUID-VkImageMemoryBarrier-image-04072", How::Dynamic(BARRIER)),
            ("VUID-VkImageMemoryBarrier-srcQueueFamilyIndex-03938", How::Dynamic(BARRIER_ALONE)),
            ("VUID-VkImageMemoryBarrier-srcQueueFamilyIndex-03939", How::Dynamic(BARRIER_ALONE)),
            ("VUID-VkImageMemoryBarrier-srcQueueFamilyIndex-04065", How::Dynamic(BARRIER_ALONE)),
            ("VUID-VkImageMemoryBarrier-srcQueueFamilyIndex-04066", How::Dynamic(BARRIER_ALONE)),
            ("VUID-VkImageMemoryBarrier-srcQueueFamilyIndex-04067", How::Dynamic(BARRIER_ALONE)),
            ("VUID-VkImageMemoryBarrier-srcQueueFamilyIndex-04068", How::Dynamic(BARRIER_ALONE)),
            ("VUID-VkImageMemoryBarrier-srcQueueFamilyIndex-04070", How::Dynamic(BARRIER_ALONE)),
            ("VUID-VkBufferMemoryBarrier-buffer-04089", How::Dynamic(BARRIER)),
            ("VUID-VkBufferMemoryBarrier-srcQueueFamilyIndex-04087", How::Dynamic(BARRIER_ALONE)),
            ("VUID-vkCmdPipelineBarrier-srcAccessMask-02815", How::Dynamic(BARRIER)),
            ("VUID-vkCmdPipelineBarrier-dstAccessMask-02816", How::Dynamic(BARRIER)),
            ("VUID-vkCmdPipelineBarrier-dependencyFlags-01186", How::Dynamic(BARRIER)),
            ("VUID-vkCmdPipelineBarrier-bufferMemoryBarrierCount-01178", How::Dynamic(BARRIER)),
            ("VUID-vkCmdPipelineBarrier-oldLayout-01181", How::Dynamic(BARRIER)),
            ("VUID-vkCmdPipelineBarrier-srcQueueFamilyIndex-01182", How::Dynamic(BARRIER)),
            ("VUID-vkCmdPipelineBarrier-None-06191", How::Dynamic(BARRIER)),
            ("VUID-vkCmdPipelineBarrier-srcStageMask-03937", How::Dynamic(BARRIER)),
            ("VUID-vkCmdPipelineBarrier-dstStageMask-03937", How::Dynamic(BARRIER)),
            ("VUID-vkCmdPipelineBarrier-pBufferMemoryBarriers-02817", How::Dynamic(BARRIER_ACCESS)),
            ("VUID-vkCmdPipelineBarrier-pBufferMemoryBarriers-02818", How::Dynamic(BARRIER_ACCESS)),
            ("VUID-vkCmdPipelineBarrier-pImageMemoryBarriers-02819", How::Dynamic(BARRIER_ACCESS)),
            ("VUID-vkCmdPipelineBarrier-pImageMemoryBarriers-02820", How::Dynamic(BARRIER_ACCESS)),
            ("VUID-VkImageMemoryBarrier-image-04071", How::User(BARRIER_CONCURRENT)),
            ("VUID-VkImageMemoryBarrier-synchronization2-03857", How::User(BARRIER_CONCURRENT)),
            ("VUID-VkBufferMemoryBarrier-buffer-04088", How::User(BARRIER_CONCURRENT)),
            ("VUID-VkBufferMemoryBarrier-synchronization2-03853", How::User(BARRIER_CONCURRENT)),
            ("VUID-VkImageMemoryBarrier-image-01672", How::User(BARRIER_PLANES)),
            ("VUID-VkImageMemoryBarrier-image-01673", How::User(BARRIER_PLANES)),
            ("VUID-vkCmdPipelineBarrier-srcStageMask-06461", How::User(BARRIER_FAMILY)),
            ("VUID-vkCmdPipelineBarrier-dstStageMask-06462", How::User(BARRIER_FAMILY)),
        ],
        ..NONE
    },
    Special {
        command: "vkCmdWaitEvents",
        check: call(
            "hooks::wait_events_checks",
            &["self", "buffer_memory_barriers", "image_memory_barriers"],
        ),
        after: call(
            "hooks::wait_events_done",
            &["self", "events", "image_memory_barriers"],
        ),
        ..NONE
    },
    Special {
        command: "vkCmdPipelineBarrier2",
        check: call("hooks::dependency_checks", &["self", "core::slice::from_ref(dependency_info)"]),
        after: call("hooks::dependency_done", &["self", "core::slice::from_ref(dependency_info)"]),
        settles: &[("VUID-VkImageMemoryBarrier2-oldLayout-01197", How::Dynamic(LAYOUT_BARRIER))],
        ..NONE
    },
    Special {
        command: "vkCmdWaitEvents2",
        check: call("hooks::dependency_checks", &["self", "dependency_infos"]),
        after: call("hooks::wait_events2_done", &["self", "events", "dependency_infos"]),
        ..NONE
    },
    Special {
        command: "vkCmdSetEvent",
        after: call("hooks::event_recorded", &["self", "event"]),
        ..NONE
    },
    Special {
        command: "vkCmdResetEvent",
        after: call("hooks::event_recorded", &["self", "event"]),
        ..NONE
    },
    Special {
        command: "vkCmdSetEvent2",
        after: call("hooks::event_recorded", &["self", "event"]),
        ..NONE
    },
    Special {
        command: "vkCmdResetEvent2",
        after: call("hooks::event_recorded", &["self", "event"]),
        ..NONE
    },
    Special {
        command: "vkCmdCopyBufferToImage",
        check: call("hooks::image_layout_checks", &["self", "crate::hooks::Names::BufferToImage(dst_image.raw(), dst_image_layout, regions)"]),
        after: call("hooks::image_layouts_named", &["self", "crate::hooks::Names::BufferToImage(dst_image.raw(), dst_image_layout, regions)"]),
        check_last: call(
            "hooks::cmd_copy_buffer_to_image_checks",
            &["self", "src_buffer", "dst_image", "regions"],
        ),
        settles: &[
            ("VUID-vkCmdCopyBufferToImage-bufferRowLength-00203", How::Dynamic(COPY_REGION)),
            ("VUID-vkCmdCopyBufferToImage-bufferImageHeight-00204", How::Dynamic(COPY_REGION)),
            ("VUID-vkCmdCopyBufferToImage-pRegions-07274", How::Dynamic(COPY_REGION)),
            ("VUID-vkCmdCopyBufferToImage-pRegions-07275", How::Dynamic(COPY_REGION)),
            ("VUID-vkCmdCopyBufferToImage-imageExtent-00207", How::Dynamic(COPY_REGION)),
            ("VUID-vkCmdCopyBufferToImage-imageExtent-00208", How::Dynamic(COPY_REGION)),
            ("VUID-vkCmdCopyBufferToImage-pRegions-07273", How::Dynamic(COPY_REGION)),
            ("VUID-vkCmdCopyBufferToImage-srcImage-04053", How::Dynamic(COPY_REGION)),
            ("VUID-vkCmdCopyBufferToImage-pRegions-07277", How::Dynamic(COPY_ROW_PITCH)),
            ("VUID-vkCmdCopyBufferToImage-dstImage-00179", How::Dynamic(COPY_REGION)),
            ("VUID-vkCmdCopyBufferToImage-pRegions-00173", How::Dynamic(COPY_OVERLAP)),
            ("VUID-vkCmdCopyBufferToImage-srcImage-00201", How::Dynamic(COPY_REGION)),
            ("VUID-vkCmdCopyBufferToImage-imageOffset-00200", How::Dynamic(COPY_REGION)),
            ("VUID-vkCmdCopyBufferToImage-aspectMask-00211", How::Dynamic(COPY_REGION)),
            ("VUID-vkCmdCopyBufferToImage-srcImage-00199", How::User(COPY_SAME_AS_Y)),
            ("VUID-vkCmdCopyBufferToImage-baseArrayLayer-00213", How::User(COPY_SAME_AS_LAYERS)),
            ("VUID-vkCmdCopyBufferToImage-pRegions-06217", How::User(COPY_SAME_AS_RANGES)),
            ("VUID-vkCmdCopyBufferToImage-pRegions-07276", How::User(COPY_BLOCK_DEPTH)),
            ("VUID-vkCmdCopyBufferToImage-imageExtent-00209", How::User(COPY_BLOCK_DEPTH)),
            ("VUID-vkCmdCopyBufferToImage-pRegions-07740", How::User(COPY_PLANES)),
            ("VUID-vkCmdCopyBufferToImage-pRegions-07741", How::User(COPY_PLANES)),
            ("VUID-vkCmdCopyBufferToImage-bufferOffset-01559", How::User(COPY_PLANES)),
            ("VUID-vkCmdCopyBufferToImage-bufferOffset-01558", How::User(COPY_SAME_AS_SIZE)),
            ("VUID-vkCmdCopyBufferToImage-dstImage-01997", How::User(COPY_FEATURES)),
            ("VUID-vkCmdCopyBufferToImage-commandBuffer-07737", How::User(COPY_FAMILY)),
            ("VUID-vkCmdCopyBufferToImage-imageOffset-07738", How::User(COPY_FAMILY)),
            ("VUID-vkCmdCopyBufferToImage-commandBuffer-07739", How::User(COPY_FAMILY)),
            ("VUID-vkCmdCopyBufferToImage-commandBuffer-01828", How::User(COPY_PROTECTED)),
            ("VUID-vkCmdCopyBufferToImage-commandBuffer-01829", How::User(COPY_PROTECTED)),
            ("VUID-vkCmdCopyBufferToImage-commandBuffer-01830", How::User(COPY_PROTECTED)),
            ("VUID-VkBufferImageCopy-bufferRowLength-00195", How::Dynamic(COPY_REGION)),
            ("VUID-VkBufferImageCopy-bufferImageHeight-00196", How::Dynamic(COPY_REGION)),
            ("VUID-VkBufferImageCopy-aspectMask-00212", How::Dynamic(COPY_REGION)),
            ("VUID-vkCmdCopyBufferToImage-dstImageLayout-00180", How::Dynamic(LAYOUT)),(
            "VUID-vkCmdCopyBufferToImage-pRegions-00171",
            How::Dynamic(BUFFER_IMAGE_RANGE),
        )],
        ..NONE
    },
    Special {
        command: "vkCmdCopyImageToBuffer",
        check: call("hooks::image_layout_checks", &["self", "crate::hooks::Names::ImageToBuffer(src_image.raw(), src_image_layout, regions)"]),
        after: call("hooks::image_layouts_named", &["self", "crate::hooks::Names::ImageToBuffer(src_image.raw(), src_image_layout, regions)"]),
        check_last: call(
            "hooks::cmd_copy_image_to_buffer_checks",
            &["self", "src_image", "dst_buffer", "regions"],
        ),
        settles: &[
            ("VUID-vkCmdCopyImageToBuffer-bufferRowLength-00203", How::Dynamic(COPY_REGION)),
            ("VUID-vkCmdCopyImageToBuffer-bufferImageHeight-00204", How::Dynamic(COPY_REGION)),
            ("VUID-vkCmdCopyImageToBuffer-pRegions-07274", How::Dynamic(COPY_REGION)),
            ("VUID-vkCmdCopyImageToBuffer-pRegions-07275", How::Dynamic(COPY_REGION)),
            ("VUID-vkCmdCopyImageToBuffer-imageExtent-00207", How::Dynamic(COPY_REGION)),
            ("VUID-vkCmdCopyImageToBuffer-imageExtent-00208", How::Dynamic(COPY_REGION)),
            ("VUID-vkCmdCopyImageToBuffer-pRegions-07273", How::Dynamic(COPY_REGION)),
            ("VUID-vkCmdCopyImageToBuffer-srcImage-04053", How::Dynamic(COPY_REGION)),
            ("VUID-vkCmdCopyImageToBuffer-pRegions-07277", How::Dynamic(COPY_ROW_PITCH)),
            ("VUID-vkCmdCopyImageToBuffer-srcImage-00188", How::Dynamic(COPY_REGION)),
            ("VUID-vkCmdCopyImageToBuffer-pRegions-00184", How::Dynamic(COPY_OVERLAP)),
            ("VUID-vkCmdCopyImageToBuffer-srcImage-00201", How::Dynamic(COPY_REGION)),
            ("VUID-vkCmdCopyImageToBuffer-imageOffset-00200", How::Dynamic(COPY_REGION)),
            ("VUID-vkCmdCopyImageToBuffer-aspectMask-00211", How::Dynamic(COPY_REGION)),
            ("VUID-vkCmdCopyImageToBuffer-srcImage-00199", How::User(COPY_SAME_AS_Y)),
            ("VUID-vkCmdCopyImageToBuffer-baseArrayLayer-00213", How::User(COPY_SAME_AS_LAYERS)),
            ("VUID-vkCmdCopyImageToBuffer-pRegions-06220", How::User(COPY_SAME_AS_RANGES)),
            ("VUID-vkCmdCopyImageToBuffer-pRegions-07276", How::User(COPY_BLOCK_DEPTH)),
            ("VUID-vkCmdCopyImageToBuffer-imageExtent-00209", How::User(COPY_BLOCK_DEPTH)),
            ("VUID-vkCmdCopyImageToBuffer-pRegions-07740", How::User(COPY_PLANES)),
            ("VUID-vkCmdCopyImageToBuffer-pRegions-07741", How::User(COPY_PLANES)),
            ("VUID-vkCmdCopyImageToBuffer-bufferOffset-01559", How::User(COPY_PLANES)),
            ("VUID-vkCmdCopyImageToBuffer-bufferOffset-01558", How::User(COPY_SAME_AS_SIZE)),
            ("VUID-vkCmdCopyImageToBuffer-srcImage-01998", How::User(COPY_FEATURES)),
            ("VUID-vkCmdCopyImageToBuffer-commandBuffer-07746", How::User(COPY_FAMILY)),
            ("VUID-vkCmdCopyImageToBuffer-imageOffset-07747", How::User(COPY_FAMILY)),
            ("VUID-vkCmdCopyImageToBuffer-commandBuffer-01831", How::User(COPY_PROTECTED)),
            ("VUID-vkCmdCopyImageToBuffer-commandBuffer-01832", How::User(COPY_PROTECTED)),
            ("VUID-vkCmdCopyImageToBuffer-commandBuffer-01833", How::User(COPY_PROTECTED)),
            ("VUID-VkImageSubresourceLayers-aspectMask-00167", How::Dynamic(COPY_REGION)),
            ("VUID-vkCmdCopyImageToBuffer-srcImageLayout-00189", How::Dynamic(LAYOUT)),(
            "VUID-vkCmdCopyImageToBuffer-pRegions-00183",
            How::Dynamic(BUFFER_IMAGE_RANGE),
        )],
        ..NONE
    },
    Special {
        command: "vkCmdCopyBufferToImage2",
        check: call("hooks::image_layout_checks", &["self", "crate::hooks::Names::BufferToImage2(copy_buffer_to_image_info)"]),
        after: call("hooks::image_layouts_named", &["self", "crate::hooks::Names::BufferToImage2(copy_buffer_to_image_info)"]),
        check_last: call(
            "hooks::cmd_copy_buffer_to_image2_checks",
            &["self", "copy_buffer_to_image_info"],
        ),
        settles: &[
            ("VUID-VkCopyBufferToImageInfo2-bufferRowLength-00203", How::Dynamic(COPY_REGION)),
            ("VUID-VkCopyBufferToImageInfo2-bufferImageHeight-00204", How::Dynamic(COPY_REGION)),
            ("VUID-VkCopyBufferToImageInfo2-pRegions-07274", How::Dynamic(COPY_REGION)),
            ("VUID-VkCopyBufferToImageInfo2-pRegions-07275", How::Dynamic(COPY_REGION)),
            ("VUID-VkCopyBufferToImageInfo2-imageExtent-00207", How::Dynamic(COPY_REGION)),
            ("VUID-VkCopyBufferToImageInfo2-imageExtent-00208", How::Dynamic(COPY_REGION)),
            ("VUID-VkCopyBufferToImageInfo2-pRegions-07273", How::Dynamic(COPY_REGION)),
            ("VUID-VkCopyBufferToImageInfo2-srcImage-04053", How::Dynamic(COPY_REGION)),
            ("VUID-VkCopyBufferToImageInfo2-pRegions-07277", How::Dynamic(COPY_ROW_PITCH)),
            ("VUID-VkCopyBufferToImageInfo2-dstImage-00179", How::Dynamic(COPY_REGION)),
            ("VUID-VkCopyBufferToImageInfo2-pRegions-00173", How::Dynamic(COPY_OVERLAP)),
            ("VUID-VkCopyBufferToImageInfo2-srcImage-00199", How::User(COPY_SAME_AS_Y)),
            ("VUID-VkCopyBufferToImageInfo2-srcImage-00201", How::User(COPY_SAME_AS_Z)),
            ("VUID-VkCopyBufferToImageInfo2-baseArrayLayer-00213", How::User(COPY_SAME_AS_LAYERS)),
            ("VUID-VkCopyBufferToImageInfo2-pRegions-00172", How::User(COPY_SAME_AS_RANGES)),
            ("VUID-VkCopyBufferToImageInfo2-pRegions-07276", How::User(COPY_BLOCK_DEPTH)),
            ("VUID-VkCopyBufferToImageInfo2-imageExtent-00209", How::User(COPY_BLOCK_DEPTH)),
            ("VUID-VkCopyBufferToImageInfo2-pRegions-07740", How::User(COPY_PLANES)),
            ("VUID-VkCopyBufferToImageInfo2-pRegions-07741", How::User(COPY_PLANES)),
            ("VUID-VkCopyBufferToImageInfo2-bufferOffset-01559", How::User(COPY_PLANES)),
            ("VUID-VkCopyBufferToImageInfo2-bufferOffset-01558", How::User(COPY_SAME_AS_SIZE)),
            ("VUID-VkCopyBufferToImageInfo2-dstImage-01997", How::User(COPY_FEATURES)),
            ("VUID-vkCmdCopyBufferToImage2-commandBuffer-07737", How::User(COPY_FAMILY)),
            ("VUID-vkCmdCopyBufferToImage2-imageOffset-07738", How::User(COPY_FAMILY)),
            ("VUID-vkCmdCopyBufferToImage2-commandBuffer-07739", How::User(COPY_FAMILY)),
            ("VUID-vkCmdCopyBufferToImage2-commandBuffer-01828", How::User(COPY_PROTECTED)),
            ("VUID-vkCmdCopyBufferToImage2-commandBuffer-01829", How::User(COPY_PROTECTED)),
            ("VUID-vkCmdCopyBufferToImage2-commandBuffer-01830", How::User(COPY_PROTECTED)),
            ("VUID-VkBufferImageCopy2-bufferRowLength-00195", How::Dynamic(COPY_REGION)),
            ("VUID-VkBufferImageCopy2-bufferImageHeight-00196", How::Dynamic(COPY_REGION)),
            ("VUID-VkBufferImageCopy2-aspectMask-00212", How::Dynamic(COPY_REGION)),
            ("VUID-VkCopyBufferToImageInfo2-dstImageLayout-00180", How::Dynamic(LAYOUT)),(
            "VUID-VkCopyBufferToImageInfo2-pRegions-00171",
            How::Dynamic(BUFFER_IMAGE_RANGE),
        )],
        ..NONE
    },
    Special {
        command: "vkCmdCopyImageToBuffer2",
        check: call("hooks::image_layout_checks", &["self", "crate::hooks::Names::ImageToBuffer2(copy_image_to_buffer_info)"]),
        after: call("hooks::image_layouts_named", &["self", "crate::hooks::Names::ImageToBuffer2(copy_image_to_buffer_info)"]),
        check_last: call(
            "hooks::cmd_copy_image_to_buffer2_checks",
            &["self", "copy_image_to_buffer_info"],
        ),
        settles: &[
            ("VUID-VkCopyImageToBufferInfo2-bufferRowLength-00203", How::Dynamic(COPY_REGION)),
            ("VUID-VkCopyImageToBufferInfo2-bufferImageHeight-00204", How::Dynamic(COPY_REGION)),
            ("VUID-VkCopyImageToBufferInfo2-pRegions-07274", How::Dynamic(COPY_REGION)),
            ("VUID-VkCopyImageToBufferInfo2-pRegions-07275", How::Dynamic(COPY_REGION)),
            ("VUID-VkCopyImageToBufferInfo2-imageExtent-00207", How::Dynamic(COPY_REGION)),
            ("VUID-VkCopyImageToBufferInfo2-imageExtent-00208", How::Dynamic(COPY_REGION)),
            ("VUID-VkCopyImageToBufferInfo2-pRegions-07273", How::Dynamic(COPY_REGION)),
            ("VUID-VkCopyImageToBufferInfo2-srcImage-04053", How::Dynamic(COPY_REGION)),
            ("VUID-VkCopyImageToBufferInfo2-pRegions-07277", How::Dynamic(COPY_ROW_PITCH)),
            ("VUID-VkCopyImageToBufferInfo2-srcImage-00188", How::Dynamic(COPY_REGION)),
            ("VUID-VkCopyImageToBufferInfo2-pRegions-00184", How::Dynamic(COPY_OVERLAP)),
            ("VUID-VkCopyImageToBufferInfo2-srcImage-00199", How::User(COPY_SAME_AS_Y)),
            ("VUID-VkCopyImageToBufferInfo2-srcImage-00201", How::User(COPY_SAME_AS_Z)),
            ("VUID-VkCopyImageToBufferInfo2-baseArrayLayer-00213", How::User(COPY_SAME_AS_LAYERS)),
            ("VUID-VkCopyImageToBufferInfo2-pRegions-00182", How::User(COPY_SAME_AS_RANGES)),
            ("VUID-VkCopyImageToBufferInfo2-pRegions-07276", How::User(COPY_BLOCK_DEPTH)),
            ("VUID-VkCopyImageToBufferInfo2-imageExtent-00209", How::User(COPY_BLOCK_DEPTH)),
            ("VUID-VkCopyImageToBufferInfo2-pRegions-07740", How::User(COPY_PLANES)),
            ("VUID-VkCopyImageToBufferInfo2-pRegions-07741", How::User(COPY_PLANES)),
            ("VUID-VkCopyImageToBufferInfo2-bufferOffset-01559", How::User(COPY_PLANES)),
            ("VUID-VkCopyImageToBufferInfo2-bufferOffset-01558", How::User(COPY_SAME_AS_SIZE)),
            ("VUID-VkCopyImageToBufferInfo2-srcImage-01998", How::User(COPY_FEATURES)),
            ("VUID-vkCmdCopyImageToBuffer2-commandBuffer-07746", How::User(COPY_FAMILY)),
            ("VUID-vkCmdCopyImageToBuffer2-imageOffset-07747", How::User(COPY_FAMILY)),
            ("VUID-vkCmdCopyImageToBuffer2-commandBuffer-01831", How::User(COPY_PROTECTED)),
            ("VUID-vkCmdCopyImageToBuffer2-commandBuffer-01832", How::User(COPY_PROTECTED)),
            ("VUID-vkCmdCopyImageToBuffer2-commandBuffer-01833", How::User(COPY_PROTECTED)),
            ("VUID-VkCopyImageToBufferInfo2-srcImageLayout-00189", How::Dynamic(LAYOUT)),(
            "VUID-VkCopyImageToBufferInfo2-pRegions-00183",
            How::Dynamic(BUFFER_IMAGE_RANGE),
        )],
        ..NONE
    },
    Special {
        command: "vkCmdCopyBuffer",
        check: call(
            "hooks::cmd_copy_buffer_checks",
            &["self", "src_buffer", "dst_buffer", "regions"],
        ),
        settles: &[
            ("VUID-vkCmdCopyBuffer-srcOffset-00113", How::Dynamic(COPY_RANGE)),
            ("VUID-vkCmdCopyBuffer-dstOffset-00114", How::Dynamic(COPY_RANGE)),
            ("VUID-vkCmdCopyBuffer-size-00115", How::Dynamic(COPY_RANGE)),
            ("VUID-vkCmdCopyBuffer-size-00116", How::Dynamic(COPY_RANGE)),
            ("VUID-VkBufferCopy-size-01988", How::Dynamic(COPY_RANGE)),
            (
                "VUID-vkCmdCopyBuffer-pRegions-00117",
                How::Dynamic("checks, when both buffers are one, that no source range overlaps a destination range"),
            ),
            ("VUID-vkCmdCopyBuffer-srcBuffer-00118", How::Dynamic(BUFFER_USE)),
            ("VUID-vkCmdCopyBuffer-srcBuffer-00119", How::Dynamic(BUFFER_USE)),
            ("VUID-vkCmdCopyBuffer-dstBuffer-00120", How::Dynamic(BUFFER_USE)),
            ("VUID-vkCmdCopyBuffer-dstBuffer-00121", How::Dynamic(BUFFER_USE)),
        ],
        ..NONE
    },
    Special {
        command: "vkBindImageMemory",
        check: call(
            "hooks::bind_image_memory_checks",
            &["self", "image", "memory", "memory_offset"],
        ),
        after: call(
            "hooks::bind_image_memory_done",
            &["self", "image", "memory", "memory_offset"],
        ),
        settles: &[
            ("VUID-vkBindImageMemory-image-07460", How::Dynamic(BIND_BOUND)),
            ("VUID-vkBindImageMemory-image-01045", How::User(UNPROVEN)),
            ("VUID-vkBindImageMemory-memoryOffset-01046", How::Dynamic(BIND_MEMORY)),
            ("VUID-vkBindImageMemory-memory-01047", How::User(UNPROVEN)),
            ("VUID-vkBindImageMemory-memoryOffset-01048", How::Dynamic(BIND_MEMORY)),
            ("VUID-vkBindImageMemory-size-01049", How::Dynamic(BIND_MEMORY)),
            ("VUID-vkBindImageMemory-image-01608", How::User(UNPROVEN)),
            ("VUID-vkBindImageMemory-image-01445", How::User(UNPROVEN_DEDICATED)),
            ("VUID-vkBindImageMemory-memory-01509", How::Dynamic(MEMORY_KIND)),
            ("VUID-vkBindImageMemory-None-01901", How::User(UNPROVEN_PROTECTED)),
            ("VUID-vkBindImageMemory-None-01902", How::User(UNPROVEN_PROTECTED)),
            ("VUID-vkBindImageMemory-memory-02728", How::Dynamic(MEMORY_KIND)),
            ("VUID-vkBindImageMemory-memory-02729", How::Static(NO_IMPORT)),
        ],
        ..NONE
    },
    Special {
        command: "vkQueueWaitIdle",
        after: call("hooks::queue_wait_idle_done", &["self"]),
        ..NONE
    },
    Special {
        command: "vkDeviceWaitIdle",
        after: call("hooks::device_wait_idle_done", &["self"]),
        ..NONE
    },
    Special {
        command: "vkGetFenceStatus",
        after: call("hooks::get_fence_status_done", &["fence", "r"]),
        ..NONE
    },
    Special {
        command: "vkWaitForFences",
        after: call("hooks::wait_for_fences_done", &["self", "fences", "wait_all", "r"]),
        ..NONE
    },
    Special {
        command: "vkCreateInstance",
        // The instance's own rules before the implicit ones: a messenger chained
        // without its extension is refused as the rule that names that case
        // (pNext-04926), not as the chain's general pNext-pNext.
        check: call("hooks::create_instance_first", &["create_info"]),
        created: call("hooks::instance_created", &["self", "out", "create_info"]),
        error: call("presence::instance_error", &["self", "create_info", "r"]),
        scope: call("hooks::create_instance_scope", &["create_info"]),
        settles: &[
            ("VUID-VkApplicationInfo-apiVersion-04010", How::Dynamic(INSTANCE_ALONE)),
            ("VUID-vkCreateInstance-ppEnabledExtensionNames-01388", How::Dynamic(INSTANCE_INFO)),
            ("VUID-VkInstanceCreateInfo-pNext-04926", How::Dynamic(INSTANCE_ALONE)),
        ],
        ..NONE
    },
    Special {
        command: "vkCreateDevice",
        check_last: call("hooks::create_device_checks", &["self", "create_info"]),
        check: call("hooks::device_extensions_emitted", &["create_info"]),
        created: call("hooks::device_created", &["self", "out", "create_info"]),
        error: call("presence::device_error", &["self", "create_info", "r"]),
        scope: call("hooks::create_device_scope", &["self", "create_info"]),
        settles: &[
            ("VUID-VkDeviceCreateInfo-pNext-00373", How::Dynamic(DEVICE_QUEUES)),
            ("VUID-VkDeviceCreateInfo-pNext-02829", How::Dynamic(DEVICE_QUEUES)),
            ("VUID-VkDeviceCreateInfo-pNext-02830", How::Dynamic(DEVICE_QUEUES)),
            ("VUID-VkDeviceCreateInfo-pNext-06532", How::Dynamic(DEVICE_QUEUES)),
            ("VUID-VkDeviceQueueCreateInfo-queueFamilyIndex-00381", How::Dynamic(DEVICE_QUEUES)),
            ("VUID-VkDeviceQueueCreateInfo-queueCount-00382", How::Dynamic(DEVICE_QUEUES)),
            ("VUID-VkDeviceQueueCreateInfo-pQueuePriorities-00383", How::Dynamic(DEVICE_QUEUES)),
            ("VUID-VkDeviceQueueCreateInfo-flags-02861", How::Dynamic(DEVICE_QUEUES)),
            ("VUID-VkDeviceCreateInfo-queueFamilyIndex-02802", How::Dynamic(DEVICE_QUEUES)),
            ("VUID-VkDeviceQueueCreateInfo-flags-06449", How::User(UNPROVEN_PROTECTED_QUEUES)),
            ("VUID-VkDeviceCreateInfo-pQueueCreateInfos-06755", How::User(UNPROVEN_PROTECTED_QUEUES)),
            ("VUID-vkCreateDevice-ppEnabledExtensionNames-01387", How::Dynamic(DEVICE_EXTENSIONS)),
            ("VUID-VkPhysicalDeviceMultiviewFeatures-multiviewGeometryShader-00580", How::Dynamic(DEVICE_QUEUES)),
            ("VUID-VkPhysicalDeviceMultiviewFeatures-multiviewTessellationShader-00581", How::Dynamic(DEVICE_QUEUES)),
            ("VUID-VkPhysicalDeviceVariablePointersFeatures-variablePointers-01431", How::Dynamic(DEVICE_QUEUES)),
            ("VUID-VkDeviceGroupDeviceCreateInfo-pPhysicalDevices-00375", How::Dynamic(DEVICE_GROUP)),
            ("VUID-VkDeviceGroupDeviceCreateInfo-pPhysicalDevices-00376", How::User(UNPROVEN_DEVICE_GROUP)),
            ("VUID-VkDeviceGroupDeviceCreateInfo-physicalDeviceCount-00377", How::User(UNPROVEN_DEVICE_GROUP)),
        ],
        ..NONE
    },
    Special {
        command: "vkCreateDescriptorPool",
        created: call("hooks::descriptor_pool_created", &["created", "create_info"]),
        ..NONE
    },
    Special {
        command: "vkCreateCommandPool",
        check: call("hooks::create_command_pool_checks", &["self", "create_info"]),
        created: call("hooks::command_pool_created", &["self", "created", "create_info"]),
        settles: &[
            ("VUID-vkCreateCommandPool-queueFamilyIndex-01937", How::Dynamic(POOL_FAMILY)),
            ("VUID-VkCommandPoolCreateInfo-flags-02860", How::Dynamic(POOL_PROTECTED)),
        ],
        ..NONE
    },
    Special {
        command: "vkAllocateMemory",
        check_last: call("hooks::allocate_memory_checks", &["self", "allocate_info"]),
        hold: call("hooks::allocate_memory_gate", &["self"]),
        keeps: Keeps::Nothing,
        created: call("hooks::memory_allocated", &["self", "created", "out", "allocate_info"]),
        settles: &[
            ("VUID-vkAllocateMemory-pAllocateInfo-01714", How::Dynamic(MEMORY_TYPES)),
            ("VUID-vkAllocateMemory-pAllocateInfo-01713", How::Dynamic(MEMORY_TYPES)),
            ("VUID-VkMemoryAllocateInfo-flags-03330", How::Dynamic(MEMORY_TYPES)),
            ("VUID-VkMemoryAllocateInfo-flags-03331", How::Dynamic(MEMORY_TYPES)),
            ("VUID-VkMemoryAllocateInfo-opaqueCaptureAddress-03329", How::Dynamic(MEMORY_TYPES)),
            ("VUID-VkMemoryAllocateInfo-memoryTypeIndex-01872", How::User(UNPROVEN_PROTECTED_TYPE)),
            ("VUID-VkMemoryAllocateFlagsInfo-deviceMask-00675", How::Dynamic(DEVICE_MASK)),
            ("VUID-VkMemoryAllocateFlagsInfo-deviceMask-00676", How::Dynamic(DEVICE_MASK)),
            ("VUID-vkAllocateMemory-maxMemoryAllocationCount-04101", How::User(UNPROVEN_ALLOCATION_COUNT)),
            ("VUID-VkMemoryDedicatedAllocateInfo-image-01432", How::Dynamic(DEDICATED)),
            ("VUID-VkMemoryDedicatedAllocateInfo-image-01433", How::Dynamic(DEDICATED)),
            ("VUID-VkMemoryDedicatedAllocateInfo-buffer-01435", How::Dynamic(DEDICATED)),
            ("VUID-VkMemoryDedicatedAllocateInfo-image-01434", How::User(UNPROVEN_SPARSE_DEDICATED)),
            ("VUID-VkMemoryDedicatedAllocateInfo-buffer-01436", How::User(UNPROVEN_SPARSE_DEDICATED)),
            ("VUID-VkMemoryDedicatedAllocateInfo-image-01797", How::User(UNPROVEN_DISJOINT_DEDICATED)),
            ("VUID-VkExportMemoryAllocateInfo-handleTypes-00656", How::Dynamic(EXPORT)),
            ("VUID-VkMemoryAllocateInfo-None-06657", How::Static(NO_IMPORT)),
            ("VUID-VkMemoryAllocateInfo-opaqueCaptureAddress-03333", How::Static(NO_IMPORT)),
        ],
        ..NONE
    },
    Special {
        command: "vkGetDeviceQueue",
        check: call(
            "hooks::get_device_queue_checks",
            &["self", "queue_family_index", "queue_index"],
        ),
        created: call("hooks::queue_got", &["self", "created", "queue_family_index"]),
        settles: &[
            ("VUID-vkGetDeviceQueue-queueFamilyIndex-00384", How::Dynamic(QUEUE_INFOS)),
            ("VUID-vkGetDeviceQueue-queueIndex-00385", How::Dynamic(QUEUE_INFOS)),
            ("VUID-vkGetDeviceQueue-flags-01841", How::Dynamic(QUEUE_INFOS)),
        ],
        ..NONE
    },
    Special {
        command: "vkGetDeviceQueue2",
        check: call("hooks::get_device_queue2_checks", &["self", "queue_info"]),
        created: call("hooks::queue2_got", &["self", "created", "queue_info"]),
        settles: &[
            ("VUID-VkDeviceQueueInfo2-queueFamilyIndex-01842", How::Dynamic(QUEUE_INFOS)),
            ("VUID-VkDeviceQueueInfo2-flags-06225", How::Dynamic(QUEUE_INFOS)),
            ("VUID-VkDeviceQueueInfo2-queueIndex-01843", How::Dynamic(QUEUE_INFOS)),
        ],
        ..NONE
    },
    Special {
        command: "vkCreateSemaphore",
        check_last: call("hooks::create_semaphore_checks", &["self", "create_info"]),
        created: call("hooks::semaphore_created", &["self", "created", "create_info"]),
        settles: &[(
            "VUID-VkExportSemaphoreCreateInfo-handleTypes-01124",
            How::Dynamic(EXPORTABLE),
        )],
        ..NONE
    },
    Special {
        command: "vkCreateDescriptorUpdateTemplate",
        created: call("hooks::descriptor_update_template_created", &["created", "create_info"]),
        ..NONE
    },
    Special {
        command: "vkAllocateDescriptorSets",
        check: call("hooks::allocate_descriptor_sets_checks", &["allocate_info"]),
        check_last: call(
            "hooks::allocate_descriptor_sets_layouts",
            &["self", "descriptor_pool", "allocate_info"],
        ),
        settles: &[
            (
                "VUID-VkDescriptorSetVariableDescriptorCountAllocateInfo-descriptorSetCount-03045",
                How::Dynamic(CHAINED_COUNT),
            ),
            (
                "VUID-VkDescriptorSetAllocateInfo-pSetLayouts-03044",
                How::User(UNPROVEN_UAB),
            ),
            (
                "VUID-VkDescriptorSetVariableDescriptorCountAllocateInfo-pSetLayouts-03046",
                How::User(UNPROVEN_VARIABLE),
            ),
        ],
        created: call(
            "hooks::descriptor_sets_allocated",
            &["self", "created", "descriptor_pool", "allocate_info"],
        ),
        ..NONE
    },
    Special {
        command: "vkAllocateCommandBuffers",
        created: call(
            "hooks::command_buffers_allocated",
            &["self", "created", "command_pool", "allocate_info"],
        ),
        ..NONE
    },
    Special {
        command: "vkCreateSwapchainKHR",
        check_last: call(
            "hooks::create_swapchain_checks",
            &["self", "surface", "create_info"],
        ),
        before: call("hooks::swapchain_retires", &["self", "create_info"]),
        created: call(
            "hooks::swapchain_created",
            &["self", "created", "surface", "create_info"],
        ),
        // VUID-vkDestroySurfaceKHR-surface-01266: swapchains go before their surface.
        keeps: Keeps::Member("surface", "VkSurfaceKHR"),
        settles: &[
            (
                "VUID-vkDestroySurfaceKHR-surface-01266",
                How::Static("a swapchain wrapper keeps its surface alive"),
            ),
            ("VUID-VkSwapchainCreateInfoKHR-surface-01270", How::User(UNPROVEN_SWAPCHAIN_SURFACE)),
            ("VUID-VkSwapchainCreateInfoKHR-minImageCount-01271", How::Dynamic(SURFACE_REPORTS)),
            ("VUID-VkSwapchainCreateInfoKHR-minImageCount-01272", How::User(UNPROVEN_SWAPCHAIN_SURFACE)),
            ("VUID-VkSwapchainCreateInfoKHR-imageFormat-01273", How::Dynamic(SURFACE_REPORTS)),
            ("VUID-VkSwapchainCreateInfoKHR-imageExtent-01689", How::Dynamic(SURFACE_REPORTS)),
            ("VUID-VkSwapchainCreateInfoKHR-imageExtent-01274", How::Dynamic(SURFACE_REPORTS)),
            ("VUID-VkSwapchainCreateInfoKHR-imageArrayLayers-01275", How::Dynamic(SURFACE_REPORTS)),
            ("VUID-VkSwapchainCreateInfoKHR-presentMode-01281", How::User(UNPROVEN_SWAPCHAIN_SURFACE)),
            ("VUID-VkSwapchainCreateInfoKHR-presentMode-01427", How::Dynamic(SURFACE_REPORTS)),
            ("VUID-VkSwapchainCreateInfoKHR-preTransform-01279", How::Dynamic(SURFACE_REPORTS)),
            ("VUID-VkSwapchainCreateInfoKHR-compositeAlpha-01280", How::Dynamic(SURFACE_REPORTS)),
            ("VUID-VkSwapchainCreateInfoKHR-imageSharingMode-01428", How::Dynamic(SURFACE_REPORTS)),
            ("VUID-VkSwapchainCreateInfoKHR-physicalDeviceCount-01429", How::Dynamic(SURFACE_REPORTS)),
            ("VUID-VkSwapchainCreateInfoKHR-imageFormat-01778", How::User(UNPROVEN_SWAPCHAIN_SURFACE)),
            ("VUID-VkSwapchainCreateInfoKHR-oldSwapchain-01933", How::Dynamic(RETIRED_SWAPCHAIN)),
        ],
        ..NONE
    },
    Special {
        command: "vkGetSwapchainImagesKHR",
        created: call(
            "hooks::swapchain_images",
            &["self", "created", "swapchain"],
        ),
        ..NONE
    },
    // Rules settled by the hand-written parts of the crate that these commands
    // live in rather than by a generated method.
    Special {
        command: "vkBeginCommandBuffer",
        settles: &[
            (
                "VUID-vkBeginCommandBuffer-commandBuffer-00049",
                How::Dynamic("`CommandBuffer::begin` refuses a buffer that a submission may still be executing; a recording holds the buffer mutably, so none is under way"),
            ),
            (
                "VUID-vkBeginCommandBuffer-commandBuffer-00050",
                How::Dynamic("`CommandBuffer::begin` refuses a buffer begun before when its pool was created without RESET_COMMAND_BUFFER"),
            ),
        ],
        ..NONE
    },
    Special {
        command: "vkDestroyFence",
        settles: &[(
            "VUID-vkDestroyFence-fence-01120",
            How::Static("a fence whose queue operation may still be executing waits for it before it is destroyed"),
        )],
        ..NONE
    },
    Special {
        command: "vkDestroySemaphore",
        settles: &[(
            "VUID-vkDestroySemaphore-semaphore-01137",
            How::Static("every queue operation holds the semaphores it names until it is known complete (its fence, a later fence of its queue, or an idle wait)"),
        )],
        ..NONE
    },
    Special {
        command: "vkMapMemory",
        settles: &[
            (
                "VUID-vkMapMemory-memory-00678",
                How::Dynamic("`DeviceMemory::map` refuses memory that a live `MappedMemory` maps"),
            ),
            (
                "VUID-vkMapMemory-memory-00682",
                How::Dynamic("`DeviceMemory::map` refuses memory whose type is not HOST_VISIBLE"),
            ),
            ("VUID-vkMapMemory-offset-00679", How::Static(WHOLE)),
            ("VUID-vkMapMemory-size-00680", How::Static(WHOLE)),
            ("VUID-vkMapMemory-size-00681", How::Static(WHOLE)),
        ],
        ..NONE
    },
    Special {
        command: "vkUnmapMemory",
        settles: &[(
            "VUID-vkUnmapMemory-memory-00689",
            How::Static("only a `MappedMemory` guard unmaps, once, the memory it mapped"),
        )],
        ..NONE
    },
];

/// The special case of a command, if it has one.
pub fn special(command: &str) -> Option<&'static Special> {
    SPECIALS.iter().find(|s| s.command == command)
}

/// How the table settles a rule, if a row settles it.
pub fn settled(vuid: &str) -> Option<How> {
    SPECIALS
        .iter()
        .flat_map(|s| s.settles)
        .find(|(v, _)| *v == vuid)
        .map(|(_, how)| *how)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_command_has_one_row_and_a_rule_one_settlement() {
        let mut commands = std::collections::BTreeSet::new();
        let mut vuids = std::collections::BTreeSet::new();
        for s in SPECIALS {
            assert!(commands.insert(s.command), "two rows for {}", s.command);
            for (v, _) in s.settles {
                assert!(vuids.insert(*v), "{v} is settled by two rows");
            }
        }
    }

    #[test]
    fn every_settled_rule_is_one_the_pinned_registry_has() {
        let path = concat!(env!("CARGO_MANIFEST_DIR"), "/../validusage.json");
        let rules = std::fs::read_to_string(path).expect("the pinned validusage.json");
        for s in SPECIALS {
            for (v, _) in s.settles {
                assert!(
                    rules.contains(&format!("\"{v}\"")),
                    "{}: {v} is no rule of the pinned registry",
                    s.command
                );
            }
        }
    }

    #[test]
    fn hooks_take_known_bindings() {
        for s in SPECIALS {
            for c in [
                s.check,
                s.check_last,
                s.before,
                s.after,
                s.created,
                s.error,
                s.scope,
            ]
            .into_iter()
            .flatten()
            {
                assert!(
                    c.path.starts_with("hooks::") || c.path.starts_with("presence::"),
                    "{}: {} is not in a hand-written module",
                    s.command,
                    c.path
                );
                assert!(
                    !c.args.is_empty(),
                    "{}: {} takes nothing",
                    s.command,
                    c.path
                );
            }
        }
    }
}
