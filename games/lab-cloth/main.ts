/**
 * Lab: cloth (Ramtal and Dobre ch. 13). A sheet on a washing line in a breeze: a grid of point masses
 * joined by compliant structural, soft shear and bending links (createCloth; the XPBD cloth solver in
 * small steps), pegged at a few points along its top (scene.ts), in the world's wind (drag on each
 * point against a breeze that rises and falls, with turbulence). It sways and leans in the gusts,
 * stretches where it is pulled and tears where a link is stretched past the tear strain; torn-off
 * pieces flutter down to the lawn.
 *
 * The challenge: four sheets, each asking for something else (levels.ts): cut out three shapes along
 * their dashed lines, cut out the four panes of a window, cut the ribbon of a peg bag to drop it into
 * a basket (a gust swings it over), and, without scissors, tear a strip off along a perforation. Each
 * target is scored by pattern.ts (a fit to its line, or where the bag lands) in stars.
 *
 * Input: drag with the scissors to cut every link the stroke crosses (cut.ts: in the cloth's frame, and
 * a stroke that ends near its start closes); on the shapes' and the window's sheets the breeze drops
 * while the scissors are down, so the sheet hangs still. Paused (P), the scissors cut the still
 * sheet, and the pieces cut away fall when it runs again. A finger's stroke is scored with FINGER_SLACK_PX of slack along
 * the lines and closes from FINGER_CLOSE_PX off (a fingertip hides the line it traces). Drag with the hand to
 * take hold of the sheet and pull it (grab.ts: a soft grip, so it stretches before it tears). The tool
 * buttons under the scene switch (key C); a right-button drag always cuts. Hold Gust (key G) to blow.
 * Undo (Ctrl/Cmd+Z) puts the sheet back as it was just before the last action that cut or tore it (a
 * scissors stroke or a pull of the hand; undo.ts: the whole world restored from a snapshot taken when
 * the action began; up to UNDO_DEPTH actions). When the shapes left cannot bring the stars up to the
 * pass mark (a pull tore through them), the status line says so and offers a retry.
 * Keys: P pause, N step, R new sheet. URL: ?level (1-4), ?size (8-48 points across), ?wind (0-10 m/s),
 * ?gusts (0-5 m/s), ?tear (0.1-2).
 */

import { createActionButton, createButtonBar, createPanel, getSound, numberParam, pointerOnCanvas } from '@bitphysics/game-kit';
import { createLabDock, createReadout, createStatusLine, fmt, followView, readUrlParams } from '@bitphysics/game-kit/lab-kit';
import { startPixiGame } from '@bitphysics/game-kit/pixi';
import { createPlot } from '@bitphysics/game-kit/plot';
import { type Cloth, type PhysicsWorld, step as physicsStep, query, removeJoint, slotOf, windAt } from '@bitphysics/physics';
import type { WorldRect } from '@bitphysics/render-pixi';
import { Container, Graphics, Text } from 'pixi.js';
import { ClothCells } from './cells';
import { ScissorsStroke } from './cut';
import { fabricTexture } from './fabric';
import { ClothGrab, gripFor } from './grab';
import { LEVELS } from './levels';
import { Challenge, type CutOut } from './pattern';
import { browserStore, loadProgress, passMark, recordBest, saveProgress } from './progress';
import { applyWind, CLOTH_SUBSTEPS, createClothScene, DEFAULTS, LINE_Y, SHEET_WIDTH, SHEET_X, sheetGrid, YARD } from './scene';
import { SheetView } from './sheet-view';
import { CutUndo } from './undo';
import { POSTS, Yard } from './yard';

const USAGE = 'Accepted: size 8-48 points across; wind 0-10 m/s; gusts 0-5 m/s; tear 0.1-2 (strain).';
const url = readUrlParams(
  () => ({
    size: numberParam('size', { default: DEFAULTS.size, min: 8, max: 48, integer: true }),
    wind: numberParam('wind', { default: DEFAULTS.wind, min: 0, max: 10 }),
    gusts: numberParam('gusts', { default: DEFAULTS.gusts, min: 0, max: 5 }),
    tear: numberParam('tear', { default: DEFAULTS.tear, min: 0.1, max: 2 }),
  }),
  USAGE,
);
const params = { ...url, substeps: CLOTH_SUBSTEPS, reset: () => shell.reset() };
/** The browser's storage for the best stars per sheet (progress.ts), null where there is none. */
const store = browserStore();
/** The best stars won on each sheet, kept over a reload (-1: not finished). */
const levelStars = loadProgress(store, LEVELS.length);
/** Whether sheet `i` (0-based) was passed: its best stars reach its pass mark (progress.ts passMark). */
const passed = (i: number): boolean => levelStars[i]! >= passMark(LEVELS[i]!.shapes(DEFAULTS.size).length);
// A failure kept by an older page (below the pass mark) is no best: the sheet counts as not finished.
levelStars.forEach((_, i) => {
  if (!passed(i)) levelStars[i] = -1;
});
/**
 * Which of LEVELS is up (0-based): ?level (1 to 4); without it the first sheet not passed yet (kept
 * over a reload), the first when every one is.
 */
let levelIndex = new URLSearchParams(location.search).has('level')
  ? numberParam('level', { default: 1, min: 1, max: LEVELS.length, integer: true }) - 1
  : Math.max(
      0,
      LEVELS.findIndex((_, i) => !passed(i)),
    );
// A level's own breeze, unless the URL sets one (the first level's is the URL's defaults).
{
  const search = new URLSearchParams(location.search);
  if (!search.has('wind')) params.wind = LEVELS[levelIndex]!.wind;
  if (!search.has('gusts')) params.gusts = LEVELS[levelIndex]!.gusts;
}

/** How much the Gust button adds to the wind, m/s, and how fast it comes and goes (1/s). */
const GUST = 5,
  GUST_RATE = 2.5;
/**
 * How fast the breeze drops while the scissors are down on a sheet for careful cuts (Level.calm: the
 * shapes, the window), and picks up again after (1/s): the air stills while you cut, and the sheet's
 * drag (time constant CLOTH_MASS / DRAG, 0.25 s) stops its swing; the other sheets' breezes keep blowing.
 */
const CALM_RATE = 4;
/**
 * After a stroke that cut something on such a sheet, the air stays still this long, s (world time),
 * and the sheet's sway is damped (CALM_DAMPING): the piece cut away changes how the sheet hangs, and
 * as the breeze came back at once the sheet swung the next shape away from the scissors.
 */
const CALM_HOLD = 8;
/**
 * Extra air damping of the sheet's points while the air is still for the scissors, 1/s (times `calm`):
 * the swing a cut sets off dies in about half a second instead of swaying on.
 */
const CALM_DAMPING = 3;
/**
 * Whether the world holds still for the scissors: a stroke is under way on a sheet for careful cuts
 * (Level.calm; not while the Gust button blows). The sheet hangs as if paused until the scissors lift,
 * then runs on (the pieces cut away fall) in still air (CALM_HOLD): with the breeze only dropping
 * (CALM_RATE, CALM_DAMPING) the window's corner still moved 10 to 15 px on a desktop in the second
 * after the scissors went down, as the sheet's lean in the breeze relaxed.
 */
function heldForScissors(): boolean {
  return cutting && !blowing && blow === 0 && LEVELS[levelIndex]!.calm;
}
/**
 * A finger's stroke (pointer type 'touch') is given this much slack, CSS px: its cut may stray this
 * much further from a line at no cost to the fit (Challenge.setSlack), and it closes within
 * FINGER_CLOSE_PX of its start. Measured on a 390 x 844 phone (a link spacing is 10 px there) with a
 * finger's circle cut as far out of its line all round: 3 stars up to 10 px, 2 at 15, 1 at 20 and
 * none at 25 (at 12 px of slack, 3 stars out to 15 px: too easy); with the mouse on a 1280 x 800
 * screen, 3 stars up to 8 px, 2 at 10-15.
 */
const FINGER_SLACK_PX = 5,
  FINGER_CLOSE_PX = 36;
/** A stroke that ends within CLOSE_GAP cells of where it began, after CLOSE_LENGTH m, closes (ScissorsStroke.close). */
const CLOSE_GAP = 2.5,
  CLOSE_LENGTH = 1;
/** The scissors follow the cloth within this many m of where a stroke begins (ScissorsStroke's frame): about twice a shape's size. */
const STROKE_FRAME = 0.9;

/** What the camera shows: the yard with a strip of each wall, the lawn (the shapes' card lies on it) and the sky over the line. */
const view: WorldRect = { minX: YARD.minX - 0.25, minY: -0.65, maxX: YARD.maxX + 0.25, maxY: LINE_Y + 0.55 };
/**
 * On a screen taller than wide (a phone held upright) the width sets the scale: the camera shows the
 * sheet and its posts, the left wall left out, and the yard out to its right wall, as far as a gust
 * (or a windy day's breeze) blows the sheet. It holds still: the framing changes only with a new
 * sheet or a new screen size (a view that followed the blowing sheet panned and zoomed under the
 * scissors).
 */
const narrowView: WorldRect = { ...view, minX: POSTS[0] - 0.06, maxX: YARD.maxX + 0.03 };
/**
 * CSS px kept free round the upright view: none, the view's own margins (the left post, 0.03 m past
 * the yard's right wall) are enough, and the width sets the scale: at 390 px across the sheet is
 * drawn 70 px a metre (with the default 24 px and wider margins, 63 px a metre: the star and heart
 * about 55 px tall, too small for a finger to trace, said a stranger on a phone).
 */
const NARROW_PADDING = 0;

/** Floating words over the scene: a shape cut out, with its fit and stars. */
interface Label {
  /** The words and the stars under them. */
  text: Container;
  /** Where it shows, m: x over the piece; y where a dropped piece landed, or NaN for the sky over the line (Label's `sky`). */
  x: number;
  y: number;
  /** When it appeared, s (performance.now() / 1000). */
  born: number;
}
/**
 * How far above the washing line a cut-out's label sits, CSS px (its bottom edge, over the pegs): a
 * label over the piece it named, rising, covered the panes still to cut on a phone.
 */
const LABEL_OVER_LINE = 14;
/** The highest a label's bottom edge goes on the canvas, CSS px from its top (the words and stars are some 52 px tall). */
const LABEL_TOP = 56;
const labels: Label[] = [];
const LABEL_LIFE = 2.6;

let cloth: Cloth;
let cells: ClothCells;
let challenge: Challenge;
/** The lab's counts saved with each stroke for undo: links cut and torn, and pieces off (Challenge.scraps) before it. */
interface Counts {
  cut: number;
  torn: number;
  scraps: number;
}
/** Undo of the scissors (undo.ts): a new one with each sheet. */
let history: CutUndo<Counts>;
/**
 * A pull of the hand stays one open action from its pointerdown until the next action begins or an
 * undo (the sheet it loosened may tear on after the hand lets go, and undo takes that back with it);
 * `tornAtPull` is the count of torn links as it began.
 */
let pullOpen = false,
  tornAtPull = 0;
/** Ends the pull left open (pullOpen), keeping it for undo if it tore the sheet. */
function closePull(): void {
  if (!pullOpen) return;
  pullOpen = false;
  history.end();
  refreshUndo();
}
/** How many strokes can be undone, at most. */
const UNDO_DEPTH = 10;
let sheet: SheetView | null = null;
let grab: ClothGrab | null = null;
/** Links torn by strain, and cut by the scissors, since the reset. */
let torn = 0,
  cut = 0;
let stepMs = 0;
/** The gust the player blows, 0 to 1 (eased toward `blowing`). */
let blow = 0,
  blowing = false;
/** How far the breeze has dropped for the scissors, 0 (blowing) to 1 (still air; see CALM_RATE). */
let calm = 0,
  /** Whether the scissors are down (a stroke is under way). */
  cutting = false,
  /** World time, s, until which the air stays still after a stroke that cut (CALM_HOLD). */
  calmUntil = -1;

function createWorld(): PhysicsWorld {
  const level = LEVELS[levelIndex]!;
  const scene = createClothScene(params, level.prepare);
  cloth = scene.cloth;
  cells = new ClothCells(cloth);
  challenge = new Challenge(scene.world, cloth, cells, level.shapes(params.size));
  history = new CutUndo(scene.world, cells, challenge, UNDO_DEPTH);
  pullOpen = false;
  grab = null;
  torn = 0;
  cut = 0;
  blow = 0;
  calm = 0;
  calmUntil = -1;
  plot?.clear();
  for (const l of labels.splice(0)) l.text.destroy({ children: true });
  return scene.world;
}

let plot: ReturnType<typeof createPlot> | null = null;
const wind = new Float64Array(3);
const sound = getSound();

/** Sets the world's wind: the breeze (dropped by `calm`) and the player's gust. */
function blowNow(world: PhysicsWorld): void {
  applyWind(world, { wind: params.wind * (1 - calm), gusts: params.gusts * (1 - calm) }, GUST * blow);
}

/** Sets the sheet's points' previous positions to their positions, so the drawing (which interpolates between the two) holds still while no step runs. */
function holdSheetStill(world: PhysicsWorld): void {
  const P = world.components.Position,
    O = world.components.PreviousPosition;
  for (const e of cloth.points) {
    const s = slotOf(e);
    O.x[s] = P.x[s]!;
    O.y[s] = P.y[s]!;
  }
}

/** Scales the velocity of every point of the sheet by `keep`, in [0, 1] (air damping while the air is still). */
function dampSheet(world: PhysicsWorld, keep: number): void {
  const V = world.components.Velocity;
  for (const e of cloth.points) {
    const s = slotOf(e);
    V.x[s] = V.x[s]! * keep;
    V.y[s] = V.y[s]! * keep;
  }
}

function labStep(world: PhysicsWorld): void {
  const target = blowing ? 1 : 0;
  const calmTarget = (cutting || world.time < calmUntil) && LEVELS[levelIndex]!.calm ? 1 : 0;
  if (blow !== target || calm !== calmTarget) {
    blow = target > blow ? Math.min(1, blow + GUST_RATE * world.dt) : Math.max(0, blow - GUST_RATE * world.dt);
    calm = calmTarget > calm ? Math.min(1, calm + CALM_RATE * world.dt) : Math.max(0, calm - CALM_RATE * world.dt);
    blowNow(world);
  }
  // On a sheet for careful cuts the sheet holds still while the scissors are down: no step at all.
  if (heldForScissors()) return;
  // Still air for the scissors: the sheet's swing is damped too (not a gust the player blows).
  if (calm > 0 && blow === 0) dampSheet(world, Math.exp(-CALM_DAMPING * calm * world.dt));
  // The hand's pull follows how far it leads the patch it holds, and hardens while held far (grab.ts).
  grab?.update(world.dt);
  const t0 = performance.now();
  physicsStep(world);
  stepMs = performance.now() - t0;
  const broke = world.joints.breaks.count;
  if (broke > 0) {
    torn += broke;
    // A pull left open (pullOpen) that tears the sheet can now be undone.
    if (pullOpen) refreshUndo();
    ripped += broke;
  }
  cells.loosen(world);
  announce(challenge.update());
  announce(challenge.watch());
  windAt(world, 2, 3, 0, world.time, wind);
  plot?.push(world.time, (sheet?.shownStretch ?? 0) * 100, wind[0]!);
}

const game = await startPixiGame({
  title: 'Cloth',
  createWorld,
  step: labStep,
  controls: [
    { keys: 'Drag', action: 'cut with the scissors, or pull with the hand (a long pull tears)' },
    { keys: 'C', action: 'scissors / hand', touch: 'Scissors / Hand', card: false },
    { keys: 'G (hold)', action: 'a gust of wind', touch: 'Gust (hold)' },
    { keys: 'Right drag', action: 'cut, with either tool', touch: '' },
    { keys: 'Ctrl+Z', action: 'undo the last cut', touch: 'Undo' },
    { keys: 'Paused', touch: 'Paused', action: 'the sheet holds still; the scissors still cut' },
  ],
  renderer: { view },
  onFrame: (alpha, world) => draw(alpha, world),
});
const { shell, renderer, app } = game;
// On a phone game-kit's touch hint card sits over the bottom of the stage, on the lawn where the card
// of shapes and stars is; here it goes over the sky at the top instead (it fades at the first touch).
const touchHint = document.querySelector<HTMLElement>('[data-hud="touch-hint"]');
if (touchHint) Object.assign(touchHint.style, { top: '12px', bottom: 'auto' });
const dock = createLabDock();
/** Whether the screen is taller than wide (the upright view). */
const upright = (): boolean => app.screen.width < app.screen.height;
const refitView = followView(
  app,
  renderer.camera,
  dock,
  () => (upright() ? narrowView : view),
  () => (upright() ? NARROW_PADDING : 24),
);

const panel = createPanel(
  params,
  [
    { type: 'slider', key: 'size', label: 'points across', min: 8, max: 48, step: 1, onRelease: true, onChange: () => shell.reset() },
    {
      type: 'slider',
      key: 'wind',
      label: 'breeze (m/s)',
      min: 0,
      max: 10,
      step: 0.1,
      onChange: () => {
        blowNow(shell.world);
        refitView();
      },
    },
    {
      type: 'slider',
      key: 'gusts',
      label: 'gusts (m/s)',
      min: 0,
      max: 5,
      step: 0.1,
      onChange: () => blowNow(shell.world),
    },
    { type: 'slider', key: 'tear', label: 'tears at strain', min: 0.1, max: 2, step: 0.01, onRelease: true, onChange: () => shell.reset() },
    {
      type: 'slider',
      key: 'substeps',
      label: 'solver substeps',
      min: 1,
      max: 30,
      step: 1,
      onChange: (v) => {
        shell.world.cloth.substeps = v as number;
      },
    },
    { type: 'button', key: 'reset', label: 'new sheet (R)' },
  ],
  { title: 'Cloth', container: dock.panelSlot },
);
const readout = createReadout(shell.hud.readout, [
  'links',
  'torn',
  'cut',
  'pieces off',
  'largest stretch',
  'wind at the sheet',
  'step time',
]);
plot = createPlot({
  parent: dock.charts,
  title: 'Stretch and wind',
  yLabel: '% / m/s',
  width: dock.chartWidth,
  height: 200,
  capacity: 1200,
  series: [
    { label: 'largest stretch (%)', color: '#e76f51' },
    { label: 'wind at the sheet (m/s)', color: '#4cc9f0' },
  ],
});

// The challenge's line above the scene, and a button for a new sheet once it is done: over the sky
// at the top of the scene, clear of the card of stars on the lawn (at the bottom, on a desktop, it
// covered the stars just won).
const status = createStatusLine();
// The status line keeps one height whatever it says (a message that wrapped to one more line moved the
// scene down and rescaled it mid-cut): one line on a wide screen, two on a narrow one, the rest cut
// with an ellipsis (the narrow screen's wording, `short`, fits in two). Its bottom padding is a
// border, outside the box that clips the text, so no sliver of a third line shows there.
{
  const style = document.createElement('style');
  style.textContent = `
.lab-status { box-sizing: border-box; height: calc(2.8em + 8px); padding-bottom: 0 !important; border-bottom: 2px solid transparent;
  display: -webkit-box; -webkit-box-orient: vertical; -webkit-line-clamp: 2; overflow: hidden; }
@media (min-width: 900px) { .lab-status { height: calc(1.4em + 8px); -webkit-line-clamp: 1; } }`;
  document.head.append(style);
}
/** Whether the screen is narrow (a phone held upright): the status line's shorter wording. */
const narrowText = window.matchMedia('(max-width: 480px)');
/** `long` on a wide screen, `brief` on a narrow one (narrowText). */
const short = (long: string, brief: string): string => (narrowText.matches ? brief : long);
/** Whether the page is used by touch (no keyboard to press P on). */
const touchInput = window.matchMedia('(pointer: coarse)');
/** Whether the sheet up was finished short of its pass mark: the action button hangs it again. */
let failed = false;
const showNext = createActionButton('Next sheet ▶', () => (failed ? shell.reset() : nextSheet()), { at: 'top' });

/** Hangs the next sheet (after the last, the first again) in its breeze. */
function nextSheet(): void {
  levelIndex = (levelIndex + 1) % LEVELS.length;
  params.wind = LEVELS[levelIndex]!.wind;
  params.gusts = LEVELS[levelIndex]!.gusts;
  panel.refresh();
  refitView();
  shell.reset();
}

function announce(fresh: CutOut[]): void {
  for (const d of fresh) {
    // A dropped piece is announced where it lands (Challenge.watch), not as it comes away.
    if (d.drop === 'falling') continue;
    // Over the piece it came away in (a dropped one: where it landed); one cut to bits has none: over
    // the middle of the sheet.
    // A cut-out's label shows over the washing line, clear of the shapes still to cut.
    const at: [number, number] = d.drop
      ? [d.landedAt!, 0.5]
      : d.piece >= 0
        ? [challenge.centre(d.piece, [0, 0])[0], Number.NaN]
        : [SHEET_X + SHEET_WIDTH / 2, Number.NaN];
    const name = challenge.shapes[d.shape]!.name;
    const text = new Container({ label: 'cut out' });
    const words = new Text({
      text:
        d.drop === 'in'
          ? 'In the basket!'
          : d.drop === 'out'
            ? 'Missed the basket'
            : `${name[0]!.toUpperCase()}${name.slice(1)}: ${Math.round(d.fit * 100)}%`,
      style: { fill: 0xffffff, fontSize: 22, fontFamily: 'sans-serif', fontWeight: 'bold', stroke: { color: 0x1b2430, width: 5 } },
    });
    words.anchor.set(0.5, 1);
    words.y = -30;
    text.addChild(words, starRow(d.stars, 13));
    labelLayer.addChild(text);
    labels.push({ text, x: at[0], y: Number.isNaN(at[1]) ? at[1] : at[1] + 0.4, born: performance.now() / 1000 });
    sound.chime([440, 660, 880, 1046][d.stars]!, 0.5);
  }
}

/** Three stars in a row centred on (0, -14), `won` of them gold, each `r` px across its points. */
function starRow(won: number, r: number): Graphics {
  const g = new Graphics();
  for (let k = 0; k < 3; k++) {
    const cx = (k - 1) * 2.3 * r,
      cy = -r - 1;
    const pts: number[] = [];
    for (let i = 0; i < 10; i++) {
      const a = -Math.PI / 2 + (Math.PI * i) / 5,
        rr = i % 2 ? r * 0.45 : r;
      pts.push(cx + rr * Math.cos(a), cy + rr * Math.sin(a));
    }
    g.poly(pts)
      .fill({ color: k < won ? 0xffd23f : 0x3a4456 })
      .stroke({ width: 2, color: 0x1b2430 });
  }
  return g;
}

// Tools: the scissors cut, the hand pulls; Gust blows while held.
type Tool = 'cut' | 'pull';
let tool: Tool = 'cut';
const ICON_SCISSORS =
  '<svg viewBox="0 0 24 24" width="20" height="20" aria-hidden="true" style="vertical-align:-4px"><g fill="none" stroke="currentColor" stroke-width="2"><circle cx="6" cy="6" r="3"/><circle cx="6" cy="18" r="3"/><path d="M8.5 7.5L20 18M8.5 16.5L20 6"/></g></svg>';
const ICON_HAND =
  '<svg viewBox="0 0 24 24" width="20" height="20" aria-hidden="true" style="vertical-align:-4px"><path d="M8 12V5a1.5 1.5 0 0 1 3 0v6M11 11V3.5a1.5 1.5 0 0 1 3 0V11M14 11V5a1.5 1.5 0 0 1 3 0v7M17 10.5a1.5 1.5 0 0 1 3 0V15a7 7 0 0 1-7 7h-1a7 7 0 0 1-5.6-2.8L3 15.5a1.6 1.6 0 0 1 2.5-2L8 16V12" fill="none" stroke="currentColor" stroke-width="1.8" stroke-linejoin="round"/></svg>';
const ICON_WIND =
  '<svg viewBox="0 0 24 24" width="20" height="20" aria-hidden="true" style="vertical-align:-4px"><path d="M3 8h11a3 3 0 1 0-3-3M3 12h16a3 3 0 1 1-3 3M3 16h8" fill="none" stroke="currentColor" stroke-width="2" stroke-linecap="round"/></svg>';
const ICON_UNDO =
  '<svg viewBox="0 0 24 24" width="20" height="20" aria-hidden="true" style="vertical-align:-4px"><path d="M9 14L4 9l5-5M4 9h10a6 6 0 0 1 0 12h-3" fill="none" stroke="currentColor" stroke-width="2" stroke-linecap="round" stroke-linejoin="round"/></svg>';
const tools = createButtonBar(
  [
    { label: 'Scissors', name: 'scissors: drag to cut (C)', onTap: () => setTool('cut'), accent: '#ffd166' },
    { label: 'Hand', name: 'hand: drag to pull (C)', onTap: () => setTool('pull'), accent: '#ffd166' },
    {
      label: 'Gust',
      name: 'gust of wind (hold G)',
      onPress: () => setBlowing(true),
      onRelease: () => setBlowing(false),
      accent: '#8ecbff',
    },
    { label: 'Undo', name: 'undo the last cut (Ctrl+Z)', onTap: () => undoCut(), accent: '#ffd166' },
  ],
  { label: 'tools', touchOnly: false },
);
tools.buttons[0]!.innerHTML = `${ICON_SCISSORS} Scissors`;
tools.buttons[1]!.innerHTML = `${ICON_HAND} Hand`;
tools.buttons[2]!.innerHTML = `${ICON_WIND} Gust`;
const undoButton = tools.buttons[3]!;
// On a narrow phone the undo button shows its icon only (its name stays for screen readers), so the
// four tools fit one row under the scene.
const narrow = window.matchMedia('(max-width: 480px)');
const labelUndo = (): void => {
  undoButton.innerHTML = narrow.matches ? ICON_UNDO : `${ICON_UNDO} Undo`;
};
narrow.addEventListener('change', labelUndo);
labelUndo();
/**
 * The tool the player last picked on this sheet, and the sheet (LEVELS index) it was picked on: a
 * reset (R, Try again) keeps it; a new sheet starts with the scissors (where it has them).
 */
let chosen: { tool: Tool; level: number } = { tool: 'cut', level: -1 };
/**
 * Picks a tool (on a level without scissors the hand stays: the scissors' button is greyed out) and
 * remembers it as the player's choice on this sheet.
 */
function setTool(t: Tool): void {
  chosen = { tool: t, level: levelIndex };
  if (t === 'cut' && !LEVELS[levelIndex]!.scissors) t = 'pull';
  tool = t;
  tools.setActive(0, t === 'cut');
  tools.setActive(1, t === 'pull');
  tools.buttons[0]!.setAttribute('aria-pressed', String(t === 'cut'));
  tools.buttons[1]!.setAttribute('aria-pressed', String(t === 'pull'));
  app.canvas.style.cursor = t === 'cut' ? 'crosshair' : 'grab';
}
function setBlowing(on: boolean): void {
  if (on && !blowing) sound.launch(0.7);
  blowing = on;
}
/**
 * Greys the scissors out on a level without them (and takes the hand), or gives them back; picks the
 * tool the player chose on this sheet (a reset keeps it), the scissors on a new one.
 */
function refreshTools(): void {
  const ok = LEVELS[levelIndex]!.scissors;
  const b = tools.buttons[0]!;
  b.disabled = !ok;
  b.style.opacity = ok ? '' : '0.45';
  b.title = ok ? '' : 'no scissors on this sheet: tear it';
  setTool(chosen.level === levelIndex ? chosen.tool : 'cut');
}
refreshTools();
window.addEventListener('keydown', (e) => {
  if (e.ctrlKey || e.metaKey || e.altKey) return;
  const k = e.key.toLowerCase();
  if (k === 'c' && !e.repeat) setTool(tool === 'cut' ? 'pull' : 'cut');
  if (k === 'g') setBlowing(true);
});
window.addEventListener('keydown', (e) => {
  if ((e.ctrlKey || e.metaKey) && !e.altKey && !e.shiftKey && e.key.toLowerCase() === 'z') {
    e.preventDefault();
    undoCut();
  }
});
window.addEventListener('keyup', (e) => {
  if (e.key.toLowerCase() === 'g') setBlowing(false);
});
window.addEventListener('blur', () => setBlowing(false));

// The pointer: a scissors stroke cuts the links it crosses, a hand grips the cloth and pulls.
const canvas = app.canvas;
canvas.addEventListener('contextmenu', (e) => e.preventDefault());
const at = { x: 0, y: 0 };
const pointerWorld = (e: PointerEvent): [number, number] => {
  pointerOnCanvas(canvas, e, at);
  return [renderer.camera.toWorldX(at.x), renderer.camera.toWorldY(at.y)];
};
/** The scissors' stroke while cutting (cut.ts) and its pointer; the recent points for the drawn slash (screen px, time s). */
let stroke: { cut: ScissorsStroke; id: number; finger: boolean } | null = null;
const slash: { x: number; y: number; t: number }[] = [];
/** Pushes the stroke's last point (on the cloth's frame, ScissorsStroke.at) to the slash. */
function slashTo(s: ScissorsStroke): void {
  const cam = renderer.camera;
  slash.push({ x: cam.toScreenX(s.at[0]), y: cam.toScreenY(s.at[1]), t: performance.now() / 1000 });
}
/** Greys the undo button out when there is nothing to undo. */
function refreshUndo(): void {
  const none = history.count === 0 && !(pullOpen && torn > tornAtPull);
  undoButton.disabled = none;
  undoButton.style.opacity = none ? '0.45' : '';
}
/**
 * Undoes the last action that cut or tore the sheet (CutUndo.undo: a scissors stroke or a pull of the
 * hand). A pull under way ends first, so undo takes it back. Does nothing while a stroke is under way.
 */
function undoCut(): void {
  if (stroke) return;
  grab?.release();
  grab = null;
  closePull();
  const done = history.undo();
  if (!done) return;
  note = '';
  cut = done.extra.cut;
  torn = done.extra.torn;
  sheet?.invalidate();
  refreshUndo();
  slash.length = 0;
  sound.snap(0.2);
}
/** Counts and scores links the scissors cut (their midpoints, as cutAlong returns them). */
function snip(cutHere: number[]): void {
  if (cutHere.length === 0) return;
  cut += cutHere.length / 2;
  snipped += cutHere.length / 2;
  cells.loosen(shell.world);
  announce(challenge.update());
}
/** Links cut since the last snip sound, and torn since the last rip sound. */
let snipped = 0,
  ripped = 0,
  lastSnip = 0,
  lastRip = 0,
  /** When the pointer last went down, ms (performance.now). */
  lastInput = 0;
/**
 * What the last stroke did when it cut something away but cut out no shape (set as the stroke ends;
 * '' when there is nothing to say): shown on the status line until the next stroke, an undo or a
 * new sheet, so a cut that missed its line is not met with silence.
 */
let note = '';
/** The note for a stroke that cut pieces away (`scrapsBefore` pieces off before it) but cut out no shape; '' if it cut nothing away. */
function strokeNote(scrapsBefore: number): string {
  const parts = challenge.partCuts();
  if (parts.length > 0)
    return parts
      .map((p) => {
        const name = challenge.shapes[p.shape]!.name;
        const fell = Math.round(p.fell * 100),
          hangs = Math.round(p.hangs * 100);
        return `${name[0]!.toUpperCase()}${name.slice(1)}: ${short(
          `cut off the line, ${fell}% of it fell and ${hangs}% still hangs: not cut out. Undo (↶) and cut along the dashes.`,
          `cut off the line, ${fell}% fell, ${hangs}% hangs. Undo (↶), cut on the dashes.`,
        )}`;
      })
      .join(' ');
  return challenge.scraps > scrapsBefore
    ? short('That piece held no shape: cut along a dashed line.', 'That piece held no shape: cut on the dashes.')
    : '';
}
/** The note after the status line's own words (' ' and the note), or ''. */
const noteTail = (): string => (note ? ` ${note}` : '');
/** Pieces off (Challenge.scraps) and shapes cut out (Challenge.done) when the current stroke began. */
let scrapsBefore = 0,
  doneBefore = 0;
/** Whether a scissors stroke was made on the paused sheet since it was last paused. */
let pausedStroke = false;
canvas.addEventListener('pointerdown', (e) => {
  if (e.button !== 0 && e.button !== 2) return;
  lastInput = performance.now();
  const [x, y] = pointerWorld(e);
  grab?.release();
  grab = null;
  closePull();
  stroke = null;
  const scissors = LEVELS[levelIndex]!.scissors;
  if ((tool === 'cut' || e.button === 2) && scissors) {
    // On the paused sheet the scissors cut too: the sheet holds still for a careful cut, and the
    // pieces cut away fall when it runs again (the status line says so).
    if (shell.paused) pausedStroke = true;
    history.begin({ cut, torn, scraps: challenge.scraps });
    scrapsBefore = challenge.scraps;
    doneBefore = challenge.done.length;
    note = '';
    // A finger hides the line it traces and is wider than a mouse's point: its cut is scored with
    // FINGER_SLACK_PX of slack (as the sheet is drawn now), and it closes from further off.
    const finger = e.pointerType === 'touch';
    challenge.setSlack(finger ? FINGER_SLACK_PX / renderer.camera.toScreenLength(1) : 0);
    // A point over a cut holds on to the cloth's nearest point within a link's length.
    stroke = {
      cut: new ScissorsStroke(shell.world, cloth, x, y, SHEET_WIDTH / (params.size - 1), STROKE_FRAME, challenge.marks),
      id: e.pointerId,
      finger,
    };
    cutting = true;
    // On a sheet for careful cuts the sheet holds still under the scissors (heldForScissors), drawn
    // where it is now (not between its last two steps), and the air is still when it runs on.
    if (heldForScissors()) {
      holdSheetStill(shell.world);
      if (calm < 1) {
        calm = 1;
        blowNow(shell.world);
      }
    }
    slash.length = 0;
    slash.push({ x: at.x, y: at.y, t: performance.now() / 1000 });
  } else if (e.button === 0) {
    grab = ClothGrab.at(shell.world, cloth, x, y, gripFor(params.size));
    // A pull that tears the sheet is an action undo takes back, as a stroke is.
    if (grab) {
      history.begin({ cut, torn, scraps: challenge.scraps });
      pullOpen = true;
      tornAtPull = torn;
    }
  }
  if (stroke || grab) canvas.setPointerCapture(e.pointerId);
});
canvas.addEventListener('pointermove', (e) => {
  const [x, y] = pointerWorld(e);
  if (stroke && e.pointerId === stroke.id) {
    snip(stroke.cut.moveTo(x, y));
    slashTo(stroke.cut);
  } else if (grab) grab.moveTo(x, y);
});
const release = (): void => {
  if (stroke) {
    const spacing = SHEET_WIDTH / (params.size - 1);
    const gap = Math.max(CLOSE_GAP * spacing, stroke.finger ? FINGER_CLOSE_PX / renderer.camera.toScreenLength(1) : 0);
    snip(stroke.cut.close(gap, CLOSE_LENGTH));
    slashTo(stroke.cut);
    if (history.end()) {
      if (challenge.done.length === doneBefore) note = strokeNote(scrapsBefore);
      refreshUndo();
      // It cut: the air stays still a while, so the sheet hangs still for the next shape.
      calmUntil = shell.world.time + CALM_HOLD;
    }
  }
  grab?.release();
  grab = null;
  stroke = null;
  cutting = false;
};
canvas.addEventListener('pointerup', release);
canvas.addEventListener('pointercancel', release);
shell.onWorldChange(() => {
  // The new sheet is drawn in the very next frame (draw builds its view there), even where a GPU slower
  // than the page has the frame pacer skip frames: the old, cut sheet would otherwise stay on the
  // canvas for seconds while the status line already names the next one.
  game.drawNext();
  refitView();
  refreshTools();
  grab = null;
  stroke = null;
  cutting = false;
  note = '';
  refreshUndo();
});
refreshUndo();

/**
 * Plays the snip and rip sounds for what was cut and torn since the last one (at most one of each per
 * 60 and 90 ms). Until the page's audio runs (the first press starts it, a moment later) they wait, up
 * to 0.4 s, so the first cut is heard too.
 */
function playSounds(): void {
  const now = performance.now();
  if (!sound.running) {
    if (now - lastInput > 400) snipped = ripped = 0;
    return;
  }
  if (snipped > 0 && now - lastSnip > 60) {
    sound.snap(Math.min(1, 0.25 + snipped / 30));
    snipped = 0;
    lastSnip = now;
  }
  if (ripped > 0 && now - lastRip > 90) {
    sound.rip(Math.min(1, 0.3 + ripped / 40));
    ripped = 0;
    lastRip = now;
  }
}

// Drawing: the yard behind, the sheet, then the pegs, the hand, the slash, the wind and the labels.
const yard = new Yard();
const pegs = new Graphics({ label: 'pegs' });
const hand = new Graphics({ label: 'hand' });
const overlay = new Graphics({ label: 'overlay' });
const labelLayer = new Container({ label: 'labels' });
const card = new Graphics({ label: 'card' });
const basket = new Graphics({ label: 'basket' });
const basketBack = new Graphics({ label: 'basket back' });
renderer.root.addChildAt(yard.back, 0);
renderer.root.addChildAt(basketBack, 1);
// The yard draws the boundary box as the lawn and the walls: the renderer's outline of it is hidden.
const outline = renderer.root.getChildByLabel('walls');
if (outline) outline.visible = false;
renderer.root.addChild(pegs, hand, yard.front, basket, card, overlay, labelLayer);

/** Wooden clothes pegs at the pegged points. */
function drawPegs(world: PhysicsWorld): void {
  const cam = renderer.camera,
    P = world.components.Position;
  pegs.clear();
  const w = Math.max(3, cam.toScreenLength(0.07)),
    h = Math.max(8, cam.toScreenLength(0.24));
  for (const e of pegPoints) {
    const x = cam.toScreenX(P.x[e]!),
      y = cam.toScreenY(P.y[e]!);
    pegs
      .roundRect(x - w / 2, y - h * 0.45, w, h, w / 2)
      .fill({ color: 0xc89a5b })
      .stroke({ width: 1, color: 0x7a5530 });
    pegs.rect(x - w / 2, y - h * 0.1, w, Math.max(1, h * 0.08)).fill({ color: 0x9aa3ad });
  }
}
let pegPoints: number[] = [];

/** The hand: a ring at the pointer and a cord to the held patch, brighter the harder it pulls. */
function drawHand(): void {
  hand.clear();
  if (!grab) return;
  const cam = renderer.camera;
  const [x, y] = grab.patch([0, 0]);
  // Full brightness (and red past 0.7) as the pull nears what tears the sheet (25-55 N, grab.ts).
  const pull = Math.min(1, grab.force() / (2.5 * grab.options.firm));
  const hx = cam.toScreenX(grab.hand[0]),
    hy = cam.toScreenY(grab.hand[1]);
  hand
    .moveTo(cam.toScreenX(x), cam.toScreenY(y))
    .lineTo(hx, hy)
    .stroke({ width: 2 + 3 * pull, color: pull > 0.7 ? 0xff6b4a : 0xffd166, alpha: 0.5 + 0.5 * pull });
  hand.circle(cam.toScreenX(x), cam.toScreenY(y), 4).fill({ color: 0xffd166 });
  hand.circle(hx, hy, 11).stroke({ width: 3, color: 0x1b2430, alpha: 0.6 });
  hand.circle(hx, hy, 11).stroke({ width: 2, color: 0xffd166 });
}

/** The scissors' slash: the last 0.3 s of the stroke, fading. */
function drawSlash(now: number): void {
  while (slash.length > 0 && now - slash[0]!.t > 0.3) slash.shift();
  overlay.clear();
  for (let i = 1; i < slash.length; i++) {
    const a = slash[i - 1]!,
      b = slash[i]!;
    const fade = 1 - (now - b.t) / 0.3;
    overlay
      .moveTo(a.x, a.y)
      .lineTo(b.x, b.y)
      .stroke({ width: 6 * fade + 1, color: 0xffffff, alpha: 0.25 * fade, cap: 'round' });
    overlay
      .moveTo(a.x, a.y)
      .lineTo(b.x, b.y)
      .stroke({ width: 2, color: 0xffffff, alpha: 0.9 * fade, cap: 'round' });
  }
}

/**
 * Places the floating labels (a dropped piece's rising as it fades; a cut-out's over the line, still;
 * each under the action button while it shows) and fades them.
 */
function drawLabels(now: number): void {
  const cam = renderer.camera;
  const button = labels.length > 0 ? document.querySelector('.bp-action button')?.getBoundingClientRect() : undefined;
  /** The lowest a label's top may be kept above, CSS px on the canvas: 6 px under the action button, if shown. */
  const under = button ? button.bottom - app.canvas.getBoundingClientRect().top + 6 : 0;
  for (let i = labels.length - 1; i >= 0; i--) {
    const l = labels[i]!;
    const age = now - l.born;
    if (age > LABEL_LIFE) {
      l.text.destroy({ children: true });
      labels.splice(i, 1);
      continue;
    }
    const half = l.text.width / 2 + 6;
    l.text.x = Math.min(Math.max(cam.toScreenX(l.x), half), cam.width - half);
    // Under the action button while it shows at the top (it covered the last sheet's "Strip: 96%").
    const top = Math.max(LABEL_TOP, under + l.text.height);
    l.text.y = Number.isNaN(l.y)
      ? Math.max(cam.toScreenY(LINE_Y) - LABEL_OVER_LINE, top)
      : Math.max(cam.toScreenY(l.y) - 30 * age, top + 8);
    l.text.alpha = Math.min(1, 3 * (1 - age / LABEL_LIFE));
  }
}

/**
 * The card on the lawn: the level's targets side by side, each drawn in its colour once done (an
 * outline while still to do), scaled to fit its place, with its stars under it.
 */
function drawCard(): void {
  const cam = renderer.camera;
  card.clear();
  const shapes = challenge.shapes,
    n = shapes.length;
  const size = Math.min(30, cam.toScreenLength(0.32)),
    gap = size * 2.6;
  const cy = cam.toScreenY(-0.3) - size * 0.1,
    cx = cam.toScreenX((YARD.minX + YARD.maxX) / 2);
  card.roundRect(cx - (n / 2) * gap, cy - size * 0.75, n * gap, size * 1.9, 8).fill({ color: 0x1b2430, alpha: 0.55 });
  shapes.forEach((shape, i) => {
    const x = cx + (i - (n - 1) / 2) * gap,
      y = cy - size * 0.05;
    const o = shape.outline;
    let x0 = Infinity,
      x1 = -Infinity,
      y0 = Infinity,
      y1 = -Infinity;
    for (let k = 0; k < o.length; k += 2) {
      x0 = Math.min(x0, o[k]!);
      x1 = Math.max(x1, o[k]!);
      y0 = Math.min(y0, o[k + 1]!);
      y1 = Math.max(y1, o[k + 1]!);
    }
    // The largest side of the shape's box fills 1.1 times `size`; the strip (4 m by 1 m) as wide.
    const scale = (size * 1.1) / Math.max(x1 - x0, y1 - y0);
    const pts: number[] = [];
    for (let k = 0; k < o.length; k += 2) pts.push(x + (o[k]! - (x0 + x1) / 2) * scale, y + (o[k + 1]! - (y0 + y1) / 2) * scale);
    const done = challenge.done.find((d) => d.shape === i && d.drop !== 'falling');
    if (done) card.poly(pts).fill({ color: shape.color }).stroke({ width: 2, color: 0xffffff });
    else card.poly(pts).stroke({ width: 2, color: 0xffffff, alpha: 0.8 });
    for (let k = 0; k < 3; k++) {
      const sx = x + (k - 1) * size * 0.42,
        sy = y + size * 0.78,
        r = size * 0.17;
      const star: number[] = [];
      for (let j = 0; j < 10; j++) {
        const a = -Math.PI / 2 + (Math.PI * j) / 5,
          rr = j % 2 ? r * 0.45 : r;
        star.push(sx + rr * Math.cos(a), sy + rr * Math.sin(a));
      }
      card.poly(star).fill({ color: done && k < done.stars ? 0xffd23f : 0x55617a });
    }
  });
}

/**
 * The basket on the lawn of a level with a piece to drop (Shape.drop): a wicker basket behind the
 * sheet's layer and the lower half of its front over it, so a piece that lands in it is seen lying
 * inside; a pale band on its rim marks the middle third (three stars).
 */
function drawBasket(): void {
  basketBack.clear();
  basket.clear();
  const drop = challenge.shapes.find((sh) => sh.drop)?.drop;
  if (!drop) return;
  const cam = renderer.camera;
  const x0 = cam.toScreenX(drop.x - drop.width / 2),
    x1 = cam.toScreenX(drop.x + drop.width / 2),
    top = cam.toScreenY(0.32),
    bottom = cam.toScreenY(0),
    lip = Math.max(2, cam.toScreenLength(0.04)),
    slant = (x1 - x0) * 0.06;
  for (const [g, from] of [
    [basketBack, 0],
    [basket, 0.5],
  ] as const) {
    const y0 = top + (bottom - top) * from,
      s0 = slant * from;
    g.poly([x0 + s0, y0, x1 - s0, y0, x1 - slant, bottom, x0 + slant, bottom]).fill({ color: from > 0 ? 0xb8874a : 0x8a5f2c });
    // Wicker: bands across and ribs down.
    for (let k = 1; k < 4; k++) {
      const y = top + ((bottom - top) * k) / 4;
      if (y > y0) g.moveTo(x0 + (slant * k) / 4, y).lineTo(x1 - (slant * k) / 4, y);
    }
    for (let k = 1; k < 8; k++) {
      const u = k / 8;
      g.moveTo(x0 + s0 + (x1 - x0 - 2 * s0) * u, y0).lineTo(x0 + slant + (x1 - x0 - 2 * slant) * u, bottom);
    }
    g.stroke({ width: 1, color: 0x5e3f1c, alpha: 0.8 });
  }
  basketBack.rect(x0 - lip, top - lip, x1 - x0 + 2 * lip, 2 * lip).fill({ color: 0x8a5f2c });
  const third = (x1 - x0) / 6;
  const mid = (x0 + x1) / 2;
  basketBack.rect(mid - third, top - lip, 2 * third, 2 * lip).fill({ color: 0xffd166, alpha: 0.8 });
}

/** The status line: what to do, and how it went. */
function updateStatus(): void {
  if (!shell.paused) pausedStroke = false;
  else if (pausedStroke) {
    const press = touchInput.matches ? 'press ▶' : 'press ▶ (or P)';
    status.set(
      `${short(`Paused: cut along the dashed lines, then ${press}`, `Paused: cut, then ${press}`)} to let the pieces fall.${noteTail()}`,
    );
    return;
  }
  const level = LEVELS[levelIndex]!;
  const done = challenge.done,
    shapes = challenge.shapes;
  const head = `${levelIndex + 1}/${LEVELS.length} ${level.title}`;
  const stars = (n: number) => `${'★'.repeat(n)}${'☆'.repeat(3 - n)}`;
  if (challenge.finished()) {
    const won = challenge.stars(),
      need = passMark(shapes.length);
    const last = levelIndex === LEVELS.length - 1;
    const missed = done.some((d) => d.drop === 'out');
    failed = missed || won < need;
    if (recordBest(levelStars, levelIndex, won, !failed)) saveProgress(store, levelStars);
    status.set(
      missed
        ? `${head}: ${short('the peg bag missed the basket. Undo (↶) and cut again, or try again.', 'missed the basket. Undo (↶) or try again.')}`
        : failed
          ? `${head}: ${short(
              `failed, ${won} of ${3 * shapes.length} stars (${need} to pass). Undo (↶) and cut again, or try again.`,
              `failed, ${won}/${3 * shapes.length} ★ (${need} to pass). Undo (↶) or try again.`,
            )}`
          : `${head}: done, ${won} of ${3 * shapes.length} stars. ${
              last
                ? `All sheets: ${levelStars.reduce((a, b) => a + Math.max(0, b), 0)} of ${3 * LEVELS.reduce((a, l) => a + l.shapes(params.size).length, 0)} stars.`
                : `Next: ${LEVELS[levelIndex + 1]!.title} (${LEVELS[levelIndex + 1]!.day}).`
            }`,
    );
    showNext(true, failed ? 'Try again ↺' : last ? 'Start again ▶' : 'Next sheet ▶');
    return;
  }
  // The shapes left cannot bring the stars up to the pass mark (a pull of the hand tore through
  // them, or they scored too few): the level cannot be won any more, so say so and offer a retry.
  const need = passMark(shapes.length);
  const spoilt = stroke ? [] : challenge.spoilt();
  const open = challenge.pending().length - spoilt.length;
  if (challenge.stars() + 3 * open < need && done.every((d) => d.drop !== 'falling')) {
    failed = true;
    const torn = spoilt.length > 0 ? `the ${spoilt.map((i) => shapes[i]!.name).join(' and the ')} torn, ` : '';
    status.set(
      `${head}: ${short(
        `${torn}this sheet can no longer reach ${need} stars (${challenge.stars()} so far). Undo (↶) the last tear or cut, or try again.`,
        `can't reach ${need} ★ now. Undo (↶) or try again.`,
      )}`,
    );
    showNext(true, 'Try again ↺');
    return;
  }
  failed = false;
  showNext(false);
  if (note) {
    status.set(`${head}: ${note}`);
    return;
  }
  const last = done[done.length - 1];
  if (!last) {
    const best = levelStars[levelIndex]!;
    status.set(
      `${head}: ${level.ask}${best >= 0 ? short(` Best so far: ${best} of ${3 * shapes.length} stars.`, ` Best ${best}/${3 * shapes.length} ★.`) : ''}${level.calm ? pauseTip() : ''}`,
    );
    return;
  }
  if (last.drop === 'falling') {
    status.set(`${head}: the peg bag falls…`);
    return;
  }
  const left = challenge.pending().map((i) => shapes[i]!.name);
  const name = shapes[last.shape]!.name;
  // Short of three stars: how to get them (on a sheet in a breeze, the paused sheet holds still).
  // A ragged edge (Fit.steady) is told apart from one that strayed: it cost the stars, not the place.
  const ragged = (last.steady ?? 1) < 0.97;
  // A notch or a tear into the shape (Fit.clean) is told apart too.
  const notched = (last.clean ?? 1) < Math.min(0.97, last.steady ?? 1);
  const tip =
    last.stars < 3
      ? notched
        ? short(' A notch or a tear into it: keep the scissors on the dashes for ★★★.', ' A notch: keep on the dashes for ★★★.')
        : ragged
          ? short(
              ` A ragged edge: one smooth stroke along the dashes for ★★★${level.calm ? ' (pause to hold the sheet still)' : ''}.`,
              ` Ragged: cut in one smooth stroke${level.calm ? ', paused' : ''}.`,
            )
          : short(
              ` Cut on the dashed line for ★★★${level.calm ? ' (pause to hold the sheet still)' : ''}.`,
              ` Cut on the dashes${level.calm ? ', paused,' : ''} for ★★★.`,
            )
      : '';
  // Three stars: the tip to pause stays in view for the shapes still to cut.
  status.set(
    `${name[0]!.toUpperCase()}${name.slice(1)}: ${Math.round(last.fit * 100)}% ${stars(last.stars)}.${tip} Still to cut: ${left.join(', ')}.${
      last.stars === 3 && level.calm && left.length > 0 ? pauseTip() : ''
    }`,
  );
}

/** The tip to cut on the paused sheet, for the sheets of careful cuts (' ' first). */
function pauseTip(): string {
  return touchInput.matches
    ? short(' Tip: pause and the sheet holds still; the scissors still cut.', ' Tip: pause, it holds still.')
    : short(' Tip: pause (P) and the sheet holds still; the scissors still cut.', ' Tip: P holds it still.');
}

let lastFrame = performance.now() / 1000;
let layerWorld: PhysicsWorld | null = null;
let links = 0,
  linksVersion = -1,
  linksWorld: PhysicsWorld | null = null;
function draw(alpha: number, world: PhysicsWorld): void {
  const now = performance.now() / 1000;
  const dt = shell.paused ? 0 : Math.min(0.05, now - lastFrame);
  lastFrame = now;
  if (layerWorld !== world) {
    sheet?.destroy();
    const grid = sheetGrid(params.size);
    const level = LEVELS[levelIndex]!;
    sheet = new SheetView(
      world,
      cloth,
      cells,
      fabricTexture(SHEET_WIDTH, grid.height, grid.spacing * 1.5, challenge.shapes, level.perforation),
      grid.spacing,
    );
    renderer.root.addChildAt(sheet.container, renderer.root.getChildIndex(basketBack) + 1);
    pegPoints = [];
    const inv = world.components.Mass.inv;
    for (let c = 0; c < cloth.columns; c++) {
      const e = slotOf(cloth.points[c]!);
      if (!(inv[e]! > 0)) pegPoints.push(e);
    }
    layerWorld = world;
  }
  yard.update(world, renderer.camera, dt, app.screen.width, app.screen.height);
  sheet!.update(renderer.camera, alpha);
  drawPegs(world);
  drawHand();
  drawSlash(now);
  drawLabels(now);
  drawCard();
  drawBasket();
  playSounds();
  updateStatus();
  // The links left, counted again only when the cloth's links changed (a query allocates).
  if (linksVersion !== world.cloth.version || linksWorld !== world) {
    links = query(world, [world.components.ClothLink]).length;
    linksVersion = world.cloth.version;
    linksWorld = world;
  }
  readout.set(0, String(links));
  readout.set(1, String(torn));
  readout.set(2, String(cut));
  readout.set(3, String(challenge.scraps));
  readout.set(4, `${fmt(sheet!.shownStretch * 100, 3)} %`);
  // While the sheet holds still (the scissors down on a sheet for careful cuts, or paused) no step
  // runs: the readout says so rather than showing the last step's figures, frozen.
  const held = heldForScissors();
  windAt(world, 2, 3, 0, world.time, wind);
  readout.set(5, held ? 'still (scissors)' : `${fmt(wind[0]!, 2)} m/s`);
  readout.set(6, held ? 'held (scissors)' : shell.paused ? 'paused' : `${fmt(stepMs, 3)} ms`);
}
shell.expose({
  params,
  plot,
  /** The cloth's point and link handles. */
  cloth: () => cloth,
  /** The current tool ('cut' or 'pull'). */
  tool: () => tool,
  /** The hand's grip while the pointer holds the cloth, else null. */
  grab: () => grab,
  /** Links left, links torn by strain and cut by the scissors since the reset. */
  links: () => query(shell.world, [shell.world.components.ClothLink]).length,
  torn: () => torn,
  cut: () => cut,
  /** Strokes that can be undone (undo button, Ctrl/Cmd+Z). */
  undoCount: () => history.count,
  /** Whether a scissors stroke is under way (the pointer down; an undo waits for it to end). */
  stroking: () => stroke !== null,
  /** Undoes the last cutting stroke (as the undo button). */
  undoCut,
  /** Hangs the next sheet (as the Next sheet button). */
  nextSheet,
  /** The challenge: shapes cut out ({ shape, fit, stars }), and pieces that came away. */
  cutOuts: () =>
    challenge.done.map((d) => ({
      shape: challenge.shapes[d.shape]!.name,
      fit: d.fit,
      stars: d.stars,
      drop: d.drop ?? '',
      landedAt: d.landedAt ?? Number.NaN,
    })),
  /** The level up: its index (0-based) and title, and its targets' names. */
  level: () => ({ index: levelIndex, title: LEVELS[levelIndex]!.title, shapes: challenge.shapes.map((sh) => sh.name) }),
  /** The level's targets' outlines (sheet coordinates: m from the sheet's left edge and down from its top, at rest). */
  targets: () => challenge.shapes.map((sh) => [...sh.outline]),
  /** The level's peg bag's basket (centre x and width, m), null on a level without one. */
  basket: () => challenge.shapes.find((sh) => sh.drop)?.drop ?? null,
  scraps: () => challenge.scraps,
  /** The card of targets and their stars on the lawn, on the canvas (CSS px: x, y, width, height). */
  /** The floating labels showing now (a cut-out's words and stars), on the canvas (CSS px: x, y, width, height each). */
  labels: () =>
    labels.map((l) => {
      const b = l.text.getBounds();
      return { x: b.x, y: b.y, width: b.width, height: b.height };
    }),
  starCard: () => {
    const b = card.getBounds();
    return { x: b.x, y: b.y, width: b.width, height: b.height };
  },
  /** The gust the player blows, 0 to 1. */
  gust: () => blow,
  /** Triangles the sheet is drawn with, and the largest stretch it shows (a strain). */
  triangles: () => sheet?.triangles ?? 0,
  shownStretch: () => sheet?.shownStretch ?? 0,
  /** Wind streaks drawn in the last frame. */
  streaks: () => yard.streaksDrawn,
  /** Removes one link (a link handle of `cloth().links`), as a tear would (tests). */
  removeLink: (h: number) => removeJoint(shell.world, h),
  /** Runs the lab's step n times (tests). */
  /** How still the air is for the scissors, 0 (the breeze blows) to 1 (still), and how long it stays still after the last cut, s of world time. */
  calm: () => ({ calm, hold: Math.max(0, calmUntil - shell.world.time) }),
  advance: (n: number) => {
    for (let i = 0; i < n; i++) labStep(shell.world);
  },
});
