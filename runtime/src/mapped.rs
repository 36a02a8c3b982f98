//! Range arithmetic for mapped memory: every offset and size is checked, and flush and
//! invalidate ranges of non-coherent memory are rounded out to `nonCoherentAtomSize`
//! without ever leaving the device memory that backs the allocation.

/// Why a mapped-memory access was refused.
///
/// ```
/// use tuff_runtime::mapped::{check_range, MapError};
/// let err = check_range(64, 60, 8).unwrap_err();
/// assert_eq!(err, MapError::OutOfRange { offset: 60, size: 8, allocation_size: 64 });
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum MapError {
    /// The allocation is not host-visible, so it has no mapping.
    NotMapped,
    /// The access does not fit in the allocation.
    OutOfRange {
        /// Offset of the access inside the allocation.
        offset: u64,
        /// Bytes accessed.
        size: u64,
        /// Size of the allocation.
        allocation_size: u64,
    },
    /// An offset or size computation overflowed.
    Overflow {
        /// Offset of the access.
        offset: u64,
        /// Bytes accessed.
        size: u64,
    },
    /// `nonCoherentAtomSize` is not a power of two (the specification requires one).
    BadAtomSize(u64),
    /// The allocation does not lie inside its device memory.
    BadAllocation {
        /// Allocation offset inside the device memory.
        offset: u64,
        /// Allocation size.
        size: u64,
        /// Size of the device memory.
        memory_size: u64,
    },
    /// vkFlushMappedMemoryRanges or vkInvalidateMappedMemoryRanges failed.
    Vulkan(ash::vk::Result),
}

// Written out rather than derived: thiserror's macro needs a syn of its own, which
// cargo builds before ash and so delays every build of tuff.
impl core::fmt::Display for MapError {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self {
            MapError::NotMapped => {
                f.write_str("the allocation is not mapped (its memory is not host-visible)")
            }
            MapError::OutOfRange {
                offset,
                size,
                allocation_size,
            } => write!(
                f,
                "{size} bytes at offset {offset} do not fit in an allocation of {allocation_size} bytes"
            ),
            MapError::Overflow { offset, size } => {
                write!(f, "offset {offset} plus size {size} overflows")
            }
            MapError::BadAtomSize(n) => write!(f, "nonCoherentAtomSize {n} is not a power of two"),
            MapError::BadAllocation {
                offset,
                size,
                memory_size,
            } => write!(
                f,
                "allocation at {offset} of {size} bytes lies outside its device memory of {memory_size} bytes"
            ),
            MapError::Vulkan(r) => {
                write!(f, "flushing or invalidating mapped memory failed: {r}")
            }
        }
    }
}

impl std::error::Error for MapError {}

/// Where an allocation lies inside its device memory.
///
/// ```
/// let p = tuff_runtime::mapped::Placement { offset: 4096, size: 256, memory_size: 1 << 20 };
/// assert_eq!(tuff_runtime::mapped::flush_range(p, 64, 0, 256), Ok(Some((4096, 256))));
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Placement {
    /// Offset of the allocation inside the device memory.
    pub offset: u64,
    /// Size of the allocation.
    pub size: u64,
    /// Size of the whole `VkDeviceMemory` object.
    pub memory_size: u64,
}

/// Check that `size` bytes at `offset` fit in an allocation of `allocation_size`
/// bytes, returning the end offset.
///
/// ```
/// use tuff_runtime::mapped::{check_range, MapError};
/// assert_eq!(check_range(256, 192, 64), Ok(256));
/// assert!(matches!(check_range(256, 193, 64), Err(MapError::OutOfRange { .. })));
/// assert!(matches!(check_range(256, u64::MAX, 2), Err(MapError::Overflow { .. })));
/// ```
#[inline]
pub fn check_range(allocation_size: u64, offset: u64, size: u64) -> Result<u64, MapError> {
    let end = offset
        .checked_add(size)
        .ok_or(MapError::Overflow { offset, size })?;
    if end > allocation_size {
        return Err(MapError::OutOfRange {
            offset,
            size,
            allocation_size,
        });
    }
    Ok(end)
}

/// The range of the device memory, as `(offset, size)` for a `VkMappedMemoryRange`,
/// to flush or invalidate so that `size` bytes at `offset` inside the allocation are
/// covered. The range is rounded out to `atom` and clamped to the device memory; where
/// the clamp cuts it, it ends exactly at the end of the memory, which the
/// specification allows. `None` when there is nothing to do (`size` is 0).
///
/// ```
/// use tuff_runtime::mapped::{flush_range, Placement};
/// let at = Placement { offset: 100, size: 1000, memory_size: 4096 };
/// // Bytes 110..120 of the memory lie in the atom 64..128.
/// assert_eq!(flush_range(at, 64, 10, 10), Ok(Some((64, 64))));
/// ```
pub fn flush_range(
    placement: Placement,
    atom: u64,
    offset: u64,
    size: u64,
) -> Result<Option<(u64, u64)>, MapError> {
    if atom == 0 || !atom.is_power_of_two() {
        return Err(MapError::BadAtomSize(atom));
    }
    let Placement {
        offset: base,
        size: allocation_size,
        memory_size,
    } = placement;
    base.checked_add(allocation_size)
        .filter(|end| *end <= memory_size)
        .ok_or(MapError::BadAllocation {
            offset: base,
            size: allocation_size,
            memory_size,
        })?;
    let end = check_range(allocation_size, offset, size)?;
    if size == 0 {
        return Ok(None);
    }
    // Both sums are at most allocation_end <= memory_size, so they cannot overflow.
    let start = base + offset;
    let stop = base + end;
    let rounded_start = start & !(atom - 1);
    let rounded_stop = match stop.checked_next_multiple_of(atom) {
        Some(s) if s <= memory_size => s,
        _ => memory_size,
    };
    Ok(Some((rounded_start, rounded_stop - rounded_start)))
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    fn at(offset: u64, size: u64, memory_size: u64) -> Placement {
        Placement {
            offset,
            size,
            memory_size,
        }
    }

    #[test]
    fn zero_sized_writes_flush_nothing() {
        assert_eq!(flush_range(at(0, 64, 64), 64, 64, 0), Ok(None));
        assert_eq!(check_range(64, 64, 0), Ok(64));
        assert!(check_range(64, 65, 0).is_err());
    }

    #[test]
    fn writes_ending_at_the_end_and_one_past_it() {
        assert_eq!(check_range(256, 255, 1), Ok(256));
        assert!(matches!(
            check_range(256, 256, 1),
            Err(MapError::OutOfRange { .. })
        ));
    }

    #[test]
    fn offsets_near_u64_max_overflow_cleanly() {
        assert!(matches!(
            check_range(u64::MAX, u64::MAX, 1),
            Err(MapError::Overflow { .. })
        ));
        assert!(matches!(
            check_range(u64::MAX, 1, u64::MAX),
            Err(MapError::Overflow { .. })
        ));
        // VK_WHOLE_SIZE is u64::MAX: it is a size no allocation can hold.
        assert!(check_range(1 << 20, 0, ash::vk::WHOLE_SIZE).is_err());
        assert!(flush_range(at(u64::MAX - 10, 10, u64::MAX), 256, 0, 10).is_ok());
        assert!(flush_range(at(u64::MAX - 10, 20, u64::MAX), 256, 0, 10).is_err());
    }

    #[test]
    fn unaligned_allocation_offsets_round_out_but_stay_in_memory() {
        // Allocation at 100 inside a 1000-byte memory whose end is not atom-aligned.
        let p = at(100, 900, 1000);
        assert_eq!(flush_range(p, 256, 0, 1), Ok(Some((0, 256))));
        assert_eq!(flush_range(p, 256, 899, 1), Ok(Some((768, 232))));
        assert_eq!(flush_range(p, 1, 5, 3), Ok(Some((105, 3))));
    }

    #[test]
    fn bad_atoms_and_placements_are_errors() {
        assert_eq!(
            flush_range(at(0, 64, 64), 0, 0, 1),
            Err(MapError::BadAtomSize(0))
        );
        assert_eq!(
            flush_range(at(0, 64, 64), 48, 0, 1),
            Err(MapError::BadAtomSize(48))
        );
        assert!(matches!(
            flush_range(at(32, 64, 64), 64, 0, 1),
            Err(MapError::BadAllocation { .. })
        ));
    }

    proptest! {
        #[test]
        fn flush_ranges_cover_the_write_and_stay_in_memory(
            atom_shift in prop::sample::select(vec![0u32, 6, 8]),
            memory_size in 1u64..=1 << 40,
            base_frac in 0.0f64..1.0,
            size_frac in 0.0f64..1.0,
            off_frac in 0.0f64..1.0,
            len_frac in 0.0f64..1.0,
        ) {
            let atom = 1u64 << atom_shift;
            let base = (memory_size as f64 * base_frac) as u64 % memory_size;
            let allocation_size = ((memory_size - base) as f64 * size_frac) as u64;
            let offset = (allocation_size as f64 * off_frac) as u64;
            let len = ((allocation_size - offset) as f64 * len_frac) as u64;
            let p = at(base, allocation_size, memory_size);
            match flush_range(p, atom, offset, len).unwrap() {
                None => prop_assert_eq!(len, 0),
                Some((start, size)) => {
                    let end = start + size;
                    prop_assert!(end <= memory_size, "inside the memory");
                    prop_assert!(start <= base + offset && end >= base + offset + len, "covers the write");
                    prop_assert_eq!(start % atom, 0);
                    prop_assert!(size % atom == 0 || end == memory_size, "valid VkMappedMemoryRange size");
                    prop_assert!(size < len + 2 * atom, "rounds out by less than an atom each side");
                }
            }
        }

        #[test]
        fn check_range_never_wraps(size in any::<u64>(), offset in any::<u64>(), len in any::<u64>()) {
            match check_range(size, offset, len) {
                Ok(end) => {
                    prop_assert_eq!(Some(end), offset.checked_add(len));
                    prop_assert!(end <= size);
                }
                Err(MapError::Overflow { .. }) => prop_assert!(offset.checked_add(len).is_none()),
                Err(MapError::OutOfRange { .. }) => prop_assert!(offset.checked_add(len).unwrap() > size),
                Err(e) => prop_assert!(false, "unexpected {e}"),
            }
        }
    }
}
