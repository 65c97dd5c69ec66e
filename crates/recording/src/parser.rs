//! A hand-written parser for frame lines. Frames are most of a recording and parsing them
//! is the cost of reading one, so this parser works on the line's bytes, allocates
//! nothing for a well-formed frame (strings are borrowed, entity names looked up by the
//! header's order first), parses short decimals with an exact fast path, and builds a
//! field path only when it reports an error.

// A reader of untrusted input (issue 23): no arithmetic that can wrap or panic, no
// cast that can truncate; each such operation is checked, saturating or proved in range.
#![deny(clippy::arithmetic_side_effects, clippy::cast_possible_truncation)]

use std::borrow::Cow;

use rustc_hash::FxHashMap;

use crate::check;
use crate::error::ErrorKind;
use crate::model::{
    Contact, EntityId, EntityKind, EntityState, Frame, Header, Pose, Quaternion, Vec3,
};

/// An error inside one line: 0-based byte column, width, field path, kind.
#[derive(Debug)]
pub(crate) struct LineError {
    pub column: usize,
    pub width: usize,
    pub field: String,
    pub kind: ErrorKind,
}

/// Where in a frame the parser is, to name the field of an error. Cheap to copy; turned
/// into a path only when an error is reported.
#[derive(Debug, Clone, Copy)]
enum Field<'a> {
    Root,
    Key(&'a [u8]),
    Time,
    Entities,
    Entity(&'a [u8]),
    Member(&'a [u8], &'static str),
    Element(&'a [u8], &'static str, usize),
    Contacts,
    Contact(usize),
    ContactEnd(usize, usize),
}

impl Field<'_> {
    fn path(self) -> String {
        let s = |b: &[u8]| String::from_utf8_lossy(b).into_owned();
        match self {
            Field::Root => String::new(),
            Field::Key(k) => s(k),
            Field::Time => "t".into(),
            Field::Entities => "entities".into(),
            Field::Entity(n) => format!("entities.{}", s(n)),
            Field::Member(n, m) => format!("entities.{}.{m}", s(n)),
            Field::Element(n, m, k) => format!("entities.{}.{m}[{k}]", s(n)),
            Field::Contacts => "contacts".into(),
            Field::Contact(i) => format!("contacts[{i}]"),
            Field::ContactEnd(i, j) => format!("contacts[{i}][{j}]"),
        }
    }
}

/// The fields of an entity state.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Member {
    Pos,
    Rot,
    Vel,
    Grip,
    Holding,
}

impl Member {
    const ALL: [Member; 5] = [
        Member::Pos,
        Member::Rot,
        Member::Vel,
        Member::Grip,
        Member::Holding,
    ];

    fn name(self) -> &'static str {
        match self {
            Member::Pos => "pos",
            Member::Rot => "rot",
            Member::Vel => "vel",
            Member::Grip => "grip",
            Member::Holding => "holding",
        }
    }
}

/// Exact powers of ten for the fast paths.
const POW10_F32: [f32; 11] = [1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10];
const POW10_F64: [f64; 23] = [
    1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10, 1e11, 1e12, 1e13, 1e14, 1e15, 1e16,
    1e17, 1e18, 1e19, 1e20, 1e21, 1e22,
];

/// The float types numbers are read as, with the fast path: a decimal `m / 10^k` whose
/// mantissa and power of ten are both exact in the type is correctly rounded by one
/// division.
trait ExactDecimal: Copy + 'static + std::str::FromStr {
    /// The largest mantissa the type holds exactly (2^24, 2^53).
    const MAX_EXACT: u64;
    /// The powers of ten the type holds exactly.
    const POW10: &'static [Self];
    /// `m / p`, negated if `negative`, with `m` converted to the type (exact up to
    /// `MAX_EXACT`).
    fn quotient(negative: bool, m: u64, p: Self) -> Self;
    fn is_finite(self) -> bool;

    /// `m / 10^fraction`, negated if `negative`, where the fast path applies.
    #[inline]
    fn exact(negative: bool, m: u64, fraction: usize) -> Option<Self> {
        if m > Self::MAX_EXACT {
            return None;
        }
        Some(Self::quotient(negative, m, *Self::POW10.get(fraction)?))
    }
}

/// The two impls differ only in their type, exactness bound and powers of ten.
macro_rules! exact_decimal {
    ($float:ty, $max_exact:expr, $pow10:expr) => {
        impl ExactDecimal for $float {
            const MAX_EXACT: u64 = $max_exact;
            const POW10: &'static [$float] = &$pow10;
            fn quotient(negative: bool, m: u64, p: $float) -> $float {
                let v = m as $float / p;
                if negative {
                    -v
                } else {
                    v
                }
            }
            fn is_finite(self) -> bool {
                <$float>::is_finite(self)
            }
        }
    };
}

exact_decimal!(f32, 1 << 24, POW10_F32);
exact_decimal!(f64, 1 << 53, POW10_F64);

/// Reads the ASCII digits of `b` from `j` on into `mantissa` (wrapping: callers take
/// the fast path only for at most 19 digits, counted in `digits`); returns the index
/// after them.
#[inline]
fn scan_digits(b: &[u8], mut j: usize, mantissa: &mut u64, digits: &mut usize) -> usize {
    while let Some(&c) = b.get(j) {
        if !c.is_ascii_digit() {
            break;
        }
        *mantissa = mantissa
            .wrapping_mul(10)
            .wrapping_add(u64::from(c.saturating_sub(b'0')));
        *digits = digits.saturating_add(1);
        j = j.saturating_add(1);
    }
    j
}

/// A scanned JSON number: its text range, and for plain decimals (no exponent, at most 19
/// digits) the digits as an integer and the number of digits after the point.
struct Number {
    start: usize,
    end: usize,
    negative: bool,
    mantissa: u64,
    fraction_digits: usize,
    plain: bool,
}

struct Cursor<'a> {
    b: &'a [u8],
    i: usize,
}

fn error(column: usize, width: usize, field: Field<'_>, kind: ErrorKind) -> LineError {
    LineError {
        column,
        width,
        field: field.path(),
        kind,
    }
}

impl<'a> Cursor<'a> {
    #[inline]
    fn ws(&mut self) {
        while let Some(&c) = self.b.get(self.i) {
            if c == b' ' || c == b'\t' {
                self.i = self.i.saturating_add(1);
            } else {
                break;
            }
        }
    }

    #[inline]
    fn peek(&self) -> Option<u8> {
        self.b.get(self.i).copied()
    }

    fn truncated(&self, field: Field<'_>) -> LineError {
        error(self.b.len(), 0, field, ErrorKind::Truncated)
    }

    /// The byte width of the token at the cursor, for underlining.
    fn token_width(&self) -> usize {
        let rest = &self.b[self.i.min(self.b.len())..];
        match rest.first() {
            None => 0,
            Some(b'"') => rest[1..]
                .iter()
                .position(|&c| c == b'"')
                .map_or(rest.len(), |p| p.saturating_add(2)),
            Some(_) => rest
                .iter()
                .position(|c| b",:]} \t".contains(c))
                .unwrap_or(rest.len())
                .max(1),
        }
    }

    /// The usual keys of an entity state, recognised without a string scan.
    #[inline(always)]
    fn known_member(&mut self) -> Option<Member> {
        let (member, len) = match &self.b[self.i..] {
            [b'"', b'p', b'o', b's', b'"', ..] => (Member::Pos, 5),
            [b'"', b'r', b'o', b't', b'"', ..] => (Member::Rot, 5),
            [b'"', b'v', b'e', b'l', b'"', ..] => (Member::Vel, 5),
            [b'"', b'g', b'r', b'i', b'p', b'"', ..] => (Member::Grip, 6),
            _ => return None,
        };
        self.i = self.i.saturating_add(len);
        Some(member)
    }

    fn unexpected(&self, field: Field<'_>, expected: &str) -> LineError {
        match self.peek() {
            None => self.truncated(field),
            Some(c) => error(
                self.i,
                self.token_width(),
                field,
                ErrorKind::Syntax(format!(
                    "expected {expected}, found {}",
                    describe_byte(c, &self.b[self.i..])
                )),
            ),
        }
    }

    #[inline]
    fn expect(&mut self, byte: u8, field: Field<'_>, expected: &str) -> Result<(), LineError> {
        if self.peek() == Some(byte) {
            self.i = self.i.saturating_add(1);
            Ok(())
        } else {
            Err(self.unexpected(field, expected))
        }
    }

    /// An object or array opened by `open` (else an error expecting `expected`): whether
    /// it is empty, its `close` consumed too (white space after `open` skipped).
    #[inline]
    fn open(
        &mut self,
        open: u8,
        close: u8,
        field: Field<'_>,
        expected: &str,
    ) -> Result<bool, LineError> {
        self.expect(open, field, expected)?;
        self.ws();
        let empty = self.peek() == Some(close);
        if empty {
            self.i = self.i.saturating_add(1);
        }
        Ok(empty)
    }

    /// After a member or element: `,` (returns true) or the closing byte (returns false).
    #[inline]
    fn comma_or(&mut self, close: u8, field: Field<'_>) -> Result<bool, LineError> {
        self.ws();
        match self.peek() {
            Some(b',') => {
                self.i = self.i.saturating_add(1);
                self.ws();
                Ok(true)
            }
            Some(c) if c == close => {
                self.i = self.i.saturating_add(1);
                Ok(false)
            }
            _ => Err(self.unexpected(field, &format!("`,` or `{}`", close as char))),
        }
    }

    /// A JSON string, borrowed from the line unless it has escapes.
    fn string(&mut self, field: Field<'_>) -> Result<Cow<'a, [u8]>, LineError> {
        if self.peek() != Some(b'"') {
            return Err(self.unexpected(field, "a string"));
        }
        let open = self.i;
        let start = self.i.saturating_add(1);
        let mut j = start;
        let b = self.b;
        while j < b.len() {
            match b[j] {
                b'"' => {
                    self.i = j.saturating_add(1);
                    return Ok(Cow::Borrowed(&b[start..j]));
                }
                b'\\' => return self.escaped_string(open, field),
                c if c < 0x20 => {
                    return Err(error(
                        j,
                        1,
                        field,
                        ErrorKind::Syntax("control character inside a string".into()),
                    ))
                }
                _ => j = j.saturating_add(1),
            }
        }
        Err(self.truncated(field))
    }

    fn escaped_string(
        &mut self,
        open: usize,
        field: Field<'_>,
    ) -> Result<Cow<'a, [u8]>, LineError> {
        let b = self.b;
        let mut j = open.saturating_add(1);
        while j < b.len() {
            match b[j] {
                b'\\' => j = j.saturating_add(2),
                b'"' => {
                    let text = &b[open..=j];
                    self.i = j.saturating_add(1);
                    return serde_json::from_slice::<String>(text)
                        .map(|s| Cow::Owned(s.into_bytes()))
                        .map_err(|e| {
                            error(
                                open,
                                text.len(),
                                field,
                                ErrorKind::Syntax(format!("bad string: {}", strip_position(&e))),
                            )
                        });
                }
                _ => j = j.saturating_add(1),
            }
        }
        Err(self.truncated(field))
    }

    /// Scans a JSON number; NaN and infinities are reported as not finite.
    fn scan_number(&mut self, field: Field<'_>) -> Result<Number, LineError> {
        let b = self.b;
        let start = self.i;
        let mut j = start;
        let negative = b.get(j) == Some(&b'-');
        if negative {
            j = j.saturating_add(1);
        }
        match b.get(j) {
            Some(c) if c.is_ascii_digit() => {}
            Some(c) if c.is_ascii_alphabetic() => {
                let end = b[j..]
                    .iter()
                    .position(|c| !c.is_ascii_alphabetic())
                    .map_or(b.len(), |k| j.saturating_add(k));
                let word = String::from_utf8_lossy(&b[start..end]).into_owned();
                let lower = word.trim_start_matches('-').to_ascii_lowercase();
                let kind = if matches!(lower.as_str(), "nan" | "inf" | "infinity") {
                    ErrorKind::NotFinite(word)
                } else {
                    ErrorKind::Syntax(format!("expected a number, found `{word}`"))
                };
                return Err(error(start, end.saturating_sub(start), field, kind));
            }
            None if j >= b.len() => return Err(self.truncated(field)),
            _ => return Err(self.unexpected(field, "a number")),
        }
        let mut mantissa: u64 = 0;
        let mut digits = 0usize;
        let int_start = j;
        j = scan_digits(b, j, &mut mantissa, &mut digits);
        if b[int_start] == b'0' && j.saturating_sub(int_start) > 1 {
            return Err(error(
                start,
                j.saturating_sub(start),
                field,
                ErrorKind::Syntax("a number with a leading zero".into()),
            ));
        }
        let mut fraction_digits = 0usize;
        if b.get(j) == Some(&b'.') {
            j = j.saturating_add(1);
            let frac_start = j;
            j = scan_digits(b, j, &mut mantissa, &mut digits);
            fraction_digits = j.saturating_sub(frac_start);
            if fraction_digits == 0 {
                return Err(self.bad_number(start, j, field));
            }
        }
        let mut plain = digits <= 19;
        if matches!(b.get(j), Some(b'e' | b'E')) {
            plain = false;
            j = j.saturating_add(1);
            if matches!(b.get(j), Some(b'+' | b'-')) {
                j = j.saturating_add(1);
            }
            let exp_start = j;
            while b.get(j).is_some_and(u8::is_ascii_digit) {
                j = j.saturating_add(1);
            }
            if j == exp_start {
                return Err(self.bad_number(start, j, field));
            }
        }
        self.i = j;
        Ok(Number {
            start,
            end: j,
            negative,
            mantissa,
            fraction_digits,
            plain,
        })
    }

    fn bad_number(&self, start: usize, end: usize, field: Field<'_>) -> LineError {
        if end >= self.b.len() {
            return self.truncated(field);
        }
        error(
            start,
            end.saturating_sub(start),
            field,
            ErrorKind::Syntax(format!(
                "malformed number `{}`",
                String::from_utf8_lossy(&self.b[start..end])
            )),
        )
    }

    fn not_finite(&self, n: &Number, field: Field<'_>) -> LineError {
        error(
            n.start,
            n.end.saturating_sub(n.start),
            field,
            ErrorKind::NotFinite(String::from_utf8_lossy(&self.b[n.start..n.end]).into_owned()),
        )
    }

    /// The fast path for the numbers recordings are made of: an optional `-`, at most 19
    /// digits with an optional fraction, no exponent, no leading zero, followed by a byte
    /// that is not part of a number. Returns the digits as an integer, the number of
    /// fraction digits and the end; `None` sends the number to the general scanner.
    #[inline(always)]
    fn plain_decimal(&self) -> Option<(bool, u64, usize, usize)> {
        let b = self.b;
        let mut j = self.i;
        let negative = b.get(j) == Some(&b'-');
        j = j.saturating_add(usize::from(negative));
        let int_start = j;
        let (mut m, mut digits) = (0u64, 0usize);
        j = scan_digits(b, j, &mut m, &mut digits);
        let int_digits = j.saturating_sub(int_start);
        if int_digits == 0 || (int_digits > 1 && b[int_start] == b'0') {
            return None;
        }
        let mut fraction = 0;
        if b.get(j) == Some(&b'.') {
            j = j.saturating_add(1);
            let frac_start = j;
            j = scan_digits(b, j, &mut m, &mut digits);
            fraction = j.saturating_sub(frac_start);
            if fraction == 0 {
                return None;
            }
        }
        if digits > 19 || matches!(b.get(j), Some(b'e' | b'E')) {
            return None;
        }
        Some((negative, m, fraction, j))
    }

    /// A number as `f32`, correctly rounded.
    #[inline]
    fn f32(&mut self, field: Field<'_>) -> Result<f32, LineError> {
        if let Some((negative, m, fraction, end)) = self.plain_decimal() {
            if let Some(v) = f32::exact(negative, m, fraction) {
                self.i = end;
                return Ok(v);
            }
        }
        Ok(self.float::<f32>(field)?.0)
    }

    /// A number as `f64`, correctly rounded; also its column and width.
    fn f64(&mut self, field: Field<'_>) -> Result<(f64, usize, usize), LineError> {
        let (v, n) = self.float::<f64>(field)?;
        Ok((v, n.start, n.end.saturating_sub(n.start)))
    }

    /// A number as `T`, correctly rounded, and where it stands; a number that is not
    /// finite in `T` is an error.
    #[inline]
    fn float<T: ExactDecimal>(&mut self, field: Field<'_>) -> Result<(T, Number), LineError> {
        let n = self.scan_number(field)?;
        let exact = if n.plain {
            T::exact(n.negative, n.mantissa, n.fraction_digits)
        } else {
            None
        };
        let v = match exact {
            Some(v) => v,
            None => self.slow_parse::<T>(&n, field)?,
        };
        if v.is_finite() {
            Ok((v, n))
        } else {
            Err(self.not_finite(&n, field))
        }
    }

    fn slow_parse<T: std::str::FromStr>(
        &self,
        n: &Number,
        field: Field<'_>,
    ) -> Result<T, LineError> {
        std::str::from_utf8(&self.b[n.start..n.end])
            .ok()
            .and_then(|s| s.parse::<T>().ok())
            .ok_or_else(|| self.bad_number(n.start, n.end, field))
    }

    /// `[a, b, c, ...]` of exactly `N` numbers.
    fn array<const N: usize>(
        &mut self,
        name: &[u8],
        member: &'static str,
    ) -> Result<[f32; N], LineError> {
        self.expect(b'[', Field::Member(name, member), "`[`")?;
        self.ws();
        let mut out = [0.0f32; N];
        for (k, slot) in out.iter_mut().enumerate() {
            if self.peek() == Some(b']') {
                return Err(error(
                    self.i,
                    1,
                    Field::Member(name, member),
                    ErrorKind::Invalid(format!("`{member}` needs {N} numbers, found {k}")),
                ));
            }
            *slot = self.f32(Field::Element(name, member, k))?;
            self.ws();
            if k.saturating_add(1) < N {
                if self.peek() == Some(b']') {
                    return Err(error(
                        self.i,
                        1,
                        Field::Member(name, member),
                        ErrorKind::Invalid(format!(
                            "`{member}` needs {N} numbers, found {}",
                            k.saturating_add(1)
                        )),
                    ));
                }
                self.expect(b',', Field::Member(name, member), "`,`")?;
                self.ws();
            }
        }
        if self.peek() == Some(b',') {
            return Err(error(
                self.i,
                1,
                Field::Member(name, member),
                ErrorKind::Invalid(format!("`{member}` needs {N} numbers, found more")),
            ));
        }
        self.expect(b']', Field::Member(name, member), "`]`")?;
        Ok(out)
    }
}

fn describe_byte(c: u8, rest: &[u8]) -> String {
    if c.is_ascii_graphic() {
        let word: Vec<u8> = rest
            .iter()
            .take_while(|c| c.is_ascii_alphanumeric() || **c == b'_')
            .take(20)
            .copied()
            .collect();
        if word.len() > 1 {
            format!("`{}`", String::from_utf8_lossy(&word))
        } else {
            format!("`{}`", c as char)
        }
    } else {
        format!("byte 0x{c:02x}")
    }
}

/// serde_json's message without its " at line L column C" suffix.
pub(crate) fn strip_position(e: &serde_json::Error) -> String {
    let s = e.to_string();
    match s.rfind(" at line ") {
        Some(p) => s[..p].to_string(),
        None => s,
    }
}

/// The members of an entity state read so far.
#[derive(Debug, Default)]
struct Parts {
    pos: Option<[f32; 3]>,
    rot: Option<[f32; 4]>,
    vel: Option<[f32; 3]>,
    grip: Option<f32>,
    /// `Some(None)`: `"holding": null`.
    holding: Option<Option<EntityId>>,
}

/// The parser's view of a header: entity names in order, a map for out-of-order names.
#[derive(Debug)]
pub(crate) struct FrameParser {
    names: Vec<Box<[u8]>>,
    kinds: Vec<EntityKind>,
    fixed: Vec<bool>,
    map: FxHashMap<Box<[u8]>, u32>,
}

/// The time of a parsed frame and where it stands in the line.
pub(crate) struct TimeToken {
    pub column: usize,
    pub width: usize,
}

/// The id of the entity at `index` in the header. Indices are below the header's entity
/// count, at most [`check::MAX_ENTITIES`], so they fit `u32`.
fn entity_id(index: usize) -> EntityId {
    EntityId(u32::try_from(index).unwrap_or(u32::MAX))
}

impl FrameParser {
    pub fn new(header: &Header) -> FrameParser {
        let names: Vec<Box<[u8]>> = header
            .entities
            .iter()
            .map(|e| e.name.as_bytes().into())
            .collect();
        let map = names
            .iter()
            .enumerate()
            .map(|(i, n)| (n.clone(), entity_id(i).0))
            .collect();
        FrameParser {
            kinds: header.entities.iter().map(|e| e.kind).collect(),
            fixed: header.entities.iter().map(|e| e.fixed.is_some()).collect(),
            names,
            map,
        }
    }

    #[inline]
    fn lookup(&self, name: &[u8], hint: &mut usize) -> Option<usize> {
        if let Some(n) = self.names.get(*hint) {
            if **n == *name {
                let id = *hint;
                *hint = id.saturating_add(1);
                return Some(id);
            }
        }
        // A few names are faster to compare than to hash.
        let id = if self.names.len() <= 16 {
            self.names.iter().position(|n| **n == *name)?
        } else {
            *self.map.get(name)? as usize
        };
        *hint = id.saturating_add(1);
        Some(id)
    }

    fn name(&self, id: usize) -> &str {
        std::str::from_utf8(&self.names[id]).unwrap_or("?")
    }

    /// Parses one frame line into `frame` (cleared first). Checks every rule of the format
    /// except the time order, which needs the previous frame.
    pub fn parse(&self, line: &[u8], frame: &mut Frame) -> Result<TimeToken, LineError> {
        frame.clear(self.names.len());
        let mut c = Cursor { b: line, i: 0 };
        c.ws();
        if c.peek() != Some(b'{') {
            return Err(c.unexpected(Field::Root, "a frame (a JSON object starting with `{`)"));
        }
        c.i = c.i.saturating_add(1);
        c.ws();
        let mut time: Option<TimeToken> = None;
        let (mut entities, mut contacts) = (false, false);
        if c.peek() == Some(b'}') {
            c.i = c.i.saturating_add(1);
        } else {
            loop {
                let key_at = c.i;
                let key = c.string(Field::Root)?;
                c.ws();
                c.expect(b':', Field::Key(&key), "`:`")?;
                c.ws();
                let twice = |seen: bool| {
                    if seen {
                        Err(error(
                            key_at,
                            key.len().saturating_add(2),
                            Field::Key(&key),
                            ErrorKind::Invalid(format!(
                                "field `{}` given twice",
                                String::from_utf8_lossy(&key)
                            )),
                        ))
                    } else {
                        Ok(())
                    }
                };
                match &*key {
                    b"t" => {
                        twice(time.is_some())?;
                        let (t, column, width) = c.f64(Field::Time)?;
                        frame.time = t;
                        time = Some(TimeToken { column, width });
                    }
                    b"entities" => {
                        twice(entities)?;
                        entities = true;
                        self.entities(&mut c, frame)?;
                    }
                    b"contacts" => {
                        twice(contacts)?;
                        contacts = true;
                        self.contacts(&mut c, frame)?;
                    }
                    other => {
                        return Err(error(
                            key_at,
                            key.len().saturating_add(2),
                            Field::Key(other),
                            ErrorKind::Invalid(format!(
                                "unknown field `{}` (a frame has `t`, `entities` and `contacts`)",
                                String::from_utf8_lossy(other)
                            )),
                        ))
                    }
                }
                if !c.comma_or(b'}', Field::Root)? {
                    break;
                }
            }
        }
        c.ws();
        if c.i < line.len() {
            return Err(error(
                c.i,
                line.len().saturating_sub(c.i),
                Field::Root,
                ErrorKind::Syntax("text after the end of the frame".into()),
            ));
        }
        time.ok_or_else(|| {
            error(
                0,
                1,
                Field::Time,
                ErrorKind::Invalid("missing field `t` (the frame's time in seconds)".into()),
            )
        })
    }

    fn entities<'a>(&self, c: &mut Cursor<'a>, frame: &mut Frame) -> Result<(), LineError> {
        if c.open(b'{', b'}', Field::Entities, "`{`")? {
            return Ok(());
        }
        let mut hint = 0usize;
        loop {
            let key_at = c.i;
            let key = c.string(Field::Entities)?;
            let width = key.len().saturating_add(2);
            let Some(id) = self.lookup(&key, &mut hint) else {
                return Err(error(
                    key_at,
                    width,
                    Field::Entity(&key),
                    ErrorKind::UnknownEntity(String::from_utf8_lossy(&key).into_owned()),
                ));
            };
            if self.fixed[id] {
                return Err(error(
                    key_at,
                    width,
                    Field::Entity(&key),
                    ErrorKind::Invalid(check::fixed_in_frame_message(self.name(id))),
                ));
            }
            if frame.states[id].is_some() {
                return Err(error(
                    key_at,
                    width,
                    Field::Entity(&key),
                    ErrorKind::Invalid(format!("entity `{}` listed twice", self.name(id))),
                ));
            }
            c.ws();
            c.expect(b':', Field::Entity(&key), "`:`")?;
            c.ws();
            let name: &[u8] = &self.names[id];
            frame.states[id] = Some(self.state(c, id, name)?);
            if !c.comma_or(b'}', Field::Entities)? {
                return Ok(());
            }
        }
    }

    fn state(&self, c: &mut Cursor<'_>, id: usize, name: &[u8]) -> Result<EntityState, LineError> {
        let open = c.i;
        let empty = c.open(b'{', b'}', Field::Entity(name), "`{`")?;
        let kind = self.kinds[id];
        let mut parts = Parts::default();
        if !empty {
            loop {
                let key_at = c.i;
                let member = match c.known_member() {
                    Some(m) => m,
                    None => {
                        let key = c.string(Field::Entity(name))?;
                        Member::ALL
                            .into_iter()
                            .find(|m| m.name().as_bytes() == &*key)
                            .ok_or_else(|| {
                                error(
                                    key_at,
                                    key.len().saturating_add(2),
                                    Field::Entity(name),
                                    ErrorKind::Invalid(format!(
                                        "unknown field `{}` (an entity state has `pos`, `rot`, \
                                         `vel`, `grip` and `holding`)",
                                        String::from_utf8_lossy(&key)
                                    )),
                                )
                            })?
                    }
                };
                c.ws();
                c.expect(b':', Field::Member(name, member.name()), "`:`")?;
                c.ws();
                self.member(c, id, kind, name, member, key_at, &mut parts)?;
                if !c.comma_or(b'}', Field::Entity(name))? {
                    break;
                }
            }
        }
        let missing = |what: &str| {
            error(
                open,
                1,
                Field::Entity(name),
                ErrorKind::Invalid(format!(
                    "entity `{}` has no `{what}`",
                    String::from_utf8_lossy(name)
                )),
            )
        };
        let pos = parts.pos.ok_or_else(|| missing("pos"))?;
        let rot = parts.rot.ok_or_else(|| missing("rot"))?;
        if kind == EntityKind::Hand && parts.grip.is_none() {
            return Err(error(
                open,
                1,
                Field::Entity(name),
                ErrorKind::Invalid(check::missing_grip_message(self.name(id))),
            ));
        }
        Ok(EntityState {
            pose: Pose {
                position: Vec3::from_array(pos),
                orientation: Quaternion::from_array(rot),
            },
            velocity: parts.vel.map(Vec3::from_array),
            grip: parts.grip,
            holding: parts.holding.flatten(),
        })
    }

    /// One member of an entity state, after its key and colon.
    #[allow(clippy::too_many_arguments)]
    #[inline(always)]
    fn member(
        &self,
        c: &mut Cursor<'_>,
        id: usize,
        kind: EntityKind,
        name: &[u8],
        member: Member,
        key_at: usize,
        parts: &mut Parts,
    ) -> Result<(), LineError> {
        let key_width = member.name().len().saturating_add(2);
        let field = Field::Member(name, member.name());
        let seen = match member {
            Member::Pos => parts.pos.is_some(),
            Member::Rot => parts.rot.is_some(),
            Member::Vel => parts.vel.is_some(),
            Member::Grip => parts.grip.is_some(),
            Member::Holding => parts.holding.is_some(),
        };
        if seen {
            return Err(error(
                key_at,
                key_width,
                field,
                ErrorKind::Invalid(format!("field `{}` given twice", member.name())),
            ));
        }
        let value_at = c.i;
        match member {
            Member::Pos => parts.pos = Some(c.array::<3>(name, "pos")?),
            Member::Rot => {
                let q = Quaternion::from_array(c.array::<4>(name, "rot")?);
                if !q.is_unit() {
                    return Err(error(
                        value_at,
                        c.i.saturating_sub(value_at),
                        field,
                        ErrorKind::Invalid(check::quaternion_message(q.norm())),
                    ));
                }
                parts.rot = Some(q.to_array());
            }
            Member::Vel => parts.vel = Some(c.array::<3>(name, "vel")?),
            Member::Grip => {
                if kind != EntityKind::Hand {
                    return Err(error(
                        key_at,
                        key_width,
                        field,
                        ErrorKind::Invalid(check::grip_not_hand_message(self.name(id), kind)),
                    ));
                }
                let g = c.f32(field)?;
                if !(0.0..=1.0).contains(&g) {
                    return Err(error(
                        value_at,
                        c.i.saturating_sub(value_at),
                        field,
                        ErrorKind::Invalid(check::grip_range_message(g)),
                    ));
                }
                parts.grip = Some(g);
            }
            Member::Holding => {
                parts.holding = Some(self.holding(c, id, kind, name, key_at, key_width)?);
            }
        }
        Ok(())
    }

    fn holding(
        &self,
        c: &mut Cursor<'_>,
        id: usize,
        kind: EntityKind,
        name: &[u8],
        key_at: usize,
        key_width: usize,
    ) -> Result<Option<EntityId>, LineError> {
        let field = Field::Member(name, "holding");
        if kind != EntityKind::Hand {
            return Err(error(
                key_at,
                key_width,
                field,
                ErrorKind::Invalid(check::holding_not_hand_message(self.name(id), kind)),
            ));
        }
        if c.b[c.i..].starts_with(b"null") {
            c.i = c.i.saturating_add(4);
            return Ok(None);
        }
        let at = c.i;
        let held = c.string(field)?;
        let width = c.i.saturating_sub(at);
        let mut no_hint = usize::MAX;
        let Some(h) = self.lookup(&held, &mut no_hint) else {
            return Err(error(
                at,
                width,
                field,
                ErrorKind::UnknownEntity(String::from_utf8_lossy(&held).into_owned()),
            ));
        };
        let message = if h == id {
            Some(check::holding_itself_message(self.name(id)))
        } else if self.kinds[h] == EntityKind::Hand {
            Some(check::holding_hand_message(self.name(h)))
        } else {
            None
        };
        match message {
            Some(m) => Err(error(at, width, field, ErrorKind::Invalid(m))),
            None => Ok(Some(entity_id(h))),
        }
    }

    fn contacts<'a>(&self, c: &mut Cursor<'a>, frame: &mut Frame) -> Result<(), LineError> {
        if c.open(b'[', b']', Field::Contacts, "`[`")? {
            return Ok(());
        }
        let mut i = 0usize;
        loop {
            let open = c.i;
            c.expect(
                b'[',
                Field::Contact(i),
                "`[` (a contact is a pair of names)",
            )?;
            c.ws();
            let mut ids = [0usize; 2];
            for (j, slot) in ids.iter_mut().enumerate() {
                let at = c.i;
                let name = c.string(Field::ContactEnd(i, j))?;
                let mut no_hint = usize::MAX;
                *slot = self.lookup(&name, &mut no_hint).ok_or_else(|| {
                    error(
                        at,
                        c.i.saturating_sub(at),
                        Field::ContactEnd(i, j),
                        ErrorKind::UnknownEntity(String::from_utf8_lossy(&name).into_owned()),
                    )
                })?;
                c.ws();
                if j == 0 {
                    c.expect(
                        b',',
                        Field::Contact(i),
                        "`,` (a contact is a pair of names)",
                    )?;
                    c.ws();
                }
            }
            c.expect(
                b']',
                Field::Contact(i),
                "`]` (a contact is a pair of names)",
            )?;
            if ids[0] == ids[1] {
                return Err(error(
                    open,
                    c.i.saturating_sub(open),
                    Field::Contact(i),
                    ErrorKind::Invalid(check::contact_self_message(self.name(ids[0]))),
                ));
            }
            frame.contacts.push(Contact {
                a: entity_id(ids[0]),
                b: entity_id(ids[1]),
            });
            i = i.saturating_add(1);
            if !c.comma_or(b']', Field::Contacts)? {
                return Ok(());
            }
        }
    }
}

#[cfg(test)]
#[allow(clippy::arithmetic_side_effects, clippy::cast_possible_truncation)] // tests, not readers
mod tests {
    use super::*;

    fn f32_of(text: &str) -> Result<f32, LineError> {
        Cursor {
            b: text.as_bytes(),
            i: 0,
        }
        .f32(Field::Root)
    }

    #[test]
    fn numbers_parse_as_std_does() {
        for t in [
            "0",
            "-0",
            "1",
            "0.1",
            "0.4123",
            "-0.98765",
            "123.25",
            "1e3",
            "1.5E-7",
            "3.4028235e38",
            "0.000000000000000000000000000000000000000000001",
            "16777217",
            "0.123456789012",
            "12345678901234567890123",
        ] {
            let expected: f32 = t.parse().unwrap();
            let got = f32_of(t).unwrap();
            assert_eq!(got.to_bits(), expected.to_bits(), "{t}");
        }
    }

    #[test]
    fn non_finite_and_malformed_numbers_are_refused() {
        for t in ["NaN", "-Infinity", "inf", "1e39"] {
            assert!(
                matches!(f32_of(t).unwrap_err().kind, ErrorKind::NotFinite(_)),
                "{t}"
            );
        }
        for t in ["01", "1.", "-", "+1", ".5", "1e", "x"] {
            let e = f32_of(t).unwrap_err();
            assert!(
                matches!(e.kind, ErrorKind::Syntax(_) | ErrorKind::Truncated),
                "{t}: {:?}",
                e.kind
            );
        }
    }

    #[test]
    fn short_decimals_take_the_fast_path_exactly() {
        // Every 4-decimal number in [-1, 1] parses to the correctly rounded f32.
        for m in -10_000i32..=10_000 {
            let t = format!("{}", f64::from(m) / 1e4);
            let expected: f32 = t.parse().unwrap();
            assert_eq!(f32_of(&t).unwrap().to_bits(), expected.to_bits(), "{t}");
        }
    }
}
