/**
 * The rotating cube's controls legend (and the phone's touch card) for each mode, in a player's
 * words: in the room the keys roll the cube over an edge (W A S D) and turn it a quarter turn flat
 * on the floor (Q E); on the free-spin pivot they push the spin arrow's tip the way they say on
 * screen; with the flipping box they torque it about the screen's axes. The page swaps the
 * legend when the mode changes (main.ts `setMode`).
 */
import type { ControlHint } from '@bitphysics/game-kit';
import type { Mode } from './scene';

/**
 * The legend lines of `mode` ('room', 'cube' or 'flip'), before
 * the camera's orbit lines. `touch`: whether the page runs on a touch screen, where a drag across
 * the cube flicks it (a plain tap there picks the floor cell under the finger, as elsewhere).
 */
export function cubeControls(mode: Mode, touch: boolean): ControlHint[] {
  const room = mode === 'room';
  return [
    room
      ? touch
        ? { keys: 'Tap', action: 'a floor cell: slide the cube onto it; drag across the cube: flick it', touch: 'Tap' }
        : { keys: 'Click', action: 'a floor cell: slide the cube onto it (a ROLL tile beside it: roll onto it)', touch: 'Tap' }
      : { keys: 'Click', action: 'a face: knock it there', touch: 'Tap' },
    room
      ? { keys: 'W A S D', action: 'roll the cube over an edge: away, left, toward you, right', touch: '▲ ◀ ▼ ▶' }
      : mode === 'cube'
        ? {
            keys: 'W S, A D',
            action: touch
              ? "push the spin arrow's tip that way on screen"
              : "push the spin arrow's tip up or down (W S), left or right (A D) on screen",
            touch: '▲▼ ◀▶',
          }
        : { keys: 'W S, A D', action: 'spin it: tip it away or toward you (W S), turn it left or right (A D)', touch: 'Pitch ▲▼ Yaw ◀▶' },
    room
      ? {
          keys: 'Q E',
          action: 'turn it a quarter turn flat on the floor, left or right (counts as a move)',
          touch: '⟲ ⟳',
        }
      : mode === 'cube'
        ? { keys: 'Q E', action: "push the spin arrow's tip toward you or away", touch: 'Near Far' }
        : { keys: 'Q E', action: 'spin it like a wheel facing you, left or right', touch: 'Roll ⟲ ⟳' },
    { keys: 'X', action: 'stop spinning', touch: 'Stop' },
    ...(room ? [{ keys: 'Space', action: 'jump (free: not a move)', touch: 'Jump', card: false }] : []),
    { keys: 'M', action: 'mode: pads / spin the cube / flipping box', touch: 'Mode' },
  ];
}

/** A finger's press that moves more than this, CSS px, is a drag, not a tap (fingers wobble more than a mouse). */
export const TAP_SLOP = 12;

/**
 * What a finger's press in the room does, from where it went down (`onCube`: on the cube) and how
 * far it moved before it lifted (`movedPx`, CSS px, >= 0): 'flick' (a drag that started on the
 * cube: the cube slides the way the finger went), 'push' (a tap: the cube slides to the floor cell
 * under the finger, whether the cube's picture covers that cell or not), 'none' (a drag from the
 * floor, which turns the camera).
 * @throws RangeError when movedPx is negative or not finite.
 */
export function touchPress(onCube: boolean, movedPx: number): 'flick' | 'push' | 'none' {
  if (!(movedPx >= 0 && Number.isFinite(movedPx))) throw new RangeError(`touchPress: movedPx must be finite and >= 0, got ${movedPx}`);
  const moved = movedPx > TAP_SLOP;
  if (onCube) return moved ? 'flick' : 'push';
  return moved ? 'none' : 'push';
}

/** Room mode: the most roll presses that wait for the cube while it is busy (RollQueue). */
export const ROLL_QUEUE_MAX = 2;

/**
 * Room mode: roll keys pressed while the cube is busy (a roll still turning, or the cube not yet at
 * rest) wait here, up to ROLL_QUEUE_MAX of them, and are pressed in order as the cube comes to rest,
 * so a quick run of presses rolls once for each (a stranger lost one press in five to a queue of one).
 * A press beyond the queue's room replaces its last key (the latest wish wins). With nothing waiting, a
 * roll key still held when the cube rests rolls it again: holding a key rolls one cell after another,
 * each landing square, at the rolls' own pace rather than the keyboard's repeat rate.
 */
export class RollQueue {
  /** The roll keys waiting ('w', 'a', 's' or 'd'), oldest first; at most ROLL_QUEUE_MAX. */
  readonly pending: string[] = [];
  /**
   * A fresh press of roll key `key` with the cube `busy` or not. @returns whether it acts now (the
   * cube free and nothing waiting); otherwise it waits at the queue's end (or replaces its last key when full).
   */
  press(key: string, busy: boolean): boolean {
    if (!busy && this.pending.length === 0) return true;
    if (this.pending.length < ROLL_QUEUE_MAX) this.pending.push(key);
    else this.pending[this.pending.length - 1] = key;
    return false;
  }
  /**
   * The key to press now that the cube is free (`busy` false): the oldest waiting (taken out of the
   * queue), else the last of the roll keys still `held` (in the order they went down), else ''; '' while busy.
   */
  take(busy: boolean, held: readonly string[] = []): string {
    if (busy) return '';
    return this.pending.shift() ?? held[held.length - 1] ?? '';
  }
  /** Forgets the waiting rolls (a new world). */
  clear(): void {
    this.pending.length = 0;
  }
}
