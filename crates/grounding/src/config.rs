//! The thresholds of grounding, with the paper's values as defaults, read from TOML.

use serde::{Deserialize, Serialize};

/// Every threshold of grounding. The defaults are the paper's (Table 2) where it gives
/// one; `docs/grounding.md` explains each, and `docs/examples/grounding.toml` is a
/// commented file with every field.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct GroundingConfig {
    /// A fact must hold (or not hold) this long (s) before a change counts; shorter runs
    /// are tracker noise and keep the value before them. Also the shortest segment.
    pub min_duration: f64,
    /// `handMove`.
    pub hand_move: HandMoveConfig,
    /// `actedOn`.
    pub acted_on: ActedOnConfig,
    /// `graspable`.
    pub graspable: GraspableConfig,
    /// `handOpen`.
    pub hand_open: HandOpenConfig,
    /// `inHand`.
    pub in_hand: InHandConfig,
    /// `inTouch` and `onTop`.
    pub in_touch: InTouchConfig,
}

/// `handMove(h)`: the hand's speed is above a threshold.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct HandMoveConfig {
    /// The paper's threshold (m/s).
    pub speed: f64,
    /// Width of the hysteresis band around `speed` (m/s): a hand starts moving above
    /// `speed + hysteresis / 2` and stops below `speed - hysteresis / 2`.
    pub hysteresis: f64,
    /// Where the velocity comes from: `reported` (the recording's, when it has one, else
    /// finite differences) or `derived` (finite differences always).
    pub velocity: VelocitySource,
    /// Finite differences are taken over this window (s), which smooths them.
    pub velocity_window: f64,
}

/// Where a hand's velocity comes from.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum VelocitySource {
    /// The recording's velocity when present, finite differences otherwise.
    Reported,
    /// Finite differences of positions, always.
    Derived,
}

/// `actedOn(h, c)`: the hand is close to the object and moves towards it.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct ActedOnConfig {
    /// The paper's distance from palm to object centre (m).
    pub distance: f64,
    /// The least speed towards the object (m/s) that counts as "moving towards it", so
    /// that a hand drifting at rest does not act on what lies beside it.
    pub toward_speed: f64,
    /// Optionally, "towards" also means aimed at: the line along the hand's velocity
    /// passes within this distance (m) of the point above the object's centre at the
    /// palm's height, so that a hand passing by an object on its way elsewhere does not
    /// act on it. Not the paper's rule, so 0 by default: the test is left out and the
    /// paper's wording alone holds (close, and getting closer).
    pub aim_radius: f64,
    /// Once acted on, the object stays so until it is this much farther (m) ...
    pub distance_hysteresis: f64,
    /// ... or the speed towards it falls this much below `toward_speed` (m/s).
    pub speed_hysteresis: f64,
}

/// `graspable(h, c)`: the object is close to the palm.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct GraspableConfig {
    /// The paper's distance from palm to object centre (m).
    pub distance: f64,
    /// Once graspable, the object stays so until it is this much farther (m).
    pub hysteresis: f64,
}

/// `handOpen(h)` from the grip (hand closure, 0 open to 1 closed), with hysteresis.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct HandOpenConfig {
    /// The hand closes when the grip rises above this.
    pub close_above: f64,
    /// The hand opens when the grip falls below this.
    pub open_below: f64,
}

/// `inHand(h, c)`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct InHandConfig {
    /// Where it comes from: `reported` (the recording's `holding`), `grip` (the hand
    /// closed around the object: the nearest graspable object when the hand closed, until
    /// it opens), or `both` (the reported object, else the grip's).
    pub source: InHandSource,
}

/// Where `inHand` comes from.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum InHandSource {
    /// The recording's `holding` only.
    Reported,
    /// The grip only: the hand closed around an object.
    Grip,
    /// The reported object when there is one, else the grip's.
    Both,
}

/// `inTouch(a, b)` and `onTop(a, b)`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct InTouchConfig {
    /// Use the contacts the recording reports.
    pub reported: bool,
    /// Use the geometry: boxes (their axis-aligned bounds) closer than `distance`.
    pub geometry: bool,
    /// Largest gap between two boxes that still counts as touching (m).
    pub distance: f64,
    /// Once touching, boxes stay so until the gap exceeds `distance` by this much (m).
    pub hysteresis: f64,
}

impl Default for GroundingConfig {
    fn default() -> Self {
        GroundingConfig {
            min_duration: 0.1,
            hand_move: HandMoveConfig::default(),
            acted_on: ActedOnConfig::default(),
            graspable: GraspableConfig::default(),
            hand_open: HandOpenConfig::default(),
            in_hand: InHandConfig::default(),
            in_touch: InTouchConfig::default(),
        }
    }
}

impl Default for HandMoveConfig {
    fn default() -> Self {
        HandMoveConfig {
            speed: 0.1,
            hysteresis: 0.02,
            velocity: VelocitySource::Reported,
            velocity_window: 0.05,
        }
    }
}

impl Default for ActedOnConfig {
    fn default() -> Self {
        ActedOnConfig {
            distance: 0.16,
            toward_speed: 0.02,
            aim_radius: 0.0,
            distance_hysteresis: 0.01,
            speed_hysteresis: 0.01,
        }
    }
}

impl Default for GraspableConfig {
    fn default() -> Self {
        GraspableConfig {
            distance: 0.10,
            hysteresis: 0.005,
        }
    }
}

impl Default for HandOpenConfig {
    fn default() -> Self {
        HandOpenConfig {
            close_above: 0.6,
            open_below: 0.4,
        }
    }
}

impl Default for InHandConfig {
    fn default() -> Self {
        InHandConfig {
            source: InHandSource::Both,
        }
    }
}

impl Default for InTouchConfig {
    fn default() -> Self {
        InTouchConfig {
            reported: true,
            geometry: true,
            distance: 0.005,
            hysteresis: 0.002,
        }
    }
}

/// A configuration file that cannot be used: where (1-based line and column, 0 when
/// unknown) and which field (a dotted path, `hand_open.close_above`).
pub type ConfigError = recording::TextError;

impl GroundingConfig {
    /// Reads a configuration from TOML text; fields left out keep their defaults.
    pub fn from_toml(text: &str) -> Result<GroundingConfig, ConfigError> {
        let config: GroundingConfig = toml::from_str(text).map_err(|e| {
            let (line, column) = e.span().map_or((0, 0), |s| line_column(text, s.start));
            ConfigError {
                line,
                column,
                field: field_at(text, line),
                message: e.message().trim().to_string(),
            }
        })?;
        config.validate().map_err(|(field, message)| {
            let (line, column) = find_field(text, &field);
            ConfigError {
                line,
                column,
                field,
                message,
            }
        })?;
        Ok(config)
    }

    /// The configuration as TOML text (every field).
    pub fn to_toml(&self) -> String {
        toml::to_string(self).unwrap_or_default()
    }

    /// Checks that the values make sense; returns the field and what is wrong.
    pub fn validate(&self) -> Result<(), (String, String)> {
        let non_negative = [
            ("min_duration", self.min_duration),
            ("hand_move.speed", self.hand_move.speed),
            ("hand_move.hysteresis", self.hand_move.hysteresis),
            ("acted_on.distance", self.acted_on.distance),
            ("acted_on.toward_speed", self.acted_on.toward_speed),
            ("acted_on.aim_radius", self.acted_on.aim_radius),
            (
                "acted_on.distance_hysteresis",
                self.acted_on.distance_hysteresis,
            ),
            ("acted_on.speed_hysteresis", self.acted_on.speed_hysteresis),
            ("graspable.distance", self.graspable.distance),
            ("graspable.hysteresis", self.graspable.hysteresis),
            ("in_touch.distance", self.in_touch.distance),
            ("in_touch.hysteresis", self.in_touch.hysteresis),
        ];
        for (field, v) in non_negative {
            if !(v.is_finite() && v >= 0.0) {
                return Err((field.into(), format!("must be a number >= 0, not {v}")));
            }
        }
        let w = self.hand_move.velocity_window;
        if !(w.is_finite() && w > 0.0) {
            return Err((
                "hand_move.velocity_window".into(),
                format!("must be a number > 0, not {w}"),
            ));
        }
        if self.hand_move.hysteresis > 2.0 * self.hand_move.speed {
            return Err((
                "hand_move.hysteresis".into(),
                "must be at most twice `speed` (a hand would never stop)".into(),
            ));
        }
        let (close, open) = (self.hand_open.close_above, self.hand_open.open_below);
        for (field, v) in [
            ("hand_open.close_above", close),
            ("hand_open.open_below", open),
        ] {
            if !(0.0..=1.0).contains(&v) {
                return Err((field.into(), format!("must be a grip in 0..1, not {v}")));
            }
        }
        if open > close {
            return Err((
                "hand_open.open_below".into(),
                format!("must not be above `close_above` ({close}), not {open}"),
            ));
        }
        Ok(())
    }
}

/// 1-based line and column of a byte offset.
fn line_column(text: &str, offset: usize) -> (usize, usize) {
    let before = &text.as_bytes()[..offset.min(text.len())];
    let line = before.iter().filter(|&&b| b == b'\n').count() + 1;
    let start = before
        .iter()
        .rposition(|&b| b == b'\n')
        .map_or(0, |p| p + 1);
    (line, offset.min(text.len()) - start + 1)
}

/// The dotted path of the key on a line (for errors that name a line, not a field).
fn field_at(text: &str, line: usize) -> String {
    let mut section = String::new();
    for (i, l) in text.lines().enumerate() {
        let l = l.trim();
        if let Some(s) = l.strip_prefix('[') {
            section = s.trim_end_matches(']').trim().to_string();
        }
        if i + 1 == line {
            if l.starts_with('[') {
                return section;
            }
            let key = l.split('=').next().unwrap_or("").trim();
            return match (section.is_empty(), key.is_empty()) {
                (_, true) => section,
                (true, false) => key.to_string(),
                (false, false) => format!("{section}.{key}"),
            };
        }
    }
    String::new()
}

/// The line and column of a dotted field in TOML text, (0, 0) if it is not written there
/// (a default made invalid by another field).
fn find_field(text: &str, field: &str) -> (usize, usize) {
    let (section, key) = field.rsplit_once('.').unwrap_or(("", field));
    let mut current = String::new();
    for (i, l) in text.lines().enumerate() {
        let t = l.trim_start();
        if let Some(s) = t.strip_prefix('[') {
            current = s.split(']').next().unwrap_or("").trim().to_string();
            continue;
        }
        let k = t.split('=').next().unwrap_or("").trim();
        let dotted = if current.is_empty() {
            k.to_string()
        } else {
            format!("{current}.{k}")
        };
        if (current == section && k == key) || dotted == field {
            return (i + 1, l.len() - t.len() + 1);
        }
    }
    (0, 0)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn defaults_are_the_papers_thresholds() {
        let c = GroundingConfig::default();
        assert_eq!(c.hand_move.speed, 0.1);
        assert_eq!(c.acted_on.distance, 0.16);
        assert_eq!(c.graspable.distance, 0.10);
        assert_eq!(
            (c.hand_open.close_above, c.hand_open.open_below),
            (0.6, 0.4)
        );
        assert_eq!(c.in_touch.distance, 0.005);
        assert_eq!(c.min_duration, 0.1);
        assert_eq!(GroundingConfig::from_toml(""), Ok(c.clone()));
        assert_eq!(GroundingConfig::from_toml(&c.to_toml()), Ok(c));
    }

    #[test]
    fn fields_left_out_keep_their_defaults() {
        let c = GroundingConfig::from_toml("min_duration = 0.2\n[hand_open]\nclose_above = 0.7\n")
            .unwrap_or_default();
        assert_eq!(c.min_duration, 0.2);
        assert_eq!(c.hand_open.close_above, 0.7);
        assert_eq!(c.hand_open.open_below, 0.4);
    }

    #[test]
    fn mistakes_name_line_and_field() {
        let e = GroundingConfig::from_toml("[hand_move]\nspeed = 0.1\nsped = 3\n").err();
        let e = e.unwrap_or_else(|| ConfigError {
            line: 0,
            column: 0,
            field: String::new(),
            message: String::new(),
        });
        assert_eq!((e.line, e.field.as_str()), (3, "hand_move.sped"));
        assert!(e.message.contains("unknown field"), "{e}");

        let e = GroundingConfig::from_toml("[hand_open]\nclose_above = 0.3\n").err();
        let e = e.map(|e| (e.line, e.field));
        assert_eq!(e, Some((0, "hand_open.open_below".to_string())));

        let e = GroundingConfig::from_toml("# c\n[graspable]\ndistance = -1.0\n").err();
        let e = e.map(|e| (e.line, e.column, e.field));
        assert_eq!(e, Some((3, 1, "graspable.distance".to_string())));

        let e = GroundingConfig::from_toml("[acted_on]\ndistance = \"far\"\n").err();
        let e = e.map(|e| (e.line, e.field));
        assert_eq!(e, Some((2, "acted_on.distance".to_string())));
    }
}

#[cfg(test)]
mod example_file {
    use super::*;

    /// `docs/examples/grounding.toml` lists every field with its default.
    #[test]
    fn the_documented_example_is_the_defaults() {
        let text = include_str!("../../../docs/examples/grounding.toml");
        assert_eq!(
            GroundingConfig::from_toml(text),
            Ok(GroundingConfig::default())
        );
        let written = toml::to_string(&GroundingConfig::default()).unwrap_or_default();
        for line in written.lines().filter(|l| l.contains(" = ")) {
            let key = line.split(" = ").next().unwrap_or_default();
            assert!(
                text.contains(&format!("\n{key} = ")),
                "{key} is not in the example"
            );
        }
    }
}
