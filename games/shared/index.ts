/**
 * The renderer-agnostic game shell every game reuses: the page contract (`window.game`, ready
 * flag), the fixed-step loop on requestAnimationFrame, keys (P pause, N step, R reset), the HUD
 * (fps, bodies, controls legend), the page layout (toolbar, info and side columns around the scene),
 * lil-gui panels, URL parameters and pointer positions.
 * The pixi part lives in './pixi' (createPixiApp, startPixiGame) so 3D games need not load pixi.
 */
export { exposeGame, markReady } from './contract';
export type { GameHandle, GameStats } from './contract';
export { createGameLoop } from './loop';
export type { GameLoop, GameLoopOptions } from './loop';
export { bindKeys } from './keys';
export type { KeyBinding } from './keys';
export { createHud, plural, touchGesture } from './hud';
export type { ControlHint, Hud, HudOptions } from './hud';
export { pageLayout, COMPACT_MAX_WIDTH, COMPACT_MAX_HEIGHT } from './layout';
export type { PageLayout } from './layout';
export { createPanel } from './panel';
export type { Panel, PanelControl, PanelOptions, SliderControl, ChoiceControl, PlainControl } from './panel';
export { numberParam, flagParam, choiceParam, seedParam } from './params';
export { pointerOnCanvas } from './pointer';
export type { NumberParamOptions } from './params';
export { createGameShell, SHELL_CONTROLS } from './shell';
export type { GameShell, GameShellOptions } from './shell';
