// A sequence with a fold toward the targets ("percent") in the browser: the waterbomb base
// collapsed to its targets in one step. The studio loads and plays it: the folds list names the
// step, and the slider's states equal `orikin sequence --at T` (every vertex to 1e-9); the label
// gives the progress (such a fold has no drive angle).
import { assert, cli, idle, run } from './harness.mjs';

const SEQ = 'tests/data/waterbomb-base-targets.seq.json';

function maxDiff(a, b) {
  let m = 0;
  for (let i = 0; i < a.length; i++) m = Math.max(m, Math.abs(a[i] - b[i]));
  return m;
}

await run('sequence_percent', SEQ, async ({ page }) => {
  await idle(page);
  const items = await page.$$eval('#folds li', (els) => els.map((e) => e.textContent));
  assert(items.length === 1, `the folds list shows the sequence's fold (got ${items.length})`);
  assert(items[0].includes('100 % of the way toward the targets'), `the fold is named as a fold toward the targets (${items[0]})`);
  for (const t of ['0.5', '0.25', '1']) {
    await page.fill('#t-value', t);
    await page.press('#t-value', 'Enter');
    await idle(page);
    const pos = await page.evaluate(() => window.studio.positions());
    const ref = cli(['sequence', SEQ, '--at', t, '--json']).vertices_coords.flat();
    assert(pos.length === ref.length, 'as many coordinates as the CLI');
    const d = maxDiff(pos, ref);
    console.log(`T = ${t}: max |page - orikin sequence --at| = ${d.toExponential(2)}`);
    assert(d <= 1e-9, `T = ${t}: the page's vertices equal orikin sequence --at ${t} to 1e-9 (off by ${d})`);
    const label = await page.textContent('#t-label');
    assert(label.includes('% toward the targets') && !label.includes('NaN'), `the label gives the progress (${label})`);
  }
});
