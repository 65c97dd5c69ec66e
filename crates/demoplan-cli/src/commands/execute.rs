//! `demoplan execute DOMAIN PROBLEM PLAN`: the execution check in the cube world, step
//! by step, with the plan and poses as JSON and the frames as a recording on request.

use std::path::{Path, PathBuf};

use crate::diagnostic::Failure;
use crate::exit::ExitCode;
use crate::input;
use crate::output::{write_atomically, write_atomically_with};

/// The arguments of `execute`.
#[derive(Debug)]
pub struct ExecuteArgs {
    pub domain: PathBuf,
    pub problem: PathBuf,
    pub plan: PathBuf,
    pub json: Option<PathBuf>,
    pub frames: Option<PathBuf>,
}

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
    let mut out = String::new();
    if !report.initial_missing.is_empty() {
        out.push_str(&format!(
            "warning: the cube world's initial state lacks {}\n",
            report.initial_missing.join(" ")
        ));
    }
    for s in &report.steps {
        let head = format!("step {} {}", s.index, s.action_text());
        for u in &s.unmet_preconditions {
            out.push_str(&format!(
                "{head}: warning: precondition {u} does not hold in the plan's state\n"
            ));
        }
        if s.ok() {
            out.push_str(&format!("{head}: ok\n"));
        } else {
            let expected: Vec<String> = s
                .failed
                .iter()
                .map(|f| {
                    if f.expected {
                        f.fact.clone()
                    } else {
                        format!("(not {})", f.fact)
                    }
                })
                .collect();
            let mut why = Vec::new();
            if !expected.is_empty() {
                why.push(format!(
                    "expected {}, grounded state has {}",
                    expected.join(" "),
                    if s.grounded.is_empty() {
                        "nothing over its objects".to_string()
                    } else {
                        s.grounded.join(" ")
                    }
                ));
            }
            if !s.collisions.is_empty() {
                why.push(format!(
                    "its motion moves things through each other: {}",
                    s.collisions.join(" ")
                ));
            }
            out.push_str(&format!("{head}: FAILED: {}\n", why.join("; ")));
        }
    }
    if let Some(i) = report.first_failure() {
        let s = &report.steps[i];
        out.push_str(&format!(
            "first failing step: {} {} ({} to {} s; motion: {})\n",
            s.index,
            s.action_text(),
            s.start,
            s.end,
            s.primitives.join(", ")
        ));
    }
    if report.goal.reached {
        out.push_str("goal reached\n");
    } else {
        out.push_str(&format!(
            "goal not reached: {} not in the final grounded state\n",
            report.goal.unsatisfied.join(" ")
        ));
    }
    print!("{out}");
    if let Some(path) = &args.json {
        let mut text =
            serde_json::to_string_pretty(&cubeworld::export(&report)).unwrap_or_default();
        text.push('\n');
        write_atomically(path, &text)?;
    }
    if let Some(path) = &args.frames {
        write_frames(path, &report.recording)?;
    }
    Ok(if report.success() {
        ExitCode::SUCCESS
    } else {
        ExitCode::CHECK_FAILED
    })
}

fn write_frames(path: &Path, rec: &recording::Recording) -> Result<(), Failure> {
    write_atomically_with(path, |out| {
        let mut writer = recording::Writer::new(out, &rec.header).map_err(std::io::Error::other)?;
        for f in &rec.frames {
            writer.write_frame(f).map_err(std::io::Error::other)?;
        }
        writer.finish().map_err(std::io::Error::other)?;
        Ok(())
    })
}
