//! C4.5 against a textbook answer and against Table 1, and the ARFF reader on tidy and
//! messy hand-state tables.

#![allow(clippy::unwrap_used, clippy::expect_used)]

use segment::{read_arff, Activity, ActivityTree, ArffKind, DecisionTree, C45};

fn fixture(name: &str) -> String {
    std::fs::read_to_string(format!(
        "{}/tests/fixtures/{name}",
        env!("CARGO_MANIFEST_DIR")
    ))
    .unwrap()
}

/// Quinlan's weather data: the known tree splits on outlook, then humidity under sunny
/// and windy under rainy (as Weka's J48 prints it).
#[test]
fn c45_learns_the_known_tree_of_the_weather_data() {
    let table = read_arff(&fixture("weather.nominal.arff")).unwrap();
    assert_eq!(table.rows.len(), 14);
    let (data, warnings) = table.dataset(None).unwrap();
    assert!(warnings.is_empty(), "{warnings:?}");
    assert_eq!(data.class_name, "play");
    let tree = C45::default().learn(&data);
    assert_eq!(
        tree.to_string(),
        "outlook = sunny\n\
         |   humidity = high: no (3.0)\n\
         |   humidity = normal: yes (2.0)\n\
         outlook = overcast: yes (4.0)\n\
         outlook = rainy\n\
         |   windy = TRUE: no (2.0)\n\
         |   windy = FALSE: yes (3.0)\n\
         \n\
         Number of Leaves  : 5\n\
         \n\
         Size of the tree : 8\n"
    );
    for c in &data.cases {
        assert_eq!(tree.classify(&c.values), c.class);
    }
    // Trees read back from JSON as they were.
    assert_eq!(DecisionTree::from_json(&tree.to_json()).unwrap(), tree);
    // Without pruning the tree is the same: nothing to prune here.
    let unpruned = C45 {
        prune: false,
        ..C45::default()
    }
    .learn(&data);
    assert_eq!(unpruned, tree);
}

#[test]
fn pruning_removes_splits_that_do_not_pay() {
    // One attribute that predicts nothing beyond noise: 20 cases, class mostly `a`.
    let mut text =
        String::from("@relation noise\n@attribute x {p, q}\n@attribute c {a, b}\n@data\n");
    for i in 0..20 {
        let x = if i % 2 == 0 { "p" } else { "q" };
        let c = if i == 3 || i == 8 { "b" } else { "a" };
        text.push_str(&format!("{x},{c}\n"));
    }
    let (data, _) = read_arff(&text).unwrap().dataset(None).unwrap();
    let tree = C45::default().learn(&data);
    assert_eq!(tree.leaves(), 1, "{tree}");
}

#[test]
fn a_hand_state_table_learns_table_one() {
    let table = read_arff(&fixture("hand-state.arff")).unwrap();
    assert!(table.is_hand_state());
    let frames = table.hand_frames(30.0).unwrap();
    assert!(frames.warnings.is_empty(), "{:?}", frames.warnings);
    assert_eq!(frames.frames.len(), 25);
    assert_eq!(frames.header.entities[1].name, "Something");
    let tree = C45 {
        min_cases: 1.0,
        ..C45::default()
    }
    .learn(&frames.dataset(&segment::LabelMap::default()));
    let activities = ActivityTree::new(tree).unwrap();
    let table_one = ActivityTree::table_one();
    for f in &frames.frames {
        let label = Activity::from_name(f.label.as_deref().unwrap()).unwrap();
        assert_eq!(activities.classify(&f.hand), label);
        assert_eq!(table_one.classify(&f.hand), label);
    }
}

#[test]
fn messy_tables_are_read_and_what_was_accepted_is_said() {
    let table = read_arff(&fixture("messy-hand-state.arff")).unwrap();
    assert_eq!(table.relation, "pancake");
    assert!(matches!(&table.attributes[0].kind, ArffKind::Nominal(v) if v.len() == 3));
    let frames = table.hand_frames(30.0).unwrap();
    let messages: Vec<String> = frames
        .warnings
        .iter()
        .map(|w| format!("{}: {}", w.line, w.message))
        .collect();
    assert_eq!(
        messages,
        [
            "12: `ObjectActedOn`: read `NONE` as None",
            "12: `ObjectInHand`: read `none` as None",
            "13: `ObjectActedOn`: accepted object names (spatula) where the header declares only {None, Something}",
            "16: `ObjectInHand`: accepted object names (spatula) where the header declares only {None, Something}",
            "18: `Activity`: accepted labels the header does not declare: Flip",
        ]
    );
    let spatula = frames
        .header
        .entities
        .iter()
        .position(|e| e.name == "spatula")
        .unwrap();
    assert_eq!(
        frames.frames[2].hand.acted_on.map(|e| e.index()),
        Some(spatula)
    );
    assert!(frames.frames[1].hand.acted_on.is_none());
    // ToolUse is a moving hand.
    assert!(frames.frames[6].hand.moving);
    assert_eq!(frames.labels, ["Idle", "Reach", "Take", "Put", "Flip"]);
    assert!(!frames.has_hand_state);
}

#[test]
fn arff_mistakes_name_line_and_field() {
    let check = |text: &str, line: usize, field: &str| {
        let e = read_arff(text)
            .err()
            .unwrap_or_else(|| panic!("accepted {text:?}"));
        assert_eq!((e.line, e.field.as_str()), (line, field), "{e}");
    };
    check("@relation r\n@attribute a {x, y}\n@data\nx,y\n", 4, "a");
    check("@relation r\n@attribute a numeric\n@data\nfour\n", 4, "a");
    check("@relation r\n@attribute a {x, y\n@data\n", 2, "a");
    check(
        "@relation r\n@attribute a {x}\n@attribute a {y}\n@data\n",
        3,
        "a",
    );
    check("@relation r\n@atribute a {x}\n@data\n", 2, "@atribute");
    check("@relation r\n@attribute a {x}\n@data\n'x\n", 4, "a");
    check("@relation r\n@attribute a {x}\n", 2, "@data");
    let table = read_arff("@relation r\n@attribute Hand {Move}\n@attribute ObjectActedOn {None}\n@attribute ObjectInHand {None}\n@data\nRun,None,None\n").unwrap();
    let e = table.hand_frames(30.0).err().unwrap();
    assert_eq!((e.line, e.field.as_str()), (6, "Hand"));
}
