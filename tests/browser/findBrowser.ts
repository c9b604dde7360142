import { existsSync } from 'node:fs';

/**
 * The browser the tests drive, looked for in order: CHROME_PATH, puppeteer's own
 * downloaded Chrome (on machines with internet), then a system Chromium or Chrome.
 */
export async function findBrowser(): Promise<string> {
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
    // No downloaded Chrome in puppeteer's cache: fall through to the system browsers.
  }
  const system = ['/usr/bin/chromium', '/usr/bin/chromium-browser', '/usr/bin/google-chrome', '/usr/bin/google-chrome-stable'];
  const found = system.find((path) => existsSync(path));
  if (found) return found;
  throw new Error(
    'No Chrome or Chromium found. Set CHROME_PATH, run `npx puppeteer browsers install chrome`, or install Chromium (Debian: apt-get install chromium).',
  );
}
