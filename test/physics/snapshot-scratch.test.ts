import { createPhysicsWorld, type PhysicsWorld, restore, SCENES, snapshot, stateHash, stepMany } from '@bitphysics/physics';
import { expect, test } from 'vitest';
import { sealSnapshot } from '../../packages/physics/src/snapshot/snapshot.js';
import { mixedScene } from './snapshot-scenes.js';

// Per-step collision scratch (margins, the pair list, solver indices and rows) and the solver's marks
// are not stored in a snapshot (snapshot.ts, SCRATCH and STAMPED): restore keeps the world's own arrays.
// Reference: the same snapshot restored into a new world; both worlds then take the same different path
// (a kick the original never had), so marks and rows left from the rewound world's own later steps
// would change its solve if they counted. Tolerance zero: stateHash compares every bit of every body.

function kick(world: PhysicsWorld): void {
  const v = world.components.Velocity;
  for (let e = 1; e < v.x.length; e++)
    if (v.x[e] !== 0 || v.y[e] !== 0) {
      v.x[e] = -v.y[e]! * 0.5;
      v.y[e] = v.x[e]! + 3;
    }
}

function ballsInBox(count: number): PhysicsWorld {
  const def = SCENES['balls-in-box']!;
  const world = createPhysicsWorld(def.worldOptions({ count }));
  def.build(world, { count });
  return world;
}

for (const [name, build, ahead] of [
  ['balls-in-box', () => ballsInBox(300), 1],
  ['mixed', mixedScene, 1],
] as const) {
  test(`${name}: a world rewound ${ahead} step(s), then sent another way, steps as a new world restored from the same snapshot`, () => {
    const world = build();
    stepMany(world, 40);
    const saved = snapshot(world);
    const stamp = world.collision.solverStamp;
    stepMany(world, ahead); // marks, rows and pairs of steps the snapshot has not seen
    restore(world, saved);
    // The counter the marks are compared with never goes back (else a mark of the undone steps could
    // match in the next steps: with one step undone, in the very next one).
    expect(world.collision.solverStamp).toBeGreaterThanOrEqual(stamp + ahead);
    const copy = createPhysicsWorld({ dimensions: world.dimensions, capacity: world.capacity });
    restore(copy, saved);
    expect(stateHash(copy)).toBe(stateHash(world));
    kick(world);
    kick(copy);
    stepMany(world, 80);
    stepMany(copy, 80);
    expect(stateHash(copy)).toBe(stateHash(world));
  });
}

test('per-step scratch is kept as type and length only, and a world without collision arrays gets zeroed ones of that length', () => {
  const world = ballsInBox(200);
  stepMany(world, 30);
  const saved = snapshot(world);
  const collision = (saved.header.state as { v: Record<string, { v: Record<string, Record<string, unknown>> }> }).v.collision!.v;
  for (const key of ['margin', 'pairA', 'pairB', 'pairKind', 'solverIndex', 'solverMark', 'bodyState', 'bodyExtra', 'bodyImpact']) {
    expect(collision[key]!.$t, key).toBe('scratch');
  }
  const copy = createPhysicsWorld({ dimensions: world.dimensions, capacity: world.capacity });
  expect(copy.collision.margin.length).toBe(0); // no body yet: no collision arrays
  restore(copy, saved);
  expect(copy.collision.margin.length).toBe(world.capacity + 1);
  expect(copy.collision.solverMark.length).toBe(world.capacity + 1);
  expect(copy.collision.solverMark.every((m) => m === 0)).toBe(true);
});

test('contact buffers are stored up to their count: restore puts back every row below it bit for bit, zeros included (the 2D tangents derived from the normals), and the buffer between steps stores nothing', () => {
  const world = ballsInBox(300);
  stepMany(world, 40);
  const saved = snapshot(world);
  const contacts = (saved.header.state as { v: Record<string, { v: Record<string, { v: Record<string, Record<string, unknown>> }> }> }).v
    .collision!.v.contacts!.v;
  expect(world.collision.contacts.count).toBe(0); // holds no rows between steps (contacts.ts)
  for (const [key, e] of Object.entries(contacts)) if (typeof e === 'object' && e !== null && 'o' in e) expect(e.n, key).toBe(0);
  // The 2D tangents of the cached rows are (-ny, nx): stored as notes, derived by restore (checked bit for bit below).
  const cached = (
    saved.header.state as {
      v: Record<string, { v: Record<string, { v: Record<string, { v: Record<string, Record<string, unknown>> }> }> }>;
    }
  ).v.collision!.v.cache!.v.rows!.v;
  expect(cached.t1x!.$t).toBe('tangent2d');
  expect(cached.t1y!.$t).toBe('tangent2d');
  // Another world, stepped further: its contact rows differ, and more of them.
  const other = ballsInBox(300);
  stepMany(other, 90);
  const rows = world.collision.cache.rows as unknown as Record<string, ArrayLike<number>>;
  const n = world.collision.cache.rows.count;
  expect(n).toBeGreaterThan(10);
  const before = new Map(
    Object.entries(rows)
      .filter(([, a]) => ArrayBuffer.isView(a))
      .map(([k, a]) => [k, Array.from(a).slice(0, n)]),
  );
  restore(other, saved);
  const got = other.collision.cache.rows as unknown as Record<string, ArrayLike<number>>;
  expect(other.collision.cache.rows.count).toBe(n);
  for (const [k, want] of before) {
    // Bits, so -0 and 0 differ: Object.is per row.
    const have = Array.from(got[k]!).slice(0, n);
    expect(
      have.every((x, i) => Object.is(x, want[i])),
      k,
    ).toBe(true);
  }
  stepMany(world, 50);
  stepMany(other, 50);
  expect(stateHash(other)).toBe(stateHash(world));
});

test('a replica restored again and again from snapshots of another world (query lists that changed, and that did not) steps like that world', () => {
  const world = mixedScene();
  const replica = createPhysicsWorld({ dimensions: world.dimensions, capacity: world.capacity });
  stepMany(world, 20);
  restore(replica, snapshot(world));
  // Particles are born and die between these snapshots: the query lists holding them change.
  for (const steps of [0, 25, 1, 30]) {
    stepMany(world, steps);
    const saved = snapshot(world);
    restore(replica, saved);
    expect(stateHash(replica)).toBe(stateHash(world));
  }
  // stateHash does not see query lists: stepping does (their members and order).
  stepMany(world, 20);
  stepMany(replica, 20);
  expect(stateHash(replica)).toBe(stateHash(world));
  stepMany(replica, 3); // the replica's own lists move on, then it is restored again
  restore(replica, snapshot(world));
  stepMany(world, 20);
  stepMany(replica, 20);
  expect(stateHash(replica)).toBe(stateHash(world));
});

test("an Int32Array whose element i is i (the sleep stage's union-find parents between island searches) keeps element 0 only, and restore writes 1, 2, ... back over other values", () => {
  const world = ballsInBox(300);
  stepMany(world, 40);
  const parent = world.collision.sleep.parent;
  const used = parent.findLastIndex((x) => x !== 0) + 1;
  expect(used).toBeGreaterThan(64);
  for (let i = 1; i < used; i++) expect(parent[i]).toBe(i); // the premise: no island search yet
  const saved = snapshot(world);
  const enc = (saved.header.state as { v: Record<string, { v: Record<string, { v: Record<string, Record<string, unknown>> }> }> }).v
    .collision!.v.sleep!.v.parent!;
  expect(enc.iota).toBe(used);
  expect(enc.n).toBe(1);
  // Another world whose parents hold other values (scribbled over: a union-find that merged islands).
  const other = ballsInBox(300);
  stepMany(other, 10);
  for (let i = 1; i < other.collision.sleep.parent.length; i += 3) other.collision.sleep.parent[i] = 7;
  restore(other, saved);
  expect(Array.from(other.collision.sleep.parent)).toEqual(Array.from(parent));
  // A damaged count (past the array) is refused with the array's path.
  const bad = structuredClone(saved);
  (bad.header.state as { v: Record<string, { v: Record<string, { v: Record<string, Record<string, unknown>> }> }> }).v.collision!.v.sleep!.v
    .parent!.iota = parent.length + 5;
  sealSnapshot(bad); // past the checksum, as a snapshot edited on purpose
  expect(() => restore(createPhysicsWorld(def300()), bad)).toThrow(/restore: snapshot's world\.collision\.sleep\.parent is damaged/);
  stepMany(world, 30);
  stepMany(other, 30);
  expect(stateHash(other)).toBe(stateHash(world));
});

function def300(): ReturnType<NonNullable<(typeof SCENES)['balls-in-box']>['worldOptions']> {
  return SCENES['balls-in-box']!.worldOptions({ count: 300 });
}
