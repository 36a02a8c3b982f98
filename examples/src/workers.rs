//! Worker threads for the deferred scene: one job per worker, each on a thread of
//! its own, joined before the frame goes on.
//!
//! tuff's wrappers cross threads only with its `multi_thread` feature (the crate
//! docs, "Threads"), which this crate's `multi_thread` feature turns on; without it
//! [`tuff_workers`] runs the same jobs one after another on the calling thread, in
//! the same order, so the image is the same. The raw-ash twin's handles cross
//! threads either way ([`on_threads`]).

/// Runs `job(i, item)` for each of `items`, each on a scoped thread of its own (on
/// the calling thread when there is only one), and returns the first error.
///
/// # Panics
///
/// When a job panics.
pub fn on_threads<T: Send, E: Send>(
    items: Vec<T>,
    job: impl Fn(usize, T) -> Result<(), E> + Sync,
) -> Result<(), E> {
    if items.len() <= 1 {
        return in_order(items, job);
    }
    let job = &job;
    std::thread::scope(|scope| {
        let handles: Vec<_> = items
            .into_iter()
            .enumerate()
            .map(|(i, t)| scope.spawn(move || job(i, t)))
            .collect();
        handles
            .into_iter()
            .try_for_each(|h| h.join().expect("a worker thread panicked"))
    })
}

/// Runs `job(i, item)` for each of `items` in order on the calling thread, and
/// returns the first error.
pub fn in_order<T, E>(items: Vec<T>, job: impl Fn(usize, T) -> Result<(), E>) -> Result<(), E> {
    items
        .into_iter()
        .enumerate()
        .try_for_each(|(i, t)| job(i, t))
}

/// How the tuff scene runs its workers: on threads with `multi_thread`.
#[cfg(feature = "multi_thread")]
pub use on_threads as tuff_workers;

/// How the tuff scene runs its workers: in order without `multi_thread`, where
/// tuff's wrappers cannot cross threads.
#[cfg(not(feature = "multi_thread"))]
pub use in_order as tuff_workers;

/// Whether the tuff scene's workers run on threads of their own.
pub const TUFF_THREADS: bool = cfg!(feature = "multi_thread");
