//! Batching of the constraints into blocks whose constraints share no body that the solver
//! moves, so that a block can be solved side by side and its lanes in any order give the
//! same result — while the solving order stays close to the contact order, which matters
//! for convergence (a stack is best solved from the bottom up, the order its contacts
//! usually come in).
//!
//! The constraints are taken in contact order. Each joins the first of [`OPEN`] open
//! batches holding neither of its bodies; a batch that reaches [`LANES`] constraints is
//! closed and goes next in the solving order, and a fresh batch takes its place (the
//! scheme of Rapier's interaction groups). A constraint that fits no open batch is set
//! aside. At the end the open batches go in batch order, then the set-aside constraints,
//! in contact order, [`LANES`] to a block but marked as not independent (they are solved
//! one lane after another, never side by side). Bodies the solver never moves (the static
//! body and kinematic bodies, of zero inverse mass: their impulses are multiplied by 0)
//! belong to no batch.

use super::lanes::LANES;

/// Batches open at once.
const OPEN: usize = 32;

/// The solving order: blocks of contact indices, each with whether its constraints are
/// independent (share no moving body).
#[derive(Clone, Debug, Default)]
pub(crate) struct Batching {
    /// Bit i set: the body is in open batch i.
    batches_of_body: Vec<u32>,
    /// The contact indices of each open batch, with their bodies (moving ones only).
    open: Vec<Vec<(u32, [Option<u32>; 2])>>,
    /// Contacts set aside.
    aside: Vec<u32>,
    /// The blocks, in solving order.
    blocks: Vec<(bool, Vec<u32>)>,
    /// Blocks in use.
    block_count: usize,
}

impl Batching {
    /// Starts a batching over `bodies` solver bodies.
    pub fn start(&mut self, bodies: usize) {
        self.batches_of_body.clear();
        self.batches_of_body.resize(bodies, 0);
        self.open.resize_with(OPEN, Vec::new);
        for batch in &mut self.open {
            batch.clear();
        }
        self.aside.clear();
        self.block_count = 0;
    }

    /// Adds the next constraint, for contact `contact` between solver bodies `a` and `b`,
    /// each given with whether the solver moves it.
    pub fn add(&mut self, contact: u32, (a, moves_a): (u32, bool), (b, moves_b): (u32, bool)) {
        let bodies = [moves_a.then_some(a), moves_b.then_some(b)];
        let taken = bodies
            .iter()
            .flatten()
            .fold(0u32, |mask, &i| mask | self.batches_of_body[i as usize]);
        if taken == u32::MAX {
            self.aside.push(contact);
            return;
        }
        let i = taken.trailing_ones() as usize;
        for &body in bodies.iter().flatten() {
            self.batches_of_body[body as usize] |= 1 << i;
        }
        self.open[i].push((contact, bodies));
        if self.open[i].len() == LANES {
            self.close(i);
        }
    }

    /// Closes open batch `i`: its constraints become the next block.
    fn close(&mut self, i: usize) {
        for &(_, bodies) in &self.open[i] {
            for &body in bodies.iter().flatten() {
                self.batches_of_body[body as usize] &= !(1 << i);
            }
        }
        let batch = core::mem::take(&mut self.open[i]);
        self.next_block(true)
            .extend(batch.iter().map(|&(contact, _)| contact));
        self.open[i] = batch;
        self.open[i].clear();
    }

    /// A fresh block at the end of the order, empty, with its independence.
    fn next_block(&mut self, independent: bool) -> &mut Vec<u32> {
        if self.block_count == self.blocks.len() {
            self.blocks.push((independent, Vec::with_capacity(LANES)));
        }
        let block = &mut self.blocks[self.block_count];
        self.block_count += 1;
        block.0 = independent;
        block.1.clear();
        &mut block.1
    }

    /// Ends the batching: the open batches, then the set-aside constraints.
    pub fn finish(&mut self) {
        for i in 0..OPEN {
            if !self.open[i].is_empty() {
                self.close(i);
            }
        }
        let aside = core::mem::take(&mut self.aside);
        for chunk in aside.chunks(LANES) {
            self.next_block(false).extend_from_slice(chunk);
        }
        self.aside = aside;
    }

    /// The blocks in solving order: (independent, contact indices).
    pub fn blocks(&self) -> impl Iterator<Item = (bool, &[u32])> {
        self.blocks[..self.block_count]
            .iter()
            .map(|(independent, contacts)| (*independent, contacts.as_slice()))
    }
}

#[cfg(test)]
mod tests;
