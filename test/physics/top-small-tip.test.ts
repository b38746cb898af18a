import { addBody, addPlane, addShape3D, createPhysicsWorld, slotOf, step } from '@bitphysics/physics';
import { describe, expect, test } from 'vitest';

const G = 9.81;

/**
 * A spinning top standing free on a small sphere tip (issue 9). Last session a 5 mm tip was reported
 * to precess 12 to 17 % slow (1 cm and up within 1.2 %), which is why lab-rigid-3d's top stands on a
 * 1.5 cm tip. Measured again at 9875d05 and at 8b96651 (where it was reported), it does not reproduce
 * at the lab's settings: the lab's top on a 5 mm tip precesses within 0.04 % of the steady root at its
 * 16 substeps (1 cm: 0.04 %, 1.5 cm: 0.06 %), and this test's top at dt 1/240 moves the same at every
 * tip size to 1e-10. The normal impulse is right too: a step's solver substeps sum to m g h (reading
 * only the last substep's, as `forEachContact` gives it for a 3D shape, shows 0.67 m g h_s on the lab's top, the
 * first substep carrying 2.0, probably as the integrator turns the body by Euler's equations before the contacts
 * are solved). What did depend on the tip was at the default step (dt 1/60): the disc's spinning rim
 * threw the top up, the more the smaller its tip (last test; fixed in shape3d-collision.ts).
 */
describe('a top on a small sphere tip', () => {
  // The ball-joint precession test's top (rigid-3d-motion.test.ts), freed: a disc (radius 0.5 m, 0.1 m
  // thick, 1000 kg/m^3) whose centre is r = 0.3 m up its axis from the centre of a sphere tip of radius
  // rho (a separate shape of the same body, of negligible mass), standing on a smooth floor, tilted
  // 0.3 rad, spinning at 100 rad/s.
  test.each([0.005, 0.015, 0.05])(
    'tip radius %s m: precesses at m g r / (I omega) (2 %), its centre of mass stays on its vertical and its tilt holds',
    (rho) => {
      const world = createPhysicsWorld({ dimensions: 3, gravity: [0, -G, 0], sleep: false, dt: 1 / 240 });
      addPlane(world, { normal: [0, 1, 0], friction: 0 });
      const th = 0.3,
        r = 0.3,
        omega = 100;
      const a = [Math.sin(th), Math.cos(th), 0];
      // The body's origin at the tip sphere's centre, which touches the floor; the axis tilted toward +x.
      const top = addBody(world, { position: [0, rho, 0], orientation: [0, 0, Math.sin(-th / 2), Math.cos(-th / 2)] });
      addShape3D(world, top, { type: 'cylinder', radius: 0.5, halfHeight: 0.05, offset: [0, r, 0], density: 1000 });
      addShape3D(world, top, { type: 'sphere', radius: rho, density: 1e-6, friction: 0 });
      const c = world.components,
        e = slotOf(top);
      const m = c.Mass.value[e]!;
      // The centre of mass is where the body now is: r from the tip sphere's centre (1e-6: the tip's mass).
      const cx = c.Position.x[e]!,
        cy = c.Position.y[e]!,
        cz = c.Position.z[e]!;
      expect(Math.abs(Math.hypot(cx, cy - rho, cz) - r)).toBeLessThan(1e-6);
      // The disc's largest principal moment is the one about its axis; the smallest, across it about the
      // centre of mass (the free top turns about its centre of mass: its tip slides on the smooth floor).
      const I3 = 1 / Math.min(c.InertiaTensor.invX[e]!, c.InertiaTensor.invY[e]!, c.InertiaTensor.invZ[e]!);
      const I1 = 1 / Math.max(c.InertiaTensor.invX[e]!, c.InertiaTensor.invY[e]!, c.InertiaTensor.invZ[e]!);
      const Omega = (m * G * r) / (I3 * omega);
      // The steady root of m g r = Omega (I3 omega - I1 Omega cos th) (Goldstein sec. 5.7), 0.15 % above
      // the gyroscope formula here; started on it (spin less Omega cos th along the axis, plus Omega about
      // the vertical), so nutation stays small.
      const L = I3 * omega,
        cos = Math.cos(th);
      const steady = (L - Math.sqrt(L * L - 4 * I1 * cos * m * G * r)) / (2 * I1 * cos);
      const s = omega - steady * cos;
      c.AngularVelocity.x[e] = s * a[0]!;
      c.AngularVelocity.y[e] = s * a[1]! + steady;
      c.AngularVelocity.z[e] = 0;
      const O = c.Orientation;
      const axis = (): number[] => {
        const x = O.x[e]!,
          y = O.y[e]!,
          z = O.z[e]!,
          w = O.w[e]!;
        return [2 * (x * y - z * w), 1 - 2 * (x * x + z * z), 2 * (y * z + x * w)];
      };
      const heading = (): number => {
        const u = axis();
        return Math.atan2(-u[2]!, u[0]!);
      };
      const start = heading();
      const steps = 240; // 1 s: about 0.24 rad of precession
      for (let i = 0; i < steps; i++) step(world);
      const rate = (heading() - start) / world.time;
      // The gyroscope formula within 2 % (the goal; measured -0.005 % at every tip size, the same
      // to 1e-10), and the steady root within 0.5 % (measured -0.12 %).
      expect(Math.abs(rate / Omega - 1)).toBeLessThan(0.02);
      expect(Math.abs(rate / steady - 1)).toBeLessThan(0.005);
      // A smooth floor pushes only upward: the centre of mass keeps its x and z (1 mm; measured 0).
      expect(Math.hypot(c.Position.x[e]! - cx, c.Position.z[e]! - cz)).toBeLessThan(1e-3);
      // The tip stays on the floor: the tip sphere's lowest point, centre of mass - r axis - rho, within
      // 0.1 mm of the floor (measured 0.03 mm into it: the soft contact's give), neither sunk nor lifted.
      const u = axis();
      expect(Math.abs(c.Position.y[e]! - r * u[1]! - rho)).toBeLessThan(1e-4);
      // The tilt holds within 0.03 rad (measured +0.0195 at every tip size: the one-substep solver gains
      // tilt at a rate first order in the step, as the ball-joint top does).
      expect(Math.abs(Math.acos(u[1]!) - th)).toBeLessThan(0.03);
    },
  );

  test("at the default step (dt 1/60, one substep) the 5 mm-tipped top stays on its tip: its disc's spinning rim does not throw it up", () => {
    // The same top at 100 rad/s is 1.67 rad of spin a step. The disc's rim points within the speculative
    // margin were followed as points of the body, so those turning down "hit" the floor a step ahead and
    // threw the top up (measured before the fix: 0.46 m with a 5 mm tip, 0.36 m with 1.5 cm, 4 cm with
    // 5 cm; the precession then -116 %, chaotic). shape3d-collision.ts now moves them onto the disc's
    // meridian plane (the round rim does not move under its own spin).
    const world = createPhysicsWorld({ dimensions: 3, gravity: [0, -G, 0], sleep: false });
    addPlane(world, { normal: [0, 1, 0], friction: 0 });
    const rho = 0.005,
      th = 0.3,
      r = 0.3,
      omega = 100;
    const top = addBody(world, { position: [0, rho, 0], orientation: [0, 0, Math.sin(-th / 2), Math.cos(-th / 2)] });
    addShape3D(world, top, { type: 'cylinder', radius: 0.5, halfHeight: 0.05, offset: [0, r, 0], density: 1000 });
    addShape3D(world, top, { type: 'sphere', radius: rho, density: 1e-6, friction: 0 });
    const c = world.components,
      e = slotOf(top),
      m = c.Mass.value[e]!;
    const I3 = 1 / Math.min(c.InertiaTensor.invX[e]!, c.InertiaTensor.invY[e]!, c.InertiaTensor.invZ[e]!);
    const I1 = 1 / Math.max(c.InertiaTensor.invX[e]!, c.InertiaTensor.invY[e]!, c.InertiaTensor.invZ[e]!);
    const Omega = (m * G * r) / (I3 * omega),
      L = I3 * omega,
      cos = Math.cos(th);
    const steady = (L - Math.sqrt(L * L - 4 * I1 * cos * m * G * r)) / (2 * I1 * cos);
    c.AngularVelocity.x[e] = (omega - steady * cos) * Math.sin(th);
    c.AngularVelocity.y[e] = (omega - steady * cos) * cos + steady;
    const O = c.Orientation;
    const axis = (): number[] => {
      const x = O.x[e]!,
        y = O.y[e]!,
        z = O.z[e]!,
        w = O.w[e]!;
      return [2 * (x * y - z * w), 1 - 2 * (x * x + z * z), 2 * (y * z + x * w)];
    };
    const start = Math.atan2(-axis()[2]!, axis()[0]!);
    let worstGap = 0,
      heading = start,
      last = start;
    for (let i = 0; i < 60; i++) {
      step(world);
      const u = axis(),
        hd = Math.atan2(-u[2]!, u[0]!);
      let d = hd - last;
      d -= 2 * Math.PI * Math.round(d / (2 * Math.PI));
      heading += d;
      last = hd;
      // The tip sphere's lowest point against the floor, every step.
      worstGap = Math.max(worstGap, Math.abs(c.Position.y[e]! - r * u[1]! - rho));
    }
    // On the floor within 1 mm all along (measured 0.44 mm into it at most).
    expect(worstGap).toBeLessThan(1e-3);
    // The gyroscope formula within 2 % (measured -1.4 %: at this step the tilt drifts, first order in the
    // step, from 0.30 to 0.39 rad in the second, as the one-substep ball-joint top's does; 0.1 rad allowed).
    expect(Math.abs((heading - start) / world.time / Omega - 1)).toBeLessThan(0.02);
    expect(Math.abs(Math.acos(axis()[1]!) - th)).toBeLessThan(0.1);
  });
});
