//! `demoplan check [DOMAIN] PROBLEM`: parse, check, summarise.

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
    let domain_file = domain_path.display().to_string();
    match problem_path {
        None => {
            let domain = input::read_domain(&domain_path)?;
            print!("{}", pddl::summary_text(&domain, &domain_file, None));
        }
        Some(problem_path) => {
            let task = input::read_task(&domain_path, &problem_path)?;
            let problem_file = problem_path.display().to_string();
            let problem = Some((&task.problem, problem_file.as_str()));
            let text = pddl::summary_text(&task.domain, &domain_file, problem);
            if task.problem.domain.text != task.domain.name.text {
                eprintln!(
                    "warning: {problem_file} names domain `{}`, but {domain_file} defines `{}`",
                    task.problem.domain.text, task.domain.name.text
                );
            }
            print!("{text}");
        }
    }
    Ok(ExitCode::SUCCESS)
}
