//! A tiny case-insensitive glob matcher for entity names: `*` matches any run of
//! characters, `?` any one character, everything else itself. Names are short, so the
//! simple backtracking below is linear enough; no character classes are needed for names.

// A reader of untrusted input (issue 23): no arithmetic that can wrap or panic, no
// cast that can truncate; each such operation is checked, saturating or proved in range.
#![deny(clippy::arithmetic_side_effects, clippy::cast_possible_truncation)]

/// Whether `name` matches `pattern`, ignoring ASCII case.
pub fn matches(pattern: &str, name: &str) -> bool {
    let p: Vec<char> = pattern.chars().map(|c| c.to_ascii_lowercase()).collect();
    let n: Vec<char> = name.chars().map(|c| c.to_ascii_lowercase()).collect();
    let (mut pi, mut ni) = (0, 0);
    // Where the last `*` was, and the name position it matched up to.
    let mut star: Option<(usize, usize)> = None;
    while ni < n.len() {
        // Positions are below the lengths of `p` and `n`: adding one cannot wrap.
        if pi < p.len() && (p[pi] == '?' || p[pi] == n[ni]) {
            pi = pi.saturating_add(1);
            ni = ni.saturating_add(1);
        } else if pi < p.len() && p[pi] == '*' {
            star = Some((pi, ni));
            pi = pi.saturating_add(1);
        } else if let Some((sp, sn)) = star {
            pi = sp.saturating_add(1);
            ni = sn.saturating_add(1);
            star = Some((sp, ni));
        } else {
            return false;
        }
    }
    p[pi..].iter().all(|&c| c == '*')
}

#[cfg(test)]
#[allow(clippy::arithmetic_side_effects, clippy::cast_possible_truncation)] // tests, not readers
mod tests {
    use super::matches;

    #[test]
    fn stars_questions_and_case() {
        for (pattern, name, expected) in [
            ("*cube*", "3DPrintedCube_red", true),
            ("*cube*", "Table_1", false),
            ("*controller_l*", "VR_Controller_L", true),
            ("*controller_l*", "VR_Controller_R", false),
            ("table_?", "Table_1", true),
            ("table_?", "Table_12", false),
            ("*", "", true),
            ("a*b*c", "axxbyyc", true),
            ("a*b*c", "axxbyy", false),
            ("exact", "exact", true),
            ("exact", "exactly", false),
        ] {
            assert_eq!(matches(pattern, name), expected, "{pattern} vs {name}");
        }
    }
}
