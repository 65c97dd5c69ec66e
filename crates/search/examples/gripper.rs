//! Times A* on gripper tasks built in code, shaped as Fast Downward's translator makes
//! them (robot room; per ball its room or gripper; per gripper free or not).
//!
//! `cargo run --release -p search --example gripper -- [BALLS] [SEARCH]`, e.g.
//! `-- 10 'astar(blind())'`. IPC gripper probNN has 2 * NN + 2 balls.

use std::time::Instant;

use search::{parse_search, search, Outcome, SearchLimits};
use task::{Fact, Operator, Task, VarId, Variable};

fn gripper(balls: u32) -> Task {
    let robot = VarId(0);
    let ball = |b: u32| VarId(1 + b);
    let free = |g: u32| VarId(1 + balls + g);
    let rooms = ["rooma", "roomb"];
    let grippers = ["left", "right"];
    let mut variables = vec![Variable {
        name: "var0".into(),
        value_names: rooms
            .iter()
            .map(|r| format!("Atom at-robby({r})"))
            .collect(),
    }];
    for b in 0..balls {
        let mut values: Vec<String> = rooms
            .iter()
            .map(|r| format!("Atom at(ball{b}, {r})"))
            .collect();
        values.extend(grippers.iter().map(|g| format!("Atom carry(ball{b}, {g})")));
        variables.push(Variable {
            name: format!("var{}", 1 + b),
            value_names: values,
        });
    }
    for g in grippers {
        variables.push(Variable::binary(&format!("free({g})")));
    }
    let mut operators = Vec::new();
    for (from, f) in rooms.iter().enumerate() {
        for (to, t) in rooms.iter().enumerate() {
            if from != to {
                operators.push(Operator {
                    name: format!("move {f} {t}"),
                    preconditions: vec![Fact::new(robot, from as u32)],
                    effects: vec![Fact::new(robot, to as u32)],
                    cost: 1,
                });
            }
        }
    }
    for b in 0..balls {
        for (r, room) in rooms.iter().enumerate() {
            for (g, gripper) in grippers.iter().enumerate() {
                let (r, g) = (r as u32, g as u32);
                operators.push(Operator {
                    name: format!("pick ball{b} {room} {gripper}"),
                    preconditions: vec![
                        Fact::new(robot, r),
                        Fact::new(ball(b), r),
                        Fact::new(free(g), 0),
                    ],
                    effects: vec![Fact::new(ball(b), 2 + g), Fact::new(free(g), 1)],
                    cost: 1,
                });
                operators.push(Operator {
                    name: format!("drop ball{b} {room} {gripper}"),
                    preconditions: vec![Fact::new(robot, r), Fact::new(ball(b), 2 + g)],
                    effects: vec![Fact::new(ball(b), r), Fact::new(free(g), 0)],
                    cost: 1,
                });
            }
        }
    }
    let mut initial_state = vec![0];
    initial_state.extend((0..balls).map(|_| 0));
    initial_state.extend([0, 0]);
    Task {
        variables,
        mutexes: vec![],
        initial_state,
        goal: (0..balls).map(|b| Fact::new(ball(b), 1)).collect(),
        operators,
        use_costs: false,
    }
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let mut args = std::env::args().skip(1);
    let balls: u32 = args.next().map_or(Ok(8), |a| a.parse())?;
    let config = parse_search(&args.next().unwrap_or_else(|| "astar(blind())".into()))?;
    let task = gripper(balls);
    let start = Instant::now();
    let result = search(
        &task,
        &config,
        &SearchLimits::default(),
        Some(&mut |p| {
            println!(
                "f = {}, {} evaluated, {} expanded",
                p.f, p.evaluated, p.expanded
            )
        }),
    )?;
    let elapsed = start.elapsed();
    let s = &result.statistics;
    match &result.outcome {
        Outcome::Solved(plan) => {
            println!("Solution found: cost {}, {} steps", plan.cost, plan.len())
        }
        other => println!("{other:?}"),
    }
    println!(
        "{config} on gripper with {balls} balls: {} expanded, {} evaluated, {} generated, {} states",
        s.expanded, s.evaluated, s.generated, s.registered_states
    );
    println!(
        "{:.3} s, {:.3} us per expansion",
        elapsed.as_secs_f64(),
        elapsed.as_secs_f64() * 1e6 / s.expanded.max(1) as f64
    );
    Ok(())
}
