//! Motion primitives: a hand's script is a list of legs (quintic Hermite segments with
//! a grip ramp), built from its current state.

use geometry::V3;

use crate::geometry::Hermite;

/// Speed of a hand that is moving (`handMove`): above the grounding's 0.11 m/s.
pub const FAST: f64 = 0.15;
/// Speed of a hand that creeps towards something without moving (`handMove` false,
/// `actedOn` true): below 0.09 m/s, above the 0.02 m/s of moving towards.
pub const CREEP: f64 = 0.05;

/// One leg of a script.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Leg {
    /// The path.
    pub path: Hermite,
    /// Grip at the start and the end of its ramp, and the ramp's length (s).
    pub grip: (f64, f64, f64),
}

/// A hand's motion for a step: legs one after another from the hand's state.
#[derive(Debug, Clone, PartialEq)]
pub struct Script {
    /// Position, velocity and grip at the start.
    pub start: (V3, V3, f64),
    /// The legs.
    pub legs: Vec<Leg>,
    /// Position, velocity and grip at the end.
    pub end: (V3, V3, f64),
    /// What the gripper is told in this script: `open`, `close` or `keep`.
    pub gripper: &'static str,
    /// A short description of the motion primitives, for reports.
    pub primitives: Vec<&'static str>,
}

impl Script {
    /// A script that starts (and for now ends) in this state.
    pub fn new(pos: V3, vel: V3, grip: f64) -> Script {
        Script {
            start: (pos, vel, grip),
            legs: Vec::new(),
            end: (pos, vel, grip),
            gripper: "keep",
            primitives: Vec::new(),
        }
    }

    /// The current end position.
    pub fn pos(&self) -> V3 {
        self.end.0
    }

    /// The current end velocity.
    pub fn vel(&self) -> V3 {
        self.end.1
    }

    /// Total length (s).
    pub fn duration(&self) -> f64 {
        self.legs.iter().map(|l| l.path.duration).sum()
    }

    /// Palm position, velocity and grip at time `s` from the start.
    pub fn at(&self, s: f64) -> (V3, V3, f64) {
        let mut t = s;
        for leg in &self.legs {
            if t <= leg.path.duration {
                let (p, v) = leg.path.at(t);
                let (g0, g1, gt) = leg.grip;
                let g = if gt <= 0.0 {
                    g1
                } else {
                    g0 + (g1 - g0) * (t / gt).clamp(0.0, 1.0)
                };
                return (p, v, g);
            }
            t -= leg.path.duration;
        }
        // Past the end: on at the final velocity (a script ends still or mid-motion, and
        // the next one takes over from there).
        (self.end.0 + self.end.1 * t, self.end.1, self.end.2)
    }

    /// A leg to `p`, arriving with velocity `v`, in `t` seconds, the grip ramping to `g`
    /// over `gt` seconds.
    pub fn leg(&mut self, p: V3, v: V3, t: f64, g: f64, gt: f64) {
        let (p0, v0, g0) = self.end;
        let path = Hermite::new(p0, v0, p, v, t);
        self.legs.push(Leg {
            path,
            grip: (g0, g, gt),
        });
        self.end = (p, v, g);
    }

    /// To `p`, arriving with velocity `v`, in a time that suits the distance.
    pub fn goto(&mut self, p: V3, v: V3) {
        let d = (p - self.pos()).norm();
        let t = (0.25 + d / 0.4).max(0.3);
        let g = self.end.2;
        self.leg(p, v, t, g, 0.0);
    }

    /// At constant velocity `v` for `t` seconds.
    pub fn linear(&mut self, v: V3, t: f64) {
        let p = self.pos() + v * t;
        let g = self.end.2;
        self.leg(p, v, t, g, 0.0);
    }

    /// At constant velocity `v` for `t` seconds while the grip ramps to `g`.
    pub fn linear_grip(&mut self, v: V3, t: f64, g: f64) {
        let p = self.pos() + v * t;
        self.leg(p, v, t, g, t.min(0.15));
        self.gripper = if g > 0.5 { "close" } else { "open" };
    }

    /// Still for `t` seconds (coming to rest first if moving).
    pub fn hold(&mut self, t: f64) {
        let p = self.pos() + self.vel() * 0.1;
        let g = self.end.2;
        if self.vel().norm() > 1e-9 {
            self.leg(p, V3::ZERO, 0.2, g, 0.0);
        }
        self.leg(p, V3::ZERO, t, g, 0.0);
    }

    /// Still while the grip ramps to `g` over `t` seconds.
    pub fn grip(&mut self, g: f64, t: f64) {
        let p = self.pos();
        if self.vel().norm() > 1e-9 {
            self.hold(0.0);
        }
        self.leg(p, V3::ZERO, t, g, t);
        self.gripper = if g > 0.5 { "close" } else { "open" };
    }

    /// To `p` (velocity `v` on arrival) over the top: up to `clear_z`, across, down, when
    /// `p` is not right below or above.
    pub fn travel(&mut self, p: V3, v: V3, clear_z: f64) {
        let here = self.pos();
        if (p - here).horizontal_norm() < 0.04 {
            self.goto(p, v);
            return;
        }
        if here.z < clear_z - 0.005 {
            self.goto(V3::new(here.x, here.y, clear_z), V3::ZERO);
        }
        let top = V3::new(p.x, p.y, clear_z.max(p.z));
        if (top - p).norm() > 0.005 {
            self.goto(top, V3::ZERO);
        }
        self.goto(p, v);
    }
}
