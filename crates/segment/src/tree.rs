//! Decision trees as data: nominal attributes, printed as Weka's J48 prints them, stored
//! as JSON; and the activity tree, whose default is the paper's Table 1.

use std::fmt;

use grounding::HandFacts;
use serde::{Deserialize, Serialize};

pub use recording::Activity;

/// A nominal attribute: a name and its values.
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize)]
pub struct Attribute {
    /// The name.
    pub name: String,
    /// The values it takes, in order.
    pub values: Vec<String>,
}

impl Attribute {
    /// An attribute from names.
    pub fn new(name: &str, values: &[&str]) -> Attribute {
        Attribute {
            name: name.into(),
            values: values.iter().map(|v| v.to_string()).collect(),
        }
    }

    /// The index of a value.
    pub fn value(&self, name: &str) -> Option<usize> {
        self.values.iter().position(|v| v == name)
    }
}

/// A node of a [`DecisionTree`].
#[derive(Debug, Clone, PartialEq)]
pub enum Node {
    /// A class, with the (weighted) training cases that reached it and how many of them
    /// were of another class.
    Leaf {
        /// Index into [`DecisionTree::classes`].
        class: usize,
        /// Training cases here (0 for a branch no case took).
        cases: f64,
        /// Of which misclassified.
        errors: f64,
    },
    /// A test of one attribute, one branch per value.
    Split {
        /// Index into [`DecisionTree::attributes`].
        attribute: usize,
        /// One child per value of the attribute, in its order.
        branches: Vec<Node>,
        /// The branch taken when the value is unknown (the one most cases took).
        default: usize,
    },
}

/// A decision tree over nominal attributes.
#[derive(Debug, Clone, PartialEq)]
pub struct DecisionTree {
    /// What is tested.
    pub attributes: Vec<Attribute>,
    /// Name of the class (`Activity`).
    pub class_name: String,
    /// The classes leaves name.
    pub classes: Vec<String>,
    /// The root.
    pub root: Node,
}

/// A tree file (or tree) that cannot be used: where, and what; the field is a path
/// (`root.branches[1].node.class`).
pub type TreeError = recording::TextError;

/// The `format` field of a tree file.
pub const TREE_FORMAT: &str = "demoplan-tree";

#[derive(Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct RawTree {
    format: String,
    version: u32,
    class: String,
    classes: Vec<String>,
    attributes: Vec<Attribute>,
    root: RawNode,
}

#[derive(Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct RawNode {
    #[serde(default, skip_serializing_if = "Option::is_none")]
    split: Option<String>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    default: Option<String>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    branches: Option<Vec<RawBranch>>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    class: Option<String>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    cases: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    errors: Option<f64>,
}

#[derive(Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct RawBranch {
    value: String,
    node: RawNode,
}

impl DecisionTree {
    /// The class of a case: `values[a]` is the value of attribute `a`, `None` when unknown
    /// (the split's default branch is taken).
    pub fn classify(&self, values: &[Option<usize>]) -> usize {
        let mut node = &self.root;
        loop {
            match node {
                Node::Leaf { class, .. } => return *class,
                Node::Split {
                    attribute,
                    branches,
                    default,
                } => {
                    let v = values
                        .get(*attribute)
                        .copied()
                        .flatten()
                        .unwrap_or(*default);
                    match branches.get(v).or_else(|| branches.get(*default)) {
                        Some(next) => node = next,
                        None => return 0,
                    }
                }
            }
        }
    }

    /// Number of leaves.
    pub fn leaves(&self) -> usize {
        fn count(n: &Node) -> usize {
            match n {
                Node::Leaf { .. } => 1,
                Node::Split { branches, .. } => branches.iter().map(count).sum(),
            }
        }
        count(&self.root)
    }

    /// Number of nodes.
    pub fn size(&self) -> usize {
        fn count(n: &Node) -> usize {
            match n {
                Node::Leaf { .. } => 1,
                Node::Split { branches, .. } => 1 + branches.iter().map(count).sum::<usize>(),
            }
        }
        count(&self.root)
    }

    /// The tree as a JSON document (the format [`DecisionTree::from_json`] reads).
    pub fn to_json(&self) -> String {
        fn raw(t: &DecisionTree, n: &Node) -> RawNode {
            match n {
                Node::Leaf {
                    class,
                    cases,
                    errors,
                } => RawNode {
                    split: None,
                    default: None,
                    branches: None,
                    class: t.classes.get(*class).cloned(),
                    cases: Some(*cases),
                    errors: Some(*errors),
                },
                Node::Split {
                    attribute,
                    branches,
                    default,
                } => {
                    let a = &t.attributes[*attribute];
                    RawNode {
                        split: Some(a.name.clone()),
                        default: a.values.get(*default).cloned(),
                        branches: Some(
                            branches
                                .iter()
                                .zip(&a.values)
                                .map(|(b, v)| RawBranch {
                                    value: v.clone(),
                                    node: raw(t, b),
                                })
                                .collect(),
                        ),
                        class: None,
                        cases: None,
                        errors: None,
                    }
                }
            }
        }
        let tree = RawTree {
            format: TREE_FORMAT.into(),
            version: 1,
            class: self.class_name.clone(),
            classes: self.classes.clone(),
            attributes: self.attributes.clone(),
            root: raw(self, &self.root),
        };
        let mut text = serde_json::to_string_pretty(&tree).unwrap_or_default();
        text.push('\n');
        text
    }

    /// Reads a tree written by [`DecisionTree::to_json`] (or by hand).
    pub fn from_json(text: &str) -> Result<DecisionTree, TreeError> {
        let raw: RawTree = serde_json::from_str(text).map_err(|e| TreeError {
            line: e.line(),
            column: e.column(),
            field: String::new(),
            message: e.to_string(),
        })?;
        let fail = |field: String, message: String, needle: Option<&str>| {
            let (line, column) = needle.map_or((0, 0), |n| locate(text, n));
            TreeError {
                line,
                column,
                field,
                message,
            }
        };
        if raw.format != TREE_FORMAT || raw.version != 1 {
            return Err(fail(
                "format".into(),
                format!(
                    "not a demoplan tree of version 1 (format `{}`, version {})",
                    raw.format, raw.version
                ),
                Some(&raw.format),
            ));
        }
        for (i, a) in raw.attributes.iter().enumerate() {
            if raw.attributes[..i].iter().any(|b| b.name == a.name) {
                return Err(fail(
                    format!("attributes[{i}].name"),
                    format!("attribute `{}` is declared twice", a.name),
                    Some(&a.name),
                ));
            }
        }
        let mut used = vec![false; raw.attributes.len()];
        let root = convert(&raw, &raw.root, "root", &mut used, &fail)?;
        Ok(DecisionTree {
            attributes: raw.attributes,
            class_name: raw.class,
            classes: raw.classes,
            root,
        })
    }
}

type Fail<'a> = dyn Fn(String, String, Option<&str>) -> TreeError + 'a;

fn convert(
    t: &RawTree,
    n: &RawNode,
    path: &str,
    used: &mut Vec<bool>,
    fail: &Fail<'_>,
) -> Result<Node, TreeError> {
    match (&n.split, &n.class) {
        (Some(_), Some(_)) | (None, None) => Err(fail(
            path.into(),
            "a node has either `split` (with `branches`) or `class`".into(),
            None,
        )),
        (None, Some(class)) => {
            let c = t.classes.iter().position(|c| c == class).ok_or_else(|| {
                fail(
                    format!("{path}.class"),
                    format!("`{class}` is not one of the tree's classes"),
                    Some(class),
                )
            })?;
            Ok(Node::Leaf {
                class: c,
                cases: n.cases.unwrap_or(0.0),
                errors: n.errors.unwrap_or(0.0),
            })
        }
        (Some(split), None) => {
            let a = t
                .attributes
                .iter()
                .position(|a| &a.name == split)
                .ok_or_else(|| {
                    fail(
                        format!("{path}.split"),
                        format!("`{split}` is not one of the tree's attributes"),
                        Some(split),
                    )
                })?;
            if used[a] {
                return Err(fail(
                    format!("{path}.split"),
                    format!("`{split}` is tested twice on one path"),
                    Some(split),
                ));
            }
            let attribute = &t.attributes[a];
            let raw_branches = n.branches.as_deref().unwrap_or(&[]);
            let mut branches: Vec<Option<Node>> = vec![None; attribute.values.len()];
            used[a] = true;
            for (i, b) in raw_branches.iter().enumerate() {
                let v = attribute.value(&b.value).ok_or_else(|| {
                    fail(
                        format!("{path}.branches[{i}].value"),
                        format!("`{}` is not a value of `{split}`", b.value),
                        Some(&b.value),
                    )
                })?;
                if branches[v].is_some() {
                    return Err(fail(
                        format!("{path}.branches[{i}].value"),
                        format!("value `{}` has two branches", b.value),
                        Some(&b.value),
                    ));
                }
                branches[v] = Some(convert(
                    t,
                    &b.node,
                    &format!("{path}.branches[{i}].node"),
                    used,
                    fail,
                )?);
            }
            used[a] = false;
            let missing: Vec<&str> = attribute
                .values
                .iter()
                .zip(&branches)
                .filter(|(_, b)| b.is_none())
                .map(|(v, _)| v.as_str())
                .collect();
            if !missing.is_empty() {
                return Err(fail(
                    format!("{path}.branches"),
                    format!("no branch for {} of `{split}`", missing.join(", ")),
                    Some(split),
                ));
            }
            let default = match &n.default {
                None => 0,
                Some(d) => attribute.value(d).ok_or_else(|| {
                    fail(
                        format!("{path}.default"),
                        format!("`{d}` is not a value of `{split}`"),
                        Some(d),
                    )
                })?,
            };
            Ok(Node::Split {
                attribute: a,
                branches: branches.into_iter().flatten().collect(),
                default,
            })
        }
    }
}

/// Line and column of the first occurrence of `"needle"` in the text.
fn locate(text: &str, needle: &str) -> (usize, usize) {
    let quoted = format!("\"{needle}\"");
    text.lines()
        .enumerate()
        .find_map(|(i, l)| l.find(&quoted).map(|c| (i + 1, c + 2)))
        .unwrap_or((0, 0))
}

/// Prints as Weka's J48 does: one line per branch, `|   ` per level, leaves with
/// `class (cases/errors)`.
impl fmt::Display for DecisionTree {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        fn leaf(f: &mut fmt::Formatter<'_>, t: &DecisionTree, n: &Node) -> fmt::Result {
            if let Node::Leaf {
                class,
                cases,
                errors,
            } = n
            {
                let name = t.classes.get(*class).map_or("?", String::as_str);
                if *errors > 0.0 {
                    write!(f, ": {name} ({cases:.1}/{errors:.1})")
                } else {
                    write!(f, ": {name} ({cases:.1})")
                }
            } else {
                Ok(())
            }
        }
        fn walk(
            f: &mut fmt::Formatter<'_>,
            t: &DecisionTree,
            n: &Node,
            depth: usize,
        ) -> fmt::Result {
            let Node::Split {
                attribute,
                branches,
                ..
            } = n
            else {
                return Ok(());
            };
            let a = &t.attributes[*attribute];
            for (b, v) in branches.iter().zip(&a.values) {
                for _ in 0..depth {
                    f.write_str("|   ")?;
                }
                write!(f, "{} = {v}", a.name)?;
                match b {
                    Node::Leaf { .. } => {
                        leaf(f, t, b)?;
                        writeln!(f)?;
                    }
                    Node::Split { .. } => {
                        writeln!(f)?;
                        walk(f, t, b, depth + 1)?;
                    }
                }
            }
            Ok(())
        }
        if let Node::Leaf { .. } = self.root {
            write!(f, "{}", self.class_name)?;
            leaf(f, self, &self.root)?;
            writeln!(f)?;
        } else {
            walk(f, self, &self.root, 0)?;
        }
        writeln!(f)?;
        writeln!(f, "Number of Leaves  : {}", self.leaves())?;
        writeln!(f)?;
        writeln!(f, "Size of the tree : {}", self.size())
    }
}

/// The features of a hand the activity tree may test: attribute names and their values.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Feature {
    /// `handMove` with values `F`, `T`.
    HandMove,
    /// `actedOn` with values `nil`, `object`.
    ActedOn,
    /// `inHand` with values `nil`, `object`.
    InHand,
    /// `handOpen` with values `F`, `T` (unknown when a table leaves it out).
    HandOpen,
}

impl Feature {
    /// Every feature.
    pub const ALL: [Feature; 4] = [
        Feature::HandMove,
        Feature::ActedOn,
        Feature::InHand,
        Feature::HandOpen,
    ];

    /// The attribute name.
    pub fn name(self) -> &'static str {
        match self {
            Feature::HandMove => "handMove",
            Feature::ActedOn => "actedOn",
            Feature::InHand => "inHand",
            Feature::HandOpen => "handOpen",
        }
    }

    /// The attribute's values: false first, then true.
    pub fn values(self) -> [&'static str; 2] {
        match self {
            Feature::HandMove | Feature::HandOpen => ["F", "T"],
            Feature::ActedOn | Feature::InHand => ["nil", "object"],
        }
    }

    /// The attribute, as a tree declares it.
    pub fn attribute(self) -> Attribute {
        Attribute::new(self.name(), &self.values())
    }

    /// The feature's value for a hand: `Some(true)` for `T` / `object`.
    pub fn of(self, hand: &HandFacts) -> Option<bool> {
        match self {
            Feature::HandMove => Some(hand.moving),
            Feature::ActedOn => Some(hand.acted_on.is_some()),
            Feature::InHand => Some(hand.in_hand.is_some()),
            Feature::HandOpen => hand.open,
        }
    }

    fn from_name(name: &str) -> Option<Feature> {
        Feature::ALL.into_iter().find(|f| f.name() == name)
    }
}

/// A decision tree that classifies hands into the paper's activities: its attributes are
/// [`Feature`]s and its classes [`Activity`] names. Classifying is a table look-up (the
/// tree is evaluated once per combination of features when it is made).
#[derive(Debug, Clone, PartialEq)]
pub struct ActivityTree {
    tree: DecisionTree,
    /// Indexed by moving + 2 acted + 4 held + 8 open (open: 0 false, 1 true, 2 unknown).
    table: [Activity; 24],
}

impl ActivityTree {
    /// The paper's Table 1 as a tree: a tuple that matches no row is Idle.
    pub fn table_one() -> ActivityTree {
        let c = |a: Activity| Node::Leaf {
            class: a.index(),
            cases: 0.0,
            errors: 0.0,
        };
        // Attributes: 0 actedOn, 1 handMove, 2 inHand.
        let split = |attribute: usize, no: Node, yes: Node| Node::Split {
            attribute,
            branches: vec![no, yes],
            default: 0,
        };
        let root = split(
            0,
            split(
                2,
                c(Activity::Idle),
                split(1, c(Activity::Take), c(Activity::Put)),
            ),
            split(
                1,
                c(Activity::Idle),
                split(2, c(Activity::Reach), c(Activity::Stack)),
            ),
        );
        let tree = DecisionTree {
            attributes: vec![
                Feature::ActedOn.attribute(),
                Feature::HandMove.attribute(),
                Feature::InHand.attribute(),
            ],
            class_name: "Activity".into(),
            classes: Activity::ALL.iter().map(|a| a.name().to_string()).collect(),
            root,
        };
        // The tree above is valid by construction.
        ActivityTree::new(tree).unwrap_or_else(|_| ActivityTree {
            tree: DecisionTree {
                attributes: Vec::new(),
                class_name: "Activity".into(),
                classes: vec!["Idle".into()],
                root: c(Activity::Idle),
            },
            table: [Activity::Idle; 24],
        })
    }

    /// Checks that a tree tests hand features and names activities.
    pub fn new(tree: DecisionTree) -> Result<ActivityTree, TreeError> {
        let err = |field: String, message: String| TreeError {
            line: 0,
            column: 0,
            field,
            message,
        };
        let mut features = Vec::new();
        for (i, a) in tree.attributes.iter().enumerate() {
            let f = Feature::from_name(&a.name).ok_or_else(|| {
                err(
                    format!("attributes[{i}].name"),
                    format!(
                        "`{}` is not a hand feature (handMove, actedOn, inHand, handOpen)",
                        a.name
                    ),
                )
            })?;
            let mut map = Vec::new();
            for v in &a.values {
                let truth = f.values().iter().position(|x| x == v).ok_or_else(|| {
                    err(
                        format!("attributes[{i}].values"),
                        format!(
                            "`{v}` is not a value of `{}` ({})",
                            a.name,
                            f.values().join(", ")
                        ),
                    )
                })?;
                map.push(truth == 1);
            }
            features.push((f, map));
        }
        let mut classes = Vec::new();
        for (i, c) in tree.classes.iter().enumerate() {
            classes.push(Activity::from_name(c).ok_or_else(|| {
                err(
                    format!("classes[{i}]"),
                    format!("`{c}` is not an activity (Stack, Idle, Reach, Put, Take)"),
                )
            })?);
        }
        let mut table = [Activity::Idle; 24];
        for (k, slot) in table.iter_mut().enumerate() {
            let hand = [k & 1 != 0, k & 2 != 0, k & 4 != 0];
            let open = match k / 8 {
                0 => Some(false),
                1 => Some(true),
                _ => None,
            };
            let values: Vec<Option<usize>> = features
                .iter()
                .map(|(f, map)| {
                    let v = match f {
                        Feature::HandMove => Some(hand[0]),
                        Feature::ActedOn => Some(hand[1]),
                        Feature::InHand => Some(hand[2]),
                        Feature::HandOpen => open,
                    };
                    v.and_then(|v| map.iter().position(|&m| m == v))
                })
                .collect();
            *slot = classes
                .get(tree.classify(&values))
                .copied()
                .unwrap_or(Activity::Idle);
        }
        Ok(ActivityTree { tree, table })
    }

    /// The activity of a hand in a frame.
    pub fn classify(&self, hand: &HandFacts) -> Activity {
        let open = match hand.open {
            Some(false) => 0,
            Some(true) => 1,
            None => 2,
        };
        let k = usize::from(hand.moving)
            + 2 * usize::from(hand.acted_on.is_some())
            + 4 * usize::from(hand.in_hand.is_some())
            + 8 * open;
        self.table[k]
    }

    /// The tree.
    pub fn tree(&self) -> &DecisionTree {
        &self.tree
    }
}

impl Default for ActivityTree {
    fn default() -> Self {
        ActivityTree::table_one()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use recording::EntityId;

    fn hand(moving: bool, acted: bool, held: bool) -> HandFacts {
        HandFacts {
            moving,
            open: None,
            acted_on: acted.then_some(EntityId(3)),
            in_hand: held.then_some(EntityId(4)),
        }
    }

    #[test]
    fn table_one_as_a_tree() {
        let t = ActivityTree::table_one();
        assert_eq!(t.classify(&hand(true, true, true)), Activity::Stack);
        assert_eq!(t.classify(&hand(true, false, false)), Activity::Idle);
        assert_eq!(t.classify(&hand(false, false, false)), Activity::Idle);
        assert_eq!(t.classify(&hand(true, true, false)), Activity::Reach);
        assert_eq!(t.classify(&hand(true, false, true)), Activity::Put);
        assert_eq!(t.classify(&hand(false, false, true)), Activity::Take);
        // No row: not moving but acting on an object.
        assert_eq!(t.classify(&hand(false, true, false)), Activity::Idle);
        assert_eq!(t.classify(&hand(false, true, true)), Activity::Idle);
    }

    #[test]
    fn trees_print_and_read_back() {
        let t = ActivityTree::table_one();
        let text = t.tree().to_string();
        assert!(
            text.starts_with("actedOn = nil\n|   inHand = nil: Idle (0.0)\n"),
            "{text}"
        );
        let json = t.tree().to_json();
        let back = DecisionTree::from_json(&json);
        assert_eq!(back.as_ref(), Ok(t.tree()));
    }

    #[test]
    fn bad_trees_name_the_field() {
        let json = ActivityTree::table_one().tree().to_json();
        let bad = json.replacen("\"split\": \"handMove\"", "\"split\": \"handMov\"", 1);
        let e = DecisionTree::from_json(&bad).err();
        let e = e.map(|e| (e.field, e.line > 1));
        assert_eq!(
            e,
            Some(("root.branches[0].node.branches[1].node.split".into(), true))
        );
        let e = DecisionTree::from_json("{\"format\": 3}")
            .err()
            .map(|e| e.line);
        assert_eq!(e, Some(1));
    }
}
