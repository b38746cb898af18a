import {
  addBody,
  addBox,
  addDistanceJoint,
  addDistanceJoint3D,
  addWeldJoint,
  createPhysicsWorld,
  gravitationalPotentialEnergy,
  kineticEnergy,
  slotOf,
  step,
} from '@bitphysics/physics';
import { describe, expect, test } from 'vitest';

/**
 * Soft joints may not add energy (issue 33). A 2 kg plank (1 m x 0.2 m) held by a weld to the fixed
 * world at the end of a lever, from rest, under gravity, with damping 0: the weld's springs are
 * conservative and the solver integrates them implicitly, so the mechanical energy KE + PE (the
 * springs' own energy, >= 0 and 0 at the start, left out) can never exceed its start. Before the fix
 * a 5 Hz weld on a 10 m lever spun up to 1.2e4 rad/s and 8e4 rad/s on 25 m (energy up by 1e7 to
 * 6e8 J), a 1 Hz weld even on 1 m: the rows' stiffness followed the anchor's effective mass, which
 * the plank's rotation changes, so the spring did work around a swing. Tolerance 1e-9 of m g L
 * (rounding; measured after the fix: the energy stays 6.7e-3 J or more below its start).
 * planck's 5 Hz weld (angular part soft only) stays under 1 rad/s on these levers; so does ours
 * (measured 0.39 to 0.71 rad/s at 5 Hz), checked with a margin: under 2 rad/s.
 *
 * A hertz so small that the spring's coefficients underflow (4e-323 Hz, a denormal) gave NaN at the
 * first step; such a spring now pushes with nothing, and the body falls freely.
 */
describe('soft joints do not add energy', () => {
  const g = 9.81;

  function weld(lever: number, hertz: number, angularHertz: number, steps: number) {
    const world = createPhysicsWorld({ gravity: [0, -g] });
    const b = addBox(world, { position: [lever, 0], halfExtents: [0.5, 0.1], density: 10 });
    addWeldJoint(world, { b, anchor: [0, 0], hertz, dampingRatio: 0, angularHertz, angularDampingRatio: 0 });
    const e0 = kineticEnergy(world) + gravitationalPotentialEnergy(world);
    const W = world.components.AngularVelocity.z;
    const s = slotOf(b);
    let gain = -Infinity,
      spin = 0;
    for (let i = 0; i < steps; i++) {
      step(world);
      gain = Math.max(gain, kineticEnergy(world) + gravitationalPotentialEnergy(world) - e0);
      spin = Math.max(spin, Math.abs(W[s]!));
    }
    return { gain, spin, scale: 2 * g * lever };
  }

  for (const lever of [1, 5, 10, 25]) {
    test(`a weld with damping 0 on a ${lever} m lever keeps its energy over 20 s (1, 5 and 20 Hz; linear, angular or both soft)`, () => {
      for (const [hertz, angularHertz] of [
        [1, 1],
        [5, 5],
        [20, 20],
        [5, 0],
        [0, 5],
        [1, 20],
      ] as const) {
        const { gain, spin, scale } = weld(lever, hertz, angularHertz, 1200);
        expect(gain, `${hertz} / ${angularHertz} Hz: energy gain, J`).toBeLessThan(1e-9 * scale);
        if (hertz === 5 && angularHertz === 5 && lever >= 5) expect(spin, 'spin at 5 Hz, rad/s').toBeLessThan(2);
      }
    });
  }

  test('a denormal hertz with damping 0 gives finite results (2D weld and distance spring, 3D distance spring)', () => {
    const w2 = createPhysicsWorld({ gravity: [0, -g] });
    const plank = addBox(w2, { position: [5, 0], halfExtents: [0.5, 0.1], density: 10 });
    addWeldJoint(w2, { b: plank, anchor: [0, 0], hertz: 4e-323, dampingRatio: 0, angularHertz: 4e-323, angularDampingRatio: 0 });
    const ball = addBody(w2, { position: [0, -3], radius: 0.2, mass: 1 });
    addDistanceJoint(w2, { b: ball, anchorA: [0, 0], length: 1, hertz: 4e-323, dampingRatio: 0 });
    for (let i = 0; i < 30; i++) step(w2);
    const V = w2.components.Velocity;
    // No spring force to speak of: both fall freely, v = -g t after 30 steps of 1/60 s.
    for (const e of [plank, ball]) expect(V.y[slotOf(e)]!).toBeCloseTo(-g * 0.5, 6);

    const w3 = createPhysicsWorld({ dimensions: 3, gravity: [0, -g, 0] });
    const ball3 = addBody(w3, { position: [0, -3, 0], radius: 0.2, mass: 1 });
    addDistanceJoint3D(w3, { b: ball3, anchorA: [0, 0, 0], length: 1, hertz: 4e-323, dampingRatio: 0 });
    for (let i = 0; i < 30; i++) step(w3);
    expect(w3.components.Velocity.y[slotOf(ball3)]!).toBeCloseTo(-g * 0.5, 6);
  });
});
