/**
 * The hoop game's best score, kept in the browser's storage across reloads, one per court layout
 * (the wide court and a phone's tall one put the hoop in different spots, so their scores differ).
 * Storage may be missing or throw (private modes, blocked cookies): then the best lasts the page's
 * life. Pure apart from the storage passed in (no DOM).
 */

/** The storage this needs: localStorage's getItem and setItem. */
export interface BestStorage {
  getItem(key: string): string | null;
  setItem(key: string, value: string): void;
}

/** The wide court's key (the one the game has always used, so a best kept before stays). */
export const BEST_KEY = 'bitphysics.bouncing-balls.best-points';
/** The tall (phone) court's key. */
export const BEST_KEY_TALL = `${BEST_KEY}.tall`;

/** The key of the best for the tall (phone) court or the wide one. */
export function bestKey(tall: boolean): string {
  return tall ? BEST_KEY_TALL : BEST_KEY;
}

/** A stored value as a best: a whole number of points > 0, else 0 (missing, garbled, negative, fractional). */
function parseBest(value: string | null): number {
  if (value === null || value.trim() === '') return 0;
  const v = Number(value);
  return Number.isSafeInteger(v) && v > 0 ? v : 0;
}

/**
 * The best kept for the court (`tall` or wide) in `storage`, 0 when none, unreadable or not a whole
 * number of points > 0. The tall court with no best of its own takes the wide key's: a phone's best
 * was kept there before the courts had one each.
 */
export function readBest(storage: BestStorage | null, tall: boolean): number {
  if (!storage) return 0;
  try {
    const own = parseBest(storage.getItem(bestKey(tall)));
    return own > 0 || !tall ? own : parseBest(storage.getItem(BEST_KEY));
  } catch {
    return 0;
  }
}

/** Writes `best` points as the court's best in `storage`; a missing or failing storage is ignored. */
export function writeBest(storage: BestStorage | null, tall: boolean, best: number): void {
  if (!storage) return;
  try {
    storage.setItem(bestKey(tall), String(best));
  } catch {
    /* full or blocked: the best is kept for this page only */
  }
}

/** The page's localStorage, or null where reading it throws (some private modes) or there is none. */
export function pageStorage(): BestStorage | null {
  try {
    return typeof localStorage === 'undefined' ? null : localStorage;
  } catch {
    return null;
  }
}
