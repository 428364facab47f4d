// Opening files as a user does: an SVG (typed image/svg+xml by browsers) and an OPX, each through
// the Open… dialog (a real file input) and by a drop on the page, become the document (never a
// texture); the page's model equals `orikin info` of the file (vertices, edges, faces); the 3D
// view is fitted to the new sheet (every vertex on screen, the sheet filling a good part of the
// view); a hand-written sequence shows no "undefined"; New clears the old document's errors;
// the export menu lists glTF once until there is a motion.
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { ORIKIN, OUT, SOURCE, assert, cli, idle, run } from './harness.mjs';

const tmp = fs.mkdtempSync(path.join(os.tmpdir(), 'orikin-open-'));
const files = {
  svg: path.join(tmp, 'waterbomb.svg'),
  opx: path.join(tmp, 'corner.opx'),
};
execFileSync(ORIKIN, ['convert', 'tests/data/waterbomb-base.fold', '-o', files.svg], { cwd: SOURCE });
execFileSync(ORIKIN, ['convert', 'examples/patterns/open-corner.fold', '-o', files.opx], { cwd: SOURCE });
const MIME = { svg: 'image/svg+xml', opx: 'application/xml' };

async function model(page) {
  return page.evaluate(() => ({
    file: document.getElementById('file-name').textContent,
    edges: document.querySelectorAll('#cp line.edge').length,
    faces: document.querySelectorAll('#tree .node.leaf').length,
    vertices: window.studio.positions().length / 3,
    textured: !document.getElementById('texture-clear').hidden,
    extent: window.studio.viewExtent(),
  }));
}

async function dropFile(page, name, type, bytes) {
  await page.evaluate(([n, t, b64]) => {
    const data = Uint8Array.from(atob(b64), (c) => c.charCodeAt(0));
    const dt = new DataTransfer();
    dt.items.add(new File([data], n, { type: t }));
    window.dispatchEvent(new DragEvent('drop', { dataTransfer: dt, bubbles: true, cancelable: true }));
  }, [name, type, bytes.toString('base64')]);
  await page.waitForTimeout(50);
  await idle(page);
}

async function expectOpened(page, kind, how) {
  const name = path.basename(files[kind]);
  const info = cli(['info', files[kind], '--json']);
  await page.waitForFunction((n) => document.getElementById('file-name').textContent === n, name, { timeout: 10000 });
  await idle(page);
  await page.waitForTimeout(100);
  const m = await model(page);
  console.log(`${kind} by ${how}: ${m.vertices} vertices, ${m.edges} edges, ${m.faces} faces; view extent ${m.extent.toFixed(3)}`);
  assert(!m.textured, `${kind} by ${how}: the file is the document, not a texture`);
  assert(m.vertices === info.vertices, `${kind} by ${how}: ${m.vertices} vertices as orikin info (${info.vertices})`);
  assert(m.edges === info.edges, `${kind} by ${how}: ${m.edges} edges drawn as orikin info (${info.edges})`);
  assert(m.faces === info.faces, `${kind} by ${how}: ${m.faces} faces in the tree as orikin info (${info.faces})`);
  // fitted: every vertex on screen, and the sheet not lost in a corner
  assert(m.extent <= 1 && m.extent >= 0.35, `${kind} by ${how}: the 3D view is fitted (extent ${m.extent})`);
  const errs = await page.evaluate(() => window.studio.errors());
  assert(errs.length === 0, `${kind} by ${how}: no error (${errs.join('; ')})`);
}

await run('open', 'examples/patterns/thesis-flap.fold', async ({ page }) => {
  // the view zoomed far out first: opening a file must fit it again
  for (let i = 0; i < 8; i++) await page.click('[data-zoom="-1"]');
  const far = await page.evaluate(() => window.studio.viewExtent());
  assert(far < 0.3, `zoomed out before opening (extent ${far})`);

  for (const kind of ['svg', 'opx']) {
    await page.setInputFiles('#open-file', { name: path.basename(files[kind]), mimeType: MIME[kind], buffer: fs.readFileSync(files[kind]) });
    await expectOpened(page, kind, 'the Open dialog');
    await page.click('#new-sheet');
    await page.click('#new-ok');
    await idle(page);
    for (let i = 0; i < 8; i++) await page.click('[data-zoom="-1"]');
    await dropFile(page, path.basename(files[kind]), MIME[kind], fs.readFileSync(files[kind]));
    await expectOpened(page, kind, 'a drop');
  }
  await page.screenshot({ path: path.join(OUT, 'open-opx.png') });

  // an image dropped on the page is not a texture (that is the texture action's): refused with
  // the hint, nothing changes
  const v0 = await page.evaluate(() => window.studio.version());
  const png = Buffer.from('iVBORw0KGgoAAAANSUhEUgAAAAEAAAABCAYAAAAfFcSJAAAADUlEQVR42mP8z8DwHwAFBQIAX8jx0gAAAABJRU5ErkJggg==', 'base64');
  await dropFile(page, 'paper.png', 'image/png', png);
  assert(await page.$eval('#texture-clear', (b) => b.hidden), 'a dropped image is not made a texture');
  assert((await page.evaluate(() => window.studio.lastError())).includes('use texture'), 'the page says how to map it');
  assert(await page.evaluate(() => window.studio.version()) === v0, 'a dropped image changes nothing');
  await page.click('#new-sheet');
  await page.click('#new-ok');
  await idle(page);
  await dropFile(page, path.basename(files.opx), MIME.opx, fs.readFileSync(files.opx));
  await expectOpened(page, 'opx', 'a drop after New');

  // glTF once in the export menu while there is no motion
  const opts = await page.evaluate(() => window.studio.exportOptions());
  assert(opts.filter((o) => o.startsWith('gltf')).length === 1, `glTF listed once (${opts.join(' ')})`);

  // a hand-written sequence (no step, no name) on the open corner: the list shows the default step
  const seq = { folds: [{ fix: 4, lock: [11], drive: 12, to: 90 }] };
  await dropFile(page, 'hand.seq.json', 'application/json', Buffer.from(JSON.stringify(seq)));
  const items = await page.$$eval('#folds li', (els) => els.map((e) => e.textContent));
  assert(items.length === 1 && items[0].includes('step 10°') && !/undefined|NaN/.test(items[0]), `the fold is listed with the default step (${items[0]})`);
  const opts2 = await page.evaluate(() => window.studio.exportOptions());
  assert(opts2.includes('gltf:sequence'), 'the sequence motion can be exported once there is a sequence');

  // a sequence whose first fold fails records nothing: one error (its verdict), no stale
  // "t: time 0 is outside [0, 0]" beside it
  await dropFile(page, 'first-fails.seq.json', 'application/json', fs.readFileSync(path.join(SOURCE, 'tests/data/kin-first-fold-invalid.seq.json')));
  const first = await page.evaluate(() => window.studio.errors());
  assert(first.length === 1 && first[0].includes('invalid assignment') && !first.some((e) => /outside/.test(e)),
    `a sequence that records nothing shows its verdict alone (${first.join(' | ')})`);

  // an error about the old document does not survive New
  const bad = { folds: [{ fix: 99, drive: 12, to: 90 }] };
  await dropFile(page, 'bad.seq.json', 'application/json', Buffer.from(JSON.stringify(bad)));
  assert((await page.evaluate(() => window.studio.errors())).length > 0, 'the bad sequence shows an error');
  await page.click('#new-sheet');
  await page.click('#new-ok');
  await idle(page);
  const after = await page.evaluate(() => window.studio.errors());
  assert(after.length === 0, `New clears the old document's errors (${after.join('; ')})`);
  assert(await page.evaluate(() => window.studio.lastError()) === '', 'no last error after New');
  assert((await page.$$eval('#folds li', (els) => els.length)) === 0, 'New empties the folding manager');
}, { allowErrors: [/Failed to load resource: the server responded with a status of 400/] });
