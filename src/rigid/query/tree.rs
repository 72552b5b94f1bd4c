//! A dynamic bounding-volume tree of axis-aligned boxes, after Box2D's `b2DynamicTree`.
//!
//! Every leaf holds one body slot and a *fat* box: the body's tight box grown by a margin,
//! so that a body that moves a little stays inside its leaf and the tree is left alone.
//! Internal nodes hold the union of their children's boxes. A new leaf goes next to the
//! sibling that grows the tree's total cost least (the surface-area heuristic, with the
//! sum of a box's three extents, m, as its cost, which never overflows), and the path back
//! to the root is rebalanced with AVL rotations, so the height stays O(log n).
//!
//! The tree is a cache, never state: its shape depends on the order of insertions and
//! moves. Queries test every leaf it returns exactly and break ties by handle, so their
//! answers do not depend on that shape.

use crate::math::Real;
use crate::rigid::aabb::Aabb;

/// No node: the end of a link.
const NULL: u32 = u32::MAX;

/// A node: a leaf (height 0, `slot` set) or an internal node with two children.
#[derive(Clone, Debug)]
struct Node<R: Real> {
    /// The fat box of a leaf, or the union of the children's boxes, m.
    aabb: Aabb<R>,
    /// The parent node; for a node on the free list, the next free node.
    parent: u32,
    left: u32,
    right: u32,
    /// 0 for a leaf, 1 + the children's greater height otherwise, −1 when free.
    height: i32,
    /// The body slot of a leaf.
    slot: u32,
}

/// The tree: nodes in one array, freed nodes reused through a free list.
#[derive(Clone, Debug)]
pub(crate) struct AabbTree<R: Real> {
    nodes: Vec<Node<R>>,
    root: u32,
    free: u32,
}

impl<R: Real> Default for AabbTree<R> {
    fn default() -> Self {
        Self {
            nodes: Vec::new(),
            root: NULL,
            free: NULL,
        }
    }
}

/// The cost of a box in the surface-area heuristic: the sum of its extents, m (a
/// perimeter-like measure that grows with the box as its area does).
fn cost<R: Real>(aabb: &Aabb<R>) -> R {
    let e = aabb.max - aabb.min;
    e.x + e.y + e.z
}

impl<R: Real> AabbTree<R> {
    /// Removes every node, keeping the storage.
    pub fn clear(&mut self) {
        self.nodes.clear();
        self.root = NULL;
        self.free = NULL;
    }

    /// The fat box of leaf `leaf`.
    pub fn fat_box(&self, leaf: u32) -> &Aabb<R> {
        &self.nodes[leaf as usize].aabb
    }

    /// Height of the tree: 0 for one leaf, −1 when empty.
    #[cfg(test)]
    pub fn height(&self) -> i32 {
        if self.root == NULL {
            -1
        } else {
            self.nodes[self.root as usize].height
        }
    }

    /// Adds a leaf for `slot` with fat box `fat`; returns the leaf's node.
    pub fn insert(&mut self, slot: u32, fat: Aabb<R>) -> u32 {
        let leaf = self.allocate();
        let node = &mut self.nodes[leaf as usize];
        node.aabb = fat;
        node.height = 0;
        node.slot = slot;
        self.insert_leaf(leaf);
        leaf
    }

    /// Removes leaf `leaf`.
    pub fn remove(&mut self, leaf: u32) {
        self.remove_leaf(leaf);
        self.release(leaf);
    }

    /// Gives leaf `leaf` the new fat box `fat`, re-inserting it.
    pub fn reinsert(&mut self, leaf: u32, fat: Aabb<R>) {
        self.remove_leaf(leaf);
        self.nodes[leaf as usize].aabb = fat;
        self.insert_leaf(leaf);
    }

    /// Walks the tree from the root: calls `visit(box, None)` for an internal node, whose
    /// children are visited only when it returns true, and `visit(box, Some(slot))` for a
    /// leaf. `stack` is working memory.
    pub fn traverse(
        &self,
        stack: &mut Vec<u32>,
        mut visit: impl FnMut(&Aabb<R>, Option<u32>) -> bool,
    ) {
        stack.clear();
        if self.root != NULL {
            stack.push(self.root);
        }
        while let Some(index) = stack.pop() {
            let node = &self.nodes[index as usize];
            if node.height == 0 {
                visit(&node.aabb, Some(node.slot));
            } else if visit(&node.aabb, None) {
                stack.push(node.right);
                stack.push(node.left);
            }
        }
    }

    /// Walks the tree nearest first: `enter(box)` gives a node's key (a ray's entry
    /// distance, m) or `None` to prune it; of two children the one with the smaller key
    /// (the left on ties) is walked first, and a node whose key exceeds `reach()` when it
    /// comes up is skipped with its subtree (a key equal to `reach()` is kept).
    /// `leaf(slot)` is called for every leaf kept. `stack` is working memory.
    pub fn traverse_nearest(
        &self,
        stack: &mut Vec<(u32, R)>,
        mut enter: impl FnMut(&Aabb<R>) -> Option<R>,
        reach: impl Fn() -> R,
        mut leaf: impl FnMut(u32),
    ) {
        stack.clear();
        if self.root == NULL {
            return;
        }
        let root = &self.nodes[self.root as usize];
        match enter(&root.aabb) {
            Some(key) => stack.push((self.root, key)),
            None => return,
        }
        while let Some((index, key)) = stack.pop() {
            if key > reach() {
                continue;
            }
            let node = &self.nodes[index as usize];
            if node.height == 0 {
                leaf(node.slot);
                continue;
            }
            let (l, r) = (node.left, node.right);
            let kl = enter(&self.nodes[l as usize].aabb);
            let kr = enter(&self.nodes[r as usize].aabb);
            match (kl, kr) {
                (Some(a), Some(b)) => {
                    if b < a {
                        stack.push((l, a));
                        stack.push((r, b));
                    } else {
                        stack.push((r, b));
                        stack.push((l, a));
                    }
                }
                (Some(a), None) => stack.push((l, a)),
                (None, Some(b)) => stack.push((r, b)),
                (None, None) => {}
            }
        }
    }

    fn allocate(&mut self) -> u32 {
        if self.free == NULL {
            self.nodes.push(Node {
                aabb: Aabb::default(),
                parent: NULL,
                left: NULL,
                right: NULL,
                height: -1,
                slot: NULL,
            });
            return (self.nodes.len() - 1) as u32;
        }
        let index = self.free;
        self.free = self.nodes[index as usize].parent;
        let node = &mut self.nodes[index as usize];
        node.parent = NULL;
        node.left = NULL;
        node.right = NULL;
        index
    }

    fn release(&mut self, index: u32) {
        let node = &mut self.nodes[index as usize];
        node.parent = self.free;
        node.height = -1;
        self.free = index;
    }

    fn is_leaf(&self, index: u32) -> bool {
        self.nodes[index as usize].height == 0
    }

    /// Links the allocated leaf `leaf` into the tree beside the best sibling.
    fn insert_leaf(&mut self, leaf: u32) {
        if self.root == NULL {
            self.root = leaf;
            self.nodes[leaf as usize].parent = NULL;
            return;
        }
        let leaf_box = self.nodes[leaf as usize].aabb;
        let mut index = self.root;
        // Descend while a child is cheaper than pairing with the current node: the cost of
        // a new parent here is 2·cost(node ∪ leaf); going down adds the growth of this
        // node (inherited by every ancestor of the new parent) to the child's own cost.
        while !self.is_leaf(index) {
            let node = &self.nodes[index as usize];
            let (left, right) = (node.left, node.right);
            let area = cost(&node.aabb);
            let combined = cost(&node.aabb.union(&leaf_box));
            let here = combined + combined;
            let inherited = (combined - area) + (combined - area);
            let child_cost = |child: u32| {
                let child_box = &self.nodes[child as usize].aabb;
                let grown = cost(&child_box.union(&leaf_box));
                if self.is_leaf(child) {
                    grown + inherited
                } else {
                    grown - cost(child_box) + inherited
                }
            };
            let (cost_left, cost_right) = (child_cost(left), child_cost(right));
            if here < cost_left && here < cost_right {
                break;
            }
            index = if cost_left <= cost_right { left } else { right };
        }
        let sibling = index;
        let old_parent = self.nodes[sibling as usize].parent;
        let parent = self.allocate();
        {
            let sibling_node = &self.nodes[sibling as usize];
            let aabb = sibling_node.aabb.union(&leaf_box);
            let height = sibling_node.height + 1;
            let node = &mut self.nodes[parent as usize];
            node.parent = old_parent;
            node.aabb = aabb;
            node.height = height;
            node.left = sibling;
            node.right = leaf;
        }
        if old_parent == NULL {
            self.root = parent;
        } else {
            self.replace_child(old_parent, sibling, parent);
        }
        self.nodes[sibling as usize].parent = parent;
        self.nodes[leaf as usize].parent = parent;
        self.refit_from(parent);
    }

    /// Unlinks leaf `leaf` (kept allocated): its parent goes, its sibling takes the
    /// parent's place.
    fn remove_leaf(&mut self, leaf: u32) {
        if leaf == self.root {
            self.root = NULL;
            return;
        }
        let parent = self.nodes[leaf as usize].parent;
        let grand = self.nodes[parent as usize].parent;
        let p = &self.nodes[parent as usize];
        let sibling = if p.left == leaf { p.right } else { p.left };
        self.nodes[sibling as usize].parent = grand;
        self.release(parent);
        if grand == NULL {
            self.root = sibling;
        } else {
            self.replace_child(grand, parent, sibling);
            self.refit_from(grand);
        }
    }

    /// In node `parent`, the child `old` becomes `new`.
    fn replace_child(&mut self, parent: u32, old: u32, new: u32) {
        let p = &mut self.nodes[parent as usize];
        if p.left == old {
            p.left = new;
        } else {
            p.right = new;
        }
    }

    /// Rebalances and recomputes boxes and heights from `index` up to the root.
    fn refit_from(&mut self, mut index: u32) {
        while index != NULL {
            index = self.balance(index);
            let node = &self.nodes[index as usize];
            let (left, right) = (
                &self.nodes[node.left as usize],
                &self.nodes[node.right as usize],
            );
            let height = 1 + left.height.max(right.height);
            let aabb = left.aabb.union(&right.aabb);
            let node = &mut self.nodes[index as usize];
            node.height = height;
            node.aabb = aabb;
            index = node.parent;
        }
    }

    /// If the subtree at `a` leans by more than one level, rotates its taller child up
    /// (Box2D's `Balance`); returns the subtree's new root.
    fn balance(&mut self, a: u32) -> u32 {
        let na = &self.nodes[a as usize];
        if na.height < 2 {
            return a;
        }
        let (b, c) = (na.left, na.right);
        let lean = self.nodes[c as usize].height - self.nodes[b as usize].height;
        if lean > 1 {
            self.rotate_up(a, c, b, false)
        } else if lean < -1 {
            self.rotate_up(a, b, c, true)
        } else {
            a
        }
    }

    /// Rotates child `up` of `a` into `a`'s place; `other` is `a`'s other child. `up`
    /// keeps `a` as its first child (left when `up` was the right child, and so on, as in
    /// Box2D) and its taller child; its shorter child goes to `a` in `up`'s place.
    fn rotate_up(&mut self, a: u32, up: u32, other: u32, up_was_left: bool) -> u32 {
        let (f, g) = {
            let n = &self.nodes[up as usize];
            (n.left, n.right)
        };
        let a_parent = self.nodes[a as usize].parent;
        self.nodes[up as usize].left = a;
        self.nodes[up as usize].parent = a_parent;
        self.nodes[a as usize].parent = up;
        if a_parent == NULL {
            self.root = up;
        } else {
            self.replace_child(a_parent, a, up);
        }
        let (tall, short) = if self.nodes[f as usize].height > self.nodes[g as usize].height {
            (f, g)
        } else {
            (g, f)
        };
        self.nodes[up as usize].right = tall;
        if up_was_left {
            self.nodes[a as usize].left = short;
        } else {
            self.nodes[a as usize].right = short;
        }
        self.nodes[short as usize].parent = a;
        let (other_node, short_node) = (&self.nodes[other as usize], &self.nodes[short as usize]);
        let a_box = other_node.aabb.union(&short_node.aabb);
        let a_height = 1 + other_node.height.max(short_node.height);
        let tall_node = &self.nodes[tall as usize];
        let up_box = a_box.union(&tall_node.aabb);
        let up_height = 1 + a_height.max(tall_node.height);
        let na = &mut self.nodes[a as usize];
        na.aabb = a_box;
        na.height = a_height;
        let nu = &mut self.nodes[up as usize];
        nu.aabb = up_box;
        nu.height = up_height;
        up
    }

    /// Checks the links, heights and boxes of every node and returns the number of leaves;
    /// panics on a broken invariant. For tests.
    #[cfg(test)]
    pub fn validate(&self) -> usize {
        if self.root == NULL {
            return 0;
        }
        assert_eq!(self.nodes[self.root as usize].parent, NULL);
        self.validate_node(self.root)
    }

    #[cfg(test)]
    fn validate_node(&self, index: u32) -> usize {
        let node = &self.nodes[index as usize];
        if node.height == 0 {
            return 1;
        }
        let (l, r) = (
            &self.nodes[node.left as usize],
            &self.nodes[node.right as usize],
        );
        assert_eq!(l.parent, index);
        assert_eq!(r.parent, index);
        assert_eq!(node.height, 1 + l.height.max(r.height));
        assert_eq!(node.aabb, l.aabb.union(&r.aabb));
        self.validate_node(node.left) + self.validate_node(node.right)
    }
}
