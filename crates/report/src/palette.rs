//! The two categorical palettes the figures draw from, each written once; a figure's own
//! colour list picks from them by index, so that the colours of one name are the same
//! wherever they appear.

use crate::Color;

/// Okabe and Ito's eight colours, readable by people with colour-blindness and printed
/// grey: black, orange, sky blue, bluish green, yellow, blue, vermillion, reddish purple.
pub const OKABE_ITO: [Color; 8] = rgb([
    0x000000, 0xe69f00, 0x56b4e9, 0x009e73, 0xf0e442, 0x0072b2, 0xd55e00, 0xcc79a7,
]);

/// Tableau's ten colours (matplotlib's `tab10`): blue, orange, green, red, purple, brown,
/// pink, grey, olive, cyan.
pub const TABLEAU10: [Color; 10] = rgb([
    0x1f77b4, 0xff7f0e, 0x2ca02c, 0xd62728, 0x9467bd, 0x8c564b, 0xe377c2, 0x7f7f7f, 0xbcbd22,
    0x17becf,
]);

/// Colours from their hex codes (`0xRRGGBB`), as the palettes are published.
const fn rgb<const N: usize>(hex: [u32; N]) -> [Color; N] {
    let mut out = [Color(0, 0, 0); N];
    let mut i = 0;
    while i < N {
        let [_, r, g, b] = hex[i].to_be_bytes();
        out[i] = Color(r, g, b);
        i += 1;
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn hex_codes_are_read_as_red_green_blue() {
        assert_eq!(OKABE_ITO[1], Color(230, 159, 0));
        assert_eq!(TABLEAU10[9], Color(23, 190, 207));
    }
}
