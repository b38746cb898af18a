import { addBody, addBox, addShape3D, createPhysicsWorld, slotOf, step } from '@bitphysics/physics';
import { describe, expect, test } from 'vitest';

/**
 * A perfectly elastic box (restitution 1) resting on the ground stays at rest, in 2D and 3D. Its
 * contact's bounce threshold is 0 (`elasticRestitutionThreshold`: an e = 1 contact bounces at any
 * approach speed), so what keeps it still is that a resting contact has no approach to reflect: the
 * step's gravity (g dt = 0.16 m/s at 60 Hz) is taken out by the contact's own solve. Were it reflected,
 * the box would leave the ground at up to 0.16 m/s and hop up to 1.3 mm (v^2 / 2 g) every step or so.
 * Bounds, over 10 s kept awake: never above where it was built by 0.1 mm, never faster than 0.01 m/s
 * (measured: it sinks 0.02 mm into the ground and moves at most 0.00006 m/s).
 */
describe('a box with restitution 1 resting on the ground', () => {
  for (const dimensions of [2, 3] as const) {
    test(`${dimensions}D: stays at rest for 10 s (sleep off)`, () => {
      const world = createPhysicsWorld({ dimensions, gravity: dimensions === 2 ? [0, -9.81] : [0, -9.81, 0], sleep: false });
      let box: number;
      if (dimensions === 2) {
        addBox(world, { position: [0, -0.5], halfExtents: [10, 0.5], static: true });
        box = addBox(world, { position: [0, 0.5], halfExtents: [0.5, 0.5], restitution: 1 });
      } else {
        const ground = addBody(world, { position: [0, -0.5, 0], static: true });
        addShape3D(world, ground, { type: 'box', halfExtents: [10, 0.5, 10] });
        box = addBody(world, { position: [0, 0.5, 0], rotates: true });
        addShape3D(world, box, { type: 'box', halfExtents: [0.5, 0.5, 0.5], density: 1, restitution: 1 });
      }
      const s = slotOf(box),
        P = world.components.Position,
        V = world.components.Velocity;
      let highest = Number.NEGATIVE_INFINITY,
        fastest = 0;
      for (let i = 0; i < 600; i++) {
        step(world);
        highest = Math.max(highest, P.y[s]! - 0.5);
        fastest = Math.max(fastest, Math.hypot(V.x[s]!, V.y[s]!, V.z[s]!));
      }
      expect(highest).toBeLessThan(1e-4);
      expect(fastest).toBeLessThan(0.01);
    });
  }
});
