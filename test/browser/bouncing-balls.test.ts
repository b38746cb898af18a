/**
 * Bouncing balls in headless Chromium: the hoop game (the goal shown above the box at once, a throw through
 * the hoop scores, is celebrated (the row says so and its score bumps, "+1" and praise over the hoop)
 * and is kept as the best, a ball thrown up from under the hoop stops at its net, the aiming arc
 * bounces off a wall, time up offers Play again under the box's floor; on a phone a tap leaves the
 * clock waiting and a pull shows the aiming arc, throws and starts the clock), the court's looks (no
 * trails, no plain physics walls), and the sandbox: a click (which starts no clock) and a slingshot
 * pull spawn balls (a pull that starts on a ball throws that ball, at once or after half a second held
 * still), holding still on a ball for 1 s drags it, P pauses (nothing moves while paused, motion
 * resumes after), N advances exactly one step, R rebuilds the same seeded scene. Aiming: a pull taken
 * back onto its press point cancels (mouse and touch), a pull straight down from the lowest heap ball
 * reaches the full speed inside the viewport, and a pull under way as the clock runs out is the round's
 * last throw, which counts (the round ends once its ball scores or misses). A rule reminder
 * ("Too high") stays until the next throw; on a phone a press on the field closes the parameters drawer,
 * and the "drag me" ball (off the side walls) scores with a finger pull that stays on the screen.
 * Tests that play the same page (size, touch, ball count) share it (./shared-page.ts); before each, the
 * game is reset (window.game.reset(), unpaused) and the page's error list emptied, so each starts from
 * the same seeded scene. Game seconds the tests wait for are stepped in the page (./stepping.ts), not
 * played in real time.
 */
import type { Page } from 'playwright-core';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { HOOP_HALF_WIDTH, HOOP_RADIUS, HOOP_SPOTS, hoopSegments, NET, slingRoom, slingSpeed } from '../../games/bouncing-balls/hoop';
import { BOX, SEGMENTS as RAMPS, SEGMENT_RADIUS } from '../../games/bouncing-balls/scene';
import { type GamePage, Harness, START_TIMEOUT_MS } from './harness';
import { decodePng } from './png';
import { sharedPage } from './shared-page';
import { touchPath } from './touch';

/** The extras bouncing-balls puts on window.game (see games/bouncing-balls/main.ts). */
interface BallsGame {
  paused: boolean;
  ballIds(): number[];
  crateIds(): number[];
  positions(): number[];
  spawn(x: number, y: number, vx?: number, vy?: number): number;
  renderer: { stats: { balls: number; frames: number } };
  world: { steps: number; components: { Velocity: { x: Float64Array; y: Float64Array } } };
}

const COUNT = 8;
/** Segments in the scene (games/bouncing-balls/scene.ts SEGMENTS) plus the hoop's backboard and rim (hoop.ts). */
const SEGMENTS = 3 + 2;

function balls(g: GamePage) {
  return g.page.evaluate(() => {
    const game = window.game as unknown as BallsGame;
    return {
      ids: game.ballIds(),
      positions: game.positions(),
      shown: game.renderer.stats.balls,
      steps: game.world.steps,
      paused: game.paused,
    };
  });
}

describe('bouncing balls', () => {
  let h: Harness;
  beforeAll(async () => {
    h = await Harness.start();
  }, START_TIMEOUT_MS);
  afterAll(async () => {
    await h?.close();
  });
  const shared = sharedPage(() => h, 'bouncing-balls', { query: { count: COUNT } });

  const open = async () => shared();

  it('starts with ?count balls plus the walls, shows the legend and the readout', async () => {
    const g = await open();
    const stats = await g.stats();
    expect(stats.entities).toBe(COUNT + SEGMENTS);
    const b = await balls(g);
    expect(b.ids.length).toBe(COUNT);
    await g.waitFor(() => (window.game as unknown as BallsGame).renderer.stats.balls === 8, null);
    const legend = await g.page.locator('.bp-legend').textContent();
    for (const key of ['P', 'N', 'R', 'Click', 'Drag']) expect(legend).toContain(key);
    await g.waitFor(() => /\d+ fps/.test(document.querySelector('[data-hud="fps"]')?.textContent ?? ''), null);
    expect(await g.page.locator('[data-hud="bodies"]').textContent()).toBe(`${COUNT} bodies`);
    // A game's looks, not a physics plot's: no trails unless asked for, and the court (frame, floor,
    // wooden ramps) drawn instead of the renderer's thin walls with their end dots.
    const looks = await g.page.evaluate(() => {
      const game = window.game as unknown as {
        params: { trails: boolean };
        app: { stage: { children: { label: string }[] } };
        renderer: { root: { children: { label: string; visible: boolean }[] } };
      };
      return {
        trails: game.params.trails,
        court: game.app.stage.children.some((c) => c.label === 'court'),
        plainWalls: game.renderer.root.children.find((c) => c.label === 'walls')?.visible,
      };
    });
    expect(looks).toEqual({ trails: false, court: true, plainWalls: false });
    expect(g.errors).toEqual([]);
  });

  it("phone 390 x 844: the tall court's best is read back after a reload, apart from the wide court's", async () => {
    const g = await h.openGame('bouncing-balls', { viewport: { width: 390, height: 844 }, touch: true, query: { count: 8 } });
    type Best = { best(): number; statusText(): string };
    await g.waitFor(() => typeof (window.game as unknown as Partial<Best> | undefined)?.best === 'function' || null, null);
    // The wide court's best (20) and the tall court's (8), as two earlier visits kept them.
    await g.page.evaluate(() => {
      localStorage.setItem('bitphysics.bouncing-balls.best-points', '20');
      localStorage.setItem('bitphysics.bouncing-balls.best-points.tall', '8');
    });
    await g.page.reload();
    await g.waitFor(() => typeof (window.game as unknown as Partial<Best> | undefined)?.best === 'function' || null, null);
    expect(await g.page.evaluate(() => (window.game as unknown as Best).best())).toBe(8);
    expect(await g.waitFor(() => /Best 8\b/.test((window.game as unknown as Best).statusText()) || null, null)).toBe(true);
    expect(g.errors).toEqual([]);
    await g.close();
  });

  it('a click adds exactly one ball, drawn on the next frame, and does not start the hoop clock', async () => {
    const g = await open();
    const before = await g.stats();
    await g.clickCanvas(0.5, 0.45);
    const after = await g.waitFor((n) => {
      const s = window.game!.stats();
      return s.entities === n + 1 ? s : null;
    }, before.entities);
    expect(after.entities).toBe(before.entities + 1);
    await g.frames(2);
    const b = await balls(g);
    expect(b.ids.length).toBe(COUNT + 1);
    expect(b.shown).toBe(COUNT + 1);
    // Only a throw starts the round: a click (meant to close a menu, say) cost the player time.
    expect(await g.page.evaluate(() => (window.game as unknown as HoopGame).round())).toMatchObject({ phase: 'ready', shots: 0 });
    expect(g.errors).toEqual([]);
  });

  it('thrown balls do not pile up: every basketball at rest after its throw or drop fades out and is removed', async () => {
    const g = await open();
    const r = await g.page.evaluate(() => {
      const game = window.game as unknown as BallsGame & { shoot(x: number, y: number): number; step(): void };
      game.paused = true;
      // 16 basketballs dropped side by side near the floor (shoot: as a throw releases them).
      const shot: number[] = [];
      for (let i = 0; i < 16; i++) shot.push(game.shoot(1 + i * 0.9, 1.2));
      for (let k = 0; k < 60; k++) game.step();
      const after1s = game.ballIds().length;
      for (let k = 0; k < 300; k++) game.step();
      const ids = game.ballIds();
      return { after1s, left: ids.length, gone: shot.filter((e) => !ids.includes(e)), shot };
    });
    // A fade takes 1 s from when the ball came to rest: 1 s in, most are still there; 6 s in, all 16
    // basketballs are gone and none of the scene's balls. (12, then 2, were kept: each throw's miss
    // stayed, and a stranger saw the heap grow by a ball a throw; a player expects a missed ball back.)
    expect(r.after1s).toBeGreaterThan(COUNT + 2);
    expect(r.left).toBe(COUNT);
    expect(r.gone).toHaveLength(16);
    expect(g.errors).toEqual([]);
  });
  it('balls knock when they hit: ball contacts play impact sounds once an input started the sound', async () => {
    const g = await open();
    type Sounding = { sound: { running: boolean; played: number } };
    await g.clickCanvas(0.5, 0.2);
    // The heap starts at rest (and the click's ball fades out at once): three sandbox balls thrown
    // down from the top land on it.
    await g.page.evaluate(() => {
      for (const x of [4, 8, 12]) (window.game as unknown as BallsGame).spawn(x, 8, 0, -5);
    });
    const before = await g.page.evaluate(() => (window.game as unknown as Sounding).sound.played);
    // The bouncing balls hit each other and the walls: begin events of ball contacts (contactEvents),
    // each a knock unless quieter than the threshold. Balls alone gave no events and no sound.
    await g.waitFor((n) => {
      const s = (window.game as unknown as Sounding).sound;
      return s.running && s.played >= n + 3;
    }, before);
    expect(g.errors).toEqual([]);
  });

  it('a pull throws a ball slingshot-style: from where the press began, opposite to the pull', async () => {
    const g = await open();
    await g.press('p'); // paused, so the new ball keeps the velocity it was thrown with
    const b = await g.canvasBox();
    // Where the press lands, m (before the throw: the status row's new hint may then resize the canvas).
    const press = await g.page.evaluate(
      ([x, y]) => {
        const cam = (window.game as unknown as { renderer: { camera: { toWorldX(x: number): number; toWorldY(y: number): number } } })
          .renderer.camera;
        return [cam.toWorldX(x), cam.toWorldY(y)];
      },
      [0.3 * b.width, 0.5 * b.height],
    );
    // Pressed at 30 % across, pulled left to 15 %: thrown to the right from the press point.
    await g.dragCanvas([0.3, 0.5], [0.15, 0.5], 6);
    const thrown = await g.waitFor(() => {
      const game = window.game as unknown as BallsGame;
      const ids = game.ballIds();
      if (ids.length !== 9) return null;
      const e = ids[ids.length - 1]! % 2 ** 25;
      const p = game.positions();
      return { vx: game.world.components.Velocity.x[e]!, vy: game.world.components.Velocity.y[e]!, x: p.at(-2)!, y: p.at(-1)! };
    }, null);
    expect(thrown.vx).toBeGreaterThan(2);
    expect(Math.abs(thrown.vy)).toBeLessThan(0.05 * thrown.vx);
    expect(Math.hypot(thrown.x - press[0]!, thrown.y - press[1]!)).toBeLessThan(0.05);
    expect(g.errors).toEqual([]);
  });

  it('P pauses: the play area dims and says "Paused"; nothing moves while paused, motion resumes after', async () => {
    const g = await open();
    type Shade = { pauseOverlay(): { visible: boolean; text: string } };
    await g.press('p');
    await g.waitFor(() => window.game!.paused, null);
    // Shown over the play area as in the other games (only a small "paused" in the sidebar before).
    const shade = await g.waitFor(() => {
      const o = (window.game as unknown as Shade).pauseOverlay();
      return o.visible ? o : null;
    }, null);
    expect(shade.text).toMatch(/^Paused · /);
    // A one-line banner at the box's top, clear of the hoop (its backboard's top is 1.6 m over the rim).
    const top = await g.page.evaluate(() => {
      const o = (window.game as unknown as { pauseOverlay(): { words: number[] } }).pauseOverlay();
      return o.words;
    });
    const hoop = await g.page.evaluate(() => (window.game as unknown as { hoop(): { y: number } }).hoop());
    const board = await g.worldToPage(0, hoop.y + 1.6);
    const canvasTop = await g.page.evaluate(() => document.querySelector('canvas')!.getBoundingClientRect().top);
    expect(canvasTop + top[1]! + top[3]!).toBeLessThan(board.y);
    expect(top[3]!).toBeLessThan(40);
    // The legend gives R once, as what it does here (it said "reset" and "new round (and reset)").
    const legend = await g.page.evaluate(() => {
      const el = document.querySelector('.bp-legend')!;
      const keys = [...el.querySelectorAll('*')].filter((e) => e.children.length === 0 && e.textContent === 'R');
      return { keys: keys.length, text: el.textContent ?? '' };
    });
    expect(legend.keys).toBe(1);
    expect(legend.text).toContain('new round');
    expect(legend.text).not.toMatch(/reset/);
    // A ball high up in the box, certain to fall once the game runs again.
    await g.page.evaluate(() => (window.game as unknown as BallsGame).spawn(8, 9.5, 1, 0));
    const a = await balls(g);
    await g.frames(10);
    const b = await balls(g);
    expect(b.steps).toBe(a.steps);
    expect(b.positions).toEqual(a.positions);
    await g.press('p');
    await g.waitFor(() => !window.game!.paused, null);
    await g.waitFor(() => !(window.game as unknown as Shade).pauseOverlay().visible || null, null);
    await g.waitFor((p0) => {
      const p = (window.game as unknown as BallsGame).positions();
      return p.length === p0.length && p.some((v, i) => Math.abs(v - p0[i]!) > 1e-6);
    }, a.positions);
    expect((await balls(g)).steps).toBeGreaterThan(a.steps);
    expect(g.errors).toEqual([]);
  });

  it('N advances exactly one step (and pauses)', async () => {
    const g = await open();
    // The heap starts at rest: a ball dropped from the top falls, and a step moves it.
    await g.clickCanvas(0.5, 0.2);
    await g.waitFor((n) => window.game!.stats().entities === n + 1, COUNT + SEGMENTS);
    await g.press('p');
    await g.waitFor(() => window.game!.paused, null);
    const a = await balls(g);
    await g.press('n');
    await g.waitFor((s) => window.game!.stats().steps === s + 1, a.steps);
    await g.frames(8);
    const b = await balls(g);
    expect(b.steps).toBe(a.steps + 1);
    expect(b.paused).toBe(true);
    expect(b.positions).not.toEqual(a.positions);
    // N while running pauses and steps once.
    await g.press('p');
    await g.waitFor(() => !window.game!.paused, null);
    await g.press('n');
    await g.waitFor(() => window.game!.paused, null);
    const c = await balls(g);
    await g.frames(5);
    expect((await balls(g)).steps).toBe(c.steps);
    expect(g.errors).toEqual([]);
  });

  it('R resets to the same seeded scene, keeping the pause state', async () => {
    const g = await open();
    await g.press('p');
    await g.waitFor(() => window.game!.paused, null);
    await g.press('r');
    const first = await balls(g);
    expect(first.steps).toBe(0);
    expect(first.ids.length).toBe(COUNT);
    // Play, add a ball, then reset again: same count, same positions, step 0, still paused.
    await g.press('p');
    await g.waitFor(() => window.game!.stats().steps > 20, null, 30_000);
    await g.clickCanvas(0.5, 0.45);
    await g.waitFor((n) => window.game!.stats().entities === n + 1, COUNT + SEGMENTS);
    await g.press('p');
    await g.waitFor(() => window.game!.paused, null);
    await g.press('r');
    const second = await balls(g);
    expect(second.steps).toBe(0);
    expect((await g.stats()).entities).toBe(COUNT + SEGMENTS);
    expect(second.positions).toEqual(first.positions);
    expect(second.paused).toBe(true);
    await g.waitFor(() => (window.game as unknown as BallsGame).renderer.stats.balls === 8, null);
    expect(g.errors).toEqual([]);
  });

  it('the heap has fallen at step 0: the page opens (and R resets) on the balls at rest low in the box, not a grid in the air', async () => {
    const g = await open();
    await g.press('p');
    await g.waitFor(() => window.game!.paused, null);
    await g.press('r');
    const state = await g.page.evaluate(() => {
      const game = window.game as unknown as BallsGame;
      const V = game.world.components.Velocity;
      return {
        steps: game.world.steps,
        heights: game.positions().filter((_, i) => i % 2 === 1),
        speeds: game.ballIds().map((e) => Math.hypot(V.x[e % 2 ** 25]!, V.y[e % 2 ** 25]!)),
      };
    });
    // Built, the balls hang on a grid from the box's top (up to 1.5 m/s each way); settled, the 8
    // balls of this page lie on the floor of the 10 m box (radii up to 0.6 m: two layers at most).
    expect(state.steps).toBe(0);
    expect(state.heights.length).toBe(COUNT);
    for (const y of state.heights) expect(y).toBeLessThan(BOX.max[1] / 4);
    for (const v of state.speeds) expect(v).toBeLessThan(0.5);
    await g.press('p');
    await g.waitFor(() => !window.game!.paused, null);
    expect(g.errors).toEqual([]);
  });

  it('the panel sets gravity, drag and restitution, and rebuilds with a new ball count', async () => {
    const g = await open();
    // The game keeps its panel in the settings drawer (the game arrangement); the toolbar button opens it.
    await g.page.getByRole('button', { name: 'parameters and charts' }).click();
    // lil-gui labels each input and select with its controller's name (aria-labelledby).
    const field = (name: string) => g.page.getByLabel(name, { exact: true });
    await field('gravity (m/s²)').fill('3.5');
    await field('gravity (m/s²)').press('Enter');
    await field('drag k (kg/s | kg/m)').fill('0.4');
    await field('drag k (kg/s | kg/m)').press('Enter');
    await field('drag').selectOption('quadratic');
    await field('restitution').fill('0.25');
    await field('restitution').press('Enter');
    const r = await g.page.evaluate(() => {
      const game = window.game as unknown as BallsGame & {
        world: { gravity: Float64Array; components: Record<string, Record<string, Float64Array>> };
      };
      const e = game.ballIds()[0]!;
      const c = game.world.components;
      return { gy: game.world.gravity[1], kq: c.QuadraticDrag!.k![e], kl: c.LinearDrag!.k![e], e: c.Material!.restitution![e] };
    });
    expect(r.gy).toBeCloseTo(-3.5, 12);
    expect(r.kq).toBeCloseTo(0.4, 12);
    expect(r.kl ?? 0).toBe(0);
    expect(r.e).toBeCloseTo(0.25, 12);
    await field('balls (rebuilds)').fill('30');
    await field('balls (rebuilds)').press('Enter');
    await g.waitFor((n) => window.game!.stats().entities === n, 30 + SEGMENTS);
    // The rebuilt world keeps the panel's settings.
    expect(await g.page.evaluate(() => (window.game as unknown as { world: { gravity: Float64Array } }).world.gravity[1])).toBeCloseTo(
      -3.5,
      12,
    );
    await g.waitFor(() => (window.game as unknown as BallsGame).renderer.stats.balls === 30, null);
    expect(g.errors).toEqual([]);
    // Back to the test count for the other tests.
    await field('balls (rebuilds)').fill('8');
    await field('balls (rebuilds)').press('Enter');
    await field('gravity (m/s²)').fill('9.81');
    await field('gravity (m/s²)').press('Enter');
    await field('drag').selectOption('none');
    await field('restitution').fill('0.8');
    await field('restitution').press('Enter');
    await g.waitFor((n) => window.game!.stats().entities === n, 8 + SEGMENTS);
    await g.page.getByRole('button', { name: 'parameters and charts' }).click();
    expect(await g.page.locator('.bp-side').isVisible()).toBe(false);
  });

  it('a pull that starts on a ball throws that ball, at once or after half a second held still; holding still on a ball for 1 s picks it up (a mouse joint, no ball added), and release lets go', async () => {
    const g = await open();
    // Paused while the ball is found and pressed (a loaded machine let it fall out from under the pointer).
    await g.press('p');
    const start = await g.page.evaluate(() => {
      const game = window.game as unknown as BallsGame & {
        world: { components: { Position: { x: Float64Array; y: Float64Array } } };
        remove(id: number): void;
      };
      // Alone in the box: a level throw into a neighbour is blocked, and a blocked release throws nothing.
      for (const id of game.ballIds().slice(1)) game.remove(id);
      const e = game.ballIds()[0]! % 2 ** 25;
      return { x: game.world.components.Position.x[e]!, y: game.world.components.Position.y[e]! };
    });
    const screen = (x: number, y: number) =>
      g.page.evaluate(
        ([x, y]) => {
          const cam = (window.game as unknown as { renderer: { camera: { toScreenX(x: number): number; toScreenY(y: number): number } } })
            .renderer.camera;
          const box = document.querySelector('canvas')!.getBoundingClientRect();
          return { x: box.left + cam.toScreenX(x), y: box.top + cam.toScreenY(y) };
        },
        [x, y] as const,
      );
    const from = await screen(start.x, start.y);
    // A pull that starts on the ball at once throws that ball (no ball added), opposite to the pull:
    // pulled 1.5 m towards the box's nearer side, it leaves towards the middle, level, and counts as a shot.
    const side = await screen(start.x < 8 ? start.x - 1.5 : start.x + 1.5, start.y);
    const toMiddle = start.x < 8 ? 1 : -1;
    /** Ball 0's velocity (m/s), the ball count and the round's shots, once a throw of it has been seen (else null), zeroing its velocity. */
    const throwOfFirst = (shots: number) =>
      g.waitFor(
        ([shots, count]) => {
          const game = window.game as unknown as BallsGame & {
            round(): { shots: number };
            world: { components: { Velocity: { x: Float64Array; y: Float64Array } } };
          };
          if (game.round().shots !== shots) return null;
          const e = game.ballIds()[0]! % 2 ** 25;
          const V = game.world.components.Velocity;
          const r = { vx: V.x[e]!, vy: V.y[e]!, added: game.ballIds().length - count, first: game.positions().slice(0, 2) };
          V.x[e] = 0;
          V.y[e] = 0;
          return r;
        },
        [shots, 1] as const,
      );
    await g.page.mouse.move(from.x, from.y);
    await g.page.mouse.down();
    await g.page.mouse.move(side.x, side.y, { steps: 3 });
    expect(await g.page.evaluate(() => (window.game as unknown as { drag: { joint: number } }).drag.joint)).toBe(0);
    await g.page.mouse.up();
    const thrown = await throwOfFirst(1);
    expect(thrown.added).toBe(0);
    expect(thrown.first).toEqual([start.x, start.y]); // paused: thrown from where it lay
    expect(toMiddle * thrown.vx).toBeGreaterThan(1);
    expect(Math.abs(thrown.vy)).toBeLessThan(0.1 * Math.abs(thrown.vx));
    // Pressed on the ball and held still half a second (aiming), then pulled: still a throw (a hold
    // of 0.45 s picked balls up from players who meant to throw).
    await g.page.mouse.move(from.x, from.y);
    await g.page.mouse.down();
    await g.page.waitForTimeout(500);
    await g.page.mouse.move(side.x, side.y, { steps: 3 });
    await g.page.mouse.up();
    const aimed = await throwOfFirst(2);
    expect(aimed.added).toBe(0);
    expect(toMiddle * aimed.vx).toBeGreaterThan(1);
    expect(await g.page.evaluate(() => (window.game as unknown as { drag: { joint: number } }).drag.joint)).toBe(0);
    // Held still on the ball: the hold (1 s) hands the pointer to the drag.
    await g.page.mouse.move(from.x, from.y);
    await g.page.mouse.down();
    const held = await g.waitFor(() => (window.game as unknown as { drag: { joint: number } }).drag.joint || null, null);
    expect(held).toBeGreaterThan(0);
    await g.press('p');
    // Pull to a point 2 m to the side at height 8 m (inside the 16 x 10 m box): free motion would keep
    // x and fall, so reaching within 0.6 m of the target shows the pull. Waited for in the page (20 s
    // at most) rather than for a fixed 40 frames: a loaded run once ended those 0.99 m away.
    const target = { x: start.x < 8 ? start.x + 2 : start.x - 2, y: 8 };
    const to = await screen(target.x, target.y);
    await g.page.mouse.move(to.x, to.y, { steps: 6 });
    const moved = await g.waitFor(
      (t) => {
        const game = window.game as unknown as BallsGame & { world: { components: { Position: { x: Float64Array; y: Float64Array } } } };
        const e = game.ballIds()[0]! % 2 ** 25;
        const r = { x: game.world.components.Position.x[e]!, y: game.world.components.Position.y[e]!, count: game.ballIds().length };
        return Math.hypot(r.x - t.x, r.y - t.y) < 0.6 ? r : null;
      },
      target,
      20_000,
    );
    await g.page.mouse.up();
    const after = await g.page.evaluate(() => (window.game as unknown as { drag: { joint: number } }).drag.joint);
    expect(Math.hypot(moved.x - target.x, moved.y - target.y)).toBeLessThan(0.6);
    expect(moved.count).toBe(1); // the press took the ball: no ball dropped or thrown
    expect(after).toBe(0);
    expect(g.errors).toEqual([]);
  });

  it('X drops a crate, a box that falls among the balls', async () => {
    const g = await open();
    const before = await g.page.evaluate(() => (window.game as unknown as BallsGame).crateIds().length);
    await g.press('x');
    await g.waitFor((n) => (window.game as unknown as BallsGame).crateIds().length === n + 1, before);
    const y0 = await g.page.evaluate(() => {
      const game = window.game as unknown as BallsGame & { world: { components: { Position: { y: Float64Array } } } };
      return game.world.components.Position.y[game.crateIds().at(-1)! % 2 ** 25]!;
    });
    await g.frames(20);
    const y1 = await g.page.evaluate(() => {
      const game = window.game as unknown as BallsGame & { world: { components: { Position: { y: Float64Array } } } };
      return game.world.components.Position.y[game.crateIds().at(-1)! % 2 ** 25]!;
    });
    expect(y1).toBeLessThan(y0);
    expect(g.errors).toEqual([]);
  });
});

/** What the hoop game puts on window.game. */
interface HoopGame {
  round(): {
    phase: 'ready' | 'playing' | 'over';
    score: number;
    timeLeft: number;
    spot: number;
    shots: number;
    seconds: number;
    atHoop: number;
    perHoop: number;
  };
  aimPath(): number[];
  aimFlight(): number[];
  aimSeconds(): number;
  world: { components: { Velocity: { x: Float64Array; y: Float64Array } } };
  best(): number;
  hoop(): { y: number; minX: number; maxX: number };
  shoot(x: number, y: number, vx?: number, vy?: number): number;
  statusText(): string;
  ballIds(): number[];
}

/** The hoop game with what the heap-throw cases step, aim and read (window.game). */
type HeapThrows = HoopGame & {
  params: { gravity: number };
  paused: boolean;
  reset(): void;
  step(): void;
  saveWorld(): unknown;
  restoreWorld(snap: unknown): void;
  aimFrom(e: number, vx: number, vy: number): number[];
  throwBall(e: number, vx: number, vy: number): boolean;
  world: {
    components: {
      Position: { x: Float64Array; y: Float64Array };
      Velocity: { x: Float64Array; y: Float64Array };
      Ball: { radius: Float64Array };
    };
  };
};

/**
 * Up to three throws from (8, 4) m, each given `seconds` of world time (stepped in the page), until
 * one scores: at `velocity` (m/s), or with null the drag-free arc that comes down on the hoop's rim
 * centre after 1.3 s. The game is left paused at the basket, so its celebration is read before it
 * ends. Returns the round's score (0 if no throw scored).
 */
async function shootUntilScored(g: GamePage, velocity: [number, number] | null, seconds: number): Promise<number> {
  for (let attempt = 0; attempt < 3; attempt++) {
    const score = await g.evaluate(
      ([v, seconds]) => {
        const game = window.game as unknown as HoopGame & { world: { time: number }; paused: boolean; step(): void };
        if (v) game.shoot(8, 4, v[0]!, v[1]!);
        else {
          const o = game.hoop();
          const x = 0.5 * (o.minX + o.maxX),
            T = 1.3;
          game.shoot(8, 4, (x - 8) / T, (o.y - 4 + 0.5 * 9.81 * T * T) / T);
        }
        const end = game.world.time + seconds;
        game.paused = true;
        while (game.round().score === 0 && game.world.time < end) game.step();
        return game.round().score;
      },
      [velocity, seconds] as const,
      'throwing at the hoop',
    );
    if (score > 0) return score;
  }
  return 0;
}

/**
 * Presses the mouse at `at`, drags to `to` in 8 moves and lets go; returns ball `id`'s velocity (m/s)
 * and the round's shot count just after the release.
 */
async function mouseThrow(g: GamePage, id: number, at: { x: number; y: number }, to: { x: number; y: number }) {
  const m = g.page.mouse;
  await m.move(at.x, at.y);
  await m.down();
  await m.move(to.x, to.y, { steps: 8 });
  await m.up();
  return g.page.evaluate((id) => {
    const game = window.game as unknown as AimGame;
    const e = id % 2 ** 25;
    return { vx: game.world.components.Velocity.x[e]!, vy: game.world.components.Velocity.y[e]!, shots: game.round().shots };
  }, id);
}

/** A finger down at the first point, through the others, then (after `before`, if given) lifted (CDP touch events). */
async function swipe(page: Page, points: Array<[number, number]>, before?: () => Promise<void>): Promise<void> {
  const cdp = await page.context().newCDPSession(page);
  const at = ([x, y]: [number, number]) => [{ x, y, id: 1 }];
  await cdp.send('Input.dispatchTouchEvent', { type: 'touchStart', touchPoints: at(points[0]!) });
  for (const p of points.slice(1)) await cdp.send('Input.dispatchTouchEvent', { type: 'touchMove', touchPoints: at(p) });
  await before?.();
  await cdp.send('Input.dispatchTouchEvent', { type: 'touchEnd', touchPoints: [] });
  await cdp.detach();
}

describe('bouncing balls: the hoop game', () => {
  let h: Harness;
  beforeAll(async () => {
    h = await Harness.start();
  }, START_TIMEOUT_MS);
  afterAll(async () => {
    await h?.close();
  });

  it('desktop 1280 x 800: the goal shows above the box; a throw through the hoop scores, is celebrated, leaves the hoop where it is and is kept as the best; time up offers Play again', async () => {
    const g = await h.openGame('bouncing-balls', { viewport: { width: 1280, height: 800 }, query: { count: 8, round: 6 } });
    const status = g.page.locator('[data-hud="hoop"]');
    await expect.poll(() => status.isVisible()).toBe(true);
    expect(await status.textContent()).toMatch(/through the hoop/);
    // The goal row sits above the box, not over it.
    const row = (await status.boundingBox())!;
    const top = await g.worldToPage(0, 10);
    expect(row.y + row.height).toBeLessThanOrEqual(top.y + 1);
    expect(await g.page.evaluate(() => (window.game as unknown as HoopGame).round())).toMatchObject({
      phase: 'ready',
      score: 0,
      seconds: 6,
    });
    // A drag-free arc from (8, 4) m coming down on the rim's centre after 1.3 s (the node test shows
    // the same throw through the hoop in the scene's physics). The eight sandbox balls are taken out
    // first (they knocked the throw away in some runs); up to three throws, each given 1.7 s of world
    // time (a loaded machine runs the world slower than the clock): three fit the 6 s round.
    await g.page.evaluate(() => {
      const game = window.game as unknown as HoopGame & { remove(id: number): void };
      for (const id of game.ballIds()) game.remove(id);
    });
    const before = await g.page.evaluate(() => (window.game as unknown as HoopGame).hoop());
    const score = await shootUntilScored(g, null, 1.7);
    expect(score).toBe(1);
    // The basket is celebrated: the status row says so and its score line bumps; over the old
    // hoop, "+2" and a word of praise (before, a small +1 and a ring for 0.8 s were all). The throw
    // touched nothing on its way: a swish, its basketball's 1 point and 1 more (hoop.ts SHOT_BONUS).
    const cheer = await g.waitFor(() => {
      const game = window.game as unknown as HoopGame & {
        app: { stage: { children: { label: string; visible: boolean; text?: string }[] } };
      };
      const texts = game.app.stage.children.filter((c) => c.visible && typeof c.text === 'string').map((c) => c.text);
      const numbers = document.querySelector('[data-hud="hoop"] [data-hud="numbers"]')!;
      return /Swish! 1 \+ 1 = \+2 · the clock runs/.test(game.statusText()) ? { texts, bump: numbers.classList.contains('bb-bump') } : null;
    }, null);
    expect(cheer.bump).toBe(true);
    // Over the hoop the same sum as on the status row: the ball's 1 and the swish's 1, then the total.
    expect(cheer.texts).toEqual(expect.arrayContaining(['+2', 'Swish! 1 + 1']));
    await g.page.evaluate(() => {
      (window.game as unknown as { paused: boolean }).paused = false;
    });
    const after = await g.page.evaluate(() => ({
      hoop: (window.game as unknown as HoopGame).hoop(),
      best: (window.game as unknown as HoopGame).best(),
      stored: localStorage.getItem('bitphysics.bouncing-balls.best-points'),
      text: (window.game as unknown as HoopGame).statusText(),
    }));
    // The hoop stays for the next baskets (hoop.ts BASKETS_PER_HOOP): the throw that scored scores again.
    expect(after.hoop).toEqual(before);
    expect(after.best).toBe(2);
    expect(after.stored).toBe('2');
    // A basketball's swish is 2 points (x1, the streak's first); the next basket would score x2.
    expect(after.text).toMatch(/Points 2 · ×2 .*Best 2/);
    // Thrown straight up from under the hoop: the net stops it (its top at the net's bottom, 1.1 m under
    // the rim) and it falls back; before, it flew up through the drawn net and the rim's opening.
    const under = await g.page.evaluate(() => {
      const game = window.game as unknown as HoopGame & {
        paused: boolean;
        step(): void;
        world: { components: { Position: { y: Float64Array } } };
      };
      game.paused = true;
      // 1.75 m under the rim: clear of the ramp under this spot, the ball's top 0.45 m under the net.
      const o = game.hoop();
      const id = game.shoot(0.5 * (o.minX + o.maxX), o.y - 1.75, 0, 6);
      let top = -Infinity;
      for (let k = 0; k < 40; k++) {
        game.step();
        top = Math.max(top, game.world.components.Position.y[id % 2 ** 25]! + 0.4);
      }
      (game as unknown as { remove(id: number): void }).remove(id);
      game.paused = false;
      return { top, rim: o.y };
    });
    expect(under.top).toBeLessThanOrEqual(under.rim - 1.1 + 1e-6);
    expect(under.top).toBeGreaterThan(under.rim - 1.1 - 0.05);
    // The predicted flight bounces: pressed low in the box's right half and pulled left and down, the
    // throw goes right into the wall and the flight comes back off it. Once the clock runs the arc drawn
    // is the flight's start as in the warm-up: at least its first 1.2 s, point for point, up to its
    // first touch (the wall). (Cut to 0.6 s once the clock ran, with "aim line shortened" on the label,
    // a stranger guessed the rest: issue 34.)
    // It no longer goes on through the bounce: a stranger wiggled the pull until the bounce's dots went
    // through the hoop, and reading the bounce is the player's to do.
    const press = await g.worldToPage(9, 2),
      pull = await g.worldToPage(5, 1.6);
    await g.page.mouse.move(press.x, press.y);
    await g.page.mouse.down();
    await g.page.mouse.move(pull.x, pull.y, { steps: 4 });
    const aim = await g.page.evaluate(() => {
      const game = window.game as unknown as HoopGame;
      return {
        shown: game.aimPath(),
        flight: game.aimFlight(),
        seconds: game.aimSeconds(),
        phase: game.round().phase,
        label: (game as unknown as { aimLabel(): string }).aimLabel(),
      };
    });
    await g.page.mouse.up();
    const xs = aim.flight.filter((_, i) => i % 2 === 0);
    expect(Math.max(...xs)).toBeGreaterThan(15.5);
    expect(xs.at(-1)!).toBeLessThan(Math.max(...xs) - 1);
    expect(aim).toMatchObject({ phase: 'playing', seconds: 1.2 });
    expect(aim.label).toMatch(/power \d+%/);
    expect(aim.label).not.toMatch(/shortened/);
    // A point every 4 steps of 1/60 s from the throw: 1.2 s is 19 points at most (one more a touch);
    // the wall ends this one sooner.
    expect(aim.shown.length).toBeGreaterThanOrEqual(8);
    expect(aim.shown.length).toBeLessThanOrEqual(2 * 21);
    expect(aim.shown.length).toBeLessThan(aim.flight.length - 4);
    for (let i = 0; i < aim.shown.length; i++) expect(aim.shown[i]).toBeCloseTo(aim.flight[i]!, 9);
    // Right to the wall and ending there: its last point is its rightmost, at the wall, and none
    // comes back off it (the flight does).
    const shownXs = aim.shown.filter((_, i) => i % 2 === 0);
    for (let i = 1; i < shownXs.length; i++) expect(shownXs[i]!).toBeGreaterThan(shownXs[i - 1]!);
    expect(shownXs.at(-1)!).toBeGreaterThan(15.5);
    expect(shownXs.at(-1)!).toBeCloseTo(Math.max(...xs), 9);
    // A ball dropped from above the rim's line does not count: 2 s on (stepped in the page), through
    // the hoop and its net, the score is as it was.
    const shots = await g.page.evaluate(() => {
      const game = window.game as unknown as HoopGame & { step(): void; paused: boolean };
      const o = game.hoop();
      game.shoot(0.5 * (o.minX + o.maxX), o.y + 1.2);
      const shots = game.round().shots;
      for (let k = 0; k < 120; k++) game.step();
      game.paused = false;
      return shots;
    });
    expect(await g.page.evaluate(() => (window.game as unknown as HoopGame).round())).toMatchObject({ score: 1, shots: shots });
    // The 6 s round ends (stepped in the page): time up, the Play-again button, which starts a new
    // round keeping the best.
    await g.runUntil(() => (window.game as unknown as HoopGame).round().phase === 'over', null, { draw: false });
    await g.frames(2);
    expect(await status.textContent()).toMatch(/Time!/);
    // Once the round is over nothing is thrown or aimed behind the end card: the same pull as above
    // (on a playing round it aims and throws) shows no arc and adds no throw (a stranger aimed and
    // threw balls behind the card).
    const overShots = await g.page.evaluate(() => (window.game as unknown as HoopGame).round().shots);
    await g.page.mouse.move(press.x, press.y);
    await g.page.mouse.down();
    await g.page.mouse.move(pull.x, pull.y, { steps: 4 });
    const overAim = await g.page.evaluate(() => (window.game as unknown as HoopGame).aimPath().length);
    await g.page.mouse.up();
    await g.frames(2);
    expect(overAim).toBe(0);
    expect(await g.page.evaluate(() => (window.game as unknown as HoopGame).round().shots)).toBe(overShots);
    // The end card over the box: the round's points, its baskets and the best.
    const card = await g.page.evaluate(() => {
      const stage = (
        window.game as unknown as { app: { stage: { children: { label: string; visible: boolean; children?: { text?: string }[] }[] } } }
      ).app.stage;
      const c = stage.children.find((k) => k.label === 'end-card');
      return { visible: c?.visible, texts: (c?.children ?? []).map((k) => k.text).filter(Boolean) };
    });
    expect(card.visible).toBe(true);
    expect(card.texts).toEqual(expect.arrayContaining(['2 points']));
    // The result first: the points, then how they stand against the best, then what made them
    // (a stranger found "Now beat that!" between the details).
    expect(card.texts.join('\n').split('\n').slice(0, 3)).toEqual(['Time!', '2 points', 'Now beat that!']);
    // The swish's bonus said as everywhere else: +1.
    expect(card.texts.join(' ')).toMatch(/1 swish \(\+1 each\) · 0 trick shots \(\+3 each\)/);
    expect(card.texts.join(' ')).toMatch(/1 basket from \d+ throws/);
    // The first scoring round has no best to beat: said plainly, not cheered as a new best.
    // On a line of its own (it wrapped mid-phrase at 390 px as part of the streak's line).
    expect(card.texts.join('\n')).toMatch(/\nNow beat that!\n/);
    expect(card.texts.join(' ')).not.toMatch(/new best|best round yet/);
    expect(await status.textContent()).not.toMatch(/best!/);
    // Paused over the end card, the pause overlay's words stand clear of the card (in the middle of
    // the view they covered its lines).
    await g.press('p');
    await g.frames(2);
    const paused = await g.page.evaluate(() => {
      const game = window.game as unknown as {
        pauseOverlay(): { visible: boolean; words: number[] };
        endCard(): { visible: boolean; box: number[] };
      };
      return { words: game.pauseOverlay(), card: game.endCard() };
    });
    expect(paused.words.visible && paused.card.visible).toBe(true);
    const [, wy, , wh] = paused.words.words as [number, number, number, number];
    const [, cy, , ch] = paused.card.box as [number, number, number, number];
    expect(wy >= cy + ch || wy + wh <= cy, `words ${wy}+${wh}, card ${cy}+${ch}`).toBe(true);
    await g.press('p');
    await g.frames(2);
    const again = g.page.getByRole('button', { name: 'Play again ▶' });
    // On the stand under the box's floor, inside the page: clear of the top ramps (a stranger found
    // it over the top one when it floated over the top of the box) and of the balls in the box.
    const button = (await again.boundingBox())!;
    expect(button.y).toBeGreaterThan((await g.worldToPage(0, 0)).y);
    expect(button.y + button.height).toBeLessThanOrEqual(800);
    await again.click();
    // The click resets the round at once; the button goes with the status row's next drawn frame. A
    // check right after the phase changed raced that frame and failed on a loaded machine ("expected
    // 1 to be +0"): the wait is for both, in the page's frames (10 s before it fails).
    await g.waitFor(
      () =>
        (window.game as unknown as HoopGame).round().phase === 'ready' &&
        ![...document.querySelectorAll('button')].some((b) => b.textContent === 'Play again ▶'),
      null,
    );
    expect(await g.page.evaluate(() => (window.game as unknown as HoopGame).best())).toBe(2);
    expect(await again.count()).toBe(0);
    // Heap throws fly their shown arc: the default heap of 40 balls settled 10 s (paused, stepped),
    // then the first two heap balls (in a fixed order) with an arc clean for 0.5 s (no red cross, no
    // bounce) thrown at 9 m/s 20 degrees off the vertical. Each is on its drag-free arc 0.5 s later
    // within 2 cm; before, the heap's neighbours knocked the second one 2.2 m off it.
    const offs = await g.page.evaluate(() => {
      const game = window.game as unknown as HoopGame & {
        params: { count: number; gravity: number };
        paused: boolean;
        reset(): void;
        step(): void;
        aimFrom(e: number, vx: number, vy: number): number[];
        throwBall(e: number, vx: number, vy: number): void;
        world: { components: { Position: { x: Float64Array; y: Float64Array }; Velocity: { x: Float64Array; y: Float64Array } } };
      };
      game.params.count = 40;
      game.reset();
      game.paused = true;
      for (let k = 0; k < 600; k++) game.step();
      const g = game.params.gravity,
        C = game.world.components,
        found: number[] = [];
      const ids = game.ballIds();
      for (let q = 0; q < ids.length && found.length < 2; q++) {
        const e = ids[(q * 17) % ids.length]!,
          s = e % 2 ** 25;
        const x = C.Position.x[s]!,
          y = C.Position.y[s]!;
        if (y > 4 || Math.hypot(C.Velocity.x[s]!, C.Velocity.y[s]!) > 0.3) continue;
        for (const angle of [70, 110, 65, 115, 75, 105, 60, 120]) {
          const vx = 9 * Math.cos((angle * Math.PI) / 180),
            vy = 9 * Math.sin((angle * Math.PI) / 180);
          // The arc's points every 4 steps: the first 8 on the parabola (0.53 s) make it clean.
          const path = game.aimFrom(e, vx, vy);
          let clean = path.length >= 20;
          for (let i = 1; clean && i <= 8; i++) {
            const t = (4 / 60) * i;
            clean = Math.hypot(path[2 * i]! - (x + vx * t), path[2 * i + 1]! - (y + vy * t - 0.5 * g * t * t)) < 1e-6;
          }
          if (!clean) continue;
          game.throwBall(e, vx, vy);
          for (let k = 0; k < 30; k++) game.step();
          found.push(Math.hypot(C.Position.x[s]! - (x + vx * 0.5), C.Position.y[s]! - (y + vy * 0.5 - 0.5 * g * 0.25)));
          for (let k = 0; k < 240; k++) game.step();
          break;
        }
      }
      return found;
    });
    expect(offs).toHaveLength(2);
    for (const off of offs) expect(off).toBeLessThan(0.02);
    // A heap ball with a ball on top of it, thrown straight up at 9 m/s, flies as a new ball would:
    // it is lifted over the ball on top (main.ts liftSpot) instead of handing it the throw. The first three such
    // balls (nothing else within 2.4 m above them, so only the neighbour is in the way, and no ramp up
    // to 2.4 m over the neighbour, where the ball is lifted to) each rise at
    // least 90 % of their free rise in 0.25 s (1.94 m), and the aiming arc rises past that (it does
    // not end on the neighbour). Before, the neighbour took part of the throw and the arc ended on it.
    const wedged = await g.page.evaluate(
      (ramps) => {
        const game = window.game as unknown as HeapThrows & { params: { count: number } };
        const out: { rise: number; free: number; arcRise: number }[] = [];
        // Heaps of 40 balls, then 44 and 48 if that one has fewer than three such balls.
        for (const count of [40, 44, 48]) {
          if (out.length >= 3) break;
          game.params.count = count;
          game.reset();
          game.paused = true;
          for (let k = 0; k < 600; k++) game.step();
          const C = game.world.components,
            g = game.params.gravity;
          const ids = game.ballIds();
          for (const e of ids) {
            if (out.length >= 3) break;
            const s = e % 2 ** 25,
              x = C.Position.x[s]!,
              y = C.Position.y[s]!,
              r = C.Ball.radius[s]!;
            if (Math.hypot(C.Velocity.x[s]!, C.Velocity.y[s]!) > 0.3) continue;
            // Balls over it: touching now (the one on top) and any further up its way.
            const over = ids.filter((o) => {
              const q = o % 2 ** 25;
              return (
                o !== e && Math.abs(C.Position.x[q]! - x) < r + C.Ball.radius[q]! && C.Position.y[q]! > y && C.Position.y[q]! < y + 2.4
              );
            });
            const touching = over.filter((o) => {
              const q = o % 2 ** 25;
              return Math.hypot(C.Position.x[q]! - x, C.Position.y[q]! - y) < r + C.Ball.radius[q]! + 0.02;
            });
            if (touching.length !== 1 || over.length !== 1) continue;
            // No ramp over it either, up to 2.4 m above the ball on top (where it is lifted to).
            const top = C.Position.y[touching[0]! % 2 ** 25]!;
            const rampOver = ramps.some(([ax, ay, bx, by, wr]) => {
              for (let u = 0; u <= 1; u += 0.01) {
                const px = ax! + u * (bx! - ax!),
                  py = ay! + u * (by! - ay!);
                if (Math.abs(px - x) < r + wr! && py > y && py < top + 2.4 + r + wr!) return true;
              }
              return false;
            });
            if (rampOver) continue;
            const arc = game.aimFrom(e, 0, 9);
            const arcRise = Math.max(...arc.filter((_, i) => i % 2 === 1)) - y;
            game.throwBall(e, 0, 9);
            for (let k = 0; k < 15; k++) game.step();
            out.push({ rise: C.Position.y[s]! - y, free: 9 * 0.25 - 0.5 * g * 0.25 * 0.25, arcRise });
            for (let k = 0; k < 240; k++) game.step();
          }
        }
        return out;
      },
      RAMPS.map(([ax, ay, bx, by]) => [ax, ay, bx, by, SEGMENT_RADIUS]),
    );
    expect(wedged).toHaveLength(3);
    for (const w of wedged) {
      expect(w.rise).toBeGreaterThan(0.9 * w.free);
      expect(w.arcRise).toBeGreaterThan(w.free);
    }
    expect(g.errors).toEqual([]);
    await g.close();
  });

  it('desktop 1280 x 800: "Too high" stays on the status row until the next throw, which ends it', async () => {
    // A page of its own: on the page shared with the baskets' cases its last check timed out twice in 4 runs.
    const g = await h.openGame('bouncing-balls', { viewport: { width: 1280, height: 800 }, query: { count: 8 } });
    await expect.poll(() => g.page.locator('[data-hud="hoop"]').isVisible()).toBe(true);
    const hint = () => g.page.locator('[data-hud="hoop"] [data-hud="hint"]').textContent();
    // A throw 1 m above the rim's line (straight up, so it lands in the box and lies there).
    const t0 = await g.page.evaluate(() => {
      const game = window.game as unknown as HoopGame & { world: { time: number } };
      game.shoot(2, game.hoop().y + 1, 0, 3);
      return game.world.time;
    });
    await expect.poll(hint).toMatch(/^Too high: throw from below the orange line/);
    // 6 s of world time later (more than one turn of the teaching hints, 5 s; before, the reminder
    // gave way to them after 2.5 s) the reminder is still there. The 6 s are stepped in the page
    // (the status row is made from the game's state on each frame drawn after).
    await g.runUntil((t) => (window.game as unknown as { world: { time: number } }).world.time > t + 6, t0, { draw: false });
    await g.frames(2);
    expect(await hint()).toMatch(/^Too high: throw from below the orange line/);
    // A throw from below the line ends it.
    await g.page.evaluate(() => (window.game as unknown as HoopGame).shoot(2, 1.5, 0, 3));
    await expect.poll(hint).not.toMatch(/Too high/);
    expect(g.errors).toEqual([]);
    await g.close();
  });

  describe('desktop 1280 x 800, 8 balls, one page', () => {
    const page = sharedPage(() => h, 'bouncing-balls', { viewport: { width: 1280, height: 800 }, query: { count: 8 } });

    it("desktop 1280 x 800: a throw off the box's top into the hoop is a plain basket, not a trick shot (a lob off the top was the best play)", async () => {
      const g = page();
      await g.page.evaluate(() => {
        const game = window.game as unknown as HoopGame & { remove(id: number): void };
        for (const id of game.ballIds()) game.remove(id);
      });
      // From (8, 4) m at (5.5, 12.5) m/s: its top meets the ceiling at about x 11 m and it comes down
      // through the first hoop's opening (hoop.ts throwPath with one ceiling bounce scores for vy 11.8
      // to 13.3 m/s at this vx). Up to three throws, each given 2.5 s of world time.
      const score = await shootUntilScored(g, [5.5, 12.5], 2.5);
      expect(score).toBe(1);
      const r = await g.page.evaluate(() => {
        const game = window.game as unknown as HoopGame & { round(): { lastStyle: string; lastPoints: number; tricks: number } };
        return { ...game.round(), text: game.statusText() };
      });
      // A basketball's 1 point, x1 (the streak's first basket): the ceiling adds nothing (it was a
      // trick shot's +3), and it is no swish either (it touched the box's top).
      expect(r).toMatchObject({ lastStyle: 'plain', lastPoints: 1, tricks: 0 });
      expect(r.text).not.toMatch(/Trick shot/);
      expect(g.errors).toEqual([]);
    });

    it('desktop 1280 x 800: a throw off the backboard or the rim into the hoop is a plain basket, not a trick shot', async () => {
      const g = page();
      const at = await g.page.evaluate(() => {
        const game = window.game as unknown as HoopGame & { reset(): void; paused: boolean; remove(id: number): void };
        game.reset();
        game.paused = true;
        for (const id of game.ballIds()) game.remove(id);
        return game.hoop();
      });
      // The first hoop (rim 12 to 14 m at 6 m, its board on the right).
      expect(at).toMatchObject({ minX: 12, maxX: 14, y: 6 });
      // From (8, 4) m at (5.5, 8) m/s: a line drive that meets the hoop (board or rim) and drops in; in
      // the physics world with the hoop alone so do its neighbours 0.25 m/s either way (touches.ts
      // forEachTouch: the hoop, then down through the opening). Up to three throws, 2.5 s each.
      expect(await shootUntilScored(g, [5.5, 8], 2.5)).toBe(1);
      const r = await g.page.evaluate(() =>
        (window.game as unknown as { round(): { lastStyle: string; tricks: number; swishes: number } }).round(),
      );
      // Before, the contact events' body 0 (every static thing) made the backboard and rim "a wall": +3.
      expect(r).toMatchObject({ lastStyle: 'plain', tricks: 0, swishes: 0 });
      expect(g.errors).toEqual([]);
    });

    it('desktop 1280 x 800: the hoop stays for three baskets (the same throw scores each time, 3 s back each after the first), then moves', async () => {
      const g = page();
      const r = await g.page.evaluate(() => {
        const game = window.game as unknown as HoopGame & {
          paused: boolean;
          reset(): void;
          step(): void;
          remove(id: number): void;
          world: { time: number };
        };
        game.reset();
        game.paused = true;
        for (const id of game.ballIds()) game.remove(id);
        const seen: { hoop: unknown; score: number; atHoop: number; timeLeft: number; elapsed: number }[] = [];
        const first = game.hoop();
        // The same throw each time: from (8, 4) m, the drag-free arc down on the first hoop's rim centre after 1.3 s.
        const x = 0.5 * (first.minX + first.maxX),
          T = 1.3;
        for (let k = 0; k < 3; k++) {
          const before = game.round().score,
            t0 = game.world.time,
            left0 = game.round().timeLeft;
          game.shoot(8, 4, (x - 8) / T, (first.y - 4 + 0.5 * 9.81 * T * T) / T);
          while (game.round().score === before && game.world.time < t0 + 2) game.step();
          // Its ball is gone (a basket takes it out); the clock's change: what ran, and what came back.
          seen.push({
            hoop: game.hoop(),
            score: game.round().score,
            atHoop: game.round().atHoop,
            timeLeft: game.round().timeLeft - left0,
            elapsed: k === 0 ? 0 : game.world.time - t0,
          });
          if (k < 2) for (let i = 0; i < 30; i++) game.step();
        }
        return { first, seen };
      });
      expect(r.seen.map((s) => s.score)).toEqual([1, 2, 3]);
      // The first two leave the hoop where it was (the repeated throw scored again); the third moves it.
      expect(r.seen[0]!.hoop).toEqual(r.first);
      expect(r.seen[1]!.hoop).toEqual(r.first);
      expect(r.seen[2]!.hoop).not.toEqual(r.first);
      expect(r.seen.map((s) => s.atHoop)).toEqual([1, 2, 0]);
      // The clock (running from the first basket) gained 3 s at each later basket, less the world time
      // since the throw (to 1/60 s, a step).
      for (const s of r.seen.slice(1)) expect(s.timeLeft).toBeCloseTo(3 - s.elapsed, 1);
      // Paused at the third basket: the status row, written on the next frames, says so.
      await g.waitFor(() => /\+3 s · the hoop moved/.test((window.game as unknown as HoopGame).statusText()) || null, null);
      await g.page.evaluate(() => {
        (window.game as unknown as { paused: boolean }).paused = false;
      });
      expect(g.errors).toEqual([]);
    });

    it('desktop 1280 x 800: after the third basket the hoop waits for a ball still in flight to come down, then moves', async () => {
      const g = page();
      const r = await g.page.evaluate(() => {
        const game = window.game as unknown as HoopGame & {
          paused: boolean;
          reset(): void;
          step(): void;
          remove(id: number): void;
          positions(): number[];
          ballIds(): number[];
          world: { time: number };
        };
        game.reset();
        game.paused = true;
        for (const id of game.ballIds()) game.remove(id);
        const first = game.hoop();
        const x = 0.5 * (first.minX + first.maxX),
          T = 1.3;
        const basket = () => game.shoot(8, 4, (x - 8) / T, (first.y - 4 + 0.5 * 9.81 * T * T) / T);
        for (let k = 0; k < 2; k++) {
          const before = game.round().score;
          basket();
          while (game.round().score === before) game.step();
          for (let i = 0; i < 30; i++) game.step();
        }
        // The third basket, and a lob straight up from (3, 2) m at 12 m/s thrown 0.4 s after it: up
        // for 1.2 s, it comes back below the rim's line 2 s or more after the third basket.
        const before = game.round().score;
        basket();
        for (let i = 0; i < 24; i++) game.step();
        const lob = game.shoot(3, 2, 0, 12);
        while (game.round().score === before) game.step();
        const scoredAt = game.world.time;
        const at3 = { hoop: game.hoop(), spot: game.round().spot };
        // Stepped until the hoop moves (at most 5 s): where the lob is then.
        while (JSON.stringify(game.hoop()) === JSON.stringify(first) && game.world.time < scoredAt + 5) game.step();
        const i = game.ballIds().indexOf(lob);
        return {
          first,
          at3,
          movedAfter: game.world.time - scoredAt,
          lobY: i < 0 ? null : game.positions()[2 * i + 1]!,
          moved: game.hoop(),
        };
      });
      // The round dealt the next spot at the third basket, but the hoop stayed while the lob flew.
      expect(r.at3.spot).not.toBe(0);
      expect(r.at3.hoop).toEqual(r.first);
      expect(r.moved).not.toEqual(r.first);
      // It moved as the lob came down below the rim's line (a miss), not before: the lob is there
      // 12 / 9.81 + sqrt(2 (2 + 12^2 / 19.62 - 6) / 9.81) = 2.05 s after its throw (drag-free), which
      // was 0.4 s after the basket's throw, 1.3 s before the basket: 1.15 s after the basket, within
      // 0.15 s (the crossing steps, 1/60 s each).
      expect(Math.abs(r.movedAfter - 1.15), `moved ${r.movedAfter} s after the basket`).toBeLessThan(0.15);
      expect(r.lobY === null || r.lobY < r.first.y).toBe(true);
      await g.page.evaluate(() => {
        (window.game as unknown as { paused: boolean }).paused = false;
      });
      expect(g.errors).toEqual([]);
    });

    it('desktop 1280 x 800: a ball in flight at the third basket scores in the hoop that waited for it, and the next hoop starts its count from none', async () => {
      const g = page();
      const r = await g.page.evaluate(() => {
        const game = window.game as unknown as HoopGame & {
          paused: boolean;
          reset(): void;
          step(): void;
          remove(id: number): void;
          ballIds(): number[];
          world: { time: number };
        };
        game.reset();
        game.paused = true;
        for (const id of game.ballIds()) game.remove(id);
        const first = game.hoop();
        const x = 0.5 * (first.minX + first.maxX),
          T = 1.3;
        const basket = () => game.shoot(8, 4, (x - 8) / T, (first.y - 4 + 0.5 * 9.81 * T * T) / T);
        for (let k = 0; k < 2; k++) {
          const before = game.round().score;
          basket();
          while (game.round().score === before) game.step();
          for (let i = 0; i < 30; i++) game.step();
        }
        // The third basket's throw, and the same throw again 0.4 s later (apart from the first all the way).
        basket();
        for (let i = 0; i < 24; i++) game.step();
        basket();
        while (game.round().score < 3) game.step();
        const at3 = game.hoop();
        const t3 = game.world.time;
        while (game.round().score < 4 && game.world.time < t3 + 2) game.step();
        return { first, at3, score: game.round().score, atHoop: game.round().atHoop, after: game.hoop(), gap: game.world.time - t3 };
      });
      // The fourth ball went in the first hoop 0.4 s after the third (24 steps of 1/60 s, within a step).
      expect(r.at3).toEqual(r.first);
      expect(r.score).toBe(4);
      expect(Math.abs(r.gap - 0.4)).toBeLessThan(0.02);
      // Then the hoop moved, none of its three baskets made yet.
      expect(r.after).not.toEqual(r.first);
      expect(r.atHoop).toBe(0);
      await g.page.evaluate(() => {
        (window.game as unknown as { paused: boolean }).paused = false;
      });
      expect(g.errors).toEqual([]);
    });

    it('desktop: the gold ball come to rest behind the backboard (under the hoop, where it cannot score) hands its gold to a ball that can', async () => {
      const g = page();
      const r = await g.page.evaluate(() => {
        type W = { components: { Position: { x: Float64Array; y: Float64Array }; Velocity: { x: Float64Array; y: Float64Array } } };
        const game = window.game as unknown as HoopGame & {
          paused: boolean;
          reset(): void;
          step(): void;
          goldBall(): number;
          positions(): number[];
          world: W;
        };
        game.reset();
        game.paused = true;
        // The gold ball put on the floor between the first hoop's backboard (x 14.08 m) and the right wall.
        const old = game.goldBall(),
          s = old % 2 ** 25,
          c = game.world.components;
        c.Position.x[s] = 15;
        c.Position.y[s] = 0.6;
        c.Velocity.x[s] = 0;
        c.Velocity.y[s] = 0;
        const at: number[] = [];
        for (let k = 0; k < 90; k++) {
          game.step();
          if (game.goldBall() !== old && at.length === 0) at.push(k);
        }
        const now = game.goldBall(),
          i = game.ballIds().indexOf(now);
        return {
          old,
          now,
          after: at[0] ?? -1,
          x: game.positions()[2 * i]!,
          y: game.positions()[2 * i + 1]!,
          stays: game.ballIds().includes(old),
        };
      });
      // Another heap ball is gold after the 0.5 s at rest there (30 steps; it lands and settles first),
      // one out from under the hoop (past the front rim's end, 11.67 m, or above the rim, 6 m); the old one stays, a heap ball.
      expect(r.now).not.toBe(r.old);
      expect(r.now).not.toBe(0);
      expect(r.after).toBeGreaterThanOrEqual(30);
      expect(r.x < 11.67 || r.y >= 6).toBe(true);
      expect(r.stays).toBe(true);
      expect(g.errors).toEqual([]);
    });

    it('desktop: a ball that sits on the backboard and rolls into the net scores; the bracket is drawn under the balls', async () => {
      const g = page();
      const r = await g.page.evaluate(() => {
        const game = window.game as unknown as HoopGame & {
          paused: boolean;
          reset(): void;
          step(): void;
          remove(id: number): void;
          world: { time: number };
          app: { stage: { children: { label: string }[] } };
          renderer: { root: unknown };
        };
        game.reset();
        game.paused = true;
        for (const id of game.ballIds()) game.remove(id);
        // Thrown from below the line, it lands on the backboard's top, rests there past MISS_SECONDS
        // (3 s), then rolls off on the hoop's side and drops in through the rim.
        const t0 = game.world.time;
        const e = game.shoot(9.5, 1, 3, 12);
        let scoredAt = -1,
          top = 0;
        for (let k = 0; k < 360 && scoredAt < 0; k++) {
          game.step();
          if (game.round().score > 0) scoredAt = game.world.time - t0;
          else top = Math.max(top, (game as unknown as { positions(): number[] }).positions()[2 * game.ballIds().indexOf(e) + 1] ?? 0);
        }
        const stage = game.app.stage.children;
        return {
          scoredAt,
          top,
          bracket: stage.findIndex((c) => c.label === 'hoop-bracket'),
          balls: stage.indexOf(game.renderer.root as { label: string }),
        };
      });
      // It went over the board's top (7.6 m) before it went in, more than 3 s after the throw; before, it
      // was called a miss at 3 s and went in for nothing.
      expect(r.top).toBeGreaterThan(7.6);
      expect(r.scoredAt).toBeGreaterThan(3);
      // The bracket has no body: it is drawn under the balls, which pass in front of it.
      expect(r.bracket).toBeGreaterThanOrEqual(0);
      expect(r.bracket).toBeLessThan(r.balls);
      expect(g.errors).toEqual([]);
    });
  });

  describe('phone 390 x 844, touch, 8 balls, one page', () => {
    const page = sharedPage(() => h, 'bouncing-balls', { viewport: { width: 390, height: 844 }, touch: true, query: { count: 8 } });

    it('phone 390 x 844, touch: a ball to throw is marked, "drag me" over it until the first throw', async () => {
      const g = page();
      type Marked = HoopGame & { throwable(): { ball: number; label: string }; ballIds(): number[]; positions(): number[] };
      const first = await g.waitFor(() => {
        const m = (window.game as unknown as Marked).throwable();
        return m.ball !== 0 && m.label !== '' ? m : null;
      }, null);
      expect(first.label).toBe('drag me');
      // A ball of the heap, below the shot line (0.3 m under the rim): a throw of it may score.
      const where = await g.page.evaluate((e) => {
        const game = window.game as unknown as Marked;
        const i = game.ballIds().indexOf(e);
        return { i, y: game.positions()[2 * i + 1]!, rim: game.hoop().y };
      }, first.ball);
      expect(where.i).toBeGreaterThanOrEqual(0);
      expect(where.y).toBeLessThan(where.rim - 0.3);
      // Thrown: the label is gone (the ring stays, on the next ball to throw).
      await g.page.evaluate(
        (e) => (window.game as unknown as { throwBall(e: number, vx: number, vy: number): boolean }).throwBall(e, 0, 6),
        first.ball,
      );
      await g.frames(3);
      expect(await g.page.evaluate(() => (window.game as unknown as Marked).throwable().label)).toBe('');
      expect(g.errors).toEqual([]);
    });

    it('phone 390 x 844, touch: the goal shows above the box; a tap does not start the clock; a pull from below the line shows the arc, throws a ball up and away, and the clock waits for the first basket', async () => {
      const g = page();
      const status = g.page.locator('[data-hud="hoop"]');
      await expect.poll(() => status.isVisible()).toBe(true);
      // The opening hint says the rule too (it said how to throw, not from where, and a stranger threw from anywhere).
      expect(await status.textContent()).toMatch(/through the hoop from below the orange line/);
      const row = (await status.boundingBox())!;
      const top = await g.worldToPage(0, 16);
      expect(row.y + row.height).toBeLessThanOrEqual(top.y + 1);
      // The touch hint card sits on the stand under the floor, inside the canvas: none of the box is
      // covered (under the box's top it hid the hoop and the arcs to it), nor the status row.
      const card = (await g.page.locator('[data-hud="touch-hint"]').boundingBox())!;
      const canvas = await g.canvasBox();
      expect(card.y).toBeGreaterThanOrEqual((await g.worldToPage(0, 0)).y);
      expect(card.y + card.height).toBeLessThanOrEqual(canvas.y + canvas.height);
      // The spare height under the floor is the court's steel stand (0x262c37), not bare page: a row
      // 6 px above the canvas' bottom, across the middle, is that colour within 3 per channel.
      expect(canvas.y + canvas.height - (await g.worldToPage(0, 0)).y).toBeGreaterThan(60);
      const strip = decodePng(
        await g.page.screenshot({
          clip: { x: canvas.x + canvas.width / 4, y: canvas.y + canvas.height - 6, width: canvas.width / 2, height: 1 },
        }),
      );
      for (let i = 0; i < strip.width; i += 8) {
        const px = Array.from(strip.data.subarray(i * strip.channels, i * strip.channels + 3));
        expect(
          px.map((c, k) => Math.abs(c - [0x26, 0x2c, 0x37][k]!)).every((d) => d <= 3),
          `pixel ${i}: ${px}`,
        ).toBe(true);
      }
      // A tap drops a ball and leaves the clock waiting for the first throw.
      const tap = await g.worldToPage(5, 13);
      await g.page.touchscreen.tap(tap.x, tap.y);
      await g.waitFor((n) => (window.game as unknown as HoopGame).ballIds().length === n + 1, 8);
      expect(await g.page.evaluate(() => (window.game as unknown as HoopGame).round())).toMatchObject({ phase: 'ready', shots: 0 });
      // Pressed 4 m above the floor, left of the box's middle, and pulled down and to the left: while
      // pulling, the dotted arc rises to the right from the press point; let go, the ball flies that way.
      const from = await g.worldToPage(3, 4),
        to = await g.worldToPage(2, 2.5);
      // Paused from the press on, so the new ball's velocity is read as thrown. The balls within 3.5 m of
      // the press are taken out: a press on a ball throws that ball, and the arc ends at a ball in its way.
      const n0 = await g.page.evaluate(() => {
        const game = window.game as unknown as HoopGame & { paused: boolean; remove(id: number): void; positions(): number[] };
        game.paused = true;
        const p = game.positions();
        for (const id of game.ballIds().filter((_, i) => Math.hypot(p[2 * i]! - 3, p[2 * i + 1]! - 4) < 3.5)) game.remove(id);
        return game.ballIds().length;
      });
      let arc: number[] = [];
      let seconds = 0;
      await swipe(
        g.page,
        [0, 0.25, 0.5, 0.75, 1].map((f) => [from.x + f * (to.x - from.x), from.y + f * (to.y - from.y)] as [number, number]),
        async () => {
          arc = await g.page.evaluate(() => (window.game as unknown as HoopGame).aimPath());
          seconds = await g.page.evaluate(() => (window.game as unknown as HoopGame).aimSeconds());
        },
      );
      // The phone's arc shows 1.5 times the desktop's flight (main.ts TALL_AIM_SCALE): 1.8 s in the
      // warm-up (1.2 s on a desktop), as the phone draws each metre a third shorter.
      expect(seconds).toBeCloseTo(1.8, 9);
      expect(arc.length).toBeGreaterThan(6);
      expect(arc[0]).toBeCloseTo(3, 1);
      expect(arc[1]).toBeCloseTo(4, 1);
      expect(arc[4]!).toBeGreaterThan(arc[0]!);
      expect(arc[5]!).toBeGreaterThan(arc[1]!);
      const r = await g.waitFor((n) => {
        const game = window.game as unknown as HoopGame;
        const ids = game.ballIds();
        if (ids.length !== n + 1 || game.round().shots !== 1) return null;
        const e = ids.at(-1)! % 2 ** 25;
        return { ...game.round(), vx: game.world.components.Velocity.x[e]!, vy: game.world.components.Velocity.y[e]! };
      }, n0);
      expect(r.phase).toBe('ready');
      // Thrown up and to the right, as the arc showed (1.5 : 1, the pull's slope).
      expect(r.vx).toBeGreaterThan(1);
      expect(r.vy / r.vx).toBeCloseTo(1.5, 1);
      await g.page.evaluate(() => {
        (window.game as unknown as { paused: boolean }).paused = false;
      });
      // A miss costs no time: half a second of world time on, the clock still shows the whole round.
      const t1 = await g.page.evaluate(() => (window.game as unknown as { world: { time: number } }).world.time);
      await g.waitFor((t) => (window.game as unknown as { world: { time: number } }).world.time > t + 0.5, t1);
      expect(await g.page.evaluate(() => (window.game as unknown as HoopGame).round())).toMatchObject({ phase: 'ready', timeLeft: 60 });
      expect(await status.textContent()).toMatch(/Score once to start the 60 s clock.*Points 0 · ×1 · Time 60 s/s);
      expect(g.errors).toEqual([]);
    });

    it('phone 390 x 844, touch: nothing moves the field while aiming, as the hint changes mid-drag; every line fits on one line', async () => {
      const g = page();
      await expect.poll(() => g.page.locator('[data-hud="hoop"]').isVisible()).toBe(true);
      // A throw from above the line: the hint says "Too high" until the next throw; a throw from below
      // the line mid-drag ends it, says its miss (a ball dropped at 2 m falls short of the rim: said
      // with no streak to break too, for 2.5 s of game time) and a teaching hint shows (held while
      // aiming: they take turns only between presses; the longest of them wrapped to two lines at 390 px).
      await g.page.evaluate(() => (window.game as unknown as HoopGame).shoot(5, 14, 0, 0));
      const sample = () =>
        g.page.evaluate(() => {
          const game = window.game as unknown as {
            app: { canvas: HTMLCanvasElement };
            renderer: { camera: { toScreenY(y: number): number } };
            courtWords(): string;
          };
          const lines = [...document.querySelectorAll<HTMLElement>('[data-hud="hoop"] > div')];
          return {
            court: game.courtWords(),
            // The field's top edge on the page, CSS px.
            field: game.app.canvas.getBoundingClientRect().top + game.renderer.camera.toScreenY(16),
            hint: document.querySelector('[data-hud="hoop"] [data-hud="hint"]')?.textContent ?? '',
            cut: lines.filter((l) => l.scrollWidth > l.clientWidth).map((l) => l.textContent),
          };
        });
      const cdp = await g.page.context().newCDPSession(g.page);
      const from = await g.worldToPage(5, 8);
      await cdp.send('Input.dispatchTouchEvent', { type: 'touchStart', touchPoints: [{ x: from.x, y: from.y, id: 1 }] });
      const seen: { court: string; field: number; hint: string; cut: (string | null)[] }[] = [];
      // Between moves a quarter of a second of world time is stepped in the page, then two frames
      // drawn, as the row is written on each frame; 28 moves, 7 s, past the hints' 6 s turn (of game
      // time: main.ts playSeconds).
      for (let i = 0; i < 28; i++) {
        if (i === 5) await g.page.evaluate(() => (window.game as unknown as HoopGame).shoot(1, 2, 0, 0));
        await cdp.send('Input.dispatchTouchEvent', {
          type: 'touchMove',
          touchPoints: [{ x: from.x - 20 + (i % 10), y: from.y + 60 + (i % 7), id: 1 }],
        });
        await g.runFrames(15, { draw: false });
        await g.frames(2);
        seen.push(await sample());
      }
      await cdp.send('Input.dispatchTouchEvent', { type: 'touchEnd', touchPoints: [] });
      await cdp.detach();
      // The hint changed twice while aiming ("Too high", the miss, then one teaching hint, held)...
      const hints = [...new Set(seen.map((s) => s.hint))];
      expect(hints).toHaveLength(3);
      expect(hints[1]).toBe('Missed: short of the rim');
      // Said on the court too, over the ball (main.ts sayOnCourt: a thumb's eyes are on the court).
      expect(seen.some((s) => s.court === 'Missed: short of the rim')).toBe(true);
      // ... the miss for a while (2.5 s of game time), in a row, before the teaching hint.
      const missed = seen.map((s, i) => (s.hint === hints[1] ? i : -1)).filter((i) => i >= 0);
      expect(missed.length).toBeGreaterThanOrEqual(2);
      expect(missed.at(-1)! - missed[0]!).toBe(missed.length - 1);
      // ... and the field stayed where it was, to the pixel, with no line of the row cut short.
      expect(new Set(seen.map((s) => Math.round(s.field * 100) / 100)).size).toBe(1);
      for (const s of seen) expect(s.cut).toEqual([]);
      expect(g.errors).toEqual([]);
    });

    it('phone 390 x 844, touch: an open drawer (settings or menu) pauses the game and its clock; the settings drawer closes when the field is pressed, and the game goes on', async () => {
      const g = page();
      await expect.poll(() => g.page.locator('[data-hud="hoop"]').isVisible()).toBe(true);
      const open = () => g.page.evaluate(() => document.querySelector<HTMLElement>('.bp-app')?.dataset.open ?? '');
      const steps = () => g.page.evaluate(() => window.game!.stats().steps);
      // The menu: paused while it is open (the round's clock runs in steps: none are taken), going on
      // once it is closed.
      await g.page.getByRole('button', { name: 'information and controls' }).tap();
      expect(await open()).toBe('info');
      await g.waitFor(() => window.game!.paused || null, null);
      const s0 = await steps();
      await g.frames(10);
      expect(await steps()).toBe(s0);
      await g.page.getByRole('button', { name: 'information and controls' }).tap();
      expect(await open()).toBe('');
      await g.waitFor(() => !window.game!.paused || null, null);
      await g.waitFor((n) => window.game!.stats().steps > n || null, s0);
      await g.page.getByRole('button', { name: 'parameters and charts' }).tap();
      expect(await open()).toBe('side');
      await g.waitFor(() => window.game!.paused || null, null);
      // A tap on the field low in the box (under the drawer), 1 m over the floor.
      const at = await g.worldToPage(5, 1);
      await g.page.touchscreen.tap(at.x, at.y);
      await expect.poll(open).toBe('');
      await g.waitFor(() => !window.game!.paused || null, null);
      expect(g.errors).toEqual([]);
    });

    it('phone 390 x 844, touch: a finger pulled up from just above the heap aims a throw down, and the game runs on', async () => {
      // A stranger's gesture: pressed just over the heap and pulled up, the throw aims down hard; the
      // touch assist's check of it asked for a flight of negative length and stopped the game.
      const g = page();
      await touchPath(
        g.page,
        [0, 1, 2, 3, 4, 5, 6].map((i) => [197 + (15 * i) / 6, 559 - (126 * i) / 6] as [number, number]),
        300,
        () => g.frames(3),
      );
      await g.frames(3);
      expect(g.errors).toEqual([]);
      expect(await g.page.evaluate(() => document.querySelector('.bp-error')?.textContent ?? '')).toBe('');
      await g.page.evaluate(() => (window.game as unknown as { reset(): void }).reset());
    });
    it('phone 390 x 844, touch: the "drag me" ball, off the side walls, scores with a finger pull that stays on the screen', async () => {
      // The page as a stranger opens it (20 balls on a phone held upright), its own: the throw ends
      // the first-throw hints. Before, the full pull (351 px) ran off the screen's bottom at 55-64 %
      // power from the balls where they lie, and no pull from the marked ball (by the left wall) that
      // stayed on the screen reached the hoop.
      const g = await h.openGame('bouncing-balls', { viewport: { width: 390, height: 844 }, touch: true });
      type Reach = AimGame & { throwable(): { ball: number; label: string }; aimFrom(e: number, vx: number, vy: number): number[] };
      const ball = await g.waitFor(() => {
        const m = (window.game as unknown as Reach).throwable();
        return m.ball !== 0 && m.label === 'drag me' ? m.ball : null;
      }, null);
      const where = await g.page.evaluate((e) => {
        localStorage.clear();
        document.querySelector('[data-hud="touch-hint"]')?.remove();
        const game = window.game as unknown as Reach;
        game.paused = true;
        const p = game.positions(),
          i = game.ballIds().indexOf(e);
        return { x: p[2 * i]!, y: p[2 * i + 1]!, hoop: game.hoop(), W: innerWidth, H: innerHeight };
      }, ball);
      // Not against a side wall (main.ts EDGE_ROOM, 1.5 m): there is room beside it to pull into.
      expect(Math.min(where.x, 10 - where.x)).toBeGreaterThanOrEqual(1.5);
      const at = await g.worldToPage(where.x, where.y);
      const cdp = await g.page.context().newCDPSession(g.page);
      const touch = (type: 'touchStart' | 'touchMove', x: number, y: number) =>
        cdp.send('Input.dispatchTouchEvent', { type, touchPoints: [{ x, y, id: 1 }] });
      await touch('touchStart', at.x, at.y);
      await touch('touchMove', at.x, at.y + 30);
      await g.frames(1);
      const full = await g.page.evaluate(() => (window.game as unknown as { fullPull(): number }).fullPull());
      // Every pull from the ball down and away from the hoop (85 to 30 degrees under level, steepest
      // first, as the clean baskets are; every 2 px of length) whose end stays on the screen (1 px
      // inside its edges), with its throw's velocity (hoop.ts slingSpeed of the length over the full pull).
      const away = Math.sign(where.x - 0.5 * (where.hoop.minX + where.hoop.maxX)) || -1;
      const pulls: number[][] = [];
      for (let a = 85; a >= 30; a -= 5)
        for (let l = 20; ; l += 2) {
          const dx = away * l * Math.cos((a * Math.PI) / 180),
            dy = l * Math.sin((a * Math.PI) / 180);
          if (at.x + dx < 1 || at.x + dx > where.W - 1 || at.y + dy > where.H - 1) break;
          const s = slingSpeed(l, full);
          pulls.push([dx, dy, (-dx / l) * s, (dy / l) * s]);
        }
      // The first whose predicted flight (the page's own, stopped by the balls in its way) goes down
      // through the hoop's opening before it touches anything (its steps across stay even: a touch
      // changes them).
      const hit = await g.page.evaluate(
        ([e, pulls]) => {
          const game = window.game as unknown as Reach;
          const o = game.hoop();
          return (
            pulls.find(([, , vx, vy]) => {
              const f = game.aimFrom(e, vx!, vy!);
              for (let i = 1; i < f.length / 2; i++) {
                const y0 = f[2 * i - 1]!,
                  y1 = f[2 * i + 1]!;
                if (Math.abs(f[2 * i]! - f[2 * i - 2]! - (f[2]! - f[0]!)) > 1e-6) return false;
                if (y0 >= o.y && y1 < o.y) {
                  const x = f[2 * i - 2]! + ((y0 - o.y) / (y0 - y1)) * (f[2 * i]! - f[2 * i - 2]!);
                  return x > o.minX && x < o.maxX;
                }
              }
              return false;
            }) ?? null
          );
        },
        [ball, pulls] as const,
      );
      expect(hit, `no on-screen pull of ${pulls.length} scores (full pull ${full} px)`).not.toBeNull();
      // Thrown by that pull (the finger's assist may take it to the middle of its run of scoring
      // lengths): it goes in within 4 s of game time.
      await touch('touchMove', at.x + hit![0]! / 2, at.y + hit![1]! / 2);
      await touch('touchMove', at.x + hit![0]!, at.y + hit![1]!);
      await g.frames(1);
      // Without help (none of 3 misses in a row yet: preview.ts) the arc shows only its first part and
      // no verdict: the aim is the player's to judge.
      type Shown = { aimLabel(): string; aimShown(): number[]; aimPath(): number[]; aimHelp(on?: boolean): boolean };
      const plain = await g.page.evaluate(() => {
        const game = window.game as unknown as Shown;
        return { help: game.aimHelp(), label: game.aimLabel(), shown: game.aimShown().length, path: game.aimPath().length };
      });
      expect(plain.help).toBe(false);
      expect(plain.label).not.toContain('on target');
      expect(plain.shown).toBeLessThan(plain.path);
      // With help on (as after 3 misses in a row) the whole arc and its verdict show.
      await g.page.evaluate(() => (window.game as unknown as Shown).aimHelp(true));
      await g.frames(1);
      // The aim says so: "on target" (the assist drew it to a basket's middle), and the arc, down
      // through the opening, is not labelled as cut by the net it may then fall into ("hits the net").
      const aim = await g.page.evaluate(() => {
        const game = window.game as unknown as {
          aimLabel(): string;
          aimCut(): { kind: string } | null;
          aimPath(): number[];
          hoop(): { y: number };
        };
        return { label: game.aimLabel(), cut: game.aimCut()?.kind ?? null, end: game.aimPath().at(-1)!, rim: game.hoop().y };
      });
      expect(aim.label).toContain('on target');
      expect(aim.cut).toBeNull();
      // The arc of a basket runs on down through the rim into the net (main.ts basketSeconds), so the
      // player sees it go in (an arc that ended 0.4 m over the rim never showed a basket).
      expect(aim.end).toBeLessThan(aim.rim);
      await cdp.send('Input.dispatchTouchEvent', { type: 'touchEnd', touchPoints: [] });
      await cdp.detach();
      const score = await g.page.evaluate(() => {
        const game = window.game as unknown as AimGame & { step(): void };
        for (let k = 0; k < 240 && game.round().score === 0; k++) game.step();
        return { score: game.round().score, shots: game.round().shots };
      });
      expect(score).toEqual({ score: 1, shots: 1 });
      expect(g.errors).toEqual([]);
      await g.close();
    });

    it('phone 390 x 844, touch: a finger slid up from a ball by the left wall pulls back from where it is, not from the ball', async () => {
      // A page of its own: the throw ends the shared page's first-throw hints the next test reads.
      const g = await h.openGame('bouncing-balls', { viewport: { width: 390, height: 844 }, touch: true, query: { count: 8 } });
      type Slide = AimGame & { spawn(x: number, y: number): number; positions(): number[] };
      await g.page.evaluate(() => {
        // The same start whatever ran before: nothing stored (best score, mute), and the touch hint
        // card (which a first touch or 9 s of wall clock fades) taken away, so the swipe meets the field.
        localStorage.clear();
        document.querySelector('[data-hud="touch-hint"]')?.remove();
        const game = window.game as unknown as Slide;
        game.paused = true;
        for (const id of game.ballIds()) game.remove(id);
        game.spawn(1, 1.5);
      });
      const shots = await g.page.evaluate(() => (window.game as unknown as Slide).round().shots);
      const at = await g.page.evaluate(() => (window.game as unknown as Slide).positions());
      const from = await g.worldToPage(at[0]!, at[1]!);
      // Pressed on the ball, slid up and right into open space (the pull's anchor follows a finger
      // above it), then pulled 60 px left and 200 px down from there: the ball leaves up and right,
      // away from that pull. Measured from the ball (the old anchor) the finger ends 60 px right of it
      // and 50 px above: a throw down and left. Not possible from the ball itself: 60 px left of it is
      // off the screen's edge for a ball this close to the wall.
      await swipe(g.page, [
        [from.x, from.y],
        [from.x + 20, from.y - 60],
        [from.x + 120, from.y - 250],
        [from.x + 90, from.y - 150],
        [from.x + 60, from.y - 50],
      ]);
      const v = await g.page.evaluate(() => {
        const game = window.game as unknown as Slide & { world: { components: { Velocity: { x: Float64Array; y: Float64Array } } } };
        const e = game.ballIds()[0]! % 2 ** 25;
        return { vx: game.world.components.Velocity.x[e]!, vy: game.world.components.Velocity.y[e]!, shots: game.round().shots };
      });
      expect(v.shots).toBe(shots + 1);
      expect(v.vx).toBeGreaterThan(0);
      expect(v.vy).toBeGreaterThan(0);
      // The direction is the pull's within the assist's reach (it changes only the length): 200/60 up.
      expect(v.vy / v.vx).toBeCloseTo(200 / 60, 0);
      await g.page.evaluate(() => {
        (window.game as unknown as Slide).paused = false;
      });
      expect(g.errors).toEqual([]);
      await g.close();
    });
  });
});

/** What the aim tests read from window.game besides HoopGame. */
interface AimGame extends HoopGame {
  paused: boolean;
  aiming(): boolean;
  lastThrow(): { aiming: boolean; ball: number };
  countdown(): string;
  aimLabel(): string;
  remove(id: number): void;
  positions(): number[];
  world: HoopGame['world'] & { time: number };
}

describe('bouncing balls: cancelling, full-power pulls and the end of a round mid-aim', () => {
  let h: Harness;
  beforeAll(async () => {
    h = await Harness.start();
  }, START_TIMEOUT_MS);
  afterAll(async () => {
    await h?.close();
  });

  /** Pauses the game and takes out the balls within 3.5 m of (x, y), m; returns the balls left and the round's shots. */
  const clearAround = (g: GamePage, x: number, y: number) =>
    g.page.evaluate(
      ([x, y]) => {
        const game = window.game as unknown as AimGame;
        game.paused = true;
        const p = game.positions();
        for (const id of game.ballIds().filter((_, i) => Math.hypot(p[2 * i]! - x!, p[2 * i + 1]! - y!) < 3.5)) game.remove(id);
        return { balls: game.ballIds().length, shots: game.round().shots };
      },
      [x, y],
    );
  /** The arc, the aim's label and whether a press is under way. */
  const aimState = (g: GamePage) =>
    g.page.evaluate(() => {
      const game = window.game as unknown as AimGame;
      return { arc: game.aimPath().length, label: game.aimLabel(), aiming: game.aiming() };
    });

  /**
   * The power label's percentage and the full pull while pulling by (dx, dy) CSS px from page point
   * `from` (a mouse, or a finger's touch events), read once a frame is drawn after the pull's last
   * move; the pull is then taken back onto its press point and let go (no throw).
   */
  const powerOf = async (g: GamePage, from: { x: number; y: number }, dx: number, dy: number, finger: boolean) => {
    const read = async () => {
      await g.frames(2);
      return g.page.evaluate(() => {
        const game = window.game as unknown as AimGame & { fullPull(): number };
        return { label: game.aimLabel(), fullPull: game.fullPull() };
      });
    };
    let got = { label: '', fullPull: 0 };
    if (finger) {
      const steps: Array<[number, number]> = [1, 2, 3, 4].map((k) => [from.x + (k * dx) / 4, from.y + (k * dy) / 4]);
      const cdp = await g.page.context().newCDPSession(g.page);
      const pt = (x: number, y: number) => [{ x, y, id: 1 }];
      await cdp.send('Input.dispatchTouchEvent', { type: 'touchStart', touchPoints: pt(from.x, from.y) });
      for (const [x, y] of steps) await cdp.send('Input.dispatchTouchEvent', { type: 'touchMove', touchPoints: pt(x, y) });
      got = await read();
      await cdp.send('Input.dispatchTouchEvent', { type: 'touchMove', touchPoints: pt(from.x, from.y) });
      await g.waitFor(() => (window.game as unknown as AimGame).aimLabel() === 'release here to cancel', null);
      await cdp.send('Input.dispatchTouchEvent', { type: 'touchEnd', touchPoints: [] });
      await cdp.detach();
    } else {
      const m = g.page.mouse;
      await m.move(from.x, from.y);
      await m.down();
      await m.move(from.x + dx, from.y + dy, { steps: 6 });
      got = await read();
      await m.move(from.x, from.y, { steps: 3 });
      await g.waitFor(() => (window.game as unknown as AimGame).aimLabel() === 'release here to cancel', null);
      await m.up();
    }
    const match = /power (\d+)%/.exec(got.label);
    expect(match, got.label).not.toBeNull();
    return { power: Number(match![1]), fullPull: got.fullPull };
  };

  for (const phone of [false, true]) {
    it(`${phone ? 'phone 390 x 844, touch' : 'desktop 1280 x 800, mouse'}: the same pull throws at the same power wherever it is pressed, and 5 px more adds a little`, async () => {
      const g = await h.openGame('bouncing-balls', {
        viewport: phone ? { width: 390, height: 844 } : { width: 1280, height: 800 },
        touch: phone,
        query: { count: 1 },
      });
      // Two presses in empty space, one high in the box and one low by the floor (near the window's
      // bottom, where the full pull used to be cut to the room left under the press: the stranger's
      // same pull threw at 62 % from one press and 69 % from another).
      const spots = phone
        ? [
            [2, 11],
            [7, 1.2],
          ]
        : [
            [4, 7],
            [12, 1.2],
          ];
      for (const [x, y] of spots) await clearAround(g, x!, y!);
      const [dx, dy] = phone ? [-40, 120] : [-90, 150];
      const got: { power: number; fullPull: number }[] = [];
      for (const [x, y] of spots) got.push(await powerOf(g, await g.worldToPage(x!, y!), dx, dy, phone));
      const longer = await powerOf(g, await g.worldToPage(spots[1]![0]!, spots[1]![1]!), dx, dy + 5, phone);
      expect(got[1]).toEqual(got[0]);
      expect(longer.fullPull).toBe(got[0]!.fullPull);
      // Desktop: hoop.ts slingSpeed of the pull's length over the full pull, of the top speed, 20 m/s;
      // phone: the share of the full pull (main.ts powerOf: its speeds fit the room over the hoop,
      // slingRoom, from where the throw starts).
      const shown = (len: number) =>
        phone ? Math.round(100 * Math.min(1, len / got[0]!.fullPull)) : Math.round((100 * slingSpeed(len, got[0]!.fullPull)) / 20);
      expect(got[0]!.power).toBe(shown(Math.hypot(dx, dy)));
      expect(longer.power).toBe(shown(Math.hypot(dx, dy + 5)));
      expect(longer.power - got[0]!.power).toBeGreaterThan(0);
      // At most 2 % with a mouse; a finger's full pull on a phone is shorter (fitting under the heap:
      // fingerFullPull), 5 px of it up to 4 % (the finger's assist takes a pull close to a basket to it).
      expect(longer.power - got[0]!.power).toBeLessThanOrEqual(phone ? 4 : 2);
      // The full pull is 60 % of the canvas' shorter side within [230, 420] px (main.ts fullPull), a
      // finger's 1.5 times that (FINGER_PULL_SCALE: gentler; the room is found by sliding up first).
      const side = await g.page.evaluate(() => {
        const c = document.querySelector('canvas')!;
        return Math.min(c.clientWidth, c.clientHeight);
      });
      // On a phone no longer than the room under a ball on the floor, down to the screen's bottom edge
      // less 10 px (main.ts fingerFullPull: a full pull of 351 px ran off the screen at 55-64 %).
      const room = await g.page.evaluate(() => innerHeight);
      const floorBall = (await g.worldToPage(0, 0.4)).y;
      const expected = Math.min(420, Math.max(230, 0.6 * side)) * (phone ? 1.5 : 1);
      expect(got[0]!.fullPull).toBeCloseTo(phone ? Math.min(expected, Math.max(100, room - floorBall - 10)) : expected, 6);
      if (phone) expect(got[0]!.fullPull).toBeLessThan(160);
      // A tap (a click, or a finger's tap) on the hoop's rim drops no ball into its net (one did, dead,
      // under the rim's line): the ball count stays and the hint says how to score.
      const rim = await g.page.evaluate(() => {
        const o = (window.game as unknown as { hoop(): { y: number; minX: number; maxX: number } }).hoop();
        return [0.5 * (o.minX + o.maxX), o.y - 0.3];
      });
      const count = () => g.page.evaluate(() => (window.game as unknown as { ballIds(): number[] }).ballIds().length);
      const n0 = await count();
      const at = await g.worldToPage(rim[0]!, rim[1]!);
      if (phone) {
        const cdp = await g.page.context().newCDPSession(g.page);
        await cdp.send('Input.dispatchTouchEvent', { type: 'touchStart', touchPoints: [{ x: at.x, y: at.y, id: 1 }] });
        await cdp.send('Input.dispatchTouchEvent', { type: 'touchEnd', touchPoints: [] });
        await cdp.detach();
      } else await g.page.mouse.click(at.x, at.y);
      await g.waitFor(
        (text) => document.querySelector('[data-hud="hoop"] [data-hud="hint"]')?.textContent === text,
        'Throw into the hoop from below the orange line',
      );
      expect(await count()).toBe(n0);
      expect(g.errors).toEqual([]);
      await g.close();
    });
  }

  describe('desktop 1280 x 800, 8 balls, one page', () => {
    const page = sharedPage(() => h, 'bouncing-balls', { viewport: { width: 1280, height: 800 }, query: { count: 8 } });

    it('desktop 1280 x 800, mouse: a pull taken back onto the press point shows "release here to cancel" and throws nothing; the stand\'s words hide under a pull', async () => {
      const g = page();
      const n0 = await clearAround(g, 3, 4);
      const from = await g.worldToPage(3, 4);
      // The stand's "room to pull back into" words: shown, but not under a pull's band.
      const standWords = () =>
        g.page.evaluate(
          () =>
            (window.game as unknown as { app: { stage: { children: { text?: string; visible: boolean }[] } } }).app.stage.children.find(
              (c) => c.text === '↓ room to pull back into ↓',
            )?.visible,
        );
      await g.frames(2);
      expect(await standWords()).toBe(true);
      const m = g.page.mouse;
      await m.move(from.x, from.y);
      await m.down();
      await m.move(from.x - 60, from.y + 90, { steps: 6 });
      await g.frames(2);
      const pulled = await aimState(g);
      expect(pulled.arc).toBeGreaterThan(6);
      expect(pulled.label).not.toBe('release here to cancel');
      expect(await standWords()).toBe(false);
      // Back to 4 px from the press point: inside the cancel zone (15 px, or the ball's drawn radius).
      await m.move(from.x - 3, from.y + 3, { steps: 6 });
      await g.frames(2);
      expect(await aimState(g)).toEqual({ arc: 0, label: 'release here to cancel', aiming: true });
      await m.up();
      await g.frames(3);
      expect(await standWords()).toBe(true);
      const after = await g.page.evaluate(() => {
        const game = window.game as unknown as AimGame;
        return { balls: game.ballIds().length, shots: game.round().shots, aiming: game.aiming() };
      });
      // No ball thrown (nor dropped), no shot counted: a thrown ball that missed would have ended a streak.
      expect(after).toEqual({ balls: n0.balls, shots: n0.shots, aiming: false });
      // The same pull let go outside the zone throws.
      await m.move(from.x, from.y);
      await m.down();
      await m.move(from.x - 60, from.y + 90, { steps: 6 });
      await m.up();
      await g.waitFor((n) => (window.game as unknown as AimGame).round().shots === n + 1, n0.shots);
      expect(g.errors).toEqual([]);
    });

    it('desktop 1280 x 800: from the lowest heap ball, a pull straight down past the viewport (captured) throws at the full speed', async () => {
      const g = page();
      // The heap settles, then the lowest ball is pressed at its centre and pulled down to the viewport's last row.
      await g.runUntil(() => (window.game as unknown as AimGame).world.time > 3, null, { draw: false, resume: false });
      await g.frames(2);
      const low = await g.page.evaluate(() => {
        const game = window.game as unknown as AimGame;
        game.paused = true;
        const ids = game.ballIds(),
          p = game.positions();
        let k = 0;
        for (let i = 1; i < ids.length; i++) if (p[2 * i + 1]! < p[2 * k + 1]!) k = i;
        return { id: ids[k]!, x: p[2 * k]!, y: p[2 * k + 1]! };
      });
      const at = await g.worldToPage(low.x, low.y);
      const viewport = g.page.viewportSize()!;
      // The strip under the box (main.ts DESK_PULL_ROOM) leaves room to pull back into: 150 px or more
      // under the lowest ball (with the floor near the window's bottom it was some 65 px).
      expect(viewport.height - at.y).toBeGreaterThan(150);
      // The full pull is the same wherever a press begins (a shorter one by the window's edge made the
      // same pull throw at different powers): past the window's bottom, as a held mouse button goes on.
      const v = await mouseThrow(g, low.id, at, { x: at.x, y: at.y + 430 });
      expect(at.y + 430).toBeGreaterThan(viewport.height);
      // hoop.ts MAX_THROW_SPEED, 20 m/s, straight up.
      expect(v.shots).toBe(1);
      expect(Math.abs(v.vx)).toBeLessThan(1e-9);
      expect(v.vy).toBeCloseTo(20, 9);
      expect(g.errors).toEqual([]);
    });

    it('desktop 1280 x 800, mouse: a click on the stand under the floor drops nothing; a pull from there with no ball over it throws a new one from the floor; a press on a ramp starts its ball clear of the ramp', async () => {
      const g = page();
      const n0 = await clearAround(g, 8, 1);
      const state = () =>
        g.page.evaluate(() => {
          const game = window.game as unknown as AimGame;
          const p = game.positions();
          return { balls: game.ballIds().length, shots: game.round().shots, aiming: game.aiming(), last: [p.at(-2)!, p.at(-1)!] };
        });
      // The stand, 1.2 m under the floor (the box's floor is y = 0), with no ball within 3.5 m of (8, 1)
      // m: a click there drops nothing (no ball can be under the floor) and the hint says what a pull does.
      const stand = await g.worldToPage(8, -1.2);
      const m = g.page.mouse;
      await m.click(stand.x, stand.y);
      await g.frames(2);
      expect(await state()).toMatchObject({ balls: n0.balls, shots: n0.shots, aiming: false });
      expect(await g.page.locator('[data-hud="hoop"] [data-hud="hint"]').textContent()).toMatch(/pull back to throw the ball above/);
      // A pull from there (the help says a press anywhere throws) shows the arc and throws a new
      // basketball from the floor straight over the press, (8, 0.42) m (its radius 0.4 m and 2 cm clear),
      // up and to the right, away from the pull.
      await m.move(stand.x, stand.y);
      await m.down();
      await m.move(stand.x - 40, stand.y + 50, { steps: 6 });
      await g.frames(2);
      expect(await g.page.evaluate(() => (window.game as unknown as AimGame).aimPath().length)).toBeGreaterThan(2);
      await m.up();
      await g.frames(2);
      const after = await state();
      expect(after).toMatchObject({ balls: n0.balls + 1, shots: n0.shots + 1, aiming: false });
      // (To a pixel, 0.018 m, across: the press's x is read off the screen.)
      expect(Math.abs(after.last[0]! - 8)).toBeLessThan(0.03);
      expect(after.last[1]).toBeCloseTo(0.42, 6);
      const v = await g.page.evaluate(() => {
        const game = window.game as unknown as AimGame;
        const e = game.ballIds().at(-1)! % 2 ** 25;
        const removed = game.ballIds().at(-1)!;
        const out = [game.world.components.Velocity.x[e]!, game.world.components.Velocity.y[e]!];
        game.remove(removed);
        return out;
      });
      // Opposite to the pull's (-40, +50) px (y down): right and up, at its slope.
      expect(v[0]!).toBeGreaterThan(0);
      expect(v[1]! / v[0]!).toBeCloseTo(50 / 40, 1);
      // On the middle of the lower left ramp (scene.ts SEGMENTS[0]): a click drops its ball clear of the
      // ramp, on the side it was pressed from (the ramp's top): not inside it, to be shoved out by the solver.
      const [ax, ay, bx, by] = RAMPS[0]!;
      const mid = await g.worldToPage((ax + bx) / 2, (ay + by) / 2 + 0.05);
      await m.click(mid.x, mid.y);
      const dropped = await g.waitFor((n) => {
        const game = window.game as unknown as AimGame;
        const p = game.positions();
        return game.ballIds().length === n + 1 ? [p.at(-2)!, p.at(-1)!] : null;
      }, n0.balls);
      const ex = bx - ax,
        ey = by - ay;
      const t = ((dropped[0]! - ax) * ex + (dropped[1]! - ay) * ey) / (ex * ex + ey * ey);
      const gap = Math.hypot(dropped[0]! - ax - t * ex, dropped[1]! - ay - t * ey);
      // hoop.ts PLAYER_RADIUS, 0.4 m, clear of the ramp's capsule (SEGMENT_RADIUS) on its upper side.
      expect(gap).toBeGreaterThanOrEqual(0.4 + SEGMENT_RADIUS);
      expect(dropped[1]!).toBeGreaterThan(ay + t * ey);
      expect(g.errors).toEqual([]);
    });

    it("desktop 1280 x 800: a high throw's aiming arc ends where it meets the box's top", async () => {
      const g = page();
      await clearAround(g, 5, 4.5);
      const from = await g.worldToPage(5, 4.5);
      const m = g.page.mouse;
      await m.move(from.x, from.y);
      await m.down();
      // Down past the window's bottom (the pointer is captured): the full pull, steeply up and a little left.
      await m.move(from.x + 40, from.y + 430, { steps: 8 });
      const arc = await g.waitFor(() => {
        const a = (window.game as unknown as AimGame).aimPath();
        return a.length > 0 ? a : null;
      }, null);
      await m.up();
      const ys = arc.filter((_, i) => i % 2 === 1);
      // It rises to the ceiling (BOX's top, 10 m; hoop.ts PLAYER_RADIUS 0.4 m) and ends there: the arc
      // stops at its first touch, so where the bounce sends it is the player's to judge (it went on off
      // the top and down again, and a stranger wiggled the pull until the dots dropped through the hoop).
      expect(ys.at(-1)! + 0.4).toBeCloseTo(BOX.max[1], 6);
      for (let i = 1; i < ys.length; i++) expect(ys[i]!).toBeGreaterThan(ys[i - 1]!);
      expect(g.errors).toEqual([]);
    });

    it("desktop 1280 x 800: a lob's aiming arc goes over its top and down to just above the rim's height", async () => {
      const g = page();
      await clearAround(g, 5, 4.5);
      const from = await g.worldToPage(5, 4.5);
      const m = g.page.mouse;
      await m.move(from.x, from.y);
      await m.down();
      // Down and a little left: a steep lob up and a little right, clear of the ramps and the hoop.
      await m.move(from.x - 10, from.y + 150, { steps: 6 });
      const got = await g.waitFor(() => {
        const game = window.game as unknown as AimGame & { hoop(): { y: number } };
        const a = game.aimPath();
        return a.length > 0 ? { arc: a, rim: game.hoop().y } : null;
      }, null);
      await m.up();
      const ys = got.arc.filter((_, i) => i % 2 === 1);
      const top = ys.indexOf(Math.max(...ys));
      // It rises well over the rim, turns over and comes down: the arc shows where the ball falls, not
      // only its rise (a stranger's throw that looked right in a rising-only arc fell short).
      expect(ys[top]!).toBeGreaterThan(got.rim + 1.5);
      expect(top).toBeGreaterThan(0);
      expect(top).toBeLessThan(ys.length - 1);
      for (let i = top + 1; i < ys.length; i++) expect(ys[i]!).toBeLessThan(ys[i - 1]!);
      // It ends 0.4 m over the rim's height (main.ts ARC_END_ABOVE_RIM), within one dot's spacing (4
      // steps of 1/60 s at the fall's speed, under 0.5 m here) and the drag left out of its length.
      expect(Math.abs(ys.at(-1)! - (got.rim + 0.4))).toBeLessThan(0.5);
      expect(g.errors).toEqual([]);
    });
  });

  it('desktop 1280 x 800, mouse: a throw straight into the ball beside it says "blocked" over the gauge, and letting go throws nothing (no shot, no miss)', async () => {
    // A page of its own: after another test's throws on a shared page, this press drew no arc.
    const g = await h.openGame('bouncing-balls', { viewport: { width: 1280, height: 800 }, query: { count: 8 } });
    // Two balls 1.2 m apart in the air, alone in the box, the world paused (they stay there).
    const at = await g.page.evaluate(() => {
      const game = window.game as unknown as AimGame & { spawn(x: number, y: number): number };
      game.paused = true;
      for (const id of game.ballIds()) game.remove(id);
      game.spawn(6, 4);
      game.spawn(7.2, 4);
      const p = game.positions();
      return { x: p[0]!, y: p[1]! };
    });
    const from = await g.worldToPage(at.x, at.y);
    const m = g.page.mouse;
    await m.move(from.x, from.y);
    await m.down();
    // Pulled straight left: thrown straight right, into the other ball a metre on.
    await m.move(from.x - 80, from.y, { steps: 6 });
    await g.waitFor(() => (window.game as unknown as AimGame).aimPath().length > 2, null);
    expect((await aimState(g)).label).toMatch(/^blocked · power \d+% · 2 points$/);
    // Let go while blocked: nothing is thrown (the ball stays where it lay, the round counts no
    // shot) and the page says why, over the ball and on the status row.
    const shotsBefore = await g.page.evaluate(() => (window.game as unknown as HoopGame).round().shots);
    await m.up();
    await g.frames(2);
    const after = await g.page.evaluate(() => {
      const game = window.game as unknown as AimGame & HoopGame;
      return { shots: game.round().shots, p: game.positions(), label: game.aimLabel(), status: game.statusText() };
    });
    expect(after.shots).toBe(shotsBefore);
    expect(Math.hypot(after.p[0]! - at.x, after.p[1]! - at.y)).toBeLessThan(1e-9);
    expect(after.label).toBe('blocked — pick the top ball');
    expect(after.status).toMatch(/Blocked: not thrown/);
    await m.move(from.x, from.y);
    await m.down();
    await m.move(from.x - 80, from.y, { steps: 6 });
    await g.waitFor(() => (window.game as unknown as AimGame).aimPath().length > 2, null);
    // Pulled down instead: thrown up, clear of it.
    await m.move(from.x, from.y + 80, { steps: 6 });
    await g.waitFor(() => /^power \d+% · 2 points$/.test((window.game as unknown as AimGame).aimLabel()), null);
    await m.up();
    expect(g.errors).toEqual([]);
    await g.close();
  });

  it('desktop 1280 x 800, mouse: a press over the heap (no ball under it) throws the free ball nearest it, not a new ball; one of two level balls whose throw is blocked gives way to the other', async () => {
    const g = await h.openGame('bouncing-balls', { viewport: { width: 1280, height: 800 }, query: { count: 8 } });
    type PickGame = AimGame & HeapThrows & { spawn(x: number, y: number): number };
    // A stack alone in the box, the world paused: A on the floor, B resting on it (touching, straight
    // over it). B is the free ball (nothing over it); A has B over it.
    const stack = await g.page.evaluate(() => {
      const game = window.game as unknown as PickGame;
      game.paused = true;
      for (const id of game.ballIds()) game.remove(id);
      const a = game.spawn(5, 1);
      const R = game.world.components.Ball.radius;
      const ra = R[a % 2 ** 25]!;
      const b = game.spawn(5, 1);
      const rb = R[b % 2 ** 25]!;
      game.world.components.Position.y[b % 2 ** 25] = 1 + ra + rb;
      return { a, b, bx: 5, by: 1 + ra + rb, rb };
    });
    // Pressed 0.45 m over B's top (beyond the drag's reach of any ball: before, a new basketball
    // started there) and pulled down and left: B flies, from where it lies, and no ball is added.
    const press = await g.worldToPage(stack.bx, stack.by + stack.rb + 0.45);
    const m = g.page.mouse;
    await m.move(press.x, press.y);
    await m.down();
    await m.move(press.x - 40, press.y + 110, { steps: 6 });
    await g.waitFor(() => (window.game as unknown as AimGame).aimPath().length > 2, null);
    const aim = await g.page.evaluate(() => ({
      path: (window.game as unknown as AimGame).aimPath(),
      label: (window.game as unknown as AimGame).aimLabel(),
    }));
    // Its arc starts at B (within 1 mm) and its label says what it is worth (a heap ball's 2), not "new ball".
    expect(Math.hypot(aim.path[0]! - stack.bx, aim.path[1]! - stack.by)).toBeLessThan(1e-3);
    expect(aim.label).toMatch(/· 2 points$/);
    expect(aim.label).not.toMatch(/new ball/);
    await m.up();
    const after = await g.page.evaluate(
      ([a, b]) => {
        const game = window.game as unknown as PickGame;
        const V = game.world.components.Velocity;
        return {
          ids: game.ballIds(),
          va: Math.hypot(V.x[a! % 2 ** 25]!, V.y[a! % 2 ** 25]!),
          vb: Math.hypot(V.x[b! % 2 ** 25]!, V.y[b! % 2 ** 25]!),
        };
      },
      [stack.a, stack.b],
    );
    expect(after.ids.length).toBe(2);
    expect(after.vb).toBeGreaterThan(2);
    expect(after.va).toBe(0);
    // Two level balls side by side on the floor, C and D touching. Pressed over C, right of its top (C
    // is the nearer), pulled left and a little down: thrown right, low, C's arc runs into D at once
    // ("blocked"). The player did not press on C: the pull goes to D (within FREE_PICK_REACH, 0.9 m,
    // of the press), which flies that way unblocked.
    const pair = await g.page.evaluate(() => {
      const game = window.game as unknown as PickGame;
      for (const id of game.ballIds()) game.remove(id);
      const c = game.spawn(5, 1);
      const d = game.spawn(5, 1);
      const R = game.world.components.Ball.radius;
      const rc = R[c % 2 ** 25]!,
        rd = R[d % 2 ** 25]!;
      game.world.components.Position.x[d % 2 ** 25] = 5 + rc + rd;
      return { c, d, rc, dx: 5 + rc + rd };
    });
    const over = await g.worldToPage(5 + 0.5 * pair.rc, 1 + pair.rc + 0.45);
    await m.move(over.x, over.y);
    await m.down();
    await m.move(over.x - 120, over.y + 30, { steps: 6 });
    await g.waitFor(() => (window.game as unknown as AimGame).aimPath().length > 2, null);
    const second = await g.page.evaluate(() => ({
      path: (window.game as unknown as AimGame).aimPath(),
      label: (window.game as unknown as AimGame).aimLabel(),
    }));
    expect(second.label).not.toMatch(/blocked/);
    expect(Math.hypot(second.path[0]! - pair.dx, second.path[1]! - 1)).toBeLessThan(1e-3);
    await m.move(over.x, over.y, { steps: 4 });
    await m.up();
    expect(g.errors).toEqual([]);
    await g.close();
  });

  it('desktop 1280 x 800, mouse: a steep throw that grazes the level ball beside it is not "blocked" (it glances off); one straight into it is', async () => {
    const g = await h.openGame('bouncing-balls', { viewport: { width: 1280, height: 800 }, query: { count: 8 } });
    type PickGame = AimGame & HeapThrows & { spawn(x: number, y: number): number; aimCut(): { kind: string; words: string } | null };
    // C and D side by side on the floor, touching, alone in the box, the world paused.
    const pair = await g.page.evaluate(() => {
      const game = window.game as unknown as PickGame;
      game.paused = true;
      for (const id of game.ballIds()) game.remove(id);
      const c = game.spawn(5, 1);
      const d = game.spawn(5, 1);
      const R = game.world.components.Ball.radius;
      game.world.components.Position.x[d % 2 ** 25] = 5 + R[c % 2 ** 25]! + R[d % 2 ** 25]!;
      return { c, d };
    });
    expect(pair.c).toBeGreaterThan(0);
    const on = await g.worldToPage(5, 1);
    const m = g.page.mouse;
    // Pressed on C, pulled 40 px left and 110 px down: thrown up and right about 70 degrees over the
    // level, its arc meets D's upper left side at once, some 70 degrees off straight at D's centre
    // (main.ts HEAD_ON_DEG 60): "hits a ball" by its cross, no "blocked" (before, it was blocked).
    await m.move(on.x, on.y);
    await m.down();
    await m.move(on.x - 40, on.y + 110, { steps: 6 });
    await g.waitFor(() => (window.game as unknown as AimGame).aimPath().length >= 2, null);
    await g.frames(2);
    const steep = await g.page.evaluate(() => ({
      label: (window.game as unknown as PickGame).aimLabel(),
      cut: (window.game as unknown as PickGame).aimCut(),
    }));
    expect(steep.cut?.kind).toBe('ball');
    expect(steep.cut?.words).toBe('hits a ball');
    expect(steep.label).not.toMatch(/blocked/);
    // Pulled straight left instead: thrown straight into D, blocked.
    await m.move(on.x - 80, on.y, { steps: 6 });
    await g.waitFor(() => /^blocked · /.test((window.game as unknown as AimGame).aimLabel()), null);
    await m.move(on.x, on.y, { steps: 4 });
    await m.up();
    expect(g.errors).toEqual([]);
    await g.close();
  });

  it('a heap ball that goes in is given back: a ball of its size comes in at the side away from the hoop, so the heap keeps its count', async () => {
    const g = await h.openGame('bouncing-balls', { viewport: { width: 1280, height: 800 }, query: { count: 8 } });
    type FeedGame = HeapThrows & { spawn(x: number, y: number): number; remove(id: number): void };
    // Alone in the box: one heap ball at (8, 4) m, thrown on the drag-free arc that comes down on the
    // rim's centre after 1.3 s (the basketball test's throw); up to three tries, 2 s of world time each.
    const got = await g.page.evaluate(() => {
      const game = window.game as unknown as FeedGame & { world: { components: { Position: { x: Float64Array; y: Float64Array } } } };
      game.paused = true;
      for (let attempt = 0; attempt < 3; attempt++) {
        for (const id of game.ballIds()) game.remove(id);
        const e = game.spawn(8, 4);
        const r = game.world.components.Ball.radius[e % 2 ** 25]!;
        const o = game.hoop();
        const x = 0.5 * (o.minX + o.maxX),
          T = 1.3;
        game.throwBall(e, (x - 8) / T, (o.y - 4 + 0.5 * 9.81 * T * T) / T);
        const score = game.round().score;
        for (let k = 0; k < 120 && game.round().score === score; k++) game.step();
        if (game.round().score === score) continue;
        const ids = game.ballIds();
        const P = game.world.components.Position;
        return {
          ids,
          thrown: e,
          r,
          hoopX: x,
          fed: ids.map((id) => ({ x: P.x[id % 2 ** 25]!, r: game.world.components.Ball.radius[id % 2 ** 25]! })),
        };
      }
      return null;
    });
    expect(got).not.toBeNull();
    // The ball that went in is gone; one new ball is in the box, of its radius, by the wall away from the hoop.
    expect(got!.ids).not.toContain(got!.thrown);
    expect(got!.ids).toHaveLength(1);
    expect(got!.fed[0]!.r).toBeCloseTo(got!.r, 9);
    // Away from the hoop: the hoop on the right half (x > 9), so the left wall (x 0): within 0.5 m of it
    // (it comes in 0.05 m off the wall and rolls inwards for the few steps since).
    expect(got!.hoopX).toBeGreaterThan(9);
    expect(got!.fed[0]!.x).toBeLessThan(0.5 + got!.r);
    expect(g.errors).toEqual([]);
    await g.close();
  });

  it('desktop 1280 x 800, mouse: an arc cut short by a ramp ends at a cross that says "hits the ramp"', async () => {
    const g = await h.openGame('bouncing-balls', { viewport: { width: 1280, height: 800 }, query: { count: 8 } });
    type CutGame = AimGame & {
      spawn(x: number, y: number): number;
      aimCut(): { kind: string; x: number; y: number; words: string } | null;
    };
    await g.page.evaluate(() => {
      const game = window.game as unknown as CutGame;
      game.paused = true;
      for (const id of game.ballIds()) game.remove(id);
      game.spawn(3, 6);
    });
    const at = await g.page.evaluate(() => (window.game as unknown as CutGame).positions());
    const from = await g.worldToPage(at[0]!, at[1]!);
    const m = g.page.mouse;
    await m.move(from.x, from.y);
    await m.down();
    // Pulled down and right: thrown up and left, into the left ramp (scene.ts SEGMENTS[0]) over it.
    let cut: { kind: string; x: number; y: number; words: string } | null = null;
    for (const [dx, dy] of [
      [150, 210],
      [180, 250],
      [130, 230],
      [200, 230],
      [120, 200],
    ] as const) {
      await m.move(from.x + dx, from.y + dy, { steps: 4 });
      await g.frames(2);
      cut = await g.page.evaluate(() => (window.game as unknown as CutGame).aimCut());
      if (cut?.kind === 'ramp') break;
    }
    expect(cut?.kind).toBe('ramp');
    expect(cut!.words).toBe('hits the ramp');
    // Independent of the page's test: the cut is where the ball (0.4 m at most) touches that ramp.
    const [ax, ay, bx, by] = RAMPS[0]!;
    const ex = bx - ax,
      ey = by - ay;
    const u = Math.max(0, Math.min(1, ((cut!.x - ax) * ex + (cut!.y - ay) * ey) / (ex * ex + ey * ey)));
    const d = Math.hypot(cut!.x - ax - u * ex, cut!.y - ay - u * ey);
    expect(d).toBeLessThan(0.4 * 1.4 + SEGMENT_RADIUS + 0.05);
    // The arc's last dot is the cut.
    const path = await g.page.evaluate(() => (window.game as unknown as CutGame).aimPath());
    expect(path.at(-2)).toBeCloseTo(cut!.x, 9);
    expect(path.at(-1)).toBeCloseTo(cut!.y, 9);
    await m.move(from.x, from.y, { steps: 4 });
    await m.up();
    expect(g.errors).toEqual([]);
    await g.close();
  });

  it('phone 390 x 844: the taking-turns hint holds while a ball is aimed and moves on after (6 s of game time each)', async () => {
    // The turns run on game time (main.ts playSeconds), stepped here in the page: the test waited
    // some 20 s of the wall clock for them before.
    const g = await h.openGame('bouncing-balls', { viewport: { width: 390, height: 844 }, touch: true, query: { count: 8 } });
    const turn = () => g.page.evaluate(() => (window.game as unknown as { hintTurn(): number }).hintTurn());
    // Paused (so only the steps below run the game's time), frames drawn: no turn.
    await g.page.evaluate(() => {
      (window.game as unknown as { paused: boolean }).paused = true;
    });
    await g.frames(2);
    const t0 = await turn();
    await g.frames(10);
    expect(await turn()).toBe(t0);
    // 6.1 s of game time (steps, then frames that write the row): the next hint.
    await g.runFrames(366, { draw: false, resume: false });
    await g.frames(2);
    const shown = await turn();
    expect(shown).toBe((t0 + 1) % 4);
    const at = await g.page.evaluate(() => (window.game as unknown as AimGame).positions());
    const from = await g.worldToPage(at[0]!, at[1]!);
    const m = g.page.mouse;
    await m.move(from.x, from.y);
    await m.down();
    await m.move(from.x - 20, from.y + 60, { steps: 4 });
    // Aimed for 8 s of game time (past 6 s), a frame drawn each quarter second: the hint stays.
    for (let i = 0; i < 32; i++) {
      await g.runFrames(15, { draw: false, resume: false });
      await g.frames(1);
    }
    expect(await turn()).toBe(shown);
    await m.up();
    // Let go: its 6 s are long over, so it moves on at once (on the next frames, no step between).
    await g.frames(2);
    expect(await turn()).toBe((shown + 1) % 4);
    expect(g.errors).toEqual([]);
    await g.close();
  });

  it('phone 390 x 844: the score line, bumped at its largest, stays inside the screen', async () => {
    const g = await h.openGame('bouncing-balls', { viewport: { width: 390, height: 844 }, touch: true, query: { count: 8 } });
    const edges = await g.page.evaluate(() => {
      const el = document.querySelector<HTMLElement>('[data-hud="hoop"] [data-hud="numbers"]')!;
      // The longest line of the issue 34 play, as the row shows it mid-round.
      el.textContent = 'Points 88 · ×2 · Time 60 s · Best 27';
      (window.game as unknown as { bumpScore(): void }).bumpScore();
      // Held at the animation's peak (20 % of 0.9 s).
      const anim = el.getAnimations()[0]!;
      anim.pause();
      anim.currentTime = 180;
      const range = document.createRange();
      range.selectNodeContents(el);
      const r = range.getBoundingClientRect();
      return { left: r.left, right: r.right, width: window.innerWidth, transform: getComputedStyle(el).transform };
    });
    // It did grow (a matrix with a scale over 1), and its text lies inside the 390 px screen.
    const scale = Number(/matrix\(([\d.]+)/.exec(edges.transform)?.[1]);
    expect(scale).toBeGreaterThan(1.01);
    expect(edges.left).toBeGreaterThanOrEqual(0);
    expect(edges.right).toBeLessThanOrEqual(edges.width);
    expect(g.errors).toEqual([]);
    await g.close();
  });

  it('desktop 1280 x 800, mouse: an arc that ends on the backboard is not labelled as a block ("hits the board")', async () => {
    const g = await h.openGame('bouncing-balls', { viewport: { width: 1280, height: 800 }, query: { count: 8 } });
    type CutGame = AimGame & {
      spawn(x: number, y: number): number;
      aimCut(): { kind: string; x: number; y: number; words: string } | null;
      aimHelp(on?: boolean): boolean;
    };
    await g.page.evaluate(() => {
      const game = window.game as unknown as CutGame;
      game.paused = true;
      for (const id of game.ballIds()) game.remove(id);
      game.spawn(8, 4);
      // The arc's verdict past its first part is help (preview.ts: shown after 3 misses in a row).
      game.aimHelp(true);
    });
    const at = await g.page.evaluate(() => (window.game as unknown as CutGame).positions());
    const from = await g.worldToPage(at[0]!, at[1]!);
    const m = g.page.mouse;
    await m.move(from.x, from.y);
    await m.down();
    // Pulled down and left at a range of angles and lengths: thrown up and right, at the first hoop's
    // backboard (HOOP_SPOTS[0], board on its right).
    let cut: { kind: string; x: number; y: number; words: string } | null = null;
    let pulled = { x: from.x, y: from.y };
    search: for (const len of [120, 150, 180, 100, 210])
      for (const deg of [10, 20, 30, 40, 50, 60]) {
        const a = (deg * Math.PI) / 180;
        pulled = { x: from.x - len * Math.cos(a), y: from.y + len * Math.sin(a) };
        await m.move(pulled.x, pulled.y, { steps: 2 });
        await g.frames(2);
        cut = await g.page.evaluate(() => (window.game as unknown as CutGame).aimCut());
        if (cut?.kind === 'board') break search;
      }
    expect(cut?.kind).toBe('board');
    // Independent of the page's test: the cut is where the ball (0.4 m at most) touches the backboard
    // (hoop.ts hoopSegments: the board first), not the front rim.
    const [ax, ay, , by] = hoopSegments(HOOP_SPOTS[0]!)[0]!;
    expect(Math.abs(cut!.x - ax)).toBeLessThan(0.4 * 1.4 + HOOP_RADIUS + 0.05);
    expect(cut!.y).toBeGreaterThan(ay - 0.4 * 1.4 - HOOP_RADIUS - 0.05);
    expect(cut!.y).toBeLessThan(by + 0.4 * 1.4 + HOOP_RADIUS + 0.05);
    // Said as it is: the board, not the hoop, and no promise of a basket (a stranger read "a bank
    // shot still scores" as "this will score" and the ball bounced out); the first time, that it may
    // go either way.
    expect(cut!.words).toBe('hits the board · may bounce in or out');
    expect(cut!.words).not.toMatch(/scor|hoop|✗/);
    await m.move(from.x, from.y, { steps: 4 });
    await m.up();
    // A cancelled pull teaches nothing: pulled the same way again, the rule is still said. Let go,
    // the throw flies; the next pull the same way says the short words (the rule was read once).
    const boardWords = async () => {
      await m.move(from.x, from.y);
      await m.down();
      await m.move(pulled.x, pulled.y, { steps: 4 });
      await g.frames(2);
      return g.page.evaluate(() => (window.game as unknown as CutGame).aimCut()?.words);
    };
    expect(await boardWords()).toBe('hits the board · may bounce in or out');
    await m.up();
    const thrown = await g.page.evaluate(() => {
      const game = window.game as unknown as CutGame & HoopGame & { step(): void };
      const shots = game.round().shots;
      // The thrown ball out of the way, the one pressed on put back where it was.
      for (const id of game.ballIds()) game.remove(id);
      game.spawn(8, 4);
      return shots;
    });
    expect(thrown).toBe(1);
    expect(await boardWords()).toBe('hits the board');
    await m.move(from.x, from.y, { steps: 4 });
    await m.up();
    expect(g.errors).toEqual([]);
    await g.close();
  });

  /** The biggest ball of the (settled) heap that no ball touches from above: its id, centre and radius, m. */
  const biggestFree = (g: GamePage) =>
    g.page.evaluate(() => {
      const game = window.game as unknown as AimGame & { world: { components: { Ball: { radius: Float64Array } } } };
      game.paused = true;
      const ids = game.ballIds(),
        p = game.positions(),
        R = game.world.components.Ball.radius;
      let best = { id: 0, x: 0, y: 0, r: 0 };
      ids.forEach((e, i) => {
        const r = R[e % 2 ** 25]!,
          x = p[2 * i]!,
          y = p[2 * i + 1]!;
        const covered = ids.some(
          (o, j) => o !== e && p[2 * j + 1]! > y && Math.hypot(p[2 * j]! - x, p[2 * j + 1]! - y) < r + R[o % 2 ** 25]! + 0.05,
        );
        if (!covered && r > best.r) best = { id: e, x, y, r };
      });
      return best;
    });

  describe('desktop 1280 x 800, 40 balls, one page', () => {
    const page = sharedPage(() => h, 'bouncing-balls', { viewport: { width: 1280, height: 800 }, query: { count: 40 } });

    it('desktop 1280 x 800, mouse: a 29 px pull from a big heap ball shows its arc (the cancel zone is 15 px, not the ball)', async () => {
      const g = page();
      const ball = await biggestFree(g);
      const at = await g.worldToPage(ball.x, ball.y);
      const edge = await g.worldToPage(ball.x + ball.r, ball.y);
      // Drawn wider than the pull: the zone was the ball's drawn radius, so this pull showed no arc.
      expect(edge.x - at.x).toBeGreaterThan(29);
      const m = g.page.mouse;
      await m.move(at.x, at.y);
      await m.down();
      await m.move(at.x - 14, at.y + 25, { steps: 4 });
      await g.waitFor(() => (window.game as unknown as AimGame).aimPath().length > 2, null);
      expect((await aimState(g)).label).toMatch(/power \d+% · 2 points$/);
      // Back within 15 px: cancelled.
      await m.move(at.x - 6, at.y + 8, { steps: 4 });
      await g.waitFor(() => (window.game as unknown as AimGame).aimLabel() === 'release here to cancel', null);
      await m.up();
      expect(g.errors).toEqual([]);
    });

    it('desktop 1280 x 800: aiming a buried ball lifted out draws nothing out to the canvas corner (no stray line)', async () => {
      const g = page();
      // The lowest ball with another ball touching it from above: pressed, it is lifted to the top of the heap.
      const ball = await g.page.evaluate(() => {
        const game = window.game as unknown as AimGame & { world: { components: { Ball: { radius: Float64Array } } } };
        game.paused = true;
        const ids = game.ballIds(),
          p = game.positions(),
          R = game.world.components.Ball.radius;
        let best = { x: 0, y: Infinity };
        ids.forEach((e, i) => {
          const x = p[2 * i]!,
            y = p[2 * i + 1]!;
          const buried = ids.some(
            (o, j) =>
              o !== e && p[2 * j + 1]! > y + 0.2 && Math.hypot(p[2 * j]! - x, p[2 * j + 1]! - y) < R[e % 2 ** 25]! + R[o % 2 ** 25]! + 0.03,
          );
          if (buried && x > 4 && x < 12 && y < best.y) best = { x, y };
        });
        return best;
      });
      const at = await g.worldToPage(ball.x, ball.y);
      const m = g.page.mouse;
      await m.move(at.x, at.y);
      await m.down();
      await m.move(at.x - 40, at.y + 80, { steps: 6 });
      await g.waitFor(() => (window.game as unknown as AimGame).aimLabel().startsWith('lifted · '), null);
      // What the pointer overlay holds: the empty place, the lifted ball, the band, the gauge and the
      // arc, all near the ball and its arc. Pixi's arc, drawn with no point before it, joined the
      // canvas's corner (0, 0) to the empty place's dashed outline with a thin white line.
      const bounds = await g.page.evaluate(() => {
        const game = window.game as unknown as AimGame & {
          app: { stage: { children: { label: string; getBounds(): { minX: number; minY: number } }[] } };
          renderer: { camera: { toScreenX(x: number): number; toScreenY(y: number): number } };
        };
        const b = game.app.stage.children.find((c) => c.label === 'pointer')!.getBounds();
        const cam = game.renderer.camera,
          arc = game.aimPath();
        const xs = arc.filter((_, i) => i % 2 === 0).map((x) => cam.toScreenX(x)),
          ys = arc.filter((_, i) => i % 2 === 1).map((y) => cam.toScreenY(y));
        return { minX: b.minX, minY: b.minY, arcX: Math.min(...xs), arcY: Math.min(...ys) };
      });
      const canvas = (await g.page.locator('canvas').first().boundingBox())!;
      expect(bounds.minX).toBeGreaterThan(Math.min(bounds.arcX, at.x - 40 - canvas.x) - 60);
      expect(bounds.minY).toBeGreaterThan(bounds.arcY - 60);
      await m.up();
      expect(g.errors).toEqual([]);
    });

    it('desktop: a ball buried in the heap is lifted to the top of the heap over it; its arc starts there and it flies it, or the arc ends on the ball in its way', async () => {
      const g = page();
      // The walls a throw may bounce off (the box's ramps, the first hoop, and its net's sides and bottom,
      // NET: the trapezoid under the rim, of no thickness), [ax, ay, bx, by, radius], m: only throws whose
      // drag-free path stays clear of them and of the box for 0.5 s are measured. (A throw at the hoop's
      // side bounces off the net, as its arc shows: 0.4 s into one, 2.5 m on.)
      const spot = HOOP_SPOTS[0]!;
      const [netL, netR, netBottom] = [spot.x - HOOP_HALF_WIDTH, spot.x + HOOP_HALF_WIDTH, spot.y - NET.depth];
      const walls = [
        ...RAMPS.map(([ax, ay, bx, by]) => [ax, ay, bx, by, SEGMENT_RADIUS]),
        ...hoopSegments(spot).map(([ax, ay, bx, by]) => [ax, ay, bx, by, HOOP_RADIUS]),
        [netL, spot.y, netL + NET.narrow, netBottom, 0],
        [netL + NET.narrow, netBottom, netR - NET.narrow, netBottom, 0],
        [netR - NET.narrow, netBottom, netR, spot.y, 0],
      ];
      const { rows, refused } = await g.page.evaluate(
        ({ walls, box }) => {
          const game = window.game as unknown as HeapThrows;
          const g = game.params.gravity;
          const out: { lift: number; column: number; gap: number; free: boolean; arcEnd: number; off: number; endGap: number }[] = [];
          let refused = 0;
          // Each case starts from the heap settled 10 s (paused, stepped) after a reset: stepped once,
          // saved, and put back after each case's reset (saveWorld, restoreWorld: the physics
          // snapshot, which steps on bit for bit as the world did).
          game.reset();
          game.paused = true;
          for (let k = 0; k < 600; k++) game.step();
          const settled = game.saveWorld();
          // Whether a throw changed the game since its last reset: a case that throws nothing only reads
          // the state (aimFrom, the arc's prediction, changes nothing), so the next case starts from the
          // same reset and restored heap without doing both again (each costs more than the case).
          let thrown = true;
          for (let i = 0; i < 60; i++) {
            if (thrown) {
              game.reset();
              game.paused = true;
              game.restoreWorld(settled);
              thrown = false;
            }
            const { Position: P, Velocity: V, Ball } = game.world.components;
            const R = Ball.radius;
            const ids = game.ballIds();
            // Inside the heap: at rest under a ball that touches it from above.
            const inside = ids.filter((e) => {
              const s = e % 2 ** 25;
              if (Math.hypot(V.x[s]!, V.y[s]!) > 0.3) return false;
              return ids.some((o) => {
                const q = o % 2 ** 25;
                return o !== e && P.y[q]! > P.y[s]! + 0.2 && Math.hypot(P.x[q]! - P.x[s]!, P.y[q]! - P.y[s]!) < R[s]! + R[q]! + 0.03;
              });
            });
            const e = inside[(i * 7) % inside.length]!,
              s = e % 2 ** 25;
            const angle = ([60, 75, 90, 105, 120][i % 5]! * Math.PI) / 180,
              speed = [9, 11, 13][Math.floor(i / 5) % 3]!;
            const vx = speed * Math.cos(angle),
              vy = speed * Math.sin(angle);
            const r = R[s]!;
            const arc = game.aimFrom(e, vx, vy);
            // Where the arc starts: straight over the ball, clear of every other ball.
            const x = arc[0]!,
              y = arc[1]!;
            let gap = Infinity;
            for (const o of ids) {
              if (o === e) continue;
              const q = o % 2 ** 25;
              gap = Math.min(gap, Math.hypot(P.x[q]! - x, P.y[q]! - y) - r - R[q]!);
            }
            const lift = y - P.y[s]!,
              column = Math.abs(x - P.x[s]!);
            const at = (t: number): [number, number] => [x + vx * t, y + vy * t - 0.5 * g * t * t];
            let clear = true,
              free = true;
            // To 32 steps: the arc's first point at or past 0.5 s (its points are 4 steps apart).
            for (let k = 1; k <= 32 && clear; k++) {
              const [px, py] = at(k / 60);
              // With 0.02 m to spare: a ball thrown straight up beside a wall it lies against grazes it,
              // and its arc ends there (the arc ends at a wall's touch).
              const m = 0.02;
              if (px - r < box.min[0] + m || px + r > box.max[0] - m || py - r < box.min[1] || py + r > box.max[1]) clear = false;
              for (const [ax, ay, bx, by, wr] of walls) {
                const ex = bx! - ax!,
                  ey = by! - ay!;
                const u = Math.max(0, Math.min(1, ((px - ax!) * ex + (py - ay!) * ey) / (ex * ex + ey * ey)));
                if (Math.hypot(px - ax! - u * ex, py - ay! - u * ey) < r + wr!) clear = false;
              }
              // Into another ball (moving towards it): the arc must end there.
              for (const o of ids) {
                const q = o % 2 ** 25;
                if (o === e) continue;
                const dx = P.x[q]! - px,
                  dy = P.y[q]! - py;
                if (Math.hypot(dx, dy) < r + R[q]! && dx * vx + dy * (vy - (g * k) / 60) > 0) free = false;
              }
            }
            if (!clear) continue;
            // How far the arc shown goes along the free path, s (its points are 4 steps apart), and how
            // far its end is from touching the nearest other ball, m.
            let arcEnd = 0;
            for (let j = 1; 2 * j + 1 < arc.length; j++) {
              const [px, py] = at((4 * j) / 60);
              if (Math.hypot(arc[2 * j]! - px, arc[2 * j + 1]! - py) > 1e-6) break;
              arcEnd = (4 * j) / 60;
            }
            let endGap = Infinity;
            for (const o of ids) {
              if (o === e) continue;
              const q = o % 2 ** 25;
              endGap = Math.min(endGap, Math.hypot(P.x[q]! - arc.at(-2)!, P.y[q]! - arc.at(-1)!) - r - R[q]!);
            }
            // A buried ball with no room over it (under a ramp) is not thrown, and its press throws
            // nothing (the game's rule): only the balls the game lifts are measured.
            thrown = true;
            if (!game.throwBall(e, vx, vy)) {
              refused++;
              continue;
            }
            // How far the ball is from the arc 0.5 s after the throw, m.
            for (let k = 0; k < 30; k++) game.step();
            let off = Infinity;
            for (let j = 0; j + 3 < arc.length; j += 2) {
              const ax = arc[j]!,
                ay = arc[j + 1]!,
                ex = arc[j + 2]! - ax,
                ey = arc[j + 3]! - ay;
              const u = Math.max(0, Math.min(1, ((P.x[s]! - ax) * ex + (P.y[s]! - ay) * ey) / (ex * ex + ey * ey || 1)));
              off = Math.min(off, Math.hypot(P.x[s]! - ax - u * ex, P.y[s]! - ay - u * ey));
            }
            out.push({ lift, column, gap, free, arcEnd, off, endGap });
          }
          return { rows: out, refused };
        },
        { walls, box: BOX },
      );
      // Before, a buried ball's arc was drawn straight through the ball on top of it (the throw passed
      // through the heap for up to 0.5 s), and a stranger saw throws that barely moved. Now it is lifted
      // first: its arc starts over it, on top of the heap, clear of every other ball.
      expect(rows.length).toBeGreaterThanOrEqual(20);
      // Most buried balls have room over them: a refused press is the exception.
      expect(refused).toBeLessThan(rows.length / 2);
      for (const r of rows) {
        expect(r.lift).toBeGreaterThan(0.2);
        expect(r.column).toBeLessThan(1e-9);
        expect(r.gap).toBeGreaterThanOrEqual(0);
      }
      // A path clear of the other balls is shown for its first 0.5 s and flown within 0.1 m; one into
      // another ball ends its arc where it touches it.
      const free = rows.filter((r) => r.free);
      expect(free.length).toBeGreaterThanOrEqual(10);
      for (const r of free) expect(r.arcEnd).toBeGreaterThanOrEqual(0.5);
      expect(free.filter((r) => r.off < 0.1).length).toBeGreaterThanOrEqual(0.9 * free.length);
      for (const r of rows.filter((r) => !r.free)) expect(r.endGap).toBeLessThan(0.05);
      expect(g.errors).toEqual([]);
    });
  });

  it('phone 390 x 844, touch: a pull taken back onto the press point cancels: no throw, no shot', async () => {
    const g = await h.openGame('bouncing-balls', { viewport: { width: 390, height: 844 }, touch: true, query: { count: 8 } });
    const n0 = await clearAround(g, 3, 4);
    const from = await g.worldToPage(3, 4);
    let pulled = { arc: 0, label: '', aiming: false };
    let back = { arc: 0, label: '', aiming: false };
    const cdp = await g.page.context().newCDPSession(g.page);
    const touch = (type: 'touchStart' | 'touchMove' | 'touchEnd', x?: number, y?: number) =>
      cdp.send('Input.dispatchTouchEvent', { type, touchPoints: x === undefined ? [] : [{ x, y: y!, id: 1 }] });
    await touch('touchStart', from.x, from.y);
    for (const f of [0.25, 0.5, 0.75, 1]) await touch('touchMove', from.x - 50 * f, from.y + 80 * f);
    await g.frames(2);
    pulled = await aimState(g);
    for (const f of [0.75, 0.5, 0.25, 0.05]) await touch('touchMove', from.x - 50 * f, from.y + 80 * f);
    await g.frames(2);
    back = await aimState(g);
    await touch('touchEnd');
    await cdp.detach();
    expect(pulled.arc).toBeGreaterThan(6);
    expect(back).toEqual({ arc: 0, label: 'release here to cancel', aiming: true });
    await g.frames(3);
    const after = await g.page.evaluate(() => {
      const game = window.game as unknown as AimGame;
      return { balls: game.ballIds().length, shots: game.round().shots, aiming: game.aiming() };
    });
    expect(after).toEqual({ balls: n0.balls, shots: n0.shots, aiming: false });
    expect(g.errors).toEqual([]);
    await g.close();
  });

  it("desktop 1280 x 1000: from a heap ball by the window's right edge, a pull past that edge (captured) throws at the full speed", async () => {
    // 1000 px tall: the box (with the strip to pull into under it) is as wide as the canvas, so it
    // reaches the window's right edge (at 800 px the strip's height leaves a band either side of it).
    const g = await h.openGame('bouncing-balls', { viewport: { width: 1280, height: 1000 }, query: { count: 40 } });
    // The box reaches the window's right edge: the heap balls by its right wall have a few tens of px
    // of room to their right. The heap settles, then the rightmost ball with 45 px or more of room
    // (main.ts MIN_FULL_PULL, 40 px, is the shortest full pull) is pressed at its centre and pulled
    // right and a little down (20 degrees) to the viewport's last column.
    await g.runUntil(() => (window.game as unknown as AimGame).world.time > 3, null, { draw: false, resume: false });
    await g.frames(2);
    const right = await g.page.evaluate(() => {
      const game = window.game as unknown as AimGame;
      game.paused = true;
      const cam = (game as unknown as { renderer: { camera: { toScreenX(x: number): number } } }).renderer.camera;
      const left = document.querySelector('canvas')!.getBoundingClientRect().left;
      const ids = game.ballIds(),
        p = game.positions();
      let k = -1;
      for (let i = 0; i < ids.length; i++)
        if (innerWidth - 1 - (left + cam.toScreenX(p[2 * i]!)) >= 45 && (k < 0 || p[2 * i]! > p[2 * k]!)) k = i;
      // Alone in the box (paused, it stays where it lay): thrown into the heap beside it, a blocked
      // release would throw nothing.
      for (const id of ids) if (id !== ids[k]) game.remove(id);
      return { id: ids[k]!, x: p[2 * k]!, y: p[2 * k + 1]! };
    });
    const at = await g.worldToPage(right.x, right.y);
    const viewport = g.page.viewportSize()!;
    const slope = Math.tan((20 * Math.PI) / 180);
    // The full pull (420 px or less) is the same wherever a press begins: the pull goes on past the
    // window's right edge, as a held mouse button does (the room to the edge no longer shortens it).
    const to = { x: at.x + 430, y: at.y + 430 * slope };
    expect(viewport.width - 1 - at.x).toBeLessThan(105);
    expect(to.x).toBeGreaterThan(viewport.width);
    const v = await mouseThrow(g, right.id, at, to);
    // hoop.ts MAX_THROW_SPEED, 20 m/s, up and to the left (opposite the pull).
    expect(v.shots).toBe(1);
    expect(Math.hypot(v.vx, v.vy)).toBeCloseTo(20, 6);
    expect(v.vx).toBeLessThan(0);
    expect(Math.atan2(v.vy, -v.vx) * (180 / Math.PI)).toBeCloseTo(20, 0);
    expect(g.errors).toEqual([]);
    await g.close();
  });

  it('phone 390 x 844, touch: a tap on the stand under the floor drops nothing and says what a pull there does; a pull from there throws the top ball of the heap over it; a pull from a heap ball by the side gives the thumb room (no full speed from a 40 px pull)', async () => {
    const g = await h.openGame('bouncing-balls', { viewport: { width: 390, height: 844 }, touch: true, query: { count: 20 } });
    await g.runUntil(() => (window.game as unknown as AimGame).world.time > 3, null, { draw: false, resume: false });
    await g.frames(2);
    const n0 = await g.page.evaluate(() => {
      const game = window.game as unknown as AimGame;
      game.paused = true;
      return { balls: game.ballIds().length, shots: game.round().shots };
    });
    const stand = await g.worldToPage(5, -1.5);
    await g.page.touchscreen.tap(stand.x, stand.y);
    await g.frames(3);
    expect(await g.page.evaluate(() => (window.game as unknown as AimGame).ballIds().length)).toBe(n0.balls);
    expect(await g.page.evaluate(() => (window.game as unknown as AimGame).round().shots)).toBe(n0.shots);
    expect(await g.page.locator('[data-hud="hoop"] [data-hud="hint"]').textContent()).toMatch(/pull back to throw the ball above/);
    // A pull from the stand (the help says a press anywhere throws): the ball it throws is the highest
    // of the heap's balls whose width spans the press's x (the top of the column over the finger).
    const column = await g.page.evaluate(() => {
      const game = window.game as unknown as AimGame;
      const ids = game.ballIds(),
        p = game.positions(),
        R = (game.world.components as unknown as { Ball: { radius: Float64Array } }).Ball.radius;
      let top = 0,
        topY = -1;
      for (let i = 0; i < ids.length; i++) {
        const r = R[ids[i]! % 2 ** 25]!;
        if (Math.abs(p[2 * i]! - 5) < r && p[2 * i + 1]! + r > topY) {
          top = ids[i]!;
          topY = p[2 * i + 1]! + r;
        }
      }
      // Its neighbours up to its height taken off (paused, the rest stay where they lay): thrown up
      // and to the right, it would be blocked by one, and a blocked release throws nothing.
      const t = ids.indexOf(top);
      for (let i = 0; i < ids.length; i++)
        if (i !== t && p[2 * i + 1]! > p[2 * t + 1]! - 0.5 && Math.abs(p[2 * i]! - p[2 * t]!) < 2.5) game.remove(ids[i]!);
      return top;
    });
    expect(column).toBeGreaterThan(0);
    n0.balls = await g.page.evaluate(() => (window.game as unknown as AimGame).ballIds().length);
    let label = '';
    await swipe(
      g.page,
      [
        [stand.x, stand.y],
        [stand.x - 10, stand.y + 10],
        [stand.x - 20, stand.y + 25],
        [stand.x - 30, stand.y + 40],
      ],
      async () => {
        await g.frames(2);
        label = await g.page.evaluate(() => (window.game as unknown as AimGame).aimLabel());
      },
    );
    const thrown = await g.waitFor(
      ([id, shots]) => {
        const game = window.game as unknown as AimGame;
        const e = id! % 2 ** 25;
        return game.round().shots === shots! + 1
          ? { vx: game.world.components.Velocity.x[e]!, vy: game.world.components.Velocity.y[e]!, balls: game.ballIds().length }
          : null;
      },
      [column, n0.shots] as const,
    );
    // A heap ball's throw (its points in the label), up and to the right (the pull went down and left);
    // no ball added.
    expect(label).toMatch(/· [25] points$/);
    expect(thrown.vx).toBeGreaterThan(0.5);
    expect(thrown.vy).toBeGreaterThan(thrown.vx);
    expect(thrown.balls).toBe(n0.balls);
    // Back to rest before the next pull (stepped in the page).
    await g.page.evaluate(() => {
      const game = window.game as unknown as AimGame & { step(): void };
      for (let k = 0; k < 240; k++) game.step();
    });
    n0.shots += 1;
    // The leftmost heap ball (the box reaches within 16 px of the screen's left edge): pulled 40 px
    // down and to the left (its room to the left is some 30 px: the full pull was cut to 40 px, and
    // such a pull threw at the full 20 m/s).
    const left = await g.page.evaluate(() => {
      const game = window.game as unknown as AimGame;
      const ids = game.ballIds(),
        p = game.positions();
      let k = 0;
      for (let i = 1; i < ids.length; i++) if (p[2 * i]! < p[2 * k]!) k = i;
      // Its neighbours up to its height taken off, as above (a blocked release throws nothing).
      for (let i = 0; i < ids.length; i++)
        if (i !== k && p[2 * i + 1]! > p[2 * k + 1]! - 0.5 && Math.abs(p[2 * i]! - p[2 * k]!) < 2.5) game.remove(ids[i]!);
      return { id: ids[k]!, x: p[2 * k]!, y: p[2 * k + 1]! };
    });
    const at = await g.worldToPage(left.x, left.y);
    const to: [number, number] = [Math.max(1, at.x - 24), at.y + 32];
    let fullPull = 0;
    await swipe(g.page, [[at.x, at.y], [at.x - 8, at.y + 11], [at.x - 16, at.y + 21], to], async () => {
      await g.frames(2);
      fullPull = await g.page.evaluate(() => (window.game as unknown as { fullPull(): number }).fullPull());
    });
    const v = await g.waitFor(
      ([id, shots]) => {
        const game = window.game as unknown as AimGame;
        const e = id! % 2 ** 25;
        return game.round().shots === shots! + 1 ? [game.world.components.Velocity.x[e]!, game.world.components.Velocity.y[e]!] : null;
      },
      [left.id, n0.shots] as const,
    );
    // main.ts TOUCH_FULL_PULL_SHARE: half the phone's full pull (0.6 x 390 px), 117 px.
    expect(fullPull).toBeGreaterThanOrEqual(117 - 1e-9);
    const pull = Math.hypot(to[0] - at.x, to[1] - at.y);
    // hoop.ts slingSpeed in the tall box's room (slingRoom: from the ball's height, under the hoop's
    // rim), well under the full pull's speed.
    const rim = await g.page.evaluate(() => (window.game as unknown as { hoop(): { y: number } }).hoop().y);
    const room = slingRoom(left.y, rim, 9.81);
    expect(pull / fullPull).toBeLessThan(0.5);
    expect(Math.hypot(v[0]!, v[1]!)).toBeCloseTo(slingSpeed(pull, fullPull, room), 6);
    expect(Math.hypot(v[0]!, v[1]!)).toBeLessThan(0.9 * room.top);
    expect(g.errors).toEqual([]);
    await g.close();
  });

  it('desktop: when time runs out mid-aim, the pull goes on as the last throw, which counts; the round ends once its ball scores or misses', async () => {
    const g = await h.openGame('bouncing-balls', { viewport: { width: 1280, height: 800 }, query: { count: 8, round: 5 } });
    await g.page.evaluate(() => {
      const game = window.game as unknown as AimGame;
      for (const id of game.ballIds()) game.remove(id);
    });
    // A basket starts the clock (the drag-free arc of the hoop-game test above), up to three tries.
    expect(await shootUntilScored(g, null, 1.7)).toBe(1);
    await g.page.evaluate(() => {
      (window.game as unknown as AimGame).paused = false;
    });
    // Aim from low on the left, below the rim's line (so the throw may score and the round waits for
    // its ball), and hold the pull past the clock's end.
    const low = await g.page.evaluate(() => Math.max(0.8, Math.min(3, (window.game as unknown as AimGame).hoop().y - 1)));
    const from = await g.worldToPage(9, low);
    const m = g.page.mouse;
    await m.move(from.x, from.y);
    await m.down();
    await m.move(from.x - 60, from.y + 80, { steps: 6 });
    await g.frames(2);
    expect((await aimState(g)).aiming).toBe(true);
    // The clock reaches 0 under the pull: the round waits for this last throw (it used to end the aim,
    // and the throw being aimed was lost).
    await g.runUntil(
      () => {
        const game = window.game as unknown as AimGame;
        return game.round().timeLeft === 0 && game.lastThrow().aiming;
      },
      null,
      { draw: false },
    );
    await g.frames(2);
    const shots = await g.page.evaluate(() => (window.game as unknown as AimGame).round().shots);
    await g.frames(3);
    const waiting = await g.page.evaluate(() => {
      const game = window.game as unknown as AimGame;
      return {
        phase: game.round().phase,
        countdown: game.countdown(),
        status: game.statusText(),
        red: document.querySelector('[data-hud="hoop"] [data-hud="numbers"]')!.classList.contains('bb-hurry'),
      };
    });
    expect(waiting).toEqual({
      phase: 'playing',
      countdown: 'Last throw!',
      status: expect.stringMatching(/last throw still counts/),
      red: true,
    });
    // Its arc is still drawn.
    expect((await aimState(g)).arc).toBeGreaterThan(2);
    // Let go: it throws, and counts as a shot.
    await m.up();
    const thrown = await g.page.evaluate(() => {
      const game = window.game as unknown as AimGame;
      game.paused = true;
      return { shots: game.round().shots, last: game.lastThrow(), phase: game.round().phase };
    });
    expect(thrown.shots).toBe(shots + 1);
    expect(thrown.last.aiming).toBe(false);
    expect(thrown.last.ball).toBeGreaterThan(0);
    expect(thrown.phase).toBe('playing');
    // No new press while the last ball flies.
    await m.move(from.x + 100, from.y);
    await m.down();
    await m.move(from.x + 40, from.y + 80, { steps: 4 });
    expect((await aimState(g)).aiming).toBe(false);
    await m.up();
    // The round ends once the last ball has scored or missed (stepped in the page).
    await g.runUntil(() => (window.game as unknown as AimGame).round().phase === 'over', null, { draw: false });
    await g.frames(2);
    expect(await g.page.evaluate(() => (window.game as unknown as AimGame).round().shots)).toBe(shots + 1);
    expect(g.errors).toEqual([]);
    await g.close();
  });
});
