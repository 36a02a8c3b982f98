//! What each recording command reads and writes, for the hazard tracker: one
//! reviewed table of per-command facts (which parameter is read or written, at
//! which stage and access type of synchronization2) over the registry's sync
//! tables, which say which stages each access type may be used with. A row whose
//! stage or access type the tables lack, or whose access type the tables do not
//! allow at its stage, stops the generator.
//!
//! Each row names the crate's `special::hazards` function that reads the memory
//! from the command's parameters; the emitted safe method calls it last, before the
//! command is recorded, with the row's facts (`sync_tables::CMD_*`). A recording
//! command without a row is one whose accesses the tracker does not know: the
//! report lists them as left to the user.

use super::special::Call;
use crate::model::SyncTables;

/// One access of a command: a role (the field of the crate's `Facts` it fills:
/// `src`, `dst`, `vertex`, `index`), a stage and an access type, as the registry
/// spells them.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Use {
    /// `src` (what it reads), `dst` (what it writes), `vertex` or `index` (a draw's
    /// vertex and index buffers).
    pub role: &'static str,
    /// `VK_PIPELINE_STAGE_2_COPY_BIT`; a comma-separated list for a command the
    /// specification can be read to run in either stage.
    pub stage: &'static str,
    /// `VK_ACCESS_2_TRANSFER_READ_BIT`.
    pub access: &'static str,
}

/// One command's facts.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Accesses {
    /// `vkCmdCopyBuffer`.
    pub command: &'static str,
    /// The crate function that declares the command's accesses to the tracker.
    pub call: Call,
    /// Its accesses (none for a command that only orders others: a barrier).
    pub uses: &'static [Use],
    /// What it does to the tracker besides its accesses, for the report.
    pub does: &'static str,
}

const fn call(path: &'static str, args: &'static [&'static str]) -> Call {
    Call {
        path,
        args,
        promise: None,
    }
}

const COPY_READ: Use = Use {
    role: "src",
    stage: "VK_PIPELINE_STAGE_2_COPY_BIT",
    access: "VK_ACCESS_2_TRANSFER_READ_BIT",
};
const COPY_WRITE: Use = Use {
    role: "dst",
    stage: "VK_PIPELINE_STAGE_2_COPY_BIT",
    access: "VK_ACCESS_2_TRANSFER_WRITE_BIT",
};
const COPY: &[Use] = &[COPY_READ, COPY_WRITE];
const BLIT: &[Use] = &[
    Use {
        role: "src",
        stage: "VK_PIPELINE_STAGE_2_BLIT_BIT",
        access: "VK_ACCESS_2_TRANSFER_READ_BIT",
    },
    Use {
        role: "dst",
        stage: "VK_PIPELINE_STAGE_2_BLIT_BIT",
        access: "VK_ACCESS_2_TRANSFER_WRITE_BIT",
    },
];
const RESOLVE: &[Use] = &[
    Use {
        role: "src",
        stage: "VK_PIPELINE_STAGE_2_RESOLVE_BIT",
        access: "VK_ACCESS_2_TRANSFER_READ_BIT",
    },
    Use {
        role: "dst",
        stage: "VK_PIPELINE_STAGE_2_RESOLVE_BIT",
        access: "VK_ACCESS_2_TRANSFER_WRITE_BIT",
    },
];
/// Clear commands: the specification's `VK_PIPELINE_STAGE_2_CLEAR_BIT` covers
/// `vkCmdClearColorImage` and `vkCmdClearDepthStencilImage`.
const CLEAR: &[Use] = &[Use {
    role: "dst",
    stage: "VK_PIPELINE_STAGE_2_CLEAR_BIT",
    access: "VK_ACCESS_2_TRANSFER_WRITE_BIT",
}];
/// `vkCmdFillBuffer` and `vkCmdUpdateBuffer`: the specification describes them among
/// the clear commands and calls them "transfer" operations; the validation layer's
/// synchronization validation times them at `COPY` (the corpus shows it). Both
/// stages are theirs, so a barrier naming either orders them: no correct program
/// under either reading is refused.
const FILL: &[Use] = &[Use {
    role: "dst",
    stage: "VK_PIPELINE_STAGE_2_COPY_BIT,VK_PIPELINE_STAGE_2_CLEAR_BIT",
    access: "VK_ACCESS_2_TRANSFER_WRITE_BIT",
}];

/// A command that reads or writes images through the layout tracker's shapes.
macro_rules! images {
    ($command:literal, $names:literal, $uses:expr) => {
        Accesses {
            command: $command,
            call: call("special::hazards::images", &["self", "&facts", $names]),
            uses: $uses,
            does: "",
        }
    };
}

/// The roles a use may fill, the fields of the crate's `Facts`.
pub const ROLES: &[&str] = &["src", "dst", "vertex", "index", "indirect"];

/// An indirect command's read of its parameters.
const INDIRECT: Use = Use {
    role: "indirect",
    stage: "VK_PIPELINE_STAGE_2_DRAW_INDIRECT_BIT",
    access: "VK_ACCESS_2_INDIRECT_COMMAND_READ_BIT",
};

/// The pipeline stage at which each shader stage reaches its descriptors: a draw or
/// dispatch reads and writes what its bound pipeline's shaders reach through the
/// bound descriptor sets, at the stage of the shader that does (`ShaderStageFlagBits`
/// name, stage name).
pub const SHADER_STAGES: &[(&str, &str)] = &[
    (
        "VK_SHADER_STAGE_VERTEX_BIT",
        "VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT",
    ),
    (
        "VK_SHADER_STAGE_TESSELLATION_CONTROL_BIT",
        "VK_PIPELINE_STAGE_2_TESSELLATION_CONTROL_SHADER_BIT",
    ),
    (
        "VK_SHADER_STAGE_TESSELLATION_EVALUATION_BIT",
        "VK_PIPELINE_STAGE_2_TESSELLATION_EVALUATION_SHADER_BIT",
    ),
    (
        "VK_SHADER_STAGE_GEOMETRY_BIT",
        "VK_PIPELINE_STAGE_2_GEOMETRY_SHADER_BIT",
    ),
    (
        "VK_SHADER_STAGE_FRAGMENT_BIT",
        "VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT",
    ),
    (
        "VK_SHADER_STAGE_COMPUTE_BIT",
        "VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT",
    ),
];

/// The access type of each way a shader reaches a descriptor (the field of the
/// crate's `DescriptorAccess` it fills, the access type): a uniform buffer's loads, a
/// sampled image's or uniform texel buffer's samples and fetches, a storage buffer's
/// or storage image's loads and stores (an atomic is both).
pub const DESCRIPTOR_ACCESSES: &[(&str, &str)] = &[
    ("uniform", "VK_ACCESS_2_UNIFORM_READ_BIT"),
    ("sampled", "VK_ACCESS_2_SHADER_SAMPLED_READ_BIT"),
    ("storage_read", "VK_ACCESS_2_SHADER_STORAGE_READ_BIT"),
    ("storage_write", "VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT"),
];

const VERTEX: Use = Use {
    role: "vertex",
    stage: "VK_PIPELINE_STAGE_2_VERTEX_ATTRIBUTE_INPUT_BIT",
    access: "VK_ACCESS_2_VERTEX_ATTRIBUTE_READ_BIT",
};
const INDEX: Use = Use {
    role: "index",
    stage: "VK_PIPELINE_STAGE_2_INDEX_INPUT_BIT",
    access: "VK_ACCESS_2_INDEX_READ_BIT",
};

/// The first version's barrier arguments, which `vkCmdWaitEvents` shares.
const BARRIER_ARGS: &[&str] = &[
    "self",
    "&facts",
    "(src_stage_mask, dst_stage_mask)",
    "memory_barriers",
    "buffer_memory_barriers",
    "image_memory_barriers",
];

/// The table.
pub const ROWS: &[Accesses] = &[
    Accesses {
        command: "vkCmdDraw",
        call: call(
            "special::hazards::draw",
            &[
                "self",
                "&facts",
                "(first_vertex, vertex_count)",
                "(first_instance, instance_count)",
            ],
        ),
        uses: &[VERTEX],
        does: "its descriptors as its bound pipeline's shaders use them",
    },
    Accesses {
        command: "vkCmdDrawIndexed",
        call: call(
            "special::hazards::draw_indexed",
            &[
                "self",
                "&facts",
                "(first_index, index_count)",
                "(first_instance, instance_count)",
            ],
        ),
        uses: &[INDEX, VERTEX],
        does: "its descriptors as its bound pipeline's shaders use them",
    },
    Accesses {
        command: "vkCmdDrawIndirect",
        call: call(
            "special::hazards::draw_indirect",
            &[
                "self",
                "&facts",
                "buffer",
                "(offset, draw_count, stride)",
                "false",
            ],
        ),
        uses: &[INDIRECT, VERTEX],
        does: "its descriptors as its bound pipeline's shaders use them",
    },
    Accesses {
        command: "vkCmdDrawIndexedIndirect",
        call: call(
            "special::hazards::draw_indirect",
            &[
                "self",
                "&facts",
                "buffer",
                "(offset, draw_count, stride)",
                "true",
            ],
        ),
        uses: &[INDIRECT, INDEX, VERTEX],
        does: "its descriptors as its bound pipeline's shaders use them",
    },
    Accesses {
        command: "vkCmdDispatch",
        call: call("special::hazards::dispatch", &["self", "&facts"]),
        uses: &[],
        does: "its descriptors as its bound pipeline's shaders use them",
    },
    Accesses {
        command: "vkCmdDispatchBase",
        call: call("special::hazards::dispatch", &["self", "&facts"]),
        uses: &[],
        does: "its descriptors as its bound pipeline's shaders use them",
    },
    Accesses {
        command: "vkCmdDispatchIndirect",
        call: call(
            "special::hazards::dispatch_indirect",
            &["self", "&facts", "buffer", "offset"],
        ),
        uses: &[INDIRECT],
        does: "its descriptors as its bound pipeline's shaders use them",
    },
    Accesses {
        command: "vkCmdCopyBuffer",
        call: call(
            "special::hazards::copy_buffer",
            &["self", "&facts", "src_buffer", "dst_buffer", "regions"],
        ),
        uses: COPY,
        does: "",
    },
    Accesses {
        command: "vkCmdCopyBuffer2",
        call: call(
            "special::hazards::copy_buffer2",
            &["self", "&facts", "copy_buffer_info"],
        ),
        uses: COPY,
        does: "",
    },
    Accesses {
        command: "vkCmdCopyBufferToImage",
        call: call(
            "special::hazards::copy_buffer_to_image",
            &["self", "&facts", "src_buffer", "dst_image", "regions"],
        ),
        uses: COPY,
        does: "",
    },
    Accesses {
        command: "vkCmdCopyBufferToImage2",
        call: call(
            "special::hazards::copy_buffer_to_image2",
            &["self", "&facts", "copy_buffer_to_image_info"],
        ),
        uses: COPY,
        does: "",
    },
    Accesses {
        command: "vkCmdCopyImageToBuffer",
        call: call(
            "special::hazards::copy_image_to_buffer",
            &["self", "&facts", "src_image", "dst_buffer", "regions"],
        ),
        uses: COPY,
        does: "",
    },
    Accesses {
        command: "vkCmdCopyImageToBuffer2",
        call: call(
            "special::hazards::copy_image_to_buffer2",
            &["self", "&facts", "copy_image_to_buffer_info"],
        ),
        uses: COPY,
        does: "",
    },
    images!(
        "vkCmdCopyImage",
        "crate::special::image_layouts::Names::CopyImage(src_image.raw(), src_image_layout, dst_image.raw(), dst_image_layout, regions)",
        COPY
    ),
    images!(
        "vkCmdCopyImage2",
        "crate::special::image_layouts::Names::CopyImage2(copy_image_info)",
        COPY
    ),
    images!(
        "vkCmdBlitImage",
        "crate::special::image_layouts::Names::BlitImage(src_image.raw(), src_image_layout, dst_image.raw(), dst_image_layout, regions)",
        BLIT
    ),
    images!(
        "vkCmdBlitImage2",
        "crate::special::image_layouts::Names::BlitImage2(blit_image_info)",
        BLIT
    ),
    images!(
        "vkCmdResolveImage",
        "crate::special::image_layouts::Names::ResolveImage(src_image.raw(), src_image_layout, dst_image.raw(), dst_image_layout, regions)",
        RESOLVE
    ),
    images!(
        "vkCmdResolveImage2",
        "crate::special::image_layouts::Names::ResolveImage2(resolve_image_info)",
        RESOLVE
    ),
    images!(
        "vkCmdClearColorImage",
        "crate::special::image_layouts::Names::ClearColor(image.raw(), image_layout, ranges)",
        CLEAR
    ),
    images!(
        "vkCmdClearDepthStencilImage",
        "crate::special::image_layouts::Names::ClearDepthStencil(image.raw(), image_layout, ranges)",
        CLEAR
    ),
    Accesses {
        command: "vkCmdFillBuffer",
        call: call(
            "special::hazards::fill_buffer",
            &["self", "&facts", "dst_buffer", "dst_offset", "size"],
        ),
        uses: FILL,
        does: "",
    },
    Accesses {
        command: "vkCmdUpdateBuffer",
        call: call(
            "special::hazards::update_buffer",
            &["self", "&facts", "dst_buffer", "dst_offset", "data"],
        ),
        uses: FILL,
        does: "",
    },
    Accesses {
        command: "vkCmdPipelineBarrier",
        call: call(
            "special::hazards::pipeline_barrier",
            BARRIER_ARGS,
        ),
        uses: &[],
        does: "its barriers order the accesses before them against those after",
    },
    Accesses {
        command: "vkCmdPipelineBarrier2",
        call: call(
            "special::hazards::pipeline_barrier2",
            &["self", "&facts", "&[dependency_info]"],
        ),
        uses: &[],
        does: "its barriers order the accesses before them against those after",
    },
    Accesses {
        command: "vkCmdWaitEvents",
        call: call(
            "special::hazards::pipeline_barrier",
            BARRIER_ARGS,
        ),
        uses: &[],
        does: "its barriers order the accesses before them against those after",
    },
    Accesses {
        command: "vkCmdWaitEvents2",
        call: call(
            "special::hazards::pipeline_barrier2",
            &["self", "&facts", "&dependency_infos.iter().collect::<Vec<_>>()"],
        ),
        uses: &[],
        does: "its barriers order the accesses before them against those after",
    },
    Accesses {
        command: "vkCmdBeginRenderPass",
        call: call(
            "special::hazards::begin_render_pass",
            &["self", "&facts", "render_pass_begin"],
        ),
        uses: &[],
        does: "the dependencies into the subpass it begins order the accesses before; the attachments that subpass uses first make their layout transitions (under the dependencies from outside, or the implicit one) and load operations (a read for LOAD, a write otherwise)",
    },
    Accesses {
        command: "vkCmdBeginRenderPass2",
        call: call(
            "special::hazards::begin_render_pass",
            &["self", "&facts", "render_pass_begin"],
        ),
        uses: &[],
        does: "the dependencies into the subpass it begins order the accesses before; the attachments that subpass uses first make their layout transitions (under the dependencies from outside, or the implicit one) and load operations (a read for LOAD, a write otherwise)",
    },
    Accesses {
        command: "vkCmdNextSubpass",
        call: call("special::hazards::next_subpass", &["self", "&facts"]),
        uses: &[],
        does: "the dependencies into the subpass it begins order the accesses before; the attachments that subpass uses first make their layout transitions (under the dependencies from outside, or the implicit one) and load operations (a read for LOAD, a write otherwise)",
    },
    Accesses {
        command: "vkCmdNextSubpass2",
        call: call("special::hazards::next_subpass", &["self", "&facts"]),
        uses: &[],
        does: "the dependencies into the subpass it begins order the accesses before; the attachments that subpass uses first make their layout transitions (under the dependencies from outside, or the implicit one) and load operations (a read for LOAD, a write otherwise)",
    },
    Accesses {
        command: "vkCmdEndRenderPass",
        call: call("special::hazards::end_render_pass", &["self", "&facts"]),
        uses: &[],
        does: "the attachments' store operations (writes) and final layout transitions; the dependencies out of the render pass order what came before",
    },
    Accesses {
        command: "vkCmdEndRenderPass2",
        call: call("special::hazards::end_render_pass", &["self", "&facts"]),
        uses: &[],
        does: "the attachments' store operations (writes) and final layout transitions; the dependencies out of the render pass order what came before",
    },
    Accesses {
        command: "vkCmdExecuteCommands",
        call: call(
            "special::hazards::execute_commands",
            &["self", "&facts", "command_buffers"],
        ),
        uses: &[],
        does: "each secondary's recorded accesses and barriers, replayed in order on the recording's",
    },
];

/// The row of a command, if the tracker knows its accesses.
pub fn row(command: &str) -> Option<&'static Accesses> {
    ROWS.iter().find(|r| r.command == command)
}

/// The name of the facts constant of a command: `vkCmdCopyBuffer` -> `CMD_COPY_BUFFER`.
pub fn facts_name(command: &str) -> String {
    use heck::ToShoutySnakeCase as _;
    command
        .strip_prefix("vk")
        .unwrap_or(command)
        .to_shouty_snake_case()
}

/// Refuses a row whose stage or access type the tables lack, or whose access type
/// the tables do not allow at its stage; the same for each descriptor access type at
/// each shader stage.
pub fn check(tables: &SyncTables) -> Result<(), String> {
    for (_, stage) in SHADER_STAGES {
        for (_, access) in DESCRIPTOR_ACCESSES {
            allowed(tables, "a descriptor", stage, access)?;
        }
    }
    for row in ROWS {
        for (u, name) in row
            .uses
            .iter()
            .flat_map(|u| u.stage.split(',').map(move |n| (u, n)))
        {
            allowed(tables, row.command, name, u.access)?;
            if !ROLES.contains(&u.role) {
                return Err(format!("{}: no role {}", row.command, u.role));
            }
        }
    }
    Ok(())
}

/// Refuses a stage or access type the tables lack, or an access type the tables do
/// not allow at the stage (`what` names the fact in the error).
fn allowed(tables: &SyncTables, what: &str, name: &str, access: &str) -> Result<(), String> {
    let stage = tables
        .stages
        .iter()
        .find(|s| s.name == name)
        .ok_or_else(|| format!("{what}: no stage {name} in <sync>"))?;
    let access_row = tables
        .accesses
        .iter()
        .find(|a| a.name == access)
        .ok_or_else(|| format!("{what}: no access type {access} in <sync>"))?;
    if let Some(stages) = &access_row.stages {
        let ok = stages.iter().any(|s| {
            s == &stage.name
                || tables
                    .stages
                    .iter()
                    .any(|m| &m.name == s && m.equivalent.contains(&stage.name))
        });
        if !ok {
            return Err(format!(
                "{what}: the registry does not allow {access} at {name}"
            ));
        }
    }
    Ok(())
}
