//! The timeline figure: signals over time in stacked panels, one group of panels per
//! track (a hand), each panel with its threshold lines, and rows of coloured bands
//! (segments, labels) under them. The data is plain (series of points, bands of time);
//! what they mean (speeds, grips, activities) is the caller's: `learn::timeline` turns a
//! segmented recording into a [`Timeline`].

use crate::draw::{pt, Anchor, Color, Figure, Stroke, Text};

/// A whole timeline: its title, the time span drawn and its tracks.
#[derive(Debug, Clone, PartialEq)]
pub struct Timeline {
    pub title: String,
    /// First and last time drawn (seconds).
    pub start: f64,
    pub end: f64,
    pub tracks: Vec<Track>,
    /// The band colours explained under the last track: `(name, colour)`.
    pub legend: Vec<(String, Color)>,
}

/// One track (a hand): its panels of signals, then its rows of bands.
#[derive(Debug, Clone, PartialEq)]
pub struct Track {
    pub name: String,
    pub panels: Vec<Panel>,
    pub bands: Vec<BandRow>,
}

/// A panel: values from 0 to `max` (larger ones are drawn at `max`), threshold lines and
/// one line per series. A panel of several series lists their names beside it.
#[derive(Debug, Clone, PartialEq)]
pub struct Panel {
    pub label: String,
    pub max: f64,
    pub thresholds: Vec<Threshold>,
    pub series: Vec<Series>,
}

/// A dashed horizontal line at `value`, labelled `name value`.
#[derive(Debug, Clone, PartialEq)]
pub struct Threshold {
    pub value: f64,
    pub name: String,
}

/// A line through `(time, value)` points; points whose value is not finite are skipped.
#[derive(Debug, Clone, PartialEq)]
pub struct Series {
    pub name: String,
    pub color: Color,
    pub points: Vec<(f64, f64)>,
}

/// A row of bands; `boundaries` also draws each band's start through the panels above.
#[derive(Debug, Clone, PartialEq)]
pub struct BandRow {
    pub label: String,
    pub bands: Vec<Band>,
    pub boundaries: bool,
}

/// The span `start..end` (seconds) in a colour.
#[derive(Debug, Clone, PartialEq)]
pub struct Band {
    pub start: f64,
    pub end: f64,
    pub color: Color,
}

/// Most points drawn per series (longer series are thinned).
pub const MAX_POINTS: usize = 2400;
// Across, in pixels: the figure, and the margins left (for labels) and right.
const WIDTH: f64 = 1200.0;
const LEFT: f64 = 150.0;
const RIGHT: f64 = 20.0;
// Ink: labels, and the frames around panels.
const TEXT: Color = Color(34, 34, 34);
const FRAME: Color = Color(153, 153, 153);
// Down, in pixels: a panel, a band row, the gap between them.
const PANEL: f64 = 80.0;
const BAND: f64 = 16.0;
const GAP: f64 = 14.0;

fn label(figure: &mut Figure, x: f64, y: f64, text: &str, anchor: Anchor, color: Color) {
    figure.text(pt(x, y), text, 1, anchor, color);
}

/// Draws the timeline. Same timeline, same figure.
pub fn timeline_figure(timeline: &Timeline) -> Figure {
    let t0 = timeline.start;
    let t1 = timeline.end.max(t0 + 1e-3);
    let plot_w = WIDTH - LEFT - RIGHT;
    let x = |t: f64| LEFT + (t - t0) / (t1 - t0) * plot_w;
    let track_height = |t: &Track| {
        t.panels.len() as f64 * (PANEL + GAP) + t.bands.len() as f64 * (BAND + 4.0) + 42.0
    };
    let height = 50.0 + timeline.tracks.iter().map(track_height).sum::<f64>() + 50.0;
    let mut f = Figure::new(WIDTH as u32, height.ceil() as u32, &timeline.title);
    f.label(Text {
        at: pt(LEFT, 24.0),
        text: timeline.title.clone(),
        scale: 1,
        anchor: Anchor::Start,
        color: TEXT,
        bold: true,
        vertical: false,
    });
    let mut y = 50.0;
    for track in &timeline.tracks {
        f.label(Text {
            at: pt(10.0, y + 4.0),
            text: track.name.clone(),
            scale: 1,
            anchor: Anchor::Start,
            color: TEXT,
            bold: true,
            vertical: false,
        });
        y += 12.0;
        let top = y;
        for panel in &track.panels {
            let max = if panel.max > 0.0 { panel.max } else { 1.0 };
            let py = |v: f64| y + PANEL - (v.clamp(0.0, max) / max) * PANEL;
            f.rect(
                LEFT,
                y,
                plot_w,
                PANEL,
                None,
                Some(Stroke::solid(FRAME, 1.0)),
            );
            label(
                &mut f,
                10.0,
                y + PANEL / 2.0,
                &panel.label,
                Anchor::Start,
                TEXT,
            );
            if panel.series.len() > 1 {
                for (k, s) in panel.series.iter().enumerate() {
                    let ly = y + PANEL / 2.0 + 12.0 * (k as f64 + 1.0);
                    label(&mut f, 10.0, ly, &s.name, Anchor::Start, s.color);
                }
            }
            label(
                &mut f,
                LEFT - 4.0,
                y + 9.0,
                &format!("{max:.2}"),
                Anchor::End,
                TEXT,
            );
            label(&mut f, LEFT - 4.0, y + PANEL, "0", Anchor::End, TEXT);
            for t in &panel.thresholds {
                let ty = py(t.value);
                f.line(
                    pt(LEFT, ty),
                    pt(LEFT + plot_w, ty),
                    Stroke::dashed(Color(136, 136, 136), 1.0, 4.0, 3.0),
                );
                let text = format!("{} {}", t.name, t.value);
                label(
                    &mut f,
                    LEFT + plot_w - 2.0,
                    ty - 2.0,
                    &text,
                    Anchor::End,
                    FRAME,
                );
            }
            for s in &panel.series {
                let stride = s.points.len().div_ceil(MAX_POINTS).max(1);
                let points: Vec<_> = s
                    .points
                    .iter()
                    .step_by(stride)
                    .filter(|p| p.1.is_finite())
                    .map(|&(t, v)| pt(x(t), py(v)))
                    .collect();
                f.polyline(points, Stroke::solid(s.color, 1.2));
            }
            y += PANEL + GAP;
        }
        for row in &track.bands {
            label(
                &mut f,
                10.0,
                y + BAND - 4.0,
                &row.label,
                Anchor::Start,
                TEXT,
            );
            for band in &row.bands {
                let (a, b) = (x(band.start), x(band.end.max(band.start)));
                f.rect(a, y, (b - a).max(0.5), BAND, Some(band.color), None);
                if row.boundaries {
                    f.line(
                        pt(a, top),
                        pt(a, y + BAND),
                        Stroke::solid(Color(170, 170, 170), 0.5),
                    );
                }
            }
            y += BAND + 4.0;
        }
        y += 30.0;
    }
    let mut lx = LEFT;
    for (name, color) in &timeline.legend {
        f.rect(lx, y, 12.0, 12.0, Some(*color), None);
        label(&mut f, lx + 16.0, y + 10.0, name, Anchor::Start, TEXT);
        lx += 80.0;
    }
    let span = format!("time {t0:.2} to {t1:.2} s");
    label(&mut f, LEFT + plot_w, y + 10.0, &span, Anchor::End, TEXT);
    f
}

#[cfg(test)]
mod tests {
    use super::*;

    fn one_track() -> Timeline {
        Timeline {
            title: "demo".into(),
            start: 0.0,
            end: 2.0,
            tracks: vec![Track {
                name: "left_hand".into(),
                panels: vec![Panel {
                    label: "speed (m/s)".into(),
                    max: 1.0,
                    thresholds: vec![Threshold {
                        value: 0.1,
                        name: "handMove".into(),
                    }],
                    series: vec![Series {
                        name: "speed".into(),
                        color: Color::BLACK,
                        points: vec![(0.0, 0.0), (1.0, f64::NAN), (2.0, 5.0)],
                    }],
                }],
                bands: vec![BandRow {
                    label: "segments".into(),
                    bands: vec![Band {
                        start: 0.5,
                        end: 1.5,
                        color: Color(214, 39, 40),
                    }],
                    boundaries: true,
                }],
            }],
            legend: vec![("Stack".into(), Color(214, 39, 40))],
        }
    }

    #[test]
    fn a_timeline_draws_its_labels_thresholds_and_bands() {
        let svg = timeline_figure(&one_track()).svg();
        for text in [
            "left_hand",
            "speed (m/s)",
            "handMove 0.1",
            "segments",
            "Stack",
        ] {
            assert!(svg.contains(text), "no {text} in {svg}");
        }
        assert!(svg.contains(r##"fill="#d62728""##), "{svg}");
        // The value 5 is drawn at the panel's top (max 1), the NaN point is left out.
        let line = svg.lines().find(|l| l.starts_with("<polyline")).unwrap();
        assert_eq!(line.matches(',').count(), 2, "{line}");
    }

    #[test]
    fn long_series_are_thinned() {
        let mut t = one_track();
        t.tracks[0].panels[0].series[0].points = (0..10 * MAX_POINTS)
            .map(|i| (i as f64 / 1e4, 0.5))
            .collect();
        let svg = timeline_figure(&t).svg();
        let line = svg.lines().find(|l| l.starts_with("<polyline")).unwrap();
        assert_eq!(line.matches(',').count(), MAX_POINTS);
    }
}
