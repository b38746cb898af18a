/**
 * The rotating cube's end-of-round banner: a card over the middle of the stage with a title ("All 5
 * pads!"), the result in large type (the stars, the moves) and a line of detail, and two actions
 * a player reaches by keyboard and by touch: Next (the Enter key, or the button) and Retry (the R
 * key, which is the game's reset, or the button). The card ignores pointers outside its buttons, so
 * the scene behind it still turns under a drag.
 */

/** What the banner shows and what its two buttons do. */
export interface WinBannerContent {
  /** First line, bold ('All 5 pads!', 'Time!'). */
  title: string;
  /** The result in large gold type ('★★★ 9 moves'). */
  big: string;
  /** A line of detail under it (par, best, time); may be ''. */
  detail: string;
  /** The Next button's words ('Next round'), run by the button and by Enter. */
  next: string;
  /** The Retry button's words ('Retry'), run by the button (R runs the game's reset, the same). */
  retry: string;
  /** Whether the round was won (a gold edge) or lost (a red one). */
  won: boolean;
}

/** A banner made by `createWinBanner`. */
export interface WinBanner {
  /** The banner's element (in the stage given, hidden until `show`). */
  readonly element: HTMLElement;
  /** Shows `content` (and lays it out again only when it changed). */
  show(content: WinBannerContent): void;
  /** Hides the banner. */
  hide(): void;
  /** Whether the banner shows. */
  readonly shown: boolean;
}

const CSS = `
.rc-win { position: absolute; left: 50%; top: 50%; transform: translate(-50%, -50%); z-index: 6; box-sizing: border-box;
  width: max-content; max-width: calc(100% - 24px); padding: 14px 22px 16px; border-radius: 14px; text-align: center;
  background: rgba(11, 15, 24, 0.92); border: 3px solid #ffd166; color: #e8ecf4; font: 500 15px/1.35 system-ui, sans-serif;
  pointer-events: none; box-shadow: 0 8px 28px rgba(0, 0, 0, 0.55); }
.rc-win[hidden] { display: none; }
.rc-win.rc-lost { border-color: #ff8a7a; }
.rc-win-title { font-weight: 700; font-size: 20px; color: #fff; }
.rc-win-big { font-weight: 800; font-size: clamp(26px, 8vw, 40px); color: #ffd166; text-shadow: 0 2px 0 #3a1a02; margin: 2px 0 4px; }
.rc-win-detail { color: #c8d0dc; margin-bottom: 12px; }
.rc-win-actions { display: flex; gap: 10px; justify-content: center; }
.rc-win button { pointer-events: auto; min-width: 110px; min-height: 44px; padding: 8px 16px; border-radius: 10px; cursor: pointer;
  font: 700 16px system-ui, sans-serif; border: 2px solid #8fa3c4; background: #1d2738; color: #fff; white-space: nowrap; }
.rc-win button.rc-win-next { background: #ffd166; border-color: #ffd166; color: #1a1206; }
.rc-win button kbd { font: 600 12px system-ui, sans-serif; opacity: 0.75; margin-left: 6px; }
`;

/**
 * Makes the banner, hidden, in `parent` (the stage: positioned) and listens for Enter while it shows.
 * @param onNext runs on the Next button or Enter.
 * @param onRetry runs on the Retry button.
 * @param touch whether the page runs on a touch screen (the buttons then name no keys).
 */
export function createWinBanner(parent: HTMLElement, onNext: () => void, onRetry: () => void, touch: boolean): WinBanner {
  const doc = parent.ownerDocument;
  if (!doc.getElementById('rc-win-style')) {
    const style = doc.createElement('style');
    style.id = 'rc-win-style';
    style.textContent = CSS;
    doc.head.append(style);
  }
  const element = doc.createElement('div');
  element.className = 'rc-win';
  element.dataset.hud = 'win-banner';
  element.setAttribute('role', 'dialog');
  element.setAttribute('aria-live', 'polite');
  element.hidden = true;
  const part = (cls: string): HTMLElement => {
    const el = doc.createElement('div');
    el.className = cls;
    element.append(el);
    return el;
  };
  const title = part('rc-win-title'),
    big = part('rc-win-big'),
    detail = part('rc-win-detail'),
    actions = part('rc-win-actions');
  const button = (cls: string, run: () => void): HTMLButtonElement => {
    const b = doc.createElement('button');
    b.type = 'button';
    b.className = cls;
    // A press on a button is not a press on the scene behind it (no camera drag, no push).
    b.addEventListener('pointerdown', (e) => e.stopPropagation());
    b.addEventListener('click', () => run());
    actions.append(b);
    return b;
  };
  const retryButton = button('rc-win-retry', onRetry),
    nextButton = button('rc-win-next', onNext);
  parent.append(element);
  let key = '';
  doc.defaultView?.addEventListener(
    'keydown',
    (e) => {
      if (element.hidden || e.key !== 'Enter' || e.ctrlKey || e.metaKey || e.altKey) return;
      // Enter on a focused button would click it as well: one action a press.
      e.preventDefault();
      e.stopPropagation();
      onNext();
    },
    { capture: true },
  );
  const label = (b: HTMLButtonElement, words: string, keyName: string): void => {
    b.textContent = words;
    if (touch) return;
    const k = doc.createElement('kbd');
    k.textContent = keyName;
    b.append(k);
  };
  return {
    element,
    get shown() {
      return !element.hidden;
    },
    show(content) {
      element.hidden = false;
      const k = JSON.stringify(content);
      if (k === key) return;
      key = k;
      element.classList.toggle('rc-lost', !content.won);
      title.textContent = content.title;
      big.textContent = content.big;
      detail.textContent = content.detail;
      detail.style.display = content.detail ? '' : 'none';
      label(nextButton, content.next, 'Enter');
      label(retryButton, content.retry, 'R');
    },
    hide() {
      element.hidden = true;
      key = '';
    },
  };
}
