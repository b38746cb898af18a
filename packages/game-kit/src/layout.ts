/**
 * The page layout every game shares: a grid that keeps the scene (the canvas) clear of the text and
 * panels around it, at every window size.
 *
 * Wide windows (at least `COMPACT_MAX_WIDTH` x `COMPACT_MAX_HEIGHT` CSS px):
 *
 *     | toolbar | status   | side  |     toolbar: title and buttons (pause, step, reset), atop the info column
 *     | info    | stage    |       |     info: readout (fps, a physics fold, a lab's numbers); help: the controls
 *     | help    | controls |       |     side: the parameter panel and the charts; status: a game's banner
 *
 * Small windows (phones, landscape or portrait): one column, toolbar / status / stage / controls;
 * info-and-help and side become drawers that the toolbar's buttons open over the scene (closed at
 * start, so nothing covers the scene until asked; a press outside the open drawer and the toolbar
 * closes it). The canvas fills the stage; the world renderer
 * fits its view into it (letterboxed, aspect kept, never cropped).
 *
 * A game's page may ask for the game arrangement with `<body data-layout="game">`: on wide windows the
 * side column is then a drawer too (the toolbar's settings button opens it over the scene's right
 * edge, closed at start), so the scene takes the width a lab gives its panel and charts; small windows
 * are arranged as for every page.
 *
 * On touch devices the help shows each control's touch gesture instead of its key, and keyboard-only
 * controls are left out (the toolbar has pause, step and reset buttons; games add on-screen pads to
 * the controls row).
 *
 * A readout a page appends straight to body with the HUD's class ('bp-hud') is moved into the side
 * column. DOM only. The first call of `pageLayout` builds it; later calls return the same one.
 */
import { onButtonPress } from './button-press.js';

/** Below this window width, CSS px, the layout is compact (toolbar and drawers). */
export const COMPACT_MAX_WIDTH = 700;
/** Below this window height, CSS px, the layout is compact (landscape phones). */
export const COMPACT_MAX_HEIGHT = 460;
/** Width of the info column in the wide layout, CSS px. */
export const INFO_WIDTH = 220;

/** The regions of a page. */
export interface PageLayout {
  /** The grid (a direct child of body). `data-open` names the open drawer on small screens ('info', 'side' or absent). */
  readonly root: HTMLElement;
  /** Title and buttons. */
  readonly toolbar: HTMLElement;
  /** Where `addButton` puts buttons (inside the toolbar). */
  readonly buttons: HTMLElement;
  /** The readout column (fps, the physics fold with bodies and steps, numbers). */
  readonly info: HTMLElement;
  /** The controls legend (inside the info column, at its bottom). */
  readonly help: HTMLElement;
  /** A row above the scene for a game's banner (lives and score, a lab's status line); hidden while empty. */
  readonly status: HTMLElement;
  /** The scene's box: the canvas goes in here and fills it. */
  readonly stage: HTMLElement;
  /** A row under the scene for on-screen controls (touch pads); hidden while empty. */
  readonly controls: HTMLElement;
  /** The right column: parameter panel, charts, docks; hidden while empty. */
  readonly side: HTMLElement;
  /** Whether the page asked for the game arrangement (`<body data-layout="game">`): its side column is a drawer on wide windows too. */
  readonly game: boolean;
  /** Whether the compact (small-screen) arrangement is in effect now. */
  compact(): boolean;
  /** Whether the device's main pointer is a finger (CSS `pointer: coarse`). */
  touch(): boolean;
  /** Sets the page title shown in the toolbar (and the document's title prefix). */
  setTitle(title: string): void;
  /**
   * Adds a toolbar button: `icon` (a key of `ICONS`, or a short text) with `label` as its accessible
   * name and tooltip; `onClick` runs on click or tap. @returns the button.
   */
  addButton(icon: string, label: string, onClick: () => void): HTMLButtonElement;
  /**
   * Width, CSS px, a column of the side region should take: `preferred` on wide windows, capped at
   * 34% of the window (at least 240) there and at the window's width on small screens.
   */
  sideWidth(preferred: number): number;
  /**
   * Opens drawer `which` on small screens (closes the other); `null` closes both. On wide windows only
   * the game arrangement's side drawer opens (see `game`); other calls have no effect there.
   */
  open(which: 'info' | 'side' | null): void;
}

/**
 * Toolbar icons as inline SVG (fonts on phones and in headless browsers often lack the media-control
 * symbols): pause-or-play, single step, reset, the info drawer and the settings drawer.
 */
export const ICONS = Object.freeze({
  pause:
    '<svg viewBox="0 0 16 16" width="16" height="16" aria-hidden="true"><path d="M3 2h3.5v12H3zM9.5 2H13v12H9.5z" fill="currentColor"/></svg>',
  play: '<svg viewBox="0 0 16 16" width="16" height="16" aria-hidden="true"><path d="M4 2l10 6-10 6z" fill="currentColor"/></svg>',
  step: '<svg viewBox="0 0 16 16" width="16" height="16" aria-hidden="true"><path d="M2 2l8 6-8 6zM11 2h3v12h-3z" fill="currentColor"/></svg>',
  reset:
    '<svg viewBox="0 0 16 16" width="16" height="16" aria-hidden="true"><path d="M8 2.5a5.5 5.5 0 1 1-5.2 3.7" fill="none" stroke="currentColor" stroke-width="1.8"/><path d="M1.5 2.5l1.6 4.4 4.2-1.8z" fill="currentColor"/></svg>',
  info: '<svg viewBox="0 0 16 16" width="16" height="16" aria-hidden="true"><path d="M2 3h12v2H2zM2 7h12v2H2zM2 11h12v2H2z" fill="currentColor"/></svg>',
  settings:
    '<svg viewBox="0 0 16 16" width="16" height="16" aria-hidden="true"><path d="M2 4h7M13 4h1M2 12h1M7 12h7" stroke="currentColor" stroke-width="1.6"/><circle cx="11" cy="4" r="2" fill="none" stroke="currentColor" stroke-width="1.6"/><circle cx="5" cy="12" r="2" fill="none" stroke="currentColor" stroke-width="1.6"/></svg>',
});

/**
 * The backing of every text region (toolbar, info, status, controls, side): dark and nearly opaque,
 * so light text on it keeps a contrast of at least 4.5:1 (WCAG AA) over any page or scene colour.
 */
export const BACKING = 'rgba(12, 16, 24, 0.86)';

const STYLE_ID = 'bp-layout-style';
const CSS = `
html, body { margin: 0; height: 100%; overflow: hidden; }
.bp-app { position: fixed; inset: 0; display: grid; box-sizing: border-box;
  grid-template-columns: ${INFO_WIDTH}px minmax(0, 1fr) auto; grid-template-rows: auto minmax(0, 1fr) auto;
  grid-template-areas: "info status side" "info stage side" "info controls side";
  color: #e8ecf1; font: 13px/1.45 system-ui, sans-serif; }
.bp-toolbar { grid-area: info; align-self: start; z-index: 1; display: flex; flex-wrap: wrap; align-items: center; gap: 6px; padding: 8px 10px 4px; min-width: 0; }
.bp-toolbar h1 { font: 600 15px/1.3 system-ui, sans-serif; margin: 0; flex: 1 0 100%; min-width: 0; }
.bp-toolbar .bp-buttons { display: flex; gap: 4px; flex-wrap: wrap; }
.bp-toolbar button { display: inline-flex; align-items: center; justify-content: center; font: 15px/1 system-ui, sans-serif; min-width: 34px; height: 30px; padding: 0 8px; color: #e8ecf1; cursor: pointer;
  background: rgba(255, 255, 255, 0.06); border: 1px solid #4a5468; border-radius: 6px; touch-action: manipulation; }
.bp-toolbar button:hover { background: rgba(255, 255, 255, 0.14); }
.bp-toolbar button[aria-pressed="true"] { background: rgba(255, 209, 102, 0.25); border-color: #ffd166; }
.bp-toolbar .bp-drawer-button { display: none; }
@media (pointer: coarse) { .bp-toolbar button { min-width: 44px; height: 44px; } }
.bp-info { grid-area: info; display: flex; flex-direction: column; gap: 8px; padding: calc(var(--bp-toolbar-height, 68px) + 4px) 10px 10px; overflow-y: auto; min-height: 0; box-sizing: border-box; }
.bp-info, .bp-side, .bp-status, .bp-controls { background: ${BACKING}; }
.bp-info .bp-help { margin-top: 4px; padding-top: 10px; border-top: 1px solid #2a3242; }
.bp-status { grid-area: status; min-width: 0; }
.bp-status:empty, .bp-controls:empty, .bp-side:empty { display: none; }
.bp-stage { grid-area: stage; position: relative; overflow: hidden; min-width: 0; min-height: 0; }
.bp-stage > canvas { position: absolute; left: 0; top: 0; display: block; }
.bp-controls { grid-area: controls; display: flex; justify-content: center; gap: 12px; padding: 6px; }
.bp-side { grid-area: side; display: flex; flex-direction: column; gap: 6px; padding: 6px; overflow-y: auto; min-height: 0; box-sizing: border-box;
  min-width: 270px; max-width: 45vw; }
.bp-side > * { flex-shrink: 0; }
.bp-side .lil-gui.lil-root { width: auto; }
@media (max-width: ${COMPACT_MAX_WIDTH - 0.02}px), (max-height: ${COMPACT_MAX_HEIGHT - 0.02}px) {
  .bp-app { grid-template-columns: minmax(0, 1fr); grid-template-rows: auto auto minmax(0, 1fr) auto;
    grid-template-areas: "toolbar" "status" "stage" "controls"; }
  /* The title wraps beside the buttons (two lines fit their 44 px height); a word wider than the room
     left moves the buttons to a row of their own, so the whole title stays readable. */
  .bp-toolbar { grid-area: toolbar; align-self: auto; flex-wrap: wrap; padding: 6px; gap: 5px; background: ${BACKING}; }
  .bp-toolbar h1 { flex: 1 1 0; min-width: min-content; font-size: 14px; line-height: 1.2; text-wrap: balance; }
  .bp-toolbar .bp-buttons { flex-wrap: nowrap; gap: 3px; margin-left: auto; }
  .bp-toolbar .bp-drawer-button { display: inline-flex; }
  .bp-info, .bp-side { position: fixed; z-index: 30; top: var(--bp-toolbar-height, 44px); max-height: calc(100% - var(--bp-toolbar-height, 44px));
    display: none; background: rgb(16, 20, 28); border-radius: 0 0 8px 8px; box-shadow: 0 6px 18px rgba(0, 0, 0, 0.5); }
  .bp-info { left: 0; width: min(100%, 320px); padding-top: 6px; }
  .bp-side { right: 0; width: min(100%, 380px); min-width: 0; max-width: none; }
  .bp-app[data-open="info"] .bp-info { display: flex; }
  .bp-app[data-open="side"] .bp-side:not(:empty) { display: flex; }
}
@media (min-width: ${COMPACT_MAX_WIDTH}px) and (min-height: ${COMPACT_MAX_HEIGHT}px) {
  .bp-app.bp-game { grid-template-columns: ${INFO_WIDTH}px minmax(0, 1fr); grid-template-areas: "info status" "info stage" "info controls"; }
  .bp-app.bp-game .bp-toolbar .bp-side-button { display: inline-flex; }
  .bp-app.bp-game .bp-side { position: fixed; z-index: 30; top: 8px; right: 8px; max-height: calc(100% - 16px);
    display: none; background: rgba(16, 20, 28, 0.96); border-radius: 8px; box-shadow: 0 6px 18px rgba(0, 0, 0, 0.5); }
  .bp-app.bp-game[data-open="side"] .bp-side:not(:empty) { display: flex; }
}
`;

let layout: PageLayout | null = null;

/** The compact media query (small screens). */
function compactQuery(): MediaQueryList {
  return window.matchMedia(`(max-width: ${COMPACT_MAX_WIDTH - 0.02}px), (max-height: ${COMPACT_MAX_HEIGHT - 0.02}px)`);
}

/**
 * The page's layout, built on first call (appended to body, its CSS injected).
 * @throws Error outside a browser (no document).
 */
export function pageLayout(): PageLayout {
  if (layout) return layout;
  if (typeof document === 'undefined') throw new Error('pageLayout: needs a browser page');
  if (!document.getElementById(STYLE_ID)) {
    const style = document.createElement('style');
    style.id = STYLE_ID;
    style.textContent = CSS;
    document.head.prepend(style);
  }
  const el = (tag: string, className: string): HTMLElement => {
    const e = document.createElement(tag);
    e.className = className;
    return e;
  };
  const root = el('div', 'bp-app');
  const game = document.body.dataset.layout === 'game';
  if (game) root.classList.add('bp-game');
  const toolbar = el('header', 'bp-toolbar');
  const title = el('h1', 'bp-title');
  const buttons = el('div', 'bp-buttons');
  toolbar.append(title, buttons);
  const info = el('section', 'bp-info');
  info.setAttribute('aria-label', 'information and controls');
  const help = el('div', 'bp-help');
  info.append(help);
  const status = el('div', 'bp-status');
  const stage = el('main', 'bp-stage');
  const controls = el('div', 'bp-controls');
  const side = el('aside', 'bp-side');
  side.setAttribute('aria-label', 'parameters and charts');
  root.append(toolbar, status, info, stage, controls, side);
  document.body.prepend(root);

  const query = compactQuery();
  const coarse = window.matchMedia('(pointer: coarse)');
  const drawerButtons: Record<'info' | 'side', HTMLButtonElement | null> = { info: null, side: null };

  const open = (which: 'info' | 'side' | null): void => {
    if (which === null || root.dataset.open === which) delete root.dataset.open;
    else root.dataset.open = which;
    for (const [name, b] of Object.entries(drawerButtons)) b?.setAttribute('aria-pressed', String(root.dataset.open === name));
  };
  const addButton = (icon: string, label: string, onClick: () => void): HTMLButtonElement => {
    const b = document.createElement('button');
    b.type = 'button';
    if (icon in ICONS) b.innerHTML = ICONS[icon as keyof typeof ICONS];
    else b.textContent = icon;
    b.title = label;
    b.setAttribute('aria-label', label);
    onButtonPress(b, onClick);
    buttons.append(b);
    return b;
  };
  // Drawer buttons (small screens only, by CSS): info-and-help, and the side column when it has content.
  const infoButton = addButton('info', 'information and controls', () => open('info'));
  infoButton.classList.add('bp-drawer-button');
  drawerButtons.info = infoButton;
  const sideButton = addButton('settings', 'parameters and charts', () => open('side'));
  sideButton.classList.add('bp-drawer-button', 'bp-side-button');
  drawerButtons.side = sideButton;
  const syncSideButton = (): void => {
    sideButton.style.display = side.childElementCount === 0 ? 'none' : '';
  };
  new MutationObserver(syncSideButton).observe(side, { childList: true });
  syncSideButton();
  // Drawers sit under the toolbar, whatever its height.
  new ResizeObserver(() => root.style.setProperty('--bp-toolbar-height', `${toolbar.offsetHeight}px`)).observe(toolbar);
  // A readout box a page appends to body (class 'bp-hud', as pages did before this layout) goes to
  // the side column instead of floating over the scene.
  const adopt = (node: Node): void => {
    if (!(node instanceof HTMLElement) || node.parentElement !== document.body || !node.classList.contains('bp-hud')) return;
    for (const k of ['top', 'bottom', 'left', 'right', 'position'] as const) node.style[k] = '';
    side.append(node);
  };
  new MutationObserver((records) => {
    for (const r of records) r.addedNodes.forEach(adopt);
  }).observe(document.body, { childList: true });
  // On a small screen, where the drawers lie over the scene, a press anywhere outside the open drawer
  // and the toolbar (the scene, the touch pads) closes it, so a player who taps the scene to get back
  // to the game gets it back; the press goes on to what it was on. Capture phase: a canvas or pad
  // that stops the event still closes the drawer.
  document.addEventListener(
    'pointerdown',
    (e) => {
      const which = root.dataset.open;
      if (which === undefined || !query.matches || !(e.target instanceof Node)) return;
      const drawer = which === 'info' ? info : side;
      if (!drawer.contains(e.target) && !toolbar.contains(e.target)) open(null);
    },
    { capture: true },
  );
  // Growing into the wide arrangement closes the drawers (but for the game arrangement's side drawer,
  // which the wide arrangement has too).
  query.addEventListener('change', () => {
    if (!query.matches && !(game && root.dataset.open === 'side')) open(null);
  });

  layout = {
    root,
    toolbar,
    buttons,
    info,
    help,
    status,
    stage,
    controls,
    side,
    game,
    compact: () => query.matches,
    touch: () => coarse.matches,
    setTitle(text) {
      title.textContent = text;
      if (!document.title) document.title = text;
    },
    addButton,
    sideWidth(preferred) {
      if (query.matches) return Math.max(200, Math.min(preferred, window.innerWidth - 12));
      return Math.round(Math.min(preferred, Math.max(240, window.innerWidth * 0.34)));
    },
    open,
  };
  return layout;
}

/**
 * Pauses `game` while a drawer of the page (the menu or the settings, `data-open` on the layout's
 * root) is open, and resumes it when the drawer closes if the drawer paused it; a pause the player
 * made stays. Play a player cannot see (a stone flying, a round's clock running under the menu) then
 * waits for them.
 * @param game anything with a writable `paused` flag (a game shell, a 3D game).
 * @param options `compactOnly` (default false): only on a small screen (`PageLayout.compact()`),
 *   where the drawers cover the scene; on a large one they sit beside it.
 * @returns a function that stops watching the drawers.
 * @throws Error outside a browser (as pageLayout).
 */
export function pauseUnderDrawers(game: { paused: boolean }, options: { compactOnly?: boolean } = {}): () => void {
  const page = pageLayout();
  const compactOnly = options.compactOnly ?? false;
  let pausedByDrawer = false;
  const observer = new MutationObserver(() => {
    const open = page.root.dataset.open !== undefined && (!compactOnly || page.compact());
    if (open && !game.paused) {
      game.paused = true;
      pausedByDrawer = true;
    } else if (!open && pausedByDrawer) {
      pausedByDrawer = false;
      if (game.paused) game.paused = false;
    }
  });
  observer.observe(page.root, { attributes: true, attributeFilter: ['data-open'] });
  return () => observer.disconnect();
}
