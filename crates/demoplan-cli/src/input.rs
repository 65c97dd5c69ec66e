//! Reading input files named on the command line.

use std::path::{Path, PathBuf};

use crate::diagnostic::Failure;
use simulate::{SimParams, Style};
use slim::ExitCode;

/// Reads a text file; a missing or unreadable file is a command line error (exit 36).
pub fn read_text(path: &Path) -> Result<String, Failure> {
    std::fs::read(path)
        .map_err(|e| {
            Failure::plain(
                ExitCode::USAGE,
                format!("cannot read {}: {e}", path.display()),
            )
        })
        .and_then(|bytes| {
            String::from_utf8(bytes).map_err(|e| {
                Failure::plain(
                    ExitCode::INPUT_ERROR,
                    format!(
                        "{}: not UTF-8 text (byte {})",
                        path.display(),
                        e.utf8_error().valid_up_to()
                    ),
                )
            })
        })
}

/// The `--params` file's (JSON) simulator parameters over the `style`'s. Not one: exit 36.
pub fn sim_params(path: Option<&Path>, style: Option<Style>) -> Result<SimParams, Failure> {
    let text = path.map(read_text).transpose()?;
    let name = path.map_or(String::new(), |p| p.display().to_string());
    SimParams::from_json_text(text.as_deref().unwrap_or("{}"), style)
        .map_err(|e| format!("{name}: not a parameter file: {e}"))
        .map_err(|m| Failure::plain(ExitCode::USAGE, m))
}

/// Finds the domain file of a problem by Fast Downward's naming rules
/// ([`pddl::find_domain_file`]); none is a command line error (36).
pub fn find_domain_file(problem: &Path) -> Result<PathBuf, Failure> {
    pddl::find_domain_file(problem, Path::is_file).map_err(|e| Failure::plain(ExitCode::USAGE, e))
}

/// A domain and problem read, parsed and checked against each other.
#[derive(Debug)]
pub struct Task {
    /// The domain.
    pub domain: pddl::Domain,
    /// The problem.
    pub problem: pddl::Problem,
}

/// Reads and checks a domain and problem.
pub fn read_task(domain_path: &Path, problem_path: &Path) -> Result<Task, Failure> {
    let domain = read_domain(domain_path)?;
    let problem_source = read_text(problem_path)?;
    let problem = pddl::parse_problem(&problem_source)
        .and_then(|p| pddl::check_problem(&domain, &p).map(|()| p))
        .map_err(|e| Failure::pddl(problem_path, &problem_source, &e))?;
    Ok(Task { domain, problem })
}

/// Reads and checks a domain.
pub fn read_domain(path: &Path) -> Result<pddl::Domain, Failure> {
    let source = read_text(path)?;
    pddl::parse_domain(&source).map_err(|e| Failure::pddl(path, &source, &e))
}
