//! The ARFF text format as Weka's `ArffLoader` reads it.
//!
//! Weka reads ARFF with a `java.io.StreamTokenizer` set up so that every character up to
//! the space, and the comma, separate tokens (so values are separated by commas, spaces,
//! tabs or any mix, and runs of separators count as one); `%` starts a comment that runs
//! to the end of the line; `'` and `"` quote a token (names and nominal values too), with
//! Java's escapes (`\n`, `\t`, `\'`, `\\`, octal `\101`, ...); `{` and `}` are tokens of
//! their own; and the end of a line ends a header declaration or a data row. This module
//! is that tokenizer and the grammar over it:
//!
//! - `@relation NAME`, `@attribute NAME TYPE` and `@data`, in any case, `@relation`
//!   first. A type is `numeric`, `real`, `integer`, `string`, `date [FORMAT]` or a
//!   nominal `{a, b, 'c d'}`. Text after a numeric, string or date type is ignored, as
//!   Weka ignores it.
//! - Dense rows, one value per attribute, `?` for missing (a quoted `'?'` is the value
//!   `?`, as in Weka). Sparse rows `{INDEX VALUE, ...}` with 0-based indices in
//!   increasing order; a value left out is 0: `0` for numeric attributes, the first
//!   declared value for nominal ones (Weka stores a nominal value as its index),
//!   1970-01-01T00:00:00 for dates in the default format, and for string attributes
//!   the placeholder Weka's loader keeps at string index 0, [`WEKA_DUMMY_STRING`].
//!
//! Where this reader differs from Weka, it refuses rather than guesses: an unclosed
//! quote (Weka ends it at the end of the line), NaN or infinite numbers, relational
//! attributes, instance weights (`{w}` after a row), and a date left out of a sparse
//! row whose format is not the default (dates are kept as text, not parsed). And it
//! accepts values of nominal attributes that the header does
//! not declare (real files have them): [`ArffTable::dataset`](super::ArffTable::dataset)
//! and [`ArffTable::hand_frames`](super::ArffTable::hand_frames) say so in warnings.

// A reader of untrusted input (issue 23): no arithmetic that can wrap or panic, no
// cast that can truncate; each such operation is checked, saturating or proved in range.
#![deny(clippy::arithmetic_side_effects, clippy::cast_possible_truncation)]

use super::{error, ArffAttribute, ArffError, ArffKind, ArffRow, ArffTable};

/// What Weka reads for a string attribute that a sparse row leaves out: its loader puts
/// this placeholder at index 0 of every string attribute's values (checked with Weka
/// 3.6.14's `ArffLoader`).
pub const WEKA_DUMMY_STRING: &str = "*WEKA*DUMMY*STRING*FOR*STRING*ATTRIBUTES*";

/// Weka's default date format.
const DEFAULT_DATE_FORMAT: &str = "yyyy-MM-dd'T'HH:mm:ss";

/// What a token is.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Kind {
    /// Unquoted text.
    Word,
    /// Quoted text (quotes removed, escapes resolved).
    Quoted,
    /// `{`.
    Open,
    /// `}`.
    Close,
}

#[derive(Debug, Clone)]
struct Token {
    kind: Kind,
    text: String,
    /// 1-based byte column of the token's first character.
    column: usize,
}

impl Token {
    /// Text that stands for a name or a value: a word or a quoted token.
    fn is_text(&self) -> bool {
        matches!(self.kind, Kind::Word | Kind::Quoted)
    }

    /// `?`, unquoted: a missing value.
    fn is_missing(&self) -> bool {
        self.kind == Kind::Word && self.text == "?"
    }

    /// The token as written, for messages.
    fn shown(&self) -> String {
        match self.kind {
            Kind::Quoted => format!("'{}'", self.text),
            _ => self.text.clone(),
        }
    }
}

/// A line that does not split into tokens: where, what, and how many tokens came first.
struct TokenError {
    column: usize,
    message: String,
    before: usize,
}

/// Separators: every character up to the space, and the comma (Weka's
/// `whitespaceChars(0, ' ')` and `whitespaceChars(',', ',')`). A byte order mark, which
/// Weka would read as part of the first word, is skipped too.
fn is_separator(c: char) -> bool {
    c <= ' ' || c == ',' || c == '\u{feff}'
}

/// Characters that end an unquoted word besides separators.
fn ends_word(c: char) -> bool {
    is_separator(c) || matches!(c, '%' | '{' | '}' | '\'' | '"')
}

/// Splits one line into tokens as Weka's tokenizer does.
fn tokenize(line: &str) -> Result<Vec<Token>, TokenError> {
    let mut tokens = Vec::new();
    let mut chars = line.char_indices().peekable();
    while let Some(&(at, c)) = chars.peek() {
        let column = at.saturating_add(1);
        if is_separator(c) {
            chars.next();
            continue;
        }
        match c {
            '%' => break,
            '{' | '}' => {
                chars.next();
                let kind = if c == '{' { Kind::Open } else { Kind::Close };
                tokens.push(Token {
                    kind,
                    text: c.to_string(),
                    column,
                });
            }
            '\'' | '"' => {
                chars.next();
                let mut text = String::new();
                loop {
                    match chars.next() {
                        None => {
                            return Err(TokenError {
                                column,
                                message: format!(
                                    "the quoted value is not closed: a {c} quote ends on the line it starts"
                                ),
                                before: tokens.len(),
                            })
                        }
                        Some((_, q)) if q == c => break,
                        Some((_, '\\')) => match chars.next() {
                            None => {
                                return Err(TokenError {
                                    column,
                                    message: "the quoted value is not closed: the line ends after `\\`".into(),
                                    before: tokens.len(),
                                })
                            }
                            Some((_, d @ '0'..='7')) => {
                                // Java's octal escape: up to three digits, the first of
                                // three at most `3`.
                                let mut code = d.to_digit(8).unwrap_or(0);
                                let mut digits: u8 = 1;
                                while let Some(&(_, e @ '0'..='7')) = chars.peek() {
                                    if digits == 2 && d > '3' || digits == 3 {
                                        break;
                                    }
                                    // At most three octal digits: below 512.
                                    code = code
                                        .saturating_mul(8)
                                        .saturating_add(e.to_digit(8).unwrap_or(0));
                                    digits = digits.saturating_add(1);
                                    chars.next();
                                }
                                text.push(char::from_u32(code).unwrap_or('\u{fffd}'));
                            }
                            Some((_, e)) => text.push(match e {
                                'a' => '\u{7}',
                                'b' => '\u{8}',
                                'f' => '\u{c}',
                                'n' => '\n',
                                'r' => '\r',
                                't' => '\t',
                                'v' => '\u{b}',
                                other => other,
                            }),
                        },
                        Some((_, other)) => text.push(other),
                    }
                }
                tokens.push(Token {
                    kind: Kind::Quoted,
                    text,
                    column,
                });
            }
            _ => {
                let mut end = line.len();
                while let Some(&(i, d)) = chars.peek() {
                    if ends_word(d) {
                        end = i;
                        break;
                    }
                    chars.next();
                }
                tokens.push(Token {
                    kind: Kind::Word,
                    text: line[at..end].to_string(),
                    column,
                });
            }
        }
    }
    Ok(tokens)
}

/// Whether a text is ARFF by its content: its first line that is neither blank nor a `%`
/// comment starts with `@relation`, in any case. Recognisers' tables often ship as
/// `.txt`; a native recording starts with `{`.
pub fn is_arff_text(text: &str) -> bool {
    for line in text.lines() {
        let rest = line.trim_start_matches(is_separator);
        if rest.is_empty() || rest.starts_with('%') {
            continue;
        }
        let end = rest.find(ends_word).unwrap_or(rest.len());
        return rest[..end].eq_ignore_ascii_case("@relation");
    }
    false
}

/// Whether the file at `path` is an ARFF table: by its extension `.arff`, or by its
/// content ([`is_arff_text`] on its first 64 KiB), since recognisers' tables often ship
/// as `.txt`. The one place that decides it, for every command. A file that cannot be
/// read is not ARFF here; reading it later says why.
pub fn is_arff_file(path: &std::path::Path) -> bool {
    use std::io::Read as _;
    if path
        .extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("arff"))
    {
        return true;
    }
    let Ok(file) = std::fs::File::open(path) else {
        return false;
    };
    let mut start = Vec::with_capacity(4096);
    if std::io::Read::take(file, 64 * 1024)
        .read_to_end(&mut start)
        .is_err()
    {
        return false;
    }
    is_arff_text(&String::from_utf8_lossy(&start))
}

/// Where the reader is in the header (after `@data`, [`ArffReader`] reads rows).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Section {
    /// Before `@relation`.
    Start,
    /// Between `@relation` and `@data`.
    Header,
}

/// Reads an ARFF file as Weka's `ArffLoader` does (see the module documentation for
/// the grammar, the sparse rows' zeros, and where this reader refuses what Weka would
/// guess). Errors name the line, the column, and the attribute (or the keyword).
///
/// The whole table in memory: for files of any length, read with [`ArffReader`].
pub fn read_arff(text: &str) -> Result<ArffTable, ArffError> {
    ArffReader::new(text.as_bytes())?.into_table()
}

/// An ARFF file read a row at a time, in memory bounded by its longest line: the header
/// when it is created, then each data row as an [`Iterator`] item. It reads exactly as
/// [`read_arff`] does, with the same errors at the same places; after an error it ends.
#[derive(Debug)]
pub struct ArffReader<R> {
    input: R,
    relation: String,
    attributes: Vec<ArffAttribute>,
    /// The number of the last line read.
    line: usize,
    /// The text of the last line read (reused from line to line).
    text: String,
    /// Set at the end of the input or after an error.
    done: bool,
}

impl<R: std::io::BufRead> ArffReader<R> {
    /// Reads the header, up to and including `@data`.
    pub fn new(input: R) -> Result<ArffReader<R>, ArffError> {
        let mut reader = ArffReader {
            input,
            relation: String::new(),
            attributes: Vec::new(),
            line: 0,
            text: String::new(),
            done: false,
        };
        reader.read_header()?;
        Ok(reader)
    }

    /// `@relation`.
    pub fn relation(&self) -> &str {
        &self.relation
    }

    /// `@attribute`s.
    pub fn attributes(&self) -> &[ArffAttribute] {
        &self.attributes
    }

    /// Reads the next line into `self.text`, without its line end (`\n` or `\r\n`, as
    /// [`str::lines`] splits). `false` at the end of the input.
    fn next_line(&mut self, field: &str) -> Result<bool, ArffError> {
        self.text.clear();
        match self.input.read_line(&mut self.text) {
            Ok(0) => Ok(false),
            Ok(_) => {
                self.line = self.line.saturating_add(1);
                if self.text.ends_with('\n') {
                    self.text.pop();
                    if self.text.ends_with('\r') {
                        self.text.pop();
                    }
                }
                Ok(true)
            }
            Err(e) => {
                let line = self.line.saturating_add(1);
                let message = if e.kind() == std::io::ErrorKind::InvalidData {
                    "the line is not UTF-8 text".to_string()
                } else {
                    format!("cannot read the file: {e}")
                };
                Err(error(line, 0, field, message))
            }
        }
    }

    fn read_header(&mut self) -> Result<(), ArffError> {
        let mut section = Section::Start;
        let field = |section: Section| match section {
            Section::Start => "@relation",
            _ => "@attribute",
        };
        while self.next_line(field(section))? {
            let line = self.line;
            let tokens =
                tokenize(&self.text).map_err(|e| error(line, e.column, "@attribute", e.message))?;
            let Some(first) = tokens.first() else {
                continue;
            };
            let keyword = first.text.to_ascii_lowercase();
            if first.kind != Kind::Word || !keyword.starts_with('@') {
                let expected = if section == Section::Start {
                    "@relation"
                } else {
                    "@attribute or @data"
                };
                return Err(error(
                    line,
                    first.column,
                    &first.text,
                    format!("expected {expected}, found `{}`", first.shown()),
                ));
            }
            match (section, keyword.as_str()) {
                (Section::Start, "@relation") => {
                    self.relation = relation_name(line, &tokens)?;
                    section = Section::Header;
                }
                (Section::Start, _) => {
                    return Err(error(
                        line,
                        first.column,
                        &first.text,
                        format!(
                            "an ARFF file starts with `@relation NAME`, found `{}`",
                            first.text
                        ),
                    ))
                }
                (_, "@attribute") => {
                    let attribute = attribute(line, &tokens)?;
                    if self.attributes.iter().any(|a| a.name == attribute.name) {
                        return Err(error(
                            line,
                            tokens[1].column,
                            &attribute.name,
                            format!("attribute `{}` is declared twice", attribute.name),
                        ));
                    }
                    self.attributes.push(attribute);
                }
                (_, "@data") => {
                    if self.attributes.is_empty() {
                        return Err(error(
                            line,
                            first.column,
                            "@data",
                            "no @attribute before @data",
                        ));
                    }
                    if let Some(extra) = tokens.get(1) {
                        return Err(error(
                            line,
                            extra.column,
                            "@data",
                            format!(
                                "expected the end of the line after @data, found `{}`",
                                extra.shown()
                            ),
                        ));
                    }
                    return Ok(());
                }
                (_, "@relation") => {
                    return Err(error(
                        line,
                        first.column,
                        "@relation",
                        "a second @relation: a file holds one relation",
                    ))
                }
                _ => {
                    return Err(error(
                        line,
                        first.column,
                        &first.text,
                        format!("expected @attribute or @data, found `{}`", first.text),
                    ))
                }
            }
        }
        let (field, what) = if section == Section::Start {
            (
                "@relation",
                "no @relation: an ARFF file starts with `@relation NAME`",
            )
        } else {
            ("@data", "no @data section")
        };
        Err(error(self.line.max(1), 0, field, what))
    }

    /// The next data row, `None` at the end of the file.
    fn read_row(&mut self) -> Result<Option<ArffRow>, ArffError> {
        loop {
            let field = self.attributes.first().map_or("@data", |a| a.name.as_str());
            let field = field.to_string();
            if !self.next_line(&field)? {
                return Ok(None);
            }
            let line = self.line;
            let attributes = &self.attributes;
            let tokens = tokenize(&self.text).map_err(|e| {
                let field = attributes
                    .get(e.before.min(attributes.len().saturating_sub(1)))
                    .map_or("@data", |a| a.name.as_str());
                error(line, e.column, field, e.message)
            })?;
            let Some(first) = tokens.first() else {
                continue;
            };
            return if first.kind == Kind::Open {
                sparse_row(line, &tokens, attributes)
            } else {
                dense_row(line, &tokens, attributes)
            }
            .map(Some);
        }
    }
}

impl<R: std::io::BufRead> ArffReader<R> {
    /// The rest of the table read into memory, for what needs every row at once (C4.5 on
    /// a data set that is not a hand-state table).
    pub fn into_table(mut self) -> Result<ArffTable, ArffError> {
        let rows = self.by_ref().collect::<Result<Vec<_>, _>>()?;
        Ok(ArffTable {
            relation: self.relation,
            attributes: self.attributes,
            rows,
        })
    }
}

impl<R: std::io::BufRead> Iterator for ArffReader<R> {
    type Item = Result<ArffRow, ArffError>;

    fn next(&mut self) -> Option<Self::Item> {
        if self.done {
            return None;
        }
        let row = self.read_row().transpose();
        if !matches!(row, Some(Ok(_))) {
            self.done = true;
        }
        row
    }
}

/// The name after a declaration's keyword (`tokens[0]`): the relation's or an
/// attribute's (`whose`).
fn declared_name(
    line: usize,
    tokens: &[Token],
    keyword: &str,
    whose: &str,
) -> Result<String, ArffError> {
    match tokens.get(1) {
        Some(t) if t.is_text() => Ok(t.text.clone()),
        Some(t) => Err(error(
            line,
            t.column,
            keyword,
            format!("expected the {whose} name, found `{}`", t.text),
        )),
        None => Err(error(
            line,
            tokens[0].column,
            keyword,
            format!("the {whose} name is missing"),
        )),
    }
}

/// `@relation NAME`, nothing after the name.
fn relation_name(line: usize, tokens: &[Token]) -> Result<String, ArffError> {
    let name = declared_name(line, tokens, "@relation", "relation's")?;
    if let Some(extra) = tokens.get(2) {
        return Err(error(
            line,
            extra.column,
            "@relation",
            format!(
                "expected the end of the line after the relation's name, found `{}` (a name with spaces is quoted)",
                extra.shown()
            ),
        ));
    }
    Ok(name)
}

/// `@attribute NAME TYPE`.
fn attribute(line: usize, tokens: &[Token]) -> Result<ArffAttribute, ArffError> {
    let name = declared_name(line, tokens, "@attribute", "attribute's")?;
    let Some(spec) = tokens.get(2) else {
        return Err(error(
            line,
            tokens[1].column,
            &name,
            format!("attribute `{name}` has no type (numeric, real, integer, string, date or {{values}})"),
        ));
    };
    let kind = match spec.kind {
        Kind::Open => nominal(line, &name, &tokens[2..])?,
        Kind::Close => {
            return Err(error(
                line,
                spec.column,
                &name,
                "a `}` without its `{`: a nominal type is `{a, b, c}`",
            ))
        }
        Kind::Word | Kind::Quoted => match spec.text.to_ascii_lowercase().as_str() {
            "numeric" | "real" | "integer" => ArffKind::Numeric,
            "string" => ArffKind::String,
            "date" => ArffKind::Date(match tokens.get(3) {
                Some(f) if f.is_text() => f.text.clone(),
                _ => DEFAULT_DATE_FORMAT.to_string(),
            }),
            "relational" => {
                return Err(error(
                    line,
                    spec.column,
                    &name,
                    "relational attributes are not supported",
                ))
            }
            _ => {
                return Err(error(
                    line,
                    spec.column,
                    &name,
                    format!(
                        "unknown type `{}` (numeric, real, integer, string, date or {{values}})",
                        spec.text
                    ),
                ))
            }
        },
    };
    Ok(ArffAttribute { name, kind, line })
}

/// `{a, b, 'c d'}`: `tokens` starts at the `{`.
fn nominal(line: usize, name: &str, tokens: &[Token]) -> Result<ArffKind, ArffError> {
    let mut values: Vec<String> = Vec::new();
    for (k, t) in tokens.iter().enumerate().skip(1) {
        match t.kind {
            Kind::Close => {
                if let Some(extra) = tokens.get(k.saturating_add(1)) {
                    return Err(error(
                        line,
                        extra.column,
                        name,
                        format!(
                            "expected the end of the line after the nominal type's `}}`, found `{}`",
                            extra.shown()
                        ),
                    ));
                }
                return Ok(ArffKind::Nominal(values));
            }
            Kind::Open => {
                return Err(error(
                    line,
                    t.column,
                    name,
                    "a `{` inside a nominal type (quote a value that has one)",
                ))
            }
            Kind::Word | Kind::Quoted => {
                if values.contains(&t.text) {
                    return Err(error(
                        line,
                        t.column,
                        name,
                        format!("value `{}` is declared twice", t.text),
                    ));
                }
                values.push(t.text.clone());
            }
        }
    }
    Err(error(
        line,
        tokens[0].column,
        name,
        "a nominal type ends with `}` on the line it starts",
    ))
}

/// A value of attribute `a` as written (`None` for `?`), checked for its type.
fn value(line: usize, t: &Token, a: &ArffAttribute) -> Result<Option<String>, ArffError> {
    if !t.is_text() {
        return Err(error(
            line,
            t.column,
            &a.name,
            format!(
                "expected a value of `{}`, found `{}` (a sparse row starts with `{{`)",
                a.name, t.text
            ),
        ));
    }
    if t.is_missing() {
        return Ok(None);
    }
    if a.kind == ArffKind::Numeric && t.text.parse::<f64>().map_or(true, |x| !x.is_finite()) {
        return Err(error(
            line,
            t.column,
            &a.name,
            format!("`{}` is not a number", t.text),
        ));
    }
    Ok(Some(t.text.clone()))
}

/// A dense row: one value per attribute.
fn dense_row(
    line: usize,
    tokens: &[Token],
    attributes: &[ArffAttribute],
) -> Result<ArffRow, ArffError> {
    let n = attributes.len();
    // A brace says more about the row than its count of values.
    if let Some((k, t)) = tokens.iter().enumerate().find(|(_, t)| !t.is_text()) {
        // The header has at least one attribute (`@data` needs one).
        value(line, t, &attributes[k.min(n.saturating_sub(1))])?;
    }
    if tokens.len() != n {
        let (column, field) = if tokens.len() < n {
            (tokens[0].column, attributes[tokens.len()].name.as_str())
        } else {
            (
                tokens[n].column,
                attributes[n.saturating_sub(1)].name.as_str(),
            )
        };
        return Err(error(
            line,
            column,
            field,
            format!(
                "{} values, but the header declares {n} attributes",
                tokens.len()
            ),
        ));
    }
    let values = tokens
        .iter()
        .zip(attributes)
        .map(|(t, a)| value(line, t, a))
        .collect::<Result<_, _>>()?;
    Ok(ArffRow { line, values })
}

/// A sparse row `{INDEX VALUE, ...}`; values left out are Weka's 0.
fn sparse_row(
    line: usize,
    tokens: &[Token],
    attributes: &[ArffAttribute],
) -> Result<ArffRow, ArffError> {
    let n = attributes.len();
    let open = tokens[0].column;
    let mut given: Vec<Option<Option<String>>> = vec![None; n];
    let mut last: Option<usize> = None;
    let mut k = 1;
    loop {
        let Some(t) = tokens.get(k) else {
            return Err(error(
                line,
                open,
                "@data",
                "a sparse row ends with `}` on the line it starts",
            ));
        };
        if t.kind == Kind::Close {
            k = k.saturating_add(1);
            break;
        }
        let index = match (t.kind, t.text.parse::<usize>()) {
            (Kind::Word, Ok(i)) => i,
            _ => {
                return Err(error(
                    line,
                    t.column,
                    "@data",
                    format!(
                        "expected an attribute index (0-based) in a sparse row, found `{}`",
                        t.shown()
                    ),
                ))
            }
        };
        if index >= n {
            return Err(error(
                line,
                t.column,
                "@data",
                format!(
                    "index {index} is out of range: the header declares {n} attributes, indices 0 to {}",
                    n.saturating_sub(1)
                ),
            ));
        }
        let a = &attributes[index];
        if let Some(previous) = last.filter(|&p| p >= index) {
            return Err(error(
                line,
                t.column,
                &a.name,
                format!(
                    "index {index} after index {previous}: a sparse row lists its indices in increasing order"
                ),
            ));
        }
        last = Some(index);
        let v = match tokens.get(k.saturating_add(1)) {
            Some(v) if v.is_text() => value(line, v, a)?,
            _ => {
                return Err(error(
                    line,
                    t.column,
                    &a.name,
                    format!("index {index} (`{}`) has no value", a.name),
                ))
            }
        };
        given[index] = Some(v);
        k = k.saturating_add(2);
    }
    if let Some(extra) = tokens.get(k) {
        return Err(error(
            line,
            extra.column,
            "@data",
            format!(
                "expected the end of the line after the sparse row's `}}`, found `{}` (instance weights are not supported)",
                extra.shown()
            ),
        ));
    }
    let mut values = Vec::with_capacity(n);
    for (v, a) in given.into_iter().zip(attributes) {
        values.push(match v {
            Some(v) => v,
            None => Some(match &a.kind {
                ArffKind::Numeric => "0".to_string(),
                ArffKind::Nominal(declared) => match declared.first() {
                    Some(first) => first.clone(),
                    None => {
                        return Err(error(
                            line,
                            open,
                            &a.name,
                            format!(
                                "the sparse row leaves out `{}`, which reads as its first value, but the header declares none",
                                a.name
                            ),
                        ))
                    }
                },
                ArffKind::Date(format) if format == DEFAULT_DATE_FORMAT => {
                    "1970-01-01T00:00:00".to_string()
                }
                ArffKind::Date(format) => {
                    return Err(error(
                        line,
                        open,
                        &a.name,
                        format!(
                            "the sparse row leaves out date `{}` (Weka reads 1970-01-01 00:00:00 UTC), which is not written in its format `{format}` here: write the value",
                            a.name
                        ),
                    ))
                }
                ArffKind::String => WEKA_DUMMY_STRING.to_string(),
            }),
        });
    }
    Ok(ArffRow { line, values })
}

#[cfg(test)]
#[allow(clippy::arithmetic_side_effects, clippy::cast_possible_truncation)] // tests, not readers
mod tests {
    use super::*;

    fn words(line: &str) -> Vec<(Kind, String)> {
        match tokenize(line) {
            Ok(t) => t.into_iter().map(|t| (t.kind, t.text)).collect(),
            Err(e) => panic!("{}: {}", e.column, e.message),
        }
    }

    #[test]
    fn separators_are_commas_and_whitespace_in_any_mix() {
        let w = |s: &str| s.to_string();
        assert_eq!(
            words("a,\tb  ,, c\t\td % e, f"),
            [
                (Kind::Word, w("a")),
                (Kind::Word, w("b")),
                (Kind::Word, w("c")),
                (Kind::Word, w("d"))
            ]
        );
        assert_eq!(
            words(r#"'it''s' "a\tb" 'q\'' '\101\0' x{y}"#),
            [
                (Kind::Quoted, w("it")),
                (Kind::Quoted, w("s")),
                (Kind::Quoted, w("a\tb")),
                (Kind::Quoted, w("q'")),
                (Kind::Quoted, w("A\0")),
                (Kind::Word, w("x")),
                (Kind::Open, w("{")),
                (Kind::Word, w("y")),
                (Kind::Close, w("}")),
            ]
        );
        // Octal: three digits only when the first is at most 3 (Java's rule).
        assert_eq!(words(r"'\477'"), [(Kind::Quoted, w("'7"))]);
    }

    #[test]
    fn content_says_arff() {
        assert!(is_arff_text("% a comment\n\n  @RELATION x\n"));
        assert!(is_arff_text("\u{feff}@relation 'a b'\n"));
        assert!(!is_arff_text("{\"format\":\"demoplan-recording\"}\n"));
        assert!(!is_arff_text("% only comments\n"));
        assert!(!is_arff_text("@relationship x\n"));
    }
}
