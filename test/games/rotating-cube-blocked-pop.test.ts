/**
 * rotating-cube's "✗ This pad needs <colour> on top" pop (main.ts `sayBlocked`, from PadChallenge
 * `settledBlocked`), headless: rolls played as the game's roll key plays them (scene.ts `rollStart`,
 * the roll torque held to 55 degrees, then `rollSettle`), a queued roll starting on the first step the
 * cube is still, as main.ts `queueRolls` starts it. A route whose last roll lands the wanted face
 * says nothing on the way, though the cube rests for a step on the pad's edge with another face
 * between its rolls; a landing with the wrong face says so once, after it has come to rest.
 */

import { addSystem, createPhysicsWorld, setAngularVelocity, setVelocity, step } from '@bitphysics/physics';
import { describe, expect, it } from 'vitest';
import {
  BLOCKED_SETTLE_TIME,
  buildRotatingCube,
  cubeStill,
  PadChallenge,
  ROLL_SPIN_MAX,
  ROLL_TORQUE,
  rollSettle,
  rollStart,
  rotatingCubeWorldOptions,
  topFace,
  torqueCouple,
} from '../../games/rotating-cube/scene';

/** The game's roll latch (main.ts ROLL_LATCH_ANGLE): the torque stays on until the cube has turned this far, rad. */
const LATCH_ANGLE = (55 * Math.PI) / 180;

/**
 * A room with the cube resting at (x, 0), +y up, and one pad at `pad` (half edge `half`, m) wanting
 * face `want`. `go(rolls)` plays that many rolls towards +x, each starting on the first step the cube
 * is still after the last (a queued key), then steps on to `steps` steps in all, calling `each` after
 * every step.
 */
function room(x: number, pad: [number, number], want: number, half: number) {
  const world = createPhysicsWorld(rotatingCubeWorldOptions());
  const body = buildRotatingCube(world).body;
  let on = false,
    armed = false;
  // The roll +x: about -z (the top goes towards +x); the torque as main.ts `torqueNow`, off at ROLL_SPIN_MAX.
  const W = world.components.AngularVelocity,
    O = world.components.Orientation,
    P = world.components.Position;
  addSystem(
    world,
    'forces',
    torqueCouple(body, () => (on && -W.z[body]! < ROLL_SPIN_MAX ? [0, 0, -ROLL_TORQUE] : [0, 0, 0])),
  );
  addSystem(
    world,
    'forces',
    rollSettle(body, () => armed && !on),
  );
  P.x[body] = x;
  P.y[body] = 0.51;
  P.z[body] = 0;
  setVelocity(world, body, [0, 0, 0]);
  setAngularVelocity(world, body, [0, 0, 0]);
  for (let i = 0; i < 40; i++) step(world);
  const pads = new PadChallenge({ seed: 0, pads: [pad], faces: [want], halves: [half], beds: [1] });
  addSystem(world, 'finalize', (w) => {
    pads.update(w, body);
  });
  let q0 = [0, 0, 0, 1];
  const go = (rolls: number, steps: number, each: (i: number) => void): void => {
    let left = rolls;
    for (let i = 0; i < steps; i++) {
      if (left > 0 && !on && cubeStill(world, body) && rollStart(world, body, 0, -1)) {
        left--;
        q0 = [O.x[body]!, O.y[body]!, O.z[body]!, O.w[body]!];
        on = armed = true;
      }
      step(world);
      const dot = Math.abs(q0[0]! * O.x[body]! + q0[1]! * O.y[body]! + q0[2]! * O.z[body]! + q0[3]! * O.w[body]!);
      if (on && 2 * Math.acos(Math.min(1, dot)) >= LATCH_ANGLE) on = false;
      each(i);
    }
  };
  return { world, body, pads, go };
}

describe('rotating-cube: the wrong-face pop waits for the cube to rest', () => {
  it('two queued rolls onto a pad 1.6 m off, the second landing the wanted face: no wrong-face pop on the way, though between the rolls the cube rests a step on the pad with another face', () => {
    // Two rolls +x from +y up bring -y (face 3) up. The first lands the cube at x 0.89, within the
    // pad's half edge 0.6 plus PAD_GRACE 0.25 of its centre 1.6: for a step it rests there, -x on top.
    const { world, body, pads, go } = room(0, [1.6, 0], 3, 0.6);
    let rawFace = 0,
      said = 0,
      reachedAt = -1;
    go(2, 200, (i) => {
      if (pads.pad > 0) {
        if (reachedAt < 0) reachedAt = i;
        return;
      }
      if (pads.blocked === 'face') rawFace++;
      if (pads.settledBlocked === 'face') said++;
    });
    expect(reachedAt).toBeGreaterThan(0);
    expect(topFace(world, body)).toBe(3);
    // Measured: the raw reason (what the pop read before) is 'face' for 1 step, between the rolls.
    expect(rawFace).toBeGreaterThan(0);
    expect(said).toBe(0);
  });

  it('one roll onto the pad with the wrong face: said once, after the cube has rested BLOCKED_SETTLE_TIME, and it stays', () => {
    // One roll +x brings -x (face 1) up; the pad at 1 wants +x (face 0).
    const { world, body, pads, go } = room(0, [1, 0], 0, 0.6);
    let rises = 0,
      prev: string = '',
      firstRaw = -1,
      firstSaid = -1,
      movedAfter = false;
    go(1, 150, (i) => {
      const now = pads.settledBlocked;
      if (pads.blocked === 'face' && firstRaw < 0) firstRaw = i;
      if (now === 'face' && prev !== 'face') {
        rises++;
        if (firstSaid < 0) firstSaid = i;
      }
      if (firstSaid >= 0 && !cubeStill(world, body)) movedAfter = true;
      prev = now;
    });
    expect(pads.pad).toBe(0);
    expect(rises).toBe(1);
    expect(movedAfter).toBe(false);
    // The rest starts at firstRaw or a bounce later; the pop follows it by BLOCKED_SETTLE_TIME (15 steps
    // at 60 a second) and by no more than the bounce, 10 steps (measured: a 4-step break).
    const steps = Math.round(BLOCKED_SETTLE_TIME / world.dt);
    expect(firstSaid - firstRaw).toBeGreaterThanOrEqual(steps);
    expect(firstSaid - firstRaw).toBeLessThanOrEqual(steps + 10);
  });
});
