//! The special-case rows of one concern; their functions are the `tuff` crate's
//! `special/shader.rs`, and a row here calls no other (but the image-layout tracker).
//!
//! Shader modules and the stages of a pipeline: entry points, specialization data,
//! subgroup sizes, built-ins and the layout the module's resources need.

use super::{call, Special, NONE, SHADER_CONTRACT};

/// The rows of this concern.
pub(super) const ROWS: &[Special] = &[Special {
    command: "vkCreateShaderModule",
    created: call(
        "special::shader::shader_module_created",
        &["self", "created", "create_info"],
    ),
    contract: Some(SHADER_CONTRACT),
    ..NONE
}];
