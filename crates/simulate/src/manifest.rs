//! What `demoplan simulate` writes beside the recordings: the manifest
//! (`simulation.json`: the seed, the participants drawn, the parameters and per
//! demonstration its files, hand, task, placements, frames and duration) and a listing
//! line per demonstration.

use std::io::Write;
use std::path::{Path, PathBuf};

use serde_json::json;

use crate::params::SimParams;
use crate::study::{Demonstration, Study};
use crate::truth::{TruthFrame, TruthWriter};

/// Name of the manifest written beside the recordings.
pub const MANIFEST: &str = "simulation.json";

/// What was written of one demonstration.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Written {
    pub frames: u64,
    /// Seconds from the first frame to the last.
    pub seconds: f64,
}

/// Rounded to milliseconds (or thousandths), as the manifest shows values.
fn milli(x: f64) -> f64 {
    (x * 1000.0).round() / 1000.0
}

impl Demonstration {
    /// The recording's file name, `ID.jsonl`.
    pub fn recording_name(&self) -> String {
        format!("{}.jsonl", self.id)
    }

    /// The ground truth's file name, `ID.truth.jsonl`.
    pub fn truth_name(&self) -> String {
        format!("{}.truth.jsonl", self.id)
    }

    /// Renders the demonstration frame by frame: its recording to `recording` and its
    /// ground truth to `truth`, in step; says what was written.
    pub fn write(&self, recording: impl Write, truth: impl Write) -> std::io::Result<Written> {
        let mut truth = TruthWriter::new(truth, &self.truth_header(), self.header())?;
        let mut writer =
            recording::Writer::new(recording, self.header()).map_err(std::io::Error::other)?;
        let (mut frames, mut first, mut last) = (0u64, 0.0, 0.0);
        let mut frame = recording::Frame::default();
        let mut t = TruthFrame::default();
        let mut render = self.frames();
        while render.next_into(&mut frame, &mut t) {
            writer.write_frame(&frame).map_err(std::io::Error::other)?;
            truth.write(&t)?;
            if frames == 0 {
                first = frame.time;
            }
            last = frame.time;
            frames += 1;
        }
        writer.finish().map_err(std::io::Error::other)?;
        truth.finish()?.flush()?;
        Ok(Written {
            frames,
            seconds: last - first,
        })
    }

    fn hand_name(&self) -> &'static str {
        self.hand.map_or("both", |h| h.name())
    }

    /// One line for people: id, hand, cubes placed, frames, seconds, the placements.
    pub fn listing_line(&self, written: Written) -> String {
        let placements: Vec<String> = self.placements.iter().map(|p| self.describe(p)).collect();
        format!(
            "{:<8} {:<5} hand  {} cube{}  {:>5} frames  {:>6.2} s  {}\n",
            self.id,
            self.hand_name(),
            self.placements.len(),
            if self.placements.len() == 1 { " " } else { "s" },
            written.frames,
            written.seconds,
            placements.join(", ")
        )
    }
}

/// The ground truth beside a simulated recording: `NAME.truth.jsonl` for `NAME.jsonl`.
pub fn truth_path(recording: &Path) -> PathBuf {
    let name = recording
        .file_name()
        .map(|n| n.to_string_lossy().into_owned())
        .unwrap_or_default();
    let stem = name.strip_suffix(".jsonl").unwrap_or(&name);
    recording.with_file_name(format!("{stem}.truth.jsonl"))
}

/// The manifest of a study simulated with `seed` and `params`, whose demonstrations were
/// written as `written` says (in the study's order), as pretty JSON ending in a newline.
pub fn manifest(study: &Study, seed: u64, params: &SimParams, written: &[Written]) -> String {
    let recordings: Vec<serde_json::Value> = study
        .demonstrations
        .iter()
        .zip(written)
        .map(|(demo, w)| {
            let placements: Vec<String> =
                demo.placements.iter().map(|p| demo.describe(p)).collect();
            json!({
                "id": demo.id,
                "recording": demo.recording_name(),
                "truth": demo.truth_name(),
                "participant": demo.participant.code,
                "hand": demo.hand_name(),
                "task": demo.header().task,
                "placements": placements,
                "frames": w.frames,
                "duration": milli(w.seconds),
            })
        })
        .collect();
    let participants: Vec<serde_json::Value> = study
        .participants
        .iter()
        .map(|p| {
            json!({
                "code": p.code,
                "dominant_hand": p.dominant.name(),
                "mean_speed": milli(p.mean_speed),
                "rest_after_grasp": milli(p.rest_after_grasp),
                "hover": milli(p.hover),
                "return_between": milli(p.return_between),
                "abort": milli(p.abort),
                "regrasp": milli(p.regrasp),
                "adjust": milli(p.adjust),
                "fidget_rate": milli(p.fidget_rate),
            })
        })
        .collect();
    let manifest = json!({
        "format": "demoplan-simulation",
        "version": 1,
        "seed": seed,
        "participants": participants,
        "params": params.to_json(),
        "recordings": recordings,
    });
    serde_json::to_string_pretty(&manifest).unwrap_or_default() + "\n"
}

/// Why a study could not be written to its folder.
#[derive(Debug, thiserror::Error)]
pub enum WriteStudyError {
    /// The folder could not be made.
    #[error("cannot create {}: {source}", path.display())]
    Folder {
        path: PathBuf,
        #[source]
        source: std::io::Error,
    },
    /// A recording, its truth or the manifest could not be written (it is unchanged).
    #[error(transparent)]
    File(#[from] atomic_write::WriteError),
}

/// Writes `study` (simulated with `seed` and `params`) into the folder `out`, as
/// `demoplan simulate -o out` does: per demonstration its recording, then its ground
/// truth, each whole or not at all, and then the manifest, which lists only what is in
/// place. Says what was written of each demonstration, in the study's order.
pub fn write_study(
    study: &Study,
    seed: u64,
    params: &SimParams,
    out: &Path,
) -> Result<Vec<Written>, WriteStudyError> {
    std::fs::create_dir_all(out).map_err(|source| WriteStudyError::Folder {
        path: out.to_path_buf(),
        source,
    })?;
    let mut all = Vec::with_capacity(study.demonstrations.len());
    for demo in &study.demonstrations {
        // The truth is rendered beside the frames, so it is kept until the recording is
        // in place; it is a small part of the recording's size.
        let mut truth = Vec::new();
        let mut written = Written {
            frames: 0,
            seconds: 0.0,
        };
        atomic_write::write_atomically_with(&out.join(demo.recording_name()), |file| {
            written = demo.write(file, &mut truth)?;
            Ok(())
        })?;
        atomic_write::write_atomically(&out.join(demo.truth_name()), &truth)?;
        all.push(written);
    }
    atomic_write::write_atomically(&out.join(MANIFEST), manifest(study, seed, params, &all))?;
    Ok(all)
}

/// What `demoplan simulate` says of a study written to `out` ([`write_study`]): a
/// listing line per demonstration ([`Demonstration::listing_line`]), then the totals.
pub fn written_listing(study: &Study, written: &[Written], out: &Path) -> String {
    let mut text: String = study
        .demonstrations
        .iter()
        .zip(written)
        .map(|(demo, w)| demo.listing_line(*w))
        .collect();
    let total_frames: u64 = written.iter().map(|w| w.frames).sum();
    let total_seconds: f64 = written.iter().map(|w| w.seconds).sum();
    text.push_str(&format!(
        "wrote {} recordings ({total_frames} frames, {total_seconds:.1} s) with their ground truth \
         to {} (listed in {MANIFEST})\n",
        study.demonstrations.len(),
        out.display()
    ));
    text
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_listing_has_a_line_per_demonstration_and_the_totals() {
        let study = crate::study(&SimParams::default(), 3, 1, 2).unwrap();
        let written = [
            Written {
                frames: 10,
                seconds: 1.0,
            },
            Written {
                frames: 5,
                seconds: 0.5,
            },
        ];
        let text = written_listing(&study, &written, Path::new("out"));
        let lines: Vec<&str> = text.lines().collect();
        assert_eq!(lines.len(), 3, "{text}");
        assert_eq!(
            lines[1],
            study.demonstrations[1].listing_line(written[1]).trim_end()
        );
        assert_eq!(
            lines[2],
            "wrote 2 recordings (15 frames, 1.5 s) with their ground truth to out (listed in \
             simulation.json)"
        );
    }

    #[test]
    fn a_written_study_has_each_recording_with_its_truth_and_the_manifest() {
        let dir = std::env::temp_dir().join(format!("simulate-write-study-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        let params = SimParams::default();
        let study = crate::study(&params, 3, 1, 2).unwrap();
        let written = write_study(&study, 3, &params, &dir.join("out")).unwrap();
        assert_eq!(written.len(), 2);
        for (demo, w) in study.demonstrations.iter().zip(&written) {
            let (mut recording, mut truth) = (Vec::new(), Vec::new());
            assert_eq!(demo.write(&mut recording, &mut truth).unwrap(), *w);
            let out = dir.join("out");
            assert_eq!(
                std::fs::read(out.join(demo.recording_name())).unwrap(),
                recording
            );
            assert_eq!(std::fs::read(out.join(demo.truth_name())).unwrap(), truth);
        }
        assert_eq!(
            std::fs::read_to_string(dir.join("out").join(MANIFEST)).unwrap(),
            manifest(&study, 3, &params, &written)
        );
        // A folder that cannot be made (a file stands in its way) names it.
        std::fs::write(dir.join("file"), "").unwrap();
        let e = write_study(&study, 3, &params, &dir.join("file").join("out")).unwrap_err();
        assert!(
            e.to_string()
                .starts_with(&format!("cannot create {}", dir.join("file/out").display())),
            "{e}"
        );
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn a_demonstration_writes_its_recording_and_its_truth_in_step() {
        let study = crate::study(&SimParams::default(), 7, 1, 1).unwrap();
        let demo = &study.demonstrations[0];
        let (mut recording, mut truth) = (Vec::new(), Vec::new());
        let written = demo.write(&mut recording, &mut truth).unwrap();
        assert!(written.frames > 0 && written.seconds > 0.0, "{written:?}");
        let lines = recording.iter().filter(|&&b| b == b'\n').count() as u64;
        assert_eq!(
            lines,
            written.frames + 1,
            "a header line, then a line a frame"
        );
        let (_, frames) = crate::read_truth(truth.as_slice(), demo.header()).unwrap();
        assert_eq!(frames.len() as u64, written.frames);
        assert_eq!(
            truth_path(Path::new("out/p1-d1.jsonl")),
            Path::new("out").join(demo.truth_name().replace(&demo.id, "p1-d1"))
        );
    }
}
