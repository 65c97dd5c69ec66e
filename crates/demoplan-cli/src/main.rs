//! The `demoplan` executable: the command line of `demoplan_cli::run`.

fn main() -> std::process::ExitCode {
    demoplan_cli::run(std::env::args_os()).into()
}
