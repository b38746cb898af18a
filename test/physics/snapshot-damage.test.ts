import {
  addBody,
  addShape3D,
  createPhysicsWorld,
  type PhysicsWorld,
  removeBody,
  restore,
  snapshot,
  stateHash,
  stepMany,
  type WorldSnapshot,
} from '@bitphysics/physics';
import { describe, expect, test } from 'vitest';
import { sealSnapshot } from '../../packages/physics/src/snapshot/snapshot.js';
import { mixedScene } from './snapshot-scenes.js';

// The independent reference for every check here is the world the snapshot was taken from: a restore
// is accepted only if the restored world then steps to the same state to the last bit (stateHash
// covers every field of every live entity's components), and a refused one must leave the target's
// complete state as it was (compared by the checksum of a snapshot of it, which covers the whole
// state tree, and by stepping it on). Tolerance zero throughout.

/** Seeded generator (mulberry32) for the damage patterns, so a failure reproduces. */
function rng(seed: number): () => number {
  let a = seed >>> 0;
  return () => {
    a = (a + 0x6d2b79f5) >>> 0;
    let t = a;
    t = Math.imul(t ^ (t >>> 15), t | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return ((t ^ (t >>> 14)) >>> 0) / 2 ** 32;
  };
}

/** A deep copy of a snapshot (its buffer copied, the original untouched). */
function copyOf(s: WorldSnapshot): WorldSnapshot {
  return { header: structuredClone(s.header), buffers: [s.buffers[0]!.slice(0)] };
}

/** The whole state of `world` as one string: the checksum of a snapshot of it. */
function fingerprint(world: PhysicsWorld): string {
  return snapshot(world).header.checksum;
}

/** The encoded world state tree's value object at `path` (keys of nested `{ $t: 'o', v }` objects). */
function stateAt(s: WorldSnapshot, ...path: string[]): Record<string, unknown> {
  let o = (s.header.state as { v: Record<string, unknown> }).v;
  for (const k of path) o = (o[k] as { v: Record<string, unknown> }).v;
  return o;
}

/** The ids alive in a snapshot: the first aliveCount of its entity index's id list (a range or a stored list). */
function snapshotAlive(s: WorldSnapshot): Int32Array {
  const ecs = s.header.ecs as { aliveCount: number; dense: { i: number }; lists: { $t: string; first?: number; o?: number }[] };
  const list = ecs.lists[ecs.dense.i]!;
  if (list.$t === 'range') return Int32Array.from({ length: ecs.aliveCount }, (_, k) => list.first! + k);
  return new Int32Array(s.buffers[0]!, list.o!, ecs.aliveCount);
}

/** The stored values of component store `component.field` in a snapshot: a view into its buffer (writes edit it). */
function storedArray(s: WorldSnapshot, component: string, field: string): Float64Array {
  const e = stateAt(s, 'components', component)[field] as { $t: string; o: number; n: number; rep?: number };
  if (e.$t !== 'Float64Array' || e.rep !== undefined) throw new Error(`${component}.${field} is not stored element by element`);
  return new Float64Array(s.buffers[0]!, e.o, e.n);
}

describe('restore of a damaged snapshot: refused with a clear error and the world left as it was, or exact', () => {
  const STEPS = 60;
  const original = mixedScene();
  stepMany(original, 30);
  const saved = snapshot(original);
  const atSave = stateHash(original);
  stepMany(original, STEPS);
  const future = stateHash(original);

  /** A target world in another state than the snapshot's (another scene time). */
  function target(): PhysicsWorld {
    const w = mixedScene();
    stepMany(w, 7);
    return w;
  }

  test('200 snapshots with 16 random bytes of their data overwritten: each refused, none restored into another future', () => {
    const random = rng(33);
    const world = target();
    const own = fingerprint(world);
    const ownHash = stateHash(world);
    const bytes = saved.header.bytes ?? saved.buffers[0]!.byteLength; // (the whole buffer for a snapshot without `bytes`)
    let refused = 0,
      exact = 0;
    for (let trial = 0; trial < 200; trial++) {
      const bad = copyOf(saved);
      const u8 = new Uint8Array(bad.buffers[0]!);
      for (let k = 0; k < 16; k++) u8[Math.floor(random() * bytes)] = Math.floor(random() * 256);
      let accepted = true;
      try {
        restore(world, bad);
      } catch (e) {
        accepted = false;
        expect((e as Error).message).toMatch(/^restore: snapshot /);
        expect(stateHash(world)).toBe(ownHash);
      }
      if (accepted) {
        // Only the same bytes written again (an overwrite with the value already there) may pass.
        expect(stateHash(world)).toBe(atSave);
        exact++;
        restore(world, snapshot(target()));
      } else refused++;
    }
    expect(refused + exact).toBe(200);
    expect(fingerprint(world)).toBe(own);
    // The refusals left nothing behind: the target steps as a fresh copy of itself does.
    stepMany(world, 20);
    const fresh = target();
    stepMany(fresh, 20);
    expect(stateHash(world)).toBe(stateHash(fresh));
  });

  test('a truncated, an extended and a swapped buffer are refused; the intact snapshot restores exactly', () => {
    const world = target();
    const own = fingerprint(world);
    const buf = saved.buffers[0]!;
    for (const buffers of [
      [buf.slice(0, buf.byteLength - 8)],
      [buf.slice(0, 16)],
      [new ArrayBuffer(0)],
      [snapshot(target()).buffers[0]!],
    ]) {
      expect(() => restore(world, { header: saved.header, buffers })).toThrow(/^restore: snapshot is damaged/);
      expect(fingerprint(world)).toBe(own);
    }
    // Extended (a longer buffer with the same data first: what `reuse` gives) restores exactly.
    const longer = new ArrayBuffer(buf.byteLength + 64);
    new Uint8Array(longer).set(new Uint8Array(buf));
    restore(world, { header: saved.header, buffers: [longer] });
    expect(stateHash(world)).toBe(atSave);
    stepMany(world, STEPS);
    expect(stateHash(world)).toBe(future);
  });

  test('an edited header value is refused by the checksum; sealed again, out-of-range values are refused by their rules', () => {
    const world = target();
    const own = fingerprint(world);
    const cases: Array<[string[], string, unknown, RegExp]> = [
      [[], 'dt', -1, /^restore: snapshot's world\.dt must be a number in \(0, 1000000\] s \(MAX_TIME_STEP\), got -1$/],
      [[], 'dt', 0, /world\.dt must be/],
      [[], 'dt', { $t: 'n', v: 'NaN' }, /world\.dt must be .* got NaN$/],
      [[], 'substeps', 1e9, /world\.substeps must be an integer in \[1, 64\], got 1000000000$/],
      [[], 'integrator', 'warp', /world\.integrator must be an integrator name, got .warp.$/],
      [['collision', 'settings'], 'solverSubsteps', 1e7, /world\.collision\.settings\.solverSubsteps must be an integer in \[1, 16\]/],
      [['collision', 'settings'], 'solverIterations', -3, /solverIterations must be an integer/],
      [['collision', 'contacts'], 'count', 1e6, /world\.collision\.contacts\.count must be at most world\.collision\.contacts\.capacity/],
      [['joints'], 'rowCount', -1, /world\.joints\.rowCount must be an integer in \[0, /],
      [['cloth'], 'substeps', 1e9, /world\.cloth\.substeps must be an integer in \[0, 1000\]/],
      [[], 'time', { $t: 'n', v: 'Infinity' }, /world\.time must be a finite number/],
      // The boundary's material as setBoundary takes it, and a diagnostic that no world holds as NaN.
      [
        ['collision', 'boundary'],
        'restitution',
        { $t: 'n', v: 'NaN' },
        /world\.collision\.boundary\.restitution must be a number in \[0, 1\], got NaN$/,
      ],
      [['collision', 'boundary'], 'staticFriction', -7, /world\.collision\.boundary\.staticFriction must be a finite number >= 0, got -7$/],
      [['cloth'], 'maxStretch', { $t: 'n', v: 'NaN' }, /world\.cloth\.maxStretch must be a finite number, got NaN$/],
      // The world's options: the header's copy is checked first; the state's must agree with the world.
      [[], 'dimensions', { $t: 'n', v: 'NaN' }, /world\.dimensions must be 2, as in the world it restores into .* got NaN$/],
      [[], 'capacity', 65, /world\.capacity must be \d+, as in the world it restores into .* got 65$/],
    ];
    for (const [path, key, value, message] of cases) {
      const bad = copyOf(saved);
      stateAt(bad, ...path)[key] = value;
      expect(() => restore(world, bad)).toThrow(/^restore: snapshot is damaged: its checksum is/);
      sealSnapshot(bad);
      expect(() => restore(world, bad)).toThrow(message);
      expect(fingerprint(world)).toBe(own);
    }
  });

  test('a snapshot refused late (a damaged array deep in the collision state) has written nothing: the world is as it was', () => {
    const world = target();
    const own = fingerprint(world);
    const ownHash = stateHash(world);
    const bad = copyOf(saved);
    // The sleep stage's union-find parents, with a count past the array: read after the world's
    // settings, clock and component stores in the state tree.
    const parent = stateAt(bad, 'collision', 'sleep').parent as Record<string, unknown>;
    parent.n = (parent.len as number) + 5;
    sealSnapshot(bad);
    expect(() => restore(world, bad)).toThrow(/^restore: snapshot's world\.collision\.sleep\.parent is damaged$/);
    expect(stateHash(world)).toBe(ownHash);
    expect(fingerprint(world)).toBe(own);
    // A damaged entity index (an id listed twice), the last part restore reads.
    const bad2 = copyOf(saved);
    const ecs = bad2.header.ecs as { aliveCount: number };
    ecs.aliveCount = 1e9;
    sealSnapshot(bad2);
    expect(() => restore(world, bad2)).toThrow(
      /^restore: snapshot's ecs\.aliveCount is damaged: must be an integer in \[0, \d+\], got 1000000000$/,
    );
    expect(fingerprint(world)).toBe(own);
  });

  test("a NaN or infinity in a live body's stored state is refused before anything is written", () => {
    const world = target();
    const own = fingerprint(world);
    const alive = snapshotAlive(saved);
    for (const [component, field, value] of [
      ['Position', 'y', Number.NaN],
      ['Velocity', 'x', Number.POSITIVE_INFINITY],
      ['AngularVelocity', 'z', Number.NEGATIVE_INFINITY],
    ] as const) {
      const bad = copyOf(saved);
      const stored = storedArray(bad, component, field);
      // The last live body whose value is stored (values past the last non-zero one are not).
      const body = Math.max(...[...alive].filter((e) => e < stored.length && stored[e] !== 0));
      stored[body] = value;
      sealSnapshot(bad);
      expect(() => restore(world, bad)).toThrow(
        new RegExp(
          `^restore: snapshot's world\\.components\\.${component}\\.${field}\\[${body}\\] must be a finite number \\(entity ${body} is alive and has ${component}\\), got ${value}$`,
        ),
      );
      expect(fingerprint(world)).toBe(own);
    }
  });

  test('a snapshot taken by an older version (no checksum) is refused naming the version', () => {
    const world = target();
    const old = copyOf(saved);
    (old.header as { version: number }).version = 2;
    expect(() => restore(world, old)).toThrow(
      /^restore: snapshot must be a bitphysics snapshot of version 3, got format .bitphysics-snapshot. version 2$/,
    );
  });
});

describe('3D: a ball body made in the slot of a removed shape body', () => {
  /**
   * A box shape body rests on a static box; it is removed and a ball body made in its slot, touching
   * the ground and rolling. `previous` chooses what held the slot: a box shape body (with an inertia
   * tensor) or a ball body (without).
   */
  function build(previous: 'box' | 'ball'): PhysicsWorld {
    const world = createPhysicsWorld({ dimensions: 3, capacity: 64, gravity: [0, -9.81, 0] });
    const ground = addBody(world, { position: [0, -0.5, 0], static: true });
    addShape3D(world, ground, { type: 'box', halfExtents: [5, 0.5, 5] });
    let old: number;
    if (previous === 'box') {
      old = addBody(world, { position: [2, 0.5, 0] });
      addShape3D(world, old, { type: 'box', halfExtents: [0.5, 0.5, 0.5] });
    } else {
      old = addBody(world, { position: [2, 0.5, 0], radius: 0.5 });
    }
    stepMany(world, 20);
    removeBody(world, old);
    addBody(world, { position: [0.3, 0.49, 0.1], radius: 0.5, velocity: [1, 0, 0] });
    return world;
  }

  test('its motion does not depend on what held the slot, and a restore reproduces its future', () => {
    // The reference: the same ball in a slot a ball body held (no tensor left behind). The ball's
    // own inertia (2/5 m r^2) must decide how it rolls, not the removed box's tensor.
    const a = build('box'),
      b = build('ball');
    stepMany(a, 5);
    stepMany(b, 5);
    const saved = snapshot(a);
    stepMany(a, 100);
    stepMany(b, 100);
    const ball = 3;
    expect(a.components.AngularVelocity.z[ball]).toBe(b.components.AngularVelocity.z[ball]);
    expect(a.components.Position.x[ball]).toBe(b.components.Position.x[ball]);
    const copy = createPhysicsWorld({ dimensions: 3, capacity: 64 });
    restore(copy, saved);
    stepMany(copy, 100);
    expect(stateHash(copy)).toBe(stateHash(a));
  });

  test("a removed body's slot is not read: a NaN left there restores, and the future is the same", () => {
    // Removal leaves a slot's data as it was (bitecs), so a world can hold anything there; only live
    // bodies' state must be finite. The reference is the world the snapshot came from.
    const world = createPhysicsWorld({ dimensions: 3, capacity: 16, gravity: [0, -9.81, 0] });
    const bodies = [0, 1, 2].map((i) => addBody(world, { position: [i, 2, 0], radius: 0.3 }));
    stepMany(world, 3);
    removeBody(world, bodies[1]!);
    const saved = snapshot(world);
    const slot = 2; // bodies[1]'s id: ids start at 1
    const x = storedArray(saved, 'Position', 'x');
    expect(x.length).toBeGreaterThan(slot);
    x[slot] = Number.NaN;
    sealSnapshot(saved);
    const copy = createPhysicsWorld({ dimensions: 3, capacity: 16, gravity: [0, -9.81, 0] });
    restore(copy, saved);
    stepMany(copy, 10);
    stepMany(world, 10);
    expect(stateHash(copy)).toBe(stateHash(world));
  });
});
