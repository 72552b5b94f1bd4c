//! Stage 1 of the solver: one constraint per contact that has a body to move, batched
//! ([`batching`](super::batching)) and stored [`LANES`] to a block, one block per batch.

use super::Solver;
use super::body::STATIC_BODY;
use super::contact_constraint::{ContactArms, ContactBlock, SolvePass};
use super::mixed_materials::MixedMaterials;
use crate::math::Real;
use crate::rigid::bodies::Bodies;
use crate::rigid::contact::Contact;

#[cfg(doc)]
use super::lanes::LANES;

impl<R: Real> Solver<R> {
    /// Builds the step's constraints from `contacts` (the world's list) for the solver
    /// bodies already set up from `bodies`. A contact gets a constraint when at least one
    /// of its bodies has finite mass and moves. The blocks come in the batching's order;
    /// the friction and restitution of a pair are the mix of its materials, and the soft
    /// effective masses those of `pass`, the step's biased pass.
    pub fn prepare(&mut self, contacts: &[Contact<R>], bodies: &Bodies<R>, pass: &SolvePass<R>) {
        let Self {
            bodies: solver_bodies,
            index_of_slot,
            batching,
            blocks,
            block_count,
            ..
        } = self;
        batching.start(solver_bodies.len());
        for (k, contact) in contacts.iter().enumerate() {
            let (a, b) = (contact.key.body_a as usize, contact.key.body_b as usize);
            let (ia, ib) = (index_of_slot[a], index_of_slot[b]);
            let moves_a = solver_bodies[ia as usize].inv_mass != R::ZERO;
            let moves_b = solver_bodies[ib as usize].inv_mass != R::ZERO;
            if (ia == STATIC_BODY && ib == STATIC_BODY) || !(moves_a || moves_b) {
                continue;
            }
            batching.add(k as u32, (ia, moves_a), (ib, moves_b));
        }
        batching.finish();

        *block_count = 0;
        let mut arms = ContactArms::ZERO;
        let mut mixed = MixedMaterials::EMPTY;
        for (independent, batch) in batching.blocks() {
            if *block_count == blocks.len() {
                blocks.push(ContactBlock::empty());
            }
            let block = &mut blocks[*block_count];
            *block_count += 1;
            block.clear(independent);
            for &k in batch {
                let contact = &contacts[k as usize];
                let (a, b) = (contact.key.body_a as usize, contact.key.body_b as usize);
                let (friction, restitution) = mixed.of(&bodies.material[a], &bodies.material[b]);
                block.prepare_lane(
                    contact,
                    k,
                    (index_of_slot[a], bodies.position[a]),
                    (index_of_slot[b], bodies.position[b]),
                    solver_bodies,
                    friction,
                    restitution,
                    &mut arms,
                );
            }
            block.prepare_products(&arms, solver_bodies);
            block.soften(pass);
        }
    }
}
