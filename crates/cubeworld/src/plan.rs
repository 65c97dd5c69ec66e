//! From a ground action to candidate motions: what the action asks of its hand (grasp,
//! place, release, lift, and how the hand ends: moving, creeping towards a cube, still),
//! turned into scripts of motion primitives. [`crate::execute`] tries them all on a
//! copy of the world and keeps the one whose grounded frames give the action's effects.

use grounding::{Fact, Predicate};
use recording::{Activity, EntityId};

use crate::motion::{Script, CREEP, FAST};
use crate::world::{World, CUBE_SIZE, GRASP_HEIGHT, TABLE_HEIGHT};
use geometry::V3;

const UP: V3 = V3::new(0.0, 0.0, 1.0);
const TOWARD_PERSON: V3 = V3::new(-1.0, 0.0, 0.0);
/// A side grasp holds the cube this far from the palm (m).
const SIDE_GRASP: f64 = 0.045;

/// Where a cube is put.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Support {
    Table,
    Cube(usize),
}

/// What an action asks of its hand, read from its effects and the state after it.
#[derive(Debug, Clone)]
pub struct Intent {
    /// The hand.
    pub hand: usize,
    grasp: Option<usize>,
    release: bool,
    close_empty: bool,
    open_empty: bool,
    place: Option<(usize, Support)>,
    lift: bool,
    /// The end speed the effects require: `Some(true)` moving, `Some(false)` still.
    moving: Option<bool>,
    anchors: Vec<usize>,
}

/// Whether an action of this type may close the gripper on a cube.
fn may_grasp(kind: Activity) -> bool {
    matches!(kind, Activity::Take | Activity::Put)
}

/// Whether it may open the gripper and lower a held cube onto something.
fn may_release(kind: Activity) -> bool {
    matches!(kind, Activity::Put | Activity::Stack | Activity::Idle)
}

fn has(facts: &[Fact], p: Predicate, a: EntityId, b: EntityId) -> bool {
    facts
        .iter()
        .any(|f| f.predicate == p && f.first() == a && f.second() == b)
}

impl Intent {
    /// The intent of an action of type `kind` for hand `hand`, with these added and
    /// deleted facts, `after` the facts of the symbolic state after it, and `cubes` the
    /// cube arguments.
    pub fn new(
        world: &World,
        hand: usize,
        kind: Activity,
        add: &[Fact],
        delete: &[Fact],
        after: &[Fact],
        cubes: &[usize],
    ) -> Intent {
        let he = world.hand_entity(hand);
        let cube_of = |e: EntityId| {
            let i = e.index().checked_sub(world.hands.len())?;
            (i < world.cubes.len()).then_some(i)
        };
        let state = world.hands[hand];
        let grasp = if may_grasp(kind) {
            add.iter()
                .filter(|f| f.predicate == Predicate::InHand && f.first() == he)
                .find_map(|f| cube_of(f.second()))
                .filter(|&c| state.holding != Some(c))
        } else {
            None
        };
        let held = grasp.or(state.holding);
        let opens = has(add, Predicate::HandOpen, he, he);
        let closes = has(delete, Predicate::HandOpen, he, he);
        let release = may_release(kind)
            && held
                .is_some_and(|c| opens || has(delete, Predicate::InHand, he, world.cube_entity(c)));
        let open_empty = may_release(kind) && held.is_none() && opens && state.grip > 0.5;
        let close_empty = may_grasp(kind) && grasp.is_none() && closes && state.grip < 0.5;
        let mut place = None;
        let mut lift = false;
        if let Some(c) = held {
            let ce = world.cube_entity(c);
            if may_release(kind) {
                place = add
                    .iter()
                    .filter(|f| {
                        matches!(f.predicate, Predicate::OnTop | Predicate::InTouch)
                            && f.args().contains(&ce)
                    })
                    .find_map(|f| {
                        let other = if f.first() == ce {
                            f.second()
                        } else {
                            f.first()
                        };
                        if f.predicate == Predicate::OnTop && f.first() != ce {
                            return None;
                        }
                        if other == world.table_entity() {
                            Some((c, Support::Table))
                        } else {
                            cube_of(other)
                                .filter(|&o| o != c)
                                .map(|o| (c, Support::Cube(o)))
                        }
                    });
            }
            lift = place.is_none()
                && delete.iter().any(|f| {
                    matches!(f.predicate, Predicate::OnTop | Predicate::InTouch)
                        && f.args().contains(&ce)
                });
        }
        let moving = if has(add, Predicate::HandMove, he, he) {
            Some(true)
        } else if has(delete, Predicate::HandMove, he, he) {
            Some(false)
        } else {
            None
        };
        let mut anchors = Vec::new();
        for f in after.iter().chain(add) {
            if matches!(f.predicate, Predicate::ActedOn | Predicate::Graspable) && f.first() == he {
                if let Some(c) = cube_of(f.second()) {
                    if !anchors.contains(&c) {
                        anchors.push(c);
                    }
                }
            }
        }
        for &c in cubes {
            if !anchors.contains(&c) {
                anchors.push(c);
            }
        }
        Intent {
            hand,
            grasp,
            release,
            close_empty,
            open_empty,
            place,
            lift,
            moving,
            anchors,
        }
    }
}

/// A core motion, what it leaves the world like, and whether it already ends the way
/// the step must end.
#[derive(Debug, Clone)]
struct Core {
    script: Script,
    /// Cube positions after the core (a placed cube where it was put).
    cubes: Vec<V3>,
    /// The cube in hand after the core, and its offset from the palm.
    held: Option<(usize, V3)>,
    done: bool,
}

/// Height the palm must keep when carrying `held` (or nothing) over everything.
fn clearance(world: &World, held: Option<(usize, V3)>, floor: f64) -> f64 {
    let top = world.highest_top(held.map(|h| h.0));
    let z = match held {
        Some((_, offset)) => top + 0.5 * CUBE_SIZE + 0.04 - offset.z,
        None => top + 0.08,
    };
    z.max(floor).max(TABLE_HEIGHT + 0.15)
}

/// Every candidate script for the intent, in order of preference.
pub fn candidates(world: &World, intent: &Intent) -> Vec<Script> {
    let hand = world.hands[intent.hand];
    let mut base = Script::new(hand.pos, hand.vel, hand.grip);
    let mut cubes: Vec<V3> = world.cubes.iter().map(|c| c.pos).collect();
    let mut held = hand.holding.and_then(|c| {
        world
            .cubes
            .get(c)
            .and_then(|cube| cube.held.map(|(_, o)| (c, o)))
    });
    if let Some(c) = intent.grasp {
        // From above, or from the side when something stands on the cube (the tower on
        // it comes along).
        let covered = world.covered(c);
        let side = (hand.pos - cubes[c]).horizontal_unit(TOWARD_PERSON);
        let (g, approach) = if covered {
            let g = cubes[c] + side * SIDE_GRASP;
            (g, g + side * 0.06)
        } else {
            let g = cubes[c] + UP * GRASP_HEIGHT;
            (g, g + UP * 0.06)
        };
        if (hand.pos - g).norm() > 0.02 {
            let clear = clearance(world, held, approach.z + 0.06);
            base.travel(approach, V3::ZERO, clear);
            base.goto(g, V3::ZERO);
            base.primitives.push("reach");
        }
        base.grip(1.0, 0.3);
        base.hold(0.1);
        base.primitives.push("grasp");
        held = Some((c, cubes[c] - g));
    } else if intent.close_empty {
        base.grip(1.0, 0.3);
        base.primitives.push("close");
    } else if intent.open_empty {
        base.grip(0.0, 0.25);
        base.primitives.push("open");
    }
    let mut cores = Vec::new();
    let start = Core {
        script: base,
        cubes: cubes.clone(),
        held,
        done: false,
    };
    match (intent.place, held) {
        (Some((c, support)), Some((hc, offset))) if c == hc => {
            let bottom = match support {
                Support::Cube(y) => cubes[y] + UP * (0.5 * CUBE_SIZE),
                Support::Table => world.free_table_spot(start.script.pos(), Some(c)),
            };
            let centre = bottom + UP * (0.5 * CUBE_SIZE);
            let palm = centre - offset;
            let clear = clearance(world, held, palm.z + 0.08);
            let mut placed = cubes.clone();
            placed[c] = centre;
            if intent.release {
                // Lowered slowly and let go while still creeping down.
                let mut s = start.script.clone();
                s.travel(palm + UP * 0.08, V3::ZERO, clear);
                s.goto(palm + UP * 0.012, UP * -CREEP);
                s.linear(UP * -CREEP, 0.24);
                s.linear_grip(UP * -CREEP, 0.15, 0.0);
                s.primitives.extend(["carry", "place", "release"]);
                cores.push(Core {
                    script: s,
                    cubes: placed.clone(),
                    held: None,
                    done: false,
                });
                // Put down, then let go at rest.
                let mut s = start.script.clone();
                s.travel(palm + UP * 0.08, V3::ZERO, clear);
                s.goto(palm, V3::ZERO);
                s.grip(0.0, 0.25);
                s.primitives.extend(["carry", "place", "release"]);
                cores.push(Core {
                    script: s,
                    cubes: placed,
                    held: None,
                    done: false,
                });
            } else {
                // Put down and keep holding.
                let mut s = start.script.clone();
                s.travel(palm + UP * 0.08, V3::ZERO, clear);
                s.goto(palm, V3::ZERO);
                s.hold(0.05);
                s.primitives.extend(["carry", "place"]);
                cores.push(Core {
                    script: s,
                    cubes: placed.clone(),
                    held,
                    done: false,
                });
                // Slide it on from the side, still moving.
                let dir = (start.script.pos() - centre).horizontal_unit(TOWARD_PERSON);
                let from = palm + dir * 0.065 + UP * 0.002;
                let mut s = start.script.clone();
                s.travel(from + UP * 0.06, V3::ZERO, clear);
                s.goto(from, dir * -FAST);
                s.linear(dir * -FAST, 0.35);
                s.primitives.extend(["carry", "slide"]);
                let end = s.pos();
                let slid = {
                    let mut p = placed.clone();
                    p[c] = end + offset;
                    p
                };
                cores.push(Core {
                    script: s.clone(),
                    cubes: slid.clone(),
                    held,
                    done: true,
                });
                // ... and come to rest.
                let stop = s.pos() - dir * 0.015;
                s.leg(stop, V3::ZERO, 0.2, s.end.2, 0.0);
                s.primitives.push("stop");
                let mut p = placed;
                p[c] = stop + offset;
                cores.push(Core {
                    script: s,
                    cubes: p,
                    held,
                    done: false,
                });
            }
        }
        _ if intent.release => {
            let mut s = start.script.clone();
            s.grip(0.0, 0.25);
            s.primitives.push("release");
            cores.push(Core {
                script: s,
                cubes: cubes.clone(),
                held: None,
                done: false,
            });
        }
        _ if intent.lift => {
            let mut s = start.script.clone();
            let up = s.pos() + UP * 0.05;
            s.goto(up, V3::ZERO);
            s.primitives.push("lift");
            if let Some((c, offset)) = held {
                cubes[c] = up + offset;
            }
            cores.push(Core {
                script: s,
                cubes: cubes.clone(),
                held,
                done: false,
            });
            cores.push(start);
        }
        _ => cores.push(start),
    }
    let mut out = Vec::new();
    for core in cores {
        if core.done {
            out.push(core.script);
            continue;
        }
        terminals(world, intent, &core, &mut out);
    }
    out
}

/// The ways a step may end, after its core motion: towards a cube (from the side or from
/// above, moving or creeping), still, rising, on as before, back to rest.
fn terminals(world: &World, intent: &Intent, core: &Core, out: &mut Vec<Script>) {
    let fast_ok = intent.moving != Some(false);
    let slow_ok = intent.moving != Some(true);
    let mut speeds = Vec::new();
    if fast_ok {
        speeds.push(FAST);
    }
    if slow_ok {
        speeds.push(CREEP);
    }
    let here = core.script.pos();
    let rest = world.hands[intent.hand].rest;
    for &x in intent.anchors.iter().take(3) {
        let Some(&target) = core.cubes.get(x) else {
            continue;
        };
        if core.held.is_some_and(|(c, _)| c == x) {
            continue;
        }
        let palm_z = match core.held {
            Some((_, offset)) => target.z + 0.5 * CUBE_SIZE + 0.012 + 0.5 * CUBE_SIZE - offset.z,
            None => target.z + GRASP_HEIGHT,
        };
        let above = match core.held {
            Some((_, offset)) => target.z + CUBE_SIZE + 0.012 - offset.z,
            None => target.z + 0.06,
        };
        let clear = clearance(world, core.held, palm_z + 0.06);
        let side = (here - target).horizontal_unit(TOWARD_PERSON);
        for &speed in &speeds {
            let (reach, t) = if speed == FAST {
                (0.07, 0.3)
            } else {
                (0.075, 0.35)
            };
            // From the side, at grasp height; at the height of its centre when something
            // stands on it (so that it, not the cube on it, is the nearest).
            let mut heights = vec![palm_z];
            if core.held.is_none() && world.covered(x) {
                heights.insert(0, target.z);
            }
            for z in heights {
                let mut s = core.script.clone();
                let from = V3::new(target.x, target.y, z) + side * reach;
                s.travel(from, side * -speed, clear);
                s.linear(side * -speed, t);
                s.primitives
                    .push(if speed == FAST { "approach" } else { "creep" });
                out.push(s);
            }
            // From above.
            let mut s = core.script.clone();
            let end = V3::new(target.x, target.y, above);
            let from = end + UP * (speed * t);
            s.travel(from, UP * -speed, clear);
            s.linear(UP * -speed, t);
            s.primitives
                .push(if speed == FAST { "approach" } else { "creep" });
            out.push(s);
        }
    }
    let v = core.script.vel();
    if v.norm() > 0.01 && (fast_ok || v.norm() < 0.09) && (slow_ok || v.norm() > 0.11) {
        let mut s = core.script.clone();
        s.linear(v, 0.3);
        s.primitives.push("continue");
        out.push(s);
    }
    if fast_ok {
        let mut s = core.script.clone();
        s.goto(here + UP * 0.03, UP * FAST);
        s.linear(UP * FAST, 0.3);
        s.primitives.push("rise");
        out.push(s);
        // Up and away, still moving: for effects that leave the cube the hand was at out
        // of its reach (`graspable` deleted) while the hand moves on. A 3 cm rise stays
        // within the 10 cm of `graspable`. Last, so it never displaces a candidate that
        // already gave an action's effects.
        let mut s = core.script.clone();
        s.goto(here + UP * 0.12, UP * FAST);
        s.linear(UP * FAST, 0.3);
        s.primitives.extend(["retreat", "rise"]);
        out.push(s);
    }
    if slow_ok {
        let mut s = core.script.clone();
        s.hold(0.35);
        s.primitives.push("stop");
        out.push(s);
        let mut s = core.script.clone();
        s.goto(here + UP * 0.1, V3::ZERO);
        s.hold(0.3);
        s.primitives.extend(["retreat", "stop"]);
        out.push(s);
        let mut s = core.script.clone();
        let clear = clearance(world, core.held, here.z);
        s.travel(rest, V3::ZERO, clear);
        s.hold(0.3);
        s.primitives.extend(["retreat", "rest"]);
        out.push(s);
    }
}
