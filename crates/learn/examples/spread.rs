//! The operator library of simulated studies over many seeds: per seed, learn the library
//! of 3 participants x 4 demonstrations (the simulator's default parameters) and measure
//! what issue 7's acceptance names; print the default seed's table and the spread.
//!
//! ```text
//! cargo run --release -p learn --example spread -- [FIRST_SEED] [COUNT] [runs]
//! ```
//! Defaults: seeds 1 to 100, activities grouped as `settled` (`runs`: every Idle run an
//! activity of its own). Also measures seed 7, the embedded default.

use grounding::GroundingConfig;
use learn::{levels, DomainOptions, Grouping, Library};
use segment::Activity;
use segment::ActivityTree;

/// What one study's library looks like.
struct Shape {
    activities: u64,
    operators: usize,
    /// Per type (`Activity::OPERATOR_ORDER`): the share of the most frequent operator.
    top_share: [f64; 5],
    seen_once: f64,
    levels: Vec<usize>,
}

fn library(seed: u64, grouping: Grouping) -> Option<Library> {
    let study = simulate::study(&simulate::SimParams::default(), seed, 3, 4).ok()?;
    let config = GroundingConfig::default();
    let tree = ActivityTree::table_one();
    let mut library = Library::with_grouping(learn::DEFAULT_LAMBDA, grouping);
    for demo in &study.demonstrations {
        let frames = demo.frames().map(|(f, _)| f).collect();
        learn::add_frames(&mut library, demo.header(), frames, &config, &tree, "");
    }
    Some(library)
}

fn shape(library: &Library) -> Shape {
    let mut top_share = [0.0; 5];
    for (i, a) in Activity::OPERATOR_ORDER.iter().enumerate() {
        let ranked = library.ranked_type(*a);
        let total = library.type_count(*a);
        if let Some(top) = ranked.first() {
            top_share[i] = top.count() as f64 / total.max(1) as f64;
        }
    }
    let once = library.entries().filter(|e| e.count == 1).count();
    Shape {
        activities: library.segments(),
        operators: library.len(),
        top_share,
        seen_once: once as f64 / library.len().max(1) as f64,
        levels: levels(library, DomainOptions::default())
            .iter()
            .map(|l| l.operators.len())
            .collect(),
    }
}

/// One of issue 7's bars: does a study's library meet it?
type Bar = dyn Fn(&Shape) -> bool;

fn quantiles(mut v: Vec<f64>) -> String {
    v.sort_by(f64::total_cmp);
    let q = |p: f64| v[((v.len() - 1) as f64 * p).round() as usize];
    if v.is_empty() {
        return "-".into();
    }
    format!(
        "{:.2} / {:.2} / {:.2} / {:.2} / {:.2}",
        q(0.0),
        q(0.25),
        q(0.5),
        q(0.75),
        q(1.0)
    )
}

fn main() {
    let args: Vec<u64> = std::env::args()
        .skip(1)
        .filter_map(|a| a.parse().ok())
        .collect();
    let first = args.first().copied().unwrap_or(1);
    let count = args.get(1).copied().unwrap_or(100);
    let grouping = if std::env::args().any(|a| a == "runs") {
        Grouping::Runs
    } else {
        Grouping::Settled
    };
    println!("Activities: {}", grouping.name());
    if let Some(lib) = library(simulate::DEFAULT_SEED, grouping) {
        let s = shape(&lib);
        println!("Seed {} (the embedded default):", simulate::DEFAULT_SEED);
        for a in Activity::OPERATOR_ORDER {
            let ranked = lib.ranked_type(a);
            let counts: Vec<String> = ranked.iter().map(|r| r.count().to_string()).collect();
            println!(
                "  {:<6} {:>3} activities, {:>2} operators, counts {}",
                a.name(),
                lib.type_count(a),
                ranked.len(),
                counts.join(" ")
            );
        }
        println!(
            "  {} activities, {} operators, {:.0}% seen once, domains by priority {:?}\n",
            s.activities,
            s.operators,
            s.seen_once * 100.0,
            s.levels
        );
    }
    let shapes: Vec<Shape> = (first..first + count)
        .filter_map(|seed| library(seed, grouping))
        .map(|l| shape(&l))
        .collect();
    let n = shapes.len();
    println!(
        "Seeds {first} to {}: {n} studies of 3 x 4 demonstrations",
        first + count - 1
    );
    println!("quantity: min / Q1 / median / Q3 / max  (bar of issue 7)");
    let col = |f: &dyn Fn(&Shape) -> f64| quantiles(shapes.iter().map(f).collect());
    println!("activities: {}  (>= 100)", col(&|s| s.activities as f64));
    println!("operators: {}  (20 to 40)", col(&|s| s.operators as f64));
    for (i, a) in Activity::OPERATOR_ORDER.iter().enumerate() {
        println!(
            "top share {}: {}  (>= 0.40)",
            a.name(),
            col(&|s| s.top_share[i])
        );
    }
    println!("seen once: {}  (>= 0.25)", col(&|s| s.seen_once));
    println!("levels: {}  (>= 4)", col(&|s| s.levels.len() as f64));
    let bars: [(&str, &Bar); 9] = [
        ("activities >= 100", &|s| s.activities >= 100),
        ("operators 20 to 40", &|s| (20..=40).contains(&s.operators)),
        ("top share Reach", &|s| s.top_share[0] >= 0.4),
        ("top share Take", &|s| s.top_share[1] >= 0.4),
        ("top share Put", &|s| s.top_share[2] >= 0.4),
        ("top share Stack", &|s| s.top_share[3] >= 0.4),
        ("top share Idle", &|s| s.top_share[4] >= 0.4),
        ("seen once >= 0.25", &|s| s.seen_once >= 0.25),
        ("levels >= 4", &|s| s.levels.len() >= 4),
    ];
    for (name, meets) in &bars {
        let missed = shapes.iter().filter(|s| !meets(s)).count();
        println!("missed {name}: {missed} of {n}");
    }
    println!(
        "studies meeting every bar: {} of {n}",
        shapes
            .iter()
            .filter(|s| bars.iter().all(|(_, meets)| meets(s)))
            .count()
    );
}
