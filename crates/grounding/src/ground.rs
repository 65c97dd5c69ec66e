//! The grounder: frames in, facts out, one frame at a time.

use std::collections::VecDeque;

use recording::{EntityId, Frame, Header, Quaternion, Vec3};

use crate::config::{GroundingConfig, InHandSource, VelocitySource};
use crate::debounce::{Debouncer, Released, NO_VALUE};
use crate::fact::{FactSpace, State, NO_BIT};

/// What a hand does in a frame: the variables of the paper's Table 1 and `handOpen`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub struct HandFacts {
    /// `handMove`.
    pub moving: bool,
    /// `handOpen`, when known (ARFF tables may leave it out).
    pub open: Option<bool>,
    /// The object of `actedOn`, if any.
    pub acted_on: Option<EntityId>,
    /// The object of `inHand`, if any.
    pub in_hand: Option<EntityId>,
}

/// A grounded frame: every fact that holds, and per hand its [`HandFacts`].
#[derive(Debug)]
pub struct GroundedFrame<'a> {
    /// 0-based position of the frame in the recording.
    pub index: u64,
    /// The frame's time (s).
    pub time: f64,
    /// The facts that hold.
    pub state: &'a State,
    /// One entry per hand of the [`FactSpace`], in its order.
    pub hands: &'a [HandFacts],
}

/// The continuous quantities behind a hand's facts in the last frame pushed (before the
/// minimum duration), for plots.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct HandSignals {
    /// Speed (m/s), from the velocity grounding uses.
    pub speed: f32,
    /// The grip, if reported.
    pub grip: Option<f32>,
    /// Distance from the palm to each object (m), in the order of
    /// [`FactSpace::objects`]; NaN while an object has not been seen.
    pub distances: Vec<f32>,
    /// Speed towards each object (m/s), same order.
    pub toward: Vec<f32>,
}

#[derive(Debug, Clone)]
struct HandTrack {
    entity: EntityId,
    pos: Vec3,
    velocity: Vec3,
    known: bool,
    history: VecDeque<(f64, Vec3)>,
    moving: bool,
    open: bool,
    acted: u16,
    latch: u16,
    held: u16,
}

#[derive(Debug, Clone, Copy)]
struct ThingTrack {
    entity: EntityId,
    half: Vec3,
    pos: Vec3,
    /// Half extents of its axis-aligned bounds in the current orientation.
    bounds: Vec3,
    known: bool,
}

/// Squared thresholds and the like, in `f32` as the poses are.
#[derive(Debug, Clone, Copy)]
struct Limits {
    move_on2: f32,
    move_off2: f32,
    derived: bool,
    window: f64,
    acted2: f32,
    acted_stay2: f32,
    toward2: f32,
    toward_stay2: f32,
    aim2: f32,
    aim_stay2: f32,
    column: f32,
    grasp2: f32,
    grasp_stay2: f32,
    close_above: f32,
    open_below: f32,
    source: InHandSource,
    contacts: bool,
    geometry: bool,
    touch: f32,
    touch_stay: f32,
}

/// Grounds a recording frame by frame: hysteresis on every threshold, then the minimum
/// duration. Frames come out `min_duration` after they go in (the last ones from
/// [`Grounder::finish`]), each exactly once and in order.
///
/// Per frame the work is a fixed number of operations per hand and object and per pair
/// of things, with no allocation: distances are compared squared, and the facts are bits
/// of a [`State`].
#[derive(Debug, Clone)]
pub struct Grounder {
    space: FactSpace,
    limits: Limits,
    hands: Vec<HandTrack>,
    things: Vec<ThingTrack>,
    /// Per object (index into `space.objects()`): its index among things.
    object_thing: Vec<usize>,
    /// Per pair of entities (row-major): the `inTouch` bit of a reported contact.
    contact_bits: Vec<u32>,
    entities: usize,
    raw: Vec<u64>,
    previous: Vec<u64>,
    values: Vec<u16>,
    debouncer: Debouncer,
    out_state: State,
    out_hands: Vec<HandFacts>,
    signals: Vec<HandSignals>,
}

impl Grounder {
    /// A grounder for recordings with this header.
    pub fn new(header: &Header, config: &GroundingConfig) -> Grounder {
        let space = FactSpace::new(header);
        let m = &config.hand_move;
        let sq = |x: f64| (x * x) as f32;
        let half_band = 0.5 * m.hysteresis;
        let limits = Limits {
            move_on2: sq(m.speed + half_band),
            move_off2: sq((m.speed - half_band).max(0.0)),
            derived: m.velocity == VelocitySource::Derived,
            window: m.velocity_window,
            acted2: sq(config.acted_on.distance),
            acted_stay2: sq(config.acted_on.distance + config.acted_on.distance_hysteresis),
            toward2: sq(config.acted_on.toward_speed),
            toward_stay2: sq(
                (config.acted_on.toward_speed - config.acted_on.speed_hysteresis).max(0.0),
            ),
            aim2: sq(config.acted_on.aim_radius),
            aim_stay2: sq(config.acted_on.aim_radius + config.acted_on.distance_hysteresis),
            column: config.acted_on.distance as f32,
            grasp2: sq(config.graspable.distance),
            grasp_stay2: sq(config.graspable.distance + config.graspable.hysteresis),
            close_above: config.hand_open.close_above as f32,
            open_below: config.hand_open.open_below as f32,
            source: config.in_hand.source,
            contacts: config.in_touch.reported,
            geometry: config.in_touch.geometry,
            touch: config.in_touch.distance as f32,
            touch_stay: (config.in_touch.distance + config.in_touch.hysteresis) as f32,
        };
        let hands: Vec<HandTrack> = space
            .hands()
            .iter()
            .map(|&entity| HandTrack {
                entity,
                pos: Vec3::ZERO,
                velocity: Vec3::ZERO,
                known: false,
                history: VecDeque::with_capacity(64),
                moving: false,
                open: true,
                acted: NO_VALUE,
                latch: NO_VALUE,
                held: NO_VALUE,
            })
            .collect();
        let things: Vec<ThingTrack> = space
            .things()
            .iter()
            .map(|&entity| {
                let e = header.entity(entity);
                let half = e.size * 0.5;
                let (pos, bounds, known) = match e.fixed {
                    Some(p) => (p.position, aabb(half, p.orientation), true),
                    None => (Vec3::ZERO, half, false),
                };
                ThingTrack {
                    entity,
                    half,
                    pos,
                    bounds,
                    known,
                }
            })
            .collect();
        let object_thing = space
            .objects()
            .iter()
            .map(|&o| space.thing_index(o).unwrap_or(0))
            .collect();
        let n = header.entities.len();
        let mut contact_bits = vec![NO_BIT; n * n];
        for (i, a) in space.things().iter().enumerate() {
            for (j, b) in space.things().iter().enumerate() {
                if i != j {
                    contact_bits[a.index() * n + b.index()] = space.in_touch_bit(i, j);
                }
            }
        }
        let words = space.words();
        let nh = hands.len();
        let objects = space.objects().len();
        Grounder {
            limits,
            things,
            object_thing,
            contact_bits,
            entities: n,
            raw: vec![0; words],
            previous: vec![0; words],
            values: vec![NO_VALUE; 2 * nh],
            debouncer: Debouncer::new(config.min_duration, words, 2 * nh),
            out_state: space.empty_state(),
            out_hands: vec![HandFacts::default(); nh],
            signals: vec![
                HandSignals {
                    speed: 0.0,
                    grip: None,
                    distances: vec![f32::NAN; objects],
                    toward: vec![0.0; objects],
                };
                nh
            ],
            hands,
            space,
        }
    }

    /// The facts this scene can have.
    pub fn space(&self) -> &FactSpace {
        &self.space
    }

    /// The continuous quantities of the last frame pushed, per hand.
    pub fn signals(&self) -> &[HandSignals] {
        &self.signals
    }

    /// Grounds a frame; `out` receives every frame that has become final (in order).
    pub fn push(&mut self, frame: &Frame, out: &mut impl FnMut(&GroundedFrame<'_>)) {
        self.observe(frame);
        self.raw_facts(frame);
        let Grounder {
            debouncer,
            raw,
            values,
            space,
            out_state,
            out_hands,
            ..
        } = self;
        debouncer.push(frame.time, raw, values, |r| {
            emit(space, out_state, out_hands, r, out);
        });
        std::mem::swap(&mut self.raw, &mut self.previous);
    }

    /// Releases the frames still held back at the end of the recording.
    pub fn finish(&mut self, out: &mut impl FnMut(&GroundedFrame<'_>)) {
        let Grounder {
            debouncer,
            space,
            out_state,
            out_hands,
            ..
        } = self;
        debouncer.finish(|r| emit(space, out_state, out_hands, r, out));
    }

    /// Updates positions and velocities from a frame (unobserved entities keep their
    /// last known pose).
    fn observe(&mut self, frame: &Frame) {
        for t in &mut self.things {
            if let Some(s) = frame.state(t.entity) {
                t.pos = s.pose.position;
                t.bounds = aabb(t.half, s.pose.orientation);
                t.known = true;
            }
        }
        let l = self.limits;
        for (h, signal) in self.hands.iter_mut().zip(&mut self.signals) {
            let Some(s) = frame.state(h.entity) else {
                continue;
            };
            let pos = s.pose.position;
            while h
                .history
                .front()
                .is_some_and(|&(t, _)| frame.time - t > l.window)
            {
                h.history.pop_front();
            }
            h.velocity = match s.velocity {
                Some(v) if !l.derived => v,
                _ => match h.history.front() {
                    Some(&(t, p)) if frame.time > t => (pos - p) * (1.0 / (frame.time - t) as f32),
                    _ => h.velocity,
                },
            };
            if h.history.len() == h.history.capacity() {
                h.history.pop_front();
            }
            h.history.push_back((frame.time, pos));
            h.pos = pos;
            h.known = true;
            let speed2 = h.velocity.dot(h.velocity);
            h.moving = if h.moving {
                speed2 > l.move_off2
            } else {
                speed2 > l.move_on2
            };
            signal.speed = speed2.sqrt();
            signal.grip = s.grip;
            let was_open = h.open;
            if let Some(g) = s.grip {
                if h.open && g > l.close_above {
                    h.open = false;
                } else if !h.open && g < l.open_below {
                    h.open = true;
                }
            }
            // The grip's idea of what is held: the nearest graspable object when the hand
            // closes, until it opens.
            if h.open {
                h.latch = NO_VALUE;
            } else if was_open {
                let mut best = (NO_VALUE, l.grasp2);
                for (o, &t) in self.object_thing.iter().enumerate() {
                    let thing = &self.things[t];
                    if thing.known {
                        let d = thing.pos - pos;
                        let d2 = d.dot(d);
                        if d2 < best.1 {
                            best = (o as u16, d2);
                        }
                    }
                }
                h.latch = best.0;
            }
            let reported = s
                .holding
                .and_then(|id| self.space.object_index(id))
                .map_or(NO_VALUE, |o| o as u16);
            h.held = match l.source {
                InHandSource::Reported => reported,
                InHandSource::Grip => h.latch,
                InHandSource::Both if reported != NO_VALUE => reported,
                InHandSource::Both => h.latch,
            };
        }
    }

    /// The raw facts of the current frame (hysteresis, no minimum duration) into `raw`
    /// and `values`.
    fn raw_facts(&mut self, frame: &Frame) {
        let l = self.limits;
        let space = &self.space;
        let raw = &mut self.raw;
        let previous = &self.previous;
        raw.iter_mut().for_each(|w| *w = 0);
        let set = |raw: &mut Vec<u64>, bit: u32| {
            if bit != NO_BIT {
                raw[(bit / 64) as usize] |= 1 << (bit % 64);
            }
        };
        let was = |bit: u32| previous[(bit / 64) as usize] & (1 << (bit % 64)) != 0;
        let nh = self.hands.len();
        for (hi, (h, signal)) in self.hands.iter_mut().zip(&mut self.signals).enumerate() {
            if h.moving {
                set(raw, space.hand_move_bit(hi));
            }
            if h.open {
                set(raw, space.hand_open_bit(hi));
            }
            let mut best = (NO_VALUE, f32::INFINITY);
            let mut keep = false;
            let v2 = h.velocity.dot(h.velocity);
            for (o, &t) in self.object_thing.iter().enumerate() {
                let thing = &self.things[t];
                if !thing.known || !h.known {
                    continue;
                }
                let d = thing.pos - h.pos;
                let d2 = d.dot(d);
                let toward = h.velocity.dot(d);
                signal.distances[o] = d2.sqrt();
                signal.toward[o] = if d2 > 0.0 { toward / d2.sqrt() } else { 0.0 };
                let gbit = space.graspable_bit(hi, o);
                if d2 < l.grasp2 || (d2 < l.grasp_stay2 && was(gbit)) {
                    set(raw, gbit);
                }
                if o as u16 == h.held || toward <= 0.0 {
                    continue;
                }
                let t2 = toward * toward;
                // Aimed at: hands go for a point above an object (the grasp, the place
                // on top), so aim at the object's column: the point above its centre at
                // the palm's height, at most `acted_on.distance` up. Squared distance
                // from that point to the ray along the velocity.
                let k = (h.pos.z - thing.pos.z).clamp(0.0, l.column);
                let w = Vec3::new(d.x, d.y, d.z + k);
                let w2 = w.dot(w);
                let along = h.velocity.dot(w);
                let miss2 = if v2 > 0.0 && along > 0.0 {
                    w2 - along * along / v2
                } else {
                    w2
                };
                let aimed = |limit2: f32| l.aim2 == 0.0 || miss2 < limit2;
                if o as u16 == h.acted
                    && d2 < l.acted_stay2
                    && t2 > l.toward_stay2 * d2
                    && aimed(l.aim_stay2)
                {
                    keep = true;
                }
                if d2 < l.acted2 && t2 > l.toward2 * d2 && aimed(l.aim2) && d2 < best.1 {
                    best = (o as u16, d2);
                }
            }
            if !keep {
                h.acted = best.0;
            }
            self.values[hi] = h.acted;
            self.values[nh + hi] = h.held;
        }
        // Things touching: reported contacts, then geometry.
        if l.contacts {
            for c in &frame.contacts {
                let (a, b) = (c.a.index(), c.b.index());
                if a < self.entities && b < self.entities {
                    set(raw, self.contact_bits[a * self.entities + b]);
                }
            }
        }
        let nt = self.things.len();
        for i in 0..nt {
            let a = &self.things[i];
            for j in i + 1..nt {
                let b = &self.things[j];
                let bit = space.in_touch_bit(i, j);
                let mut touching = raw[(bit / 64) as usize] & (1 << (bit % 64)) != 0;
                if l.geometry && !touching && a.known && b.known {
                    let d = a.pos - b.pos;
                    let gap = (d.x.abs() - a.bounds.x - b.bounds.x)
                        .max(d.y.abs() - a.bounds.y - b.bounds.y)
                        .max(d.z.abs() - a.bounds.z - b.bounds.z);
                    let limit = if was(bit) { l.touch_stay } else { l.touch };
                    touching = gap <= limit;
                    if touching {
                        set(raw, bit);
                    }
                }
                if touching {
                    if a.pos.z > b.pos.z + b.bounds.z {
                        set(raw, space.on_top_bit(i, j));
                    } else if b.pos.z > a.pos.z + a.bounds.z {
                        set(raw, space.on_top_bit(j, i));
                    }
                }
            }
        }
    }
}

fn emit(
    space: &FactSpace,
    state: &mut State,
    hands: &mut [HandFacts],
    r: Released<'_>,
    out: &mut impl FnMut(&GroundedFrame<'_>),
) {
    let words = state.words_mut();
    words.copy_from_slice(r.words);
    let nh = hands.len();
    let objects = space.objects();
    for (hi, facts) in hands.iter_mut().enumerate() {
        let (acted, held) = (r.values[hi], r.values[nh + hi]);
        let mut object = |value: u16, bit: fn(&FactSpace, usize, usize) -> u32| {
            objects.get(value as usize).map(|&id| {
                let b = bit(space, hi, value as usize);
                words[(b / 64) as usize] |= 1 << (b % 64);
                id
            })
        };
        let acted_on = object(acted, FactSpace::acted_on_bit);
        let in_hand = object(held, FactSpace::in_hand_bit);
        let bit = |b: u32| words[(b / 64) as usize] & (1 << (b % 64)) != 0;
        *facts = HandFacts {
            moving: bit(space.hand_move_bit(hi)),
            open: Some(bit(space.hand_open_bit(hi))),
            acted_on,
            in_hand,
        };
    }
    out(&GroundedFrame {
        index: r.seq,
        time: r.time,
        state,
        hands,
    });
}

/// Half extents of the axis-aligned bounds of a box with half extents `half` turned by
/// `q`.
fn aabb(half: Vec3, q: Quaternion) -> Vec3 {
    let (x, y, z, w) = (q.x, q.y, q.z, q.w);
    let m = [
        [
            1.0 - 2.0 * (y * y + z * z),
            2.0 * (x * y - z * w),
            2.0 * (x * z + y * w),
        ],
        [
            2.0 * (x * y + z * w),
            1.0 - 2.0 * (x * x + z * z),
            2.0 * (y * z - x * w),
        ],
        [
            2.0 * (x * z - y * w),
            2.0 * (y * z + x * w),
            1.0 - 2.0 * (x * x + y * y),
        ],
    ];
    let row = |r: [f32; 3]| r[0].abs() * half.x + r[1].abs() * half.y + r[2].abs() * half.z;
    Vec3::new(row(m[0]), row(m[1]), row(m[2]))
}
