import {
  addBody,
  addBox,
  addDistanceJoint,
  addDistanceJoint3D,
  addShape3D,
  addWheelJoint,
  createPhysicsWorld,
  gravitationalPotentialEnergy,
  kineticEnergy,
  type PhysicsWorld,
  step,
} from '@bitphysics/physics';
import { describe, expect, test } from 'vitest';

/**
 * Spring joints may not add energy (issue 33: "a soft joint may not add energy"). A 2 kg plank (1 m x
 * 0.2 m, 0.2 m deep in 3D) hangs from the fixed world by a spring attached at the end of a lever
 * (the anchor `lever` metres from the plank's centre), from rest, under gravity, the spring at its
 * rest length, with damping 0. A spring of fixed stiffness stores energy 1/2 k C^2 >= 0 that is 0 at
 * the start, so the mechanical energy KE + PE can never exceed its start; the solver's soft step is
 * an implicit (backward Euler) update of that spring, which only loses energy. Before the fix the
 * stiffness followed the anchor's effective mass, which the plank's rotation changes, so the spring
 * did work around a swing: a 1 Hz distance spring on a 5 m lever gained 6.4e5 J, a 5 Hz one on 25 m
 * went to NaN, a 5 Hz wheel spring on 25 m reached 5e176 J and a 20 Hz 3D distance spring on 25 m
 * 1.7e24 J. Tolerance: 1e-9 of m g L (rounding) for the distance springs, whose energy falls (measured
 * 1.3e-3 J or more below its start); the wheel's is below.
 */
describe('spring joints do not add energy', () => {
  const g = 9.81;
  const mass = 2;

  function energyGain(world: PhysicsWorld, steps: number): number {
    const e0 = kineticEnergy(world) + gravitationalPotentialEnergy(world);
    let gain = -Infinity;
    for (let i = 0; i < steps; i++) {
      step(world);
      gain = Math.max(gain, kineticEnergy(world) + gravitationalPotentialEnergy(world) - e0);
    }
    return gain;
  }

  type Kind = 'distance' | 'wheel' | 'distance-3d';
  function hang(kind: Kind, lever: number, hertz: number): PhysicsWorld {
    if (kind === 'distance-3d') {
      const world = createPhysicsWorld({ dimensions: 3, gravity: [0, -g, 0] });
      const b = addBody(world, { position: [lever, -5, 0] });
      addShape3D(world, b, { type: 'box', halfExtents: [0.5, 0.1, 0.1], density: mass / 0.04 });
      addDistanceJoint3D(world, { b, anchorA: [0, 0, 0], anchorB: [0, -5, 0], length: 5, hertz, dampingRatio: 0 });
      return world;
    }
    const world = createPhysicsWorld({ gravity: [0, -g] });
    const b = addBox(world, { position: [lever, -5], halfExtents: [0.5, 0.1], density: mass / 0.2 });
    if (kind === 'distance') addDistanceJoint(world, { b, anchorA: [0, 0], anchorB: [0, -5], length: 5, hertz, dampingRatio: 0 });
    // A wheel's spring along a vertical axis through the anchor; the plank turns freely about it.
    if (kind === 'wheel') addWheelJoint(world, { b, anchor: [0, -5], axis: [0, 1], hertz, dampingRatio: 0 });
    return world;
  }

  // The wheel's rigid row across its axis corrects drift with a little velocity, which the relax pass
  // does not take back in full: a 20 Hz wheel on a 1 m lever gains up to 0.052 J (0.26 % of m g L) in
  // its first second at 4 substeps (0.018 J at 8, 0.003 J at 16: a discretisation error that falls with
  // h, not a pump), so the wheel's bound is 1 % of m g L; before the fix a 1 Hz wheel gained 2.8 % on a
  // 1 m lever and 5.6e7 J on 5 m.
  const tolerance = (kind: Kind, lever: number) => (kind === 'wheel' ? 1e-2 : 1e-9) * mass * g * Math.max(1, lever);
  for (const kind of ['distance', 'wheel', 'distance-3d'] as const) {
    test(`a ${kind} spring with damping 0 keeps its energy over 20 s on levers of 0 to 25 m (1, 5 and 20 Hz)`, () => {
      for (const lever of [0, 1, 5, 10, 25]) {
        for (const hertz of [1, 5, 20]) {
          const gain = energyGain(hang(kind, lever, hertz), 1200);
          expect({ kind, lever, hertz, gain: gain <= tolerance(kind, lever) }).toEqual({ kind, lever, hertz, gain: true });
        }
      }
    });
  }
});
