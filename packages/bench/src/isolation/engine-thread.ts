/**
 * The worker thread of one isolated peer engine (see isolated-engine.ts): builds the scene, runs and
 * times blocks of steps, and answers the bench thread's requests, raising the shared flag after each
 * reply. Built to packages/bench/dist/engine-thread.js beside the CLI.
 */
import { performance } from 'node:perf_hooks';
import { workerData } from 'node:worker_threads';
import { ENGINES } from '../engines/index.js';
import type { EngineInstance } from '../engines/types.js';
import { collectGarbage, engineMemoryMB, sampleMemory } from '../memory.js';
import { Flag, type CreatedReply, type EngineReply, type EngineRequest, type EngineThreadData, type RunReply, type StatsReply } from './isolated-engine.js';

const { engine, port, flag } = workerData as EngineThreadData;
let instance: EngineInstance | undefined;

/** CPU time the process has used so far (user + system, all threads), ms. */
function cpuMs(): number {
  const u = process.cpuUsage();
  return (u.user + u.system) / 1000;
}

/** The built instance. @throws Error before `create`. */
function built(): EngineInstance {
  if (instance === undefined) throw new Error(`${engine}: no scene built in its worker thread`);
  return instance;
}

/** Carries out one request. */
async function handle(req: EngineRequest): Promise<unknown> {
  switch (req.op) {
    case 'create': {
      const adapter = ENGINES[engine];
      if (adapter === undefined) throw new Error(`no engine named "${engine}"`);
      await adapter.prepare?.();
      // Twice: the first collection can leave garbage that only a second one frees (as the runner does).
      collectGarbage(); collectGarbage();
      const m0 = sampleMemory();
      const t0 = performance.now();
      instance = await adapter.create(req.options);
      const setupMs = performance.now() - t0;
      collectGarbage(); collectGarbage();
      const reply: CreatedReply = {
        engine: instance.engine, notes: instance.notes, setupMs,
        engineMemoryMB: engineMemoryMB(m0, sampleMemory(), instance.benchBytes),
      };
      return reply;
    }
    case 'run': {
      const inst = built(), n = req.steps;
      const times = req.timed ? new Float64Array(n) : null;
      const c0 = cpuMs();
      let hooks = 0;
      for (let s = 0; s < n; s++) {
        const t0 = performance.now();
        inst.step();
        if (times) times[s] = performance.now() - t0;
        if (times && inst.afterStep) {
          const a0 = cpuMs();
          inst.afterStep();
          hooks += cpuMs() - a0;
        }
      }
      const reply: RunReply = { times, cpuMs: cpuMs() - c0 - hooks };
      return reply;
    }
    case 'beginTiming':
      collectGarbage();
      built().beginTiming?.(req.steps);
      return null;
    case 'endTiming':
      built().endTiming?.();
      return null;
    case 'stats': {
      const reply: StatsReply = { stats: built().stats(), heapUsedMB: sampleMemory().heapUsed };
      return reply;
    }
    case 'snapshot':
      return built().snapshot();
    case 'dispose':
      instance?.dispose();
      instance = undefined;
      return null;
  }
}

port.on('message', (req: EngineRequest) => {
  handle(req).then(
    (value): EngineReply => ({ ok: true, value }),
    (error: unknown): EngineReply => {
      const e = error instanceof Error ? error : new Error(String(error));
      return { ok: false, name: e.name, message: e.message, stack: e.stack };
    },
  ).then((reply) => {
    port.postMessage(reply);
    Atomics.store(flag, 0, Flag.Replied);
    Atomics.notify(flag, 0);
  });
});

// A thread that ends for any reason releases a waiting bench thread (which then reports it).
process.on('exit', () => {
  Atomics.store(flag, 0, Flag.Exited);
  Atomics.notify(flag, 0);
});
