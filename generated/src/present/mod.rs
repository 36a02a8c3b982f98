//! Presentation: surfaces made from windows, and the swapchain's recreate path.

#[cfg(feature = "khr_swapchain")]
mod swapchain;
#[cfg(feature = "khr_surface")]
pub(crate) mod window;
