import type { ParticlesHandles } from '@bitphysics/physics';
import type { BenchScene, ExtraValue } from './types.js';

/**
 * Bench side of `particles`: the count limit of `particlesLayout`, and a position checksum (sum of
 * every coordinate after the last step) that shows whether two engines computed the same states;
 * ours and plain-loop use the same arithmetic in the same order, so their checksums agree exactly.
 */
export const particlesBench: BenchScene = {
  name: 'particles',
  maxCount: 16_000_000,
  bodyIds(handles: unknown): ArrayLike<number> {
    return (handles as ParticlesHandles).particles;
  },
  extras(snapshot) {
    let sum = 0;
    const p = snapshot.positions;
    for (let i = 0; i < p.length; i++) sum += p[i]!;
    return { positionChecksum: sum };
  },
  columns: [
    {
      key: 'positionChecksum',
      label: 'sum of coords (m)',
      format: (v: ExtraValue) => (typeof v === 'number' ? v.toPrecision(12) : String(v)),
    },
  ],
};
