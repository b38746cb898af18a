/**
 * The joints lab (lab-joints) in headless Chromium: it loads without errors, draws, lists its
 * controls, and an input changes it as read through window.game (a drag moves a body through a mouse
 * joint). The rope and cloth labs have their own file (labs-cloth-rope.test.ts).
 */
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { type GamePage, Harness, START_TIMEOUT_MS } from './harness';

interface Cam {
  toScreenX(x: number): number;
  toScreenY(y: number): number;
}
interface LabWindow {
  paused: boolean;
  reset(): void;
  advance(n: number): void;
  renderer: { camera: Cam };
  world: { components: { Position: { x: Float64Array; y: Float64Array }; Velocity: { x: Float64Array; y: Float64Array } } };
}

let h: Harness;
beforeAll(async () => {
  h = await Harness.start();
}, START_TIMEOUT_MS);
afterAll(async () => {
  await h?.close();
});

/** Opens a lab, checks the common furniture, pauses it on a fresh world. */
async function open(folder: string, query: Record<string, string | number>, keys: string[]): Promise<GamePage> {
  const g = await h.openGame(folder, { query });
  expect(await g.canvasColors()).toBeGreaterThan(8);
  const legend = await g.page.locator('.bp-legend').textContent();
  for (const key of ['P', 'N', 'R', ...keys]) expect(legend).toContain(key);
  expect(await g.page.locator('.lil-gui').count()).toBeGreaterThan(0);
  expect(await g.page.locator('[data-lab="info"]').count()).toBe(1);
  await g.page.evaluate(() => {
    const w = window.game as unknown as LabWindow;
    w.paused = true;
    w.reset();
  });
  expect(g.errors).toEqual([]);
  return g;
}

/** Screen point of world point (x, y) on the lab's canvas. */
function screen(g: GamePage, x: number, y: number): Promise<{ x: number; y: number }> {
  return g.page.evaluate(
    ([x, y]) => {
      const cam = (window.game as unknown as LabWindow).renderer.camera;
      const box = document.querySelector('canvas')!.getBoundingClientRect();
      return { x: box.left + cam.toScreenX(x), y: box.top + cam.toScreenY(y) };
    },
    [x, y] as const,
  );
}

describe('lab-joints', () => {
  let g: GamePage;
  beforeAll(async () => {
    g = await open('lab-joints', { scene: 'pendulum' }, ['Drag']);
  });
  afterAll(async () => {
    await g?.close();
  });

  it('the pendulum swings with the exact large-amplitude period', async () => {
    const m = await g.page.evaluate(() => {
      const w = window.game as unknown as LabWindow & { measure: { period: number; exactPeriod: number; turns: number } };
      w.advance(60 * 12);
      return { ...w.measure };
    });
    expect(m.turns).toBeGreaterThanOrEqual(3);
    expect(Math.abs(m.period / m.exactPeriod - 1)).toBeLessThan(5e-3);
    expect(g.errors).toEqual([]);
  });

  it('dragging the bob with the mouse moves it', async () => {
    await g.page.evaluate(() => {
      const w = window.game as unknown as LabWindow;
      w.reset();
      // Paused while the bob is found and grabbed: a swinging bob moves away between the two.
      w.paused = true;
    });
    const bob = await g.page.evaluate(() => {
      const w = window.game as unknown as LabWindow & { ids(): { bob: number } };
      const b = w.ids().bob;
      return { x: w.world.components.Position.x[b]!, y: w.world.components.Position.y[b]! };
    });
    const from = await screen(g, bob.x, bob.y);
    await g.page.mouse.move(from.x, from.y);
    await g.page.mouse.down();
    const held = await g.page.evaluate(() => (window.game as unknown as { drag: { joint: number } }).drag.joint);
    expect(held).toBeGreaterThan(0);
    await g.page.evaluate(() => {
      (window.game as unknown as LabWindow).paused = false;
    });
    const to = await screen(g, 0, 2.5);
    await g.page.mouse.move(to.x, to.y, { steps: 6 });
    await g.frames(40);
    const moved = await g.page.evaluate(() => {
      const w = window.game as unknown as LabWindow & { ids(): { bob: number } };
      const b = w.ids().bob;
      return { x: w.world.components.Position.x[b]!, y: w.world.components.Position.y[b]! };
    });
    await g.page.mouse.up();
    // Pulled toward (0, 2.5) above the pin: it ends near the top of its circle.
    expect(moved.y).toBeGreaterThan(2.5);
    expect(g.errors).toEqual([]);
  });

  it('every scene builds and steps without errors', async () => {
    for (const scene of ['chain', 'bridge', 'car', 'ragdoll', 'windmill']) {
      const err = await g.page.evaluate((s) => {
        const w = window.game as unknown as LabWindow & { params: { scene: string }; world: { joints: { stats: { maxError: number } } } };
        w.params.scene = s;
        w.reset();
        w.advance(120);
        return w.world.joints.stats.maxError;
      }, scene);
      expect(err).toBeLessThan(0.2);
    }
    expect(g.errors).toEqual([]);
  });
});
