/**
 * The 3D rigid-body lab's scenes, headless: the top precesses at the rate of a heavy symmetric top,
 * dominoes topple in order, the stack of ten stands.
 */
import { describe, expect, it } from 'vitest';
import { createPhysicsWorld, step } from '@bitphysics/physics';
import { buildLab, hasToppled, labWorldOptions, topHeading } from '../../games/lab-rigid-3d/scene';

describe('lab-rigid-3d scenes', () => {
  it('the top precesses at the steady rate of a heavy symmetric top, near m g r / (I3 omega3)', () => {
    const world = createPhysicsWorld(labWorldOptions('top'));
    const h = buildLab(world, 'top', { spin: 60 });
    const t = h.top!;
    let heading = topHeading(world, h), last = heading;
    const start = heading;
    for (let i = 0; i < 60; i++) {
      step(world);
      const hd = topHeading(world, h);
      let d = hd - last;
      d -= 2 * Math.PI * Math.round(d / (2 * Math.PI));
      heading += d; last = hd;
    }
    const measured = (heading - start) / (60 * world.dt);
    // The steady root of m g r = Omega (I3 w3 - I1 Omega cos tilt) at the start (1.427 rad/s): within 3 %
    // (the tilt grows by about 2 degrees in this second as the joint-held top loses energy, first order in
    // the substep, and a larger tilt precesses more slowly).
    expect(Math.abs(measured / t.steadyPrecession - 1)).toBeLessThan(0.03);
    // The gyroscope formula m g r / (I3 w3) leaves out the I1 Omega^2 cos term: it is 5.7 % below the
    // steady root here (I1 cos(tilt) m g r / (I3 w3)^2 = 0.054 to first order), so within 6 % of the measurement.
    expect(t.precession).toBeLessThan(t.steadyPrecession);
    expect(Math.abs(measured / t.precession - 1)).toBeLessThan(0.06);
  });

  it('dominoes topple one after another', () => {
    const world = createPhysicsWorld(labWorldOptions('dominoes'));
    const h = buildLab(world, 'dominoes', { dominoes: 12 });
    const when: number[] = h.parts.map(() => Infinity);
    for (let s = 0; s < 120; s++) {
      step(world);
      for (let i = 0; i < h.parts.length; i++) if (when[i] === Infinity && hasToppled(world, h, i)) when[i] = s;
    }
    // At least eight fall in 2 s, each no earlier than the one before it.
    const fallen = when.filter((s) => s < Infinity).length;
    expect(fallen).toBeGreaterThanOrEqual(8);
    for (let i = 1; i < fallen; i++) expect(when[i]).toBeGreaterThanOrEqual(when[i - 1]!);
  });

  it('the stack of ten stands: the top box moves less than 2 cm in 2 s', () => {
    const world = createPhysicsWorld(labWorldOptions('stack'));
    const h = buildLab(world, 'stack');
    const P = world.components.Position, b = h.main;
    const x0 = P.x[b]!, y0 = P.y[b]!, z0 = P.z[b]!;
    for (let i = 0; i < 120; i++) step(world);
    expect(Math.hypot(P.x[b]! - x0, P.y[b]! - y0, P.z[b]! - z0)).toBeLessThan(0.02);
  });
});
