//! The operator library on the command line: `learn`, `operators`, `domain`, `problem`.

use std::path::Path;

use learn::{
    cards_markdown, cards_text, chosen_domain, domain_text, levels, levels_table, summary_table,
    DomainChoice, DomainOptions, Library, LibraryFileError, LockError, Scene, Tower, TowerError,
    Update, UpdateError,
};

use crate::cli::{DomainArgs, LearnArgs, OperatorsArgs, ProblemArgs};
use crate::commands::demo_input;
use crate::diagnostic::Failure;
use crate::output::write_atomically;
use slim::ExitCode;

/// Reads a library file: a missing file is a command line error (36), a damaged or newer
/// one an input error (31) that names the line.
pub fn read_library(path: &Path) -> Result<Library, Failure> {
    Library::read_file(path).map_err(read_failure)
}

fn read_failure(e: LibraryFileError) -> Failure {
    match e {
        LibraryFileError::Io { .. } => Failure::plain(ExitCode::USAGE, e),
        LibraryFileError::NotText { .. } => Failure::plain(ExitCode::INPUT_ERROR, e),
        LibraryFileError::Library { path, text, error } => {
            demo_input::text_failure(&path, &text, "learn::library", &error)
        }
    }
}

/// A library whose update wrote nothing: settings other than the library's are a
/// command line error (36), a lock still held after `--lock-timeout`
/// [`ExitCode::LOCKED`], a lock or library that cannot be written an I/O error (35).
impl From<UpdateError> for Failure {
    fn from(e: UpdateError) -> Failure {
        match e {
            UpdateError::Read(e) => read_failure(e),
            UpdateError::Lock(e @ LockError::Held { .. }) => Failure::plain(
                ExitCode::LOCKED,
                format!(
                    "{e}; try again later or with a longer --lock-timeout (a lock is held by \
                     a running process only, and released when it ends)"
                ),
            ),
            e @ (UpdateError::Lock(_) | UpdateError::Write(_)) => {
                Failure::plain(ExitCode::CRITICAL_ERROR, e)
            }
            e => Failure::plain(ExitCode::USAGE, e), // the hash, lambda, grouping or form
        }
    }
}

/// Learning in two phases around the library's lock ([`learn::Update`]), so that
/// concurrent learners of one library lose no counts (`docs/reliability.md`).
pub fn learn(args: LearnArgs) -> Result<ExitCode, Failure> {
    let lock_timeout = task::units::parse_time_limit(&args.lock_timeout)
        .map_err(|e| Failure::plain(ExitCode::USAGE, format!("--lock-timeout: {e}")))?;
    let update = Update {
        library: args.library.as_deref(),
        out: &args.out,
        lambda: args.lambda,
        grouping: args.activities,
        form: args.form.form(),
        lock_timeout,
    };
    let before = update.read()?;
    // ARFF hand-state tables are segmented as they are (no geometry to ground); their
    // states hold the hand's own facts only (docs/operators.md).
    let segmentation = demo_input::segmentation(&args.segmentation)?;
    let segment = |path: &Path| demo_input::segment_file(path, &segmentation);
    let files = demo_input::recordings(&args.files)?;
    let updated = update.run(before, &files, segment, |w| eprintln!("{w}"))?;
    let library = &updated.library;
    print!("{}", updated.log);
    print!("{}", summary_table(library));
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
    let prio = args
        .prio
        .map_or(1, |p| usize::try_from(p).unwrap_or(usize::MAX));
    let choice = match args.full {
        true => DomainChoice::Full,
        false => DomainChoice::Priority(prio),
    };
    let (operators, what) = chosen_domain(&library, choice, options).map_err(|e| {
        Failure::plain(
            ExitCode::INPUT_ERROR,
            format!("{}: {e}", args.library.display()),
        )
    })?;
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
    let wanted = args.frame.unwrap_or(0);
    let mut reader = crate::recording_input::open(path, None)?;
    let (scene, frames) = learn::scene_at_frame(&mut reader, &config, wanted)
        .map_err(|e| crate::recording_input::recording_failure(path, &e))?;
    scene.ok_or_else(|| {
        Failure::plain(
            ExitCode::USAGE,
            format!(
                "{} has {frames} frames; --frame {wanted} is not one of them (frames count from 0)",
                path.display()
            ),
        )
    })
}

pub fn problem(args: ProblemArgs) -> Result<ExitCode, Failure> {
    let scene = scene(&args)?;
    // clap asks for exactly one of --tower and --paper-goal.
    let text = Tower::chosen(args.tower.as_deref(), args.paper_goal)
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
