/**
 * A pool of worker threads that run ranges of a system's loop on shared memory (issue: every core).
 * Thread 0 is the calling (main) thread; threads 1 .. n-1 are workers (Node `worker_threads` or the
 * browser's `Worker`), each built from the same source (worker-source.ts) and holding views of the
 * same SharedArrayBuffers. A `run` writes the kernel, the range size and the array ids into a small
 * control array, wakes the workers with Atomics.notify, runs range 0 itself and waits (Atomics.wait,
 * or a spin on a browser's main thread, where waiting is not allowed) until every worker is done.
 *
 * Each array travels to the workers once, in a message, the first time a kernel uses it; nothing is
 * sent per step or per entity. Workers are unref'd in Node, so a pool never keeps the process alive;
 * `dispose` stops and terminates them.
 *
 * A worker that dies never finishes its range, so no wait here is unbounded: the calling thread
 * waits in slices of WAIT_SLICE_MS and between them checks that every worker took the command (a
 * live worker acknowledges it at once: worker-main.ts `ACK`; one that has not after ACK_LIMIT_MS is
 * dead), that none wrote `DEAD` on its way out, that no `error` or `exit` event came, and that the
 * run has not taken `runLimitMs`. A dead worker makes the run throw
 * `<system>: worker thread <i> died ...`; the pool is then disposed and the world steps on one thread.
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

/**
 * Milliseconds within which a live worker acknowledges a command (it writes the generation as soon
 * as it wakes, whatever the run's length); a worker that has not is taken for dead. Far above the
 * wake-up latency of a loaded machine (microseconds to tens of milliseconds; a live worker on two
 * cores shared by about fifteen busy threads once took over 500 ms), and short enough that a frozen
 * worker is reported within a few seconds. A worker whose thread ends is reported at once (`DEAD`,
 * its `exit` event), not after this limit.
 * @category Threads
 */
export const ACK_LIMIT_MS = 2000;

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
  private readonly workers: AnyWorker[];
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
  /** Resolves `ready` (set by the constructor). */
  private resolveReady: (() => void) | null = null;
  /** The first error a worker died of (it could not start), or null: the pool then runs on one thread. */
  failure: string | null = null;
  /**
   * How a worker that had started died (an `error` or `exit` event, seen between steps), or null. The
   * next run throws it (then the pool is disposed and the world steps on one thread).
   */
  lost: string | null = null;
  /**
   * Most milliseconds one run (or start and join) may take before the calling thread gives up on the
   * workers (a worker stuck in an endless kernel, or killed while it ran). Default 60,000: no loop of a
   * step comes near it. The run then throws and the pool is disposed.
   */
  runLimitMs = 60_000;
  /** Loops this pool has run on its threads (a count for tests and the bench). */
  runs = 0;

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
    this.ctl = new Int32Array(new SharedArrayBuffer(CONTROL.LENGTH * 4));
    this.ctl[CONTROL.SPIN] = IDLE_SPIN_MICROSECONDS;
    this.params = sharedFloat64(MAX_PARAMS);
    this.results = sharedFloat64(threads);
    this.finished = sharedFloat64(threads);
    this.balance = new RangeBalance(threads);
    this.errorText = new Uint16Array(new SharedArrayBuffer(ERROR_TEXT * 2));
    this.idBuffer = new Int32Array(new SharedArrayBuffer(4));
    this.blocking = canBlock();
    const source = workerSource(kernels, helpers);
    this.workers = [];
    const started: Array<Promise<void>> = [];
    for (let i = 1; i < threads; i++) {
      const w = factory(source);
      w.unref?.();
      // A worker that dies must not crash the process. One that could not start: the pool falls back
      // to one thread. One that had started: the next run says so (see `lost`).
      const died = (e: unknown): void => {
        if (this.disposed) return;
        const text = String((e as { message?: unknown })?.message ?? e);
        this.failure ??= text;
        this.lost ??= `worker thread ${i} died (${text})`;
      };
      if (typeof w.on === 'function') {
        w.on('error', died);
        w.on('exit', (code: unknown) => {
          if (!this.disposed) this.lost ??= `worker thread ${i} exited (code ${String(code)})`;
        });
      } else w.onerror = died;
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
      this.workers.push(w);
    }
    // Each worker posts one 'ready' message once it has joined the control buffer (no timer: the
    // physics package uses none); dispose resolves the promise too.
    const ctl = this.ctl,
      want = threads - 1;
    started.push(
      new Promise<void>((resolve) => {
        this.resolveReady = resolve;
        if (Atomics.load(ctl, CONTROL.READY) >= want) resolve();
      }),
    );
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
    this.ready = Promise.all(started).then(() => undefined);
  }

  /**
   * Whether parallel loops choose between the threads and one thread by the time each takes
   * (adaptive.ts; default true). False: every loop long enough runs on the threads (for tests).
   */
  adaptive = true;

  /** The per-loop choices of an adaptive pool. */
  readonly chooser = new LoopChooser();

  /** Whether every worker has started (a browser pool runs on one thread until then). */
  isReady(): boolean {
    return !this.disposed && this.failure === null && Atomics.load(this.ctl, CONTROL.READY) >= this.workers.length;
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
   * Runs `kernel` (a function of the pool's kernel table) over [0, n) split into `threads` contiguous ranges (in
   * proportion to how fast each thread has run this kernel: balance.ts), with
   * `arrays` (each on a SharedArrayBuffer; at most CONTROL.MAX_ARRAYS) and the scalar `params` (at most
   * 64); `ids` (null: dense ids lo+1..hi) is copied to a shared buffer. Returns the sum of the ranges'
   * return values, in thread order.
   * @throws RangeError naming `system` if `kernel` is not in the pool's table or `arrays` or `params` is
   *   too long (nothing runs).
   * @throws Error naming `system` if a worker's range threw (the message is the worker's), or if a
   *   worker died (`<system>: worker thread <i> died ...`; the pool is disposed, the world steps on one thread).
   */
  run(system: string, kernel: Kernel, arrays: KernelArray[], params: ArrayLike<number>, n: number, ids: ArrayLike<number> | null): number {
    this.join();
    if (this.lost !== null) this.fail(system, this.lost);
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
    this.dispatch(COMMAND.RUN);
    this.runs++;
    const t = this.threads;
    let own: number,
      t1 = t0;
    try {
      own = kernel(arrays, this.params, ids === null ? null : this.idBuffer, 0, ctl[CONTROL.BOUNDS + 1]!, 0, this.helpers);
      t1 = epochMs();
    } finally {
      this.await(system);
    }
    if (ctl[CONTROL.ERROR] !== 0) throw new Error(`${system}: a worker thread failed: ${this.workerError()}`);
    this.balance.record(k, n, t0, t1, this.finished);
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
    this.sync(system);
    const P = this.params;
    for (let i = 0; i < params.length; i++) P[i] = params[i]!;
    ctl[CONTROL.KERNEL] = k;
    ctl[CONTROL.NARRAYS] = arrays.length;
    ctl[CONTROL.IDS] = idsId;
    ctl[CONTROL.ERROR] = 0;
    return k;
  }

  /** The system of the kernel `start` left running on a worker, or null. */
  private started: string | null = null;

  /**
   * Starts `kernel` (a function of the pool's kernel table) over all of [0, n) on the first worker alone and returns at
   * once, so the calling thread can do other work meanwhile (work that neither writes what the kernel
   * reads nor reads what it writes); `join` waits for it. The other threads' ranges are empty
   * ([n, n) and, for the caller, [0, 0)), so the kernel must do nothing on an empty range. The next
   * `run` or `start` joins it first. Needs a usable pool (`usable()`) with at least one worker.
   * @throws RangeError naming `system` if the pool has no usable worker or `arrays` or `params` is too long.
   */
  start(system: string, kernel: Kernel, arrays: KernelArray[], params: ArrayLike<number>, n: number): void {
    this.join();
    if (this.lost !== null) this.fail(system, this.lost);
    if (this.workers.length === 0 || !this.usable()) throw new RangeError(`${system}: ThreadPool.start needs a usable worker`);
    this.setUp(system, kernel, arrays, params, -1);
    const ctl = this.ctl;
    ctl[CONTROL.BOUNDS] = 0;
    ctl[CONTROL.BOUNDS + 1] = 0;
    for (let i = 2; i <= this.threads; i++) ctl[CONTROL.BOUNDS + i] = n;
    this.started = system;
    this.dispatch(COMMAND.RUN);
    this.runs++;
  }

  /**
   * Waits for the kernel `start` left running (nothing if none) and returns its result (0 if none).
   * @throws Error naming the started kernel's system if the worker's range threw.
   */
  join(): number {
    const system = this.started;
    if (system === null) return 0;
    this.started = null;
    this.await(system);
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
    this.started = null;
    const ctl = this.ctl;
    ctl[CONTROL.CMD] = COMMAND.QUIT;
    Atomics.add(ctl, CONTROL.GEN, 1);
    Atomics.notify(ctl, CONTROL.GEN);
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
      this.pendingSync = true;
    }
    return id;
  }

  private pendingSync = false;

  /** Makes every worker receive the arrays posted since the last sync (they leave their wait loop to read messages). */
  private sync(system: string): void {
    if (!this.pendingSync) return;
    this.pendingSync = false;
    this.ctl[CONTROL.EXPECT] = this.ids.size;
    this.dispatch(COMMAND.SYNC);
    this.await(system);
  }

  /** When the last command was dispatched (Date.now(), ms). */
  private dispatchedAt = 0;

  private dispatch(cmd: number): void {
    const ctl = this.ctl;
    ctl[CONTROL.CMD] = cmd;
    Atomics.store(ctl, CONTROL.PENDING, this.workers.length);
    this.dispatchedAt = Date.now();
    Atomics.add(ctl, CONTROL.GEN, 1);
    Atomics.notify(ctl, CONTROL.GEN);
  }

  /**
   * Waits until every worker has finished the last command, in slices (see the file's header), and
   * checks between slices that they all live.
   * @throws Error `<system>: worker thread <i> died ...` (the pool is then disposed).
   */
  private await(system: string): void {
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
      const dead = this.deadWorker();
      if (dead !== null) this.fail(system, dead);
    }
  }

  /** Why the last command cannot finish (a worker is dead, or the run took too long), or null while it may. */
  private deadWorker(): string | null {
    const ctl = this.ctl;
    const who = Atomics.load(ctl, CONTROL.DEAD);
    if (who !== 0) return `worker thread ${who} died (its thread ended)`;
    if (this.lost !== null) return this.lost;
    const waited = Date.now() - this.dispatchedAt;
    if (waited >= ACK_LIMIT_MS) {
      const gen = Atomics.load(ctl, CONTROL.GEN);
      for (let i = 1; i <= this.workers.length; i++) {
        if (Atomics.load(ctl, CONTROL.ACK + i) !== gen)
          return `worker thread ${i} died (it did not take the command within ${ACK_LIMIT_MS} ms)`;
      }
    }
    if (waited >= this.runLimitMs) return `the workers did not finish within runLimitMs (${this.runLimitMs} ms)`;
    return null;
  }

  /**
   * Gives up on the pool: records why, disposes it (the world's loops then run on the calling thread
   * alone) and throws. @throws Error `<system>: <why>; ...`.
   */
  private fail(system: string, why: string): never {
    this.failure ??= why;
    this.lost ??= why;
    this.dispose();
    throw new Error(`${system}: ${why}; the thread pool is shut down and the world steps on the calling thread alone from now on`);
  }
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
