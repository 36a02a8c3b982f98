//! What the generated wrappers share: the loader, the error type, the handle trait,
//! slices of handles and of C strings, and the typed `pNext` chain marker.

use ash::vk;
use core::ffi::{c_char, CStr};
use core::marker::PhantomData;
use core::ptr::NonNull;
use tuff_runtime::Vrc;

/// Refuses a call that would break the rule `vuid`, saying what and where: the one
/// way every check, hand-written or emitted, says no.
#[cold]
pub(crate) fn refuse(vuid: &'static str, message: impl Into<String>) -> Result<()> {
    Err(Error::Validation {
        vuid,
        message: message.into(),
    })
}

/// Errors of the generated wrappers. New kinds may come with new checks, so a
/// `match` on it needs a catch-all arm.
///
/// ```no_run
/// # fn f(device: &tuff::Device) {
/// // A buffer of size 0 breaks a rule: the safe method names it, Vulkan never sees it.
/// match device.create_buffer(&tuff::BufferCreateInfo::new()) {
///     Err(tuff::Error::Validation { vuid, message }) => eprintln!("{vuid}: {message}"),
///     Err(other) => eprintln!("{other}"),
///     Ok(_buffer) => {}
/// }
/// # }
/// ```
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub enum Error {
    /// A command returned an error code.
    Vk(vk::Result),
    /// A dynamic check of a valid-usage rule failed before the command was called.
    Validation {
        /// The rule.
        vuid: &'static str,
        /// What was wrong.
        message: String,
    },
    /// A safe method was asked for something it cannot do while keeping its
    /// guarantees; the text says which method can.
    Misuse(&'static str),
    /// An extension command was called on an instance or device that did not enable
    /// the extension.
    ExtensionNotEnabled(&'static str),
    /// A command of a core version (`"Vulkan 1.4"`) was called on a device whose
    /// version, or its instance's `apiVersion`, is lower.
    VersionNotSupported(&'static str),
    /// A safe `create_instance` or `create_device` was asked to enable an extension
    /// that tuff does not emit. Its rules would then apply to calls no safe method
    /// checks them on; the `unsafe` `_unchecked` constructor enables it.
    ExtensionNotEmitted(String),
    /// A safe `create_instance` or `create_device` was asked to enable an emitted
    /// extension that brings rules to methods outside it which no check enforces
    /// (not in `api_info::CHECKED_EXTENSIONS`; `generated/VALIDATION.md` lists the
    /// rules); the `unsafe` `_unchecked` constructor enables it.
    ExtensionUnchecked(String),
    /// A mapped-memory access did not fit in the mapping, or its flush or
    /// invalidate range could not be formed.
    Map(tuff_runtime::MapError),
    /// A window gave no handle a surface can be made from: it has none now, or its
    /// window system has no surface extension in this build.
    Window(String),
    /// The Vulkan loader could not be found or opened.
    Load(String),
    /// An allocator could not give memory; the text is its
    /// [`tuff_runtime::AllocError`]'s.
    Alloc(String),
    /// An instance or device could not be created because layers, extensions or
    /// features it asked for are not there; `names` says which.
    NotPresent {
        /// What the creation returned: `ERROR_LAYER_NOT_PRESENT`,
        /// `ERROR_EXTENSION_NOT_PRESENT` or `ERROR_FEATURE_NOT_PRESENT`.
        result: vk::Result,
        /// "instance layer", "instance extension", "device extension" or
        /// "device feature".
        what: &'static str,
        /// The missing names, as the registry spells them.
        names: Vec<String>,
    },
}

// Written out rather than derived: thiserror's macro needs a syn of its own, which
// cargo builds before ash and so delays the crate's build (scripts/compile-time.sh).
impl core::fmt::Display for Error {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self {
            Error::Vk(r) => write!(f, "Vulkan returned {r}"),
            Error::Validation { vuid, message } => write!(f, "{vuid}: {message}"),
            Error::Misuse(what) => f.write_str(what),
            Error::ExtensionNotEnabled(name) => {
                write!(f, "extension {name} is not enabled on this instance or device")
            }
            Error::VersionNotSupported(version) => write!(
                f,
                "{version} commands need a device of {version} or newer, created from an instance whose apiVersion is at least {version}"
            ),
            Error::ExtensionNotEmitted(name) => write!(
                f,
                "extension {name} is outside tuff's emitted API (`api_info::EXTENSIONS`); only the `unsafe` `_unchecked` constructor enables it"
            ),
            Error::ExtensionUnchecked(name) => write!(
                f,
                "extension {name} brings rules to other methods that tuff does not check (it is not in `api_info::CHECKED_EXTENSIONS`); only the `unsafe` `_unchecked` constructor enables it"
            ),
            Error::Map(e) => write!(f, "mapped memory: {e}"),
            Error::Window(what) => write!(f, "window: {what}"),
            Error::Load(what) => write!(f, "cannot load the Vulkan loader: {what}"),
            Error::Alloc(what) => write!(f, "allocation failed: {what}"),
            Error::NotPresent {
                result,
                what,
                names,
            } => write!(f, "{what} not present: {} ({result:?})", names.join(", ")),
        }
    }
}

impl std::error::Error for Error {}

/// The result of a fallible wrapper call.
///
/// ```no_run
/// fn idle(device: &tuff::Device) -> tuff::Result<()> {
///     device.wait_idle()
/// }
/// ```
pub type Result<T> = core::result::Result<T, Error>;

impl From<vk::Result> for Error {
    fn from(r: vk::Result) -> Self {
        Error::Vk(r)
    }
}

/// A wrapper of a Vulkan handle.
pub trait Handle {
    /// The raw ash handle.
    type Raw: Copy;
    /// The raw handle, valid as long as the wrapper lives.
    fn raw(&self) -> Self::Raw;
    /// The raw handle in place, borrowed for as long as the wrapper is: what lets one
    /// wrapper stand for an array of one handle ([`Handles`]).
    fn raw_ref(&self) -> &Self::Raw;
}

pub(crate) mod sealed {
    /// Keeps [`Handles`](super::Handles) to the forms whose handles are laid out
    /// as Vulkan reads them.
    pub trait Sealed {}
}

/// What a command parameter or a struct member that is an array of handles takes, the
/// same in both: one wrapper (`&fence`, or a [`Bound`](crate::Bound) resource) or a
/// [`HandleSlice`] of several
/// (`&HandleSlice::new(&[&a, &b])`). Either borrows the wrappers, so none of them can
/// be dropped while the call or the struct holds its handle.
///
/// ```no_run
/// # fn f(device: &tuff::Device, a: &tuff::Fence, b: &tuff::Fence,
/// #      layout: &tuff::DescriptorSetLayout, pool: &tuff::DescriptorPool) -> tuff::Result<()> {
/// device.reset_fences(a)?;
/// device.reset_fences(&tuff::HandleSlice::new(&[a, b]))?;
/// let info = tuff::DescriptorSetAllocateInfo::new(pool).set_layouts(layout);
/// # let _ = info;
/// # Ok(()) }
/// ```
#[diagnostic::on_unimplemented(
    message = "`{Self}` is not a way to pass `{T}` handles",
    label = "one wrapper (`&x`) or a `&HandleSlice` of several",
    note = "several handles: `&HandleSlice::new(&[&a, &b])`, or `.iter().collect::<HandleSlice<_>>()`"
)]
pub trait Handles<'a, T: Handle + 'a>: Copy + sealed::Sealed {
    /// The raw handles, contiguous as Vulkan reads an array of them.
    fn raws(self) -> &'a [T::Raw];
    /// The wrappers, in the same order.
    fn wrappers(&self) -> &[&'a T];
}

impl<T: Handle> sealed::Sealed for &T {}

impl<'a, T: Handle> Handles<'a, T> for &'a T {
    #[inline]
    fn raws(self) -> &'a [T::Raw] {
        core::slice::from_ref(self.raw_ref())
    }
    #[inline]
    fn wrappers(&self) -> &[&'a T] {
        core::slice::from_ref(self)
    }
}

impl<T: Handle> sealed::Sealed for &HandleSlice<'_, T> {}

impl<'a, 'w: 'a, T: Handle> Handles<'a, T> for &'a HandleSlice<'w, T> {
    #[inline]
    fn raws(self) -> &'a [T::Raw] {
        &self.raw
    }
    #[inline]
    fn wrappers(&self) -> &[&'a T] {
        let pointers: &[NonNull<T>] = &self.wrappers;
        // SAFETY: each pointer was made from a `&'w T` (`'w: 'a`), so it is non-null,
        // aligned and points to a live `T` for `'a`; `NonNull<T>` and `&T` have one
        // layout, so the slice of one is a slice of the other.
        unsafe { core::slice::from_raw_parts(pointers.as_ptr().cast::<&'a T>(), pointers.len()) }
    }
}

/// The Vulkan loader: entry points that need no instance.
///
/// ```no_run
/// let entry = tuff::Entry::load()?;
/// let version = entry.enumerate_instance_version()?;
/// assert!(version >= ash::vk::API_VERSION_1_0);
/// # Ok::<(), tuff::Error>(())
/// ```
#[derive(Clone)]
pub struct Entry {
    inner: Vrc<ash::Entry>,
    // The callbacks instances and devices made from this entry are created and
    // destroyed with; they hold the entry, so the allocator outlives them.
    host: Option<crate::HostAllocator>,
}

impl core::fmt::Debug for Entry {
    /// The loader has no handle to show.
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.debug_struct("Entry").finish_non_exhaustive()
    }
}

impl Entry {
    /// Opens the system's Vulkan loader.
    pub fn load() -> Result<Entry> {
        // SAFETY: loading the loader library runs its initialisation, which the
        // Vulkan loader documents as safe to run at any time.
        let entry = unsafe { ash::Entry::load() }.map_err(|e| Error::Load(e.to_string()))?;
        Ok(Entry {
            inner: Vrc::new(entry),
            host: None,
        })
    }

    /// Wraps an already-loaded ash entry.
    pub fn from_ash(entry: ash::Entry) -> Entry {
        Entry {
            inner: Vrc::new(entry),
            host: None,
        }
    }

    /// This entry, whose instances and devices the implementation allocates host
    /// memory for through `host` (their `vkCreate*`/`vkDestroy*` take its callbacks).
    /// Instances made before keep the allocator they were made with.
    ///
    /// ```no_run
    /// let host = tuff::HostAllocator::new();
    /// let entry = tuff::Entry::load()?.with_host_allocator(host.clone());
    /// let instance = entry.create_instance(&tuff::InstanceCreateInfo::new())?;
    /// assert!(host.stats().live_blocks > 0);
    /// # drop(instance);
    /// # Ok::<(), tuff::Error>(())
    /// ```
    pub fn with_host_allocator(mut self, host: crate::HostAllocator) -> Entry {
        self.host = Some(host);
        self
    }

    /// The host allocator set by [`Self::with_host_allocator`].
    #[inline]
    pub fn host_allocator(&self) -> Option<&crate::HostAllocator> {
        self.host.as_ref()
    }

    /// ash's loader tables.
    #[inline]
    pub fn fns(&self) -> &ash::Entry {
        &self.inner
    }
}

/// Several wrappers and their raw handles side by side, for a command parameter or a
/// struct member that is an array of handles ([`Handles`]; one handle needs none:
/// `&fence` is taken as it is). Borrowing the wrappers keeps them alive while the call
/// or the struct uses their handles.
///
/// ```no_run
/// # fn f(a: &tuff::Semaphore, b: &tuff::Semaphore) -> tuff::Result<()> {
/// let waits = tuff::HandleSlice::new(&[a, b]);
/// let stages = [ash::vk::PipelineStageFlags::TRANSFER; 2];
/// let submit = tuff::SubmitInfo::new().wait_semaphores(&waits, &stages)?;
/// # let _ = submit;
/// # Ok(()) }
/// ```
pub struct HandleSlice<'a, T: Handle> {
    raw: smallvec::SmallVec<[T::Raw; 4]>,
    // Pointers rather than `&'a T`: a `SmallVec` has drop glue, which would make a
    // `HandleSlice` hold its wrappers borrowed until it is dropped rather than until
    // its last use, and invariant in `'a`.
    wrappers: smallvec::SmallVec<[NonNull<T>; 4]>,
    _marker: PhantomData<&'a T>,
}

impl<T: Handle> core::fmt::Debug for HandleSlice<'_, T>
where
    T::Raw: core::fmt::Debug,
{
    /// The raw handles, in order.
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.debug_list().entries(self.raw.iter()).finish()
    }
}

impl<'a, T: Handle> HandleSlice<'a, T> {
    /// Collects the raw handles of `wrappers`.
    pub fn new(wrappers: &[&'a T]) -> Self {
        wrappers.iter().copied().collect()
    }

    /// The number of handles.
    #[inline]
    pub fn len(&self) -> usize {
        self.raw.len()
    }

    /// Whether there are none.
    #[inline]
    pub fn is_empty(&self) -> bool {
        self.raw.is_empty()
    }

    /// The raw handles.
    #[inline]
    pub fn as_ptr(&self) -> *const T::Raw {
        self.raw.as_ptr()
    }

    /// The raw handles as a slice.
    #[inline]
    pub fn as_slice(&self) -> &[T::Raw] {
        &self.raw
    }
}

// SAFETY: a `HandleSlice` is raw handles and `&'a T`s held as pointers; a `&T` may go
// to, and be shared with, another thread when `T` is `Sync`.
unsafe impl<T: Handle + Sync> Send for HandleSlice<'_, T> where T::Raw: Send {}
// SAFETY: as for `Send`.
unsafe impl<T: Handle + Sync> Sync for HandleSlice<'_, T> where T::Raw: Sync {}

impl<'a, T: Handle> FromIterator<&'a T> for HandleSlice<'a, T> {
    /// Collects wrappers: `sets.iter().collect::<HandleSlice<_>>()`.
    fn from_iter<I: IntoIterator<Item = &'a T>>(iter: I) -> Self {
        let (raw, wrappers) = iter
            .into_iter()
            .map(|w| (w.raw(), NonNull::from(w)))
            .unzip();
        HandleSlice {
            raw,
            wrappers,
            _marker: PhantomData,
        }
    }
}

/// A C string pointer borrowed from a `CStr`, laid out as `const char*` so a slice of
/// them is a valid `const char* const*` array.
///
/// ```
/// let names = [tuff::CStrPtr::from(c"VK_LAYER_KHRONOS_validation")];
/// let info = tuff::InstanceCreateInfo::new().enabled_layer_names(&names);
/// assert_eq!(info.enabled_layer_count, 1);
/// ```
#[repr(transparent)]
#[derive(Clone, Copy, Debug)]
pub struct CStrPtr<'a> {
    ptr: *const c_char,
    _marker: PhantomData<&'a CStr>,
}

impl<'a> CStrPtr<'a> {
    /// The pointer to `s`; a `const fn`, so lists of names can be constants.
    ///
    /// ```
    /// const LAYERS: [tuff::CStrPtr<'static>; 1] =
    ///     [tuff::CStrPtr::new(c"VK_LAYER_KHRONOS_validation")];
    /// let info = tuff::InstanceCreateInfo::new().enabled_layer_names(&LAYERS);
    /// # let _ = info;
    /// ```
    pub const fn new(s: &'a CStr) -> Self {
        CStrPtr {
            ptr: s.as_ptr(),
            _marker: PhantomData,
        }
    }
}

impl<'a> From<&'a CStr> for CStrPtr<'a> {
    fn from(s: &'a CStr) -> Self {
        CStrPtr::new(s)
    }
}

/// Reads the names of an enabled-extensions array.
///
/// # Safety
///
/// `names` must point to `count` valid C strings.
unsafe fn names<'a>(count: u32, names: *const *const c_char) -> Vec<&'a CStr> {
    if names.is_null() {
        return Vec::new();
    }
    // SAFETY: the caller promises `count` valid pointers.
    unsafe {
        core::slice::from_raw_parts(names, count as usize)
            .iter()
            .map(|p| CStr::from_ptr(*p))
            .collect()
    }
}

impl crate::structs::InstanceCreateInfo<'_> {
    /// The extensions this info enables.
    pub(crate) fn enabled_extensions(&self) -> Vec<&CStr> {
        // SAFETY: the safe setter only stores slices of `CStrPtr`, valid C strings.
        unsafe {
            names(
                self.enabled_extension_count,
                self.pp_enabled_extension_names,
            )
        }
    }
}

impl crate::structs::InstanceCreateInfo<'_> {
    /// The layers this info enables.
    pub(crate) fn enabled_layers(&self) -> Vec<&CStr> {
        // SAFETY: the safe setter only stores slices of `CStrPtr`, valid C strings.
        unsafe { names(self.enabled_layer_count, self.pp_enabled_layer_names) }
    }
}

impl crate::structs::InstanceCreateInfo<'_> {
    /// The API version the application asks for (1.0 without application info).
    pub(crate) fn api_version(&self) -> u32 {
        if self.p_application_info.is_null() {
            return vk::API_VERSION_1_0;
        }
        // SAFETY: the safe setter stores a reference that outlives `self`.
        unsafe { (*self.p_application_info).api_version }
    }
}

impl crate::structs::DeviceCreateInfo<'_> {
    /// The extensions this info enables.
    pub(crate) fn enabled_extensions(&self) -> Vec<&CStr> {
        // SAFETY: the safe setter only stores slices of `CStrPtr`, valid C strings.
        unsafe {
            names(
                self.enabled_extension_count,
                self.pp_enabled_extension_names,
            )
        }
    }
}

/// The nodes of a `pNext` chain, from the first one `next` points to.
///
/// # Safety
///
/// `next` is null or points to a chain of live structs that each begin with `sType`
/// and `pNext`, as every chain `push_next` builds on the safe structs does.
pub(crate) unsafe fn chain_nodes<'a>(
    next: *const core::ffi::c_void,
) -> impl Iterator<Item = &'a vk::BaseInStructure<'a>> {
    let mut p = next.cast::<vk::BaseInStructure<'a>>();
    core::iter::from_fn(move || {
        // SAFETY: the caller vouches for every node of the chain.
        let node = unsafe { p.as_ref() }?;
        p = node.p_next;
        Some(node)
    })
}

/// Typed `pNext` chains.
pub mod chain {
    /// Implemented by every struct that may extend the `pNext` chain of `Head`.
    ///
    /// # Safety
    ///
    /// Implementors must begin with `sType` and `pNext`, as `VkBaseOutStructure`
    /// does, and be listed in the head's `structextends` in the registry.
    pub unsafe trait Extends<Head> {}
}

/// What every safe struct has besides its definition and setters, written once:
/// `Deref` to ash's struct, `as_raw`, and on request a zeroed `new` with `Default`
/// (`zeroed`) and a typed `push_next` (`chained`). The generated `structs` module
/// invokes it after each struct, as `safe_struct!(Name, 'a; zeroed chained);`, with
/// the struct's `#[cfg]` first where it has one and `'a` where ash's struct borrows.
macro_rules! safe_struct {
    ($(#[cfg($cfg:meta)])? $name:ident $(, $lt:lifetime)?; $($part:ident)*) => {
        $(#[cfg($cfg)])?
        impl<'a> $name<'a> {
            /// The ash struct this lowers to.
            #[inline]
            pub fn as_raw(&self) -> &crate::vk::$name $(<$lt>)? {
                &self.raw
            }
            /// The ash struct, for a command that writes into it.
            #[inline]
            #[allow(dead_code)]
            pub(crate) fn as_raw_mut(&mut self) -> &mut crate::vk::$name $(<$lt>)? {
                &mut self.raw
            }
            /// The ash struct, to change a value member that has no setter of the
            /// shape wanted (a nested member, one bit of a flags value).
            ///
            /// # Safety
            ///
            /// Only plain value members may change: the pointer members, the counts
            /// that go with them and `pNext` must stay as the setters left them, since
            /// the safe struct's borrows and the checks rely on them.
            #[inline]
            pub unsafe fn raw_values_mut(&mut self) -> &mut crate::vk::$name $(<$lt>)? {
                &mut self.raw
            }
        }
        $(#[cfg($cfg)])?
        impl<'a> core::fmt::Debug for $name<'a> {
            /// The ash struct's members, as ash prints them.
            fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
                core::fmt::Debug::fmt(&self.raw, f)
            }
        }
        $(#[cfg($cfg)])?
        impl<'a> core::ops::Deref for $name<'a> {
            type Target = crate::vk::$name $(<$lt>)?;
            #[inline]
            fn deref(&self) -> &Self::Target {
                &self.raw
            }
        }
        $crate::support::safe_struct!(@parts [$($cfg)?] $name [$($lt)?]; $($part)*);
    };
    (@parts [$($cfg:meta)?] $name:ident [$($lt:lifetime)?];) => {};
    (@parts [$($cfg:meta)?] $name:ident [$($lt:lifetime)?]; zeroed $($rest:ident)*) => {
        $(#[cfg($cfg)])?
        impl<'a> $name<'a> {
            /// A struct with every member zero or empty (and `sType` set, where it
            /// has one).
            #[inline]
            pub fn new() -> Self {
                Self { raw: Default::default(), _marker: core::marker::PhantomData }
            }
        }
        $(#[cfg($cfg)])?
        impl Default for $name<'_> {
            fn default() -> Self {
                Self::new()
            }
        }
        $crate::support::safe_struct!(@parts [$($cfg)?] $name [$($lt)?]; $($rest)*);
    };
    (@parts [$($cfg:meta)?] $name:ident [$($lt:lifetime)?]; chained $($rest:ident)*) => {
        $(#[cfg($cfg)])?
        impl<'a> $name<'a> {
            /// Pushes a struct that extends this one onto its `pNext` chain; only
            /// structs that the registry says extend this one are accepted.
            ///
            /// `next` becomes one node of this chain: whatever `next` chained before
            /// is no longer on it, and `next` stays borrowed, for as long as this
            /// struct's own borrows, so it cannot be used again with this chain's
            /// pointer in it.
            #[inline]
            pub fn push_next<T: $crate::chain::Extends<Self>>(mut self, next: &'a mut T) -> Self {
                // SAFETY: `Extends` is implemented only for structs that begin with
                // `sType` and `pNext` (the VkBaseOutStructure layout), as this one
                // does, and only for `T` of this struct's lifetime; `next` is
                // borrowed for that lifetime, so the chain it now points into
                // outlives every use of it.
                unsafe {
                    let node = next as *mut T as *mut ash::vk::BaseOutStructure<'a>;
                    (*node).p_next = self.raw.p_next as *mut _;
                    self.raw.p_next = node as _;
                }
                self
            }
        }
        $crate::support::safe_struct!(@parts [$($cfg)?] $name [$($lt)?]; $($rest)*);
    };
}
pub(crate) use safe_struct;

/// A Vulkan two-call enumeration: the count first, then that many items, and again
/// from the start when the implementation answers `VK_INCOMPLETE` (the list grew
/// between the calls). Commands that return nothing answer `SUCCESS` through `call`.
///
/// # Safety
///
/// `call(count, items)` calls one enumeration command with these two out-parameters
/// and every other argument valid: with `items` null it writes only `*count`;
/// otherwise it writes at most `*count` items to `items`, and sets `*count` to how
/// many it wrote.
pub(crate) unsafe fn two_call<T: Default, C: Copy + Default + TryFrom<usize> + TryInto<usize>>(
    mut call: impl FnMut(&mut C, *mut T) -> vk::Result,
) -> Result<Vec<T>> {
    let ok = |r: vk::Result| r == vk::Result::SUCCESS || r == vk::Result::INCOMPLETE;
    loop {
        let mut count = C::default();
        let r = call(&mut count, core::ptr::null_mut());
        if !ok(r) {
            return Err(Error::Vk(r));
        }
        let n: usize = count.try_into().unwrap_or(0);
        let mut items: Vec<T> = Vec::with_capacity(n);
        items.resize_with(n, T::default);
        let r = call(&mut count, items.as_mut_ptr());
        if !ok(r) {
            return Err(Error::Vk(r));
        }
        if r == vk::Result::INCOMPLETE {
            continue;
        }
        // The command wrote `count` items, no more than the `n` it was given.
        items.truncate(count.try_into().unwrap_or(0));
        return Ok(items);
    }
}

/// [`two_call`] for two arrays of one count that the same calls fill (a performance
/// query's counters and their descriptions).
///
/// # Safety
///
/// As for [`two_call`], for both arrays.
// Only an extension's commands use it, so a build without them has none.
#[allow(dead_code)]
pub(crate) unsafe fn two_call_pair<
    A: Default,
    B: Default,
    C: Copy + Default + TryFrom<usize> + TryInto<usize>,
>(
    mut call: impl FnMut(&mut C, *mut A, *mut B) -> vk::Result,
) -> Result<(Vec<A>, Vec<B>)> {
    let ok = |r: vk::Result| r == vk::Result::SUCCESS || r == vk::Result::INCOMPLETE;
    loop {
        let mut count = C::default();
        let r = call(&mut count, core::ptr::null_mut(), core::ptr::null_mut());
        if !ok(r) {
            return Err(Error::Vk(r));
        }
        let n: usize = count.try_into().unwrap_or(0);
        let mut a: Vec<A> = Vec::with_capacity(n);
        a.resize_with(n, A::default);
        let mut b: Vec<B> = Vec::with_capacity(n);
        b.resize_with(n, B::default);
        let r = call(&mut count, a.as_mut_ptr(), b.as_mut_ptr());
        if !ok(r) {
            return Err(Error::Vk(r));
        }
        if r == vk::Result::INCOMPLETE {
            continue;
        }
        // The command wrote `count` of each, no more than the `n` it was given.
        let written = count.try_into().unwrap_or(0);
        a.truncate(written);
        b.truncate(written);
        return Ok((a, b));
    }
}

/// What every wrapper of a child object (created from a device or an instance, or
/// allocated from a pool) has besides its construction and parent, written once:
/// the accessors of its shared state, [`Handle`] and `Deref` to the raw handle. The
/// generated `handles` module invokes it after each such wrapper, as
/// `child_handle!(Buffer);`, with the wrapper's `#[cfg]` first where it has one.
macro_rules! child_handle {
    ($(#[cfg($cfg:meta)])? $name:ident) => {
        $(#[cfg($cfg)])?
        impl $name {
            /// The object's host synchronization: held by every call that the
            /// specification says must not use the object from two threads at once.
            #[inline]
            #[allow(dead_code)]
            pub(crate) fn host_sync(&self) -> &tuff_runtime::HostSync {
                &self.inner.sync
            }
            /// Another object this one keeps alive (a swapchain for its images).
            #[inline]
            #[allow(dead_code)]
            pub(crate) fn kept(&self) -> Option<&tuff_runtime::Retained> {
                self.inner.keep.as_ref()
            }
            /// The address of the shared state, which identifies the object.
            #[inline]
            pub fn address(&self) -> usize {
                tuff_runtime::Vrc::as_ptr(&self.inner) as usize
            }
            /// This wrapper as a type-erased reference that keeps it alive.
            #[inline]
            pub fn retained(&self) -> tuff_runtime::Retained {
                self.inner.clone()
            }
        }
        $(#[cfg($cfg)])?
        impl $crate::Handle for $name {
            type Raw = crate::vk::$name;
            #[inline]
            fn raw(&self) -> crate::vk::$name {
                self.inner.raw
            }
            #[inline]
            fn raw_ref(&self) -> &crate::vk::$name {
                &self.inner.raw
            }
        }
        $(#[cfg($cfg)])?
        impl core::ops::Deref for $name {
            type Target = crate::vk::$name;
            #[inline]
            fn deref(&self) -> &crate::vk::$name {
                &self.inner.raw
            }
        }
        $(#[cfg($cfg)])?
        impl core::fmt::Debug for $name {
            /// The type and the raw handle: `Buffer(0x5581e2a0)`.
            fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
                f.debug_tuple(stringify!($name)).field(&self.inner.raw).finish()
            }
        }
    };
}
pub(crate) use child_handle;

#[cfg(test)]
mod tests {
    use super::*;

    /// A command that reports `total` items, fills as many as it is given, and says
    /// `INCOMPLETE` when that is fewer; `grow` more appear after the first count.
    fn counters(total: u32, grow: u32) -> impl FnMut(&mut u32, *mut u32, *mut u64) -> vk::Result {
        let mut calls = 0;
        move |count: &mut u32, a: *mut u32, b: *mut u64| {
            calls += 1;
            let have = if calls > 1 { total + grow } else { total };
            if a.is_null() {
                *count = have;
                return vk::Result::SUCCESS;
            }
            let n = (*count).min(have);
            for i in 0..n {
                // SAFETY: the caller gave arrays of `*count` elements each.
                unsafe {
                    *a.add(i as usize) = i;
                    *b.add(i as usize) = u64::from(i) * 10;
                }
            }
            *count = n;
            match n < have {
                true => vk::Result::INCOMPLETE,
                false => vk::Result::SUCCESS,
            }
        }
    }

    #[test]
    fn two_arrays_of_one_count_come_back_together() {
        // SAFETY: `counters` writes no more than the count it is handed.
        let (a, b) = unsafe { two_call_pair(counters(3, 0)) }.expect("filled");
        assert_eq!(a, [0, 1, 2]);
        assert_eq!(b, [0, 10, 20]);
        // More items between the calls: `INCOMPLETE`, then a second round.
        // SAFETY: as above.
        let (a, b) = unsafe { two_call_pair(counters(2, 1)) }.expect("filled");
        assert_eq!((a.len(), b.len()), (3, 3));
    }
}
