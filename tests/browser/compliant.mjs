// The whole pattern's slider with "compliant" ticked (issue 23, the studio half): on a degree-4
// vertex that is not flat-foldable the rigid fold toward the targets does not move (it gets no nearer to the goal),
// while the compliant one folds it, bending its panels. A real click on the slider and on the
// check box; the page's fold angles equal `orikin fold FILE --compliant --percent P --json` (to
// 1e-9), its label gives the CLI's maximum strain, the 3D view shows the bent sheet (the
// positions read back), and unticked the slider is the rigid fold again.
import { execFileSync } from 'node:child_process';
import { mkdtempSync, readFileSync, rmSync } from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { ORIKIN, OUT, SOURCE, assert, cli, idle, run } from './harness.mjs';

const FILE = 'examples/patterns/non-flat-foldable-vertex.fold';

async function settle(page) {
  await page.waitForTimeout(50);
  await idle(page);
}

await run('compliant', FILE, async ({ page }) => {
  const box = await page.locator('#whole-slider').boundingBox();
  await page.mouse.click(box.x + box.width * 0.5, box.y + box.height / 2);
  await settle(page);
  const p = await page.evaluate(() => window.studio.wholePercent());
  assert(p >= 35 && p <= 65, `about halfway (${p} %)`);
  const rigid = await page.textContent('#whole-label');
  assert(rigid.includes('gets no nearer to the goal') && rigid.includes('tick "compliant"'),
    `the rigid fold does not move this vertex, and the label says what will (${rigid})`);

  await page.locator('#whole-compliant').click();
  await settle(page);
  const ref = cli(['fold', FILE, '--compliant', '--percent', String(p), '--json']);
  assert(ref.reached, `the CLI's compliant fold reaches ${p} %`);
  const got = await page.evaluate(() => window.studio.angles());
  assert(got.length === ref.fold_angles_deg.length, `as many angles as the CLI (${got.length})`);
  let d = 0;
  for (let i = 0; i < got.length; i++) d = Math.max(d, Math.abs(got[i] - ref.fold_angles_deg[i]));
  const moved = Math.max(...ref.fold_angles_deg.map(Math.abs));
  console.log(`compliant ${p} %: max |page - orikin fold --compliant| = ${d.toExponential(2)} deg, largest angle ${moved.toFixed(3)} deg, max strain ${(100 * ref.max_strain).toPrecision(3)} %`);
  assert(d <= 1e-9 && moved > 10, `the angles equal the CLI's to 1e-9 (off by ${d}) and the vertex folds (${moved}°)`);
  const label = await page.textContent('#whole-label');
  const strain = `max strain ${(100 * ref.max_strain).toPrecision(3)} %`;
  assert(label.includes(`compliant: ${p} % of the way toward the targets`) && label.includes(strain), `the label (${label})`);
  const pos = await page.evaluate(() => window.studio.positions());
  const want = ref.vertices;
  assert(pos.length === 3 * want, `the 3D view has the model's ${want} vertices (${pos.length / 3})`);
  const zmax = Math.max(...pos.filter((_, i) => i % 3 === 2).map(Math.abs));
  assert(zmax > 0.05, `the 3D view shows the bent sheet (max |z| ${zmax})`);
  // the faces coloured by strain, as orikin render --color strain paints them: the most strained
  // face at the top of viridis, the least at its bottom
  const colors = await page.evaluate(() => window.studio.faceColors());
  const fs = ref.face_strains;
  assert(colors && colors.length === fs.length, `a colour per face (${colors && colors.length})`);
  const top = fs.indexOf(Math.max(...fs)), low = fs.indexOf(Math.min(...fs));
  const near = (c, want) => c.every((x, i) => Math.abs(x - want[i]) < 0.01);
  assert(near(colors[top], [0.993, 0.906, 0.144]), `the most strained face is yellow (${colors[top]})`);
  assert(near(colors[low], [0.267, 0.005, 0.329]), `the least strained face is dark blue (${colors[low]})`);
  await page.screenshot({ path: path.join(OUT, 'compliant-half.png') });

  // the Export menu: the bent sheet's mesh is orikin export --compliant's, byte for byte (its
  // strain as vertex colours), and its load steps are offered as a GIF and a morphing glTF
  const offered = await page.$$eval('#export-format option', (os) => os.map((o) => o.value));
  assert(offered.includes('gif:compliant') && offered.includes('glb:compliant'), `the compliant motion is offered: ${offered.join(' ')}`);
  const [dl] = await Promise.all([page.waitForEvent('download'), page.selectOption('#export-format', 'glb')]);
  const glb = readFileSync(await dl.path());
  await idle(page);
  const tmp = mkdtempSync(path.join(os.tmpdir(), 'orikin-compliant-'));
  const glbRef = path.join(tmp, 'ref.glb');
  execFileSync(ORIKIN, ['export', FILE, '--compliant', '--percent', String(p), '--front', await page.inputValue('#color-front'),
    '--back', await page.inputValue('#color-back'), '-o', glbRef], { cwd: SOURCE, stdio: 'ignore' });
  assert(Buffer.compare(glb, readFileSync(glbRef)) === 0, 'the GLB of the state shown is orikin export --compliant\'s');
  const [gif] = await Promise.all([page.waitForEvent('download'), page.selectOption('#export-format', 'gif:compliant')]);
  const gifBytes = readFileSync(await gif.path());
  await idle(page);
  assert(gif.suggestedFilename().endsWith('-compliant.gif') && gifBytes.subarray(0, 6).toString() === 'GIF89a' && gifBytes.length > 2000,
    `a GIF of the load steps (${gif.suggestedFilename()}, ${gifBytes.length} bytes)`);
  rmSync(tmp, { recursive: true });

  // unticked: the rigid fold again, at the same percent
  await page.locator('#whole-compliant').click();
  await settle(page);
  const back = await page.textContent('#whole-label');
  assert((await page.evaluate(() => window.studio.faceColors())) === null, 'unticked, the sheet\'s own colours');
  assert(back.includes('gets no nearer to the goal'), `unticked, the rigid fold (${back})`);
  // the page says the rigid fold is blocked (each time it runs), and nothing else
  const errs = await page.evaluate(() => window.studio.errors());
  assert(errs.length > 0 && errs.every((e) => e.startsWith('fold 1 is blocked: the rigid motion gets no nearer')),
    'only the rigid fold\'s verdict: ' + errs.join('; '));
});
