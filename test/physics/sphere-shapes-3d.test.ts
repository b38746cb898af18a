import { addBody, addShape3D, createPhysicsWorld, slotOf, step } from '@bitphysics/physics';
import { describe, expect, test } from 'vitest';

/**
 * A sphere shape resting on each other 3D shape: a 0.2 m sphere (1,000 kg/m^3) dropped from 0.3 m
 * above the top of a static box, capsule (lying: its axis turned to x), cylinder (upright) and
 * convex hull (a square frustum: 3 m square base, 2 m square top), each with its top at y = 0.5 m. At rest its centre is at top + r = 0.7 m: the contact
 * manifold's normal and depth are right for sphere-vs-shape (the audit found no test of these pairs).
 * Tolerance 1 mm: the soft contact sags a little under the weight (measured 0.069 mm on all four);
 * a wrong support point or normal is off by centimetres. Friction 0.6 and no
 * restitution, so the sphere lands and stays on the flat or round top.
 */
describe('sphere shape resting on box, capsule, cylinder and hull', () => {
  const cases: [string, (world: ReturnType<typeof createPhysicsWorld>) => void][] = [
    [
      'box',
      (w) => {
        const b = addBody(w, { position: [0, 0.25, 0], static: true });
        addShape3D(w, b, { type: 'box', halfExtents: [1, 0.25, 1] });
      },
    ],
    [
      'capsule',
      (w) => {
        const b = addBody(w, { position: [0, 0.3, 0], static: true, orientation: [0, 0, Math.SQRT1_2, Math.SQRT1_2] });
        addShape3D(w, b, { type: 'capsule', radius: 0.2, halfHeight: 1 });
      },
    ],
    [
      'cylinder',
      (w) => {
        const b = addBody(w, { position: [0, 0.25, 0], static: true });
        addShape3D(w, b, { type: 'cylinder', radius: 1, halfHeight: 0.25 });
      },
    ],
    [
      'hull',
      (w) => {
        const b = addBody(w, { position: [0, 0, 0], static: true });
        const v: number[][] = [];
        for (const [x, z] of [
          [-1, -1],
          [1, -1],
          [1, 1],
          [-1, 1],
        ]) {
          v.push([x * 1.5, 0, z * 1.5], [x, 0.5, z]);
        }
        addShape3D(w, b, { type: 'hull', vertices: v });
      },
    ],
  ];
  for (const [name, build] of cases) {
    test(`on a ${name}: centre at top + r = 0.7 m within 1 mm`, () => {
      const world = createPhysicsWorld({ dimensions: 3, gravity: [0, -9.81, 0], sleep: false });
      build(world);
      const s = addBody(world, { position: [0, 1.0, 0], friction: 0.6, restitution: 0 });
      addShape3D(world, s, { type: 'sphere', radius: 0.2, density: 1000 });
      for (let i = 0; i < 180; i++) step(world);
      const e = slotOf(s),
        P = world.components.Position,
        V = world.components.Velocity;
      expect(Math.abs(P.y[e]! - 0.7)).toBeLessThan(1e-3);
      expect(Math.hypot(P.x[e]!, P.z[e]!)).toBeLessThan(1e-3);
      expect(Math.hypot(V.x[e]!, V.y[e]!, V.z[e]!)).toBeLessThan(1e-3);
    });
  }
});
