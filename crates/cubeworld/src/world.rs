//! The cube world: a table, 5 cm cubes and grippers, moved kinematically. A cube in a
//! closed gripper moves with it (never below what is under it); a released cube drops
//! onto what is below it.

use recording::{Entity, EntityId, EntityKind, EntityState, Frame, Header, Pose, Quaternion};

use geometry::V3;

/// Edge of a cube (m).
pub const CUBE_SIZE: f64 = 0.05;
/// Height of the table top (m).
pub const TABLE_HEIGHT: f64 = 0.75;
/// The table's extent along x (m) and its centre's x.
pub const TABLE_DEPTH: f64 = 0.8;
/// The table's extent along y (m).
pub const TABLE_WIDTH: f64 = 1.2;
/// x of the table's centre (m).
pub const TABLE_X: f64 = 0.55;
/// The box of a hand: length, width, thickness (m); its centre is the palm.
pub const HAND_SIZE: [f64; 3] = [0.12, 0.09, 0.04];
/// Height of the palm above the centre of a cube it holds (m).
pub const GRASP_HEIGHT: f64 = 0.04;
/// Frames per second of the generated recording.
pub const FRAME_RATE: f64 = 90.0;
/// A gripper closes on (and lets go of) a cube when its grip passes this value.
pub const GRIP_LATCH: f64 = 0.5;
/// A closing gripper takes the nearest cube whose centre is this close to the palm (m).
pub const GRAB_DISTANCE: f64 = 0.09;
/// Where the cubes of the initial scene stand: a row at this x ...
const ROW_X: [f64; 3] = [0.45, 0.65, 0.85];
/// ... this far apart along y (m).
const SPACING: f64 = 0.2;
const GRAVITY: f64 = 9.81;

/// A hand: palm position and velocity, grip (0 open to 1 closed), the cube it holds.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Hand {
    /// Palm position (m).
    pub pos: V3,
    /// Palm velocity (m/s).
    pub vel: V3,
    /// Closure, 0 (open) to 1 (closed).
    pub grip: f64,
    /// The cube held (index into [`World::cubes`]).
    pub holding: Option<usize>,
    /// Where the hand rests.
    pub rest: V3,
}

/// A cube: its centre, and how it hangs in a hand or falls.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Cube {
    /// Centre (m); cubes stay axis-aligned.
    pub pos: V3,
    /// The hand holding it, and the offset of its centre from the palm.
    pub held: Option<(usize, V3)>,
    /// Falling speed (m/s, downwards).
    pub fall: f64,
}

/// The world: names and kinds as the recording's header has them, hands, cubes, time.
#[derive(Debug, Clone)]
pub struct World {
    /// The recording header (hands, then cubes, then the table).
    pub header: Header,
    /// Hands, in header order.
    pub hands: Vec<Hand>,
    /// Cubes, in header order after the hands.
    pub cubes: Vec<Cube>,
    /// Time of the next frame (s).
    pub time: f64,
    /// Frames emitted so far.
    pub frames: u64,
    /// Per hand, how far it has been carried along since its script began: a hand that
    /// does not act but holds a cube standing on a cube that another hand moves comes
    /// along (two hands carrying a tower).
    pub carried: Vec<V3>,
}

/// Where the cubes of a scene start: towers bottom first (each a list of cube indices),
/// the cube each hand holds, if any.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Layout {
    /// Towers standing on the table, bottom first.
    pub towers: Vec<Vec<usize>>,
    /// Per hand, the cube it holds at the start.
    pub held: Vec<Option<usize>>,
    /// Per hand, whether it starts closed.
    pub closed: Vec<bool>,
}

impl World {
    /// A world with these hands and cubes (names), laid out as `layout` says: towers in
    /// rows 20 cm apart in front of the participant, hands at rest beside the table (the
    /// first at +y), held cubes in their hands above the table's front edge.
    pub fn new(
        id: &str,
        hands: &[String],
        cubes: &[String],
        table: &str,
        layout: &Layout,
    ) -> World {
        let mut entities = Vec::new();
        let hs = recording::Vec3::from_f64(V3::new(HAND_SIZE[0], HAND_SIZE[1], HAND_SIZE[2]));
        for h in hands {
            entities.push(Entity {
                name: h.clone(),
                kind: EntityKind::Hand,
                size: hs,
                fixed: None,
            });
        }
        let cs = recording::Vec3::from_f64(V3::new(CUBE_SIZE, CUBE_SIZE, CUBE_SIZE));
        for c in cubes {
            entities.push(Entity {
                name: c.clone(),
                kind: EntityKind::Cube,
                size: cs,
                fixed: None,
            });
        }
        entities.push(Entity {
            name: table.to_string(),
            kind: EntityKind::Table,
            size: recording::Vec3::from_f64(V3::new(TABLE_DEPTH, TABLE_WIDTH, TABLE_HEIGHT)),
            fixed: Some(Pose {
                position: recording::Vec3::from_f64(V3::new(TABLE_X, 0.0, 0.5 * TABLE_HEIGHT)),
                orientation: Quaternion::IDENTITY,
            }),
        });
        let header = Header {
            id: id.to_string(),
            participant: "cubeworld".into(),
            task: "execution".into(),
            frame_rate: FRAME_RATE,
            entities,
            meta: Default::default(),
        };
        let hands: Vec<Hand> = (0..hands.len())
            .map(|i| {
                let side = if i % 2 == 0 { 1.0 } else { -1.0 };
                let rest = V3::new(
                    0.10,
                    side * (0.30 + 0.25 * (i / 2) as f64),
                    TABLE_HEIGHT + 0.05,
                );
                Hand {
                    pos: rest,
                    vel: V3::ZERO,
                    grip: if layout.closed.get(i).copied().unwrap_or(false) {
                        1.0
                    } else {
                        0.0
                    },
                    holding: None,
                    rest,
                }
            })
            .collect();
        let mut world = World {
            header,
            hands,
            cubes: vec![
                Cube {
                    pos: V3::ZERO,
                    held: None,
                    fall: 0.0,
                };
                cubes.len()
            ],
            time: 0.0,
            frames: 0,
            carried: Vec::new(),
        };
        world.carried = vec![V3::ZERO; world.hands.len()];
        let spots = table_spots(layout.towers.len().max(cubes.len()));
        for (tower, spot) in layout.towers.iter().zip(&spots) {
            for (level, &c) in tower.iter().enumerate() {
                if let Some(cube) = world.cubes.get_mut(c) {
                    cube.pos = V3::new(
                        spot.x,
                        spot.y,
                        TABLE_HEIGHT + CUBE_SIZE * (0.5 + level as f64),
                    );
                }
            }
        }
        for (h, held) in layout.held.iter().enumerate() {
            if let (Some(c), Some(hand)) = (held, world.hands.get_mut(h)) {
                hand.pos = V3::new(0.2, hand.rest.y, TABLE_HEIGHT + 0.15);
                hand.rest = hand.pos;
                hand.grip = 1.0;
                hand.holding = Some(*c);
                let offset = V3::new(0.0, 0.0, -GRASP_HEIGHT);
                if let Some(cube) = world.cubes.get_mut(*c) {
                    cube.pos = hand.pos + offset;
                    cube.held = Some((h, offset));
                }
            }
        }
        world
    }

    /// The entity id of hand `h`.
    pub fn hand_entity(&self, h: usize) -> EntityId {
        EntityId(h as u32)
    }

    /// The entity id of cube `c`.
    pub fn cube_entity(&self, c: usize) -> EntityId {
        EntityId((self.hands.len() + c) as u32)
    }

    /// The table's entity id.
    pub fn table_entity(&self) -> EntityId {
        EntityId((self.hands.len() + self.cubes.len()) as u32)
    }

    /// Height of the highest support under a footprint centred at (x, y): the table or
    /// the top of a cube (other than `except`) that overlaps it and whose top is at most
    /// `below` (+1 mm).
    pub fn support_top(&self, at: V3, below: f64, except: Option<usize>) -> f64 {
        let mut top = if in_table(at) { TABLE_HEIGHT } else { 0.0 };
        for (i, c) in self.cubes.iter().enumerate() {
            if Some(i) == except {
                continue;
            }
            let t = c.pos.z + 0.5 * CUBE_SIZE;
            if (c.pos.x - at.x).abs() < CUBE_SIZE - 1e-6
                && (c.pos.y - at.y).abs() < CUBE_SIZE - 1e-6
                && t <= below + 1e-3
                && t > top
            {
                top = t;
            }
        }
        top
    }

    /// The cube that cube `i` rests on (its bottom within 2 mm of that cube's top,
    /// footprints overlapping), if any.
    pub fn resting_on(&self, i: usize) -> Option<usize> {
        let c = self.cubes.get(i)?;
        let bottom = c.pos.z - 0.5 * CUBE_SIZE;
        self.cubes.iter().enumerate().position(|(j, o)| {
            j != i
                && (o.pos.x - c.pos.x).abs() < CUBE_SIZE - 1e-6
                && (o.pos.y - c.pos.y).abs() < CUBE_SIZE - 1e-6
                && (o.pos.z + 0.5 * CUBE_SIZE - bottom).abs() < 0.002
        })
    }

    /// Whether something stands on cube `i` (held or not).
    pub fn covered(&self, i: usize) -> bool {
        (0..self.cubes.len()).any(|j| j != i && self.resting_on(j) == Some(i))
    }

    /// The cubes standing on cube `i`, directly or higher up its tower.
    pub fn riders(&self, i: usize) -> Vec<usize> {
        let mut out: Vec<usize> = Vec::new();
        let mut frontier = vec![i];
        while let Some(b) = frontier.pop() {
            for j in 0..self.cubes.len() {
                if j != i
                    && !out.contains(&j)
                    && self.cubes[j].held.is_none()
                    && self.resting_on(j) == Some(b)
                {
                    out.push(j);
                    frontier.push(j);
                }
            }
        }
        out
    }

    /// Pairs of entities (header indices, lower first) that have gone through each
    /// other: cubes whose volumes overlap by more than `tolerance` (m) along every axis,
    /// and a hand with the cube it holds when the cube, stopped by what is below it,
    /// is more than `slip` (m) from where the grasp holds it. The world has no
    /// collisions, so a motion can do either; [`crate::execute`] avoids motions that do.
    pub fn interpenetrating(&self, tolerance: f64, slip: f64) -> Vec<(usize, usize)> {
        let limit = CUBE_SIZE - tolerance;
        let nh = self.hands.len();
        let mut out = Vec::new();
        for (h, hand) in self.hands.iter().enumerate() {
            let Some(c) = hand.holding else {
                continue;
            };
            if let Some(Cube {
                pos,
                held: Some((_, offset)),
                ..
            }) = self.cubes.get(c)
            {
                if (*pos - (hand.pos + *offset)).norm() > slip {
                    out.push((h, nh + c));
                }
            }
        }
        for (i, a) in self.cubes.iter().enumerate() {
            for (j, b) in self.cubes.iter().enumerate().skip(i + 1) {
                let d = a.pos - b.pos;
                if d.x.abs() < limit && d.y.abs() < limit && d.z.abs() < limit {
                    out.push((nh + i, nh + j));
                }
            }
        }
        out
    }

    /// The top of everything standing (m): what a carried cube must clear.
    pub fn highest_top(&self, except: Option<usize>) -> f64 {
        let riding = except.map(|e| self.riders(e)).unwrap_or_default();
        self.cubes
            .iter()
            .enumerate()
            .filter(|(i, c)| Some(*i) != except && c.held.is_none() && !riding.contains(i))
            .map(|(_, c)| c.pos.z + 0.5 * CUBE_SIZE)
            .fold(TABLE_HEIGHT, f64::max)
    }

    /// A free place on the table for a cube (the centre of its bottom face), nearest to
    /// `near`: the spots of the initial rows that no standing cube covers.
    pub fn free_table_spot(&self, near: V3, except: Option<usize>) -> V3 {
        let spots = table_spots(3 * 6);
        let free = spots.into_iter().filter(|s| {
            self.cubes.iter().enumerate().all(|(i, c)| {
                Some(i) == except
                    || c.held.is_some()
                    || (c.pos.x - s.x).abs() >= 0.12
                    || (c.pos.y - s.y).abs() >= 0.12
            })
        });
        let mut best: Option<(f64, V3)> = None;
        for s in free {
            let d = (s - near).horizontal_norm();
            if best.is_none_or(|(bd, _)| d < bd - 1e-9) {
                best = Some((d, s));
            }
        }
        best.map_or(V3::new(ROW_X[2], 0.0, TABLE_HEIGHT), |(_, s)| s)
    }

    /// Moves time on by one frame: hands take the given palm positions, velocities and
    /// grips; grippers take and let go of cubes; held cubes follow their hands; free
    /// cubes fall onto what is below. Returns the frame.
    ///
    /// A `passive` hand (one that does not act in this step) follows its target shifted
    /// by how far it has been carried along (see [`World::carried`]).
    pub fn step(&mut self, targets: &[(V3, V3, f64)], passive: &[bool]) -> Frame {
        let dt = 1.0 / FRAME_RATE;
        // What each cube rests on, before anything moves.
        let old: Vec<V3> = self.cubes.iter().map(|c| c.pos).collect();
        let resting: Vec<Option<usize>> =
            (0..self.cubes.len()).map(|i| self.resting_on(i)).collect();
        for (h, &(pos, vel, grip)) in targets.iter().enumerate() {
            let pos = if passive.get(h).copied().unwrap_or(false) {
                pos + self.carried.get(h).copied().unwrap_or(V3::ZERO)
            } else {
                pos
            };
            let Some(hand) = self.hands.get(h).copied() else {
                continue;
            };
            let was = hand.grip;
            let mut hand = Hand {
                pos,
                vel,
                grip: grip.clamp(0.0, 1.0),
                ..hand
            };
            if was < GRIP_LATCH && hand.grip >= GRIP_LATCH && hand.holding.is_none() {
                let mut best: Option<(f64, usize)> = None;
                for (i, c) in self.cubes.iter().enumerate() {
                    let d = (c.pos - pos).norm();
                    if c.held.is_none() && d < GRAB_DISTANCE && best.is_none_or(|(bd, _)| d < bd) {
                        best = Some((d, i));
                    }
                }
                if let Some((_, c)) = best {
                    hand.holding = Some(c);
                    self.cubes[c].held = Some((h, self.cubes[c].pos - pos));
                    self.cubes[c].fall = 0.0;
                }
            } else if hand.grip < GRIP_LATCH {
                if let Some(c) = hand.holding.take() {
                    if let Some(cube) = self.cubes.get_mut(c) {
                        cube.held = None;
                    }
                }
            }
            self.hands[h] = hand;
        }
        // Held cubes follow their hands, never into what is below them.
        for (i, before) in old.iter().enumerate() {
            if let Some((h, offset)) = self.cubes[i].held {
                let Some(hand) = self.hands.get(h) else {
                    continue;
                };
                let mut p = hand.pos + offset;
                let floor = self.support_top(p, before.z - 0.5 * CUBE_SIZE + 0.002, Some(i));
                p.z = p.z.max(floor + 0.5 * CUBE_SIZE);
                self.cubes[i].pos = p;
            }
        }
        // Free cubes ride on what they rest on (a tower lifted by its lower cube comes
        // along), lowest first; then they fall onto the highest support below.
        let mut order: Vec<usize> = (0..self.cubes.len()).collect();
        order.sort_by(|&a, &b| old[a].z.total_cmp(&old[b].z));
        for &i in &order {
            let Some(s) = resting[i] else {
                continue;
            };
            let moved = self.cubes[s].pos - old[s];
            match self.cubes[i].held {
                None => self.cubes[i].pos = old[i] + moved,
                Some((h, offset)) if passive.get(h).copied().unwrap_or(false) => {
                    if moved.norm() > 1e-12 {
                        self.cubes[i].pos = old[i] + moved;
                        if let Some(hand) = self.hands.get_mut(h) {
                            hand.pos = old[i] + moved - offset;
                            hand.vel += moved * FRAME_RATE;
                        }
                        if let Some(c) = self.carried.get_mut(h) {
                            *c += moved;
                        }
                    }
                }
                Some(_) => {}
            }
        }
        for i in order {
            let c = self.cubes[i];
            if c.held.is_some() {
                continue;
            }
            let bottom = c.pos.z - 0.5 * CUBE_SIZE;
            let floor = self.support_top(c.pos, bottom, Some(i));
            if bottom > floor + 1e-9 {
                let fall = c.fall + GRAVITY * dt;
                let z = (bottom - fall * dt).max(floor);
                self.cubes[i].fall = if z <= floor { 0.0 } else { fall };
                self.cubes[i].pos.z = z + 0.5 * CUBE_SIZE;
            } else {
                self.cubes[i].fall = 0.0;
            }
        }
        let frame = self.frame();
        self.time += dt;
        self.frames += 1;
        frame
    }

    /// The current frame.
    pub fn frame(&self) -> Frame {
        let n = self.header.entities.len();
        let mut frame = Frame::empty(round_time(self.time), n);
        for (h, hand) in self.hands.iter().enumerate() {
            frame.states[h] = Some(EntityState {
                pose: Pose {
                    position: recording::Vec3::from_f64(hand.pos),
                    orientation: Quaternion::IDENTITY,
                },
                velocity: Some(recording::Vec3::from_f64(hand.vel)),
                grip: Some(hand.grip as f32),
                holding: hand.holding.map(|c| self.cube_entity(c)),
            });
        }
        for (c, cube) in self.cubes.iter().enumerate() {
            frame.states[self.hands.len() + c] = Some(EntityState {
                pose: Pose {
                    position: recording::Vec3::from_f64(cube.pos),
                    orientation: Quaternion::IDENTITY,
                },
                velocity: None,
                grip: None,
                holding: None,
            });
        }
        frame
    }
}

/// Times to the microsecond, so that the written recording reads back the same.
fn round_time(t: f64) -> f64 {
    (t * 1e6).round() / 1e6
}

fn in_table(p: V3) -> bool {
    (p.x - TABLE_X).abs() <= 0.5 * TABLE_DEPTH && p.y.abs() <= 0.5 * TABLE_WIDTH
}

/// Places on the table (bottom centres) for `n` towers: rows of six 20 cm apart.
fn table_spots(n: usize) -> Vec<V3> {
    let mut spots = Vec::new();
    for &x in &ROW_X {
        for k in 0..6 {
            spots.push(V3::new(x, (2.5 - k as f64) * SPACING, TABLE_HEIGHT));
        }
    }
    spots.truncate(n.max(1).min(spots.len()));
    spots
}

/// The most towers a scene can have.
pub const MAX_TOWERS: usize = 18;

#[cfg(test)]
mod tests {
    use super::*;
    use grounding::{Fact, Grounder, GroundingConfig, Predicate};

    fn names(prefix: &str, n: usize) -> Vec<String> {
        (1..=n).map(|i| format!("{prefix}_{i}")).collect()
    }

    /// One hand, two cubes on the table; the hand holds cube_2 `gap` metres above
    /// cube_1.
    fn holding_above(gap: f64) -> World {
        let layout = Layout {
            towers: vec![vec![0], vec![1]],
            held: vec![None],
            closed: vec![false],
        };
        let mut w = World::new("t", &names("hand", 1), &names("cube", 2), "table", &layout);
        let below = w.cubes[0].pos;
        let offset = V3::new(0.0, 0.0, -GRASP_HEIGHT);
        let c = below + V3::new(0.0, 0.0, CUBE_SIZE + gap);
        w.cubes[1] = Cube {
            pos: c,
            held: Some((0, offset)),
            fall: 0.0,
        };
        w.hands[0].pos = c - offset;
        w.hands[0].grip = 1.0;
        w.hands[0].holding = Some(1);
        w
    }

    #[test]
    fn a_released_cube_lands_on_the_cube_below_and_grounds_on_top() {
        let mut w = holding_above(0.03);
        let mut grounder = Grounder::new(&w.header, &GroundingConfig::default());
        let mut last = None;
        let palm = w.hands[0].pos;
        for k in 0..90 {
            // Open over 0.2 s, then keep still.
            let grip = (1.0 - k as f64 / 18.0).max(0.0);
            let frame = w.step(&[(palm, V3::ZERO, grip)], &[false]);
            grounder.push(&frame, &mut |g| last = Some(g.state.clone()));
        }
        grounder.finish(&mut |g| last = Some(g.state.clone()));
        let top = w.cubes[0].pos.z + CUBE_SIZE;
        assert!((w.cubes[1].pos.z - top).abs() < 1e-9, "{:?}", w.cubes[1]);
        assert!(w.cubes[1].held.is_none() && w.hands[0].holding.is_none());
        let space = grounder.space();
        let state = last.unwrap();
        let (c1, c2) = (w.cube_entity(0), w.cube_entity(1));
        for fact in [
            Fact::binary(Predicate::OnTop, c2, c1),
            Fact::binary(Predicate::InTouch, c1, c2),
            Fact::unary(Predicate::HandOpen, w.hand_entity(0)),
        ] {
            assert!(state.contains(space.id(&fact).unwrap()), "{fact:?}");
        }
        let held = Fact::binary(Predicate::InHand, w.hand_entity(0), c2);
        assert!(!state.contains(space.id(&held).unwrap()));
    }

    #[test]
    fn a_held_cube_follows_its_hand_but_not_into_the_cube_below() {
        let mut w = holding_above(0.02);
        let start = w.hands[0].pos;
        // Down by 5 cm: the held cube stops on cube_1; then up again, it comes along.
        let down = start - V3::new(0.0, 0.0, 0.05);
        w.step(&[(down, V3::ZERO, 1.0)], &[false]);
        let top = w.cubes[0].pos.z + CUBE_SIZE;
        assert!((w.cubes[1].pos.z - top).abs() < 1e-9);
        let up = start + V3::new(0.1, 0.0, 0.1);
        w.step(&[(up, V3::ZERO, 1.0)], &[false]);
        let offset = w.cubes[1].pos - up;
        assert!((offset - V3::new(0.0, 0.0, -GRASP_HEIGHT)).norm() < 1e-9);
        // A cube standing on a lifted cube rides along.
        let mut w = holding_above(0.0);
        let rider_layout_cube = w.cubes[0].pos;
        w.cubes[0].pos = rider_layout_cube + V3::new(0.0, 0.0, 2.0 * CUBE_SIZE);
        w.cubes[0].held = None;
        // cube_1 now stands on the held cube_2 (which is at cube_1's old top).
        w.cubes[1].pos = rider_layout_cube + V3::new(0.0, 0.0, CUBE_SIZE);
        w.cubes[0].pos = w.cubes[1].pos + V3::new(0.0, 0.0, CUBE_SIZE);
        w.hands[0].pos = w.cubes[1].pos + V3::new(0.0, 0.0, GRASP_HEIGHT);
        let lift = w.hands[0].pos + V3::new(0.05, 0.0, 0.05);
        w.step(&[(lift, V3::ZERO, 1.0)], &[false]);
        assert!((w.cubes[0].pos - (w.cubes[1].pos + V3::new(0.0, 0.0, CUBE_SIZE))).norm() < 1e-9);
    }
}
