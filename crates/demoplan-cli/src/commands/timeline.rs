//! `demoplan timeline RECORDING -o FILE.svg`: one recording over time, per hand: its
//! speed, its distance to every object, its grip, with the grounding thresholds, and the
//! segments as coloured bands (with the ground truth's activities when a simulated
//! recording has them beside it), so that a person can see why a segment was cut where
//! it was. The SVG is written by hand and atomically.

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use segment::Activity;

use crate::commands::demo_input;
use crate::diagnostic::Failure;
use crate::exit::ExitCode;
use crate::output::write_atomically;

/// The command line of `timeline`.
#[derive(Debug)]
pub struct TimelineArgs {
    pub file: PathBuf,
    pub out: PathBuf,
    pub config: Option<PathBuf>,
    pub tree: Option<PathBuf>,
}

/// Most points drawn per line (longer recordings are thinned).
const MAX_POINTS: usize = 2400;
const WIDTH: f64 = 1200.0;
const LEFT: f64 = 150.0;
const RIGHT: f64 = 20.0;
const PANEL: f64 = 80.0;
const BAND: f64 = 16.0;
const GAP: f64 = 14.0;

/// A panel: its label, the top of its scale, and its threshold lines.
type Panel<'a> = (&'a str, f64, Vec<(f64, &'a str)>);

struct Sample {
    time: f64,
    speed: Vec<f32>,
    grip: Vec<Option<f32>>,
    distances: Vec<Vec<f32>>,
}

pub fn run(args: TimelineArgs) -> Result<ExitCode, Failure> {
    if args
        .out
        .extension()
        .is_none_or(|e| !e.eq_ignore_ascii_case("svg"))
    {
        return Err(Failure::plain(
            ExitCode::USAGE,
            format!(
                "{}: the timeline is an SVG file (name it FILE.svg)",
                args.out.display()
            ),
        ));
    }
    let config = demo_input::config(args.config.as_deref())?;
    let tree = demo_input::activity_tree(args.tree.as_deref())?;
    let mut samples = Vec::new();
    let segmented = demo_input::segment_recording(
        &args.file,
        &config,
        &tree,
        |frame, grounder| {
            let s = grounder.signals();
            samples.push(Sample {
                time: frame.time,
                speed: s.iter().map(|h| h.speed).collect(),
                grip: s.iter().map(|h| h.grip).collect(),
                distances: s.iter().map(|h| h.distances.clone()).collect(),
            });
        },
        |_| {},
    )?;
    let truth = if demo_input::truth_path(&args.file).is_file() {
        Some(demo_input::read_truth(&args.file, &segmented.header)?)
    } else {
        None
    };
    let svg = draw(&args.file, &segmented, &samples, truth.as_deref(), &config);
    write_atomically(&args.out, &svg)?;
    println!(
        "{}: {} frames, {} segments drawn to {}",
        args.file.display(),
        segmented.frames,
        segmented.segments.len(),
        args.out.display()
    );
    Ok(ExitCode::SUCCESS)
}

fn colour(a: Activity) -> &'static str {
    match a {
        Activity::Stack => "#d62728",
        Activity::Idle => "#d9d9d9",
        Activity::Reach => "#1f77b4",
        Activity::Put => "#2ca02c",
        Activity::Take => "#ff7f0e",
    }
}

const OBJECT_COLOURS: [&str; 8] = [
    "#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd", "#8c564b", "#e377c2", "#17becf",
];

fn escape(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
}

fn draw(
    path: &Path,
    s: &demo_input::Segmented,
    samples: &[Sample],
    truth: Option<&[Vec<String>]>,
    config: &grounding::GroundingConfig,
) -> String {
    let hands = s.space.hands();
    let objects = s.space.objects();
    let t0 = samples.first().map_or(0.0, |x| x.time);
    let t1 = samples.last().map_or(1.0, |x| x.time).max(t0 + 1e-3);
    let plot_w = WIDTH - LEFT - RIGHT;
    let x = |t: f64| LEFT + (t - t0) / (t1 - t0) * plot_w;
    let bands = if truth.is_some() { 2.0 } else { 1.0 };
    let per_hand = 3.0 * (PANEL + GAP) + bands * (BAND + 4.0) + 30.0;
    let height = 60.0 + per_hand * hands.len() as f64 + 50.0;
    let stride = samples.len().div_ceil(MAX_POINTS).max(1);
    let max_speed = samples
        .iter()
        .flat_map(|x| x.speed.iter().copied())
        .fold(0.3f32, f32::max)
        .min(3.0) as f64;
    let mut o = String::new();
    let _ = writeln!(
        o,
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="{WIDTH}" height="{height:.0}" viewBox="0 0 {WIDTH} {height:.0}" font-family="sans-serif" font-size="11">"#
    );
    let _ = writeln!(o, r#"<rect width="100%" height="100%" fill="white"/>"#);
    let _ = writeln!(
        o,
        r#"<text x="{LEFT}" y="24" font-size="15">{} ({}, {} frames, {:.2} s)</text>"#,
        escape(&s.header.id),
        escape(&path.display().to_string()),
        s.frames,
        s.duration
    );
    let mut y = 50.0;
    for (hi, &hand) in hands.iter().enumerate() {
        let hand_name = &s.header.entity(hand).name;
        let _ = writeln!(
            o,
            r#"<text x="10" y="{:.1}" font-size="13" font-weight="bold">{}</text>"#,
            y + 4.0,
            escape(hand_name)
        );
        y += 12.0;
        let top = y;
        // Panels: speed, distances, grip.
        let panels: [Panel<'_>; 3] = [
            (
                "speed (m/s)",
                max_speed,
                vec![(config.hand_move.speed, "handMove")],
            ),
            (
                "distance (m)",
                0.4,
                vec![
                    (config.acted_on.distance, "actedOn"),
                    (config.graspable.distance, "graspable"),
                ],
            ),
            (
                "grip",
                1.0,
                vec![
                    (config.hand_open.close_above, "closed"),
                    (config.hand_open.open_below, "open"),
                ],
            ),
        ];
        for (pi, (label, max, lines)) in panels.iter().enumerate() {
            let py = |v: f64| y + PANEL - (v.clamp(0.0, *max) / max) * PANEL;
            let _ = writeln!(
                o,
                r##"<rect x="{LEFT}" y="{y:.1}" width="{plot_w:.1}" height="{PANEL}" fill="none" stroke="#999"/>"##
            );
            let _ = writeln!(
                o,
                r#"<text x="10" y="{:.1}">{label}</text>"#,
                y + PANEL / 2.0
            );
            let _ = writeln!(
                o,
                r#"<text x="{:.1}" y="{:.1}" text-anchor="end">{max:.2}</text>"#,
                LEFT - 4.0,
                y + 9.0
            );
            let _ = writeln!(
                o,
                r#"<text x="{:.1}" y="{:.1}" text-anchor="end">0</text>"#,
                LEFT - 4.0,
                y + PANEL
            );
            for (v, name) in lines {
                let _ = writeln!(
                    o,
                    r##"<line x1="{LEFT}" x2="{:.1}" y1="{:.1}" y2="{:.1}" stroke="#888" stroke-dasharray="4 3"/><text x="{:.1}" y="{:.1}" fill="#666" text-anchor="end">{name} {v}</text>"##,
                    LEFT + plot_w,
                    py(*v),
                    py(*v),
                    LEFT + plot_w - 2.0,
                    py(*v) - 2.0
                );
            }
            let mut poly = |values: &dyn Fn(&Sample) -> Option<f64>, stroke: &str, width: f64| {
                let mut points = String::new();
                for sample in samples.iter().step_by(stride) {
                    if let Some(v) = values(sample).filter(|v| v.is_finite()) {
                        let _ = write!(points, "{:.1},{:.1} ", x(sample.time), py(v));
                    }
                }
                let _ = writeln!(
                    o,
                    r#"<polyline fill="none" stroke="{stroke}" stroke-width="{width}" points="{}"/>"#,
                    points.trim_end()
                );
            };
            match pi {
                0 => poly(&|smp| smp.speed.get(hi).map(|&v| f64::from(v)), "#222", 1.2),
                1 => {
                    for (k, _) in objects.iter().enumerate() {
                        poly(
                            &|smp| {
                                smp.distances
                                    .get(hi)
                                    .and_then(|d| d.get(k))
                                    .map(|&v| f64::from(v))
                            },
                            OBJECT_COLOURS[k % OBJECT_COLOURS.len()],
                            1.0,
                        );
                    }
                }
                _ => poly(
                    &|smp| smp.grip.get(hi).copied().flatten().map(f64::from),
                    "#222",
                    1.2,
                ),
            }
            y += PANEL + GAP;
        }
        // Object legend beside the distance panel.
        for (k, &obj) in objects.iter().enumerate() {
            let _ = writeln!(
                o,
                r#"<text x="10" y="{:.1}" fill="{}">{}</text>"#,
                top + PANEL + GAP + 24.0 + 11.0 * k as f64,
                OBJECT_COLOURS[k % OBJECT_COLOURS.len()],
                escape(&s.header.entity(obj).name)
            );
        }
        // Segment bands, and boundaries through the panels.
        let _ = writeln!(
            o,
            r#"<text x="10" y="{:.1}">segments</text>"#,
            y + BAND - 4.0
        );
        for g in s.segments.iter().filter(|g| g.hand == hand) {
            let (a, b) = (x(g.start), x(g.end.max(g.start)));
            let _ = writeln!(
                o,
                r#"<rect x="{a:.1}" y="{y:.1}" width="{:.1}" height="{BAND}" fill="{}"><title>{} {:.3}-{:.3} s</title></rect>"#,
                (b - a).max(0.5),
                colour(g.activity),
                g.activity,
                g.start,
                g.end
            );
            let _ = writeln!(
                o,
                r##"<line x1="{a:.1}" x2="{a:.1}" y1="{top:.1}" y2="{:.1}" stroke="#555" stroke-width="0.5" opacity="0.5"/>"##,
                y + BAND
            );
        }
        y += BAND + 4.0;
        if let Some(truth) = truth {
            let _ = writeln!(
                o,
                r#"<text x="10" y="{:.1}">ground truth</text>"#,
                y + BAND - 4.0
            );
            let mut run: Option<(f64, &str)> = None;
            let mut last_t = t0;
            for (sample, names) in samples.iter().zip(truth) {
                let name = names.get(hi).map_or("Idle", String::as_str);
                match run {
                    Some((_, n)) if n == name => {}
                    _ => {
                        if let Some((start, n)) = run {
                            truth_rect(&mut o, x(start), x(sample.time), y, n);
                        }
                        run = Some((sample.time, name));
                    }
                }
                last_t = sample.time;
            }
            if let Some((start, n)) = run {
                truth_rect(&mut o, x(start), x(last_t), y, n);
            }
            y += BAND + 4.0;
        }
        y += 30.0;
    }
    // Legend and time axis.
    let mut lx = LEFT;
    for a in Activity::ALL {
        let _ = writeln!(
            o,
            r#"<rect x="{lx:.1}" y="{:.1}" width="12" height="12" fill="{}"/><text x="{:.1}" y="{:.1}">{a}</text>"#,
            y,
            colour(a),
            lx + 16.0,
            y + 10.0
        );
        lx += 80.0;
    }
    let _ = writeln!(
        o,
        r#"<text x="{:.1}" y="{:.1}" text-anchor="end">time {t0:.2} to {t1:.2} s</text>"#,
        LEFT + plot_w,
        y + 10.0
    );
    o.push_str("</svg>\n");
    o
}

fn truth_rect(o: &mut String, a: f64, b: f64, y: f64, name: &str) {
    let fill = Activity::from_name(name).map_or("#000", colour);
    let _ = writeln!(
        o,
        r#"<rect x="{a:.1}" y="{y:.1}" width="{:.1}" height="{BAND}" fill="{fill}" opacity="0.8"><title>truth {name}</title></rect>"#,
        (b - a).max(0.5)
    );
}
