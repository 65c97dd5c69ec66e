//! The command line: arguments as parsed, before they are checked against the files.

use std::path::PathBuf;

use clap::{Args, Parser, Subcommand};
use experiment::grid::{FastDownwardArgs, GridArgs, RunLimitArgs, SlurmArgs};

/// demoplan: planning domains from human demonstrations, and a fast optimal planner.
#[derive(Debug, Parser)]
#[command(name = "demoplan", version, about, max_term_width = 100)]
pub struct Cli {
    /// What to do.
    #[command(subcommand)]
    pub command: Command,
}

/// The subcommands.
#[derive(Debug, Subcommand)]
pub enum Command {
    /// Parse a domain and problem, check them against each other, print a summary.
    ///
    /// With one file: a domain is checked alone; a problem's domain is found beside it by
    /// Fast Downward's naming rules (domain.pddl, NAME-domain.pddl, ...).
    Check(CheckArgs),
    /// Rewrite PDDL files in demoplan's canonical form (lowercase, one fact per line).
    ///
    /// The comment block at the top of a file is kept; comments inside the definition are
    /// dropped, and a warning says how many.
    Fmt(FmtArgs),
    /// Find an optimal plan, speaking Fast Downward's protocol.
    ///
    /// Input: `[DOMAIN] PROBLEM` in PDDL, or a Fast Downward `output.sas` file. The plan is
    /// written to the plan file, one `(action args)` per line and a final
    /// `; cost = N (general cost)` or `(unit cost)` line. Exit codes as Fast Downward's: 0
    /// solved, 11 unsolvable, 22 out of memory, 23 out of time, 31/33 input errors, 34
    /// unsupported, 36 bad command line.
    Plan(PlanArgs),
    /// Translate a PDDL task into a finite-domain task, as Fast Downward's translator does.
    ///
    /// Prints the sizes ("Translator variables: N", ...) and writes the task in Fast
    /// Downward's output.sas format. A goal unreachable even in the relaxation is reported
    /// at once as unsolvable (exit 11), with a trivially unsolvable task written.
    Translate(TranslateArgs),
    /// Validate plans against a domain and problem, in the manner of VAL's `validate`.
    ///
    /// For each plan: whether every step is applicable, whether the goal holds at the end,
    /// and the plan's value (total-cost, or the plan length without a metric). The exit
    /// status is the number of invalid plans.
    Validate(ValidateArgs),
    /// Simulate VR demonstrations of people stacking cubes, with ground truth.
    ///
    /// Writes one recording per demonstration in demoplan's JSON Lines format (NAME.jsonl),
    /// its ground truth beside it (NAME.truth.jsonl: phase and the paper's activity per
    /// frame and hand) and a manifest (simulation.json). The defaults are the paper's study:
    /// 3 participants times 4 demonstrations, seed 7. Deterministic per seed.
    Simulate(SimulateArgs),
    /// Read recordings to the end and summarise them: duration, frame rate, gaps,
    /// entities, which fields are present.
    ///
    /// A malformed recording is reported with its file, line, column and field (exit 31).
    Inspect(InspectArgs),
    /// Import real recordings (Unity VR playback logs) as native recordings DIR/STEM.jsonl.
    ///
    /// Each source is read twice, streaming (names and start poses, then frames), and its
    /// recording written atomically. Prints per file the duration and measured rate, the
    /// entities mapped and ignored, the grasps found and the gaps, then the mapping used
    /// as TOML ready to edit. Two sources with one output name: exit 36, nothing written.
    Import(ImportArgs),
    /// Ground recordings, cut each hand's frames into segments and classify them as
    /// Reach, Take, Put, Stack or Idle (the paper's Tables 2 and 1).
    ///
    /// Prints per segment its hand, start, end, activity, the object in hand and the object
    /// acted on; `--json` adds the facts at the last frame before each segment and at its
    /// last frame. ARFF hand-state tables (FILE.arff, or ARFF by content) are segmented too, their states the hand's own facts.
    Segment(SegmentArgs),
    /// Print, learn or check the decision tree that classifies activities.
    ///
    /// With no FILE: print the tree (the paper's Table 1, or `--tree`). With `--learn`:
    /// learn a tree with C4.5 (gain ratio, pessimistic pruning at CF 0.25) from labelled
    /// frames (ARFF hand-state tables, or simulated recordings with NAME.truth.jsonl
    /// beside them; any nominal ARFF data set on its own, with `--class`), print it and
    /// write it with `-o`. Otherwise: classify the labelled frames of each FILE with the
    /// tree and compare with their labels.
    Classify(ClassifyArgs),
    /// Draw one recording over time as SVG: per hand its speed, its distance to each
    /// object and its grip with the thresholds, and its segments as coloured bands (and
    /// the ground truth's, when NAME.truth.jsonl is beside the recording).
    Timeline(TimelineArgs),
    /// Learn planning operators from recordings into a library (JSON).
    ///
    /// Each activity (a run of one hand's segments with one class, and the Idle that
    /// settles it: see `--activities`) becomes a lifted operator; equal operators are merged and counted, and each gets the cost
    /// ceil(lambda * (1 - count / type count)). With `--library`, the recordings are added
    /// to an existing library; a recording already in it (same content) is not counted
    /// again. Prints per type the operators with count and cost. The library is written
    /// atomically and durably; learners writing one library take turns through its lock
    /// file (FILE.lock), so none loses another's counts.
    Learn(LearnArgs),
    /// Print a library's operators as cards (the paper's Figure 2): preconditions and
    /// effects side by side, count, cost and the recordings that show it.
    Operators(OperatorsArgs),
    /// Write the PDDL domain of a priority (the paper's OperatorSubset), or list the
    /// priority levels (without `-o`).
    ///
    /// Priority N keeps, per type, the N most frequent operators and every operator tied
    /// with the N-th. Operators that change nothing are left out unless
    /// `--keep-without-effects`.
    Domain(DomainArgs),
    /// Write a PDDL problem: a scene and a tower to build.
    ///
    /// The scene is cubes cube_1 ... cube_N on the table with both hands open and still
    /// (`--cubes`, default 6), or the facts of one frame of a recording (`--from`). The
    /// tower is listed bottom first; the goal is its onTop facts (the bottom cube on the
    /// table). The paper's goals 1 to 5 are towers of 2 to 6 cubes (`--paper-goal`).
    Problem(ProblemArgs),
    /// Plan with the paper's Algorithm 1: the domain of priority 1, 2, ... of a library
    /// until a plan is found.
    ///
    /// A level whose goal is unreachable even when deletes are ignored is rejected before
    /// search; others are searched until proven unsolvable or their time or memory limit.
    /// Each plan is executed in the cube world: an operator whose step fails is set aside
    /// and the level searched again (not with --no-execute). Prints per level operators,
    /// outcome, time, expansions, cost, failing steps and the cumulative time. Exit 0 with
    /// a plan, 45 when no plan executes, 11 when every level is unsolvable, 12 on a limit.
    Solve(SolveArgs),
    /// Reproduce the paper's experiment: simulate the 12 demonstrations, learn the
    /// library, build every priority domain, plan the five goals on each with
    /// astar(lmcut()) and astar(ipdb()) (and Algorithm 1 beside them), check every plan by
    /// execution, and write tables (search time and total time), CSV and JSON results,
    /// figures and report.html into the output folder.
    ///
    /// A run that hits the time limit is shown as "> limit" and ratios involving it are
    /// bounds. The paper's goals 1 to 5 are reconstructed as towers of 2 to 6 cubes.
    Reproduce(ReproduceArgs),
    /// When does slimming pay off? Plan priority 1, the full domain and Algorithm 1 over
    /// seeds and conditions (hands, tower heights, several towers, distractor cubes,
    /// grouping, operators without effects), execute every plan, and write runs.csv,
    /// ratios.csv, scaling.svg/.png and report.html (docs/study.md). Resumes: runs
    /// already in the folder's results.jsonl are skipped.
    Study(StudyArgs),
    /// Execute a plan in the cube world and check it step by step.
    ///
    /// A table, 5 cm cubes and grippers laid out from the problem's initial state; each
    /// step becomes motion primitives of its action's type (reach, take, put, stack,
    /// idle), its frames are grounded with the paper's Table 2 grounding and its effects
    /// checked; then the goal. Exit 0 when every step and the goal check pass, 1 when
    /// execution fails, 31 for malformed inputs.
    Execute(ExecuteArgs),
}

/// The options of `check`.
#[derive(Debug, Args)]
pub struct CheckArgs {
    /// `[DOMAIN] PROBLEM`, or a lone domain.
    #[arg(value_name = "FILE", num_args = 1..=2, required = true)]
    pub files: Vec<PathBuf>,
}

/// The options of `fmt`.
#[derive(Debug, Args)]
pub struct FmtArgs {
    /// The files to rewrite.
    #[arg(value_name = "FILE", required = true)]
    pub files: Vec<PathBuf>,
    /// Change nothing; exit 1 if a file is not in canonical form.
    #[arg(long, conflicts_with = "stdout")]
    pub check: bool,
    /// Print the canonical form instead of rewriting the file.
    #[arg(long)]
    pub stdout: bool,
}

/// The options of `plan`.
#[derive(Debug, Args)]
pub struct PlanArgs {
    /// `[DOMAIN] PROBLEM`, or `FILE.sas`.
    #[arg(value_name = "FILE", num_args = 1..=2, required = true)]
    pub files: Vec<PathBuf>,
    /// The search, e.g. `astar(blind())`, `astar(lmcut(), pruning=atom_centric_stubborn_sets())`.
    /// Heuristics: blind, hmax, lmcut, pdb, ipdb, cpdbs, and saturated cost partitioning
    /// `scp([projections(sys_scp())], orders=greedy_orders())` or `scp_online([...], interval=N)`.
    #[arg(long, value_name = "SEARCH", required_unless_present = "alias")]
    pub search: Option<String>,
    /// A named configuration: `seq-opt-lmcut` (`astar(lmcut())`), `demoplan-opt` (demoplan's
    /// optimal configuration; it switches both translator options on, and options given
    /// besides are switched on in addition).
    #[arg(long, value_name = "NAME", conflicts_with = "search")]
    pub alias: Option<String>,
    /// Where to write the plan.
    #[arg(long, value_name = "FILE", default_value = "sas_plan")]
    pub plan_file: PathBuf,
    /// Time limit for the whole run, e.g. `30s`, `5m`, `1h` (seconds without a unit).
    #[arg(long, value_name = "TIME")]
    pub overall_time_limit: Option<String>,
    /// Memory limit for the whole run, e.g. `512M`, `3G` (bytes without a unit).
    #[arg(long, value_name = "MEMORY")]
    pub overall_memory_limit: Option<String>,
    /// Also write the run's statistics as JSON.
    #[arg(long, value_name = "FILE")]
    pub stats_json: Option<PathBuf>,
    /// Validate the plan with the independent validator before reporting success
    /// (PDDL input only).
    #[arg(long)]
    pub validate: bool,
    #[command(flatten)]
    pub translator: translate::TranslateOptions,
}

/// The options of `translate`.
#[derive(Debug, Args)]
pub struct TranslateArgs {
    /// `[DOMAIN] PROBLEM`; the domain is found beside the problem when omitted.
    #[arg(value_name = "FILE", num_args = 1..=2, required = true)]
    pub files: Vec<PathBuf>,
    /// Where to write the task.
    #[arg(long, value_name = "FILE", default_value = "output.sas")]
    pub sas_file: PathBuf,
    #[command(flatten)]
    pub translator: translate::TranslateOptions,
}

/// The options of `validate`.
#[derive(Debug, Args)]
pub struct ValidateArgs {
    /// The domain file.
    pub domain: PathBuf,
    /// The problem file.
    pub problem: PathBuf,
    /// Plan files: one action `(name arg1 arg2)` per line; `;` starts a comment.
    #[arg(value_name = "PLAN", required = true)]
    pub plans: Vec<PathBuf>,
}

/// The options of `simulate`.
#[derive(Debug, Args)]
pub struct SimulateArgs {
    /// Where to write (created if missing).
    #[arg(short = 'o', long = "out", value_name = "DIR")]
    pub out: PathBuf,
    /// Number of participants.
    #[arg(long, value_name = "N", default_value_t = 3)]
    pub participants: u32,
    /// Demonstrations per participant.
    #[arg(long, value_name = "N", default_value_t = 4)]
    pub per_participant: u32,
    /// Seed of the random numbers.
    #[arg(long, value_name = "N", default_value_t = 7)]
    pub seed: u64,
    /// Number of cubes on the table (default 6).
    #[arg(long, value_name = "N")]
    pub cubes: Option<u32>,
    /// Simulator parameters as JSON; fields left out keep their defaults
    /// (docs/recording-format.md lists them).
    #[arg(long, value_name = "FILE")]
    pub params: Option<PathBuf>,
    /// `paper` (default: the `--params` file's) or `two-handed` (both hands at once, poses only)
    #[arg(long, value_name = "NAME", value_parser = simulate::Style::parse)]
    pub style: Option<simulate::Style>,
}

/// The options of `inspect`.
#[derive(Debug, Args)]
pub struct InspectArgs {
    /// Recordings in demoplan's JSON Lines format, or Unity playback logs.
    #[arg(value_name = "RECORDING", required = true)]
    pub files: Vec<PathBuf>,
    #[command(flatten)]
    pub import: MappingArgs,
}

/// The options of `import`.
#[derive(Debug, Args)]
pub struct ImportArgs {
    /// Unity playback logs (JSON), told by their content.
    #[arg(value_name = "SOURCE", required = true)]
    pub sources: Vec<PathBuf>,
    /// The mapping file (TOML, docs/import.md); keys left out keep the defaults.
    #[arg(long, value_name = "FILE")]
    pub mapping: Option<PathBuf>,
    /// The folder to write the recordings into.
    #[arg(short = 'o', long = "out", value_name = "DIR")]
    pub out: PathBuf,
    /// Print the peak heap (bytes, counted by the allocator) on standard error.
    #[arg(long, hide = true)]
    pub peak_heap: bool,
}

/// The options of `segment`.
#[derive(Debug, Args)]
pub struct SegmentArgs {
    /// Recordings (JSON Lines) or ARFF hand-state tables.
    #[arg(value_name = "FILE", required = true)]
    pub files: Vec<PathBuf>,
    /// Print JSON instead of a table.
    #[arg(long)]
    pub json: bool,
    #[command(flatten)]
    pub segmentation: SegmentationArgs,
}

/// `--mapping`: how Unity logs and bags among the inputs are imported (`inspect`, and
/// every command that segments recordings).
#[derive(Debug, Args)]
pub struct MappingArgs {
    /// Mapping file (TOML) for Unity logs among the inputs (docs/import.md); default:
    /// the format's defaults.
    #[arg(long, value_name = "FILE")]
    pub mapping: Option<PathBuf>,
}

/// How recordings become segments: the grounding thresholds, the activity tree and the
/// import mapping (`segment`, `timeline`, `learn`).
#[derive(Debug, Args)]
pub struct SegmentationArgs {
    /// Grounding thresholds as TOML (docs/grounding.md; fields left out keep the
    /// paper's values).
    #[arg(long, value_name = "FILE")]
    pub config: Option<PathBuf>,
    /// The activity tree as JSON (`classify --learn ... -o TREE`); default: Table 1.
    #[arg(long, value_name = "FILE")]
    pub tree: Option<PathBuf>,
    #[command(flatten)]
    pub import: MappingArgs,
}

/// The options of `classify`.
#[derive(Debug, Args)]
pub struct ClassifyArgs {
    /// Labelled frames: ARFF tables (by extension or content) or simulated
    /// recordings.
    #[arg(value_name = "FILE", required_if_eq("learn", "true"))]
    pub files: Vec<PathBuf>,
    /// Learn a tree from the files.
    #[arg(long)]
    pub learn: bool,
    /// Where to write the learned tree (JSON).
    #[arg(short = 'o', long = "out", value_name = "TREE")]
    pub out: Option<PathBuf>,
    /// The tree to print or check with (JSON); default: Table 1.
    #[arg(long, value_name = "TREE", conflicts_with = "learn")]
    pub tree: Option<PathBuf>,
    /// The class attribute of a (non hand-state) ARFF data set; default: the last.
    #[arg(long, value_name = "NAME", requires = "learn")]
    pub class: Option<String>,
    /// Grounding thresholds as TOML, for recordings.
    #[arg(long, value_name = "FILE")]
    pub config: Option<PathBuf>,
    /// The mapping file (TOML, docs/import.md) whose `[labels]` table maps ARFF
    /// labels to activities (`PourSomething = "Put"`), over the defaults.
    #[arg(long, value_name = "FILE")]
    pub mapping: Option<PathBuf>,
}

/// The options of `timeline`.
#[derive(Debug, Args)]
pub struct TimelineArgs {
    /// A recording.
    #[arg(value_name = "RECORDING")]
    pub file: PathBuf,
    /// The SVG file to write.
    #[arg(short = 'o', long = "out", value_name = "FILE.svg")]
    pub out: PathBuf,
    #[command(flatten)]
    pub segmentation: SegmentationArgs,
}

/// The options of `learn`.
#[derive(Debug, Args)]
pub struct LearnArgs {
    /// Recordings (JSON Lines), Unity playback logs, ARFF hand-state tables, or
    /// folders: every recording in a folder (native, Unity or ARFF, by content),
    /// sorted by name, without the simulator's `*.truth.jsonl` and `simulation.json`.
    #[arg(value_name = "RECORDING", required = true)]
    pub files: Vec<PathBuf>,
    /// A library to add to (it may also be the output file).
    #[arg(long, value_name = "FILE")]
    pub library: Option<PathBuf>,
    /// Where to write the library.
    #[arg(short = 'o', long = "out", value_name = "FILE")]
    pub out: PathBuf,
    /// The largest cost, for a new library (default 100, the paper's).
    #[arg(long, value_name = "N")]
    pub lambda: Option<u32>,
    /// How a hand's segments become activities, for a new library (default
    /// `settled`): `settled` ends an activity where the Idle right after it ends (the
    /// hand coming to rest at the cube it reached, the stacked cube landing as the
    /// hand opens); `runs` keeps that Idle an activity of its own. See
    /// docs/operators.md.
    #[arg(long, value_name = "KIND", value_enum)]
    pub activities: Option<learn::Grouping>,
    #[command(flatten)]
    pub form: learn::FormArgs,
    #[command(flatten)]
    pub segmentation: SegmentationArgs,
    /// How long to wait while another learner writes the same library (its lock,
    /// FILE.lock, is held), with Fast Downward's units (`10`, `10s`, `2m`,
    /// `infinity`); then exit 75.
    #[arg(long, value_name = "TIME", default_value = "10s")]
    pub lock_timeout: String,
}

/// The options of `operators`.
#[derive(Debug, Args)]
pub struct OperatorsArgs {
    /// The library.
    #[arg(value_name = "LIBRARY")]
    pub library: PathBuf,
    /// Print Markdown.
    #[arg(long)]
    pub markdown: bool,
}

/// The options of `domain`.
#[derive(Debug, Args)]
pub struct DomainArgs {
    /// The library.
    #[arg(value_name = "LIBRARY")]
    pub library: PathBuf,
    /// The priority.
    #[arg(long, value_name = "N", value_parser = clap::value_parser!(u64).range(1..), conflicts_with = "full")]
    pub prio: Option<u64>,
    /// Every operator (the full domain).
    #[arg(long)]
    pub full: bool,
    /// Where to write the domain; without it, the levels are listed.
    #[arg(short = 'o', long = "out", value_name = "FILE")]
    pub out: Option<PathBuf>,
    /// Keep operators that change nothing.
    #[arg(long)]
    pub keep_without_effects: bool,
}

/// The options of `problem`.
#[derive(Debug, Args)]
pub struct ProblemArgs {
    /// The tower, bottom first: `cube_1,cube_2,cube_3`.
    #[arg(
        long,
        value_name = "LIST",
        required_unless_present = "paper_goal",
        conflicts_with = "paper_goal"
    )]
    pub tower: Option<String>,
    /// The paper's goal N (1 to 5): a tower of N + 1 cubes, cube_1 at the bottom.
    #[arg(long, value_name = "N")]
    pub paper_goal: Option<usize>,
    /// Cubes on the table in the default scene.
    #[arg(long, value_name = "N", conflicts_with = "from", value_parser = clap::value_parser!(u64).range(2..=64))]
    pub cubes: Option<u64>,
    /// Hands in the default scene: 2 (left_hand, right_hand) or 1 (left_hand, a
    /// one-armed robot).
    #[arg(long, value_name = "N", conflicts_with = "from", value_parser = clap::value_parser!(u64).range(1..=2))]
    pub hands: Option<u64>,
    /// Ground the scene from a recording's frame.
    #[arg(long, value_name = "RECORDING")]
    pub from: Option<PathBuf>,
    /// The frame of `--from` (counting from 0; default 0).
    #[arg(long, value_name = "K", requires = "from")]
    pub frame: Option<u64>,
    /// Grounding thresholds as TOML, for `--from`.
    #[arg(long, value_name = "FILE", requires = "from")]
    pub config: Option<PathBuf>,
    /// Where to write the problem.
    #[arg(short = 'o', long = "out", value_name = "FILE")]
    pub out: PathBuf,
}

/// The options of `solve`.
#[derive(Debug, Args)]
pub struct SolveArgs {
    /// The library.
    #[arg(value_name = "LIBRARY")]
    pub library: PathBuf,
    /// The problem (e.g. from `demoplan problem`).
    #[arg(value_name = "PROBLEM")]
    pub problem: PathBuf,
    /// The search, in Fast Downward's syntax.
    #[arg(long, value_name = "SEARCH", default_value = "astar(lmcut())")]
    pub search: String,
    /// A named configuration of demoplan's planner instead: seq-opt-lmcut, demoplan-opt.
    #[arg(long, value_name = "NAME", conflicts_with = "search")]
    pub alias: Option<String>,
    #[command(flatten)]
    pub limits: RunLimitArgs,
    /// Who plans: demoplan or fast-downward.
    #[arg(long, value_name = "PLANNER", default_value = "demoplan", value_enum)]
    pub planner: slim::PlannerName,
    /// Fast Downward's fast-downward.py (else the DEMOPLAN_FD environment variable).
    #[arg(long, value_name = "PATH")]
    pub fd: Option<PathBuf>,
    /// Also plan on the full domain and print its optimal cost beside the slim plan's.
    #[arg(long)]
    pub compare_full: bool,
    /// Where to write the plan.
    #[arg(long, value_name = "FILE", default_value = "sas_plan")]
    pub plan_file: PathBuf,
    /// Keep operators that change nothing in the domains.
    #[arg(long)]
    pub keep_without_effects: bool,
    #[command(flatten)]
    pub execution: closed_loop::ExecutionArgs,
}

/// The options of `execute`.
#[derive(Debug, Args)]
pub struct ExecuteArgs {
    /// The domain file.
    pub domain: PathBuf,
    /// The problem file.
    pub problem: PathBuf,
    /// The plan file: one action `(name arg1 arg2)` per line.
    pub plan: PathBuf,
    /// Write the plan with the poses of hands and cubes per step as JSON.
    #[arg(long, value_name = "FILE")]
    pub json: Option<PathBuf>,
    /// Write the frames of the execution as a recording (JSON Lines).
    #[arg(long, value_name = "FILE.jsonl")]
    pub frames: Option<PathBuf>,
}

/// The options of `reproduce`.
#[derive(Debug, Args)]
#[command(mut_arg("time_limit", |a| a.default_value("60")))]
pub struct ReproduceArgs {
    /// The output folder (created if missing).
    #[arg(
        short = 'o',
        long = "out",
        value_name = "DIR",
        default_value = "reproduction"
    )]
    pub out: PathBuf,
    #[command(flatten)]
    pub limits: RunLimitArgs,
    /// Runs per cell; tables show medians.
    #[arg(long, value_name = "N", default_value_t = 1, value_parser = clap::value_parser!(u32).range(1..=100))]
    pub repeat: u32,
    /// The goals to plan, e.g. `1,2,3`.
    #[arg(
        long,
        value_name = "LIST",
        default_value = "1,2,3,4,5",
        value_delimiter = ','
    )]
    pub goals: Vec<usize>,
    /// Only these priority levels, e.g. `1,2` (default: every level).
    #[arg(long, value_name = "LIST", value_delimiter = ',')]
    pub prios: Option<Vec<usize>>,
    #[command(flatten)]
    pub fast_downward: FastDownwardArgs,
    /// Seed of the simulated demonstrations.
    #[arg(long, value_name = "N", default_value_t = 7)]
    pub seed: u64,
    /// Hands in the problems' scene: 1 (a one-armed robot, as the paper's TIAGo) or 2.
    #[arg(long, value_name = "N", default_value_t = 1, value_parser = clap::value_parser!(u64).range(1..=2))]
    pub hands: u64,
    #[command(flatten)]
    pub grid: GridArgs,
    #[command(flatten)]
    pub slurm: SlurmArgs,
}

/// The options of `study`.
#[derive(Debug, Args)]
#[command(mut_arg("time_limit", |a| a.default_value("20")))]
pub struct StudyArgs {
    #[command(flatten)]
    pub conditions: experiment::StudyConditionArgs,
    /// The simulator's parameters (JSON, as `demoplan simulate --params`).
    #[arg(long, value_name = "FILE")]
    pub params: Option<PathBuf>,
    #[command(flatten)]
    pub limits: RunLimitArgs,
    #[command(flatten)]
    pub fast_downward: FastDownwardArgs,
    /// The output folder (created if missing; a folder with results resumes).
    #[arg(short = 'o', long = "out", value_name = "DIR", default_value = "study")]
    pub out: PathBuf,
    #[command(flatten)]
    pub grid: GridArgs,
    #[command(flatten)]
    pub slurm: SlurmArgs,
}
