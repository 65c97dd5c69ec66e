//! Slimming ratios between runs, and their quartiles when some runs hit their limit.
//!
//! - `ratio_p1`: the full domain's time over priority 1's.
//! - `ratio_alg1`: the full domain's time over Algorithm 1's cumulative time (failed
//!   levels included, the paper's own argument).
//!
//! Both by search time and by total time ([`Measure`]). A run that hit its limit only
//! says that its time is at least what it used, so a ratio with it in the numerator is
//! a lower bound (`>=`), in the denominator an upper bound (`<=`); with both, nothing is
//! known and there is no ratio.
//!
//! **Censored quartiles.** The quartiles of a list of ratios, some of them bounds, are
//! computed twice: once with every bound at its least possible value (a lower bound at
//! its value, an upper bound at 0) and once at its greatest (a lower bound at +infinity,
//! an upper bound at its value). A quartile (linear interpolation between order
//! statistics) grows with every value, so the true quartile lies between the two. When
//! they agree the quartile is exact; when the greatest is finite it is reported as an
//! upper bound (`<=` that value); else, when the least is positive, as a lower bound
//! (`>=`); else it is unknown. So a median that falls on runs at the limit is itself
//! reported as a bound, never as a number it might not be.

use report::{Bound, Measure, Ratio};

use crate::record::RunRecord;

/// `numerator`'s time over `denominator`'s by `measure`, a bound when either hit its
/// limit; `None` when either has no time (no plan exists in its domain, an error), both
/// hit their limit, or the denominator is zero.
pub fn ratio(numerator: &RunRecord, denominator: &RunRecord, measure: Measure) -> Option<Ratio> {
    let (n, nb) = numerator.time(measure)?;
    let (d, db) = denominator.time(measure)?;
    if d <= 0.0 || !n.is_finite() || !d.is_finite() {
        return None;
    }
    let bound = match (nb, db) {
        (Bound::Exact, Bound::Exact) => Bound::Exact,
        (Bound::AtLeast, Bound::Exact) => Bound::AtLeast,
        (Bound::Exact, Bound::AtLeast) => Bound::AtMost,
        _ => return None,
    };
    Some(Ratio {
        value: n / d,
        bound,
    })
}

/// The first quartile, median and third quartile of ratios that may be bounds, and how
/// many there were and how many of them were bounds.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Quartiles {
    pub n: usize,
    pub bounds: usize,
    pub q1: Option<Ratio>,
    pub median: Option<Ratio>,
    pub q3: Option<Ratio>,
}

/// The quartiles of `values`, censored as the module says.
pub fn quartiles(values: &[Ratio]) -> Quartiles {
    let mut least: Vec<f64> = values
        .iter()
        .map(|r| match r.bound {
            Bound::AtMost => 0.0,
            _ => r.value,
        })
        .collect();
    let mut greatest: Vec<f64> = values
        .iter()
        .map(|r| match r.bound {
            Bound::AtLeast => f64::INFINITY,
            _ => r.value,
        })
        .collect();
    least.sort_by(f64::total_cmp);
    greatest.sort_by(f64::total_cmp);
    let at = |p: f64| -> Option<Ratio> {
        let lo = quantile(&least, p)?;
        let hi = quantile(&greatest, p)?;
        if lo == hi {
            Some(Ratio {
                value: lo,
                bound: Bound::Exact,
            })
        } else if hi.is_finite() {
            Some(Ratio {
                value: hi,
                bound: Bound::AtMost,
            })
        } else if lo > 0.0 {
            Some(Ratio {
                value: lo,
                bound: Bound::AtLeast,
            })
        } else {
            None
        }
    };
    Quartiles {
        n: values.len(),
        bounds: values.iter().filter(|r| r.bound != Bound::Exact).count(),
        q1: at(0.25),
        median: at(0.5),
        q3: at(0.75),
    }
}

/// The `p`-quantile of sorted values by linear interpolation between order statistics
/// (R's type 7); +infinity stays +infinity.
fn quantile(sorted: &[f64], p: f64) -> Option<f64> {
    let last = sorted.len().checked_sub(1)?;
    let h = last as f64 * p;
    let i = h.floor() as usize;
    let f = h - i as f64;
    let a = sorted[i];
    let Some(&b) = sorted.get(i + 1) else {
        return Some(a);
    };
    if f == 0.0 || a == b {
        Some(a)
    } else if b.is_infinite() {
        Some(f64::INFINITY)
    } else {
        Some(a + f * (b - a))
    }
}

/// A ratio as CSV and tables write it: `12.5`, `>=12.5`, `<=12.5`, or empty.
pub fn ratio_text(r: Option<Ratio>) -> String {
    match r {
        None => String::new(),
        Some(r) => {
            let prefix = match r.bound {
                Bound::Exact => "",
                Bound::AtLeast => ">=",
                Bound::AtMost => "<=",
            };
            format!("{prefix}{:.4}", r.value)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn exact(v: f64) -> Ratio {
        Ratio {
            value: v,
            bound: Bound::Exact,
        }
    }

    fn at_least(v: f64) -> Ratio {
        Ratio {
            value: v,
            bound: Bound::AtLeast,
        }
    }

    fn at_most(v: f64) -> Ratio {
        Ratio {
            value: v,
            bound: Bound::AtMost,
        }
    }

    #[test]
    fn exact_quartiles_interpolate() {
        let q = quartiles(&[exact(4.0), exact(1.0), exact(3.0), exact(2.0), exact(5.0)]);
        assert_eq!(
            (q.q1, q.median, q.q3),
            (Some(exact(2.0)), Some(exact(3.0)), Some(exact(4.0)))
        );
        let q = quartiles(&[exact(1.0), exact(2.0)]);
        assert_eq!(q.median, Some(exact(1.5)));
        assert_eq!(quartiles(&[]).median, None);
    }

    #[test]
    fn lower_bounds_above_the_median_leave_it_exact() {
        // Two of five seeds hit the limit on the full domain: they order last, and the
        // median is the third exact value.
        let q = quartiles(&[
            exact(2.0),
            at_least(50.0),
            exact(3.0),
            at_least(9.0),
            exact(1.0),
        ]);
        assert_eq!(q.median, Some(exact(3.0)));
        assert_eq!(q.q1, Some(exact(2.0)));
        // The third quartile falls on a censored run: at least its bound.
        assert_eq!(q.q3, Some(at_least(9.0)));
        assert_eq!(q.bounds, 2);
    }

    #[test]
    fn a_median_on_censored_runs_is_a_bound() {
        let q = quartiles(&[at_least(20.0), at_least(30.0), exact(5.0)]);
        assert_eq!(q.median, Some(at_least(20.0)));
        let q = quartiles(&[at_most(0.5), at_most(0.2), exact(5.0)]);
        assert_eq!(q.median, Some(at_most(0.5)));
        // Bounds both ways: the median of a <= 0.5 and b >= 30 is at least 15.
        let q = quartiles(&[at_most(0.5), at_least(30.0)]);
        assert_eq!(q.median, Some(at_least(15.0)));
    }

    #[test]
    fn ratio_text_marks_bounds() {
        assert_eq!(ratio_text(Some(at_least(12.5))), ">=12.5000");
        assert_eq!(ratio_text(Some(exact(3.0))), "3.0000");
        assert_eq!(ratio_text(None), "");
    }
}
