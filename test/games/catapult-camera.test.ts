/**
 * Catapult camera's decisions (games/catapult/camera.ts), headless: on an upright phone the level
 * opens on the overview, then frames the catapult large, follows a throw to the castle, and the look
 * button shows the castle while aiming; on a wide screen the aim view is the overview. The aim view's
 * width is checked against every level's castle (scene.ts) at 390 px.
 */

import { createPhysicsWorld } from '@bitphysics/physics';
import { describe, expect, it } from 'vitest';
import { AIM_PX_PER_M, type CameraInput, cameraShot, INTRO_HOLD, uprightAimSpan } from '../../games/catapult/camera';
import { buildLevel, LAUNCH, LEVEL_COUNT, worldOptions } from '../../games/catapult/scene';

/** A phone held upright, 3 s into a level, touched, nothing thrown. */
const aiming: CameraInput = { upright: true, sinceStart: 3, touched: true, peeking: false, shotView: false, wreck: false, zoomsIn: true };

describe('catapult camera', () => {
  it('upright: the overview at the start until INTRO_HOLD or the first touch, then the aim view', () => {
    expect(cameraShot({ ...aiming, sinceStart: 0, touched: false })).toBe('overview');
    expect(cameraShot({ ...aiming, sinceStart: INTRO_HOLD - 0.01, touched: false })).toBe('overview');
    expect(cameraShot({ ...aiming, sinceStart: INTRO_HOLD + 0.01, touched: false })).toBe('aim');
    expect(cameraShot({ ...aiming, sinceStart: 0.1, touched: true })).toBe('aim');
    // The hold is "a moment": long enough to read the castle (a second), short of keeping the player waiting (3 s).
    expect(INTRO_HOLD).toBeGreaterThanOrEqual(1);
    expect(INTRO_HOLD).toBeLessThanOrEqual(3);
  });

  it('upright: the look button shows the overview while aiming; a throw is followed; a finished level shows the wreck', () => {
    expect(cameraShot({ ...aiming, peeking: true })).toBe('overview');
    expect(cameraShot({ ...aiming, shotView: true })).toBe('follow');
    expect(cameraShot({ ...aiming, shotView: true, peeking: true })).toBe('follow');
    expect(cameraShot({ ...aiming, wreck: true })).toBe('castle');
    expect(cameraShot({ ...aiming, wreck: true, shotView: true })).toBe('castle');
  });

  it('wide: the overview while aiming and at the start; the castle only where it is closer than the overview', () => {
    const wide = { ...aiming, upright: false };
    for (const sinceStart of [0, 5]) expect(cameraShot({ ...wide, sinceStart, touched: false })).toBe('overview');
    expect(cameraShot({ ...wide, peeking: true })).toBe('overview');
    expect(cameraShot({ ...wide, shotView: true })).toBe('follow');
    expect(cameraShot({ ...wide, shotView: true, zoomsIn: false })).toBe('overview');
    expect(cameraShot({ ...wide, wreck: true, zoomsIn: false })).toBe('overview');
  });

  it('the aim view on a 390 px phone: at least AIM_PX_PER_M on every level, the catapult in it, the whole overview where it fits', () => {
    const left = LAUNCH.x - 3.2;
    for (let level = 0; level < LEVEL_COUNT; level++) {
      const w = createPhysicsWorld(worldOptions({ gravity: 9.81 }));
      const lv = buildLevel(w, { level, seed: 1, gravity: 9.81, jointStrength: 400 });
      const far = lv.castleMaxX + 0.8;
      const [minX, maxX] = uprightAimSpan(left, far, 390);
      const perM = 390 / (maxX - minX);
      // The scale, to a millionth: never under AIM_PX_PER_M; where the overview is as large, the overview.
      expect(perM).toBeGreaterThanOrEqual(AIM_PX_PER_M * (1 - 1e-6));
      if (390 / (far - left) >= AIM_PX_PER_M) expect([minX, maxX]).toEqual([left, far]);
      else expect(perM).toBeCloseTo(AIM_PX_PER_M, 6);
      // The catapult's arm (to 1.1 m past the launch point) and 3 m ahead of it for the flight's start.
      expect(minX).toBe(left);
      expect(maxX).toBeGreaterThan(LAUNCH.x + 4);
    }
    // Level 9's whole field at 390 px is about half that scale: the reason for the aim view.
    const w = createPhysicsWorld(worldOptions({ gravity: 9.81 }));
    const last = buildLevel(w, { level: LEVEL_COUNT - 1, seed: 1, gravity: 9.81, jointStrength: 400 });
    expect(390 / (last.castleMaxX + 0.8 - left)).toBeLessThan(0.6 * AIM_PX_PER_M);
  });

  it('rejects bad input, naming the function and the value', () => {
    expect(() => cameraShot({ ...aiming, sinceStart: -1 })).toThrow(/cameraShot: sinceStart .* got -1/);
    expect(() => cameraShot({ ...aiming, sinceStart: Number.NaN })).toThrow(/cameraShot: sinceStart .* got NaN/);
    expect(() => uprightAimSpan(0, 10, 0)).toThrow(/uprightAimSpan: width .* got 0/);
    expect(() => uprightAimSpan(5, 5, 390)).toThrow(/uprightAimSpan: overviewMaxX .* got 5/);
  });
});
