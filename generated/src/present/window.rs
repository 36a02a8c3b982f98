//! Surfaces from windows: the window-system handles come from the window itself,
//! through `raw-window-handle`, and the surface keeps the window alive, so no raw
//! pointer passes through the caller's hands.
//!
//! ```no_run
//! # fn f<W>(instance: &tuff::Instance, window: tuff::runtime::Vrc<W>) -> tuff::Result<()>
//! # where W: raw_window_handle::HasWindowHandle + raw_window_handle::HasDisplayHandle
//! #     + tuff::runtime::MaybeSendSync + 'static {
//! let surface = instance.create_surface(window)?;
//! # drop(surface);
//! # Ok(()) }
//! ```

use crate::handles::{Instance, SurfaceKHR};
use crate::{Error, Result};
use ash::vk;
use raw_window_handle::{HasDisplayHandle, HasWindowHandle, RawDisplayHandle, RawWindowHandle};
use tuff_runtime::{MaybeSendSync, Retained, Vrc};

impl Instance {
    /// Creates a surface for `window` with the surface extension of its window
    /// system (`VK_KHR_xlib_surface`, `VK_KHR_xcb_surface`,
    /// `VK_KHR_wayland_surface` or `VK_KHR_win32_surface`, whichever this build's
    /// features emit and the instance enabled). The surface keeps `window` alive, and
    /// every swapchain keeps its surface alive, so the window outlives all of them.
    ///
    /// Safe because the handles are the window's own and the surface keeps the
    /// window: `raw-window-handle` promises that the pointers in a window's and
    /// display's handles (the Xlib `Display`, the XCB connection, the Wayland display
    /// and surface) are valid while the handle is borrowed, and this method relies on
    /// the window object keeping them valid as long as it lives, as the windows of
    /// winit and of the other window libraries do (`VUID-VkXlibSurfaceCreateInfoKHR-
    /// dpy-01313` and its siblings); a window type that frees its display or surface
    /// through `&self` while alive breaks that. Window IDs are a number in the window
    /// system's protocol (an X11 `Window`, a Win32 `HWND`): the window object names its
    /// own window, which it does not destroy while it lives; another connection to
    /// the window system can, which no Rust type can prevent, as `raw-window-handle`
    /// says of these IDs. wgpu and vulkano make surfaces from windows on the same
    /// terms.
    ///
    /// # Errors
    ///
    /// [`Error::Window`] when the window gives no handle now, or one of a window
    /// system this build has no surface extension for (macOS and iOS need a
    /// `CAMetalLayer`, which `Instance::create_metal_surface_ext` (feature `ext_metal_surface`) takes);
    /// [`Error::ExtensionNotEnabled`] when the instance did not enable the
    /// extension; and the errors of `vkCreate*SurfaceKHR`.
    pub fn create_surface<W>(&self, window: Vrc<W>) -> Result<SurfaceKHR>
    where
        W: HasWindowHandle + HasDisplayHandle + MaybeSendSync + 'static,
    {
        let display = window
            .display_handle()
            .map_err(|e| Error::Window(format!("the window's display has no handle: {e}")))?
            .as_raw();
        let handle = window
            .window_handle()
            .map_err(|e| Error::Window(format!("the window has no handle: {e}")))?
            .as_raw();
        let raw = self.surface_for(display, handle)?;
        let kept: Retained = window;
        Ok(SurfaceKHR::from_raw(raw, self, Some(kept), true))
    }

    /// The raw surface for the handles of a window that the caller keeps alive with
    /// the surface.
    fn surface_for(
        &self,
        display: RawDisplayHandle,
        handle: RawWindowHandle,
    ) -> Result<vk::SurfaceKHR> {
        match (display, handle) {
            #[cfg(feature = "khr_xlib_surface")]
            (RawDisplayHandle::Xlib(_), RawWindowHandle::Xlib(w)) => {
                let dpy = xlib_display(display)?;
                let fp = self
                    .ext()
                    .khr_xlib_surface
                    .as_ref()
                    .ok_or(Error::ExtensionNotEnabled("VK_KHR_xlib_surface"))?
                    .create_xlib_surface_khr;
                let info = vk::XlibSurfaceCreateInfoKHR::default()
                    .dpy(dpy.as_ptr().cast())
                    .window(w.window);
                let mut out = vk::SurfaceKHR::null();
                // SAFETY: the display pointer is the window's, valid while the window
                // is, and the caller keeps the window alive with the surface (01313);
                // the window ID is the window's own (01314); the struct is made here
                // with no chain and no flags.
                let r = unsafe { fp(crate::Handle::raw(self), &info, core::ptr::null(), &mut out) };
                created(r, out)
            }
            #[cfg(feature = "khr_xcb_surface")]
            (RawDisplayHandle::Xcb(_), RawWindowHandle::Xcb(w)) => {
                let connection = xcb_connection(display)?;
                let fp = self
                    .ext()
                    .khr_xcb_surface
                    .as_ref()
                    .ok_or(Error::ExtensionNotEnabled("VK_KHR_xcb_surface"))?
                    .create_xcb_surface_khr;
                let info = vk::XcbSurfaceCreateInfoKHR::default()
                    .connection(connection.as_ptr())
                    .window(w.window.get());
                let mut out = vk::SurfaceKHR::null();
                // SAFETY: as for Xlib: the connection is the window's, kept alive
                // with the surface; the window ID is the window's own.
                let r = unsafe { fp(crate::Handle::raw(self), &info, core::ptr::null(), &mut out) };
                created(r, out)
            }
            #[cfg(feature = "khr_wayland_surface")]
            (RawDisplayHandle::Wayland(_), RawWindowHandle::Wayland(w)) => {
                let wl_display = wayland_display(display)?;
                let fp = self
                    .ext()
                    .khr_wayland_surface
                    .as_ref()
                    .ok_or(Error::ExtensionNotEnabled("VK_KHR_wayland_surface"))?
                    .create_wayland_surface_khr;
                let info = vk::WaylandSurfaceCreateInfoKHR::default()
                    .display(wl_display.as_ptr())
                    .surface(w.surface.as_ptr());
                let mut out = vk::SurfaceKHR::null();
                // SAFETY: the display and surface pointers are the window's, valid
                // while the window is, which the surface keeps alive.
                let r = unsafe { fp(crate::Handle::raw(self), &info, core::ptr::null(), &mut out) };
                created(r, out)
            }
            #[cfg(feature = "khr_win32_surface")]
            (RawDisplayHandle::Windows(_), RawWindowHandle::Win32(w)) => {
                let fp = self
                    .ext()
                    .khr_win32_surface
                    .as_ref()
                    .ok_or(Error::ExtensionNotEnabled("VK_KHR_win32_surface"))?
                    .create_win32_surface_khr;
                let hinstance = w.hinstance.ok_or_else(|| {
                    Error::Window("the Win32 window handle names no HINSTANCE".into())
                })?;
                let info = vk::Win32SurfaceCreateInfoKHR::default()
                    .hinstance(hinstance.get())
                    .hwnd(w.hwnd.get());
                let mut out = vk::SurfaceKHR::null();
                // SAFETY: the window's own instance and window handles, the window
                // kept alive with the surface.
                let r = unsafe { fp(crate::Handle::raw(self), &info, core::ptr::null(), &mut out) };
                created(r, out)
            }
            (display, handle) => Err(Error::Window(format!(
                "no surface extension of this build makes a surface for this window ({handle:?} on {display:?})"
            ))),
        }
    }
}

/// The surface a `vkCreate*SurfaceKHR` call wrote, or its error.
#[allow(dead_code)] // A build with no window system's extension makes no surface.
fn created(r: vk::Result, out: vk::SurfaceKHR) -> Result<vk::SurfaceKHR> {
    if r.as_raw() < 0 {
        return Err(Error::Vk(r));
    }
    Ok(out)
}

/// The Xlib `Display` a display handle carries, for a surface or a command that takes
/// one: [`Error::Window`] for a handle of another window system or one naming none.
#[cfg(any(feature = "khr_xlib_surface", feature = "ext_acquire_xlib_display"))]
pub(crate) fn xlib_display(
    display: RawDisplayHandle,
) -> Result<core::ptr::NonNull<core::ffi::c_void>> {
    match display {
        RawDisplayHandle::Xlib(d) => d
            .display
            .ok_or_else(|| Error::Window("the Xlib display handle names no Display".into())),
        _ => Err(Error::Window(
            "the display handle is not an Xlib one".into(),
        )),
    }
}

/// The XCB connection a display handle carries, as `xlib_display` does.
#[cfg(feature = "khr_xcb_surface")]
pub(crate) fn xcb_connection(
    display: RawDisplayHandle,
) -> Result<core::ptr::NonNull<core::ffi::c_void>> {
    match display {
        RawDisplayHandle::Xcb(d) => d
            .connection
            .ok_or_else(|| Error::Window("the XCB display handle names no connection".into())),
        _ => Err(Error::Window("the display handle is not an XCB one".into())),
    }
}

/// The Wayland display a display handle carries, as `xlib_display` does.
#[cfg(feature = "khr_wayland_surface")]
pub(crate) fn wayland_display(
    display: RawDisplayHandle,
) -> Result<core::ptr::NonNull<core::ffi::c_void>> {
    match display {
        RawDisplayHandle::Wayland(d) => Ok(d.display),
        _ => Err(Error::Window(
            "the display handle is not a Wayland one".into(),
        )),
    }
}
