import type { PhysicsWorld } from '@bitphysics/physics';
import { addBody, contactLength, createPhysicsWorld, setBoundary, solverSubstepsFor, step, stepMany } from '@bitphysics/physics';
import { describe, expect, test } from 'vitest';

/**
 * Lengths that scale (issue 13): small balls squash no more than big ones, because the solver takes
 * the substeps their contact stiffness needs (solver/contact-scale.ts).
 */
describe('contact scale', () => {
  /**
   * The count follows f = contactHertz sqrt(1 m / r) = 60 Hz sqrt(1 m / r) at f h_s <= 0.6:
   * ceil(h f / 0.6). 2 cm at dt 1/60: 424 Hz -> ceil(11.79) = 12; 0.5 m: 84.9 Hz -> 3, so the world's 4;
   * 1 mm: 1,897 Hz -> 53, capped at 16. A scene scaled by L in length and sqrt(L) in time step gets the
   * same count (h f is unchanged). These are exact integers from the formula.
   */
  test('solverSubstepsFor takes the substeps the smallest ball needs, never fewer than the setting', () => {
    const world = createPhysicsWorld({ dimensions: 2 });
    const st = world.collision.settings;
    const h = 1 / 60;
    expect(solverSubstepsFor(st, 0.02, h)).toBe(12);
    expect(solverSubstepsFor(st, 0.5, h)).toBe(4);
    expect(solverSubstepsFor(st, Infinity, h)).toBe(4);
    expect(solverSubstepsFor(st, 0.001, h)).toBe(16);
    expect(solverSubstepsFor(st, 0.02 * 25, h * 5)).toBe(12);
    st.solverSubsteps = 14;
    expect(solverSubstepsFor(st, 0.02, h)).toBe(14);
    st.autoSubsteps = false;
    st.solverSubsteps = 4;
    expect(solverSubstepsFor(st, 0.02, h)).toBe(4);
  });

  /** One bin of the bench's Galton board: 2 cm balls in a column 5 radii (10 cm) wide, `count` of them. */
  function galtonBin(count: number, autoSubsteps: boolean): { world: PhysicsWorld; ids: number[]; r: number } {
    const r = 0.02;
    const world = createPhysicsWorld({ dimensions: 2, capacity: count + 8 });
    world.collision.settings.autoSubsteps = autoSubsteps;
    setBoundary(world, { min: [0, 0], max: [5 * r, 1000 * r], restitution: 0.3, friction: 0.2 });
    const ids: number[] = [];
    for (let i = 0; i < count; i++) {
      const col = i % 2,
        row = Math.floor(i / 2);
      ids.push(
        addBody(world, {
          position: [r * (1.1 + 2.1 * col + 0.3 * (row % 2)), r * (1.1 + 2.2 * row)],
          radius: r,
          mass: 0.03,
          restitution: 0.3,
          friction: 0.2,
        }),
      );
    }
    return { world, ids, r };
  }

  function deepestOverlap(world: PhysicsWorld, ids: number[], r: number): number {
    const P = world.components.Position;
    let worst = 0;
    for (let a = 0; a < ids.length; a++) {
      for (let b = a + 1; b < ids.length; b++) {
        worst = Math.max(worst, 2 * r - Math.hypot(P.x[ids[a]!]! - P.x[ids[b]!]!, P.y[ids[a]!]! - P.y[ids[b]!]!));
      }
    }
    return worst / r;
  }

  /**
   * A column of 120 balls of radius 2 cm (60 layers, zigzagging between walls 5 radii apart, as in the
   * Galton board's bins) after 200 steps (3.3 s): the deepest overlap must stay under 5 % of a radius,
   * the budget, as 0.5 m balls do (balls-in-box: 1.2 %). Measured 0.93 % with the automatic
   * 12 substeps; with the world's 4 (autoSubsteps false, the behaviour before) 16.8 %, which the second
   * half checks (over 10 %) so the test shows what it guards.
   */
  test("contactLength reads the length the world's last step used for its contacts; a bad world is refused", () => {
    // Reference: every ball is 2 cm, and the first step with ball contacts takes their smallest radius
    // at once (no ramp from a previous length), so the step's length is exactly 0.02 m.
    const world = createPhysicsWorld({ dimensions: 2, capacity: 64 });
    setBoundary(world, { min: [-0.2, 0], max: [0.2, 1] });
    expect(contactLength(world, world.collision.cache.rows)).toBe(Infinity); // no step, no rows
    for (let i = 0; i < 20; i++) addBody(world, { position: [-0.18 + (i % 10) * 0.04, 0.02 + Math.floor(i / 10) * 0.039], radius: 0.02 });
    stepMany(world, 5);
    expect(world.collision.cache.rows.count).toBeGreaterThan(0);
    expect(contactLength(world, world.collision.cache.rows)).toBe(0.02);
    // The call before the world was passed: contactLength(buf).
    const old = contactLength as unknown as (buf: unknown) => number;
    expect(() => old(world.collision.cache.rows)).toThrow(/contactLength: world must be a physics world/);
  });

  test('a Galton bin of 2 cm balls overlaps less than 5 % of a radius at the defaults', () => {
    const auto = galtonBin(120, true);
    stepMany(auto.world, 200);
    expect(deepestOverlap(auto.world, auto.ids, auto.r)).toBeLessThan(0.05);
    const P = auto.world.components.Position;
    // Settled into about 60 layers, not still falling (the top ball started at 131 r).
    expect(Math.max(...auto.ids.map((e) => P.y[e]!)) / auto.r).toBeLessThan(115);
    const fixed = galtonBin(120, false);
    stepMany(fixed.world, 200);
    expect(deepestOverlap(fixed.world, fixed.ids, fixed.r)).toBeGreaterThan(0.1);
  });

  /**
   * The stiffness of a step's contacts follows its smallest ball, and moves there gradually (at most
   * 1.5 times shorter a length per step). 60 balls of 0.5 m rest in a box; five 2 cm balls (e = 0.8) land
   * on them and bounce. The big balls must not be thrown: fastest big ball under 0.2 m/s over 300
   * steps (measured 0.09 m/s; 0.06 m/s before the automatic substeps; 0.8 m/s with the stiffness jumping
   * from 85 Hz to 424 Hz in one step, the pile's resting overlap then pushed out at once).
   */
  test('small balls landing on a pile of big ones do not throw it', () => {
    const R = 0.5,
      across = 6;
    const world = createPhysicsWorld({ dimensions: 2, capacity: 100, sleep: false });
    setBoundary(world, { min: [0, 0], max: [(2 * across + 1) * R, 100], restitution: 0.3, friction: 0.3 });
    const ids: number[] = [];
    for (let i = 0; i < 60; i++) {
      const c = i % across,
        row = Math.floor(i / across);
      ids.push(
        addBody(world, {
          position: [R * (1.1 + 2.1 * c + 0.3 * (row % 2)), R * (1.1 + 2.2 * row)],
          radius: R,
          mass: 1,
          restitution: 0.3,
          friction: 0.3,
        }),
      );
    }
    stepMany(world, 400);
    const V = world.components.Velocity,
      P = world.components.Position;
    const fastest = (): number => Math.max(...ids.map((e) => Math.hypot(V.x[e]!, V.y[e]!)));
    expect(fastest()).toBeLessThan(0.01);
    const top = Math.max(...ids.map((e) => P.y[e]!));
    const small: number[] = [];
    for (let k = 0; k < 5; k++)
      small.push(
        addBody(world, {
          position: [R * (2 + 2 * k), top + R + 0.05 + 0.3 * k],
          radius: 0.02,
          mass: 0.01,
          restitution: 0.8,
          friction: 0.3,
        }),
      );
    let worst = 0,
      lowest = Infinity;
    for (let s = 0; s < 300; s++) {
      step(world);
      worst = Math.max(worst, fastest());
      for (const e of small) lowest = Math.min(lowest, P.y[e]!);
    }
    // The small balls did reach the pile (a 2 cm ball on the top ball has its centre at top + R + 0.02).
    expect(lowest).toBeLessThan(top + R + 0.021);
    expect(worst).toBeLessThan(0.2);
  });
});
