// Replaying a simulation in the studio: `orikin simulate -o` writes the thesis' flap folding as
// FOLD frames with frame_time (seconds); opened in the studio, the folding manager's slider, the
// t field and play run over those seconds, and the 3D view shows each frame exactly as the file
// holds it (every vertex to 1e-6), halfway between two frames their interpolation; a screenshot.
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import path from 'node:path';
import { ORIKIN, OUT, SOURCE, assert, idle, measurePng, run } from './harness.mjs';

fs.mkdirSync(OUT, { recursive: true });
const FILE = path.join(OUT, 'replay-flap.fold');
execFileSync(ORIKIN, ['simulate', 'examples/patterns/thesis-flap.fold', '--fix', '0', '--current', '0.02', '--duration', '0.006',
  '--frames', '13', '-o', FILE], { cwd: SOURCE, stdio: 'ignore' });
const fold = JSON.parse(fs.readFileSync(FILE, 'utf8'));
const frames = fold.file_frames;
const times = frames.map((f) => f.frame_time);
const coords = frames.map((f) => f.vertices_coords.map((p) => [p[0], p[1], p[2] || 0]).flat());

function maxDiff(a, b) {
  assert(a.length === b.length, `as many coordinates (${a.length} and ${b.length})`);
  let m = 0;
  for (let i = 0; i < a.length; i++) m = Math.max(m, Math.abs(a[i] - b[i]));
  return m;
}

async function typeTime(page, t) {
  await page.fill('#t-value', String(t));
  await page.press('#t-value', 'Enter');
  await idle(page);
}

await run('replay', FILE, async ({ page }) => {
  await idle(page);
  assert(frames.length === 13 && Math.abs(times[12] - 0.006) < 1e-12, `the simulation wrote 13 frames up to 0.006 s (${frames.length}, ${times.at(-1)})`);
  assert(!(await page.isDisabled('#t-slider')) && !(await page.isDisabled('#play')), 'the slider and play are enabled');
  const unit = await page.$eval('#t-value', (e) => e.parentElement.firstChild.textContent);
  assert(unit.trim() === 't (s)', `the time field says seconds (${unit})`);

  // every frame, its time typed in: the file's vertices
  let worst = 0;
  for (let k = 0; k < frames.length; k++) {
    await typeTime(page, times[k]);
    const d = maxDiff(await page.evaluate(() => window.studio.positions()), coords[k]);
    worst = Math.max(worst, d);
    assert(d <= 1e-6, `t = ${times[k]} s shows frame ${k + 1} (off by ${d})`);
  }
  console.log(`13 frames at their frame_time: max |page - file| = ${worst.toExponential(2)}`);
  const label = await page.textContent('#t-label');
  assert(/0\.006 s: frame 13 of the file/.test(label), `the readout says seconds and the frame (${label})`);

  // halfway between frames 4 and 5 (file frames 5 and 6): the vertices' interpolation
  await typeTime(page, (times[4] + times[5]) / 2);
  const mid = coords[4].map((x, i) => (x + coords[5][i]) / 2);
  const dm = maxDiff(await page.evaluate(() => window.studio.positions()), mid);
  assert(dm <= 1e-6, `halfway between two frames: their interpolation (off by ${dm})`);
  assert(/between frames 5 and 6/.test(await page.textContent('#t-label')), 'the readout says interpolated');

  // the slider at its end: the last frame
  await page.evaluate(() => {
    const s = document.getElementById('t-slider');
    s.value = s.max;
    s.dispatchEvent(new Event('input', { bubbles: true }));
  });
  await idle(page);
  assert(maxDiff(await page.evaluate(() => window.studio.positions()), coords[12]) <= 1e-6, 'the slider at its end shows the last frame');

  // play from the start at 4×: time moves forward; then to the end, the last frame shown
  await page.evaluate(() => {
    const s = document.getElementById('t-slider');
    s.value = '0';
    s.dispatchEvent(new Event('input', { bubbles: true }));
  });
  await page.selectOption('#speed', '4');
  await page.click('#play');
  await page.waitForTimeout(300);
  const tPlayed = await page.evaluate(() => window.studio.replayT());
  assert(tPlayed > 0 && tPlayed < 0.006, `playing moved the time forward (t = ${tPlayed} s)`);
  await page.waitForFunction((end) => window.studio.replayT() === end, times[12], { timeout: 10000 });
  assert((await page.textContent('#play')).trim() === '▶', 'play stops at the end');
  const de = maxDiff(await page.evaluate(() => window.studio.positions()), coords[12]);
  assert(de <= 1e-6, `played to the end: the last frame (off by ${de})`);

  // halfway through the fold, seen in 3D
  await typeTime(page, times[6]);
  await page.selectOption('#preset', 'iso');
  await page.waitForTimeout(100);
  const png = await page.screenshot({ path: path.join(OUT, 'replay.png') });
  const m = await measurePng(page, png);
  console.log(`screenshot ${m.width}x${m.height}: ${(100 * m.drawn).toFixed(1)}% drawn, ${m.colors} colours`);
  assert(m.drawn > 0.05 && m.colors > 50, 'the screenshot is not blank');
});
