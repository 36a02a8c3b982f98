//! A safe home for what layers report through `VK_EXT_debug_utils`.
//!
//! A messenger's callback gets a raw user-data pointer, which would dangle if the log
//! it points to went first; the instance's own messenger (chained into
//! `VkInstanceCreateInfo`) even runs during `vkDestroyInstance`. So the pointer given
//! to Vulkan is not an address but the log's number, looked up in a table of live
//! logs: a message that arrives after its log is gone is dropped, never written
//! through a dangling pointer.
//!
//! ```no_run
//! # fn f(entry: &tuff::Entry) -> tuff::Result<()> {
//! let log = tuff::MessageLog::new();
//! let layers = [tuff::CStrPtr::from(c"VK_LAYER_KHRONOS_validation")];
//! let extensions = [tuff::CStrPtr::from(c"VK_EXT_debug_utils")];
//! let mut chained = log.messenger_info();
//! // SAFETY: VK_EXT_debug_utils, which the chained messenger needs, is enabled, and
//! // it requires no other extension; the API version is left at 1.0.
//! let instance = unsafe {
//!     entry.create_instance(
//!         &tuff::InstanceCreateInfo::new()
//!             .enabled_layer_names(&layers)
//!             .enabled_extension_names(&extensions)
//!             .push_next(&mut chained),
//!     )
//! }?;
//! let messenger = instance.create_debug_utils_messenger_ext(&log.messenger_info())?;
//! // ... use Vulkan ...
//! drop((messenger, instance));
//! assert!(log.take().is_empty(), "the validation layer complained");
//! # Ok(()) }
//! ```

use crate::DebugUtilsMessengerCreateInfoEXT;
use ash::vk;
use core::ffi::{c_void, CStr};
use std::collections::HashMap;
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::sync::{Arc, Mutex, Weak};

/// What a log holds; shared with the table of live logs.
#[derive(Default)]
struct Lines {
    lines: Mutex<Vec<String>>,
    /// Whether the callback asks the layer to skip a call it reports an error on.
    abort: AtomicBool,
}

/// The live logs by number. Layers may call back from any thread, so this is a real
/// lock whatever the `multi_thread` feature says.
static LOGS: Mutex<Option<HashMap<usize, Weak<Lines>>>> = Mutex::new(None);

/// Numbers for logs; 0 is never used, so a null user-data pointer finds no log.
static NEXT: AtomicUsize = AtomicUsize::new(1);

/// Collects the messages of debug messengers made from [`MessageLog::messenger_info`],
/// each as `"<severity>: <message>"`.
///
/// ```
/// let log = tuff::MessageLog::new();
/// assert!(log.is_empty());
/// ```
pub struct MessageLog {
    id: usize,
    messages: Arc<Lines>,
}

impl core::fmt::Debug for MessageLog {
    /// How many messages it holds now.
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        let held = self.messages.lines.lock().map(|m| m.len()).unwrap_or(0);
        f.debug_struct("MessageLog")
            .field("messages", &held)
            .finish_non_exhaustive()
    }
}

impl MessageLog {
    /// An empty log.
    ///
    /// ```
    /// let log = tuff::MessageLog::new();
    /// assert!(log.take().is_empty());
    /// ```
    pub fn new() -> Self {
        let id = NEXT.fetch_add(1, Ordering::Relaxed);
        let messages = Arc::new(Lines::default());
        if let Ok(mut logs) = LOGS.lock() {
            logs.get_or_insert_with(HashMap::new)
                .insert(id, Arc::downgrade(&messages));
        }
        MessageLog { id, messages }
    }

    /// A messenger create info whose callback writes into this log: warnings and
    /// errors of every message type. Chain it into an `InstanceCreateInfo` to hear
    /// instance creation and destruction, and pass it to
    /// `create_debug_utils_messenger_ext` for the rest; change the severities or
    /// types with its setters.
    ///
    /// ```
    /// use tuff::vk::DebugUtilsMessageSeverityFlagsEXT as Severity;
    /// let log = tuff::MessageLog::new();
    /// let info = log.messenger_info().message_severity(Severity::ERROR);
    /// # let _ = info;
    /// ```
    pub fn messenger_info(&self) -> DebugUtilsMessengerCreateInfoEXT<'static> {
        DebugUtilsMessengerCreateInfoEXT::new()
            .message_severity(
                vk::DebugUtilsMessageSeverityFlagsEXT::WARNING
                    | vk::DebugUtilsMessageSeverityFlagsEXT::ERROR,
            )
            .message_type(
                vk::DebugUtilsMessageTypeFlagsEXT::GENERAL
                    | vk::DebugUtilsMessageTypeFlagsEXT::VALIDATION
                    | vk::DebugUtilsMessageTypeFlagsEXT::PERFORMANCE,
            )
            .pfn_user_callback(Some(on_message))
            // The number, not an address: see the module's docs.
            .user_data(self.id as *mut c_void)
    }

    /// The messages so far, leaving the log empty.
    ///
    /// ```
    /// let log = tuff::MessageLog::new();
    /// assert_eq!(log.take(), Vec::<String>::new());
    /// ```
    pub fn take(&self) -> Vec<String> {
        self.messages
            .lines
            .lock()
            .map(|mut m| std::mem::take(&mut *m))
            .unwrap_or_default()
    }

    /// Whether the messengers of this log ask the validation layer to skip each call
    /// it reports an error on (the callback returns `VK_TRUE`), so that the driver
    /// never sees a call that breaks a rule. Off by default. A test that proves a
    /// rule through an `_unchecked` method turns it on, so the broken call cannot
    /// crash the driver.
    ///
    /// ```
    /// let log = tuff::MessageLog::new();
    /// log.abort_on_error(true);
    /// ```
    pub fn abort_on_error(&self, abort: bool) {
        self.messages.abort.store(abort, Ordering::Relaxed);
    }

    /// Whether no message arrived since the last [`MessageLog::take`].
    ///
    /// ```
    /// assert!(tuff::MessageLog::new().is_empty());
    /// ```
    pub fn is_empty(&self) -> bool {
        self.messages
            .lines
            .lock()
            .map(|m| m.is_empty())
            .unwrap_or(true)
    }
}

impl Default for MessageLog {
    fn default() -> Self {
        Self::new()
    }
}

impl Drop for MessageLog {
    fn drop(&mut self) {
        if let Ok(mut logs) = LOGS.lock() {
            if let Some(logs) = logs.as_mut() {
                logs.remove(&self.id);
            }
        }
    }
}

/// The callback of every messenger made from a [`MessageLog`]. It never unwinds: a
/// poisoned lock or a missing log drops the message.
unsafe extern "system" fn on_message(
    severity: vk::DebugUtilsMessageSeverityFlagsEXT,
    _types: vk::DebugUtilsMessageTypeFlagsEXT,
    data: *const vk::DebugUtilsMessengerCallbackDataEXT<'_>,
    user: *mut c_void,
) -> vk::Bool32 {
    // SAFETY: the layer passes null or valid callback data whose message is null or
    // a NUL-terminated string, both valid for the duration of the call.
    let text = unsafe { data.as_ref() }
        .filter(|d| !d.p_message.is_null())
        // SAFETY: as above, a non-null message is a valid C string.
        .map(|d| unsafe { CStr::from_ptr(d.p_message) }.to_string_lossy())
        .unwrap_or_else(|| "<no message>".into());
    let log = LOGS
        .lock()
        .ok()
        .and_then(|logs| logs.as_ref()?.get(&(user as usize))?.upgrade());
    let Some(messages) = log else {
        return vk::FALSE;
    };
    if let Ok(mut m) = messages.lines.lock() {
        m.push(format!("{severity:?}: {text}"));
    }
    let abort = messages.abort.load(Ordering::Relaxed)
        && severity.contains(vk::DebugUtilsMessageSeverityFlagsEXT::ERROR);
    if abort {
        vk::TRUE
    } else {
        vk::FALSE
    }
}
