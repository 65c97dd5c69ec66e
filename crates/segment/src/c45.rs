//! Quinlan's C4.5 for nominal attributes: splits by gain ratio, unknown values spread
//! over the branches by weight, and pessimistic pruning with a confidence factor.

use crate::tree::{Attribute, DecisionTree, Node};

/// Labelled cases to learn from.
#[derive(Debug, Clone, PartialEq)]
pub struct Dataset {
    /// The attributes (nominal).
    pub attributes: Vec<Attribute>,
    /// Name of the class.
    pub class_name: String,
    /// The classes.
    pub classes: Vec<String>,
    /// The cases.
    pub cases: Vec<Case>,
}

/// One labelled case.
#[derive(Debug, Clone, PartialEq)]
pub struct Case {
    /// Per attribute, the index of its value, `None` when unknown.
    pub values: Vec<Option<usize>>,
    /// Index of the class.
    pub class: usize,
    /// Weight (1 for an ordinary case).
    pub weight: f64,
}

/// C4.5's settings, Quinlan's defaults by [`Default`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct C45 {
    /// Confidence factor of pruning (0.25); smaller prunes more.
    pub confidence: f64,
    /// Least (weighted) cases in at least two branches of a split (2).
    pub min_cases: f64,
    /// Prune after growing.
    pub prune: bool,
}

impl Default for C45 {
    fn default() -> Self {
        C45 {
            confidence: 0.25,
            min_cases: 2.0,
            prune: true,
        }
    }
}

/// Gains within this of the average count as average (C4.5's `Epsilon`).
const EPSILON: f64 = 1e-3;

impl C45 {
    /// Grows a tree on the dataset and prunes it.
    ///
    /// At a node: if every case has one class or there are fewer than twice `min_cases`,
    /// a leaf; else, among the attributes not tested above whose split leaves at least
    /// two branches with `min_cases`, those with at least the average information gain,
    /// the one with the highest gain ratio. Cases with an unknown value go down every
    /// branch with their weight shared in proportion to the known cases. Pruning
    /// (subtree replacement) turns a subtree into a leaf when the leaf's pessimistic
    /// error estimate (the upper limit of the binomial confidence interval at
    /// `confidence`) is no worse than the subtree's. Subtree raising is not done.
    ///
    /// Cost: O(attributes^2 x cases) for growing in the worst case.
    pub fn learn(&self, data: &Dataset) -> DecisionTree {
        let cases: Vec<(usize, f64)> = data
            .cases
            .iter()
            .enumerate()
            .map(|(i, c)| (i, c.weight))
            .collect();
        let mut used = vec![false; data.attributes.len()];
        let mut root = self.grow(data, &cases, &mut used, None);
        if self.prune {
            self.prune(data, &mut root, &cases);
        }
        DecisionTree {
            attributes: data.attributes.clone(),
            class_name: data.class_name.clone(),
            classes: data.classes.clone(),
            root,
        }
    }

    fn grow(
        &self,
        data: &Dataset,
        cases: &[(usize, f64)],
        used: &mut Vec<bool>,
        parent_class: Option<usize>,
    ) -> Node {
        let counts = class_counts(data, cases);
        let total: f64 = counts.iter().sum();
        let (class, best) = majority(&counts, parent_class);
        let leaf = Node::Leaf {
            class,
            cases: total,
            errors: total - best,
        };
        if total < 2.0 * self.min_cases || best >= total - 1e-9 {
            return leaf;
        }
        // Per candidate attribute: gain and gain ratio.
        let mut candidates = Vec::new();
        for (a, attribute) in data.attributes.iter().enumerate() {
            if used[a] {
                continue;
            }
            let nv = attribute.values.len();
            let mut per_value = vec![vec![0.0; data.classes.len()]; nv];
            let mut unknown = 0.0;
            for &(i, w) in cases {
                let c = &data.cases[i];
                match c.values.get(a).copied().flatten() {
                    Some(v) if v < nv => per_value[v][c.class] += w,
                    _ => unknown += w,
                }
            }
            let known = total - unknown;
            if known <= 0.0 {
                continue;
            }
            let sizes: Vec<f64> = per_value.iter().map(|c| c.iter().sum()).collect();
            if sizes.iter().filter(|&&s| s >= self.min_cases).count() < 2 {
                continue;
            }
            let mut known_counts = vec![0.0; data.classes.len()];
            for c in &per_value {
                for (k, x) in known_counts.iter_mut().zip(c) {
                    *k += x;
                }
            }
            let after: f64 = per_value
                .iter()
                .zip(&sizes)
                .map(|(c, &s)| s / known * entropy(c))
                .sum();
            let gain = known / total * (entropy(&known_counts) - after);
            let mut parts = sizes.clone();
            parts.push(unknown);
            let split_info = entropy(&parts);
            if gain <= 0.0 || split_info <= 0.0 {
                continue;
            }
            candidates.push((a, gain, gain / split_info));
        }
        if candidates.is_empty() {
            return leaf;
        }
        let average = candidates.iter().map(|c| c.1).sum::<f64>() / candidates.len() as f64;
        let mut chosen: Option<(usize, f64)> = None;
        for &(a, gain, ratio) in &candidates {
            if gain >= average - EPSILON && chosen.is_none_or(|(_, r)| ratio > r) {
                chosen = Some((a, ratio));
            }
        }
        let Some((a, _)) = chosen else {
            return leaf;
        };
        let nv = data.attributes[a].values.len();
        let (subsets, sizes) = split_cases(data, cases, a, nv);
        let default = sizes
            .iter()
            .enumerate()
            .fold(0, |best, (v, &s)| if s > sizes[best] { v } else { best });
        used[a] = true;
        let branches = subsets
            .iter()
            .map(|s| {
                if s.is_empty() {
                    Node::Leaf {
                        class,
                        cases: 0.0,
                        errors: 0.0,
                    }
                } else {
                    self.grow(data, s, used, Some(class))
                }
            })
            .collect();
        used[a] = false;
        Node::Split {
            attribute: a,
            branches,
            default,
        }
    }

    /// Prunes bottom-up; returns the estimated errors of what is left.
    fn prune(&self, data: &Dataset, node: &mut Node, cases: &[(usize, f64)]) -> f64 {
        let counts = class_counts(data, cases);
        let total: f64 = counts.iter().sum();
        let Node::Split {
            attribute,
            branches,
            ..
        } = node
        else {
            if let Node::Leaf { class, .. } = node {
                let errors = total - counts.get(*class).copied().unwrap_or(0.0);
                return errors + add_errors(total, errors, self.confidence);
            }
            return 0.0;
        };
        let a = *attribute;
        let nv = branches.len();
        let (subsets, _) = split_cases(data, cases, a, nv);
        let subtree: f64 = branches
            .iter_mut()
            .zip(&subsets)
            .map(|(b, s)| self.prune(data, b, s))
            .sum();
        let (class, best) = majority(&counts, None);
        let errors = total - best;
        let as_leaf = errors + add_errors(total, errors, self.confidence);
        if as_leaf <= subtree + 0.1 {
            *node = Node::Leaf {
                class,
                cases: total,
                errors,
            };
            as_leaf
        } else {
            subtree
        }
    }
}

/// The weighted `cases` split by their value of attribute `a` (of `nv` values), as C4.5
/// splits them: a case whose value is unknown goes into every subset, its weight scaled
/// by that subset's share of the known weight (into none if no case is known). Returns
/// the subsets and the known weight of each.
fn split_cases(
    data: &Dataset,
    cases: &[(usize, f64)],
    a: usize,
    nv: usize,
) -> (Vec<Vec<(usize, f64)>>, Vec<f64>) {
    let mut subsets: Vec<Vec<(usize, f64)>> = vec![Vec::new(); nv];
    let mut unknown = Vec::new();
    for &(i, w) in cases {
        match data.cases[i].values.get(a).copied().flatten() {
            Some(v) if v < nv => subsets[v].push((i, w)),
            _ => unknown.push((i, w)),
        }
    }
    let sizes: Vec<f64> = subsets
        .iter()
        .map(|s| s.iter().map(|c| c.1).sum())
        .collect();
    let known: f64 = sizes.iter().sum();
    if known > 0.0 {
        for (subset, &size) in subsets.iter_mut().zip(&sizes) {
            let share = size / known;
            if share > 0.0 {
                subset.extend(unknown.iter().map(|&(i, w)| (i, w * share)));
            }
        }
    }
    (subsets, sizes)
}

fn class_counts(data: &Dataset, cases: &[(usize, f64)]) -> Vec<f64> {
    let mut counts = vec![0.0; data.classes.len()];
    for &(i, w) in cases {
        if let Some(c) = counts.get_mut(data.cases[i].class) {
            *c += w;
        }
    }
    counts
}

/// The most frequent class and its count; ties go to `prefer`, then to the first.
fn majority(counts: &[f64], prefer: Option<usize>) -> (usize, f64) {
    let mut best = (
        prefer.unwrap_or(0),
        prefer.and_then(|p| counts.get(p)).copied().unwrap_or(-1.0),
    );
    for (c, &n) in counts.iter().enumerate() {
        if n > best.1 + 1e-12 {
            best = (c, n);
        }
    }
    (best.0, best.1.max(0.0))
}

/// Entropy (bits) of a distribution given by counts.
fn entropy(counts: &[f64]) -> f64 {
    let total: f64 = counts.iter().sum();
    if total <= 0.0 {
        return 0.0;
    }
    counts
        .iter()
        .filter(|&&c| c > 0.0)
        .map(|&c| {
            let p = c / total;
            -p * p.log2()
        })
        .sum()
}

/// C4.5's `AddErrs`: the errors to add to `e` observed among `n` cases so that the total
/// is the upper limit of the confidence interval at `cf` (a binomial bound, with the
/// normal approximation for `e >= 1`, as in Quinlan's code).
pub fn add_errors(n: f64, e: f64, cf: f64) -> f64 {
    if n <= 0.0 {
        return 0.0;
    }
    if e < 1e-6 {
        return n * (1.0 - (cf.ln() / n).exp());
    }
    if e < 0.9999 {
        let v = n * (1.0 - (cf.ln() / n).exp());
        return v + e * (add_errors(n, 1.0, cf) - v);
    }
    if e + 0.5 >= n {
        return 0.67 * (n - e);
    }
    let z = deviation(cf);
    let coeff = z * z;
    let pr = (e
        + 0.5
        + coeff / 2.0
        + (coeff * ((e + 0.5) * (1.0 - (e + 0.5) / n) + coeff / 4.0)).sqrt())
        / (n + coeff);
    n * pr - e
}

/// The normal deviate for a one-sided confidence `cf`, interpolated in C4.5's table.
fn deviation(cf: f64) -> f64 {
    const VAL: [f64; 9] = [0.0, 0.001, 0.005, 0.01, 0.05, 0.10, 0.20, 0.40, 1.00];
    const DEV: [f64; 9] = [4.0, 3.09, 2.58, 2.33, 1.65, 1.28, 0.84, 0.25, 0.00];
    let mut i = 0;
    while i + 1 < VAL.len() && cf > VAL[i] {
        i += 1;
    }
    if i == 0 {
        return DEV[0];
    }
    DEV[i - 1] + (DEV[i] - DEV[i - 1]) * (cf - VAL[i - 1]) / (VAL[i] - VAL[i - 1])
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn quinlans_error_bounds() {
        // C4.5 at CF = 0.25 (Quinlan 1993, section 4.2): U(0, 6) = 0.206, so a leaf of
        // 6 cases with no error counts as 6 x 0.206 errors; U(1, 16) = 0.157, so one of
        // 16 cases with one error counts as 16 x 0.157 = 2.5.
        let e = add_errors(6.0, 0.0, 0.25);
        assert!((e - 6.0 * 0.206).abs() < 0.01, "{e}");
        let e = 1.0 + add_errors(16.0, 1.0, 0.25);
        assert!((e - 2.5).abs() < 0.2, "{e}");
        assert!((deviation(0.25) - 0.6925).abs() < 1e-9);
    }
}
