/**
 * rotating-cube's free-spin challenge (games/rotating-cube/spin-challenge.ts), headless, on the cube's
 * pivot: left alone its slow tumble reaches no target; the keys' torque (0.5 N m, as the game's) held
 * the way ω's tip must go, then let go, reaches each target and holds it, so the round is won; stars
 * by the time taken.
 */

import { addSystem, createPhysicsWorld, step } from '@bitphysics/physics';
import { describe, expect, it } from 'vitest';
import { buildRotatingCube, rotatingCubeWorldOptions, torqueCouple } from '../../games/rotating-cube/scene';
import { SPIN_HOLD, SPIN_RATE, SPIN_TARGETS, SPIN_TOLERANCE, SpinChallenge, spinTargets } from '../../games/rotating-cube/spin-challenge';

/** The game's key torque on the pivot, N m. */
const KEY_TORQUE = 0.5;

/** A pivot world with the cube and a torque the caller sets, and the challenge checked after every step. */
function pivot(targets: [number, number, number][]) {
  const world = createPhysicsWorld(rotatingCubeWorldOptions('cube'));
  const h = buildRotatingCube(world, { mode: 'cube' });
  const torque = [0, 0, 0];
  addSystem(
    world,
    'forces',
    torqueCouple(h.body, () => torque),
  );
  const spins = new SpinChallenge(targets);
  addSystem(world, 'finalize', (w) => {
    spins.update(w, h.body);
  });
  return { world, body: h.body, torque, spins };
}

describe('rotating-cube free-spin challenge', () => {
  const right = [Math.SQRT1_2, 0, -Math.SQRT1_2],
    up = [0, 1, 0];

  it('targets: SPIN_RATE about up, about right, then between up and -right; a non-unit axis throws', () => {
    const t = spinTargets(right, up);
    expect(t.length).toBe(SPIN_TARGETS);
    expect(t[0]).toEqual([0, SPIN_RATE, 0]);
    for (const v of t) expect(Math.hypot(...v)).toBeCloseTo(SPIN_RATE, 12);
    expect(() => spinTargets([1, 1, 0], up)).toThrow(/spinTargets: right/);
  });

  it('left alone the tumble reaches no target in 30 s; before the first input nothing counts', () => {
    const { world, spins } = pivot(spinTargets(right, up));
    for (let i = 0; i < 600; i++) step(world);
    expect(spins.off).toBe(0);
    spins.start(world.time);
    for (let i = 0; i < 1800; i++) step(world);
    expect([spins.target, spins.won]).toEqual([0, false]);
    // The tumble (0.9 rad/s) lies over 1 rad/s from the first target.
    expect(spins.off).toBeGreaterThan(1);
  });

  it("the keys' torque held towards each target (the spin stopped first, X) and let go reaches it and holds it: won in about 3 x (0.7 + 2) s, three stars", () => {
    const { world, body, torque, spins } = pivot(spinTargets(right, up));
    const W = world.components.AngularVelocity;
    spins.start(world.time);
    const I = 1 / 6;
    for (let k = 0; k < SPIN_TARGETS; k++) {
      const aim = spins.targets[k]!;
      // X: stop; then the torque along the target for SPIN_RATE I / KEY_TORQUE s (w grows at KEY_TORQUE / I along it).
      W.x[body] = W.y[body] = W.z[body] = 0;
      const steps = Math.round(((SPIN_RATE * I) / KEY_TORQUE) * 60);
      for (let i = 0; i < 3; i++) torque[i] = (KEY_TORQUE * aim[i]!) / SPIN_RATE;
      for (let i = 0; i < steps; i++) step(world);
      torque.fill(0);
      expect(spins.off).toBeLessThan(SPIN_TOLERANCE);
      for (let i = 0; i < 60 * SPIN_HOLD + 5 && spins.target === k; i++) step(world);
      expect(spins.target).toBe(k + 1);
    }
    expect(spins.won).toBe(true);
    expect(spins.time(world.time)).toBeCloseTo(SPIN_TARGETS * (SPIN_HOLD + (SPIN_RATE * I) / KEY_TORQUE), 0);
    expect(spins.stars()).toBe(3);
  });
});
