//! `demoplan fmt FILE...`: rewrite PDDL in canonical form.

use crate::cli::FmtArgs;
use crate::diagnostic::Failure;
use crate::input;
use crate::output::write_atomically;
use slim::ExitCode;

pub fn run(args: FmtArgs) -> Result<ExitCode, Failure> {
    let (check, stdout) = (args.check, args.stdout);
    let mut code = ExitCode::SUCCESS;
    for path in &args.files {
        let source = input::read_text(path)?;
        let canonical =
            pddl::canonical_form(&source).map_err(|e| Failure::pddl(path, &source, &e))?;
        let (formatted, dropped) = (canonical.text, canonical.dropped_comments);
        if stdout {
            print!("{formatted}");
        } else if check {
            if formatted != source {
                println!("{} is not in canonical form", path.display());
                code = ExitCode::CHECK_FAILED;
            }
        } else if formatted != source {
            write_atomically(path, &formatted)?;
        }
        if dropped > 0 && !check {
            eprintln!(
                "warning: {}: {dropped} comment{} inside the definition dropped",
                path.display(),
                if dropped == 1 { "" } else { "s" }
            );
        }
    }
    Ok(code)
}
