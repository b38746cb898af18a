/**
 * The bouncing-balls heap pinned to the bit: 40 balls dropped into the game's box onto its ramps
 * (segment walls), with and without the hoop's shapes, stepped 600 times (10 s), must reach the state
 * hashes recorded for the layout of scene.ts SEGMENTS (a new layout records new ones). No scene of test/physics has balls resting on segments and
 * shapes for seconds (a pile that falls asleep), so a refactor of the ball-shape contact path, the
 * solver's body order or the sleep classification could change this game's trajectory while every
 * physics hash stayed equal. The reference is the engine's own earlier state; the tolerance is zero
 * (stateHash hashes every bit). A change meant to alter the trajectory must say so and record the new hashes.
 * The hashes hold for one JavaScript engine family: V8's Math functions are its own software
 * implementations, the same on every machine.
 */
import { createPhysicsWorld, disposeWorld, stateHash, step } from '@bitphysics/physics';
import { expect, test } from 'vitest';
import { addHoop, hoopSpots } from '../../games/bouncing-balls/hoop';
import { bouncingBallsWorldOptions, buildBouncingBalls } from '../../games/bouncing-balls/scene';

/** The heap's state hash after `steps` steps, with the first hoop in place or not. */
function heapHash(hoop: boolean, steps: number): string {
  const options = { count: 40, tall: false };
  const world = createPhysicsWorld(bouncingBallsWorldOptions(options));
  const h = buildBouncingBalls(world, options);
  if (hoop) addHoop(world, hoopSpots(false)[0]!, h.params.restitution, h.params.friction);
  for (let k = 0; k < steps; k++) step(world);
  const hash = stateHash(world);
  disposeWorld(world);
  return hash;
}

test('the heap on the ramps reaches the recorded state hash after 10 s', () => {
  expect(heapHash(false, 600)).toBe('4e4fd9b5246e51d2');
});

test('the heap on the ramps with the hoop reaches the recorded state hash after 10 s', () => {
  expect(heapHash(true, 600)).toBe('6d2305c8d848eda1');
  // The hoop changes the trajectory (the hash tells the two scenes apart).
  expect(heapHash(true, 600)).not.toBe(heapHash(false, 600));
});
