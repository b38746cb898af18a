// A minimal stand-in for the DOM, for node tests of game-kit's DOM parts (status row, result card):
// elements with children, classes, attributes, dataset, style, hidden, listeners and focus, and a
// document with a head, an active element and a window for key listeners. `writes` counts
// textContent assignments.

type Listener = (e: FakeEvent) => void;

/** An event as the parts under test read it. */
export interface FakeEvent {
  [field: string]: unknown;
  preventDefault(): void;
  stopPropagation(): void;
}

/** Listeners by type, with dispatch: what elements and the window share. */
class FakeTarget {
  private readonly listeners = new Map<string, Listener[]>();
  addEventListener(type: string, fn: Listener): void {
    this.listeners.set(type, [...(this.listeners.get(type) ?? []), fn]);
  }
  removeEventListener(type: string, fn: Listener): void {
    this.listeners.set(
      type,
      (this.listeners.get(type) ?? []).filter((f) => f !== fn),
    );
  }
  /** Runs the listeners of `type` with an event of `fields`; returns whether one stopped it or prevented its default. */
  fire(type: string, fields: Record<string, unknown> = {}): { stopped: boolean; prevented: boolean } {
    const out = { stopped: false, prevented: false };
    const event: FakeEvent = {
      button: 0,
      pointerId: 1,
      detail: 0,
      ...fields,
      preventDefault: () => {
        out.prevented = true;
      },
      stopPropagation: () => {
        out.stopped = true;
      },
    };
    for (const fn of this.listeners.get(type) ?? []) fn(event);
    return out;
  }
  listenerCount(type: string): number {
    return this.listeners.get(type)?.length ?? 0;
  }
}

export class FakeElement extends FakeTarget {
  children: FakeElement[] = [];
  parent: FakeElement | null = null;
  readonly dataset: Record<string, string> = {};
  readonly attributes = new Map<string, string>();
  readonly classes = new Set<string>();
  readonly styleProps = new Map<string, string>();
  readonly style: Record<string, unknown> = { setProperty: (k: string, v: string) => this.styleProps.set(k, v) };
  readonly nodeType = 1;
  id = '';
  type = '';
  hidden = false;
  private text = '';
  constructor(
    readonly tagName: string,
    readonly ownerDocument: FakeDocument,
  ) {
    super();
  }
  set className(v: string) {
    this.classes.clear();
    for (const c of v.split(' ').filter(Boolean)) this.classes.add(c);
  }
  get className(): string {
    return [...this.classes].join(' ');
  }
  readonly classList = {
    toggle: (c: string, on: boolean) => (on ? this.classes.add(c) : this.classes.delete(c)),
    contains: (c: string) => this.classes.has(c),
  };
  set textContent(v: string) {
    this.ownerDocument.writes++;
    this.text = v;
    this.children = [];
  }
  get textContent(): string {
    return this.text + this.children.map((c) => c.textContent).join('');
  }
  append(...nodes: FakeElement[]): void {
    for (const n of nodes) {
      n.parent?.children.splice(n.parent.children.indexOf(n), 1);
      n.parent = this;
    }
    this.children.push(...nodes);
  }
  replaceChildren(...nodes: FakeElement[]): void {
    for (const c of this.children) c.parent = null;
    this.children = [];
    this.append(...nodes);
  }
  remove(): void {
    this.parent?.children.splice(this.parent.children.indexOf(this), 1);
    this.parent = null;
  }
  contains(other: FakeElement | null): boolean {
    for (let e = other; e; e = e.parent) if (e === this) return true;
    return false;
  }
  setAttribute(name: string, value: string): void {
    this.attributes.set(name, value);
  }
  getAttribute(name: string): string | null {
    return this.attributes.get(name) ?? null;
  }
  focus(): void {
    this.ownerDocument.activeElement = this;
  }
  blur(): void {
    if (this.ownerDocument.activeElement === this) this.ownerDocument.activeElement = this.ownerDocument.body;
  }
  /** Every element under this one, depth first, that `test` accepts. */
  findAll(test: (e: FakeElement) => boolean): FakeElement[] {
    return this.children.flatMap((c) => [...(test(c) ? [c] : []), ...c.findAll(test)]);
  }
}

export class FakeDocument {
  writes = 0;
  readonly head = new FakeElement('head', this);
  readonly body = new FakeElement('body', this);
  activeElement: FakeElement = this.body;
  readonly defaultView = new FakeTarget();
  createElement(tag: string): FakeElement {
    return new FakeElement(tag, this);
  }
  getElementById(id: string): FakeElement | null {
    return this.head.children.find((c) => c.id === id) ?? null;
  }
}
