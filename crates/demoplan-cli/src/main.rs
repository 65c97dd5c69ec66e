//! The `demoplan` executable: parses the command line and hands each subcommand to the
//! library crates. It is the only place that touches files, processes and the terminal.

mod cli;
mod commands;
mod diagnostic;
mod exit;
mod input;
mod memory;
mod output;
mod progress;
mod recording_input;

use std::io::Write;

use clap::Parser;

#[global_allocator]
static ALLOCATOR: memory::CountingAllocator = memory::CountingAllocator;

use diagnostic::Failure;
use exit::ExitCode;

fn main() {
    stop_cleanly_when_stdout_fails();
    let code = match cli::Cli::try_parse() {
        Ok(cli) => match run(cli) {
            Ok(code) => code,
            Err(failure) => {
                let _ = std::io::stdout().flush();
                eprint!("{}", failure.text);
                failure.code
            }
        },
        Err(e) => {
            // Help and version are not errors. Anything else is Fast Downward's "driver
            // input error" (36): clap's own code 2 means "plan found, out of time" there.
            let _ = e.print();
            if e.use_stderr() {
                ExitCode::USAGE
            } else {
                ExitCode::SUCCESS
            }
        }
    };
    std::process::exit(code.0);
}

/// Rust ignores SIGPIPE, so printing to a closed pipe or a full disk panics inside
/// `println!`. A reader that stops early (`| head`) is no error: exit quietly with the
/// code a shell shows for SIGPIPE. Any other failure to write standard output is an I/O
/// error (35) with a message, not a panic report.
fn stop_cleanly_when_stdout_fails() {
    let default_hook = std::panic::take_hook();
    std::panic::set_hook(Box::new(move |info| {
        let text = info.to_string();
        if let Some(at) = text.find("failed printing to stdout: ") {
            if text.contains("Broken pipe") {
                std::process::exit(ExitCode::OUTPUT_CLOSED.0);
            }
            let cause = &text[at + "failed printing to stdout: ".len()..];
            eprintln!("error: cannot write to standard output: {}", cause.trim());
            std::process::exit(ExitCode::CRITICAL_ERROR.0);
        }
        default_hook(info);
    }));
}

fn run(cli: cli::Cli) -> Result<ExitCode, Failure> {
    match cli.command {
        cli::Command::Check { files } => commands::check::run(&files),
        cli::Command::Plan {
            files,
            search,
            alias,
            plan_file,
            overall_time_limit,
            overall_memory_limit,
            stats_json,
            validate,
        } => commands::plan::run(commands::plan::PlanArgs {
            files,
            search,
            alias,
            plan_file,
            time_limit: overall_time_limit,
            memory_limit: overall_memory_limit,
            stats_json,
            validate,
        }),
        cli::Command::Translate { files, sas_file } => commands::translate::run(&files, &sas_file),
        cli::Command::Fmt {
            files,
            check,
            stdout,
        } => commands::fmt::run(&files, check, stdout),
        cli::Command::Validate {
            domain,
            problem,
            plans,
        } => commands::validate::run(&domain, &problem, &plans),
        cli::Command::Simulate {
            out,
            participants,
            per_participant,
            seed,
            cubes,
            params,
        } => commands::simulate::run(commands::simulate::SimulateArgs {
            participants,
            per_participant,
            seed,
            out,
            params,
            cubes,
        }),
        cli::Command::Inspect { files, mapping } => {
            recording_input::use_mapping(mapping);
            commands::inspect::run(&files)
        }
        cli::Command::Import {
            sources,
            mapping,
            out,
            peak_heap,
        } => commands::import::run(commands::import::ImportArgs {
            sources,
            mapping,
            out,
            peak_heap,
        }),
        cli::Command::Segment {
            files,
            json,
            config,
            tree,
            mapping,
        } => {
            recording_input::use_mapping(mapping);
            commands::segment::run(commands::segment::SegmentArgs {
                files,
                json,
                config,
                tree,
            })
        }
        cli::Command::Classify {
            files,
            learn,
            out,
            tree,
            class,
            config,
            mapping,
        } => commands::classify::run(commands::classify::ClassifyArgs {
            files,
            tree,
            learn,
            out,
            class,
            config,
            mapping,
        }),
        cli::Command::Timeline {
            file,
            out,
            mapping,
            config,
            tree,
        } => {
            recording_input::use_mapping(mapping);
            commands::timeline::run(commands::timeline::TimelineArgs {
                file,
                out,
                config,
                tree,
            })
        }
        cli::Command::Learn {
            files,
            mapping,
            library,
            out,
            lambda,
            activities,
            config,
            tree,
            lock_timeout,
        } => {
            recording_input::use_mapping(mapping);
            commands::plan::parse_time_limit(&lock_timeout)
                .map_err(|e| Failure::plain(ExitCode::USAGE, format!("--lock-timeout: {e}")))
                .and_then(|lock_timeout| {
                    commands::library::learn(commands::library::LearnArgs {
                        files,
                        library,
                        out,
                        lambda,
                        grouping: activities.map(cli::ActivitiesArg::grouping),
                        config,
                        tree,
                        lock_timeout,
                    })
                })
        }
        cli::Command::Operators { library, markdown } => {
            commands::library::operators(commands::library::OperatorsArgs { library, markdown })
        }
        cli::Command::Domain {
            library,
            prio,
            full,
            out,
            keep_without_effects,
        } => commands::library::run_domain(commands::library::DomainArgs {
            library,
            prio: prio.map(|p| p as usize),
            full,
            out,
            keep_without_effects,
        }),
        cli::Command::Solve {
            library,
            problem,
            search,
            time_limit,
            planner,
            fd,
            compare_full,
            plan_file,
            keep_without_effects,
        } => {
            let time_limit = match time_limit {
                Some(text) => time_limit_option(&text)?,
                None => None,
            };
            commands::solve::run(commands::solve::SolveArgs {
                library,
                problem,
                search,
                time_limit,
                planner,
                fd,
                compare_full,
                plan_file,
                keep_without_effects,
            })
        }
        cli::Command::Reproduce(args) => commands::reproduce::run(args),
        cli::Command::Study(args) => commands::study::run(args),
        cli::Command::Problem {
            tower,
            paper_goal,
            cubes,
            hands,
            from,
            frame,
            config,
            out,
        } => commands::library::run_problem(commands::library::ProblemArgs {
            tower,
            paper_goal,
            cubes: cubes.map(|c| c as usize),
            hands: hands.map(|h| h as usize),
            from,
            frame,
            out,
            config,
        }),
        cli::Command::Execute {
            domain,
            problem,
            plan,
            json,
            frames,
        } => commands::execute::run(commands::execute::ExecuteArgs {
            domain,
            problem,
            plan,
            json,
            frames,
        }),
    }
}

/// A `--time-limit` value with Fast Downward's units (`None`: `infinity`); a bad one is a
/// command line error.
fn time_limit_option(text: &str) -> Result<Option<std::time::Duration>, Failure> {
    commands::plan::parse_time_limit(text)
        .map_err(|e| Failure::plain(ExitCode::USAGE, format!("--time-limit: {e}")))
}
