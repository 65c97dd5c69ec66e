//! The limits test set (issue 23): `demoplan plan` stops by itself at
//! `--overall-time-limit` and `--overall-memory-limit` in every phase, with Fast
//! Downward's exit code (23 out of time, 22 out of memory), never killed or aborted.
//!
//! Each case runs the binary as a child process and reads its wall time and peak
//! resident memory from `wait4(2)`'s rusage. A case passes if the run ends with the
//! expected code, within its time limit plus 1.5 s, and (with a memory limit) with a
//! peak resident set within the memory limit plus 32 MiB (the binary, stack and the
//! allocator's slack are not heap). These check a promise with loose bounds, never a
//! speed (CONVENTIONS, habit 10). The instances are generated here, in a temporary
//! folder, not read from `../shared`.
//!
//! Every case prints one line (`--nocapture` shows them); `.ci/run` runs this test binary
//! on its own and prints its summary.

#![allow(clippy::unwrap_used, clippy::expect_used)] // tests fail loudly by design

use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::sync::{Mutex, OnceLock};
use std::time::{Duration, Instant};

/// The slack allowed past a time limit.
const TIME_MARGIN: Duration = Duration::from_millis(1500);
/// The slack allowed past a memory limit, in bytes of resident memory.
const MEMORY_MARGIN: u64 = 32 << 20;

/// How a child run ended, as `wait4` reports it.
#[derive(Debug)]
struct Measured {
    /// The exit code (`None`: killed by a signal).
    code: Option<i32>,
    /// The signal that killed it, if one did.
    signal: Option<i32>,
    wall: Duration,
    /// Peak resident set size in bytes (`ru_maxrss`).
    peak_rss: u64,
    stdout: String,
    stderr: String,
}

/// Runs `demoplan ARGS` in `dir` and waits for it with `wait4`, which reports the peak
/// resident memory of this one child.
fn measure(dir: &Path, args: &[&str]) -> Measured {
    let out = dir.join(format!("stdout-{}", std::process::id()));
    let err = dir.join(format!("stderr-{}", std::process::id()));
    let start = Instant::now();
    let child = Command::new(env!("CARGO_BIN_EXE_demoplan"))
        .args(args)
        .current_dir(dir)
        .env("NO_COLOR", "1")
        .stdin(Stdio::null())
        .stdout(std::fs::File::create(&out).unwrap())
        .stderr(std::fs::File::create(&err).unwrap())
        .spawn()
        .unwrap();
    let pid = libc::pid_t::try_from(child.id()).unwrap();
    let mut status: libc::c_int = 0;
    // SAFETY: `rusage` is plain data, zeroed as the C API allows.
    #[allow(unsafe_code)]
    let mut usage: libc::rusage = unsafe { std::mem::zeroed() };
    // SAFETY: `pid` is our child, not yet waited for (std never waits on its own); both
    // pointers point to live, writable values of the types wait4 expects.
    #[allow(unsafe_code)]
    let waited = unsafe { libc::wait4(pid, &mut status, 0, &mut usage) };
    let wall = start.elapsed();
    assert_eq!(waited, pid, "wait4: {}", std::io::Error::last_os_error());
    // The child was reaped by wait4: dropping `Child` neither waits nor kills.
    drop(child);
    let exited = libc::WIFEXITED(status);
    let signalled = libc::WIFSIGNALED(status);
    Measured {
        code: exited.then(|| libc::WEXITSTATUS(status)),
        signal: signalled.then(|| libc::WTERMSIG(status)),
        wall,
        // Linux reports kilobytes.
        peak_rss: u64::try_from(usage.ru_maxrss).unwrap_or(0) * 1024,
        stdout: std::fs::read_to_string(&out).unwrap(),
        stderr: std::fs::read_to_string(&err).unwrap(),
    }
}

/// A limits case: the command, its limits as given and as numbers, the expected code.
struct Case<'a> {
    name: &'a str,
    dir: &'a Path,
    args: Vec<&'a str>,
    time_limit: Duration,
    memory_limit: Option<u64>,
    expected_code: i32,
    /// A line the run must print, saying where it stopped.
    expected_line: &'a str,
}

/// How a command takes its limits, and the statistics line it prints at the end.
struct LimitOptions {
    time: &'static str,
    memory: &'static str,
    statistics: &'static str,
}

impl LimitOptions {
    fn of(command: &str) -> LimitOptions {
        match command {
            // Limits per level: a case's limits are then those of each level, and its
            // time limit should leave room for every level it tries.
            "solve" => LimitOptions {
                time: "--time-limit",
                memory: "--memory-limit",
                statistics: "Cumulative time over ",
            },
            _ => LimitOptions {
                time: "--overall-time-limit",
                memory: "--overall-memory-limit",
                statistics: "Peak memory: ",
            },
        }
    }
}

/// Runs a case and checks the promise; prints one line per case.
fn check(case: Case) -> Measured {
    // One case at a time: cases run side by side would take each other's CPU.
    static SERIAL: Mutex<()> = Mutex::new(());
    let _turn = SERIAL
        .lock()
        .unwrap_or_else(|poisoned| poisoned.into_inner());
    let mut args = case.args.clone();
    let options = LimitOptions::of(args[0]);
    let seconds = format!("{:.3}s", case.time_limit.as_secs_f64());
    args.extend([options.time, &seconds]);
    let memory = case.memory_limit.map(|m| m.to_string());
    if let Some(m) = &memory {
        args.extend([options.memory, m]);
    }
    let run = measure(case.dir, &args);
    println!(
        "limits case {}: exit {:?}, {:.2} s wall (limit {:.1} s), peak RSS {:.1} MiB{}",
        case.name,
        run.code,
        run.wall.as_secs_f64(),
        case.time_limit.as_secs_f64(),
        run.peak_rss as f64 / f64::from(1 << 20),
        case.memory_limit.map_or(String::new(), |m| format!(
            " (limit {:.0} MiB)",
            m as f64 / f64::from(1 << 20)
        ))
    );
    let context = || {
        format!(
            "case {}: demoplan {}\n--- stdout (end)\n{}\n--- stderr\n{}",
            case.name,
            args.join(" "),
            tail(&run.stdout, 30),
            run.stderr
        )
    };
    assert_eq!(run.signal, None, "killed by a signal; {}", context());
    assert_eq!(run.code, Some(case.expected_code), "{}", context());
    assert!(
        run.stdout.contains(case.expected_line),
        "no line `{}`; {}",
        case.expected_line,
        context()
    );
    assert!(
        run.stdout.contains(options.statistics),
        "no statistics; {}",
        context()
    );
    assert!(!run.stderr.contains("panicked"), "{}", context());
    assert!(
        run.wall <= case.time_limit + TIME_MARGIN,
        "{:.2} s wall for a {:.1} s limit; {}",
        run.wall.as_secs_f64(),
        case.time_limit.as_secs_f64(),
        context()
    );
    if let Some(limit) = case.memory_limit {
        assert!(
            run.peak_rss <= limit + MEMORY_MARGIN,
            "peak RSS {} bytes for a limit of {limit}; {}",
            run.peak_rss,
            context()
        );
    }
    run
}

fn tail(text: &str, lines: usize) -> String {
    let all: Vec<&str> = text.lines().collect();
    all[all.len().saturating_sub(lines)..].join("\n")
}

/// A temporary folder for this test binary's instances, removed at the end of the
/// process by nobody: each run takes a fresh one under the target folder's tmp.
fn scratch(name: &str) -> PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR"))
        .join(format!("limits-{}", std::process::id()))
        .join(name);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

fn write(dir: &Path, name: &str, text: &str) {
    std::fs::write(dir.join(name), text).unwrap();
}

/// An action schema with five parameters over `objects` objects, every binding
/// reachable: `objects^5` ground actions (60 objects: 777,600,000), far more than fit in
/// the time or memory.
fn grounding_blow_up(objects: usize) -> PathBuf {
    let dir = scratch(&format!("blow-up-{objects}"));
    write(
        &dir,
        "domain.pddl",
        "(define (domain blow-up) (:predicates (p ?x) (q ?a ?b ?c ?d ?e))
           (:action join :parameters (?a ?b ?c ?d ?e)
             :precondition (and (p ?a) (p ?b) (p ?c) (p ?d) (p ?e))
             :effect (q ?a ?b ?c ?d ?e)))",
    );
    let names: Vec<String> = (0..objects).map(|i| format!("o{i}")).collect();
    let init: Vec<String> = names.iter().map(|n| format!("(p {n})")).collect();
    write(
        &dir,
        "problem.pddl",
        &format!(
            "(define (problem p) (:domain blow-up) (:objects {}) (:init {}) (:goal (q o0 o1 o2 o1 o0)))",
            names.join(" "),
            init.join(" ")
        ),
    );
    dir
}

/// `n` independent switches, each turned on once: translated into `n` binary variables
/// (no mutex groups), numbered 0 to n - 1.
fn switches(n: usize) -> PathBuf {
    let dir = scratch(&format!("switches-{n}"));
    write(
        &dir,
        "domain.pddl",
        "(define (domain switches) (:requirements :strips :negative-preconditions)
           (:predicates (on ?s))
           (:action turn-on :parameters (?s) :precondition (not (on ?s)) :effect (on ?s)))",
    );
    let names: Vec<String> = (0..n).map(|i| format!("s{i}")).collect();
    let goal: Vec<String> = names.iter().map(|s| format!("(on {s})")).collect();
    write(
        &dir,
        "problem.pddl",
        &format!(
            "(define (problem p) (:domain switches) (:objects {}) (:init) (:goal (and {})))",
            names.join(" "),
            goal.join(" ")
        ),
    );
    dir
}

/// The pigeonhole problem: `holes + 1` pigeons into `holes` holes. Solvable when deletes
/// are ignored, so translation keeps it and LM-cut sees no dead end at the start, but
/// unsolvable: a search must exhaust the placements of pigeons, far more than fit in
/// the limits (12 holes: over 10^9 states).
fn pigeonhole(holes: usize) -> PathBuf {
    let dir = scratch(&format!("pigeonhole-{holes}"));
    write(
        &dir,
        "domain.pddl",
        "(define (domain pigeonhole) (:requirements :strips :typing)
           (:types pigeon hole)
           (:predicates (free ?h - hole) (waiting ?p - pigeon) (placed ?p - pigeon) (in ?p - pigeon ?h - hole))
           (:action put :parameters (?p - pigeon ?h - hole)
             :precondition (and (waiting ?p) (free ?h))
             :effect (and (in ?p ?h) (placed ?p) (not (waiting ?p)) (not (free ?h)))))",
    );
    let pigeons: Vec<String> = (0..=holes).map(|i| format!("p{i}")).collect();
    let hole_names: Vec<String> = (0..holes).map(|i| format!("h{i}")).collect();
    let init: Vec<String> = pigeons
        .iter()
        .map(|p| format!("(waiting {p})"))
        .chain(hole_names.iter().map(|h| format!("(free {h})")))
        .collect();
    let goal: Vec<String> = pigeons.iter().map(|p| format!("(placed {p})")).collect();
    write(
        &dir,
        "problem.pddl",
        &format!(
            "(define (problem p) (:domain pigeonhole) (:objects {} - pigeon {} - hole) (:init {}) (:goal (and {})))",
            pigeons.join(" "),
            hole_names.join(" "),
            init.join(" "),
            goal.join(" ")
        ),
    );
    dir
}

/// The full domain learned from the default simulated study (`simulate`, `learn`,
/// `domain --full`), the paper's goal 5 (a tower of six cubes, `problem.pddl`) and a
/// tower of twelve (`tower-12.pddl`), made once per test binary with the binary itself.
fn learned_full_domain() -> &'static Path {
    static DIR: OnceLock<PathBuf> = OnceLock::new();
    DIR.get_or_init(|| {
        let dir = scratch("learned");
        let demoplan = |args: &[&str]| {
            let out = Command::new(env!("CARGO_BIN_EXE_demoplan"))
                .args(args)
                .current_dir(&dir)
                .output()
                .unwrap();
            assert!(
                out.status.success(),
                "demoplan {}: {}",
                args.join(" "),
                String::from_utf8_lossy(&out.stderr)
            );
        };
        demoplan(&["simulate", "-o", "study"]);
        demoplan(&["learn", "study", "-o", "library.json"]);
        demoplan(&["domain", "library.json", "--full", "-o", "domain.pddl"]);
        demoplan(&["problem", "--paper-goal", "5", "-o", "problem.pddl"]);
        let tower: Vec<String> = (1..=12).map(|i| format!("cube_{i}")).collect();
        let tower = tower.join(",");
        demoplan(&[
            "problem",
            "--cubes",
            "12",
            "--tower",
            &tower,
            "-o",
            "tower-12.pddl",
        ]);
        dir
    })
}

const PLAN: &str = "plan";
const FILES: [&str; 2] = ["domain.pddl", "problem.pddl"];

fn plan_args(search: &str) -> Vec<&str> {
    let mut args = vec![PLAN];
    args.extend(FILES);
    args.extend(["--search", search]);
    args
}

#[test]
fn a_grounding_blow_up_stops_at_the_time_limit() {
    let dir = grounding_blow_up(60);
    check(Case {
        name: "grounding blow-up, 1 s",
        dir: &dir,
        args: plan_args("astar(blind())"),
        time_limit: Duration::from_secs(1),
        memory_limit: None,
        expected_code: 23,
        expected_line: "Translation stopped: time limit reached",
    });
}

#[test]
fn a_grounding_blow_up_stops_at_the_memory_limit() {
    let dir = grounding_blow_up(60);
    check(Case {
        name: "grounding blow-up, 64 MiB",
        dir: &dir,
        args: plan_args("astar(blind())"),
        time_limit: Duration::from_secs(60),
        memory_limit: Some(64 << 20),
        expected_code: 22,
        expected_line: "Translation stopped: memory limit reached",
    });
}

#[test]
fn an_ipdb_climb_that_outlasts_its_limit_leaves_the_search_its_half() {
    let dir = learned_full_domain();
    let run = check(Case {
        // On goal 5 the climb converges within 0.1 s (debug build); on a tower of twelve
        // it takes about 1.7 s, over three times the half of the limit it may use.
        name: "iPDB on the learned full domain, a tower of 12, 1 s",
        dir,
        args: vec![
            PLAN,
            "domain.pddl",
            "tower-12.pddl",
            "--search",
            "astar(ipdb())",
        ],
        time_limit: Duration::from_secs(1),
        memory_limit: None,
        expected_code: 23,
        expected_line: "Time limit reached. Abort search.",
    });
    // The climb stopped at its half of the limit, and the search began.
    assert!(
        run.stdout.contains("Hill climbing ended: time limit"),
        "{}",
        tail(&run.stdout, 40)
    );
    assert!(run.stdout.contains("Search time: "), "{}", run.stdout);
}

#[test]
fn a_pattern_database_that_does_not_fit_is_never_allocated() {
    let dir = switches(40);
    let pattern: Vec<String> = (0..30).map(|v| v.to_string()).collect();
    let search = format!("astar(pdb([{}]))", pattern.join(", "));
    for (name, search) in [
        ("pdb over 30 binary variables, 200 MB", search.clone()),
        (
            "cpdbs with that pattern, 200 MB",
            format!("astar(cpdbs([[0], [{}]]))", pattern.join(", ")),
        ),
    ] {
        check(Case {
            name,
            dir: &dir,
            args: plan_args(&search),
            time_limit: Duration::from_secs(60),
            memory_limit: Some(200_000_000),
            expected_code: 22,
            expected_line: "Memory limit has been reached.",
        });
    }
}

#[test]
fn lmcut_and_blind_search_stop_at_the_limits_on_a_task_they_cannot_finish() {
    let dir = pigeonhole(12);
    for (name, search) in [
        ("LM-cut on pigeonhole 13/12, 2 s", "astar(lmcut())"),
        ("blind on pigeonhole 13/12, 2 s", "astar(blind())"),
    ] {
        check(Case {
            name,
            dir: &dir,
            args: plan_args(search),
            time_limit: Duration::from_secs(2),
            memory_limit: None,
            expected_code: 23,
            expected_line: "Time limit reached. Abort search.",
        });
    }
    check(Case {
        name: "blind on pigeonhole 13/12, 100 MiB",
        dir: &dir,
        args: plan_args("astar(blind())"),
        time_limit: Duration::from_secs(120),
        memory_limit: Some(100 << 20),
        expected_code: 22,
        expected_line: "Memory limit has been reached.",
    });
}

#[test]
fn solve_stops_every_level_at_its_memory_limit() {
    // Issue 23: `solve` gives each level the memory limit of its own; blind search on a
    // tower of twelve fills it on every level, which then has the outcome `memory`, and
    // the process (the library and the levels' own heap) stays within the limit.
    let dir = learned_full_domain();
    check(Case {
        // Six levels of about 2 s each (debug build) before each fills its 16 MiB.
        name: "solve, blind on a tower of 12, 16 MiB per level",
        dir,
        args: vec![
            "solve",
            "library.json",
            "tower-12.pddl",
            "--search",
            "astar(blind())",
        ],
        time_limit: Duration::from_secs(60),
        memory_limit: Some(16 << 20),
        expected_code: 12,
        expected_line: "No plan: some level reached its memory limit (exit 12).",
    });
}
