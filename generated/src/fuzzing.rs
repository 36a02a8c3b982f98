//! The body of the SPIR-V fuzz target (`fuzz/fuzz_targets/spirv.rs`), here so that the
//! test suite replays its corpus, and every crash it found, on the stable toolchain
//! (`tests/fuzz_corpus.rs`). Not API: hidden from the docs, free to change.

use crate::spirv::{interface, spirv_words, IoVar};

/// Bytes read as a shader module is: its words, its interface, and every question the
/// pipeline checks ask of that interface. Any bytes must return, never panic.
pub fn spirv(bytes: &[u8]) {
    let Ok(words) = spirv_words(bytes) else {
        return;
    };
    let reflected = interface(&words);
    use ash::vk::ShaderStageFlags as S;
    let stages = [
        S::VERTEX,
        S::TESSELLATION_CONTROL,
        S::TESSELLATION_EVALUATION,
        S::GEOMETRY,
        S::FRAGMENT,
        S::COMPUTE,
        S::TASK_EXT,
    ];
    for entry in &reflected.entry_points {
        for stage in stages {
            let _ = reflected.entry_point(entry.name.as_bytes(), stage);
        }
        for location in [0, 1, 15, u32::MAX] {
            let _ = reflected.reads_vertex_location(entry.name.as_bytes(), location);
        }
        for &(mode, _) in &entry.modes {
            let _ = (entry.mode(mode), entry.first_of(&[mode, 0, 4, 17]));
        }
        let io: &[IoVar] = &entry.io;
        for a in io {
            let _ = a.ty.locations();
            for b in io {
                let _ = (a.ty.matches(&b.ty, false), a.ty.matches(&b.ty, true));
            }
        }
    }
}
