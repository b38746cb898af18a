import {
  addBody,
  addBox,
  addDistanceJoint,
  addHeightField3D,
  addHingeJoint3D,
  addMouseJoint,
  addShape3D,
  createPhysicsWorld,
  createRope,
  MAX_HEIGHT_FIELD_POINTS,
  MAX_HULL_VERTICES,
  setShapeFilter,
  slotOf,
} from '@bitphysics/physics';
import { describe, expect, test } from 'vitest';

/**
 * Error messages of the rigid-body API (issue 33): every refusal reads `<function>: <param> must be
 * <rule>, got <value>` and names the function the user called; documented defaults are accepted when
 * given explicitly; size limits are documented and checked before any work.
 */
describe('clear errors', () => {
  test("addBox refuses a ball's option naming addBox, the option and the valid ones", () => {
    const world = createPhysicsWorld({ capacity: 8 });
    expect(() => addBox(world, { halfExtents: [1, 1], mass: 3 } as never)).toThrow(
      /^addBox: unknown option "mass"; known options are .*halfExtents.*density/,
    );
    expect(() => addBox(world, { halfExtents: [1, 1], velocity: [1] })).toThrow(/^addBox: velocity must be an array of 2 numbers/);
    expect(() => addBox(world, { halfExtents: [1, 1], density: null } as never)).toThrow(/^addBox: density must be a value/);
    expect(world.entityIndex.aliveCount).toBe(0);
  });

  test('breakForce Infinity, the documented default, is accepted', () => {
    const world = createPhysicsWorld({ capacity: 64 });
    const a = addBody(world, { position: [0, 0] }),
      b = addBody(world, { position: [1, 0] });
    const j = addDistanceJoint(world, { a, b, breakForce: Infinity, breakTorque: Infinity });
    expect(world.components.Joint.breakForce[slotOf(j)]).toBe(Infinity);
    expect(createRope(world, { start: [0, 5], end: [1, 5], segments: 2, breakForce: Infinity }).joints.length).toBe(2);
    const w3 = createPhysicsWorld({ dimensions: 3, capacity: 8 });
    const c = addBody(w3, { position: [0, 0, 0] }),
      d = addBody(w3, { position: [1, 0, 0] });
    expect(() => addHingeJoint3D(w3, { a: c, b: d, axis: [0, 0, 1], breakForce: Infinity })).not.toThrow();
    expect(() => addDistanceJoint(world, { a, b, breakForce: 0 })).toThrow(/^addDistanceJoint: breakForce must be > 0/);
  });

  test('setShapeFilter without a filter is a TypeError naming the filter', () => {
    const world = createPhysicsWorld({ capacity: 8 });
    const box = addBox(world, { halfExtents: [1, 1] });
    expect(() => setShapeFilter(world, box, undefined as never)).toThrow(/^setShapeFilter: filter must be an object, got undefined/);
    expect(() => setShapeFilter(world, box, { mask: null } as never)).toThrow(/^setShapeFilter: filter.mask must be a value/);
  });

  test("addShape3D with type '__proto__' is refused like any unknown type", () => {
    const world = createPhysicsWorld({ dimensions: 3, capacity: 8 });
    const b = addBody(world, { position: [0, 0, 0] });
    expect(() => addShape3D(world, b, { type: '__proto__' } as never)).toThrow(/^addShape3D: type must be one of 'sphere'/);
    expect(() => addShape3D(world, b, { type: 'constructor' } as never)).toThrow(/^addShape3D: type must be one of 'sphere'/);
  });

  test('addMouseJoint on a static body blames the body, not an option that was not passed', () => {
    const world = createPhysicsWorld({ capacity: 8 });
    const ground = addBody(world, { position: [0, 0], static: true });
    expect(() => addMouseJoint(world, { b: ground })).toThrow(/^addMouseJoint: b must be a dynamic body/);
  });

  test('a hull whose convex hull is too big is refused before the whole hull is built', () => {
    // 200 points on a sphere (Fibonacci lattice): all are hull vertices, more than MAX_HULL_VERTICES.
    const pts: number[][] = [];
    for (let i = 0; i < 200; i++) {
      const z = 1 - (2 * (i + 0.5)) / 200,
        r = Math.sqrt(1 - z * z),
        t = i * 2.399963229728653;
      pts.push([r * Math.cos(t), r * Math.sin(t), z]);
    }
    const world = createPhysicsWorld({ dimensions: 3, capacity: 8 });
    const b = addBody(world, { position: [0, 0, 0] });
    expect(() => addShape3D(world, b, { type: 'hull', vertices: pts })).toThrow(
      new RegExp(
        `^addShape3D: vertices must have a convex hull of at most ${MAX_HULL_VERTICES} vertices, got more than ${MAX_HULL_VERTICES}`,
      ),
    );
  });

  test('a height field above the documented limit is refused before any work', () => {
    const world = createPhysicsWorld({ dimensions: 3, capacity: 8 });
    const side = Math.floor(Math.sqrt(MAX_HEIGHT_FIELD_POINTS)) + 1;
    const row = new Array<number>(side).fill(0);
    // Rows shared: the check reads the grid's size only, so no row is walked.
    const heights = new Array<number[]>(side).fill(row);
    expect(() => addHeightField3D(world, { heights, spacing: [1, 1] })).toThrow(
      new RegExp(`^addHeightField3D: heights must have at most ${MAX_HEIGHT_FIELD_POINTS} points`),
    );
    expect(world.entityIndex.aliveCount).toBe(0);
  });
});
