import { addBallJoint3D, addBody, addPlane, addShape3D, createPhysicsWorld, slotOf, step } from '@bitphysics/physics';
import { describe, expect, test } from 'vitest';

const G = 9.81;

describe('3D rigid motion against independent laws', () => {
  test('a spinning top on its tip precesses at Omega = m g r / (I omega) (2 %)', () => {
    // A disc (radius 0.5 m, 0.1 m thick) on a massless stem: its centre r = 0.3 m from the tip, which a
    // ball joint pins to the world; tilted 0.3 rad from the vertical, spinning at 100 rad/s about its axis.
    const world = createPhysicsWorld({ dimensions: 3, gravity: [0, -G, 0], sleep: false, dt: 1 / 240 });
    const th = 0.3,
      r = 0.3,
      omega = 100;
    const a = [Math.sin(th), Math.cos(th), 0];
    const top = addBody(world, { position: [r * a[0]!, r * a[1]!, 0], orientation: [0, 0, Math.sin(-th / 2), Math.cos(-th / 2)] });
    addShape3D(world, top, { type: 'cylinder', radius: 0.5, halfHeight: 0.05, density: 1000 });
    addBallJoint3D(world, { b: top, anchor: [0, 0, 0] });
    const c = world.components,
      e = slotOf(top);
    const m = c.Mass.value[e]!;
    // The disc's largest principal moment is the one about its axis.
    const I = 1 / Math.min(c.InertiaTensor.invX[e]!, c.InertiaTensor.invY[e]!, c.InertiaTensor.invZ[e]!);
    // Gyroscope (fast top) limit; the next term, I_pivot Omega cos(th) / (I omega), is 0.3 % here.
    const Omega = (m * G * r) / (I * omega);
    // Start on the steady precession (spin plus Omega about the vertical), so nutation stays small.
    c.AngularVelocity.x[e] = omega * a[0]!;
    c.AngularVelocity.y[e] = omega * a[1]! + Omega;
    c.AngularVelocity.z[e] = 0;
    const azimuth = (): number => Math.atan2(-c.Position.z[e]!, c.Position.x[e]!);
    const steps = 240; // 1 s: about 0.24 rad of precession
    for (let i = 0; i < steps; i++) step(world);
    const measured = azimuth() / world.time;
    expect(Math.abs(measured - Omega) / Omega).toBeLessThan(0.02);
    // The tilt holds (the top neither falls nor rises by more than 0.02 rad).
    expect(Math.abs(Math.acos(c.Position.y[e]! / r) - th)).toBeLessThan(0.02);
  });

  test('a row of dominoes topples in order, each one after the one before it (sleeping on: the far ones are asleep when hit)', () => {
    const world = createPhysicsWorld({ dimensions: 3, gravity: [0, -G, 0] });
    addPlane(world, { normal: [0, 1, 0], friction: 0.6 });
    const n = 8,
      gap = 0.6,
      half = [0.05, 0.5, 0.25];
    const dominoes: number[] = [];
    for (let i = 0; i < n; i++) {
      const d = addBody(world, { position: [i * gap, half[1]!, 0] });
      addShape3D(world, d, { type: 'box', halfExtents: half, density: 600, friction: 0.6 });
      dominoes.push(slotOf(d));
    }
    // Tip the first one over with a spin about -z (toward +x).
    const c = world.components;
    c.AngularVelocity.z[dominoes[0]!] = -2.5;
    // The time each domino's top first passes 0.2 rad of tilt (its centre moves toward +x).
    const fell = new Array<number>(n).fill(Infinity);
    for (let s = 0; s < 400 && fell[n - 1] === Infinity; s++) {
      step(world);
      for (let i = 0; i < n; i++) {
        const e = dominoes[i]!;
        // Tilt from the orientation: the body's y axis against the vertical (cos = 1 - 2 (x^2 + z^2)).
        const tilt = Math.acos(Math.min(1, 1 - 2 * (c.Orientation.x[e]! ** 2 + c.Orientation.z[e]! ** 2)));
        if (fell[i] === Infinity && tilt > 0.2) fell[i] = world.time;
      }
    }
    // Every domino fell, strictly in order (a domino is knocked over only by the one before it).
    for (let i = 0; i < n; i++) expect(fell[i]).toBeLessThan(Infinity);
    for (let i = 1; i < n; i++) expect(fell[i]!).toBeGreaterThan(fell[i - 1]!);
    // And they fell forward: every one ends past its start toward +x, none sideways.
    for (let i = 0; i < n; i++) {
      expect(c.Position.x[dominoes[i]!]!).toBeGreaterThan(i * gap);
      expect(Math.abs(c.Position.z[dominoes[i]!]!)).toBeLessThan(0.05);
    }
  });
});
