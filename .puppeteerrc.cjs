// Installing the npm packages never downloads a browser: where the network reaches only
// package registries that download fails, and with it the whole `npm install`/`npm ci`.
// `npm test` gets a browser itself before the browser tests (tests/browser/ensure-browser.mjs:
// puppeteer's download where the network allows, else Debian's chromium when root, else
// one line saying what to install); tests/browser/harness.ts finds it.
module.exports = { skipDownload: true };
