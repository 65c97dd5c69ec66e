//! The Python extension module `demoplan._demoplan`: the binding only. Each function
//! converts Python arguments, releases the GIL, calls a library crate (or the command
//! line, [`demoplan_cli::run`]) and converts the result back; failures become the
//! exception classes of `demoplan.errors`. The Python package in `python/demoplan`
//! wraps these functions in its public API.

use std::ffi::OsString;
use std::path::Path;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{mpsc, Mutex};
use std::time::{Duration, Instant};

use demoplan_cli::{ExitCode, Failure};
use pyo3::prelude::*;

mod learning;

/// Runs the `demoplan` command line on `argv` (its first item is the program's name) in
/// this process, printing what the binary prints, and returns its exit code. The GIL is
/// released for the whole run. `program` is the command that runs demoplan again (a
/// grid's cells; this process's executable is Python, not demoplan).
#[pyfunction]
#[pyo3(signature = (argv, program=None))]
fn run(py: Python<'_>, argv: Vec<OsString>, program: Option<Vec<OsString>>) -> i32 {
    py.detach(|| match program {
        Some(program) if !program.is_empty() => demoplan_cli::run_as(program, argv).0,
        _ => demoplan_cli::run(argv).0,
    })
}

/// What [`plan`] hands back to Python: the outcome word, the plan file's text (when
/// solved), the cost, and the statistics record (`--stats-json`'s) as JSON.
type PlanAnswer = (String, Option<String>, Option<u64>, String);

/// Plans `problem` in `domain` (PDDL texts; the names are where they came from, for
/// diagnostics) with `search` or the configuration `alias` names
/// ([`slim::PlannerConfig::resolve`]; neither: `astar(lmcut())`), translated with the
/// translator options `demoplan plan` takes (`--h2-mutexes`,
/// `--remove-dominated-operators`; switched on beside an alias's own), under `time_limit`
/// seconds and `memory_limit` bytes of Rust heap on top of what the process holds at the
/// start. The GIL is released; the calling thread wakes every 50 ms to let Python handle
/// signals, and a Ctrl-C sets the run's cancel flag, which every phase checks with its
/// limits.
#[pyfunction]
#[pyo3(signature = (domain, domain_name, problem, problem_name, search, alias=None, time_limit=None, memory_limit=None, h2_mutexes=false, remove_dominated_operators=false))]
#[allow(clippy::too_many_arguments)]
fn plan(
    py: Python<'_>,
    domain: String,
    domain_name: String,
    problem: String,
    problem_name: String,
    search: Option<String>,
    alias: Option<String>,
    time_limit: Option<f64>,
    memory_limit: Option<u64>,
    h2_mutexes: bool,
    remove_dominated_operators: bool,
) -> PyResult<PlanAnswer> {
    let start = Instant::now();
    let options = translate::TranslateOptions {
        h2_mutexes,
        remove_dominated_operators,
    };
    let time = seconds(py, time_limit)?;
    let flag = CancelFlag::take();
    let limits = slim::RunLimits {
        time,
        memory_bytes: memory_limit,
        memory: Some(slim::MemoryProbe::counting()),
    };
    let mut task_limits = limits.starting_at(start);
    task_limits.cancel = Some(flag.0);
    let answer = run_cancellable(py, flag.0, move || {
        plan_texts(
            (&domain, Path::new(&domain_name)),
            (&problem, Path::new(&problem_name)),
            (search.as_deref(), alias.as_deref()),
            options,
            &task_limits,
            start,
        )
    });
    drop(flag);
    match answer? {
        Ok(answer) => Ok(answer),
        Err(f) => Err(failure_from(py, f)),
    }
}

/// Plans the task of the texts `domain` and `problem`, each with the name diagnostics
/// give it.
fn plan_texts(
    (domain_text, domain_path): (&str, &Path),
    (problem_text, problem_path): (&str, &Path),
    (search, alias): (Option<&str>, Option<&str>),
    options: translate::TranslateOptions,
    limits: &task::Limits,
    start: Instant,
) -> Result<PlanAnswer, Failure> {
    let search = search.or(Some("astar(lmcut())").filter(|_| alias.is_none()));
    let config = slim::PlannerConfig::resolve(search, alias, options)
        .map_err(|e| Failure::plain(e.exit_code(), e.to_string()))?;
    let (domain, problem) = parse_pddl(domain_text, domain_path, problem_text, problem_path)?;
    let input = slim::PlanInput::Pddl {
        domain: &domain,
        problem: &problem,
        options: config.translator,
    };
    let logged = slim::plan_logged(input, &config.search, limits, start, &mut |_| {})
        .map_err(|e| Failure::plain(e.exit_code(), e.message(problem_path)))?;
    let record = logged.statistics_record(None);
    let statistics = serde_json::to_string(&record)
        .map_err(|e| Failure::plain(ExitCode::CRITICAL_ERROR, e.to_string()))?;
    let outcome = match &logged.run.outcome {
        slim::Outcome::Error => {
            let reason = logged.run.error.clone().unwrap_or_default();
            return Err(Failure::plain(ExitCode::CRITICAL_SEARCH_ERROR, reason));
        }
        other => other.word().to_string(),
    };
    Ok((outcome, logged.run.plan_text(), logged.run.cost, statistics))
}

/// Parses and checks a domain and problem, failing as the command line does (the
/// diagnostic names the file, line and column).
fn parse_pddl(
    domain_text: &str,
    domain_path: &Path,
    problem_text: &str,
    problem_path: &Path,
) -> Result<(pddl::Domain, pddl::Problem), Failure> {
    let domain =
        pddl::parse_domain(domain_text).map_err(|e| Failure::pddl(domain_path, domain_text, &e))?;
    let problem = pddl::parse_problem(problem_text)
        .and_then(|p| pddl::check_problem(&domain, &p).map(|()| p))
        .map_err(|e| Failure::pddl(problem_path, problem_text, &e))?;
    Ok((domain, problem))
}

/// Validates the plan text `plan` (named `plan_name`) for the task; returns whether it
/// is valid, VAL's report, and the plan's value (its cost) when valid.
#[pyfunction]
#[pyo3(name = "validate")]
fn validate_plan(
    py: Python<'_>,
    domain: String,
    domain_name: String,
    problem: String,
    problem_name: String,
    plan: String,
    plan_name: String,
) -> PyResult<(bool, String, Option<i64>)> {
    let result = py.detach(|| -> Result<(bool, String, Option<i64>), Failure> {
        let (d, p) = parse_pddl(
            &domain,
            Path::new(&domain_name),
            &problem,
            Path::new(&problem_name),
        )?;
        let steps = pddl::parse_plan(&plan).map_err(|e| {
            Failure::plain(
                ExitCode::INPUT_ERROR,
                format!("{plan_name}:{}: {}", e.line, e.kind),
            )
        })?;
        let report = ::validate::validate(&d, &p, &steps)
            .map_err(|e| Failure::plain(ExitCode::INPUT_ERROR, format!("{problem_name}: {e}")))?;
        let valid = report.is_valid();
        Ok((valid, report.val_text(), valid.then_some(report.value)))
    });
    result.map_err(|f| failure_from(py, f))
}

/// Runs `work` on a worker thread (with the 8 MiB stack the main thread has: the
/// translator recurses) while the calling thread, without the GIL, wakes every 50 ms to
/// let Python run its signal handlers. A handler that raises (Ctrl-C's
/// KeyboardInterrupt) sets `cancel`; the work stops at its next limits check and the
/// exception is returned once it has.
fn run_cancellable<T: Send>(
    py: Python<'_>,
    cancel: &'static AtomicBool,
    work: impl FnOnce() -> T + Send,
) -> PyResult<T> {
    py.detach(|| {
        std::thread::scope(|scope| {
            let (done, finished) = mpsc::channel();
            let worker = std::thread::Builder::new()
                .name("demoplan".into())
                .stack_size(8 << 20)
                .spawn_scoped(scope, move || {
                    let _ = done.send(work());
                })
                .map_err(|e| {
                    pyo3::exceptions::PyRuntimeError::new_err(format!(
                        "cannot start the planning thread: {e}"
                    ))
                })?;
            let mut interrupted: Option<PyErr> = None;
            let answer = loop {
                match finished.recv_timeout(Duration::from_millis(50)) {
                    Ok(answer) => break Some(answer),
                    Err(mpsc::RecvTimeoutError::Disconnected) => break None,
                    Err(mpsc::RecvTimeoutError::Timeout) => {
                        if interrupted.is_none() {
                            if let Err(e) = Python::attach(|py| py.check_signals()) {
                                cancel.store(true, Ordering::Relaxed);
                                interrupted = Some(e);
                            }
                        }
                    }
                }
            };
            let joined = worker.join();
            if let Some(e) = interrupted {
                return Err(e);
            }
            match (answer, joined) {
                (Some(answer), Ok(())) => Ok(answer),
                _ => Err(pyo3::exceptions::PyRuntimeError::new_err(
                    "demoplan's planning thread panicked: this is a bug in demoplan, please report it",
                )),
            }
        })
    })
}

/// A time limit in seconds as a `Duration`: `None` is no limit, and so is one too
/// large to represent; a negative or NaN limit is an InputError.
fn seconds(py: Python<'_>, limit: Option<f64>) -> PyResult<Option<Duration>> {
    match limit {
        None => Ok(None),
        Some(t) if t.is_finite() && t >= 0.0 => Ok(Duration::try_from_secs_f64(t).ok()),
        Some(t) if t == f64::INFINITY => Ok(None),
        Some(t) => Err(failure(
            py,
            ExitCode::USAGE,
            &format!("time_limit: {t} is not a number of seconds >= 0"),
        )),
    }
}

/// A cancel flag for one run. `task::Limits` holds a `'static` reference so that it
/// stays `Copy`; flags are leaked once and reused through a free list, so the leak is
/// bounded by the most runs ever at once.
struct CancelFlag(&'static AtomicBool);

static FREE_FLAGS: Mutex<Vec<&'static AtomicBool>> = Mutex::new(Vec::new());

impl CancelFlag {
    fn take() -> CancelFlag {
        let reused = FREE_FLAGS
            .lock()
            .unwrap_or_else(std::sync::PoisonError::into_inner)
            .pop();
        CancelFlag(reused.unwrap_or_else(|| Box::leak(Box::new(AtomicBool::new(false)))))
    }
}

impl Drop for CancelFlag {
    fn drop(&mut self) {
        self.0.store(false, Ordering::Relaxed);
        FREE_FLAGS
            .lock()
            .unwrap_or_else(std::sync::PoisonError::into_inner)
            .push(self.0);
    }
}

/// The exception of `demoplan.errors` for a failure with `code` and `message`.
fn failure(py: Python<'_>, code: ExitCode, message: &str) -> PyErr {
    failure_from(py, Failure::plain(code, message))
}

fn failure_from(py: Python<'_>, failure: Failure) -> PyErr {
    let made = py
        .import("demoplan.errors")
        .and_then(|errors| errors.getattr("error_for_exit_code"))
        .and_then(|make| make.call1((failure.code.0, failure.text.trim_end())));
    match made {
        Ok(exception) => PyErr::from_value(exception),
        Err(e) => e,
    }
}

#[pymodule]
fn _demoplan(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    m.add_function(wrap_pyfunction!(run, m)?)?;
    m.add_function(wrap_pyfunction!(plan, m)?)?;
    m.add_function(wrap_pyfunction!(validate_plan, m)?)?;
    m.add_class::<learning::PyLibrary>()?;
    m.add_function(wrap_pyfunction!(learning::solve, m)?)?;
    m.add_function(wrap_pyfunction!(learning::read_poses, m)?)?;
    m.add_function(wrap_pyfunction!(learning::learn_recordings, m)?)?;
    m.add_function(wrap_pyfunction!(learning::simulate_study, m)?)?;
    m.add_function(wrap_pyfunction!(learning::tower_problem, m)?)?;
    Ok(())
}
