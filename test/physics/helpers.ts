import {
  contactSpringEnergy,
  createPhysicsWorld,
  forEachContact,
  gravitationalPotentialEnergy,
  kineticEnergy,
  type PhysicsWorld,
  slotOf,
} from '@bitphysics/physics';

/** Mechanical energy as the soft-contact model defines it: kinetic + gravitational + contact springs, J. */
export function modelEnergy(world: PhysicsWorld): number {
  return kineticEnergy(world) + gravitationalPotentialEnergy(world) + contactSpringEnergy(world);
}

/** A world with no gravity, for collision tests. */
export function zeroGravityWorld(dimensions: 2 | 3 = 2): PhysicsWorld {
  return createPhysicsWorld({ dimensions, gravity: dimensions === 2 ? [0, 0] : [0, 0, 0] });
}

/** The largest overlap between any two of `ids` (balls of radius r), m, found with a uniform grid. */
export function maxPairOverlap(world: PhysicsWorld, ids: ArrayLike<number>): number {
  const P = world.components.Position,
    R = world.components.Ball.radius;
  let rMax = 0;
  for (let i = 0; i < ids.length; i++) rMax = Math.max(rMax, R[ids[i]!]!);
  const cell = 2 * rMax;
  const grid = new Map<string, number[]>();
  const key = (x: number, y: number, z: number) => `${Math.floor(x / cell)},${Math.floor(y / cell)},${Math.floor(z / cell)}`;
  for (let i = 0; i < ids.length; i++) {
    const e = ids[i]!;
    const k = key(P.x[e]!, P.y[e]!, P.z[e]!);
    const list = grid.get(k) ?? [];
    list.push(e);
    grid.set(k, list);
  }
  let worst = 0;
  for (let i = 0; i < ids.length; i++) {
    const e = ids[i]!;
    const cx = Math.floor(P.x[e]! / cell),
      cy = Math.floor(P.y[e]! / cell),
      cz = Math.floor(P.z[e]! / cell);
    for (let dx = -1; dx <= 1; dx++)
      for (let dy = -1; dy <= 1; dy++)
        for (let dz = -1; dz <= 1; dz++) {
          for (const f of grid.get(`${cx + dx},${cy + dy},${cz + dz}`) ?? []) {
            if (f <= e) continue;
            const d = Math.hypot(P.x[f]! - P.x[e]!, P.y[f]! - P.y[e]!, P.z[f]! - P.z[e]!);
            worst = Math.max(worst, R[e]! + R[f]! - d);
          }
        }
  }
  return worst;
}

/** Contact points of the last step between bodies a and b (either order), with the least separation. */
export function pairContacts(world: PhysicsWorld, a: number, b: number): { points: number; minSep: number } {
  const ea = slotOf(a),
    eb = slotOf(b);
  let points = 0,
    minSep = Infinity;
  forEachContact(world, (c) => {
    if ((c.bodyA === ea && c.bodyB === eb) || (c.bodyA === eb && c.bodyB === ea)) {
      points++;
      minSep = Math.min(minSep, c.separation);
    }
  });
  return { points, minSep };
}
