/**
 * Wrecking ball on a phone (390 x 844, touch): a two-finger pinch moves the camera and nothing else.
 * Once a second finger touches, any aim the first began is cancelled (no swing, no hook move) and
 * nothing fires until every finger has lifted (games/wrecking-ball/main.ts, the pointer handlers).
 * Fingers are real touch input (CDP Input.dispatchTouchEvent; a touchEnd lists the fingers still down).
 */
import type { CDPSession } from 'playwright-core';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { Harness, START_TIMEOUT_MS } from './harness';

type Pt = { x: number; y: number; id: number };
interface WB {
  swings(): { used: number };
  handles(): { controls: { moves: unknown[]; goal: number[] | null }; pieces: { body: number; kind: string }[] };
  aim(): { piece: number };
  app: { camera: { position: { x: number; y: number; z: number } } };
}

describe('wrecking ball on a phone: a pinch, a pull toward the camera, the HUD', () => {
  let h: Harness;
  beforeAll(async () => {
    h = await Harness.start();
  }, START_TIMEOUT_MS);
  afterAll(async () => {
    await h?.close();
  });

  /**
   * Two fingers at (120, 350) and (270, 600) pinched inward over 8 moves, the second put down
   * `stagger` ms after the first (the first moving meanwhile), then lifted one by one.
   */
  async function pinch(cdp: CDPSession, wait: (ms: number) => Promise<void>, stagger: number): Promise<void> {
    const a = (k: number): Pt => ({ x: 120 + 8 * k, y: 350 + 14 * k, id: 1 });
    const b = (k: number): Pt => ({ x: 270 - 8 * k, y: 600 - 14 * k, id: 2 });
    const send = (type: 'touchStart' | 'touchMove' | 'touchEnd', touchPoints: Pt[]) =>
      cdp.send('Input.dispatchTouchEvent', { type, touchPoints });
    await send('touchStart', [a(0)]);
    if (stagger > 0) {
      await wait(stagger / 2);
      await send('touchMove', [a(1)]);
      await wait(stagger / 2);
      await send('touchStart', [a(1), b(0)]);
    } else await send('touchStart', [a(0), b(0)]);
    for (let k = 1; k <= 8; k++) {
      await send('touchMove', [a(Math.max(k, stagger > 0 ? 1 : 0)), b(k)]);
      await wait(16);
    }
    // The first finger lifts while the second stays down and moves, then the second lifts.
    await send('touchEnd', [b(8)]);
    await send('touchMove', [{ ...b(8), x: b(8).x + 20 }]);
    await send('touchEnd', []);
  }

  it('a pull toward the camera says what its dashes meet, as one across the screen does; the HUD shows the score', async () => {
    const g = await h.openGame('wrecking-ball', {
      viewport: { width: 390, height: 844 },
      touch: true,
      query: { level: 1, shadows: 0 },
      readyTimeoutMs: 60_000,
    });
    await g.press('p');
    // The drawn centre of level 1's tower's lowest block, page px.
    const tower = await g.page.evaluate(() => {
      type G = WB & {
        world: { components: { Position: { y: Float64Array } } };
        renderer: { drawnPosition(e: number): number[] | null };
        app: {
          camera: { position: { clone(): { set(x: number, y: number, z: number): { project(c: unknown): { x: number; y: number } } } } };
        };
      };
      const game = window.game as unknown as G;
      const P = game.world.components.Position;
      const low = game
        .handles()
        .pieces.filter((p) => p.kind === 'tower')
        .reduce((a, b) => (P.y[b.body]! < P.y[a.body]! ? b : a)).body;
      const at = game.renderer.drawnPosition(low)!;
      const s = game.app.camera.position.clone().set(at[0]!, at[1]!, at[2]!).project(game.app.camera);
      const r = document.querySelector('canvas')!.getBoundingClientRect();
      return { x: r.left + ((s.x + 1) / 2) * r.width, y: r.top + ((1 - s.y) / 2) * r.height };
    });
    /** Page px of one line of the compact hint: 12 px type at line height 1.25 (15 px) and 2 + 2 px of padding. */
    const ONE_LINE_PX = 19;
    /**
     * The hint while a finger pulls (dx, dy) px from the tower, before it lifts (the touch is then
     * cancelled). It must be one line there (it took three, 49 px, over the top of the scene): within
     * 2 px of ONE_LINE_PX (the border and rounding).
     */
    const hintWhilePulling = async (dx: number, dy: number): Promise<string> => {
      const cdp = await g.page.context().newCDPSession(g.page);
      const pt = (k: number): Pt[] => [{ x: tower.x + (dx * k) / 5, y: tower.y + (dy * k) / 5, id: 1 }];
      await cdp.send('Input.dispatchTouchEvent', { type: 'touchStart', touchPoints: pt(0) });
      for (let k = 1; k <= 5; k++) await cdp.send('Input.dispatchTouchEvent', { type: 'touchMove', touchPoints: pt(k) });
      await g.page.waitForTimeout(200);
      const text = (await g.page.locator('[data-hud="tap-hint"]').textContent()) ?? '';
      expect((await g.page.locator('[data-hud="tap-hint"]').boundingBox())!.height).toBeLessThanOrEqual(ONE_LINE_PX + 2);
      await cdp.send('Input.dispatchTouchEvent', { type: 'touchCancel', touchPoints: [] });
      await cdp.detach();
      return text;
    };
    // The status line over the scene carries the score on a phone (the side column's score is in the
    // menu drawer there), after the level and before the swings.
    expect(await g.page.locator('[data-hud="wrecking-ball"]').textContent()).toMatch(/^Level 1 · score 0 · swings left 5\/5/);
    // The ⌂ view button is a finger's target: at least 44 px tall (it was 25), within the viewport.
    const view = (await g.page.locator('[data-hud="reset-view"]').boundingBox())!;
    expect(view.height).toBeGreaterThanOrEqual(44);
    expect(view.y + view.height).toBeLessThanOrEqual(844);
    // Straight down the screen: the ball would run straight away from the camera. The hint says what
    // the dashes drawn in 3D meet (it said "Glancing: ... hits few blocks" from the camera's angle
    // alone, on swings that brought down 18 blocks).
    const toward = await hintWhilePulling(0, 100);
    expect(toward).not.toMatch(/Glancing|few blocks/);
    expect(toward).toMatch(/^(Let go|The ball (meets|would miss))/);
    // To the left: the ball runs across the screen.
    const across = await hintWhilePulling(-90, 0);
    // In a few words on a phone: let go, and the pull's power and speed.
    expect(across).toMatch(/^Let go: (full power|power \d+ %), \d+\.\d m\/s$/);
    expect(await g.page.evaluate(() => (window.game as unknown as WB).swings().used)).toBe(0);
    expect(g.errors).toEqual([]);
    await g.close();
  });

  for (const stagger of [0, 80]) {
    it(`a pinch (second finger ${stagger} ms after the first) uses no swing, aims nothing and leaves the hook`, async () => {
      const g = await h.openGame('wrecking-ball', {
        viewport: { width: 390, height: 844 },
        touch: true,
        query: { level: 1, shadows: 0 },
        readyTimeoutMs: 60_000,
      });
      await g.page.waitForTimeout(500);
      const state = () =>
        g.page.evaluate(() => {
          const game = window.game as unknown as WB;
          const c = game.handles().controls;
          const p = game.app.camera.position;
          return { used: game.swings().used, moves: c.moves.length, goal: c.goal, piece: game.aim().piece, camera: [p.x, p.y, p.z] };
        });
      const before = await state();
      expect(before.used).toBe(0);
      expect(before.moves).toBe(0);
      const cdp = await g.page.context().newCDPSession(g.page);
      await pinch(cdp, (ms) => g.page.waitForTimeout(ms), stagger);
      await cdp.detach();
      await g.page.waitForTimeout(300);
      const after = await state();
      // No swing used or planned, no hook sent, nothing left aiming.
      expect({ used: after.used, moves: after.moves, goal: after.goal, piece: after.piece }).toEqual({
        used: 0,
        moves: 0,
        goal: before.goal,
        piece: 0,
      });
      // The pinch went to the camera: it moved (zoomed) at least 0.1 m.
      const moved = Math.hypot(...after.camera.map((v, i) => v - before.camera[i]!));
      expect(moved).toBeGreaterThan(0.1);
      expect(await g.page.locator('[data-hud="wrecking-ball"]').textContent()).toContain('swings left 5/5');
      // After the pinch, one finger on open ground (left of the ball, short of the plank stack) sends
      // the hook there as it lifts, not before (it might still have become a pinch).
      const cdp2 = await g.page.context().newCDPSession(g.page);
      await cdp2.send('Input.dispatchTouchEvent', { type: 'touchStart', touchPoints: [{ x: 60, y: 640, id: 3 }] });
      await g.page.waitForTimeout(100);
      const held = await state();
      await cdp2.send('Input.dispatchTouchEvent', { type: 'touchEnd', touchPoints: [] });
      await cdp2.detach();
      expect(held.goal).toEqual(before.goal);
      expect((await state()).goal).not.toEqual(before.goal);
      expect(g.errors).toEqual([]);
      await g.close();
    });
  }
});
