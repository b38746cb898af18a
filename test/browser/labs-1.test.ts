/**
 * The six labs of Part II (projectile with drag, orbits, integrators, spring chain, bungee,
 * pendulum) in headless Chromium. For each lab: the page loads without errors, draws its scene and
 * its chart, lists its controls; its physics agrees with the exact result it shows (measured through
 * window.game after `advance(n)`, which runs the lab's own step n times while the page is paused);
 * and an input (click, drag, key or panel value) changes the state as read through window.game.
 * Plus: a bad URL parameter stops a lab with a message that names it.
 *
 * One page per lab, small and paused while measuring, so the file stays well under a minute.
 */
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { type GamePage, Harness, START_TIMEOUT_MS } from './harness';
import { type ContractRun, checkPageContract, contractOptions } from './page-contract';

/** Fields every lab puts on window.game (see games/lab-*\/main.ts). */
interface LabGame {
  paused: boolean;
  reset(): void;
  stats(): { entities: number; steps: number; fps: number };
  advance(n: number): void;
  params: Record<string, unknown>;
  world: {
    time: number;
    steps: number;
    integrator: string;
    substeps: number;
    components: Record<string, Record<string, Float64Array>>;
  };
  renderer: {
    camera: { toScreenX(x: number): number; toScreenY(y: number): number; toWorldX(x: number): number; toWorldY(y: number): number };
  };
  plot?: { length: number };
}

/**
 * Opens a lab and checks what every lab must show: canvas drawn, chart with data, legend, readout, no errors;
 * with `run`, opened as that run of the page contract (./page-contract), which it checks first.
 */
async function openLab(
  h: Harness,
  folder: string,
  query: Record<string, string | number> = {},
  keys: string[] = [],
  run?: ContractRun,
): Promise<GamePage> {
  const g = await h.openGame(folder, { query, ...(run ? contractOptions(run) : {}) });
  if (run) await checkPageContract(g, folder, run);
  expect(await g.canvasColors()).toBeGreaterThan(16);
  // The chart gets data as the lab runs (a few frames of real time), then its canvas is drawn.
  await g.waitFor(
    () => {
      const w = window.game as unknown as { plot?: { length: number }; plots?: { height: { length: number } } };
      return (w.plot?.length ?? w.plots?.height.length ?? 0) > 12;
    },
    null,
    20_000,
  );
  await g.frames(2);
  expect(await g.canvasColors('.bp-plot canvas')).toBeGreaterThan(4);
  const legend = await g.page.locator('.bp-legend').textContent();
  for (const key of ['P', 'N', 'R', ...keys]) expect(legend).toContain(key);
  expect(await g.page.locator('[data-lab="info"]').count()).toBe(1);
  expect(await g.page.locator('.lil-gui').count()).toBeGreaterThan(0);
  expect(g.errors).toEqual([]);
  return g;
}

/** Pauses the lab and resets it to a fresh world (step 0). */
async function pauseAndReset(g: GamePage): Promise<void> {
  await g.page.evaluate(() => {
    const w = window.game as unknown as LabGame;
    w.paused = true;
    w.reset();
  });
}

/** A lil-gui control by its label. */
const field = (g: GamePage, name: string) => g.page.getByLabel(name, { exact: true });

/** Types `value` into a lil-gui number field and commits it. */
async function setNumber(g: GamePage, name: string, value: number): Promise<void> {
  await field(g, name).fill(String(value));
  await field(g, name).press('Enter');
}

let h: Harness;
beforeAll(async () => {
  h = await Harness.start();
}, START_TIMEOUT_MS);
afterAll(async () => {
  await h?.close();
});

describe('lab-projectile-drag', () => {
  let g: GamePage;
  beforeAll(async () => {
    g = await openLab(h, 'lab-projectile-drag', { law: 'linear', k: 0.5 }, ['Click', 'Space', 'C']);
  });
  afterAll(async () => {
    await g?.close();
  });

  it('follows the exact curves: parabola and linear-drag closed form (rk4), terminal speed under quadratic drag', async () => {
    await pauseAndReset(g);
    const linear = await g.page.evaluate(() => {
      const w = window.game as unknown as LabGame & { flight: { maxDeviation: number; flying: boolean; samples: number } };
      w.advance(90);
      return { ...w.flight };
    });
    expect(linear.samples).toBe(90);
    expect(linear.flying).toBe(true);
    expect(linear.maxDeviation).toBeLessThan(1e-6);
    // No drag: the parabola. Chosen in the panel (relaunches).
    await field(g, 'drag law').selectOption('none');
    const none = await g.page.evaluate(() => {
      const w = window.game as unknown as LabGame & { flight: { maxDeviation: number }; ball(): number };
      w.advance(90);
      return { dev: w.flight.maxDeviation, k: w.world.components.LinearDrag!.k![w.ball() % 2 ** 25] };
    });
    expect(none.k).toBe(0);
    expect(none.dev).toBeLessThan(1e-6);
    // Semi-implicit Euler integrates constant gravity exactly on a body no other force acts on (the
    // drift correction of integrators/semi-implicit-euler.ts), so the parabola holds to rounding...
    await field(g, 'integrator').selectOption('semi-implicit-euler');
    const euler = await g.page.evaluate(() => {
      const w = window.game as unknown as LabGame & { flight: { maxDeviation: number } };
      w.advance(90);
      return { dev: w.flight.maxDeviation, integrator: w.world.integrator };
    });
    expect(euler.integrator).toBe('semi-implicit-euler');
    expect(euler.dev).toBeLessThan(1e-6);
    // ...but it is first order under drag: visibly off the linear-drag closed form (the comparison can fail).
    await field(g, 'drag law').selectOption('linear');
    const eulerDrag = await g.page.evaluate(() => {
      const w = window.game as unknown as LabGame & { flight: { maxDeviation: number } };
      w.advance(90);
      return w.flight.maxDeviation;
    });
    expect(eulerDrag).toBeGreaterThan(0.01);
    // Quadratic drag: the fall speed approaches but never exceeds sqrt(m g / k).
    await field(g, 'integrator').selectOption('rk4');
    await field(g, 'drag law').selectOption('quadratic');
    await setNumber(g, 'quadratic k (kg/m)', 0.1);
    const quad = await g.page.evaluate(() => {
      const w = window.game as unknown as LabGame & {
        flight: { maxFallSpeed: number; flying: boolean; landedTime: number };
        ball(): number;
      };
      for (let i = 0; i < 1200 && w.flight.flying; i++) w.advance(1);
      return { ...w.flight, k: w.world.components.QuadraticDrag!.k![w.ball() % 2 ** 25], m: w.params.mass as number };
    });
    expect(quad.k).toBeCloseTo(0.1, 12);
    expect(quad.flying).toBe(false);
    const vt = Math.sqrt((quad.m * 9.81) / 0.1);
    expect(quad.maxFallSpeed).toBeLessThan(vt);
    expect(quad.maxFallSpeed).toBeGreaterThan(0.8 * vt);
    expect(g.errors).toEqual([]);
  });

  it('a click sets the launch direction and launches', async () => {
    await pauseAndReset(g);
    // Aim level to the right of the launch point: angle about 0, horizontal launch.
    const target = await g.page.evaluate(() => {
      const cam = (window.game as unknown as LabGame).renderer.camera;
      const y0 = (window.game as unknown as LabGame).params.height as number;
      return { x: cam.toScreenX(6), y: cam.toScreenY(y0) };
    });
    const box = await g.canvasBox(); // camera coordinates are the canvas'; the mouse takes the page's
    await g.page.mouse.click(box.x + target.x, box.y + target.y);
    const after = await g.waitFor(() => {
      const w = window.game as unknown as LabGame & { ball(): number };
      if (Math.abs(w.params.angle as number) > 2) return null;
      const e = w.ball();
      return {
        angle: w.params.angle as number,
        vx: w.world.components.Velocity!.x![e % 2 ** 25]!,
        vy: w.world.components.Velocity!.y![e % 2 ** 25]!,
        steps: w.world.steps,
      };
    }, null);
    expect(Math.abs(after.angle)).toBeLessThan(2);
    expect(after.vx).toBeGreaterThan(15);
    expect(after.steps).toBe(0);
    expect(g.errors).toEqual([]);
  });
});

describe('lab-orbits', () => {
  let g: GamePage;
  beforeAll(async () => {
    g = await openLab(h, 'lab-orbits', { planets: 3 }, ['Drag', 'Click', 'S', 'X']);
  });
  afterAll(async () => {
    await g?.close();
  });

  it("conserves the selected orbit's energy and turns in the Kepler period (velocity Verlet); explicit Euler drifts", async () => {
    await pauseAndReset(g);
    await field(g, 'integrator').selectOption('velocity-verlet');
    type Orbit = { eid: number; turns: number; measuredPeriod: number; keplerPeriod: number; maxDrift: number };
    const run = () =>
      g.page.evaluate(() => {
        const w = window.game as unknown as LabGame & { orbit: Orbit; orbiters(): number[]; select(e: number): void };
        w.select(w.orbiters()[0]!);
        w.advance(60 * 8);
        return { ...w.orbit, integrator: w.world.integrator };
      });
    const vv = await run();
    expect(vv.integrator).toBe('velocity-verlet');
    expect(vv.turns).toBeGreaterThanOrEqual(2);
    expect(Math.abs(vv.measuredPeriod - vv.keplerPeriod) / vv.keplerPeriod).toBeLessThan(0.005);
    expect(vv.maxDrift).toBeLessThan(2e-3);
    await field(g, 'integrator').selectOption('explicit-euler');
    const ee = await run();
    expect(ee.maxDrift).toBeGreaterThan(0.05);
    await field(g, 'integrator').selectOption('semi-implicit-euler');
    expect(g.errors).toEqual([]);
  });

  it('a drag launches a body with the drag as velocity, a click selects, the panel sets G M', async () => {
    await pauseAndReset(g);
    const before = await g.stats();
    const pts = await g.page.evaluate(() => {
      const cam = (window.game as unknown as LabGame).renderer.camera;
      return { x0: cam.toScreenX(-4), y0: cam.toScreenY(-4), x1: cam.toScreenX(-4), y1: cam.toScreenY(-1) };
    });
    const m = g.page.mouse;
    const box = await g.canvasBox(); // camera coordinates are the canvas'; the mouse takes the page's
    await m.move(box.x + pts.x0, box.y + pts.y0);
    await m.down();
    await m.move(box.x + pts.x1, box.y + pts.y1, { steps: 6 });
    await m.up();
    const launched = await g.waitFor((n) => {
      const w = window.game as unknown as LabGame & { orbit: { eid: number } };
      if (w.stats().entities !== n + 1) return null;
      const e = w.orbit.eid,
        P = w.world.components.Position!,
        V = w.world.components.Velocity!;
      return { e, x: P.x![e % 2 ** 25]!, y: P.y![e % 2 ** 25]!, vx: V.x![e % 2 ** 25]!, vy: V.y![e % 2 ** 25]! };
    }, before.entities);
    expect(launched.x).toBeCloseTo(-4, 0);
    expect(launched.y).toBeCloseTo(-4, 0);
    expect(Math.abs(launched.vx)).toBeLessThan(0.3);
    expect(launched.vy).toBeGreaterThan(2.5);
    expect(launched.vy).toBeLessThan(3.5);
    // Click next to planet 0 selects it.
    const p0 = await g.page.evaluate(() => {
      const w = window.game as unknown as LabGame & { orbiters(): number[] };
      const e = w.orbiters()[0]!,
        cam = w.renderer.camera,
        P = w.world.components.Position!;
      return { e, x: cam.toScreenX(P.x![e % 2 ** 25]!) + 3, y: cam.toScreenY(P.y![e % 2 ** 25]!) + 3 };
    });
    await g.page.mouse.click(box.x + p0.x, box.y + p0.y);
    await g.waitFor((e) => (window.game as unknown as { orbit: { eid: number } }).orbit.eid === e, p0.e);
    await setNumber(g, 'G M (m³/s²)', 80);
    const mass = await g.page.evaluate(() => {
      const w = window.game as unknown as LabGame & { orbiters(): number[] };
      const A = w.world.components.Attractor!;
      let found = 0;
      for (let e = 1; e < A.mass!.length; e++) if (A.mass![e % 2 ** 25]! > 0) found = A.mass![e % 2 ** 25]!;
      return found;
    });
    expect(mass).toBe(80);
    expect(g.errors).toEqual([]);
  });
});

describe('lab-integrators', () => {
  let g: GamePage;
  beforeAll(async () => {
    g = await openLab(h, 'lab-integrators', {}, ['+'], 'desktop');
  });
  afterAll(async () => {
    await g?.close();
  });

  it('runs the seven schemes from one state; after an orbit their energy errors rank by order', async () => {
    await pauseAndReset(g);
    type Run = { name: string; error: number; diverged: boolean; time: number; steps: number; x: number; y: number };
    const start = await g.page.evaluate(() => (window.game as unknown as { runs(): Run[] }).runs());
    expect(start.map((r) => r.name)).toEqual([
      'explicit-euler',
      'semi-implicit-euler',
      'implicit-euler',
      'rk2',
      'rk4',
      'position-verlet',
      'velocity-verlet',
    ]);
    for (const r of start) {
      expect(r.x).toBe(start[0]!.x);
      expect(r.y).toBe(start[0]!.y);
    }
    const runs = await g.page.evaluate(() => {
      const w = window.game as unknown as LabGame & { runs(): Run[] };
      w.advance(240); // one period (4 s) at dt = 1/60 s, e = 0.5
      return Object.fromEntries(w.runs().map((r) => [r.name, r]));
    });
    for (const r of Object.values(runs)) if (!r.diverged) expect(r.steps).toBe(240);
    expect(runs.rk4!.error).toBeLessThan(1e-4);
    expect(runs.rk4!.error).toBeLessThan(runs.rk2!.error);
    expect(runs['velocity-verlet']!.error).toBeLessThan(runs['explicit-euler']!.error);
    expect(runs['semi-implicit-euler']!.error).toBeLessThan(runs['explicit-euler']!.error);
    expect(runs['explicit-euler']!.error).toBeGreaterThan(0.05);
    expect(runs['implicit-euler']!.diverged || runs['implicit-euler']!.error > 0.01).toBe(true);
    expect(g.errors).toEqual([]);
  });

  it('the panel rebuilds with a new eccentricity; + raises the speed-up', async () => {
    await setNumber(g, 'eccentricity', 0.2);
    const x = await g.waitFor(() => {
      const runs = (window.game as unknown as { runs(): Array<{ x: number; steps: number }> }).runs();
      return runs[0]!.steps === 0 ? runs.map((r) => r.x) : null;
    }, null);
    for (const v of x) expect(v).toBeCloseTo(4 * (1 - 0.2), 12);
    const s0 = await g.page.evaluate(() => (window.game as unknown as LabGame).params.speedUp as number);
    await g.press('+');
    expect(await g.page.evaluate(() => (window.game as unknown as LabGame).params.speedUp)).toBe(s0 + 1);
    expect(g.errors).toEqual([]);
  });
});

describe('lab-spring-chain', () => {
  let g: GamePage;
  beforeAll(async () => {
    g = await openLab(h, 'lab-spring-chain', { links: 5 }, ['Drag']);
  });
  afterAll(async () => {
    await g?.close();
  });

  it('keeps its total energy without damping and loses it with damping', async () => {
    await pauseAndReset(g);
    type Energy = { total: number; reference: number; maxDrift: number };
    const free = await g.page.evaluate(() => {
      const w = window.game as unknown as LabGame & { energy: Energy };
      w.advance(300);
      return { ...w.energy };
    });
    expect(free.maxDrift).toBeLessThan(0.005 * Math.abs(free.reference));
    await setNumber(g, 'damping (N s/m)', 1);
    const damped = await g.page.evaluate(() => {
      const w = window.game as unknown as LabGame & { energy: Energy; springs(): number[] };
      const d = w.world.components.Spring!.damping![w.springs()[0]!];
      w.advance(300);
      return { ...w.energy, d };
    });
    expect(damped.d).toBe(1);
    expect(damped.total).toBeLessThan(damped.reference - 0.1 * Math.abs(damped.reference));
    await setNumber(g, 'damping (N s/m)', 0);
    expect(g.errors).toEqual([]);
  });

  it('dragging a ball pulls it on a mouse spring that follows the pointer and goes on release', async () => {
    await pauseAndReset(g);
    await g.frames(2);
    const ball = await g.page.evaluate(() =>
      (window.game as unknown as { ballOnScreen(i: number): { x: number; y: number } }).ballOnScreen(2),
    );
    const m = g.page.mouse;
    const box = await g.canvasBox(); // ballOnScreen is in canvas coordinates; the mouse takes the page's
    await m.move(box.x + ball.x, box.y + ball.y);
    await m.down();
    await m.move(box.x + ball.x + 60, box.y + ball.y + 20, { steps: 4 });
    const held = await g.page.evaluate(
      ([px, py]) => {
        const w = window.game as unknown as LabGame & { grab: { ball: number; spring: number }; balls(): number[] };
        const S = w.world.components.Spring!,
          cam = w.renderer.camera;
        return {
          grabbed: w.grab.ball === w.balls()[2],
          spring: w.grab.spring,
          ax: S.anchorX![w.grab.spring % 2 ** 25]!,
          ay: S.anchorY![w.grab.spring % 2 ** 25]!,
          px: cam.toWorldX(px!),
          py: cam.toWorldY(py!),
        };
      },
      [ball.x + 60, ball.y + 20],
    );
    expect(held.grabbed).toBe(true);
    expect(held.spring).toBeGreaterThan(0);
    expect(held.ax).toBeCloseTo(held.px, 6);
    expect(held.ay).toBeCloseTo(held.py, 6);
    // While held, the ball is pulled toward the pointer.
    const moved = await g.page.evaluate(() => {
      const w = window.game as unknown as LabGame & { grab: { ball: number; spring: number } };
      const P = w.world.components.Position!,
        S = w.world.components.Spring!;
      const e = w.grab.ball,
        s = w.grab.spring;
      const d0 = Math.hypot(P.x![e % 2 ** 25]! - S.anchorX![s % 2 ** 25]!, P.y![e % 2 ** 25]! - S.anchorY![s % 2 ** 25]!);
      w.advance(60);
      return { d0, d1: Math.hypot(P.x![e % 2 ** 25]! - S.anchorX![s % 2 ** 25]!, P.y![e % 2 ** 25]! - S.anchorY![s % 2 ** 25]!) };
    });
    expect(moved.d1).toBeLessThan(moved.d0);
    await m.up();
    const after = await g.page.evaluate(() => {
      const w = window.game as unknown as LabGame & { grab: { spring: number } };
      return { spring: w.grab.spring, entities: w.stats().entities };
    });
    expect(after.spring).toBe(0);
    expect(after.entities).toBe(10); // 5 balls + 5 springs: the mouse spring is gone
    expect(g.errors).toEqual([]);
  });
});

describe('lab-bungee', () => {
  let g: GamePage;
  beforeAll(async () => {
    g = await openLab(h, 'lab-bungee', {}, ['Space', 'Click'], 'desktop');
  });
  afterAll(async () => {
    await g?.close();
  });

  it('falls freely along the exact curve and bottoms out where energy predicts', async () => {
    await pauseAndReset(g);
    const jump = await g.page.evaluate(() => {
      const w = window.game as unknown as LabGame & {
        jump: { freeFallError: number; lowest: number; predictedLowest: number; tautTime: number; freeFallTime: number };
      };
      w.advance(60 * 4);
      return { ...w.jump };
    });
    expect(jump.freeFallError).toBeLessThan(0.01);
    expect(Math.abs(jump.tautTime - jump.freeFallTime)).toBeLessThan(1 / 60);
    expect(Math.abs(jump.lowest - jump.predictedLowest)).toBeLessThan(0.05);
    expect(g.errors).toEqual([]);
  });

  it('the panel sets the rope; Space jumps again', async () => {
    await setNumber(g, 'rope length L (m)', 20);
    const rope = await g.waitFor(() => {
      const w = window.game as unknown as LabGame & { ids(): { rope: number } };
      const L = w.world.components.Spring!.restLength![w.ids().rope % 2 ** 25]!;
      return L === 20 ? { L, oneSided: w.world.components.Spring!.oneSided![w.ids().rope % 2 ** 25]! } : null;
    }, null);
    expect(rope.oneSided).toBe(1);
    await g.page.evaluate(() => (window.game as unknown as LabGame).advance(30));
    expect((await g.stats()).steps).toBeGreaterThanOrEqual(30);
    await g.press('Space');
    expect((await g.stats()).steps).toBe(0);
    expect(g.errors).toEqual([]);
  });
});

describe('lab-pendulum', () => {
  let g: GamePage;
  beforeAll(async () => {
    g = await openLab(h, 'lab-pendulum', { amplitude: 30 }, ['Click']);
  });
  afterAll(async () => {
    await g?.close();
  });

  it('swings with the exact large-amplitude period, longer than 2π√(L/g)', async () => {
    await pauseAndReset(g);
    const swing = await g.page.evaluate(() => {
      const w = window.game as unknown as LabGame & {
        swing: { measuredPeriod: number; exactPeriod: number; smallAnglePeriod: number; crossings: number; maxStretch: number };
      };
      w.advance(60 * 7);
      return { ...w.swing };
    });
    expect(swing.crossings).toBeGreaterThanOrEqual(4);
    expect(Math.abs(swing.measuredPeriod - swing.exactPeriod) / swing.exactPeriod).toBeLessThan(1e-3);
    // At 30 degrees the true period is 1.7 % longer than the small-angle one.
    expect(swing.measuredPeriod / swing.smallAnglePeriod).toBeGreaterThan(1.01);
    expect(swing.maxStretch).toBeLessThan(1e-3);
    expect(g.errors).toEqual([]);
  });

  it('a click places the bob; N steps once', async () => {
    await pauseAndReset(g);
    const target = await g.page.evaluate(() => {
      const cam = (window.game as unknown as LabGame).renderer.camera;
      return { x: cam.toScreenX(1), y: cam.toScreenY(-1) };
    });
    const box = await g.canvasBox(); // camera coordinates are the canvas'; the mouse takes the page's
    await g.page.mouse.click(box.x + target.x, box.y + target.y);
    const placed = await g.waitFor(() => {
      const w = window.game as unknown as LabGame & { ids(): { bob: number } };
      if (Math.abs((w.params.amplitude as number) - 45) > 1) return null;
      const P = w.world.components.Position!,
        b = w.ids().bob;
      return { length: w.params.length as number, x: P.x![b % 2 ** 25]!, y: P.y![b % 2 ** 25]!, steps: w.world.steps };
    }, null);
    expect(placed.length).toBeCloseTo(Math.SQRT2, 1);
    expect(placed.x).toBeCloseTo(1, 1);
    expect(placed.y).toBeCloseTo(-1, 1);
    expect(placed.steps).toBe(0);
    await g.press('n');
    expect((await g.stats()).steps).toBe(1);
    expect(g.errors).toEqual([]);
  });

  it('a bad URL parameter stops the lab with a message naming it', async () => {
    const bad = await h.openGame('lab-pendulum', { query: { length: 'long' }, waitReady: false });
    const text = await bad.page.locator('[data-lab="error"]').textContent();
    expect(text).toContain('length');
    expect(text).toContain('"long"');
    await expect.poll(() => bad.errors.some((e) => e.includes('URL parameter length'))).toBe(true);
    await bad.close();
  });
});
