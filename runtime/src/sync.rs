//! Sharing and locking with one API in both threading modes.
//!
//! Without the `multi_thread` feature, [`Vrc`] is [`std::rc::Rc`] and [`Vutex`] a cell
//! with a borrow flag: neither is `Send` nor `Sync`, and single-threaded code pays for
//! no atomics. With it, [`Vrc`] is [`std::sync::Arc`] and [`Vutex`] a
//! `parking_lot::Mutex`: a `Vutex` is `Send + Sync` for `Send` contents, a `Vrc` for
//! `Send + Sync` contents.

/// The reference-counted pointer the wrappers share parents with: `Rc`, or `Arc` with
/// the `multi_thread` feature.
///
/// ```
/// let device = tuff_runtime::Vrc::new(42);
/// let child_keeps_parent = tuff_runtime::Vrc::clone(&device);
/// assert_eq!(*child_keeps_parent, 42);
/// ```
#[cfg(not(feature = "multi_thread"))]
pub type Vrc<T> = std::rc::Rc<T>;

/// The reference-counted pointer the wrappers share parents with: `Rc`, or `Arc` with
/// the `multi_thread` feature.
///
/// ```
/// let device = tuff_runtime::Vrc::new(42);
/// let child_keeps_parent = tuff_runtime::Vrc::clone(&device);
/// assert_eq!(*child_keeps_parent, 42);
/// ```
#[cfg(feature = "multi_thread")]
pub type Vrc<T> = std::sync::Arc<T>;

/// Bound that is `Send + Sync` with the `multi_thread` feature and nothing without it,
/// so trait objects shared through [`Vrc`] can cross threads exactly when `Vrc` can.
///
/// ```
/// fn share<T: tuff_runtime::MaybeSendSync + ?Sized>(_: &tuff_runtime::Vrc<T>) {}
/// share(&tuff_runtime::Vrc::new(5u8));
/// ```
#[cfg(feature = "multi_thread")]
pub trait MaybeSendSync: Send + Sync {}
#[cfg(feature = "multi_thread")]
impl<T: Send + Sync + ?Sized> MaybeSendSync for T {}

/// Bound that is `Send + Sync` with the `multi_thread` feature and nothing without it,
/// so trait objects shared through [`Vrc`] can cross threads exactly when `Vrc` can.
///
/// ```
/// fn share<T: tuff_runtime::MaybeSendSync + ?Sized>(_: &tuff_runtime::Vrc<T>) {}
/// share(&tuff_runtime::Vrc::new(5u8));
/// ```
#[cfg(not(feature = "multi_thread"))]
pub trait MaybeSendSync {}
#[cfg(not(feature = "multi_thread"))]
impl<T: ?Sized> MaybeSendSync for T {}

/// Bound that is `Send` with the `multi_thread` feature and nothing without it.
///
/// ```
/// fn hand_over<T: tuff_runtime::MaybeSend>(_: T) {}
/// hand_over(vec![1u32]);
/// ```
#[cfg(feature = "multi_thread")]
pub trait MaybeSend: Send {}
#[cfg(feature = "multi_thread")]
impl<T: Send + ?Sized> MaybeSend for T {}

/// Bound that is `Send` with the `multi_thread` feature and nothing without it.
///
/// ```
/// fn hand_over<T: tuff_runtime::MaybeSend>(_: T) {}
/// hand_over(vec![1u32]);
/// ```
#[cfg(not(feature = "multi_thread"))]
pub trait MaybeSend {}
#[cfg(not(feature = "multi_thread"))]
impl<T: ?Sized> MaybeSend for T {}

/// How many locks this thread has taken ([`Vutex`] and [`HostSync`], held or tried),
/// with the `work_counts` feature: tests assert that a path takes none (a count is
/// work, not time, so noise cannot fool them). Without the feature nothing counts.
///
/// ```
/// # #[cfg(feature = "work_counts")] {
/// let before = tuff_runtime::locks_taken();
/// drop(tuff_runtime::Vutex::new(0).lock());
/// assert_eq!(tuff_runtime::locks_taken(), before + 1);
/// # }
/// ```
#[cfg(feature = "work_counts")]
pub fn locks_taken() -> u64 {
    COUNTS.with(|c| c.get().0)
}

/// How many hashes this thread has computed through [`count_hash`] (tuff's record
/// tables count every lookup and insertion), with the `work_counts` feature.
///
/// ```
/// # #[cfg(feature = "work_counts")] {
/// let before = tuff_runtime::hashes_taken();
/// tuff_runtime::count_hash();
/// assert_eq!(tuff_runtime::hashes_taken(), before + 1);
/// # }
/// ```
#[cfg(feature = "work_counts")]
pub fn hashes_taken() -> u64 {
    COUNTS.with(|c| c.get().1)
}

#[cfg(feature = "work_counts")]
thread_local! {
    /// Locks and hashes taken by this thread.
    static COUNTS: core::cell::Cell<(u64, u64)> = const { core::cell::Cell::new((0, 0)) };
}

/// Counts one lock taken by this thread (with `work_counts`; nothing without).
#[inline(always)]
fn count_lock() {
    #[cfg(feature = "work_counts")]
    COUNTS.with(|c| {
        let (locks, hashes) = c.get();
        c.set((locks + 1, hashes));
    });
}

/// Counts one hash computed by this thread (with `work_counts`; nothing without):
/// tuff's hashers call it.
///
/// ```
/// tuff_runtime::count_hash();
/// ```
#[inline(always)]
pub fn count_hash() {
    #[cfg(feature = "work_counts")]
    COUNTS.with(|c| {
        let (locks, hashes) = c.get();
        c.set((locks, hashes + 1));
    });
}

/// A lock for externally synchronized Vulkan objects, with one API in both modes.
///
/// ```
/// let pool = tuff_runtime::Vutex::new(Vec::<u32>::new());
/// pool.lock().push(7);
/// assert_eq!(pool.lock().len(), 1);
/// ```
pub struct Vutex<T> {
    #[cfg(not(feature = "multi_thread"))]
    cell: std::cell::RefCell<T>,
    // Keeps the single-threaded lock off other threads even for `Send` contents.
    #[cfg(not(feature = "multi_thread"))]
    _not_send: std::marker::PhantomData<*const ()>,
    #[cfg(feature = "multi_thread")]
    mutex: parking_lot::Mutex<T>,
}

/// Exclusive access to the contents of a [`Vutex`], released when dropped.
///
/// ```
/// let v = tuff_runtime::Vutex::new(String::new());
/// let mut guard: tuff_runtime::VutexGuard<'_, String> = v.lock();
/// guard.push('x');
/// ```
#[cfg(not(feature = "multi_thread"))]
pub type VutexGuard<'a, T> = std::cell::RefMut<'a, T>;

/// Exclusive access to the contents of a [`Vutex`], released when dropped.
///
/// ```
/// let v = tuff_runtime::Vutex::new(String::new());
/// let mut guard: tuff_runtime::VutexGuard<'_, String> = v.lock();
/// guard.push('x');
/// ```
#[cfg(feature = "multi_thread")]
pub type VutexGuard<'a, T> = parking_lot::MutexGuard<'a, T>;

impl<T> Vutex<T> {
    /// Wrap `value`.
    ///
    /// ```
    /// let queue = tuff_runtime::Vutex::new("a queue");
    /// assert_eq!(*queue.lock(), "a queue");
    /// ```
    pub fn new(value: T) -> Self {
        Vutex {
            #[cfg(not(feature = "multi_thread"))]
            cell: std::cell::RefCell::new(value),
            #[cfg(not(feature = "multi_thread"))]
            _not_send: std::marker::PhantomData,
            #[cfg(feature = "multi_thread")]
            mutex: parking_lot::Mutex::new(value),
        }
    }

    /// Lock it.
    ///
    /// # Panics
    ///
    /// Without `multi_thread`, when the same thread already holds the lock: that is a
    /// bug that would deadlock with a real mutex.
    ///
    /// ```
    /// let count = tuff_runtime::Vutex::new(0);
    /// *count.lock() += 1;
    /// assert_eq!(*count.lock(), 1);
    /// ```
    pub fn lock(&self) -> VutexGuard<'_, T> {
        count_lock();
        #[cfg(not(feature = "multi_thread"))]
        {
            self.cell
                .try_borrow_mut()
                .expect("Vutex locked twice on one thread (this would deadlock with multi_thread)")
        }
        #[cfg(feature = "multi_thread")]
        {
            self.mutex.lock()
        }
    }

    /// Lock it if no one holds it now.
    ///
    /// ```
    /// let v = tuff_runtime::Vutex::new(1);
    /// let held = v.lock();
    /// assert!(v.try_lock().is_none());
    /// drop(held);
    /// assert!(v.try_lock().is_some());
    /// ```
    pub fn try_lock(&self) -> Option<VutexGuard<'_, T>> {
        count_lock();
        #[cfg(not(feature = "multi_thread"))]
        {
            self.cell.try_borrow_mut().ok()
        }
        #[cfg(feature = "multi_thread")]
        {
            self.mutex.try_lock()
        }
    }

    /// The contents, by unique access (no locking needed).
    ///
    /// ```
    /// let mut v = tuff_runtime::Vutex::new(1);
    /// *v.get_mut() = 2;
    /// assert_eq!(v.into_inner(), 2);
    /// ```
    pub fn get_mut(&mut self) -> &mut T {
        #[cfg(not(feature = "multi_thread"))]
        {
            self.cell.get_mut()
        }
        #[cfg(feature = "multi_thread")]
        {
            self.mutex.get_mut()
        }
    }

    /// Unwrap the contents.
    ///
    /// ```
    /// assert_eq!(tuff_runtime::Vutex::new(vec![1]).into_inner(), [1]);
    /// ```
    pub fn into_inner(self) -> T {
        #[cfg(not(feature = "multi_thread"))]
        {
            self.cell.into_inner()
        }
        #[cfg(feature = "multi_thread")]
        {
            self.mutex.into_inner()
        }
    }
}

impl<T: std::fmt::Debug> std::fmt::Debug for Vutex<T> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self.try_lock() {
            Some(v) => f.debug_tuple("Vutex").field(&*v).finish(),
            None => f.write_str("Vutex(<locked>)"),
        }
    }
}

/// A weak reference of a [`Vrc`]: `std::rc::Weak`, or `std::sync::Weak` with
/// `multi_thread`.
///
/// ```
/// let strong = tuff_runtime::Vrc::new(1);
/// let weak: tuff_runtime::sync::Vweak<i32> = tuff_runtime::Vrc::downgrade(&strong);
/// assert_eq!(weak.upgrade().map(|v| *v), Some(1));
/// ```
#[cfg(not(feature = "multi_thread"))]
pub type Vweak<T> = std::rc::Weak<T>;

/// A weak reference of a [`Vrc`]: `std::rc::Weak`, or `std::sync::Weak` with
/// `multi_thread`.
///
/// ```
/// let strong = tuff_runtime::Vrc::new(1);
/// let weak: tuff_runtime::sync::Vweak<i32> = tuff_runtime::Vrc::downgrade(&strong);
/// assert_eq!(weak.upgrade().map(|v| *v), Some(1));
/// ```
#[cfg(feature = "multi_thread")]
pub type Vweak<T> = std::sync::Weak<T>;

/// Anything a wrapper can keep alive on behalf of another: a handle wrapper's shared
/// state, an allocation, a closure's captures.
pub trait Retain: MaybeSendSync {}
impl<T: MaybeSendSync + ?Sized> Retain for T {}

/// A type-erased strong reference that keeps an object alive (a recorded command
/// buffer keeps what its commands use; a fence keeps what its submission uses).
///
/// ```
/// let kept: tuff_runtime::Retained = tuff_runtime::Vrc::new(vec![1u8, 2, 3]);
/// drop(kept);
/// ```
pub type Retained = Vrc<dyn Retain>;

/// Whether this build shares wrappers between threads (`multi_thread`).
///
/// ```
/// assert_eq!(tuff_runtime::MULTI_THREAD, cfg!(feature = "multi_thread"));
/// ```
pub const MULTI_THREAD: bool = cfg!(feature = "multi_thread");

/// The host synchronization of one Vulkan object: what the specification asks of a
/// parameter it marks externally synchronized (no two threads use the object in
/// such a call at once). With `multi_thread` it is a reentrant lock, so one thread
/// may hold it across nested calls (a recording holds its command pool's); without
/// it, nothing can reach the object from another thread and it is empty.
///
/// ```
/// let queue = tuff_runtime::HostSync::new();
/// let guard = queue.lock();
/// let again = queue.lock(); // the same thread may lock it again
/// drop((again, guard));
/// ```
#[derive(Clone, Default)]
pub struct HostSync {
    #[cfg(feature = "multi_thread")]
    lock: std::sync::Arc<parking_lot::ReentrantMutex<()>>,
}

impl core::fmt::Debug for HostSync {
    /// Whether it is a real lock in this build.
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.debug_struct("HostSync")
            .field("locks", &cfg!(feature = "multi_thread"))
            .finish()
    }
}

/// A held [`HostSync`]: released when dropped. It owns its share of the lock, so a
/// recorder can hold one for as long as it records.
#[must_use = "the object is synchronized only while the guard lives"]
pub struct HostSyncGuard {
    #[cfg(feature = "multi_thread")]
    _guard: parking_lot::lock_api::ArcReentrantMutexGuard<
        parking_lot::RawMutex,
        parking_lot::RawThreadId,
        (),
    >,
}

impl core::fmt::Debug for HostSyncGuard {
    /// A guard has nothing to show but that it is held.
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.debug_struct("HostSyncGuard").finish_non_exhaustive()
    }
}

impl HostSync {
    /// A new, unlocked synchronization.
    pub fn new() -> Self {
        Self::default()
    }

    /// Waits until no other thread holds the object, then holds it.
    #[inline]
    pub fn lock(&self) -> HostSyncGuard {
        count_lock();
        HostSyncGuard {
            #[cfg(feature = "multi_thread")]
            _guard: parking_lot::ReentrantMutex::lock_arc(&self.lock),
        }
    }

    /// Holds the object if no other thread does, without waiting.
    #[inline]
    pub fn try_lock(&self) -> Option<HostSyncGuard> {
        count_lock();
        #[cfg(feature = "multi_thread")]
        {
            parking_lot::ReentrantMutex::try_lock_arc(&self.lock)
                .map(|g| HostSyncGuard { _guard: g })
        }
        #[cfg(not(feature = "multi_thread"))]
        {
            Some(HostSyncGuard {})
        }
    }

    /// Identifies the lock, so several are always taken in one order.
    #[cfg(feature = "multi_thread")]
    fn key(&self) -> usize {
        std::sync::Arc::as_ptr(&self.lock) as usize
    }
}

/// Holds every object of one call, each once, in one order for all threads (by
/// address), so two calls that share objects cannot each wait for the other.
///
/// ```
/// let (a, b) = (tuff_runtime::HostSync::new(), tuff_runtime::HostSync::new());
/// let held = tuff_runtime::lock_all(vec![b.clone(), a.clone(), b.clone()]);
/// drop(held);
/// ```
#[allow(unused_mut)]
pub fn lock_all(mut syncs: Vec<HostSync>) -> Vec<HostSyncGuard> {
    #[cfg(feature = "multi_thread")]
    {
        syncs.sort_by_key(HostSync::key);
        syncs.dedup_by_key(|s| s.key());
        syncs.iter().map(HostSync::lock).collect()
    }
    #[cfg(not(feature = "multi_thread"))]
    {
        drop(syncs);
        Vec::new()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[cfg(feature = "multi_thread")]
    #[test]
    fn host_syncs_exclude_other_threads_and_never_deadlock() {
        use std::sync::atomic::{AtomicUsize, Ordering};
        let (a, b) = (HostSync::new(), HostSync::new());
        let inside = AtomicUsize::new(0);
        std::thread::scope(|scope| {
            for flip in [false, true] {
                let (a, b, inside) = (a.clone(), b.clone(), &inside);
                scope.spawn(move || {
                    for _ in 0..10_000 {
                        // Opposite orders on the two threads: lock_all sorts them.
                        let order = if flip {
                            vec![b.clone(), a.clone()]
                        } else {
                            vec![a.clone(), b.clone()]
                        };
                        let held = lock_all(order);
                        assert_eq!(
                            inside.fetch_add(1, Ordering::SeqCst),
                            0,
                            "two threads inside"
                        );
                        // Reentrant: the holder may lock again.
                        drop(a.lock());
                        inside.fetch_sub(1, Ordering::SeqCst);
                        drop(held);
                    }
                });
            }
        });
        let held = a.lock();
        let other =
            std::thread::scope(|scope| scope.spawn(|| a.try_lock().is_none()).join().unwrap());
        assert!(other, "another thread got a held lock");
        drop(held);
    }

    #[test]
    fn try_lock_fails_while_locked() {
        let v = Vutex::new(1);
        let guard = v.lock();
        assert!(v.try_lock().is_none());
        drop(guard);
        assert_eq!(*v.try_lock().unwrap(), 1);
    }

    #[cfg(not(feature = "multi_thread"))]
    mod single_thread {
        use super::super::*;
        static_assertions::assert_not_impl_any!(Vutex<u32>: Send, Sync);
        static_assertions::assert_not_impl_any!(Vrc<u32>: Send, Sync);
    }

    #[cfg(feature = "multi_thread")]
    mod multi_thread {
        use super::super::*;
        static_assertions::assert_impl_all!(Vutex<u32>: Send, Sync);
        static_assertions::assert_impl_all!(Vrc<Vutex<u32>>: Send, Sync);
        static_assertions::assert_not_impl_any!(Vutex<std::rc::Rc<u32>>: Send, Sync);
    }
}
