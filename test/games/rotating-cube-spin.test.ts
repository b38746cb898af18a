/**
 * rotating-cube's free-spin challenge (games/rotating-cube/spin-challenge.ts), headless, on the cube's
 * pivot: left alone its slow tumble reaches no target; the keys' torque (0.5 N m, as the game's) held
 * the way ω's tip must go, then let go, reaches each target and holds it, so the round is won; stars
 * by the time taken. The guides' numbers: the closeness meter falls as ω moves off the target and
 * marks the ball's edge; the torque's alignment with the gap says which way a push takes ω.
 */

import { addSystem, createPhysicsWorld, step } from '@bitphysics/physics';
import { describe, expect, it } from 'vitest';
import { buildRotatingCube, rotatingCubeWorldOptions, torqueCouple } from '../../games/rotating-cube/scene';
import {
  closenessBar,
  pushAlignment,
  SPIN_HOLD,
  SPIN_IN_BALL,
  SPIN_RATE,
  SPIN_TARGETS,
  SPIN_TOLERANCE,
  SpinChallenge,
  spinCloseness,
  spinTargets,
} from '../../games/rotating-cube/spin-challenge';

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

describe('rotating-cube free spin: the guides', () => {
  it("the closeness meter reads 1 on the target, SPIN_IN_BALL at the ball's edge, falls steadily to 0 at twice SPIN_RATE off, and a held push along the gap raises it", () => {
    expect(spinCloseness(0)).toBe(1);
    expect(spinCloseness(SPIN_TOLERANCE)).toBeCloseTo(SPIN_IN_BALL, 12);
    expect(spinCloseness(SPIN_TOLERANCE + 1e-6)).toBeLessThan(SPIN_IN_BALL);
    expect(spinCloseness(2 * SPIN_RATE)).toBe(0);
    expect(spinCloseness(100)).toBe(0);
    // At rest the first target is SPIN_RATE off: under half the meter, so there is room to show progress.
    expect(spinCloseness(SPIN_RATE)).toBeGreaterThan(0.3);
    expect(spinCloseness(SPIN_RATE)).toBeLessThan(0.5);
    let last = 2;
    for (let off = 0; off <= 2 * SPIN_RATE; off += 0.01) {
      const c = spinCloseness(off);
      expect(c).toBeLessThan(last);
      last = c;
    }
    expect(() => spinCloseness(-1)).toThrow(/spinCloseness: off/);
    expect(() => spinCloseness(Number.NaN)).toThrow(/spinCloseness: off/);
    expect(closenessBar(0)).toBe('▱▱▱▱▱▱▱▱▱▱');
    expect(closenessBar(SPIN_IN_BALL)).toBe('▰▰▰▰▰▰▰▰▱▱');
    expect(closenessBar(1)).toBe('▰▰▰▰▰▰▰▰▰▰');
    // In the physics: the key torque held along the gap from rest raises the meter every step until ω's tip is in the ball.
    const { world, spins: challenge, torque, body: b } = pivot(spinTargets([1, 0, 0], [0, 1, 0]));
    challenge.start(0);
    const W = world.components.AngularVelocity;
    // From rest (the cube starts with a slow tumble), the torque about up: the first target's axis.
    W.x[b] = W.y[b] = W.z[b] = 0;
    torque[1] = KEY_TORQUE;
    let before = -1,
      steps = 0;
    for (; steps < 600 && challenge.held === 0; steps++) {
      step(world);
      const gap = [0 - W.x[b]!, SPIN_RATE - W.y[b]!, 0 - W.z[b]!];
      expect(pushAlignment(torque, gap)).toBeCloseTo(1, 6);
      const c = spinCloseness(challenge.off);
      expect(c).toBeGreaterThan(before);
      before = c;
    }
    expect(challenge.held).toBeGreaterThan(0);
    expect(before).toBeGreaterThanOrEqual(SPIN_IN_BALL);
  });

  it('pushAlignment: the cosine between the torque and the gap, 0 when either is nothing', () => {
    expect(pushAlignment([0, 2, 0], [0, 5, 0])).toBeCloseTo(1, 12);
    expect(pushAlignment([0, -2, 0], [0, 5, 0])).toBeCloseTo(-1, 12);
    expect(pushAlignment([1, 0, 0], [0, 5, 0])).toBeCloseTo(0, 12);
    expect(pushAlignment([1, 1, 0], [0, 5, 0])).toBeCloseTo(Math.SQRT1_2, 12);
    expect(pushAlignment([0, 0, 0], [0, 5, 0])).toBe(0);
    expect(pushAlignment([0, 1, 0], [0, 0, 0])).toBe(0);
  });
});
