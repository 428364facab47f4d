// Self-collision in the browser, on the two flaps (examples/two-flaps.seq.json): the sequence
// stops before the flaps meet (the slider never passes the first contact), "contact" shows the
// state where they meet with the colliding faces and the witness point of `orikin sequence`;
// the collide check of the state shown; a fold computed by clicks that collides gets exactly
// what `orikin fold --json` prints, and without the check what `--no-collisions` prints; the
// sequence's motion and a state exported as meshes are byte for byte `orikin export`'s.
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { ORIKIN, SOURCE, assert, cli, clickEdge, clickFace, idle, run } from './harness.mjs';

const SEQ = 'examples/two-flaps.seq.json';
const FLAPS = 'examples/patterns/two-flaps.fold';

function maxDiff(a, b) {
  let m = 0;
  for (let i = 0; i < a.length; i++) m = Math.max(m, Math.abs(a[i] - b[i]));
  return m;
}

async function tool(page, name) {
  const on = await page.$eval(`[data-tool="${name}"]`, (b) => b.classList.contains('on'));
  if (!on) await page.click(`[data-tool="${name}"]`);
}

// Export through the menu and return the downloaded bytes.
async function exportMenu(page, value) {
  const [dl] = await Promise.all([page.waitForEvent('download'), page.selectOption('#export-format', value)]);
  const p = await dl.path();
  await idle(page);
  return { name: dl.suggestedFilename(), bytes: fs.readFileSync(p) };
}

const tmp = fs.mkdtempSync(path.join(os.tmpdir(), 'orikin-collide-'));

// the state where the flaps meet: fold 2 of the sequence from frame 1 (the left flap up) to the
// located drive, without the collision check
const seqRef = cli(['sequence', SEQ, '--json']);
const contactOut = path.join(tmp, 'contact.fold');
execFileSync(ORIKIN, ['fold', FLAPS, '--frame', '1', '--fix', '1', '--drive', '8', '--lock', '7', '--to',
  String(seqRef.collision.drive_deg), '--step', '200', '--no-collisions', '-o', contactOut], { cwd: SOURCE });
const contactDoc = JSON.parse(fs.readFileSync(contactOut, 'utf8'));
const contactRef = contactDoc.file_frames[contactDoc.file_frames.length - 1].vertices_coords.flat();

await run('collide', SEQ, async ({ page }) => {
  await idle(page);
  // the sequence collides: its verdict, and the slider stops before the contact
  const seq = await page.evaluate(() => window.studio.sequence());
  assert(JSON.stringify(seq) === JSON.stringify(seqRef), 'the page got exactly what orikin sequence --json prints');
  assert(seq.verdict === 'collision', 'verdict collision');
  const msgs = await page.$$eval('#messages .msg.error', (els) => els.map((e) => e.textContent));
  assert(msgs.some((m) => m.includes('faces 0 and 2 penetrate')), 'the collision is reported: ' + msgs.join(' | '));
  await page.evaluate(() => {
    const s = document.getElementById('t-slider');
    s.value = s.max;
    s.dispatchEvent(new Event('input', { bubbles: true }));
  });
  await idle(page);
  const shownEnd = await page.evaluate(() => window.studio.shownT());
  const session = await page.evaluate(async () => (await fetch('/api/session', { headers: { 'X-Orikin-Token': sessionStorage.getItem('orikin-token') } })).json());
  const tc = session.sequence.collision_t;
  assert(shownEnd < tc && shownEnd > tc - 0.01, `the slider's end ${shownEnd} is the last grid instant before the contact at ${tc}`);
  const endRef = await page.evaluate(() => window.studio.positions());
  assert(endRef.length === 24, 'the state at the slider\'s end is shown');

  // the contact: the state where the flaps meet, the colliding faces and the witness point
  assert(!(await page.$eval('#show-seq-contact', (b) => b.hidden)), 'the contact button is offered');
  await page.click('#show-seq-contact');
  await idle(page);
  const hl = await page.evaluate(() => window.studio.highlight());
  assert(JSON.stringify(hl.faces) === JSON.stringify(seqRef.collision.faces), 'the colliding faces are highlighted: ' + JSON.stringify(hl.faces));
  assert(maxDiff(hl.point, seqRef.collision.point) === 0, 'the witness point is orikin sequence\'s');
  const pos = await page.evaluate(() => window.studio.positions());
  const d = maxDiff(pos, contactRef);
  console.log(`contact state: max |page - orikin fold to the contact drive| = ${d.toExponential(2)}`);
  assert(d <= 1e-9, `the contact state is the fold to the located drive (off by ${d})`);
  assert((await page.textContent('#state3d')).includes('first contact of the sequence'), 'the 3D view says what it shows');
  const colliding = await page.$$eval('#cp .face.colliding', (els) => els.map((e) => +e.dataset.face).sort());
  assert(JSON.stringify(colliding) === '[0,2]', 'the colliding faces are marked in 2D too');

  // the collide check of the state shown: the contact collides, T = 1.5 is clean
  await page.click('#collide');
  await idle(page);
  let c = await page.evaluate(() => window.studio.collide());
  assert(c.collides && c.state === 'first contact of the sequence', 'the contact state collides');
  assert(await page.$eval('#collide-summary div', (e) => e.dataset.collides) === 'true', 'the summary says so');
  await page.fill('#t-value', '1.5');
  await page.press('#t-value', 'Enter');
  await idle(page);
  assert((await page.evaluate(() => window.studio.highlight())).faces.length === 0, 'a clean state clears the overlay');
  await page.click('#collide');
  await idle(page);
  c = await page.evaluate(() => window.studio.collide());
  assert(!c.collides && c.state === 't = 1.5', 'T = 1.5 is clean: ' + c.state);
  assert(c.min_clearance > 0 && c.clearance_faces.join() === '0,2', `least clearance between the flaps (${c.min_clearance})`);

  // exports: the sequence's motion and the state shown, byte for byte orikin export's
  const glb = await exportMenu(page, 'glb:sequence');
  const glbRef = path.join(tmp, 'ref.glb');
  execFileSync(ORIKIN, ['export', SEQ, '--animate', '--front', await page.inputValue('#color-front'), '--back',
    await page.inputValue('#color-back'), '-o', glbRef], { cwd: SOURCE });
  assert(glb.name === 'two-flaps-sequence.glb', 'the file is named: ' + glb.name);
  assert(Buffer.compare(glb.bytes, fs.readFileSync(glbRef)) === 0, 'the GLB animation is orikin export --animate\'s');
  const obj = await exportMenu(page, 'obj');
  const objRef = path.join(tmp, 'ref.obj');
  execFileSync(ORIKIN, ['export', SEQ, '--at', '1.5', '--front', await page.inputValue('#color-front'), '--back',
    await page.inputValue('#color-back'), '-o', objRef], { cwd: SOURCE });
  // a download is one file: the OBJ without the mtllib line that names the .mtl written beside a file
  const objRefText = fs.readFileSync(objRef, 'utf8').replace(/^mtllib .*\n/m, '');
  assert(fs.existsSync(path.join(tmp, 'ref.mtl')), 'orikin export writes ref.mtl beside ref.obj');
  assert(obj.bytes.toString('utf8') === objRefText, 'the OBJ of the state shown is orikin export --at 1.5\'s (but mtllib)');
  const png = await exportMenu(page, 'png');
  assert(png.bytes.subarray(1, 4).toString() === 'PNG' && png.bytes.length > 2000, 'a PNG picture of the state shown');

  // a fold specified by clicks from frame 1 that collides: exactly orikin fold --json
  await page.click('#clear-spec');
  await tool(page, 'fix');
  await clickFace(page, 1);
  await tool(page, 'drive');
  await clickEdge(page, 8);
  await tool(page, 'lock');
  await clickEdge(page, 7);
  await tool(page, 'select');
  await page.fill('#spec-to', '180');
  await page.fill('#spec-step', '10');
  await page.selectOption('#start-frame', '1');
  await page.click('#compute');
  await idle(page);
  const foldRef = cli(['fold', FLAPS, '--frame', '1', '--fix', '1', '--drive', '8', '--lock', '7', '--to', '180', '--step', '10', '--json']);
  const fold = await page.evaluate(() => window.studio.fold());
  assert(JSON.stringify(fold) === JSON.stringify(foldRef), 'the page got exactly what orikin fold --json prints');
  assert(await page.$eval('#verdict .invalid', (e) => e.dataset.verdict) === 'collision', 'the verdict: collision');
  assert((await page.textContent('#verdict')).includes('first contact at drive 131.810315'), 'the contact drive is shown');
  const fh = await page.evaluate(() => window.studio.highlight());
  assert(JSON.stringify(fh.faces) === '[0,2]' && maxDiff(fh.point, foldRef.collision.point) === 0, 'the fold\'s contact is shown');
  assert(+(await page.$eval('#fold-slider', (e) => e.max)) === foldRef.frames.length - 1, 'the fold\'s slider stops before the contact');
  // without the check: what --no-collisions prints
  await page.uncheck('#check-collisions');
  await page.click('#compute');
  await idle(page);
  const unchecked = await page.evaluate(() => window.studio.fold());
  const uncheckedRef = cli(['fold', FLAPS, '--frame', '1', '--fix', '1', '--drive', '8', '--lock', '7', '--to', '180', '--step', '10',
    '--no-collisions', '--json']);
  assert(JSON.stringify(unchecked) === JSON.stringify(uncheckedRef), 'unchecked: orikin fold --no-collisions --json');
  assert(unchecked.verdict === 'valid', 'unchecked, the fold is valid');
  await page.check('#check-collisions');
});
fs.rmSync(tmp, { recursive: true, force: true });
