//! Rendering a plan into frames: the noise-free world step by step (hands moving, grips
//! closing, the VR grab system attaching and releasing cubes, released cubes dropping
//! onto what is below), its ground truth, and what a tracker would report.

use recording::{Contact, EntityId, EntityState, Frame, Pose};

use crate::motion::{bump, bump_rate, min_jerk, min_jerk_rate, SlowNoise};
use crate::params::SimParams;
use crate::rng::Rng;
use crate::script::{align_to_faces, turn, Goal, HandPlan, Plan, Support};
use crate::study::Demonstration;
use crate::truth::{Activity, HandTruth, Phase, TruthFrame};
use geometry::{Quat, V3};

const GRAVITY: f64 = 9.81;

/// Written precision: positions to 0.1 mm, quaternion components to 1e-4, velocities to
/// 1 mm/s, grip to 0.001, time to 1 microsecond.
const POSITION_STEP: f64 = 1e-4;
const ROTATION_STEP: f64 = 1e-4;
const VELOCITY_STEP: f64 = 1e-3;
const GRIP_STEP: f64 = 1e-3;
const TIME_STEP: f64 = 1e-6;

fn quantise(v: f64, step: f64) -> f32 {
    // `+ 0.0` turns -0.0 into 0.0, so that files never say "-0".
    ((v / step).round() * step + 0.0) as f32
}

fn quantise_v(v: V3, step: f64) -> recording::Vec3 {
    recording::Vec3::new(
        quantise(v.x, step),
        quantise(v.y, step),
        quantise(v.z, step),
    )
}

fn quantise_r(r: Quat) -> recording::Quaternion {
    let r = r.canonical();
    recording::Quaternion::new(
        quantise(r.x, ROTATION_STEP),
        quantise(r.y, ROTATION_STEP),
        quantise(r.z, ROTATION_STEP),
        quantise(r.w, ROTATION_STEP),
    )
}

#[derive(Debug, Clone, Copy)]
struct Active {
    start: f64,
    duration: f64,
    goal: Goal,
    arc: f64,
    /// x, y, z, yaw.
    disp: [f64; 4],
}

#[derive(Debug, Clone, Copy)]
struct GripSegment {
    t0: f64,
    g0: f64,
    target: f64,
    tau: f64,
}

impl GripSegment {
    fn at(&self, t: f64) -> f64 {
        let dt = (t - self.t0).max(0.0);
        self.target + (self.g0 - self.target) * (-dt / self.tau).exp()
    }
}

#[derive(Debug, Clone, Copy)]
struct Held {
    cube: usize,
    /// The cube's centre in the hand's frame.
    offset: V3,
    /// The cube's rotation relative to the hand's.
    rel: Quat,
}

#[derive(Debug, Clone)]
struct HandSim {
    base: [f64; 4],
    next_move: usize,
    active: Vec<Active>,
    grip: GripSegment,
    next_grip: usize,
    phase: usize,
    held: Option<Held>,
    noise: SlowNoise,
    noise_prev: V3,
    rng: Rng,
    // Noise-free state at the current step.
    pos: V3,
    vel: V3,
    rot: Quat,
    g: f64,
}

#[derive(Debug, Clone, Copy, PartialEq)]
enum CubeState {
    Resting,
    Held(usize),
    Falling { t0: f64, z0: f64, rest_z: f64 },
}

#[derive(Debug, Clone, Copy)]
struct CubeSim {
    pos: V3,
    rot: Quat,
    state: CubeState,
}

/// The frames of a demonstration with their ground truth, rendered one at a time.
#[derive(Debug, Clone)]
pub struct Frames<'a> {
    p: &'a SimParams,
    plan: &'a Plan,
    dt: f64,
    step: u64,
    written: u64,
    limit: Option<u64>,
    /// Dropped frames still to come in the current run.
    drop_left: u32,
    /// Whether the frame before was dropped.
    dropped_last: bool,
    time_rng: Rng,
    cube_rng: Rng,
    hands: [HandSim; 2],
    cubes: Vec<CubeSim>,
    cube0: usize,
    table: usize,
}

impl<'a> Frames<'a> {
    pub(crate) fn new(demo: &'a Demonstration) -> Frames<'a> {
        let p = &demo.params;
        let plan = &demo.plan;
        let dt = 1.0 / p.frame_rate;
        let seed = demo.seed;
        let hand = |i: usize| {
            let hp = &plan.hands[i];
            let mut rng = Rng::derive(seed, &[10, i as u64]);
            let noise = SlowNoise::new(&mut rng, p.hand_noise, p.hand_noise_time, dt);
            let mut h = HandSim {
                base: [hp.rest.x, hp.rest.y, hp.rest.z, hp.natural_yaw],
                next_move: 0,
                active: Vec::new(),
                grip: GripSegment {
                    t0: 0.0,
                    g0: hp.grip_start,
                    target: hp.grip_start,
                    tau: 1.0,
                },
                next_grip: 0,
                phase: 0,
                held: None,
                noise_prev: noise.value(),
                noise,
                rng,
                pos: hp.rest,
                vel: V3::ZERO,
                rot: Quat::IDENTITY,
                g: hp.grip_start,
            };
            // The base is the rest pose; the drift is added when the hand is evaluated.
            h.evaluate(hp, 0.0);
            h
        };
        let hands = [hand(0), hand(1)];
        let cubes = plan
            .cubes
            .iter()
            .map(|&(pos, yaw)| CubeSim {
                pos,
                rot: Quat::from_yaw(yaw),
                state: CubeState::Resting,
            })
            .collect::<Vec<_>>();
        let table = 2 + cubes.len();
        Frames {
            p,
            plan,
            dt,
            step: 0,
            written: 0,
            limit: demo.frame_limit,
            drop_left: 0,
            dropped_last: false,
            time_rng: Rng::derive(seed, &[11]),
            cube_rng: Rng::derive(seed, &[12]),
            hands,
            cubes,
            cube0: 2,
            table,
        }
    }

    fn done(&self) -> bool {
        match self.limit {
            Some(n) => self.written >= n,
            None => self.step as f64 * self.dt > self.plan.end,
        }
    }

    /// Renders the next frame into `frame` and `truth` (reusing their allocations).
    /// Returns `false` after the last frame.
    pub fn next_into(&mut self, frame: &mut Frame, truth: &mut TruthFrame) -> bool {
        loop {
            if self.done() {
                return false;
            }
            let k = self.step;
            self.step += 1;
            let nominal = k as f64 * self.dt;
            if nominal < self.plan.start {
                // Before the recording starts (mid-motion): the world moves, unseen.
                self.advance(nominal);
                continue;
            }
            let jitter = if k == 0 {
                0.0
            } else {
                self.time_rng
                    .gauss(0.0, self.p.time_jitter)
                    .clamp(-0.4 * self.dt, 0.4 * self.dt)
            };
            let t = ((nominal + jitter) / TIME_STEP).round() * TIME_STEP;
            let dropped = self.drop(k);
            self.advance(t);
            self.observe(t, frame);
            if dropped {
                continue;
            }
            self.ground_truth(t, truth);
            self.written += 1;
            return true;
        }
    }

    /// Whether frame `k` is dropped: on its own chance, or as part of a run of up to
    /// `frame_drop_run` frames (after which a frame is kept).
    fn drop(&mut self, k: u64) -> bool {
        let run = self.p.frame_drop_run;
        let dropped = if self.drop_left > 0 {
            self.drop_left -= 1;
            true
        } else if run > 1 && self.dropped_last {
            false
        } else {
            let starts = k > 0 && self.time_rng.chance(self.p.frame_drop);
            if starts && run > 1 {
                self.drop_left = self.time_rng.below(run as usize) as u32;
            }
            starts
        };
        self.dropped_last = dropped;
        dropped
    }

    /// Moves the noise-free world to time `t`.
    fn advance(&mut self, t: f64) {
        let p = self.p;
        for i in 0..2 {
            let hp = &self.plan.hands[i];
            // Movements that start now get their displacement from the world as it is.
            while let Some(m) = hp.moves.get(self.hands[i].next_move) {
                if m.start > t {
                    break;
                }
                let fin = self.hands[i].final_pose(None);
                let disp = self.resolve(i, m.goal, m.start + m.duration, fin);
                let h = &mut self.hands[i];
                h.active.push(Active {
                    start: m.start,
                    duration: m.duration,
                    goal: m.goal,
                    arc: m.arc,
                    disp,
                });
                h.next_move += 1;
            }
            let h = &mut self.hands[i];
            h.retire(t);
            while let Some(e) = hp.grips.get(h.next_grip) {
                if e.time > t {
                    break;
                }
                let g0 = h.grip.at(e.time);
                h.grip = GripSegment {
                    t0: e.time,
                    g0,
                    target: e.target,
                    tau: e.tau,
                };
                h.next_grip += 1;
            }
            while hp.phases.get(h.phase + 1).is_some_and(|m| m.time <= t) {
                h.phase += 1;
            }
            h.evaluate(hp, t);
        }
        // The grab system: attach when the grip closes near the cube being grasped,
        // release when it opens.
        for i in 0..2 {
            let hp = &self.plan.hands[i];
            let mark = hp.phases[self.hands[i].phase];
            let g = self.hands[i].g;
            match self.hands[i].held {
                None if g >= p.grab_grip => {
                    let Some(c) = mark.object else { continue };
                    let grasping = matches!(mark.phase, Phase::Grasp | Phase::Carry);
                    let free = !matches!(self.cubes[c].state, CubeState::Held(_));
                    let near = (self.cubes[c].pos - self.hands[i].pos).norm() <= p.grasp_radius;
                    if grasping && free && near {
                        self.attach(i, c);
                    }
                }
                Some(held) if g < p.release_grip => {
                    self.hands[i].held = None;
                    self.release(held.cube, t);
                }
                _ => {}
            }
        }
        for c in 0..self.cubes.len() {
            match self.cubes[c].state {
                CubeState::Held(i) => {
                    if let Some(held) = self.hands[i].held {
                        let h = &self.hands[i];
                        self.cubes[c].pos = h.pos + h.rot.rotate(held.offset);
                        self.cubes[c].rot = h.rot.mul(held.rel).normalised();
                    }
                }
                CubeState::Falling { t0, z0, rest_z } => {
                    let dt = t - t0;
                    let z = z0 - 0.5 * GRAVITY * dt * dt;
                    if z <= rest_z {
                        self.cubes[c].pos.z = rest_z;
                        self.cubes[c].state = CubeState::Resting;
                    } else {
                        self.cubes[c].pos.z = z;
                    }
                }
                CubeState::Resting => {}
            }
        }
    }

    fn attach(&mut self, i: usize, c: usize) {
        let h = &self.hands[i];
        let inv = h.rot.conjugate();
        let held = Held {
            cube: c,
            offset: inv.rotate(self.cubes[c].pos - h.pos),
            rel: inv.mul(self.cubes[c].rot).normalised(),
        };
        self.hands[i].held = Some(held);
        self.cubes[c].state = CubeState::Held(i);
        // Placing movements already under way were aimed with a guessed grip on the cube;
        // aim them again with the real one. They have barely started, so the hand does
        // not jump.
        let mut order: Vec<usize> = (0..self.hands[i].active.len()).collect();
        order.sort_by(|&a, &b| {
            let (aa, bb) = (&self.hands[i].active[a], &self.hands[i].active[b]);
            aa.start.total_cmp(&bb.start)
        });
        for idx in order {
            let a = self.hands[i].active[idx];
            if matches!(a.goal, Goal::Place { .. }) {
                let fin = self.hands[i].final_pose(Some(a.start));
                let disp = self.resolve(i, a.goal, a.start + a.duration, fin);
                self.hands[i].active[idx].disp = disp;
            }
        }
    }

    /// Lets a cube go: it keeps its heading, turns flat and drops onto what is below.
    fn release(&mut self, c: usize, t: f64) {
        let half = 0.5 * self.p.cube_size;
        let me = self.cubes[c];
        let bottom = me.pos.z - half;
        let mut top = f64::NEG_INFINITY;
        if self.on_table(me.pos) {
            top = self.p.table_height;
        }
        for (j, other) in self.cubes.iter().enumerate() {
            if j == c || matches!(other.state, CubeState::Held(_)) {
                continue;
            }
            let other_z = match other.state {
                CubeState::Falling { rest_z, .. } => rest_z,
                _ => other.pos.z,
            };
            let other_top = other_z + half;
            let over =
                (me.pos.x - other.pos.x).abs() < half && (me.pos.y - other.pos.y).abs() < half;
            if over && other_top <= bottom + 0.01 && other_top > top {
                top = other_top;
            }
        }
        if !top.is_finite() {
            top = 0.0; // off the table: the floor
        }
        let rest_z = top + half;
        let cube = &mut self.cubes[c];
        cube.rot = Quat::from_yaw(cube.rot.yaw());
        if cube.pos.z <= rest_z {
            cube.pos.z = rest_z;
            cube.state = CubeState::Resting;
        } else {
            cube.state = CubeState::Falling {
                t0: t,
                z0: cube.pos.z,
                rest_z,
            };
        }
    }

    fn on_table(&self, pos: V3) -> bool {
        let p = self.p;
        (pos.x - p.table_x).abs() <= 0.5 * p.table_depth && pos.y.abs() <= 0.5 * p.table_width
    }

    /// The displacement (x, y, z, yaw) of a movement towards `goal` ending at `t_end`,
    /// for a hand whose movements so far end at `fin`.
    fn resolve(&self, i: usize, goal: Goal, t_end: f64, fin: [f64; 4]) -> [f64; 4] {
        let p = self.p;
        let hp = &self.plan.hands[i];
        let h = &self.hands[i];
        let drift = hp.drift.at(t_end);
        let fin_pos = V3::new(fin[0], fin[1], fin[2]);
        let to = |target: V3, yaw: f64, fraction: f64| {
            let d = (target - drift - fin_pos) * fraction;
            [d.x, d.y, d.z, turn(fin[3], yaw) * fraction]
        };
        match goal {
            Goal::Rest => to(hp.rest, hp.natural_yaw, 1.0),
            Goal::Relative(v) => [v.x, v.y, v.z, 0.0],
            Goal::Grasp {
                cube,
                fraction,
                error,
                align,
            } => {
                let c = &self.cubes[cube];
                let palm = c.pos + V3::new(0.0, 0.0, p.grasp_height) + error;
                let yaw = align_to_faces(c.rot.yaw() + align, hp.natural_yaw);
                to(palm, yaw, fraction)
            }
            Goal::Place {
                onto,
                height,
                error,
                align,
            } => {
                let (offset, rel) = match h.held {
                    Some(held) => (held.offset, held.rel),
                    None => {
                        // Not holding yet (a grasp on the fly): guess the grip from where
                        // the cube is now.
                        let inv = h.rot.conjugate();
                        let c = hp
                            .phases
                            .get(h.phase)
                            .and_then(|m| m.object)
                            .map_or(&self.cubes[0], |c| &self.cubes[c]);
                        (inv.rotate(c.pos - h.pos), inv.mul(c.rot))
                    }
                };
                let half = 0.5 * p.cube_size;
                let (top, support_yaw) = match onto {
                    Support::Cube(s) => {
                        let s = &self.cubes[s];
                        (s.pos + V3::new(0.0, 0.0, half), Some(s.rot.yaw()))
                    }
                    Support::Table { x, y } => (V3::new(x, y, p.table_height), None),
                };
                let centre = top + V3::new(error.0, error.1, half + height);
                let rel_yaw = rel.yaw();
                let cube_yaw_now = fin[3] + rel_yaw;
                let cube_yaw = match support_yaw {
                    Some(y) => align_to_faces(y + align, cube_yaw_now),
                    None => cube_yaw_now,
                };
                let hand_yaw = cube_yaw - rel_yaw;
                let wobble = hp.wobble.at(t_end);
                let rot_end = Quat::from_euler(wobble.x, wobble.y, hand_yaw);
                let palm = centre - rot_end.rotate(offset);
                let d = palm - drift - fin_pos;
                [d.x, d.y, d.z, hand_yaw - fin[3]]
            }
        }
    }

    /// What the tracker reports at time `t`.
    fn observe(&mut self, t: f64, frame: &mut Frame) {
        let p = self.p;
        let n = self.cubes.len() + 3;
        frame.clear(n);
        frame.time = t;
        let rot_sd = p.hand_rot_noise_deg.to_radians();
        let mut observed = [(V3::ZERO, Quat::IDENTITY); 2];
        for (i, seen) in observed.iter_mut().enumerate() {
            let h = &mut self.hands[i];
            let slow = h.noise.step(&mut h.rng);
            let slow_rate = (slow - h.noise_prev) * (1.0 / self.dt);
            h.noise_prev = slow;
            let jitter = V3::new(
                h.rng.gauss(0.0, p.hand_jitter),
                h.rng.gauss(0.0, p.hand_jitter),
                h.rng.gauss(0.0, p.hand_jitter),
            );
            let pos = h.pos + slow + jitter;
            let wrong = V3::new(
                h.rng.gauss(0.0, rot_sd),
                h.rng.gauss(0.0, rot_sd),
                h.rng.gauss(0.0, rot_sd),
            );
            let rot = h.rot.mul(Quat::from_rotation_vector(wrong)).normalised();
            let vel = h.vel
                + slow_rate
                + V3::new(
                    h.rng.gauss(0.0, p.velocity_noise),
                    h.rng.gauss(0.0, p.velocity_noise),
                    h.rng.gauss(0.0, p.velocity_noise),
                );
            let grip = (h.g + h.rng.gauss(0.0, p.grip_noise)).clamp(0.0, 1.0);
            *seen = (pos, rot);
            frame.states[i] = Some(EntityState {
                pose: Pose {
                    position: quantise_v(pos, POSITION_STEP),
                    orientation: quantise_r(rot),
                },
                velocity: p.velocities.then(|| quantise_v(vel, VELOCITY_STEP)),
                grip: Some(quantise(grip, GRIP_STEP)),
                holding: if p.held {
                    h.held.map(|held| EntityId((self.cube0 + held.cube) as u32))
                } else {
                    None
                },
            });
        }
        for c in 0..self.cubes.len() {
            let cube = self.cubes[c];
            let held = match cube.state {
                CubeState::Held(i) => self.hands[i].held.map(|x| (i, x)),
                _ => None,
            };
            let (pos, rot) = match held {
                Some((i, held)) => {
                    // A held cube is drawn at the tracked hand: it shares the hand's error.
                    let (hp, hr) = observed[i];
                    (hp + hr.rotate(held.offset), hr.mul(held.rel))
                }
                _ => {
                    let j = V3::new(
                        self.cube_rng.gauss(0.0, p.cube_jitter),
                        self.cube_rng.gauss(0.0, p.cube_jitter),
                        self.cube_rng.gauss(0.0, p.cube_jitter),
                    );
                    (cube.pos + j, cube.rot)
                }
            };
            frame.states[self.cube0 + c] = Some(EntityState {
                pose: Pose {
                    position: quantise_v(pos, POSITION_STEP),
                    orientation: quantise_r(rot),
                },
                velocity: None,
                grip: None,
                holding: None,
            });
        }
        if p.contacts {
            self.contacts(frame);
        }
    }

    /// Contacts from the noise-free geometry: a hand and the cube it holds; a cube and
    /// the table or cube whose top its bottom is within `contact_distance` of.
    fn contacts(&self, frame: &mut Frame) {
        let p = self.p;
        let half = 0.5 * p.cube_size;
        let id = |i: usize| EntityId(i as u32);
        for (i, h) in self.hands.iter().enumerate() {
            if let Some(held) = h.held {
                frame.contacts.push(Contact {
                    a: id(i),
                    b: id(self.cube0 + held.cube),
                });
            }
        }
        for (c, cube) in self.cubes.iter().enumerate() {
            let bottom = cube.pos.z - half;
            if self.on_table(cube.pos) && (bottom - p.table_height).abs() <= p.contact_distance {
                frame.contacts.push(Contact {
                    a: id(self.cube0 + c),
                    b: id(self.table),
                });
            }
            for (j, other) in self.cubes.iter().enumerate() {
                if j == c {
                    continue;
                }
                let top = other.pos.z + half;
                let overlap = (cube.pos.x - other.pos.x).abs() < p.cube_size
                    && (cube.pos.y - other.pos.y).abs() < p.cube_size;
                if overlap && (bottom - top).abs() <= p.contact_distance {
                    frame.contacts.push(Contact {
                        a: id(self.cube0 + c),
                        b: id(self.cube0 + j),
                    });
                }
            }
        }
    }

    fn ground_truth(&self, t: f64, truth: &mut TruthFrame) {
        let p = self.p;
        truth.time = t;
        truth.hands.clear();
        for (i, h) in self.hands.iter().enumerate() {
            let mark = self.plan.hands[i].phases[h.phase];
            let speed = h.vel.norm();
            let moving = speed > p.move_speed;
            let in_hand = h.held.map(|x| x.cube);
            // The paper's Table 2 rule on the noise-free state: the nearest cube within
            // `acted_on_distance` of the palm that the hand moves towards, never the one
            // in hand. Not only the scripted target: a hand passing close by a cube on
            // its way, heading for it, acts on it as the paper defines it.
            let mut acted_on = None;
            let mut nearest = p.acted_on_distance;
            for (c, cube) in self.cubes.iter().enumerate() {
                if Some(c) == in_hand {
                    continue;
                }
                let d = cube.pos - h.pos;
                let dist = d.norm();
                if dist < nearest && dist > 0.0 && h.vel.dot(d) / dist > p.toward_speed {
                    acted_on = Some(c);
                    nearest = dist;
                }
            }
            let cube = |c: usize| EntityId((self.cube0 + c) as u32);
            truth.hands.push(HandTruth {
                hand: EntityId(i as u32),
                phase: mark.phase,
                activity: Activity::classify(moving, acted_on.is_some(), in_hand.is_some()),
                moving,
                speed: quantise(speed, VELOCITY_STEP),
                target: mark.target.map(cube),
                acted_on: acted_on.map(cube),
                in_hand: in_hand.map(cube),
            });
        }
    }
}

impl HandSim {
    /// Where the hand's movements so far (those started before `before`, if given) end.
    fn final_pose(&self, before: Option<f64>) -> [f64; 4] {
        let mut f = self.base;
        for a in &self.active {
            if before.is_some_and(|b| a.start >= b) {
                continue;
            }
            for (x, d) in f.iter_mut().zip(a.disp) {
                *x += d;
            }
        }
        f
    }

    fn retire(&mut self, t: f64) {
        let base = &mut self.base;
        self.active.retain(|a| {
            if a.start + a.duration <= t {
                for (x, d) in base.iter_mut().zip(a.disp) {
                    *x += d;
                }
                false
            } else {
                true
            }
        });
    }

    fn evaluate(&mut self, hp: &HandPlan, t: f64) {
        let mut pos = V3::new(self.base[0], self.base[1], self.base[2]);
        let mut vel = V3::ZERO;
        let mut yaw = self.base[3];
        for a in &self.active {
            let tau = (t - a.start) / a.duration;
            let s = min_jerk(tau);
            let r = min_jerk_rate(tau) / a.duration;
            let d = V3::new(a.disp[0], a.disp[1], a.disp[2]);
            pos += d * s + V3::new(0.0, 0.0, a.arc * bump(tau));
            vel += d * r + V3::new(0.0, 0.0, a.arc * bump_rate(tau) / a.duration);
            yaw += a.disp[3] * s;
        }
        let (drift, drift_rate) = hp.drift.with_rate(t);
        let wobble = hp.wobble.at(t);
        self.pos = pos + drift;
        self.vel = vel + drift_rate;
        self.rot = Quat::from_euler(wobble.x, wobble.y, yaw);
        self.g = self.grip.at(t);
    }
}
