//! The stage benchmark: each frame of the teapots scene split into the stages a
//! frame loop goes through, timed on the host, for tuff and for raw ash, headless and
//! in a window, and for vulkano (headless; behind the `vulkano` feature), the peer.
//! `src/bin/stages.rs` runs the variants interleaved and writes the tables; this
//! module holds the frame loops' clock, the samples and their report.
//!
//! Stages, in frame order: **wait** (the fence of the frame slot's last submission),
//! **acquire** (the next swapchain image; windows only), **uniform** (the frame's
//! camera block written into mapped memory, and flushed where it is not coherent),
//! **command** (the frame's command buffer recorded), **submit**, and **present**
//! (`vkQueuePresentKHR` in a window; headless, the copy of the frame into a readback
//! buffer, recorded and submitted on its own). Wait and acquire measure the device
//! and the presentation engine rather than the API, so the stage table leaves them
//! out and reports them apart.

pub mod ash_frames;
pub mod report;
pub mod tuff_frames;
#[cfg(feature = "vulkano")]
pub mod vulkano_frames;

use anyhow::Context as _;
use std::time::{Duration, Instant};

/// A stage of a frame.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Stage {
    /// Waiting for the fence of the slot's last submission.
    Wait,
    /// Acquiring the swapchain image (windows only).
    Acquire,
    /// Writing the frame's uniform data.
    Uniform,
    /// Recording the frame's command buffer.
    Command,
    /// Submitting it.
    Submit,
    /// Presenting (window), or copying the frame into a readback buffer (headless).
    Present,
}

impl Stage {
    /// Every stage, in frame order.
    pub const ALL: [Stage; 6] = [
        Stage::Wait,
        Stage::Acquire,
        Stage::Uniform,
        Stage::Command,
        Stage::Submit,
        Stage::Present,
    ];
    /// The stages the API's cost shows in; wait and acquire are reported apart.
    pub const TABLE: [Stage; 4] = [
        Stage::Uniform,
        Stage::Command,
        Stage::Submit,
        Stage::Present,
    ];

    /// Its name in CSV headers and tables.
    pub fn name(self) -> &'static str {
        match self {
            Stage::Wait => "wait",
            Stage::Acquire => "acquire",
            Stage::Uniform => "uniform",
            Stage::Command => "command",
            Stage::Submit => "submit",
            Stage::Present => "present",
        }
    }

    /// The stage of a name, as [`Stage::name`] writes it.
    pub fn from_name(name: &str) -> Option<Stage> {
        Stage::ALL.into_iter().find(|s| s.name() == name)
    }
}

/// One frame's time in each stage, in nanoseconds, indexed as [`Stage::ALL`].
pub type Sample = [u64; 6];

/// Times a frame's stages: each [`Timer::lap`] charges the time since the last lap
/// (or [`Timer::start`]) to a stage.
#[derive(Debug, Clone, Copy)]
pub struct Timer {
    mark: Instant,
    spent: [Duration; 6],
}

impl Default for Timer {
    fn default() -> Self {
        Timer {
            mark: Instant::now(),
            spent: [Duration::ZERO; 6],
        }
    }
}

impl Timer {
    /// Starts a frame: every stage at zero.
    pub fn start(&mut self) {
        *self = Timer::default();
    }

    /// Charges the time since the last lap to `stage` (stages may be charged more
    /// than once a frame; the times add up).
    #[inline]
    pub fn lap(&mut self, stage: Stage) {
        let now = Instant::now();
        let i = Stage::ALL.iter().position(|s| *s == stage).unwrap_or(0);
        self.spent[i] += now - self.mark;
        self.mark = now;
    }

    /// The frame's times so far.
    pub fn sample(&self) -> Sample {
        self.spent
            .map(|d| u64::try_from(d.as_nanos()).unwrap_or(u64::MAX))
    }
}

/// Collects the samples of the frames after the first `warmup` ones.
#[derive(Debug, Clone, Default)]
pub struct Samples {
    /// Frames left out at the start (pipeline caches, first-touch page faults).
    pub warmup: u32,
    seen: u32,
    /// The kept frames' samples, in frame order.
    pub frames: Vec<Sample>,
    /// The last frame as read back, RGBA with packed rows (headless runs; empty in a
    /// window): what shows the variants draw the same image.
    pub last_frame: Vec<u8>,
}

impl Samples {
    /// Keeps frames after the first `warmup`.
    pub fn new(warmup: u32) -> Samples {
        Samples {
            warmup,
            ..Default::default()
        }
    }

    /// Records a drawn frame's timer.
    pub fn push(&mut self, timer: &Timer) {
        if self.seen >= self.warmup {
            self.frames.push(timer.sample());
        }
        self.seen += 1;
    }

    /// Frames seen so far, warm-up included.
    pub fn seen(&self) -> u32 {
        self.seen
    }
}

/// What one run renders.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Run {
    /// Teapots in the grid.
    pub count: u32,
    /// Camera blocks written per frame.
    pub writes: u32,
    /// Frames timed, after the warm-up.
    pub frames: u32,
    /// Frames drawn first and not timed.
    pub warmup: u32,
    /// Image (or window) width and height in pixels.
    pub size: u32,
    /// In a window (X11) rather than headless.
    pub window: bool,
}

/// Writes through a temporary file and a rename, so a failed run leaves the old file.
pub fn write_file(path: &std::path::Path, text: &str) -> anyhow::Result<()> {
    let tmp = path.with_extension("tmp");
    std::fs::write(&tmp, text).with_context(|| format!("cannot write {}", tmp.display()))?;
    std::fs::rename(&tmp, path).with_context(|| format!("cannot write {}", path.display()))
}

/// Today's UTC date, YYYY-MM-DD.
pub fn today() -> String {
    let secs = std::time::SystemTime::now()
        .duration_since(std::time::UNIX_EPOCH)
        .map_or(0, |d| d.as_secs());
    // Days to civil date (Howard Hinnant's algorithm).
    let z = (secs / 86_400) as i64 + 719_468;
    let era = z.div_euclid(146_097);
    let doe = z - era * 146_097;
    let yoe = (doe - doe / 1460 + doe / 36_524 - doe / 146_096) / 365;
    let doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
    let mp = (5 * doy + 2) / 153;
    let day = doy - (153 * mp + 2) / 5 + 1;
    let month = if mp < 10 { mp + 3 } else { mp - 9 };
    let year = yoe + era * 400 + i64::from(month <= 2);
    format!("{year:04}-{month:02}-{day:02}")
}
