// The replay page in a real headless Chromium (Debian's /usr/bin/chromium, software WebGL),
// driven by playwright-core: `node test/replay_test.mjs cc8|pr2 [--keep-screenshots DIR]`.
// Runs a short scenario report, starts `mechsim view` on it, loads the page and checks: no console
// errors, the robot is drawn (pixels differ with it hidden), it moves between two times (pixels
// of two screenshots differ; the same time twice gives the same pixels), dragging the time slider
// moves it, the plot cursor follows the time; then the command line's bad-input errors (a report
// from another format version, a busy port) and the page's message for a report rewritten under
// a running server; and the exported self-contained page, opened from disk.
// Exit 77 (CTest: skipped) when Chromium, node_modules or the built page are missing.
import { spawn, spawnSync } from 'node:child_process';
import { existsSync, mkdtempSync, readFileSync, rmSync, writeFileSync, copyFileSync, mkdirSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';

const here = dirname(fileURLToPath(import.meta.url));
const web = dirname(here);
const chromiumPath = process.env.MECHSIM_CHROMIUM ?? '/usr/bin/chromium';
const exe = process.env.MECHSIM_EXE;
const source = process.env.MECHSIM_SOURCE_DIR ?? dirname(web);
const pageDir = process.env.MECHSIM_PAGE_DIR;
const which = process.argv[2];
const keepIndex = process.argv.indexOf('--keep-screenshots');
const keepDir = keepIndex > 0 ? process.argv[keepIndex + 1] : null;

function skip(why) {
  console.log(`replay_test: skipped: ${why}`);
  process.exit(77);
}
if (!['cc8', 'pr2'].includes(which)) {
  console.error('usage: node test/replay_test.mjs cc8|pr2 [--keep-screenshots DIR]');
  process.exit(2);
}
if (!exe || !pageDir) {
  console.error('replay_test: MECHSIM_EXE and MECHSIM_PAGE_DIR must be set (CTest sets them)');
  process.exit(2);
}
if (!existsSync(chromiumPath)) skip(`no Chromium at ${chromiumPath} (scripts/install-deps.sh installs Debian's chromium)`);
if (!existsSync(join(web, 'node_modules', 'playwright-core'))) skip(`no ${join(web, 'node_modules')} (run npm ci in web/ or scripts/install-deps.sh)`);
if (!existsSync(join(pageDir, 'app.js'))) skip(`the page is not built (${join(pageDir, 'app.js')} missing)`);
const { chromium } = await import('playwright-core');

const scenarios = {
  cc8: { file: 'robots/cc8/scenarios/mars_yard_route.yaml', duration: '4', times: [0.0, 3.9] },
  pr2: { file: 'robots/pr2/scenarios/arm_trajectory.yaml', duration: '3', times: [0.0, 2.9] },
};
const scenario = scenarios[which];
const work = mkdtempSync(join(tmpdir(), `mechsim_replay_test_${which}_`));
const started = [];
let browser = null;
let failures = 0;

const t0 = Date.now();
function check(ok, what) {
  console.log(`${ok ? 'ok  ' : 'FAIL'} [${((Date.now() - t0) / 1000).toFixed(1)} s] ${what}`);
  if (!ok) failures++;
}

function run(args, timeout = 60000) {
  const r = spawnSync(exe, args, { encoding: 'utf8', timeout });
  return r;
}

// Starts `mechsim view` and resolves with its address (or rejects with its error output).
function startView(report, port = '0') {
  return new Promise((resolve, reject) => {
    const child = spawn(exe, ['view', report, '--port', port, '--page-dir', pageDir], { stdio: ['ignore', 'pipe', 'pipe'] });
    started.push(child);
    let out = '';
    let err = '';
    const timer = setTimeout(() => reject(new Error(`mechsim view printed no address in 10 s: ${out}${err}`)), 10000);
    child.stdout.on('data', (d) => {
      out += d;
      const m = out.match(/http:\/\/127\.0\.0\.1:(\d+)\//);
      if (m) {
        clearTimeout(timer);
        resolve({ child, url: m[0], port: m[1] });
      }
    });
    child.stderr.on('data', (d) => { err += d; });
    child.on('exit', (code) => {
      clearTimeout(timer);
      reject(new Error(`mechsim view exited with ${code}: ${err}`));
    });
  });
}

// Screenshot pixels, decoded by the browser: grey levels on a 1/4 grid.
async function pixels(page, png) {
  return page.evaluate(async (b64) => {
    const img = new Image();
    img.src = `data:image/png;base64,${b64}`;
    await img.decode();
    const w = Math.floor(img.width / 4);
    const h = Math.floor(img.height / 4);
    const canvas = document.createElement('canvas');
    canvas.width = w;
    canvas.height = h;
    const ctx = canvas.getContext('2d');
    ctx.drawImage(img, 0, 0, w, h);
    const data = ctx.getImageData(0, 0, w, h).data;
    const grey = [];
    for (let i = 0; i < data.length; i += 4) grey.push((data[i] + data[i + 1] + data[i + 2]) / 3);
    return grey;
  }, png.toString('base64'));
}

function changed(a, b) {
  let n = 0;
  for (let i = 0; i < a.length; i++) if (Math.abs(a[i] - b[i]) > 24) n++;
  return n / a.length;
}

async function openPage(url, errors) {
  const page = await browser.newPage();
  page.on('console', (m) => { if (m.type() === 'error') errors.push(m.text()); });
  page.on('pageerror', (e) => errors.push(String(e)));
  await page.goto(url);
  await page.waitForFunction(() => window.mechsimReplay && (window.mechsimReplay.ready || window.mechsimReplay.error),
    null, { timeout: 40000 });
  return page;
}

async function shot(page, name) {
  const png = await page.locator('#view').screenshot();
  if (keepDir) {
    mkdirSync(keepDir, { recursive: true });
    writeFileSync(join(keepDir, `${which}_${name}.png`), png);
  }
  return png;
}

try {
  const report = join(work, 'report');
  const r = run(['run', join(source, scenario.file), '--duration', scenario.duration, '-o', report]);
  check(existsSync(join(report, 'replay', 'manifest.json')), `mechsim run ${scenario.file} --duration ${scenario.duration} wrote replay/ (status ${r.status})`);
  if (!existsSync(join(report, 'replay', 'manifest.json'))) throw new Error(`mechsim run failed: ${r.stderr}`);

  const view = await startView(report);
  // A fresh profile (--user-data-dir) in the test's folder.
  browser = await chromium.launchPersistentContext(join(work, 'chromium-profile'), {
    executablePath: chromiumPath,
    headless: true,
    viewport: { width: 1280, height: 720 },
    args: ['--headless', '--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run', '--disable-background-networking',
      '--disable-component-update', '--disable-sync'],
  });
  const errors = [];
  const page = await openPage(`${view.url}?follow=0`, errors);
  const state = await page.evaluate(() => ({ ready: window.mechsimReplay.ready, error: window.mechsimReplay.error, duration: window.mechsimReplay.duration }));
  check(state.ready && !state.error, `the page loaded the replay (${state.error ?? `${state.duration?.toFixed(2)} s`})`);

  const [ta, tb] = scenario.times;
  await page.evaluate((t) => window.mechsimReplay.setTime(t), ta);
  const a = await pixels(page, await shot(page, 'start'));
  const a2 = await pixels(page, await shot(page, 'start_again'));
  await page.evaluate(() => window.mechsimReplay.setRobotVisible(false));
  const empty = await pixels(page, await shot(page, 'no_robot'));
  await page.evaluate(() => window.mechsimReplay.setRobotVisible(true));
  const robotShare = changed(a, empty);
  check(robotShare > 0.005, `the robot is drawn: ${(100 * robotShare).toFixed(2)} % of the view changes when it is hidden`);
  check(changed(a, a2) < 0.001, `the same time gives the same picture (${(100 * changed(a, a2)).toFixed(3)} % differ)`);
  await page.evaluate((t) => window.mechsimReplay.setTime(t), tb);
  const b = await pixels(page, await shot(page, 'end'));
  const moved = changed(a, b);
  check(moved > 0.003, `the robot moved between t=${ta} s and t=${tb} s: ${(100 * moved).toFixed(2)} % of the view differs`);
  const cursorAt = () => page.evaluate(() => [...document.querySelectorAll('.cursor')].filter((c) => c.style.display !== 'none').map((c) => parseFloat(c.style.left)));
  const cursorsEnd = await cursorAt();

  // Drag the slider (a real mouse press on the range input) back to the start.
  await page.evaluate((t) => window.mechsimReplay.setTime(t), tb);
  const box = await page.locator('#time').boundingBox();
  await page.mouse.click(box.x + 3, box.y + box.height / 2);
  const tSlid = await page.evaluate(() => window.mechsimReplay.time());
  const c = await pixels(page, await shot(page, 'slider'));
  check(tSlid < 0.3 * tb, `clicking the slider's start moved the time to ${tSlid.toFixed(2)} s`);
  check(changed(b, c) > 0.003, `the slider moved the robot: ${(100 * changed(b, c)).toFixed(2)} % of the view differs`);
  const cursorsStart = await cursorAt();
  check(cursorsEnd.length > 0 && cursorsStart.length > 0 && cursorsStart[0] < cursorsEnd[0],
    `the plots' time cursor follows the time (${cursorsStart[0]?.toFixed(1)} % -> ${cursorsEnd[0]?.toFixed(1)} % of the plot width)`);
  await page.screenshot({ path: join(work, 'page.png') });
  if (keepDir) copyFileSync(join(work, 'page.png'), join(keepDir, `${which}_page.png`));
  check(errors.length === 0, `no console errors${errors.length ? `: ${errors.join(' | ')}` : ''}`);

  // Bad input on the command line: a busy port, a report from another format version.
  const busy = run(['view', report, '--port', view.port, '--page-dir', pageDir], 10000);
  check(busy.status !== 0 && /port \d+ on 127\.0\.0\.1 is in use/.test(busy.stderr), `a second view on port ${view.port}: ${busy.stderr.trim()}`);
  const manifestFile = join(report, 'replay', 'manifest.json');
  const manifest = readFileSync(manifestFile, 'utf8');
  writeFileSync(manifestFile, manifest.replace('"version": 1', '"version": 2'));
  const old = run(['view', report, '--port', '0', '--page-dir', pageDir], 10000);
  check(old.status !== 0 && /replay format version 2, this mechsim reads version 1/.test(old.stderr), `another format version: ${old.stderr.trim()}`);
  // ... and in the page, for a report changed under the running server.
  const badErrors = [];
  const bad = await openPage(view.url, badErrors);
  const shown = await bad.evaluate(() => document.getElementById('error').hidden ? '' : document.getElementById('error').textContent);
  check(/version 2/.test(shown), `the page says: ${shown}`);
  writeFileSync(manifestFile, manifest);
  await bad.close();

  // The exported page, from disk, with the server stopped.
  view.child.kill('SIGTERM');
  const exported = join(work, 'replay.html');
  const ex = run(['view', report, '--export', exported, '--page-dir', pageDir], 30000);
  check(ex.status === 0 && existsSync(exported), `--export wrote one file (${ex.stdout.trim()})`);
  const exErrors = [];
  const offline = await openPage(`file://${exported}?follow=0`, exErrors);
  await offline.evaluate((t) => window.mechsimReplay.setTime(t), tb);
  const ok = await offline.evaluate(() => window.mechsimReplay.ready && !window.mechsimReplay.error);
  const e = await pixels(offline, await offline.locator('#view').screenshot());
  check(ok && exErrors.length === 0, `the exported page plays from disk without errors${exErrors.length ? `: ${exErrors.join(' | ')}` : ''}`);
  check(changed(b, e) < 0.01, `the exported page shows what the served one did at t=${tb} s (${(100 * changed(b, e)).toFixed(2)} % differ)`);
} catch (e) {
  console.log(`FAIL ${e.stack ?? e}`);
  failures++;
} finally {
  if (browser) await browser.close();
  for (const child of started) if (child.exitCode === null) child.kill('SIGTERM');
  rmSync(work, { recursive: true, force: true });
}
console.log(failures ? `replay_test ${which}: ${failures} failure(s)` : `replay_test ${which}: all passed`);
process.exit(failures ? 1 : 0);
