//! Source axes: a signed permutation from a source's frame to REP 103, and the quaternion
//! component order.
//!
//! A change of axes that is a signed permutation `M` maps positions as `p' = M p`. A
//! rotation `R` becomes `M R M^T`; for a unit quaternion `(w, v)` that is `w' = w`,
//! `v' = det(M) M v`. The `det(M)` factor is what keeps the result a proper rotation when
//! `M` flips handedness (Unity is left-handed): a rotation vector is a pseudovector.

use std::fmt;

use serde::de::{self, Deserializer, SeqAccess, Visitor};
use serde::{Deserialize, Serialize, Serializer};

/// One REP 103 axis written as a signed source axis: `"x"`, `"-z"`, ...
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct SignedAxis {
    /// The source axis, 0 (x), 1 (y) or 2 (z).
    pub axis: u8,
    /// Whether it is negated.
    pub negated: bool,
}

impl SignedAxis {
    const fn new(axis: u8, negated: bool) -> SignedAxis {
        SignedAxis { axis, negated }
    }

    fn parse(text: &str) -> Option<SignedAxis> {
        let (negated, name) = match text.strip_prefix('-') {
            Some(rest) => (true, rest),
            None => (false, text.strip_prefix('+').unwrap_or(text)),
        };
        let axis = match name {
            "x" => 0,
            "y" => 1,
            "z" => 2,
            _ => return None,
        };
        Some(SignedAxis { axis, negated })
    }
}

impl fmt::Display for SignedAxis {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let name = ["x", "y", "z"][usize::from(self.axis.min(2))];
        if self.negated {
            write!(f, "-{name}")
        } else {
            f.write_str(name)
        }
    }
}

/// The source's axes: REP 103's x (forward), y (left) and z (up), each as a signed source
/// axis. Always a signed permutation (each source axis used once).
///
/// In a mapping file: a preset name, `"rep103"` (identity) or `"unity"` (left-handed,
/// y up: REP 103 `(x, y, z)` is Unity's `(z, -x, y)`), or an explicit list such as
/// `["z", "-x", "y"]`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Axes {
    /// REP 103 x, y, z as signed source axes.
    pub rep103: [SignedAxis; 3],
}

impl Axes {
    /// The identity: the source already follows REP 103 (ROS).
    pub const REP103: Axes = Axes {
        rep103: [
            SignedAxis::new(0, false),
            SignedAxis::new(1, false),
            SignedAxis::new(2, false),
        ],
    };

    /// Unity: left-handed, y up, z forward, x right. REP 103 `(x, y, z)` = Unity `(z, -x, y)`.
    pub const UNITY: Axes = Axes {
        rep103: [
            SignedAxis::new(2, false),
            SignedAxis::new(0, true),
            SignedAxis::new(1, false),
        ],
    };

    /// The named presets, for parsing and printing.
    const PRESETS: [(&'static str, Axes); 2] = [("rep103", Axes::REP103), ("unity", Axes::UNITY)];

    /// The axes from three signed axes, if they form a signed permutation.
    pub fn new(rep103: [SignedAxis; 3]) -> Option<Axes> {
        let mut used = [false; 3];
        for a in rep103 {
            let slot = used.get_mut(usize::from(a.axis))?;
            if *slot {
                return None;
            }
            *slot = true;
        }
        Some(Axes { rep103 })
    }

    /// The determinant of the permutation matrix: +1 keeps handedness, -1 flips it.
    pub fn determinant(&self) -> f64 {
        let [a, b, c] = self.rep103.map(|s| s.axis);
        // The parity of the permutation (a, b, c) of (0, 1, 2).
        let even = matches!((a, b, c), (0, 1, 2) | (1, 2, 0) | (2, 0, 1));
        let negations = self.rep103.iter().filter(|s| s.negated).count();
        let sign = if even { 1.0 } else { -1.0 };
        if negations % 2 == 0 {
            sign
        } else {
            -sign
        }
    }

    /// A source vector (position or velocity) in REP 103 axes: `M v`.
    pub fn vector(&self, v: [f64; 3]) -> [f64; 3] {
        self.rep103.map(|s| {
            let value = v[usize::from(s.axis)];
            if s.negated {
                -value
            } else {
                value
            }
        })
    }

    /// A source rotation, as `(w, [x, y, z])` in source axes, in REP 103 axes:
    /// `w' = w`, `v' = det(M) M v`, so the result is a proper rotation.
    pub fn rotation(&self, w: f64, v: [f64; 3]) -> (f64, [f64; 3]) {
        let d = self.determinant();
        (w, self.vector(v).map(|c| d * c))
    }
}

impl Serialize for Axes {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        if let Some((name, _)) = Axes::PRESETS.iter().find(|(_, a)| a == self) {
            return s.serialize_str(name);
        }
        let names = self.rep103.map(|a| a.to_string());
        names.serialize(s)
    }
}

impl<'de> Deserialize<'de> for Axes {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Axes, D::Error> {
        struct AxesVisitor;
        impl<'de> Visitor<'de> for AxesVisitor {
            type Value = Axes;
            fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
                f.write_str(
                    "\"rep103\", \"unity\", or REP 103's x, y, z as signed source axes such as \
                     [\"z\", \"-x\", \"y\"]",
                )
            }
            fn visit_str<E: de::Error>(self, v: &str) -> Result<Axes, E> {
                Axes::PRESETS
                    .iter()
                    .find(|(name, _)| *name == v)
                    .map(|(_, a)| *a)
                    .ok_or_else(|| {
                        E::custom(format!(
                            "unknown axes preset `{v}`: use \"rep103\", \"unity\" or a list \
                             such as [\"z\", \"-x\", \"y\"]"
                        ))
                    })
            }
            fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<Axes, A::Error> {
                let mut axes = [SignedAxis::new(0, false); 3];
                for (i, slot) in axes.iter_mut().enumerate() {
                    let text: String = seq
                        .next_element()?
                        .ok_or_else(|| de::Error::invalid_length(i, &self))?;
                    *slot = SignedAxis::parse(&text).ok_or_else(|| {
                        de::Error::custom(format!(
                            "`{text}` is not a signed axis (\"x\", \"-x\", \"y\", \"-y\", \"z\" \
                             or \"-z\")"
                        ))
                    })?;
                }
                if seq.next_element::<de::IgnoredAny>()?.is_some() {
                    return Err(de::Error::invalid_length(4, &self));
                }
                Axes::new(axes).ok_or_else(|| {
                    de::Error::custom(
                        "the axes must use each of x, y and z once (a signed permutation)",
                    )
                })
            }
        }
        d.deserialize_any(AxesVisitor)
    }
}

/// The order of a quaternion's components in the source.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
pub enum QuaternionOrder {
    /// Scalar first, `[w, x, y, z]` (Unity loggers).
    #[serde(rename = "wxyz")]
    WFirst,
    /// Scalar last, `[x, y, z, w]` (ROS).
    #[serde(rename = "xyzw")]
    WLast,
}

impl QuaternionOrder {
    /// Splits four components in this order into `(w, [x, y, z])`.
    pub fn split(self, q: [f64; 4]) -> (f64, [f64; 3]) {
        match self {
            QuaternionOrder::WFirst => (q[0], [q[1], q[2], q[3]]),
            QuaternionOrder::WLast => (q[3], [q[0], q[1], q[2]]),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn unity_position_becomes_rep103() {
        assert_eq!(Axes::UNITY.vector([1.0, 2.0, 3.0]), [3.0, -1.0, 2.0]);
        assert_eq!(Axes::UNITY.determinant(), -1.0);
        assert_eq!(Axes::REP103.determinant(), 1.0);
    }

    #[test]
    fn unity_turn_about_y_is_a_turn_the_other_way_about_z() {
        let h = std::f64::consts::FRAC_PI_4;
        let (w, v) = Axes::UNITY.rotation(h.cos(), [0.0, h.sin(), 0.0]);
        assert!((w - h.cos()).abs() < 1e-12);
        assert!(v[0].abs() < 1e-12 && v[1].abs() < 1e-12);
        assert!((v[2] + h.sin()).abs() < 1e-12, "{v:?}");
    }

    #[test]
    fn determinant_counts_parity_and_negations() {
        let ax = |s: [&str; 3]| Axes::new(s.map(|t| SignedAxis::parse(t).unwrap())).unwrap();
        assert_eq!(ax(["y", "x", "z"]).determinant(), -1.0);
        assert_eq!(ax(["y", "z", "x"]).determinant(), 1.0);
        assert_eq!(ax(["-x", "-y", "z"]).determinant(), 1.0);
        assert_eq!(ax(["-x", "y", "z"]).determinant(), -1.0);
        assert!(Axes::new([SignedAxis::new(0, false); 3]).is_none());
    }
}
