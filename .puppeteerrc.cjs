// Puppeteer downloads its own Chrome on install. Where a browser is already present
// (CHROME_PATH or a system Chromium) or the network reaches only package registries,
// that download would fail the whole `npm install`, so it is skipped; the tests then
// find the browser themselves (tests/browser/find-browser.ts).
const fs = require('node:fs');
const systemBrowsers = ['/usr/bin/chromium', '/usr/bin/chromium-browser', '/usr/bin/google-chrome'];
const haveBrowser = Boolean(process.env.CHROME_PATH) || systemBrowsers.some((p) => fs.existsSync(p));
module.exports = {
  skipDownload: haveBrowser || process.env.PUPPETEER_SKIP_DOWNLOAD === 'true' || process.env.CI === 'true',
};
