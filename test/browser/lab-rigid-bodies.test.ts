/**
 * Rigid bodies in headless Chromium: the incline demo starts with its two boxes, B and a click each
 * drop a crate, P pauses (no steps while paused), the tall box tips before the wide one slides as
 * the board rises, every demo builds and steps, and the page logs no error.
 */
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { type GamePage, Harness, START_TIMEOUT_MS } from './harness';

/** The extras games/lab-rigid-bodies/main.ts puts on window.game. */
interface TemplateGame {
  boxCount(): number;
  paused: boolean;
  world: { steps: number; components: { Angle: { value: Float64Array }; Position: { x: Float64Array; y: Float64Array } } };
  ids(): { board?: number; tall?: number; wide?: number };
  advance(n: number): void;
  params: { scene: string };
  reset(): void;
}

describe('lab-rigid-bodies', () => {
  let h: Harness;
  let g: GamePage;
  beforeAll(async () => {
    h = await Harness.start();
    g = await h.openGame('lab-rigid-bodies', { query: { scene: 'incline' } });
  }, START_TIMEOUT_MS);
  afterAll(async () => {
    await h?.close();
  });

  const balls = () => g.page.evaluate(() => (window.game as unknown as TemplateGame).boxCount());

  it('starts with the incline demo, draws and steps', async () => {
    expect(await balls()).toBe(2);
    expect(await g.canvasColors()).toBeGreaterThan(4);
    await g.waitFor(() => (window.game as unknown as TemplateGame).world.steps > 2, null);
    expect(g.errors).toEqual([]);
  });

  it('drops a crate on B and on a click', async () => {
    const before = await balls();
    await g.press('b');
    await g.waitFor((n) => (window.game as unknown as TemplateGame).boxCount() === n + 1, before);
    const box = (await g.page.locator('canvas').first().boundingBox())!;
    await g.page.mouse.click(box.x + box.width / 2, box.y + box.height / 3);
    await g.waitFor((n) => (window.game as unknown as TemplateGame).boxCount() === n + 2, before);
    expect(g.errors).toEqual([]);
  });

  it('pauses on P: no steps while paused', async () => {
    await g.press('p');
    await g.waitFor(() => (window.game as unknown as TemplateGame).paused, null);
    const steps = await g.page.evaluate(() => (window.game as unknown as TemplateGame).world.steps);
    await g.frames(5);
    expect(await g.page.evaluate(() => (window.game as unknown as TemplateGame).world.steps)).toBe(steps);
    await g.press('p');
    expect(g.errors).toEqual([]);
  });

  it('on the rising board the tall box (w/h 0.4) tips before the wide one (mu 0.6) slides', async () => {
    const r = await g.page.evaluate(() => {
      const game = window.game as unknown as TemplateGame;
      game.paused = true;
      game.reset();
      const ids = game.ids();
      const slot = (hh: number) => hh % 33554432;
      const c = game.world.components;
      let tipAt = -1,
        slideAt = -1;
      // Distance of the wide box along the board from its pivot (2, 1.5), the scene's BOARD constant.
      const along = (a: number) =>
        (c.Position.x[slot(ids.wide!)]! - 2) * Math.cos(a) + (c.Position.y[slot(ids.wide!)]! - 1.5) * Math.sin(a);
      const s0 = along(0);
      for (let i = 0; i < 600; i++) {
        game.advance(1);
        const a = c.Angle.value[slot(ids.board!)]!;
        if (tipAt < 0 && Math.abs(c.Angle.value[slot(ids.tall!)]! - a) > 0.5) tipAt = a;
        if (slideAt < 0 && along(a) < s0 - 0.5) slideAt = a;
      }
      return { tipAt, slideAt };
    });
    // Rigid-body statics: tips past atan(0.4) = 21.8 deg, slides past atan(0.6) = 31 deg. The board
    // turns 0.08 rad/s and the soft contacts lag: a few degrees late is allowed, the order is not.
    const deg = (a: number) => (a * 180) / Math.PI;
    expect(deg(r.tipAt)).toBeGreaterThan(21);
    expect(deg(r.tipAt)).toBeLessThan(30);
    expect(deg(r.slideAt)).toBeGreaterThan(deg(r.tipAt));
    expect(g.errors).toEqual([]);
  });

  it('builds and steps every demo', async () => {
    for (const scene of ['bouncing', 'colliding', 'torque', 'turbine', 'incline']) {
      const steps = await g.page.evaluate((name) => {
        const game = window.game as unknown as TemplateGame;
        game.params.scene = name;
        game.reset();
        game.advance(30);
        return game.world.steps;
      }, scene);
      expect(steps).toBeGreaterThanOrEqual(30);
    }
    expect(g.errors).toEqual([]);
  });
});
