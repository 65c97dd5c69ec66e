//! Cooperative checks of the run's limits ([`task::Limits`]) inside translation's loops.
//!
//! Grounding, invariant synthesis and reachability call [`Watch::tick`] once per unit of
//! work (a binding, an atom, an action, a candidate invariant); every 1,024 ticks it
//! reads the clock and the memory probe. Once a limit is reached the watch stays
//! stopped, every later tick says so, and each loop returns at once, so that translation
//! ends within a few microseconds of the limit with nothing half-built handed on.

use std::cell::Cell;

use task::{Limit, Limits};

/// How many ticks between two readings of the clock and the memory probe.
const CHECK_EVERY: u32 = 1024;

/// The limits of one translation and whether one has been reached.
#[derive(Debug)]
pub(crate) struct Watch<'l> {
    limits: &'l Limits,
    ticks: Cell<u32>,
    stopped: Cell<Option<Limit>>,
}

impl<'l> Watch<'l> {
    pub(crate) fn new(limits: &'l Limits) -> Watch<'l> {
        Watch {
            limits,
            ticks: Cell::new(0),
            stopped: Cell::new(None),
        }
    }

    /// Counts one unit of work; true if a limit has been reached (now or before). Memory
    /// is read only through the limits' probe: translation does not count its own bytes.
    pub(crate) fn tick(&self) -> bool {
        if self.stopped.get().is_some() {
            return true;
        }
        let ticks = self.ticks.get().wrapping_add(1);
        self.ticks.set(ticks);
        if !ticks.is_multiple_of(CHECK_EVERY) {
            return false;
        }
        self.check()
    }

    /// Reads the limits now (at the end of a phase); true if one has been reached.
    pub(crate) fn check(&self) -> bool {
        if self.stopped.get().is_none() {
            self.stopped.set(self.limits.reached(|| 0));
        }
        self.stopped.get().is_some()
    }

    /// True if allocating `bytes` more would exceed the memory limit (then the watch
    /// stops at it), or a limit has been reached already: the check before a large
    /// allocation.
    pub(crate) fn would_exceed(&self, bytes: u64) -> bool {
        if !self.check() && self.limits.would_exceed(bytes, || 0) {
            self.stopped.set(Some(Limit::Memory));
        }
        self.stopped.get().is_some()
    }

    /// The limit reached, if one was.
    pub(crate) fn stopped(&self) -> Option<Limit> {
        self.stopped.get()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::time::Instant;

    #[test]
    fn a_watch_stops_within_one_interval_of_the_limit_and_stays_stopped() {
        let limits = Limits {
            deadline: Some(Instant::now()),
            ..Limits::default()
        };
        let watch = Watch::new(&limits);
        let ticks = (1..=CHECK_EVERY).take_while(|_| !watch.tick()).count();
        assert_eq!(ticks as u32, CHECK_EVERY - 1);
        assert!(watch.tick());
        assert_eq!(watch.stopped(), Some(Limit::Time));
        let free = Limits::default();
        let watch = Watch::new(&free);
        assert!(!(0..10 * CHECK_EVERY).any(|_| watch.tick()));
        assert!(!watch.check());
    }
}
