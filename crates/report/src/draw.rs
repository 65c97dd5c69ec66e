//! The drawing model: a [`Figure`] is a canvas size and a list of [`Shape`]s in pixel
//! coordinates (origin top left, y down), drawn in order. It renders to SVG text here;
//! the PNG is that SVG rendered (`render`), so the two agree.

use std::fmt::Write as _;

use crate::render::{self, RenderError, ADVANCE_EM};

/// An opaque sRGB colour.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct Color(pub u8, pub u8, pub u8);

impl Color {
    pub const WHITE: Color = Color(255, 255, 255);
    pub const BLACK: Color = Color(0, 0, 0);
    pub const GREY: Color = Color(120, 120, 120);
    pub const LIGHT: Color = Color(225, 225, 225);

    /// `#rrggbb`.
    pub fn hex(self) -> String {
        format!("#{:02x}{:02x}{:02x}", self.0, self.1, self.2)
    }
}

/// A point in figure pixels.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Point {
    pub x: f64,
    pub y: f64,
}

/// Shorthand for a [`Point`].
pub fn pt(x: f64, y: f64) -> Point {
    Point { x, y }
}

/// How a line is drawn: colour, width in pixels, and an optional dash pattern
/// (dash length, gap length).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Stroke {
    pub color: Color,
    pub width: f64,
    pub dash: Option<(f64, f64)>,
}

impl Stroke {
    /// A solid line.
    pub fn solid(color: Color, width: f64) -> Stroke {
        Stroke {
            color,
            width,
            dash: None,
        }
    }

    /// A dashed line.
    pub fn dashed(color: Color, width: f64, dash: f64, gap: f64) -> Stroke {
        Stroke {
            color,
            width,
            dash: Some((dash, gap)),
        }
    }
}

/// Where a text's reference point lies on its baseline.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Anchor {
    Start,
    Middle,
    End,
}

/// A text label at an integer `scale`: set in a monospace font of size `10 * scale`
/// pixels, in PNGs always the embedded DejaVu Sans Mono (see [`text_width`]).
#[derive(Debug, Clone, PartialEq)]
pub struct Text {
    /// Reference point on the baseline (see `anchor`).
    pub at: Point,
    pub text: String,
    pub scale: u32,
    pub anchor: Anchor,
    pub color: Color,
    pub bold: bool,
    /// Rotated by -90 degrees (reads bottom to top), about `at`.
    pub vertical: bool,
}

/// One drawing primitive.
#[derive(Debug, Clone, PartialEq)]
pub enum Shape {
    Line {
        from: Point,
        to: Point,
        stroke: Stroke,
    },
    Polyline {
        points: Vec<Point>,
        stroke: Stroke,
    },
    /// `at` is the top left corner; `size` the width and height.
    Rect {
        at: Point,
        size: (f64, f64),
        fill: Option<Color>,
        stroke: Option<Stroke>,
    },
    /// A filled polygon without outline (a quartile band).
    Polygon {
        points: Vec<Point>,
        fill: Color,
    },
    Circle {
        center: Point,
        r: f64,
        fill: Option<Color>,
        stroke: Option<Stroke>,
    },
    Text(Text),
}

/// A figure drawn once and rendered both ways: [`Figure::svg`] and [`Figure::png`].
/// Rendering is deterministic: the same figure gives the same bytes.
#[derive(Debug, Clone, PartialEq)]
pub struct Figure {
    width: u32,
    height: u32,
    title: String,
    shapes: Vec<Shape>,
}

impl Figure {
    /// An empty white canvas of `width` x `height` pixels; `title` becomes the SVG's
    /// `<title>` (its accessible name).
    pub fn new(width: u32, height: u32, title: &str) -> Figure {
        Figure {
            width: width.max(1),
            height: height.max(1),
            title: title.to_string(),
            shapes: Vec::new(),
        }
    }

    pub fn width(&self) -> u32 {
        self.width
    }

    pub fn height(&self) -> u32 {
        self.height
    }

    pub fn title(&self) -> &str {
        &self.title
    }

    pub fn shapes(&self) -> &[Shape] {
        &self.shapes
    }

    /// Adds a shape on top of the others.
    pub fn push(&mut self, shape: Shape) {
        self.shapes.push(shape);
    }

    pub fn line(&mut self, from: Point, to: Point, stroke: Stroke) {
        self.push(Shape::Line { from, to, stroke });
    }

    pub fn polyline(&mut self, points: Vec<Point>, stroke: Stroke) {
        self.push(Shape::Polyline { points, stroke });
    }

    pub fn rect(
        &mut self,
        x: f64,
        y: f64,
        w: f64,
        h: f64,
        fill: Option<Color>,
        stroke: Option<Stroke>,
    ) {
        let (at, size) = (pt(x, y), (w, h));
        self.push(Shape::Rect {
            at,
            size,
            fill,
            stroke,
        });
    }

    pub fn polygon(&mut self, points: Vec<Point>, fill: Color) {
        self.push(Shape::Polygon { points, fill });
    }

    pub fn circle(&mut self, center: Point, r: f64, fill: Option<Color>, stroke: Option<Stroke>) {
        self.push(Shape::Circle {
            center,
            r,
            fill,
            stroke,
        });
    }

    /// A horizontal, regular-weight label.
    pub fn text(&mut self, at: Point, text: &str, scale: u32, anchor: Anchor, color: Color) {
        self.push(Shape::Text(Text {
            at,
            text: text.to_string(),
            scale: scale.max(1),
            anchor,
            color,
            bold: false,
            vertical: false,
        }));
    }

    /// Any label (bold, vertical).
    pub fn label(&mut self, text: Text) {
        self.push(Shape::Text(text));
    }

    /// The figure as a standalone SVG document.
    pub fn svg(&self) -> String {
        let mut s = String::new();
        let (w, h) = (self.width, self.height);
        let _ = writeln!(s, r#"<?xml version="1.0" encoding="UTF-8"?>"#);
        let _ = writeln!(
            s,
            r#"<svg xmlns="http://www.w3.org/2000/svg" width="{w}" height="{h}" viewBox="0 0 {w} {h}" font-family="DejaVu Sans Mono, Menlo, Consolas, monospace">"#
        );
        let _ = writeln!(s, "<title>{}</title>", escape(&self.title));
        let _ = writeln!(
            s,
            r##"<rect x="0" y="0" width="{w}" height="{h}" fill="#ffffff"/>"##
        );
        for shape in &self.shapes {
            svg_shape(&mut s, shape);
        }
        s.push_str("</svg>\n");
        s
    }

    /// The figure's SVG rendered with the embedded font (anti-aliased) and encoded as an
    /// RGB PNG of `width` x `height` pixels.
    pub fn png(&self) -> Result<Vec<u8>, RenderError> {
        let rgb = render::rgb(&self.svg(), self.width, self.height)?;
        render::encode_png(self.width, self.height, &rgb)
    }
}

/// Width in figure pixels of `text` at `scale`: the embedded font's advance per
/// character, for the layout of labels.
pub fn text_width(text: &str, scale: u32) -> f64 {
    text.chars().count() as f64 * f64::from(10 * scale.max(1)) * ADVANCE_EM
}

/// Escapes text for XML content and double-quoted attributes; characters XML 1.0 does
/// not allow (control characters other than tab and line breaks) become U+FFFD, so that
/// every figure's SVG is well-formed whatever its labels hold.
pub fn escape(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        match c {
            '\t' | '\n' | '\r' => out.push(c),
            c if c.is_control() || c == '\u{fffe}' || c == '\u{ffff}' => out.push('\u{fffd}'),
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            _ => out.push(c),
        }
    }
    out
}

/// A coordinate with at most two decimals and no trailing zeros (`12`, `3.5`, `-0.25`).
pub(crate) fn num(x: f64) -> String {
    if !x.is_finite() {
        return "0".to_string();
    }
    let mut s = format!("{x:.2}");
    if s.contains('.') {
        while s.ends_with('0') {
            s.pop();
        }
        if s.ends_with('.') {
            s.pop();
        }
    }
    if s == "-0" {
        s = "0".to_string();
    }
    s
}

fn stroke_attrs(stroke: &Stroke) -> String {
    let mut s = format!(
        r#" stroke="{}" stroke-width="{}""#,
        stroke.color.hex(),
        num(stroke.width)
    );
    if let Some((dash, gap)) = stroke.dash {
        let _ = write!(s, r#" stroke-dasharray="{} {}""#, num(dash), num(gap));
    }
    s
}

fn fill_attr(fill: Option<Color>) -> String {
    match fill {
        Some(c) => format!(r#" fill="{}""#, c.hex()),
        None => r#" fill="none""#.to_string(),
    }
}

/// The `points` attribute's value: `x,y` pairs separated by spaces.
fn points_attr(points: &[Point]) -> String {
    let pts: Vec<String> = points
        .iter()
        .map(|p| format!("{},{}", num(p.x), num(p.y)))
        .collect();
    pts.join(" ")
}

fn svg_shape(s: &mut String, shape: &Shape) {
    match shape {
        Shape::Line { from, to, stroke } => {
            let _ = writeln!(
                s,
                r#"<line x1="{}" y1="{}" x2="{}" y2="{}"{} stroke-linecap="round"/>"#,
                num(from.x),
                num(from.y),
                num(to.x),
                num(to.y),
                stroke_attrs(stroke)
            );
        }
        Shape::Polyline { points, stroke } => {
            let _ = writeln!(
                s,
                r#"<polyline points="{}" fill="none"{} stroke-linejoin="round" stroke-linecap="round"/>"#,
                points_attr(points),
                stroke_attrs(stroke)
            );
        }
        Shape::Polygon { points, fill } => {
            let _ = writeln!(
                s,
                r#"<polygon points="{}" fill="{}" stroke="none"/>"#,
                points_attr(points),
                fill.hex()
            );
        }
        Shape::Rect {
            at,
            size: (w, h),
            fill,
            stroke,
        } => {
            let _ = writeln!(
                s,
                r#"<rect x="{}" y="{}" width="{}" height="{}"{}{}/>"#,
                num(at.x),
                num(at.y),
                num(*w),
                num(*h),
                fill_attr(*fill),
                stroke.as_ref().map(stroke_attrs).unwrap_or_default()
            );
        }
        Shape::Circle {
            center,
            r,
            fill,
            stroke,
        } => {
            let _ = writeln!(
                s,
                r#"<circle cx="{}" cy="{}" r="{}"{}{}/>"#,
                num(center.x),
                num(center.y),
                num(*r),
                fill_attr(*fill),
                stroke.as_ref().map(stroke_attrs).unwrap_or_default()
            );
        }
        Shape::Text(t) => {
            let anchor = match t.anchor {
                Anchor::Start => "start",
                Anchor::Middle => "middle",
                Anchor::End => "end",
            };
            let mut attrs = format!(
                r#"x="{}" y="{}" font-size="{}" text-anchor="{}" fill="{}""#,
                num(t.at.x),
                num(t.at.y),
                10 * t.scale.max(1),
                anchor,
                t.color.hex()
            );
            if t.bold {
                attrs.push_str(r#" font-weight="bold""#);
            }
            if t.vertical {
                let _ = write!(
                    attrs,
                    r#" transform="rotate(-90 {} {})""#,
                    num(t.at.x),
                    num(t.at.y)
                );
            }
            let _ = writeln!(s, "<text {attrs}>{}</text>", escape(&t.text));
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_are_short_and_stable() {
        assert_eq!(num(12.0), "12");
        assert_eq!(num(3.5), "3.5");
        assert_eq!(num(-0.001), "0");
        assert_eq!(num(1.239), "1.24");
        assert_eq!(num(f64::NAN), "0");
    }

    #[test]
    fn text_is_escaped() {
        assert_eq!(escape(r#"a<b & "c">"#), "a&lt;b &amp; &quot;c&quot;&gt;");
        assert_eq!(
            escape("a\u{1}b\u{7f}\u{fffe}"),
            "a\u{fffd}b\u{fffd}\u{fffd}"
        );
    }
}
