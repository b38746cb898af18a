import type { Browser, BrowserServer } from 'playwright-core';

/** Repository root (absolute path). */
export declare const repoRoot: string;
/** Chromium flags used for every launch (headless is added by `launchChromium`). */
export declare const CHROMIUM_ARGS: readonly string[];
/** $CHROMIUM_PATH, else /usr/bin/chromium if present, else @sparticuz/chromium's binary. @throws Error if $CHROMIUM_PATH does not exist. */
export declare function chromiumPath(): Promise<string>;
/** Launches headless Chromium with CHROMIUM_ARGS. */
export declare function launchChromium(): Promise<Browser>;
/** Launches headless Chromium with CHROMIUM_ARGS as a server that test files connect to. */
export declare function launchChromiumServer(): Promise<BrowserServer>;
/** Connects to a browser server started by launchChromiumServer. */
export declare function connectChromium(wsEndpoint: string): Promise<Browser>;
/** A TCP port on 127.0.0.1 that was free a moment ago. */
export declare function freePort(): Promise<number>;
/** Takes the cross-process site lock (dist/site is shared). @returns its release function. @throws Error after timeoutMs. */
export declare function acquireSiteLock(options?: { timeoutMs?: number; name?: string }): Promise<() => void>;
/** Builds and serves the site on a free port under the site lock. `url` ends with '/'. */
export declare function startSite(options?: { lockTimeoutMs?: number }): Promise<{ url: string; stop: () => Promise<void> }>;
/** One gallery entry, from games/<folder>/game.json. */
export interface RegistryEntry {
  folder: string;
  title: string;
  summary: string;
  category: string;
  order: number;
}
/** The gallery registry (scripts/build.mjs readRegistry). */
export declare function readRegistry(): Promise<RegistryEntry[]>;
