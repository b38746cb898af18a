/**
 * What the layout test checks on a page (run in the page by `checkLayout`): the scene's box on
 * screen, overlays that cover it, and things cut off.
 *
 * The scene's box is the renderer's view rectangle (the pixi camera's fitted world rectangle, mapped
 * to the screen and offset by the canvas), or the canvas for pages without one (3D). An overlay is
 * any visible element, other than the canvas and the elements that contain it, whose box meets the
 * scene's box by more than 2 px each way; elements marked `data-scene-overlay` (labels drawn as part
 * of the scene) are skipped with their children. Clipped: the scene's box reaching outside the
 * canvas or the window (the world cropped), a layout region reaching outside the window, text cut
 * off by an element that hides its overflow (with or without an ellipsis), or the page's title not
 * shown whole (wider or taller than its box, or under a toolbar button).
 */
import type { Page } from 'playwright-core';

/** A box in CSS px. */
export interface Box {
  x: number;
  y: number;
  width: number;
  height: number;
}

/** What `checkLayout` found. */
export interface LayoutReport {
  /** The scene's box on screen. */
  scene: Box;
  /** Where it came from: 'camera view' or 'canvas'. */
  sceneFrom: string;
  /** Fraction of the window's area the scene's box takes, in [0, 1]. */
  sceneShare: number;
  /**
   * How fully the scene's box spans the canvas along its tighter direction: max(scene width / canvas
   * width, scene height / canvas height). Near 1 when the world is framed to fit (letterboxed).
   */
  sceneFill: number;
  /** Elements covering the scene: 'tag.class "text" at x,y wxh'. */
  overlays: string[];
  /** Things cut off: descriptions. */
  clipped: string[];
}

/** Runs the checks in `page` (a ready game page). */
export function checkLayout(page: Page): Promise<LayoutReport> {
  return page.evaluate(() => {
    const r = (b: DOMRect | { x: number; y: number; width: number; height: number }) => ({
      x: b.x,
      y: b.y,
      width: b.width,
      height: b.height,
    });
    const describeEl = (el: Element): string => {
      const b = el.getBoundingClientRect();
      const cls = typeof el.className === 'string' && el.className ? `.${el.className.trim().split(/\s+/).join('.')}` : '';
      const text = (el.textContent ?? '').trim().replace(/\s+/g, ' ').slice(0, 40);
      return `${el.tagName.toLowerCase()}${cls} "${text}" at ${Math.round(b.x)},${Math.round(b.y)} ${Math.round(b.width)}x${Math.round(b.height)}`;
    };
    const canvas = (document.querySelector('.bp-stage canvas') ?? document.querySelector('canvas')) as HTMLCanvasElement | null;
    if (!canvas) throw new Error('no canvas');
    const cb = canvas.getBoundingClientRect();
    const game = (
      window as unknown as {
        game?: {
          renderer?: {
            camera?: {
              view: { minX: number; minY: number; maxX: number; maxY: number } | null;
              toScreenX(x: number): number;
              toScreenY(y: number): number;
            };
          };
        };
      }
    ).game;
    const cam = game?.renderer?.camera;
    let scene = r(cb);
    let sceneFrom = 'canvas';
    if (cam?.view && typeof cam.toScreenX === 'function') {
      const x0 = cam.toScreenX(cam.view.minX),
        x1 = cam.toScreenX(cam.view.maxX);
      const y0 = cam.toScreenY(cam.view.maxY),
        y1 = cam.toScreenY(cam.view.minY);
      scene = { x: cb.x + x0, y: cb.y + y0, width: x1 - x0, height: y1 - y0 };
      sceneFrom = 'camera view';
    }
    const W = window.innerWidth,
      H = window.innerHeight;
    const clipped: string[] = [];
    const tol = 1.5;
    if (
      scene.x < cb.x - tol ||
      scene.y < cb.y - tol ||
      scene.x + scene.width > cb.right + tol ||
      scene.y + scene.height > cb.bottom + tol
    ) {
      clipped.push(`scene ${JSON.stringify(scene)} reaches outside the canvas ${JSON.stringify(r(cb))}`);
    }
    if (cb.x < -tol || cb.y < -tol || cb.right > W + tol || cb.bottom > H + tol)
      clipped.push(`canvas ${JSON.stringify(r(cb))} reaches outside the window ${W}x${H}`);
    const ancestors = new Set<Element>();
    for (let e: Element | null = canvas; e; e = e.parentElement) ancestors.add(e);
    const overlays: string[] = [];
    const visible = (el: Element): boolean => {
      const st = getComputedStyle(el);
      if (st.display === 'none' || st.visibility === 'hidden' || Number(st.opacity) === 0) return false;
      const b = el.getBoundingClientRect();
      return b.width > 0 && b.height > 0;
    };
    const walk = (el: Element): void => {
      if (el instanceof HTMLElement && el.dataset.sceneOverlay !== undefined) return;
      if (el.tagName === 'SCRIPT' || el.tagName === 'STYLE' || el.tagName === 'HEAD') return;
      const st = getComputedStyle(el);
      if (st.display === 'none') return;
      if (el !== canvas && !ancestors.has(el) && visible(el)) {
        const b = el.getBoundingClientRect();
        const ix = Math.min(b.right, scene.x + scene.width) - Math.max(b.x, scene.x);
        const iy = Math.min(b.bottom, scene.y + scene.height) - Math.max(b.y, scene.y);
        if (ix > 2 && iy > 2) {
          overlays.push(describeEl(el));
          return; // its children are covered by the report of their parent
        }
        // Text cut off by an element that hides its overflow (an ellipsis counts as cut off too).
        const hides = /hidden|clip/.test(st.overflowX) || /hidden|clip/.test(st.overflowY);
        if (
          hides &&
          !['CANVAS', 'INPUT', 'TEXTAREA', 'SELECT'].includes(el.tagName) &&
          (el.scrollWidth > el.clientWidth + 2 || el.scrollHeight > el.clientHeight + 2)
        ) {
          clipped.push(
            `${describeEl(el)} cuts off its content (${el.scrollWidth}x${el.scrollHeight} in ${el.clientWidth}x${el.clientHeight})`,
          );
        }
      }
      for (const child of Array.from(el.children)) walk(child);
    };
    walk(document.body);
    // Layout regions and their direct children stay inside the window (scrolling columns may scroll).
    for (const el of Array.from(
      document.querySelectorAll('.bp-toolbar, .bp-status, .bp-controls, .bp-info, .bp-side, .bp-toolbar > *, .bp-plot'),
    )) {
      if (!visible(el)) continue;
      const b = el.getBoundingClientRect();
      const inScroller = el.closest('.bp-side, .bp-info') !== null && !el.matches('.bp-side, .bp-info');
      if (b.x < -tol || b.right > W + tol || (!inScroller && (b.y < -tol || b.bottom > H + tol)))
        clipped.push(`${describeEl(el)} reaches outside the window ${W}x${H}`);
    }
    // The page's title is shown whole: its text fits its box, and the box clears the toolbar's buttons.
    const title = document.querySelector('.bp-title');
    if (title && visible(title)) {
      if (title.scrollWidth > title.clientWidth + 1 || title.scrollHeight > title.clientHeight + 1)
        clipped.push(
          `${describeEl(title)}: title cut off (${title.scrollWidth}x${title.scrollHeight} in ${title.clientWidth}x${title.clientHeight})`,
        );
      const t = title.getBoundingClientRect();
      for (const b of Array.from(document.querySelectorAll('.bp-toolbar button'))) {
        if (!visible(b)) continue;
        const bb = b.getBoundingClientRect();
        if (Math.min(t.right, bb.right) - Math.max(t.x, bb.x) > 0.5 && Math.min(t.bottom, bb.bottom) - Math.max(t.y, bb.y) > 0.5)
          clipped.push(`${describeEl(title)}: title under the button ${describeEl(b)}`);
      }
    }
    // Chart titles fit their chart.
    for (const t of Array.from(document.querySelectorAll('.bp-plot .u-title'))) {
      if (t.scrollWidth > t.clientWidth + 2) clipped.push(`${describeEl(t)}: chart title cut off`);
    }
    const share = Math.max(0, scene.width * scene.height) / (W * H);
    const fill = Math.max(scene.width / Math.max(1, cb.width), scene.height / Math.max(1, cb.height));
    return { scene, sceneFrom, sceneShare: share, sceneFill: fill, overlays, clipped };
  });
}
