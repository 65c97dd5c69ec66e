//! Executing a plan: per step, candidate motions tried on a copy of the world, the best
//! one run, its frames grounded, the effects checked.

use std::collections::BTreeSet;

use grounding::{Fact, FactId, FactSpace, Grounder, GroundingConfig, State};
use pddl::{Domain, Problem};
use recording::{Frame, Recording};
use serde::Serialize;

use crate::motion::Script;
use crate::plan::{candidates, Intent};
use crate::symbolic::{
    atom_text, fact_of, fact_text, ground_action, initial_atoms, layout, scene_objects, Atom,
    GroundAction,
};
use crate::world::{World, FRAME_RATE};
use crate::ExecuteError;
use geometry::V3;

/// How long the scene stands still before the first step and after the last (s).
const SETTLE: f64 = 0.4;
/// A step's effects must also hold this many frames before its last one (0.13 s, more
/// than the grounding's minimum duration), so that they do not depend on what follows.
const STABLE_FRAMES: u64 = 12;
/// Cubes whose volumes overlap by more than this (m) along every axis have been moved
/// into each other (the world has no collisions).
const PENETRATION: f64 = 0.001;
/// A held cube stopped by what is below it while the palm goes on this far (m) has had
/// the palm go through it (placing lets the palm creep on by less).
const SLIP: f64 = 0.03;

/// A hand at the end of a step.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct HandPose {
    /// Its name.
    pub name: String,
    /// Palm position (m).
    pub position: [f64; 3],
    /// Orientation (x, y, z, w); grippers keep theirs.
    pub orientation: [f64; 4],
    /// Closure, 0 open to 1 closed.
    pub grip: f64,
    /// The cube it holds.
    pub holding: Option<String>,
}

/// A cube at the end of a step.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct CubePose {
    /// Its name.
    pub name: String,
    /// Centre (m).
    pub position: [f64; 3],
    /// Orientation (x, y, z, w); cubes stay axis-aligned.
    pub orientation: [f64; 4],
}

/// An effect the grounded state did not give.
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
pub struct FailedEffect {
    /// The atom, `(inhand left_hand cube_2)`.
    pub fact: String,
    /// Whether it should hold (an add effect) or not (a delete effect).
    pub expected: bool,
}

/// One step of the execution.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct StepReport {
    /// 1-based position in the plan.
    pub index: usize,
    /// The action's name.
    pub name: String,
    /// Its arguments.
    pub arguments: Vec<String>,
    /// Its type.
    #[serde(rename = "type")]
    pub kind: recording::Activity,
    /// The hand that acts.
    pub hand: String,
    /// Time of the step's first and last frames (s).
    pub start: f64,
    /// See `start`.
    pub end: f64,
    /// Index of the step's last frame in the recording.
    pub end_frame: u64,
    /// What the gripper is told: `open`, `close` or `keep`.
    pub gripper: String,
    /// The motion primitives, in order.
    pub primitives: Vec<String>,
    /// Effects not given by the grounded state at the step's end; empty when it is ok.
    pub failed: Vec<FailedEffect>,
    /// What the step's motion moved through each other: two cubes, `(cube_2 cube_3)`,
    /// or a hand and the cube it holds, `(left_hand cube_2)`, when the cube was stopped
    /// by what is below it and the palm went on more than 3 cm. The world has no
    /// collisions, so a motion that gives the effects only this way is no execution of
    /// the step; empty when it is ok.
    pub collisions: Vec<String>,
    /// Preconditions that did not hold in the plan's symbolic state (a plan that is not
    /// valid in PDDL); the step is executed anyway.
    pub unmet_preconditions: Vec<String>,
    /// The grounded facts over the step's objects at its end.
    pub grounded: Vec<String>,
    /// Hands at the end.
    pub hands: Vec<HandPose>,
    /// Cubes at the end.
    pub cubes: Vec<CubePose>,
}

impl StepReport {
    /// Whether every effect held and no cube was moved into another.
    pub fn ok(&self) -> bool {
        self.failed.is_empty() && self.collisions.is_empty()
    }

    /// `(take left_hand cube_2)`.
    pub fn action_text(&self) -> String {
        atom_text(&(self.name.clone(), self.arguments.clone()))
    }
}

/// The goal check on the final grounded state.
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
pub struct GoalReport {
    /// Whether every goal literal holds.
    pub reached: bool,
    /// The goal literals that do not.
    pub unsatisfied: Vec<String>,
}

/// The result of executing a plan.
#[derive(Debug, Clone)]
pub struct ExecutionReport {
    /// The domain's name.
    pub domain: String,
    /// The problem's name.
    pub problem: String,
    /// Initial atoms the grounded first frames do not have (the cube world could not lay
    /// them out; e.g. a hand that starts moving).
    pub initial_missing: Vec<String>,
    /// Hands and cubes at the start.
    pub initial_hands: Vec<HandPose>,
    /// See `initial_hands`.
    pub initial_cubes: Vec<CubePose>,
    /// The steps, in plan order.
    pub steps: Vec<StepReport>,
    /// The goal check.
    pub goal: GoalReport,
    /// The frames the execution produced, as a recording.
    pub recording: Recording,
}

impl ExecutionReport {
    /// The first step whose effects failed (its index into `steps`).
    pub fn first_failure(&self) -> Option<usize> {
        self.steps.iter().position(|s| !s.ok())
    }

    /// Every step ok and the goal reached.
    pub fn success(&self) -> bool {
        self.first_failure().is_none() && self.goal.reached
    }
}

/// The world and its grounder, copied for each trial.
#[derive(Debug, Clone)]
struct Sim {
    world: World,
    grounder: Grounder,
    /// Pairs of entities moved through each other during the last `advance` (see
    /// [`World::interpenetrating`]; not so at its start).
    collisions: Vec<(usize, usize)>,
}

impl Sim {
    /// Runs the scripts (one per hand) for `duration` seconds; returns the index of the
    /// last frame.
    fn advance(
        &mut self,
        scripts: &[Script],
        acting: Option<usize>,
        duration: f64,
        on_frame: &mut impl FnMut(&Frame),
        on_grounded: &mut impl FnMut(u64, &State),
    ) -> u64 {
        let n = frames_for(duration);
        let mut targets = Vec::with_capacity(scripts.len());
        let passive: Vec<bool> = (0..scripts.len()).map(|h| Some(h) != acting).collect();
        self.world.carried.iter_mut().for_each(|c| *c = V3::ZERO);
        let overlapping = self.world.interpenetrating(PENETRATION, SLIP);
        self.collisions.clear();
        for k in 1..=n {
            let s = k as f64 / FRAME_RATE;
            targets.clear();
            targets.extend(scripts.iter().map(|sc| sc.at(s)));
            let frame = self.world.step(&targets, &passive);
            self.grounder
                .push(&frame, &mut |g| on_grounded(g.index, g.state));
            on_frame(&frame);
            for pair in self.world.interpenetrating(PENETRATION, SLIP) {
                if !overlapping.contains(&pair) && !self.collisions.contains(&pair) {
                    self.collisions.push(pair);
                }
            }
        }
        self.world.frames.saturating_sub(1)
    }
}

fn frames_for(duration: f64) -> u64 {
    ((duration * FRAME_RATE - 1e-6).ceil() as u64).max(1)
}

/// A hand that does not act in a step: it comes to rest where it is.
fn idle_script(world: &World, h: usize) -> Script {
    let hand = world.hands[h];
    let mut s = Script::new(hand.pos, hand.vel, hand.grip);
    if hand.vel.norm() > 1e-9 {
        s.hold(0.0);
    }
    s
}

/// The checks of one step: effects (fact, expected) and the symbolic state after it
/// over the step's objects, preferred but not required.
struct Checks {
    effects: Vec<(Option<FactId>, Atom, bool)>,
    preferred: Vec<(FactId, bool)>,
}

impl Checks {
    fn failed(&self, state: &State) -> Vec<FailedEffect> {
        self.effects
            .iter()
            .filter(|(id, _, expected)| id.is_some_and(|i| state.contains(i)) != *expected)
            .map(|(_, a, expected)| FailedEffect {
                fact: atom_text(a),
                expected: *expected,
            })
            .collect()
    }

    fn disagreements(&self, state: &State) -> usize {
        self.preferred
            .iter()
            .filter(|(id, expected)| state.contains(*id) != *expected)
            .count()
    }
}

/// Executes a plan in the cube world: lays out the problem's initial state, then for
/// each step moves the acting hand with the motion primitives of the action's type, in
/// the variant whose grounded frames (the paper's Table 2 grounding, default thresholds)
/// give the action's effects, and checks them after the step; finally checks the goal
/// on the grounded state of the still scene.
///
/// Errors are inputs the cube world cannot execute (not a failed execution): a problem
/// whose objects are not hands, cubes and a table, a step whose action the domain does
/// not have or whose type is not one of the five, an effect outside Table 2's
/// predicates.
///
/// Cost: each step tries some tens of candidate motions of a few hundred frames each on
/// a copy of the world and grounder.
pub fn execute(
    domain: &Domain,
    problem: &Problem,
    plan: &[pddl::Step],
) -> Result<ExecutionReport, ExecuteError> {
    let objects = scene_objects(problem)?;
    let init = initial_atoms(problem);
    let lay = layout(&objects, &init)?;
    let world = World::new(
        problem.name.as_str(),
        &objects.hands,
        &objects.cubes,
        &objects.table,
        &lay,
    );
    let grounder = Grounder::new(&world.header, &GroundingConfig::default());
    let space: FactSpace = grounder.space().clone();
    let header = world.header.clone();
    let actions: Vec<GroundAction> = plan
        .iter()
        .map(|s| ground_action(domain, &s.action, &s.args))
        .collect::<Result<_, _>>()?;
    // Every effect must be a fact of Table 2 over the scene's objects.
    let mut effect_ids = Vec::new();
    for a in &actions {
        let mut ids = Vec::new();
        for (atom, expected) in a
            .add
            .iter()
            .map(|x| (x, true))
            .chain(a.delete.iter().map(|x| (x, false)))
        {
            ids.push((fact_of(&header, &space, atom)?, atom.clone(), expected));
        }
        effect_ids.push(ids);
    }
    let fact_set = |atoms: &BTreeSet<Atom>| -> BTreeSet<FactId> {
        atoms
            .iter()
            .filter_map(|a| fact_of(&header, &space, a).ok().flatten())
            .collect()
    };

    let mut sim = Sim {
        world,
        grounder,
        collisions: Vec::new(),
    };
    let mut frames: Vec<Frame> = Vec::new();
    let mut grounded: Vec<State> = Vec::new();
    let mut keep = |i: u64, s: &State| {
        debug_assert_eq!(i as usize, grounded.len());
        grounded.push(s.clone());
    };
    // The still scene first.
    let first = sim.world.step(
        &sim.world
            .hands
            .iter()
            .map(|h| (h.pos, h.vel, h.grip))
            .collect::<Vec<_>>(),
        &vec![true; sim.world.hands.len()],
    );
    sim.grounder.push(&first, &mut |g| keep(g.index, g.state));
    frames.push(first);
    let initial_hands = hand_poses(&sim.world);
    let initial_cubes = cube_poses(&sim.world);
    let still: Vec<Script> = (0..sim.world.hands.len())
        .map(|h| idle_script(&sim.world, h))
        .collect();
    let settled = sim.advance(
        &still,
        None,
        SETTLE,
        &mut |f| frames.push(f.clone()),
        &mut keep,
    );

    let mut symbolic = init.clone();
    let mut pending: Vec<StepReport> = Vec::new();
    let mut pending_checks = Vec::new();
    for (index, (action, effects)) in actions.iter().zip(&effect_ids).enumerate() {
        let unmet = action.unmet(&symbolic);
        let mut after = symbolic.clone();
        action.apply(&mut after);
        let hand = action
            .args
            .iter()
            .find_map(|a| objects.hands.iter().position(|h| h == a))
            .ok_or_else(|| {
                ExecuteError::Plan(format!(
                    "step {} {} names no hand",
                    index + 1,
                    atom_text(&(action.name.clone(), action.args.clone()))
                ))
            })?;
        let arg_ids: Vec<_> = action.args.iter().filter_map(|a| header.find(a)).collect();
        let after_ids = fact_set(&after);
        let preferred: Vec<(FactId, bool)> = space
            .facts()
            .iter()
            .enumerate()
            .filter(|(_, f)| f.args().iter().all(|a| arg_ids.contains(a)))
            .map(|(i, _)| {
                let id = FactId(i as u32);
                (id, after_ids.contains(&id))
            })
            .collect();
        let checks = Checks {
            effects: effects.clone(),
            preferred,
        };
        let to_facts = |atoms: &[Atom]| -> Vec<Fact> {
            atoms
                .iter()
                .filter_map(|a| fact_of(&header, &space, a).ok().flatten())
                .filter_map(|id| space.fact(id))
                .collect()
        };
        let after_facts: Vec<Fact> = after_ids.iter().filter_map(|&id| space.fact(id)).collect();
        let cube_args: Vec<usize> = action
            .args
            .iter()
            .filter_map(|a| objects.cubes.iter().position(|c| c == a))
            .collect();
        let intent = Intent::new(
            &sim.world,
            hand,
            action.kind,
            &to_facts(&action.add),
            &to_facts(&action.delete),
            &after_facts,
            &cube_args,
        );
        // Try every candidate on a copy; keep the first that gives the effects without
        // moving a cube into another, else the one that does not collide and fails
        // fewest.
        let mut best: Option<((usize, usize, usize, usize), Script)> = None;
        for (k, cand) in candidates(&sim.world, &intent).into_iter().enumerate() {
            let score = trial(&sim, hand, &cand, &checks);
            let key = (score.0, score.1, score.2, k);
            if best.as_ref().is_none_or(|(b, _)| key < *b) {
                best = Some((key, cand));
            }
            if score == (0, 0, 0) {
                break;
            }
        }
        let Some((_, script)) = best else {
            return Err(ExecuteError::Plan(format!(
                "no motion for step {}",
                index + 1
            )));
        };
        let scripts: Vec<Script> = (0..sim.world.hands.len())
            .map(|h| {
                if h == hand {
                    script.clone()
                } else {
                    idle_script(&sim.world, h)
                }
            })
            .collect();
        let start = sim.world.time;
        let end_frame = sim.advance(
            &scripts,
            Some(hand),
            script.duration(),
            &mut |f| frames.push(f.clone()),
            &mut keep,
        );
        let end = sim.world.time - 1.0 / FRAME_RATE;
        pending.push(StepReport {
            index: index + 1,
            name: action.name.clone(),
            arguments: action.args.clone(),
            kind: action.kind,
            hand: objects.hands[hand].clone(),
            start: round(start),
            end: round(end),
            end_frame,
            gripper: script.gripper.to_string(),
            primitives: script.primitives.iter().map(|p| p.to_string()).collect(),
            failed: Vec::new(),
            collisions: sim
                .collisions
                .iter()
                .map(|&(a, b)| {
                    let name = |e: usize| {
                        header
                            .entities
                            .get(e)
                            .map_or_else(String::new, |e| e.name.clone())
                    };
                    format!("({} {})", name(a), name(b))
                })
                .collect(),
            unmet_preconditions: unmet,
            grounded: Vec::new(),
            hands: hand_poses(&sim.world),
            cubes: cube_poses(&sim.world),
        });
        // Checked once grounding has caught up.
        pending_checks.push((checks, arg_ids));
        symbolic = after;
    }
    // The scene comes to rest; then every frame is grounded.
    let still: Vec<Script> = (0..sim.world.hands.len())
        .map(|h| idle_script(&sim.world, h))
        .collect();
    sim.advance(
        &still,
        None,
        SETTLE,
        &mut |f| frames.push(f.clone()),
        &mut keep,
    );
    sim.grounder.finish(&mut |g| keep(g.index, g.state));

    let empty = space.empty_state();
    let state_at = |i: u64| grounded.get(i as usize).unwrap_or(&empty);
    let mut steps = Vec::new();
    for (mut report, (checks, arg_ids)) in pending.into_iter().zip(pending_checks) {
        let st = state_at(report.end_frame);
        report.failed = checks.failed(st);
        report.grounded = st
            .facts(&space)
            .filter(|f| f.args().iter().all(|a| arg_ids.contains(a)))
            .map(|f| fact_text(&header, &f))
            .collect();
        steps.push(report);
    }
    let initial_state = state_at(settled);
    let initial_missing = init
        .iter()
        .filter(|a| match fact_of(&header, &space, a) {
            Ok(Some(id)) => !initial_state.contains(id),
            _ => false,
        })
        .map(atom_text)
        .collect();
    let final_state = grounded.last().unwrap_or(&empty);
    let mut unsatisfied = Vec::new();
    for l in &problem.goal {
        let atom = (
            l.atom.predicate.as_str().to_string(),
            l.atom
                .args
                .iter()
                .map(|t| t.name().as_str().to_string())
                .collect::<Vec<_>>(),
        );
        let holds = fact_of(&header, &space, &atom)?.is_some_and(|id| final_state.contains(id));
        if holds != l.positive {
            let text = atom_text(&atom);
            unsatisfied.push(if l.positive {
                text
            } else {
                format!("(not {text})")
            });
        }
    }
    Ok(ExecutionReport {
        domain: domain.name.as_str().to_string(),
        problem: problem.name.as_str().to_string(),
        initial_missing,
        initial_hands,
        initial_cubes,
        steps,
        goal: GoalReport {
            reached: unsatisfied.is_empty(),
            unsatisfied,
        },
        recording: Recording { header, frames },
    })
}

/// Runs a candidate on a copy of the world: (pairs of cubes it moves into each other,
/// effects failed at the end or 0.13 s before, disagreements with the symbolic state
/// after the step).
fn trial(sim: &Sim, hand: usize, script: &Script, checks: &Checks) -> (usize, usize, usize) {
    let mut copy = sim.clone();
    let scripts: Vec<Script> = (0..copy.world.hands.len())
        .map(|h| {
            if h == hand {
                script.clone()
            } else {
                idle_script(&copy.world, h)
            }
        })
        .collect();
    let end = copy.world.frames + frames_for(script.duration()) - 1;
    let early = end.saturating_sub(STABLE_FRAMES);
    let mut at_end = None;
    let mut at_early = None;
    let mut grab = |i: u64, s: &State| {
        if i == end {
            at_end = Some(s.clone());
        } else if i == early {
            at_early = Some(s.clone());
        }
    };
    copy.advance(
        &scripts,
        Some(hand),
        script.duration(),
        &mut |_| {},
        &mut grab,
    );
    copy.grounder.finish(&mut |g| grab(g.index, g.state));
    let (Some(e), Some(a)) = (at_end, at_early) else {
        return (usize::MAX, usize::MAX, usize::MAX);
    };
    (
        copy.collisions.len(),
        checks.failed(&e).len() + checks.failed(&a).len(),
        checks.disagreements(&e),
    )
}

fn round(x: f64) -> f64 {
    (x * 1e6).round() / 1e6
}

fn hand_poses(world: &World) -> Vec<HandPose> {
    world
        .hands
        .iter()
        .enumerate()
        .map(|(h, hand)| HandPose {
            name: world.header.entities[h].name.clone(),
            position: hand.pos.to_array().map(|x| (x * 1e4).round() / 1e4),
            orientation: [0.0, 0.0, 0.0, 1.0],
            grip: (hand.grip * 1e3).round() / 1e3,
            holding: hand
                .holding
                .map(|c| world.header.entities[world.hands.len() + c].name.clone()),
        })
        .collect()
}

fn cube_poses(world: &World) -> Vec<CubePose> {
    world
        .cubes
        .iter()
        .enumerate()
        .map(|(c, cube)| CubePose {
            name: world.header.entities[world.hands.len() + c].name.clone(),
            position: cube.pos.to_array().map(|x| (x * 1e4).round() / 1e4),
            orientation: [0.0, 0.0, 0.0, 1.0],
        })
        .collect()
}
