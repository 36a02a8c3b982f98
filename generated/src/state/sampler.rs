//! What the device records of samplers.

use super::live::Live;
use ash::vk::{self, Handle as _};

impl Live {
    /// Records what a new sampler does ([`sampler_bits`]).
    pub(crate) fn sampler_created(&self, raw: vk::Sampler, bits: u8) {
        self.samplers.lock().insert(raw.as_raw(), bits);
    }

    /// The gate a safe sampler creation holds from its count check until its sampler
    /// is listed, and the number of live samplers made through the wrappers.
    pub(crate) fn sampler_gate(&self) -> (tuff_runtime::VutexGuard<'_, ()>, usize) {
        let gate = self.sampling.lock();
        let live = self.samplers.lock().len();
        (gate, live)
    }

    /// What a live sampler made through the wrappers does ([`sampler_bits`]).
    pub(crate) fn sampler_bits(&self, raw: vk::Sampler) -> Option<u8> {
        self.samplers.lock().get(&raw.as_raw()).copied()
    }
}
