//! Every parameter of the simulator, in one place.
//!
//! The defaults are the "embedded default" that later stages reproduce the paper with.
//! Changing one changes the default demonstrations, and so every result measured on them:
//! do it deliberately, and note it in `docs/recording-format.md` (whose parameter table
//! lists every field below; a test keeps the two in step).
//!
//! Units: metres, seconds, metres per second; angles in degrees where the name ends in
//! `_deg`; probabilities in 0..1. An [`Interval`] `[min, max]` is a range a value is
//! drawn from uniformly: once per participant for a participant's style, once per event
//! otherwise.

use serde::{Deserialize, Serialize};

use crate::style::Style;

/// A closed range `[min, max]` to draw from; written as a two-element JSON list. A single
/// number `x` reads as `[x, x]` (so a parameter that was once a single value, such as
/// `hover`, still reads from older `--params` files).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(from = "IntervalText", into = "[f64; 2]")]
pub struct Interval {
    /// Smallest value.
    pub min: f64,
    /// Largest value.
    pub max: f64,
}

impl Interval {
    /// `[min, max]`.
    pub const fn new(min: f64, max: f64) -> Interval {
        Interval { min, max }
    }

    /// The midpoint.
    pub fn mid(self) -> f64 {
        0.5 * (self.min + self.max)
    }
}

/// How an [`Interval`] may be written: `[min, max]` or one number.
#[derive(Deserialize)]
#[serde(untagged)]
enum IntervalText {
    Range([f64; 2]),
    Value(f64),
}

impl From<IntervalText> for Interval {
    fn from(t: IntervalText) -> Interval {
        match t {
            IntervalText::Range(a) => a.into(),
            IntervalText::Value(x) => Interval::new(x, x),
        }
    }
}

impl From<[f64; 2]> for Interval {
    fn from(a: [f64; 2]) -> Interval {
        Interval::new(a[0], a[1])
    }
}

impl From<Interval> for [f64; 2] {
    fn from(i: Interval) -> [f64; 2] {
        [i.min, i.max]
    }
}

/// The simulator's parameters. See the module documentation for units; the table in
/// `docs/recording-format.md` repeats each with its reason.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct SimParams {
    // ----- style -----
    /// The style of demonstration ([`Style`]): `paper` (the default; not written) or
    /// `two-handed`. It chooses the script (one hand at a time, or both at once); its
    /// parameter overrides are [`Style::params`].
    #[serde(skip_serializing_if = "Style::is_default")]
    pub style: Style,

    // ----- scene -----
    /// Nominal tracker frame rate (Hz); VR headsets run at 90.
    pub frame_rate: f64,
    /// Cubes on the table.
    pub cubes: u32,
    /// Edge of a cube (m); the paper's cubes are 5 cm.
    pub cube_size: f64,
    /// Height of the table top above the floor (m).
    pub table_height: f64,
    /// Extent of the table along x, away from the participant (m).
    pub table_depth: f64,
    /// Extent of the table along y (m).
    pub table_width: f64,
    /// x of the table's centre; the participant stands at the origin facing +x (m).
    pub table_x: f64,
    /// Where cubes start, along x (m).
    pub cube_area_x: Interval,
    /// Where cubes start, along y (m).
    pub cube_area_y: Interval,
    /// Least distance between cube centres at the start (m); more than the 0.16 m of
    /// `actedOn`, so that a reach for one cube is not a reach for its neighbour.
    pub cube_spacing: f64,
    /// Box of a hand: length, width, thickness (m); its centre is the palm.
    pub hand_size: [f64; 3],
    /// x of a resting hand (m).
    pub rest_x: f64,
    /// |y| of a resting hand: left hand at +y, right hand at -y (m).
    pub rest_y: f64,
    /// Height of a resting palm above the table top (m): the hand lies on the table.
    pub rest_height: f64,

    // ----- participants: motion -----
    /// A participant's mean hand speed over a movement (m/s); a minimum-jerk movement
    /// peaks at 1.875 times its mean speed.
    pub mean_speed: Interval,
    /// Shortest movement (s); a movement takes this plus distance over mean speed.
    pub move_time_floor: f64,
    /// Log-standard deviation of a movement's duration around its nominal value.
    pub move_time_jitter: f64,
    /// Movements of the non-dominant hand take this much longer.
    pub off_hand_slowdown: f64,
    /// Probability that a participant is left-handed.
    pub left_handed: f64,
    /// Height of the arc of a reach above the straight line (m).
    pub reach_arc: Interval,
    /// Height of the arc of a carry above the straight line (m).
    pub carry_arc: Interval,
    /// A carry lifts the cube by this much (m) early in the movement, ...
    pub lift_height: Interval,
    /// ... in this fraction of the carry's duration (a lift blended into the transport;
    /// 0.6 times that for a lift on the fly).
    pub lift_share: Interval,
    /// Height above its place at which the carried cube ends the carry (m).
    pub above_target: Interval,
    /// Duration of the final descent onto the target (s).
    pub approach_time: Interval,
    /// Fraction of the carry still to go when the descent starts (smooth transitions).
    pub approach_overlap: Interval,
    /// Per participant: probability of hovering still above the target before
    /// descending (a careful placer checks the alignment first).
    pub hover: Interval,
    /// How long a hover lasts (s).
    pub hover_time: Interval,
    /// Palm above a cube's centre when grasping it (m).
    pub grasp_height: f64,
    /// Standard deviation of where the palm ends up relative to the cube, per axis (m).
    pub grasp_error: f64,
    /// Standard deviation of where a cube is put relative to the centre of what it is
    /// put on, per horizontal axis (m).
    pub placement_error: f64,
    /// Height above its support at which a cube is let go (m); it then drops.
    pub place_clearance: Interval,
    /// Heading of a hand at rest and when grasping, turned inwards (degrees).
    pub natural_yaw_deg: f64,
    /// Standard deviation of the alignment of hand to cube and of cube to cube (degrees).
    pub align_error_deg: f64,
    /// Root mean square of the slow wobble of the wrist's roll and pitch (degrees); its
    /// periods are 0.3 times `drift_period`.
    pub wrist_wobble_deg: f64,

    // ----- participants: behaviour -----
    /// Per participant: probability of resting the hand after grasping (the paper's
    /// Reach, Take, Put); otherwise the cube is lifted in one flowing motion (Reach, Put:
    /// the paper's `Put2`).
    pub rest_after_grasp: Interval,
    /// How long a resting hand stays still after closing on a cube (s).
    pub take_pause: Interval,
    /// In a flowing grasp, the fraction of the reach still to go when the lift starts;
    /// limited so that the palm is within `flow_reach` of the grasp point then.
    pub flow_overlap: Interval,
    /// In a flowing grasp, the farthest the palm may be from the grasp point when the
    /// hand closes on the cube (m).
    pub flow_reach: f64,
    /// A resting grasp starts closing this long before the reach ends (s).
    pub close_lead: Interval,
    /// The hand starts opening to release this long before the descent ends (s).
    pub release_lead: Interval,
    /// Before the first movement (s).
    pub start_pause: Interval,
    /// After the last movement (s).
    pub end_pause: Interval,
    /// Where the recording starts: this fraction of the way into the task's first
    /// movement (mid-motion, as a real recording started by hand). `[0, 0]` (the default;
    /// not written): at time 0, before the start pause.
    #[serde(skip_serializing_if = "is_zero")]
    pub start_cut: Interval,
    /// Where the recording ends: this fraction of the way into the last movement (a hand
    /// still on its way back). `[0, 0]` (the default; not written): `end_pause` after it.
    #[serde(skip_serializing_if = "is_zero")]
    pub end_cut: Interval,
    /// Between placements, when the hand went back to rest (s).
    pub between_pause: Interval,
    /// Still after opening the hand, before leaving (s).
    pub release_pause: Interval,
    /// Per participant: probability of going back to rest between two placements.
    pub return_between: Interval,
    /// Per participant: probability that a reach first heads for another cube and is
    /// redirected (a change of mind, or a reach for the wrong cube).
    pub abort: Interval,
    /// How far towards the wrong cube an aborted reach gets (fraction of the way).
    pub abort_fraction: Interval,
    /// When the redirection starts, as a fraction of the aborted movement's duration
    /// (below 1: blended into it; above 1: after a hesitation).
    pub abort_redirect: Interval,
    /// Per participant: probability of opening and closing the hand again on a grasped
    /// cube (a grip found poor is corrected before lifting).
    pub regrasp: Interval,
    /// How far a regrasp loosens the grip (below `release_grip`, so the cube is let go).
    pub regrasp_grip: Interval,
    /// How far the hand shifts while regrasping (m).
    pub regrasp_shift: Interval,
    /// After releasing without going back to rest, how far the hand rises (m).
    pub lift_away: Interval,
    /// Per participant: probability that, after putting a cube down, the hand takes it
    /// again, lifts it a little and sets it down once more on the same support
    /// (straightening a cube that landed askew).
    pub adjust: Interval,
    /// How high an adjustment lifts the cube above its place (m).
    pub adjust_lift: Interval,

    // ----- grip -----
    /// Grip of a relaxed hand, per participant.
    pub grip_rest: Interval,
    /// Grip of a hand opened to grasp, per participant.
    pub grip_open: Interval,
    /// Grip of a hand closed on a cube (the cube stops the fingers), per grasp.
    pub grip_hold: Interval,
    /// Time constant of closing the hand (s).
    pub grip_close_time: f64,
    /// Time constant of opening the hand (s).
    pub grip_open_time: f64,
    /// Time constant of a hand relaxing after a release (s).
    pub grip_relax_time: f64,
    /// The hand starts opening to grasp at this fraction of the reach (pre-shaping).
    pub preshape_at: f64,
    /// The VR grab system attaches a cube when the (noise-free) grip rises above this.
    pub grab_grip: f64,
    /// The grab system lets the cube go when the grip falls below this.
    pub release_grip: f64,
    /// A cube is grabbed only if its centre is this close to the palm (m): the paper's
    /// `graspable` distance.
    pub grasp_radius: f64,

    // ----- idle hands -----
    /// Root mean square of the slow drift of a hand along x and y (m).
    pub drift: f64,
    /// Root mean square of the drift along z (m).
    pub drift_z: f64,
    /// Periods of the drift's components (s).
    pub drift_period: Interval,
    /// Per participant: small movements of a resting hand, per second.
    pub fidget_rate: Interval,
    /// Their size (m).
    pub fidget_size: Interval,
    /// Duration of each of their two movements, out and back (s).
    pub fidget_time: Interval,

    // ----- tracking -----
    /// Standard deviation of the slowly varying tracking error of a hand, per axis (m).
    pub hand_noise: f64,
    /// Correlation time of that error (s).
    pub hand_noise_time: f64,
    /// Standard deviation of the frame-to-frame jitter of a hand, per axis (m).
    pub hand_jitter: f64,
    /// Standard deviation of the orientation error of a hand (degrees).
    pub hand_rot_noise_deg: f64,
    /// Standard deviation of the error of a reported hand velocity, per axis (m/s).
    pub velocity_noise: f64,
    /// Standard deviation of the error of the reported grip.
    pub grip_noise: f64,
    /// Standard deviation of the physics engine's jitter of a resting cube, per axis (m).
    pub cube_jitter: f64,
    /// Probability that a frame is dropped (a gap in the recording): that a run of
    /// dropped frames starts there.
    pub frame_drop: f64,
    /// Longest run of dropped frames: a run is 1 to this many frames long (uniform). With
    /// 1 (the default; not written) frames drop one at a time, each on its own chance;
    /// above 1 the frame after a run is kept, so runs never join.
    #[serde(skip_serializing_if = "is_one")]
    pub frame_drop_run: u32,
    /// Standard deviation of a frame's timestamp around its nominal time (s).
    pub time_jitter: f64,

    // ----- what the recordings contain -----
    /// Write the hands' velocities (as a VR tracker reports them).
    pub velocities: bool,
    /// Write what each hand holds (as a VR grab system knows it).
    pub held: bool,
    /// Write contacts (as a physics engine reports them).
    pub contacts: bool,
    /// A cube touches what is below it when the gap is at most this (m).
    pub contact_distance: f64,

    // ----- ground truth (the paper's Table 2 thresholds) -----
    /// `handMove`: noise-free hand speed above this (m/s).
    pub move_speed: f64,
    /// `actedOn`: a cube is this close to the palm (m), the nearest such, and ...
    pub acted_on_distance: f64,
    /// `actedOn`: ... the hand moves towards it faster than this (m/s).
    pub toward_speed: f64,
}

impl Default for SimParams {
    fn default() -> SimParams {
        SimParams {
            style: Style::Paper,

            frame_rate: 90.0,
            cubes: 6,
            cube_size: 0.05,
            table_height: 0.75,
            table_depth: 0.8,
            table_width: 1.2,
            table_x: 0.55,
            cube_area_x: Interval::new(0.40, 0.76),
            cube_area_y: Interval::new(-0.42, 0.42),
            cube_spacing: 0.18,
            hand_size: [0.12, 0.09, 0.04],
            rest_x: 0.27,
            rest_y: 0.30,
            rest_height: 0.025,

            mean_speed: Interval::new(0.28, 0.42),
            move_time_floor: 0.25,
            move_time_jitter: 0.12,
            off_hand_slowdown: 1.12,
            left_handed: 0.1,
            reach_arc: Interval::new(0.02, 0.06),
            carry_arc: Interval::new(0.02, 0.06),
            lift_height: Interval::new(0.04, 0.08),
            lift_share: Interval::new(0.3, 0.45),
            above_target: Interval::new(0.04, 0.10),
            approach_time: Interval::new(0.35, 0.65),
            approach_overlap: Interval::new(0.15, 0.45),
            hover: Interval::new(0.05, 0.4),
            hover_time: Interval::new(0.2, 0.6),
            grasp_height: 0.045,
            grasp_error: 0.004,
            placement_error: 0.004,
            place_clearance: Interval::new(0.001, 0.005),
            natural_yaw_deg: 15.0,
            align_error_deg: 4.0,
            wrist_wobble_deg: 4.0,

            rest_after_grasp: Interval::new(0.55, 0.95),
            take_pause: Interval::new(0.3, 0.8),
            flow_overlap: Interval::new(0.2, 0.3),
            flow_reach: 0.035,
            close_lead: Interval::new(0.02, 0.08),
            release_lead: Interval::new(0.04, 0.09),
            start_pause: Interval::new(0.5, 1.5),
            end_pause: Interval::new(0.5, 1.2),
            start_cut: Interval::new(0.0, 0.0),
            end_cut: Interval::new(0.0, 0.0),
            between_pause: Interval::new(0.2, 0.8),
            release_pause: Interval::new(0.1, 0.35),
            return_between: Interval::new(0.1, 0.9),
            abort: Interval::new(0.0, 0.16),
            abort_fraction: Interval::new(0.35, 0.75),
            abort_redirect: Interval::new(0.55, 1.25),
            regrasp: Interval::new(0.0, 0.16),
            regrasp_grip: Interval::new(0.2, 0.35),
            regrasp_shift: Interval::new(0.008, 0.02),
            lift_away: Interval::new(0.06, 0.12),
            adjust: Interval::new(0.1, 0.5),
            adjust_lift: Interval::new(0.01, 0.03),

            grip_rest: Interval::new(0.15, 0.30),
            grip_open: Interval::new(0.02, 0.10),
            grip_hold: Interval::new(0.75, 0.88),
            grip_close_time: 0.09,
            grip_open_time: 0.07,
            grip_relax_time: 0.3,
            preshape_at: 0.35,
            grab_grip: 0.6,
            release_grip: 0.4,
            grasp_radius: 0.10,

            drift: 0.006,
            drift_z: 0.0015,
            drift_period: Interval::new(3.0, 12.0),
            fidget_rate: Interval::new(0.0, 0.06),
            fidget_size: Interval::new(0.02, 0.06),
            fidget_time: Interval::new(0.5, 0.9),

            hand_noise: 0.002,
            hand_noise_time: 0.25,
            hand_jitter: 0.0004,
            hand_rot_noise_deg: 0.5,
            velocity_noise: 0.01,
            grip_noise: 0.015,
            cube_jitter: 0.0002,
            frame_drop: 0.003,
            frame_drop_run: 1,
            time_jitter: 0.0003,

            velocities: true,
            held: true,
            contacts: true,
            contact_distance: 0.002,

            move_speed: 0.1,
            acted_on_distance: 0.16,
            toward_speed: 0.02,
        }
    }
}

fn is_one(x: &u32) -> bool {
    *x == 1
}

fn is_zero(i: &Interval) -> bool {
    i.min == 0.0 && i.max == 0.0
}

/// A parameter out of its range.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("parameter `{field}`: {message}")]
pub struct ParamError {
    /// The parameter's name.
    pub field: String,
    /// What is wrong.
    pub message: String,
}

fn err(field: &str, message: impl Into<String>) -> ParamError {
    ParamError {
        field: field.into(),
        message: message.into(),
    }
}

impl SimParams {
    /// The parameters as a JSON object (for `--params` files and the manifest).
    pub fn to_json(&self) -> serde_json::Value {
        serde_json::to_value(self).unwrap_or(serde_json::Value::Null)
    }

    /// Checks every parameter's range and the relations between them.
    pub fn validate(&self) -> Result<(), ParamError> {
        let intervals: &[(&str, Interval)] = &[
            ("cube_area_x", self.cube_area_x),
            ("cube_area_y", self.cube_area_y),
            ("mean_speed", self.mean_speed),
            ("reach_arc", self.reach_arc),
            ("carry_arc", self.carry_arc),
            ("lift_height", self.lift_height),
            ("lift_share", self.lift_share),
            ("above_target", self.above_target),
            ("approach_time", self.approach_time),
            ("approach_overlap", self.approach_overlap),
            ("place_clearance", self.place_clearance),
            ("rest_after_grasp", self.rest_after_grasp),
            ("take_pause", self.take_pause),
            ("flow_overlap", self.flow_overlap),
            ("start_pause", self.start_pause),
            ("end_pause", self.end_pause),
            ("start_cut", self.start_cut),
            ("end_cut", self.end_cut),
            ("between_pause", self.between_pause),
            ("release_pause", self.release_pause),
            ("abort_fraction", self.abort_fraction),
            ("grip_rest", self.grip_rest),
            ("grip_open", self.grip_open),
            ("grip_hold", self.grip_hold),
            ("drift_period", self.drift_period),
            ("fidget_size", self.fidget_size),
            ("hover_time", self.hover_time),
            ("close_lead", self.close_lead),
            ("release_lead", self.release_lead),
            ("abort_redirect", self.abort_redirect),
            ("regrasp_grip", self.regrasp_grip),
            ("regrasp_shift", self.regrasp_shift),
            ("lift_away", self.lift_away),
            ("fidget_time", self.fidget_time),
            ("hover", self.hover),
            ("return_between", self.return_between),
            ("abort", self.abort),
            ("regrasp", self.regrasp),
            ("adjust", self.adjust),
            ("adjust_lift", self.adjust_lift),
            ("fidget_rate", self.fidget_rate),
        ];
        for &(name, i) in intervals {
            if !(i.min.is_finite() && i.max.is_finite() && i.min <= i.max) {
                return Err(err(
                    name,
                    format!("[{}, {}] is not an interval [min, max]", i.min, i.max),
                ));
            }
            if i.min < 0.0 && !name.starts_with("cube_area") {
                return Err(err(name, "must not be negative"));
            }
        }
        for (name, v) in [
            ("frame_rate", self.frame_rate),
            ("cube_size", self.cube_size),
            ("table_height", self.table_height),
            ("table_depth", self.table_depth),
            ("table_width", self.table_width),
            ("grip_close_time", self.grip_close_time),
            ("grip_open_time", self.grip_open_time),
            ("grip_relax_time", self.grip_relax_time),
            ("flow_reach", self.flow_reach),
            ("hand_noise_time", self.hand_noise_time),
            ("grasp_radius", self.grasp_radius),
            ("move_speed", self.move_speed),
            ("acted_on_distance", self.acted_on_distance),
            ("off_hand_slowdown", self.off_hand_slowdown),
            ("hand_size[0]", self.hand_size[0]),
            ("hand_size[1]", self.hand_size[1]),
            ("hand_size[2]", self.hand_size[2]),
        ] {
            if !(v.is_finite() && v > 0.0) {
                return Err(err(name, format!("{v} must be positive")));
            }
        }
        if self.mean_speed.min <= 0.0 {
            return Err(err("mean_speed", "must be positive"));
        }
        if self.drift_period.min <= 0.0 {
            return Err(err("drift_period", "must be positive"));
        }
        for (name, v) in [
            ("table_x", self.table_x),
            ("cube_spacing", self.cube_spacing),
            ("rest_x", self.rest_x),
            ("rest_y", self.rest_y),
            ("rest_height", self.rest_height),
            ("move_time_floor", self.move_time_floor),
            ("move_time_jitter", self.move_time_jitter),
            ("grasp_height", self.grasp_height),
            ("grasp_error", self.grasp_error),
            ("placement_error", self.placement_error),
            ("natural_yaw_deg", self.natural_yaw_deg),
            ("align_error_deg", self.align_error_deg),
            ("wrist_wobble_deg", self.wrist_wobble_deg),
            ("drift", self.drift),
            ("drift_z", self.drift_z),
            ("hand_noise", self.hand_noise),
            ("hand_jitter", self.hand_jitter),
            ("hand_rot_noise_deg", self.hand_rot_noise_deg),
            ("velocity_noise", self.velocity_noise),
            ("grip_noise", self.grip_noise),
            ("cube_jitter", self.cube_jitter),
            ("time_jitter", self.time_jitter),
            ("toward_speed", self.toward_speed),
            ("contact_distance", self.contact_distance),
        ] {
            if !(v.is_finite() && v >= 0.0) {
                return Err(err(name, format!("{v} must be a non-negative number")));
            }
        }
        for (name, p) in [
            ("left_handed", self.left_handed),
            ("hover", self.hover.max),
            ("return_between", self.return_between.max),
            ("abort", self.abort.max),
            ("regrasp", self.regrasp.max),
            ("adjust", self.adjust.max),
            ("frame_drop", self.frame_drop),
            ("rest_after_grasp", self.rest_after_grasp.min),
            ("rest_after_grasp", self.rest_after_grasp.max),
            ("abort_fraction", self.abort_fraction.max),
            ("approach_overlap", self.approach_overlap.max),
            ("grip_rest", self.grip_rest.max),
            ("grip_hold", self.grip_hold.max),
            ("flow_overlap", self.flow_overlap.max),
            ("preshape_at", self.preshape_at),
            ("lift_share", self.lift_share.max),
            ("start_cut", self.start_cut.max),
            ("end_cut", self.end_cut.max),
        ] {
            if !(0.0..=1.0).contains(&p) {
                return Err(err(
                    name,
                    format!("{p} is not a probability or fraction in 0..1"),
                ));
            }
        }
        if self.frame_drop > 0.5 {
            return Err(err("frame_drop", "more than half the frames dropped"));
        }
        if self.cubes < 3 || self.cubes > 64 {
            return Err(err(
                "cubes",
                format!(
                    "{} cubes: the tasks need at least 3, and at most 64 fit",
                    self.cubes
                ),
            ));
        }
        if self.release_grip >= self.grab_grip || self.release_grip.is_nan() {
            return Err(err("release_grip", "must be below grab_grip"));
        }
        if self.grip_rest.max >= self.release_grip || self.grip_open.max >= self.release_grip {
            return Err(err(
                "grip_rest",
                "a relaxed or opened hand must stay below release_grip",
            ));
        }
        if self.regrasp_grip.max >= self.release_grip {
            return Err(err(
                "regrasp_grip",
                "a regrasp must loosen the grip below release_grip",
            ));
        }
        if self.fidget_time.min <= 0.0 {
            return Err(err("fidget_time", "must be positive"));
        }
        if self.grip_hold.min <= self.grab_grip {
            return Err(err("grip_hold", "a closed hand must rise above grab_grip"));
        }
        if self.grasp_height + 2.0 * self.grasp_error >= self.grasp_radius {
            return Err(err(
                "grasp_height",
                "the palm must end up within grasp_radius",
            ));
        }
        let table_x = Interval::new(
            self.table_x - 0.5 * self.table_depth,
            self.table_x + 0.5 * self.table_depth,
        );
        let half = 0.5 * self.cube_size;
        if self.cube_area_x.min - half < table_x.min
            || self.cube_area_x.max + half > table_x.max
            || self.cube_area_y.min - half < -0.5 * self.table_width
            || self.cube_area_y.max + half > 0.5 * self.table_width
        {
            return Err(err("cube_area_x", "the cube area is not on the table"));
        }
        if self.cube_spacing < self.cube_size * 1.5 {
            return Err(err(
                "cube_spacing",
                "cubes would touch: use at least 1.5 cube sizes",
            ));
        }
        if !(1..=100).contains(&self.frame_drop_run) {
            return Err(err(
                "frame_drop_run",
                format!("{}: between 1 and 100 frames", self.frame_drop_run),
            ));
        }
        if self.frame_rate > 10_000.0 {
            return Err(err("frame_rate", "above 10 kHz"));
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn defaults_are_valid_and_round_trip_through_json() {
        let p = SimParams::default();
        p.validate().unwrap();
        let text = serde_json::to_string(&p).unwrap();
        let back: SimParams = serde_json::from_str(&text).unwrap();
        assert_eq!(back, p);
        // A partial file overrides only what it names.
        // A probability once written as one number reads as the interval [x, x].
        let partial: SimParams = serde_json::from_str(r#"{"cubes": 4, "hover": 0.5}"#).unwrap();
        assert_eq!(
            (partial.cubes, partial.hover, partial.frame_rate),
            (4, Interval::new(0.5, 0.5), 90.0)
        );
        assert!(serde_json::from_str::<SimParams>(r#"{"cubez": 4}"#).is_err());
    }

    #[test]
    fn out_of_range_parameters_are_named() {
        let p = SimParams {
            cubes: 2,
            ..SimParams::default()
        };
        assert_eq!(p.validate().unwrap_err().field, "cubes");
        let p = SimParams {
            mean_speed: Interval::new(0.5, 0.2),
            ..SimParams::default()
        };
        assert_eq!(p.validate().unwrap_err().field, "mean_speed");
        let p = SimParams {
            release_grip: 0.7,
            ..SimParams::default()
        };
        assert_eq!(p.validate().unwrap_err().field, "release_grip");
    }
}
