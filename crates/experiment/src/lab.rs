//! Computing cells: the simulated study and its library (kept for the cells that share
//! them), the domain and problem of a cell, the planning run and the execution check.

use std::collections::HashMap;
use std::time::{Duration, Instant};

use grounding::GroundingConfig;
use learn::{levels, problem, tower_goal, DomainOptions, Grouping, Library, Scene};
use segment::ActivityTree;
use slim::{Backend, FastDownward, MemoryProbe, Outcome, PlanRun};

use crate::cell::{params_key, Cell, Conditions, LevelChoice, Planner};
use crate::record::{RunRecord, Times, WideningStep};
use crate::ExperimentError;

/// Where the cells of a grid are computed: the simulator's parameters every cell's
/// `params` must name, Fast Downward if the grid runs it, and how to measure peak heap.
#[derive(Debug)]
pub struct Lab {
    params: simulate::SimParams,
    params_key: String,
    fast_downward: Option<FastDownward>,
    memory: Option<MemoryProbe>,
    libraries: HashMap<String, Library>,
}

impl Lab {
    /// A lab for cells of these simulator parameters.
    pub fn new(
        params: simulate::SimParams,
        fast_downward: Option<FastDownward>,
        memory: Option<MemoryProbe>,
    ) -> Lab {
        Lab {
            params_key: params_key(&params),
            params,
            fast_downward,
            memory,
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
            self.libraries
                .insert(key.clone(), learn_study(&study, grouping));
        }
        self.libraries
            .get(&key)
            .ok_or_else(|| ExperimentError::Condition("library missing".into()))
    }

    /// Computes one cell.
    pub fn run(&mut self, cell: &Cell) -> Result<RunRecord, ExperimentError> {
        let backend = self.backend(cell.planner, cell.time_limit)?;
        let memory = self.memory;
        let conditions = cell.conditions.clone();
        let options = DomainOptions {
            keep_without_effects: conditions.keep_without_effects,
        };
        let problem = tower_problem(&conditions)?;
        let library = self.library(&conditions)?;
        let all = levels(library, options);
        let mut record = RunRecord {
            id: cell.id(),
            conditions: conditions.clone(),
            level: cell.level.name(),
            planner: cell.planner.name().to_string(),
            time_limit_s: cell.time_limit.as_secs_f64(),
            repeat: cell.repeat,
            prio: 0,
            operators: 0,
            outcome: String::new(),
            times: Times::default(),
            expansions: None,
            generated: None,
            cost: None,
            length: None,
            peak_memory_kb: None,
            executed: None,
            plan: Vec::new(),
            unit_cost: false,
            widening: Vec::new(),
            error: None,
        };
        let limit = Some(cell.time_limit);
        let level = match cell.level {
            LevelChoice::Prio(n) => all.iter().find(|l| l.prio == n),
            LevelChoice::Full => all.last(),
            LevelChoice::Algorithm1 => {
                let start = Instant::now();
                let solved = slim::solve(library, options, &problem, &backend, limit, |_| {});
                let mut times = Times::default();
                for l in &solved.levels {
                    let step = Times::of(&l.run);
                    times.add(&step);
                    record.widening.push(WideningStep {
                        prio: l.prio,
                        operators: l.operators,
                        outcome: l.run.outcome.word().to_string(),
                        times: step,
                    });
                }
                times.total_s = start.elapsed().as_secs_f64();
                record.times = times;
                let last = solved.plan_level().or(solved.levels.last());
                if let Some(l) = last {
                    record.prio = l.prio;
                    record.operators = l.operators;
                    fill(&mut record, &l.run, &l.domain, &problem, false);
                }
                record.outcome = match solved.plan_level() {
                    Some(_) => "solved",
                    None if solved.any_limit() => "limit",
                    None if solved.levels.is_empty() => "error",
                    None => "unsolvable",
                }
                .to_string();
                if solved.levels.is_empty() {
                    record.error = Some("the library has no level".into());
                }
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
        let run = backend.plan_measured(&domain, &problem, limit, memory);
        record.prio = level.prio;
        record.operators = level.operators.len();
        record.times = Times::of(&run);
        fill(&mut record, &run, &domain, &problem, true);
        Ok(record)
    }

    fn backend(&self, planner: Planner, limit: Duration) -> Result<Backend, ExperimentError> {
        let search = planner.search_string(limit);
        if planner.is_fast_downward() {
            let fd = self
                .fast_downward
                .clone()
                .ok_or(ExperimentError::FastDownwardMissing)?;
            Ok(Backend::FastDownward(fd, search))
        } else {
            let config = search::parse_search(&search)
                .map_err(|e| ExperimentError::Condition(e.to_string()))?;
            Ok(Backend::Demoplan(config))
        }
    }
}

/// Outcome, counts, plan and execution check of a run into its record.
fn fill(
    record: &mut RunRecord,
    run: &PlanRun,
    domain: &pddl::Domain,
    problem: &pddl::Problem,
    with_outcome: bool,
) {
    if with_outcome {
        record.outcome = run.outcome.word().to_string();
    }
    if let Outcome::Error(e) = &run.outcome {
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
    let config = GroundingConfig::default();
    let tree = ActivityTree::table_one();
    let mut library = Library::with_grouping(learn::DEFAULT_LAMBDA, grouping);
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
pub fn execute(domain: &pddl::Domain, problem: &pddl::Problem, plan: &[pddl::Step]) -> Option<bool> {
    cubeworld::execute(domain, problem, plan)
        .ok()
        .map(|report| report.success())
}
