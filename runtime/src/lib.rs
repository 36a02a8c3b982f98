//! `tuff-runtime`: what tuff's generated wrappers need at run time, and nothing more.
//!
//! - [`Vrc`] and [`Vutex`]: sharing and locking that cost no atomics unless the
//!   `multi_thread` feature asks for them.
//! - [`Allocator`]: device-memory allocation behind one trait, with a
//!   [`NaiveAllocator`] (one `vkAllocateMemory` per resource) and the default
//!   [`GpuAllocator`] (sub-allocation through `gpu-allocator`). See [`memory`] for how
//!   allocations keep their device alive.
//! - [`Allocation`]'s typed, checked access to mapped memory, with flushes and
//!   invalidations of non-coherent memory rounded to `nonCoherentAtomSize`.
//! - [`RUNTIME_IMPLICIT_VALIDATIONS`]: always true: the generated code runs its checks
//!   of implicit rules in every safe method.
//!
//! ```
//! use tuff_runtime::{Vrc, Vutex};
//! let shared = Vrc::new(Vutex::new(0u32));
//! *shared.lock() += 1;
//! assert_eq!(*shared.lock(), 1);
//! ```
#![warn(missing_docs)]

pub mod mapped;
pub mod memory;
pub mod sync;

pub use mapped::MapError;
pub use memory::{
    AllocError, Allocation, AllocationBacking, AllocationParts, AllocationRequest, Allocator,
    DeviceOwner, GpuAllocator, MemoryLocation, NaiveAllocator,
};
pub use sync::{
    count_hash, lock_all, HostSync, HostSyncGuard, MaybeSend, MaybeSendSync, Retain, Retained, Vrc,
    Vutex, VutexGuard, Vweak, MULTI_THREAD,
};
#[cfg(feature = "work_counts")]
pub use sync::{hashes_taken, locks_taken};

/// Always true: the generated code runs its checks of implicit rules in every safe
/// method, so that no build leaves a safe method without the checks its safety needs
/// (the `unsafe` `_unchecked` twins skip them). The `runtime_implicit_validations`
/// feature that used to switch them is kept, and changes nothing, so builds that name
/// it still work.
///
/// ```
/// assert!(tuff_runtime::RUNTIME_IMPLICIT_VALIDATIONS);
/// ```
pub const RUNTIME_IMPLICIT_VALIDATIONS: bool = true;
