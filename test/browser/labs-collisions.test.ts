/**
 * The collision labs (lab-newtons-cradle, lab-molecules) in headless Chromium: each loads without
 * errors, draws, lists its controls; its physics keeps what it should (the cradle sends one ball out
 * and keeps its energy; the gas keeps its kinetic energy); and an input changes it as read through
 * window.game (a drag lifts a ball; a click heats the gas).
 */
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { type GamePage, Harness, START_TIMEOUT_MS } from './harness';
import { type ContractRun, checkPageContract, contractOptions } from './page-contract';

interface Cam {
  toScreenX(x: number): number;
  toScreenY(y: number): number;
}
interface LabWindow {
  paused: boolean;
  reset(): void;
  advance(n: number): void;
  renderer: { camera: Cam };
  world: { components: { Position: { x: Float64Array; y: Float64Array } } };
}

let h: Harness;
beforeAll(async () => {
  h = await Harness.start();
}, START_TIMEOUT_MS);
afterAll(async () => {
  await h?.close();
});

/** Opens a lab, checks the common furniture, pauses it on a fresh world. */
/** Opens a lab and checks it is drawn, its legend and panel; with `run`, as that run of the page contract, which it checks first. */
async function open(folder: string, keys: string[], run?: ContractRun): Promise<GamePage> {
  const g = await h.openGame(folder, run ? contractOptions(run) : {});
  if (run) await checkPageContract(g, folder, run);
  expect(await g.canvasColors()).toBeGreaterThan(8);
  const legend = await g.page.locator('.bp-legend').textContent();
  for (const key of ['P', 'N', 'R', ...keys]) expect(legend).toContain(key);
  expect(await g.page.locator('.lil-gui').count()).toBeGreaterThan(0);
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

describe('lab-newtons-cradle', () => {
  let g: GamePage;
  beforeAll(async () => {
    g = await open('lab-newtons-cradle', ['Drag'], 'desktop');
  });
  afterAll(async () => {
    await g?.close();
  });

  /**
   * One ball lifted by 30 degrees on 1 m strings: after the impacts the last ball swings out to
   * about 30 degrees (it gets the first ball's whole speed, v = sqrt(2 g L (1 - cos 30)) = 1.62 m/s)
   * and the others stay within 2 degrees; energy within 1 % (e = 1, stiff strings).
   */
  it('sends the last ball out as high as the first was lifted and keeps the energy', async () => {
    const m = await g.page.evaluate(() => {
      const w = window.game as unknown as LabWindow & { balls(): number[]; measure: { energy: number; energy0: number } };
      const P = w.world.components.Position;
      const balls = w.balls().map((b) => b % 2 ** 25);
      const x0 = balls.map((s) => P.x[s]!);
      const most = balls.map(() => 0);
      for (let i = 0; i < 90; i++) {
        w.advance(1);
        balls.forEach((s, k) => {
          most[k] = Math.max(most[k]!, P.x[s]! - x0[k]!);
        });
      }
      return { most, ratio: w.measure.energy / w.measure.energy0 };
    });
    const last = m.most[m.most.length - 1]!;
    expect((Math.asin(last) * 180) / Math.PI).toBeGreaterThan(28);
    for (let k = 1; k < m.most.length - 1; k++) expect(m.most[k]!).toBeLessThan(Math.sin((2 * Math.PI) / 180));
    expect(Math.abs(m.ratio - 1)).toBeLessThan(0.01);
    expect(g.errors).toEqual([]);
  });

  it('dragging a ball with the mouse lifts it', async () => {
    await g.page.evaluate(() => {
      const w = window.game as unknown as LabWindow;
      w.reset();
    });
    const start = await g.page.evaluate(() => {
      const w = window.game as unknown as LabWindow & { balls(): number[] };
      const s = w.balls()[1]! % 2 ** 25;
      return { s, x: w.world.components.Position.x[s]!, y: w.world.components.Position.y[s]! };
    });
    const from = await screen(g, start.x, start.y);
    const to = await screen(g, start.x - 0.5, start.y + 0.3);
    await g.page.mouse.move(from.x, from.y);
    await g.page.mouse.down();
    await g.page.mouse.move(to.x, to.y, { steps: 6 });
    const lifted = await g.page.evaluate((s) => (window.game as unknown as LabWindow).world.components.Position.x[s]!, start.s);
    await g.page.mouse.up();
    expect(lifted).toBeLessThan(start.x - 0.2);
    // Let go and running, it swings back into the row: the hit clicks (a ball contact's begin event,
    // a metal knock; the press started the sound).
    await g.page.evaluate(() => {
      (window.game as unknown as LabWindow).paused = false;
    });
    await g.waitFor(() => {
      const s = (window.game as unknown as { sound: { running: boolean; played: number } }).sound;
      return s.running && s.played >= 1;
    }, null);
    await g.page.evaluate(() => {
      (window.game as unknown as LabWindow).paused = true;
    });
    expect(g.errors).toEqual([]);
  });
  /**
   * Two balls lifted through real pointer input, the world running: press on the second ball, drag it
   * left and up to a string angle a (it takes the first ball with it), hold still for 10 frames, let
   * go; at a = 10, 30, 50 and 70 degrees (with exactly touching balls the solver misses the chain at
   * some angles, 10 among them: see HANG_GAP in the scene). While held the row waits at rest in the
   * lifted pose (the balls do not fall and strike the row before the release). After the release the
   * two far balls leave with the entering speed of the lifted pair, v = sqrt(2 g L (1 - cos a))
   * (energy of the drop; equal masses, e = 1: k balls in, k balls out), within 3 %: the speed is
   * sampled every step and peaks at the bottom, where the far balls leave, so sampling costs under
   * 0.1 %, and the strings' soft joints keep energy within 1 %. The middle ball never leaves (peak
   * under 3 % of v) and the lifted pair stops (under 3 % of v once the far balls are out).
   */
  it('a two-ball lift with the mouse sends two balls out on the far side at the entering speed', async () => {
    const ball = (i: number): Promise<{ x: number; y: number }> =>
      g.page.evaluate((i) => {
        const w = window.game as unknown as LabWindow & { balls(): number[] };
        const s = w.balls()[i]! % 2 ** 25,
          P = w.world.components.Position;
        return { x: P.x[s]!, y: P.y[s]! };
      }, i);
    const L = 1,
      gravity = 9.81;
    for (const deg of [10, 30, 50, 70]) {
      await g.page.evaluate(() => {
        const w = window.game as unknown as LabWindow;
        w.paused = false;
        w.reset();
      });
      const start = await ball(1);
      const a = (deg * Math.PI) / 180;
      const from = await screen(g, start.x, start.y);
      const to = await screen(g, start.x - L * Math.sin(a), -L * Math.cos(a));
      await g.page.mouse.move(from.x, from.y);
      await g.page.mouse.down();
      await g.page.mouse.move(to.x, to.y, { steps: 6 });
      const lifted = [await ball(0), await ball(1)];
      await g.frames(10);
      const still = [await ball(0), await ball(1)];
      const held = await g.page.evaluate(() => {
        const w = window.game as unknown as LabWindow & { held(): number };
        return { held: w.held(), paused: w.paused };
      });
      expect(held).toEqual({ held: 1, paused: false });
      // Lifted together (touching, same string angle, within a degree of the pointer) and held still while the world runs.
      expect(Math.abs(Math.acos(-lifted[1]!.y / L) - a)).toBeLessThan(Math.PI / 180);
      expect(Math.abs(lifted[1]!.y - lifted[0]!.y)).toBeLessThan(1e-9);
      for (let k = 0; k < 2; k++) expect(Math.hypot(still[k]!.x - lifted[k]!.x, still[k]!.y - lifted[k]!.y)).toBeLessThan(1e-9);
      // Pause, then let go, so the steps after the release are counted from the release.
      await g.page.evaluate(() => {
        (window.game as unknown as LabWindow).paused = true;
      });
      await g.page.mouse.up();
      const m = await g.page.evaluate(() => {
        const w = window.game as unknown as LabWindow & {
          balls(): number[];
          held(): number;
          world: { components: { Velocity: { x: Float64Array } } };
        };
        const V = w.world.components.Velocity;
        const balls = w.balls().map((b) => b % 2 ** 25);
        const peak = balls.map(() => 0);
        for (let i = 0; i < 50; i++) {
          w.advance(1);
          balls.forEach((s, k) => {
            peak[k] = Math.max(peak[k]!, Math.abs(V.x[s]!));
          });
        }
        return { held: w.held(), peak, after: balls.map((s) => V.x[s]!) };
      });
      expect(m.held).toBe(-1);
      const v = Math.sqrt(2 * gravity * (L + still[1]!.y)); // anchors at y = 0: L (1 - cos a) = L + y
      const n = m.peak.length,
        what = `lift ${deg} deg: peaks ${m.peak.map((p) => (p / v).toFixed(3)).join(' ')} of v = ${v.toFixed(3)} m/s`;
      for (const k of [n - 2, n - 1]) expect(Math.abs(m.peak[k]! / v - 1), what).toBeLessThan(0.03);
      for (let k = 2; k < n - 2; k++) expect(m.peak[k]!, what).toBeLessThan(0.03 * v);
      for (const k of [0, 1]) expect(Math.abs(m.after[k]!), what).toBeLessThan(0.03 * v);
    }
    expect(g.errors).toEqual([]);
  });
});

describe('lab-molecules', () => {
  let g: GamePage;
  beforeAll(async () => {
    g = await open('lab-molecules', ['Click'], 'desktop');
  });
  afterAll(async () => {
    await g?.close();
  });

  /** Perfectly elastic discs: kinetic energy constant within 1 % over 600 steps (10 s). */
  it('keeps the kinetic energy of the gas', async () => {
    const ratio = await g.page.evaluate(() => {
      const w = window.game as unknown as LabWindow & { gas: { energyRatio: number } };
      w.advance(600);
      return w.gas.energyRatio;
    });
    expect(Math.abs(ratio - 1)).toBeLessThan(0.01);
    expect(g.errors).toEqual([]);
  });

  it('a click in the box heats the gas', async () => {
    await g.page.evaluate(() => {
      const w = window.game as unknown as LabWindow;
      w.reset();
    });
    const before = await g.page.evaluate(() => (window.game as unknown as { gas: { kT: number } }).gas.kT);
    const box = await g.page.evaluate(() => (window.game as unknown as { box(): { width: number; height: number } }).box());
    const at = await screen(g, box.width / 2, box.height / 2);
    await g.page.mouse.click(at.x, at.y);
    const after = await g.page.evaluate(() => (window.game as unknown as { gas: { kT: number } }).gas.kT);
    expect(after).toBeGreaterThan(before * 1.02);
    expect(g.errors).toEqual([]);
  });
});
