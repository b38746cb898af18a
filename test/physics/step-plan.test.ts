// step resolves each stage's systems once (step/plan.ts) and skips a built-in law while its idle
// guard's queries are empty. These tests change a world after its plans were made and check the
// laws against the formulas: a law that becomes busy acts in the very next step, one that becomes
// idle again stops, and a system added or removed after the first step runs or stops.

import {
  addBody,
  addSystem,
  createPhysicsWorld,
  type PhysicsWorld,
  removeBody,
  removeSystem,
  setAttractor,
  setGravitation,
  slotOf,
  step,
} from '@bitphysics/physics';
import { describe, expect, it } from 'vitest';

function world(): PhysicsWorld {
  return createPhysicsWorld({ dimensions: 2, gravity: [0, 0], capacity: 16, dt: 0.01 });
}

describe('stage plans', () => {
  it('an attractor added after steps without one pulls in the next step, as F = -G M m r / r^3', () => {
    const w = world();
    const ship = addBody(w, { position: [0, 0], mass: 2 });
    for (let i = 0; i < 5; i++) step(w);
    const s = slotOf(ship);
    expect(w.components.Velocity.x[s]).toBe(0);
    setGravitation(w, { constant: 1 });
    const hole = addBody(w, { position: [10, 0], static: true });
    setAttractor(w, hole, { mass: 1000 });
    step(w);
    // Semi-implicit Euler: v = a h from the position at the start of the step, a = G M / r^2 towards
    // the hole: 1 x 1000 / 10^2 x 0.01 = 0.1 m/s.
    expect(w.components.Velocity.x[s]).toBeCloseTo(0.1, 12);
    removeBody(w, hole);
    const v = w.components.Velocity.x[s]!;
    step(w);
    step(w);
    expect(w.components.Velocity.x[s]).toBe(v);
  });

  it('a system added after the first step runs from the next one, and one removed stops', () => {
    const w = world();
    addBody(w, { position: [0, 0], mass: 1 });
    step(w);
    let calls = 0;
    const count = (): void => {
      calls++;
    };
    addSystem(w, 'forces', count);
    step(w);
    step(w);
    expect(calls).toBe(2);
    expect(removeSystem(w, 'forces', count)).toBe(true);
    step(w);
    expect(calls).toBe(2);
    // A direct write to the stage's list counts too.
    w.stages.integrate.push(count);
    step(w);
    expect(calls).toBe(3);
  });
});
