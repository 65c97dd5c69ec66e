//! The number lists of a study's options, as people write them: `1-20` (inclusive), `7`,
//! or `1,4,9`, each part a number or a range.

/// The numbers of `text`, sorted and without repeats. A part that is no number, an empty
/// range (`3-1`) or one of more than 100,001 numbers is an error that says so.
pub fn numbers(text: &str) -> Result<Vec<u64>, String> {
    let mut out = Vec::new();
    for part in text.split(',').map(str::trim) {
        let number = |t: &str| {
            t.trim()
                .parse::<u64>()
                .map_err(|_| format!("{t:?} is not a number (give e.g. 1-20, 3 or 1,4,9)"))
        };
        match part.split_once('-') {
            Some((a, b)) => {
                let (a, b) = (number(a)?, number(b)?);
                if a > b {
                    return Err(format!("the range {a}-{b} is empty"));
                }
                if b - a > 100_000 {
                    return Err(format!("the range {a}-{b} is too long"));
                }
                out.extend(a..=b);
            }
            None => out.push(number(part)?),
        }
    }
    out.sort_unstable();
    out.dedup();
    Ok(out)
}

/// [`numbers`] as sizes (counts of hands, cubes, towers).
pub fn sizes(text: &str) -> Result<Vec<usize>, String> {
    numbers(text)?
        .into_iter()
        .map(|n| usize::try_from(n).map_err(|_| format!("{n} is too large")))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lists_read_as_ranges_and_numbers() {
        assert_eq!(numbers("1-3"), Ok(vec![1, 2, 3]));
        assert_eq!(numbers("5, 1,2-3"), Ok(vec![1, 2, 3, 5]));
        assert_eq!(sizes("2-4,2"), Ok(vec![2, 3, 4]));
        assert_eq!(numbers("3-1"), Err("the range 3-1 is empty".to_string()));
        assert!(numbers("0-200000").is_err_and(|e| e.contains("too long")));
        for bad in ["x", "1-", ""] {
            assert!(
                numbers(bad).is_err_and(|e| e.contains("is not a number")),
                "{bad}"
            );
        }
    }
}
