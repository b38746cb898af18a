/**
 * The flight simulator's course (games/flight-simulator/course.ts), headless: the rings are laid
 * where the layout rule says (an easy first ring, spacing, heights clear of the hills), and a move
 * through a ring's plane passes it inside the radius, misses it outside, and counts nothing the
 * wrong way or far off.
 */

import { createPhysicsWorld } from '@bitphysics/physics';
import { aircraft, terrainHeight } from '@bitphysics/projects';
import { describe, expect, it } from 'vitest';
import {
  courseStars,
  crossRing,
  layCourse,
  MISS_RANGE,
  nextRing,
  RING_CLEARANCE,
  RING_RADIUS,
  type Ring,
} from '../../games/flight-simulator/course';

const terrain = aircraft.build(createPhysicsWorld(aircraft.worldOptions()), { seed: 3 }).terrain;

describe('flight simulator course', () => {
  it('lays the rings: the first 1.6 km straight ahead, then 1.5 to 2.2 km apart, clear of the hills', () => {
    for (const seed of [1, 2, 3, 4, 5]) {
      const rings = layCourse({ terrain, seed, count: 30, start: [0, 900, 0] });
      expect(rings).toHaveLength(30);
      expect(rings[0]!.x).toBeCloseTo(1600, 9);
      expect(rings[0]!.z).toBeCloseTo(0, 9);
      expect(rings[0]!.y).toBe(Math.max(900, terrainHeight(terrain, 1600, 0) + RING_CLEARANCE));
      for (let i = 0; i < rings.length; i++) {
        const r = rings[i]!;
        expect(r.y - terrainHeight(terrain, r.x, r.z)).toBeGreaterThanOrEqual(RING_CLEARANCE - 1e-9);
        expect(Math.hypot(r.nx, r.ny, r.nz)).toBeCloseTo(1, 12);
        expect(r.status).toBe('ahead');
        if (i === 0) continue;
        const p = rings[i - 1]!;
        const across = Math.hypot(r.x - p.x, r.z - p.z);
        expect(across).toBeGreaterThanOrEqual(1500 - 1e-9);
        expect(across).toBeLessThanOrEqual(2200 + 1e-9);
        // The normal points from the ring before to this one.
        const d = Math.hypot(r.x - p.x, r.y - p.y, r.z - p.z);
        expect(r.nx).toBeCloseTo((r.x - p.x) / d, 12);
        // The course leads on: each ring's heading within 100 degrees of +x.
        expect(Math.abs(Math.atan2(r.z - p.z, r.x - p.x))).toBeLessThanOrEqual(1.75 + 1e-9);
      }
    }
    expect(() => layCourse({ terrain, seed: 1, count: 0, start: [0, 900, 0] })).toThrow(/layCourse: count must be an integer >= 1, got 0/);
  });

  it('passes a ring crossed inside its radius, misses one crossed outside, ignores the wrong way and far off', () => {
    const ring: Ring = { x: 100, y: 500, z: 0, nx: 1, ny: 0, nz: 0, status: 'ahead' };
    const cross = (y: number, z: number, back = false) =>
      back ? crossRing(ring, [102, y, z], [98, y, z]) : crossRing(ring, [98, y, z], [102, y, z]);
    expect(cross(500, 0)).toBe('passed');
    expect(cross(500 + 0.99 * RING_RADIUS, 0)).toBe('passed');
    expect(cross(500, -1.01 * RING_RADIUS)).toBe('missed');
    expect(cross(500 + 0.99 * MISS_RANGE, 0)).toBe('missed');
    expect(cross(500 + 1.01 * MISS_RANGE, 0)).toBeNull();
    expect(cross(500, 0, true)).toBeNull();
    expect(crossRing(ring, [90, 500, 0], [95, 500, 0])).toBeNull(); // not there yet
    // The crossing point is where the move meets the plane: a slanted move through the centre passes.
    expect(crossRing(ring, [90, 500 - 40, 0], [110, 500 + 40, 0])).toBe('passed');
    expect(nextRing([{ ...ring, status: 'passed' }, ring])).toBe(1);
    expect(nextRing([{ ...ring, status: 'missed' }])).toBe(-1);
  });

  it('gives stars for the share of rings passed', () => {
    expect([courseStars(10, 10), courseStars(7, 10), courseStars(6, 10), courseStars(4, 10), courseStars(3, 10)]).toEqual([3, 2, 1, 1, 0]);
  });
});
