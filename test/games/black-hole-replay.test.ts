/**
 * Black hole's replay without a page (games/black-hole/replay.ts): a run with thrust changes, a fall,
 * a cleared level and the next level begun is recorded; played back (rewound in the same game, or in a
 * new game made with the same options) it ends in the same state to the last bit. Reference: the
 * recorded run itself; tolerance zero (stateHash covers every bit of every body; the game's own
 * counters are compared exactly).
 */

import { slotOf, stateHash } from '@bitphysics/physics';
import { describe, expect, test } from 'vitest';
import { canThrust, type LevelRun, startLevel, stepLevel } from '../../games/black-hole/levels';
import { type BlackHoleReplay, createBlackHoleReplay, REPLAY_LEAD_STEPS } from '../../games/black-hole/replay';
import { type BlackHoleGame, createBlackHoleGame, setThrust } from '../../games/black-hole/rules';

const summary = (g: BlackHoleGame, run: LevelRun) => ({
  hash: stateHash(g.world),
  lives: g.lives,
  score: g.score,
  falls: g.falls,
  crossings: g.crossings,
  thrust: g.thrust,
  holes: [...g.holes],
  level: run.spec.level,
  waiting: run.waiting,
  fuel: run.fuelLeft,
  time: run.time,
  rng: { ...g.rng },
  rings: run.rings.map((r) => [...r]),
  ringsTaken: run.ringsTaken,
});

/**
 * Level 1 of a game of `seed`, its ring moved onto the way `playRecorded` flies (where a dry run of it
 * without the ring is at step 300: after the fall, on the climb), so the recorded run clears it.
 */
function ringedLevel1(seed: number): { g: BlackHoleGame; run: LevelRun } {
  const dry = createBlackHoleGame({ seed }),
    dryRun = startLevel(dry, 1);
  dryRun.rings.length = 0;
  const at: [number, number] = [0, 0];
  for (let k = 0; k <= 300; k++) {
    const want = !canThrust(dry, dryRun) ? 'none' : k < 180 ? 'up' : k < 204 ? 'right' : k % 36 < 15 ? 'up' : 'none';
    if (dry.thrust !== want) setThrust(dry, want);
    stepLevel(dry, dryRun);
    at[0] = dry.world.components.Position.x[slotOf(dry.ship)]!;
    at[1] = dry.world.components.Position.y[slotOf(dry.ship)]!;
  }
  const g = createBlackHoleGame({ seed });
  const run = startLevel(g, 1);
  run.rings[0] = at;
  return { g, run };
}

/**
 * Holds thrust up for 3 s (into level 1's hole), then thrusts right for 0.4 s and taps thrust up (on
 * 0.25 s, off 0.35 s), with right again for a while later; begins the next level when one is cleared.
 */
function playRecorded(g: BlackHoleGame, run: LevelRun, replay: BlackHoleReplay, steps: number): void {
  for (let k = 0; k < steps; k++) {
    const phase = k % 36;
    const want = !canThrust(g, run) ? 'none' : k < 180 ? 'up' : k < 204 || (k > 900 && k < 960) ? 'right' : phase < 15 ? 'up' : 'none';
    if (g.thrust !== want) replay.input('thrust', want);
    if (run.waiting && k % 50 === 0) replay.input('beginLevel');
    replay.step();
  }
}

describe('black hole replay', () => {
  test('a recorded run replays to the same final state, rewound in the same game and in a new game', () => {
    const make = () => ringedLevel1(4);
    const { g, run } = make();
    const replay = createBlackHoleReplay(g, run);
    playRecorded(g, run, replay, 1500);
    const end = summary(g, run);
    expect([end.crossings > 0, end.falls > 0]).toEqual([true, true]); // a clear and a fall in the run
    expect(replay.recorder.replay.events.length).toBeGreaterThan(20);

    replay.play();
    expect(replay.player).not.toBeNull();
    expect(g.world.steps).toBe(0); // rewound
    while (replay.player) replay.step();
    expect(summary(g, run)).toEqual(end);

    const other = make();
    const theirs = createBlackHoleReplay(other.g, other.run);
    const recorded = replay.recorder.replay;
    // Play the first game's recording in the second: the same options give the same world and systems.
    theirs.play(recorded);
    while (theirs.player) theirs.step();
    expect(summary(other.g, other.run)).toEqual(end);
  });

  test('inputs given while a replay plays are ignored (the replay is not changed by them)', () => {
    const g = createBlackHoleGame({ seed: 2 });
    const run = startLevel(g, 1);
    const replay = createBlackHoleReplay(g, run);
    playRecorded(g, run, replay, 200);
    const end = summary(g, run);
    const events = replay.recorder.replay.events.length;
    replay.play();
    replay.step();
    replay.input('thrust', 'left');
    while (replay.player) replay.step();
    expect(replay.recorder.replay.events.length).toBe(events);
    expect(summary(g, run)).toEqual(end);
  });

  test('a replay skips the idle wait before the first thrust and after a clear, and still ends bit-equal', () => {
    const { g, run } = ringedLevel1(4);
    const replay = createBlackHoleReplay(g, run);
    // A player who reads the screen for 15 s before the first thrust (the stranger's phone run).
    const idle = 900;
    for (let k = 0; k < idle; k++) replay.step();
    playRecorded(g, run, replay, 1500);
    const end = summary(g, run);
    // World steps (a cleared level waits without stepping its world, and its wait is not replayed).
    const recorded = replay.recorder.replay.steps;
    replay.play();
    let calls = 0;
    while (replay.player) {
      replay.step();
      calls++;
    }
    expect(summary(g, run)).toEqual(end);
    // The opening wait is shown for REPLAY_LEAD_STEPS only; the flight's own steps all play (a wait
    // parked at the start after a fall or a clear is cut to the same lead).
    expect(calls).toBeLessThanOrEqual(recorded - idle + REPLAY_LEAD_STEPS);
    expect(calls).toBeGreaterThan(1000);
  });

  test('stop leaves a replay for the state it was started in, and the live run goes on as if none had played', () => {
    const make = () => {
      const g = createBlackHoleGame({ seed: 7 });
      const run = startLevel(g, 1);
      return { g, run, replay: createBlackHoleReplay(g, run) };
    };
    const a = make(),
      b = make();
    playRecorded(a.g, a.run, a.replay, 700);
    playRecorded(b.g, b.run, b.replay, 700);
    const end = summary(a.g, a.run);
    a.replay.play();
    for (let k = 0; k < 120; k++) a.replay.step();
    expect(summary(a.g, a.run)).not.toEqual(end); // mid-replay
    a.replay.stop();
    expect(a.replay.player).toBeNull();
    expect(summary(a.g, a.run)).toEqual(end);
    // The twin that never replayed is the reference: the same inputs from here give the same states.
    playRecorded(a.g, a.run, a.replay, 400);
    playRecorded(b.g, b.run, b.replay, 400);
    expect(summary(a.g, a.run)).toEqual(summary(b.g, b.run));
  });
});
