/** One keyboard shortcut. */
export interface KeyBinding {
  /**
   * The key, compared case-insensitively with `KeyboardEvent.key` ('p', 'n', 'r', ' ', 'ArrowLeft').
   * A non-empty string.
   */
  key: string;
  /** What it does, for the on-screen legend ("pause / resume"). */
  label: string;
  /** Runs when the key is pressed. */
  action: () => void;
  /** Whether holding the key repeats the action (auto-repeat events). Default false. */
  repeat?: boolean;
}

/** True when the event comes from a text field, where keys must type instead of trigger shortcuts. */
function isTyping(target: EventTarget | null): boolean {
  if (!target || typeof (target as HTMLElement).tagName !== 'string') return false;
  const el = target as HTMLElement;
  const tag = el.tagName;
  if (tag === 'TEXTAREA' || tag === 'SELECT') return true;
  if (tag === 'INPUT') {
    const type = (el as HTMLInputElement).type;
    return type !== 'checkbox' && type !== 'radio' && type !== 'button' && type !== 'range';
  }
  return el.isContentEditable === true;
}

/**
 * Listens for `bindings` on `target` (keydown). Ignores keys typed into text fields and keys pressed
 * with Ctrl, Meta or Alt (browser shortcuts stay intact); calls preventDefault on handled keys.
 * @returns a function that removes the listener.
 * @throws TypeError if a binding has an empty key, a non-function action, or two bindings share a key.
 */
export function bindKeys(bindings: readonly KeyBinding[], target: EventTarget = window): () => void {
  const map = new Map<string, KeyBinding>();
  for (const b of bindings) {
    if (typeof b.key !== 'string' || b.key.length === 0)
      throw new TypeError(`bindKeys: key must be a non-empty string, got ${JSON.stringify(b.key)}`);
    if (typeof b.action !== 'function') throw new TypeError(`bindKeys: action of key ${JSON.stringify(b.key)} must be a function`);
    const k = b.key.toLowerCase();
    if (map.has(k)) throw new TypeError(`bindKeys: key ${JSON.stringify(b.key)} is bound twice`);
    map.set(k, b);
  }
  const listener = (event: Event): void => {
    const e = event as KeyboardEvent;
    if (e.ctrlKey || e.metaKey || e.altKey || isTyping(e.target)) return;
    const b = map.get(e.key.toLowerCase());
    if (!b) return;
    e.preventDefault();
    if (e.repeat && !b.repeat) return;
    b.action();
  };
  target.addEventListener('keydown', listener);
  return () => target.removeEventListener('keydown', listener);
}
