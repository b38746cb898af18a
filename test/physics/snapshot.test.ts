import { readdirSync, readFileSync, statSync } from 'node:fs';
import { join } from 'node:path';
import {
  addBody,
  addComponent,
  createPhysicsWorld,
  enableThreads,
  type PhysicsWorld,
  restore,
  setBoundary,
  setGravity,
  snapshot,
  stateHash,
  step,
  stepMany,
  type WorldSnapshot,
} from '@bitphysics/physics';
import { query, removeComponent } from 'bitecs';
import { describe, expect, test } from 'vitest';
import { externalWorldStates } from '../../packages/physics/src/world/external-state.js';
import { mixedScene, SNAPSHOT_SCENES } from './snapshot-scenes.js';

// Worlds with threads > 1 need the thread pool (step/enable-threads.ts).
enableThreads();

// Independent reference for every check here: the original world itself. A restored world must step to
// the same state to the last bit (stateHash covers every field of every component of every live entity,
// bit for bit), so the tolerance is zero.

const STEPS = 1000;

function optionsOf(world: PhysicsWorld) {
  return { dimensions: world.dimensions, capacity: world.capacity };
}

describe('snapshot and restore', () => {
  for (const { name, build } of SNAPSHOT_SCENES) {
    test(`${name}: stepping after restore into a new world is bit-identical to stepping the original (${STEPS} steps)`, () => {
      const original = build();
      stepMany(original, 30);
      const saved = snapshot(original);
      stepMany(original, STEPS);
      const expected = stateHash(original);
      // A bare world made with the same dimensions and capacity: everything else comes from the snapshot.
      const copy = createPhysicsWorld(optionsOf(original));
      restore(copy, saved);
      stepMany(copy, STEPS);
      expect(stateHash(copy)).toBe(expected);
    });
  }

  test('restore rewinds a world in place (twice from one snapshot), and the hash sees a one-bit change', () => {
    const world = mixedScene();
    stepMany(world, 20);
    const saved = snapshot(world);
    const atSave = stateHash(world);
    stepMany(world, 200);
    const after = stateHash(world);
    expect(after).not.toBe(atSave);
    restore(world, saved);
    expect(stateHash(world)).toBe(atSave);
    stepMany(world, 200);
    expect(stateHash(world)).toBe(after);
    restore(world, saved);
    const P = world.components.Velocity.x;
    const e = 2;
    const v = P[e]!;
    P[e] = v + Math.abs(v) * Number.EPSILON + Number.MIN_VALUE; // the smallest change of one value
    expect(stateHash(world)).not.toBe(atSave);
  });

  test('a snapshot is transferable: structured clone with its buffers transferred, and its header survives JSON', () => {
    const world = mixedScene();
    stepMany(world, 40);
    const saved = snapshot(world);
    stepMany(world, 100);
    const expected = stateHash(world);
    const json = JSON.parse(JSON.stringify(saved.header)) as WorldSnapshot['header'];
    const moved = structuredClone(saved.buffers, { transfer: saved.buffers });
    expect(saved.buffers.every((b) => b.byteLength === 0)).toBe(true); // detached: they were moved, not copied
    const copy = createPhysicsWorld(optionsOf(world));
    restore(copy, { header: json, buffers: moved });
    stepMany(copy, 100);
    expect(stateHash(copy)).toBe(expected);
  });

  test('entities created after restore take the same slots and handles as in the original', () => {
    const world = mixedScene();
    stepMany(world, 60); // particles have died: their slots wait to be reused in bitecs' order
    const saved = snapshot(world);
    const a = [addBody(world, { position: [0, 5] }), addBody(world, { position: [1, 5] })];
    const copy = createPhysicsWorld(optionsOf(world));
    restore(copy, saved);
    const b = [addBody(copy, { position: [0, 5] }), addBody(copy, { position: [1, 5] })];
    expect(b).toEqual(a);
  });

  test('query lists changed between two snapshots (same lengths, new order) are captured as they are now', () => {
    // The second snapshot may reuse the first one's finding that two lists are equal only if neither
    // changed (world/lean-ecs.ts versions): here one list is reordered without changing its length, and
    // another gains and loses members, so a stale finding would restore the old order.
    const world = createPhysicsWorld({ capacity: 16 });
    const C = world.components;
    const ids: number[] = [];
    for (let i = 0; i < 6; i++) ids.push(addBody(world, { position: [i, 0], velocity: [0, 0] }));
    const awake = () => [...query(world as never, [C.Position, C.Velocity])];
    const before = awake();
    snapshot(world);
    // Take one body out of the queries of Velocity and put it back: it moves to the end of those lists.
    const e = before[1]!;
    const vx = C.Velocity.x[e]!;
    removeComponent(world as never, e, C.Velocity);
    awake(); // a query commits the removal (else the re-add keeps the body's place)
    addComponent(world, e, C.Velocity);
    C.Velocity.x[e] = vx;
    const now = awake();
    expect(now).not.toEqual(before);
    expect([...now].sort()).toEqual([...before].sort());
    const saved = snapshot(world);
    const copy = createPhysicsWorld({ capacity: 16 });
    restore(copy, saved);
    expect([...query(copy as never, [copy.components.Position, copy.components.Velocity])]).toEqual(now);
    expect(stateHash(copy)).toBe(stateHash(world));
    // Rewind: a list reordered after the snapshot is put back in the snapshot's order by restore (a
    // list unchanged since the snapshot may be skipped; this one must not be), twice in a row.
    for (let round = 0; round < 2; round++) {
      removeComponent(world as never, now[0]!, C.Velocity);
      awake();
      addComponent(world, now[0]!, C.Velocity);
      expect(awake()).not.toEqual(now);
      restore(world, saved);
      expect(awake()).toEqual(now);
      expect(stateHash(world)).toBe(stateHash(copy));
    }
  });

  test('trailing-zero trimming keeps every bit: -0 and NaN at the end, odd lengths, small element types, repeated values', () => {
    // The snapshot stores an array up to its last element whose bits are not all zero, read as 64-bit
    // words where aligned; each case below puts the last such element where a word-sized read could misjudge it.
    const world = createPhysicsWorld({ capacity: 10 });
    const cases: Record<string, ArrayLike<number> & { [i: number]: number }> = {
      negZero64: new Float64Array(11),
      nan64: new Float64Array(11),
      negZero32: new Float32Array(11),
      odd32: new Int32Array(11),
      even32: new Uint32Array(12),
      bytes: new Uint8Array(13),
      shorts: new Int16Array(9),
      repeated32: new Uint32Array(11),
      repeated64: new Float64Array(11),
    };
    cases.negZero64![9] = -0;
    cases.nan64![10] = NaN;
    cases.negZero32![10] = -0;
    cases.odd32![10] = -1;
    cases.even32![10] = 7;
    cases.bytes![12] = 1;
    cases.shorts![7] = -2;
    for (let i = 1; i < 11; i++) {
      cases.repeated32![i] = 3;
      cases.repeated64![i] = 0.1;
    }
    (world as unknown as Record<string, unknown>).futureArrays = cases;
    const saved = snapshot(world);
    const expected = Object.fromEntries(Object.entries(cases).map(([k, a]) => [k, Array.from(a)]));
    for (const a of Object.values(cases)) for (let i = 0; i < a.length; i++) a[i] = 5;
    restore(world, saved);
    for (const [k, a] of Object.entries(cases)) {
      const want = expected[k]!;
      for (let i = 0; i < a.length; i++) expect(Object.is(a[i], want[i]), `${k}[${i}]: ${a[i]} vs ${want[i]}`).toBe(true);
    }
  });

  test('stage settings come from the snapshot (gravity, dt, integrator, solver settings)', () => {
    const world = createPhysicsWorld({ capacity: 50, dt: 1 / 120, integrator: 'velocity-verlet', solverSubsteps: 6, gravity: [0, -3] });
    addBody(world, { position: [0, 10] });
    setGravity(world, [1, -2]);
    const saved = snapshot(world);
    const copy = createPhysicsWorld({ capacity: 50 });
    restore(copy, saved);
    expect([copy.dt, copy.integrator, copy.collision.settings.solverSubsteps, [...copy.gravity]]).toEqual([
      1 / 120,
      'velocity-verlet',
      6,
      [1, -2, 0],
    ]);
  });

  test('refused: another capacity or dimensions, or not a snapshot; the world is left as it was', () => {
    const world = mixedScene();
    stepMany(world, 10);
    const saved = snapshot(world);
    const other = createPhysicsWorld({ capacity: 100 });
    addBody(other, { position: [0, 1] });
    const before = stateHash(other);
    expect(() => restore(other, saved)).toThrow(
      'restore: snapshot must come from a world with the same options: it has dimensions 2 and capacity 3000, this world 2 and 100',
    );
    expect(() => restore(createPhysicsWorld({ dimensions: 3, capacity: 3000 }), saved)).toThrow(
      /dimensions 2 and capacity 3000, this world 3 and 3000/,
    );
    expect(() => restore(other, {} as WorldSnapshot)).toThrow(/restore: snapshot must be a value returned by snapshot\(world\)/);
    expect(() => restore(other, { header: { ...saved.header, format: 'x' }, buffers: [] })).toThrow(
      /restore: snapshot must be a bitphysics snapshot/,
    );
    expect(stateHash(other)).toBe(before);
    step(other);
  });
});

describe('snapshot captures every piece of state', () => {
  test('every array of every component store is in the snapshot (found by walking the stores, not by a list)', () => {
    const world = mixedScene();
    stepMany(world, 5);
    const saved = snapshot(world);
    type Enc = { $t: string; o?: number; n?: number; len?: number; rep?: number };
    const stores = (saved.header.state as { v: Record<string, { v: Record<string, { v: Record<string, Enc> }> }> }).v.components.v;
    expect(saved.buffers.length).toBe(1);
    let copied = 0;
    for (const [name, store] of Object.entries(world.components)) {
      const members = query(world, [store as object]).length;
      for (const [field, arr] of Object.entries(store as object)) {
        if (!ArrayBuffer.isView(arr)) continue;
        const a = arr as Float64Array;
        const enc = stores[name]?.v[field];
        expect(enc, `${name}.${field}`).toBeDefined();
        if (enc!.$t === 'unused') {
          // Only a store no entity has may be left out: nothing reads its contents, its allocation is kept.
          expect([members, enc!.n], `${name}.${field}`).toEqual([0, a.length]);
        } else {
          // Stored up to its last non-zero element (or as its first two elements, the second repeated up to
          // `rep`): those bytes exactly, and nothing but zero bits after them.
          expect([enc!.$t, enc!.len], `${name}.${field}`).toEqual([a.constructor.name, a.length]);
          const n = enc!.n!,
            bytes = a.BYTES_PER_ELEMENT,
            end = enc!.rep ?? n;
          const whole = new Uint8Array(a.buffer, a.byteOffset, a.byteLength);
          const stored = new Uint8Array(saved.buffers[0]!, enc!.o!, n * bytes);
          expect(Buffer.from(stored).equals(Buffer.from(whole.subarray(0, n * bytes))), `${name}.${field}`).toBe(true);
          for (let i = n; i < end; i++) {
            expect(
              Buffer.from(whole.subarray(i * bytes, (i + 1) * bytes)).equals(Buffer.from(stored.subarray(bytes, 2 * bytes))),
              `${name}.${field}[${i}]`,
            ).toBe(true);
          }
          expect(
            whole.subarray(end * bytes).every((x) => x === 0),
            `${name}.${field} beyond the stored part`,
          ).toBe(true);
          copied++;
        }
      }
    }
    expect(copied).toBeGreaterThan(60);
  });

  test('an entity with a component outside world.components is refused, not silently dropped', () => {
    const world = createPhysicsWorld({ capacity: 10 });
    addBody(world, { position: [0, 1] });
    const e = addBody(world, { position: [1, 1] });
    expect(() => snapshot(world)).not.toThrow();
    addComponent(world, e, { foreign: new Float64Array(11) });
    expect(() => snapshot(world)).toThrow(
      `snapshot: entity ${e} has a component that is not one of world.components; only those can be captured`,
    );
  });

  test('a store or world field added later is captured and restored without changes to snapshot code', () => {
    const world = createPhysicsWorld({ capacity: 10 });
    const extra = { level: new Float64Array(11) };
    (world.components as unknown as Record<string, unknown>).FutureStore = extra;
    (world as unknown as Record<string, unknown>).futureSetting = { depth: 3 };
    extra.level[4] = 2.5;
    const saved = snapshot(world);
    extra.level[4] = 0;
    (world as unknown as { futureSetting: { depth: number } }).futureSetting.depth = 9;
    restore(world, saved);
    expect(extra.level[4]).toBe(2.5);
    expect((world as unknown as { futureSetting: { depth: number } }).futureSetting.depth).toBe(3);
    // State that is not data is refused rather than silently dropped.
    (world as unknown as Record<string, unknown>).futureHook = () => 1;
    expect(() => snapshot(world)).toThrow(/snapshot: cannot capture world\.futureHook \(a function\)/);
  });

  test('feature state lives on the world: each registered state is world.features[name], made and cleared there', () => {
    // The design: a feature's per-world state is a field of world.features under the name it registers
    // for snapshots (world/external-state.ts), not a module's WeakMap. For every registration, in a 2D
    // and a 3D world: get(world, true) makes the state on the world, clear removes it from there.
    for (const dimensions of [2, 3] as const) {
      const world = createPhysicsWorld({ dimensions, capacity: 16 });
      const names = externalWorldStates().map((e) => e.name);
      expect(names.length).toBeGreaterThanOrEqual(8);
      // A new world holds every registered name, undefined (create-world.ts: one object layout in
      // every world), and nothing else.
      expect(Object.keys(world.features).sort()).toEqual([...names].sort());
      for (const name of names) expect(world.features[name], name).toBeUndefined();
      for (const ext of externalWorldStates()) {
        const state = ext.get(world, true);
        expect(state, ext.name).toBeDefined();
        expect(world.features[ext.name], ext.name).toBe(state);
        ext.clear(world);
        expect(world.features[ext.name], ext.name).toBeUndefined();
        expect(ext.get(world, false), ext.name).toBeUndefined();
      }
    }
  });

  test('per-world scratch lives on the world: no module-level WeakMap is keyed by a world or a part of one', () => {
    // Buffers and caches kept for one world between calls are fields of world.scratch (world/scratch.ts),
    // so a world's whole state is reachable from the world. The module-level WeakMaps left are keyed by
    // objects that are not a world's: a component passed to Not (world/query.ts), a system function
    // (world/trusted-systems.ts: its finite trust, its idle guard), a snapshot (snapshot/ecs-capture.ts
    // `matching`). A key type counts as a world's when it is one of the world's types or a name a file
    // gives one of them or a part of one (`type Stages = PhysicsWorld['stages']`, `Components as C`).
    const kept = [
      'snapshot/ecs-capture.ts: matching',
      'world/query.ts: nots',
      'world/trusted-systems.ts: idleGuards',
      'world/trusted-systems.ts: trusted',
    ];
    const declared = /^(?:export )?const (\w+)\s*=\s*new WeakMap\b/gm;
    const WORLD_TYPES = ['PhysicsWorld', 'PhysicsWorldContext', 'CollisionState', 'Components', 'ContactBuffer', 'WorldScratch'];
    /** The names `src` gives the world's types or their parts: the types themselves, type aliases of them (indexed or not, chained), and imports renamed. */
    const worldNames = (src: string): string[] => {
      const names = [...WORLD_TYPES];
      for (let grew = true; grew; ) {
        grew = false;
        const any = names.join('|');
        const alias = new RegExp(`\\btype\\s+(\\w+)\\s*=\\s*(?:${any})\\s*(?:\\[[^\\]]*\\]\\s*)*;`, 'g');
        const renamed = new RegExp(`\\b(?:${any})\\s+as\\s+(\\w+)`, 'g');
        for (const m of [...src.matchAll(alias), ...src.matchAll(renamed)])
          if (!names.includes(m[1]!)) {
            names.push(m[1]!);
            grew = true;
          }
      }
      return names;
    };
    const keyedByWorld = (src: string): boolean => new RegExp(`new WeakMap<\\s*(?:${worldNames(src).join('|')})\\b`).test(src);
    // Self-check on made-up sources: the patterns see what they look for, aliases and parts included,
    // and a system function (a type that takes a world) is not a world's.
    expect([...'const sourcesOf = new WeakMap<PhysicsWorld, Float64Array>();'.matchAll(declared)].map((m) => m[1])).toEqual(['sourcesOf']);
    expect(keyedByWorld('const scratchOf = new WeakMap<CollisionState, ColorScratch>();')).toBe(true);
    expect(keyedByWorld("type Stages = PhysicsWorld['stages'];\nconst plansOf = new WeakMap<Stages, StagePlans>();")).toBe(true);
    expect(keyedByWorld("type Components = PhysicsWorld['components'];\nconst t = new WeakMap<Components, object[]>();")).toBe(true);
    expect(keyedByWorld("type W = PhysicsWorld;\ntype K = W['collision'];\nconst t = new WeakMap<K, object>();")).toBe(true);
    expect(keyedByWorld("import type { Components as C } from './components.js';\nconst t = new WeakMap<C, object>();")).toBe(true);
    expect(keyedByWorld('type System = (world: PhysicsWorld) => void;\nconst marks = new WeakMap<System, number>();')).toBe(false);
    const root = join(__dirname, '../../packages/physics/src');
    const files: string[] = [];
    const walk = (dir: string) => {
      for (const f of readdirSync(dir)) {
        const p = join(dir, f);
        if (statSync(p).isDirectory()) walk(p);
        else if (p.endsWith('.ts')) files.push(p);
      }
    };
    walk(root);
    expect(files.length).toBeGreaterThan(100);
    const found: string[] = [];
    for (const f of files) {
      const src = readFileSync(f, 'utf8');
      const rel = f.slice(root.length + 1);
      expect(keyedByWorld(src), `${rel} keys a WeakMap by a world or a part of one: keep it in world.scratch`).toBe(false);
      for (const m of src.matchAll(declared)) found.push(`${rel}: ${m[1]}`);
    }
    expect(found.sort()).toEqual(kept);
  });

  test('world.scratch is not stored by snapshots and restore leaves it as it is', () => {
    // A 2D world of balls in a box with substeps fills scratch (the step start, the fused pass's terms,
    // the contact lengths); a snapshot's header has no scratch, and after a restore the world holds the
    // very same scratch objects and steps on exactly as a world restored fresh does.
    const world = createPhysicsWorld({ dimensions: 2, capacity: 400, substeps: 2 });
    setBoundary(world, { min: [-5, 0], max: [5, 20] });
    for (let i = 0; i < 300; i++) addBody(world, { position: [-4.5 + (i % 20) * 0.45, 0.5 + Math.floor(i / 20) * 0.45], radius: 0.2 });
    stepMany(world, 20);
    const scratch = world.scratch;
    const filled = Object.entries(scratch).filter(([, v]) => v !== undefined && !(v instanceof Map && v.size === 0));
    expect(filled.map(([k]) => k)).toEqual(expect.arrayContaining(['stepStart', 'fusedTerms', 'contactLengths']));
    const before = Object.fromEntries(Object.entries(scratch));
    const saved = snapshot(world);
    expect(Object.keys((saved.header.state as { v: object }).v)).not.toContain('scratch');
    stepMany(world, 5);
    restore(world, saved);
    expect(world.scratch).toBe(scratch);
    for (const [k, v] of Object.entries(before)) if (v !== undefined) expect(world.scratch[k as keyof typeof scratch], k).toBe(v);
    const copy = createPhysicsWorld({ dimensions: 2, capacity: 400, substeps: 2 });
    restore(copy, saved);
    expect(copy.scratch).not.toBe(scratch);
    stepMany(world, 30);
    stepMany(copy, 30);
    expect(stateHash(copy)).toBe(stateHash(world));
  });
});
