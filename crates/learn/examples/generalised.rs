//! Library sizes with and without generalisation (issue 39): per simulated study of 3
//! participants x 4 demonstrations (the simulator's default parameters), the activities,
//! the operators, and the operators per type (Reach, Take, Put, Stack, Idle), specific
//! and generalised, and the sizes of the domains by priority.
//!
//! ```text
//! cargo run --release -p learn --example generalised -- [FIRST_SEED] [COUNT] [runs] [two-handed]
//! ```
//! `two-handed`: the simulator's two-handed style instead of the default parameters.
//! Defaults: the embedded default seed (7), then seeds 1 to 20; activities `settled`
//! (`runs`: every Idle run an activity of its own). `show`: list the default seed's
//! operators with a short id of their effects up to renaming.

use grounding::GroundingConfig;
use learn::{levels, DomainOptions, Grouping, Library, OperatorForm};
use segment::{Activity, ActivityTree};

fn library(seed: u64, grouping: Grouping, form: OperatorForm) -> Option<Library> {
    let params = if std::env::args().any(|a| a == "two-handed") {
        simulate::Style::TwoHanded.params()
    } else {
        simulate::SimParams::default()
    };
    let study = simulate::study(&params, seed, 3, 4).ok()?;
    let mut library = Library::with_form(learn::DEFAULT_LAMBDA, grouping, form);
    for demo in &study.demonstrations {
        let frames = demo.frames().map(|(f, _)| f).collect();
        learn::add_frames(
            &mut library,
            demo.header(),
            frames,
            &GroundingConfig::default(),
            &ActivityTree::table_one(),
            "",
        );
    }
    Some(library)
}

/// `operators (reach/take/put/stack/idle) [levels]`.
fn sizes(library: &Library) -> String {
    let per_type: Vec<String> = Activity::OPERATOR_ORDER
        .iter()
        .map(|&a| library.ranked_type(a).len().to_string())
        .collect();
    let levels: Vec<usize> = levels(library, DomainOptions::default())
        .iter()
        .map(|l| l.operators.len())
        .collect();
    format!(
        "{:>3} ({:>14}) {:?}",
        library.len(),
        per_type.join("/"),
        levels
    )
}

fn main() {
    let numbers: Vec<u64> = std::env::args()
        .skip(1)
        .filter_map(|a| a.parse().ok())
        .collect();
    let first = numbers.first().copied().unwrap_or(1);
    let count = numbers.get(1).copied().unwrap_or(20);
    let grouping = if std::env::args().any(|a| a == "runs") {
        Grouping::Runs
    } else {
        Grouping::Settled
    };
    println!(
        "Activities: {}. Per seed: activities; specific operators (per type \
         reach/take/put/stack/idle) [domain sizes by priority]; generalised the same.",
        grouping.name()
    );
    if std::env::args().any(|a| a == "show") {
        // The default seed's operators, grouped by their effects up to renaming.
        if let Some(specific) = library(simulate::DEFAULT_SEED, grouping, OperatorForm::Specific) {
            for r in specific.ranked() {
                println!(
                    "{:<8} {:>3}  effects {}  {}",
                    r.name(),
                    r.count(),
                    &learn::effect_key(r.operator()).id()[..6],
                    r.operator()
                );
            }
        }
        return;
    }
    let seeds = std::iter::once(simulate::DEFAULT_SEED).chain(first..first + count);
    let (mut specific_total, mut general_total, mut studies) = (0usize, 0usize, 0usize);
    for (i, seed) in seeds.enumerate() {
        let (Some(specific), Some(general)) = (
            library(seed, grouping, OperatorForm::Specific),
            library(seed, grouping, OperatorForm::Generalised),
        ) else {
            continue;
        };
        println!(
            "seed {seed:>3}{}: {:>3} activities; specific {}; generalised {}",
            if i == 0 { " (default)" } else { "" },
            specific.segments(),
            sizes(&specific),
            sizes(&general)
        );
        if i > 0 {
            specific_total += specific.len();
            general_total += general.len();
            studies += 1;
        }
    }
    if studies > 0 {
        println!(
            "seeds {first} to {}: mean operators {:.1} specific, {:.1} generalised",
            first + count - 1,
            specific_total as f64 / studies as f64,
            general_total as f64 / studies as f64
        );
    }
}
