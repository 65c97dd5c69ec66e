//! From the grounded propositional task and its mutex groups to the finite-domain task.
//!
//! Variables are chosen greedily, as Fast Downward's translator does: the mutex group
//! covering the most atoms not yet covered becomes a variable, until no group covers two;
//! every other fluent atom becomes a binary variable. Two kinds of atoms stay out of a
//! group, because a multi-valued variable cannot express them without conditional
//! effects or multiplying operators out: atoms that occur negated where no positive
//! condition on another atom of the group implies the negation, and atoms that some
//! action deletes without requiring them and without setting another value of the group.
//! Finally, variables that cannot influence the goal (not ancestors of a goal variable in
//! the causal graph of precondition-to-effect arcs) are removed, with the operators left
//! without effects.

use rustc_hash::FxHashSet;
use task::{Fact, Operator, Task, VarId, Variable};

use crate::ground::{atom_text, AtomId, Grounding};
use crate::model::Model;
use crate::variable_order;
use crate::TranslateError;

const NONE_OF_THOSE: &str = "<none of those>";

/// Where a fluent atom lives in the finite-domain task.
#[derive(Debug, Clone, Copy)]
struct Slot {
    var: u32,
    value: u32,
}

pub(crate) struct SasResult {
    pub task: Task,
    /// Variables before irrelevant ones were removed.
    pub variables_before_relevance: usize,
}

/// A task, or the finding that the goal is contradictory.
pub(crate) enum Built {
    Task(SasResult),
    Unsolvable(String),
}

pub(crate) fn build(
    model: &Model,
    g: &Grounding,
    groups: &[Vec<AtomId>],
) -> Result<Built, TranslateError> {
    let n = g.atoms.len();
    // Where each atom occurs negated: the positive conditions beside it (an action's
    // precondition, or the goal).
    let mut negated_beside: Vec<Vec<&[AtomId]>> = vec![Vec::new(); n];
    for a in &g.actions {
        for &x in &a.neg {
            negated_beside[x as usize].push(&a.pre);
        }
    }
    for &x in &g.goal_neg {
        negated_beside[x as usize].push(&g.goal_pos);
    }
    // Actions that delete an atom without requiring it.
    let mut unrequired_deleters: Vec<Vec<u32>> = vec![Vec::new(); n];
    for (i, a) in g.actions.iter().enumerate() {
        for &d in &a.del {
            if a.pre.binary_search(&d).is_err() {
                unrequired_deleters[d as usize].push(i as u32);
            }
        }
    }

    // Greedy choice of groups.
    let mut covered = vec![false; n];
    let mut candidates: Vec<Vec<AtomId>> = groups
        .iter()
        .map(|grp| {
            let mut c: Vec<AtomId> = grp.clone();
            refine(&mut c, g, &unrequired_deleters, &negated_beside);
            c
        })
        .collect();
    let mut containing: Vec<Vec<u32>> = vec![Vec::new(); n];
    for (i, c) in candidates.iter().enumerate() {
        for &a in c {
            containing[a as usize].push(i as u32);
        }
    }
    // Which of the groups covering as many atoms goes first decides the variables, and so
    // LM-cut's values (in freecell, whether "what is on card X" or "where is card X"
    // becomes a variable). The choice follows Fast Downward's translator: groups are
    // bucketed by size in the order of their sorted atoms, the last of the largest bucket
    // goes first, and a group that lost atoms moves to the end of the bucket of its new
    // size when the bucket it was in comes up.
    let rank = lexicographic_rank(model, g, &candidates);
    let mut in_rank_order: Vec<usize> = (0..candidates.len()).collect();
    in_rank_order.sort_by_key(|&i| rank[i]);
    let mut max_size = candidates.iter().map(Vec::len).max().unwrap_or(0);
    let mut by_size: Vec<Vec<usize>> = vec![Vec::new(); max_size + 1];
    for i in in_rank_order {
        by_size[candidates[i].len()].push(i);
    }
    let mut chosen: Vec<Vec<AtomId>> = Vec::new();
    loop {
        let mut best = None;
        while max_size > 1 {
            match by_size[max_size].pop() {
                Some(i) if candidates[i].len() == max_size => {
                    best = Some(i);
                    break;
                }
                Some(i) => by_size[candidates[i].len()].push(i),
                None => max_size -= 1,
            }
        }
        let Some(best) = best else {
            break;
        };
        let group = std::mem::take(&mut candidates[best]);
        let mut touched: Vec<u32> = Vec::new();
        for &a in &group {
            covered[a as usize] = true;
            touched.extend(&containing[a as usize]);
        }
        touched.sort_unstable();
        touched.dedup();
        for i in touched {
            let c = &mut candidates[i as usize];
            c.retain(|&a| !covered[a as usize]);
            refine(c, g, &unrequired_deleters, &negated_beside);
        }
        chosen.push(group);
    }

    // Values in the order of their atoms (as Fast Downward's translator keeps them).
    for group in &mut chosen {
        group.sort_by_cached_key(|&a| atom_key(model, g, a));
    }

    let mut slots: Vec<Option<Slot>> = vec![None; n];
    let mut variables: Vec<Variable> = Vec::new();
    let mut has_none: Vec<Option<u32>> = Vec::new();
    // Whether a variable is an atom's own (values: the atom, its negation).
    let mut binary: Vec<bool> = Vec::new();
    for group in &chosen {
        let var = variables.len() as u32;
        let mut value_names: Vec<String> = group
            .iter()
            .map(|&a| format!("Atom {}", text(model, g, a)))
            .collect();
        for (value, &a) in group.iter().enumerate() {
            slots[a as usize] = Some(Slot {
                var,
                value: value as u32,
            });
        }
        let none = if needs_none_value(g, group) {
            value_names.push(NONE_OF_THOSE.to_string());
            Some(group.len() as u32)
        } else {
            None
        };
        has_none.push(none);
        binary.push(false);
        variables.push(Variable {
            name: format!("var{var}"),
            value_names,
        });
    }
    for a in 0..n as AtomId {
        if g.fluent[a as usize] && slots[a as usize].is_none() {
            let var = variables.len() as u32;
            let t = text(model, g, a);
            variables.push(Variable {
                name: format!("var{var}"),
                value_names: vec![format!("Atom {t}"), format!("NegatedAtom {t}")],
            });
            has_none.push(Some(1));
            binary.push(true);
            slots[a as usize] = Some(Slot { var, value: 0 });
        }
    }
    let slot = |a: AtomId| {
        slots[a as usize]
            .ok_or_else(|| TranslateError::Internal(format!("atom {a} has no variable")))
    };
    let false_value = |s: Slot| has_none[s.var as usize];

    let mut init: Vec<u32> = has_none.iter().map(|h| h.unwrap_or(0)).collect();
    for &a in &g.init {
        let s = slot(a)?;
        init[s.var as usize] = s.value;
    }

    let mut operators = Vec::new();
    'actions: for a in &g.actions {
        let mut pre: Vec<Fact> = Vec::new();
        for &x in &a.pre {
            let s = slot(x)?;
            pre.push(Fact::new(VarId(s.var), s.value));
        }
        for &x in &a.neg {
            let s = slot(x)?;
            if binary[s.var as usize] {
                pre.push(Fact::new(VarId(s.var), 1));
            } else if !pre.iter().any(|f| f.var.0 == s.var && f.value != s.value) {
                // Groups keep a negated atom only where a positive condition on another
                // atom of the group implies the negation (`refine`).
                return Err(TranslateError::Internal(format!(
                    "operator {}: a negated atom of a group without the condition that implies it",
                    action_name(model, a)
                )));
            }
        }
        pre.sort_unstable();
        pre.dedup();
        if pre.windows(2).any(|w| w[0].var == w[1].var) {
            continue; // two values of one variable required: never applicable
        }
        let mut eff: Vec<Fact> = Vec::new();
        for &x in &a.add {
            let s = slot(x)?;
            eff.push(Fact::new(VarId(s.var), s.value));
        }
        eff.sort_unstable();
        eff.dedup();
        if eff.windows(2).any(|w| w[0].var == w[1].var) {
            return Err(TranslateError::Internal(format!(
                "operator {} sets a variable twice",
                action_name(model, a)
            )));
        }
        for &x in &a.del {
            let s = slot(x)?;
            if eff.iter().any(|f| f.var.0 == s.var) {
                continue; // the add of another value of the variable overrides
            }
            let value = false_value(s).ok_or_else(|| {
                TranslateError::Internal(format!(
                    "operator {} deletes from an exactly-one group",
                    action_name(model, a)
                ))
            })?;
            eff.push(Fact::new(VarId(s.var), value));
        }
        eff.sort_unstable();
        // An effect that sets the value the precondition requires changes nothing.
        eff.retain(|f| !pre.contains(f));
        if eff.is_empty() {
            continue 'actions;
        }
        operators.push(Operator {
            name: action_name(model, a),
            preconditions: pre,
            effects: eff,
            cost: a.cost,
        });
    }

    // Operators in the order of their names as Fast Downward's translator sorts them,
    // `(name arg ...)`, and `(name )` without arguments: the order decides ties in
    // LM-cut's exploration (freecell 3-3 expands ten times fewer states in this order than
    // in grounding order).
    operators.sort_by_cached_key(|op| {
        if op.name.contains(' ') {
            format!("({})", op.name)
        } else {
            format!("({} )", op.name)
        }
    });

    let mut goal: Vec<Fact> = Vec::new();
    for &x in &g.goal_pos {
        let s = slot(x)?;
        goal.push(Fact::new(VarId(s.var), s.value));
    }
    for &x in &g.goal_neg {
        let s = slot(x)?;
        if binary[s.var as usize] {
            goal.push(Fact::new(VarId(s.var), 1));
        } else if !goal.iter().any(|f| f.var.0 == s.var && f.value != s.value) {
            return Err(TranslateError::Internal(
                "a negated goal atom of a group without the goal atom that implies it".into(),
            ));
        }
    }
    goal.sort_unstable();
    goal.dedup();
    if goal.windows(2).any(|w| w[0].var == w[1].var) {
        return Ok(Built::Unsolvable(
            "the goal requires two mutually exclusive atoms".into(),
        ));
    }

    let mutexes: Vec<Vec<Fact>> = groups
        .iter()
        .map(|grp| {
            grp.iter()
                .filter_map(|&a| slots[a as usize].map(|s| Fact::new(VarId(s.var), s.value)))
                .collect::<Vec<Fact>>()
        })
        .filter(|grp| grp.len() >= 2)
        .collect();

    let task = Task::new(variables, mutexes, init, goal, operators, model.use_costs);
    let variables_before_relevance = task.variables.len();
    let task = variable_order::by_atoms(task);
    Ok(Built::Task(SasResult {
        task: variable_order::by_causal_graph(keep_relevant(task)),
        variables_before_relevance,
    }))
}

/// Drops atoms of `group` that some action deletes without requiring them and without
/// adding another atom of the group; repeats until stable (dropping an atom can make
/// another unsafe).
/// Shrinks a candidate group to atoms a multi-valued variable can hold: atoms deleted
/// without being required only where the deleting action adds another atom of the group
/// (`remove_unsafely_deleted`), and atoms that occur negated only where a positive
/// condition beside the negation is another atom of the group, which implies it (a
/// variable cannot say "not this value" otherwise). The learned cube-stacking domains
/// require `(not (inhand ?h ?c))` next to `(handopen ?h)`: with this, "the hand is open
/// or holds one cube" becomes one variable, as in Fast Downward's translation. Repeats
/// until neither removes anything, since each removal can take away another atom's
/// reason to stay.
fn refine(
    group: &mut Vec<AtomId>,
    g: &Grounding,
    unrequired: &[Vec<u32>],
    negated_beside: &[Vec<&[AtomId]>],
) {
    loop {
        let before = group.len();
        let members: FxHashSet<AtomId> = group.iter().copied().collect();
        group.retain(|&x| {
            negated_beside[x as usize]
                .iter()
                .all(|positive| positive.iter().any(|&y| y != x && members.contains(&y)))
        });
        remove_unsafely_deleted(group, g, unrequired);
        if group.len() == before {
            return;
        }
    }
}

fn remove_unsafely_deleted(group: &mut Vec<AtomId>, g: &Grounding, unrequired: &[Vec<u32>]) {
    if group.iter().all(|&a| unrequired[a as usize].is_empty()) {
        return;
    }
    loop {
        let members: FxHashSet<AtomId> = group.iter().copied().collect();
        let before = group.len();
        group.retain(|&a| {
            unrequired[a as usize].iter().all(|&act| {
                g.actions[act as usize]
                    .add
                    .iter()
                    .any(|x| members.contains(x))
            })
        });
        if group.len() == before {
            return;
        }
    }
}

/// A group needs a "none of those" value unless exactly one of its atoms is true
/// initially and every action that deletes one adds another.
fn needs_none_value(g: &Grounding, group: &[AtomId]) -> bool {
    let members: FxHashSet<AtomId> = group.iter().copied().collect();
    let initially = g.init.iter().filter(|a| members.contains(a)).count();
    if initially != 1 {
        return true;
    }
    g.actions.iter().any(|a| {
        a.del.iter().any(|d| members.contains(d)) && !a.add.iter().any(|x| members.contains(x))
    })
}

/// For each group, its position among all groups ordered by their sorted atoms.
fn lexicographic_rank(model: &Model, g: &Grounding, groups: &[Vec<AtomId>]) -> Vec<usize> {
    let keys: Vec<Vec<(String, Vec<String>)>> = groups
        .iter()
        .map(|grp| {
            let mut atoms: Vec<_> = grp.iter().map(|&a| atom_key(model, g, a)).collect();
            atoms.sort_unstable();
            atoms
        })
        .collect();
    let mut order: Vec<usize> = (0..groups.len()).collect();
    order.sort_by(|&a, &b| keys[a].cmp(&keys[b]).then(a.cmp(&b)));
    let mut rank = vec![0; groups.len()];
    for (position, &group) in order.iter().enumerate() {
        rank[group] = position;
    }
    rank
}

/// What atoms are ordered by: predicate name, then argument names.
fn atom_key(model: &Model, g: &Grounding, a: AtomId) -> (String, Vec<String>) {
    (
        model.predicates[g.atoms.pred(a).0 as usize].name.clone(),
        g.atoms
            .args(a)
            .iter()
            .map(|&o| model.objects[o as usize].clone())
            .collect(),
    )
}

fn text(model: &Model, g: &Grounding, a: AtomId) -> String {
    atom_text(model, g.atoms.pred(a), g.atoms.args(a).iter().copied())
}

fn action_name(model: &Model, a: &crate::ground::GroundAction) -> String {
    let mut name = model.schemas[a.schema as usize].name.clone();
    for o in &a.args {
        name.push(' ');
        name.push_str(&model.objects[o.0 as usize]);
    }
    name
}

/// Keeps the variables that are goal variables or ancestors of one in the causal graph
/// (arcs from an operator's precondition variables to its effect variables), and
/// renumbers them: a variable no relevant operator reads can never matter for reaching
/// the goal, even if relevant operators also change it.
fn keep_relevant(task: Task) -> Task {
    let nvars = task.variables.len();
    let mut parents: Vec<Vec<u32>> = vec![Vec::new(); nvars];
    for op in &task.operators {
        for e in &op.effects {
            for p in &op.preconditions {
                if p.var != e.var {
                    parents[e.var.index()].push(p.var.0);
                }
            }
        }
    }
    let mut keep = vec![false; nvars];
    let mut stack: Vec<u32> = task.goal.iter().map(|f| f.var.0).collect();
    while let Some(v) = stack.pop() {
        if !keep[v as usize] {
            keep[v as usize] = true;
            stack.extend(parents[v as usize].iter().copied());
        }
    }
    let mut new_index = vec![u32::MAX; nvars];
    let mut count = 0;
    for v in 0..nvars {
        if keep[v] {
            new_index[v] = count;
            count += 1;
        }
    }
    let map = |facts: &[Fact]| -> Vec<Fact> {
        facts
            .iter()
            .filter(|f| keep[f.var.index()])
            .map(|f| Fact::new(VarId(new_index[f.var.index()]), f.value))
            .collect()
    };
    let variables = task
        .variables
        .into_iter()
        .enumerate()
        .filter(|(v, _)| keep[*v])
        .map(|(v, mut var)| {
            var.name = format!("var{}", new_index[v]);
            var
        })
        .collect();
    let operators = task
        .operators
        .into_iter()
        .filter_map(|op| {
            let effects = map(&op.effects);
            (!effects.is_empty()).then(|| Operator {
                preconditions: map(&op.preconditions),
                effects,
                ..op
            })
        })
        .collect();
    Task {
        variables,
        mutexes: task
            .mutexes
            .iter()
            .map(|m| map(m))
            .filter(|m| m.len() >= 2)
            .collect(),
        initial_state: task
            .initial_state
            .iter()
            .enumerate()
            .filter(|(v, _)| keep[*v])
            .map(|(_, &x)| x)
            .collect(),
        goal: map(&task.goal),
        operators,
        use_costs: task.use_costs,
    }
}
