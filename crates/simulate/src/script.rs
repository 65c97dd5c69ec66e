//! The script of a demonstration: for each hand, a timeline of minimum-jerk movements,
//! grip changes and phases, planned before any frame is rendered.
//!
//! Movement goals are symbolic ("grasp cube 3", "put the held cube 6 cm above cube 5"):
//! the renderer turns each into a displacement when the movement starts, from where
//! things really are then (a person corrects by sight). Durations are fixed here, from
//! planned distances.

use crate::motion::{min_jerk, Drift};
use crate::params::{Interval, SimParams};
use crate::rng::Rng;
use crate::study::{Participant, Side};
use crate::truth::Phase;
use geometry::{wrap_angle, V3};

/// Where a cube is put: on another cube, or on the table at (x, y).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum Support {
    Cube(usize),
    Table { x: f64, y: f64 },
}

/// What a movement aims for.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum Goal {
    /// The hand's rest pose.
    Rest,
    /// The palm above a cube, ready to close; `fraction` < 1 stops part way (an aborted
    /// reach). `error` is where the palm ends relative to the ideal grasp; `align` the
    /// error of the hand's heading relative to the cube's faces (radians).
    Grasp {
        cube: usize,
        fraction: f64,
        error: V3,
        align: f64,
    },
    /// The held cube `height` above its place on `onto`, off-centre by `error`.
    Place {
        onto: Support,
        height: f64,
        error: (f64, f64),
        align: f64,
    },
    /// A displacement (fidgets, small adjustments, lifting the hand away).
    Relative(V3),
}

#[derive(Debug, Clone, Copy)]
pub(crate) struct Move {
    pub start: f64,
    pub duration: f64,
    pub goal: Goal,
    /// Height of the movement's arc (m).
    pub arc: f64,
}

#[derive(Debug, Clone, Copy)]
pub(crate) struct GripEvent {
    pub time: f64,
    pub target: f64,
    pub tau: f64,
}

#[derive(Debug, Clone, Copy)]
pub(crate) struct PhaseMark {
    pub time: f64,
    pub phase: Phase,
    /// The cube being handled: the one to grasp, or the one held.
    pub object: Option<usize>,
    /// The cube the hand goes for (`actedOn` candidate).
    pub target: Option<usize>,
}

#[derive(Debug, Clone)]
pub(crate) struct HandPlan {
    pub rest: V3,
    pub natural_yaw: f64,
    pub grip_start: f64,
    pub drift: Drift,
    /// Roll (x) and pitch (y) of the wrist, radians.
    pub wobble: Drift,
    pub moves: Vec<Move>,
    pub grips: Vec<GripEvent>,
    pub phases: Vec<PhaseMark>,
}

#[derive(Debug, Clone)]
pub(crate) struct Plan {
    pub hands: [HandPlan; 2],
    /// Cube positions (centres) and headings at the start.
    pub cubes: Vec<(V3, f64)>,
    /// When the recording starts (0, or mid-motion: `start_cut`).
    pub start: f64,
    /// When the recording ends.
    pub end: f64,
}

/// When the steps of a planned placement happen (s).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Timing {
    /// The hand closes on the cube.
    pub grasp: f64,
    /// The hand starts opening to let the cube go.
    pub release: f64,
}

/// The cube's heading plus a multiple of 90 degrees, nearest to `reference`.
pub(crate) fn align_to_faces(cube_yaw: f64, reference: f64) -> f64 {
    let q = std::f64::consts::FRAC_PI_2;
    cube_yaw + ((reference - cube_yaw) / q).round() * q
}

#[derive(Debug, Clone, Copy)]
struct PlannedCube {
    pos: V3,
    yaw: f64,
    /// The cube this one stands on (None: the table).
    on: Option<usize>,
    /// The cube standing on this one.
    under: Option<usize>,
}

/// Plans placements one after the other, keeping a planned picture of the scene.
pub(crate) struct Planner<'a> {
    p: &'a SimParams,
    who: &'a Participant,
    rng: Rng,
    cubes: Vec<PlannedCube>,
    hands: [HandPlan; 2],
    hand_pos: [V3; 2],
    free_at: [f64; 2],
    start: Vec<(V3, f64)>,
    /// Per cube: from when it stands where the plan put it last with no hand on it (a
    /// hand waits for it before carrying a cube onto it, when `wait_for_support`).
    ready_at: Vec<f64>,
    /// Both hands work at once ([`crate::Style::TwoHanded`]): a placement onto a cube
    /// another hand is still placing waits for it.
    wait_for_support: bool,
}

impl<'a> Planner<'a> {
    pub fn new(
        p: &'a SimParams,
        who: &'a Participant,
        mut rng: Rng,
        cubes: Vec<(V3, f64)>,
    ) -> Self {
        let hand = |rng: &mut Rng, side: Side| {
            let rest = V3::new(
                p.rest_x,
                side.sign() * p.rest_y,
                p.table_height + p.rest_height,
            );
            let wobble = p.wrist_wobble_deg.to_radians();
            HandPlan {
                rest,
                natural_yaw: -side.sign() * p.natural_yaw_deg.to_radians(),
                grip_start: who.grip_rest,
                drift: Drift::new(
                    rng,
                    [p.drift, p.drift, p.drift_z],
                    p.drift_period.min,
                    p.drift_period.max,
                ),
                wobble: Drift::new(
                    rng,
                    [wobble, wobble, 0.0],
                    0.3 * p.drift_period.min,
                    0.3 * p.drift_period.max,
                ),
                moves: Vec::new(),
                grips: Vec::new(),
                phases: vec![PhaseMark {
                    time: 0.0,
                    phase: Phase::Rest,
                    object: None,
                    target: None,
                }],
            }
        };
        let hands = [hand(&mut rng, Side::Left), hand(&mut rng, Side::Right)];
        let hand_pos = [hands[0].rest, hands[1].rest];
        Planner {
            p,
            who,
            rng,
            cubes: cubes
                .iter()
                .map(|&(pos, yaw)| PlannedCube {
                    pos,
                    yaw,
                    on: None,
                    under: None,
                })
                .collect(),
            hands,
            hand_pos,
            free_at: [0.0, 0.0],
            ready_at: vec![0.0; cubes.len()],
            start: cubes,
            wait_for_support: p.style == crate::Style::TwoHanded,
        }
    }

    fn draw(&mut self, i: Interval) -> f64 {
        self.rng.uniform(i.min, i.max)
    }

    /// The earliest time both hands are free.
    pub fn now(&self) -> f64 {
        self.free_at[0].max(self.free_at[1])
    }

    /// Lets time pass before the next placement.
    pub fn wait_until(&mut self, t: f64) {
        for f in &mut self.free_at {
            *f = f.max(t);
        }
    }

    /// Lets time pass before the next placement of one hand (the other may be busy).
    pub fn wait_hand_until(&mut self, side: Side, t: f64) {
        let f = &mut self.free_at[side.index()];
        *f = f.max(t);
    }

    /// Cubes with nothing on them.
    pub fn free_cubes(&self) -> Vec<usize> {
        (0..self.cubes.len())
            .filter(|&c| self.cubes[c].under.is_none())
            .collect()
    }

    /// How many cubes stand in the tower whose top is `c`.
    pub fn tower_height(&self, c: usize) -> usize {
        let mut n = 1;
        let mut at = c;
        while let Some(below) = self.cubes[at].on {
            n += 1;
            at = below;
        }
        n
    }

    /// Centres of the towers' bases (for finding free table spots).
    pub fn bases(&self) -> Vec<V3> {
        self.cubes
            .iter()
            .filter(|c| c.on.is_none())
            .map(|c| c.pos)
            .collect()
    }

    /// The position of a cube in the plan.
    pub fn cube_pos(&self, c: usize) -> V3 {
        self.cubes[c].pos
    }

    /// The rest position of a hand.
    pub fn rest(&self, side: Side) -> V3 {
        self.hands[side.index()].rest
    }

    fn duration(&mut self, side: Side, distance: f64) -> f64 {
        let slow = if side == self.who.dominant {
            1.0
        } else {
            self.p.off_hand_slowdown
        };
        let jitter = self.rng.factor(self.p.move_time_jitter);
        (self.p.move_time_floor + distance / self.who.mean_speed) * slow * jitter
    }

    fn support_top(&self, s: Support) -> V3 {
        match s {
            Support::Cube(c) => self.cubes[c].pos + V3::new(0.0, 0.0, 0.5 * self.p.cube_size),
            Support::Table { x, y } => V3::new(x, y, self.p.table_height),
        }
    }

    /// Plans one placement: `cube` onto `onto` with the hand `side`. `last` sends the
    /// hand back to rest afterwards. With `wait_for_support`, a hand whose support is
    /// still being placed by the other hand grasps its cube and holds it still (a Take)
    /// until that hand has let go and leaves.
    pub fn placement(&mut self, side: Side, cube: usize, onto: Support, last: bool) -> Timing {
        let p = self.p;
        // When the support stands ready (never later than now in the paper's style).
        let ready = match onto {
            Support::Cube(s) if self.wait_for_support => self.ready_at[s],
            _ => f64::NEG_INFINITY,
        };
        let h = side.index();
        let mut t = self.free_at[h];
        let mut pos = self.hand_pos[h];
        let up = |z: f64| V3::new(0.0, 0.0, z);

        // An aborted reach: head for another cube, then redirect.
        let distractors: Vec<usize> = self
            .free_cubes()
            .into_iter()
            .filter(|&c| c != cube && Support::Cube(c) != onto)
            // Not a cube the other hand is busy with.
            .filter(|&c| !self.wait_for_support || self.ready_at[c] <= t)
            .collect();
        if !distractors.is_empty() && self.rng.chance(self.who.abort) {
            let x = distractors[self.rng.below(distractors.len())];
            let f = self.draw(p.abort_fraction);
            let goal = self.cubes[x].pos + up(p.grasp_height);
            let d = (goal - pos).norm() * f;
            let dur = self.duration(side, d);
            let arc = self.draw(p.reach_arc) * f;
            self.mark(h, t, Phase::Reach, Some(x), Some(x));
            self.hands[h].moves.push(Move {
                start: t,
                duration: dur,
                goal: Goal::Grasp {
                    cube: x,
                    fraction: f,
                    error: V3::ZERO,
                    align: 0.0,
                },
                arc,
            });
            pos = pos + (goal - pos) * f;
            // Redirected while still moving (blended), or after a short hesitation.
            t += dur * self.draw(p.abort_redirect);
        }

        // The reach.
        let error = V3::new(
            self.rng.gauss(0.0, p.grasp_error),
            self.rng.gauss(0.0, p.grasp_error),
            self.rng.gauss(0.0, p.grasp_error),
        );
        let grasp = self.cubes[cube].pos + up(p.grasp_height) + error;
        let reach_time = self.duration(side, (grasp - pos).norm());
        let align = self.rng.gauss(0.0, p.align_error_deg.to_radians());
        let arc = self.draw(p.reach_arc);
        self.mark(h, t, Phase::Reach, Some(cube), Some(cube));
        self.hands[h].moves.push(Move {
            start: t,
            duration: reach_time,
            goal: Goal::Grasp {
                cube,
                fraction: 1.0,
                error,
                align,
            },
            arc,
        });
        let open = self.who.grip_open;
        self.grip(
            h,
            t + p.preshape_at * reach_time,
            open,
            2.0 * p.grip_open_time,
        );
        let arrive = t + reach_time;

        // The grasp: rest after closing (Reach, Take, Put) or lift on the fly (Put2).
        let hold = self.draw(p.grip_hold);
        let regrasp = self.rng.chance(self.who.regrasp);
        // A lift on the fly cannot wait: a hand whose support is not ready by then rests.
        let must_wait = ready > arrive - 0.3;
        let rests = regrasp || must_wait || self.rng.chance(self.who.rest_after_grasp);
        let grasp_at;
        // Time for the grip to rise from open to the grab threshold.
        let to_grab = p.grip_close_time * ((hold - open) / (hold - p.grab_grip)).ln();
        let lift_at;
        if rests {
            let close = arrive - self.draw(p.close_lead);
            grasp_at = close;
            self.mark(h, close, Phase::Grasp, Some(cube), Some(cube));
            self.grip(h, close, hold, p.grip_close_time);
            let pause = self.draw(p.take_pause);
            if regrasp {
                let reopen = close + to_grab + self.rng.uniform(0.3, 0.5);
                let loosened = self.draw(p.regrasp_grip);
                self.grip(h, reopen, loosened, p.grip_open_time);
                let angle = self.rng.uniform(0.0, std::f64::consts::TAU);
                let shift = self.draw(p.regrasp_shift);
                self.hands[h].moves.push(Move {
                    start: reopen + 0.05,
                    duration: self.rng.uniform(0.25, 0.4),
                    goal: Goal::Relative(V3::new(angle.cos() * shift, angle.sin() * shift, 0.0)),
                    arc: 0.0,
                });
                let close_again = reopen + self.rng.uniform(0.5, 0.7);
                let hold_again = self.draw(p.grip_hold);
                self.grip(h, close_again, hold_again, p.grip_close_time);
                lift_at = (close_again + to_grab + pause).max(ready);
            } else {
                lift_at = (arrive + pause.max(to_grab + 0.2)).max(ready);
            }
        } else {
            // The lift starts while the reach still has a fraction `overlap` of its way to
            // go, and no more than `flow_reach` of distance.
            let distance = (grasp - pos).norm();
            let mut overlap = self.draw(p.flow_overlap);
            while overlap > 0.01 && distance * (1.0 - min_jerk(1.0 - overlap)) > p.flow_reach {
                overlap *= 0.9;
            }
            lift_at = arrive - overlap * reach_time;
            // The grip reaches the grab threshold just before the lift starts, while the
            // hand still moves towards the cube.
            let close = lift_at - self.rng.uniform(0.0, 0.04) - to_grab;
            grasp_at = close;
            self.mark(h, close, Phase::Grasp, Some(cube), Some(cube));
            self.grip(h, close, hold, p.grip_close_time);
        }

        // The carry, to above the place.
        let support_cube = match onto {
            Support::Cube(s) => Some(s),
            Support::Table { .. } => None,
        };
        let place_error = (
            self.rng.gauss(0.0, p.placement_error),
            self.rng.gauss(0.0, p.placement_error),
        );
        let align = self.rng.gauss(0.0, p.align_error_deg.to_radians());
        let above = self.draw(p.above_target);
        let centre =
            self.support_top(onto) + V3::new(place_error.0, place_error.1, 0.5 * p.cube_size);
        let pre = centre + up(above + p.grasp_height);
        let carry_arc = self.draw(p.carry_arc);
        let lift_height = self.draw(p.lift_height);
        let lifted = grasp + up(lift_height);
        let carry_time = self.duration(side, (pre - lifted).norm() + carry_arc + lift_height);
        // A lift on the fly is quicker: it takes over from the reach's speed.
        let quick = if rests { 1.0 } else { 0.6 };
        let lift_time = (self.draw(p.lift_share) * carry_time * quick).max(0.2);
        self.mark(h, lift_at, Phase::Carry, Some(cube), support_cube);
        self.hands[h].moves.push(Move {
            start: lift_at,
            duration: lift_time,
            goal: Goal::Relative(up(lift_height)),
            arc: 0.0,
        });
        self.hands[h].moves.push(Move {
            start: lift_at,
            duration: carry_time,
            goal: Goal::Place {
                onto,
                height: above,
                error: place_error,
                align,
            },
            arc: carry_arc,
        });

        // The approach: blended into the carry, or after hovering.
        let approach_at = if self.rng.chance(self.who.hover) {
            lift_at + carry_time + self.draw(p.hover_time)
        } else {
            lift_at + carry_time * (1.0 - self.draw(p.approach_overlap))
        };
        let slow = if side == self.who.dominant {
            1.0
        } else {
            p.off_hand_slowdown
        };
        // The descent ends after the carry does, whatever their overlap.
        let carry_end = lift_at + carry_time;
        let approach_time = (self.draw(p.approach_time) * slow).max(carry_end - approach_at + 0.15);
        let clearance = self.draw(p.place_clearance);
        self.mark(h, approach_at, Phase::Approach, Some(cube), support_cube);
        self.hands[h].moves.push(Move {
            start: approach_at,
            duration: approach_time,
            goal: Goal::Place {
                onto,
                height: clearance,
                error: place_error,
                align,
            },
            arc: 0.0,
        });

        // The release.
        let release_at = approach_at + approach_time - self.draw(p.release_lead);
        self.mark(h, release_at, Phase::Release, Some(cube), support_cube);
        self.grip(h, release_at, open, p.grip_open_time);
        let mut leave_at = release_at + self.draw(p.release_pause);

        // Update the planned scene.
        if let Some(below) = self.cubes[cube].on {
            self.cubes[below].under = None;
        }
        let yaw = match onto {
            Support::Cube(s) => self.cubes[s].yaw,
            Support::Table { .. } => self.cubes[cube].yaw,
        };
        self.cubes[cube] = PlannedCube {
            pos: centre,
            yaw,
            on: support_cube,
            under: None,
        };
        if let Some(s) = support_cube {
            self.cubes[s].under = Some(cube);
        }
        let placed_palm = centre + up(clearance + p.grasp_height);

        // An adjustment: the hand closes on the cube again where it stands, lifts it a
        // little, straightens it over its support and sets it down once more.
        if self.rng.chance(self.who.adjust) {
            leave_at = self.adjust(h, side, cube, onto, leave_at, hold, to_grab);
        }
        self.ready_at[cube] = leave_at;
        let timing = Timing {
            grasp: grasp_at,
            release: release_at,
        };

        // The retreat: back to rest, or up and away towards the next cube.
        self.mark(h, leave_at, Phase::Retreat, None, None);
        let rest_grip = self.who.grip_rest;
        self.grip(h, leave_at + 0.15, rest_grip, p.grip_relax_time);
        if last || self.rng.chance(self.who.return_between) {
            let rest = self.hands[h].rest;
            let dur = self.duration(side, (rest - placed_palm).norm());
            let arc = self.draw(p.reach_arc);
            self.hands[h].moves.push(Move {
                start: leave_at,
                duration: dur,
                goal: Goal::Rest,
                arc,
            });
            self.mark(h, leave_at + dur, Phase::Rest, None, None);
            self.hand_pos[h] = rest;
            self.free_at[h] = leave_at
                + dur
                + if last {
                    0.0
                } else {
                    self.draw(p.between_pause)
                };
        } else {
            let rise = self.draw(p.lift_away);
            let lift = V3::new(-0.4 * rise * self.rng.f64(), 0.0, rise);
            let dur = self.rng.uniform(0.4, 0.6);
            self.hands[h].moves.push(Move {
                start: leave_at,
                duration: dur,
                goal: Goal::Relative(lift),
                arc: 0.0,
            });
            self.hand_pos[h] = placed_palm + lift;
            // The next reach starts while the hand still rises.
            self.free_at[h] = leave_at + dur * self.rng.uniform(0.5, 0.9);
        }
        timing
    }

    /// Plans an adjustment of `cube`, just put on `onto` by the hand `h`, starting at
    /// `from` with the palm still above it; returns when the hand may leave.
    #[allow(clippy::too_many_arguments)]
    fn adjust(
        &mut self,
        h: usize,
        side: Side,
        cube: usize,
        onto: Support,
        from: f64,
        hold: f64,
        to_grab: f64,
    ) -> f64 {
        let p = self.p;
        let support_cube = match onto {
            Support::Cube(s) => Some(s),
            Support::Table { .. } => None,
        };
        self.mark(h, from, Phase::Grasp, Some(cube), Some(cube));
        self.grip(h, from, hold, p.grip_close_time);
        let lift_at = from + to_grab + self.draw(p.take_pause);
        let rise = self.draw(p.adjust_lift);
        let lift_time = self.rng.uniform(0.35, 0.55);
        self.mark(h, lift_at, Phase::Carry, Some(cube), support_cube);
        self.hands[h].moves.push(Move {
            start: lift_at,
            duration: lift_time,
            goal: Goal::Relative(V3::new(0.0, 0.0, rise)),
            arc: 0.0,
        });
        // Set down closer to the centre of the support than the first time.
        let error = (
            self.rng.gauss(0.0, 0.5 * p.placement_error),
            self.rng.gauss(0.0, 0.5 * p.placement_error),
        );
        let align = self.rng.gauss(0.0, 0.5 * p.align_error_deg.to_radians());
        let slow = if side == self.who.dominant {
            1.0
        } else {
            p.off_hand_slowdown
        };
        let down_at = lift_at + lift_time + self.rng.uniform(0.1, 0.3);
        let down_time = self.draw(p.approach_time) * slow;
        let clearance = self.draw(p.place_clearance);
        self.mark(h, down_at, Phase::Approach, Some(cube), support_cube);
        self.hands[h].moves.push(Move {
            start: down_at,
            duration: down_time,
            goal: Goal::Place {
                onto,
                height: clearance,
                error,
                align,
            },
            arc: 0.0,
        });
        let release_at = down_at + down_time - self.draw(p.release_lead);
        self.mark(h, release_at, Phase::Release, Some(cube), support_cube);
        let open = self.who.grip_open;
        self.grip(h, release_at, open, p.grip_open_time);
        release_at + self.draw(p.release_pause)
    }

    fn mark(
        &mut self,
        h: usize,
        time: f64,
        phase: Phase,
        object: Option<usize>,
        target: Option<usize>,
    ) {
        self.hands[h].phases.push(PhaseMark {
            time,
            phase,
            object,
            target,
        });
    }

    fn grip(&mut self, h: usize, time: f64, target: f64, tau: f64) {
        self.hands[h].grips.push(GripEvent { time, target, tau });
    }

    /// Adds the fidgets of resting hands, orders every timeline, and ends the plan
    /// `end_pause` after the last movement.
    ///
    /// With `start_cut` (`end_cut`) the recording starts (ends) that fraction of the way
    /// into the first (last) movement: mid-motion.
    pub fn finish(mut self, end_pause: f64) -> Plan {
        let last = self
            .hands
            .iter()
            .flat_map(|h| h.moves.iter().map(|m| m.start + m.duration))
            .fold(self.now(), f64::max);
        let mut end = last + end_pause;
        let moves = || self.hands.iter().flat_map(|h| h.moves.iter());
        let first_move = moves().min_by(|a, b| a.start.total_cmp(&b.start)).copied();
        let last_move = moves()
            .max_by(|a, b| (a.start + a.duration).total_cmp(&(b.start + b.duration)))
            .copied();
        let mut start = 0.0;
        if let (Some(m), true) = (first_move, self.p.start_cut.max > 0.0) {
            start = m.start + self.draw(self.p.start_cut) * m.duration;
        }
        if let (Some(m), true) = (last_move, self.p.end_cut.max > 0.0) {
            end = m.start + self.draw(self.p.end_cut) * m.duration;
        }
        for h in 0..2 {
            let hand = &mut self.hands[h];
            hand.phases.sort_by(|a, b| a.time.total_cmp(&b.time));
            // Rest windows: from a Rest mark to the next mark (or the end).
            let mut windows = Vec::new();
            for (i, m) in hand.phases.iter().enumerate() {
                if m.phase == Phase::Rest {
                    let until = hand.phases.get(i + 1).map_or(end, |n| n.time);
                    windows.push((m.time, until));
                }
            }
            let mut fidgets = Vec::new();
            for (from, until) in windows {
                let mut t = from + 0.5;
                loop {
                    if self.who.fidget_rate <= 0.0 {
                        break;
                    }
                    t += -(1.0 - self.rng.f64()).ln() / self.who.fidget_rate;
                    let out = self
                        .rng
                        .uniform(self.p.fidget_time.min, self.p.fidget_time.max);
                    let stay = self.rng.uniform(0.3, 1.2);
                    let back = self
                        .rng
                        .uniform(self.p.fidget_time.min, self.p.fidget_time.max);
                    if t + out + stay + back > until - 0.5 {
                        break;
                    }
                    let angle = self.rng.uniform(0.0, std::f64::consts::TAU);
                    let size = self
                        .rng
                        .uniform(self.p.fidget_size.min, self.p.fidget_size.max);
                    let v = V3::new(angle.cos() * size, angle.sin() * size, 0.3 * size);
                    fidgets.push(Move {
                        start: t,
                        duration: out,
                        goal: Goal::Relative(v),
                        arc: 0.0,
                    });
                    fidgets.push(Move {
                        start: t + out + stay,
                        duration: back,
                        goal: Goal::Relative(-v),
                        arc: 0.0,
                    });
                    t += out + stay + back;
                }
            }
            let hand = &mut self.hands[h];
            hand.moves.extend(fidgets);
            hand.moves.sort_by(|a, b| a.start.total_cmp(&b.start));
            hand.grips.sort_by(|a, b| a.time.total_cmp(&b.time));
        }
        Plan {
            hands: self.hands,
            cubes: self.start,
            start,
            end,
        }
    }
}

/// The heading difference `to − from` wrapped into (−π, π].
pub(crate) fn turn(from: f64, to: f64) -> f64 {
    wrap_angle(to - from)
}
