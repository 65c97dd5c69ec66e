//! The format's rules on headers and frames, shared by the writer (which refuses what the
//! reader would refuse) and the reader (which checks a header once it is parsed; frame
//! rules are checked while parsing, with the same messages, to point at the token).

// A reader of untrusted input (issue 23): no arithmetic that can wrap or panic, no
// cast that can truncate; each such operation is checked, saturating or proved in range.
#![deny(clippy::arithmetic_side_effects, clippy::cast_possible_truncation)]

use crate::model::{EntityId, EntityKind, EntityState, Frame, Header, Pose};

/// A broken rule: the field (as a path) and what is wrong.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Problem {
    /// The field, as a path such as `entities[1].name` or `entities.cube_1.grip`.
    pub field: String,
    /// What is wrong.
    pub message: String,
}

fn problem(field: impl Into<String>, message: impl Into<String>) -> Problem {
    Problem {
        field: field.into(),
        message: message.into(),
    }
}

/// Longest entity name in bytes.
pub const MAX_NAME_LEN: usize = 64;

/// Most entities a recording may declare: 65,534. Readers downstream index entities in 16
/// bits (`grounding` keeps the object a hand acts on or holds as a `u16`, with `u16::MAX`
/// for none), so the format stops one short of that.
pub const MAX_ENTITIES: usize = 65_534;

/// Whether `name` is a valid entity name: an ASCII letter, then ASCII letters, digits, `_`
/// or `-`, at most [`MAX_NAME_LEN`] bytes.
pub fn is_valid_name(name: &str) -> bool {
    let b = name.as_bytes();
    !b.is_empty()
        && b.len() <= MAX_NAME_LEN
        && b[0].is_ascii_alphabetic()
        && b.iter()
            .all(|&c| c.is_ascii_alphanumeric() || c == b'_' || c == b'-')
}

pub(crate) fn name_message(name: &str) -> String {
    format!(
        "`{name}` is not a valid entity name (an ASCII letter, then letters, digits, `_` or `-`, \
         at most {MAX_NAME_LEN} bytes)"
    )
}

pub(crate) fn too_many_entities_message(count: usize) -> String {
    format!(
        "{count} entities: a recording declares at most {MAX_ENTITIES} (entities are indexed \
         in 16 bits); split the scene or leave untracked objects out"
    )
}

pub(crate) fn grip_range_message(grip: f32) -> String {
    format!("grip {grip} is outside 0..1")
}

pub(crate) fn quaternion_message(norm: f32) -> String {
    format!(
        "not a unit quaternion (norm {norm}); write rotations as (x, y, z, w) with norm 1 \
         (within {})",
        crate::Quaternion::NORM_TOLERANCE
    )
}

pub(crate) fn fixed_in_frame_message(name: &str) -> String {
    format!("entity `{name}` is fixed (its pose is in the header) and must not be listed in frames")
}

pub(crate) fn grip_not_hand_message(name: &str, kind: EntityKind) -> String {
    format!("`{name}` is a {kind}, not a hand: only hands have a grip")
}

pub(crate) fn holding_not_hand_message(name: &str, kind: EntityKind) -> String {
    format!("`{name}` is a {kind}, not a hand: only hands hold objects")
}

pub(crate) fn holding_itself_message(name: &str) -> String {
    format!("hand `{name}` cannot hold itself")
}

pub(crate) fn holding_hand_message(held: &str) -> String {
    format!("`{held}` is a hand: a hand holds objects, not hands")
}

pub(crate) fn missing_grip_message(name: &str) -> String {
    format!("hand `{name}` has no `grip` (hands need one, 0 open to 1 closed)")
}

pub(crate) fn contact_self_message(name: &str) -> String {
    format!("a contact of `{name}` with itself")
}

/// Checks a header: names, sizes, fixed poses, frame rate.
pub fn check_header(header: &Header) -> Result<(), Problem> {
    if header.id.is_empty() {
        return Err(problem("id", "the recording id is empty"));
    }
    if !(header.frame_rate.is_finite() && header.frame_rate > 0.0) {
        return Err(problem(
            "frame_rate",
            format!(
                "frame rate {} is not a positive number of frames per second",
                header.frame_rate
            ),
        ));
    }
    if header.entities.is_empty() {
        return Err(problem(
            "entities",
            "no entities: a recording tracks something",
        ));
    }
    if header.entities.len() > MAX_ENTITIES {
        return Err(problem(
            "entities",
            too_many_entities_message(header.entities.len()),
        ));
    }
    let mut seen: rustc_hash::FxHashMap<String, usize> = Default::default();
    for (i, e) in header.entities.iter().enumerate() {
        if !is_valid_name(&e.name) {
            return Err(problem(
                format!("entities[{i}].name"),
                name_message(&e.name),
            ));
        }
        if let Some(j) = seen.insert(e.name.to_ascii_lowercase(), i) {
            return Err(problem(
                format!("entities[{i}].name"),
                format!(
                    "`{}` is declared twice (also entities[{j}] `{}`; names are compared \
                     ignoring case)",
                    e.name, header.entities[j].name
                ),
            ));
        }
        let s = e.size;
        if !(s.is_finite() && s.x > 0.0 && s.y > 0.0 && s.z > 0.0) {
            return Err(problem(
                format!("entities[{i}].size"),
                format!(
                    "size [{}, {}, {}] is not three positive lengths in metres",
                    s.x, s.y, s.z
                ),
            ));
        }
        if let Some(pose) = e.fixed {
            check_pose(&pose, &format!("entities[{i}].pose"))?;
        }
    }
    Ok(())
}

fn check_pose(pose: &Pose, at: &str) -> Result<(), Problem> {
    if !pose.position.is_finite() {
        return Err(problem(format!("{at}.pos"), "position is not finite"));
    }
    if !pose.orientation.is_finite() {
        return Err(problem(format!("{at}.rot"), "rotation is not finite"));
    }
    if !pose.orientation.is_unit() {
        return Err(problem(
            format!("{at}.rot"),
            quaternion_message(pose.orientation.norm()),
        ));
    }
    Ok(())
}

/// Checks a frame against its header and the previous frame's time.
pub fn check_frame(header: &Header, frame: &Frame, previous: Option<f64>) -> Result<(), Problem> {
    if !frame.time.is_finite() {
        return Err(problem("t", format!("time {} is not finite", frame.time)));
    }
    if let Some(p) = previous {
        if frame.time <= p {
            return Err(problem(
                "t",
                format!(
                    "time {} s is not after the previous frame's {p} s",
                    frame.time
                ),
            ));
        }
    }
    if frame.states.len() != header.entities.len() {
        return Err(problem(
            "entities",
            format!(
                "{} entity states for {} entities in the header",
                frame.states.len(),
                header.entities.len()
            ),
        ));
    }
    // As many states as entities (checked above), at most `MAX_ENTITIES`: ids fit u32.
    for (id, state) in (0u32..).map(EntityId).zip(&frame.states) {
        if let Some(state) = state {
            check_state(header, id, state)?;
        }
    }
    for (i, c) in frame.contacts.iter().enumerate() {
        for (j, id) in [c.a, c.b].into_iter().enumerate() {
            if id.index() >= header.entities.len() {
                return Err(problem(
                    format!("contacts[{i}][{j}]"),
                    format!("entity id {} out of range", id.0),
                ));
            }
        }
        if c.a == c.b {
            return Err(problem(
                format!("contacts[{i}]"),
                contact_self_message(&header.entity(c.a).name),
            ));
        }
    }
    Ok(())
}

fn check_state(header: &Header, id: EntityId, state: &EntityState) -> Result<(), Problem> {
    let entity = header.entity(id);
    let name = &entity.name;
    let at = format!("entities.{name}");
    if entity.fixed.is_some() {
        return Err(problem(at, fixed_in_frame_message(name)));
    }
    check_pose(&state.pose, &at)?;
    if let Some(v) = state.velocity {
        if !v.is_finite() {
            return Err(problem(format!("{at}.vel"), "velocity is not finite"));
        }
    }
    match (entity.kind, state.grip) {
        (EntityKind::Hand, None) => return Err(problem(at, missing_grip_message(name))),
        (EntityKind::Hand, Some(g)) if !(0.0..=1.0).contains(&g) => {
            return Err(problem(format!("{at}.grip"), grip_range_message(g)))
        }
        (kind, Some(_)) if kind != EntityKind::Hand => {
            return Err(problem(
                format!("{at}.grip"),
                grip_not_hand_message(name, kind),
            ))
        }
        _ => {}
    }
    if let Some(held) = state.holding {
        let field = format!("{at}.holding");
        if entity.kind != EntityKind::Hand {
            return Err(problem(field, holding_not_hand_message(name, entity.kind)));
        }
        let Some(target) = header.entities.get(held.index()) else {
            return Err(problem(field, format!("entity id {} out of range", held.0)));
        };
        if held == id {
            return Err(problem(field, holding_itself_message(name)));
        }
        if target.kind == EntityKind::Hand {
            return Err(problem(field, holding_hand_message(&target.name)));
        }
    }
    Ok(())
}

#[cfg(test)]
#[allow(clippy::arithmetic_side_effects, clippy::cast_possible_truncation)] // tests, not readers
mod tests {
    use super::*;

    #[test]
    fn names() {
        for ok in ["cube_1", "left-hand", "T", "a1"] {
            assert!(is_valid_name(ok), "{ok}");
        }
        for bad in [
            "",
            "1cube",
            "cube 1",
            "cube\"",
            "_x",
            &"x".repeat(65),
            "kübel",
        ] {
            assert!(!is_valid_name(bad), "{bad}");
        }
    }
}
