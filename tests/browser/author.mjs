// Authoring by clicks (thesis ch. 9.3): on a blank 2 × 2 sheet, the open corner built from the
// crease collection on faces picked in the tree (MiddleH on Obj1, MiddleV on Obj11 and Obj12,
// DiagonalL on Obj121) and the mountain set with the M tool; the downloaded FOLD has the creases
// of examples/patterns/open-corner.fold. Hover shows FOLD indices; the axiom tool shows every
// solution and creases the one clicked; flip, move, remove, undo and redo.
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { ORIKIN, SOURCE, assert, clickEdge, clickFace, clickSheet, idle, run } from './harness.mjs';

const tmp = fs.mkdtempSync(path.join(os.tmpdir(), 'orikin-author-'));
const sheet = path.join(tmp, 'sheet.fold');
execFileSync(ORIKIN, ['new', '--square', '2', '-o', sheet], { cwd: SOURCE });

async function treeClick(page, name) {
  await page.click(`#tree .node.leaf:has(> span:text-is("${name}"))`);
}

async function tool(page, name) {
  const on = await page.$eval(`[data-tool="${name}"]`, (b) => b.classList.contains('on'));
  if (!on) await page.click(`[data-tool="${name}"]`);
}

async function collection(page, label) {
  await page.click(`#collection button:text-is("${label}")`);
  await idle(page);
}

async function documentJson(page) {
  return page.evaluate(async () => {
    const token = sessionStorage.getItem('orikin-token');
    const r = await fetch('/api/document', { headers: { 'X-Orikin-Token': token } });
    return r.json();
  });
}

async function downloadFold(page) {
  const [dl] = await Promise.all([page.waitForEvent('download'), page.click('#download-fold')]);
  const file = await dl.path();
  return { name: dl.suggestedFilename(), json: JSON.parse(fs.readFileSync(file, 'utf8')) };
}

await run('author', sheet, async ({ page }) => {
  // the collection, on faces picked in the tree
  await page.selectOption('#collection-assign', 'V');
  for (const [face, pattern] of [['Obj1', 'MiddleH'], ['Obj11', 'MiddleV'], ['Obj12', 'MiddleV'], ['Obj121', 'DiagonalL']]) {
    await treeClick(page, face);
    await collection(page, pattern);
  }
  const leaves = await page.$$eval('#tree .node.leaf > span', (els) => els.map((e) => e.textContent));
  assert(JSON.stringify(leaves.sort()) === JSON.stringify(['Obj111', 'Obj112', 'Obj1211', 'Obj1212', 'Obj122']), 'the tree: ' + leaves);
  // the mountain: the left half of the horizontal middle crease, clicked with the M tool
  await tool(page, 'assign-M');
  await clickSheet(page, 0.5, 1);
  await tool(page, 'select');

  const { name, json } = await downloadFold(page);
  assert(name === 'sheet.fold', 'the download is named after the document: ' + name);
  const ref = JSON.parse(fs.readFileSync(path.join(SOURCE, 'examples/patterns/open-corner.fold'), 'utf8'));
  for (const f of ['vertices_coords', 'edges_vertices', 'edges_assignment', 'faces_vertices', 'orikin:faces_name', 'orikin:face_tree'])
    assert(JSON.stringify(json[f]) === JSON.stringify(ref[f]), `the saved ${f} equals examples/patterns/open-corner.fold's`);

  // hover: the FOLD index of a crease, a face, a vertex
  const [ex, ey] = await page.evaluate(() => window.studio.edgeClient(12));
  await page.mouse.move(ex, ey);
  assert((await page.textContent('#hover-info')).startsWith('crease 12: valley'), 'hovering crease 12: ' + (await page.textContent('#hover-info')));
  const [fx, fy] = await page.evaluate(() => window.studio.faceClient(3));
  await page.mouse.move(fx, fy);
  assert((await page.textContent('#hover-info')).startsWith('Obj122 (face 3)'), 'hovering face 3');
  const [vx, vy] = await page.evaluate(() => window.studio.vertexClient(6));
  await page.mouse.move(vx + 2, vy - 1);
  assert((await page.textContent('#hover-info')).startsWith('vertex 6 (1, 1)'), 'hovering vertex 6');
  // the check drawn on the pattern: vertex 6 fails, the reason on hover
  assert(await page.$$eval('#cp .bad-vertex', (els) => els.map((e) => e.dataset.badVertex).join()) === '6', 'vertex 6 is marked');

  // flip, undo, redo
  const v0 = await page.evaluate(() => window.studio.version());
  await tool(page, 'flip');
  await clickEdge(page, 12);
  assert((await documentJson(page)).edges_assignment[12] === 'M', 'flip made crease 12 a mountain');
  await page.click('#undo');
  await idle(page);
  assert((await documentJson(page)).edges_assignment[12] === 'V', 'undo restored the valley');
  await page.click('#redo');
  await idle(page);
  assert((await documentJson(page)).edges_assignment[12] === 'M', 'redo flipped it again');
  await page.keyboard.press('Control+z');
  await idle(page);
  assert((await documentJson(page)).edges_assignment[12] === 'V', 'Ctrl+Z undoes');

  // remove crease 12 (the diagonal): Obj1211 and Obj1212 merge back into Obj121
  await tool(page, 'remove');
  await clickEdge(page, 12);
  let doc = await documentJson(page);
  assert(doc.edges_vertices.length === 12 && doc['orikin:faces_name'].includes('Obj121'), 'remove merged the faces into Obj121');
  await page.click('#undo');
  await idle(page);

  // move crease 12 onto the other diagonal of Obj121: click it, then two vertices
  await tool(page, 'move');
  await clickEdge(page, 12);
  await clickSheet(page, 0, 1);
  await clickSheet(page, 1, 0);
  doc = await documentJson(page);
  const moved = doc.edges_vertices.map(([a, b]) => [doc.vertices_coords[a], doc.vertices_coords[b]].map(String).sort().join(' '));
  assert(moved.includes('0,1 1,0'), 'the moved crease runs from (0, 1) to (1, 0)');
  await page.click('#undo');
  await idle(page);

  // the axiom tool: axiom 2 (p1 onto p2) from vertex (2, 2) to vertex (1, 2) on Obj112
  await treeClick(page, 'Obj112');
  await tool(page, 'axiom');
  await page.selectOption('#axiom-number', '2');
  await clickSheet(page, 2, 2);
  await clickSheet(page, 1, 2);
  const solutions = await page.$$eval('#axiom-solutions button', (els) => els.length);
  assert(solutions === 1, 'axiom 2 shows its one solution');
  assert(await page.$$eval('#cp .axiom-line', (els) => els.length) >= 1, 'the solution line is drawn');
  // axiom 5 shows both of its solutions
  await page.selectOption('#axiom-number', '5');
  await clickSheet(page, 0, 0);
  await clickSheet(page, 0, 2);
  await clickEdge(page, 2); // the top side, y = 2
  assert(await page.$$eval('#axiom-solutions button', (els) => els.length) === 2, 'axiom 5 shows two solutions');
  // back to axiom 2 and crease its solution on the selected face (still Obj112)
  assert(await page.$eval('#tree .node.selected > span', (e) => e.textContent) === 'Obj112', 'Obj112 is still selected');
  await page.selectOption('#axiom-number', '2');
  await clickSheet(page, 2, 2);
  await clickSheet(page, 1, 2);
  const before = (await documentJson(page)).faces_vertices.length;
  await page.click('#axiom-solutions button');
  await idle(page);
  doc = await documentJson(page);
  assert(doc.faces_vertices.length === before + 1, 'creasing the solution split Obj112');
  assert(doc['orikin:faces_name'].includes('Obj1121'), 'the split faces are named Obj1121, Obj1122');
  await page.click('#undo');
  await idle(page);
  assert((await documentJson(page)).faces_vertices.length === before, 'undo');
  assert(await page.evaluate(() => window.studio.version()) > v0, 'the version moved on with every change');
});
fs.rmSync(tmp, { recursive: true, force: true });
