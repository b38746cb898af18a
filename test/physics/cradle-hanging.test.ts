import { createPhysicsWorld, step } from '@bitphysics/physics';
import { describe, expect, test } from 'vitest';
import { buildCradle, cradleWorldOptions, liftBalls } from '../../games/lab-newtons-cradle/scene.js';

/**
 * The Newton's cradle lab's scene (games/lab-newtons-cradle/scene.ts) as built for the lab: five
 * equal balls (radius 0.1 m, 1 kg, e = 1, no friction) hung on 1 m strings (distance joints) under
 * g = 9.81 m/s^2, exactly touching (no gap), dt 1/60 s in 2 substeps. The first k = 1, 2 or 3 balls
 * are lifted together to the string angle a and let go at rest. They reach the bottom at the speed
 * u = sqrt(2 g L (1 - cos a)) (energy of the drop) and there, equal masses with e = 1 can keep both
 * momentum and kinetic energy only by sending k balls out of the far end at u while the others stop
 * (Ramtal and Dobre ch. 11; any mechanics text).
 *
 * Angles: 41 from 5 to 80 degrees in equal steps. The lifted balls reach the bottom after a quarter
 * period T/4 = K(sin(a/2)) sqrt(L/g) (K the complete elliptic integral of the first kind), so the first
 * touch falls at a different phase of the 1/120 s substep for each angle; the test checks that these
 * phases cover the substep (no gap wider than 0.1 of it), so a fix that works only when the touch
 * falls at a step's start cannot pass. Before the fix (packages/physics/src/solver/impacts.ts:
 * carriesLoad, ballsMeet, and the spare gap in worlds with joints) the impact stage took the touching
 * balls for resting (a rounding-level contact load, a rounding-level approach of the lifted balls) at
 * some angles and left the chain to the soft substeps: with two or three lifted, 3 and 2 of these 41
 * angles failed (a ball behind the first hit left at up to u, the far ones at 0.77 to 1.16 of u).
 *
 * Tolerances, relative to u: the k far balls' peak speed after the hit within 3 %, the others' under
 * 2 % (the bounds). Measured worst: 0.25 % and 0.24 %; the peak is read at the ends of steps
 * (the far balls leave at the bottom, where their speed peaks) and the strings are soft joint rows.
 */
describe("Newton's cradle hung on strings with touching balls (the lab's scene)", () => {
  const g = 9.81,
    L = 1,
    count = 5;

  /** Complete elliptic integral of the first kind K(k), by the arithmetic-geometric mean. */
  const ellipticK = (k: number): number => {
    let a = 1,
      b = Math.sqrt(1 - k * k);
    for (let i = 0; i < 8; i++) [a, b] = [(a + b) / 2, Math.sqrt(a * b)];
    return Math.PI / (2 * a);
  };

  /** Peak speeds after the hit, as fractions of u, of every ball; and u. */
  const run = (lifted: number, deg: number): { peak: number[]; u: number } => {
    const world = createPhysicsWorld(cradleWorldOptions());
    const h = buildCradle(world);
    const a = (deg * Math.PI) / 180;
    liftBalls(world, h, 0, lifted - 1, -a);
    const u = Math.sqrt(2 * g * L * (1 - Math.cos(a)));
    const V = world.components.Velocity;
    const last = h.balls[count - 1]!;
    const peak = h.balls.map(() => 0);
    let hit = -1;
    for (let k = 0; k < 120; k++) {
      step(world);
      // The step of the hit: the far ball starts to move.
      if (hit < 0 && Math.abs(V.x[last]!) > 0.05 * u) hit = k;
      if (hit >= 0)
        h.balls.forEach((b, i) => {
          peak[i] = Math.max(peak[i]!, Math.hypot(V.x[b]!, V.y[b]!) / u);
        });
      if (hit >= 0 && k >= hit + 6) break;
    }
    expect(hit, `lifted ${lifted}, ${deg} degrees: no hit`).toBeGreaterThan(0);
    return { peak, u };
  };

  const angles = Array.from({ length: 41 }, (_, j) => 5 + (75 * j) / 40);

  test('the first touch falls at phases covering the whole substep', () => {
    const hs = 1 / 60 / 2;
    const phases = angles
      .map((deg) => {
        const t = ellipticK(Math.sin((deg * Math.PI) / 360)) * Math.sqrt(L / g);
        return t / hs - Math.floor(t / hs);
      })
      .sort((x, y) => x - y);
    let widest = phases[0]! + 1 - phases[phases.length - 1]!;
    for (let i = 1; i < phases.length; i++) widest = Math.max(widest, phases[i]! - phases[i - 1]!);
    expect(widest).toBeLessThan(0.1);
  });

  for (const lifted of [1, 2, 3]) {
    test(`${lifted} lifted: ${lifted} ball(s) leave the far end at u (within 3 %), the others stay under 2 % of u, 5 to 80 degrees`, () => {
      for (const deg of angles) {
        const { peak } = run(lifted, deg);
        peak.forEach((p, i) => {
          const where = `lifted ${lifted}, ${deg.toFixed(3)} degrees, ball ${i}: ${p.toFixed(4)} u`;
          if (i >= count - lifted) expect(Math.abs(p - 1), where).toBeLessThan(0.03);
          else expect(p, where).toBeLessThan(0.02);
        });
      }
    });
  }
});
