// Performance of the studio on a 100 × 100 Miura-ori sequence (10,201 vertices, 20,200 edges):
// how fast GET /api/sequence/at answers (on the scrubbing grid and off it, JSON and binary) and
// how many states per second the page shows while the slider is dragged in headless Chromium.
// The figures are printed (targets: under 20 ms, at least 30 states per second); only errors fail.
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { ORIKIN, SOURCE, assert, idle, run } from './harness.mjs';

const N = 100;
const tmp = fs.mkdtempSync(path.join(os.tmpdir(), 'orikin-perf-'));
const pattern = path.join(tmp, 'miura.fold');
execFileSync(ORIKIN, ['generate', 'miura', '--rows', String(N), '--cols', String(N), '-o', pattern], { cwd: SOURCE });
const fold = JSON.parse(fs.readFileSync(pattern, 'utf8'));
// the middle zig-zag crease, as bench/bench_miura.c drives it, and a face at its foot
const a = (N / 2) * (N + 1) + N / 2, b = (N / 2 + 1) * (N + 1) + N / 2;
const drive = fold.edges_vertices.findIndex(([u, v]) => (u === a && v === b) || (u === b && v === a));
const fix = fold.faces_vertices.findIndex((f) => f.includes(a));
const sign = fold.edges_assignment[drive] === 'V' ? 1 : -1;
const seq = path.join(tmp, 'miura.seq.json');
fs.writeFileSync(seq, JSON.stringify({ pattern: 'miura.fold', folds: [{ fix, drive, to: sign * 90, step: 10 }] }));

function stats(ms) {
  const s = [...ms].sort((x, y) => x - y);
  return `median ${s[Math.floor(s.length / 2)].toFixed(1)} ms, max ${s[s.length - 1].toFixed(1)} ms over ${s.length}`;
}

const t0 = Date.now();
await run('perf', seq, async ({ page, url }) => {
  console.log(`studio on a ${N}x${N} Miura-ori sequence ready in ${((Date.now() - t0) / 1000).toFixed(1)} s (run, scrubbing cache, page)`);
  const u = new URL(url);
  const token = u.searchParams.get('token');
  const session = await (await fetch(new URL('/api/session', u), { headers: { 'X-Orikin-Token': token } })).json();
  const grid = session.sequence.grid;
  assert(grid > 0, 'the scrubbing cache exists');
  const get = async (q, binary) => {
    const t = performance.now();
    const r = await fetch(new URL(`/api/sequence/at?${q}${binary ? '&binary=1' : ''}`, u), { headers: { 'X-Orikin-Token': token } });
    assert(r.ok, 'status ' + r.status);
    const body = binary ? await r.arrayBuffer() : await r.json();
    return [performance.now() - t, body];
  };
  const on = [], onBin = [], off = [];
  for (let i = 0; i < 40; i++) {
    const k = (i * 7919) % grid;
    on.push((await get(`t=${k / grid}`, false))[0]);
    onBin.push((await get(`t=${k / grid}`, true))[0]);
  }
  for (let i = 0; i < 5; i++) off.push((await get(`t=${(i + 0.5) / 5 + 1e-7}`, false))[0]);
  const [, state] = await get('t=0.5', false);
  assert(state.vertices_coords.length === (N + 1) * (N + 1), 'every vertex');
  console.log(`GET /api/sequence/at (${grid} cached states per fold): JSON ${stats(on)}; binary ${stats(onBin)}; ` +
    `off the grid (an exact restore) ${stats(off)}`);

  // drag the slider for two seconds: one step per animation frame
  await idle(page);
  const r = await page.evaluate(async () => {
    const s = document.getElementById('t-slider');
    const max = +s.max;
    const before = window.studio.stats();
    const t0 = performance.now();
    let k = 0, moves = 0;
    await new Promise((done) => {
      const tick = () => {
        if (performance.now() - t0 > 2000) { done(); return; }
        k = (k + 3) % (max + 1);
        s.value = String(k);
        s.dispatchEvent(new Event('input', { bubbles: true }));
        moves++;
        requestAnimationFrame(tick);
      };
      requestAnimationFrame(tick);
    });
    const dt = (performance.now() - t0) / 1000;
    const after = window.studio.stats();
    return { moves, dt, states: after.states - before.states, drawn: after.framesDrawn - before.framesDrawn, latency: after.latencyMs };
  });
  await idle(page);
  console.log(`scrubbing in headless Chromium: ${(r.states / r.dt).toFixed(1)} states/s shown (${(r.drawn / r.dt).toFixed(1)} frames/s ` +
    `drawn, ${(r.moves / r.dt).toFixed(0)} slider moves/s, mean request ${r.latency.toFixed(1)} ms)`);
  assert(r.states > 0, 'states were shown while scrubbing');

  // a computation shows what runs while it runs (after a second; here at once)
  await page.evaluate(() => {
    window.studio.setProgressDelay(0);
    window.progressSeen = [];
    new MutationObserver(() => {
      const p = document.getElementById('progress');
      if (!p.hidden) window.progressSeen.push(document.getElementById('progress-text').textContent);
    }).observe(document.getElementById('progress'), { attributes: true, childList: true, subtree: true });
  });
  await page.click('[data-tool="fix"]');
  const [fx, fy] = await page.evaluate((f) => window.studio.faceClient(f), fix);
  await page.mouse.click(fx, fy);
  await page.click('[data-tool="drive"]');
  const [dx, dy] = await page.evaluate((e) => window.studio.edgeClient(e), drive);
  await page.mouse.click(dx, dy);
  await page.fill('#spec-step', '30');
  await page.click('#compute');
  await idle(page);
  const seen = await page.evaluate(() => window.progressSeen);
  assert(seen.some((t) => t.startsWith('fold')), 'the progress box named the running fold: ' + JSON.stringify(seen));
  assert(await page.$eval('#progress', (e) => e.hidden), 'and went away');
  assert(await page.$eval('#verdict .valid', (e) => e.dataset.verdict) === 'valid', 'the Miura-ori folds');
}, { startMs: 240000 });
fs.rmSync(tmp, { recursive: true, force: true });
