import { createCloth, createPhysicsWorld, pinClothPoint, setTimeStep, setWind, slotOf, step, windAt } from '@bitphysics/physics';
import { describe, expect, test } from 'vitest';
import { cosine } from '../../packages/physics/src/math/cosine.js';

describe('cloth solver', () => {
  test("a compliant link holds its load by Hooke's law: extension = compliance x weight", () => {
    // A 2 x 2 cloth pinned along its top: each lower point hangs on a vertical structural link of rest
    // length 1 m and compliance alpha (1 / stiffness); the lower horizontal link carries no load. In
    // small-step XPBD the rest state is exactly alpha m g below the rest length (Macklin et al. 2019: the
    // substep's gravity displacement g h^2 is undone by w dlambda with dlambda = -C / (w + alpha / h^2)).
    // Chosen for a 5% stretch, where a square-root-free projection that is only first-order right
    // (Jakobsen's, 2.5% off at 5% strain) would be 1.2 mm out; the solver's rational step is 6e-4 of
    // the strain off, 3e-5 m here. Tolerance 1e-4 m, with the oscillation damped by drag (tau ~ 0.17 s).
    const g = 9.81,
      m = 0.25,
      alpha = 0.05 / (m * g);
    const world = createPhysicsWorld({ dimensions: 2, gravity: [0, -g], capacity: 32 });
    const cloth = createCloth(world, {
      columns: 2,
      rows: 2,
      width: 1,
      height: 1,
      origin: [0, 2],
      mass: 4 * m,
      compliance: alpha,
      shearCompliance: null,
      bendCompliance: null,
      drag: 3,
    });
    for (let i = 0; i < 240; i++) step(world);
    const y = world.components.Position.y;
    for (const i of [2, 3]) expect(Math.abs(2 - y[slotOf(cloth.points[i]!)]! - (1 + alpha * m * g))).toBeLessThan(1e-4);
    expect(Math.abs(world.cloth.maxStretch - 0.05)).toBeLessThan(1e-4);
  });

  test('the per-link factors it keeps between steps are the ones it would compute afresh (pins, releases, a new dt)', () => {
    // The solver reuses its per-link factors while the links, the points' inverse masses and h_s stay the
    // same. Reference: the same cloth with the cache emptied before every step (preparedVersion = -1), so
    // the factors are computed afresh each step. Holding a point (inverse mass 0), letting it go and
    // changing dt must all reach the factors: the two runs must agree to the bit (tolerance 0).
    const run = (fresh: boolean, hold = true): Float64Array => {
      const world = createPhysicsWorld({ dimensions: 2, gravity: [0, -9.81], capacity: 512 });
      const cloth = createCloth(world, { columns: 8, rows: 8, width: 1, height: 1, origin: [0, 2], compliance: 1e-4 });
      const grabbed = cloth.points[7 * 8 + 3]!;
      const n = cloth.points.length,
        out = new Float64Array(4 * n),
        p = world.components.Position;
      const record = (at: number): void =>
        cloth.points.forEach((h, i) => {
          out[at + 2 * i] = p.x[slotOf(h)]!;
          out[at + 2 * i + 1] = p.y[slotOf(h)]!;
        });
      for (let i = 0; i < 90; i++) {
        if (hold && i === 20) pinClothPoint(world, grabbed, [0.4, 0.6]);
        if (hold && i === 50) pinClothPoint(world, grabbed, null);
        if (i === 70) setTimeStep(world, 1 / 120);
        if (fresh) world.cloth.preparedVersion = -1;
        step(world);
        if (i === 49) record(0);
      }
      record(2 * n); // positions while held (step 49), then at the end
      return out;
    };
    const kept = run(false),
      fresh = run(true);
    expect(Array.from(kept)).toEqual(Array.from(fresh));
    // The hold changed the motion (by more than 1 cm somewhere), so the comparison covers it.
    const free = run(false, false);
    expect(Math.max(...kept.map((v, i) => Math.abs(v - free[i]!)))).toBeGreaterThan(0.01);
  });
});

describe("cosine (the wind's turbulence)", () => {
  test('matches Math.cos within its stated bound, 5e-14 + 2.4e-16 |x|', () => {
    let worst = 0;
    for (let i = 0; i <= 200000; i++) {
      const x = -1000 + i * 0.0100003;
      const err = Math.abs(cosine(x) - Math.cos(x)) - 2.4e-16 * Math.abs(x);
      if (err > worst) worst = err;
    }
    expect(worst).toBeLessThan(5e-14);
    expect(Math.abs(cosine(0) - 1)).toBeLessThan(5e-14);
    expect(Math.abs(cosine(Math.PI) + 1)).toBeLessThan(5e-14);
    expect(cosine(Infinity)).toBeNaN();
    expect(cosine(NaN)).toBeNaN();
  });

  test('windAt sums the turbulent modes it documents (checked with Math.cos)', () => {
    const world = createPhysicsWorld({ dimensions: 2, gravity: [0, 0] });
    setWind(world, { velocity: [4, 0], turbulence: { intensity: 1, lengthScale: 2, timeScale: 1, seed: 3, modes: 8 } });
    const w = world.laws.wind,
      out = new Float64Array(3);
    const amp = w.intensity * Math.sqrt(4 / w.modes);
    for (const [x, y, t] of [
      [0.3, 6.1, 0],
      [5.2, -1.4, 12.5],
      [300, 200, 3600],
    ] as const) {
      let u = 4,
        v = 0;
      for (let m = 0; m < w.modes; m++) {
        const d = w.modeData,
          o = 8 * m;
        const c = amp * Math.cos(d[o]! * x + d[o + 1]! * y - d[o + 3]! * t + d[o + 4]!);
        u += c * d[o + 5]!;
        v += c * d[o + 6]!;
      }
      windAt(world, x, y, 0, t, out);
      expect(Math.abs(out[0]! - u)).toBeLessThan(1e-10);
      expect(Math.abs(out[1]! - v)).toBeLessThan(1e-10);
    }
  });
});
