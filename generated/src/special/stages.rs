//! Which pipeline stages support which access types, and which stages are
//! framebuffer-space: the specification's table of supported access types for the
//! stages and accesses of Vulkan 1.0 to 1.3. The pinned registry (1.3.239) has no
//! `<sync>` block to read it from; newer registries do, and the generator can take
//! this table from there once it reads them.

use ash::vk;

pub(super) type S = vk::PipelineStageFlags;

pub(super) type A = vk::AccessFlags;

/// The shader stages of a graphics or compute pipeline.
const SHADERS: S = S::from_raw(
    S::VERTEX_SHADER.as_raw()
        | S::TESSELLATION_CONTROL_SHADER.as_raw()
        | S::TESSELLATION_EVALUATION_SHADER.as_raw()
        | S::GEOMETRY_SHADER.as_raw()
        | S::FRAGMENT_SHADER.as_raw()
        | S::COMPUTE_SHADER.as_raw(),
);

/// The stages of a graphics pipeline, which `ALL_GRAPHICS` stands for.
pub(crate) const GRAPHICS: S = S::from_raw(
    S::TOP_OF_PIPE.as_raw()
        | S::DRAW_INDIRECT.as_raw()
        | S::VERTEX_INPUT.as_raw()
        | S::VERTEX_SHADER.as_raw()
        | S::TESSELLATION_CONTROL_SHADER.as_raw()
        | S::TESSELLATION_EVALUATION_SHADER.as_raw()
        | S::GEOMETRY_SHADER.as_raw()
        | S::FRAGMENT_SHADER.as_raw()
        | S::EARLY_FRAGMENT_TESTS.as_raw()
        | S::LATE_FRAGMENT_TESTS.as_raw()
        | S::COLOR_ATTACHMENT_OUTPUT.as_raw()
        | S::BOTTOM_OF_PIPE.as_raw(),
);

/// The framebuffer-space stages.
pub(crate) const FRAMEBUFFER_SPACE: S = S::from_raw(
    S::FRAGMENT_SHADER.as_raw()
        | S::EARLY_FRAGMENT_TESTS.as_raw()
        | S::LATE_FRAGMENT_TESTS.as_raw()
        | S::COLOR_ATTACHMENT_OUTPUT.as_raw(),
);

/// Each access type and the stages that support it (`MEMORY_READ` and
/// `MEMORY_WRITE` are supported by every stage).
const SUPPORTED: [(A, S); 15] = [
    (A::INDIRECT_COMMAND_READ, S::DRAW_INDIRECT),
    (A::INDEX_READ, S::VERTEX_INPUT),
    (A::VERTEX_ATTRIBUTE_READ, S::VERTEX_INPUT),
    (A::UNIFORM_READ, SHADERS),
    (A::SHADER_READ, SHADERS),
    (A::SHADER_WRITE, SHADERS),
    (A::INPUT_ATTACHMENT_READ, S::FRAGMENT_SHADER),
    (A::COLOR_ATTACHMENT_READ, S::COLOR_ATTACHMENT_OUTPUT),
    (A::COLOR_ATTACHMENT_WRITE, S::COLOR_ATTACHMENT_OUTPUT),
    (
        A::DEPTH_STENCIL_ATTACHMENT_READ,
        S::from_raw(S::EARLY_FRAGMENT_TESTS.as_raw() | S::LATE_FRAGMENT_TESTS.as_raw()),
    ),
    (
        A::DEPTH_STENCIL_ATTACHMENT_WRITE,
        S::from_raw(S::EARLY_FRAGMENT_TESTS.as_raw() | S::LATE_FRAGMENT_TESTS.as_raw()),
    ),
    (A::TRANSFER_READ, S::TRANSFER),
    (A::TRANSFER_WRITE, S::TRANSFER),
    (A::HOST_READ, S::HOST),
    (A::HOST_WRITE, S::HOST),
];

/// The stages a mask names, with `ALL_GRAPHICS` and `ALL_COMMANDS` spelled out
/// (every stage of the emitted API for the latter).
pub(crate) fn expand(stages: S) -> S {
    let mut out = stages;
    if stages.contains(S::ALL_GRAPHICS) {
        out |= GRAPHICS;
    }
    if stages.contains(S::ALL_COMMANDS) {
        out |= GRAPHICS | S::COMPUTE_SHADER | S::TRANSFER | S::HOST;
    }
    out
}

/// The first access type of `access` that no stage of `stages` supports.
pub(crate) fn unsupported_access(access: A, stages: S) -> Option<A> {
    let stages = expand(stages);
    SUPPORTED
        .iter()
        .find(|(a, supported)| access.contains(*a) && !stages.intersects(*supported))
        .map(|(a, _)| *a)
}

/// The first stage of `stages` that no capability of a queue with `flags` supports
/// (the specification's table of supported pipeline stages); `HOST` is no queue's.
pub(crate) fn unsupported_stage(stages: S, flags: vk::QueueFlags) -> Option<S> {
    use vk::QueueFlags as Q;
    let graphics = flags.contains(Q::GRAPHICS);
    let compute = flags.contains(Q::COMPUTE);
    let transfer = graphics || compute || flags.contains(Q::TRANSFER);
    let each: [(S, bool); 16] = [
        (S::TOP_OF_PIPE, true),
        (S::BOTTOM_OF_PIPE, true),
        (S::ALL_COMMANDS, true),
        (S::DRAW_INDIRECT, graphics || compute),
        (S::VERTEX_INPUT, graphics),
        (S::VERTEX_SHADER, graphics),
        (S::TESSELLATION_CONTROL_SHADER, graphics),
        (S::TESSELLATION_EVALUATION_SHADER, graphics),
        (S::GEOMETRY_SHADER, graphics),
        (S::FRAGMENT_SHADER, graphics),
        (S::EARLY_FRAGMENT_TESTS, graphics),
        (S::LATE_FRAGMENT_TESTS, graphics),
        (S::COLOR_ATTACHMENT_OUTPUT, graphics),
        (S::ALL_GRAPHICS, graphics),
        (S::COMPUTE_SHADER, compute),
        (S::TRANSFER, transfer),
    ];
    each.iter()
        .find(|(s, ok)| stages.contains(*s) && !ok)
        .map(|(s, _)| *s)
        .or_else(|| stages.contains(S::HOST).then_some(S::HOST))
}

/// As [`unsupported_stage`], for a `VkPipelineStageFlags2` mask: its low 32 bits
/// are the first version's stages, and the stages synchronization2 adds belong to
/// transfer (copy, resolve, blit, clear) or graphics (index and vertex attribute
/// input, the pre-rasterization shaders).
pub(crate) fn unsupported_stage2(
    stages: vk::PipelineStageFlags2,
    flags: vk::QueueFlags,
) -> Option<vk::PipelineStageFlags2> {
    use vk::PipelineStageFlags2 as S2;
    use vk::QueueFlags as Q;
    let graphics = flags.contains(Q::GRAPHICS);
    let transfer = graphics || flags.contains(Q::COMPUTE) || flags.contains(Q::TRANSFER);
    let each: [(S2, bool); 7] = [
        (S2::COPY, transfer),
        (S2::RESOLVE, transfer),
        (S2::BLIT, transfer),
        (S2::CLEAR, transfer),
        (S2::INDEX_INPUT, graphics),
        (S2::VERTEX_ATTRIBUTE_INPUT, graphics),
        (S2::PRE_RASTERIZATION_SHADERS, graphics),
    ];
    // The low bits name the same stages as the first version's flags.
    let low = S::from_raw(stages.as_raw() as u32);
    unsupported_stage(low, flags)
        .map(|s| S2::from_raw(u64::from(s.as_raw())))
        .or_else(|| {
            each.iter()
                .find(|(s, ok)| stages.contains(*s) && !ok)
                .map(|(s, _)| *s)
        })
}
