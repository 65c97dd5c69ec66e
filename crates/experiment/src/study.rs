//! `demoplan study`: the slimming effect over seeds and conditions, as distributions.
//!
//! The grid is every seed x hands x distractors x height x towers x grouping x
//! (operators without effects dropped, and kept too when asked) x (specific operators,
//! and generalised ones too when asked) x planner x level,
//! where the levels are priority 1, the full domain and Algorithm 1. It is a grid
//! ([`crate::grid`]): each cell writes its result into its run folder as it finishes,
//! and a study run again on the same folder skips the cells already there.

use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::path::PathBuf;

use report::{html_escape, Bound, Measure, Ratio};

use crate::cell::{params_key, Cell, Conditions, LevelChoice, Planner};
use crate::grid::{named_option, GridExperiment, GridRun, GridSettings};
use crate::lab::Lab;
use crate::output::{condition_fields, create_dir, machine, write_png, write_text};
use crate::ratio::{quartiles, ratio, ratio_text, Quartiles};
use crate::record::RunRecord;
use crate::reproduce::{runs_csv_row, RUNS_HEADER};
use crate::{ExperimentError, Progress};

/// The most cubes a scene may hold (the cube world's table has room for them).
pub const MAX_CUBES: usize = 24;

/// What a study varies and how it runs.
#[derive(Debug, Clone)]
pub struct StudyOptions {
    pub out: PathBuf,
    pub seeds: Vec<u64>,
    pub participants: u32,
    pub per_participant: u32,
    pub hands: Vec<usize>,
    pub distractors: Vec<usize>,
    pub heights: Vec<usize>,
    pub towers: Vec<usize>,
    /// `settled`, `runs`.
    pub activities: Vec<String>,
    /// Also run every condition with operators that change nothing kept in the domains.
    pub keep_without_effects: bool,
    /// Also run every condition with the library's operators generalised
    /// (`learn --generalise`).
    pub generalise: bool,
    pub params: simulate::SimParams,
    /// How the cells run (limits, Fast Downward beside, processes).
    pub grid: GridSettings,
}

/// What a study varies, as its command line gives it (`demoplan study`): lists of
/// numbers as [`crate::numbers`] and [`crate::sizes`] read them, groupings by name.
/// With the `clap` feature these are its options, declared once here.
#[derive(Debug, Clone, PartialEq, Eq)]
#[cfg_attr(feature = "clap", derive(clap::Args))]
pub struct StudyConditionArgs {
    /// Seeds of the simulated studies: `1-20` (inclusive), `3`, or `1,4,9`.
    #[cfg_attr(
        feature = "clap",
        arg(long, value_name = "RANGE", default_value = "1-20")
    )]
    pub seeds: String,
    /// Simulated participants per study.
    #[cfg_attr(feature = "clap", arg(long, value_name = "N", default_value_t = 3))]
    pub participants: u32,
    /// Demonstrations per participant.
    #[cfg_attr(feature = "clap", arg(long, value_name = "N", default_value_t = 4))]
    pub per_participant: u32,
    /// Hands in the problems' scene, e.g. `1,2`.
    #[cfg_attr(
        feature = "clap",
        arg(long, value_name = "LIST", default_value = "1,2")
    )]
    pub hands: String,
    /// Cubes on the table beyond the towers', e.g. `0,2`.
    #[cfg_attr(feature = "clap", arg(long, value_name = "LIST", default_value = "0"))]
    pub distractors: String,
    /// Tower heights in cubes: `2-8` or a list.
    #[cfg_attr(
        feature = "clap",
        arg(long, value_name = "RANGE", default_value = "2-8")
    )]
    pub heights: String,
    /// Towers per goal, built from distinct cubes, e.g. `1,2`.
    #[cfg_attr(feature = "clap", arg(long, value_name = "LIST", default_value = "1"))]
    pub towers: String,
    /// How segments become activities: `settled`, `runs`, or both (`settled,runs`).
    #[cfg_attr(
        feature = "clap",
        arg(long, value_name = "LIST", default_value = "settled")
    )]
    pub activities: String,
    /// Also run every condition with operators that change nothing kept in the domains
    /// (they are dropped by default).
    #[cfg_attr(feature = "clap", arg(long))]
    pub keep_without_effects: bool,
    /// The simulated people's style: `paper` (one hand at a time) or `two-handed` (both
    /// hands at once, cut mid-motion, poses only); default: the parameters' (`paper`).
    #[cfg_attr(
        feature = "clap",
        arg(long, value_name = "NAME", value_parser = simulate::Style::parse)
    )]
    pub style: Option<simulate::Style>,
    /// Also run every condition with the library's operators generalised, as `learn
    /// --generalise` learns them (specific operators only by default).
    #[cfg_attr(feature = "clap", arg(long))]
    pub generalise: bool,
}

impl StudyConditionArgs {
    /// The study of these conditions, writing into `out`, with the simulator's `params`,
    /// its cells run with `grid`. A list that does not read is an
    /// [`ExperimentError::Options`] naming its option; [`study`] checks the values.
    pub fn options(
        &self,
        out: PathBuf,
        params: simulate::SimParams,
        grid: GridSettings,
    ) -> Result<StudyOptions, ExperimentError> {
        let sizes = |option: &str, text: &str| crate::sizes(text).map_err(named_option(option));
        // The style is the parameters' (`simulate::Style::params` and a `--params` file
        // make them); `--style` must agree with them.
        if let Some(style) = self.style {
            if style != params.style {
                return Err(ExperimentError::Options(format!(
                    "--style {style}: the simulator's parameters are of style {}",
                    params.style
                )));
            }
        }
        let mut activities: Vec<String> = (self.activities.split(','))
            .map(|a| a.trim().to_string())
            .collect();
        activities.dedup();
        Ok(StudyOptions {
            out,
            seeds: crate::numbers(&self.seeds).map_err(named_option("--seeds"))?,
            participants: self.participants,
            per_participant: self.per_participant,
            hands: sizes("--hands", &self.hands)?,
            distractors: sizes("--distractors", &self.distractors)?,
            heights: sizes("--heights", &self.heights)?,
            towers: sizes("--towers", &self.towers)?,
            activities,
            keep_without_effects: self.keep_without_effects,
            generalise: self.generalise,
            params,
            grid,
        })
    }
}

/// What a study did.
#[derive(Debug, Clone)]
pub struct StudyOutcome {
    /// Every cell's record, and what the grid computed now.
    pub grid: GridRun,
    pub report: PathBuf,
}

impl StudyOptions {
    /// The lab that computes the study's cells.
    fn lab(&self) -> Lab {
        self.grid.lab(self.params.clone())
    }

    fn check(&self) -> Result<(), ExperimentError> {
        let bad = |m: String| Err(ExperimentError::Options(m));
        let empty = [
            ("--seeds", self.seeds.is_empty()),
            ("--hands", self.hands.is_empty()),
            ("--distractors", self.distractors.is_empty()),
            ("--heights", self.heights.is_empty()),
            ("--towers", self.towers.is_empty()),
            ("--activities", self.activities.is_empty()),
        ];
        if let Some((name, _)) = empty.iter().find(|(_, e)| *e) {
            return bad(format!("{name}: give at least one value"));
        }
        if let Some(h) = self.hands.iter().find(|h| !(1..=2).contains(*h)) {
            return bad(format!("--hands: {h} hands; a scene has 1 or 2"));
        }
        if let Some(h) = self.heights.iter().find(|h| **h < 2) {
            return bad(format!(
                "--heights: a tower of {h} cube(s) is no stacking goal; give 2 or more"
            ));
        }
        if self.towers.contains(&0) {
            return bad("--towers: 0 towers is no goal; give 1 or more".into());
        }
        if let Some(a) = self
            .activities
            .iter()
            .find(|a| learn::Grouping::from_name(a).is_none())
        {
            return bad(format!("--activities: {a:?} is neither settled nor runs"));
        }
        if self.participants == 0 || self.per_participant == 0 {
            return bad("--participants and --per-participant must be at least 1".into());
        }
        if self.grid.time_limit.is_zero() {
            return bad("--time-limit must be more than 0".into());
        }
        let most = self.heights.iter().max().copied().unwrap_or(0)
            * self.towers.iter().max().copied().unwrap_or(0)
            + self.distractors.iter().max().copied().unwrap_or(0);
        if most > MAX_CUBES {
            return bad(format!(
                "height x towers + distractors reaches {most} cubes; the cube world holds \
                 at most {MAX_CUBES}"
            ));
        }
        Ok(())
    }
}

/// Every cell of a study, seed by seed (so that each seed's library is learned once
/// and its cells finish together).
pub fn study_grid(options: &StudyOptions) -> Vec<Cell> {
    let params = params_key(&options.params);
    let keeps: &[bool] = if options.keep_without_effects {
        &[false, true]
    } else {
        &[false]
    };
    let forms: &[bool] = if options.generalise {
        &[false, true]
    } else {
        &[false]
    };
    let mut cells = Vec::new();
    for &seed in &options.seeds {
        for activities in &options.activities {
            for (&keep, &generalised) in
                keeps.iter().flat_map(|k| forms.iter().map(move |g| (k, g)))
            {
                for &hands in &options.hands {
                    for &distractors in &options.distractors {
                        for &towers in &options.towers {
                            for &height in &options.heights {
                                let conditions = Conditions {
                                    seed,
                                    participants: options.participants,
                                    per_participant: options.per_participant,
                                    params: params.clone(),
                                    hands,
                                    height,
                                    towers,
                                    distractors,
                                    activities: activities.clone(),
                                    keep_without_effects: keep,
                                    generalised,
                                };
                                for planner in options.grid.planners() {
                                    for level in [
                                        LevelChoice::Prio(1),
                                        LevelChoice::Full,
                                        LevelChoice::Algorithm1,
                                    ] {
                                        cells.push(Cell {
                                            conditions: conditions.clone(),
                                            level,
                                            planner,
                                            time_limit: options.grid.time_limit,
                                            repeat: 0,
                                        });
                                    }
                                }
                            }
                        }
                    }
                }
            }
        }
    }
    cells
}

/// Runs a study (resuming from the results already in `options.out`) and writes
/// `results.jsonl`, `runs.csv`, `ratios.csv`, `scaling.svg`/`.png` (search time),
/// `scaling-total.svg`/`.png`, `study.json` and `report.html`.
pub fn study(
    options: &StudyOptions,
    progress: &mut dyn FnMut(Progress<'_>),
) -> Result<StudyOutcome, ExperimentError> {
    options.check()?;
    let out = &options.out;
    create_dir(out)?;
    let cells = study_grid(options);
    let mut lab = options.lab();
    let describe = |c: &Cell| {
        format!(
            "seed {} {} height {} {}",
            c.conditions.seed,
            c.planner.name(),
            c.conditions.height,
            c.level.name()
        )
    };
    let grid = options
        .grid
        .run_or_collect(&mut lab, &cells, out, progress, &describe)?;
    let records = &grid.records;

    write_text(&out.join("study.json"), &study_json(options, cells.len()))?;
    let mut runs = format!("{RUNS_HEADER},levels_tried\n");
    for r in records {
        let _ = writeln!(runs, "{},{}", runs_csv_row(r), r.widening.len());
    }
    write_text(&out.join("runs.csv"), &runs)?;
    let table = ratio_table(records);
    write_text(&out.join("ratios.csv"), &ratios_csv(&table))?;
    let mut figures = Vec::new();
    for (measure, name) in [
        (Measure::Search, "scaling"),
        (Measure::Total, "scaling-total"),
    ] {
        let panels = scaling_panels(records, measure);
        let figure = report::scaling_figure(
            &format!("{} against tower height", measure.title()),
            measure,
            &panels,
            options.grid.time_limit.as_secs_f64(),
        );
        write_text(&out.join(format!("{name}.svg")), &figure.svg())?;
        write_png(&out.join(format!("{name}.png")), &figure)?;
        figures.push((format!("{name}.svg"), format!("{name}.png"), measure));
    }
    let page = out.join("report.html");
    write_text(&page, &report_page(options, records, &table, &figures))?;
    Ok(StudyOutcome { grid, report: page })
}

/// The study's cells, in their order, once its options are checked (`--list-cells`).
pub fn study_cells(options: &StudyOptions) -> Result<Vec<Cell>, ExperimentError> {
    options.check()?;
    Ok(study_grid(options))
}

/// Computes one cell of the study, by id, in this process, into its run folder: what
/// each child process of a study run with [`StudyOptions::children`] (or a Slurm array
/// task) does. Algorithm 1 cells reuse the runs already in the study's folder.
pub fn study_cell(options: &StudyOptions, id: &str) -> Result<RunRecord, ExperimentError> {
    options.check()?;
    let cells = study_grid(options);
    options
        .grid
        .run_cell(&mut options.lab(), &cells, id, &options.out)
}

impl GridExperiment for StudyOptions {
    const NAME: &'static str = "study";
    fn settings(&self) -> &GridSettings {
        &self.grid
    }
    fn cells(&self) -> Result<Vec<Cell>, ExperimentError> {
        study_cells(self)
    }
    fn cell(&self, id: &str) -> Result<RunRecord, ExperimentError> {
        study_cell(self, id)
    }
}

fn study_json(options: &StudyOptions, cells: usize) -> String {
    let value = serde_json::json!({
        "format": "demoplan-study",
        "version": 1,
        "seeds": options.seeds,
        "participants": options.participants,
        "per_participant": options.per_participant,
        "hands": options.hands,
        "distractors": options.distractors,
        "heights": options.heights,
        "towers": options.towers,
        "activities": options.activities,
        "keep_without_effects": options.keep_without_effects,
        "generalise": options.generalise,
        "params": options.params.to_json(),
        "params_key": params_key(&options.params),
        "time_limit_s": options.grid.time_limit.as_secs_f64(),
        "with_fd": options.grid.fast_downward.is_some(),
        "cells": cells,
        "jobs": options.grid.at_once(),
        "machine": machine(),
    });
    let mut text = serde_json::to_string_pretty(&value).unwrap_or_default();
    text.push('\n');
    text
}

/// Which ratio.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
enum Which {
    P1,
    Alg1,
}

impl Which {
    fn name(self) -> &'static str {
        match self {
            Which::P1 => "ratio_p1",
            Which::Alg1 => "ratio_alg1",
        }
    }
}

/// One row of `ratios.csv`.
struct RatioRow {
    conditions: Conditions,
    planner: Planner,
    measure: Measure,
    which: Which,
    /// Seeds with no ratio (no plan on a level, or both at the limit).
    missing: usize,
    quartiles: Quartiles,
}

/// Per condition (without the seed), planner, measure and ratio: the quartiles over
/// seeds.
fn ratio_table(records: &[RunRecord]) -> Vec<RatioRow> {
    // (conditions without seed, planner's name, planner) -> seed -> level -> record; by
    // the planner's name, the order ratios.csv has always had.
    type Levels<'a> = BTreeMap<LevelChoice, &'a RunRecord>;
    type Key = (Conditions, &'static str, Planner);
    let mut groups: BTreeMap<Key, BTreeMap<u64, Levels<'_>>> = BTreeMap::new();
    for r in records {
        groups
            .entry((r.conditions.without_seed(), r.planner.name(), r.planner))
            .or_default()
            .entry(r.conditions.seed)
            .or_default()
            .insert(r.level, r);
    }
    let mut rows = Vec::new();
    for ((conditions, _, planner), seeds) in &groups {
        for measure in Measure::ALL {
            for which in [Which::P1, Which::Alg1] {
                let mut values = Vec::new();
                let mut missing = 0;
                for levels in seeds.values() {
                    let den = match which {
                        Which::P1 => levels.get(&LevelChoice::Prio(1)),
                        Which::Alg1 => levels.get(&LevelChoice::Algorithm1),
                    };
                    match (levels.get(&LevelChoice::Full), den) {
                        (Some(f), Some(d)) => match ratio(f, d, measure) {
                            Some(r) => values.push(r),
                            None => missing += 1,
                        },
                        _ => missing += 1,
                    }
                }
                rows.push(RatioRow {
                    conditions: conditions.clone(),
                    planner: *planner,
                    measure,
                    which,
                    missing,
                    quartiles: quartiles(&values),
                });
            }
        }
    }
    rows
}

fn ratios_csv(rows: &[RatioRow]) -> String {
    let mut s = String::from(
        "participants,per_participant,params,hands,height,towers,distractors,cubes,activities,keep_without_effects,generalised,planner,measure,ratio,seeds,bounds,missing,q1,median,q3\n",
    );
    for row in rows {
        let c = &row.conditions;
        let q = &row.quartiles;
        let _ = writeln!(
            s,
            "{},{},{},{},{},{},{},{},{},{}",
            condition_fields(c),
            row.planner,
            row.measure.name(),
            row.which.name(),
            q.n + row.missing,
            q.bounds,
            row.missing,
            ratio_text(q.q1),
            ratio_text(q.median),
            ratio_text(q.q3)
        );
    }
    s
}

/// Per planner, lines for priority 1, full and Algorithm 1: quartiles of the time over
/// every record of a height (all seeds and other conditions pooled). A run at the limit
/// counts as a lower bound; runs with no plan in their domain are left out.
fn scaling_panels(records: &[RunRecord], measure: Measure) -> Vec<report::ScalingPanel> {
    let mut planners: Vec<Planner> = records.iter().map(|r| r.planner).collect();
    planners.sort_unstable();
    planners.dedup();
    let mut heights: Vec<usize> = records.iter().map(|r| r.conditions.height).collect();
    heights.sort_unstable();
    heights.dedup();
    planners
        .iter()
        .map(|planner| {
            let series = [
                (LevelChoice::Prio(1), "priority 1"),
                (LevelChoice::Full, "full"),
                (LevelChoice::Algorithm1, "Algorithm 1"),
            ]
            .iter()
            .map(|(level, label)| report::ScalingSeries {
                label: label.to_string(),
                points: heights
                    .iter()
                    .filter_map(|&h| {
                        let times: Vec<Ratio> = records
                            .iter()
                            .filter(|r| {
                                r.planner == *planner
                                    && r.level == *level
                                    && r.conditions.height == h
                            })
                            .filter_map(|r| r.time(measure))
                            .map(|(value, bound)| Ratio { value, bound })
                            .collect();
                        let q = quartiles(&times);
                        let median = q.median?;
                        let v = |r: Option<Ratio>| r.map_or(median.value, |r| r.value);
                        Some(report::ScalingPoint {
                            height: h,
                            q1: v(q.q1),
                            median: median.value,
                            q3: v(q.q3),
                            censored: median.bound != Bound::Exact,
                        })
                    })
                    .collect(),
            })
            .collect();
            report::ScalingPanel {
                title: planner.label().to_string(),
                series,
            }
        })
        .collect()
}

const STYLE: &str = "body { font-family: system-ui, sans-serif; max-width: 1100px; margin: 2em auto; padding: 0 1em; line-height: 1.45; }
table { border-collapse: collapse; margin: 1em 0; font-size: 0.92em; }
th, td { border: 1px solid #ccc; padding: 0.2em 0.5em; }
th { background: #f3f3f3; }
td.num { text-align: right; font-variant-numeric: tabular-nums; }
figure img { max-width: 100%; border: 1px solid #eee; }
code { background: #f3f3f3; padding: 0 0.2em; }";

fn report_page(
    options: &StudyOptions,
    records: &[RunRecord],
    table: &[RatioRow],
    figures: &[(String, String, Measure)],
) -> String {
    let mut s = String::new();
    let _ = writeln!(
        s,
        "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>demoplan \
         study: when does slimming pay off?</title>\n<style>{STYLE}</style>\n</head>\n<body>\n\
         <h1>When does slimming pay off?</h1>"
    );
    let seeds = match (options.seeds.first(), options.seeds.last()) {
        (Some(a), Some(b)) if options.seeds.len() > 1 => {
            format!("{} seeds ({a} to {b})", options.seeds.len())
        }
        (Some(a), _) => format!("seed {a}"),
        _ => String::new(),
    };
    let _ = writeln!(
        s,
        "<p>{} planning runs on {}: {} participants x {} demonstrations each; hands {:?}; \
         tower heights {:?}; towers {:?}; distractor cubes {:?}; activities {:?}; operators \
         without effects {}; operators {}; {} s per run; machine {}. Written by <code>demoplan study</code>; \
         every file is described in <code>docs/study.md</code>.</p>",
        records.len(),
        html_escape(&seeds),
        options.participants,
        options.per_participant,
        options.hands,
        options.heights,
        options.towers,
        options.distractors,
        options.activities,
        if options.keep_without_effects {
            "dropped and kept"
        } else {
            "dropped"
        },
        if options.generalise {
            "specific and generalised"
        } else {
            "specific"
        },
        report::format_limit(options.grid.time_limit.as_secs_f64()),
        html_escape(&format!(
            "{}; {} run(s) at once",
            machine(),
            options.grid.at_once()
        ))
    );
    s.push_str(
        "<p><code>ratio_p1</code> is the full domain's time over priority 1's, \
         <code>ratio_alg1</code> the full domain's time over Algorithm 1's cumulative time \
         (failed levels included), per seed; the table gives their quartiles over seeds. \
         <code>&gt;=</code> marks a lower bound (runs at the time limit), <code>&lt;=</code> \
         an upper bound; a quartile that falls on such runs is itself a bound. The paper: 72 \
         (iPDB) and 120 (LM-cut), search time, one library.</p>\n",
    );
    for (svg, png, measure) in figures {
        let _ = writeln!(
            s,
            "<figure><a href=\"{svg}\"><img src=\"{svg}\" alt=\"{t}\"></a><figcaption>{t} \
             against tower height: median and quartiles over seeds (<a href=\"{svg}\">SVG</a>, \
             <a href=\"{png}\">PNG</a>).</figcaption></figure>",
            t = measure.title()
        );
    }
    s.push_str("<h2>Ratios</h2>\n<table>\n<tr><th>hands</th><th>height</th><th>towers</th><th>distractors</th><th>activities</th><th>without effects</th><th>operators</th><th>planner</th><th>measure</th><th>ratio</th><th>seeds</th><th>bounds</th><th>no ratio</th><th>q1</th><th>median</th><th>q3</th></tr>\n");
    for row in table {
        let c = &row.conditions;
        let q = &row.quartiles;
        let show = |r: Option<Ratio>| r.map_or("-".to_string(), |r| r.to_string());
        let _ = writeln!(
            s,
            "<tr><td class=\"num\">{}</td><td class=\"num\">{}</td><td class=\"num\">{}</td><td class=\"num\">{}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td class=\"num\">{}</td><td class=\"num\">{}</td><td class=\"num\">{}</td><td class=\"num\">{}</td><td class=\"num\">{}</td><td class=\"num\">{}</td></tr>",
            c.hands,
            c.height,
            c.towers,
            c.distractors,
            html_escape(&c.activities),
            if c.keep_without_effects { "kept" } else { "dropped" },
            if c.generalised { "generalised" } else { "specific" },
            html_escape(row.planner.label()),
            row.measure.name(),
            row.which.name(),
            q.n + row.missing,
            q.bounds,
            row.missing,
            html_escape(&show(q.q1)),
            html_escape(&show(q.median)),
            html_escape(&show(q.q3))
        );
    }
    s.push_str("</table>\n");
    // Where priority 1 cannot plan: Algorithm 1's widening.
    let widened: Vec<&RunRecord> = records
        .iter()
        .filter(|r| r.level == LevelChoice::Algorithm1 && r.widening.len() > 1)
        .collect();
    s.push_str("<h2>Where priority 1 cannot plan: Algorithm 1 widens</h2>\n");
    if widened.is_empty() {
        s.push_str("<p>In every condition of this study, priority 1 planned (or Algorithm 1 stopped there).</p>\n");
    } else {
        let _ = writeln!(
            s,
            "<p>{} runs of Algorithm 1 went past priority 1. Each line: the levels tried, \
             their outcome and total time, and the cumulative time, which the paper's argument \
             counts against slimming.</p>\n<table>\n<tr><th>seed</th><th>activities</th><th>without effects</th><th>hands</th><th>height</th><th>towers</th><th>distractors</th><th>planner</th><th>levels tried</th><th>outcome</th><th>cumulative search (s)</th><th>cumulative total (s)</th></tr>",
            widened.len()
        );
        for r in widened {
            let c = &r.conditions;
            let tried: Vec<String> = r
                .widening
                .iter()
                .map(|w| {
                    format!(
                        "{} ({} ops): {} {} s",
                        w.prio,
                        w.operators,
                        w.outcome,
                        report::format_seconds(w.times.total_s)
                    )
                })
                .collect();
            let _ = writeln!(
                s,
                "<tr><td class=\"num\">{}</td><td>{}</td><td>{}</td><td class=\"num\">{}</td><td class=\"num\">{}</td><td class=\"num\">{}</td><td class=\"num\">{}</td><td>{}</td><td>{}</td><td>{}</td><td class=\"num\">{}</td><td class=\"num\">{}</td></tr>",
                c.seed,
                html_escape(&c.activities),
                if c.keep_without_effects { "kept" } else { "dropped" },
                c.hands,
                c.height,
                c.towers,
                c.distractors,
                html_escape(r.planner.label()),
                html_escape(&tried.join("; ")),
                r.outcome,
                report::format_seconds(r.times.search_s),
                report::format_seconds(r.times.total_s)
            );
        }
        s.push_str("</table>\n");
    }
    let solved = records.iter().filter(|r| r.solved()).count();
    let failed = records.iter().filter(|r| r.executed == Some(false)).count();
    let _ = writeln!(
        s,
        "<h2>Execution check</h2>\n<p>{solved} runs found a plan; every plan was executed in \
         the cube world; {failed} failed the check.</p>"
    );
    s.push_str("<h2>Files</h2>\n<ul>\n<li><a href=\"runs.csv\">runs.csv</a>: every run, with its conditions and four times</li>\n<li><a href=\"ratios.csv\">ratios.csv</a>: quartiles of the ratios per condition, planner and measure</li>\n<li><a href=\"results.jsonl\">results.jsonl</a>: every cell's record, one JSON line each (the study resumes from it)</li>\n<li><a href=\"study.json\">study.json</a>: the options</li>\n</ul>\n</body>\n</html>\n");
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    fn conditions(style: Option<&str>) -> StudyConditionArgs {
        StudyConditionArgs {
            seeds: "1".into(),
            participants: 3,
            per_participant: 4,
            hands: "1".into(),
            distractors: "0".into(),
            heights: "2".into(),
            towers: "1".into(),
            activities: "settled".into(),
            keep_without_effects: false,
            style: style.and_then(simulate::Style::from_name),
            generalise: false,
        }
    }

    /// `--style` must name a style and agree with the parameters; the cells of a style's
    /// own parameters carry its name, the default's stay `default`.
    #[test]
    fn the_style_names_agree_with_the_parameters() {
        let grid = || GridSettings::in_process(std::time::Duration::from_secs(1));
        let two = simulate::Style::TwoHanded.params();
        let options =
            (conditions(Some("two-handed")).options("out".into(), two.clone(), grid())).unwrap();
        assert!(study_grid(&options)
            .iter()
            .all(|c| c.conditions.params == "two-handed"));
        let default = (conditions(None).options("out".into(), Default::default(), grid())).unwrap();
        assert!(study_grid(&default)
            .iter()
            .all(|c| c.conditions.params == "default"));
        for (style, params) in [
            (Some("two-handed"), simulate::SimParams::default()),
            (Some("paper"), two),
        ] {
            let e = (conditions(style).options("out".into(), params, grid())).unwrap_err();
            assert!(e.to_string().contains("--style"), "{e}");
        }
    }
}
