//! The message decoder, driven by a [`Schema`]: the ROS 1 serialization (little-endian, no
//! padding, `u32` lengths) and CDR as ROS 2 writes it (a 4-byte encapsulation header, then
//! each primitive aligned to its size relative to the end of that header, strings with their
//! terminating NUL counted in the length).
//!
//! Every length prefix is checked against the bytes left before anything is allocated, so a
//! corrupt message is an error naming the field and byte offset, never a huge allocation.

use crate::definition::{Arity, ElementType, Primitive, Schema, TypeId, MAX_NESTING};
use crate::value::{Message, Value};

/// How the bytes of a message are laid out.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Encoding {
    Ros1,
    Cdr,
}

/// Where and why a message did not decode.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("field `{field}`, byte {offset} of the message: {what}")]
pub struct DecodeError {
    pub field: String,
    pub offset: usize,
    pub what: String,
}

/// Decodes one message of the schema's root type.
pub fn decode(schema: &Schema, encoding: Encoding, data: &[u8]) -> Result<Value, DecodeError> {
    let mut cursor = Cursor {
        data,
        pos: 0,
        base: 0,
        little: true,
        cdr: encoding == Encoding::Cdr,
        path: Vec::new(),
    };
    if cursor.cdr {
        let header = cursor.take(4)?;
        cursor.little = match header[1] {
            0 => false,
            1 => true,
            kind => {
                return Err(cursor.error(format!(
                "CDR encapsulation kind {kind} is not plain CDR (0 big-endian or 1 little-endian)"
            )))
            }
        };
        cursor.base = 4;
    }
    cursor.message(schema, schema.root, 0)
}

struct Cursor<'a> {
    data: &'a [u8],
    pos: usize,
    /// Where CDR alignment counts from.
    base: usize,
    little: bool,
    cdr: bool,
    /// The field being read, for errors.
    path: Vec<&'a str>,
}

impl<'a> Cursor<'a> {
    fn error(&self, what: String) -> DecodeError {
        let field = if self.path.is_empty() {
            "(message)".to_string()
        } else {
            self.path.join(".")
        };
        DecodeError {
            field,
            offset: self.pos,
            what,
        }
    }

    fn remaining(&self) -> usize {
        // `pos` only moves by `take`, which stays within the data.
        self.data.len().saturating_sub(self.pos)
    }

    fn take(&mut self, n: usize) -> Result<&'a [u8], DecodeError> {
        if n > self.remaining() {
            return Err(self.error(format!(
                "needs {n} bytes, the message has {} left",
                self.remaining()
            )));
        }
        let end = self.pos.saturating_add(n);
        let out = &self.data[self.pos..end];
        self.pos = end;
        Ok(out)
    }

    fn align(&mut self, n: usize) -> Result<(), DecodeError> {
        if self.cdr && n > 1 {
            // `n` is a primitive's size (2, 4 or 8), `base` at most `pos`.
            let offset = self
                .pos
                .saturating_sub(self.base)
                .checked_rem(n)
                .unwrap_or(0);
            if offset != 0 {
                self.take(n.saturating_sub(offset))?;
            }
        }
        Ok(())
    }

    fn fixed<const N: usize>(&mut self) -> Result<[u8; N], DecodeError> {
        self.align(N)?;
        let bytes = self.take(N)?;
        let mut out = [0u8; N];
        out.copy_from_slice(bytes);
        if !self.little {
            out.reverse();
        }
        Ok(out)
    }

    fn u32(&mut self) -> Result<u32, DecodeError> {
        Ok(u32::from_le_bytes(self.fixed::<4>()?))
    }

    /// A length prefix, checked against what is left (each element takes `min_size` bytes).
    fn length(&mut self, min_size: usize) -> Result<usize, DecodeError> {
        let n = self.u32()? as usize;
        if n.saturating_mul(min_size.max(1)) > self.remaining() {
            return Err(self.error(format!(
                "length {n} is more than the {} bytes left",
                self.remaining()
            )));
        }
        Ok(n)
    }

    fn message(
        &mut self,
        schema: &'a Schema,
        id: TypeId,
        depth: usize,
    ) -> Result<Value, DecodeError> {
        if depth > MAX_NESTING {
            return Err(self.error(format!("messages nest deeper than {MAX_NESTING} levels")));
        }
        let message_type = schema.message_type(id);
        let mut values = Vec::with_capacity(message_type.fields.len());
        for field in &message_type.fields {
            self.path.push(&field.name);
            let value = match field.arity {
                Arity::Single => self.element(schema, field.element, depth)?,
                Arity::Fixed(n) => self.array(schema, field.element, n as usize, depth)?,
                Arity::Sequence => {
                    let n = self.length(min_size(field.element))?;
                    self.array(schema, field.element, n, depth)?
                }
            };
            self.path.pop();
            values.push(value);
        }
        Ok(Value::Message(Message {
            names: message_type.field_names.clone(),
            values,
        }))
    }

    fn array(
        &mut self,
        schema: &'a Schema,
        element: ElementType,
        n: usize,
        depth: usize,
    ) -> Result<Value, DecodeError> {
        if n.saturating_mul(min_size(element).max(1)) > self.remaining() {
            return Err(self.error(format!(
                "{n} elements do not fit in the {} bytes left",
                self.remaining()
            )));
        }
        if let ElementType::Primitive(Primitive::UInt8 | Primitive::Int8) = element {
            return Ok(Value::Bytes(self.take(n)?.to_vec()));
        }
        let mut items = Vec::with_capacity(n);
        for _ in 0..n {
            items.push(self.element(schema, element, depth)?);
        }
        Ok(Value::Array(items))
    }

    fn element(
        &mut self,
        schema: &'a Schema,
        element: ElementType,
        depth: usize,
    ) -> Result<Value, DecodeError> {
        let primitive = match element {
            ElementType::Message(id) => return self.message(schema, id, depth.saturating_add(1)),
            ElementType::Primitive(primitive) => primitive,
        };
        Ok(match primitive {
            Primitive::Bool => Value::Bool(self.take(1)?[0] != 0),
            Primitive::Int8 => Value::Int(i8::from_le_bytes(self.fixed::<1>()?) as i64),
            Primitive::UInt8 => Value::UInt(self.take(1)?[0] as u64),
            Primitive::Int16 => Value::Int(i16::from_le_bytes(self.fixed::<2>()?) as i64),
            Primitive::UInt16 => Value::UInt(u16::from_le_bytes(self.fixed::<2>()?) as u64),
            Primitive::Int32 => Value::Int(i32::from_le_bytes(self.fixed::<4>()?) as i64),
            Primitive::UInt32 => Value::UInt(self.u32()? as u64),
            Primitive::Int64 => Value::Int(i64::from_le_bytes(self.fixed::<8>()?)),
            Primitive::UInt64 => Value::UInt(u64::from_le_bytes(self.fixed::<8>()?)),
            Primitive::Float32 => Value::Float(f32::from_le_bytes(self.fixed::<4>()?) as f64),
            Primitive::Float64 => Value::Float(f64::from_le_bytes(self.fixed::<8>()?)),
            Primitive::String => {
                let n = self.length(1)?;
                let bytes = self.take(n)?;
                // CDR counts the terminating NUL; ROS 1 has none.
                let bytes = if self.cdr {
                    bytes.strip_suffix(&[0]).unwrap_or(bytes)
                } else {
                    bytes
                };
                match std::str::from_utf8(bytes) {
                    Ok(text) => Value::String(text.to_string()),
                    Err(_) => return Err(self.error("string is not UTF-8".into())),
                }
            }
            Primitive::Time => {
                let sec = self.u32()? as i64;
                let nsec = self.u32()? as i64;
                // Seconds of 32 bits times 10^9 fit i64.
                Value::Time(sec.saturating_mul(1_000_000_000).saturating_add(nsec))
            }
            Primitive::Duration => {
                let sec = i32::from_le_bytes(self.fixed::<4>()?) as i64;
                let nsec = i32::from_le_bytes(self.fixed::<4>()?) as i64;
                Value::Duration(sec.saturating_mul(1_000_000_000).saturating_add(nsec))
            }
        })
    }
}

fn min_size(element: ElementType) -> usize {
    match element {
        ElementType::Primitive(primitive) => primitive.min_size(),
        // An empty message takes no bytes in ROS 1; count 1 so that a length prefix is
        // still bounded by the bytes left.
        ElementType::Message(_) => 1,
    }
}

#[cfg(test)]
#[allow(clippy::arithmetic_side_effects, clippy::cast_possible_truncation)] // tests, not readers
mod tests {
    use super::*;

    fn schema() -> Schema {
        Schema::parse(
            "pkg/Obj",
            "string name\nfloat64[2] xy\nuint8[] raw\nint16 small\nbuiltin_interfaces/Time t\n",
        )
        .unwrap()
    }

    #[test]
    fn decodes_ros1_without_padding() {
        let mut data = Vec::new();
        data.extend(3u32.to_le_bytes());
        data.extend(b"cub");
        data.extend(1.5f64.to_le_bytes());
        data.extend((-2.0f64).to_le_bytes());
        data.extend(2u32.to_le_bytes());
        data.extend([7, 8]);
        data.extend((-3i16).to_le_bytes());
        data.extend(5i32.to_le_bytes());
        data.extend(6u32.to_le_bytes());
        let value = decode(&schema(), Encoding::Ros1, &data).unwrap();
        assert_eq!(value.lookup_one("name").unwrap().as_str(), Some("cub"));
        assert_eq!(
            value.lookup_one("xy").unwrap(),
            &Value::Array(vec![Value::Float(1.5), Value::Float(-2.0)])
        );
        assert_eq!(value.lookup_one("raw").unwrap(), &Value::Bytes(vec![7, 8]));
        assert_eq!(value.lookup_one("small").unwrap(), &Value::Int(-3));
        assert_eq!(
            value.lookup_one("t").unwrap().as_nanos(),
            Some(5_000_000_006)
        );
    }

    #[test]
    fn decodes_cdr_with_alignment_and_nul_terminated_strings() {
        let mut data = vec![0, 1, 0, 0];
        data.extend(4u32.to_le_bytes());
        data.extend(b"cub\0");
        // offset 8 from the header's end: already aligned for f64
        data.extend(1.5f64.to_le_bytes());
        data.extend((-2.0f64).to_le_bytes());
        data.extend(1u32.to_le_bytes());
        data.push(9);
        data.push(0); // padding to 2
        data.extend((-3i16).to_le_bytes());
        data.extend(5i32.to_le_bytes());
        data.extend(6u32.to_le_bytes());
        let value = decode(&schema(), Encoding::Cdr, &data).unwrap();
        assert_eq!(value.lookup_one("name").unwrap().as_str(), Some("cub"));
        assert_eq!(value.lookup_one("raw").unwrap(), &Value::Bytes(vec![9]));
        assert_eq!(value.lookup_one("small").unwrap(), &Value::Int(-3));
        assert_eq!(
            value.lookup_one("t").unwrap().as_nanos(),
            Some(5_000_000_006)
        );
    }

    #[test]
    fn a_length_beyond_the_message_is_an_error_naming_the_field() {
        let mut data = Vec::new();
        data.extend(1000u32.to_le_bytes());
        data.extend(b"cub");
        let err = decode(&schema(), Encoding::Ros1, &data).unwrap_err();
        assert_eq!(err.field, "name");
        assert_eq!(err.offset, 4);
        assert!(err.what.contains("length 1000"), "{}", err.what);
        let mut data = Vec::new();
        data.extend(0u32.to_le_bytes());
        data.extend(1.5f64.to_le_bytes());
        let err = decode(&schema(), Encoding::Ros1, &data).unwrap_err();
        assert_eq!(err.field, "xy");
        let err = decode(&schema(), Encoding::Cdr, &[0, 2, 0, 0]).unwrap_err();
        assert!(err.what.contains("encapsulation kind 2"), "{}", err.what);
    }
}
