//! Message definitions as bags carry them: the text of a ROS 1 connection header's
//! `message_definition` or of an MCAP `ros1msg`/`ros2msg` schema. The main type comes
//! first; each type it uses follows after a line of `=` and a `MSG: pkg/Type` line.
//!
//! A definition is compiled into a [`Schema`]: a table of message types whose fields name
//! either a primitive or another entry of the table, so that decoding never looks a name up.

use std::collections::HashMap;
use std::sync::Arc;

/// Longest chain of nested messages a schema may have. ROS types are never recursive; a
/// definition that nests deeper than this is refused rather than followed.
pub const MAX_NESTING: usize = 64;

/// The builtin field types of ROS 1 and ROS 2 messages.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Primitive {
    Bool,
    Int8,
    UInt8,
    Int16,
    UInt16,
    Int32,
    UInt32,
    Int64,
    UInt64,
    Float32,
    Float64,
    String,
    /// ROS 1 `time`: seconds and nanoseconds, both unsigned 32-bit.
    Time,
    /// ROS 1 `duration`: seconds and nanoseconds, both signed 32-bit.
    Duration,
}

impl Primitive {
    fn from_name(name: &str) -> Option<Primitive> {
        Some(match name {
            "bool" => Primitive::Bool,
            // ROS 1 `byte` is int8 and `char` uint8; ROS 2 `byte` and `char` are one octet too.
            "int8" | "byte" => Primitive::Int8,
            "uint8" | "char" => Primitive::UInt8,
            "int16" => Primitive::Int16,
            "uint16" => Primitive::UInt16,
            "int32" => Primitive::Int32,
            "uint32" => Primitive::UInt32,
            "int64" => Primitive::Int64,
            "uint64" => Primitive::UInt64,
            "float32" => Primitive::Float32,
            "float64" => Primitive::Float64,
            "string" => Primitive::String,
            "time" => Primitive::Time,
            "duration" => Primitive::Duration,
            _ => return None,
        })
    }

    /// Bytes the value takes on the wire at least (a string's length prefix).
    pub fn min_size(self) -> usize {
        match self {
            Primitive::Bool | Primitive::Int8 | Primitive::UInt8 => 1,
            Primitive::Int16 | Primitive::UInt16 => 2,
            Primitive::Int32 | Primitive::UInt32 | Primitive::Float32 | Primitive::String => 4,
            Primitive::Int64 | Primitive::UInt64 | Primitive::Float64 => 8,
            Primitive::Time | Primitive::Duration => 8,
        }
    }
}

/// Index of a message type in its [`Schema`].
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct TypeId(pub u32);

/// What one element of a field is.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ElementType {
    Primitive(Primitive),
    Message(TypeId),
}

/// Whether a field is one element, a fixed-size array or a sequence with a length prefix.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Arity {
    Single,
    Fixed(u32),
    /// A sequence, bounded (`T[<=N]`) or not; the bound is not enforced on reading.
    Sequence,
}

#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Field {
    pub name: Arc<str>,
    pub element: ElementType,
    pub arity: Arity,
}

/// One message type: its full name (`pkg/Type`) and fields in wire order.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct MessageType {
    pub name: String,
    pub fields: Vec<Field>,
    /// The field names, shared by every decoded value of this type.
    pub field_names: Arc<[Arc<str>]>,
}

/// A compiled definition: the root type and every type it uses.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Schema {
    pub types: Vec<MessageType>,
    pub root: TypeId,
}

/// What is wrong with a definition, and on which line of its text.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("line {line}: {what}")]
pub struct DefinitionError {
    /// 1-based line in the definition text (0 when the problem is not on one line).
    pub line: usize,
    pub what: String,
}

impl Schema {
    pub fn root_type(&self) -> &MessageType {
        &self.types[self.root.0 as usize]
    }

    pub fn message_type(&self, id: TypeId) -> &MessageType {
        &self.types[id.0 as usize]
    }

    /// Parses a definition whose main type is `type_name` (`pkg/Type` or `pkg/msg/Type`).
    pub fn parse(type_name: &str, text: &str) -> Result<Schema, DefinitionError> {
        let root_name = normalize_type_name(type_name);
        // Split into sections: (type name, first line number, lines).
        let mut sections: Vec<(String, Vec<(usize, &str)>)> = vec![(root_name.clone(), Vec::new())];
        for (index, line) in text.lines().enumerate() {
            let number = index.saturating_add(1);
            let trimmed = line.trim();
            if trimmed.len() >= 3 && trimmed.bytes().all(|b| b == b'=') {
                sections.push((String::new(), Vec::new()));
                continue;
            }
            if let Some(name) = trimmed.strip_prefix("MSG:") {
                if let Some(last) = sections.last_mut() {
                    if last.0.is_empty() {
                        last.0 = normalize_type_name(name.trim());
                        continue;
                    }
                }
                return Err(DefinitionError {
                    line: number,
                    what: "`MSG:` line that does not follow a line of `=`".into(),
                });
            }
            if let Some(last) = sections.last_mut() {
                last.1.push((number, line));
            }
        }
        let mut texts: HashMap<String, Vec<(usize, &str)>> = HashMap::new();
        for (name, lines) in sections {
            if name.is_empty() {
                if lines
                    .iter()
                    .all(|(_, l)| strip_comment(l).trim().is_empty())
                {
                    continue;
                }
                let line = lines.first().map_or(0, |(n, _)| *n);
                return Err(DefinitionError {
                    line,
                    what: "a section with no `MSG:` line".into(),
                });
            }
            texts.entry(name).or_insert(lines);
        }
        let mut builder = Builder {
            texts,
            types: Vec::new(),
            ids: HashMap::new(),
        };
        let root = builder.compile(&root_name, 0, 0)?;
        Ok(Schema {
            types: builder.types,
            root,
        })
    }

    /// Checks that `path` (fields separated by `.`, `[]` or `[N]` after an array field)
    /// names a field of the root type; returns the type of what it names.
    pub fn resolve_path(&self, path: &str) -> Result<(ElementType, Arity), String> {
        let mut at = (ElementType::Message(self.root), Arity::Single);
        let mut shown = String::new();
        for segment in path_segments(path)? {
            let id = match at {
                (ElementType::Message(id), Arity::Single) => id,
                (_, Arity::Fixed(_) | Arity::Sequence) => {
                    return Err(format!(
                        "`{shown}` is an array: write `{shown}[]` or `{shown}[N]`"
                    ));
                }
                (ElementType::Primitive(primitive), Arity::Single) => {
                    return Err(format!("`{shown}` is a {primitive:?} and has no fields"));
                }
            };
            let message = self.message_type(id);
            let Some(field) = message.fields.iter().find(|f| &*f.name == segment.name) else {
                let known: Vec<&str> = message.fields.iter().map(|f| &*f.name).collect();
                return Err(format!(
                    "{} has no field `{}` (its fields: {})",
                    message.name,
                    segment.name,
                    known.join(", ")
                ));
            };
            at = (field.element, field.arity);
            if segment.index.is_some() {
                if at.1 == Arity::Single {
                    return Err(format!("`{}` is not an array", segment.name));
                }
                at.1 = Arity::Single;
            }
            if !shown.is_empty() {
                shown.push('.');
            }
            shown.push_str(segment.text);
        }
        Ok(at)
    }
}

/// One `name`, `name[]` or `name[N]` of a field path.
#[derive(Debug)]
pub(crate) struct PathSegment<'a> {
    pub name: &'a str,
    /// `None` without brackets, `Some(None)` for `[]` (every element), `Some(Some(n))` for `[n]`.
    pub index: Option<Option<usize>>,
    /// The segment as written.
    pub text: &'a str,
}

/// Splits `a.b[].c[2]` into its segments.
pub(crate) fn path_segments(path: &str) -> Result<Vec<PathSegment<'_>>, String> {
    if path.is_empty() {
        return Err("empty field path".into());
    }
    let mut out = Vec::new();
    for part in path.split('.') {
        let (name, index) = match part.find('[') {
            Some(open) => {
                let Some(inner) = part[open.saturating_add(1)..].strip_suffix(']') else {
                    return Err(format!("`{part}`: an index is `[]` or `[N]`"));
                };
                let position = if inner.is_empty() {
                    None
                } else {
                    Some(
                        inner
                            .parse::<usize>()
                            .map_err(|_| format!("`{part}`: `{inner}` is not an index"))?,
                    )
                };
                (&part[..open], Some(position))
            }
            None => (part, None),
        };
        if name.is_empty() || !name.bytes().all(|b| b.is_ascii_alphanumeric() || b == b'_') {
            return Err(format!("`{part}` is not a field name"));
        }
        out.push(PathSegment {
            name,
            index,
            text: part,
        });
    }
    Ok(out)
}

/// `pkg/msg/Type` (ROS 2) and `pkg/Type` (ROS 1) name the same type.
pub fn normalize_type_name(name: &str) -> String {
    let name = name.trim();
    match name.split('/').collect::<Vec<_>>().as_slice() {
        [package, "msg", type_name] => format!("{package}/{type_name}"),
        _ => name.to_string(),
    }
}

fn strip_comment(line: &str) -> &str {
    match line.find('#') {
        Some(at) => &line[..at],
        None => line,
    }
}

struct Builder<'a> {
    texts: HashMap<String, Vec<(usize, &'a str)>>,
    types: Vec<MessageType>,
    ids: HashMap<String, TypeId>,
}

impl Builder<'_> {
    /// Compiles `name` and what it uses; `line` is where it was referred to, for errors.
    fn compile(
        &mut self,
        name: &str,
        line: usize,
        depth: usize,
    ) -> Result<TypeId, DefinitionError> {
        if let Some(&id) = self.ids.get(name) {
            return Ok(id);
        }
        if depth > MAX_NESTING {
            return Err(DefinitionError {
                line,
                what: format!("messages nest deeper than {MAX_NESTING} levels at {name} (a type that contains itself?)"),
            });
        }
        let lines = match self.texts.get(name) {
            Some(lines) => lines.clone(),
            None => match builtin_definition(name) {
                Some(text) => text.lines().map(|l| (0, l)).collect(),
                None => {
                    return Err(DefinitionError {
                        line,
                        what: format!("type {name} is used but the definition does not include it"),
                    })
                }
            },
        };
        let package = name.split('/').next().unwrap_or("").to_string();
        let Ok(index) = u32::try_from(self.types.len()) else {
            return Err(DefinitionError {
                line,
                what: format!("more than {} message types", u32::MAX),
            });
        };
        let id = TypeId(index);
        // Reserve the slot first so that a type using itself is caught by the depth limit
        // rather than compiled twice.
        self.types.push(MessageType {
            name: name.to_string(),
            fields: Vec::new(),
            field_names: Arc::from(Vec::new()),
        });
        let mut fields = Vec::new();
        for (number, raw) in lines {
            let Some(field) = self.field(raw, number, &package, depth)? else {
                continue;
            };
            if fields.iter().any(|f: &Field| f.name == field.name) {
                return Err(DefinitionError {
                    line: number,
                    what: format!("{name} declares field `{}` twice", field.name),
                });
            }
            fields.push(field);
        }
        let field_names: Arc<[Arc<str>]> = fields.iter().map(|f| f.name.clone()).collect();
        self.types[id.0 as usize] = MessageType {
            name: name.to_string(),
            fields,
            field_names,
        };
        self.ids.insert(name.to_string(), id);
        Ok(id)
    }

    /// One line of a definition: a field, or `None` for blank lines, comments and constants.
    fn field(
        &mut self,
        raw: &str,
        number: usize,
        package: &str,
        depth: usize,
    ) -> Result<Option<Field>, DefinitionError> {
        let err = |what: String| DefinitionError { line: number, what };
        let line = raw.trim();
        let Some((type_token, rest)) = line.split_once(char::is_whitespace) else {
            if strip_comment(line).trim().is_empty() {
                return Ok(None);
            }
            return Err(err(format!("`{line}` is not `TYPE NAME`")));
        };
        if type_token.starts_with('#') {
            return Ok(None);
        }
        let rest = rest.trim_start();
        // A constant: `TYPE NAME=VALUE` (a string constant's value may hold `#`).
        if let Some(eq) = rest.find('=') {
            let before = &rest[..eq];
            if !before.contains('#')
                && before
                    .trim()
                    .bytes()
                    .all(|b| b.is_ascii_alphanumeric() || b == b'_')
            {
                return Ok(None);
            }
        }
        let rest = strip_comment(rest);
        let mut words = rest.split_whitespace();
        let Some(field_name) = words.next() else {
            return Err(err(format!("`{line}` has a type but no field name")));
        };
        // A third word is a ROS 2 default value, which decoding does not need.
        if !field_name
            .bytes()
            .all(|b| b.is_ascii_alphanumeric() || b == b'_')
        {
            return Err(err(format!("`{field_name}` is not a field name")));
        }
        let (base, arity) = match type_token.find('[') {
            Some(open) => {
                let Some(inner) = type_token[open.saturating_add(1)..].strip_suffix(']') else {
                    return Err(err(format!(
                        "`{type_token}`: an array type is `T[]`, `T[N]` or `T[<=N]`"
                    )));
                };
                let arity = if inner.is_empty() || inner.starts_with("<=") {
                    Arity::Sequence
                } else {
                    Arity::Fixed(inner.parse().map_err(|_| {
                        err(format!("`{type_token}`: `{inner}` is not an array size"))
                    })?)
                };
                (&type_token[..open], arity)
            }
            None => (type_token, Arity::Single),
        };
        // Bounded strings `string<=N`: the bound is not needed to read.
        let base = base.split("<=").next().unwrap_or(base);
        let element = match Primitive::from_name(base) {
            Some(primitive) => ElementType::Primitive(primitive),
            None if base == "wstring" => {
                return Err(err("`wstring` fields are not supported".into()));
            }
            None => {
                let full = if base == "Header" {
                    "std_msgs/Header".to_string()
                } else if base.contains('/') {
                    normalize_type_name(base)
                } else {
                    format!("{package}/{base}")
                };
                ElementType::Message(self.compile(&full, number, depth.saturating_add(1))?)
            }
        };
        Ok(Some(Field {
            name: Arc::from(field_name),
            element,
            arity,
        }))
    }
}

/// Types so basic that some writers leave them out of a schema's dependencies.
fn builtin_definition(name: &str) -> Option<&'static str> {
    match name {
        "builtin_interfaces/Time" | "builtin_interfaces/Duration" => {
            Some("int32 sec\nuint32 nanosec")
        }
        _ => None,
    }
}

#[cfg(test)]
#[allow(clippy::arithmetic_side_effects, clippy::cast_possible_truncation)] // tests, not readers
mod tests {
    use super::*;

    const TF_ROS1: &str = "geometry_msgs/TransformStamped[] transforms\n\
================================================================================\n\
MSG: geometry_msgs/TransformStamped\n\
# comment\n\
Header header\n\
string child_frame_id # the frame\n\
Transform transform\n\
================================================================================\n\
MSG: std_msgs/Header\n\
uint32 seq\n\
time stamp\n\
string frame_id\n\
================================================================================\n\
MSG: geometry_msgs/Transform\n\
Vector3 translation\n\
Quaternion rotation\n\
================================================================================\n\
MSG: geometry_msgs/Vector3\n\
float64 x\nfloat64 y\nfloat64 z\n\
================================================================================\n\
MSG: geometry_msgs/Quaternion\n\
float64 x\nfloat64 y\nfloat64 z\nfloat64 w\n";

    #[test]
    fn parses_a_ros1_tf_message_with_relative_types_and_header() {
        let schema = Schema::parse("tf2_msgs/TFMessage", TF_ROS1).unwrap();
        assert_eq!(schema.root_type().name, "tf2_msgs/TFMessage");
        assert_eq!(
            schema
                .resolve_path("transforms[].transform.rotation.w")
                .unwrap(),
            (ElementType::Primitive(Primitive::Float64), Arity::Single)
        );
        assert_eq!(
            schema.resolve_path("transforms[0].header.stamp").unwrap(),
            (ElementType::Primitive(Primitive::Time), Arity::Single)
        );
        let err = schema
            .resolve_path("transforms[].transform.rotaton")
            .unwrap_err();
        assert!(
            err.contains("geometry_msgs/Transform has no field `rotaton`"),
            "{err}"
        );
        let err = schema.resolve_path("transforms.header").unwrap_err();
        assert!(err.contains("is an array"), "{err}");
    }

    #[test]
    fn skips_constants_and_ros2_defaults_and_reads_array_kinds() {
        let text = "int32 FOO=1\nstring S = a#b\nfloat64[3] fixed\nint32[<=4] bounded\nstring<=8 name \"x\"\nbuiltin_interfaces/Time t\n";
        let schema = Schema::parse("pkg/msg/Thing", text).unwrap();
        let root = schema.root_type();
        assert_eq!(root.name, "pkg/Thing");
        let names: Vec<&str> = root.fields.iter().map(|f| &*f.name).collect();
        assert_eq!(names, ["fixed", "bounded", "name", "t"]);
        assert_eq!(root.fields[0].arity, Arity::Fixed(3));
        assert_eq!(root.fields[1].arity, Arity::Sequence);
        assert!(schema.resolve_path("t.nanosec").is_ok());
    }

    #[test]
    fn a_missing_dependency_or_a_type_containing_itself_is_an_error_with_its_line() {
        let err = Schema::parse("a/B", "float64 x\na/C c\n").unwrap_err();
        assert_eq!(err.line, 2);
        assert!(err.what.contains("a/C is used"), "{}", err.what);
        let err = Schema::parse("a/B", "B[2] again\n").unwrap_err();
        assert!(err.what.contains("nest deeper"), "{}", err.what);
        let err = Schema::parse("a/B", "float64\n").unwrap_err();
        assert_eq!(err.line, 1);
        let err = Schema::parse("a/B", "float64[x] y\n").unwrap_err();
        assert!(err.what.contains("not an array size"), "{}", err.what);
    }
}
