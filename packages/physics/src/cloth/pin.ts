import { addComponent, hasComponent, removeComponent } from 'bitecs';
import { resolveKind } from '../world/handles.js';
import type { PhysicsWorld } from '../world/options.js';
import { assertVector } from '../world/validate.js';

/**
 * Holds a cloth point (or any dynamic body) fixed at `position` (m), or with `position` null lets it go
 * again. While held it is kinematic with zero velocity: links pull on it as on a pin, so dragging it
 * away tears the cloth around it (links past their `tearStretch`). Call it every frame with the
 * pointer's position to drag.
 * @param point a body's handle.
 * @throws RangeError if `point` is not a live body, or is static; TypeError | RangeError on a bad position.
 * @category Cloth
 */
export function pinClothPoint(world: PhysicsWorld, point: number, position: ArrayLike<number> | null): void {
  const where = 'pinClothPoint';
  const e = resolveKind(world, point, 'body', where, 'point');
  const c = world.components;
  if (hasComponent(world, e, c.Static)) throw new RangeError(`${where}: point must be a moving body, got a static one (id ${point})`);
  if (position !== null) assertVector(where, 'position', position, 2);
  if (position === null) {
    if (hasComponent(world, e, c.Kinematic)) {
      removeComponent(world, e, c.Kinematic);
      const m = c.Mass.value[e]!;
      c.Mass.inv[e] = m > 0 ? 1 / m : 0;
    }
    return;
  }
  if (!hasComponent(world, e, c.Kinematic)) {
    addComponent(world, e, c.Kinematic);
    c.Mass.inv[e] = 0;
  }
  c.Position.x[e] = position[0]!;
  c.Position.y[e] = position[1]!;
  c.PreviousPosition.x[e] = position[0]!;
  c.PreviousPosition.y[e] = position[1]!;
  c.Velocity.x[e] = 0;
  c.Velocity.y[e] = 0;
}
