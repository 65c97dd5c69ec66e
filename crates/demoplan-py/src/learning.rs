//! The learning side for Python: the operator library (`learn::Library`), learning into
//! it (`learn::Update`), its levels and domains, Algorithm 1 with execution in the loop
//! (`closed_loop::solve`), simulated
//! demonstrations (`simulate::study`), tower problems (`learn::Tower`), and recordings
//! read as arrays. Conversions only; the library crates compute everything, and bad
//! input is reported with the command line's renderers, as its commands report it.

use std::path::{Path, PathBuf};
use std::time::Duration;

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
        let choice = learn::DomainChoice::Priority(prio);
        let options = domain_options(keep_without_effects);
        let (operators, what) = learn::chosen_domain(&self.inner, choice, options)
            .map_err(|e| failure_from(py, Failure::plain(ExitCode::INPUT_ERROR, e)))?;
        Ok(learn::domain_text(&self.inner, &operators, &what))
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
    Option<&'static str>,
);

/// An operator the execution loop set aside: name, id, priority, step, action, the
/// facts promised, the facts found, and why.
type SetAsideRow = (
    String,
    String,
    usize,
    usize,
    String,
    Vec<String>,
    Vec<String>,
    String,
);

/// What `solve` returns: every attempt, the cumulative seconds, the operators set aside,
/// the seconds spent executing plans, and the text of "no executable plan" if so.
type SolveAnswer = (Vec<LevelRow>, f64, Vec<SetAsideRow>, f64, Option<String>);

/// Algorithm 1 with execution in the loop (`closed_loop::solve`; `execute=False`:
/// Algorithm 1 alone) on `problem` (PDDL text named `problem_name`) with the library's
/// levels, each run with `search` under the limits. A scene the cube world cannot lay
/// out is an input error (exit 31). The GIL is released.
#[pyfunction]
#[pyo3(signature = (library, problem, problem_name, search, keep_without_effects=false, time_limit=None, memory_limit=None, execute=true))]
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
    execute: bool,
) -> PyResult<SolveAnswer> {
    let time = crate::seconds(py, time_limit)?;
    let answer = py.detach(|| -> Result<SolveAnswer, Failure> {
        let config = search::parse_search(&search)
            .map_err(|e| Failure::plain(ExitCode::SEARCH_INPUT_ERROR, format!("search: {e}")))?;
        let parsed = pddl::parse_problem(&problem)
            .map_err(|e| Failure::pddl(Path::new(&problem_name), &problem, &e))?;
        let limits = slim::RunLimits {
            time,
            memory_bytes: memory_limit,
            memory: Some(slim::MemoryProbe::counting()),
        };
        let execution = if execute {
            closed_loop::Execution::On
        } else {
            closed_loop::Execution::Off
        };
        let solved = closed_loop::solve(
            &library.inner,
            domain_options(keep_without_effects),
            &parsed,
            &slim::Backend::Demoplan(config.into()),
            limits,
            execution,
            |_| {},
        )
        .map_err(|e| Failure::plain(e.exit_code(), format!("{problem_name}: {e}")))?;
        let rows = solved
            .attempts
            .iter()
            .map(|a| {
                let l = &a.level;
                (
                    l.prio,
                    l.operators,
                    l.run.outcome.word().to_string(),
                    l.run.plan_text(),
                    l.run.cost,
                    l.run.expansions,
                    l.run.total_time.as_secs_f64(),
                    match a.check {
                        closed_loop::Check::NotRun => None,
                        closed_loop::Check::Executed => Some("executed"),
                        closed_loop::Check::StepFailed(_) => Some("step-failed"),
                        closed_loop::Check::GoalNotReached { .. } => Some("goal-not-reached"),
                    },
                )
            })
            .collect();
        let set_aside = solved
            .set_aside()
            .into_iter()
            .map(|s| {
                (
                    s.name.clone(),
                    s.id.clone(),
                    s.prio,
                    s.step,
                    s.action.clone(),
                    s.promised.clone(),
                    s.found.clone(),
                    s.why.clone(),
                )
            })
            .collect();
        let none = matches!(solved.verdict(), closed_loop::Verdict::NoExecutablePlan)
            .then(|| solved.no_executable_plan_text());
        Ok((
            rows,
            solved.cumulative.as_secs_f64(),
            set_aside,
            solved.execution_time.as_secs_f64(),
            none,
        ))
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

/// Learns the recordings `files` into `library` as `demoplan learn` does
/// ([`learn::Update`]), segmenting them as it does by default (Unity logs and bags
/// imported with `mapping`, ARFF tables as they are), with its checks and its errors.
/// The update writes `folder`/library.json (a folder of the caller's own): the library to
/// add to is written there first when it holds anything. Returns the library learned and
/// the log `demoplan learn` prints (what was skipped, ARFF warnings, a line per
/// recording, the summary table, what was written). `generalise` is `learn
/// --generalise`: an empty library becomes one of generalised operators, a library of
/// specific operators refuses it (exit 36). The GIL is released.
#[pyfunction]
#[pyo3(name = "learn", signature = (library, files, folder, mapping=None, generalise=false))]
pub fn learn_recordings(
    py: Python<'_>,
    library: &PyLibrary,
    files: Vec<PathBuf>,
    folder: PathBuf,
    mapping: Option<PathBuf>,
    generalise: bool,
) -> PyResult<(PyLibrary, String)> {
    let answer = py.detach(|| {
        learn_into(
            &library.inner,
            &files,
            &folder,
            mapping.as_deref(),
            generalise,
        )
    });
    answer
        .map(|(inner, log)| (PyLibrary { inner }, log))
        .map_err(|f| failure_from(py, f))
}

fn learn_into(
    library: &learn::Library,
    paths: &[PathBuf],
    folder: &Path,
    mapping: Option<&Path>,
    generalise: bool,
) -> Result<(learn::Library, String), Failure> {
    let out = folder.join("library.json");
    let start_from = library.segments() > 0 || library.recordings().next().is_some();
    if start_from {
        demoplan_cli::write_atomically(&out, &library.to_json())?;
    }
    let update = learn::Update {
        library: start_from.then_some(out.as_path()),
        out: &out,
        lambda: Some(library.lambda),
        grouping: None,
        // `--generalise`; without it, an empty library keeps its own form (a library
        // read from a file may be generalised and hold nothing yet).
        form: match (generalise, start_from) {
            (true, _) => Some(learn::OperatorForm::Generalised),
            (false, false) => Some(library.form()),
            (false, true) => None,
        },
        // `demoplan learn`'s default; the folder is the caller's, so no other learner
        // holds its lock.
        lock_timeout: Some(Duration::from_secs(10)),
    };
    let before = update.read()?;
    let inputs = learn::learning_inputs(paths).map_err(|e| match e {
        learn::InputsError::Open(e) => demoplan_cli::file_failure(learn::FileError::Open {
            path: PathBuf::new(),
            error: e,
        }),
        e => Failure::plain(ExitCode::USAGE, e),
    })?;
    let mut log: String = inputs.notes.iter().map(|n| format!("{n}\n")).collect();
    let config = grounding::GroundingConfig::default();
    let tree = segment::ActivityTree::table_one();
    let mut warnings = String::new();
    let segment = |path: &Path| {
        if segment::is_arff_file(path) {
            learn::segment_arff(path, &tree, config.min_duration, &mut |w| {
                warnings.push_str(&format!(
                    "warning: {}:{}: {}\n",
                    path.display(),
                    w.line,
                    w.message
                ));
            })
            .map_err(demoplan_cli::file_failure)
        } else {
            let mut reader = demoplan_cli::open_recording(path, mapping)?;
            learn::segment_reader(&mut reader, &config, &tree, &mut ()).map_err(|error| {
                demoplan_cli::file_failure(learn::FileError::Recording {
                    path: path.to_path_buf(),
                    error,
                })
            })
        }
    };
    let mut waited = String::new();
    let updated = update.run(before, &inputs.files, segment, |w| {
        waited = format!("{w}\n");
    })?;
    let learned = updated.library;
    log.push_str(&warnings);
    log.push_str(&waited);
    log.push_str(&updated.log);
    log.push_str(&learn::summary_table(&learned));
    log.push_str(&format!(
        "wrote {} ({} operators from {} activities of {} recordings)\n",
        out.display(),
        learned.len(),
        learned.segments(),
        learned.recordings().count()
    ));
    Ok((learned, log))
}

/// Simulated demonstrations as `demoplan simulate -o out` writes them (default
/// parameters): each recording with its ground truth beside it, written whole or not
/// at all, and the manifest; returns the recordings' file names. The GIL is released.
#[pyfunction]
#[pyo3(name = "simulate", signature = (out, participants, per_participant, seed, cubes=None))]
pub fn simulate_study(
    py: Python<'_>,
    out: PathBuf,
    participants: u32,
    per_participant: u32,
    seed: u64,
    cubes: Option<u32>,
) -> PyResult<Vec<String>> {
    let answer = py.detach(|| -> Result<Vec<String>, Failure> {
        let mut params = simulate::SimParams::default();
        if let Some(c) = cubes {
            params.cubes = c;
        }
        let study = simulate::study(&params, seed, participants, per_participant)
            // The error names the parameter (`participants`, `per_participant`,
            // `cubes`), which the Python function's are named after.
            .map_err(|e| Failure::plain(ExitCode::USAGE, e))?;
        simulate::write_study(&study, seed, &params, &out)
            .map_err(|e| Failure::plain(ExitCode::CRITICAL_ERROR, e))?;
        Ok(study
            .demonstrations
            .iter()
            .map(|d| d.recording_name())
            .collect())
    });
    answer.map_err(|f| failure_from(py, f))
}

/// A tower problem's PDDL text as `demoplan problem` writes it: the cubes of `tower`
/// (comma-separated, bottom first) or the paper's goal `paper_goal`, on a table of
/// `cubes` cubes (2 to 64) with `hands` hands (1 or 2).
#[pyfunction]
#[pyo3(signature = (tower=None, paper_goal=None, cubes=None, hands=None))]
pub fn tower_problem(
    py: Python<'_>,
    tower: Option<String>,
    paper_goal: Option<usize>,
    cubes: Option<usize>,
    hands: Option<usize>,
) -> PyResult<String> {
    let within =
        |name: &str, value: Option<usize>, low: usize, high: usize, default: usize| match value {
            None => Ok(default),
            Some(v) if (low..=high).contains(&v) => Ok(v),
            Some(v) => Err(Failure::plain(
                ExitCode::USAGE,
                format!("{name}: {v} is not in {low}..={high}"),
            )),
        };
    let text = (|| -> Result<String, Failure> {
        let scene = learn::Scene::with_hands(
            within("cubes", cubes, 2, 64, learn::DEFAULT_CUBES)?,
            within("hands", hands, 1, 2, learn::DEFAULT_HANDS.len())?,
        );
        let tower = learn::Tower::chosen(tower.as_deref(), paper_goal);
        tower.and_then(|t| t.problem_text(&scene)).map_err(|e| {
            let message = match &e {
                learn::TowerError::NoGoal => {
                    "give the goal with tower or paper_goal, one of them".to_string()
                }
                learn::TowerError::NoPaperGoal(n) => format!("paper_goal {n}: {e}"),
                learn::TowerError::TooShort => format!("{e}: tower [\"c1\", \"c2\"]"),
                _ => e.to_string(),
            };
            Failure::plain(ExitCode::USAGE, message)
        })
    })();
    text.map_err(|f| failure_from(py, f))
}
