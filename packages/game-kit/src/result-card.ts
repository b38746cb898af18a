/**
 * A card drawn over a pixi.js scene at the end of a round or a level: a title, one big line (the
 * points, the stars) and a few lines of detail, on a rounded dark panel with a coloured edge.
 */

import { Container, Graphics, Text } from 'pixi.js';

/** Options of `createResultCard`. Every field is optional. */
export interface ResultCardOptions {
  /** The card container's label (pixi's `label`, handy in tests and devtools). Default 'result-card'. */
  label?: string;
  /** Font size of the big line, CSS px, > 0. Default 52. */
  bigSize?: number;
  /** Panel colour (0xRRGGBB). Default 0x0b0f18. */
  background?: number;
  /** Panel opacity in [0, 1]. Default 0.88. */
  backgroundAlpha?: number;
}

/** What a result card shows. */
export interface ResultCardContent {
  /** First line, bold ('Time!', 'Level 2 lit!'). */
  title: string;
  /** The big line in gold ('23 points', '★★☆'). */
  big: string;
  /** Lines of detail under it, each wrapped to the card's width; may be empty. */
  lines: readonly string[];
  /** Colour of the card's edge (0xRRGGBB). Default 0xffd166 (gold); e.g. a red for a lost level. */
  edge?: number;
}

/**
 * Where a result card goes, in the stage's CSS px. Give `top` (the card's upper edge) or `bottom`
 * (its lower edge, the card then grows upwards and stays at least `minTop` from the top).
 */
export interface ResultCardPlace {
  /** Centre of the card, x. */
  cx: number;
  /** Upper edge of the card, y. */
  top?: number;
  /** Lower edge of the card, y (used when `top` is not given). */
  bottom?: number;
  /** With `bottom`: the least y of the upper edge. Default 8. */
  minTop?: number;
  /** The widest the card may be, > 0. */
  maxWidth: number;
  /** Wrap width of the detail lines, > 0. Default `maxWidth - 56`. */
  wrapWidth?: number;
}

/** A result card made by `createResultCard`. */
export interface ResultCard {
  /** The card's container (already added to the stage given; hidden until `show`). */
  readonly container: Container;
  /** Shows `content` at `place`; lays the card out again only when the content or place changed. */
  show(content: ResultCardContent, place: ResultCardPlace): void;
  /** Hides the card. */
  hide(): void;
  /** The card's box as last laid out, CSS px (zeros before the first `show`). */
  readonly box: { readonly x: number; readonly y: number; readonly width: number; readonly height: number };
}

const FONT = 'system-ui, sans-serif';
/** Padding above the title and below the last line, px. */
const PAD = 14;

/**
 * Makes a result card and adds it, hidden, to `stage` (on top of what is there).
 * @param stage - The container to draw on, usually `app.stage`.
 * @param options - See ResultCardOptions.
 * @returns the card: `show(content, place)` and `hide()`.
 * @throws RangeError if `bigSize` is not a number > 0 or `backgroundAlpha` is not in [0, 1].
 */
export function createResultCard(stage: Container, options: ResultCardOptions = {}): ResultCard {
  const bigSize = options.bigSize ?? 52;
  if (!(bigSize > 0 && Number.isFinite(bigSize))) throw new RangeError(`createResultCard: bigSize must be a number > 0, got ${bigSize}`);
  const alpha = options.backgroundAlpha ?? 0.88;
  if (!(alpha >= 0 && alpha <= 1)) throw new RangeError(`createResultCard: backgroundAlpha must be in [0, 1], got ${alpha}`);
  const background = options.background ?? 0x0b0f18;
  const container = new Container({ label: options.label ?? 'result-card' });
  const back = new Graphics();
  const title = new Text({ text: '', style: { fontFamily: FONT, fontSize: 22, fontWeight: '700', fill: 0xffffff, align: 'center' } });
  const big = new Text({
    text: '',
    style: { fontFamily: FONT, fontSize: bigSize, fontWeight: '800', fill: 0xffd166, stroke: { color: 0x3a1a02, width: 6 } },
  });
  const lines = new Text({
    text: '',
    style: { fontFamily: FONT, fontSize: 16, fill: 0xe8ecf4, align: 'center', lineHeight: 24, wordWrap: true },
  });
  for (const t of [title, big, lines]) t.anchor.set(0.5, 0);
  container.addChild(back, title, big, lines);
  container.visible = false;
  stage.addChild(container);
  const box = { x: 0, y: 0, width: 0, height: 0 };
  let shown = '';

  return {
    container,
    box,
    show(content, place) {
      container.visible = true;
      const key = JSON.stringify([content, place]);
      if (key === shown) return;
      shown = key;
      title.text = content.title;
      big.text = content.big;
      lines.style.wordWrapWidth = Math.max(1, place.wrapWidth ?? place.maxWidth - 56);
      lines.text = content.lines.join('\n');
      const w = Math.min(place.maxWidth, Math.max(title.width, big.width, lines.width) + 48);
      const h = PAD + title.height + 2 + big.height + 4 + (content.lines.length ? lines.height : 0) + PAD;
      const top = place.top ?? Math.max(place.minTop ?? 8, Math.round((place.bottom ?? h) - h));
      title.position.set(place.cx, top + PAD);
      big.position.set(place.cx, title.y + title.height + 2);
      lines.position.set(place.cx, big.y + big.height + 4);
      back.clear();
      back
        .roundRect(place.cx - w / 2, top, w, h, 14)
        .fill({ color: background, alpha })
        .stroke({ width: 3, color: content.edge ?? 0xffd166, alpha: 0.9 });
      box.x = place.cx - w / 2;
      box.y = top;
      box.width = w;
      box.height = h;
    },
    hide() {
      container.visible = false;
      shown = '';
    },
  };
}
