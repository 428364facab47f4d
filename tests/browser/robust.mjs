// Robustness in the browser: malformed files dropped onto the page show the error and change
// nothing (same document version, same FOLD text); a valid SVG drop opens; a request without
// the token is refused while the page keeps working; a New sheet and Download work.
import { assert, idle, run } from './harness.mjs';

async function drop(page, name, text) {
  await page.evaluate(([n, t]) => {
    const dt = new DataTransfer();
    dt.items.add(new File([t], n));
    window.dispatchEvent(new DragEvent('drop', { dataTransfer: dt, bubbles: true, cancelable: true }));
  }, [name, text]);
  await page.waitForTimeout(50);
  await idle(page);
}

async function documentText(page) {
  return page.evaluate(async () => {
    const r = await fetch('/api/document', { headers: { 'X-Orikin-Token': sessionStorage.getItem('orikin-token') } });
    return r.text();
  });
}

const SVG = '<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 100 100">' +
  '<line x1="0" y1="0" x2="100" y2="0" stroke="#000"/><line x1="100" y1="0" x2="100" y2="100" stroke="#000"/>' +
  '<line x1="100" y1="100" x2="0" y2="100" stroke="#000"/><line x1="0" y1="100" x2="0" y2="0" stroke="#000"/>' +
  '<line x1="0" y1="0" x2="100" y2="100" stroke="#f00"/></svg>';

// The server answers the deliberately malformed files with 400, which Chromium logs as a failed
// resource load; those (and only those) are expected here.
await run('robust', 'examples/patterns/open-corner.fold', async ({ page }) => {
  const text0 = await documentText(page);
  const v0 = await page.evaluate(() => window.studio.version());
  const bad = [
    ['broken.fold', '{"vertices_coords": [[0, 0], [1, 0]], "edges_vertices": [[0, 5]]', 'broken.fold: line'],
    ['wrong-index.fold', '{"vertices_coords": [[0, 0], [1, 0]], "edges_vertices": [[0, 5]]}', 'edges_vertices'],
    ['broken.svg', '<svg><line x1="0"', 'broken.svg'],
    ['broken.cp', '2 0 0 1\n', 'broken.cp'],
    ['broken.opx', '<opx', 'broken.opx'],
    ['notes.txt', 'hello', 'unsupported file type'],
    ['broken.json', '{"folds": ', 'malformed JSON'],
    ['other.json', '{"hello": 1}', 'fold sequence ("folds") or a composite'],
  ];
  for (const [name, content, expect] of bad) {
    await drop(page, name, content);
    const err = await page.evaluate(() => window.studio.lastError());
    assert(err.includes(expect), `${name}: the error is shown (${err})`);
    assert(await page.$eval('#messages .msg.error', (e) => e.textContent) === err, `${name}: in the messages`);
    assert(await page.evaluate(() => window.studio.version()) === v0, `${name}: the document version did not change`);
    assert(await documentText(page) === text0, `${name}: the document did not change`);
    assert(await page.textContent('#file-name') === 'examples/patterns/open-corner.fold', `${name}: still the same file`);
  }
  // a sequence whose fold names a face that does not exist: refused, nothing changes
  await drop(page, 'bad.seq.json', '{"pattern": "x.fold", "folds": [{"fix": 99, "drive": 12, "to": 90}]}');
  assert((await page.evaluate(() => window.studio.lastError())).includes('no face 99'), 'the bad sequence is refused');
  assert(await documentText(page) === text0, 'the bad sequence changed nothing');

  // the API refuses a request without the token; the page is unaffected
  const status = await page.evaluate(async () => (await fetch('/api/session')).status);
  assert(status === 401, 'no token: 401');

  // a valid drawing opens
  await drop(page, 'diagonal.svg', SVG);
  assert(await page.textContent('#file-name') === 'diagonal.svg', 'the SVG opened');
  assert(await page.$$eval('#cp line.edge.M', (els) => els.length) === 1, 'its red line is a mountain');
  assert(await page.$$eval('#tree .node.leaf', (els) => els.length) === 2, 'two faces');
  // undo brings the open corner back
  await page.click('#undo');
  await idle(page);
  assert(await documentText(page) === text0, 'undo of the open restores the document');

  // a new sheet from the dialog
  await page.click('#new-sheet');
  await page.fill('#new-side', '3');
  await page.click('#new-ok');
  await idle(page);
  assert(await page.$$eval('#tree .node.leaf', (els) => els.length) === 1, 'a blank sheet: one face');
  assert((await page.textContent('#tree')).includes('Obj1'), 'named Obj1');
}, { allowErrors: [/Failed to load resource: the server responded with a status of (400|401)/] });
