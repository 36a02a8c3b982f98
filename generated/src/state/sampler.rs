//! What the device records of samplers.

use super::live::Live;
use ash::vk::{self, Handle as _};

impl Live {
    /// Records what a new sampler does ([`sampler_bits`]).
    pub(crate) fn sampler_created(&self, raw: vk::Sampler, bits: u8) {
        self.samplers.lock().insert(raw.as_raw(), bits);
    }

    /// What a live sampler made through the wrappers does ([`sampler_bits`]).
    pub(crate) fn sampler_bits(&self, raw: vk::Sampler) -> Option<u8> {
        self.samplers.lock().get(&raw.as_raw()).copied()
    }
}
