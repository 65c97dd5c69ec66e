//! The report page and the search-time tables (the paper's Tables 3 and 4).

use std::fmt::Write as _;

use crate::model::{
    domain_label, format_limit, format_seconds, slimming_ratio_by, time_cell_by, Experiment,
    Measure, Outcome, Run,
};
pub use crate::paper::{PAPER_IPDB, PAPER_LMCUT, PAPER_OPERATORS, PAPER_TITLE};
use crate::Planner;

/// A plain table of texts: a header row and body rows of the same width.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Table {
    pub header: Vec<String>,
    pub rows: Vec<Vec<String>>,
}

impl Table {
    /// GitHub-flavoured Markdown, the first column left-aligned, the others right.
    pub fn to_markdown(&self) -> String {
        let mut s = String::new();
        let line = |cells: &[String]| format!("| {} |\n", cells.join(" | "));
        s.push_str(&line(&self.header));
        let rule: Vec<String> = (0..self.header.len())
            .map(|i| {
                if i == 0 {
                    ":---".to_string()
                } else {
                    "---:".to_string()
                }
            })
            .collect();
        s.push_str(&line(&rule));
        for row in &self.rows {
            s.push_str(&line(row));
        }
        s
    }
}

/// The label of the ratio row of [`search_time_table`].
pub const RATIO_ROW: &str = "largest / smallest";

/// Search time of `planner` per domain (rows, `dom{prio}({operators})`) and goal
/// (columns), as the paper's Tables 3 and 4: seconds, `> limit`, `unsolvable`,
/// `error`, or `-` for a run that is missing. A last row gives the ratio of the largest
/// domain over the smallest per goal (`>= 30x` when the largest hit the limit).
pub fn search_time_table(exp: &Experiment, planner: Planner) -> Table {
    time_table(exp, planner, Measure::Search)
}

/// [`search_time_table`] by any [`Measure`].
pub fn time_table(exp: &Experiment, planner: Planner, measure: Measure) -> Table {
    let goals = exp.goal_numbers();
    let mut header = vec!["domain".to_string()];
    header.extend(goals.iter().map(|g| format!("Goal {g}")));
    let mut rows = Vec::new();
    for (prio, ops) in exp.domains() {
        let mut row = vec![domain_label(prio, ops)];
        row.extend(goals.iter().map(|&g| {
            exp.run(planner, prio, g)
                .map(|r| time_cell_by(r, measure))
                .unwrap_or_else(|| "-".to_string())
        }));
        rows.push(row);
    }
    if exp.domains().len() > 1 {
        let mut row = vec![RATIO_ROW.to_string()];
        row.extend(goals.iter().map(|&g| {
            slimming_ratio_by(exp, planner, g, measure)
                .map(|r| r.to_string())
                .unwrap_or_else(|| "-".to_string())
        }));
        rows.push(row);
    }
    Table { header, rows }
}

/// Escapes text for HTML content and double-quoted attributes. `>` is left as it is
/// (valid in both), so that a cell reads `> limit` in the source too.
pub fn html_escape(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '"' => out.push_str("&quot;"),
            _ => out.push(c),
        }
    }
    out
}

const STYLE: &str = "
body { font-family: system-ui, -apple-system, 'Segoe UI', Helvetica, Arial, sans-serif;
       max-width: 1000px; margin: 2em auto; padding: 0 1em; line-height: 1.5; color: #1e1e1e; }
h1 { font-size: 1.6em; line-height: 1.25; }
h2 { margin-top: 2em; border-bottom: 1px solid #ddd; }
table { border-collapse: collapse; margin: 1em 0; }
th, td { border: 1px solid #ccc; padding: 0.25em 0.6em; }
th { background: #f3f3f3; }
td.num { text-align: right; font-variant-numeric: tabular-nums; font-family: ui-monospace, Menlo, Consolas, monospace; }
td.limit { color: #b41e1e; font-weight: bold; }
td.unsolvable, td.error, td.failed { color: #7a4b00; background: #fff6e0; }
tr.ratio td { border-top: 2px solid #999; font-style: italic; }
dl { display: grid; grid-template-columns: max-content 1fr; gap: 0.2em 1em; }
dt { font-weight: bold; }
dd { margin: 0; }
figure { margin: 1.5em 0; }
figure img { max-width: 100%; border: 1px solid #eee; }
figcaption { font-size: 0.95em; color: #444; }
.muted { color: #666; font-size: 0.95em; }
code { background: #f3f3f3; padding: 0 0.2em; }
";

fn run_details(run: &Run) -> String {
    let mut parts = vec![format!("{:?}", run.outcome).to_lowercase()];
    parts.push(format!("search {} s", format_seconds(run.search_time)));
    parts.push(format!("total {} s", format_seconds(run.total_time)));
    if let Some(e) = run.expansions {
        parts.push(format!("{e} expansions"));
    }
    if let Some(c) = run.cost {
        parts.push(format!("cost {c}"));
    }
    if let Some(l) = run.length {
        parts.push(format!("{l} actions"));
    }
    match run.executed {
        Some(true) => parts.push("executed".to_string()),
        Some(false) => parts.push("execution FAILED".to_string()),
        None => {}
    }
    if run.times.len() > 1 {
        let times: Vec<String> = run.times.iter().map(|t| format_seconds(*t)).collect();
        parts.push(format!("runs {}", times.join(" ")));
    }
    parts.join(", ")
}

fn cell_class(run: &Run) -> &'static str {
    match (run.outcome, run.executed) {
        (Outcome::Limit, _) => "num limit",
        (Outcome::Unsolvable, _) => "num unsolvable",
        (Outcome::Error, _) => "num error",
        (Outcome::Solved, Some(false)) => "num failed",
        (Outcome::Solved, _) => "num",
    }
}

fn times_table(s: &mut String, exp: &Experiment, planner: Planner, measure: Measure) {
    let goals = exp.goal_numbers();
    let domains = exp.domains();
    s.push_str("<table class=\"times\">\n<thead><tr><th>domain</th>");
    for g in &goals {
        let _ = write!(s, "<th>Goal {g}</th>");
    }
    s.push_str("</tr></thead>\n<tbody>\n");
    for &(prio, ops) in &domains {
        let _ = write!(s, "<tr><th>{}</th>", html_escape(&domain_label(prio, ops)));
        for &g in &goals {
            match exp.run(planner, prio, g) {
                Some(run) => {
                    let mark = if run.executed == Some(false) {
                        " (execution failed)"
                    } else {
                        ""
                    };
                    let _ = write!(
                        s,
                        "<td class=\"{}\" title=\"{}\">{}{}</td>",
                        cell_class(run),
                        html_escape(&run_details(run)),
                        html_escape(&time_cell_by(run, measure)),
                        mark
                    );
                }
                None => s.push_str("<td class=\"num\">-</td>"),
            }
        }
        s.push_str("</tr>\n");
    }
    if domains.len() > 1 {
        let _ = write!(s, "<tr class=\"ratio\"><th>{RATIO_ROW}</th>");
        for &g in &goals {
            let text = slimming_ratio_by(exp, planner, g, measure)
                .map(|r| r.to_string())
                .unwrap_or_else(|| "-".to_string());
            let _ = write!(s, "<td class=\"num\">{}</td>", html_escape(&text));
        }
        s.push_str("</tr>\n");
    }
    s.push_str("</tbody>\n</table>\n");
}

fn paper_table(s: &mut String, caption: &str, times: &[[&str; 5]; 5]) {
    let _ = writeln!(
        s,
        "<table class=\"paper\">\n<caption>{}</caption>",
        html_escape(caption)
    );
    s.push_str("<thead><tr><th>domain</th>");
    for g in 1..=5 {
        let _ = write!(s, "<th>Goal {g}</th>");
    }
    s.push_str("</tr></thead>\n<tbody>\n");
    for (i, row) in times.iter().enumerate() {
        let _ = write!(
            s,
            "<tr><th>{}</th>",
            domain_label(i + 1, PAPER_OPERATORS[i])
        );
        for cell in row {
            let _ = write!(s, "<td class=\"num\">{cell}</td>");
        }
        s.push_str("</tr>\n");
    }
    s.push_str("</tbody>\n</table>\n");
}

/// The number of cubes the goals are built from: the highest `cube_N` named, at least
/// the tallest tower.
fn scene_cubes(exp: &Experiment) -> usize {
    if exp.cubes > 0 {
        return exp.cubes;
    }
    let tallest = exp.goals.iter().map(|g| g.tower.len()).max().unwrap_or(0);
    let named = exp
        .goals
        .iter()
        .flat_map(|g| &g.tower)
        .filter_map(|n| n.strip_prefix("cube_")?.parse::<usize>().ok())
        .max()
        .unwrap_or(0);
    tallest.max(named)
}

fn list_words(items: &[String]) -> String {
    match items {
        [] => String::new(),
        [one] => one.clone(),
        [init @ .., last] => format!("{} and {}", init.join(", "), last),
    }
}

/// The path with its extension replaced.
fn sibling(path: &str, ext: &str) -> Option<String> {
    let dot = path.rfind('.')?;
    if path[dot..].contains('/') {
        return None;
    }
    Some(format!("{}.{ext}", &path[..dot]))
}

/// One self-contained page (inline style, no scripts, nothing fetched from elsewhere):
/// title, what the paper did and what demoplan reproduces (with the goals as towers),
/// machine and versions, the domains, one search-time table per planner (as the paper's
/// Tables 3 and 4, `> limit` for a run at the time limit, the ratio of the largest
/// domain over the smallest per goal), the figures (every `.svg` artefact as an image,
/// linked with its `.png` sibling when that is an artefact too), the notes, the paper's
/// own numbers, every run, and links to every artefact. `artefacts` are (path relative
/// to the page, caption), shown in the order given.
pub fn report_html(exp: &Experiment, artefacts: &[(String, String)]) -> String {
    let mut s = String::new();
    s.push_str("<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n");
    s.push_str("<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n");
    let _ = writeln!(
        s,
        "<title>demoplan reproduce: {}</title>",
        html_escape(PAPER_TITLE)
    );
    let _ = writeln!(s, "<style>{STYLE}</style>\n</head>\n<body>");
    let _ = writeln!(
        s,
        "<h1>Reproducing &ldquo;{}&rdquo;</h1>",
        html_escape(PAPER_TITLE)
    );
    s.push_str(
        "<p class=\"muted\">Maximilian Diehl, Chris Paxton and Karinne Ramirez-Amaro. \
         This page was written by <code>demoplan reproduce</code>.</p>\n",
    );

    // What the paper did and what is reproduced.
    s.push_str("<h2>The experiment</h2>\n");
    s.push_str(
        "<p><strong>The paper</strong> learns planning operators from 12 human demonstrations \
         of cube stacking in virtual reality and counts how often each operator was \
         demonstrated. It builds PDDL domains by priority: priority 1 keeps the most \
         frequently demonstrated operator of each type (reach, take, put, stack, idle), each \
         further priority adds the next most frequent ones (ties all included), giving five \
         domains of 5, 11, 18, 23 and 30 operators. It plans five increasingly tall stacking \
         goals on every domain with Fast Downward's A* search with the iPDB and the LM-cut \
         heuristic (its Tables 3 and 4, Figures 5 and 6). For the hardest goal the largest \
         domain is 72 times (iPDB) and 120 times (LM-cut) slower than the priority-1 domain, \
         and the priority-1 domain suffices for every goal.</p>\n",
    );
    let planners: Vec<String> = exp
        .planners()
        .iter()
        .map(|p| p.label().to_string())
        .collect();
    let repeats = if exp.repeat > 1 {
        format!("{} times each; the tables show medians", exp.repeat)
    } else {
        "once each".to_string()
    };
    let _ = writeln!(
        s,
        "<p><strong>demoplan reproduces</strong> the whole chain: it simulates the 12 \
         demonstrations (seed {}), segments and classifies them, learns the operator library, \
         builds the domain of every distinct priority level, and plans every goal on every \
         domain with {} under a time limit of {} s per run, {}. Every plan is checked by \
         executing it in a simulated cube world. A run that hits the limit is shown as \
         <q>> limit</q>, not dropped, and a ratio that involves it is a bound \
         (<code>>=</code>).</p>",
        exp.seed,
        html_escape(&list_words(&planners)),
        format_limit(exp.time_limit),
        html_escape(&repeats)
    );

    let mut goals = exp.goals.clone();
    goals.sort_by_key(|g| g.number);
    if !goals.is_empty() {
        let heights: Vec<String> = goals.iter().map(|g| g.tower.len().to_string()).collect();
        let _ = writeln!(
            s,
            "<p><strong>The goals.</strong> The paper shows its five goals only as pictures of \
             increasingly tall stacks (its Figure 4; goal 5 needs at least 20 actions). demoplan \
             reconstructs them as towers of {} cubes, built from {} cubes that start on the \
             table{}; a goal is the tower's <code>onTop</code> facts, bottom first:</p>",
            list_words(&heights),
            scene_cubes(exp),
            match exp.hands {
                0 => String::new(),
                1 => " with one hand (a one-armed robot, as the paper's TIAGo)".to_string(),
                n => format!(" with {n} hands"),
            }
        );
        s.push_str("<table class=\"goals\">\n<thead><tr><th>goal</th><th>tower, bottom first</th><th>cubes</th></tr></thead>\n<tbody>\n");
        for g in &goals {
            let _ = writeln!(
                s,
                "<tr><th>Goal {}</th><td>{}</td><td class=\"num\">{}</td></tr>",
                g.number,
                html_escape(&g.tower.join(", ")),
                g.tower.len()
            );
        }
        s.push_str("</tbody>\n</table>\n");
    }

    // Setting.
    s.push_str("<h2>Setting</h2>\n<dl>\n");
    let setting = [
        ("machine", exp.machine.clone()),
        ("versions", exp.versions.clone()),
        ("planners", list_words(&planners)),
        (
            "time limit",
            format!("{} s per run", format_limit(exp.time_limit)),
        ),
        ("repeats", exp.repeat.to_string()),
        ("seed", exp.seed.to_string()),
    ];
    for (k, v) in setting {
        let _ = writeln!(s, "<dt>{k}</dt><dd>{}</dd>", html_escape(&v));
    }
    s.push_str("</dl>\n");

    // Domains.
    if !exp.levels.is_empty() {
        s.push_str("<h2>Domains</h2>\n<p>Operators per type in the domain of each priority level (as the paper's Figure 3).</p>\n");
        s.push_str("<table class=\"levels\">\n<thead><tr><th>domain</th><th>priority</th><th>operators</th>");
        for t in recording::Activity::OPERATOR_ORDER {
            let _ = write!(s, "<th>{}</th>", t.operator_name());
        }
        s.push_str("</tr></thead>\n<tbody>\n");
        let mut levels = exp.levels.clone();
        levels.sort_by_key(|l| l.prio);
        for l in &levels {
            let _ = write!(
                s,
                "<tr><th>{}</th><td class=\"num\">{}</td><td class=\"num\">{}</td>",
                domain_label(l.prio, l.operators),
                l.prio,
                l.operators
            );
            for n in l.per_type {
                let _ = write!(s, "<td class=\"num\">{n}</td>");
            }
            s.push_str("</tr>\n");
        }
        s.push_str("</tbody>\n</table>\n");
    }

    // Search time tables.
    s.push_str("<h2>Search time</h2>\n");
    let _ = writeln!(
        s,
        "<p>Search time in seconds per domain and goal{}. The last row divides the largest \
         domain's time by the smallest's, as the paper does for goal 5 (72 times with iPDB, \
         120 times with LM-cut); <code>>=</code> marks a lower bound because the largest \
         domain hit the limit, <code>&lt;=</code> an upper bound because the smallest did. Hover over a cell for the outcome, total time, expansions, \
         plan cost and length, and the execution check.</p>",
        if exp.repeat > 1 { " (median)" } else { "" }
    );
    for planner in exp.planners() {
        let _ = writeln!(
            s,
            "<h3>{} (as the paper's {})</h3>",
            html_escape(planner.label()),
            planner.paper_table()
        );
        times_table(&mut s, exp, planner, Measure::Search);
    }
    if !exp.runs.is_empty() {
        s.push_str("<h2>Total time</h2>\n");
        s.push_str(
            "<p>The same runs by total time in seconds: translation, heuristic construction \
             (iPDB's hill climbing, LM-cut's relaxed task) and search together, which is what a \
             user waits for. The last row is the same ratio on this measure.</p>\n",
        );
        for planner in exp.planners() {
            let _ = writeln!(s, "<h3>{}</h3>", html_escape(planner.label()));
            times_table(&mut s, exp, planner, Measure::Total);
        }
    }
    if exp.runs.is_empty() {
        s.push_str("<p>No runs.</p>\n");
    }

    // Figures.
    let figures: Vec<&(String, String)> = artefacts
        .iter()
        .filter(|(p, _)| p.ends_with(".svg"))
        .collect();
    if !figures.is_empty() {
        s.push_str("<h2>Figures</h2>\n");
        for (path, caption) in figures {
            let png = sibling(path, "png").filter(|p| artefacts.iter().any(|(a, _)| a == p));
            let _ = write!(
                s,
                "<figure>\n<a href=\"{0}\"><img src=\"{0}\" alt=\"{1}\"></a>\n<figcaption>{1} \
                 (<a href=\"{0}\">SVG</a>",
                html_escape(path),
                html_escape(caption)
            );
            if let Some(png) = png {
                let _ = write!(s, ", <a href=\"{}\">PNG</a>", html_escape(&png));
            }
            s.push_str(")</figcaption>\n</figure>\n");
        }
    }

    // Notes.
    s.push_str("<h2>Findings</h2>\n");
    if exp.notes.is_empty() {
        s.push_str("<p>No findings were recorded.</p>\n");
    } else {
        s.push_str("<ul class=\"notes\">\n");
        for n in &exp.notes {
            let _ = writeln!(s, "<li>{}</li>", html_escape(n));
        }
        s.push_str("</ul>\n");
    }

    // The paper's numbers.
    s.push_str("<h2>The paper's numbers</h2>\n<details>\n<summary>Tables 3 and 4 of the paper (Fast Downward, the authors' machine)</summary>\n");
    paper_table(
        &mut s,
        "Table 3: search time (s), astar(ipdb())",
        &PAPER_IPDB,
    );
    paper_table(
        &mut s,
        "Table 4: search time (s), astar(lmcut())",
        &PAPER_LMCUT,
    );
    s.push_str("</details>\n");

    // All runs.
    if !exp.runs.is_empty() {
        s.push_str("<h2>All runs</h2>\n<details>\n<summary>Every run of the grid</summary>\n");
        s.push_str(
            "<table class=\"runs\">\n<thead><tr><th>planner</th><th>domain</th><th>goal</th>\
             <th>outcome</th><th>search (s)</th><th>total (s)</th><th>expansions</th>\
             <th>cost</th><th>length</th><th>executed</th><th>every run (s)</th></tr></thead>\n<tbody>\n",
        );
        let mut runs: Vec<&Run> = exp.runs.iter().collect();
        runs.sort_by_key(|r| (r.planner, r.prio, r.goal));
        let opt = |v: Option<String>| v.unwrap_or_else(|| "-".to_string());
        for r in runs {
            let times: Vec<String> = r.times.iter().map(|t| format_seconds(*t)).collect();
            let _ = writeln!(
                s,
                "<tr><td>{}</td><td>{}</td><td class=\"num\">{}</td><td class=\"{}\">{}</td>\
                 <td class=\"num\">{}</td><td class=\"num\">{}</td><td class=\"num\">{}</td>\
                 <td class=\"num\">{}</td><td class=\"num\">{}</td><td>{}</td><td class=\"num\">{}</td></tr>",
                r.planner,
                domain_label(r.prio, r.operators),
                r.goal,
                cell_class(r),
                format!("{:?}", r.outcome).to_lowercase(),
                format_seconds(r.search_time),
                format_seconds(r.total_time),
                opt(r.expansions.map(|e| e.to_string())),
                opt(r.cost.map(|c| c.to_string())),
                opt(r.length.map(|l| l.to_string())),
                match r.executed {
                    Some(true) => "yes",
                    Some(false) => "FAILED",
                    None => "-",
                },
                times.join(" ")
            );
        }
        s.push_str("</tbody>\n</table>\n</details>\n");
    }

    // Files.
    s.push_str("<h2>Files</h2>\n<ul class=\"files\">\n");
    for (path, caption) in artefacts {
        let _ = writeln!(
            s,
            "<li><a href=\"{0}\">{0}</a>: {1}</li>",
            html_escape(path),
            html_escape(caption)
        );
    }
    s.push_str("</ul>\n");
    let _ = writeln!(
        s,
        "<footer class=\"muted\"><p>{}</p></footer>\n</body>\n</html>",
        html_escape(&exp.versions)
    );
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn siblings_swap_the_extension() {
        assert_eq!(sibling("fig/a.svg", "png"), Some("fig/a.png".to_string()));
        assert_eq!(sibling("a.b/c", "png"), None);
        assert_eq!(sibling("noext", "png"), None);
    }

    #[test]
    fn words_are_listed() {
        let w = |v: &[&str]| list_words(&v.iter().map(|s| s.to_string()).collect::<Vec<_>>());
        assert_eq!(w(&[]), "");
        assert_eq!(w(&["2"]), "2");
        assert_eq!(w(&["2", "3", "4"]), "2, 3 and 4");
    }

    #[test]
    fn escape_keeps_greater_than() {
        assert_eq!(
            html_escape("> limit <b> & \"q\""),
            "> limit &lt;b> &amp; &quot;q&quot;"
        );
    }
}
