// Save-back and the autosave, as a user meets them: an edit, the file changed on disk by someone
// else, Save → the studio says so and asks before overwriting; an unsaved edit left when the
// studio stops is offered at the next start (the banner), and Recover brings it back.
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { OUT, SOURCE, assert, idle, run } from './harness.mjs';

const tmp = fs.mkdtempSync(path.join(os.tmpdir(), 'orikin-save-'));
const file = path.join(tmp, 'corner.fold');
const journal = path.join(tmp, '.corner.fold.orikin-autosave');
fs.copyFileSync(path.join(SOURCE, 'examples/patterns/open-corner.fold'), file);

async function api(page, method, route, body) {
  return page.evaluate(async ([method, route, body]) => {
    const token = sessionStorage.getItem('orikin-token');
    const r = await fetch('/api/' + route, {
      method, headers: { 'X-Orikin-Token': token, 'Content-Type': 'application/json' },
      body: body === undefined ? undefined : JSON.stringify(body),
    });
    return r.json();
  }, [method, route, body]);
}

await run('save', file, async ({ page, errors }) => {
  const dialogs = [];
  page.on('dialog', (d) => { dialogs.push(d.message()); d.accept(); });
  await api(page, 'POST', 'edit', { ops: [{ op: 'flip', edge: 12 }] });
  await page.evaluate(() => window.studio.refresh && window.studio.refresh());
  assert(fs.existsSync(journal), 'the edit is journaled beside the file');
  fs.appendFileSync(file, '\n\n'); // someone else changes the file
  const theirs = fs.readFileSync(file, 'utf8');
  await page.click('#save-back');
  await idle(page);
  assert(dialogs.length === 2 && /changed on disk/.test(dialogs[1]), 'the studio asks before overwriting: ' + JSON.stringify(dialogs));
  // the browser logs the refused first save (409) as a failed resource: that one is expected
  const i = errors.findIndex((e) => /status of 409/.test(e));
  assert(i >= 0, 'the first save was refused with 409');
  errors.splice(i, 1);
  const doc = await api(page, 'GET', 'document');
  const saved = JSON.parse(fs.readFileSync(file, 'utf8'));
  assert(fs.readFileSync(file, 'utf8') !== theirs && JSON.stringify(saved.edges_assignment) === JSON.stringify(doc.edges_assignment),
    'overwritten with the document once confirmed');
  assert(!fs.existsSync(journal), 'saved: no journal');
  // an edit left unsaved when the studio stops
  await api(page, 'POST', 'edit', { ops: [{ op: 'flip', edge: 12 }] });
  assert(fs.existsSync(journal), 'the second edit is journaled');
}, { autosave: true });

await run('save-recover', file, async ({ page }) => {
  await page.waitForSelector('#recovery:not([hidden])');
  assert((await page.textContent('#recovery-text')).includes('.corner.fold.orikin-autosave'), 'the banner names the autosave');
  await page.screenshot({ path: path.join(OUT, 'studio-recovery.png') });
  const before = (await api(page, 'GET', 'document')).edges_assignment[12];
  await page.click('#recover');
  await idle(page);
  await page.waitForSelector('#recovery[hidden]', { state: 'attached' });
  const after = (await api(page, 'GET', 'document')).edges_assignment[12];
  assert(before !== after, `recovered: crease 12 is ${after} again (the file has ${before})`);
  assert((await page.textContent('#save-back')) === 'Save*', 'the recovered edit is unsaved');
}, { autosave: true });
fs.rmSync(tmp, { recursive: true, force: true });
