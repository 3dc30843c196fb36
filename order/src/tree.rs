//! Rooted trees: the index set of Runge–Kutta order conditions.
//!
//! A tree is stored canonically as its sorted list of subtrees, so structural equality is
//! isomorphism. Trees are ordered by number of vertices first, then by their subtrees
//! lexicographically; within one order this puts the bushy tree first and the tall tree
//! last, e.g. for order 4: `[τ³]`, `[τ[τ]]`, `[[τ²]]`, `[[[τ]]]`.

use std::fmt;

use crate::forest;

/// The largest order [`trees_of_order`] generates; above it the number of trees (634,847 at
/// order 17, growing about threefold per order) is too large to be useful.
pub const MAX_TREE_ORDER: usize = 16;

/// An unlabelled rooted tree, kept in canonical form (subtrees sorted).
#[derive(Clone, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct RootedTree {
    /// Number of vertices (compared first by the derived ordering).
    order: usize,
    /// Subtrees of the root, sorted ascending.
    children: Vec<RootedTree>,
}

impl Default for RootedTree {
    fn default() -> Self {
        RootedTree::leaf()
    }
}

impl RootedTree {
    /// The tree with a single vertex, `τ`.
    pub fn leaf() -> Self {
        RootedTree {
            order: 1,
            children: Vec::new(),
        }
    }

    /// The tree whose root carries the given subtrees, `[t_1 … t_m]` (in any order).
    pub fn from_children(mut children: Vec<RootedTree>) -> Self {
        children.sort();
        let order = children.iter().fold(1usize, |n, child| n.saturating_add(child.order));
        RootedTree { order, children }
    }

    /// The subtrees of the root, in canonical (ascending) order.
    pub fn children(&self) -> &[RootedTree] {
        &self.children
    }

    /// Number of vertices, `|t|`.
    pub fn order(&self) -> usize {
        self.order
    }

    /// The density `γ(t)`: the order times the product of the subtrees' densities.
    /// The order condition of `t` is `sum_i b_i Φ_i(t) = 1/γ(t)`.
    pub fn density(&self) -> f64 {
        self.children
            .iter()
            .fold(self.order as f64, |g, child| g * child.density())
    }

    /// The density as an integer, saturating at `u128::MAX` (exact for any tree that fits
    /// in memory with up to 34 vertices).
    pub fn density_exact(&self) -> u128 {
        self.children
            .iter()
            .fold(self.order as u128, |g, child| g.saturating_mul(child.density_exact()))
    }

    /// The symmetry `σ(t)`: the order of the tree's automorphism group, the product over
    /// each distinct subtree `u` repeated `m` times of `σ(u)^m m!`.
    pub fn symmetry(&self) -> f64 {
        let mut sigma = 1.0;
        for (child, m) in self.grouped_children() {
            let s = child.symmetry();
            for k in 1..=m {
                sigma *= s * k as f64;
            }
        }
        sigma
    }

    /// Subtrees with their multiplicities, in canonical order.
    fn grouped_children(&self) -> Vec<(&RootedTree, usize)> {
        let mut groups: Vec<(&RootedTree, usize)> = Vec::new();
        for child in &self.children {
            match groups.last_mut() {
                Some((last, m)) if *last == child => *m += 1,
                _ => groups.push((child, 1)),
            }
        }
        groups
    }

    /// The order condition of this tree written out for the weights named `weights`,
    /// with the exact right-hand side `1/γ(t)`.
    ///
    /// Leaves attached to a vertex with index `x` appear as `c_x^m` (`c_x` when `m = 1`),
    /// every other subtree as `a_xy` followed by its own factors, `y` a fresh index letter
    /// (`i j k l m n o p q r s …`), depth first:
    ///
    /// * `τ`: `"sum b_i = 1"`
    /// * `[τ³]`: `"sum b_i c_i^3 = 1/4"`
    /// * `[τ[τ]]`: `"sum b_i c_i a_ij c_j = 1/8"`
    /// * `[[τ²]]`: `"sum b_i a_ij c_j^2 = 1/12"`
    /// * `[[[τ]]]`: `"sum b_i a_ij a_jk c_k = 1/24"`
    pub fn condition_text(&self, weights: &str) -> String {
        let mut text = format!("sum {weights}_i");
        let mut next = 1;
        self.write_factors(&mut text, 0, &mut next);
        let gamma = self.density_exact();
        if gamma == 1 {
            text.push_str(" = 1");
        } else {
            text.push_str(&format!(" = 1/{gamma}"));
        }
        text
    }

    fn write_factors(&self, out: &mut String, index: usize, next: &mut usize) {
        let name = index_name(index);
        let leaves = self.children.iter().filter(|c| c.order == 1).count();
        match leaves {
            0 => {}
            1 => out.push_str(&format!(" c_{name}")),
            m => out.push_str(&format!(" c_{name}^{m}")),
        }
        for child in self.children.iter().filter(|c| c.order > 1) {
            let j = *next;
            *next += 1;
            out.push_str(&format!(" a_{name}{}", index_name(j)));
            child.write_factors(out, j, next);
        }
    }
}

/// Summation index names: `i`, `j`, …, `z`, then `v18`, `v19`, ….
fn index_name(index: usize) -> String {
    const LETTERS: &[u8] = b"ijklmnopqrstuvwxyz";
    match LETTERS.get(index) {
        Some(&c) => char::from(c).to_string(),
        None => format!("v{index}"),
    }
}

/// Butcher's bracket notation: `τ`, `[τ]`, `[τ²]`, `[τ[τ]]`, `[[τ]²]`.
impl fmt::Display for RootedTree {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.children.is_empty() {
            return f.write_str("τ");
        }
        f.write_str("[")?;
        for (child, m) in self.grouped_children() {
            write!(f, "{child}")?;
            if m > 1 {
                f.write_str(&superscript(m))?;
            }
        }
        f.write_str("]")
    }
}

fn superscript(n: usize) -> String {
    const DIGITS: [char; 10] = ['⁰', '¹', '²', '³', '⁴', '⁵', '⁶', '⁷', '⁸', '⁹'];
    n.to_string()
        .bytes()
        .map(|d| DIGITS[usize::from(d - b'0') % 10])
        .collect()
}

/// All rooted trees (non-isomorphic, unlabelled) with exactly `order` vertices, in the
/// canonical order of [`RootedTree`] (bushy first).
///
/// There are 1, 1, 2, 4, 9, 20, 48, 115, 286, 719 trees of orders 1 to 10. Trees up to
/// [`MAX_ORDER`](crate::MAX_ORDER) are generated once per process and cached; higher orders
/// up to [`MAX_TREE_ORDER`] are generated on each call. Order 0 and orders above
/// [`MAX_TREE_ORDER`] yield an empty vector.
pub fn trees_of_order(order: usize) -> Vec<RootedTree> {
    if order == 0 || order > MAX_TREE_ORDER {
        return Vec::new();
    }
    forest::with_forest(order, |forest| forest.trees_of_order(order).to_vec())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn tree(children: Vec<RootedTree>) -> RootedTree {
        RootedTree::from_children(children)
    }

    fn t() -> RootedTree {
        RootedTree::leaf()
    }

    #[test]
    fn counts_match_oeis_a000081() {
        let expected = [1, 1, 2, 4, 9, 20, 48, 115, 286, 719, 1842, 4766];
        for (n, &count) in expected.iter().enumerate() {
            let trees = trees_of_order(n + 1);
            assert_eq!(trees.len(), count, "order {}", n + 1);
            assert!(trees.iter().all(|t| t.order() == n + 1));
            // Distinct and in canonical ascending order.
            assert!(trees.windows(2).all(|w| w[0] < w[1]), "order {}", n + 1);
        }
        assert!(trees_of_order(0).is_empty());
        assert!(trees_of_order(MAX_TREE_ORDER + 1).is_empty());
        assert!(trees_of_order(usize::MAX).is_empty());
    }

    #[test]
    fn generation_is_fast() {
        let start = std::time::Instant::now();
        let total: usize = (1..=10).map(|n| trees_of_order(n).len()).sum();
        assert_eq!(total, 1 + 1 + 2 + 4 + 9 + 20 + 48 + 115 + 286 + 719);
        let elapsed = start.elapsed();
        assert!(elapsed.as_millis() < 200, "took {elapsed:?}");
    }

    #[test]
    fn densities_and_symmetries() {
        assert_eq!(t().density_exact(), 1);
        assert_eq!(tree(vec![t()]).density_exact(), 2);
        assert_eq!(tree(vec![t(), t()]).density_exact(), 3);
        assert_eq!(tree(vec![tree(vec![t()])]).density_exact(), 6);
        let order4: Vec<u128> = trees_of_order(4).iter().map(RootedTree::density_exact).collect();
        assert_eq!(order4, vec![4, 8, 12, 24]);
        let order4: Vec<f64> = trees_of_order(4).iter().map(RootedTree::symmetry).collect();
        assert_eq!(order4, vec![6.0, 1.0, 2.0, 1.0]);
        // Tall tree of order n has density n!.
        let mut tall = t();
        for _ in 1..10 {
            tall = tree(vec![tall]);
        }
        assert_eq!(tall.order(), 10);
        assert!((tall.density() - 3_628_800.0).abs() < 0.5);
        assert!(trees_of_order(10).contains(&tall));
        // Over the trees of order n, n!/σ(t) adds up to the n^(n-1) labelled rooted trees
        // and n!/(σ(t) γ(t)) to the (n-1)! monotonically labelled ones.
        for n in 1..=9usize {
            let fact: f64 = (1..=n).map(|k| k as f64).product();
            let trees = trees_of_order(n);
            let labelled: f64 = trees.iter().map(|t| fact / t.symmetry()).sum();
            let expected = (n as f64).powi(n as i32 - 1);
            assert!((labelled - expected).abs() < 1e-6, "order {n}: {labelled}");
            let monotone: f64 = trees.iter().map(|t| fact / (t.symmetry() * t.density())).sum();
            let expected = fact / n as f64;
            assert!((monotone - expected).abs() < 1e-6, "order {n}: {monotone}");
        }
    }

    #[test]
    fn condition_texts() {
        let texts: Vec<String> = trees_of_order(4).iter().map(|t| t.condition_text("b")).collect();
        assert_eq!(
            texts,
            vec![
                "sum b_i c_i^3 = 1/4",
                "sum b_i c_i a_ij c_j = 1/8",
                "sum b_i a_ij c_j^2 = 1/12",
                "sum b_i a_ij a_jk c_k = 1/24",
            ]
        );
        assert_eq!(t().condition_text("b"), "sum b_i = 1");
        assert_eq!(tree(vec![t()]).condition_text("b_hat"), "sum b_hat_i c_i = 1/2");
        let forked = tree(vec![tree(vec![t()]), tree(vec![tree(vec![t(), t()])])]);
        assert_eq!(forked.condition_text("b"), "sum b_i a_ij c_j a_ik a_kl c_l^2 = 1/168");
        assert_eq!(forked.density_exact(), 7 * 2 * (4 * 3));
    }

    #[test]
    fn canonical_form_and_display() {
        let x = tree(vec![tree(vec![t()]), t()]);
        let y = tree(vec![t(), tree(vec![t()])]);
        assert_eq!(x, y);
        assert_eq!(x.to_string(), "[τ[τ]]");
        assert_eq!(tree(vec![t(), t(), t()]).to_string(), "[τ³]");
        assert_eq!(tree(vec![tree(vec![t()]), tree(vec![t()])]).to_string(), "[[τ]²]");
        assert_eq!(t().to_string(), "τ");
        let names: Vec<String> = trees_of_order(4).iter().map(ToString::to_string).collect();
        assert_eq!(names, vec!["[τ³]", "[τ[τ]]", "[[τ²]]", "[[[τ]]]"]);
    }
}
