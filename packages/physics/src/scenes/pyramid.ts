import { addBox } from '../bodies/shapes-2d.js';
import { assertInteger, optionOr } from '../validation/validate.js';
import { slotOf } from '../world/handles.js';
import type { PhysicsWorld } from '../world/options.js';
import type { SceneDefinition } from './types.js';

/**
 * Options of the `pyramid` scene.
 * @category Scenes
 */
export interface PyramidOptions {
  /** Boxes in the bottom row (the base), integer in [1, 1000]; the pyramid has base (base + 1) / 2 boxes. Default 40 (820 boxes). */
  count?: number;
  /** Unused (the layout is regular); accepted so every scene takes a seed. */
  seed?: number;
}

/**
 * The layout every engine builds for `pyramid` (SI units).
 * @category Scenes
 */
export interface PyramidLayout {
  /** Boxes in the bottom row. */
  base: number;
  /** Boxes in all, base (base + 1) / 2. */
  count: number;
  /** Box half extent, m (boxes are 1 m x 1 m). */
  half: number;
  /** Horizontal distance between box centres in a row, m. */
  pitch: number;
  /** Friction coefficient of boxes and ground. */
  friction: number;
  /** Restitution of boxes and ground. */
  restitution: number;
  /** Areal density of the boxes, kg/m^2 (1 kg boxes). */
  density: number;
  /** Gravity, m/s^2. */
  gravity: [number, number];
  /** Box centres (x0, y0, x1, y1, ...), bottom row first, left to right; rows rest exactly on each other. */
  positions: Float64Array;
  /** The static ground: a box centred at (0, -groundHalf[1]) with these half extents, its top at y = 0. */
  groundHalf: [number, number];
}

/**
 * The layout of `pyramid`: rows of 1 m boxes, each row one box shorter, centred, 1.05 m apart along a
 * row, every row resting exactly on the one below (no gap, no overlap), on a static ground whose top
 * is y = 0 and which reaches 10 m beyond the pyramid on each side.
 * @throws RangeError if count is not an integer in [1, 1000].
 * @category Scenes
 */
export function pyramidLayout(options: PyramidOptions = {}): PyramidLayout {
  const base = optionOr('pyramid', 'count', options.count, 40, assertInteger, 1, 1000);
  const count = (base * (base + 1)) / 2;
  const pitch = 1.05,
    half = 0.5;
  const positions = new Float64Array(2 * count);
  let k = 0;
  for (let row = 0; row < base; row++) {
    const n = base - row;
    for (let i = 0; i < n; i++) {
      positions[k++] = (i - (n - 1) / 2) * pitch;
      positions[k++] = half + row * 2 * half;
    }
  }
  return {
    base,
    count,
    half,
    pitch,
    friction: 0.6,
    restitution: 0,
    density: 1,
    gravity: [0, -10],
    positions,
    groundHalf: [(base * pitch) / 2 + 10, 0.5],
  };
}

/**
 * What `pyramid`'s build returns.
 * @category Scenes
 */
export interface PyramidHandles {
  /** The boxes' entity slots, in layout order (bottom row first). */
  boxes: Uint32Array;
  /** The ground's entity slot. */
  ground: number;
  /** The layout built. */
  layout: PyramidLayout;
}

/**
 * `pyramid`: Box2D's large-pyramid benchmark in 2D: `count` is the base (base 40: 820 boxes of 1 x 1 m,
 * friction 0.6, restitution 0) on a static ground; rows rest exactly on each other with a 1.05 m
 * pitch. The world takes 8 solver substeps (shape contacts are stiff enough to hold a 40-high
 * pyramid to a few centimetres only at 60 Hz, and are stable at 60 Hz with 8 substeps; see
 * solver/contact-scale.ts SHAPE_HERTZ_FRACTION); everything else is the world's default.
 * @category Scenes
 */
export const pyramid: SceneDefinition<PyramidOptions, PyramidHandles> = {
  name: 'pyramid',
  description: 'pyramid of 1 m boxes (friction 0.6, 1.05 m pitch) on a static ground; --count is the base (40: 820 boxes); 2D',
  defaultCount: 40,
  worldOptions(options = {}) {
    const layout = pyramidLayout(options);
    return { dimensions: 2, capacity: layout.count + 16, gravity: layout.gravity, solverSubsteps: 8 };
  },
  build(world: PhysicsWorld, options: PyramidOptions = {}): PyramidHandles {
    if (world.dimensions !== 2) throw new RangeError(`pyramid: needs a 2D world, got dimensions ${world.dimensions}`);
    const layout = pyramidLayout(options);
    const material = { friction: layout.friction, restitution: layout.restitution };
    const ground = slotOf(
      addBox(world, { position: [0, -layout.groundHalf[1]], halfExtents: layout.groundHalf, static: true, ...material }),
    );
    const boxes = new Uint32Array(layout.count);
    const p = layout.positions;
    const half = [layout.half, layout.half];
    for (let i = 0; i < layout.count; i++) {
      boxes[i] = slotOf(addBox(world, { position: [p[2 * i]!, p[2 * i + 1]!], halfExtents: half, density: layout.density, ...material }));
    }
    return { boxes, ground, layout };
  },
};
