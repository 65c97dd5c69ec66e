//! Computing cells: the simulated study and its library (kept for the cells that share
//! them), the domain and problem of a cell, the planning run and the execution check.

use std::collections::HashMap;
use std::time::Duration;

use grounding::GroundingConfig;
use learn::{levels, problem, tower_goal, DomainOptions, Grouping, Library, OperatorForm, Scene};
use segment::ActivityTree;
use slim::{Backend, FastDownward, MemoryProbe, Outcome, PlanRun, RunLimits};

use crate::cell::{params_key, Cell, Conditions, LevelChoice, Planner};
use crate::record::{RunRecord, SetAsideRecord, Times, WideningStep};
use crate::ExperimentError;

/// Where the cells of a grid are computed: the simulator's parameters every cell's
/// `params` must name, Fast Downward if the grid runs it, how to measure peak heap, and
/// the memory limit of each run.
///
/// The memory limit belongs to the lab, not to the cell (it is not in [`Cell::id`]):
/// like the machine's speed, it is where the grid runs. A run that reaches it is
/// recorded with the outcome `memory`, as one that reaches its time limit is with
/// `limit`.
#[derive(Debug)]
pub struct Lab {
    params: simulate::SimParams,
    params_key: String,
    fast_downward: Option<FastDownward>,
    memory: Option<MemoryProbe>,
    memory_limit: Option<u64>,
    libraries: HashMap<String, Library>,
}

impl Lab {
    /// A lab for cells of these simulator parameters, each run limited to
    /// `memory_limit` bytes of heap of its own (`None`: no limit), read through
    /// `memory` (without a probe the planner counts its own main structures).
    pub fn new(
        params: simulate::SimParams,
        fast_downward: Option<FastDownward>,
        memory: Option<MemoryProbe>,
        memory_limit: Option<u64>,
    ) -> Lab {
        Lab {
            params_key: params_key(&params),
            params,
            fast_downward,
            memory,
            memory_limit,
            libraries: HashMap::new(),
        }
    }

    /// [`Conditions::params`] of this lab's parameters.
    pub fn params_key(&self) -> &str {
        &self.params_key
    }

    /// The operator library of `conditions`: the simulated study learned with its
    /// grouping. Computed once per study and grouping.
    pub fn library(&mut self, conditions: &Conditions) -> Result<&Library, ExperimentError> {
        if conditions.params != self.params_key {
            return Err(ExperimentError::Params {
                wanted: conditions.params.clone(),
                have: self.params_key.clone(),
            });
        }
        let key = conditions.library_key();
        if !self.libraries.contains_key(&key) {
            let grouping = Grouping::from_name(&conditions.activities).ok_or_else(|| {
                ExperimentError::Condition(format!(
                    "activities: {:?} is neither settled nor runs",
                    conditions.activities
                ))
            })?;
            let study = simulate::study(
                &self.params,
                conditions.seed,
                conditions.participants,
                conditions.per_participant,
            )
            .map_err(|e| ExperimentError::Condition(e.to_string()))?;
            let form = match conditions.generalised {
                true => OperatorForm::Generalised,
                false => OperatorForm::Specific,
            };
            self.libraries
                .insert(key.clone(), learn_study_as(&study, grouping, form));
        }
        self.libraries
            .get(&key)
            .ok_or_else(|| ExperimentError::Condition("library missing".into()))
    }

    /// Computes one cell. An Algorithm 1 cell takes the run of a level it tries from
    /// `known` when the grid has that level as a cell of its own (same conditions,
    /// planner, limit and repeat) and it is there already: the same planning run,
    /// measured once. Without it the cell computes every level itself.
    pub fn run(&mut self, cell: &Cell, known: &Known) -> Result<RunRecord, ExperimentError> {
        let planners = Planners {
            fast_downward: self.fast_downward.clone(),
            limits: RunLimits {
                time: Some(cell.time_limit),
                memory_bytes: self.memory_limit,
                memory: self.memory,
            },
        };
        let backend = planners.backend(cell.planner, cell.time_limit)?;
        let conditions = cell.conditions.clone();
        let options = DomainOptions {
            keep_without_effects: conditions.keep_without_effects,
        };
        let problem = tower_problem(&conditions)?;
        let library = self.library(&conditions)?;
        let all = levels(library, options);
        let mut record = RunRecord::blank(cell);
        let level = match cell.level {
            LevelChoice::Prio(n) => all.iter().find(|l| l.prio == n),
            LevelChoice::Full => all.last(),
            LevelChoice::Algorithm1 => {
                planners.algorithm1(cell, &all, &problem, known, &mut record)?;
                return Ok(record);
            }
        };
        let Some(level) = level else {
            return Err(ExperimentError::Condition(format!(
                "level {}: the library has levels {}",
                cell.level.name(),
                all.iter()
                    .map(|l| l.prio.to_string())
                    .collect::<Vec<_>>()
                    .join(", ")
            )));
        };
        let domain = learn::domain("demoplan", &level.operators);
        let run = backend.plan(&domain, &problem, &planners.limits);
        record.prio = level.prio;
        record.operators = level.operators.len();
        record.times = Times::of(&run);
        fill(&mut record, &run, &domain, &problem, true);
        Ok(record)
    }
}

/// Who plans a cell's runs: Fast Downward if the grid runs it, and the limits of each
/// run (the cell's time limit, the lab's memory limit and probe).
struct Planners {
    fast_downward: Option<FastDownward>,
    limits: RunLimits,
}

impl Planners {
    /// The paper's Algorithm 1 under one time budget, the cell's limit: priority 1, 2,
    /// ... until a level gives a plan, each level with what is left of the budget, so
    /// that its cumulative time is comparable with one run on the full domain. A level
    /// that proves there is no plan passes the rest of the budget on; a level that hits
    /// the limit ends the widening (a wider domain only searches more). Execution is in
    /// the loop, as in `demoplan solve`: a plan the cube world does not execute sets
    /// its failing step's operator aside (recorded in `set_aside`, counted in
    /// `replans`) and the level is searched again without it, within the same budget;
    /// a plan whose steps execute but whose goal does not widens. With no executable
    /// plan the record has no plan, and the outcome of the last level tried.
    fn algorithm1(
        &self,
        cell: &Cell,
        all: &[learn::Level<'_>],
        problem: &pddl::Problem,
        known: &Known,
        record: &mut RunRecord,
    ) -> Result<(), ExperimentError> {
        let budget = cell.time_limit.as_secs_f64();
        let mut times = Times::default();
        let mut peak: Option<u64> = None;
        let mut outcome = if all.is_empty() {
            Outcome::Error
        } else {
            Outcome::Unsolvable
        };
        // Operators the execution loop set aside for this problem (their ids).
        let mut aside: Vec<String> = Vec::new();
        'levels: for (i, level) in all.iter().enumerate() {
            loop {
                let left = budget - times.total_s;
                if left <= 0.0 {
                    outcome = Outcome::TimeLimit;
                    break 'levels;
                }
                let operators: Vec<learn::Ranked<'_>> = level
                    .operators
                    .iter()
                    .filter(|r| !aside.contains(&r.operator().id()))
                    .copied()
                    .collect();
                let domain = learn::domain("demoplan", &operators);
                let sibling = |choice: LevelChoice| {
                    known.get(
                        &Cell {
                            level: choice,
                            ..cell.clone()
                        }
                        .id(),
                    )
                };
                // A sibling cell plans the whole level: of no use once something is aside.
                let reused = sibling(LevelChoice::Prio(level.prio))
                    .or_else(|| {
                        (i + 1 == all.len())
                            .then(|| sibling(LevelChoice::Full))
                            .flatten()
                    })
                    .filter(|r| r.outcome != Outcome::Error && aside.is_empty());
                let mut step = match reused {
                    Some(r) => r.clone(),
                    None => {
                        let left = Duration::from_secs_f64(left);
                        let backend = self.backend(cell.planner, left)?;
                        let limits = self.limits.with_time(Some(left));
                        let run = backend.plan(&domain, problem, &limits);
                        let mut step = record.clone();
                        step.times = Times::of(&run);
                        step.outcome = run.outcome;
                        fill(&mut step, &run, &domain, problem, false);
                        step
                    }
                };
                // A level run that outlasted what is left would have been stopped there.
                if step.times.total_s > left {
                    step.times = step.times.truncated(left);
                    step.outcome = Outcome::TimeLimit;
                }
                times.add(&step.times);
                peak = peak.max(step.peak_memory_kb);
                record.widening.push(WideningStep {
                    prio: level.prio,
                    operators: operators.len(),
                    outcome: step.outcome,
                    times: step.times,
                });
                record.prio = level.prio;
                record.operators = operators.len();
                record.expansions = step.expansions;
                record.generated = step.generated;
                record.error = step.error.clone();
                match step.outcome {
                    // Execution in the loop (`closed_loop`): a plan the cube world does
                    // not execute sets the operator of its failing step aside and the
                    // level is searched again; one whose goal fails widens.
                    Outcome::Solved if step.executed == Some(false) => {
                        record.replans += 1;
                        let check = closed_loop::check(
                            level.prio, &domain, &operators, problem, &step.plan,
                        );
                        match check {
                            Ok(closed_loop::Check::StepFailed(s)) => {
                                record.set_aside.push(SetAsideRecord::of(&s));
                                aside.push(s.id);
                                continue;
                            }
                            Ok(_) => continue 'levels,
                            Err(e) => {
                                record.error = Some(e.to_string());
                                outcome = Outcome::Error;
                                break 'levels;
                            }
                        }
                    }
                    Outcome::Solved => {
                        record.cost = step.cost;
                        record.length = step.length;
                        record.plan = step.plan;
                        record.unit_cost = step.unit_cost;
                        record.executed = step.executed;
                    }
                    // A level out of memory ends the widening as one out of time does; so
                    // does a cancelled one (the lab sets no cancel flag today).
                    Outcome::TimeLimit
                    | Outcome::MemoryLimit
                    | Outcome::Cancelled
                    | Outcome::Error => {}
                    Outcome::RelaxedUnreachable | Outcome::Unsolvable => continue 'levels,
                }
                outcome = step.outcome;
                break 'levels;
            }
        }
        if all.is_empty() {
            record.error = Some("the library has no level".into());
        }
        record.times = times;
        record.peak_memory_kb = peak;
        record.outcome = outcome;
        Ok(())
    }

    fn backend(&self, planner: Planner, limit: Duration) -> Result<Backend, ExperimentError> {
        let search = crate::cell::search_string(planner, limit);
        if planner.is_fast_downward() {
            let fd = self
                .fast_downward
                .clone()
                .ok_or(ExperimentError::FastDownwardMissing)?;
            Ok(Backend::FastDownward(fd, search))
        } else {
            let config = search::parse_search(&search)
                .map_err(|e| ExperimentError::Condition(e.to_string()))?;
            Ok(Backend::Demoplan(config.into()))
        }
    }
}

/// Records already computed, by cell id (see [`Lab::run`]).
pub type Known = HashMap<String, RunRecord>;

/// Outcome, counts, plan and execution check of a run into its record.
fn fill(
    record: &mut RunRecord,
    run: &PlanRun,
    domain: &pddl::Domain,
    problem: &pddl::Problem,
    with_outcome: bool,
) {
    if with_outcome {
        record.outcome = run.outcome;
    }
    if let Some(e) = &run.error {
        record.error = Some(e.clone());
    }
    record.expansions = run.expansions;
    record.generated = run.generated;
    record.peak_memory_kb = run.peak_memory_kb;
    if run.outcome == Outcome::Solved {
        record.cost = run.cost;
        record.length = Some(run.plan.len());
        record.plan = run.plan.clone();
        record.unit_cost = run.cost_kind == pddl::CostKind::Unit;
        record.executed = execute(domain, problem, &run.plan);
    }
}

/// Learns the library of a simulated study in-process (what `demoplan simulate` and
/// `demoplan learn` do through files).
pub fn learn_study(study: &simulate::Study, grouping: Grouping) -> Library {
    learn_study_as(study, grouping, OperatorForm::Specific)
}

/// [`learn_study`] into a library of operators of `form` (`learn --generalise`).
pub fn learn_study_as(study: &simulate::Study, grouping: Grouping, form: OperatorForm) -> Library {
    let config = GroundingConfig::default();
    let tree = ActivityTree::table_one();
    let mut library = Library::with_form(learn::DEFAULT_LAMBDA, grouping, form);
    let source = format!("simulated, seed {}", study.seed);
    for demo in &study.demonstrations {
        let frames = demo.frames().map(|(f, _)| f).collect();
        learn::add_frames(&mut library, demo.header(), frames, &config, &tree, &source);
    }
    library
}

/// The towers of `conditions`, bottom first: tower `t` is `cube_{t*h+1}` to
/// `cube_{(t+1)*h}`; the distractors are the cubes after them.
pub fn towers(conditions: &Conditions) -> Vec<Vec<String>> {
    (0..conditions.towers)
        .map(|t| {
            (1..=conditions.height)
                .map(|i| format!("cube_{}", t * conditions.height + i))
                .collect()
        })
        .collect()
}

/// The problem of `conditions`: every cube on the table, open still hands, and the
/// towers' `onTop` facts as the goal.
pub fn tower_problem(conditions: &Conditions) -> Result<pddl::Problem, ExperimentError> {
    if conditions.height < 2 || conditions.towers == 0 || !(1..=2).contains(&conditions.hands) {
        return Err(ExperimentError::Condition(format!(
            "a goal needs towers of at least 2 cubes, at least one tower, and 1 or 2 hands \
             (height {}, towers {}, hands {})",
            conditions.height, conditions.towers, conditions.hands
        )));
    }
    let scene = Scene::with_hands(conditions.cubes(), conditions.hands);
    let mut goal = Vec::new();
    for tower in towers(conditions) {
        goal.extend(tower_goal(&scene, &tower));
    }
    Ok(problem(
        &format!(
            "towers-{}x{}-distractors-{}",
            conditions.towers, conditions.height, conditions.distractors
        ),
        "demoplan",
        &scene,
        &goal,
    ))
}

/// Checks a plan in the cube world: every step's effects, and the goal, hold in the
/// geometry re-grounded; `None` when the cube world cannot run it at all.
pub fn execute(
    domain: &pddl::Domain,
    problem: &pddl::Problem,
    plan: &[pddl::Step],
) -> Option<bool> {
    cubeworld::execute(domain, problem, plan)
        .ok()
        .map(|report| report.success())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn cell(level: LevelChoice, hands: usize) -> Cell {
        Cell {
            conditions: Conditions::paper_goal(7, 2, hands),
            level,
            planner: Planner::Lmcut,
            time_limit: Duration::from_secs(20),
            repeat: 0,
        }
    }

    fn lab() -> Lab {
        Lab::new(simulate::SimParams::default(), None, None, None)
    }

    #[test]
    fn algorithm1_reuses_the_run_of_a_level_the_grid_has() {
        let mut lab = lab();
        let p1 = lab
            .run(&cell(LevelChoice::Prio(1), 1), &Known::new())
            .unwrap();
        assert!(p1.solved(), "{p1:?}");
        // Computed alone, Algorithm 1 plans on priority 1 itself.
        let alone = lab
            .run(&cell(LevelChoice::Algorithm1, 1), &Known::new())
            .unwrap();
        assert_eq!((alone.outcome, alone.prio), (Outcome::Solved, 1));
        assert_eq!(alone.plan, p1.plan);
        // With priority 1's cell known, it takes that run, times and all.
        let mut known = Known::new();
        let mut slow = p1.clone();
        slow.times.search_s = 7.5;
        slow.times.total_s = 8.0;
        known.insert(slow.id.clone(), slow.clone());
        let reused = lab.run(&cell(LevelChoice::Algorithm1, 1), &known).unwrap();
        assert_eq!(reused.outcome, Outcome::Solved);
        assert_eq!(reused.times, slow.times);
        assert_eq!(reused.widening.len(), 1);
        assert_eq!(reused.widening[0].times, slow.times);
        assert_eq!(reused.plan, p1.plan);
        assert_eq!(reused.executed, Some(true));
    }

    #[test]
    fn algorithm1_has_one_budget_for_every_level() {
        let mut lab = lab();
        let p1 = lab
            .run(&cell(LevelChoice::Prio(1), 1), &Known::new())
            .unwrap();
        // A level run that took longer than the cell's limit would have been stopped:
        // Algorithm 1 hit its limit, at the limit, with its phases cut in order.
        let mut known = Known::new();
        let mut slow = p1.clone();
        slow.times.translate_s = 1.0;
        slow.times.heuristic_s = 4.0;
        slow.times.search_s = 25.0;
        slow.times.total_s = 30.0;
        known.insert(slow.id.clone(), slow);
        let cut = lab.run(&cell(LevelChoice::Algorithm1, 1), &known).unwrap();
        assert_eq!(cut.outcome, Outcome::TimeLimit);
        assert_eq!(cut.times.total_s, 20.0);
        assert_eq!(
            (
                cut.times.translate_s,
                cut.times.heuristic_s,
                cut.times.search_s
            ),
            (1.0, 4.0, 15.0)
        );
        assert!(cut.plan.is_empty() && cut.cost.is_none());
    }

    #[test]
    fn a_run_out_of_memory_is_recorded_as_memory_and_ends_the_widening() {
        // No probe: the planner counts its own structures, which exceed one byte at its
        // first check.
        let mut lab = lab_with_limit(Some(1));
        let full = lab.run(&cell(LevelChoice::Full, 1), &Known::new()).unwrap();
        assert_eq!(full.outcome, Outcome::MemoryLimit, "{full:?}");
        assert!(full.hit_limit() && !full.solved());
        assert!(full.plan.is_empty() && full.cost.is_none() && full.error.is_none());
        let line = full.to_json_line();
        assert!(line.contains(r#""outcome":"memory""#), "{line}");
        // Algorithm 1 stops at the first level that runs out, with that outcome.
        let alg1 = lab
            .run(&cell(LevelChoice::Algorithm1, 1), &Known::new())
            .unwrap();
        assert_eq!(alg1.outcome, Outcome::MemoryLimit, "{alg1:?}");
        assert_eq!(alg1.widening.len(), 1);
        assert_eq!(alg1.widening[0].outcome, Outcome::MemoryLimit);
        // The same lab without the limit plans the same cell.
        let mut unlimited = lab_with_limit(None);
        let solved = unlimited
            .run(&cell(LevelChoice::Full, 1), &Known::new())
            .unwrap();
        assert!(solved.solved(), "{solved:?}");
    }

    fn lab_with_limit(bytes: Option<u64>) -> Lab {
        Lab::new(simulate::SimParams::default(), None, None, bytes)
    }

    #[test]
    fn algorithm1_sets_aside_an_operator_whose_step_fails_and_plans_again() {
        let mut lab = lab();
        let alg1 = cell(LevelChoice::Algorithm1, 1);
        // The library of the cell's conditions, replaced by one whose cheapest way to
        // pick a cube up is an Idle that adds inHand (closed-loop's fixture).
        let text = std::fs::read_to_string(concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/../closed-loop/tests/fixtures/broken-idle-library.json"
        ))
        .unwrap();
        let broken = Library::from_json(&text).unwrap();
        lab.libraries.insert(alg1.conditions.library_key(), broken);
        let r = lab.run(&alg1, &Known::new()).unwrap();
        assert_eq!((r.outcome, r.prio), (Outcome::Solved, 1), "{r:?}");
        assert_eq!(r.executed, Some(true));
        assert_eq!(r.replans, 1);
        let names: Vec<&str> = r.set_aside.iter().map(|s| s.name.as_str()).collect();
        assert_eq!(names, ["idle"]);
        assert!(r.plan.iter().all(|s| s.action != "idle"), "{r:?}");
        // Priority 1 twice, the second time without the idle.
        let tried: Vec<(usize, usize)> = r.widening.iter().map(|w| (w.prio, w.operators)).collect();
        assert_eq!(tried, [(1, 3), (1, 2)]);
        assert_eq!(r.operators, 2);
        // The priority-1 cell plans the whole level: its plan does not execute.
        let p1 = lab
            .run(&cell(LevelChoice::Prio(1), 1), &Known::new())
            .unwrap();
        assert_eq!(p1.executed, Some(false));
        // Known, it is taken for the first attempt and the loop goes on from there.
        let mut known = Known::new();
        known.insert(p1.id.clone(), p1);
        let reused = lab.run(&alg1, &known).unwrap();
        assert_eq!((reused.replans, reused.plan.clone()), (1, r.plan.clone()));
    }

    #[test]
    fn a_failed_sibling_is_computed_again() {
        let mut lab = lab();
        let p1 = cell(LevelChoice::Prio(1), 1);
        let mut known = Known::new();
        known.insert(p1.id(), RunRecord::failed(&p1, "crashed".into()));
        let alg1 = lab.run(&cell(LevelChoice::Algorithm1, 1), &known).unwrap();
        assert_eq!(alg1.outcome, Outcome::Solved, "{alg1:?}");
        assert!(alg1.error.is_none());
    }
}
