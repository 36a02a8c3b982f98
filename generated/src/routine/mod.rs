//! Routine work in one call each: setup (submit and wait, layout transitions,
//! uploads), frames in flight, one-object forms of array commands, and choosing a
//! physical device and queue family.

pub(crate) mod frames;
mod physical;
mod setup;
mod single;
