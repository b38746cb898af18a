import {
  addBody,
  addSegment,
  createPhysicsWorld,
  forEachContact,
  kineticEnergy,
  linearMomentum,
  setBoundary,
  step,
  stepMany,
} from '@bitphysics/physics';
import { describe, expect, test } from 'vitest';

/**
 * Collisions against their analytic results: bounce heights, Newton's cradle, oblique elastic hits,
 * the restitution threshold of perfectly elastic contacts, and robustness (huge coordinates, fast
 * balls at a long step). Sources: Ramtal and Dobre ch. 11 (restitution, momentum exchange); any
 * mechanics text for the two-body impact along the line of centres.
 */
describe('collision accuracy', () => {
  /**
   * A ball dropped from h = 5 m onto a floor with restitution e rises to h e^(2n) after bounce n (each
   * bounce scales the speed by e, the height by e^2). Tolerance 1 %: the apex is read from the state
   * of the step in which the ball turns, under exact free flight (y + v^2 / 2g).
   */
  test('bounce n = 1..5 of a ball dropped from 5 m with e = 0.8 reaches h e^(2n) within 1 % at dt 1/60 and 1/240', () => {
    for (const dt of [1 / 60, 1 / 240]) {
      const world = createPhysicsWorld({ dimensions: 2, capacity: 4, dt });
      setBoundary(world, { min: [-10, 0], max: [10, 100], restitution: 0.8 });
      const r = 0.1,
        g = 9.81;
      const ball = addBody(world, { position: [0, 5 + r], radius: r, restitution: 0.8, friction: 0 });
      const P = world.components.Position,
        V = world.components.Velocity;
      const peaks: number[] = [];
      for (let i = 0; i < 30 / dt && peaks.length < 5; i++) {
        const y0 = P.y[ball]!,
          v0 = V.y[ball]!;
        step(world);
        if (v0 > 0 && V.y[ball]! <= 0) peaks.push(y0 + (v0 * v0) / (2 * g) - r);
      }
      expect(peaks.length).toBe(5);
      peaks.forEach((p, n) => {
        expect(Math.abs(p / (5 * 0.8 ** (2 * (n + 1))) - 1)).toBeLessThan(0.01);
      });
    }
  });

  /**
   * Newton's cradle: five equal balls, e = 1, no friction, the first arriving at 2 m/s. Momentum and
   * energy can only both be conserved if the last ball leaves at 2 m/s and the others stop (the
   * pairwise exchange of equal masses). Tolerances from the issue: 2 % of 2 m/s for the last ball,
   * under 2 % of it for the others; touching and with 5 cm gaps.
   */
  test("Newton's cradle, touching and with gaps, sends the last ball on at 2 m/s and stops the others", () => {
    for (const gap of [0, 0.05]) {
      const world = createPhysicsWorld({ dimensions: 2, capacity: 8, gravity: [0, 0] });
      const r = 0.5;
      const ids: number[] = [];
      for (let i = 0; i < 5; i++)
        ids.push(addBody(world, { position: [i * (2 * r + gap), 0], radius: r, mass: 1, restitution: 1, friction: 0 }));
      world.components.Position.x[ids[0]!] = -0.3 - gap;
      world.components.Velocity.x[ids[0]!] = 2;
      stepMany(world, 120);
      const V = world.components.Velocity;
      expect(Math.abs(V.x[ids[4]!]! - 2)).toBeLessThan(0.04);
      for (let i = 0; i < 4; i++) expect(Math.abs(V.x[ids[i]!]!)).toBeLessThan(0.04);
      expect(Math.abs(kineticEnergy(world) - 2)).toBeLessThan(2 * 0.01);
    }
  });

  /**
   * Two equal balls, e = 1, no friction: the moving one (speed u, impact parameter b R) hits the one
   * at rest. At the touch the normal is n = (sqrt(1 - b^2), -b) from the mover to the target; the
   * target leaves with (u . n) n and the mover with u - (u . n) n. Every impact parameter and every
   * phase of the step must give these within 0.1 % of u (the solver resolves the hit at its time of
   * impact, along the line of centres there); and the balls must never bounce across a gap.
   */
  test('oblique elastic hit matches the analytic velocities within 0.1 % at any impact parameter and phase of the step', () => {
    // Impact parameters 0.05 to 0.85 R and the glancing 0.9, 0.95, 0.99 R (issue 13: at 0.9 R the
    // balls left 1 deg off, worst 36 deg at 10 m/s, once bouncing across a 3.9 cm gap); speeds 2, 5, 10 m/s.
    const impacts = [0.05, 0.15, 0.25, 0.35, 0.45, 0.55, 0.65, 0.75, 0.85, 0.9, 0.95, 0.99];
    for (const u of [2, 5, 10]) {
      for (const b of impacts) {
        for (let j = 0; j < 10; j++) {
          const world = createPhysicsWorld({ dimensions: 2, capacity: 4, gravity: [0, 0] });
          const h = world.dt,
            R = 0.5;
          const nx = Math.sqrt(1 - b * b),
            ny = -b;
          const x0 = -nx - u * h * (3 + j / 10);
          const A = addBody(world, { position: [x0, b], velocity: [u, 0], radius: R, mass: 1, restitution: 1, friction: 0 });
          const B = addBody(world, { position: [0, 0], radius: R, mass: 1, restitution: 1, friction: 0 });
          const P = world.components.Position,
            V = world.components.Velocity;
          let hitStep = -1,
            gapAtImpulse = Number.NaN;
          for (let i = 0; i < 8; i++) {
            const before = V.x[B]!;
            step(world);
            if (before === 0 && V.x[B]! !== 0) {
              hitStep = i;
              // B sat at the origin until the impulse, then moved at its new velocity for the rest of
              // the step, tau; A likewise moved at its new velocity for tau. So tau = |x_B| / |v_B|
              // and the centres were |x_A - v_A tau - 0| apart when the impulse was applied.
              const vb = Math.hypot(V.x[B]!, V.y[B]!),
                tau = Math.hypot(P.x[B]!, P.y[B]!) / vb;
              expect(tau).toBeLessThanOrEqual(h * (1 + 1e-9));
              gapAtImpulse = Math.hypot(P.x[A]! - V.x[A]! * tau, P.y[A]! - V.y[A]! * tau) - 2 * R;
            }
          }
          const vn = u * nx;
          expect(Math.hypot(V.x[A]! - (u - vn * nx), V.y[A]! - -vn * ny)).toBeLessThan(1e-3 * u);
          expect(Math.hypot(V.x[B]! - vn * nx, V.y[B]! - vn * ny)).toBeLessThan(1e-3 * u);
          // The hit happens in the step that contains the touch (index 3; at its very start, j = 0, the
          // touch is the end of step 2), never earlier across a gap.
          expect(j === 0 ? [2, 3] : [3]).toContain(hitStep);
          // No bounce across a gap: the centres at most 2R apart when the impulse is applied. Tolerance
          // 1e-9 m (2e-9 R): rounding of the back-extrapolation at 1 m coordinates is ~1e-16 m (measured:
          // the impulse lands within -3e-16 to 2e-16 m of the touch in all 360 cases); issue 13 saw 3.9 cm.
          expect(gapAtImpulse).toBeLessThanOrEqual(1e-9);
        }
      }
    }
  });

  /**
   * An e = 1 ball hitting a wall at 0.3 m/s (below the 0.5 m/s default threshold of inelastic
   * contacts) bounces back at 0.3 m/s: perfectly elastic contacts have no threshold unless the user
   * sets one. With the world option set, the user's threshold applies to them too.
   */
  test('an e = 1 contact bounces at any speed unless the user set a threshold', () => {
    const run = (options: { restitutionThreshold?: number }) => {
      const world = createPhysicsWorld({ dimensions: 2, capacity: 4, gravity: [0, 0], ...options });
      setBoundary(world, { min: [-5, -5], max: [5, 5], restitution: 1 });
      const ball = addBody(world, { position: [4, 0], velocity: [0.3, 0], radius: 0.5, restitution: 1, friction: 0 });
      stepMany(world, 120);
      return world.components.Velocity.x[ball]!;
    };
    expect(Math.abs(run({}) - -0.3)).toBeLessThan(1e-12);
    expect(Math.abs(run({ restitutionThreshold: 0.5 }))).toBeLessThan(1e-9);
  });

  /** The soft contact's stiffness: the documented default (60 Hz) is the default. */
  test('contactHertz defaults to the documented 60 Hz', () => {
    expect(createPhysicsWorld({}).collision.settings.contactHertz).toBe(60);
  });

  /**
   * A step always returns: a ball of radius 5 m at (1e17, 1e17) beside ten small balls near the origin.
   * The broadphase's cell coordinates are clamped, so its cell loops are finite at any coordinate.
   * (Without the clamp the cell loop could not advance past 2^53 and the step never returned.)
   */
  test('broadphase cell ranges are clamped: a huge ball at (1e17, 1e17) does not stall the step', () => {
    const world = createPhysicsWorld({ dimensions: 2, capacity: 16 });
    const big = addBody(world, { position: [1e17, 1e17], radius: 5 });
    const small: number[] = [];
    for (let i = 0; i < 10; i++) small.push(addBody(world, { position: [i * 0.3, 0], radius: 0.1 }));
    stepMany(world, 10);
    expect(world.components.Position.x[big]).toBe(1e17);
    // The small balls still collide with each other (touching neighbours pushed apart, not passing through).
    const P = world.components.Position;
    for (let i = 1; i < small.length; i++) expect(P.x[small[i]!]! - P.x[small[i - 1]!]!).toBeGreaterThan(0.2 - 0.01);
  });

  /**
   * No escape from the boundary box at dt = 1/10 s: 100 balls at up to 200 m/s bouncing in a 10 m box
   * for 60 s. Before: 17 to 21 of 100 left it by up to 2.8 m. Tolerance: not one ball centre farther
   * than its radius beyond a wall, ever.
   */
  test('no ball leaves the boundary box at dt 1/10 s and speeds up to 200 m/s', () => {
    const world = createPhysicsWorld({ dimensions: 2, capacity: 128, dt: 0.1 });
    setBoundary(world, { min: [0, 0], max: [10, 10], restitution: 0.9 });
    let seed = 5;
    const rnd = () => (seed = (seed * 16807) % 2147483647) / 2147483647;
    const ids: number[] = [];
    for (let i = 0; i < 100; i++) {
      const a = rnd() * 2 * Math.PI,
        s = 200 * rnd();
      ids.push(
        addBody(world, {
          position: [1 + 8 * rnd(), 1 + 8 * rnd()],
          velocity: [s * Math.cos(a), s * Math.sin(a)],
          radius: 0.2,
          restitution: 0.9,
        }),
      );
    }
    const P = world.components.Position;
    let worst = 0;
    for (let i = 0; i < 600; i++) {
      step(world);
      for (const e of ids) worst = Math.max(worst, 0.2 - P.x[e]!, P.x[e]! - 9.8, 0.2 - P.y[e]!, P.y[e]! - 9.8);
    }
    expect(worst).toBeLessThan(1e-9);
  });

  /**
   * An elastic cluster with no walls: every collision is ball-ball, so momentum is conserved to
   * rounding (1e-12 of the total |p| scale) and, the impacts being exact pairwise exchanges, kinetic
   * energy within 1 %.
   */
  test('an elastic cluster without walls conserves momentum exactly and kinetic energy within 1 %', () => {
    const world = createPhysicsWorld({ dimensions: 2, capacity: 256, gravity: [0, 0], sleep: false });
    let seed = 9;
    const rnd = () => (seed = (seed * 16807) % 2147483647) / 2147483647;
    let scale = 0;
    for (let i = 0; i < 100; i++) {
      const a = rnd() * 2 * Math.PI,
        s = 1 + rnd();
      scale += s;
      addBody(world, {
        position: [(i % 10) * 0.5, Math.floor(i / 10) * 0.5],
        velocity: [s * Math.cos(a), s * Math.sin(a)],
        radius: 0.2,
        mass: 1 + rnd(),
        restitution: 1,
        friction: 0,
      });
    }
    const p0 = linearMomentum(world),
      k0 = kineticEnergy(world);
    stepMany(world, 600);
    const p1 = linearMomentum(world);
    expect(Math.hypot(p1[0]! - p0[0]!, p1[1]! - p0[1]!)).toBeLessThan(1e-12 * scale);
    expect(Math.abs(kineticEnergy(world) / k0 - 1)).toBeLessThan(0.01);
  });

  /**
   * The book's elastic gas (Ramtal and Dobre ch. 11): 500 discs (r 0.1 m, unit mass, 1 m/s in random
   * directions, 12 % area fraction), e = 1, no friction, no gravity, in a box with e = 1 walls. Every
   * collision is an exact pairwise exchange, so kinetic energy is kept. The budget is 1 % over
   * 20,000 steps (the bench's `balls-in-box --restitution 1` and the molecules lab run long gases);
   * 20,000 steps of 500 balls take too long for this suite, so 500 steps get the budget scaled to
   * them, 1 % x 500 / 20,000 = 0.025 %. Before the fix (soft substeps acting on rows that stay apart,
   * the relax pass looking a substep past the step) this gas lost 0.096 % in 500 steps.
   */
  test('an elastic gas of 500 balls in a box keeps its kinetic energy (0.025 % over 500 steps)', () => {
    const count = 500,
      r = 0.1;
    const world = createPhysicsWorld({ dimensions: 2, capacity: count + 8, gravity: [0, 0], sleep: false });
    const H = Math.sqrt((count * Math.PI * r * r) / 0.12 / 1.5),
      W = 1.5 * H;
    setBoundary(world, { min: [0, 0], max: [W, H], restitution: 1, friction: 0 });
    let seed = 3;
    const rnd = () => (seed = (seed * 16807) % 2147483647) / 2147483647;
    const cols = Math.ceil(Math.sqrt(count * 1.5)),
      rows = Math.ceil(count / cols);
    const dx = W / cols,
      dy = H / rows;
    for (let i = 0; i < count; i++) {
      const a = 2 * Math.PI * rnd();
      const x = ((i % cols) + 0.5) * dx + (rnd() - 0.5) * 0.4 * (dx - 2 * r),
        y = (Math.floor(i / cols) + 0.5) * dy + (rnd() - 0.5) * 0.4 * (dy - 2 * r);
      addBody(world, { position: [x, y], velocity: [Math.cos(a), Math.sin(a)], radius: r, mass: 1, restitution: 1, friction: 0 });
    }
    const k0 = kineticEnergy(world);
    stepMany(world, 500);
    expect(Math.abs(kineticEnergy(world) / k0 - 1)).toBeLessThan(0.00025);
  });

  /**
   * Lengths that scale (contact-scale.ts): the same scene at 2 m and at 0.2 m (a marble run: a ball
   * rolls down a ramp with friction, bounces on the floor and runs into a column of three balls resting
   * in the corner), with gravity unchanged and the time step scaled by sqrt(L) (so g t^2 / L is the same
   * at each step), must follow the same nondimensional trajectories x / L. Stiffness, push-out speed,
   * stick speed, speculative margin and the impact stage's resting speed all follow the balls' size, so
   * the two runs differ only by rounding amplified through the contacts: a perturbation of 1e-9 of L grows
   * to 1.1e-5 of L over these 300 steps. Tolerance 1e-3 of L (measured: 1.3e-4); with one contact
   * frequency for every size the small column squashed ten times deeper and the runs parted by 0.12 L.
   * The user's restitution threshold is a speed, so the scene scales it by sqrt(L) too.
   */
  test('a 0.2 m marble run follows the 2 m one scaled, within 1e-3 of its length', () => {
    const run = (L: number): Float64Array[] => {
      const world = createPhysicsWorld({
        dimensions: 2,
        capacity: 16,
        dt: Math.sqrt(L / 2) / 60,
        sleep: false,
        restitutionThreshold: 0.5 * Math.sqrt(L / 2),
      });
      setBoundary(world, { min: [0, 0], max: [L, L], restitution: 0.4, friction: 0.3 });
      addSegment(world, { a: [0.05 * L, 0.75 * L], b: [0.65 * L, 0.4 * L], friction: 0.3, restitution: 0.4 });
      const r = 0.04 * L;
      const ids: number[] = [];
      for (let i = 0; i < 3; i++)
        ids.push(addBody(world, { position: [L - r, r + 2 * r * i], radius: r, mass: 1, restitution: 0.4, friction: 0.3 }));
      ids.push(addBody(world, { position: [0.1 * L, 0.75 * L + 1.2 * r], radius: r, mass: 2, restitution: 0.4, friction: 0.3 }));
      const P = world.components.Position;
      const path: Float64Array[] = [];
      for (let k = 0; k < 300; k++) {
        step(world);
        path.push(Float64Array.from(ids.flatMap((e) => [P.x[e]! / L, P.y[e]! / L])));
      }
      return path;
    };
    const big = run(2),
      small = run(0.2);
    let worst = 0;
    big.forEach((frame, k) => {
      frame.forEach((v, j) => {
        worst = Math.max(worst, Math.abs(v - small[k]![j]!));
      });
    });
    expect(worst).toBeLessThan(1e-3);
    // The run did something: the rolling ball reached the column and moved it.
    expect(big[299]![0]!).toBeLessThan(0.95);
  });

  /**
   * Small balls do not squash: a bin 9 radii wide filled with 100 balls of radius 2 cm (25 layers, the
   * load of a Galton board's bin; the full board of 2,000 balls is in the bench's quick study). The
   * lowest contacts carry about 25 balls' weight; with the stiffness following the size the deepest
   * overlap after 200 steps must stay under 5 % of a radius, as the 0.5 m balls of balls-in-box do
   * (measured 3.9 %; 21.7 % with one 60 Hz contact frequency for every size).
   */
  test('a bin of 100 balls of radius 2 cm overlaps by less than 5 % of a radius', () => {
    const r = 0.02,
      count = 100,
      across = 4;
    const world = createPhysicsWorld({ dimensions: 2, capacity: count + 8 });
    setBoundary(world, { min: [0, 0], max: [(2 * across + 1) * r, 1000 * r], restitution: 0.5, friction: 0.3 });
    const ids: number[] = [];
    for (let i = 0; i < count; i++) {
      const col = i % across,
        row = Math.floor(i / across);
      ids.push(
        addBody(world, {
          position: [r * (1.1 + 2.1 * col + 0.3 * (row % 2)), r * (1.1 + 2.2 * row)],
          radius: r,
          mass: 1,
          restitution: 0.5,
          friction: 0.3,
        }),
      );
    }
    stepMany(world, 200);
    const P = world.components.Position;
    let worst = 0,
      top = 0;
    for (let a = 0; a < count; a++) {
      top = Math.max(top, P.y[ids[a]!]!);
      for (let b = a + 1; b < count; b++)
        worst = Math.max(worst, 2 * r - Math.hypot(P.x[ids[a]!]! - P.x[ids[b]!]!, P.y[ids[a]!]! - P.y[ids[b]!]!));
    }
    expect(worst / r).toBeLessThan(0.05);
    // Settled into about 25 layers (not still falling: the top ball is below its start of 218 r).
    expect(top / r).toBeLessThan(60);
  });
});

describe('contacts after a step', () => {
  /**
   * `forEachContact` lists the last step's contacts with entity ids, normal, point and impulse. A ball
   * resting on a static ball under gravity: one contact, normal straight up from the static ball, the
   * point at the bottom of the ball, and the impulse of one step of support, m g h, within 1 % (the
   * soft contact's support equals the weight at rest).
   */
  test('forEachContact reports the resting contact with its ids, normal, point and impulse m g h', () => {
    const world = createPhysicsWorld({ dimensions: 2, capacity: 4, sleep: false });
    const base = addBody(world, { position: [0, 0], radius: 0.5, static: true });
    const ball = addBody(world, { position: [0, 1], radius: 0.5, mass: 2, restitution: 0, friction: 0 });
    stepMany(world, 120);
    const seen: { a: number; b: number; nx: number; ny: number; y: number; impulse: number }[] = [];
    forEachContact(world, (c) => seen.push({ a: c.a, b: c.b, nx: c.nx, ny: c.ny, y: c.y, impulse: c.impulse }));
    expect(seen.length).toBe(1);
    const c = seen[0]!;
    expect([c.a, c.b]).toEqual([base, ball]);
    expect(Math.abs(c.nx)).toBeLessThan(1e-6);
    expect(Math.abs(c.ny - 1)).toBeLessThan(1e-6);
    expect(Math.abs(c.y - 0.5)).toBeLessThan(0.01);
    expect(Math.abs(c.impulse / (2 * 9.81 * world.dt) - 1)).toBeLessThan(0.01);
  });
});
