import {
  addElectricField,
  addEmitter,
  addParticle,
  addParticles,
  createPhysicsWorld,
  emitNow,
  handleOf,
  hasComponent,
  isAlive,
  onParticleBirth,
  onParticleDeath,
  type PhysicsWorld,
  particlesExpired,
  removeBody,
  restore,
  SCENES,
  setCharge,
  setDrag,
  setMass,
  setVelocity,
  slotOf,
  snapshot,
  stateHash,
  step,
  stepMany,
} from '@bitphysics/physics';
import { $internal, addComponent, query } from 'bitecs';
import { describe, expect, test } from 'vitest';
import { archetypes } from '../../packages/physics/src/particles/archetype.js';

// The churn path (particles/archetype.ts) writes bitecs' entity index, masks and query lists itself.
// The independent reference here is bitecs' own definition of a query: a live entity belongs to a
// query exactly when it has every component of it and none of its Not components (checked component
// by component with hasComponent), once, and dead entities belong to none.

interface Q {
  dense: ArrayLike<number>;
  sparse: ArrayLike<number>;
  allComponents: object[];
  notComponents: object[];
  orComponents: object[];
  toRemove: { dense: ArrayLike<number> };
}
function ecs(world: PhysicsWorld): { queries: Iterable<Q>; entityIndex: { aliveCount: number; dense: number[] } } {
  return (world as unknown as Record<symbol, never>)[$internal];
}

/** Every query of the world holds exactly the live entities that match it, once each, with a consistent sparse index. */
function expectQueriesConsistent(world: PhysicsWorld): void {
  const ctx = ecs(world);
  const alive = ctx.entityIndex.dense.slice(0, ctx.entityIndex.aliveCount);
  for (const q of ctx.queries) {
    const pending = new Set(Array.from(q.toRemove.dense));
    const members = Array.from(q.dense).filter((e) => !pending.has(e));
    expect(new Set(members).size).toBe(members.length);
    for (let i = 0; i < q.dense.length; i++) expect(q.sparse[q.dense[i]!]).toBe(i);
    const and = q.allComponents.filter((c) => !q.notComponents.includes(c) && !q.orComponents.includes(c));
    const expected = alive.filter(
      (e) =>
        and.every((c) => hasComponent(world, e, c)) &&
        !q.notComponents.some((c) => hasComponent(world, e, c)) &&
        (q.orComponents.length === 0 || q.orComponents.some((c) => hasComponent(world, e, c))),
    );
    expect(members.sort((a, b) => a - b)).toEqual(expected.sort((a, b) => a - b));
  }
}

const particles = (world: PhysicsWorld) => Array.from(query(world, [world.components.Particle]));

describe('particle churn', () => {
  test('a recycled slot carries nothing of its previous life: state, user components, queries', () => {
    const world = createPhysicsWorld({ gravity: [0, 0], capacity: 200 });
    const em = addEmitter(world, {
      position: [1, 2],
      speed: [3, 3],
      lifetime: 0.05,
      policy: 'drop-new',
      particle: { mass: 0.5, quadraticDrag: 0.01, colorStart: 0x112233, colorEnd: 0x445566, sizeStart: 0.2, alphaStart: 0.7 },
    });
    const c = world.components;
    expect(emitNow(world, em, 40)).toBe(40);
    const first = particles(world);
    const stamps = first.map((e) => world.spawnStamp[e]!);
    // Scribble over everything a particle has, and give it a component the emitter does not.
    for (const e of first) {
      c.Velocity.x[e] = 99;
      c.AngularVelocity.z[e] = 7;
      c.Lifetime.age[e] = 0.01;
      c.Particle.colorStart[e] = 0xffffff;
      c.Particle.generation[e] = 5;
      c.Mass.value[e] = 9;
      c.QuadraticDrag.k[e] = 4;
      setCharge(world, handleOf(world, e), 1);
    }
    stepMany(world, 3); // lifetime 0.05 s = 3 steps: all expire
    expect(particles(world)).toEqual([]);
    expect(emitNow(world, em, 40)).toBe(40);
    const second = particles(world);
    // The slots are reused (bitecs hands out the freed ones first)...
    expect(new Set(second)).toEqual(new Set(first));
    for (const e of second) {
      // ...as new lives (renderers key trails on the stamp) with the emitter's values only.
      expect(world.spawnStamp[e]).toBe(stamps[first.indexOf(e)]! + 1);
      expect(Math.hypot(c.Velocity.x[e]!, c.Velocity.y[e]!)).toBeCloseTo(3, 12);
      expect(c.AngularVelocity.z[e]).toBe(0);
      expect(c.Lifetime.age[e]).toBe(0);
      expect(c.Lifetime.duration[e]).toBe(0.05);
      expect(c.Particle.colorStart[e]).toBe(0x112233);
      expect(c.Particle.generation[e]).toBe(0);
      expect(c.Mass.value[e]).toBe(0.5);
      expect(c.QuadraticDrag.k[e]).toBe(0.01);
      expect(hasComponent(world, e, c.Charge)).toBe(false);
    }
    expectQueriesConsistent(world);
  });

  test('a stale particle handle is refused after its death and after its slot is reused', () => {
    const world = createPhysicsWorld({ gravity: [0, 0], capacity: 50 });
    const em = addEmitter(world, { lifetime: 0.05 });
    emitNow(world, em, 5);
    const old = particles(world).map((e) => handleOf(world, e));
    expect(old.every((h) => isAlive(world, h))).toBe(true);
    stepMany(world, 3);
    for (const h of old) {
      expect(isAlive(world, h)).toBe(false);
      expect(() => setVelocity(world, h, [1, 0])).toThrow(/setVelocity: entity refers to a removed entity/);
    }
    emitNow(world, em, 5);
    for (const h of old) {
      expect(isAlive(world, h)).toBe(false);
      expect(() => setVelocity(world, h, [1, 0])).toThrow(/refers to a removed entity \(id \d+, slot \d+ now holds handle \d+\)/);
    }
    for (const e of particles(world)) expect(isAlive(world, handleOf(world, e))).toBe(true);
  });

  test('births and deaths are counted exactly (fireworks: counters against spawn stamps and a death hook)', () => {
    const def = SCENES.fireworks!;
    const world = createPhysicsWorld(def.worldOptions({ count: 2000 }));
    const h = def.build(world, { count: 2000 }) as { shells: number; sparks: number; embers: number };
    let hooked = 0;
    onParticleDeath(world, () => {
      hooked++;
    });
    const spawned = () => [h.shells, h.sparks, h.embers].reduce((s, em) => s + world.components.Emitter.spawned[em]!, 0);
    const lives = () => world.spawnStamp.reduce((s, x) => s + x, 0);
    stepMany(world, 200);
    const s0 = spawned(),
      l0 = lives(),
      x0 = particlesExpired(world),
      hk0 = hooked,
      alive0 = world.entityIndex.aliveCount;
    let expiredSteps = 0;
    for (let i = 0; i < 150; i++) {
      const before = particlesExpired(world);
      step(world);
      if (particlesExpired(world) > before) expiredSteps++;
    }
    const births = spawned() - s0,
      deaths = particlesExpired(world) - x0;
    expect(births).toBeGreaterThan(1000);
    expect(expiredSteps).toBeGreaterThan(100);
    expect(lives() - l0).toBe(births); // every birth is one new life of a slot, and nothing else was made
    expect(hooked - hk0).toBe(deaths); // every expiry ran the hook once
    expect(world.entityIndex.aliveCount - alive0).toBe(births - deaths); // nothing recycled: capacity has room
    expectQueriesConsistent(world);
  });

  test('force laws see the components a user gives particles, and only while the particle has them', () => {
    // Uniform field E = (3, 0) V/m on charge q = 2 C of mass 1 kg (setCharge's default mass): one step of
    // semi-implicit Euler adds q E h / m = 0.1 m/s to vx (exact up to rounding); an uncharged particle, none.
    const world = createPhysicsWorld({ gravity: [0, 0], capacity: 100 });
    addElectricField(world, { field: [3, 0] });
    const em = addEmitter(world, { speed: [0, 0], lifetime: 0.05 });
    emitNow(world, em, 10);
    for (const e of particles(world)) setCharge(world, handleOf(world, e), 2);
    step(world);
    for (const e of particles(world)) expect(world.components.Velocity.x[e]).toBeCloseTo(0.1, 14);
    stepMany(world, 2); // they expire with the charge on (a component set no emitter gives)
    emitNow(world, em, 10); // new particles in the same slots
    step(world);
    for (const e of particles(world)) expect(world.components.Velocity.x[e]).toBe(0);
    expectQueriesConsistent(world);
    // A birth hook gives every new particle the charge: the law sees each of them from its first step.
    stepMany(world, 2);
    onParticleBirth(world, (w, e) => setCharge(w, handleOf(w, e), 2));
    emitNow(world, em, 10);
    step(world);
    expect(particles(world).length).toBe(10);
    for (const e of particles(world)) expect(world.components.Velocity.x[e]).toBeCloseTo(0.1, 14);
    expectQueriesConsistent(world);
  });

  test('addParticles with mass, drag, charge, lifetime and colour makes the world the setters make one by one', () => {
    // The reference: the same particles made one at a time with addParticle and the public setters
    // (the component data an emitter would write for lifetime and colour), in a world with the same
    // history (slots freed before, so both the recycled and the new-slot paths are taken). Equal
    // state hashes (every bit of every component) before and after 40 steps under drag, an electric
    // field and the lifetimes; tolerance zero.
    const n = 300;
    const make = () => {
      const w = createPhysicsWorld({ capacity: 400, gravity: [0, -9.81] });
      addElectricField(w, { field: [0, 3] });
      const old = [];
      for (let i = 0; i < 50; i++) old.push(addParticle(w, { position: [i, 0] }));
      for (let i = 0; i < 50; i += 2) removeBody(w, old[i]!);
      return w;
    };
    const positions = new Float64Array(2 * n).map((_, i) => i * 0.1 - 3),
      velocities = new Float64Array(2 * n).map((_, i) => (i % 5) - 2);
    const mass = Float64Array.from({ length: n }, (_, i) => 0.5 + (i % 4));
    const lifetime = Float64Array.from({ length: n }, (_, i) => (i % 3 === 0 ? 0.25 : 10));
    const a = make(),
      b = make();
    const ha = Array.from(
      addParticles(a, n, { positions, velocities, mass, linearDrag: 0.3, quadraticDrag: 0.02, charge: -0.5, lifetime, color: 0x336699 }),
    );
    const hb: number[] = [];
    const c = b.components;
    for (let i = 0; i < n; i++) {
      const h = addParticle(b, {
        position: [positions[2 * i]!, positions[2 * i + 1]!],
        velocity: [velocities[2 * i]!, velocities[2 * i + 1]!],
      });
      setMass(b, h, mass[i]!);
      setDrag(b, h, { linear: 0.3 });
      setDrag(b, h, { quadratic: 0.02 });
      setCharge(b, h, -0.5);
      const e = slotOf(h);
      addComponent(b, e, c.Lifetime);
      addComponent(b, e, c.Particle);
      c.Lifetime.age[e] = 0;
      c.Lifetime.duration[e] = lifetime[i]!;
      const P = c.Particle;
      P.emitter[e] = 0;
      P.emitterStamp[e] = 0;
      P.generation[e] = 0;
      P.colorStart[e] = P.colorEnd[e] = 0x336699;
      P.sizeStart[e] = P.sizeEnd[e] = 0.1;
      P.alphaStart[e] = P.alphaEnd[e] = 1;
      hb.push(h);
    }
    expect(ha).toEqual(hb);
    expect(stateHash(a)).toBe(stateHash(b));
    expectQueriesConsistent(a);
    // The lifetimes: a third of them (0.25 s) are gone after 15 steps of 1/60 s, not after 14.
    const alive = (w: PhysicsWorld) => ha.filter((h) => isAlive(w, h)).length;
    stepMany(a, 14);
    expect(alive(a)).toBe(n);
    step(a);
    expect(alive(a)).toBe(n - n / 3);
    stepMany(a, 25);
    stepMany(b, 40);
    expect(stateHash(a)).toBe(stateHash(b));
    expectQueriesConsistent(a);
    // Bad properties are refused, naming the option and the particle, and change nothing.
    const before = a.entityIndex.aliveCount;
    expect(() => addParticles(a, 2, { mass: 0 })).toThrow(/^addParticles: mass must be a finite number > 0, got 0$/);
    expect(() => addParticles(a, 2, { linearDrag: [0.1, -1] })).toThrow(
      /^addParticles: linearDrag\[1\] must be a finite number >= 0, got -1$/,
    );
    expect(() => addParticles(a, 2, { lifetime: [1] })).toThrow(/^addParticles: lifetime must hold 2 numbers \(one a particle\), got 1$/);
    expect(() => addParticles(a, 2, { color: 0x1000000 })).toThrow(/^addParticles: color must be an integer in \[0, 0xFFFFFF\]/);
    expect(() => addParticles(a, 2, { charge: 'x' as never })).toThrow(/^addParticles: charge must be a number or an array of 2 numbers/);
    expect(a.entityIndex.aliveCount).toBe(before);
  });

  test('addParticles makes the same world as addParticle in a loop, and checks its input', () => {
    const n = 500;
    const positions = new Float64Array(2 * n).map((_, i) => i * 0.25 - 7),
      velocities = new Float64Array(2 * n).map((_, i) => (i % 7) - 3);
    const a = createPhysicsWorld({ capacity: 600 }),
      b = createPhysicsWorld({ capacity: 600 });
    const ha = Array.from(addParticles(a, n, { positions, velocities }));
    const hb: number[] = [];
    for (let i = 0; i < n; i++)
      hb.push(
        addParticle(b, { position: [positions[2 * i]!, positions[2 * i + 1]!], velocity: [velocities[2 * i]!, velocities[2 * i + 1]!] }),
      );
    expect(ha).toEqual(hb);
    expect(stateHash(a)).toBe(stateHash(b));
    stepMany(a, 10);
    stepMany(b, 10);
    expect(stateHash(a)).toBe(stateHash(b));
    expectQueriesConsistent(a);
    expect(() => addParticles(a, 101)).toThrow(/addParticles: count must be .*got 101/);
    expect(() => addParticles(a, 2, { positions: [1, 2, 3] })).toThrow(/addParticles: positions must hold 4 numbers/);
    expect(() => addParticles(a, 2, { velocities: [1, 2, NaN, 0] })).toThrow(
      /addParticles: velocities\[2\] must be a finite number, got NaN/,
    );
    expect(a.entityIndex.aliveCount).toBe(n); // refused calls changed nothing
  });

  test('addParticles in bulk (freed slots first, then a long run of new ones) makes the same world as addParticle in a loop', () => {
    // 6,000 particles: above the length (4,096) from which the new slots' ids are appended to bitecs'
    // lists in one go (bulk.ts), after 300 slots freed by removals (taken first, one at a time, as bitecs would).
    const n = 6_000,
      cap = 7_000;
    const positions = new Float64Array(2 * n).map((_, i) => (i % 97) * 0.5 - 20),
      velocities = new Float64Array(2 * n).map((_, i) => (i % 13) - 6);
    const make = () => {
      const w = createPhysicsWorld({ capacity: cap });
      const hs: number[] = [];
      for (let i = 0; i < 600; i++) hs.push(addParticle(w, { position: [i, 1], velocity: [0, 0] }));
      for (let i = 0; i < 600; i += 2) removeBody(w, hs[i]!);
      step(w);
      return w;
    };
    const a = make(),
      b = make();
    const ha = Array.from(addParticles(a, n, { positions, velocities }));
    const hb: number[] = [];
    for (let i = 0; i < n; i++)
      hb.push(
        addParticle(b, { position: [positions[2 * i]!, positions[2 * i + 1]!], velocity: [velocities[2 * i]!, velocities[2 * i + 1]!] }),
      );
    expect(ha).toEqual(hb);
    expect(ecs(a).entityIndex.dense).toEqual(ecs(b).entityIndex.dense);
    expect(stateHash(a)).toBe(stateHash(b));
    stepMany(a, 3);
    stepMany(b, 3);
    expect(stateHash(a)).toBe(stateHash(b));
    expectQueriesConsistent(a);
    // The query lists hold the same entities in the same order as bitecs' own path made them.
    const lists = (w: PhysicsWorld) => Array.from(ecs(w).queries, (q) => Array.from(q.dense));
    expect(lists(a)).toEqual(lists(b));
  });

  test('snapshot and restore with churn: stepping after restore is bit-identical, across a reordering of the query lists', () => {
    const def = SCENES.fireworks!;
    const original = createPhysicsWorld(def.worldOptions({ count: 4000 }));
    def.build(original, { count: 4000 });
    stepMany(original, 320);
    const saved = snapshot(original);
    let reordered = 0,
      last = archetypes(original).order.disorder;
    for (let i = 0; i < 200; i++) {
      step(original);
      const d = archetypes(original).order.disorder;
      if (d < last) reordered++;
      last = d;
    }
    expect(reordered).toBeGreaterThan(0); // the window includes a defragment of the query lists
    const copy = createPhysicsWorld({ dimensions: 2, capacity: original.capacity });
    restore(copy, saved);
    stepMany(copy, 200);
    expect(stateHash(copy)).toBe(stateHash(original));
    expectQueriesConsistent(copy);
  });

  test('births queued and written one array at a time leave every store exactly as births one by one (a birth hook turns the queue off)', () => {
    // The reference is the one-by-one path (spawnOne), which a registered birth hook forces; the hook
    // does nothing, so both worlds must agree on every element of every component store, the entity
    // index and the queries. Fireworks covers bursts (onDeath) and rate births of two kinds; the second
    // emitter (emitNow) the other kinds: a collider (Ball, Material), linear drag and a gravity scale.
    const build = (hooked: boolean): PhysicsWorld => {
      const def = SCENES.fireworks!;
      const world = createPhysicsWorld(def.worldOptions({ count: 3000 }));
      def.build(world, { count: 3000 });
      if (hooked) onParticleBirth(world, () => {});
      const other = addEmitter(world, {
        position: [5, 5],
        shape: 'disc',
        size: 1,
        speed: [1, 4],
        lifetime: [0.2, 0.6],
        particle: { radius: 0.05, mass: 0.01, linearDrag: 0.001, gravityScale: 0.5, colorStart: 0x336699 },
      });
      for (let i = 0; i < 260; i++) {
        if (i % 20 === 0) emitNow(world, other, 150, [i * 0.1, 3], [1, 2]);
        step(world);
      }
      return world;
    };
    const queued = build(false),
      oneByOne = build(true);
    expect(queued.entityIndex.aliveCount).toBeGreaterThan(1500);
    expect(Array.from(queued.entityIndex.dense)).toEqual(Array.from(oneByOne.entityIndex.dense));
    let arrays = 0;
    for (const [name, store] of Object.entries(queued.components)) {
      const other = (oneByOne.components as unknown as Record<string, Record<string, unknown>>)[name]!;
      for (const [field, a] of Object.entries(store as Record<string, unknown>)) {
        if (!ArrayBuffer.isView(a)) continue;
        const b = other[field] as ArrayLike<number>;
        const x = a as unknown as ArrayLike<number>;
        expect(x.length, `${name}.${field}`).toBe(b.length);
        for (let i = 0; i < x.length; i++)
          if (!Object.is(x[i], b[i])) expect(`${name}.${field}[${i}] = ${x[i]}`).toBe(`${name}.${field}[${i}] = ${b[i]}`);
        arrays++;
      }
    }
    expect(arrays).toBeGreaterThan(40);
    expect(stateHash(queued)).toBe(stateHash(oneByOne));
    // The query lists in the same order too (the queued births' query work is done one query at a time).
    const qa = Array.from(ecs(queued).queries),
      qb = Array.from(ecs(oneByOne).queries);
    expect(qa.length).toBe(qb.length);
    for (let i = 0; i < qa.length; i++) expect(Array.from(qa[i]!.dense)).toEqual(Array.from(qb[i]!.dense));
    expectQueriesConsistent(queued);
  });
});
