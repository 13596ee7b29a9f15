// A picture of the replay page for the documentation: `node web/test/screenshot.mjs REPORT OUT.png
// [--t SECONDS] [--zoom F] [--follow 0|1]`, with `mechsim view` (MECHSIM_EXE, default
// build/release/bin/mechsim; page from MECHSIM_PAGE_DIR, default build/release/web) and Debian's
// headless Chromium.
import { spawn } from 'node:child_process';
import { mkdtempSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { dirname, join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import { chromium } from 'playwright-core';

const root = dirname(dirname(dirname(fileURLToPath(import.meta.url))));
const [report, out] = process.argv.slice(2);
const option = (name, fallback) => {
  const i = process.argv.indexOf(`--${name}`);
  return i > 0 ? process.argv[i + 1] : fallback;
};
if (!report || !out) {
  console.error('usage: node web/test/screenshot.mjs REPORT OUT.png [--t SECONDS] [--zoom F] [--follow 0|1]');
  process.exit(2);
}
const exe = process.env.MECHSIM_EXE ?? join(root, 'build/release/bin/mechsim');
const pageDir = process.env.MECHSIM_PAGE_DIR ?? join(root, 'build/release/web');
const view = spawn(exe, ['view', report, '--port', '0', '--page-dir', pageDir], { stdio: ['ignore', 'pipe', 'inherit'] });
const url = await new Promise((ok, fail) => {
  let text = '';
  view.stdout.on('data', (d) => {
    text += d;
    const m = text.match(/http:\/\/127\.0\.0\.1:\d+\//);
    if (m) ok(m[0]);
  });
  view.on('exit', (code) => fail(new Error(`mechsim view exited with ${code}`)));
});
const profile = mkdtempSync(join(tmpdir(), 'mechsim_screenshot_'));
const context = await chromium.launchPersistentContext(profile, {
  executablePath: '/usr/bin/chromium', headless: true, viewport: { width: 1280, height: 720 },
  args: ['--headless', '--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run', '--disable-background-networking',
    '--disable-component-update', '--disable-sync'],
});
try {
  const page = await context.newPage();
  await page.goto(`${url}?follow=${option('follow', '1')}&zoom=${option('zoom', '1')}`);
  await page.waitForFunction(() => window.mechsimReplay?.ready || window.mechsimReplay?.error, null, { timeout: 60000 });
  // Step through the run to the time, as a viewer dragging the slider would (the follow camera
  // moves with the robot).
  const t = Number(option('t', '0'));
  for (let k = 1; k <= 20; k++) await page.evaluate((s) => window.mechsimReplay.setTime(s), (t * k) / 20);
  await page.screenshot({ path: resolve(out) });
  console.log(`wrote ${out}`);
} finally {
  await context.close();
  view.kill('SIGTERM');
  rmSync(profile, { recursive: true, force: true });
}
