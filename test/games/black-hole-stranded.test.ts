/**
 * Black hole's attempts that could not end by themselves (games/black-hole/levels.ts `trackOrbit`,
 * `stepLevel`): a ship caught going round one of level 3's small holes used to circle it for as long
 * as the page stayed open, and a tank run dry (level 8 on) left the ship on the pad with no way to
 * thrust again. Now an orbit of ORBIT_TURNS turns ends the attempt (no life lost), a coast on an empty
 * tank ends after FUEL_OUT_SECONDS, and each attempt flies on a full tank.
 */
import { setPosition, setVelocity, slotOf } from '@bitphysics/physics';
import { describe, expect, test } from 'vitest';
import {
  FUEL_OUT_SECONDS,
  type LevelRun,
  levelSpec,
  ORBIT_TURNS,
  STALL_SECONDS,
  startLevel,
  stepLevel,
} from '../../games/black-hole/levels';
import { type BlackHoleGame, createBlackHoleGame, gravitationalConstant, setThrust } from '../../games/black-hole/rules';
import { waitWords } from '../../games/black-hole/wait-words';

/** A level-3 game (the zig-zag) whose first attempt has begun: the first thrust left the pad, then let go. */
function flying() {
  const g = createBlackHoleGame({ seed: 1 });
  const run = startLevel(g, 3);
  setThrust(g, 'up');
  stepLevel(g, run);
  setThrust(g, 'none');
  g.thrustVec[0] = g.thrustVec[1] = 0;
  return { g, run };
}

/**
 * Steps the level with the ship moved, before each step, to `at(t)` (m; t the time since the first, s)
 * at the speed of that motion (a ship held on a course: the step's own pull moves it a hair off it),
 * until an event or `limit` s. Returns the event and the time it came, s.
 */
function fly(g: BlackHoleGame, run: LevelRun, at: (t: number) => [number, number], limit: number): [string, number] {
  const dt = g.world.dt;
  for (let k = 0; k * dt < limit; k++) {
    const [x, y] = at(k * dt),
      [x1, y1] = at((k + 1) * dt);
    setPosition(g.world, g.ship, [x, y]);
    setVelocity(g.world, g.ship, [(x1 - x) / dt, (y1 - y) / dt]);
    const event = stepLevel(g, run);
    if (event !== 'none') return [event, (k + 1) * dt];
  }
  return ['none', limit];
}

/** The centre of the game's hole `i`, m. */
function holeAt(g: BlackHoleGame, i: number): [number, number] {
  const P = g.world.components.Position,
    h = slotOf(g.holes[i]!);
  return [P.x[h]!, P.y[h]!];
}

describe('black hole: an attempt that cannot end by itself is ended', () => {
  test('a ship going round a hole is sent back to the start after ORBIT_TURNS turns, no life lost', () => {
    const { g, run } = flying();
    const [hx, hy] = holeAt(g, 0);
    // 1.4 m out, a turn in 2 s (about the circular speed there: the pull far above the thrust).
    expect((gravitationalConstant(g) * g.holeMass[0]!) / 1.4 ** 2).toBeGreaterThan(g.params.thrust);
    const lives = g.lives;
    const [event, t] = fly(g, run, (t) => [hx + 1.4 * Math.cos(Math.PI * t), hy + 1.4 * Math.sin(Math.PI * t)], 60);
    expect(event).toBe('lost');
    // Two turns of 2 s each; up to a quarter turn (0.5 s) sooner, counted from the jump off the pad below the hole.
    expect(t).toBeGreaterThan(2 * ORBIT_TURNS - 0.6);
    expect(t).toBeLessThan(2 * ORBIT_TURNS + 0.1);
    expect([g.lives, run.stranded, run.parked, run.missedRing]).toEqual([lives, 'orbit', true, false]);
    expect(g.message).toMatch(/orbit/);
    // The words over the field while the ship waits say why, not "Off the field".
    expect(waitWords('lost', { lives, practice: false, touch: true, stranded: run.stranded })).toBe(
      'Caught in orbit!\nBack to the start, no life lost\nTap ↑, ← or → to fly on',
    );
    const P = g.world.components.Position;
    expect([P.x[slotOf(g.ship)], P.y[slotOf(g.ship)]]).toEqual([g.start[0], g.start[1]]);
  });

  test('swings to and fro round a hole are no orbit: the turns cancel', () => {
    const { g, run } = flying();
    const [hx, hy] = holeAt(g, 0);
    // To and fro over three quarters of a turn for 10 s (under STALL_SECONDS): the turns cancel.
    const swing = (t: number): [number, number] => {
      const a = 1.5 * Math.PI * Math.sin(t);
      return [hx + 1.4 * Math.cos(a), hy + 1.4 * Math.sin(a)];
    };
    expect(fly(g, run, swing, 10)).toEqual(['none', 10]);
    expect(run.stranded).toBe('');
  });

  test('a ship thrown to and fro among the holes without climbing goes back to the start after STALL_SECONDS', () => {
    const { g, run } = flying();
    // Back and forth across the field under the zig-zag, 4 m up, a crossing every 3 s: no turn round a
    // hole, no height gained after the first moment.
    const [event, t] = fly(g, run, (t) => [16 + 9 * Math.sin((Math.PI * t) / 3), 4], 60);
    expect([event, run.stranded]).toEqual(['lost', 'stall']);
    expect(t).toBeCloseTo(STALL_SECONDS, 0);
  });

  test('a ship climbing slowly is never stalled', () => {
    const { g, run } = flying();
    // Up the field's left side at 0.1 m/s: 0.5 m every 5 s, under STALL_SECONDS.
    expect(fly(g, run, (t) => [2, 2 + 0.1 * t], STALL_SECONDS * 2)).toEqual(['none', STALL_SECONDS * 2]);
  });

  test('a tank run dry: the ship coasts FUEL_OUT_SECONDS, then goes back to the start with a full tank and can thrust again', () => {
    const g = createBlackHoleGame({ seed: 2 });
    const run = startLevel(g, 8);
    const fuel = levelSpec(8).fuel;
    // A tank all but empty: a few steps of ← burn it out.
    run.fuelLeft = 0.1;
    setThrust(g, 'left');
    const dt = g.world.dt;
    let event = 'none';
    for (let k = 0; k < 20 && event === 'none'; k++) event = stepLevel(g, run);
    expect([event, run.fuelLeft, g.thrust]).toEqual(['none', 0, 'none']);
    // A ship drifting slowly, with no way to steer: held here at rest before each step (stopped, it
    // would drift for ever; the holes' pull moves it only a little in a step).
    let k = 0;
    for (; k * dt < FUEL_OUT_SECONDS + 1 && event === 'none'; k++) {
      setPosition(g.world, g.ship, [g.start[0], 3]);
      setVelocity(g.world, g.ship, [0, 0]);
      event = stepLevel(g, run);
    }
    expect(event).toBe('lost');
    expect(k * dt).toBeGreaterThan(FUEL_OUT_SECONDS - 0.5);
    expect([run.stranded, run.fuelLeft, run.parked]).toEqual(['fuel', fuel, true]);
    expect(waitWords('lost', { lives: g.lives, practice: false, touch: false, stranded: run.stranded })).toMatch(/^Out of fuel!\n/);
    setThrust(g, 'up');
    stepLevel(g, run);
    expect(run.parked).toBe(false);
  });

  test('a fall refills the tank for the next attempt', () => {
    const g = createBlackHoleGame({ seed: 3 });
    const run = startLevel(g, 8);
    setThrust(g, 'up');
    let event = 'none';
    for (let k = 0; k < 1200 && event !== 'fell' && event !== 'lost'; k++) event = stepLevel(g, run);
    expect(['fell', 'lost']).toContain(event);
    expect(run.fuelLeft).toBe(levelSpec(8).fuel);
  });
});
