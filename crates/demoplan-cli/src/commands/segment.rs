//! `demoplan segment FILE...`: ground recordings (or read ARFF hand-state tables), cut
//! each hand's frames into segments and classify them; print `learn`'s table or JSON.

use std::io::Write;

use crate::cli::SegmentArgs;
use crate::commands::demo_input;
use crate::diagnostic::Failure;
use crate::output::{self, stdout_failure};
use slim::ExitCode;

pub fn run(args: SegmentArgs) -> Result<ExitCode, Failure> {
    let segmentation = demo_input::segmentation(&args.segmentation)?;
    // Each file is printed as soon as it is segmented, and JSON one segment at a time:
    // memory follows one file's segments, not the text of all of them.
    let mut out = std::io::BufWriter::new(std::io::stdout().lock());
    if args.json {
        output::print(&mut out, "{\n  \"files\": [")?;
    }
    for (i, path) in args.files.iter().enumerate() {
        let segmented = demo_input::segment_file(path, &segmentation)?;
        let source = path.display().to_string();
        if args.json {
            output::print(&mut out, if i > 0 { ",\n" } else { "\n" })?;
            segmented
                .write_json(&mut out, &source)
                .map_err(|e| stdout_failure(&e))?;
        } else {
            let blank = if i > 0 { "\n" } else { "" };
            output::print(&mut out, &format!("{blank}{}", segmented.table(&source)))?;
        }
    }
    if args.json {
        let end = if args.files.is_empty() {
            "]\n}\n"
        } else {
            "\n  ]\n}\n"
        };
        output::print(&mut out, end)?;
    }
    out.flush()
        .map_err(|e| stdout_failure(&e))
        .map(|()| ExitCode::SUCCESS)
}
