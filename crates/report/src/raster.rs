//! The rasteriser: shapes into an RGB pixel buffer, without anti-aliasing.
//!
//! A pixel is inked when its centre lies inside the shape (half-open on the right and
//! bottom edges, so that a 1-pixel line at an integer coordinate inks one column).
//! Lines of any width are filled quadrilaterals, so a line at least one pixel wide
//! never has gaps; wide lines get round caps and joins. Text is the bitmap font of
//! `font`, each font pixel a `scale` x `scale` block.

use crate::draw::{Anchor, Color, Point, Shape, Stroke, Text};
use crate::font;

/// An RGB image, row-major, three bytes per pixel.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Canvas {
    width: u32,
    height: u32,
    pixels: Vec<u8>,
}

impl Canvas {
    /// A canvas filled with `background`.
    pub fn new(width: u32, height: u32, background: Color) -> Canvas {
        let n = width as usize * height as usize;
        let mut pixels = Vec::with_capacity(n * 3);
        for _ in 0..n {
            pixels.extend_from_slice(&[background.0, background.1, background.2]);
        }
        Canvas {
            width,
            height,
            pixels,
        }
    }

    pub fn width(&self) -> u32 {
        self.width
    }

    pub fn height(&self) -> u32 {
        self.height
    }

    /// Row-major RGB bytes.
    pub fn pixels(&self) -> &[u8] {
        &self.pixels
    }

    /// The colour at `(x, y)`, if inside.
    pub fn get(&self, x: u32, y: u32) -> Option<Color> {
        if x >= self.width || y >= self.height {
            return None;
        }
        let i = (y as usize * self.width as usize + x as usize) * 3;
        Some(Color(
            self.pixels[i],
            self.pixels[i + 1],
            self.pixels[i + 2],
        ))
    }

    fn set(&mut self, x: i64, y: i64, c: Color) {
        if x < 0 || y < 0 || x >= i64::from(self.width) || y >= i64::from(self.height) {
            return;
        }
        let i = (y as usize * self.width as usize + x as usize) * 3;
        self.pixels[i] = c.0;
        self.pixels[i + 1] = c.1;
        self.pixels[i + 2] = c.2;
    }

    /// Pixels of row `py` whose centres lie in `[xa, xb)`.
    fn span(&mut self, py: i64, xa: f64, xb: f64, c: Color) {
        if py < 0 || py >= i64::from(self.height) || xb <= xa {
            return;
        }
        let first = ((xa - 0.5).ceil() as i64).max(0);
        let last = ((xb - 0.5).ceil() as i64 - 1).min(i64::from(self.width) - 1);
        for px in first..=last {
            self.set(px, py, c);
        }
    }

    /// Rows whose centres lie in `[ya, yb)`, clipped to the canvas.
    fn rows(&self, ya: f64, yb: f64) -> std::ops::Range<i64> {
        let first = ((ya - 0.5).ceil() as i64).max(0);
        let end = ((yb - 0.5).ceil() as i64).min(i64::from(self.height));
        first..end.max(first)
    }

    /// Fills a polygon (even-odd rule) by scanlines through pixel centres.
    pub fn fill_polygon(&mut self, points: &[Point], c: Color) {
        if points.len() < 3 || points.iter().any(|p| !p.x.is_finite() || !p.y.is_finite()) {
            return;
        }
        let ymin = points.iter().map(|p| p.y).fold(f64::INFINITY, f64::min);
        let ymax = points.iter().map(|p| p.y).fold(f64::NEG_INFINITY, f64::max);
        let mut xs: Vec<f64> = Vec::with_capacity(8);
        for py in self.rows(ymin, ymax) {
            let yc = py as f64 + 0.5;
            xs.clear();
            for i in 0..points.len() {
                let a = points[i];
                let b = points[(i + 1) % points.len()];
                if (a.y <= yc && b.y > yc) || (b.y <= yc && a.y > yc) {
                    xs.push(a.x + (yc - a.y) * (b.x - a.x) / (b.y - a.y));
                }
            }
            xs.sort_by(f64::total_cmp);
            for pair in xs.chunks_exact(2) {
                self.span(py, pair[0], pair[1], c);
            }
        }
    }

    /// Fills the disc of radius `r` about `center`.
    pub fn fill_circle(&mut self, center: Point, r: f64, c: Color) {
        if r.is_nan() || r <= 0.0 {
            return;
        }
        for py in self.rows(center.y - r, center.y + r) {
            let dy = py as f64 + 0.5 - center.y;
            let half = (r * r - dy * dy).max(0.0).sqrt();
            self.span(py, center.x - half, center.x + half, c);
        }
    }

    fn ring(&mut self, center: Point, r: f64, width: f64, c: Color) {
        let outer = r + width / 2.0;
        let inner = (r - width / 2.0).max(0.0);
        for py in self.rows(center.y - outer, center.y + outer) {
            let dy = py as f64 + 0.5 - center.y;
            let ho = (outer * outer - dy * dy).max(0.0).sqrt();
            if dy.abs() >= inner {
                self.span(py, center.x - ho, center.x + ho, c);
            } else {
                let hi = (inner * inner - dy * dy).max(0.0).sqrt();
                self.span(py, center.x - ho, center.x - hi, c);
                self.span(py, center.x + hi, center.x + ho, c);
            }
        }
    }

    fn segment(&mut self, a: Point, b: Point, width: f64, c: Color) {
        let w = width.max(1.0);
        let (dx, dy) = (b.x - a.x, b.y - a.y);
        let len = (dx * dx + dy * dy).sqrt();
        if len.is_nan() || len <= 1e-9 {
            self.fill_circle(a, w / 2.0, c);
            return;
        }
        let (nx, ny) = (-dy / len * w / 2.0, dx / len * w / 2.0);
        let quad = [
            Point {
                x: a.x + nx,
                y: a.y + ny,
            },
            Point {
                x: b.x + nx,
                y: b.y + ny,
            },
            Point {
                x: b.x - nx,
                y: b.y - ny,
            },
            Point {
                x: a.x - nx,
                y: a.y - ny,
            },
        ];
        self.fill_polygon(&quad, c);
        if w >= 2.5 {
            self.fill_circle(a, w / 2.0, c);
            self.fill_circle(b, w / 2.0, c);
        }
    }

    /// Strokes a path, continuing the dash pattern across its vertices.
    fn path(&mut self, points: &[Point], stroke: &Stroke) {
        let Some((dash, gap)) = stroke.dash.filter(|(d, g)| *d > 0.0 && *g >= 0.0) else {
            for pair in points.windows(2) {
                self.segment(pair[0], pair[1], stroke.width, stroke.color);
            }
            return;
        };
        let mut on = true;
        let mut left = dash;
        for pair in points.windows(2) {
            let (a, b) = (pair[0], pair[1]);
            let len = ((b.x - a.x).powi(2) + (b.y - a.y).powi(2)).sqrt();
            let mut t = 0.0;
            while t < len {
                let step = left.min(len - t);
                if on {
                    let p = |s: f64| Point {
                        x: a.x + (b.x - a.x) * s / len,
                        y: a.y + (b.y - a.y) * s / len,
                    };
                    self.segment(p(t), p(t + step), stroke.width, stroke.color);
                }
                t += step;
                left -= step;
                if left <= 1e-9 {
                    on = !on;
                    left = if on { dash } else { gap.max(1e-3) };
                }
            }
        }
    }

    fn text(&mut self, t: &Text) {
        let scale = t.scale.max(1);
        let s = i64::from(scale);
        let width = f64::from(font::text_width(&t.text) * scale);
        let offset = match t.anchor {
            Anchor::Start => 0.0,
            Anchor::Middle => width / 2.0,
            Anchor::End => width,
        };
        let ox = t.at.x.round() as i64;
        let oy = t.at.y.round() as i64;
        let start = -(offset.round() as i64);
        let top = -i64::from(font::CAP_HEIGHT) * s;
        for (i, ch) in t.text.chars().enumerate() {
            let gx = start + i as i64 * i64::from(font::ADVANCE) * s;
            for (row, bits) in font::glyph(ch).iter().enumerate() {
                for col in 0..font::GLYPH_WIDTH {
                    if bits & (1 << (4 - col)) == 0 {
                        continue;
                    }
                    let bx = gx + i64::from(col) * s;
                    let by = top + row as i64 * s;
                    let extra = i64::from(t.bold);
                    for u in 0..(s + extra) {
                        for v in 0..s {
                            // (u, v): along the text and down from the baseline.
                            let (along, down) = (bx + u, by + v);
                            if t.vertical {
                                self.set(ox + down, oy - along - 1, t.color);
                            } else {
                                self.set(ox + along, oy + down, t.color);
                            }
                        }
                    }
                }
            }
        }
    }

    /// Draws one shape on top of what is there.
    pub fn draw(&mut self, shape: &Shape) {
        match shape {
            Shape::Line { from, to, stroke } => self.path(&[*from, *to], stroke),
            Shape::Polyline { points, stroke } => {
                self.path(points, stroke);
                if stroke.width >= 2.5 && stroke.dash.is_none() {
                    for p in points.iter().skip(1).take(points.len().saturating_sub(2)) {
                        self.fill_circle(*p, stroke.width / 2.0, stroke.color);
                    }
                }
            }
            Shape::Rect {
                x,
                y,
                w,
                h,
                fill,
                stroke,
            } => {
                if let Some(c) = fill {
                    for py in self.rows(*y, y + h) {
                        self.span(py, *x, x + w, *c);
                    }
                }
                if let Some(st) = stroke {
                    let corners = [
                        Point { x: *x, y: *y },
                        Point { x: x + w, y: *y },
                        Point { x: x + w, y: y + h },
                        Point { x: *x, y: y + h },
                        Point { x: *x, y: *y },
                    ];
                    self.path(&corners, st);
                }
            }
            Shape::Polygon { points, fill } => self.fill_polygon(points, *fill),
            Shape::Circle {
                center,
                r,
                fill,
                stroke,
            } => {
                if let Some(c) = fill {
                    self.fill_circle(*center, *r, *c);
                }
                if let Some(st) = stroke {
                    self.ring(*center, *r, st.width.max(1.0), st.color);
                }
            }
            Shape::Text(t) => self.text(t),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::draw::pt;

    const RED: Color = Color(255, 0, 0);

    fn inked(c: &Canvas) -> usize {
        c.pixels()
            .chunks(3)
            .filter(|p| p != &[255, 255, 255])
            .count()
    }

    #[test]
    fn one_pixel_line_at_integer_coordinate_inks_one_column() {
        let mut c = Canvas::new(10, 10, Color::WHITE);
        c.draw(&Shape::Line {
            from: pt(5.0, 0.0),
            to: pt(5.0, 10.0),
            stroke: Stroke::solid(RED, 1.0),
        });
        assert_eq!(inked(&c), 10);
        assert_eq!(c.get(4, 3), Some(RED));
    }

    #[test]
    fn diagonal_line_has_no_gaps() {
        let mut c = Canvas::new(40, 40, Color::WHITE);
        c.draw(&Shape::Line {
            from: pt(0.0, 3.0),
            to: pt(40.0, 29.0),
            stroke: Stroke::solid(RED, 1.0),
        });
        for x in 0..40 {
            assert!((0..40).any(|y| c.get(x, y) == Some(RED)), "column {x}");
        }
    }

    #[test]
    fn rect_fill_covers_exactly_its_pixels() {
        let mut c = Canvas::new(10, 10, Color::WHITE);
        c.draw(&Shape::Rect {
            x: 2.0,
            y: 3.0,
            w: 4.0,
            h: 2.0,
            fill: Some(RED),
            stroke: None,
        });
        assert_eq!(inked(&c), 8);
        assert_eq!(c.get(2, 3), Some(RED));
        assert_eq!(c.get(6, 3), Some(Color::WHITE));
    }

    #[test]
    fn shapes_outside_the_canvas_are_clipped() {
        let mut c = Canvas::new(5, 5, Color::WHITE);
        c.fill_circle(pt(-50.0, -50.0), 20.0, RED);
        c.draw(&Shape::Line {
            from: pt(-100.0, 2.0),
            to: pt(100.0, 2.0),
            stroke: Stroke::dashed(RED, 3.0, 4.0, 2.0),
        });
        assert!(inked(&c) > 0);
    }

    #[test]
    fn text_inks_the_glyph_rows_above_the_baseline() {
        let mut c = Canvas::new(20, 20, Color::WHITE);
        c.draw(&Shape::Text(Text {
            at: pt(1.0, 10.0),
            text: "1".to_string(),
            scale: 1,
            anchor: Anchor::Start,
            color: RED,
            bold: false,
            vertical: false,
        }));
        // '1' has its top pixel in column 2, row 0 (y = 10 - 7).
        assert_eq!(c.get(3, 3), Some(RED));
        assert_eq!(c.get(3, 2), Some(Color::WHITE));
        assert_eq!(inked(&c), 10);
    }
}
