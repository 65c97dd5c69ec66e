//! Unity VR playback logs, as a lab's Unity logger writes them (`docs/import.md`).
//!
//! One JSON document: `{"playbackTimestepMilliseconds": <ms>, "log": [step, ...]}`, each
//! step `{"time": <ms>, "logStep": [record, ...]}`, each record `{"name", "position":
//! [x, y, z], "orientation": [w, x, y, z], "velocity": [x, y, z], "events": [...]}` in
//! Unity's axes (left-handed, y up). Grab events sit in a controller's record:
//! `{"name": "OnGrabPressReplay", "property": "<object name>,<id>"}` starts holding the
//! named object, `{"name": "OnGrabReleaseReplay"}` ends it.
//!
//! The log is read with a streaming visitor over `log`: one step is in memory at a time,
//! whatever the length of the file. Numbers may also be written as the strings `"NaN"`,
//! `"Infinity"` and `"-Infinity"` (as .NET serialisers do), so that such a pose is
//! reported as a non-finite pose of its entity rather than as a syntax error.

// A reader of untrusted input (issue 23): no arithmetic that can wrap or panic, no
// cast that can truncate; each such operation is checked, saturating or proved in range.
#![deny(clippy::arithmetic_side_effects, clippy::cast_possible_truncation)]

use std::cell::{Cell, RefCell};
use std::collections::BTreeMap;
use std::fmt;
use std::io::{BufReader, Read};
use std::rc::Rc;

use rustc_hash::FxHashMap;
use serde::de::{self, DeserializeSeed, Deserializer, IgnoredAny, MapAccess, SeqAccess, Visitor};
use serde::Deserialize;

use crate::assemble::{Event, Held, Observation, Sink, Source};
use crate::error::{ImportError, Location, Problem};
use crate::mapping::Format;

/// The grab event's name.
pub const GRAB_PRESS: &str = "OnGrabPressReplay";
/// The release event's name.
pub const GRAB_RELEASE: &str = "OnGrabReleaseReplay";

/// Largest step of a log accepted, in bytes of its JSON text: 64 MiB (a step of 65,534
/// records with velocities and events takes about 15 MB). The reader holds one step in
/// memory; a step over this size is an input error naming the step and its line rather
/// than a buffer as large as the file. Text outside the steps (before the `log` list,
/// between and after its steps) counts towards the step that follows it.
pub const MAX_STEP_BYTES: u64 = 64 << 20;

/// Whether the start of a file looks like a Unity playback log: a JSON object whose
/// first kilobytes name `log` or `playbackTimestepMilliseconds`.
pub fn looks_like_unity_log(start: &[u8]) -> bool {
    let text = String::from_utf8_lossy(&start[..start.len().min(4096)]);
    let text = text.trim_start_matches('\u{feff}').trim_start();
    text.starts_with('{')
        && (text.contains("\"playbackTimestepMilliseconds\"") || text.contains("\"log\""))
}

/// The Unity log in the file at `path`, reopened for each pass.
pub fn log_file(
    path: &std::path::Path,
) -> UnityLog<impl FnMut() -> std::io::Result<std::fs::File> + '_> {
    UnityLog::new(move || std::fs::File::open(path))
}

/// A Unity playback log, reopened by `open` for each pass.
pub struct UnityLog<F> {
    open: F,
    playback_step: Option<f64>,
}

impl<F> fmt::Debug for UnityLog<F> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("UnityLog")
            .field("playback_step", &self.playback_step)
            .finish_non_exhaustive()
    }
}

impl<F, R> UnityLog<F>
where
    F: FnMut() -> std::io::Result<R>,
    R: Read,
{
    /// A log read from what `open` returns (called once per pass).
    pub fn new(open: F) -> UnityLog<F> {
        UnityLog {
            open,
            playback_step: None,
        }
    }
}

impl<F, R> Source for UnityLog<F>
where
    F: FnMut() -> std::io::Result<R>,
    R: Read,
{
    fn format(&self) -> Format {
        Format::Unity
    }

    fn pass(&mut self, sink: &mut dyn Sink) -> Result<(), ImportError> {
        let lines = Rc::new(Cell::new(0u64));
        let step_bytes = Rc::new(Cell::new(0u64));
        // serde_json reads a byte at a time and looks ahead by at most one, so counting
        // the newlines it has been given tells where each step ends.
        let input = LineCounter {
            inner: BufReader::with_capacity(1 << 16, (self.open)()?),
            lines: Rc::clone(&lines),
            step_bytes: Rc::clone(&step_bytes),
        };
        let state = RefCell::new(PassState {
            sink,
            lines: Rc::clone(&lines),
            step_bytes: Rc::clone(&step_bytes),
            step_end_line: 0,
            step: 0,
            in_log: false,
            problem: None,
            holding: FxHashMap::default(),
            observation: Observation::default(),
            seen: Vec::new(),
        });
        let mut de = serde_json::Deserializer::from_reader(input);
        let result = (TopLevel { state: &state })
            .deserialize(&mut de)
            .and_then(|step| de.end().map(|()| step));
        let state = state.into_inner();
        match result {
            Ok(step) => {
                self.playback_step = step;
                Ok(())
            }
            Err(e) => {
                if step_bytes.get() > MAX_STEP_BYTES {
                    let location = Location {
                        step: state.in_log.then_some(state.step),
                        line: Some(lines.get().saturating_add(1)),
                        ..Location::default()
                    };
                    let what = if state.in_log {
                        "the step is"
                    } else {
                        "the text before the `log` list is"
                    };
                    return Err(ImportError::input(
                        location,
                        Problem::new(format!(
                            "{what} longer than {MAX_STEP_BYTES} bytes, the most a Unity log \
                             step may have (a step is read whole)"
                        )),
                    ));
                }
                if e.is_io() {
                    return Err(ImportError::Io(std::io::Error::other(e.to_string())));
                }
                // A problem of the step's content is found once the step is read: the
                // position is then the step's end, and only its line is meaningful.
                let location = Location {
                    step: state.in_log.then_some(state.step),
                    line: Some(if state.problem.is_some() {
                        state.step_end_line
                    } else {
                        e.line() as u64
                    }),
                    column: state.problem.is_none().then_some(e.column() as u64),
                    ..Location::default()
                };
                let problem = state.problem.unwrap_or_else(|| {
                    let text = e.to_string();
                    let message = match text.rfind(" at line ") {
                        Some(i) => text[..i].to_string(),
                        None => text,
                    };
                    Problem::new(if e.is_eof() {
                        format!("{message} (truncated file?)")
                    } else if e.is_syntax() {
                        format!(
                            "not valid JSON: {message} (non-finite numbers must be written as \
                             the strings \"NaN\", \"Infinity\" or \"-Infinity\")"
                        )
                    } else {
                        message
                    })
                });
                Err(ImportError::input(location, problem))
            }
        }
    }

    fn meta(&self) -> BTreeMap<String, String> {
        let mut meta = BTreeMap::new();
        if let Some(ms) = self.playback_step {
            meta.insert("unity_playback_step_ms".to_string(), ms.to_string());
        }
        meta
    }
}

struct PassState<'s> {
    sink: &'s mut dyn Sink,
    /// Index of the step being read.
    step: u64,
    /// Whether reading has reached the `log` list.
    in_log: bool,
    /// Newlines read so far.
    lines: Rc<Cell<u64>>,
    /// Bytes read since the last step began (the reader refuses more than
    /// [`MAX_STEP_BYTES`]).
    step_bytes: Rc<Cell<u64>>,
    /// The line on which the last step read ends (where its problems are reported).
    step_end_line: u64,
    /// A problem the sink or the step's checks raised (the JSON error carries only the
    /// position).
    problem: Option<Problem>,
    /// What each controller holds since its last grab event.
    holding: FxHashMap<String, Held>,
    observation: Observation,
    seen: Vec<String>,
}

impl PassState<'_> {
    fn step(&mut self, step: Step) -> Result<(), Problem> {
        let time = step.time.0 / 1000.0;
        self.seen.clear();
        for (i, r) in step.log_step.into_iter().enumerate() {
            if self.seen.contains(&r.name) {
                return Err(Problem::at(
                    &r.name,
                    &format!("logStep[{i}].name"),
                    "appears twice in one step (duplicate entity name)",
                ));
            }
            for (k, e) in r.events.iter().enumerate() {
                match e.name.as_str() {
                    GRAB_PRESS => {
                        let object = e
                            .property
                            .rsplit_once(',')
                            .map_or(e.property.as_str(), |(name, _id)| name)
                            .trim();
                        if object.is_empty() {
                            return Err(Problem::at(
                                &r.name,
                                &format!("logStep[{i}].events[{k}].property"),
                                format!(
                                    "{GRAB_PRESS} names no object (expected \"<object name>,<id>\", \
                                     found {:?})",
                                    e.property
                                ),
                            ));
                        }
                        self.holding
                            .insert(r.name.clone(), Held::Object(object.to_string()));
                    }
                    GRAB_RELEASE => {
                        self.holding.insert(r.name.clone(), Held::Nothing);
                    }
                    _ => {}
                }
            }
            let o = &mut self.observation;
            o.time = time;
            o.name.clone_from(&r.name);
            o.position = r.position.map(|n| n.0);
            o.orientation = r.orientation.map(|n| n.0);
            o.velocity = r.velocity.map(|v| v.map(|n| n.0));
            o.grip = None;
            o.held = self.holding.get(&r.name).cloned();
            o.grip = o.held.as_ref().map(|h| match h {
                Held::Nothing => 0.0,
                Held::Object(_) => 1.0,
            });
            o.grabbed_by = None;
            o.contacts.clear();
            self.sink.event(Event::Observe(o)).map_err(|mut p| {
                if let Some(f) = &mut p.field {
                    if matches!(
                        f.split(['[', '.']).next(),
                        Some("position" | "orientation" | "velocity")
                    ) {
                        *f = format!("logStep[{i}].{f}");
                    }
                }
                p
            })?;
            self.seen.push(r.name);
        }
        self.sink.event(Event::Frame(time))
    }
}

/// A number, also from the strings .NET writes for non-finite values.
#[derive(Debug, Clone, Copy)]
struct Number(f64);

impl<'de> Deserialize<'de> for Number {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Number, D::Error> {
        struct V;
        impl Visitor<'_> for V {
            type Value = Number;
            fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
                f.write_str("a number")
            }
            fn visit_f64<E: de::Error>(self, v: f64) -> Result<Number, E> {
                Ok(Number(v))
            }
            fn visit_i64<E: de::Error>(self, v: i64) -> Result<Number, E> {
                Ok(Number(v as f64))
            }
            fn visit_u64<E: de::Error>(self, v: u64) -> Result<Number, E> {
                Ok(Number(v as f64))
            }
            fn visit_str<E: de::Error>(self, v: &str) -> Result<Number, E> {
                match v {
                    "NaN" => Ok(Number(f64::NAN)),
                    "Infinity" => Ok(Number(f64::INFINITY)),
                    "-Infinity" => Ok(Number(f64::NEG_INFINITY)),
                    _ => Err(E::invalid_value(de::Unexpected::Str(v), &self)),
                }
            }
        }
        d.deserialize_any(V)
    }
}

#[derive(Debug, Deserialize)]
struct UnityEvent {
    name: String,
    #[serde(default)]
    property: String,
}

#[derive(Debug, Deserialize)]
struct Record {
    name: String,
    position: [Number; 3],
    orientation: [Number; 4],
    #[serde(default)]
    velocity: Option<[Number; 3]>,
    #[serde(default)]
    events: Vec<UnityEvent>,
}

#[derive(Debug, Deserialize)]
struct Step {
    time: Number,
    #[serde(rename = "logStep")]
    log_step: Vec<Record>,
}

struct TopLevel<'a, 's> {
    state: &'a RefCell<PassState<'s>>,
}

impl<'de> DeserializeSeed<'de> for TopLevel<'_, '_> {
    /// The playback step in milliseconds, if given.
    type Value = Option<f64>;
    fn deserialize<D: Deserializer<'de>>(self, d: D) -> Result<Option<f64>, D::Error> {
        d.deserialize_map(self)
    }
}

impl<'de> Visitor<'de> for TopLevel<'_, '_> {
    type Value = Option<f64>;
    fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("a Unity playback log: an object with `playbackTimestepMilliseconds` and `log`")
    }
    fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<Option<f64>, A::Error> {
        let mut playback = None;
        let mut log = false;
        while let Some(key) = map.next_key::<String>()? {
            match key.as_str() {
                "playbackTimestepMilliseconds" => playback = Some(map.next_value::<Number>()?.0),
                "log" => {
                    if log {
                        return Err(de::Error::duplicate_field("log"));
                    }
                    map.next_value_seed(Log { state: self.state })?;
                    self.state.borrow_mut().in_log = false;
                    log = true;
                }
                _ => {
                    map.next_value::<IgnoredAny>()?;
                }
            }
        }
        if !log {
            return Err(de::Error::missing_field("log"));
        }
        Ok(playback)
    }
}

struct Log<'a, 's> {
    state: &'a RefCell<PassState<'s>>,
}

impl<'de> DeserializeSeed<'de> for Log<'_, '_> {
    type Value = ();
    fn deserialize<D: Deserializer<'de>>(self, d: D) -> Result<(), D::Error> {
        d.deserialize_seq(self)
    }
}

impl<'de> Visitor<'de> for Log<'_, '_> {
    type Value = ();
    fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("a list of steps `{\"time\", \"logStep\"}`")
    }
    fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<(), A::Error> {
        self.state.borrow_mut().in_log = true;
        loop {
            self.state.borrow().step_bytes.set(0);
            let Some(step) = seq.next_element::<Step>()? else {
                break;
            };
            let mut state = self.state.borrow_mut();
            state.step_end_line = state.lines.get().saturating_add(1);
            if let Err(p) = state.step(step) {
                let message = p.message.clone();
                state.problem = Some(p);
                return Err(de::Error::custom(message));
            }
            state.step = state.step.saturating_add(1);
        }
        Ok(())
    }
}

/// Counts the newlines read through it, and the bytes since the step began; refuses to
/// read more than [`MAX_STEP_BYTES`] for one step (the pass reports it as the step's
/// problem).
struct LineCounter<R> {
    inner: R,
    lines: Rc<Cell<u64>>,
    step_bytes: Rc<Cell<u64>>,
}

impl<R: Read> Read for LineCounter<R> {
    fn read(&mut self, buf: &mut [u8]) -> std::io::Result<usize> {
        let n = self.inner.read(buf)?;
        let read = &buf[..n.min(buf.len())];
        let newlines = read.iter().filter(|&&b| b == b'\n').count();
        self.lines
            .set(self.lines.get().saturating_add(newlines as u64));
        let step = self.step_bytes.get().saturating_add(read.len() as u64);
        self.step_bytes.set(step);
        if step > MAX_STEP_BYTES {
            return Err(std::io::Error::other("step too large"));
        }
        Ok(n)
    }
}
