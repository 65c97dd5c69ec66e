//! Domains by priority (the paper's `OperatorSubset` and Algorithm 1's levels) and the
//! PDDL domains and problems every demoplan planning run uses.

use grounding::{FactSpace, Predicate, State};
use pddl::{
    Action, Atom, CostExpr, Domain, Effect, FunctionDecl, FunctionTerm, InitEntry, Literal, Metric,
    Name, Number, PredicateDecl, Problem, Requirement, Span, Term, Type, Typed,
};
use recording::{Activity, EntityKind, Header};

use crate::library::{Library, Ranked};
use crate::operator::LiftedFact;

/// Which operators may go into domains.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct DomainOptions {
    /// Keep operators that change nothing (left out by default: they can never help a
    /// plan, but they count toward their type's count and so toward costs).
    pub keep_without_effects: bool,
}

/// The operators eligible for domains, per type in [`Activity::OPERATOR_ORDER`], most frequent first.
fn eligible<'a>(library: &'a Library, options: DomainOptions) -> Vec<Vec<Ranked<'a>>> {
    Activity::OPERATOR_ORDER
        .iter()
        .map(|&a| {
            library
                .ranked_type(a)
                .into_iter()
                .filter(|r| options.keep_without_effects || r.operator().has_effects())
                .collect()
        })
        .collect()
}

/// The paper's `OperatorSubset(O, prio)`: per type, the `prio` most frequent operators
/// and every operator whose count equals that of the `prio`-th (ties are all in); a type
/// with fewer operators gives all of them. Types in [`Activity::OPERATOR_ORDER`], each most frequent
/// first.
pub fn operator_subset(library: &Library, prio: usize, options: DomainOptions) -> Vec<Ranked<'_>> {
    let mut subset = Vec::new();
    for ranked in eligible(library, options) {
        if ranked.is_empty() || prio == 0 {
            continue;
        }
        let threshold = ranked[prio.min(ranked.len()) - 1].count();
        subset.extend(ranked.into_iter().filter(|r| r.count() >= threshold));
    }
    subset
}

/// One level of Algorithm 1: the priority that first gives this subset, and the subset.
#[derive(Debug, Clone)]
pub struct Level<'a> {
    /// The priority (`prio` of `OperatorSubset`).
    pub prio: usize,
    /// Its operators.
    pub operators: Vec<Ranked<'a>>,
}

/// Which domain of a library to write (`demoplan domain -o`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum DomainChoice {
    /// The paper's `OperatorSubset` of this priority (1 or more).
    Priority(usize),
    /// Every eligible operator: the last level's subset.
    Full,
}

/// A domain with no operator ([`chosen_domain`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq, thiserror::Error)]
#[error("the library has no operator that changes anything; a domain would be empty")]
pub struct EmptyDomain;

/// The operators of the domain `choice` names, most frequent first per type, and how the
/// domain names itself (`priority 2`, `full domain`); [`EmptyDomain`] when no eligible
/// operator changes anything.
pub fn chosen_domain(
    library: &Library,
    choice: DomainChoice,
    options: DomainOptions,
) -> Result<(Vec<Ranked<'_>>, String), EmptyDomain> {
    let (prio, what) = match choice {
        DomainChoice::Priority(prio) => (prio, format!("priority {prio}")),
        DomainChoice::Full => {
            let most = levels(library, options).last().map_or(0, |l| l.prio);
            (most.max(1), "full domain".to_string())
        }
    };
    let operators = operator_subset(library, prio, options);
    match operators.is_empty() {
        true => Err(EmptyDomain),
        false => Ok((operators, what)),
    }
}

/// The distinct subsets for priority 1, 2, ... up to the full domain, equal consecutive
/// subsets skipped.
pub fn levels(library: &Library, options: DomainOptions) -> Vec<Level<'_>> {
    let most = eligible(library, options)
        .iter()
        .map(Vec::len)
        .max()
        .unwrap_or(0);
    let mut out: Vec<Level<'_>> = Vec::new();
    for prio in 1..=most {
        let operators = operator_subset(library, prio, options);
        let same = out.last().is_some_and(|l| {
            l.operators.len() == operators.len()
                && l.operators
                    .iter()
                    .zip(&operators)
                    .all(|(a, b)| std::ptr::eq(a.entry, b.entry))
        });
        if !same {
            out.push(Level { prio, operators });
        }
    }
    out
}

/// The PDDL name of a predicate (PDDL names are lowercase; the paper writes camel case).
pub fn pddl_predicate(p: Predicate) -> String {
    p.name().to_ascii_lowercase()
}

fn name(s: &str) -> Name {
    Name::new(s)
}

fn typed(n: &str, t: &str) -> Typed {
    Typed {
        name: name(n),
        ty: Some(Type::Named(name(t))),
    }
}

fn requirement(s: &str) -> Requirement {
    Requirement {
        name: s.to_string(),
        span: Span::NONE,
    }
}

fn atom(predicate: &str, args: Vec<Term>) -> Atom {
    Atom {
        predicate: name(predicate),
        args,
        span: Span::NONE,
    }
}

/// The predicate declarations every demoplan domain has, in the order of the paper's
/// Table 2.
fn predicate_decls() -> Vec<PredicateDecl> {
    Predicate::ALL
        .iter()
        .map(|&p| {
            let params = match p {
                Predicate::HandMove | Predicate::HandOpen => vec![typed("?h", "hand")],
                Predicate::ActedOn | Predicate::Graspable | Predicate::InHand => {
                    vec![typed("?h", "hand"), typed("?x", "thing")]
                }
                Predicate::InTouch | Predicate::OnTop => {
                    vec![typed("?x", "thing"), typed("?y", "thing")]
                }
            };
            PredicateDecl {
                name: name(&pddl_predicate(p)),
                params,
            }
        })
        .collect()
}

/// The atoms of a lifted fact over parameter terms: `inTouch` is symmetric, so it is
/// written in both orders (problems list both orders too).
fn lifted_atoms(f: &LiftedFact, terms: &[Term]) -> Vec<Atom> {
    let term = |i: u8| {
        terms
            .get(i as usize)
            .cloned()
            .unwrap_or(Term::Object(name("?")))
    };
    let p = pddl_predicate(f.predicate);
    match f.predicate.arity() {
        1 => vec![atom(&p, vec![term(f.args[0])])],
        _ if f.predicate == Predicate::InTouch && f.args[0] != f.args[1] => vec![
            atom(&p, vec![term(f.args[0]), term(f.args[1])]),
            atom(&p, vec![term(f.args[1]), term(f.args[0])]),
        ],
        _ => vec![atom(&p, vec![term(f.args[0]), term(f.args[1])])],
    }
}

/// The PDDL action of a ranked operator: named by rank, costed by count. Parameters of
/// the same type must bind different objects (`(not (= ?c1 ?c2))`): the demonstration
/// had different objects there.
pub fn action(r: &Ranked<'_>) -> Action {
    let op = r.operator();
    let names = op.param_names();
    let terms: Vec<Term> = names.iter().map(|n| Term::Variable(name(n))).collect();
    let mut precondition = Vec::new();
    for (positive, facts) in [(true, &op.pre_positive), (false, &op.pre_negative)] {
        for f in facts {
            for a in lifted_atoms(f, &terms) {
                precondition.push(Literal { positive, atom: a });
            }
        }
    }
    for i in 0..op.params.len() {
        for j in i + 1..op.params.len() {
            if op.params[i] == op.params[j] {
                precondition.push(Literal {
                    positive: false,
                    atom: atom("=", vec![terms[i].clone(), terms[j].clone()]),
                });
            }
        }
    }
    let mut effects = Vec::new();
    for f in &op.delete {
        effects.extend(lifted_atoms(f, &terms).into_iter().map(Effect::Delete));
    }
    for f in &op.add {
        effects.extend(lifted_atoms(f, &terms).into_iter().map(Effect::Add));
    }
    effects.push(Effect::IncreaseCost(CostExpr::Constant(Number {
        value: i64::from(r.cost),
        span: Span::NONE,
    })));
    Action {
        name: name(&r.name()),
        params: names
            .iter()
            .zip(&op.params)
            .map(|(n, t)| typed(n, t.name()))
            .collect(),
        precondition,
        effects,
    }
}

/// A PDDL domain of the given operators (as [`operator_subset`] or [`levels`] give
/// them), in their order.
pub fn domain(domain_name: &str, operators: &[Ranked<'_>]) -> Domain {
    Domain {
        name: name(domain_name),
        requirements: [
            ":strips",
            ":typing",
            ":negative-preconditions",
            ":equality",
            ":action-costs",
        ]
        .iter()
        .map(|r| requirement(r))
        .collect(),
        types: vec![
            typed("hand", "object"),
            typed("thing", "object"),
            typed("cube", "thing"),
            typed("table", "thing"),
        ],
        constants: Vec::new(),
        predicates: predicate_decls(),
        functions: vec![FunctionDecl {
            name: name("total-cost"),
            params: Vec::new(),
        }],
        actions: operators.iter().map(action).collect(),
    }
}

/// The objects and initial facts of a planning problem.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Scene {
    /// Hand names.
    pub hands: Vec<String>,
    /// Cube names.
    pub cubes: Vec<String>,
    /// The table's name.
    pub table: String,
    /// Other things' names.
    pub others: Vec<String>,
    /// Initial facts: predicate and argument names (`inTouch` in one order; problems
    /// write both).
    pub facts: Vec<(Predicate, Vec<String>)>,
}

/// Hands of the default scene, as the simulator names them.
pub const DEFAULT_HANDS: [&str; 2] = ["left_hand", "right_hand"];

/// Cubes of the paper's scene.
pub const DEFAULT_CUBES: usize = 6;

impl Scene {
    /// Cubes `cube_1` ... `cube_N` on the table, both hands open and still.
    pub fn cubes_on_table(cubes: usize) -> Scene {
        Scene::with_hands(cubes, DEFAULT_HANDS.len())
    }

    /// Cubes `cube_1` ... `cube_N` on the table and the first `hands` of
    /// [`DEFAULT_HANDS`] (at least one), open and still. One hand is a one-armed robot
    /// such as the paper's TIAGo.
    pub fn with_hands(cubes: usize, hands: usize) -> Scene {
        let hands = &DEFAULT_HANDS[..hands.clamp(1, DEFAULT_HANDS.len())];
        let cubes: Vec<String> = (1..=cubes).map(|i| format!("cube_{i}")).collect();
        let table = "table".to_string();
        let mut facts = Vec::new();
        for h in hands {
            facts.push((Predicate::HandOpen, vec![h.to_string()]));
        }
        for c in &cubes {
            facts.push((Predicate::InTouch, vec![c.clone(), table.clone()]));
            facts.push((Predicate::OnTop, vec![c.clone(), table.clone()]));
        }
        Scene {
            hands: hands.iter().map(|h| h.to_string()).collect(),
            cubes,
            table,
            others: Vec::new(),
            facts,
        }
    }

    /// The scene of a recording with the facts of one grounded state.
    pub fn from_state(header: &Header, space: &FactSpace, state: &State) -> Scene {
        let names = |kind: EntityKind| -> Vec<String> {
            header
                .entities
                .iter()
                .filter(|e| e.kind == kind)
                .map(|e| e.name.clone())
                .collect()
        };
        let facts = state
            .facts(space)
            .map(|f| {
                let args = f
                    .args()
                    .iter()
                    .map(|a| {
                        header
                            .entities
                            .get(a.index())
                            .map(|e| e.name.clone())
                            .unwrap_or_default()
                    })
                    .collect();
                (f.predicate, args)
            })
            .collect();
        Scene {
            hands: names(EntityKind::Hand),
            cubes: names(EntityKind::Cube),
            table: names(EntityKind::Table)
                .into_iter()
                .next()
                .unwrap_or_else(|| "table".to_string()),
            others: names(EntityKind::Other),
            facts,
        }
    }

    /// Whether the scene has a cube of this name.
    pub fn has_cube(&self, cube: &str) -> bool {
        self.cubes.iter().any(|c| c == cube)
    }
}

/// A tower, bottom first: its goal facts (`onTop` of each cube on the one below, the
/// bottom one on the table).
pub fn tower_goal(scene: &Scene, tower: &[String]) -> Vec<(Predicate, Vec<String>)> {
    let mut goal = Vec::new();
    for (i, c) in tower.iter().enumerate() {
        let below = if i == 0 {
            scene.table.clone()
        } else {
            tower[i - 1].clone()
        };
        goal.push((Predicate::OnTop, vec![c.clone(), below]));
    }
    goal
}

/// The paper's goal `n` (1 to 5), reconstructed: a tower of `n + 1` cubes,
/// `cube_1` at the bottom.
pub fn paper_goal_tower(n: usize) -> Vec<String> {
    (1..=n + 1).map(|i| format!("cube_{i}")).collect()
}

/// A goal tower, bottom first, and the name its problem gets.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Tower {
    /// The cubes, bottom first.
    pub cubes: Vec<String>,
    /// The problem's name: `tower-A-B-...` or `paper-goal-N`.
    pub name: String,
}

/// Why a tower is no goal for a scene.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum TowerError {
    /// The paper has goals 1 to 5 only.
    #[error("the paper has goals 1 to 5")]
    NoPaperGoal(usize),
    /// Fewer than two cubes.
    #[error("a tower needs at least two cubes, listed bottom first")]
    TooShort,
    /// A cube the scene does not have.
    #[error("the tower names `{cube}`, which is not a cube of the scene (cubes: {})", .cubes.join(", "))]
    UnknownCube {
        /// The cube named.
        cube: String,
        /// The scene's cubes.
        cubes: Vec<String>,
    },
    /// A cube named twice.
    #[error("the tower names `{0}` twice")]
    Twice(String),
    /// Neither a tower nor a paper goal was given, or both ([`Tower::chosen`]).
    #[error("give the goal as a tower or as the paper's goal, one of them")]
    NoGoal,
}

impl Tower {
    /// A tower from a comma-separated list of cube names, bottom first (names are
    /// lowercased, as all PDDL names are).
    pub fn listed(list: &str) -> Tower {
        let cubes: Vec<String> = list
            .split(',')
            .map(|c| c.trim().to_ascii_lowercase())
            .collect();
        let name = format!("tower-{}", cubes.join("-"));
        Tower { cubes, name }
    }

    /// The goal a problem asks for (`demoplan problem`, the Python `tower_problem`):
    /// the cubes `listed` ([`Tower::listed`]) or the paper's goal `paper_goal`
    /// ([`Tower::paper_goal`]), exactly one of them.
    pub fn chosen(listed: Option<&str>, paper_goal: Option<usize>) -> Result<Tower, TowerError> {
        match (listed, paper_goal) {
            (Some(list), None) => Ok(Tower::listed(list)),
            (None, Some(n)) => Tower::paper_goal(n),
            _ => Err(TowerError::NoGoal),
        }
    }

    /// The paper's goal `n` (1 to 5), reconstructed ([`paper_goal_tower`]).
    pub fn paper_goal(n: usize) -> Result<Tower, TowerError> {
        if !(1..=5).contains(&n) {
            return Err(TowerError::NoPaperGoal(n));
        }
        Ok(Tower {
            cubes: paper_goal_tower(n),
            name: format!("paper-goal-{n}"),
        })
    }

    /// The tower's problem on `scene`, as PDDL text with a comment that lists the tower:
    /// refused when the tower has fewer than two cubes, or names a cube the scene does
    /// not have, or one twice.
    pub fn problem_text(&self, scene: &Scene) -> Result<String, TowerError> {
        if self.cubes.len() < 2 {
            return Err(TowerError::TooShort);
        }
        for (i, c) in self.cubes.iter().enumerate() {
            if !scene.has_cube(c) {
                return Err(TowerError::UnknownCube {
                    cube: c.clone(),
                    cubes: scene.cubes.clone(),
                });
            }
            if self.cubes[..i].contains(c) {
                return Err(TowerError::Twice(c.clone()));
            }
        }
        let goal = tower_goal(scene, &self.cubes);
        Ok(format!(
            "; demoplan problem: a tower of {} cubes, bottom first: {}.\n{}",
            self.cubes.len(),
            self.cubes.join(", "),
            problem(&self.name, "demoplan", scene, &goal)
        ))
    }
}

fn ground_atoms(p: Predicate, args: &[String]) -> Vec<Atom> {
    let pn = pddl_predicate(p);
    let terms: Vec<Term> = args.iter().map(|a| Term::Object(name(a))).collect();
    if p == Predicate::InTouch && terms.len() == 2 && terms[0] != terms[1] {
        vec![
            atom(&pn, terms.clone()),
            atom(&pn, vec![terms[1].clone(), terms[0].clone()]),
        ]
    } else {
        vec![atom(&pn, terms)]
    }
}

/// A PDDL problem: the scene's objects and facts, the goal facts, and total cost.
pub fn problem(
    problem_name: &str,
    domain_name: &str,
    scene: &Scene,
    goal: &[(Predicate, Vec<String>)],
) -> Problem {
    let mut objects: Vec<Typed> = Vec::new();
    objects.extend(scene.hands.iter().map(|h| typed(h, "hand")));
    objects.extend(scene.cubes.iter().map(|c| typed(c, "cube")));
    objects.push(typed(&scene.table, "table"));
    objects.extend(scene.others.iter().map(|o| typed(o, "thing")));
    let mut init: Vec<InitEntry> = scene
        .facts
        .iter()
        .flat_map(|(p, args)| ground_atoms(*p, args))
        .map(InitEntry::Fact)
        .collect();
    init.push(InitEntry::FunctionValue {
        term: FunctionTerm {
            function: name("total-cost"),
            args: Vec::new(),
            span: Span::NONE,
        },
        value: Number {
            value: 0,
            span: Span::NONE,
        },
    });
    Problem {
        name: name(problem_name),
        domain: name(domain_name),
        requirements: Vec::new(),
        objects,
        init,
        goal: goal
            .iter()
            .flat_map(|(p, args)| ground_atoms(*p, args))
            .map(|atom| Literal {
                positive: true,
                atom,
            })
            .collect(),
        metric: Some(Metric { span: Span::NONE }),
    }
}

/// The name a domain of priority `prio` gets.
pub fn domain_name(prio: usize) -> String {
    format!("demoplan-prio{prio}")
}

/// Operators per type of a set of ranked operators, in [`Activity::OPERATOR_ORDER`].
pub fn per_type(operators: &[Ranked<'_>]) -> [usize; 5] {
    let mut n = [0; 5];
    for r in operators {
        if let Some(i) = Activity::OPERATOR_ORDER
            .iter()
            .position(|&a| a == r.operator().activity)
        {
            n[i] += 1;
        }
    }
    n
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn towers_are_checked_against_the_scene() {
        let scene = Scene::cubes_on_table(3);
        let cube = |i: usize| scene.cubes[i].clone();
        let listed = Tower::listed(&format!(" {} ,{}", cube(0).to_uppercase(), cube(1)));
        assert_eq!(listed.cubes, [cube(0), cube(1)]);
        assert_eq!(listed.name, format!("tower-{}-{}", cube(0), cube(1)));
        let text = listed.problem_text(&scene).unwrap();
        assert!(text.starts_with("; demoplan problem: a tower of 2 cubes, bottom first:"));
        assert!(
            text.contains(&format!("(ontop {} {})", cube(1), cube(0))),
            "{text}"
        );
        assert_eq!(
            Tower::listed(&cube(0)).problem_text(&scene),
            Err(TowerError::TooShort)
        );
        assert_eq!(
            Tower::listed(&format!("{},{}", cube(0), cube(0))).problem_text(&scene),
            Err(TowerError::Twice(cube(0)))
        );
        assert!(matches!(
            Tower::listed(&format!("{},nope", cube(0))).problem_text(&scene),
            Err(TowerError::UnknownCube { cube, .. }) if cube == "nope"
        ));
        assert_eq!(Tower::paper_goal(6), Err(TowerError::NoPaperGoal(6)));
        assert_eq!(Tower::paper_goal(2).unwrap().cubes.len(), 3);
        // Exactly one of a list and a paper goal.
        assert_eq!(Tower::chosen(Some("a,b"), None), Ok(Tower::listed("a,b")));
        assert_eq!(Tower::chosen(None, Some(2)), Tower::paper_goal(2));
        assert_eq!(Tower::chosen(None, None), Err(TowerError::NoGoal));
        assert_eq!(Tower::chosen(Some("a,b"), Some(2)), Err(TowerError::NoGoal));
    }
    use crate::operator::{Operator, ParamType};

    /// A distinct operator of a type: `k` tells them apart (the hand moves or not, and
    /// the number of cubes); `effects` whether it changes anything.
    fn op(activity: Activity, k: u8, effects: bool) -> Operator {
        let mut params = vec![ParamType::Hand];
        params.extend(std::iter::repeat_n(ParamType::Cube, k as usize));
        let add = if effects {
            vec![LiftedFact::new(Predicate::HandMove, 0, 0)]
        } else {
            Vec::new()
        };
        Operator::new(activity, params, Vec::new(), Vec::new(), add, Vec::new())
    }

    fn library(counts: &[(Activity, &[u64])]) -> Library {
        let mut library = Library::default();
        for (a, cs) in counts {
            for (k, &c) in cs.iter().enumerate() {
                library.insert_counted(op(*a, k as u8, true), c);
            }
        }
        library
    }

    fn sizes(l: &Library, prio: usize) -> [usize; 5] {
        per_type(&operator_subset(l, prio, DomainOptions::default()))
    }

    #[test]
    fn operator_subset_keeps_ties_with_the_prio_th() {
        // Reach counts 5, 3, 3, 1: priority 2 keeps both operators counted 3.
        let l = library(&[(Activity::Reach, &[5, 3, 3, 1]), (Activity::Take, &[4])]);
        assert_eq!(sizes(&l, 1), [1, 1, 0, 0, 0]);
        assert_eq!(sizes(&l, 2), [3, 1, 0, 0, 0]);
        assert_eq!(sizes(&l, 3), [3, 1, 0, 0, 0]);
        assert_eq!(sizes(&l, 4), [4, 1, 0, 0, 0]);
        assert_eq!(sizes(&l, 9), [4, 1, 0, 0, 0]);
        // A tie at the top: priority 1 has both.
        let l = library(&[(Activity::Idle, &[2, 2, 1])]);
        assert_eq!(sizes(&l, 1), [0, 0, 0, 0, 2]);
        // Levels skip equal subsets: priorities 1, 2 and 4 of the first library.
        let l = library(&[(Activity::Reach, &[5, 3, 3, 1]), (Activity::Take, &[4])]);
        let prios: Vec<usize> = levels(&l, DomainOptions::default())
            .iter()
            .map(|x| x.prio)
            .collect();
        assert_eq!(prios, [1, 2, 4]);
    }

    #[test]
    fn a_chosen_domain_is_a_priority_or_the_last_level() {
        let l = library(&[(Activity::Reach, &[5, 3, 3, 1]), (Activity::Take, &[4])]);
        let chosen = |choice| {
            let (operators, what) = chosen_domain(&l, choice, DomainOptions::default()).unwrap();
            (per_type(&operators), what)
        };
        let two = (sizes(&l, 2), "priority 2".to_string());
        assert_eq!(chosen(DomainChoice::Priority(2)), two);
        assert_eq!(
            chosen(DomainChoice::Full),
            (sizes(&l, 4), "full domain".into())
        );
        // Only operators that change nothing: every domain would be empty.
        let mut l = Library::default();
        l.insert_counted(op(Activity::Idle, 0, false), 2);
        for choice in [DomainChoice::Priority(1), DomainChoice::Full] {
            assert_eq!(
                chosen_domain(&l, choice, DomainOptions::default()).err(),
                Some(EmptyDomain)
            );
        }
    }

    #[test]
    fn operators_without_effects_stay_out_of_domains_unless_kept() {
        let mut l = library(&[(Activity::Idle, &[3])]);
        l.insert_counted(op(Activity::Idle, 5, false), 9);
        // The no-effect operator is the most frequent but never in a default domain; it
        // still counts toward the type's count and so toward costs.
        assert_eq!(sizes(&l, 1), [0, 0, 0, 0, 1]);
        assert_eq!(l.type_count(Activity::Idle), 12);
        let kept = DomainOptions {
            keep_without_effects: true,
        };
        assert_eq!(per_type(&operator_subset(&l, 1, kept)), [0, 0, 0, 0, 1]);
        assert!(!operator_subset(&l, 1, kept)[0].operator().has_effects());
        assert_eq!(operator_subset(&l, 1, DomainOptions::default())[0].cost, 75);
    }

    #[test]
    fn domains_are_deterministic_and_parse() {
        let l = library(&[
            (Activity::Reach, &[5, 3]),
            (Activity::Stack, &[3, 2, 1]),
            (Activity::Idle, &[1]),
        ]);
        let ops = operator_subset(&l, 3, DomainOptions::default());
        let text = domain("demoplan", &ops).to_string();
        assert_eq!(text, domain("demoplan", &ops).to_string());
        let parsed = pddl::parse_domain(&text).unwrap();
        let names: Vec<&str> = parsed.actions.iter().map(|a| a.name.as_str()).collect();
        assert_eq!(
            names,
            ["reach", "reach2", "stack", "stack2", "stack3", "idle"]
        );
        // Same-typed parameters (stack3 has two cubes) bind different objects.
        let stack = &parsed.actions[4];
        assert_eq!(stack.params.len(), 3);
        assert!(stack
            .precondition
            .iter()
            .any(|l| !l.positive && l.atom.is_equality()));
    }

    #[test]
    fn problems_parse_against_domains() {
        let l = library(&[(Activity::Reach, &[1])]);
        let d = domain(
            "demoplan",
            &operator_subset(&l, 1, DomainOptions::default()),
        );
        let scene = Scene::cubes_on_table(6);
        for n in 1..=5 {
            let tower = paper_goal_tower(n);
            assert_eq!(tower.len(), n + 1);
            let p = problem("p", "demoplan", &scene, &tower_goal(&scene, &tower));
            let parsed_d = pddl::parse_domain(&d.to_string()).unwrap();
            let parsed_p = pddl::parse_problem(&p.to_string()).unwrap();
            pddl::check_problem(&parsed_d, &parsed_p).unwrap();
            assert_eq!(parsed_p.goal.len(), n + 1);
        }
    }
}
