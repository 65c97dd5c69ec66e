//! A file written by Fast Downward's translator, read and written back.
//!
//! `fixtures/cubes-tower-3.sas` is the output of Fast Downward 26.6 for the repository's
//! own example (`fast-downward.py --sas-file cubes-tower-3.sas --translate
//! examples/cubes/domain.pddl examples/cubes/tower-3.pddl`). Fast Downward is not run here.

#![allow(clippy::unwrap_used, clippy::expect_used)] // tests fail loudly by design

use task::sas_file::{read, write};
use task::*;

const FIXTURE: &str = include_str!("fixtures/cubes-tower-3.sas");

/// The translator lists an operator's effect lines in its own variable order from before
/// it renumbered the variables; `write` lists them by variable, since [`Operator::effects`]
/// is sorted. This sorts the prevail and effect lines of every operator by variable and
/// leaves every other line alone.
fn sort_operator_lines(text: &str) -> String {
    let lines: Vec<&str> = text.lines().collect();
    let mut out: Vec<&str> = Vec::new();
    let mut i = 0;
    while i < lines.len() {
        out.push(lines[i]);
        if lines[i] == "begin_operator" {
            out.push(lines[i + 1]); // name
            i += 2;
            for var_column in [0, 1] {
                // Prevail lines `VAR VALUE`, then effect lines `0 VAR PRE POST`.
                let count: usize = lines[i].parse().unwrap();
                out.push(lines[i]);
                let mut block = lines[i + 1..i + 1 + count].to_vec();
                block.sort_by_key(|line| {
                    line.split(' ')
                        .nth(var_column)
                        .unwrap()
                        .parse::<u32>()
                        .unwrap()
                });
                out.extend(block);
                i += 1 + count;
            }
        } else {
            i += 1;
        }
    }
    out.join("\n") + "\n"
}

#[test]
fn write_read_gives_back_the_translator_file() {
    let task = read(FIXTURE).unwrap();
    let written = write(&task);
    assert_eq!(written, sort_operator_lines(FIXTURE));
    // The only difference is that order: the file does list some effects out of order.
    assert_ne!(written, FIXTURE);
    assert_eq!(sort_operator_lines(&written), written);
    assert_eq!(read(&written), Ok(task));
}

#[test]
fn reads_the_translator_file() {
    let task = read(FIXTURE).unwrap();
    assert_eq!(
        task.sizes().to_string(),
        "18 variables, 52 facts, 72 operators, 2 mutex groups, 2 goal facts"
    );
    assert!(task.use_costs);
    assert_eq!(task.variables[8].name, "var8");
    assert_eq!(task.variables[8].value_names[5], "Atom on-top(c1, table)");
    let f = |var, value| Fact::new(VarId(var), value);
    assert_eq!(task.goal, vec![f(16, 2), f(17, 3)]);
    assert_eq!(
        task.mutexes[0],
        vec![f(14, 0), f(8, 0), f(16, 0), f(17, 0), f(12, 0)]
    );
    // In the file: prevail `13 0`; effects `0 0 0 1`, `0 9 -1 0`, `0 14 0 1`, `0 8 2 0`.
    let take = task
        .operators
        .iter()
        .find(|op| op.name == "take left c1 c2")
        .unwrap();
    assert_eq!(
        take.preconditions,
        vec![f(0, 0), f(8, 2), f(13, 0), f(14, 0)]
    );
    assert_eq!(take.effects, vec![f(0, 1), f(8, 0), f(9, 0), f(14, 1)]);
    assert_eq!(take.cost, 1);
}

#[test]
fn the_obvious_plan_reaches_the_goal() {
    let task = read(FIXTURE).unwrap();
    let plan = [
        "reach left c2",
        "take left c2 table",
        "stack left c2 c1",
        "reach left c3",
        "take left c3 table",
        "stack left c3 c2",
    ];
    let mut state = task.initial_state.clone();
    let mut cost = 0;
    for step in plan {
        let op = task.operators.iter().find(|op| op.name == step).unwrap();
        assert!(task.is_applicable(op, &state), "{step} is not applicable");
        assert!(!task.is_goal(&state));
        for effect in &op.effects {
            state[effect.var.index()] = effect.value;
        }
        cost += task.cost(op);
    }
    assert!(task.is_goal(&state));
    assert_eq!(cost, 6);
}
