/**
 * The submarine game's levels (games/submarine/levels.ts): level 1 is the page's course as it was,
 * each later level has more beacons, more mines and narrower passages (the mines nearer the straight
 * way between the beacons), and every level keeps the mines' fairness rules against its own layout:
 * no mine touches a hull run straight from beacon to beacon, none within MINE_BEACON_CLEARANCE of a
 * beacon, above MINE_TOP, or its layout's lead and gap, and a boat heeding the warning passes them.
 * Laid as the page lays them (scene, layCourse, layMines).
 */

import { createPhysicsWorld, step } from '@bitphysics/physics';
import { SUBMARINE_NEUTRAL_FILL, submarine } from '@bitphysics/projects';
import { describe, expect, it } from 'vitest';
import { layCourse } from '../../games/submarine/beacons';
import { currentAt, driftInCurrent } from '../../games/submarine/current';
import { createHelmState, HELM, type HelmInput, type HelmState, steer } from '../../games/submarine/helm';
import { LEVELS, levelCourse } from '../../games/submarine/levels';
import {
  courseOrder,
  hullDistance,
  layMines,
  MINE_BEACON_CLEARANCE,
  MINE_LAYOUT,
  MINE_RADIUS,
  MINE_REACTION,
  MINE_TOP,
  MINE_WAY_CLEARANCE,
  type MineAhead,
  mineAhead,
  touchesMine,
} from '../../games/submarine/mines';

/** Level `level`'s course for page seed `seed` and 6 beacons: beacons (x, y pairs, m), mines, and each mine's distance to the way, m. */
function laid(level: number, seed: number) {
  const course = levelCourse(level, seed, 6);
  const world = createPhysicsWorld(submarine.worldOptions());
  const h = submarine.build(world, { seed: course.seed, count: course.beacons });
  layCourse(h.beacons, h.seabed, course.seed);
  const mines = layMines(h.beacons, h.seabed, course.seed, course.mines);
  const order = courseOrder(h.beacons);
  const way: number[] = mines.map(() => Number.POSITIVE_INFINITY);
  for (let leg = 1; leg < order.length; leg++) {
    const [ax, ay, bx, by] = [
      h.beacons[2 * order[leg - 1]!]!,
      h.beacons[2 * order[leg - 1]! + 1]!,
      h.beacons[2 * order[leg]!]!,
      h.beacons[2 * order[leg]! + 1]!,
    ];
    // The hull's centre run straight along the leg, every 0.2 %.
    for (let f = 0; f <= 1; f += 0.002)
      mines.forEach((m, i) => {
        const x = ax + f * (bx - ax),
          y = ay + f * (by - ay);
        expect(touchesMine(x, y, 0, m.x, m.y)).toBe(false);
        way[i] = Math.min(way[i]!, Math.hypot(m.x - x, m.y - y));
      });
  }
  return { h, course, mines, way, order };
}

describe('submarine levels', () => {
  it('level 1 is the page course as it was: its seed, its beacons, the mines of MINE_LAYOUT', () => {
    expect(levelCourse(1, 7, 6)).toEqual({ seed: 7, beacons: 6, mines: MINE_LAYOUT });
    expect(LEVELS.length).toBeGreaterThanOrEqual(3);
    expect(() => levelCourse(0, 1, 6)).toThrow(/levelCourse: number must be an integer from 1 to 3, got 0/);
    expect(() => levelCourse(1, Number.NaN, 6)).toThrow(/levelCourse: seed must be finite/);
    expect(() => levelCourse(1, 1, 0)).toThrow(/levelCourse: beacons must be an integer/);
    expect(() => levelCourse(3, 1, 20).beacons).not.toThrow();
    expect(levelCourse(3, 1, 20).beacons).toBe(20);
  });

  it('each level has more beacons, more mines and narrower passages than the one before, on seeds 1 to 5, and keeps the mines fair', () => {
    const totals: { beacons: number; mines: number; nearest: number; meanWay: number }[] = [];
    for (const level of LEVELS) {
      let beacons = 0,
        mines = 0,
        nearest = Number.POSITIVE_INFINITY,
        sumWay = 0;
      for (const seed of [1, 2, 3, 4, 5]) {
        const r = laid(level.number, seed);
        beacons += r.course.beacons;
        mines += r.mines.length;
        const xs = r.order.map((i) => r.h.beacons[2 * i]!);
        r.mines.forEach((m, i) => {
          nearest = Math.min(nearest, r.way[i]!);
          sumWay += r.way[i]!;
          expect(r.way[i]!).toBeGreaterThan(level.mines.clearance - 1e-6);
          expect(m.y).toBeLessThanOrEqual(-MINE_TOP);
          for (let b = 0; b < r.course.beacons; b++)
            expect(Math.hypot(r.h.beacons[2 * b]! - m.x, r.h.beacons[2 * b + 1]! - m.y)).toBeGreaterThanOrEqual(MINE_BEACON_CLEARANCE);
          expect(m.x - Math.max(...xs.filter((x) => x < m.x))).toBeGreaterThanOrEqual(level.mines.lead);
          for (const o of r.mines) if (o !== m) expect(Math.abs(o.x - m.x)).toBeGreaterThanOrEqual(level.mines.gap);
        });
      }
      totals.push({ beacons, mines, nearest, meanWay: sumWay / mines });
    }
    console.log(
      totals
        .map(
          (t, i) =>
            `level ${i + 1}: ${t.beacons} beacons, ${t.mines} mines, way to mine ${t.nearest.toFixed(1)} m least, ${t.meanWay.toFixed(1)} m mean`,
        )
        .join('\n'),
    );
    for (let i = 1; i < totals.length; i++) {
      expect(totals[i]!.beacons).toBeGreaterThan(totals[i - 1]!.beacons);
      expect(totals[i]!.mines).toBeGreaterThan(totals[i - 1]!.mines);
      expect(totals[i]!.meanWay).toBeLessThan(totals[i - 1]!.meanWay - 1);
    }
    // The narrowest passage still clears the hull: contact is MINE_RADIUS plus half the hull's height (3.9 m).
    expect(Math.min(...totals.map((t) => t.nearest))).toBeGreaterThan(MINE_WAY_CLEARANCE);
  });
});

/**
 * The mines test's fair pilot (test/games/submarine-mines.test.ts) on level `level`'s course for
 * page seed `seed`, in the level's current (games/submarine/current.ts): from each beacon at full
 * ahead (HELM.topSpeed through the water), ordered to the depth of the leg's
 * first mine (dead on for it), holding Rise or Dive as the warning (mineAhead) tells from
 * MINE_REACTION s after it comes. Returns the mines met, the least room past contact (m) and the
 * earliest warning (s before contact).
 */
function fairRun(level: number, seed: number): { mines: number; closest: number; earliest: number } {
  const { h: scene, course, mines: placed } = laid(level, seed);
  const order = courseOrder(scene.beacons);
  let mines = 0,
    closest = Number.POSITIVE_INFINITY,
    earliest = Number.POSITIVE_INFINITY;
  for (let leg = 1; leg < order.length; leg++) {
    const [ax, ay, bx] = [scene.beacons[2 * order[leg - 1]!]!, scene.beacons[2 * order[leg - 1]! + 1]!, scene.beacons[2 * order[leg]!]!];
    const on = placed.flatMap((m, i) => (m.x > ax && m.x < bx ? [i] : []));
    if (on.length === 0) continue;
    const world = createPhysicsWorld(submarine.worldOptions());
    const h = submarine.build(world, { seed: course.seed, count: course.beacons, fill: SUBMARINE_NEUTRAL_FILL, position: [ax, ay] });
    h.seabed.y.set(scene.seabed.y);
    const c = world.components,
      e = h.hull;
    c.Velocity.x[e] = HELM.topSpeed + currentAt(level, ay);
    const state: HelmState = { ...createHelmState(SUBMARINE_NEUTRAL_FILL), throttle: 1, holdY: placed[on[0]!]!.y, mode: 'holding' };
    const live = placed.map(() => true);
    const warnedAt = new Map<number, number>();
    const near = on.map(() => Number.POSITIVE_INFINITY);
    let told: MineAhead | null = null;
    const end = placed[on[on.length - 1]!]!.x + 15;
    for (let n = 0; n < 60 * 30 && c.Position.x[e]! < end; n++) {
      const heaving = state.mode === 'diving' || state.mode === 'rising';
      if (n % 3 === 0)
        told = mineAhead(c.Position.x[e]!, c.Position.y[e]!, c.Velocity.x[e]!, c.Velocity.y[e]!, state.holdY, placed, live, h.seabed, {
          prefer: told,
          heaving,
        });
      if (told && !warnedAt.has(told.index)) {
        warnedAt.set(told.index, world.time);
        earliest = Math.min(earliest, told.time);
      }
      const go = told !== null && world.time >= warnedAt.get(told.index)! + MINE_REACTION;
      const input: HelmInput = {
        dive: go && told!.side === 'under',
        rise: go && told!.side === 'over',
        noseDown: false,
        noseUp: false,
        ahead: true,
        astern: false,
      };
      // The level's current at the hull (games/submarine/current.ts): the screw drives through the water.
      const water = currentAt(level, c.Position.y[e]!);
      steer(world, h, input, state, water);
      driftInCurrent(world, h, water);
      step(world);
      on.forEach((i, k) => {
        near[k] = Math.min(near[k]!, hullDistance(c.Position.x[e]!, c.Position.y[e]!, c.Angle.value[e]!, placed[i]!.x, placed[i]!.y));
      });
    }
    mines += on.length;
    closest = Math.min(closest, ...near.map((d) => d - MINE_RADIUS));
  }
  return { mines, closest, earliest };
}

describe('submarine levels, fair', () => {
  it('on levels 2 and 3 a boat at full ahead dead on for each mine, heeding the warning MINE_REACTION s late, passes every one', () => {
    for (const level of [2, 3]) {
      let mines = 0,
        closest = Number.POSITIVE_INFINITY,
        earliest = Number.POSITIVE_INFINITY;
      for (const seed of [1, 2]) {
        const r = fairRun(level, seed);
        mines += r.mines;
        closest = Math.min(closest, r.closest);
        earliest = Math.min(earliest, r.earliest);
      }
      console.log(
        `level ${level}: ${mines} mines passed, ${closest.toFixed(2)} m least past contact, warned ${earliest.toFixed(1)} s or more ahead`,
      );
      expect(mines).toBeGreaterThan(10);
      expect(closest).toBeGreaterThan(0.5);
      expect(earliest).toBeGreaterThan(2);
    }
  }, 60_000);
});
