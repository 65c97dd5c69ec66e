//! The learning side for Python: the operator library (`learn::Library`), its levels
//! and domains, Algorithm 1 (`slim::solve`), and recordings read as arrays. Conversions
//! only; the library crates compute everything.

use std::path::Path;

use demoplan_cli::{ExitCode, Failure};
use pyo3::prelude::*;

use crate::failure_from;

/// One operator as Python sees it: name, activity, count, cost, and its provenance
/// (recording id, recording hash, participant, hand, start, end).
type OperatorRow = (
    String,
    String,
    u64,
    u32,
    Vec<(String, String, String, String, f64, f64)>,
);

/// An operator library (`learn::Library`).
#[derive(Debug)]
#[pyclass(name = "_Library", module = "demoplan._demoplan", frozen)]
pub struct PyLibrary {
    pub(crate) inner: learn::Library,
}

fn domain_options(keep_without_effects: bool) -> learn::DomainOptions {
    learn::DomainOptions {
        keep_without_effects,
    }
}

#[pymethods]
impl PyLibrary {
    /// An empty library with `lambda`, the largest action cost.
    #[new]
    fn new(lambda: u32) -> PyLibrary {
        PyLibrary {
            inner: learn::Library::new(lambda),
        }
    }

    /// The library of the JSON text `text` (read from `name`); a damaged or newer file
    /// is an InputError naming its line and field.
    #[staticmethod]
    fn from_json(py: Python<'_>, text: &str, name: &str) -> PyResult<PyLibrary> {
        learn::Library::from_json(text)
            .map(|inner| PyLibrary { inner })
            .map_err(|e| {
                let at = match (e.line, e.column) {
                    (0, _) => String::new(),
                    (line, 0) => format!(":{line}"),
                    (line, column) => format!(":{line}:{column}"),
                };
                failure_from(
                    py,
                    Failure::plain(
                        ExitCode::INPUT_ERROR,
                        format!("{name}{at}: field `{}`: {}", e.field, e.message),
                    ),
                )
            })
    }

    /// The library file's text.
    fn to_json(&self) -> String {
        self.inner.to_json()
    }

    /// The largest action cost.
    #[getter(lambda_)]
    fn lambda(&self) -> u32 {
        self.inner.lambda
    }

    /// Segments counted.
    #[getter]
    fn segments(&self) -> u64 {
        self.inner.segments()
    }

    /// Ids of the recordings learned from.
    #[getter]
    fn recordings(&self) -> Vec<String> {
        self.inner.recordings().map(|r| r.id.clone()).collect()
    }

    /// Every operator, ranked as `demoplan operators` lists them.
    fn operators(&self) -> Vec<OperatorRow> {
        self.inner
            .ranked()
            .iter()
            .map(|r| {
                let provenance = r
                    .entry
                    .provenance
                    .iter()
                    .map(|p| {
                        (
                            p.recording.clone(),
                            p.hash.clone(),
                            p.participant.clone(),
                            p.hand.clone(),
                            p.start,
                            p.end,
                        )
                    })
                    .collect();
                (
                    r.name(),
                    learn::display_name(r.operator().activity, 1),
                    r.count(),
                    r.cost,
                    provenance,
                )
            })
            .collect()
    }

    /// `demoplan operators`' text: one card per operator.
    fn cards(&self) -> String {
        learn::cards_text(&self.inner)
    }

    /// The levels of Algorithm 1: each distinct priority and its operators' names.
    fn levels(&self, keep_without_effects: bool) -> Vec<(usize, Vec<String>)> {
        learn::levels(&self.inner, domain_options(keep_without_effects))
            .iter()
            .map(|l| (l.prio, l.operators.iter().map(|r| r.name()).collect()))
            .collect()
    }

    /// The PDDL domain of the operators of priority `prio` (`demoplan domain --prio`).
    fn domain(&self, py: Python<'_>, prio: usize, keep_without_effects: bool) -> PyResult<String> {
        let operators =
            learn::operator_subset(&self.inner, prio, domain_options(keep_without_effects));
        if operators.is_empty() {
            return Err(failure_from(
                py,
                Failure::plain(
                    ExitCode::INPUT_ERROR,
                    "the library has no operator that changes anything; a domain would be empty",
                ),
            ));
        }
        Ok(learn::domain_text(
            &self.inner,
            &operators,
            &format!("priority {prio}"),
        ))
    }
}

/// One level's run as Python sees it: prio, operators, outcome word, plan text, cost,
/// expansions, total seconds.
type LevelRow = (
    usize,
    usize,
    String,
    Option<String>,
    Option<u64>,
    Option<u64>,
    f64,
);

/// Algorithm 1 on `problem` (PDDL text named `problem_name`) with the library's levels,
/// each run with `search` under the limits; returns every level tried and the
/// cumulative seconds. The GIL is released.
#[pyfunction]
#[pyo3(signature = (library, problem, problem_name, search, keep_without_effects=false, time_limit=None, memory_limit=None))]
#[allow(clippy::too_many_arguments)]
pub fn solve(
    py: Python<'_>,
    library: &PyLibrary,
    problem: String,
    problem_name: String,
    search: String,
    keep_without_effects: bool,
    time_limit: Option<f64>,
    memory_limit: Option<u64>,
) -> PyResult<(Vec<LevelRow>, f64)> {
    let time = crate::seconds(py, time_limit)?;
    let answer = py.detach(|| -> Result<(Vec<LevelRow>, f64), Failure> {
        let config = search::parse_search(&search)
            .map_err(|e| Failure::plain(ExitCode::SEARCH_INPUT_ERROR, format!("search: {e}")))?;
        let parsed = pddl::parse_problem(&problem)
            .map_err(|e| Failure::pddl(Path::new(&problem_name), &problem, &e))?;
        let limits = slim::RunLimits {
            time,
            memory_bytes: memory_limit,
            memory: Some(demoplan_cli::memory_probe()),
        };
        let solved = slim::solve(
            &library.inner,
            domain_options(keep_without_effects),
            &parsed,
            &slim::Backend::Demoplan(config),
            limits,
            |_| {},
        );
        let rows = solved
            .levels
            .iter()
            .map(|l| {
                (
                    l.prio,
                    l.operators,
                    l.run.outcome.word().to_string(),
                    l.run.plan_text(),
                    l.run.cost,
                    l.run.expansions,
                    l.run.total_time.as_secs_f64(),
                )
            })
            .collect();
        Ok((rows, solved.cumulative.as_secs_f64()))
    });
    answer.map_err(|f| failure_from(py, f))
}

/// Entity names, frame times, and the flat poses of [`read_poses`].
type Poses = (Vec<String>, Vec<f64>, Vec<f32>);

/// A recording's entities' names, its frame times, and every frame's pose per entity as
/// 7 numbers (x, y, z, qx, qy, qz, qw), flat, NaN where the entity was not observed (a
/// fixed entity has its fixed pose in every frame).
#[pyfunction]
pub fn read_poses(py: Python<'_>, path: std::path::PathBuf) -> PyResult<Poses> {
    let answer = py.detach(|| -> Result<Poses, Failure> {
        let name = path.display();
        let file = std::fs::File::open(&path).map_err(|e| {
            Failure::plain(
                ExitCode::USAGE,
                format!("cannot read recording {name}: {e}"),
            )
        })?;
        let fail =
            |e: recording::ReadError| Failure::plain(ExitCode::INPUT_ERROR, format!("{name}: {e}"));
        let mut reader = recording::Reader::new(std::io::BufReader::new(file)).map_err(fail)?;
        let header = reader.header().clone();
        let names = header.entities.iter().map(|e| e.name.clone()).collect();
        let mut times = Vec::new();
        let mut poses = Vec::new();
        let mut frame = recording::Frame::default();
        while reader.read_frame(&mut frame).map_err(fail)? {
            times.push(frame.time);
            for (entity, state) in header.entities.iter().zip(&frame.states) {
                match state.as_ref().map(|s| s.pose).or(entity.fixed) {
                    Some(p) => poses.extend_from_slice(&[
                        p.position.x,
                        p.position.y,
                        p.position.z,
                        p.orientation.x,
                        p.orientation.y,
                        p.orientation.z,
                        p.orientation.w,
                    ]),
                    None => poses.extend_from_slice(&[f32::NAN; 7]),
                }
            }
        }
        Ok((names, times, poses))
    });
    answer.map_err(|f| failure_from(py, f))
}
