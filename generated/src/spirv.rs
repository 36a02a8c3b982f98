//! Shader modules from SPIR-V as it is stored in a file: bytes, in either byte order,
//! checked before Vulkan sees them.
//!
//! ```no_run
//! # fn f(device: &tuff::Device, bytes: &[u8]) -> tuff::Result<()> {
//! let module = device.create_shader_module_from_spirv(bytes)?;
//! # let _ = module;
//! # Ok(()) }
//! ```

use crate::handles::{Device, ShaderModule};
use crate::structs::ShaderModuleCreateInfo;
use crate::{Error, Result};

/// The first word of every SPIR-V module.
const MAGIC: u32 = 0x0723_0203;

impl Device {
    /// `vkCreateShaderModule` from the bytes of a SPIR-V module (a `.spv` file),
    /// which may be in either byte order. See [`spirv_words`] for what is checked.
    pub fn create_shader_module_from_spirv(&self, bytes: &[u8]) -> Result<ShaderModule> {
        let words = spirv_words(bytes)?;
        self.create_shader_module(&ShaderModuleCreateInfo::new().code(&words))
    }
}

/// The words of the SPIR-V module stored in `bytes`, in the host's byte order.
///
/// Refuses, naming the rule, bytes that are empty
/// (`VUID-VkShaderModuleCreateInfo-codeSize-01085`), not a whole number of words
/// (`VUID-VkShaderModuleCreateInfo-codeSize-01086`), or that do not begin with the
/// SPIR-V magic number in either byte order, so cannot be the SPIR-V that
/// `VUID-VkShaderModuleCreateInfo-pCode-01087` asks for.
///
/// ```
/// let words = tuff::spirv_words(&[0x03, 0x02, 0x23, 0x07, 1, 0, 0, 0]).unwrap();
/// assert_eq!(words, [0x0723_0203, 1]);
/// // The same module stored big-endian.
/// let swapped = tuff::spirv_words(&[0x07, 0x23, 0x02, 0x03, 0, 0, 0, 1]).unwrap();
/// assert_eq!(swapped, words);
/// assert!(tuff::spirv_words(b"#version 450").is_err());
/// ```
pub fn spirv_words(bytes: &[u8]) -> Result<Vec<u32>> {
    let refuse = |vuid: &'static str, message: String| Err(Error::Validation { vuid, message });
    if bytes.is_empty() {
        return refuse(
            "VUID-VkShaderModuleCreateInfo-codeSize-01085",
            "the SPIR-V module is empty".into(),
        );
    }
    if bytes.len() % 4 != 0 {
        return refuse(
            "VUID-VkShaderModuleCreateInfo-codeSize-01086",
            format!(
                "{} bytes of SPIR-V are not a whole number of 4-byte words",
                bytes.len()
            ),
        );
    }
    let mut words: Vec<u32> = bytes
        .chunks_exact(4)
        .map(|w| u32::from_le_bytes([w[0], w[1], w[2], w[3]]))
        .collect();
    match words[0] {
        MAGIC => {}
        swapped if swapped == MAGIC.swap_bytes() => {
            words.iter_mut().for_each(|w| *w = w.swap_bytes());
        }
        other => {
            return refuse(
                "VUID-VkShaderModuleCreateInfo-pCode-01087",
                format!(
                    "the bytes do not begin with the SPIR-V magic number {MAGIC:#010x} \
                     (they begin with {other:#010x}): not a SPIR-V module"
                ),
            );
        }
    }
    Ok(words)
}

/// A resource variable a module declares: its set, binding and array size (0 for a
/// runtime-sized array).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct Resource {
    /// `DescriptorSet`.
    pub set: u32,
    /// `Binding`.
    pub binding: u32,
    /// Descriptors the variable spans: 1, an array's length, or 0 for a runtime array.
    pub count: u32,
}

/// What a module's shaders need from a pipeline layout: every resource variable it
/// declares with a set and binding, and whether it declares push constants. A
/// module whose entry points do not all use every variable asks for more than the
/// one in a pipeline needs; that errs on the side of refusing.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub(crate) struct Interface {
    /// The resource variables.
    pub resources: Vec<Resource>,
    /// Whether a `PushConstant` variable is declared.
    pub push_constants: bool,
}

/// The interface of the SPIR-V module in `words` (in the host's byte order, as
/// [`spirv_words`] returns them). Malformed instructions end the walk; what was read
/// until then is kept.
pub(crate) fn interface(words: &[u32]) -> Interface {
    use std::collections::HashMap;
    const OP_DECORATE: u32 = 71;
    const OP_VARIABLE: u32 = 59;
    const OP_TYPE_POINTER: u32 = 32;
    const OP_TYPE_ARRAY: u32 = 28;
    const OP_TYPE_RUNTIME_ARRAY: u32 = 29;
    const OP_CONSTANT: u32 = 43;
    const BINDING: u32 = 33;
    const DESCRIPTOR_SET: u32 = 34;
    const PUSH_CONSTANT: u32 = 9;
    let mut sets: HashMap<u32, u32> = HashMap::new();
    let mut bindings: HashMap<u32, u32> = HashMap::new();
    let mut pointers: HashMap<u32, u32> = HashMap::new();
    let mut arrays: HashMap<u32, Option<u32>> = HashMap::new();
    let mut constants: HashMap<u32, u32> = HashMap::new();
    let mut variables: Vec<(u32, u32, u32)> = Vec::new();
    // The header is five words; instructions follow.
    let mut at = 5;
    while at < words.len() {
        let (count, op) = ((words[at] >> 16) as usize, words[at] & 0xffff);
        if count == 0 || at + count > words.len() {
            break;
        }
        let w = &words[at..at + count];
        match (op, w.len()) {
            (OP_DECORATE, 4..) if w[2] == DESCRIPTOR_SET => {
                sets.insert(w[1], w[3]);
            }
            (OP_DECORATE, 4..) if w[2] == BINDING => {
                bindings.insert(w[1], w[3]);
            }
            (OP_TYPE_POINTER, 4..) => {
                pointers.insert(w[1], w[3]);
            }
            (OP_TYPE_ARRAY, 4..) => {
                arrays.insert(w[1], Some(w[3]));
            }
            (OP_TYPE_RUNTIME_ARRAY, 3..) => {
                arrays.insert(w[1], None);
            }
            (OP_CONSTANT, 4..) => {
                constants.insert(w[2], w[3]);
            }
            (OP_VARIABLE, 4..) => variables.push((w[1], w[2], w[3])),
            _ => {}
        }
        at += count;
    }
    let mut out = Interface::default();
    for (ty, id, storage) in variables {
        if storage == PUSH_CONSTANT {
            out.push_constants = true;
        }
        let (Some(&set), Some(&binding)) = (sets.get(&id), bindings.get(&id)) else {
            continue;
        };
        let pointee = pointers.get(&ty).copied().unwrap_or(ty);
        let count = match arrays.get(&pointee) {
            Some(Some(length)) => constants.get(length).copied().unwrap_or(1),
            Some(None) => 0,
            None => 1,
        };
        out.resources.push(Resource {
            set,
            binding,
            count,
        });
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn words(bytes: &[u8]) -> Vec<u32> {
        spirv_words(bytes).expect("SPIR-V")
    }

    #[test]
    fn the_test_shaders_interfaces() {
        let comp = interface(&words(include_bytes!("../../shaders/spv/test.comp.spv")));
        let mut found: Vec<(u32, u32, u32)> = comp
            .resources
            .iter()
            .map(|r| (r.set, r.binding, r.count))
            .collect();
        found.sort_unstable();
        assert_eq!(found, [(0, 0, 1), (0, 1, 1)]);
        assert!(!comp.push_constants);
        let frag = interface(&words(include_bytes!("../../shaders/spv/test.frag.spv")));
        assert!(frag.resources.is_empty());
        assert!(frag.push_constants);
    }

    #[test]
    fn a_truncated_module_keeps_what_was_read() {
        let mut w = words(include_bytes!("../../shaders/spv/test.comp.spv"));
        w.truncate(20);
        let _ = interface(&w);
        assert_eq!(interface(&w[..3]), Interface::default());
    }
}
