//! Studies (participants times demonstrations, as in the paper) and long sessions.

use recording::{Entity, EntityId, EntityKind, Header, Pose, Quaternion, Vec3};

use crate::params::{ParamError, SimParams};
use crate::render::Frames;
use crate::rng::Rng;
use crate::script::{Plan, Planner, Support};
use crate::style::Style;
use crate::truth::{TruthHeader, TRUTH_FORMAT_NAME, TRUTH_FORMAT_VERSION};
use geometry::V3;

/// A hand.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Side {
    /// The left hand, resting at +y.
    Left,
    /// The right hand, resting at -y.
    Right,
}

impl Side {
    /// Both, left first (the order of the hands in recordings).
    pub const BOTH: [Side; 2] = [Side::Left, Side::Right];

    /// `left` or `right`.
    pub fn name(self) -> &'static str {
        match self {
            Side::Left => "left",
            Side::Right => "right",
        }
    }

    /// The hand's entity name: `left_hand`, `right_hand`.
    pub fn entity_name(self) -> &'static str {
        match self {
            Side::Left => "left_hand",
            Side::Right => "right_hand",
        }
    }

    /// The hand's entity id in simulated recordings (0 left, 1 right).
    pub fn entity(self) -> EntityId {
        EntityId(self.index() as u32)
    }

    pub(crate) fn index(self) -> usize {
        match self {
            Side::Left => 0,
            Side::Right => 1,
        }
    }

    /// +1 for left, -1 for right: the sign of the hand's y at rest.
    pub(crate) fn sign(self) -> f64 {
        match self {
            Side::Left => 1.0,
            Side::Right => -1.0,
        }
    }
}

/// A simulated person: the style drawn for them from the parameters' intervals. A
/// participant is one draw, so the people of two seeds differ as two real groups do; the
/// probabilities below are per event (per reach, grasp, placement, second of rest).
#[derive(Debug, Clone, PartialEq)]
pub struct Participant {
    /// `p01`, `p02`, ...
    pub code: String,
    /// The hand movements are fastest with.
    pub dominant: Side,
    /// Mean hand speed over a movement (m/s).
    pub mean_speed: f64,
    /// Probability of resting the hand after grasping (the paper's Put rather than Put2).
    pub rest_after_grasp: f64,
    /// Grip of the relaxed hand.
    pub grip_rest: f64,
    /// Grip of the hand opened to grasp.
    pub grip_open: f64,
    /// Probability of hovering above the target before descending.
    pub hover: f64,
    /// Probability of going back to rest between two placements.
    pub return_between: f64,
    /// Probability that a reach first heads for another cube.
    pub abort: f64,
    /// Probability of regrasping a cube before lifting it.
    pub regrasp: f64,
    /// Probability of lifting a cube just put down and setting it down again.
    pub adjust: f64,
    /// Small movements of a resting hand, per second.
    pub fidget_rate: f64,
}

impl Participant {
    fn draw(code: String, p: &SimParams, rng: &mut Rng) -> Participant {
        let mut d = |i: crate::Interval| rng.uniform(i.min, i.max);
        let mean_speed = d(p.mean_speed);
        let rest_after_grasp = d(p.rest_after_grasp);
        let grip_rest = d(p.grip_rest);
        let grip_open = d(p.grip_open);
        let dominant = if rng.chance(p.left_handed) {
            Side::Left
        } else {
            Side::Right
        };
        let mut d = |i: crate::Interval| rng.uniform(i.min, i.max);
        let hover = d(p.hover);
        let return_between = d(p.return_between);
        let abort = d(p.abort);
        let regrasp = d(p.regrasp);
        let adjust = d(p.adjust);
        let fidget_rate = d(p.fidget_rate);
        Participant {
            code,
            dominant,
            mean_speed,
            rest_after_grasp,
            grip_rest,
            grip_open,
            hover,
            return_between,
            abort,
            regrasp,
            adjust,
            fidget_rate,
        }
    }
}

/// Where a cube is put.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Target {
    /// On top of this cube.
    Cube(EntityId),
    /// On the table, centred at (x, y).
    Table {
        /// x of the place (m).
        x: f64,
        /// y of the place (m).
        y: f64,
    },
}

/// One pick-and-place of the script.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Placement {
    /// The hand that does it.
    pub hand: Side,
    /// The cube moved.
    pub cube: EntityId,
    /// Where it goes.
    pub onto: Target,
}

/// One simulated recording: its header, its script, and the means to render its frames.
#[derive(Debug, Clone)]
pub struct Demonstration {
    /// The recording id, e.g. `p01-d03`.
    pub id: String,
    /// Who demonstrates.
    pub participant: Participant,
    /// The hand told to do the task (`None` for a session with both hands).
    pub hand: Option<Side>,
    /// What is done, in order.
    pub placements: Vec<Placement>,
    pub(crate) header: Header,
    pub(crate) plan: Plan,
    pub(crate) params: SimParams,
    pub(crate) seed: u64,
    pub(crate) frame_limit: Option<u64>,
}

impl Demonstration {
    /// The recording's header.
    pub fn header(&self) -> &Header {
        &self.header
    }

    /// The frames and their ground truth, rendered one at a time.
    pub fn frames(&self) -> Frames<'_> {
        Frames::new(self)
    }

    /// The header of the ground-truth file.
    pub fn truth_header(&self) -> TruthHeader {
        TruthHeader {
            format: TRUTH_FORMAT_NAME.into(),
            version: TRUTH_FORMAT_VERSION,
            recording: self.id.clone(),
            hands: Side::BOTH.iter().map(|s| s.entity_name().into()).collect(),
            move_speed: self.params.move_speed,
            acted_on_distance: self.params.acted_on_distance,
            toward_speed: self.params.toward_speed,
        }
    }

    /// The planned length of the recording (s).
    pub fn duration(&self) -> f64 {
        match self.frame_limit {
            Some(n) => n as f64 / self.params.frame_rate,
            None => self.plan.end - self.plan.start,
        }
    }

    /// A placement in words: `cube_3 onto cube_5`.
    pub fn describe(&self, placement: &Placement) -> String {
        let name = |id: EntityId| self.header.entity(id).name.clone();
        match placement.onto {
            Target::Cube(c) => format!("{} onto {}", name(placement.cube), name(c)),
            Target::Table { x, y } => {
                format!(
                    "{} onto the table at ({x:.3}, {y:.3})",
                    name(placement.cube)
                )
            }
        }
    }
}

/// The participants and demonstrations of a simulated study.
#[derive(Debug, Clone)]
pub struct Study {
    /// The seed everything was drawn from.
    pub seed: u64,
    /// The parameters used.
    pub params: SimParams,
    /// The participants.
    pub participants: Vec<Participant>,
    /// The demonstrations, participant by participant.
    pub demonstrations: Vec<Demonstration>,
}

fn cube_name(i: usize) -> String {
    format!("cube_{}", i + 1)
}

fn header(
    p: &SimParams,
    id: &str,
    participant: &str,
    task: &str,
    meta: Vec<(&str, String)>,
) -> Header {
    let hand = Vec3::new(
        p.hand_size[0] as f32,
        p.hand_size[1] as f32,
        p.hand_size[2] as f32,
    );
    let cube = Vec3::new(p.cube_size as f32, p.cube_size as f32, p.cube_size as f32);
    let mut entities = vec![
        Entity {
            name: Side::Left.entity_name().into(),
            kind: EntityKind::Hand,
            size: hand,
            fixed: None,
        },
        Entity {
            name: Side::Right.entity_name().into(),
            kind: EntityKind::Hand,
            size: hand,
            fixed: None,
        },
    ];
    for i in 0..p.cubes as usize {
        entities.push(Entity {
            name: cube_name(i),
            kind: EntityKind::Cube,
            size: cube,
            fixed: None,
        });
    }
    entities.push(Entity {
        name: "table".into(),
        kind: EntityKind::Table,
        size: Vec3::new(
            p.table_depth as f32,
            p.table_width as f32,
            p.table_height as f32,
        ),
        fixed: Some(Pose {
            position: Vec3::new(p.table_x as f32, 0.0, (0.5 * p.table_height) as f32),
            orientation: Quaternion::IDENTITY,
        }),
    });
    Header {
        id: id.into(),
        participant: participant.into(),
        task: task.into(),
        frame_rate: p.frame_rate,
        entities,
        meta: meta.into_iter().map(|(k, v)| (k.to_string(), v)).collect(),
    }
}

/// Cubes scattered on the table at least `cube_spacing` apart, with random headings
/// (positions to 0.1 mm, so the plan and the files agree).
fn layout(p: &SimParams, rng: &mut Rng) -> Result<Vec<(V3, f64)>, ParamError> {
    let z = p.table_height + 0.5 * p.cube_size;
    for _ in 0..200 {
        let mut cubes: Vec<(V3, f64)> = Vec::new();
        let mut tries = 0;
        while cubes.len() < p.cubes as usize && tries < 2000 {
            tries += 1;
            let x = rng.uniform(p.cube_area_x.min, p.cube_area_x.max);
            let y = rng.uniform(p.cube_area_y.min, p.cube_area_y.max);
            let c = V3::new((x * 1e4).round() / 1e4, (y * 1e4).round() / 1e4, z);
            if cubes.iter().all(|(o, _)| (*o - c).norm() >= p.cube_spacing) {
                let yaw = rng.uniform(-0.25, 0.25) * std::f64::consts::PI;
                cubes.push((c, yaw));
            }
        }
        if cubes.len() == p.cubes as usize {
            return Ok(cubes);
        }
    }
    Err(ParamError {
        field: "cubes".into(),
        message: format!(
            "{} cubes do not fit {} m apart in the cube area",
            p.cubes, p.cube_spacing
        ),
    })
}

/// Picks a cube, preferring those near the hand's rest position.
fn pick(rng: &mut Rng, candidates: &[usize], cubes: &[(V3, f64)], near: V3) -> usize {
    let weights: Vec<f64> = candidates
        .iter()
        .map(|&c| (-(cubes[c].0 - near).horizontal_norm() / 0.35).exp())
        .collect();
    let total: f64 = weights.iter().sum();
    let mut x = rng.uniform(0.0, total);
    for (&c, w) in candidates.iter().zip(&weights) {
        if x < *w {
            return c;
        }
        x -= w;
    }
    candidates[candidates.len() - 1]
}

/// The paper's study: `participants` people, `per_participant` demonstrations each. Each
/// person does the four tasks (one cube or two, left hand or right) in a random order,
/// and again in a new order when there are more than four demonstrations.
///
/// In the [`Style::TwoHanded`] style every task is a tower of three built with both hands
/// (two cubes stacked onto a base, one by each hand, the other hand reaching for its cube
/// while the first still carries and puts its own); the four tasks differ in the hand
/// that starts (each starts twice).
pub fn study(
    params: &SimParams,
    seed: u64,
    participants: u32,
    per_participant: u32,
) -> Result<Study, ParamError> {
    params.validate()?;
    if participants == 0 || participants > 999 {
        return Err(ParamError {
            field: "participants".into(),
            message: format!("{participants}: between 1 and 999"),
        });
    }
    if per_participant == 0 || per_participant > 999 {
        return Err(ParamError {
            field: "per_participant".into(),
            message: format!("{per_participant}: between 1 and 999"),
        });
    }
    let mut people = Vec::new();
    let mut demos = Vec::new();
    for pi in 0..participants {
        let mut rng = Rng::derive(seed, &[1, u64::from(pi)]);
        let who = Participant::draw(format!("p{:02}", pi + 1), params, &mut rng);
        let mut order: Vec<(usize, Side)> = Vec::new();
        for di in 0..per_participant {
            if di % 4 == 0 {
                order = vec![
                    (1, Side::Left),
                    (1, Side::Right),
                    (2, Side::Left),
                    (2, Side::Right),
                ];
                rng.shuffle(&mut order);
            }
            let (count, hand) = order[(di % 4) as usize];
            let id = format!("{}-d{:02}", who.code, di + 1);
            let demo_seed = Rng::derive(seed, &[2, u64::from(pi), u64::from(di)]).next_u64();
            demos.push(match params.style {
                Style::Paper => demonstration(params, seed, demo_seed, &who, id, count, hand)?,
                Style::TwoHanded => two_handed(params, seed, demo_seed, &who, id, hand)?,
            });
        }
        people.push(who);
    }
    Ok(Study {
        seed,
        params: params.clone(),
        participants: people,
        demonstrations: demos,
    })
}

fn demonstration(
    p: &SimParams,
    seed: u64,
    demo_seed: u64,
    who: &Participant,
    id: String,
    count: usize,
    hand: Side,
) -> Result<Demonstration, ParamError> {
    let mut rng = Rng::derive(demo_seed, &[0]);
    let cubes = layout(p, &mut rng)?;
    let all: Vec<usize> = (0..cubes.len()).collect();
    let rest = V3::new(p.rest_x, hand.sign() * p.rest_y, p.table_height);
    let base = all[rng.below(all.len())];
    let mut chosen = vec![base];
    for _ in 0..count {
        let rest_cubes: Vec<usize> = all
            .iter()
            .copied()
            .filter(|c| !chosen.contains(c))
            .collect();
        chosen.push(pick(&mut rng, &rest_cubes, &cubes, rest));
    }
    let mut planner = Planner::new(p, who, Rng::derive(demo_seed, &[1]), cubes.clone());
    planner.wait_until(rng.uniform(p.start_pause.min, p.start_pause.max));
    let mut placements = Vec::new();
    for k in 0..count {
        let (cube, onto) = (chosen[k + 1], chosen[k]);
        planner.placement(hand, cube, Support::Cube(onto), k + 1 == count);
        placements.push(Placement {
            hand,
            cube: EntityId((2 + cube) as u32),
            onto: Target::Cube(EntityId((2 + onto) as u32)),
        });
    }
    let plan = planner.finish(rng.uniform(p.end_pause.min, p.end_pause.max));
    let task = match count {
        1 => format!(
            "Stack one cube on another cube with the {} hand.",
            hand.name()
        ),
        2 => format!(
            "Stack two cubes on another cube, one after the other, with the {} hand.",
            hand.name()
        ),
        _ => format!(
            "Stack {count} cubes on another cube, one after the other, with the {} hand.",
            hand.name()
        ),
    };
    let mut demo = Demonstration {
        id: id.clone(),
        participant: who.clone(),
        hand: Some(hand),
        placements,
        header: header(p, &id, &who.code, &task, vec![]),
        plan,
        params: p.clone(),
        seed: demo_seed,
        frame_limit: None,
    };
    demo.header.meta = meta(&demo, seed);
    Ok(demo)
}

/// A tower built with both hands: `first` puts a cube onto the base, the other hand a
/// cube onto that one (and so on, alternating, when there are more). Each next hand
/// starts reaching while the one before holds its cube (from 0.2 s before its grasp to a
/// third of the way from its grasp to its release), takes its own cube and holds it still until the cube below is in place and
/// the other hand leaves. Every hand goes back to rest after its last placement.
fn two_handed(
    p: &SimParams,
    seed: u64,
    demo_seed: u64,
    who: &Participant,
    id: String,
    first: Side,
) -> Result<Demonstration, ParamError> {
    const PLACEMENTS: usize = 2;
    let mut rng = Rng::derive(demo_seed, &[0]);
    let cubes = layout(p, &mut rng)?;
    let all: Vec<usize> = (0..cubes.len()).collect();
    let other = |s: Side| match s {
        Side::Left => Side::Right,
        Side::Right => Side::Left,
    };
    let hands: Vec<Side> = (0..PLACEMENTS)
        .map(|k| if k % 2 == 0 { first } else { other(first) })
        .collect();
    let base = all[rng.below(all.len())];
    let mut chosen = vec![base];
    for hand in &hands {
        let rest = V3::new(p.rest_x, hand.sign() * p.rest_y, p.table_height);
        let free: Vec<usize> = all
            .iter()
            .copied()
            .filter(|c| !chosen.contains(c))
            .collect();
        chosen.push(pick(&mut rng, &free, &cubes, rest));
    }
    let mut planner = Planner::new(p, who, Rng::derive(demo_seed, &[1]), cubes.clone());
    planner.wait_until(rng.uniform(p.start_pause.min, p.start_pause.max));
    let mut placements = Vec::new();
    let mut before: Option<crate::script::Timing> = None;
    for (k, &hand) in hands.iter().enumerate() {
        if let Some(t) = before {
            // Early enough that the reach ends while the other hand still holds its cube.
            let latest = t.grasp + 0.35 * (t.release - t.grasp);
            planner.wait_hand_until(hand, rng.uniform(t.grasp - 0.2, latest));
        }
        let (cube, onto) = (chosen[k + 1], chosen[k]);
        let last = !hands[k + 1..].contains(&hand);
        before = Some(planner.placement(hand, cube, Support::Cube(onto), last));
        placements.push(Placement {
            hand,
            cube: EntityId((2 + cube) as u32),
            onto: Target::Cube(EntityId((2 + onto) as u32)),
        });
    }
    let plan = planner.finish(rng.uniform(p.end_pause.min, p.end_pause.max));
    let task = format!(
        "Stack two cubes on another cube with both hands, one each, starting with the {} \
         hand.",
        first.name()
    );
    let mut demo = Demonstration {
        id: id.clone(),
        participant: who.clone(),
        hand: None,
        placements,
        header: header(p, &id, &who.code, &task, vec![]),
        plan,
        params: p.clone(),
        seed: demo_seed,
        frame_limit: None,
    };
    demo.header.meta = meta(&demo, seed);
    demo.header
        .meta
        .insert("style".into(), p.style.name().to_string());
    demo.header
        .meta
        .insert("first_hand".into(), first.name().to_string());
    Ok(demo)
}

fn meta(demo: &Demonstration, seed: u64) -> std::collections::BTreeMap<String, String> {
    let mut m = std::collections::BTreeMap::new();
    m.insert("generator".into(), "demoplan simulate".into());
    m.insert("seed".into(), seed.to_string());
    if let Some(h) = demo.hand {
        m.insert("hand".into(), h.name().into());
    }
    let placements: Vec<String> = demo.placements.iter().map(|pl| demo.describe(pl)).collect();
    m.insert("placements".into(), placements.join("; "));
    m
}

/// A long recording: one participant rearranging the cubes with both hands, one
/// pick-and-place after another (onto another cube, towers of at most three, or onto a
/// free spot of the table), for `frames` frames. For measuring readers and grounding on
/// long inputs; its frames are rendered as they are asked for.
pub fn session(params: &SimParams, seed: u64, frames: u64) -> Result<Demonstration, ParamError> {
    params.validate()?;
    let mut rng = Rng::derive(seed, &[5]);
    let who = Participant::draw("p01".into(), params, &mut rng);
    let cubes = layout(params, &mut rng)?;
    let mut planner = Planner::new(params, &who, Rng::derive(seed, &[6]), cubes.clone());
    planner.wait_until(1.0);
    // Frames lost to drops are made up by planning a little more than asked.
    let needed = frames as f64 / params.frame_rate * (1.0 + 2.0 * params.frame_drop) + 5.0;
    let mut placements = Vec::new();
    let half = 0.5 * params.cube_size;
    while planner.now() < needed {
        let hand = if rng.chance(0.5) {
            Side::Left
        } else {
            Side::Right
        };
        let free = planner.free_cubes();
        let cube = pick(
            &mut rng,
            &free,
            &(0..params.cubes as usize)
                .map(|c| (planner.cube_pos(c), 0.0))
                .collect::<Vec<_>>(),
            planner.rest(hand),
        );
        let bases: Vec<usize> = free
            .iter()
            .copied()
            .filter(|&c| c != cube && planner.tower_height(c) < 3)
            .collect();
        let mut onto = None;
        if bases.is_empty() || rng.chance(0.4) {
            let others: Vec<V3> = planner
                .bases()
                .into_iter()
                .filter(|b| (*b - planner.cube_pos(cube)).horizontal_norm() > 1e-9)
                .collect();
            for _ in 0..100 {
                let x = rng.uniform(params.cube_area_x.min, params.cube_area_x.max);
                let y = rng.uniform(params.cube_area_y.min, params.cube_area_y.max);
                let spot = V3::new(x, y, params.table_height + half);
                if others
                    .iter()
                    .all(|o| (*o - spot).horizontal_norm() >= params.cube_spacing)
                {
                    onto = Some(Support::Table { x, y });
                    break;
                }
            }
        }
        let onto = match (onto, bases.is_empty()) {
            (Some(s), _) => s,
            (None, false) => Support::Cube(bases[rng.below(bases.len())]),
            (None, true) => break,
        };
        planner.placement(hand, cube, onto, true);
        let pause = rng.uniform(params.between_pause.min, params.between_pause.max);
        planner.wait_until(planner.now() + pause);
        placements.push(Placement {
            hand,
            cube: EntityId((2 + cube) as u32),
            onto: match onto {
                Support::Cube(c) => Target::Cube(EntityId((2 + c) as u32)),
                Support::Table { x, y } => Target::Table { x, y },
            },
        });
    }
    let plan = planner.finish(1.0);
    let id = "session".to_string();
    let task = "Rearrange the cubes, one at a time, with either hand (a long simulated session).";
    let mut demo = Demonstration {
        id: id.clone(),
        participant: who.clone(),
        hand: None,
        placements,
        header: header(params, &id, &who.code, task, vec![]),
        plan,
        params: params.clone(),
        seed,
        frame_limit: Some(frames),
    };
    let mut m = meta(&demo, seed);
    m.remove("placements");
    m.insert("placements".into(), demo.placements.len().to_string());
    demo.header.meta = m;
    Ok(demo)
}
