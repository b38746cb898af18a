import { MessageChannel, type MessagePort, receiveMessageOnPort, Worker } from 'node:worker_threads';
import type { BodySnapshot, EngineAdapter, EngineInstance, EngineStats, SceneRunOptions } from '../engines/types.js';

/**
 * Peer engines in their own V8 isolate: each peer instance is built and stepped in a worker thread of
 * its own, driven synchronously from the bench's thread, so that one engine's runtime state cannot slow
 * another's code.
 *
 * Why: V8 keeps process-wide (in fact isolate-wide) assumptions called protectors, and compiled code
 * relies on them. The first time any ArrayBuffer in an isolate is detached (a WebAssembly memory that
 * grows detaches its old buffer; so does a transfer), V8 drops the "ArrayBufferDetaching" protector, and
 * from then on every typed-array access in optimised JavaScript checks whether its buffer was detached
 * (`node --trace-protector-invalidation` shows the moment). rapier's and box2d-wasm's memories grow
 * while they build a scene. Measured on box-pile-3d at 5,000 boxes (seed 1, 300 steps after 30, a
 * script timing bitphysics alone): 9.0 to 9.3 ms a step in a clean isolate, 10.0 to 10.4 ms after one
 * 8-byte buffer was detached, and the same 10.3 to 10.4 ms after a rapier3d world of 5,000 boxes was
 * merely built (not stepped) in the same isolate; every JavaScript engine, ours, matter's and planck's,
 * pays it, WebAssembly does not. A user's program that runs bitphysics has no rapier in it, so each peer
 * gets an isolate of its own (ours stays on the bench's thread, with its own worker threads under
 * `--threads`), and the engines are timed as each runs alone, still alternating in blocks of steps
 * across the same stretch of machine load. `--same-isolate` runs every engine on the bench's thread as
 * before, to see the effect.
 *
 * Protocol: requests go to the worker over a MessageChannel; the bench's thread then blocks in
 * Atomics.wait on a shared flag the worker raises once its reply is posted, and takes the reply with
 * receiveMessageOnPort. Steps are run and timed in the worker a block at a time (`runSteps`), so no
 * message crosses inside a timed step; the bench's thread waits without using CPU, so the process CPU
 * time the worker measures over its block is the engine's.
 */

/** A request to the engine thread (engine-thread.ts). */
export type EngineRequest =
  | { readonly op: 'create'; readonly options: SceneRunOptions }
  | { readonly op: 'run'; readonly steps: number; readonly timed: boolean }
  | { readonly op: 'beginTiming'; readonly steps: number }
  | { readonly op: 'endTiming' }
  | { readonly op: 'stats' }
  | { readonly op: 'snapshot' }
  | { readonly op: 'dispose' };

/** The engine thread's reply to a request: its result, or the error it threw. */
export type EngineReply =
  | { readonly ok: true; readonly value: unknown }
  | { readonly ok: false; readonly name: string; readonly message: string; readonly stack?: string };

/** What `create` replies: the instance's fixed fields and its setup time and memory measured in its isolate. */
export interface CreatedReply {
  readonly engine: string;
  readonly notes: readonly string[];
  readonly setupMs: number;
  readonly engineMemoryMB: number;
}

/** What `run` replies: every step's milliseconds (timed runs) and the process CPU time of the block less the afterStep hooks', ms. */
export interface RunReply {
  readonly times: Float64Array | null;
  readonly cpuMs: number;
}

/** What `stats` replies: the engine's counters and its isolate's V8 heap in use, MB. */
export interface StatsReply {
  readonly stats: EngineStats;
  readonly heapUsedMB: number;
}

/** Values of the shared flag (Int32Array of one element): a request in flight, the reply posted, the worker thread exited. */
export const Flag = Object.freeze({ Waiting: 0, Replied: 1, Exited: 2 });

/** What the worker receives as workerData. */
export interface EngineThreadData {
  /** Name of the engine in the bench's registry (engines/index.ts). */
  readonly engine: string;
  /** The worker's end of the request channel. */
  readonly port: MessagePort;
  /** The shared flag (one Int32). */
  readonly flag: Int32Array;
}

/**
 * An engine instance whose engine lives in a worker thread: every call is a synchronous request.
 * `step()` alone is never used by the runner for it (a message round trip would be timed); the runner
 * calls `runSteps`.
 */
export class IsolatedInstance implements EngineInstance {
  readonly engine: string;
  readonly notes: readonly string[];
  /** Time to build the scene, ms, measured in the engine's isolate. */
  readonly setupMs: number;
  /** The engine's memory, MB, measured in its isolate (`engineMemoryMB`). */
  readonly engineMemoryMB: number;
  private readonly worker: Worker;
  private readonly port: MessagePort;
  private readonly flag: Int32Array;
  private disposed = false;

  private constructor(worker: Worker, port: MessagePort, flag: Int32Array, created: CreatedReply) {
    this.worker = worker;
    this.port = port;
    this.flag = flag;
    this.engine = created.engine;
    this.notes = [...created.notes, 'runs in a worker thread of its own (its own V8 isolate; --same-isolate: beside bitphysics)'];
    this.setupMs = created.setupMs;
    this.engineMemoryMB = created.engineMemoryMB;
  }

  /**
   * Starts a worker thread for engine `name`, builds the scene there and returns the instance.
   * @throws the error the engine's `create` threw (a RangeError or TypeError keeps its kind: bad options);
   *   Error if the worker thread stops.
   */
  static create(name: string, options: SceneRunOptions): IsolatedInstance {
    const channel = new MessageChannel();
    const flag = new Int32Array(new SharedArrayBuffer(4));
    const data: EngineThreadData = { engine: name, port: channel.port2, flag };
    const worker = new Worker(new URL('./engine-thread.js', import.meta.url), { workerData: data, transferList: [channel.port2] });
    // The bench exits when its work is done whether or not a worker is still winding down.
    worker.unref();
    try {
      const created = request(name, channel.port1, flag, { op: 'create', options }) as CreatedReply;
      return new IsolatedInstance(worker, channel.port1, flag, created);
    } catch (error) {
      channel.port1.close();
      void worker.terminate();
      throw error;
    }
  }

  /** One step, with a message round trip: for untimed use only. */
  step(): void {
    this.runSteps(1, false);
  }

  /** Runs `steps` steps in the engine's thread; with `timed`, returns each step's milliseconds measured there. */
  runSteps(steps: number, timed: boolean): RunReply {
    return this.call({ op: 'run', steps, timed }) as RunReply;
  }

  /** The engine's beginTiming, in its thread (after a full collection there). */
  beginTiming(steps: number): void {
    this.call({ op: 'beginTiming', steps });
  }

  /** The engine's endTiming, in its thread. */
  endTiming(): void {
    this.call({ op: 'endTiming' });
  }

  /** V8 heap in use in the engine's isolate at the last `stats`, MB. */
  private lastHeapMB = 0;

  /** The engine's counters, read in its thread (also records its isolate's heap for `heapUsedMB`). */
  stats(): EngineStats {
    const reply = this.call({ op: 'stats' }) as StatsReply;
    this.lastHeapMB = reply.heapUsedMB;
    return reply.stats;
  }

  /** V8 heap in use in the engine's isolate when `stats` was last called, MB. */
  heapUsedMB(): number {
    return this.lastHeapMB;
  }

  /** The engine's snapshot, copied from its thread. */
  snapshot(): BodySnapshot {
    return this.call({ op: 'snapshot' }) as BodySnapshot;
  }

  /** Disposes the engine in its thread, then ends the thread. Idempotent. */
  dispose(): void {
    if (this.disposed) return;
    this.disposed = true;
    try {
      this.call({ op: 'dispose' });
    } finally {
      this.port.close();
      void this.worker.terminate();
    }
  }

  /** A synchronous request to the engine's thread. @throws Error once disposed; the request's own error. */
  private call(req: EngineRequest): unknown {
    if (this.disposed && req.op !== 'dispose') throw new Error(`${this.engine}: the instance was disposed`);
    return request(this.engine, this.port, this.flag, req);
  }
}

/**
 * Posts `req` and blocks until the worker raised the flag, then returns the reply's value.
 * @throws the worker's error, rebuilt with its kind (RangeError, TypeError, else Error); Error if the thread exited.
 */
function request(engine: string, port: MessagePort, flag: Int32Array, req: EngineRequest): unknown {
  Atomics.store(flag, 0, Flag.Waiting);
  port.postMessage(req);
  while (Atomics.load(flag, 0) === Flag.Waiting) Atomics.wait(flag, 0, Flag.Waiting, 1000);
  const received = receiveMessageOnPort(port);
  if (received === undefined) throw new Error(`${engine}: its worker thread stopped during "${req.op}"`);
  const reply = received.message as EngineReply;
  if (reply.ok) return reply.value;
  const Kind = reply.name === 'RangeError' ? RangeError : reply.name === 'TypeError' ? TypeError : Error;
  const error = new Kind(reply.message);
  if (reply.stack !== undefined) error.stack = reply.stack;
  throw error;
}

/**
 * The adapter `adapter` with each of its instances built and stepped in a worker thread of its own
 * (see the module's docstring). Same name, description and scenes.
 */
export function isolated(adapter: EngineAdapter): EngineAdapter {
  return {
    name: adapter.name,
    description: adapter.description,
    supports: (scene) => adapter.supports(scene),
    create: (options) => Promise.resolve().then(() => IsolatedInstance.create(adapter.name, options)),
  };
}
