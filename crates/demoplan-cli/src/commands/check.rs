//! `demoplan check [DOMAIN] PROBLEM`: parse, check, summarise.

use std::path::Path;

use crate::cli::CheckArgs;
use crate::diagnostic::Failure;
use crate::input;
use slim::ExitCode;

pub fn run(args: CheckArgs) -> Result<ExitCode, Failure> {
    let (domain_path, problem_path) = match args.files.as_slice() {
        [domain, problem] => (domain.clone(), Some(problem.clone())),
        [single] => {
            let source = input::read_text(single)?;
            match pddl::parse_file(&source) {
                Ok(parsed) if matches!(parsed.content, pddl::PddlFile::Domain(_)) => {
                    (single.clone(), None)
                }
                Ok(_) => (input::find_domain_file(single)?, Some(single.clone())),
                Err(e) => return Err(Failure::pddl(single, &source, &e)),
            }
        }
        _ => return Err(Failure::plain(ExitCode::USAGE, "expected [DOMAIN] PROBLEM")),
    };
    let mut out = String::new();
    match problem_path {
        None => {
            let domain = input::read_domain(&domain_path)?;
            summarise_domain(&mut out, &domain_path, &domain, None);
        }
        Some(problem_path) => {
            let task = input::read_task(&domain_path, &problem_path)?;
            summarise_domain(&mut out, &domain_path, &task.domain, Some(&task.problem));
            summarise_problem(&mut out, &problem_path, &task.problem);
            if task.problem.domain.text != task.domain.name.text {
                eprintln!(
                    "warning: {} names domain `{}`, but {} defines `{}`",
                    problem_path.display(),
                    task.problem.domain.text,
                    domain_path.display(),
                    task.domain.name.text
                );
            }
        }
    }
    print!("{out}");
    Ok(ExitCode::SUCCESS)
}

fn line(out: &mut String, key: &str, value: impl std::fmt::Display) {
    out.push_str(&format!("{key:<22} {value}\n"));
}

fn summarise_domain(out: &mut String, path: &Path, d: &pddl::Domain, p: Option<&pddl::Problem>) {
    line(
        out,
        "domain",
        format!("{} ({})", d.name.text, path.display()),
    );
    for (key, value) in d.summary(p) {
        line(out, key, value);
    }
}

fn summarise_problem(out: &mut String, path: &Path, p: &pddl::Problem) {
    line(
        out,
        "problem",
        format!("{} ({})", p.name.text, path.display()),
    );
    for (key, value) in p.summary() {
        line(out, key, value);
    }
}
