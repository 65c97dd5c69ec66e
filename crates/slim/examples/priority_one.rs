//! Does the priority-1 domain plan the paper's five goals, over many simulated studies?
//! Per seed: simulate 3 participants x 4 demonstrations (default parameters), learn the
//! library, build the domain of priority 1 (the most frequent operator of each type) and
//! plan goals 1 to 5 (towers of 2 to 6 cubes, one hand) with `astar(lmcut())`.
//!
//! ```text
//! cargo run --release -p slim --example priority_one -- [FIRST_SEED] [COUNT] [runs]
//! ```
//! Defaults: seeds 1 to 100, activities `settled` (`runs`: every Idle run apart). Each
//! goal gets 10 s; a goal that is not planned within it counts as not planned.

use std::time::{Duration, Instant};

use grounding::GroundingConfig;
use learn::{levels, DomainOptions, Grouping, Library, Scene};
use segment::ActivityTree;
use slim::{plan_task, translate_checked, Outcome, RunLimits, Translated};

fn library(seed: u64, grouping: Grouping) -> Option<Library> {
    let study = simulate::study(&simulate::SimParams::default(), seed, 3, 4).ok()?;
    let mut library = Library::with_grouping(learn::DEFAULT_LAMBDA, grouping);
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

fn main() {
    let numbers: Vec<u64> = std::env::args()
        .skip(1)
        .filter_map(|a| a.parse().ok())
        .collect();
    let first = numbers.first().copied().unwrap_or(1);
    let count = numbers.get(1).copied().unwrap_or(100);
    let grouping = if std::env::args().any(|a| a == "runs") {
        Grouping::Runs
    } else {
        Grouping::Settled
    };
    let Ok(config) = search::parse_search("astar(lmcut())") else {
        return;
    };
    let scene = Scene::with_hands(learn::DEFAULT_CUBES, 1);
    let mut all_goals = 0;
    let mut per_goal = [0usize; 5];
    let mut studies = 0;
    for seed in first..first + count {
        let Some(lib) = library(seed, grouping) else {
            continue;
        };
        studies += 1;
        let Some(level) = levels(&lib, DomainOptions::default()).into_iter().next() else {
            continue;
        };
        let domain = learn::domain("demoplan", &level.operators);
        let mut planned = Vec::new();
        for goal in 1..=5 {
            let tower = learn::paper_goal_tower(goal);
            let problem = learn::problem(
                &format!("goal-{goal}"),
                "demoplan",
                &scene,
                &learn::tower_goal(&scene, &tower),
            );
            let start = Instant::now();
            let outcome = match translate_checked(&domain, &problem) {
                Translated::Task(task, _) => {
                    plan_task(
                        &task,
                        &config,
                        &RunLimits::time(Duration::from_secs(10)).starting_at(start),
                    )
                    .outcome
                }
                Translated::Done(run) => run.outcome,
            };
            if outcome == Outcome::Solved {
                per_goal[goal - 1] += 1;
                planned.push(goal);
            }
        }
        if planned.len() == 5 {
            all_goals += 1;
        }
        println!("seed {seed}: priority 1 plans goals {planned:?}");
    }
    println!(
        "Activities {}: the priority-1 domain plans all five goals in {all_goals} of \
         {studies} studies; per goal {per_goal:?}",
        grouping.name()
    );
}
