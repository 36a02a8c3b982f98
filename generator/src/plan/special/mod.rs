//! The special cases of the emitted commands, one table per concern.
//!
//! Most of a command's method follows from its parameters' shapes. What does not (a
//! check every build needs for memory safety, bookkeeping after a submission, a
//! created wrapper that must remember its create flags) is a row here: the command,
//! the hand-written functions of the `tuff` crate's `special` module it calls and when,
//! and the rules those functions settle. The commands renderer turns a row into calls;
//! the report reads the rules from the same row, so what is checked and what the
//! report says is checked cannot drift apart. The functions carry the code and its
//! `// SAFETY:` comments; the table carries only names. Each concern's rows sit in
//! the file named for it, beside the settlement texts only they use, and call only
//! the crate's `special/<concern>.rs` (and `special::image_layouts`, the tracker every
//! command that names a layout uses).

mod acceleration;
mod barriers;
mod blits;
mod buffer;
mod command_buffers;
mod copies;
mod descriptor_set_layout;
mod descriptors;
mod device;
mod draw;
mod draw_state;
mod framebuffer;
mod image;
mod image_copies;
pub mod indirect;
mod memory;
mod pass_instance;
mod pipeline;
mod pipeline_layout;
mod query;
mod queue;
mod render_pass;
mod rendering;
mod resolves;
mod sampler;
mod secondaries;
mod shader;
mod surface;
mod swapchain;
mod sync;
mod view;

/// A call of a hand-written function: its path under the `tuff` crate root and the
/// bindings of the generated method it takes, in order. A binding is `self`, a
/// parameter's Rust name (a handle slice is the caller's `&[&T]`), `r` (the
/// `vk::Result` of the call), `out` (the raw output of a create or get) or `created`
/// (the wrapper the method would return without the special case).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Call {
    /// `special::queue::queue_submit_checks`.
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

pub(super) const NONE: Special = Special {
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

/// The structs a command reads from a buffer when it executes (its indirect
/// arguments, which live in GPU memory): no parameter names them, but their rules
/// apply to every call, so a method is safe only when they are settled too. The
/// generated methods, which take any buffer, cannot see them and stay `unsafe`; the
/// core ones have safe forms over host-written arguments ([`indirect::FORMS`]).
pub const INDIRECT: &[(&str, &str)] = &[
    ("vkCmdDispatchIndirect", "VkDispatchIndirectCommand"),
    ("vkCmdDrawIndirect", "VkDrawIndirectCommand"),
    ("vkCmdDrawIndirectCount", "VkDrawIndirectCommand"),
    ("vkCmdDrawIndexedIndirect", "VkDrawIndexedIndirectCommand"),
    (
        "vkCmdDrawIndexedIndirectCount",
        "VkDrawIndexedIndirectCommand",
    ),
    (
        "vkCmdDrawMeshTasksIndirectEXT",
        "VkDrawMeshTasksIndirectCommandEXT",
    ),
    (
        "vkCmdDrawMeshTasksIndirectCountEXT",
        "VkDrawMeshTasksIndirectCommandEXT",
    ),
    (
        "vkCmdDrawMeshTasksIndirectNV",
        "VkDrawMeshTasksIndirectCommandNV",
    ),
    (
        "vkCmdDrawMeshTasksIndirectCountNV",
        "VkDrawMeshTasksIndirectCommandNV",
    ),
    ("vkCmdTraceRaysIndirectKHR", "VkTraceRaysIndirectCommandKHR"),
    (
        "vkCmdTraceRaysIndirect2KHR",
        "VkTraceRaysIndirectCommand2KHR",
    ),
];

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

pub(super) const FENCE: &str =
    "checks the fence is unsignalled and not in use by a queue operation that may still be executing";
pub(super) const LAYOUT: &str = "checks the layout named against the one the recording's earlier commands leave the subresources in, and, for subresources the recording has not touched before, at submission against the one the device's earlier submissions leave (the recorder follows every barrier, render pass and secondary that changes a layout, in the order the queue executes them)";
pub(super) const LAYOUT_BARRIER: &str = "checks the old layout against the one the recording's earlier commands leave the subresources in, and, for subresources the recording has not touched before, at submission against the one the device's earlier submissions leave; an acquire (a transfer from another queue family to the pool's) follows the new layout without needing the old one, which the release named and moved from";
pub(super) const UNPROVEN: &str =
    "checked by the safe methods in every build, but no test breaks it yet, so the report does not count it";
pub(super) const ACTIVE_QUERIES: &str = "checks the queries the recorder has begun and not ended, with the subpass each began in (a refused end of an instance first ends them, so the driver sees a valid end of an unsubmittable buffer)";
pub(super) const ACTIVE_QUERIES_ALONE: &str = "checks the queries the recorder has begun and not ended, with the subpass each began in (the 1.3.239 layer does not check it: proven by the error alone; a refused end of an instance first ends them, so the driver sees a valid end of an unsubmittable buffer)";
pub(super) const UNPROVEN_SURFACE: &str = "checked by the safe methods in every build (a query of each queue family's support), but no test breaks it: every lavapipe queue family presents to every X11 surface";
pub(super) const UNPROVEN_FAMILY: &str = "checked by the safe methods in every build (against the pool's queue family flags), but no test breaks it: lavapipe's one queue family supports graphics and compute";
pub(super) const SEMAPHORE_TYPE: &str =
    "checks the semaphore's type, kept by the wrapper from its creation";
pub(super) const VIEWPORTS: &str =
    "checks the first index plus the count against the device's maxViewports, read once";
pub(super) const MULTI_VIEWPORT: &str = "checks one viewport or scissor, the first, unless the device was created with the multiViewport feature, which it remembers";
pub(super) const CHAINED_COUNT: &str =
    "checks the chained struct's count against the count of the struct it extends";
pub(super) const ONE_WAITER: &str = "checked by the safe methods in every build: a wait leaves the semaphore waited on, so a second wait before another signal is refused as a wait on an unsignaled semaphore, which is the rule the error names";
pub(super) const BINARY_STATE: &str = "checks the binary semaphore's state, which the device follows through every command that signals or waits on one (queue submissions, sparse binds, acquires, presentations): a wait needs a signal submitted and not waited on since, a signal needs it unsignaled, or waited on earlier on the same queue, and a wait is pending until the operation that waits is known complete";
pub(super) const RANGE: &str = "checks the offsets and sizes against the buffer's size, kept from its creation, and their alignment";
pub(super) const BUFFER_USE: &str = "checks the buffer's usage, kept from its creation, and that memory is bound to it (or it is sparse)";

/// Every special case, by the concern its file is named for: a row of `queue.rs`
/// calls only `special::queue::*` in the crate (and the image-layout tracker,
/// `special::image_layouts`).
pub const TABLES: &[(&str, &[Special])] = &[
    ("acceleration", acceleration::ROWS),
    ("barriers", barriers::ROWS),
    ("blits", blits::ROWS),
    ("buffer", buffer::ROWS),
    ("command_buffers", command_buffers::ROWS),
    ("copies", copies::ROWS),
    ("descriptor_set_layout", descriptor_set_layout::ROWS),
    ("descriptors", descriptors::ROWS),
    ("device", device::ROWS),
    ("draw", draw::ROWS),
    ("draw_state", draw_state::ROWS),
    ("framebuffer", framebuffer::ROWS),
    ("image", image::ROWS),
    ("image_copies", image_copies::ROWS),
    ("memory", memory::ROWS),
    ("pass_instance", pass_instance::ROWS),
    ("pipeline", pipeline::ROWS),
    ("pipeline_layout", pipeline_layout::ROWS),
    ("query", query::ROWS),
    ("queue", queue::ROWS),
    ("render_pass", render_pass::ROWS),
    ("rendering", rendering::ROWS),
    ("resolves", resolves::ROWS),
    ("sampler", sampler::ROWS),
    ("secondaries", secondaries::ROWS),
    ("shader", shader::ROWS),
    ("surface", surface::ROWS),
    ("swapchain", swapchain::ROWS),
    ("sync", sync::ROWS),
    ("view", view::ROWS),
];

/// Every special case.
pub fn specials() -> impl Iterator<Item = &'static Special> {
    TABLES.iter().flat_map(|(_, rows)| rows.iter())
}

/// The special case of a command, if it has one.
pub fn special(command: &str) -> Option<&'static Special> {
    specials().find(|s| s.command == command)
}

/// How the table settles a rule, if a row settles it.
pub fn settled(vuid: &str) -> Option<How> {
    specials()
        .flat_map(|s| s.settles)
        .find(|(v, _)| *v == vuid)
        .map(|(_, how)| *how)
        .or_else(|| indirect::settled(vuid))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_command_has_one_row_and_a_rule_one_settlement() {
        let mut commands = std::collections::BTreeSet::new();
        let mut vuids = std::collections::BTreeSet::new();
        for s in specials() {
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
        let rows = specials().map(|s| (s.command, s.settles));
        let forms = indirect::FORMS.iter().map(|f| (f.command, f.settles));
        for (command, settles) in rows.chain(forms) {
            for (v, _) in settles {
                assert!(
                    rules.contains(&format!("\"{v}\"")),
                    "{command}: {v} is no rule of the pinned registry"
                );
            }
        }
    }

    #[test]
    fn every_indirect_argument_struct_is_the_pinned_registrys_and_has_rules() {
        let path = concat!(env!("CARGO_MANIFEST_DIR"), "/../validusage.json");
        let rules = std::fs::read_to_string(path).expect("the pinned validusage.json");
        for (command, read) in INDIRECT {
            assert!(
                rules.contains(&format!("\"VUID-{command}-")),
                "{command} is no command of the pinned registry"
            );
            // Every core one has rules of its own: the reason it is listed.
            if !read.ends_with("EXT") && !read.ends_with("NV") && !read.ends_with("KHR") {
                assert!(
                    rules.contains(&format!("\"VUID-{read}-")),
                    "{read} has no rule in the pinned registry"
                );
            }
        }
    }

    #[test]
    fn calls_take_known_bindings_in_their_concern() {
        for (concern, rows) in TABLES {
            let own = format!("special::{concern}::");
            for s in rows.iter() {
                for c in [
                    s.check,
                    s.check_last,
                    s.hold,
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
                        c.path.starts_with(&own)
                            || c.path.starts_with("special::image_layouts::")
                            || c.path.starts_with("diagnostics::presence::"),
                        "{}: {} is not in the crate's special::{concern}, the file of its row",
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
}
