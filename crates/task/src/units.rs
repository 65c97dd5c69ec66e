//! Limits as users write them, in Fast Downward's units: `30s`, `5m`, `1h` or seconds for
//! time, `512M`, `3G` or bytes for memory, and `infinity` for none.

use std::time::Duration;

/// `30s`, `5m`, `1h`, `90` (seconds), `1e3`, `infinity`. A limit too large for a
/// `Duration` (over about 5.8e11 years, `1e20`) is no limit, as `infinity` is; negative,
/// NaN and infinite numbers are refused.
pub fn parse_time_limit(text: &str) -> Result<Option<Duration>, String> {
    let t = text.trim().to_ascii_lowercase();
    if t == "infinity" {
        return Ok(None);
    }
    let (number, unit) = match t.char_indices().last() {
        Some((i, 's')) => (&t[..i], 1.0),
        Some((i, 'm')) => (&t[..i], 60.0),
        Some((i, 'h')) => (&t[..i], 3600.0),
        _ => (t.as_str(), 1.0),
    };
    match number.parse::<f64>() {
        Ok(v) if v.is_finite() && v >= 0.0 => Ok(Duration::try_from_secs_f64(v * unit).ok()),
        _ => Err(format!(
            "invalid time limit `{text}`: expected e.g. 30s, 5m, 1h or infinity"
        )),
    }
}

/// `512M`, `3G`, `100K`, `1048576` (bytes), `infinity`; units are powers of 1024.
pub fn parse_memory_limit(text: &str) -> Result<Option<u64>, String> {
    let t = text.trim().to_ascii_lowercase();
    if t == "infinity" {
        return Ok(None);
    }
    let (number, unit) = match t.char_indices().last() {
        Some((i, 'k')) => (&t[..i], 1u64 << 10),
        Some((i, 'm')) => (&t[..i], 1 << 20),
        Some((i, 'g')) => (&t[..i], 1 << 30),
        _ => (t.as_str(), 1),
    };
    match number.parse::<u64>() {
        Ok(v) => v
            .checked_mul(unit)
            .map(Some)
            .ok_or_else(|| format!("memory limit `{text}` is too large")),
        Err(_) => Err(format!(
            "invalid memory limit `{text}`: expected e.g. 512M, 3G or infinity"
        )),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn time_limits_take_fast_downward_units() {
        assert_eq!(parse_time_limit("30s"), Ok(Some(Duration::from_secs(30))));
        assert_eq!(parse_time_limit("5m"), Ok(Some(Duration::from_secs(300))));
        assert_eq!(parse_time_limit("1h"), Ok(Some(Duration::from_secs(3600))));
        assert_eq!(parse_time_limit("90"), Ok(Some(Duration::from_secs(90))));
        assert_eq!(parse_time_limit("infinity"), Ok(None));
        assert!(parse_time_limit("10x").is_err());
        assert!(parse_time_limit("-1s").is_err());
        assert!(parse_time_limit("nan").is_err());
        assert!(parse_time_limit("inf").is_err());
        // Beyond what a deadline can be: no limit, never a panic.
        assert_eq!(parse_time_limit("1e20"), Ok(None));
        assert_eq!(parse_time_limit("1e300h"), Ok(None));
        assert_eq!(parse_time_limit("1e3"), Ok(Some(Duration::from_secs(1000))));
    }

    #[test]
    fn memory_limits_take_binary_units() {
        assert_eq!(parse_memory_limit("512M"), Ok(Some(512 << 20)));
        assert_eq!(parse_memory_limit("3G"), Ok(Some(3 << 30)));
        assert_eq!(parse_memory_limit("100k"), Ok(Some(100 << 10)));
        assert_eq!(parse_memory_limit("4096"), Ok(Some(4096)));
        assert!(parse_memory_limit("lots").is_err());
        assert!(parse_memory_limit("99999999999999999999G").is_err());
    }
}
