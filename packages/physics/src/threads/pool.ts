/**
 * A pool of worker threads that run ranges of a system's loop on shared memory.
 * Thread 0 is the calling (main) thread; threads 1 .. n-1 are workers (Node `worker_threads` or the
 * browser's `Worker`), each built from the same source (worker-source.ts) and holding views of the
 * same SharedArrayBuffers. A `run` writes the kernel, the ranges and the array ids into a small
 * control array, opens each worker's range (a claim slot holding the command's generation), wakes the
 * workers with Atomics.notify and runs range 0 itself.
 *
 * A run always finishes, with the result it would have with every worker on time. Each range of each
 * command runs once, on the thread that claims it (Atomics.compareExchange of its slot from the
 * generation to its complement; worker-main.ts). When the calling thread has finished range 0 it
 * claims every range a worker has not claimed yet and runs it itself (the same kernel over the same
 * bounds, with the worker's `part`, so the per-range outputs are the same), then waits for the ranges
 * the workers did claim. A worker that was late (not scheduled, asleep, or still receiving arrays)
 * and wakes afterwards finds its claim gone and writes nothing, not into the finished command's
 * arrays nor into a later command's (a later command has a later generation, which its stale claim
 * does not match). Kernels that claim blocks of their own (threads/block-claim.ts, the coloured solve)
 * already let any thread take a late thread's blocks; the calling thread's run of such a range
 * finds them done. So lateness costs time, never an error: there is no acknowledgement deadline.
 *
 * A worker whose thread ended (its `exit` or `error` event, seen between steps, or its exit hook's
 * `DEAD`) is replaced by a new one before the next command (its ranges meanwhile run on the calling
 * thread, as any late worker's); after `MAX_REPLACEMENTS` the pool stops using its workers and the
 * world's loops run on the calling thread (`failure`). Nothing of this throws: it is counted in
 * `stats()` (ranges taken over, stale wake-ups, workers replaced, the last event).
 *
 * What still throws out of a run (and so out of `step`):
 * - a kernel that throws, on any thread: a bug, reported as `<system>: a worker thread failed:
 *   <message>` (or the calling thread's own error) once every other range of the run has finished, so
 *   no thread writes after the throw. The world is left as the run left it, as a one-thread world's
 *   loop that throws midway leaves it; undoing a step would need a copy of the world's state every
 *   step, which the engine does not pay for a bug. The pool keeps working;
 * - a worker whose thread ends while it holds a claimed range (only `terminate()` from outside the
 *   pool or a fatal error of the runtime does that): how much of its range it wrote is unknown, so the
 *   range cannot be run again safely. Its exit hook's `DEAD` reports it at once in Node; a terminated
 *   worker runs no hook, and the run gives up after `runLimitMs`. The run throws
 *   `<system>: worker thread <i> died ...`, the pool is disposed and the world steps on one thread.
 *
 * Each array travels to the workers once, in a message, the first time a kernel uses it; nothing is
 * sent per step or per entity. Workers are unref'd in Node, so a pool never keeps the process alive;
 * `dispose` stops and terminates them.
 */

import { LoopChooser } from './adaptive.js';
import { epochMs, RangeBalance } from './balance.js';
import type { Kernel, KernelArray, KernelHelper } from './kernel-types.js';
import { COMMAND, CONTROL, type PoolMessage } from './worker-main.js';
import { workerSource } from './worker-source.js';

/** The least a worker must offer: Node's Worker and the browser's Worker both do. */
interface AnyWorker {
  postMessage(message: unknown): void;
  terminate(): unknown;
  unref?(): void;
  /** Node: error and message events. */
  on?(event: 'error' | 'message' | 'exit', f: (e: unknown) => void): void;
  /** Node: removes a listener (a message listener would keep an unref'd worker's process alive). */
  off?(event: 'message', f: (e: unknown) => void): void;
  /** Browser: error handler. */
  onerror?: ((e: unknown) => void) | null;
  /** Browser: message handler. */
  onmessage?: ((e: { data: unknown }) => void) | null;
}

/** Most scalar parameters a kernel takes. */
const MAX_PARAMS = 64;

/**
 * Default microseconds an idle worker watches for the next run before it blocks (ThreadPool.idleSpin).
 * The loops of a step come a few hundred microseconds apart, with the caller's own work between them.
 * @category Threads
 */
export const IDLE_SPIN_MICROSECONDS = 500;

/** Milliseconds the calling thread blocks at a time while it waits for the workers (then it checks they live). */
const WAIT_SLICE_MS = 25;

/** Characters of a worker's error message kept (longer messages are cut). */
const ERROR_TEXT = 1024;

/**
 * Whether SharedArrayBuffer can be used here (a browser page must be cross-origin isolated).
 * @category Threads
 */
export function sharedMemoryAvailable(): boolean {
  return typeof SharedArrayBuffer === 'function' && typeof Atomics === 'object';
}

/**
 * A Float64Array of `n` elements on a new SharedArrayBuffer.
 * @category Threads
 */
export function sharedFloat64(n: number): Float64Array {
  return new Float64Array(new SharedArrayBuffer(n * 8));
}

/**
 * A typed array of the same type as `like` and `n` elements, on a new SharedArrayBuffer.
 * @category Threads
 */
export function sharedLike<T extends KernelArray>(like: T, n: number): T {
  const C = like.constructor as { new (b: SharedArrayBuffer): T; BYTES_PER_ELEMENT: number };
  return new C(new SharedArrayBuffer(n * C.BYTES_PER_ELEMENT));
}

/**
 * `a` itself if it lives on a SharedArrayBuffer, else a copy of it there (same type and contents).
 * @category Threads
 */
export function sharedCopy<T extends KernelArray>(a: T): T {
  if (isShared(a)) return a;
  const copy = sharedLike(a, a.length);
  copy.set(a as never);
  return copy;
}

/**
 * Whether a typed array lives on a SharedArrayBuffer.
 * @category Threads
 */
export function isShared(a: ArrayBufferView): boolean {
  return typeof SharedArrayBuffer === 'function' && a.buffer instanceof SharedArrayBuffer;
}

/** Makes a worker running `source`; Node and browser versions below. */
type WorkerFactory = (source: string) => AnyWorker;

function defaultWorkerFactory(): WorkerFactory | null {
  const g = globalThis as unknown as {
    process?: { getBuiltinModule?: (name: string) => unknown; versions?: { node?: string } };
    Worker?: new (url: string, options?: object) => AnyWorker;
    Blob?: new (parts: string[], options?: object) => unknown;
    URL?: { createObjectURL(blob: unknown): string };
  };
  if (g.process?.versions?.node !== undefined) {
    const wt = g.process.getBuiltinModule?.('node:worker_threads') as
      | { Worker: new (src: string, options: object) => AnyWorker }
      | undefined;
    if (wt === undefined) return null;
    return (source) => new wt.Worker(source, { eval: true });
  }
  if (typeof g.Worker === 'function' && typeof g.Blob === 'function' && g.URL !== undefined) {
    const W = g.Worker,
      B = g.Blob,
      U = g.URL;
    let url: string | null = null;
    return (source) => {
      url ??= U.createObjectURL(new B([source], { type: 'text/javascript' }));
      return new W(url);
    };
  }
  return null;
}

/** Whether this thread may block in Atomics.wait (not a browser's main thread). */
function canBlock(): boolean {
  try {
    Atomics.wait(new Int32Array(new SharedArrayBuffer(4)), 0, 1, 0);
    return true;
  } catch {
    return false;
  }
}

/**
 * Workers a pool replaces in its life (those whose threads ended) before it stops using its workers
 * and the world's loops run on the calling thread: a worker that dies again and again (one that cannot
 * start here) costs a worker's start-up each time.
 * @category Threads
 */
export const MAX_REPLACEMENTS = 8;

/**
 * What a pool did about workers that were late or died (`ThreadPool.stats`). None of it is an error:
 * a run finishes with the same result either way.
 * @category Threads
 */
export interface ThreadPoolStats {
  /** Ranges the calling thread ran because their worker had not claimed them when it finished its own (count). */
  rangesTakenOver: number;
  /** Wake-ups of workers that found their range taken over or their command finished, and wrote nothing (count). */
  staleWakeUps: number;
  /** Workers replaced because their threads ended (count, at most MAX_REPLACEMENTS). */
  workersReplaced: number;
  /** The last worker that died or was replaced, and why (text), or null. */
  lastWorkerEvent: string | null;
}

/**
 * A pool of `threads - 1` workers plus the calling thread. Make it with `createThreadPool`.
 * @category Threads
 */
export class ThreadPool {
  /** Threads that share a loop: the calling thread and its workers. */
  readonly threads: number;
  /** The kernel table the pool runs; the workers get its source text and find a run's kernel by its place in it. */
  readonly kernels: readonly Kernel[];
  /** Each kernel of `kernels` to its place there. */
  private readonly kernelIndex: Map<Kernel, number>;
  /** The functions the kernels call, by index (solver/kernel-helpers.ts), passed to every kernel as its last argument. */
  readonly helpers: readonly KernelHelper[];
  /** Resolves once every worker has started and can take work (a browser page may await it; Node waits by itself). */
  readonly ready: Promise<void>;
  /** Worker i at [i - 1]. */
  private readonly workers: AnyWorker[];
  private readonly factory: WorkerFactory;
  private readonly source: string;
  private readonly ctl: Int32Array;
  private readonly params: Float64Array;
  private readonly results: Float64Array;
  /** When each worker finished its range of the last run, ms since the epoch (slot 0 unused). */
  private readonly finished: Float64Array;
  /** The threads' learnt shares of each kernel's loop (balance.ts). */
  readonly balance: RangeBalance;
  private readonly errorText: Uint16Array;
  private readonly ids = new Map<ArrayBufferView, number>();
  private readonly blocking: boolean;
  private idBuffer: Int32Array;
  private disposed = false;
  /** Whether every worker had started once (a worker that dies before then could not start: `failure`). */
  private started = false;
  /** Resolves `ready` (set by the constructor). */
  private resolveReady: (() => void) | null = null;
  /**
   * Why the pool no longer uses its workers, or null: a worker could not start, or workers died more
   * than MAX_REPLACEMENTS times, or a worker died holding a range. The world's loops then run on one thread.
   */
  failure: string | null = null;
  /** Why each worker's thread ended, seen by its `exit` or `error` event (worker i at [i - 1]), or null while it lives. */
  private readonly dead: Array<string | null>;
  /**
   * Most milliseconds one run (or start and join) may wait for a range a worker claimed (a worker
   * stuck in an endless kernel, or terminated from outside while it ran one). Default 60,000: no loop
   * of a step comes near it. The run then throws and the pool is disposed (see the file's header).
   */
  runLimitMs = 60_000;
  /** Loops this pool has run on its threads (a count for tests and the bench). */
  runs = 0;
  private rangesTakenOver = 0;
  /** Which ranges of the command being settled the calling thread claimed (1), by thread. */
  private readonly takenHere: Uint8Array;
  private workersReplaced = 0;
  private lastWorkerEvent: string | null = null;

  /**
   * Microseconds an idle worker keeps watching for the next run before it blocks in Atomics.wait
   * (integer in [0, 1e6]; default `IDLE_SPIN_MICROSECONDS`). A run that starts within it finds the
   * worker awake; past it the worker sleeps and costs no CPU.
   * @throws RangeError `ThreadPool.idleSpin: ...` on a value out of range.
   */
  get idleSpin(): number {
    return this.ctl[CONTROL.SPIN]!;
  }
  set idleSpin(us: number) {
    if (!Number.isInteger(us) || us < 0 || us > 1e6)
      throw new RangeError(`ThreadPool.idleSpin: microseconds must be an integer in [0, 1e6], got ${us}`);
    this.ctl[CONTROL.SPIN] = us;
  }

  constructor(threads: number, factory: WorkerFactory, kernels: readonly Kernel[], helpers: readonly KernelHelper[]) {
    this.threads = threads;
    this.kernels = kernels;
    this.kernelIndex = new Map(kernels.map((k, i) => [k, i]));
    this.helpers = helpers;
    this.factory = factory;
    this.ctl = new Int32Array(new SharedArrayBuffer(CONTROL.LENGTH * 4));
    this.ctl[CONTROL.SPIN] = IDLE_SPIN_MICROSECONDS;
    this.params = sharedFloat64(MAX_PARAMS);
    this.results = sharedFloat64(threads);
    this.finished = sharedFloat64(threads);
    this.balance = new RangeBalance(threads);
    this.errorText = new Uint16Array(new SharedArrayBuffer(ERROR_TEXT * 2));
    this.idBuffer = new Int32Array(new SharedArrayBuffer(4));
    this.blocking = canBlock();
    this.takenHere = new Uint8Array(threads);
    this.source = workerSource(kernels, helpers);
    this.workers = [];
    this.dead = [];
    for (let i = 1; i < threads; i++) {
      this.workers.push(this.makeWorker(i));
      this.dead.push(null);
    }
    // Each worker posts one 'ready' message once it has joined the control buffer (no timer: the
    // physics package uses none); dispose resolves the promise too.
    const ctl = this.ctl,
      want = threads - 1;
    const started = new Promise<void>((resolve) => {
      this.resolveReady = resolve;
      if (Atomics.load(ctl, CONTROL.READY) >= want) resolve();
    });
    for (const w of this.workers) {
      const onReady = (m: unknown): void => {
        if ((m as { type?: unknown } | null)?.type !== 'ready') return;
        if (typeof w.off === 'function') w.off('message', onReady);
        else w.onmessage = null;
        if (Atomics.load(ctl, CONTROL.READY) >= want) this.resolveReady?.();
      };
      if (typeof w.on === 'function') w.on('message', onReady);
      else w.onmessage = (e) => onReady(e.data);
    }
    this.ready = started;
  }

  /**
   * Makes worker `i` (1 .. threads - 1) and posts it the control buffers and every array the pool
   * has sent so far (in id order, as a replacement needs them).
   */
  private makeWorker(i: number): AnyWorker {
    const w = this.factory(this.source);
    w.unref?.();
    // A worker that dies must not crash the process. One that could not start: the pool runs on one
    // thread (`failure`). One that had started: it is replaced before the next command (`heal`).
    const died = (why: string): void => {
      if (this.disposed || this.workers[i - 1] !== w) return;
      if (!this.started) this.failure ??= why;
      this.dead[i - 1] ??= why;
    };
    if (typeof w.on === 'function') {
      w.on('error', (e) => died(`worker thread ${i} died (${String((e as { message?: unknown })?.message ?? e)})`));
      w.on('exit', (code) => died(`worker thread ${i} exited (code ${String(code)})`));
    } else w.onerror = (e) => died(`worker thread ${i} died (${String((e as { message?: unknown })?.message ?? e)})`);
    const msg: PoolMessage = {
      type: 'init',
      index: i,
      ctl: this.ctl,
      params: this.params,
      results: this.results,
      finished: this.finished,
      errorText: this.errorText,
    };
    w.postMessage(msg);
    for (const [array, id] of this.ids) w.postMessage({ type: 'array', id, array } satisfies PoolMessage);
    return w;
  }

  /**
   * Whether parallel loops choose between the threads and one thread by the time each takes
   * (adaptive.ts; default true). False: every loop long enough runs on the threads (for tests).
   */
  adaptive = true;

  /** The per-loop choices of an adaptive pool. */
  readonly chooser = new LoopChooser();

  /**
   * Whether the pool's first workers have all started (a browser pool runs on one thread until then).
   * `CONTROL.READY` counts every worker's start and is never lowered, so after a replacement this is
   * true before the new worker has started; until it has, the calling thread runs that worker's
   * ranges (the results are the same).
   */
  isReady(): boolean {
    if (this.disposed || this.failure !== null || Atomics.load(this.ctl, CONTROL.READY) < this.workers.length) return false;
    this.started = true;
    return true;
  }

  /**
   * Whether `run` will use the workers now: not disposed, and the workers have started (in Node this
   * waits up to 10 s for them; a browser page's main thread cannot wait, and runs alone until `ready`).
   */
  usable(): boolean {
    if (this.disposed || this.failure !== null) return false;
    if (this.isReady()) return true;
    if (!this.blocking) return false;
    const deadline = Date.now() + 10_000;
    let r: number;
    while ((r = Atomics.load(this.ctl, CONTROL.READY)) < this.workers.length && Date.now() < deadline) {
      Atomics.wait(this.ctl, CONTROL.READY, r, 50);
    }
    return this.isReady();
  }

  /**
   * What the pool did about late and dead workers so far (see ThreadPoolStats); a new object each call.
   */
  stats(): ThreadPoolStats {
    return {
      rangesTakenOver: this.rangesTakenOver,
      staleWakeUps: Atomics.load(this.ctl, CONTROL.STALE),
      workersReplaced: this.workersReplaced,
      lastWorkerEvent: this.lastWorkerEvent,
    };
  }

  /**
   * Runs `kernel` (a function of the pool's kernel table) over [0, n) split into `threads` contiguous ranges (in
   * proportion to how fast each thread has run this kernel: balance.ts), with
   * `arrays` (each on a SharedArrayBuffer; at most CONTROL.MAX_ARRAYS) and the scalar `params` (at most
   * 64); `ids` (null: dense ids lo+1..hi) is copied to a shared buffer. Returns the sum of the ranges'
   * return values, in thread order. The ranges workers have not claimed when the calling thread has
   * finished its own run on the calling thread (see the file's header); on a disposed pool all do.
   * @throws RangeError naming `system` if `kernel` is not in the pool's table or `arrays` or `params` is
   *   too long (nothing runs).
   * @throws Error naming `system` if a range's kernel threw (a worker's: `<system>: a worker thread
   *   failed: <message>`), or if a worker's thread ended while it held a range
   *   (`<system>: worker thread <i> died ...`; the pool is disposed, the world steps on one thread).
   */
  run(system: string, kernel: Kernel, arrays: KernelArray[], params: ArrayLike<number>, n: number, ids: ArrayLike<number> | null): number {
    this.join();
    this.heal();
    const ctl = this.ctl;
    let idsId = -1;
    if (ids !== null) {
      if (this.idBuffer.length < n) this.idBuffer = new Int32Array(new SharedArrayBuffer(Math.max(n, this.idBuffer.length * 2) * 4));
      const buf = this.idBuffer;
      for (let i = 0; i < n; i++) buf[i] = ids[i]!;
      idsId = this.idOf(buf);
    }
    const k = this.setUp(system, kernel, arrays, params, idsId);
    this.balance.bounds(k, n, ctl, CONTROL.BOUNDS);
    const t0 = epochMs();
    const g = this.dispatch(COMMAND.RUN);
    this.runs++;
    const t = this.threads;
    const idsArg = ids === null ? null : this.idBuffer;
    let own = 0,
      t1 = t0,
      ok = false,
      took = 0;
    try {
      own = kernel(arrays, this.params, idsArg, 0, ctl[CONTROL.BOUNDS + 1]!, 0, this.helpers);
      t1 = epochMs();
      ok = true;
    } finally {
      // After a throw the open ranges are only closed (claimed, not run): no worker starts one.
      took = this.settle(system, g, ok ? kernel : null, arrays, idsArg);
    }
    if (ctl[CONTROL.ERROR] !== 0) throw new Error(`${system}: a worker thread failed: ${this.workerError()}`);
    if (took === 0) this.balance.record(k, n, t0, t1, this.finished);
    let sum = own;
    for (let i = 1; i < t; i++) sum += this.results[i]!;
    return sum;
  }

  /** `kernel`'s place in the pool's kernel table, or -1 if it is not there. */
  indexOf(kernel: Kernel): number {
    return this.kernelIndex.get(kernel) ?? -1;
  }

  /**
   * Writes a run's kernel, arrays (posted to the workers first if new), parameters and ids slot
   * (-1: none) into the control block, and clears the error flag. Returns the kernel's place in the table.
   * @throws RangeError naming `system` if `kernel` is not in the table or `arrays` or `params` is too long.
   */
  private setUp(system: string, kernel: Kernel, arrays: KernelArray[], params: ArrayLike<number>, idsId: number): number {
    const k = this.kernelIndex.get(kernel);
    if (k === undefined) throw new RangeError(`${system}: kernel ${kernel.name || '(anonymous)'} is not in the thread pool's kernel table`);
    if (arrays.length > CONTROL.MAX_ARRAYS) throw new RangeError(`${system}: a kernel takes at most ${CONTROL.MAX_ARRAYS} arrays`);
    if (params.length > MAX_PARAMS)
      throw new RangeError(`${system}: a kernel takes at most ${MAX_PARAMS} parameters, got ${params.length}`);
    const ctl = this.ctl;
    for (let i = 0; i < arrays.length; i++) ctl[CONTROL.ARRAYS + i] = this.idOf(arrays[i]!);
    // A worker that holds fewer arrays receives the new ones before it claims its range.
    ctl[CONTROL.EXPECT] = this.ids.size;
    const P = this.params;
    for (let i = 0; i < params.length; i++) P[i] = params[i]!;
    ctl[CONTROL.KERNEL] = k;
    ctl[CONTROL.NARRAYS] = arrays.length;
    ctl[CONTROL.IDS] = idsId;
    ctl[CONTROL.ERROR] = 0;
    return k;
  }

  /** The system of the kernel `start` left running on a worker, or null; its kernel, arrays (a copy: callers reuse theirs) and generation. */
  private pending: string | null = null;
  private pendingKernel: Kernel | null = null;
  private readonly pendingArrays: KernelArray[] = [];
  private pendingGen = 0;

  /**
   * Starts `kernel` (a function of the pool's kernel table) over all of [0, n) on the first worker alone and returns at
   * once, so the calling thread can do other work meanwhile (work that neither writes what the kernel
   * reads nor reads what it writes); `join` waits for it (and runs it itself if the worker has not
   * claimed it by then). The other threads' ranges are empty
   * ([n, n) and, for the caller, [0, 0)), so the kernel must do nothing on an empty range. The next
   * `run` or `start` joins it first. Needs a usable pool (`usable()`) with at least one worker.
   * @throws RangeError naming `system` if the pool has no usable worker or `arrays` or `params` is too long.
   */
  start(system: string, kernel: Kernel, arrays: KernelArray[], params: ArrayLike<number>, n: number): void {
    this.join();
    this.heal();
    if (this.workers.length === 0 || !this.usable()) throw new RangeError(`${system}: ThreadPool.start needs a usable worker`);
    this.setUp(system, kernel, arrays, params, -1);
    const ctl = this.ctl;
    ctl[CONTROL.BOUNDS] = 0;
    ctl[CONTROL.BOUNDS + 1] = 0;
    for (let i = 2; i <= this.threads; i++) ctl[CONTROL.BOUNDS + i] = n;
    const kept = this.pendingArrays;
    kept.length = arrays.length;
    for (let i = 0; i < arrays.length; i++) kept[i] = arrays[i]!;
    this.pending = system;
    this.pendingKernel = kernel;
    this.pendingGen = this.dispatch(COMMAND.RUN);
    this.runs++;
  }

  /**
   * Waits for the kernel `start` left running (nothing if none), running it on the calling thread if
   * its worker has not claimed it, and returns its result (0 if none).
   * @throws Error naming the started kernel's system if its kernel threw.
   */
  join(): number {
    const system = this.pending;
    if (system === null) return 0;
    this.pending = null;
    this.settle(system, this.pendingGen, this.pendingKernel, this.pendingArrays, null);
    if (this.ctl[CONTROL.ERROR] !== 0) throw new Error(`${system}: a worker thread failed: ${this.workerError()}`);
    return this.results[1]!;
  }

  /** The message of the worker's error of the last run. */
  private workerError(): string {
    const text = this.errorText;
    let msg = '';
    for (let i = 0; i < text.length && text[i] !== 0; i++) msg += String.fromCharCode(text[i]!);
    return msg;
  }

  /** Stops and terminates the workers; the pool cannot run afterwards. Safe to call twice. */
  dispose(): void {
    if (this.disposed) return;
    this.disposed = true;
    this.pending = null;
    const ctl = this.ctl;
    ctl[CONTROL.CMD] = COMMAND.QUIT;
    Atomics.add(ctl, CONTROL.GEN, 1);
    Atomics.notify(ctl, CONTROL.GEN);
    for (let i = 1; i < this.threads; i++) {
      Atomics.store(ctl, CONTROL.HOLD + i, 0);
      Atomics.notify(ctl, CONTROL.HOLD + i);
    }
    for (const w of this.workers) void w.terminate();
    this.workers.length = 0;
    this.resolveReady?.();
  }

  /** Whether `dispose` was called. */
  get isDisposed(): boolean {
    return this.disposed;
  }

  private idOf(a: ArrayBufferView): number {
    let id = this.ids.get(a);
    if (id === undefined) {
      if (!isShared(a)) throw new TypeError('thread pool: an array of a parallel loop is not on a SharedArrayBuffer');
      id = this.ids.size;
      this.ids.set(a, id);
      const msg: PoolMessage = { type: 'array', id, array: a };
      for (const w of this.workers) w.postMessage(msg);
    }
    return id;
  }

  /** When the last command was dispatched (Date.now(), ms). */
  private dispatchedAt = 0;

  /** Opens every worker's range of the next command `cmd` and wakes the workers; returns the command's generation. */
  private dispatch(cmd: number): number {
    const ctl = this.ctl;
    ctl[CONTROL.CMD] = cmd;
    const g = (ctl[CONTROL.GEN]! + 1) | 0;
    for (let i = 1; i < this.threads; i++) Atomics.store(ctl, CONTROL.CLAIM + i, g);
    Atomics.store(ctl, CONTROL.PENDING, this.threads - 1);
    this.dispatchedAt = Date.now();
    Atomics.store(ctl, CONTROL.GEN, g);
    Atomics.notify(ctl, CONTROL.GEN);
    return g;
  }

  /**
   * Finishes command `g` once the calling thread's own range is done: claims each range no worker has
   * claimed and runs it here (`kernel` with `arrays`, the command's parameters, `ids` and that range's
   * bounds and part; null `kernel`: claims them only, after the caller's own range threw), then waits
   * for the ranges workers claimed. Returns the ranges taken over.
   * @throws Error `<system>: worker thread <i> died ...` if a worker's thread ended while it held a range.
   */
  private settle(system: string, g: number, kernel: Kernel | null, arrays: KernelArray[], ids: Int32Array | null): number {
    const ctl = this.ctl,
      t = this.threads;
    const here = this.takenHere;
    here.fill(0);
    let took = 0,
      i = 1;
    try {
      for (; i < t; i++) {
        if (Atomics.compareExchange(ctl, CONTROL.CLAIM + i, g, ~g) !== g) continue;
        here[i] = 1;
        took++;
        Atomics.sub(ctl, CONTROL.PENDING, 1);
        if (kernel === null) continue;
        try {
          this.results[i] = kernel(arrays, this.params, ids, ctl[CONTROL.BOUNDS + i]!, ctl[CONTROL.BOUNDS + i + 1]!, i, this.helpers);
        } catch (e) {
          // The same error as the worker's own run of the range would give.
          throw new Error(`${system}: a worker thread failed: ${e instanceof Error ? e.message : String(e)}`, { cause: e });
        }
      }
    } finally {
      // A range's kernel threw here: the ranges after it are closed, not run.
      for (i++; i < t; i++) {
        if (Atomics.compareExchange(ctl, CONTROL.CLAIM + i, g, ~g) !== g) continue;
        here[i] = 1;
        Atomics.sub(ctl, CONTROL.PENDING, 1);
      }
      this.rangesTakenOver += took;
      this.await(system, g);
    }
    return took;
  }

  /**
   * Waits until every range workers claimed of command `g` is done, in slices (see the file's
   * header), and checks between slices that the workers holding them live.
   * @throws Error `<system>: worker thread <i> died ...` (the pool is then disposed).
   */
  private await(system: string, g: number): void {
    const ctl = this.ctl;
    let p: number;
    for (;;) {
      if (this.blocking) {
        // Woken at once by the last worker's notify; the timeout only bounds the wait.
        if ((p = Atomics.load(ctl, CONTROL.PENDING)) === 0) return;
        Atomics.wait(ctl, CONTROL.PENDING, p, WAIT_SLICE_MS);
        if (Atomics.load(ctl, CONTROL.PENDING) === 0) return;
      } else {
        // A browser's main thread may not wait: it spins, reading the clock now and then.
        const until = Date.now() + WAIT_SLICE_MS;
        let k = 0;
        while (Atomics.load(ctl, CONTROL.PENDING) !== 0) {
          if ((++k & 1023) === 0 && Date.now() >= until) break;
        }
        if (Atomics.load(ctl, CONTROL.PENDING) === 0) return;
      }
      const lost = this.lostRange(g);
      if (lost !== null) this.fail(system, lost);
    }
  }

  /** Why command `g` cannot finish (a worker died holding a range, or the run took too long), or null while it may. */
  private lostRange(g: number): string | null {
    const ctl = this.ctl;
    const who = Atomics.load(ctl, CONTROL.DEAD);
    // Every range is claimed by now; one its worker claimed and did not finish before its thread ended is lost.
    if (who !== 0 && this.takenHere[who] === 0 && Atomics.load(ctl, CONTROL.DONE + who) !== g)
      return `worker thread ${who} died (its thread ended while it ran its range)`;
    if (Date.now() - this.dispatchedAt >= this.runLimitMs) return `the workers did not finish within runLimitMs (${this.runLimitMs} ms)`;
    return null;
  }

  /**
   * Replaces the workers whose threads ended (their `exit` or `error` event, or `DEAD`), before a
   * command; after MAX_REPLACEMENTS the pool stops using its workers (`failure`).
   */
  private heal(): void {
    if (this.disposed) return;
    const ctl = this.ctl;
    const who = Atomics.load(ctl, CONTROL.DEAD);
    if (who !== 0) {
      this.dead[who - 1] ??= `worker thread ${who} died (its thread ended)`;
      Atomics.store(ctl, CONTROL.DEAD, 0);
    }
    for (let i = 1; i < this.threads; i++) {
      const why = this.dead[i - 1];
      if (why === null || why === undefined) continue;
      this.dead[i - 1] = null;
      this.lastWorkerEvent = why;
      if (this.failure !== null) continue;
      if (this.workersReplaced >= MAX_REPLACEMENTS) {
        this.failure = `${why}, after ${MAX_REPLACEMENTS} workers replaced`;
        continue;
      }
      const old = this.workers[i - 1]!;
      void old.terminate();
      Atomics.store(ctl, CONTROL.HOLD + i, 0); // the new worker starts unheld
      try {
        this.workers[i - 1] = this.makeWorker(i);
        this.workersReplaced++;
        this.lastWorkerEvent = `${why}; replaced`;
      } catch (e) {
        this.failure = `${why}; no new worker (${String((e as { message?: unknown })?.message ?? e)})`;
      }
    }
  }

  /**
   * Gives up on the pool: records why, disposes it (the world's loops then run on the calling thread
   * alone) and throws. @throws Error `<system>: <why>; ...`.
   */
  private fail(system: string, why: string): never {
    this.failure ??= why;
    this.lastWorkerEvent = why;
    this.dispose();
    throw new Error(`${system}: ${why}; the thread pool is shut down and the world steps on the calling thread alone from now on`);
  }
}

/**
 * The test hook of worker lateness: worker `i` (1 .. threads - 1) of `pool` blocks before it claims its
 * next command's range (Atomics.wait, as a worker the system does not schedule would) while `hold`,
 * and goes on when called again with false. The package's index does not export it, so only code that
 * imports threads/pool.ts itself (the tests) reaches it.
 * @throws RangeError `holdWorkerForTests: ...` on an index that is not a worker's.
 * @category Threads
 */
export function holdWorkerForTests(pool: ThreadPool, i: number, hold: boolean): void {
  if (!Number.isInteger(i) || i < 1 || i >= pool.threads)
    throw new RangeError(`holdWorkerForTests: worker index must be an integer in [1, ${pool.threads - 1}], got ${i}`);
  // biome-ignore lint/complexity/useLiteralKeys: bracket access is TypeScript's way into the pool's private control array
  const ctl = pool['ctl'];
  Atomics.store(ctl, CONTROL.HOLD + i, hold ? 1 : 0);
  if (!hold) Atomics.notify(ctl, CONTROL.HOLD + i);
}

/**
 * Makes a pool of `threads` threads (the caller and threads - 1 workers) that runs the kernels of
 * `kernels` (a run names its kernel by its place there) with `helpers` as their last argument. The pool knows no
 * physics: a world's pool gets the physics kernel table (step/kernel-table.ts) from `enableThreads`.
 * @throws Error if SharedArrayBuffer is missing (a page that is not cross-origin isolated) or no
 *   worker can be made here; the message starts with `where`.
 * @category Threads
 */
export function createThreadPool(where: string, threads: number, kernels: readonly Kernel[], helpers: readonly KernelHelper[]): ThreadPool {
  if (!sharedMemoryAvailable()) {
    throw new Error(
      `${where}: threads > 1 needs SharedArrayBuffer (in a browser, serve the page cross-origin isolated: Cross-Origin-Opener-Policy: same-origin and Cross-Origin-Embedder-Policy: require-corp)`,
    );
  }
  const factory = defaultWorkerFactory();
  if (factory === null)
    throw new Error(
      `${where}: threads > 1 needs worker threads (Node >= 20.16 worker_threads, or a browser Worker), and none is available here`,
    );
  return new ThreadPool(threads, factory, kernels, helpers);
}
