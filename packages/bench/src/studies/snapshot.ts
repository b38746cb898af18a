import { createPhysicsWorld, type PhysicsWorld, restore, SCENES, snapshot, stateHash, stepMany } from '@bitphysics/physics';
import { sig } from '../scenes/format.js';
import { median } from '../stats.js';
import type { BenchStudy, StudyResult, StudyRunOptions } from './types.js';

/**
 * The snapshot study (`--scene snapshot`): what `snapshot(world)` and `restore(world, snapshot)` cost
 * for a balls-in-box world of `count` bodies after `warmup` steps (contacts, warm-start caches and
 * sleeping islands in place), as medians over `steps` rounds: snapshot, snapshot over an earlier
 * snapshot's buffer (`snapshot(world, reuse)`, a rollback ring; `reusedRounds` counts the rounds that wrote into that buffer rather than allocating), restore into the same world one
 * step after the snapshot (a rewind), restore into a fresh world made with the same options (one world,
 * restored into every round: from the second round on it has the stores and queries), restore into a
 * world made just before it (untimed) each round, whose first restore makes its queries; each
 * round first steps the world once (untimed), so every snapshot and rewind sees a state that moved
 * (and query lists that sleeping and waking changed); beside them, a plain copy of the
 * snapshot's bytes into a new buffer, the floor any snapshot that allocates its data pays. It checks that both restored
 * worlds step to the same state as the world the snapshot came from (stateHash after 10 steps).
 */
export const snapshotStudy: BenchStudy = {
  name: 'snapshot',
  description:
    'snapshot(world) and restore(world, snapshot) cost for a balls-in-box world (median ms), and the restored worlds step bit-identically',
  defaultCount: 100_000,
  maxCount: 1_000_000,
  defaults: { steps: 20, warmup: 30 },
  run(options: StudyRunOptions): StudyResult {
    const def = SCENES['balls-in-box']!;
    const sceneOptions = { count: options.count, seed: options.seed };
    const worldOptions = { ...def.worldOptions(sceneOptions), seed: options.seed };
    const make = (): PhysicsWorld => createPhysicsWorld(worldOptions);
    const world = make();
    def.build(world, sceneOptions);
    options.onProgress?.(`warm-up: ${options.warmup} steps of ${options.count} bodies`);
    stepMany(world, options.warmup);
    const fresh = make();
    const snapMs: number[] = [],
      reuseMs: number[] = [],
      rewindMs: number[] = [],
      freshMs: number[] = [],
      newMs: number[] = [];
    let saved = snapshot(world);
    let spare = snapshot(world);
    // CPU time of the process beside the wall time: on a machine shared with other work the wall time
    // also counts the time other processes held the core; CPU time does not (it does count V8's helper
    // threads, such as concurrent garbage collection, while the operation runs).
    const snapCpu: number[] = [],
      reuseCpu: number[] = [],
      rewindCpu: number[] = [],
      freshCpu: number[] = [],
      newCpu: number[] = [];
    const cpuNow = (): number => {
      const u = process.cpuUsage();
      return (u.user + u.system) / 1000;
    };
    const timed = (wall: number[], cpu: number[], f: () => void): void => {
      const c = cpuNow(),
        t = performance.now();
      f();
      wall.push(performance.now() - t);
      cpu.push(cpuNow() - c);
    };
    let reused = 0; // rounds whose reuse snapshot wrote into the spare's buffer (a miss allocates a new one)
    for (let r = 0; r < options.steps; r++) {
      // One step (untimed) before the snapshots and again before the rewind, as in a rollback loop:
      // bodies move, some fall asleep or wake, so the state and query lists differ from the last round's.
      stepMany(world, 1);
      timed(snapMs, snapCpu, () => {
        saved = snapshot(world);
      });
      // A rollback ring writes each new snapshot over its oldest one's buffer.
      const spareBuffer = spare.buffers[0];
      timed(reuseMs, reuseCpu, () => {
        spare = snapshot(world, spare);
      });
      if (spare.buffers[0] === spareBuffer) reused++;
      stepMany(world, 1);
      timed(rewindMs, rewindCpu, () => restore(world, saved));
      timed(freshMs, freshCpu, () => restore(fresh, saved));
      // A world made just now (untimed): the first restore also makes its queries and allocates its stores.
      const made = make();
      timed(newMs, newCpu, () => restore(made, saved));
    }
    const bytes = saved.buffers.reduce((s, b) => s + b.byteLength, 0);
    // Baseline in the same run: copying the snapshot's bytes once (one memcpy into a new buffer).
    const copyMs: number[] = [];
    const copyCpu: number[] = [];
    for (let r = 0; r < options.steps; r++)
      timed(copyMs, copyCpu, () => {
        for (const b of saved.buffers) b.slice(0);
      });
    const headerBytes = JSON.stringify(saved.header).length;
    // Bit-identical check: the original, the rewound and the fresh world step 10 steps from the snapshot.
    const reference = make();
    restore(reference, saved);
    stepMany(world, 10);
    stepMany(fresh, 10);
    stepMany(reference, 10);
    const hash = stateHash(world);
    const identical = stateHash(fresh) === hash && stateHash(reference) === hash;
    const record = {
      bodies: options.count,
      snapshotMs: median(snapMs),
      snapshotReuseMs: median(reuseMs),
      restoreMs: median(rewindMs),
      restoreFreshMs: median(freshMs),
      restoreNewWorldMs: median(newMs),
      reusedRounds: reused,
      copyMs: median(copyMs),
      cpuMs: {
        snapshot: median(snapCpu),
        snapshotReuse: median(reuseCpu),
        restore: median(rewindCpu),
        restoreFresh: median(freshCpu),
        restoreNewWorld: median(newCpu),
        copy: median(copyCpu),
      },
      bytes,
      headerBytes,
      buffers: saved.buffers.length,
      identical,
      stateHash: hash,
    };
    return {
      records: [record],
      header: [
        'bodies',
        'snapshot ms',
        'snapshot ms (reused buffer)',
        'restore ms (same world)',
        'restore ms (fresh world)',
        'restore ms (new world)',
        'copy of the bytes ms',
        'data MB',
        'header kB',
        'bit-identical after',
      ],
      rows: [
        [
          String(options.count),
          String(sig(record.snapshotMs)),
          String(sig(record.snapshotReuseMs)),
          String(sig(record.restoreMs)),
          String(sig(record.restoreFreshMs)),
          String(sig(record.restoreNewWorldMs)),
          String(sig(record.copyMs)),
          String(sig(bytes / 1e6)),
          String(sig(headerBytes / 1e3)),
          identical ? 'yes' : 'NO',
        ],
      ],
      notes: [
        `medians of ${options.steps} rounds after ${options.warmup} warm-up steps; ${saved.buffers.length} buffers; the reused buffer was written into in ${reused} of ${options.steps} rounds; goal: under 5 ms each for 100,000 bodies`,
        `CPU ms (medians, same order): ${[snapCpu, reuseCpu, rewindCpu, freshCpu, newCpu, copyCpu].map((a) => String(sig(median(a)))).join(', ')}`,
        `state after 10 more steps: ${hash} (original, rewound and fresh world ${identical ? 'agree' : 'DIFFER'})`,
      ],
    };
  },
};
