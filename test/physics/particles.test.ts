import {
  addBody,
  addEmitter,
  burst,
  createPhysicsWorld,
  emitNow,
  onParticleDeath,
  particleLook,
  removeBody,
  setEmitter,
  setVortex,
  slotOf,
  step,
  stepMany,
} from '@bitphysics/physics';
import { query } from 'bitecs';
import { describe, expect, test } from 'vitest';

const particlesOf = (world: ReturnType<typeof createPhysicsWorld>) => query(world, [world.components.Particle]).length;

describe('emitters', () => {
  test('a rate of r particles/s spawns floor(r t) by time t (the fraction carries over)', () => {
    const world = createPhysicsWorld({ gravity: [0, 0], capacity: 2000 });
    const em = addEmitter(world, { rate: 37.5, lifetime: 100 });
    stepMany(world, 120); // 2 s
    expect(world.components.Emitter.spawned[em]).toBe(75);
    expect(particlesOf(world)).toBe(75);
  });

  test('projectSphere: a burst of one speed fills a disc as a spherical shell seen from the side', () => {
    // Directions uniform on the sphere, seen side-on: the in-plane speed is s = v sin(theta) with
    // cos(theta) uniform in [-1, 1], so P(s <= x v) = 1 - sqrt(1 - x^2) (the shell's projected
    // fraction inside radius x). Against that law at x = 0.5, 0.8 and 0.95 (0.134, 0.4, 0.688) with
    // 20,000 particles: the binomial standard error is at most 0.0035, tolerance 0.015 (over 4 of them).
    // Without the option every particle has s = v (a ring): the fractions would be 0, 0 and 0.
    const world = createPhysicsWorld({ gravity: [0, 0], capacity: 20_100 });
    const em = addEmitter(world, { position: [0, 0], speed: 3, lifetime: 100, projectSphere: true });
    emitNow(world, em, 20_000, [0, 0], [0, 0]);
    const V = world.components.Velocity;
    const speeds = Array.from(query(world, [world.components.Particle]), (e) => Math.hypot(V.x[e]!, V.y[e]!) / 3);
    expect(speeds.length).toBe(20_000);
    expect(Math.max(...speeds)).toBeLessThanOrEqual(1 + 1e-12);
    for (const x of [0.5, 0.8, 0.95]) {
      const inside = speeds.filter((s) => s <= x).length / speeds.length;
      expect(Math.abs(inside - (1 - Math.sqrt(1 - x * x)))).toBeLessThan(0.015);
    }
    // The directions in the plane stay uniform: a quarter of them in each quadrant (same tolerance).
    const up = Array.from(query(world, [world.components.Particle])).filter((e) => V.x[e]! > 0 && V.y[e]! > 0).length;
    expect(Math.abs(up / 20_000 - 0.25)).toBeLessThan(0.015);
  });

  test('projectSphere is refused in a 3D world and when not a boolean, and changes nothing then', () => {
    const w3 = createPhysicsWorld({ dimensions: 3, capacity: 10 });
    expect(() => addEmitter(w3, { projectSphere: true })).toThrow(/addEmitter: projectSphere is for 2D worlds/);
    const w2 = createPhysicsWorld({ capacity: 10 });
    const em = addEmitter(w2, {});
    expect(() => setEmitter(w2, em, { projectSphere: 1 as unknown as boolean })).toThrow(/setEmitter.*projectSphere/);
    expect(w2.components.Emitter.projectSphere[slotOf(em)]).toBe(0);
    setEmitter(w2, em, { projectSphere: true });
    expect(w2.components.Emitter.projectSphere[slotOf(em)]).toBe(1);
  });

  test('particles expire after their lifetime; the live count settles at rate x lifetime', () => {
    const world = createPhysicsWorld({ gravity: [0, 0], capacity: 2000 });
    addEmitter(world, { rate: 60, lifetime: 0.5 });
    stepMany(world, 300);
    // Each particle lives ceil(0.5 s / (1/60 s)) = 30 steps and one is born each step.
    expect(particlesOf(world)).toBe(30);
  });

  test('speeds, directions and lifetimes stay in their ranges; the emitter passes on velocity', () => {
    const world = createPhysicsWorld({ gravity: [0, 0], capacity: 5000 });
    const em = addEmitter(world, {
      position: [0, 0],
      velocity: [10, 0],
      inheritVelocity: 0.5,
      direction: [0, 1],
      spread: 0.3,
      speed: [2, 4],
      lifetime: [1, 3],
    });
    emitNow(world, em, 2000, [0, 0], [10, 0]);
    const ids = query(world, [world.components.Particle]);
    const V = world.components.Velocity,
      L = world.components.Lifetime;
    for (const e of ids) {
      const vx = V.x[e]! - 5,
        vy = V.y[e]!; // minus the inherited half of (10, 0)
      const speed = Math.hypot(vx, vy),
        angle = Math.atan2(vy, vx) - Math.PI / 2;
      expect(speed).toBeGreaterThanOrEqual(2 - 1e-12);
      expect(speed).toBeLessThanOrEqual(4 + 1e-12);
      expect(Math.abs(angle)).toBeLessThanOrEqual(0.3 + 1e-12);
      expect(L.duration[e]!).toBeGreaterThanOrEqual(1);
      expect(L.duration[e]!).toBeLessThanOrEqual(3);
    }
  });

  test('3D cone: every direction within the spread of the axis, and the cone is filled', () => {
    const world = createPhysicsWorld({ dimensions: 3, gravity: [0, 0, 0], capacity: 5000 });
    const em = addEmitter(world, { direction: [1, 1, 0], spread: 0.5, speed: 1 });
    emitNow(world, em, 3000);
    const V = world.components.Velocity;
    let maxAngle = 0;
    for (const e of query(world, [world.components.Particle])) {
      const c = (V.x[e]! + V.y[e]!) / Math.SQRT2;
      maxAngle = Math.max(maxAngle, Math.acos(Math.min(1, c)));
    }
    expect(maxAngle).toBeLessThanOrEqual(0.5 + 1e-9);
    expect(maxAngle).toBeGreaterThan(0.48);
  });

  test('fireworks: a particle bursts into particles of another emitter when it dies, up to the generation limit', () => {
    const world = createPhysicsWorld({ gravity: [0, 0], capacity: 10000 });
    const sparks = addEmitter(world, { rate: 0, lifetime: 0.5, speed: 1 });
    // Shell (generation 0) -> 10 sparks (generation 1) -> 3 each (generation 2, the limit): 1 -> 10 -> 30.
    const world2 = world;
    world2.components.Emitter.deathEmitter[sparks] = sparks;
    world2.components.Emitter.deathCount[sparks] = 3;
    world2.components.Emitter.maxGeneration[sparks] = 2;
    const shells = addEmitter(world, { rate: 0, lifetime: 0.5, speed: 1, onDeath: { emitter: sparks, count: 10, maxGeneration: 1 } });
    emitNow(world, shells, 1);
    const counts: number[] = [];
    let deaths = 0;
    onParticleDeath(world, () => {
      deaths++;
    });
    for (let i = 0; i < 200; i++) {
      step(world);
      counts.push(particlesOf(world));
    }
    expect(Math.max(...counts)).toBe(30);
    expect(world.components.Emitter.spawned[sparks]).toBe(10 + 30);
    expect(deaths).toBe(1 + 10 + 30);
    expect(counts[counts.length - 1]).toBe(0);
  });

  test('drop-new: a full world drops new particles, counts them, and never throws', () => {
    const world = createPhysicsWorld({ gravity: [0, 0], capacity: 50 });
    const em = addEmitter(world, { rate: 600, lifetime: 10 });
    stepMany(world, 60);
    expect(world.entityIndex.aliveCount).toBe(50);
    expect(world.components.Emitter.dropped[em]!).toBeGreaterThan(500);
  });

  test('recycle-oldest: a full world removes the oldest particle to make room', () => {
    const world = createPhysicsWorld({ gravity: [0, 0], capacity: 21 });
    const em = addEmitter(world, { rate: 60, lifetime: 100, policy: 'recycle-oldest' });
    stepMany(world, 20);
    const firstBorn = [...query(world, [world.components.Particle])];
    expect(firstBorn.length).toBe(20);
    const oldest =
      Math.min(...firstBorn.map((e) => world.components.Lifetime.age[e]!)) < 0
        ? -1
        : firstBorn.reduce((a, e) => (world.components.Lifetime.age[e]! > world.components.Lifetime.age[a]! ? e : a));
    const oldestAge = world.components.Lifetime.age[oldest]!;
    step(world);
    const now = query(world, [world.components.Particle]);
    expect(now.length).toBe(20);
    // The particle that was oldest is gone (its id was recycled for the newborn, now age 0 or one step).
    expect(world.components.Lifetime.age[oldest]!).toBeLessThan(oldestAge);
    expect(world.components.Emitter.dropped[em]).toBe(0);
  });

  test('constant churn keeps the entity count flat and ids within capacity for 5,000 steps', () => {
    const world = createPhysicsWorld({ gravity: [0, -10], capacity: 3000 });
    const sparks = addEmitter(world, { lifetime: [0.3, 0.8], speed: [3, 8], particle: { quadraticDrag: 0.01, mass: 0.01 } });
    const shells = addEmitter(world, {
      rate: 20,
      lifetime: [0.4, 0.6],
      speed: [10, 12],
      direction: [0, 1],
      spread: 0.2,
      onDeath: { emitter: sparks, count: 40, maxGeneration: 1 },
      policy: 'recycle-oldest',
    });
    const counts: number[] = [];
    for (let i = 0; i < 5000; i++) {
      step(world);
      if (i >= 1000) counts.push(world.entityIndex.aliveCount);
    }
    expect(Math.max(...counts)).toBeLessThanOrEqual(3000);
    expect(world.entityIndex.maxId).toBeLessThanOrEqual(3000);
    // Flat: the mean over the last 1,000 steps is within 10% of the mean over steps 1,000-2,000.
    const mean = (a: number[]) => a.reduce((s, v) => s + v, 0) / a.length;
    expect(Math.abs(mean(counts.slice(-1000)) - mean(counts.slice(0, 1000))) / mean(counts.slice(0, 1000))).toBeLessThan(0.1);
    void shells;
  });

  test('the same seed replays the same particles', () => {
    const run = () => {
      const world = createPhysicsWorld({ gravity: [0, -10], capacity: 1000, seed: 5 });
      addEmitter(world, { rate: 100, lifetime: [0.5, 1], speed: [1, 5], shape: 'disc', size: 2 });
      stepMany(world, 100);
      const P = world.components.Position;
      return Array.from(query(world, [world.components.Particle]), (e) => [P.x[e], P.y[e]]);
    };
    expect(run()).toEqual(run());
  });

  test('look over life interpolates colour, size and alpha linearly in age', () => {
    const world = createPhysicsWorld({ gravity: [0, 0], dt: 0.1 });
    const em = addEmitter(world, {
      lifetime: 1,
      particle: { colorStart: 0xff0000, colorEnd: 0x0000ff, sizeStart: 1, sizeEnd: 0, alphaStart: 1, alphaEnd: 0 },
    });
    emitNow(world, em, 1);
    stepMany(world, 5); // age 0.5
    const [p] = query(world, [world.components.Particle]);
    const look = particleLook(world, p!, { color: 0, size: 0, alpha: 0 });
    expect(look.color).toBe(0x800080);
    expect(look.size).toBeCloseTo(0.5, 12);
    expect(look.alpha).toBeCloseTo(0.5, 12);
  });

  test('a vortex pushes tangentially: a particle on a circle feels k r^(n-1) along axis x r_hat', () => {
    const world = createPhysicsWorld({ gravity: [0, 0] });
    const b = addBody(world, { position: [2, 0], mass: 1 });
    setVortex(world, b, { centre: [0, 0], k: 3, n: 2 });
    step(world);
    expect(world.components.Force.x[b]).toBeCloseTo(0, 12);
    expect(world.components.Force.y[b]).toBeCloseTo(6, 12); // 3 * 2^(2-1) along z x x = +y
  });

  test('a particle whose emitter was removed does not burst with the emitter that reuses its id', () => {
    const world = createPhysicsWorld({ gravity: [0, 0], capacity: 500 });
    const target = addEmitter(world, { lifetime: 10 });
    const host = addBody(world, {});
    const plain = addEmitter(world, { attachTo: host, lifetime: 0.5 });
    emitNow(world, plain, 1);
    removeBody(world, host);
    const host2 = addBody(world, {});
    expect(slotOf(host2)).toBe(slotOf(host));
    addEmitter(world, { attachTo: host2, lifetime: 0.5, onDeath: { emitter: target, count: 50, maxGeneration: 1 } });
    stepMany(world, 40);
    expect(world.components.Emitter.spawned[target]).toBe(0);
  });

  test('setEmitter changes rate, direction, speeds and future particles', () => {
    const world = createPhysicsWorld({ gravity: [0, 0], capacity: 2000 });
    const em = addEmitter(world, { rate: 0, direction: [1, 0], spread: 0, speed: 1, lifetime: 5 });
    setEmitter(world, em, { rate: 60, direction: [0, 1], speed: [3, 3], particle: { quadraticDrag: 0.1, mass: 1 } });
    step(world);
    const [p] = query(world, [world.components.Particle]);
    expect(world.components.Velocity.x[p!]!).toBeCloseTo(0, 12);
    expect(world.components.Velocity.y[p!]!).toBeGreaterThan(2.9);
    expect(world.components.QuadraticDrag.k[p!]).toBe(0.1);
    expect(() => setEmitter(world, em, { spread: 5 })).toThrow(/spread must be in \[0, 3.14/);
  });

  test('bad input', () => {
    const world = createPhysicsWorld();
    expect(() => addEmitter(world, { rate: -1 })).toThrow(/addEmitter: rate must be in \[0, 1000000000\], got -1/);
    expect(() => addEmitter(world, { lifetime: [2, 1] })).toThrow(/lifetime must be \[min, max\] with max >= min/);
    expect(() => addEmitter(world, { lifetime: 0 })).toThrow(/lifetime\[0\] must be > 0, got 0/);
    expect(() => addEmitter(world, { spread: 4 })).toThrow(/spread must be in \[0, 3.14/);
    expect(() => addEmitter(world, { shape: 'cone' as never })).toThrow(
      /shape must be one of 'point', 'disc', 'ring', 'box', 'line', got "cone"/,
    );
    expect(() => addEmitter(world, { onDeath: { emitter: 999, count: 3, maxGeneration: 1 } })).toThrow(
      /addEmitter: onDeath.emitter must be an entity of this world .*got 999/,
    );
    expect(() => addEmitter(world, { policy: 'grow' as never })).toThrow(/policy must be one of 'drop-new', 'recycle-oldest', got "grow"/);
    expect(() => burst(world, 12345, 3)).toThrow(/burst: emitter must be an entity of this world .*got 12345/);
  });
});
