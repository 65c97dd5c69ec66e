//! PNG figures: the figure's own SVG, rendered by resvg (usvg's tree, tiny-skia's
//! anti-aliased rasteriser) and encoded by the `png` crate.
//!
//! Text is set only in the embedded font, DejaVu Sans Mono 2.37 (`fonts/`, under the
//! Bitstream Vera and Arev licence in `fonts/LICENSE-DejaVu`): the font database holds that
//! one face and nothing else, and no system font is ever looked up, so a figure renders to
//! the same pixels on every machine. Bold labels are set in the same face: resvg matches
//! `font-weight="bold"` to the nearest weight the database has.

use std::sync::{Arc, OnceLock};

use resvg::tiny_skia::{Pixmap, Transform};
use resvg::usvg::{fontdb, Options, Tree};

/// The embedded font file.
pub(crate) const FONT: &[u8] = include_bytes!("../fonts/DejaVuSansMono.ttf");

/// The embedded font's family name, first in every figure's `font-family`.
pub(crate) const FONT_FAMILY: &str = "DejaVu Sans Mono";

/// Horizontal advance of every character of the embedded font, in ems (1233 of its 2048
/// units per em: the font is monospaced).
pub(crate) const ADVANCE_EM: f64 = 1233.0 / 2048.0;

/// Why a figure could not be rendered to PNG.
#[derive(Debug, thiserror::Error)]
pub enum RenderError {
    /// The figure's SVG was refused by the SVG parser.
    #[error("the figure's SVG could not be parsed: {0}")]
    Svg(String),
    /// The figure is too large for a pixel buffer.
    #[error("a figure of {width} x {height} pixels is too large to render")]
    Size { width: u32, height: u32 },
    /// The PNG encoder failed.
    #[error("the PNG encoder failed: {0}")]
    Png(String),
}

/// The font database: the embedded face only, also standing in for the generic families.
fn fonts() -> Arc<fontdb::Database> {
    static FONTS: OnceLock<Arc<fontdb::Database>> = OnceLock::new();
    FONTS
        .get_or_init(|| {
            let mut db = fontdb::Database::new();
            db.load_font_data(FONT.to_vec());
            db.set_monospace_family(FONT_FAMILY);
            db.set_sans_serif_family(FONT_FAMILY);
            db.set_serif_family(FONT_FAMILY);
            Arc::new(db)
        })
        .clone()
}

/// `svg` parsed into usvg's tree with text resolved against the embedded font only.
pub(crate) fn parse(svg: &str) -> Result<Tree, RenderError> {
    let options = Options {
        font_family: FONT_FAMILY.to_string(),
        fontdb: fonts(),
        ..Options::default()
    };
    Tree::from_str(svg, &options).map_err(|e| RenderError::Svg(e.to_string()))
}

/// `svg` rendered at its own size into RGB bytes (row-major, three bytes a pixel), on
/// white: the figures are opaque.
pub(crate) fn rgb(svg: &str, width: u32, height: u32) -> Result<Vec<u8>, RenderError> {
    let tree = parse(svg)?;
    let mut pixmap = Pixmap::new(width, height).ok_or(RenderError::Size { width, height })?;
    pixmap.fill(resvg::tiny_skia::Color::WHITE);
    resvg::render(&tree, Transform::identity(), &mut pixmap.as_mut());
    // On an opaque background premultiplied RGBA is plain RGBA with alpha 255.
    Ok(pixmap
        .data()
        .chunks_exact(4)
        .flat_map(|p| [p[0], p[1], p[2]])
        .collect())
}

/// RGB bytes of a `width` x `height` image encoded as an 8-bit RGB PNG, with fixed
/// settings, so that the same pixels give the same bytes.
pub(crate) fn encode_png(width: u32, height: u32, rgb: &[u8]) -> Result<Vec<u8>, RenderError> {
    let mut bytes = Vec::new();
    let mut encoder = png::Encoder::new(&mut bytes, width, height);
    encoder.set_color(png::ColorType::Rgb);
    encoder.set_depth(png::BitDepth::Eight);
    encoder.set_compression(png::Compression::Balanced);
    let mut writer = encoder
        .write_header()
        .map_err(|e| RenderError::Png(e.to_string()))?;
    writer
        .write_image_data(rgb)
        .map_err(|e| RenderError::Png(e.to_string()))?;
    writer
        .finish()
        .map_err(|e| RenderError::Png(e.to_string()))?;
    Ok(bytes)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_database_holds_the_embedded_face_alone() {
        let db = fonts();
        let families: Vec<String> = db
            .faces()
            .flat_map(|f| f.families.iter().map(|(name, _)| name.clone()))
            .collect();
        assert_eq!(families, [FONT_FAMILY]);
    }

    #[test]
    fn text_is_set_in_the_embedded_font_at_its_advance() {
        // Forty characters at 20 px: the text's outline spans about 40 advances, whatever
        // font-family the SVG asks for first (no other face exists to match it).
        let text = "0123456789abcdefghijklmnopqrstuvwxyzABCD";
        for family in ["DejaVu Sans Mono", "Helvetica", "monospace", "serif"] {
            let svg = format!(
                r#"<svg xmlns="http://www.w3.org/2000/svg" width="600" height="40"><text x="10" y="30" font-size="20" font-family="{family}">{text}</text></svg>"#
            );
            let tree = parse(&svg).unwrap_or_else(|e| panic!("{family}: {e}"));
            let bounds = tree.root().abs_bounding_box();
            let expected = 40.0 * 20.0 * ADVANCE_EM;
            // The ink starts a little after the first advance's start and ends before
            // the last one's end (side bearings), never more than one advance either way.
            let width = f64::from(bounds.width());
            assert!(
                (width - expected).abs() < 20.0 * ADVANCE_EM,
                "{family}: {width} against {expected}"
            );
        }
    }

    #[test]
    fn encoded_pixels_decode_unchanged() {
        let (w, h) = (7, 3);
        let rgb: Vec<u8> = (0..w * h * 3).map(|i| (i * 37 % 256) as u8).collect();
        let bytes = encode_png(w, h, &rgb).unwrap_or_else(|e| panic!("{e}"));
        let decoder = png::Decoder::new(std::io::Cursor::new(bytes));
        let mut reader = decoder.read_info().unwrap_or_else(|e| panic!("{e}"));
        let mut out = vec![0; reader.output_buffer_size().unwrap_or_default()];
        let info = reader
            .next_frame(&mut out)
            .unwrap_or_else(|e| panic!("{e}"));
        assert_eq!((info.width, info.height), (w, h));
        assert_eq!(info.color_type, png::ColorType::Rgb);
        assert_eq!(&out[..info.buffer_size()], &rgb[..]);
    }

    #[test]
    fn a_figure_with_characters_xml_forbids_is_an_error_not_a_panic() {
        let svg = "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"10\" height=\"10\"><text>\u{1}</text></svg>";
        assert!(matches!(rgb(svg, 10, 10), Err(RenderError::Svg(_))));
    }
}
