//! The finite-domain planning task that translation produces and search consumes.
//!
//! A task has variables with finite domains, an initial state assigning each a value, a
//! goal (a partial assignment) and operators with preconditions (a partial assignment),
//! effects (assignments) and a non-negative 64-bit cost. This is Fast Downward's SAS+
//! task without axioms and conditional effects, which the supported PDDL fragment never
//! produces. [`sas_file`] reads and writes Fast Downward's `output.sas` format.
//!
//! ```
//! use task::*;
//! let task = Task {
//!     variables: vec![Variable::binary("at-a")],
//!     mutexes: vec![],
//!     initial_state: vec![1],
//!     goal: vec![Fact::new(VarId(0), 0)],
//!     operators: vec![Operator {
//!         name: "go".into(),
//!         preconditions: vec![Fact::new(VarId(0), 1)],
//!         effects: vec![Fact::new(VarId(0), 0)],
//!         cost: 1,
//!     }],
//!     use_costs: false,
//! };
//! task.validate()?;
//! assert!(!task.is_goal(&task.initial_state));
//! # Ok::<(), task::TaskError>(())
//! ```

pub mod limits;
pub mod memory;
pub mod sas_file;
#[cfg(feature = "testing")]
pub mod testing;
pub mod units;

pub use limits::{deadline_after, Deadline, Limit, Limits};

use std::fmt;

/// Index of a variable in [`Task::variables`].
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct VarId(pub u32);

/// Index of an operator in [`Task::operators`].
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct OpId(pub u32);

impl VarId {
    /// As an index into a vector.
    pub fn index(self) -> usize {
        self.0 as usize
    }
}

impl OpId {
    /// As an index into a vector.
    pub fn index(self) -> usize {
        self.0 as usize
    }
}

/// A variable-value pair: "variable `var` has value `value`".
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct Fact {
    /// The variable.
    pub var: VarId,
    /// The value, below the variable's domain size.
    pub value: u32,
}

impl Fact {
    /// The fact `var = value`.
    pub fn new(var: VarId, value: u32) -> Fact {
        Fact { var, value }
    }
}

/// A state variable.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Variable {
    /// A name for logs and files (`var3` in Fast Downward's files).
    pub name: String,
    /// What each value means, e.g. `Atom on(a, b)`, `NegatedAtom clear(a)` or
    /// `<none of those>`; its length is the domain size.
    pub value_names: Vec<String>,
}

impl Variable {
    /// A variable with values `0` (`Atom NAME`) and `1` (`NegatedAtom NAME`).
    pub fn binary(name: &str) -> Variable {
        Variable {
            name: name.to_string(),
            value_names: vec![format!("Atom {name}"), format!("NegatedAtom {name}")],
        }
    }

    /// The number of values.
    pub fn domain_size(&self) -> u32 {
        self.value_names.len() as u32
    }
}

/// An operator: applicable where its preconditions hold; sets its effects.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Operator {
    /// The ground action, as a plan line says it without parentheses: `pick-up a`.
    pub name: String,
    /// Sorted by variable, at most one fact per variable.
    pub preconditions: Vec<Fact>,
    /// Sorted by variable, at most one fact per variable.
    pub effects: Vec<Fact>,
    /// The cost; 64 bits since IPC costs reach millions and plans are long.
    pub cost: u64,
}

/// A finite-domain planning task.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Task {
    /// The variables.
    pub variables: Vec<Variable>,
    /// Groups of facts of which at most one is true in any reachable state, beyond those
    /// implied by the variables themselves (kept for interchange; search needs none).
    pub mutexes: Vec<Vec<Fact>>,
    /// One value per variable.
    pub initial_state: Vec<u32>,
    /// Sorted by variable, at most one fact per variable.
    pub goal: Vec<Fact>,
    /// The operators.
    pub operators: Vec<Operator>,
    /// True if the task has action costs (`:metric`); otherwise every cost is 1 and plans
    /// are reported with "unit cost".
    pub use_costs: bool,
}

/// A task that breaks its own invariants.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum TaskError {
    /// A fact names a variable or value that does not exist.
    #[error("{context}: fact {var}={value} is out of range")]
    FactOutOfRange {
        /// Where.
        context: String,
        /// The variable index.
        var: u32,
        /// The value.
        value: u32,
    },
    /// A partial assignment names a variable twice or is not sorted.
    #[error("{context}: facts must be sorted by variable, one per variable")]
    Unsorted {
        /// Where.
        context: String,
    },
    /// The initial state has the wrong length.
    #[error("initial state has {found} values for {expected} variables")]
    InitialState {
        /// Number of variables.
        expected: usize,
        /// Number of values.
        found: usize,
    },
    /// A variable with an empty domain.
    #[error("variable {0} has no values")]
    EmptyDomain(u32),
}

impl Task {
    /// A task from its parts, in the order of [`Task`]'s fields (and of an output.sas
    /// file's sections); it is not validated ([`Task::validate`]).
    pub fn new(
        variables: Vec<Variable>,
        mutexes: Vec<Vec<Fact>>,
        initial_state: Vec<u32>,
        goal: Vec<Fact>,
        operators: Vec<Operator>,
        use_costs: bool,
    ) -> Task {
        Task {
            variables,
            mutexes,
            initial_state,
            goal,
            operators,
            use_costs,
        }
    }

    /// For each variable, its position when variables are sorted by their atoms: the
    /// `Atom predicate(arguments)` value names, read as (predicate, arguments), each
    /// variable's sorted, variables compared by those lists (ties, such as variables without
    /// atom names, by index). This is how Fast Downward's translator numbers variables before
    /// it orders them by the causal graph, so it can be recovered from any translation,
    /// demoplan's or Fast Downward's output.sas.
    pub fn atom_order_ranks(&self) -> Vec<u32> {
        fn atom(value_name: &str) -> Option<(&str, Vec<&str>)> {
            let atom = value_name.strip_prefix("Atom ")?;
            Some(match atom.split_once('(') {
                Some((predicate, rest)) => {
                    let args = rest.strip_suffix(')').unwrap_or(rest);
                    let args = if args.is_empty() {
                        Vec::new()
                    } else {
                        args.split(", ").collect()
                    };
                    (predicate, args)
                }
                None => (atom, Vec::new()),
            })
        }
        let keys: Vec<Vec<(&str, Vec<&str>)>> = self
            .variables
            .iter()
            .map(|v| {
                let mut atoms: Vec<_> = v.value_names.iter().filter_map(|n| atom(n)).collect();
                atoms.sort_unstable();
                atoms
            })
            .collect();
        let mut order: Vec<usize> = (0..keys.len()).collect();
        order.sort_by(|&a, &b| keys[a].cmp(&keys[b]).then(a.cmp(&b)));
        let mut rank = vec![0u32; keys.len()];
        for (position, &var) in order.iter().enumerate() {
            rank[var] = position as u32;
        }
        rank
    }

    /// Checks the invariants documented on the fields.
    pub fn validate(&self) -> Result<(), TaskError> {
        for (i, v) in self.variables.iter().enumerate() {
            if v.value_names.is_empty() {
                return Err(TaskError::EmptyDomain(i as u32));
            }
        }
        if self.initial_state.len() != self.variables.len() {
            return Err(TaskError::InitialState {
                expected: self.variables.len(),
                found: self.initial_state.len(),
            });
        }
        let init: Vec<Fact> = self
            .initial_state
            .iter()
            .enumerate()
            .map(|(i, &v)| Fact::new(VarId(i as u32), v))
            .collect();
        self.check_facts(&init, "initial state")?;
        self.check_partial(&self.goal, "goal")?;
        for op in &self.operators {
            self.check_partial(
                &op.preconditions,
                &format!("operator `{}` preconditions", op.name),
            )?;
            self.check_partial(&op.effects, &format!("operator `{}` effects", op.name))?;
        }
        for (i, group) in self.mutexes.iter().enumerate() {
            self.check_facts(group, &format!("mutex group {i}"))?;
        }
        Ok(())
    }

    fn check_facts(&self, facts: &[Fact], context: &str) -> Result<(), TaskError> {
        for f in facts {
            let ok = self
                .variables
                .get(f.var.index())
                .is_some_and(|v| f.value < v.domain_size());
            if !ok {
                return Err(TaskError::FactOutOfRange {
                    context: context.to_string(),
                    var: f.var.0,
                    value: f.value,
                });
            }
        }
        Ok(())
    }

    fn check_partial(&self, facts: &[Fact], context: &str) -> Result<(), TaskError> {
        self.check_facts(facts, context)?;
        if facts.windows(2).any(|w| w[0].var >= w[1].var) {
            return Err(TaskError::Unsorted {
                context: context.to_string(),
            });
        }
        Ok(())
    }

    /// True if `state` (one value per variable) satisfies the goal.
    pub fn is_goal(&self, state: &[u32]) -> bool {
        self.goal.iter().all(|f| state[f.var.index()] == f.value)
    }

    /// True if the operator's preconditions hold in `state`.
    pub fn is_applicable(&self, op: &Operator, state: &[u32]) -> bool {
        op.preconditions
            .iter()
            .all(|f| state[f.var.index()] == f.value)
    }

    /// The cost search uses for `op`: its cost, or 1 without action costs.
    pub fn cost(&self, op: &Operator) -> u64 {
        if self.use_costs {
            op.cost
        } else {
            1
        }
    }

    /// Sizes for logs, in Fast Downward's words.
    pub fn sizes(&self) -> TaskSizes {
        TaskSizes {
            variables: self.variables.len(),
            facts: self.variables.iter().map(|v| v.value_names.len()).sum(),
            operators: self.operators.len(),
            mutex_groups: self.mutexes.len(),
            goal_facts: self.goal.len(),
        }
    }
}

/// The sizes of a task.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct TaskSizes {
    /// Variables.
    pub variables: usize,
    /// Facts: the sum of the domain sizes.
    pub facts: usize,
    /// Operators.
    pub operators: usize,
    /// Mutex groups.
    pub mutex_groups: usize,
    /// Goal facts.
    pub goal_facts: usize,
}

impl fmt::Display for TaskSizes {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "{} variables, {} facts, {} operators, {} mutex groups, {} goal facts",
            self.variables, self.facts, self.operators, self.mutex_groups, self.goal_facts
        )
    }
}
