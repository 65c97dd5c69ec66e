//! How a grid command runs its grid, shared by `reproduce` and `study`: the settings
//! every cell runs with ([`GridSettings`]), what the grid is asked to do instead of
//! running (`--list-cells`, `--cell ID`, `--slurm DIR`: [`GridArgs::instead_of_grid`]),
//! and the options that say so ([`GridArgs`], [`SlurmArgs`], [`FastDownwardArgs`], and
//! [`RunLimitArgs`], which `solve` takes too).
//! With the `clap` feature those derive `clap::Args`: they are the command line's options,
//! declared once here beside what they switch on (their doc comments are the `--help`
//! texts; docs/grids.md).

use std::path::{Path, PathBuf};
use std::time::Duration;

use slim::{FastDownward, MemoryProbe};

use super::slurm::SlurmOptions;
use super::{cell_or_list, collect, jobs, memory_limit, run_cell, run_grid, GridRun};
use super::{CellCommand, Relaunch, RunLayout, Runner};
use crate::cell::{Cell, Planner};
use crate::lab::Lab;
use crate::record::RunRecord;
use crate::{ExperimentError, Progress};

/// How a grid's cells run: what `reproduce` and `study` share beside their conditions.
#[derive(Debug, Clone)]
pub struct GridSettings {
    /// Per run.
    pub time_limit: Duration,
    /// Fast Downward, to run the same grid on it beside demoplan.
    pub fast_downward: Option<FastDownward>,
    /// How to measure demoplan's peak heap per run.
    pub memory: Option<MemoryProbe>,
    /// Heap bytes per run, on top of what the process holds when the run starts
    /// (`None`: no limit); a run that reaches it is recorded as `memory`.
    pub memory_limit: Option<u64>,
    /// Run the cells in child processes, several at a time; `None` runs them here,
    /// one after another.
    pub children: Option<CellCommand>,
    /// Compute every cell again, even those with a result in the folder.
    pub force: bool,
    /// Compute nothing: build the report from the results in the folder (a cluster's
    /// collect job); cells without one are an error naming them.
    pub collect_only: bool,
}

impl GridSettings {
    /// Settings for a grid run here, one cell after another, with no memory limit.
    pub fn in_process(time_limit: Duration) -> GridSettings {
        GridSettings {
            time_limit,
            fast_downward: None,
            memory: None,
            memory_limit: None,
            children: None,
            force: false,
            collect_only: false,
        }
    }

    /// The lab that computes the cells, with the simulator's `params`.
    pub(crate) fn lab(&self, params: simulate::SimParams) -> Lab {
        Lab::new(
            params,
            self.fast_downward.clone(),
            self.memory,
            self.memory_limit,
        )
    }

    /// demoplan's planners, and Fast Downward's when it runs beside.
    pub(crate) fn planners(&self) -> Vec<Planner> {
        let mut planners = Planner::DEMOPLAN.to_vec();
        if self.fast_downward.is_some() {
            planners.extend(Planner::DEMOPLAN.map(Planner::with_fast_downward));
        }
        planners
    }

    /// Cells computed at once.
    pub(crate) fn at_once(&self) -> usize {
        self.children.as_ref().map_or(1, |c| c.jobs.max(1))
    }

    /// Runs the grid `cells` into `out` ([`run_grid`]), in `lab` or in child processes;
    /// with [`GridSettings::collect_only`], only [`collect`]s their results.
    pub(crate) fn run_or_collect(
        &self,
        lab: &mut Lab,
        cells: &[Cell],
        out: &Path,
        progress: &mut dyn FnMut(Progress<'_>),
        describe: &dyn Fn(&Cell) -> String,
    ) -> Result<GridRun, ExperimentError> {
        let runner = match &self.children {
            Some(command) => Runner::Children(command),
            None => Runner::InProcess(lab),
        };
        if self.collect_only {
            return Ok(GridRun {
                jobs: runner.jobs(),
                records: collect(out, cells)?,
                computed: 0,
                crashed: 0,
            });
        }
        run_grid(runner, cells, out, self.force, progress, describe)
    }

    /// Computes the cell `id` of `cells` in `lab`, into its run folder under `out`.
    pub(crate) fn run_cell(
        &self,
        lab: &mut Lab,
        cells: &[Cell],
        id: &str,
        out: &Path,
    ) -> Result<RunRecord, ExperimentError> {
        run_cell(lab, cells, id, &RunLayout::new(out), self.force)
    }
}

/// An experiment that is a grid: its name (the Slurm jobs'), its settings, its cells and
/// one cell computed alone.
pub trait GridExperiment {
    /// `reproduce`, `study`.
    const NAME: &'static str;
    fn settings(&self) -> &GridSettings;
    /// The cells, in their order.
    fn cells(&self) -> Result<Vec<Cell>, ExperimentError>;
    /// Computes the cell `id` in this process (what each child process does).
    fn cell(&self, id: &str) -> Result<RunRecord, ExperimentError>;
}

/// The limits of each planning run: a level of `solve`, a run of `reproduce` and
/// `study`. The time limit's default is the command's (`mut_arg` on its `Args`).
#[derive(Debug, Clone, PartialEq, Eq)]
#[cfg_attr(feature = "clap", derive(clap::Args))]
pub struct RunLimitArgs {
    /// Time limit per run, with Fast Downward's units (`60`, `60s`, `2m`).
    #[cfg_attr(feature = "clap", arg(long, value_name = "TIME"))]
    pub time_limit: Option<String>,
    /// Memory limit per run, on the heap the run allocates, in binary units (`512M`,
    /// `2G`; bytes without a unit). `auto`: the memory available at the start, shared by
    /// the runs going at once; `infinity`: none. A run that reaches it stops with the
    /// outcome `memory`.
    #[cfg_attr(
        feature = "clap",
        arg(
            long,
            value_name = "MEMORY",
            default_value = "auto",
            overrides_with = "memory_limit"
        )
    )]
    pub memory_limit: String,
}

impl RunLimitArgs {
    /// The time limit (Fast Downward's units; none or `infinity`: `None`).
    pub fn time(&self) -> Result<Option<Duration>, ExperimentError> {
        let text = self.time_limit.as_deref().unwrap_or("infinity");
        task::units::parse_time_limit(text).map_err(named_option("--time-limit"))
    }

    /// The memory limit of each of `runs_at_once` runs ([`memory_limit`]: `auto` is
    /// shared by them, or fixed on a grid written for Slurm, `slurm`).
    pub fn memory(&self, runs_at_once: usize, slurm: bool) -> Result<Option<u64>, ExperimentError> {
        memory_limit(&self.memory_limit, runs_at_once, slurm)
            .map_err(named_option("--memory-limit"))
    }
}

/// An option's error, named: `--NAME: error`.
pub(crate) fn named_option(name: &str) -> impl Fn(String) -> ExperimentError + '_ {
    move |e| ExperimentError::Options(format!("{name}: {e}"))
}

/// Fast Downward run beside demoplan (`reproduce`, `study`).
#[derive(Debug, Clone, Default, PartialEq, Eq)]
#[cfg_attr(feature = "clap", derive(clap::Args))]
pub struct FastDownwardArgs {
    /// Run the same grid with Fast Downward beside demoplan.
    #[cfg_attr(feature = "clap", arg(long))]
    pub with_fd: bool,
    /// Fast Downward's fast-downward.py (else the DEMOPLAN_FD environment variable).
    #[cfg_attr(feature = "clap", arg(long, value_name = "PATH", requires = "with_fd"))]
    pub fd: Option<PathBuf>,
}

/// A grid's options (`reproduce`, `study`; docs/grids.md).
#[derive(Debug, Clone, Default, PartialEq, Eq)]
#[cfg_attr(feature = "clap", derive(clap::Args))]
pub struct GridArgs {
    /// Cells at once, each a child process of its own (default: the number of cores).
    #[cfg_attr(feature = "clap", arg(short = 'j', long = "jobs", value_name = "N", value_parser = clap::value_parser!(u32).range(1..=256)))]
    pub jobs: Option<u32>,
    /// Compute only the cell with this id into its run folder under -o DIR, and print
    /// its record as one JSON line (what each child process does).
    #[cfg_attr(feature = "clap", arg(long, value_name = "ID"))]
    pub cell: Option<String>,
    /// Compute every cell again, even those with a result in -o DIR.
    #[cfg_attr(feature = "clap", arg(long))]
    pub force: bool,
    /// Print the cells (task, id, Lab's names, conditions) and run nothing.
    #[cfg_attr(feature = "clap", arg(long))]
    pub list_cells: bool,
}

/// The grid as Slurm jobs (`reproduce`, `study`; docs/grids.md).
#[derive(Debug, Clone, Default, PartialEq, Eq)]
#[cfg_attr(feature = "clap", derive(clap::Args))]
pub struct SlurmArgs {
    /// Write the grid as Slurm array jobs into DIR (scripts and logs; the results go to
    /// -o DIR) and run nothing: `bash DIR/submit.sh` submits them.
    #[cfg_attr(feature = "clap", arg(long, value_name = "DIR"))]
    pub slurm: Option<PathBuf>,
    /// `sbatch --partition` (default: none, the cluster's default partition).
    #[cfg_attr(feature = "clap", arg(long, value_name = "NAME", requires = "slurm"))]
    pub slurm_partition: Option<String>,
    /// `sbatch --cpus-per-task`.
    #[cfg_attr(
        feature = "clap",
        arg(long, value_name = "N", default_value_t = 1, requires = "slurm")
    )]
    pub slurm_cpus_per_task: u32,
    /// `sbatch --mem` (default: the memory limit plus 512M).
    #[cfg_attr(feature = "clap", arg(long, value_name = "MEMORY", requires = "slurm", value_parser = super::slurm::parse_mem))]
    pub slurm_mem: Option<u64>,
    /// `sbatch --time` of an array task (default: the time limit plus a margin, times
    /// the cells per task).
    #[cfg_attr(feature = "clap", arg(long, value_name = "TIME", requires = "slurm", value_parser = super::slurm::parse_time))]
    pub slurm_time: Option<Duration>,
    /// Cells per array task (default: as few as keep the array within 1000 tasks).
    #[cfg_attr(feature = "clap", arg(long, value_name = "N", requires = "slurm", value_parser = clap::value_parser!(u32).range(1..)))]
    pub slurm_cells_per_task: Option<u32>,
    /// Array tasks running at once, at most (K of `--array=1-N%K`).
    #[cfg_attr(feature = "clap", arg(long, value_name = "K", default_value_t = 100, requires = "slurm", value_parser = clap::value_parser!(u32).range(1..)))]
    pub slurm_max_running: u32,
    /// Seed of the shuffle that deals the cells to the array tasks.
    #[cfg_attr(
        feature = "clap",
        arg(long, value_name = "N", default_value_t = 1, requires = "slurm")
    )]
    pub slurm_seed: u64,
    /// A further `sbatch` option for every job, e.g. `--slurm-sbatch=--account=NAME`.
    #[cfg_attr(feature = "clap", arg(long, value_name = "OPTION", requires = "slurm"))]
    pub slurm_sbatch: Vec<String>,
    /// Compute nothing: build the report from the results in -o DIR (what the Slurm
    /// collect job runs; cells without a result are an error naming them).
    #[cfg_attr(feature = "clap", arg(long, hide = true))]
    pub collect: bool,
}

impl SlurmArgs {
    /// `--slurm DIR`, unless this is the collect job (which runs nothing on Slurm).
    fn writing(&self) -> Option<&Path> {
        self.slurm.as_deref().filter(|_| !self.collect)
    }

    /// The options of the jobs written into `dir`.
    fn options(&self, dir: &Path) -> SlurmOptions {
        SlurmOptions {
            partition: self.slurm_partition.clone(),
            cpus_per_task: self.slurm_cpus_per_task,
            mem: self.slurm_mem,
            time: self.slurm_time,
            cells_per_task: self.slurm_cells_per_task.map(|n| n as usize),
            max_running: self.slurm_max_running as usize,
            seed: self.slurm_seed,
            sbatch: self.slurm_sbatch.clone(),
            ..SlurmOptions::new(dir)
        }
    }
}

impl GridArgs {
    /// The settings these options ask for, with the run `limits` (no time limit is one
    /// too far to reach; `auto` memory is shared by the cells at once, or fixed on a grid
    /// written for Slurm): the cells run as child processes of `this` program, their
    /// peak heap counted. A limit that does not parse or a Fast Downward not found is
    /// an [`ExperimentError::Options`] naming the option.
    pub fn settings(
        &self,
        slurm: &SlurmArgs,
        fast_downward: &FastDownwardArgs,
        limits: &RunLimitArgs,
        this: &Relaunch,
    ) -> Result<GridSettings, ExperimentError> {
        let jobs = jobs(self.jobs);
        let memory_limit = limits.memory(jobs, slurm.writing().is_some())?;
        let time_limit = limits.time()?;
        let time_limit = time_limit.unwrap_or(Duration::from_secs(u64::from(u32::MAX)));
        let fast_downward = match fast_downward.with_fd {
            true => Some(
                FastDownward::locate(fast_downward.fd.as_deref())
                    .map_err(ExperimentError::Options)?,
            ),
            false => None,
        };
        Ok(GridSettings {
            time_limit,
            fast_downward,
            memory: Some(MemoryProbe::counting()),
            memory_limit,
            children: Some(this.cells(jobs, memory_limit)),
            force: self.force,
            collect_only: slurm.collect,
        })
    }

    /// What the grid command does instead of running `experiment`'s grid: `--list-cells`
    /// (the cell list), `--cell ID` (that cell computed, its record as one JSON line),
    /// `--slurm DIR` (the jobs written to run `this` program, and their summary): the
    /// text to print. `None`: run the grid.
    pub fn instead_of_grid<E: GridExperiment>(
        &self,
        slurm: &SlurmArgs,
        experiment: &E,
        this: &Relaunch,
    ) -> Option<Result<String, ExperimentError>> {
        let list = || experiment.cells();
        let compute = |id: &str| experiment.cell(id);
        if let Some(done) = cell_or_list(self.list_cells, self.cell.as_deref(), list, compute) {
            return Some(done);
        }
        let dir = slurm.writing()?;
        let memory_limit = experiment.settings().memory_limit;
        let job = experiment
            .cells()
            .and_then(|cells| this.write_slurm(E::NAME, &cells, memory_limit, &slurm.options(dir)));
        Some(job.map(|job| job.summary()))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::ffi::OsString;

    fn this() -> Relaunch {
        Relaunch::new(&[OsString::from("demoplan")], &[OsString::from("study")]).unwrap()
    }

    fn limits(time: Option<&str>, memory: &str) -> RunLimitArgs {
        RunLimitArgs {
            time_limit: time.map(str::to_string),
            memory_limit: memory.to_string(),
        }
    }

    #[test]
    fn the_options_become_the_settings_of_child_processes() {
        let grid = GridArgs {
            jobs: Some(3),
            force: true,
            ..GridArgs::default()
        };
        let fd = FastDownwardArgs::default();
        let s = grid
            .settings(
                &SlurmArgs::default(),
                &fd,
                &limits(Some("2m"), "1G"),
                &this(),
            )
            .unwrap();
        assert_eq!(s.time_limit, Duration::from_secs(120));
        assert_eq!(s.memory_limit, Some(1 << 30));
        assert!(s.force && !s.collect_only && s.fast_downward.is_none());
        let children = s.children.unwrap();
        assert_eq!(children.jobs, 3);
        assert_eq!(children.args.last().unwrap(), "1073741824");
        // No time limit is a very long one; `infinity` no memory limit.
        let s = grid
            .settings(
                &SlurmArgs::default(),
                &fd,
                &limits(None, "infinity"),
                &this(),
            )
            .unwrap();
        assert_eq!(s.time_limit, Duration::from_secs(u64::from(u32::MAX)));
        assert_eq!(s.memory_limit, None);
    }

    #[test]
    fn bad_limits_name_their_option() {
        let grid = GridArgs::default();
        let fd = FastDownwardArgs::default();
        let slurm = SlurmArgs::default();
        let e = grid
            .settings(&slurm, &fd, &limits(Some("soon"), "1G"), &this())
            .unwrap_err();
        assert!(e.to_string().starts_with("--time-limit: "), "{e}");
        let e = grid
            .settings(&slurm, &fd, &limits(None, "lots"), &this())
            .unwrap_err();
        assert!(e.to_string().starts_with("--memory-limit: "), "{e}");
        let missing = FastDownwardArgs {
            with_fd: true,
            fd: Some("/no/such/fast-downward.py".into()),
        };
        let e = grid
            .settings(&slurm, &missing, &limits(None, "1G"), &this())
            .unwrap_err();
        assert!(e.to_string().contains("Fast Downward not found"), "{e}");
        assert_eq!(e.exit_code(), slim::ExitCode::USAGE);
    }

    #[test]
    fn auto_is_the_fixed_slurm_default_only_when_jobs_are_written() {
        let grid = GridArgs::default();
        let fd = FastDownwardArgs::default();
        let writing = SlurmArgs {
            slurm: Some("jobs".into()),
            ..SlurmArgs::default()
        };
        let s = grid
            .settings(&writing, &fd, &limits(None, "auto"), &this())
            .unwrap();
        assert_eq!(s.memory_limit, Some(super::super::slurm::AUTO_MEMORY_LIMIT));
        // The collect job runs nothing on Slurm; it collects.
        let collecting = SlurmArgs {
            collect: true,
            ..writing
        };
        assert_eq!(collecting.writing(), None);
        let s = grid
            .settings(&collecting, &fd, &limits(None, "2G"), &this())
            .unwrap();
        assert!(s.collect_only);
    }
}
