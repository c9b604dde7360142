import puppeteer from 'puppeteer';
import type { TestProject } from 'vitest/node';
import { BROWSER_ARGS, findBrowser } from './harness';

declare module 'vitest' {
  export interface ProvidedContext {
    browserEndpoint: string;
  }
}

/**
 * The browser project's global set-up: one headless Chromium for every test file. A fresh
 * browser per file would compile the same shader programs again in each of them, which on
 * SwiftShader costs seconds per program; tests still open their own pages.
 */
export default async function setup(project: TestProject): Promise<() => Promise<void>> {
  const browser = await puppeteer.launch({ executablePath: await findBrowser(), args: BROWSER_ARGS, headless: true });
  project.provide('browserEndpoint', browser.wsEndpoint());
  return async () => {
    await browser.close();
  };
}
