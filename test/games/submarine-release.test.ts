/**
 * What a let-go of Dive holds (games/submarine/release.ts): the depth order line as last put on the
 * screen, when the frame pacer skipped the frames after it while the key was still held; and the
 * boat, headless on a calm sea, stops on that line instead of the order run on past it.
 */

import { createPhysicsWorld, step } from '@bitphysics/physics';
import { SUBMARINE_NEUTRAL_FILL, submarine } from '@bitphysics/projects';
import { describe, expect, it } from 'vitest';
import { createHelmState, keyHeaveShare, NO_INPUT, steer } from '../../games/submarine/helm';
import { createShownOrder, releasedOrder } from '../../games/submarine/release';

describe('submarine let-go', () => {
  it('holds the line last drawn when the order ran past it, never runs the order on', () => {
    expect(releasedOrder(-45, -42, 'diving')).toBe(-42);
    expect(releasedOrder(-40, -42, 'diving')).toBe(-40);
    expect(releasedOrder(-35, -38, 'rising')).toBe(-38);
    expect(releasedOrder(-40, -38, 'rising')).toBe(-40);
    expect(releasedOrder(-45, Number.NaN, 'diving')).toBe(-45);
    expect(() => releasedOrder(-45, -42, 'holding')).toThrow(/releasedOrder: mode/);
    // Only frames put on the screen count: the pacer's drawn count must pass the one noted before.
    const shown = createShownOrder();
    expect(shown.shown(0)).toBeNaN();
    shown.note(-30, 0); // drawn: the count goes to 1
    expect(shown.shown(1)).toBe(-30);
    shown.note(-31, 1); // skipped: the count stays at 1
    shown.note(-32, 1); // skipped
    expect(shown.shown(1)).toBe(-30);
    shown.note(-33, 1); // drawn
    expect(shown.shown(2)).toBe(-33);
  });

  it('a Dive held through 0.3 s of frames not drawn, let go, stops within 0.3 m of the line last drawn, not metres past it', () => {
    const world = createPhysicsWorld(submarine.worldOptions());
    const h = submarine.build(world, { seed: 1, count: 0, fill: SUBMARINE_NEUTRAL_FILL, position: [0, -40] });
    world.components.FluidRegion.surface.fill(0);
    const helm = createHelmState(SUBMARINE_NEUTRAL_FILL);
    const run = (steps: number, dive: boolean) => {
      for (let i = 0; i < steps; i++) {
        steer(world, h, { ...NO_INPUT, dive, heave: keyHeaveShare(0, 0) }, helm);
        step(world);
      }
    };
    run(120, false);
    run(90, true); // 1.5 s of Dive: the boat at the key's 6 m/s
    const line = helm.holdY; // the last frame drawn
    run(18, true); // 0.3 s more held, no frame drawn
    const ranOn = helm.holdY;
    expect(line - ranOn).toBeGreaterThan(1.5); // 6 m/s for 0.3 s
    helm.holdY = releasedOrder(helm.holdY, line, helm.mode);
    run(600, false);
    expect(Math.abs(world.components.Position.y[h.hull]! - line)).toBeLessThan(0.3);
  });
});
