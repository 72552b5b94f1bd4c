//! Feeding a sparse, tick-ordered list of inputs to a world one tick at a time.

use crate::math::Fx;
use crate::world::TickInput;

/// Walks inputs sorted by ascending tick (a scene's script or a replay's inputs) and hands
/// out the input for each tick, or an empty one when the list has none for it.
#[derive(Debug)]
pub struct InputFeed<'a> {
    inputs: &'a [TickInput<Fx>],
    next: usize,
    empty: TickInput<Fx>,
}

impl<'a> InputFeed<'a> {
    /// A feed over `inputs`, which must be in ascending tick order.
    pub fn new(inputs: &'a [TickInput<Fx>]) -> Self {
        Self {
            inputs,
            next: 0,
            empty: TickInput::default(),
        }
    }

    /// The input for `tick`. Ticks must be asked for in ascending order; inputs for ticks
    /// that were skipped are passed over.
    pub fn at(&mut self, tick: u64) -> &TickInput<Fx> {
        while self.inputs.get(self.next).is_some_and(|i| i.tick < tick) {
            self.next += 1;
        }
        match self.inputs.get(self.next) {
            Some(input) if input.tick == tick => {
                self.next += 1;
                input
            }
            _ => {
                self.empty.tick = tick;
                &self.empty
            }
        }
    }
}
