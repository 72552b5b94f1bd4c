//! A deliberate desync, to test that peers detect one.

use fixstep::math::Fx;
use fixstep::rigid::BodyKind;
use fixstep::world::World;

/// Moves the first live dynamic body by one unit in the last place along x (2⁻³² m for
/// I32F32): the smallest change the state can take. Returns false, changing nothing, when
/// the world has no dynamic body.
pub fn nudge_first_body(world: &mut World<Fx>) -> bool {
    let mut state = world.snapshot();
    let Some(rigid) = state.rigid.as_mut() else {
        return false;
    };
    let Some(body) = rigid
        .handles()
        .find(|&h| rigid.kind(h) == Some(BodyKind::Dynamic))
    else {
        return false;
    };
    let mut position = rigid.position(body).expect("a live body");
    position.x = Fx::from_bits(position.x.to_bits().wrapping_add(1));
    rigid.set_position(body, position);
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
