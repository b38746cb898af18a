import { addBody, addShape3D, applyImpulseAtPoint, createPhysicsWorld, setMass, slotOf } from '@bitphysics/physics';
import { describe, expect, test } from 'vitest';

describe('setMass on a 3D body with shapes', () => {
  test('scales its principal moments with the mass: a 1 x 2 x 3 m box set to 2,000 kg turns as m (b^2 + c^2) / 12 says (1e-12)', () => {
    // Before, setMass changed only the mass of a shaped 3D body: its inertia tensor stayed the one of
    // its shapes' density (6,000 kg here), so an impulse spun it 3 times too slowly.
    const world = createPhysicsWorld({ dimensions: 3, gravity: [0, 0, 0] });
    const box = addBody(world, { position: [0, 0, 0] });
    addShape3D(world, box, { type: 'box', halfExtents: [0.5, 1, 1.5], density: 1000 });
    setMass(world, box, 2000);
    const c = world.components,
      e = slotOf(box),
      m = 2000;
    // Solid box of edges a, b, c: I_x = m (b^2 + c^2) / 12, etc. (principal axes = the box's, unturned).
    const I = [(m * (4 + 9)) / 12, (m * (1 + 9)) / 12, (m * (1 + 4)) / 12];
    const T = c.InertiaTensor;
    expect([T.x[e]!, T.y[e]!, T.z[e]!].map((v, k) => Math.abs(v - I[k]!) / I[k]!).every((d) => d < 1e-12)).toBe(true);
    expect(c.Mass.value[e]).toBe(m);
    // An impulse J = 1 N s along z applied at (0, 1, 0): angular impulse (0, 1, 0) x (0, 0, 1) = (1, 0, 0),
    // so w_x = 1 / I_x, and v_z = J / m.
    applyImpulseAtPoint(world, box, [0, 0, 1], [0, 1, 0]);
    expect(Math.abs(c.AngularVelocity.x[e]! - 1 / I[0]!) * I[0]!).toBeLessThan(1e-12);
    expect(Math.abs(c.Velocity.z[e]! - 1 / m) * m).toBeLessThan(1e-12);
  });
});
