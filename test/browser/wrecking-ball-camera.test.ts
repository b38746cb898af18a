/**
 * Wrecking ball, 1280 x 800, level 1: the camera holds still between swings. A swing at the log
 * stack, then at the brick wall: the spot where each structure stood is drawn within a few px of
 * where it was drawn before the swing, through every frame of the swing's run and settling
 * (games/wrecking-ball/main.ts, followAction: the view moves only when the ball would leave the
 * screen, a piece is knocked off it, or the player moves it).
 */
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { Harness, START_TIMEOUT_MS } from './harness';

interface WB {
  world: { components: { Position: { x: Float64Array; y: Float64Array; z: Float64Array } } };
  handles(): {
    pieces: { body: number; kind: string; x0: number; z0: number; fallen: boolean }[];
    controls: { moves: unknown[]; goal: unknown };
  };
  pressAt(x: number, y: number): string;
  releaseAt(x: number, y: number): string;
  swings(): { used: number };
  app: { camera: { position: { clone(): { set(x: number, y: number, z: number): { project(c: unknown): { x: number; y: number } } } } } };
}

describe('wrecking ball: the camera holds still between swings', () => {
  let h: Harness;
  beforeAll(async () => {
    h = await Harness.start();
  }, START_TIMEOUT_MS);
  afterAll(async () => {
    await h?.close();
  });

  it('1280 x 800, level 1: through every frame of a swing at the log stack that knocks logs down and none off the screen, each structure is drawn where it was (within 4 px); so too through one at the brick wall unless the framing widens for bricks knocked off the screen', async () => {
    const g = await h.openGame('wrecking-ball', {
      viewport: { width: 1280, height: 800 },
      query: { level: 1, shadows: 0 },
      readyTimeoutMs: 60_000,
    });
    // Game time is run in the page's own frames (GamePage.runFrames / runUntil), 3 steps a frame
    // (1/20 s): nothing waits on the clock. The game is paused between them (runFrames unpauses it
    // for its frames), so no frames of the page's own run at the machine's speed between the swings,
    // and each run of the test plays the same swings. The camera's spring runs on the world's time
    // (main.ts cameraNow), closing in under 1 s.
    const RUN = { seconds: 1 / 20 };
    await g.page.evaluate(() => {
      (window.game as unknown as { paused: boolean }).paused = true;
    });
    await g.runFrames(30, RUN);
    /**
     * A drag back from the middle of the lowest piece of `kind` by (dx, dy) NDC: a swing at it. The
     * ball is drawn back opposite the arrow while the drag is held (./scene pullBack), so a pull
     * must keep it on the screen for the camera to have no reason to move.
     */
    const swingAt = (kind: string, dx: number, dy: number) =>
      g.page.evaluate(
        ([kind, dx, dy]) => {
          const game = window.game as unknown as WB;
          const P = game.world.components.Position;
          const piece = game
            .handles()
            .pieces.filter((p) => p.kind === kind)
            .reduce((a, b) => (P.y[b.body]! < P.y[a.body]! ? b : a)).body;
          const s = game.app.camera.position.clone().set(P.x[piece]!, P.y[piece]!, P.z[piece]!).project(game.app.camera);
          game.pressAt(s.x, s.y);
          return game.releaseAt(s.x + dx, s.y + dy);
        },
        [kind, dx, dy] as const,
      );
    type Reading = { spots: Record<string, number[]>; widenings: number; fallen: number };
    // Installed in the page for the predicate below: the px on the canvas of each structure's first
    // piece's starting spot (a fixed point of the world: only the camera moves it; measured from the
    // canvas's corner, as a line of the HUD above the canvas moves the canvas down the page by 19 px
    // while a swing runs, which is no move of the camera), and how many times the
    // framing has widened for a piece knocked off the screen (wreckageWidenings).
    await g.page.evaluate(() => {
      (window as unknown as { cameraTestRead(): Reading }).cameraTestRead = () => {
        const game = window.game as unknown as WB & { wreckageWidenings(): number };
        const canvas = document.querySelector('canvas')!.getBoundingClientRect();
        const spots: Record<string, number[]> = {};
        for (const p of game.handles().pieces) {
          if (spots[p.kind]) continue;
          const s = game.app.camera.position.clone().set(p.x0, 0.5, p.z0).project(game.app.camera);
          spots[p.kind] = [((s.x + 1) / 2) * canvas.width, ((1 - s.y) / 2) * canvas.height];
        }
        return { spots, widenings: game.wreckageWidenings(), fallen: game.handles().pieces.filter((p) => p.fallen).length };
      };
    });
    /**
     * Swings at `kind` by (dx, dy) (swing number `used` of the level), then runs the game until that
     * swing has begun and its run is over, and 6 s more (the wreckage settling), reading the spots
     * after every frame.
     * @returns `worst`, the most any spot moved, px, from where it was before the swing, over the
     *   frames before any widening of the framing for a piece knocked off the screen (issue 34: it
     *   then rightly widens to take the piece in; that frame's own easing already moves the camera a
     *   little, so it is not counted); `held`, whether the swing ran to its end without such a
     *   widening; and how many pieces it knocked down.
     */
    const stage = async (kind: string, dx: number, dy: number, used: number) => {
      const start = await g.page.evaluate(() => (window as unknown as { cameraTestRead(): Reading }).cameraTestRead());
      expect(Object.keys(start.spots)).toEqual(expect.arrayContaining(['planks', 'wall', 'tower']));
      expect(await swingAt(kind, dx, dy)).toBe('swing');
      // Phases: waiting for the swing to begin (0), for its run to be over (1), then 120 frames (2).
      const arg = { used, start, phase: 0, frames: 0, worst: 0 };
      const end = await g.runUntil(
        (arg) => {
          const game = window.game as unknown as WB;
          const now = (window as unknown as { cameraTestRead(): Reading }).cameraTestRead();
          if (now.widenings === arg.start.widenings)
            for (const [k, [x, y]] of Object.entries(arg.start.spots))
              arg.worst = Math.max(arg.worst, Math.hypot(now.spots[k]![0]! - x!, now.spots[k]![1]! - y!));
          if (arg.phase === 0 && game.swings().used >= arg.used) arg.phase = 1;
          if (arg.phase === 1 && game.handles().controls.moves.length === 0) arg.phase = 2;
          if (arg.phase === 2 && ++arg.frames >= 120)
            return { worst: arg.worst, held: now.widenings === arg.start.widenings, knocked: now.fallen - arg.start.fallen };
          return null;
        },
        arg,
        { ...RUN, maxFrames: 1920 },
      );
      return end;
    };
    // A pull of 120 px down the screen at the log stack (power 0.75, main.ts aimDrag) knocks 4 logs
    // down and none off the screen (as do 0.3 to 0.4 NDC, 0.1 either side: the choice is not on a
    // knife's edge), and the ball stays on it. The wall stands near the screen's lower left (pulled
    // down or left the ball would be drawn off it), so it is pulled right; its bricks fly off the
    // screen's edge and the framing widens to take them in (the ball, carried on past the wall, may
    // widen it first), so that swing is checked only when the framing held.
    const planks = await stage('planks', 0, -0.3, 1);
    const wall = await stage('wall', 0.2, 0, 2);
    console.log(JSON.stringify({ planks, wall }));
    // A camera that holds still draws these fixed points of the world at the same px (0.00 px apart
    // in every run here); 4 px allows for nothing but rounding, and a camera that follows the ball or
    // re-frames after a swing moved them by 80 px or more.
    expect(planks.knocked).toBeGreaterThan(0);
    expect(planks.held).toBe(true);
    expect(planks.worst).toBeLessThan(4);
    if (wall.held) expect(wall.worst).toBeLessThan(4);
    // Every fallen piece is on the screen (the framing widens to take in one knocked off it).
    expect(await g.page.evaluate(() => (window.game as unknown as { pieceOffScreen(): boolean }).pieceOffScreen())).toBe(false);
    expect(g.errors).toEqual([]);
    await g.close();
  });
  it('390 x 844, touch: a spread of two fingers 100 -> 220 px or a pinch 270 -> 30 px keeps the camera within 0.6x..2x its framing distance; "⌂ view" brings it back', async () => {
    const g = await h.openGame('wrecking-ball', {
      viewport: { width: 390, height: 844 },
      touch: true,
      query: { level: 1, shadows: 0 },
      readyTimeoutMs: 60_000,
    });
    await g.runFrames(20, { seconds: 1 / 20 });
    const distance = () =>
      g.page.evaluate(() => {
        const game = window.game as unknown as {
          app: { camera: { position: { distanceTo(v: unknown): number } }; controls: { target: unknown } };
        };
        return game.app.camera.position.distanceTo(game.app.controls.target);
      });
    /** Two fingers about (195, 420), from `from` px apart to `to` px apart along a diagonal, over 10 moves. */
    const pinch = async (from: number, to: number) => {
      const cdp = await g.page.context().newCDPSession(g.page);
      const at = (k: number) => {
        const half = (from + ((to - from) * k) / 10) / 2 / Math.SQRT2;
        return [
          { x: 195 - half, y: 420 - half, id: 1 },
          { x: 195 + half, y: 420 + half, id: 2 },
        ];
      };
      await cdp.send('Input.dispatchTouchEvent', { type: 'touchStart', touchPoints: at(0) });
      for (let k = 1; k <= 10; k++) {
        await cdp.send('Input.dispatchTouchEvent', { type: 'touchMove', touchPoints: at(k) });
      }
      await cdp.send('Input.dispatchTouchEvent', { type: 'touchEnd', touchPoints: [] });
      await cdp.detach();
      await g.runFrames(2);
    };
    const d0 = await distance();
    await pinch(100, 220);
    const nearer = await distance();
    // Spread 2.2 times: the camera comes nearer by 2.2^0.5 (about 1.48 times), not 2.2 times.
    expect(d0 / nearer).toBeGreaterThan(1.2);
    expect(d0 / nearer).toBeLessThan(1.7);
    await pinch(270, 30);
    await pinch(270, 30);
    const far = await distance();
    expect(far / d0).toBeLessThanOrEqual(2.01);
    expect(far / d0).toBeGreaterThan(1.5);
    for (let i = 0; i < 3; i++) await pinch(60, 300);
    const near = await distance();
    expect(near / d0).toBeGreaterThanOrEqual(0.599);
    await g.page.locator('[data-hud="reset-view"]').click();
    await g.runFrames(2);
    expect(Math.abs((await distance()) / d0 - 1)).toBeLessThan(0.02);
    // More than 6 s into the level with no swing (run on in the page's frames, 1/10 s each, and a few
    // more for the hint, redrawn every 6th frame): the phone's intro has shrunk to one line.
    await g.runUntil(() => (window.game as unknown as { world: { time: number } }).world.time > 6.5, null, { seconds: 1 / 10 });
    await g.runFrames(6);
    expect(await g.page.evaluate(() => (window.game as unknown as { world: { time: number } }).world.time)).toBeGreaterThan(6.5);
    expect(await g.page.locator('[data-hud="tap-hint"]').textContent()).toBe('Drag back from a block and let go');
    expect(g.errors).toEqual([]);
    await g.close();
  });
});
