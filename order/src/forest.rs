//! The forest: every rooted tree up to some order, indexed, with each tree's subtrees
//! given as indices of earlier trees. This is what makes the elementary weights cheap: the
//! weights of a tree are products of vectors already computed for its subtrees.

use std::sync::OnceLock;

use crate::conditions::MAX_ORDER;
use crate::tree::RootedTree;

/// One tree of the forest.
pub(crate) struct Node {
    /// Number of vertices.
    pub order: usize,
    /// Indices of the root's subtrees, ascending; all smaller than this node's index.
    pub children: Vec<usize>,
}

/// All trees of orders `1..=max_order`, in canonical order.
pub(crate) struct Forest {
    pub nodes: Vec<Node>,
    trees: Vec<RootedTree>,
    /// `starts[n]` is the index of the first tree of order `n`; `starts[max_order + 1]`
    /// is the number of trees. `starts[0] = 0`.
    starts: Vec<usize>,
}

impl Forest {
    /// Generates every tree of order `1..=max_order`.
    ///
    /// A tree of order `n` is a root with a multiset of smaller trees whose orders add up
    /// to `n - 1`; multisets are enumerated as ascending index sequences in lexicographic
    /// order, which is exactly the derived ordering of [`RootedTree`].
    fn build(max_order: usize) -> Forest {
        let mut forest = Forest {
            nodes: Vec::new(),
            trees: Vec::new(),
            starts: vec![0, 0],
        };
        for n in 1..=max_order {
            let mut found = Vec::new();
            forest.multisets(n - 1, 0, &mut Vec::new(), &mut found);
            for children in found {
                let tree = RootedTree::from_children(children.iter().map(|&c| forest.trees[c].clone()).collect());
                forest.nodes.push(Node { order: n, children });
                forest.trees.push(tree);
            }
            forest.starts.push(forest.nodes.len());
        }
        forest
    }

    /// Appends to `out` every ascending sequence of indices `>= min` extending `current`
    /// whose orders add up to `remaining`.
    fn multisets(&self, remaining: usize, min: usize, current: &mut Vec<usize>, out: &mut Vec<Vec<usize>>) {
        if remaining == 0 {
            out.push(current.clone());
            return;
        }
        // Trees of order <= remaining.
        let end = self.end_of(remaining);
        for index in min..end {
            current.push(index);
            self.multisets(remaining - self.nodes[index].order, index, current, out);
            current.pop();
        }
    }

    /// The largest order held.
    pub fn max_order(&self) -> usize {
        self.starts.len() - 2
    }

    /// One past the index of the last tree of order `<= order`.
    pub fn end_of(&self, order: usize) -> usize {
        let i = (order + 1).min(self.starts.len() - 1);
        self.starts[i]
    }

    /// The trees of exactly `order` vertices (empty if not held).
    pub fn trees_of_order(&self, order: usize) -> &[RootedTree] {
        if order == 0 || order > self.max_order() {
            return &[];
        }
        &self.trees[self.starts[order]..self.starts[order + 1]]
    }

    /// The tree at `index`.
    pub fn tree(&self, index: usize) -> &RootedTree {
        &self.trees[index]
    }
}

/// Runs `f` on a forest holding at least the trees up to `order`: the process-wide cache
/// for orders up to [`MAX_ORDER`], a freshly generated one above.
pub(crate) fn with_forest<R>(order: usize, f: impl FnOnce(&Forest) -> R) -> R {
    static CACHE: OnceLock<Forest> = OnceLock::new();
    if order <= MAX_ORDER {
        f(CACHE.get_or_init(|| Forest::build(MAX_ORDER)))
    } else {
        f(&Forest::build(order))
    }
}
