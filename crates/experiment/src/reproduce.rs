//! The paper's experiment in one call: simulate the demonstrations, learn the library,
//! build every priority domain, plan the five goals on each with iPDB and LM-cut (and
//! Algorithm 1 beside them), check the plans by execution, and write tables, data,
//! figures and a report page.

use std::fmt::Write as _;
use std::path::PathBuf;

use learn::{levels, per_type, DomainOptions};
use report::Measure;
use slim::Outcome;

use crate::cell::{Cell, Conditions, LevelChoice, Planner};
use crate::findings::{findings, median_record};
use crate::grid::{GridExperiment, GridRun, GridSettings};
use crate::lab::{tower_problem, towers, Lab};
use crate::output::{condition_fields, create_dir, machine, opt, write_png, write_text};
use crate::ratio::ratio;
use crate::record::RunRecord;
use crate::{ExperimentError, Progress};

/// What `reproduce` runs.
#[derive(Debug, Clone)]
pub struct ReproduceOptions {
    /// The output folder (created if missing).
    pub out: PathBuf,
    /// Runs per cell; tables show the median by search time.
    pub repeat: u32,
    /// The paper's goals to plan, 1 to 5.
    pub goals: Vec<usize>,
    /// Only these priority levels (`None`: every level).
    pub prios: Option<Vec<usize>>,
    /// The simulator's seed.
    pub seed: u64,
    /// Hands in the problems' scene.
    pub hands: usize,
    /// How the cells run (limits, Fast Downward beside, processes).
    pub grid: GridSettings,
}

/// What `reproduce` did.
#[derive(Debug, Clone)]
pub struct Reproduction {
    /// The library's summary and the domains, for people.
    pub summary: String,
    /// `tables.md`.
    pub tables: String,
    /// Every run's record, and what the grid computed now.
    pub grid: GridRun,
    /// The report page.
    pub report: PathBuf,
}

/// The grid: every planner x level (of `prios`) x goal x repeat, then Algorithm 1 per
/// planner and goal (its widening gives ratio_alg1).
fn reproduce_grid(options: &ReproduceOptions, prios: &[usize]) -> Vec<Cell> {
    let mut cells = Vec::new();
    for planner in options.grid.planners() {
        for &prio in prios {
            for &g in &options.goals {
                for repeat in 0..options.repeat {
                    cells.push(Cell {
                        conditions: Conditions::paper_goal(options.seed, g, options.hands),
                        level: LevelChoice::Prio(prio),
                        planner,
                        time_limit: options.grid.time_limit,
                        repeat,
                    });
                }
            }
        }
        for &g in &options.goals {
            cells.push(Cell {
                conditions: Conditions::paper_goal(options.seed, g, options.hands),
                level: LevelChoice::Algorithm1,
                planner,
                time_limit: options.grid.time_limit,
                repeat: 0,
            });
        }
    }
    cells
}

/// The lab of a reproduction and its one library (seed 7's by default), learned once.
fn lab_and_library(options: &ReproduceOptions) -> Result<(Lab, learn::Library), ExperimentError> {
    let mut lab = options.grid.lab(simulate::SimParams::default());
    let base = Conditions::paper_goal(options.seed, 1, options.hands);
    let library = lab.library(&base)?.clone();
    Ok((lab, library))
}

/// The lab and the grid's cells (the levels come from the library it learns).
fn lab_and_cells(options: &ReproduceOptions) -> Result<(Lab, Vec<Cell>), ExperimentError> {
    let (lab, library) = lab_and_library(options)?;
    let prios: Vec<usize> = levels(&library, DomainOptions::default())
        .iter()
        .map(|l| l.prio)
        .filter(|p| {
            options
                .prios
                .as_ref()
                .is_none_or(|chosen| chosen.contains(p))
        })
        .collect();
    Ok((lab, reproduce_grid(options, &prios)))
}

/// The reproduction's cells, in their order (`--list-cells`; [`crate::grid::cell_list`]).
pub fn reproduce_cells(options: &ReproduceOptions) -> Result<Vec<Cell>, ExperimentError> {
    Ok(lab_and_cells(options)?.1)
}

/// Computes one cell of the reproduction, by id, in this process: what each child
/// process of a reproduction run with [`ReproduceOptions::children`] does.
pub fn reproduce_cell(options: &ReproduceOptions, id: &str) -> Result<RunRecord, ExperimentError> {
    let (mut lab, cells) = lab_and_cells(options)?;
    options.grid.run_cell(&mut lab, &cells, id, &options.out)
}

impl GridExperiment for ReproduceOptions {
    const NAME: &'static str = "reproduce";
    fn settings(&self) -> &GridSettings {
        &self.grid
    }
    fn cells(&self) -> Result<Vec<Cell>, ExperimentError> {
        reproduce_cells(self)
    }
    fn cell(&self, id: &str) -> Result<RunRecord, ExperimentError> {
        reproduce_cell(self, id)
    }
}

/// The paper's goal of a record (its tower's height less one).
fn goal(r: &RunRecord) -> usize {
    r.conditions.height.saturating_sub(1)
}

/// Runs the paper's grid and writes its files into `options.out`.
pub fn reproduce(
    options: &ReproduceOptions,
    progress: &mut dyn FnMut(Progress<'_>),
) -> Result<Reproduction, ExperimentError> {
    for g in &options.goals {
        if !(1..=5).contains(g) {
            return Err(ExperimentError::Options(format!(
                "--goals: goal {g} does not exist (the paper has goals 1 to 5)"
            )));
        }
    }
    if options.goals.is_empty() || options.repeat == 0 {
        return Err(ExperimentError::Options(
            "--goals and --repeat need at least one".into(),
        ));
    }
    let (mut lab, library) = lab_and_library(options)?;
    let all_levels = levels(&library, DomainOptions::default());
    let chosen: Vec<&learn::Level<'_>> = all_levels
        .iter()
        .filter(|l| options.prios.as_ref().is_none_or(|p| p.contains(&l.prio)))
        .collect();
    if chosen.is_empty() {
        return Err(ExperimentError::Options(format!(
            "--prios matches no level; the levels are {}",
            all_levels
                .iter()
                .map(|l| l.prio.to_string())
                .collect::<Vec<_>>()
                .join(", ")
        )));
    }
    let out = &options.out;
    for sub in ["", "domains", "problems", "plans", "figures"] {
        create_dir(&out.join(sub))?;
    }
    write_text(&out.join("library.json"), &library.to_json())?;
    write_text(&out.join("operators.md"), &learn::cards_markdown(&library))?;
    let mut summary = format!(
        "Learned {} operators from {} activities of {} simulated demonstrations (seed {}):\n{}",
        library.len(),
        library.segments(),
        library.recordings().count(),
        options.seed,
        learn::summary_table(&library)
    );
    for l in &chosen {
        write_text(
            &out.join(format!("domains/prio-{}.pddl", l.prio)),
            &learn::domain_text(&library, &l.operators, &format!("priority {}", l.prio)),
        )?;
    }
    let _ = writeln!(
        summary,
        "Domains: {}",
        chosen
            .iter()
            .map(|l| format!("priority {} ({} operators)", l.prio, l.operators.len()))
            .collect::<Vec<_>>()
            .join(", ")
    );
    let mut problems = Vec::new();
    for &g in &options.goals {
        let conditions = Conditions::paper_goal(options.seed, g, options.hands);
        let tower = towers(&conditions).concat();
        let p = tower_problem(&conditions)?;
        write_text(
            &out.join(format!("problems/goal-{g}.pddl")),
            &format!(
                "; the paper's goal {g}, reconstructed: a tower of {} cubes, bottom first: {}\n{p}",
                tower.len(),
                tower.join(", ")
            ),
        )?;
        problems.push((g, tower, p));
    }

    let prios: Vec<usize> = chosen.iter().map(|l| l.prio).collect();
    let cells = reproduce_grid(options, &prios);
    let describe = |c: &Cell| {
        format!(
            "{} {} goal {}",
            c.planner.name(),
            c.level.name(),
            c.conditions.height - 1
        )
    };
    // A grid: each cell writes its run folder as it finishes; cells already there are
    // reused unless forced.
    let grid = options
        .grid
        .run_or_collect(&mut lab, &cells, out, progress, &describe)?;
    let records = &grid.records;

    // Results.
    for r in records.iter().filter(|r| r.solved() && r.repeat == 0) {
        if r.level == LevelChoice::Algorithm1 {
            continue;
        }
        let Some(cost) = r.cost else { continue };
        let kind = if r.unit_cost {
            pddl::CostKind::Unit
        } else {
            pddl::CostKind::General
        };
        let text = pddl::write_plan(&r.plan, cost, kind);
        write_text(
            &out.join(format!(
                "plans/{}-prio-{}-goal-{}.plan",
                r.planner,
                r.prio,
                goal(r)
            )),
            &text,
        )?;
    }
    let complete = chosen.len() == all_levels.len();
    let mut notes = findings(records);
    if !complete {
        notes.push(
            "The grid leaves out some levels (--prios): its largest domain is not the full \
             domain."
                .to_string(),
        );
    }
    notes.extend(ground_actions(&chosen, &problems));
    let experiment = experiment(records, &all_levels, &problems, options, &notes);
    let tables = tables_markdown(&experiment, records, options, &notes);
    write_text(&out.join("tables.md"), &tables)?;
    write_text(&out.join("results.csv"), &results_csv(records))?;
    write_text(
        &out.join("results.json"),
        &results_json(records, options, &notes),
    )?;
    let mut artefacts: Vec<(String, String)> = Vec::new();
    for planner in experiment.planners() {
        for measure in Measure::ALL {
            let figure = report::time_figure(&experiment, planner, measure);
            let base = format!("figures/{}-time-{planner}", measure.name());
            write_text(&out.join(format!("{base}.svg")), &figure.svg())?;
            write_png(&out.join(format!("{base}.png")), &figure)?;
            artefacts.push((
                format!("{base}.svg"),
                format!(
                    "{} per goal and domain, {} (as the paper's Figures 5 and 6)",
                    measure.title(),
                    planner.label()
                ),
            ));
        }
    }
    let figure = report::operators_figure(&experiment.levels);
    write_text(&out.join("figures/operators.svg"), &figure.svg())?;
    write_png(&out.join("figures/operators.png"), &figure)?;
    artefacts.push((
        "figures/operators.svg".into(),
        "Operators per type and priority (as the paper's Figure 3)".into(),
    ));
    for goal in &experiment.goals {
        let figure = report::goal_figure(goal, learn::DEFAULT_CUBES);
        let base = format!("figures/goal-{}", goal.number);
        write_text(&out.join(format!("{base}.svg")), &figure.svg())?;
        write_png(&out.join(format!("{base}.png")), &figure)?;
        artefacts.push((
            format!("{base}.svg"),
            format!("Goal {} (as the paper's Figure 4)", goal.number),
        ));
    }
    for (file, caption) in [
        (
            "tables.md",
            "Search and total times as the paper's Tables 3 and 4, the time split and the ratios",
        ),
        ("results.csv", "Every run, as CSV"),
        ("results.json", "Every run, as JSON"),
        ("results.jsonl", "Every run's record, one JSON line each"),
        ("operators.md", "Operator cards (as the paper's Figure 2)"),
        ("library.json", "The operator library"),
    ] {
        artefacts.push((file.into(), caption.into()));
    }
    let page = out.join("report.html");
    write_text(&page, &report::report_html(&experiment, &artefacts))?;
    Ok(Reproduction {
        summary,
        tables,
        grid,
        report: page,
    })
}

/// How many ground actions each domain gives the largest goal (the search's
/// branching).
fn ground_actions(
    chosen: &[&learn::Level<'_>],
    problems: &[(usize, Vec<String>, pddl::Problem)],
) -> Vec<String> {
    let Some((goal, _, problem)) = problems.iter().max_by_key(|p| p.0) else {
        return Vec::new();
    };
    let sizes: Vec<String> = chosen
        .iter()
        .map(|l| {
            let d = learn::domain("demoplan", &l.operators);
            match slim::translate_checked(&d, problem) {
                slim::Translated::Task(task, _) => format!(
                    "priority {} ({} operators): {}",
                    l.prio,
                    l.operators.len(),
                    task.operators.len()
                ),
                slim::Translated::Done(_) => format!(
                    "priority {} ({} operators): none (unreachable)",
                    l.prio,
                    l.operators.len()
                ),
            }
        })
        .collect();
    vec![format!(
        "Ground actions after translation for goal {goal}: {}.",
        sizes.join("; ")
    )]
}

/// How a run shows in the report: "unsolvable" whether relaxed reachability or the
/// search proved it, "> limit" for either limit.
fn report_outcome(r: &RunRecord) -> report::Outcome {
    match r.outcome {
        Outcome::Solved => report::Outcome::Solved,
        Outcome::RelaxedUnreachable | Outcome::Unsolvable => report::Outcome::Unsolvable,
        Outcome::TimeLimit | Outcome::MemoryLimit => report::Outcome::Limit,
        // A run cancelled before its end has no result, as one that failed.
        Outcome::Cancelled | Outcome::Error => report::Outcome::Error,
    }
}

/// The medians over repeats of the priority levels' runs, as the report crate reads
/// them.
fn experiment(
    records: &[RunRecord],
    all_levels: &[learn::Level<'_>],
    problems: &[(usize, Vec<String>, pddl::Problem)],
    options: &ReproduceOptions,
    notes: &[String],
) -> report::Experiment {
    let mut keys: Vec<(Planner, usize, usize)> = records
        .iter()
        .filter(|r| matches!(r.level, LevelChoice::Prio(_)))
        .map(|r| (r.planner, r.prio, goal(r)))
        .collect();
    keys.dedup();
    let runs = keys
        .iter()
        .filter_map(|(planner, prio, g)| {
            let group: Vec<&RunRecord> = records
                .iter()
                .filter(|r| {
                    r.planner == *planner
                        && r.prio == *prio
                        && goal(r) == *g
                        && matches!(r.level, LevelChoice::Prio(_))
                })
                .collect();
            let m = median_record(&group)?;
            Some(report::Run {
                planner: *planner,
                prio: *prio,
                operators: m.operators,
                goal: *g,
                outcome: report_outcome(m),
                search_time: m.times.search_s,
                total_time: m.times.total_s,
                times: group.iter().map(|r| r.times.search_s).collect(),
                expansions: m.expansions,
                cost: m.cost,
                length: m.length,
                executed: m.executed,
            })
        })
        .collect();
    report::Experiment {
        runs,
        levels: all_levels
            .iter()
            .map(|l| report::Level {
                prio: l.prio,
                operators: l.operators.len(),
                per_type: per_type(&l.operators),
            })
            .collect(),
        goals: problems
            .iter()
            .map(|(g, tower, _)| report::Goal {
                number: *g,
                tower: tower.clone(),
            })
            .collect(),
        time_limit: options.grid.time_limit.as_secs_f64(),
        repeat: options.repeat as usize,
        seed: options.seed,
        // Parallel timings are noisier: the report says how many ran at once.
        machine: format!("{}; {} run(s) at once", machine(), options.grid.at_once()),
        versions: format!(
            "demoplan {}; Fast Downward {}",
            env!("CARGO_PKG_VERSION"),
            if options.grid.fast_downward.is_some() {
                "as installed (see --fd)"
            } else {
                "not run"
            }
        ),
        notes: notes.to_vec(),
        cubes: learn::DEFAULT_CUBES,
        hands: options.hands,
    }
}

fn table_title(planner: Planner) -> String {
    match planner {
        Planner::Ipdb => "Table 3: A* with iPDB (demoplan)".to_string(),
        Planner::Lmcut => "Table 4: A* with LM-cut (demoplan)".to_string(),
        Planner::FdIpdb | Planner::FdLmcut => {
            format!("{}, beside {}", planner.label(), planner.paper_table())
        }
    }
}

/// `tables.md`: per planner the paper's table by search time and by total time, the
/// four times of every run of the largest goal, the ratios, plan costs and findings.
fn tables_markdown(
    exp: &report::Experiment,
    records: &[RunRecord],
    options: &ReproduceOptions,
    notes: &[String],
) -> String {
    let limit = report::format_limit(options.grid.time_limit.as_secs_f64());
    let mut s = String::from("# Search time and total time per domain and goal\n\n");
    let _ = writeln!(
        s,
        "Seconds{}; `> limit` hit the {limit} s limit, `unsolvable` includes goals rejected \
         by relaxed reachability before search. *Search time* is the search proper, as Fast \
         Downward prints it and the paper's tables report it; *total time* adds translation \
         and heuristic construction (iPDB's hill climbing). The last row divides the largest \
         domain's time by the smallest's.\n",
        if options.repeat > 1 {
            ", median over repeats by search time"
        } else {
            ""
        }
    );
    for planner in exp.planners() {
        for measure in Measure::ALL {
            let _ = writeln!(
                s,
                "## {}, {}\n",
                table_title(planner),
                measure.title().to_lowercase()
            );
            s.push_str(&report::time_table(exp, planner, measure).to_markdown());
            s.push('\n');
        }
    }
    let tallest = records.iter().map(goal).max().unwrap_or(0);
    let _ = writeln!(
        s,
        "## Time by phase, goal {tallest}\n\nSeconds: translate (parse and translate; Fast \
         Downward: its translator's wall-clock time), heuristic (construction; Fast Downward: \
         total minus search time), search, total (the whole run; Fast Downward: the whole \
         process tree). Peak memory: demoplan's peak heap, Fast Downward's peak resident set.\n"
    );
    s.push_str("| planner | level | operators | outcome | translate | heuristic | search | total | expansions | peak memory (KB) |\n|:---|:---|---:|:---|---:|---:|---:|---:|---:|---:|\n");
    for r in records
        .iter()
        .filter(|r| goal(r) == tallest && r.repeat == 0)
    {
        let level = match r.level {
            LevelChoice::Algorithm1 => format!("Algorithm 1 (planned at {})", r.prio),
            _ => format!("priority {}", r.prio),
        };
        let _ = writeln!(
            s,
            "| {} | {level} | {} | {} | {} | {} | {} | {} | {} | {} |",
            r.planner.label(),
            r.operators,
            r.outcome,
            report::format_seconds(r.times.translate_s),
            report::format_seconds(r.times.heuristic_s),
            report::format_seconds(r.times.search_s),
            report::format_seconds(r.times.total_s),
            opt(r.expansions),
            opt(r.peak_memory_kb)
        );
    }
    s.push('\n');
    let _ = writeln!(
        s,
        "## Slimming ratios\n\n`ratio_p1`: the largest domain's time over priority 1's; \
         `ratio_alg1`: over Algorithm 1's cumulative time (failed levels included). `>=` is a \
         lower bound (the numerator hit the limit), `<=` an upper bound. The paper, goal 5, \
         search time: {:.0} (iPDB) and {:.0} (LM-cut).\n",
        crate::paper::RATIO_IPDB,
        crate::paper::RATIO_LMCUT
    );
    s.push_str("| planner | goal | ratio_p1 search | ratio_p1 total | ratio_alg1 search | ratio_alg1 total |\n|:---|---:|---:|---:|---:|---:|\n");
    for planner in exp.planners() {
        for &g in &exp.goal_numbers() {
            let pick = |f: &dyn Fn(&RunRecord) -> bool| {
                let group: Vec<&RunRecord> = records
                    .iter()
                    .filter(|r| r.planner == planner && goal(r) == g && f(r))
                    .collect();
                median_record(&group)
            };
            let largest = records
                .iter()
                .filter(|r| matches!(r.level, LevelChoice::Prio(_)))
                .map(|r| r.prio)
                .max()
                .unwrap_or(0);
            let full = pick(&|r| matches!(r.level, LevelChoice::Prio(_)) && r.prio == largest);
            let p1 = pick(&|r| r.level == LevelChoice::Prio(1));
            let alg1 = pick(&|r| r.level == LevelChoice::Algorithm1);
            let cell = |den: Option<&RunRecord>, m: Measure| match (full, den) {
                (Some(f), Some(d)) if f.prio != d.prio || d.level == LevelChoice::Algorithm1 => {
                    ratio(f, d, m).map_or("-".to_string(), |r| r.to_string())
                }
                _ => "-".to_string(),
            };
            let _ = writeln!(
                s,
                "| {} | {g} | {} | {} | {} | {} |",
                planner.label(),
                cell(p1, Measure::Search),
                cell(p1, Measure::Total),
                cell(alg1, Measure::Search),
                cell(alg1, Measure::Total)
            );
        }
    }
    let _ = writeln!(s, "\n## Plan cost per domain and goal (LM-cut)\n");
    let mut header = String::from("| domain |");
    let mut rule = String::from("|---|");
    for g in exp.goal_numbers() {
        let _ = write!(header, " goal {g} |");
        rule.push_str("---|");
    }
    let _ = writeln!(s, "{header}\n{rule}");
    for (prio, _) in exp.domains() {
        let mut row = format!("| priority {prio} |");
        for g in exp.goal_numbers() {
            let cost = exp
                .run(Planner::Lmcut, prio, g)
                .and_then(|r| r.cost)
                .map_or("-".to_string(), |c| c.to_string());
            let _ = write!(row, " {cost} |");
        }
        let _ = writeln!(s, "{row}");
    }
    if !notes.is_empty() {
        let _ = writeln!(s, "\n## Findings\n");
        for n in notes {
            let _ = writeln!(s, "- {n}");
        }
    }
    s
}

/// The columns of `results.csv` and `runs.csv`: conditions, level, planner, outcome,
/// the four times and the counts.
pub(crate) const RUNS_HEADER: &str = "id,seed,participants,per_participant,params,hands,height,towers,distractors,cubes,activities,keep_without_effects,generalised,level,prio,operators,planner,time_limit_s,repeat,outcome,translate_s,heuristic_s,search_s,total_s,expansions,generated,cost,length,peak_memory_kb,executed";

pub(crate) fn runs_csv_row(r: &RunRecord) -> String {
    let c = &r.conditions;
    format!(
        "{},{},{},{},{},{},{},{},{},{},{:.6},{:.6},{:.6},{:.6},{},{},{},{},{},{}",
        r.id,
        c.seed,
        condition_fields(c),
        r.level,
        r.prio,
        r.operators,
        r.planner,
        r.time_limit_s,
        r.repeat,
        r.outcome,
        r.times.translate_s,
        r.times.heuristic_s,
        r.times.search_s,
        r.times.total_s,
        opt(r.expansions),
        opt(r.generated),
        opt(r.cost),
        opt(r.length),
        opt(r.peak_memory_kb),
        opt(r.executed)
    )
}

fn results_csv(records: &[RunRecord]) -> String {
    let mut s = format!("{RUNS_HEADER},goal\n");
    for r in records {
        let _ = writeln!(s, "{},{}", runs_csv_row(r), goal(r));
    }
    s
}

fn results_json(records: &[RunRecord], options: &ReproduceOptions, notes: &[String]) -> String {
    let value = serde_json::json!({
        "format": "demoplan-reproduce",
        "version": 2,
        "seed": options.seed,
        "time_limit_s": options.grid.time_limit.as_secs_f64(),
        "repeat": options.repeat,
        "findings": notes,
        "runs": records.iter().map(|r| {
            let mut v = serde_json::to_value(r).unwrap_or_default();
            if let Some(o) = v.as_object_mut() {
                o.insert("goal".into(), goal(r).into());
            }
            v
        }).collect::<Vec<_>>(),
    });
    let mut text = serde_json::to_string_pretty(&value).unwrap_or_default();
    text.push('\n');
    text
}
