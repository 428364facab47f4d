// Specifying and computing a fold by clicks (thesis ch. 9.4): fix face 4 (the bone structure is
// drawn), drive crease 12, lock crease 11, compute: valid, Frame A / Frame B / surrounding
// coloured, the 3D state equal to what `orikin fold -o` writes; two folds added to the folding
// manager make the open corner's sequence. Then the wrongly oriented pattern, dropped onto the
// page: its invalid creases are highlighted with the reason.
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { ORIKIN, OUT, SOURCE, assert, cli, clickEdge, clickFace, idle, run } from './harness.mjs';

const CORNER = 'examples/patterns/open-corner.fold';

function maxDiff(a, b) {
  let m = 0;
  for (let i = 0; i < a.length; i++) m = Math.max(m, Math.abs(a[i] - b[i]));
  return m;
}

async function tool(page, name) {
  const on = await page.$eval(`[data-tool="${name}"]`, (b) => b.classList.contains('on'));
  if (!on) await page.click(`[data-tool="${name}"]`);
}

async function specify(page, { fix, drive, locks, to, step }) {
  await page.click('#clear-spec');
  await tool(page, 'fix');
  await clickFace(page, fix);
  await tool(page, 'drive');
  await clickEdge(page, drive);
  await tool(page, 'lock');
  for (const e of locks) await clickEdge(page, e);
  await page.fill('#spec-to', String(to));
  await page.fill('#spec-step', String(step));
  await tool(page, 'select');
}

// Drop a file onto the page as a user does (a DataTransfer with the file).
async function drop(page, name, text) {
  await page.evaluate(([n, t]) => {
    const dt = new DataTransfer();
    dt.items.add(new File([t], n));
    window.dispatchEvent(new DragEvent('drop', { dataTransfer: dt, bubbles: true, cancelable: true }));
  }, [name, text]);
  await page.waitForTimeout(50);
  await idle(page);
}

const tmp = fs.mkdtempSync(path.join(os.tmpdir(), 'orikin-fold-'));
const wrong = path.join(tmp, 'wrong.fold');
execFileSync(ORIKIN, ['edit', CORNER, '--flip', '@0.5,0.5', '-o', wrong], { cwd: SOURCE });
const folded = path.join(tmp, 'folded.fold');
try { execFileSync(ORIKIN, ['fold', CORNER, '--fix', '4', '--drive', '12', '--lock', '11', '--to', '90', '--step', '10', '-o', folded], { cwd: SOURCE }); } catch (e) { /* exit 0 expected */ }

await run('fold', CORNER, async ({ page }) => {
  await specify(page, { fix: 4, drive: 12, locks: [11], to: 90, step: 10 });
  const spec = await page.evaluate(() => window.studio.spec());
  assert(spec.fix === 4 && spec.drive === 12 && spec.locks.length === 1 && spec.locks[0] === 11, 'fix 4, drive 12, lock 11 by clicks: ' + JSON.stringify(spec));
  const bones = await page.$$eval('#cp .bone', (els) => els.length);
  assert(bones === 10, `the bone structure is drawn when a face is fixed (${bones} bones)`);
  assert(await page.$eval('#tree .node.fixed', (e) => e.dataset.face) === '4', 'the tree marks the fixed face');

  await page.click('#compute');
  await idle(page);
  const verdict = await page.$eval('#verdict .valid', (e) => e.dataset.verdict);
  assert(verdict === 'valid', 'the verdict is shown: valid');
  const ref = cli(['fold', CORNER, '--fix', '4', '--drive', '12', '--lock', '11', '--to', '90', '--step', '10', '--json']);
  const fold = await page.evaluate(() => window.studio.fold());
  assert(JSON.stringify(fold) === JSON.stringify(ref), 'the page got exactly what orikin fold --json prints');
  const split = await page.evaluate(() => ({
    a: [...document.querySelectorAll('#cp .halo.frame-a')].map((e) => +e.dataset.halo),
    b: [...document.querySelectorAll('#cp .halo.frame-b')].map((e) => +e.dataset.halo),
    s: [...document.querySelectorAll('#cp .halo.surround')].map((e) => +e.dataset.halo),
  }));
  assert(JSON.stringify(split.a) === JSON.stringify(ref.frame_a) && JSON.stringify(split.b) === JSON.stringify(ref.frame_b) &&
    JSON.stringify(split.s) === JSON.stringify(ref.surrounding), 'Frame A, Frame B and the surrounding are coloured: ' + JSON.stringify(split));
  assert((await page.textContent('#split')).includes('Frame A 12, 6'), 'the split is named');
  // the 3D view shows the last state: what orikin fold -o writes as the last frame
  const doc = JSON.parse(fs.readFileSync(folded, 'utf8'));
  const last = doc.file_frames[doc.file_frames.length - 1].vertices_coords.flat();
  const pos = await page.evaluate(() => window.studio.positions());
  const d = maxDiff(pos, last);
  console.log(`fold at 90 deg: max |page - orikin fold -o| = ${d.toExponential(2)}`);
  assert(d <= 1e-9, `the 3D state is the CLI's to 1e-9 (off by ${d})`);
  const dof = await page.$eval('#dof-summary', (e) => e.dataset.dof);
  assert(dof === '2', `the DOF with crease 11 locked is shown (${dof})`);
  // the fold's states on its own slider
  await page.evaluate(() => { const s = document.getElementById('fold-slider'); s.value = '3'; s.dispatchEvent(new Event('input')); });
  await idle(page);
  assert((await page.textContent('#state3d')).includes('drive 30'), 'the fold slider shows state 3 (30 deg)');

  // the folding manager: fold 1 to 180, then fold 2 from where it ends
  await specify(page, { fix: 4, drive: 12, locks: [11], to: 180, step: 10 });
  await page.click('#add-fold');
  await idle(page);
  await specify(page, { fix: 4, drive: 11, locks: [12], to: 90, step: 10 });
  await page.click('#compute');
  await idle(page);
  assert(await page.$eval('#verdict .valid', (e) => e.dataset.verdict) === 'valid', 'fold 2 from the end of fold 1 is valid');
  await page.click('#add-fold');
  await idle(page);
  assert(await page.$$eval('#folds li', (els) => els.length) === 2, 'two folds in the manager');
  await page.evaluate(() => {
    const s = document.getElementById('t-slider');
    s.value = String(Math.round(1.5 * (+s.max) / 2));
    s.dispatchEvent(new Event('input', { bubbles: true }));
  });
  await idle(page);
  const seqPos = await page.evaluate(() => window.studio.positions());
  const seqRef = cli(['sequence', 'examples/open-corner.seq.json', '--at', '1.5', '--json']).vertices_coords.flat();
  const ds = maxDiff(seqPos, seqRef);
  assert(ds <= 1e-9, `the sequence built by clicks restores T = 1.5 as orikin sequence --at 1.5 (off by ${ds})`);

  // the wrongly oriented pattern (the diagonal flipped), dropped onto the page
  await drop(page, 'wrong.fold', fs.readFileSync(wrong, 'utf8'));
  assert((await page.textContent('#file-name')) === 'wrong.fold', 'the dropped file is open');
  await specify(page, { fix: 4, drive: 12, locks: [11], to: -90, step: 30 });
  await page.click('#compute');
  await idle(page);
  const bad = await page.$eval('#verdict .invalid', (e) => e.dataset.verdict);
  assert(bad === 'invalid assignment', 'the verdict: invalid assignment');
  const offending = await page.$$eval('#cp .halo.offending', (els) => els.map((e) => +e.dataset.halo).sort((a, b) => a - b));
  assert(JSON.stringify(offending) === '[6,8,9]', 'the offending creases are highlighted: ' + JSON.stringify(offending));
  const labels = await page.$$eval('#cp .labels text', (els) => els.map((e) => e.textContent));
  assert(labels.some((t) => t.startsWith('6: M')), 'crease 6 is labelled: ' + labels.join(' | '));
  assert((await page.textContent('#verdict')).includes('crease 6 (assigned mountain) would fold to 35.26438968°'), 'the reason is shown');
  const [cx, cy] = await page.evaluate(() => window.studio.edgeClient(6));
  await page.mouse.move(cx, cy);
  const tip = await page.textContent('#tooltip');
  assert(tip.includes('crease 6') && tip.includes('against its assignment'), 'hovering the crease tells why: ' + tip);
  await page.screenshot({ path: path.join(OUT, 'studio-invalid-fold.png') });
});
fs.rmSync(tmp, { recursive: true, force: true });
