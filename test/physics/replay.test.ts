import {
  addBody,
  applyImpulse,
  createInputRecorder,
  createPhysicsWorld,
  createReplayPlayer,
  type PhysicsWorld,
  playReplay,
  setGravity,
  stateHash,
  stepMany,
} from '@bitphysics/physics';
import { describe, expect, test } from 'vitest';
import { mixedScene } from './snapshot-scenes.js';

// Reference: the recorded run itself. Replayed from its start with the same inputs at the same steps, the
// world must end in the same state to the last bit (stateHash hashes every bit), so the tolerance is zero.

function handlersFor(world: PhysicsWorld) {
  return {
    kick: (slot: number, ix: number, iy: number) => applyImpulse(world, slot, [ix, iy]),
    gravity: (gx: number, gy: number) => setGravity(world, [gx, gy]),
    drop: (x: number, y: number) => {
      addBody(world, { position: [x, y], radius: 0.3, restitution: 0.4 });
    },
  };
}

function recordRun(world: PhysicsWorld) {
  const rec = createInputRecorder(world, { handlers: handlersFor(world) });
  stepMany(world, 25);
  rec.input('kick', 9, 2, 3);
  stepMany(world, 40);
  rec.input('drop', 1, 12);
  rec.input('gravity', 1.5, -9.81);
  stepMany(world, 80);
  rec.input('drop', -3, 10);
  stepMany(world, 155);
  return rec.replay;
}

describe('input replay', () => {
  test('a recorded run (impulses, a gravity change, bodies dropped in) replays to the same final state, in a new world and in the same one', () => {
    const world = mixedScene();
    stepMany(world, 10);
    const replay = recordRun(world);
    expect(replay.steps).toBe(300);
    expect(replay.events.map((e) => [e.step, e.name])).toEqual([
      [25, 'kick'],
      [65, 'drop'],
      [65, 'gravity'],
      [145, 'drop'],
    ]);
    const expected = stateHash(world);
    const copy = createPhysicsWorld({ dimensions: 2, capacity: world.capacity });
    playReplay(copy, replay, { handlers: handlersFor(copy) });
    expect(stateHash(copy)).toBe(expected);
    playReplay(world, replay, { handlers: handlersFor(world) });
    expect(stateHash(world)).toBe(expected);
  });

  test('the replay is data: it survives structuredClone; moving one input by one step changes the end state', () => {
    const world = mixedScene();
    const replay = recordRun(world);
    const expected = stateHash(world);
    const copy = createPhysicsWorld({ dimensions: 2, capacity: world.capacity });
    playReplay(copy, structuredClone(replay), { handlers: handlersFor(copy) });
    expect(stateHash(copy)).toBe(expected);
    const moved = { ...replay, events: replay.events.map((e, i) => (i === 0 ? { ...e, step: e.step + 1 } : e)) };
    playReplay(copy, moved, { handlers: handlersFor(copy) });
    expect(stateHash(copy)).not.toBe(expected);
  });

  test('the player steps frame by frame and stops at the end; outside state is saved and loaded', () => {
    const world = createPhysicsWorld({ capacity: 20 });
    const ball = addBody(world, { position: [0, 10] });
    const score = { points: 0 };
    const options = {
      handlers: {
        score: (n: number) => {
          score.points += n;
        },
        kick: (v: number) => applyImpulse(world, ball, [v, 0]),
      },
      save: () => ({ ...score }),
      load: (s: unknown) => Object.assign(score, s),
    };
    score.points = 5;
    const rec = createInputRecorder(world, options);
    stepMany(world, 3);
    rec.input('score', 2);
    rec.input('kick', 1);
    stepMany(world, 3);
    const replay = rec.replay;
    const end = stateHash(world);
    score.points = 100;
    const player = createReplayPlayer(world, replay, options);
    expect(score.points).toBe(5);
    let frames = 0;
    while (!player.done) {
      player.step();
      frames++;
    }
    player.step(); // nothing once done
    expect([frames, player.played, score.points, stateHash(world)]).toEqual([6, 6, 7, end]);
  });

  test('bad input: unknown input names and handlers that are not functions are refused', () => {
    const world = createPhysicsWorld({ capacity: 5 });
    const rec = createInputRecorder(world, { handlers: { a: () => {} } });
    expect(() => rec.input('b')).toThrow(/InputRecorder.input: name must be one of the handlers \(a\), got .b./);
    expect(rec.replay.events).toEqual([]);
    expect(() => createInputRecorder(world, { handlers: { a: 3 as never } })).toThrow(
      /createInputRecorder: handlers.a must be a function, got 3/,
    );
    rec.input('a');
    expect(() => playReplay(world, rec.replay, { handlers: {} })).toThrow(/the replay calls 'a', which is not among the handlers/);
  });
});
