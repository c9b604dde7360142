// `npm test` needs a browser. Installing the npm packages never downloads one (see
// .puppeteerrc.cjs), so this finds one before the browser tests, or gets one: first
// puppeteer's own Chrome download (works wherever the network reaches Google's storage),
// then Debian's chromium through apt-get when running as root on Debian/Ubuntu. Otherwise
// it stops with one line saying what to install.
import { execSync } from 'node:child_process';
import { existsSync } from 'node:fs';
import { locateBrowser, NO_BROWSER_MESSAGE } from './findBrowser.mjs';

function attempt(label, command) {
  console.log(`[oceano] no browser found: ${label}`);
  try {
    execSync(command, { stdio: ['ignore', 'inherit', 'pipe'], timeout: 10 * 60 * 1000 });
    return true;
  } catch (error) {
    const reason =
      String(error.stderr ?? error.message)
        .split('\n')
        .find((line) => /error/i.test(line)) ?? 'failed';
    console.log(`[oceano] that did not work: ${reason.trim()}`);
    return false;
  }
}

let browser;
try {
  browser = await locateBrowser();
} catch (error) {
  console.error(`[oceano] ${error.message}`);
  process.exit(1);
}
if (!browser) {
  const root = typeof process.getuid === 'function' && process.getuid() === 0;
  attempt("trying puppeteer's Chrome download", 'npx --no-install puppeteer browsers install chrome') ||
    (root &&
      existsSync('/usr/bin/apt-get') &&
      attempt(
        "installing Debian's chromium with apt-get",
        'apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq chromium fonts-dejavu-core',
      ));
  browser = await locateBrowser();
}
if (!browser) {
  console.error(`[oceano] ${NO_BROWSER_MESSAGE}`);
  process.exit(1);
}
