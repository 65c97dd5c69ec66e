//! The IPC benchmark suite demoplan is tested and measured on.
//!
//! The suite lives outside the repository (its licences forbid copying some files in):
//! `DEMOPLAN_BENCHMARKS` names the folder; a relative path, and the default
//! `../shared/benchmarks`, are taken relative to the workspace root. A missing folder is an
//! error, never a reason to skip a test.
//!
//! ```no_run
//! let suite = benchmarks::Suite::locate()?;
//! for instance in suite.instances()? {
//!     println!("{} {} {}", instance.domain, instance.name, instance.optimal_cost);
//! }
//! # Ok::<(), String>(())
//! ```

use std::path::{Path, PathBuf};

/// One instance of `optimal_costs.csv`.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Instance {
    /// The benchmark domain's folder name, e.g. `blocks`.
    pub domain: String,
    /// The instance name, e.g. `probBLOCKS-4-0`.
    pub name: String,
    /// Absolute path of the domain file.
    pub domain_file: PathBuf,
    /// Absolute path of the problem file.
    pub problem_file: PathBuf,
    /// The known optimal plan cost.
    pub optimal_cost: u64,
}

/// The benchmark folder.
#[derive(Debug, Clone)]
pub struct Suite {
    root: PathBuf,
}

impl Suite {
    /// Finds the suite from `DEMOPLAN_BENCHMARKS` or the default `../shared/benchmarks`.
    pub fn locate() -> Result<Suite, String> {
        let workspace = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
        let configured = std::env::var_os("DEMOPLAN_BENCHMARKS")
            .map(PathBuf::from)
            .unwrap_or_else(|| PathBuf::from("../shared/benchmarks"));
        let root = if configured.is_absolute() {
            configured
        } else {
            workspace.join(configured)
        };
        let root = root.canonicalize().map_err(|e| {
            format!(
                "benchmark folder {} not found ({e}); set DEMOPLAN_BENCHMARKS to the folder with \
                 optimal_costs.csv",
                root.display()
            )
        })?;
        if !root.join("optimal_costs.csv").is_file() {
            return Err(format!("{} has no optimal_costs.csv", root.display()));
        }
        Ok(Suite { root })
    }

    /// The folder.
    pub fn root(&self) -> &Path {
        &self.root
    }

    /// The instances of `optimal_costs.csv`, in file order.
    pub fn instances(&self) -> Result<Vec<Instance>, String> {
        let path = self.root.join("optimal_costs.csv");
        let text =
            std::fs::read_to_string(&path).map_err(|e| format!("{}: {e}", path.display()))?;
        let mut lines = text.lines().enumerate();
        let header = lines.next().map(|(_, l)| l).unwrap_or_default();
        let columns: Vec<&str> = header.split(',').collect();
        let col = |name: &str| {
            columns
                .iter()
                .position(|c| *c == name)
                .ok_or_else(|| format!("{}: no column `{name}`", path.display()))
        };
        let (domain, instance, domain_file, problem_file, cost) = (
            col("domain")?,
            col("instance")?,
            col("domain_file")?,
            col("problem_file")?,
            col("optimal_cost")?,
        );
        let mut out = Vec::new();
        for (index, line) in lines {
            if line.trim().is_empty() {
                continue;
            }
            let fields: Vec<&str> = line.split(',').collect();
            let field = |i: usize| {
                fields
                    .get(i)
                    .copied()
                    .ok_or_else(|| format!("{}:{}: too few fields", path.display(), index + 1))
            };
            out.push(Instance {
                domain: field(domain)?.to_string(),
                name: field(instance)?.to_string(),
                domain_file: self.root.join(field(domain_file)?),
                problem_file: self.root.join(field(problem_file)?),
                optimal_cost: field(cost)?
                    .parse()
                    .map_err(|e| format!("{}:{}: optimal_cost: {e}", path.display(), index + 1))?,
            });
        }
        Ok(out)
    }

    /// The instance `name` of `domain` in `optimal_costs.csv`.
    pub fn instance(&self, domain: &str, name: &str) -> Result<Instance, String> {
        self.instances()?
            .into_iter()
            .find(|i| i.domain == domain && i.name == name)
            .ok_or_else(|| format!("{domain}/{name} is not in the benchmark suite"))
    }

    /// Every `.pddl` file below `downward-benchmarks`, sorted.
    pub fn pddl_files(&self) -> Result<Vec<PathBuf>, String> {
        let mut out = Vec::new();
        let mut dirs = vec![self.root.join("downward-benchmarks")];
        while let Some(dir) = dirs.pop() {
            let entries = std::fs::read_dir(&dir).map_err(|e| format!("{}: {e}", dir.display()))?;
            for entry in entries {
                let path = entry.map_err(|e| format!("{}: {e}", dir.display()))?.path();
                if path.is_dir() {
                    dirs.push(path);
                } else if path.extension().is_some_and(|x| x == "pddl") {
                    out.push(path);
                }
            }
        }
        out.sort();
        Ok(out)
    }
}
