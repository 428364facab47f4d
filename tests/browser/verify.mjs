// Rounded drawings in the browser, on tests/data/rounded-miura.fold (a Miura-ori drawn with
// rounded coordinates): the check fails with the rounding hint; a tolerance marks the vertices
// within it (as `orikin check --tolerance`); regularize replaces the document by exactly what
// `orikin regularize -o` writes, reports the displacement, and undo restores the drawing; the
// crease view exported as PNG is byte for byte `orikin render`'s.
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { ORIKIN, SOURCE, assert, cli, idle, run } from './harness.mjs';

const FILE = 'tests/data/rounded-miura.fold';

async function exportMenu(page, value) {
  const [dl] = await Promise.all([page.waitForEvent('download'), page.selectOption('#export-format', value)]);
  const p = await dl.path();
  await idle(page);
  return { name: dl.suggestedFilename(), bytes: fs.readFileSync(p) };
}

const tmp = fs.mkdtempSync(path.join(os.tmpdir(), 'orikin-verify-'));

await run('verify', FILE, async ({ page }) => {
  await idle(page);
  // the exact check fails; the hint says the drawing looks rounded
  let c = await page.evaluate(() => window.studio.check());
  const ref = cli(['check', FILE, '--json']);
  assert(JSON.stringify(c) === JSON.stringify(ref), 'the page got exactly what orikin check --json prints');
  assert(!c.locally_flat_foldable && c.hint && c.hint.includes('regularize'), 'the exact check fails with the hint');
  assert((await page.textContent('#check-summary')).includes('the drawing looks rounded'), 'the hint is shown');
  const bad = await page.$$eval('#cp .bad-vertex', (els) => els.length);
  assert(bad === c.failed_vertices && bad > 0, `the failing vertices are marked (${bad})`);

  // a tolerance: the vertices within it are marked, with their deviation on hover
  await page.fill('#check-tolerance', '0.05');
  await page.press('#check-tolerance', 'Enter');
  await idle(page);
  c = await page.evaluate(() => window.studio.check());
  const tolRef = cli(['check', FILE, '--tolerance', '0.05', '--json']);
  assert(JSON.stringify(c) === JSON.stringify(tolRef), 'with the tolerance: orikin check --tolerance 0.05 --json');
  const within = await page.$$eval('#cp .within-vertex', (els) => els.map((e) => +e.dataset.badVertex));
  const withinRef = tolRef.vertices.filter((v) => v.within_tolerance).map((v) => v.vertex);
  assert(JSON.stringify(within) === JSON.stringify(withinRef) && within.length === 5, 'the vertices within tolerance are marked: ' + within);
  assert((await page.$$eval('#cp .bad-vertex', (els) => els.length)) === 0, 'none fails within 0.05 deg');
  // (with a tool that picks no vertices, the mark under the pointer answers)
  await page.click('[data-tool="fix"]');
  const [vx, vy] = await page.evaluate((v) => window.studio.vertexClient(v), within[0]);
  await page.mouse.move(vx + 2, vy + 2);
  const tip = await page.textContent('#tooltip');
  await page.click('[data-tool="fix"]');
  assert(tip.includes('within tolerance') && tip.includes('°'), 'hovering tells the deviation: ' + tip);
  assert((await page.textContent('#check-summary')).includes('5 within 0.05°'), 'the summary counts them');
  await page.fill('#check-tolerance', '');
  await page.press('#check-tolerance', 'Enter');
  await idle(page);

  // the crease view as a PNG picture: what orikin render draws
  const png = await exportMenu(page, 'png');
  const pngRef = path.join(tmp, 'ref.png');
  execFileSync(ORIKIN, ['render', FILE, '-o', pngRef], { cwd: SOURCE });
  assert(Buffer.compare(png.bytes, fs.readFileSync(pngRef)) === 0, 'the crease view is orikin render\'s PNG');

  // regularize: the document becomes what orikin regularize -o writes
  const before = await page.evaluate(() => window.studio.positions());
  const version = await page.evaluate(() => window.studio.version());
  await page.click('#regularize');
  await idle(page);
  const r = await page.evaluate(() => window.studio.regularizeResult());
  const rRef = cli(['regularize', FILE, '--json']);
  for (const k of Object.keys(rRef)) assert(JSON.stringify(r[k]) === JSON.stringify(rRef[k]), `regularize's ${k} is the CLI's`);
  assert(r.replaced && (await page.evaluate(() => window.studio.version())) > version, 'the document was replaced');
  const summary = await page.textContent('#regularize-summary');
  assert(summary.includes(`vertex ${rRef.max_move_vertex}`) && summary.includes('of the sheet'), 'the displacement is reported: ' + summary);
  const out = path.join(tmp, 'exact.fold');
  execFileSync(ORIKIN, ['regularize', FILE, '-o', out], { cwd: SOURCE });
  const fold = await exportMenu(page, 'fold');
  const mine = JSON.parse(fold.bytes.toString('utf8')), theirs = JSON.parse(fs.readFileSync(out, 'utf8'));
  assert(JSON.stringify(mine.vertices_coords) === JSON.stringify(theirs.vertices_coords), 'the vertices are orikin regularize\'s');
  c = await page.evaluate(() => window.studio.check());
  assert(c.locally_flat_foldable && c.hint === null, 'the regularized pattern checks exactly');
  assert((await page.$$eval('#cp .bad-vertex, #cp .within-vertex', (els) => els.length)) === 0, 'no vertex is marked any more');

  // undo restores the drawing
  await page.click('#undo');
  await idle(page);
  const undone = await page.evaluate(() => window.studio.positions());
  assert(JSON.stringify(undone) === JSON.stringify(before), 'undo restores the drawing exactly');

  // the rigid variant too
  await page.check('#regularize-rigid');
  await page.click('#regularize');
  await idle(page);
  const rr = await page.evaluate(() => window.studio.regularizeResult());
  const rrRef = cli(['regularize', FILE, '--rigid', '--json']);
  assert(rr.replaced && rr.rigid && rr.rigid_after === rrRef.rigid_after && rr.max_move_rel === rrRef.max_move_rel,
    'regularize --rigid as the CLI');
});
fs.rmSync(tmp, { recursive: true, force: true });
