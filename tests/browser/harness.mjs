// Shared set-up of the studio's browser tests: start `orikin view --port 0 --no-browser FILE`,
// read its URL line, drive Debian's chromium (headless, fresh profile) with playwright-core,
// collect console errors, run the CLI for reference answers, and measure screenshots.
//
// Environment: ORIKIN (the binary), ORIKIN_SOURCE_DIR (the repository), ORIKIN_OUT (a build
// directory for screenshots), ORIKIN_UPDATE_DOCS=1 (also write docs/images/studio.png),
// CHROMIUM (default /usr/bin/chromium). A test exits 77 (skipped) when node_modules or chromium
// is missing.
import { spawn, execFileSync } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

const here = path.dirname(fileURLToPath(import.meta.url));
export const SOURCE = process.env.ORIKIN_SOURCE_DIR || path.resolve(here, '../..');
export const ORIKIN = process.env.ORIKIN || path.join(SOURCE, 'build/orikin');
export const OUT = process.env.ORIKIN_OUT || path.join(SOURCE, 'build/browser');
const CHROMIUM = process.env.CHROMIUM || '/usr/bin/chromium';
export const SKIP = 77;

export function skip(why) {
  console.log(`SKIP: ${why}`);
  process.exit(SKIP);
}

// Thrown inside a test body: the test is skipped (exit 77) once the browser and the studio
// are closed.
export class Skip extends Error {}

export async function loadPlaywright() {
  const pw = path.join(SOURCE, 'node_modules/playwright-core/index.mjs');
  if (!fs.existsSync(pw)) skip('node_modules/playwright-core is missing (run make deps)');
  if (!fs.existsSync(CHROMIUM)) skip(`${CHROMIUM} is missing (Debian package chromium; run make deps)`);
  if (!fs.existsSync(ORIKIN)) skip(`${ORIKIN} is missing (build first)`);
  return import(pw);
}

// Start the studio on FILE (relative to the repository) and return {url, stop}. It prints its URL
// once the file is loaded (and a sequence run): startMs bounds that.
export function startStudio(file, startMs = 30000, autosave = false) {
  return new Promise((resolve, reject) => {
    // (no journal beside the repository's example files unless the test is about it)
    const args = ['view', '--port', '0', '--no-browser'];
    if (!autosave) args.push('--no-autosave');
    if (file) args.push(file);
    const proc = spawn(ORIKIN, args, { cwd: SOURCE, stdio: ['ignore', 'pipe', 'pipe'] });
    let out = '', err = '';
    const timer = setTimeout(() => {
      proc.kill('SIGKILL');
      reject(new Error(`orikin view printed no URL within ${startMs / 1000} s: ` + err));
    }, startMs);
    proc.stdout.on('data', (d) => {
      out += d;
      const m = /^orikin view: (http:\/\/\S+)$/m.exec(out);
      if (m) {
        clearTimeout(timer);
        resolve({
          url: m[1],
          proc,
          // Ctrl-C: the server stops cleanly, exit 0 (under the sanitizers: no leak, no error)
          stop: () => new Promise((r) => { proc.once('exit', (code, signal) => r({ code, signal, err })); proc.kill('SIGINT'); }),
        });
      }
    });
    proc.stderr.on('data', (d) => { err += d; });
    proc.on('exit', (code) => {
      clearTimeout(timer);
      if (/orikin view: http/.test(out)) return;
      if (code === 4 && /web assets were not built/.test(err)) skip('this orikin was built without node_modules: ' + err.trim());
      reject(new Error(`orikin view exited ${code}: ${err}`));
    });
  });
}

// Chromium as the CI runs it: headless, no sandbox, no GPU, no network side traffic, a fresh
// profile. Returns {page, errors, close}; errors collects console errors and page errors.
export async function openBrowser(pw, url, { viewport = { width: 1400, height: 900 }, allowErrors = [] } = {}) {
  const profile = fs.mkdtempSync(path.join(os.tmpdir(), 'orikin-chromium-'));
  const context = await pw.chromium.launchPersistentContext(profile, {
    executablePath: CHROMIUM,
    headless: true,
    viewport,
    acceptDownloads: true,
    args: ['--headless', '--no-sandbox', '--disable-gpu', '--disable-quic', '--disable-background-networking',
      '--disable-component-update', '--disable-sync', '--no-first-run'],
  });
  const page = context.pages()[0] || (await context.newPage());
  const errors = [];
  const allowed = (text) => allowErrors.some((re) => re.test(text));
  page.on('console', (m) => { if (m.type() === 'error' && !allowed(m.text())) errors.push('console: ' + m.text()); });
  page.on('pageerror', (e) => errors.push('page error: ' + e.message));
  await page.goto(url);
  await page.waitForFunction(() => window.studio && window.studio.ready === true, null, { timeout: 20000 });
  return {
    page,
    errors,
    close: async () => {
      await context.close();
      fs.rmSync(profile, { recursive: true, force: true });
    },
  };
}

// Wait until the page has no request in flight.
export async function idle(page) {
  await page.waitForFunction(() => window.studio.busy() === 0, null, { timeout: 30000 });
}

// Click a point of the sheet (sheet coordinates) in the 2D view, as a user does.
export async function clickSheet(page, x, y) {
  const [cx, cy] = await page.evaluate(([a, b]) => window.studio.clientOf(a, b), [x, y]);
  await page.mouse.click(cx, cy);
  await idle(page);
}

export async function clickFace(page, f) {
  const [cx, cy] = await page.evaluate((k) => window.studio.faceClient(k), f);
  await page.mouse.click(cx, cy);
  await idle(page);
}

export async function clickEdge(page, e) {
  const [cx, cy] = await page.evaluate((k) => window.studio.edgeClient(k), e);
  await page.mouse.click(cx, cy);
  await idle(page);
}

// The CLI's JSON answer.
export function cli(args) {
  try {
    return JSON.parse(execFileSync(ORIKIN, args, { cwd: SOURCE, encoding: 'utf8' }));
  } catch (e) {
    if (e.stdout) return JSON.parse(e.stdout);
    throw e;
  }
}

export function assert(cond, message) {
  if (!cond) throw new Error('assertion failed: ' + message);
}

// How much of an image is drawn: decode the PNG in the page (a 2D canvas), count the pixels
// that differ from the most common colour and the distinct colours.
export async function measurePng(page, png) {
  return page.evaluate(async (b64) => {
    const img = new Image();
    img.src = 'data:image/png;base64,' + b64;
    await img.decode();
    const c = document.createElement('canvas');
    c.width = img.width; c.height = img.height;
    const ctx = c.getContext('2d');
    ctx.drawImage(img, 0, 0);
    const d = ctx.getImageData(0, 0, c.width, c.height).data;
    const counts = new Map();
    for (let i = 0; i < d.length; i += 4) {
      const k = (d[i] << 16) | (d[i + 1] << 8) | d[i + 2];
      counts.set(k, (counts.get(k) || 0) + 1);
    }
    let top = 0;
    for (const v of counts.values()) top = Math.max(top, v);
    const n = d.length / 4;
    return { width: c.width, height: c.height, colors: counts.size, drawn: 1 - top / n };
  }, png.toString('base64'));
}

// Run a test body with the studio and a browser; report and exit.
export async function run(name, file, body, options = {}) {
  const pw = await loadPlaywright();
  fs.mkdirSync(OUT, { recursive: true });
  const studio = await startStudio(file, options.startMs, options.autosave);
  let browser = null;
  const t0 = Date.now();
  try {
    browser = await openBrowser(pw, studio.url, options);
    await body({ page: browser.page, errors: browser.errors, url: studio.url, pw });
    await idle(browser.page);
    assert(browser.errors.length === 0, 'console errors:\n  ' + browser.errors.join('\n  '));
    console.log(`PASS ${name} (${((Date.now() - t0) / 1000).toFixed(1)} s)`);
  } catch (e) {
    if (e instanceof Skip) {
      console.log(`SKIP: ${e.message}`);
      process.exitCode = SKIP;
      return;
    }
    if (browser) {
      try {
        await browser.page.screenshot({ path: path.join(OUT, `${name}-failure.png`) });
        const msgs = await browser.page.$$eval('#messages .msg', (els) => els.slice(0, 5).map((e) => e.textContent));
        if (msgs.length) console.error('the page said:\n  ' + msgs.join('\n  '));
      } catch (x) { /* ignore */ }
    }
    console.error(`FAIL ${name}: ${e.stack || e.message}`);
    process.exitCode = 1;
  } finally {
    if (browser) await browser.close();
    const end = await studio.stop();
    if (end.code !== 0) {
      console.error(`FAIL ${name}: orikin view ended with ${end.code !== null ? 'exit ' + end.code : end.signal}:\n${end.err.slice(-3000)}`);
      process.exitCode = 1;
    }
  }
}
