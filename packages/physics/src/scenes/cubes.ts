import { addBody, setBoundary } from '../bodies/api.js';
import { addShape3D } from '../bodies/shapes-3d.js';
import { slotOf } from '../world/handles.js';
import type { PhysicsWorld } from '../world/options.js';

/**
 * Adds `count` cubes of half extent `half` (m) and mass `mass` (kg) at rest, axis-aligned, centred at
 * positions (x0, y0, z0, x1, ...; m), each a body with one box shape of the given friction and
 * restitution; returns their body slots in that order. Shared by the box-pile-3d and pyramid-3d scenes.
 * @category Scenes
 */
export function addCubes(
  world: PhysicsWorld,
  positions: Float64Array,
  count: number,
  half: number,
  mass: number,
  material: { friction: number; restitution: number },
): Uint32Array {
  const boxes = new Uint32Array(count);
  const p = positions,
    extents = [half, half, half];
  const density = mass / (8 * half * half * half);
  for (let i = 0; i < count; i++) {
    const b = addBody(world, { position: [p[3 * i]!, p[3 * i + 1]!, p[3 * i + 2]!] });
    addShape3D(world, b, { type: 'box', halfExtents: extents, density, ...material });
    boxes[i] = slotOf(b);
  }
  return boxes;
}

/**
 * Closes `world` in the layout's box (inner corners min and max, m; the balls' restitution and
 * friction) and adds its `count` balls (2D) or spheres (3D: `dims` 3) at rest, centred at `positions`
 * (`dims` numbers a ball, m), of its radius (m) and mass (kg); returns their entity ids in layout
 * order. Shared by the balls-in-box and spheres-in-box scenes.
 * @category Scenes
 */
export function addBallsInBox(
  world: PhysicsWorld,
  layout: Record<'count' | 'radius' | 'mass' | 'restitution' | 'friction', number> & Record<'positions' | 'min' | 'max', ArrayLike<number>>,
  dims: 2 | 3,
): Uint32Array {
  setBoundary(world, { min: layout.min, max: layout.max, restitution: layout.restitution, friction: layout.friction });
  const balls = new Uint32Array(layout.count);
  const p = layout.positions,
    pos = dims === 2 ? [0, 0] : [0, 0, 0];
  for (let i = 0; i < layout.count; i++) {
    for (let d = 0; d < dims; d++) pos[d] = p[dims * i + d]!;
    balls[i] = addBody(world, {
      position: pos,
      radius: layout.radius,
      mass: layout.mass,
      restitution: layout.restitution,
      friction: layout.friction,
    });
  }
  return balls;
}
