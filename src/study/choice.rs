//! The rule that chooses among candidate models on calibration rows (SPEC.md section 7), fixed
//! before it is applied: what the rows can tell apart, and what they cannot.
//!
//! Each candidate brings the held-out error of every calibration row (its prediction by the fit
//! made without the row's group, a string, minus the measured value) and its cost. Its score is
//! the RMS of those errors. Few groups make a score uncertain, so each score gets a 90 %
//! bootstrap interval over the groups: a replicate draws as many groups as there are, with
//! replacement, and scores every candidate on the rows of the groups drawn (each as often as it
//! was drawn). With `n` groups there are `n^n` equally likely draws, all of them enumerated
//! while `n^n` <= [`EXACT_UP_TO`] (3 strings: 27 draws); above that [`DRAWS`] draws from a fixed
//! seed. The interval runs between the 5 % and 95 % quantiles of the replicates (linear
//! between order statistics, Hyndman and Fan's type 7).
//!
//! The rule: the best candidate is the one with the least score; every candidate whose interval
//! overlaps the best's is **tied** with it (the rows cannot tell them apart); of the tied ones
//! the **cheapest** is chosen: the fewest fitted parameters, then the fewest mechanisms, then
//! the least score. A candidate without a score (a held-out error that is not finite) is
//! ranked last and never chosen.

/// The confidence level of the bootstrap intervals.
pub const LEVEL: f64 = 0.90;
/// The most draws enumerated exactly (`n^n` for `n` groups).
pub const EXACT_UP_TO: u64 = 200_000;
/// The draws of a sampled bootstrap (above [`EXACT_UP_TO`]).
pub const DRAWS: usize = 20_000;

/// What a candidate costs, compared field by field in this order: fewer is cheaper.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
pub struct Cost {
    /// The parameters fitted.
    pub fitted: usize,
    /// The mechanisms of its law on top of the elastic one.
    pub mechanisms: usize,
}

/// One calibration row's held-out error under a candidate.
#[derive(Debug, Clone, PartialEq)]
pub struct HeldOut {
    /// The row's group (its string).
    pub group: String,
    /// Its prediction without its group, minus the measured value.
    pub error: f64,
}

/// A candidate: its cost and the held-out error of every calibration row.
#[derive(Debug, Clone, PartialEq)]
pub struct Candidate {
    /// Its cost.
    pub cost: Cost,
    /// The held-out errors, one per calibration row (the same rows, in the same groups, for
    /// every candidate).
    pub rows: Vec<HeldOut>,
}

/// A candidate's place in the ranking.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Ranked {
    /// Its index among the candidates.
    pub index: usize,
    /// Its score: the RMS of its held-out errors (NaN if one is not finite).
    pub score: f64,
    /// The 90 % bootstrap interval of the score.
    pub interval: (f64, f64),
    /// Whether its interval overlaps the best candidate's (the best is tied with itself).
    pub tie: bool,
    /// Whether the rule chooses it.
    pub chosen: bool,
}

/// The ranking: every candidate, least score first.
#[derive(Debug, Clone, PartialEq)]
pub struct Ranking {
    /// The candidates, least score first (those without a score last, in their order).
    pub ranked: Vec<Ranked>,
    /// The groups, in the order of their first row.
    pub groups: Vec<String>,
    /// The replicates of the bootstrap.
    pub draws: usize,
    /// Whether every draw was enumerated (else sampled from a fixed seed).
    pub exact: bool,
}

impl Ranking {
    /// The chosen candidate's entry (`None` if no candidate has a score).
    pub fn chosen(&self) -> Option<&Ranked> {
        self.ranked.iter().find(|r| r.chosen)
    }

    /// The entry of candidate `index`.
    pub fn of(&self, index: usize) -> Option<&Ranked> {
        self.ranked.iter().find(|r| r.index == index)
    }
}

/// Rank `candidates` and choose by the rule of this module. An error if they do not share
/// their rows' groups.
pub fn rank(candidates: &[Candidate]) -> crate::error::Result<Ranking> {
    let mut groups: Vec<String> = Vec::new();
    if let Some(first) = candidates.first() {
        for r in &first.rows {
            if !groups.contains(&r.group) {
                groups.push(r.group.clone());
            }
        }
    }
    for (i, c) in candidates.iter().enumerate() {
        let same = c.rows.len() == candidates[0].rows.len()
            && c.rows.iter().zip(&candidates[0].rows).all(|(a, b)| a.group == b.group);
        if !same {
            return Err(crate::error::Error::invalid(
                "candidates",
                i,
                "every candidate must bring the same calibration rows, in the same groups",
            ));
        }
    }
    // each candidate's squared errors and row counts per group
    let per_group: Vec<Vec<(f64, f64)>> = candidates
        .iter()
        .map(|c| {
            groups
                .iter()
                .map(|g| {
                    let e: Vec<f64> = c.rows.iter().filter(|r| &r.group == g).map(|r| r.error).collect();
                    (e.iter().map(|x| x * x).sum(), e.len() as f64)
                })
                .collect()
        })
        .collect();
    let score_of = |sums: &[(f64, f64)], counts: &[usize]| -> f64 {
        let (mut s, mut n) = (0.0, 0.0);
        for (&(sq, rows), &k) in sums.iter().zip(counts) {
            s += k as f64 * sq;
            n += k as f64 * rows;
        }
        (s / n).sqrt()
    };
    let ones = vec![1usize; groups.len()];
    let scores: Vec<f64> = per_group.iter().map(|g| score_of(g, &ones)).collect();
    // the draws: counts of each group
    let n = groups.len();
    let total = (n as u64).checked_pow(n as u32).unwrap_or(u64::MAX);
    let exact = total <= EXACT_UP_TO;
    let draws: Vec<Vec<usize>> = if n == 0 {
        Vec::new()
    } else if exact {
        (0..total)
            .map(|k| {
                let mut counts = vec![0usize; n];
                let mut rest = k;
                for _ in 0..n {
                    counts[(rest % n as u64) as usize] += 1;
                    rest /= n as u64;
                }
                counts
            })
            .collect()
    } else {
        let mut state = SEED;
        (0..DRAWS)
            .map(|_| {
                let mut counts = vec![0usize; n];
                for _ in 0..n {
                    counts[(splitmix64(&mut state) % n as u64) as usize] += 1;
                }
                counts
            })
            .collect()
    };
    let intervals: Vec<(f64, f64)> = per_group
        .iter()
        .map(|g| {
            let mut r: Vec<f64> = draws.iter().map(|counts| score_of(g, counts)).collect();
            if r.is_empty() || r.iter().any(|x| !x.is_finite()) {
                return (f64::NAN, f64::NAN);
            }
            r.sort_by(f64::total_cmp);
            let tail = (1.0 - LEVEL) / 2.0;
            (quantile(&r, tail), quantile(&r, 1.0 - tail))
        })
        .collect();
    let scored = |i: usize| scores[i].is_finite() && intervals[i].0.is_finite();
    let mut order: Vec<usize> = (0..candidates.len()).collect();
    order.sort_by(|&a, &b| match (scored(a), scored(b)) {
        (true, true) => scores[a].total_cmp(&scores[b]).then(candidates[a].cost.cmp(&candidates[b].cost)),
        (true, false) => std::cmp::Ordering::Less,
        (false, true) => std::cmp::Ordering::Greater,
        (false, false) => std::cmp::Ordering::Equal,
    });
    let best = order.first().copied().filter(|&b| scored(b));
    let tied = |i: usize| {
        best.is_some_and(|b| scored(i) && intervals[i].0 <= intervals[b].1 && intervals[b].0 <= intervals[i].1)
    };
    let chosen = order
        .iter()
        .copied()
        .filter(|&i| tied(i))
        .min_by(|&a, &b| candidates[a].cost.cmp(&candidates[b].cost).then(scores[a].total_cmp(&scores[b])));
    let ranked = order
        .iter()
        .map(|&i| Ranked {
            index: i,
            score: if scored(i) { scores[i] } else { f64::NAN },
            interval: intervals[i],
            tie: tied(i),
            chosen: chosen == Some(i),
        })
        .collect();
    Ok(Ranking { ranked, groups, draws: draws.len(), exact })
}

/// The seed of a sampled bootstrap.
const SEED: u64 = 0x5EED_0046;

/// SplitMix64 (Steele, Lea and Flood 2014): a sampled bootstrap's draws, the same on every
/// machine (a few lines instead of a random-number crate in the library's dependencies).
fn splitmix64(state: &mut u64) -> u64 {
    *state = state.wrapping_add(0x9E37_79B9_7F4A_7C15);
    let mut z = *state;
    z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    z ^ (z >> 31)
}

/// The `p` quantile of the sorted `v`, linear between order statistics (type 7).
fn quantile(v: &[f64], p: f64) -> f64 {
    let h = (v.len() - 1) as f64 * p;
    let (lo, hi) = (h.floor() as usize, h.ceil() as usize);
    v[lo] + (h - lo as f64) * (v[hi] - v[lo])
}

#[cfg(test)]
mod tests {
    use super::*;

    fn candidate(fitted: usize, mechanisms: usize, errors: &[(&str, f64)]) -> Candidate {
        Candidate {
            cost: Cost { fitted, mechanisms },
            rows: errors.iter().map(|(g, e)| HeldOut { group: g.to_string(), error: *e }).collect(),
        }
    }

    /// Three strings of two rows each: 27 draws, every one enumerated; a replicate of one string
    /// drawn three times scores that string's rows alone.
    #[test]
    fn three_groups_are_bootstrapped_exactly_over_their_27_draws() {
        let c = candidate(1, 1, &[("a", 10.0), ("a", 10.0), ("b", 20.0), ("b", 20.0), ("c", 40.0), ("c", 40.0)]);
        let r = rank(&[c]).unwrap();
        assert_eq!((r.draws, r.exact, r.groups.len()), (27, true, 3));
        let e = r.ranked[0];
        let rms = ((100.0 + 400.0 + 1600.0) / 3.0f64).sqrt();
        assert!((e.score - rms).abs() < 1e-12);
        // the extremes of the replicates are the groups alone (10 and 40); the 90 % interval
        // lies within them and holds the score
        assert!(10.0 <= e.interval.0 && e.interval.0 < rms && rms < e.interval.1 && e.interval.1 <= 40.0);
        assert!(e.tie && e.chosen);
    }

    /// Scores far apart against their scatter: no tie, and the best is chosen though it costs
    /// more.
    #[test]
    fn a_clearly_better_candidate_is_chosen_whatever_it_costs() {
        let rows = |x: f64| [("a", x), ("a", -x), ("b", x * 1.1), ("b", -x), ("c", x * 0.9), ("c", x)];
        let cheap = candidate(1, 0, &rows(300.0));
        let dear = candidate(2, 4, &rows(50.0));
        let r = rank(&[cheap, dear]).unwrap();
        assert_eq!(r.ranked[0].index, 1);
        assert!(r.ranked[0].chosen && !r.ranked[1].tie && !r.ranked[1].chosen);
    }

    /// Overlapping intervals are a tie, and the tie goes to the cheaper candidate, even with the
    /// larger score: fewer fitted parameters first, then fewer mechanisms.
    #[test]
    fn a_tie_goes_to_the_cheaper_candidate() {
        let spread = |a: f64, b: f64, c: f64| [("a", a), ("a", -a), ("b", b), ("b", -b), ("c", c), ("c", -c)];
        let best = candidate(1, 1, &spread(50.0, 150.0, 250.0));
        let close_cheaper = candidate(1, 0, &spread(60.0, 160.0, 260.0));
        let close_more_params = candidate(2, 0, &spread(40.0, 140.0, 240.0));
        let r = rank(&[best.clone(), close_cheaper, close_more_params]).unwrap();
        assert_eq!(r.ranked.iter().map(|e| e.index).collect::<Vec<_>>(), [2, 0, 1]);
        assert!(r.ranked.iter().all(|e| e.tie));
        assert_eq!(r.chosen().unwrap().index, 1, "one parameter and no mechanism: the cheapest");
        // with equal costs the least score wins the tie
        let twin = candidate(1, 1, &spread(55.0, 155.0, 255.0));
        assert_eq!(rank(&[twin, best]).unwrap().chosen().unwrap().index, 1);
    }

    /// A candidate without a score (a held-out error not posed) is ranked last and never chosen;
    /// candidates with different rows are refused.
    #[test]
    fn an_unscored_candidate_is_last_and_different_rows_are_refused() {
        let good = candidate(1, 1, &[("a", 10.0), ("b", 20.0)]);
        let nan = candidate(1, 0, &[("a", f64::NAN), ("b", 20.0)]);
        let r = rank(&[nan, good.clone()]).unwrap();
        assert_eq!(r.ranked[1].index, 0);
        assert!(r.ranked[1].score.is_nan() && !r.ranked[1].tie && !r.ranked[1].chosen);
        assert_eq!(r.chosen().unwrap().index, 1);
        let other = candidate(1, 0, &[("a", 10.0), ("c", 20.0)]);
        assert!(rank(&[good, other]).is_err());
    }

    /// Beyond the exact enumeration the draws are sampled from a fixed seed: the same ranking
    /// every time.
    #[test]
    fn many_groups_are_sampled_the_same_way_every_time() {
        let groups: Vec<String> = (0..9).map(|g| format!("s{g}")).collect();
        let rows: Vec<(&str, f64)> = groups.iter().enumerate().map(|(i, g)| (g.as_str(), 10.0 * i as f64)).collect();
        let a = rank(&[candidate(1, 0, &rows)]).unwrap();
        assert_eq!((a.draws, a.exact), (DRAWS, false));
        assert_eq!(a, rank(&[candidate(1, 0, &rows)]).unwrap());
    }
}
