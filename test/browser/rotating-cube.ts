/**
 * Helpers for the rotating cube's browser cases (rigid-3d-games and phone-controls): where a world
 * point of its room shows on the page, and the cube's state, read through `window.game`.
 */
import { expect } from 'vitest';
import type { GamePage } from './harness';

/** The cube's state: centre (x, y, z), m; speed, m/s; spin, rad/s; world time, s; the challenge's lit pad. */
export interface CubeState {
  x: number;
  y: number;
  z: number;
  speed: number;
  spin: number;
  time: number;
  pad: number;
  pads: number[][];
}

/** Reads the cube's state (see CubeState). */
export function cubeState(g: GamePage): Promise<CubeState> {
  return g.page.evaluate(() => {
    const game = window.game as unknown as {
      body(): number;
      world: { time: number; components: Record<'Position' | 'Velocity' | 'AngularVelocity', Record<'x' | 'y' | 'z', Float64Array>> };
      challenge(): { pad: number; pads: number[][] };
    };
    const c = game.world.components,
      e = game.body();
    const ch = game.challenge();
    return {
      x: c.Position.x[e]!,
      y: c.Position.y[e]!,
      z: c.Position.z[e]!,
      speed: Math.hypot(c.Velocity.x[e]!, c.Velocity.y[e]!, c.Velocity.z[e]!),
      spin: Math.hypot(c.AngularVelocity.x[e]!, c.AngularVelocity.y[e]!, c.AngularVelocity.z[e]!),
      time: game.world.time,
      pad: ch.pad,
      pads: ch.pads,
    };
  });
}

/**
 * Waits (up to `timeoutMs` of the clock) until the cube rests flat on a face: its centre under 0.51 m
 * (a 1 m cube on a face sits at 0.5 m; tipped 2 degrees onto an edge, at 0.52 m), slower than 0.05 m/s
 * and 0.1 rad/s. A cube that rolled short of its tipping point stands still for a moment at the top of
 * its swing back, tipped (its centre up to 0.71 m high), before it falls back onto its face.
 */
export async function waitCubeAtRest(g: GamePage, timeoutMs = 60_000): Promise<void> {
  await g.waitFor(
    () => {
      const game = window.game as unknown as {
        body?(): number;
        world: { time: number; components: Record<'Position' | 'Velocity' | 'AngularVelocity', Record<'x' | 'y' | 'z', Float64Array>> };
      };
      // The page's own hooks come after the kit's (its module has more to set up once the shell is ready).
      if (typeof game?.body !== 'function') return false;
      const c = game.world.components,
        e = game.body();
      return (
        game.world.time > 1 &&
        c.Position.y[e]! < 0.51 &&
        Math.hypot(c.Velocity.x[e]!, c.Velocity.y[e]!, c.Velocity.z[e]!) < 0.05 &&
        Math.hypot(c.AngularVelocity.x[e]!, c.AngularVelocity.y[e]!, c.AngularVelocity.z[e]!) < 0.1
      );
    },
    null,
    timeoutMs,
  );
}

/** Waits (up to 60 s of the clock) until the cube's centre is over 0.8 m along the floor from (x, z), m. */
export async function waitCubeMoved(g: GamePage, x: number, z: number): Promise<void> {
  await g.waitFor(
    ([x0, z0]) => {
      const game = window.game as unknown as { body(): number; world: { components: { Position: Record<'x' | 'z', Float64Array> } } };
      const P = game.world.components.Position;
      return Math.hypot(P.x[game.body()]! - x0!, P.z[game.body()]! - z0!) > 0.8;
    },
    [x, z],
    60_000,
  );
}

/** Page position (CSS px) of world point (x, y, z), m, through the game's three.js camera and the canvas' box. */
export function pageOf(g: GamePage, x: number, y: number, z: number): Promise<{ x: number; y: number }> {
  return g.page.evaluate(
    ([x, y, z]) => {
      type V = { x: number; y: number; project(c: unknown): V };
      const game = window.game as unknown as { app: { camera: { position: { constructor: new (x: number, y: number, z: number) => V } } } };
      const v = new game.app.camera.position.constructor(x!, y!, z!).project(game.app.camera);
      const r = document.querySelector('canvas')!.getBoundingClientRect();
      return { x: r.left + ((v.x + 1) / 2) * r.width, y: r.top + ((1 - v.y) / 2) * r.height };
    },
    [x, y, z],
  );
}

/**
 * Page position of world point (x, y, z) once two animation frames in a row put it within half a
 * pixel of each other (the camera may still be easing into its framing).
 */
export async function stillPageOf(g: GamePage, x: number, y: number, z: number): Promise<{ x: number; y: number }> {
  let at = await pageOf(g, x, y, z);
  for (let tries = 0; tries < 100; tries++) {
    await g.frames(1);
    const next = await pageOf(g, x, y, z);
    const still = Math.hypot(next.x - at.x, next.y - at.y) < 0.5;
    at = next;
    if (still) break;
  }
  return at;
}

/**
 * Sets the cube down by hand in the page: its centre at (x, 0.51, z), m, resting (no velocity or
 * spin), with face `face` of the game's FACES (+x, -x, +y, -y, +z, -z) on top, square to the world's axes.
 */
export async function placeCube(g: GamePage, x: number, z: number, face: number): Promise<void> {
  await g.page.evaluate(
    ([x, z, face]) => {
      const S = Math.SQRT1_2;
      // (x, y, z, w) with each face on top: +x up is +90 degrees about z, and so on.
      const up = [
        [0, 0, S, S],
        [0, 0, -S, S],
        [0, 0, 0, 1],
        [1, 0, 0, 0],
        [-S, 0, 0, S],
        [S, 0, 0, S],
      ][face!]!;
      const game = window.game as unknown as {
        body(): number;
        world: { components: Record<'Position' | 'Velocity' | 'AngularVelocity' | 'Orientation', Record<string, Float64Array>> };
      };
      const c = game.world.components,
        e = game.body();
      c.Position.x![e] = x!;
      c.Position.y![e] = 0.51;
      c.Position.z![e] = z!;
      [c.Orientation.x![e], c.Orientation.y![e], c.Orientation.z![e], c.Orientation.w![e]] = up as [number, number, number, number];
      for (const v of [c.Velocity, c.AngularVelocity]) v.x![e] = v.y![e] = v.z![e] = 0;
    },
    [x, z, face],
  );
}

/**
 * Rolls the resting cube forward with `roll` (a key press or a tap of the on-screen button) and checks
 * the roll: another face comes on top, the one the face net showed for forward before it; the cube
 * comes to rest flat; and it moved straight up the screen (more than 20 px, sideways under a fifth of
 * that), as the cube is dropped square to the camera's heading.
 */
export async function expectRollsStraightUp(g: GamePage, roll: () => Promise<void>): Promise<void> {
  type Net = { faceNet(): Record<string, string>; challenge(): { face: number } };
  const face = await g.page.evaluate(() => (window.game as unknown as Net).challenge().face);
  const net = await g.waitFor(() => {
    const n = (window.game as unknown as Net).faceNet();
    return n.top !== '' ? n : null;
  }, null);
  const before = await cubeState(g);
  const p0 = await pageOf(g, before.x, before.y, before.z);
  await roll();
  await g.waitFor((f) => (window.game as unknown as Net).challenge().face !== f, face, 60_000);
  await waitCubeAtRest(g);
  expect(await g.page.evaluate(() => (window.game as unknown as Net).challenge().face)).not.toBe(face);
  expect(await g.waitFor((w) => (window.game as unknown as Net).faceNet().top === w || null, net.w)).toBe(true);
  const after = await cubeState(g);
  const p1 = await pageOf(g, after.x, after.y, after.z);
  expect(p1.y).toBeLessThan(p0.y - 20);
  expect(Math.abs(p1.x - p0.x)).toBeLessThan(0.2 * Math.abs(p1.y - p0.y));
}

/**
 * Clicks (or taps, with `click`) the page position of the centre of floor cells around the lit pad of
 * layout 11 (its first pad at x = 1.5 m, z = 0.2 m; the puzzle's cells are 1 m squares centred on the
 * lit pad) and checks that the cube comes to rest on each cell clicked, its centre within 0.1 m of the
 * cell's centre: one cell behind the cube (farther from the camera, its picture partly covered by the
 * cube's) and a cell beside it too. A click on the cube's own cell moves nothing, costs no move and
 * the pop says why. Last the pad's own cell: the cube rests there and the pad counts.
 */
export async function expectClicksLandOnCells(g: GamePage, click: (x: number, y: number) => Promise<void>): Promise<void> {
  type Game = {
    challenge(): { pad: number; moves: number };
    pop(): { text: string; count: number };
    refused(): { count: number; shown: boolean };
  };
  await waitCubeAtRest(g);
  const s0 = await cubeState(g);
  expect(s0.pad).toBe(0);
  const [px, pz] = s0.pads[0]! as [number, number];
  const onto = async (i: number, j: number): Promise<CubeState> => {
    const at = await stillPageOf(g, px + i, 0, pz + j);
    const moves = await g.page.evaluate(() => (window.game as unknown as Game).challenge().moves);
    await click(at.x, at.y);
    // The click's push sets the cube's velocity at once and counts a move; then it slides to rest.
    await g.waitFor((n) => (window.game as unknown as Game).challenge().moves > n, moves);
    await waitCubeAtRest(g);
    return cubeState(g);
  };
  // From where it landed to a cell left of the pad, then the one behind that, then the one beside it.
  for (const [i, j] of [
    [-1, 0],
    [-1, -1],
    [0, -1],
  ] as const) {
    const s = await onto(i, j);
    expect(Math.hypot(s.x - (px + i), s.z - (pz + j)), `cell (${i}, ${j}) of the pad`).toBeLessThan(0.1);
  }
  // Its own cell: no move, none counted, a word why.
  const moves = await g.page.evaluate(() => (window.game as unknown as Game).challenge().moves);
  const pops = await g.page.evaluate(() => (window.game as unknown as Game).pop().count);
  const refused = await g.page.evaluate(() => (window.game as unknown as Game).refused().count);
  const here = await stillPageOf(g, px, 0, pz - 1);
  await click(here.x, here.y);
  const said = await g.waitFor((n) => {
    const p = (window.game as unknown as Game).pop();
    return p.count > n ? p.text : null;
  }, pops);
  expect(said).toContain('on that cell');
  // And a "can't go there" cue on the cell itself: a red ring flashed there (counted, shown now).
  expect(await g.page.evaluate(() => (window.game as unknown as Game).refused().count)).toBe(refused + 1);
  await g.frames(3);
  expect(await g.page.evaluate(() => (window.game as unknown as Game).challenge().moves)).toBe(moves);
  const still = await cubeState(g);
  expect(Math.hypot(still.x - px, still.z - (pz - 1))).toBeLessThan(0.1);
  // The pad's cell, next to it: the cube rests on the pad and it counts.
  const at = await stillPageOf(g, px, 0, pz);
  await click(at.x, at.y);
  await g.waitFor(() => (window.game as unknown as Game).challenge().pad === 1, null, 60_000);
  const s = await cubeState(g);
  expect(Math.hypot(s.x - px, s.z - pz)).toBeLessThan(0.1);
}
