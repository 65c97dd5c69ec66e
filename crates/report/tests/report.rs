//! The figures and the page, as the reproduce command uses them.

mod common;

use common::{check_markup, experiment, run};
use report::{
    goal_figure, goals_figure, operators_figure, report_html, search_time_figure,
    search_time_table, text_width, Experiment, Figure, Goal, Level, LogScale, Outcome, Planner,
    Shape,
};

fn figures(exp: &Experiment) -> Vec<(&'static str, Figure)> {
    vec![
        ("search-time-lmcut", search_time_figure(exp, Planner::Lmcut)),
        ("search-time-ipdb", search_time_figure(exp, Planner::Ipdb)),
        (
            "search-time-fd-lmcut",
            search_time_figure(exp, Planner::FdLmcut),
        ),
        ("operators", operators_figure(&exp.levels)),
        ("goal-1", goal_figure(&exp.goals[0], 6)),
        ("goal-5", goal_figure(&exp.goals[4], 6)),
        ("goals", goals_figure(&exp.goals, 6)),
    ]
}

const PNG_SIGNATURE: &[u8] = b"\x89PNG\r\n\x1a\n";

fn png(fig: &Figure) -> Vec<u8> {
    fig.png().unwrap_or_else(|e| panic!("{}: {e}", fig.title()))
}

/// A PNG decoded by the `png` crate's reader: width, height and 8-bit RGB rows.
fn decode_rgb(png: &[u8]) -> Result<(u32, u32, Vec<u8>), String> {
    let decoder = png::Decoder::new(std::io::Cursor::new(png));
    let mut reader = decoder.read_info().map_err(|e| e.to_string())?;
    let mut rgb = vec![0; reader.output_buffer_size().unwrap_or_default()];
    let info = reader.next_frame(&mut rgb).map_err(|e| e.to_string())?;
    if (info.color_type, info.bit_depth) != (png::ColorType::Rgb, png::BitDepth::Eight) {
        return Err(format!("{:?} {:?}", info.color_type, info.bit_depth));
    }
    rgb.truncate(info.buffer_size());
    Ok((info.width, info.height, rgb))
}

#[test]
fn svgs_are_well_formed() {
    let exp = Experiment::example();
    for (name, fig) in figures(&exp) {
        let svg = fig.svg();
        let opened = check_markup(&svg, false).unwrap_or_else(|e| panic!("{name}: {e}"));
        assert_eq!(opened.first().map(String::as_str), Some("svg"), "{name}");
        assert!(svg.contains(&format!(
            r#"width="{}" height="{}""#,
            fig.width(),
            fig.height()
        )));
        assert!(opened.iter().any(|t| t == "text"), "{name} has no text");
    }
}

#[test]
fn pngs_decode_at_the_figure_size_with_the_figure_drawn() {
    let exp = Experiment::example();
    for (name, fig) in figures(&exp) {
        let png = png(&fig);
        assert_eq!(&png[..8], PNG_SIGNATURE, "{name}");
        let (w, h, rgb) = decode_rgb(&png).unwrap_or_else(|e| panic!("{name}: {e}"));
        assert_eq!((w, h), (fig.width(), fig.height()), "{name}");
        // Something is drawn, and the compression is worth having.
        let inked = rgb.chunks(3).filter(|p| p != &[255, 255, 255]).count();
        assert!(inked > 100, "{name} is all but blank: {inked} pixels");
        assert!(png.len() < rgb.len() / 4, "{name}: {} bytes", png.len());
    }
}

#[test]
fn rendering_is_deterministic() {
    let a = Experiment::example();
    let b = Experiment::example();
    let artefacts = [("x.svg".to_string(), "x".to_string())];
    for ((_, fa), (_, fb)) in figures(&a).into_iter().zip(figures(&b)) {
        assert_eq!(fa.svg(), fb.svg());
        assert_eq!(png(&fa), png(&fb));
    }
    assert_eq!(report_html(&a, &artefacts), report_html(&b, &artefacts));
}

#[test]
fn log_axis_places_decades_evenly_from_a_thousandth_to_above_the_limit() {
    let exp = Experiment::example();
    let min = 0.00042 * 0.93;
    let y = LogScale::covering(min, exp.time_limit, -3, 470.0, 60.0);
    assert_eq!((y.lo, y.hi), (-4, 3));
    let step = y.map(1.0) - y.map(10.0);
    for k in y.lo..y.hi {
        let d = y.map(10f64.powi(k)) - y.map(10f64.powi(k + 1));
        assert!((d - step).abs() < 1e-9);
    }
    assert!((y.map(60.0) - (y.map(10.0) - step * 60f64.log10().fract())).abs() < 1e-9);
    // Never faster than a thousandth on the axis if every run took longer.
    assert_eq!(LogScale::covering(0.5, 60.0, -3, 1.0, 0.0).lo, -3);
}

#[test]
fn runs_at_the_limit_show_as_open_markers_with_a_note() {
    let exp = Experiment::example();
    let svg = search_time_figure(&exp, Planner::Lmcut).svg();
    assert!(svg.contains("&gt; limit"));
    assert!(svg.contains("limit 60 s"));
    assert!(
        svg.contains(r##"fill="#ffffff" stroke="##),
        "no open marker"
    );
    for label in ["dom1(5)", "dom5(30)", "0.001", "100", "goal (tower height)"] {
        assert!(svg.contains(label), "{label}");
    }
}

#[test]
fn tables_show_limit_runs_and_bounded_ratios() {
    let exp = Experiment::example();
    let table = search_time_table(&exp, Planner::Lmcut);
    assert_eq!(
        table.header,
        ["domain", "Goal 1", "Goal 2", "Goal 3", "Goal 4", "Goal 5"]
    );
    assert_eq!(table.rows[0][0], "dom1(5)");
    assert_eq!(table.rows[0][5], "14.3");
    assert_eq!(table.rows[4][5], "> limit");
    assert_eq!(table.rows[5][0], report::RATIO_ROW);
    assert!(table.rows[5][5].starts_with(">= "), "{}", table.rows[5][5]);
    insta::assert_snapshot!(table.to_markdown());
}

#[test]
fn the_page_links_every_artefact_and_shows_the_tables() {
    let exp = Experiment::example();
    let artefacts: Vec<(String, String)> = [
        ("search-time-lmcut.svg", "Search time, LM-cut"),
        ("search-time-lmcut.png", "Search time, LM-cut (PNG)"),
        ("figures/operators.svg", "Operators per type"),
        ("results.csv", "All results"),
        ("results.json", "All results as JSON"),
        ("tables.md", "Tables 3 and 4"),
    ]
    .iter()
    .map(|(a, b)| (a.to_string(), b.to_string()))
    .collect();
    let html = report_html(&exp, &artefacts);
    check_markup(&html, true).unwrap_or_else(|e| panic!("{e}"));
    for (path, caption) in &artefacts {
        assert!(html.contains(&format!("href=\"{path}\"")), "{path}");
        assert!(html.contains(caption.as_str()), "{caption}");
    }
    assert!(html.contains(r#"<img src="search-time-lmcut.svg""#));
    assert!(html.contains(r#"<img src="figures/operators.svg""#));
    assert!(html.contains(r#"<a href="search-time-lmcut.png">PNG</a>"#));
    assert!(!html.contains(r#"<img src="results.csv""#));
    // A run at the limit reads "> limit" in its table cell.
    assert!(exp.run(Planner::Lmcut, 5, 5).map(|r| r.outcome) == Some(Outcome::Limit));
    assert!(html.contains(">> limit</td>"));
    // Machine, versions, notes, the goals and both planners' tables.
    for text in [
        exp.machine.as_str(),
        "demoplan 0.1.0; Fast Downward 26.6 (not run)",
        exp.notes[1].as_str(),
        "cube_1, cube_2, cube_3, cube_4, cube_5, cube_6",
        "towers of 2, 3, 4, 5 and 6 cubes",
        "demoplan astar(ipdb()) (as the paper's Table 3)",
        "demoplan astar(lmcut()) (as the paper's Table 4)",
        "1725.18",
    ] {
        assert!(html.contains(text), "{text}");
    }
    // Self-contained: nothing fetched from elsewhere.
    assert!(!html.contains("http://") && !html.contains("https://") && !html.contains("<script"));
}

#[test]
fn odd_inputs_draw_without_panicking() {
    let empty = experiment(vec![]);
    let mut odd = empty.clone();
    odd.time_limit = f64::NAN;
    odd.runs = vec![
        run(Planner::Lmcut, 1, 1, Outcome::Unsolvable, 0.2),
        run(Planner::Lmcut, 1, 2, Outcome::Error, f64::NAN),
        run(Planner::Lmcut, 2, 1, Outcome::Solved, 0.0),
        run(Planner::Lmcut, 2, 2, Outcome::Solved, f64::INFINITY),
        run(Planner::Lmcut, 3, 7, Outcome::Limit, 1e12),
    ];
    odd.levels = vec![Level {
        prio: 1,
        operators: 9,
        per_type: [0, 0, 0, 0, 0],
    }];
    odd.goals = vec![
        Goal {
            number: 1,
            tower: vec![],
        },
        Goal {
            number: 2,
            tower: vec![
                "a <red> & \"blue\" cube".to_string(),
                "cube_99".to_string(),
                "bell\u{7}".to_string(),
            ],
        },
    ];
    for exp in [&empty, &odd] {
        let mut figs = vec![
            search_time_figure(exp, Planner::Lmcut),
            // A planner without runs.
            search_time_figure(exp, Planner::FdIpdb),
            operators_figure(&exp.levels),
            goals_figure(&exp.goals, 3),
        ];
        figs.extend(exp.goals.iter().map(|g| goal_figure(g, 0)));
        for fig in figs {
            check_markup(&fig.svg(), false).unwrap_or_else(|e| panic!("{e}"));
            assert!(decode_rgb(&png(&fig)).is_ok());
        }
        let html = report_html(exp, &[("a&b.svg".to_string(), "<caption>".to_string())]);
        check_markup(&html, true).unwrap_or_else(|e| panic!("{e}"));
        assert!(html.contains("href=\"a&amp;b.svg\""));
    }
    let table = search_time_table(&odd, Planner::Lmcut);
    assert_eq!(table.rows[0][1], "unsolvable");
    assert_eq!(table.rows[0][2], "error");
}

#[test]
fn goal_figure_snapshot() {
    let goal = Goal {
        number: 2,
        tower: vec!["cube_1".into(), "cube_2".into(), "cube_3".into()],
    };
    insta::assert_snapshot!(goal_figure(&goal, 4).svg());
}

fn goal_2() -> Figure {
    let goal = Goal {
        number: 2,
        tower: vec!["cube_1".into(), "cube_2".into(), "cube_3".into()],
    };
    goal_figure(&goal, 4)
}

/// The PNG of one figure, byte for byte: resvg with the embedded font and the png
/// crate's encoder give these bytes on any machine (no system font takes part).
#[test]
fn goal_figure_png_snapshot() {
    insta::assert_binary_snapshot!("goal-2.png", png(&goal_2()));
}

/// Text is anti-aliased: the caption's pixels (grey #787878 on white) take many levels
/// between the ink and the paper, not just the two a bitmap font gives, and all are grey.
#[test]
fn text_is_anti_aliased_in_the_png() {
    let fig = goal_2();
    let caption = fig
        .shapes()
        .iter()
        .find_map(|s| match s {
            Shape::Text(t) if t.text.starts_with("bottom first") => Some(t.clone()),
            _ => None,
        })
        .unwrap_or_else(|| panic!("no caption"));
    let (w, _, rgb) = decode_rgb(&png(&fig)).unwrap_or_else(|e| panic!("{e}"));
    // The caption's box: from its start to its advance width, from a cap height above
    // the baseline (10 px font) to a descender below it.
    let (x0, x1) = (
        caption.at.x as usize,
        (caption.at.x + text_width(&caption.text, caption.scale)) as usize,
    );
    let (y0, y1) = (caption.at.y as usize - 9, caption.at.y as usize + 3);
    let mut levels = std::collections::BTreeSet::new();
    for y in y0..y1 {
        for x in x0..x1 {
            let i = (y * w as usize + x) * 3;
            let (r, g, b) = (rgb[i], rgb[i + 1], rgb[i + 2]);
            assert!(r == g && g == b, "({x}, {y}) is not grey: {r} {g} {b}");
            assert!(r >= 0x78, "({x}, {y}) is darker than the ink: {r}");
            levels.insert(r);
        }
    }
    assert!(levels.contains(&255), "no paper between the letters");
    assert!(
        levels.len() > 2,
        "the caption has {} grey levels: {levels:?}",
        levels.len()
    );
}
