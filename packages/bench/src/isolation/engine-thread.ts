/**
 * The worker thread of one isolated peer engine (see isolated-engine.ts): builds the scene, runs and
 * times blocks of steps, and answers the bench thread's requests, raising the shared flag after each
 * reply. Built to packages/bench/dist/engine-thread.js beside the CLI.
 */
import { workerData } from 'node:worker_threads';
import { ENGINES } from '../engines/index.js';
import type { EngineInstance } from '../engines/types.js';
import { collectGarbage, sampleMemory } from '../memory.js';
import { buildMeasured, runBlock } from '../runner.js';
import {
  type CreatedReply,
  type EngineReply,
  type EngineRequest,
  type EngineThreadData,
  Flag,
  type RunReply,
  type StatsReply,
} from './isolated-engine.js';

const { engine, port, flag } = workerData as EngineThreadData;
let instance: EngineInstance | undefined;

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
      const measured = await buildMeasured(() => adapter.create(req.options));
      instance = measured.instance;
      const reply: CreatedReply = {
        engine: instance.engine,
        notes: instance.notes,
        setupMs: measured.setupMs,
        engineMemoryMB: measured.engineMemoryMB,
      };
      return reply;
    }
    case 'run': {
      const times = req.timed ? new Float64Array(req.steps) : null;
      const reply: RunReply = { times, cpuMs: runBlock(built(), req.steps, times, 0) };
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
  handle(req)
    .then(
      (value): EngineReply => ({ ok: true, value }),
      (error: unknown): EngineReply => {
        const e = error instanceof Error ? error : new Error(String(error));
        return { ok: false, name: e.name, message: e.message, stack: e.stack };
      },
    )
    .then((reply) => {
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
