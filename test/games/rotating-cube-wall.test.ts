/**
 * rotating-cube's room, headless: a roll into a wall. The game's roll (a press's `rollStart` and the
 * roll torque held on until the cube has turned 55 degrees or 1.5 s have passed) turned a cube resting
 * against the wall over in place onto another face, which the round counted as a move; a blocked
 * roll (`rollBlocked`) now only bumps it (`BUMP_SPIN`) and it falls back onto the same face.
 */

import { addSystem, createPhysicsWorld, type PhysicsWorld, setAngularVelocity, setVelocity, step } from '@bitphysics/physics';
import { describe, expect, it } from 'vitest';
import {
  BUMP_SPIN,
  buildRotatingCube,
  CLASSIC_LAYOUT,
  cubeStill,
  PadChallenge,
  ROLL_SPIN_MAX,
  ROLL_TORQUE,
  rollBlocked,
  rollStart,
  rotatingCubeWorldOptions,
  topFace,
  torqueCouple,
} from '../../games/rotating-cube/scene';

/** A room with its cube set flat (+y up) at (x, 0.5, 0) and settled for 0.5 s, and a PadChallenge that has seen it. */
function cubeAt(x: number): { world: PhysicsWorld; e: number; pads: PadChallenge } {
  const world = createPhysicsWorld(rotatingCubeWorldOptions());
  const e = buildRotatingCube(world).body;
  const P = world.components.Position,
    O = world.components.Orientation;
  P.x[e] = x;
  P.y[e] = 0.5;
  P.z[e] = 0;
  [O.x[e], O.y[e], O.z[e], O.w[e]] = [0, 0, 0, 1];
  setVelocity(world, e, [0, 0, 0]);
  setAngularVelocity(world, e, [0, 0, 0]);
  const pads = new PadChallenge(CLASSIC_LAYOUT);
  for (let i = 0; i < 30; i++) {
    step(world);
    pads.update(world, e);
  }
  return { world, e, pads };
}

describe('rotating-cube: a roll into a wall', () => {
  it('rollBlocked: a roll whose next cell is past the wall is blocked, one along the floor or away from the wall is not', () => {
    // The +x wall's inside face is at x = 3: a cube at x = 2 would land at 3 (blocked), one at 1 at 2.
    expect(rollBlocked(2, 0, 1, 0)).toBe(true);
    expect(rollBlocked(0, -2.05, 0, -1)).toBe(true);
    expect(rollBlocked(1, 0, 1, 0)).toBe(false);
    expect(rollBlocked(2, 0, -1, 0)).toBe(false);
    expect(rollBlocked(2, 0, 0, 1)).toBe(false);
  });

  it("the game's held roll turned the cube over in place against the wall (a move); the bump keeps its face and counts none", () => {
    // The old way: press (rollStart) and the roll torque towards +x, as the game's latch, 1.5 s.
    const old = cubeAt(2);
    const W = old.world.components.AngularVelocity;
    let on = true;
    addSystem(
      old.world,
      'forces',
      torqueCouple(old.e, () => [0, 0, on && -W.z[old.e]! < ROLL_SPIN_MAX ? -ROLL_TORQUE : 0]),
    );
    const top0 = topFace(old.world, old.e);
    rollStart(old.world, old.e, 0, -1);
    for (let i = 1; i <= 150; i++) {
      if (i > 90) on = false;
      step(old.world);
      old.pads.update(old.world, old.e);
    }
    expect(topFace(old.world, old.e)).not.toBe(top0);
    expect(old.pads.moves).toBeGreaterThanOrEqual(1);

    // The blocked roll: only the bump. It tips visibly (over 4 degrees: the far edge rises 3.5 cm),
    // falls back onto the same face within 0.05 m of where it was (the wall not touched), and rests.
    const now = cubeAt(2);
    const O = now.world.components.Orientation,
      P = now.world.components.Position;
    expect(rollBlocked(P.x[now.e]!, P.z[now.e]!, 1, 0)).toBe(true);
    expect(rollStart(now.world, now.e, 0, -1, BUMP_SPIN)).toBe(true);
    let most = 0;
    for (let i = 1; i <= 60; i++) {
      step(now.world);
      now.pads.update(now.world, now.e);
      most = Math.max(most, (2 * Math.acos(Math.min(1, Math.abs(O.w[now.e]!))) * 180) / Math.PI);
    }
    expect(most).toBeGreaterThan(4);
    expect(most).toBeLessThan(20);
    expect(topFace(now.world, now.e)).toBe(top0);
    expect(Math.abs(P.x[now.e]! - 2)).toBeLessThan(0.05);
    expect(cubeStill(now.world, now.e)).toBe(true);
    expect(now.pads.moves).toBe(0);
  });
});
