// The folding manager in the browser: the open corner's two-fold sequence; the slider moved to
// T = 1.5 shows exactly the state `orikin sequence --at 1.5` prints (every vertex to 1e-9);
// play, the 3D tools, the plot; screenshots that are not blank (the README's picture).
import fs from 'node:fs';
import path from 'node:path';
import { OUT, SOURCE, assert, cli, idle, measurePng, run } from './harness.mjs';

const SEQ = 'examples/open-corner.seq.json';

async function setSlider(page, t) {
  await page.evaluate((tt) => {
    const s = document.getElementById('t-slider');
    const steps = (+s.max) / window.studio.sequence().duration;
    s.value = String(Math.round(tt * steps));
    s.dispatchEvent(new Event('input', { bubbles: true }));
  }, t);
  await idle(page);
}

function maxDiff(a, b) {
  let m = 0;
  for (let i = 0; i < a.length; i++) m = Math.max(m, Math.abs(a[i] - b[i]));
  return m;
}

await run('sequence', SEQ, async ({ page }) => {
  await idle(page);
  const folds = await page.$$eval('#folds li', (els) => els.length);
  assert(folds === 2, `the folds list shows the sequence's 2 folds (got ${folds})`);

  for (const t of [1.5, 0.25, 2]) {
    await setSlider(page, t);
    const shown = await page.evaluate(() => window.studio.shownT());
    assert(shown === t, `the slider shows T = ${t} (got ${shown})`);
    const pos = await page.evaluate(() => window.studio.positions());
    const ref = cli(['sequence', SEQ, '--at', String(t), '--json']).vertices_coords.flat();
    assert(pos.length === ref.length, 'as many coordinates as the CLI');
    const d = maxDiff(pos, ref);
    console.log(`T = ${t}: max |page - orikin sequence --at| = ${d.toExponential(2)}`);
    assert(d <= 1e-9, `T = ${t}: the page's vertices equal orikin sequence --at ${t} to 1e-9 (off by ${d})`);
  }

  // the exact value typed in
  await page.fill('#t-value', '1.5');
  await page.press('#t-value', 'Enter');
  await idle(page);
  const typed = await page.evaluate(() => window.studio.positions());
  assert(maxDiff(typed, cli(['sequence', SEQ, '--at', '1.5', '--json']).vertices_coords.flat()) <= 1e-9, 'T typed in');

  // play from the start for a moment at 4x: time moves forward, then pause
  await setSlider(page, 0);
  await page.selectOption('#speed', '4');
  await page.click('#play');
  await page.waitForTimeout(700);
  await page.click('#play');
  await idle(page);
  const tPlayed = await page.evaluate(() => window.studio.shownT());
  assert(tPlayed > 0.2 && tPlayed < 2, `playing moved the time forward (T = ${tPlayed})`);

  // the 3D tools
  await setSlider(page, 1.5);
  for (const sel of ['[data-rot="roll,1"]', '[data-rot="pitch,1"]', '[data-rot="yaw,-1"]', '[data-zoom="1"]', '#fit3d'])
    await page.click(sel);
  await page.selectOption('#preset', 'iso');
  await page.uncheck('#grid-toggle');
  await page.check('#grid-toggle');
  await page.waitForTimeout(100);

  // two-sided colours: a green front shows
  await page.fill('#color-front', '#00c000');
  await page.waitForTimeout(100);
  const green = await page.evaluate(async (b64) => {
    const img = new Image();
    img.src = 'data:image/png;base64,' + b64;
    await img.decode();
    const c = document.createElement('canvas');
    c.width = img.width; c.height = img.height;
    const ctx = c.getContext('2d');
    ctx.drawImage(img, 0, 0);
    const d = ctx.getImageData(0, 0, c.width, c.height).data;
    let n = 0;
    for (let i = 0; i < d.length; i += 4) if (d[i + 1] > 90 && d[i + 1] > 2 * d[i] && d[i + 1] > 2 * d[i + 2]) n++;
    return n / (d.length / 4);
  }, (await page.locator('#gl').screenshot()).toString('base64'));
  assert(green > 0.02, `the front colour is drawn (${(100 * green).toFixed(1)} % green)`);
  await page.fill('#color-front', '#e8833a');
  // a texture image chosen with texture… is mapped on the front side (dropped on the page it is
  // refused: tests/browser/open.mjs)
  const png = Buffer.from(await page.evaluate(async () => {
    const c = document.createElement('canvas');
    c.width = 64; c.height = 64;
    const ctx = c.getContext('2d');
    for (let i = 0; i < 8; i++) for (let j = 0; j < 8; j++) {
      ctx.fillStyle = (i + j) % 2 ? '#1b3a8a' : '#f2d13a';
      ctx.fillRect(8 * i, 8 * j, 8, 8);
    }
    return c.toDataURL('image/png').split(',')[1];
  }), 'base64');
  await page.setInputFiles('#texture-file', { name: 'checker.png', mimeType: 'image/png', buffer: png });
  await page.waitForFunction(() => !document.getElementById('texture-clear').hidden);
  await page.waitForTimeout(150);
  const tex = await measurePng(page, await page.locator('#gl').screenshot());
  assert(tex.colors > 200, `the texture is drawn (${tex.colors} colours)`);
  await page.click('#texture-clear');

  // screenshots that are not blank
  await page.mouse.move(1, 1);
  await page.evaluate(() => { document.getElementById('nav').scrollTop = 0; });
  await page.waitForTimeout(100);
  const gl = await page.locator('#gl').screenshot();
  const m3 = await measurePng(page, gl);
  console.log(`3D view ${m3.width}x${m3.height}: ${(100 * m3.drawn).toFixed(1)} % drawn, ${m3.colors} colours`);
  assert(m3.drawn > 0.05 && m3.colors > 50, '3D view not blank');
  const plot = await page.locator('#plot').screenshot();
  const mp = await measurePng(page, plot);
  assert(mp.drawn > 0.02 && mp.colors > 5, `the plot is drawn (${(100 * mp.drawn).toFixed(1)} %)`);
  const full = await page.screenshot();
  const mf = await measurePng(page, full);
  console.log(`page ${mf.width}x${mf.height}: ${(100 * mf.drawn).toFixed(1)} % drawn, ${mf.colors} colours`);
  assert(mf.drawn > 0.2 && mf.colors > 200, 'the page is not blank');
  fs.writeFileSync(path.join(OUT, 'studio.png'), full);
  if (process.env.ORIKIN_UPDATE_DOCS === '1') {
    fs.writeFileSync(path.join(SOURCE, 'docs/images/studio.png'), full);
    console.log('wrote docs/images/studio.png');
  }
});
