//! The findings text: what a set of results says about slimming, written from the
//! records alone (so a results file gives the same text on any machine).

use report::{format_seconds, Measure, Planner, Ratio};

use crate::cell::LevelChoice;
use crate::ratio::ratio;
use crate::record::RunRecord;

/// The record whose search time is the median of `records` (the lower middle one).
pub(crate) fn median_record<'a>(records: &[&'a RunRecord]) -> Option<&'a RunRecord> {
    let mut sorted = records.to_vec();
    sorted.sort_by(|a, b| a.times.search_s.total_cmp(&b.times.search_s));
    sorted.get(sorted.len().saturating_sub(1) / 2).copied()
}

fn ratio_words(r: Option<Ratio>) -> String {
    r.map_or("none".to_string(), |r| r.to_string())
}

fn seconds(r: &RunRecord, measure: Measure) -> String {
    let t = format_seconds(r.times.get(measure));
    if r.hit_limit() {
        format!("more than {t} s (limit)")
    } else {
        format!("{t} s")
    }
}

/// "0.5 s of search", or why there is no search time.
fn search_words(r: &RunRecord) -> String {
    if r.time(Measure::Search).is_none() && r.hit_limit() {
        "no search time (the limit came before the search expanded a state)".to_string()
    } else {
        format!("{} of search", seconds(r, Measure::Search))
    }
}

/// Findings for the tallest goal of `records`, per planner: the full domain against
/// priority 1 (`ratio_p1`) and against Algorithm 1's cumulative time (`ratio_alg1`),
/// both by search and by total time, beside the paper's; what the full domain's time
/// is made of; Algorithm 1's widening where priority 1 does not plan; and the
/// execution check over every plan.
pub fn findings(records: &[RunRecord]) -> Vec<String> {
    let mut notes = Vec::new();
    let Some(height) = records.iter().map(|r| r.conditions.height).max() else {
        return notes;
    };
    let mut planners: Vec<Planner> = records.iter().map(|r| r.planner).collect();
    planners.sort_unstable();
    planners.dedup();
    for planner in planners {
        let of = |pick: &dyn Fn(&RunRecord) -> bool| -> Option<&RunRecord> {
            let chosen: Vec<&RunRecord> = records
                .iter()
                .filter(|r| r.planner == planner && r.conditions.height == height && pick(r))
                .collect();
            median_record(&chosen)
        };
        let domain_levels =
            |r: &RunRecord| matches!(r.level, LevelChoice::Prio(_) | LevelChoice::Full);
        let largest = records
            .iter()
            .filter(|r| r.planner == planner && r.conditions.height == height && domain_levels(r))
            .map(|r| r.prio)
            .max();
        let full = largest.and_then(|p| of(&|r| domain_levels(r) && r.prio == p));
        let p1 = of(&|r| r.level == LevelChoice::Prio(1));
        let alg1 = of(&|r| r.level == LevelChoice::Algorithm1);
        let label = planner.label();
        let paper_ratio = planner.paper_ratio();
        let Some(full) = full else { continue };
        let mut text = format!(
            "{label}, towers of {height} cubes: the largest domain (priority {}, {} \
             operators) takes {} and {} in total",
            full.prio,
            full.operators,
            search_words(full),
            seconds(full, Measure::Total)
        );
        match p1 {
            Some(p1) if p1.solved() && full.prio != 1 => text.push_str(&format!(
                "; priority 1 ({} operators) {} and {}. ratio_p1 = {} by search time, {} by \
                 total time (the paper: {paper_ratio:.0}, search time)",
                p1.operators,
                seconds(p1, Measure::Search),
                seconds(p1, Measure::Total),
                ratio_words(ratio(full, p1, Measure::Search)),
                ratio_words(ratio(full, p1, Measure::Total)),
            )),
            Some(p1) if full.prio != 1 => text.push_str(&format!(
                "; priority 1 ({} operators) gives no plan ({}), so ratio_p1 is undefined",
                p1.operators, p1.outcome
            )),
            _ => {}
        }
        text.push('.');
        notes.push(text);
        if let Some(a) = alg1 {
            let tried: Vec<String> = a
                .widening
                .iter()
                .map(|w| {
                    format!(
                        "priority {} ({} operators): {}, {} s",
                        w.prio,
                        w.operators,
                        w.outcome,
                        format_seconds(w.times.total_s)
                    )
                })
                .collect();
            let planned = if a.solved() {
                format!("plans at priority {}", a.prio)
            } else {
                format!("gives no plan ({})", a.outcome)
            };
            notes.push(format!(
                "{label}: Algorithm 1 {planned} after {} level(s) [{}], cumulatively {} of \
                 search and {} in total: ratio_alg1 = {} by search time, {} by total time.",
                a.widening.len(),
                tried.join("; "),
                seconds(a, Measure::Search),
                seconds(a, Measure::Total),
                ratio_words(ratio(full, a, Measure::Search)),
                ratio_words(ratio(full, a, Measure::Total)),
            ));
        }
        let t = full.times;
        if t.total_s > 0.0 {
            let share = |x: f64| format!("{:.0}%", 100.0 * x / t.total_s);
            let mut drive = format!(
                "{label}: the largest domain's total time is {} heuristic construction, {} \
                 translation and {} search",
                share(t.heuristic_s),
                share(t.translate_s),
                share(t.search_s)
            );
            if let Some(p1) = p1.filter(|p| p.solved()) {
                if let (Some(cf), Some(cp)) = (full.cost, p1.cost) {
                    if cf < cp {
                        drive.push_str(&format!(
                            "; its extra operators allow cheaper plans (cost {cf} against \
                             {cp}), which the optimal search must prove optimal"
                        ));
                    }
                }
                if let (Some(ef), Some(ep)) = (full.expansions, p1.expansions) {
                    drive.push_str(&format!(
                        "; it expands {ef} states against priority 1's {ep}"
                    ));
                }
            }
            drive.push('.');
            notes.push(drive);
        }
    }
    let solved: Vec<&RunRecord> = records.iter().filter(|r| r.solved()).collect();
    let failed = solved.iter().filter(|r| r.executed == Some(false)).count();
    let unchecked = solved.iter().filter(|r| r.executed.is_none()).count();
    if !solved.is_empty() {
        let mut text = if failed == 0 {
            format!(
                "All {} plans found executed successfully in the cube world",
                solved.len()
            )
        } else {
            format!(
                "{failed} of {} plans failed the execution check in the cube world",
                solved.len()
            )
        };
        if unchecked > 0 {
            text.push_str(&format!(" ({unchecked} could not be run there at all)"));
        }
        text.push('.');
        notes.push(text);
    }
    notes
}
