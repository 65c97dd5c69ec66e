//! The paper's figures, drawn with the [`Figure`] model: search time per goal on a log
//! axis (Figures 5 and 6), operators per type and priority level (Figure 3), and the
//! goal towers (Figure 4).

use crate::draw::{pt, text_width, Anchor, Color, Figure, Point, Stroke, Text};
use crate::model::{domain_label, format_limit, Experiment, Goal, Level, Measure, Outcome, Run};
use crate::palette::{OKABE_ITO as O, TABLEAU10 as T};
use crate::Planner;

/// Line colours for domains, by priority order (Okabe-Ito, readable when printed grey).
const DOMAIN_COLORS: [Color; 8] = [O[5], O[1], O[3], O[6], O[7], O[2], O[0], MID_GREY];
const MID_GREY: Color = Color(140, 140, 140);

/// Bar colours for the operator types reach, take, put, stack, idle.
const TYPE_COLORS: [Color; 5] = [O[2], O[1], O[3], O[5], LIGHT_GREY];
const LIGHT_GREY: Color = Color(170, 170, 170);

/// Cube colours, by cube number (`cube_1` is the first): Tableau's, with a yellow of
/// their own for the fourth.
const CUBE_COLORS: [Color; 10] = [T[3], T[0], T[2], YELLOW, T[4], T[1], T[9], T[5], T[6], T[7]];
const YELLOW: Color = Color(232, 195, 27);

const INK: Color = Color(30, 30, 30);
const GRID: Color = Color(228, 228, 228);
const LIMIT: Color = Color(180, 30, 30);
const TABLE: Color = Color(140, 109, 70);

/// A legend entry's label, right of its key (drawn at `lx` on the row at `row`).
fn legend_label(fig: &mut Figure, lx: f64, row: f64, label: &str) {
    text(fig, pt(lx + 40.0, row + 2.0), label, 2, Anchor::Start, INK);
}

/// A logarithmic axis over whole decades: `10^lo` maps to pixel `from`, `10^hi` to
/// pixel `to` (for a y axis, `from` is the bottom). Values outside are clamped.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LogScale {
    pub lo: i32,
    pub hi: i32,
    pub from: f64,
    pub to: f64,
}

impl LogScale {
    /// The decades from `min(10^lo_at_most, min)` to at least half a decade above
    /// `max`, so that a value at `max` (the time limit) has room for a note above it.
    /// Non-positive or non-finite inputs are ignored.
    pub fn covering(min: f64, max: f64, lo_at_most: i32, from: f64, to: f64) -> LogScale {
        let lo = if min > 0.0 && min.is_finite() {
            (min.log10().floor() as i32).min(lo_at_most)
        } else {
            lo_at_most
        };
        let hi = if max > 0.0 && max.is_finite() {
            (max.log10() + 0.5).ceil() as i32
        } else {
            lo + 1
        };
        LogScale {
            lo,
            hi: hi.max(lo + 1),
            from,
            to,
        }
    }

    /// The pixel of `value`.
    pub fn map(&self, value: f64) -> f64 {
        let lo = f64::from(self.lo);
        let hi = f64::from(self.hi);
        let v = if value > 0.0 && value.is_finite() {
            value.log10().clamp(lo, hi)
        } else if value == f64::INFINITY {
            hi
        } else {
            lo
        };
        self.from + (v - lo) / (hi - lo) * (self.to - self.from)
    }

    /// The decade exponents `lo..=hi`.
    pub fn decades(&self) -> impl Iterator<Item = i32> {
        self.lo..=self.hi
    }
}

/// `10^k` as a plain number: `0.001`, `1`, `100`; `1e-5` below a thousandth, `1e7`
/// above a million.
pub fn decade_label(k: i32) -> String {
    match k {
        i32::MIN..=-4 | 7..=i32::MAX => format!("1e{k}"),
        -3..=-1 => format!("0.{}1", "0".repeat((-k - 1) as usize)),
        _ => format!("1{}", "0".repeat(k as usize)),
    }
}

fn text(fig: &mut Figure, at: Point, s: &str, scale: u32, anchor: Anchor, color: Color) {
    fig.text(at, s, scale, anchor, color);
}

fn title(fig: &mut Figure, s: &str) {
    let x = f64::from(fig.width()) / 2.0;
    fig.label(Text {
        at: pt(x, 32.0),
        text: s.to_string(),
        scale: 2,
        anchor: Anchor::Middle,
        color: INK,
        bold: true,
        vertical: false,
    });
}

fn vertical_label(fig: &mut Figure, x: f64, y: f64, s: &str) {
    fig.label(Text {
        at: pt(x, y),
        text: s.to_string(),
        scale: 2,
        anchor: Anchor::Middle,
        color: INK,
        bold: false,
        vertical: true,
    });
}

fn open_marker(fig: &mut Figure, at: Point, color: Color) {
    fig.circle(at, 5.5, Some(Color::WHITE), Some(Stroke::solid(color, 2.0)));
}

fn dot_marker(fig: &mut Figure, at: Point, color: Color) {
    fig.circle(at, 4.5, Some(color), None);
}

fn cross_marker(fig: &mut Figure, at: Point, color: Color) {
    let d = 5.0;
    fig.line(
        pt(at.x - d, at.y - d),
        pt(at.x + d, at.y + d),
        Stroke::solid(color, 2.0),
    );
    fig.line(
        pt(at.x - d, at.y + d),
        pt(at.x + d, at.y - d),
        Stroke::solid(color, 2.0),
    );
}

/// Figures 5 and 6: search time of `planner` per goal (x) on a log axis (y, decades
/// from 0.001 s, or lower if a run was faster, to above the time limit), one line per
/// domain labelled by its operator count. Runs that hit the limit are open markers at
/// the limit with a "> limit" note, joined by dashed lines (the true time is higher);
/// unsolvable runs are crosses; with repeats, a bar shows each run's min-max spread.
pub fn search_time_figure(exp: &Experiment, planner: Planner) -> Figure {
    time_figure(exp, planner, Measure::Search)
}

/// [`search_time_figure`] by any [`Measure`]: the same figure of total times, titled
/// so (repeats' spreads are drawn for search time only, the one measure kept per
/// repeat).
pub fn time_figure(exp: &Experiment, planner: Planner, measure: Measure) -> Figure {
    let (w, h) = (900u32, 580u32);
    let mut fig = Figure::new(
        w,
        h,
        &format!("{} per goal, {}", measure.title(), planner.label()),
    );
    let (left, right, top, bottom) = (116.0, 670.0, 60.0, 470.0);
    title(
        &mut fig,
        &format!("{} per goal: {}", measure.title(), planner.label()),
    );
    let spread = |r: &Run| -> Vec<f64> {
        match measure {
            Measure::Search => r.times.clone(),
            Measure::Total => Vec::new(),
        }
    };

    let runs: Vec<&Run> = exp.runs.iter().filter(|r| r.planner == planner).collect();
    let goals = exp.goal_numbers();
    let domains: Vec<(usize, usize)> = exp
        .domains()
        .into_iter()
        .filter(|(p, _)| runs.iter().any(|r| r.prio == *p))
        .collect();

    // Axes.
    let min_time = runs
        .iter()
        .flat_map(|r| spread(r).into_iter().chain([r.time(measure)]))
        .filter(|t| *t > 0.0 && t.is_finite())
        .fold(f64::INFINITY, f64::min);
    let max_time = runs
        .iter()
        .flat_map(|r| spread(r).into_iter().chain([r.time(measure)]))
        .filter(|t| t.is_finite())
        .fold(exp.time_limit, f64::max);
    let y = LogScale::covering(min_time, max_time, -3, bottom, top);
    for k in y.decades() {
        let py = y.map(10f64.powi(k));
        if k > y.lo && k < y.hi {
            fig.line(pt(left, py), pt(right, py), Stroke::solid(GRID, 1.0));
        }
        fig.line(pt(left - 7.0, py), pt(left, py), Stroke::solid(INK, 1.5));
        text(
            &mut fig,
            pt(left - 12.0, py + 7.0),
            &decade_label(k),
            2,
            Anchor::End,
            INK,
        );
        if k < y.hi {
            for m in 2..10 {
                let pm = y.map(f64::from(m) * 10f64.powi(k));
                fig.line(pt(left - 4.0, pm), pt(left, pm), Stroke::solid(INK, 1.0));
            }
        }
    }
    let n_goals = goals.len().max(1) as f64;
    let slot = (right - left) / n_goals;
    let gx = |g: usize| -> f64 {
        let i = goals.iter().position(|x| *x == g).unwrap_or(0) as f64;
        left + slot * (i + 0.5)
    };
    for &g in &goals {
        let x = gx(g);
        fig.line(pt(x, bottom), pt(x, bottom + 6.0), Stroke::solid(INK, 1.5));
        text(
            &mut fig,
            pt(x, bottom + 26.0),
            &g.to_string(),
            2,
            Anchor::Middle,
            INK,
        );
        if let Some(goal) = exp.goals.iter().find(|x| x.number == g) {
            let sub = format!("{} cubes", goal.tower.len());
            text(
                &mut fig,
                pt(x, bottom + 46.0),
                &sub,
                2,
                Anchor::Middle,
                Color::GREY,
            );
        }
    }
    fig.rect(
        left,
        top,
        right - left,
        bottom - top,
        None,
        Some(Stroke::solid(INK, 1.5)),
    );
    text(
        &mut fig,
        pt((left + right) / 2.0, bottom + 74.0),
        "goal (tower height)",
        2,
        Anchor::Middle,
        INK,
    );
    vertical_label(
        &mut fig,
        26.0,
        (top + bottom) / 2.0,
        &format!("{} (s), log scale", measure.title().to_lowercase()),
    );

    // The time limit.
    let ly = y.map(exp.time_limit);
    if exp.time_limit > 0.0 && exp.time_limit.is_finite() {
        fig.line(
            pt(left, ly),
            pt(right, ly),
            Stroke::dashed(LIMIT, 1.5, 8.0, 5.0),
        );
        let label = format!("limit {} s", format_limit(exp.time_limit));
        text(
            &mut fig,
            pt(left + 8.0, ly - 6.0),
            &label,
            2,
            Anchor::Start,
            LIMIT,
        );
    }

    if runs.is_empty() {
        text(
            &mut fig,
            pt((left + right) / 2.0, (top + bottom) / 2.0),
            "no runs for this planner",
            2,
            Anchor::Middle,
            Color::GREY,
        );
    }

    // One line per domain, dodged sideways so that equal times stay visible.
    let n = domains.len() as f64;
    let mut limit_goals: Vec<usize> = Vec::new();
    let mut any_unsolvable = false;
    let mut any_spread = false;
    for (i, &(prio, _)) in domains.iter().enumerate() {
        let color = DOMAIN_COLORS[i % DOMAIN_COLORS.len()];
        let dx = (i as f64 - (n - 1.0) / 2.0) * 7.0;
        let point = |r: &Run| pt(gx(r.goal) + dx, y.map(r.time(measure)));
        let series: Vec<Option<&Run>> = goals
            .iter()
            .map(|&g| runs.iter().copied().find(|r| r.prio == prio && r.goal == g))
            .collect();
        let drawable = |r: &&Run| matches!(r.outcome, Outcome::Solved | Outcome::Limit);
        for pair in series.windows(2) {
            if let (Some(a), Some(b)) = (pair[0].filter(drawable), pair[1].filter(drawable)) {
                let (pa, pb) = (point(a), point(b));
                let pb = if b.outcome == Outcome::Limit {
                    pt(pb.x, ly)
                } else {
                    pb
                };
                let pa = if a.outcome == Outcome::Limit {
                    pt(pa.x, ly)
                } else {
                    pa
                };
                let stroke = if a.outcome == Outcome::Solved && b.outcome == Outcome::Solved {
                    Stroke::solid(color, 2.5)
                } else {
                    Stroke::dashed(color, 2.5, 7.0, 5.0)
                };
                fig.line(pa, pb, stroke);
            }
        }
        for r in series.iter().flatten() {
            let p = point(r);
            match r.outcome {
                Outcome::Solved => {
                    let finite: Vec<f64> =
                        spread(r).into_iter().filter(|t| t.is_finite()).collect();
                    if finite.len() > 1 {
                        let lo = finite.iter().copied().fold(f64::INFINITY, f64::min);
                        let hi = finite.iter().copied().fold(f64::NEG_INFINITY, f64::max);
                        if hi > lo {
                            any_spread = true;
                            fig.line(
                                pt(p.x, y.map(lo)),
                                pt(p.x, y.map(hi)),
                                Stroke::solid(color, 1.5),
                            );
                        }
                    }
                    dot_marker(&mut fig, p, color);
                }
                Outcome::Limit => {
                    open_marker(&mut fig, pt(p.x, ly), color);
                    if !limit_goals.contains(&r.goal) {
                        limit_goals.push(r.goal);
                    }
                }
                Outcome::Unsolvable => {
                    any_unsolvable = true;
                    cross_marker(&mut fig, p, color);
                }
                Outcome::Error => {}
            }
        }
    }
    for g in limit_goals {
        text(
            &mut fig,
            pt(gx(g), ly - 14.0),
            "> limit",
            2,
            Anchor::Middle,
            LIMIT,
        );
    }

    // Legend.
    let lx = right + 24.0;
    let mut ly_row = top + 18.0;
    text(&mut fig, pt(lx, ly_row), "domain", 2, Anchor::Start, INK);
    ly_row += 28.0;
    for (i, &(prio, ops)) in domains.iter().enumerate() {
        let color = DOMAIN_COLORS[i % DOMAIN_COLORS.len()];
        let cy = ly_row - 5.0;
        fig.line(pt(lx, cy), pt(lx + 30.0, cy), Stroke::solid(color, 2.5));
        dot_marker(&mut fig, pt(lx + 15.0, cy), color);
        legend_label(&mut fig, lx, ly_row, &domain_label(prio, ops));
        ly_row += 26.0;
    }
    ly_row += 14.0;
    let key = Color::GREY;
    let mut keys: Vec<(&str, u8)> = vec![("solved", 0), ("> limit", 1)];
    if any_unsolvable {
        keys.push(("unsolvable", 2));
    }
    if any_spread {
        keys.push(("min-max", 3));
    }
    for (label, kind) in keys {
        let c = pt(lx + 15.0, ly_row - 5.0);
        match kind {
            0 => dot_marker(&mut fig, c, key),
            1 => open_marker(&mut fig, c, key),
            2 => cross_marker(&mut fig, c, key),
            _ => fig.line(
                pt(c.x, c.y - 9.0),
                pt(c.x, c.y + 9.0),
                Stroke::solid(key, 1.5),
            ),
        }
        legend_label(&mut fig, lx, ly_row, label);
        ly_row += 26.0;
    }
    let legend_w = f64::from(w) - lx - 12.0;
    fig.rect(
        lx - 12.0,
        top,
        legend_w + 6.0,
        ly_row - top - 8.0,
        None,
        Some(Stroke::solid(GRID, 1.5)),
    );

    let repeats = if exp.repeat > 1 {
        format!("medians of {} runs each", exp.repeat)
    } else {
        "one run each".to_string()
    };
    let foot = format!(
        "{repeats}; open markers hit the {} s limit (the true time is higher)",
        format_limit(exp.time_limit)
    );
    text(
        &mut fig,
        pt(12.0, f64::from(h) - 10.0),
        &foot,
        1,
        Anchor::Start,
        Color::GREY,
    );
    fig
}

/// The smallest "nice" step (1, 2 or 5 times a power of ten) that divides `max` into at
/// most `ticks` intervals.
fn nice_step(max: f64, ticks: usize) -> f64 {
    let raw = (max / ticks.max(1) as f64).max(1.0);
    let mag = 10f64.powi(raw.log10().floor() as i32);
    for m in [1.0, 2.0, 5.0, 10.0] {
        if m * mag >= raw {
            return m * mag;
        }
    }
    10.0 * mag
}

/// Black or white, whichever reads better on `bg`.
fn text_on(bg: Color) -> Color {
    let luma = 0.299 * f64::from(bg.0) + 0.587 * f64::from(bg.1) + 0.114 * f64::from(bg.2);
    if luma > 150.0 {
        INK
    } else {
        Color::WHITE
    }
}

/// Figure 3: stacked bars of operators per type (reach, take, put, stack, idle) for each
/// priority level, labelled `dom{prio}({operators})`, with the total on top.
pub fn operators_figure(levels: &[Level]) -> Figure {
    let mut levels: Vec<&Level> = levels.iter().collect();
    levels.sort_by_key(|l| l.prio);
    let slot = 110.0;
    let (left, top, bottom) = (90.0, 60.0, 400.0);
    let right = left + slot * levels.len().max(1) as f64;
    let w = (right + 190.0).max(640.0);
    let h = 470.0;
    let mut fig = Figure::new(w as u32, h as u32, "Operators per type and priority level");
    title(&mut fig, "Operators per type and priority level");

    let totals: Vec<usize> = levels
        .iter()
        .map(|l| l.per_type.iter().sum::<usize>().max(l.operators))
        .collect();
    let max_total = totals.iter().copied().max().unwrap_or(0).max(1) as f64;
    let step = nice_step(max_total, 6);
    // Room above the tallest bar for its total.
    let mut y_max = (max_total / step).ceil() * step;
    if y_max - max_total < 0.15 * y_max {
        y_max += step;
    }
    let ymap = |v: f64| bottom - v / y_max * (bottom - top);
    let mut v = 0.0;
    while v <= y_max + 1e-9 {
        let py = ymap(v);
        if v > 0.0 {
            fig.line(pt(left, py), pt(right, py), Stroke::solid(GRID, 1.0));
        }
        fig.line(pt(left - 6.0, py), pt(left, py), Stroke::solid(INK, 1.5));
        text(
            &mut fig,
            pt(left - 10.0, py + 7.0),
            &format!("{v}"),
            2,
            Anchor::End,
            INK,
        );
        v += step;
    }

    for (i, (level, total)) in levels.iter().zip(&totals).enumerate() {
        let cx = left + slot * (i as f64 + 0.5);
        let bw = slot * 0.6;
        let mut base = 0.0;
        for (t, &count) in level.per_type.iter().enumerate() {
            if count == 0 {
                continue;
            }
            let (y0, y1) = (ymap(base), ymap(base + count as f64));
            let color = TYPE_COLORS[t];
            fig.rect(
                cx - bw / 2.0,
                y1,
                bw,
                y0 - y1,
                Some(color),
                Some(Stroke::solid(Color::WHITE, 1.0)),
            );
            if y0 - y1 >= 18.0 {
                text(
                    &mut fig,
                    pt(cx, (y0 + y1) / 2.0 + 7.0),
                    &count.to_string(),
                    2,
                    Anchor::Middle,
                    text_on(color),
                );
            }
            base += count as f64;
        }
        let rest = level.operators.saturating_sub(level.per_type.iter().sum());
        if rest > 0 {
            let (y0, y1) = (ymap(base), ymap(base + rest as f64));
            fig.rect(
                cx - bw / 2.0,
                y1,
                bw,
                y0 - y1,
                None,
                Some(Stroke::dashed(INK, 1.0, 4.0, 3.0)),
            );
        }
        text(
            &mut fig,
            pt(cx, ymap(*total as f64) - 8.0),
            &total.to_string(),
            2,
            Anchor::Middle,
            INK,
        );
        fig.line(
            pt(cx, bottom),
            pt(cx, bottom + 6.0),
            Stroke::solid(INK, 1.5),
        );
        text(
            &mut fig,
            pt(cx, bottom + 26.0),
            &domain_label(level.prio, level.operators),
            2,
            Anchor::Middle,
            INK,
        );
    }
    fig.line(pt(left, bottom), pt(right, bottom), Stroke::solid(INK, 1.5));
    fig.line(pt(left, top), pt(left, bottom), Stroke::solid(INK, 1.5));
    if levels.is_empty() {
        text(
            &mut fig,
            pt((left + right) / 2.0, (top + bottom) / 2.0),
            "no levels",
            2,
            Anchor::Middle,
            Color::GREY,
        );
    }
    text(
        &mut fig,
        pt((left + right) / 2.0, bottom + 56.0),
        "domain: dom<prio>(<operators>)",
        2,
        Anchor::Middle,
        INK,
    );
    vertical_label(&mut fig, 30.0, (top + bottom) / 2.0, "operators");

    // Legend, top down in the reverse of the stacking order, so it reads like the bars.
    let lx = right + 30.0;
    let mut ly = top + 18.0;
    text(&mut fig, pt(lx, ly), "type", 2, Anchor::Start, INK);
    ly += 28.0;
    for t in (0..5).rev() {
        fig.rect(lx, ly - 14.0, 16.0, 16.0, Some(TYPE_COLORS[t]), None);
        text(
            &mut fig,
            pt(lx + 26.0, ly),
            recording::Activity::OPERATOR_ORDER[t].operator_name(),
            2,
            Anchor::Start,
            INK,
        );
        ly += 26.0;
    }
    fig
}

/// The label drawn on a cube: the number of `cube_N`, else the name itself.
fn cube_label(name: &str) -> &str {
    name.strip_prefix("cube_")
        .filter(|s| !s.is_empty())
        .unwrap_or(name)
}

/// The colour of a cube: by its number if it has one, else by `fallback`.
fn cube_color(name: &str, fallback: usize) -> Color {
    let index = cube_label(name)
        .parse::<usize>()
        .ok()
        .and_then(|n| n.checked_sub(1))
        .unwrap_or(fallback);
    CUBE_COLORS[index % CUBE_COLORS.len()]
}

fn cube(fig: &mut Figure, x: f64, y_bottom: f64, size: f64, name: &str, fallback: usize) {
    let color = cube_color(name, fallback);
    fig.rect(
        x,
        y_bottom - size,
        size,
        size,
        Some(color),
        Some(Stroke::solid(INK, 1.5)),
    );
    let label = cube_label(name);
    let scale = if text_width(label, 2) <= size - 6.0 {
        2
    } else {
        1
    };
    let shown: String = if text_width(label, scale) <= size - 4.0 {
        label.to_string()
    } else {
        label
            .chars()
            .take(((size - 4.0) / 6.0).max(1.0) as usize)
            .collect()
    };
    let baseline = y_bottom - size / 2.0 + f64::from(3 * scale + scale / 2);
    text(
        fig,
        pt(x + size / 2.0, baseline),
        &shown,
        scale,
        Anchor::Middle,
        text_on(color),
    );
}

/// Cube names of a scene with `cubes` cubes that are not in `tower`.
fn others(tower: &[String], cubes: usize) -> Vec<String> {
    (1..=cubes)
        .map(|i| format!("cube_{i}"))
        .filter(|n| !tower.contains(n))
        .collect()
}

/// Draws one goal: the tower standing on the table at `x`, the other cubes beside it.
/// Returns the width used.
fn goal_panel(fig: &mut Figure, x: f64, table_y: f64, goal: &Goal, cubes: usize, size: f64) -> f64 {
    let gap = (size / 4.0).round();
    let rest = others(&goal.tower, cubes);
    let tower_x = x + 16.0;
    for (i, name) in goal.tower.iter().enumerate() {
        cube(fig, tower_x, table_y - size * i as f64, size, name, i);
    }
    let mut ox = tower_x + size + 2.0 * gap + 8.0;
    for (j, name) in rest.iter().enumerate() {
        cube(fig, ox, table_y, size, name, goal.tower.len() + j);
        ox += size + gap;
    }
    let width = if rest.is_empty() {
        tower_x + size + 16.0 - x
    } else {
        ox - gap + 16.0 - x
    };
    fig.rect(x, table_y, width, 10.0, Some(TABLE), None);
    width
}

/// Figure 4, one goal: the tower to build (bottom first, cubes as coloured squares on
/// the table, labelled by number) and the remaining cubes of a scene with `cubes` cubes
/// (`cube_1` .. `cube_N`) on the table beside it.
pub fn goal_figure(goal: &Goal, cubes: usize) -> Figure {
    let size = 48.0;
    let height_cubes = goal.tower.len().max(1) as f64;
    let rest = others(&goal.tower, cubes).len() as f64;
    let panel = 16.0 + size + 2.0 * 12.0 + 8.0 + rest * (size + 12.0) + 16.0;
    let caption = format!(
        "Goal {}: a tower of {} cubes",
        goal.number,
        goal.tower.len()
    );
    let w = (panel + 60.0).max(text_width(&caption, 2) + 60.0);
    let table_y = 70.0 + height_cubes * size + 10.0;
    let h = table_y + 60.0;
    let mut fig = Figure::new(w as u32, h as u32, &caption);
    title(&mut fig, &caption);
    goal_panel(&mut fig, 30.0, table_y, goal, cubes, size);
    let bottom_first = format!("bottom first: {}", goal.tower.join(", "));
    let scale = if text_width(&bottom_first, 2) <= w - 20.0 {
        2
    } else {
        1
    };
    text(
        &mut fig,
        pt(30.0, table_y + 40.0),
        &bottom_first,
        scale,
        Anchor::Start,
        Color::GREY,
    );
    fig
}

/// Figure 4, all goals side by side, each with its tower and the remaining cubes.
pub fn goals_figure(goals: &[Goal], cubes: usize) -> Figure {
    let size = 36.0;
    let tallest = goals
        .iter()
        .map(|g| g.tower.len())
        .max()
        .unwrap_or(1)
        .max(1) as f64;
    let table_y = 84.0 + tallest * size;
    // Measure first on a scratch figure, then draw for real.
    let mut scratch = Figure::new(1, 1, "");
    let widths: Vec<f64> = goals
        .iter()
        .map(|g| goal_panel(&mut scratch, 0.0, table_y, g, cubes, size))
        .collect();
    let spacing = 24.0;
    let total: f64 = widths.iter().sum::<f64>() + spacing * (widths.len().max(1) as f64 - 1.0);
    let caption = format!("Planning goals: towers to build from {cubes} cubes on the table");
    let w = (total + 40.0).max(text_width(&caption, 2) + 40.0);
    let h = table_y + 46.0;
    let mut fig = Figure::new(w as u32, h as u32, &caption);
    title(&mut fig, &caption);
    let mut x = 20.0;
    for (g, width) in goals.iter().zip(&widths) {
        goal_panel(&mut fig, x, table_y, g, cubes, size);
        text(
            &mut fig,
            pt(x + width / 2.0, table_y + 34.0),
            &format!("goal {}", g.number),
            2,
            Anchor::Middle,
            INK,
        );
        x += width + spacing;
    }
    fig
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn log_scale_maps_decades_evenly() {
        let s = LogScale::covering(0.0004, 60.0, -3, 400.0, 0.0);
        assert_eq!((s.lo, s.hi), (-4, 3));
        assert!((s.map(1e-4) - 400.0).abs() < 1e-9);
        assert!((s.map(1000.0) - 0.0).abs() < 1e-9);
        let one = s.map(1.0);
        assert!((one - (400.0 - 400.0 * 4.0 / 7.0)).abs() < 1e-9);
        // One decade is always the same distance.
        assert!(((s.map(0.01) - s.map(0.1)) - (s.map(1.0) - s.map(10.0))).abs() < 1e-9);
        // Clamped outside, zero at the bottom.
        assert_eq!(s.map(0.0), 400.0);
        assert_eq!(s.map(1e9), 0.0);
        // The limit is never near the frame: at least half a decade below it.
        assert_eq!(LogScale::covering(0.01, 10.0, -3, 1.0, 0.0).hi, 2);
        assert_eq!(LogScale::covering(0.01, 30.0, -3, 1.0, 0.0).hi, 2);
        assert_eq!(LogScale::covering(0.01, 60.0, -3, 1.0, 0.0).hi, 3);
        assert_eq!(
            LogScale::covering(f64::INFINITY, 0.0, -3, 1.0, 0.0),
            LogScale {
                lo: -3,
                hi: -2,
                from: 1.0,
                to: 0.0
            }
        );
    }

    #[test]
    fn decade_labels_are_plain_numbers() {
        let labels: Vec<String> = (-5..=7).map(decade_label).collect();
        assert_eq!(
            labels,
            [
                "1e-5", "1e-4", "0.001", "0.01", "0.1", "1", "10", "100", "1000", "10000",
                "100000", "1000000", "1e7"
            ]
        );
    }

    #[test]
    fn nice_steps() {
        assert_eq!(nice_step(30.0, 6), 5.0);
        assert_eq!(nice_step(5.0, 6), 1.0);
        assert_eq!(nice_step(120.0, 6), 20.0);
    }

    #[test]
    fn other_cubes_exclude_the_tower() {
        let tower = vec!["cube_2".to_string(), "cube_1".to_string()];
        assert_eq!(others(&tower, 4), ["cube_3", "cube_4"]);
        assert_eq!(cube_label("cube_12"), "12");
        assert_eq!(cube_label("red"), "red");
        assert_eq!(cube_color("cube_1", 5), CUBE_COLORS[0]);
    }
}

/// One point of a [`ScalingSeries`]: the quartiles of a time over the seeds and
/// conditions of one tower height. `censored` says that a quartile is a bound (a run at
/// the time limit decided it): drawn as an open marker at the bound.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ScalingPoint {
    pub height: usize,
    pub q1: f64,
    pub median: f64,
    pub q3: f64,
    pub censored: bool,
}

/// One line of a scaling panel: e.g. `"priority 1"`, `"full"`, `"Algorithm 1"`.
#[derive(Debug, Clone, PartialEq)]
pub struct ScalingSeries {
    pub label: String,
    pub points: Vec<ScalingPoint>,
}

/// One panel of [`scaling_figure`]: one planner's series.
#[derive(Debug, Clone, PartialEq)]
pub struct ScalingPanel {
    pub title: String,
    pub series: Vec<ScalingSeries>,
}

/// The study's scaling figure: a time (`measure`) against tower height, one panel per
/// planner side by side, one line per series (the median, a light band from the first
/// to the third quartile), on a log axis shared by the panels. Censored medians are
/// open markers; the time limit is a dashed red line.
pub fn scaling_figure(
    title_text: &str,
    measure: Measure,
    panels: &[ScalingPanel],
    time_limit: f64,
) -> Figure {
    let panel_w = 360.0;
    let (left, top, bottom) = (100.0, 70.0, 430.0);
    let legend_w = 200.0;
    let n = panels.len().max(1) as f64;
    let w = (left + n * panel_w + legend_w) as u32;
    let h = 520u32;
    let mut fig = Figure::new(w, h, title_text);
    title(&mut fig, title_text);
    let values = panels
        .iter()
        .flat_map(|p| &p.series)
        .flat_map(|s| &s.points)
        .flat_map(|p| [p.q1, p.median, p.q3]);
    let (mut min, mut max) = (f64::INFINITY, time_limit);
    for v in values {
        if v > 0.0 && v.is_finite() {
            min = min.min(v);
            max = max.max(v);
        }
    }
    let y = LogScale::covering(min, max, -2, bottom, top);
    let heights: Vec<usize> = {
        let mut hs: Vec<usize> = panels
            .iter()
            .flat_map(|p| &p.series)
            .flat_map(|s| s.points.iter().map(|p| p.height))
            .collect();
        hs.sort_unstable();
        hs.dedup();
        hs
    };
    let (hmin, hmax) = (
        heights.first().copied().unwrap_or(1),
        heights.last().copied().unwrap_or(2),
    );
    let span = (hmax - hmin).max(1) as f64;
    for (i, panel) in panels.iter().enumerate() {
        let x0 = left + i as f64 * panel_w;
        let x1 = x0 + panel_w - 40.0;
        let gx = |height: usize| x0 + 20.0 + (height - hmin) as f64 / span * (x1 - x0 - 40.0);
        fig.rect(
            x0,
            top,
            x1 - x0,
            bottom - top,
            None,
            Some(Stroke::solid(GRID, 1.0)),
        );
        for k in y.decades() {
            let py = y.map(10f64.powi(k));
            fig.line(pt(x0, py), pt(x1, py), Stroke::solid(GRID, 1.0));
            if i == 0 {
                text(
                    &mut fig,
                    pt(x0 - 8.0, py + 5.0),
                    &decade_label(k),
                    2,
                    Anchor::End,
                    INK,
                );
            }
        }
        for &hh in &heights {
            text(
                &mut fig,
                pt(gx(hh), bottom + 24.0),
                &hh.to_string(),
                2,
                Anchor::Middle,
                INK,
            );
        }
        text(
            &mut fig,
            pt((x0 + x1) / 2.0, top - 10.0),
            &panel.title,
            2,
            Anchor::Middle,
            INK,
        );
        text(
            &mut fig,
            pt((x0 + x1) / 2.0, bottom + 50.0),
            "tower height (cubes)",
            2,
            Anchor::Middle,
            INK,
        );
        let ly = y.map(time_limit);
        fig.line(pt(x0, ly), pt(x1, ly), Stroke::dashed(LIMIT, 1.5, 6.0, 4.0));
        for (j, series) in panel.series.iter().enumerate() {
            let color = DOMAIN_COLORS[j % DOMAIN_COLORS.len()];
            let band = Color(
                ((u16::from(color.0) + 3 * 255) / 4) as u8,
                ((u16::from(color.1) + 3 * 255) / 4) as u8,
                ((u16::from(color.2) + 3 * 255) / 4) as u8,
            );
            let mut outline: Vec<Point> = series
                .points
                .iter()
                .map(|p| pt(gx(p.height), y.map(p.q3)))
                .collect();
            outline.extend(
                series
                    .points
                    .iter()
                    .rev()
                    .map(|p| pt(gx(p.height), y.map(p.q1))),
            );
            if series.points.len() > 1 {
                fig.polygon(outline, band);
            }
        }
        for (j, series) in panel.series.iter().enumerate() {
            let color = DOMAIN_COLORS[j % DOMAIN_COLORS.len()];
            let line: Vec<Point> = series
                .points
                .iter()
                .map(|p| pt(gx(p.height), y.map(p.median)))
                .collect();
            fig.polyline(line, Stroke::solid(color, 2.5));
            for p in &series.points {
                let at = pt(gx(p.height), y.map(p.median));
                if p.censored {
                    open_marker(&mut fig, at, color);
                } else {
                    dot_marker(&mut fig, at, color);
                }
            }
        }
    }
    vertical_label(
        &mut fig,
        26.0,
        (top + bottom) / 2.0,
        &format!("{} (s), log scale", measure.title().to_lowercase()),
    );
    // Legend: the series of the first panel (every panel has the same ones).
    let lx = left + n * panel_w;
    let mut row = top + 18.0;
    let labels: Vec<&str> = panels
        .first()
        .map(|p| p.series.iter().map(|s| s.label.as_str()).collect())
        .unwrap_or_default();
    for (j, label) in labels.iter().enumerate() {
        let color = DOMAIN_COLORS[j % DOMAIN_COLORS.len()];
        fig.line(
            pt(lx, row - 5.0),
            pt(lx + 30.0, row - 5.0),
            Stroke::solid(color, 2.5),
        );
        legend_label(&mut fig, lx, row, label);
        row += 26.0;
    }
    text(
        &mut fig,
        pt(lx, row + 10.0),
        "line: median",
        2,
        Anchor::Start,
        Color::GREY,
    );
    text(
        &mut fig,
        pt(lx, row + 34.0),
        "band: quartiles",
        2,
        Anchor::Start,
        Color::GREY,
    );
    text(
        &mut fig,
        pt(lx, row + 58.0),
        "open: a bound",
        2,
        Anchor::Start,
        Color::GREY,
    );
    text(
        &mut fig,
        pt(lx, row + 82.0),
        "dashed: limit",
        2,
        Anchor::Start,
        LIMIT,
    );
    fig
}

#[cfg(test)]
mod scaling_tests {
    use super::*;
    use crate::draw::Shape;

    #[test]
    fn the_scaling_figure_draws_a_band_and_a_line_per_series() {
        let point = |height, m: f64| ScalingPoint {
            height,
            q1: m / 2.0,
            median: m,
            q3: m * 2.0,
            censored: height == 4,
        };
        let panel = ScalingPanel {
            title: "demoplan astar(lmcut())".into(),
            series: vec![
                ScalingSeries {
                    label: "priority 1".into(),
                    points: vec![point(2, 0.01), point(3, 0.1), point(4, 1.0)],
                },
                ScalingSeries {
                    label: "full".into(),
                    points: vec![point(2, 0.02), point(3, 0.5), point(4, 20.0)],
                },
            ],
        };
        let fig = scaling_figure("Search time", Measure::Search, &[panel], 20.0);
        let bands = fig
            .shapes()
            .iter()
            .filter(|s| matches!(s, Shape::Polygon { .. }))
            .count();
        let lines = fig
            .shapes()
            .iter()
            .filter(|s| matches!(s, Shape::Polyline { .. }))
            .count();
        assert_eq!((bands, lines), (2, 2));
        let svg = fig.svg();
        assert!(svg.contains("<polygon"), "{svg}");
        assert!(svg.contains("tower height"));
        let png = fig.png().unwrap_or_else(|e| panic!("{e}"));
        assert!(png.starts_with(b"\x89PNG\r\n\x1a\n"));
    }
}
