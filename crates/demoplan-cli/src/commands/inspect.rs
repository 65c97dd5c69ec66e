//! `demoplan inspect RECORDING...`: read each recording to the end and print its
//! `recording::Summary`.

use recording::{Frame, Summary};

use crate::cli::InspectArgs;
use crate::diagnostic::Failure;
use crate::recording_input;
use slim::ExitCode;

pub fn run(args: InspectArgs) -> Result<ExitCode, Failure> {
    let mut out = String::new();
    for (i, path) in args.files.iter().enumerate() {
        if i > 0 {
            out.push('\n');
        }
        let mut reader = recording_input::open(path, args.import.mapping.as_deref())?;
        let mut summary = Summary::new(reader.header());
        let mut frame = Frame::default();
        while reader
            .read_frame(&mut frame)
            .map_err(|e| recording_input::recording_failure(path, &e))?
        {
            summary.observe(&frame);
        }
        out.push_str(&summary.render(&path.display().to_string()));
    }
    print!("{out}");
    Ok(ExitCode::SUCCESS)
}
