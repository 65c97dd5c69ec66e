//! Decoded messages: a dynamic tree of values, looked up by field path.

use std::sync::Arc;

use crate::definition::path_segments;

/// One decoded value. Integers keep their sign class, floats are widened to `f64`, ROS 1
/// `time` and `duration` are nanoseconds, and arrays of octets stay bytes.
#[derive(Debug, Clone, PartialEq)]
pub enum Value {
    Bool(bool),
    Int(i64),
    UInt(u64),
    Float(f64),
    String(String),
    /// ROS 1 `time`, in nanoseconds since the epoch.
    Time(i64),
    /// ROS 1 `duration`, in nanoseconds.
    Duration(i64),
    /// An array or sequence of `uint8`, `int8`, `byte` or `char`.
    Bytes(Vec<u8>),
    Array(Vec<Value>),
    Message(Message),
}

/// A decoded message: its fields in definition order.
#[derive(Debug, Clone, PartialEq)]
pub struct Message {
    /// Field names, shared with every other value of the same type.
    pub names: Arc<[Arc<str>]>,
    pub values: Vec<Value>,
}

impl Message {
    pub fn field(&self, name: &str) -> Option<&Value> {
        let at = self.names.iter().position(|n| &**n == name)?;
        self.values.get(at)
    }
}

impl Value {
    /// The field `name` of a message value.
    pub fn field(&self, name: &str) -> Option<&Value> {
        match self {
            Value::Message(message) => message.field(name),
            _ => None,
        }
    }

    pub fn as_f64(&self) -> Option<f64> {
        match *self {
            Value::Float(x) => Some(x),
            Value::Int(x) => Some(x as f64),
            Value::UInt(x) => Some(x as f64),
            _ => None,
        }
    }

    pub fn as_str(&self) -> Option<&str> {
        match self {
            Value::String(s) => Some(s),
            _ => None,
        }
    }

    pub fn as_bool(&self) -> Option<bool> {
        match *self {
            Value::Bool(b) => Some(b),
            Value::Int(x) => Some(x != 0),
            Value::UInt(x) => Some(x != 0),
            _ => None,
        }
    }

    /// A time stamp in nanoseconds: ROS 1 `time`, or a message with `sec` and `nanosec`
    /// (ROS 2 `builtin_interfaces/Time`) or `secs` and `nsecs`.
    pub fn as_nanos(&self) -> Option<i64> {
        match self {
            Value::Time(t) | Value::Duration(t) => Some(*t),
            Value::Message(m) => {
                // A float to integer cast saturates (NaN gives 0): a stamp out of range
                // becomes the nearest `i64`, never a wrapped one.
                #[allow(clippy::cast_possible_truncation)]
                let (sec, nsec) = (
                    m.field("sec").or_else(|| m.field("secs"))?.as_f64()? as i64,
                    m.field("nanosec").or_else(|| m.field("nsecs"))?.as_f64()? as i64,
                );
                Some(sec.saturating_mul(1_000_000_000).saturating_add(nsec))
            }
            _ => None,
        }
    }

    /// The elements of an array value (bytes are not elements).
    pub fn as_array(&self) -> Option<&[Value]> {
        match self {
            Value::Array(items) => Some(items),
            _ => None,
        }
    }

    /// Every value `path` reaches: `a.b` a field of a field, `a[2]` one element, `a[]`
    /// each element. An error says which segment is missing or of the wrong kind.
    pub fn lookup(&self, path: &str) -> Result<Vec<&Value>, String> {
        let segments = path_segments(path)?;
        let mut current = vec![self];
        let mut shown = String::new();
        for segment in segments {
            let mut next = Vec::with_capacity(current.len());
            for value in current {
                let Some(field) = value.field(segment.name) else {
                    return Err(if shown.is_empty() {
                        format!("no field `{}`", segment.name)
                    } else {
                        format!("`{shown}` has no field `{}`", segment.name)
                    });
                };
                match segment.index {
                    None => next.push(field),
                    Some(position) => {
                        let Some(items) = field.as_array() else {
                            return Err(format!("`{}` is not an array of messages", segment.name));
                        };
                        match position {
                            None => next.extend(items.iter()),
                            Some(at) => match items.get(at) {
                                Some(item) => next.push(item),
                                None => {
                                    return Err(format!(
                                        "`{}` has {} elements, no [{at}]",
                                        segment.name,
                                        items.len()
                                    ))
                                }
                            },
                        }
                    }
                }
            }
            current = next;
            if !shown.is_empty() {
                shown.push('.');
            }
            shown.push_str(segment.text);
        }
        Ok(current)
    }

    /// The one value `path` reaches (an error if it reaches none or several).
    pub fn lookup_one(&self, path: &str) -> Result<&Value, String> {
        let found = self.lookup(path)?;
        match found.as_slice() {
            [one] => Ok(one),
            _ => Err(format!("`{path}` gives {} values, not one", found.len())),
        }
    }
}
