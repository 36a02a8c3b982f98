//! A plain X11 window for surface tests, on the display `DISPLAY` names (Xvfb on CI).
//! libX11 is loaded at run time, so building the tests needs no X development files.
#![allow(dead_code)]

use x11_dl::xlib;

/// An open display connection with one mapped window; both go on drop.
pub struct X11Window {
    xlib: xlib::Xlib,
    /// The display connection.
    pub display: *mut xlib::Display,
    /// The window.
    pub window: xlib::Window,
    /// The default screen the window is on.
    screen: i32,
    /// The window was destroyed before drop ([`X11Window::destroy_window`]).
    destroyed: std::sync::atomic::AtomicBool,
}

// SAFETY: the process calls XInitThreads before any other Xlib call (`open`), which
// makes the connection's calls safe from any thread; the rest is the loaded library's
// function table.
unsafe impl Send for X11Window {}
// SAFETY: as above.
unsafe impl Sync for X11Window {}

impl raw_window_handle::HasWindowHandle for X11Window {
    fn window_handle(
        &self,
    ) -> Result<raw_window_handle::WindowHandle<'_>, raw_window_handle::HandleError> {
        let raw = raw_window_handle::XlibWindowHandle::new(self.window);
        // SAFETY: the window is destroyed only when `self` drops.
        Ok(unsafe { raw_window_handle::WindowHandle::borrow_raw(raw.into()) })
    }
}

impl raw_window_handle::HasDisplayHandle for X11Window {
    fn display_handle(
        &self,
    ) -> Result<raw_window_handle::DisplayHandle<'_>, raw_window_handle::HandleError> {
        let raw = raw_window_handle::XlibDisplayHandle::new(
            std::ptr::NonNull::new(self.display.cast()),
            self.screen,
        );
        // SAFETY: the display connection is closed only when `self` drops.
        Ok(unsafe { raw_window_handle::DisplayHandle::borrow_raw(raw.into()) })
    }
}

impl X11Window {
    /// Opens the display and maps a `width` x `height` window. Panics with what to do
    /// when there is no libX11 or no X server: a test that needs a window fails then.
    pub fn open(width: u32, height: u32) -> Self {
        let xlib = xlib::Xlib::open().expect("cannot load libX11 (apt-get install libx11-6)");
        // SAFETY: XInitThreads is called before any other Xlib call of this connection;
        // the display pointer is checked before use and the window is made on it.
        unsafe {
            // Once per process, before any other Xlib call: tests open windows from
            // several threads.
            static THREADS: std::sync::Once = std::sync::Once::new();
            THREADS.call_once(|| {
                (xlib.XInitThreads)();
            });
            let display = (xlib.XOpenDisplay)(std::ptr::null());
            assert!(
                !display.is_null(),
                "cannot open the X display {:?}: start an X server (scripts/test.sh starts \
                 Xvfb) and set DISPLAY",
                std::env::var("DISPLAY").unwrap_or_default()
            );
            let screen = (xlib.XDefaultScreen)(display);
            let root = (xlib.XRootWindow)(display, screen);
            let window = (xlib.XCreateSimpleWindow)(display, root, 0, 0, width, height, 0, 0, 0);
            (xlib.XMapWindow)(display, window);
            (xlib.XSync)(display, xlib::False);
            Self {
                xlib,
                display,
                window,
                screen,
                destroyed: false.into(),
            }
        }
    }

    /// The ID of the default visual of the window's screen.
    pub fn visual_id(&self) -> xlib::VisualID {
        // SAFETY: the display is live until drop, and the screen is one of its own.
        unsafe {
            let visual = (self.xlib.XDefaultVisual)(self.display, self.screen);
            (self.xlib.XVisualIDFromVisual)(visual)
        }
    }

    /// Resizes the window and waits until the server has done it.
    pub fn resize(&self, width: u32, height: u32) {
        // SAFETY: the display and window are live until drop.
        unsafe {
            (self.xlib.XResizeWindow)(self.display, self.window, width, height);
            (self.xlib.XSync)(self.display, xlib::False);
        }
    }
}

impl X11Window {
    /// Destroys the window behind the back of whatever surface was made from it, as a
    /// window manager or the user closing it would: the surface is lost. The display
    /// connection stays open until drop.
    pub fn destroy_window(&self) {
        use std::sync::atomic::Ordering;
        if !self.destroyed.swap(true, Ordering::SeqCst) {
            // SAFETY: the display is live until drop; the window is destroyed once.
            unsafe {
                (self.xlib.XDestroyWindow)(self.display, self.window);
                (self.xlib.XSync)(self.display, xlib::False);
            }
        }
    }
}

impl Drop for X11Window {
    fn drop(&mut self) {
        // SAFETY: the window was made on this display, and every Vulkan surface made
        // from them is gone (the owner drops this after its surfaces).
        unsafe {
            if !*self.destroyed.get_mut() {
                (self.xlib.XDestroyWindow)(self.display, self.window);
            }
            (self.xlib.XCloseDisplay)(self.display);
        }
    }
}
