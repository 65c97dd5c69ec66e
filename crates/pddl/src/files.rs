//! Fast Downward's naming rules for the domain file of a problem given alone. The crate
//! does no I/O: it names the candidates, and the caller takes the first that exists.

use std::path::{Path, PathBuf};

/// The files that may be the domain of `problem`, in the order Fast Downward's driver
/// tries them, all beside the problem: `domain.pddl`, `NAME-domain.pddl`, the first
/// three characters of the problem's name followed by `-domain.pddl` (airport's
/// `p01-domain.pddl`), `domain_NAME.pddl`, `domain-NAME.pddl`.
pub fn domain_file_candidates(problem: &Path) -> Vec<PathBuf> {
    let dir = problem.parent().unwrap_or(Path::new(""));
    let lossy = |s: Option<&std::ffi::OsStr>| s.map(|n| n.to_string_lossy().into_owned());
    let name = lossy(problem.file_name()).unwrap_or_default();
    let stem = lossy(problem.file_stem()).unwrap_or_default();
    let suffix = lossy(problem.extension()).map_or(String::new(), |e| format!(".{e}"));
    let prefix: String = name.chars().take(3).collect();
    [
        "domain.pddl".to_string(),
        format!("{stem}-domain{suffix}"),
        format!("{prefix}-domain.pddl"),
        format!("domain_{name}"),
        format!("domain-{name}"),
    ]
    .iter()
    .map(|c| dir.join(c))
    .collect()
}

/// No domain file beside a problem given alone: the candidates tried, by name.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error(
    "could not find the domain file of {} using the naming rules (tried {}); name it on \
     the command line",
    problem.display(),
    tried.join(", ")
)]
pub struct NoDomainFile {
    pub problem: PathBuf,
    /// The candidates' file names, in the order tried.
    pub tried: Vec<String>,
}

/// The domain file of `problem`: the first of [`domain_file_candidates`] that `exists`
/// says is a file (the caller looks; the crate does no I/O).
pub fn find_domain_file(
    problem: &Path,
    exists: impl Fn(&Path) -> bool,
) -> Result<PathBuf, NoDomainFile> {
    let candidates = domain_file_candidates(problem);
    if let Some(found) = candidates.iter().find(|p| exists(p)) {
        return Ok(found.clone());
    }
    Err(NoDomainFile {
        problem: problem.to_path_buf(),
        tried: (candidates.iter().filter_map(|c| c.file_name()))
            .map(|n| n.to_string_lossy().into_owned())
            .collect(),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn candidates_follow_fast_downwards_rules() {
        let names: Vec<PathBuf> = domain_file_candidates(Path::new("ipc/airport/p01-airport.pddl"));
        let expected = [
            "domain.pddl",
            "p01-airport-domain.pddl",
            "p01-domain.pddl",
            "domain_p01-airport.pddl",
            "domain-p01-airport.pddl",
        ];
        assert_eq!(
            names,
            expected.map(|n| Path::new("ipc/airport").join(n)).to_vec()
        );
        assert_eq!(
            domain_file_candidates(Path::new("task"))[1],
            Path::new("task-domain")
        );
        let beside = |p: &Path| p == Path::new("ipc/p01-domain.pddl");
        let found = find_domain_file(Path::new("ipc/p01.pddl"), beside);
        assert_eq!(found, Ok(Path::new("ipc/p01-domain.pddl").to_path_buf()));
        let missing = find_domain_file(Path::new("ipc/p01.pddl"), |_| false).unwrap_err();
        assert_eq!(missing.tried[..2], ["domain.pddl", "p01-domain.pddl"]);
        assert!(missing
            .to_string()
            .contains("of ipc/p01.pddl using the naming rules"));
    }
}
