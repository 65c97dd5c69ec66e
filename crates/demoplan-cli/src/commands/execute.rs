//! `demoplan execute DOMAIN PROBLEM PLAN`: the execution check in the cube world, step
//! by step, with the plan and poses as JSON and the frames as a recording on request.

use crate::cli::ExecuteArgs;
use crate::diagnostic::Failure;
use crate::input;
use crate::output::{write_atomically, write_atomically_with};
use slim::ExitCode;

pub fn run(args: ExecuteArgs) -> Result<ExitCode, Failure> {
    let task = input::read_task(&args.domain, &args.problem)?;
    let text = input::read_text(&args.plan)?;
    let plan = pddl::parse_plan(&text).map_err(|e| {
        Failure::plain(
            ExitCode::INPUT_ERROR,
            format!("{}:{}: {}", args.plan.display(), e.line, e.kind),
        )
    })?;
    let report = cubeworld::execute(&task.domain, &task.problem, &plan.steps).map_err(|e| {
        Failure::plain(
            ExitCode::INPUT_ERROR,
            format!("{}: {e}", args.plan.display()),
        )
    })?;
    let out = report.text();
    print!("{out}");
    if let Some(path) = &args.json {
        let mut text =
            serde_json::to_string_pretty(&cubeworld::export(&report)).unwrap_or_default();
        text.push('\n');
        write_atomically(path, &text)?;
    }
    if let Some(path) = &args.frames {
        write_atomically_with(path, |out| {
            report
                .recording
                .write(out)
                .map(drop)
                .map_err(std::io::Error::other)
        })?;
    }
    Ok(if report.success() {
        ExitCode::SUCCESS
    } else {
        ExitCode::CHECK_FAILED
    })
}
