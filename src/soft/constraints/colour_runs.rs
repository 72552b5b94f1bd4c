//! Runs of constraint rows that share no vertex, for solving a Gauss–Seidel pass across
//! threads with the bits of one thread.
//!
//! The distance and bending rows are stored in colour order (`colour_order` in
//! `build.rs`), so a pass visits them colour after colour. Cutting the row list greedily,
//! in order, into maximal runs of consecutive rows in which no vertex appears twice gives
//! the colours (and splits the last, capped colour where it must): the rows of a run read
//! no position another row of the run writes, so solving them in any order, or side by
//! side, equals solving them in order. The runs depend on the rows alone, never on the
//! thread count.

use core::ops::Range;

/// The runs of a row list with `K` vertices a row, and what a parallel pass needs to
/// solve each run on copies of its rows' ends.
#[derive(Debug)]
pub(crate) struct ColourRuns<const K: usize> {
    /// Consecutive runs of rows, together covering every row in order.
    pub runs: Vec<Range<usize>>,
    /// For run r, `touches[offsets[r]..offsets[r + 1]]`: every (vertex, slot) the run
    /// moves, slot = K·(row − run start) + corner, sorted by vertex (each vertex once).
    touches: Vec<(u32, u32)>,
    offsets: Vec<usize>,
    /// `local[k][i] = K·i + k`: the corners of row i of a chunk in the chunk's copy of its
    /// ends.
    pub local: [Vec<u32>; K],
    /// The same, row by row.
    pub local_rows: Vec<[u32; K]>,
    /// All true: the blocks of eight rows of a chunk share no vertex.
    #[cfg(vector_kernels)]
    pub independent: Vec<bool>,
}

impl<const K: usize> Default for ColourRuns<K> {
    /// No runs (no rows).
    fn default() -> Self {
        Self::new(&[], 0, 0)
    }
}

impl<const K: usize> ColourRuns<K> {
    /// The runs of `rows` (each row's K vertices, all below `vertices`), with local
    /// patterns for chunks of up to `chunk` rows.
    pub fn new(rows: &[[u32; K]], vertices: usize, chunk: usize) -> Self {
        let mut runs = Vec::new();
        let mut seen = vec![usize::MAX; vertices];
        let mut start = 0;
        for (r, row) in rows.iter().enumerate() {
            let repeats = |&v: &u32| seen[v as usize] != usize::MAX && seen[v as usize] >= start;
            if row.iter().any(repeats) {
                runs.push(start..r);
                start = r;
            }
            for &v in row {
                seen[v as usize] = r;
            }
        }
        if start < rows.len() {
            runs.push(start..rows.len());
        }
        let mut touches = Vec::with_capacity(K * rows.len());
        let mut offsets = vec![0];
        for run in &runs {
            let first = touches.len();
            for (i, row) in rows[run.clone()].iter().enumerate() {
                for (k, &v) in row.iter().enumerate() {
                    touches.push((v, (K * i + k) as u32));
                }
            }
            touches[first..].sort_unstable();
            offsets.push(touches.len());
        }
        let local = core::array::from_fn(|k| (0..chunk).map(|i| (K * i + k) as u32).collect());
        let local_rows = (0..chunk)
            .map(|i| core::array::from_fn(|k| (K * i + k) as u32))
            .collect();
        Self {
            runs,
            touches,
            offsets,
            local,
            local_rows,
            #[cfg(vector_kernels)]
            independent: vec![true; chunk.div_ceil(8)],
        }
    }

    /// The (vertex, slot) pairs run `r` moves, sorted by vertex.
    pub fn touches(&self, r: usize) -> &[(u32, u32)] {
        &self.touches[self.offsets[r]..self.offsets[r + 1]]
    }
}

#[cfg(test)]
mod tests {
    use super::ColourRuns;

    #[test]
    fn runs_share_no_vertex_and_cover_the_rows() {
        let rows = [[0, 1], [2, 3], [1, 2], [3, 4], [0, 4], [5, 6]];
        let runs = ColourRuns::new(&rows, 7, 8);
        assert_eq!(runs.runs, vec![0..2, 2..4, 4..6]);
        assert_eq!(runs.touches(0), &[(0, 0), (1, 1), (2, 2), (3, 3)]);
        assert_eq!(runs.touches(2), &[(0, 0), (4, 1), (5, 2), (6, 3)]);
        assert_eq!(runs.local[1][..3], [1, 3, 5]);
    }
}
