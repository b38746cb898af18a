/**
 * Text legibility of a page's own text (toolbar, readouts, legends, status lines, panels): the WCAG
 * 2.x contrast ratio of every visible text element's colour against the colour behind it, found by
 * compositing the background colours of its ancestors and the boxes under its centre (`elementsFromPoint`) over
 * the page's (html and body, else white); over a canvas, the worse of a white and a black scene.
 * Text drawn into a canvas is not seen. WCAG AA asks for 4.5:1, or 3:1 for large text (24 px, or
 * 18.66 px bold). (Relative luminance and contrast ratio: WCAG 2.1, definitions of the same names.)
 */
import type { Page } from 'playwright-core';

/** One text element below the bar. */
export interface LowContrast {
  /** The start of its text. */
  text: string;
  /** Its contrast ratio against what is behind it, rounded to 0.01. */
  ratio: number;
  /** Its colour and the composited background, CSS rgb(). */
  color: string;
  background: string;
}

/** The visible text elements of `page` whose contrast is below WCAG AA (4.5:1; 3:1 for large text). */
export function lowContrastText(page: Page): Promise<LowContrast[]> {
  return page.evaluate(() => {
    type RGBA = [number, number, number, number];
    const parse = (css: string): RGBA | null => {
      const m = /^rgba?\(([^)]+)\)$/.exec(css.trim());
      if (!m) return null;
      const p = m[1]!
        .split(/[\s,/]+/)
        .filter(Boolean)
        .map(Number);
      return [p[0]!, p[1]!, p[2]!, p.length > 3 ? p[3]! : 1];
    };
    /** `top` over the opaque `under`. */
    const over = (top: RGBA, under: RGBA): RGBA => [
      top[0] * top[3] + under[0] * (1 - top[3]),
      top[1] * top[3] + under[1] * (1 - top[3]),
      top[2] * top[3] + under[2] * (1 - top[3]),
      1,
    ];
    const luminance = (c: RGBA): number => {
      const lin = (v: number): number => {
        const s = v / 255;
        return s <= 0.04045 ? s / 12.92 : ((s + 0.055) / 1.055) ** 2.4;
      };
      return 0.2126 * lin(c[0]) + 0.7152 * lin(c[1]) + 0.0722 * lin(c[2]);
    };
    const ratio = (a: RGBA, b: RGBA): number => {
      const la = luminance(a),
        lb = luminance(b);
      return (Math.max(la, lb) + 0.05) / (Math.min(la, lb) + 0.05);
    };
    let base: RGBA = [255, 255, 255, 1];
    for (const el of [document.documentElement, document.body]) {
      const c = parse(getComputedStyle(el).backgroundColor);
      if (c && c[3] > 0) base = over(c, base);
    }
    const out: { text: string; ratio: number; color: string; background: string }[] = [];
    const walker = document.createTreeWalker(document.body, NodeFilter.SHOW_TEXT);
    const seen = new Set<Element>();
    for (let n = walker.nextNode(); n; n = walker.nextNode()) {
      const el = n.parentElement;
      if (!el || seen.has(el) || !n.textContent?.trim()) continue;
      seen.add(el);
      if (el.closest('script, style, canvas, select, [hidden]')) continue; // a select's options are not shown until opened
      const style = getComputedStyle(el);
      if (style.visibility !== 'visible' || el.getClientRects().length === 0) continue;
      const rect = el.getBoundingClientRect();
      if (rect.right <= 0 || rect.bottom <= 0 || rect.left >= innerWidth || rect.top >= innerHeight) continue;
      const fg = parse(style.color);
      if (!fg) continue;
      // The backgrounds behind the text: its own and its ancestors', then, down to the first opaque one
      // or a canvas, the other boxes painted under its centre (the layout's info column under the
      // toolbar, the canvas under a label); composited bottom-up.
      const layers: RGBA[] = [];
      let opaque = false,
        overCanvas = false;
      const chain = new Set<Element>();
      for (let a: Element | null = el; a && a !== document.body; a = a.parentElement) {
        chain.add(a);
        const c = parse(getComputedStyle(a).backgroundColor);
        if (c && c[3] > 0) layers.push(c);
        if (c && c[3] >= 1) {
          opaque = true;
          break;
        }
      }
      const r0 = el.getClientRects()[0]!;
      if (!opaque)
        for (const a of document.elementsFromPoint(r0.left + r0.width / 2, r0.top + r0.height / 2)) {
          if (a === document.body || a === document.documentElement) break;
          if (chain.has(a) || el.contains(a)) continue;
          if (a.tagName === 'CANVAS') {
            overCanvas = true;
            break;
          }
          const c = parse(getComputedStyle(a).backgroundColor);
          if (c && c[3] > 0) layers.push(c);
          if (c && c[3] >= 1) break;
        }
      // Over a canvas the scene's colour is unknown: the worse of a white and a black scene under the backings.
      const bases: RGBA[] = overCanvas
        ? [
            [255, 255, 255, 1],
            [0, 0, 0, 1],
          ]
        : [base];
      let r = Infinity,
        bg = base,
        colour = fg;
      for (const under of bases) {
        let b = under;
        for (let i = layers.length - 1; i >= 0; i--) b = over(layers[i]!, b);
        const c = over(fg, b);
        const rb = ratio(c, b);
        if (rb < r) {
          r = rb;
          bg = b;
          colour = c;
        }
      }
      const size = Number.parseFloat(style.fontSize),
        bold = Number(style.fontWeight) >= 700;
      const bar = size >= 24 || (bold && size >= 18.66) ? 3 : 4.5;
      if (r < bar) {
        const rgb = (c: RGBA) => `rgb(${c.slice(0, 3).map(Math.round).join(', ')})`;
        out.push({ text: n.textContent.trim().slice(0, 40), ratio: Math.round(r * 100) / 100, color: rgb(colour), background: rgb(bg) });
      }
    }
    return out;
  });
}
