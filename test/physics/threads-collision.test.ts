import { afterEach, expect, test } from 'vitest';
import { ballsInBox, createPhysicsWorld, disposeWorld, spheresInBox, stateHash, stepMany, type PhysicsWorld } from '@bitphysics/physics';
import { broadphaseSystem } from '../../packages/physics/src/collision/broadphase.js';
import { PAIRS_MIN_PER_THREAD } from '../../packages/physics/src/collision/broadphase-pairs.js';

// The broadphase's cell pass on the world's threads: each thread finds the pairs of a range of the
// grid, and the ranges are appended in order, so the pair list and the whole state are identical to
// the bit to one thread (stateHash hashes every bit; tolerance zero). Independent check: the pairs
// are exactly those a brute-force test of every pair of balls finds.

const worlds: PhysicsWorld[] = [];
afterEach(() => { for (const w of worlds.splice(0)) disposeWorld(w); });

const count = 2 * PAIRS_MIN_PER_THREAD + 300;

for (const scene of [ballsInBox, spheresInBox]) {
  test(`${scene.name}: the cell pass on 2 threads gives the one-thread state; its pairs are the brute-force ones`, () => {
    const options = { count, seed: 3 };
    const run = (threads: number): [string, PhysicsWorld] => {
      const world = createPhysicsWorld({ ...scene.worldOptions(options), threads });
      worlds.push(world);
      if (world.threadPool !== null) world.threadPool.adaptive = false;
      scene.build(world, options as never);
      stepMany(world, 4);
      return [stateHash(world), world];
    };
    const [one] = run(1);
    const [two, world] = run(2);
    expect(world.threadPool!.runs, 'the pass ran on the threads every step').toBeGreaterThanOrEqual(4);
    expect(two).toBe(one);
    // Brute force over every pair of balls: within reach (radius + margin each) at the start-of-step
    // positions, and at least one of the two dynamic (every ball here is).
    const runs = world.threadPool!.runs;
    broadphaseSystem(world);
    expect(world.threadPool!.runs).toBe(runs + 1);
    const c = world.components, cs = world.collision;
    const balls: number[] = [];
    for (let e = 1; e < c.Ball.radius.length; e++) if (c.Ball.radius[e]! > 0) balls.push(e);
    const found = new Set<string>();
    for (let i = 0; i < cs.pairCount; i++) found.add(`${cs.pairA[i]} ${cs.pairB[i]}`);
    expect(found.size).toBe(cs.pairCount);
    let brute = 0;
    const ox = c.PreviousPosition.x, oy = c.PreviousPosition.y, oz = c.PreviousPosition.z;
    for (let i = 0; i < balls.length; i++) {
      const e = balls[i]!;
      for (let j = i + 1; j < balls.length; j++) {
        const f = balls[j]!;
        const rr = c.Ball.radius[e]! + cs.margin[e]! + c.Ball.radius[f]! + cs.margin[f]!;
        const dx = ox[f]! - ox[e]!, dy = oy[f]! - oy[e]!, dz = oz[f]! - oz[e]!;
        if (dx * dx + dy * dy + dz * dz < rr * rr) {
          brute++;
          if (!found.has(`${e} ${f}`)) throw new Error(`pair ${e} ${f} missed`);
        }
      }
    }
    expect(cs.pairCount).toBe(brute);
  }, 60_000);
}
