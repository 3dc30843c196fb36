//! The free Lie algebra over a graded alphabet, truncated at a weight: the index set of the
//! order conditions of splittings and compositions.
//!
//! A step that composes exact flows `exp(c_1 X_1) exp(c_2 X_2) ...` (the first flow applied
//! written first, as Lie operators act) is a series `P` over the words of the alphabet; its
//! logarithm is a Lie series, written in the Lyndon basis: the bracket `P(w)` of each Lyndon
//! word `w` by its standard factorization (`AAB` is `[A,[A,B]]`, `ABB` is `[[A,B],B]`). The
//! coordinates of `log P` in that basis are the quantities the order conditions set to zero.
//!
//! Every series is computed twice: with the coefficients, and with their absolute values
//! and every operation on magnitudes (the size of the terms a coordinate sums, which bounds
//! its rounding error and the effect of the digits the coefficients were given with).

use std::collections::HashMap;

use crate::double_double::Scalar;

/// A letter, by its index in the alphabet (its order in the lexicographic order of words).
pub(crate) type Letter = u8;

/// Every word of weight `1..=max_weight` over an alphabet whose letters have weights, with
/// what products of series need: the (prefix, suffix) splits of each word.
pub(crate) struct Words {
    /// `words[0]` is the empty word; then by weight, lexicographically within one weight.
    words: Vec<Vec<Letter>>,
    /// `starts[n]` is the index of the first word of weight `n`, `starts[max + 1]` the count.
    starts: Vec<usize>,
    index: HashMap<Vec<Letter>, usize>,
    /// Splits of word `w` into two non-empty words, at `split_starts[w]..split_starts[w + 1]`.
    split_starts: Vec<usize>,
    splits: Vec<(u32, u32)>,
}

impl Words {
    /// All words of weight up to `max_weight` over letters of the given weights (each >= 1).
    pub(crate) fn new(letter_weights: &[usize], max_weight: usize) -> Words {
        let mut by_weight: Vec<Vec<Vec<Letter>>> = vec![vec![Vec::new()]];
        for n in 1..=max_weight {
            let mut found = Vec::new();
            for (x, &w) in letter_weights.iter().enumerate() {
                if w <= n {
                    for prefix in &by_weight[n - w] {
                        let mut word = prefix.clone();
                        word.push(x as Letter);
                        found.push(word);
                    }
                }
            }
            found.sort();
            by_weight.push(found);
        }
        let mut words = Vec::new();
        let mut starts = Vec::new();
        for group in by_weight {
            starts.push(words.len());
            words.extend(group);
        }
        starts.push(words.len());
        let index: HashMap<Vec<Letter>, usize> = words.iter().enumerate().map(|(i, w)| (w.clone(), i)).collect();
        let mut split_starts = vec![0];
        let mut splits = Vec::new();
        for word in &words {
            for cut in 1..word.len() {
                splits.push((index[&word[..cut]] as u32, index[&word[cut..]] as u32));
            }
            split_starts.push(splits.len());
        }
        Words {
            words,
            starts,
            index,
            split_starts,
            splits,
        }
    }

    /// The largest weight held.
    pub(crate) fn max_weight(&self) -> usize {
        self.starts.len() - 2
    }

    /// One past the index of the last word of weight `<= weight`.
    pub(crate) fn end_of(&self, weight: usize) -> usize {
        self.starts[(weight + 1).min(self.starts.len() - 1)]
    }

    /// The indices of the words of weight exactly `weight`.
    pub(crate) fn of_weight(&self, weight: usize) -> std::ops::Range<usize> {
        self.starts[weight]..self.end_of(weight)
    }

    /// The index of a word, if held.
    pub(crate) fn index(&self, word: &[Letter]) -> Option<usize> {
        self.index.get(word).copied()
    }

    /// The letters of word `i`.
    pub(crate) fn word(&self, i: usize) -> &[Letter] {
        &self.words[i]
    }

    /// The product `a b` of two series, truncated at the words below `end`.
    pub(crate) fn product<T: Scalar>(&self, a: &[T], b: &[T], end: usize) -> Vec<T> {
        let mut c = vec![T::of(0.0); end];
        for w in 0..end {
            let mut sum = a[w] * b[0];
            if w != 0 {
                sum = sum + a[0] * b[w];
            }
            for &(u, v) in &self.splits[self.split_starts[w]..self.split_starts[w + 1]] {
                sum = sum + a[u as usize] * b[v as usize];
            }
            c[w] = sum;
        }
        c
    }

    /// `exp(sum_x z_x x)` for one coefficient `z_x` per letter: the word `x_1 .. x_m` has
    /// coefficient `z_x1 ... z_xm / m!`.
    pub(crate) fn exp_of_letters<T: Scalar>(&self, z: &[T], end: usize) -> Vec<T> {
        let mut e = vec![T::of(0.0); end];
        e[0] = T::of(1.0);
        for w in 1..end {
            let word = &self.words[w];
            // the word without its last letter: the prefix of its last split
            let head = if word.len() == 1 {
                0
            } else {
                self.splits[self.split_starts[w + 1] - 1].0 as usize
            };
            let last = usize::from(word[word.len() - 1]);
            e[w] = (e[head] * z[last]).over(word.len() as f64);
        }
        e
    }

    /// `log p` for a series with constant term 1, truncated at weight `max_weight`, as
    /// `sum_k (-1)^(k+1) (p - 1)^k / k`; `magnitude` gives the same sum of magnitudes for
    /// the magnitudes of `p` (every term added).
    pub(crate) fn log<T: Scalar>(&self, p: &[T], max_weight: usize, magnitude: bool) -> Vec<T> {
        let end = self.end_of(max_weight);
        let mut x = p[..end].to_vec();
        x[0] = T::of(0.0);
        let mut log = x.clone();
        let mut power = x.clone();
        for k in 2..=max_weight {
            power = self.product(&power, &x, end);
            let add = magnitude || k % 2 == 1;
            for (l, q) in log.iter_mut().zip(&power) {
                let term = q.over(k as f64);
                *l = if add { *l + term } else { *l - term };
            }
        }
        log
    }
}

/// A Lie polynomial written out over words: `(word index, integer coefficient)`.
pub(crate) type Expansion = Vec<(usize, i64)>;

/// The Lyndon words of an alphabet up to a weight, their brackets and the triangular
/// change of basis from word coefficients to Lyndon coordinates.
pub(crate) struct Lyndon {
    /// The Lyndon words, by weight, lexicographically within one weight.
    pub words: Vec<Vec<Letter>>,
    /// `starts[n]`: the first Lyndon word of weight `n`; `starts[max + 1]` the count.
    starts: Vec<usize>,
    /// The bracket `P(w)` of each, written out over words.
    pub expansions: Vec<Expansion>,
    /// For Lyndon word `i`: the word index of `i` itself.
    pub word_index: Vec<usize>,
    /// For Lyndon word `i`: `(j, c)` with `j < i` of the same weight and `c` the coefficient
    /// of the word `w_i` in `P(w_j)` (`P(w_i)` has coefficient 1 on `w_i`).
    below: Vec<Vec<(usize, f64)>>,
}

/// Whether `w` is a Lyndon word: strictly smaller than each of its proper suffixes.
fn is_lyndon(w: &[Letter]) -> bool {
    !w.is_empty() && (1..w.len()).all(|k| w < &w[k..])
}

impl Lyndon {
    /// The Lyndon words of `words`'s alphabet up to its largest weight.
    pub(crate) fn new(words: &Words) -> Lyndon {
        let max = words.max_weight();
        let mut lyndon: Vec<Vec<Letter>> = Vec::new();
        let mut starts = vec![0, 0];
        for n in 1..=max {
            lyndon.extend(
                words
                    .of_weight(n)
                    .map(|i| words.word(i))
                    .filter(|w| is_lyndon(w))
                    .map(<[Letter]>::to_vec),
            );
            starts.push(lyndon.len());
        }
        let mut memo: HashMap<Vec<Letter>, HashMap<Vec<Letter>, i64>> = HashMap::new();
        let expansions: Vec<Expansion> = lyndon
            .iter()
            .map(|w| {
                let mut terms: Vec<(usize, i64)> = bracket(w, &mut memo)
                    .iter()
                    .filter(|(_, &c)| c != 0)
                    .map(|(word, &c)| (words.index(word).expect("same weight"), c))
                    .collect();
                terms.sort_unstable();
                terms
            })
            .collect();
        let word_index: Vec<usize> = lyndon.iter().map(|w| words.index(w).expect("held")).collect();
        let lyndon_of_word: HashMap<usize, usize> = word_index.iter().enumerate().map(|(i, &w)| (w, i)).collect();
        let mut below = vec![Vec::new(); lyndon.len()];
        for (j, expansion) in expansions.iter().enumerate() {
            for &(w, c) in expansion {
                match lyndon_of_word.get(&w) {
                    Some(&i) if i != j => below[i].push((j, c as f64)),
                    _ => {}
                }
            }
        }
        Lyndon {
            words: lyndon,
            starts,
            expansions,
            word_index,
            below,
        }
    }

    /// The indices of the Lyndon words of weight exactly `n`.
    pub(crate) fn of_weight(&self, n: usize) -> std::ops::Range<usize> {
        let n = n.min(self.starts.len() - 2);
        self.starts[n]..self.starts[n + 1]
    }

    /// One past the last Lyndon word of weight `<= n`.
    pub(crate) fn end_of(&self, n: usize) -> usize {
        self.starts[(n + 1).min(self.starts.len() - 1)]
    }

    /// The coordinates `lambda` of a Lie series `l` (over words) in the Lyndon basis, for
    /// the Lyndon words below `end`: `l[w_i] = sum_j lambda_j P(w_j)[w_i]` solved by forward
    /// substitution. With `magnitude`, the same with every term added (for magnitudes).
    pub(crate) fn coordinates<T: Scalar>(&self, l: &[T], end: usize, magnitude: bool) -> Vec<T> {
        let mut lambda = vec![T::of(0.0); end];
        for i in 0..end {
            let mut value = l[self.word_index[i]];
            for &(j, c) in &self.below[i] {
                if magnitude {
                    value = value + T::of(c.abs()) * lambda[j];
                } else {
                    value = value - T::of(c) * lambda[j];
                }
            }
            lambda[i] = value;
        }
        lambda
    }

    /// The bracket of Lyndon word `i` written with the letter names, e.g. `[A,[A,B]]`.
    pub(crate) fn bracket_text(&self, i: usize, names: &[&str]) -> String {
        text(&self.words[i], names)
    }
}

/// The standard factorization `w = u v` of a Lyndon word of length >= 2: `v` its longest
/// proper suffix that is a Lyndon word.
fn standard_factorization(w: &[Letter]) -> (&[Letter], &[Letter]) {
    let cut = (1..w.len()).find(|&k| is_lyndon(&w[k..])).unwrap_or(w.len() - 1);
    w.split_at(cut)
}

fn text(w: &[Letter], names: &[&str]) -> String {
    if w.len() == 1 {
        return names[usize::from(w[0])].to_string();
    }
    let (u, v) = standard_factorization(w);
    format!("[{},{}]", text(u, names), text(v, names))
}

/// `P(w)` over words, memoized: a letter is itself, `P(uv) = P(u) P(v) - P(v) P(u)`.
fn bracket(w: &[Letter], memo: &mut HashMap<Vec<Letter>, HashMap<Vec<Letter>, i64>>) -> HashMap<Vec<Letter>, i64> {
    if let Some(known) = memo.get(w) {
        return known.clone();
    }
    let result = if w.len() == 1 {
        HashMap::from([(w.to_vec(), 1)])
    } else {
        let (u, v) = standard_factorization(w);
        let (pu, pv) = (bracket(u, memo), bracket(v, memo));
        commutator(&pu, &pv)
    };
    memo.insert(w.to_vec(), result.clone());
    result
}

/// `x y - y x` for two polynomials over words.
pub(crate) fn commutator(x: &HashMap<Vec<Letter>, i64>, y: &HashMap<Vec<Letter>, i64>) -> HashMap<Vec<Letter>, i64> {
    let mut out: HashMap<Vec<Letter>, i64> = HashMap::new();
    for (a, &ca) in x {
        for (b, &cb) in y {
            *out.entry([a.as_slice(), b].concat()).or_insert(0) += ca * cb;
            *out.entry([b.as_slice(), a].concat()).or_insert(0) -= ca * cb;
        }
    }
    out.retain(|_, c| *c != 0);
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lyndon_counts_follow_witts_formula() {
        let words = Words::new(&[1, 1], 10);
        let lyndon = Lyndon::new(&words);
        let counts: Vec<usize> = (1..=10).map(|n| lyndon.of_weight(n).len()).collect();
        assert_eq!(counts, [2, 1, 2, 3, 6, 9, 18, 30, 56, 99]);
        assert_eq!(words.end_of(10), 2047);
        let names = ["A", "B"];
        let texts: Vec<String> = lyndon.of_weight(3).map(|i| lyndon.bracket_text(i, &names)).collect();
        assert_eq!(texts, ["[A,[A,B]]", "[[A,B],B]"]);
        // P(w) = w + lexicographically larger words
        for i in 0..lyndon.words.len() {
            let own = lyndon.expansions[i].iter().find(|(w, _)| *w == lyndon.word_index[i]);
            assert_eq!(own.map(|t| t.1), Some(1), "{:?}", lyndon.words[i]);
            assert!(lyndon.expansions[i]
                .iter()
                .all(|(w, _)| words.word(*w) >= lyndon.words[i].as_slice()));
        }
    }

    #[test]
    fn bch_of_two_exponentials() {
        // log(exp(a A) exp(b B)) = aA + bB + ab/2 [A,B] + a^2 b/12 [A,[A,B]] + a b^2/12 [[A,B],B] + ...
        let words = Words::new(&[1, 1], 4);
        let lyndon = Lyndon::new(&words);
        let (a, b) = (0.7, -1.3);
        let end = words.end_of(4);
        let p = words.product(
            &words.exp_of_letters(&[a, 0.0], end),
            &words.exp_of_letters(&[0.0, b], end),
            end,
        );
        let log = words.log(&p, 4, false);
        let lambda = lyndon.coordinates(&log, lyndon.end_of(4), false);
        let expected = [
            a,
            b,
            a * b / 2.0,
            a * a * b / 12.0,
            a * b * b / 12.0,
            0.0,
            a * a * b * b / 24.0,
            0.0,
        ];
        for (i, (got, want)) in lambda.iter().zip(expected).enumerate() {
            assert!((got - want).abs() < 1e-15, "{:?}: {got} vs {want}", lyndon.words[i]);
        }
    }
}
