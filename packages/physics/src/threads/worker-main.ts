/**
 * The body of every worker thread of a pool (pool.ts): its loop as source text, sent to the worker
 * together with the kernels (worker-source.ts).
 *
 * Protocol (WORKER_MAIN_SOURCE below), over the control Int32Array `ctl` on a SharedArrayBuffer (slots in `CONTROL`):
 * - the pool opens command g: it writes the command, then `CLAIM + i` = g for every worker i (range i
 *   open), `PENDING` = the workers, and raises `GEN` to g;
 * - the worker waits for `GEN` to change: it watches it for `SPIN` microseconds, then blocks in
 *   Atomics.wait. It then claims its range of the generation g it saw: Atomics.compareExchange of
 *   `CLAIM + index` from g to ~g. Only a claim that succeeds lets it read the command and write
 *   anything; a claim that fails means the calling thread took the range over (the worker was late)
 *   or a later command is open, and the worker writes nothing but a count in `STALE`, then looks at
 *   `GEN` again. The calling thread claims a range the same way, so each range of each command runs once;
 * - RUN (claimed): it runs kernel `KERNEL` with the arrays whose ids are in `ARRAYS..`, over its range
 *   of the loop, from `BOUNDS + index` to `BOUNDS + index + 1` (thread `index`, passed to the kernel
 *   as `part`; the main thread is thread 0), stores its kernel's return value in `results[index]`
 *   and when it finished in `finished[index]` (ms since the epoch, performance.timeOrigin + now():
 *   one clock across threads), writes g into `DONE + index` and decrements `PENDING` (notifying at 0);
 * - a worker that holds fewer arrays than `EXPECT` (new shared arrays were posted as messages) does not
 *   claim: it returns to its event loop to receive them, then tries the claim of g;
 * - QUIT: it leaves the loop (the pool then terminates it).
 * A kernel that throws sets `ERROR` and writes its message (char codes) into `errorText`. A Node
 * worker whose thread ends (process.exit, an uncaught error) writes its index into `DEAD` on its way
 * out and wakes the pool. `HOLD + index` is a test hook (pool.ts holdWorkerForTests): while it is
 * not 0 the worker blocks before it claims, as a worker the system does not schedule would.
 * No message is sent per step or per entity: the arrays travel once, when first used.
 */

/**
 * Slots of the control array shared by a pool and its workers.
 * @category Threads
 */
export const CONTROL = Object.freeze({
  GEN: 0,
  CMD: 1,
  KERNEL: 2,
  PENDING: 3,
  ERROR: 4,
  EXPECT: 5,
  READY: 6,
  /** Index of a worker whose thread ended (its exit hook wrote it), or 0. */
  DEAD: 7,
  /** Claims that failed: wake-ups of workers whose range the calling thread had taken over, or of a command already finished. */
  STALE: 8,
  IDS: 9,
  NARRAYS: 10,
  ARRAYS: 11,
  /**
   * Most arrays a kernel takes: room for the ball narrowphase on 16 threads (11 inputs, the buffer's
   * 10 fields, and 10 more per thread after the first: 171).
   */
  MAX_ARRAYS: 176,
  /** First slot of the ranges' bounds (ARRAYS + MAX_ARRAYS): thread i runs [ctl[BOUNDS + i], ctl[BOUNDS + i + 1]) (balance.ts). */
  BOUNDS: 187,
  /** Microseconds an idle worker watches `GEN` before it blocks in Atomics.wait (ThreadPool.idleSpin); after 65 bounds. */
  SPIN: 252,
  /** First slot of the ranges' claims: range i of command g is open while CLAIM + i holds g, taken once it holds ~g. */
  CLAIM: 253,
  /** First slot of the ranges' completions: worker i writes g into DONE + i when it finished its range of command g. */
  DONE: 253 + 64,
  /** First slot of the test hook: worker i blocks before it claims while HOLD + i is not 0 (pool.ts holdWorkerForTests). */
  HOLD: 253 + 128,
  /** Length of the control array (room for the claims, completions and holds of 64 threads). */
  LENGTH: 253 + 192,
});

/**
 * Commands in `CONTROL.CMD`.
 * @category Threads
 */
export const COMMAND = Object.freeze({ RUN: 0, QUIT: 2 });

/**
 * Message a pool posts to its workers.
 * @category Threads
 */
export type PoolMessage =
  | {
      type: 'init';
      index: number;
      ctl: Int32Array;
      params: Float64Array;
      results: Float64Array;
      finished: Float64Array;
      errorText: Uint16Array;
    }
  | { type: 'array'; id: number; array: ArrayBufferView };

/**
 * The worker's loop, as JavaScript source text: `workerMain(kernels, helpers, nodePort)` (helpers: the
 * kernels' last argument, solver/kernel-helpers.ts KERNEL_HELPERS) installs the message
 * handler on `nodePort` (Node's parentPort, or null for the browser's `self`) and serves the pool's
 * commands as the file's header describes. It is text, not a function of this module, because
 * bundlers rewrite inner functions (a minifier keeping names wraps them in a helper of its own
 * naming), which would leave the worker calling a helper it does not have. The control slots below
 * are those of `CONTROL`; commands those of `COMMAND`.
 * @category Threads
 */
export const WORKER_MAIN_SOURCE = `
function workerMain(kernels, helpers, nodePort) {
  var GEN = ${CONTROL.GEN}, CMD = ${CONTROL.CMD}, KERNEL = ${CONTROL.KERNEL}, PENDING = ${CONTROL.PENDING}, ERROR = ${CONTROL.ERROR}, EXPECT = ${CONTROL.EXPECT}, READY = ${CONTROL.READY}, DEAD = ${CONTROL.DEAD}, STALE = ${CONTROL.STALE}, IDS = ${CONTROL.IDS}, NARRAYS = ${CONTROL.NARRAYS}, ARRAYS = ${CONTROL.ARRAYS}, BOUNDS = ${CONTROL.BOUNDS}, SPIN = ${CONTROL.SPIN}, CLAIM = ${CONTROL.CLAIM}, DONE = ${CONTROL.DONE}, HOLD = ${CONTROL.HOLD};
  var RUN = ${COMMAND.RUN}, QUIT = ${COMMAND.QUIT};
  var arrays = [], have = 0, ctl = null, params = null, results = null, finished = null, errorText = null, index = 0, seen = 0, waiting = false, args = [];
  var clock = globalThis.performance;
  function fail(e) {
    var text = String(e instanceof Error ? e.message : e);
    var n = Math.min(text.length, errorText.length - 1);
    for (var i = 0; i < n; i++) errorText[i] = text.charCodeAt(i);
    errorText[n] = 0;
    Atomics.store(ctl, ERROR, 1);
  }
  // Waits for GEN to move past seen: a spin of ctl[SPIN] microseconds first (a run that follows soon
  // then starts at once, and the caller's notify finds no sleeper to wake), then Atomics.wait.
  function idle() {
    var spinMs = ctl[SPIN] / 1000;
    if (spinMs > 0 && clock !== undefined) {
      var t0 = clock.now(), k = 0;
      while (Atomics.load(ctl, GEN) === seen) {
        if ((++k & 127) === 0 && clock.now() - t0 >= spinMs) break;
      }
    }
    Atomics.wait(ctl, GEN, seen);
  }
  // Serves command g: false when the worker must leave its loop (QUIT, or arrays to receive first).
  function serve(g) {
    if (ctl[CMD] === QUIT) return false;
    // The test hook: block here, before the claim, while the pool holds this worker.
    for (var h; (h = Atomics.load(ctl, HOLD + index)) !== 0; ) Atomics.wait(ctl, HOLD + index, h);
    if (have < ctl[EXPECT]) {
      waiting = true;
      return false;
    }
    // The claim: nothing of command g is read or written unless this range of g is still open.
    if (Atomics.compareExchange(ctl, CLAIM + index, g, ~g) !== g) {
      Atomics.add(ctl, STALE, 1);
      return true;
    }
    if (ctl[CMD] !== RUN) return true;
    try {
      var na = ctl[NARRAYS];
      args.length = na;
      for (var i = 0; i < na; i++) args[i] = arrays[ctl[ARRAYS + i]];
      var idsId = ctl[IDS];
      var ids = idsId < 0 ? null : arrays[idsId];
      var lo = ctl[BOUNDS + index], hi = ctl[BOUNDS + index + 1];
      results[index] = kernels[ctl[KERNEL]](args, params, ids, lo, hi, index, helpers);
      finished[index] = clock !== undefined ? clock.timeOrigin + clock.now() : Date.now();
    } catch (e) {
      fail(e);
    }
    Atomics.store(ctl, DONE + index, g);
    if (Atomics.sub(ctl, PENDING, 1) === 1) Atomics.notify(ctl, PENDING);
    return true;
  }
  // The loop; 'again' serves the generation already seen first (after the arrays it waited for came).
  function loop(again) {
    for (;;) {
      if (!again) {
        idle();
        var g = Atomics.load(ctl, GEN);
        if (g === seen) continue;
        seen = g;
      }
      again = false;
      if (!serve(seen)) return;
    }
  }
  function onMessage(m) {
    if (m.type === 'init') {
      ctl = m.ctl; params = m.params; results = m.results; finished = m.finished; errorText = m.errorText; index = m.index;
      // A command already open when this worker starts (it replaces a dead one) is the caller's.
      seen = Atomics.load(ctl, GEN);
      // A thread that ends says so (the pool would otherwise wait for its range forever).
      if (nodePort !== null && typeof process === 'object' && typeof process.on === 'function') {
        process.on('exit', function () {
          Atomics.store(ctl, DEAD, index);
          Atomics.notify(ctl, PENDING);
        });
      }
      Atomics.add(ctl, READY, 1);
      Atomics.notify(ctl, READY);
      // One message at start-up, so the pool's ready promise resolves without a timer.
      if (nodePort !== null) nodePort.postMessage({ type: 'ready' });
      else globalThis.postMessage({ type: 'ready' });
      loop(false);
      return;
    }
    if (m.type === 'array') {
      arrays[m.id] = m.array;
      have++;
      if (waiting && ctl !== null && have >= ctl[EXPECT]) {
        waiting = false;
        loop(true);
      }
    }
  }
  if (nodePort !== null) nodePort.on('message', onMessage);
  else globalThis.onmessage = function (e) { onMessage(e.data); };
}
`;
