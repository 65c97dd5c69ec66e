//! Property: random domains and problems in the fragment, written and parsed back, are
//! equal; and the writer's output is a fixed point of `fmt`.
//!
//! The trees are built from a proptest-chosen seed by a small generator that keeps them
//! valid (declared names, right arities, acyclic types), so the parser's checks pass and
//! the property tests the writer and reader, not the checker.

#![allow(clippy::unwrap_used, clippy::expect_used)] // tests fail loudly by design

use pddl::*;
use proptest::prelude::*;

/// xorshift64*: enough randomness for shapes, and no dependency.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        self.0.wrapping_mul(0x2545_f491_4f6c_dd1d)
    }
    fn below(&mut self, n: usize) -> usize {
        (self.next() % n.max(1) as u64) as usize
    }
    fn chance(&mut self, percent: u64) -> bool {
        self.next() % 100 < percent
    }
    fn pick<'a, T>(&mut self, items: &'a [T]) -> Option<&'a T> {
        if items.is_empty() {
            None
        } else {
            Some(&items[self.below(items.len())])
        }
    }
}

const SYLLABLES: &[&str] = &["ba", "ko", "ri", "tu", "me", "x", "z9", "q_", "lo-"];

fn word(rng: &mut Rng, index: usize) -> String {
    let mut s = String::new();
    for _ in 0..=rng.below(3) {
        s.push_str(SYLLABLES[rng.below(SYLLABLES.len())]);
    }
    // The index makes names unique; a letter first keeps them names, not numbers.
    format!("{s}{index}")
}

fn typed_list(rng: &mut Rng, names: Vec<String>, types: &[String]) -> Vec<Typed> {
    let mut items: Vec<Typed> = names
        .into_iter()
        .map(|n| {
            let ty = if types.is_empty() || rng.chance(20) {
                None
            } else if rng.chance(15) && types.len() > 1 {
                let a = rng.below(types.len());
                let b = (a + 1) % types.len();
                Some(Type::Either(vec![
                    Name::new(&types[a]),
                    Name::new(&types[b]),
                ]))
            } else {
                rng.pick(types).map(|t| Type::Named(Name::new(t)))
            };
            Typed {
                name: Name::new(n),
                ty,
            }
        })
        .collect();
    // As parsed: items without a type come last (PDDL gives earlier ones the next type).
    items.sort_by_key(|t| t.ty.is_none());
    items
}

fn term(rng: &mut Rng, vars: &[String], constants: &[String]) -> Term {
    if !vars.is_empty() && (constants.is_empty() || rng.chance(80)) {
        Term::Variable(Name::new(&vars[rng.below(vars.len())]))
    } else {
        Term::Object(Name::new(&constants[rng.below(constants.len())]))
    }
}

fn atom(
    rng: &mut Rng,
    preds: &[(String, usize)],
    vars: &[String],
    constants: &[String],
) -> Option<Atom> {
    let (name, arity) = rng.pick(preds)?.clone();
    if arity > 0 && vars.is_empty() && constants.is_empty() {
        return None;
    }
    let args = (0..arity).map(|_| term(rng, vars, constants)).collect();
    Some(Atom {
        predicate: Name::new(name),
        args,
        span: Span::NONE,
    })
}

fn domain(seed: u64) -> Domain {
    let mut rng = Rng(seed | 1);
    let mut type_names: Vec<String> = Vec::new();
    let mut types = Vec::new();
    for i in 0..rng.below(5) {
        let name = word(&mut rng, i);
        // Parents are earlier types or `object`, so the hierarchy has no cycle.
        let parents: Vec<String> = type_names
            .iter()
            .cloned()
            .chain(["object".to_string()])
            .collect();
        let ty = if rng.chance(30) {
            None
        } else {
            rng.pick(&parents).map(|p| Type::Named(Name::new(p)))
        };
        types.push(Typed {
            name: Name::new(&name),
            ty,
        });
        type_names.push(name);
    }
    types.sort_by_key(|t| t.ty.is_none());
    let constant_names: Vec<String> = (0..rng.below(4)).map(|i| word(&mut rng, 100 + i)).collect();
    let constants = typed_list(&mut rng, constant_names.clone(), &type_names);
    let mut preds: Vec<(String, usize)> = Vec::new();
    let mut predicates = Vec::new();
    for i in 0..rng.below(6) {
        let arity = rng.below(4);
        let name = word(&mut rng, 200 + i);
        let params = typed_list(
            &mut rng,
            (0..arity).map(|k| format!("?a{k}")).collect(),
            &type_names,
        );
        predicates.push(PredicateDecl {
            name: Name::new(&name),
            params,
        });
        preds.push((name, arity));
    }
    let mut functions = Vec::new();
    let mut cost_functions: Vec<(String, usize)> = Vec::new();
    if rng.chance(50) {
        functions.push(FunctionDecl {
            name: Name::new("total-cost"),
            params: vec![],
        });
        for i in 0..rng.below(3) {
            let arity = rng.below(3);
            let name = word(&mut rng, 300 + i);
            let params = typed_list(
                &mut rng,
                (0..arity).map(|k| format!("?f{k}")).collect(),
                &type_names,
            );
            functions.push(FunctionDecl {
                name: Name::new(&name),
                params,
            });
            cost_functions.push((name, arity));
        }
    }
    let mut actions = Vec::new();
    for i in 0..rng.below(5) {
        let vars: Vec<String> = (0..rng.below(4))
            .map(|k| format!("?{}", word(&mut rng, k)))
            .collect();
        let params = typed_list(&mut rng, vars.clone(), &type_names);
        let mut precondition = Vec::new();
        for _ in 0..rng.below(5) {
            if rng.chance(15) && (!vars.is_empty() || !constant_names.is_empty()) {
                let args = vec![
                    term(&mut rng, &vars, &constant_names),
                    term(&mut rng, &vars, &constant_names),
                ];
                precondition.push(Literal {
                    positive: rng.chance(30),
                    atom: Atom {
                        predicate: Name::new("="),
                        args,
                        span: Span::NONE,
                    },
                });
            } else if let Some(a) = atom(&mut rng, &preds, &vars, &constant_names) {
                precondition.push(Literal {
                    positive: rng.chance(70),
                    atom: a,
                });
            }
        }
        let mut effects = Vec::new();
        for _ in 0..rng.below(5) {
            if let Some(a) = atom(&mut rng, &preds, &vars, &constant_names) {
                effects.push(if rng.chance(60) {
                    Effect::Add(a)
                } else {
                    Effect::Delete(a)
                });
            }
        }
        if !functions.is_empty() && rng.chance(70) {
            let cost = match rng.pick(&cost_functions).cloned() {
                Some((name, arity))
                    if rng.chance(50)
                        && (arity == 0 || !vars.is_empty() || !constant_names.is_empty()) =>
                {
                    let args = (0..arity)
                        .map(|_| term(&mut rng, &vars, &constant_names))
                        .collect();
                    CostExpr::Function(FunctionTerm {
                        function: Name::new(name),
                        args,
                        span: Span::NONE,
                    })
                }
                _ => CostExpr::Constant(Number {
                    value: (rng.next() % 5_000_000_000) as i64,
                    span: Span::NONE,
                }),
            };
            effects.push(Effect::IncreaseCost(cost));
        }
        actions.push(Action {
            name: Name::new(word(&mut rng, 400 + i)),
            params,
            precondition,
            effects,
        });
    }
    let requirements = [":strips", ":typing", ":action-costs", ":adl"]
        .iter()
        .filter(|_| rng.chance(50))
        .map(|r| Requirement {
            name: r.to_string(),
            span: Span::NONE,
        })
        .collect();
    Domain {
        name: Name::new(word(&mut rng, 0)),
        requirements,
        types,
        constants,
        predicates,
        functions,
        actions,
    }
}

fn problem(seed: u64, d: &Domain) -> Problem {
    let mut rng = Rng(seed.rotate_left(17) | 1);
    let type_names: Vec<String> = d.types.iter().map(|t| t.name.text.clone()).collect();
    let object_names: Vec<String> = (0..rng.below(6)).map(|i| word(&mut rng, 500 + i)).collect();
    let objects = typed_list(&mut rng, object_names.clone(), &type_names);
    let all: Vec<String> = object_names
        .iter()
        .cloned()
        .chain(d.constants.iter().map(|c| c.name.text.clone()))
        .collect();
    let preds: Vec<(String, usize)> = d
        .predicates
        .iter()
        .map(|p| (p.name.text.clone(), p.params.len()))
        .collect();
    let mut init = Vec::new();
    for _ in 0..rng.below(8) {
        if let Some(a) = atom(&mut rng, &preds, &[], &all) {
            init.push(InitEntry::Fact(a));
        }
    }
    for f in &d.functions {
        if f.params.is_empty() || !all.is_empty() {
            let args = (0..f.params.len())
                .map(|_| term(&mut rng, &[], &all))
                .collect();
            let term = FunctionTerm {
                function: f.name.clone(),
                args,
                span: Span::NONE,
            };
            init.push(InitEntry::FunctionValue {
                term,
                value: Number {
                    value: rng.below(1000) as i64,
                    span: Span::NONE,
                },
            });
        }
    }
    let mut goal = Vec::new();
    for _ in 0..rng.below(4) {
        if let Some(a) = atom(&mut rng, &preds, &[], &all) {
            goal.push(Literal {
                positive: rng.chance(80),
                atom: a,
            });
        }
    }
    Problem {
        name: Name::new(word(&mut rng, 1)),
        domain: d.name.clone(),
        requirements: Vec::new(),
        objects,
        init,
        goal,
        metric: if d.functions.is_empty() {
            None
        } else {
            Some(Metric { span: Span::NONE })
        },
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(2000))]

    #[test]
    fn written_domains_parse_back_equal(seed in any::<u64>()) {
        let d = domain(seed);
        let text = d.to_string();
        let back = parse_domain(&text).map_err(|e| TestCaseError::fail(format!("{e:?}\n{text}")))?;
        prop_assert_eq!(&back, &d, "{}", text);
        prop_assert_eq!(back.to_string(), text);
    }

    #[test]
    fn written_problems_parse_back_equal(seed in any::<u64>()) {
        let d = domain(seed);
        let p = problem(seed, &d);
        let text = p.to_string();
        let back = parse_problem(&text).map_err(|e| TestCaseError::fail(format!("{e:?}\n{text}")))?;
        check_problem(&d, &back).map_err(|e| TestCaseError::fail(format!("{e:?}\n{text}")))?;
        prop_assert_eq!(&back, &p, "{}", text);
    }

    #[test]
    fn upper_case_reads_as_lower_case(seed in any::<u64>()) {
        let d = domain(seed);
        let text = d.to_string();
        prop_assert_eq!(parse_domain(&text.to_uppercase()).map_err(|e| TestCaseError::fail(format!("{e:?}")))?, d);
    }

    #[test]
    fn arbitrary_text_never_panics(text in "[()a-z ?:;=\\-\n0-9]{0,200}") {
        let _ = parse_file(&text);
    }
}
