// Two-sided colours in the 3D view as in `orikin render`: the thesis' flap (two squares, one
// valley) folded to 180° lies flat on the fixed square, so from the top only its back shows;
// flipped to a mountain and folded to -180° it lies under it and the fixed square's front shows.
// The page's 3D view (top preset, red front, blue back) is screenshotted and its pixels sorted
// into red and blue; `orikin render --camera top` of the same state, with the same colours, must
// show the same side (and the flat sheet, the front only).
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { ORIKIN, OUT, SOURCE, assert, clickEdge, clickFace, idle, run } from './harness.mjs';

const FILE = 'examples/patterns/thesis-flap.fold';
const FRONT = '#ff0000', BACK = '#0000ff';
const tmp = fs.mkdtempSync(path.join(os.tmpdir(), 'orikin-colors-'));
const flipped = path.join(tmp, 'mountain.fold');
execFileSync(ORIKIN, ['edit', FILE, '--flip', '0', '-o', flipped], { cwd: SOURCE, stdio: 'ignore' });

function render(file, to) {
  const out = path.join(tmp, `render-${to}.png`);
  execFileSync(ORIKIN, ['render', file, '--fix', '0', '--drive', '0', '--to', String(to), '--step', '30', '--camera', 'top',
    '--front', FRONT, '--back', BACK, '--size', '600x450', '-o', out], { cwd: SOURCE, stdio: 'ignore' });
  return fs.readFileSync(out);
}

// The shares of red-dominant and blue-dominant pixels among the coloured ones.
async function sides(page, png) {
  return page.evaluate(async (b64) => {
    const img = new Image();
    img.src = 'data:image/png;base64,' + b64;
    await img.decode();
    const c = document.createElement('canvas');
    c.width = img.width; c.height = img.height;
    const ctx = c.getContext('2d');
    ctx.drawImage(img, 0, 0);
    const d = ctx.getImageData(0, 0, c.width, c.height).data;
    let red = 0, blue = 0;
    for (let i = 0; i < d.length; i += 4) {
      if (d[i] > d[i + 2] + 60 && d[i] > d[i + 1] + 60) red++;
      else if (d[i + 2] > d[i] + 60 && d[i + 2] > d[i + 1] + 60) blue++;
    }
    const n = red + blue || 1;
    return { red: red / n, blue: blue / n, pixels: red + blue };
  }, png.toString('base64'));
}

async function tool(page, name) {
  const on = await page.$eval(`[data-tool="${name}"]`, (b) => b.classList.contains('on'));
  if (!on) await page.click(`[data-tool="${name}"]`);
}

async function foldTo(page, to) {
  await page.click('#clear-spec');
  await tool(page, 'fix');
  await clickFace(page, 0);
  await tool(page, 'drive');
  await clickEdge(page, 0);
  await page.fill('#spec-to', String(to));
  await page.fill('#spec-step', '30');
  await tool(page, 'select');
  await page.click('#compute');
  await idle(page);
  await page.selectOption('#preset', 'top');
  await page.mouse.move(1, 1);
  await page.waitForTimeout(200);
}

async function compare(page, label, ref, expect) {
  const shot = await page.locator('#gl').screenshot();
  fs.writeFileSync(path.join(OUT, `colors-${label}.png`), shot);
  const got = await sides(page, shot);
  const want = await sides(page, ref);
  console.log(`${label}: page red ${(100 * got.red).toFixed(1)} % blue ${(100 * got.blue).toFixed(1)} % (${got.pixels} px); ` +
    `orikin render red ${(100 * want.red).toFixed(1)} % blue ${(100 * want.blue).toFixed(1)} %`);
  assert(want[expect] > 0.95, `${label}: orikin render shows the ${expect === 'red' ? 'front' : 'back'} (${JSON.stringify(want)})`);
  assert(got.pixels > 1000 && got[expect] > 0.95, `${label}: the page shows the same side as orikin render (${JSON.stringify(got)})`);
}

await run('colors', FILE, async ({ page }) => {
  await page.fill('#color-front', FRONT);
  await page.fill('#color-back', BACK);
  await page.selectOption('#preset', 'top');
  await page.mouse.move(1, 1);
  await page.waitForTimeout(200);
  const flat = await sides(page, await page.locator('#gl').screenshot());
  assert(flat.red > 0.95, `the flat sheet from the top: its front (${JSON.stringify(flat)})`);

  await foldTo(page, 180);
  await compare(page, 'valley-180', render(FILE, 180), 'blue');

  // the crease flipped to a mountain by a click: the flap folds under
  await tool(page, 'flip');
  await clickEdge(page, 0);
  await tool(page, 'select');
  await foldTo(page, -180);
  await compare(page, 'mountain-180', render(flipped, -180), 'red');
});
