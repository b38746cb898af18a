import { type ContactBuffer, createPhysicsWorld, SCENES, step } from '@bitphysics/physics';
import { expect, test } from 'vitest';

// A scene's first steps must not reallocate its contact stores step after step (each growth allocates
// every column: 26-77 ms of wall time apiece for spheres-in-box 5,000, issue 36). The contact rows
// live in two buffers that swap each step (world.collision.contacts and cache.rows): each may grow
// once, to the estimate from the ball count (8,000 rows here), so at most 2 growths are seen over the
// first 91 steps (the old code doubled them from 1,024 and 16 rows). Event lists: at most 2 growths of
// the begin list (16 -> 1,024 -> 2,048; the old code doubled from 16). Growths are counted as changed
// capacities (or columns) after each step, which may hide several within one step: a lower bound.
test('spheres-in-box 2,000: the contact buffers grow at most twice, the begin events twice, over steps 0-90', () => {
  const def = SCENES['spheres-in-box']!;
  const world = createPhysicsWorld(def.worldOptions({ count: 2000 }));
  def.build(world, { count: 2000 });
  const cs = world.collision;
  const capacity = new Map<ContactBuffer, number>([
    [cs.contacts, cs.contacts.capacity],
    [cs.cache.rows, cs.cache.rows.capacity],
  ]);
  let growths = 0;
  let eventGrowths = 0;
  let beginColumn = cs.events.begin.shapeA;
  for (let i = 0; i <= 90; i++) {
    step(world);
    for (const buf of [cs.contacts, cs.cache.rows]) {
      if (capacity.get(buf) !== buf.capacity) growths++;
      capacity.set(buf, buf.capacity);
    }
    if (cs.events.begin.shapeA !== beginColumn) eventGrowths++;
    beginColumn = cs.events.begin.shapeA;
  }
  // The scene does make a pile: its contacts pass 5,000 rows by step 90 (6,596 measured).
  expect(cs.stats.contacts).toBeGreaterThan(5000);
  expect(growths).toBeLessThanOrEqual(2);
  expect(eventGrowths).toBeLessThanOrEqual(2);
});
