/**
 * rotating-cube's room mode (the default), headless: the free cube lands on the floor and comes to
 * rest on a face (centre 0.5 m up), and thrown at a wall it bounces back instead of passing through;
 * and where the gallery lists it, with the two other pages that have no goal to win.
 */

import { readFileSync } from 'node:fs';
import { createPhysicsWorld, setAngularVelocity, setVelocity, step } from '@bitphysics/physics';
import { describe, expect, it } from 'vitest';
import { CARD_LINES } from '../../games/gallery-cards';
import { buildRotatingCube, EDGES, ROOM_HALF, rotatingCubeWorldOptions } from '../../games/rotating-cube/scene';

describe('rotating-cube room mode', () => {
  it('the cube falls, lands and rests on a face; thrown at a wall it stays in the room', () => {
    // No mode given: the room is the default, with Earth gravity.
    const world = createPhysicsWorld(rotatingCubeWorldOptions());
    const h = buildRotatingCube(world);
    expect(h.mode).toBe('room');
    expect(world.gravity[1]).toBeCloseTo(-9.81, 12);
    const P = world.components.Position,
      V = world.components.Velocity;
    expect(h.walls).toHaveLength(4);
    for (let i = 0; i < 180; i++) step(world);
    // Resting on a face: the centre of a 1 m cube is 0.5 m up (contact slop and soft contacts: 1 cm).
    expect(P.y[h.body]).toBeCloseTo(0.5, 1);
    expect(Math.abs(P.y[h.body]! - 0.5)).toBeLessThan(0.01);
    expect(Math.hypot(V.x[h.body]!, V.y[h.body]!, V.z[h.body]!)).toBeLessThan(0.05);
    // 8 m/s at the +x wall: the face reaches the wall in 0.3 s; with restitution 0.3 it comes back.
    setVelocity(world, h.body, [8, 0.5, 0]);
    setAngularVelocity(world, h.body, [0, 0, 0]);
    const O = world.components.Orientation,
      half = EDGES.room[0] / 2;
    let maxX = -Infinity,
      reach = -Infinity;
    for (let i = 0; i < 60; i++) {
      step(world);
      const e = h.body,
        x = O.x[e]!,
        y = O.y[e]!,
        z = O.z[e]!,
        w = O.w[e]!;
      maxX = Math.max(maxX, P.x[e]!);
      // The cube's farthest point along +x: its centre plus half an edge times the summed |x components|
      // of its three body axes (row x of its rotation matrix): half an edge on a face, up to the half
      // diagonal turned.
      const sx = Math.abs(1 - 2 * (y * y + z * z)) + Math.abs(2 * (x * y - w * z)) + Math.abs(2 * (x * z + w * y));
      reach = Math.max(reach, P.x[e]! + half * sx);
    }
    // The cube never enters the wall (the room's inside face at x = ROOM_HALF) by more than 2 cm (the
    // contacts' slop and soft push-out; measured farthest point 2.997 m, none): so its centre stays at least half an edge
    // inside, less those 2 cm (measured maxX 2.30 against 2.5).
    expect(reach).toBeLessThan(ROOM_HALF + 0.02);
    expect(maxX).toBeLessThan(ROOM_HALF - half + 0.02);
    expect(maxX).toBeGreaterThan(ROOM_HALF - 0.9);
    expect(V.x[h.body]).toBeLessThan(0.5);
  });
});

describe('pages without a goal in the gallery', () => {
  it('rotating-cube, balls-3d and earth-moon are listed in the physics playground, their cards saying what to explore', () => {
    // A stranger found them under Games with nothing to win. Each is a toy to explore (a score for a
    // spinning cube, a box of balls or the Moon's orbit would be made up), so each is a lab now.
    const explore: Record<string, RegExp> = {
      'rotating-cube': /spin axis wander.*flip over by itself/,
      'balls-3d': /gravity and bounce.*watch the pile settle/,
      'earth-moon': /speed up time.*Earth wobble/i,
    };
    for (const [folder, line] of Object.entries(explore)) {
      const entry = JSON.parse(readFileSync(new URL(`../../games/${folder}/game.json`, import.meta.url), 'utf8')) as { category: string };
      expect(entry.category, folder).toBe('Labs');
      expect(CARD_LINES[folder], folder).toMatch(line);
    }
  });
});
