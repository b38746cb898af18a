/**
 * The renderer-agnostic game shell every game reuses: the page contract (`window.game`, ready
 * flag), the fixed-step loop on requestAnimationFrame, keys (P pause, N step, R reset), the HUD
 * (fps, bodies, controls legend), the page layout (toolbar, info and side columns around the scene),
 * lil-gui panels, URL parameters and pointer positions.
 * The pixi part lives in './pixi' (createPixiApp, startPixiGame) so 3D games need not load pixi.
 */

export type { GameHandle, GameStats } from './contract';
export { exposeGame, markReady } from './contract';
export type { ControlHint, Hud, HudOptions } from './hud';
export { createHud, plural, touchGesture } from './hud';
export type { ImpactListener } from './impacts';
export { forEachImpact } from './impacts';
export type { KeyBinding } from './keys';
export { bindKeys } from './keys';
export type { PageLayout } from './layout';
export { COMPACT_MAX_HEIGHT, COMPACT_MAX_WIDTH, pageLayout } from './layout';
export type { GameLoop, GameLoopOptions } from './loop';
export { createGameLoop } from './loop';
export type { ChoiceControl, Panel, PanelControl, PanelOptions, PlainControl, SliderControl } from './panel';
export { createPanel } from './panel';
export type { NumberParamOptions } from './params';
export { choiceParam, flagParam, numberParam, seedParam } from './params';
export { pointerOnCanvas } from './pointer';
export type { GameShell, GameShellOptions } from './shell';
export { createGameShell, SHELL_CONTROLS } from './shell';
export type { EngineSound, Sound, SoundMaterial } from './sound';
export { addMuteButton, getSound } from './sound';
export type { ButtonBar, ButtonBarOptions, Stick, StickOptions, TouchButton } from './touch-controls';
export { createActionButton, createButtonBar, createStick, isTouchDevice } from './touch-controls';
