import { disposeWorld, type PhysicsWorld } from '@bitphysics/physics';
import { afterEach } from 'vitest';
import { stageThreading } from '../../packages/physics/src/solver/stages-threads.js';

/**
 * The list a thread test file pushes its worlds to: after each test every world in it is disposed (its
 * pool's workers end) and `stageThreading.minPerThread`, which a test may lower so small scenes run on
 * the threads, is put back to its value when the file called this. Call it once, at the file's top level.
 */
export function threadTestWorlds(): PhysicsWorld[] {
  const worlds: PhysicsWorld[] = [];
  const saved = stageThreading.minPerThread;
  afterEach(() => {
    for (const w of worlds.splice(0)) disposeWorld(w);
    stageThreading.minPerThread = saved;
  });
  return worlds;
}
