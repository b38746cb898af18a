/**
 * The pause overlay of a page whose scene is not drawn by pixi (three.js games): an HTML element over
 * the scene that dims it and says "Paused" and how to resume in the middle, so a paused game is not
 * mistaken for a hung one. The words match the pixi overlay's (./pause-overlay.ts). DOM only.
 */

/** Options of `createDomPauseOverlay`. Every field is optional. */
export interface DomPauseOverlayOptions {
  /** Opacity of the black shade over the scene, in [0, 1]. Default 0.45. */
  shadeAlpha?: number;
  /**
   * Called when the overlay is tapped or clicked (it then takes pointer events, and the words say
   * 'Tap to resume' on a touch screen); without it the overlay lets every pointer event through.
   */
  onResume?: () => void;
}

/** A pause overlay made by `createDomPauseOverlay`. */
export interface DomPauseOverlay {
  /**
   * The overlay's element (data-hud="paused", and data-scene-overlay: it covers the scene on purpose,
   * only while paused, so a check for page furniture over the scene passes it by), a child of the
   * parent given.
   */
  readonly element: HTMLDivElement;
  /** Whether the overlay shows (as last updated). */
  readonly visible: boolean;
  /** The words as last shown, lines joined by '\n' ('' before the first update while paused). */
  readonly text: string;
  /**
   * Shows the overlay when `paused`, else hides it. The second line says how to resume: 'P to
   * resume' with keys; on a touch screen (`touch`) 'Tap to resume' with `onResume`, else '▶ to
   * resume' (the toolbar's button). Cheap when nothing changed.
   */
  update(paused: boolean, touch: boolean): void;
}

/**
 * Makes a pause overlay, hidden, covering `parent` (which must be positioned: the page layout's stage
 * is). Call `update` every frame.
 * @param parent - The element the overlay covers (the scene's stage).
 * @param options - See DomPauseOverlayOptions.
 * @returns the overlay.
 * @throws TypeError if `parent` is not an HTMLElement; RangeError if `shadeAlpha` is not in [0, 1].
 */
export function createDomPauseOverlay(parent: HTMLElement, options: DomPauseOverlayOptions = {}): DomPauseOverlay {
  if (!(parent instanceof HTMLElement)) throw new TypeError(`createDomPauseOverlay: parent must be an HTMLElement, got ${String(parent)}`);
  const alpha = options.shadeAlpha ?? 0.45;
  if (!(alpha >= 0 && alpha <= 1)) throw new RangeError(`createDomPauseOverlay: shadeAlpha must be in [0, 1], got ${alpha}`);
  const element = document.createElement('div');
  element.dataset.hud = 'paused';
  element.dataset.sceneOverlay = '';
  element.setAttribute('role', 'status');
  // Above the scene's other overlays (labels, tips: z-index 6), under the page's menus.
  element.style.cssText = `position: absolute; inset: 0; z-index: 20; display: none; flex-direction: column; align-items: center; justify-content: center; gap: 6px; background: rgba(0, 0, 0, ${alpha}); color: #fff; font: 800 40px/1.15 system-ui, sans-serif; text-align: center; text-shadow: 0 0 6px #000, 0 2px 3px #000; user-select: none; pointer-events: ${options.onResume ? 'auto' : 'none'}; cursor: ${options.onResume ? 'pointer' : 'default'};`;
  const title = document.createElement('div');
  title.textContent = 'Paused';
  const how = document.createElement('div');
  how.style.cssText = 'font-size: 24px; font-weight: 700;';
  element.append(title, how);
  parent.append(element);
  if (options.onResume) {
    const resume = options.onResume;
    element.addEventListener('pointerdown', (e) => {
      e.preventDefault();
      e.stopPropagation();
      resume();
    });
  }
  let visible = false,
    text = '';
  return {
    element,
    get visible() {
      return visible;
    },
    get text() {
      return text;
    },
    update(paused, touch) {
      if (paused !== visible) {
        visible = paused;
        element.style.display = paused ? 'flex' : 'none';
      }
      if (!paused) return;
      const line = touch ? (options.onResume ? 'Tap to resume' : '▶ to resume') : 'P to resume';
      if (how.textContent !== line) {
        how.textContent = line;
        text = `Paused\n${line}`;
      }
      const small = parent.clientWidth < 500;
      const size = small ? '32px' : '40px';
      if (element.style.fontSize !== size) element.style.fontSize = size;
    },
  };
}
