import type { PhysicsWorld } from '../world/options.js';

/**
 * The softened inverse-square pair sum shared by mutual gravity and Coulomb's law: for every pair
 * (a, b) of `ents`, the force on a is
 *   F_a = scale s_a s_b (x_b - x_a) / (|x_b - x_a|^2 + eps2)^(3/2)
 * and the opposite acts on b (Newton's third law, so momentum is conserved to rounding). Gravity
 * uses scale = G and s = mass (attraction); Coulomb uses scale = -k and s = charge (like charges
 * repel). Adds into the Force accumulator; bodies with s = 0 are skipped. Cost N(N-1)/2 pairs.
 * Source: Aarseth, Gravitational N-Body Simulations (2003), ch. 2 (Plummer softening).
 * @param ents entity ids (a live query array); `s` the per-entity source strength (kg or C);
 *   `scale` the coupling constant with its sign; `eps2` the squared softening length, m^2 (>= 0).
 * @category Forces
 */
export function inverseSquarePairs(world: PhysicsWorld, ents: ArrayLike<number>, s: ArrayLike<number>, scale: number, eps2: number): void {
  const c = world.components;
  const n = ents.length;
  const { x: px, y: py, z: pz } = c.Position;
  const { x: fx, y: fy, z: fz } = c.Force;
  for (let i = 0; i < n; i++) {
    const a = ents[i]!;
    const sa = scale * s[a]!;
    if (sa === 0) continue;
    const xa = px[a]!,
      ya = py[a]!,
      za = pz[a]!;
    let sx = 0,
      sy = 0,
      sz = 0;
    for (let j = i + 1; j < n; j++) {
      const b = ents[j]!;
      const dx = px[b]! - xa,
        dy = py[b]! - ya,
        dz = pz[b]! - za;
      const r2 = dx * dx + dy * dy + dz * dz + eps2;
      if (r2 === 0) continue;
      const k = (sa * s[b]!) / (r2 * Math.sqrt(r2));
      const kx = k * dx,
        ky = k * dy,
        kz = k * dz;
      sx += kx;
      sy += ky;
      sz += kz;
      fx[b] = fx[b]! - kx;
      fy[b] = fy[b]! - ky;
      fz[b] = fz[b]! - kz;
    }
    fx[a] = fx[a]! + sx;
    fy[a] = fy[a]! + sy;
    fz[a] = fz[a]! + sz;
  }
}
