/**
 * The depth the submarine's on-screen stick orders (games/submarine/stick.ts stickOrder) and the
 * helm taking the boat to it (helm.ts HelmInput.orderY), headless on a calm sea over open water.
 * Issue 34: a stranger on a phone held the stick down 1.5 s and got 13 m, 3.8 s and got 27 m, and
 * could not tell where the boat would level off. Now the stick moves an order (marked on the depth
 * ruler) and, let go, the boat levels on it: where it ends is what the mark showed at the let-go.
 */

import { step } from '@bitphysics/physics';
import { SUBMARINE } from '@bitphysics/projects';
import { describe, expect, it } from 'vitest';
import { KEY_HEAVE_SHARE, NO_INPUT, steer } from '../../games/submarine/helm';
import { STICK_ORDER_LEAD, STICK_ORDER_SPEED, stickHeaveDirection, stickOrder, stickShare } from '../../games/submarine/stick';
import { hovering } from './submarine-hover';

describe('submarine stick order', () => {
  it('moves at STICK_ORDER_SPEED times the share from past the hull, at most STICK_ORDER_LEAD ahead, inside floor and ceiling', () => {
    const dt = 1 / 60;
    expect(stickOrder(Number.NaN, -1, 1, dt, -10, Number.NaN, -200, 0)).toBeCloseTo(-10.5 - STICK_ORDER_SPEED * dt, 12);
    expect(stickOrder(-20, -1, 0.5, dt, -10, -12, -200, 0)).toBeCloseTo(-20 - 0.5 * STICK_ORDER_SPEED * dt, 12);
    expect(stickOrder(-20, 0, 1, dt, -10, -12, -200, 0)).toBe(-20);
    expect(stickOrder(-40, -1, 1, dt, -10, -12, -200, 0)).toBe(-10 - STICK_ORDER_LEAD);
    expect(stickOrder(-30, -1, 1, dt, -25, -12, -30, 0)).toBe(-30);
    expect(stickOrder(-2, 1, 1, 1, -5, -2, -30, -1.5)).toBe(-1.5);
    // Pushed up with an order below the hull: it starts from past the hull the way it is pushed.
    expect(stickOrder(-20, 1, 1, 0, -10, -12, -200, 0)).toBe(-9.5);
    expect(() => stickOrder(0, -1, 2, dt, -10, 0, -200, 0)).toThrow(/stickOrder: share/);
  });

  it('held 1.5 s or 3.8 s and let go, the boat levels within 0.5 m of the order shown at the let-go; 2 s held dives as far as a Dive key within 5 %', () => {
    const dive = (held: number, key: boolean) => {
      const b = hovering(-6);
      let order = Number.NaN,
        shown = Number.NaN;
      const dt = b.world.dt;
      for (let i = 0; i < (held + 8) / dt; i++) {
        const t = i * dt,
          on = t < held;
        if (key) steer(b.world, b.h, { ...NO_INPUT, dive: on, heave: KEY_HEAVE_SHARE }, b.helm);
        else {
          order = stickOrder(order, on ? -1 : 0, 1, dt, b.c.Position.y[b.e]!, b.helm.holdY, -1000, -SUBMARINE.height / 2);
          if (on) shown = order;
          steer(b.world, b.h, { ...NO_INPUT, orderY: order, heave: KEY_HEAVE_SHARE }, b.helm);
        }
        step(b.world);
        if (key && Math.abs(t - held) < dt / 2) shown = b.c.Position.y[b.e]!;
      }
      return { end: b.c.Position.y[b.e]!, shown, vy: b.c.Velocity.y[b.e]! };
    };
    for (const held of [1.5, 3.8]) {
      const s = dive(held, false);
      console.log(`stick held ${held} s: order shown at the let-go ${(-s.shown).toFixed(1)} m, levelled at ${(-s.end).toFixed(1)} m`);
      expect(Math.abs(s.end - s.shown)).toBeLessThan(0.5);
      expect(Math.abs(s.vy)).toBeLessThan(0.1);
    }
    // The rim and a Dive key take the boat down alike while held (the page's test of the two at 2 s).
    const rim = hovering(-6),
      key = hovering(-6);
    let order = Number.NaN;
    for (let i = 0; i < 2 / rim.world.dt; i++) {
      order = stickOrder(order, -1, 1, rim.world.dt, rim.c.Position.y[rim.e]!, rim.helm.holdY, -1000, 0);
      steer(rim.world, rim.h, { ...NO_INPUT, orderY: order, heave: KEY_HEAVE_SHARE }, rim.helm);
      step(rim.world);
      steer(key.world, key.h, { ...NO_INPUT, dive: true, heave: KEY_HEAVE_SHARE }, key.helm);
      step(key.world);
    }
    const r = -6 - rim.c.Position.y[rim.e]!,
      k = -6 - key.c.Position.y[key.e]!;
    console.log(`2 s: stick rim ${r.toFixed(2)} m down, Dive key ${k.toFixed(2)} m`);
    expect(Math.abs(r - k)).toBeLessThan(0.05 * k);
  });

  it('levelled and then held on Ahead with the thumb 10 degrees low, the boat stays within 0.5 m of its depth for 20 s (it drifted 32 m)', () => {
    // Issue 34: "the stick sets a target depth and the boat should level at it and stay; it drifts
    // off". A thumb pushed to the rim for Ahead is seldom level: 10 degrees low (and 18 degrees
    // low still dives: test/games/submarine-stick.test.ts). Tolerance 0.5 m: the hold's own
    // settling at full ahead, well under the 32 m the order ran before.
    const b = hovering(-30);
    b.c.Velocity.x[b.e] = 8;
    const a = (10 * Math.PI) / 180,
      x = Math.cos(a),
      y = -Math.sin(a);
    let order = Number.NaN;
    const dt = b.world.dt;
    for (let i = 0; i < 20 / dt; i++) {
      const dir = stickHeaveDirection(y, x);
      order = stickOrder(order, dir, stickShare(y, false), dt, b.c.Position.y[b.e]!, b.helm.holdY, -1000, -SUBMARINE.height / 2);
      const input = { ...NO_INPUT, ahead: true, drive: stickShare(x, false), heave: KEY_HEAVE_SHARE };
      steer(b.world, b.h, Number.isFinite(order) ? { ...input, orderY: order } : input, b.helm);
      step(b.world);
    }
    const off = b.c.Position.y[b.e]! + 30;
    console.log(`thumb 10 degrees low on Ahead for 20 s: ${off.toFixed(2)} m off the depth levelled at`);
    expect(Math.abs(off)).toBeLessThan(0.5);
  });
});
