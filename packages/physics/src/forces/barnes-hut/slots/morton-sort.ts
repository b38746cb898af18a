/**
 * The argument slots of the Morton sort's three kernels (forces/barnes-hut/gather.ts: mortonKeysHist,
 * mortonScatter, mortonBucketSort), filled by mortonSort and buildTree (forces/barnes-hut/tree-build.ts):
 * where each array sits in a kernel's `A` (a kernel's own slots, named after it) and each number in the
 * `P` the three share, imported as `SORT` (`A[SORT.KEYS_HIST]`, `P[SORT.SCALE]`) by the kernels and by
 * their caller. A module of numeric constants only, which every build folds into the code
 * (threads/worker-source.ts).
 *
 * A call's range [lo, hi) is a range of parts; part p of the first two kernels holds bodies
 * floor(n p / parts) .. floor(n (p + 1) / parts) - 1 (the same in both, so the scatter sees the
 * histogram's bodies); the last kernel's parts are ranges of buckets.
 */

// A of mortonKeysHist (pass 1).
/** Position x, m (Float64, input order). */
export const KEYS_X = 0;
/** Position y, m. */
export const KEYS_Y = 1;
/** Position z, m (3D only). */
export const KEYS_Z = 2;
/** The Morton key of each body (Uint32, out, input order). */
export const KEYS_KEY = 3;
/** Each part's histogram of the first digit (Int32, out: 2^P[BITS] counts a part, the part's at p * 2^P[BITS]). */
export const KEYS_HIST = 4;

// A of mortonScatter (pass 2).
/** The keys (Uint32, input order). */
export const SCATTER_KEY = 0;
/** The keys by first digit (Uint32, out). */
export const SCATTER_KEY2 = 1;
/** The input index of each placed key (Int32, out). */
export const SCATTER_IDX2 = 2;
/** Each part's first place of each digit (Int32, 2^P[BITS] a part, the part's at p * 2^P[BITS]; advanced as it goes). */
export const SCATTER_OFFSET = 3;

// A of mortonBucketSort (pass 3).
/** Pass 2's keys (Uint32; also scratch). */
export const BUCKETS_KEY2 = 0;
/** Pass 2's input indices (Int32; also scratch). */
export const BUCKETS_IDX2 = 1;
/** The sorted keys (Uint32, out). */
export const BUCKETS_KEY = 2;
/** The input index of each sorted key (Int32, out: the tree's perm). */
export const BUCKETS_PERM = 3;
/** Each bucket's first slot (Int32, 2^P[BITS] + 1 entries). */
export const BUCKETS_FIRST = 4;
/** The parts' runs of buckets (Int32: part p sorts buckets group[p] .. group[p + 1] - 1). */
export const BUCKETS_GROUP = 5;
/** Each part's digit counts (Int32, BUCKET_RADIX a part). */
export const BUCKETS_LOCAL = 6;
/** Position x, m (Float64, input order). */
export const BUCKETS_X = 7;
/** Position y, m. */
export const BUCKETS_Y = 8;
/** Position z, m. */
export const BUCKETS_Z = 9;
/** Mass, kg (Float64, input order). */
export const BUCKETS_MASS = 10;
/** Position x in tree order, m (Float64, out). */
export const BUCKETS_TX = 11;
/** Position y in tree order, m (out). */
export const BUCKETS_TY = 12;
/** Position z in tree order, m (out; 3D only: in 2D it stays 0). */
export const BUCKETS_TZ = 13;
/** Mass in tree order, kg (out). */
export const BUCKETS_TM = 14;

// P: the numbers the three kernels share.
/** The root cube's low corner x, m. */
export const X0 = 0;
/** The root cube's low corner y, m. */
export const Y0 = 1;
/** The root cube's low corner z, m. */
export const Z0 = 2;
/** Key units per metre. */
export const SCALE = 3;
/** The largest key coordinate. */
export const TOP = 4;
/** The world's dimensions, 2 or 3. */
export const DIMENSIONS = 5;
/** The body count n. */
export const COUNT = 6;
/** The part count. */
export const PARTS = 7;
/** The first digit's shift: the key's bits less P[BITS]. */
export const SHIFT = 8;
/** The first digit's bits (at most SORT_RADIX_BITS, forces/barnes-hut/gather.ts). */
export const BITS = 9;
/** Numbers in P. */
export const PARAMS = 10;

// The buckets' sort (mortonBucketSort).
/** Digits of the passes that sort a large bucket (the bits below the first digit, 8 at a time). */
export const BUCKET_RADIX = 256;
/** Buckets of at most this many keys are sorted by insertion, larger ones by radix passes. */
export const BUCKET_INSERTION_MAX = 48;
