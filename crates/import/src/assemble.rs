//! Source-independent assembly: observations and frame ticks in, native frames out.
//!
//! A [`Source`] replays its content as [`Event`]s, in time order, as often as asked.
//! [`Importer::survey`] makes the first pass (names, kinds, start poses, which entities
//! report velocities, frame times) and plans the native [`Header`]; [`Importer::assemble`]
//! makes the second and yields one [`Frame`] per frame tick. Memory is bounded by the
//! number of entities, never by the length of the source.

use std::collections::BTreeMap;

use recording::{
    Contact, Entity, EntityId, EntityKind, EntityState, Frame, Header, Pose, Quaternion, Vec3,
};
use rustc_hash::FxHashMap;

use crate::error::{ImportError, Location, Problem};
use crate::mapping::{ContactSource, Format, GraspSource, Mapping, Origin, Role};

/// What a source says about one entity at one moment, in the source's own axes, units and
/// quaternion order (the [`Mapping`] converts them).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Observation {
    /// Seconds, on the source's clock (any origin; the import subtracts the first frame's).
    pub time: f64,
    /// The source's name for the entity (a tf frame id, a Unity object name).
    pub name: String,
    /// Position in source axes and units.
    pub position: [f64; 3],
    /// Orientation in the source's axes and component order.
    pub orientation: [f64; 4],
    /// Linear velocity in source axes and units per second, when reported. An entity
    /// whose velocities are all zero is taken to report none.
    pub velocity: Option<[f64; 3]>,
    /// Hand closure 0 (open) to 1 (closed), when reported.
    pub grip: Option<f64>,
    /// What a hand holds, when the source says (grab events, a "held" field).
    pub held: Option<Held>,
    /// The hand holding this object, when the source says so from the object's side
    /// (a "grabbed by" relation): `Some("")` for none.
    pub grabbed_by: Option<String>,
    /// Source names of the entities it touches (used with `contacts = "reported"`).
    pub contacts: Vec<String>,
}

/// What a hand holds, as a source reports it.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Held {
    /// Nothing.
    Nothing,
    /// The object with this source name.
    Object(String),
}

/// One event of a source, in time order.
#[derive(Debug, Clone, Copy)]
pub enum Event<'a> {
    /// An entity was observed.
    Observe(&'a Observation),
    /// A frame at this time (seconds, source clock): every entity takes its latest
    /// observation at or before it, and is missing if that is older than `max_age`.
    Frame(f64),
}

/// Where a source sends its events.
pub trait Sink {
    /// Takes one event; a [`Problem`] stops the pass, and the source reports it with its
    /// location.
    fn event(&mut self, event: Event<'_>) -> Result<(), Problem>;
}

/// A re-readable source of events: a Unity log, a bag.
pub trait Source {
    /// The source's format (for the defaults and the report).
    fn format(&self) -> Format;

    /// Replays the whole source from its start into `sink`. Called twice per import. A
    /// [`Problem`] returned by the sink must be returned as [`ImportError::Input`] with
    /// the source's location of the event.
    fn pass(&mut self, sink: &mut dyn Sink) -> Result<(), ImportError>;

    /// Notes about the source for the header's `meta` (after a pass).
    fn meta(&self) -> BTreeMap<String, String> {
        BTreeMap::new()
    }
}

/// A source entity the import keeps.
#[derive(Debug, Clone, PartialEq)]
pub struct MappedEntity {
    /// The source's name.
    pub source: String,
    /// The native entity.
    pub id: EntityId,
    /// The rule that mapped it.
    pub rule: String,
    /// Observations of it.
    pub observations: u64,
    /// Whether its velocities are kept (false: none reported, or all zero).
    pub velocity: bool,
}

/// A source entity left out, and why.
#[derive(Debug, Clone, PartialEq)]
pub struct IgnoredEntity {
    /// The source's name.
    pub source: String,
    /// Why.
    pub reason: String,
}

/// An entity missing from frames (its latest observation older than `max_age`) between
/// two frames where it was present.
#[derive(Debug, Clone, PartialEq)]
pub struct Gap {
    /// The native entity.
    pub entity: EntityId,
    /// Native time of the last frame before the gap with the entity present.
    pub from: f64,
    /// Native time of the first frame after it with the entity present.
    pub to: f64,
}

/// What an import did, per file.
#[derive(Debug, Clone, PartialEq)]
pub struct Report {
    /// The source format.
    pub format: Format,
    /// Native frames written.
    pub frames: u64,
    /// Frame ticks dropped because they repeated the previous frame's time.
    pub repeated_ticks: u64,
    /// Seconds from the first frame to the last.
    pub duration: f64,
    /// Measured frames per second.
    pub rate: f64,
    /// Source entities kept, in header order.
    pub mapped: Vec<MappedEntity>,
    /// Source entities left out.
    pub ignored: Vec<IgnoredEntity>,
    /// How the table was found.
    pub table: String,
    /// Grasps found (a hand starting to hold an object).
    pub grasps: u64,
    /// How many gaps there were.
    pub gap_count: u64,
    /// The longest gaps (at most [`Report::LONGEST_GAPS`]), longest first; kept bounded
    /// so that memory does not grow with the source.
    pub gaps: Vec<Gap>,
}

impl Report {
    /// How many of the longest gaps a report keeps.
    pub const LONGEST_GAPS: usize = 10;

    fn add_gap(&mut self, gap: Gap) {
        self.gap_count += 1;
        let length = gap.to - gap.from;
        let at = self
            .gaps
            .iter()
            .position(|g| g.to - g.from < length)
            .unwrap_or(self.gaps.len());
        if at < Report::LONGEST_GAPS {
            self.gaps.insert(at, gap);
            self.gaps.truncate(Report::LONGEST_GAPS);
        }
    }

    /// The report as text, one fact a line, with the native names of `header`.
    pub fn render(&self, header: &Header) -> String {
        let mut out = String::new();
        let mut line = |s: String| {
            out.push_str(&s);
            out.push('\n');
        };
        line(format!(
            "{} frames over {:.3} s, measured rate {:.1} Hz{}",
            self.frames,
            self.duration,
            self.rate,
            if self.repeated_ticks > 0 {
                format!(
                    " ({} ticks with a repeated time dropped)",
                    self.repeated_ticks
                )
            } else {
                String::new()
            }
        ));
        line(format!("entities mapped: {}", self.mapped.len()));
        for m in &self.mapped {
            let e = header.entity(m.id);
            line(format!(
                "  {} -> {} ({}{}, {}; {} observations{})",
                m.source,
                e.name,
                e.kind,
                hand_side(&e.name),
                m.rule,
                m.observations,
                if m.velocity { ", velocities" } else { "" }
            ));
        }
        line(format!("table: {}", self.table));
        line(format!("entities ignored: {}", self.ignored.len()));
        for i in &self.ignored {
            line(format!("  {} ({})", i.source, i.reason));
        }
        line(format!("grasps found: {}", self.grasps));
        line(format!(
            "gaps: {}{}",
            self.gap_count,
            if self.gap_count > self.gaps.len() as u64 {
                format!(" (the {} longest:)", self.gaps.len())
            } else {
                String::new()
            }
        ));
        for g in &self.gaps {
            line(format!(
                "  {} missing from {:.3} s to {:.3} s ({:.3} s)",
                header.entity(g.entity).name,
                g.from,
                g.to,
                g.to - g.from
            ));
        }
        out
    }
}

fn hand_side(name: &str) -> &'static str {
    match name {
        "left_hand" => ", left",
        "right_hand" => ", right",
        _ => "",
    }
}

/// Per source name, what the first pass learned.
#[derive(Debug, Clone)]
struct Surveyed {
    name: String,
    first: Converted,
    last_time: f64,
    observations: u64,
    moving_velocity: bool,
}

/// A pose in REP 103 axes and metres, as the source placed it (before the box origin).
#[derive(Debug, Clone, Copy, PartialEq)]
struct Converted {
    position: [f64; 3],
    /// (w, x, y, z), unit.
    rotation: (f64, [f64; 3]),
}

/// The first pass.
#[derive(Debug, Default)]
struct Survey {
    entities: Vec<Surveyed>,
    index: FxHashMap<String, usize>,
    frames: u64,
    repeated_ticks: u64,
    first_frame: Option<f64>,
    last_frame: Option<f64>,
}

/// Converts and checks an observation's pose and velocity.
fn convert(mapping: &Mapping, o: &Observation) -> Result<(Converted, Option<[f64; 3]>), Problem> {
    if !o.time.is_finite() {
        return Err(Problem::at(
            &o.name,
            "time",
            format!("time {} is not finite", o.time),
        ));
    }
    if let Some(i) = o.position.iter().position(|v| !v.is_finite()) {
        return Err(Problem::at(
            &o.name,
            &format!("position[{i}]"),
            format!("{} is not a finite position", o.position[i]),
        ));
    }
    if let Some(i) = o.orientation.iter().position(|v| !v.is_finite()) {
        return Err(Problem::at(
            &o.name,
            &format!("orientation[{i}]"),
            format!("{} is not a finite quaternion component", o.orientation[i]),
        ));
    }
    if let Some(v) = o.velocity {
        if let Some(i) = v.iter().position(|v| !v.is_finite()) {
            return Err(Problem::at(
                &o.name,
                &format!("velocity[{i}]"),
                format!("{} is not a finite velocity", v[i]),
            ));
        }
    }
    if let Some(g) = o.grip {
        if !(g.is_finite() && (0.0..=1.0).contains(&g)) {
            return Err(Problem::at(
                &o.name,
                "grip",
                format!("grip {g} is outside 0..1"),
            ));
        }
    }
    let norm = o.orientation.iter().map(|v| v * v).sum::<f64>().sqrt();
    // Loggers round components; a norm this far off is not a rounded unit quaternion.
    if !(0.9..=1.1).contains(&norm) {
        return Err(Problem::at(
            &o.name,
            "orientation",
            format!("not a unit quaternion (norm {norm:.4})"),
        ));
    }
    let (w, v) = mapping.quaternion.split(o.orientation);
    let (w, v) = mapping.axes.rotation(w / norm, v.map(|c| c / norm));
    let position = mapping.axes.vector(o.position).map(|c| c * mapping.unit);
    let scaled = |p: [f64; 3]| -> Result<[f64; 3], Problem> {
        // f32 in the native model: a finite f64 can still overflow it.
        if p.iter().all(|c| (*c as f32).is_finite()) {
            Ok(p)
        } else {
            Err(Problem::at(
                &o.name,
                "position",
                format!("{p:?} is too large for metres"),
            ))
        }
    };
    let position = scaled(position)?;
    let velocity = o
        .velocity
        .map(|v| mapping.axes.vector(v).map(|c| c * mapping.unit));
    Ok((
        Converted {
            position,
            rotation: (w, v),
        },
        velocity,
    ))
}

struct SurveySink<'m> {
    mapping: &'m Mapping,
    survey: Survey,
}

impl Sink for SurveySink<'_> {
    fn event(&mut self, event: Event<'_>) -> Result<(), Problem> {
        let s = &mut self.survey;
        match event {
            Event::Frame(t) => {
                if !t.is_finite() {
                    return Err(Problem::new(format!("frame time {t} is not finite")));
                }
                match s.last_frame {
                    Some(last) if t < last => {
                        return Err(Problem::new(format!(
                            "time goes backwards: {t} s after {last} s"
                        )))
                    }
                    Some(last) if t == last => s.repeated_ticks += 1,
                    _ => {
                        s.frames += 1;
                        s.first_frame.get_or_insert(t);
                        s.last_frame = Some(t);
                    }
                }
            }
            Event::Observe(o) => {
                let (converted, velocity) = convert(self.mapping, o)?;
                let moving = velocity.is_some_and(|v| v.iter().any(|c| *c != 0.0));
                match s.index.get(&o.name) {
                    Some(&i) => {
                        let e = &mut s.entities[i];
                        if o.time < e.last_time {
                            return Err(Problem::at(
                                &o.name,
                                "time",
                                format!(
                                    "time goes backwards: observed at {} s after {} s",
                                    o.time, e.last_time
                                ),
                            ));
                        }
                        e.last_time = o.time;
                        e.observations += 1;
                        e.moving_velocity |= moving;
                    }
                    None => {
                        s.index.insert(o.name.clone(), s.entities.len());
                        s.entities.push(Surveyed {
                            name: o.name.clone(),
                            first: converted,
                            last_time: o.time,
                            observations: 1,
                            moving_velocity: moving,
                        });
                    }
                }
            }
        }
        Ok(())
    }
}

/// How one source name is treated in the second pass.
#[derive(Debug, Clone, Copy)]
enum Target {
    /// A native entity that moves.
    Tracked(EntityId),
    /// The fixed table, or another entity left out.
    Skipped,
}

/// The plan of an import: the native header and how each source name maps onto it. Made
/// by the first pass ([`Importer::survey`]); the second ([`Importer::assemble`]) uses it.
#[derive(Debug, Clone)]
pub struct Importer {
    mapping: Mapping,
    header: Header,
    targets: FxHashMap<String, Target>,
    /// Per native entity: its origin offset along its own z (centre = pose + R (0,0,dz)).
    origin_lift: Vec<f64>,
    /// Per native entity: whether its velocities are kept.
    velocity: Vec<bool>,
    first_frame: f64,
    report: Report,
}

/// Distance between a hand and a cube below which a grasp from geometry can start (m).
const GRASP_REACH: f64 = 0.12;
/// A held cube is let go when it has moved this far from where it sat in the hand (m).
const GRASP_SLIP: f64 = 0.03;
/// A cube moves with a hand when it moved at least this far since the last frame (m).
const GRASP_MIN_STEP: f64 = 0.004;

impl Importer {
    /// The first pass: reads `source` once, maps its names and plans the header (with
    /// recording id `id`).
    ///
    /// The table: one table entity whose size the mapping gives and that some cube rests
    /// on at the start becomes the fixed table at its first pose. Otherwise (no table,
    /// several, or geometry unknown, such as a pivot on the floor) the support surface is
    /// the plane under the lowest cube at the start, and the table is a slab under the
    /// cubes, named after the table entity nearest the cubes (or `table`). Other tables
    /// are ignored.
    pub fn survey(
        source: &mut dyn Source,
        mapping: &Mapping,
        id: &str,
    ) -> Result<Importer, ImportError> {
        let mut sink = SurveySink {
            mapping,
            survey: Survey::default(),
        };
        source.pass(&mut sink)?;
        let survey = sink.survey;
        let (Some(first_frame), Some(last_frame)) = (survey.first_frame, survey.last_frame) else {
            return Err(ImportError::input(
                Location::default(),
                Problem::new("no frames: the source has no step or clock message"),
            ));
        };

        let mut entities: Vec<Entity> = Vec::new();
        let mut mapped = Vec::new();
        let mut ignored = Vec::new();
        let mut targets = FxHashMap::default();
        let mut origin_lift = Vec::new();
        let mut velocity = Vec::new();
        let mut tables = Vec::new();
        let mut natives: FxHashMap<String, String> = FxHashMap::default();
        for s in &survey.entities {
            let r = mapping.resolve(&s.name);
            if r.role == Role::Table {
                tables.push((s, r));
                targets.insert(s.name.clone(), Target::Skipped);
                continue;
            }
            let Some(kind) = r.role.kind() else {
                targets.insert(s.name.clone(), Target::Skipped);
                ignored.push(IgnoredEntity {
                    source: s.name.clone(),
                    reason: if r.rule == "no rule" {
                        "no rule matches".to_string()
                    } else {
                        format!("{} says ignore", r.rule)
                    },
                });
                continue;
            };
            if let Some(other) = natives.insert(r.native.to_ascii_lowercase(), s.name.clone()) {
                return Err(duplicate(&s.name, &other, &r.native));
            }
            let size = r.size.unwrap_or(crate::mapping::OTHER_SIZE);
            let id = EntityId(entities.len() as u32);
            entities.push(Entity {
                name: r.native.clone(),
                kind,
                size: vec3(size),
                fixed: None,
            });
            origin_lift.push(match r.origin {
                Origin::Center => 0.0,
                Origin::Bottom => size[2] / 2.0,
            });
            velocity.push(s.moving_velocity);
            targets.insert(s.name.clone(), Target::Tracked(id));
            mapped.push(MappedEntity {
                source: s.name.clone(),
                id,
                rule: r.rule,
                observations: s.observations,
                velocity: s.moving_velocity,
            });
        }

        // Cubes' resting boxes at the start, for the support surface.
        let cubes: Vec<([f64; 3], [f64; 3])> = mapped
            .iter()
            .filter(|m| entities[m.id.index()].kind == EntityKind::Cube)
            .filter_map(|m| {
                let s = &survey.entities[*survey.index.get(&m.source)?];
                let e = &entities[m.id.index()];
                let centre = lifted(s.first, origin_lift[m.id.index()]);
                Some((centre, [e.size.x, e.size.y, e.size.z].map(f64::from)))
            })
            .collect();
        let table = plan_table(&tables, &cubes, &mut ignored);
        let table_note = match table {
            Some((entity, note)) => {
                if let Some(other) =
                    natives.insert(entity.name.to_ascii_lowercase(), entity.name.clone())
                {
                    return Err(duplicate(&entity.name, &other, &entity.name));
                }
                entities.push(entity);
                origin_lift.push(0.0);
                velocity.push(false);
                note
            }
            None => "none (no cube to rest on one)".to_string(),
        };
        if entities.is_empty() {
            return Err(ImportError::input(
                Location::default(),
                Problem::new(format!(
                    "no entity is mapped ({} names seen, all ignored): give a mapping",
                    survey.entities.len()
                )),
            ));
        }

        let duration = last_frame - first_frame;
        let rate = if survey.frames > 1 && duration > 0.0 {
            (survey.frames - 1) as f64 / duration
        } else {
            1.0
        };
        let mut meta = source.meta();
        meta.insert(
            "source_format".to_string(),
            source.format().name().to_string(),
        );
        let header = Header {
            id: id.to_string(),
            participant: "unknown".to_string(),
            task: format!("imported from a {} source", source.format()),
            frame_rate: (rate * 100.0).round().max(1.0) / 100.0,
            entities,
            meta,
        };
        recording::check_header(&header).map_err(|p| {
            ImportError::input(
                Location::default(),
                Problem {
                    entity: None,
                    field: Some(p.field),
                    message: p.message,
                },
            )
        })?;
        Ok(Importer {
            mapping: mapping.clone(),
            header,
            targets,
            origin_lift,
            velocity,
            first_frame,
            report: Report {
                format: source.format(),
                frames: survey.frames,
                repeated_ticks: survey.repeated_ticks,
                duration,
                rate,
                mapped,
                ignored,
                table: table_note,
                grasps: 0,
                gap_count: 0,
                gaps: Vec::new(),
            },
        })
    }

    /// The native header the frames will have.
    pub fn header(&self) -> &Header {
        &self.header
    }

    /// The second pass: reads `source` again and hands each native frame, in time order,
    /// to `on_frame`. Returns the report.
    pub fn assemble(
        &self,
        source: &mut dyn Source,
        on_frame: &mut dyn FnMut(&Frame) -> Result<(), ImportError>,
    ) -> Result<Report, ImportError> {
        let n = self.header.entities.len();
        let mut sink = AssemblySink {
            importer: self,
            on_frame,
            latest: vec![None; n],
            frame: Frame::empty(0.0, n),
            previous_positions: vec![None; n],
            geometry_holds: vec![None; n],
            last_present: vec![None; n],
            missing: vec![false; n],
            last_time: None,
            held_before: vec![None; n],
            report: self.report.clone(),
            failure: None,
        };
        let result = source.pass(&mut sink);
        if let Some(e) = sink.failure.take() {
            return Err(e);
        }
        result?;
        Ok(sink.report)
    }
}

fn duplicate(name: &str, other: &str, native: &str) -> ImportError {
    ImportError::input(
        Location::default(),
        Problem::at(
            name,
            "name",
            format!(
                "`{name}` and `{other}` both map to the native name `{native}` (names are \
                 compared ignoring case): give one of them another name (`as`) or ignore it \
                 in the mapping"
            ),
        ),
    )
}

fn vec3(a: [f64; 3]) -> Vec3 {
    Vec3::new(a[0] as f32, a[1] as f32, a[2] as f32)
}

fn quaternion((w, v): (f64, [f64; 3])) -> Quaternion {
    Quaternion::new(v[0] as f32, v[1] as f32, v[2] as f32, w as f32)
}

/// The box centre of a pose whose position sits `lift` below the centre along the box's
/// own z axis.
fn lifted(c: Converted, lift: f64) -> [f64; 3] {
    if lift == 0.0 {
        return c.position;
    }
    let q = quaternion(c.rotation);
    let up = q.rotate(Vec3::new(0.0, 0.0, lift as f32));
    [
        c.position[0] + f64::from(up.x),
        c.position[1] + f64::from(up.y),
        c.position[2] + f64::from(up.z),
    ]
}

/// Chooses the table (see [`Importer::survey`]).
fn plan_table(
    tables: &[(&Surveyed, crate::mapping::Resolved)],
    cubes: &[([f64; 3], [f64; 3])],
    ignored: &mut Vec<IgnoredEntity>,
) -> Option<(Entity, String)> {
    // A table with known geometry that a cube rests on.
    let rests_on = |centre: [f64; 3], size: [f64; 3]| {
        cubes.iter().any(|(c, s)| {
            let bottom = c[2] - s[2] / 2.0;
            let top = centre[2] + size[2] / 2.0;
            (bottom - top).abs() < 0.02
                && (c[0] - centre[0]).abs() <= size[0] / 2.0
                && (c[1] - centre[1]).abs() <= size[1] / 2.0
        })
    };
    let known: Vec<(usize, [f64; 3], [f64; 3])> = tables
        .iter()
        .enumerate()
        .filter_map(|(i, (s, r))| {
            let size = r.size?;
            let lift = match r.origin {
                Origin::Center => 0.0,
                Origin::Bottom => size[2] / 2.0,
            };
            let centre = lifted(s.first, lift);
            rests_on(centre, size).then_some((i, centre, size))
        })
        .collect();
    let chosen = if let [(i, centre, size)] = known[..] {
        let (s, r) = &tables[i];
        Some((
            i,
            Entity {
                name: r.native.clone(),
                kind: EntityKind::Table,
                size: vec3(size),
                fixed: Some(Pose {
                    position: vec3(centre),
                    orientation: quaternion(s.first.rotation),
                }),
            },
            format!("{} at its first pose ({})", s.name, r.rule),
        ))
    } else if cubes.is_empty() {
        None
    } else {
        // The plane under the lowest cube, a slab reaching well past the cubes.
        const MARGIN: f64 = 0.4;
        const THICKNESS: f64 = 0.04;
        let surface = cubes
            .iter()
            .map(|(c, s)| c[2] - s[2] / 2.0)
            .fold(f64::INFINITY, f64::min);
        let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
        for (c, _) in cubes {
            for k in 0..2 {
                lo[k] = lo[k].min(c[k]);
                hi[k] = hi[k].max(c[k]);
            }
        }
        let mid = [(lo[0] + hi[0]) / 2.0, (lo[1] + hi[1]) / 2.0];
        let nearest = tables
            .iter()
            .enumerate()
            .min_by(|(_, a), (_, b)| {
                let d = |s: &Surveyed| {
                    (s.first.position[0] - mid[0]).powi(2) + (s.first.position[1] - mid[1]).powi(2)
                };
                d(a.0).total_cmp(&d(b.0))
            })
            .map(|(i, _)| i);
        let name = nearest.map_or_else(|| "table".to_string(), |i| tables[i].1.native.clone());
        let note = format!(
            "support surface at z = {surface:.3} m under the cubes' start{}",
            nearest.map_or_else(String::new, |i| format!(
                " (named after {})",
                tables[i].0.name
            ))
        );
        Some((
            nearest.unwrap_or(usize::MAX),
            Entity {
                name,
                kind: EntityKind::Table,
                size: vec3([
                    hi[0] - lo[0] + 2.0 * MARGIN,
                    hi[1] - lo[1] + 2.0 * MARGIN,
                    THICKNESS,
                ]),
                fixed: Some(Pose {
                    position: vec3([mid[0], mid[1], surface - THICKNESS / 2.0]),
                    orientation: Quaternion::IDENTITY,
                }),
            },
            note,
        ))
    };
    for (i, (s, _)) in tables.iter().enumerate() {
        if chosen.as_ref().is_some_and(|(c, _, _)| *c == i) {
            continue;
        }
        ignored.push(IgnoredEntity {
            source: s.name.clone(),
            reason: "a table no cube rests on".to_string(),
        });
    }
    chosen.map(|(_, e, note)| (e, note))
}

/// The latest observation of a native entity, converted.
#[derive(Debug, Clone)]
struct Latest {
    time: f64,
    pose: Pose,
    velocity: Option<Vec3>,
    grip: Option<f32>,
    /// `Some(None)`: reported holding nothing.
    held: Option<Option<EntityId>>,
    /// For an object: the hand a "grabbed by" relation names (`Some(None)`: none).
    grabbed_by: Option<Option<EntityId>>,
    contacts: Vec<EntityId>,
}

struct AssemblySink<'a> {
    importer: &'a Importer,
    on_frame: &'a mut dyn FnMut(&Frame) -> Result<(), ImportError>,
    latest: Vec<Option<Latest>>,
    frame: Frame,
    previous_positions: Vec<Option<Vec3>>,
    /// Grasps from geometry: per hand, the cube and its offset from the hand at the grasp.
    geometry_holds: Vec<Option<(EntityId, Vec3)>>,
    last_present: Vec<Option<f64>>,
    missing: Vec<bool>,
    last_time: Option<f64>,
    /// Per hand: what it held in the previous frame (for counting grasps).
    held_before: Vec<Option<EntityId>>,
    report: Report,
    failure: Option<ImportError>,
}

impl AssemblySink<'_> {
    fn resolve_object(&self, observer: &str, field: &str, name: &str) -> Result<EntityId, Problem> {
        let role = |what: &str| Problem::at(observer, field, what.to_string());
        match self.importer.targets.get(name) {
            Some(Target::Tracked(id)) => {
                let kind = self.importer.header.entity(*id).kind;
                if kind == EntityKind::Hand && field != "grabbed_by" {
                    return Err(role(&format!(
                        "names `{name}`, which is a hand, not an object"
                    )));
                }
                Ok(*id)
            }
            Some(Target::Skipped) => Err(role(&format!(
                "names `{name}`, which the mapping leaves out (a table or an ignored entity)"
            ))),
            None => Err(role(&format!(
                "names `{name}`, which is not an entity of the source"
            ))),
        }
    }

    fn observe(&mut self, o: &Observation) -> Result<(), Problem> {
        let Some(Target::Tracked(id)) = self.importer.targets.get(&o.name).copied() else {
            return Ok(());
        };
        let imp = self.importer;
        let (c, velocity) = convert(&imp.mapping, o)?;
        let lift = imp.origin_lift[id.index()];
        let pose = Pose {
            position: vec3(lifted(c, lift)),
            orientation: quaternion(c.rotation),
        };
        let is_hand = imp.header.entity(id).kind == EntityKind::Hand;
        let held = match &o.held {
            Some(Held::Object(name)) if is_hand => {
                Some(Some(self.resolve_object(&o.name, "held", name)?))
            }
            Some(Held::Nothing) if is_hand => Some(None),
            _ => None,
        };
        let grabbed_by = match o.grabbed_by.as_deref() {
            Some("") => Some(None),
            Some(hand) => {
                let h = self.resolve_object(&o.name, "grabbed_by", hand)?;
                if imp.header.entity(h).kind != EntityKind::Hand {
                    return Err(Problem::at(
                        &o.name,
                        "grabbed_by",
                        format!("names `{hand}`, which is not a hand"),
                    ));
                }
                Some(Some(h))
            }
            None => None,
        };
        let mut contacts = Vec::new();
        if imp.mapping.contacts == ContactSource::Reported {
            for other in &o.contacts {
                match imp.targets.get(other) {
                    Some(Target::Tracked(b)) if *b != id => contacts.push(*b),
                    Some(Target::Tracked(_)) => {}
                    Some(Target::Skipped) => {
                        // Contacts with the fixed table matter (onTop); others left out do not.
                        if let Some(t) = imp.header.ids_of(EntityKind::Table).next() {
                            if matches!(imp.mapping.resolve(other).role, Role::Table) {
                                contacts.push(t);
                            }
                        }
                    }
                    None => {
                        return Err(Problem::at(
                            &o.name,
                            "contacts",
                            format!("names `{other}`, which is not an entity of the source"),
                        ))
                    }
                }
            }
        }
        if let Some(prev) = &self.latest[id.index()] {
            if o.time < prev.time {
                return Err(Problem::at(
                    &o.name,
                    "time",
                    format!(
                        "time goes backwards: observed at {} s after {} s",
                        o.time, prev.time
                    ),
                ));
            }
        }
        self.latest[id.index()] = Some(Latest {
            time: o.time,
            pose,
            velocity: velocity.filter(|_| imp.velocity[id.index()]).map(vec3),
            grip: o.grip.map(|g| g as f32),
            held,
            grabbed_by,
            contacts,
        });
        Ok(())
    }

    fn tick(&mut self, t: f64) -> Result<(), Problem> {
        if let Some(last) = self.last_time {
            if t <= last {
                // Repeated ticks were counted by the survey; backwards time refused there.
                return Ok(());
            }
        }
        self.last_time = Some(t);
        let imp = self.importer;
        let n = imp.header.entities.len();
        let time = t - imp.first_frame;
        self.frame.clear(n);
        self.frame.time = time;
        for i in 0..n {
            let Some(l) = &self.latest[i] else { continue };
            if imp.header.entities[i].fixed.is_some() || t - l.time > imp.mapping.max_age + 1e-9 {
                continue;
            }
            self.frame.states[i] = Some(EntityState {
                pose: l.pose,
                velocity: l.velocity,
                grip: None,
                holding: None,
            });
        }
        self.grasps(n);
        // Contacts, each unordered pair once.
        if imp.mapping.contacts == ContactSource::Reported {
            for (i, l) in self.latest.iter().enumerate() {
                let Some(l) = l else { continue };
                if self.frame.states[i].is_none() {
                    continue;
                }
                for &b in &l.contacts {
                    let (a, b) = (EntityId(i as u32).min(b), EntityId(i as u32).max(b));
                    let c = Contact { a, b };
                    if !self.frame.contacts.contains(&c) {
                        self.frame.contacts.push(c);
                    }
                }
            }
            self.frame.contacts.sort();
        }
        // Gaps.
        for i in 0..n {
            if imp.header.entities[i].fixed.is_some() {
                continue;
            }
            if self.frame.states[i].is_some() {
                if self.missing[i] {
                    if let Some(from) = self.last_present[i] {
                        self.report.add_gap(Gap {
                            entity: EntityId(i as u32),
                            from,
                            to: time,
                        });
                    }
                    self.missing[i] = false;
                }
                self.last_present[i] = Some(time);
            } else if self.last_present[i].is_some() {
                self.missing[i] = true;
            }
        }
        if let Err(e) = (self.on_frame)(&self.frame) {
            self.failure = Some(e);
            return Err(Problem::new("the output failed"));
        }
        Ok(())
    }

    /// Grips and held objects of the hands in `self.frame`.
    fn grasps(&mut self, n: usize) {
        let imp = self.importer;
        let hands: Vec<usize> = (0..n)
            .filter(|&i| imp.header.entities[i].kind == EntityKind::Hand)
            .collect();
        for &h in &hands {
            let Some(hand) = self.frame.states[h] else {
                continue;
            };
            let l = self.latest[h].as_ref();
            let reported_grip = l.and_then(|l| l.grip);
            let reported_held = l.and_then(|l| l.held);
            // "Grabbed by" relations on the objects' side.
            let grabbed = (0..n).find(|&o| {
                self.latest[o]
                    .as_ref()
                    .and_then(|l| l.grabbed_by)
                    .is_some_and(|g| g == Some(EntityId(h as u32)))
            });
            let holding = match imp.mapping.grasps {
                GraspSource::Events | GraspSource::Field => match (reported_held, grabbed) {
                    (Some(held), _) => held,
                    (None, Some(o)) => Some(EntityId(o as u32)),
                    (None, None) => None,
                },
                GraspSource::Grip | GraspSource::Geometry => {
                    let closed = match imp.mapping.grasps {
                        GraspSource::Grip => reported_grip.map(|g| g >= 0.5),
                        _ => None,
                    };
                    self.geometry_grasp(h, hand.pose.position, closed, n)
                }
            };
            let was = self.held_before[h];
            if holding.is_some() && holding != was {
                self.report.grasps += 1;
            }
            let grip = reported_grip.unwrap_or(if holding.is_some() { 1.0 } else { 0.0 });
            if let Some(s) = &mut self.frame.states[h] {
                s.grip = Some(grip.clamp(0.0, 1.0));
                s.holding = holding;
            }
            self.held_before[h] = holding;
        }
        for i in 0..n {
            if let Some(s) = &self.frame.states[i] {
                self.previous_positions[i] = Some(s.pose.position);
            }
        }
    }

    /// A grasp from geometry: a cube near the hand that moves with it (or, with a grip
    /// signal, the nearest cube while the grip is closed) is held until it slips more than
    /// [`GRASP_SLIP`] from where it sat in the hand (or the grip opens).
    fn geometry_grasp(
        &mut self,
        h: usize,
        hand: Vec3,
        closed: Option<bool>,
        n: usize,
    ) -> Option<EntityId> {
        if let Some((c, offset)) = self.geometry_holds[h] {
            let slipped = self.frame.states[c.index()]
                .is_some_and(|s| (s.pose.position - hand - offset).norm() > GRASP_SLIP as f32);
            if !slipped && closed != Some(false) {
                return Some(c);
            }
            self.geometry_holds[h] = None;
        }
        if closed == Some(false) {
            return None;
        }
        let hand_step = hand - self.previous_positions[h]?;
        let taken: Vec<EntityId> = self
            .geometry_holds
            .iter()
            .flatten()
            .map(|(c, _)| *c)
            .collect();
        let mut best: Option<(f32, EntityId, Vec3)> = None;
        for c in 0..n {
            let id = EntityId(c as u32);
            if self.importer.header.entities[c].kind != EntityKind::Cube || taken.contains(&id) {
                continue;
            }
            let Some(s) = self.frame.states[c] else {
                continue;
            };
            let distance = s.pose.position.distance(hand);
            if distance > GRASP_REACH as f32 {
                continue;
            }
            if closed.is_none() {
                let Some(prev) = self.previous_positions[c] else {
                    continue;
                };
                let step = s.pose.position - prev;
                let moving = step.norm() >= GRASP_MIN_STEP as f32;
                let together = (step - hand_step).norm() <= 0.3 * step.norm().max(hand_step.norm());
                if !(moving && together) {
                    continue;
                }
            }
            if best.is_none_or(|(d, _, _)| distance < d) {
                best = Some((distance, id, s.pose.position - hand));
            }
        }
        let (_, c, offset) = best?;
        self.geometry_holds[h] = Some((c, offset));
        Some(c)
    }
}

impl Sink for AssemblySink<'_> {
    fn event(&mut self, event: Event<'_>) -> Result<(), Problem> {
        match event {
            Event::Observe(o) => self.observe(o),
            Event::Frame(t) => self.tick(t),
        }
    }
}

/// How many times [`import`] reads its source through ([`Importer::survey`], then
/// [`Importer::assemble`]): a caller showing progress expects this many full reads.
pub const SOURCE_PASSES: u64 = 2;

/// Imports `source` into a native recording written to `out`: both passes, with
/// recording id `id`. Returns the output, the header and the report.
pub fn import<W: std::io::Write>(
    source: &mut dyn Source,
    mapping: &Mapping,
    id: &str,
    out: W,
) -> Result<(W, Header, Report), ImportError> {
    let importer = Importer::survey(source, mapping, id)?;
    let mut writer = recording::Writer::new(out, importer.header())?;
    let report = importer.assemble(source, &mut |frame| {
        writer.write_frame(frame).map_err(ImportError::from)
    })?;
    Ok((writer.finish()?, importer.header, report))
}
