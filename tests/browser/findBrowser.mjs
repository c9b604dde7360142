// Where the browser tests' Chrome comes from, in order: CHROME_PATH, puppeteer's own
// downloaded Chrome (machines with internet), then a system Chromium or Chrome. Shared by
// tests/browser/ensure-browser.mjs (which installs one when none is found) and the browser tests.
import { existsSync } from 'node:fs';

export const SYSTEM_BROWSERS = [
  '/usr/bin/chromium',
  '/usr/bin/chromium-browser',
  '/usr/bin/google-chrome',
  '/usr/bin/google-chrome-stable',
];

/** The path of a usable browser, or undefined. Throws only when CHROME_PATH names nothing. */
export async function locateBrowser() {
  const fromEnv = process.env.CHROME_PATH;
  if (fromEnv) {
    if (!existsSync(fromEnv)) throw new Error(`CHROME_PATH points at ${fromEnv}, which does not exist.`);
    return fromEnv;
  }
  try {
    const puppeteer = (await import('puppeteer')).default;
    const own = puppeteer.executablePath();
    if (own && existsSync(own)) return own;
  } catch {
    // No Chrome in puppeteer's cache: fall through to the system browsers.
  }
  return SYSTEM_BROWSERS.find((path) => existsSync(path));
}

export const NO_BROWSER_MESSAGE =
  'No Chrome or Chromium for the browser tests: install Chromium (Debian/Ubuntu: `sudo apt-get install chromium`), or run `npx puppeteer browsers install chrome`, or set CHROME_PATH.';
