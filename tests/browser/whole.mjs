// The whole pattern's fold slider, the first control of the page: on the waterbomb base (one
// degree-8 vertex, several degrees of freedom) a real click on the slider and the keyboard fold
// every crease P % of the way toward the file's targets with no face chosen; each state's fold
// angles equal `orikin fold FILE --percent P --json`'s last state (to 1e-9), the label names the
// default fixed face, and back at 0 the sheet is flat again.
import path from 'node:path';
import { OUT, assert, cli, idle, run } from './harness.mjs';

const FILE = 'tests/data/waterbomb-base.fold';

async function settle(page) {
  await page.waitForTimeout(50);
  await idle(page);
}

async function compare(page, why) {
  const p = await page.evaluate(() => window.studio.wholePercent());
  const ref = cli(['fold', FILE, '--percent', String(p), '--json']);
  const want = ref.frames[ref.frames.length - 1].fold_angles_deg;
  const got = await page.evaluate(() => window.studio.angles());
  assert(got.length === want.length, `${why}: as many angles as the CLI (${got.length}, ${want.length})`);
  let d = 0;
  for (let i = 0; i < want.length; i++) d = Math.max(d, Math.abs(got[i] - want[i]));
  const moved = Math.max(...want.map(Math.abs));
  console.log(`${why}: ${p} %: max |page - orikin fold --percent ${p}| = ${d.toExponential(2)} deg (largest angle ${moved.toFixed(3)} deg)`);
  assert(d <= 1e-9, `${why}: the angles equal orikin fold --percent ${p} to 1e-9 (off by ${d})`);
  const label = await page.textContent('#whole-label');
  assert(label.includes(`${p} % of the way toward the targets`) && label.includes('(default)'), `${why}: the label (${label})`);
  return { p, moved };
}

const dof = cli(['dof', FILE, '--json']).dof;
await run('whole', FILE, async ({ page }) => {
  assert(dof > 1, `the waterbomb base has several degrees of freedom (${dof})`);
  // the slider is the first control of the page after the file group
  const box = await page.locator('#whole-slider').boundingBox();
  assert(box && box.y < 80, `the fold slider is in the toolbar (y = ${box && box.y})`);
  await page.mouse.click(box.x + box.width * 0.5, box.y + box.height / 2);
  await settle(page);
  const half = await compare(page, 'a click halfway along the slider');
  assert(half.p >= 35 && half.p <= 65 && half.moved > 1, `about halfway (${half.p} %) and folded (${half.moved}°)`);
  await page.screenshot({ path: path.join(OUT, 'whole-half.png') });
  await page.focus('#whole-slider');
  await page.keyboard.press('End');
  await settle(page);
  const full = await compare(page, 'End');
  assert(full.p === 100 && full.moved > half.moved, `all the way (${full.moved}° > ${half.moved}°)`);
  await page.keyboard.press('Home');
  await settle(page);
  const pos = await page.evaluate(() => window.studio.positions());
  const zmax = Math.max(...pos.filter((_, i) => i % 3 === 2).map(Math.abs));
  assert(zmax === 0, `back at 0 % the sheet is flat (max |z| ${zmax})`);
  const errs = await page.evaluate(() => window.studio.errors());
  assert(errs.length === 0, 'no error: ' + errs.join('; '));
});
