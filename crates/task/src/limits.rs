//! The time and memory limits of one planning run, shared by every phase that honours
//! them: translation (grounding, invariant synthesis, reachability), heuristic
//! construction and search. Each phase checks them cooperatively, at points where it can
//! stop cleanly, and reports a [`Limit`] as its outcome: reaching a limit is a result,
//! not an error. A caller may also cancel a run from another thread (the Python
//! package's Ctrl-C) through a flag that the phases check wherever they check the
//! deadline.

use std::sync::atomic::{AtomicBool, Ordering};
use std::time::{Duration, Instant};

/// When to give up. The default has no limits.
#[derive(Debug, Clone, Copy, Default)]
pub struct Limits {
    /// Stop with [`Limit::Time`] once this instant has passed.
    pub deadline: Option<Instant>,
    /// Stop with [`Limit::Memory`] once memory use exceeds this many bytes, and do not
    /// start an allocation that an estimate says would exceed it.
    pub memory_limit_bytes: Option<u64>,
    /// The process's memory use in bytes (e.g. a counting allocator's reading). Without
    /// it a phase counts the bytes of its own main structures, which leaves out
    /// everything else.
    pub memory_usage: Option<fn() -> u64>,
    /// Stop with [`Limit::Cancelled`] once this flag is set (by another thread). A
    /// `'static` reference keeps `Limits` `Copy`; the Python extension keeps a pool of
    /// flags for its runs.
    pub cancel: Option<&'static AtomicBool>,
}

/// The deadline with the cancel flag: the stop of a phase that watches only the clock
/// (clique enumeration and pruning, which keep what they found when it comes).
#[derive(Debug, Clone, Copy, Default)]
pub struct Deadline {
    /// The instant to stop at; `None` is no deadline.
    pub at: Option<Instant>,
    /// The run's cancel flag ([`Limits::cancel`]).
    pub cancel: Option<&'static AtomicBool>,
}

impl Deadline {
    /// A deadline alone, with no cancel flag.
    pub fn at(at: Option<Instant>) -> Deadline {
        Deadline { at, cancel: None }
    }

    /// True once the flag is set or the instant has passed.
    pub fn passed(&self) -> bool {
        self.cancel.is_some_and(|flag| flag.load(Ordering::Relaxed))
            || self.at.is_some_and(|d| Instant::now() >= d)
    }

    /// The same stop, with the instant `other` where that comes first.
    pub fn or_earlier(self, other: Option<Instant>) -> Deadline {
        let at = match (self.at, other) {
            (Some(a), Some(b)) => Some(a.min(b)),
            (a, b) => a.or(b),
        };
        Deadline { at, ..self }
    }
}

/// A limit that was reached.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Limit {
    /// The deadline passed.
    Time,
    /// Memory use exceeded the limit, or would have.
    Memory,
    /// The caller cancelled the run ([`Limits::cancel`]).
    Cancelled,
}

impl std::fmt::Display for Limit {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(match self {
            Limit::Time => "time limit",
            Limit::Memory => "memory limit",
            Limit::Cancelled => "cancellation",
        })
    }
}

/// The deadline `limit` after `start`, or `None` ("no limit") when there is no limit or
/// the instant cannot be represented (a limit of centuries, `1e20` seconds): no run
/// lasts that long, so such a limit is no limit. Never panics.
pub fn deadline_after(start: Instant, limit: Option<Duration>) -> Option<Instant> {
    limit.and_then(|l| start.checked_add(l))
}

impl Limits {
    /// Memory in use as the probe reads it, or `own_bytes` without a probe.
    pub fn memory_in_use(&self, own_bytes: impl FnOnce() -> u64) -> u64 {
        match self.memory_usage {
            Some(read) => read(),
            None => own_bytes(),
        }
    }

    /// The deadline and the cancel flag, for phases that watch only the clock.
    pub fn clock(&self) -> Deadline {
        Deadline {
            at: self.deadline,
            cancel: self.cancel,
        }
    }

    /// True once the caller has set the cancel flag.
    pub fn cancelled(&self) -> bool {
        self.cancel.is_some_and(|flag| flag.load(Ordering::Relaxed))
    }

    /// The time-like limit reached now, if any: cancellation, then the deadline. What a
    /// phase that watches only the clock checks.
    pub fn out_of_time(&self) -> Option<Limit> {
        if self.cancelled() {
            return Some(Limit::Cancelled);
        }
        self.deadline
            .is_some_and(|d| Instant::now() >= d)
            .then_some(Limit::Time)
    }

    /// The limit reached now, if any: cancellation first, then the deadline, then
    /// memory (see [`memory_in_use`](Self::memory_in_use)).
    pub fn reached(&self, own_bytes: impl FnOnce() -> u64) -> Option<Limit> {
        if let Some(limit) = self.out_of_time() {
            return Some(limit);
        }
        let limit = self.memory_limit_bytes?;
        (self.memory_in_use(own_bytes) > limit).then_some(Limit::Memory)
    }

    /// True if allocating `bytes` more on top of what is in use would exceed the memory
    /// limit: the check made before a large allocation whose size is known in advance.
    pub fn would_exceed(&self, bytes: u64, own_bytes: impl FnOnce() -> u64) -> bool {
        self.memory_limit_bytes
            .is_some_and(|limit| self.memory_in_use(own_bytes).saturating_add(bytes) > limit)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn no_limits_are_never_reached() {
        let limits = Limits::default();
        assert_eq!(limits.reached(|| u64::MAX), None);
        assert!(!limits.would_exceed(u64::MAX, || u64::MAX));
    }

    #[test]
    fn a_past_deadline_is_reached_before_memory() {
        let limits = Limits {
            deadline: Some(Instant::now()),
            memory_limit_bytes: Some(0),
            ..Limits::default()
        };
        assert_eq!(limits.reached(|| 1), Some(Limit::Time));
    }

    #[test]
    fn a_set_cancel_flag_is_reached_before_everything_else() {
        static FLAG: AtomicBool = AtomicBool::new(false);
        let limits = Limits {
            deadline: Some(Instant::now()),
            memory_limit_bytes: Some(0),
            cancel: Some(&FLAG),
            ..Limits::default()
        };
        assert_eq!(limits.reached(|| 1), Some(Limit::Time));
        assert!(!limits.cancelled());
        FLAG.store(true, Ordering::Relaxed);
        assert!(limits.cancelled());
        assert_eq!(limits.reached(|| 1), Some(Limit::Cancelled));
        assert_eq!(limits.out_of_time(), Some(Limit::Cancelled));
        // A clock-only phase sees the flag too.
        let later = Some(Instant::now() + Duration::from_secs(3600));
        let clock = Limits {
            deadline: later,
            ..limits
        }
        .clock();
        assert!(clock.passed());
        assert!(!Deadline::at(later).passed());
        assert!(Deadline::at(later)
            .or_earlier(Some(Instant::now()))
            .passed());
    }

    #[test]
    fn memory_is_read_from_the_probe_when_there_is_one() {
        fn probe() -> u64 {
            1000
        }
        let own = Limits {
            memory_limit_bytes: Some(500),
            ..Limits::default()
        };
        assert_eq!(own.reached(|| 400), None);
        assert_eq!(own.reached(|| 501), Some(Limit::Memory));
        assert!(own.would_exceed(101, || 400));
        assert!(!own.would_exceed(100, || 400));
        assert!(own.would_exceed(u64::MAX, || 400), "no overflow");
        let probed = Limits {
            memory_usage: Some(probe),
            ..own
        };
        assert_eq!(probed.reached(|| 0), Some(Limit::Memory));
    }

    #[test]
    fn deadlines_too_far_away_mean_no_limit() {
        let now = Instant::now();
        assert_eq!(deadline_after(now, None), None);
        assert_eq!(deadline_after(now, Some(Duration::MAX)), None);
        assert_eq!(
            deadline_after(now, Some(Duration::from_secs(1))),
            Some(now + Duration::from_secs(1))
        );
    }
}
