//! Memory: buffers and images bound to memory from an allocator, and host access to
//! mapped memory.

pub(crate) mod allocation;
pub(crate) mod host;
pub(crate) mod indirect;
pub(crate) mod mapping;
