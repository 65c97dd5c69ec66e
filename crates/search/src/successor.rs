//! Successor generation through a decision tree over variables.
//!
//! Each node of the tree lists the operators whose preconditions are all tested on the
//! way to it, and may switch on one variable: one child per value of that variable, for
//! the operators with a precondition on it, and a "don't care" child for those without.
//! Along every path the variables switched on strictly increase, so the depth is at most
//! the number of variables, and a lookup visits only nodes whose tests hold: time
//! O(visited nodes + applicable operators) instead of O(all preconditions).

use task::{OpId, Task};

const NONE: u32 = u32::MAX;

#[derive(Debug, Clone, Copy)]
struct Node {
    /// The variable switched on, or `NONE` for a leaf.
    var: u32,
    /// Children for values `0..domain size` in `children[children_start..]` (`NONE` where
    /// no operator needs that value).
    children_start: u32,
    /// The child for operators without a precondition on `var`, or `NONE`.
    dont_care: u32,
    /// The operators applicable once this node is reached: `ops[ops_start..ops_end]`.
    ops_start: u32,
    ops_end: u32,
}

/// Finds the operators applicable in a state, without testing every operator.
///
/// Built once per task in O(total preconditions * depth); holds a reusable traversal stack,
/// so [`applicable`](Self::applicable) allocates nothing once buffers have grown.
#[derive(Debug, Clone)]
pub struct SuccessorGenerator {
    nodes: Vec<Node>,
    children: Vec<u32>,
    ops: Vec<OpId>,
    stack: Vec<u32>,
}

impl SuccessorGenerator {
    /// The generator for `task`, whose preconditions must be sorted by variable with
    /// values inside their domains (as [`Task::validate`] checks).
    pub fn new(task: &Task) -> SuccessorGenerator {
        let domain = |var: u32| {
            task.variables
                .get(var as usize)
                .map_or(0, |v| v.domain_size())
        };
        let mut nodes = vec![empty_node()];
        let mut children: Vec<u32> = Vec::new();
        let mut ops: Vec<OpId> = Vec::new();
        // (node, operators with how many of their preconditions are already tested).
        let all: Vec<(u32, u32)> = (0..task.operators.len() as u32).map(|op| (op, 0)).collect();
        let mut work: Vec<(u32, Vec<(u32, u32)>)> = vec![(0, all)];
        while let Some((node, items)) = work.pop() {
            let pre = |op: u32| &task.operators[op as usize].preconditions;
            let ops_start = ops.len() as u32;
            let mut rest = Vec::with_capacity(items.len());
            for (op, pos) in items {
                if pos as usize == pre(op).len() {
                    ops.push(OpId(op));
                } else {
                    rest.push((op, pos));
                }
            }
            let mut this = Node {
                ops_start,
                ops_end: ops.len() as u32,
                ..empty_node()
            };
            if let Some(var) = rest
                .iter()
                .map(|&(op, pos)| pre(op)[pos as usize].var.0)
                .min()
            {
                let size = domain(var) as usize;
                let mut groups: Vec<Vec<(u32, u32)>> = vec![Vec::new(); size];
                let mut dont_care = Vec::new();
                for (op, pos) in rest {
                    let fact = pre(op)[pos as usize];
                    if fact.var.0 == var {
                        if let Some(group) = groups.get_mut(fact.value as usize) {
                            group.push((op, pos + 1));
                        }
                        // A value outside the domain never holds: the operator is dropped.
                    } else {
                        dont_care.push((op, pos));
                    }
                }
                this.var = var;
                this.children_start = children.len() as u32;
                children.resize(children.len() + size, NONE);
                for (value, group) in groups.into_iter().enumerate() {
                    if !group.is_empty() {
                        let child = nodes.len() as u32;
                        nodes.push(empty_node());
                        children[this.children_start as usize + value] = child;
                        work.push((child, group));
                    }
                }
                if !dont_care.is_empty() {
                    let child = nodes.len() as u32;
                    nodes.push(empty_node());
                    this.dont_care = child;
                    work.push((child, dont_care));
                }
            }
            nodes[node as usize] = this;
        }
        SuccessorGenerator {
            nodes,
            children,
            ops,
            stack: Vec::new(),
        }
    }

    /// Replaces `out` with the operators applicable in `state` (one value per variable),
    /// in Fast Downward's order: sorted by their sorted preconditions, then by index (a
    /// node's own operators, then its value child's, then its don't-care child's).
    /// `ipdb`'s random walks rely on that order.
    #[inline]
    pub fn applicable(&mut self, state: &[u32], out: &mut Vec<OpId>) {
        out.clear();
        let ops = &self.ops;
        traverse(
            &self.nodes,
            &self.children,
            state,
            &mut self.stack,
            |node| {
                out.extend_from_slice(&ops[node.ops_start as usize..node.ops_end as usize]);
            },
        );
    }

    /// The nodes a lookup in `state` visits (a measure of its cost).
    pub(crate) fn visited_nodes(&self, state: &[u32]) -> usize {
        let mut visited = 0;
        traverse(&self.nodes, &self.children, state, &mut Vec::new(), |_| {
            visited += 1;
        });
        visited
    }

    /// The number of tree nodes (for logs).
    pub fn num_nodes(&self) -> usize {
        self.nodes.len()
    }
}

/// Visits the nodes whose tests hold in `state`, depth first: a node, then its child for
/// the state's value, then its don't-care child.
#[inline]
fn traverse(
    nodes: &[Node],
    children: &[u32],
    state: &[u32],
    stack: &mut Vec<u32>,
    mut visit: impl FnMut(&Node),
) {
    stack.clear();
    stack.push(0);
    while let Some(n) = stack.pop() {
        let node = &nodes[n as usize];
        visit(node);
        if node.var != NONE {
            if node.dont_care != NONE {
                stack.push(node.dont_care);
            }
            let child = children[node.children_start as usize + state[node.var as usize] as usize];
            if child != NONE {
                stack.push(child);
            }
        }
    }
}

fn empty_node() -> Node {
    Node {
        var: NONE,
        children_start: 0,
        dont_care: NONE,
        ops_start: 0,
        ops_end: 0,
    }
}

#[cfg(test)]
pub(crate) mod tests {
    use super::*;
    use task::{Fact, Operator, VarId, Variable};

    /// A small deterministic generator for tests.
    pub(crate) struct Rng(pub u64);

    impl Rng {
        pub(crate) fn below(&mut self, n: u32) -> u32 {
            self.0 = self
                .0
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            ((self.0 >> 33) % u64::from(n.max(1))) as u32
        }
    }

    /// A random valid task: `vars` variables of domain sizes 1..=5, `ops` operators.
    pub(crate) fn random_task(rng: &mut Rng, vars: u32, ops: u32) -> Task {
        let sizes: Vec<u32> = (0..vars).map(|_| 1 + rng.below(5)).collect();
        let variables = sizes
            .iter()
            .enumerate()
            .map(|(i, &s)| Variable {
                name: format!("var{i}"),
                value_names: (0..s).map(|v| format!("v{v}")).collect(),
            })
            .collect();
        let partial = |rng: &mut Rng, density: u32| -> Vec<Fact> {
            let mut facts = Vec::new();
            for v in 0..vars {
                if rng.below(100) < density {
                    facts.push(Fact::new(VarId(v), rng.below(sizes[v as usize])));
                }
            }
            facts
        };
        let operators = (0..ops)
            .map(|i| Operator {
                name: format!("op{i}"),
                preconditions: partial(rng, 40),
                effects: partial(rng, 30),
                cost: u64::from(rng.below(4)),
            })
            .collect();
        let goal = partial(rng, 30);
        let initial_state = sizes.iter().map(|&s| rng.below(s)).collect();
        let task = Task {
            variables,
            mutexes: vec![],
            initial_state,
            goal,
            operators,
            use_costs: rng.below(2) == 0,
        };
        task.validate().unwrap();
        task
    }

    #[test]
    fn matches_a_naive_scan_on_random_states() {
        let mut rng = Rng(7);
        let mut out = Vec::new();
        for round in 0..200 {
            let task = random_task(&mut rng, 1 + round % 12, round * 3 % 60);
            let mut generator = SuccessorGenerator::new(&task);
            for _ in 0..50 {
                let state: Vec<u32> = task
                    .variables
                    .iter()
                    .map(|v| rng.below(v.domain_size()))
                    .collect();
                generator.applicable(&state, &mut out);
                let mut got = out.clone();
                got.sort();
                let expected: Vec<OpId> = task
                    .operators
                    .iter()
                    .enumerate()
                    .filter(|(_, op)| task.is_applicable(op, &state))
                    .map(|(i, _)| OpId(i as u32))
                    .collect();
                assert_eq!(got, expected, "task {task:?} state {state:?}");
            }
        }
    }

    #[test]
    fn empty_task_and_no_precondition_operators() {
        let task = Task {
            variables: vec![Variable::binary("a")],
            mutexes: vec![],
            initial_state: vec![0],
            goal: vec![],
            operators: vec![],
            use_costs: false,
        };
        let mut generator = SuccessorGenerator::new(&task);
        let mut out = vec![OpId(9)];
        generator.applicable(&[0], &mut out);
        assert!(out.is_empty());

        let op = |pre: Vec<Fact>| Operator {
            name: "o".into(),
            preconditions: pre,
            effects: vec![Fact::new(VarId(0), 1)],
            cost: 1,
        };
        let task = Task {
            operators: vec![op(vec![]), op(vec![Fact::new(VarId(0), 0)]), op(vec![])],
            ..task
        };
        let mut generator = SuccessorGenerator::new(&task);
        generator.applicable(&[0], &mut out);
        out.sort();
        assert_eq!(out, vec![OpId(0), OpId(1), OpId(2)]);
        generator.applicable(&[1], &mut out);
        out.sort();
        assert_eq!(out, vec![OpId(0), OpId(2)]);
    }
}
