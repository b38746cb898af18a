import GUI, { type Controller } from 'lil-gui';
import { pageLayout } from './layout.js';

/** Keys of `P` whose values are numbers. */
type NumberKey<P> = { [K in keyof P]: P[K] extends number ? K : never }[keyof P] & string;

/** What every control may say besides its kind and parameter. */
export interface ControlPlace {
  /**
   * The folder the control goes in: controls naming the same folder share one, closed at start and
   * placed where its first control is listed (knobs a player need not see, such as physics
   * constants). Default none: the panel itself.
   */
  folder?: string;
}

/** A slider for a number parameter. */
export interface SliderControl<P> extends ControlPlace {
  /** Kind of control. */
  type: 'slider';
  /** The parameter (a number field of the params object). */
  key: NumberKey<P>;
  /** Label shown; default the key. */
  label?: string;
  /** Smallest value, finite; < max. */
  min: number;
  /** Largest value, finite; > min. */
  max: number;
  /** Increment, > 0; default lil-gui's choice. */
  step?: number;
  /** Called after the value changed, with the new value and the params object. */
  onChange?: (value: number, params: P) => void;
  /** Call onChange only when the user lets go of the slider (for expensive rebuilds). Default false. */
  onRelease?: boolean;
}

/** A dropdown choosing one of `options` for a parameter. */
export interface ChoiceControl<P> extends ControlPlace {
  /** Kind of control. */
  type: 'choice';
  /** The parameter. */
  key: keyof P & string;
  /** Label shown; default the key. */
  label?: string;
  /** The choices: an array of values, or an object mapping labels to values. */
  options: readonly unknown[] | Readonly<Record<string, unknown>>;
  /** Called after the value changed. */
  onChange?: (value: unknown, params: P) => void;
}

/** A checkbox (boolean parameter), a button (function parameter) or a text field (string parameter). */
export interface PlainControl<P> extends ControlPlace {
  /** Kind of control: 'checkbox' (boolean field), 'button' (function field), 'text' (string field). */
  type: 'checkbox' | 'button' | 'text';
  /** The parameter. */
  key: keyof P & string;
  /** Label shown; default the key. */
  label?: string;
  /** Called after the value changed (checkbox, text). */
  onChange?: (value: unknown, params: P) => void;
}

/** One control of a panel. */
export type PanelControl<P> = SliderControl<P> | ChoiceControl<P> | PlainControl<P>;

/** Options of `createPanel`. */
export interface PanelOptions {
  /** Panel title. Default 'Parameters'. */
  title?: string;
  /** Width, px, > 0. Default lil-gui's 245. */
  width?: number;
  /** Element to put the panel in. Default: the top of the page layout's side column (./layout). */
  container?: HTMLElement;
  /** Start collapsed. Default false (on small screens the side column is a drawer, closed at start). */
  closed?: boolean;
}

/** A lil-gui parameter panel bound to a params object. */
export interface Panel<P> {
  /** The lil-gui instance (add folders or controls directly if needed). */
  readonly gui: GUI;
  /** The params object the controls edit. */
  readonly params: P;
  /** The controller of `key`. @throws RangeError if the panel has no control for it. */
  controller(key: keyof P & string): Controller;
  /** Re-reads every control from `params` (after code changed them). */
  refresh(): void;
  /** Removes the panel. */
  destroy(): void;
}

/**
 * Builds a lil-gui panel over `params`, one control per entry, in order: sliders, dropdowns,
 * checkboxes, buttons and text fields, chosen by each entry's `type`; an entry with a `folder` goes in
 * that folder (closed at start, where its first entry is).
 * @throws TypeError if `params` is not an object, a key is not a field of params, a type is unknown
 *   or does not match the field (slider: number, checkbox: boolean, button: function, text: string);
 *   RangeError if a slider's min >= max or step <= 0.
 * @example
 * createPanel(params, [{ type: 'slider', key: 'gravity', min: 0, max: 30, onChange: (g) => { world.gravity[1] = -g; } }]);
 */
export function createPanel<P extends object>(params: P, controls: readonly PanelControl<P>[], options: PanelOptions = {}): Panel<P> {
  const where = 'createPanel';
  if (params === null || typeof params !== 'object') throw new TypeError(`${where}: params must be an object`);
  const record = params as Record<string, unknown>;
  const side = options.container ? null : pageLayout().side;
  const gui = new GUI({
    title: options.title ?? 'Parameters',
    ...(options.width !== undefined ? { width: options.width } : {}),
    ...(options.container ? { container: options.container } : {}),
    ...(side ? { autoPlace: false } : {}),
  });
  if (side) side.prepend(gui.domElement);
  const byKey = new Map<string, Controller>();
  const folders = new Map<string, GUI>();
  try {
    for (const control of controls) {
      let into = gui;
      if (control.folder !== undefined) {
        into = folders.get(control.folder) ?? gui.addFolder(control.folder).close();
        folders.set(control.folder, into);
      }
      const key = control.key;
      if (!(key in record)) throw new TypeError(`${where}: key ${JSON.stringify(key)} is not a field of params`);
      let ctl: Controller;
      const expected = { slider: 'number', choice: '', checkbox: 'boolean', button: 'function', text: 'string' }[control.type];
      if (expected === undefined)
        throw new TypeError(`${where}: control ${JSON.stringify(key)} has unknown type ${JSON.stringify(control.type)}`);
      if (expected && typeof record[key] !== expected) {
        throw new TypeError(`${where}: ${control.type} ${JSON.stringify(key)} needs a ${expected} field, got ${typeof record[key]}`);
      }
      if (control.type === 'slider') {
        if (!(Number.isFinite(control.min) && Number.isFinite(control.max) && control.min < control.max)) {
          throw new RangeError(
            `${where}: slider ${JSON.stringify(key)} needs finite min < max, got min ${control.min}, max ${control.max}`,
          );
        }
        if (control.step !== undefined && !(control.step > 0)) {
          throw new RangeError(`${where}: slider ${JSON.stringify(key)} needs step > 0, got ${control.step}`);
        }
        ctl = into.add(params, key as keyof P, control.min, control.max, control.step);
        const cb = control.onChange;
        if (cb) {
          const handler = (v: number) => cb(v, params);
          if (control.onRelease) ctl.onFinishChange(handler);
          else ctl.onChange(handler);
        }
      } else if (control.type === 'choice') {
        ctl = into.add(params, key as keyof P, control.options as object);
        const cb = control.onChange;
        if (cb) ctl.onChange((v: unknown) => cb(v, params));
      } else {
        ctl = into.add(params, key as keyof P);
        const cb = control.onChange;
        if (cb) ctl.onChange((v: unknown) => cb(v, params));
      }
      if (control.label) ctl.name(control.label);
      byKey.set(key, ctl);
    }
  } catch (error) {
    gui.destroy();
    throw error;
  }
  if (options.closed) gui.close();
  return {
    gui,
    params,
    controller(key) {
      const ctl = byKey.get(key);
      if (!ctl) throw new RangeError(`Panel.controller: no control for ${JSON.stringify(key)}`);
      return ctl;
    },
    refresh() {
      for (const ctl of byKey.values()) ctl.updateDisplay();
    },
    destroy() {
      gui.destroy();
    },
  };
}
