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
