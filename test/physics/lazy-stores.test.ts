import {
  addBody,
  addComponent,
  addEmitter,
  addParticle,
  createPhysicsWorld,
  entityExists,
  getEntityComponents,
  hasComponent,
  LAZY_GROUPS,
  Not,
  type PhysicsWorld,
  query as physicsQuery,
  removeComponent,
  restore,
  slotOf,
  snapshot,
  stateHash,
  stepMany,
} from '@bitphysics/physics';
import { $internal, addEntity, getAllEntities, Or, query, removeEntity } from 'bitecs';
import { describe, expect, test } from 'vitest';

// Stores a world never uses are never allocated (world/components.ts), and bitecs' bookkeeping is kept in
// typed arrays (world/lean-ecs.ts). The references here are independent of that code: the documented
// defaults, a brute-force membership check over every entity, and a world that never took the lazy path.

const allocated = (store: object, capacity: number): boolean[] =>
  Object.values(store)
    .filter((a) => ArrayBuffer.isView(a))
    .map((a) => (a as Float64Array).length === capacity + 1);

describe('lazily allocated stores', () => {
  test('a world of bare particles holds only Position, Velocity and PreviousPosition; a body allocates the body group, an emitter the particle group', () => {
    const cap = 50;
    const world = createPhysicsWorld({ capacity: cap });
    for (let i = 0; i < 10; i++) addParticle(world, { position: [i, 1], velocity: [1, 0] });
    const c = world.components as unknown as Record<string, object>;
    for (const [name, store] of Object.entries(c)) {
      const flags = allocated(store, cap);
      const eager = name === 'Position' || name === 'Velocity' || name === 'PreviousPosition';
      expect(
        flags.every((f) => f === eager),
        name,
      ).toBe(true);
    }
    expect(world.collision.invMass.length).toBe(0);
    stepMany(world, 3); // bare particles step without any other store
    expect(world.components.Position.x[1]).toBeCloseTo(0 + 3 / 60, 12);

    const ball = addBody(world, { position: [0, 5], radius: 0.3 });
    for (const name of LAZY_GROUPS[0]!) expect(allocated(c[name]!, cap).every(Boolean), name).toBe(true);
    expect(world.collision.invMass.length).toBe(cap + 1);
    expect(allocated(c.Particle!, cap).some(Boolean)).toBe(false);
    // The store object is the same; its arrays, taken now, hold the body's values (documented defaults).
    expect(world.components.Ball.radius[slotOf(ball)]).toBe(0.3);
    expect(world.components.Material.friction[slotOf(ball)]).toBe(0.6);

    addEmitter(world, { position: [0, 0], rate: 0 });
    expect(allocated(c.Lifetime!, cap).every(Boolean) && allocated(c.Particle!, cap).every(Boolean)).toBe(true);
  });

  test('without interpolation, PreviousPosition waits for the first body and starts at the current positions', () => {
    const world = createPhysicsWorld({ capacity: 20, interpolation: false });
    for (let i = 0; i < 4; i++) addParticle(world, { position: [i, 10], velocity: [1, 0] });
    stepMany(world, 6);
    expect(world.components.PreviousPosition.x.length).toBe(0);
    const b = addBody(world, { position: [0, 0], radius: 0.5 });
    const P = world.components.Position,
      O = world.components.PreviousPosition;
    expect(O.x.length).toBe(21);
    for (let e = 1; e <= 4; e++) expect([O.x[e], O.y[e]]).toEqual([P.x[e], P.y[e]]);
    expect([O.x[slotOf(b)], O.y[slotOf(b)]]).toEqual([0, 0]);
    stepMany(world, 2); // the body keeps its previous position every step (contacts read it)
    expect(O.y[slotOf(b)]).toBeLessThan(0);
    expect(O.y[slotOf(b)]).toBeGreaterThan(P.y[slotOf(b)]!);
  });

  test('a snapshot taken before any body restores into a world that has bodies, and both worlds step alike after the same new body', () => {
    const make = (): PhysicsWorld => createPhysicsWorld({ capacity: 40, seed: 3 });
    const a = make();
    for (let i = 0; i < 5; i++) addParticle(a, { position: [i, 2], velocity: [0, 1] });
    const saved = snapshot(a); // the body group is not allocated in `a`
    const b = make();
    for (let i = 0; i < 12; i++) addBody(b, { position: [i, 3], radius: 0.2, velocity: [1, -2] });
    stepMany(b, 20); // b's body stores and collision scratch hold values for ids that a never had
    restore(b, saved);
    expect(stateHash(b)).toBe(stateHash(a));
    for (const w of [a, b]) {
      addBody(w, { position: [1, 1], radius: 0.4 });
      addBody(w, { position: [1.5, 1], radius: 0.4, velocity: [-1, 0] });
      stepMany(w, 60);
    }
    expect(stateHash(b)).toBe(stateHash(a));
  });
});

describe('lean bitecs bookkeeping', () => {
  test('queries, component lists and recycled ids match a brute-force check after a seeded mix of adds and removals', () => {
    const world = createPhysicsWorld({ capacity: 200 });
    const c = world.components;
    const stores = [c.Position, c.Velocity, c.Mass, c.Ball, c.LinearDrag];
    let seed = 12345;
    const rand = (): number => (seed = (Math.imul(seed, 1103515245) + 12345) >>> 0) / 2 ** 32;
    const alive = new Set<number>();
    for (let k = 0; k < 2000; k++) {
      const r = rand();
      if (r < 0.3 && alive.size < 200) {
        const e = addEntity(world);
        alive.add(e);
      } else if (r < 0.45 && alive.size > 0) {
        const e = [...alive][Math.floor(rand() * alive.size)]!;
        removeEntity(world, e);
        alive.delete(e);
      } else if (alive.size > 0) {
        const e = [...alive][Math.floor(rand() * alive.size)]!;
        const s = stores[Math.floor(rand() * stores.length)]!;
        if (rand() < 0.7) addComponent(world, e, s);
        else removeComponent(world, e, s);
      }
    }
    for (const e of alive) expect(entityExists(world, e)).toBe(true);
    // Every query holds exactly the live entities with (and without) its terms.
    const pairs: Array<[object, object]> = [
      [c.Position, c.Velocity],
      [c.Mass, c.Ball],
      [c.Position, c.LinearDrag],
    ];
    for (const [s1, s2] of pairs) {
      const got = [...query(world, [s1, s2])].sort((x, y) => x - y);
      const want = [...alive].filter((e) => hasComponent(world, e, s1) && hasComponent(world, e, s2)).sort((x, y) => x - y);
      expect(got).toEqual(want);
    }
    // Component lists come from the masks: exactly the stores the entity has (force laws bring Force).
    const every = Object.values(c) as object[];
    for (const e of alive) {
      const listed = new Set(getEntityComponents(world, e));
      for (const s of every) expect(listed.has(s), `entity ${e}`).toBe(hasComponent(world, e, s));
      expect(listed.size).toBe(every.filter((s) => hasComponent(world, e, s)).length);
    }
    // A recycled id carries nothing of its previous life: no component, and Position's documented reset.
    const e = [...alive][0]!;
    addComponent(world, e, c.Position);
    addComponent(world, e, c.Velocity);
    c.Velocity.x[e] = 7;
    removeEntity(world, e);
    const again = addEntity(world);
    expect(again).toBe(e);
    expect(getEntityComponents(world, again)).toEqual([]);
    addComponent(world, again, c.Position);
    addComponent(world, again, c.Velocity);
    expect(c.Velocity.x[again]).toBe(0);
  });

  test('a query made while entities exist holds the matching entities in the entity index order (Not, Or, two mask generations)', () => {
    const world = createPhysicsWorld({ capacity: 300 });
    const c = world.components;
    // Components from both ends of the registration order: the first 31 share one mask word, later ones another.
    const all = Object.values(c) as object[];
    const ctx = (world as unknown as Record<symbol, { componentMap: Map<object, { generationId: number }>; queries: Set<object> }>)[
      $internal
    ]!;
    const late = all.filter((s) => (ctx.componentMap.get(s)?.generationId ?? 0) > 0).slice(0, 3);
    expect(late.length).toBe(3);
    const stores = [c.Position, c.Velocity, c.Mass, c.Ball, ...late];
    let seed = 777;
    const rand = (): number => (seed = (Math.imul(seed, 1103515245) + 12345) >>> 0) / 2 ** 32;
    for (let k = 0; k < 250; k++) {
      const e = addEntity(world);
      for (const s of stores) if (rand() < 0.5) addComponent(world, e, s);
      if (rand() < 0.1) removeEntity(world, e);
    }
    const ordered = (has: (e: number) => boolean): number[] => Array.from(getAllEntities(world)).filter(has);
    const cases: Array<[object[], (e: number) => boolean]> = [
      [
        [c.Position, c.Velocity, Not(c.Ball)],
        (e) => hasComponent(world, e, c.Position) && hasComponent(world, e, c.Velocity) && !hasComponent(world, e, c.Ball),
      ],
      [[c.Mass, Not(c.Ball)], (e) => hasComponent(world, e, c.Mass) && !hasComponent(world, e, c.Ball)],
      [[c.Position, late[0]!], (e) => hasComponent(world, e, c.Position) && hasComponent(world, e, late[0]!)],
      [[late[1]!, Not(c.Ball)], (e) => hasComponent(world, e, late[1]!) && !hasComponent(world, e, c.Ball)],
      [[Or(c.Ball, late[2]!)], (e) => hasComponent(world, e, c.Ball) || hasComponent(world, e, late[2]!)],
    ];
    for (const [terms, has] of cases) {
      const want = ordered(has);
      expect(want.length).toBeGreaterThan(5);
      const before = ctx.queries.size;
      expect(Array.from(physicsQuery(world, terms))).toEqual(want);
      expect(ctx.queries.size, 'a query new to the world').toBe(before + 1);
    }
  });
});
