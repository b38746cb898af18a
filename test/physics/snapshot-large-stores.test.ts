import { addBody, createPhysicsWorld, type PhysicsWorld, restore, snapshot, stateHash, stepMany } from '@bitphysics/physics';
import { expect, test } from 'vitest';
import { sealSnapshot } from '../../packages/physics/src/snapshot/snapshot.js';

// Stores longer than 64 kB (capacity 12,000: 96 kB a Float64 store) take the snapshot's native paths
// in Node (snapshot.ts: trailing zeros dropped 64 kB at a time, repeats found by comparing a store
// with itself shifted, restore writing only the zero blocks that are not zero already and leaving a
// repeat that is already in place). Reference: the original world's own arrays; tolerance zero (a
// restore must put back every bit of every component store), and stepping after it bit-identical.

const CAPACITY = 12_000;

/** A world of `n` balls in a row, all of one mass and radius (stores that repeat one value), a few moving sideways. */
function build(n: number, vx: (i: number) => number, mass: number): PhysicsWorld {
  const world = createPhysicsWorld({ dimensions: 2, capacity: CAPACITY, seed: 3, gravity: [0, -9.81] });
  for (let i = 0; i < n; i++) {
    addBody(world, { position: [(i % 200) * 0.3, 1 + Math.floor(i / 200) * 0.3], velocity: [vx(i), 0], radius: 0.1, mass });
  }
  return world;
}

/** Every typed array of every component store, by path. */
function stores(world: PhysicsWorld): Map<string, ArrayBufferView> {
  const out = new Map<string, ArrayBufferView>();
  for (const [name, store] of Object.entries(world.components)) {
    for (const [field, a] of Object.entries(store as Record<string, unknown>)) {
      if (ArrayBuffer.isView(a)) out.set(`${name}.${field}`, a);
    }
  }
  return out;
}

function expectSameBits(a: PhysicsWorld, b: PhysicsWorld): void {
  const sa = stores(a),
    sb = stores(b);
  for (const [path, x] of sa) {
    const y = sb.get(path);
    expect(y, path).toBeDefined();
    const bx = new Uint8Array(x.buffer, x.byteOffset, x.byteLength),
      by = new Uint8Array(y!.buffer, y!.byteOffset, y!.byteLength);
    expect(by.length, path).toBe(bx.length);
    let first = -1;
    for (let i = 0; i < bx.length; i++)
      if (bx[i] !== by[i]) {
        first = i;
        break;
      }
    expect(first, `${path}: first differing byte`).toBe(-1);
  }
}

test('stores over 64 kB: restore into a world holding other values puts back every bit, twice, and steps bit-identically', () => {
  // 11,000 balls: Velocity.x non-zero only for ids below 50 (a zero tail of ~88 kB, more than one
  // 64 kB block), mass and radius one value each (stored as a repeat).
  const world = build(11_000, (i) => (i < 50 ? 0.5 : 0), 2);
  stepMany(world, 2);
  const saved = snapshot(world);
  // The entity list 1 .. 11,000 (no removals) is stored as a range, not 44 kB of ids.
  const lists = (saved.header.ecs as { lists: Array<{ $t: string; first?: number; n?: number }> }).lists;
  expect(lists.some((l) => l.$t === 'range' && l.first === 1 && l.n === 11_000)).toBe(true);
  // The target: more balls (ids up to 11,500), other masses, every one moving sideways: its stores
  // hold non-zero values in every block past the snapshot's stored parts, and another repeated mass.
  const other = build(11_500, (i) => 0.01 * ((i % 7) + 1), 3);
  stepMany(other, 2);
  restore(other, saved);
  expectSameBits(world, other);
  // Again into the same world (now the repeats and the zero blocks are already in place: left alone).
  restore(other, saved);
  expectSameBits(world, other);
  stepMany(world, 20);
  stepMany(other, 20);
  expect(stateHash(other)).toBe(stateHash(world));
});

test('a damaged id range (ids past the capacity) is refused with a RangeError naming the list, the world left as it was', () => {
  const world = build(100, () => 0, 1);
  const saved = snapshot(world);
  const header = JSON.parse(JSON.stringify(saved.header)) as typeof saved.header;
  const lists = (header.ecs as { lists: Array<{ $t: string; first?: number; n?: number }> }).lists;
  const range = lists.find((l) => l.$t === 'range')!;
  expect(range).toBeDefined();
  range.first = CAPACITY;
  const target = build(30, () => 1, 2);
  const before = stateHash(target);
  const bad = { header, buffers: saved.buffers };
  // Its checksum refuses it first; sealed again (as by someone editing it on purpose), the range check does.
  expect(() => restore(target, bad)).toThrow(/^restore: snapshot is damaged: its checksum is/);
  sealSnapshot(bad);
  expect(() => restore(target, bad)).toThrow(/restore: snapshot's ecs\.lists\[\d+\] is damaged/);
  expect(stateHash(target)).toBe(before); // refused before anything was written
});
