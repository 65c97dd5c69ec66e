//! `demoplan fmt FILE...`: rewrite PDDL in canonical form.

use crate::cli::FmtArgs;
use crate::diagnostic::Failure;
use crate::exit::ExitCode;
use crate::input;
use crate::output::write_atomically;

pub fn run(args: FmtArgs) -> Result<ExitCode, Failure> {
    let (check, stdout) = (args.check, args.stdout);
    let mut code = ExitCode::SUCCESS;
    for path in &args.files {
        let source = input::read_text(path)?;
        let parsed = pddl::parse_file(&source).map_err(|e| Failure::pddl(path, &source, &e))?;
        let header = leading_comments(&source);
        let body = match &parsed.content {
            pddl::PddlFile::Domain(d) => d.to_string(),
            pddl::PddlFile::Problem(p) => p.to_string(),
        };
        let formatted = if header.is_empty() {
            body
        } else {
            format!("{header}\n{body}")
        };
        let header_comments = header.lines().count();
        let dropped = parsed.comments.len().saturating_sub(header_comments);
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

/// The `;` comment lines before the definition, each trimmed at the end.
fn leading_comments(source: &str) -> String {
    let mut out = String::new();
    for l in source.lines() {
        let t = l.trim();
        if t.starts_with(';') {
            out.push_str(t);
            out.push('\n');
        } else if !t.is_empty() {
            break;
        }
    }
    out
}
