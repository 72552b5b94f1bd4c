//! A deliberate desync, to test that peers detect one.

use crate::math::Fx;
use crate::rigid::BodyKind;
use crate::world::World;

/// Moves the first live dynamic body by one unit in the last place along x (2⁻³² m for
/// I32F32): the smallest change the state can take. Returns false, changing nothing, when
/// the world has no dynamic body.
pub fn nudge_first_body(world: &mut World<Fx>) -> bool {
    let mut state = world.snapshot();
    let Some(bodies) = state.rigid.as_mut().map(|rigid| &mut rigid.bodies) else {
        return false;
    };
    let Some(i) = (0..bodies.position.len())
        .find(|&i| bodies.alive[i] && bodies.kind[i] == BodyKind::Dynamic)
    else {
        return false;
    };
    let x = &mut bodies.position[i].x;
    *x = Fx::from_bits(x.to_bits().wrapping_add(1));
    world.restore(&state);
    true
}

/// Whether the world has a body [`nudge_first_body`] can move.
pub fn has_dynamic_body(world: &World<Fx>) -> bool {
    world.rigid().is_some_and(|rigid| {
        rigid
            .handles()
            .any(|h| rigid.kind(h) == Some(BodyKind::Dynamic))
    })
}
