//! Host memory the implementation allocates: `VkAllocationCallbacks` that allocate
//! through Rust's global allocator, count what is live, and let a policy refuse.
//!
//! Vulkan lets an application hand the implementation (the loader, the layers, the
//! driver) its own allocator. Raw callbacks are easy to get wrong (a pointer of the
//! wrong alignment, a block freed twice), so tuff does not take them: it owns the
//! allocator and the caller decides only which requests succeed. That is enough to
//! account for the host memory a driver keeps, to cap it, and to test a program's
//! handling of `ERROR_OUT_OF_HOST_MEMORY` by refusing on purpose.
//!
//! The callbacks go to `vkCreateInstance` and `vkCreateDevice` (and the matching
//! destroys, as VUID-vkDestroyInstance-instance-00630 and
//! VUID-vkDestroyDevice-device-00379 ask); objects of the device are created with
//! NULL, which leaves the choice to the implementation (Mesa's drivers then use the
//! device's allocator).

use ash::vk;
use core::ffi::c_void;
use std::alloc::Layout;
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::Arc;

/// One request the implementation makes of the host allocator, as its policy sees it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct HostRequest {
    /// Bytes asked for (for a reallocation, the new size).
    pub size: usize,
    /// Their alignment: a power of two.
    pub alignment: usize,
    /// How long the implementation says it will keep them.
    pub scope: vk::SystemAllocationScope,
    /// For a reallocation (a block it grows or shrinks), that block's size now;
    /// `None` for a new block.
    pub old_size: Option<usize>,
}

/// What a [`HostAllocator`] has done so far. Counts are of blocks and bytes the
/// implementation asked for, without the allocator's own header.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct HostStats {
    /// Blocks given and not yet freed.
    pub live_blocks: u64,
    /// Bytes in those blocks.
    pub live_bytes: u64,
    /// The most bytes live at once.
    pub peak_bytes: u64,
    /// Allocations and reallocations that got their block.
    pub granted: u64,
    /// Allocations and reallocations that got NULL: the policy refused, or no
    /// block of that size and alignment could be made.
    pub refused: u64,
}

/// The allocator [`crate::Entry::with_host_allocator`] hands to Vulkan: blocks from
/// Rust's global allocator, counted, each request first put to a policy.
///
/// ```no_run
/// use std::sync::atomic::{AtomicBool, Ordering};
/// use std::sync::Arc;
/// // Refuse every host allocation while `starve` is set.
/// let starve = Arc::new(AtomicBool::new(false));
/// let flag = starve.clone();
/// let host = tuff::HostAllocator::with_policy(move |_| !flag.load(Ordering::Relaxed));
/// let entry = tuff::Entry::load()?.with_host_allocator(host.clone());
/// // ... create the instance and device from `entry`; then:
/// println!("{} bytes live in the implementation", host.stats().live_bytes);
/// # Ok::<(), tuff::Error>(())
/// ```
#[derive(Clone)]
pub struct HostAllocator {
    inner: Arc<Inner>,
}

struct Inner {
    callbacks: vk::AllocationCallbacks<'static>,
    // Boxed so that the callbacks' user data, a pointer to it, stays put.
    state: Box<State>,
}

// SAFETY: `callbacks` holds function pointers and a pointer to `state`, which is
// `Send + Sync` (atomics and a `Send + Sync` policy) and lives as long as `Inner`.
unsafe impl Send for Inner {}
// SAFETY: as for `Send`; nothing in `Inner` is written after it is made.
unsafe impl Sync for Inner {}

type Policy = dyn Fn(&HostRequest) -> bool + Send + Sync;

struct State {
    policy: Box<Policy>,
    live_blocks: AtomicU64,
    live_bytes: AtomicU64,
    peak_bytes: AtomicU64,
    granted: AtomicU64,
    refused: AtomicU64,
}

impl core::fmt::Debug for HostAllocator {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.debug_struct("HostAllocator")
            .field("stats", &self.stats())
            .finish_non_exhaustive()
    }
}

impl Default for HostAllocator {
    fn default() -> Self {
        Self::new()
    }
}

impl HostAllocator {
    /// An allocator that grants every request and counts.
    pub fn new() -> Self {
        Self::with_policy(|_| true)
    }

    /// An allocator that grants a request when `policy` returns `true` and otherwise
    /// gives the implementation NULL, which it reports as
    /// `ERROR_OUT_OF_HOST_MEMORY`. The policy runs on whichever thread the
    /// implementation allocates from (a driver's own threads included), so it must be
    /// `Send + Sync`; a policy that panics refuses. It runs inside Vulkan calls,
    /// perhaps with the driver's locks held: it must not call Vulkan nor own a tuff
    /// object (an entry, instance or device it owned would keep itself alive).
    pub fn with_policy(policy: impl Fn(&HostRequest) -> bool + Send + Sync + 'static) -> Self {
        let state = Box::new(State {
            policy: Box::new(policy),
            live_blocks: AtomicU64::new(0),
            live_bytes: AtomicU64::new(0),
            peak_bytes: AtomicU64::new(0),
            granted: AtomicU64::new(0),
            refused: AtomicU64::new(0),
        });
        let callbacks = vk::AllocationCallbacks {
            p_user_data: (&*state as *const State).cast_mut().cast(),
            pfn_allocation: Some(allocation),
            pfn_reallocation: Some(reallocation),
            pfn_free: Some(free),
            pfn_internal_allocation: None,
            pfn_internal_free: None,
            _marker: core::marker::PhantomData,
        };
        HostAllocator {
            inner: Arc::new(Inner { callbacks, state }),
        }
    }

    /// What the allocator has done so far.
    pub fn stats(&self) -> HostStats {
        let s = &self.inner.state;
        HostStats {
            live_blocks: s.live_blocks.load(Ordering::Relaxed),
            live_bytes: s.live_bytes.load(Ordering::Relaxed),
            peak_bytes: s.peak_bytes.load(Ordering::Relaxed),
            granted: s.granted.load(Ordering::Relaxed),
            refused: s.refused.load(Ordering::Relaxed),
        }
    }

    /// The callbacks, valid while this allocator (or a clone) lives.
    pub(crate) fn callbacks(&self) -> *const vk::AllocationCallbacks<'static> {
        &self.inner.callbacks
    }
}

/// The callbacks a create or destroy of an instance or device passes: those of the
/// entry's host allocator, or NULL. Instances and devices hold their entry, so the
/// pointer outlives what was created with it.
pub(crate) trait HostCallbacks {
    fn host_callbacks(&self) -> *const vk::AllocationCallbacks<'static>;
}

impl HostCallbacks for crate::Entry {
    fn host_callbacks(&self) -> *const vk::AllocationCallbacks<'static> {
        self.host_allocator()
            .map_or(core::ptr::null(), HostAllocator::callbacks)
    }
}

impl HostCallbacks for crate::Instance {
    fn host_callbacks(&self) -> *const vk::AllocationCallbacks<'static> {
        self.entry().host_callbacks()
    }
}

impl HostCallbacks for crate::PhysicalDevice {
    fn host_callbacks(&self) -> *const vk::AllocationCallbacks<'static> {
        self.parent().host_callbacks()
    }
}

/// Each block carries its size and alignment in a header just before the pointer
/// the implementation sees, so that a reallocation and a free (which are given only
/// the pointer) can rebuild its layout. The header takes `offset` bytes, at least
/// the header's own size and a multiple of the alignment, so the pointer stays
/// aligned.
const HEADER: usize = 2 * core::mem::size_of::<usize>();

fn offset(alignment: usize) -> usize {
    alignment.max(HEADER)
}

fn block_layout(size: usize, alignment: usize) -> Option<Layout> {
    if !alignment.is_power_of_two() {
        return None;
    }
    let off = offset(alignment);
    Layout::from_size_align(size.checked_add(off)?, off).ok()
}

impl State {
    /// Whether the policy grants `request`; a refusal is counted here, a grant
    /// when its block is made ([`Self::take`]).
    fn ask(&self, request: &HostRequest) -> bool {
        let policy = &self.policy;
        // A panic must not unwind into the implementation's C frames.
        let yes = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| policy(request)))
            .unwrap_or(false);
        if !yes {
            self.refused.fetch_add(1, Ordering::Relaxed);
        }
        yes
    }

    /// A block of `size` bytes at `alignment`, counted as granted; null, counted
    /// as refused, when the layout is impossible or the global allocator has none.
    fn take(&self, size: usize, alignment: usize) -> *mut c_void {
        // SAFETY: the layout's size is at least `HEADER`, never zero.
        let base = block_layout(size, alignment).map_or(core::ptr::null_mut(), |layout| unsafe {
            std::alloc::alloc(layout)
        });
        if base.is_null() {
            self.refused.fetch_add(1, Ordering::Relaxed);
            return core::ptr::null_mut();
        }
        self.granted.fetch_add(1, Ordering::Relaxed);
        let off = offset(alignment);
        // SAFETY: `off <= layout.size()`, so the pointer stays inside the block; the
        // header's two words lie in `[off - HEADER, off)`, inside it too, and are
        // aligned because `off` and `HEADER` are multiples of a word.
        let user = unsafe {
            let user = base.add(off);
            let header = user.sub(HEADER).cast::<usize>();
            header.write(size);
            header.add(1).write(alignment);
            user
        };
        self.live_blocks.fetch_add(1, Ordering::Relaxed);
        let live = self.live_bytes.fetch_add(size as u64, Ordering::Relaxed) + size as u64;
        self.peak_bytes.fetch_max(live, Ordering::Relaxed);
        user.cast()
    }

    /// The size and alignment of a block [`Self::take`] gave.
    ///
    /// # Safety
    ///
    /// `user` came from `take` and was not given back.
    unsafe fn header(user: *mut c_void) -> (usize, usize) {
        // SAFETY: `take` wrote both words just before `user` (the caller's promise).
        unsafe {
            let header = user.cast::<u8>().sub(HEADER).cast::<usize>();
            (header.read(), header.add(1).read())
        }
    }

    /// Gives back a block [`Self::take`] gave.
    ///
    /// # Safety
    ///
    /// `user` came from `take` and was not given back.
    unsafe fn give_back(&self, user: *mut c_void) {
        // SAFETY: the caller's promise.
        let (size, alignment) = unsafe { Self::header(user) };
        let layout = block_layout(size, alignment).expect("the layout `take` used");
        // SAFETY: the block began `offset(alignment)` bytes before `user` and was
        // allocated with this layout.
        unsafe { std::alloc::dealloc(user.cast::<u8>().sub(offset(alignment)), layout) };
        self.live_blocks.fetch_sub(1, Ordering::Relaxed);
        self.live_bytes.fetch_sub(size as u64, Ordering::Relaxed);
    }
}

/// # Safety
///
/// `user_data` is the `State` of a live `HostAllocator` (Vulkan hands back the
/// pointer the callbacks were given).
unsafe fn state<'a>(user_data: *mut c_void) -> &'a State {
    // SAFETY: the caller's promise.
    unsafe { &*user_data.cast::<State>() }
}

unsafe extern "system" fn allocation(
    user_data: *mut c_void,
    size: usize,
    alignment: usize,
    scope: vk::SystemAllocationScope,
) -> *mut c_void {
    // SAFETY: Vulkan passes back the user data of callbacks that are live while
    // anything created with them is (HostCallbacks).
    let state = unsafe { state(user_data) };
    let request = HostRequest {
        size,
        alignment,
        scope,
        old_size: None,
    };
    if !state.ask(&request) {
        return core::ptr::null_mut();
    }
    state.take(size, alignment)
}

unsafe extern "system" fn reallocation(
    user_data: *mut c_void,
    original: *mut c_void,
    size: usize,
    alignment: usize,
    scope: vk::SystemAllocationScope,
) -> *mut c_void {
    // SAFETY: as in `allocation`.
    let state = unsafe { state(user_data) };
    // The specification's cases: zero size is a free (of nothing, for NULL: no
    // block is made that no one would free), NULL an allocation.
    if size == 0 {
        if !original.is_null() {
            // SAFETY: `original` is a live block of this allocator
            // (PFN_vkReallocationFunction).
            unsafe { state.give_back(original) };
        }
        return core::ptr::null_mut();
    }
    if original.is_null() {
        // SAFETY: the arguments Vulkan gave.
        return unsafe { allocation(user_data, size, alignment, scope) };
    }
    // SAFETY: `original` is a live block of this allocator.
    let (old_size, _) = unsafe { State::header(original) };
    let request = HostRequest {
        size,
        alignment,
        scope,
        old_size: Some(old_size),
    };
    if !state.ask(&request) {
        // Refused: the original block stays as it was, as the specification asks.
        return core::ptr::null_mut();
    }
    let moved = state.take(size, alignment);
    if moved.is_null() {
        return moved;
    }
    // SAFETY: `original` is a live block of this allocator; the two blocks are
    // distinct and each holds at least the bytes copied.
    unsafe {
        core::ptr::copy_nonoverlapping(
            original.cast::<u8>(),
            moved.cast::<u8>(),
            old_size.min(size),
        );
        state.give_back(original);
    }
    moved
}

unsafe extern "system" fn free(user_data: *mut c_void, memory: *mut c_void) {
    if memory.is_null() {
        return;
    }
    // SAFETY: as in `allocation`; `memory` is a live block of this allocator
    // (PFN_vkFreeFunction).
    unsafe { state(user_data).give_back(memory) };
}

#[cfg(test)]
mod tests {
    use super::*;

    fn call_alloc(h: &HostAllocator, size: usize, alignment: usize) -> *mut c_void {
        let c = h.inner.callbacks;
        // SAFETY: the allocator's own callbacks and user data.
        unsafe {
            (c.pfn_allocation.unwrap())(
                c.p_user_data,
                size,
                alignment,
                vk::SystemAllocationScope::OBJECT,
            )
        }
    }

    #[test]
    fn blocks_are_aligned_counted_moved_and_freed() {
        let h = HostAllocator::new();
        let c = h.inner.callbacks;
        for alignment in [1, 8, 16, 64, 4096] {
            let p = call_alloc(&h, 100, alignment);
            assert!(!p.is_null());
            assert_eq!(p as usize % alignment, 0);
            // SAFETY: 100 bytes of a live block.
            unsafe { core::ptr::write_bytes(p.cast::<u8>(), 7, 100) };
            // SAFETY: a live block of this allocator.
            let q = unsafe {
                (c.pfn_reallocation.unwrap())(
                    c.p_user_data,
                    p,
                    1000,
                    alignment,
                    vk::SystemAllocationScope::OBJECT,
                )
            };
            assert_eq!(q as usize % alignment, 0);
            // SAFETY: the first 100 bytes were copied over.
            assert!(unsafe { core::slice::from_raw_parts(q.cast::<u8>(), 100) }
                .iter()
                .all(|&b| b == 7));
            assert_eq!(h.stats().live_bytes, 1000);
            // SAFETY: a live block of this allocator.
            unsafe { (c.pfn_free.unwrap())(c.p_user_data, q) };
            assert_eq!(h.stats().live_blocks, 0);
        }
        // A move holds both blocks for a moment.
        assert_eq!(h.stats().peak_bytes, 1100);
        // An alignment that is no power of two gets NULL, not a misaligned block.
        assert!(call_alloc(&h, 8, 3).is_null());
    }

    #[test]
    fn a_refusal_keeps_the_original_block() {
        let h = HostAllocator::with_policy(|r| r.old_size.is_none());
        let c = h.inner.callbacks;
        let p = call_alloc(&h, 16, 8);
        // SAFETY: a live block of this allocator.
        let q = unsafe {
            (c.pfn_reallocation.unwrap())(
                c.p_user_data,
                p,
                64,
                8,
                vk::SystemAllocationScope::OBJECT,
            )
        };
        assert!(q.is_null());
        assert_eq!(h.stats().live_blocks, 1);
        assert_eq!(h.stats().refused, 1);
        // SAFETY: still live.
        unsafe { (c.pfn_free.unwrap())(c.p_user_data, p) };
        assert_eq!(h.stats().live_bytes, 0);
        // Reallocating nothing to nothing makes no block.
        // SAFETY: NULL is a valid original.
        let none = unsafe {
            (c.pfn_reallocation.unwrap())(
                c.p_user_data,
                core::ptr::null_mut(),
                0,
                8,
                vk::SystemAllocationScope::OBJECT,
            )
        };
        assert!(none.is_null());
        assert_eq!(h.stats().live_blocks, 0);
        let panicky = HostAllocator::with_policy(|_| panic!("no"));
        assert!(call_alloc(&panicky, 16, 8).is_null());
    }
}
