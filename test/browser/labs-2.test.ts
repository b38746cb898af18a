/**
 * The labs of Part II in headless Chromium: floating, balloon and parachute, electric field,
 * cyclotron, rocket. For each: it loads with no console or page errors, draws a canvas that is not
 * blank, fills its chart, reacts to an input (click, key), and its physics matches the exact value
 * the lab plots against (each lab exposes `advance(n)` on window.game, which runs n steps at once, so
 * these checks do not depend on how fast software WebGL draws). One page per lab, small viewports.
 * A bad URL parameter is reported on the page.
 */

import { createPhysicsWorld, slotOf, step } from '@bitphysics/physics';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { equilibriumAltitude, fallSpeedFromRest, resolveOptions } from '../../games/lab-balloon-parachute/scene';
import { createOrbitMeter, meterSample } from '../../games/lab-cyclotron/scene';
import { circularSegmentArea, equilibriumDepth } from '../../games/lab-floating/scene';
import { applyControls, buildRocket, rocketWorldOptions, uniformGravityModel } from '../../games/lab-rocket/scene';
import { type GamePage, Harness, START_TIMEOUT_MS } from './harness';
import { checkPageContract, contractOptions } from './page-contract';

describe('exact curves of the labs (Node)', () => {
  it('circular segment: half and whole disc; the equilibrium draft balances the areas', () => {
    expect(circularSegmentArea(2, 2)).toBeCloseTo(2 * Math.PI, 12);
    expect(circularSegmentArea(2, 4)).toBeCloseTo(4 * Math.PI, 12);
    expect(circularSegmentArea(2, -1)).toBe(0);
    const d = equilibriumDepth('ball', 0.5, 300, 1000);
    expect(circularSegmentArea(0.5, d)).toBeCloseTo(0.3 * Math.PI * 0.25, 10);
    expect(equilibriumDepth('ball', 0.5, 500, 1000)).toBeCloseTo(0.5, 10);
    expect(equilibriumDepth('box', 0.4, 250, 1000)).toBeCloseTo(0.2, 12);
    expect(equilibriumDepth('ball', 0.5, 1200, 1000)).toBeNaN();
  });

  it("balloon equilibrium: the disc-averaged exponential atmosphere lifts exactly the balloon's mass there", () => {
    const p = resolveOptions({ balloonRadius: 2, scaleHeight: 40 });
    const y = equilibriumAltitude(p);
    // Midpoint quadrature of rho0 exp(-(y + eta) / H) over the disc of radius r.
    const n = 2000,
      r = p.balloonRadius;
    let lift = 0;
    for (let i = 0; i < n; i++) {
      const eta = -r + ((i + 0.5) * 2 * r) / n;
      lift += 1.225 * Math.exp(-(y + eta) / p.scaleHeight) * 2 * Math.sqrt(r * r - eta * eta) * ((2 * r) / n);
    }
    const mass = 0.1786 * Math.PI * r * r + p.envelopeMass;
    expect(lift / mass).toBeCloseTo(1, 5);
  });

  it('free fall with quadratic drag: tanh law starts at 0 with slope g and tends to v_t', () => {
    expect(fallSpeedFromRest(0, 50)).toBe(0);
    expect(fallSpeedFromRest(1e-6, 50) / 1e-6).toBeCloseTo(9.81, 6);
    expect(fallSpeedFromRest(100, 50)).toBeCloseTo(50, 9);
  });

  it('orbit meter: a sampled circle gives its radius and period', () => {
    const m = createOrbitMeter();
    const w = (2 * Math.PI) / 5,
      R = 1.5,
      h = 1 / 240;
    for (let t = 0; t < 16; t += h) meterSample(m, t, R * Math.sin(-w * t), -R * w * Math.cos(w * t));
    expect(m.revolutions).toBeGreaterThanOrEqual(2);
    expect(m.period).toBeCloseTo(5, 6);
    expect(m.radius).toBeCloseTo(R, 4);
  });

  it('rocket: the uniform-gravity model matches the physics while gravity is still nearly uniform', () => {
    // A vertical burn on the toy planet over the first quarter second: the rocket rises 7 cm, g changes
    // by 1.4e-4 of itself, and the model's speed and height (variable mass, thrust, gravity at the pad)
    // agree with the physics to that order.
    const world = createPhysicsWorld(rocketWorldOptions({ planet: 'toy', drag: false }));
    const h = buildRocket(world, { planet: 'toy', drag: false });
    const out = new Float64Array(2);
    for (let i = 0; i < 15; i++) {
      applyControls(world, h);
      step(world);
    }
    uniformGravityModel(world, h, out);
    const P = world.components.Position,
      V = world.components.Velocity;
    const height = P.y[h.rocket]! - 1000 - 1.5;
    expect(Math.abs(V.y[h.rocket]! - out[0]!) / out[0]!).toBeLessThan(5e-4);
    expect(Math.abs(height - out[1]!) / out[1]!).toBeLessThan(5e-4);
  });
});

/** The parts of window.game every lab of this file exposes. */
interface LabGame {
  paused: boolean;
  plot: { length: number; last(i: number): number };
  advance(n: number): void;
  reset(): void;
  world: { time: number; steps: number };
}

function lab<T>(g: GamePage, fn: (game: LabGame & T) => unknown): Promise<unknown> {
  return g.page.evaluate(`(${fn.toString()})(window.game)`);
}

/** Checks the page contract, a drawn canvas, a chart with data and no errors. */
async function basics(g: GamePage): Promise<void> {
  expect(await g.canvasColors()).toBeGreaterThan(16);
  await g.waitFor(() => ((window.game as unknown as LabGame).plot.length > 0 ? true : null), null, 20_000);
  expect(await g.page.locator('.bp-plot canvas').count()).toBeGreaterThan(0);
  expect(await g.page.locator('.bp-legend').textContent()).toMatch(/P[\s\S]*N[\s\S]*R/);
  expect(g.errors).toEqual([]);
}

describe('labs of Part II', () => {
  let h: Harness;
  beforeAll(async () => {
    h = await Harness.start();
  }, START_TIMEOUT_MS);
  afterAll(async () => {
    await h?.close();
  });

  it('floating: a click drops a ball, E puts the tracked body at its exact equilibrium and it stays there', async () => {
    const g = await h.openGame('lab-floating', contractOptions('desktop'));
    await checkPageContract(g, 'lab-floating', 'desktop');
    await basics(g);
    const before = (await lab<{ handles(): { balls: number[] } }>(g, (game) => game.handles().balls.length)) as number;
    // Above the water near the right wall, away from the tracked (medium) ball.
    await g.clickWorld(12.5, 8);
    await g.waitFor(
      (n) => ((window.game as unknown as { handles(): { balls: number[] } }).handles().balls.length === n + 1 ? true : null),
      before,
    );
    // E: the tracked (medium) body at rest at the circular-segment equilibrium; upthrust balances weight, so it stays.
    await g.page.evaluate(() => {
      (window.game as unknown as LabGame).paused = true;
    });
    await g.press('e');
    const r = (await lab<{ draft(k: string): number; equilibrium(k: string): number }>(g, (game) => {
      const start = game.draft('medium');
      game.advance(300);
      return { start, end: game.draft('medium'), exact: game.equilibrium('medium'), sinks: game.equilibrium('heavy') };
    })) as { start: number; end: number; exact: number; sinks: number };
    expect(r.start).toBeCloseTo(r.exact, 9);
    expect(Math.abs(r.end - r.exact)).toBeLessThan(2e-3);
    expect(Number.isFinite(r.sinks)).toBe(true); // 920 < 1000: the "heavy" ball floats too
    // The light and heavy balls held up by the divider's top, 1.4 m apart: their density labels and the
    // divider's would meet there; none of the five labels overlaps another (canvas px, touching allowed).
    const slots = (await lab<{ handles(): { light: number; heavy: number } }>(g, (game) => [
      game.handles().light,
      game.handles().heavy,
    ])) as number[];
    await g.page.evaluate(([light, heavy]) => {
      const C = (window.game as unknown as { world: { components: Record<string, { x: Float64Array; y: Float64Array }> } }).world
        .components;
      for (const [s, x] of [
        [light, 3.9],
        [heavy, 5.3],
      ] as const)
        for (const P of [C.Position!, C.PreviousPosition!]) {
          P.x[s] = x;
          P.y[s] = 8.4;
        }
    }, slots.map(slotOf));
    await g.frames(2);
    const labels = (await lab<{ labelBoxes(): [string, number, number, number, number][] }>(g, (game) => game.labelBoxes())) as [
      string,
      number,
      number,
      number,
      number,
    ][];
    expect(labels.map((b) => b[0])).toEqual(['divider', 'light', 'medium', 'heavy', 'box']);
    for (const [i, a] of labels.entries())
      for (const b of labels.slice(i + 1)) {
        const overlap = Math.min(a[3], b[3]) - Math.max(a[1], b[1]) > 0 && Math.min(a[4], b[4]) - Math.max(a[2], b[2]) > 0;
        expect(
          overlap,
          `${a[0]} label at ${a.slice(1).map((v) => Math.round(v as number))} overlaps ${b[0]} at ${b.slice(1).map((v) => Math.round(v as number))}`,
        ).toBe(false);
      }
    expect(g.errors).toEqual([]);
    await g.close();
  });

  it('parachute: free fall follows v_t tanh(g t / v_t), O opens the chute and the speed settles at sqrt(m g / k_open)', async () => {
    const g = await h.openGame('lab-balloon-parachute', { query: { autoOpen: 0 } });
    await basics(g);
    const r = (await lab<{ descentSpeed(): number; terminalSpeeds(): [number, number]; handles(): { openedAt: number } }>(g, (game) => {
      game.paused = true;
      game.reset();
      game.advance(60 * 12);
      const t = game.world.time;
      const [vt1, vt2] = game.terminalSpeeds();
      return { t, v: game.descentSpeed(), vt1, vt2, opened: game.handles().openedAt };
    })) as { t: number; v: number; vt1: number; vt2: number; opened: number };
    // Exact fall from rest with quadratic drag in still air (Taylor eq. 2.57).
    const exact = r.vt1 * Math.tanh((9.81 * r.t) / r.vt1);
    expect(Math.abs(r.v - exact) / exact).toBeLessThan(2e-3);
    expect(Number.isNaN(r.opened)).toBe(true);
    await g.press('o');
    const after = (await lab<{ descentSpeed(): number; handles(): { openedAt: number } }>(g, (game) => {
      const opened = game.handles().openedAt;
      game.advance(60 * 10);
      return { opened, v: game.descentSpeed() };
    })) as { opened: number; v: number };
    expect(Number.isFinite(after.opened)).toBe(true);
    expect(Math.abs(after.v - r.vt2) / r.vt2).toBeLessThan(1e-3);
    expect(g.errors).toEqual([]);
    await g.close();
  });

  it('balloon: rises to the exact equilibrium height of the layered atmosphere; T ties the tether', async () => {
    const g = await h.openGame('lab-balloon-parachute', { query: { scene: 'balloon' } });
    await basics(g);
    const r = (await lab<{ height(): number; equilibriumAltitude(): number }>(g, (game) => {
      game.paused = true;
      game.reset();
      game.advance(60 * 150);
      return { y: game.height(), exact: game.equilibriumAltitude() };
    })) as { y: number; exact: number };
    expect(r.exact).toBeGreaterThan(50);
    expect(Math.abs(r.y - r.exact) / r.exact).toBeLessThan(1e-2);
    await g.press('t');
    expect(await lab<{ handles(): { tether: number } }>(g, (game) => game.handles().tether)).toBeGreaterThan(0);
    expect(g.errors).toEqual([]);
    await g.close();
  });

  it('electric field: click adds +, shift-click adds -, F hides the field lines; the test charge keeps its energy', async () => {
    const g = await h.openGame('lab-electric-field', contractOptions('desktop'));
    await checkPageContract(g, 'lab-electric-field', 'desktop');
    await basics(g);
    type Charges = { charges(): [number, number, number][]; fieldLineCount(): number };
    const count = async () => (await lab<Charges>(g, (game) => game.charges())) as [number, number, number][];
    expect((await count()).length).toBe(2);
    await g.clickWorld(-5, 3);
    await g.waitFor(() => ((window.game as unknown as Charges).charges().length === 3 ? true : null), null);
    await g.page.keyboard.down('Shift');
    await g.clickWorld(-5, -3);
    await g.page.keyboard.up('Shift');
    await g.waitFor(() => ((window.game as unknown as Charges).charges().length === 4 ? true : null), null);
    const signs = (await count()).map((c) => Math.sign(c[2]));
    expect(signs.slice(2)).toEqual([1, -1]);
    await g.frames(2);
    expect(await lab<Charges>(g, (game) => game.fieldLineCount())).toBeGreaterThan(8);
    await g.press('f');
    expect(await lab<Charges>(g, (game) => game.fieldLineCount())).toBe(0);
    const e = (await lab<{ energy(): { measured: number; exact: number } }>(g, (game) => {
      game.paused = true;
      game.reset();
      game.advance(60 * 10);
      return game.energy();
    })) as { measured: number; exact: number };
    expect(Math.abs(e.measured - e.exact) / Math.abs(e.exact)).toBeLessThan(5e-3);
    expect(g.errors).toEqual([]);
    await g.close();
  });

  it('cyclotron: measured radius and period match m v / (|q| B) and 2 pi m / (|q| B); F flips the field', async () => {
    const g = await h.openGame('lab-cyclotron', { query: { E: 0 } });
    await basics(g);
    type Cyc = {
      measurement(): { radius: number; period: number; revolutions: number; exactRadius: number; exactPeriod: number };
      field(): number;
    };
    const run = async () =>
      (await lab<Cyc>(g, (game) => {
        game.advance(60 * 16);
        return game.measurement();
      })) as ReturnType<Cyc['measurement']>;
    await g.page.evaluate(() => {
      const game = window.game as unknown as LabGame;
      game.paused = true;
      game.reset();
    });
    const m = await run();
    expect(m.exactRadius).toBeCloseTo(3, 12); // 1 g, 3 m/s, 1 mC, 1 T
    expect(m.revolutions).toBeGreaterThanOrEqual(1);
    expect(Math.abs(m.radius - m.exactRadius) / m.exactRadius).toBeLessThan(1e-3);
    expect(Math.abs(m.period - m.exactPeriod) / m.exactPeriod).toBeLessThan(1e-3);
    const b0 = (await lab<Cyc>(g, (game) => game.field())) as number;
    await g.press('f');
    expect(await lab<Cyc>(g, (game) => game.field())).toBe(-b0);
    const flipped = await run();
    expect(flipped.revolutions).toBeGreaterThanOrEqual(1);
    expect(Math.abs(flipped.radius - flipped.exactRadius) / flipped.exactRadius).toBeLessThan(1e-3);
    expect(g.errors).toEqual([]);
    await g.close();
  });

  it('cyclotron: a bad URL parameter is shown on the page', async () => {
    const g = await h.openGame('lab-cyclotron', { query: { B: 'strong' }, waitReady: false });
    const text = await g.page.locator('.lab-param-error').textContent({ timeout: 15_000 });
    expect(text).toContain('B');
    expect(text).toContain('strong');
    expect(g.errors.join('\n')).toContain('URL parameter B');
    await g.close();
  });

  it("rocket: in free space the speed is Tsiolkovsky's ve ln(m0 / m); arrow keys steer, Space cuts the engine", async () => {
    const g = await h.openGame('lab-rocket', contractOptions('desktop'));
    await checkPageContract(g, 'lab-rocket', 'desktop');
    await basics(g);
    type Rocket = { state(): { speed: number; tsiolkovsky: number; heading: number; throttle: number; fuel: number; altitude: number } };
    // Steering: hold Left for a while (the heading turns in simulated time while frames run).
    const h0 = ((await lab<Rocket>(g, (game) => game.state())) as ReturnType<Rocket['state']>).heading;
    await g.page.keyboard.down('ArrowLeft');
    await g.waitFor((start) => ((window.game as unknown as Rocket).state().heading > start + 0.05 ? true : null), h0, 20_000);
    await g.page.keyboard.up('ArrowLeft');
    await g.press('Space');
    expect(((await lab<Rocket>(g, (game) => game.state())) as ReturnType<Rocket['state']>).throttle).toBe(0);
    expect(g.errors).toEqual([]);
    await g.close();

    const free = await h.openGame('lab-rocket', { query: { planet: 'none' } });
    const s = (await lab<Rocket>(free, (game) => {
      game.paused = true;
      game.reset();
      game.advance(60 * 12); // the 450 kg of fuel burn in 10 s
      return game.state();
    })) as ReturnType<Rocket['state']>;
    expect(s.fuel).toBe(0);
    expect(s.tsiolkovsky).toBeCloseTo(220 * Math.log(750 / 300), 9);
    expect(Math.abs(s.speed - s.tsiolkovsky) / s.tsiolkovsky).toBeLessThan(1e-6);
    expect(free.errors).toEqual([]);
    await free.close();
  });
});
