//! What a grid command does around its grid, given the command line it was run with:
//! the cells' child processes, `--list-cells`, `--cell ID`, `--slurm DIR`, and the
//! memory limit every cell gets. The CLI parses the options and calls these.

use super::cell_list;
use super::children::CellCommand;
use super::slurm::{write_job, GridCommand, SlurmJob, SlurmOptions, AUTO_MEMORY_LIMIT};
use crate::cell::Cell;
use crate::record::RunRecord;
use crate::ExperimentError;
use std::ffi::OsString;

/// The command that runs this program again (`demoplan`, or `python -m demoplan` from
/// the Python package) and the grid's command line after it: each cell runs as
/// `program... args... --cell ID`.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Relaunch {
    program: OsString,
    args: Vec<OsString>,
}

impl Relaunch {
    /// `program` (the executable, then its own arguments) and `argv` (the grid's
    /// arguments, without the program's name). An empty `program` is an error: there
    /// is nothing to run the cells with.
    pub fn new(program: &[OsString], argv: &[OsString]) -> Result<Relaunch, ExperimentError> {
        let (first, rest) = program.split_first().ok_or_else(|| {
            ExperimentError::Options(
                "no program to run demoplan again with (the command is empty)".into(),
            )
        })?;
        Ok(Relaunch {
            program: first.clone(),
            args: rest.iter().chain(argv).cloned().collect(),
        })
    }

    /// How the cells run, `jobs` at a time, each a child process with the memory limit
    /// this process resolved (the last `--memory-limit` wins: `auto` again in a child
    /// would count its siblings).
    pub fn cells(&self, jobs: usize, memory_limit: Option<u64>) -> CellCommand {
        CellCommand {
            program: self.program.clone().into(),
            args: self
                .args
                .iter()
                .cloned()
                .chain(["--memory-limit".into(), limit_arg(memory_limit).into()])
                .collect(),
            jobs,
        }
    }

    /// `--slurm`: writes the grid `cells` (named `name`: `study`, `reproduce`) as Slurm
    /// jobs, to run in the current folder.
    pub fn write_slurm(
        &self,
        name: &str,
        cells: &[Cell],
        memory_limit: Option<u64>,
        options: &SlurmOptions,
    ) -> Result<SlurmJob, ExperimentError> {
        let workdir = std::env::current_dir()
            .map_err(|e| ExperimentError::Options(format!("--slurm: {e}")))?;
        let command = GridCommand {
            program: self.program.clone().into(),
            args: self.args.clone(),
            workdir,
            name: name.into(),
            memory_limit,
        };
        write_job(cells, &command, options)
    }
}

fn limit_arg(memory_limit: Option<u64>) -> String {
    memory_limit.map_or("infinity".to_string(), |b| b.to_string())
}

/// Cells at once: `-j N`, else the number of cores.
pub fn jobs(option: Option<u32>) -> usize {
    option.map_or_else(
        || std::thread::available_parallelism().map_or(1, usize::from),
        |n| n as usize,
    )
}

/// Each cell's memory limit: `text` (`--memory-limit`: `auto`, `infinity` or a size).
/// `auto` is what the machine has free, shared by `jobs` cells
/// ([`crate::auto_memory_limit`]), except on a grid written for Slurm (`slurm`), where
/// it is [`AUTO_MEMORY_LIMIT`]: the memory free where the jobs are written says
/// nothing about the nodes.
pub fn memory_limit(text: &str, jobs: usize, slurm: bool) -> Result<Option<u64>, String> {
    if text.trim().eq_ignore_ascii_case("auto") {
        return Ok(if slurm {
            Some(AUTO_MEMORY_LIMIT)
        } else {
            crate::auto_memory_limit(jobs)
        });
    }
    task::units::parse_memory_limit(text)
}

/// What a grid command does before its grid: `--list-cells` (`list`) is the cell list,
/// `--cell ID` (`cell`) computes that cell and is its record as one JSON line; `None`
/// when neither is asked for, and the grid runs.
pub fn cell_or_list(
    list: bool,
    cell: Option<&str>,
    cells: impl FnOnce() -> Result<Vec<Cell>, ExperimentError>,
    compute: impl FnOnce(&str) -> Result<RunRecord, ExperimentError>,
) -> Option<Result<String, ExperimentError>> {
    if list {
        return Some(cells().map(|c| cell_list(&c)));
    }
    let id = cell?;
    Some(compute(id).map(|r| r.to_json_line() + "\n"))
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::path::Path;

    fn os(items: &[&str]) -> Vec<OsString> {
        items.iter().map(OsString::from).collect()
    }

    #[test]
    fn an_empty_program_is_an_error_not_a_panic() {
        let e = Relaunch::new(&[], &os(&["study"])).unwrap_err();
        assert!(e.to_string().contains("no program"), "{e}");
    }

    #[test]
    fn cells_run_the_program_again_with_the_resolved_memory_limit() {
        let again = Relaunch::new(
            &os(&["python", "-m", "demoplan"]),
            &os(&["study", "-j", "2"]),
        )
        .unwrap();
        let command = again.cells(2, Some(1024));
        assert_eq!(command.program, Path::new("python"));
        assert_eq!(
            command.args,
            os(&[
                "-m",
                "demoplan",
                "study",
                "-j",
                "2",
                "--memory-limit",
                "1024"
            ])
        );
        assert_eq!(command.jobs, 2);
        let unlimited = again.cells(1, None);
        assert_eq!(unlimited.args.last().unwrap(), "infinity");
    }

    #[test]
    fn auto_on_slurm_is_the_fixed_default() {
        assert_eq!(memory_limit("auto", 4, true), Ok(Some(AUTO_MEMORY_LIMIT)));
        assert_eq!(memory_limit(" AUTO ", 4, true), Ok(Some(3 << 30)));
        assert_eq!(memory_limit("2G", 4, true), Ok(Some(2 << 30)));
        assert_eq!(memory_limit("infinity", 1, false), Ok(None));
        assert!(memory_limit("lots", 1, false).is_err());
    }

    #[test]
    fn list_and_cell_come_before_the_grid() {
        let none = cell_or_list(false, None, || panic!("no list"), |_| panic!("no cell"));
        assert!(none.is_none());
        let listed = cell_or_list(true, Some("x"), || Ok(Vec::new()), |_| panic!("no cell"));
        assert_eq!(
            listed.unwrap().unwrap(),
            "task\tid\talgorithm\tdomain\tproblem\tconditions\n"
        );
        let failed = cell_or_list(
            false,
            Some("abc"),
            || panic!("no list"),
            |id| Err(ExperimentError::Options(format!("--cell {id}: none"))),
        );
        assert!(failed.unwrap().is_err());
    }
}
