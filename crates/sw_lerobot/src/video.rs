//! Video files: RGB frames piped into Debian's `ffmpeg` (H.264 in MP4, yuv420p, one
//! keyframe a second, one thread), written to a temporary name and renamed into place
//! when ffmpeg has finished — so a kill never leaves a half-written file under the final
//! name. Frames are also sampled for the images' statistics.

use std::io::Write as _;
use std::path::{Path, PathBuf};
use std::process::{Child, Command, Stdio};

use crate::LeRobotError;
use crate::stats::FeatureStats;

/// The codec written into `info.json`.
pub const CODEC: &str = "h264";
pub const PIX_FMT: &str = "yuv420p";

/// Pixels sampled per frame for the statistics (every n-th).
const STAT_STRIDE: usize = 17;
/// Frames sampled for the statistics (every n-th).
const STAT_FRAME_STRIDE: usize = 3;

/// One video being encoded.
#[derive(Debug)]
pub struct VideoWriter {
    child: Child,
    tmp: PathBuf,
    dest: PathBuf,
    width: usize,
    height: usize,
    frames: usize,
    /// Sampled pixel values per channel, in [0, 1].
    samples: [Vec<f64>; 3],
}

impl VideoWriter {
    /// Starts `ffmpeg` writing `dest` (through a temporary sibling).
    pub fn create(dest: &Path, width: usize, height: usize, fps: u32) -> Result<Self, LeRobotError> {
        if width % 2 == 1 || height % 2 == 1 {
            return Err(LeRobotError::Video(format!(
                "video frames must have even sides for {PIX_FMT}, got {width}x{height}"
            )));
        }
        if let Some(dir) = dest.parent() {
            fs_err::create_dir_all(dir).map_err(|e| LeRobotError::Io(e.to_string()))?;
        }
        let tmp = dest.with_extension(format!("partial-{}.mp4", std::process::id()));
        let child = Command::new("ffmpeg")
            .args(["-hide_banner", "-loglevel", "error", "-y", "-f", "rawvideo", "-pix_fmt", "rgb24", "-s"])
            .arg(format!("{width}x{height}"))
            .args(["-r", &fps.to_string(), "-i", "-", "-c:v", "libx264", "-preset", "veryfast", "-crf", "23"])
            .args(["-pix_fmt", PIX_FMT, "-g", &fps.to_string(), "-threads", "1", "-movflags", "+faststart"])
            .arg(&tmp)
            .stdin(Stdio::piped())
            .stdout(Stdio::null())
            .stderr(Stdio::piped())
            .spawn()
            .map_err(|e| {
                LeRobotError::Video(format!(
                    "cannot run ffmpeg ({e}); install it (`apt-get install ffmpeg`, or scripts/setup.sh)"
                ))
            })?;
        Ok(Self { child, tmp, dest: dest.to_path_buf(), width, height, frames: 0, samples: Default::default() })
    }

    /// Appends one frame (rows top to bottom, RGB).
    pub fn push(&mut self, rgb: &[u8]) -> Result<(), LeRobotError> {
        if rgb.len() != self.width * self.height * 3 {
            return Err(LeRobotError::Video(format!(
                "a frame of {} bytes for a {}x{} video",
                rgb.len(),
                self.width,
                self.height
            )));
        }
        if self.frames.is_multiple_of(STAT_FRAME_STRIDE) {
            for px in rgb.chunks_exact(3).step_by(STAT_STRIDE) {
                for (samples, v) in self.samples.iter_mut().zip(px) {
                    samples.push(f64::from(*v) / 255.0);
                }
            }
        }
        self.frames += 1;
        let stdin = self.child.stdin.as_mut().ok_or_else(|| LeRobotError::Video("ffmpeg's input is closed".into()))?;
        stdin.write_all(rgb).map_err(|e| LeRobotError::Video(format!("ffmpeg stopped taking frames: {e}")))
    }

    /// Waits for ffmpeg, renames the file into place; the images' statistics.
    pub fn finish(mut self) -> Result<FeatureStats, LeRobotError> {
        drop(self.child.stdin.take());
        let mut msg = String::new();
        if let Some(mut err) = self.child.stderr.take() {
            let _ = std::io::Read::read_to_string(&mut err, &mut msg);
        }
        let status = self.child.wait().map_err(|e| LeRobotError::Video(e.to_string()))?;
        if !status.success() {
            let _ = std::fs::remove_file(&self.tmp);
            return Err(LeRobotError::Video(format!("ffmpeg failed: {}", msg.lines().last().unwrap_or("no message"))));
        }
        std::fs::rename(&self.tmp, &self.dest)
            .map_err(|e| LeRobotError::Io(format!("{}: {e}", self.dest.display())))?;
        let count = self.frames as u64;
        Ok(FeatureStats::of_columns(std::mem::take(&mut self.samples).into(), count))
    }

    pub fn frames(&self) -> usize {
        self.frames
    }
}

impl Drop for VideoWriter {
    fn drop(&mut self) {
        // An abandoned writer (an error elsewhere): stop ffmpeg and remove its output.
        if self.child.stdin.is_some() {
            drop(self.child.stdin.take());
            let _ = self.child.kill();
            let _ = self.child.wait();
            let _ = std::fs::remove_file(&self.tmp);
        }
    }
}
