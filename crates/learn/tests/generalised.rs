//! Generalised operators (issue 39) on the simulator's demonstrations: every
//! generalised operator holds in the start state of every activity it came from, with
//! that activity's effects; learning in any order, incrementally and by merging gives
//! the same bytes; the file records the form and round-trips; counts add up.

#![allow(clippy::unwrap_used, clippy::expect_used)]

use grounding::{Fact, FactSpace, Predicate, State};
use learn::{covers, effect_key, Grouping, Library, OperatorForm, ParamType, RecordingInfo};
use recording::{EntityId, Header};
use segment::{Activity, ActivityTree, Segment};

struct Learnable {
    info: RecordingInfo,
    header: Header,
    segmented: learn::Segmented,
}

fn learnable(demo: &simulate::Demonstration) -> Learnable {
    let header = demo.header().clone();
    let frames: Vec<recording::Frame> = demo.frames().map(|(f, _)| f).collect();
    let hash = learn::recording_hash(&header, &frames);
    let segmented = learn::segment_frames(
        &header,
        frames,
        &grounding::GroundingConfig::default(),
        &ActivityTree::table_one(),
    );
    Learnable {
        info: RecordingInfo {
            hash,
            id: header.id.clone(),
            participant: header.participant.clone(),
            source: String::new(),
            frames: segmented.frames,
            segments: 0,
            ..Default::default()
        },
        header,
        segmented,
    }
}

fn add(library: &mut Library, l: &Learnable) {
    library.add_recording(
        l.info.clone(),
        &l.header,
        &l.segmented.space,
        &l.segmented.segments,
    );
}

fn recordings(seed: u64) -> Vec<Learnable> {
    simulate::study(&simulate::SimParams::default(), seed, 3, 4)
        .unwrap()
        .demonstrations
        .iter()
        .map(learnable)
        .collect()
}

fn generalised() -> Library {
    Library::with_form(
        learn::DEFAULT_LAMBDA,
        Grouping::Settled,
        OperatorForm::Generalised,
    )
}

/// Whether a ground fact holds in a state (a fact the scene cannot have does not).
fn holds(space: &FactSpace, state: &State, p: Predicate, a: EntityId, b: EntityId) -> bool {
    let fact = if p.arity() == 1 {
        Fact::unary(p, a)
    } else {
        Fact::binary(p, a, b)
    };
    space.id(&fact).is_some_and(|id| state.contains(id))
}

/// Whether some binding of the operator's parameters to distinct entities of their
/// types makes its precondition hold in the segment's start state and its effects
/// hold (added facts true, deleted facts false) at the segment's last frame.
fn applies(op: &learn::Operator, s: &Segment, space: &FactSpace, header: &Header) -> bool {
    fn search(
        op: &learn::Operator,
        s: &Segment,
        space: &FactSpace,
        candidates: &[Vec<EntityId>],
        binding: &mut Vec<EntityId>,
    ) -> bool {
        let i = binding.len();
        if i == op.params.len() {
            let at = |f: &learn::LiftedFact| {
                (
                    f.predicate,
                    binding[f.args[0] as usize],
                    binding[f.args[1] as usize],
                )
            };
            let all = |facts: &[learn::LiftedFact], state: &State, want: bool| {
                facts.iter().all(|f| {
                    let (p, a, b) = at(f);
                    holds(space, state, p, a, b) == want
                })
            };
            return all(&op.pre_positive, &s.start_state, true)
                && all(&op.pre_negative, &s.start_state, false)
                && all(&op.add, &s.end_state, true)
                && all(&op.delete, &s.end_state, false);
        }
        for &e in &candidates[i] {
            if !binding.contains(&e) {
                binding.push(e);
                if search(op, s, space, candidates, binding) {
                    return true;
                }
                binding.pop();
            }
        }
        false
    }
    let candidates: Vec<Vec<EntityId>> = op
        .params
        .iter()
        .map(|&t| {
            (0..header.entities.len() as u32)
                .map(EntityId)
                .filter(|&e| ParamType::of_kind(header.entities[e.index()].kind) == t)
                .collect()
        })
        .collect();
    search(op, s, space, &candidates, &mut Vec::new())
}

#[test]
fn a_generalised_operator_holds_in_every_start_state_it_came_from() {
    for seed in [simulate::DEFAULT_SEED, 4, 13] {
        let recordings = recordings(seed);
        let mut library = generalised();
        for r in &recordings {
            add(&mut library, r);
        }
        let mut checked = 0;
        for r in &recordings {
            let grouped = learn::activities(&r.segmented.segments, library.grouping);
            let (mended, _) = learn::mend(&grouped, library.grouping, &r.segmented.space);
            let (operators, _) = learn::lift_all(&mended, &r.segmented.space, &r.header);
            for (s, specific) in mended.iter().zip(operators) {
                // Its generalised operator: the one with its effects.
                let mine: Vec<&learn::Entry> = library
                    .entries()
                    .filter(|e| e.operator.activity == specific.activity)
                    .filter(|e| effect_key(&e.operator) == effect_key(&specific))
                    .collect();
                assert_eq!(mine.len(), 1, "seed {seed}: {specific}");
                let general = &mine[0].operator;
                assert!(covers(general, &specific), "{general} / {specific}");
                assert!(
                    applies(general, s, &r.segmented.space, &r.header),
                    "seed {seed}: {general} does not hold where {specific} started"
                );
                checked += 1;
            }
        }
        assert_eq!(checked as u64, library.segments());
    }
}

#[test]
fn counts_and_provenance_add_up_over_the_members() {
    let recordings = recordings(13);
    let mut specific = Library::default();
    let mut general = generalised();
    for r in &recordings {
        add(&mut specific, r);
        add(&mut general, r);
    }
    assert_eq!(general.segments(), specific.segments());
    for a in Activity::OPERATOR_ORDER {
        assert_eq!(general.type_count(a), specific.type_count(a));
    }
    assert!(general.len() <= specific.len());
    assert_eq!(
        general.specific_entries().collect::<Vec<_>>(),
        specific.entries().collect::<Vec<_>>()
    );
    for g in general.entries() {
        let members: Vec<&learn::Entry> = specific
            .entries()
            .filter(|e| {
                e.operator.activity == g.operator.activity
                    && effect_key(&e.operator) == effect_key(&g.operator)
            })
            .collect();
        assert!(!members.is_empty());
        assert_eq!(g.count, members.iter().map(|e| e.count).sum::<u64>());
        assert_eq!(
            g.provenance.len(),
            members.iter().map(|e| e.provenance.len()).sum::<usize>()
        );
        for m in &members {
            assert!(covers(&g.operator, &m.operator));
        }
    }
    // Seed 13 has operators that merge (docs/operators.md's table).
    assert!(general.len() < specific.len());
}

#[test]
fn learning_order_batches_and_merges_give_the_same_generalised_bytes() {
    let recordings = recordings(simulate::DEFAULT_SEED);
    let mut batch = generalised();
    for r in &recordings {
        add(&mut batch, r);
    }
    let mut reversed = generalised();
    for r in recordings.iter().rev() {
        add(&mut reversed, r);
    }
    assert_eq!(batch.to_json(), reversed.to_json());
    let mut first = generalised();
    for r in &recordings[..5] {
        add(&mut first, r);
    }
    let mut second = Library::from_json(&first.to_json()).unwrap();
    assert_eq!(second.form(), OperatorForm::Generalised);
    for r in &recordings[5..] {
        add(&mut second, r);
    }
    assert_eq!(batch.to_json(), second.to_json());
    let mut a = generalised();
    let mut b = generalised();
    for (i, r) in recordings.iter().enumerate() {
        add(if i % 3 == 0 { &mut a } else { &mut b }, r);
    }
    a.merge(&b).unwrap();
    assert_eq!(batch.to_json(), a.to_json());
    // A library of the other form is not merged.
    let error = a.merge(&Library::default()).unwrap_err();
    assert!(
        error
            .to_string()
            .contains("cannot merge a library of specific operators into one of generalised"),
        "{error}"
    );
}

#[test]
fn the_file_records_the_form_and_keeps_the_demonstrated_operators() {
    let recordings = recordings(simulate::DEFAULT_SEED);
    let mut library = generalised();
    let mut specific = Library::default();
    for r in &recordings {
        add(&mut library, r);
        add(&mut specific, r);
    }
    let text = library.to_json();
    assert!(
        text.contains("\"operator_form\": \"generalised\""),
        "{text}"
    );
    assert!(text.contains("\"specific_operators\": ["));
    let read = Library::from_json(&text).unwrap();
    assert_eq!(read, library);
    assert_eq!(read.to_json(), text);
    // A library of specific operators is written as before the form existed.
    let plain = specific.to_json();
    assert!(!plain.contains("operator_form") && !plain.contains("specific_operators"));
    assert_eq!(
        Library::from_json(&plain).unwrap().form(),
        OperatorForm::Specific
    );
    // Damaged files: each error names its field and line.
    let unknown = text.replace(
        "\"operator_form\": \"generalised\"",
        "\"operator_form\": \"x\"",
    );
    let e = Library::from_json(&unknown).unwrap_err();
    assert!(e.line > 0 && e.field == "operator_form", "{e}");
    assert!(e.to_string().contains("unknown operator form \"x\""), "{e}");
    let without_form = text.replace("  \"operator_form\": \"generalised\",\n", "");
    assert_ne!(without_form, text);
    let e = Library::from_json(&without_form).unwrap_err();
    assert!(e.line > 0 && e.field == "specific_operators", "{e}");
    let start = text.find("  \"specific_operators\"").unwrap();
    let mut without_specific = text[..start].trim_end().trim_end_matches(',').to_string();
    without_specific.push_str("\n}\n");
    let e = Library::from_json(&without_specific).unwrap_err();
    assert!(
        e.to_string()
            .contains("lists the demonstrated ones in `specific_operators`"),
        "{e}"
    );
}
