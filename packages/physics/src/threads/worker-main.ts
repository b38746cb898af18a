/**
 * The body of every worker thread of a pool (pool.ts). It is sent to the worker as source text,
 * together with the kernels (worker-source.ts), so it refers to nothing but its arguments and
 * JavaScript's globals.
 *
 * Protocol, over the control Int32Array `ctl` on a SharedArrayBuffer (slots in `CONTROL`):
 * - the worker waits (Atomics.wait) for `GEN` to change; then reads `CMD`;
 * - RUN: it runs kernel `KERNEL` with the arrays whose ids are in `ARRAYS..`, over its range of
 *   [0, `COUNT`) (thread `index` of `THREADS`; the main thread is thread 0), stores its kernel's
 *   return value in `results[index]` and decrements `PENDING` (notifying at 0);
 * - SYNC: new shared arrays were posted as messages; the worker returns to its event loop to receive
 *   them, and reports done once it holds `EXPECT` arrays;
 * - QUIT: it leaves the loop (the pool then terminates it).
 * A kernel that throws sets `ERROR` and writes its message (char codes) into `errorText`.
 * No message is sent per step or per entity: the arrays travel once, when first used.
 */

/** Slots of the control array shared by a pool and its workers. */
export const CONTROL = Object.freeze({
  GEN: 0, CMD: 1, KERNEL: 2, PENDING: 3, ERROR: 4, EXPECT: 5, READY: 6, COUNT: 7, THREADS: 8, IDS: 9, NARRAYS: 10, ARRAYS: 11,
  /** Most arrays a kernel takes. */
  MAX_ARRAYS: 24,
  /** Length of the control array. */
  LENGTH: 36,
});

/** Commands in `CONTROL.CMD`. */
export const COMMAND = Object.freeze({ RUN: 0, SYNC: 1, QUIT: 2 });

/** Port of a worker: the browser's worker global or Node's parentPort. */
export interface WorkerPort {
  postMessage(message: unknown): void;
}

/** Message a pool posts to its workers. */
export type PoolMessage =
  | { type: 'init'; index: number; ctl: Int32Array; params: Float64Array; results: Float64Array; errorText: Uint16Array }
  | { type: 'array'; id: number; array: ArrayBufferView };

/**
 * Runs in the worker: installs the message handler on `port` (Node's parentPort, or null for the
 * browser's `self`) and serves the pool's commands. `kernels` are the functions of kernels.ts.
 */
export function workerMain(
  kernels: ReadonlyArray<(A: unknown[], P: Float64Array, ids: Int32Array | null, lo: number, hi: number) => number>,
  nodePort: { on(event: 'message', f: (m: PoolMessage) => void): void } | null,
): void {
  const C = { GEN: 0, CMD: 1, KERNEL: 2, PENDING: 3, ERROR: 4, EXPECT: 5, READY: 6, COUNT: 7, THREADS: 8, IDS: 9, NARRAYS: 10, ARRAYS: 11 };
  const RUN = 0, SYNC = 1, QUIT = 2;
  const arrays: unknown[] = [];
  let have = 0;
  let ctl: Int32Array | null = null;
  let params: Float64Array | null = null;
  let results: Float64Array | null = null;
  let errorText: Uint16Array | null = null;
  let index = 0;
  let seen = 0;
  let waiting = false;
  const args: unknown[] = [];

  const finish = (): void => {
    const c = ctl!;
    if (Atomics.sub(c, C.PENDING, 1) === 1) Atomics.notify(c, C.PENDING);
  };
  const fail = (e: unknown): void => {
    const text = String(e instanceof Error ? e.message : e);
    const out = errorText!;
    const n = Math.min(text.length, out.length - 1);
    for (let i = 0; i < n; i++) out[i] = text.charCodeAt(i);
    out[n] = 0;
    Atomics.store(ctl!, C.ERROR, 1);
  };
  const loop = (): void => {
    const c = ctl!;
    for (;;) {
      Atomics.wait(c, C.GEN, seen);
      const g = Atomics.load(c, C.GEN);
      if (g === seen) continue;
      seen = g;
      const cmd = c[C.CMD];
      if (cmd === QUIT) return;
      if (cmd === SYNC) {
        if (have >= c[C.EXPECT]!) { finish(); continue; }
        waiting = true;
        return;
      }
      if (cmd !== RUN) continue;
      try {
        const na = c[C.NARRAYS]!;
        args.length = na;
        for (let i = 0; i < na; i++) args[i] = arrays[c[C.ARRAYS + i]!];
        const idsId = c[C.IDS]!;
        const ids = idsId < 0 ? null : (arrays[idsId] as Int32Array);
        const n = c[C.COUNT]!, t = c[C.THREADS]!;
        const lo = Math.floor((n * index) / t), hi = Math.floor((n * (index + 1)) / t);
        results![index] = kernels[c[C.KERNEL]!]!(args, params!, ids, lo, hi);
      } catch (e) {
        fail(e);
      }
      finish();
    }
  };
  const onMessage = (m: PoolMessage): void => {
    if (m.type === 'init') {
      ctl = m.ctl; params = m.params; results = m.results; errorText = m.errorText; index = m.index;
      seen = Atomics.load(ctl, C.GEN);
      Atomics.add(ctl, C.READY, 1);
      Atomics.notify(ctl, C.READY);
      loop();
      return;
    }
    if (m.type === 'array') {
      arrays[m.id] = m.array;
      have++;
      if (waiting && ctl !== null && have >= ctl[C.EXPECT]!) {
        waiting = false;
        finish();
        loop();
      }
    }
  };
  if (nodePort !== null) nodePort.on('message', onMessage);
  else (globalThis as unknown as { onmessage: (e: { data: PoolMessage }) => void }).onmessage = (e) => onMessage(e.data);
}
