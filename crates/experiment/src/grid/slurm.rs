//! A grid as Slurm jobs (`--slurm DIR`): written, never submitted or run here.
//!
//! [`write_job`] writes into DIR an `sbatch` array job per phase of the grid (its
//! cells, then its Algorithm 1 cells, which reuse the levels' runs and so wait for
//! them), a collect job that builds the report once they have ended
//! (`--dependency=afterany`), the list of the cells each array task computes, and
//! `submit.sh`, which submits them in that order from any directory. Each array task
//! runs the grid's own command line again with `--cell ID` for each of its cells, which
//! writes the cell's results into the grid's `-o DIR` in the same layout as a local
//! run; DIR holds only the scripts and the jobs' logs. A cell with a result is skipped
//! by its task, so submitting again computes only what is missing, as Lab does.
//!
//! Cells are shuffled (seeded, so the same grid gives the same tasks) before they are
//! dealt to tasks: a grid lists its cells by conditions, and the slow ones (the highest
//! towers) would otherwise crowd into the last tasks.

use std::ffi::OsString;
use std::path::{Path, PathBuf};
use std::time::Duration;

use crate::cell::{Cell, LevelChoice};
use crate::output::{create_dir, io_error, write_text};
use crate::ExperimentError;

/// Array tasks at most by default: Slurm's default `MaxArraySize` is 1001, so indices
/// up to 1000 are accepted everywhere.
pub const MAX_ARRAY_TASKS: usize = 1000;

/// What `--mem` adds to a cell's memory limit by default: the limit counts the
/// planning run's heap, not the process around it (the binary, the simulated study and
/// its library).
pub const MEMORY_MARGIN: u64 = 512 << 20;

/// What `--time` adds to a cell's time limit by default (per cell), at least: the
/// limit counts the planning run, not the process's start (simulating and learning),
/// Fast Downward's driver or the writing of the results. A tenth of the limit when that
/// is more.
pub const TIME_MARGIN: Duration = Duration::from_secs(60);

/// Each cell's memory limit on Slurm when the grid's is `auto`: the memory available
/// where the job is written says nothing about the nodes.
pub const AUTO_MEMORY_LIMIT: u64 = 3 << 30;

/// A time limit at least this long is no limit: the job gets no `--time` line and
/// runs under the partition's default.
const NO_TIME_LIMIT: Duration = Duration::from_secs(365 * 24 * 3600);

/// The collect job's `--time` by default: it reads the records and writes the report.
const COLLECT_TIME: Duration = Duration::from_secs(3600);

/// How the grid's Slurm jobs ask for resources; every field has a default
/// ([`SlurmOptions::new`]).
#[derive(Debug, Clone, PartialEq)]
pub struct SlurmOptions {
    /// Where the job scripts and logs go (made absolute when written).
    pub dir: PathBuf,
    /// `--partition`; none: the cluster's default partition, and no line.
    pub partition: Option<String>,
    /// `--cpus-per-task` (default 1: a planning run uses one core).
    pub cpus_per_task: u32,
    /// `--mem` in bytes; none: the cells' memory limit plus [`MEMORY_MARGIN`] (no
    /// line when the cells have no memory limit).
    pub mem: Option<u64>,
    /// `--time` of an array task; none: the cells' time limit plus a margin
    /// ([`TIME_MARGIN`]), times the cells per task.
    pub time: Option<Duration>,
    /// Cells per array task; none: as few as keep the array within
    /// [`MAX_ARRAY_TASKS`] tasks.
    pub cells_per_task: Option<usize>,
    /// K of `--array=1-N%K`: tasks running at once, at most (default 100).
    pub max_running: usize,
    /// The seed of the shuffle that deals cells to tasks.
    pub seed: u64,
    /// Further `sbatch` options, one per line (`--account=NAME`, `--qos=NAME`).
    pub sbatch: Vec<String>,
}

impl SlurmOptions {
    /// The defaults, writing into `dir`.
    pub fn new(dir: &Path) -> SlurmOptions {
        SlurmOptions {
            dir: dir.to_path_buf(),
            partition: None,
            cpus_per_task: 1,
            mem: None,
            time: None,
            cells_per_task: None,
            max_running: 100,
            seed: 1,
            sbatch: Vec::new(),
        }
    }
}

/// The grid's command line, as the jobs run it.
#[derive(Debug, Clone, PartialEq)]
pub struct GridCommand {
    /// The executable, absolute (on a cluster: on a file system every node shares).
    pub program: PathBuf,
    /// The grid's arguments as given (`--slurm` among them: `--cell` and `--collect`
    /// take precedence over it).
    pub args: Vec<OsString>,
    /// The folder the command was given in: the jobs run there, so that relative paths
    /// in `args` (`-o DIR`, `--params FILE`) mean what they meant.
    pub workdir: PathBuf,
    /// The grid command's name, for the jobs' names (`study`, `reproduce`).
    pub name: String,
    /// Each cell's memory limit in bytes (none: no limit), passed to every cell as
    /// `--memory-limit`, so that a node does not work out its own `auto`.
    pub memory_limit: Option<u64>,
}

/// One array job: a phase of the grid's cells, dealt to tasks.
#[derive(Debug, Clone, PartialEq)]
pub struct ArrayJob {
    /// The script's file name in DIR (`cells.sh`, `algorithm1.sh`).
    pub script: String,
    /// Per task (task 1 first), the ids of its cells.
    pub tasks: Vec<Vec<String>>,
    /// The `--time` each task asks for, if any.
    pub time: Option<Duration>,
}

/// What [`write_job`] wrote.
#[derive(Debug, Clone, PartialEq)]
pub struct SlurmJob {
    /// DIR, absolute.
    pub dir: PathBuf,
    /// The array jobs in submission order (a phase without cells has none).
    pub arrays: Vec<ArrayJob>,
    /// `submit.sh`.
    pub submit: PathBuf,
    /// Cells in the grid.
    pub cells: usize,
}

impl SlurmJob {
    /// What `--slurm` says when it has written the job.
    pub fn summary(&self) -> String {
        let arrays: Vec<String> = self
            .arrays
            .iter()
            .map(|a| {
                let cells: usize = a.tasks.iter().map(Vec::len).sum();
                format!("{} ({cells} cells in {} tasks)", a.script, a.tasks.len())
            })
            .collect();
        format!(
            "wrote {} cells as Slurm array jobs {} and a collect job into {}\n\
             submit them with: bash {}\n",
            self.cells,
            arrays.join(", "),
            self.dir.display(),
            self.submit.display()
        )
    }
}

/// `cells` in a seeded order: a Fisher-Yates shuffle drawing from MT19937 (64-bit).
fn shuffled<'a>(cells: &[&'a Cell], seed: u64) -> Vec<&'a Cell> {
    let mut order = cells.to_vec();
    let mut rng = rand_mt::Mt64::new(seed);
    for i in (1..order.len()).rev() {
        let j = (rng.next_u64() % (i as u64 + 1)) as usize;
        order.swap(i, j);
    }
    order
}

/// The cells per task: the option, else as few as keep within [`MAX_ARRAY_TASKS`].
fn cells_per_task(options: &SlurmOptions, cells: usize) -> usize {
    options
        .cells_per_task
        .unwrap_or_else(|| cells.div_ceil(MAX_ARRAY_TASKS))
        .max(1)
}

/// `--time` of a task of `per_task` cells of limit `limit`: the option, else the limit
/// plus its margin, times the cells.
fn task_time(options: &SlurmOptions, limit: Duration, per_task: usize) -> Option<Duration> {
    if let Some(t) = options.time {
        return Some(t);
    }
    if limit >= NO_TIME_LIMIT {
        return None;
    }
    let per_cell = limit + TIME_MARGIN.max(limit / 10);
    Some(per_cell * per_task as u32)
}

/// `--slurm-mem`: a size in Fast Downward's units (`512M`, `3G`; bytes without one).
pub fn parse_mem(text: &str) -> Result<u64, String> {
    task::units::parse_memory_limit(text)?
        .ok_or_else(|| "a job asks for a size: infinity is none".to_string())
}

/// `--slurm-time`: a duration in Fast Downward's units (`90m`, `2h`; seconds without
/// one).
pub fn parse_time(text: &str) -> Result<Duration, String> {
    task::units::parse_time_limit(text)?
        .ok_or_else(|| "a job asks for a duration: infinity is none".to_string())
}

/// Slurm's `--time` value, `D-HH:MM:SS` (`HH:MM:SS` under a day), rounded up to whole
/// minutes (Slurm's unit).
pub fn slurm_time(t: Duration) -> String {
    let seconds = t.as_secs() + u64::from(t.subsec_nanos() > 0);
    let minutes = seconds.div_ceil(60).max(1);
    let (days, hours, mins) = (minutes / 1440, minutes / 60 % 24, minutes % 60);
    if days > 0 {
        format!("{days}-{hours:02}:{mins:02}:00")
    } else {
        format!("{hours:02}:{mins:02}:00")
    }
}

/// Slurm's `--mem` value in MiB (`M`, Slurm's default unit), rounded up.
pub fn slurm_mem(bytes: u64) -> String {
    format!("{}M", bytes.div_ceil(1 << 20).max(1))
}

/// A path as a shell word.
fn quoted_path(path: &Path) -> Result<String, ExperimentError> {
    let text = path.to_str().ok_or_else(|| {
        ExperimentError::Options(format!(
            "--slurm: {} is not UTF-8, which the job scripts cannot name",
            path.display()
        ))
    })?;
    quoted(text)
}

fn quoted(word: &str) -> Result<String, ExperimentError> {
    shlex::try_quote(word)
        .map(|q| q.into_owned())
        .map_err(|e| ExperimentError::Options(format!("--slurm: cannot quote {word:?}: {e}")))
}

/// A file name pattern of `sbatch --output`, `pattern` (with Slurm's `%A`, `%a`, `%j`)
/// in `folder`: `%` is Slurm's escape, so a literal one in the folder is doubled.
fn output_pattern(folder: &Path, pattern: &str) -> Result<String, ExperimentError> {
    let text = folder.to_str().ok_or_else(|| {
        ExperimentError::Options(format!("--slurm: {} is not UTF-8", folder.display()))
    })?;
    quoted(&format!("{}/{pattern}", text.replace('%', "%%")))
}

/// The `#SBATCH` lines every job shares: partition, CPUs, memory and the extra options.
fn common_lines(options: &SlurmOptions, mem: Option<u64>) -> Vec<String> {
    let mut lines = Vec::new();
    if let Some(p) = &options.partition {
        lines.push(format!("--partition={p}"));
    }
    lines.push(format!("--cpus-per-task={}", options.cpus_per_task.max(1)));
    if let Some(m) = mem {
        lines.push(format!("--mem={}", slurm_mem(m)));
    }
    lines.extend(options.sbatch.iter().cloned());
    lines
}

/// The shell lines that set `program` and `args` to the grid's command.
fn command_lines(command: &GridCommand) -> Result<String, ExperimentError> {
    let mut args = Vec::with_capacity(command.args.len());
    for a in &command.args {
        let text = a.to_str().ok_or_else(|| {
            ExperimentError::Options(format!(
                "--slurm: the argument {a:?} is not UTF-8, which the job scripts cannot pass"
            ))
        })?;
        args.push(quoted(text)?);
    }
    Ok(format!(
        "program={}\nargs=({})\n",
        quoted_path(&command.program)?,
        args.join(" ")
    ))
}

fn script(sbatch: &[String], comment: &str, body: &str) -> String {
    let mut s = String::from("#!/bin/bash\n");
    for line in sbatch {
        s.push_str(&format!("#SBATCH {line}\n"));
    }
    for line in comment.lines() {
        s.push_str(&format!("# {line}\n").replace("# \n", "#\n"));
    }
    s.push_str(body);
    s
}

/// Writes the grid `cells`, run by `command`, as Slurm jobs into `options.dir`:
/// `cells.sh` (and `algorithm1.sh` when the grid has Algorithm 1 cells) with their
/// task lists `cells.tasks` (`algorithm1.tasks`), `collect.sh`, `submit.sh`, and the
/// folder `logs`. Nothing is submitted.
pub fn write_job(
    cells: &[Cell],
    command: &GridCommand,
    options: &SlurmOptions,
) -> Result<SlurmJob, ExperimentError> {
    if cells.is_empty() {
        return Err(ExperimentError::Options(
            "--slurm: the grid has no cells".into(),
        ));
    }
    if options.max_running == 0 {
        return Err(ExperimentError::Options(
            "--slurm-max-running: must be at least 1".into(),
        ));
    }
    if !command.program.is_absolute() || !command.workdir.is_absolute() {
        return Err(ExperimentError::Options(format!(
            "--slurm: the program ({}) and the folder it runs in ({}) must be absolute paths",
            command.program.display(),
            command.workdir.display()
        )));
    }
    let dir = if options.dir.is_absolute() {
        options.dir.clone()
    } else {
        command.workdir.join(&options.dir)
    };
    create_dir(&dir.join("logs"))?;
    let mem = options.mem.or(command
        .memory_limit
        .map(|m| m.saturating_add(MEMORY_MARGIN)));
    let limit = cells.iter().map(|c| c.time_limit).max().unwrap_or_default();
    let memory_arg = command
        .memory_limit
        .map_or("infinity".to_string(), |b| b.to_string());
    let (levels, widenings): (Vec<&Cell>, Vec<&Cell>) = cells
        .iter()
        .partition(|c| c.level != LevelChoice::Algorithm1);
    let per_task = cells_per_task(options, levels.len().max(widenings.len()));
    let set_command = command_lines(command)?;
    let mut arrays = Vec::new();
    for (phase, name) in [(levels, "cells"), (widenings, "algorithm1")] {
        if phase.is_empty() {
            continue;
        }
        let tasks: Vec<Vec<String>> = shuffled(&phase, options.seed)
            .chunks(per_task)
            .map(|chunk| chunk.iter().map(|c| c.id()).collect())
            .collect();
        let tasks_file = dir.join(format!("{name}.tasks"));
        let mut list = String::new();
        for task in &tasks {
            list.push_str(&task.join(" "));
            list.push('\n');
        }
        write_text(&tasks_file, &list)?;
        let time = task_time(options, limit, per_task);
        let mut lines = vec![
            format!("--job-name=demoplan-{}-{name}", command.name),
            format!("--array=1-{}%{}", tasks.len(), options.max_running),
        ];
        lines.extend(common_lines(options, mem));
        if let Some(t) = time {
            lines.push(format!("--time={}", slurm_time(t)));
        }
        let what = if name == "cells" {
            "the grid's cells but its Algorithm 1 cells"
        } else {
            "the grid's Algorithm 1 cells (after the others: they reuse their runs)"
        };
        let comment = format!(
            "Written by `demoplan {} --slurm`: an array job over {what}.\n\
             Task T computes the cells on line T of {name}.tasks, each with `--cell ID`,\n\
             into the grid's -o DIR; a cell with a result there is skipped.\n\
             Submitted by submit.sh (which adds --chdir and --output).",
            command.name
        );
        let body = format!(
            "set -u\n{set_command}tasks={}\n\
             status=0\n\
             for id in $(sed -n \"${{SLURM_ARRAY_TASK_ID}}p\" \"$tasks\"); do\n\
             \x20   echo \"demoplan: cell $id (task $SLURM_ARRAY_TASK_ID on $(hostname))\"\n\
             \x20   \"$program\" \"${{args[@]}}\" --memory-limit {memory_arg} --cell \"$id\" || status=1\n\
             done\n\
             exit $status\n",
            quoted_path(&tasks_file)?
        );
        let path = dir.join(format!("{name}.sh"));
        write_text(&path, &script(&lines, &comment, &body))?;
        arrays.push(ArrayJob {
            script: format!("{name}.sh"),
            tasks,
            time,
        });
    }
    let mut lines = vec![format!("--job-name=demoplan-{}-collect", command.name)];
    lines.extend(common_lines(options, mem));
    lines.push(format!("--time={}", slurm_time(COLLECT_TIME)));
    let comment = format!(
        "Written by `demoplan {} --slurm`: builds the report from the cells' results in\n\
         the grid's -o DIR once the array jobs have ended (submit.sh makes it depend on\n\
         them with afterany). It computes nothing: a cell without a result makes it fail,\n\
         naming the cells; submit again to compute them.",
        command.name
    );
    let body = format!("set -u\n{set_command}exec \"$program\" \"${{args[@]}}\" --collect\n");
    write_text(&dir.join("collect.sh"), &script(&lines, &comment, &body))?;
    let submit = dir.join("submit.sh");
    write_text(&submit, &submit_script(&dir, command, &arrays)?)?;
    make_executable(&submit)?;
    Ok(SlurmJob {
        dir,
        arrays,
        submit,
        cells: cells.len(),
    })
}

fn submit_script(
    dir: &Path,
    command: &GridCommand,
    arrays: &[ArrayJob],
) -> Result<String, ExperimentError> {
    let mut s = format!(
        "#!/usr/bin/env bash\n\
         # Written by `demoplan {name} --slurm`: submits the grid's array jobs, one after\n\
         # the other, and the collect job once they have ended. Run it from any folder; run\n\
         # it again to compute the cells without a result (the others are skipped).\n\
         # --wait: wait for the collect job and exit with its exit code.\n\
         # The job ids go to {jobs} as they are known (`cells ID`, ..., `collect ID`).\n\
         set -euo pipefail\n\
         dir={dir_q}\n\
         workdir={workdir}\n\
         wait=no\n\
         case \"${{1:-}}\" in\n\
         --wait) wait=yes ;;\n\
         '') ;;\n\
         *) echo \"usage: $0 [--wait]\" >&2; exit 2 ;;\n\
         esac\n\
         mkdir -p \"$dir/logs\"\n\
         : >\"$dir/jobs\"\n\
         after=\n",
        name = command.name,
        jobs = dir.join("jobs").display(),
        dir_q = quoted_path(dir)?,
        workdir = quoted_path(&command.workdir)?,
    );
    for array in arrays {
        let name = array.script.trim_end_matches(".sh");
        let log = output_pattern(&dir.join("logs"), &format!("{name}-%A_%a.out"))?;
        s.push_str(&format!(
            "id=$(sbatch --parsable ${{after:+--dependency=afterany$after}} --chdir=\"$workdir\" \\\n\
             \x20   --output={log} \"$dir/{script}\")\n\
             id=${{id%%;*}}\n\
             echo \"{name} $id\" >>\"$dir/jobs\"\n\
             echo \"submitted {name}: array job $id ({tasks} tasks)\"\n\
             after=\"$after:$id\"\n",
            script = array.script,
            tasks = array.tasks.len(),
        ));
    }
    let log = output_pattern(&dir.join("logs"), "collect-%j.out")?;
    s.push_str(&format!(
        "id=$(sbatch --parsable --dependency=afterany$after --chdir=\"$workdir\" \\\n\
         \x20   --output={log} \"$dir/collect.sh\")\n\
         id=${{id%%;*}}\n\
         echo \"collect $id\" >>\"$dir/jobs\"\n\
         echo \"submitted collect: job $id; logs in $dir/logs\"\n\
         [ \"$wait\" = yes ] || exit 0\n\
         # Polled each second (sbatch --wait backs off to half a minute): the job's state\n\
         # is known to scontrol until MinJobAge (300 s by default) after it ends.\n\
         while :; do\n\
         \x20   state=$(scontrol show job -o \"$id\")\n\
         \x20   case \"$state\" in\n\
         \x20   *JobState=PENDING* | *JobState=RUNNING* | *JobState=CONFIGURING* | *JobState=COMPLETING* | *JobState=SUSPENDED*) sleep 1 ;;\n\
         \x20   *) break ;;\n\
         \x20   esac\n\
         done\n\
         case \"$state\" in\n\
         *JobState=COMPLETED*) exit 0 ;;\n\
         *JobState=FAILED*' 'ExitCode=*)\n\
         \x20   code=${{state##*' 'ExitCode=}}\n\
         \x20   echo \"the collect job $id failed (exit code ${{code%%:*}}): see $dir/logs/collect-$id.out\" >&2\n\
         \x20   exit \"${{code%%:*}}\" ;;\n\
         *) echo \"the collect job $id ended: $state\" >&2; exit 1 ;;\n\
         esac\n"
    ));
    Ok(s)
}

#[cfg(unix)]
fn make_executable(path: &Path) -> Result<(), ExperimentError> {
    use std::os::unix::fs::PermissionsExt;
    std::fs::set_permissions(path, std::fs::Permissions::from_mode(0o755))
        .map_err(|e| io_error(path, e))
}

#[cfg(not(unix))]
fn make_executable(_path: &Path) -> Result<(), ExperimentError> {
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::cell::{Conditions, Planner};
    use std::collections::BTreeMap;
    use std::process::Command;

    fn grid(seeds: u64, limit: u64) -> Vec<Cell> {
        let mut cells = Vec::new();
        for seed in 1..=seeds {
            for level in [
                LevelChoice::Prio(1),
                LevelChoice::Full,
                LevelChoice::Algorithm1,
            ] {
                cells.push(Cell {
                    conditions: Conditions::paper_goal(seed, 1, 1),
                    level,
                    planner: Planner::Lmcut,
                    time_limit: Duration::from_secs(limit),
                    repeat: 0,
                });
            }
        }
        cells
    }

    fn scratch(name: &str) -> PathBuf {
        let dir =
            std::env::temp_dir().join(format!("demoplan-slurm-{name}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).unwrap();
        dir
    }

    fn command(program: &Path, workdir: &Path) -> GridCommand {
        GridCommand {
            program: program.to_path_buf(),
            args: [
                "study",
                "--seeds",
                "1-4",
                "-o",
                "out dir/it's here",
                "--slurm",
                "jobs",
            ]
            .map(OsString::from)
            .to_vec(),
            workdir: workdir.to_path_buf(),
            name: "study".into(),
            memory_limit: Some(1 << 30),
        }
    }

    fn sbatch_lines(script: &str) -> Vec<&str> {
        script
            .lines()
            .filter_map(|l| l.strip_prefix("#SBATCH "))
            .collect()
    }

    #[test]
    fn the_shuffle_is_a_seeded_permutation() {
        let cells = grid(20, 10);
        let refs: Vec<&Cell> = cells.iter().collect();
        let ids = |order: Vec<&Cell>| order.iter().map(|c| c.id()).collect::<Vec<_>>();
        let once = ids(shuffled(&refs, 1));
        assert_eq!(once, ids(shuffled(&refs, 1)));
        assert_ne!(once, ids(shuffled(&refs, 2)));
        assert_ne!(once, ids(refs.clone()));
        let mut sorted = once.clone();
        sorted.sort();
        let mut all = ids(refs);
        all.sort();
        assert_eq!(sorted, all);
    }

    #[test]
    fn option_values_in_fast_downwards_units() {
        assert_eq!(parse_mem("3G"), Ok(3 << 30));
        assert_eq!(parse_mem("512M"), Ok(512 << 20));
        assert!(parse_mem("infinity").unwrap_err().contains("infinity"));
        assert!(parse_mem("lots").is_err());
        assert_eq!(parse_time("90m"), Ok(Duration::from_secs(5400)));
        assert!(parse_time("infinity").is_err());
    }

    #[test]
    fn slurm_values_round_up() {
        assert_eq!(slurm_time(Duration::from_secs(80)), "00:02:00");
        assert_eq!(slurm_time(Duration::from_secs(60)), "00:01:00");
        assert_eq!(slurm_time(Duration::from_millis(60_001)), "00:02:00");
        assert_eq!(slurm_time(Duration::from_secs(1)), "00:01:00");
        assert_eq!(
            slurm_time(Duration::from_secs(25 * 3600 + 61)),
            "1-01:02:00"
        );
        assert_eq!(slurm_mem(1 << 30), "1024M");
        assert_eq!(slurm_mem((1 << 30) + 1), "1025M");
    }

    #[test]
    fn defaults_ask_for_one_cpu_the_limits_and_a_margin_and_no_partition() {
        let dir = scratch("defaults");
        let job = write_job(
            &grid(4, 20),
            &command(Path::new("/usr/bin/demoplan"), &dir),
            &SlurmOptions::new(&dir.join("jobs")),
        )
        .unwrap();
        let cells = std::fs::read_to_string(dir.join("jobs/cells.sh")).unwrap();
        assert_eq!(
            sbatch_lines(&cells),
            [
                "--job-name=demoplan-study-cells",
                "--array=1-8%100",
                "--cpus-per-task=1",
                // 1 GiB and the margin of 512 MiB.
                "--mem=1536M",
                // 20 s and a margin of 60 s, one cell per task.
                "--time=00:02:00",
            ]
        );
        assert!(!cells.contains("partition"), "{cells}");
        let alg1 = std::fs::read_to_string(dir.join("jobs/algorithm1.sh")).unwrap();
        assert!(sbatch_lines(&alg1).contains(&"--array=1-4%100"), "{alg1}");
        assert_eq!(job.arrays.len(), 2);
        assert_eq!(job.arrays[0].tasks.len(), 8);
        assert!(job.arrays[0].tasks.iter().all(|t| t.len() == 1));
        let collect = std::fs::read_to_string(dir.join("jobs/collect.sh")).unwrap();
        assert!(sbatch_lines(&collect).contains(&"--mem=1536M"), "{collect}");
        assert!(!collect.contains("--array"), "{collect}");
        assert!(job.summary().contains("12 cells"), "{}", job.summary());
        let _ = std::fs::remove_dir_all(&dir);
    }

    #[test]
    fn every_value_can_be_set() {
        let dir = scratch("options");
        let options = SlurmOptions {
            partition: Some("short".into()),
            cpus_per_task: 2,
            mem: Some(3 << 30),
            time: None,
            cells_per_task: Some(3),
            max_running: 5,
            seed: 9,
            sbatch: vec!["--account=planning".into()],
            ..SlurmOptions::new(&dir.join("jobs"))
        };
        let job = write_job(&grid(4, 20), &command(Path::new("/bin/d"), &dir), &options).unwrap();
        let cells = std::fs::read_to_string(dir.join("jobs/cells.sh")).unwrap();
        assert_eq!(
            sbatch_lines(&cells),
            [
                "--job-name=demoplan-study-cells",
                // 8 cells, 3 per task.
                "--array=1-3%5",
                "--partition=short",
                "--cpus-per-task=2",
                "--mem=3072M",
                "--account=planning",
                // (20 s + 60 s) x 3 cells = 240 s.
                "--time=00:04:00",
            ]
        );
        assert_eq!(
            job.arrays[0].tasks.iter().map(Vec::len).collect::<Vec<_>>(),
            [3, 3, 2]
        );
        let timed = SlurmOptions {
            time: Some(Duration::from_secs(7200)),
            ..options
        };
        write_job(&grid(4, 20), &command(Path::new("/bin/d"), &dir), &timed).unwrap();
        let cells = std::fs::read_to_string(dir.join("jobs/cells.sh")).unwrap();
        assert!(sbatch_lines(&cells).contains(&"--time=02:00:00"), "{cells}");
        let _ = std::fs::remove_dir_all(&dir);
    }

    #[test]
    fn no_limit_no_line() {
        let dir = scratch("unlimited");
        let mut unlimited = command(Path::new("/bin/d"), &dir);
        unlimited.memory_limit = None;
        write_job(
            &grid(1, u64::from(u32::MAX)),
            &unlimited,
            &SlurmOptions::new(&dir.join("jobs")),
        )
        .unwrap();
        let cells = std::fs::read_to_string(dir.join("jobs/cells.sh")).unwrap();
        let lines = sbatch_lines(&cells);
        assert!(
            !lines
                .iter()
                .any(|l| l.starts_with("--mem") || l.starts_with("--time")),
            "{cells}"
        );
        assert!(cells.contains("--memory-limit infinity"), "{cells}");
        let _ = std::fs::remove_dir_all(&dir);
    }

    /// A stand-in for demoplan that logs its arguments, one line per run, each
    /// argument in brackets.
    fn logging_program(dir: &Path) -> PathBuf {
        let program = dir.join("fake demoplan");
        std::fs::write(
            &program,
            format!(
                "#!/bin/bash\nprintf '[%s]' \"$@\" >>{}\necho >>{}\n",
                dir.join("calls").display(),
                dir.join("calls").display()
            ),
        )
        .unwrap();
        make_executable(&program).unwrap();
        program
    }

    #[test]
    fn the_tasks_run_every_cell_once_with_the_grids_arguments() {
        let dir = scratch("tasks");
        let program = logging_program(&dir);
        let cells = grid(5, 20);
        let options = SlurmOptions {
            cells_per_task: Some(2),
            ..SlurmOptions::new(&dir.join("jobs"))
        };
        let job = write_job(&cells, &command(&program, &dir), &options).unwrap();
        for array in &job.arrays {
            for task in 1..=array.tasks.len() {
                let status = Command::new("bash")
                    .arg(dir.join("jobs").join(&array.script))
                    .env("SLURM_ARRAY_TASK_ID", task.to_string())
                    .status()
                    .unwrap();
                assert!(status.success());
            }
        }
        let calls = std::fs::read_to_string(dir.join("calls")).unwrap();
        let mut ran: BTreeMap<String, usize> = BTreeMap::new();
        for call in calls.lines() {
            let (head, id) = call.rsplit_once("[--cell][").unwrap();
            assert_eq!(
                head,
                "[study][--seeds][1-4][-o][out dir/it's here][--slurm][jobs]\
                 [--memory-limit][1073741824]"
            );
            *ran.entry(id.trim_end_matches(']').to_string()).or_default() += 1;
        }
        let mut all: Vec<String> = cells.iter().map(Cell::id).collect();
        all.sort();
        assert_eq!(ran.keys().cloned().collect::<Vec<_>>(), all);
        assert!(ran.values().all(|&n| n == 1), "{ran:?}");
        // The collect job runs the grid's command with --collect.
        std::fs::remove_file(dir.join("calls")).unwrap();
        let status = Command::new("bash")
            .arg(dir.join("jobs/collect.sh"))
            .status()
            .unwrap();
        assert!(status.success());
        let calls = std::fs::read_to_string(dir.join("calls")).unwrap();
        assert_eq!(
            calls,
            "[study][--seeds][1-4][-o][out dir/it's here][--slurm][jobs][--collect]\n"
        );
        let _ = std::fs::remove_dir_all(&dir);
    }

    #[test]
    fn submit_chains_the_jobs_from_any_folder() {
        let dir = scratch("submit");
        // An `sbatch` that logs its arguments and answers as `--parsable` does.
        let bin = dir.join("bin");
        std::fs::create_dir_all(&bin).unwrap();
        let log = dir.join("sbatch.log");
        std::fs::write(
            bin.join("sbatch"),
            format!(
                "#!/bin/bash\necho \"$*\" >>{log}\nn=$(wc -l <{log})\necho \"$((100 + n));demoplan\"\n",
                log = log.display()
            ),
        )
        .unwrap();
        make_executable(&bin.join("sbatch")).unwrap();
        let work = dir.join("work");
        std::fs::create_dir_all(&work).unwrap();
        let job = write_job(
            &grid(2, 20),
            &command(Path::new("/opt/demoplan"), &work),
            &SlurmOptions::new(Path::new("jobs")),
        )
        .unwrap();
        assert_eq!(job.dir, work.join("jobs"));
        let path = format!(
            "{}:{}",
            bin.display(),
            std::env::var("PATH").unwrap_or_default()
        );
        let out = Command::new("bash")
            .arg(&job.submit)
            .current_dir("/")
            .env("PATH", path)
            .output()
            .unwrap();
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        let jobs_dir = work.join("jobs");
        let calls = std::fs::read_to_string(&log).unwrap();
        let calls: Vec<&str> = calls.lines().collect();
        let d = jobs_dir.display();
        let w = work.display();
        assert_eq!(
            calls,
            [
                format!("--parsable --chdir={w} --output={d}/logs/cells-%A_%a.out {d}/cells.sh"),
                format!(
                    "--parsable --dependency=afterany:101 --chdir={w} \
                     --output={d}/logs/algorithm1-%A_%a.out {d}/algorithm1.sh"
                ),
                format!(
                    "--parsable --dependency=afterany:101:102 --chdir={w} \
                     --output={d}/logs/collect-%j.out {d}/collect.sh"
                ),
            ]
        );
        assert_eq!(
            std::fs::read_to_string(jobs_dir.join("jobs")).unwrap(),
            "cells 101\nalgorithm1 102\ncollect 103\n"
        );
        let _ = std::fs::remove_dir_all(&dir);
    }

    #[test]
    fn submit_waits_for_the_collect_job_and_exits_with_its_code() {
        let dir = scratch("wait");
        let bin = dir.join("bin");
        std::fs::create_dir_all(&bin).unwrap();
        let n = dir.join("n");
        std::fs::write(bin.join("sbatch"), "#!/bin/bash\necho \"7;demoplan\"\n").unwrap();
        // Running twice, then what the test's `STATE` says, as `scontrol show job -o`.
        std::fs::write(
            bin.join("scontrol"),
            format!(
                "#!/bin/bash\necho x >>{n}\nif [ $(wc -l <{n}) -le 2 ]; then\n\
                 echo 'JobId=7 JobName=c JobState=RUNNING Reason=None ExitCode=0:0'\n\
                 else echo \"JobId=7 JobName=c $STATE DerivedExitCode=0:0\"; fi\n",
                n = n.display()
            ),
        )
        .unwrap();
        for tool in ["sbatch", "scontrol"] {
            make_executable(&bin.join(tool)).unwrap();
        }
        let job = write_job(
            &grid(1, 20),
            &command(Path::new("/opt/demoplan"), &dir),
            &SlurmOptions::new(&dir.join("jobs")),
        )
        .unwrap();
        let path = format!(
            "{}:{}",
            bin.display(),
            std::env::var("PATH").unwrap_or_default()
        );
        for (state, code) in [
            ("JobState=COMPLETED Reason=None ExitCode=0:0", 0),
            ("JobState=FAILED Reason=NonZeroExitCode ExitCode=4:0", 4),
            ("JobState=TIMEOUT Reason=TimeLimit ExitCode=0:15", 1),
        ] {
            let _ = std::fs::remove_file(&n);
            let out = Command::new("bash")
                .arg(&job.submit)
                .arg("--wait")
                .env("PATH", &path)
                .env("STATE", state)
                .output()
                .unwrap();
            assert_eq!(out.status.code(), Some(code), "{state}: {out:?}");
            // It polled until the job had ended.
            assert_eq!(std::fs::read_to_string(&n).unwrap().lines().count(), 3);
        }
        let _ = std::fs::remove_dir_all(&dir);
    }

    #[test]
    fn relative_programs_and_empty_grids_are_refused() {
        let dir = scratch("refused");
        let e = write_job(
            &grid(1, 20),
            &command(Path::new("demoplan"), &dir),
            &SlurmOptions::new(&dir),
        )
        .unwrap_err();
        assert!(e.to_string().contains("must be absolute"), "{e}");
        let e = write_job(
            &[],
            &command(Path::new("/bin/d"), &dir),
            &SlurmOptions::new(&dir),
        )
        .unwrap_err();
        assert!(e.to_string().contains("no cells"), "{e}");
        let _ = std::fs::remove_dir_all(&dir);
    }
}
