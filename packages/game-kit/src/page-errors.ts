/**
 * Every page of the site starts with this module (scripts/build.mjs injects it before each page's
 * own code): the locale guard (./locale-guard) first, then handlers that turn anything thrown and
 * not caught, at import time (a module that fails to evaluate, a rejected top-level await) or later
 * (an event handler), into a red box with the message, instead of a blank canvas.
 * The game loop catches its own errors and shows them in the HUD (./hud `showError`).
 */
import './locale-guard.js';

/** Messages the browser raises that are no failure of the page. */
const BENIGN = [/ResizeObserver loop/];

/** The text of an error, event reason or anything thrown. */
function messageOf(reason: unknown): string {
  if (reason instanceof Error) return `${reason.name}: ${reason.message}`;
  return String(reason);
}

/**
 * Shows `message` in the page's error box (role "alert", `data-page-error`), created on first use;
 * a message already shown in an alert on the page (a lab's URL-parameter box) is not repeated.
 * Does nothing outside a browser.
 */
export function showUncaughtError(message: string): void {
  if (typeof document === 'undefined' || BENIGN.some((re) => re.test(message))) return;
  const bare = message.replace(/^\w*Error: /, '');
  for (const el of Array.from(document.querySelectorAll('[role="alert"]'))) {
    if (el.textContent?.includes(bare)) return;
  }
  const show = (): void => {
    let box = document.querySelector<HTMLElement>('[data-page-error]');
    if (!box) {
      box = document.createElement('div');
      box.dataset.pageError = '';
      box.setAttribute('role', 'alert');
      box.style.cssText =
        'position:fixed;top:40%;left:50%;transform:translate(-50%,-50%);z-index:1000;max-width:min(80vw,640px);' +
        'box-sizing:border-box;padding:12px 16px;border-radius:8px;background:rgba(160,20,40,0.95);color:#fff;' +
        'font:14px/1.5 system-ui,sans-serif;white-space:pre-wrap;overflow-wrap:anywhere';
      const title = document.createElement('strong');
      title.textContent = 'This page stopped with an error:';
      box.append(title, document.createElement('br'));
      document.body.append(box);
    }
    box.append(document.createTextNode(`${message}\n`));
  };
  if (document.body) show();
  else document.addEventListener('DOMContentLoaded', show, { once: true });
}

if (typeof window !== 'undefined') {
  window.addEventListener('error', (event) => showUncaughtError(messageOf(event.error ?? event.message)));
  window.addEventListener('unhandledrejection', (event) => showUncaughtError(messageOf(event.reason)));
}
