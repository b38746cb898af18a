/**
 * The shell recipes of the fireworks show (games/fireworks/recipes.ts) burst as their names say,
 * checked on the physics state right after the burst and over the stars' lives: a ring's stars all
 * leave at one speed, a peony's (a sphere seen from the side) from 0 to its largest; crossette stars
 * split into four; willow stars, under four times the drag, fall at a terminal speed half a peony
 * star's; strobes flash again where they die; no burst, held as long as it grows, is wider than the
 * sky; the auto-show plays PROGRAMME in order.
 */

import { type PhysicsWorld, slotOf } from '@bitphysics/physics';
import { query } from 'bitecs';
import { describe, expect, test } from 'vitest';
import { RECIPE_NAMES, RECIPES, type RecipeName } from '../../games/fireworks/recipes';
import {
  BURST_REFERENCE_WIDTH,
  BURST_SPEED,
  createFireworks,
  type FireworksShow,
  launchShell,
  MAX_HOLD,
  PALETTE,
  PROGRAMME,
  recipeEmitter,
  SPARK_MASS,
  stepFireworks,
} from '../../games/fireworks/show';

/** Stars alive made by emitter `em` (Particle.emitter holds the emitter's slot). */
function starsOf(world: PhysicsWorld, em: number): number[] {
  const P = world.components.Particle;
  return Array.from(query(world, [P])).filter((e) => P.emitter[e] === slotOf(em));
}

/**
 * A quiet show (no opening, no auto-show, no drag unless asked) with one shell of `recipe` launched;
 * steps until it bursts. The sky is BURST_REFERENCE_WIDTH wide, where stars leave at their nominal
 * speeds under the nominal drag (a wider sky scales both).
 */
function burstOne(recipe: RecipeName, drag = 0) {
  const { world, show } = createFireworks({ seed: 5, opening: 0, sparks: 400, drag, sky: { width: BURST_REFERENCE_WIDTH, height: 70 } });
  launchShell(world, show, 40, 40, 0, recipe);
  let v: [number, number] = [0, 0];
  const shell = show.shellIds[0]!;
  // The shell's linear drag rate, 1/s (a 1 kg body: k = c).
  const c = world.components.LinearDrag.k[slotOf(shell)]!;
  for (let i = 0; i < 600 && show.bursts === 0; i++) {
    v = [world.components.Velocity.x[slotOf(shell)]!, world.components.Velocity.y[slotOf(shell)]!];
    stepFireworks(world, show);
  }
  expect(show.bursts).toBe(1);
  // v was read before the burst step, which added the shell's drag -c v dt and gravity -g dt.
  const dt = world.dt;
  v = [v[0] - c * v[0] * dt, v[1] - c * v[1] * dt - 9.81 * dt];
  return { world, show, shellVelocity: v, em: recipeEmitterOf(world, show, recipe) };
}

function recipeEmitterOf(world: PhysicsWorld, show: FireworksShow, recipe: RecipeName): number {
  // The shell's colour is drawn at launch; find the emitter that has stars.
  for (let c = 0; c < PALETTE.length; c++) {
    const em = recipeEmitter(world, show, RECIPES[recipe], c);
    if (starsOf(world, em).length > 0) return em;
  }
  throw new Error(`no stars of ${recipe}`);
}

describe('shell recipes', () => {
  test('ring: every star leaves at the same speed relative to the shell (to 1e-9); peony: a sphere seen side-on, speeds from near 0 to 16 m/s', () => {
    const ring = burstOne('ring');
    const V = ring.world.components.Velocity;
    const speeds = starsOf(ring.world, ring.em).map((e) => Math.hypot(V.x[e]! - ring.shellVelocity[0], V.y[e]! - ring.shellVelocity[1]));
    expect(speeds.length).toBe(Math.round(400 * RECIPES.ring.stars));
    for (const v of speeds) expect(Math.abs(v - RECIPES.ring.speed[0] * BURST_SPEED)).toBeLessThan(1e-9);
    const peony = burstOne('peony');
    const P = peony.world.components.Velocity;
    const ps = starsOf(peony.world, peony.em).map((e) => Math.hypot(P.x[e]! - peony.shellVelocity[0], P.y[e]! - peony.shellVelocity[1]));
    expect(Math.max(...ps) - Math.min(...ps)).toBeGreaterThan(0.5 * BURST_SPEED);
    // Its stars leave at 0.8 to 1 of the burst speed in 3D; seen side-on, a star moving near the line
    // of sight shows a small speed: P(v sin(theta) < 0.3 v_max) is about 6%, some 23 of 400 stars (a flat
    // burst would have none below 0.8).
    expect(Math.min(...ps)).toBeLessThan(0.3 * BURST_SPEED);
  });

  test('crossette: every star that dies splits into four', () => {
    const { world, show, em } = burstOne('crossette');
    const n = starsOf(world, em).length;
    expect(n).toBeGreaterThan(0);
    for (let i = 0; i < 60; i++) stepFireworks(world, show); // lifetime 0.6 to 0.8 s: all have split
    expect(starsOf(world, em).length).toBe(0);
    const P = world.components.Particle;
    const children = Array.from(query(world, [P])).filter((e) => P.generation[e] === 1);
    expect(children.length).toBe(4 * n);
  });

  test('willow: under 4 x the drag its stars fall at terminal speed sqrt(m g / 4k), half a peony star', () => {
    expect(RECIPES.willow.drag).toBe(4);
    const k = 5e-5;
    const vt = Math.sqrt((SPARK_MASS * 9.81) / (RECIPES.willow.drag * k));
    const { world, show, em } = burstOne('willow', k);
    for (let i = 0; i < 200; i++) stepFireworks(world, show); // 3.3 s (within the 3.5 s lifetime), 4.7 time constants of vt / g = 0.71 s
    const V = world.components.Velocity;
    const vs = starsOf(world, em).map((e) => -V.y[e]!);
    expect(vs.length).toBeGreaterThan(10);
    for (const v of vs) expect(v / vt).toBeCloseTo(1, 2);
  });

  test('strobe: a star flashes again where it dies, for five generations', () => {
    const { world, show } = burstOne('strobe');
    const P = world.components.Particle;
    let deepest = 0;
    for (let i = 0; i < 150; i++) {
      stepFireworks(world, show);
      for (const e of query(world, [P])) deepest = Math.max(deepest, P.generation[e]!);
    }
    expect(deepest).toBe(5);
  });

  test('no burst is wider than the sky: at the longest hold, 95 % of the stars stay within half its width of the centre', () => {
    // The issue this answers: a held shell's burst was larger than the sky (a held chrysanthemum's
    // stars spread 0.6 of the sky's width either side, a palm's 0.85). Measured now: 0.21 (willow,
    // strobe) to 0.48 (crackle). The phone's sky (BURST_REFERENCE_WIDTH); a wider sky scales the
    // bursts with it (./fireworks.test.ts). Over the stars' whole lives, crackles included.
    const width = BURST_REFERENCE_WIDTH;
    for (const recipe of RECIPE_NAMES) {
      const { world, show } = createFireworks({ seed: 31, opening: 0, sparks: 200, generations: 2, sky: { width, height: 124 } });
      launchShell(world, show, width / 2, 80, MAX_HOLD, recipe);
      while (show.bursts === 0) stepFireworks(world, show);
      const cx = show.flashes[0]!;
      const P = world.components.Particle,
        X = world.components.Position;
      let widest = 0;
      for (let i = 0; i < 320; i++) {
        stepFireworks(world, show);
        if (i % 4 !== 0) continue;
        const d = Array.from(query(world, [P]))
          .map((e) => Math.abs(X.x[e]! - cx))
          .sort((a, b) => a - b);
        if (d.length < 20) break;
        widest = Math.max(widest, d[Math.floor(0.95 * d.length)]!);
      }
      expect(widest / width, recipe).toBeLessThan(0.5);
      expect(widest / width, recipe).toBeGreaterThan(0.15);
    }
  });

  test('the auto-show plays PROGRAMME in order, every recipe appears, and an unknown recipe is refused', () => {
    const { world, show } = createFireworks({ seed: 9, opening: 0, autoShow: true, sparks: 50 });
    const seen: string[] = [];
    let launched = 0;
    for (let i = 0; i < 60 * 30; i++) {
      stepFireworks(world, show);
      for (; launched < show.launched; launched++)
        seen.push(RECIPE_NAMES[show.shellRecipe[show.shellCount - (show.launched - launched)]!]!);
    }
    const expected = PROGRAMME.flatMap((a) => Array.from({ length: a.count }, () => a.recipe));
    expect(seen.slice(0, expected.length)).toEqual(expected);
    expect(new Set(seen)).toEqual(new Set(RECIPE_NAMES));
    expect(() => launchShell(world, show, 10, 10, 0, 'rocket' as RecipeName)).toThrow(/recipe must be one of peony, .*got rocket/);
  });
});
