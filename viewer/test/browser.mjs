// Chromium for the viewer's browser tests: Debian's (no browser download), headless, a fresh
// profile, every request but the page's own file aborted, driven by playwright-core.

import assert from 'node:assert/strict';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';

const CHROMIUM = process.env.HULLINSPECT_CHROMIUM || '/usr/bin/chromium';

export class Browser {
  // `args`: Chromium's command-line switches.
  static async launch(args) {
    let chromium;
    try {
      ({chromium} = await import('playwright-core'));
    } catch (e) {
      assert.fail(`playwright-core is not installed: run scripts/setup (npm ci in viewer/test): ${e.message}`);
    }
    const browser = new Browser();
    browser.userDataDir = fs.mkdtempSync(path.join(os.tmpdir(), 'hullinspect-chromium-'));
    browser.context = await chromium.launchPersistentContext(browser.userDataDir, {
      executablePath: CHROMIUM,
      headless: true,
      args,
      viewport: {width: 1400, height: 900},
      deviceScaleFactor: 1,
    });
    // No network: anything but the page's own file is refused (the page's CSP forbids it too).
    await browser.context.route('**/*', (route) =>
      route.request().url().startsWith('file:') ? route.continue() : route.abort());
    return browser;
  }

  async close() {
    if (this.context) await this.context.close();
    if (this.userDataDir) fs.rmSync(this.userDataDir, {recursive: true, force: true});
  }

  // Opens a viewer page; returns the page, the requests it made and the time until it was ready.
  async open(file) {
    const page = await this.context.newPage();
    const requests = [];
    const errors = [];
    page.on('request', (r) => requests.push(r.url()));
    page.on('pageerror', (e) => errors.push(e.message));
    const started = performance.now();
    await page.goto(`file://${file}`);
    await page.waitForFunction(() => window.hullViewer && (window.hullViewer.ready || window.hullViewer.error));
    const openMs = performance.now() - started;
    assert.equal(await page.evaluate(() => window.hullViewer.error), null);
    assert.deepEqual(errors, []);
    await settle(page);
    return {page, requests, errors, openMs};
  }
}

// Waits until the viewer has drawn what was asked (drawing happens on animation frames).
export async function settle(page) {
  await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
}
