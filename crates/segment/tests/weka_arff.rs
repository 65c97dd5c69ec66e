//! ARFF as Weka reads it: each fixture against the values Weka gives for it, written out
//! by hand below (so the test is an oracle, not our own output read back). Every table
//! was also loaded once with Weka 3.6.14 (Debian's `weka` package): dense tables with
//! `java -cp weka.jar weka.core.converters.CSVSaver -i FILE`, sparse ones through
//! `weka.filters.unsupervised.instance.SparseToNonSparse`, with `TZ=UTC`; the rows it
//! printed are the ones asserted here (the `.txt` table copied to `.arff` first, since
//! Weka's converters choose a loader by extension).

#![allow(clippy::unwrap_used, clippy::expect_used)]

use grounding::Predicate;
use segment::{
    is_arff_text, read_arff, Activity, ActivityTree, ArffKind, ArffTable, LabelMap,
    WEKA_DUMMY_STRING,
};

fn fixture(name: &str) -> String {
    std::fs::read_to_string(format!(
        "{}/tests/fixtures/{name}",
        env!("CARGO_MANIFEST_DIR")
    ))
    .unwrap()
}

/// The table's values, `?` for missing.
fn values(table: &ArffTable) -> Vec<Vec<&str>> {
    table
        .rows
        .iter()
        .map(|r| {
            r.values
                .iter()
                .map(|v| v.as_deref().unwrap_or("?"))
                .collect()
        })
        .collect()
}

/// The fixture `name` read, after checking its relation and attribute names.
fn fixture_table(name: &str, relation: &str, attributes: &[&str]) -> ArffTable {
    let table = read_arff(&fixture(name)).unwrap();
    assert_eq!(table.relation, relation);
    assert_eq!(names(&table), attributes);
    table
}

fn names(table: &ArffTable) -> Vec<&str> {
    table.attributes.iter().map(|a| a.name.as_str()).collect()
}

/// Tabs between values, a comma and a tab together, leading blanks, comments on their
/// own lines and after values, blank lines, `@Relation`/`@ATTRIBUTE`/`@DATA`. Weka
/// (which prints the number `0.0` as `0`; the reader keeps numbers as written):
/// ```text
/// NotMove,None,None,Open,0,IdleMotion
/// Move,cube,None,Open,0.5,Reach
/// NotMove,cube,cube,Close,1,Take
/// Move,None,cube,Close,1.5,PutSomethingSomeWhere
/// NotMove,None,None,Open,2,IdleMotion
/// ```
#[test]
fn tab_separated_with_comments() {
    let table = fixture_table(
        "tabs.arff",
        "tabbed",
        &[
            "Hand",
            "ObjectActedOn",
            "ObjectInHand",
            "HandState",
            "Time",
            "Activity",
        ],
    );
    assert_eq!(
        table.attributes[1].kind,
        ArffKind::Nominal(vec!["None".into(), "cube".into()])
    );
    assert_eq!(table.attributes[4].kind, ArffKind::Numeric);
    assert_eq!(
        values(&table),
        [
            ["NotMove", "None", "None", "Open", "0.0", "IdleMotion"],
            ["Move", "cube", "None", "Open", "0.5", "Reach"],
            ["NotMove", "cube", "cube", "Close", "1.0", "Take"],
            [
                "Move",
                "None",
                "cube",
                "Close",
                "1.5",
                "PutSomethingSomeWhere"
            ],
            ["NotMove", "None", "None", "Open", "2.0", "IdleMotion"],
        ]
    );
    assert_eq!(
        table.rows.iter().map(|r| r.line).collect::<Vec<_>>(),
        [14, 15, 18, 19, 20]
    );
    // As hand frames: the Time column gives the times, the label map the activities.
    let frames = table.hand_frames(30.0).unwrap();
    assert!(frames.warnings.is_empty(), "{:?}", frames.warnings);
    let times: Vec<f64> = frames.frames.iter().map(|f| f.time).collect();
    assert_eq!(times, [0.0, 0.5, 1.0, 1.5, 2.0]);
    let mapped = frames.activities(&LabelMap::default());
    assert!(mapped.unknown.is_empty());
    assert_eq!(
        mapped.activities,
        [
            Some(Activity::Idle),
            Some(Activity::Reach),
            Some(Activity::Take),
            Some(Activity::Put),
            Some(Activity::Idle)
        ]
    );
}

/// Quoted names (`'Hand'`, `"ObjectActedOn"`) and values in both styles, `\'` and `\t`
/// escapes, `%` and `,` inside quotes, a quoted `'?'` (a value) and a bare `?`
/// (missing). Weka (its CSV saver quotes again what needs it):
/// ```text
/// NotMove,None,None,Idle,'it\'s resting'
/// Move,'red cube',None,Reach,'a \% sign, and a comma'
/// NotMove,None,'red cube',Take,'?'
/// Move,None,'red cube',Put,?
/// Move,'blue cube','red cube',Stack,'tab\there'
/// ```
#[test]
fn quoted_names_values_and_escapes() {
    let table = fixture_table(
        "quoted.arff",
        "pick and place: \"red\"",
        &["Hand", "ObjectActedOn", "ObjectInHand", "Activity", "note"],
    );
    assert_eq!(
        table.attributes[1].kind,
        ArffKind::Nominal(vec!["None".into(), "red cube".into(), "blue cube".into()])
    );
    assert_eq!(table.attributes[4].kind, ArffKind::String);
    let rows: Vec<Vec<Option<&str>>> = table
        .rows
        .iter()
        .map(|r| r.values.iter().map(|v| v.as_deref()).collect())
        .collect();
    assert_eq!(
        rows,
        [
            [
                Some("NotMove"),
                Some("None"),
                Some("None"),
                Some("Idle"),
                Some("it's resting")
            ],
            [
                Some("Move"),
                Some("red cube"),
                Some("None"),
                Some("Reach"),
                Some("a % sign, and a comma")
            ],
            [
                Some("NotMove"),
                Some("None"),
                Some("red cube"),
                Some("Take"),
                Some("?")
            ],
            [
                Some("Move"),
                Some("None"),
                Some("red cube"),
                Some("Put"),
                None
            ],
            [
                Some("Move"),
                Some("blue cube"),
                Some("red cube"),
                Some("Stack"),
                Some("tab\there")
            ],
        ]
    );
    // Objects with spaces in their names are entities of the frames' header.
    let frames = table.hand_frames(30.0).unwrap();
    let objects: Vec<&str> = frames.header.entities[1..]
        .iter()
        .map(|e| e.name.as_str())
        .collect();
    assert_eq!(objects, ["blue cube", "red cube"]);
}

/// Sparse rows mixed with a dense one; a value left out is the attribute's first
/// declared value. Weka, through SparseToNonSparse:
/// ```text
/// NotMove,None,None,Open,Idle
/// Move,cube,None,Open,Reach
/// NotMove,None,cube,Close,Take
/// Move,None,cube,Close,Put
/// NotMove,None,None,Open,?
/// NotMove,None,None,Open,Idle
/// ```
#[test]
fn sparse_rows_leave_out_the_first_nominal_value() {
    let table = read_arff(&fixture("sparse.arff")).unwrap();
    assert_eq!(
        values(&table),
        [
            ["NotMove", "None", "None", "Open", "Idle"],
            ["Move", "cube", "None", "Open", "Reach"],
            ["NotMove", "None", "cube", "Close", "Take"],
            ["Move", "None", "cube", "Close", "Put"],
            ["NotMove", "None", "None", "Open", "?"],
            ["NotMove", "None", "None", "Open", "Idle"],
        ]
    );
    // Segmented, the hand's own facts are the segments' states: the Take ends holding
    // the cube with the hand closed.
    let frames = table.hand_frames(30.0).unwrap();
    let (space, segments) = frames.segments(&ActivityTree::table_one(), 0.0);
    let take = segments
        .iter()
        .find(|s| s.activity == Activity::Take)
        .unwrap();
    let end: Vec<String> = take
        .end_state
        .facts(&space)
        .map(|f| f.display(&frames.header).to_string())
        .collect();
    assert_eq!(end, ["inHand(hand, cube)"]);
    let reach = segments
        .iter()
        .find(|s| s.activity == Activity::Reach)
        .unwrap();
    let predicates: Vec<Predicate> = reach.end_state.facts(&space).map(|f| f.predicate).collect();
    assert_eq!(
        predicates,
        [Predicate::HandMove, Predicate::HandOpen, Predicate::ActedOn]
    );
}

/// What a left-out value is for each type. Weka, through SparseToNonSparse with TZ=UTC:
/// ```text
/// 0,first,2024-05-01T10:00:00,green
/// 3.5,*WEKA*DUMMY*STRING*FOR*STRING*ATTRIBUTES*,1970-01-01T00:00:00,red
/// 0,'second name',1970-01-01T00:00:00,red
/// ```
#[test]
fn sparse_rows_of_every_type() {
    let table = read_arff(&fixture("sparse-types.arff")).unwrap();
    assert_eq!(
        table.attributes[2].kind,
        ArffKind::Date("yyyy-MM-dd'T'HH:mm:ss".into())
    );
    assert_eq!(
        values(&table),
        [
            ["0", "first", "2024-05-01T10:00:00", "green"],
            ["3.5", WEKA_DUMMY_STRING, "1970-01-01T00:00:00", "red"],
            ["0", "second name", "1970-01-01T00:00:00", "red"],
        ]
    );
}

/// A `.txt` table is ARFF by its content. Weka reads its labels as written
/// (`IdleMotion`, `Reach_1`, ..., `Pour`); the label map makes them activities by their
/// names without the instance suffix and leaves out `Pour`, which it does not know.
#[test]
fn a_txt_table_with_suffixed_and_unknown_labels() {
    let text = fixture("recogniser-labels.txt");
    assert!(is_arff_text(&text));
    assert!(!is_arff_text(
        &std::fs::read_to_string(concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/../../docs/examples/two-cubes.jsonl"
        ))
        .unwrap()
    ));
    let table = read_arff(&text).unwrap();
    let labels: Vec<&str> = values(&table).iter().map(|r| r[4]).collect();
    assert_eq!(
        labels,
        [
            "IdleMotion",
            "IdleMotion",
            "Reach_1",
            "Reach_1",
            "Take_1",
            "Take_1",
            "Pour",
            "Pour",
            "Pour",
            "PutSomethingSomewhere_1",
            "PutSomethingSomewhere_1",
            "Release_2",
            "Stack_3",
            "IdleMotion"
        ]
    );
    let frames = table.hand_frames(30.0).unwrap();
    let mapped = frames.activities(&LabelMap::default());
    use Activity::*;
    assert_eq!(
        mapped.activities,
        [
            Some(Idle),
            Some(Idle),
            Some(Reach),
            Some(Reach),
            Some(Take),
            Some(Take),
            None,
            None,
            None,
            Some(Put),
            Some(Put),
            Some(Put),
            Some(Stack),
            Some(Idle)
        ]
    );
    assert_eq!(mapped.left_out(), 3);
    let warning = mapped.warning().unwrap();
    assert_eq!(
        (warning.line, warning.message.as_str()),
        (
            17,
            "labels the label map does not know, left out: Pour (3 frames)"
        )
    );
    // An override maps Pour; learning then sees every frame.
    let map = LabelMap::with_overrides([("Pour", "Put")]).unwrap();
    let mapped = frames.activities(&map);
    assert_eq!(mapped.activities[6], Some(Put));
    assert_eq!(frames.dataset(&map).cases.len(), 14);
    assert_eq!(frames.dataset(&LabelMap::default()).cases.len(), 11);
}

/// Bad tables: the line, the 1-based column and the attribute (or keyword) named.
#[test]
fn mistakes_name_line_column_and_attribute() {
    let header = "@relation r\n@attribute a {x, y}\n@attribute n numeric\n@data\n";
    let check = |body: &str, line: usize, column: usize, field: &str, says: &str| {
        let text = format!("{header}{body}");
        let e = read_arff(&text)
            .err()
            .unwrap_or_else(|| panic!("accepted {body:?}"));
        assert_eq!(
            (e.line, e.column, e.field.as_str()),
            (line, column, field),
            "{body:?}: {e}"
        );
        assert!(e.message.contains(says), "{body:?}: {e}");
    };
    let cases: Vec<&str> = include_str!("fixtures/arff-data-mistakes.txt")
        .lines()
        .filter(|l| !l.starts_with('#'))
        .collect();
    assert_eq!(cases.len(), 12, "the fixture's cases");
    for case in cases {
        let [body, line, column, field, says] = case.split(" | ").collect::<Vec<_>>()[..] else {
            panic!("not a case: {case:?}");
        };
        let body = body.replace("\\n", "\n").replace("\\t", "\t");
        check(
            &body,
            line.parse().unwrap(),
            column.parse().unwrap(),
            field,
            says,
        );
    }
    let check_header = |text: &str, line: usize, field: &str, says: &str| {
        let e = read_arff(text)
            .err()
            .unwrap_or_else(|| panic!("accepted {text:?}"));
        assert_eq!((e.line, e.field.as_str()), (line, field), "{text:?}: {e}");
        assert!(e.message.contains(says), "{text:?}: {e}");
    };
    check_header("@attribute a {x}\n@data\n", 1, "@attribute", "starts with");
    check_header(
        "@relation stack two\n@data\n",
        1,
        "@relation",
        "a name with spaces is quoted",
    );
    check_header(
        "@relation r\n@attribute a {x, x}\n@data\n",
        2,
        "a",
        "declared twice",
    );
    check_header("@relation r\n@attribute a\n@data\n", 2, "a", "has no type");
    check_header(
        "@relation r\n@attribute a nominal\n@data\n",
        2,
        "a",
        "unknown type `nominal`",
    );
    check_header(
        "@relation r\n@attribute d date 'dd.MM.yyyy'\n@data\n{}\n",
        4,
        "d",
        "format `dd.MM.yyyy`",
    );
    check_header(
        "@relation r\n@attribute a {}\n@data\n{}\n",
        4,
        "a",
        "declares none",
    );
    check_header("@relation r\n@attribute a {x}\n", 2, "@data", "no @data");
}

/// Label map overrides name activities; anything else is refused with the label named.
#[test]
fn label_map_overrides_are_checked() {
    let e = LabelMap::with_overrides([("Pour", "Put"), ("Wipe", "Clean")]).unwrap_err();
    assert_eq!((e.label.as_str(), e.activity.as_str()), ("Wipe", "Clean"));
    let map = LabelMap::with_overrides([("IdleMotion", "Reach")]).unwrap();
    assert_eq!(map.activity("IdleMotion_4"), Some(Activity::Reach));
}

/// Texts made of ARFF's pieces, well and badly put together.
fn arff_pieces() -> impl proptest::strategy::Strategy<Value = String> {
    use proptest::prelude::*;
    let pieces = [
        "@relation r\n",
        "@RELATION 'a b'\n",
        "@attribute Hand {NotMove, Move}\n",
        "@attribute ObjectActedOn {None, 'red cube'}\n",
        "@attribute ObjectInHand {None,'red cube'}\n",
        "@attribute n numeric\n",
        "@attribute s string\n",
        "@attribute d date\n",
        "@data\n",
        "{",
        "}",
        "0 ",
        "1 Move",
        "2 ",
        "'",
        "\"",
        "\\",
        "\\1",
        "%",
        ",",
        "\t",
        " ",
        "?",
        "Move",
        "None",
        "3.5",
        "\n",
        "é",
        "\u{feff}",
        "\r\n",
    ];
    // Half of them after a good header, so that rows are read too.
    let header = "@relation r\n@attribute Hand {NotMove, Move}\n@attribute ObjectActedOn {None, 'red cube'}\n@attribute ObjectInHand {None, 'red cube'}\n@attribute n numeric\n@data\n";
    (
        any::<bool>(),
        proptest::collection::vec(proptest::sample::select(pieces.to_vec()), 0..40),
    )
        .prop_map(move |(h, p)| {
            let body = p.concat();
            if h {
                format!("{header}{body}")
            } else {
                body
            }
        })
}

proptest::proptest! {
    /// Whatever the text, the reader answers: a table whose rows each have one value per
    /// attribute (and which reads as hand frames or says why), or an error whose line
    /// exists and whose column is on a character of it (the CLI underlines it there).
    #[test]
    fn any_text_reads_or_is_refused_at_a_real_place(text in arff_pieces()) {
        match read_arff(&text) {
            Ok(table) => {
                for row in &table.rows {
                    proptest::prop_assert_eq!(row.values.len(), table.attributes.len());
                }
                if let Ok(frames) = table.hand_frames(30.0) {
                    let _ = frames.segments(&ActivityTree::table_one(), 0.1);
                    let _ = frames.dataset(&LabelMap::default());
                }
            }
            Err(e) => {
                let lines: Vec<&str> = text.lines().collect();
                proptest::prop_assert!(e.line >= 1 && e.line <= lines.len().max(1), "{e}");
                if e.column > 0 {
                    let line = lines[e.line - 1];
                    proptest::prop_assert!(e.column <= line.len() + 1, "{e}");
                    proptest::prop_assert!(line.is_char_boundary(e.column - 1), "{e}");
                }
            }
        }
    }
}

/// Runs of separators count as one (`1,,x` is two values), words after a numeric type
/// are ignored, and a trailing comment ends a row. Weka 3.6.14 reads these rows as
/// `1,x`, `2,y`, `0,y`.
#[test]
fn separators_collapse_and_type_trailers_are_ignored() {
    let text = "@relation r\n@attribute a numeric ignored words\n@attribute b {x,y}\n@data\n1,,x\n2 y % c\n{1 y}\n";
    let table = read_arff(text).unwrap();
    assert_eq!(table.attributes[0].kind, ArffKind::Numeric);
    assert_eq!(values(&table), [["1", "x"], ["2", "y"], ["0", "y"]]);
}

/// Read a row at a time from any `BufRead` (here one that hands out a byte at a time, and
/// with Windows line ends), each fixture gives the rows `read_arff` gives for its text,
/// and the two passes of `HandTable` give the frames `hand_frames` gives.
#[test]
fn rows_read_one_at_a_time_are_the_rows_of_the_whole_text() {
    use segment::{ArffReader, HandTable};
    use std::io::BufReader;
    for name in [
        "tabs.arff",
        "quoted.arff",
        "sparse.arff",
        "sparse-types.arff",
        "recogniser-labels.txt",
        "messy-hand-state.arff",
        "weather.nominal.arff",
    ] {
        let text = fixture(name);
        let whole = read_arff(&text).unwrap();
        for text in [text.clone(), text.replace('\n', "\r\n")] {
            let reader = ArffReader::new(BufReader::with_capacity(1, text.as_bytes())).unwrap();
            assert_eq!(reader.relation(), whole.relation, "{name}");
            assert_eq!(reader.attributes(), whole.attributes, "{name}");
            let rows: Vec<_> = reader.collect::<Result<_, _>>().unwrap();
            assert_eq!(rows, whole.rows, "{name}");
            if whole.is_hand_state() {
                let table = HandTable::scan(
                    &whole.relation,
                    &whole.attributes,
                    ArffReader::new(text.as_bytes()).unwrap(),
                    30.0,
                )
                .unwrap();
                let frames: Vec<_> = table
                    .frames(ArffReader::new(text.as_bytes()).unwrap())
                    .collect::<Result<_, _>>()
                    .unwrap();
                let in_memory = whole.hand_frames(30.0).unwrap();
                assert_eq!(frames, in_memory.frames, "{name}");
                assert_eq!(table.header, in_memory.header, "{name}");
                assert_eq!(table.labels, in_memory.labels, "{name}");
                assert_eq!(table.warnings, in_memory.warnings, "{name}");
            }
        }
    }
}

/// A line that is not UTF-8 text is an error at that line, and the rows before it read.
#[test]
fn a_line_that_is_not_utf8_is_an_error_at_its_line() {
    let mut bytes = b"@relation r\n@attribute a {x, y}\n@data\nx\ny\n".to_vec();
    bytes.extend_from_slice(b"\xff\n");
    let mut reader = segment::ArffReader::new(&bytes[..]).unwrap();
    assert_eq!(reader.next().unwrap().unwrap().line, 4);
    assert_eq!(reader.next().unwrap().unwrap().line, 5);
    let e = reader.next().unwrap().unwrap_err();
    assert_eq!(
        (e.line, e.message.as_str()),
        (6, "the line is not UTF-8 text")
    );
    assert!(reader.next().is_none());
}
