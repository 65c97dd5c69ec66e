//! The operator library on the command line: `learn`, `operators`, `domain`, `problem`.

use std::path::Path;

pub use learn::{cards_markdown, cards_text, domain_text, levels_table, summary_table};
use learn::{
    levels, operator_subset, Batch, DomainOptions, Library, LockError, Scene, Tower, TowerError,
    WriteLock,
};

use crate::cli::{ActivitiesArg, DomainArgs, LearnArgs, OperatorsArgs, ProblemArgs};
use crate::commands::demo_input;
use crate::diagnostic::Failure;
use crate::exit::ExitCode;
use crate::input;
use crate::output::{remove_stale_temporaries, write_atomically, write_durably};

/// Reads a library file: a missing file is a command line error (36), a damaged or newer
/// one an input error (31) that names the line.
pub fn read_library(path: &Path) -> Result<Library, Failure> {
    let text = input::read_text(path)?;
    Library::from_json(&text).map_err(|e| {
        demo_input::text_failure(
            path,
            &text,
            "learn::library",
            e.line,
            e.column,
            &e.field,
            &e.message,
        )
    })
}

/// The content hash of a file ([`learn::content_hash`]).
fn file_hash(path: &Path) -> Result<String, Failure> {
    std::fs::File::open(path)
        .and_then(learn::content_hash)
        .map_err(|e| {
            Failure::plain(
                ExitCode::USAGE,
                format!("cannot read {}: {e}", path.display()),
            )
        })
}

/// The lambda of `--lambda` and the grouping of `--activities` must be the library's.
fn check_lambda(args: &LearnArgs, path: &Path, library: &Library) -> Result<(), Failure> {
    let grouping = args.activities.map(ActivitiesArg::grouping);
    if let Some(l) = args.lambda.filter(|&l| l != library.lambda) {
        return Err(Failure::plain(
            ExitCode::USAGE,
            format!(
                "--lambda {l} differs from the library's lambda {} ({}); costs of one \
                 library use one lambda",
                library.lambda,
                path.display()
            ),
        ));
    }
    if let Some(g) = grouping.filter(|&g| g != library.grouping) {
        return Err(Failure::plain(
            ExitCode::USAGE,
            format!(
                "--activities {} differs from the library's `{}` activities ({}); one \
                 library counts activities of one kind",
                g.name(),
                library.grouping.name(),
                path.display()
            ),
        ));
    }
    Ok(())
}

/// A library whose lock was not taken: still held after `--lock-timeout` is
/// [`ExitCode::LOCKED`], a lock file that cannot be opened or locked an I/O error.
fn lock_failure(e: LockError) -> Failure {
    match e {
        LockError::Held { .. } => Failure::plain(
            ExitCode::LOCKED,
            format!(
                "{e}; try again later or with a longer --lock-timeout (a lock is held by a \
                 running process only, and released when it ends)"
            ),
        ),
        e => Failure::plain(ExitCode::CRITICAL_ERROR, e.to_string()),
    }
}

/// Learning in two phases, so that concurrent learners of one library lose no counts and
/// wait for each other only briefly: first the slow part, grounding and segmenting the
/// recordings, without a lock; then, holding the output's [`WriteLock`], reading the
/// library again, adding the recordings and writing it (durably, by a rename), so that
/// the read and the write see no other writer in between (`docs/reliability.md`).
pub fn learn(args: LearnArgs) -> Result<ExitCode, Failure> {
    let lock_timeout = task::units::parse_time_limit(&args.lock_timeout)
        .map_err(|e| Failure::plain(ExitCode::USAGE, format!("--lock-timeout: {e}")))?;
    // A first look at the library: its lambda, and the recordings it already counts
    // (not segmented again). It is read again under the lock.
    let before = match &args.library {
        Some(path) => {
            let library = read_library(path)?;
            check_lambda(&args, path, &library)?;
            Some(library)
        }
        None => None,
    };
    // ARFF hand-state tables are segmented as they are (no geometry to ground); their
    // states hold the hand's own facts only (docs/operators.md).
    let segmentation = demo_input::segmentation(&args.segmentation)?;
    let segment = |path: &Path| demo_input::segment_file(path, &segmentation);
    let files = demo_input::recordings(&args.files)?;
    let batch = Batch::prepare(&files, before.as_ref(), file_hash, segment)?;
    drop(before);

    // The lock and the write go to the library's canonical path: through a symlink or
    // a relative name, one library is one file with one lock.
    let lock =
        WriteLock::acquire(&args.out, lock_timeout, |w| eprintln!("{w}")).map_err(lock_failure)?;
    remove_stale_temporaries(lock.target());
    let mut library = match &args.library {
        Some(path) => {
            let library = read_library(path)?;
            check_lambda(&args, path, &library)?;
            library
        }
        None => Library::with_grouping(
            args.lambda.unwrap_or(learn::DEFAULT_LAMBDA),
            args.activities
                .map(ActivitiesArg::grouping)
                .unwrap_or_default(),
        ),
    };
    let log = batch.add_to(&mut library, segment)?;
    write_durably(lock.target(), &library.to_json())?;
    drop(lock);
    print!("{log}");
    print!("{}", summary_table(&library));
    println!(
        "wrote {} ({} operators from {} activities of {} recordings)",
        args.out.display(),
        library.len(),
        library.segments(),
        library.recordings().count()
    );
    Ok(ExitCode::SUCCESS)
}

pub fn operators(args: OperatorsArgs) -> Result<ExitCode, Failure> {
    let library = read_library(&args.library)?;
    let text = if args.markdown {
        cards_markdown(&library)
    } else {
        cards_text(&library)
    };
    print!("{text}");
    Ok(ExitCode::SUCCESS)
}

pub fn domain(args: DomainArgs) -> Result<ExitCode, Failure> {
    let library = read_library(&args.library)?;
    let options = DomainOptions {
        keep_without_effects: args.keep_without_effects,
    };
    let all = levels(&library, options);
    let Some(out) = args.out else {
        // No output file: list the levels.
        print!("{}", levels_table(&all));
        return Ok(ExitCode::SUCCESS);
    };
    let (operators, what) = if args.full {
        let most = all.last().map_or(0, |l| l.prio);
        (
            operator_subset(&library, most.max(1), options),
            "full domain".to_string(),
        )
    } else {
        let prio = args
            .prio
            .map_or(1, |p| usize::try_from(p).unwrap_or(usize::MAX));
        (
            operator_subset(&library, prio, options),
            format!("priority {prio}"),
        )
    };
    if operators.is_empty() {
        return Err(Failure::plain(
            ExitCode::INPUT_ERROR,
            format!(
                "{}: the library has no operator that changes anything; a domain would be \
                 empty",
                args.library.display()
            ),
        ));
    }
    write_atomically(&out, &domain_text(&library, &operators, &what))?;
    println!(
        "wrote {} ({what}: {} operators)",
        out.display(),
        operators.len()
    );
    Ok(ExitCode::SUCCESS)
}

/// The scene of a problem: grounded from a recording's frame, or the default.
fn scene(args: &ProblemArgs) -> Result<Scene, Failure> {
    let Some(path) = &args.from else {
        // Both are bounded by their value parsers (64 cubes, 2 hands).
        return Ok(Scene::with_hands(
            args.cubes.map_or(learn::DEFAULT_CUBES, |c| c as usize),
            args.hands
                .map_or(learn::DEFAULT_HANDS.len(), |h| h as usize),
        ));
    };
    let config = demo_input::config(args.config.as_deref())?;
    let tree = segment::ActivityTree::table_one();
    let wanted = args.frame.unwrap_or(0);
    let mut at = learn::StateAt {
        wanted,
        state: None,
    };
    let segmented = demo_input::segment_recording(path, None, &config, &tree, &mut at)?;
    let Some(state) = at.state else {
        return Err(Failure::plain(
            ExitCode::USAGE,
            format!(
                "{} has {} frames; --frame {wanted} is not one of them (frames count from 0)",
                path.display(),
                segmented.frames
            ),
        ));
    };
    Ok(Scene::from_state(
        &segmented.header,
        &segmented.space,
        &state,
    ))
}

pub fn problem(args: ProblemArgs) -> Result<ExitCode, Failure> {
    let scene = scene(&args)?;
    let tower = match (&args.tower, args.paper_goal) {
        (Some(list), None) => Ok(Tower::listed(list)),
        (None, Some(n)) => Tower::paper_goal(n),
        _ => {
            return Err(Failure::plain(
                ExitCode::USAGE,
                "give the goal with --tower LIST or --paper-goal N",
            ))
        }
    };
    let text = tower
        .and_then(|t| Ok((t.problem_text(&scene)?, t.name)))
        .map_err(|e| {
            let message = match &e {
                TowerError::NoPaperGoal(n) => format!("--paper-goal {n}: {e}"),
                TowerError::TooShort => format!("{e}: --tower c1,c2"),
                _ => e.to_string(),
            };
            Failure::plain(ExitCode::USAGE, message)
        });
    let (text, name) = text?;
    write_atomically(&args.out, &text)?;
    println!("wrote {} ({name})", args.out.display());
    Ok(ExitCode::SUCCESS)
}
