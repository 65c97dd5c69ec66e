//! Writes every figure and the report page for a made-up experiment, so that a person
//! can look at them: `cargo run -p report --example sample -- OUT_DIR`.

use std::path::Path;
use std::process::ExitCode;

use report::{
    goal_figure, goals_figure, operators_figure, report_html, search_time_figure,
    search_time_table, Experiment, Figure, Planner,
};

fn write(dir: &Path, name: &str, bytes: &[u8]) -> std::io::Result<()> {
    std::fs::write(dir.join(name), bytes)
}

fn figure(
    dir: &Path,
    stem: &str,
    fig: &Figure,
    caption: &str,
    artefacts: &mut Vec<(String, String)>,
) -> std::io::Result<()> {
    write(dir, &format!("{stem}.svg"), fig.svg().as_bytes())?;
    let png = fig.png().map_err(std::io::Error::other)?;
    write(dir, &format!("{stem}.png"), &png)?;
    artefacts.push((format!("{stem}.svg"), caption.to_string()));
    artefacts.push((format!("{stem}.png"), format!("{caption} (PNG)")));
    Ok(())
}

fn run(dir: &Path) -> std::io::Result<()> {
    std::fs::create_dir_all(dir)?;
    let exp = Experiment::example();
    let mut artefacts = Vec::new();
    figure(
        dir,
        "operators",
        &operators_figure(&exp.levels),
        "Operators per type and priority level (Figure 3)",
        &mut artefacts,
    )?;
    figure(
        dir,
        "goals",
        &goals_figure(&exp.goals, 6),
        "The five goals as towers (Figure 4)",
        &mut artefacts,
    )?;
    for goal in &exp.goals {
        figure(
            dir,
            &format!("goal-{}", goal.number),
            &goal_figure(goal, 6),
            &format!("Goal {}", goal.number),
            &mut artefacts,
        )?;
    }
    for (planner, paper) in [(Planner::Ipdb, "Figure 5"), (Planner::Lmcut, "Figure 6")] {
        figure(
            dir,
            &format!("search-time-{planner}"),
            &search_time_figure(&exp, planner),
            &format!("Search time per goal, {planner} ({paper})"),
            &mut artefacts,
        )?;
    }
    let mut tables = String::new();
    for planner in exp.planners() {
        tables.push_str(&format!("## {planner}\n\n"));
        tables.push_str(&search_time_table(&exp, planner).to_markdown());
        tables.push('\n');
    }
    write(dir, "tables.md", tables.as_bytes())?;
    artefacts.push((
        "tables.md".to_string(),
        "Tables 3 and 4 as Markdown".to_string(),
    ));
    write(dir, "report.html", report_html(&exp, &artefacts).as_bytes())?;
    println!(
        "wrote {} files and report.html to {}",
        artefacts.len(),
        dir.display()
    );
    Ok(())
}

fn main() -> ExitCode {
    let Some(dir) = std::env::args_os().nth(1) else {
        eprintln!("usage: sample OUT_DIR");
        return ExitCode::from(2);
    };
    match run(Path::new(&dir)) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("sample: {e}");
            ExitCode::FAILURE
        }
    }
}
