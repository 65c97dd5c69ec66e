//! Named styles of demonstration: a set of parameter overrides plus script behaviour.
//!
//! [`Style::Paper`] is the paper's study as the simulator always made it (one hand at a
//! time, a VR tracker that knows grasps and contacts); its output never changes.
//! [`Style::TwoHanded`] is what real recordings of people stacking cubes look like: both
//! hands work at once (one puts a cube on the tower while the other already reaches for
//! and takes the next), recordings start and end mid-motion, and the tracker reports
//! poses only (see [`Style::params`]).

use serde::{Deserialize, Serialize};

use crate::params::{Interval, SimParams};

/// A named style of demonstration.
#[derive(
    Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Default, Serialize, Deserialize,
)]
#[serde(rename_all = "kebab-case")]
pub enum Style {
    /// The paper's study: one hand at a time, grasps and contacts reported (the default).
    #[default]
    Paper,
    /// Both hands at once, cut mid-motion, tracked as real trackers do.
    TwoHanded,
}

impl Style {
    /// Every style, the default first.
    pub const ALL: [Style; 2] = [Style::Paper, Style::TwoHanded];

    /// `paper`, `two-handed`.
    pub fn name(self) -> &'static str {
        match self {
            Style::Paper => "paper",
            Style::TwoHanded => "two-handed",
        }
    }

    /// The style of a name, as [`Style::name`] writes it.
    pub fn from_name(name: &str) -> Option<Style> {
        Style::ALL.into_iter().find(|s| s.name() == name)
    }

    /// The style of a name, or a message that lists the names (a command line's parser).
    pub fn parse(name: &str) -> Result<Style, String> {
        Style::from_name(name).ok_or_else(|| format!("{name:?} is none of {}", Style::names()))
    }

    /// The names, for messages: `paper, two-handed`.
    pub fn names() -> String {
        Style::ALL.map(Style::name).join(", ")
    }

    /// Whether this is the default, [`Style::Paper`] (for `skip_serializing_if`).
    pub fn is_default(&self) -> bool {
        *self == Style::Paper
    }

    /// The style's parameters: the defaults with the style's overrides.
    ///
    /// [`Style::TwoHanded`] sets what real tracking shows: 100 Hz; no velocities (poses
    /// only, as `/tf`), no held object, no contacts (grasps and support only from
    /// geometry); a noisier grip (0.05); runs of 1 to 4 dropped frames, about one a
    /// second; more timestamp jitter; three cubes on the table, as in the real study.
    pub fn params(self) -> SimParams {
        let mut p = SimParams::default();
        if self == Style::TwoHanded {
            p.style = self;
            p.frame_rate = 100.0;
            p.cubes = 3;
            p.velocities = false;
            p.held = false;
            p.contacts = false;
            p.grip_noise = 0.05;
            p.frame_drop = 0.01;
            p.frame_drop_run = 4;
            p.time_jitter = 0.0008;
            p.start_cut = Interval::new(0.2, 0.7);
            p.end_cut = Interval::new(0.3, 0.8);
        }
        p
    }
}

impl std::fmt::Display for Style {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.name())
    }
}

impl SimParams {
    /// Parameters from a JSON object (a `--params` file): the fields it names, and for
    /// the others the values of the style: `style` if given, else the file's own `style`
    /// field, else the paper's. A style given here wins over the file's.
    pub fn from_json_text(
        text: &str,
        style: Option<Style>,
    ) -> Result<SimParams, serde_json::Error> {
        // Parsed once as it is, so that mistakes are reported with their line and column.
        let named: SimParams = serde_json::from_str(text)?;
        let style = style.unwrap_or(named.style);
        let serde_json::Value::Object(fields) = serde_json::from_str(text)? else {
            return Ok(named);
        };
        let mut merged = style.params().to_json();
        if let Some(object) = merged.as_object_mut() {
            object.extend(fields);
            object.remove("style");
        }
        let mut params: SimParams = serde_json::from_value(merged)?;
        params.style = style;
        Ok(params)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_round_trip_and_the_paper_is_the_default() {
        for s in Style::ALL {
            assert_eq!(Style::from_name(s.name()), Some(s));
        }
        assert_eq!(Style::from_name("two_handed"), None);
        assert_eq!(Style::default(), Style::Paper);
        assert_eq!(Style::Paper.params(), SimParams::default());
        // The default writes no `style` field, so its files and hashes stay as they were.
        assert!(SimParams::default().to_json().get("style").is_none());
        let two = Style::TwoHanded.params();
        two.validate().unwrap();
        assert_eq!(two.to_json()["style"], "two-handed");
        assert_eq!(
            (two.held, two.contacts, two.velocities),
            (false, false, false)
        );
    }

    #[test]
    fn a_file_overrides_the_style_it_names_or_is_given() {
        let p = SimParams::from_json_text(r#"{"cubes": 4}"#, Some(Style::TwoHanded)).unwrap();
        assert_eq!(
            (p.style, p.cubes, p.frame_rate),
            (Style::TwoHanded, 4, 100.0)
        );
        let p = SimParams::from_json_text(r#"{"style": "two-handed", "grip_noise": 0.1}"#, None)
            .unwrap();
        assert_eq!(
            (p.style, p.grip_noise, p.held),
            (Style::TwoHanded, 0.1, false)
        );
        let p =
            SimParams::from_json_text(r#"{"style": "two-handed"}"#, Some(Style::Paper)).unwrap();
        assert_eq!(p, SimParams::default());
        // An empty file is the style's parameters exactly (the CLI reads no file as one).
        for style in Style::ALL {
            let p = SimParams::from_json_text("{}", Some(style)).unwrap();
            assert_eq!(p, style.params());
        }
        assert_eq!(
            SimParams::from_json_text("{}", None).unwrap(),
            SimParams::default()
        );
        let e = SimParams::from_json_text("{\n\"cubez\": 4}", Some(Style::TwoHanded)).unwrap_err();
        assert_eq!(e.line(), 2);
    }
}
