/**
 * Error messages show the values the user passed: NaN, Infinity, -0 and undefined inside an array
 * read as such (JSON.stringify wrote them as null or 0: "(in [null,0])").
 */
import { expect, it, describe as suite } from 'vitest';
import { addBody, createPhysicsWorld, setVelocity } from '../../packages/physics/src/index.js';
import { describe } from '../../packages/physics/src/validation/validate.js';

suite('values in error messages', () => {
  it('a NaN in a vector is shown as NaN', () => {
    const world = createPhysicsWorld({ dimensions: 2, capacity: 4 });
    const ball = addBody(world, { position: [0, 0], radius: 0.1, mass: 1 });
    expect(() => setVelocity(world, ball, [Number.NaN, 0])).toThrow('setVelocity: velocity[0] must be finite, got NaN (in [NaN,0])');
  });

  it('formats arrays element by element, objects as JSON, and stops at 80 characters', () => {
    expect(describe([Number.POSITIVE_INFINITY, -0, undefined, 'a', null])).toBe('[Infinity,-0,undefined,"a",null]');
    expect(describe([[Number.NaN], { x: 1 }])).toBe('[[null],{"x":1}]');
    expect(describe(new Array(100).fill(1))).toHaveLength(80);
    const self: unknown[] = [];
    self.push(self);
    expect(describe(self)).toBe('[[object Array]]');
  });
});
