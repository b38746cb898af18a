/**
 * The renderer-agnostic game shell every game reuses: the page contract (`window.game`, ready
 * flag), the fixed-step loop on requestAnimationFrame, keys (P pause, N step, R reset), the HUD
 * (fps, a physics fold with bodies and steps, controls legend), the page layout (toolbar, info and side columns around the scene),
 * lil-gui panels, URL parameters, pointer positions, a game's status row (goal, numbers, hint),
 * the DOM result card at a round's end and saved values (best scores) checked on read.
 * The pixi part lives in './pixi' (createPixiApp, startPixiGame) so 3D games need not load pixi.
 */

export { onButtonPress } from './button-press.js';
export type { GameHandle, GameStats } from './contract.js';
export { exposeGame, markReady } from './contract.js';
export type { DomPauseOverlay, DomPauseOverlayOptions } from './dom-pause-overlay.js';
export { createDomPauseOverlay } from './dom-pause-overlay.js';
export type { DomResultCard, DomResultCardContent, DomResultCardOptions, ResultCardButton, ResultCardLine } from './dom-result-card.js';
/**
 * createDomResultCard(parent, options): the end-of-round dialog of a DOM page (title, stars out of N,
 * a big result line, lines of detail, buttons with keyboard shortcuts), hidden until `show(content)`;
 * `hide()`, `destroy()`. Buttons are at least 44 x 44 px and its text at least 4.5:1 on its ground.
 * Throws TypeError naming `createDomResultCard` and the parameter on a parent that is not a DOM
 * element or an empty `options.name`, RangeError on a `titleSize` (px) outside [12, 48]; `show`
 * throws on an empty title or button label, a missing onPress, or stars outside 0 <= earned <= outOf <= 10.
 */
export { createDomResultCard } from './dom-result-card.js';
export type { ControlHint, Hud, HudOptions } from './hud.js';
export { createHud, plural, touchGesture } from './hud.js';
export type { ImpactListener } from './impacts.js';
export { forEachImpact } from './impacts.js';
export type { KeyBinding } from './keys.js';
export { bindKeys } from './keys.js';
export type { PageLayout } from './layout.js';
export { COMPACT_MAX_HEIGHT, COMPACT_MAX_WIDTH, pageLayout, pauseUnderDrawers } from './layout.js';
export type { GameLoop, GameLoopOptions } from './loop.js';
export { createGameLoop } from './loop.js';
export type { ChoiceControl, Panel, PanelControl, PanelOptions, PlainControl, SliderControl } from './panel.js';
export { createPanel } from './panel.js';
export type { NumberParamOptions } from './params.js';
export { choiceParam, flagParam, numberParam, seedParam } from './params.js';
export { pointerOnCanvas } from './pointer.js';
export { seededRandom } from './random.js';
export { segmentsCross } from './segments.js';
export type { GameShell, GameShellOptions } from './shell.js';
export { createGameShell, SHELL_CONTROLS } from './shell.js';
export type { EngineSound, Sound, SoundMaterial } from './sound.js';
export { addMuteButton, getSound } from './sound.js';
export type { StatusLines, StatusRow, StatusRowOptions } from './status-row.js';
export { createStatusRow } from './status-row.js';
export type { KeyValueStorage, StorageOptions, StoredCheck, StoredRecord, StoredValue } from './storage.js';
/**
 * Saved values kept in localStorage across reloads, as JSON under a namespaced key ('my-game.best'),
 * checked on read so a garbled or out-of-range entry reads as the fallback: `storedValue(key, check,
 * fallback)` (read, write), `storedRecord(key, entryCheck)` (read, get, set: one entry per course),
 * the checks `numberCheck({ min, max, integer })`, `listCheck(item, length, fill)` and
 * `shapeCheck(fields)`, and `pageStorage()`. Missing or throwing storage (Node, private modes, a full
 * quota) costs only the keeping; only a bad key, range or written value throws.
 */
export { listCheck, numberCheck, pageStorage, shapeCheck, storedRecord, storedValue } from './storage.js';
export type { ActionButtonOptions, ButtonBar, ButtonBarOptions, Stick, StickOptions, TouchButton } from './touch-controls.js';
export { createActionButton, createButtonBar, createStick, isTouchDevice } from './touch-controls.js';
