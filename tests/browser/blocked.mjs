// A blocked fold's partial motion in the fold panel: issue 14's degree-4 vertex, fix face 3,
// drive crease 10 to -180° by clicks. The verdict is "blocked" with the stop explained (crease 9
// reaches -180° at drive -120.68°); the fold's slider runs over every state up to the stop, each
// equal to the frame `orikin fold -o` writes for it (the motion up to the stop) to 1e-9, and the
// readout counts the states as the verdict does ("state 6 of 6").
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { ORIKIN, OUT, SOURCE, assert, cli, clickEdge, clickFace, idle, run } from './harness.mjs';

const FILE = 'tests/data/kin-issue14-vertex.fold';
const ARGS = ['--fix', '3', '--drive', '10', '--to', '-180', '--step', '30'];

async function tool(page, name) {
  const on = await page.$eval(`[data-tool="${name}"]`, (b) => b.classList.contains('on'));
  if (!on) await page.click(`[data-tool="${name}"]`);
}

const tmp = fs.mkdtempSync(path.join(os.tmpdir(), 'orikin-blocked-'));
const out = path.join(tmp, 'partial.fold');
try { execFileSync(ORIKIN, ['fold', FILE, ...ARGS, '-o', out], { cwd: SOURCE, stdio: 'ignore' }); } catch (e) { /* exit 1: blocked */ }
const written = JSON.parse(fs.readFileSync(out, 'utf8'));

await run('blocked', FILE, async ({ page }) => {
  await tool(page, 'fix');
  await clickFace(page, 3);
  await tool(page, 'drive');
  await clickEdge(page, 10);
  await page.fill('#spec-to', '-180');
  await page.fill('#spec-step', '30');
  await tool(page, 'select');
  await page.click('#compute');
  await idle(page);
  const ref = cli(['fold', FILE, ...ARGS, '--json']);
  const fold = await page.evaluate(() => window.studio.fold());
  assert(JSON.stringify(fold) === JSON.stringify(ref), 'the page got exactly what orikin fold --json prints');
  assert(ref.verdict === 'blocked' && ref.frames.length === 6, `the CLI's fold is blocked after 6 states (${ref.verdict}, ${ref.frames.length})`);
  const verdict = await page.textContent('#verdict');
  assert(verdict.includes('blocked: 6 states up to the stop'), `the verdict counts the partial motion (${verdict})`);
  assert(verdict.includes('where crease 9 reaches -180'), `the stop is explained (${verdict})`);
  const max = await page.$eval('#fold-slider', (s) => ({ max: +s.max, disabled: s.disabled }));
  assert(max.max === 5 && !max.disabled, `the fold's slider runs over the 6 states (${JSON.stringify(max)})`);
  const frames = written.file_frames;
  assert(frames.length === 6 && written['orikin:partial'], `orikin fold -o wrote the 6 states up to the stop (${frames.length})`);
  await page.focus('#fold-slider');
  await page.keyboard.press('Home');
  let worst = 0;
  for (let k = 0; k < 6; k++) {
    if (k > 0) await page.keyboard.press('ArrowRight');
    await page.waitForTimeout(30);
    await idle(page);
    const text = await page.textContent('#state3d');
    assert(text.includes(`state ${k + 1} of 6`), `state ${k}: the readout counts as the verdict (${text})`);
    const pos = await page.evaluate(() => window.studio.positions());
    const want = frames[k].vertices_coords.flat();
    let d = 0;
    for (let i = 0; i < want.length; i++) d = Math.max(d, Math.abs(pos[i] - want[i]));
    worst = Math.max(worst, d);
    assert(d <= 1e-9, `state ${k} equals orikin fold -o's frame ${k} to 1e-9 (off by ${d})`);
  }
  const last = await page.textContent('#state3d');
  assert(last.includes('drive -120.68'), `the last state is the stop (${last})`);
  console.log(`blocked fold: 6 states up to the stop at drive -120.68 deg, max |page - orikin fold -o| = ${worst.toExponential(2)}`);
  await page.screenshot({ path: path.join(OUT, 'blocked.png') });
});
