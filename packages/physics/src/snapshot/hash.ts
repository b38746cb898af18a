import { $internal, hasComponent } from 'bitecs';
import type { PhysicsWorld } from '../world/options.js';

const f64 = new Float64Array(1);
const u32 = new Uint32Array(f64.buffer);

/**
 * A 64-bit fingerprint (16 hex digits) of a world's state: the time, the step count, and for every live
 * entity in slot order, its slot, spawn stamp and every field of every component it has (the bits of
 * each value, so -0 and 0 differ and NaN payloads count). Two worlds with the same hash hold the same
 * bodies with the same state to the last bit (up to hash collisions, about 2^-64 for unrelated states).
 * Use it to compare runs across processes and machines (determinism), or a replay with its recording.
 *
 * Hash: two 32-bit FNV-1a streams (Fowler, Noll and Vo) over the 32-bit words, with different offset bases.
 * @category Snapshots
 */
export function stateHash(world: PhysicsWorld): string {
  let h1 = 0x811c9dc5,
    h2 = 0x01000193 ^ 0x9e3779b9;
  const word = (w: number) => {
    h1 = Math.imul(h1 ^ (w & 0xffff), 0x01000193);
    h1 = Math.imul(h1 ^ (w >>> 16), 0x01000193);
    h2 = Math.imul(h2 ^ (w >>> 16), 0x01000193);
    h2 = Math.imul(h2 ^ (w & 0xffff), 0x01000193);
  };
  const num = (v: number) => {
    f64[0] = v;
    word(u32[0]!);
    word(u32[1]!);
  };
  num(world.time);
  num(world.steps);
  const ix = (world as unknown as Record<symbol, { entityIndex: { aliveCount: number; dense: number[] } }>)[$internal]!.entityIndex;
  const alive = Int32Array.from(ix.dense.slice(0, ix.aliveCount)).sort();
  const stores = Object.entries(world.components).map(
    ([, s]) => [s, Object.values(s as object).filter((a) => ArrayBuffer.isView(a))] as const,
  );
  for (let i = 0; i < alive.length; i++) {
    const e = alive[i]!;
    word(e);
    word(world.spawnStamp[e]!);
    for (let c = 0; c < stores.length; c++) {
      const [store, arrays] = stores[c]!;
      if (!hasComponent(world, e, store)) continue;
      word(c);
      for (const a of arrays) {
        const arr = a as unknown as ArrayLike<number>;
        // Per-entity arrays have capacity + 1 entries; strided ones (shape vertices) hold 8 an entity.
        const stride = Math.max(1, Math.floor(arr.length / (world.capacity + 1)));
        for (let k = 0; k < stride; k++) num(arr[e * stride + k] ?? 0);
      }
    }
  }
  return (h1 >>> 0).toString(16).padStart(8, '0') + (h2 >>> 0).toString(16).padStart(8, '0');
}
