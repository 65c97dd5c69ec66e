//! The default memory limit per run (`--memory-limit auto` of `solve`, `reproduce` and
//! `study`): what the machine can give, shared by the runs at once.

/// The memory available when this is called (`MemAvailable` of `/proc/meminfo`: what
/// the system can give to new work without swapping), divided by `runs_at_once`, so
/// that runs side by side stop themselves at their limits before the kernel would kill
/// one; `None` (no limit) where the system does not say. A fixed default would be more
/// than a small machine has; the whole machine would count what other programs hold.
pub fn auto_memory_limit(runs_at_once: usize) -> Option<u64> {
    let meminfo = std::fs::read_to_string("/proc/meminfo").ok()?;
    let runs = u64::try_from(runs_at_once.max(1)).unwrap_or(u64::MAX);
    mem_available(&meminfo).map(|bytes| bytes / runs)
}

/// `MemAvailable` of a `/proc/meminfo` text, in bytes.
fn mem_available(meminfo: &str) -> Option<u64> {
    let line = meminfo.lines().find(|l| l.starts_with("MemAvailable:"))?;
    let kib: u64 = line.split_whitespace().nth(1)?.parse().ok()?;
    kib.checked_mul(1024)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn mem_available_is_read_in_bytes() {
        let meminfo = "MemTotal:        8000000 kB\nMemFree:          100000 kB\n\
                       MemAvailable:     4000000 kB\nBuffers:           1000 kB\n";
        assert_eq!(mem_available(meminfo), Some(4_000_000 * 1024));
        assert_eq!(mem_available("MemTotal: 8000000 kB\n"), None);
        assert_eq!(mem_available("MemAvailable: lots kB\n"), None);
        assert_eq!(
            mem_available("MemAvailable: 99999999999999999999 kB\n"),
            None
        );
    }

    #[test]
    fn the_machine_is_shared_by_the_runs_at_once() {
        if let (Some(one), Some(four)) = (auto_memory_limit(1), auto_memory_limit(4)) {
            // Read twice, the available memory may have moved a little in between.
            assert!(four < one, "{four} {one}");
        }
        assert_eq!(
            auto_memory_limit(0).is_some(),
            auto_memory_limit(1).is_some()
        );
    }
}
