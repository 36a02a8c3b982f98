//! Diagnostics: what the layers report, kept safely, and why an instance or device
//! could not be created.

#[cfg(feature = "ext_debug_utils")]
pub(crate) mod debug_log;
pub(crate) mod presence;
