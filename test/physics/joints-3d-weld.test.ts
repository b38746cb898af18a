import {
  addBallJoint3D,
  addBody,
  addFixedJoint3D,
  addHingeJoint3D,
  addShape3D,
  createPhysicsWorld,
  forEachContact,
  type PhysicsWorld,
  slotOf,
  step,
} from '@bitphysics/physics';
import { describe, expect, test } from 'vitest';

/** Angle of B's orientation relative to A's, rad: 2 acos |w| of conj(q_A) q_B (both start unturned). */
function relativeAngle(world: PhysicsWorld, a: number, b: number): number {
  const O = world.components.Orientation;
  const x1 = -O.x[a]!,
    y1 = -O.y[a]!,
    z1 = -O.z[a]!,
    w1 = O.w[a]!,
    x2 = O.x[b]!,
    y2 = O.y[b]!,
    z2 = O.z[b]!,
    w2 = O.w[b]!;
  const rw = w1 * w2 - x1 * x2 - y1 * y2 - z1 * z2;
  return 2 * Math.acos(Math.min(1, Math.abs(rw)));
}

const DEG = Math.PI / 180;

describe('3D fixed joint between two dynamic bodies', () => {
  test("a 1 m, 1 kg lever welded to a dynamic carrier bends by the soft rows' static deflection, whatever the substep count", () => {
    // Carrier A: an 8 kg cube (0.2 m, I = 8 (0.2^2 + 0.2^2) / 12 = 0.0533 kg m^2) on a hinge about y to the
    // world (dynamic, free to spin about y only). Lever B: 1 x 0.02 x 0.02 m, 1 kg (I_z = (1 + 0.0004) / 12),
    // welded to A's face and sticking out along x. The weld carries B's weight torque about B's centre,
    // tau = m g L / 2 = 4.905 N m (the point rows carry the force m g at the anchor, 0.5 m from B's centre).
    // A soft row of stiffness f (Box2D v3 b2MakeSoft, warm-started) at rest deflects like a spring of
    // stiffness m_eff (2 pi f)^2, m_eff = 1 / (1 / I_A + 1 / I_B): theta = tau (1 / I_A + 1 / I_B) / (2 pi f)^2,
    // with f = 60 Hz (the joint stiffness; below a quarter of the substep rate for 4 and 8 substeps at 60 Hz).
    // That is 0.0608 degree. Tolerance 3 %: the formula is the rows' exact fixed point; what is left after
    // 2 s is the lever's settling (damping ratio 2) and the carrier's own soft hinge.
    const IA = (8 * (0.04 + 0.04)) / 12,
      IB = (1 * (1 + 0.0004)) / 12,
      tau = 1 * 9.81 * 0.5,
      omega = 2 * Math.PI * 60;
    const expected = (tau * (1 / IA + 1 / IB)) / (omega * omega);
    for (const solverSubsteps of [4, 8]) {
      const world = createPhysicsWorld({ dimensions: 3, gravity: [0, -9.81, 0], sleep: false, dt: 1 / 60, solverSubsteps });
      const a = addBody(world, { position: [0, 0, 0] });
      addShape3D(world, a, { type: 'box', halfExtents: [0.1, 0.1, 0.1], density: 1000 });
      addHingeJoint3D(world, { b: a, anchor: [0, 0, 0], axis: [0, 1, 0] });
      const b = addBody(world, { position: [0.6, 0, 0] });
      addShape3D(world, b, { type: 'box', halfExtents: [0.5, 0.01, 0.01], density: 1 / (1 * 0.02 * 0.02) });
      addFixedJoint3D(world, { a, b, anchor: [0.1, 0, 0] });
      for (let i = 0; i < 120; i++) step(world);
      const angle = relativeAngle(world, slotOf(a), slotOf(b));
      expect(Math.abs(angle - expected) / expected).toBeLessThan(0.03);
      expect(angle).toBeLessThan(0.1 * DEG); // a small fraction of a degree
    }
  });

  test('two welded boxes that overlap at the weld do not collide (collideConnected false): the weld holds them within 0.1 degree while they swing', () => {
    // An L: a 1 m upright (10 kg) hung from the world by a ball joint, a 0.6 m arm (6 kg) welded across its
    // lower end; the boxes overlap there by 5 x 5 cm. Released sideways it swings through 147 degrees and
    // spins at 2-3 rad/s. Before 3D joints had collideConnected (default false), the overlap's contact
    // fought the weld (7,600 N along the upright) and the arm turned up to 0.78 degree relative to the
    // upright, more with more substeps (0.97 with 8). Now 0.049 degree (measured), the soft rows' deflection
    // under the swing's loads (as the lever above); 0.1 degree allowed.
    const build = (collideConnected: boolean): { w: PhysicsWorld; a: number; b: number; ha: number; hb: number } => {
      const w = createPhysicsWorld({ dimensions: 3, gravity: [0, -9.81, 0], sleep: false, dt: 1 / 240 });
      const a = addBody(w, { position: [0, -0.5, 0] });
      addShape3D(w, a, { type: 'box', halfExtents: [0.05, 0.5, 0.05], density: 1000 });
      const b = addBody(w, { position: [0.3, -1, 0] });
      addShape3D(w, b, { type: 'box', halfExtents: [0.3, 0.05, 0.05], density: 1000 });
      addBallJoint3D(w, { b: a, anchor: [0, 0, 0] });
      addFixedJoint3D(w, { a, b, anchor: [0, -1, 0], collideConnected });
      w.components.Velocity.z[slotOf(a)] = 1;
      return { w, a: slotOf(a), b: slotOf(b), ha: a, hb: b };
    };
    const pairContacts = (w: PhysicsWorld, a: number, b: number): number => {
      let n = 0;
      forEachContact(w, (c) => {
        if ((c.bodyA === a && c.bodyB === b) || (c.bodyA === b && c.bodyB === a)) n++;
      });
      return n;
    };
    const free = build(false);
    let rel = 0,
      contacts = 0,
      turned = 0;
    const O = free.w.components.Orientation;
    for (let i = 0; i < 240; i++) {
      step(free.w);
      turned = Math.max(turned, 2 * Math.acos(Math.min(1, Math.abs(O.w[free.b]!))));
      contacts += pairContacts(free.w, free.a, free.b);
      rel = Math.max(rel, relativeAngle(free.w, free.a, free.b));
    }
    expect(turned).toBeGreaterThan(0.2); // it did swing (rad)
    expect(contacts).toBe(0);
    expect(rel).toBeLessThan(0.1 * DEG);
    expect(rel).toBeGreaterThan(0); // the weld does carry load
    // collideConnected true: the overlap is a contact again (the old behaviour).
    const touching = build(true);
    step(touching.w);
    expect(pairContacts(touching.w, touching.a, touching.b)).toBeGreaterThan(0);
    expect(() => addFixedJoint3D(touching.w, { a: touching.ha, b: touching.hb, collideConnected: 1 as unknown as boolean })).toThrow(
      /addFixedJoint3D: collideConnected/,
    );
  });
});
