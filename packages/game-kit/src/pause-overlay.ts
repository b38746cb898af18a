/**
 * The pause overlay of a pixi.js game: the scene dimmed and "Paused" with how to resume in the middle,
 * so that a paused game is not mistaken for a hung one.
 */

import { Container, Graphics, Text } from 'pixi.js';

/** Options of `createPauseOverlay`. Every field is optional. */
export interface PauseOverlayOptions {
  /** The overlay container's label (pixi's `label`, handy in tests and devtools). Default 'paused'. */
  label?: string;
  /** Opacity of the black shade over the scene, in [0, 1]. Default 0.45. */
  shadeAlpha?: number;
  /** Font size of the words, CSS px, > 0. Default 40 (32 on a view under 500 px wide). */
  fontSize?: number;
  /**
   * Whether a tap or click on the paused scene resumes the game (the game does it: the overlay only
   * says so): the words then say 'Tap to resume' on a touch screen and 'Click or P to resume' with a
   * mouse. Default false ('▶ to resume' / 'P to resume').
   */
  tapToResume?: boolean;
}

/** A pause overlay made by `createPauseOverlay`. */
export interface PauseOverlay {
  /** The overlay's container: the shade, then the words. Add it where it should be drawn (above the scene). */
  readonly container: Container;
  /** Whether the overlay shows (as last drawn). */
  readonly visible: boolean;
  /** The words as last drawn ('' before the first draw while paused). */
  readonly text: string;
  /**
   * The words' Text, anchored at its centre. `draw` puts it in the middle of the view; a game may move
   * it after each `draw` (e.g. off what the player needs to see while paused).
   */
  readonly words: Text;
  /**
   * Shows the overlay over a `width` x `height` px view when `paused`, else hides it. The words say
   * how to resume: '▶ to resume' when `touch`, else 'P to resume' (with `tapToResume`, 'Tap to
   * resume' and 'Click or P to resume'). Cheap when nothing changed.
   */
  draw(paused: boolean, width: number, height: number, touch: boolean): void;
}

/**
 * Makes a pause overlay, hidden. Add `container` to the stage (on top), and call `draw` every frame.
 * @param options - See PauseOverlayOptions.
 * @returns the overlay.
 * @throws RangeError if `shadeAlpha` is not in [0, 1] or `fontSize` is not a number > 0.
 */
export function createPauseOverlay(options: PauseOverlayOptions = {}): PauseOverlay {
  const alpha = options.shadeAlpha ?? 0.45;
  if (!(alpha >= 0 && alpha <= 1)) throw new RangeError(`createPauseOverlay: shadeAlpha must be in [0, 1], got ${alpha}`);
  const size = options.fontSize;
  if (size !== undefined && !(size > 0 && Number.isFinite(size)))
    throw new RangeError(`createPauseOverlay: fontSize must be a number > 0, got ${size}`);
  const container = new Container({ label: options.label ?? 'paused' });
  const shade = new Graphics();
  const words = new Text({
    text: '',
    style: {
      fill: 0xffffff,
      fontSize: size ?? 40,
      fontWeight: '800',
      fontFamily: 'system-ui, sans-serif',
      align: 'center',
      stroke: { color: 0x000000, width: 6 },
    },
  });
  words.anchor.set(0.5);
  container.addChild(shade, words);
  container.visible = false;
  let shadeW = -1,
    shadeH = -1;
  return {
    container,
    get visible() {
      return container.visible;
    },
    get text() {
      return words.text;
    },
    words,
    draw(paused, width, height, touch) {
      container.visible = paused;
      if (!paused) return;
      if (width !== shadeW || height !== shadeH) {
        shade.clear().rect(0, 0, width, height).fill({ color: 0x000000, alpha });
        shadeW = width;
        shadeH = height;
      }
      const text = options.tapToResume
        ? touch
          ? 'Paused\nTap to resume'
          : 'Paused\nClick or P to resume'
        : touch
          ? 'Paused\n▶ to resume'
          : 'Paused\nP to resume';
      if (words.text !== text) words.text = text;
      const fontSize = size ?? (width < 500 ? 32 : 40);
      if (words.style.fontSize !== fontSize) words.style.fontSize = fontSize;
      words.position.set(width / 2, height / 2);
    },
  };
}
