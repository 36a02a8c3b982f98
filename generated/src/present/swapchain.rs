//! The swapchain's recreate path: the new swapchain retires the old one and both keep
//! their surface alive, so the surface is destroyed only after the last of them.

use crate::{Device, Error, Handle, Result, SurfaceKHR, SwapchainCreateInfoKHR, SwapchainKHR};

impl SwapchainKHR {
    /// The surface this swapchain presents to, which it keeps alive.
    #[inline]
    pub fn presents_to(&self, surface: &SurfaceKHR) -> bool {
        self.kept().is_some_and(|k| {
            tuff_runtime::Vrc::as_ptr(k) as *const () as usize == surface.address()
        })
    }

    crate::helpers::as_safe_as! { vkCreateSwapchainKHR,
        /// Creates the swapchain that replaces this one (after a resize, or when a present
        /// or acquire said `ERROR_OUT_OF_DATE_KHR` or `SUBOPTIMAL_KHR`): `create_info`'s
        /// `oldSwapchain` is set to this swapchain, which Vulkan then retires, and its
        /// `surface` to `surface`. This swapchain stays usable for presenting images it
        /// already acquired; drop it once they are presented and its work is done.
        ///
        /// Fails with the rule's VUID when `surface` is not the one this swapchain
        /// presents to (`VUID-VkSwapchainCreateInfoKHR-oldSwapchain-01933`).
        ///
        /// # Safety
        ///
        /// This method is `unsafe` exactly when [`Device::create_swapchain_khr`] is (it
        /// is safe with this crate's emitted API; a crate generated from more of the
        /// registry may leave it rules); the caller then upholds the rules its
        /// `# Safety` section lists for `create_info`.
        ///
        /// ```no_run
        /// # fn f(device: &tuff::Device, surface: &tuff::SurfaceKHR, old: &tuff::SwapchainKHR,
        /// #      info: &tuff::SwapchainCreateInfoKHR) -> tuff::Result<()> {
        /// let swapchain = old.recreate(device, surface, info)?;
        /// drop(swapchain);
        /// # Ok(()) }
        /// ```
        pub fn recreate<'a>(
            &'a self,
            device: &Device,
            surface: &SurfaceKHR,
            create_info: &SwapchainCreateInfoKHR<'a>,
        ) -> Result<SwapchainKHR> {
            if !self.presents_to(surface) {
                return Err(Error::Validation {
                    vuid: "VUID-VkSwapchainCreateInfoKHR-oldSwapchain-01933",
                    message: "the old swapchain presents to another surface".into(),
                });
            }
            if self.parent().raw() != device.raw() {
                return Err(Error::Validation {
                    vuid: "VUID-VkSwapchainCreateInfoKHR-oldSwapchain-parent",
                    message: "the old swapchain comes from another device".into(),
                });
            }
            let info = (*create_info).old_swapchain(Some(self));
            // `create_swapchain_khr` is safe in the pinned configuration and may be
            // `unsafe` in wider ones.
            #[allow(unused_unsafe)]
            // SAFETY: where `create_swapchain_khr` is `unsafe`, so is this method, and its
            // caller upholds the rules of `create_info`; `oldSwapchain` is this live
            // swapchain of the same device and surface (checked above).
            unsafe {
                device.create_swapchain_khr(surface, &info)
            }
        }
    }
}
