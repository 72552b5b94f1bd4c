//! A bounding-volume hierarchy over a mesh's triangles, built once from the triangles and
//! never stored: snapshots and replays carry the mesh's source data and rebuild it.
//!
//! Construction is a deterministic top-down median split: a node's triangles are split in
//! two equal halves (the lower half one larger for odd counts) along the longest axis of
//! the bounding box of their centroids (x before y before z on ties), ordered by the
//! centroid's coordinate on that axis with the triangle index breaking ties, a total
//! order. Nodes of at most [`LEAF_SIZE`] triangles are leaves, whose triangles are kept in
//! ascending index order. The tree is therefore a function of the triangles alone, and
//! has depth ⌈log₂(n / 4)⌉ + 1 at most.
//!
//! Nodes are stored depth first: a node's first child follows it, and it records where
//! its second child is.

use crate::math::{Real, Vec3};
use crate::rigid::aabb::Aabb;

/// The most triangles in a leaf.
pub const LEAF_SIZE: usize = 4;

/// Depth bound of the traversal stack: enough for 2⁶⁰ triangles at [`LEAF_SIZE`].
const MAX_DEPTH: usize = 64;

/// One node: its bounds, and either a leaf's range of [`Bvh::order`] or an inner node's
/// second child.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct BvhNode<R: Real> {
    /// Bounds of every triangle below the node, m, in the mesh's frame.
    pub bounds: Aabb<R>,
    /// Leaf: index of its first triangle in `order`. Inner node: index of its second child.
    pub first: u32,
    /// Leaf: number of triangles (1 to [`LEAF_SIZE`]). Inner node: 0.
    pub count: u32,
}

/// The tree: nodes depth first, root at 0, and the triangle indices as the leaves hold them.
#[derive(Clone, Debug, Default, PartialEq)]
pub(crate) struct Bvh<R: Real> {
    pub nodes: Vec<BvhNode<R>>,
    pub order: Vec<u32>,
}

impl<R: Real> Bvh<R> {
    /// The tree over triangles with the given `bounds` (one box per triangle) and
    /// `centroids` (any fixed multiple of each triangle's centroid: the sum of its
    /// vertices, to save a division). Empty for no triangles.
    pub fn build(bounds: &[Aabb<R>], centroids: &[Vec3<R>]) -> Self {
        let mut bvh = Self {
            nodes: Vec::with_capacity(2 * bounds.len().div_ceil(LEAF_SIZE)),
            order: (0..bounds.len() as u32).collect(),
        };
        if !bounds.is_empty() {
            bvh.split(0, bounds.len(), bounds, centroids);
        }
        bvh
    }

    /// Builds the subtree over `order[start..end]` at the end of `nodes`.
    fn split(&mut self, start: usize, end: usize, bounds: &[Aabb<R>], centroids: &[Vec3<R>]) {
        let slice = &mut self.order[start..end];
        let node_bounds = slice
            .iter()
            .map(|&t| bounds[t as usize])
            .reduce(|a, b| a.union(&b))
            .unwrap_or_default();
        let index = self.nodes.len();
        self.nodes.push(BvhNode {
            bounds: node_bounds,
            first: start as u32,
            count: slice.len() as u32,
        });
        if slice.len() <= LEAF_SIZE {
            slice.sort_unstable();
            return;
        }
        let (low, high) = slice.iter().fold(
            (centroids[slice[0] as usize], centroids[slice[0] as usize]),
            |(low, high), &t| {
                let c = centroids[t as usize];
                (low.min_elem(c), high.max_elem(c))
            },
        );
        let spread = high - low;
        let axis = if spread.x >= spread.y && spread.x >= spread.z {
            0
        } else if spread.y >= spread.z {
            1
        } else {
            2
        };
        let middle = slice.len().div_ceil(2);
        // A total order (coordinate, then index): the two halves are the same sets
        // whatever the selection algorithm does.
        slice.select_nth_unstable_by(middle - 1, |&a, &b| {
            let (ca, cb) = (centroids[a as usize][axis], centroids[b as usize][axis]);
            ca.total_cmp(&cb).then(a.cmp(&b))
        });
        self.split(start, start + middle, bounds, centroids);
        let second = self.nodes.len() as u32;
        self.nodes[index].first = second;
        self.nodes[index].count = 0;
        self.split(start + middle, end, bounds, centroids);
    }

    /// The bounds of every triangle, or `None` for an empty tree.
    pub fn root_bounds(&self) -> Option<Aabb<R>> {
        self.nodes.first().map(|node| node.bounds)
    }

    /// Calls `visit(triangle)` for every triangle whose box overlaps `aabb` (both in the
    /// mesh's frame), leaf by leaf in tree order, each triangle once.
    pub fn for_each_overlap(&self, aabb: &Aabb<R>, mut visit: impl FnMut(u32)) {
        self.walk(
            |bounds| bounds.overlaps(aabb),
            |triangles| {
                triangles.iter().for_each(|&t| visit(t));
            },
        );
    }

    /// Visits the tree: `enter(bounds)` decides whether a node's subtree is searched, and
    /// `leaf(triangles)` receives the triangles of every leaf entered, first child first.
    pub fn walk(&self, mut enter: impl FnMut(&Aabb<R>) -> bool, mut leaf: impl FnMut(&[u32])) {
        if self.nodes.is_empty() {
            return;
        }
        let mut stack = [0u32; MAX_DEPTH];
        let mut depth = 1;
        while depth > 0 {
            depth -= 1;
            let node = &self.nodes[stack[depth] as usize];
            if !enter(&node.bounds) {
                continue;
            }
            if node.count > 0 {
                let first = node.first as usize;
                leaf(&self.order[first..first + node.count as usize]);
            } else {
                // Second child below the first on the stack: the first is visited first.
                let index = stack[depth];
                stack[depth] = node.first;
                stack[depth + 1] = index + 1;
                depth += 2;
            }
        }
    }

    /// Bytes held by the tree's arrays.
    pub fn heap_bytes(&self) -> usize {
        self.nodes.capacity() * core::mem::size_of::<BvhNode<R>>()
            + self.order.capacity() * core::mem::size_of::<u32>()
    }
}
